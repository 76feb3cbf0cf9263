/* SPDX-License-Identifier: MIT */
/* Stroke to tree: resampling, open/closed, attachment (root moves, tip stays). */
#include <string.h>

#include "doc.h"
#include "sketch.h"
#include "test.h"

static struct doc_op line_op(double x0, double y0, double x1, double y1, int n)
{
	struct doc_op op = { .kind = DOC_OP_STROKE, .tool = EVENT_TOOL_PEN };

	op.points = calloc((size_t)n, sizeof(*op.points));
	CHECK(op.points);
	op.npoints = (size_t)n;
	for (int i = 0; i < n; i++) {
		double s = (double)i / (n - 1);

		op.points[i] = (struct doc_point){ (float)(x0 + (x1 - x0) * s),
						   (float)(y0 + (y1 - y0) * s), 0.5f, (uint32_t)i };
	}
	return op;
}

static struct doc_op circle_op(double cx, double cy, double r, int n)
{
	struct doc_op op = { .kind = DOC_OP_STROKE, .tool = EVENT_TOOL_PEN };

	op.points = calloc((size_t)n, sizeof(*op.points));
	CHECK(op.points);
	op.npoints = (size_t)n;
	for (int i = 0; i < n; i++) {
		double a = 2 * 3.14159265358979 * i / (n - 1) * 0.97;

		op.points[i] = (struct doc_point){ (float)(cx + r * cos(a)), (float)(cy + r * sin(a)),
						   0.5f, (uint32_t)i };
	}
	return op;
}

static void test_resample(void)
{
	struct vec3 in[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 } }, *out;
	size_t n;

	CHECK_INT(sketch_resample(in, 3, 0.1, &out, &n), 0);
	CHECK_INT(n, 21);
	CHECK_NEAR(out[10].x, 1.0, 1e-9);
	CHECK(memcmp(&out[n - 1], &in[2], sizeof(in[2])) == 0);
	for (size_t i = 1; i < n; i++)
		CHECK_NEAR(vec3_dist(out[i - 1], out[i]), 0.1, 1e-9);
	free(out);
}

static void test_tree(void)
{
	struct tree t;
	struct doc_op op;
	const struct branch *b;

	tree_init(&t);
	op = line_op(0, 0, 0.2, 6, 50);
	CHECK_INT(doc_apply_stroke(&t, &op), 0);
	doc_op_finish(&op);
	CHECK_INT(t.nbranches, 1);
	CHECK_INT(t.branches[0].parent, -1);
	CHECK(t.branches[0].radii[0] > t.branches[0].radii[t.branches[0].npoints - 1]);

	/* starts 0.3 m right of the trunk at y=3: root moves onto the trunk, tip stays */
	op = line_op(0.4, 3.0, 2.5, 4.5, 30);
	CHECK_INT(doc_apply_stroke(&t, &op), 0);
	CHECK_INT(t.nbranches, 2);
	b = &t.branches[1];
	CHECK_INT(b->parent, 0);
	CHECK_INT(b->generation, 1);
	CHECK_NEAR(b->points[b->npoints - 1].x, 2.5, 1e-6);
	CHECK_NEAR(b->points[b->npoints - 1].y, 4.5, 1e-6);
	{
		struct sketch_hit h = sketch_nearest(&t, b->points[0]);

		CHECK_NEAR(h.dist, 0.0, 1e-9);
	}
	CHECK_NEAR(b->parent_t, 0.5, 0.02);
	CHECK(b->radii[0] < t.branches[0].radii[0]);
	doc_op_finish(&op);

	/* a small loop near the branch tip is a leaf on that branch */
	op = circle_op(2.7, 4.6, 0.2, 40);
	CHECK_INT(doc_apply_stroke(&t, &op), 0);
	doc_op_finish(&op);
	CHECK_INT(t.nleaves, 1);
	CHECK_INT(t.leaves[0].branch, 1);
	CHECK(t.leaves[0].npoints >= 10);

	/* the leaf is held in b1's frame: turn b1 a quarter about its root and the leaf turns
	 * with it */
	{
		struct branch *b1 = &t.branches[1];
		struct vec3 root = b1->points[0], before[64];
		size_t n = t.leaves[0].npoints;

		CHECK(n <= 64);
		for (size_t i = 0; i < n; i++)
			before[i] = t.leaves[0].points[i];
		for (size_t i = 0; i < b1->npoints; i++) {
			struct vec3 d = vec3_sub(b1->points[i], root);

			b1->points[i] = vec3_add(root, vec3(-d.y, d.x, 0));
		}
		tree_leaves_follow(&t, 1);
		for (size_t i = 0; i < n; i++) {
			struct vec3 d = vec3_sub(before[i], root);

			CHECK_NEAR(t.leaves[0].points[i].x, root.x - d.y, 1e-9);
			CHECK_NEAR(t.leaves[0].points[i].y, root.y + d.x, 1e-9);
		}
	}

	/* a cut right at a branch's root removes it rather than leaving a zero-length one */
	{
		size_t nb = t.nbranches;

		CHECK_INT(tree_cut_branch(&t, 1, 0, 0.0), 0);
		CHECK(t.nbranches < nb);
		CHECK_INT(t.nleaves, 0); /* the leaf on it went too */
		for (size_t i = 0; i < t.nbranches; i++)
			CHECK(tree_branch_length(&t.branches[i]) > 0.1);
	}

	/* a tap makes nothing */
	op = line_op(1, 1, 1.01, 1, 2);
	CHECK_INT(doc_apply_stroke(&t, &op), 0);
	doc_op_finish(&op);
	CHECK_INT(t.nbranches, 1);
	tree_finish(&t);
}

static void test_closed(void)
{
	struct vec3 loop[5] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.05, 0.05, 0 } };
	struct vec3 open[5] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0.6, 0 } };

	CHECK(sketch_is_closed(loop, 5));
	CHECK(!sketch_is_closed(open, 5));
}

static void test_smooth(void)
{
	struct vec3 p[41];

	/* a wobbly line into a right-angle corner and out again */
	for (int i = 0; i <= 20; i++)
		p[i] = vec3(0.1 * i, (i % 2 ? 0.02 : -0.02) * (i > 0 && i < 20), 0);
	for (int i = 21; i <= 40; i++)
		p[i] = vec3(2.0, 0.1 * (i - 20), 0);
	sketch_smooth(p, 41, false);
	CHECK_NEAR(p[0].x, 0, 0);
	CHECK_NEAR(p[0].y, 0, 0);
	CHECK_NEAR(p[40].y, 2.0, 0);
	/* the corner stays where it was drawn */
	CHECK_NEAR(p[20].x, 2.0, 1e-12);
	CHECK_NEAR(p[20].y, 0.0, 1e-12);
	/* the jitter is damped */
	for (int i = 3; i < 18; i++)
		CHECK(fabs(p[i].y) < 0.011);
}

int main(void)
{
	test_smooth();
	test_resample();
	test_closed();
	test_tree();
	return 0;
}
