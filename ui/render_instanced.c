/* SPDX-License-Identifier: MIT */
/*
 * Leaves drawn instanced on GLES 3: one glDrawElementsInstanced a leaf shape
 * (leaf_instances.c), the instances' 3x4 matrices as three vec4 attributes with a divisor
 * of 1. The only file that needs GLES 3's entry points; render.c calls it only when the
 * context is GLES 3.
 */
#include <GLES3/gl3.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "leaf_instances.h"
#include "render_private.h"
#include "tree.h"

/*
 * GLSL ES 1.00 (GLES 3 takes it; divisors are vertex array state, not the shader's): the
 * tree program's vertex shader with the instance's matrix applied first. The matrix is a
 * rotation times a uniform scale, so it turns normals as it turns positions; normalised
 * here and again per fragment, lit by render_tree_fs exactly as the merged leaves are.
 */
static const char instanced_vs[] =
	"uniform mat4 u_mvp;\n"
	"attribute vec3 a_position;\n"
	"attribute vec3 a_normal;\n"
	"attribute vec4 a_row0;\n"
	"attribute vec4 a_row1;\n"
	"attribute vec4 a_row2;\n"
	"varying vec3 v_normal;\n"
	"void main() {\n"
	"	vec4 p = vec4(a_position, 1.0);\n"
	"	vec3 world = vec3(dot(a_row0, p), dot(a_row1, p), dot(a_row2, p));\n"
	"	v_normal = normalize(vec3(dot(a_row0.xyz, a_normal), dot(a_row1.xyz, a_normal),\n"
	"				  dot(a_row2.xyz, a_normal)));\n"
	"	gl_Position = u_mvp * vec4(world, 1.0);\n"
	"}\n";

#define MATRIX_BYTES (12 * sizeof(float))

int render_instanced_create(struct render *r)
{
	static const char *const attribs[] = { "a_position", "a_normal", "a_row0", "a_row1",
					       "a_row2" };
	static const GLuint locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_ROW0, ATTR_ROW0 + 1,
					    ATTR_ROW0 + 2 };
	struct render_instanced *in = &r->inst;

	leaf_instances_init(&in->li);
	in->program = render_program("instanced leaves", instanced_vs, render_tree_fs, attribs,
				     locations, 5);
	if (!in->program)
		return -1;
	in->mvp = glGetUniformLocation(in->program, "u_mvp");
	in->color = glGetUniformLocation(in->program, "u_color");
	in->light = glGetUniformLocation(in->program, "u_light");
	in->two_sided = glGetUniformLocation(in->program, "u_two_sided");
	return 0;
}

void render_instanced_clear(struct render *r)
{
	struct render_instanced *in = &r->inst;

	for (size_t k = 0; k < LEAF_INSTANCES_MAX_SHAPES; k++)
		render_mesh_finish(&in->shapes[k]);
	render_mesh_finish(&in->loose);
	glDeleteBuffers(1, &in->matrices);
	in->matrices = 0;
	in->nshapes = 0;
	leaf_instances_finish(&in->li);
}

void render_instanced_finish(struct render *r)
{
	render_instanced_clear(r);
	glDeleteProgram(r->inst.program);
	r->inst.program = 0;
}

static int upload(struct render *r, const struct leaf_instances *li, const struct mesh *merged)
{
	struct render_instanced *in = &r->inst;
	size_t k = 0;
	int ret = 0;

	for (size_t s = 0; s < li->nshapes && ret == 0; s++) {
		const struct leaf_shape *sh = &li->shapes[s];

		if (!sh->instanced)
			continue;
		ret = render_mesh_upload(&in->shapes[k], &sh->mesh, r->uint_indices);
		in->first[k] = sh->first;
		in->count[k] = sh->count;
		r->upload_bytes += in->shapes[k].bytes;
		k++;
	}
	/* nothing instanced: every leaf is loose, and the merged mesh is all of them */
	if (ret == 0)
		ret = render_mesh_upload(&in->loose, k ? &li->loose : merged, r->uint_indices);
	if (ret < 0)
		return ret;
	r->upload_bytes += in->loose.bytes;
	/* shapes gone since the last upload give their memory back */
	for (size_t j = k; j < LEAF_INSTANCES_MAX_SHAPES; j++)
		render_mesh_finish(&in->shapes[j]);
	if (li->ninstanced > (size_t)INT32_MAX / MATRIX_BYTES)
		return -ENOMEM;
	if (!in->matrices)
		glGenBuffers(1, &in->matrices);
	glBindBuffer(GL_ARRAY_BUFFER, in->matrices);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(li->ninstanced * MATRIX_BYTES),
		     li->ninstanced ? li->matrices : NULL, GL_STATIC_DRAW);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	r->upload_bytes += li->ninstanced * MATRIX_BYTES;
	in->nshapes = k;
	return 0;
}

int render_instanced_upload(struct render *r, const struct tree *t, const struct mesh *merged)
{
	int ret;

	r->inst.nshapes = 0;
	r->inst.loose.count = 0;
	ret = leaf_instances_build(&r->inst.li, t);
	if (ret == 0)
		ret = upload(r, &r->inst.li, merged);
	if (ret < 0) {
		r->inst.nshapes = 0;
		r->inst.loose.count = 0;
	}
	return ret;
}

void render_instanced_draw(struct render *r, const float mvp[16], const float light[3],
			   const float color[3])
{
	struct render_instanced *in = &r->inst;

	if (in->nshapes == 0)
		return;
	glUseProgram(in->program);
	glUniformMatrix4fv(in->mvp, 1, GL_FALSE, mvp);
	glUniform3fv(in->light, 1, light);
	glUniform3fv(in->color, 1, color);
	glUniform1i(in->two_sided, 1);
	glEnableVertexAttribArray(ATTR_NORMAL);
	for (GLuint i = 0; i < 3; i++) {
		glEnableVertexAttribArray(ATTR_ROW0 + i);
		glVertexAttribDivisor(ATTR_ROW0 + i, 1);
	}
	for (size_t k = 0; k < in->nshapes; k++) {
		const struct render_mesh *rm = &in->shapes[k];
		const char *at = (const char *)(uintptr_t)(in->first[k] * MATRIX_BYTES);

		if (rm->count == 0 || in->count[k] == 0)
			continue;
		glBindBuffer(GL_ARRAY_BUFFER, rm->positions);
		glVertexAttribPointer(ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, 0, NULL);
		glBindBuffer(GL_ARRAY_BUFFER, rm->normals);
		glVertexAttribPointer(ATTR_NORMAL, 3, GL_FLOAT, GL_FALSE, 0, NULL);
		glBindBuffer(GL_ARRAY_BUFFER, in->matrices);
		for (GLuint i = 0; i < 3; i++)
			glVertexAttribPointer(ATTR_ROW0 + i, 4, GL_FLOAT, GL_FALSE, MATRIX_BYTES,
					      at + 4 * sizeof(float) * i);
		if (rm->indexed) {
			glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, rm->indices);
			glDrawElementsInstanced(GL_TRIANGLES, rm->count, GL_UNSIGNED_INT, NULL,
						(GLsizei)in->count[k]);
			glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
		} else {
			glDrawArraysInstanced(GL_TRIANGLES, 0, rm->count, (GLsizei)in->count[k]);
		}
		r->stats.draw_calls++;
		r->stats.triangles += rm->ntriangles * in->count[k];
		r->stats.tree_triangles += rm->ntriangles * in->count[k];
	}
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	/* the other programs read attributes 0 and 1 only, per vertex */
	for (GLuint i = 0; i < 3; i++) {
		glVertexAttribDivisor(ATTR_ROW0 + i, 0);
		glDisableVertexAttribArray(ATTR_ROW0 + i);
	}
}
