/* SPDX-License-Identifier: MIT */
/* Tree meshes on the GPU: uploaded when the tree changes, drawn every frame; and the scratch
 * buffer their colours go up through. */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "render_private.h"

static void buffer_data(GLuint *name, GLenum target, size_t size, const void *data)
{
	if (!*name)
		glGenBuffers(1, name);
	glBindBuffer(target, *name);
	/* a zero-sized store is legal and keeps the name valid */
	glBufferData(target, (GLsizeiptr)size, size ? data : NULL, GL_STATIC_DRAW);
}

/*
 * Without 32-bit indices (GLES 2 lacking OES_element_index_uint), every triangle gets
 * its own three vertices and is drawn without indices: three times the memory, but no
 * splitting of meshes into 64k-vertex pieces. Mesa has 32-bit indices; this is the
 * fallback for small GLES 2 GPUs.
 */
static int upload_expanded(struct render_mesh *rm, const struct mesh *m)
{
	size_t n = m->nindices;
	float *positions = malloc((n ? n : 1) * 3 * sizeof(float));
	float *normals = malloc((n ? n : 1) * 3 * sizeof(float));

	if (!positions || !normals) {
		free(positions);
		free(normals);
		return -ENOMEM;
	}
	for (size_t i = 0; i < n; i++) {
		memcpy(positions + 3 * i, m->positions + 3 * (size_t)m->indices[i], 3 * sizeof(float));
		memcpy(normals + 3 * i, m->normals + 3 * (size_t)m->indices[i], 3 * sizeof(float));
	}
	buffer_data(&rm->positions, GL_ARRAY_BUFFER, n * 3 * sizeof(float), positions);
	buffer_data(&rm->normals, GL_ARRAY_BUFFER, n * 3 * sizeof(float), normals);
	free(positions);
	free(normals);
	rm->indexed = false;
	rm->bytes = 2 * n * 3 * sizeof(float);
	return 0;
}

int render_mesh_upload(struct render_mesh *rm, const struct mesh *m, bool uint_indices)
{
	int r = 0;

	rm->count = 0;
	rm->ntriangles = 0;
	rm->bytes = 0;
	/* colours belong to what was there before */
	glDeleteBuffers(1, &rm->tints);
	rm->tints = 0;
	if (m->nindices > INT_MAX || m->nindices % 3 != 0)
		return -EINVAL;
	/* an index past the vertices would read outside the buffer: refuse the mesh */
	for (size_t i = 0; i < m->nindices; i++) {
		if (m->indices[i] >= m->nvertices)
			return -EINVAL;
	}

	if (uint_indices) {
		buffer_data(&rm->positions, GL_ARRAY_BUFFER, m->nvertices * 3 * sizeof(float),
			    m->positions);
		buffer_data(&rm->normals, GL_ARRAY_BUFFER, m->nvertices * 3 * sizeof(float),
			    m->normals);
		buffer_data(&rm->indices, GL_ELEMENT_ARRAY_BUFFER, m->nindices * sizeof(uint32_t),
			    m->indices);
		rm->indexed = true;
		rm->bytes = 2 * m->nvertices * 3 * sizeof(float) + m->nindices * sizeof(uint32_t);
	} else {
		r = upload_expanded(rm, m);
		if (r < 0)
			return r;
	}
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
	rm->count = (GLsizei)m->nindices;
	rm->ntriangles = m->nindices / 3;
	return 0;
}

/* Without 32-bit indices the colours are expanded as the positions were. */
int render_mesh_upload_tints(struct render_mesh *rm, const struct mesh *m, const float *rgb)
{
	float *expanded = NULL;
	size_t n = m->nvertices;

	if (!rm->indexed) {
		n = m->nindices;
		expanded = malloc((n ? n : 1) * 3 * sizeof(float));
		if (!expanded)
			return -ENOMEM;
		for (size_t i = 0; i < n; i++)
			memcpy(expanded + 3 * i, rgb + 3 * (size_t)m->indices[i], 3 * sizeof(float));
		rgb = expanded;
	}
	buffer_data(&rm->tints, GL_ARRAY_BUFFER, n * 3 * sizeof(float), rgb);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	free(expanded);
	rm->bytes += n * 3 * sizeof(float);
	return 0;
}

void render_mesh_draw_tinted(struct render *r, const struct render_mesh *rm)
{
	if (rm->count == 0 || !rm->tints)
		return;
	glBindBuffer(GL_ARRAY_BUFFER, rm->tints);
	glVertexAttribPointer(ATTR_TINT, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	glEnableVertexAttribArray(ATTR_TINT);
	render_mesh_draw(r, rm);
	/* the other programs do not read it */
	glDisableVertexAttribArray(ATTR_TINT);
}

void render_mesh_draw(struct render *r, const struct render_mesh *rm)
{
	if (rm->count == 0)
		return;
	glBindBuffer(GL_ARRAY_BUFFER, rm->positions);
	glVertexAttribPointer(ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	glBindBuffer(GL_ARRAY_BUFFER, rm->normals);
	glVertexAttribPointer(ATTR_NORMAL, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	if (rm->indexed) {
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, rm->indices);
		glDrawElements(GL_TRIANGLES, rm->count, GL_UNSIGNED_INT, NULL);
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
	} else {
		glDrawArrays(GL_TRIANGLES, 0, rm->count);
	}
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	r->stats.draw_calls++;
	r->stats.triangles += rm->ntriangles;
	r->stats.tree_triangles += rm->ntriangles;
}

void render_mesh_finish(struct render_mesh *rm)
{
	/* deleting name 0 is a no-op */
	glDeleteBuffers(1, &rm->positions);
	glDeleteBuffers(1, &rm->normals);
	glDeleteBuffers(1, &rm->indices);
	glDeleteBuffers(1, &rm->tints);
	memset(rm, 0, sizeof(*rm));
}

float *render_tint_scratch(struct render *r, size_t n)
{
	if (n > r->tint_cap) {
		float *p = realloc(r->tint_scratch, n * sizeof(*p));

		if (!p)
			return NULL;
		r->tint_scratch = p;
		r->tint_cap = n;
	}
	return r->tint_scratch;
}
