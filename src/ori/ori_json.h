/* SPDX-License-Identifier: MIT */
#pragma once

#include "buf.h"
#include "ori.h"

#define ORI_JSON_FORMAT "edaha-origami"
#define ORI_JSON_VERSION 1

/*
 * origami.json (docs/origami-leaves.md, "The command line and origami.json"): leaf l's
 * flat pattern, creases, margin and faces, its folded (bud) state, and `opened`, its
 * vertices at opening t as ori_open placed them (nvertices rows); then the design's name,
 * t, the mesh's triangle count and the lobes' tips against their targets. Numbers are
 * metres (degrees for a lobe's theta) to the micrometre, as skeleton.json's. Appends to
 * out: 0 or -ENOMEM (out as it was). Same input, same bytes.
 */
int ori_json(const struct ori_leaf *l, const char *name, double t, const double (*opened)[3],
	     struct buf *out);
