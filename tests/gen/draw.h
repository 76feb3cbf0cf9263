/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "shape.h"

/*
 * What the property tests that draw random parameter files share (test_shrub_fill.c,
 * test_gen_version.c): a seeded sequence of their own (splitmix64, not the generator's
 * rng.c, so that the files do not move when the generator's draws do), and the file's text
 * written a key at a time. Every failure exits as test.h's CHECK does.
 */

/* The next number of the sequence whose state is *s. */
uint64_t draw_mix(uint64_t *s);
/* Uniform in [0, 1). */
double draw_uni(uint64_t *s);
/* Uniform in [lo, hi). */
double draw_span(uint64_t *s, double lo, double hi);
/* Log-uniform in [lo, hi): small and large alike. */
double draw_logspan(uint64_t *s, double lo, double hi);

/* Appends printf-formatted text to the file's text (yaml, of size bytes); it must fit. */
void draw_put(char *yaml, size_t size, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* Appends the shrub's clip: line for shape sh. */
void draw_put_clip(char *yaml, size_t size, const struct shape *sh);
