/* SPDX-License-Identifier: MIT */
#include "font_file.h"

#include <errno.h>

#include "fileio.h"

const char *const font_file_defaults[] = {
	"/usr/share/fonts/truetype/vlgothic/VL-PGothic-Regular.ttf",
	"/usr/share/fonts/truetype/vlgothic/VL-Gothic-Regular.ttf",
	"/usr/share/fonts/truetype/fonts-japanese-gothic.ttf",
	"/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc",
	"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
	NULL,
};

int font_file_read(const char *path, char **data, size_t *len, const char **used,
		   struct error *err)
{
	int ret = -ENOENT;

	*data = NULL;
	*len = 0;
	*used = NULL;
	if (path) {
		ret = fileio_read_all(path, FONT_FILE_MAX_BYTES, data, len, err);
		if (ret == 0)
			*used = path;
		return ret;
	}
	for (size_t i = 0; font_file_defaults[i]; i++) {
		ret = fileio_read_all(font_file_defaults[i], FONT_FILE_MAX_BYTES, data, len, err);
		if (ret == 0) {
			*used = font_file_defaults[i];
			return 0;
		}
	}
	return error_set(err, ret, "no font for the labels: none of the defaults (%s, ...) can be read",
			 font_file_defaults[0]);
}
