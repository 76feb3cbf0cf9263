/* SPDX-License-Identifier: MIT */
#include <stdio.h>

#include "config.h"
#include "headless.h"
#include "options.h"
#if HAVE_DRM
#include "config_file.h"
#include "kiosk.h"
#endif
#if HAVE_DRM && HAVE_LIBINPUT
#include "input_libinput.h"
#endif
#if HAVE_DRM && HAVE_GPIOD
#include "gpio.h"
#endif

/* The kiosk needs the DRM/GBM display back-end; a build without it is headless only. */
#define KIOSK_AVAILABLE HAVE_DRM

#if HAVE_DRM
/* The input modules hand their events to the loop's app. */
static void feed(void *data, const struct event *ev)
{
	kiosk_feed(data, ev);
}

static int add_source(struct kiosk *k, struct kiosk_source src)
{
	int ret = kiosk_add_source(k, &src);

	if (ret < 0)
		fputs("edaha: out of memory\n", stderr);
	return ret;
}
#endif

static int kiosk_main(const struct options *o)
{
#if HAVE_DRM
	struct kiosk_config cfg = {
		.seed = o->seed,
		.record = o->record,
		.frames = o->kiosk_frames,
		.screenshot = o->screenshot,
	};
	struct config conf;
	struct error err = { { 0 } };
	struct kiosk *k;
	int status = 1, w, h;
#if HAVE_LIBINPUT
	struct input *in = NULL;
#endif
#if HAVE_GPIOD
	struct gpio *g = NULL;
#endif

	(void)w, (void)h;
	if (o->load) {
		fputs("edaha: --load is not in the kiosk yet; use it with --headless\n", stderr);
		return 2;
	}
	/* a broken configuration is the installer's to fix: say where, and stop */
	if (config_load(o->config ? o->config : CONFIG_PATH, &conf, stderr, &err) < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return 2;
	}
	cfg.display.card = conf.display.card[0] ? conf.display.card : NULL;
	cfg.display.connector = conf.display.connector[0] ? conf.display.connector : NULL;
	cfg.display.width = conf.display.mode_w;
	cfg.display.height = conf.display.mode_h;
	cfg.display.refresh = conf.display.mode_hz;
	cfg.display.rotation = conf.display.rotation;
	k = kiosk_create(&cfg);
	if (!k)
		return 1;
#if HAVE_LIBINPUT
	/* without a pen the kiosk still shows itself (and its buttons may still work) */
	kiosk_size(k, &w, &h);
	in = input_create(&conf, w, h, feed, k, &err);
	if (!in)
		fprintf(stderr, "edaha: warning: no pen input: %s\n", err.msg);
	else if (add_source(k, input_source(in)) < 0)
		goto out;
#endif
#if HAVE_GPIOD
	g = gpio_create(&conf, feed, k, &err);
	if (!g)
		fprintf(stderr, "edaha: warning: no GPIO buttons: %s\n", err.msg);
	else if (gpio_button_count(g) > 0 && add_source(k, gpio_source(g)) < 0)
		goto out;
#endif
	status = kiosk_run(k);
#if HAVE_LIBINPUT || HAVE_GPIOD
out:
#endif
#if HAVE_GPIOD
	gpio_destroy(g);
#endif
#if HAVE_LIBINPUT
	input_destroy(in);
#endif
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
