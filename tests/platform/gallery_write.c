/* SPDX-License-Identifier: MIT */
/*
 * gallery_write DIR [en|ja]: writes DIR/index.html as a Save does (gallery.c), for
 * gallery.sh to open in a browser. Prints how many trees it lists.
 */
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "gallery.h"

int main(int argc, char **argv)
{
	struct error err = { { 0 } };
	size_t count = 0;
	int fd, r;

	if (argc < 2 || argc > 3) {
		fputs("usage: gallery_write DIR [en|ja]\n", stderr);
		return 2;
	}
	fd = open(argv[1], O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (fd < 0) {
		perror(argv[1]);
		return 1;
	}
	r = gallery_write(fd, argc == 3 && !strcmp(argv[2], "ja") ? CONFIG_LANG_JA : CONFIG_LANG_EN,
			  &count, &err);
	close(fd);
	if (r < 0) {
		fprintf(stderr, "gallery_write: %s\n", err.msg);
		return 1;
	}
	printf("%zu\n", count);
	return 0;
}
