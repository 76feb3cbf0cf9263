/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the origami leaf design reader (ori_read, docs/leaf-format.md) on arbitrary
 * bytes. A refusal names the file and a line of it ("fuzz:LINE: "; only running out of
 * memory may name the file alone) and changes nothing. What is accepted is within every
 * range of the format's table (checked here from the table, and by ori_design_check), its
 * lines are lines of the input, and it reads the same a second time.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_refusal.h"
#include "ori.h"
#include "ori_design.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The message and code by the shared rule; the struct as it was. */
static void check_refusal(int ret, const struct error *err, const struct ori_design *d,
			  const struct ori_design *before, unsigned long lines)
{
	fuzz_check_refusal(ret, err, lines);
	if (memcmp(d, before, sizeof(*d)) != 0)
		abort();
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi;
}

static bool line_ok(unsigned long line, unsigned long lines)
{
	return line >= 1 && line <= lines;
}

/* docs/leaf-format.md's table, written out again: not ori_design_check's code. */
static void check_ranges(const struct ori_design *d, unsigned long lines)
{
	size_t n = strnlen(d->name, ORI_NAME_MAX);

	if (n == 0 || n == ORI_NAME_MAX || strspn(d->name, "abcdefghijklmnopqrstuvwxyz0123456789-") != n)
		abort();
	if (d->fold != ORI_FOLD_FAN && d->fold != ORI_FOLD_HALF)
		abort();
	if (!in(d->size, 0.005, 0.5) || !in(d->rest, 0.5, 1))
		abort();
	if (!in(d->middle[0], 2, 170) || !in(d->middle[1], 2, 170))
		abort();
	if (d->nnodes > ORI_MAX_NODES || d->nsides > ORI_MAX_SIDES)
		abort();
	if (d->fold == ORI_FOLD_HALF && (d->nnodes || d->nsides))
		abort();
	for (size_t i = 0; i < d->nnodes; i++) {
		const struct ori_node *p = &d->nodes[i];

		if (!(p->at > 0 && p->at < 1) || (i > 0 && !(p->at > d->nodes[i - 1].at)))
			abort();
		for (int s = 0; s < 2; s++)
			if (!(0 < p->psi[s] && p->psi[s] < p->phi[s] && p->phi[s] < 90))
				abort();
		if (!line_ok(p->line, lines))
			abort();
	}
	for (size_t i = 0; i < d->nsides; i++) {
		const struct ori_side *p = &d->sides[i];

		if (!in(p->angle, 5, 170) || p->forks < 0 || p->forks > ORI_MAX_FORKS ||
		    !in(p->fork_at, 0.1, 0.9) || !in(p->fork_a, 1, 80) || !in(p->fork_b, 1, 80))
			abort();
		if (!line_ok(p->line, lines))
			abort();
	}
	if (!in(d->junction, 0.05, 0.95) || !in(d->theta0, 30, 720) || !in(d->width, 0.05, 1) ||
	    !in(d->power, 0.2, 1))
		abort();
	if (!line_ok(d->line, lines) || !line_ok(d->line_middle, lines) ||
	    !line_ok(d->line_cut, lines))
		abort();
}

/* Field by field: struct padding is not part of a design. */
static bool same(const struct ori_design *a, const struct ori_design *b)
{
	bool ok = !strcmp(a->name, b->name) && a->fold == b->fold && a->size == b->size &&
		  a->rest == b->rest && a->middle[0] == b->middle[0] && a->middle[1] == b->middle[1] &&
		  a->nnodes == b->nnodes && a->nsides == b->nsides && a->junction == b->junction &&
		  a->theta0 == b->theta0 && a->width == b->width && a->power == b->power &&
		  a->line == b->line && a->line_middle == b->line_middle && a->line_cut == b->line_cut;

	for (size_t i = 0; ok && i < ORI_MAX_NODES; i++) {
		const struct ori_node *p = &a->nodes[i], *q = &b->nodes[i];

		ok = p->at == q->at && p->phi[0] == q->phi[0] && p->phi[1] == q->phi[1] &&
		     p->psi[0] == q->psi[0] && p->psi[1] == q->psi[1] && p->line == q->line;
	}
	for (size_t i = 0; ok && i < ORI_MAX_SIDES; i++) {
		const struct ori_side *p = &a->sides[i], *q = &b->sides[i];

		ok = p->angle == q->angle && p->forks == q->forks && p->fork_at == q->fork_at &&
		     p->fork_a == q->fork_a && p->fork_b == q->fork_b && p->line == q->line;
	}
	return ok;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct ori_design d, before, again;
	struct error err = { { 0 } };
	struct ori_fault at;
	unsigned long lines = fuzz_lines_of(data, size);
	int ret;

	memset(&d, 0x5a, sizeof(d));
	memcpy(&before, &d, sizeof(d)); /* padding too: a refusal leaves every byte */
	ret = ori_read((const char *)data, size, "fuzz", &d, &err);
	if (ret < 0) {
		check_refusal(ret, &err, &d, &before, lines);
		return 0;
	}
	if (ret != 0 || ori_design_check(&d, &at, &err) != 0)
		abort();
	check_ranges(&d, lines);
	if (ori_read((const char *)data, size, "again", &again, &err) != 0 || !same(&d, &again))
		abort();
	return 0;
}
