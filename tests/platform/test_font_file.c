/* SPDX-License-Identifier: MIT */
/* font_file_read: a named file or the first default that reads; errors name the file. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "font_file.h"
#include "test.h"

int main(void)
{
	struct error err = { { 0 } };
	const char *used = "x";
	char *data = (char *)1;
	size_t len = 7;

	CHECK_INT(font_file_read("/nonexistent/edaha/font.ttf", &data, &len, &used, &err), -ENOENT);
	CHECK(data == NULL && len == 0 && used == NULL);
	CHECK(strstr(err.msg, "/nonexistent/edaha/font.ttf") != NULL);
	CHECK(font_file_read("/", &data, &len, &used, &err) < 0); /* a directory */
	CHECK(data == NULL);

	/* the image installs fonts-vlgothic: the first default */
	CHECK_INT(font_file_read(NULL, &data, &len, &used, &err), 0);
	CHECK(used == font_file_defaults[0]);
	CHECK(len > 1000000);
	CHECK(memcmp(data, "\x00\x01\x00\x00", 4) == 0); /* a TrueType file */
	free(data);

	/* named, the same file */
	CHECK_INT(font_file_read(font_file_defaults[0], &data, &len, &used, &err), 0);
	CHECK(strcmp(used, font_file_defaults[0]) == 0);
	free(data);
	return 0;
}
