/* SPDX-License-Identifier: MIT */
/*
 * Every malformed trace in tests/malformed (argv[1]) listed in its EXPECT file
 * ("FILENAME LINE", 0 when only the file can be named) fails to load with -EINVAL and a
 * message starting "PATH:LINE: ". Every *.edaha-trace and *.yml there must be listed.
 */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "trace.h"

#define MAX_FILES 256

static bool ends_with(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);

	return n >= m && strcmp(s + n - m, suffix) == 0;
}

static void check_file(const char *dir, const char *file, unsigned long line)
{
	char path[1024], prefix[1100];
	struct trace t = { 0 };
	struct error err = { { 0 } };
	int r;

	snprintf(path, sizeof(path), "%s/%s", dir, file);
	if (line)
		snprintf(prefix, sizeof(prefix), "%s:%lu: ", path, line);
	else
		snprintf(prefix, sizeof(prefix), "%s: ", path);
	r = trace_load(path, 1280, 800, &t, &err);
	printf("%s\n", r < 0 ? err.msg : "(accepted)");
	if (r != -EINVAL || strncmp(err.msg, prefix, strlen(prefix)) != 0) {
		fprintf(stderr, "%s: r = %d, message \"%s\", wanted -EINVAL and \"%s...\"\n", file, r,
			err.msg, prefix);
		exit(1);
	}
	/* The message says something after the location. */
	CHECK(strlen(err.msg) > strlen(prefix) + 8);
	CHECK(t.nevents == 0 && t.events == NULL);
}

int main(int argc, char **argv)
{
	const char *dir = argc > 1 ? argv[1] : "tests/malformed";
	char path[1024], name[256], *listed[MAX_FILES];
	size_t nlisted = 0, nedaha = 0, nyaml = 0;
	unsigned long line;
	struct dirent *de;
	FILE *f;
	DIR *d;

	snprintf(path, sizeof(path), "%s/EXPECT", dir);
	f = fopen(path, "r");
	if (!f) {
		perror(path);
		return 1;
	}
	while (fscanf(f, "%255s %lu", name, &line) == 2) {
		CHECK(nlisted < MAX_FILES);
		check_file(dir, name, line);
		listed[nlisted] = strdup(name);
		CHECK(listed[nlisted]);
		nlisted++;
		nedaha += ends_with(name, ".edaha-trace");
		nyaml += ends_with(name, ".yml");
	}
	CHECK(feof(f));
	fclose(f);
	CHECK(nedaha >= 12);
	CHECK(nyaml >= 8);

	/* Nothing in the folder goes untested. */
	d = opendir(dir);
	CHECK(d);
	while ((de = readdir(d))) {
		bool found = false;

		if (!ends_with(de->d_name, ".edaha-trace") && !ends_with(de->d_name, ".yml"))
			continue;
		for (size_t i = 0; i < nlisted; i++)
			found |= strcmp(listed[i], de->d_name) == 0;
		if (!found) {
			fprintf(stderr, "%s/%s is not listed in EXPECT\n", dir, de->d_name);
			return 1;
		}
	}
	closedir(d);
	for (size_t i = 0; i < nlisted; i++)
		free(listed[i]);
	printf("%zu malformed traces refused with the right line\n", nlisted);
	return 0;
}
