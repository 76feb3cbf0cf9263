/* SPDX-License-Identifier: MIT */
/*
 * The vines' stems at the forest's coarser levels (docs/forest.md, "The wood and the
 * vines"): each shoot swept as vine_mesh_append sweeps it (vine.h: rings along its
 * smoothed axis, counter-clockwise about the tangent on rotation-minimising frames, open
 * at the root, a cone at the tip one radius long), with a level's fewer sides and a ring
 * only every few points of the axis. At full detail the stems are vine_mesh_append's
 * own; this file makes the coarser ones only.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "forest_lod_private.h"
#include "vine.h"

/* A vine's helix turns a sixteenth about its support a point (the default's 22.5
 * degrees): a ring every 8 points is one every half turn, which far away still reads as
 * a stem that winds. Besides, a shoot keeps its rings at its last point and at its points
 * farthest along each of +-x, +-y, +-z: its outline. */
const int forest_lod_stem_stride[FOREST_LOD_LEVELS] = { 1, 2, 2, 3, 4, 6, 8 };

void lod_stems_init(struct lod_stems *ls)
{
	memset(ls, 0, sizeof(*ls));
}

void lod_stems_finish(struct lod_stems *ls)
{
	for (size_t i = 0; i < ls->n; i++)
		free(ls->s[i].axis);
	free(ls->s);
	lod_stems_init(ls);
}

static double polyline_length(const struct vec3 *a, size_t n)
{
	double len = 0.0;

	for (size_t k = 1; k < n; k++)
		len += vec3_dist(a[k - 1], a[k]);
	return isfinite(len) ? len : 0.0;
}

/* A shoot's points farthest along x, -x, y, -y, z and -z (the first such). */
static void shoot_far(struct lod_shoot *s)
{
	for (int d = 0; d < 6; d++) {
		double best = -INFINITY;

		s->far[d] = 0;
		for (size_t k = 0; k < s->n; k++) {
			struct vec3 p = s->axis[k];
			double x = (d / 2 == 0 ? p.x : d / 2 == 1 ? p.y : p.z) * (d % 2 ? -1.0 : 1.0);

			if (x > best) {
				best = x;
				s->far[d] = k;
			}
		}
	}
}

int lod_stems_read(struct lod_stems *ls, const struct tree *t)
{
	size_t n = 0, at = 0;
	int r = 0;

	lod_stems_finish(ls);
	for (size_t i = 0; i < t->nvines; i++)
		n += t->vines[i].nshoots;
	if (n == 0)
		return 0;
	ls->s = calloc(n, sizeof(*ls->s));
	if (!ls->s)
		return -ENOMEM;
	ls->n = n;
	for (size_t i = 0; i < t->nvines && r == 0; i++) {
		const struct vine *v = &t->vines[i];
		size_t base = at;

		for (size_t k = 0; k < v->nshoots && r == 0; k++, at++) {
			struct lod_shoot *s = &ls->s[at];
			int p = v->shoots[k].parent;

			r = vine_smooth(v, k, &s->axis);
			if (r < 0)
				break;
			s->n = v->shoots[k].n;
			s->sides = v->p.ring_sides >= 3 ? v->p.ring_sides : 3;
			s->radius = v->p.radius;
			/* a parent drawn before it (vine_grow's laterals grow from shoot 0) */
			s->parent = p >= 0 && (size_t)p < k ? (int)(base + (size_t)p) : -1;
			s->worth = polyline_length(s->axis, s->n) * s->radius;
			shoot_far(s);
		}
	}
	if (r < 0)
		lod_stems_finish(ls);
	return r;
}

/* A level's stride: past the coarsest, the outline alone. */
static size_t level_stride(int level)
{
	return level > FOREST_LOD_LEVELS ? 0 : (size_t)forest_lod_stem_stride[level - 1];
}

static int level_sides(const struct lod_shoot *s, int level)
{
	int m = forest_lod_levels[(level > FOREST_LOD_LEVELS ? FOREST_LOD_LEVELS : level) - 1]
			.max_sides;

	return s->sides < m ? s->sides : m < MESH_MIN_SIDES ? MESH_MIN_SIDES : m;
}

/* Whether a shoot keeps a ring at point k at a stride (0: its first and last only). */
static bool ring_at(const struct lod_shoot *s, size_t stride, size_t k)
{
	if ((stride ? k % stride == 0 : k == 0) || k + 1 == s->n)
		return true;
	for (int d = 0; d < 6; d++)
		if (s->far[d] == k)
			return true;
	return false;
}

/* The points of shoot s that keep a ring at a stride, into at (NULL: counted only). */
static size_t rings_of(const struct lod_shoot *s, size_t stride, struct vec3 *at)
{
	size_t n = 0;

	for (size_t k = 0; k < s->n; k++) {
		if (!ring_at(s, stride, k))
			continue;
		if (at)
			at[n] = s->axis[k];
		n++;
	}
	return n;
}

size_t lod_stems_triangles(const struct lod_stems *ls, size_t i, int level)
{
	const struct lod_shoot *s = &ls->s[i];
	size_t m, rings;

	if (s->n < 2)
		return 0; /* a bud that never grew */
	m = (size_t)level_sides(s, level);
	rings = rings_of(s, level_stride(level), NULL);
	return 2 * m * (rings - 1) + m;
}

int lod_stems_build(const struct lod_stems *ls, int level, const bool *keep, struct mesh *out)
{
	size_t nv = 0, ni = 0, longest = 0, stride = level_stride(level);
	struct vec3 *pts = NULL, *t = NULL, *nr = NULL;
	int r = 0;

	for (size_t i = 0; i < ls->n; i++) {
		const struct lod_shoot *s = &ls->s[i];
		size_t rings, m;

		if (s->n < 2 || (keep && !keep[i]))
			continue;
		m = (size_t)level_sides(s, level);
		rings = rings_of(s, stride, NULL);
		nv += m * (rings + 1) + 1;
		ni += 3 * (2 * m * (rings - 1) + m);
		longest = rings > longest ? rings : longest;
	}
	if (nv == 0)
		return 0;
	if (nv > UINT32_MAX - out->nvertices)
		return -EINVAL;
	pts = malloc(longest * sizeof(*pts));
	t = malloc(longest * sizeof(*t));
	nr = malloc(longest * sizeof(*nr));
	if (!pts || !t || !nr)
		r = -ENOMEM;
	if (r == 0)
		r = mesh_reserve(out, nv, ni);
	for (size_t i = 0; i < ls->n && r == 0; i++) {
		const struct lod_shoot *s = &ls->s[i];
		size_t rings;

		if (s->n < 2 || (keep && !keep[i]))
			continue;
		rings = rings_of(s, stride, pts);
		vine_stem_tube(pts, rings, (size_t)level_sides(s, level), s->radius, t, nr, out);
	}
	free(nr);
	free(t);
	free(pts);
	return r;
}
