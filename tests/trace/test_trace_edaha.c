/* SPDX-License-Identifier: MIT */
/*
 * The edaha trace format: writer -> parser round trips bit-exact, screen scaling, every
 * error names the right line and leaves the trace empty, trace_load and the demo trace.
 * argv[1]: tests/data
 */
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "buf.h"
#include "test.h"
#include "trace.h"

static const char *data_dir = "tests/data";

static bool same_double(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

static bool same_event(const struct event *a, const struct event *b)
{
	return a->type == b->type && a->time_us == b->time_us && a->tool == b->tool &&
	       same_double(a->x, b->x) && same_double(a->y, b->y) &&
	       same_double(a->pressure, b->pressure) && same_double(a->tilt_x, b->tilt_x) &&
	       same_double(a->tilt_y, b->tilt_y) && a->button == b->button &&
	       a->pressed == b->pressed;
}

static int parse(const char *text, int w, int h, struct trace *t, struct error *err)
{
	return trace_parse_edaha(text, strlen(text), "t.trace", w, h, t, err);
}

/* Events of every kind, with doubles that only survive an exact format. */
static size_t make_events(struct event *ev, size_t max)
{
	size_t n = 0;
	uint64_t t = 1000;

#define ADD(...)                                                  \
	do {                                                      \
		CHECK(n < max);                                   \
		ev[n] = (struct event){ __VA_ARGS__ };            \
		ev[n].time_us = t;                                \
		t += 7919;                                        \
		n++;                                              \
	} while (0)

	ADD(.type = EVENT_PROXIMITY_IN, .x = 640.0, .y = 736.0);
	ADD(.type = EVENT_MOTION, .x = 1.0 / 3.0, .y = 2.0 / 3.0, .pressure = 0.1,
	    .tilt_x = -0.0, .tilt_y = 1e-300);
	ADD(.type = EVENT_TIP_DOWN, .x = 639.99999999999989, .y = 735.5, .pressure = 0.3,
	    .tilt_x = 12.345678901234567, .tilt_y = -45.0);
	ADD(.type = EVENT_MOTION, .x = -12.5, .y = 1e6, .pressure = 1.0, .tilt_x = 90.0,
	    .tilt_y = -90.0);
	ADD(.type = EVENT_MOTION, .x = 5e-324, .y = DBL_MAX, .pressure = DBL_MIN,
	    .tilt_x = nextafter(90.0, 0.0), .tilt_y = 0.1 + 0.2);
	ADD(.type = EVENT_PEN_BUTTON, .x = 700.25, .y = 400.125, .pressure = 0.5,
	    .button = EVENT_PEN_BUTTON_STYLUS, .pressed = true);
	ADD(.type = EVENT_PEN_BUTTON, .x = 700.25, .y = 400.125, .pressure = 0.5,
	    .button = EVENT_PEN_BUTTON_STYLUS2, .pressed = false);
	ADD(.type = EVENT_TIP_UP, .x = 701.0, .y = 399.0);
	ADD(.type = EVENT_PROXIMITY_OUT, .x = 701.0, .y = 399.0);
	ADD(.type = EVENT_PROXIMITY_IN, .tool = EVENT_TOOL_ERASER, .x = 10.0, .y = 20.0,
	    .tilt_x = -30.0, .tilt_y = 30.0);
	ADD(.type = EVENT_TIP_DOWN, .tool = EVENT_TOOL_ERASER, .x = 10.0, .y = 20.0,
	    .pressure = 0.75, .tilt_x = -30.0, .tilt_y = 30.0);
	ADD(.type = EVENT_TIP_UP, .tool = EVENT_TOOL_ERASER, .x = 10.0, .y = 20.0);
	ADD(.type = EVENT_PROXIMITY_OUT, .tool = EVENT_TOOL_ERASER, .x = 10.0, .y = 20.0);
	for (int b = 0; b < BUTTON_COUNT; b++) {
		ADD(.type = EVENT_BUTTON, .button = b, .pressed = true);
		ADD(.type = EVENT_BUTTON, .button = b, .pressed = false);
	}
	t = TRACE_MAX_TIME_US; /* the largest time still parses */
	ADD(.type = EVENT_BUTTON, .button = BUTTON_UNDO, .pressed = true);
#undef ADD
	return n;
}

static void test_round_trip(void)
{
	struct event ev[128];
	size_t n = make_events(ev, 128);
	struct trace t = { 0 };
	struct error err;
	struct buf b;

	buf_init(&b);
	CHECK(buf_printf(&b, "edaha-trace 1\nscreen 1280 800\n") == 0);
	for (size_t i = 0; i < n; i++) {
		char line[TRACE_LINE_MAX];
		int len = trace_format_event(&ev[i], line, sizeof(line));

		CHECK(len > 0 && line[len - 1] == '\n');
		CHECK(buf_append(&b, line, (size_t)len) == 0);
	}
	CHECK(trace_parse_edaha((const char *)b.data, b.len, "rt", 1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, n);
	for (size_t i = 0; i < n; i++) {
		if (!same_event(&t.events[i], &ev[i])) {
			fprintf(stderr, "event %zu differs after the round trip\n", i);
			CHECK(0);
		}
	}
	/* Parsing again replaces the events, it does not append. */
	CHECK(trace_parse((const char *)b.data, b.len, "rt", 1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, n);
	trace_finish(&t);
	buf_finish(&b);
}

static void test_format(void)
{
	struct event ev = { .type = EVENT_MOTION, .time_us = 42, .x = 1.5, .y = 2, .pressure = 0.5,
			    .tilt_x = -3, .tilt_y = 4 };
	char line[TRACE_LINE_MAX];

	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), 29);
	CHECK(strcmp(line, "42 motion pen 1.5 2 0.5 -3 4\n") == 0);
	CHECK_INT(trace_format_event(&ev, line, 10), -ENOSPC);
	ev.type = EVENT_BUTTON;
	ev.button = BUTTON_FIXED_COUNT;
	ev.pressed = true;
	CHECK(trace_format_event(&ev, line, sizeof(line)) > 0);
	CHECK(strcmp(line, "42 button fixed-count pressed\n") == 0);
	ev.button = BUTTON_COUNT;
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_PEN_BUTTON, .button = EVENT_PEN_BUTTON_STYLUS2,
			     .tool = EVENT_TOOL_ERASER, .time_us = 7 };
	CHECK(trace_format_event(&ev, line, sizeof(line)) > 0);
	CHECK(strcmp(line, "7 pen-button stylus2 released eraser 0 0 0 0 0\n") == 0);
	ev.button = 5;
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	/* What the parser would refuse is refused here too. */
	ev = (struct event){ .type = EVENT_MOTION, .x = NAN };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_MOTION, .y = INFINITY };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_MOTION, .pressure = 1.5 };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_MOTION, .tilt_y = -91 };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_MOTION, .tool = 7 };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = 0 };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev = (struct event){ .type = EVENT_BUTTON, .time_us = TRACE_MAX_TIME_US + 1 };
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev.time_us = UINT64_MAX;
	CHECK_INT(trace_format_event(&ev, line, sizeof(line)), -EINVAL);
	ev.time_us = TRACE_MAX_TIME_US;
	CHECK(trace_format_event(&ev, line, sizeof(line)) > 0);
	CHECK(strcmp(line, "4611686018427387904 button 3d released\n") == 0);
	/* The longest line fits TRACE_LINE_MAX. */
	ev = (struct event){ .type = EVENT_PEN_BUTTON, .time_us = TRACE_MAX_TIME_US,
			     .tool = EVENT_TOOL_ERASER, .button = EVENT_PEN_BUTTON_STYLUS2,
			     .x = -DBL_MAX, .y = -DBL_MIN, .pressure = nextafter(0.0, 1.0),
			     .tilt_x = -nextafter(90.0, 0.0), .tilt_y = -89.999999999999986 };
	CHECK(trace_format_event(&ev, line, sizeof(line)) > 0);
}

static void test_scaling(void)
{
	struct trace t = { 0 };
	struct error err;

	CHECK(parse("edaha-trace 1\nscreen 640 400\n"
		    "5 motion pen 320.5 200.25 0.5 10 -10\n",
		    1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, 1);
	CHECK(t.events[0].x == 641.0 && t.events[0].y == 400.5);
	CHECK(t.events[0].pressure == 0.5 && t.events[0].tilt_x == 10 && t.events[0].tilt_y == -10);
	/* Per axis: only the height differs here. */
	CHECK(parse("edaha-trace 1\nscreen 1280 1024\n"
		    "5 motion pen 0.1 512 0.5 0 0\n"
		    "6 button new pressed\n",
		    1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, 2);
	CHECK(same_double(t.events[0].x, 0.1));
	CHECK(t.events[0].y == 400.0);
	CHECK(t.events[1].type == EVENT_BUTTON && t.events[1].button == BUTTON_NEW &&
	      t.events[1].pressed);
	CHECK(parse("edaha-trace 1\nscreen 1920 1080\n5 tip-down eraser 1920 1080 1 0 0\n", 1280,
		    800, &t, &err) == 0);
	CHECK_NEAR(t.events[0].x, 1280.0, 1e-9);
	CHECK_NEAR(t.events[0].y, 800.0, 1e-9);
	CHECK(t.events[0].tool == EVENT_TOOL_ERASER);
	trace_finish(&t);
}

static void test_accepts(void)
{
	struct trace t = { 0 };
	struct error err;
	struct buf b;

	/* Comments, blank lines, CRLF, tabs and leading blanks. */
	CHECK(parse("\n# recorded by hand\n  \r\n\tedaha-trace 1\r\n# screen next\r\n"
		    "screen\t1280 800\r\n\r\n  # a comment\n"
		    "10\tproximity-in   pen 1 2 0 0 0\r\n"
		    "10 tip-down pen 1 2 +0.5 0 0\n"
		    "20 motion pen 1e1 2E1 .25 -1.5e1 0.\n"
		    "20 tip-up pen 1 2 0 0 0",
		    1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, 4);
	CHECK(t.events[0].type == EVENT_PROXIMITY_IN && t.events[0].time_us == 10);
	CHECK(t.events[1].pressure == 0.5);
	CHECK(t.events[2].x == 10 && t.events[2].y == 20 && t.events[2].pressure == 0.25 &&
	      t.events[2].tilt_x == -15);
	CHECK(t.events[3].type == EVENT_TIP_UP);

	/* A byte order mark, as some editors write. */
	CHECK(trace_parse("\xef\xbb\xbf" "edaha-trace 1\nscreen 9 9\n1 button 3d pressed\n", 48, "bom",
			  9, 9, &t, &err) == 0);
	CHECK_INT(t.nevents, 1);

	/* Only the header and screen: a valid, empty trace. */
	CHECK(parse("edaha-trace 1\nscreen 1 1\n", 1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, 0);

	/* Lines have no length limit. */
	buf_init(&b);
	CHECK(buf_printf(&b, "edaha-trace 1\nscreen 1280 800\n#") == 0);
	for (int i = 0; i < 100000; i++)
		CHECK(buf_append(&b, "x", 1) == 0);
	CHECK(buf_printf(&b, "\n5 motion pen") == 0);
	for (int i = 0; i < 100000; i++)
		CHECK(buf_append(&b, " ", 1) == 0);
	CHECK(buf_printf(&b, "12.5 13 0 0 0\n6 motion pen 1 2 0 0 0") == 0);
	for (int i = 0; i < 300000; i++)
		CHECK(buf_append(&b, "0", 1) == 0);
	CHECK(buf_printf(&b, "\n") == 0);
	CHECK(trace_parse((const char *)b.data, b.len, "long", 1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, 2);
	CHECK(t.events[0].x == 12.5 && t.events[1].tilt_y == 0.0);
	buf_finish(&b);
	trace_finish(&t);
}

struct bad {
	const char *text;
	unsigned line;
	const char *msg;
};

static const struct bad bad_inputs[] = {
	{ "", 0, "empty file" },
	{ "# nothing\n\n", 0, "empty file" },
	{ "edaha-trace\n", 1, "version is missing" },
	{ "edaha-trace 2\nscreen 1 1\n", 1, "unsupported trace version 2 (this edaha reads 1)" },
	{ "# hi\nedaha-trace 10\n", 2, "unsupported trace version 10" },
	{ "edaha-trace x1\n", 1, "bad trace version \"x1\"" },
	{ "edaha-trace 1 2\n", 1, "trailing \"2\"" },
	{ "edaha-tracer 1\n", 1, "not an edaha trace" },
	{ "edaha-trace 1\n", 1, "missing \"screen W H\"" },
	{ "edaha-trace 1\n5 motion pen 1 2 0 0 0\n", 2, "expected \"screen W H\" after the header" },
	{ "edaha-trace 1\nscreen 1280\n", 2, "expected 3 fields for screen, got 2" },
	{ "edaha-trace 1\nscreen 0 800\n", 2, "bad screen width \"0\"" },
	{ "edaha-trace 1\nscreen 1280 -800\n", 2, "bad screen height \"-800\"" },
	{ "edaha-trace 1\nscreen 1280 99999999999999999999999\n", 2, "bad screen height" },
	{ "edaha-trace 1\nscreen 1280 800\nscreen 1280 800\n", 3, "\"screen\" may only appear once" },
	{ "edaha-trace 1\nscreen 1280 800\n\n\n5 motion pen 1 2\n", 5,
	  "expected 8 fields for motion, got 5" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 0 0 0 0\n", 3,
	  "expected 8 fields for motion, got 9 (trailing \"0\")" },
	{ "edaha-trace 1\nscreen 1280 800\n5 tip-down pen 1 2 0 0 0 # x\n", 3, "trailing \"#\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5\n", 3, "got 1 field" },
	{ "edaha-trace 1\nscreen 1280 800\n5 hover pen 1 2 0 0 0\n", 3, "unknown event \"hover\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5 Motion pen 1 2 0 0 0\n", 3, "unknown event \"Motion\"" },
	{ "edaha-trace 1\nscreen 1280 800\n-5 motion pen 1 2 0 0 0\n", 3, "bad time \"-5\"" },
	{ "edaha-trace 1\nscreen 1280 800\n+5 motion pen 1 2 0 0 0\n", 3, "bad time \"+5\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5.0 motion pen 1 2 0 0 0\n", 3, "bad time \"5.0\"" },
	{ "edaha-trace 1\nscreen 1280 800\n0x10 motion pen 1 2 0 0 0\n", 3, "bad time" },
	{ "edaha-trace 1\nscreen 1280 800\n18446744073709551616 motion pen 1 2 0 0 0\n", 3,
	  "bad time" },
	/* Past 2^62 us: a replay adds gaps to times and must not overflow. */
	{ "edaha-trace 1\nscreen 1280 800\n4611686018427387905 motion pen 1 2 0 0 0\n", 3,
	  "time 4611686018427387905 too large (limit 4611686018427387904 us)" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 0 0 0\n18446744073709551615 button new "
	  "pressed\n", 4, "time 18446744073709551615 too large" },
	{ "edaha-trace 1\nscreen 1280 800\n04611686018427387905 hover\n", 3, "too large" },
	{ "edaha-trace 1\nscreen 1280 800\n1300 motion pen 1 2 0 0 0\n1200 motion pen 1 2 0 0 0\n", 4,
	  "time goes backwards (1200 < 1300)" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pencil 1 2 0 0 0\n", 3, "unknown tool \"pencil\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1,5 2 0 0 0\n", 3, "bad number \"1,5\" for x" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2x 0 0 0\n", 3, "bad number \"2x\" for y" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 0x10 2 0 0 0\n", 3, "bad number \"0x10\" for x" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen nan 2 0 0 0\n", 3,
	  "x \"nan\" is not a finite number" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 -inf 0 0 0\n", 3,
	  "y \"-inf\" is not a finite number" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 NAN 0 0\n", 3, "not a finite number" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1e999 2 0 0 0\n", 3, "not a finite number" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 1.7 0 0\n", 3,
	  "pressure 1.7 out of range 0..1" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 -0.01 0 0\n", 3,
	  "pressure -0.01 out of range 0..1" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 0 90.5 0\n", 3,
	  "tilt_x 90.5 out of range -90..90" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 0 0 -91\n", 3,
	  "tilt_y -91 out of range -90..90" },
	{ "edaha-trace 1\nscreen 1280 800\n5 button 3D pressed\n", 3,
	  "unknown button \"3D\" (valid: 3d clone leaf propagate undo redo export new fixed-count "
	  "fixed-size view season tpl-blank" },
	/* the list goes on to the last name */
	{ "edaha-trace 1\nscreen 1280 800\n5 button 3D pressed\n", 3, " leaf-maple vine grow)" },
	{ "edaha-trace 1\nscreen 1280 800\n5 button undo down\n", 3,
	  "expected pressed or released, got \"down\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5 button undo\n", 3, "expected 4 fields for button, got 3" },
	{ "edaha-trace 1\nscreen 1280 800\n5 button undo pressed now\n", 3, "trailing \"now\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5 pen-button stylus pressed pen 1 2 0 0\n", 3,
	  "expected 10 fields for pen-button, got 9" },
	{ "edaha-trace 1\nscreen 1280 800\n5 pen-button stylus3 pressed pen 1 2 0 0 0\n", 3,
	  "unknown pen button \"stylus3\"" },
	{ "edaha-trace 1\nscreen 1280 800\n5 pen-button stylus on pen 1 2 0 0 0\n", 3,
	  "expected pressed or released" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen \x01\xff 2 0 0 0\n", 3,
	  "bad number \"\\x01\\xff\" for x" },
	{ "edaha-trace 1\nscreen 1280 800\n5 motion pen 1 2 0 0 0\n\n# end\n6 motion pen 1 2 0 0 0 \r\r\n", 6,
	  "trailing \"\\x0d\"" },
	{ "edaha-trace 1\nscreen 1280 800\nedaha-trace 1\n", 3, "may only appear once" },
	{ "edaha-trace 1\nscreen 1 800\n5 motion pen 1e308 2 0 0 0\n", 3,
	  "position 1e308 2 out of range on a 1280x800 screen" },
};

static void check_error(const char *what, int r, const struct error *err, const struct trace *t,
			unsigned line, const char *msg)
{
	char prefix[64];

	if (line)
		snprintf(prefix, sizeof(prefix), "t.trace:%u: ", line);
	else
		snprintf(prefix, sizeof(prefix), "t.trace: ");
	if (r != -EINVAL || strncmp(err->msg, prefix, strlen(prefix)) != 0 ||
	    !strstr(err->msg, msg) || t->nevents != 0 || t->events) {
		fprintf(stderr, "input %s\n  r = %d, message: %s\n  wanted prefix \"%s\" and \"%s\"\n",
			what, r, err->msg, prefix, msg);
		CHECK(0);
	}
}

static void test_errors(void)
{
	for (size_t i = 0; i < sizeof(bad_inputs) / sizeof(bad_inputs[0]); i++) {
		const struct bad *b = &bad_inputs[i];
		struct trace t = { 0 };
		struct error err = { { 0 } };
		char what[32];
		int r;

		/* Start from a full trace: a failure must leave it empty. */
		CHECK(parse("edaha-trace 1\nscreen 1 1\n1 motion pen 1 1 0 0 0\n", 1, 1, &t, &err) == 0);
		CHECK_INT(t.nevents, 1);
		snprintf(what, sizeof(what), "#%zu", i);
		r = trace_parse_edaha(b->text, strlen(b->text), "t.trace", 1280, 800, &t, &err);
		check_error(what, r, &err, &t, b->line, b->msg);
	}
}

static void test_nul_and_screen_args(void)
{
	static const char nul[] = "edaha-trace 1\nscreen 1280 800\n5 motion pen 1\0 2 0 0 0\n";
	struct trace t = { 0 };
	struct error err;
	int r;

	r = trace_parse_edaha(nul, sizeof(nul) - 1, "t.trace", 1280, 800, &t, &err);
	check_error("NUL", r, &err, &t, 3, "NUL byte");
	r = trace_parse_edaha("edaha-trace 1\nscreen 1 1\n", 25, "t.trace", 0, 800, &t, &err);
	check_error("screen 0", r, &err, &t, 0, "bad screen size 0x800");
	r = trace_parse_edaha(NULL, 0, "t.trace", 1280, 800, &t, &err);
	check_error("NULL", r, &err, &t, 0, "empty file");
}

static void test_dispatch(void)
{
	static const char hand[] =
		"\n\n# made by hand\n  edaha-trace 1\nscreen 10 10\n1 motion pen 1 1 0 0 0\n";
	struct trace t = { 0 };
	struct error err;
	int r;

	CHECK(trace_parse(hand, strlen(hand), "x", 10, 10, &t, &err) == 0);
	CHECK_INT(t.nevents, 1);
	r = trace_parse("  \n# only a comment\n", 20, "t.trace", 1280, 800, &t, &err);
	check_error("empty", r, &err, &t, 0, "empty file");
	/* Anything else goes to the libinput importer, which names its own problem. */
	r = trace_parse("hello\n", 6, "t.trace", 1280, 800, &t, &err);
	check_error("hello", r, &err, &t, 1, "libinput");
	trace_finish(&t);
}

static char *temp_dir(void)
{
	const char *tmp = getenv("TMPDIR");
	char *dir;

	if (!tmp || !*tmp)
		tmp = "/tmp";
	dir = malloc(strlen(tmp) + 32);
	CHECK(dir);
	sprintf(dir, "%s/edaha-trace-XXXXXX", tmp);
	CHECK(mkdtemp(dir));
	return dir;
}

static void test_writer_and_load(void)
{
	struct event ev[128];
	size_t n = make_events(ev, 128);
	char *dir = temp_dir();
	char path[512], missing[512], big[512];
	struct trace_writer *w;
	struct trace t = { 0 };
	struct error err;
	struct event e;
	int fd, r;

	snprintf(path, sizeof(path), "%s/rec.edaha-trace", dir);
	w = trace_writer_create(path, 1280, 800, &err);
	CHECK(w);
	for (size_t i = 0; i < n; i++)
		CHECK(trace_writer_write(w, &ev[i]) == 0);
	CHECK(trace_writer_destroy(w) == 0);
	CHECK(trace_load(path, 1280, 800, &t, &err) == 0);
	CHECK_INT(t.nevents, n);
	for (size_t i = 0; i < n; i++)
		CHECK(same_event(&t.events[i], &ev[i]));

	/* The writer keeps a recording readable: clamps, or refuses what it cannot fix. */
	w = trace_writer_create(path, 1280, 800, &err);
	CHECK(w);
	e = (struct event){ .type = EVENT_MOTION, .time_us = 500, .pressure = 1.0000001,
			    .tilt_x = -90.5 };
	CHECK(trace_writer_write(w, &e) == 0);
	e.time_us = 400; /* another clock, a little behind */
	e.pressure = -1e-9;
	CHECK(trace_writer_write(w, &e) == 0);
	e.x = NAN;
	CHECK_INT(trace_writer_write(w, &e), -EINVAL);
	e = (struct event){ .type = EVENT_BUTTON, .time_us = UINT64_MAX, .pressed = true };
	CHECK(trace_writer_write(w, &e) == 0); /* past the limit: stops there */
	CHECK(trace_writer_destroy(w) == 0);
	CHECK(trace_writer_destroy(NULL) == 0);
	CHECK(trace_load(path, 640, 400, &t, &err) == 0);
	CHECK_INT(t.nevents, 3);
	CHECK(t.events[0].pressure == 1.0 && t.events[0].tilt_x == -90.0);
	CHECK(t.events[1].time_us == 500 && t.events[1].pressure == 0.0);
	CHECK(t.events[2].time_us == TRACE_MAX_TIME_US && t.events[2].type == EVENT_BUTTON);

	/* I/O errors name the file and carry -errno. */
	snprintf(missing, sizeof(missing), "%s/nope/rec.edaha-trace", dir);
	CHECK(trace_writer_create(missing, 1280, 800, &err) == NULL);
	CHECK(strncmp(err.msg, missing, strlen(missing)) == 0);
	CHECK(strstr(err.msg, ": No such file or directory"));
	CHECK(trace_writer_create(path, 0, 800, &err) == NULL);
	snprintf(missing, sizeof(missing), "%s/missing.edaha-trace", dir);
	CHECK_INT(trace_load(missing, 1280, 800, &t, &err), -ENOENT);
	CHECK(strncmp(err.msg, missing, strlen(missing)) == 0);
	CHECK(strcmp(err.msg + strlen(missing), ": No such file or directory") == 0);
	CHECK(t.nevents == 0 && !t.events);
	CHECK_INT(trace_load(dir, 1280, 800, &t, &err), -EISDIR);
	CHECK(strstr(err.msg, ": Is a directory"));

	/* Too large: a sparse file, so the test costs nothing. */
	snprintf(big, sizeof(big), "%s/big.edaha-trace", dir);
	fd = open(big, O_WRONLY | O_CREAT | O_TRUNC, 0644);
	CHECK(fd >= 0);
	CHECK(ftruncate(fd, (off_t)256 * 1024 * 1024 + 1) == 0);
	close(fd);
	r = trace_load(big, 1280, 800, &t, &err);
	CHECK_INT(r, -EFBIG);
	CHECK(strstr(err.msg, "too large"));
	CHECK(strncmp(err.msg, big, strlen(big)) == 0);

	/* A file error is reported like a parse error, with the path as the name. */
	fd = open(path, O_WRONLY | O_TRUNC);
	CHECK(fd >= 0);
	CHECK(write(fd, "edaha-trace 1\nscreen 9 9\n1 jump\n", 32) == 32);
	close(fd);
	CHECK_INT(trace_load(path, 1280, 800, &t, &err), -EINVAL);
	CHECK(strncmp(err.msg, path, strlen(path)) == 0);
	CHECK(strcmp(err.msg + strlen(path), ":3: unknown event \"jump\" (valid: proximity-in "
			"proximity-out tip-down tip-up motion pen-button button)") == 0);

	CHECK(unlink(big) == 0);
	CHECK(unlink(path) == 0);
	CHECK(rmdir(dir) == 0);
	free(dir);
	trace_finish(&t);
}

static double dist(const struct event *a, const struct event *b)
{
	return hypot(a->x - b->x, a->y - b->y);
}

/* The README demo: a believable child's tree. */
static void test_demo(void)
{
	char path[1024];
	struct trace t = { 0 };
	struct error err;
	size_t strokes = 0, loops = 0, branches_on_tree = 0, first_down = 0;
	size_t down_at[32];

	snprintf(path, sizeof(path), "%s/demo.edaha-trace", data_dir);
	if (trace_load(path, 1280, 800, &t, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
	CHECK(t.nevents > 200);
	for (size_t i = 0; i < t.nevents; i++) {
		const struct event *e = &t.events[i];

		CHECK(e->type != EVENT_BUTTON);
		if (i > 0)
			CHECK(e->time_us >= t.events[i - 1].time_us);
		if (e->type == EVENT_TIP_DOWN) {
			CHECK(strokes < 32);
			down_at[strokes++] = i;
			CHECK(i > 0 && t.events[i - 1].type == EVENT_MOTION);
		}
		if (e->type == EVENT_MOTION && i > 0 && t.events[i - 1].type != EVENT_PROXIMITY_IN &&
		    t.events[i - 1].type != EVENT_TIP_UP) {
			/* ~8 ms apart while drawing, pressure 0.3..0.8 */
			CHECK(e->time_us - t.events[i - 1].time_us >= 7000);
			CHECK(e->time_us - t.events[i - 1].time_us <= 9000);
			CHECK(e->pressure >= 0.3 && e->pressure <= 0.8);
		}
		if (e->type == EVENT_TIP_UP) {
			const struct event *d = &t.events[down_at[strokes - 1]];

			CHECK(i + 2 < t.nevents);
			CHECK(t.events[i + 1].type == EVENT_MOTION);
			CHECK(t.events[i + 2].type == EVENT_PROXIMITY_OUT);
			if (dist(d, e) < 1e-6 && i - down_at[strokes - 1] > 10)
				loops++;
		}
	}
	CHECK(strokes >= 8 && strokes <= 11);
	CHECK(loops >= 3 && loops <= 4);
	/* The trunk: from the ground at the centre upwards to about y 330. */
	first_down = down_at[0];
	CHECK_NEAR(t.events[first_down].x, 640, 1);
	CHECK_NEAR(t.events[first_down].y, 736, 1);
	/* Every later non-loop stroke starts on or near something already drawn. */
	for (size_t s = 1; s < strokes; s++) {
		const struct event *start = &t.events[down_at[s]];
		double best = 1e9;

		for (size_t i = 0; i < down_at[s]; i++)
			if (t.events[i].type == EVENT_MOTION && t.events[i].pressure > 0)
				best = fmin(best, dist(&t.events[i], start));
		if (best < 6.0)
			branches_on_tree++;
	}
	CHECK(branches_on_tree >= 4);
	trace_finish(&t);
}

int main(int argc, char **argv)
{
	if (argc > 1)
		data_dir = argv[1];
	test_format();
	test_round_trip();
	test_scaling();
	test_accepts();
	test_errors();
	test_nul_and_screen_args();
	test_dispatch();
	test_writer_and_load();
	test_demo();
	return 0;
}
