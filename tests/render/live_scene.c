/* SPDX-License-Identifier: MIT */
/*
 * The living tree on the screen (issue 26, docs/living-trees.md), on the demo's tree
 * (tests/data/demo.edaha-trace replayed into the app, then the 3D button), drawn headless:
 *
 *   live-scene [--twice] SCENE OUT.png   a moment as a picture, for golden.sh: live-grow
 *                                        (1.8 s into the growth), live-wind (the tree at
 *                                        the wind's strongest, S = 1)
 *   live-scene --check                   the tests:
 *
 * - the end of the growth is the settled screen: a frame drawn by the living programs a
 *   microsecond before the growth ends is the settled frame byte for byte (the pull is
 *   exactly 1 and the still wind exactly 0 there), leaves merged and instanced;
 * - the shader's wind is live_wind_frame_offset's: the tree at a moment of wind (S = 1)
 *   drawn by the living programs against the same meshes moved on the CPU by the
 *   reference and drawn by the still programs, within imgcmp's default tolerance (8
 *   levels, 0.1% of the pixels), while the wind itself moves far more pixels than that;
 * - the frame uploads nothing while the tree moves (no mesh rebuilt per frame);
 * - origami leaves unfold as the tree grows in (a maple tree: edit-propagate-count's
 *   drawing with maple leaves, instanced): the growth's order holds every instance once,
 *   an origami shape's by their anchors' d; at 40 moments each leaf is drawn at the
 *   keyframe live_grow_unfold_frame gives its d (the ranges the frame draws, counted),
 *   none past the front; the picture differs from the same moment with the leaves only
 *   scaled in; and the end of the growth is the settled frame byte for byte.
 *
 *   live-scene SCENE also makes live-unfold (the maple tree three quarters into its growth).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "app_private.h"
#include "buf.h"
#include "egl_headless.h"
#include "font_file.h"
#include "live.h"
#include "pngio.h"
#include "render.h"
#include "render_private.h"
#include "scene.h"
#include "test.h"
#include "trace.h"

#define WIDTH 1280
#define HEIGHT 800
#define SEED 1

struct scene {
	struct egl_headless *egl;
	struct render *r;
	struct app *app;
	uint64_t press_us;
	uint8_t *rgba[3];
};

/* The demo drawn and made 3D: the press goes down 100 ms after the last event. */
static struct app *demo_3d(uint64_t *press_us)
{
	struct app *app = app_create(WIDTH, HEIGHT, SEED);
	struct trace t;
	struct error err;
	struct event ev = { .type = EVENT_BUTTON, .button = BUTTON_3D, .pressed = true };

	CHECK(app);
	trace_init(&t);
	CHECK(trace_load(DEMO_TRACE, WIDTH, HEIGHT, &t, &err) == 0);
	for (size_t i = 0; i < t.nevents; i++)
		app_handle_event(app, &t.events[i]);
	CHECK(t.nevents > 0);
	ev.time_us = t.events[t.nevents - 1].time_us + 100000;
	*press_us = ev.time_us;
	app_handle_event(app, &ev);
	ev.pressed = false;
	ev.time_us += 50000;
	app_handle_event(app, &ev);
	trace_finish(&t);
	CHECK(app->tree.lifted && !app->failed);
	return app;
}

/* The render tests' leafy tree (scene.h): a shape of leaves copied over every branch, drawn
 * instanced on GLES 3; growing from 1 s. */
static struct app leafy_app;

static struct app *leafy(uint64_t *press_us)
{
	scene_leafy(&leafy_app, WIDTH, HEIGHT, camera_normalize(-30.0, 10.0), true);
	app_live_init(&leafy_app);
	*press_us = 1000000;
	CHECK(app_live_grow_start(&leafy_app, *press_us) == 0);
	CHECK(leafy_app.live.growing);
	return &leafy_app;
}

/* A maple tree: the leaf-maple card, then edit-propagate-count's drawing (its strokes,
 * 3D, leaves arranged and propagated) as the headless run replays it; growing in from
 * 100 ms after its last event, as a loaded drawing would. */
static struct app *maple(uint64_t *press_us)
{
	struct app *app = app_create(WIDTH, HEIGHT, SEED);
	struct trace t;
	struct error err;
	struct event ev = { .type = EVENT_BUTTON, .button = BUTTON_LEAF_MAPLE, .pressed = true };

	CHECK(app);
	app_handle_event(app, &ev);
	ev.pressed = false;
	ev.time_us = 50000;
	app_handle_event(app, &ev);
	trace_init(&t);
	CHECK(trace_load(PROPAGATE_TRACE, WIDTH, HEIGHT, &t, &err) == 0);
	for (size_t i = 0; i < t.nevents; i++) {
		t.events[i].time_us += 100000;
		app_handle_event(app, &t.events[i]);
	}
	CHECK(t.nevents > 0);
	*press_us = t.events[t.nevents - 1].time_us + 100000;
	trace_finish(&t);
	CHECK(app->tree.lifted && !app->failed);
	CHECK(app->tree.nleaves > 10 && app->tree.leaf_kind >= 0);
	app->live.grow_in = true;
	CHECK(app_live_grow_start(app, *press_us) == 0);
	CHECK(app->live.growing);
	return app;
}

static void done(struct app *app)
{
	if (app != &leafy_app) {
		app_destroy(app);
		return;
	}
	app_live_finish(app);
	scene_leafy_finish(app);
}

static void draw(struct scene *s, uint64_t now_us, int k)
{
	CHECK(render_frame_at(s->r, s->app, now_us) == 0);
	CHECK(egl_headless_read_rgba(s->egl, s->rgba[k]) == 0);
}

/* The fraction of pixels some channel of which differs by more than 8 (imgcmp's rule). */
static double differing(const uint8_t *a, const uint8_t *b)
{
	size_t n = 0;

	for (size_t i = 0; i < (size_t)WIDTH * HEIGHT; i++) {
		int worst = 0;

		for (int c = 0; c < 4; c++) {
			int d = abs((int)a[4 * i + c] - (int)b[4 * i + c]);

			worst = d > worst ? d : worst;
		}
		n += worst > 8;
	}
	return (double)n / ((double)WIDTH * HEIGHT);
}

/* The moment of the wind's strongest sway of the whole tree after `after`: band 0 at a
 * quarter of its period. */
static uint64_t strongest(const struct app *app, uint64_t after)
{
	const struct live_wind *w = &app->live.wind;
	double loop = w->loop, t = ceil((double)after * 1e-6 / loop) * loop;

	return (uint64_t)llround((t + loop / (4.0 * w->harmonic[0])) * 1e6);
}

/* A renderer with the labels' font, as the kiosk's. */
static struct render *renderer(void)
{
	struct render *r = render_create();
	struct error err;
	const char *used;
	char *font;
	size_t len;

	CHECK(r);
	CHECK(font_file_read(NULL, &font, &len, &used, &err) == 0);
	CHECK(render_set_text(r, font, len, RENDER_LANG_EN) == 0);
	free(font);
	return r;
}

static void setup(struct scene *s)
{
	struct error err;

	s->egl = egl_headless_create(WIDTH, HEIGHT, &err);
	if (!s->egl) {
		fprintf(stderr, "live-scene: %s\n", err.msg);
		exit(1);
	}
	s->r = renderer();
	for (int k = 0; k < 3; k++)
		CHECK((s->rgba[k] = malloc((size_t)WIDTH * HEIGHT * 4)));
}

static void teardown(struct scene *s)
{
	render_destroy(s->r);
	egl_headless_destroy(s->egl);
	for (int k = 0; k < 3; k++)
		free(s->rgba[k]);
}

typedef struct app *(*maker)(uint64_t *press_us);

/* The end of the growth, drawn living, is the settled frame. */
static void check_end(struct scene *s, maker make, bool instanced)
{
	bool could = s->r->instanced;
	uint64_t end;

	s->r->instanced = could && instanced;
	s->app = make(&s->press_us);
	s->app->turning = false; /* the swing into 3D aside: the settled camera all along */
	end = app_live_grow_end(s->app);
	CHECK(end > s->press_us);
	draw(s, UINT64_MAX, 0);
	CHECK(!s->r->live.on);
	draw(s, end - 1, 1);
	CHECK(s->r->live.on);
	CHECK(memcmp(s->rgba[0], s->rgba[1], (size_t)WIDTH * HEIGHT * 4) == 0);
	/* half way, it is growing: another picture */
	draw(s, s->press_us + (end - s->press_us) / 2, 2);
	CHECK(s->r->live.on);
	printf("end of growth (%s, %s leaves): the settled frame byte for byte; half way %.1f%% "
	       "of the pixels differ\n", s->app == &leafy_app ? "leafy tree" : "demo",
	       s->r->uploaded_instanced && s->r->inst.nshapes ? "instanced" : "merged",
	       100.0 * differing(s->rgba[0], s->rgba[2]));
	CHECK(differing(s->rgba[0], s->rgba[2]) > 0.01);
	done(s->app);
	s->r->instanced = could;
}

/* m's vertices moved by the reference wind of frame f, as v binds them. */
static void move(struct mesh *m, const struct live_attrs *v, const struct app_live_frame *f)
{
	CHECK(v->n == m->nvertices);
	for (size_t i = 0; i < m->nvertices; i++) {
		struct vec3 o = live_wind_frame_offset(&f->wind, &v->v[i]);

		m->positions[3 * i] = (float)(m->positions[3 * i] + o.x);
		m->positions[3 * i + 1] = (float)(m->positions[3 * i + 1] + o.y);
		m->positions[3 * i + 2] = (float)(m->positions[3 * i + 2] + o.z);
	}
}

/* The shader's wind against the reference's on the CPU. */
static void check_wind(struct scene *s, maker make, bool instanced)
{
	bool could = s->r->instanced;
	struct live_attrs bark, leaves;
	struct app_live_frame f;
	struct render_stats st;
	uint64_t t;
	double moved, off;
	bool inst_drawn;

	s->r->instanced = could && instanced;
	s->app = make(&s->press_us);
	s->app->turning = false;
	s->app->live.growing = false;
	CHECK(app_set_wind(s->app, 1.0) == 0);
	t = strongest(s->app, s->press_us + 10000000);
	draw(s, UINT64_MAX, 0); /* still */
	draw(s, t, 1);
	CHECK(s->r->live.on);
	/* a frame of wind uploads nothing: the meshes and their data are on the GPU */
	draw(s, t + 16667, 2);
	render_get_stats(s->r, &st);
	CHECK(st.uploads == 0 && s->r->live.bytes == 0);
	draw(s, t, 1);
	inst_drawn = s->r->uploaded_instanced && s->r->inst.nshapes;
	moved = differing(s->rgba[0], s->rgba[1]);
	/* the reference: the same meshes moved on the CPU, drawn still */
	CHECK(app_live_at(s->app, t, &f) && f.moving && !f.growing);
	live_attrs_init(&bark);
	live_attrs_init(&leaves);
	CHECK(live_attrs_bind_bark(&bark, app_live_skeleton(s->app), &s->app->tree,
				   &s->app->mesh.bark, &s->app->mesh_marks) == 0);
	CHECK(live_attrs_bind_leaves(&leaves, app_live_skeleton(s->app), &s->app->tree,
				     &s->app->mesh.leaves, &s->app->mesh_marks) == 0);
	move(&s->app->mesh.bark, &bark, &f);
	move(&s->app->mesh.leaves, &leaves, &f);
	CHECK(app_set_wind(s->app, 0.0) == 0);
	s->app->mesh_serial++;
	/* leaves merged: an instanced leaf is its shape moved rigidly, which a moved copy is
	 * not quite */
	s->r->instanced = false;
	draw(s, t, 2);
	CHECK(!s->r->live.on);
	off = differing(s->rgba[1], s->rgba[2]);
	printf("wind at S = 1 (%s leaves): %.2f%% of the pixels moved; the shader against the "
	       "reference moved on the CPU: %.3f%% differ (imgcmp allows 0.1%%)\n",
	       inst_drawn ? "instanced" : "merged", 100.0 * moved, 100.0 * off);
	CHECK(moved > 0.01);
	CHECK(off <= 0.001);
	live_attrs_finish(&bark);
	live_attrs_finish(&leaves);
	done(s->app);
	s->r->instanced = could;
}

/* The origami leaves unfold by keyframes as the tree grows in. */
static void check_unfold(struct scene *s)
{
	struct render_instanced *in = &s->r->inst;
	uint64_t end;
	size_t origami = 0, ranges = 0, at_keyframe = 0, open = 0, unborn = 0, most = 0;
	bool frames[LEAF_INSTANCES_MAX_SHAPES];
	double scaled = 0.0;

	if (!s->r->instanced) {
		printf("unfolding: no GLES 3 here, no instanced leaves: skipped\n");
		return;
	}
	s->app = maple(&s->press_us);
	s->app->turning = false;
	end = app_live_grow_end(s->app);
	for (int m = 1; m < 40; m++) {
		uint64_t now = s->press_us + (end - s->press_us) * (uint64_t)m / 40;
		const struct app_live_frame *f = &s->r->live.frame;
		struct render_stats st;
		size_t drawn = 0, kf_before = at_keyframe;

		draw(s, now, 0);
		CHECK(s->r->live.on && f->growing && in->grow_ok && s->r->live.grow_instances.ok);
		render_get_stats(s->r, &st);
		CHECK(m == 1 || (st.uploads == 0 && s->r->live.bytes == 0));
		/* the order: each instance once, an origami shape's by d, each at the keyframe
		 * its d gives, in the range the frame draws it */
		for (size_t k = 0; k < in->nshapes; k++) {
			size_t a = in->first[k], b = a + in->count[k];

			if (!in->has_frames[k])
				continue;
			origami += m == 1 ? in->count[k] : 0;
			for (size_t i = a; i < b; i++) {
				unsigned kf = live_grow_unfold_frame(f->front, f->swell, ORI_UNFOLD_FRAMES,
								     in->grow_d[i]);

				CHECK(in->grow_order[i] >= a && in->grow_order[i] < b);
				CHECK(i == a || in->grow_d[i - 1] <= in->grow_d[i]);
				CHECK(i == a || in->grow_order[i - 1] != in->grow_order[i]);
				if (in->grow_d[i] > f->front) {
					unborn++;
					continue;
				}
				drawn++;
				if (kf == ORI_UNFOLD_FRAMES)
					open++;
				else
					at_keyframe++;
				/* a new range wherever the keyframe changes */
				if (i == a || in->grow_d[i - 1] > f->front ||
				    kf != live_grow_unfold_frame(f->front, f->swell, ORI_UNFOLD_FRAMES,
								 in->grow_d[i - 1]))
					ranges++;
			}
		}
		/* the same moment with the leaves only scaling in, as the others: where the
		 * most leaves are unfolding */
		if (at_keyframe - kf_before > most) {
			double d;

			most = at_keyframe - kf_before;
			draw(s, now, 1);
			for (size_t k = 0; k < in->nshapes; k++) {
				frames[k] = in->has_frames[k];
				in->has_frames[k] = false;
			}
			draw(s, now, 2);
			for (size_t k = 0; k < in->nshapes; k++)
				in->has_frames[k] = frames[k];
			d = differing(s->rgba[1], s->rgba[2]);
			scaled = d > scaled ? d : scaled;
		}
		(void)drawn;
	}
	CHECK(origami > 0 && at_keyframe > 0 && open > 0 && unborn > 0);
	CHECK(scaled > 0.0002);
	/* and its end is the settled frame */
	draw(s, UINT64_MAX, 0);
	draw(s, end - 1, 1);
	CHECK(s->r->live.on);
	CHECK(memcmp(s->rgba[0], s->rgba[1], (size_t)WIDTH * HEIGHT * 4) == 0);
	printf("unfolding (maple tree, %zu origami leaves instanced): at 39 moments %zu leaves "
	       "drawn at a keyframe, %zu open, %zu not yet, in %zu ranges; against scaling in "
	       "%.2f%% of the pixels differ; the end the settled frame byte for byte\n",
	       origami, at_keyframe, open, unborn, ranges, 100.0 * scaled);
	done(s->app);
}

static int write_png(const char *path, const uint8_t *rgba)
{
	struct buf b;
	struct error err;
	FILE *f;
	int ret;

	buf_init(&b);
	ret = pngio_encode_rgba(rgba, WIDTH, HEIGHT, &b, &err);
	if (ret == 0) {
		f = fopen(path, "wb");
		ret = f && fwrite(b.data, 1, b.len, f) == b.len ? 0 : -EIO;
		if (f && fclose(f) != 0)
			ret = -EIO;
	}
	buf_finish(&b);
	return ret;
}

/* A scene's moment as a picture; with twice, drawn again by the same renderer and a new
 * one, byte for byte the same. */
static int picture(struct scene *s, const char *name, const char *out, bool twice)
{
	uint64_t now;

	s->app = !strcmp(name, "live-unfold") ? maple(&s->press_us) : demo_3d(&s->press_us);
	if (!strcmp(name, "live-unfold")) {
		s->app->turning = false;
		now = s->press_us + (app_live_grow_end(s->app) - s->press_us) * 3 / 4;
	} else if (!strcmp(name, "live-grow")) {
		now = s->press_us + 1800000;
	} else if (!strcmp(name, "live-wind")) {
		s->app->live.growing = false;
		CHECK(app_set_wind(s->app, 1.0) == 0);
		now = strongest(s->app, s->press_us + 10000000);
	} else {
		fprintf(stderr, "live-scene: no scene %s (live-grow, live-wind, live-unfold)\n",
			name);
		return 2;
	}
	draw(s, now, 0);
	if (twice) {
		draw(s, now, 1);
		CHECK(memcmp(s->rgba[0], s->rgba[1], (size_t)WIDTH * HEIGHT * 4) == 0);
		render_destroy(s->r);
		s->r = renderer();
		draw(s, now, 1);
		CHECK(memcmp(s->rgba[0], s->rgba[1], (size_t)WIDTH * HEIGHT * 4) == 0);
	}
	CHECK(write_png(out, s->rgba[0]) == 0);
	app_destroy(s->app);
	return 0;
}

int main(int argc, char **argv)
{
	struct scene s = { 0 };
	bool twice = argc == 4 && !strcmp(argv[1], "--twice");
	int status = 0;

	if (argc == 2 && !strcmp(argv[1], "--check")) {
		setup(&s);
		check_end(&s, demo_3d, false);
		check_end(&s, leafy, false);
		check_end(&s, leafy, true);
		check_wind(&s, demo_3d, false);
		check_wind(&s, leafy, false);
		check_wind(&s, leafy, true);
		check_unfold(&s);
		teardown(&s);
		return 0;
	}
	if (argc != 3 && !twice) {
		fprintf(stderr, "usage: live-scene [--twice] SCENE OUT.png | --check\n");
		return 2;
	}
	setup(&s);
	status = picture(&s, argv[argc - 2], argv[argc - 1], twice);
	teardown(&s);
	return status;
}
