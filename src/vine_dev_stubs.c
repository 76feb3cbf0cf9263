/* SPDX-License-Identifier: MIT */
/*
 * THROWAWAY (branch i16-shape only, removed before it is merged): stand-ins for
 * vine_support.c (the spatial index) and vine_params.c (the defaults), which are being
 * written on other branches, so vine_grow.c and vine_shape.c build and their tests run
 * here. The support is brute force over every triangle (Ericson's closest point on a
 * triangle); the defaults are Table 4.1's as issue 16 gives them.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "vine.h"
#include "vine_support.h"

struct vine_support {
	struct vec3 *p; /* 3 a triangle */
	size_t n;
	struct vec3 lo, hi;
};

void vine_params_default(struct vine_params *p)
{
	memset(p, 0, sizeof(*p));
	p->internode = 0.06;
	p->radius = 0.002;
	p->step_time = 10;
	p->angle = 18;
	p->free_nodes = 1;
	p->twining = VINE_LEFT;
	p->leaves_per_node = 1;
	p->cotyledons = 2;
	p->leaf_size = 0.012;
	p->points_per_internode = 8;
	p->ring_sides = 8;
	p->sweep = 2.25;
	p->internodes = 40;
	p->seed = 1;
}

int vine_support_create(const float *positions, size_t nvertices, const uint32_t *indices,
			size_t ntriangles, struct vine_support **out)
{
	struct vine_support *s;

	for (size_t i = 0; i < 3 * ntriangles; i++)
		if (indices[i] >= nvertices)
			return -EINVAL;
	for (size_t i = 0; i < 3 * nvertices; i++)
		if (!isfinite(positions[i]))
			return -EINVAL;
	s = calloc(1, sizeof(*s));
	if (!s)
		return -ENOMEM;
	s->p = malloc((ntriangles ? 3 * ntriangles : 1) * sizeof(*s->p));
	if (!s->p) {
		free(s);
		return -ENOMEM;
	}
	s->n = ntriangles;
	s->lo = vec3(INFINITY, INFINITY, INFINITY);
	s->hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	for (size_t i = 0; i < 3 * ntriangles; i++) {
		const float *q = positions + 3 * (size_t)indices[i];
		struct vec3 v = vec3(q[0], q[1], q[2]);

		s->p[i] = v;
		s->lo = vec3(fmin(s->lo.x, v.x), fmin(s->lo.y, v.y), fmin(s->lo.z, v.z));
		s->hi = vec3(fmax(s->hi.x, v.x), fmax(s->hi.y, v.y), fmax(s->hi.z, v.z));
	}
	*out = s;
	return 0;
}

void vine_support_destroy(struct vine_support *s)
{
	if (!s)
		return;
	free(s->p);
	free(s);
}

size_t vine_support_triangles(const struct vine_support *s)
{
	return s->n;
}

void vine_support_bounds(const struct vine_support *s, struct vec3 *lo, struct vec3 *hi)
{
	*lo = s->lo;
	*hi = s->hi;
}

static struct vec3 closest_on_segment(struct vec3 p, struct vec3 a, struct vec3 b)
{
	struct vec3 ab = vec3_sub(b, a);
	double dd = vec3_dot(ab, ab), t = dd > 0 ? vec3_dot(vec3_sub(p, a), ab) / dd : 0;

	return vec3_add(a, vec3_scale(ab, t < 0 ? 0 : t > 1 ? 1 : t));
}

/* Ericson, Real-Time Collision Detection, 5.1.5; degenerate triangles as their edges. */
static struct vec3 closest_on_triangle(struct vec3 p, struct vec3 a, struct vec3 b, struct vec3 c)
{
	struct vec3 ab = vec3_sub(b, a), ac = vec3_sub(c, a), ap = vec3_sub(p, a), bp, cp;
	double d1, d2, d3, d4, d5, d6, va, vb, vc, den;

	if (vec3_len(vec3_cross(ab, ac)) <= 1e-20) {
		struct vec3 q[3] = { closest_on_segment(p, a, b), closest_on_segment(p, b, c),
				     closest_on_segment(p, c, a) };
		size_t best = 0;

		for (size_t i = 1; i < 3; i++)
			if (vec3_dist(p, q[i]) < vec3_dist(p, q[best]))
				best = i;
		return q[best];
	}
	d1 = vec3_dot(ab, ap);
	d2 = vec3_dot(ac, ap);
	if (d1 <= 0 && d2 <= 0)
		return a;
	bp = vec3_sub(p, b);
	d3 = vec3_dot(ab, bp);
	d4 = vec3_dot(ac, bp);
	if (d3 >= 0 && d4 <= d3)
		return b;
	vc = d1 * d4 - d3 * d2;
	if (vc <= 0 && d1 >= 0 && d3 <= 0)
		return vec3_add(a, vec3_scale(ab, d1 / (d1 - d3)));
	cp = vec3_sub(p, c);
	d5 = vec3_dot(ab, cp);
	d6 = vec3_dot(ac, cp);
	if (d6 >= 0 && d5 <= d6)
		return c;
	vb = d5 * d2 - d1 * d6;
	if (vb <= 0 && d2 >= 0 && d6 <= 0)
		return vec3_add(a, vec3_scale(ac, d2 / (d2 - d6)));
	va = d3 * d6 - d5 * d4;
	if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
		return vec3_add(b, vec3_scale(vec3_sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
	den = 1.0 / (va + vb + vc);
	return vec3_add(a, vec3_add(vec3_scale(ab, vb * den), vec3_scale(ac, vc * den)));
}

double vine_support_distance(const struct vine_support *s, struct vec3 p, double max,
			     struct vec3 *nearest, size_t *triangle)
{
	double best = max;
	struct vec3 q = p;
	size_t t = 0;
	bool found = false;

	for (size_t i = 0; i < s->n; i++) {
		struct vec3 c = closest_on_triangle(p, s->p[3 * i], s->p[3 * i + 1], s->p[3 * i + 2]);
		double dist = vec3_dist(p, c);

		if (dist < best) {
			best = dist;
			q = c;
			t = i;
			found = true;
		}
	}
	if (!found)
		return max;
	if (nearest)
		*nearest = q;
	if (triangle)
		*triangle = t;
	return best;
}
