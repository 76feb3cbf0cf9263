/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

/* The page's own parts as compiled in (tools/embed-presets.py writes
 * export_page_parts_data.c from src/export/page/): "page-style" (CSS), "page-viewer"
 * (edaha's script), "page-notice" (the comment naming three.js and its licence). */
struct export_page_part_text {
	const char *name; /* the file's name without its extension */
	const char *text;
	size_t len;
};
extern const struct export_page_part_text export_page_part_texts[];
extern const size_t export_page_part_ntexts;
