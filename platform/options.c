/* SPDX-License-Identifier: MIT */
#include "options.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"

#define DEFAULT_WIDTH 1280
#define DEFAULT_HEIGHT 800
#define DEFAULT_SEED 1

void options_usage(FILE *f)
{
	fputs("Usage: edaha [OPTIONS]\n"
	      "Sketch a tree with a pen, make it 3D, grow it, take it home.\n"
	      "\n"
	      "With no options edaha runs the kiosk fullscreen on the display.\n"
	      "\n"
	      "Headless runs (no display; EGL surfaceless rendering):\n"
	      "  --headless          run without a display and write results to --out\n"
	      "  --out DIR           where to write screen.png, model.glb, model.obj, model.mtl,\n"
	      "                      skeleton.json and drawing.edaha (created if missing)\n"
	      "  --size WxH          screen size in pixels (default 1280x800); a --window's\n"
	      "                      first size, the picture's for good\n"
	      "  --seed N            random seed of a new drawing (default 1); a loaded\n"
	      "                      drawing keeps its own seed\n"
	      "  --load FILE         continue a saved drawing (a drawing.edaha file)\n"
	      "  --generate FILE     start from the tree a parameter file describes (a\n"
	      "                      functional tree: docs/tree-params.md); --replay,\n"
	      "                      --press and --view apply after it\n"
	      "  --skeleton FILE.json  start from the branches of a skeleton.json (as\n"
	      "                      edaha writes it: docs/skeleton-format.md; its leaves and\n"
	      "                      vines are left out), a 3D tree: an import op of the\n"
	      "                      drawing; --replay, --press and --view apply after it;\n"
	      "                      not with --load or --generate (docs/wood.md)\n"
	      "  --replay FILE       feed recorded input: an edaha trace or a `libinput record`\n"
	      "                      YAML file; may be repeated\n"
	      "  --press BUTTON      press and release a button: 3d, clone, leaf, propagate,\n"
	      "                      vine, grow, undo, redo, export, new, fixed-count,\n"
	      "                      fixed-size, view, season, tpl-blank, tpl-cherry,\n"
	      "                      tpl-zelkova, tpl-hedge, tpl-ball, tpl-cone, tpl-palm,\n"
	      "                      gen-more, gen-fewer, gen-wider, gen-narrower,\n"
	      "                      gen-taller, gen-shorter, gen-leafier, gen-barer; may be\n"
	      "                      repeated.\n"
	      "                      --replay and --press apply in the order given.\n"
	      "  --view YAW[,PITCH]  show a 3D tree turned: the camera's azimuth (90 = from\n"
	      "                      the right) and height in degrees, after all input\n"
	      "  --idle SECONDS      show the screen this long after the last input, as the\n"
	      "                      kiosk would (messages fade after 4 s, the attract\n"
	      "                      screen comes after 90 s)\n"
	      "  --leaf NAME|FILE    an origami leaf alone instead of a tree: a preset (entire,\n"
	      "                      hop, maple) or a leaf design file (docs/leaf-format.md);\n"
	      "                      writes origami.json, leaf.glb and screen.png to --out\n"
	      "                      (docs/origami-leaves.md); only --opening and --size go\n"
	      "                      with it\n"
	      "  --opening T         how far the --leaf is open, from 0 (folded in the bud) to\n"
	      "                      1 (flat); default: the design's rest opening (a grown\n"
	      "                      leaf's, 0.9 in the presets)\n"
	      "  --support FILE.obj  a twining vine alone instead of a tree, grown to its end\n"
	      "                      on this support (a Wavefront OBJ, metres, y up); writes\n"
	      "                      skeleton.json (its \"vines\"), model.glb, model.obj,\n"
	      "                      model.mtl and screen.png to --out (docs/vines.md); needs\n"
	      "                      --vine and --plant; only --size goes with them\n"
	      "  --vine NAME|FILE    the vine: a preset (default, morning-glory) or a vine\n"
	      "                      file (docs/vine-format.md)\n"
	      "  --plant X,Y,Z       where the vine is planted, metres\n"
	      "  --wood FILE         what the grow button grows with: a wood settings file\n"
	      "                      (docs/wood-format.md); default: broadleaf, the 64 grid\n"
	      "  --dump-voxels       also write voxels.json and voxels.bin: the grown wood's\n"
	      "                      voxels after the last grow press (docs/wood.md)\n"
	      "  --forest DIR        today's forest instead of a tree: plants every *.edaha\n"
	      "                      in DIR (name order, numbered 1, 2, 3, ...; the newest\n"
	      "                      40 stand) and writes forest.json and forest.glb\n"
	      "                      (docs/forest.md); only --idle, --size, --lang and\n"
	      "                      --wind go with it\n"
	      "\n"
	      "Kiosk test runs (no effect on a normal kiosk):\n"
	      "  --kiosk-frames N    draw a new frame every vblank, as if the drawing changed\n"
	      "                      each time, and exit after N frames are shown; prints\n"
	      "                      the frame rate and the time to the first frame\n"
	      "  --screenshot FILE   write the last frame as a PNG: after --kiosk-frames N,\n"
	      "                      or the screen as it is when the kiosk stops\n"
	      "\n"
	      "Kiosk:\n"
	      "  --window            a resizable window on the desktop (SDL2): the mouse or a\n"
	      "                      tablet is the pen, keys 1-9 and letters the buttons\n"
	      "                      (docs/window.md); the default when WAYLAND_DISPLAY or\n"
	      "                      DISPLAY is set and this build has the window\n"
	      "  --kiosk             fullscreen on DRM/KMS even under a desktop session\n"
	      "  --config FILE       the configuration (default /etc/edaha/edaha.conf)\n"
	      "  --stats             on exit, print how long pen input took to reach the\n"
	      "                      screen (percentiles) and the frame rate\n"
	      "  --forest-reset      empty today's forest now (a new day begins: the next\n"
	      "                      archived drawing is its No. 1) and exit; the kiosk\n"
	      "                      running shows it at its next minute (docs/forest.md)\n"

	      "\n"
	      "Any mode:\n"
	      "  --wind S            the wind's strength, from 0 (still) to 1 (a gale);\n"
	      "                      headless default 0, the kiosk's kiosk.wind (default\n"
	      "                      0.35, a breeze); model.glb sways at it, or at 0.35\n"
	      "                      where it is 0 (docs/living-trees.md)\n"
	      "  --lang en|ja        language of the on-screen labels (default: the\n"
	      "                      configuration's, else en)\n"
	      "  --record FILE       write every input event to FILE as an edaha trace\n"
	      "  --help              show this help\n"
	      "  --version           show the version\n"
	      "\n"
	      "Exit status: 0 success, 1 runtime failure (display, files), 2 bad usage or\n"
	      "malformed input (the message names the file and line).\n"
	      "Formats: docs/trace-format.md, docs/document-format.md, docs/skeleton-format.md.\n",
	      f);
}

static int usage_error(const char *fmt, const char *arg)
{
	fputs("edaha: ", stderr);
	fprintf(stderr, fmt, arg);
	fputs("\nTry 'edaha --help'.\n", stderr);
	return 2;
}

static int add_step(struct options *o, struct step s)
{
	struct step *steps = realloc(o->steps, (o->nsteps + 1) * sizeof(*steps));

	if (!steps) {
		fputs("edaha: out of memory\n", stderr);
		return 2;
	}
	o->steps = steps;
	o->steps[o->nsteps++] = s;
	return 0;
}

static bool parse_size(const char *s, int *w, int *h)
{
	char *end;
	long x, y;

	errno = 0;
	x = strtol(s, &end, 10);
	if (errno || end == s || (*end != 'x' && *end != 'X'))
		return false;
	s = end + 1;
	y = strtol(s, &end, 10);
	if (errno || end == s || *end)
		return false;
	/* Small enough for any GL implementation's framebuffer limits. */
	if (x < 64 || y < 64 || x > 8192 || y > 8192)
		return false;
	*w = (int)x;
	*h = (int)y;
	return true;
}

static bool parse_seed(const char *s, uint64_t *seed)
{
	char *end;
	unsigned long long v;

	if (*s < '0' || *s > '9')
		return false;
	errno = 0;
	v = strtoull(s, &end, 10);
	if (errno || *end)
		return false;
	*seed = v;
	return true;
}

static bool parse_view(const char *s, double *yaw, double *pitch)
{
	char *end;

	errno = 0;
	*yaw = strtod(s, &end);
	*pitch = 0.0;
	if (errno || end == s || !isfinite(*yaw) || fabs(*yaw) > 360.0)
		return false;
	if (*end == ',') {
		s = end + 1;
		*pitch = strtod(s, &end);
		if (errno || end == s || !(*pitch >= CAMERA_PITCH_MIN_DEG && *pitch <= CAMERA_PITCH_MAX_DEG))
			return false;
	}
	return *end == '\0';
}

static bool parse_frames(const char *s, unsigned long *n)
{
	uint64_t v;

	/* a bound, so that a typo cannot keep a test VM busy for hours */
	if (!parse_seed(s, &v) || v < 1 || v > 1000000)
		return false;
	*n = (unsigned long)v;
	return true;
}

static bool parse_opening(const char *s, double *t)
{
	char *end;

	/* the range check refuses NaN and an overflow; an underflow is a fine 0 */
	*t = strtod(s, &end) + 0.0; /* + 0: -0 is 0 */
	return end != s && !*end && *t >= 0.0 && *t <= 1.0;
}

static bool parse_plant(const char *s, double p[3])
{
	char *end;

	for (int k = 0; k < 3; k++) {
		errno = 0;
		p[k] = strtod(s, &end) + 0.0; /* + 0: -0 is 0 */
		if (errno || end == s || !isfinite(p[k]) || *end != (k < 2 ? ',' : '\0'))
			return false;
		s = end + 1;
	}
	return true;
}

static bool parse_idle(const char *s, double *seconds)
{
	char *end;

	errno = 0;
	*seconds = strtod(s, &end);
	return !errno && end != s && !*end && *seconds >= 0.0 && *seconds <= 86400.0;
}

/* A wind's strength: a number from 0 to 1. */
static bool parse_wind(const char *s, double *strength)
{
	char *end;

	errno = 0;
	*strength = strtod(s, &end) + 0.0; /* + 0: -0 is 0 */
	return !errno && end != s && !*end && *strength >= 0.0 && *strength <= 1.0;
}

enum {
	OPT_HEADLESS = 256, OPT_SIZE, OPT_SEED, OPT_OUT, OPT_LOAD, OPT_REPLAY, OPT_PRESS, OPT_VIEW,
	OPT_RECORD, OPT_HELP, OPT_VERSION, OPT_KIOSK_FRAMES, OPT_SCREENSHOT, OPT_CONFIG, OPT_STATS,
	OPT_LANG, OPT_IDLE, OPT_GENERATE, OPT_LEAF, OPT_OPENING, OPT_SUPPORT, OPT_VINE, OPT_PLANT,
	OPT_WOOD, OPT_DUMP_VOXELS, OPT_SKELETON, OPT_WINDOW, OPT_KIOSK, OPT_WIND, OPT_FOREST,
	OPT_FOREST_RESET,
};

static const struct option longopts[] = {
	{ "headless", no_argument, NULL, OPT_HEADLESS },
	{ "size", required_argument, NULL, OPT_SIZE },
	{ "seed", required_argument, NULL, OPT_SEED },
	{ "out", required_argument, NULL, OPT_OUT },
	{ "load", required_argument, NULL, OPT_LOAD },
	{ "generate", required_argument, NULL, OPT_GENERATE },
	{ "skeleton", required_argument, NULL, OPT_SKELETON },
	{ "replay", required_argument, NULL, OPT_REPLAY },
	{ "press", required_argument, NULL, OPT_PRESS },
	{ "view", required_argument, NULL, OPT_VIEW },
	{ "record", required_argument, NULL, OPT_RECORD },
	{ "kiosk-frames", required_argument, NULL, OPT_KIOSK_FRAMES },
	{ "screenshot", required_argument, NULL, OPT_SCREENSHOT },
	{ "config", required_argument, NULL, OPT_CONFIG },
	{ "stats", no_argument, NULL, OPT_STATS },
	{ "window", no_argument, NULL, OPT_WINDOW },
	{ "kiosk", no_argument, NULL, OPT_KIOSK },
	{ "lang", required_argument, NULL, OPT_LANG },
	{ "idle", required_argument, NULL, OPT_IDLE },
	{ "leaf", required_argument, NULL, OPT_LEAF },
	{ "opening", required_argument, NULL, OPT_OPENING },
	{ "support", required_argument, NULL, OPT_SUPPORT },
	{ "vine", required_argument, NULL, OPT_VINE },
	{ "plant", required_argument, NULL, OPT_PLANT },
	{ "wood", required_argument, NULL, OPT_WOOD },
	{ "dump-voxels", no_argument, NULL, OPT_DUMP_VOXELS },
	{ "wind", required_argument, NULL, OPT_WIND },
	{ "forest", required_argument, NULL, OPT_FOREST },
	{ "forest-reset", no_argument, NULL, OPT_FOREST_RESET },
	{ "help", no_argument, NULL, OPT_HELP },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ NULL, 0, NULL, 0 },
};

/* What an option group's parser returns for an option that is not one of its own (else 0,
 * or 2 with the usage error printed). */
#define OPTION_NOT_OURS (-1)

/* An option naming a file: an empty name is a usage error, not "the current directory". */
static int set_file(const char **dst, const char *arg, const char *name)
{
	if (!arg[0])
		return usage_error("%s needs a file name", name);
	*dst = arg;
	return 0;
}

/* A headless run's start and its results: what it draws from, where it writes. */
static int parse_run_option(struct options *o, int c, const char *arg)
{
	switch (c) {
	case OPT_HEADLESS:
		o->headless = true;
		return 0;
	case OPT_OUT:
		o->out_dir = arg;
		return 0;
	case OPT_SIZE:
		if (!parse_size(arg, &o->width, &o->height))
			return usage_error("bad --size \"%s\" (expected WxH, 64..8192)", arg);
		return 0;
	case OPT_SEED:
		if (!parse_seed(arg, &o->seed))
			return usage_error("bad --seed \"%s\" (expected a whole number)", arg);
		o->seed_given = true;
		return 0;
	case OPT_LOAD:
		o->load = arg;
		return 0;
	case OPT_GENERATE:
		return set_file(&o->generate, arg, "--generate");
	case OPT_SKELETON:
		return set_file(&o->skeleton, arg, "--skeleton");
	case OPT_WOOD:
		return set_file(&o->wood, arg, "--wood");
	case OPT_DUMP_VOXELS:
		o->dump_voxels = true;
		return 0;
	}
	return OPTION_NOT_OURS;
}

/* The input a headless run is fed, in command-line order, and the screen after it. */
static int parse_input_option(struct options *o, int c, const char *arg)
{
	struct step s = { 0 };

	switch (c) {
	case OPT_REPLAY:
		s.kind = STEP_REPLAY;
		s.path = arg;
		return add_step(o, s);
	case OPT_PRESS:
		s.kind = STEP_PRESS;
		if (!button_from_name(arg, &s.button))
			return usage_error("unknown button \"%s\" (3d, clone, leaf, propagate, vine, "
					   "grow, undo, redo, export, new, fixed-count, fixed-size, "
					   "view, season, tpl-..., gen-...: see --help)", arg);
		return add_step(o, s);
	case OPT_VIEW:
		if (!parse_view(arg, &o->view_yaw, &o->view_pitch))
			return usage_error("bad --view \"%s\" (expected YAW or YAW,PITCH in degrees, "
					   "pitch -20..75)", arg);
		o->view_given = true;
		return 0;
	case OPT_IDLE:
		if (!parse_idle(arg, &o->idle_s))
			return usage_error("bad --idle \"%s\" (expected seconds, 0..86400)", arg);
		o->idle_given = true;
		return 0;
	}
	return OPTION_NOT_OURS;
}

/* The headless modes without a drawing: an origami leaf alone, a vine alone. */
static int parse_alone_option(struct options *o, int c, const char *arg)
{
	switch (c) {
	case OPT_LEAF:
		if (!arg[0])
			return usage_error("%s needs a leaf preset's name or a file name", "--leaf");
		o->leaf = arg;
		return 0;
	case OPT_OPENING:
		if (!parse_opening(arg, &o->opening))
			return usage_error("bad --opening \"%s\" (expected a number from 0, folded "
					   "in the bud, to 1, flat)", arg);
		o->opening_given = true;
		return 0;
	case OPT_SUPPORT:
		return set_file(&o->support, arg, "--support");
	case OPT_VINE:
		if (!arg[0])
			return usage_error("%s needs a vine preset's name or a file name", "--vine");
		o->vine = arg;
		return 0;
	case OPT_FOREST:
		return set_file(&o->forest, arg, "--forest");
	case OPT_PLANT:
		if (!parse_plant(arg, o->plant))
			return usage_error("bad --plant \"%s\" (expected X,Y,Z: three numbers, "
					   "metres)", arg);
		o->plant_given = true;
		return 0;
	}
	return OPTION_NOT_OURS;
}

/* The kiosk: its display, its configuration and its test runs. */
static int parse_kiosk_option(struct options *o, int c, const char *arg)
{
	switch (c) {
	case OPT_WINDOW:
		o->window = true;
		return 0;
	case OPT_KIOSK:
		o->kiosk = true;
		return 0;
	case OPT_CONFIG:
		return set_file(&o->config, arg, "--config");
	case OPT_STATS:
		o->stats = true;
		return 0;
	case OPT_KIOSK_FRAMES:
		if (!parse_frames(arg, &o->kiosk_frames))
			return usage_error("bad --kiosk-frames \"%s\" (expected 1..1000000)", arg);
		return 0;
	case OPT_SCREENSHOT:
		return set_file(&o->screenshot, arg, "--screenshot");
	case OPT_FOREST_RESET:
		o->forest_reset = true;
		return 0;
	}
	return OPTION_NOT_OURS;
}

/* Any mode's. */
static int parse_common_option(struct options *o, int c, const char *arg)
{
	switch (c) {
	case OPT_LANG:
		if (strcmp(arg, "en") != 0 && strcmp(arg, "ja") != 0)
			return usage_error("bad --lang \"%s\" (expected en or ja)", arg);
		o->lang = arg;
		return 0;
	case OPT_RECORD:
		o->record = arg;
		return 0;
	case OPT_WIND:
		if (!parse_wind(arg, &o->wind))
			return usage_error("bad --wind \"%s\" (expected a strength from 0, still, "
					   "to 1)", arg);
		return 0;
	case OPT_HELP:
		o->help = true;
		return 0;
	case OPT_VERSION:
		o->version = true;
		return 0;
	}
	return OPTION_NOT_OURS;
}

/* One option getopt_long() returned: 0, 2 (usage error, printed), or OPTION_NOT_OURS for an
 * unknown one or one without its argument. */
static int parse_option(struct options *o, int c, const char *arg)
{
	static int (*const groups[])(struct options *, int, const char *) = {
		parse_run_option, parse_input_option, parse_alone_option, parse_kiosk_option,
		parse_common_option,
	};

	for (size_t i = 0; i < sizeof(groups) / sizeof(groups[0]); i++) {
		int ret = groups[i](o, c, arg);

		if (ret != OPTION_NOT_OURS)
			return ret;
	}
	return OPTION_NOT_OURS;
}

/* The grow button's settings and voxels: a headless tree's, not a leaf's or a vine's. */
static int check_wood(const struct options *o)
{
	if (!o->headless && (o->wood || o->dump_voxels))
		return usage_error("%s needs --headless", o->wood ? "--wood" : "--dump-voxels");
	if ((o->leaf || o->support) && (o->wood || o->dump_voxels))
		return usage_error("%s is for a tree, not --leaf or --support",
				   o->wood ? "--wood" : "--dump-voxels");
	if (o->forest_reset && (o->headless || o->window || o->kiosk || o->kiosk_frames ||
				o->screenshot || o->stats || o->load || o->record || o->nsteps))
		return usage_error("%s goes with --config only", "--forest-reset");
	return 0;
}

/* What only a headless run takes: its input, its results, the modes without a drawing. */
static int check_headless_only(const struct options *o)
{
	if (!o->headless && (o->out_dir || o->nsteps || o->view_given || o->idle_given || o->generate ||
			     o->leaf || o->opening_given || o->support || o->vine || o->plant_given))
		return usage_error("%s needs --headless",
				   o->out_dir ? "--out" : o->nsteps ? "--replay/--press" :
				   o->view_given ? "--view" : o->generate ? "--generate" :
				   o->leaf ? "--leaf" : o->opening_given ? "--opening" :
				   o->support ? "--support" : o->vine ? "--vine" :
				   o->plant_given ? "--plant" : "--idle");
	return 0;
}

static int check_skeleton(const struct options *o)
{
	if (o->skeleton && !o->headless)
		return usage_error("%s needs --headless", "--skeleton");
	/* the skeleton is the start of a new drawing, as a parameter file is */
	if (o->skeleton && (o->load || o->generate || o->leaf || o->support))
		return usage_error("%s does not go with --skeleton",
				   o->load ? "--load" : o->generate ? "--generate" :
				   o->leaf ? "--leaf" : "--support");
	return 0;
}

/* One display: a window, the kiosk's DRM/KMS, or none (headless, which writes to --out). */
static int check_display(const struct options *o)
{
	if (o->window && o->kiosk)
		return usage_error("%s does not go with --kiosk", "--window");
	if (o->headless && (o->window || o->kiosk))
		return usage_error("%s is not --headless", o->window ? "--window" : "--kiosk");
	if (o->headless && (o->kiosk_frames || o->screenshot || o->config || o->stats))
		return usage_error("%s is for the kiosk, not --headless",
				   o->kiosk_frames ? "--kiosk-frames" : o->screenshot ? "--screenshot" :
				   o->config ? "--config" : "--stats");
	if (o->headless && (!o->out_dir || !o->out_dir[0]))
		return usage_error("%s needs --out DIR", "--headless");
	return 0;
}

static int check_leaf(const struct options *o)
{
	if (o->opening_given && !o->leaf)
		return usage_error("%s is for a --leaf", "--opening");
	/* a leaf alone: no drawing, so nothing to load, feed, turn, record or sway */
	if (o->leaf && (o->load || o->generate || o->nsteps || o->view_given || o->idle_given ||
			o->record || o->seed_given || o->lang || o->wind >= 0))
		return usage_error("%s does not go with --leaf (only --out, --opening and --size do)",
				   o->load ? "--load" : o->generate ? "--generate" :
				   o->nsteps ? "--replay/--press" : o->view_given ? "--view" :
				   o->idle_given ? "--idle" : o->record ? "--record" :
				   o->seed_given ? "--seed" : o->lang ? "--lang" : "--wind");
	return 0;
}

static int check_vine(const struct options *o)
{
	if ((o->vine || o->plant_given) && !o->support)
		return usage_error("%s is for a --support", o->vine ? "--vine" : "--plant");
	if (o->support && (!o->vine || !o->plant_given))
		return usage_error("%s needs --vine NAME|FILE and --plant X,Y,Z", "--support");
	/* a vine alone: no drawing, no leaf, no tree to sway */
	if (o->support && (o->leaf || o->opening_given || o->load || o->generate || o->nsteps ||
			   o->view_given || o->idle_given || o->record || o->seed_given ||
			   o->lang || o->wind >= 0))
		return usage_error("%s does not go with --support (only --out, --vine, --plant and "
				   "--size do)",
				   o->leaf ? "--leaf" : o->opening_given ? "--opening" :
				   o->load ? "--load" : o->generate ? "--generate" :
				   o->nsteps ? "--replay/--press" : o->view_given ? "--view" :
				   o->idle_given ? "--idle" : o->record ? "--record" :
				   o->seed_given ? "--seed" : o->lang ? "--lang" : "--wind");
	return 0;
}

/* Today's forest headless (--forest DIR): only its output, its moment and its look; the
 * kiosk's forest emptied (--forest-reset): only the configuration it finds it by. */
static int check_forest(const struct options *o)
{
	if (o->forest && !o->headless)
		return usage_error("%s needs --headless", "--forest");
	if (o->forest && (o->leaf || o->opening_given || o->support || o->load || o->generate ||
			  o->skeleton || o->nsteps || o->view_given || o->record || o->seed_given ||
			  o->wood || o->dump_voxels))
		return usage_error("%s does not go with --forest (only --out, --idle, --size, "
				   "--lang and --wind do)",
				   o->leaf ? "--leaf" : o->opening_given ? "--opening" :
				   o->support ? "--support" : o->load ? "--load" :
				   o->generate ? "--generate" : o->skeleton ? "--skeleton" :
				   o->nsteps ? "--replay/--press" : o->view_given ? "--view" :
				   o->record ? "--record" : o->seed_given ? "--seed" :
				   o->wood ? "--wood" : "--dump-voxels");
	return 0;
}

/* The options that do not go together, in this order: the first conflict found is the one
 * the message names. */
static int check_options(const struct options *o)
{
	static int (*const checks[])(const struct options *) = {
		check_forest, check_wood, check_headless_only, check_skeleton, check_display,
		check_leaf, check_vine,
	};

	for (size_t i = 0; i < sizeof(checks) / sizeof(checks[0]); i++) {
		int ret = checks[i](o);

		if (ret)
			return ret;
	}
	return 0;
}

static void options_init(struct options *o)
{
	memset(o, 0, sizeof(*o));
	o->width = DEFAULT_WIDTH;
	o->height = DEFAULT_HEIGHT;
	o->seed = DEFAULT_SEED;
	o->wind = -1.0;
}

int options_parse(struct options *o, int argc, char **argv)
{
	int c, ret;

	options_init(o);
	opterr = 0;
	optind = 1;
	while ((c = getopt_long(argc, argv, "", longopts, NULL)) != -1) {
		ret = parse_option(o, c, optarg);
		if (ret == OPTION_NOT_OURS)
			return usage_error("unknown or incomplete option \"%s\"", argv[optind - 1]);
		if (ret)
			return ret;
	}
	if (optind < argc)
		return usage_error("unexpected argument \"%s\"", argv[optind]);
	if (o->help || o->version)
		return 0;
	return check_options(o);
}

void options_finish(struct options *o)
{
	free(o->steps);
	o->steps = NULL;
	o->nsteps = 0;
}
