/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* renameat2, RENAME_NOREPLACE */
#include "export_set.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "export.h"
#include "fileio.h"
#include "pngio.h"

/* The OBJ is built before its name is known; export_set_write renames the MTL it uses. */
#define EXPORT_SET_MTL_PLACEHOLDER "tree.mtl"
#define NAME_SIZE 48

/* The kiosk's page, set on its main thread before any set is made there. */
static struct page_look page_default;

void export_set_page_default(const struct page_look *look)
{
	if (look)
		page_default = *look;
	else
		page_default = (struct page_look){ .viewer = NULL };
}

void export_set_init(struct export_set *s)
{
	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++)
		buf_init(&s->files[i]);
	s->wind = 0.0;
	buf_init(&s->forest);
	s->forest_date[0] = s->forest_name[0] = '\0';
	s->forest_only = false;
	s->page = page_default;
	s->page_date[0] = '\0';
}

/* Today as the page says it, by the local clock ("" when it cannot be read). */
static void page_today(struct export_set *s)
{
	time_t now = time(NULL);
	struct tm tm;

	s->page_date[0] = '\0';
	if (now == (time_t)-1 || !localtime_r(&now, &tm))
		return;
	(void)export_page_date(s->page.lang, tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
			       s->page_date, sizeof(s->page_date));
}

void export_set_finish(struct export_set *s)
{
	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++)
		buf_finish(&s->files[i]);
	buf_finish(&s->forest);
}

int export_set_build(struct export_set *s, const struct app *app, const uint8_t *rgba,
		     struct error *err)
{
	const struct export_wind wind = { .strength = s->wind, .angle = EXPORT_WIND_ANGLE,
					  .seed = app->doc.seed };
	struct buf *f = s->files;
	int r;

	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++)
		buf_reset(&f[i]);
	r = export_glb_wind(&app->tree, &app->mesh, &app->mesh_marks, &wind, &f[EXPORT_SET_GLB]);
	if (r < 0)
		return error_set(err, r, "cannot build the .glb: %s", strerror(-r));
	r = export_obj(&app->tree, &app->mesh, &app->mesh_marks, EXPORT_SET_MTL_PLACEHOLDER,
		       &f[EXPORT_SET_OBJ], &f[EXPORT_SET_MTL]);
	if (r < 0)
		return error_set(err, r, "cannot build the .obj: %s", strerror(-r));
	if ((r = doc_serialize(&app->doc, &app->tree, &f[EXPORT_SET_EDAHA])) < 0)
		return error_set(err, r, "cannot build the .edaha: %s", strerror(-r));
	page_today(s);
	if (rgba)
		return pngio_encode_rgba(rgba, app->screen.width, app->screen.height,
					 &f[EXPORT_SET_PNG], err);
	return 0;
}

/* A forest's temporary (export_set_write_forest): ".forest-YYYY-MM-DD[...].glb.tmp". */
static bool forest_temp(const char *name)
{
	size_t n = strlen(name);

	return strncmp(name, ".forest-", 8) == 0 && n > 16 && strcmp(name + n - 8, ".glb.tmp") == 0;
}

int export_set_pick(int dirfd, unsigned *number, struct error *err)
{
	struct export_names *names;
	struct dirent *d;
	DIR *dir;
	int r = fileio_opendir_at(dirfd, &dir, err);

	if (r < 0)
		return r;
	/* 12 KiB of bits: on the heap, as this runs on threads with small stacks too */
	names = malloc(sizeof(*names));
	if (!names) {
		closedir(dir);
		return error_set(err, -ENOMEM, "out of memory");
	}
	export_names_init(names);
	for (;;) {
		errno = 0;
		d = readdir(dir);
		if (!d) {
			if (errno)
				r = error_set(err, -errno, "cannot list the directory: %s",
					      strerror(errno));
			break;
		}
		/* ours, from a write the stick was pulled in: never a final name, so safe to
		 * remove (a directory of that name stays: unlinkat refuses it) */
		if (export_names_add(names, d->d_name) == EXPORT_NAME_TEMP || forest_temp(d->d_name))
			(void)unlinkat(dirfd, d->d_name, 0);
	}
	closedir(dir);
	if (r == 0 && export_names_next(names, number) < 0)
		r = error_set(err, -ENOSPC, "every name tree-0001 to tree-%u is taken",
			      EXPORT_NAMES_MAX);
	free(names);
	return r;
}

int export_set_rename(int dirfd, const char *from, const char *to, bool noreplace)
{
	struct stat st;

	if (noreplace) {
		if (renameat2(dirfd, from, dirfd, to, RENAME_NOREPLACE) == 0)
			return 0;
		if (errno != EINVAL && errno != ENOSYS)
			return -errno;
	}
	if (fstatat(dirfd, to, &st, AT_SYMLINK_NOFOLLOW) == 0)
		return -EEXIST;
	if (errno != ENOENT)
		return -errno;
	return renameat(dirfd, from, dirfd, to) < 0 ? -errno : 0;
}

static int write_all(int fd, const unsigned char *p, size_t len)
{
	while (len > 0) {
		/* chunks: a slow stick's writes return, and a signal interrupts them, sooner */
		ssize_t n = write(fd, p, len < (1u << 20) ? len : (1u << 20));

		if (n < 0) {
			if (errno == EINTR)
				continue;
			return -errno;
		}
		if (n == 0)
			return -EIO;
		p += n;
		len -= (size_t)n;
	}
	return 0;
}

/* One temporary: created (never over anything, never through a symlink), written,
 * fsynced, closed. 0 or -errno. */
static int write_temp(int dirfd, const char *tmp, const struct buf *b)
{
	int fd = openat(dirfd, tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
	int r;

	if (fd < 0)
		return -errno;
	r = write_all(fd, b->data, b->len);
	if (r == 0 && fsync(fd) < 0)
		r = -errno;
	if (close(fd) < 0 && r == 0)
		r = -errno;
	return r;
}

int export_set_write(int dirfd, struct export_set *s, unsigned number, struct error *err)
{
	char tmp[EXPORT_NAMES_NSUFFIXES][NAME_SIZE], final[EXPORT_NAMES_NSUFFIXES][NAME_SIZE];
	bool wrote[EXPORT_NAMES_NSUFFIXES] = { false }, renamed[EXPORT_NAMES_NSUFFIXES] = { false };
	size_t i;
	int r = 0;

	for (i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		const char *sfx = export_names_suffixes[i];

		if (export_names_format(tmp[i], NAME_SIZE, number, sfx, true) < 0 ||
		    export_names_format(final[i], NAME_SIZE, number, sfx, false) < 0)
			return error_set(err, -EINVAL, "bad set number %u", number);
	}
	/* the OBJ names its own MTL */
	r = export_obj_mtllib(&s->files[EXPORT_SET_OBJ], final[EXPORT_SET_MTL]);
	if (r < 0)
		return error_set(err, r, "cannot name the .mtl in the .obj: %s", strerror(-r));
	/* the page shows the number: made again for each */
	buf_reset(&s->files[EXPORT_SET_HTML]);
	if (s->page.viewer) {
		const struct buf *glb = &s->files[EXPORT_SET_GLB];

		r = page_viewer_html(&s->page, glb->data, glb->len, number, s->page_date,
				     &s->files[EXPORT_SET_HTML]);
		if (r < 0)
			return error_set(err, r, "cannot build the .html: %s", strerror(-r));
	}
	for (i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		if ((i == EXPORT_SET_PNG || i == EXPORT_SET_HTML) && s->files[i].len == 0)
			continue;
		r = write_temp(dirfd, tmp[i], &s->files[i]);
		/* even a failed create may have made the name (EIO after it): remove it
		 * unless it was there before us */
		wrote[i] = r != -EEXIST;
		if (r < 0) {
			error_set(err, r, "%s: %s", final[i], strerror(-r));
			goto undo;
		}
	}
	for (i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		if (!wrote[i])
			continue;
		r = export_set_rename(dirfd, tmp[i], final[i], true);
		if (r < 0) {
			error_set(err, r, "%s: rename: %s", final[i], strerror(-r));
			goto undo;
		}
		renamed[i] = true;
	}
	if (fsync(dirfd) < 0) {
		r = -errno;
		error_set(err, r, "fsync of the directory: %s", strerror(-r));
		goto undo;
	}
	return 0;

undo:
	/* on a pulled stick these fail too; nothing then reaches it anyway */
	for (i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		if (renamed[i])
			(void)unlinkat(dirfd, final[i], 0);
		else if (wrote[i])
			(void)unlinkat(dirfd, tmp[i], 0);
	}
	(void)fsync(dirfd);
	return r;
}

static bool forest_date_ok(const char *d)
{
	for (int i = 0; i < 10; i++)
		if (i == 4 || i == 7 ? d[i] != '-' : d[i] < '0' || d[i] > '9')
			return false;
	return d[10] == '\0';
}

int export_set_write_forest(int dirfd, struct export_set *s, struct error *err)
{
	char tmp[NAME_SIZE], final[sizeof(s->forest_name)];
	int r;

	if (!forest_date_ok(s->forest_date))
		return error_set(err, -EINVAL, "bad date for the forest's file");
	snprintf(tmp, sizeof(tmp), ".forest-%s.glb.tmp", s->forest_date);
	/* ours, from a save a pulled stick cut short: never a final name */
	(void)unlinkat(dirfd, tmp, 0);
	r = write_temp(dirfd, tmp, &s->forest);
	if (r < 0) {
		if (r != -EEXIST)
			(void)unlinkat(dirfd, tmp, 0);
		return error_set(err, r, "forest-%s.glb: %s", s->forest_date, strerror(-r));
	}
	r = -EEXIST;
	for (int n = 1; n <= EXPORT_SET_FOREST_MAX && r == -EEXIST; n++) {
		if (n == 1)
			snprintf(final, sizeof(final), "forest-%s.glb", s->forest_date);
		else
			snprintf(final, sizeof(final), "forest-%s-%d.glb", s->forest_date, n);
		r = export_set_rename(dirfd, tmp, final, true);
	}
	if (r == 0 && fsync(dirfd) < 0) {
		r = -errno;
		(void)unlinkat(dirfd, final, 0);
	}
	if (r < 0) {
		(void)unlinkat(dirfd, tmp, 0);
		(void)fsync(dirfd);
		return error_set(err, r, "forest-%s.glb: %s", s->forest_date,
				 r == -EEXIST ? "every name for the day is taken" : strerror(-r));
	}
	memcpy(s->forest_name, final, sizeof(final));
	return 0;
}

int export_set_save(int dirfd, struct export_set *s, char *base, size_t base_size,
		    struct error *err)
{
	unsigned number;
	int r = -EEXIST;

	if (s->forest_only) {
		r = export_set_write_forest(dirfd, s, err);
		if (r == 0)
			snprintf(base, base_size, "%s", s->forest_name);
		return r;
	}
	/* a name taken between the listing and the write: once more, past it */
	for (int attempt = 0; attempt < 2 && r == -EEXIST; attempt++) {
		r = export_set_pick(dirfd, &number, err);
		if (r == 0)
			r = export_set_write(dirfd, s, number, err);
	}
	if (r == 0 && export_names_format(base, base_size, number, "", false) < 0)
		r = error_set(err, -ENAMETOOLONG, "no room for the name");
	if (r == 0 && s->forest.len)
		r = export_set_write_forest(dirfd, s, err);
	return r;
}
