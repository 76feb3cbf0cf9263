/* SPDX-License-Identifier: MIT */
#include "mesh.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* M_PI is POSIX, not C11. */

/* Tubes never get thinner than this, so no ring collapses into a point (no zero-area faces). */
#define TUBE_MIN_RADIUS 0.0005
/* Consecutive points closer than this (metres) are the same point. */
#define TUBE_MIN_STEP 1e-6
/* Ring side count grows linearly with the branch's thickest radius between these. */
#define TUBE_MIN_SIDES 6
#define TUBE_MAX_SIDES 16
#define TUBE_TWIG_RADIUS 0.01
#define TUBE_TRUNK_RADIUS 0.25
/* The tip closes with a cone this many tip radii long: reads as a rounded end. */
#define TUBE_TIP_LENGTH 1.0
/* Limits how far taper tilts the smooth normals (|dr/ds|), so steep tapers still shade sanely. */
#define TUBE_MAX_SLOPE 3.0
/* Consecutive leaf points closer than this (metres) are the same point. */
#define LEAF_MIN_STEP 1e-7

void mesh_init(struct mesh *m)
{
	memset(m, 0, sizeof(*m));
}

void mesh_finish(struct mesh *m)
{
	free(m->positions);
	free(m->normals);
	free(m->indices);
	mesh_init(m);
}

void mesh_clear(struct mesh *m)
{
	m->nvertices = 0;
	m->nindices = 0;
}

void tree_mesh_init(struct tree_mesh *tm)
{
	mesh_init(&tm->bark);
	mesh_init(&tm->leaves);
}

void tree_mesh_finish(struct tree_mesh *tm)
{
	mesh_finish(&tm->bark);
	mesh_finish(&tm->leaves);
}

static size_t grow_cap(size_t cap, size_t need)
{
	size_t ncap = cap ? cap : 256;

	while (ncap < need)
		ncap *= 2;
	return ncap;
}

/* Makes room for nv more vertices and ni more indices, so the pushes below cannot fail. */
static int mesh_reserve(struct mesh *m, size_t nv, size_t ni)
{
	/* Indices are 32-bit: a mesh that needs more vertices cannot be represented. */
	if (nv > UINT32_MAX - m->nvertices || ni > SIZE_MAX / 8 - m->nindices)
		return -ENOMEM;

	if (m->nvertices + nv > m->cap_vertices) {
		size_t cap = grow_cap(m->cap_vertices, m->nvertices + nv);
		float *p, *n;

		if (cap > SIZE_MAX / (3 * sizeof(float)))
			return -ENOMEM;
		p = realloc(m->positions, cap * 3 * sizeof(float));
		if (!p)
			return -ENOMEM;
		m->positions = p;
		n = realloc(m->normals, cap * 3 * sizeof(float));
		if (!n)
			return -ENOMEM; /* positions just has spare room; cap stays truthful */
		m->normals = n;
		m->cap_vertices = cap;
	}
	if (m->nindices + ni > m->cap_indices) {
		size_t cap = grow_cap(m->cap_indices, m->nindices + ni);
		uint32_t *idx = realloc(m->indices, cap * sizeof(uint32_t));

		if (!idx)
			return -ENOMEM;
		m->indices = idx;
		m->cap_indices = cap;
	}
	return 0;
}

static uint32_t mesh_push_vertex(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *pos = &m->positions[3 * m->nvertices];
	float *nor = &m->normals[3 * m->nvertices];

	pos[0] = (float)p.x;
	pos[1] = (float)p.y;
	pos[2] = (float)p.z;
	nor[0] = (float)n.x;
	nor[1] = (float)n.y;
	nor[2] = (float)n.z;
	return (uint32_t)m->nvertices++;
}

static void mesh_push_tri(struct mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t *idx = &m->indices[m->nindices];

	idx[0] = a;
	idx[1] = b;
	idx[2] = c;
	m->nindices += 3;
}

static bool vec3_finite(struct vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* Per-build scratch arrays, grown to the longest polyline seen, reused across elements. */
struct scratch {
	struct vec3 *p; /* cleaned points */
	struct vec3 *t; /* tangents */
	struct vec3 *n; /* frame normals */
	double *r;      /* radii */
	double *x, *y;  /* leaf points in their plane */
	size_t *live;   /* leaf polygon vertices not clipped yet */
	size_t cap;
};

static void scratch_finish(struct scratch *s)
{
	free(s->p);
	free(s->t);
	free(s->n);
	free(s->r);
	free(s->x);
	free(s->y);
	free(s->live);
	memset(s, 0, sizeof(*s));
}

#define SCRATCH_GROW(field, cap)                                                  \
	do {                                                                      \
		void *p_ = realloc(s->field, (cap) * sizeof(*s->field));          \
		if (!p_)                                                          \
			return -ENOMEM;                                           \
		s->field = p_;                                                    \
	} while (0)

static int scratch_reserve(struct scratch *s, size_t n)
{
	size_t cap;

	if (n <= s->cap)
		return 0;
	if (n > SIZE_MAX / 2 / sizeof(struct vec3))
		return -ENOMEM;
	cap = grow_cap(s->cap, n);
	/* s->cap only moves once every array has the new size. */
	SCRATCH_GROW(p, cap);
	SCRATCH_GROW(t, cap);
	SCRATCH_GROW(n, cap);
	SCRATCH_GROW(r, cap);
	SCRATCH_GROW(x, cap);
	SCRATCH_GROW(y, cap);
	SCRATCH_GROW(live, cap);
	s->cap = cap;
	return 0;
}

/* A unit vector perpendicular to unit t, a fixed function of t: the frame's starting normal. */
static struct vec3 perpendicular(struct vec3 t)
{
	/* Prefer the viewing axis: sketched branches lie in z = 0, so rings face the viewer. */
	struct vec3 ref = fabs(t.z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0);

	return vec3_norm_or(vec3_sub(ref, vec3_scale(t, vec3_dot(ref, t))), vec3(0, 1, 0));
}

/* Reflects v in the plane through the origin with normal a (|a|^2 = aa). */
static struct vec3 reflect(struct vec3 v, struct vec3 a, double aa)
{
	return vec3_sub(v, vec3_scale(a, 2.0 * vec3_dot(v, a) / aa));
}

static int tube_sides(double radius)
{
	double f = (radius - TUBE_TWIG_RADIUS) / (TUBE_TRUNK_RADIUS - TUBE_TWIG_RADIUS);

	f = f < 0 ? 0 : f > 1 ? 1 : f;
	return TUBE_MIN_SIDES + (int)lround(f * (TUBE_MAX_SIDES - TUBE_MIN_SIDES));
}

/* Copies the branch's usable points: finite, radius clamped, consecutive duplicates merged. */
static size_t tube_clean(const struct branch *b, struct scratch *s)
{
	size_t k = 0;

	for (size_t i = 0; i < b->npoints; i++) {
		struct vec3 q = b->points[i];
		double r = b->radii ? b->radii[i] : 0.0;

		if (!vec3_finite(q))
			continue;
		if (!isfinite(r) || r < TUBE_MIN_RADIUS)
			r = TUBE_MIN_RADIUS;
		if (k > 0 && vec3_dist(q, s->p[k - 1]) <= TUBE_MIN_STEP)
			continue;
		s->p[k] = q;
		s->r[k] = r;
		k++;
	}
	return k;
}

/*
 * Tangents (averaged segment directions) and rotation-minimising normals, carried along by
 * the double reflection method (Wang, Juettler, Zheng, Liu 2008).
 */
static void tube_frames(struct scratch *s, size_t k)
{
	struct vec3 *p = s->p, *t = s->t, *n = s->n;

	for (size_t i = 0; i < k; i++) {
		struct vec3 in = i > 0 ? vec3_sub(p[i], p[i - 1]) : vec3_sub(p[1], p[0]);
		struct vec3 out = i + 1 < k ? vec3_sub(p[i + 1], p[i]) : in;
		struct vec3 din = vec3_norm_or(in, vec3(0, 1, 0));
		struct vec3 dout = vec3_norm_or(out, din);

		/* A hairpin turn averages to zero: fall back to the outgoing direction. */
		t[i] = vec3_norm_or(vec3_add(din, dout), dout);
	}

	n[0] = perpendicular(t[0]);
	for (size_t i = 0; i + 1 < k; i++) {
		struct vec3 v1 = vec3_sub(p[i + 1], p[i]);
		double c1 = vec3_dot(v1, v1);
		struct vec3 rl = reflect(n[i], v1, c1);
		struct vec3 tl = reflect(t[i], v1, c1);
		struct vec3 v2 = vec3_sub(t[i + 1], tl);
		double c2 = vec3_dot(v2, v2);
		struct vec3 r = c2 > 1e-20 ? reflect(rl, v2, c2) : rl;

		/* Re-orthonormalise against the tangent so rounding cannot accumulate. */
		r = vec3_sub(r, vec3_scale(t[i + 1], vec3_dot(r, t[i + 1])));
		n[i + 1] = vec3_norm_or(r, perpendicular(t[i + 1]));
	}
}

/* dr/ds at point i, clamped: tilts the normals of a tapering tube. */
static double tube_slope(const struct scratch *s, size_t k, size_t i)
{
	size_t a = i > 0 ? i - 1 : i;
	size_t b = i + 1 < k ? i + 1 : i;
	double len = 0.0, slope;

	for (size_t j = a; j < b; j++)
		len += vec3_dist(s->p[j], s->p[j + 1]);
	slope = len > 0 ? (s->r[b] - s->r[a]) / len : 0.0;
	return slope < -TUBE_MAX_SLOPE ? -TUBE_MAX_SLOPE : slope > TUBE_MAX_SLOPE ? TUBE_MAX_SLOPE : slope;
}

/* The ring shape of one branch: `sides` directions around the axis. */
struct ring {
	int sides;
	double cs[TUBE_MAX_SIDES], sn[TUBE_MAX_SIDES];
};

static struct vec3 ring_dir(const struct ring *rg, struct vec3 n, struct vec3 b, int j)
{
	return vec3_add(vec3_scale(n, rg->cs[j]), vec3_scale(b, rg->sn[j]));
}

/* One ring of vertices per point, joined by quads; returns the first ring's first vertex. */
static uint32_t tube_side(struct mesh *m, const struct scratch *sc, size_t k, const struct ring *rg)
{
	uint32_t base = (uint32_t)m->nvertices, s = (uint32_t)rg->sides;

	for (size_t i = 0; i < k; i++) {
		struct vec3 t = sc->t[i], n = sc->n[i], b = vec3_cross(t, n);
		double slope = tube_slope(sc, k, i);

		for (int j = 0; j < rg->sides; j++) {
			struct vec3 radial = ring_dir(rg, n, b, j);
			struct vec3 pos = vec3_add(sc->p[i], vec3_scale(radial, sc->r[i]));
			struct vec3 nor = vec3_norm_or(vec3_sub(radial, vec3_scale(t, slope)), radial);

			mesh_push_vertex(m, pos, nor);
		}
	}
	for (size_t i = 0; i + 1 < k; i++) {
		uint32_t ring = base + (uint32_t)i * s;

		for (uint32_t j = 0; j < s; j++) {
			uint32_t a = ring + j, a1 = ring + (j + 1) % s;

			mesh_push_tri(m, a, a1, a1 + s);
			mesh_push_tri(m, a, a1 + s, a + s);
		}
	}
	return base;
}

/* Copies vertex v's position with a new normal (caps shade flat / as a cone). */
static uint32_t push_copy(struct mesh *m, uint32_t v, struct vec3 normal)
{
	const float *q = &m->positions[3 * (size_t)v];

	return mesh_push_vertex(m, vec3(q[0], q[1], q[2]), normal);
}

/* The root: a flat disc facing back along the axis (inside the parent for child branches). */
static void tube_root(struct mesh *m, const struct scratch *sc, uint32_t ring, uint32_t s)
{
	struct vec3 back = vec3_scale(sc->t[0], -1.0);
	uint32_t c = mesh_push_vertex(m, sc->p[0], back);

	for (uint32_t j = 0; j < s; j++)
		push_copy(m, ring + j, back);
	for (uint32_t j = 0; j < s; j++)
		mesh_push_tri(m, c, c + 1 + (j + 1) % s, c + 1 + j);
}

/* The tip: a cone TUBE_TIP_LENGTH radii long on the last ring, apex on the axis. */
static void tube_tip(struct mesh *m, const struct scratch *sc, size_t last, uint32_t ring,
		     const struct ring *rg)
{
	struct vec3 t = sc->t[last], n = sc->n[last], b = vec3_cross(t, n);
	double r = sc->r[last], h = TUBE_TIP_LENGTH * r;
	uint32_t first = (uint32_t)m->nvertices, s = (uint32_t)rg->sides, apex;

	for (int j = 0; j < rg->sides; j++) {
		/* The cone side's normal: radial * h + t * r, normalised. */
		struct vec3 nor = vec3_norm_or(
			vec3_add(vec3_scale(ring_dir(rg, n, b, j), h), vec3_scale(t, r)), t);

		push_copy(m, ring + (uint32_t)j, nor);
	}
	apex = mesh_push_vertex(m, vec3_add(sc->p[last], vec3_scale(t, h)), t);
	for (uint32_t j = 0; j < s; j++)
		mesh_push_tri(m, first + j, first + (j + 1) % s, apex);
}

/*
 * A branch as a closed tube: rings run counter-clockwise around the tangent, so the side,
 * the root disc and the tip cone all wind counter-clockwise seen from outside.
 */
static int tube_build(struct mesh *m, const struct branch *br, struct scratch *sc)
{
	struct ring rg;
	double rmax = 0.0;
	size_t k;
	uint32_t base;
	int r;

	r = scratch_reserve(sc, br->npoints);
	if (r < 0)
		return r;
	k = tube_clean(br, sc);
	if (k < 2)
		return 0;
	tube_frames(sc, k);

	for (size_t i = 0; i < k; i++)
		rmax = sc->r[i] > rmax ? sc->r[i] : rmax;
	rg.sides = tube_sides(rmax);
	for (int j = 0; j < rg.sides; j++) {
		rg.cs[j] = cos(2.0 * VEC_PI * j / rg.sides);
		rg.sn[j] = sin(2.0 * VEC_PI * j / rg.sides);
	}

	/* k rings + root disc + tip cone; 2 triangles a side per ring gap, 1 per side per cap */
	r = mesh_reserve(m, k * (size_t)rg.sides + 2 * ((size_t)rg.sides + 1),
			 3 * 2 * (size_t)rg.sides * k);
	if (r < 0)
		return r;
	base = tube_side(m, sc, k, &rg);
	tube_root(m, sc, base, (uint32_t)rg.sides);
	tube_tip(m, sc, k - 1, base + (uint32_t)((k - 1) * (size_t)rg.sides), &rg);
	return 0;
}

/* Twice the signed area of (a, b, c) in the leaf plane: > 0 when counter-clockwise. */
static double orient(const struct scratch *s, size_t a, size_t b, size_t c)
{
	return (s->x[b] - s->x[a]) * (s->y[c] - s->y[a]) - (s->y[b] - s->y[a]) * (s->x[c] - s->x[a]);
}

static bool same_point(const struct scratch *s, size_t a, size_t b)
{
	return s->x[a] == s->x[b] && s->y[a] == s->y[b];
}

/* Does any other remaining vertex lie in (or on) triangle (a, b, c)? Then it is no ear. */
static bool ear_blocked(const struct scratch *s, size_t cnt, size_t a, size_t b, size_t c,
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

static void live_remove(struct scratch *s, size_t *cnt, size_t i)
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
static void leaf_clip(struct mesh *m, struct scratch *s, size_t n, uint32_t base, double eps)
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
 * A leaf: the polygon projected onto its best-fit plane (Newell normal), ear-clipped there,
 * the 3D points kept as they are. One-sided, facing along the Newell normal.
 */
static int leaf_build(struct mesh *m, const struct leaf *l, struct scratch *s)
{
	struct vec3 c = vec3(0, 0, 0), nn = vec3(0, 0, 0), normal, u, v;
	double extent = 0.0, area2, eps;
	size_t k = 0;
	uint32_t base;
	int r;

	r = scratch_reserve(s, l->npoints);
	if (r < 0)
		return r;
	for (size_t i = 0; i < l->npoints; i++) {
		struct vec3 q = l->points[i];

		if (!vec3_finite(q))
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

	u = perpendicular(normal);
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

int tree_mesh_append(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
		     size_t first_leaf)
{
	struct scratch sc;
	int r = 0;

	memset(&sc, 0, sizeof(sc));
	for (size_t i = first_branch; i < t->nbranches && r == 0; i++)
		r = tube_build(&tm->bark, &t->branches[i], &sc);
	for (size_t i = first_leaf; i < t->nleaves && r == 0; i++)
		r = leaf_build(&tm->leaves, &t->leaves[i], &sc);

	scratch_finish(&sc);
	if (r < 0) {
		/* Half a tree is no tree. */
		mesh_clear(&tm->bark);
		mesh_clear(&tm->leaves);
	}
	return r;
}

int tree_mesh_build(struct tree_mesh *tm, const struct tree *t)
{
	mesh_clear(&tm->bark);
	mesh_clear(&tm->leaves);
	return tree_mesh_append(tm, t, 0, 0);
}
