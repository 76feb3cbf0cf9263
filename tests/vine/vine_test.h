/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "vec.h"
#include "vine.h"
#include "vine_support.h"

/*
 * What the vine tests (test_vine_grow, test_vine_shape, test_vine_effects) share: supports
 * made of capped cylinders, and the helix a shoot winds round a pole standing on the y axis.
 * Every failure exits as test.h's CHECK does.
 */

/* Cylinders gathered into one triangle mesh. */
struct mesh_build {
	float *p;
	uint32_t *t;
	size_t np, nt;
};

/* A capped cylinder of radius R (`sides` sides, a vertex at angle 0) along +y (axis 1) or
 * +x (axis 0) from o, length h, appended to m. */
void cylinder(struct mesh_build *m, double R, double h, int sides, struct vec3 o, int axis);
/* The support of what m holds; m is emptied. */
struct vine_support *support_of(struct mesh_build *m);
/* A pole of radius R, `sides` sides, height h, standing at the origin. */
struct vine_support *pole(double R, double h, int sides);

/* p's azimuth about +y, radians: counter-clockwise seen from above, atan2(-z, x). */
double azimuth(struct vec3 p);

/*
 * The twined part of a shoot round a pole on the y axis: its points touching the support
 * (contact) below `below`, from the first to the last. turned is the azimuth they sweep,
 * radians (> 0: counter-clockwise seen from above, a right-handed helix), pitch the rise
 * a turn, the radii the points' distances from the pole's axis.
 */
struct helix {
	size_t first, last;
	double turned, pitch;
	double radius_mean, radius_min, radius_max;
};
/* False (h unset) when fewer than two points touch below `below`. */
bool pole_helix(const struct vine_shoot *sh, double below, struct helix *h);
