/* SPDX-License-Identifier: MIT */
#include "export_dir.h"

#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fileio.h"
#include "output.h"

static const char *const suffixes[] = { ".glb", ".obj", ".mtl", ".png", ".edaha" };
#define NSUFFIXES (sizeof(suffixes) / sizeof(suffixes[0]))

/* Whether any name of set n exists in dirfd (a dangling symlink counts: it is a name). */
static int set_taken(int dirfd, unsigned n, bool *taken)
{
	char name[32];
	struct stat st;

	*taken = false;
	for (size_t i = 0; i < NSUFFIXES; i++) {
		snprintf(name, sizeof(name), "tree-%04u%s", n, suffixes[i]);
		if (fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0) {
			*taken = true;
			return 0;
		}
		if (errno != ENOENT)
			return -errno;
	}
	return 0;
}

int export_dir_write(const struct app *app, const char *dir, const uint8_t *rgba, char *base,
		     size_t base_size, struct error *err)
{
	char names[NSUFFIXES][32];
	struct output_names out;
	unsigned n = 0;
	bool taken = true;
	int dirfd, ret;

	ret = fileio_mkdirs(dir, err);
	if (ret < 0)
		return ret;
	dirfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dirfd < 0)
		return error_set(err, -errno, "%s: %s", dir, strerror(errno));
	while (taken && ++n <= EXPORT_DIR_MAX_SETS) {
		ret = set_taken(dirfd, n, &taken);
		if (ret < 0) {
			close(dirfd);
			return error_set(err, ret, "%s: %s", dir, strerror(-ret));
		}
	}
	close(dirfd);
	if (taken)
		return error_set(err, -EEXIST, "%s already holds %d exports", dir, EXPORT_DIR_MAX_SETS);
	for (size_t i = 0; i < NSUFFIXES; i++)
		snprintf(names[i], sizeof(names[i]), "tree-%04u%s", n, suffixes[i]);
	out = (struct output_names){ .glb = names[0], .obj = names[1], .mtl = names[2],
				     .png = names[3], .drawing = names[4] };
	ret = output_write(app, dir, &out, rgba, err);
	if (ret == 0)
		snprintf(base, base_size, "tree-%04u", n);
	return ret;
}
