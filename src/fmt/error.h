/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * A message for the person who fed us bad input: "FILE:LINE: what is wrong".
 * Functions that can fail on input return a negative errno and fill one of these.
 */
struct error {
	char msg[512];
};

/* Formats msg and returns code, so callers can write `return error_set(...)`. */
int error_set(struct error *err, int code, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* Same, prefixed with "name:line: " (line 0 means "name: "). */
int error_at(struct error *err, int code, const char *name, unsigned long line,
	     const char *fmt, ...) __attribute__((format(printf, 5, 6)));
