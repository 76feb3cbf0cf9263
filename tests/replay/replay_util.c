/* SPDX-License-Identifier: MIT */
#include "replay_util.h"

#include <stdio.h>
#include <stdlib.h>

#include "export.h"
#include "test.h"
#include "trace.h"

struct app *replay_trace(const char *dir, const char *name, int w, int h, uint64_t seed)
{
	char path[4096];
	struct trace t;
	struct error err = { { 0 } };
	struct app *app = app_create(w, h, seed);

	CHECK(app);
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	trace_init(&t);
	if (trace_load(path, w, h, &t, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	for (size_t i = 0; i < t.nevents; i++)
		app_handle_event(app, &t.events[i]);
	trace_finish(&t);
	CHECK_INT(app->failed, 0);
	return app;
}

void replay_press(struct app *app, enum button b)
{
	struct event e = { .type = EVENT_BUTTON, .time_us = app->last_time_us + 100000,
			   .button = (int)b, .pressed = true };

	app_handle_event(app, &e);
	e.pressed = false;
	app_handle_event(app, &e);
}

char *replay_skeleton_text(const struct tree *t)
{
	struct buf b;

	buf_init(&b);
	CHECK_INT(export_skeleton(t, &b), 0);
	CHECK_INT(buf_append(&b, "", 1), 0);
	return (char *)b.data;
}

json_object *replay_skeleton_json(const struct tree *t)
{
	char *text = replay_skeleton_text(t);
	json_object *j = json_tokener_parse(text);

	CHECK(j);
	free(text);
	return j;
}

json_object *replay_get(json_object *o, const char *key)
{
	json_object *v;

	CHECK(json_object_object_get_ex(o, key, &v));
	return v;
}
