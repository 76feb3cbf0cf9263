/* SPDX-License-Identifier: MIT */
/*
 * `libinput record` import: exact events from real-layout recordings (positions from each
 * file's absinfo on a 1280x800 screen), frame semantics, and errors with lines.
 * argv[1]: tests/data
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "test.h"
#include "trace.h"

#define SCREEN_W 1280
#define SCREEN_H 800
#define PI 3.14159265358979323846

static const char *data_dir = "tests/data";

struct axis {
	double min, max, res;
};

/* Expected events in device units, as they appear in the recording. */
struct expect {
	const char *type;
	uint64_t time_us;
	int tool;
	double x, y, pressure, tilt_x, tilt_y;
	int button, pressed;
};

struct device_axes {
	struct axis x, y, pressure, tilt_x, tilt_y;
	bool has_pressure, has_tilt;
};

static double px(const struct axis *a, double v, int screen)
{
	return (v - a->min) * screen / (a->max - a->min + 1);
}

static double tilt(const struct axis *a, double v)
{
	if (a->res != 0 && a->max > 0 && a->min < 0)
		return v / a->res * 180.0 / PI;
	return ((v - a->min) / (a->max - a->min) * 2 - 1) * 64.0;
}

static void load(const char *file, struct trace *t)
{
	char path[1024];
	struct error err;

	snprintf(path, sizeof(path), "%s/%s", data_dir, file);
	if (trace_load(path, SCREEN_W, SCREEN_H, t, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
}

static void check_events(const char *what, const struct trace *t, const struct expect *ex,
			 size_t n, const struct device_axes *d)
{
	if (t->nevents != n)
		fprintf(stderr, "%s: %zu events, expected %zu\n", what, t->nevents, n);
	CHECK_INT(t->nevents, n);
	for (size_t i = 0; i < n; i++) {
		const struct event *e = &t->events[i];
		const struct expect *x = &ex[i];
		enum event_type type;

		CHECK(event_type_from_name(x->type, &type));
		if (e->type != type || e->time_us != x->time_us)
			fprintf(stderr, "%s: event %zu is %s at %llu, expected %s at %llu\n", what, i,
				event_type_name(e->type), (unsigned long long)e->time_us, x->type,
				(unsigned long long)x->time_us);
		CHECK(e->type == type);
		CHECK(e->time_us == x->time_us);
		CHECK_INT(e->tool, x->tool);
		/* Same formula as the importer: exact. */
		CHECK(e->x == px(&d->x, x->x, SCREEN_W));
		CHECK(e->y == px(&d->y, x->y, SCREEN_H));
		if (d->has_pressure)
			CHECK_NEAR(e->pressure, (x->pressure - d->pressure.min) /
						  (d->pressure.max - d->pressure.min), 1e-12);
		else
			CHECK(e->pressure == x->pressure);
		if (d->has_tilt) {
			CHECK_NEAR(e->tilt_x, tilt(&d->tilt_x, x->tilt_x), 1e-9);
			CHECK_NEAR(e->tilt_y, tilt(&d->tilt_y, x->tilt_y), 1e-9);
		} else {
			CHECK(e->tilt_x == 0 && e->tilt_y == 0);
		}
		if (type == EVENT_PEN_BUTTON) {
			CHECK_INT(e->button, x->button);
			CHECK_INT(e->pressed, x->pressed);
		}
	}
}

/* ../shared/reference's recording from the VM's virtual pen, unchanged. */
static void test_virtual_pen(void)
{
	static const struct device_axes d = {
		.x = { 0, 32767, 100 }, .y = { 0, 32767, 100 }, .pressure = { 0, 8191, 0 },
		.has_pressure = true,
	};
	static const struct expect ex[] = {
		{ "proximity-in", 0, 0, 10000, 8000, 0, 0, 0, 0, 0 },
		{ "motion", 102836, 0, 10000, 8000, 3000, 0, 0, 0, 0 },
		{ "tip-down", 102836, 0, 10000, 8000, 3000, 0, 0, 0, 0 },
		{ "motion", 2586392, 0, 10500, 8000, 3500, 0, 0, 0, 0 },
		{ "motion", 2607946, 0, 11000, 8000, 4000, 0, 0, 0, 0 },
		{ "motion", 2628699, 0, 11500, 8000, 4500, 0, 0, 0, 0 },
		{ "motion", 2657231, 0, 11500, 8000, 0, 0, 0, 0, 0 },
		{ "tip-up", 2657231, 0, 11500, 8000, 0, 0, 0, 0, 0 },
		{ "proximity-out", 2759038, 0, 11500, 8000, 0, 0, 0, 0, 0 },
	};
	struct trace t = { 0 };

	load("virtual-pen.yml", &t);
	check_events("virtual-pen.yml", &t, ex, sizeof(ex) / sizeof(ex[0]), &d);
	/* Spelled out once: x 10000 of 0..32767 on 1280 pixels. */
	CHECK(t.events[0].x == 390.625);
	CHECK(t.events[0].y == 195.3125);
	CHECK(t.events[2].pressure == 3000.0 / 8191.0);
	trace_finish(&t);
}

/* Hand-made in `libinput record` layout from a Wacom Intuos Pro M (PTH-660): pen + pad. */
static void test_wacom(void)
{
	static const struct device_axes d = {
		.x = { 0, 44800, 200 }, .y = { 0, 29600, 200 }, .pressure = { 0, 8191, 0 },
		.tilt_x = { -64, 63, 57 }, .tilt_y = { -64, 63, 57 },
		.has_pressure = true, .has_tilt = true,
	};
	static const struct expect ex[] = {
		/* the trunk: hover in at the bottom centre, press, up the page */
		{ "proximity-in", 1000, 0, 22400, 26900, 0, 12, -9, 0, 0 },
		{ "motion", 6000, 0, 22400, 26850, 0, 12, -9, 0, 0 },
		/* (a frame with only ABS_DISTANCE and MSC_SERIAL: nothing) */
		{ "motion", 16017, 0, 22400, 26800, 1230, 12, -9, 0, 0 },
		{ "tip-down", 16017, 0, 22400, 26800, 1230, 12, -9, 0, 0 },
		{ "motion", 21029, 0, 22420, 26000, 2810, 13, -10, 0, 0 },
		{ "motion", 26018, 0, 22380, 24600, 3960, 13, -10, 0, 0 },
		{ "motion", 31021, 0, 22450, 23000, 4410, 14, -11, 0, 0 },
		{ "motion", 36015, 0, 22310, 21200, 4870, 14, -11, 0, 0 },
		{ "motion", 41023, 0, 22260, 19400, 5120, 15, -12, 0, 0 },
		{ "motion", 46022, 0, 22330, 17500, 4980, 15, -12, 0, 0 },
		{ "motion", 51012, 0, 22180, 15600, 4650, 16, -13, 0, 0 },
		{ "motion", 56016, 0, 22120, 13700, 4100, 16, -13, 0, 0 },
		{ "motion", 61011, 0, 22050, 11900, 3320, 17, -14, 0, 0 },
		{ "motion", 66020, 0, 22050, 11900, 0, 17, -14, 0, 0 },
		{ "tip-up", 66020, 0, 22050, 11900, 0, 17, -14, 0, 0 },
		/* the pad's BTN_0 at 101020..129020: nothing */
		{ "motion", 131020, 0, 22200, 17200, 0, 20, -6, 0, 0 },
		/* the side branch, barrel button pressed on the way */
		{ "motion", 171020, 0, 22200, 17200, 2600, 20, -6, 0, 0 },
		{ "tip-down", 171020, 0, 22200, 17200, 2600, 20, -6, 0, 0 },
		{ "motion", 176020, 0, 23300, 16600, 3700, 20, -6, 0, 0 },
		{ "motion", 181012, 0, 24500, 15900, 4300, 20, -6, 0, 0 },
		{ "motion", 186006, 0, 25800, 15200, 4700, 20, -6, 0, 0 },
		{ "pen-button", 186006, 0, 25800, 15200, 4700, 20, -6, 0, 1 },
		{ "motion", 191002, 0, 27000, 14500, 4900, 20, -6, 0, 0 },
		{ "motion", 196000, 0, 28100, 13800, 4500, 22, -4, 0, 0 },
		{ "pen-button", 196000, 0, 28100, 13800, 4500, 22, -4, 0, 0 },
		{ "motion", 201000, 0, 29100, 13200, 3900, 22, -4, 0, 0 },
		{ "motion", 206002, 0, 30000, 12600, 3000, 22, -4, 0, 0 },
		{ "motion", 211006, 0, 30000, 12600, 0, 22, -4, 0, 0 },
		{ "tip-up", 211006, 0, 30000, 12600, 0, 22, -4, 0, 0 },
		/* out where it was last seen, not at the zeroes of the leaving frame */
		{ "proximity-out", 296006, 0, 30000, 12600, 0, 22, -4, 0, 0 },
		/* the eraser end */
		{ "proximity-in", 1196006, 1, 29500, 13100, 0, -18, 25, 0, 0 },
		{ "motion", 1201006, 1, 29500, 13100, 3100, -18, 25, 0, 0 },
		{ "tip-down", 1201006, 1, 29500, 13100, 3100, -18, 25, 0, 0 },
		{ "motion", 1206006, 1, 29800, 12900, 3300, -18, 25, 0, 0 },
		{ "motion", 1211006, 1, 29400, 13000, 3500, -18, 25, 0, 0 },
		{ "motion", 1216006, 1, 29900, 12800, 3700, -18, 25, 0, 0 },
		{ "motion", 1221006, 1, 29500, 13100, 3900, -18, 25, 0, 0 },
		{ "motion", 1226006, 1, 29500, 13100, 0, -18, 25, 0, 0 },
		{ "tip-up", 1226006, 1, 29500, 13100, 0, -18, 25, 0, 0 },
		{ "proximity-out", 1231006, 1, 29500, 13100, 0, -18, 25, 0, 0 },
	};
	static const uint64_t pad_times[] = { 101020, 129020, 199006, 204006, 1631006, 1741006 };
	struct trace t = { 0 };

	load("wacom-intuos-pro-m.yml", &t);
	check_events("wacom-intuos-pro-m.yml", &t, ex, sizeof(ex) / sizeof(ex[0]), &d);
	for (size_t i = 0; i < t.nevents; i++)
		for (size_t k = 0; k < sizeof(pad_times) / sizeof(pad_times[0]); k++)
			CHECK(t.events[i].time_us != pad_times[k]);
	/* Spelled out: the trunk starts at the bottom centre of the screen... */
	CHECK_NEAR(t.events[3].x, 640.0, 0.1);
	CHECK_NEAR(t.events[3].y, 724.3, 0.1);
	/* ...and ends at about y 322; tilt 12 units at 57 units/radian is ~12.06 degrees. */
	CHECK_NEAR(t.events[14].y, 11900.0 * 800 / 29601, 1e-9);
	CHECK_NEAR(t.events[0].tilt_x, 12.0623, 1e-4);
	CHECK_NEAR(t.events[0].tilt_y, -9.0467, 1e-4);
	trace_finish(&t);
}

/* A touchscreen pen without pressure or tilt: pressure is 1 while the tip is down. */
static void test_no_pressure(void)
{
	static const struct device_axes d = { .x = { 0, 4095, 0 }, .y = { 0, 4095, 0 } };
	static const struct expect ex[] = {
		{ "proximity-in", 0, 0, 2048, 3700, 0, 0, 0, 0, 0 },
		{ "tip-down", 8000, 0, 2048, 3700, 1, 0, 0, 0, 0 },
		{ "motion", 16000, 0, 2048, 3500, 1, 0, 0, 0, 0 },
		{ "motion", 24000, 0, 2058, 3100, 1, 0, 0, 0, 0 },
		{ "motion", 32000, 0, 2068, 2700, 1, 0, 0, 0, 0 },
		{ "motion", 40000, 0, 2078, 2300, 1, 0, 0, 0, 0 },
		{ "motion", 48000, 0, 2088, 1900, 1, 0, 0, 0, 0 },
		{ "pen-button", 56000, 0, 2088, 1900, 1, 0, 0, 0, 1 },
		{ "motion", 64000, 0, 2088, 1500, 1, 0, 0, 0, 0 },
		{ "pen-button", 64000, 0, 2088, 1500, 1, 0, 0, 0, 0 },
		{ "tip-up", 72000, 0, 2088, 1500, 0, 0, 0, 0, 0 },
		{ "proximity-out", 80000, 0, 2088, 1500, 0, 0, 0, 0, 0 },
	};
	struct trace t = { 0 };

	load("pen-no-pressure.yml", &t);
	check_events("pen-no-pressure.yml", &t, ex, sizeof(ex) / sizeof(ex[0]), &d);
	trace_finish(&t);
}

/* A Huion-like pen display: tilt -60..60 without resolution maps onto -64..64 degrees. */
static void test_tilt_without_resolution(void)
{
	static const struct device_axes d = {
		.x = { 0, 53580, 200 }, .y = { 0, 30140, 200 }, .pressure = { 0, 8191, 0 },
		.tilt_x = { -60, 60, 0 }, .tilt_y = { -60, 60, 0 },
		.has_pressure = true, .has_tilt = true,
	};
	static const struct expect ex[] = {
		{ "proximity-in", 0, 0, 26790, 27000, 0, -60, 30, 0, 0 },
		{ "motion", 3000, 0, 26790, 27000, 900, -60, 30, 0, 0 },
		{ "tip-down", 3000, 0, 26790, 27000, 900, -60, 30, 0, 0 },
		{ "motion", 6000, 0, 26790, 26000, 1500, -60, 30, 0, 0 },
		{ "motion", 9000, 0, 26830, 24000, 2400, -48, 24, 0, 0 },
		{ "motion", 12000, 0, 26870, 22000, 3300, -36, 18, 0, 0 },
		{ "motion", 15000, 0, 26910, 20000, 4200, -24, 12, 0, 0 },
		{ "motion", 18000, 0, 26950, 18000, 5100, -12, 6, 0, 0 },
		{ "motion", 21000, 0, 26990, 16000, 6000, 0, 0, 0, 0 },
		{ "pen-button", 24000, 0, 26990, 16000, 6000, 0, 0, 1, 1 },
		{ "motion", 27000, 0, 26990, 16000, 0, 0, 0, 0, 0 },
		{ "pen-button", 27000, 0, 26990, 16000, 0, 0, 0, 1, 0 },
		{ "tip-up", 27000, 0, 26990, 16000, 0, 0, 0, 0, 0 },
		{ "motion", 30000, 0, 26990, 16000, 0, 60, -60, 0, 0 },
		{ "proximity-out", 33000, 0, 26990, 16000, 0, 60, -60, 0, 0 },
	};
	struct trace t = { 0 };

	load("huion-tilt-no-resolution.yml", &t);
	check_events("huion-tilt-no-resolution.yml", &t, ex, sizeof(ex) / sizeof(ex[0]), &d);
	CHECK(t.events[0].tilt_x == -64.0 && t.events[0].tilt_y == 32.0);
	CHECK(t.events[13].tilt_x == 64.0 && t.events[13].tilt_y == -64.0);
	trace_finish(&t);
}

/* ---- small inline recordings ------------------------------------------------------ */

#define HEAD "version: 1\ndevices:\n"
#define PEN_EVDEV(name, keys, abs, absinfo)                                                \
	"- evdev:\n    name: \"" name "\"\n    codes:\n      1: [" keys "]\n      3: [" abs \
	"]\n    absinfo:\n" absinfo

static int parse(const char *yaml, struct trace *t, struct error *err)
{
	return trace_parse_libinput(yaml, strlen(yaml), "r.yml", SCREEN_W, SCREEN_H, t, err);
}

static void dump(const struct trace *t)
{
	for (size_t i = 0; i < t->nevents; i++) {
		char line[TRACE_LINE_MAX];

		if (trace_format_event(&t->events[i], line, sizeof(line)) > 0)
			fprintf(stderr, "  %s", line);
	}
}

static void check_types(const struct trace *t, const char *types)
{
	struct buf b;

	buf_init(&b);
	for (size_t i = 0; i < t->nevents; i++)
		CHECK(buf_printf(&b, "%s%s", i ? " " : "", event_type_name(t->events[i].type)) == 0);
	CHECK(buf_append(&b, "", 1) == 0);
	if (strcmp((const char *)b.data, types) != 0) {
		fprintf(stderr, "got      %s\nexpected %s\n", (const char *)b.data, types);
		dump(t);
		CHECK(0);
	}
	buf_finish(&b);
}

static void test_pressure_threshold(void)
{
	/* No BTN_TOUCH: the tip is down above 5% of the pressure range. */
	static const char yaml[] = HEAD PEN_EVDEV("No Touch Pen", "320, 331", "0, 1, 24",
						   "      0: [0, 999, 0, 0, 0]\n"
						   "      1: [0, 999, 0, 0, 0]\n"
						   "      24: [100, 1100, 0, 0, 0]\n")
		"  events:\n"
		"  - evdev:\n"
		"    - [0, 10, 1, 320, 1]\n    - [0, 10, 0, 0, 0]\n"
		"  - evdev:\n"
		"    - [0, 20, 3, 24, 150]\n    - [0, 20, 0, 0, 0]\n" /* 5% exactly: still up */
		"  - evdev:\n"
		"    - [0, 30, 3, 24, 151]\n    - [0, 30, 0, 0, 0]\n" /* down */
		"  - evdev:\n"
		"    - [0, 40, 3, 0, 500]\n    - [0, 40, 0, 0, 0]\n"
		"  - evdev:\n"
		"    - [0, 50, 3, 24, 90]\n    - [0, 50, 0, 0, 0]\n" /* below min: clamped to 0 */
		"  - evdev:\n"
		"    - [0, 60, 1, 320, 0]\n    - [0, 60, 0, 0, 0]\n";
	struct trace t = { 0 };
	struct error err;

	CHECK(parse(yaml, &t, &err) == 0);
	check_types(&t, "proximity-in motion motion tip-down motion motion tip-up proximity-out");
	CHECK(t.events[1].pressure == 0.05);
	CHECK(t.events[3].pressure == 0.051);
	CHECK(t.events[4].x == 500.0 * 1280 / 1000);
	CHECK(t.events[5].pressure == 0.0);
	trace_finish(&t);
}

static void test_frames(void)
{
	/* Pen swapped for eraser within one frame; events before the device description;
	 * `- libinput:` items, unknown keys, an unfinished last frame. */
	static const char yaml[] =
		"# libinput record\n"
		"version: 1\n"
		"ndevices: 1\n"
		"unknown-key: {a: [1, 2, {b: c}]}\n"
		"devices:\n"
		"- node: /dev/input/event5\n"
		"  events:\n"
		"  - evdev:\n"
		"    - [1, 0, 3, 0, 100]\n"
		"    - [1, 0, 1, 320, 1]\n"
		"    - [1, 0, 4, 5, 12345]\n" /* MSC_SERIAL: ignored */
		"    - [1, 0, 0, 0, 0]\n"
		"  - libinput:\n"
		"    - {type: TABLET_TOOL_PROXIMITY, time: 1.000000}\n"
		"  - evdev:\n"
		"    - [1, 500, 1, 330, 1]\n"
		"    - [1, 500, 1, 332, 1]\n"
		"    - [1, 500, 0, 0, 0]\n"
		"  - evdev:\n"
		"    - [1, 900, 1, 320, 0]\n"
		"    - [1, 900, 1, 321, 1]\n"
		"    - [1, 900, 1, 332, 0]\n"
		"    - [1, 900, 3, 0, 200]\n"
		"    - [1, 900, 0, 0, 0]\n"
		"  - evdev:\n"
		"    - [2, 0, 3, 0, 300]\n"
		"    - [2, 0, 0, 2, 0]\n" /* SYN_MT_REPORT: not the end of a frame */
		"    - [2, 0, 3, 1, 300]\n"
		"    - [2, 0, 0, 0, 0]\n"
		"  - evdev:\n"
		"    - [3, 0, 1, 321, 0]\n" /* no SYN_REPORT: dropped */
		"  evdev:\n"
		"    name: Swap Pen\n"
		"    id: [3, 1, 2, 3]\n"
		"    codes:\n"
		"      0: [0, 1, 2]\n"
		"      1: [320, 321, 330, 331, 332]\n"
		"      3: [0, 1]\n"
		"    absinfo:\n"
		"      0: [0, 1279, 0, 0, 0]\n"
		"      1: [0, 799, 0, 0, 0]\n"
		"  quirks:\n"
		"  udev: ~\n";
	struct trace t = { 0 };
	struct error err;

	if (parse(yaml, &t, &err) < 0)
		fprintf(stderr, "%s\n", err.msg);
	CHECK(t.nevents > 0);
	check_types(&t, "proximity-in tip-down pen-button pen-button tip-up proximity-out "
			"proximity-in tip-down motion");
	CHECK(t.events[0].time_us == 1000000 && t.events[0].x == 100.0);
	CHECK(t.events[2].button == EVENT_PEN_BUTTON_STYLUS2 && t.events[2].pressed);
	CHECK(t.events[2].pressure == 1.0);
	/* Leaving: buttons up, tip up, out at the last position; then the eraser comes in
	 * where the new frame says, its tip already down. */
	CHECK(t.events[3].button == EVENT_PEN_BUTTON_STYLUS2 && !t.events[3].pressed);
	CHECK(t.events[5].tool == EVENT_TOOL_PEN && t.events[5].x == 100.0);
	CHECK(t.events[6].tool == EVENT_TOOL_ERASER && t.events[6].x == 200.0);
	CHECK(t.events[7].tool == EVENT_TOOL_ERASER && t.events[7].time_us == 1000900);
	CHECK(t.events[8].x == 300.0 && t.events[8].y == 300.0 && t.events[8].time_us == 2000000);
	trace_finish(&t);
}

static void test_two_tablets(void)
{
	/* Events of several tablets interleave by time; ties keep the file's order. */
	static const char yaml[] = HEAD
		PEN_EVDEV("A", "320", "0, 1", "      0: [0, 1279, 0, 0, 0]\n      1: [0, 799, 0, 0, 0]\n")
		"  events:\n"
		"  - evdev: [[0, 10, 1, 320, 1], [0, 10, 0, 0, 0]]\n"
		"  - evdev: [[0, 30, 3, 0, 5], [0, 30, 0, 0, 0]]\n"
		"  - evdev: [[0, 50, 1, 320, 0], [0, 50, 0, 0, 0]]\n"
		"- evdev:\n"
		"    name: a keyboard\n"
		"    codes: {1: [30, 31]}\n"
		"  events:\n"
		"  - evdev: [[0, 15, 1, 30, 1], [0, 15, 0, 0, 0]]\n"
		PEN_EVDEV("B", "321", "0, 1", "      0: [0, 2559, 0, 0, 0]\n      1: [0, 1599, 0, 0, 0]\n")
		"  events:\n"
		"  - evdev: [[0, 20, 3, 1, 800], [0, 20, 1, 321, 1], [0, 20, 0, 0, 0]]\n"
		"  - evdev: [[0, 30, 3, 0, 6], [0, 30, 0, 0, 0]]\n"
		"  - evdev: [[0, 40, 1, 321, 0], [0, 40, 0, 0, 0]]\n";
	static const uint64_t times[] = { 10, 20, 30, 30, 40, 50 };
	static const int tools[] = { 0, 1, 0, 1, 1, 0 };
	struct trace t = { 0 };
	struct error err;

	CHECK(parse(yaml, &t, &err) == 0);
	check_types(&t, "proximity-in proximity-in motion motion proximity-out proximity-out");
	for (size_t i = 0; i < t.nevents; i++) {
		CHECK(t.events[i].time_us == times[i]);
		CHECK_INT(t.events[i].tool, tools[i]);
	}
	CHECK(t.events[1].y == 400.0);
	CHECK(t.events[2].x == 5.0 && t.events[3].x == 3.0);
	trace_finish(&t);
}

struct bad {
	const char *yaml;
	unsigned line;
	const char *msg;
};

#define VPEN                                                                             \
	HEAD PEN_EVDEV("Virtual Pen", "320, 330", "0, 1",                                \
		       "      0: [0, 32767, 0, 0, 100]\n      1: [0, 32767, 0, 0, 100]\n") \
		"  events:\n"

static const struct bad bad_inputs[] = {
	{ "", 0, "empty file" },
	{ "just some words\n", 1, "got a scalar" },
	{ "- a\n- b\n", 1, "got a sequence" },
	{ "version: 1\ndevices: [\n", 3, "YAML error" },
	{ "version: 1\ndevices: ]\n", 2, "YAML error" },
	{ "version: 1\ndevices: \"\x01\"\n", 2, "not a libinput recording" },
	{ "version: 2\ndevices: []\n", 1, "unsupported libinput record version 2 (this edaha reads 1)" },
	{ "# c\n\nversion: one\ndevices: []\n", 3, "version \"one\" is not an integer" },
	{ "version: [1]\n", 1, "expected an integer for version, got a sequence" },
	{ "devices: []\n", 0, "no \"version\"" },
	{ "version: 1\n", 0, "no \"devices\"" },
	{ "version: 1\ndevices: []\n", 0, "no pen tablet device in this recording" },
	{ "version: 1\ndevices: 3\n", 2, "expected a sequence for devices, got a scalar" },
	{ "version: 1\ndevices:\n- 3\n", 3, "expected a mapping for a device, got a scalar" },
	{ "version: 1\ndevices:\n- evdev: [1]\n", 3, "expected a mapping for evdev, got a sequence" },
	{ "version: 1\ndevices:\n- evdev:\n    codes: {x: [1]}\n", 4, "bad event type \"x\"" },
	{ "version: 1\ndevices:\n- evdev:\n    codes: {1: [320, pen]}\n", 4,
	  "event code \"pen\" is not an integer" },
	{ "version: 1\ndevices:\n- evdev:\n    codes: {1: 320}\n", 4, "expected a sequence for event codes" },
	{ "version: 1\ndevices:\n- evdev:\n    absinfo: {0: [0, 1, 2, 3]}\n", 4,
	  "expected 5 integers, got 4" },
	{ "version: 1\ndevices:\n- evdev:\n    absinfo:\n      0: [0, 1.5, 0, 0, 0]\n", 5,
	  "\"1.5\" is not an integer" },
	{ HEAD PEN_EVDEV("P", "320", "0, 1", "      0: [0, 100, 0, 0, 0]\n      1: [5, 5, 0, 0, 0]\n"), 10,
	  "device \"P\": absinfo for ABS_Y (1) has max 5 <= min 5" },
	{ HEAD PEN_EVDEV("P", "320", "0, 1, 24",
			 "      0: [0, 100, 0, 0, 0]\n      1: [0, 100, 0, 0, 0]\n"
			 "      24: [0, -1, 0, 0, 0]\n"),
	  11, "absinfo for ABS_PRESSURE (24) has max -1 <= min 0" },
	{ HEAD PEN_EVDEV("P", "320", "0, 1", "      0: [0, 100, 0, 0, 0]\n      1: [5000000000, 6000000000, 0, 0, 0]\n"), 10,
	  "absinfo value 5000000000 out of range" },
	{ HEAD PEN_EVDEV("P\\x01\\n", "320", "0, 1", "      0: [0, 100, 0, 0, 0]\n      1: [0, 0, 0, 0, 0]\n"), 10,
	  "device \"P??\": absinfo" },
	{ HEAD PEN_EVDEV("P", "321", "0, 1", "      0: [0, 100, 0, 0, 0]\n"), 3,
	  "device \"P\" is a pen tablet but has no absinfo for ABS_Y (1)" },
	{ HEAD "- events: []\n  evdev:\n    name: Q\n    codes: {1: [320], 3: [0, 1, 26]}\n"
	       "    absinfo: {0: [0, 9, 0, 0, 0], 1: [0, 9, 0, 0, 0]}\n",
	  4, "device \"Q\" is a pen tablet but has no absinfo for ABS_TILT_X (26)" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0]\n", 13, "bad evdev row [sec, usec, type, code, value]: expected 5 integers, got 4" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, 1, 2]\n", 13, "expected 5 integers, got 6" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, x]\n", 13, "\"x\" is not an integer" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, 0x10]\n", 13, "\"0x10\" is not an integer" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, [1]]\n", 13, "expected an integer" },
	{ VPEN "  - evdev:\n    - 5\n", 13, "bad evdev row: expected [sec, usec, type, code, value], got a scalar" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, 4294967296]\n", 13, "value 4294967296 out of range" },
	{ VPEN "  - evdev:\n    - [-1, 0, 3, 0, 1]\n", 13, "sec -1 is negative" },
	{ VPEN "  - evdev:\n    - [0, -1, 3, 0, 1]\n", 13, "usec -1 out of range 0..999999" },
	{ VPEN "  - evdev:\n    - [0, 1000000, 3, 0, 1]\n", 13, "usec 1000000 out of range 0..999999" },
	/* Times stop at TRACE_MAX_TIME_US, 2^62 us; sec * 10^6 must not overflow first. */
	{ VPEN "  - evdev:\n    - [4611686018427, 387905, 0, 0, 0]\n", 13,
	  "time 4611686018427.387905 s too large (limit 4611686018427.387904 s)" },
	{ VPEN "  - evdev:\n    - [4611686018428, 0, 0, 0, 0]\n", 13, "time 4611686018428.000000 s too large" },
	{ VPEN "  - evdev:\n    - [18446744073709552, 0, 3, 0, 1]\n", 13, "too large" },
	{ VPEN "  - evdev:\n    - [4611686018427387903, 999999, 3, 0, 1]\n", 13, "too large" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 65536, 1]\n", 13, "code 65536 out of range" },
	{ VPEN "  - evdev:\n    - [0, 0, 3, 0, 99999999999999999999]\n", 13, "out of range" },
	{ VPEN "  - evdev: [[1, 5, 0, 0, 0]]\n  - evdev: [[1, 4, 0, 0, 0]]\n", 13,
	  "time goes backwards (1000004 < 1000005 us)" },
	{ VPEN "  - 7\n", 12, "expected a mapping for an events item" },
	{ VPEN "  - evdev: 7\n", 12, "expected a sequence for evdev frame, got a scalar" },
	{ "version: 1\ndevices: &d []\nother: *d\n", 0, "no pen tablet" },
	{ "version: 1\ndevices: *nope\n", 2, "expected a sequence for devices, got an alias" },
	{ "version: 1\ndevices:\n- evdev: *x\n", 3, "expected a mapping for evdev, got an alias" },
};

static void test_errors(void)
{
	static const char full[] = "edaha-trace 1\nscreen 1 1\n1 motion pen 1 1 0 0 0\n";

	for (size_t i = 0; i < sizeof(bad_inputs) / sizeof(bad_inputs[0]); i++) {
		const struct bad *b = &bad_inputs[i];
		struct trace t = { 0 };
		struct error err = { { 0 } };
		char prefix[32];
		int r;

		/* A full trace beforehand: failure must leave it empty. */
		CHECK(trace_parse_edaha(full, strlen(full), "x", 1, 1, &t, &err) == 0);
		r = parse(b->yaml, &t, &err);
		if (b->line)
			snprintf(prefix, sizeof(prefix), "r.yml:%u: ", b->line);
		else
			snprintf(prefix, sizeof(prefix), "r.yml: ");
		if (r != -EINVAL || strncmp(err.msg, prefix, strlen(prefix)) != 0 ||
		    !strstr(err.msg, b->msg) || t.nevents || t.events) {
			fprintf(stderr, "bad input #%zu:\n%s\n  r = %d, message: %s\n"
				"  wanted \"%s\" and \"%s\"\n", i, b->yaml, r, err.msg, prefix, b->msg);
			CHECK(0);
		}
	}
}

static void test_time_limit(void)
{
	/* The last microsecond the parsers take: a replay adds its gaps to that. */
	static const char yaml[] = VPEN
		"  - evdev: [[4611686018427, 387903, 1, 320, 1], [4611686018427, 387903, 0, 0, 0]]\n"
		"  - evdev: [[4611686018427, 387904, 1, 320, 0], [4611686018427, 387904, 0, 0, 0]]\n";
	struct trace t = { 0 };
	struct error err;

	CHECK(parse(yaml, &t, &err) == 0);
	check_types(&t, "proximity-in proximity-out");
	CHECK(t.events[0].time_us == TRACE_MAX_TIME_US - 1);
	CHECK(t.events[1].time_us == TRACE_MAX_TIME_US);
	trace_finish(&t);
}

static void test_screen_sizes(void)
{
	struct trace t = { 0 };
	struct error err;
	char path[1024];

	snprintf(path, sizeof(path), "%s/virtual-pen.yml", data_dir);
	CHECK(trace_load(path, 1920, 1080, &t, &err) == 0);
	CHECK(t.events[0].x == 10000.0 * 1920 / 32768);
	CHECK(t.events[0].y == 8000.0 * 1080 / 32768);
	CHECK_INT(trace_parse_libinput("version: 1\n", 11, "r.yml", 0, 0, &t, &err), -EINVAL);
	CHECK(strstr(err.msg, "bad screen size"));
	trace_finish(&t);
}

int main(int argc, char **argv)
{
	if (argc > 1)
		data_dir = argv[1];
	test_virtual_pen();
	test_wacom();
	test_no_pressure();
	test_tilt_without_resolution();
	test_pressure_threshold();
	test_frames();
	test_two_tablets();
	test_errors();
	test_time_limit();
	test_screen_sizes();
	return 0;
}
