/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

#include "app.h"

/*
 * App states built by hand for the render tests: no app.c, no mesh builder, so the
 * golden images change only when the renderer does. A small tree of tubes and leaves,
 * a stroke under the pen, a hovering pen, a mode and the undo history's position.
 */

/* Names of the scenes, NULL-terminated. */
extern const char *const scene_names[];

/* Fills *app (zeroed first) with the named scene. 0, -EINVAL (no such scene) or -ENOMEM. */
int scene_build(struct app *app, const char *name);
void scene_finish(struct app *app);
/* The moment of the app's clock a scene is drawn at (render_frame_at; UINT64_MAX: the
 * settled view), and whether its words are Japanese. */
uint64_t scene_time_us(const char *name);
bool scene_japanese(const char *name);

/*
 * An app holding a 3D tree of 24 branches made as a visitor would: a leaf drawn on one
 * branch and whorl-added, another drawn there, propagated onto every branch (fixed
 * count), then one more leaf drawn by hand: 2 shapes with copies, one leaf of its own
 * (without copies: 3 leaves of their own). Meshes and their marks as app.c builds them.
 * Checks as it goes (tests/lib/test.h).
 */
void scene_leafy(struct app *app, int width, int height, struct camera cam, bool copies);
void scene_leafy_finish(struct app *app);

/* Appends a tube from a to b, radii ra and rb, to the bark: for tests that build their own. */
int scene_add_tube(struct mesh *m, struct vec3 a, struct vec3 b, double ra, double rb);
