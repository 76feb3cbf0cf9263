/* SPDX-License-Identifier: MIT */
/*
 * The shrub type (seed 001, 3.2): a vertical trunk built apart, and a crown grown by the
 * L-system recursion into a clipping shape (sphere, box or cone), as a gardener clips a
 * hedge or a topiary: every branch that would leave the shape is cut at its surface, its
 * bark and tip inside, and grows no further; leaves that would stick out are made smaller
 * or left out. So the crown fills its shape up to the surface and nothing sticks out.
 *
 * The crown's first branches are ratios x L0 long, L0 chosen so that a straight run
 * through every generation would reach 1.25 times as far as the farthest point of the
 * shape from the trunk's top: the crown reaches every part of it before it is clipped.
 */
#include <errno.h>
#include <math.h>

#include "gen_private.h"

#define REACH_FACTOR 1.25
/* A leaf keeps this far inside the surface (metres). */
#define LEAF_CLEARANCE 0.002
#define LEAF_MIN_SCALE (1.0 / 3.0)

void gen_clip_shape_of(const struct gen_params *p, struct gen_clip_shape *s)
{
	s->kind = p->clip;
	s->center = p->clip_center;
	s->radius = p->clip_radius;
	s->height = p->clip_height;
	s->half = vec3_scale(p->clip_size, 0.5);
}

double gen_clip_distance(const struct gen_clip_shape *s, struct vec3 x)
{
	struct vec3 d = vec3_sub(x, s->center);

	switch (s->kind) {
	case GEN_CLIP_BOX: {
		double qx = fabs(d.x) - s->half.x, qy = fabs(d.y) - s->half.y, qz = fabs(d.z) - s->half.z;
		double out = vec3_len(vec3(fmax(qx, 0), fmax(qy, 0), fmax(qz, 0)));

		return out + fmin(fmax(qx, fmax(qy, qz)), 0.0);
	}
	case GEN_CLIP_CONE: {
		/* below the base, or beyond the slanted side (its distance in the meridian plane) */
		double slant = (hypot(d.x, d.z) - s->radius * (1.0 - d.y / s->height)) * s->height /
			       hypot(s->height, s->radius);

		return fmax(-d.y, slant);
	}
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	return vec3_len(d) - s->radius;
}

struct vec3 gen_clip_normal(const struct gen_clip_shape *s, struct vec3 x)
{
	const double h = 1e-5;
	struct vec3 g = vec3(gen_clip_distance(s, vec3_add(x, vec3(h, 0, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(h, 0, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, h, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, h, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, 0, h))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, 0, h))));

	return vec3_norm_or(g, vec3(0, 1, 0));
}

static double depth_needed(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			   double r1, double f)
{
	return gen_clip_distance(s, vec3_lerp(a, b, f)) + GEN_CLIP_MARGIN * (r0 + (r1 - r0) * f);
}

/* The largest f in [0, hi] with g(f) + extra <= 0, g convex and g(0) + extra <= 0. */
static double last_inside(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			  double r1, double extra, double hi)
{
	double lo = 0.0;

	for (int i = 0; i < 48; i++) {
		double mid = 0.5 * (lo + hi);

		if (depth_needed(s, a, b, r0, r1, mid) + extra <= 0)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

double gen_clip_segment(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			double r1, double setback)
{
	double inside;

	if (depth_needed(s, a, b, r0, r1, 0.0) > 0)
		return -1.0;
	/* convex along the segment: inside at both ends is inside all along */
	if (depth_needed(s, a, b, r0, r1, 1.0) <= 0)
		return 1.0;
	inside = last_inside(s, a, b, r0, r1, 0.0, 1.0);
	/* cut it back by the setback where it can be; a branch that starts nearer the surface
	 * than that (a shoot of a clipped branch) goes to the surface */
	if (depth_needed(s, a, b, r0, r1, 0.0) + setback > 0)
		return inside;
	return last_inside(s, a, b, r0, r1, setback, inside);
}

static bool leaf_fits(const struct gen_clip_shape *s, const struct vec3 *p, size_t n, double k)
{
	for (size_t i = 0; i < n; i++)
		if (gen_clip_distance(s, vec3_lerp(p[0], p[i], k)) > -LEAF_CLEARANCE)
			return false;
	return true;
}

bool gen_clip_leaf(const struct gen_clip_shape *s, struct vec3 *p, size_t n)
{
	double lo = LEAF_MIN_SCALE, hi = 1.0;

	if (leaf_fits(s, p, n, 1.0))
		return true;
	if (!leaf_fits(s, p, n, lo))
		return false;
	for (int i = 0; i < 24; i++) {
		double mid = 0.5 * (lo + hi);

		if (leaf_fits(s, p, n, mid))
			lo = mid;
		else
			hi = mid;
	}
	for (size_t i = 1; i < n; i++)
		p[i] = vec3_lerp(p[0], p[i], lo);
	return true;
}

/* The farthest the shape reaches from x. */
static double reach(const struct gen_clip_shape *s, struct vec3 x)
{
	double far = 0.0;

	switch (s->kind) {
	case GEN_CLIP_BOX:
		for (int i = 0; i < 8; i++) {
			struct vec3 c = vec3(s->center.x + (i & 1 ? s->half.x : -s->half.x),
					     s->center.y + (i & 2 ? s->half.y : -s->half.y),
					     s->center.z + (i & 4 ? s->half.z : -s->half.z));

			far = fmax(far, vec3_dist(x, c));
		}
		return far;
	case GEN_CLIP_CONE:
		far = vec3_dist(x, vec3_add(s->center, vec3(0, s->height, 0)));
		for (int i = 0; i < 32; i++) {
			double a = 2.0 * VEC_PI * i / 32;
			struct vec3 rim = vec3_add(s->center, vec3(s->radius * cos(a), 0, s->radius * sin(a)));

			far = fmax(far, vec3_dist(x, rim));
		}
		return far;
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	return vec3_dist(x, s->center) + s->radius;
}

int gen_shrub(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	struct gen_clip_shape shape;
	struct vec3 top = vec3_add(p->trunk_start, vec3(0, p->trunk_height, 0));
	double mean = 0.0, run = 0.0, k = 1.0;
	int trunk;

	gen_clip_shape_of(p, &shape);
	for (int i = 0; i < p->children; i++)
		mean += p->ratios[i] / p->children;
	for (int l = 1; l < p->levels; l++) {
		k *= mean;
		run += k;
	}
	trunk = gen_add_branch(g, -1, p->trunk_start, top, p->thickness,
			       p->thickness * p->thickness_ratio, p->levels);
	if (trunk < 0)
		return trunk;
	return gen_lsystem_grow(g, trunk, gen_reference(vec3(0, 1, 0)),
				run > 0 ? REACH_FACTOR * reach(&shape, top) / run : 0.0, &shape);
}
