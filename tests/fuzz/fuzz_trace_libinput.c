/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the `libinput record` importer on arbitrary bytes. Whatever it accepts must
 * be events an edaha trace can hold: finite, in range, in time order.
 */
#include <stdint.h>
#include <stdlib.h>

#include "trace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct trace t = { 0 };
	struct error err;

	if (trace_parse_libinput((const char *)data, size, "fuzz", 1280, 800, &t, &err) < 0) {
		if (t.nevents || t.events)
			abort(); /* a failure must leave the trace empty */
		return 0;
	}
	for (size_t i = 0; i < t.nevents; i++) {
		const struct event *e = &t.events[i];
		char line[TRACE_LINE_MAX];

		if (trace_format_event(e, line, sizeof(line)) < 0)
			abort();
		if (i > 0 && e->time_us < t.events[i - 1].time_us)
			abort();
		if (e->type == EVENT_BUTTON)
			abort(); /* mode buttons never come from a pen recording */
	}
	trace_finish(&t);
	return 0;
}
