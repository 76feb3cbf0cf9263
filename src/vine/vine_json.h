/* SPDX-License-Identifier: MIT */
#pragma once

#include "buf.h"
#include "tree.h"
#include "vine.h"

struct json_object;
/* Sets root's "vines" to skeleton.json's "vines" section (docs/skeleton-format.md,
 * "Vines") for the vines given: per vine its parameters (every key of a vine file,
 * docs/vine-format.md), its planting point, its shoots (raw and smoothed axes, the points
 * touching the support, whether it stopped) and its leaves, numbers as skeleton.json
 * writes them (micrometres). What export_skeleton and export_skeleton_vines (export.h)
 * write. json_out's way: root back, or NULL without memory (root freed; a NULL root gives
 * NULL). */
struct json_object *vine_json_set(struct json_object *root, const struct vine *vines,
				  size_t nvines);
