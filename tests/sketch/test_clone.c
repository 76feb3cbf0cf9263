/* SPDX-License-Identifier: MIT */
/*
 * Cloning (src/sketch/clone.c, seed 000 sections 3.4 and 4.4), checked against rules computed
 * here on their own: the turtle frame (head = the parent's tangent, up = world up made
 * perpendicular, +z when head is vertical), the widest gap between neighbouring children,
 * interpolation from that pair, rotation as far as allowed from the other children (over
 * the full circle on a parent within 30 degrees of the vertical, within 120 degrees of up
 * on an inclined one), a sibling's shape in its own chord frame; determinism; and
 * clone_remove giving back the tree exactly. On hand-built trees and on a lifted drawing.
 */
#include <errno.h>
#include <string.h>

#include "app.h"
#include "clone.h"
#include "pen.h"
#include "test.h"

#define MAXK 256
#define DEG (VEC_PI / 180.0)
#define EPS 1e-9

/* ---- the rules, computed here ---- */

struct turtle {
	struct vec3 origin, head, up, left;
};

static struct vec3 point_at(const struct branch *b, double t)
{
	size_t seg;
	double s;

	if (b->npoints < 2)
		return b->points[0];
	tree_locate(b, t, &seg, &s);
	return vec3_lerp(b->points[seg], b->points[seg + 1], s);
}

static struct turtle turtle(const struct branch *b, double t)
{
	struct turtle tu = { .origin = point_at(b, t), .head = vec3(0, 1, 0) };
	struct vec3 up;

	if (b->npoints >= 2 && tree_branch_length(b) > 0)
		tu.head = tree_frame_at(b, t).tangent;
	up = vec3_sub(vec3(0, 1, 0), vec3_scale(tu.head, tu.head.y));
	if (vec3_len(up) < 1e-9)
		up = vec3(0, 0, 1); /* head vertical: the documented fallback */
	tu.up = vec3_scale(up, 1.0 / vec3_len(up));
	tu.left = vec3_cross(tu.up, tu.head);
	return tu;
}

static struct vec3 chord_dir(const struct branch *b)
{
	struct vec3 c = vec3_sub(b->points[b->npoints - 1], b->points[0]);

	return vec3_scale(c, 1.0 / vec3_len(c));
}

static double down_of(const struct tree *t, const struct branch *c)
{
	struct turtle tu = turtle(&t->branches[c->parent], c->parent_t);

	return acos(fmax(-1.0, fmin(1.0, vec3_dot(chord_dir(c), tu.head))));
}

static double rot_of(const struct tree *t, const struct branch *c)
{
	struct turtle tu = turtle(&t->branches[c->parent], c->parent_t);
	struct vec3 d = chord_dir(c);

	return atan2(vec3_dot(d, tu.left), vec3_dot(d, tu.up));
}

static double angle_dist(double a, double b)
{
	double d = fmod(fabs(a - b), 2 * VEC_PI);

	return d > VEC_PI ? 2 * VEC_PI - d : d;
}

static double clearance(const double *rot, size_t m, double phi)
{
	double d = HUGE_VAL;

	for (size_t i = 0; i < m; i++)
		d = fmin(d, angle_dist(phi, rot[i]));
	return d;
}

/* How far the farthest direction around the parent (the full circle, 0.25 degree steps)
 * is from the nearest of m rotation angles. */
static double worst_clearance(const double *rot, size_t m)
{
	double worst = 0;

	for (double g = -180; g <= 180; g += 0.25)
		worst = fmax(worst, clearance(rot, m, g * DEG));
	return worst;
}

/* Upright: the head within 30 degrees of the vertical line (pointing up or down). */
static bool upright_at(const struct tree *t, int parent, double pt)
{
	struct vec3 h = turtle(&t->branches[parent], pt).head;

	return acos(fmin(1.0, fabs(h.y))) <= 30 * DEG;
}

/* Which rule check_add saw, so a test can tell it exercised the one it means to. */
static size_t nupright, ninclined;

/*
 * The new rotation phi against the n others: on an upright parent no angle on the full
 * circle is farther from them, on an inclined one phi is within 120 degrees of up and no
 * angle there is farther; the middle of the widest angular gap when that is allowed (and
 * clearly the widest).
 */
static void check_rotation(const double *rot, size_t n, double phi, bool upright)
{
	double lim = upright ? 180 : 120, best = -1, mid = 0, second = -1;

	if (upright) {
		nupright++;
	} else {
		ninclined++;
		CHECK(fabs(phi) <= CLONE_MAX_ROTATION_DEG * DEG + EPS);
		CHECK(fabs(phi) <= 120 * DEG + EPS);
	}
	for (double g = -lim; g <= lim; g += 0.05)
		CHECK(clearance(rot, n, g * DEG) <= clearance(rot, n, phi) + EPS);
	for (size_t i = 0; i < n; i++) {
		double lo = rot[i], hi = HUGE_VAL;

		for (size_t j = 0; j < n; j++) {
			double d = fmod(rot[j] - lo + 4 * VEC_PI, 2 * VEC_PI);

			if (j != i && d > 0 && lo + d < hi)
				hi = lo + d;
		}
		if (hi == HUGE_VAL)
			hi = lo + 2 * VEC_PI;
		if (hi - lo > best) {
			second = best;
			best = hi - lo;
			mid = remainder(lo + 0.5 * (hi - lo), 2 * VEC_PI);
		} else if (hi - lo > second) {
			second = hi - lo;
		}
	}
	if ((upright || fabs(mid) <= 120 * DEG) && best - second > 1e-6)
		CHECK_NEAR(angle_dist(phi, mid), 0, EPS);
}

/* parent's children (ids) in parent_t order */
static size_t kids(const struct tree *t, int parent, int *out)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent == parent) {
			size_t k = n++;

			CHECK(n <= MAXK);
			while (k > 0 && t->branches[out[k - 1]].parent_t > t->branches[i].parent_t) {
				out[k] = out[k - 1];
				k--;
			}
			out[k] = (int)i;
		}
	return n;
}

/* The farthest-apart neighbours; one child pairs with the end leaving the larger gap. */
struct pair {
	int a, b;
	double ta, tb;
};

static struct pair widest(const struct tree *t, int parent)
{
	int k[MAXK];
	size_t n = kids(t, parent, k);
	struct pair p = { k[0], k[0], 0, 0 };
	double gap = -1;

	CHECK(n > 0);
	if (n == 1) {
		double c = t->branches[k[0]].parent_t;

		p.ta = c > 0.5 ? 0.0 : c;
		p.tb = c > 0.5 ? c : 1.0;
		return p;
	}
	for (size_t i = 0; i + 1 < n; i++) {
		double ta = t->branches[k[i]].parent_t, tb = t->branches[k[i + 1]].parent_t;

		if (tb - ta > gap) {
			gap = tb - ta;
			p = (struct pair){ k[i], k[i + 1], ta, tb };
		}
	}
	return p;
}

static bool between(double x, double a, double b, double eps)
{
	return x >= fmin(a, b) - eps && x <= fmax(a, b) + eps;
}

/* Local coordinates of b's points in its chord frame (x chord, y head made perpendicular). */
static void chord_local(const struct tree *t, const struct branch *b, size_t i, double out[3])
{
	struct turtle tu = turtle(&t->branches[b->parent], b->parent_t);
	struct vec3 x = chord_dir(b), y, z, v = vec3_sub(b->points[i], b->points[0]);

	y = vec3_sub(tu.head, vec3_scale(x, vec3_dot(tu.head, x)));
	y = vec3_len(y) > 1e-12 ? vec3_scale(y, 1.0 / vec3_len(y)) : tu.up;
	z = vec3_cross(x, y);
	out[0] = vec3_dot(v, x);
	out[1] = vec3_dot(v, y);
	out[2] = vec3_dot(v, z);
}

/* c is sibling s scaled and carried over: same points in its chord frame, radii scaled. */
static bool same_shape(const struct tree *t, const struct branch *c, const struct branch *s)
{
	double k = tree_branch_length(c) / tree_branch_length(s);
	double kr = c->radii[0] / s->radii[0];

	if (c->npoints != s->npoints)
		return false;
	for (size_t i = 0; i < c->npoints; i++) {
		double lc[3], ls[3];

		chord_local(t, c, i, lc);
		chord_local(t, s, i, ls);
		for (int j = 0; j < 3; j++)
			if (fabs(lc[j] - k * ls[j]) > EPS)
				return false;
		if (fabs(c->radii[i] - kr * s->radii[i]) > 1e-12)
			return false;
	}
	return true;
}

static bool finite_branch(const struct branch *b)
{
	for (size_t i = 0; i < b->npoints; i++)
		if (!isfinite(b->points[i].x) || !isfinite(b->points[i].y) ||
		    !isfinite(b->points[i].z) || !isfinite(b->radii[i]))
			return false;
	return true;
}

/*
 * One clone_add on parent, checked against everything the rules say. Returns its id.
 * All children of the parent have directions here.
 */
static int check_add(struct tree *t, int parent, struct rng *rng)
{
	int k[MAXK], id;
	size_t n = kids(t, parent, k), before = t->nbranches;
	struct pair p = widest(t, parent);
	const struct branch *a, *b, *c;
	double rot[MAXK], la, lb, da, db, len, down;
	struct turtle tu;

	for (size_t i = 0; i < n; i++)
		rot[i] = rot_of(t, &t->branches[k[i]]);
	a = &t->branches[p.a];
	b = &t->branches[p.b];
	la = tree_branch_length(a);
	lb = tree_branch_length(b);
	da = down_of(t, a);
	db = down_of(t, b);

	id = clone_add(t, parent, rng);
	CHECK_INT(id, before);
	CHECK_INT(t->nbranches, before + 1);
	c = &t->branches[id];
	a = &t->branches[p.a]; /* t->branches may have moved */
	b = &t->branches[p.b];
	CHECK_INT(c->id, id);
	CHECK_INT(c->parent, parent);
	CHECK_INT(c->origin, ORIGIN_CLONE);
	CHECK_INT(c->generation, t->branches[parent].generation + 1);
	CHECK(c->npoints >= 2 && finite_branch(c));

	/* where: strictly inside the widest gap, its root on the parent */
	CHECK(c->parent_t > p.ta && c->parent_t < p.tb);
	CHECK_NEAR(c->parent_t, 0.5 * (p.ta + p.tb), 1e-12);
	CHECK_NEAR(vec3_dist(c->points[0], point_at(&t->branches[parent], c->parent_t)), 0, EPS);

	/* length, root radius and down angle from the pair (at the middle: the mean) */
	len = tree_branch_length(c);
	CHECK(between(len, la, lb, EPS));
	CHECK_NEAR(len, 0.5 * (la + lb), EPS);
	CHECK_NEAR(c->radii[0], 0.5 * (a->radii[0] + b->radii[0]), 1e-12);
	down = down_of(t, c);
	CHECK(between(down, da, db, EPS));
	CHECK_NEAR(down, 0.5 * (da + db), EPS);

	/* rotation: the full circle on an upright parent, within 120 degrees of up otherwise */
	check_rotation(rot, n, rot_of(t, c), upright_at(t, parent, c->parent_t));

	/* shape: one of the siblings, in its chord frame, scaled */
	tu = turtle(&t->branches[parent], c->parent_t);
	CHECK_NEAR(vec3_dot(chord_dir(c), tu.head), cos(down), EPS);
	{
		bool found = false;

		for (size_t i = 0; i < n && !found; i++)
			found = same_shape(t, c, &t->branches[k[i]]);
		CHECK(found);
	}
	return id;
}

/* ---- trees ---- */

static void copy_tree(struct tree *dst, const struct tree *src)
{
	tree_init(dst);
	for (size_t i = 0; i < src->nbranches; i++) {
		const struct branch *b = &src->branches[i];

		CHECK_INT(tree_add_branch(dst, b->parent, b->parent_t, b->origin, b->points, b->radii,
					  b->npoints),
			  i);
		dst->branches[i].generation = b->generation;
	}
	for (size_t i = 0; i < src->nleaves; i++) {
		const struct leaf *l = &src->leaves[i];

		CHECK_INT(tree_add_leaf(dst, l->branch, l->origin, l->points, l->npoints), i);
		dst->leaves[i].branch_t = l->branch_t;
	}
	dst->lifted = src->lifted;
}

/* Bit for bit: ids, parents, parameters, points, radii, leaves. */
static void check_same_tree(const struct tree *a, const struct tree *b)
{
	CHECK_INT(a->nbranches, b->nbranches);
	CHECK_INT(a->nleaves, b->nleaves);
	CHECK(a->lifted == b->lifted);
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->parent, y->parent);
		CHECK(x->parent_t == y->parent_t);
		CHECK_INT(x->generation, y->generation);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
		CHECK(memcmp(x->radii, y->radii, x->npoints * sizeof(*x->radii)) == 0);
	}
	for (size_t i = 0; i < a->nleaves; i++) {
		const struct leaf *x = &a->leaves[i], *y = &b->leaves[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->branch, y->branch);
		CHECK(x->branch_t == y->branch_t);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
	}
}

/* A child of `parent` at parameter pt, leaving at down angle `down` and rotation `rot`
 * (degrees, in the turtle frame there), bent by `bend` x its length sideways and down. */
static int add_child(struct tree *t, int parent, double pt, double rot, double down, double len,
		     double bend, double r0, size_t n)
{
	struct turtle tu = turtle(&t->branches[parent], pt);
	struct vec3 d, y, z, pts[32];
	double radii[32];
	int id;

	CHECK(n >= 2 && n <= 32);
	d = vec3_add(vec3_scale(tu.head, cos(down * DEG)),
		     vec3_scale(vec3_add(vec3_scale(tu.up, cos(rot * DEG)),
					 vec3_scale(tu.left, sin(rot * DEG))),
				sin(down * DEG)));
	y = vec3_sub(vec3(0, 1, 0), vec3_scale(d, d.y));
	y = vec3_len(y) > 1e-9 ? vec3_scale(y, 1.0 / vec3_len(y)) : tu.up;
	z = vec3_cross(d, y);
	for (size_t i = 0; i < n; i++) {
		double s = (double)i / (double)(n - 1), arch = sin(VEC_PI * s) * bend * len;

		/* the arch vanishes at both ends: the chord is d x len */
		pts[i] = vec3_add(tu.origin, vec3_add(vec3_scale(d, s * len),
						      vec3_add(vec3_scale(y, -arch),
							       vec3_scale(z, 0.4 * arch * s))));
		radii[i] = r0 * (1.0 - 0.8 * s);
	}
	id = tree_add_branch(t, parent, pt, ORIGIN_SKETCH, pts, radii, n);
	CHECK(id >= 0);
	return id;
}

static int add_trunk(struct tree *t, bool vertical)
{
	struct vec3 pts[13];
	double radii[13];

	for (int i = 0; i < 13; i++) {
		double y = 0.5 * i;

		pts[i] = vertical ? vec3(0.3, y, -0.2)
				  : vec3(0.05 * sin(1.3 * y), y, 0.04 * y * y / 6.0);
		radii[i] = 0.2 - 0.013 * i;
	}
	return tree_add_branch(t, -1, 0, ORIGIN_SKETCH, pts, radii, 13);
}

/* A straight trunk from the origin, 6 long, leaning `lean` degrees from world up towards
 * azimuth `az` (degrees about world up from +x towards -z); 180 hangs straight down. */
static int add_straight_trunk(struct tree *t, double lean, double az)
{
	struct vec3 d = vec3(sin(lean * DEG) * cos(az * DEG), cos(lean * DEG),
			     -sin(lean * DEG) * sin(az * DEG));
	struct vec3 pts[13];
	double radii[13];

	for (int i = 0; i < 13; i++) {
		pts[i] = vec3_scale(d, 0.5 * i);
		radii[i] = 0.2 - 0.013 * i;
	}
	return tree_add_branch(t, -1, 0, ORIGIN_SKETCH, pts, radii, 13);
}

/* Five children at uneven gaps all round trunk 0 (1..5), child 2 tilted with three
 * children of its own (6..8), a leaf on child 1. */
static void conifer_children(struct tree *t)
{
	static const double pt[] = { 0.12, 0.3, 0.41, 0.66, 0.9 };
	static const double rot[] = { 10, 100, -80, 170, -150 };
	static const double down[] = { 70, 60, 55, 45, 35 };
	static const double len[] = { 2.2, 1.9, 1.6, 1.2, 0.7 };
	const struct vec3 leaf[] = { vec3(1, 4, 0), vec3(1.1, 4.2, 0), vec3(0.9, 4.2, 0.1) };

	for (int i = 0; i < 5; i++)
		CHECK_INT(add_child(t, 0, pt[i], rot[i], down[i], len[i], 0.1 + 0.03 * i,
				    0.08 - 0.01 * i, (size_t)(4 + i)),
			  i + 1);
	CHECK_INT(add_child(t, 2, 0.2, 40, 50, 0.6, 0.05, 0.03, 5), 6);
	CHECK_INT(add_child(t, 2, 0.5, -60, 40, 0.5, 0.15, 0.025, 6), 7);
	CHECK_INT(add_child(t, 2, 0.8, 150, 65, 0.3, 0.2, 0.02, 7), 8);
	CHECK_INT(tree_add_leaf(t, 1, ORIGIN_SKETCH, leaf, 3), 0);
	t->leaves[0].branch_t = 0.5;
	t->lifted = true;
}

/* A drawn trunk (0), slightly bent and leaning by a few degrees (upright), or a straight
 * vertical one, with conifer_children. */
static void conifer(struct tree *t, bool vertical)
{
	tree_init(t);
	CHECK_INT(add_trunk(t, vertical), 0);
	conifer_children(t);
}

/* n checked adds on parent, then n removes back to the tree it started as. */
static void adds_then_removes(struct tree *t, int parent, uint64_t seed, int n)
{
	struct tree orig;
	struct rng rng;
	int kids_before[MAXK];
	size_t nk = kids(t, parent, kids_before);

	copy_tree(&orig, t);
	rng_seed(&rng, seed);
	for (int i = 0; i < n; i++)
		CHECK_INT(check_add(t, parent, &rng), orig.nbranches + (size_t)i);
	{
		int k[MAXK];

		CHECK_INT(kids(t, parent, k), nk + (size_t)n);
	}
	for (int i = n - 1; i >= 0; i--)
		CHECK_INT(clone_remove(t, parent), orig.nbranches + (size_t)i);
	check_same_tree(t, &orig);
	tree_finish(&orig);
}

/* ---- tests ---- */

static void test_turtle_frame(void)
{
	struct tree t;
	struct clone_turtle c;
	struct turtle m;

	conifer(&t, false);
	for (size_t b = 0; b < 3; b++)
		for (double u = 0; u <= 1.0; u += 0.125) {
			c = clone_turtle_at(&t.branches[b], u);
			m = turtle(&t.branches[b], u);
			CHECK_NEAR(vec3_dist(c.origin, m.origin), 0, 1e-12);
			CHECK_NEAR(vec3_dist(c.head, m.head), 0, 1e-12);
			CHECK_NEAR(vec3_dist(c.up, m.up), 0, 1e-12);
			CHECK_NEAR(vec3_dist(c.left, m.left), 0, 1e-12);
			/* head x left = up (the L-system turtle) and up leans to world up */
			CHECK_NEAR(vec3_dist(vec3_cross(c.head, c.left), c.up), 0, 1e-12);
			CHECK(c.up.y > 0);
		}
	tree_finish(&t);
	/* a vertical head: up is world +z */
	conifer(&t, true);
	c = clone_turtle_at(&t.branches[0], 0.4);
	CHECK(c.head.x == 0 && c.head.y == 1 && c.head.z == 0);
	CHECK(c.up.x == 0 && c.up.y == 0 && c.up.z == 1);
	tree_finish(&t);
}

static void test_trunk_ten(void)
{
	struct tree t;

	conifer(&t, false);
	adds_then_removes(&t, 0, 1, 10);
	adds_then_removes(&t, 0, 99, 10);
	tree_finish(&t);
}

/* A tilted parent: the world up made perpendicular to it is its upper side. */
static void test_branch_ten(void)
{
	struct tree t;
	size_t up0 = nupright, in0 = ninclined;

	conifer(&t, false);
	CHECK(fabs(clone_turtle_at(&t.branches[2], 0.5).head.y) < 0.9);
	adds_then_removes(&t, 2, 5, 10);
	/* every add on it kept within 120 degrees of up */
	CHECK_INT(nupright, up0);
	CHECK_INT(ninclined, in0 + 10);
	tree_finish(&t);
}

/*
 * An upright trunk: up is world +z (vertical) or the horizontal direction of the lean, so
 * a 120-degree window about it would leave a wedge of the trunk bare for good. Each add
 * takes the middle of the widest angular gap over the full circle; after 60 no direction
 * round the trunk is more than 5 degrees from a child, and some clones turn more than
 * 120 degrees from up.
 */
static void upright_spread(struct tree *t, uint64_t seed)
{
	struct rng rng;
	int k[MAXK];
	double rot[MAXK];
	size_t n, up0 = nupright, in0 = ninclined, beyond = 0;

	adds_then_removes(t, 0, seed, 10);
	CHECK_INT(nupright, up0 + 10);
	CHECK_INT(ninclined, in0);
	rng_seed(&rng, seed);
	for (int i = 0; i < 60; i++) {
		int id = check_add(t, 0, &rng); /* before indexing: t->branches may move */

		beyond += fabs(rot_of(t, &t->branches[id])) > 120 * DEG + 1e-6;
	}
	CHECK(beyond > 0);
	n = kids(t, 0, k);
	CHECK_INT(n, 65);
	for (size_t i = 0; i < n; i++)
		rot[i] = rot_of(t, &t->branches[k[i]]);
	CHECK(worst_clearance(rot, n) < 5 * DEG);
}

static void test_vertical_trunk(void)
{
	struct tree t;

	conifer(&t, true);
	CHECK(clone_turtle_at(&t.branches[0], 0.5).up.z == 1); /* the +z fallback */
	upright_spread(&t, 3);
	tree_finish(&t);
}

static void test_leaning_trunk(void)
{
	struct tree t;

	tree_init(&t);
	CHECK_INT(add_straight_trunk(&t, 10, 40), 0);
	conifer_children(&t);
	/* up is the lean's horizontal direction, turned up by 10 degrees */
	CHECK_NEAR(clone_turtle_at(&t.branches[0], 0.5).up.y, sin(10 * DEG), 1e-12);
	upright_spread(&t, 4);
	tree_finish(&t);
}

/*
 * The 30 degrees: one child at rotation 30 on a straight parent; the clone goes opposite
 * it (-150) within 30 degrees of the vertical line, up or down, and to the nearest
 * allowed angle (-120) beyond.
 */
static void test_upright_limit(void)
{
	static const double lean[] = { 0, 10, 29, 31, 45, 90, 135, 149, 151, 170, 180 };

	CHECK(CLONE_UPRIGHT_DEG == 30.0);
	for (size_t i = 0; i < sizeof(lean) / sizeof(lean[0]); i++) {
		bool upright = lean[i] < 30 || lean[i] > 150;
		struct tree t;
		struct rng rng;
		int id;

		tree_init(&t);
		CHECK_INT(add_straight_trunk(&t, lean[i], 70), 0);
		CHECK_INT(add_child(&t, 0, 0.3, 30, 60, 1.5, 0.1, 0.05, 5), 1);
		CHECK(upright_at(&t, 0, 0.65) == upright);
		rng_seed(&rng, 1);
		id = check_add(&t, 0, &rng);
		CHECK_NEAR(rot_of(&t, &t.branches[id]), (upright ? -150 : -120) * DEG, EPS);
		tree_finish(&t);
	}
}

/* Many more: every add still keeps to the rules and the spread keeps filling in. */
static void test_many(void)
{
	struct tree t;
	struct rng rng;
	int k[MAXK];
	double rot[MAXK], worst = 0;
	size_t n;

	conifer(&t, false);
	rng_seed(&rng, 7);
	for (int i = 0; i < 60; i++)
		check_add(&t, 0, &rng);
	n = kids(&t, 0, k);
	CHECK_INT(n, 65);
	for (size_t i = 0; i < n; i++)
		rot[i] = rot_of(&t, &t.branches[k[i]]);
	/* the drawn trunk is upright: no rotation is more than 10 degrees from some child */
	worst = worst_clearance(rot, n);
	CHECK(worst < 10 * DEG);
	/* the new ones stay within the span of the children there were */
	for (size_t i = 9; i < t.nbranches; i++)
		if (t.branches[i].parent == 0)
			CHECK(t.branches[i].parent_t > 0.12 && t.branches[i].parent_t < 0.9);
	tree_finish(&t);
}

static void test_determinism(void)
{
	struct tree a, b, c;
	struct rng ra, rb, rc;
	bool differ = false;

	conifer(&a, false);
	conifer(&b, false);
	conifer(&c, false);
	rng_seed(&ra, 42);
	rng_seed(&rb, 42);
	rng_seed(&rc, 43);
	for (int i = 0; i < 10; i++) {
		CHECK(clone_add(&a, 0, &ra) >= 0);
		CHECK(clone_add(&b, 0, &rb) >= 0);
		CHECK(clone_add(&c, 0, &rc) >= 0);
	}
	check_same_tree(&a, &b);
	/* the seed picks the shapes: another seed, other shapes, same places */
	for (size_t i = 9; i < a.nbranches; i++) {
		CHECK(a.branches[i].parent_t == c.branches[i].parent_t);
		differ |= a.branches[i].npoints != c.branches[i].npoints;
	}
	CHECK(differ);
	tree_finish(&a);
	tree_finish(&b);
	tree_finish(&c);
}

/* One child: paired with the end of the parent that leaves the larger gap (the tip on a
 * tie), which stands in as a copy of it. */
static void test_single_child(void)
{
	static const double at[] = { 0.3, 0.8, 0.5 }, want[] = { 0.65, 0.4, 0.75 };

	for (int i = 0; i < 3; i++) {
		struct tree t;
		struct rng rng;
		int id;

		tree_init(&t);
		CHECK_INT(add_trunk(&t, false), 0);
		CHECK_INT(add_child(&t, 0, at[i], 30, 60, 1.5, 0.1, 0.05, 5), 1);
		rng_seed(&rng, 1);
		id = check_add(&t, 0, &rng);
		CHECK_NEAR(t.branches[id].parent_t, want[i], 1e-15);
		CHECK_NEAR(tree_branch_length(&t.branches[id]), tree_branch_length(&t.branches[1]),
			   1e-12);
		/* the drawn trunk is upright: opposite the child, 210 degrees from up */
		CHECK_NEAR(rot_of(&t, &t.branches[id]), -150 * DEG, EPS);
		adds_then_removes(&t, 0, 2, 10);
		tree_finish(&t);
	}
}

static void test_enoent(void)
{
	struct tree t;
	struct rng rng;
	const struct vec3 one = vec3(0.1, 1, 0);
	const double r = 0.02;
	size_t n;

	rng_seed(&rng, 1);
	tree_init(&t);
	CHECK_INT(clone_add(&t, 0, &rng), -ENOENT);
	CHECK_INT(clone_remove(&t, 0), -ENOENT);
	conifer(&t, false);
	n = t.nbranches;
	CHECK_INT(clone_add(&t, -1, &rng), -ENOENT);
	CHECK_INT(clone_add(&t, (int)n, &rng), -ENOENT);
	CHECK_INT(clone_add(&t, 7, &rng), -ENOENT); /* no children */
	CHECK_INT(clone_remove(&t, -1), -ENOENT);
	CHECK_INT(clone_remove(&t, (int)n), -ENOENT);
	CHECK_INT(clone_remove(&t, 7), -ENOENT);
	CHECK_INT(t.nbranches, n);
	/* a parent whose only child is one point: nothing to learn a shape from */
	CHECK_INT(tree_add_branch(&t, 7, 0.5, ORIGIN_SKETCH, &one, &r, 1), (int)n);
	CHECK_INT(clone_add(&t, 7, &rng), -ENOENT);
	CHECK_INT(t.nbranches, n + 1);
	CHECK_INT(clone_remove(&t, 7), (int)n);
	CHECK_INT(t.nbranches, n);
	CHECK_INT(clone_remove(&t, 0), 5);
	CHECK_INT(t.nbranches, n - 1);
	CHECK_INT(clone_remove(&t, 0), 4);
	CHECK_INT(clone_remove(&t, 0), 3);
	/* the newest child left is 2: its three children go with it */
	CHECK_INT(clone_remove(&t, 0), 2);
	CHECK_INT(t.nbranches, 2); /* trunk and child 1 */
	CHECK_INT(t.nleaves, 1);
	CHECK_INT(clone_remove(&t, 0), 1);
	CHECK_INT(t.nleaves, 0);
	CHECK_INT(clone_remove(&t, 0), -ENOENT);
	CHECK_INT(clone_add(&t, 0, &rng), -ENOENT);
	tree_finish(&t);
}

/* Zero-length and one-point parents, one-point and overlapping children: no crash, no
 * NaN, the root on the parent. */
static void test_degenerate(void)
{
	struct tree t;
	struct rng rng;
	const struct vec3 still[] = { vec3(1, 2, 3), vec3(1, 2, 3), vec3(1, 2, 3) };
	const struct vec3 kid[] = { vec3(1, 2, 3), vec3(1.5, 2.5, 3), vec3(2, 2.7, 3.2) };
	const struct vec3 kid2[] = { vec3(1, 2, 3), vec3(0.4, 2.6, 2.9) };
	const double radii[] = { 0.1, 0.08, 0.05 };
	int id;

	rng_seed(&rng, 11);
	/* a zero-length parent: head is world up, up is +z */
	tree_init(&t);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, still, radii, 3), 0);
	CHECK_INT(tree_add_branch(&t, 0, 0.2, ORIGIN_SKETCH, kid, radii, 3), 1);
	CHECK_INT(tree_add_branch(&t, 0, 0.7, ORIGIN_SKETCH, kid2, radii, 2), 2);
	for (int i = 0; i < 5; i++) {
		int k[MAXK];
		double rot[MAXK];
		size_t n = kids(&t, 0, k);

		for (size_t j = 0; j < n; j++)
			rot[j] = rot_of(&t, &t.branches[k[j]]);
		id = clone_add(&t, 0, &rng);
		CHECK(id >= 3);
		CHECK(finite_branch(&t.branches[id]));
		CHECK(memcmp(&t.branches[id].points[0], &still[0], sizeof(still[0])) == 0);
		/* its head is world up: upright, the full circle */
		CHECK(upright_at(&t, 0, t.branches[id].parent_t));
		check_rotation(rot, n, rot_of(&t, &t.branches[id]), true);
	}
	tree_finish(&t);

	/* a one-point parent */
	tree_init(&t);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, still, radii, 1), 0);
	CHECK_INT(tree_add_branch(&t, 0, 0.0, ORIGIN_SKETCH, kid, radii, 3), 1);
	id = clone_add(&t, 0, &rng);
	CHECK_INT(id, 2);
	CHECK(finite_branch(&t.branches[id]));
	CHECK(memcmp(&t.branches[id].points[0], &still[0], sizeof(still[0])) == 0);
	tree_finish(&t);

	/* a one-point child paired with a real one: length interpolated from 0, down angle
	 * and shape from the real one */
	tree_init(&t);
	CHECK_INT(add_trunk(&t, false), 0);
	CHECK_INT(add_child(&t, 0, 0.1, 20, 50, 1.0, 0.1, 0.05, 5), 1);
	CHECK_INT(tree_add_branch(&t, 0, 0.9, ORIGIN_SKETCH, &t.branches[0].points[10], radii, 1), 2);
	id = clone_add(&t, 0, &rng);
	CHECK(id == 3 && finite_branch(&t.branches[id]));
	CHECK_NEAR(t.branches[id].parent_t, 0.5, 1e-15);
	CHECK_NEAR(tree_branch_length(&t.branches[id]), 0.5 * tree_branch_length(&t.branches[1]), EPS);
	CHECK_NEAR(down_of(&t, &t.branches[id]), down_of(&t, &t.branches[1]), EPS);
	CHECK(same_shape(&t, &t.branches[id], &t.branches[1]));
	tree_finish(&t);

	/* children at the same parameter: the clone goes there too */
	conifer(&t, false);
	CHECK_INT(add_child(&t, 6, 0.5, 0, 40, 0.2, 0.1, 0.01, 4), 9);
	CHECK_INT(add_child(&t, 6, 0.5, 90, 40, 0.3, 0.1, 0.01, 4), 10);
	id = clone_add(&t, 6, &rng);
	CHECK(id == 11 && finite_branch(&t.branches[id]));
	CHECK(t.branches[id].parent_t == 0.5);
	CHECK_NEAR(tree_branch_length(&t.branches[id]),
		   0.5 * (tree_branch_length(&t.branches[9]) + tree_branch_length(&t.branches[10])), EPS);
	/* a child running along its parent's head has no rotation angle: the clone is
	 * placed by the others */
	{
		struct clone_turtle tu = clone_turtle_at(&t.branches[8], 0.5);
		struct vec3 along[] = { tu.origin, vec3_add(tu.origin, vec3_scale(tu.head, 0.3)) };

		CHECK_INT(tree_add_branch(&t, 8, 0.5, ORIGIN_SKETCH, along, radii, 2), 12);
		CHECK_INT(add_child(&t, 8, 0.1, 60, 40, 0.2, 0.1, 0.01, 4), 13);
		id = clone_add(&t, 8, &rng);
		CHECK(id == 14 && finite_branch(&t.branches[id]));
		CHECK_NEAR(t.branches[id].parent_t, 0.3, 1e-15);
		CHECK_NEAR(down_of(&t, &t.branches[id]), 20 * DEG, EPS);
		CHECK_NEAR(rot_of(&t, &t.branches[id]), -120 * DEG, EPS);
	}
	tree_finish(&t);
}

/* ---- through the app: a drawing lifted with the 3D button ---- */

/* 10 motion events a line; a pause after each: no two strokes are one branch's outlines */
static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

static void test_lifted_drawing(void)
{
	struct app *app = app_create(1280, 800, 7);
	struct tree t;
	int k[MAXK];

	CHECK(app);
	pen_line(&pen, app, 560, 736, 560, 236);
	pen_line(&pen, app, 560, 536, 800, 400);
	pen_line(&pen, app, 560, 480, 330, 350);
	pen_line(&pen, app, 560, 400, 700, 250);
	pen_line(&pen, app, 560, 360, 420, 220);
	pen_line(&pen, app, 700, 454, 760, 500);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	CHECK(kids(&app->tree, 0, k) >= 4);
	/* a copy: the app's tree is the document's to change */
	copy_tree(&t, &app->tree);
	adds_then_removes(&t, 0, 17, 10);
	if (kids(&t, 1, k) > 0)
		adds_then_removes(&t, 1, 18, 10);
	tree_finish(&t);
	app_destroy(app);
}

int main(void)
{
	test_turtle_frame();
	test_trunk_ten();
	test_branch_ten();
	test_vertical_trunk();
	test_leaning_trunk();
	test_upright_limit();
	test_many();
	test_determinism();
	test_single_child();
	test_enoent();
	test_degenerate();
	test_lifted_drawing();
	return 0;
}
