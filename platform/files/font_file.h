/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "error.h"

/* Larger files are refused: a CJK font collection is some 20 MB. */
#define FONT_FILE_MAX_BYTES (64u * 1024u * 1024u)

/* Where the labels' font is looked for when none is configured, in order: the image
 * installs fonts-vlgothic; the others are Debian's Japanese fonts, then one for English. */
extern const char *const font_file_defaults[];

/*
 * Reads the font for the on-screen labels: path, or with path NULL the first of
 * font_file_defaults that can be read. 0 with a malloc'ed *data of *len bytes and the
 * file's name in *used (path, or one of the defaults); -errno with a message in err.
 * Whether FreeType can use the bytes is the renderer's to find out.
 */
int font_file_read(const char *path, char **data, size_t *len, const char **used,
		   struct error *err);
