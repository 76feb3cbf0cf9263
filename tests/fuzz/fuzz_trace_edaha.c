/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the edaha trace parser on arbitrary bytes. Whatever it accepts must write
 * back out (trace_format_event) and parse again to the very same events.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "trace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static bool same(const struct event *a, const struct event *b)
{
	return a->type == b->type && a->time_us == b->time_us && a->tool == b->tool &&
	       memcmp(&a->x, &b->x, sizeof(a->x)) == 0 && memcmp(&a->y, &b->y, sizeof(a->y)) == 0 &&
	       memcmp(&a->pressure, &b->pressure, sizeof(a->pressure)) == 0 &&
	       memcmp(&a->tilt_x, &b->tilt_x, sizeof(a->tilt_x)) == 0 &&
	       memcmp(&a->tilt_y, &b->tilt_y, sizeof(a->tilt_y)) == 0 && a->button == b->button &&
	       a->pressed == b->pressed;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct trace t = { 0 }, again = { 0 };
	struct error err;
	struct buf b;

	if (trace_parse_edaha((const char *)data, size, "fuzz", 1280, 800, &t, &err) < 0) {
		if (t.nevents || t.events)
			abort(); /* a failure must leave the trace empty */
		return 0;
	}
	buf_init(&b);
	if (buf_printf(&b, "edaha-trace 1\nscreen 1280 800\n") < 0)
		abort();
	for (size_t i = 0; i < t.nevents; i++) {
		char line[TRACE_LINE_MAX];
		int n = trace_format_event(&t.events[i], line, sizeof(line));

		if (n < 0 || buf_append(&b, line, (size_t)n) < 0)
			abort(); /* everything parsed must be writable */
	}
	if (trace_parse_edaha((const char *)b.data, b.len, "again", 1280, 800, &again, &err) < 0 ||
	    again.nevents != t.nevents)
		abort();
	for (size_t i = 0; i < t.nevents; i++)
		if (!same(&t.events[i], &again.events[i]))
			abort();
	trace_finish(&again);
	trace_finish(&t);
	buf_finish(&b);
	return 0;
}
