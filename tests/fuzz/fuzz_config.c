/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the kiosk configuration parser on arbitrary bytes. A failure must name the
 * file ("fuzz:...") and leave the defaults; whatever is accepted must be in range.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "config_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_name(const char *s, size_t size)
{
	if (!memchr(s, '\0', size))
		abort();
}

static void check_line(const struct config_gpio_line *l)
{
	if (!l->set)
		return;
	check_name(l->chip, sizeof(l->chip));
	check_name(l->name, sizeof(l->name));
	if (!l->chip[0] || (l->offset < 0) == (l->name[0] == '\0') || l->offset > 65535)
		abort(); /* a chip, and either a name or an offset */
}

static bool quarter(int r)
{
	return r == 0 || r == 90 || r == 180 || r == 270;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct config c, defaults;
	struct error err;

	config_defaults(&defaults);
	if (config_parse((const char *)data, size, "fuzz", &c, NULL, &err) < 0) {
		if (strncmp(err.msg, "fuzz:", 5) != 0 || memcmp(&c, &defaults, sizeof(c)) != 0)
			abort();
		return 0;
	}
	check_name(c.display.card, sizeof(c.display.card));
	check_name(c.display.connector, sizeof(c.display.connector));
	check_name(c.font, sizeof(c.font));
	if (!quarter(c.display.rotation) || !quarter(c.input.rotation))
		abort();
	if (c.display.mode_w < 0 || c.display.mode_w > 16384 || c.display.mode_h < 0 ||
	    c.display.mode_h > 16384 || (c.display.mode_w == 0) != (c.display.mode_h == 0))
		abort();
	if (c.input.area == CONFIG_AREA_RECT) {
		const double *r = c.input.area_rect;

		for (int i = 0; i < 4; i++)
			if (!(r[i] >= 0.0 && r[i] <= 1.0))
				abort();
		if (!(r[2] > r[0] && r[3] > r[1]))
			abort();
	}
	if (c.gpio.debounce_ms < 0 || c.gpio.debounce_ms > CONFIG_DEBOUNCE_MS_MAX)
		abort();
	for (int b = 0; b < BUTTON_COUNT; b++) {
		check_line(&c.gpio.buttons[b]);
		check_line(&c.gpio.leds[b]);
		if (c.gpio.leds[b].set && !config_button_is_mode((enum button)b))
			abort();
	}
	if (c.language != CONFIG_LANG_EN && c.language != CONFIG_LANG_JA)
		abort();
	if (c.kiosk.attract_after_s < 0 || c.kiosk.attract_after_s > CONFIG_ATTRACT_S_MAX)
		abort();
	/* absolute, or "" for none */
	check_name(c.kiosk.export_dir, sizeof(c.kiosk.export_dir));
	if (c.kiosk.export_dir[0] && c.kiosk.export_dir[0] != '/')
		abort();
	check_name(c.usb.helper_socket, sizeof(c.usb.helper_socket));
	if (c.usb.helper_socket[0] != '/')
		abort();
	return 0;
}
