/* SPDX-License-Identifier: MIT */
/*
 * src/live/ (floor 5 of src/FLOORS, beside sketch, gen, vine and wood, which it never
 * includes): the living tree (issue 26): its sway in the wind and its growing in, as pure
 * functions of the skeleton, a vertex's data and the time. Includes mesh, core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mesh.h"
#include "tree.h"
#include "vec.h"

/*
 * A tree that lives (docs/living-trees.md says why each choice, and the measured
 * figures). No mesh is rebuilt while it moves: every vertex of every mesh is bound once
 * to a point of the skeleton (struct live_vertex, what a vertex shader reads), and the
 * motion is a sum of a few fixed per-vertex vectors, each times a function of time:
 *
 *   offset(v, t) = sum_j g_j(t) T_j(v)     j < LIVE_WIND_TARGETS
 *
 * which a shader computes from the vertex's data and a few numbers a frame
 * (struct live_wind_frame), and which a glTF file carries as morph targets T_j with the
 * g_j as the animated weights (live_wind_targets, live_wind_weights). Growing in is a front
 * running along the skeleton from the trunk's foot (struct live_grow): one number a frame.
 *
 * Everything here is deterministic: no clock (times are arguments, in seconds), no I/O,
 * phases from the seeded generator (rng.h) and the document's seed.
 *
 * The pieces, in the order a caller makes them:
 *
 *   live_skeleton_init   per branch: band, path length from the foot, band weights and
 *                        phases at its base (O(branches + points + leaves))
 *   live_attrs_bind_*    per vertex of a mesh: struct live_vertex
 *   live_wind_setup      the wind's numbers for this tree and strength (O(1))
 *   live_grow_setup      the growth's numbers for this tree (O(1))
 *
 * then per frame live_wind_frame and live_grow_front (O(1), whatever the tree's size).
 */

/* ---- the skeleton ------------------------------------------------------------------ */

/*
 * Bands. The trunk (a branch without a parent) is band 0: it bends as a whole with the
 * tree. Every other branch gets band 1..3 by its size relative to the trunk,
 * sigma = sqrt((r / r_trunk) * (L / H)) from its base radius r (the trunk's: r_trunk) and
 * its length L (H: the tree's height, which a trunk spans; a shrub's short trunk would
 * make every branch of its crown a limb): band 1 from LIVE_BAND1_SIZE up (limbs), band 2
 * from LIVE_BAND2_SIZE, band 3 below (twigs); then made monotone along the chain,
 * band(child) = max(band(parent), own). A band's motion grows with the path length inside
 * it, from the point where the chain entered it, counting each branch from where it leaves
 * its parent's tube (its axis farther from the parent's axis than the parent's radius):
 * the part inside the parent moves with the parent's point, hidden in its bark (or in the
 * wood's, which the iso-surface draws round both).
 */
#define LIVE_BANDS 4
#define LIVE_BAND1_SIZE 0.17
#define LIVE_BAND2_SIZE 0.09

/* What the skeleton gives every branch (live_skeleton.c). */
struct live_branch {
	double d0;          /* path length along the skeleton from its trunk's foot to its base */
	double dy;          /* the height its chain gives its base minus its base's own y */
	double length;      /* its polyline's arc length */
	double exit;        /* arc length where it leaves its parent's tube (0 for a trunk) */
	double wb[LIVE_BANDS]; /* band weights w_1..w_3 at its base ([0] unused: 0) */
	size_t first;       /* its points' arc lengths: live_skeleton.arc[first .. +npoints) */
	int band;           /* 0..3 */
	uint8_t phase[LIVE_BANDS]; /* bands 1..3: its band-entry branch's phase, 1/256 turns */
};

struct live_skeleton {
	struct live_branch *branches;
	size_t nbranches;
	double *arc;        /* every branch's points' arc lengths from its base, in order */
	double *hmax;       /* beside arc: the highest chain height from the foot to the point */
	size_t narc;
	uint8_t *leaf_phase; /* a leaf's flutter phase, 1/256 turns */
	size_t nleaves;
	double foot_y;      /* branch 0's first point's y: the ground the tree bends from */
	double height;      /* H: the highest skeleton point above the foot (chain heights) */
	double d_max;       /* the largest path length from a foot to a skeleton point */
	size_t counts[LIVE_BANDS]; /* branches in each band */
};

/*
 * The skeleton of t: every branch's band, base path length, chain heights, exit, band
 * weights and phases (phases from rng.h seeded by `seed` and the element's id: the
 * document's seed makes them, so a replay gives the same). A branch whose parent is
 * missing or not before it is treated as a trunk. The functions that take sk take the
 * same t. 0 or -ENOMEM (sk then empty, and finish-able).
 */
int live_skeleton_init(struct live_skeleton *sk, const struct tree *t, uint64_t seed);
void live_skeleton_finish(struct live_skeleton *sk);

/* ---- a vertex's data ---------------------------------------------------------------- */

/*
 * What a vertex moves with: 44 bytes, laid out for a vertex buffer as it is (offsets in
 * docs/living-trees.md, "Per-vertex data"). A tube ring's vertices share their skeleton
 * point, so the ring moves rigidly; a leaf's vertices share their anchor.
 */
struct live_vertex {
	float point[3];   /* the skeleton point it is bound to (a leaf's: its anchor), world m */
	float d;          /* path length from the trunk's foot to that point along the skeleton */
	float w[LIVE_BANDS]; /* band weights: w[0] = (h / H)^2 (0..1), h the highest the chain
			      * from the foot to the point rises above the foot; w[1..3] metres
			      * of the chain inside band k */
	float leaf;       /* a leaf's vertex: its distance from the anchor (m); else 0 */
	uint8_t phase[LIVE_BANDS]; /* [1..3] bands 1..3, [0] the leaf's flutter: 1/256 turns */
	int8_t flutter[4]; /* a leaf's flutter direction (its mean normal), snorm / 127; else 0 */
};
_Static_assert(sizeof(struct live_vertex) == 44, "a vertex buffer's stride");

/*
 * The data of skeleton point (branch b, arc length s from its base; clamped to the
 * branch). false when b is no branch of sk (out untouched).
 */
bool live_skeleton_vertex(const struct live_skeleton *sk, const struct tree *t, size_t b, double s,
			  struct live_vertex *out);
/*
 * The data every vertex of leaf i shares (its anchor's, its phase, `normal` as its flutter
 * direction), `leaf` 0: an instanced leaf's per-instance data, the shader taking each
 * vertex's distance from the anchor itself. false when i is no leaf of t or sk.
 */
bool live_skeleton_leaf(const struct live_skeleton *sk, const struct tree *t, size_t i,
			struct vec3 normal, struct live_vertex *out);

/* Per-vertex data of one mesh: v[i] for its vertex i. */
struct live_attrs {
	struct live_vertex *v;
	size_t n, cap;
};

void live_attrs_init(struct live_attrs *a);
void live_attrs_finish(struct live_attrs *a);
/*
 * Binds every vertex of `bark` (tree_mesh_build's bark of t) to its branch by mk's ranges
 * (NULL: found by meshing t's branches again, tree_mesh_build_parts): projected onto the
 * branch's polyline, snapped to the polyline point whose ring it is (within
 * LIVE_RING_SNAP of its radius), so a ring moves as one. 0, -EINVAL (the ranges do not
 * describe this mesh, or sk is not t's) or -ENOMEM (a then empty).
 */
#define LIVE_RING_SNAP 1e-3
int live_attrs_bind_bark(struct live_attrs *a, const struct live_skeleton *sk, const struct tree *t,
			 const struct mesh *bark, const struct tree_mesh_marks *mk);
/*
 * Binds every vertex of `leaves` (tree_mesh_build's leaves of t) to its leaf's anchor
 * (leaf.branch at leaf.branch_t) by mk's ranges (NULL: found as for the bark); the
 * flutter direction is the mean of the leaf's vertex normals. 0, -EINVAL or -ENOMEM.
 */
int live_attrs_bind_leaves(struct live_attrs *a, const struct live_skeleton *sk,
			   const struct tree *t, const struct mesh *leaves,
			   const struct tree_mesh_marks *mk);
/*
 * Binds every vertex of any mesh on the tree (the wood's iso-surface, a vine's stem and
 * leaves) to its nearest skeleton point: the least |v - q| - r(q) over every branch's
 * segments, q the nearest point of the segment's axis and r its radius there (the bark's
 * surface nearest, so a trunk's vertex does not go with a twig inside it); a grid of the
 * segments (live_nearest.c) keeps it near O(vertices). No leaf flutter. A mesh with
 * vertices and no branch to bind them to: -EINVAL. 0, -EINVAL or -ENOMEM.
 */
int live_attrs_bind_nearest(struct live_attrs *a, const struct live_skeleton *sk,
			    const struct tree *t, const struct mesh *m);

/* ---- wind ------------------------------------------------------------------------- */

/*
 * The wind (GPU Gems 3, ch. 16, Crysis's vegetation: main bending, detail bending, leaf
 * flutter), strength S in 0..1 scaling every amplitude:
 *
 * - band 0, the whole tree: w0 (h / H)^2 times amp0 = S * LIVE_WIND_TRUNK_SWAY * H
 *   metres along the wind D at the trunk's frequency f0 = 1 / P0, plus
 *   LIVE_WIND_FIGURE_EIGHT of that across it (C) at 2 f0: a figure eight. The foot
 *   (h = 0) never moves; the top of the tree moves amp0 at most (at S = 1, 7.5% of H;
 *   at the default breeze, 2.6%).
 * - P0 = LIVE_WIND_PERIOD_REF_S * sqrt(H / LIVE_WIND_HEIGHT_REF_M), within
 *   [LIVE_WIND_PERIOD_MIN_S, LIVE_WIND_PERIOD_MAX_S]: 1.77 s at 5 m, 3.06 s at 15 m (a
 *   cantilever's first mode scales as r / L^2; with r ~ L^1.5, period ~ sqrt(L)).
 * - The loop: T_loop = n P0, n = the most whole periods within LIVE_WIND_LOOP_MAX_S; every
 *   frequency is a whole number of cycles a loop (harmonic m: f = m / T_loop), so the sum
 *   loops seamlessly. Band 0 is harmonic n. A common loop (p.loop > 0: the forest, where
 *   every tree's wind must loop over the same seconds) is T_loop = p.loop, and n the whole
 *   number nearest p.loop / P0 (at least 1): the trunk sways at p.loop / n, within 17% of
 *   P0 for trees 5 to 15 m tall in an 8 s loop (docs/living-trees.md, "A common
 *   loop"); the rest follows from T_loop as above.
 * - band k = 1..3: w_k (metres of branch inside band k up to the point) times
 *   amp_k = S * LIVE_WIND_BAND_SWAY[k] along E_k = unit(D + LIVE_WIND_BAND_BOB[k] y), as
 *   sin(2 pi f_k t + phi_k): phi_k the band-entry branch's phase; f_k the harmonic
 *   nearest LIVE_WIND_BAND_HZ[k] above the lower bands' (never 2n: the across motion's).
 *   A small branch sways at a rate of its own size, whatever tree it is on. Limbs sway
 *   least a metre (they mostly ride the whole tree's bending), twigs most: a twig's
 *   0.20 S exceeds the whole tree's steepest bend along it, 2 * 0.075 S * sqrt(1 + 0.3^2)
 *   = 0.157 S, so what a twig adds is its own faster sway.
 * - leaves: their distance from the anchor times amp_L = S * LIVE_WIND_LEAF_SWAY along
 *   their flutter direction, at the harmonic nearest LIVE_WIND_LEAF_HZ (above band 3's),
 *   with the leaf's own phase.
 *
 * D = (cos a, 0, sin a) for the wind's angle a, C = (-sin a, 0, cos a). On screen the angle
 * drifts (live_wind_angle); an export takes it at t = 0.
 */
#define LIVE_WIND_DEFAULT_STRENGTH 0.35
#define LIVE_WIND_TRUNK_SWAY 0.075
#define LIVE_WIND_FIGURE_EIGHT 0.3
#define LIVE_WIND_PERIOD_REF_S 2.5
#define LIVE_WIND_HEIGHT_REF_M 10.0
#define LIVE_WIND_PERIOD_MIN_S 1.0
#define LIVE_WIND_PERIOD_MAX_S 6.0
#define LIVE_WIND_LOOP_MAX_S 8.0
#define LIVE_WIND_LEAF_HZ 3.5
#define LIVE_WIND_LEAF_SWAY 0.35
/* The screen's drift: a = a0 + LIVE_WIND_DRIFT_RAD sin(2 pi t / LIVE_WIND_DRIFT_PERIOD_S). */
#define LIVE_WIND_DRIFT_RAD 0.35
#define LIVE_WIND_DRIFT_PERIOD_S 47.0
/* per band 1..3, as array initialisers ([0] unused) */
#define LIVE_WIND_BAND_HZ { 0.0, 1.0, 1.6, 2.4 }
#define LIVE_WIND_BAND_SWAY { 0.0, 0.06, 0.12, 0.20 }
#define LIVE_WIND_BAND_BOB { 0.0, 0.25, 0.35, 0.5 }

/* A common loop's bounds (live_wind_params.loop), seconds: at least the shortest trunk
 * period; at most a minute, which keeps every harmonic (the leaves': 3.5 Hz x 60 s) and an
 * export's keys few. The forest's loop is LIVE_WIND_COMMON_LOOP_S. */
#define LIVE_WIND_COMMON_LOOP_MIN_S LIVE_WIND_PERIOD_MIN_S
#define LIVE_WIND_COMMON_LOOP_MAX_S 60.0
#define LIVE_WIND_COMMON_LOOP_S LIVE_WIND_LOOP_MAX_S

struct live_wind_params {
	double strength; /* S, 0..1: 0 still, LIVE_WIND_DEFAULT_STRENGTH a breeze */
	double angle;    /* radians at t = 0: D = (cos, 0, sin) */
	double loop;     /* 0: the tree's own loop; else the loop, seconds, in
			  * [LIVE_WIND_COMMON_LOOP_MIN_S, LIVE_WIND_COMMON_LOOP_MAX_S] */
};

/* live_wind_targets' order: band 0 along and across, bands 1..3 and the leaves' (sin, cos). */
enum {
	LIVE_TARGET_ALONG = 0,
	LIVE_TARGET_ACROSS,
	LIVE_TARGET_BAND1,      /* + 2 (k - 1) for band k: its sin target, then its cos target */
	LIVE_TARGET_LEAF = 8,   /* sin, cos */
	LIVE_WIND_TARGETS = 10,
};

/* The wind's numbers for one tree and strength. */
struct live_wind {
	double strength, angle;
	double height;  /* H, m */
	double period;  /* P0, s (the tree's own, whatever the loop) */
	double loop;    /* T_loop, s */
	/* whole cycles a loop: [0] band 0, [1..3] bands 1..3; [4] the leaves. The across
	 * motion runs at 2 * harmonic[0]. */
	int harmonic[LIVE_BANDS + 1];
	double amp0;               /* metres at w0 = 1 */
	double amp[LIVE_BANDS];    /* metres a metre of w_k ([0] unused) */
	double amp_leaf;           /* metres a metre from the anchor */
};

/*
 * The wind of sk's tree at p. 0, or -EINVAL (strength outside 0..1, angle not finite, loop
 * neither 0 nor within its bounds; w untouched).
 */
int live_wind_setup(struct live_wind *w, const struct live_skeleton *sk,
		    const struct live_wind_params *p);
/* Frequency of harmonic m, Hz. */
double live_wind_hz(const struct live_wind *w, int m);
/* The wind's angle on screen at time t (radians): it drifts slowly about p.angle. */
double live_wind_angle(const struct live_wind *w, double t);

/*
 * What a frame needs, the same for every vertex (a vertex shader's uniforms): the
 * directions at the frame's angle, the amplitudes, and each motion's angle now (radians,
 * 0..2 pi, reduced in double so a float shader loses nothing over a long run).
 */
struct live_wind_frame {
	struct vec3 along, across;          /* D, C */
	struct vec3 dir[LIVE_BANDS];        /* E_1..E_3 ([0] unused) */
	double amp0, amp[LIVE_BANDS], amp_leaf;
	double sway_along, sway_across;     /* sin of band 0's angles: the along, across weights */
	double theta[LIVE_BANDS];           /* 2 pi f_k t for bands 1..3 ([0]: band 0's) */
	double theta_leaf;
};

/* The frame at time t with the wind blowing at `angle` (live_wind_angle(w, t) on screen,
 * w->angle in an export). */
void live_wind_frame(const struct live_wind *w, double t, double angle, struct live_wind_frame *f);
/*
 * A vertex's offset in a frame, the reference the shader mirrors (in double here):
 *   amp0 w0 (sway_along D + LIVE_WIND_FIGURE_EIGHT sway_across C)
 *   + sum_k amp_k w_k sin(theta_k + 2 pi phase_k / 256) E_k
 *   + amp_leaf leaf sin(theta_leaf + 2 pi phase_0 / 256) flutter / 127
 */
struct vec3 live_wind_frame_offset(const struct live_wind_frame *f, const struct live_vertex *v);
/* offset(v, t) at the wind's own angle (what an export samples). */
struct vec3 live_wind_offset(const struct live_wind *w, const struct live_vertex *v, double t);

/*
 * The decomposition for glTF morph targets: T_j(v) (metres, at w's strength and angle)
 * and g_j(t) (in -1..1) with sum_j g_j(t) T_j(v) = live_wind_offset(w, v, t). The weights
 * depend on the loop's fraction u = t / T_loop only (live_wind_weights_at takes u: i / N
 * for N keyframes, so the last, u = 1, is the first exactly); rates are dg_j/dt (per
 * second), a cubic spline's tangents.
 */
void live_wind_targets(const struct live_wind *w, const struct live_vertex *v,
		       struct vec3 out[LIVE_WIND_TARGETS]);
void live_wind_weights(const struct live_wind *w, double t, double out[LIVE_WIND_TARGETS]);
void live_wind_weights_at(const struct live_wind *w, double u, double out[LIVE_WIND_TARGETS]);
void live_wind_rates_at(const struct live_wind *w, double u, double out[LIVE_WIND_TARGETS]);

/* ---- growing in ------------------------------------------------------------------- */

/*
 * Growing in: a front runs along the skeleton from the trunk's foot,
 *
 *   D(t) = D_end ease(t / duration),  ease(u) = 3u^2 - 2u^3 (0 before 0, 1 after 1),
 *   D_end = D_max + swell + 1e-6 (1 + D_max)
 *
 * D_max the farthest skeleton point's path length from the foot, swell =
 * LIVE_GROW_SWELL * D_max (at least LIVE_GROW_MIN_SWELL_M); the micrometre a metre
 * because a vertex's d is a float, which may round up past D_max. A vertex whose d
 * exceeds D(t) is not drawn; one the front passed is pulled towards its skeleton point by
 * the factor f = ease((D - d) / swell): 0 at the front, exactly 1 a swell behind it (a
 * branch's radius swells as it lengthens; a leaf, all of whose vertices share its
 * anchor's d, scales in about its anchor once the front passed it). The duration follows
 * the tree's size, LIVE_GROW_RATE_S * sqrt(D_max / 1 m) within [LIVE_GROW_MIN_S,
 * LIVE_GROW_MAX_S]: the front runs faster on a larger tree, which takes longer all the
 * same. At t >= duration the front is D_end, every vertex is drawn and f = 1: the
 * settled tree. Vines start at the duration (they grow by the app's clock after it:
 * docs/living-trees.md).
 */
#define LIVE_GROW_RATE_S 1.2
#define LIVE_GROW_MIN_S 2.0
#define LIVE_GROW_MAX_S 6.0
#define LIVE_GROW_SWELL 0.12
#define LIVE_GROW_MIN_SWELL_M 0.01

struct live_grow {
	double d_max, swell, d_end;
	double duration; /* s */
};

void live_grow_setup(struct live_grow *g, const struct live_skeleton *sk);
/* D(t), metres of path from the foot; t seconds since the growth began. */
double live_grow_front(const struct live_grow *g, double t);
/* Whether a vertex at path length d is drawn with the front at `front`. */
bool live_grow_visible(double front, double d);
/* Its pull factor, 0..1 (1 exactly a swell behind the front and beyond). */
double live_grow_pull(const struct live_grow *g, double front, double d);
/*
 * Where vertex v (at rest at pos) is drawn with the front at `front`: its skeleton point
 * plus f (pos - point), written pos * f + point * (1 - f) so that f = 1 gives pos exactly
 * (the shader writes it so too). Not drawn unless live_grow_visible.
 */
struct vec3 live_grow_position(const struct live_grow *g, double front, const struct live_vertex *v,
			       struct vec3 pos);
/*
 * An origami leaf unfolds as the front passes its anchor (at path length d): its progress
 * is the pull ease((front - d) / swell), and it is drawn at keyframe k of nframes
 * (ori_unfold_frames: the bud first) while the progress is in [k / nframes, (k + 1) /
 * nframes), at rest (k = nframes) from 1. live_grow_unfold_bounds gives the path lengths
 * where the keyframes change, bound[k] = front - swell ease^-1(k / nframes) for k = 0 ..
 * nframes (falling): a leaf is at keyframe k or later when d <= bound[k], so leaves sorted
 * by d are at one keyframe in runs, a few binary searches a frame whatever their number.
 * live_grow_unfold_frame is the same for one d (by the same bounds). Not drawn at all
 * past the front (d > bound[0] = front).
 */
void live_grow_unfold_bounds(double front, double swell, unsigned nframes, double *bound);
unsigned live_grow_unfold_frame(double front, double swell, unsigned nframes, double d);
