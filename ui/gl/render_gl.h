/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The renderer's GL helpers (render_gl.c): building programs, asking the context what it
 * offers, clearing its error flags. The bottom of ui's renderer: the frame (render.c) and
 * the layers (render_*.c) call these; these call nothing of theirs and need no struct
 * render, only a current GLES context.
 */

#include <GLES2/gl2.h>
#include <stdbool.h>
#include <stddef.h>

/* Attribute locations, bound before linking so all programs agree. */
enum {
	ATTR_POSITION = 0,
	ATTR_NORMAL = 1, /* tree program */
	ATTR_COLOR = 1,  /* flat program */
	ATTR_ROW0 = 2,   /* instanced leaves: the rows of each instance's 3x4 matrix, 2..4 */
	ATTR_UV = 5,     /* flat program: the atlas texel; clear of the instanced rows */
	ATTR_TINT = 6,   /* tinted programs: a leaf's colour, per vertex or per instance */
	/* The living programs' vertex data (a_live0, a_live1, a_phase, a_flutter): per vertex
	 * in the places of the instanced rows and the atlas texel, which they do not read,
	 * so that the merged ones need no more than GLES 2's 8 attributes; per instance
	 * after the tint (GLES 3 has 16). */
	ATTR_LIVE = 2,
	ATTR_INST_LIVE = 7,
	ATTR_LIVE_COUNT = 4,
	/* the forest's programs: a tree's trunk harmonic and phase per vertex, the eighth */
	ATTR_TRUNK = 7,
};

/* A lit program: the tree program's uniforms. */
struct render_program_tree {
	GLuint program;
	GLint mvp, color, light, two_sided;
};

/* A linked program with attributes at the given locations, or 0 (stderr says why). */
GLuint render_program(const char *name, const char *vertex_src, const char *fragment_src,
		      const char *const *attribs, const GLuint *locations, size_t nattribs);
/* A lit program (the tree program's uniforms) from these sources: false if it did not
 * build (stderr says why). */
bool render_program_tree_init(struct render_program_tree *p, const char *name, const char *vs,
			      const char *fs, const char *const *attribs, const GLuint *locations,
			      size_t nattribs);
bool render_has_extension(const char *name);
int render_gl_major_version(void);
/* Empties GL's error flags: errors left by others are not ours to report. */
void render_drain_gl_errors(void);
/* out = a b, 4x4 column-major (GL's layout); out may not be a or b. */
void render_mat4_mul(const float a[16], const float b[16], float out[16]);
