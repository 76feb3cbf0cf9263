/* SPDX-License-Identifier: MIT */
#include <stdio.h>

#include "config.h"
#include "headless.h"
#include "options.h"
#if HAVE_DRM
#include "kiosk.h"
#endif

/* The kiosk needs the DRM/GBM display back-end; a build without it is headless only. */
#define KIOSK_AVAILABLE HAVE_DRM

static int kiosk_main(const struct options *o)
{
#if HAVE_DRM
	struct kiosk_config cfg = {
		.seed = o->seed,
		.record = o->record,
		.frames = o->kiosk_frames,
		.screenshot = o->screenshot,
	};
	struct kiosk *k;
	int status;

	if (o->load) {
		fputs("edaha: --load is not in the kiosk yet; use it with --headless\n", stderr);
		return 2;
	}
	k = kiosk_create(&cfg);
	if (!k)
		return 1;
	status = kiosk_run(k);
	kiosk_destroy(k);
	return status;
#else
	(void)o;
	fputs("edaha: this build has no kiosk display (no libdrm/gbm); use --headless (see --help)\n",
	      stderr);
	return 1;
#endif
}

int main(int argc, char **argv)
{
	struct options o;
	int status = options_parse(&o, argc, argv);

	if (status == 0) {
		if (o.help)
			options_usage(stdout);
		else if (o.version)
			printf("edaha %s\nkiosk: %s\n", EDAHA_VERSION, KIOSK_AVAILABLE ? "yes" : "no");
		else if (o.headless)
			status = headless_run(&o);
		else
			status = kiosk_main(&o);
	}
	options_finish(&o);
	return status;
}
