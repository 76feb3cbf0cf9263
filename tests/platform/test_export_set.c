/* SPDX-License-Identifier: MIT */
/*
 * Export sets into a directory fd, as on a USB stick: the numbering from one listing
 * (thousands of files, names in any case, our leftovers), never over a name or through
 * a symlink planted at a temporary or a final name, and on failure (a full disk,
 * simulated with RLIMIT_FSIZE) nothing of the set left behind.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"
#include "export_names.h"
#include "export_set.h"
#include "dir_count.h"
#include "test.h"

static void test_classify(void)
{
	unsigned n = 0;

	CHECK_INT(export_names_classify("tree-0001.glb", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 1);
	CHECK_INT(export_names_classify("TREE-0042.GLB", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 42);
	CHECK_INT(export_names_classify("Tree-7", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 7);
	CHECK_INT(export_names_classify("tree-12345.whatever.txt", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 12345);
	CHECK_INT(export_names_classify("tree-000000000000000003.png", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 3);
	/* not ours, or numbers no name of ours has */
	CHECK_INT(export_names_classify("tree-0001x.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-0000.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-100000.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-99999999999999999999999.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("mytree-0001.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("..", &n), EXPORT_NAME_OTHER);
	/* temporaries: exactly ours */
	CHECK_INT(export_names_classify(".tree-0009.glb.tmp", &n), EXPORT_NAME_TEMP);
	CHECK_INT(n, 9);
	CHECK_INT(export_names_classify(".TREE-0009.EDAHA.TMP", &n), EXPORT_NAME_TEMP);
	CHECK_INT(export_names_classify(".tree-0009.txt.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0009.glb.tmp2", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0009.glb", &n), EXPORT_NAME_OTHER);
}

static void test_next(void)
{
	struct export_names *names = malloc(sizeof(*names));
	char s[48];
	unsigned n;

	CHECK(names);
	export_names_init(names);
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 1);
	export_names_add(names, "tree-0003.png");
	export_names_add(names, "notes.txt");
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 4); /* the newest sorts last, a gap stays a gap */
	export_names_add(names, "tree-99999.glb");
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 1); /* at the top: the lowest free one */
	for (unsigned v = 1; v <= EXPORT_NAMES_MAX; v++) {
		snprintf(s, sizeof(s), "tree-%u", v);
		export_names_add(names, s);
	}
	CHECK_INT(export_names_next(names, &n), -ENOSPC);
	CHECK_INT(export_names_format(s, sizeof(s), 7, ".glb", false), 0);
	CHECK(!strcmp(s, "tree-0007.glb"));
	CHECK_INT(export_names_format(s, sizeof(s), 12345, ".edaha", true), 0);
	CHECK(!strcmp(s, ".tree-12345.edaha.tmp"));
	CHECK_INT(export_names_format(s, 8, 1, ".glb", false), -ENAMETOOLONG);
	free(names);
}

static void touch(int dirfd, const char *name)
{
	int fd = openat(dirfd, name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);

	CHECK(fd >= 0);
	CHECK_INT(write(fd, "x", 1), 1);
	close(fd);
}

static bool exists(int dirfd, const char *name)
{
	struct stat st;

	return fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0;
}

static void set_of(struct app *app, struct export_set *s, bool picture)
{
	static uint8_t rgba[64 * 64 * 4];
	struct error err = { { 0 } };

	CHECK_INT(export_set_build(s, app, picture ? rgba : NULL, &err), 0);
}

static void test_save(struct app *app, const char *root)
{
	char path[600], base[32], line[256];
	struct error err = { { 0 } };
	struct export_set s;
	int dirfd;
	FILE *f;
	bool found = false;

	snprintf(path, sizeof(path), "%s/save", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, true);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001"));
	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		snprintf(path, sizeof(path), "tree-0001%s", export_names_suffixes[i]);
		CHECK(exists(dirfd, path));
	}
	CHECK_INT(dir_count(dirfd, ".", "."), 2); /* . and .., no temporaries */
	/* the obj names its own mtl */
	snprintf(path, sizeof(path), "%s/save/tree-0001.obj", root);
	f = fopen(path, "r");
	CHECK(f);
	while (fgets(line, sizeof(line), f))
		found |= strcmp(line, "mtllib tree-0001.mtl\n") == 0;
	fclose(f);
	CHECK(found);
	/* no picture: four files */
	set_of(app, &s, false);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0002"));
	CHECK(!exists(dirfd, "tree-0002.png"));
	CHECK(exists(dirfd, "tree-0002.edaha"));

	/* a symlink planted at a final name (a hostile ext4 stick) is a taken name, and
	 * stays as it was; the set goes past it */
	CHECK_INT(symlinkat("/etc/passwd", dirfd, "tree-0003.glb"), 0);
	/* one at the next set's temporary: ours by name, so removed unfollowed */
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".tree-0004.obj.tmp"), 0);
	set_of(app, &s, true);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0005"));
	{
		char target[64] = { 0 };

		CHECK(readlinkat(dirfd, "tree-0003.glb", target, sizeof(target) - 1) > 0);
		CHECK(!strcmp(target, "/etc/passwd"));
	}
	CHECK(!exists(dirfd, ".tree-0004.obj.tmp"));
	CHECK_INT(dir_count(dirfd, ".", "."), 2);

	/* a symlink planted at a temporary after the listing: O_EXCL | O_NOFOLLOW refuses
	 * it, it is not followed nor removed, and nothing of the set is left */
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".tree-0006.mtl.tmp"), 0);
	CHECK_INT(export_set_write(dirfd, &s, 6, &err), -EEXIST);
	CHECK(strstr(err.msg, "tree-0006.mtl"));
	CHECK(exists(dirfd, ".tree-0006.mtl.tmp"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0006"), 0);
	CHECK_INT(dir_count(dirfd, ".", "."), 3);
	CHECK_INT(unlinkat(dirfd, ".tree-0006.mtl.tmp", 0), 0);

	/* a final name that turned up after the listing: the rename refuses to replace
	 * it, the renamed ones are taken back */
	touch(dirfd, "tree-0006.png");
	CHECK_INT(export_set_write(dirfd, &s, 6, &err), -EEXIST);
	CHECK_INT(dir_count(dirfd, ".", "tree-0006"), 1);
	CHECK_INT(dir_count(dirfd, ".", "."), 2);
	/* and save goes round once more, past it */
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0007"));

	/* the fallback without RENAME_NOREPLACE refuses too */
	touch(dirfd, "a");
	touch(dirfd, "b");
	CHECK_INT(export_set_rename(dirfd, "a", "b", false), -EEXIST);
	CHECK_INT(export_set_rename(dirfd, "a", "c", false), 0);
	CHECK(exists(dirfd, "c") && !exists(dirfd, "a"));
	CHECK_INT(export_set_rename(dirfd, "c", "b", true), -EEXIST);
	export_set_finish(&s);
	close(dirfd);
}

static void test_many(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	int dirfd;

	snprintf(path, sizeof(path), "%s/many", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	/* thousands of files, as a well-used stick's, in the cases other systems write */
	for (int i = 1; i <= 3000; i++) {
		static const char *const forms[] = { "tree-%04d.glb", "TREE-%04d.PNG", "Tree-%d.Obj",
						     "photo-%d.jpg" };

		snprintf(path, sizeof(path), forms[i % 4], i);
		touch(dirfd, path);
	}
	export_set_init(&s);
	set_of(app, &s, false);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-3001")); /* past tree-3000.glb; 2999 is a photo */
	CHECK(exists(dirfd, "tree-3001.glb"));
	export_set_finish(&s);
	close(dirfd);
}

/* A full disk, as a file size limit: the first file is written, a later one fails. */
static void test_full(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct rlimit old, lim;
	int dirfd;

	snprintf(path, sizeof(path), "%s/full", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, true);
	/* the glb fits, a larger file after it does not */
	CHECK(s.files[EXPORT_SET_PNG].len > s.files[EXPORT_SET_GLB].len);
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = s.files[EXPORT_SET_GLB].len;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "tree-0001.") && strstr(err.msg, strerror(EFBIG)));
	CHECK_INT(dir_count(dirfd, ".", "tree-"), 0);
	CHECK_INT(dir_count(dirfd, ".", "."), 2);
	/* with room again, the same set goes in whole */
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001"));
	export_set_finish(&s);
	close(dirfd);
}

/* Save on today's forest (docs/forest.md): forest-DATE.glb beside the set, never over a
 * name (the same day again: -2, -3, ...), never through a symlink, a stale temporary of
 * ours removed, a bad date refused, a full stick leaving nothing of it. */
static void test_forest(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct rlimit old, lim;
	int dirfd;

	snprintf(path, sizeof(path), "%s/forest", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, false);
	CHECK_INT(buf_append(&s.forest, "glTF forest bytes", 17), 0);
	snprintf(s.forest_date, sizeof(s.forest_date), "2026-12-05");
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001") && !strcmp(s.forest_name, "forest-2026-12-05.glb"));
	CHECK(exists(dirfd, "forest-2026-12-05.glb"));
	/* the same day again, with a symlink at -2 (a hostile stick): past both */
	CHECK_INT(symlinkat("/etc/passwd", dirfd, "forest-2026-12-05-2.glb"), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0002") && !strcmp(s.forest_name, "forest-2026-12-05-3.glb"));
	{
		char target[64] = { 0 };

		CHECK(readlinkat(dirfd, "forest-2026-12-05-2.glb", target, sizeof(target) - 1) > 0);
		CHECK(!strcmp(target, "/etc/passwd"));
	}
	/* a temporary a pulled stick left (another day's too): gone at the next save */
	touch(dirfd, ".forest-2026-11-30.glb.tmp");
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".forest-2026-12-05.glb.tmp"), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(s.forest_name, "forest-2026-12-05-4.glb"));
	CHECK(!exists(dirfd, ".forest-2026-11-30.glb.tmp") && !exists(dirfd, ".forest-2026-12-05.glb.tmp"));
	CHECK_INT(dir_count(dirfd, ".", ".forest"), 0);
	/* a date that is not one: refused, nothing written */
	snprintf(s.forest_date, sizeof(s.forest_date), "../../etc");
	CHECK_INT(export_set_write_forest(dirfd, &s, &err), -EINVAL);
	CHECK_INT(dir_count(dirfd, ".", "forest-"), 4);
	/* a full stick: no temporary, no final name of it */
	snprintf(s.forest_date, sizeof(s.forest_date), "2026-12-06");
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = 8;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(export_set_write_forest(dirfd, &s, &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "forest-2026-12-06.glb"));
	CHECK_INT(dir_count(dirfd, ".", "forest-2026-12-06"), 0);
	CHECK_INT(dir_count(dirfd, ".", ".forest"), 0);
	/* an empty canvas on the forest: the forest alone */
	s.forest_only = true;
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "forest-2026-12-06.glb") && exists(dirfd, base));
	CHECK_INT(dir_count(dirfd, ".", "tree-"), 12); /* three sets of four, as before */
	export_set_finish(&s);
	close(dirfd);
}

int main(void)
{
	char root[] = "/tmp/edaha-export-set-XXXXXX", cmd[128];
	struct app *app = app_create(64, 64, 1);

	CHECK(app);
	test_classify();
	test_next();
	CHECK(mkdtemp(root));
	test_save(app, root);
	test_many(app, root);
	test_full(app, root);
	test_forest(app, root);
	app_destroy(app);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	CHECK_INT(system(cmd), 0);
	return 0;
}
