/* SPDX-License-Identifier: MIT */
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TUBE_SIDES 10
#define PI 3.14159265358979323846

const char *const scene_names[] = { "leaf", "eraser", "kiosk", "saved", "save-failed-ja",
				    "saving", "saved-usb-ja", "stick-pulled", "no-stick-ja", NULL };

/* The status scenes are drawn a second into their message; a held one (saving) ten
 * seconds in, long after another would have gone. */
#define STATUS_AT_US 5000000u

static const struct {
	const char *scene;
	enum app_status status;
	bool held;
} status_scenes[] = {
	{ "saved", APP_STATUS_SAVED, false },
	{ "save-failed-ja", APP_STATUS_SAVE_FAILED, false },
	{ "saving", APP_STATUS_SAVING, true },
	{ "saved-usb-ja", APP_STATUS_SAVED_USB, false },
	{ "stick-pulled", APP_STATUS_STICK_PULLED, false },
	{ "no-stick-ja", APP_STATUS_NO_STICK, false },
};
#define NSTATUS_SCENES (sizeof(status_scenes) / sizeof(status_scenes[0]))

/* The index of a status scene, or -1. */
static int status_scene(const char *name)
{
	for (size_t i = 0; i < NSTATUS_SCENES; i++)
		if (!strcmp(name, status_scenes[i].scene))
			return (int)i;
	return -1;
}

static int reserve(struct mesh *m, size_t nv, size_t ni)
{
	if (m->nvertices + nv > m->cap_vertices) {
		size_t cap = (m->nvertices + nv) * 2;
		float *p = realloc(m->positions, cap * 3 * sizeof(float));
		float *n;

		if (!p)
			return -ENOMEM;
		m->positions = p;
		n = realloc(m->normals, cap * 3 * sizeof(float));
		if (!n)
			return -ENOMEM;
		m->normals = n;
		m->cap_vertices = cap;
	}
	if (m->nindices + ni > m->cap_indices) {
		size_t cap = (m->nindices + ni) * 2;
		uint32_t *i = realloc(m->indices, cap * sizeof(uint32_t));

		if (!i)
			return -ENOMEM;
		m->indices = i;
		m->cap_indices = cap;
	}
	return 0;
}

static uint32_t vertex(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *pos = m->positions + 3 * m->nvertices, *nrm = m->normals + 3 * m->nvertices;

	pos[0] = (float)p.x;
	pos[1] = (float)p.y;
	pos[2] = (float)p.z;
	nrm[0] = (float)n.x;
	nrm[1] = (float)n.y;
	nrm[2] = (float)n.z;
	return (uint32_t)m->nvertices++;
}

static void triangle(struct mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
	m->indices[m->nindices++] = a;
	m->indices[m->nindices++] = b;
	m->indices[m->nindices++] = c;
}

int scene_add_tube(struct mesh *m, struct vec3 a, struct vec3 b, double ra, double rb)
{
	struct vec3 d = vec3_norm_or(vec3_sub(b, a), vec3(0, 1, 0));
	/* (d, n1, z) is right-handed, so the winding below is counter-clockwise from outside */
	struct vec3 n1 = vec3_norm_or(vec3(-d.y, d.x, 0), vec3(1, 0, 0));
	struct vec3 n2 = vec3_cross(d, n1);
	uint32_t base;

	if (reserve(m, 2 * TUBE_SIDES, 6 * TUBE_SIDES) < 0)
		return -ENOMEM;
	base = (uint32_t)m->nvertices;
	for (int k = 0; k < TUBE_SIDES; k++) {
		double t = 2.0 * PI * k / TUBE_SIDES;
		struct vec3 n = vec3_add(vec3_scale(n1, cos(t)), vec3_scale(n2, sin(t)));

		vertex(m, vec3_add(a, vec3_scale(n, ra)), n);
		vertex(m, vec3_add(b, vec3_scale(n, rb)), n);
	}
	for (uint32_t k = 0; k < TUBE_SIDES; k++) {
		uint32_t a0 = base + 2 * k, b0 = a0 + 1;
		uint32_t a1 = base + 2 * ((k + 1) % TUBE_SIDES), b1 = a1 + 1;

		triangle(m, a0, a1, b0);
		triangle(m, a1, b1, b0);
	}
	return 0;
}

/* A diamond leaf from base along dir, tilted out of the sketch plane by tilt (z per metre). */
static int add_leaf(struct mesh *m, struct vec3 base, double angle, double length, double tilt,
		    bool flipped)
{
	struct vec3 dir = vec3(cos(angle), sin(angle), tilt);
	struct vec3 side = vec3(-sin(angle), cos(angle), 0.0);
	struct vec3 tip = vec3_add(base, vec3_scale(dir, length));
	struct vec3 mid = vec3_add(base, vec3_scale(dir, 0.45 * length));
	struct vec3 l = vec3_add(mid, vec3_scale(side, 0.28 * length));
	struct vec3 r = vec3_sub(mid, vec3_scale(side, 0.28 * length));
	struct vec3 n = vec3_norm_or(vec3_cross(vec3_sub(tip, base), vec3_sub(l, r)), vec3(0, 0, 1));
	uint32_t i;

	if (reserve(m, 4, 6) < 0)
		return -ENOMEM;
	if (flipped)
		n = vec3_scale(n, -1.0);
	i = (uint32_t)m->nvertices;
	vertex(m, base, n);
	vertex(m, r, n);
	vertex(m, tip, n);
	vertex(m, l, n);
	/* a flipped leaf shows its back: wound the other way, normal away from the viewer */
	if (flipped) {
		triangle(m, i, i + 2, i + 1);
		triangle(m, i, i + 3, i + 2);
	} else {
		triangle(m, i, i + 1, i + 2);
		triangle(m, i, i + 2, i + 3);
	}
	return 0;
}

struct branch_spec {
	struct vec3 a, b;
	double ra, rb;
};

static const struct branch_spec branches[] = {
	{ { 0.0, -0.1, 0.0 }, { 0.0, 2.6, 0.0 }, 0.34, 0.26 },
	{ { 0.0, 2.5, 0.0 }, { -0.15, 4.6, 0.0 }, 0.26, 0.16 },
	{ { -0.15, 4.5, 0.0 }, { 0.1, 6.4, 0.0 }, 0.16, 0.07 },
	{ { 0.0, 2.4, 0.0 }, { -2.0, 4.1, 0.4 }, 0.15, 0.06 },
	{ { -0.05, 3.4, 0.0 }, { 1.9, 5.0, -0.3 }, 0.13, 0.05 },
	{ { -0.1, 4.2, 0.0 }, { -1.4, 5.6, 0.2 }, 0.09, 0.04 },
	{ { -1.1, 3.3, 0.2 }, { -1.9, 3.0, 0.2 }, 0.05, 0.03 },
};

static int build_tree(struct tree_mesh *tm)
{
	int r;

	for (size_t i = 0; i < sizeof(branches) / sizeof(branches[0]); i++) {
		const struct branch_spec *b = &branches[i];

		r = scene_add_tube(&tm->bark, b->a, b->b, b->ra, b->rb);
		if (r < 0)
			return r;
	}
	/* leaves along the branch tips, fanned, some showing their backs */
	for (size_t i = 1; i < sizeof(branches) / sizeof(branches[0]); i++) {
		const struct branch_spec *b = &branches[i];

		for (int k = 0; k < 6; k++) {
			double t = 0.55 + 0.09 * k;
			struct vec3 at = vec3_lerp(b->a, b->b, t);
			double angle = (k % 2 ? 0.35 : 2.6) + 0.25 * (double)i + 0.1 * k;

			r = add_leaf(&tm->leaves, at, angle, 0.55 + 0.05 * (k % 3), 0.3 * (k % 3) - 0.3,
				     (k + (int)i) % 3 == 0);
			if (r < 0)
				return r;
		}
	}
	return 0;
}

static int add_point(struct app_stroke *s, double x, double y, double pressure)
{
	if (s->npoints == s->cap) {
		size_t cap = s->cap ? 2 * s->cap : 64;
		struct app_point *p = realloc(s->points, cap * sizeof(*p));

		if (!p)
			return -ENOMEM;
		s->points = p;
		s->cap = cap;
	}
	s->points[s->npoints++] = (struct app_point){ x, y, pressure, 8000 * s->npoints };
	return 0;
}

/* A swoop drawn with a pressure that rises and falls, as children press. */
static int build_stroke(struct app *app, enum event_tool tool, double x0, double y0, double x1,
			double y1, double bend)
{
	struct app_stroke *s = &app->stroke;
	const int n = 40;

	s->tool = tool;
	s->active = true;
	for (int i = 0; i < n; i++) {
		double t = (double)i / (n - 1);
		double x = x0 + (x1 - x0) * t - bend * sin(PI * t) * (y1 - y0);
		double y = y0 + (y1 - y0) * t + bend * sin(PI * t) * (x1 - x0);
		double pressure = 0.1 + 0.9 * sin(PI * t) * (0.7 + 0.3 * cos(9.0 * t));
		int r = add_point(s, x, y, pressure);

		if (r < 0)
			return r;
	}
	app->pen.in_proximity = true;
	app->pen.tool = tool;
	app->pen.x = s->points[n - 1].x;
	app->pen.y = s->points[n - 1].y;
	app->pen.pressure = s->points[n - 1].pressure;
	return 0;
}

/* The strokes of the scenes' histories, for what reads them (the side strip asks whether
 * the tree is a generated one): never applied. */
static struct doc_op scene_ops[5] = {
	{ .kind = DOC_OP_STROKE }, { .kind = DOC_OP_STROKE }, { .kind = DOC_OP_STROKE },
	{ .kind = DOC_OP_STROKE }, { .kind = DOC_OP_STROKE },
};

int scene_build(struct app *app, const char *name)
{
	int r;

	/* all-zero is an empty mesh, stroke and history */
	memset(app, 0, sizeof(*app));
	app->mesh_serial = 1;
	app->doc.ops = scene_ops;

	if (!strcmp(name, "leaf")) {
		/* drawing a new branch in leaf mode; undo possible, nothing to redo */
		view_init(&app->view, 640, 400);
		app->mode = APP_MODE_LEAF;
		app->doc.nops = 3;
		app->doc.cursor = 3;
		r = build_stroke(app, EVENT_TOOL_PEN, 130, 330, 230, 140, 0.25);
	} else if (!strcmp(name, "eraser")) {
		/* rubbing out in clone mode, the clone button held, everything undone */
		view_init(&app->view, 640, 400);
		app->mode = APP_MODE_CLONE;
		app->doc.nops = 2;
		app->doc.cursor = 0;
		app->buttons_down[BUTTON_CLONE] = true;
		app->buttons_down[BUTTON_EXPORT] = true;
		r = build_stroke(app, EVENT_TOOL_ERASER, 250, 200, 420, 260, -0.2);
	} else if (status_scene(name) >= 0) {
		/* the kiosk's size, the pen away, a message over the drawing */
		int i = status_scene(name);

		view_init(&app->view, 1280, 800);
		app->mode = !strcmp(name, "save-failed-ja") ? APP_MODE_PROPAGATE : APP_MODE_SKETCH;
		app->doc.nops = 5;
		app->doc.cursor = 5;
		app->last_time_us = STATUS_AT_US;
		if (status_scenes[i].held)
			app_hold_status(app, status_scenes[i].status, STATUS_AT_US);
		else
			app_set_status(app, status_scenes[i].status, STATUS_AT_US);
		r = 0;
	} else if (!strcmp(name, "kiosk")) {
		/* the kiosk's own size, sketch mode, the pen hovering near the tree */
		view_init(&app->view, 1280, 800);
		app->mode = APP_MODE_SKETCH;
		app->doc.nops = 5;
		app->doc.cursor = 4;
		app->pen.in_proximity = true;
		app->pen.x = 760;
		app->pen.y = 420;
		r = 0;
	} else {
		return -EINVAL;
	}
	if (r == 0)
		r = build_tree(&app->mesh);
	if (r < 0)
		scene_finish(app);
	return r;
}

uint64_t scene_time_us(const char *name)
{
	int i = status_scene(name);

	if (i >= 0)
		return STATUS_AT_US + (status_scenes[i].held ? 10000000u : 1000000u);
	return UINT64_MAX;
}

bool scene_japanese(const char *name)
{
	size_t n = strlen(name);

	return n > 3 && !strcmp(name + n - 3, "-ja");
}

void scene_finish(struct app *app)
{
	free(app->mesh.bark.positions);
	free(app->mesh.bark.normals);
	free(app->mesh.bark.indices);
	free(app->mesh.leaves.positions);
	free(app->mesh.leaves.normals);
	free(app->mesh.leaves.indices);
	free(app->stroke.points);
	memset(app, 0, sizeof(*app));
}
