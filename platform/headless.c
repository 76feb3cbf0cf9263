/* SPDX-License-Identifier: MIT */
#include "headless.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "buf.h"
#include "docfile.h"
#include "egl_headless.h"
#include "fileio.h"
#include "gen.h"
#include "headless_one.h"
#include "leaf_tint.h"
#include "output.h"
#include "page_viewer.h"
#include "render.h"
#include "render_shaders.h"
#include "skeleton_read.h"
#include "trace.h"
#include "wood.h"

/* Gaps put between inputs given one after another, so time always moves forward. */
#define GAP_BETWEEN_INPUTS_US 100000
#define PRESS_LENGTH_US 50000

/* Exit status for a failure to read input: the input's fault (2) or the machine's (1). */
static int input_status(int err)
{
	return err == -ENOMEM || err == -EIO ? 1 : 2;
}

struct run {
	const struct options *o;
	struct app *app;
	struct trace_writer *rec;
	uint64_t now_us;
	int status;
	bool page; /* model.html written */
};

static void feed(struct run *r, const struct event *ev)
{
	if (r->rec && trace_writer_write(r->rec, ev) < 0 && r->status == 0) {
		fprintf(stderr, "edaha: %s: cannot write the recording\n", r->o->record);
		r->status = 1;
	}
	r->now_us = ev->time_us;
	app_handle_event(r->app, ev);
}

static void replay(struct run *r, const struct trace *t)
{
	uint64_t offset = 0;

	/* Each trace starts after what came before, whatever its own clock said. */
	if (t->nevents && t->events[0].time_us <= r->now_us)
		offset = r->now_us + GAP_BETWEEN_INPUTS_US - t->events[0].time_us;
	/* Parsers cap times far below this, so the sums below cannot wrap. */
	for (size_t i = 0; i < t->nevents; i++) {
		struct event ev = t->events[i];

		ev.time_us += offset;
		feed(r, &ev);
	}
}

static void press(struct run *r, enum button button)
{
	struct event ev = { .type = EVENT_BUTTON, .button = (int)button, .pressed = true };

	ev.time_us = r->now_us + GAP_BETWEEN_INPUTS_US;
	feed(r, &ev);
	ev.pressed = false;
	ev.time_us += PRESS_LENGTH_US;
	feed(r, &ev);
}

static int load_doc(struct run *r, const char *path)
{
	struct error err = { { 0 } };
	struct doc doc;
	int ret = docfile_read(path, &doc, &err);

	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return input_status(ret);
	}
	if (r->o->seed_given && doc.seed != r->o->seed)
		fprintf(stderr, "edaha: %s keeps its own seed %llu; --seed ignored\n", path,
			(unsigned long long)doc.seed);
	if (app_load_doc(r->app, &doc) < 0) {
		doc_finish(&doc);
		fprintf(stderr, "edaha: out of memory loading %s\n", path);
		return 1;
	}
	return 0;
}

/* The tree parameter file, read before anything runs: a bad one stops the run (exit 2)
 * with FILE:LINE and nothing written. */
static int read_params(const char *path, struct gen_params *p)
{
	struct error err = { { 0 } };
	size_t len;
	char *data;
	int ret = fileio_read_all(path, 1u << 20, &data, &len, &err);

	if (ret == 0) {
		ret = gen_read(data, len, path, 0, p, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return input_status(ret);
	}
	return 0;
}

/* The wood settings file (--wood), read before anything runs, as the tree parameters. */
static int read_wood(const char *path, struct wood_params *p)
{
	struct error err = { { 0 } };
	size_t len;
	char *data;
	int ret = fileio_read_all(path, 2 * WOOD_READ_MAX_BYTES, &data, &len, &err);

	if (ret == 0) {
		ret = wood_read(data, len, path, 0, p, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return input_status(ret);
	}
	return 0;
}

/* The skeleton.json's branches, read before anything runs as the parameter file is. */
static int read_skeleton(const char *path, struct tree *t)
{
	struct error err = { { 0 } };
	size_t len;
	char *data;
	int ret = fileio_read_all(path, SKELETON_READ_MAX_BYTES, &data, &len, &err);

	if (ret == 0) {
		ret = skeleton_read(data, len, path, t, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return input_status(ret);
	}
	return 0;
}

/* --dump-voxels: the grown wood's voxels beside the other files (docs/wood.md). */
static int dump_voxels(const struct app *app, const char *dir)
{
	struct error err = { { 0 } };
	struct buf json, bin;
	int ret;

	buf_init(&json);
	buf_init(&bin);
	ret = wood_dump(app->tree.wood, &json, &bin);
	if (ret == 0)
		ret = fileio_write_atomic(dir, "voxels.json", json.data, json.len, &err);
	if (ret == 0)
		ret = fileio_write_atomic(dir, "voxels.bin", bin.data, bin.len, &err);
	if (ret < 0)
		fprintf(stderr, "edaha: %s\n", ret == -ENOMEM ? "out of memory" : err.msg);
	buf_finish(&json);
	buf_finish(&bin);
	return ret < 0 ? 1 : 0;
}

/* Reads every trace before anything runs, so bad input stops the run before it starts. */
static int load_traces(const struct options *o, struct trace *traces)
{
	for (size_t i = 0; i < o->nsteps; i++) {
		struct error err = { { 0 } };
		int ret;

		trace_init(&traces[i]);
		if (o->steps[i].kind != STEP_REPLAY)
			continue;
		ret = trace_load(o->steps[i].path, o->width, o->height, &traces[i], &err);
		if (ret < 0) {
			fprintf(stderr, "edaha: %s\n", err.msg);
			return input_status(ret);
		}
	}
	return 0;
}

/*
 * The moment shown: the settled screen, or with --idle what the kiosk shows that long
 * after the last input (a step of the turn into 3D, a vine growing, a message, the
 * attract screen).
 */
static int draw(struct render *render, const struct run *r)
{
	uint64_t idle_us;

	if (!r->o->idle_given) {
		(void)app_vines_advance(r->app, UINT64_MAX); /* grown */
		return render_frame(render, r->app);
	}
	r->app->attract_after_us = APP_ATTRACT_US_DEFAULT;
	/* --idle is at most a day: no overflow */
	idle_us = (uint64_t)llround(r->o->idle_s * 1e6);
	(void)app_vines_advance(r->app, r->app->last_time_us + idle_us);
	return render_frame_at(render, r->app, r->app->last_time_us + idle_us);
}

static int render_and_write(struct run *r)
{
	const struct options *o = r->o;
	struct error err = { { 0 } };
	struct egl_headless *egl;
	struct render *render = NULL;
	uint8_t *rgba = NULL;
	int ret = -EIO;

	egl = egl_headless_create(o->width, o->height, &err);
	if (!egl) {
		fprintf(stderr, "edaha: no headless GL: %s\n", err.msg);
		return 1;
	}
	render = render_create();
	rgba = malloc((size_t)o->width * (size_t)o->height * 4);
	if (!render || !rgba)
		fprintf(stderr, "edaha: cannot set up the renderer\n");
	else if (headless_set_text(render, o) < 0)
		; /* said why */
	else if (draw(render, r) < 0 || egl_headless_read_rgba(egl, rgba) < 0)
		fprintf(stderr, "edaha: rendering failed\n");
	else
		ret = 0;
	render_destroy(render);
	egl_headless_destroy(egl);
	if (ret == 0) {
		/* the screen's wind; the file's is the breeze where that is still */
		const struct export_wind wind = { .strength = o->wind > 0 ? o->wind : 0.0,
						  .angle = EXPORT_WIND_ANGLE,
						  .seed = r->app->doc.seed };
		struct page_look look = {
			.lang = o->lang && !strcmp(o->lang, "ja") ? EXPORT_PAGE_JA : EXPORT_PAGE_EN,
			.paper = { render_paper[0], render_paper[1], render_paper[2] },
		.bark = { render_bark[0], render_bark[1], render_bark[2] },
		.leaves = { LEAF_TINT_SUMMER_RGB },
		.stem = { render_vine_stem[0], render_vine_stem[1], render_vine_stem[2] },
		};
		struct page_viewer viewer;

		/* the page needs the viewer's scripts; the rest is written without them */
		page_viewer_init(&viewer);
		if (page_viewer_load(&viewer, NULL, &err) < 0)
			fprintf(stderr, "edaha: no model.html: %s (the viewer's scripts are Debian's "
				"libjs-three)\n", err.msg);
		else
			look.viewer = &viewer;
		r->page = look.viewer != NULL;
		ret = output_write_all(r->app, o->out_dir, rgba, &wind, &look, &err);
		if (ret < 0)
			fprintf(stderr, "edaha: %s\n", err.msg);
		page_viewer_finish(&viewer);
	}
	free(rgba);
	return ret < 0 ? 1 : 0;
}

int headless_run(const struct options *o)
{
	struct run r = { .o = o };
	struct gen_params params;
	struct tree skeleton;
	struct trace *traces = calloc(o->nsteps ? o->nsteps : 1, sizeof(*traces));
	struct error err = { { 0 } };
	int status;

	tree_init(&skeleton);
	r.app = app_create(o->width, o->height, o->seed);
	if (!traces || !r.app) {
		fprintf(stderr, "edaha: out of memory\n");
		status = 1;
		goto out;
	}
	/* the screen's wind (headless: still unless --wind) */
	if (o->wind > 0 && app_set_wind(r.app, o->wind) < 0) {
		fprintf(stderr, "edaha: out of memory\n");
		status = 1;
		goto out;
	}
	status = load_traces(o, traces);
	if (status == 0 && o->generate)
		status = read_params(o->generate, &params);
	if (status == 0 && o->wood)
		status = read_wood(o->wood, &r.app->wood_settings);
	if (status == 0 && o->skeleton)
		status = read_skeleton(o->skeleton, &skeleton);
	if (status == 0 && o->load)
		status = load_doc(&r, o->load);
	if (status == 0 && o->record) {
		r.rec = trace_writer_create(o->record, o->width, o->height, &err);
		if (!r.rec) {
			fprintf(stderr, "edaha: %s\n", err.msg);
			status = 1;
		}
	}
	if (status)
		goto out;
	/* the tree first, as a template tap on the canvas (or on the loaded drawing) */
	if (o->generate && app_generate(r.app, &params, r.now_us + GAP_BETWEEN_INPUTS_US) == 0)
		r.now_us += GAP_BETWEEN_INPUTS_US;
	/* or the skeleton's branches, as the drawing's first op */
	if (o->skeleton) {
		int ret = app_import(r.app, &skeleton, r.now_us + GAP_BETWEEN_INPUTS_US);

		if (ret < 0) {
			fprintf(stderr, "edaha: %s: %s\n", o->skeleton,
				ret == -ENOMEM ? "out of memory" : "too big for a drawing");
			status = ret == -ENOMEM ? 1 : 2;
			goto out;
		}
		r.now_us += GAP_BETWEEN_INPUTS_US;
	}
	for (size_t i = 0; i < o->nsteps; i++) {
		if (o->steps[i].kind == STEP_REPLAY)
			replay(&r, &traces[i]);
		else
			press(&r, o->steps[i].button);
	}
	(void)app_take_requests(r.app); /* headless writes everything at the end anyway */
	if (o->view_given &&
	    !app_set_camera(r.app, camera_normalize(o->view_yaw, o->view_pitch)))
		fprintf(stderr, "edaha: --view: the drawing is not 3D (press 3d first); it is shown "
			"from the front\n");
	if (r.app->failed) {
		fprintf(stderr, "edaha: %s\n", r.app->failed == -ENOMEM ? "out of memory" : "internal error");
		status = 1;
		goto out;
	}
	status = r.status;
	if (status == 0 && o->dump_voxels && !r.app->tree.wood) {
		fprintf(stderr, "edaha: --dump-voxels: the tree has no wood to dump (it was never "
			"grown: --press grow)\n");
		status = 2;
	}
	if (status == 0)
		status = render_and_write(&r);
	if (status == 0 && o->dump_voxels)
		status = dump_voxels(r.app, o->out_dir);
	if (status == 0)
		printf("edaha: wrote screen.png, model.glb, %smodel.obj, model.mtl, skeleton.json%s "
		       "and drawing.edaha to %s\n", r.page ? "model.html, " : "",
		       o->dump_voxels ? ", voxels.json, voxels.bin" : "", o->out_dir);
out:
	if (r.rec && trace_writer_destroy(r.rec) < 0 && status == 0) {
		fprintf(stderr, "edaha: %s: cannot write the recording\n", o->record);
		status = 1;
	}
	for (size_t i = 0; traces && i < o->nsteps; i++)
		trace_finish(&traces[i]);
	free(traces);
	tree_finish(&skeleton);
	app_destroy(r.app);
	return status;
}
