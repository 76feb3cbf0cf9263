/* SPDX-License-Identifier: MIT */
/*
 * Level of detail (mesh.h): ring sides follow a branch's radius on screen, rings are left
 * out where a branch runs straight (within a stated tolerance), a child's root ring hides
 * inside its parent, and a 1,000-branch tree stays light.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mesh.h"
#include "mesh_check.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"
#include "screen.h"

#define TEST_PI 3.14159265358979323846
#define PX_PER_M (MESH_REF_SCREEN_PX / SCREEN_HEIGHT_M)
/* Tubes never get thinner than this (mesh.c's TUBE_MIN_RADIUS). */
#define MIN_RADIUS 0.0005

static void build(struct tree_mesh *tm, const struct tree *t)
{
	CHECK_INT(tree_mesh_build(tm, t), 0);
	check_mesh_sane(&tm->bark);
	check_mesh_sane(&tm->leaves);
}

/* No triangle of the bark is degenerate. */
static void check_no_slivers(const struct mesh *m)
{
	for (size_t f = 0; f < m->nindices / 3; f++)
		CHECK(vec3_len(tri_cross(m, f)) > 1e-12);
}

/*
 * A branch's counts from the radii of the rings it kept: V = sum s + (s0 + 1) + (sl + 1)
 * (rings, root disc, tip cone), F = 2 sum s.
 */
static void check_counts(const struct mesh *m, const double *ring_r, size_t nrings)
{
	size_t sum = 0, s0 = (size_t)mesh_ring_sides(ring_r[0]);
	size_t sl = (size_t)mesh_ring_sides(ring_r[nrings - 1]);

	for (size_t i = 0; i < nrings; i++)
		sum += (size_t)mesh_ring_sides(ring_r[i]);
	CHECK_INT(m->nvertices, sum + s0 + 1 + sl + 1);
	CHECK_INT(m->nindices / 3, 2 * sum);
}

/* Sides follow the radius in pixels at the reference screen, within bounds. */
static void test_sides(void)
{
	int prev = 0;

	for (double r = 1e-4; r < 3.0; r *= 1.01) {
		int s = mesh_ring_sides(r);
		double px = r * PX_PER_M;

		CHECK(s >= MESH_MIN_SIDES && s <= MESH_MAX_SIDES);
		CHECK(s >= prev);
		/* the fewest sides whose polygon keeps within MESH_SIDE_ERROR_PX of the circle */
		if (s < MESH_MAX_SIDES)
			CHECK(px * (1.0 - cos(TEST_PI / s)) <= MESH_SIDE_ERROR_PX);
		if (s > MESH_MIN_SIDES)
			CHECK(px * (1.0 - cos(TEST_PI / (s - 1))) > MESH_SIDE_ERROR_PX);
		prev = s;
	}
	CHECK_INT(mesh_ring_sides(0.002), 3); /* hair-thin: 0.2 px */
	CHECK_INT(mesh_ring_sides(0.009), 3); /* 1 px */
	CHECK_INT(mesh_ring_sides(0.015), 4);
	CHECK_INT(mesh_ring_sides(0.05), 8);
	CHECK_INT(mesh_ring_sides(0.1), 11);
	CHECK_INT(mesh_ring_sides(0.25), 16); /* a trunk */
	CHECK_INT(mesh_ring_sides(5.0), 16);
	CHECK_INT(mesh_ring_sides(0.0), 3);
	CHECK_INT(mesh_ring_sides(NAN), 3);
}

/* Adds a branch; a child hangs on its parent where its root is nearest (arc-length
 * parameter), as sketching records it. */
static int add(struct tree *t, int parent, const struct vec3 *p, const double *r, size_t n)
{
	double param = 0.0;

	if (parent >= 0) {
		const struct branch *pb = &t->branches[parent];
		double best = INFINITY, walked = 0.0, len = tree_branch_length(pb);

		for (size_t i = 0; i + 1 < pb->npoints; i++) {
			struct vec3 a = pb->points[i], b = pb->points[i + 1], d = vec3_sub(b, a);
			double f = vec3_dot(vec3_sub(p[0], a), d) / vec3_dot(d, d);

			f = f < 0 ? 0 : f > 1 ? 1 : f;
			if (vec3_dist(p[0], vec3_add(a, vec3_scale(d, f))) < best) {
				best = vec3_dist(p[0], vec3_add(a, vec3_scale(d, f)));
				param = (walked + f * vec3_len(d)) / len;
			}
			walked += vec3_len(d);
		}
	}
	return tree_add_branch(t, parent, param, ORIGIN_SKETCH, p, r, n);
}

/* One straight segment: two rings, 4 s triangles. Thin twigs cost a fifth of a trunk. */
static void test_triangles_thin_thick(void)
{
	static const double radii[] = { 0.001, 0.004, 0.009, 0.02, 0.05, 0.1, 0.2, 0.3, 1.0 };
	const struct vec3 p[] = { { 0, 1, 0 }, { 0.3, 2, 0.1 } };
	struct tree t;
	struct tree_mesh tm;
	size_t prev = 0, thin = 0, thick = 0;

	tree_init(&t);
	tree_mesh_init(&tm);
	for (size_t i = 0; i < sizeof(radii) / sizeof(radii[0]); i++) {
		double r[2] = { radii[i], radii[i] };
		size_t tris;

		tree_clear(&t);
		CHECK_INT(add(&t, -1, p, r, 2), 0);
		build(&tm, &t);
		tris = tm.bark.nindices / 3;
		CHECK_INT(tris, 4 * (size_t)mesh_ring_sides(radii[i]));
		CHECK(tris >= prev);
		CHECK(tris >= 4 * MESH_MIN_SIDES && tris <= 4 * MESH_MAX_SIDES);
		CHECK_INT(check_closed_surface(&tm.bark), 2);
		prev = tris;
		if (i == 1)
			thin = tris;
		if (i == 7)
			thick = tris;
	}
	CHECK_INT(thin, 12);  /* 4 mm: 3 sides */
	CHECK_INT(thick, 64); /* 0.3 m: 16 sides */
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Nearest point to x on segment ab. */
static struct vec3 on_segment(struct vec3 x, struct vec3 a, struct vec3 b)
{
	struct vec3 d = vec3_sub(b, a);
	double f = vec3_dot(vec3_sub(x, a), d) / vec3_dot(d, d);

	f = f < 0 ? 0 : f > 1 ? 1 : f;
	return vec3_add(a, vec3_scale(d, f));
}

/*
 * A tapering branch bending 10 degrees a point keeps every ring; its sides shrink with its
 * radius, neighbouring rings with different counts are zipped into a closed surface, and
 * every side face and vertex normal points away from the axis.
 */
static void test_taper(void)
{
	struct vec3 p[24];
	double r[24], a = 0.0;
	struct tree t;
	struct tree_mesh tm;
	size_t sum = 0, nside;

	p[0] = vec3(0, 0, 0);
	for (int i = 0; i < 24; i++) {
		r[i] = 0.3 * pow(0.85, i); /* 0.3 m .. 7 mm */
		if (i > 0) {
			struct vec3 dir = vec3(sin(a), cos(a), 0.3 * sin(3 * a));

			p[i] = vec3_add(p[i - 1], vec3_scale(dir, 0.25));
			a += 10.0 * TEST_PI / 180.0 * (i % 8 < 4 ? 1 : -1);
		}
	}
	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(add(&t, -1, p, r, 24), 0);
	build(&tm, &t);
	check_counts(&tm.bark, r, 24);
	CHECK_INT(mesh_ring_sides(r[0]), 16);
	CHECK_INT(mesh_ring_sides(r[23]), 3);
	CHECK_INT(check_closed_surface(&tm.bark), 2);
	check_no_slivers(&tm.bark);

	for (int i = 0; i < 24; i++) {
		int s = mesh_ring_sides(r[i]);

		for (int j = 0; j < s; j++) {
			uint32_t v = (uint32_t)(sum + (size_t)j);
			struct vec3 out = vec3_sub(mesh_pos(&tm.bark, v), p[i]);

			CHECK_NEAR(vec3_len(out), r[i], 1e-5);
			CHECK(vec3_dot(mesh_nor(&tm.bark, v), out) > 0);
		}
		sum += (size_t)s;
	}
	/* side faces come first: 2 sum s less the two end rings' share of the caps */
	nside = 2 * sum - (size_t)mesh_ring_sides(r[0]) - (size_t)mesh_ring_sides(r[23]);
	for (size_t f = 0; f < nside; f++) {
		const uint32_t *tri = &tm.bark.indices[3 * f];
		struct vec3 mid = vec3_scale(vec3_add(vec3_add(mesh_pos(&tm.bark, tri[0]),
							       mesh_pos(&tm.bark, tri[1])),
						      mesh_pos(&tm.bark, tri[2])),
					     1.0 / 3.0);
		struct vec3 axis = p[0];
		double best = INFINITY;

		for (int i = 0; i + 1 < 24; i++) {
			struct vec3 q = on_segment(mid, p[i], p[i + 1]);

			if (vec3_dist(q, mid) < best) {
				best = vec3_dist(q, mid);
				axis = q;
			}
		}
		CHECK(vec3_dot(tri_cross(&tm.bark, f), vec3_sub(mid, axis)) > 0);
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/*
 * Which of a branch's points kept a ring: ring vertices come first, point by point, each
 * ring centred on its point at its radius (a root branch: no joint shrinks its root).
 */
static size_t kept_rings(const struct mesh *m, const struct vec3 *p, const double *r, size_t n,
			 bool *kept)
{
	size_t pos = 0, nk = 0, total;

	total = m->nvertices - (size_t)mesh_ring_sides(r[0]) - 1 -
		(size_t)mesh_ring_sides(r[n - 1]) - 1;
	for (size_t i = 0; i < n; i++) {
		size_t s = (size_t)mesh_ring_sides(r[i]);
		struct vec3 c = vec3(0, 0, 0);
		bool ok = pos + s <= total;

		for (size_t j = 0; ok && j < s; j++) {
			struct vec3 q = mesh_pos(m, (uint32_t)(pos + j));

			c = vec3_add(c, q);
			ok = fabs(vec3_dist(q, p[i]) - r[i]) < 1e-5;
		}
		kept[i] = ok && vec3_dist(vec3_scale(c, 1.0 / (double)s), p[i]) < 1e-5;
		if (kept[i]) {
			pos += s;
			nk++;
		}
	}
	CHECK_INT(pos, total);
	return nk;
}

/* Turn of the polyline at point i, degrees. */
static double turn_deg(const struct vec3 *p, size_t i)
{
	struct vec3 a = vec3_sub(p[i], p[i - 1]), b = vec3_sub(p[i + 1], p[i]);
	double c = vec3_dot(a, b) / (vec3_len(a) * vec3_len(b));

	return acos(c > 1 ? 1 : c) * 180.0 / TEST_PI;
}

/* Winding number of closed triangles [f0, f1) around x: 1 inside, 0 outside. */
static double winding(const struct mesh *m, size_t f0, size_t f1, struct vec3 x)
{
	double sum = 0.0;

	for (size_t f = f0; f < f1; f++) {
		struct vec3 a = vec3_sub(mesh_pos(m, m->indices[3 * f]), x);
		struct vec3 b = vec3_sub(mesh_pos(m, m->indices[3 * f + 1]), x);
		struct vec3 c = vec3_sub(mesh_pos(m, m->indices[3 * f + 2]), x);
		double la = vec3_len(a), lb = vec3_len(b), lc = vec3_len(c);
		double num = vec3_dot(a, vec3_cross(b, c));
		double den = la * lb * lc + vec3_dot(a, b) * lc + vec3_dot(a, c) * lb +
			     vec3_dot(b, c) * la;

		sum += 2.0 * atan2(num, den);
	}
	return sum / (4.0 * TEST_PI);
}

/*
 * Checks what ring dropping promised (mesh.h) on branch p/r: ends kept, points where the
 * branch turns more than MESH_DROP_TURN_DEG kept, and every left-out point within
 * mesh_drop_tolerance(r) (axis distance plus radius difference) of the straight tube
 * between the kept rings around it, and inside the mesh. Returns the rings kept.
 */
static size_t check_dropping(const struct vec3 *p, const double *r, size_t n)
{
	struct tree t;
	struct tree_mesh tm;
	bool kept[256];
	size_t nk, a = 0;

	CHECK(n <= 256);
	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(add(&t, -1, p, r, n), 0);
	build(&tm, &t);
	CHECK_INT(check_closed_surface(&tm.bark), 2);
	check_no_slivers(&tm.bark);
	nk = kept_rings(&tm.bark, p, r, n, kept);
	CHECK(kept[0] && kept[n - 1]);
	/* points left out have the sides of the ring kept before them */
	for (size_t i = 1, before = 0; i < n; i++) {
		if (kept[i])
			before = i;
		else
			CHECK_INT(mesh_ring_sides(r[i]), mesh_ring_sides(r[before]));
	}
	for (size_t i = 1; i + 1 < n; i++)
		if (turn_deg(p, i) > MESH_DROP_TURN_DEG + 1e-9)
			CHECK(kept[i]);
	for (size_t b = 1; b < n; b++) {
		if (!kept[b])
			continue;
		CHECK(b - a <= MESH_DROP_MAX_SPAN);
		for (size_t j = a + 1; j < b; j++) {
			struct vec3 d = vec3_sub(p[b], p[a]);
			double f = vec3_dot(vec3_sub(p[j], p[a]), d) / vec3_dot(d, d);
			double rr = r[a] + (r[b] - r[a]) * f;
			double err = vec3_dist(p[j], on_segment(p[j], p[a], p[b])) + fabs(r[j] - rr);

			CHECK(f > 0 && f < 1);
			CHECK(err <= mesh_drop_tolerance(r[j]) + 1e-9);
			CHECK(winding(&tm.bark, 0, tm.bark.nindices / 3, p[j]) > 0.5);
		}
		a = b;
	}
	{
		double kr[256];
		size_t m = 0;

		for (size_t i = 0; i < n; i++)
			if (kept[i])
				kr[m++] = r[i];
		check_counts(&tm.bark, kr, m);
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
	return nk;
}

/*
 * Rings are left out where a branch runs straight, never beyond the stated tolerance: a
 * left-out point's distance from the straight tube's axis plus its radius's difference
 * from the tube's is at most min(0.25 px at 1080 px = 2.3 mm, 25% of its radius).
 */
static void test_dropping(void)
{
	struct vec3 p[64];
	double r[64], a = 0.0;
	size_t nk;

	CHECK_NEAR(mesh_drop_tolerance(0.006), 0.0015, 1e-12);
	CHECK_NEAR(mesh_drop_tolerance(0.25), 0.25 / PX_PER_M, 1e-12);
	CHECK_NEAR(0.25 / PX_PER_M, 0.0023148, 1e-7);

	/* A thin twig (6 mm: tolerance 1.5 mm) bending half a degree every 5 cm, with a 20
	 * degree corner halfway and a taper that is not linear: most rings go. */
	p[0] = vec3(0.2, 1.0, -0.1);
	for (int i = 0; i < 60; i++) {
		double s = i / 59.0;

		r[i] = 0.006 * (1.0 - 0.5 * s * s);
		if (i > 0)
			p[i] = vec3_add(p[i - 1], vec3_scale(vec3(sin(a), cos(a), 0.2), 0.05));
		a += (i == 30 ? 20.0 : 0.5) * TEST_PI / 180.0;
	}
	nk = check_dropping(p, r, 60);
	printf("thin twig, 60 points bending 0.5 deg each: %zu rings\n", nk);
	CHECK(nk <= 20);

	/* A straight trunk 5 cm a point: only the ends and every MESH_DROP_MAX_SPAN-th point. */
	for (int i = 0; i < 40; i++) {
		p[i] = vec3(0, 0.05 * i, 0);
		r[i] = 0.3 - 0.001 * i; /* 16 sides throughout */
	}
	CHECK_INT(check_dropping(p, r, 40), 4);
	/* Tapering from 16 sides to 8: the rings where the count changes stay too. */
	for (int i = 0; i < 40; i++)
		r[i] = 0.25 - 0.005 * i;
	nk = check_dropping(p, r, 40);
	printf("straight trunk tapering from %d to %d sides: %zu rings\n", mesh_ring_sides(r[0]),
	       mesh_ring_sides(r[39]), nk);
	CHECK(nk > 4 && nk < 20);

	/* Bending 6 degrees a point is more than a few degrees: every ring stays. */
	a = 0.0;
	for (int i = 0; i < 30; i++) {
		r[i] = 0.004;
		p[i] = i ? vec3_add(p[i - 1], vec3_scale(vec3(sin(a), cos(a), 0), 0.05))
			 : vec3(0, 0, 0);
		a += 6.0 * TEST_PI / 180.0;
	}
	CHECK_INT(check_dropping(p, r, 30), 30);

	/* A hand-drawn wobble: a millimetre or two of jitter on a thin and a thick branch. */
	for (int k = 0; k < 2; k++) {
		for (int i = 0; i < 64; i++) {
			double j = 0.0015 * sin(i * 2.7) * cos(i * 1.3);

			r[i] = (k ? 0.12 : 0.01) * (1.0 - 0.6 * i / 63.0);
			p[i] = vec3(0.03 * i + j, 1.0 + 0.04 * i - j, 0.5 * j);
		}
		nk = check_dropping(p, r, 64);
		printf("wobbly %s branch, 64 points: %zu rings\n", k ? "thick" : "thin", nk);
		CHECK(nk < 64);
	}
}

/* Where each branch's vertices and triangles are in the bark. */
struct range {
	size_t v0, v1, f0, f1;
};

/*
 * Meshes the tree one branch at a time with tree_mesh_append, noting each branch's range;
 * the result must be the bytes of a full build.
 */
static void mesh_by_append(const struct tree *full, struct tree_mesh *tm, struct range *rg)
{
	struct tree t;
	struct tree_mesh fb;

	tree_init(&t);
	tree_mesh_init(&fb);
	for (size_t i = 0; i < full->nbranches; i++) {
		const struct branch *b = &full->branches[i];

		CHECK_INT(tree_add_branch(&t, b->parent, b->parent_t, b->origin, b->points, b->radii,
					  b->npoints),
			  (long long)i);
		rg[i].v0 = tm->bark.nvertices;
		rg[i].f0 = tm->bark.nindices / 3;
		CHECK_INT(tree_mesh_append(tm, &t, i, 0), 0);
		rg[i].v1 = tm->bark.nvertices;
		rg[i].f1 = tm->bark.nindices / 3;
	}
	build(&fb, full);
	CHECK_INT(fb.bark.nvertices, tm->bark.nvertices);
	CHECK_INT(fb.bark.nindices, tm->bark.nindices);
	CHECK(!memcmp(fb.bark.positions, tm->bark.positions, tm->bark.nvertices * 3 * sizeof(float)));
	CHECK(!memcmp(fb.bark.normals, tm->bark.normals, tm->bark.nvertices * 3 * sizeof(float)));
	CHECK(!memcmp(fb.bark.indices, tm->bark.indices, tm->bark.nindices * sizeof(uint32_t)));
	tree_mesh_finish(&fb);
	tree_finish(&t);
}

struct joint_stats {
	size_t children, shrunk, no_room, outside;
};

/*
 * Every child's root ring lies inside its parent's closed tube (winding number), or its
 * grandparent's, so no root shows beside its parent and the child leaves it without a gap.
 * Where there was no room at all (a root on the trunk's root disc), the ring must have the
 * least radius; those are counted in `outside`. Branch `skip` (a root away from its
 * parent) is not checked.
 */
static struct joint_stats check_joints(const struct tree *t, int skip)
{
	struct tree_mesh tm;
	struct range *rg = calloc(t->nbranches, sizeof(*rg));
	struct joint_stats st = { 0, 0, 0, 0 };

	CHECK(rg);
	tree_mesh_init(&tm);
	mesh_by_append(t, &tm, rg);
	check_mesh_sane(&tm.bark);
	check_no_slivers(&tm.bark);
	for (size_t c = 0; c < t->nbranches; c++) {
		const struct branch *b = &t->branches[c];
		const struct range *pr;
		struct vec3 root = b->points[0];
		int gp;
		double r0;
		size_t s0 = 0;
		bool least, out = false;

		if (b->parent < 0 || (int)c == skip || rg[c].v1 == rg[c].v0)
			continue;
		pr = &rg[b->parent];
		gp = t->branches[b->parent].parent;
		r0 = vec3_dist(mesh_pos(&tm.bark, (uint32_t)rg[c].v0), root);
		while (s0 < MESH_MAX_SIDES && rg[c].v0 + s0 < rg[c].v1 &&
		       fabs(vec3_dist(mesh_pos(&tm.bark, (uint32_t)(rg[c].v0 + s0)), root) - r0) < 2e-6)
			s0++;
		CHECK(s0 >= MESH_MIN_SIDES);
		CHECK(r0 <= b->radii[0] + 1e-6);
		least = r0 < MIN_RADIUS + 1e-6 && b->radii[0] > MIN_RADIUS + 1e-6;
		st.children++;
		st.shrunk += r0 < b->radii[0] - 1e-6;
		st.no_room += least;
		for (size_t j = 0; j < s0; j++) {
			struct vec3 v = mesh_pos(&tm.bark, (uint32_t)(rg[c].v0 + j));
			double w = winding(&tm.bark, pr->f0, pr->f1, v);

			/* near its parent's root, the grandparent may be what hides it */
			if (!(w > 0.5) && gp >= 0)
				w = winding(&tm.bark, rg[gp].f0, rg[gp].f1, v);
			if (!(w > 0.5) && !least)
				fprintf(stderr, "branch %zu: root vertex %zu outside parent %d"
						" (winding %g)\n",
					c, j, b->parent, w);
			CHECK(w > 0.5 || least);
			out = out || !(w > 0.5);
		}
		st.outside += out;
	}
	tree_mesh_finish(&tm);
	free(rg);
	return st;
}

/* Joints that used to show: thin few-sided parents, thick children, ends, bends. */
static void test_joints_hard(void)
{
	const struct vec3 trunk[] = { { 0, 0, 0 }, { 0, 2, 0 }, { 0, 4, 0 } };
	const double trunk_r[] = { 0.2, 0.2, 0.2 };
	/* 4 mm: three sides, a triangle whose inscribed circle is half the radius */
	const struct vec3 twig[] = { { 0, 2, 0 }, { 0.5, 2.2, 0 }, { 1, 2.3, 0.1 }, { 1.5, 2.5, 0 } };
	const double twig_r[] = { 0.004, 0.004, 0.004, 0.004 };
	/* thicker than its parent, leaving it square on */
	const struct vec3 thick[] = { { 0.5, 2.2, 0 }, { 0.5, 2.25, 0.3 }, { 0.5, 2.3, 0.6 } };
	const double thick_r[] = { 0.012, 0.01, 0.008 };
	/* from the twig's tip: sideways, and straight on */
	const struct vec3 side[] = { { 1.5, 2.5, 0 }, { 1.5, 2.8, 0 }, { 1.6, 3.0, 0 } };
	const struct vec3 on[] = { { 1.5, 2.5, 0 }, { 2.0, 2.7, 0 } };
	const double small_r[] = { 0.003, 0.003, 0.003 };
	/* from the twig's root (on the trunk), at its bend, and a millimetre off its axis */
	const struct vec3 at_root[] = { { 0, 2, 0 }, { -0.1, 2.5, 0.2 } };
	const struct vec3 at_bend[] = { { 1, 2.3, 0.1 }, { 1.1, 2.6, 0.3 } };
	const struct vec3 off_axis[] = { { 0.75, 2.251, 0.05 }, { 0.7, 2.6, 0.1 } };
	/* from the thick child's root, which shrank into the twig */
	const struct vec3 from_thick[] = { { 0.5, 2.2, 0 }, { 0.4, 2.6, 0.2 } };
	/* from the trunk's tip, square on; and from its very root (no room: a point) */
	const struct vec3 crown[] = { { 0, 4, 0 }, { 0.6, 4.1, 0 } };
	const struct vec3 ground[] = { { 0, 0, 0 }, { 0.5, 0.3, 0 } };
	const double big_r[] = { 0.15, 0.1 };
	/* a root a metre from its parent: nothing to hide it in, left as drawn */
	const struct vec3 away[] = { { 3, 3, 0 }, { 3.5, 3.5, 0 } };
	struct tree t;
	struct joint_stats st;
	int away_id;

	tree_init(&t);
	CHECK_INT(add(&t, -1, trunk, trunk_r, 3), 0);
	CHECK_INT(add(&t, 0, twig, twig_r, 4), 1);
	CHECK_INT(add(&t, 1, thick, thick_r, 3), 2);
	CHECK_INT(add(&t, 1, side, small_r, 3), 3);
	CHECK_INT(add(&t, 1, on, small_r, 2), 4);
	CHECK_INT(add(&t, 1, at_root, small_r, 2), 5);
	CHECK_INT(add(&t, 1, at_bend, small_r, 2), 6);
	CHECK_INT(add(&t, 1, off_axis, small_r, 2), 7);
	CHECK_INT(add(&t, 0, crown, big_r, 2), 8);
	CHECK_INT(add(&t, 0, ground, big_r, 2), 9);
	CHECK_INT(add(&t, 2, from_thick, small_r, 2), 10);
	away_id = add(&t, 0, away, big_r, 2);
	CHECK_INT(away_id, 11);
	st = check_joints(&t, away_id);
	printf("hard joints: %zu children, %zu roots shrunk into their parent, %zu to the least"
	       " radius, %zu of those not inside\n",
	       st.children, st.shrunk, st.no_room, st.outside);
	/* the root on the trunk's root disc and the one a millimetre off the 4 mm twig's axis,
	 * where its triangle's inscribed circle is 2 mm; only the first shows (0.5 mm) */
	CHECK_INT(st.no_room, 2);
	CHECK_INT(st.outside, 1);
	CHECK_INT(st.shrunk, 8);
	/* the away branch, meshed last, keeps its drawn root radius */
	{
		struct tree_mesh tm;
		size_t s0 = (size_t)mesh_ring_sides(big_r[0]), s1 = (size_t)mesh_ring_sides(big_r[1]);
		uint32_t first;

		tree_mesh_init(&tm);
		build(&tm, &t);
		first = (uint32_t)(tm.bark.nvertices - 2 * (s0 + s1) - 2);
		CHECK_NEAR(vec3_dist(mesh_pos(&tm.bark, first), away[0]), big_r[0], 1e-6);
		tree_mesh_finish(&tm);
	}
	tree_finish(&t);
}

/* The same tree with every branch resampled every 5 cm, as sketching samples strokes. */
static void resample_tree(const struct tree *in, struct tree *out)
{
	tree_clear(out);
	for (size_t i = 0; i < in->nbranches; i++) {
		const struct branch *b = &in->branches[i];
		struct vec3 p[512];
		double r[512];
		size_t n = 0;

		for (size_t j = 0; j + 1 < b->npoints; j++) {
			double len = vec3_dist(b->points[j], b->points[j + 1]);
			int steps = (int)ceil(len / 0.05);

			for (int k = 0; k < steps && n < 511; k++) {
				double f = (double)k / steps;

				p[n] = vec3_lerp(b->points[j], b->points[j + 1], f);
				r[n++] = b->radii[j] + (b->radii[j + 1] - b->radii[j]) * f;
			}
		}
		p[n] = b->points[b->npoints - 1];
		r[n++] = b->radii[b->npoints - 1];
		CHECK_INT(tree_add_branch(out, b->parent, b->parent_t, b->origin, p, r, n),
			  (long long)i);
	}
}

/*
 * Every joint of big synthetic trees, their meshes appended branch by branch; and of one
 * resampled every 5 cm, where parents have rings left out.
 */
static void test_joints_synth(void)
{
	static const uint64_t seeds[] = { 7, 2024, 99, 5 };
	struct tree t, dense;

	tree_init(&t);
	tree_init(&dense);
	for (size_t i = 0; i < sizeof(seeds) / sizeof(seeds[0]); i++) {
		struct joint_stats st;
		bool resampled = i == 3;

		CHECK_INT(synth_tree(&t, i ? 400 : 1000, 0, seeds[i]), 0);
		if (resampled)
			resample_tree(&t, &dense);
		st = check_joints(resampled ? &dense : &t, -1);
		printf("synth_tree(%zu, seed %llu)%s: %zu children, %zu roots shrunk into their"
		       " parent, %zu to the least radius\n",
		       t.nbranches, (unsigned long long)seeds[i], resampled ? " every 5 cm" : "",
		       st.children, st.shrunk, st.no_room);
		CHECK_INT(st.outside, 0);
	}
	tree_finish(&dense);
	tree_finish(&t);
}

/*
 * A 1,000-branch tree stays light. synth_tree(1000, 5, 7), before detail adapted (6 to 16
 * sides from a branch's thickest radius, a ring at every point): 151,828 bark triangles;
 * with it: 86,882. The same tree resampled every 5 cm as sketching samples strokes (21,379
 * points): 296,876 before, 94,810 with it. Leaves are untouched.
 */
static void test_budget(void)
{
	struct tree t, dense;
	struct tree_mesh tm;

	tree_init(&t);
	tree_init(&dense);
	tree_mesh_init(&tm);
	CHECK_INT(synth_tree(&t, 1000, 5, 7), 0);
	build(&tm, &t);
	check_no_slivers(&tm.bark);
	printf("synth_tree(1000, 5, 7): %zu bark triangles, %zu vertices\n", tm.bark.nindices / 3,
	       tm.bark.nvertices);
	CHECK(tm.bark.nindices / 3 <= 90000);
	/* leaves are what they were */
	CHECK_INT(tm.leaves.nindices / 3, 30225);

	resample_tree(&t, &dense);
	build(&tm, &dense);
	check_no_slivers(&tm.bark);
	printf("resampled every 5 cm: %zu bark triangles, %zu vertices\n", tm.bark.nindices / 3,
	       tm.bark.nvertices);
	CHECK(tm.bark.nindices / 3 <= 100000);
	tree_mesh_finish(&tm);
	tree_finish(&dense);
	tree_finish(&t);
}

int main(void)
{
	test_sides();
	test_triangles_thin_thick();
	test_taper();
	test_dropping();
	test_joints_hard();
	test_joints_synth();
	test_budget();
	return 0;
}
