/* SPDX-License-Identifier: MIT */
/*
 * config_parse / config_load: defaults, a file with every key, unknown keys as warnings
 * with their lines, and every malformed file in tests/malformed/config failing at the
 * line its EXPECT file names.
 *   test_config DATA_DIR MALFORMED_DIR
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config_file.h"
#include "fileio.h"
#include "forest.h"
#include "live.h"
#include "test.h"

static char *path_of(const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	char *p = malloc(n);

	CHECK(p);
	snprintf(p, n, "%s/%s", dir, name);
	return p;
}

static void check_defaults(const struct config *c)
{
	CHECK(c->display.card[0] == '\0');
	CHECK(c->display.connector[0] == '\0');
	CHECK_INT(c->display.mode_w, 0);
	CHECK_INT(c->display.rotation, 0);
	CHECK_INT(c->input.rotation, 0);
	CHECK_INT(c->input.area, CONFIG_AREA_FIT);
	CHECK_INT(c->gpio.debounce_ms, CONFIG_DEBOUNCE_MS_DEFAULT);
	CHECK_INT(c->language, CONFIG_LANG_EN);
	CHECK_INT(c->kiosk.attract_after_s, CONFIG_ATTRACT_S_DEFAULT);
	CHECK(strcmp(c->kiosk.export_dir, CONFIG_EXPORT_DIR_DEFAULT) == 0);
	CHECK(c->kiosk.wind == LIVE_WIND_DEFAULT_STRENGTH);
	CHECK(c->kiosk.grow_in);
	CHECK_INT(c->kiosk.max_fps, CONFIG_MAX_FPS_DEFAULT);
	CHECK(c->forest.enabled);
	CHECK_INT(c->forest.max_trees, FOREST_MAX_TREES_DEFAULT);
	CHECK_INT(c->forest.reset_hour, 4);
	CHECK_INT(c->forest.reset_minute, 0);
	CHECK(c->usb.enabled);
	CHECK(strcmp(c->usb.helper_socket, CONFIG_USB_SOCKET_DEFAULT) == 0);
	CHECK(c->font[0] == '\0');
	for (int b = 0; b < BUTTON_COUNT; b++) {
		CHECK(!c->gpio.buttons[b].set);
		CHECK(!c->gpio.leds[b].set);
	}
}

static void test_defaults(void)
{
	static const char *const empty[] = { "", "\n", "# nothing\n", "---\n", "~\n", "{}\n",
					     "display:\ninput:\ngpio:\n" };
	struct config c;
	struct error err;

	for (size_t i = 0; i < sizeof(empty) / sizeof(empty[0]); i++) {
		memset(&c, 0x5a, sizeof(c));
		CHECK_INT(config_parse(empty[i], strlen(empty[i]), "t", &c, NULL, &err), 0);
		check_defaults(&c);
	}
	memset(&c, 0x5a, sizeof(c));
	CHECK_INT(config_load("/nonexistent/edaha/edaha.conf", &c, NULL, &err), 0);
	check_defaults(&c);
	/* a directory is not a missing file */
	CHECK(config_load("/", &c, NULL, &err) < 0);
	check_defaults(&c);
}

static void test_good(const char *dir)
{
	char *path = path_of(dir, "edaha.conf");
	const struct config_gpio_line *l;
	struct config c;
	struct error err;
	char *out = NULL;
	size_t outlen = 0;
	FILE *warn = open_memstream(&out, &outlen);

	CHECK(warn);
	if (config_load(path, &c, warn, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
	CHECK_INT(fclose(warn), 0);
	CHECK_INT(outlen, 0); /* no warnings */
	free(out);
	CHECK(strcmp(c.display.card, "/dev/dri/card1") == 0);
	CHECK(strcmp(c.display.connector, "HDMI-A-1") == 0);
	CHECK_INT(c.display.mode_w, 1920);
	CHECK_INT(c.display.mode_h, 1080);
	CHECK_INT(c.display.mode_hz, 60);
	CHECK_INT(c.display.rotation, 90);
	CHECK_INT(c.input.rotation, 180);
	CHECK_INT(c.input.area, CONFIG_AREA_RECT);
	CHECK_NEAR(c.input.area_rect[0], 0.1, 1e-12);
	CHECK_NEAR(c.input.area_rect[1], 0.2, 1e-12);
	CHECK_NEAR(c.input.area_rect[2], 0.9, 1e-12);
	CHECK_NEAR(c.input.area_rect[3], 0.8, 1e-12);
	CHECK_INT(c.gpio.debounce_ms, 30);
	CHECK_INT(c.language, CONFIG_LANG_JA);
	CHECK_INT(c.kiosk.attract_after_s, 300);
	CHECK(strcmp(c.kiosk.export_dir, "/srv/edaha/exports") == 0);
	CHECK(!c.usb.enabled);
	CHECK(strcmp(c.usb.helper_socket, "/run/edaha-test/usb.sock") == 0);
	CHECK(strcmp(c.font, "/usr/share/fonts/truetype/vlgothic/VL-PGothic-Regular.ttf") == 0);

	l = &c.gpio.buttons[BUTTON_3D];
	CHECK(l->set && strcmp(l->chip, "pinctrl-bcm2711") == 0 && strcmp(l->name, "GPIO17") == 0);
	CHECK_INT(l->offset, -1);
	CHECK(l->active_low && l->pull_up);
	CHECK_INT(l->conf_line, 13);
	l = &c.gpio.buttons[BUTTON_CLONE];
	CHECK(l->set && l->name[0] == '\0');
	CHECK_INT(l->offset, 27);
	l = &c.gpio.buttons[BUTTON_LEAF]; /* quoted digits: a line name */
	CHECK(l->set && strcmp(l->name, "22") == 0 && l->offset == -1);
	CHECK(!l->active_low && !l->pull_up);
	l = &c.gpio.buttons[BUTTON_PROPAGATE];
	CHECK(l->set && strcmp(l->chip, "kiosk-buttons") == 0 &&
	      strcmp(l->name, "btn-propagate") == 0);
	l = &c.gpio.buttons[BUTTON_VINE]; /* the vine mode (issue 16), a button like the others */
	CHECK(l->set && strcmp(l->chip, "kiosk-buttons") == 0 && strcmp(l->name, "btn-vine") == 0);
	l = &c.gpio.buttons[BUTTON_EXPORT];
	CHECK(l->set && l->offset == 3 && !l->active_low);
	CHECK(!c.gpio.buttons[BUTTON_UNDO].set);
	CHECK(!c.gpio.buttons[BUTTON_NEW].set);
	l = &c.gpio.leds[BUTTON_3D];
	CHECK(l->set && strcmp(l->name, "GPIO5") == 0);
	l = &c.gpio.leds[BUTTON_LEAF];
	CHECK(l->set && l->offset == 6 && l->active_low);
	l = &c.gpio.leds[BUTTON_VINE]; /* a mode, so it has an LED */
	CHECK(l->set && strcmp(l->name, "led-vine") == 0 && !l->active_low);
	CHECK(config_button_is_mode(BUTTON_VINE));
	CHECK(!config_button_is_mode(BUTTON_SEASON));
	CHECK(!config_button_is_mode(BUTTON_GROW)); /* an action: no state for an LED to show */
	CHECK(!c.gpio.leds[BUTTON_CLONE].set);
	free(path);

	/* the other spellings */
	static const char more[] = "display:\n  card: auto\n  connector: auto\n"
				   "  mode: preferred\ninput:\n  area: stretch\n";
	CHECK_INT(config_parse(more, strlen(more), "more", &c, NULL, &err), 0);
	CHECK(c.display.card[0] == '\0' && c.display.connector[0] == '\0');
	CHECK_INT(c.display.mode_w, 0);
	CHECK_INT(c.input.area, CONFIG_AREA_STRETCH);
	static const char font_auto[] = "font: auto\n";
	CHECK_INT(config_parse(font_auto, strlen(font_auto), "font", &c, NULL, &err), 0);
	CHECK(c.font[0] == '\0');
	/* no local copy, the stick alone */
	static const char no_copy[] = "kiosk:\n  export_dir: none\n";
	CHECK_INT(config_parse(no_copy, strlen(no_copy), "none", &c, NULL, &err), 0);
	CHECK(c.kiosk.export_dir[0] == '\0' && c.usb.enabled);
	/* grow (issue 17): a button like the others, with no LED */
	static const char grow[] = "gpio:\n  buttons:\n    grow: { chip: pinctrl-bcm2711, "
				   "line: GPIO20, active_low: true, pull_up: true }\n";
	CHECK_INT(config_parse(grow, strlen(grow), "grow", &c, NULL, &err), 0);
	l = &c.gpio.buttons[BUTTON_GROW];
	CHECK(l->set && strcmp(l->name, "GPIO20") == 0 && l->active_low && l->pull_up);
	CHECK_INT(l->conf_line, 3);
	static const char grow_led[] = "gpio:\n  leds:\n    grow: { chip: a, line: 1 }\n";
	CHECK_INT(config_parse(grow_led, strlen(grow_led), "grow-led", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "grow-led:3:") && strstr(err.msg, "not grow"));
	/* the wind (issue 26): 0..1, 0 still */
	static const char wind[] = "kiosk:\n  wind: 0.8\n";
	CHECK_INT(config_parse(wind, strlen(wind), "wind", &c, NULL, &err), 0);
	CHECK(c.kiosk.wind == 0.8);
	static const char still[] = "kiosk:\n  wind: 0\n";
	CHECK_INT(config_parse(still, strlen(still), "still", &c, NULL, &err), 0);
	CHECK(c.kiosk.wind == 0.0);
	static const char gale[] = "kiosk:\n  wind: 1.5\n";
	CHECK_INT(config_parse(gale, strlen(gale), "gale", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "gale:2:") && strstr(err.msg, "kiosk.wind 1.5 out of range 0..1"));
	static const char word[] = "kiosk:\n  wind: strong\n";
	CHECK_INT(config_parse(word, strlen(word), "word", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "word:2:") && strstr(err.msg, "is not a number"));
	/* growing in and the frame cap (issue 26) */
	static const char live[] = "kiosk:\n  grow_in: false\n  max_fps: 60\n";
	CHECK_INT(config_parse(live, strlen(live), "live", &c, NULL, &err), 0);
	CHECK(!c.kiosk.grow_in);
	CHECK_INT(c.kiosk.max_fps, 60);
	static const char fast[] = "kiosk:\n  max_fps: 1000\n";
	CHECK_INT(config_parse(fast, strlen(fast), "fast", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "fast:2:") && strstr(err.msg, "kiosk.max_fps"));
	static const char maybe[] = "kiosk:\n  grow_in: maybe\n";
	CHECK_INT(config_parse(maybe, strlen(maybe), "maybe", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "maybe:2:") && strstr(err.msg, "kiosk.grow_in"));
	/* today's forest (issue 27) */
	static const char forest[] = "forest:\n  enabled: false\n  max_trees: 12\n  reset_at: \"23:30\"\n";
	CHECK_INT(config_parse(forest, strlen(forest), "forest", &c, NULL, &err), 0);
	CHECK(!c.forest.enabled);
	CHECK_INT(c.forest.max_trees, 12);
	CHECK_INT(c.forest.reset_hour, 23);
	CHECK_INT(c.forest.reset_minute, 30);
	static const char plain[] = "forest:\n  reset_at: 06:05\n";
	CHECK_INT(config_parse(plain, strlen(plain), "plain", &c, NULL, &err), 0);
	CHECK_INT(c.forest.reset_hour, 6);
	CHECK_INT(c.forest.reset_minute, 5);
	static const char *const bad_times[] = { "24:00", "4:00", "04:60", "04:00:00", "noon", "-1:00" };
	for (size_t i = 0; i < sizeof(bad_times) / sizeof(*bad_times); i++) {
		char text[64];

		snprintf(text, sizeof(text), "forest:\n  reset_at: \"%s\"\n", bad_times[i]);
		CHECK_INT(config_parse(text, strlen(text), "when", &c, NULL, &err), -EINVAL);
		CHECK(strstr(err.msg, "when:2:") && strstr(err.msg, "forest.reset_at"));
	}
	static const char many[] = "forest:\n  max_trees: 1000\n";
	CHECK_INT(config_parse(many, strlen(many), "many", &c, NULL, &err), -EINVAL);
	CHECK(strstr(err.msg, "many:2:") && strstr(err.msg, "forest.max_trees"));
	static const char mode[] = "display:\n  mode: 800x480\n";
	CHECK_INT(config_parse(mode, strlen(mode), "mode", &c, NULL, &err), 0);
	CHECK_INT(c.display.mode_w, 800);
	CHECK_INT(c.display.mode_h, 480);
	CHECK_INT(c.display.mode_hz, 0);
}

static void test_unknown_keys(const char *dir)
{
	char *path = path_of(dir, "unknown-keys.conf");
	struct config c;
	struct error err;
	char *out = NULL;
	size_t outlen = 0;
	FILE *warn = open_memstream(&out, &outlen);
	static const char *const expect[] = { ":2: warning: unknown key \"brightness\" in display",
					      ":5: warning: unknown key \"hand\" in input",
					      ":6: warning: unknown key \"colour\" in the top level",
					      ":9: warning: unknown key \"blink\" in gpio.buttons.new" };

	CHECK(warn);
	CHECK_INT(config_load(path, &c, warn, &err), 0);
	CHECK_INT(fclose(warn), 0);
	CHECK_INT(c.input.rotation, 270);
	CHECK(c.gpio.buttons[BUTTON_NEW].set);
	for (size_t i = 0; i < sizeof(expect) / sizeof(expect[0]); i++) {
		if (!strstr(out, expect[i])) {
			fprintf(stderr, "missing warning %s in:\n%s", expect[i], out);
			CHECK(0);
		}
	}
	CHECK(strncmp(out, path, strlen(path)) == 0);
	free(out);
	free(path);
}

static void test_malformed(const char *dir)
{
	char *expect = path_of(dir, "EXPECT");
	char *data;
	size_t len;
	struct error err;
	int count = 0;

	CHECK_INT(fileio_read_all(expect, 1 << 20, &data, &len, &err), 0);
	for (char *line = strtok(data, "\n"); line; line = strtok(NULL, "\n")) {
		char name[128], want[160], *path;
		unsigned long at;
		struct config c;

		if (line[0] == '#')
			continue;
		CHECK(sscanf(line, "%127s %lu", name, &at) == 2);
		path = path_of(dir, name);
		memset(&c, 0x5a, sizeof(c));
		if (config_load(path, &c, NULL, &err) != -EINVAL) {
			fprintf(stderr, "%s: not refused with -EINVAL\n", path);
			CHECK(0);
		}
		check_defaults(&c); /* nothing half-parsed */
		snprintf(want, sizeof(want), "%s:%lu: ", path, at);
		if (strncmp(err.msg, want, strlen(want)) != 0) {
			fprintf(stderr, "%s: expected \"%s...\", got \"%s\"\n", name, want, err.msg);
			CHECK(0);
		}
		printf("%s\n", err.msg);
		free(path);
		count++;
	}
	CHECK(count >= 20);
	free(data);
	free(expect);

	/* too large */
	size_t big = CONFIG_MAX_BYTES + 1;
	char *huge = malloc(big);
	struct config c;

	CHECK(huge);
	memset(huge, '#', big);
	CHECK_INT(config_parse(huge, big, "huge", &c, NULL, &err), -EINVAL);
	CHECK(strncmp(err.msg, "huge: ", 6) == 0);
	free(huge);
}

int main(int argc, char **argv)
{
	CHECK(argc == 3);
	test_defaults();
	test_good(argv[1]);
	test_unknown_keys(argv[1]);
	test_malformed(argv[2]);
	return 0;
}
