/* SPDX-License-Identifier: MIT */
/* Exports into a directory: numbered sets, never over an earlier file or a symlink. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"
#include "export_dir.h"
#include "test.h"

static bool exists(const char *dir, const char *name)
{
	char path[1024];
	struct stat st;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	return lstat(path, &st) == 0;
}

int main(void)
{
	char tmpl[] = "/tmp/edaha-export-XXXXXX", dir[600], path[700], base[32];
	const char *sub;
	struct app *app = app_create(64, 64, 1);
	uint8_t rgba[64 * 64 * 4] = { 0 };
	struct error err = { { 0 } };

	CHECK(app);
	CHECK(mkdtemp(tmpl));
	/* a directory that is not there yet */
	snprintf(dir, sizeof(dir), "%s/stick/edaha", tmpl);
	CHECK_INT(export_dir_write(app, dir, rgba, base, sizeof(base), &err), 0);
	CHECK(strcmp(base, "tree-0001") == 0);
	for (int i = 0; i < 5; i++) {
		static const char *const names[] = { "tree-0001.glb", "tree-0001.obj", "tree-0001.mtl",
						     "tree-0001.png", "tree-0001.edaha" };
		CHECK(exists(dir, names[i]));
	}
	CHECK_INT(export_dir_write(app, dir, NULL, base, sizeof(base), &err), 0);
	CHECK(strcmp(base, "tree-0002") == 0);
	CHECK(!exists(dir, "tree-0002.png")); /* no picture given */
	/* any name of a set taken, even by a dangling symlink, moves to the next set */
	snprintf(path, sizeof(path), "%s/tree-0003.mtl", dir);
	CHECK_INT(symlink("/nonexistent", path), 0);
	CHECK_INT(export_dir_write(app, dir, rgba, base, sizeof(base), &err), 0);
	CHECK(strcmp(base, "tree-0004") == 0);
	/* the obj names its own mtl */
	{
		char obj[700], line[256];
		FILE *f;
		bool found = false;

		snprintf(obj, sizeof(obj), "%s/tree-0004.obj", dir);
		f = fopen(obj, "r");
		CHECK(f);
		while (fgets(line, sizeof(line), f))
			found |= strcmp(line, "mtllib tree-0004.mtl\n") == 0;
		fclose(f);
		CHECK(found);
	}
	/* a file where the directory should be: an error naming it, nothing crashes */
	sub = "plain";
	snprintf(path, sizeof(path), "%s/%s", tmpl, sub);
	{
		FILE *f = fopen(path, "w");

		CHECK(f);
		fclose(f);
	}
	CHECK(export_dir_write(app, path, rgba, base, sizeof(base), &err) < 0);
	CHECK(strstr(err.msg, "plain"));
	app_destroy(app);
	CHECK_INT(system((snprintf(path, sizeof(path), "rm -rf '%s'", tmpl), path)), 0);
	return 0;
}
