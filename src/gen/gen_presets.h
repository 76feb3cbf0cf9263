/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

/* The preset files as compiled in (tools/embed-presets.py writes gen_presets_data.c). */
struct gen_preset_text {
	const char *name; /* the file's name without .yaml */
	const char *text;
	size_t len;
};
extern const struct gen_preset_text gen_preset_texts[];
extern const size_t gen_preset_ntexts;
