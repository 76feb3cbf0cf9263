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

/* Appends a tube from a to b, radii ra and rb, to the bark: for tests that build their own. */
int scene_add_tube(struct mesh *m, struct vec3 a, struct vec3 b, double ra, double rb);
