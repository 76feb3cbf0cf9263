/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The malformed files of a reader's test directory: DIR/EXPECT lists them, a line each,
 * "FILE LINE TEXT" (# comments). Each must be refused with -EINVAL, its out left as it was
 * (nothing half-read), the message "PATH:LINE: ..." containing TEXT, LINE judged by
 * reading the file. For the flat and YAML readers' tests (vine, wood, leaf designs).
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "fileio.h"
#include "test.h"

/* What the test's reader is: data (the file's text, named path) into out. */
typedef int (*malformed_read_fn)(const char *data, size_t len, const char *path, void *out,
				 struct error *err);

static inline char *malformed_path(const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	char *p = malloc(n);

	CHECK(p);
	snprintf(p, n, "%s/%s", dir, name);
	return p;
}

/* Checks every file EXPECT names; returns how many. out is scratch of size bytes. */
static inline int malformed_dir_check(const char *dir, malformed_read_fn read, void *out,
				      size_t size)
{
	char *expect = malformed_path(dir, "EXPECT"), *data;
	unsigned char *before = malloc(size);
	size_t len;
	struct error err;
	int count = 0;

	CHECK(before);
	CHECK_INT(fileio_read_all(expect, 1 << 20, &data, &len, &err), 0);
	for (char *line = strtok(data, "\n"); line; line = strtok(NULL, "\n")) {
		char name[128], want[192], *path, *text, *file;
		size_t flen;
		unsigned long at;
		int skip = 0, ret;

		if (line[0] == '#')
			continue;
		CHECK(sscanf(line, "%127s %lu %n", name, &at, &skip) == 2 && skip > 0);
		text = line + skip;
		CHECK(*text);
		path = malformed_path(dir, name);
		CHECK_INT(fileio_read_all(path, 1 << 20, &file, &flen, &err), 0);
		memset(out, 0xa5, size);
		memcpy(before, out, size);
		ret = read(file, flen, path, out, &err);
		if (ret != -EINVAL) {
			fprintf(stderr, "%s: not refused with -EINVAL (%d)\n", path, ret);
			CHECK(0);
		}
		CHECK(memcmp(out, before, size) == 0); /* nothing half-read */
		snprintf(want, sizeof(want), "%s:%lu: ", path, at);
		if (strncmp(err.msg, want, strlen(want)) != 0 || !strstr(err.msg, text)) {
			fprintf(stderr, "%s: expected \"%s...%s...\", got \"%s\"\n", name, want, text,
				err.msg);
			CHECK(0);
		}
		printf("%s\n", err.msg);
		free(file);
		free(path);
		count++;
	}
	free(before);
	free(data);
	free(expect);
	return count;
}
