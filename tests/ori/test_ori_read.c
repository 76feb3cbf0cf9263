/* SPDX-License-Identifier: MIT */
/*
 * The origami leaf design reader (ori_read, docs/leaf-format.md): the defaults, the
 * presets, a number or [right, left], the lines a design keeps for ori_build's messages,
 * and every malformed file in tests/ori/malformed refused at the line its EXPECT file
 * names, the design untouched.
 *   test_ori_read MALFORMED_DIR
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "ori.h"
#include "ori_design.h"
#include "ori_presets.h"
#include "malformed_dir.h"
#include "test.h"

static int read_text(const char *text, struct ori_design *d, struct error *err)
{
	return ori_read(text, strlen(text), "t", d, err);
}

/* Reads text, which must be accepted (else says why) and be within every range. */
static void read_ok(const char *text, struct ori_design *d)
{
	struct ori_fault at;
	struct error err;

	if (read_text(text, d, &err) != 0) {
		fprintf(stderr, "refused: %s\n---\n%s---\n", err.msg, text);
		CHECK(0);
	}
	CHECK_INT(ori_design_check(d, &at, &err), 0);
}

/* Field by field but the lines: padding is no part of a design. */
static void check_same(const struct ori_design *a, const struct ori_design *b)
{
	CHECK(strcmp(a->name, b->name) == 0);
	CHECK_INT(a->fold, b->fold);
	CHECK(a->size == b->size && a->rest == b->rest);
	CHECK(a->middle[0] == b->middle[0] && a->middle[1] == b->middle[1]);
	CHECK_INT(a->nnodes, b->nnodes);
	for (size_t i = 0; i < ORI_MAX_NODES; i++) {
		const struct ori_node *p = &a->nodes[i], *q = &b->nodes[i];

		CHECK(p->at == q->at);
		CHECK(p->phi[0] == q->phi[0] && p->phi[1] == q->phi[1]);
		CHECK(p->psi[0] == q->psi[0] && p->psi[1] == q->psi[1]);
	}
	CHECK_INT(a->nsides, b->nsides);
	for (size_t i = 0; i < ORI_MAX_SIDES; i++) {
		const struct ori_side *p = &a->sides[i], *q = &b->sides[i];

		CHECK(p->angle == q->angle && p->forks == q->forks && p->fork_at == q->fork_at);
		CHECK(p->fork_a == q->fork_a && p->fork_b == q->fork_b);
		CHECK_INT(p->nnodes, q->nnodes);
		for (size_t k = 0; k < ORI_MAX_NODES; k++) {
			const struct ori_node *m = &p->nodes[k], *n = &q->nodes[k];

			CHECK(m->at == n->at);
			CHECK(m->phi[0] == n->phi[0] && m->phi[1] == n->phi[1]);
			CHECK(m->psi[0] == n->psi[0] && m->psi[1] == n->psi[1]);
		}
	}
	CHECK(a->junction == b->junction && a->theta0 == b->theta0);
	CHECK(a->width == b->width && a->power == b->power);
}

static void test_defaults(void)
{
	struct ori_design d;
	struct ori_fault at;
	struct error err;

	memset(&d, 0x5a, sizeof(d));
	ori_design_default(&d, ORI_FOLD_FAN);
	CHECK(strcmp(d.name, "leaf") == 0);
	CHECK_INT(d.fold, ORI_FOLD_FAN);
	CHECK(d.size == 0.08 && d.rest == 0.9);
	CHECK(d.middle[0] == 30 && d.middle[1] == 30);
	CHECK_INT(d.nnodes, 0);
	CHECK_INT(d.nsides, 2);
	for (size_t i = 0; i < 2; i++) {
		CHECK(d.sides[i].angle == 55 && d.sides[i].forks == 0);
		CHECK(d.sides[i].fork_at == 0.5 && d.sides[i].fork_a == 30 && d.sides[i].fork_b == 30);
		CHECK_INT(d.sides[i].line, 0);
	}
	CHECK(d.sides[2].angle == 0 && d.sides[3].angle == 0); /* past nsides: zero */
	CHECK(d.junction == 0.4 && d.theta0 == 200 && d.width == 0.35 && d.power == 0.8);
	CHECK(d.line == 0 && d.line_middle == 0 && d.line_cut == 0);
	CHECK_INT(ori_design_check(&d, &at, &err), 0);

	memset(&d, 0x5a, sizeof(d));
	ori_design_default(&d, ORI_FOLD_HALF);
	CHECK_INT(d.fold, ORI_FOLD_HALF);
	CHECK(d.size == 0.08 && d.rest == 0.9);
	CHECK(d.middle[0] == 90 && d.middle[1] == 90);
	CHECK_INT(d.nnodes, 0);
	CHECK_INT(d.nsides, 0);
	CHECK(d.sides[0].angle == 0);
	CHECK(d.junction == 0.4 && d.theta0 == 200 && d.width == 0.35 && d.power == 0.8);
	CHECK(d.line == 0 && d.line_middle == 0 && d.line_cut == 0);
	CHECK_INT(ori_design_check(&d, &at, &err), 0);
}

/* What a file leaves out is the default of its fold; spelling the defaults out reads the
 * same. What the file leaves out is told at its first line. */
static void test_round_trip_defaults(void)
{
	static const char fan_full[] = "edaha-leaf: 1\n"
				       "name: leaf\n"
				       "fold: fan\n"
				       "size: 0.08\n"
				       "rest: 0.9\n"
				       "middle:\n"
				       "  angle: 60\n"
				       "  nodes: []\n"
				       "sides:\n"
				       "  - {angle: 55, forks: 0, fork: {at: 0.5, a: 30, b: 30}}\n"
				       "  - {angle: 55}\n"
				       "cut:\n"
				       "  junction: 0.4\n"
				       "  theta0: 200\n";
	static const char half_full[] = "# the half fold's defaults\n"
					"edaha-leaf: 1\n"
					"fold: half\n"
					"name: leaf\n"
					"size: 0.08\n"
					"rest: 0.9\n"
					"middle: {angle: [90, 90]}\n"
					"cut: {width: 0.35, power: 0.8}\n";
	struct ori_design want, d;

	ori_design_default(&want, ORI_FOLD_FAN);
	read_ok("edaha-leaf: 1\n", &d);
	check_same(&d, &want);
	CHECK(d.line == 1 && d.line_middle == 1 && d.line_cut == 1);
	CHECK(d.sides[0].line == 1 && d.sides[1].line == 1);
	read_ok("edaha-leaf: 1\nfold: fan\n", &d);
	check_same(&d, &want);
	read_ok(fan_full, &d);
	check_same(&d, &want);
	CHECK(d.line == 1 && d.line_middle == 6 && d.line_cut == 12);
	CHECK(d.sides[0].line == 10 && d.sides[1].line == 11);

	ori_design_default(&want, ORI_FOLD_HALF);
	read_ok("edaha-leaf: 1\nfold: half\n", &d);
	check_same(&d, &want);
	CHECK(d.line == 1 && d.line_middle == 1 && d.line_cut == 1);
	/* the fold decides the defaults wherever it is */
	read_ok("edaha-leaf: 1\nsize: 0.08\nfold: half\n", &d);
	check_same(&d, &want);
	read_ok(half_full, &d);
	check_same(&d, &want);
	CHECK(d.line == 2 && d.line_middle == 7 && d.line_cut == 8);
	/* flow style, on one line */
	read_ok("{edaha-leaf: 1, fold: half, cut: {width: 0.35}}", &d);
	check_same(&d, &want);
}

/* The hop preset's design: nodes, forks, both forms. */
static const char hop_block[] = "edaha-leaf: 1\n"
				"name: hop\n"
				"fold: fan\n"
				"size: 0.09\n"
				"middle:\n"
				"  angle: 80\n"
				"  nodes:\n"
				"    - {at: 0.3, phi: 45, psi: 32}\n"
				"    -\n"
				"      at: 0.55\n"
				"      phi: 40\n"
				"      psi: 30\n"
				"sides:\n"
				"  - angle: 60\n"
				"    forks: 2\n"
				"    fork: {at: 0.45, a: 28, b: 28}\n"
				"  - {angle: 55, forks: 1, fork: {at: 0.5, a: 30, b: 30}}\n"
				"cut:\n"
				"  junction: 0.45\n"
				"  theta0: 360\n";
static const char hop_pairs[] = "edaha-leaf: 1\n"
				"name: hop\n"
				"size: 0.09\n"
				"middle:\n"
				"  angle: [40, 40]\n"
				"  nodes:\n"
				"    - {at: 0.3, phi: [45, 45], psi: [32, 32]}\n"
				"    - {at: 0.55, phi: [40, 40], psi: 30}\n"
				"sides:\n"
				"  - {angle: 60, forks: 2, fork: {at: 0.45, a: 28, b: 28}}\n"
				"  - {angle: 55, forks: 1}\n"
				"cut: {junction: 0.45, theta0: 360}\n";

static void check_hop(const struct ori_design *d)
{
	CHECK(strcmp(d->name, "hop") == 0);
	CHECK_INT(d->fold, ORI_FOLD_FAN);
	CHECK(d->size == 0.09 && d->rest == 0.9);
	CHECK(d->middle[0] == 40 && d->middle[1] == 40);
	CHECK_INT(d->nnodes, 2);
	CHECK(d->nodes[0].at == 0.3 && d->nodes[0].phi[0] == 45 && d->nodes[0].phi[1] == 45);
	CHECK(d->nodes[0].psi[0] == 32 && d->nodes[0].psi[1] == 32);
	CHECK(d->nodes[1].at == 0.55 && d->nodes[1].phi[0] == 40 && d->nodes[1].phi[1] == 40);
	CHECK(d->nodes[1].psi[0] == 30 && d->nodes[1].psi[1] == 30);
	CHECK_INT(d->nsides, 2);
	CHECK(d->sides[0].angle == 60 && d->sides[0].forks == 2 && d->sides[0].fork_at == 0.45);
	CHECK(d->sides[0].fork_a == 28 && d->sides[0].fork_b == 28);
	CHECK(d->sides[1].angle == 55 && d->sides[1].forks == 1 && d->sides[1].fork_at == 0.5);
	CHECK(d->sides[1].fork_a == 30 && d->sides[1].fork_b == 30);
	CHECK(d->junction == 0.45 && d->theta0 == 360);
}

static void test_forms(void)
{
	struct ori_design a, b;
	struct error err;
	int ret;

	read_ok(hop_block, &a);
	check_hop(&a);
	/* the lines: the version's, the middle and cut keys', each list item's */
	CHECK(a.line == 1 && a.line_middle == 5 && a.line_cut == 18);
	CHECK(a.nodes[0].line == 8 && a.nodes[1].line == 10);
	CHECK(a.sides[0].line == 14 && a.sides[1].line == 17);
	CHECK(a.nodes[2].line == 0 && a.sides[2].line == 0);
	/* a number for both sides (middle.angle: their sum), or [right, left]: the same */
	read_ok(hop_pairs, &b);
	check_hop(&b);
	check_same(&a, &b);
	read_ok("edaha-leaf: 1\nmiddle: {angle: 61}\n", &a);
	CHECK(a.middle[0] == 30.5 && a.middle[1] == 30.5);
	read_ok("edaha-leaf: 1\nmiddle: {angle: [30.5, 30.5]}\n", &b);
	check_same(&a, &b);
	/* a list of side parts replaces the defaults' */
	read_ok("edaha-leaf: 1\nsides: [{angle: 40}]\n", &a);
	CHECK_INT(a.nsides, 1);
	CHECK(a.sides[0].angle == 40 && a.sides[0].forks == 0 && a.sides[0].fork_at == 0.5);
	CHECK(a.sides[1].angle == 0 && a.sides[1].line == 0);
	read_ok("edaha-leaf: 1\nsides: []\n", &a);
	CHECK_INT(a.nsides, 0);
	/* a vein that does not fork may keep its fork's settings */
	read_ok("edaha-leaf: 1\nsides: [{angle: 50, fork: {at: 0.3}}, {angle: 40}]\n", &a);
	CHECK(a.sides[0].forks == 0 && a.sides[0].fork_at == 0.3);
	/* different right and left values are not the reader's to refuse: ori_build's,
	 * at the node's line */
	ret = read_text("edaha-leaf: 1\nmiddle:\n  angle: 70\n  nodes:\n"
			"    - {at: 0.35, phi: [55, 56], psi: 28}\n", &a, &err);
	if (ret != 0) {
		CHECK_INT(ret, -EINVAL);
		CHECK(strncmp(err.msg, "t:5: ", 5) == 0);
		CHECK(!strstr(err.msg, "not within") && !strstr(err.msg, "strictly between"));
	} else {
		CHECK(a.nodes[0].phi[0] == 55 && a.nodes[0].phi[1] == 56);
	}
	/* a side part's vein with nodes: block and flow, a number or [right, left]; the lines
	 * of the part and of each node */
	read_ok("edaha-leaf: 1\n"
		"sides:\n"
		"  - angle: 50\n"
		"    nodes:\n"
		"      - {at: 0.5, phi: 30, psi: 22}\n"
		"      -\n"
		"        at: 0.7\n"
		"        phi: 28\n"
		"        psi: 20\n"
		"  - angle: 40\n", &a);
	CHECK_INT(a.nsides, 2);
	CHECK_INT(a.sides[0].nnodes, 2);
	CHECK_INT(a.sides[1].nnodes, 0);
	CHECK(a.sides[0].nodes[0].at == 0.5 && a.sides[0].nodes[0].phi[1] == 30);
	CHECK(a.sides[0].nodes[1].at == 0.7 && a.sides[0].nodes[1].psi[0] == 20);
	CHECK(a.sides[0].line == 3 && a.sides[0].nodes[0].line == 5 &&
	      a.sides[0].nodes[1].line == 7 && a.sides[1].line == 10);
	read_ok("edaha-leaf: 1\nsides: [{angle: 50, nodes: [{at: 0.5, phi: [30, 30], psi: 22}, "
		"{at: 0.7, phi: 28, psi: [20, 20]}]}, {angle: 40}]\n", &b);
	check_same(&a, &b);
	/* no error to fill */
	CHECK_INT(ori_read("size: 1\n", 8, "t", &a, NULL), -EINVAL);
}

static void test_presets(void)
{
	const char *const *names;
	struct ori_design d;
	struct error err;
	size_t n;

	names = ori_preset_names(&n);
	CHECK_INT(n, 3);
	CHECK(strcmp(names[0], "entire") == 0 && strcmp(names[1], "hop") == 0 &&
	      strcmp(names[2], "maple") == 0);
	/* every one compiled in, and nothing else */
	CHECK_INT(ori_preset_ntexts, n);
	for (size_t i = 0; i < n; i++) {
		CHECK(strcmp(ori_preset_texts[i].name, names[i]) == 0);
		memset(&d, 0x5a, sizeof(d));
		if (ori_preset(names[i], &d, &err) != 0) {
			fprintf(stderr, "preset %s: %s\n", names[i], err.msg);
			CHECK(0);
		}
		CHECK(strcmp(d.name, names[i]) == 0);
	}
	CHECK(ori_preset_names(NULL) == names);

	CHECK_INT(ori_preset("entire", &d, &err), 0);
	CHECK_INT(d.fold, ORI_FOLD_HALF);
	CHECK(d.size == 0.06 && d.rest == 0.9 && d.middle[0] == 90 && d.middle[1] == 90);
	CHECK(d.nnodes == 0 && d.nsides == 0 && d.width == 0.32 && d.power == 0.8);

	/* issue 24: a momiji, seven lobes, two nodes on the five upper lobes' veins and one on
	 * the outermost pair's: 74 triangles a leaf */
	CHECK_INT(ori_preset("maple", &d, &err), 0);
	CHECK_INT(d.fold, ORI_FOLD_FAN);
	CHECK(d.size == 0.08 && d.middle[0] == 18 && d.middle[1] == 18);
	CHECK_INT(d.nnodes, 2);
	CHECK(d.nodes[0].at == 0.5 && d.nodes[0].phi[0] == 30 && d.nodes[0].psi[0] == 22);
	CHECK_INT(d.nsides, 3);
	CHECK(d.sides[0].angle == 38 && d.sides[1].angle == 38 && d.sides[2].angle == 38);
	CHECK(d.sides[0].nnodes == 2 && d.sides[1].nnodes == 1 && d.sides[2].nnodes == 1);
	CHECK(d.sides[0].nodes[1].at == 0.72 && d.sides[2].nodes[0].at == 0.6);
	CHECK(d.sides[0].forks == 0 && d.sides[1].forks == 0 && d.sides[2].forks == 0);
	CHECK(d.junction == 0.25 && d.theta0 == 400);
	/* 36 + 2 (38 + 38 + 38) degrees */
	CHECK(d.middle[0] + d.middle[1] + 2 * (d.sides[0].angle + d.sides[1].angle +
					       d.sides[2].angle) == 264);

	CHECK_INT(ori_preset("hop", &d, &err), 0);
	/* issue 24: three nodes on the midrib, two on the side lobes' veins, one on the base's
	 * halves': 64 triangles a leaf */
	CHECK(strcmp(d.name, "hop") == 0 && d.fold == ORI_FOLD_FAN && d.size == 0.09);
	CHECK_INT(d.nnodes, 3);
	CHECK(d.nodes[0].at == 0.4 && d.nodes[0].phi[0] == 58 && d.nodes[0].psi[0] == 42);
	CHECK_INT(d.nsides, 2);
	CHECK(d.sides[0].nnodes == 2 && d.sides[1].nnodes == 1);
	CHECK(d.sides[0].forks == 0 && d.sides[1].forks == 0);
	CHECK(d.junction == 0.38 && d.theta0 == 290);
	CHECK(d.middle[0] + d.middle[1] + 2 * (d.sides[0].angle + d.sides[1].angle) == 350);

	memset(&d, 0x5a, sizeof(d));
	CHECK_INT(ori_preset("oak", &d, &err), -EINVAL);
	CHECK(strstr(err.msg, "oak") != NULL);
	CHECK_INT(ori_preset(NULL, &d, &err), -EINVAL);
	CHECK(d.size != 0.08); /* untouched: still the pattern */
}

static int read_one(const char *data, size_t len, const char *path, void *out,
		    struct error *err)
{
	return ori_read(data, len, path, out, err);
}

static void test_malformed(const char *dir)
{
	struct ori_design scratch;

	CHECK(malformed_dir_check(dir, read_one, &scratch, sizeof(scratch)) >= 30);
}

static void test_too_large(void)
{
	size_t big = ORI_READ_MAX_BYTES + 1;
	char *huge = malloc(big);
	struct ori_design d;
	struct error err;

	CHECK(huge);
	memset(huge, '#', big);
	memset(&d, 0x5a, sizeof(d));
	CHECK_INT(ori_read(huge, big, "huge", &d, &err), -EINVAL);
	CHECK(strncmp(err.msg, "huge:1: larger than", 19) == 0);
	/* a comment just within: an empty file */
	CHECK_INT(ori_read(huge, big - 1, "huge", &d, &err), -EINVAL);
	CHECK(strncmp(err.msg, "huge:1: empty", 13) == 0);
	free(huge);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	test_defaults();
	test_round_trip_defaults();
	test_forms();
	test_presets();
	test_malformed(argv[1]);
	test_too_large();
	return 0;
}
