/* SPDX-License-Identifier: MIT */
/* Lifting (seed 000, 4.1-4.3): the constraints hold for every branch, a sine stroke
 * becomes a helix, the same seed gives the same tree and another seed another. */
#include <string.h>

#include "doc.h"
#include "lift.h"
#include "sketch.h"
#include "test.h"

static uint64_t now;

static void stroke(struct tree *t, struct rng *rng, double x0, double y0, double x1, double y1,
		   double wave)
{
	struct doc_op op = { .kind = DOC_OP_STROKE, .tool = EVENT_TOOL_PEN, .time_us = now };
	int n = 60;

	(void)rng; /* a stroke draws without chance (sketch_stroke takes none) */
	now += 5000000;
	op.points = calloc((size_t)n, sizeof(*op.points));
	CHECK(op.points);
	op.npoints = (size_t)n;
	for (int i = 0; i < n; i++) {
		double s = (double)i / (n - 1), dx = x1 - x0, dy = y1 - y0, l = hypot(dx, dy);
		double off = wave * sin(s * 2 * VEC_PI * 2); /* two waves across the stroke */

		op.points[i] = (struct doc_point){ (float)(x0 + dx * s - dy / l * off),
						   (float)(y0 + dy * s + dx / l * off), 0.5f,
						   (uint32_t)i * 8000 };
	}
	CHECK(doc_apply_stroke(t, &op) >= 0);
	doc_op_finish(&op);
}

/* A broad, left-right symmetric tree: trunk, 3 pairs of branches, twigs on them. */
static void broadleaf(struct tree *t, struct rng *rng)
{
	stroke(t, rng, 0, 0, 0, 6, 0);
	for (int k = 0; k < 3; k++) {
		double y = 2.5 + k * 1.2, reach = 2.8 - 0.6 * k;

		stroke(t, rng, 0, y, reach, y + 1.2, 0);
		stroke(t, rng, 0, y, -reach, y + 1.2, 0);
	}
	for (int k = 1; k <= 6; k++) {
		const struct branch *b = &t->branches[k];
		struct vec3 m = b->points[b->npoints / 2];

		stroke(t, rng, m.x, m.y, m.x + 0.3 * (m.x > 0 ? 1 : -1), m.y + 0.9, 0);
	}
}

static struct vec3 end_of(const struct branch *b)
{
	return b->points[b->npoints - 1];
}

static double angle(struct vec3 a, struct vec3 b)
{
	return acos(fmin(1, fmax(-1, vec3_dot(a, b) / (vec3_len(a) * vec3_len(b)))));
}

static void test_constraints(void)
{
	struct tree t2, t3;
	struct rng rng;
	double xmin = INFINITY, xmax = -INFINITY;

	tree_init(&t2);
	rng_seed(&rng, 11);
	broadleaf(&t2, &rng);
	CHECK_INT(t2.nbranches, 13);
	tree_init(&t3);
	for (size_t i = 0; i < t2.nbranches; i++) {
		const struct branch *b = &t2.branches[i];

		CHECK(tree_add_branch(&t3, b->parent, b->parent_t, b->origin, b->points, b->radii,
				      b->npoints) >= 0);
		for (size_t k = 0; k < b->npoints; k++) {
			xmin = fmin(xmin, b->points[k].x);
			xmax = fmax(xmax, b->points[k].x);
		}
	}
	CHECK_INT(lift_tree(&t3, &rng, false), 0);
	CHECK_INT(t3.nbranches, t2.nbranches);
	/* the trunk's ends stay in the sketch plane */
	CHECK_NEAR(t3.branches[0].points[0].z, 0, 1e-12);
	CHECK_NEAR(end_of(&t3.branches[0]).z, 0, 1e-9);
	for (size_t i = 0; i < t3.nbranches; i++) {
		const struct branch *b2 = &t2.branches[i], *b3 = &t3.branches[i];
		struct vec3 s3 = b3->points[0], e3 = end_of(b3), d3 = vec3_sub(e3, s3);

		/* the front view is the sketch: x and y exactly as drawn */
		for (size_t k = 0; k < b3->npoints; k++) {
			CHECK_NEAR(b3->points[k].x, b2->points[k].x, 0.06);
			CHECK_NEAR(b3->points[k].y, b2->points[k].y, 0.06);
		}
		/* inside the sqrt(2)-scaled hull (a looser, independent bound) */
		CHECK(fabs(e3.z) <= LIFT_HULL_SCALE * 0.5 * (xmax - xmin) + 1e-9);
		if (b3->parent < 0)
			continue;
		{
			const struct branch *p3 = &t3.branches[b3->parent], *p2 = &t2.branches[b2->parent];
			double plen = vec3_dist(p3->points[0], end_of(p3));
			double amax2 = 0;

			/* at most 1.2 x as long as the parent */
			CHECK(vec3_len(d3) <= LIFT_MAX_LENGTH_RATIO * plen + 0.02);
			/* 45..135 degrees from the view direction */
			CHECK(fabs(d3.z) <= hypot(d3.x, d3.y) + 0.02);
			/* parent-child angle at most 1.2 x the largest drawn one */
			for (size_t j = 0; j < t2.nbranches; j++)
				if (t2.branches[j].parent == b2->parent)
					amax2 = fmax(amax2, angle(vec3_sub(end_of(p2), p2->points[0]),
								  vec3_sub(end_of(&t2.branches[j]),
									   t2.branches[j].points[0])));
			CHECK(angle(vec3_sub(end_of(p3), p3->points[0]), d3) <=
			      LIFT_MAX_ANGLE_RATIO * amax2 + 0.02);
			/* the root is on the parent */
			CHECK(vec3_dist(s3, tree_frame_at(p3, b3->parent_t).origin) < 0.08);
		}
	}
	tree_finish(&t2);
	tree_finish(&t3);
}

static void test_merge_and_seed(void)
{
	struct tree a, b, c;
	struct rng r;
	double zmin = INFINITY, zmax = -INFINITY, xmin = INFINITY, xmax = -INFINITY;
	bool differ = false;

	for (int k = 0; k < 3; k++) {
		struct tree *t = k == 0 ? &a : k == 1 ? &b : &c;

		tree_init(t);
		rng_seed(&r, 11);
		broadleaf(t, &r);
		rng_seed(&r, k < 2 ? 100 : 101);
		CHECK_INT(lift_tree(t, &r, true), 0);
	}
	/* merged: the turned copy without its trunk, marked "merge" */
	CHECK_INT(a.nbranches, 13 + 12);
	CHECK_INT(a.branches[13].origin, ORIGIN_MERGE);
	CHECK_INT(a.branches[13].parent, 0);
	/* every branch, merged ones and their children too, starts on its parent */
	for (size_t i = 1; i < a.nbranches; i++) {
		const struct branch *br = &a.branches[i];

		CHECK(vec3_dist(br->points[0], tree_frame_at(&a.branches[br->parent], br->parent_t).origin) <
		      1e-6);
	}
	/* same seed, same tree; another seed, another */
	for (size_t i = 0; i < a.nbranches; i++) {
		CHECK(memcmp(a.branches[i].points, b.branches[i].points,
			     a.branches[i].npoints * sizeof(struct vec3)) == 0);
		if (memcmp(a.branches[i].points, c.branches[i].points,
			   a.branches[i].npoints * sizeof(struct vec3)))
			differ = true;
	}
	CHECK(differ);
	/* a left-right symmetric sketch grows about as deep as it is wide */
	for (size_t i = 0; i < a.nbranches; i++)
		for (size_t k = 0; k < a.branches[i].npoints; k++) {
			struct vec3 p = a.branches[i].points[k];

			zmin = fmin(zmin, p.z), zmax = fmax(zmax, p.z);
			xmin = fmin(xmin, p.x), xmax = fmax(xmax, p.x);
		}
	fprintf(stderr, "depth/width = %.2f\n", (zmax - zmin) / (xmax - xmin));
	CHECK((zmax - zmin) >= 0.5 * (xmax - xmin) && (zmax - zmin) <= 1.5 * (xmax - xmin));
	tree_finish(&a);
	tree_finish(&b);
	tree_finish(&c);
}

/* A leaning trunk: the merged copy's first generation must be moved onto the unturned
 * trunk, and everything on those branches with them. */
static void test_merge_leaning_trunk(void)
{
	struct tree t;
	struct rng r;

	tree_init(&t);
	rng_seed(&r, 5);
	stroke(&t, &r, 0, 0, 1.2, 6, 0);
	stroke(&t, &r, 0.6, 3, 2.5, 4.5, 0);
	stroke(&t, &r, 0.9, 4.5, -1.5, 5.5, 0);
	stroke(&t, &r, 1.55, 3.75, 1.9, 5.2, 0); /* a twig on the first branch */
	CHECK_INT(t.branches[3].parent, 1);
	CHECK_INT(lift_tree(&t, &r, true), 0);
	CHECK_INT(t.nbranches, 7);
	for (size_t i = 1; i < t.nbranches; i++) {
		const struct branch *br = &t.branches[i];

		CHECK(vec3_dist(br->points[0], tree_frame_at(&t.branches[br->parent], br->parent_t).origin) <
		      1e-6);
	}
	tree_finish(&t);
}

/* The 4.2 merge adds the turned copy and leaves the first tree exactly as a lift without
 * the merge makes it: the second lift starts from the first tree's distance field, and
 * never changes it for the first tree. */
static void test_merge_keeps_first_tree(void)
{
	for (uint64_t seed = 1; seed <= 5; seed++) {
		struct tree a, b;
		struct rng r;

		tree_init(&a);
		tree_init(&b);
		rng_seed(&r, 11);
		broadleaf(&a, &r);
		rng_seed(&r, 11);
		broadleaf(&b, &r);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree(&a, &r, false), 0);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree(&b, &r, true), 0);
		CHECK_INT(b.nbranches, a.nbranches + 12);
		for (size_t i = 0; i < a.nbranches; i++) {
			CHECK_INT(b.branches[i].npoints, a.branches[i].npoints);
			CHECK(memcmp(a.branches[i].points, b.branches[i].points,
				     a.branches[i].npoints * sizeof(struct vec3)) == 0);
			CHECK(a.branches[i].parent_t == b.branches[i].parent_t);
		}
		tree_finish(&a);
		tree_finish(&b);
	}
}

/* The 3D hull at height y, from the sketch's points by brute force (independent of
 * lift.c): the 2D convex hull's width there is spanned by segments between points on
 * either side of y; a disc across it, the radius scaled by sqrt(2). */
static void brute_hull_disc(const struct tree *t2, double y, double *xc, double *r)
{
	double lo = INFINITY, hi = -INFINITY, ymin = INFINITY, ymax = -INFINITY;

	for (size_t i = 0; i < t2->nbranches; i++)
		for (size_t k = 0; k < t2->branches[i].npoints; k++) {
			ymin = fmin(ymin, t2->branches[i].points[k].y);
			ymax = fmax(ymax, t2->branches[i].points[k].y);
		}
	y = fmin(fmax(y, ymin), ymax);
	for (size_t i = 0; i < t2->nbranches; i++)
		for (size_t k = 0; k < t2->branches[i].npoints; k++)
			for (size_t j = 0; j < t2->nbranches; j++)
				for (size_t m = 0; m < t2->branches[j].npoints; m++) {
					struct vec3 p = t2->branches[i].points[k], q = t2->branches[j].points[m];
					double x;

					if (p.y > y || q.y < y)
						continue;
					x = q.y > p.y ? p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y) : p.x;
					lo = fmin(lo, x);
					hi = fmax(hi, x);
				}
	CHECK(lo <= hi);
	*xc = 0.5 * (lo + hi);
	*r = LIFT_HULL_SCALE * 0.5 * (hi - lo);
}

/* On a leaning trunk the merge moves the turned copy onto the unturned trunk: the second
 * lift must test its ends against the hull where they will be after that. Each copy's
 * depth is its drawn x turned, which no lifting changes; where the hull has room at that
 * depth its end is inside, elsewhere as near as that depth allows. And the view rule holds
 * turned with it: 45..135 degrees from the x axis. */
static void test_merge_leaning_trunk_hull(void)
{
	int inside = 0, outside = 0;

	for (uint64_t seed = 1; seed <= 10; seed++) {
		struct tree t, t2;
		struct rng r;

		tree_init(&t);
		rng_seed(&r, 5);
		stroke(&t, &r, 0, 0, 1.2, 6, 0);
		stroke(&t, &r, 0.6, 3, 2.5, 4.5, 0);
		stroke(&t, &r, 0.9, 4.5, -1.5, 5.5, 0);
		stroke(&t, &r, 1.55, 3.75, 1.9, 5.2, 0);
		tree_init(&t2);
		for (size_t i = 0; i < t.nbranches; i++)
			CHECK(tree_add_branch(&t2, t.branches[i].parent, t.branches[i].parent_t,
					      ORIGIN_SKETCH, t.branches[i].points, t.branches[i].radii,
					      t.branches[i].npoints) >= 0);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree(&t, &r, true), 0);
		CHECK_INT(t.nbranches, 7);
		for (size_t i = 4; i < t.nbranches; i++) {
			const struct branch *b = &t.branches[i];
			struct vec3 e = end_of(b), d = vec3_sub(e, b->points[0]);
			double xc, rad, out;

			CHECK_INT(b->origin, ORIGIN_MERGE);
			brute_hull_disc(&t2, e.y, &xc, &rad);
			out = hypot(e.x - xc, e.z) - rad;
			CHECK(out <= fmax(0, fabs(e.z) - rad) + 1e-9);
			inside += out <= 1e-9;
			outside += out > 1e-9;
			CHECK(fabs(d.x) <= hypot(d.y, d.z) + 1e-9);
		}
		tree_finish(&t);
		tree_finish(&t2);
	}
	fprintf(stderr, "leaning trunk: %d copies' ends inside the hull, %d as near as they can\n",
		inside, outside);
}

static void test_helix(void)
{
	struct tree t;
	struct rng r;
	const struct branch *b;
	double xamp = 0, zamp = 0, zmin = INFINITY, zmax = -INFINITY;

	tree_init(&t);
	rng_seed(&r, 1);
	/* a vertical trunk waving sideways with amplitude 0.4 m, two waves */
	stroke(&t, &r, 0, 0, 0, 6, 0.4);
	CHECK_INT(lift_tree(&t, &r, false), 0);
	b = &t.branches[0];
	for (size_t k = 0; k < b->npoints; k++) {
		xamp = fmax(xamp, fabs(b->points[k].x));
		zmin = fmin(zmin, b->points[k].z);
		zmax = fmax(zmax, b->points[k].z);
	}
	zamp = 0.5 * (zmax - zmin);
	fprintf(stderr, "helix: sideways %.3f, depth %.3f\n", xamp, zamp);
	CHECK(fabs(zamp - xamp) <= 0.2 * xamp);
	/* a quarter period out of phase: every interior extreme of the depth lies within an
	 * eighth of a period (3 m / 8) of a place where x crosses zero */
	{
		int extremes = 0;

		for (size_t k = 1; k + 1 < b->npoints; k++) {
			double z0 = b->points[k - 1].z, z1 = b->points[k].z, z2 = b->points[k + 1].z;
			double nearest = INFINITY;

			if (!((z1 > z0 && z1 >= z2) || (z1 < z0 && z1 <= z2)))
				continue;
			extremes++;
			for (size_t j = 0; j + 1 < b->npoints; j++)
				if ((b->points[j].x < 0) != (b->points[j + 1].x < 0))
					nearest = fmin(nearest, fabs(b->points[j].y - b->points[k].y));
			CHECK(nearest < 3.0 / 8);
		}
		CHECK(extremes >= 3);
	}
	tree_finish(&t);
}

/* Children of a wavy branch: 4.1 places each from the point of its parent's final (wavy,
 * lifted) polyline it hangs on, so the constraints hold for the branches as they end up,
 * not only for straightened stand-ins (they were off by up to the wave's depth). */
static void test_children_of_wavy_branch(void)
{
	for (uint64_t seed = 1; seed <= 10; seed++) {
		struct tree t, t2;
		struct rng r;

		tree_init(&t);
		rng_seed(&r, 3);
		stroke(&t, &r, 0, 0, 0, 7, 0);
		stroke(&t, &r, 0, 3, 4, 5, 0.3);
		for (int k = 1; k <= 5; k++) {
			const struct branch *b = &t.branches[1];
			struct vec3 m = b->points[b->npoints * (size_t)k / 6];

			stroke(&t, &r, m.x, m.y, m.x + 0.4 * (k - 3), m.y + 1.2, 0);
		}
		CHECK_INT(t.nbranches, 7);
		tree_init(&t2);
		for (size_t i = 0; i < t.nbranches; i++)
			CHECK(tree_add_branch(&t2, t.branches[i].parent, t.branches[i].parent_t,
					      ORIGIN_SKETCH, t.branches[i].points, t.branches[i].radii,
					      t.branches[i].npoints) >= 0);
		rng_seed(&r, seed);
		CHECK_INT(lift_tree(&t, &r, false), 0);
		for (size_t i = 2; i < t.nbranches; i++) {
			const struct branch *b = &t.branches[i], *p = &t.branches[1];
			const struct branch *b2 = &t2.branches[i], *p2 = &t2.branches[1];
			struct vec3 d = vec3_sub(end_of(b), b->points[0]), pd = vec3_sub(end_of(p), p->points[0]);
			double amax2 = 0;

			CHECK_INT(b->parent, 1);
			for (size_t j = 2; j < t2.nbranches; j++)
				amax2 = fmax(amax2, angle(vec3_sub(end_of(p2), p2->points[0]),
							  vec3_sub(end_of(&t2.branches[j]),
								   t2.branches[j].points[0])));
			CHECK(angle(vec3_sub(end_of(b2), b2->points[0]), vec3_sub(end_of(p2), p2->points[0])) <= amax2);
			CHECK(fabs(d.z) <= hypot(d.x, d.y) + 1e-9);
			CHECK(vec3_len(d) <= LIFT_MAX_LENGTH_RATIO * vec3_len(pd) + 1e-9);
			CHECK(angle(pd, d) <= LIFT_MAX_ANGLE_RATIO * amax2 + 1e-9);
		}
		tree_finish(&t);
		tree_finish(&t2);
	}
}

/* Leaves hung exactly on a vertex of a bent branch keep that vertex's segment, and so its
 * direction, through lifting and the merge: the branch's new arc lengths must not hand
 * them the neighbouring segment's frame (about 4% of them got it before the fix). */
static void test_vertex_anchors(void)
{
	for (uint64_t seed = 1; seed <= 20; seed++) {
		struct tree t;
		struct rng r;
		struct vec3 p[40];
		double rad[40];
		size_t seg0[32], n0;

		tree_init(&t);
		rng_seed(&r, seed);
		for (int i = 0; i < 40; i++) {
			p[i] = vec3(0.01 * sin(i * 0.7), i * 0.15, 0);
			rad[i] = 0.1;
		}
		CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, rad, 40) == 0);
		for (int i = 0; i < 30; i++) {
			double a = 0.2 + 0.03 * (double)seed;

			/* a wavy branch, so every vertex bends */
			p[i] = vec3(i * 0.1 * cos(a) + 0.02 * sin(i * 1.3 + (double)seed),
				    2 + i * 0.1 * sin(a), 0);
			rad[i] = 0.05;
		}
		CHECK(tree_add_branch(&t, 0, 2.0 / tree_branch_length(&t.branches[0]), ORIGIN_SKETCH, p,
				      rad, 30) == 1);
		for (size_t k = 1; k + 1 < 30; k++) {
			struct vec3 lp[3] = { vec3(0, 0, 0), vec3(0.1, 0, 0), vec3(0, 0.1, 0) };
			int id;
			double f;

			for (int q = 0; q < 3; q++)
				lp[q] = vec3_add(lp[q], t.branches[1].points[k]);
			id = tree_add_leaf(&t, 1, ORIGIN_SKETCH, lp, 3);
			CHECK(id >= 0);
			t.leaves[id].branch_t = tree_param(&t.branches[1], k - 1, 1.0);
			CHECK_INT(tree_leaf_attach(&t, (size_t)id), 0);
			tree_locate(&t.branches[1], t.leaves[id].branch_t, &seg0[id], &f);
		}
		n0 = t.nleaves;
		CHECK_INT(lift_tree(&t, &r, true), 0);
		CHECK_INT(t.nleaves, 2 * n0); /* the merged copies, in the same order */
		for (size_t i = 0; i < t.nleaves; i++) {
			const struct leaf *l = &t.leaves[i];
			const struct branch *b = &t.branches[l->branch];
			size_t k;
			double f;
			struct tree_frame fr = tree_frame_at(b, l->branch_t);
			struct vec3 dir = vec3_norm_or(vec3_sub(b->points[seg0[i % n0] + 1],
							       b->points[seg0[i % n0]]),
						       vec3(0, 1, 0));

			tree_locate(b, l->branch_t, &k, &f);
			CHECK_INT(k, seg0[i % n0]);
			CHECK(vec3_dist(fr.tangent, dir) < 1e-9);
		}
		tree_finish(&t);
	}
}

int main(void)
{
	test_constraints();
	test_merge_and_seed();
	test_merge_leaning_trunk();
	test_merge_keeps_first_tree();
	test_merge_leaning_trunk_hull();
	test_helix();
	test_children_of_wavy_branch();
	test_vertex_anchors();
	return 0;
}
