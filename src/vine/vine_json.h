/* SPDX-License-Identifier: MIT */
#pragma once

#include "buf.h"
#include "tree.h"
#include "vine.h"

/*
 * skeleton.json with a "vines" section (docs/skeleton-format.md, "Vines"): tree t's
 * skeleton as export_skeleton writes it (an empty tree: the keys with nothing in them),
 * its "vines" the vines given, in place of t's own: per vine its parameters (every key of
 * a vine file, docs/vine-format.md), its planting point, its shoots (raw and smoothed
 * axes, the points touching the support, whether it stopped) and its leaves. Numbers as
 * skeleton.json writes them (micrometres). Appends to out: 0 or -ENOMEM (out as it was).
 * Same vines, same bytes. What `edaha --support` writes.
 */
int vine_skeleton(const struct tree *t, const struct vine *vines, size_t nvines, struct buf *out);

struct json_object;
/* Sets root's "vines" to that section for the vines given (export_skeleton_object's for a
 * tree's own): json_out's way, root back, or NULL without memory (root freed; a NULL root
 * gives NULL). */
struct json_object *vine_json_set(struct json_object *root, const struct vine *vines,
				  size_t nvines);
