/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "buf.h"
#include "error.h"

/* RGBA8 images, top row first. Encoding is deterministic (no time chunks). */
int pngio_encode_rgba(const uint8_t *rgba, int width, int height, struct buf *out, struct error *err);
/* Decodes any PNG into RGBA8; *rgba is malloc'ed. 0, -EINVAL (not a PNG / damaged) or -ENOMEM. */
int pngio_decode_rgba(const void *data, size_t len, const char *name, uint8_t **rgba, int *width,
		    int *height, struct error *err);
