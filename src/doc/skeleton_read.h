/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "error.h"
#include "tree.h"

/* The most skeleton_read takes: far above a 10,000-branch tree's file. */
#define SKELETON_READ_MAX_BYTES (64u << 20)

/*
 * Reads a skeleton.json (docs/skeleton-format.md, versions 1 and 2) from memory: its
 * `branches` only (leaves, vines and any other key are ignored), as `--skeleton` starts
 * from (docs/wood.md, "Starting from a skeleton"). Strict: `format` "edaha-skeleton",
 * `version` 1 or 2, ids 0..n-1 in order, each parent -1 or an earlier id, parent_t in
 * 0..1, generation 0..1000, 2 to DOC_MAX_STROKE_POINTS points of 3 numbers within
 * +-DOC_MAX_COORD_M, as many radii within 0..DOC_MAX_COORD_M, every number finite, at most
 * TREE_MAX_BRANCHES branches and DOC_MAX_POINTS points in all: what an import op holds and
 * a drawing reads back. Every branch's origin is ORIGIN_SKETCH and its level 0 (an import
 * op keeps neither). out is an initialised tree; on success it holds just those branches
 * (what it had is freed), unlifted. name is the file's name for messages.
 * 0, or -EINVAL/-ENOMEM with err "NAME:LINE: what is wrong" (out untouched): LINE is the
 * line of a syntax error, or of the offending value (a missing key: its object's "{").
 */
int skeleton_read(const char *data, size_t len, const char *name, struct tree *out,
		  struct error *err);
