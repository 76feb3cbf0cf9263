/* SPDX-License-Identifier: MIT */
/* The kiosk's templates: presets/\*.yaml, compiled in, read as any parameter file. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "gen.h"
#include "gen_presets.h"

static const char *const names[GEN_PRESET_COUNT] = {
	[GEN_PRESET_CHERRY] = "cherry",
	[GEN_PRESET_ZELKOVA] = "zelkova",
	[GEN_PRESET_HEDGE] = "hedge",
	[GEN_PRESET_BALL] = "ball",
	[GEN_PRESET_CONE] = "cone",
	[GEN_PRESET_PALM] = "palm",
};

const char *gen_preset_name(enum gen_preset p)
{
	return (unsigned)p < GEN_PRESET_COUNT ? names[p] : "?";
}

int gen_preset(enum gen_preset which, struct gen_params *p, struct error *err)
{
	char file[64];

	if ((unsigned)which >= GEN_PRESET_COUNT)
		return error_set(err, -EINVAL, "no such preset");
	for (size_t i = 0; i < gen_preset_ntexts; i++) {
		const struct gen_preset_text *t = &gen_preset_texts[i];

		if (strcmp(t->name, names[which]))
			continue;
		snprintf(file, sizeof(file), "presets/%s.yaml", t->name);
		return gen_read(t->text, t->len, file, 0, p, err);
	}
	return error_set(err, -EINVAL, "presets/%s.yaml was not compiled in", names[which]);
}
