/* SPDX-License-Identifier: MIT */
#pragma once

/* Helpers shared by the trace readers and the writer; not part of the trace API. */

#include <stddef.h>

/* Room for a quoted field cut short: some 50 characters of text, escapes included. */
#define TRACE_QUOTE_SIZE 64

/*
 * Quotes len bytes of s for an error message: printable ASCII as is, other bytes (NUL
 * included) as \xNN, cut with "..." to fit size (at least 16). Returns buf.
 */
const char *trace_quote(const char *s, size_t len, char *buf, size_t size);

/* trace_quote() into a buffer that lives until the end of the enclosing block: fine as
 * a printf argument. */
#define TRACE_Q(s, len) trace_quote((s), (len), (char[TRACE_QUOTE_SIZE]){ 0 }, TRACE_QUOTE_SIZE)

/* v limited to lo..hi; NaN stays NaN, so that callers still refuse it. */
double trace_clamp(double v, double lo, double hi);
