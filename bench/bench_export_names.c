/* SPDX-License-Identifier: MIT */
/*
 * Picking the next export's number in a directory that already holds N files (a
 * well-used USB stick): export_set_pick's one readdir with export_names' classification,
 * against probing numbers one by one with five fstatat each (what export_dir.c did
 * before USB export), for N = 10, 1,000 and 10,000 files (N/5 sets of five, names in mixed
 * case). Medians of REPS runs, in a directory under /tmp (TMPDIR); then the
 * classification alone, per name.
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
	return 0;
}
