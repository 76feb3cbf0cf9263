/* SPDX-License-Identifier: MIT */
#pragma once

/* Shared by the renderer's files; not for its users (tests may poke at it). */

#include <GLES2/gl2.h>
#include <stdbool.h>
#include <stdint.h>

#include "arrange.h"
#include "batch.h"
#include "camera.h"
#include "render.h"

struct app;
struct mesh;

/* Attribute locations, bound before linking so all programs agree. */
enum {
	ATTR_POSITION = 0,
	ATTR_NORMAL = 1, /* tree program */
	ATTR_COLOR = 1,  /* flat program */
};

/* A tree mesh on the GPU. */
struct render_mesh {
	GLuint positions, normals, indices;
	GLsizei count;     /* indices to draw, or vertices when not indexed */
	bool indexed;      /* false: expanded to a plain triangle list */
	size_t ntriangles;
};

struct render {
	/* lit tree meshes: world positions and normals */
	GLuint tree_program;
	GLint tree_mvp, tree_color, tree_light, tree_two_sided;
	/* flat-coloured screen-space triangles */
	GLuint flat_program;
	GLint flat_proj;
	GLuint flat_vbo;

	/* GLES 3 or OES_element_index_uint; without it meshes are expanded on upload */
	bool uint_indices;

	struct render_mesh bark, leaves;
	bool uploaded;       /* the meshes hold mesh_serial's tree */
	uint64_t mesh_serial;

	/* the leaf suggestions' thumbnails */
	struct render_mesh preview_bark[ARRANGE_COUNT], preview_leaves[ARRANGE_COUNT];
	bool previews_uploaded;
	uint64_t previews_serial;

	struct batch batch;
	struct render_stats stats;
};

/* render_gl.c: a linked program with attributes at the given locations, or 0 (stderr says why). */
GLuint render_program(const char *name, const char *vertex_src, const char *fragment_src,
		      const char *const *attribs, const GLuint *locations, size_t nattribs);
bool render_has_extension(const char *name);
int render_gl_major_version(void);

/* render_mesh.c */
int render_mesh_upload(struct render_mesh *rm, const struct mesh *m, bool uint_indices);
void render_mesh_draw(struct render *r, const struct render_mesh *rm);
void render_mesh_finish(struct render_mesh *rm);

/* render_ui.c: the 2D layers, added to r->batch. */
void render_ui_ground(struct batch *b, const struct app *app);
void render_ui_stroke(struct batch *b, const struct app *app);
void render_ui_buttons(struct batch *b, const struct app *app);
void render_ui_cursor(struct batch *b, const struct app *app);
/* The branch clone mode works on, marked over the tree as the camera xf shows it. */
void render_ui_selection(struct batch *b, const struct app *app, const struct camera_xf *xf);

/* render_preview.c: the 3D pictures inside the leaf suggestion thumbnails (the cards
 * behind them are render_ui_buttons'). 0 or a negative errno. */
int render_previews(struct render *r, const struct app *app, const struct camera_xf *xf,
		    const float light[3]);
void render_previews_finish(struct render *r);

