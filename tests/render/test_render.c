/* SPDX-License-Identifier: MIT */
/*
 * The renderer beyond its pictures: meshes upload only when mesh_serial changes, the
 * expanded-index fallback draws the same pixels, broken meshes are refused, strokes are
 * antialiased, the draw-call count stays small (labels included), leaves drawn instanced
 * (GLES 3) look as the merged ones do, at a call a shape; a status message fades out,
 * the attract screen holds still, and a missing or broken font leaves the icons.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "app_mode.h"
#include "arrange.h"
#include "layout.h"
#include "egl_headless.h"
#include "font.h"
#include "font_file.h"
#include "propagate.h"
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
	fixture_init(&f, app.screen.width, app.screen.height);
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

/* Pixels whose channels differ by more than max_diff. */
static size_t differing(const uint8_t *a, const uint8_t *b, size_t size, int max_diff)
{
	size_t n = 0;

	for (size_t i = 0; i < size; i += 4) {
		bool d = false;

		for (int c = 0; c < 4; c++)
			d = d || abs((int)a[i + c] - (int)b[i + c]) > max_diff;
		n += d;
	}
	return n;
}

/* Leaves drawn instanced (GLES 3) and merged (GLES 2's way, forced): the same picture
 * within imgcmp's golden tolerance, from the front and turned; a call a shape with
 * copies, one for the leaves that are no copies; less uploaded. */
static void test_instanced(void)
{
	static const struct camera cams[] = { { 0.0f, 0.0f }, { 70.0f, 35.0f },
					      { 200.0f, -20.0f } };
	struct fixture f;
	struct app app;
	struct render *inst, *merged;
	struct render_stats si, sm;
	struct leaf_instances li;

	fixture_init(&f, 640, 400);
	inst = render_create();
	merged = render_create();
	CHECK(inst && merged);
	CHECK(inst->instanced); /* Mesa gives GLES 3 */
	merged->instanced = false;
	for (size_t c = 0; c < sizeof(cams) / sizeof(cams[0]); c++) {
		size_t diff;

		scene_leafy(&app, 640, 400, cams[c], true);
		app.mesh_serial = 10 * (c + 1); /* a new tree to the renderers */
		leaf_instances_init(&li);
		CHECK_INT(leaf_instances_build(&li, &app.tree), 0);
		CHECK_INT(li.ninstanced_shapes, 2);
		CHECK_INT(li.ninstanced, app.tree.nleaves - 1);

		draw(&f, inst, &app, f.a);
		render_get_stats(inst, &si);
		draw(&f, merged, &app, f.b);
		render_get_stats(merged, &sm);
		CHECK(inst->uploaded_instanced && !merged->uploaded_instanced);
		CHECK_INT(si.uploads, 2);
		CHECK_INT(sm.uploads, 2);
		/* ground, bark, the loose leaf, 2 shapes, stroke + buttons + cursor */
		CHECK_INT(sm.draw_calls, 4);
		CHECK_INT(si.draw_calls, 3 + 1 + li.ninstanced_shapes);
		CHECK_INT(si.tree_triangles, sm.tree_triangles);
		CHECK_INT(si.triangles, sm.triangles);
		CHECK(inst->upload_bytes < merged->upload_bytes);

		diff = differing(f.a, f.b, f.size, 8);
		fprintf(stderr, "instanced vs merged, camera %zu: %zu pixels differ by more "
				"than 8, %zu by more than 0; %zu vs %zu bytes uploaded\n",
			c, diff, differing(f.a, f.b, f.size, 0), inst->upload_bytes,
			merged->upload_bytes);
		CHECK(diff <= f.size / 4 / 1000);
		/* the leaves are there: the picture differs without them */
		app.tree.nleaves = 0;
		app.mesh.leaves.nindices = 0;
		app.mesh_serial++;
		draw(&f, inst, &app, f.b);
		render_get_stats(inst, &si);
		CHECK(!inst->uploaded_instanced);
		CHECK_INT(si.draw_calls, 3);
		CHECK(differing(f.a, f.b, f.size, 8) > 1000);
		app.tree.nleaves = li.ninstances;
		leaf_instances_finish(&li);
		scene_leafy_finish(&app);
	}

	/* no copies: the merged leaves mesh, drawn in one call, uploaded as it is */
	scene_leafy(&app, 640, 400, cams[1], false);
	app.mesh_serial = 100;
	draw(&f, inst, &app, f.a);
	render_get_stats(inst, &si);
	draw(&f, merged, &app, f.b);
	render_get_stats(merged, &sm);
	CHECK(inst->uploaded_instanced);
	CHECK_INT(inst->inst.nshapes, 0);
	CHECK_INT(si.draw_calls, 4);
	CHECK_INT(si.tree_triangles, sm.tree_triangles);
	CHECK_INT(inst->upload_bytes, merged->upload_bytes);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	scene_leafy_finish(&app);

	render_destroy(inst);
	render_destroy(merged);
	fixture_finish(&f);
}

/* Pixels of the canvas (left of x1, of a 640-pixel wide image) where the red channel leads
 * the green by a margin: autumn's leaves, not summer's or the bark's. */
static size_t reddish(const uint8_t *img, size_t size, int x1)
{
	size_t n = 0;

	for (size_t i = 0; i < size; i += 4)
		n += (int)(i / 4 % 640) < x1 && img[i] > img[i + 1] + 60;
	return n;
}

/* Whether two 640-pixel wide images agree left of x1 (the bar shows the season). */
static bool same_canvas(const uint8_t *a, const uint8_t *b, size_t size, int x1)
{
	for (size_t i = 0; i < size; i += 640 * 4)
		if (memcmp(a + i, b + i, (size_t)x1 * 4) != 0)
			return false;
	return true;
}

/*
 * Seasons: leaves in autumn, in a colour each, drawn instanced (a colour an instance) and
 * merged (a colour a vertex, GLES 2's way, and expanded without 32-bit indices) give the
 * same picture, with as many calls as summer's; in winter no leaf is drawn; back in summer
 * the picture is summer's again, drawn with one colour.
 */
static void test_seasons(void)
{
	struct fixture f;
	struct app app;
	struct render *inst, *merged, *expanded;
	struct render_stats si, sm;
	uint8_t *summer, *bare;
	size_t bark_triangles;

	fixture_init(&f, 640, 400);
	summer = malloc(f.size);
	bare = malloc(f.size);
	inst = render_create();
	merged = render_create();
	expanded = render_create();
	CHECK(summer && bare && inst && merged && expanded);
	merged->instanced = false;
	expanded->instanced = false;
	expanded->uint_indices = false;
	scene_leafy(&app, 640, 400, (struct camera){ 30.0f, 20.0f }, true);
	bark_triangles = app.mesh.bark.nindices / 3;

	draw(&f, inst, &app, summer);
	CHECK(!inst->uploaded_tinted);
	CHECK_INT(reddish(summer, f.size, (int)layout_bar(&app.screen).x), 0);
	for (int s = 0; s < 2; s++) {
		app.tree.season = s == 0 ? SEASON_AUTUMN : SEASON_SPRING;
		app.mesh_serial++;
		draw(&f, inst, &app, f.a);
		render_get_stats(inst, &si);
		CHECK(inst->uploaded_instanced && inst->uploaded_tinted);
		draw(&f, merged, &app, f.b);
		render_get_stats(merged, &sm);
		CHECK(!merged->uploaded_instanced && merged->uploaded_tinted);
		CHECK_INT(si.draw_calls, 3 + 1 + inst->inst.nshapes);
		CHECK_INT(sm.draw_calls, 4);
		CHECK_INT(si.tree_triangles, sm.tree_triangles);
		CHECK(differing(f.a, f.b, f.size, 8) <= f.size / 4 / 1000);
		CHECK(differing(f.a, summer, f.size, 8) > 1000);
		if (s == 0)
			CHECK(reddish(f.a, f.size, (int)layout_bar(&app.screen).x) > 500);
		draw(&f, expanded, &app, f.a);
		CHECK(!expanded->leaves.indexed);
		CHECK(memcmp(f.a, f.b, f.size) == 0);
	}

	/* winter: the branches alone, as a tree without leaves */
	app.tree.season = SEASON_WINTER;
	app.mesh_serial++;
	draw(&f, inst, &app, f.a);
	render_get_stats(inst, &si);
	CHECK_INT(si.tree_triangles, bark_triangles);
	CHECK_INT(si.draw_calls, 3);
	draw(&f, merged, &app, f.b);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	{
		size_t nleaves = app.tree.nleaves, nindices = app.mesh.leaves.nindices;

		app.tree.season = SEASON_SUMMER;
		app.tree.nleaves = 0;
		app.mesh.leaves.nindices = 0;
		app.mesh_serial++;
		draw(&f, merged, &app, bare);
		CHECK(same_canvas(f.a, bare, f.size, (int)layout_bar(&app.screen).x));
		CHECK(memcmp(f.a, bare, f.size) != 0); /* the season button's picture */
		app.tree.nleaves = nleaves;
		app.mesh.leaves.nindices = nindices;
	}

	/* summer again: one colour, summer's picture, the season alone telling (no new serial) */
	app.tree.season = SEASON_SUMMER;
	draw(&f, inst, &app, f.a);
	CHECK(!inst->uploaded_tinted);
	CHECK(memcmp(f.a, summer, f.size) == 0);

	scene_leafy_finish(&app);
	render_destroy(inst);
	render_destroy(merged);
	render_destroy(expanded);
	free(summer);
	free(bare);
	fixture_finish(&f);
}

/* GLES 2 without OES_element_index_uint expands meshes: same pixels. */
static void test_expanded_indices(void)
{
	struct fixture f;
	struct app app;
	struct render *indexed, *expanded;
	struct render_stats st;

	CHECK_INT(scene_build(&app, "eraser"), 0);
	fixture_init(&f, app.screen.width, app.screen.height);
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
	fixture_init(&f, app.screen.width, app.screen.height);
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
	screen_init(&app.screen, 320, 200);
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
	screen_init(&app.screen, 320, 200);
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
	/* the turn alone (the growing in that comes with it: live_scene.c's tests) */
	app_set_grow_in(app, false);
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

static void press_button(struct app *app, uint64_t *t, enum button b)
{
	struct event e = { .type = EVENT_BUTTON, .button = (int)b, .pressed = true };

	e.time_us = (*t += 8000);
	app_handle_event(app, &e);
	e.pressed = false;
	e.time_us = (*t += 80000);
	app_handle_event(app, &e);
}

/* Pixels of a rectangle (top-down rows) that are not the card's paper: what is drawn on it. */
static size_t drawn_in(const uint8_t *img, int width, struct layout_rect r)
{
	size_t n = 0;

	for (int y = (int)r.y + 4; y < (int)(r.y + r.h) - 4; y++)
		for (int x = (int)r.x + 4; x < (int)(r.x + r.w) - 4; x++) {
			const uint8_t *p = img + ((size_t)y * (size_t)width + (size_t)x) * 4;

			n += p[0] < 230 || p[1] < 230 || p[2] < 220;
		}
	return n;
}

/*
 * The New strip: every card shows its tree (the blank one its sheet), each picture's meshes
 * uploaded once until previews_serial changes; the leaf suggestions' slots are not the
 * templates'.
 */
static void test_templates(void)
{
	struct fixture f;
	struct app *app = app_create(640, 400, 1);
	struct app_side_item items[APP_SIDE_MAX];
	struct render_stats st;
	struct render *r;
	uint64_t t = 1000;
	size_t n;

	CHECK(app);
	press_button(app, &t, BUTTON_NEW);
	CHECK_INT(app->mode, APP_MODE_NEW);
	CHECK(app->templates_ready);
	n = app_side_items(app, items);
	CHECK_INT(n, 1 + GEN_PRESET_COUNT);
	CHECK_INT(app_side_kind(&items[0]), LAYOUT_SIDE_NAMED_CARDS);
	fixture_init(&f, 640, 400);
	r = render_create();
	CHECK(r);

	draw(&f, r, app, f.a);
	render_get_stats(r, &st);
	/* the (empty) tree's two meshes, two for each template */
	CHECK_INT(st.uploads, 2 + 2 * GEN_PRESET_COUNT);
	CHECK_INT(st.tree_triangles, 0);
	for (size_t i = 0; i < n; i++) {
		struct layout_rect card = layout_side_slot(&app->screen, i, LAYOUT_SIDE_NAMED_CARDS);
		size_t drawn = drawn_in(f.a, 640, layout_card_picture(card, LAYOUT_SIDE_NAMED_CARDS));

		if (drawn < 200)
			fprintf(stderr, "card %zu: %zu pixels drawn\n", i, drawn);
		CHECK(drawn >= 200);
	}
	/* nothing changed: nothing uploaded, the same picture */
	draw(&f, r, app, f.b);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 0);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	/* the app's pictures changed: each template again */
	app->previews_serial++;
	draw(&f, r, app, f.b);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 2 * GEN_PRESET_COUNT);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	/* drawing closes the strip: no pictures, no uploads */
	pen_line(app, &t, 320, 368, 320, 200);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	draw(&f, r, app, f.b);
	render_get_stats(r, &st);
	CHECK_INT(st.uploads, 2);

	render_destroy(r);
	fixture_finish(&f);
	app_destroy(app);
}

static char *font_data;
static size_t font_len;

static void load_font(void)
{
	struct error err;
	const char *used;

	if (font_file_read(NULL, &font_data, &font_len, &used, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
}

static struct render *labelled(enum render_lang lang)
{
	struct render *r = render_create();

	CHECK(r);
	CHECK_INT(render_set_text(r, font_data, font_len, lang), 0);
	return r;
}

/* Labels cost no draw call of their own: the kiosk scene draws in as many calls with
 * them as without; they change the picture, and so does the language. */
static void test_labels_batched(void)
{
	struct fixture f;
	struct app app;
	struct render *plain, *en, *ja;
	struct render_stats sp, se;
	uint8_t *c;

	CHECK_INT(scene_build(&app, "kiosk"), 0);
	fixture_init(&f, app.screen.width, app.screen.height);
	c = malloc(f.size);
	CHECK(c);
	plain = render_create();
	CHECK(plain);
	en = labelled(RENDER_LANG_EN);
	ja = labelled(RENDER_LANG_JA);
	draw(&f, plain, &app, f.a);
	render_get_stats(plain, &sp);
	draw(&f, en, &app, f.b);
	render_get_stats(en, &se);
	CHECK_INT(se.draw_calls, sp.draw_calls);
	CHECK_INT(se.draw_calls, 4);
	/* two triangles a glyph more */
	CHECK(se.triangles > sp.triangles + 2 * 20);
	CHECK(differing(f.a, f.b, f.size, 8) > 500);
	draw(&f, ja, &app, c);
	CHECK(differing(f.b, c, f.size, 8) > 500);
	/* the canvas is the same in all three: only the bar changed */
	{
		struct layout_rect bar = layout_bar(&app.screen);
		size_t row = (size_t)app.screen.width * 4;

		for (int y = 0; y < app.screen.height; y += 7)
			CHECK(memcmp(f.a + y * row, c + y * row, (size_t)(bar.x - 12) * 4) == 0);
	}
	/* the same again: the glyphs are cached, none is rasterised a second time */
	{
		size_t glyphs = font_cached(en->text.font);

		CHECK(glyphs >= 15); /* the distinct letters of the eight labels */
		draw(&f, en, &app, c);
		CHECK_INT(font_cached(en->text.font), glyphs);
		CHECK(memcmp(f.b, c, f.size) == 0);
	}

	/* no font, or one FreeType cannot read: icons only, as without */
	CHECK_INT(render_set_text(en, NULL, 0, RENDER_LANG_EN), 0);
	draw(&f, en, &app, c);
	CHECK(memcmp(f.a, c, f.size) == 0);
	CHECK_INT(render_set_text(ja, "junk", 4, RENDER_LANG_JA), -EINVAL);
	draw(&f, ja, &app, c);
	CHECK(memcmp(f.a, c, f.size) == 0);

	free(c);
	render_destroy(plain);
	render_destroy(en);
	render_destroy(ja);
	fixture_finish(&f);
	scene_finish(&app);
}

/* A pixel's red channel. */
static int red_at(const uint8_t *img, int width, int x, int y)
{
	return img[((size_t)y * (size_t)width + (size_t)x) * 4];
}

/* The message shows from when it was set, fully until its last half second, fading
 * then, gone after; the settled view (render_frame) has none. */
static void test_status_fades(void)
{
	struct fixture f;
	struct app app;
	struct render *r;
	uint8_t *none, *half;
	uint64_t at, until;
	int x = 0, y = 0, best = -1;

	CHECK_INT(scene_build(&app, "saved"), 0);
	at = app.status_us;
	CHECK_INT(app_status_at(&app, at, &until), APP_STATUS_SAVED);
	fixture_init(&f, app.screen.width, app.screen.height);
	none = malloc(f.size);
	half = malloc(f.size);
	CHECK(none && half);
	r = labelled(RENDER_LANG_EN);

	CHECK_INT(render_frame_at(r, &app, at - 1), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, none), 0);
	draw(&f, r, &app, f.b);
	CHECK(memcmp(none, f.b, f.size) == 0);
	CHECK_INT(render_frame_at(r, &app, until), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.b), 0);
	CHECK(memcmp(none, f.b, f.size) == 0);

	CHECK_INT(render_frame_at(r, &app, at), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.a), 0);
	CHECK(differing(none, f.a, f.size, 8) > 2000);
	/* still whole just before the fade */
	CHECK_INT(render_frame_at(r, &app, until - APP_STATUS_FADE_US), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.b), 0);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	CHECK_INT(render_frame_at(r, &app, until - APP_STATUS_FADE_US / 2), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, half), 0);
	CHECK(differing(half, f.a, f.size, 8) > 1000);
	CHECK(differing(half, none, f.size, 8) > 1000);
	/* half way: the tick's green disc is half over the paper */
	for (int yy = 0; yy < app.screen.height / 4; yy++)
		for (int xx = 0; xx < app.screen.width; xx++) {
			int d = red_at(none, app.screen.width, xx, yy) - red_at(f.a, app.screen.width, xx, yy);

			if (d > best) {
				best = d;
				x = xx;
				y = yy;
			}
		}
	CHECK(best > 100);
	{
		int full = red_at(f.a, app.screen.width, x, y), bare = red_at(none, app.screen.width, x, y);
		int mid = red_at(half, app.screen.width, x, y);

		CHECK(abs(mid - (full + bare) / 2) <= 12);
	}
	free(none);
	free(half);
	render_destroy(r);
	fixture_finish(&f);
	scene_finish(&app);
}

/* The attract screen comes attract_after_us after the last event, holds still (an idle
 * kiosk need not draw), leaves the bar alone, and the next event ends it. */
static void test_attract(void)
{
	struct fixture f;
	struct app *app = app_create(640, 400, 3);
	struct render *r;
	struct event ev = { .type = EVENT_PROXIMITY_IN, .x = 300, .y = 200, .time_us = 1000 };
	struct layout_rect bar;
	uint8_t *later;
	uint64_t from;

	CHECK(app);
	app->attract_after_us = APP_ATTRACT_US_DEFAULT;
	app_handle_event(app, &ev);
	ev.type = EVENT_PROXIMITY_OUT;
	app_handle_event(app, &ev);
	CHECK(!app_attract_at(app, 1000 + APP_ATTRACT_US_DEFAULT - 1, &from));
	CHECK_INT(from, 1000 + APP_ATTRACT_US_DEFAULT);
	fixture_init(&f, 640, 400);
	later = malloc(f.size);
	CHECK(later);
	r = labelled(RENDER_LANG_JA);

	draw(&f, r, app, f.a);
	CHECK_INT(render_frame_at(r, app, from - 1), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.b), 0);
	CHECK(memcmp(f.a, f.b, f.size) == 0);
	CHECK_INT(render_frame_at(r, app, from), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, f.b), 0);
	CHECK(differing(f.a, f.b, f.size, 8) > 20000);
	CHECK_INT(render_frame_at(r, app, from + 3600u * 1000000u), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, later), 0);
	CHECK(memcmp(f.b, later, f.size) == 0);
	/* over the canvas only */
	bar = layout_bar(&app->screen);
	for (int y = 0; y < 400; y++)
		CHECK(memcmp(f.a + ((size_t)y * 640 + (size_t)bar.x) * 4,
			     f.b + ((size_t)y * 640 + (size_t)bar.x) * 4, (size_t)bar.w * 4) == 0);
	/* the pen comes near: gone */
	ev.type = EVENT_PROXIMITY_IN;
	ev.time_us = from + 5000000;
	app_handle_event(app, &ev);
	ev.type = EVENT_PROXIMITY_OUT;
	app_handle_event(app, &ev);
	CHECK_INT(render_frame_at(r, app, ev.time_us + 1), 0);
	CHECK_INT(egl_headless_read_rgba(f.egl, later), 0);
	CHECK(memcmp(f.a, later, f.size) == 0);

	free(later);
	render_destroy(r);
	fixture_finish(&f);
	app_destroy(app);
}

int main(void)
{
	load_font();
	test_labels_batched();
	test_status_fades();
	test_attract();
	test_turn();
	test_templates();
	test_upload_only_on_serial();
	test_expanded_indices();
	test_instanced();
	test_seasons();
	test_bad_mesh();
	test_empty();
	test_antialiased_stroke();
	free(font_data);
	return 0;
}
