/* SPDX-License-Identifier: MIT */
/*
 * A virtual pen tablet through uinput (libevdev), driven by a script on stdin, for the
 * kiosk's VM tests. Root and /dev/uinput (modprobe uinput) needed. Positions are fractions
 * 0..1 of the tablet (216 x 135 mm, 100 units a mm); pressure 0..1. One command a line:
 *   in X Y [eraser]    the tool comes into proximity
 *   down P             tip down with pressure P
 *   move X Y [P]       one motion
 *   line X0 Y0 X1 Y1 N MS   N motions from (X0, Y0) to (X1, Y1), one every MS ms
 *   up                 tip up
 *   out                out of proximity
 *   button stylus|stylus2 0|1
 *   sleep MS
 *   unplug / plug      the device goes away / comes back (hotplug)
 *   sh COMMAND...      runs a shell command and waits for it (a GPIO button pressed
 *                      between strokes); a failing command ends the script
 * libinput forces a tool out of proximity after some 50 ms without events: keep moving.
 *   uinput_pen [--direct | --touch] < script
 * --direct: a screen tablet (INPUT_PROP_DIRECT). --touch: a touchscreen of the same size
 * (multitouch slot 0): down/up put a finger on and off, in/out/button do nothing.
 */
#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define W 21600
#define H 13500
#define PMAX 4095

static struct libevdev *dev;
static struct libevdev_uinput *ui;
static bool eraser, touch;
static int tracking_id;
/* UINPUT_PEN_WAIT_MS: how long a plugged device is given before events (udev under TCG is slow) */
static long plug_wait_ms = 3000;

static void die(const char *what, int err)
{
	fprintf(stderr, "uinput_pen: %s: %s\n", what, strerror(err));
	exit(1);
}

static void ev(unsigned type, unsigned code, int value)
{
	int r;

	if (!ui)
		return; /* unplugged: events go nowhere, as on a real bus */
	r = libevdev_uinput_write_event(ui, type, code, value);
	if (r < 0)
		die("write", -r);
}

static void syn(void)
{
	ev(EV_SYN, SYN_REPORT, 0);
}

static void sleep_ms(long ms)
{
	struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };

	while (nanosleep(&ts, &ts) < 0 && errno == EINTR)
		;
}

static double cur_x, cur_y;

static void pos(double x, double y)
{
	cur_x = x;
	cur_y = y;
	if (touch) {
		ev(EV_ABS, ABS_MT_SLOT, 0);
		ev(EV_ABS, ABS_MT_POSITION_X, (int)(x * W + 0.5));
		ev(EV_ABS, ABS_MT_POSITION_Y, (int)(y * H + 0.5));
	}
	ev(EV_ABS, ABS_X, (int)(x * W + 0.5));
	ev(EV_ABS, ABS_Y, (int)(y * H + 0.5));
}

static void touch_plug(void)
{
	struct input_absinfo ax = { .maximum = W, .resolution = 100 };
	struct input_absinfo ay = { .maximum = H, .resolution = 100 };
	struct input_absinfo slot = { .maximum = 9 };
	struct input_absinfo id = { .maximum = 65535 };

	if (libevdev_enable_event_code(dev, EV_KEY, BTN_TOUCH, NULL) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_X, &ax) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_Y, &ay) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_MT_SLOT, &slot) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_MT_TRACKING_ID, &id) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_MT_POSITION_X, &ax) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_MT_POSITION_Y, &ay) < 0 ||
	    libevdev_enable_property(dev, INPUT_PROP_DIRECT) < 0)
		die("enable touch", EINVAL);
}

static void plug(bool direct)
{
	struct input_absinfo ax = { .maximum = W, .resolution = 100 };
	struct input_absinfo ay = { .maximum = H, .resolution = 100 };
	struct input_absinfo ap = { .maximum = PMAX };
	struct input_absinfo at = { .minimum = -64, .maximum = 63, .resolution = 57 };
	static const unsigned keys[] = { BTN_TOOL_PEN, BTN_TOOL_RUBBER, BTN_TOUCH, BTN_STYLUS,
					 BTN_STYLUS2 };
	int r;

	dev = libevdev_new();
	if (!dev)
		die("libevdev_new", ENOMEM);
	libevdev_set_name(dev, touch ? "edaha virtual touchscreen" : "edaha virtual pen");
	libevdev_set_id_bustype(dev, BUS_USB);
	libevdev_set_id_vendor(dev, 0x1d50);
	libevdev_set_id_product(dev, 0x6189);
	if (libevdev_enable_event_type(dev, EV_KEY) < 0 || libevdev_enable_event_type(dev, EV_ABS) < 0)
		die("enable type", EINVAL);
	if (touch) {
		touch_plug();
		goto create;
	}
	for (size_t i = 0; i < sizeof(keys) / sizeof(keys[0]); i++)
		if (libevdev_enable_event_code(dev, EV_KEY, keys[i], NULL) < 0)
			die("enable key", EINVAL);
	if (libevdev_enable_event_code(dev, EV_ABS, ABS_X, &ax) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_Y, &ay) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_PRESSURE, &ap) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_TILT_X, &at) < 0 ||
	    libevdev_enable_event_code(dev, EV_ABS, ABS_TILT_Y, &at) < 0)
		die("enable abs", EINVAL);
	if (libevdev_enable_property(dev, direct ? INPUT_PROP_DIRECT : INPUT_PROP_POINTER) < 0)
		die("enable property", EINVAL);
create:
	r = libevdev_uinput_create_from_device(dev, LIBEVDEV_UINPUT_OPEN_MANAGED, &ui);
	if (r < 0)
		die("uinput (root? modprobe uinput?)", -r);
	fprintf(stderr, "uinput_pen: %s\n", libevdev_uinput_get_devnode(ui));
	sleep_ms(plug_wait_ms); /* udev (slow under TCG) and libinput pick the device up */
}

static void unplug(void)
{
	if (ui)
		libevdev_uinput_destroy(ui);
	if (dev)
		libevdev_free(dev);
	ui = NULL;
	dev = NULL;
}

int main(int argc, char **argv)
{
	bool direct = argc > 1 && strcmp(argv[1], "--direct") == 0;

	touch = argc > 1 && strcmp(argv[1], "--touch") == 0;
	char line[512];
	unsigned long n = 0;

	if (getenv("UINPUT_PEN_WAIT_MS"))
		plug_wait_ms = atol(getenv("UINPUT_PEN_WAIT_MS"));
	plug(direct);
	while (fgets(line, sizeof(line), stdin)) {
		double x, y, x1, y1, p = 0.5;
		char word[32] = "", arg[32] = "";
		int count, k;
		long ms;

		n++;
		if (sscanf(line, "%31s", word) != 1 || word[0] == '#')
			continue;
		if (touch && (strcmp(word, "in") == 0 || strcmp(word, "out") == 0 ||
			      strcmp(word, "button") == 0)) {
			if (strcmp(word, "in") == 0 && sscanf(line, "%*s %lf %lf", &x, &y) == 2) {
				cur_x = x; /* where the finger will land */
				cur_y = y;
			}
		} else if (touch && strcmp(word, "down") == 0) {
			ev(EV_ABS, ABS_MT_SLOT, 0);
			ev(EV_ABS, ABS_MT_TRACKING_ID, tracking_id++);
			pos(cur_x, cur_y);
			ev(EV_KEY, BTN_TOUCH, 1);
			syn();
		} else if (touch && strcmp(word, "up") == 0) {
			ev(EV_ABS, ABS_MT_SLOT, 0);
			ev(EV_ABS, ABS_MT_TRACKING_ID, -1);
			ev(EV_KEY, BTN_TOUCH, 0);
			syn();
		} else if (strcmp(word, "in") == 0 && sscanf(line, "%*s %lf %lf %31s", &x, &y, arg) >= 2) {
			eraser = strcmp(arg, "eraser") == 0;
			pos(x, y);
			ev(EV_KEY, eraser ? BTN_TOOL_RUBBER : BTN_TOOL_PEN, 1);
			syn();
		} else if (strcmp(word, "down") == 0 && sscanf(line, "%*s %lf", &p) == 1) {
			ev(EV_ABS, ABS_PRESSURE, (int)(p * PMAX));
			ev(EV_KEY, BTN_TOUCH, 1);
			syn();
		} else if (strcmp(word, "move") == 0 &&
			   (k = sscanf(line, "%*s %lf %lf %lf", &x, &y, &p)) >= 2) {
			pos(x, y);
			if (k == 3)
				ev(EV_ABS, ABS_PRESSURE, (int)(p * PMAX));
			syn();
		} else if (strcmp(word, "line") == 0 &&
			   sscanf(line, "%*s %lf %lf %lf %lf %d %ld", &x, &y, &x1, &y1, &count, &ms) == 6 &&
			   count > 0) {
			for (k = 0; k <= count; k++) {
				pos(x + (x1 - x) * k / count, y + (y1 - y) * k / count);
				syn();
				sleep_ms(ms);
			}
		} else if (strcmp(word, "up") == 0) {
			ev(EV_ABS, ABS_PRESSURE, 0);
			ev(EV_KEY, BTN_TOUCH, 0);
			syn();
		} else if (strcmp(word, "out") == 0) {
			ev(EV_KEY, eraser ? BTN_TOOL_RUBBER : BTN_TOOL_PEN, 0);
			syn();
		} else if (strcmp(word, "button") == 0 && sscanf(line, "%*s %31s %d", arg, &k) == 2) {
			ev(EV_KEY, strcmp(arg, "stylus2") == 0 ? BTN_STYLUS2 : BTN_STYLUS, k != 0);
			syn();
		} else if (strcmp(word, "sleep") == 0 && sscanf(line, "%*s %ld", &ms) == 1) {
			sleep_ms(ms);
		} else if (strcmp(word, "sh") == 0) {
			int status = system(line + strspn(line, " \t") + 2);

			if (status != 0) {
				fprintf(stderr, "uinput_pen: stdin:%lu: %s failed (%d)\n", n, line, status);
				unplug();
				return 1;
			}
		} else if (strcmp(word, "unplug") == 0) {
			unplug();
		} else if (strcmp(word, "plug") == 0) {
			if (!ui)
				plug(direct);
		} else {
			fprintf(stderr, "uinput_pen: stdin:%lu: cannot read \"%s\"\n", n, word);
			unplug();
			return 2;
		}
	}
	sleep_ms(200);
	unplug();
	return 0;
}
