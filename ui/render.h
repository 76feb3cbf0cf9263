/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

struct app;

/*
 * Draws what the kiosk shows for an app state: the tree, the stroke under the pen, the
 * hover cursor, the on-screen buttons with their labels, status messages and the attract
 * screen. Needs a current GLES context (2.0 or later); draws into the bound framebuffer at
 * app->screen's size. Same state, same pixels. The tree's meshes are uploaded to the GPU
 * only when app->mesh_serial changes.
 */
struct render;

/* The language of the words on the screen (ui/labels.c). */
enum render_lang {
	RENDER_LANG_EN = 0,
	RENDER_LANG_JA,
};

/* NULL if the context lacks what is needed (a message says why on stderr). */
struct render *render_create(void);
/* Needs the context render_create ran in to be current. */
void render_destroy(struct render *r);
/*
 * The font of the labels and messages, the bytes of a TrueType/OpenType file (copied;
 * NULL: none, the buttons show their icons alone), and their language. 0; -EINVAL if
 * FreeType cannot read the font, -ENOMEM: no font then. A font without a glyph that the
 * language needs is used, with a warning on stderr.
 */
int render_set_text(struct render *r, const void *font, size_t len, enum render_lang lang);
/*
 * Returns 0; -EIO if GL reported an error; -ENOMEM; -EINVAL if a mesh has an index
 * past its vertices (that mesh is not drawn).
 */
int render_frame(struct render *r, const struct app *app);
/* The same at a moment of the app's clock: the animated turn into 3D shows its step at
 * now_us, a status message shows while app_status_at says so (fading at the end), the
 * attract screen while app_attract_at does. render_frame shows the settled view, without
 * either. */
int render_frame_at(struct render *r, const struct app *app, uint64_t now_us);

struct mesh;
/*
 * An origami leaf alone (edaha --leaf): m (metres, a normal a face: ori_mesh_append) on the
 * paper, double-sided in the screen's leaf green, lit like the tree, seen from a fixed
 * three-quarter view above its front (RENDER_LEAF_YAW_DEG, RENDER_LEAF_PITCH_DEG) and
 * framed to fill most of a width x height view. Same mesh, same pixels. 0; -EIO if GL
 * reported an error; -ENOMEM; -EINVAL for a bad mesh or size.
 */
#define RENDER_LEAF_YAW_DEG -30.0
#define RENDER_LEAF_PITCH_DEG 30.0
int render_leaf(struct render *r, const struct mesh *m, int width, int height);
/*
 * A twining vine alone on its support (edaha --support): support in the bark's colour,
 * stems a stem green, leaves double-sided in the leaf green, lit as the leaf alone, seen
 * from a fixed three-quarter view (RENDER_VINE_YAW_DEG, RENDER_VINE_PITCH_DEG) and framed
 * to fit all three in a width x height view. Same meshes, same pixels. 0; -EIO if GL
 * reported an error; -ENOMEM; -EINVAL for a bad mesh or size.
 */
#define RENDER_VINE_YAW_DEG -30.0
#define RENDER_VINE_PITCH_DEG 20.0
int render_vine(struct render *r, const struct mesh *support, const struct mesh *stems,
		const struct mesh *leaves, int width, int height);

/* What the last render_frame() did: for benchmarks and tests. */
struct render_stats {
	unsigned draw_calls;   /* glDraw* calls */
	size_t triangles;      /* triangles in those calls */
	size_t tree_triangles; /* of which bark and leaves */
	unsigned uploads;      /* meshes uploaded (0 when mesh_serial did not change) */
};

void render_get_stats(const struct render *r, struct render_stats *stats);
