/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "buf.h"
#include "options.h"

struct render;

/*
 * What the runs that show one object alone share (edaha --headless --leaf, --support):
 * naming a preset, the picture, and writing the files all or none.
 */

/* Exit status for a failure to read input: the input's fault (2) or the machine's (1). */
int headless_input_status(int err);
/* Whether arg is one of the n preset names. */
bool headless_is_preset(const char *const *names, size_t n, const char *arg);
/* A name that is no preset and nothing on disk (most likely a preset misspelt): says so
 * on stderr, listing the presets, "edaha: OPT "ARG": no such WHAT preset or file
 * (presets: ...)". Returns the exit status, 2. */
int headless_no_such_preset(const char *opt, const char *what, const char *arg,
			    const char *const *names, size_t n);
/* The labels' font and language (--lang) for a headless screen: 0, or a negative errno
 * with stderr saying why (a screen without its words would be wrong). */
int headless_set_text(struct render *render, const struct options *o);
/* The picture draw() makes (o->width x o->height, headless GL) as a PNG in png. 0, or 1
 * with stderr saying why. */
int headless_one_picture(const struct options *o,
			 int (*draw)(struct render *r, const void *ctx, int width, int height),
			 const void *ctx, struct buf *png);
/* files[i] as names[i] in dir (made if missing), each atomically. 0, or 1 with stderr
 * naming the file. */
int headless_one_write(const char *dir, const char *const *names, const struct buf *files,
		       size_t n);
