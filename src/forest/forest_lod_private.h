/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What the levels of detail share between their files (forest_lod.c: the tree's own bark
 * and leaves, the budget; forest_lod_wood.c: the wood's bark made coarser;
 * forest_lod_vine.c: the vines' stems made coarser). docs/forest.md, "Drawing it fast
 * enough" and "The wood and the vines".
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "forest.h"

/* Appends from's triangles to `to`, their indices moved past to's vertices. 0, -EINVAL
 * (more vertices than 32-bit indices hold) or -ENOMEM (to unchanged). */
int lod_mesh_append(struct mesh *to, const struct mesh *from);

/*
 * Which of n items stay when their triangles (tris[i]) must fit cap: all if they fit;
 * else they go, least worth first, until the rest fits or only `root` (SIZE_MAX: none) is
 * left. An item's worth is worth[i], or more if an item on it (parent[j] == i, parents
 * before their children; any other parent is none) is worth more: so an item goes after
 * every item on it, and none stays without its parent. Items held (held[i]: they hold the
 * outline; a held item's parent must be held) go after every other. keep[i] says which
 * stay, *kept how many. 0 or -ENOMEM.
 */
int lod_keep(size_t n, const int *parent, const double *worth, const bool *held,
	     const size_t *tris, size_t cap, size_t root, bool *keep, size_t *kept);

/* ---- the wood (forest_lod_wood.c) ------------------------------------------------- */

/*
 * A closed mesh made coarser by half-edge collapses, least quadric error first: the
 * whole sequence, found once; any number of triangles is then a prefix of it
 * (lod_decimate_apply), so a second budget costs one pass over the mesh.
 */
struct lod_decimate {
	const struct mesh *m;
	uint32_t *from, *to; /* collapse k: vertex from[k] goes into to[k] (2 triangles go) */
	size_t n;            /* collapses */
	size_t start;        /* m's triangles (those with three vertices) */
	size_t fewest;       /* after all the collapses: start - 2 n */
};
void lod_decimate_init(struct lod_decimate *d);
void lod_decimate_finish(struct lod_decimate *d);
/* The sequence for m (kept pointed to: m must outlive d). 0, -EINVAL (an index past the
 * vertices, more than 2^32 - 1 of them) or -ENOMEM (d empty then). */
int lod_decimate_plan(struct lod_decimate *d, const struct mesh *m);
/* Appends m with the fewest collapses that leave at most max triangles (all of them: its
 * fewest) to out: the vertices left in their order, the triangles left in theirs, every
 * position and normal m's own. 0, -EINVAL or -ENOMEM (out unchanged). */
int lod_decimate_apply(const struct lod_decimate *d, size_t max, struct mesh *out);
/* The triangles lod_decimate_apply leaves for max. */
size_t lod_decimate_triangles(const struct lod_decimate *d, size_t max);

/* ---- the vines' stems (forest_lod_vine.c) ------------------------------------------- */

/* One shoot of one of the tree's vines, its smoothed axis (vine_smooth). */
struct lod_shoot {
	struct vec3 *axis;
	size_t n;
	int sides;     /* its vine's ring_sides */
	double radius; /* its vine's stem radius */
	int parent;    /* among all the shoots (the vines' in order), or -1 */
	double worth;  /* its axis's length times its radius */
	size_t far[6]; /* its points farthest along x, -x, y, -y, z, -z (the first such) */
};
struct lod_stems {
	struct lod_shoot *s;
	size_t n;
};
void lod_stems_init(struct lod_stems *ls);
void lod_stems_finish(struct lod_stems *ls);
/* Every shoot of t's vines, in order. 0 or -ENOMEM (ls empty then). */
int lod_stems_read(struct lod_stems *ls, const struct tree *t);
/* Shoot i's triangles at coarser level l (1..FOREST_LOD_LEVELS): a ring every
 * forest_lod_stem_stride[l - 1] points, at its last and at its farthest along each axis;
 * at FOREST_LOD_STEM_OUTLINE, at its first, its last and its farthest only. */
size_t lod_stems_triangles(const struct lod_stems *ls, size_t i, int level);
/* Appends the shoots kept (keep NULL: all) at coarser level l to out. 0 or -ENOMEM (out
 * unchanged). */
int lod_stems_build(const struct lod_stems *ls, int level, const bool *keep, struct mesh *out);
