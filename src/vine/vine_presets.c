/* SPDX-License-Identifier: MIT */
/* The vine presets: presets/vines/\*.yaml, compiled in, read as any vine parameter file. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "vine.h"
#include "vine_presets.h"

/* a test checks each is compiled in and nothing else is */
static const char *const names[] = { "default", "morning-glory" };

const char *const *vine_preset_names(size_t *n)
{
	if (n)
		*n = sizeof(names) / sizeof(names[0]);
	return names;
}

int vine_preset(const char *name, struct vine_params *p, struct error *err)
{
	char file[64];

	if (!name)
		return error_set(err, -EINVAL, "no such vine preset");
	for (size_t i = 0; i < vine_preset_ntexts; i++) {
		const struct vine_preset_text *t = &vine_preset_texts[i];

		if (strcmp(t->name, name))
			continue;
		snprintf(file, sizeof(file), "presets/vines/%s.yaml", t->name);
		return vine_read(t->text, t->len, file, p, err);
	}
	return error_set(err, -EINVAL, "no vine preset \"%.32s\" (presets/vines/)", name);
}
