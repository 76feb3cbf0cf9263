/* SPDX-License-Identifier: MIT */
#include <stdio.h>

#include "config.h"
#include "headless.h"
#include "options.h"

/* The kiosk loop needs the DRM, libinput and GPIO back-ends; it is not built yet. */
#define KIOSK_AVAILABLE 0

static int kiosk_run(const struct options *o)
{
	(void)o;
	/* The DRM/libinput/GPIO kiosk loop is its own module (see docs/ARCHITECTURE.md). */
	fputs("edaha: this build has no kiosk display loop yet; use --headless (see --help)\n",
	      stderr);
	return 1;
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
			status = kiosk_run(&o);
	}
	options_finish(&o);
	return status;
}
