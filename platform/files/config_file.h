/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The kiosk's configuration, /etc/edaha/edaha.conf (YAML, docs/config.md): the display,
 * how the tablet maps onto it, the GPIO buttons and LEDs, the language and the font of
 * the labels, where exports go (USB sticks, a local copy). A missing file means the defaults; every error names "file:line"; unknown
 * keys are warnings.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "event.h"

#define CONFIG_PATH "/etc/edaha/edaha.conf"
/* Larger files are refused: a configuration is a page of text. */
#define CONFIG_MAX_BYTES (64 * 1024)
#define CONFIG_NAME_MAX 64
#define CONFIG_DEBOUNCE_MS_DEFAULT 20
#define CONFIG_DEBOUNCE_MS_MAX 1000
#define CONFIG_ATTRACT_S_DEFAULT 90
#define CONFIG_ATTRACT_S_MAX 86400
/* Where every export also keeps a copy (a teacher collects them); "none": nowhere. */
#define CONFIG_EXPORT_DIR_DEFAULT "/var/lib/edaha/export"
/* edaha-usb-helper's socket (systemd/edaha-usb.socket). */
#define CONFIG_USB_SOCKET_DEFAULT "/run/edaha/usb.sock"
#define CONFIG_USB_SOCKET_MAX 108 /* sun_path, with the NUL */
/* The autosave journal and the archive of drawings (autosave.h); the service's
 * StateDirectory=. */
#define CONFIG_STATE_DIR_DEFAULT "/var/lib/edaha"
#define CONFIG_RESET_S_DEFAULT 600
#define CONFIG_RESET_S_MAX (7 * 86400)
#define CONFIG_ARCHIVE_KEEP_DEFAULT 10000
#define CONFIG_ARCHIVE_KEEP_MAX 1000000
#define CONFIG_MAX_FPS_DEFAULT 30
#define CONFIG_MAX_FPS_MAX 240

enum config_language { CONFIG_LANG_EN = 0, CONFIG_LANG_JA };

enum config_area {
	CONFIG_AREA_FIT = 0, /* the largest part of the tablet with the display's aspect */
	CONFIG_AREA_STRETCH, /* the whole tablet onto the whole display */
	CONFIG_AREA_RECT,    /* input.area_rect of the (rotated) tablet onto the display */
};

/* One GPIO line, found by chip label (or name, "gpiochip0") and line name or offset. */
struct config_gpio_line {
	bool set;
	char chip[CONFIG_NAME_MAX];
	char name[CONFIG_NAME_MAX]; /* line name, "" when offset is used */
	int offset;                 /* -1 when name is used */
	bool active_low;
	bool pull_up; /* inputs only */
	unsigned long conf_line; /* where it was configured, for messages */
};

struct config {
	struct {
		char card[256];                 /* "" = the first card that can modeset */
		char connector[CONFIG_NAME_MAX]; /* "" = the first connected one */
		int mode_w, mode_h, mode_hz;    /* 0 = the preferred mode; hz 0 = any */
		int rotation;                   /* 0, 90, 180, 270 degrees clockwise */
	} display;
	struct {
		int rotation; /* the tablet turned clockwise on the desk: 0, 90, 180, 270 */
		enum config_area area;
		double area_rect[4]; /* left, top, right, bottom in 0..1 (CONFIG_AREA_RECT) */
	} input;
	struct {
		int debounce_ms;
		struct config_gpio_line buttons[BUTTON_COUNT];
		struct config_gpio_line leds[BUTTON_COUNT]; /* mode buttons only */
	} gpio;
	enum config_language language;
	struct {
		int attract_after_s; /* idle seconds before the attract screen; 0: never */
		char export_dir[256]; /* absolute: where export keeps a copy; "": none */
		char state_dir[256];  /* absolute: the autosave journal and the archive */
		bool autosave;        /* false: a drawing lives only as long as the process */
		int reset_after_s;    /* idle seconds before the drawing is archived and the
				       * canvas cleared; 0: never */
		int archive_keep;     /* archived drawings kept; 0: all */
		double wind;          /* the wind's strength, 0 (still) to 1; default
				       * LIVE_WIND_DEFAULT_STRENGTH, a breeze. Exports sway at
				       * it, or at the breeze where it is 0 */
		bool grow_in;         /* a tree grows in when it becomes 3D */
		int max_fps;          /* frames a second at most while the tree moves */
	} kiosk;
	struct {
		bool enabled;    /* today's forest on the attract screen (docs/forest.md) */
		int max_trees;   /* standing at once, the newest */
		int reset_hour, reset_minute; /* local time the day's forest starts empty */
	} forest;
	struct {
		bool enabled; /* save to USB sticks */
		char helper_socket[CONFIG_USB_SOCKET_MAX]; /* absolute */
	} usb;
	char font[256]; /* the labels' font file; "" = the first of font_file_defaults */
};

void config_defaults(struct config *c);

/*
 * Parses a configuration (name is used in messages). Fills *c (defaults first) and
 * returns 0, or -EINVAL / -ENOMEM with "name:line: ..." in err. Warnings (unknown keys)
 * go to warn as "name:line: warning: ..." lines; warn may be NULL.
 */
int config_parse(const char *data, size_t len, const char *name, struct config *c, FILE *warn,
		 struct error *err);

/* Reads and parses path: a missing file gives the defaults and 0; -errno otherwise. */
int config_load(const char *path, struct config *c, FILE *warn, struct error *err);

/* The buttons that are modes (and may have an LED): 3d, clone, leaf, propagate, vine. */
bool config_button_is_mode(enum button b);
