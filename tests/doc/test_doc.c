/* SPDX-License-Identifier: MIT */
/* drawing.edaha: history semantics, exact round trip, and line-numbered errors. */
#include <errno.h>
#include <string.h>

#include "arrange.h"
#include "doc.h"
#include "gen.h"
#include "ori_kinds.h"
#include "propagate.h"
#include "test.h"
#include "tree.h"

static void push_stroke(struct doc *d, uint64_t t, int n)
{
	struct doc_op op = { .kind = DOC_OP_STROKE, .time_us = t, .tool = EVENT_TOOL_PEN };

	op.points = calloc((size_t)n, sizeof(*op.points));
	CHECK(op.points);
	op.npoints = (size_t)n;
	for (int i = 0; i < n; i++)
		op.points[i] = (struct doc_point){ 0.1f * (float)i + 1e-7f, 3.3f * (float)i / 7.0f,
						   0.5f, (uint32_t)i * 8000 };
	CHECK_INT(doc_push(d, &op), 0);
	CHECK(op.points == NULL);
}

static void test_history(void)
{
	struct doc d;
	struct doc_op op = { .kind = DOC_OP_NEW };

	doc_init(&d, 7);
	CHECK(!doc_can_undo(&d) && !doc_can_redo(&d));
	push_stroke(&d, 1, 3);
	push_stroke(&d, 2, 4);
	CHECK(doc_undo(&d));
	CHECK_INT(d.cursor, 1);
	CHECK(doc_can_redo(&d));
	CHECK(doc_redo(&d));
	CHECK(!doc_redo(&d));
	CHECK(doc_undo(&d));
	/* a new edit after undo drops the undone op */
	CHECK_INT(doc_push(&d, &op), 0);
	CHECK_INT(d.nops, 2);
	CHECK_INT(d.ops[1].kind, DOC_OP_NEW);
	CHECK(!doc_can_redo(&d));
	doc_finish(&d);
}

static void test_roundtrip(void)
{
	struct doc d, e;
	struct buf a, b;
	struct error err = { { 0 } };
	struct tree t;
	struct vec3 pts[2] = { { 0, 0, 0 }, { 0, 1, 0 } };
	double radii[2] = { 0.1, 0.02 };

	doc_init(&d, 123456789012345ULL);
	push_stroke(&d, 1000, 5);
	push_stroke(&d, 900000, 17);
	CHECK(doc_undo(&d));
	tree_init(&t);
	CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, pts, radii, 2) == 0);
	buf_init(&a);
	buf_init(&b);
	CHECK_INT(doc_serialize(&d, &t, &a), 0);
	CHECK_INT(doc_parse((const char *)a.data, a.len, "x.edaha", &e, &err), 0);
	CHECK(e.seed == d.seed);
	CHECK_INT(e.nops, 2);
	CHECK_INT(e.cursor, 1);
	CHECK_INT(e.ops[1].npoints, 17);
	for (size_t i = 0; i < e.ops[1].npoints; i++)
		CHECK(memcmp(&e.ops[1].points[i], &d.ops[1].points[i], sizeof(struct doc_point)) == 0);
	CHECK_INT(doc_serialize(&e, &t, &b), 0);
	CHECK(a.len == b.len && memcmp(a.data, b.data, a.len) == 0);
	doc_finish(&d);
	doc_finish(&e);
	tree_finish(&t);
	buf_finish(&a);
	buf_finish(&b);
}

static void expect_error_len(const char *text, size_t len, const char *prefix)
{
	struct doc d;
	struct error err = { { 0 } };
	int ret = doc_parse(text, len, "bad.edaha", &d, &err);

	if (ret != -EINVAL || strncmp(err.msg, prefix, strlen(prefix)) != 0) {
		fprintf(stderr, "input:\n%s\nret %d, message \"%s\", wanted prefix \"%s\"\n", text, ret,
			err.msg, prefix);
		exit(1);
	}
	CHECK(d.nops == 0 && d.ops == NULL);
}

static void expect_error(const char *text, const char *prefix)
{
	expect_error_len(text, strlen(text), prefix);
}

static void test_errors(void)
{
	expect_error("", "bad.edaha: empty file");
	expect_error("hello\n", "bad.edaha:1: not an edaha drawing");
	expect_error("# c\nedaha-drawing 9\n", "bad.edaha:2: drawing format version 9");
	/* the editing ops came with version 4 */
	expect_error("edaha-drawing 3\nseed 1\nhistory 1 1\nclone-add 5 0\n", "bad.edaha:4: unknown line");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\nclone-add 5\n",
		     "bad.edaha:4: expected 3 fields for clone-add, got 2");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\nclone-remove 5 -1\n",
		     "bad.edaha:4: bad branch \"-1\"");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\nclone-add 5 4294967296\n",
		     "bad.edaha:4: bad branch");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\narrange 5 0 whorl\n",
		     "bad.edaha:4: unknown leaf arrangement \"whorl\"");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\npropagate 5 0 fixed\n",
		     "bad.edaha:4: unknown propagation pattern \"fixed\"");
	expect_error("edaha-drawing 4\nseed 1\nhistory 1 1\npropagate 5 0\n",
		     "bad.edaha:4: expected 4 fields for propagate, got 3");
	expect_error("edaha-drawing 0\n", "bad.edaha:1: drawing format version 0");
	/* version 1 files have no lift op */
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 1\nlift 5\nend\n", "bad.edaha:4: unknown line");
	/* the camera came with version 3, within the orbit's range */
	expect_error("edaha-drawing 2\nseed 1\nhistory 1 1\nstroke pen 0 1 30 10\n",
		     "bad.edaha:4: expected 4 fields for stroke, got 6");
	expect_error("edaha-drawing 2\nseed 1\nview 30 10\n", "bad.edaha:3: unknown line");
	expect_error("edaha-drawing 3\nseed 1\nhistory 1 1\nstroke pen 0 1 30 80\n",
		     "bad.edaha:4: camera pitch 80 out of range -20..75");
	expect_error("edaha-drawing 3\nseed 1\nhistory 1 1\nstroke pen 0 1 200 0\n",
		     "bad.edaha:4: camera yaw 200 out of range -180..180");
	expect_error("edaha-drawing 3\nseed 1\nhistory 1 1\nstroke pen 0 1 inf 0\n",
		     "bad.edaha:4: bad camera yaw");
	expect_error("edaha-drawing 3\nseed 1\nhistory 1 1\nstroke pen 0 1 30\n",
		     "bad.edaha:4: expected 4 fields for stroke, got 5");
	expect_error("edaha-drawing 3\nseed 1\nview 30\n", "bad.edaha:3: expected 3 fields for view");
	expect_error("edaha-drawing 1\nseed x\n", "bad.edaha:2: bad seed");
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 2\n", "bad.edaha:3: bad cursor");
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 1\nstroke pen 0 2\n0 0 0.5 0\n",
		     "bad.edaha:5: file ends inside a stroke");
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 1\nstroke pen 0 1\n0 0 1.5 0\nend\n",
		     "bad.edaha:5: pressure 1.5 out of range");
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 1\nstroke pen 0 1\nnan 0 0.5 0\nend\n",
		     "bad.edaha:5: bad x");
	expect_error("edaha-drawing 1\nseed 1\nhistory 1 1\nstroke brush 0 1\n",
		     "bad.edaha:4: unknown tool");
	expect_error("edaha-drawing 1\nseed 1\nhistory 2 1\nnew 5\nend\n",
		     "bad.edaha:5: history says 2 ops, found 1");
	expect_error("edaha-drawing 1\nseed 1\nhistory 0 0\nend\nmore\n", "bad.edaha:5: text after");
	expect_error("edaha-drawing 1\nseed 1\nhistory 0 0\n", "bad.edaha:3: file ends without");
	expect_error("edaha-drawing 1\nseed 1\nhistory 0 0\nwobble\n", "bad.edaha:4: unknown line");
	static const char nul[] = "edaha-drawing 1\nseed 1\nhis\0tory 0 0\n";

	expect_error_len(nul, sizeof(nul) - 1, "bad.edaha:3: binary data");
}

/* A version 1 file (before the lift op) still loads; version 2 has lift. */
static void test_versions(void)
{
	static const char v1[] = "edaha-drawing 1\nseed 4\nhistory 1 1\nnew 5\nend\n";
	static const char v2[] = "edaha-drawing 2\nseed 4\nhistory 2 2\nnew 5\nlift 9\nend\n";
	struct error err = { { 0 } };
	struct doc d;
	struct buf b;

	CHECK_INT(doc_parse(v1, sizeof(v1) - 1, "v1", &d, &err), 0);
	CHECK_INT(d.nops, 1);
	doc_finish(&d);
	CHECK_INT(doc_parse(v2, sizeof(v2) - 1, "v2", &d, &err), 0);
	CHECK_INT(d.ops[1].kind, DOC_OP_LIFT);
	CHECK(d.ops[1].time_us == 9);
	buf_init(&b);
	CHECK_INT(doc_serialize(&d, NULL, &b), 0);
	/* read as version 2, written as the newest: a front-view drawing needs no camera */
	CHECK(b.len > 0 && strstr((const char *)b.data, "\nlift 9\n") &&
	      strncmp((const char *)b.data, "edaha-drawing 8\n", 16) == 0 &&
	      !strstr((const char *)b.data, "view"));
	buf_finish(&b);
	doc_finish(&d);
}

/* Version 4: the editing ops round-trip. */
static void test_edit_ops(void)
{
	static const char v4[] = "edaha-drawing 4\nseed 4\nhistory 6 6\nlift 2\nclone-add 3 0\n"
				 "clone-remove 4 0\narrange 5 2 whorl-add\narrange 6 2 spiral-extend\n"
				 "propagate 7 1 fixed-size\nend\n";
	struct error err = { { 0 } };
	struct doc d;
	struct buf b;

	CHECK_INT(doc_parse(v4, sizeof(v4) - 1, "v4", &d, &err), 0);
	CHECK_INT(d.nops, 6);
	CHECK(d.ops[1].kind == DOC_OP_CLONE_ADD && d.ops[1].branch == 0 && d.ops[1].time_us == 3);
	CHECK(d.ops[2].kind == DOC_OP_CLONE_REMOVE);
	CHECK(d.ops[3].kind == DOC_OP_ARRANGE && d.ops[3].branch == 2 &&
	      d.ops[3].pattern == ARRANGE_WHORL_ADD);
	CHECK(d.ops[4].pattern == ARRANGE_SPIRAL_EXTEND);
	CHECK(d.ops[5].kind == DOC_OP_PROPAGATE && d.ops[5].branch == 1 &&
	      d.ops[5].pattern == PROPAGATE_FIXED_SIZE);
	buf_init(&b);
	CHECK_INT(doc_serialize(&d, NULL, &b), 0);
	CHECK(b.len == sizeof(v4) - 1 + strlen("# The history is the drawing; the tree section is a summary for other tools.\n"));
	CHECK(strstr((const char *)b.data, "lift 2\nclone-add 3 0\nclone-remove 4 0\narrange 5 2 "
					   "whorl-add\narrange 6 2 spiral-extend\npropagate 7 1 "
					   "fixed-size\nend\n"));
	buf_finish(&b);
	doc_finish(&d);
}

/* Version 6: the leaf type (issue 15) reads, writes back the same, and is refused in
 * version 5 and with a name it does not know. */
static void test_leaftype(void)
{
	static const char v6[] = "edaha-drawing 6\nseed 4\nhistory 4 3\nleaftype 2 maple\n"
				 "leaftype 3 hop\nleaftype 4 drawn\nleaftype 5 entire\nend\n";
	static const char v5[] = "edaha-drawing 5\nseed 4\nhistory 1 1\nleaftype 2 maple\nend\n";
	static const char bad[] = "edaha-drawing 6\nseed 4\nhistory 1 1\nleaftype 2 ginkgo\nend\n";
	struct error err = { { 0 } };
	struct doc d, e;
	struct buf b;

	CHECK_INT(doc_parse(v6, sizeof(v6) - 1, "v6", &d, &err), 0);
	CHECK_INT(d.nops, 4);
	CHECK_INT(d.cursor, 3);
	CHECK(d.ops[0].kind == DOC_OP_LEAFTYPE && d.ops[0].time_us == 2 &&
	      d.ops[0].pattern == ORI_KIND_MAPLE);
	CHECK_INT(d.ops[1].pattern, ORI_KIND_HOP);
	CHECK_INT(d.ops[2].pattern, ORI_KIND_DRAWN);
	CHECK_INT(d.ops[3].pattern, ORI_KIND_ENTIRE);
	buf_init(&b);
	CHECK_INT(doc_serialize(&d, NULL, &b), 0);
	CHECK(strstr((const char *)b.data, "history 4 3\nleaftype 2 maple\nleaftype 3 hop\n"
					   "leaftype 4 drawn\nleaftype 5 entire\nend\n"));
	CHECK_INT(doc_parse((const char *)b.data, b.len, "again", &e, &err), 0);
	CHECK_INT(e.nops, d.nops);
	for (size_t i = 0; i < d.nops; i++)
		CHECK(e.ops[i].kind == d.ops[i].kind && e.ops[i].pattern == d.ops[i].pattern &&
		      e.ops[i].time_us == d.ops[i].time_us);
	buf_finish(&b);
	doc_finish(&e);
	doc_finish(&d);
	CHECK_INT(doc_parse(v5, sizeof(v5) - 1, "v5", &d, &err), -EINVAL);
	CHECK_INT(doc_parse(bad, sizeof(bad) - 1, "bad", &d, &err), -EINVAL);
	CHECK(strstr(err.msg, "bad:4: unknown leaf type \"ginkgo\""));
}

/* Version 3: a stroke drawn on a turned tree keeps its camera, the file the view. */
static void test_camera(void)
{
	static const char v3[] = "edaha-drawing 3\nseed 4\nview -90 12.5\nhistory 3 3\nnew 1\n"
				 "lift 2\nstroke pen 3 2 37.25 -7.5\n0 1 0.5 0\n0.5 1.5 0.5 10\n"
				 "end\n";
	static const char edge[] = "edaha-drawing 3\nseed 4\nhistory 1 1\nstroke pen 3 1 180 75\n"
				   "0 1 0.5 0\nend\n";
	struct error err = { { 0 } };
	struct doc d, again;
	struct buf b, b2;

	CHECK_INT(doc_parse(v3, sizeof(v3) - 1, "v3", &d, &err), 0);
	CHECK(d.view.yaw == -90.0f && d.view.pitch == 12.5f);
	CHECK(camera_is_front(d.ops[0].camera) && camera_is_front(d.ops[1].camera));
	CHECK(d.ops[2].camera.yaw == 37.25f && d.ops[2].camera.pitch == -7.5f);
	buf_init(&b);
	buf_init(&b2);
	CHECK_INT(doc_serialize(&d, NULL, &b), 0);
	CHECK(strstr((const char *)b.data, "\nview -90 12.5\n") &&
	      strstr((const char *)b.data, "\nstroke pen 3 2 37.25 -7.5\n"));
	CHECK_INT(doc_parse((const char *)b.data, b.len, "again", &again, &err), 0);
	CHECK_INT(doc_serialize(&again, NULL, &b2), 0);
	CHECK(b.len == b2.len && memcmp(b.data, b2.data, b.len) == 0);
	doc_finish(&again);
	doc_finish(&d);
	/* yaw 180 is the same camera as -180, which is how it is kept */
	CHECK_INT(doc_parse(edge, sizeof(edge) - 1, "edge", &d, &err), 0);
	CHECK(d.ops[0].camera.yaw == -180.0f && d.ops[0].camera.pitch == 75.0f);
	doc_finish(&d);
	buf_finish(&b);
	buf_finish(&b2);
}

/* Generator versions (gen.h, GEN_VERSION): each generate op keeps the version it was made
 * with, read and written back as read, in a drawing of both; copies keep it; its weight
 * is its version's counts; a version this edaha does not have is refused at its line. */
static void test_gen_versions(void)
{
#define SHRUB "{edaha-tree: 1, type: shrub, precision: 6, trunk: {start: [0, 0, 0]}, levels: 2, " \
	      "children: 2, angle: {min: 30, max: 70, randomness: 0.8}, ratios: [0.8, 0.75], " \
	      "spread: 120, twist: 60, thickness: 0.06, thickness_ratio: 0.75, leaves: {amount: 5, " \
	      "size: 0.15, type: round}, season: summer, trunk_height: 0.8, clip: {shape: sphere, " \
	      "center: [0, 1.5, 0], radius: 1}}"
	static const char both[] = "edaha-drawing 8\nseed 4\nhistory 3 3\n"
				   "generate 5 1 77 " SHRUB "\ngenerate 6 2 77 " SHRUB "\n"
				   "generate 7 1 78 " SHRUB "\nend\n";
	static const char v3[] = "edaha-drawing 8\nseed 4\nhistory 1 1\ngenerate 5 3 77 " SHRUB "\nend\n";
	static const int want[3] = { 1, 2, 1 };
	struct error err = { { 0 } };
	struct doc d, e;
	struct doc_op copy;
	struct buf a, b;
	struct tree t;

	CHECK_INT(doc_parse(both, sizeof(both) - 1, "both", &d, &err), 0);
	CHECK_INT(d.nops, 3);
	for (size_t i = 0; i < 3; i++)
		CHECK(d.ops[i].kind == DOC_OP_GENERATE && d.ops[i].params->gen_version == want[i]);
	buf_init(&a);
	buf_init(&b);
	CHECK_INT(doc_serialize(&d, NULL, &a), 0);
	CHECK(strstr((const char *)a.data, "\ngenerate 5 1 77 {") &&
	      strstr((const char *)a.data, "\ngenerate 6 2 77 {") &&
	      strstr((const char *)a.data, "\ngenerate 7 1 78 {"));
	CHECK_INT(doc_parse((const char *)a.data, a.len, "again", &e, &err), 0);
	for (size_t i = 0; i < 3; i++)
		CHECK_INT(e.ops[i].params->gen_version, want[i]);
	CHECK_INT(doc_serialize(&e, NULL, &b), 0);
	CHECK(a.len == b.len && memcmp(a.data, b.data, a.len) == 0);
	CHECK_INT(doc_op_copy(&copy, &d.ops[0]), 0);
	CHECK_INT(copy.params->gen_version, 1);
	/* version 1: the L-system's 3 branches clipped, a tip on all but the trunk; version 2:
	 * at least 256 tips aimed at the sphere */
	CHECK_INT(doc_op_weight(&copy), 3 + 2 * 5);
	CHECK(doc_op_weight(&d.ops[1]) >= 256 * 6);
	/* and the tree each builds is its version's: version 1 has at most those 3 branches */
	tree_init(&t);
	CHECK_INT(gen_build(&t, copy.params, copy.seed), 0);
	CHECK(t.nbranches >= 1 && t.nbranches <= 3);
	CHECK_INT(gen_build(&t, d.ops[1].params, d.ops[1].seed), 0);
	CHECK(t.nbranches > 256);
	tree_finish(&t);
	doc_op_finish(&copy);
	doc_finish(&e);
	doc_finish(&d);
	buf_finish(&a);
	buf_finish(&b);
	expect_error(v3, "bad.edaha:4: generator version 3 is not supported (this edaha has 1 to 2)");
#undef SHRUB
}

int main(void)
{
	test_gen_versions();
	test_versions();
	test_camera();
	test_edit_ops();
	test_leaftype();
	test_history();
	test_roundtrip();
	test_errors();
	return 0;
}
