/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What the fuzz targets of the file readers check of a refusal: the message names the file
 * ("fuzz") and a line of the input ("fuzz:LINE: what"; running out of memory may name the
 * file alone), and the code is -EINVAL or -ENOMEM. abort() otherwise, for libFuzzer.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"

static inline bool fuzz_line_break(uint8_t c)
{
	return c == '\n' || c == '\r' || c == 0x85 || c == 0xa8 || c == 0xa9;
}

/* A bound on the input's lines: YAML breaks lines at \n, \r and three Unicode breaks
 * (U+0085, U+2028, U+2029, whose UTF-8 ends in one of these bytes); JSON at \n alone. */
static inline unsigned long fuzz_lines_of(const uint8_t *data, size_t size)
{
	unsigned long n = 1;

	for (size_t i = 0; i < size; i++)
		n += fuzz_line_break(data[i]);
	return n;
}

static inline void fuzz_check_refusal(int ret, const struct error *err, unsigned long lines)
{
	const char *s = err->msg + strlen("fuzz:");
	unsigned long line = 0;

	if (ret != -EINVAL && ret != -ENOMEM)
		abort();
	if (strncmp(err->msg, "fuzz:", 5) != 0 || !memchr(err->msg, '\0', sizeof(err->msg)))
		abort();
	if (*s == ' ' && ret == -ENOMEM)
		return;
	if (*s < '1' || *s > '9')
		abort();
	while (*s >= '0' && *s <= '9' && line <= lines)
		line = line * 10 + (unsigned long)(*s++ - '0');
	if (s[0] != ':' || s[1] != ' ' || line > lines)
		abort();
}
