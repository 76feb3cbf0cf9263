/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on disk (platform/files/forest_state.c, docs/forest.md):
 *
 * - the archive's numbers, ascending, other names ignored, the next number as
 *   autosave_archive gives it (an archive written by autosave_archive itself);
 * - the day file saved and loaded back; missing: no day; damaged: a warning naming its
 *   line and no day (a new one begins), never an error;
 * - --forest-reset: a new day now, its first the next archive number;
 * - the reset moment by a test clock in three time zones (Tokyo, Berlin and New York,
 *   the last two across their daylight saving changes), at 2,000 seeded random moments
 *   and reset times: at or before now, at hour:minute local time (or an hour later where
 *   the clocks skip it), and no such moment between it and now.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "autosave.h"
#include "doc.h"
#include "fileio.h"
#include "forest_state.h"
#include "rng.h"
#include "test.h"

static void write_file(const char *dir, const char *name, const char *text)
{
	struct error err;

	CHECK(fileio_write_atomic(dir, name, text, strlen(text), &err) == 0);
}

static void test_archive(const char *dir)
{
	char arch[512];
	uint64_t *numbers, next;
	size_t n;
	struct error err;
	struct autosave *a;
	struct doc d;
	struct tree t;
	char name[64];

	/* none yet */
	CHECK(forest_state_archive(dir, &numbers, &n, &next, &err) == 0);
	CHECK(n == 0 && numbers == NULL && next == 1);
	snprintf(arch, sizeof(arch), "%s/%s", dir, AUTOSAVE_ARCHIVE_DIR);
	CHECK(fileio_mkdirs(arch, &err) == 0);
	write_file(arch, "drawing-000007.edaha", "x");
	write_file(arch, "drawing-000003.edaha", "x");
	write_file(arch, "drawing-12.edaha", "x");
	write_file(arch, "notes.txt", "x");
	write_file(arch, "drawing-000005.edaha.tmp", "x");
	CHECK(forest_state_archive(dir, &numbers, &n, &next, &err) == 0);
	CHECK(n == 2 && numbers[0] == 3 && numbers[1] == 7 && next == 8);
	free(numbers);
	/* what autosave_archive writes next is the number said */
	a = autosave_create(dir, &err);
	CHECK(a);
	doc_init(&d, 1);
	tree_init(&t);
	CHECK(autosave_archive(a, &d, &t, 0, name, sizeof(name), &err) == 0);
	CHECK(strcmp(name, "drawing-000008.edaha") == 0);
	CHECK(forest_state_archive(dir, &numbers, &n, &next, &err) == 0);
	CHECK(n == 3 && numbers[2] == 8 && next == 9);
	free(numbers);
	tree_finish(&t);
	doc_finish(&d);
	autosave_destroy(a);
}

static void test_day_file(const char *dir)
{
	struct forest_day day = { 1764907200, 42 }, back;
	struct error err, warn;

	CHECK(forest_state_load(dir, &back, &warn, &err) == 0);
	CHECK(back.start == 0 && back.first == 0 && !warn.msg[0]);
	CHECK(forest_state_save(dir, &day, &err) == 0);
	CHECK(forest_state_load(dir, &back, &warn, &err) == 0);
	CHECK(back.start == day.start && back.first == day.first && !warn.msg[0]);
	/* damaged: said at its line, and no day */
	write_file(dir, FOREST_STATE_FILE, "edaha-forest-day: 1\nstart: 12\nfirst: many\n");
	CHECK(forest_state_load(dir, &back, &warn, &err) == 0);
	CHECK(back.start == 0 && back.first == 0);
	CHECK(strstr(warn.msg, FOREST_STATE_FILE ":3:") != NULL);
	write_file(dir, FOREST_STATE_FILE, "\xff\xfe garbage");
	CHECK(forest_state_load(dir, &back, &warn, &err) == 0);
	CHECK(back.start == 0 && warn.msg[0]);
	/* --forest-reset: the next archived drawing is the day's first */
	CHECK(forest_state_reset(dir, 1764950000, &err) == 0);
	CHECK(forest_state_load(dir, &back, &warn, &err) == 0);
	CHECK(back.start == 1764950000 && back.first == 9 && !warn.msg[0]);
}

static void test_reset_moment(void)
{
	static const char *const zones[] = { "Asia/Tokyo", "Europe/Berlin", "America/New_York" };
	struct rng r;
	size_t checked = 0, skipped = 0;

	rng_seed(&r, 2727);
	for (size_t z = 0; z < sizeof(zones) / sizeof(*zones); z++) {
		CHECK(setenv("TZ", zones[z], 1) == 0);
		tzset();
		for (int i = 0; i < 2000; i++) {
			/* 2026 and 2027: both daylight saving changes in each */
			int64_t now = 1767225600 + (int64_t)(rng_next(&r) % (2 * 365 * 86400ull));
			int hour = (int)(rng_next(&r) % 24), minute = (int)(rng_next(&r) % 60);
			int64_t m = forest_state_reset_moment(now, hour, minute);
			time_t tm_ = (time_t)m;
			struct tm lt;

			if (i % 5 == 0) /* near the hour, where it matters most */
				now = m + (int64_t)(rng_next(&r) % 3) - 1 + 86400;
			m = forest_state_reset_moment(now, hour, minute);
			tm_ = (time_t)m;
			CHECK(localtime_r(&tm_, &lt));
			CHECK(m <= now);
			CHECK(now - m <= 25 * 3600);
			if (lt.tm_hour == hour && lt.tm_min == minute) {
				checked++;
			} else {
				/* a time the clocks skipped: an hour later */
				CHECK(lt.tm_min == minute && lt.tm_hour == (hour + 1) % 24);
				skipped++;
			}
			/* no later such moment before now: a minute-by-minute walk would be slow;
			 * the next day's moment is after now */
			{
				struct tm next = lt;
				time_t t;

				next.tm_mday += 1;
				next.tm_hour = hour;
				next.tm_min = minute;
				next.tm_sec = 0;
				next.tm_isdst = -1;
				t = mktime(&next);
				CHECK((int64_t)t > now);
			}
		}
	}
	unsetenv("TZ");
	tzset();
	printf("forest reset moment: %zu random moments in 3 time zones at their hour, %zu where "
	       "daylight saving skipped it\n", checked, skipped);
}

int main(void)
{
	char dir[] = "/tmp/edaha-forest-state.XXXXXX";
	char cmd[128];

	CHECK(mkdtemp(dir) != NULL);
	test_archive(dir);
	test_day_file(dir);
	test_reset_moment();
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	CHECK(system(cmd) == 0);
	return 0;
}
