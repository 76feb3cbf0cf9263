/* SPDX-License-Identifier: MIT */
/*
 * src/ori/ (floor 3 of src/FLOORS): origami leaves (seed 003): a design's crease
 * pattern, its fold and opening, the presets and their placement. Includes core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "error.h"

/*
 * Origami leaves (seed 003, Kaino et al.): a leaf is a crease pattern that folds flat in
 * the bud; the margin is a cut across the folded leaf, and unfolding gives lobes (maple)
 * or teeth (hop). docs/origami-leaves.md says how and why; docs/leaf-format.md is the
 * design file (`edaha-leaf: 1`), read by ori_read().
 *
 * A design is a few angles. The leaf base O is the origin, the midrib runs along +y,
 * "right" is +x. From O run, right to left: the right edge of the petiole's notch, the
 * side parts' veins (valleys) separated by boundary mountains, the middle part's midrib
 * (a valley, with nodes that send out pairs of side veins), the left side parts mirrored,
 * the notch's left edge. ori_build() turns a design into the flat pattern, its folded
 * (bud) state and the margin; ori_open() places it in 3D at an opening t. Everything is
 * pure and deterministic.
 */

/* The design file's version (`edaha-leaf: N`) this edaha reads. */
#define ORI_DESIGN_VERSION 1

#define ORI_NAME_MAX 32
#define ORI_MAX_SIDES 4 /* side parts on each side of the middle one */
#define ORI_MAX_NODES 4 /* nodes on the midrib, or on one side part's vein */
#define ORI_MAX_FORKS 3 /* times a side part's vein forks on its way to the margin */
#define ORI_MAX_LEAF_NODES (ORI_MAX_NODES * (2 * ORI_MAX_SIDES + 1)) /* in a whole leaf */
#define ORI_CURVE_POINTS 12 /* points of a curved cut between O and the tip */

enum ori_fold {
	ORI_FOLD_FAN = 0, /* parts between boundary mountains, each folded on its vein */
	ORI_FOLD_HALF,    /* an entire leaf folded in two on its midrib, a curved cut */
};

/* A node of the midrib or of a side part's vein: a pair of side veins (valleys) at phi from
 * the vein's direction and, between each and the vein, an extra mountain at psi < phi. [0]
 * right (clockwise of the vein), [1] left; the pattern is symmetric, so they must be
 * equal. */
struct ori_node {
	double at; /* along the vein, fraction of its length to its tip, increasing from O */
	double phi[2], psi[2]; /* degrees */
	unsigned long line;    /* where the design says it (0: not from a file) */
};

/* A part beside the middle one, counted from the middle outwards; the left side mirrors
 * the right. Its vein bisects its angle at O; each fork splits a vein into children at +a
 * and -b degrees from its direction with an extra mountain at a - b between them. A vein
 * without forks may have nodes, as the midrib does: each a tooth on either edge of the
 * lobe. */
struct ori_side {
	double angle;   /* the part's angle at O, degrees */
	int forks;      /* 0..ORI_MAX_FORKS */
	double fork_at; /* where a vein forks: fraction of its length to the cut */
	double fork_a, fork_b; /* degrees */
	size_t nnodes;  /* nodes on the vein (not with forks) */
	struct ori_node nodes[ORI_MAX_NODES];
	unsigned long line;
};

struct ori_design {
	char name[ORI_NAME_MAX];
	enum ori_fold fold;
	double size;      /* the midrib's length, metres */
	double rest;      /* the opening a grown leaf rests at (curled: see ori_open) */
	double middle[2]; /* the middle part's angle at O right and left of the midrib, degrees */
	size_t nnodes;
	struct ori_node nodes[ORI_MAX_NODES];
	size_t nsides;
	struct ori_side sides[ORI_MAX_SIDES];
	/* fan: each part is cut on the line through its junction (where its boundary
	 * mountains meet the margin, `junction` x size from O: neighbours meet there) and its
	 * vein's tip, at the spiral's r = size (1 - theta / theta0) for a vein theta degrees
	 * from the midrib (section 2.1) */
	double junction, theta0;
	/* half: the cut is the curve x = width * size * sin(pi s)^power, y = s * size */
	double width, power;
	/* where the design file says each of these (0: not from a file): for messages */
	unsigned long line, line_middle, line_cut;
};

/* Sets the defaults of a fan (a plain five-lobed leaf) or a half fold. */
void ori_design_default(struct ori_design *d, enum ori_fold fold);

/*
 * Reads a design file (docs/leaf-format.md) from memory. name is the file's name for
 * messages. 0, or -EINVAL/-ENOMEM with err "NAME:LINE: what is wrong" (*d unchanged). A
 * design that reads but cannot fold (ori_build refuses it) is refused here too, at the
 * line of what is wrong.
 */
int ori_read(const char *data, size_t len, const char *name, struct ori_design *d,
	     struct error *err);
#define ORI_READ_MAX_BYTES 65536
#define ORI_READ_MAX_DEPTH 6

/* The compiled-in presets (presets/leaves/: entire, hop, maple). NULL if no such. */
const char *const *ori_preset_names(size_t *n);
int ori_preset(const char *name, struct ori_design *d, struct error *err);

enum ori_crease_type {
	ORI_MOUNTAIN = 0,
	ORI_VALLEY,
};

/* How a crease's fold angle follows the opening (ori_open). */
enum ori_rule {
	ORI_RULE_BASE = 0, /* from O: pi (1 - t) */
	ORI_RULE_FORK_CHILD, /* tan(rho_parent / 2) = k tan(rho / 2) */
	ORI_RULE_FORK_MOUNTAIN, /* rho_parent */
	ORI_RULE_NODE_VEIN,     /* a node's side vein: as the midrib entering it */
	ORI_RULE_NODE_MOUNTAIN, /* a node's extra mountain: closure (solved) */
	ORI_RULE_NODE_MIDRIB,   /* the midrib leaving a node: closure (solved) */
};

struct ori_crease {
	int a, b; /* vertices: a nearer O in the crease tree, b the far end */
	enum ori_crease_type type;
	enum ori_rule rule;
	int parent; /* the crease whose fold angle this one's follows; -1 for BASE */
	double k;   /* FORK_CHILD */
	int node;   /* NODE_*: the node's index in the leaf's nodes */
};

/* A face: vertices face_index[face_start[f] .. + face_len[f]), counter-clockwise. */
struct ori_leaf {
	size_t nvertices;
	double (*flat)[2];   /* the flat pattern, metres */
	double (*folded)[2]; /* at t = 0: every face reflected across the creases between it
			      * and the root face (the middle part's, right of the midrib) */
	size_t ncreases;
	struct ori_crease *creases;
	size_t nmargin;
	int *margin; /* the outline, counter-clockwise from O */
	size_t nfaces;
	size_t *face_start, *face_len;
	int *face_index;
	/* The placing order for ori_open: faces from the root, each reached across a crease. */
	int *face_from;   /* [f]: the face it is placed from (-1: the root) */
	int *face_across; /* [f]: the crease crossed */
	int root_face;
	/* The veins' nodes, in the walk's order (along each vein from O): their creases and
	 * angles (radians), for ori_open's closure. */
	size_t nnodes;
	struct ori_node_geo {
		int in, out, vein[2], mountain[2]; /* creases; [0] right, [1] left */
		double phi, psi;
		int part; /* the part whose vein it is on, right to left (the midrib's: nsides) */
		bool midrib;
	} *nodes;
	/* The lobes' tips against the spiral's targets (fan only): for a report. */
	size_t nlobes;
	struct ori_lobe {
		double theta; /* the vein's angle from the midrib, degrees */
		double target, tip; /* metres from O: r0 (1 - theta/theta0) and the farthest
				     * margin point of the part */
	} *lobes;
	int *vertex_part; /* [v]: the part a margin vertex cuts (from 0, right to left) */
	int tip;          /* the midrib's tip: the vertex at (0, size); O is vertex 0 */
	double size;
	double rest;
};

void ori_leaf_init(struct ori_leaf *l);
void ori_leaf_finish(struct ori_leaf *l);

/*
 * Builds the pattern. name (a file's) names what is refused: "NAME:LINE: what", the line
 * the design's element's. -EINVAL for a design that cannot fold flat (crossing creases,
 * a span of 360 degrees or more, an asymmetric middle, a cut that misses a fork), -ENOMEM.
 */
int ori_build(const struct ori_design *d, const char *name, struct ori_leaf *l,
	      struct error *err);

/*
 * The vertices in 3D at opening t in [0, 1] (0: flat-folded in the bud, 1: flat), metres:
 * rigid, faces turn only about their creases; the midrib's first segment stays on +y and
 * the pattern stays symmetric about the plane x = 0. out has nvertices rows. 0, or
 * -EDOM if a midrib node's closure cannot be solved (not for a design ori_build took).
 */
int ori_open(const struct ori_leaf *l, double t, double (*out)[3]);

/* n >= 2 openings evenly from 0 to 1 (keyframes), in one pass: out holds n x nvertices
 * rows, opening k / (n - 1) from row k x nvertices. As ori_open gives each. */
int ori_open_frames(const struct ori_leaf *l, size_t n, double (*out)[3]);

/*
 * A new leaf unfolding from the bud to its rest, as n keyframes (out: n x nvertices rows):
 * keyframe j is the path at s = j / n, where s in [0, ORI_UNFOLD_OPEN] opens the leaf from
 * 0 to flat and the rest of the way curls it to its rest (the mirror of the leaf opened
 * back to `rest`, as ori_rest): s = 1 would be the leaf at rest, which is not a keyframe.
 */
#define ORI_UNFOLD_FRAMES 10
#define ORI_UNFOLD_OPEN 0.8
int ori_unfold_frames(const struct ori_leaf *l, size_t n, double (*out)[3]);

/* A grown leaf's shape: the mirror (z -> -z) of the leaf opened to its rest: curling is
 * not the opening run backwards. */
int ori_rest(const struct ori_leaf *l, double (*out)[3]);

struct mesh;
/*
 * Appends the leaf's faces at positions pos (nvertices rows, metres) to m: each face its
 * own vertices with its own normal (flat shading shows the folds), fanned into triangles
 * counter-clockwise seen from the leaf's front (+z when flat; leaves are drawn
 * double-sided). xf (row-major 3x4, NULL: none) moves them; it may scale uniformly. 0 or
 * -ENOMEM (m unchanged).
 */
int ori_mesh_append(const struct ori_leaf *l, const double (*pos)[3], const double *xf,
		    struct mesh *m);
/* Triangles a leaf adds: the sum over faces of their corners minus 2. */
size_t ori_mesh_triangles(const struct ori_leaf *l);
