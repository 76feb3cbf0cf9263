/* SPDX-License-Identifier: MIT */
/* Tree parameters: what gen_write puts on a drawing's line reads back exactly, the
 * defaults and presets are valid, and the kiosk's buttons change what
 * docs/functional-trees.md says they do. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gen.h"
#include "rng.h"
#include "test.h"

/* A valid parameter set of random type and values; what its type has no key for keeps
 * the type's default, as after reading a file. */
static void random_params(struct rng *r, struct gen_params *p)
{
	enum gen_type type = (enum gen_type)(rng_next(r) % GEN_TYPE_COUNT);
	struct error err;
	const char *key;

	do {
		gen_params_default(p, type);
		p->precision = 3 + (int)(rng_next(r) % 14);
		p->trunk_start = vec3(rng_range(r, -5, 5), rng_range(r, -1, 1), rng_range(r, -5, 5));
		if (type != GEN_SHRUB)
			p->trunk_end = vec3_add(p->trunk_start,
						vec3(rng_range(r, -0.3, 0.3), rng_range(r, 0.5, 4),
						     rng_range(r, -0.3, 0.3)));
		p->angle_min = rng_range(r, 0, 60);
		p->angle_max = p->angle_min + rng_range(r, 0, 60);
		p->randomness = rng_uniform(r);
		p->thickness = rng_range(r, 0.01, 0.3);
		p->thickness_ratio = rng_range(r, 0.3, 1);
		p->leaf_amount = (int)(rng_next(r) % 8);
		p->leaf_size = rng_range(r, 0.01, 0.4);
		p->leaf_type = (enum gen_leaf)(rng_next(r) % GEN_LEAF_COUNT);
		p->season = (enum season)(rng_next(r) % SEASON_COUNT);
		if (type != GEN_PALM) {
			p->levels = 1 + (int)(rng_next(r) % 7);
			p->children = 2 + (int)(rng_next(r) % 2);
			for (int i = 0; i < p->children; i++)
				p->ratios[i] = rng_range(r, 0.3, 0.9);
			p->spread = rng_range(r, 0, 360);
			p->twist = rng_range(r, -360, 360);
		}
		if (type == GEN_SHRUB) {
			p->clip = (enum gen_clip)(rng_next(r) % GEN_CLIP_COUNT);
			p->trunk_height = rng_range(r, 0.3, 1.5);
			p->clip_center = vec3_add(p->trunk_start,
						  vec3(0, p->trunk_height + rng_range(r, 0, 0.5), 0));
			if (p->clip == GEN_CLIP_BOX)
				p->clip_size = vec3(rng_range(r, 1, 4), rng_range(r, 1.2, 3), rng_range(r, 1, 4));
			else
				p->clip_radius = rng_range(r, 0.6, 2);
			if (p->clip == GEN_CLIP_CONE) {
				p->clip_height = rng_range(r, 1.5, 4);
				p->clip_center.y = p->trunk_start.y + p->trunk_height * 0.5;
			}
		}
		if (type == GEN_PALM) {
			p->trunk_end = vec3_add(p->trunk_start,
						vec3(rng_range(r, -0.2, 0.2), 1, rng_range(r, -0.2, 0.2)));
			p->height = rng_range(r, 1, 12);
			p->fronds = 1 + (int)(rng_next(r) % 20);
			p->frond_length = rng_range(r, 0.5, 4);
			p->droop = rng_range(r, 0, 150);
		}
	} while (gen_params_check(p, &key, &err) < 0);
}

/* What the drawing stores reads back bit for bit, with every type's keys. */
static void test_round_trip(void)
{
	struct rng r;

	rng_seed(&r, 42);
	for (int i = 0; i < 2000; i++) {
		struct gen_params p, q;
		struct error err = { { 0 } };
		struct buf b;

		random_params(&r, &p);
		buf_init(&b);
		CHECK_INT(gen_write(&p, &b), 0);
		CHECK(!memchr(b.data, '\n', b.len)); /* one line of the drawing */
		if (gen_read((const char *)b.data, b.len, "line", 0, &q, &err) < 0) {
			fprintf(stderr, "%s\n%.*s\n", err.msg, (int)b.len, (const char *)b.data);
			CHECK(0);
		}
		CHECK(memcmp(&p, &q, sizeof(p)) == 0);
		buf_finish(&b);
	}
}

static void test_defaults_and_presets(void)
{
	for (int t = 0; t < GEN_TYPE_COUNT; t++) {
		struct gen_params p, q;
		struct error err;
		const char *key;
		char file[64];

		gen_params_default(&p, (enum gen_type)t);
		CHECK_INT(gen_params_check(&p, &key, &err), 0);
		/* a file with only the version and the type is the defaults */
		snprintf(file, sizeof(file), "edaha-tree: 1\ntype: %s\n", gen_type_name((enum gen_type)t));
		CHECK_INT(gen_read(file, strlen(file), "t.yaml", 0, &q, &err), 0);
		CHECK(memcmp(&p, &q, sizeof(p)) == 0);
	}
	for (int i = 0; i < GEN_PRESET_COUNT; i++) {
		struct gen_params p;
		struct error err = { { 0 } };
		struct tree t;

		if (gen_preset((enum gen_preset)i, &p, &err) < 0) {
			fprintf(stderr, "%s\n", err.msg);
			CHECK(0);
		}
		tree_init(&t);
		CHECK_INT(gen_build(&t, &p, 1), 0);
		CHECK(t.nbranches > 1 && t.nleaves > 1 && t.lifted);
		tree_finish(&t);
	}
}

/* The errors name the line of the value at fault, the first line for a default's. */
static void test_error_lines(void)
{
	static const struct {
		const char *text, *want;
	} cases[] = {
		{ "edaha-tree: 1\nlevels: 13\n", "f:2: levels: 13 is not within 1..12" },
		{ "edaha-tree: 1\nangle:\n  min: 10\n  max: 400\n", "f:4: angle.max: 400 is not within 0..180" },
		{ "edaha-tree: 1\nleaves: {amount: 3, size: 9}\n", "f:2: leaves.size: 9 is not within" },
		{ "edaha-tree: 1\ntype: shrub\nclip: {shape: box, radius: 2}\n",
		  "f:3: clip.radius: not a measure of a box" },
		{ "edaha-tree: 1\ntype: shrub\ntrunk_height: 3\n", "f:3: trunk_height: the trunk's top" },
		{ "edaha-tree: 1\nchildren: 3\nlevels: 10\n", "f:3: the tree would have 29524 branches" },
		{ "edaha-tree: 1\ntype: palm\ntrunk: {end: [1, 1, 0]}\n", "f:3: trunk: a palm's trunk leans" },
		{ "edaha-tree: 1\nlevels: 3\nlevels: 4\n", "f:3: duplicate key \"levels\" (first on line 2)" },
		{ "edaha-tree: 2\n", "f:1: edaha-tree: version 2" },
		{ "type: palm\n", "f:1: not a tree parameter file" },
		{ "edaha-tree: 1\nthickness: 0x10\n", "f:2: thickness: \"0x10\" is not a number" },
		{ "edaha-tree: 1\nthickness: .nan\n", "f:2: thickness: \".nan\" is not a number" },
		{ "edaha-tree: 1\nleaves: {type: ginkgo}\n", "f:2: leaves.type: \"ginkgo\" is none of" },
		{ "edaha-tree: 1\nlevels: 2.5\n", "f:2: levels: expected a whole number" },
		{ "edaha-tree: 1\n---\nedaha-tree: 1\n", "f:3: a second YAML document" },
		/* libyaml marks an empty document at the end of unended text a line past the last */
		{ "edaha-tree: 1\n---", "f:2: a second YAML document" },
		{ "edaha-tree: 1\nlevels:", "f:2: levels: \"\" is not a number" },
		{ "edaha-tree: 1\ntrunk: {start: [0, 0]}\n", "f:2: trunk.start: expected [x, y, z], three" },
		{ "edaha-tree: 1\nseason: monsoon\n", "f:2: season: \"monsoon\" is none of" },
	};

	for (size_t i = 0; i < sizeof(cases) / sizeof(*cases); i++) {
		struct gen_params p;
		struct error err = { { 0 } };
		int ret = gen_read(cases[i].text, strlen(cases[i].text), "f", 0, &p, &err);

		if (ret != -EINVAL || strncmp(err.msg, cases[i].want, strlen(cases[i].want))) {
			fprintf(stderr, "case %zu: %d \"%s\", wanted \"%s\"\n", i, ret, err.msg, cases[i].want);
			CHECK(0);
		}
	}
	/* in a drawing, the line's number */
	{
		struct gen_params p;
		struct error err = { { 0 } };
		const char *line = "{edaha-tree: 1, levels: 0}";

		CHECK_INT(gen_read(line, strlen(line), "drawing.edaha", 6, &p, &err), -EINVAL);
		CHECK(!strncmp(err.msg, "drawing.edaha:7: levels: 0", 26));
	}
}

/* The parameter buttons (docs/functional-trees.md's table). */
static void test_adjust(void)
{
	struct gen_params p, q;

	gen_params_default(&p, GEN_LSYSTEM);
	CHECK(gen_adjust(&p, GEN_MORE, &q) && q.levels == p.levels + 1);
	CHECK(gen_adjust(&p, GEN_FEWER, &q) && q.levels == p.levels - 1);
	CHECK(gen_adjust(&p, GEN_WIDER, &q) && q.angle_min == p.angle_min + 8 &&
	      q.angle_max == p.angle_max + 8 && q.spread == fmin(180, p.spread + 20));
	CHECK(gen_adjust(&p, GEN_NARROWER, &q) && q.angle_min == p.angle_min - 8 && q.spread == p.spread - 20);
	CHECK(gen_adjust(&p, GEN_TALLER, &q) && fabs(q.ratios[1] / p.ratios[1] - 1.15) < 1e-12);
	CHECK(gen_adjust(&p, GEN_SHORTER, &q) && fabs(p.ratios[1] / q.ratios[1] - 1.15) < 1e-12);
	CHECK(gen_adjust(&p, GEN_LEAFIER, &q) && q.leaf_amount == p.leaf_amount + 2);
	CHECK(gen_adjust(&p, GEN_BARER, &q) && q.leaf_amount == p.leaf_amount - 2);
	/* at a limit nothing changes */
	p.levels = 1;
	CHECK(!gen_adjust(&p, GEN_FEWER, &q) && !memcmp(&p, &q, sizeof(p)));
	p.levels = 12;
	CHECK(!gen_adjust(&p, GEN_MORE, &q)); /* 4095 branches is fine, but its leaves are not */
	p.leaf_amount = 0;
	CHECK(!gen_adjust(&p, GEN_BARER, &q));

	gen_params_default(&p, GEN_PALM);
	CHECK(gen_adjust(&p, GEN_MORE, &q) && q.fronds == p.fronds + 2 && q.levels == p.levels);
	CHECK(gen_adjust(&p, GEN_WIDER, &q) && fabs(q.frond_length / p.frond_length - 1.15) < 1e-12);
	CHECK(gen_adjust(&p, GEN_TALLER, &q) && fabs(q.height / p.height - 1.15) < 1e-12);
	CHECK(gen_adjust(&p, GEN_LEAFIER, &q) && q.leaf_amount == p.leaf_amount + 8);

	gen_params_default(&p, GEN_SHRUB);
	CHECK(gen_adjust(&p, GEN_TALLER, &q) && fabs(q.trunk_height / p.trunk_height - 1.15) < 1e-12 &&
	      fabs(q.clip_radius / p.clip_radius - 1.15) < 1e-12 && q.trunk_start.y == p.trunk_start.y);
	/* a shrub's shape decides its crown: wider widens the shape about its centre */
	CHECK(gen_adjust(&p, GEN_WIDER, &q) && fabs(q.clip_radius / p.clip_radius - 1.15) < 1e-12 &&
	      q.clip_center.y == p.clip_center.y && q.angle_min == p.angle_min && q.spread == p.spread);
	CHECK(gen_adjust(&p, GEN_NARROWER, &q) && fabs(p.clip_radius / q.clip_radius - 1.15) < 1e-12);
	p.clip = GEN_CLIP_BOX; /* [2, 1, 1] round (0, 1.5, 0): the trunk up into it */
	p.trunk_height = 1.5;
	CHECK(gen_adjust(&p, GEN_WIDER, &q) && fabs(q.clip_size.x / p.clip_size.x - 1.15) < 1e-12 &&
	      fabs(q.clip_size.z / p.clip_size.z - 1.15) < 1e-12 && q.clip_size.y == p.clip_size.y);
	/* levels add tips above what the shape needs (3^6 = 729 > 3^5 = 243 > 256 > 81): below,
	 * fewer changes nothing and is refused */
	p.levels = 7;
	CHECK(gen_adjust(&p, GEN_FEWER, &q) && q.levels == 6);
	CHECK(gen_count_branches(&q) < gen_count_branches(&p));
	p.levels = 6;
	CHECK(!gen_adjust(&p, GEN_FEWER, &q) && !memcmp(&p, &q, sizeof(p)));
	CHECK(gen_adjust(&p, GEN_MORE, &q) && q.levels == 7);
}

int main(void)
{
	test_round_trip();
	test_defaults_and_presets();
	test_error_lines();
	test_adjust();
	return 0;
}
