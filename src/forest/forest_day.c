/* SPDX-License-Identifier: MIT */
/*
 * Which archived drawings stand in today's forest, and their numbers in the day
 * (docs/forest.md, "Which trees"). The clock is the caller's: a reset moment comes in as
 * seconds, so the tests drive the day with a test clock.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>

#include "forest.h"
#include "yaml_flat.h"

bool forest_day_update(struct forest_day *day, int64_t reset, uint64_t next)
{
	if (day->start != 0 && reset <= day->start)
		return false;
	day->start = reset;
	day->first = next;
	return true;
}

void forest_day_restart(struct forest_day *day, int64_t now, uint64_t next)
{
	day->start = now;
	day->first = next;
}

uint64_t forest_day_number(const struct forest_day *day, uint64_t archive_number)
{
	return archive_number < day->first ? 0 : archive_number - day->first + 1;
}

size_t forest_day_standing(const struct forest_day *day, const uint64_t *numbers, size_t n,
			   size_t max, size_t *out)
{
	size_t got = 0;
	uint64_t below = UINT64_MAX;

	/* the newest first, walking down: each step the largest number below the last taken
	 * (O(n max), n a day's archive and max 40: no allocation, no sort) */
	while (got < max) {
		size_t best = n;

		for (size_t i = 0; i < n; i++)
			if (numbers[i] >= day->first && numbers[i] < below &&
			    (best == n || numbers[i] > numbers[best]))
				best = i;
		if (best == n)
			break;
		out[got++] = best;
		below = numbers[best];
	}
	/* oldest first */
	for (size_t i = 0; i < got / 2; i++) {
		size_t t = out[i];

		out[i] = out[got - 1 - i];
		out[got - 1 - i] = t;
	}
	return got;
}

struct day_file {
	uint64_t start, first;
};

static const struct yaml_flat_key keys[] = {
	{ "start", YAML_FLAT_SEED, offsetof(struct day_file, start), NULL, NULL },
	{ "first", YAML_FLAT_SEED, offsetof(struct day_file, first), NULL, NULL },
};

static void defaults(void *p)
{
	*(struct day_file *)p = (struct day_file){ 0, 0 };
}

static int check(const void *p, const char **key, struct error *err)
{
	const struct day_file *f = p;

	/* a day's start is a moment since 1970 a signed 64-bit second count holds */
	if (f->start > (uint64_t)INT64_MAX) {
		*key = "start";
		return error_set(err, -EINVAL, "start %" PRIu64 " is past any clock", f->start);
	}
	return 0;
}

static const struct yaml_flat_format format = {
	.version_key = "edaha-forest-day",
	.version = FOREST_DAY_VERSION,
	.what = "forest day file",
	.keys = keys,
	.nkeys = sizeof(keys) / sizeof(keys[0]),
	.max_bytes = 4096,
	.max_depth = 4,
	.size = sizeof(struct day_file),
	.defaults = defaults,
	.check = check,
};

int forest_day_read(const char *data, size_t len, const char *name, struct forest_day *day,
		    struct error *err)
{
	struct day_file f;
	int ret = yaml_flat_read(&format, data, len, name, 0, &f, err);

	if (ret < 0)
		return ret;
	day->start = (int64_t)f.start;
	day->first = f.first;
	return 0;
}

int forest_day_write(const struct forest_day *day, struct buf *out)
{
	return buf_printf(out,
			  "# today's forest (docs/forest.md): when the day began and the archive\n"
			  "# number of its first tree\n"
			  "edaha-forest-day: %d\nstart: %" PRId64 "\nfirst: %" PRIu64 "\n",
			  FOREST_DAY_VERSION, day->start, day->first);
}
