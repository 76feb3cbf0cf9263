/* SPDX-License-Identifier: MIT */
#pragma once

/* Geometry checks shared by the mesh and export tests (header-only, static functions). */

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "test.h"

/* Every position and normal finite, every normal unit length, every index in range. */
static inline void check_mesh_sane(const struct mesh *m)
{
	CHECK(m->nindices % 3 == 0);
	for (size_t i = 0; i < 3 * m->nvertices; i++) {
		CHECK(isfinite(m->positions[i]));
		CHECK(isfinite(m->normals[i]));
	}
	for (size_t i = 0; i < m->nvertices; i++) {
		const float *n = &m->normals[3 * i];

		CHECK_NEAR(sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]), 1.0,
			   1e-6);
	}
	for (size_t i = 0; i < m->nindices; i++)
		CHECK(m->indices[i] < m->nvertices);
}

static inline struct vec3 mesh_pos(const struct mesh *m, uint32_t i)
{
	return vec3(m->positions[3 * i], m->positions[3 * i + 1], m->positions[3 * i + 2]);
}

static inline struct vec3 mesh_nor(const struct mesh *m, uint32_t i)
{
	return vec3(m->normals[3 * i], m->normals[3 * i + 1], m->normals[3 * i + 2]);
}

/* Twice the area vector of triangle t (its geometric normal times 2 * area). */
static inline struct vec3 tri_cross(const struct mesh *m, size_t t)
{
	struct vec3 a = mesh_pos(m, m->indices[3 * t]);
	struct vec3 b = mesh_pos(m, m->indices[3 * t + 1]);
	struct vec3 c = mesh_pos(m, m->indices[3 * t + 2]);

	return vec3_cross(vec3_sub(b, a), vec3_sub(c, a));
}

struct edge {
	uint32_t a, b;
};

static inline int edge_cmp(const void *x, const void *y)
{
	const struct edge *e = x, *f = y;

	if (e->a != f->a)
		return e->a < f->a ? -1 : 1;
	return (e->b > f->b) - (e->b < f->b);
}

/*
 * Closed, consistently oriented surface: with vertices welded by exact position (caps have
 * their own vertices for their normals), every directed edge occurs once and its reverse
 * once. Returns the Euler characteristic V - E + F of the welded surface.
 */
static inline long check_closed_surface(const struct mesh *m)
{
	uint32_t *weld = calloc(m->nvertices ? m->nvertices : 1, sizeof(*weld));
	size_t ntri = m->nindices / 3, nv = 0;
	struct edge *edges = calloc(m->nindices ? m->nindices : 1, sizeof(*edges));

	CHECK(weld && edges);
	/* Quadratic welding is fine at test sizes. */
	for (uint32_t i = 0; i < m->nvertices; i++) {
		weld[i] = i;
		for (uint32_t j = 0; j < i; j++) {
			if (weld[j] == j && !memcmp(&m->positions[3 * i], &m->positions[3 * j],
						    3 * sizeof(float))) {
				weld[i] = j;
				break;
			}
		}
		nv += weld[i] == i;
	}
	for (size_t t = 0; t < ntri; t++) {
		for (int k = 0; k < 3; k++) {
			uint32_t a = weld[m->indices[3 * t + (size_t)k]];
			uint32_t b = weld[m->indices[3 * t + (size_t)(k + 1) % 3]];

			CHECK(a != b);
			edges[3 * t + (size_t)k] = (struct edge){ a, b };
		}
	}
	qsort(edges, m->nindices, sizeof(*edges), edge_cmp);
	for (size_t i = 0; i < m->nindices; i++) {
		struct edge rev = { edges[i].b, edges[i].a };

		/* each directed edge once ... */
		CHECK(i + 1 == m->nindices || edge_cmp(&edges[i], &edges[i + 1]) != 0);
		/* ... and its reverse exactly once */
		CHECK(bsearch(&rev, edges, m->nindices, sizeof(*edges), edge_cmp) != NULL);
	}
	free(weld);
	free(edges);
	/* E = 3F / 2 for a closed triangle surface */
	return (long)nv - (long)(m->nindices / 2) + (long)ntri;
}
