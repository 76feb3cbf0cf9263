/* SPDX-License-Identifier: MIT */
#pragma once

/* What the replay tests share: a trace through a new app, buttons, skeleton.json. */
#include <json-c/json.h>
#include <stdint.h>

#include "app.h"

/* dir/name (an edaha trace or libinput recording) replayed through a new w x h app with
 * the drawing seed `seed`; a trace that does not load ends the test. */
struct app *replay_trace(const char *dir, const char *name, int w, int h, uint64_t seed);
/* Presses and releases a button 0.1 s after the app's last event. */
void replay_press(struct app *app, enum button b);
/* skeleton.json as the exporter writes it: malloc'ed, NUL-terminated. */
char *replay_skeleton_text(const struct tree *t);
/* ...and parsed; json_object_put() it. */
json_object *replay_skeleton_json(const struct tree *t);
/* o[key], which must be there. */
json_object *replay_get(json_object *o, const char *key);
