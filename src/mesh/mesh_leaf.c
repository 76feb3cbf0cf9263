/* SPDX-License-Identifier: MIT */
/* A leaf's shape: its outline clipped into triangles in its plane, or an origami kind's
 * mesh placed on it (mesh_private.h). */
#include "mesh_private.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "tube_frame.h"
#include "ori_kinds.h"

/* Twice the signed area of (a, b, c) in the leaf plane: > 0 when counter-clockwise. */
static double orient(const struct mesh_scratch *s, size_t a, size_t b, size_t c)
{
	return (s->x[b] - s->x[a]) * (s->y[c] - s->y[a]) - (s->y[b] - s->y[a]) * (s->x[c] - s->x[a]);
}

static bool same_point(const struct mesh_scratch *s, size_t a, size_t b)
{
	return s->x[a] == s->x[b] && s->y[a] == s->y[b];
}

/* Does any other remaining vertex lie in (or on) triangle (a, b, c)? Then it is no ear. */
static bool ear_blocked(const struct mesh_scratch *s, size_t cnt, size_t a, size_t b, size_t c,
			double eps)
{
	for (size_t i = 0; i < cnt; i++) {
		size_t q = s->live[i];

		if (q == a || q == b || q == c)
			continue;
		/* A polygon touching itself repeats a point; that copy does not block the ear. */
		if (same_point(s, q, a) || same_point(s, q, b) || same_point(s, q, c))
			continue;
		if (orient(s, a, b, q) >= -eps && orient(s, b, c, q) >= -eps &&
		    orient(s, c, a, q) >= -eps)
			return true;
	}
	return false;
}

static void live_remove(struct mesh_scratch *s, size_t *cnt, size_t i)
{
	memmove(&s->live[i], &s->live[i + 1], (*cnt - i - 1) * sizeof(*s->live));
	(*cnt)--;
}

/*
 * Ear clipping of the counter-clockwise polygon (x, y)[0..n): emits triangles as indices
 * base + i. Collinear vertices and zero-width spikes are dropped without a triangle. A
 * polygon with no ear left (self-intersecting junk) gets its most convex corners clipped
 * as a best effort; inverted leftovers are dropped.
 */
static void leaf_clip(struct mesh *m, struct mesh_scratch *s, size_t n, uint32_t base, double eps)
{
	size_t cnt = n, i = 0, misses = 0;

	for (size_t j = 0; j < n; j++)
		s->live[j] = j;

	while (cnt > 3) {
		size_t a = s->live[(i + cnt - 1) % cnt], b = s->live[i], c = s->live[(i + 1) % cnt];
		double o = orient(s, a, b, c);

		if (fabs(o) <= eps || (o > 0 && !ear_blocked(s, cnt, a, b, c, eps))) {
			if (fabs(o) > eps)
				mesh_push_tri(m, base + (uint32_t)a, base + (uint32_t)b, base + (uint32_t)c);
			live_remove(s, &cnt, i);
			if (i >= cnt)
				i = 0;
			misses = 0;
			continue;
		}
		i = (i + 1) % cnt;
		if (++misses < cnt)
			continue;

		/* A whole round without an ear: clip the most convex corner regardless. */
		{
			size_t best = cnt;
			double best_o = eps;

			for (size_t j = 0; j < cnt; j++) {
				double oj = orient(s, s->live[(j + cnt - 1) % cnt], s->live[j],
						   s->live[(j + 1) % cnt]);

				if (oj > best_o) {
					best_o = oj;
					best = j;
				}
			}
			if (best == cnt)
				return;
			mesh_push_tri(m, base + (uint32_t)s->live[(best + cnt - 1) % cnt],
				      base + (uint32_t)s->live[best],
				      base + (uint32_t)s->live[(best + 1) % cnt]);
			live_remove(s, &cnt, best);
			i = best < cnt ? best : 0;
			misses = 0;
		}
	}
	if (cnt == 3 && orient(s, s->live[0], s->live[1], s->live[2]) > eps)
		mesh_push_tri(m, base + (uint32_t)s->live[0], base + (uint32_t)s->live[1],
			      base + (uint32_t)s->live[2]);
}

/*
 * An origami leaf: its kind's faces at rest (ori_mesh_append), flat-shaded so the folds
 * show, in the frame its points give back. 1 when it is not one (its points do not fit
 * its kind: an outline, meshed as one), 0 or -ENOMEM.
 */
static int origami_build(struct mesh *m, const struct leaf *l)
{
	const struct ori_kind *k;
	double xf[12];

	if (l->kind < 0 || l->kind >= ORI_KIND_COUNT)
		return 1;
	k = ori_kind_get(l->kind);
	if (!k)
		return -ENOMEM; /* built on first use: only memory can be missing */
	for (size_t i = 0; i < l->npoints; i++)
		if (!mesh_vec3_finite(l->points[i]))
			return 0; /* corrupt leaf: left out, as an outline would be */
	if (!ori_kind_frame(k, l->points, l->npoints, xf))
		return 1;
	return ori_mesh_append(&k->leaf, (const double (*)[3])k->rest, xf, m);
}

/*
 * A leaf: the polygon projected onto its best-fit plane (Newell normal), ear-clipped there,
 * the 3D points kept as they are. One-sided, facing along the Newell normal.
 */
int mesh_leaf_build(struct mesh *m, const struct leaf *l, struct mesh_scratch *s)
{
	struct vec3 c = vec3(0, 0, 0), nn = vec3(0, 0, 0), normal, u, v;
	double extent = 0.0, area2, eps;
	size_t k = 0;
	uint32_t base;
	int r;

	r = origami_build(m, l);
	if (r <= 0)
		return r;
	r = mesh_scratch_reserve(s, l->npoints);
	if (r < 0)
		return r;
	for (size_t i = 0; i < l->npoints; i++) {
		struct vec3 q = l->points[i];

		if (!mesh_vec3_finite(q))
			return 0; /* corrupt leaf: leave it out rather than guess */
		if (k > 0 && vec3_dist(q, s->p[k - 1]) <= LEAF_MIN_STEP)
			continue;
		s->p[k++] = q;
	}
	/* The polygon is closed implicitly; drop an explicit closing point. */
	while (k > 1 && vec3_dist(s->p[k - 1], s->p[0]) <= LEAF_MIN_STEP)
		k--;
	if (k < 3)
		return 0;

	for (size_t i = 0; i < k; i++)
		c = vec3_add(c, s->p[i]);
	c = vec3_scale(c, 1.0 / (double)k);
	for (size_t i = 0; i < k; i++) {
		struct vec3 a = vec3_sub(s->p[i], c), b = vec3_sub(s->p[(i + 1) % k], c);

		/* Newell: the sum of edge cross products is twice the area vector. */
		nn = vec3_add(nn, vec3_cross(a, b));
		extent = fmax(extent, vec3_len(a));
	}
	area2 = vec3_len(nn);
	if (!(area2 > 1e-12 * extent * extent) || area2 < 1e-18)
		return 0; /* no area, or a figure eight that cancels out */
	normal = vec3_scale(nn, 1.0 / area2);

	u = tube_frame_perpendicular(normal);
	v = vec3_cross(normal, u);
	for (size_t i = 0; i < k; i++) {
		struct vec3 d = vec3_sub(s->p[i], c);

		s->x[i] = vec3_dot(d, u);
		s->y[i] = vec3_dot(d, v);
	}

	r = mesh_reserve(m, k, 3 * (k - 2));
	if (r < 0)
		return r;
	base = (uint32_t)m->nvertices;
	for (size_t i = 0; i < k; i++)
		mesh_push_vertex(m, s->p[i], normal);

	/* Relative tolerance: a leaf is a leaf at any size. */
	eps = 1e-10 * extent * extent;
	{
		size_t before = m->nindices;

		leaf_clip(m, s, k, base, eps);
		if (m->nindices == before)
			m->nvertices = base; /* nothing came of it: no stray vertices */
	}
	return 0;
}
