/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

/*
 * Decimal text for exported numbers without printf: rounded to micrometres (6 decimals)
 * by integer arithmetic, so it is exact, fast (a tree has ~10^5 numbers) and needs no
 * locale. Never "-0". Values beyond +-1e12 are clamped, non-finite ones become 0 (the
 * model holds neither).
 */
#define NUMFMT_MAX 32

/* trim: "0.1" and "2" rather than "0.100000" and "2.000000". Returns the length written
 * to out (at most NUMFMT_MAX - 1; out is NUL-terminated). */
size_t numfmt_micro(char out[NUMFMT_MAX], double v, bool trim);

/* Shared by every exporter so the bark and leaves look the same in every format. */
#define MATERIAL_BARK_RGB 0.33, 0.22, 0.13
#define MATERIAL_LEAVES_RGB 0.24, 0.52, 0.16
/* A vine's stems: the screen's stem green (ui/render_vine.c), darker and yellower than the
 * leaves. */
#define MATERIAL_VINE_RGB 0.30, 0.45, 0.16
