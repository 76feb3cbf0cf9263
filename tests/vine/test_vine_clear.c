/* SPDX-License-Identifier: MIT */
/*
 * A vine's drawn stem stays out of its support (issue 24 item 4, docs/vines.md "Clear of
 * the support"): on a pole, a T (the issue's: a pole of radius 1 cm, 0.8 m, a bar as
 * thick across its top, a stem of 2 mm), a cross, square posts and bars (sharp edges), a
 * drawn 3D tree (its forks), each twining both ways; then a few hundred seeded random
 * supports (unions of prisms and boxes at random angles, meeting at junctions) with random
 * vines within the format's limits.
 *
 * Every point of every shoot's smoothed axis (vine_smooth, what skeleton.json's "smooth"
 * is) must lie at least 0.95 r from the support and outside it; no vertex of the stems'
 * mesh may be inside the support by more than its own float rounding. Both are measured
 * here against the support's triangles, independently of src/: the exact distance from a
 * point to a triangle (the plane's foot when it falls inside, else the nearest edge), and
 * inside as the test's own solids say (a convex piece's face planes; the tree's bark by
 * its winding number). The worst margins are printed.
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "mesh.h"
#include "pen.h"
#include "rng.h"
#include "test.h"
#include "tree.h"
#include "vine.h"
#include "vine_support.h"

#define DEG (VEC_PI / 180.0)
#define MAX_PIECES 6
#define MAX_SIDES 32

/* ---- The test's own geometry ---- */

struct tri3 {
	struct vec3 a, b, c;
	struct vec3 lo, hi; /* its box */
};

/* A convex piece: its face planes (outward normal n, n . p <= d inside) and box. */
struct piece {
	struct vec3 n[MAX_SIDES + 2];
	double d[MAX_SIDES + 2];
	int nplanes;
	struct vec3 lo, hi;
};

/* A support: triangles for src/ (floats) and for the measures (the same floats, as doubles),
 * the convex pieces it is the union of (none: inside by winding number). */
struct solid {
	float *pos;
	uint32_t *idx;
	size_t nv, nt;
	struct tri3 *tri;
	struct piece piece[MAX_PIECES];
	int npieces;
};

static struct vec3 vmin(struct vec3 a, struct vec3 b)
{
	return vec3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
}

static struct vec3 vmax(struct vec3 a, struct vec3 b)
{
	return vec3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
}

static size_t add_vertex(struct solid *s, struct vec3 p)
{
	s->pos = realloc(s->pos, 3 * (s->nv + 1) * sizeof(*s->pos));
	CHECK(s->pos);
	s->pos[3 * s->nv] = (float)p.x;
	s->pos[3 * s->nv + 1] = (float)p.y;
	s->pos[3 * s->nv + 2] = (float)p.z;
	return s->nv++;
}

static struct vec3 vertex_of(const struct solid *s, size_t i)
{
	return vec3(s->pos[3 * i], s->pos[3 * i + 1], s->pos[3 * i + 2]);
}

static void add_triangle(struct solid *s, size_t a, size_t b, size_t c)
{
	struct tri3 *t;

	s->idx = realloc(s->idx, 3 * (s->nt + 1) * sizeof(*s->idx));
	s->tri = realloc(s->tri, (s->nt + 1) * sizeof(*s->tri));
	CHECK(s->idx && s->tri);
	s->idx[3 * s->nt] = (uint32_t)a;
	s->idx[3 * s->nt + 1] = (uint32_t)b;
	s->idx[3 * s->nt + 2] = (uint32_t)c;
	t = &s->tri[s->nt++];
	t->a = vertex_of(s, a);
	t->b = vertex_of(s, b);
	t->c = vertex_of(s, c);
	t->lo = vmin(vmin(t->a, t->b), t->c);
	t->hi = vmax(vmax(t->a, t->b), t->c);
}

/* The plane through a, b, c (counter-clockwise seen from outside) into piece p. */
static void add_plane(struct piece *p, struct vec3 a, struct vec3 b, struct vec3 c)
{
	struct vec3 n = vec3_norm_or(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)), vec3(0, 1, 0));

	CHECK(p->nplanes < MAX_SIDES + 2);
	p->n[p->nplanes] = n;
	p->d[p->nplanes++] = vec3_dot(n, a);
}

/*
 * A convex prism appended to s as one piece: the polygon (cx[i], cy[i]) (counter-clockwise,
 * convex) across direction u, from o to o + h u, the polygon turned by `phase` about u.
 * Quads for the sides, fans for the caps, every vertex a float.
 */
static void prism(struct solid *s, const double *cx, const double *cy, int sides, struct vec3 o,
		  struct vec3 u, double h, double phase)
{
	struct vec3 e1 = vec3_norm_or(vec3_cross(u, vec3(0, 0, 1)), vec3(1, 0, 0)), e2;
	struct piece *pc = &s->piece[s->npieces++];
	size_t base = s->nv, c0, c1;
	struct vec3 ring[2][MAX_SIDES];

	CHECK(s->npieces <= MAX_PIECES && sides >= 3 && sides <= MAX_SIDES);
	u = vec3_norm_or(u, vec3(0, 1, 0));
	if (vec3_len(vec3_cross(u, vec3(0, 0, 1))) < 1e-6)
		e1 = vec3(1, 0, 0);
	e2 = vec3_cross(u, e1);
	memset(pc, 0, sizeof(*pc));
	pc->lo = vec3(INFINITY, INFINITY, INFINITY);
	pc->hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	for (int e = 0; e < 2; e++)
		for (int i = 0; i < sides; i++) {
			double x = cx[i] * cos(phase) - cy[i] * sin(phase);
			double y = cx[i] * sin(phase) + cy[i] * cos(phase);
			struct vec3 p = vec3_add(vec3_add(o, vec3_scale(u, e * h)),
						 vec3_add(vec3_scale(e1, x), vec3_scale(e2, y)));

			add_vertex(s, p);
			ring[e][i] = vertex_of(s, s->nv - 1);
			pc->lo = vmin(pc->lo, ring[e][i]);
			pc->hi = vmax(pc->hi, ring[e][i]);
		}
	c0 = add_vertex(s, vec3_add(vec3_scale(ring[0][0], 0.5), vec3_scale(ring[0][sides / 2], 0.5)));
	c1 = add_vertex(s, vec3_add(vec3_scale(ring[1][0], 0.5), vec3_scale(ring[1][sides / 2], 0.5)));
	for (int i = 0; i < sides; i++) {
		int j = (i + 1) % sides;
		size_t a0 = base + (size_t)i, b0 = base + (size_t)j;
		size_t a1 = a0 + (size_t)sides, b1 = b0 + (size_t)sides;

		add_triangle(s, a0, b0, b1);
		add_triangle(s, a0, b1, a1);
		add_triangle(s, c0, b0, a0);
		add_triangle(s, c1, a1, b1);
		add_plane(pc, ring[0][i], ring[0][j], ring[1][j]);
	}
	/* the caps: their planes from three ring points (the cap centres are midpoints) */
	add_plane(pc, ring[0][0], ring[0][2 % sides], ring[0][1]);
	add_plane(pc, ring[1][0], ring[1][1], ring[1][2 % sides]);
}

static void cylinder_piece(struct solid *s, double R, int sides, struct vec3 o, struct vec3 u,
			   double h, double phase)
{
	double cx[MAX_SIDES], cy[MAX_SIDES];

	for (int i = 0; i < sides; i++) {
		cx[i] = R * cos(2 * VEC_PI * i / sides);
		cy[i] = R * sin(2 * VEC_PI * i / sides);
	}
	prism(s, cx, cy, sides, o, u, h, phase);
}

/* A box of half-widths a, b across u. */
static void box_piece(struct solid *s, double a, double b, struct vec3 o, struct vec3 u, double h,
		      double phase)
{
	const double cx[4] = { a, -a, -a, a }, cy[4] = { b, b, -b, -b };

	prism(s, cx, cy, 4, o, u, h, phase);
}

static void solid_finish(struct solid *s)
{
	free(s->pos);
	free(s->idx);
	free(s->tri);
	memset(s, 0, sizeof(*s));
}

/* The squared distance from p to segment a-b. */
static double seg_d2(struct vec3 p, struct vec3 a, struct vec3 b)
{
	struct vec3 ab = vec3_sub(b, a), q = a;
	double l2 = vec3_dot(ab, ab);

	if (l2 > 0) {
		double t = vec3_dot(vec3_sub(p, a), ab) / l2;

		q = vec3_add(a, vec3_scale(ab, t < 0 ? 0 : t > 1 ? 1 : t));
	}
	return vec3_dot(vec3_sub(p, q), vec3_sub(p, q));
}

/* The exact distance from p to triangle t: the foot on its plane when that falls inside
 * (all three edge tests agree with the normal), else its nearest edge. */
static double tri_dist(struct vec3 p, const struct tri3 *t)
{
	struct vec3 n = vec3_cross(vec3_sub(t->b, t->a), vec3_sub(t->c, t->a));
	double nn = vec3_dot(n, n), d2;

	if (nn > 0) {
		double h = vec3_dot(vec3_sub(p, t->a), n) / nn;
		struct vec3 f = vec3_sub(p, vec3_scale(n, h));

		if (vec3_dot(vec3_cross(vec3_sub(t->b, t->a), vec3_sub(f, t->a)), n) >= 0 &&
		    vec3_dot(vec3_cross(vec3_sub(t->c, t->b), vec3_sub(f, t->b)), n) >= 0 &&
		    vec3_dot(vec3_cross(vec3_sub(t->a, t->c), vec3_sub(f, t->c)), n) >= 0)
			return fabs(h) * sqrt(nn);
	}
	d2 = fmin(seg_d2(p, t->a, t->b), fmin(seg_d2(p, t->b, t->c), seg_d2(p, t->c, t->a)));
	return sqrt(d2);
}

static double box_dist(struct vec3 p, struct vec3 lo, struct vec3 hi)
{
	double dx = fmax(fmax(lo.x - p.x, p.x - hi.x), 0), dy = fmax(fmax(lo.y - p.y, p.y - hi.y), 0);
	double dz = fmax(fmax(lo.z - p.z, p.z - hi.z), 0);

	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The distance from p to the support's triangles, or `cap` if none is nearer. */
static double solid_dist(const struct solid *s, struct vec3 p, double cap)
{
	double best = cap;

	for (size_t i = 0; i < s->nt; i++)
		if (box_dist(p, s->tri[i].lo, s->tri[i].hi) < best)
			best = fmin(best, tri_dist(p, &s->tri[i]));
	return best;
}

/* The solid angle of triangle abc seen from p, signed (Van Oosterom and Strackee). */
static double solid_angle(struct vec3 p, const struct tri3 *t)
{
	struct vec3 a = vec3_sub(t->a, p), b = vec3_sub(t->b, p), c = vec3_sub(t->c, p);
	double la = vec3_len(a), lb = vec3_len(b), lc = vec3_len(c);
	double num = vec3_dot(a, vec3_cross(b, c));
	double den = la * lb * lc + vec3_dot(a, b) * lc + vec3_dot(b, c) * la + vec3_dot(c, a) * lb;

	return 2 * atan2(num, den);
}

/* Inside the support: inside one of its convex pieces (deeper than tol), or with no
 * pieces, a winding number of the triangles (seen from outside counter-clockwise) of 1/2
 * or more. */
static bool solid_inside(const struct solid *s, struct vec3 p, double tol)
{
	if (s->npieces == 0) {
		double w = 0;

		for (size_t i = 0; i < s->nt; i++)
			w += solid_angle(p, &s->tri[i]);
		return w / (4 * VEC_PI) >= 0.5 && solid_dist(s, p, tol) >= tol;
	}
	for (int k = 0; k < s->npieces; k++) {
		const struct piece *pc = &s->piece[k];
		bool in = box_dist(p, pc->lo, pc->hi) == 0;

		for (int i = 0; in && i < pc->nplanes; i++)
			in = vec3_dot(pc->n[i], p) - pc->d[i] < -tol;
		if (in)
			return true;
	}
	return false;
}

static struct vine_support *support_of_solid(const struct solid *s)
{
	struct vine_support *vs;

	CHECK_INT(vine_support_create(s->pos, s->nv, s->idx, s->nt, &vs), 0);
	return vs;
}

/* ---- The measures ---- */

/* The worst margins seen: the smoothed axis' distance over r, the stems' vertices' signed
 * distance over r (negative inside), and where. */
struct margins {
	double axis, vertex, raw;
	char axis_at[96], vertex_at[96];
	size_t vines, points, vertices, moved;
};

static void margins_init(struct margins *m)
{
	memset(m, 0, sizeof(*m));
	m->axis = m->vertex = m->raw = INFINITY;
}

/* A float vertex's own rounding: half an ulp a coordinate, all three. */
static double float_tol(struct vec3 p)
{
	return 2 * FLT_EPSILON * fmax(fmax(fabs(p.x), fabs(p.y)), fmax(fabs(p.z), 1e-3));
}

/*
 * v against s: every smoothed point at least 0.95 r from it and outside; no stem vertex
 * inside by more than its float rounding. Records the worst margins in m (name says where).
 */
static void check_vine(const struct vine *v, const struct solid *s, const char *name,
		       struct margins *m)
{
	double r = v->p.radius;
	struct mesh stem, leaves;

	m->vines++;
	for (size_t k = 0; k < v->nshoots; k++) {
		const struct vine_shoot *sh = &v->shoots[k];
		struct vec3 *a;

		CHECK_INT(vine_smooth(v, k, &a), 0);
		for (size_t i = 0; i < sh->n; i++) {
			double d = solid_dist(s, a[i], 2 * r), raw = solid_dist(s, sh->axis[i], 2 * r);

			m->points++;
			m->moved += memcmp(&a[i], &sh->axis[i], sizeof(a[i])) != 0;
			if (solid_inside(s, a[i], 0))
				d = -d;
			if (d / r < m->axis) {
				m->axis = d / r;
				snprintf(m->axis_at, sizeof(m->axis_at), "%s, shoot %zu point %zu", name,
					 k, i);
			}
			m->raw = fmin(m->raw, raw / r);
			/* the raw axis too: every point r clear (to rounding) and outside, but the
			 * root where it was planted (outside, r clear, by the tests' choice) */
			CHECK(raw >= (1 - 1e-9) * r && !solid_inside(s, sh->axis[i], 0));
			if (!(d >= 0.95 * r))
				fprintf(stderr, "%s: shoot %zu point %zu of %zu (%.6f %.6f %.6f) is "
					"%.4f r from the support (raw %.4f r)\n", name, k, i, sh->n,
					a[i].x, a[i].y, a[i].z, d / r, raw / r);
			CHECK(d >= 0.95 * r);
		}
		free(a);
	}
	mesh_init(&stem);
	mesh_init(&leaves);
	CHECK_INT(vine_mesh_append(v, &stem, &leaves), 0);
	for (size_t i = 0; i < stem.nvertices; i++) {
		const float *q = stem.positions + 3 * i;
		struct vec3 p = vec3(q[0], q[1], q[2]);
		double tol = float_tol(p), d = solid_dist(s, p, 2 * r);

		m->vertices++;
		if (solid_inside(s, p, tol))
			d = -d;
		if (d / r < m->vertex) {
			m->vertex = d / r;
			snprintf(m->vertex_at, sizeof(m->vertex_at), "%s, vertex %zu", name, i);
		}
		if (d < 0)
			fprintf(stderr, "%s: stem vertex %zu (%.6f %.6f %.6f) is %.3g m inside\n",
				name, i, p.x, p.y, p.z, -d);
		CHECK(d >= 0);
	}
	mesh_finish(&stem);
	mesh_finish(&leaves);
}

static void margins_print(const char *what, const struct margins *m)
{
	printf("%s: %zu vines, %zu smoothed points (%zu off the raw axis), %zu stem vertices\n"
	       "  worst smoothed point %.4f r from the support (%s; the raw axis %.4f r)\n"
	       "  worst stem vertex %+.3g r outside it (%s)\n",
	       what, m->vines, m->points, m->moved, m->vertices, m->axis, m->axis_at, m->raw,
	       m->vertex, m->vertex_at);
}

static struct vine_params params(double angle, enum vine_twining tw, int internodes)
{
	struct vine_params p;

	vine_params_default(&p);
	p.angle = angle;
	p.twining = tw;
	p.internodes = internodes;
	return p;
}

/* A vine with p grown to its end on s from plant, checked; returns how high it got. */
static double grow_check(const struct solid *s, const struct vine_support *vs,
			 const struct vine_params *p, struct vec3 plant, const char *name,
			 struct margins *m)
{
	struct vine v;
	double top = -INFINITY;

	vine_init(&v, p, plant);
	CHECK_INT(vine_grow(&v, vs, INFINITY), 0);
	check_vine(&v, s, name, m);
	for (size_t k = 0; k < v.nshoots; k++)
		for (size_t i = 0; i < v.shoots[k].n; i++)
			top = fmax(top, v.shoots[k].axis[i].y);
	vine_finish(&v);
	return top;
}

/* ---- Named supports ---- */

static const struct vec3 UP = { 0, 1, 0 }, ALONG_X = { 1, 0, 0 };

/* Each named support, both twinings, both the default lean (18) and the morning glory's
 * (30), planted by the pole's foot r and a millimetre from its side. */
static void test_named(void)
{
	struct margins all;

	margins_init(&all);
	for (int kind = 0; kind < 5; kind++) {
		static const char *names[] = { "pole", "T (issue 24)", "cross", "square post and bar",
					       "crate" };
		struct solid s = { 0 };
		struct vine_support *vs;
		double side = 0; /* the post's half-width along +x, at the foot */
		struct margins m;

		switch (kind) {
		case 0: /* the command line's pole: 2 cm, 1 m, 32 sides */
			cylinder_piece(&s, 0.02, 32, vec3(0, 0, 0), UP, 1.0, 0);
			side = 0.02;
			break;
		case 1: /* the T: 1 cm, 0.8 m, a bar as thick across its top */
			cylinder_piece(&s, 0.01, 32, vec3(0, 0, 0), UP, 0.8, 0);
			cylinder_piece(&s, 0.01, 32, vec3(-0.2, 0.8, 0), ALONG_X, 0.4, 0);
			side = 0.01;
			break;
		case 2: /* the command line's cross: a bar as thick, 0.6 m, at 0.5 m */
			cylinder_piece(&s, 0.02, 32, vec3(0, 0, 0), UP, 1.0, 0);
			cylinder_piece(&s, 0.02, 32, vec3(-0.3, 0.5, 0), ALONG_X, 0.6, 0);
			side = 0.02;
			break;
		case 3: /* a square post 3 cm, turned 30 degrees, a square bar 2 cm through it at
			 * 0.45 m and one resting on its top: sharp edges everywhere */
			box_piece(&s, 0.015, 0.015, vec3(0, 0, 0), UP, 0.9, 30 * DEG);
			box_piece(&s, 0.01, 0.01, vec3(-0.25, 0.45, -0.05), vec3(1, 0, 0.2), 0.5, 0);
			box_piece(&s, 0.012, 0.012, vec3(-0.2, 0.912, 0.1), vec3(1, 0, -0.5), 0.45,
				  10 * DEG);
			side = 0.015 * sqrt(2); /* the corner's reach, turned */
			break;
		default: /* a crate 12 cm on a post: a vine reaching its underside and edges */
			box_piece(&s, 0.012, 0.012, vec3(0, 0, 0), UP, 0.5, 0);
			box_piece(&s, 0.06, 0.06, vec3(0, 0.5, 0), UP, 0.12, 45 * DEG);
			side = 0.012 * sqrt(2);
			break;
		}
		vs = support_of_solid(&s);
		/* the measure itself: the post's axis is inside, a point beside its foot not */
		CHECK(solid_inside(&s, vec3(0, 0.2, 0), 0));
		CHECK(!solid_inside(&s, vec3(side + 0.0025, 0.2, 0), 0));
		{
			double d = solid_dist(&s, vec3(side + 0.0025, 0.2, 0), 1);

			/* side is the post's reach: a turned square's face is nearer */
			CHECK(d >= 0.0025 * (1 - 1e-6) && d <= 0.0025 + 0.3 * side);
		}
		margins_init(&m);
		for (int tw = 0; tw < 2; tw++)
			for (int lean = 0; lean < 2; lean++) {
				struct vine_params p = params(lean ? 30 : 18, tw ? VINE_RIGHT : VINE_LEFT, 60);
				char name[96];
				double top;

				snprintf(name, sizeof(name), "%s, %s, %d degrees", names[kind],
					 tw ? "right" : "left", lean ? 30 : 18);
				top = grow_check(&s, vs, &p, vec3(side + p.radius + 0.001, 0, 0), name, &m);
				printf("%s: climbed to %.3f m\n", name, top);
				CHECK(top > 0.3); /* it climbed: the junctions are where it went */
			}
		margins_print(names[kind], &m);
		all.vines += m.vines;
		all.points += m.points;
		all.vertices += m.vertices;
		all.moved += m.moved;
		if (m.axis < all.axis) {
			all.axis = m.axis;
			memcpy(all.axis_at, m.axis_at, sizeof(all.axis_at));
		}
		if (m.vertex < all.vertex) {
			all.vertex = m.vertex;
			memcpy(all.vertex_at, m.vertex_at, sizeof(all.vertex_at));
		}
		all.raw = fmin(all.raw, m.raw);
		vine_support_destroy(vs);
		solid_finish(&s);
	}
	margins_print("named supports", &all);
}

/* ---- A drawn 3D tree ---- */

static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

/*
 * The vine mode's tap beside a drawn tree's trunk (a trunk and four limbs, made 3D), and
 * the same vine twining the other way on the same bark: they wind up the trunk past the
 * limbs' forks.
 */
static void test_drawn_tree(void)
{
	struct app *app = app_create(1280, 800, 7);
	struct tree_mesh bark;
	struct solid s = { 0 };
	struct vine_support *vs;
	struct margins m;
	const struct vine *planted;
	struct vine_params p;
	size_t forks = 0;

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 536, 880, 400);
	pen_line(&pen, app, 640, 480, 410, 350);
	pen_line(&pen, app, 640, 400, 780, 250);
	pen_line(&pen, app, 640, 360, 500, 220);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	pen_button(&pen, app, BUTTON_VINE);
	pen_line(&pen, app, 680, 730, 680, 730);
	CHECK_INT(app->tree.nvines, 1);
	planted = &app->tree.vines[0];

	/* the bark it grew on, as the kiosk builds it (app_vine_support) */
	tree_mesh_init(&bark);
	CHECK_INT(tree_mesh_append(&bark, &app->tree, 0, app->tree.nleaves), 0);
	s.pos = malloc(3 * bark.bark.nvertices * sizeof(*s.pos));
	CHECK(s.pos);
	memcpy(s.pos, bark.bark.positions, 3 * bark.bark.nvertices * sizeof(*s.pos));
	s.nv = bark.bark.nvertices;
	for (size_t i = 0; i < bark.bark.nindices; i += 3)
		add_triangle(&s, bark.bark.indices[i], bark.bark.indices[i + 1],
			     bark.bark.indices[i + 2]);
	tree_mesh_finish(&bark);
	/* the measure itself: the trunk's axis is inside its bark, a point beside it not */
	{
		const struct branch *tr = &app->tree.branches[0];
		struct vec3 mid = tr->points[tr->npoints / 2];

		CHECK(solid_inside(&s, mid, 0));
		CHECK(!solid_inside(&s, vec3_add(mid, vec3(0, 0, 3 * tr->radii[tr->npoints / 2])),
				    0));
	}
	vs = support_of_solid(&s);
	margins_init(&m);
	check_vine(planted, &s, "drawn tree, the kiosk's vine (right)", &m);

	/* the forks it passes: limbs' roots within three trunk radii of its drawn axis */
	for (size_t b = 1; b < app->tree.nbranches; b++) {
		const struct branch *br = &app->tree.branches[b];
		double near = INFINITY;

		if (br->parent != 0)
			continue;
		for (size_t k = 0; k < planted->nshoots; k++)
			for (size_t i = 0; i < planted->shoots[k].n; i++)
				near = fmin(near, vec3_dist(planted->shoots[k].axis[i], br->points[0]));
		forks += near < 3 * app->tree.branches[0].radii[0];
	}
	printf("drawn tree: bark %zu triangles, trunk radius %.3f m, the vine %.1f mm thick, "
	       "past %zu forks\n", s.nt, app->tree.branches[0].radii[0], 2e3 * planted->p.radius,
	       forks);
	CHECK(forks >= 2);

	/* the same, twining left, and both grown here again (the same as the kiosk's) */
	p = planted->p;
	for (int tw = 0; tw < 2; tw++) {
		char name[64];

		p.twining = tw ? VINE_RIGHT : VINE_LEFT;
		snprintf(name, sizeof(name), "drawn tree, %s", tw ? "right" : "left");
		grow_check(&s, vs, &p, planted->plant, name, &m);
	}
	margins_print("drawn tree", &m);
	vine_support_destroy(vs);
	solid_finish(&s);
	app_destroy(app);
}

/* A solid of t's bark as the kiosk's vines climb it (app_vine_support): the branches'
 * tubes and, on a grown tree, its wood's bark; the measure's own copy. */
static void solid_of_bark(struct solid *s, const struct tree *t)
{
	struct tree_mesh bark;
	const struct mesh *parts[2];

	tree_mesh_init(&bark);
	CHECK_INT(tree_mesh_append(&bark, t, 0, t->nleaves), 0);
	parts[0] = &bark.bark;
	parts[1] = t->wood ? &t->wood->bark : NULL;
	for (int k = 0; k < 2; k++) {
		const struct mesh *m = parts[k];
		size_t v0 = s->nv;

		if (!m || !m->nvertices)
			continue;
		s->pos = realloc(s->pos, 3 * (s->nv + m->nvertices) * sizeof(*s->pos));
		CHECK(s->pos);
		memcpy(s->pos + 3 * v0, m->positions, 3 * m->nvertices * sizeof(*s->pos));
		s->nv += m->nvertices;
		for (size_t i = 0; i < m->nindices; i += 3)
			add_triangle(s, v0 + m->indices[i], v0 + m->indices[i + 1],
				     v0 + m->indices[i + 2]);
	}
	tree_mesh_finish(&bark);
}

/*
 * A grown tree (two grow presses: its trunk and limbs are its wood's bark, thicker than
 * their tubes) and the kiosk's vine planted at its foot afterwards: the vine twines round
 * the wood, clear of it and outside it, as round any bark (it once climbed the thin
 * tubes inside the wood: app_vine_support left the wood out).
 */
static void test_grown_tree(void)
{
	struct app *app = app_create(1280, 800, 7);
	struct solid s = { 0 };
	struct margins m;
	double wood_r = 0.0;

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 536, 880, 400);
	pen_line(&pen, app, 640, 480, 410, 350);
	pen_line(&pen, app, 640, 400, 780, 250);
	pen_button(&pen, app, BUTTON_3D);
	pen_button(&pen, app, BUTTON_GROW);
	pen_button(&pen, app, BUTTON_GROW);
	CHECK(app->tree.wood && app->tree.wood->bark.nvertices);
	pen_button(&pen, app, BUTTON_VINE);
	pen_line(&pen, app, 700, 730, 700, 730);
	CHECK_INT(app->tree.nvines, 1);
	solid_of_bark(&s, &app->tree);
	/* the wood is thicker than the trunk's tube at its foot: the case that matters */
	{
		const struct branch *tr = &app->tree.branches[0];
		const struct mesh *w = &app->tree.wood->bark;
		struct vec3 foot = tr->points[0];

		for (size_t i = 0; i < w->nvertices; i++) {
			const float *q = w->positions + 3 * i;

			if (q[1] - foot.y < 4 * tr->radii[0])
				wood_r = fmax(wood_r, hypot(q[0] - foot.x, q[2] - foot.z));
		}
		printf("grown tree: the trunk's tube %.3f m, its wood %.3f m at the foot\n",
		       tr->radii[0], wood_r);
		CHECK(wood_r > tr->radii[0]);
	}
	margins_init(&m);
	check_vine(&app->tree.vines[0], &s, "grown tree, the kiosk's vine", &m);
	margins_print("grown tree", &m);
	solid_finish(&s);
	app_destroy(app);
}

/* ---- Random supports ---- */

static double uni(struct rng *g, double lo, double hi)
{
	return rng_range(g, lo, hi);
}

static int uni_int(struct rng *g, int lo, int hi)
{
	int v = lo + (int)(rng_uniform(g) * (hi - lo + 1));

	return v > hi ? hi : v;
}

/* A random valid vine: lengths a plant's, every key within docs/vine-format.md's limits. */
static struct vine_params random_params(struct rng *g, int twining)
{
	struct vine_params p;
	const char *key;
	struct error err = { { 0 } };

	vine_params_default(&p);
	p.internode = uni(g, 0.02, 0.12);
	p.points_per_internode = uni_int(g, 2, 12);
	p.radius = uni(g, 0.0005, fmin(0.01, 0.999 * p.internode / 4));
	p.angle = uni(g, 5, 60);
	p.free_nodes = uni_int(g, 0, 3);
	p.step_time = uni(g, 1, 100);
	p.sweep = uni(g, 0.1, fmin(30, 45 / p.step_time));
	p.twining = twining ? VINE_RIGHT : VINE_LEFT;
	p.leaves_per_node = uni_int(g, 0, 2);
	p.cotyledons = uni_int(g, 0, 2);
	p.ring_sides = uni_int(g, 3, 16);
	p.internodes = uni_int(g, 8, 360 / p.points_per_internode);
	p.seed = rng_next(g);
	CHECK_INT(vine_params_check(&p, &key, &err), 0);
	return p;
}

/* A random direction within `tilt` of d. */
static struct vec3 tilted(struct rng *g, struct vec3 d, double tilt)
{
	struct vec3 e1 = vec3_norm_or(vec3_cross(d, vec3(0.3, 0.1, 1)), vec3(1, 0, 0));
	struct vec3 e2 = vec3_cross(d, e1);
	double a = uni(g, 0, 2 * VEC_PI), t = uni(g, 0, tilt);

	return vec3_add(vec3_scale(d, cos(t)),
			vec3_scale(vec3_add(vec3_scale(e1, cos(a)), vec3_scale(e2, sin(a))), sin(t)));
}

/* A random prism or box across u from o, at least `thick` across. */
static void random_piece(struct rng *g, struct solid *s, struct vec3 o, struct vec3 u, double h,
			 double thick)
{
	double R = uni(g, thick, thick + 0.04), phase = uni(g, 0, 2 * VEC_PI);

	if (rng_uniform(g) < 0.4)
		box_piece(s, R, uni(g, thick, R + 0.02), o, u, h, phase);
	else
		cylinder_piece(s, R, uni_int(g, 5, 32), o, u, h, phase);
}

/*
 * Support k: a post (leaning up to 25 degrees) and one to three more pieces meeting it (or
 * each other) at junctions: through it (a cross), from it (a fork), across its top (a T),
 * at any angle. Every piece at least half an axis segment thick (so the raw axis, a point
 * every l/d, cannot step through one) and 3 mm.
 */
static void random_support(struct rng *g, struct solid *s, const struct vine_params *p)
{
	double seg = p->internode / p->points_per_internode;
	double thick = fmax(fmax(0.5 * seg, 0.5 * p->radius), 0.003);
	double H = uni(g, 0.3, 1.2);
	struct vec3 up = tilted(g, UP, 25 * DEG), axis[MAX_PIECES], base[MAX_PIECES];
	double len[MAX_PIECES];
	int n = uni_int(g, 2, 4);

	random_piece(g, s, vec3(0, 0, 0), up, H, thick);
	axis[0] = up;
	base[0] = vec3(0, 0, 0);
	len[0] = H;
	for (int k = 1; k < n; k++) {
		int on = uni_int(g, 0, k - 1);
		double at = rng_uniform(g) < 0.3 ? len[on] : uni(g, 0.3, 1.0) * len[on];
		struct vec3 j = vec3_add(base[on], vec3_scale(axis[on], at));
		struct vec3 u = rng_uniform(g) < 0.5 ? tilted(g, ALONG_X, VEC_PI) :
						       tilted(g, vec3(0.7, 0.7, 0), 50 * DEG);
		double h = uni(g, 0.1, 0.6), from = rng_uniform(g) < 0.5 ? -0.5 * h : -0.1 * h;

		u = vec3_norm_or(u, ALONG_X);
		base[k] = vec3_add(j, vec3_scale(u, from));
		axis[k] = u;
		len[k] = h;
		random_piece(g, s, base[k], u, h, thick);
	}
}

/* A planting point by the post's foot: outside the support, r to 4 r from it. */
static struct vec3 random_plant(struct rng *g, const struct solid *s, double r)
{
	for (int tries = 0; tries < 1000; tries++) {
		double a = uni(g, 0, 2 * VEC_PI), x = uni(g, 0.003, 0.12);
		struct vec3 q = vec3(x * cos(a), 0, x * sin(a));
		double d = solid_dist(s, q, 5 * r);

		if (d >= r * 1.0001 && d < 4 * r && !solid_inside(s, q, 0))
			return q;
	}
	CHECK(!"no planting point found");
	return vec3(0, 0, 0);
}

static void test_random(int count)
{
	struct margins m;
	size_t touched = 0;

	margins_init(&m);
	for (int k = 0; k < count; k++) {
		struct rng g;
		struct solid s = { 0 };
		struct vine_support *vs;
		struct vine_params p;
		struct vec3 plant;
		struct vine v;
		char name[64];

		rng_seed(&g, 0x5EED0000u + (uint64_t)k);
		p = random_params(&g, k % 2);
		random_support(&g, &s, &p);
		plant = random_plant(&g, &s, p.radius);
		vs = support_of_solid(&s);
		snprintf(name, sizeof(name), "random support %d (%s)", k,
			 p.twining == VINE_RIGHT ? "right" : "left");
		vine_init(&v, &p, plant);
		CHECK_INT(vine_grow(&v, vs, INFINITY), 0);
		check_vine(&v, &s, name, &m);
		for (size_t j = 0; j < v.nshoots; j++) {
			bool any = false;

			for (size_t i = 0; i < v.shoots[j].n; i++)
				any = any || v.shoots[j].contact[i];
			touched += any;
			if (any)
				break;
		}
		vine_finish(&v);
		vine_support_destroy(vs);
		solid_finish(&s);
	}
	printf("random supports: %d, their vines touching in %zu\n", count, touched);
	CHECK(touched > (size_t)count / 2); /* most found their support: the test bites */
	margins_print("random supports", &m);
}

int main(void)
{
	test_named();
	test_drawn_tree();
	test_grown_tree();
	test_random(300);
	return 0;
}
