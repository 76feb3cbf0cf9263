/* SPDX-License-Identifier: MIT */
/* The leaf presets: presets/leaves/\*.yaml, compiled in, read as any design file. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "ori.h"
#include "ori_presets.h"

/* ori.h's order; a test checks each is compiled in and nothing else is */
static const char *const names[] = { "entire", "hop", "maple" };

const char *const *ori_preset_names(size_t *n)
{
	if (n)
		*n = sizeof(names) / sizeof(names[0]);
	return names;
}

int ori_preset(const char *name, struct ori_design *d, struct error *err)
{
	char file[64];

	if (!name)
		return error_set(err, -EINVAL, "no such leaf preset");
	for (size_t i = 0; i < ori_preset_ntexts; i++) {
		const struct ori_preset_text *t = &ori_preset_texts[i];

		if (strcmp(t->name, name))
			continue;
		snprintf(file, sizeof(file), "presets/leaves/%s.yaml", t->name);
		return ori_read(t->text, t->len, file, d, err);
	}
	return error_set(err, -EINVAL, "no leaf preset \"%.32s\" (presets/leaves/)", name);
}
