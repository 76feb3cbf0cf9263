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
#include <stdlib.h>
#include <string.h>

#include "leaf_instances.h"
#include "leaf_tint.h"
#include "render_private.h"
#include "tree.h"

/*
 * GLSL ES 1.00 (GLES 3 takes it; divisors are vertex array state, not the shader's): the
 * tree program's vertex shader with the instance's matrix applied first. The matrix is a
 * rotation times a uniform scale, so it turns normals as it turns positions; normalised
 * here and again per fragment, lit by render_tree_fs exactly as the merged leaves are.
 */
#define INSTANCED_VS                                                                       \
	"uniform mat4 u_mvp;\n"                                                            \
	"attribute vec3 a_position;\n"                                                     \
	"attribute vec3 a_normal;\n"                                                       \
	"attribute vec4 a_row0;\n"                                                         \
	"attribute vec4 a_row1;\n"                                                         \
	"attribute vec4 a_row2;\n"                                                         \
	"varying vec3 v_normal;\n"                                                         \
	RENDER_TINT_VS_DECLS                                                               \
	RENDER_LIVE_VS_DECLS                                                               \
	"void main() {\n"                                                                  \
	RENDER_TINT_VS_PASS                                                                \
	"	vec4 p = vec4(a_position, 1.0);\n"                                        \
	"	vec3 world = vec3(dot(a_row0, p), dot(a_row1, p), dot(a_row2, p));\n"     \
	"	v_normal = normalize(vec3(dot(a_row0.xyz, a_normal), dot(a_row1.xyz, a_normal),\n" \
	"				  dot(a_row2.xyz, a_normal)));\n"                 \
	"#ifdef LIVE\n"                                                                    \
	"	world = live_move(world);\n"                                              \
	"#endif\n"                                                                         \
	"	gl_Position = u_mvp * vec4(world, 1.0);\n"                                \
	"}\n"

static const char instanced_vs[] = INSTANCED_VS;
/* the colour of each instance comes per instance too (spring, autumn) */
static const char instanced_tinted_vs[] = "#define TINT\n" INSTANCED_VS;
/* the living leaves: a leaf's skeleton data per instance (render_live.c) */
static const char instanced_live_vs[] = "#define LIVE\n" INSTANCED_VS;
static const char instanced_live_tinted_vs[] = "#define LIVE\n#define TINT\n" INSTANCED_VS;

#define MATRIX_BYTES (12 * sizeof(float))

int render_instanced_create(struct render *r)
{
	static const char *const attribs[] = { "a_position", "a_normal", "a_row0", "a_row1",
					       "a_row2", "a_tint" };
	static const GLuint locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_ROW0, ATTR_ROW0 + 1,
					    ATTR_ROW0 + 2, ATTR_TINT };
	static const char *const live_attribs[] = { "a_position", "a_normal", "a_row0", "a_row1",
						    "a_row2", "a_tint", "a_live0", "a_live1",
						    "a_phase", "a_flutter" };
	static const GLuint live_locations[] = { ATTR_POSITION, ATTR_NORMAL, ATTR_ROW0,
						 ATTR_ROW0 + 1, ATTR_ROW0 + 2, ATTR_TINT,
						 ATTR_INST_LIVE, ATTR_INST_LIVE + 1,
						 ATTR_INST_LIVE + 2, ATTR_INST_LIVE + 3 };
	struct render_instanced *in = &r->inst;

	leaf_instances_init(&in->li);
	if (!render_program_tree_init(&in->plain, "instanced leaves", instanced_vs, render_tree_fs,
				      attribs, locations, 5) ||
	    !render_program_tree_init(&in->tinted, "instanced tinted leaves", instanced_tinted_vs,
				      render_tinted_fs, attribs, locations, 6))
		return -1;
	/* without them, a tree with instanced leaves stands still (render_live_begin) */
	if (render_program_tree_init(&in->live.tree, "instanced living leaves", instanced_live_vs,
				     render_live_fs, live_attribs, live_locations, 10) &&
	    render_program_tree_init(&in->live_tinted.tree, "instanced living tinted leaves",
				     instanced_live_tinted_vs, render_live_tinted_fs, live_attribs,
				     live_locations, 10)) {
		render_live_program_locate(&in->live);
		render_live_program_locate(&in->live_tinted);
	} else {
		glDeleteProgram(in->live.tree.program);
		in->live.tree.program = 0;
	}
	return 0;
}

void render_instanced_clear(struct render *r)
{
	struct render_instanced *in = &r->inst;

	for (size_t k = 0; k < LEAF_INSTANCES_MAX_SHAPES; k++) {
		render_mesh_finish(&in->shapes[k]);
		for (size_t j = 0; j < ORI_UNFOLD_FRAMES; j++)
			render_mesh_finish(&in->frames[k][j]);
		in->has_frames[k] = false;
	}
	render_mesh_finish(&in->loose);
	glDeleteBuffers(1, &in->matrices);
	glDeleteBuffers(1, &in->tints);
	in->matrices = 0;
	in->tints = 0;
	in->nshapes = 0;
	render_instanced_grow_drop(r);
	leaf_instances_finish(&in->li);
}

void render_instanced_finish(struct render *r)
{
	render_instanced_clear(r);
	free(r->inst.grow_order);
	free(r->inst.grow_d);
	r->inst.grow_order = NULL;
	r->inst.grow_d = NULL;
	r->inst.grow_cap = 0;
	glDeleteProgram(r->inst.plain.program);
	glDeleteProgram(r->inst.tinted.program);
	glDeleteProgram(r->inst.live.tree.program);
	glDeleteProgram(r->inst.live_tinted.tree.program);
	r->inst.plain.program = 0;
	r->inst.tinted.program = 0;
	r->inst.live.tree.program = 0;
	r->inst.live_tinted.tree.program = 0;
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
		in->has_frames[k] = sh->frames != NULL;
		for (size_t j = 0; j < ORI_UNFOLD_FRAMES; j++) {
			if (!sh->frames) {
				render_mesh_finish(&in->frames[k][j]);
				continue;
			}
			if (ret == 0)
				ret = render_mesh_upload(&in->frames[k][j], &sh->frames[j],
							 r->uint_indices);
			r->upload_bytes += in->frames[k][j].bytes;
		}
		k++;
	}
	/* nothing instanced: every leaf is loose, and the merged mesh is all of them */
	if (ret == 0)
		ret = render_mesh_upload(&in->loose, k ? &li->loose : merged, r->uint_indices);
	if (ret < 0)
		return ret;
	r->upload_bytes += in->loose.bytes;
	/* shapes gone since the last upload give their memory back */
	for (size_t j = k; j < LEAF_INSTANCES_MAX_SHAPES; j++) {
		render_mesh_finish(&in->shapes[j]);
		for (size_t f = 0; f < ORI_UNFOLD_FRAMES; f++)
			render_mesh_finish(&in->frames[j][f]);
		in->has_frames[j] = false;
	}
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

/* Every leaf's colour in t's season: an instance's, and the loose mesh's vertices'. */
static int upload_tints(struct render *r, const struct tree *t, const struct mesh *merged,
			const struct tree_mesh_marks *mk)
{
	struct render_instanced *in = &r->inst;
	const struct leaf_instances *li = &in->li;
	const struct mesh *loose = in->nshapes ? &li->loose : merged;
	size_t n = li->ninstanced > loose->nvertices ? li->ninstanced : loose->nvertices;
	float *rgb = n <= SIZE_MAX / 3 - 1 ? render_tint_scratch(r, 3 * n + 3) : NULL;
	int ret;

	if (!rgb)
		return -ENOMEM;
	if (in->nshapes)
		ret = leaf_tint_loose(t, mk, li, rgb);
	else
		ret = leaf_tint_vertices(t, mk, loose->nvertices, rgb) ? 0 : -EINVAL;
	if (ret == 0)
		ret = render_mesh_upload_tints(&in->loose, loose, rgb);
	if (ret < 0)
		return ret;
	r->upload_bytes += 3 * sizeof(float) * (loose->nvertices + li->ninstanced);
	leaf_tint_instances(t, li, rgb);
	if (!in->tints)
		glGenBuffers(1, &in->tints);
	glBindBuffer(GL_ARRAY_BUFFER, in->tints);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(li->ninstanced * 3 * sizeof(float)),
		     li->ninstanced ? rgb : NULL, GL_STATIC_DRAW);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	return 0;
}

int render_instanced_upload(struct render *r, const struct tree *t, const struct mesh *merged,
			    const struct tree_mesh_marks *mk, bool tinted)
{
	int ret;

	r->inst.nshapes = 0;
	r->inst.loose.count = 0;
	ret = leaf_instances_build(&r->inst.li, t);
	if (ret == 0)
		ret = upload(r, &r->inst.li, merged);
	if (ret == 0 && tinted) {
		ret = upload_tints(r, t, merged, mk);
	} else if (ret == 0) {
		/* one colour: the last season's no longer hold */
		glDeleteBuffers(1, &r->inst.tints);
		r->inst.tints = 0;
	}
	if (ret < 0) {
		r->inst.nshapes = 0;
		r->inst.loose.count = 0;
	}
	return ret;
}

/* Instances [start, start + n) of the shapes' matrices (and tints) drawn with mesh rm;
 * grown: of the growth's copies, in its order (render_instanced_grow.c). */
static void draw_range(struct render *r, const struct render_mesh *rm, size_t start, size_t n,
		       bool tinted, bool grown)
{
	struct render_instanced *in = &r->inst;
	const char *at = (const char *)(uintptr_t)(start * MATRIX_BYTES);

	if (rm->count == 0 || n == 0)
		return;
	glBindBuffer(GL_ARRAY_BUFFER, rm->positions);
	glVertexAttribPointer(ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	glBindBuffer(GL_ARRAY_BUFFER, rm->normals);
	glVertexAttribPointer(ATTR_NORMAL, 3, GL_FLOAT, GL_FALSE, 0, NULL);
	glBindBuffer(GL_ARRAY_BUFFER, grown ? in->grow_matrices : in->matrices);
	for (GLuint i = 0; i < 3; i++)
		glVertexAttribPointer(ATTR_ROW0 + i, 4, GL_FLOAT, GL_FALSE, MATRIX_BYTES,
				      at + 4 * sizeof(float) * i);
	if (tinted) {
		glBindBuffer(GL_ARRAY_BUFFER, grown ? in->grow_tints : in->tints);
		glVertexAttribPointer(ATTR_TINT, 3, GL_FLOAT, GL_FALSE, 0,
				      (const char *)(uintptr_t)(start * 3 * sizeof(float)));
	}
	if (r->live.on)
		render_live_pointers(grown ? r->live.grow_instances.vbo : r->live.instances.vbo,
				     ATTR_INST_LIVE, start);
	if (rm->indexed) {
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, rm->indices);
		glDrawElementsInstanced(GL_TRIANGLES, rm->count, GL_UNSIGNED_INT, NULL, (GLsizei)n);
		glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
	} else {
		glDrawArraysInstanced(GL_TRIANGLES, 0, rm->count, (GLsizei)n);
	}
	r->stats.draw_calls++;
	r->stats.triangles += rm->ntriangles * n;
	r->stats.tree_triangles += rm->ntriangles * n;
}

/* The first of instances [from, to) whose leaf is at least `leaf` (they are in leaf order). */
static size_t first_from(const struct leaf_instances *li, size_t from, size_t to, size_t leaf)
{
	while (from < to) {
		size_t mid = from + (to - from) / 2;

		if (li->instances[mid].leaf < leaf)
			from = mid + 1;
		else
			to = mid;
	}
	return from;
}

/* The first of the growth's instances [from, to) whose d is past `bound` (grow_d rises). */
static size_t first_past(const float *d, size_t from, size_t to, double bound)
{
	while (from < to) {
		size_t mid = from + (to - from) / 2;

		if (d[mid] <= bound)
			from = mid + 1;
		else
			to = mid;
	}
	return from;
}

/* An origami shape while the tree grows in: the leaves the front passed long enough ago
 * at rest, the others at the keyframe their pull has reached, unscaled (u_unfolding), and
 * none past the front. A few binary searches, whatever the number of leaves. */
static void draw_growing(struct render *r, size_t k, bool tinted, GLint unfolding)
{
	struct render_instanced *in = &r->inst;
	const struct app_live_frame *f = &r->live.frame;
	double bound[ORI_UNFOLD_FRAMES + 1];
	size_t at = in->first[k], end = in->first[k] + in->count[k], hi;

	live_grow_unfold_bounds(f->front, f->swell, ORI_UNFOLD_FRAMES, bound);
	glUniform1f(unfolding, 1.0f);
	hi = first_past(in->grow_d, at, end, bound[ORI_UNFOLD_FRAMES]);
	draw_range(r, &in->shapes[k], at, hi - at, tinted, true);
	for (unsigned j = ORI_UNFOLD_FRAMES; j-- > 0;) {
		size_t lo = hi;

		hi = first_past(in->grow_d, lo, end, bound[j]);
		draw_range(r, &in->frames[k][j], lo, hi - lo, tinted, true);
	}
	glUniform1f(unfolding, 0.0f);
}

/* Shape k's instances: at rest with its mesh, those of unfolding leaves with the
 * keyframe their span is at (a shape without keyframes draws them all at rest); while
 * the tree grows in, an origami shape's by the growth (draw_growing). */
static void draw_shape(struct render *r, size_t k, const struct app_unfold_span *spans,
		       size_t nspans, bool tinted, GLint unfolding)
{
	struct render_instanced *in = &r->inst;
	size_t at = in->first[k], end = in->first[k] + in->count[k];

	if (r->live.on && r->live.frame.growing && in->grow_ok && in->has_frames[k] &&
	    r->live.grow_instances.ok) {
		draw_growing(r, k, tinted, unfolding);
		return;
	}
	for (size_t s = 0; s < nspans && in->has_frames[k]; s++) {
		size_t lo = first_from(&in->li, at, end, spans[s].first);
		size_t hi = first_from(&in->li, lo, end, spans[s].end);
		unsigned f = spans[s].frame < ORI_UNFOLD_FRAMES ? spans[s].frame : 0;

		draw_range(r, &in->shapes[k], at, lo - at, tinted, false);
		draw_range(r, &in->frames[k][f], lo, hi - lo, tinted, false);
		at = hi;
	}
	draw_range(r, &in->shapes[k], at, end - at, tinted, false);
}

void render_instanced_draw(struct render *r, const float mvp[16], const float light[3],
			   const float color[3], const struct app_unfold_span *spans,
			   size_t nspans)
{
	struct render_instanced *in = &r->inst;
	const struct render_live_program *lp = color ? &in->live : &in->live_tinted;
	const struct render_program_tree *p = r->live.on ? &lp->tree
					      : color	   ? &in->plain
							   : &in->tinted;

	if (in->nshapes == 0 || (r->live.on && !r->live.instances.ok))
		return;
	glUseProgram(p->program);
	glUniformMatrix4fv(p->mvp, 1, GL_FALSE, mvp);
	glUniform3fv(p->light, 1, light);
	if (r->live.on) {
		render_live_uniforms(r, lp);
		for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++) {
			glEnableVertexAttribArray(ATTR_INST_LIVE + i);
			glVertexAttribDivisor(ATTR_INST_LIVE + i, 1);
		}
	}
	if (color)
		glUniform3fv(p->color, 1, color);
	glUniform1i(p->two_sided, 1);
	glEnableVertexAttribArray(ATTR_NORMAL);
	for (GLuint i = 0; i < 3; i++) {
		glEnableVertexAttribArray(ATTR_ROW0 + i);
		glVertexAttribDivisor(ATTR_ROW0 + i, 1);
	}
	if (!color) {
		glEnableVertexAttribArray(ATTR_TINT);
		glVertexAttribDivisor(ATTR_TINT, 1);
	}
	for (size_t k = 0; k < in->nshapes; k++)
		draw_shape(r, k, spans, nspans, !color, lp->unfolding);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	/* the other programs read attributes 0 and 1 only, per vertex */
	for (GLuint i = 0; i < 3; i++) {
		glVertexAttribDivisor(ATTR_ROW0 + i, 0);
		glDisableVertexAttribArray(ATTR_ROW0 + i);
	}
	if (!color) {
		glVertexAttribDivisor(ATTR_TINT, 0);
		glDisableVertexAttribArray(ATTR_TINT);
	}
	if (r->live.on) {
		for (GLuint i = 0; i < ATTR_LIVE_COUNT; i++) {
			glVertexAttribDivisor(ATTR_INST_LIVE + i, 0);
			glDisableVertexAttribArray(ATTR_INST_LIVE + i);
		}
	}
}
