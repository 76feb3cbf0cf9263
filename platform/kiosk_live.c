/* SPDX-License-Identifier: MIT */
/*
 * The living tree on the kiosk (docs/living-trees.md): the wind and growing in as the
 * configuration sets them, and the pace of the frames while the tree moves by itself. A
 * still tree (wind 0, nothing growing) is drawn only when something changed, as always;
 * a moving one at the display's rate, capped at max_fps: each frame costs the board the
 * GPU's work on the whole tree, so the cap is what bounds its power and heat.
 */
#include "kiosk_private.h"

#include <errno.h>
#include <stdio.h>

int kiosk_live_setup(struct kiosk *k)
{
	double s = k->cfg.wind < 0.0 ? LIVE_WIND_DEFAULT_STRENGTH : k->cfg.wind;
	int ret = app_set_wind(k->app, s);

	if (ret == -EINVAL) {
		fprintf(stderr, "edaha: wind %g is not in 0..1: the tree stands still\n", s);
		ret = app_set_wind(k->app, 0.0);
	}
	app_set_grow_in(k->app, !k->cfg.grow_in_off);
	if (ret < 0)
		fputs("edaha: out of memory setting the wind\n", stderr);
	return ret;
}

uint64_t kiosk_living_next_us(const struct kiosk *k)
{
	unsigned fps = k->cfg.max_fps ? k->cfg.max_fps : KIOSK_MAX_FPS_DEFAULT;

	return k->frame_start_us + 1000000u / fps;
}
