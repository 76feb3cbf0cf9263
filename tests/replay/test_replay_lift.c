/* SPDX-License-Identifier: MIT */
/*
 * Lifting replays (tests/data/lift-*.edaha-trace, made by gen-lift-traces.py): each sketch
 * is replayed through the app, then the 3D button is pressed, and the assertions are on
 * skeleton.json as the exporter writes it (docs/lifting.md, "Tests and measurements"):
 *
 * - the first tree (origin != "merge") seen from the front is the sketch: every lifted
 *   branch's (x, y) polyline is within 1% of the sketch's height of the same branch in the
 *   skeleton of the same trace replayed without pressing 3D;
 * - 4.1's constraints hold for every branch of the first tree: its end inside the
 *   sqrt(2)-scaled hull, at most 1.2 x its parent's length and 1.2 x the largest drawn
 *   parent-child angle, 45..135 degrees from the view direction; and for the merged
 *   copies, turned with them: their ends inside the hull where their depth allows it, as
 *   near as it allows elsewhere;
 * - a left-right symmetric sketch grows about as deep as it is wide;
 * - the branch ends are sparser than with random admissible depths (LIFT_PICK_RANDOM),
 *   on the first tree and on the whole merged tree;
 * - a sine-wave stroke becomes a helix;
 * - the same seed gives identical files, another seed another tree.
 */
#include <json-c/json.h>
#include <string.h>

#include "app.h"
#include "replay_util.h"
#include "export.h"
#include "lift.h"
#include "test.h"
#include "trace.h"

#define W 1280
#define H 800
#define SEEDS 20

static const char *dir;

/* The trace's events through the app, with the drawing's seed; then 3D if asked. */
static struct app *replay(const char *name, uint64_t seed, bool lift)
{
	struct app *app = replay_trace(dir, name, W, H, seed);

	if (lift) {
		CHECK(!app->tree.lifted);
		replay_press(app, BUTTON_3D);
		CHECK(app->tree.lifted);
	}
	CHECK_INT(app->failed, 0);
	return app;
}

static void skeleton_bytes(const struct tree *t, struct buf *b)
{
	buf_init(b);
	CHECK_INT(export_skeleton(t, b), 0);
	CHECK_INT(buf_append(b, "", 1), 0);
}

/* skeleton.json, parsed into plain arrays */
struct sbranch {
	int parent;
	bool merged;
	size_t n;
	struct vec3 *p;
};

struct skel {
	size_t n;
	struct sbranch *b;
};

static struct skel parse(const struct tree *t)
{
	struct buf b;
	json_object *j, *br;
	struct skel s;

	skeleton_bytes(t, &b);
	j = json_tokener_parse((const char *)b.data);
	CHECK(j);
	buf_finish(&b);
	br = replay_get(j, "branches");
	s.n = json_object_array_length(br);
	s.b = calloc(s.n + 1, sizeof(*s.b));
	CHECK(s.b);
	for (size_t i = 0; i < s.n; i++) {
		json_object *o = json_object_array_get_idx(br, i), *pts = replay_get(o, "points");

		CHECK_INT(json_object_get_int(replay_get(o, "id")), i);
		s.b[i].parent = json_object_get_int(replay_get(o, "parent"));
		s.b[i].merged = strcmp(json_object_get_string(replay_get(o, "origin")), "merge") == 0;
		s.b[i].n = json_object_array_length(pts);
		s.b[i].p = calloc(s.b[i].n + 1, sizeof(*s.b[i].p));
		CHECK(s.b[i].p && s.b[i].n >= 2);
		for (size_t k = 0; k < s.b[i].n; k++) {
			json_object *p = json_object_array_get_idx(pts, k);

			s.b[i].p[k] = vec3(json_object_get_double(json_object_array_get_idx(p, 0)),
					   json_object_get_double(json_object_array_get_idx(p, 1)),
					   json_object_get_double(json_object_array_get_idx(p, 2)));
		}
	}
	json_object_put(j);
	return s;
}

static void skel_free(struct skel *s)
{
	for (size_t i = 0; i < s->n; i++)
		free(s->b[i].p);
	free(s->b);
}

static struct vec3 start_of(const struct sbranch *b) { return b->p[0]; }
static struct vec3 end_of(const struct sbranch *b) { return b->p[b->n - 1]; }
static struct vec3 chord(const struct sbranch *b) { return vec3_sub(end_of(b), start_of(b)); }

static double angle(struct vec3 a, struct vec3 b)
{
	return acos(fmin(1, fmax(-1, vec3_dot(a, b) / (vec3_len(a) * vec3_len(b)))));
}

/* Distance in (x, y) from p to the polyline q. */
static double dist_xy_to_polyline(struct vec3 p, const struct sbranch *q)
{
	double best = INFINITY;

	for (size_t i = 0; i + 1 < q->n; i++) {
		double ax = q->p[i].x, ay = q->p[i].y, dx = q->p[i + 1].x - ax, dy = q->p[i + 1].y - ay;
		double dd = dx * dx + dy * dy;
		double s = dd > 0 ? ((p.x - ax) * dx + (p.y - ay) * dy) / dd : 0.0;

		s = fmin(fmax(s, 0), 1);
		best = fmin(best, hypot(ax + s * dx - p.x, ay + s * dy - p.y));
	}
	return best;
}

static void extent(const struct skel *s, bool first_only, struct vec3 *lo, struct vec3 *hi)
{
	*lo = vec3(INFINITY, INFINITY, INFINITY);
	*hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	for (size_t i = 0; i < s->n; i++) {
		if (first_only && s->b[i].merged)
			continue;
		for (size_t k = 0; k < s->b[i].n; k++) {
			struct vec3 p = s->b[i].p[k];

			*lo = vec3(fmin(lo->x, p.x), fmin(lo->y, p.y), fmin(lo->z, p.z));
			*hi = vec3(fmax(hi->x, p.x), fmax(hi->y, p.y), fmax(hi->z, p.z));
		}
	}
}

/* ---- the 2D sketch's convex hull, made 3D as the paper says (independent of lift.c) -- */

struct hull {
	double x[4096], y[4096];
	size_t n;
	double ymin, ymax;
};

static int cmp_pt(const void *a, const void *b)
{
	const double *p = a, *q = b;

	if (p[0] != q[0])
		return p[0] < q[0] ? -1 : 1;
	return (p[1] > q[1]) - (p[1] < q[1]);
}

static double turn(const double *o, const double *a, const double *b)
{
	return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static void hull_of(const struct skel *s2, struct hull *h)
{
	size_t n = 0, k = 0;
	double (*p)[2], (*out)[2];

	for (size_t i = 0; i < s2->n; i++)
		n += s2->b[i].n;
	p = calloc(n, sizeof(*p));
	out = calloc(2 * n + 1, sizeof(*out));
	CHECK(p && out);
	n = 0;
	for (size_t i = 0; i < s2->n; i++)
		for (size_t j = 0; j < s2->b[i].n; j++) {
			p[n][0] = s2->b[i].p[j].x;
			p[n][1] = s2->b[i].p[j].y;
			n++;
		}
	qsort(p, n, sizeof(*p), cmp_pt);
	for (size_t i = 0; i < n; i++) { /* Andrew's monotone chain */
		while (k >= 2 && turn(out[k - 2], out[k - 1], p[i]) <= 0)
			k--;
		memcpy(out[k++], p[i], sizeof(*p));
	}
	for (size_t i = n - 1, lo = k + 1; i-- > 0;) {
		while (k >= lo && turn(out[k - 2], out[k - 1], p[i]) <= 0)
			k--;
		memcpy(out[k++], p[i], sizeof(*p));
	}
	h->n = k - 1;
	CHECK(h->n >= 2 && h->n < 4096);
	h->ymin = INFINITY;
	h->ymax = -INFINITY;
	for (size_t i = 0; i < h->n; i++) {
		h->x[i] = out[i][0];
		h->y[i] = out[i][1];
		h->ymin = fmin(h->ymin, h->y[i]);
		h->ymax = fmax(h->ymax, h->y[i]);
	}
	free(p);
	free(out);
}

/* The 3D hull at height y (clamped to the hull's): a disc across the hull's width there,
 * centred at (xc, 0), its radius r scaled by sqrt(2). */
static void hull_disc(const struct hull *h, double y, double *xc, double *r)
{
	double lo = INFINITY, hi = -INFINITY;

	y = fmin(fmax(y, h->ymin), h->ymax);

	for (size_t i = 0; i < h->n; i++) {
		double ax = h->x[i], ay = h->y[i], bx = h->x[(i + 1) % h->n], by = h->y[(i + 1) % h->n];

		if ((ay <= y && by >= y) || (by <= y && ay >= y)) {
			double x = ay == by ? ax : ax + (bx - ax) * (y - ay) / (by - ay);

			lo = fmin(lo, fmin(x, ay == by ? bx : x));
			hi = fmax(hi, fmax(x, ay == by ? bx : x));
		}
	}
	CHECK(lo <= hi);
	*xc = 0.5 * (lo + hi);
	*r = LIFT_HULL_SCALE * 0.5 * (hi - lo);
}

/* How far outside the 3D hull (x, y, z) is, in metres (<= 0: inside). */
static double outside_hull(const struct hull *h, struct vec3 p)
{
	double xc, r;

	hull_disc(h, p.y, &xc, &r);
	return hypot(p.x - xc, p.z) - r;
}

/* The least that outside_hull() can be for a point at p's height and depth, whatever its
 * x: a merged copy's depth is its drawn x turned, which no lifting can change. */
static double outside_hull_at_depth(const struct hull *h, struct vec3 p)
{
	double xc, r;

	hull_disc(h, p.y, &xc, &r);
	return fmax(0, fabs(p.z) - r);
}

/* ---- the checks ---- */

/* Same branches, same order; the first tree seen from the front is the sketch. */
static void check_front_view(const struct skel *s2, const struct skel *s3)
{
	struct vec3 lo, hi;
	double height, worst = 0;

	extent(s2, false, &lo, &hi);
	height = hi.y - lo.y;
	CHECK(s3->n >= s2->n);
	for (size_t i = 0; i < s3->n; i++) {
		CHECK_INT(s3->b[i].merged, i >= s2->n); /* the merged copies come after */
		if (s3->b[i].merged)
			continue;
		CHECK_INT(s3->b[i].parent, s2->b[i].parent);
		/* both ways (Hausdorff), so the lifted branch covers the whole stroke */
		for (size_t k = 0; k < s3->b[i].n; k++)
			worst = fmax(worst, dist_xy_to_polyline(s3->b[i].p[k], &s2->b[i]));
		for (size_t k = 0; k < s2->b[i].n; k++)
			worst = fmax(worst, dist_xy_to_polyline(s2->b[i].p[k], &s3->b[i]));
		/* drawn in the plane */
		for (size_t k = 0; k < s2->b[i].n; k++)
			CHECK(s2->b[i].p[k].z == 0);
	}
	fprintf(stderr, "  front view: within %.2g m of the sketch (1%% of its height: %.3g m)\n",
		worst, 0.01 * height);
	CHECK(worst <= 0.01 * height);
}

/* The largest drawn angle between branch `parent` and its children, in the sketch. */
static double drawn_max_child_angle(const struct skel *s2, int parent)
{
	double a = 0;

	for (size_t j = 0; j < s2->n; j++)
		if (s2->b[j].parent == parent)
			a = fmax(a, angle(chord(&s2->b[parent]), chord(&s2->b[j])));
	return a;
}

/* 4.1 for every branch, as segments from start to end. The exported numbers are rounded
 * to the micrometre: EPS. */
#define EPS 1e-5

/* The largest ratios of a tree's branches to 4.1's limits (<= 1), and how far their ends
 * are outside the hull. */
struct ratios {
	double hull, len, ang, view;
	int out, n;
};

/* The root of b is on its parent's polyline p. */
static void check_root(const struct sbranch *b, const struct sbranch *p)
{
	double best = INFINITY;

	for (size_t k = 0; k + 1 < p->n; k++) {
		struct vec3 a = p->p[k], e = vec3_sub(p->p[k + 1], a);
		double t = vec3_dot(vec3_sub(start_of(b), a), e) / fmax(vec3_dot(e, e), 1e-300);

		t = fmin(fmax(t, 0), 1);
		best = fmin(best, vec3_dist(start_of(b), vec3_add(a, vec3_scale(e, t))));
	}
	CHECK(best <= EPS);
}

/*
 * The first tree: every end inside the hull, and the rules with the view direction
 * (0, 0, -1). The merged copies (the second tree turned 90 degrees about the vertical):
 * the same length and angle rules, the view rule turned with them (45..135 degrees from
 * the x axis), and every end inside the hull, or, where no point at its depth is (its
 * depth is its drawn distance from the trunk, turned), as near as that depth allows.
 */
static void check_constraints(const struct skel *s2, const struct skel *s3)
{
	struct hull *h = malloc(sizeof(*h));
	struct ratios r[2] = { { -INFINITY, 0, 0, 0, 0, 0 }, { -INFINITY, 0, 0, 0, 0, 0 } };
	int *src = calloc(s3->n + 1, sizeof(*src));
	size_t next = 0;

	CHECK(h && src);
	hull_of(s2, h);
	/* the trunk stays in the sketch plane at both ends */
	CHECK_NEAR(start_of(&s3->b[0]).z, 0, EPS);
	CHECK_NEAR(end_of(&s3->b[0]).z, 0, EPS);
	for (size_t i = 0; i < s3->n; i++) {
		const struct sbranch *b = &s3->b[i], *p;
		struct ratios *q = &r[b->merged];
		struct vec3 d = chord(b);
		double amax, o = outside_hull(h, end_of(b));

		/* which drawn branch it is: the copies are the sketch's branches but its trunk,
		 * in order */
		if (!b->merged) {
			src[i] = (int)i;
		} else {
			while (next < s2->n && s2->b[next].parent < 0)
				next++;
			CHECK(next < s2->n);
			src[i] = (int)next++;
		}
		q->hull = fmax(q->hull, o);
		q->out += o > EPS;
		q->n++;
		CHECK(o <= (b->merged ? outside_hull_at_depth(h, end_of(b)) : 0) + EPS);
		if (b->parent < 0)
			continue;
		p = &s3->b[b->parent];
		CHECK_INT(src[b->parent], s2->b[src[i]].parent);
		amax = LIFT_MAX_ANGLE_RATIO * drawn_max_child_angle(s2, s2->b[src[i]].parent);
		/* ratios to the limits: <= 1 */
		q->len = fmax(q->len, vec3_len(d) / (LIFT_MAX_LENGTH_RATIO * vec3_len(chord(p))));
		q->ang = fmax(q->ang, angle(chord(p), d) / amax);
		CHECK(vec3_len(d) <= LIFT_MAX_LENGTH_RATIO * vec3_len(chord(p)) + EPS);
		CHECK(angle(chord(p), d) <= amax + EPS);
		/* 45..135 degrees from the view direction (0, 0, -1): |dz| <= |dxy|; turned */
		if (!b->merged) {
			q->view = fmax(q->view, fabs(d.z) / hypot(d.x, d.y));
			CHECK(fabs(d.z) <= hypot(d.x, d.y) + EPS);
		} else {
			q->view = fmax(q->view, fabs(d.x) / hypot(d.z, d.y));
			CHECK(fabs(d.x) <= hypot(d.z, d.y) + EPS);
		}
		check_root(b, p);
	}
	fprintf(stderr,
		"  4.1, first tree: hull %+.3f m (<= 0 inside), largest ratio to the limit: length "
		"%.2f, angle %.2f, |dz|/|dxy| %.2f\n",
		r[0].hull, r[0].len, r[0].ang, r[0].view);
	if (r[1].n)
		fprintf(stderr,
			"  4.1, merged copies: %d of %d ends outside the hull (by up to %.2f m, as near "
			"as their depth allows), largest ratio to the limit: length %.2f, angle %.2f, "
			"|dx|/|dyz| %.2f\n",
			r[1].out, r[1].n, fmax(r[1].hull, 0), r[1].len, r[1].ang, r[1].view);
	free(src);
	free(h);
}

/* Mean distance from each branch end to the nearest other one: of the first tree, or of
 * the whole merged tree. */
static double end_spacing(const struct skel *s, bool first_only)
{
	double sum = 0;
	size_t n = 0;

	for (size_t i = 0; i < s->n; i++) {
		double best = INFINITY;

		if (first_only && s->b[i].merged)
			continue;
		for (size_t j = 0; j < s->n; j++)
			if (j != i && !(first_only && s->b[j].merged))
				best = fmin(best, vec3_dist(end_of(&s->b[i]), end_of(&s->b[j])));
		sum += best;
		n++;
	}
	return sum / (double)n;
}

/* How much sparser than random admissible depths, at least: on the mean over the seeds,
 * and for the least sparse seed (against the random mean). */
struct margin {
	double mean, each;
};

/* Mean and least sparse seed of the sparsest rule, and the random mean, over the seeds. */
struct spacing {
	double sparse, worst, rnd;
};

static void report_spacing(const char *name, const char *what, struct spacing s, struct margin m)
{
	fprintf(stderr,
		"%s: branch end to the nearest other (%s, %d seeds): sparsest %.3f m (least sparse "
		"seed %.3f m), random admissible %.3f m: x%.3f (asserted x%.2f), least sparse seed "
		"x%.3f (asserted x%.2f)\n",
		name, what, SEEDS, s.sparse, s.worst, s.rnd, s.sparse / s.rnd, m.mean, s.worst / s.rnd,
		m.each);
	CHECK(s.sparse >= m.mean * s.rnd);
	CHECK(s.worst >= m.each * s.rnd);
}

/*
 * Sparsest (the app's 3D button) against random admissible depths (LIFT_PICK_RANDOM), over
 * SEEDS drawing seeds, measured twice (docs/lifting.md has the numbers):
 *
 * - the first tree (the merged copies left out of both), against one random lift;
 * - the whole merged tree, against both lifts picking random depths: the second lift
 *   starts with the first tree's branches in its distance field, so its copies avoid them.
 *
 * The mean must be at least `mean` x the random mean, and every seed at least `each` x it.
 * Also: the SEEDS seeds give at least `min_distinct` different trees. The second tree now
 * follows the first, so two seeds that give the same first tree (a few branches, placed
 * alike) can give the same whole tree.
 */
#define FIRST_TREE ((struct margin){ 1.08, 1.05 })
#define WHOLE_TREE ((struct margin){ 1.05, 0.95 })

static void check_sparser(const char *name, struct margin first, struct margin whole,
			  int min_distinct)
{
	struct spacing f = { 0, INFINITY, 0 }, w = { 0, INFINITY, 0 };
	struct buf sk[SEEDS];
	int distinct = 0;

	for (uint64_t seed = 1; seed <= SEEDS; seed++) {
		struct app *a = replay(name, seed, true), *b = replay(name, seed, false);
		struct app *c = replay(name, seed, false);
		struct buf *k = &sk[seed - 1];
		bool same = false;
		struct skel s;
		struct rng r;
		double v;

		skeleton_bytes(&a->tree, k);
		for (struct buf *o = sk; o < k; o++)
			same |= o->len == k->len && memcmp(o->data, k->data, k->len) == 0;
		distinct += !same;
		s = parse(&a->tree);
		v = end_spacing(&s, true);
		f.sparse += v;
		f.worst = fmin(f.worst, v);
		v = end_spacing(&s, false);
		w.sparse += v;
		w.worst = fmin(w.worst, v);
		skel_free(&s);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree_with(&b->tree, &r, false, LIFT_PICK_RANDOM), 0);
		s = parse(&b->tree);
		f.rnd += end_spacing(&s, true);
		skel_free(&s);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree_with(&c->tree, &r, true, LIFT_PICK_RANDOM), 0);
		s = parse(&c->tree);
		w.rnd += end_spacing(&s, false);
		skel_free(&s);
		app_destroy(a);
		app_destroy(b);
		app_destroy(c);
	}
	f.sparse /= SEEDS, f.rnd /= SEEDS;
	w.sparse /= SEEDS, w.rnd /= SEEDS;
	report_spacing(name, "first tree", f, first);
	report_spacing(name, "whole tree", w, whole);
	fprintf(stderr, "%s: %d different trees of %d seeds (asserted %d)\n", name, distinct, SEEDS,
		min_distinct);
	CHECK(distinct >= min_distinct);
	for (int i = 0; i < SEEDS; i++)
		buf_finish(&sk[i]);
}

/* Depth extent over width: the whole tree, or the first tree only. */
static double depth_over_width(const struct skel *s, bool first_only)
{
	struct vec3 lo, hi;

	extent(s, first_only, &lo, &hi);
	return (hi.z - lo.z) / (hi.x - lo.x);
}

/* Same seed: identical skeleton.json and drawing; another seed: another tree (the same
 * front view). */
static void check_seeds(const char *name)
{
	struct app *a = replay(name, 7, true), *b = replay(name, 7, true), *c = replay(name, 8, true);
	struct buf sa, sb, sc, da, db;
	struct skel pa, pc;
	bool differ = false;

	skeleton_bytes(&a->tree, &sa);
	skeleton_bytes(&b->tree, &sb);
	skeleton_bytes(&c->tree, &sc);
	buf_init(&da);
	buf_init(&db);
	CHECK_INT(doc_serialize(&a->doc, &a->tree, &da), 0);
	CHECK_INT(doc_serialize(&b->doc, &b->tree, &db), 0);
	CHECK(sa.len == sb.len && memcmp(sa.data, sb.data, sa.len) == 0);
	CHECK(da.len == db.len && memcmp(da.data, db.data, da.len) == 0);
	CHECK(sa.len != sc.len || memcmp(sa.data, sc.data, sa.len) != 0);
	pa = parse(&a->tree);
	pc = parse(&c->tree);
	CHECK_INT(pa.n, pc.n);
	for (size_t i = 0; i < pa.n; i++) {
		CHECK_INT(pa.b[i].n, pc.b[i].n);
		for (size_t k = 0; k < pa.b[i].n; k++) {
			if (!pa.b[i].merged) {
				CHECK(pa.b[i].p[k].x == pc.b[i].p[k].x);
				CHECK(pa.b[i].p[k].y == pc.b[i].p[k].y);
			}
			differ |= pa.b[i].p[k].z != pc.b[i].p[k].z;
		}
	}
	CHECK(differ);
	skel_free(&pa);
	skel_free(&pc);
	buf_finish(&sa), buf_finish(&sb), buf_finish(&sc), buf_finish(&da), buf_finish(&db);
	app_destroy(a);
	app_destroy(b);
	app_destroy(c);
}

/* The sketch replayed without and with 3D (drawing seed 1), both skeletons checked. */
static void lifted(const char *name, struct skel *s2, struct skel *s3)
{
	struct app *a2 = replay(name, 1, false), *a3 = replay(name, 1, true);

	fprintf(stderr, "%s\n", name);
	*s2 = parse(&a2->tree);
	*s3 = parse(&a3->tree);
	CHECK(!a2->tree.lifted);
	check_front_view(s2, s3);
	check_constraints(s2, s3);
	app_destroy(a2);
	app_destroy(a3);
}

static void test_young(void)
{
	struct skel s2, s3;

	lifted("lift-young.edaha-trace", &s2, &s3);
	CHECK_INT(s2.n, 6);
	/* the merged copy: every branch but the trunk, turned */
	CHECK_INT(s3.n, 6 + 5);
	skel_free(&s2);
	skel_free(&s3);
}

static void test_broadleaf(void)
{
	struct skel s2, s3;
	double r;

	lifted("lift-broadleaf.edaha-trace", &s2, &s3);
	CHECK_INT(s2.n, 13);
	CHECK_INT(s3.n, 13 + 12);
	/* left-right symmetric: about as deep as it is wide */
	r = depth_over_width(&s3, false);
	fprintf(stderr, "  depth / width: whole tree %.2f, first tree %.2f\n", r,
		depth_over_width(&s3, true));
	CHECK(r >= 0.5 && r <= 1.5);
	skel_free(&s2);
	skel_free(&s3);
}

static void test_conifer(void)
{
	struct skel s2, s3;

	lifted("lift-conifer.edaha-trace", &s2, &s3);
	CHECK_INT(s2.n, 17);
	CHECK_INT(s3.n, 17 + 16);
	/* branches on alternate sides: nearly symmetric, not asserted */
	fprintf(stderr, "  depth / width: whole tree %.2f, first tree %.2f\n",
		depth_over_width(&s3, false), depth_over_width(&s3, true));
	skel_free(&s2);
	skel_free(&s3);
}

/*
 * A helix: in the frame of branch b's chord (u along it, x across it on the screen), the
 * depth off the chord is as large as the sideways excursion (within 20%), and a quarter
 * period out of phase: every interior depth extreme lies within an eighth of a period of
 * a place where x crosses zero.
 */
static void check_helix(const struct sbranch *b, double period)
{
	struct vec3 a = start_of(b), d = chord(b);
	double L = hypot(d.x, d.y), cx = d.x / L, cy = d.y / L;
	double xamp = 0, zlo = INFINITY, zhi = -INFINITY, *u, *x, *z;
	int extremes = 0;

	u = calloc(3 * b->n, sizeof(*u));
	CHECK(u);
	x = u + b->n;
	z = x + b->n;
	for (size_t k = 0; k < b->n; k++) {
		struct vec3 q = vec3_sub(b->p[k], a);

		u[k] = q.x * cx + q.y * cy;
		x[k] = -q.x * cy + q.y * cx;
		z[k] = q.z - d.z * u[k] / L; /* off the chord */
		xamp = fmax(xamp, fabs(x[k]));
		zlo = fmin(zlo, z[k]);
		zhi = fmax(zhi, z[k]);
	}
	fprintf(stderr, "  helix: sideways %.3f m, depth %.3f m\n", xamp, 0.5 * (zhi - zlo));
	CHECK(fabs(0.5 * (zhi - zlo) - xamp) <= 0.2 * xamp);
	for (size_t k = 1; k + 1 < b->n; k++) {
		double nearest = INFINITY;

		if (!((z[k] > z[k - 1] && z[k] >= z[k + 1]) || (z[k] < z[k - 1] && z[k] <= z[k + 1])))
			continue;
		extremes++;
		for (size_t j = 0; j + 1 < b->n; j++)
			if ((x[j] < 0) != (x[j + 1] < 0))
				nearest = fmin(nearest, fabs(u[j] - u[k]));
		CHECK(nearest < period / 8);
	}
	CHECK(extremes >= 3);
	free(u);
}

static void test_sine(void)
{
	struct skel s2, s3;

	lifted("lift-sine.edaha-trace", &s2, &s3);
	CHECK_INT(s3.n, 1);
	check_helix(&s3.b[0], 240 * 10.0 / H); /* two waves over 480 px */
	skel_free(&s2);
	skel_free(&s3);
}

static void test_sine_branch(void)
{
	struct skel s2, s3;

	lifted("lift-sine-branch.edaha-trace", &s2, &s3);
	CHECK_INT(s3.n, 3);
	check_helix(&s3.b[1], 0.5 * hypot(360, 180) * 10.0 / H);
	skel_free(&s2);
	skel_free(&s3);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	dir = argv[1];
	test_young();
	test_broadleaf();
	test_conifer();
	test_sine();
	test_sine_branch();
	/* measured (first tree; whole tree): young x1.13, x1.12; x1.10, x1.00; broadleaf x1.17,
	 * x1.15; x1.10, x1.07; conifer x1.21, x1.10; x1.15, x1.06 (mean; least sparse seed).
	 * Different trees of 20: young 18 (the first trees alone: 15), broadleaf and conifer 20. */
	check_sparser("lift-young.edaha-trace", FIRST_TREE, WHOLE_TREE, 17);
	check_sparser("lift-broadleaf.edaha-trace", FIRST_TREE, WHOLE_TREE, SEEDS);
	check_sparser("lift-conifer.edaha-trace", FIRST_TREE, WHOLE_TREE, SEEDS);
	check_seeds("lift-young.edaha-trace");
	check_seeds("lift-conifer.edaha-trace");
	return 0;
}
