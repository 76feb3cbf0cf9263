/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: a whole headless session from arbitrary bytes. Whatever trace (edaha or
 * libinput record) is accepted is fed to the app, then everything edaha writes is made:
 * skeleton.json, model.glb, model.obj/.mtl and drawing.edaha. The drawing must load back
 * to the very same document: edaha must never write a drawing it cannot read.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "buf.h"
#include "doc.h"
#include "export.h"
#include "trace.h"

/* The fuzzer's screen: small, so that meshes stay cheap. */
#define SCREEN_W 320
#define SCREEN_H 200
/*
 * Work per input, so that a timeout means a real slowness rather than a big input: events
 * fed, and mesh built. Every stroke and undo rebuilds the whole tree mesh, so a session
 * costs the square of its strokes; summing the vertices and indices of every rebuild
 * caps that at a few seconds under ASan.
 */
#define MAX_EVENTS 20000
#define MAX_MESH_WORK 30000000u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));

static void die(const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "fuzz_replay: ");
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, "\n");
	abort();
}

/* Running out of memory is not a bug the fuzzer looks for; anything else is. */
static void check(const char *what, int r)
{
	if (r < 0 && r != -ENOMEM)
		die("%s failed: %s", what, strerror(-r));
}

static bool same_float(float a, float b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

/* drawing.edaha holds the document exactly: every op, point and number as it was. */
static void check_same_doc(const struct doc *a, const struct doc *b)
{
	if (a->seed != b->seed || a->nops != b->nops || a->cursor != b->cursor)
		die("drawing.edaha reads back with another seed or history");
	for (size_t i = 0; i < a->nops; i++) {
		const struct doc_op *x = &a->ops[i], *y = &b->ops[i];

		if (x->kind != y->kind || x->time_us != y->time_us ||
		    (x->kind == DOC_OP_STROKE && (x->tool != y->tool || x->npoints != y->npoints)))
			die("drawing.edaha reads back with another op %zu", i);
		if (x->kind != DOC_OP_STROKE)
			continue;
		for (size_t k = 0; k < x->npoints; k++) {
			const struct doc_point *p = &x->points[k], *q = &y->points[k];

			if (!same_float(p->x, q->x) || !same_float(p->y, q->y) ||
			    !same_float(p->pressure, q->pressure) || p->dt_us != q->dt_us)
				die("drawing.edaha reads back with another point %zu of op %zu", k, i);
		}
	}
}

static void export_all(struct app *app)
{
	struct error err = { { 0 } };
	struct buf a, b;
	struct doc d;
	int r;

	buf_init(&a);
	buf_init(&b);
	check("export_skeleton", export_skeleton(&app->tree, &a));
	buf_reset(&a);
	check("export_glb", export_glb(&app->tree, &app->mesh, &app->mesh_marks, &a));
	buf_reset(&a);
	check("export_obj", export_obj(&app->tree, &app->mesh, &app->mesh_marks, "model.mtl", &a, &b));
	buf_reset(&a);
	r = doc_serialize(&app->doc, &app->tree, &a);
	check("doc_serialize", r);
	if (r == 0) {
		r = doc_parse((const char *)a.data, a.len, "drawing.edaha", &d, &err);
		if (r == -ENOMEM) {
			buf_finish(&b);
			buf_finish(&a);
			return;
		}
		if (r < 0) {
			fwrite(a.data, 1, a.len < 4096 ? a.len : 4096, stderr);
			die("edaha wrote a drawing it cannot load: %s", err.msg);
		}
		check_same_doc(&app->doc, &d);
		doc_finish(&d);
	}
	buf_finish(&b);
	buf_finish(&a);
}

static size_t mesh_work(const struct tree_mesh *m)
{
	return m->bark.nvertices + m->bark.nindices + m->leaves.nvertices + m->leaves.nindices;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct trace t = { 0 };
	struct error err;
	struct app *app;

	if (trace_parse((const char *)data, size, "fuzz", SCREEN_W, SCREEN_H, &t, &err) < 0)
		return 0;
	app = app_create(SCREEN_W, SCREEN_H, 1);
	if (app) {
		uint64_t serial = app->mesh_serial;
		size_t work = 0;

		for (size_t i = 0; i < t.nevents && i < MAX_EVENTS && work < MAX_MESH_WORK; i++) {
			app_handle_event(app, &t.events[i]);
			if (app->mesh_serial != serial) {
				serial = app->mesh_serial;
				work += mesh_work(&app->mesh);
			}
		}
		export_all(app);
		app_destroy(app);
	}
	trace_finish(&t);
	return 0;
}
