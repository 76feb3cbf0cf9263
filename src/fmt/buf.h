/* SPDX-License-Identifier: MIT */
/*
 * src/fmt/ (floor 1 of src/FLOORS): growable byte buffers (this header), errors at
 * FILE:LINE, number formatting, JSON out and the YAML reader. Includes no other folder.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* A growable byte buffer: exporters and serialisers write into one, platform/ writes it out. */
struct buf {
	unsigned char *data;
	size_t len;
	size_t cap;
	bool failed; /* an allocation failed; further appends are no-ops */
};

void buf_init(struct buf *b);
void buf_finish(struct buf *b);
void buf_reset(struct buf *b);
/* All appends return 0 or -ENOMEM (and set failed). */
int buf_reserve(struct buf *b, size_t extra);
int buf_append(struct buf *b, const void *data, size_t len);
int buf_append_u32le(struct buf *b, uint32_t v);
int buf_append_f32le(struct buf *b, float v);
int buf_printf(struct buf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* v as the shortest of %.15g..%.17g that strtod reads back as exactly v (parameter files
 * that a drawing stores on a line). */
int buf_print_exact(struct buf *b, double v);
/* Pads with byte `fill` until len is a multiple of `align`. */
int buf_pad(struct buf *b, size_t align, unsigned char fill);
