/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "error.h"
#include "event.h"

/*
 * Recorded input. Two kinds are read: edaha's own trace format (docs/trace-format.md)
 * and `libinput record` YAML (version 1). Both become the same struct event sequence,
 * with positions in pixels of a screen of the size given to the parser.
 */
/*
 * Event times above this (2^62 us, some 146,000 years) are refused by the parsers, so that
 * whoever replays a trace can add gaps and offsets to its times without overflowing.
 */
#define TRACE_MAX_TIME_US ((uint64_t)1 << 62)

struct trace {
	struct event *events;
	size_t nevents, cap;
};

void trace_init(struct trace *t);
void trace_finish(struct trace *t);
int trace_append(struct trace *t, const struct event *ev); /* 0 or -ENOMEM */

/* All parsers: name is used in messages ("name:line: ..."); 0, -EINVAL or -ENOMEM.
 * *t must be initialised (trace_init or zeroed); its old events are replaced.
 * On failure *t holds no events and nothing leaks. */
int trace_parse_edaha(const char *data, size_t len, const char *name, int screen_w,
		      int screen_h, struct trace *t, struct error *err);
int trace_parse_libinput(const char *data, size_t len, const char *name, int screen_w,
			 int screen_h, struct trace *t, struct error *err);
/* Picks the parser from the content ("edaha-trace" first line, or libinput record YAML). */
int trace_parse(const char *data, size_t len, const char *name, int screen_w, int screen_h,
		struct trace *t, struct error *err);
/* Reads a file and parses it; -errno for I/O errors, -EFBIG past 256 MiB. */
int trace_load(const char *path, int screen_w, int screen_h, struct trace *t, struct error *err);

/* Writes edaha traces (--record). Times that go backwards or past TRACE_MAX_TIME_US and
 * pressure/tilt a hair out of range are clamped so the file always reads back;
 * non-finite positions give -EINVAL. */
struct trace_writer;
struct trace_writer *trace_writer_create(const char *path, int screen_w, int screen_h,
					 struct error *err);
int trace_writer_write(struct trace_writer *w, const struct event *ev);
/* Flushes and closes; returns 0 or -errno of the first failure. */
int trace_writer_destroy(struct trace_writer *w);
/* The same line format into a memory buffer (tests, fuzzers), '\n' included: returns
 * its length, -EINVAL for an event the parser would refuse, -ENOSPC if size is too small.
 * TRACE_LINE_MAX always suffices. */
#define TRACE_LINE_MAX 256
int trace_format_event(const struct event *ev, char *line, size_t size);
