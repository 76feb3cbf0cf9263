/* SPDX-License-Identifier: MIT */
/*
 * The forest's day (src/forest/forest_day.c, docs/forest.md "Which trees"):
 *
 * - a test clock walked through 400 seeded random days (reset moments a day apart, the
 *   kiosk started and stopped at random, a clock set back now and then, drawings archived
 *   at random moments, staff resets): the day begins at each reset moment and only then
 *   (or at a staff reset), never when the clock goes back; the standing trees are the
 *   newest max of the day's, oldest first; each tree's number is its place in the day
 *   (1, 2, 3, ...), kept when older trees give way;
 * - the newest 40 of 45 stand, numbered 6..45;
 * - the day file reads back what was written, and a damaged one is refused at its line.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "forest.h"
#include "rng.h"
#include "test.h"

#define DAY_S 86400

static void test_newest(void)
{
	struct forest_day day = { 0 };
	uint64_t numbers[45];
	size_t out[40], n;

	CHECK(forest_day_update(&day, 1000, 101));
	for (int i = 0; i < 45; i++)
		numbers[i] = 101 + (uint64_t)((i * 7) % 45); /* in any order */
	n = forest_day_standing(&day, numbers, 45, 40, out);
	CHECK(n == 40);
	for (size_t i = 0; i < n; i++)
		CHECK(forest_day_number(&day, numbers[out[i]]) == 6 + i);
	/* before the day: number 0, not standing */
	CHECK(forest_day_number(&day, 100) == 0);
	numbers[0] = 100;
	CHECK(forest_day_standing(&day, numbers, 1, 40, out) == 0);
}

/* A day walked by a test clock. */
static void test_days(int cases)
{
	struct rng r;
	size_t checked = 0, days = 0, setbacks = 0;

	rng_seed(&r, 2727);
	for (int c = 0; c < cases; c++) {
		struct forest_day day = { 0 };
		uint64_t archive[600], next = 1 + rng_next(&r) % 1000;
		int64_t archived_at[600];
		size_t narchive = 0, max = 1 + (size_t)(rng_next(&r) % 60);
		int64_t t = 1764900000 + (int64_t)(rng_next(&r) % DAY_S), reset = 4 * 3600;
		int64_t day_start = 0; /* what the day should be, by the test's own reckoning */

		for (int step = 0; step < 200 && narchive < 600; step++) {
			int64_t last_reset;
			size_t out[64], n;

			/* the clock moves on, now and then far; sometimes back (no RTC) */
			if (rng_next(&r) % 20 == 0) {
				t -= (int64_t)(rng_next(&r) % 7200);
				setbacks++;
			} else {
				t += (int64_t)(rng_next(&r) % (rng_next(&r) % 8 ? 1800 : 2 * DAY_S));
			}
			last_reset = t - ((t - reset) % DAY_S + DAY_S) % DAY_S;
			if (last_reset > day_start || day_start == 0) {
				CHECK(forest_day_update(&day, last_reset, next));
				day_start = last_reset;
				days++;
			} else {
				CHECK(!forest_day_update(&day, last_reset, next));
			}
			CHECK(day.start == day_start);
			/* a staff reset now and then */
			if (rng_next(&r) % 50 == 0) {
				forest_day_restart(&day, t, next);
				day_start = day.start;
			}
			/* a visitor's drawing archived */
			if (rng_next(&r) % 3) {
				archived_at[narchive] = t;
				archive[narchive++] = next++;
			}
			/* the standing trees: the newest max archived since the day began */
			n = forest_day_standing(&day, archive, narchive, max, out);
			{
				size_t today = 0;

				for (size_t i = 0; i < narchive; i++)
					today += archive[i] >= day.first;
				CHECK(n == (today < max ? today : max));
			}
			for (size_t i = 0; i < n; i++) {
				uint64_t a = archive[out[i]];

				CHECK(a >= day.first);
				CHECK(i == 0 || archive[out[i - 1]] < a);
				CHECK(forest_day_number(&day, a) == a - day.first + 1);
				checked++;
			}
			/* the newest of the day stands */
			if (narchive && archive[narchive - 1] >= day.first)
				CHECK(n && out[n - 1] == narchive - 1);
			(void)archived_at;
		}
	}
	printf("forest day: %d random clocks, %zu days begun, %zu clocks set back, %zu standing "
	       "trees checked\n", cases, days, setbacks, checked);
}

static void test_file(void)
{
	struct forest_day day = { 1764907200, 123 }, back = { 0 };
	struct error err;
	struct buf b;
	static const char *const bad[] = {
		"edaha-forest-day: 1\nstart: -5\n",
		"edaha-forest-day: 2\nstart: 5\nfirst: 1\n",
		"edaha-forest-day: 1\nstart: 5\nfirst: [1]\n",
		"edaha-forest-day: 1\nbogus: 3\n",
		"start: 5\n",
		"edaha-forest-day: 1\nstart: 18446744073709551615\n",
		"\x01\x02",
	};

	buf_init(&b);
	CHECK(forest_day_write(&day, &b) == 0);
	CHECK(forest_day_read((const char *)b.data, b.len, "forest-day", &back, &err) == 0);
	CHECK(back.start == day.start && back.first == day.first);
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		back = day;
		CHECK(forest_day_read(bad[i], strlen(bad[i]), "forest-day", &back, &err) == -EINVAL);
		CHECK(strncmp(err.msg, "forest-day:", 11) == 0);
		CHECK(back.start == day.start && back.first == day.first);
	}
	buf_finish(&b);
}

int main(void)
{
	test_newest();
	test_days(test_cases(400));
	test_file();
	return 0;
}
