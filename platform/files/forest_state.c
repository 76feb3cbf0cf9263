/* SPDX-License-Identifier: MIT */
/* Today's forest on disk: the day file, the archive's numbers, the local reset moment. */
#include "forest_state.h"

#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "autosave.h"
#include "buf.h"
#include "fileio.h"

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return x < y ? -1 : x > y;
}

int forest_state_archive(const char *state_dir, uint64_t **numbers, size_t *n, uint64_t *next,
			 struct error *err)
{
	char dir[PATH_MAX];
	DIR *dp;
	struct dirent *e;
	uint64_t *list = NULL, hi = 0;
	size_t count = 0, cap = 0;

	*numbers = NULL;
	*n = 0;
	*next = 1;
	if ((size_t)snprintf(dir, sizeof(dir), "%s/%s", state_dir, AUTOSAVE_ARCHIVE_DIR) >= sizeof(dir))
		return error_set(err, -ENAMETOOLONG, "%s: path too long", state_dir);
	dp = opendir(dir);
	if (!dp)
		return errno == ENOENT ? 0 : error_set(err, -errno, "%s: %s", dir, strerror(errno));
	while ((e = readdir(dp))) {
		unsigned a = autosave_archive_number(e->d_name);

		if (!a)
			continue;
		if (count == cap) {
			size_t c = cap ? 2 * cap : 64;
			uint64_t *l = realloc(list, c * sizeof(*l));

			if (!l) {
				free(list);
				closedir(dp);
				return error_set(err, -ENOMEM, "out of memory");
			}
			list = l;
			cap = c;
		}
		list[count++] = a;
		hi = a > hi ? a : hi;
	}
	closedir(dp);
	if (count)
		qsort(list, count, sizeof(*list), cmp_u64);
	*numbers = list;
	*n = count;
	/* as autosave_archive numbers the next one */
	*next = hi >= AUTOSAVE_ARCHIVE_MAX ? 1 : hi + 1;
	return 0;
}

int forest_state_load(const char *state_dir, struct forest_day *day, struct error *warn,
		      struct error *err)
{
	char path[PATH_MAX];
	char *data = NULL;
	size_t len = 0;
	int ret;

	*day = (struct forest_day){ 0, 0 };
	warn->msg[0] = '\0';
	if ((size_t)snprintf(path, sizeof(path), "%s/%s", state_dir, FOREST_STATE_FILE) >= sizeof(path))
		return error_set(err, -ENAMETOOLONG, "%s: path too long", state_dir);
	ret = fileio_read_all(path, 4096, &data, &len, err);
	if (ret == -ENOENT)
		return 0;
	if (ret == -EFBIG || ret == -EISDIR || ret == -EINVAL) {
		/* no day file at all: a new day, and the next save replaces it */
		error_set(warn, ret, "%s", err->msg);
		return 0;
	}
	if (ret < 0)
		return ret;
	if (forest_day_read(data, len, path, day, warn) < 0)
		*day = (struct forest_day){ 0, 0 };
	free(data);
	return 0;
}

int forest_state_save(const char *state_dir, const struct forest_day *day, struct error *err)
{
	struct buf b;
	int ret;

	buf_init(&b);
	ret = forest_day_write(day, &b);
	if (ret < 0)
		ret = error_set(err, ret, "out of memory");
	if (ret == 0)
		ret = fileio_mkdirs(state_dir, err);
	if (ret == 0)
		ret = fileio_write_atomic(state_dir, FOREST_STATE_FILE, b.data, b.len, err);
	buf_finish(&b);
	return ret;
}

/* hour:minute on the local day of `day` (its date), as seconds; daylight saving decided
 * by mktime (tm_isdst -1): a time the clocks skip comes out an hour later. */
static int64_t at(const struct tm *day, int hour, int minute)
{
	struct tm t = *day;

	t.tm_hour = hour;
	t.tm_min = minute;
	t.tm_sec = 0;
	t.tm_isdst = -1;
	return (int64_t)mktime(&t);
}

int64_t forest_state_reset_moment(int64_t now, int hour, int minute)
{
	time_t tn = (time_t)now;
	struct tm today;
	int64_t m;

	if (!localtime_r(&tn, &today))
		return now;
	m = at(&today, hour, minute);
	if (m > now) {
		/* yesterday's: a day back from noon today, away from any daylight saving jump */
		struct tm noon = today, y;
		time_t t;

		noon.tm_hour = 12;
		noon.tm_min = noon.tm_sec = 0;
		noon.tm_isdst = -1;
		t = mktime(&noon) - 86400;
		if (!localtime_r(&t, &y))
			return now;
		m = at(&y, hour, minute);
	}
	return m;
}

uint64_t forest_state_first_since(const char *state_dir, const uint64_t *numbers, size_t n,
				  int64_t since, uint64_t next)
{
	char path[PATH_MAX];
	struct stat st;

	/* ascending: the first written since is the day's first (numbers wrap only after
	 * 999,999 drawings) */
	for (size_t i = 0; i < n; i++) {
		if ((size_t)snprintf(path, sizeof(path), "%s/%s/drawing-%06" PRIu64 ".edaha", state_dir,
				     AUTOSAVE_ARCHIVE_DIR, numbers[i]) >= sizeof(path))
			continue;
		if (stat(path, &st) == 0 && (int64_t)st.st_mtime >= since)
			return numbers[i];
	}
	return next;
}

int forest_state_reset(const char *state_dir, int64_t now, struct error *err)
{
	struct forest_day day;
	uint64_t *numbers, next;
	size_t n;
	int ret = forest_state_archive(state_dir, &numbers, &n, &next, err);

	if (ret < 0)
		return ret;
	free(numbers);
	forest_day_restart(&day, now, next);
	return forest_state_save(state_dir, &day, err);
}
