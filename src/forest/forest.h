/* SPDX-License-Identifier: MIT */
/*
 * src/forest/ (floor 8 of src/FLOORS: includes export and every floor below): today's
 * forest on the attract screen (issue 27, docs/forest.md), as pure functions: which
 * archived drawings form the day's forest and their numbers in it (forest_day.c), where
 * the trees stand (forest_layout.c), forest.json (forest_json.c), a tree's size
 * (forest_size.c) and its meshes at the level of detail the forest draws (forest_lod.c).
 * The clock, the archive's files and the trees' building are the caller's (platform/).
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "error.h"
#include "live.h"
#include "mesh.h"
#include "tree.h"

/* The whole forest's triangles on screen, shared among its trees by crown width
 * (forest_lod_shares): what a Pi-class GPU draws at the attract screen's rate. */
#define FOREST_TRIANGLES 300000
#define FOREST_MAX_TREES_DEFAULT 40
#define FOREST_MAX_TREES_LIMIT 200

/* ---- the day ------------------------------------------------------------------- */

/*
 * What the forest keeps across restarts (STATE_DIR/forest-day): when the day began and
 * the archive number of its first tree. Everything else is rebuilt from the archive.
 */
struct forest_day {
	int64_t start;  /* seconds since 1970 (UTC); 0: no day yet */
	uint64_t first; /* the archive number of the day's first tree */
};

/*
 * A new day begins when the last reset moment at or before now (`reset`, the caller's
 * clock and time zone) is later than the day's start: day becomes {reset, next}, the next
 * archive number, and the function returns true. A clock set back never begins a day.
 */
bool forest_day_update(struct forest_day *day, int64_t reset, uint64_t next);
/* A new day now, whatever the hour (edaha --forest-reset). */
void forest_day_restart(struct forest_day *day, int64_t now, uint64_t next);
/*
 * The trees standing among archive numbers[0..n) (any order; duplicates count once):
 * those numbered day->first or more, the newest max of them. Writes their indexes into
 * numbers to out (at most max), oldest first, and returns how many.
 */
size_t forest_day_standing(const struct forest_day *day, const uint64_t *numbers, size_t n,
			   size_t max, size_t *out);
/* A tree's number in the day (1 for the day's first), 0 for one before the day. */
uint64_t forest_day_number(const struct forest_day *day, uint64_t archive_number);

/* The file (docs/forest.md), a flat YAML mapping: `edaha-forest-day: 1`, `start: S`,
 * `first: N`. read: 0, or -EINVAL / -ENOMEM with err "NAME:LINE: what is wrong" (day
 * unchanged). write: 0 or -ENOMEM. */
#define FOREST_DAY_VERSION 1
int forest_day_read(const char *data, size_t len, const char *name, struct forest_day *day,
		    struct error *err);
int forest_day_write(const struct forest_day *day, struct buf *out);

/* ---- the layout ------------------------------------------------------------------ */

/*
 * Where the trees stand on the ground (x, z, metres; y up): the tree numbered n at slot
 * (n - 1) mod max of a sunflower spiral, radius c sqrt(k + 1/2) at k golden angles, so a
 * tree keeps its place while it stands. c is the least scale at which every two trunks
 * are FOREST_GAP times the sum of their crown widths apart (and at least FOREST_MIN_C).
 * numbers[i] (1..; distinct modulo max) and widths[i] (metres, >= 0) of n trees; writes
 * xz[2i], xz[2i + 1]. Returns c, or -1 when two trees share a slot or an input is bad.
 */
#define FOREST_GAP 0.45
#define FOREST_MIN_C 1.0
double forest_layout(const uint64_t *numbers, const double *widths, size_t n, size_t max,
		     double *xz);

/* ---- forest.json ----------------------------------------------------------------- */

struct forest_json_tree {
	uint64_t number;
	const char *file;
	double position[3];
	double height, crown_width;
	size_t branches, leaves;
};
struct forest_json_skip {
	const char *file;
	const char *why;
};
/* {"format": "edaha-forest", "version": 1, "trees": [...], "skipped": [...]}. 0 or
 * -ENOMEM. */
int forest_json(const struct forest_json_tree *trees, size_t ntrees,
		const struct forest_json_skip *skipped, size_t nskipped, struct buf *out);

/* ---- levels of detail ---------------------------------------------------------- */

/*
 * A tree's size (forest_size.c), measured from its trunk's foot (the first point of its
 * first branch without a parent): its height, the highest any branch's surface (a point's
 * height plus its radius) or leaf point reaches above the foot; its crown width, twice the
 * farthest any branch's surface (a point's horizontal distance from the vertical through
 * the foot plus its radius) or leaf point reaches from that vertical. Both are the same
 * whichever way the tree is turned about it. Points that are not finite are left out;
 * 0 for a tree without branches.
 */
double forest_tree_height(const struct tree *t);
double forest_tree_crown_width(const struct tree *t);

/*
 * A tree's meshes for the forest within max_triangles (bark + leaves; docs/forest.md,
 * "Drawing it fast enough"), with what it draws beside its own meshes: the wood's bark
 * (t->wood->bark, in place of the tubes of the branches it holds, tree_branch_in_wood)
 * and its vines (vine_mesh_append's stems and leaves):
 *
 * - Everything as it is when it fits, byte for byte: the bark tree_mesh_build's, then the
 *   wood's bark, then the vines' stems (vine after vine); the leaves tree_mesh_build's,
 *   then the vines'.
 * - Otherwise the bark (all three) may take the larger of FOREST_LOD_BARK_SHARE of the
 *   budget and what the leaves as they are (the vines' too) leave of it. Within that the
 *   wood and the stems each take a share in proportion to their own triangles (together
 *   no more than the tubes' outline, the trunk's and those forest_lod_keep keeps last at
 *   the coarsest level, leaves), the stems at the first level that fits
 *   (forest_lod_stem_stride; past the coarsest, shoots go least worth first but those
 *   that hold the outline, drawn at FOREST_LOD_STEM_OUTLINE if need be); the tubes what
 *   those two leave, made coarser level by level (forest_lod_levels: fewer sides, fewer
 *   rings, tree_mesh_build_parts_coarse), past the coarsest with branches gone as
 *   forest_lod_keep says (least worth first, never one before the branches on it, the
 *   trunk never); then of what the tubes leave the stems their part again (if more) and
 *   the wood all the rest, made coarser by forest_lod_decimate.
 * - The leaves as they are when they fit the rest; else as cards: the leaves (those with
 *   triangles; the tree's, then the vines') binned by their centroids in a grid of cubes
 *   over them, the finest whose occupied cells fit the rest at 2 triangles a card (at
 *   least one card). Each cell's leaves make one card: a rectangle facing the axis their
 *   normals gather round (the principal axis of the sum of a a^T / |a| over their area
 *   vectors a, so a leaf and one turned over count alike; the side most of their area
 *   faces), through their centroid (by area) moved along that axis to their outer face
 *   (their farthest vertex on the side away from the centre of all the leaves'
 *   centroids), covering every one of their vertices seen along it (sides at least
 *   FOREST_LOD_CARD_MIN_M), one-sided (counter-clockwise about its normal) and drawn
 *   double-sided as leaves are; along each of +-x, +-y, +-z the card of the leaf that
 *   reaches farthest is stretched in its plane until it reaches as far. Cards are
 *   numbered in the order of their first leaf. When cards leave room (a card a leaf),
 *   the bark is made again with all the leaves leave.
 * Never more than max_triangles, but never less than the trunk's tube at the coarsest
 * level (none when the wood holds it), the wood at its fewest, the stems that hold the
 * outline at FOREST_LOD_STEM_OUTLINE and (with leaves) one card: a budget below that (0
 * too) gets that, and st->over_budget says so. Same tree and budget, same bytes; the
 * meshes are the same in every season (winter does not draw the leaves). out
 * (initialised) is cleared first. 0 or -ENOMEM (out then empty). st may be NULL.
 */
#define FOREST_LOD_BARK_SHARE 0.4
#define FOREST_LOD_CARD_MIN_M 0.001

struct forest_lod_stats {
	size_t full_triangles;                 /* the tree's own meshes, its wood's and vines' */
	size_t bark_triangles, leaf_triangles; /* these */
	int level;               /* 0: the tree's own tubes; l: forest_lod_levels[l - 1] */
	int sides;               /* the most sides a ring may have at that level */
	size_t branches_kept;    /* of t->nbranches */
	size_t wood_triangles;   /* of bark_triangles: the wood's bark (0: no wood) */
	size_t stem_triangles;   /* of bark_triangles: the vines' stems */
	size_t stem_vertices;    /* the bark's last vertices: the vines' stems */
	int stem_level;          /* 0: the vines' own stems; l: forest_lod_levels[l - 1]'s
				  * sides, a ring every forest_lod_stem_stride[l - 1] points */
	size_t shoots, shoots_kept; /* the vines' shoots, and those drawn */
	size_t leaves_as_cards;  /* leaves drawn as cards (0: all as they are), the vines' too */
	size_t cards;
	double cell;             /* the cards' grid's cell, metres (0: no cards) */
	bool over_budget;        /* the least this function makes did not fit max_triangles */
};

/*
 * Which of t's branches stay when its bark (branch i: tris[i] triangles) must fit cap: all
 * if they fit; else they go, least worth first, until the rest fits or only the trunk
 * (the first branch without a parent) is left. A branch's worth is its length times its
 * root radius, or more if a branch on it is worth more: so a branch goes after every
 * branch on it, and none stays without its parent. Branches that hold the outline go last:
 * along each of x, -x, y, -y, z and -z, the branch with the farthest point (unless a vertex of
 * `leaves`, which may be NULL, reaches as far) and those it hangs on. keep[i] (nbranches
 * of them) says which stay, *kept how many. 0 or -ENOMEM.
 */
int forest_lod_keep(const struct tree *t, const struct mesh *leaves, const size_t *tris,
		    size_t cap, bool *keep, size_t *kept);

/* The bark's coarser levels, in order. */
#define FOREST_LOD_LEVELS 7
extern const struct mesh_coarse forest_lod_levels[FOREST_LOD_LEVELS];
/* The vines' stems at level l: a ring every forest_lod_stem_stride[l - 1] points of a
 * shoot's smoothed axis (and at its last), forest_lod_levels[l - 1].max_sides sides at most. */
extern const int forest_lod_stem_stride[FOREST_LOD_LEVELS];
/* The stems' level past the coarsest: the shoots that hold the outline alone, a ring at
 * their first and last points and at their farthest along each of +-x, +-y, +-z. */
#define FOREST_LOD_STEM_OUTLINE (FOREST_LOD_LEVELS + 1)

/*
 * A closed, consistently oriented manifold mesh (the wood's bark: wood_iso's) with at most
 * max_triangles triangles, appended to out (docs/forest.md, "The wood and the vines"):
 * half-edge collapses, least quadric error first (each vertex goes into a neighbour and
 * takes its place: the vertices left are m's own, their normals too), each keeping a
 * closed manifold, turning no face over, and never taking a vertex farthest along +-x,
 * +-y or +-z (the box stays). When no collapse is left to take the mesh comes out with
 * more (*fewest, may be NULL: the fewest it goes to). Same mesh, same bytes; a larger
 * max is a prefix of a smaller's collapses. 0, -EINVAL (an index past the vertices) or
 * -ENOMEM (out as it was).
 */
int forest_lod_decimate(const struct mesh *m, size_t max_triangles, struct mesh *out,
			size_t *fewest);

int forest_lod_build(const struct tree *t, size_t max_triangles, struct tree_mesh *out,
		     struct forest_lod_stats *st);

/*
 * The season's colour of each vertex of forest_lod_build's leaves (linear RGB, 3 floats a
 * vertex, season.h's palette as leaf_colors_fill gives them): a leaf as it is takes its own
 * palette colour (a vine's leaf the palette's first, as the screen tints vine leaves); a
 * card, the mean of its leaves' colours weighted by their areas (what the eye mixes them
 * to from afar). The screen maps them as any palette colour
 * (ui/leaf_tint.h). n: out->leaves.nvertices, or 0 in winter (no palette: not drawn).
 */
struct forest_lod_colors {
	float *rgb;
	size_t n, cap; /* vertices coloured; room for cap */
};
void forest_lod_colors_init(struct forest_lod_colors *c);
void forest_lod_colors_finish(struct forest_lod_colors *c);
/* forest_lod_build, and its leaves' colours into colors (may be NULL). 0 or -ENOMEM. */
int forest_lod_build_colors(const struct tree *t, size_t max_triangles, struct tree_mesh *out,
			    struct forest_lod_colors *colors, struct forest_lod_stats *st);

/*
 * Each of n trees' share of a forest's total triangles: in proportion to its crown width
 * (widths[i], metres; below 0 or not finite counts as 0; all 0: equal shares), and
 * water-filled: a tree whose own meshes need fewer (need[i]; need NULL: unknown) takes
 * what it needs and what it leaves is shared again among the others. Writes share[i];
 * the shares sum to at most total.
 */
void forest_lod_shares(const double *widths, const size_t *need, size_t n, size_t total,
		       size_t *share);

/* ---- the scene: what the screen draws (forest_scene.c) ---------------------------- */

/*
 * One tree made ready for the forest's screen, on the planting thread (docs/forest.md,
 * "Drawing it fast enough"): its level of detail within `budget` triangles (its wood's
 * bark and its vines in it: forest_lod_build), and each of its vertices' living data
 * (bound to its skeleton by the nearest point, as the drawing screen binds the wood and
 * the vines), its wind over the forest's common loop (LIVE_WIND_COMMON_LOOP_S) at
 * `strength`, all in the tree's own coordinates with its trunk's foot at `foot`.
 */
struct forest_part {
	struct tree_mesh mesh;
	struct forest_lod_colors colors; /* its leaves' season colours (n 0: one colour) */
	struct live_attrs bark, leaves;  /* a vertex each of mesh.bark, mesh.leaves */
	double foot[3];
	double height, crown_width;
	size_t branches, leaves_drawn;   /* the tree's: branches, leaves */
	double amp0;                     /* its trunk's sway, metres at w0 = 1 */
	int harmonic0;                   /* its trunk's whole cycles a loop */
	uint8_t phase0;                  /* its trunk's phase, 1/256 turns, from the seed */
	struct live_wind wind;           /* its wind, over the common loop */
	size_t bark_stems;               /* mesh.bark's last vertices: its vines' stems */
};
void forest_part_init(struct forest_part *p);
void forest_part_finish(struct forest_part *p);
/* 0; -EINVAL (no branches, a strength outside 0..1); -ENOMEM (p then empty). */
int forest_part_build(struct forest_part *p, const struct tree *t, uint64_t seed,
		      size_t budget, double strength);

/*
 * The standing trees as the screen draws them: every part placed (its foot at its
 * position) and merged into one bark and one leaves mesh, so the forest is a few draw
 * calls whatever its number of trees. Tree i's vertices and indices are one range of
 * each, in the order given (the newest last: drawn apart while it grows in). Their
 * living data is placed with them; the trunk's sway is folded into w0 against the
 * scene's wind (the tree that sways most's), so one frame's uniforms move every tree by
 * its own height; each tree's trunk harmonic and phase go per vertex (trunk[2 v], trunk[2 v + 1]).
 *
 * Each tree's growing in (`grow`, live_grow_setup's rule) is set up from D_max, the
 * farthest path length any of its vertices is bound to (live_vertex.d, its level of
 * detail's: the skeleton's own when the farthest branch is drawn), so that at the end of
 * its growth every vertex the scene holds of it is drawn whole.
 */
struct forest_scene_tree {
	uint64_t number;
	double position[3];
	double height, crown_width;
	size_t bark_vertices[2], bark_indices[2];     /* [first, end) */
	size_t leaves_vertices[2], leaves_indices[2];
	struct live_grow grow;                        /* its growing in */
};
struct forest_scene {
	struct forest_scene_tree *trees;
	size_t ntrees, cap_trees;
	struct tree_mesh mesh;               /* world coordinates */
	float *leaf_rgb;                     /* 3 a leaves vertex, or NULL: one colour */
	struct live_attrs bark, leaves;      /* placed */
	uint8_t *bark_trunk, *leaves_trunk;  /* 2 a vertex: harmonic0, phase0 */
	uint8_t *bark_vine;                  /* 1 a bark vertex: a vine's stem (the screen
					      * colours it as a vine); NULL: no vines */
	size_t cap_bark_trunk, cap_leaves_trunk;
	struct live_wind wind;               /* the frame's (the most swaying tree's) */
	double center[3], radius, top;       /* what the camera frames: the trees' feet's
					      * centre, the farthest crown's reach, the top */
	uint64_t serial;                     /* bumped at each build */
};
void forest_scene_init(struct forest_scene *s);
void forest_scene_finish(struct forest_scene *s);
/* parts[i] numbered numbers[i], its foot at positions[3 i..]; 0 or -ENOMEM (s empty). */
int forest_scene_build(struct forest_scene *s, const struct forest_part *const *parts,
		       const uint64_t *numbers, const double *positions, size_t n);
