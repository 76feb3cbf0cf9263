/* SPDX-License-Identifier: MIT */
/*
 * Twining vines (seed 004, issue 16): the support's index (src/vine/vine_support.c). For a pole
 * (a capped cylinder, 5 cm by 2 m) and a bumpy sphere (30 cm) of about 1k, 10k and 100k
 * triangles: the build, and a query (max 4 r, r = 2 mm: a few stem radii) from points
 * 0.5 r, 2 r and 20 r off the surface (along a triangle's normal from a point of it,
 * chosen by area), as the median of batches of QUERIES queries (ms a batch = us a query).
 * The batches walk a pool of points spread over the whole support, so each query starts
 * with cold caches: the worst case. Then a growth's worth of queries around the largest
 * pole, one after the other as a growth asks them: 8,000 axis points of a helix whose
 * axis is 2.5 r from the bark (the stem 1.5 r off it), 30 queries each within 2 r of the
 * axis point (a box of side 4 r about it), against the 100 ms for the whole
 * growth. Then the crossing query (vine_support_crosses): does a step of l/d = 7.5 mm (the
 * default vine's) from a point 2 r off the surface, in a random direction, meet a
 * triangle; a growth asks it for each new point, and for each smoothed point it moves.
 * Prints medians and growth with size.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "rng.h"
#include "vine_support.h"

#define R 0.002 /* the stem's radius */
#define QUERIES 1000
#define POOL 16384
#define POLE_R 0.05
#define POLE_H 2.0
#define SPHERE_R 0.3
#define STEP 0.0075 /* l/d: a new axis point's step */
#define DIRS 64

struct mesh {
	float *pos;
	uint32_t *idx;
	size_t nv, nt;
};

struct job {
	struct mesh m;
	struct vine_support *s;
	struct vec3 *pool;
	size_t next;
	double max;
	struct vec3 dirs[DIRS]; /* the crossing query's steps */
};

static volatile double sink;

static void mesh_alloc(struct mesh *m, size_t nv, size_t nt)
{
	m->pos = calloc(3 * nv, sizeof(*m->pos));
	m->idx = calloc(3 * nt, sizeof(*m->idx));
	if (!m->pos || !m->idx)
		exit(1);
	m->nv = m->nt = 0;
}

static void vertex(struct mesh *m, double x, double y, double z)
{
	m->pos[3 * m->nv] = (float)x;
	m->pos[3 * m->nv + 1] = (float)y;
	m->pos[3 * m->nv + 2] = (float)z;
	m->nv++;
}

static void triangle(struct mesh *m, size_t a, size_t b, size_t c)
{
	m->idx[3 * m->nt] = (uint32_t)a;
	m->idx[3 * m->nt + 1] = (uint32_t)b;
	m->idx[3 * m->nt + 2] = (uint32_t)c;
	m->nt++;
}

/* A capped pole of about n triangles, as square as they come. */
static void pole(struct mesh *m, size_t n)
{
	size_t sides = (size_t)lround(sqrt((double)n * 2 * VEC_PI * POLE_R / (2 * POLE_H)));
	size_t rings = n / (2 * sides), cb, ct;

	mesh_alloc(m, sides * (rings + 1) + 2, 2 * sides * rings + 2 * sides);
	for (size_t j = 0; j <= rings; j++)
		for (size_t i = 0; i < sides; i++) {
			double a = 2 * VEC_PI * (double)i / (double)sides;

			vertex(m, POLE_R * cos(a), POLE_H * (double)j / (double)rings,
			       POLE_R * sin(a));
		}
	cb = m->nv;
	ct = cb + 1;
	vertex(m, 0, 0, 0);
	vertex(m, 0, POLE_H, 0);
	for (size_t j = 0; j < rings; j++)
		for (size_t i = 0; i < sides; i++) {
			size_t b0 = j * sides + i, b1 = j * sides + (i + 1) % sides;

			triangle(m, b0, b1 + sides, b1);
			triangle(m, b0, b0 + sides, b1 + sides);
		}
	for (size_t i = 0; i < sides; i++) {
		triangle(m, cb, i, (i + 1) % sides);
		triangle(m, ct, rings * sides + (i + 1) % sides, rings * sides + i);
	}
}

/* A sphere with bumps of 10 % of its radius, of about n triangles (latitude rings, fans
 * at the poles). */
static void bumpy_sphere(struct mesh *m, size_t n)
{
	size_t lat = (size_t)lround(sqrt((double)n / 4)) + 1, lon = 2 * (lat - 1), np, sp;

	mesh_alloc(m, (lat - 1) * lon + 2, 2 * lon * (lat - 1));
	for (size_t j = 1; j < lat; j++)
		for (size_t i = 0; i < lon; i++) {
			double th = VEC_PI * (double)j / (double)lat;
			double ph = 2 * VEC_PI * (double)i / (double)lon;
			double r = SPHERE_R * (1 + 0.1 * sin(5 * th) * sin(7 * ph));

			vertex(m, r * sin(th) * cos(ph), r * cos(th), r * sin(th) * sin(ph));
		}
	np = m->nv;
	sp = np + 1;
	vertex(m, 0, SPHERE_R, 0);
	vertex(m, 0, -SPHERE_R, 0);
	for (size_t i = 0; i < lon; i++) {
		size_t i1 = (i + 1) % lon;

		triangle(m, np, i1, i);
		triangle(m, sp, (lat - 2) * lon + i, (lat - 2) * lon + i1);
		for (size_t j = 0; j + 2 < lat; j++) {
			size_t a = j * lon + i, b = j * lon + i1;

			triangle(m, a, b, b + lon);
			triangle(m, a, b + lon, a + lon);
		}
	}
}

static struct vec3 vtx(const struct mesh *m, size_t t, int k)
{
	const float *v = m->pos + 3 * (size_t)m->idx[3 * t + (size_t)k];

	return vec3(v[0], v[1], v[2]);
}

/* POOL points off the surface by off, from points chosen by area, along the triangle's
 * normal turned away from centre. */
static struct vec3 *query_pool(const struct mesh *m, double off, struct vec3 centre, uint64_t seed)
{
	struct vec3 *pool = calloc(POOL, sizeof(*pool));
	double *cum = calloc(m->nt, sizeof(*cum)), total = 0;
	struct rng r;

	if (!pool || !cum)
		exit(1);
	for (size_t t = 0; t < m->nt; t++) {
		struct vec3 a = vtx(m, t, 0);

		total += vec3_len(vec3_cross(vec3_sub(vtx(m, t, 1), a), vec3_sub(vtx(m, t, 2), a)));
		cum[t] = total;
	}
	rng_seed(&r, seed);
	for (size_t i = 0; i < POOL; i++) {
		double x = rng_uniform(&r) * total, u = rng_uniform(&r), v = rng_uniform(&r);
		size_t lo = 0, hi = m->nt - 1;
		struct vec3 a, ab, ac, p, nrm;

		while (lo < hi) {
			size_t mid = lo + (hi - lo) / 2;

			if (cum[mid] <= x)
				lo = mid + 1;
			else
				hi = mid;
		}
		if (u + v > 1) {
			u = 1 - u;
			v = 1 - v;
		}
		a = vtx(m, lo, 0);
		ab = vec3_sub(vtx(m, lo, 1), a);
		ac = vec3_sub(vtx(m, lo, 2), a);
		p = vec3_add(a, vec3_add(vec3_scale(ab, u), vec3_scale(ac, v)));
		nrm = vec3_norm_or(vec3_cross(ab, ac), vec3(0, 1, 0));
		if (vec3_dot(nrm, vec3_sub(p, centre)) < 0)
			nrm = vec3_scale(nrm, -1);
		pool[i] = vec3_add(p, vec3_scale(nrm, off));
	}
	free(cum);
	return pool;
}

static void build(void *arg)
{
	struct job *j = arg;
	struct vine_support *s;

	if (vine_support_create(j->m.pos, j->m.nv, j->m.idx, j->m.nt, &s) < 0)
		exit(1);
	vine_support_destroy(s);
}

static void queries(void *arg)
{
	struct job *j = arg;
	double sum = 0;

	for (int i = 0; i < QUERIES; i++) {
		struct vec3 q;
		size_t t;

		sum += vine_support_distance(j->s, j->pool[j->next], j->max, &q, &t);
		j->next = (j->next + 1) % POOL;
	}
	sink = sum;
}

static void crossings(void *arg)
{
	struct job *j = arg;
	int met = 0;

	for (int i = 0; i < QUERIES; i++) {
		struct vec3 p = j->pool[j->next];

		met += vine_support_crosses(j->s, p, vec3_add(p, j->dirs[(size_t)i % DIRS]));
		j->next = (j->next + 1) % POOL;
	}
	sink = met;
}

static void shape(const char *name, void (*make)(struct mesh *, size_t), struct vec3 centre)
{
	static const double offs[] = { 0.5 * R, 2 * R, 20 * R };
	static const size_t sizes[] = { 1000, 10000, 100000 };
	double pb = 0, ptb = 0, pq[4] = { 0 }, ptq[4] = { 0 };

	printf("# %s: the build (ms), and %d queries with max 4 r (ms; = us a query)\n", name,
	       QUERIES);
	for (size_t k = 0; k < BENCH_COUNT(sizes); k++) {
		struct job j = { .max = 4 * R };
		char row[64];

		make(&j.m, sizes[k]);
		snprintf(row, sizeof(row), "%s build, triangles", name);
		bench_row(row, (double)j.m.nt, bench_run(build, &j, bench_reps(sizes[k] > 10000 ? 11 : 31)),
			  &pb, &ptb);
		if (vine_support_create(j.m.pos, j.m.nv, j.m.idx, j.m.nt, &j.s) < 0)
			exit(1);
		for (int o = 0; o < 3; o++) {
			j.pool = query_pool(&j.m, offs[o], centre, 16 + (uint64_t)o);
			j.next = 0;
			snprintf(row, sizeof(row), "  query at %g r", offs[o] / R);
			bench_row(row, (double)j.m.nt, bench_run(queries, &j, bench_reps(3 * POOL / QUERIES)),
				  &pq[o], &ptq[o]);
			free(j.pool);
		}
		{
			struct rng r;

			rng_seed(&r, 40);
			for (int d = 0; d < DIRS; d++) {
				struct vec3 u = vec3(rng_range(&r, -1, 1), rng_range(&r, -1, 1),
						     rng_range(&r, -1, 1));

				j.dirs[d] = vec3_scale(vec3_norm_or(u, vec3(0, 1, 0)), STEP);
			}
			j.pool = query_pool(&j.m, 2 * R, centre, 20);
			j.next = 0;
			bench_row("  crossing a step from 2 r", (double)j.m.nt,
				  bench_run(crossings, &j, 3 * POOL / QUERIES), &pq[3], &ptq[3]);
			free(j.pool);
		}
		vine_support_destroy(j.s);
		free(j.m.pos);
		free(j.m.idx);
	}
}

struct growth {
	struct vine_support *s;
	struct vec3 *axis;
	struct vec3 *probe;
};

#define AXIS_POINTS 8000
#define PROBES 30

/* Each axis point asks about PROBES points around it, as a growth step would. */
static void growth(void *arg)
{
	struct growth *g = arg;
	double sum = 0;

	for (size_t i = 0; i < AXIS_POINTS; i++)
		for (size_t k = 0; k < PROBES; k++)
			sum += vine_support_distance(g->s, vec3_add(g->axis[i], g->probe[k]), 4 * R,
						     NULL, NULL);
	sink = sum;
}

static void growth_run(void)
{
	struct mesh m;
	struct growth g;
	struct rng r;
	double t;

	pole(&m, bench_quick ? 10000 : 100000);
	if (vine_support_create(m.pos, m.nv, m.idx, m.nt, &g.s) < 0)
		exit(1);
	g.axis = calloc(AXIS_POINTS, sizeof(*g.axis));
	g.probe = calloc(PROBES, sizeof(*g.probe));
	if (!g.axis || !g.probe)
		exit(1);
	/* 8,000 axis points (1,000 internodes of 8) up 1.6 m of pole, a turn every 25 cm */
	for (size_t i = 0; i < AXIS_POINTS; i++) {
		double y = 0.1 + 1.6 * (double)i / AXIS_POINTS, a = 2 * VEC_PI * y / 0.25;
		double rr = POLE_R + R + 1.5 * R;

		g.axis[i] = vec3(rr * cos(a), y, rr * sin(a));
	}
	rng_seed(&r, 30);
	for (size_t k = 0; k < PROBES; k++)
		g.probe[k] = vec3(rng_range(&r, -2 * R, 2 * R), rng_range(&r, -2 * R, 2 * R),
				  rng_range(&r, -2 * R, 2 * R));
	t = bench_run(growth, &g, bench_reps(7));
	printf("# a growth's queries around the %zu-triangle pole: %d axis points x %d queries, "
	       "max 4 r\n", m.nt, AXIS_POINTS, PROBES);
	printf("%-28s %10d %12.3f ms   (%.3f us a query)\n", "growth queries", AXIS_POINTS * PROBES,
	       t * 1e3, t * 1e6 / (AXIS_POINTS * PROBES));
	vine_support_destroy(g.s);
	free(g.axis);
	free(g.probe);
	free(m.pos);
	free(m.idx);
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	shape("pole", pole, vec3(0, 0.5 * POLE_H, 0));
	shape("bumpy sphere", bumpy_sphere, vec3(0, 0, 0));
	growth_run();
	return 0;
}
