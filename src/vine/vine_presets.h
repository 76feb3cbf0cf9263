/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "error.h"
#include "vine.h"

/* The vine preset files as compiled in (tools/embed-presets.py writes vine_presets_data.c
 * from presets/vines/). */
struct vine_preset_text {
	const char *name; /* the file's name without .yaml */
	const char *text;
	size_t len;
};
extern const struct vine_preset_text vine_preset_texts[];
extern const size_t vine_preset_ntexts;

/* The compiled-in presets (presets/vines/: default, morning-glory), read as any vine file
 * (vine_read): 0, or -EINVAL with err naming the preset (*p unchanged). */
const char *const *vine_preset_names(size_t *n);
int vine_preset(const char *name, struct vine_params *p, struct error *err);
