/* SPDX-License-Identifier: MIT */
/*
 * TEMPORARY (branch i15-kiosk): the presets' interface (ori.h: ori_preset,
 * ori_preset_names) with designs written in code, so the kiosk's side can be built and
 * tested before branch i15-read (the presets in presets/leaves, the design reader) is merged.
 * Deleted by that merge: the real presets replace these.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "ori.h"

static const char *const names[] = { "entire", "hop", "maple" };

const char *const *ori_preset_names(size_t *n)
{
	*n = sizeof(names) / sizeof(names[0]);
	return names;
}

int ori_preset(const char *name, struct ori_design *d, struct error *err)
{
	struct ori_design x;

	memset(&x, 0, sizeof(x));
	snprintf(x.name, sizeof(x.name), "%s", name);
	x.junction = 0.38;
	x.theta0 = 200;
	x.rest = 0.9;
	if (!strcmp(name, "maple")) {
		x.fold = ORI_FOLD_FAN;
		x.size = 0.08;
		x.middle[0] = x.middle[1] = 25;
		x.nsides = 2;
		x.sides[0] = (struct ori_side){ 55, 0, 0.5, 30, 30, 0 };
		x.sides[1] = (struct ori_side){ 45, 0, 0.5, 30, 30, 0 };
	} else if (!strcmp(name, "entire")) {
		x.fold = ORI_FOLD_HALF;
		x.size = 0.06;
		x.middle[0] = x.middle[1] = 90;
		x.width = 0.32;
		x.power = 0.8;
	} else if (!strcmp(name, "hop")) {
		/* three lobes, the side ones toothed by two forks of their veins */
		x.fold = ORI_FOLD_FAN;
		x.size = 0.07;
		x.rest = 0.85;
		x.middle[0] = x.middle[1] = 30;
		x.nsides = 1;
		x.sides[0] = (struct ori_side){ 55, 2, 0.45, 15, 15, 0 };
		x.junction = 0.4;
		x.theta0 = 500;
	} else {
		return error_set(err, -EINVAL, "%s: no such leaf preset", name);
	}
	*d = x;
	return 0;
}
