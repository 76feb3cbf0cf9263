/* SPDX-License-Identifier: MIT */
#include "autosave.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "buf.h"
#include "fileio.h"
#include "journal.h"

/* What the journal holds of each op: enough to see that an op changed without keeping
 * a copy of its points (a stroke's points are its own allocation). */
struct autosave_id {
	enum doc_op_kind kind;
	uint64_t time_us;
	const void *points;
	size_t npoints;
	int branch, pattern;
	const void *params;
};

struct autosave {
	char *dir;
	char path[PATH_MAX];
	int fd;       /* the journal, for appending; -1: start afresh at the next sync */
	size_t bytes; /* appended since the last start */
	struct autosave_id *ids;
	size_t nids, cap;
	size_t cursor;
};

struct autosave *autosave_create(const char *dir, struct error *err)
{
	struct autosave *a;

	if (fileio_mkdirs(dir, err) < 0)
		return NULL;
	a = calloc(1, sizeof(*a));
	if (!a || !(a->dir = strdup(dir))) {
		free(a);
		error_set(err, -ENOMEM, "out of memory");
		return NULL;
	}
	if ((size_t)snprintf(a->path, sizeof(a->path), "%s/%s", dir, AUTOSAVE_JOURNAL) >=
	    sizeof(a->path)) {
		autosave_destroy(a);
		error_set(err, -ENAMETOOLONG, "%s: path too long", dir);
		return NULL;
	}
	a->fd = -1;
	return a;
}

void autosave_destroy(struct autosave *a)
{
	if (!a)
		return;
	if (a->fd >= 0)
		close(a->fd);
	free(a->ids);
	free(a->dir);
	free(a);
}

const char *autosave_path(const struct autosave *a)
{
	return a->path;
}

static struct autosave_id id_of(const struct doc_op *op)
{
	return (struct autosave_id){ op->kind, op->time_us, op->points, op->npoints, op->branch,
				     op->pattern, op->params };
}

static bool id_equal(const struct autosave_id *a, const struct autosave_id *b)
{
	return a->kind == b->kind && a->time_us == b->time_us && a->points == b->points &&
	       a->npoints == b->npoints && a->branch == b->branch && a->pattern == b->pattern &&
	       a->params == b->params;
}

/* The first op of d the journal does not hold as it is. */
static size_t first_changed(const struct autosave *a, const struct doc *d)
{
	size_t n = a->nids < d->nops ? a->nids : d->nops;

	for (size_t i = 0; i < n; i++) {
		struct autosave_id id = id_of(&d->ops[i]);

		if (!id_equal(&a->ids[i], &id))
			return i;
	}
	return n;
}

bool autosave_pending(const struct autosave *a, const struct doc *d)
{
	return a->fd < 0 || first_changed(a, d) != a->nids || a->nids != d->nops ||
	       a->cursor != d->cursor;
}

static int remember(struct autosave *a, const struct doc *d)
{
	if (d->nops > a->cap) {
		struct autosave_id *ids = realloc(a->ids, d->nops * sizeof(*ids));

		if (!ids)
			return -ENOMEM;
		a->ids = ids;
		a->cap = d->nops;
	}
	for (size_t i = 0; i < d->nops; i++)
		a->ids[i] = id_of(&d->ops[i]);
	a->nids = d->nops;
	a->cursor = d->cursor;
	return 0;
}

/* After a write: the journal holds d. If that cannot be noted, the next sync starts the
 * journal afresh rather than append to one whose contents are unknown. */
static int remember_or_drop(struct autosave *a, const struct doc *d, struct error *err)
{
	int ret = remember(a, d);

	if (ret < 0) {
		close(a->fd);
		a->fd = -1;
		return error_set(err, ret, "out of memory");
	}
	return 0;
}

int autosave_restore(struct autosave *a, struct doc *doc, struct error *warn,
		     struct error *err)
{
	struct journal_replay r;
	char *data;
	size_t len;
	int ret;

	warn->msg[0] = '\0';
	ret = fileio_read_all(a->path, JOURNAL_MAX_RECORD, &data, &len, err);
	if (ret == -ENOENT)
		return 0;
	if (ret == -EFBIG || ret == -EISDIR || ret == -ELOOP || ret == -EINVAL) {
		/* not something a journal becomes: say so and start a new drawing */
		error_set(warn, ret, "%s", err->msg);
		return 0;
	}
	if (ret < 0)
		return ret;
	ret = journal_replay(data, len, a->path, doc, &r, err);
	free(data);
	if (ret == -EINVAL) {
		char bad[PATH_MAX + 8];

		snprintf(bad, sizeof(bad), "%s.bad", a->path);
		if (rename(a->path, bad) == 0)
			error_set(warn, ret, "%s; kept as %s, starting a new drawing", err->msg, bad);
		else
			error_set(warn, ret, "%s; starting a new drawing", err->msg);
		return 0;
	}
	if (ret < 0)
		return ret;
	if (r.torn)
		error_set(warn, -EINVAL, "%s; the drawing is as it was before it (%zu edits read)",
			  r.tail.msg, r.records);
	return r.records > 0;
}

int autosave_start(struct autosave *a, const struct doc *d, struct error *err)
{
	struct buf b;
	int ret;

	if (a->fd >= 0) {
		close(a->fd);
		a->fd = -1;
	}
	buf_init(&b);
	ret = journal_header(&b);
	if (ret == 0)
		ret = journal_record(d, 0, &b);
	if (ret < 0) {
		buf_finish(&b);
		return error_set(err, ret, "%s: out of memory", a->path);
	}
	/* the old journal stays whole until the new one replaces it */
	ret = fileio_write_atomic(a->dir, AUTOSAVE_JOURNAL, b.data, b.len, err);
	buf_finish(&b);
	if (ret < 0)
		return ret;
	a->fd = open(a->path, O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC);
	if (a->fd < 0)
		return error_set(err, -errno, "%s: %s", a->path, strerror(errno));
	a->bytes = 0;
	return remember_or_drop(a, d, err);
}

static int write_all(int fd, const unsigned char *p, size_t len)
{
	while (len) {
		ssize_t n = write(fd, p, len);

		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			return -errno;
		p += n;
		len -= (size_t)n;
	}
	return 0;
}

int autosave_sync(struct autosave *a, const struct doc *d, struct error *err)
{
	struct buf b;
	size_t from;
	int ret;

	if (a->fd < 0 || a->bytes >= AUTOSAVE_COMPACT_BYTES)
		return autosave_start(a, d, err);
	from = first_changed(a, d);
	if (from == a->nids && a->nids == d->nops && a->cursor == d->cursor)
		return 0;
	buf_init(&b);
	ret = journal_record(d, from, &b);
	if (ret < 0) {
		buf_finish(&b);
		return error_set(err, ret, "%s: out of memory", a->path);
	}
	ret = write_all(a->fd, b.data, b.len);
	if (ret == 0 && fsync(a->fd) < 0)
		ret = -errno;
	a->bytes += b.len;
	buf_finish(&b);
	if (ret < 0) {
		/* a half-written record ends the journal for a reader: start afresh next time */
		close(a->fd);
		a->fd = -1;
		return error_set(err, ret, "%s: %s", a->path, strerror(-ret));
	}
	return remember_or_drop(a, d, err);
}

unsigned autosave_archive_number(const char *name)
{
	unsigned n = 0;
	int used = 0;

	if (sscanf(name, "drawing-%6u.edaha%n", &n, &used) != 1 || name[used] != '\0' ||
	    strlen(name) != strlen("drawing-000000.edaha"))
		return 0;
	return n;
}

/* The lowest and highest numbers there, and how many. */
static int archive_scan(const char *dir, unsigned *lo, unsigned *hi, size_t *count)
{
	DIR *dp = opendir(dir);
	struct dirent *e;

	*lo = UINT_MAX;
	*hi = 0;
	*count = 0;
	if (!dp)
		return -errno;
	while ((e = readdir(dp))) {
		unsigned n = autosave_archive_number(e->d_name);

		if (!n)
			continue;
		(*count)++;
		if (n < *lo)
			*lo = n;
		if (n > *hi)
			*hi = n;
	}
	closedir(dp);
	return 0;
}

/* The oldest archives beyond keep go: a kiosk left for a year fills no card. */
static void archive_prune(const char *dir, unsigned keep)
{
	unsigned lo, hi;
	size_t count;
	char name[32];

	if (!keep || archive_scan(dir, &lo, &hi, &count) < 0)
		return;
	for (unsigned n = lo; count > keep && n <= hi; n++) {
		int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);

		if (dfd < 0)
			return;
		snprintf(name, sizeof(name), "drawing-%06u.edaha", n);
		if (unlinkat(dfd, name, 0) == 0)
			count--;
		close(dfd);
	}
}

int autosave_archived_already(struct autosave *a, const struct doc *d, const struct tree *t)
{
	char dir[PATH_MAX], path[PATH_MAX + 32];
	struct error err = { { 0 } };
	unsigned lo, hi;
	size_t count, len = 0;
	char *data = NULL;
	struct buf b;
	int ret;

	if ((size_t)snprintf(dir, sizeof(dir), "%s/%s", a->dir, AUTOSAVE_ARCHIVE_DIR) >= sizeof(dir))
		return -ENAMETOOLONG;
	ret = archive_scan(dir, &lo, &hi, &count);
	if (ret < 0 || count == 0)
		return ret == -ENOENT ? 0 : ret;
	snprintf(path, sizeof(path), "%s/drawing-%06u.edaha", dir, hi);
	ret = fileio_read_all(path, DOC_MAX_FILE_BYTES, &data, &len, &err);
	if (ret < 0)
		return ret == -ENOENT ? 0 : ret;
	buf_init(&b);
	ret = doc_serialize(d, t, &b);
	if (ret == 0)
		ret = b.len == len && memcmp(b.data, data, len) == 0;
	buf_finish(&b);
	free(data);
	return ret;
}

int autosave_archive(struct autosave *a, const struct doc *d, const struct tree *t,
		     unsigned keep, char *name, size_t name_size, struct error *err)
{
	char dir[PATH_MAX];
	unsigned lo, hi;
	size_t count;
	struct buf b;
	int ret;

	if ((size_t)snprintf(dir, sizeof(dir), "%s/%s", a->dir, AUTOSAVE_ARCHIVE_DIR) >= sizeof(dir))
		return error_set(err, -ENAMETOOLONG, "%s: path too long", a->dir);
	ret = fileio_mkdirs(dir, err);
	if (ret < 0)
		return ret;
	ret = archive_scan(dir, &lo, &hi, &count);
	if (ret < 0)
		return error_set(err, ret, "%s: %s", dir, strerror(-ret));
	/* numbers only grow; past the last one they start over (the oldest are long gone) */
	snprintf(name, name_size, "drawing-%06u.edaha", hi >= AUTOSAVE_ARCHIVE_MAX ? 1 : hi + 1);
	buf_init(&b);
	ret = doc_serialize(d, t, &b);
	if (ret < 0)
		ret = error_set(err, ret, "out of memory");
	else
		ret = fileio_write_atomic(dir, name, b.data, b.len, err);
	buf_finish(&b);
	if (ret == 0)
		archive_prune(dir, keep);
	return ret;
}
