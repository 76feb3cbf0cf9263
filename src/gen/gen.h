/* SPDX-License-Identifier: MIT */
/*
 * src/gen/ (floor 5 of src/FLOORS, beside sketch, vine and wood, which it never
 * includes): functional trees from parameters (seed 001) and their presets. Includes ori,
 * core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "error.h"
#include "season.h"
#include "tree.h"
#include "vec.h"

/*
 * Functional trees (seed 001, Haruguchi): a tree is a function of a handful of
 * parameters. Three generators, as in the paper's section 3:
 *
 *   lsystem  the MakeTree recursion (3.1, after Aono and Kunii's A-system): a trunk from
 *            trunk.start to trunk.end, every branch straight, 2 or 3 children at its tip
 *   shrub    a vertical trunk and a crown grown by the same recursion into a clipping
 *            shape (sphere, box or cone): hedges and topiary (3.2)
 *   palm     a bare trunk and a crown of drooping fronds, each a midrib with leaflets (3.2)
 *
 * The parameter file (docs/tree-params.md, `edaha-tree: 1`) is read by gen_read(); the
 * drawing stores the parameters (gen_write) and the seed, never the points
 * (docs/document-format.md, the `generate` op). Everything here is pure and deterministic:
 * the same parameters and seed give the same tree, bit for bit. docs/functional-trees.md
 * says how each generator works and why.
 */

/* The parameter file's version (`edaha-tree: N`) this edaha reads and writes. */
#define GEN_PARAMS_VERSION 1
/*
 * The generators' version, stored with every generated tree in a drawing: a later edaha
 * whose generators give other trees bumps it and keeps building older drawings as they
 * were (docs/functional-trees.md, "Generator versions"):
 *
 *   1  the first generators: a shrub's crown is the L-system recursion clipped to its
 *      shape (gen_shrub_v1.c)
 *   2  a shrub's crown is aimed at points spread over its shape's surface (gen_shrub.c,
 *      issue 24); L-system trees and palms as in 1
 */
#define GEN_VERSION 2

enum gen_type {
	GEN_LSYSTEM = 0,
	GEN_SHRUB,
	GEN_PALM,
	GEN_TYPE_COUNT
};

enum gen_clip {
	GEN_CLIP_SPHERE = 0,
	GEN_CLIP_BOX,
	GEN_CLIP_CONE,
	GEN_CLIP_COUNT
};

/* Leaf outlines (gen_leaf.c). */
enum gen_leaf {
	GEN_LEAF_OVAL = 0, /* cherry: elliptic with a drawn-out tip */
	GEN_LEAF_POINTED,  /* zelkova: narrow ovate, long-pointed, toothed */
	GEN_LEAF_ROUND,    /* box, privet: small and roundish */
	GEN_LEAF_NEEDLE,   /* yew, conifer topiary: a short narrow blade */
	GEN_LEAF_LEAFLET,  /* a palm frond's leaflet: long and narrow */
	/* Origami leaves (seed 003, ori_kinds.h), each placed in the frame of the oval
	 * leaf it replaces (ori_place.h) */
	GEN_LEAF_ENTIRE,
	GEN_LEAF_HOP,
	GEN_LEAF_MAPLE,
	GEN_LEAF_COUNT
};

#define GEN_MAX_CHILDREN 3
#define GEN_MAX_LEVELS 12
#define GEN_MIN_PRECISION 3
#define GEN_MAX_PRECISION 16 /* the mesh's most sides (MESH_MAX_SIDES) */

struct gen_params {
	enum gen_type type;
	int precision; /* sides of every branch's cross-section */
	struct vec3 trunk_start, trunk_end;
	int levels;    /* the trunk's level; level-1 branches are tips */
	int children;  /* 2 or 3 */
	double angle_min, angle_max; /* degrees between a parent's and a child's direction */
	double randomness;           /* 0..1: how much of [min, max] the angles spread over */
	double ratios[GEN_MAX_CHILDREN]; /* child i's length / its parent's */
	double spread; /* degrees between two children around their parent's axis */
	double twist;  /* degrees the branching plane turns from one generation to the next */
	double thickness;       /* the trunk's base radius, metres */
	double thickness_ratio; /* a branch's tip radius / its base radius */
	int leaf_amount;        /* leaves on each tip branch (palm: leaflets on each frond) */
	double leaf_size;       /* a leaf's length, metres */
	enum gen_leaf leaf_type;
	enum season season;
	/* shrub */
	double trunk_height;
	enum gen_clip clip;
	struct vec3 clip_center; /* sphere, box: the centre; cone: the centre of its base */
	double clip_radius;      /* sphere, cone */
	struct vec3 clip_size;   /* box: its edges along x, y, z */
	double clip_height;      /* cone */
	/* palm */
	double height;       /* the trunk's length */
	int fronds;
	double frond_length;
	double droop;        /* degrees a frond bends down from its base to its tip */
	/* The generators' version that builds the tree (1..GEN_VERSION): not a key of the
	 * parameter file but the `generate` line's G in a drawing. gen_params_default, and so
	 * gen_read and gen_preset, give GEN_VERSION; gen_read_version an older one. */
	int gen_version;
};

const char *gen_type_name(enum gen_type t);
const char *gen_clip_name(enum gen_clip c);
const char *gen_leaf_name(enum gen_leaf l);
/* The origami kind (ori_kinds.h) a leaf type is, or -1 (ORI_KIND_DRAWN): an outline. */
int gen_leaf_kind(enum gen_leaf l);
bool gen_leaf_from_name(const char *name, enum gen_leaf *l);

/* The documented defaults of a type (docs/tree-params.md): what missing keys take. */
void gen_params_default(struct gen_params *p, enum gen_type type);

/* How many branches and leaves p makes at its gen_version (a shrub: the most it can, its
 * crown being cut to its shape). */
size_t gen_count_branches(const struct gen_params *p);
size_t gen_count_leaves(const struct gen_params *p);

/*
 * Whether p is within every limit: each value in its documented range and the tree within
 * TREE_MAX_BRANCHES and TREE_MAX_LEAVES. Returns 0, or -EINVAL with the parameter at
 * fault in *key, as a key path ("levels", "angle.min"), and what is wrong in err
 * ("levels: 13 is not within 1..12").
 */
int gen_params_check(const struct gen_params *p, const char **key, struct error *err);

/*
 * Reads a tree parameter file (YAML, docs/tree-params.md) from memory. name is used in
 * messages; line_offset is added to every line number (a drawing's `generate` line holds
 * the parameters in YAML's flow style on one line). Unknown keys, keys of another type,
 * bad values, values out of range and trees over the limits are refused: -EINVAL and
 * "NAME:LINE: what is wrong" in err. 0, -EINVAL or -ENOMEM.
 */
int gen_read(const char *data, size_t len, const char *name, unsigned long line_offset,
	     struct gen_params *p, struct error *err);
/* gen_read for a tree of generator version `version` (1..GEN_VERSION; else -EINVAL): a
 * drawing's `generate` line. Its limits are that version's counts (gen_count_branches). */
int gen_read_version(const char *data, size_t len, const char *name, unsigned long line_offset,
		     int version, struct gen_params *p, struct error *err);

/*
 * p as YAML in flow style, on one line without a line end: every key of its type, in
 * the documented order, numbers printed so that gen_read gives back exactly p.
 * 0 or -ENOMEM (out as it was).
 */
int gen_write(const struct gen_params *p, struct buf *out);

/*
 * Builds the tree p describes into t (emptied first) with the generators of
 * p->gen_version: every element with origin ORIGIN_GENERATE and its level, the tree 3D
 * (`lifted`), t->sides = p->precision and t->season = p->season. seed is the generator's
 * seed: only angles are random. 0, -EINVAL (p fails gen_params_check) or -ENOMEM (t then
 * empty).
 */
int gen_build(struct tree *t, const struct gen_params *p, uint64_t seed);

/* The kiosk's parameter buttons (docs/functional-trees.md says what each changes for each
 * type). Each makes a new parameter set from p, at GEN_VERSION whatever p's (a press on an
 * older drawing's tree grows it as this edaha does); false when it would change nothing
 * or pass a limit (then q is p). */
enum gen_adjust {
	GEN_MORE = 0, /* more branches: levels + 1 (palm: 2 fronds more) */
	GEN_FEWER,
	GEN_WIDER,    /* the crown opens: angles and spread (palm: longer fronds) */
	GEN_NARROWER,
	GEN_TALLER,   /* ratios (shrub: its shape; palm: its trunk) */
	GEN_SHORTER,
	GEN_LEAFIER,  /* more leaves on each tip */
	GEN_BARER,
	GEN_ADJUST_COUNT
};
bool gen_adjust(const struct gen_params *p, enum gen_adjust what, struct gen_params *q);

/* The presets of the kiosk's New strip (presets/\*.yaml, compiled in by meson): their
 * names ("cherry", ...) and the parameters they read to. */
enum gen_preset {
	GEN_PRESET_CHERRY = 0,
	GEN_PRESET_ZELKOVA,
	GEN_PRESET_HEDGE,
	GEN_PRESET_BALL,
	GEN_PRESET_CONE,
	GEN_PRESET_PALM,
	GEN_PRESET_COUNT
};
const char *gen_preset_name(enum gen_preset p);
/* 0, or -EINVAL/-ENOMEM when the compiled-in file does not read (a build that got past its
 * test cannot). */
int gen_preset(enum gen_preset which, struct gen_params *p, struct error *err);
