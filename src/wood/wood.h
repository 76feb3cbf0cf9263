/* SPDX-License-Identifier: MIT */
/*
 * src/wood/ (floor 5 of src/FLOORS, beside sketch, gen and vine, which it never
 * includes): stress-driven thickening (seed 002): voxels, the mass-spring solve, the
 * iso-surface. Includes mesh, core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "mesh.h"
#include "tree.h"
#include "vec.h"

/*
 * Growing wood (seed 002, Ohshida, Muraoka and Chiba; issue 17): a tree's thick branches
 * registered in a voxel space as a density field, a mass-spring model of the voxels at
 * rest under gravity (and wind), and the wood thickened in the surface layer where it is
 * compressed (conifers: compression wood) or stretched (broadleaf trees: tension wood);
 * the bark drawn back from the field as its iso-surface at density 0.5. docs/wood.md says
 * how; docs/wood-format.md is the settings file (`edaha-wood: 1`). Pure and deterministic:
 * the same tree and settings give the same field, bit for bit.
 *
 * Units in the grid: lengths in voxels (a spring's rest length is 1, sqrt 2 or sqrt 3),
 * every spring's constant k = 1, every mass m = 1, forces in those units; `gravity` and
 * `wind` are accelerations in them (docs/wood.md: "Units").
 */

/* The settings file's version (`edaha-wood: N`) this edaha reads. */
#define WOOD_PARAMS_VERSION 1

enum wood_mode {
	WOOD_CONIFER = 0, /* thickens where compressed */
	WOOD_BROADLEAF,   /* thickens where stretched */
};

struct wood_params {
	enum wood_mode mode;
	int grid;        /* cells along the padded box's longest side: 64 (the kiosk) or 128 */
	double alpha;    /* Csi = (alpha * C_den * f)^beta */
	double beta;
	double gravity;  /* downward acceleration, voxel units (k = 1, m = 1) */
	double wind[3];  /* a horizontal acceleration on every mass point (y ignored) */
};

/* The defaults (docs/wood-format.md): broadleaf, the 64 grid, beta 1, no wind; alpha and
 * gravity these. */
#define WOOD_ALPHA_DEFAULT 2e4
#define WOOD_GRAVITY_DEFAULT 2e-7
void wood_params_default(struct wood_params *p);
/* Within every limit: 0, or -EINVAL with err naming the key (*key set, may be NULL). */
int wood_params_check(const struct wood_params *p, const char **key, struct error *err);
/*
 * Reads a settings file (docs/wood-format.md) from memory; name is the file's name for
 * messages, line_offset the lines before the text in its file (0 for a file of its own).
 * 0, or -EINVAL/-ENOMEM with err "NAME:LINE: what is wrong" (*p unchanged).
 */
int wood_read(const char *data, size_t len, const char *name, unsigned long line_offset,
	      struct wood_params *p, struct error *err);
#define WOOD_READ_MAX_BYTES 65536

/* Step 1: the paper's power law at every fork, d^a = d1^a + d2^a + ..., with a = 2.5. */
#define WOOD_POWER_LAW_A 2.5
/*
 * The radii so that at every fork the parent's radius at the point below it, to the a-th
 * power, is the sum of its radius at the point above and its children's root radii there
 * (children whose parent_t is in (t_k, t_k+1] join below point k + 1, at point k); each
 * tip keeps its drawn radius, and between forks a branch keeps its drawn taper (the ratio
 * of neighbouring radii), from the tips down to the trunk. Applying it again changes
 * nothing. 0 or -ENOMEM (t unchanged). wood_radii.c.
 */
int wood_power_law(struct tree *t, double a);

/* A branch is voxelised (as octagonal prisms, one an internode) when its radius is at
 * least this many voxels at its root; thinner twigs keep their swept meshes. */
#define WOOD_PRISM_MIN_VOXELS 1.5
#define WOOD_PRISM_SIDES 8
/* Rays a voxel along z (step 3): the centre and four about it. */
#define WOOD_RAYS 5
/* The box about the prisms is padded by this fraction of its longest side on every
 * side, so that the wood has room to grow. */
#define WOOD_PAD 0.15

/* Flags of a voxel. */
enum {
	WOOD_MASS = 1u << 0,  /* a kept mass point: density above 0, held from the base */
	WOOD_FIXED = 1u << 1, /* within one voxel of the ground under the trunk */
};

/* The voxel space: nx * ny * nz cells of side h metres, x fastest, then y, then z;
 * `origin` the grid's minimum corner (world metres, y up). */
struct wood_grid {
	int nx, ny, nz;
	struct vec3 origin;
	double h;
	double *density;      /* 0..1 a voxel */
	double *compression;  /* per voxel: the sum of |S| over its compressed springs */
	double *tension;      /* per voxel: the sum of S over its stretched springs */
	double *displacement; /* 3 a voxel: its mass point's, voxel units (0 elsewhere) */
	uint8_t *flags;
};

/* An empty grid of the given size (all zero). 0, -EINVAL (a size < 1 or above 1024 a
 * side, h not positive and finite) or -ENOMEM. */
int wood_grid_create(struct wood_grid *g, int nx, int ny, int nz, struct vec3 origin,
		     double h);
void wood_grid_finish(struct wood_grid *g);
static inline size_t wood_index(const struct wood_grid *g, int x, int y, int z)
{
	return (size_t)x + (size_t)g->nx * ((size_t)y + (size_t)g->ny * (size_t)z);
}
static inline size_t wood_cells(const struct wood_grid *g)
{
	return (size_t)g->nx * (size_t)g->ny * (size_t)g->nz;
}

/*
 * Steps 2-3 (wood_voxel.c). The prisms: one octagonal prism (WOOD_PRISM_SIDES) an
 * internode of every branch of t at least WOOD_PRISM_MIN_VOXELS voxels thick at its root,
 * for a grid of cells along its padded box's longest side, as a closed, outward-oriented
 * triangle mesh (each prism its own closed solid; they overlap at forks). *voxelised
 * (t->nbranches entries, may be NULL) says which branches are.
 * The grid depends on the branches chosen and they on its h, so (docs/wood.md): thickest
 * first, equal radii together, while the thinnest so far is thick enough in the grid of
 * those so far; a branch thick enough only in a grid made without it is left out.
 * Appended to out (on an empty out, wood_grid_for makes the grid they were chosen for).
 * 0, -EINVAL (cells not 1..1024) or -ENOMEM (out and *voxelised unchanged).
 */
int wood_prisms(const struct tree *t, int cells, struct mesh *out, bool *voxelised);
/* The grid for those prisms: their box padded by WOOD_PAD on every side, `cells` along
 * its longest side, every density 0. 0, -EINVAL (nothing to voxelise) or -ENOMEM. */
int wood_grid_for(const struct mesh *prisms, int cells, struct wood_grid *g);
/*
 * Each voxel's density: the part of its WOOD_RAYS rays along z (through the voxel's
 * footprint, parallel) inside the union of the prisms (a point is inside when the signed
 * crossings below it sum above 0), averaged: 0..1. Adds to the field (call on a grid of
 * zeros). The rays are the voxel's centre and (+-1/4, +-1/4) of a voxel about it; a ray
 * exactly on an edge or a corner is counted as the ray moved by (+e, +e^2), e > 0 tiny
 * (docs/wood.md), so each crossing once. 0, -EINVAL (an index past the vertices) or
 * -ENOMEM.
 */
int wood_voxelise(struct wood_grid *g, const struct mesh *prisms);

/*
 * Steps 4-5 (wood_spring.c; wood_solve.c and wood_mg.c; wood_euler.c). Mass points are
 * the voxels of density above 0; springs join each to its 26 neighbours that are mass
 * points (rest lengths 1, sqrt 2, sqrt 3 voxels, k = 1, m = 1, whatever the density).
 * Fixed: the mass points within one voxel of the ground (the trunk's root's height,
 * `ground_y` in metres), those whose centre's height origin.y + (y + 0.5) h is at most
 * ground_y + h: the trunk's foot (and any wood lower). Kept: the fixed points and then,
 * again and again, every mass point whose springs to kept ones pull in all three
 * directions (their rest directions span space), so that the kept points' linearised
 * springs hold every one of them (K is positive definite). The others are dropped
 * (*dropped; their flags and fields 0): those not joined to a fixed point through springs,
 * and the few joined but not held (*loose: a voxel hanging by a corner or an edge, a sheet
 * one voxel thin), which linear springs cannot hold still. Then the rest state under
 * gravity and wind, solved directly as the static equilibrium of the springs (small
 * displacements: K u = f, f = m (wind.x, -gravity, wind.z) on every free point,
 * conjugate gradients preconditioned by a multigrid cycle, to a relative force residual
 * |f - K u| / |f| of at most 1e-6), into displacement, compression, tension and flags of
 * the kept points (every other voxel's fields 0). A spring's force S = k e . (u_j - u_i),
 * e its rest direction, S > 0 stretched; a point's compression is the sum of |S| over its
 * compressed springs and its tension the sum of S over its stretched ones (the paper's
 * sums, of magnitudes: a vector sum would cancel inside an evenly loaded column). With no
 * load (gravity 0, no wind) u = 0 and every force 0, without an iteration. The forces are
 * in proportion to the load. 0; -EINVAL (no point fixed; ground_y, gravity or wind not
 * finite), -ENOMEM or -ETIMEDOUT (the iterations did not converge: not seen); on an error
 * every field but density is 0.
 */
struct wood_solve_stats {
	size_t points, fixed, springs, dropped; /* kept points, fixed ones, springs between kept
						   points (each once), mass points dropped */
	size_t loose;    /* of dropped: joined to a fixed point, but not held in 3 directions */
	int iterations;  /* wood_rest: CG's; wood_rest_euler: time steps */
	double residual; /* |f - K u| / |f| reached (wood_rest_euler: |net force| / |f|) */
};
int wood_rest(struct wood_grid *g, const struct wood_params *p, double ground_y,
	      struct wood_solve_stats *stats);
/*
 * The paper's own scheme for the same kept springs: improved Euler with damping C,
 *   v(t + dt) = v(t) + dt (g + sum S - C v(t)),  h(t + dt) = h(t) + dt/2 (v(t) + v(t + dt))
 * (m = 1), on full springs (S = k (l - l0) along the current direction, |l - l0| limited
 * to WOOD_SPRING_LIMIT), from rest at the rest positions until every free point's speed
 * and net force are below `tol` or max_steps pass: for small cases, to check wood_rest
 * against (they differ by the springs' turning, in proportion to the displacements: within
 * 1% where the largest is about 0.01 voxel). Stable when damping > dt * 26/3 (K's largest
 * eigenvalue is at most 2 * 26/3): e.g. dt 0.1, damping 1. Fills the same fields from the
 * last state, at rest or not (compression and tension from its springs' S). 0, -ETIMEDOUT
 * (not at rest in max_steps), -EINVAL (as wood_rest; dt or tol not above 0, damping or
 * max_steps below 0) or -ENOMEM.
 */
#define WOOD_SPRING_LIMIT 0.5
int wood_rest_euler(struct wood_grid *g, const struct wood_params *p, double ground_y,
		    double dt, double damping, long max_steps, double tol,
		    struct wood_solve_stats *stats);

/*
 * Step 6 (wood_thicken.c): Csi = (alpha * density * f)^beta in every mass point of the
 * surface layer (density below 1), f its compression (conifer) or tension (broadleaf),
 * all computed from the field before any is added; added to its density; what passes 1.0
 * goes to the voxels below 1.0 about it in proportion to 1 / distance, ring by ring
 * outwards until all of it is placed (a voxel at 1.0 takes no more). Every density stays
 * within 0..1 and none decreases. *added: the wood added (sum of Csi), *lost: what found
 * no room inside the grid (its edge); either may be NULL. Each Csi goes into its own voxel
 * first, then the excesses spread all at once, in rounds (no source before another: a
 * voxel offered more than its room shares it among its offers); a ring's share is split
 * among its voxels inside the grid (docs/wood.md "Step 6: thickening"). Flags,
 * compression and tension are left as they were. 0, -EINVAL (mode unknown, or a Csi not
 * finite: alpha, beta or a force out of range) or -ENOMEM; on an error the field is
 * unchanged.
 */
int wood_thicken(struct wood_grid *g, const struct wood_params *p, double *added, double *lost);

/*
 * Step 7 (wood_iso.c): the bark as the iso-surface of the density at `iso` (0.5) by Doi's
 * method (marching tetrahedra, six a cube), in world metres, with smooth normals (the
 * density's gradient): closed, consistently oriented (outward), no degenerate triangles.
 * Appended to out. 0 or -ENOMEM.
 * Samples at the voxels' centres, 0 outside the grid (closed at its sides too); inside is
 * density >= iso; each vertex kept 1e-3 of its edge from either end; a manifold for any
 * field; on -ENOMEM out keeps what it had (docs/wood.md, "Step 7").
 */
int wood_iso(const struct wood_grid *g, double iso, struct mesh *out);
/*
 * The triangles of an iso-surface are chords inside curved bark (a 1.5-voxel branch loses
 * a tenth): moves the vertices of m from first (its triangles from first_index) along
 * their normals by their chords' sag, all by one factor, so that the volume is `wood`
 * (m^3, the sum of density h^3); a face that would turn over keeps its corners. Normals
 * and triangles unchanged. 0 or -ENOMEM (m unchanged).
 */
int wood_iso_keep_volume(struct mesh *m, size_t first, size_t first_index, double wood,
			 double h);

/* Frames of a press's swelling on screen, its bark the last (docs/wood.md). */
#define WOOD_SWELL_FRAMES 8

/*
 * A tree's wood through its presses (wood_press.c): begun once (the power law on the
 * tree, its prisms voxelised: density0), then each press finds the rest state and
 * thickens, from the field the press before left.
 */
struct wood {
	struct wood_params p;
	struct wood_grid g;
	double *density0;  /* the field before the first press */
	double ground_y;   /* the trunk's foot, metres */
	bool *voxelised;   /* per branch of the tree begun on */
	size_t nbranches;
	int presses;
	/* the last press's */
	struct wood_solve_stats solve;
	double added, lost;
	/* the bark of the voxelised branches: the field's iso-surface at 0.5 (wood_iso),
	 * world metres; made by wood_press (empty before the first) */
	struct mesh bark;
	/* The last press's swelling, for the screen: the iso-surfaces of the field between
	 * before and after it, at k / WOOD_SWELL_FRAMES for k = 1 .. nswell; bark is the
	 * last frame. Not copied (wood_copy): a tree undone to shows its bark at rest. */
	struct mesh swell[WOOD_SWELL_FRAMES - 1];
	int nswell;
};
/* Applies the power law to t (its radii change: the twigs' meshes show it), and registers
 * its thick branches in a new grid (p->grid cells); sets t's wood hooks (wood_tree_ops) so
 * that t can own w. 0, -EINVAL (no branch thick enough to
 * voxelise, or no trunk) or -ENOMEM (w empty then). */
int wood_begin(struct wood *w, struct tree *t, const struct wood_params *p);
/* One press: the rest state (wood_rest), then thickening (wood_thicken). 0, -EINVAL (no
 * point fixed) or -ENOMEM. */
int wood_press(struct wood *w);
void wood_finish(struct wood *w);
/*
 * A year of growth on tree t (what a grow op does): its wood begun if it has none (the
 * power law, the grid: wood_begin), a press, and its leaves and vines moved out of the new
 * bark (wood_move_out). Pure: a copy of the tree grown on another thread gives the same
 * tree. 0; 1 when nothing holds wood (no branch thick enough, or none on the ground: the
 * radii alone may have changed); -ENOMEM (t's wood dropped).
 */
int wood_grow(struct tree *t, const struct wood_params *p);
/*
 * After a press (wood_move.c, docs/wood.md "Leaves and vines move out"): what the new bark
 * buried moves out of it. Buried: the density there (wood_density_at) above 0.5. A leaf
 * with a point buried moves rigidly across its branch's axis (at branch_t, towards its
 * centroid; a leaf on a branch not voxelised, away from the nearest voxelised axis) by
 * the smallest shift that unburies it and 0.05 voxel more; its `local` follows. A buried
 * vine axis point (every shoot's, raw) moves away from the nearest voxelised axis to the
 * surface plus the stem's radius; the smoothed axes and meshes, drawn from it, follow;
 * contacts stay. Nothing else changes, bit for bit. Deterministic, no allocation:
 * 0, or -EINVAL (w has no field).
 */
int wood_move_out(const struct wood *w, struct tree *t);
/* The density at p (world metres): the voxel centres' samples trilinearly interpolated, 0
 * outside the grid. */
double wood_density_at(const struct wood_grid *g, struct vec3 p);
/* dst (not initialised) becomes a copy of src. 0 or -ENOMEM (dst empty then). */
int wood_copy(struct wood *dst, const struct wood *src);
/* Bytes w's arrays take. */
size_t wood_bytes(const struct wood *w);
/* How a tree frees, copies and counts its wood and which branches it holds (tree.h's
 * hooks): wood_begin sets it on the tree it begins on, and so does an undo that brings a
 * wood back (tree_delta_swap). */
extern const struct tree_wood_ops wood_tree_ops;
struct buf;
/* The settings as one line of YAML in flow style, every key, that wood_read reads back
 * bit for bit (how a drawing stores a grow press). 0 or -ENOMEM (out as it was). */
int wood_write(const struct wood_params *p, struct buf *out);

/* voxels.json and voxels.bin (docs/wood.md, "Voxels dumped"): w's grid, settings and
 * presses; its fields density0, density, compression, tension, displacement (3, f64) and
 * flags (u8), x fastest. Appended: 0 or -ENOMEM (both as they were). wood_dump.c. */
int wood_dump(const struct wood *w, struct buf *json, struct buf *bin);
