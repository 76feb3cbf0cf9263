/* SPDX-License-Identifier: MIT */
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "arrange.h"
#include "propagate.h"
#include "test.h"

#define TUBE_SIDES 10
#define PI 3.14159265358979323846

const char *const scene_names[] = { "leaf", "eraser", "kiosk", "saved", "save-failed-ja",
				    "saving", "saved-usb-ja", "stick-pulled", "no-stick-ja",
				    "vine-7inch-ja", NULL };

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
		screen_init(&app->screen, 640, 400);
		app->mode = APP_MODE_LEAF;
		app->doc.nops = 3;
		app->doc.cursor = 3;
		r = build_stroke(app, EVENT_TOOL_PEN, 130, 330, 230, 140, 0.25);
	} else if (!strcmp(name, "eraser")) {
		/* rubbing out in clone mode, the clone button held, everything undone */
		screen_init(&app->screen, 640, 400);
		app->mode = APP_MODE_CLONE;
		app->doc.nops = 2;
		app->doc.cursor = 0;
		app->buttons_down[BUTTON_CLONE] = true;
		app->buttons_down[BUTTON_EXPORT] = true;
		r = build_stroke(app, EVENT_TOOL_ERASER, 250, 200, 420, 260, -0.2);
	} else if (status_scene(name) >= 0) {
		/* the kiosk's size, the pen away, a message over the drawing */
		int i = status_scene(name);

		screen_init(&app->screen, 1280, 800);
		app->mode = !strcmp(name, "save-failed-ja") ? APP_MODE_PROPAGATE : APP_MODE_SKETCH;
		app->doc.nops = 5;
		app->doc.cursor = 5;
		app->last_time_us = STATUS_AT_US;
		if (status_scenes[i].held)
			app_hold_status(app, status_scenes[i].status, STATUS_AT_US);
		else
			app_set_status(app, status_scenes[i].status, STATUS_AT_US);
		r = 0;
	} else if (!strcmp(name, "vine-7inch-ja")) {
		/* a 7-inch kiosk's 800x480 in the vine mode: its button lit beside season */
		screen_init(&app->screen, 800, 480);
		app->mode = APP_MODE_VINE;
		app->doc.nops = 5;
		app->doc.cursor = 5;
		r = 0;
	} else if (!strcmp(name, "kiosk")) {
		/* the kiosk's own size, sketch mode, the pen hovering near the tree */
		screen_init(&app->screen, 1280, 800);
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

/* A branch from root (or from the point at pt on parent) along dir, curving to bend. */
static int add_bent(struct tree *t, int parent, double pt, struct vec3 root, struct vec3 dir,
		    struct vec3 bend, double len, double r0)
{
	struct vec3 p[8];
	double r[8], l0;
	int id;

	if (parent >= 0)
		root = tree_frame_at(&t->branches[parent], pt).origin;
	for (int k = 0; k < 8; k++) {
		double s = k / 7.0;

		p[k] = vec3_add(vec3_scale(dir, s), vec3_scale(bend, s * s));
		r[k] = r0 * (1.0 - 0.7 * s);
	}
	l0 = vec3_polyline_length(p, 8);
	for (int k = 0; k < 8; k++)
		p[k] = vec3_add(root, vec3_scale(p[k], len / l0));
	id = tree_add_branch(t, parent, parent >= 0 ? pt : 0.0, ORIGIN_SKETCH, p, r, 8);
	CHECK(id >= 0);
	return id;
}

/* A lobed leaf of n points beside branch b at u, tilted out of the picture plane. */
static void add_tree_leaf(struct tree *t, int b, double u, double size, int n, double lobe)
{
	struct tree_frame f = tree_frame_at(&t->branches[b], u);
	struct vec3 p[16];
	int id;

	for (int i = 0; i < n; i++) {
		double a = 2.0 * VEC_PI * i / n, l = i % 2 ? lobe : 1.0;
		struct vec3 across = vec3_scale(f.normal, size * l * (1.0 + cos(a)));
		struct vec3 along = vec3_scale(f.tangent, 0.5 * size * l * sin(a));
		struct vec3 out = vec3_scale(f.binormal, 0.4 * size * (1.0 + cos(a)));

		p[i] = vec3_add(f.origin, vec3_add(across, vec3_add(along, out)));
	}
	id = tree_add_leaf(t, b, ORIGIN_SKETCH, p, (size_t)n);
	CHECK(id >= 0);
	t->leaves[id].branch_t = u;
	CHECK_INT(tree_leaf_attach(t, (size_t)id), 0);
}

/* scene.h says what it holds. */
void scene_leafy(struct app *app, int width, int height, struct camera cam, bool copies)
{
	struct tree *t = &app->tree;
	int trunk, s;

	memset(app, 0, sizeof(*app));
	screen_init(&app->screen, width, height);
	tree_init(t);
	tree_mesh_init(&app->mesh);
	tree_mesh_marks_init(&app->mesh_marks);
	trunk = add_bent(t, -1, 0, vec3(0, 0, 0), vec3(0, 1, 0), vec3(0.4, 0, 0.3), 6.0, 0.3);
	for (int k = 0; k < 23; k++) {
		double a = 2.4 * k, up = 0.3 + 0.03 * k;
		int parent = k < 8 ? trunk : 1 + (k % 8);

		struct vec3 dir = vec3(cos(a), up + (k < 8 ? 0.2 : 0.6), sin(a));

		add_bent(t, parent, 0.35 + 0.025 * k, vec3(0, 0, 0), dir,
			 vec3(0, 0.3, 0.1 * (k % 3)), k < 8 ? 2.2 - 0.1 * k : 0.9,
			 k < 8 ? 0.08 : 0.03);
	}
	s = 3;
	add_tree_leaf(t, s, 0.8, 0.22, 9, 0.6);
	if (copies)
		CHECK_INT(arrange_apply(t, s, ARRANGE_WHORL_ADD), 1);
	add_tree_leaf(t, s, 0.5, 0.18, 7, 0.8);
	if (copies)
		CHECK(propagate_apply(t, s, PROPAGATE_FIXED_COUNT) > 40);
	add_tree_leaf(t, 0, 0.55, 0.3, 8, 0.5);
	t->lifted = true;
	app->camera = cam;
	CHECK_INT(tree_mesh_build_marked(&app->mesh, t, &app->mesh_marks), 0);
	app->mesh_serial = 1;
}

void scene_leafy_finish(struct app *app)
{
	tree_mesh_marks_finish(&app->mesh_marks);
	tree_mesh_finish(&app->mesh);
	tree_finish(&app->tree);
	memset(app, 0, sizeof(*app));
}
