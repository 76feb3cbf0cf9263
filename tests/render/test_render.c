/* SPDX-License-Identifier: MIT */
/*
 * The renderer beyond its pictures: meshes upload only when mesh_serial changes, the
 * expanded-index fallback draws the same pixels, broken meshes are refused, strokes are
 * antialiased, and the draw-call count stays small.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "egl_headless.h"
#include "render.h"
#include "render_private.h"
#include "scene.h"
#include "test.h"

struct fixture {
	struct egl_headless *egl;
	uint8_t *a, *b;
	size_t size;
};

static void fixture_init(struct fixture *f, int width, int height)
{
	struct error err = { "" };

	f->egl = egl_headless_create(width, height, &err);
	if (!f->egl)
		fprintf(stderr, "egl_headless_create: %s\n", err.msg);
	CHECK(f->egl);
	f->size = (size_t)width * (size_t)height * 4;
	f->a = malloc(f->size);
	f->b = malloc(f->size);
	CHECK(f->a && f->b);
}

static void fixture_finish(struct fixture *f)
{
	free(f->a);
	free(f->b);
	egl_headless_destroy(f->egl);
}

static void draw(struct fixture *f, struct render *r, const struct app *app, uint8_t *out)
{
	CHECK_INT(render_frame(r, app), 0);
	CHECK_INT(egl_headless_read_rgba(f->egl, out), 0);
}

static void shift_bark(struct app *app, float dx)
{
	for (size_t i = 0; i < app->mesh.bark.nvertices; i++)
		app->mesh.bark.positions[3 * i] += dx;
}

static void test_upload_only_on_serial(void)
{
	struct fixture f;
	struct app app;
	struct render *r;
	struct render_stats st;
	size_t tree_tris;

	CHECK_INT(scene_build(&app, "leaf"), 0);
	tree_tris = (app.mesh.bark.nindices + app.mesh.leaves.nindices) / 3;
	fixture_init(&f, app.view.width, app.view.height);
	r = render_create();
	CHECK(r);

	draw(&f, r, &app, f.a);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 2);
	CHECK_INT(st.tree_triangles, tree_tris);
	/* ground, bark, leaves, then stroke + buttons + cursor in one */
	CHECK_INT(st.draw_calls, 4);
	CHECK(st.triangles > st.tree_triangles);

	/* the mesh changes but the serial does not: the GPU copy is drawn */
	shift_bark(&app, 1.5f);
	draw(&f, r, &app, f.b);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 0);
	CHECK(memcmp(f.a, f.b, f.size) == 0);

	/* a new serial uploads and shows the change */
	app.mesh_serial++;
	draw(&f, r, &app, f.b);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 2);
	CHECK(memcmp(f.a, f.b, f.size) != 0);

	render_destroy(r);
	fixture_finish(&f);
	scene_finish(&app);
}

/* GLES 2 without OES_element_index_uint expands meshes: same pixels. */
static void test_expanded_indices(void)
{
	struct fixture f;
	struct app app;
	struct render *indexed, *expanded;
	struct render_stats st;

	CHECK_INT(scene_build(&app, "eraser"), 0);
	fixture_init(&f, app.view.width, app.view.height);
	indexed = render_create();
	expanded = render_create();
	CHECK(indexed && expanded);
	CHECK(indexed->uint_indices); /* Mesa has them */
	expanded->uint_indices = false;

	draw(&f, indexed, &app, f.a);
	draw(&f, expanded, &app, f.b);
	CHECK(!expanded->bark.indexed);
	render_get_stats(expanded, &st);
	CHECK_INT(st.tree_triangles, (app.mesh.bark.nindices + app.mesh.leaves.nindices) / 3);
	CHECK(memcmp(f.a, f.b, f.size) == 0);

	render_destroy(indexed);
	render_destroy(expanded);
	fixture_finish(&f);
	scene_finish(&app);
}

static void test_bad_mesh(void)
{
	struct fixture f;
	struct app app;
	struct render *r;
	uint32_t good;

	CHECK_INT(scene_build(&app, "leaf"), 0);
	fixture_init(&f, app.view.width, app.view.height);
	r = render_create();
	CHECK(r);

	good = app.mesh.leaves.indices[4];
	app.mesh.leaves.indices[4] = (uint32_t)app.mesh.leaves.nvertices;
	CHECK_INT(render_frame(r, &app), -EINVAL);
	/* refused meshes are retried on the next frame, and drawn once fixed */
	CHECK_INT(render_frame(r, &app), -EINVAL);
	app.mesh.leaves.indices[4] = good;
	CHECK_INT(render_frame(r, &app), 0);

	render_destroy(r);
	fixture_finish(&f);
	scene_finish(&app);
}

/* Nothing drawn yet: paper, ground and buttons only, in two calls. */
static void test_empty(void)
{
	struct fixture f;
	struct app app;
	struct render *r;
	struct render_stats st;

	memset(&app, 0, sizeof(app));
	view_init(&app.view, 320, 200);
	fixture_init(&f, 320, 200);
	r = render_create();
	CHECK(r);
	draw(&f, r, &app, f.a);
	render_get_stats(r, &st);
	CHECK_INT(st.draw_calls, 2);
	CHECK_INT(st.tree_triangles, 0);
	/* the top left is paper */
	CHECK(f.a[0] > 240 && f.a[1] > 230 && f.a[2] > 210 && f.a[3] == 255);

	render_destroy(r);
	fixture_finish(&f);
}

/* The stroke's edges blend into the paper: MSAA at work. */
static void test_antialiased_stroke(void)
{
	struct fixture f;
	struct app app;
	struct render *r;
	struct app_point pts[2] = { { 40, 40, 1.0, 0 }, { 200, 120, 1.0, 0 } };
	const uint8_t *paper, *ink = NULL;
	size_t blended = 0;

	memset(&app, 0, sizeof(app));
	view_init(&app.view, 320, 200);
	app.stroke.points = pts;
	app.stroke.npoints = 2;
	app.stroke.active = true;
	fixture_init(&f, 320, 200);
	r = render_create();
	CHECK(r);
	draw(&f, r, &app, f.a);

	paper = f.a;
	/* the middle of the stroke is ink */
	ink = f.a + ((size_t)80 * 320 + 120) * 4;
	CHECK(ink[0] < 80 && ink[1] < 80 && ink[2] < 80);
	for (int y = 20; y < 150; y++) {
		for (int x = 20; x < 220; x++) {
			const uint8_t *p = f.a + ((size_t)y * 320 + (size_t)x) * 4;

			if (memcmp(p, paper, 4) != 0 && memcmp(p, ink, 4) != 0)
				blended++;
		}
	}
	/* without antialiasing there would be none; with it, much of both long edges */
	CHECK(blended > 100);

	render_destroy(r);
	fixture_finish(&f);
}

static void pen_line(struct app *app, uint64_t *t, double x0, double y0, double x1, double y1)
{
	struct event e = { .type = EVENT_TIP_DOWN, .x = x0, .y = y0, .pressure = 0.5 };

	for (int i = 0; i <= 20; i++) {
		e.time_us = (*t += 8000);
		e.x = x0 + (x1 - x0) * i / 20;
		e.y = y0 + (y1 - y0) * i / 20;
		app_handle_event(app, &e);
		e.type = EVENT_MOTION;
	}
	e.type = EVENT_TIP_UP;
	app_handle_event(app, &e);
	*t += 4000000;
}

/* The turn into 3D is shown frame by frame and ends on the settled picture; a turned
 * tree draws differently from the front. */
static void test_turn(void)
{
	struct fixture f;
	struct app *app = app_create(320, 200, 5);
	struct event press = { .type = EVENT_BUTTON, .button = BUTTON_3D, .pressed = true };
	struct render *r;
	uint8_t *mid;
	uint64_t t = 1000, t0;

	CHECK(app);
	pen_line(app, &t, 140, 184, 140, 60);
	pen_line(app, &t, 140, 130, 200, 90);
	pen_line(app, &t, 140, 110, 90, 70);
	t0 = press.time_us = t;
	app_handle_event(app, &press);
	CHECK(app->tree.lifted && app->turning);
	fixture_init(&f, 320, 200);
	mid = malloc(f.size);
	CHECK(mid);
	r = render_create();
	CHECK(r);
	draw(&f, r, app, f.a);
	CHECK_INT(render_frame_at(r, app, t0 + APP_TURN_US / 4), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, mid), 0);
	CHECK(memcmp(f.a, mid, f.size) != 0);
	CHECK_INT(render_frame_at(r, app, t0 + APP_TURN_US), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.b), 0);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	/* turned by hand: a different picture, the same meshes */
	CHECK(app_set_camera(app, (struct camera){ 90.0f, 30.0f }));
	draw(&f, r, app, f.b);
	CHECK(memcmp(f.a, f.b, f.size) != 0);

	free(mid);
	render_destroy(r);
	fixture_finish(&f);
	app_destroy(app);
}

int main(void)
{
	test_turn();
	test_upload_only_on_serial();
	test_expanded_indices();
	test_bad_mesh();
	test_empty();
	test_antialiased_stroke();
	return 0;
}
