/* SPDX-License-Identifier: MIT */
#pragma once
/*
 * What a bark from wood_iso must be, checked on a part of a mesh (from vertex v0 and index
 * i0 on): closed and consistently turned, a manifold, no triangle without area, no two
 * vertices in one place, every vertex used, unit normals on the side of their faces; with
 * its volume, Euler characteristic and parts counted. For test_wood_iso's hand-made fields
 * and test_wood_press's pressed trees.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "test.h"
#include "vec.h"

struct iso_stats {
	size_t vertices, edges, faces;
	long euler;
	size_t components;
	double volume;   /* m^3, by the divergence theorem */
	double min_area; /* smallest triangle's, in h^2 */
	size_t normals_off; /* faces against their vertex normals' mean */
	size_t corners_off; /* vertex normals against one of their faces' (slivers) */
	size_t fans_off;    /* vertex normals against their faces' sum, by area */
};

static inline int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return (x > y) - (x < y);
}

static inline struct vec3 pos(const struct mesh *m, uint32_t v)
{
	return vec3(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
}

static inline struct vec3 nrm(const struct mesh *m, uint32_t v)
{
	return vec3(m->normals[3 * v], m->normals[3 * v + 1], m->normals[3 * v + 2]);
}

/* Each directed edge once, and each with its reverse: closed and consistently turned. */
static inline size_t check_edges(const struct mesh *m, size_t i0)
{
	size_t n = m->nindices - i0;
	uint64_t *e = malloc((n + 1) * sizeof(*e));

	CHECK(e);
	for (size_t t = 0; t < n; t += 3)
		for (int k = 0; k < 3; k++) {
			uint64_t a = m->indices[i0 + t + k], b = m->indices[i0 + t + (k + 1) % 3];

			e[t + k] = a << 32 | b;
		}
	qsort(e, n, sizeof(*e), cmp_u64);
	for (size_t i = 0; i < n; i++) {
		uint64_t rev = e[i] << 32 | e[i] >> 32;

		CHECK(i == 0 || e[i] != e[i - 1]);
		CHECK(bsearch(&rev, e, n, sizeof(*e), cmp_u64));
	}
	free(e);
	return n / 2;
}

/* About every vertex its triangles make one fan: the edges opposite it, b -> c in each
 * triangle (v, b, c), one cycle. */
static inline void check_fans(const struct mesh *m, size_t i0)
{
	size_t n = m->nindices - i0;
	uint64_t *c = malloc((n + 1) * sizeof(*c));
	uint32_t *bc = malloc((2 * n + 2) * sizeof(*bc));

	CHECK(c && bc);
	for (size_t t = 0; t < n; t += 3)
		for (int k = 0; k < 3; k++)
			c[t + k] = (uint64_t)m->indices[i0 + t + k] << 32 | (t + k);
	qsort(c, n, sizeof(*c), cmp_u64);
	for (size_t g = 0; g < n;) {
		size_t end = g, len = 0;
		uint32_t start, at;

		while (end < n && c[end] >> 32 == c[g] >> 32)
			end++;
		for (size_t i = g; i < end; i++) {
			size_t corner = (size_t)(c[i] & 0xffffffffu), t = corner - corner % 3;

			bc[2 * (i - g)] = m->indices[i0 + t + (corner % 3 + 1) % 3];
			bc[2 * (i - g) + 1] = m->indices[i0 + t + (corner % 3 + 2) % 3];
		}
		start = at = bc[0];
		do {
			size_t i = 0;

			while (i < end - g && bc[2 * i] != at)
				i++;
			CHECK(i < end - g);
			at = bc[2 * i + 1];
			len++;
			CHECK(len <= end - g);
		} while (at != start);
		CHECK_INT(len, end - g);
		g = end;
	}
	free(c);
	free(bc);
}

static inline int cmp_pos(const void *a, const void *b)
{
	const float *p = a, *q = b;

	for (int k = 0; k < 3; k++)
		if (p[k] != q[k])
			return (p[k] > q[k]) - (p[k] < q[k]);
	return 0;
}

/* No two vertices in one place. */
static inline void check_distinct(const struct mesh *m, size_t v0)
{
	size_t n = m->nvertices - v0;
	float *p = malloc((3 * n + 1) * sizeof(*p));

	CHECK(p);
	memcpy(p, m->positions + 3 * v0, 3 * n * sizeof(*p));
	qsort(p, n, 3 * sizeof(*p), cmp_pos);
	for (size_t i = 1; i < n; i++)
		CHECK(cmp_pos(p + 3 * (i - 1), p + 3 * i) != 0);
	free(p);
}

static inline size_t find(size_t *parent, size_t a)
{
	while (parent[a] != a)
		a = parent[a] = parent[parent[a]];
	return a;
}

/* The parts of the mesh joined through its triangles. */
static inline size_t components(const struct mesh *m, size_t v0, size_t i0)
{
	size_t n = m->nvertices - v0, count = 0;
	size_t *parent = malloc((n + 1) * sizeof(*parent));

	CHECK(parent);
	for (size_t i = 0; i < n; i++)
		parent[i] = i;
	for (size_t t = i0; t < m->nindices; t += 3)
		for (int k = 0; k < 2; k++) {
			size_t a = find(parent, m->indices[t + k] - v0);
			size_t b = find(parent, m->indices[t + k + 1] - v0);

			parent[a] = b;
		}
	for (size_t i = 0; i < n; i++)
		count += find(parent, i) == i;
	free(parent);
	return count;
}

/* The triangles' own checks: indices, area, volume, normals; every vertex used. */
static inline void check_triangles(const struct mesh *m, size_t v0, size_t i0, double h,
			    struct iso_stats *st)
{
	size_t n = m->nvertices - v0;
	char *used = calloc(n + 1, 1);
	double *fan = calloc(3 * n + 1, sizeof(*fan));

	CHECK(used && fan);
	st->min_area = INFINITY;
	for (size_t t = i0; t < m->nindices; t += 3) {
		const uint32_t *v = m->indices + t;
		struct vec3 p[3], f;
		double area;

		for (int k = 0; k < 3; k++) {
			CHECK(v[k] >= v0 && v[k] < m->nvertices);
			used[v[k] - v0] = 1;
			p[k] = pos(m, v[k]);
		}
		CHECK(v[0] != v[1] && v[1] != v[2] && v[2] != v[0]);
		f = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		area = 0.5 * vec3_len(f) / (h * h);
		CHECK(area > 1e-12);
		st->min_area = area < st->min_area ? area : st->min_area;
		st->volume += vec3_dot(p[0], vec3_cross(p[1], p[2])) / 6.0;
		for (int k = 0; k < 3; k++) {
			st->corners_off += vec3_dot(f, nrm(m, v[k])) <= 0.0;
			fan[3 * (v[k] - v0)] += f.x;
			fan[3 * (v[k] - v0) + 1] += f.y;
			fan[3 * (v[k] - v0) + 2] += f.z;
		}
		st->normals_off += vec3_dot(f, vec3_add(vec3_add(nrm(m, v[0]), nrm(m, v[1])),
							nrm(m, v[2]))) <= 0.0;
	}
	for (size_t i = 0; i < n; i++) {
		struct vec3 nv = nrm(m, (uint32_t)(v0 + i));

		CHECK(used[i]);
		CHECK(isfinite(nv.x) && isfinite(nv.y) && isfinite(nv.z));
		CHECK_NEAR(vec3_len(nv), 1.0, 1e-5);
		st->fans_off += vec3_dot(nv, vec3(fan[3 * i], fan[3 * i + 1], fan[3 * i + 2])) <= 0;
	}
	free(used);
	free(fan);
}

/* Everything a closed, oriented, manifold mesh without degenerate triangles is, for the
 * part of m from vertex v0 and index i0 on; its numbers into st. */
static inline void check_mesh(const struct mesh *m, size_t v0, size_t i0, double h, struct iso_stats *st)
{
	memset(st, 0, sizeof(*st));
	CHECK(m->nindices % 3 == 0);
	check_triangles(m, v0, i0, h, st);
	st->vertices = m->nvertices - v0;
	st->faces = (m->nindices - i0) / 3;
	st->edges = check_edges(m, i0);
	check_fans(m, i0);
	check_distinct(m, v0);
	st->components = components(m, v0, i0);
	st->euler = (long)st->vertices - (long)st->edges + (long)st->faces;
	/* wood_iso's promise, whatever the field */
	CHECK_INT(st->fans_off, 0);
}

