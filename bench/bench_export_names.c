/* SPDX-License-Identifier: MIT */
/*
 * Picking the next export's number in a directory that already holds N files (a
 * well-used USB stick): export_set_pick's one readdir with export_names' classification,
 * against probing numbers one by one with five fstatat each (what export_dir.c did
 * before USB export), for N = 10, 1,000 and 10,000 files (N/5 sets of five, names in mixed
 * case). Medians of REPS runs, in a directory under /tmp (TMPDIR); then the
 * classification alone, per name. Then the stick's gallery (gallery.c) for 2, 200 and
 * 2,000 saved trees (six files each: page, model, picture, obj, mtl, drawing): its one
 * listing, a stat a tree and the page in memory, and the whole write with its fsyncs
 * (the disk's, here; a USB stick's are slower).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench_util.h"
#include "error.h"
#include "export_names.h"
#include "export_set.h"
#include "gallery.h"

#define REPS 15

struct pick_arg {
	int dirfd;
	unsigned number;
};

static void pick_readdir(void *data)
{
	struct pick_arg *a = data;
	struct error err;

	if (export_set_pick(a->dirfd, &a->number, &err) < 0) {
		fprintf(stderr, "bench_export_names: %s\n", err.msg);
		exit(1);
	}
}

/* The way before: the first number none of whose five names exists, by fstatat. */
static void pick_stat(void *data)
{
	struct pick_arg *a = data;
	char name[48];
	struct stat st;

	for (unsigned n = 1; n <= EXPORT_NAMES_MAX; n++) {
		bool taken = false;

		for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES && !taken; i++) {
			export_names_format(name, sizeof(name), n, export_names_suffixes[i], false);
			taken = fstatat(a->dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0;
		}
		if (!taken) {
			a->number = n;
			return;
		}
	}
}

static int fill(int dirfd, int nfiles)
{
	static const char *const forms[] = { "tree-%04d.glb", "TREE-%04d.OBJ", "tree-%04d.mtl",
					     "Tree-%04d.png", "tree-%04d.edaha" };
	char name[48];

	for (int i = 0; i < nfiles; i++) {
		int fd;

		snprintf(name, sizeof(name), forms[i % 5], i / 5 + 1);
		fd = openat(dirfd, name, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
		if (fd < 0)
			return -errno;
		close(fd);
	}
	return 0;
}

static volatile unsigned sink;

static int fill_trees(int dirfd, int trees)
{
	static const char *const sfx[] = { ".html", ".glb", ".png", ".obj", ".mtl", ".edaha" };
	char name[48];

	for (int i = 1; i <= trees; i++) {
		for (size_t k = 0; k < sizeof(sfx) / sizeof(sfx[0]); k++) {
			int fd;

			export_names_format(name, sizeof(name), (unsigned)i, sfx[k], false);
			fd = openat(dirfd, name, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
			if (fd < 0)
				return -errno;
			close(fd);
		}
	}
	return 0;
}

struct gallery_arg {
	int dirfd;
	size_t count, bytes;
};

static void gallery_page(void *data)
{
	struct gallery_arg *a = data;
	struct error err;
	struct gallery g;
	struct buf html;

	gallery_init(&g);
	buf_init(&html);
	if (gallery_list(a->dirfd, &g, &err) < 0 || gallery_html(&g, CONFIG_LANG_EN, &html) < 0) {
		fprintf(stderr, "bench_export_names: gallery: %s\n", err.msg);
		exit(1);
	}
	a->count = g.count;
	a->bytes = html.len;
	buf_finish(&html);
	gallery_finish(&g);
}

static void gallery_whole(void *data)
{
	struct gallery_arg *a = data;
	struct error err;

	if (gallery_write(a->dirfd, CONFIG_LANG_EN, &a->count, &err) < 0) {
		fprintf(stderr, "bench_export_names: gallery: %s\n", err.msg);
		exit(1);
	}
}

static void classify_many(void *data)
{
	const int *count = data;
	char name[48];
	unsigned v = 0;

	for (int i = 0; i < *count; i++) {
		snprintf(name, sizeof(name), i & 1 ? "TREE-%04d.PNG" : "photo-%d.jpg", i);
		export_names_classify(name, &v);
	}
	sink = v;
}

int main(int argc, char **argv)
{
	static const int sizes[] = { 10, 1000, 10000 };
	const char *tmp = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
	double prev_n = 0, prev_s = 0, prev_n2 = 0, prev_s2 = 0;
	char dir[512], cmd[600];
	int reps;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);

	printf("%-28s %10s %12s\n", "stage", "files", "median");
	for (size_t k = 0; k < BENCH_COUNT(sizes); k++) {
		struct pick_arg a = { 0 };
		double t_readdir, t_stat;

		snprintf(dir, sizeof(dir), "%s/edaha-bench-names-XXXXXX", tmp);
		if (!mkdtemp(dir) || (a.dirfd = open(dir, O_RDONLY | O_DIRECTORY)) < 0 ||
		    fill(a.dirfd, sizes[k]) < 0) {
			perror("bench_export_names");
			return 1;
		}
		t_readdir = bench_run(pick_readdir, &a, reps);
		if (a.number != (unsigned)(sizes[k] + 4) / 5 + 1) {
			fprintf(stderr, "bench_export_names: picked %u in %s\n", a.number, dir);
			return 1;
		}
		bench_row("pick, one readdir", sizes[k], t_readdir, &prev_n, &prev_s);
		t_stat = bench_run(pick_stat, &a, reps);
		bench_row("pick, fstatat each (before)", sizes[k], t_stat, &prev_n2, &prev_s2);
		close(a.dirfd);
		snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
		if (system(cmd) != 0)
			return 1;
	}
	{
		int count = bench_quick ? 1000 : 100000;
		double t = bench_run(classify_many, &count, reps);

		printf("export_names_classify: %.1f ns a name (with its snprintf)\n", t / count * 1e9);
	}
	prev_n = prev_s = prev_n2 = prev_s2 = 0;
	for (size_t k = 0; k < BENCH_COUNT(sizes); k++) {
		struct gallery_arg a = { 0 };
		int trees = sizes[k] / 5;
		double t_page, t_write;

		snprintf(dir, sizeof(dir), "%s/edaha-bench-gallery-XXXXXX", tmp);
		if (!mkdtemp(dir) || (a.dirfd = open(dir, O_RDONLY | O_DIRECTORY)) < 0 ||
		    fill_trees(a.dirfd, trees) < 0) {
			perror("bench_export_names");
			return 1;
		}
		t_page = bench_run(gallery_page, &a, reps);
		if (a.count != (size_t)trees) {
			fprintf(stderr, "bench_export_names: the gallery lists %zu of %d\n", a.count,
				trees);
			return 1;
		}
		bench_row("gallery, list and page", trees, t_page, &prev_n, &prev_s);
		t_write = bench_run(gallery_whole, &a, reps);
		bench_row("gallery, written (fsyncs)", trees, t_write, &prev_n2, &prev_s2);
		printf("  index.html for %d trees: %zu bytes\n", trees, a.bytes);
		close(a.dirfd);
		snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
		if (system(cmd) != 0)
			return 1;
	}
	return 0;
}
