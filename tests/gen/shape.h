/* SPDX-License-Identifier: MIT */
#pragma once

/* A shrub's clipping shape (docs/tree-params.md: clip.*), measured by the tests' own
 * geometry rather than the generator's. */
#include <stdbool.h>

enum shape_kind { SHAPE_SPHERE, SHAPE_BOX, SHAPE_CONE };

struct shape {
	enum shape_kind kind;
	double c[3];    /* sphere, box: the centre; cone: the centre of its base */
	double r, h;    /* sphere, cone: radius; cone: height */
	double half[3]; /* box: half its edges */
};

/* From arguments "sphere CX CY CZ R", "box CX CY CZ SX SY SZ" or "cone CX CY CZ R H":
 * how many arguments it took, or 0 when they are not a shape. */
int shape_parse(char **argv, int argc, struct shape *s);
/* Signed distance from x to the surface, < 0 inside; exact on both sides. */
double shape_distance(const struct shape *s, const double x[3]);
/* The i-th of n points spread uniformly by area over the surface, and its outward
 * normal. Deterministic. */
void shape_sample(const struct shape *s, unsigned i, unsigned n, double p[3], double normal[3]);
/* The radius of the largest ball inside the shape. */
double shape_inradius(const struct shape *s);
