/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "event.h"

/* One input step of a headless run, applied in command-line order. */
enum step_kind {
	STEP_REPLAY,
	STEP_PRESS,
};

struct step {
	enum step_kind kind;
	const char *path;    /* STEP_REPLAY */
	enum button button;  /* STEP_PRESS */
};

struct options {
	bool headless, help, version;
	int width, height;
	uint64_t seed;
	bool seed_given;
	const char *out_dir;
	const char *load;
	const char *generate; /* a tree parameter file (docs/tree-params.md) */
	const char *skeleton; /* headless: start from a skeleton.json's branches */
	const char *record;
	bool view_given;
	double view_yaw, view_pitch; /* degrees */
	struct step *steps;
	size_t nsteps;
	/* kiosk test runs: stop after this many frames (0: run until a signal)... */
	unsigned long kiosk_frames;
	const char *screenshot; /* ...and write the last one here */
	const char *config;     /* kiosk: the configuration file (default CONFIG_PATH) */
	bool stats;             /* kiosk: print the responsiveness figures on exit */
	/* --window, --kiosk: the display forced (else a window under a desktop session) */
	bool window, kiosk;
	const char *lang;       /* "en", "ja", or NULL: the configuration's (kiosk), en */
	bool idle_given;        /* headless: render this long after the last input */
	double idle_s;
	const char *leaf;       /* headless: an origami leaf alone, a preset's name or a file */
	bool opening_given;     /* ...opened this far, 0..1 (else the design's rest) */
	double opening;
	const char *wood;       /* headless: the grow button's settings file (docs/wood-format.md) */
	bool dump_voxels;       /* headless: voxels.json and voxels.bin of the grown wood */
	const char *support;    /* headless: a vine on this OBJ support alone... */
	const char *vine;       /* ...a vine preset's name or a vine file... */
	bool plant_given;       /* ...planted here, metres */
	double plant[3];
	/* --wind S: the wind's strength, 0 (still) to 1; -1: not given (headless: a still
	 * screen; the kiosk: kiosk.wind). model.glb carries LIVE_WIND_DEFAULT_STRENGTH where
	 * it is 0 or not given (docs/living-trees.md). */
	double wind;
	/* --forest DIR: headless, today's forest of the drawings in DIR (docs/forest.md) */
	const char *forest;
	/* --forest-reset: the kiosk's forest starts a new day now, then edaha exits */
	bool forest_reset;
};

/* Parses argv. Returns 0, or 2 (usage error, message printed) as an exit status. */
int options_parse(struct options *o, int argc, char **argv);
void options_finish(struct options *o);
void options_usage(FILE *f);
