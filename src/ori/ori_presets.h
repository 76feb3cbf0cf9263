/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

/* The leaf preset files as compiled in (tools/embed-presets.py writes ori_presets_data.c
 * from presets/leaves/). */
struct ori_preset_text {
	const char *name; /* the file's name without .yaml */
	const char *text;
	size_t len;
};
extern const struct ori_preset_text ori_preset_texts[];
extern const size_t ori_preset_ntexts;
