/* SPDX-License-Identifier: MIT */
/*
 * src/doc/ (floor 6 of src/FLOORS): the drawing (this header: its ops), its file
 * format, history and undo deltas, the journal, the skeleton reader. Includes the systems
 * below it.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "camera.h"
#include "error.h"
#include "event.h"
#include "tree.h"

struct gen_params;
struct vine_params;
struct wood_params;
struct tree;

/*
 * The drawing as inputs, not polygons: the random seed and the edit history (ops).
 * The tree is what you get by applying ops[0..cursor) in order from an empty canvas;
 * undo/redo move the cursor, a new op drops the ops after it.
 */

enum doc_op_kind {
	DOC_OP_STROKE = 0, /* a pen stroke, in world metres */
	DOC_OP_NEW,        /* clears the canvas (undoable) */
	DOC_OP_LIFT,       /* the 3D button: the sketch becomes a 3D tree (version 2) */
	/* Example-based editing (version 4); `branch` names the branch by its id then. */
	DOC_OP_CLONE_ADD,    /* clone mode: one more child on `branch` */
	DOC_OP_CLONE_REMOVE, /* clone mode: one child less */
	DOC_OP_ARRANGE,      /* leaf mode: leaf arrangement `pattern` (enum arrange_pattern) */
	DOC_OP_PROPAGATE,    /* propagate mode: `branch`'s children everywhere, `pattern`
			      * (enum propagate_pattern) */
	/* Functional trees (version 5, seed 001): the canvas becomes the tree `params` (owned)
	 * give with generator seed `seed`, built by the generators of params->gen_version (the
	 * line's G: GEN_VERSION for a tree made now, older in an older drawing): a template of
	 * the New strip, --generate, or one of the parameter buttons on it. */
	DOC_OP_GENERATE,
	DOC_OP_SEASON,       /* the season button: `pattern` is the season (enum season) */
	/* The leaf mode's leaf buttons (version 6, issue 15): `pattern` is the leaf kind
	 * arrangement and propagation place from then on (ori_kinds.h; -1 the drawn one). */
	DOC_OP_LEAFTYPE,
	/* The vine mode's tap (version 7, issue 16): a twining vine with parameters `vine`
	 * (owned, already scaled to the tree) planted at `plant` (world metres) and grown to
	 * its end on the tree's bark. */
	DOC_OP_VINE,
	/* Growing wood (version 8, issue 17): the grow button, a year of thickening with the
	 * settings `wood` (owned); and a skeleton.json's branches as the canvas's tree
	 * (`import`, owned: branches only, lifted), as --skeleton starts from. */
	DOC_OP_GROW,
	DOC_OP_IMPORT,
};

/* Stored as float so that what is written is exactly what is replayed. */
struct doc_point {
	float x, y;     /* world metres on the sketch plane */
	float pressure; /* 0..1 */
	uint32_t dt_us; /* since the stroke started */
};

struct doc_op {
	enum doc_op_kind kind;
	uint64_t time_us; /* when the op was made */
	enum event_tool tool;
	struct doc_point *points;
	size_t npoints;
	struct camera camera; /* strokes: the camera they were drawn in (the front view
			       * before version 3) */
	int branch;           /* editing ops: the branch they work on */
	int pattern;          /* arrange, propagate: which pattern; season: the season;
			       * leaftype: the kind */
	struct gen_params *params; /* generate: the tree's parameters and generator version
				    * (owned) */
	uint64_t seed;        /* generate: the generator's seed */
	struct vine_params *vine; /* vine: the vine's parameters (owned) */
	double plant[3];      /* vine: where it is planted, world metres */
	struct wood_params *wood; /* grow: the settings (owned) */
	struct tree *import;  /* import: the branches (owned; tree_finish'ed and freed) */
};

struct doc {
	uint64_t seed;
	struct doc_op *ops;
	size_t nops, cap;
	size_t cursor; /* ops[0..cursor) are in effect */
	struct camera view; /* how the kiosk showed the tree when it was saved (version 3) */
};

/* 2 added the lift op, 3 the camera (of strokes drawn on a turned 3D tree, and the
 * view when saved), 4 the editing ops (clone, arrange, propagate), 5 the generated trees
 * and the season, 6 the leaf type (origami leaves), 7 the vines, 8 growing wood (grow,
 * import); older files read as before. */
#define DOC_FORMAT_VERSION 8

/*
 * Limits on a drawing, far beyond what a visitor draws in a day, so that a damaged or
 * hostile file cannot make the kiosk build a mesh of gigabytes. The app never makes a
 * document past them, so whatever edaha writes it can read back.
 */
#define DOC_MAX_OPS 20000u
#define DOC_MAX_STROKE_POINTS 100000u
#define DOC_MAX_POINTS 4000000u    /* in all strokes together, generated elements counted
				    * as points (doc_op_weight) */
#define DOC_MAX_COORD_M TREE_MAX_COORD_M /* |x|, |y| on the sketch plane (tree.h) */
#define DOC_MAX_FILE_BYTES (256u << 20)
/* A grow press costs a solve of the tree's springs (up to seconds on the board): it counts
 * as this many points, so that a drawing holds at most 40 and --load stays bounded. */
#define DOC_GROW_WEIGHT 100000u

void doc_init(struct doc *d, uint64_t seed);
void doc_finish(struct doc *d);
void doc_op_finish(struct doc_op *op);
/* dst becomes a copy of src with its own points and params. 0 or -ENOMEM (dst then holds
 * nothing to free). */
int doc_op_copy(struct doc_op *dst, const struct doc_op *src);
/* Appends op at the cursor (dropping redo ops) and takes ownership of its points and
 * params.
 * Returns 0, -ENOMEM, or -ENOSPC when the op would take the drawing past a DOC_MAX_ limit
 * (op is left to the caller then). */
int doc_push(struct doc *d, struct doc_op *op);
/* What an op counts towards DOC_MAX_POINTS: a stroke its points, a generated tree its
 * branches and leaves (gen_count_branches + gen_count_leaves), a vine its budget's axis
 * points (internodes x points_per_internode), a grow press DOC_GROW_WEIGHT, an import its
 * branches' points. */
size_t doc_op_weight(const struct doc_op *op);
/* The weight of ops[0..nops). */
size_t doc_total_points(const struct doc *d);
bool doc_can_undo(const struct doc *d);
bool doc_can_redo(const struct doc *d);
bool doc_undo(struct doc *d);
bool doc_redo(struct doc *d);

/* Applies a stroke op to t: sketch_stroke (sketch.h) with the op's points, tool, camera and
 * times. SKETCH_GREW, SKETCH_CHANGED or -ENOMEM; SKETCH_GREW for any other op, or a stroke
 * without points. */
int doc_apply_stroke(struct tree *t, const struct doc_op *op);

struct tree;
/* drawing.edaha, see docs/document-format.md. The tree (built from d) is written as
 * a readable summary for other tools; loading rebuilds it from the history instead. */
int doc_serialize(const struct doc *d, const struct tree *t, struct buf *out);
/* name is used in error messages; returns 0, -EINVAL (malformed) or -ENOMEM. */
int doc_parse(const char *data, size_t len, const char *name, struct doc *d, struct error *err);
