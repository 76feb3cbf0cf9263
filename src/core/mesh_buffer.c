/* SPDX-License-Identifier: MIT */
#include "mesh_buffer.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

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

static size_t grow_cap(size_t cap, size_t need)
{
	size_t ncap = cap ? cap : 256;

	while (ncap < need)
		ncap *= 2;
	return ncap;
}

/* Makes room for nv more vertices and ni more indices, so that pushes cannot fail. */
int mesh_reserve(struct mesh *m, size_t nv, size_t ni)
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
