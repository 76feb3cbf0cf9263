/* SPDX-License-Identifier: MIT */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "config.h"
#include "config_file.h"
#include "forest_state.h"
#include "headless.h"
#include "options.h"
#if HAVE_DRM || HAVE_WINDOW
#include <errno.h>

#include "docfile.h"
#include "font_file.h"
#include "kiosk.h"
#include "kiosk_input.h"
#endif

/* The kiosk needs a display back-end: DRM/GBM, or SDL2's window on a desktop; a build
 * without either is headless only. */
#define KIOSK_AVAILABLE HAVE_DRM
#define WINDOW_AVAILABLE HAVE_WINDOW

#if HAVE_DRM || HAVE_WINDOW
/* The labels' font: the configured one, else the defaults; without one the kiosk still
 * runs, its buttons showing their icons. NULL then. */
static char *kiosk_font(const struct config *conf, size_t *len)
{
	struct error err = { { 0 } };
	const char *used;
	char *font = NULL;

	if (conf->font[0] && font_file_read(conf->font, &font, len, &used, &err) < 0)
		fprintf(stderr, "edaha: warning: %s; trying the default fonts\n", err.msg);
	if (!font && font_file_read(NULL, &font, len, &used, &err) < 0)
		fprintf(stderr, "edaha: warning: %s: the buttons show icons alone\n", err.msg);
	return font;
}

/* A window when asked, or under a desktop session (whose display the DRM path could
 * not become the master of) if this build has one; else the DRM screen. */
static enum display_kind display_kind(const struct options *o)
{
	const char *wayland = getenv("WAYLAND_DISPLAY"), *x11 = getenv("DISPLAY");

	if (o->window)
		return DISPLAY_WINDOW;
	if (o->kiosk)
		return DISPLAY_DRM;
	if (display_available(DISPLAY_WINDOW) && ((wayland && wayland[0]) || (x11 && x11[0])))
		return DISPLAY_WINDOW;
	return DISPLAY_DRM;
}
#endif

/* --forest-reset: the day file in the configuration's state directory says a new day
 * began now. */
static int forest_reset_main(const struct options *o)
{
	struct config conf;
	struct error err = { { 0 } };
	const char *path = o->config ? o->config : CONFIG_PATH;

	if (config_load(path, &conf, stderr, &err) < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return 2;
	}
	if (forest_state_reset(conf.kiosk.state_dir, (int64_t)time(NULL), &err) < 0) {
		fprintf(stderr, "edaha: --forest-reset: %s\n", err.msg);
		return 1;
	}
	printf("edaha: today's forest is empty: the next drawing archived in %s is its No. 1\n",
	       conf.kiosk.state_dir);
	return 0;
}

static int kiosk_main(const struct options *o)
{
#if HAVE_DRM || HAVE_WINDOW
	struct kiosk_config cfg = {
		.seed = o->seed,
		.record = o->record,
		.frames = o->kiosk_frames,
		.screenshot = o->screenshot,
		.stats = o->stats,
	};
	struct config conf;
	struct error err = { { 0 } };
	struct doc doc;
	struct kiosk_input *in;
	struct kiosk *k;
	char *font;
	int status = 1;

	/* a broken configuration is the installer's to fix: say where, and stop */
	if (config_load(o->config ? o->config : CONFIG_PATH, &conf, stderr, &err) < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return 2;
	}
	cfg.export_dir = conf.kiosk.export_dir;
	cfg.usb = conf.usb.enabled;
	cfg.usb_socket = conf.usb.helper_socket;
	cfg.attract_after_us = (uint64_t)conf.kiosk.attract_after_s * 1000000u;
	cfg.state_dir = conf.kiosk.autosave ? conf.kiosk.state_dir : NULL;
	cfg.reset_after_us = (uint64_t)conf.kiosk.reset_after_s * 1000000u;
	cfg.archive_keep = (unsigned)conf.kiosk.archive_keep;
	cfg.wind = o->wind >= 0 ? o->wind : conf.kiosk.wind;
	cfg.grow_in_off = !conf.kiosk.grow_in;
	cfg.max_fps = (unsigned)conf.kiosk.max_fps;
	cfg.forest = conf.forest.enabled;
	cfg.forest_max = (unsigned)conf.forest.max_trees;
	cfg.forest_reset_hour = conf.forest.reset_hour;
	cfg.forest_reset_minute = conf.forest.reset_minute;
	if (o->load) {
		int ret = docfile_read(o->load, &doc, &err);

		if (ret < 0) {
			fprintf(stderr, "edaha: %s\n", err.msg);
			return ret == -ENOMEM || ret == -EIO ? 1 : 2;
		}
		if (o->seed_given && doc.seed != o->seed)
			fprintf(stderr, "edaha: %s keeps its own seed %llu; --seed ignored\n", o->load,
				(unsigned long long)doc.seed);
		cfg.doc = &doc;
	}
	cfg.display.kind = display_kind(o);
	if (!display_available(cfg.display.kind)) {
		fprintf(stderr, "edaha: this build has no %s; see --version\n",
			cfg.display.kind == DISPLAY_WINDOW ? "window (SDL2)" :
							   "kiosk display (libdrm/gbm)");
		if (cfg.doc)
			doc_finish(cfg.doc);
		return 1;
	}
	cfg.display.drm.card = conf.display.card[0] ? conf.display.card : NULL;
	cfg.display.drm.connector = conf.display.connector[0] ? conf.display.connector : NULL;
	cfg.display.drm.width = conf.display.mode_w;
	cfg.display.drm.height = conf.display.mode_h;
	cfg.display.drm.refresh = conf.display.mode_hz;
	cfg.display.drm.rotation = conf.display.rotation;
	/* the window's first size, and the app's for good (--size) */
	cfg.display.window.width = o->width;
	cfg.display.window.height = o->height;
	/* --lang over the configuration's */
	if (o->lang)
		cfg.language = strcmp(o->lang, "ja") == 0 ? RENDER_LANG_JA : RENDER_LANG_EN;
	else
		cfg.language = conf.language == CONFIG_LANG_JA ? RENDER_LANG_JA : RENDER_LANG_EN;
	font = kiosk_font(&conf, &cfg.font_len);
	cfg.font = font;
	k = kiosk_create(&cfg);
	if (!k) {
		free(font);
		return 1;
	}
	/* the renderer has its own copy */
	free(font);
	/* a window brings its own mouse and keys (display.h); the kiosk's tablet and GPIO
	 * buttons are the desktop's, not ours, there */
	in = NULL;
	if (cfg.display.kind == DISPLAY_WINDOW || (in = kiosk_input_create(&conf, k)))
		status = kiosk_run(k);
	kiosk_input_destroy(in);
	kiosk_destroy(k);
	return status;
#else
	(void)o;
	fputs("edaha: this build has no kiosk display (no libdrm/gbm, no SDL2); use --headless (see --help)\n",
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
			printf("edaha %s\nkiosk: %s\nwindow: %s\n", EDAHA_VERSION,
			       KIOSK_AVAILABLE ? "yes" : "no", WINDOW_AVAILABLE ? "yes" : "no");
		else if (o.headless && o.support)
			status = headless_vine_run(&o);
		else if (o.headless && o.leaf)
			status = headless_leaf_run(&o);
		else if (o.headless && o.forest)
			status = headless_forest_run(&o);
		else if (o.forest_reset)
			status = forest_reset_main(&o);
		else if (o.headless)
			status = headless_run(&o);
		else
			status = kiosk_main(&o);
	}
	options_finish(&o);
	return status;
}
