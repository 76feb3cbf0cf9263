/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

/*
 * The one input event type. Tablet (libinput), GPIO buttons, on-screen buttons and
 * replayed traces all become these; the app's state machine sees nothing else.
 */
enum event_type {
	EVENT_PROXIMITY_IN = 1,
	EVENT_PROXIMITY_OUT,
	EVENT_TIP_DOWN,
	EVENT_TIP_UP,
	EVENT_MOTION,
	EVENT_PEN_BUTTON, /* a button on the pen barrel */
	EVENT_BUTTON,     /* a mode/action button: GPIO, on-screen or --press */
};

enum event_tool {
	EVENT_TOOL_PEN = 0,
	EVENT_TOOL_ERASER,
};

enum event_pen_button {
	EVENT_PEN_BUTTON_STYLUS = 0,
	EVENT_PEN_BUTTON_STYLUS2,
};

/* Names (button_name) are a contract: traces, --press and the kiosk config use them. */
enum button {
	BUTTON_3D = 0,
	BUTTON_CLONE,
	BUTTON_LEAF,
	BUTTON_PROPAGATE,
	BUTTON_UNDO,
	BUTTON_REDO,
	BUTTON_EXPORT,
	BUTTON_NEW,
	BUTTON_FIXED_COUNT, /* propagation pattern: same number of children */
	BUTTON_FIXED_SIZE,  /* propagation pattern: same size and spacing */
	BUTTON_VIEW,        /* a turned 3D tree back to the front view */
	/* Functional trees (seed 001): the season, the New strip's templates and the
	 * parameter buttons of a generated tree (docs/functional-trees.md). */
	BUTTON_SEASON,
	BUTTON_TPL_BLANK,
	BUTTON_TPL_CHERRY,
	BUTTON_TPL_ZELKOVA,
	BUTTON_TPL_HEDGE,
	BUTTON_TPL_BALL,
	BUTTON_TPL_CONE,
	BUTTON_TPL_PALM,
	BUTTON_GEN_MORE,
	BUTTON_GEN_FEWER,
	BUTTON_GEN_WIDER,
	BUTTON_GEN_NARROWER,
	BUTTON_GEN_TALLER,
	BUTTON_GEN_SHORTER,
	BUTTON_GEN_LEAFIER,
	BUTTON_GEN_BARER,
	/* The leaf mode's leaves (issue 15): the visitor's own drawn leaf, or an origami
	 * preset (ori_kinds.h), in that order */
	BUTTON_LEAF_DRAWN,
	BUTTON_LEAF_ENTIRE,
	BUTTON_LEAF_HOP,
	BUTTON_LEAF_MAPLE,
	/* Twining vines (issue 16, seed 004): the vine mode, where a tap at the tree's foot
	 * plants a vine (docs/vines.md) */
	BUTTON_VINE,
	/* Growing wood (issue 17, seed 002): a year of thickening a press (docs/wood.md) */
	BUTTON_GROW,
	BUTTON_COUNT
};

struct event {
	enum event_type type;
	uint64_t time_us; /* monotonic clock, microseconds */
	/* Pen state, valid for proximity, tip, motion and pen-button events. */
	enum event_tool tool;
	double x, y;           /* screen pixels, origin top left */
	double pressure;       /* 0..1 */
	double tilt_x, tilt_y; /* degrees from the vertical */
	/* EVENT_PEN_BUTTON: enum event_pen_button; EVENT_BUTTON: enum button. */
	int button;
	bool pressed;
};

const char *event_type_name(enum event_type type);
bool event_type_from_name(const char *name, enum event_type *type);
const char *event_tool_name(enum event_tool tool);
bool event_tool_from_name(const char *name, enum event_tool *tool);
const char *event_pen_button_name(enum event_pen_button button);
bool event_pen_button_from_name(const char *name, enum event_pen_button *button);
const char *button_name(enum button button);
bool button_from_name(const char *name, enum button *button);
