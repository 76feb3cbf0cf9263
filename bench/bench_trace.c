/* SPDX-License-Identifier: MIT */
/*
 * Parsing recorded input: edaha traces and `libinput record` YAML of growing size, made
 * in memory. Both should be linear; a replay of a long kiosk session must load fast.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "buf.h"
#include "trace.h"

/* Medians of 7 parses; libyaml is slower, 5 keep the whole run under ~20 s. */
#define REPS_EDAHA 7
#define REPS_LIBINPUT 5
#define PI 3.14159265358979323846
#define STROKE 100 /* events per stroke: in, down, 96 motions, up, out */

static const size_t sizes[] = { 12500, 25000, 50000, 100000 };

struct job {
	const char *data;
	size_t len;
	int (*parse)(const char *data, size_t len, const char *name, int w, int h,
		     struct trace *t, struct error *err);
	int reps;
	size_t nevents;
};

static void die(const char *what)
{
	fprintf(stderr, "bench_trace: %s\n", what);
	exit(1);
}

/* A pen position along a wavy stroke, so numbers have all their digits like real ones. */
static void pen_at(size_t i, double *x, double *y, double *p)
{
	double u = (double)(i % STROKE) / STROKE;

	*x = 200.0 + 800.0 * u + 13.0 * sin((double)i * 0.37);
	*y = 700.0 - 400.0 * u + 7.0 * cos((double)i * 0.21);
	*p = 0.3 + 0.5 * sin(PI * u);
}

/* Written through trace_format_event, exactly as `edaha --record` does. */
static void make_edaha(struct buf *b, size_t n)
{
	if (buf_printf(b, "edaha-trace 1\n# recorded by edaha\nscreen 1280 800\n") < 0)
		die("out of memory");
	for (size_t i = 0; i < n; i++) {
		struct event ev = { .time_us = 1000000 + 8000 * (uint64_t)i, .tilt_x = 12.5,
				    .tilt_y = -7.25 };
		char line[TRACE_LINE_MAX];
		size_t k = i % STROKE;
		int len;

		pen_at(i, &ev.x, &ev.y, &ev.pressure);
		ev.type = k == 0 ? EVENT_PROXIMITY_IN
			: k == 1 ? EVENT_TIP_DOWN
			: k == STROKE - 2 ? EVENT_TIP_UP
			: k == STROKE - 1 ? EVENT_PROXIMITY_OUT
			: EVENT_MOTION;
		if (k == 0 || k >= STROKE - 2)
			ev.pressure = 0.0;
		len = trace_format_event(&ev, line, sizeof(line));
		if (len < 0 || buf_append(b, line, (size_t)len) < 0)
			die("cannot format");
	}
}

static int row(struct buf *b, uint64_t t, int type, int code, long value, const char *comment)
{
	return buf_printf(b, "    - [%3llu, %6llu, %3d, %3d, %7ld] # %s\n",
			  (unsigned long long)(t / 1000000), (unsigned long long)(t % 1000000),
			  type, code, value, comment);
}

/* A Wacom-like pen, laid out as `libinput record` writes it, comments and all. */
static void make_libinput(struct buf *b, size_t frames)
{
	int r = buf_printf(b, "# libinput record\nversion: 1\nndevices: 1\nlibinput:\n"
			      "  version: \"1.22.1\"\n  git: \"unknown\"\nsystem:\n"
			      "  os: \"debian:12\"\n  kernel: \"6.1.0-13-amd64\"\n"
			      "devices:\n- node: /dev/input/event13\n  evdev:\n"
			      "    name: \"Wacom Intuos Pro M Pen\"\n    id: [3, 1386, 855, 272]\n"
			      "    codes:\n      0: [0, 1, 2, 3]\n      1: [320, 321, 330, 331, 332]\n"
			      "      3: [0, 1, 24, 25, 26, 27]\n      4: [0]\n    absinfo:\n"
			      "      0: [0, 44800, 4, 0, 200]\n      1: [0, 29600, 4, 0, 200]\n"
			      "      24: [0, 8191, 0, 0, 0]\n      25: [0, 63, 0, 0, 0]\n"
			      "      26: [-64, 63, 0, 0, 57]\n      27: [-64, 63, 0, 0, 57]\n"
			      "    properties: [0]\n  udev:\n    properties:\n    - ID_INPUT=1\n"
			      "    - ID_INPUT_TABLET=1\n  quirks:\n  events:\n");

	for (size_t i = 0; i < frames && r == 0; i++) {
		uint64_t t = 8000 * (uint64_t)i;
		size_t k = i % STROKE;
		double x, y, p;

		pen_at(i, &x, &y, &p);
		r = buf_printf(b, "  - evdev:\n");
		if (r == 0)
			r = row(b, t, 3, 0, lround(x * 35.0), "EV_ABS / ABS_X");
		if (r == 0)
			r = row(b, t, 3, 1, lround(y * 37.0), "EV_ABS / ABS_Y");
		if (r == 0 && k != 0 && k < STROKE - 2)
			r = row(b, t, 3, 24, lround(p * 8191.0), "EV_ABS / ABS_PRESSURE");
		if (r == 0 && k == 0)
			r = row(b, t, 1, 320, 1, "EV_KEY / BTN_TOOL_PEN");
		if (r == 0 && k == 1)
			r = row(b, t, 1, 330, 1, "EV_KEY / BTN_TOUCH");
		if (r == 0 && k == STROKE - 2)
			r = row(b, t, 1, 330, 0, "EV_KEY / BTN_TOUCH");
		if (r == 0 && k == STROKE - 1)
			r = row(b, t, 1, 320, 0, "EV_KEY / BTN_TOOL_PEN");
		if (r == 0)
			r = row(b, t, 4, 0, 294236147, "EV_MSC / MSC_SERIAL");
		if (r == 0)
			r = row(b, t, 0, 0, 0, "------------ SYN_REPORT (0) ----------");
	}
	if (r < 0)
		die("out of memory");
}

static void run(void *arg)
{
	struct job *job = arg;
	struct trace t = { 0 };
	struct error err;

	if (job->parse(job->data, job->len, "bench", 1280, 800, &t, &err) < 0)
		die(err.msg);
	job->nevents = t.nevents;
	trace_finish(&t);
}

static void bench(const char *name, void (*make)(struct buf *b, size_t n), struct job *job)
{
	double prev_size = 0, prev_s = 0, last_s = 0;
	size_t last_events = 0, last_bytes = 0;

	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		size_t n = bench_quick ? sizes[i] / 10 : sizes[i];
		struct buf b;
		char label[64];
		double s;

		buf_init(&b);
		make(&b, n);
		job->data = (const char *)b.data;
		job->len = b.len;
		s = bench_run(run, job, job->reps);
		snprintf(label, sizeof(label), "%s (%.1f MB)", name, (double)b.len / 1e6);
		bench_row(label, (double)n, s, &prev_size, &prev_s);
		last_s = s;
		last_events = job->nevents;
		last_bytes = b.len;
		buf_finish(&b);
	}
	printf("%-28s %10zu events  %.2f M events/s  %.0f MB/s\n", name, last_events,
	       (double)last_events / last_s / 1e6, (double)last_bytes / last_s / 1e6);
}

int main(int argc, char **argv)
{
	struct job edaha = { .parse = trace_parse_edaha, .reps = REPS_EDAHA };
	struct job libinput = { .parse = trace_parse_libinput, .reps = REPS_LIBINPUT };

	if (bench_init(&argc, argv, NULL))
		return 1;
	edaha.reps = bench_reps(REPS_EDAHA);
	libinput.reps = bench_reps(REPS_LIBINPUT);
	printf("# size: events (edaha) or evdev frames (libinput); median of %d and %d parses\n",
	       edaha.reps, libinput.reps);
	bench("edaha trace", make_edaha, &edaha);
	bench("libinput record", make_libinput, &libinput);
	return 0;
}
