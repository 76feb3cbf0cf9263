/* SPDX-License-Identifier: MIT */
/*
 * The vine parameter reader (vine_read, docs/vine-format.md): the defaults, every key
 * read, the presets, each limit taken and just missed, and every malformed file in
 * tests/vine/malformed refused at the line its EXPECT file names, the parameters untouched.
 *   test_vine_read MALFORMED_DIR
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fileio.h"
#include "malformed_dir.h"
#include "test.h"
#include "vine.h"
#include "vine_presets.h"

static int read_text(const char *text, struct vine_params *p, struct error *err)
{
	return vine_read(text, strlen(text), "t", p, err);
}

/* Reads text, which must be accepted (else says why) and be within every limit. */
static void read_ok(const char *text, struct vine_params *p)
{
	struct error err;
	const char *key = NULL;

	if (read_text(text, p, &err) != 0) {
		fprintf(stderr, "refused: %s\n---\n%s---\n", err.msg, text);
		CHECK(0);
	}
	CHECK_INT(vine_params_check(p, &key, &err), 0);
}

/* Reads text, which must be refused at "t:LINE: " with a message holding want, p as
 * it was. */
static void read_bad(const char *text, unsigned long line, const char *want)
{
	struct vine_params p, before;
	struct error err;
	char head[32];
	int ret;

	memset(&p, 0xa5, sizeof(p));
	memcpy(&before, &p, sizeof(p));
	ret = read_text(text, &p, &err);
	snprintf(head, sizeof(head), "t:%lu: ", line);
	if (ret != -EINVAL || strncmp(err.msg, head, strlen(head)) || !strstr(err.msg, want)) {
		fprintf(stderr, "expected \"%s...%s...\", got %d \"%s\"\n---\n%s---\n", head, want, ret,
			ret ? err.msg : "", text);
		CHECK(0);
	}
	CHECK(memcmp(&p, &before, sizeof(p)) == 0);
}

/* Field by field: padding is no part of the parameters. */
static void check_same(const struct vine_params *a, const struct vine_params *b)
{
	CHECK(a->internode == b->internode && a->radius == b->radius);
	CHECK(a->step_time == b->step_time && a->angle == b->angle);
	CHECK_INT(a->free_nodes, b->free_nodes);
	CHECK_INT(a->twining, b->twining);
	CHECK_INT(a->leaves_per_node, b->leaves_per_node);
	CHECK_INT(a->cotyledons, b->cotyledons);
	CHECK(a->leaf_size == b->leaf_size);
	CHECK_INT(a->points_per_internode, b->points_per_internode);
	CHECK_INT(a->ring_sides, b->ring_sides);
	CHECK(a->sweep == b->sweep);
	CHECK_INT(a->internodes, b->internodes);
	CHECK(a->seed == b->seed);
}

static void test_defaults(void)
{
	struct vine_params p, q;
	struct error err;
	const char *key = "x";

	memset(&p, 0x5a, sizeof(p));
	vine_params_default(&p);
	/* Table 4.1, one thesis unit a millimetre */
	CHECK(p.internode == 0.060 && p.radius == 0.002 && p.step_time == 10 && p.angle == 18);
	CHECK_INT(p.free_nodes, 1);
	CHECK_INT(p.twining, VINE_LEFT);
	CHECK_INT(p.leaves_per_node, 1); /* alternate, as Table 4.1's */
	CHECK_INT(p.cotyledons, 1);
	CHECK(p.leaf_size == 0.012);
	/* edaha's own: 22.5 degrees a new point, a turn every two internodes */
	CHECK_INT(p.points_per_internode, 8);
	CHECK_INT(p.ring_sides, 8);
	CHECK(p.sweep == 2.25);
	CHECK(p.sweep * p.step_time * p.points_per_internode * 2 == 360);
	CHECK_INT(p.internodes, 40);
	CHECK(p.seed == 1);
	CHECK_INT(vine_params_check(&p, &key, &err), 0);
	CHECK(strcmp(key, "x") == 0); /* untouched when all is well */
	CHECK_INT(vine_params_check(&p, NULL, NULL), 0);

	/* the version alone is the defaults; so is every key spelled out at its default */
	read_ok("edaha-vine: 1\n", &q);
	check_same(&p, &q);
	read_ok("edaha-vine: 1\ninternode: 0.06\nradius: 0.002\nstep_time: 10\nangle: 18\n"
		"free_nodes: 1\ntwining: left\nleaves_per_node: 1\ncotyledons: 1\n"
		"leaf_size: 0.012\npoints_per_internode: 8\nring_sides: 8\nsweep: 2.25\n"
		"internodes: 40\nseed: 1\n", &q);
	check_same(&p, &q);
}

/* vine_params_check on values no file can give: NaN, an unknown twining. */
static void test_check(void)
{
	struct vine_params p;
	struct error err;
	const char *key = NULL;

	vine_params_default(&p);
	p.angle = NAN;
	CHECK_INT(vine_params_check(&p, &key, &err), -EINVAL);
	CHECK(strcmp(key, "angle") == 0 && strncmp(err.msg, "angle: ", 7) == 0);
	vine_params_default(&p);
	p.twining = (enum vine_twining)7;
	CHECK_INT(vine_params_check(&p, &key, &err), -EINVAL);
	CHECK(strcmp(key, "twining") == 0);
	vine_params_default(&p);
	p.sweep = NAN;
	CHECK_INT(vine_params_check(&p, &key, NULL), -EINVAL);
	CHECK(strcmp(key, "sweep") == 0);
	vine_params_default(&p);
	p.internode = INFINITY;
	CHECK_INT(vine_params_check(&p, NULL, &err), -EINVAL);
	CHECK(strncmp(err.msg, "internode: ", 11) == 0);
}

static void test_every_key(void)
{
	static const char block[] = "# every key, none at its default\n"
				    "edaha-vine: 1\n"
				    "internode: 0.08\n"
				    "radius: 0.003\n"
				    "step_time: 12.5\n"
				    "angle: 25\n"
				    "free_nodes: 3\n"
				    "twining: right\n"
				    "leaves_per_node: 2\n"
				    "cotyledons: 0\n"
				    "leaf_size: 0.03\n"
				    "points_per_internode: 12\n"
				    "ring_sides: 6\n"
				    "sweep: 1.5\n"
				    "internodes: 250\n"
				    "seed: 18446744073709551615\n";
	static const char flow[] = "{edaha-vine: 1, seed: 18446744073709551615, internodes: 250,"
				   " sweep: 1.5e0, ring_sides: 6, points_per_internode: 12,"
				   " leaf_size: 3e-2, cotyledons: 0, leaves_per_node: 2.0,"
				   " twining: right, free_nodes: +3, angle: 25, step_time: 12.50,"
				   " radius: .003, internode: 0.080}";
	struct vine_params p, q;

	read_ok(block, &p);
	CHECK(p.internode == 0.08 && p.radius == 0.003 && p.step_time == 12.5 && p.angle == 25);
	CHECK_INT(p.free_nodes, 3);
	CHECK_INT(p.twining, VINE_RIGHT);
	CHECK_INT(p.leaves_per_node, 2);
	CHECK_INT(p.cotyledons, 0);
	CHECK(p.leaf_size == 0.03);
	CHECK_INT(p.points_per_internode, 12);
	CHECK_INT(p.ring_sides, 6);
	CHECK(p.sweep == 1.5);
	CHECK_INT(p.internodes, 250);
	CHECK(p.seed == UINT64_MAX);
	/* flow style, any order after the version, other spellings of the same numbers */
	read_ok(flow, &q);
	check_same(&p, &q);
	/* the seed exactly, past a double's 2^53 */
	read_ok("edaha-vine: 1\nseed: 9007199254740993\n", &p);
	CHECK(p.seed == 9007199254740993ull);
	read_ok("edaha-vine: 1\nseed: 18446744073709551614\n", &p);
	CHECK(p.seed == UINT64_MAX - 1);
	read_ok("edaha-vine: 1\nseed: 0\n", &p);
	CHECK(p.seed == 0);
	read_ok("edaha-vine: 1\nseed: 007\n", &p); /* decimal, as the numbers: not octal */
	CHECK(p.seed == 7);
	read_ok("edaha-vine: 1\ntwining: left\n", &p);
	CHECK_INT(p.twining, VINE_LEFT);
	/* comments, CRLF line ends, a document start and end */
	read_ok("--- # a vine\r\nedaha-vine: 1 # the version\r\nangle: 20\r\n...\r\n", &p);
	CHECK(p.angle == 20);
	read_bad("edaha-vine: 1\r\n\r\nangle: 70\r\n", 3, "angle: 70 is not within 5..60 degrees");
	/* nested four deep passes the prescan and is refused as the wrong type */
	read_bad("edaha-vine: 1\nangle: [[[18]]]\n", 2, "angle: expected a number, got a list");
	read_bad("edaha-vine: 1\nangle: [[[[18]]]]\n", 2, "nested more than 4 deep");
	/* no error to fill */
	CHECK_INT(vine_read("angle: 1\n", 9, "t", &p, NULL), -EINVAL);
	CHECK_INT(vine_read("edaha-vine: 1\nangle: 1\n", 23, "t", &p, NULL), -EINVAL);
}

/*
 * Each limit of docs/vine-format.md's table taken (read back exactly) and just missed
 * (refused at the key's line). extra: other keys the limit needs, before the key.
 */
static void test_limits(void)
{
	static const struct {
		const char *key, *extra, *ok, *bad;
	} limits[] = {
		{ "internode", "radius: 0.001\n", "0.005", "0.0049" },
		{ "internode", "", "1", "1.001" },
		{ "radius", "", "0.0005", "0.00049" },
		{ "radius", "internode: 1\n", "0.05", "0.0501" },
		{ "radius", "internode: 0.06\n", "0.0149", "0.015" }, /* below internode / 4 */
		{ "radius", "internode: 0.2\n", "0.0499", "0.05" },
		{ "step_time", "", "1", "0.99" },
		{ "step_time", "sweep: 0.45\n", "100", "100.01" },
		{ "angle", "", "5", "4.999" },
		{ "angle", "", "60", "60.001" },
		{ "free_nodes", "", "0", "-1" },
		{ "free_nodes", "", "5", "6" },
		{ "leaves_per_node", "", "0", "-1" },
		{ "leaves_per_node", "", "2", "3" },
		{ "cotyledons", "", "0", "-1" },
		{ "cotyledons", "", "2", "3" },
		{ "leaf_size", "", "0.001", "0.00099" },
		{ "leaf_size", "", "0.2", "0.2001" },
		{ "points_per_internode", "", "2", "1" },
		{ "points_per_internode", "", "32", "33" },
		{ "ring_sides", "", "3", "2" },
		{ "ring_sides", "", "16", "17" },
		{ "sweep", "", "0.1", "0.0999" },
		{ "sweep", "step_time: 1.5\n", "30", "30.001" },
		/* sweep x step_time at most 45, exactly */
		{ "sweep", "", "4.5", "4.5001" },
		{ "sweep", "step_time: 100\n", "0.45", "0.4501" },
		{ "sweep", "step_time: 50\n", "0.9", "0.90001" },
		{ "sweep", "step_time: 7\n", "6.42857", "6.42858" }, /* 45 / 7 = 6.428571.. */
		{ "internodes", "", "1", "0" },
		{ "internodes", "", "2000", "2001" },
	};
	char text[256], want[64];
	struct vine_params p;

	for (size_t i = 0; i < sizeof(limits) / sizeof(limits[0]); i++) {
		unsigned long line = 2;

		for (const char *c = limits[i].extra; *c; c++)
			line += *c == '\n';
		snprintf(text, sizeof(text), "edaha-vine: 1\n%s%s: %s\n", limits[i].extra,
			 limits[i].key, limits[i].ok);
		read_ok(text, &p);
		snprintf(text, sizeof(text), "edaha-vine: 1\n%s%s: %s\n", limits[i].extra,
			 limits[i].key, limits[i].bad);
		snprintf(want, sizeof(want), "%s: %s ", limits[i].key, limits[i].bad);
		read_bad(text, line, want);
	}
	/* read back exactly at the limits */
	read_ok("edaha-vine: 1\nstep_time: 100\nsweep: 0.45\n", &p);
	CHECK(p.step_time == 100 && p.sweep == 0.45);
	read_ok("edaha-vine: 1\ninternode: 1\nradius: 0.05\nangle: 60\nleaf_size: 0.2\n"
		"points_per_internode: 32\nring_sides: 16\nfree_nodes: 5\ninternodes: 2000\n", &p);
	CHECK(p.internode == 1 && p.radius == 0.05 && p.angle == 60 && p.leaf_size == 0.2);
	CHECK(p.points_per_internode == 32 && p.ring_sides == 16 && p.free_nodes == 5);
	CHECK_INT(p.internodes, 2000);
	read_ok("edaha-vine: 1\ninternode: 0.005\nradius: 0.0005\nangle: 5\nleaf_size: 0.001\n"
		"points_per_internode: 2\nring_sides: 3\nfree_nodes: 0\ninternodes: 1\n"
		"step_time: 1\nsweep: 0.1\nleaves_per_node: 0\ncotyledons: 0\n", &p);
	CHECK(p.internode == 0.005 && p.radius == 0.0005 && p.angle == 5 && p.leaf_size == 0.001);
	CHECK(p.step_time == 1 && p.sweep == 0.1);
	/* a limit two keys share, the default of one at fault: told at the other's line */
	read_bad("edaha-vine: 1\nangle: 20\ninternode: 0.008\n", 3,
		 "radius: 0.002 is not below internode / 4 (0.002 m)");
	read_bad("edaha-vine: 1\nstep_time: 21\n", 2, "sweep: 2.25 degrees per unit of time is "
		 "47.25 degrees a new point at step_time 21; at most 45");
	/* and at its own line when the file gives both */
	read_bad("edaha-vine: 1\nsweep: 3\nangle: 20\nstep_time: 20\n", 2, "sweep: 3 degrees");
	read_bad("edaha-vine: 1\nradius: 0.004\nangle: 20\ninternode: 0.016\n", 2,
		 "radius: 0.004 is not below internode / 4 (0.004 m)");
}

static void test_presets(void)
{
	const char *const *names;
	struct vine_params p, want;
	struct error err;
	size_t n;

	names = vine_preset_names(&n);
	CHECK_INT(n, 2);
	CHECK(strcmp(names[0], "default") == 0 && strcmp(names[1], "morning-glory") == 0);
	/* every one compiled in, and nothing else */
	CHECK_INT(vine_preset_ntexts, n);
	for (size_t i = 0; i < n; i++) {
		CHECK(strcmp(vine_preset_texts[i].name, names[i]) == 0);
		memset(&p, 0x5a, sizeof(p));
		if (vine_preset(names[i], &p, &err) != 0) {
			fprintf(stderr, "preset %s: %s\n", names[i], err.msg);
			CHECK(0);
		}
		CHECK_INT(vine_params_check(&p, NULL, &err), 0);
	}
	CHECK(vine_preset_names(NULL) == names);

	/* the default preset is the defaults, spelled out */
	vine_params_default(&want);
	CHECK_INT(vine_preset("default", &p, &err), 0);
	check_same(&p, &want);

	want.twining = VINE_RIGHT;
	want.angle = 30;
	want.leaves_per_node = 1;
	want.leaf_size = 0.02;
	CHECK_INT(vine_preset("morning-glory", &p, &err), 0);
	check_same(&p, &want);

	memset(&p, 0x5a, sizeof(p));
	CHECK_INT(vine_preset("hop", &p, &err), -EINVAL);
	CHECK(strstr(err.msg, "hop") != NULL);
	CHECK_INT(vine_preset(NULL, &p, &err), -EINVAL);
	CHECK(p.internode != 0.06); /* untouched: still the pattern */
}

static int read_one(const char *data, size_t len, const char *path, void *out,
		    struct error *err)
{
	return vine_read(data, len, path, out, err);
}

static void test_malformed(const char *dir)
{
	struct vine_params scratch;

	CHECK(malformed_dir_check(dir, read_one, &scratch, sizeof(scratch)) >= 40);
}

static void test_too_large(void)
{
	size_t big = VINE_READ_MAX_BYTES + 1;
	char *huge = malloc(big);
	struct vine_params p;
	struct error err;

	CHECK(huge);
	memset(huge, '#', big);
	memset(&p, 0x5a, sizeof(p));
	CHECK_INT(vine_read(huge, big, "huge", &p, &err), -EINVAL);
	CHECK(strncmp(err.msg, "huge:1: larger than", 19) == 0);
	/* a comment just within: an empty file */
	CHECK_INT(vine_read(huge, big - 1, "huge", &p, &err), -EINVAL);
	CHECK(strncmp(err.msg, "huge:1: empty", 13) == 0);
	free(huge);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	test_defaults();
	test_check();
	test_every_key();
	test_limits();
	test_presets();
	test_malformed(argv[1]);
	test_too_large();
	return 0;
}
