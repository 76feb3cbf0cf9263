/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the vine parameter reader (vine_read, docs/vine-format.md) on arbitrary
 * bytes. A refusal names the file and a line of it ("fuzz:LINE: "; only running out of
 * memory may name the file alone) and changes nothing. What is accepted is within every
 * range of the format's table (checked here from the table, and by vine_params_check),
 * and it reads the same a second time.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_refusal.h"
#include "vine.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_refusal(int ret, const struct error *err, const struct vine_params *p,
			  const struct vine_params *before, unsigned long lines)
{
	fuzz_check_refusal(ret, err, lines);
	if (memcmp(p, before, sizeof(*p)) != 0)
		abort();
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi;
}

/* docs/vine-format.md's table, written out again: not vine_params_check's code. */
static void check_ranges(const struct vine_params *p)
{
	if (!in(p->internode, 0.005, 1) || !in(p->radius, 0.0005, 0.05) ||
	    !(p->radius < p->internode / 4))
		abort();
	if (!in(p->step_time, 1, 100) || !in(p->angle, 5, 60) || !in(p->leaf_size, 0.001, 0.2))
		abort();
	if (p->free_nodes < 0 || p->free_nodes > 5 || p->leaves_per_node < 0 ||
	    p->leaves_per_node > 2 || p->cotyledons < 0 || p->cotyledons > 2)
		abort();
	if (p->twining != VINE_LEFT && p->twining != VINE_RIGHT)
		abort();
	if (p->points_per_internode < 2 || p->points_per_internode > 32 || p->ring_sides < 3 ||
	    p->ring_sides > 16 || p->internodes < 1 || p->internodes > 2000)
		abort();
	/* at most 45 degrees a new point, to rounding */
	if (!in(p->sweep, 0.1, 30) || !(p->sweep * p->step_time <= 45 * (1 + 1e-12)))
		abort();
}

/* Field by field: struct padding is no part of the parameters. */
static bool same(const struct vine_params *a, const struct vine_params *b)
{
	return a->internode == b->internode && a->radius == b->radius &&
	       a->step_time == b->step_time && a->angle == b->angle &&
	       a->free_nodes == b->free_nodes && a->twining == b->twining &&
	       a->leaves_per_node == b->leaves_per_node && a->cotyledons == b->cotyledons &&
	       a->leaf_size == b->leaf_size && a->points_per_internode == b->points_per_internode &&
	       a->ring_sides == b->ring_sides && a->sweep == b->sweep &&
	       a->internodes == b->internodes && a->seed == b->seed;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct vine_params p, before, again;
	struct error err = { { 0 } };
	const char *key = NULL;
	int ret;

	memset(&p, 0x5a, sizeof(p));
	memcpy(&before, &p, sizeof(p)); /* padding too: a refusal leaves every byte */
	ret = vine_read((const char *)data, size, "fuzz", &p, &err);
	if (ret < 0) {
		check_refusal(ret, &err, &p, &before, fuzz_lines_of(data, size));
		return 0;
	}
	if (ret != 0 || vine_params_check(&p, &key, &err) != 0)
		abort();
	check_ranges(&p);
	if (vine_read((const char *)data, size, "again", &again, &err) != 0 || !same(&p, &again))
		abort();
	return 0;
}
