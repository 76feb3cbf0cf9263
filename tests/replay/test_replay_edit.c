/* SPDX-License-Identifier: MIT */
/*
 * Example-based editing replays (tests/data/edit-*.edaha-trace, made by
 * gen-edit-traces.py): the clone, leaf and propagate modes used with the pen through the
 * app, asserting on skeleton.json as the exporter writes it (docs/editing.md):
 *
 * - clone: ten taps on a selected parent add ten children (origin clone), each between
 *   the pair of neighbouring children that were farthest apart, its rotation about the
 *   parent at most 120 degrees from up; ten counter-clockwise circles remove them again,
 *   byte for byte; clockwise circles add like taps;
 * - leaf arrangement (taps on the thumbnails): a whorl of n leaves is spaced 360/n
 *   degrees within 1 degree; whorl-extend and spiral-extend reach the tip at the drawn
 *   spacing (1%) and turn (1 degree);
 * - propagate: fixed count gives every target the source's count at the same places;
 *   fixed size copies onto each target exactly the source's children that fit, counted
 *   from the tip, at the same distance from the tip;
 * - the drawing saved after each replay loads back to the same skeleton.
 */
#include <json-c/json.h>
#include <string.h>

#include "app.h"
#include "replay_util.h"
#include "test.h"

#define W 1280
#define H 800

static const char *dir;

/* The drawing the app would save loads back to the same skeleton. */
static void check_reload(const struct app *app)
{
	struct app *again = app_create(W, H, 1);
	struct buf b;
	struct doc d;
	struct error err = { { 0 } };
	char *s1, *s2;

	CHECK(again);
	buf_init(&b);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &b), 0);
	CHECK_INT(doc_parse((const char *)b.data, b.len, "reload", &d, &err), 0);
	CHECK_INT(app_load_doc(again, &d), 0);
	s1 = replay_skeleton_text(&app->tree);
	s2 = replay_skeleton_text(&again->tree);
	CHECK(strcmp(s1, s2) == 0);
	free(s1);
	free(s2);
	buf_finish(&b);
	doc_finish(&d);
	app_destroy(again);
}

/* ---- skeleton.json, parsed ---- */

struct sbranch {
	int parent;
	double parent_t;
	char origin[16];
	size_t n;
	struct vec3 *p;
};

struct sleaf {
	int branch;
	double branch_t;
	char origin[16];
	size_t n;
	struct vec3 *p;
};

struct skel {
	size_t nb, nl;
	struct sbranch *b;
	struct sleaf *l;
};

static struct vec3 *points(json_object *pts, size_t *n)
{
	struct vec3 *p;

	*n = json_object_array_length(pts);
	p = calloc(*n + 1, sizeof(*p));
	CHECK(p);
	for (size_t k = 0; k < *n; k++) {
		json_object *q = json_object_array_get_idx(pts, k);

		p[k] = vec3(json_object_get_double(json_object_array_get_idx(q, 0)),
			    json_object_get_double(json_object_array_get_idx(q, 1)),
			    json_object_get_double(json_object_array_get_idx(q, 2)));
	}
	return p;
}

static struct skel parse(const struct tree *t)
{
	char *text = replay_skeleton_text(t);
	json_object *j = json_tokener_parse(text), *br, *lv;
	struct skel s;

	CHECK(j);
	free(text);
	br = replay_get(j, "branches");
	lv = replay_get(j, "leaves");
	s.nb = json_object_array_length(br);
	s.nl = json_object_array_length(lv);
	s.b = calloc(s.nb + 1, sizeof(*s.b));
	s.l = calloc(s.nl + 1, sizeof(*s.l));
	CHECK(s.b && s.l);
	for (size_t i = 0; i < s.nb; i++) {
		json_object *o = json_object_array_get_idx(br, i);

		s.b[i].parent = json_object_get_int(replay_get(o, "parent"));
		s.b[i].parent_t = json_object_get_double(replay_get(o, "parent_t"));
		snprintf(s.b[i].origin, sizeof(s.b[i].origin), "%s", json_object_get_string(replay_get(o, "origin")));
		s.b[i].p = points(replay_get(o, "points"), &s.b[i].n);
	}
	for (size_t i = 0; i < s.nl; i++) {
		json_object *o = json_object_array_get_idx(lv, i);

		s.l[i].branch = json_object_get_int(replay_get(o, "branch"));
		s.l[i].branch_t = json_object_get_double(replay_get(o, "branch_t"));
		snprintf(s.l[i].origin, sizeof(s.l[i].origin), "%s", json_object_get_string(replay_get(o, "origin")));
		s.l[i].p = points(replay_get(o, "points"), &s.l[i].n);
	}
	json_object_put(j);
	return s;
}

static void skel_free(struct skel *s)
{
	for (size_t i = 0; i < s->nb; i++)
		free(s->b[i].p);
	for (size_t i = 0; i < s->nl; i++)
		free(s->l[i].p);
	free(s->b);
	free(s->l);
}

static double length(const struct sbranch *b)
{
	return vec3_polyline_length(b->p, b->n);
}

/* Point and unit tangent at arc-length parameter u. */
static struct vec3 point_at(const struct sbranch *b, double u, struct vec3 *tangent)
{
	double want = u * length(b), walked = 0.0;

	for (size_t i = 0; i + 1 < b->n; i++) {
		double seg = vec3_dist(b->p[i], b->p[i + 1]);

		if (walked + seg >= want || i + 2 == b->n) {
			double f = seg > 0 ? fmin(1.0, (want - walked) / seg) : 0.0;

			*tangent = vec3_norm_or(vec3_sub(b->p[i + 1], b->p[i]), vec3(0, 1, 0));
			return vec3_lerp(b->p[i], b->p[i + 1], f);
		}
		walked += seg;
	}
	*tangent = vec3(0, 1, 0);
	return b->p[0];
}

/* ---- clone ---- */

/* Children of `parent` among branches [0, upto), in order along it. */
static size_t children(const struct skel *s, int parent, size_t upto, double *t)
{
	size_t n = 0;

	for (size_t i = 0; i < upto; i++)
		if (s->b[i].parent == parent)
			t[n++] = s->b[i].parent_t;
	for (size_t i = 1; i < n; i++)
		for (size_t k = i; k > 0 && t[k - 1] > t[k]; k--) {
			double x = t[k];

			t[k] = t[k - 1];
			t[k - 1] = x;
		}
	return n;
}

/* Every clone of `parent` (in the order they were added) sits inside a widest gap
 * between neighbouring children as they were, and turns at most 120 degrees from up. */
static void check_clones(const struct skel *s, int parent, size_t first_clone, size_t nclones)
{
	const struct sbranch *p = &s->b[parent];
	double *t = calloc(s->nb + 1, sizeof(*t));
	size_t found = 0;

	CHECK(t);
	for (size_t i = first_clone; i < s->nb; i++) {
		const struct sbranch *c = &s->b[i];
		struct vec3 head, root, dir, up, side;
		double widest = 0.0, rot;
		size_t n;
		bool inside = false;

		if (strcmp(c->origin, "clone") != 0)
			continue;
		CHECK_INT(c->parent, parent);
		found++;
		n = children(s, parent, i, t);
		CHECK(n >= 2);
		for (size_t k = 0; k + 1 < n; k++)
			widest = fmax(widest, t[k + 1] - t[k]);
		/* equal gaps tie to within the parameters' 6-decimal rounding */
		for (size_t k = 0; k + 1 < n; k++)
			if (t[k + 1] - t[k] >= widest - 3e-6 && c->parent_t > t[k] && c->parent_t < t[k + 1])
				inside = true;
		CHECK(inside);
		/* the turtle at the root: rotation about head from the up vector */
		root = point_at(p, c->parent_t, &head);
		CHECK_NEAR(vec3_dist(root, c->p[0]), 0, 1e-5); /* micrometre rounding */
		up = vec3_sub(vec3(0, 1, 0), vec3_scale(head, head.y));
		if (vec3_len(up) < 0.05)
			continue; /* a vertical parent has no up to turn from */
		up = vec3_norm_or(up, up);
		dir = vec3_sub(c->p[c->n - 1], c->p[0]);
		side = vec3_sub(dir, vec3_scale(head, vec3_dot(dir, head)));
		rot = acos(fmax(-1, fmin(1, vec3_dot(vec3_norm_or(side, up), up)))) * 180.0 / VEC_PI;
		CHECK(rot <= 120.0 + 1e-3);
	}
	CHECK_INT(found, nclones);
	free(t);
}

static void test_clone(void)
{
	struct app *base = replay_trace(dir, "edit-clone-select.edaha-trace", W, H, 11);
	struct app *taps = replay_trace(dir, "edit-clone-taps.edaha-trace", W, H, 11);
	struct app *circles = replay_trace(dir, "edit-clone-circles.edaha-trace", W, H, 11);
	struct app *cw = replay_trace(dir, "edit-clone-cw.edaha-trace", W, H, 11);
	struct app *branch = replay_trace(dir, "edit-clone-branch.edaha-trace", W, H, 11);
	struct skel s0 = parse(&base->tree), st = parse(&taps->tree), sc = parse(&cw->tree);
	struct skel sb = parse(&branch->tree);
	char *a = replay_skeleton_text(&base->tree), *b = replay_skeleton_text(&circles->tree);

	CHECK(base->tree.lifted && base->mode == APP_MODE_CLONE && base->selected == 0);
	/* ten taps: ten children on the trunk */
	CHECK_INT(st.nb, s0.nb + 10);
	check_clones(&st, 0, s0.nb, 10);
	/* ten counter-clockwise circles: the tree as it was, byte for byte */
	CHECK(strcmp(a, b) == 0);
	CHECK_INT(circles->doc.cursor, base->doc.cursor + 20);
	/* clockwise circles add */
	CHECK_INT(sc.nb, s0.nb + 3);
	check_clones(&sc, 0, s0.nb, 3);
	/* on a leaning branch with two twigs (the first tap selects it) */
	CHECK_INT(sb.nb, s0.nb + 10);
	check_clones(&sb, 1, s0.nb, 10);
	check_reload(taps);
	check_reload(circles);
	check_reload(branch);
	free(a);
	free(b);
	skel_free(&s0);
	skel_free(&st);
	skel_free(&sc);
	skel_free(&sb);
	app_destroy(base);
	app_destroy(taps);
	app_destroy(circles);
	app_destroy(cw);
	app_destroy(branch);
}

/* ---- leaf arrangement ---- */

/* A leaf's angle about its branch: its centroid in the branch's frame at branch_t (the
 * frame of tree_frame_at: normal across the picture plane), degrees. */
static double leaf_angle(const struct skel *s, const struct sleaf *l)
{
	struct vec3 tangent, o = point_at(&s->b[l->branch], l->branch_t, &tangent), c = vec3(0, 0, 0);
	struct vec3 normal = vec3_norm_or(vec3_cross(vec3(0, 0, 1), tangent), vec3(1, 0, 0));
	struct vec3 binormal = vec3_cross(tangent, normal);

	for (size_t k = 0; k < l->n; k++)
		c = vec3_add(c, l->p[k]);
	c = vec3_sub(vec3_scale(c, 1.0 / (double)l->n), o);
	return atan2(vec3_dot(c, binormal), vec3_dot(c, normal)) * 180.0 / VEC_PI;
}

static double wrap180(double a)
{
	while (a > 180.0)
		a -= 360.0;
	while (a <= -180.0)
		a += 360.0;
	return a;
}

/* The leaves on branch b (not merged copies), sorted by branch_t then angle. */
static size_t leaves_on(const struct skel *s, int b, const struct sleaf **out)
{
	size_t n = 0;

	for (size_t i = 0; i < s->nl; i++)
		if (s->l[i].branch == b && strcmp(s->l[i].origin, "merge") != 0)
			out[n++] = &s->l[i];
	for (size_t i = 1; i < n; i++)
		for (size_t k = i; k > 0 && out[k - 1]->branch_t > out[k]->branch_t; k--) {
			const struct sleaf *x = out[k];

			out[k] = out[k - 1];
			out[k - 1] = x;
		}
	return n;
}

static void test_whorl(void)
{
	struct app *app = replay_trace(dir, "edit-leaf-whorl.edaha-trace", W, H, 11);
	struct skel s = parse(&app->tree);
	const struct sleaf *l[64];
	double a[64];
	size_t n = leaves_on(&s, 3, l);

	CHECK(app->mode == APP_MODE_LEAF);
	CHECK_INT(n, 5); /* the drawn leaf and four taps */
	for (size_t i = 0; i < n; i++) {
		CHECK_NEAR(l[i]->branch_t, l[0]->branch_t, 1e-6);
		a[i] = leaf_angle(&s, l[i]);
	}
	for (size_t i = 1; i < n; i++)
		for (size_t k = i; k > 0 && a[k - 1] > a[k]; k--) {
			double x = a[k];

			a[k] = a[k - 1];
			a[k - 1] = x;
		}
	for (size_t i = 0; i < n; i++)
		CHECK_NEAR(wrap180(a[(i + 1) % n] - a[i] - 360.0 / n), 0, 1.0);
	check_reload(app);
	skel_free(&s);
	app_destroy(app);
}

/* Leaves grouped by place along branch b: each group's position and first leaf. */
static size_t groups(const struct skel *s, int b, double *t, const struct sleaf **first, size_t *size)
{
	const struct sleaf *l[256];
	size_t n = leaves_on(s, b, l), g = 0;

	CHECK(n < 256);
	double sum = 0.0;

	for (size_t i = 0; i < n; i++) {
		/* a group's place is its members' mean (drawn leaves are never quite level) */
		if (g == 0 || l[i]->branch_t - first[g - 1]->branch_t > 0.05) {
			if (g > 0)
				t[g - 1] = sum / (double)size[g - 1];
			first[g] = l[i];
			size[g++] = 0;
			sum = 0.0;
		}
		size[g - 1]++;
		sum += l[i]->branch_t;
	}
	if (g > 0)
		t[g - 1] = sum / (double)size[g - 1];
	return g;
}

static void test_extend(const char *trace, int b, size_t set)
{
	struct app *app = replay_trace(dir, trace, W, H, 11);
	struct skel s = parse(&app->tree);
	const struct sleaf *first[64];
	double t[64], L = length(&s.b[b]), step, turn;
	size_t size[64], g = groups(&s, b, t, first, size);

	CHECK(g >= 4);
	step = t[1] - t[0];
	turn = wrap180(leaf_angle(&s, first[1]) - leaf_angle(&s, first[0]));
	for (size_t i = 0; i < g; i++) {
		CHECK_INT(size[i], set);
		if (i == 0)
			continue;
		/* the drawn spacing (1%) and, leaf for leaf, the drawn turn (1 degree) */
		CHECK_NEAR((t[i] - t[i - 1]) * L, step * L, 0.01 * step * L);
		if (set == 1)
			CHECK_NEAR(wrap180(leaf_angle(&s, first[i]) - leaf_angle(&s, first[i - 1]) - turn), 0, 1.0);
	}
	/* up to the tip: no room for one more */
	CHECK(t[g - 1] <= 1.0 + 1e-6 && (1.0 - t[g - 1]) < step + 1e-6);
	check_reload(app);
	skel_free(&s);
	app_destroy(app);
}

static void test_suggestions(void)
{
	struct app *app = replay_trace(dir, "edit-leaf-suggest.edaha-trace", W, H, 11);
	enum arrange_pattern p[ARRANGE_COUNT];

	/* leaf mode shows what the pair and the leaf above suggest */
	CHECK(app->mode == APP_MODE_LEAF && app->suggest_branch == 2);
	CHECK_INT(app_suggestions(app, p), 2);
	CHECK(p[0] == ARRANGE_WHORL_ADD && p[1] == ARRANGE_WHORL_EXTEND);
	CHECK(app->previews[ARRANGE_WHORL_EXTEND].leaves.nvertices >
	      app->previews[ARRANGE_WHORL_ADD].leaves.nvertices);
	app_destroy(app);
}

/* ---- propagate ---- */

static void test_propagate(const char *trace, bool fixed_size)
{
	struct app *app = replay_trace(dir, trace, W, H, 11);
	struct skel s = parse(&app->tree);
	int src = -1, ntargets = 0;
	double Ls;
	size_t nsrc = 0;

	CHECK(app->mode == APP_MODE_PROPAGATE);
	/* the source: the branch with the drawn leaves */
	for (size_t i = 0; i < s.nl; i++)
		if (strcmp(s.l[i].origin, "sketch") == 0) {
			CHECK(src < 0 || src == s.l[i].branch);
			src = s.l[i].branch;
			nsrc++;
		}
	CHECK(src > 0 && nsrc == 4);
	Ls = length(&s.b[src]);
	for (size_t b = 1; b < s.nb; b++) {
		double Lt = length(&s.b[b]);
		size_t got = 0, want = 0;

		if ((int)b == src)
			continue;
		ntargets++;
		for (size_t i = 0; i < s.nl; i++)
			if (s.l[i].branch == (int)b && strcmp(s.l[i].origin, "propagate") == 0)
				got++;
		for (size_t i = 0; i < s.nl; i++) {
			const struct sleaf *l = &s.l[i];
			double d = (1.0 - l->branch_t) * Ls;
			bool placed = false;

			if (l->branch != src || strcmp(l->origin, "sketch") != 0)
				continue;
			if (fixed_size && d > Lt + 1e-6)
				continue; /* does not fit: only the tip-most ones are copied */
			want++;
			/* a copy at the same place: the same parameter, or the same distance
			 * from the tip */
			for (size_t k = 0; k < s.nl; k++) {
				const struct sleaf *c = &s.l[k];

				if (c->branch != (int)b || strcmp(c->origin, "propagate") != 0)
					continue;
				if (fixed_size ? fabs((1.0 - c->branch_t) * Lt - d) < 2e-5 :
						 fabs(c->branch_t - l->branch_t) < 2e-6)
					placed = true;
			}
			CHECK(placed);
		}
		CHECK_INT(got, want);
		if (!fixed_size)
			CHECK_INT(got, nsrc);
	}
	CHECK(ntargets >= 8); /* the first tree's branches and twigs, and the merged ones */
	check_reload(app);
	skel_free(&s);
	app_destroy(app);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	dir = argv[1];
	test_clone();
	test_suggestions();
	test_whorl();
	test_extend("edit-leaf-extend.edaha-trace", 2, 2);
	test_extend("edit-leaf-spiral.edaha-trace", 1, 1);
	test_propagate("edit-propagate-size.edaha-trace", true);
	test_propagate("edit-propagate-count.edaha-trace", false);
	return 0;
}
