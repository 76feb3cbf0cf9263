/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the tree parameter reader (gen_read, docs/tree-params.md) on arbitrary bytes.
 * A refusal names the file and a line of it (fuzz_refusal.h) and changes nothing. What is
 * accepted is within every limit, is written by gen_write as one line that reads back to
 * the same parameters (a drawing's generate line), and, when the tree is small, builds at
 * every generator version whose limits take it: every element its generator's, no more
 * than that version's counts said (an lsystem tree's and a palm's exactly).
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "fuzz_refusal.h"
#include "gen.h"
#include "tree.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Field by field: struct padding is not part of the parameters. */
static bool same(const struct gen_params *a, const struct gen_params *b)
{
	bool ok = a->type == b->type && a->precision == b->precision && a->levels == b->levels &&
		  a->children == b->children && a->leaf_amount == b->leaf_amount &&
		  a->leaf_type == b->leaf_type && a->season == b->season && a->clip == b->clip &&
		  a->fronds == b->fronds;
	const double da[] = { a->trunk_start.x, a->trunk_start.y, a->trunk_start.z, a->trunk_end.x,
			      a->trunk_end.y, a->trunk_end.z, a->angle_min, a->angle_max, a->randomness,
			      a->ratios[0], a->ratios[1], a->ratios[2], a->spread, a->twist, a->thickness,
			      a->thickness_ratio, a->leaf_size, a->trunk_height, a->clip_center.x,
			      a->clip_center.y, a->clip_center.z, a->clip_radius, a->clip_size.x,
			      a->clip_size.y, a->clip_size.z, a->clip_height, a->height, a->frond_length,
			      a->droop };
	const double db[] = { b->trunk_start.x, b->trunk_start.y, b->trunk_start.z, b->trunk_end.x,
			      b->trunk_end.y, b->trunk_end.z, b->angle_min, b->angle_max, b->randomness,
			      b->ratios[0], b->ratios[1], b->ratios[2], b->spread, b->twist, b->thickness,
			      b->thickness_ratio, b->leaf_size, b->trunk_height, b->clip_center.x,
			      b->clip_center.y, b->clip_center.z, b->clip_radius, b->clip_size.x,
			      b->clip_size.y, b->clip_size.z, b->clip_height, b->height, b->frond_length,
			      b->droop };

	for (size_t i = 0; i < sizeof(da) / sizeof(da[0]); i++)
		ok = ok && da[i] == db[i];
	return ok;
}

/* fuzz_refusal.h's rule, and the parameters left as they were */
static void check_refusal(int ret, const struct error *err, const struct gen_params *p,
			  const struct gen_params *before, unsigned long lines)
{
	fuzz_check_refusal(ret, err, lines);
	if (memcmp(p, before, sizeof(*p)) != 0)
		abort();
}

/*
 * The trees built at fuzzing speed: up to 200 branches and 600 leaves; a shrub, which at
 * version 2 has at least 256 tips (390 branches with 3 children, 511 with 2), up to
 * SHRUB_MAX_BRANCHES and SHRUB_MAX_LEAVES: the shape presets of the corpus (729 tips of 3
 * leaves) at both versions, and what their mutations keep as sparse. On the corpus, 30 s
 * of the clang ASan+UBSan build ran 82,000 to 97,000 inputs (2,600 to 3,100 a second, on
 * the shared 2-core build machine; 7,200 with the old bound of 200 branches for shrubs,
 * which built none: every shrub has at least 390 since issue 24).
 */
#define MAX_BRANCHES 200
#define MAX_LEAVES 600
#define SHRUB_MAX_BRANCHES 1100
#define SHRUB_MAX_LEAVES 3300

static void build_version(const struct gen_params *p, int version, uint64_t seed)
{
	struct gen_params q = *p;
	size_t nb, nl;
	int ret;
	struct error why;
	const char *key;
	struct tree t;

	q.gen_version = version;
	/* an older version's limits may refuse what this one takes */
	if (gen_params_check(&q, &key, &why) != 0)
		return;
	nb = gen_count_branches(&q);
	nl = gen_count_leaves(&q);
	if (nb > (q.type == GEN_SHRUB ? SHRUB_MAX_BRANCHES : MAX_BRANCHES) ||
	    nl > (q.type == GEN_SHRUB ? SHRUB_MAX_LEAVES : MAX_LEAVES))
		return;
	tree_init(&t);
	ret = gen_build(&t, &q, seed);
	if (ret != 0 && ret != -ENOMEM)
		abort(); /* its parameters passed the check */
	if (ret == 0 && (t.nbranches == 0 || t.nbranches > nb || t.nleaves > nl ||
	    (q.type != GEN_SHRUB && t.nbranches != nb) || (q.type != GEN_SHRUB && t.nleaves != nl) ||
	    t.sides != q.precision))
		abort();
	for (size_t i = 0; i < t.nbranches; i++)
		if (t.branches[i].origin != ORIGIN_GENERATE)
			abort();
	tree_finish(&t);
}

static void build(const struct gen_params *p, uint64_t seed)
{
	for (int v = 1; v <= GEN_VERSION; v++)
		build_version(p, v, seed);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct gen_params p, before, again;
	struct error err = { { 0 } }, why;
	const char *key;
	struct buf line;
	int ret;

	memset(&p, 0x5a, sizeof(p));
	memcpy(&before, &p, sizeof(p)); /* padding too: a refusal leaves every byte */
	ret = gen_read((const char *)data, size, "fuzz", 0, &p, &err);
	if (ret < 0) {
		check_refusal(ret, &err, &p, &before, fuzz_lines_of(data, size));
		return 0;
	}
	if (gen_params_check(&p, &key, &why) != 0)
		abort();
	buf_init(&line);
	if (gen_write(&p, &line) == 0) {
		if (memchr(line.data, '\n', line.len) || memchr(line.data, '\0', line.len))
			abort();
		if (gen_read((const char *)line.data, line.len, "again", 9, &again, &err) != 0)
			abort();
		if (!same(&p, &again))
			abort();
	}
	buf_finish(&line);
	build(&p, size);
	return 0;
}
