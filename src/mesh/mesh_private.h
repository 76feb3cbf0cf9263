/* SPDX-License-Identifier: MIT */
/*
 * What the tree's mesh builder shares between its files: mesh.c (the tree mesh: builds,
 * marks, reuse), mesh_tube.c (a branch's tube and its joints) and mesh_leaf.c (a leaf's
 * polygon or origami shape). Not for use outside src/mesh/.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mesh.h"
#include "tree.h"
#include "screen.h"

/* Tubes never get thinner than this, so no ring collapses into a point (no zero-area faces). */
#define TUBE_MIN_RADIUS 0.0005
/* Consecutive points closer than this (metres) are the same point. */
#define TUBE_MIN_STEP 1e-6
/* The tip closes with a cone this many tip radii long: reads as a rounded end. */
#define TUBE_TIP_LENGTH 1.0
/* Limits how far taper tilts the smooth normals (|dr/ds|), so steep tapers still shade sanely. */
#define TUBE_MAX_SLOPE 3.0
/* A child's root ring stays within this fraction of the room its parent's tube leaves it
 * (the parent's rings lean at bends, which narrows its tube a little between them). */
#define TUBE_JOINT_MARGIN 0.9
/* Consecutive leaf points closer than this (metres) are the same point. */
#define LEAF_MIN_STEP 1e-7

/* Pixels a metre at the reference screen height (see mesh.h). */
#define TUBE_PX_PER_M (MESH_REF_SCREEN_PX / SCREEN_HEIGHT_M)

/* Ring shapes for every side count, and what each count costs in accuracy. */
struct lod {
	/* 1 - cos(pi / sides): how far a polygon's edge middles fall inside its circle. */
	double sag[MESH_MAX_SIDES + 1];
	double cs[MESH_MAX_SIDES + 1][MESH_MAX_SIDES], sn[MESH_MAX_SIDES + 1][MESH_MAX_SIDES];
	double cos_turn; /* of MESH_DROP_TURN_DEG (times drop_scale when coarse) */
	double sin_turn; /* of MESH_DROP_TURN_DEG: a joint's, coarse or not */
	int fixed; /* every ring's sides (a tree's `sides`), or 0: by radius */
	/* Coarser bark (struct mesh_coarse): no ring above max_sides sides (0: no cap), and
	 * rings left out drop_scale times as far (1: the tree's own mesh). */
	int max_sides;
	double drop_scale;
};

/* Per-build scratch arrays, grown to the longest polyline seen, reused across elements. */
struct mesh_scratch {
	struct vec3 *p; /* cleaned points */
	struct vec3 *t; /* tangents */
	struct vec3 *n; /* frame normals */
	double *r;      /* radii */
	int *sides;     /* ring sides */
	double *x, *y;  /* leaf points in their plane */
	size_t *live;   /* leaf polygon vertices not clipped yet */
	size_t cap;
	struct lod lod;
	/* Branches that children's roots hide in, cleaned once per build: branch i's points
	 * are hp/hx/hy[host_at[i] ..] (position, arc length, radius), host_n[i] of them;
	 * host_at[i] == SIZE_MAX until needed. host_at/host_n have nhosts entries. */
	size_t *host_at, *host_n, nhosts;
	struct vec3 *hp;
	double *hx, *hy;
	size_t hlen, hcap;
};

size_t mesh_grow_cap(size_t cap, size_t need);
uint32_t mesh_push_vertex(struct mesh *m, struct vec3 p, struct vec3 n);
void mesh_push_tri(struct mesh *m, uint32_t a, uint32_t b, uint32_t c);
bool mesh_vec3_finite(struct vec3 v);
void mesh_lod_init(struct lod *l);
/* Makes l coarser by c (mesh.h); NULL or {0, 1} leave it as it is. */
void mesh_lod_coarsen(struct lod *l, const struct mesh_coarse *c);
void mesh_scratch_finish(struct mesh_scratch *s);
int mesh_scratch_reserve(struct mesh_scratch *s, size_t n);
/* Appends branch index's tube to m (mesh_tube.c). 0 or negative errno. */
int mesh_tube_build(struct mesh *m, const struct tree *tr, size_t index, struct mesh_scratch *sc);
/* Appends leaf l's shape to m (mesh_leaf.c). 0 or negative errno. */
int mesh_leaf_build(struct mesh *m, const struct leaf *l, struct mesh_scratch *s);
