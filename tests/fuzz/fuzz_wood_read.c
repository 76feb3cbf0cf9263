/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the wood settings reader (wood_read, docs/wood-format.md) on arbitrary
 * bytes. A refusal names the file and a line of it ("fuzz:LINE: "; only running out of
 * memory may name the file alone) and changes nothing. What is accepted is within every
 * range of the format's table (checked here from the table, and by wood_params_check),
 * and it reads the same a second time.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_refusal.h"
#include "wood.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_refusal(int ret, const struct error *err, const struct wood_params *p,
			  const struct wood_params *before, unsigned long lines)
{
	fuzz_check_refusal(ret, err, lines);
	if (memcmp(p, before, sizeof(*p)) != 0)
		abort();
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi;
}

/* docs/wood-format.md's table, written out again: not wood_params_check's code. */
static void check_ranges(const struct wood_params *p)
{
	if (p->mode != WOOD_CONIFER && p->mode != WOOD_BROADLEAF)
		abort();
	if ((p->grid != 64 && p->grid != 128) || !in(p->alpha, 0, 1e6) || !in(p->beta, 0.1, 10) ||
	    !in(p->gravity, 0, 1))
		abort();
	if (!in(p->wind[0], -1, 1) || p->wind[1] != 0 || !in(p->wind[2], -1, 1))
		abort();
}

/* Field by field: struct padding is no part of the settings. */
static bool same(const struct wood_params *a, const struct wood_params *b)
{
	return a->mode == b->mode && a->grid == b->grid && a->alpha == b->alpha &&
	       a->beta == b->beta && a->gravity == b->gravity && a->wind[0] == b->wind[0] &&
	       a->wind[1] == b->wind[1] && a->wind[2] == b->wind[2];
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct wood_params p, before, again;
	struct error err = { { 0 } };
	const char *key = NULL;
	int ret;

	memset(&p, 0x5a, sizeof(p));
	memcpy(&before, &p, sizeof(p)); /* padding too: a refusal leaves every byte */
	ret = wood_read((const char *)data, size, "fuzz", 0, &p, &err);
	if (ret < 0) {
		check_refusal(ret, &err, &p, &before, fuzz_lines_of(data, size));
		return 0;
	}
	if (ret != 0 || wood_params_check(&p, &key, &err) != 0)
		abort();
	check_ranges(&p);
	if (wood_read((const char *)data, size, "again", 0, &again, &err) != 0 || !same(&p, &again))
		abort();
	return 0;
}
