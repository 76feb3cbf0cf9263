/* SPDX-License-Identifier: MIT */
/*
 * The vine's support (src/vine/vine_support.c) against a scan of every triangle: random meshes
 * of 1 to 20,000 triangles (small, large and degenerate ones, some sharing vertices) and
 * points on, near and far from them, with and without max; a capped pole and a unit cube
 * with known distances; degenerate triangles; the empty mesh; input it refuses; and every
 * allocation failing in turn. The scan's distance is computed here another way than the
 * index's (the plane's projection if it falls inside, else the nearest edge), so the two
 * check each other.
 */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fail_alloc.h"
#include "rng.h"
#include "test.h"
#include "vine_support.h"

#define EPS 1e-12
/* Nearest triangles nearer than this to each other are both "the nearest": no point is
 * compared then, only distances. */
#define UNIQUE 1e-9

struct mesh {
	float *pos;
	uint32_t *idx;
	size_t nv, nt, cap_v, cap_t;
};

static void mesh_vertex(struct mesh *m, struct vec3 v)
{
	if (m->nv == m->cap_v) {
		m->cap_v = m->cap_v ? 2 * m->cap_v : 64;
		m->pos = realloc(m->pos, m->cap_v * 3 * sizeof(*m->pos));
		CHECK(m->pos);
	}
	m->pos[3 * m->nv] = (float)v.x;
	m->pos[3 * m->nv + 1] = (float)v.y;
	m->pos[3 * m->nv + 2] = (float)v.z;
	m->nv++;
}

static void mesh_triangle(struct mesh *m, size_t a, size_t b, size_t c)
{
	if (m->nt == m->cap_t) {
		m->cap_t = m->cap_t ? 2 * m->cap_t : 64;
		m->idx = realloc(m->idx, m->cap_t * 3 * sizeof(*m->idx));
		CHECK(m->idx);
	}
	m->idx[3 * m->nt] = (uint32_t)a;
	m->idx[3 * m->nt + 1] = (uint32_t)b;
	m->idx[3 * m->nt + 2] = (uint32_t)c;
	m->nt++;
}

static void mesh_free(struct mesh *m)
{
	free(m->pos);
	free(m->idx);
	memset(m, 0, sizeof(*m));
}

static struct vec3 vtx(const struct mesh *m, size_t t, int k)
{
	const float *v = m->pos + 3 * (size_t)m->idx[3 * t + (size_t)k];

	return vec3(v[0], v[1], v[2]);
}

static struct vine_support *build(const struct mesh *m)
{
	struct vine_support *s = NULL;

	CHECK_INT(vine_support_create(m->pos, m->nv, m->idx, m->nt, &s), 0);
	CHECK(s);
	CHECK_INT(vine_support_triangles(s), m->nt);
	return s;
}

/* ---- The scan ---- */

static double ref_segment(struct vec3 p, struct vec3 a, struct vec3 b, struct vec3 *q)
{
	struct vec3 d = vec3_sub(b, a);
	double dd = vec3_dot(d, d), t = dd > 0 ? vec3_dot(vec3_sub(p, a), d) / dd : 0.0;

	t = fmin(fmax(t, 0.0), 1.0);
	*q = vec3_add(a, vec3_scale(d, t));
	return vec3_dist(p, *q);
}

/* The projection on the plane, if it is inside (on the inner side of every edge); else
 * the nearest edge. */
static double ref_triangle(struct vec3 p, struct vec3 a, struct vec3 b, struct vec3 c,
			   struct vec3 *q)
{
	struct vec3 n = vec3_cross(vec3_sub(b, a), vec3_sub(c, a)), qe;
	double nn = vec3_dot(n, n), d, de;

	if (nn > 0) {
		struct vec3 f = vec3_sub(p, vec3_scale(n, vec3_dot(vec3_sub(p, a), n) / nn));

		if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(f, a)), n) >= 0 &&
		    vec3_dot(vec3_cross(vec3_sub(c, b), vec3_sub(f, b)), n) >= 0 &&
		    vec3_dot(vec3_cross(vec3_sub(a, c), vec3_sub(f, c)), n) >= 0) {
			*q = f;
			return vec3_dist(p, f);
		}
	}
	d = ref_segment(p, a, b, q);
	if ((de = ref_segment(p, b, c, &qe)) < d) {
		d = de;
		*q = qe;
	}
	if ((de = ref_segment(p, c, a, &qe)) < d) {
		d = de;
		*q = qe;
	}
	return d;
}

static double ref_tri(const struct mesh *m, size_t t, struct vec3 p, struct vec3 *q)
{
	return ref_triangle(p, vtx(m, t, 0), vtx(m, t, 1), vtx(m, t, 2), q);
}

struct scan {
	double d, second; /* the nearest, and the nearest of the other triangles */
	size_t t;
	struct vec3 q;
};

static struct scan scan(const struct mesh *m, struct vec3 p)
{
	struct scan r = { INFINITY, INFINITY, SIZE_MAX, { 0, 0, 0 } };

	for (size_t t = 0; t < m->nt; t++) {
		struct vec3 q;
		double d = ref_tri(m, t, p, &q);

		if (d < r.d) {
			r.second = r.d;
			r.d = d;
			r.t = t;
			r.q = q;
		} else if (d < r.second) {
			r.second = d;
		}
	}
	return r;
}

/* One query against the scan: the answer, where, and that the outputs are optional. */
static void check_query(const struct vine_support *s, const struct mesh *m, struct vec3 p,
			double max)
{
	struct scan r = scan(m, p);
	struct vec3 q = vec3(-7, -7, -7), q2;
	size_t t = SIZE_MAX;
	double d = vine_support_distance(s, p, max, &q, &t), d2;

	if (r.d < max - EPS) {
		CHECK_NEAR(d, r.d, EPS);
		CHECK(d < max);
		CHECK(t < m->nt);
		/* where it says: on triangle t, at that distance */
		CHECK_NEAR(vec3_dist(p, q), d, EPS);
		CHECK_NEAR(ref_tri(m, t, q, &q2), 0.0, EPS);
		CHECK_NEAR(ref_tri(m, t, p, &q2), d, EPS);
		if (r.second - r.d > UNIQUE) {
			CHECK_INT(t, r.t);
			CHECK_NEAR(q.x, r.q.x, EPS);
			CHECK_NEAR(q.y, r.q.y, EPS);
			CHECK_NEAR(q.z, r.q.z, EPS);
		}
	} else if (r.d >= max + EPS) {
		CHECK(d >= max);
		CHECK(t == SIZE_MAX);
		CHECK(q.x == -7 && q.y == -7 && q.z == -7);
	} else {
		CHECK(d >= max || fabs(d - r.d) <= EPS);
	}
	/* the same without the outputs, to the bit */
	d2 = vine_support_distance(s, p, max, NULL, NULL);
	CHECK(d2 == d || (isnan(d) && isnan(d2)));
}

/* ---- Random meshes ---- */

static struct vec3 rnd_in(struct rng *r, double h)
{
	return vec3(rng_range(r, -h, h), rng_range(r, -h, h), rng_range(r, -h, h));
}

static struct vec3 rnd_dir(struct rng *r)
{
	for (;;) {
		struct vec3 v = rnd_in(r, 1.0);
		double l = vec3_len(v);

		if (l > 0.1 && l <= 1.0)
			return vec3_scale(v, 1.0 / l);
	}
}

/* n triangles in [-1, 1]^3: mostly small ones (1 mm to 10 cm), some large, some sharing
 * vertices with earlier ones, some without area (a point, a repeated vertex, collinear
 * vertices) and some slivers. */
static void random_mesh(struct mesh *m, struct rng *r, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		double kind = rng_uniform(r), size = pow(10.0, rng_range(r, -3, -1));
		struct vec3 c = rnd_in(r, 1.0), a, b;
		size_t v = m->nv;

		if (kind < 0.05) {
			size = rng_range(r, 0.3, 1.0);
		} else if (kind < 0.15 && m->nv >= 3) { /* reuses two earlier vertices */
			size_t i0 = (size_t)(rng_uniform(r) * (double)m->nv);
			size_t i1 = (size_t)(rng_uniform(r) * (double)m->nv);
			const float *p0 = m->pos + 3 * i0;

			mesh_vertex(m, vec3_add(vec3(p0[0], p0[1], p0[2]), rnd_in(r, size)));
			mesh_triangle(m, i0, i1, v);
			continue;
		} else if (kind < 0.17) { /* a point */
			mesh_vertex(m, c);
			mesh_triangle(m, v, v, v);
			continue;
		} else if (kind < 0.19) { /* a repeated vertex */
			mesh_vertex(m, c);
			mesh_vertex(m, c);
			mesh_vertex(m, vec3_add(c, rnd_in(r, size)));
			mesh_triangle(m, v, v + 1, v + 2);
			continue;
		} else if (kind < 0.21) { /* collinear, on an axis so exactly so in floats */
			a = vec3_add(c, vec3(rng_range(r, -size, size), 0, 0));
			mesh_vertex(m, c);
			mesh_vertex(m, a);
			mesh_vertex(m, vec3(0.5 * (c.x + a.x), c.y, c.z));
			mesh_triangle(m, v, v + 1, v + 2);
			continue;
		} else if (kind < 0.23) { /* a sliver */
			a = vec3_add(c, vec3_scale(rnd_dir(r), size));
			b = vec3_add(vec3_lerp(c, a, rng_uniform(r)),
				     vec3_scale(rnd_dir(r), size * 1e-6));
			mesh_vertex(m, c);
			mesh_vertex(m, a);
			mesh_vertex(m, b);
			mesh_triangle(m, v, v + 1, v + 2);
			continue;
		}
		for (int k = 0; k < 3; k++)
			mesh_vertex(m, vec3_add(c, rnd_in(r, size)));
		mesh_triangle(m, v, v + 1, v + 2);
	}
}

/* A point on triangle t, at barycentric coordinates chosen at random. */
static struct vec3 on_triangle(const struct mesh *m, struct rng *r, size_t t)
{
	double u = rng_uniform(r), v = rng_uniform(r);

	if (u + v > 1) {
		u = 1 - u;
		v = 1 - v;
	}
	return vec3_add(vtx(m, t, 0), vec3_add(vec3_scale(vec3_sub(vtx(m, t, 1), vtx(m, t, 0)), u),
					     vec3_scale(vec3_sub(vtx(m, t, 2), vtx(m, t, 0)), v)));
}

static struct vec3 query_point(const struct mesh *m, struct rng *r)
{
	double kind = rng_uniform(r);
	size_t t = (size_t)(rng_uniform(r) * (double)m->nt);

	if (kind < 0.15) /* on the surface */
		return on_triangle(m, r, t);
	if (kind < 0.25) /* at a vertex */
		return vtx(m, t, (int)(rng_uniform(r) * 3));
	if (kind < 0.7) /* near: 1 um to 10 cm off */
		return vec3_add(on_triangle(m, r, t),
				vec3_scale(rnd_dir(r), pow(10.0, rng_range(r, -6, -1))));
	if (kind < 0.95) /* anywhere about */
		return rnd_in(r, 3.0);
	return rnd_in(r, 1e3); /* far */
}

static void test_random(size_t n, int meshes, int queries, uint64_t seed)
{
	static const double maxes[] = { INFINITY, 1.0, 0.1, 0.01, 1e-3, 1e-5 };

	for (int i = 0; i < meshes; i++) {
		struct mesh m = { 0 };
		struct rng r;
		struct vine_support *s, *again;
		struct vec3 lo, hi, elo = vec3(INFINITY, INFINITY, INFINITY), ehi;

		rng_seed(&r, seed + (uint64_t)i);
		random_mesh(&m, &r, n);
		s = build(&m);
		again = build(&m);
		/* the box of every triangle's vertices */
		ehi = vec3_scale(elo, -1);
		for (size_t t = 0; t < m.nt; t++)
			for (int k = 0; k < 3; k++) {
				struct vec3 v = vtx(&m, t, k);

				elo = vec3(fmin(elo.x, v.x), fmin(elo.y, v.y), fmin(elo.z, v.z));
				ehi = vec3(fmax(ehi.x, v.x), fmax(ehi.y, v.y), fmax(ehi.z, v.z));
			}
		vine_support_bounds(s, &lo, &hi);
		CHECK(lo.x == elo.x && lo.y == elo.y && lo.z == elo.z);
		CHECK(hi.x == ehi.x && hi.y == ehi.y && hi.z == ehi.z);
		for (int j = 0; j < queries; j++) {
			struct vec3 p = query_point(&m, &r), q1, q2;
			double max = maxes[(size_t)j % (sizeof(maxes) / sizeof(maxes[0]))];
			size_t t1 = 0, t2 = 0;
			double d1, d2;

			check_query(s, &m, p, max);
			/* max right at the distance: in just above, out at it */
			if (j % 7 == 0) {
				double d = vine_support_distance(s, p, INFINITY, NULL, NULL);

				CHECK(vine_support_distance(s, p, d, NULL, NULL) >= d);
				if (d > 0)
					CHECK(vine_support_distance(s, p, nextafter(d, INFINITY),
								    NULL, NULL) == d);
			}
			/* the same mesh built again answers the same, to the bit */
			d1 = vine_support_distance(s, p, max, &q1, &t1);
			d2 = vine_support_distance(again, p, max, &q2, &t2);
			CHECK(d1 == d2 && t1 == t2);
			if (d1 < max)
				CHECK(q1.x == q2.x && q1.y == q2.y && q1.z == q2.z);
		}
		vine_support_destroy(again);
		vine_support_destroy(s);
		mesh_free(&m);
	}
}

/* ---- Known shapes ---- */

/* A pole: sides sides of radius r from y = 0 to y = h, capped by fans. */
static void cylinder(struct mesh *m, int sides, double radius, double h)
{
	for (int i = 0; i < sides; i++) {
		double a = 2 * VEC_PI * i / sides;

		mesh_vertex(m, vec3(radius * cos(a), 0, radius * sin(a)));
		mesh_vertex(m, vec3(radius * cos(a), h, radius * sin(a)));
	}
	mesh_vertex(m, vec3(0, 0, 0));
	mesh_vertex(m, vec3(0, h, 0));
	for (int i = 0; i < sides; i++) {
		size_t b0 = 2 * (size_t)i, t0 = b0 + 1;
		size_t b1 = 2 * (size_t)((i + 1) % sides), t1 = b1 + 1;
		size_t cb = 2 * (size_t)sides, ct = cb + 1;

		mesh_triangle(m, b0, b1, t1);
		mesh_triangle(m, b0, t1, t0);
		mesh_triangle(m, cb, b1, b0);
		mesh_triangle(m, ct, t0, t1);
	}
}

static double dist_at(const struct vine_support *s, struct vec3 p, double max, struct vec3 *q)
{
	return vine_support_distance(s, p, max, q, NULL);
}

static void test_pole(void)
{
	const int sides = 32;
	const double r = 0.02, h = 1.0, apothem = r * cos(VEC_PI / sides), half = VEC_PI / sides;
	struct mesh m = { 0 };
	struct vine_support *s;
	struct vec3 q, lo, hi;
	struct rng rg;

	cylinder(&m, sides, r, h);
	CHECK_INT(m.nt, 4 * sides);
	s = build(&m);
	vine_support_bounds(s, &lo, &hi);
	CHECK_NEAR(lo.x, -r, 1e-8);
	CHECK_NEAR(hi.x, r, 1e-8);
	CHECK(lo.y == 0 && hi.y == 1);
	/* beside a vertical edge (angle 0): the edge */
	CHECK_NEAR(dist_at(s, vec3(0.03, 0.5, 0), INFINITY, &q), 0.01, 1e-8);
	CHECK_NEAR(q.x, r, 1e-8);
	CHECK_NEAR(q.y, 0.5, 1e-12);
	/* beside a side's middle: the side, at the apothem */
	CHECK_NEAR(dist_at(s, vec3(0.05 * cos(half), 0.25, 0.05 * sin(half)), INFINITY, &q),
		   0.05 - apothem, 1e-8);
	CHECK_NEAR(vec3_len(vec3(q.x, 0, q.z)), apothem, 1e-8);
	/* inside, on the axis: the sides; near the bottom, the cap */
	CHECK_NEAR(dist_at(s, vec3(0, 0.5, 0), INFINITY, NULL), apothem, 1e-8);
	CHECK_NEAR(dist_at(s, vec3(0, 0.005, 0), INFINITY, &q), 0.005, 1e-12);
	CHECK(q.y == 0);
	/* above the top cap, and beyond its rim */
	CHECK_NEAR(dist_at(s, vec3(0.01, 1.03, 0.005), INFINITY, &q), 0.03, 1e-12);
	CHECK_NEAR(q.x, 0.01, 1e-12);
	CHECK_NEAR(q.z, 0.005, 1e-12);
	CHECK_NEAR(dist_at(s, vec3(0.07, 1.03, 0), INFINITY, &q), sqrt(0.05 * 0.05 + 0.03 * 0.03),
		   1e-8);
	CHECK(q.y == 1);
	/* max: 1 cm off is not within 9 mm, and is within 11 mm */
	q = vec3(5, 5, 5);
	CHECK(dist_at(s, vec3(0.03, 0.5, 0), 0.009, &q) >= 0.009);
	CHECK(q.x == 5 && q.y == 5 && q.z == 5);
	CHECK_NEAR(dist_at(s, vec3(0.03, 0.5, 0), 0.011, &q), 0.01, 1e-8);
	/* a vine's path: a helix 0.5 to 40 mm off the pole, a few stem radii of max */
	rng_seed(&rg, 16);
	for (int i = 0; i < 2000; i++) {
		double a = 0.05 * i, off = rng_range(&rg, 0.0005, 0.04);
		double y = rng_range(&rg, -0.1, 1.1);
		struct vec3 p = vec3((r + off) * cos(a), y, (r + off) * sin(a));

		check_query(s, &m, p, 0.008);
		check_query(s, &m, p, INFINITY);
	}
	vine_support_destroy(s);
	mesh_free(&m);
}

static void test_cube(void)
{
	/* [0, 1]^3, two triangles a face */
	static const uint32_t faces[6][4] = {
		{ 0, 1, 3, 2 }, { 4, 6, 7, 5 }, { 0, 4, 5, 1 },
		{ 2, 3, 7, 6 }, { 0, 2, 6, 4 }, { 1, 5, 7, 3 },
	};
	struct mesh m = { 0 };
	struct vine_support *s;
	struct vec3 q;
	size_t t = SIZE_MAX, lowest = SIZE_MAX;

	for (int i = 0; i < 8; i++) /* vertex i: x = bit 2, y = bit 1, z = bit 0 */
		mesh_vertex(&m, vec3(i >> 2 & 1, i >> 1 & 1, i & 1));
	for (int f = 0; f < 6; f++) {
		mesh_triangle(&m, faces[f][0], faces[f][1], faces[f][2]);
		mesh_triangle(&m, faces[f][0], faces[f][2], faces[f][3]);
	}
	s = build(&m);
	/* off a face, an edge, a corner; inside; on it */
	CHECK(vine_support_distance(s, vec3(0.5, 0.25, 1.25), INFINITY, &q, &t) == 0.25);
	CHECK(q.x == 0.5 && q.y == 0.25 && q.z == 1);
	CHECK_NEAR(vine_support_distance(s, vec3(1.5, 0.5, -0.5), INFINITY, &q, NULL), sqrt(0.5),
		   EPS);
	CHECK_NEAR(q.x, 1, EPS);
	CHECK_NEAR(q.y, 0.5, EPS);
	CHECK_NEAR(q.z, 0, EPS);
	CHECK(vine_support_distance(s, vec3(2, 2, 2), INFINITY, &q, &t) == sqrt(3.0));
	CHECK(q.x == 1 && q.y == 1 && q.z == 1);
	/* equal distances go to the lowest triangle: here the first with vertex 7 */
	for (size_t i = 0; i < m.nt && lowest == SIZE_MAX; i++)
		for (int k = 0; k < 3; k++)
			if (m.idx[3 * i + (size_t)k] == 7)
				lowest = i;
	CHECK_INT(t, lowest);
	CHECK(vine_support_distance(s, vec3(0.5, 0.5, 0.5), INFINITY, NULL, &t) == 0.5);
	CHECK_INT(t, 0);
	CHECK(vine_support_distance(s, vec3(0.3, 0.7, 1.0), INFINITY, &q, NULL) == 0);
	CHECK(vine_support_distance(s, vec3(0.2, 0.4, 0.6), 0.1, NULL, NULL) >= 0.1);
	CHECK_NEAR(vine_support_distance(s, vec3(0.2, 0.4, 0.6), 0.3, NULL, NULL), 0.2, EPS);
	/* max: "below max", so a distance of max is not found */
	q = vec3(9, 9, 9);
	t = 99;
	CHECK(vine_support_distance(s, vec3(0.5, 0.25, 1.25), 0.25, &q, &t) >= 0.25);
	CHECK(q.x == 9 && t == 99);
	CHECK(vine_support_distance(s, vec3(0.5, 0.25, 1.25), nextafter(0.25, 1), &q, &t) == 0.25);
	/* no max, a NaN max, a point not finite: nothing */
	q = vec3(9, 9, 9);
	t = 99;
	CHECK(vine_support_distance(s, vec3(0.5, 0.25, 1.25), 0, NULL, NULL) >= 0);
	CHECK(vine_support_distance(s, vec3(0.5, 0.25, 1.25), -1, NULL, NULL) >= -1);
	CHECK(isnan(vine_support_distance(s, vec3(0.5, 0.25, 1.25), NAN, &q, &t)));
	CHECK(vine_support_distance(s, vec3(NAN, 0, 0), INFINITY, &q, &t) >= INFINITY);
	CHECK(vine_support_distance(s, vec3(0, -INFINITY, 0), 1, &q, &t) >= 1);
	CHECK(q.x == 9 && t == 99);
	vine_support_destroy(s);
	mesh_free(&m);
}

/* Triangles at x = 2^-i/2, each the size of its distance to the origin: the area
 * heuristic would peel them off one or a few at a time, 240 deep; the median takes over
 * past depth 32 and the queries' stack still suffices. */
static void test_deep(void)
{
	struct mesh m = { 0 };
	struct vine_support *s;
	struct rng r;

	for (int i = 0; i < 240; i++) {
		double x = pow(2.0, -0.5 * i);
		size_t v = m.nv;

		mesh_vertex(&m, vec3(x, 0, 0));
		mesh_vertex(&m, vec3(1.1 * x, 0.1 * x, 0));
		mesh_vertex(&m, vec3(x, 0, 0.1 * x));
		mesh_triangle(&m, v, v + 1, v + 2);
	}
	s = build(&m);
	rng_seed(&r, 240);
	for (int i = 0; i < 2000; i++) {
		size_t t = (size_t)(rng_uniform(&r) * (double)m.nt);
		double x = vtx(&m, t, 0).x;
		struct vec3 p = vec3_add(on_triangle(&m, &r, t),
					 vec3_scale(rnd_dir(&r), x * rng_uniform(&r)));

		check_query(s, &m, p, i % 2 ? INFINITY : 0.5 * x);
	}
	vine_support_destroy(s);
	mesh_free(&m);
}

/* ---- Degenerate triangles, the empty mesh, refused input ---- */

static void test_degenerate(void)
{
	static const float pos[] = {
		0.1f, 0.2f, 0.3f,  /* 0: a point */
		0, 0, 0, 1, 0, 0, 0.25f, 0, 0, /* 1-3: collinear */
		5, 5, 5, 5, 5, 6,  /* 4, 5: a segment, as a repeated vertex */
	};
	static const uint32_t point[] = { 0, 0, 0 }, line[] = { 1, 2, 3 }, seg[] = { 4, 4, 5 },
			      seg2[] = { 5, 4, 5 };
	struct vine_support *s;
	struct vec3 q, v0 = vec3(0.1f, 0.2f, 0.3f);
	size_t t = 99;

	CHECK_INT(vine_support_create(pos, 6, point, 1, &s), 0);
	CHECK(vine_support_distance(s, vec3(1, 2, 3), INFINITY, &q, &t) ==
	      vec3_dist(vec3(1, 2, 3), v0));
	CHECK(q.x == v0.x && q.y == v0.y && q.z == v0.z);
	CHECK_INT(t, 0);
	CHECK(vine_support_distance(s, v0, 1e-9, &q, &t) == 0);
	vine_support_destroy(s);

	CHECK_INT(vine_support_create(pos, 6, line, 1, &s), 0);
	CHECK(vine_support_distance(s, vec3(0.5, 1, 0), INFINITY, &q, NULL) == 1);
	CHECK(q.x == 0.5 && q.y == 0 && q.z == 0);
	CHECK(vine_support_distance(s, vec3(2, 0, 0), INFINITY, &q, NULL) == 1);
	CHECK(q.x == 1);
	CHECK(vine_support_distance(s, vec3(-3, 4, 0), INFINITY, &q, NULL) == 5);
	CHECK(q.x == 0);
	vine_support_destroy(s);

	for (int i = 0; i < 2; i++) {
		CHECK_INT(vine_support_create(pos, 6, i ? seg2 : seg, 1, &s), 0);
		CHECK(vine_support_distance(s, vec3(5, 8, 5.5), INFINITY, &q, NULL) == 3);
		CHECK(q.x == 5 && q.y == 5 && q.z == 5.5);
		CHECK(vine_support_distance(s, vec3(5, 5, 10), INFINITY, &q, NULL) == 4);
		vine_support_destroy(s);
	}

	/* many degenerate triangles, all in the same place */
	{
		struct mesh m = { 0 };
		struct rng r;

		rng_seed(&r, 3);
		for (int i = 0; i < 300; i++) {
			mesh_vertex(&m, vec3(0.5, 0.5, 0.5));
			mesh_triangle(&m, 0, 0, 0);
			mesh_triangle(&m, 0, (size_t)i, (size_t)i);
		}
		s = build(&m);
		CHECK(vine_support_distance(s, vec3(0.5, 1.5, 0.5), INFINITY, NULL, &t) == 1);
		CHECK_INT(t, 0);
		for (int i = 0; i < 100; i++)
			check_query(s, &m, rnd_in(&r, 2), i % 2 ? 1.0 : INFINITY);
		vine_support_destroy(s);
		mesh_free(&m);
	}
}

static void test_empty(void)
{
	static const float pos[] = { 1, 2, 3 };
	struct vine_support *s = NULL;
	struct vec3 q = vec3(4, 4, 4), lo, hi;
	size_t t = 4;

	for (int i = 0; i < 2; i++) {
		CHECK_INT(vine_support_create(i ? pos : NULL, i ? 1 : 0, NULL, 0, &s), 0);
		CHECK_INT(vine_support_triangles(s), 0);
		vine_support_bounds(s, &lo, &hi);
		CHECK(lo.x == 0 && lo.y == 0 && lo.z == 0 && hi.x == 0 && hi.y == 0 && hi.z == 0);
		CHECK(vine_support_distance(s, vec3(1, 2, 3), 1.0, &q, &t) >= 1.0);
		CHECK(vine_support_distance(s, vec3(1, 2, 3), INFINITY, &q, &t) >= INFINITY);
		CHECK(q.x == 4 && t == 4);
		CHECK(!vine_support_crosses(s, vec3(-5, -5, -5), vec3(5, 5, 5)));
		vine_support_destroy(s);
	}
	vine_support_destroy(NULL);
}

/* ---- Crossing ---- */

/*
 * Whether segment a-b meets triangle t, worked out here another way (Cramer's rule for
 * a + s (b - a) = p0 + u e1 + v e2): 1 it does, with every coordinate at least EDGE inside
 * its range; 0 it does not, one coordinate EDGE or more outside; -1 too near an edge, an
 * end or the plane to tell. Triangles without area (exactly) are never met.
 */
#define EDGE 1e-6
static int ref_crosses(const struct mesh *m, size_t t, struct vec3 a, struct vec3 b)
{
	struct vec3 p0 = vtx(m, t, 0), e1 = vec3_sub(vtx(m, t, 1), p0), e2 = vec3_sub(vtx(m, t, 2), p0);
	struct vec3 d = vec3_sub(b, a), n = vec3_cross(e1, e2), w = vec3_sub(a, p0);
	double det = -vec3_dot(d, n), sc, u, v, scale;

	if (n.x == 0 && n.y == 0 && n.z == 0)
		return 0;
	scale = vec3_len(d) * vec3_len(n);
	if (fabs(det) <= 1e-9 * scale)
		return -1; /* (nearly) parallel to the plane */
	sc = vec3_dot(w, n) / det;
	u = -vec3_dot(d, vec3_cross(w, e2)) / det;
	v = -vec3_dot(d, vec3_cross(e1, w)) / det;
	if (sc < -EDGE || sc > 1 + EDGE || u < -EDGE || v < -EDGE || u + v > 1 + EDGE)
		return 0;
	if (sc > EDGE && sc < 1 - EDGE && u > EDGE && v > EDGE && u + v < 1 - EDGE)
		return 1;
	return -1;
}

/* The scan: 1 some triangle is met, 0 none is, -1 none clearly is and one may be. */
static int ref_scan_crosses(const struct mesh *m, struct vec3 a, struct vec3 b)
{
	int any = 0;

	for (size_t t = 0; t < m->nt; t++) {
		int c = ref_crosses(m, t, a, b);

		if (c == 1)
			return 1;
		if (c < 0)
			any = -1;
	}
	return any;
}

/* Random meshes and segments (short, long, from on the surface): the index says what the
 * scan says, wherever the scan can tell. */
static void test_crosses_random(void)
{
	long told = 0, met = 0;

	for (int i = 0; i < 40; i++) {
		struct mesh m = { 0 };
		struct rng r;
		struct vine_support *s;

		rng_seed(&r, 5000 + (uint64_t)i);
		random_mesh(&m, &r, i < 20 ? 50 : 2000);
		s = build(&m);
		for (int j = 0; j < 400; j++) {
			struct vec3 a = query_point(&m, &r), b;
			double kind = rng_uniform(&r);
			int want;

			if (kind < 0.4)
				b = vec3_add(a, vec3_scale(rnd_dir(&r), pow(10.0, rng_range(&r, -4, -1))));
			else if (kind < 0.8)
				b = rnd_in(&r, 1.5);
			else
				b = on_triangle(&m, &r, (size_t)(rng_uniform(&r) * (double)m.nt));
			want = ref_scan_crosses(&m, a, b);
			if (want < 0)
				continue;
			told++;
			met += want;
			CHECK(vine_support_crosses(s, a, b) == (want == 1));
			CHECK(vine_support_crosses(s, b, a) == (want == 1));
		}
		vine_support_destroy(s);
		mesh_free(&m);
	}
	printf("crossing: %ld random segments told by the scan, %ld meeting a triangle\n", told,
	       met);
	CHECK(met > told / 10 && met < told - told / 10);
}

/*
 * A closed mesh has no gap: every segment from inside the unit cube, or the pole, to
 * outside it meets it, through a face, an edge, a vertex (exactly), or ending on it; a
 * segment outside that passes it by does not; a point not finite meets nothing.
 */
static void test_crosses_closed(void)
{
	static const uint32_t faces[6][4] = {
		{ 0, 1, 3, 2 }, { 4, 6, 7, 5 }, { 0, 4, 5, 1 },
		{ 2, 3, 7, 6 }, { 0, 2, 6, 4 }, { 1, 5, 7, 3 },
	};
	struct mesh m = { 0 };
	struct vine_support *s;
	struct rng r;
	struct vec3 c = vec3(0.5, 0.5, 0.5);

	for (int i = 0; i < 8; i++)
		mesh_vertex(&m, vec3(i >> 2 & 1, i >> 1 & 1, i & 1));
	for (int f = 0; f < 6; f++) {
		mesh_triangle(&m, faces[f][0], faces[f][1], faces[f][2]);
		mesh_triangle(&m, faces[f][0], faces[f][2], faces[f][3]);
	}
	s = build(&m);
	/* through every vertex, every edge's middle and every face's centre, exactly */
	for (int i = 0; i < 8; i++) {
		struct vec3 v = vec3(i >> 2 & 1, i >> 1 & 1, i & 1);

		CHECK(vine_support_crosses(s, c, vec3_add(c, vec3_scale(vec3_sub(v, c), 3))));
		for (int j = 0; j < 8; j++) {
			struct vec3 e = vec3_scale(vec3_add(v, vec3(j >> 2 & 1, j >> 1 & 1, j & 1)), 0.5);

			if (vec3_dist(e, c) == 0)
				continue; /* opposite corners: their middle is the centre */
			CHECK(vine_support_crosses(s, c, vec3_add(c, vec3_scale(vec3_sub(e, c), 2.5))));
			CHECK(vine_support_crosses(s, vec3_add(c, vec3_scale(vec3_sub(e, c), 2.5)), c));
		}
	}
	CHECK(vine_support_crosses(s, vec3(0.3, 0.4, 2), vec3(0.3, 0.4, 1))); /* ends on it */
	CHECK(vine_support_crosses(s, vec3(0.3, 0.5, 1.5), vec3(0.3, 1.5, 0.5))); /* grazes an edge */
	CHECK(!vine_support_crosses(s, vec3(2, 2, 2), vec3(2, -1, 2)));
	CHECK(!vine_support_crosses(s, vec3(0.5, 1.5, 0.5), vec3(1.5, 1.001, -0.5)));
	CHECK(!vine_support_crosses(s, c, vec3(0.9, 0.1, 0.2))); /* inside, all of it */
	CHECK(!vine_support_crosses(s, vec3(NAN, 0, 0), c));
	CHECK(!vine_support_crosses(s, c, vec3(0, INFINITY, 0)));
	vine_support_destroy(s);
	mesh_free(&m);

	/* the pole: from its axis out, at random, thousands of times */
	cylinder(&m, 7, 0.02, 1.0);
	s = build(&m);
	rng_seed(&r, 77);
	for (int i = 0; i < 20000; i++) {
		struct vec3 in = vec3(rng_range(&r, -0.009, 0.009), rng_range(&r, 0.01, 0.99),
				      rng_range(&r, -0.009, 0.009));
		struct vec3 out = vec3_add(in, vec3_scale(rnd_dir(&r), rng_range(&r, 0.01, 2)));

		if (hypot(out.x, out.z) <= 0.02 && out.y >= 0 && out.y <= 1)
			continue; /* not outside the circle round it: perhaps inside */
		CHECK(vine_support_crosses(s, in, out));
		CHECK(vine_support_crosses(s, out, in));
	}
	vine_support_destroy(s);
	mesh_free(&m);
}

static void test_refused(void)
{
	float pos[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
	uint32_t idx[] = { 0, 1, 2 }, bad[] = { 0, 1, 3 }, huge[] = { 0, 1, UINT32_MAX };
	struct vine_support *keep = (struct vine_support *)pos, *s = keep;
	const float bad_values[] = { NAN, INFINITY, -INFINITY };

	CHECK_INT(vine_support_create(pos, 3, bad, 1, &s), -EINVAL);
	CHECK_INT(vine_support_create(pos, 3, huge, 1, &s), -EINVAL);
	CHECK_INT(vine_support_create(pos, 0, idx, 1, &s), -EINVAL);
	for (size_t i = 0; i < 3; i++) {
		pos[4] = bad_values[i];
		CHECK_INT(vine_support_create(pos, 3, idx, 1, &s), -EINVAL);
		/* not used by a triangle, and still not a position */
		CHECK_INT(vine_support_create(pos, 3, NULL, 0, &s), -EINVAL);
	}
	pos[4] = 0;
	CHECK_INT(vine_support_create(NULL, 3, idx, 1, &s), -EINVAL);
	CHECK_INT(vine_support_create(pos, 3, NULL, 1, &s), -EINVAL);
	CHECK_INT(vine_support_create(pos, 3, idx, 1, NULL), -EINVAL);
	/* sizes no array can have, refused before they are read */
	CHECK_INT(vine_support_create(pos, 3, idx, SIZE_MAX, &s), -ENOMEM);
	CHECK_INT(vine_support_create(pos, 3, idx, SIZE_MAX / 3 + 1, &s), -ENOMEM);
	CHECK_INT(vine_support_create(pos, SIZE_MAX / 3 + 1, idx, 1, &s), -ENOMEM);
	if (SIZE_MAX > UINT32_MAX)
		CHECK_INT(vine_support_create(pos, 3, idx, (size_t)UINT32_MAX + 1, &s), -ENOMEM);
	CHECK(s == keep);
	CHECK_INT(vine_support_create(pos, 3, idx, 1, &s), 0);
	CHECK(s != keep);
	vine_support_destroy(s);
}

#if FAIL_ALLOC_HOOK
/* Every allocation failing in turn: -ENOMEM, *out untouched, nothing kept. */
static void test_oom(void)
{
	struct mesh m = { 0 };
	struct rng r;

	if (!fail_alloc_hooked())
		return;
	rng_seed(&r, 99);
	random_mesh(&m, &r, 1000);
	for (size_t nt = 0; nt <= m.nt; nt += nt < 3 ? 1 : m.nt - 3) {
		for (long n = 0;; n++) {
			struct vine_support *keep = (struct vine_support *)&m, *s = keep;
			long before = fail_alloc_live();
			int ret;

			fail_alloc_at(n);
			ret = vine_support_create(m.pos, m.nv, m.idx, nt, &s);
			fail_alloc_off();
			if (ret < 0) {
				CHECK_INT(ret, -ENOMEM);
				CHECK(s == keep);
			} else {
				CHECK_INT(ret, 0);
				CHECK_INT(vine_support_triangles(s), nt);
				if (nt > 0)
					CHECK(vine_support_distance(s, vtx(&m, 0, 1), 1.0, NULL,
								    NULL) == 0);
				vine_support_destroy(s);
			}
			CHECK_INT(fail_alloc_live(), before);
			if (fail_alloc_calls() <= n) {
				CHECK_INT(ret, 0);
				break;
			}
		}
	}
	mesh_free(&m);
}
#else
static void test_oom(void)
{
}
#endif

int main(void)
{
	test_cube();
	test_pole();
	test_deep();
	test_degenerate();
	test_empty();
	test_refused();
	test_random(1, 200, 60, 1000);
	test_random(10, 50, 200, 2000);
	test_random(1000, 4, 2000, 3000);
	test_random(20000, 1, 600, 4000);
	test_crosses_closed();
	test_crosses_random();
	test_oom();
	return 0;
}
