/* SPDX-License-Identifier: MIT */
/* A drawing planted for today's forest (forest_plant.h). */
#include "forest_plant.h"

#include <errno.h>

#include "app.h"
#include "docfile.h"
#include "event.h"

/* The app's size does not matter to the tree a drawing makes: the kiosk's. */
#define PLANT_WIDTH 1280
#define PLANT_HEIGHT 800

void forest_planted_init(struct forest_planted *p)
{
	tree_init(&p->tree);
	tree_mesh_init(&p->mesh);
	tree_mesh_marks_init(&p->marks);
	p->seed = 0;
}

void forest_planted_finish(struct forest_planted *p)
{
	tree_finish(&p->tree);
	tree_mesh_finish(&p->mesh);
	tree_mesh_marks_finish(&p->marks);
}

/* The 3D button, pressed and released after the drawing's last moment. */
static void lift(struct app *app)
{
	struct event ev = { .type = EVENT_BUTTON, .button = BUTTON_3D, .pressed = true,
			    .time_us = 1000000 };

	app_handle_event(app, &ev);
	ev.pressed = false;
	ev.time_us += 50000;
	app_handle_event(app, &ev);
}

int forest_plant(const char *path, struct forest_planted *p, struct error *err)
{
	struct doc doc;
	struct app *app;
	int ret;

	forest_planted_finish(p);
	forest_planted_init(p);
	ret = docfile_read(path, &doc, err);
	if (ret < 0)
		return ret;
	p->seed = doc.seed;
	app = app_create(PLANT_WIDTH, PLANT_HEIGHT, doc.seed);
	if (!app) {
		doc_finish(&doc);
		return error_set(err, -ENOMEM, "%s: out of memory", path);
	}
	ret = app_load_doc(app, &doc); /* the app owns doc's contents once loaded */
	if (ret < 0)
		doc_finish(&doc);
	if (ret == 0 && app->failed)
		ret = -ENOMEM;
	if (ret == 0 && app->tree.nbranches == 0)
		ret = error_set(err, -ENODATA, "%s: the drawing holds no tree", path);
	if (ret == 0 && !app->tree.lifted) {
		app_set_grow_in(app, false);
		lift(app);
		if (app->failed || !app->tree.lifted)
			ret = error_set(err, -ENOMEM, "%s: the sketch could not be lifted", path);
	}
	if (ret == 0)
		ret = tree_copy(&p->tree, &app->tree);
	if (ret == 0)
		ret = tree_mesh_build_marked(&p->mesh, &p->tree, &p->marks);
	if (ret == -ENOMEM)
		error_set(err, ret, "%s: out of memory", path);
	app_destroy(app);
	if (ret < 0) {
		forest_planted_finish(p);
		forest_planted_init(p);
	}
	return ret;
}
