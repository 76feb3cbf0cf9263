/* SPDX-License-Identifier: MIT */
/* drm_kms_pick_mode: the configured mode, the preferred one, the fallback on replug. */
#include <string.h>

#include "drm_kms.h"
#include "test.h"

static drmModeModeInfo mode(int w, int h, int hz, bool preferred)
{
	drmModeModeInfo m;

	memset(&m, 0, sizeof(m));
	m.hdisplay = (uint16_t)w;
	m.vdisplay = (uint16_t)h;
	m.vrefresh = (uint32_t)hz;
	m.type = DRM_MODE_TYPE_DRIVER | (preferred ? DRM_MODE_TYPE_PREFERRED : 0);
	return m;
}

int main(void)
{
	const drmModeModeInfo modes[] = {
		mode(1920, 1080, 60, false), mode(1920, 1080, 50, false), mode(1280, 800, 75, true),
		mode(1280, 800, 60, true), mode(1024, 768, 60, false),
	};
	const drmModeModeInfo unpreferred[] = { mode(1024, 768, 60, false), mode(800, 600, 60, false) };
	int n = (int)(sizeof(modes) / sizeof(modes[0]));

	/* nothing asked: the first preferred mode, wherever it is listed */
	CHECK(drm_kms_pick_mode(modes, n, 0, 0, 0, false) == &modes[2]);
	/* no preferred mode: the first listed one */
	CHECK(drm_kms_pick_mode(unpreferred, 2, 0, 0, 0, false) == &unpreferred[0]);
	/* a size: its first mode, any rate; a size and rate: that one */
	CHECK(drm_kms_pick_mode(modes, n, 1920, 1080, 0, false) == &modes[0]);
	CHECK(drm_kms_pick_mode(modes, n, 1920, 1080, 50, false) == &modes[1]);
	CHECK(drm_kms_pick_mode(modes, n, 1280, 800, 60, false) == &modes[3]);
	/* not offered: nothing, unless falling back (a display replugged) */
	CHECK(drm_kms_pick_mode(modes, n, 1920, 1080, 30, false) == NULL);
	CHECK(drm_kms_pick_mode(modes, n, 3840, 2160, 0, false) == NULL);
	CHECK(drm_kms_pick_mode(modes, n, 3840, 2160, 0, true) == &modes[2]);
	CHECK(drm_kms_pick_mode(unpreferred, 2, 1280, 800, 75, true) == &unpreferred[0]);
	/* offered and falling back: still the mode asked for */
	CHECK(drm_kms_pick_mode(modes, n, 1024, 768, 60, true) == &modes[4]);
	/* no modes at all */
	CHECK(drm_kms_pick_mode(modes, 0, 0, 0, 0, true) == NULL);
	puts("drm_kms: OK");
	return 0;
}
