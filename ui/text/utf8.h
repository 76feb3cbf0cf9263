/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

/* What a malformed sequence decodes to. */
#define UTF8_REPLACEMENT 0xfffdu

/*
 * Decodes the code point at s[*pos] (of len bytes; *pos < len), moves *pos past it and
 * returns it. A byte that does not start a well-formed sequence (overlong, a surrogate,
 * past U+10FFFF, cut short) gives U+FFFD and moves one byte, so decoding always ends.
 */
uint32_t utf8_next(const char *s, size_t len, size_t *pos);
