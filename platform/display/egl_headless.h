/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "error.h"

/*
 * A GLES context on Mesa's surfaceless EGL platform rendering into an offscreen
 * framebuffer of a fixed size: what --headless, the tests and the benchmarks draw into.
 */
struct egl_headless;

/* Makes the context current with its framebuffer bound. NULL on failure (err says why). */
struct egl_headless *egl_headless_create(int width, int height, struct error *err);
void egl_headless_destroy(struct egl_headless *e);
/* Reads the framebuffer as RGBA, top row first, into rgba (width*height*4 bytes). 0 or -EIO. */
int egl_headless_read_rgba(struct egl_headless *e, uint8_t *rgba);
