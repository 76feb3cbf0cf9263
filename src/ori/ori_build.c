/* SPDX-License-Identifier: MIT */
/*
 * The crease pattern of an origami leaf, its folded (bud) state and its margin
 * (procedures 1-4 of seed 003; docs/origami-leaves.md).
 *
 * The creases form a tree rooted at the leaf base O. Walking round it counter-clockwise
 * (right notch edge, right parts, midrib, left parts, left notch edge) visits the faces in
 * order: every crease that ends on the margin (a ray) separates a face from the next, and
 * the next face's folded map is the current one composed with the reflection across that
 * crease. Where a crease ends inside the leaf (a fork, a node of the midrib) the walk
 * goes round its far vertex and comes back: the face it comes back in must map as the face
 * it left, reflected across that crease; that is Kawasaki's theorem, checked at every
 * such vertex. The margin is where each ray's folded image meets its part's cut: the
 * geometry of a fork (how far along its vein) depends on that, so the pattern is built
 * during the walk.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ori_private.h"
#include "vec.h"

static int full(struct ori_builder *b)
{
	return error_at(b->err, -EINVAL, b->name, b->d->line,
			"too many creases: not a leaf this edaha can fold");
}

static void dir_at(double deg, double out[2])
{
	out[0] = cos(deg * VEC_PI / 180.0);
	out[1] = sin(deg * VEC_PI / 180.0);
}

/* d turned counter-clockwise by deg. */
static void dir_turn(const double d[2], double deg, double out[2])
{
	double c = cos(deg * VEC_PI / 180.0), s = sin(deg * VEC_PI / 180.0);
	double x = c * d[0] - s * d[1], y = s * d[0] + c * d[1];

	out[0] = x;
	out[1] = y;
}

static int add_vertex(struct ori_builder *b, double x, double y)
{
	if (b->nv == ORI_MAX_V)
		return -1;
	b->v[b->nv][0] = x;
	b->v[b->nv][1] = y;
	b->part_of[b->nv] = b->part;
	return (int)b->nv++;
}

static int add_crease(struct ori_builder *b, int from, int to, enum ori_crease_type type,
		      enum ori_rule rule, int parent, double k, int node)
{
	if (b->nc == ORI_MAX_C)
		return -1;
	b->c[b->nc] = (struct ori_crease){ .a = from, .b = to, .type = type, .rule = rule,
					   .parent = parent, .k = k, .node = node };
	return (int)b->nc++;
}

static int face_push(struct ori_builder *b, int v)
{
	if (b->ncur == ORI_MAX_CUR)
		return full(b);
	b->cur[b->ncur++] = v;
	return 0;
}

/* Ends the face being walked; the next starts across crease c (-1: none, the last). */
static int face_close(struct ori_builder *b)
{
	if (b->nf == ORI_MAX_F || b->nfi + b->ncur > ORI_MAX_FI)
		return full(b);
	b->fstart[b->nf] = b->nfi;
	b->flen[b->nf] = b->ncur;
	memcpy(b->fidx + b->nfi, b->cur, b->ncur * sizeof(*b->cur));
	b->nfi += b->ncur;
	b->fmap[b->nf] = b->M;
	b->across[b->nf] = b->cur_across;
	b->from[b->nf] = b->nf > 0 ? (int)b->nf - 1 : -1;
	b->nf++;
	b->ncur = 0;
	return 0;
}

static int refuse(struct ori_builder *b, const char *what)
{
	return error_at(b->err, -EINVAL, b->name, b->part_line, "%s%s%s", b->part_what,
			b->part_what[0] ? ": " : "", what);
}

/* Which side of the part's cut a folded point is on: > 0 O's. */
static double cut_side(const struct ori_builder *b, const double p[2])
{
	double ab[2] = { b->cut_b[0] - b->cut_a[0], b->cut_b[1] - b->cut_a[1] };
	double ap[2] = { p[0] - b->cut_a[0], p[1] - b->cut_a[1] };

	return cross2(ab, ap) * b->inside;
}

/* How far along d from s (flat) the folded image of the ray meets the part's cut; < 0 if
 * it never does. */
static double cut_length(const struct ori_builder *b, const double s[2], const double d[2])
{
	double p[2], q[2], ab[2] = { b->cut_b[0] - b->cut_a[0], b->cut_b[1] - b->cut_a[1] };
	double den, u, ap[2];

	iso_apply(&b->M, s, p);
	iso_dir(&b->M, d, q);
	den = cross2(q, ab);
	if (fabs(den) < 1e-12)
		return -1;
	ap[0] = b->cut_a[0] - p[0];
	ap[1] = b->cut_a[1] - p[1];
	u = cross2(ap, ab) / den;
	return u > 1e-9 ? u : -1;
}

/* Sets the cut of the part whose right edge (a ray from O along edge) the walk is at:
 * through its junction on that edge and its vein's tip at r. */
static void set_cut(struct ori_builder *b, const double edge[2], const double vein[2], double r)
{
	double m = b->d->junction * b->d->size, j[2] = { m * edge[0], m * edge[1] };
	double t[2] = { r * vein[0], r * vein[1] }, o[2] = { 0, 0 }, oo[2];

	iso_apply(&b->M, j, b->cut_a);
	iso_apply(&b->M, t, b->cut_b);
	b->inside = 1.0;
	iso_apply(&b->M, o, oo);
	b->inside = cut_side(b, oo) >= 0 ? 1.0 : -1.0;
}

/* A crease from vertex s that runs to the margin. */
static int ray(struct ori_builder *b, int s, const double d[2], enum ori_crease_type type,
	       enum ori_rule rule, int parent, double k, int node, int *out)
{
	double u = cut_length(b, b->v[s], d);
	int e, c;
	struct iso r;

	if (u < 0)
		return refuse(b, "a crease runs away from the cut: the leaf would have no margin there");
	e = add_vertex(b, b->v[s][0] + u * d[0], b->v[s][1] + u * d[1]);
	if (e < 0)
		return full(b);
	c = add_crease(b, s, e, type, rule, parent, k, node);
	if (c < 0)
		return full(b);
	if (out)
		*out = c;
	b->margin[b->nmargin++] = e;
	if (face_push(b, e) < 0 || face_close(b) < 0)
		return -EINVAL;
	r = iso_reflect(b->v[s], d);
	b->M = iso_mul(&b->M, &r);
	b->cur_across = c;
	if (face_push(b, e) < 0 || face_push(b, s) < 0)
		return -EINVAL;
	return 0;
}

/* A crease from s to v inside the leaf: begins the walk round v. */
static int inner_begin(struct ori_builder *b, int s, double x, double y, enum ori_crease_type type,
		       enum ori_rule rule, int parent, double k, int node, int *v, int *c,
		       struct iso *before)
{
	double p[2];

	*v = add_vertex(b, x, y);
	if (*v < 0)
		return full(b);
	iso_apply(&b->M, b->v[*v], p);
	if (cut_side(b, p) <= 1e-9 * b->d->size)
		return refuse(b, "a fork or node lies on or beyond the cut");
	*c = add_crease(b, s, *v, type, rule, parent, k, node);
	if (*c < 0)
		return full(b);
	*before = b->M;
	return face_push(b, *v);
}

/* Back along crease c to s: the face now must be the one left before, reflected. */
static int inner_end(struct ori_builder *b, int s, int c, const struct iso *before)
{
	double d[2] = { b->v[b->c[c].b][0] - b->v[s][0], b->v[b->c[c].b][1] - b->v[s][1] };
	double l = hypot(d[0], d[1]);
	struct iso r, want;

	d[0] /= l;
	d[1] /= l;
	r = iso_reflect(b->v[s], d);
	want = iso_mul(before, &r);
	if (iso_diff(&want, &b->M) > 1e-9)
		return refuse(b, "the creases round a fork or node do not fold flat (Kawasaki)");
	b->M = want;
	return face_push(b, s);
}

/* A side part's vein from s along d; depth forks made so far. mirror: a left part. */
static int vein(struct ori_builder *b, const struct ori_side *p, bool mirror, int s,
		const double d[2], int depth, enum ori_rule rule, int parent, double k)
{
	double a = mirror ? p->fork_b : p->fork_a, bb = mirror ? p->fork_a : p->fork_b;
	double u, kk, dc[2];
	struct iso before;
	int v, c, ret;

	if (depth == p->forks)
		return ray(b, s, d, ORI_VALLEY, rule, parent, k, -1, NULL);
	u = cut_length(b, b->v[s], d);
	if (u < 0)
		return refuse(b, "a vein runs away from the cut");
	u *= p->fork_at;
	ret = inner_begin(b, s, b->v[s][0] + u * d[0], b->v[s][1] + u * d[1], ORI_VALLEY, rule,
			  parent, k, -1, &v, &c, &before);
	if (ret < 0)
		return ret;
	/* children at +a and -b, the extra mountain at a - b between them (Kawasaki) */
	kk = cos((a + bb) * VEC_PI / 360.0) / cos((a - bb) * VEC_PI / 360.0);
	dir_turn(d, -bb, dc);
	if ((ret = vein(b, p, mirror, v, dc, depth + 1, ORI_RULE_FORK_CHILD, c, kk)) < 0)
		return ret;
	dir_turn(d, a - bb, dc);
	if ((ret = ray(b, v, dc, ORI_MOUNTAIN, ORI_RULE_FORK_MOUNTAIN, c, 0, -1, NULL)) < 0)
		return ret;
	dir_turn(d, a, dc);
	if ((ret = vein(b, p, mirror, v, dc, depth + 1, ORI_RULE_FORK_CHILD, c, kk)) < 0)
		return ret;
	return inner_end(b, s, c, &before);
}

/* A vein with nodes: the midrib, or a side part's vein without forks. */
struct ori_axis {
	double dir[2]; /* from O */
	double len;    /* from O to its tip on the cut */
	const struct ori_node *nodes;
	size_t nnodes;
	int part;
	const char *what; /* "middle.nodes", "sides: part 2" */
	unsigned long line;
};

/* The axis from s (O, or node i - 1 of the axis, the leaf's node snode) on; parent the
 * crease entering s. Each node sends out its right side vein and mountain, the axis goes
 * on, then its left mountain and vein. */
static int axis(struct ori_builder *b, const struct ori_axis *x, int s, size_t i, int parent,
		int snode)
{
	enum ori_rule rule = i == 0 ? ORI_RULE_BASE : ORI_RULE_NODE_MIDRIB;
	int node = i == 0 ? -1 : snode;
	const struct ori_node *n = &x->nodes[i];
	double dc[2];
	struct ori_node_geo *g;
	struct iso before;
	int v = 0, c = 0, ret, gi;

	if (i == x->nnodes)
		return ray(b, s, x->dir, ORI_VALLEY, rule, parent, 0, node, NULL);
	if (b->nnodes == ORI_MAX_LEAF_NODES)
		return full(b);
	b->part_line = n->line ? n->line : x->line;
	snprintf(b->what, sizeof(b->what), "%s: node %zu", x->what, i + 1);
	b->part_what = b->what;
	ret = inner_begin(b, s, n->at * x->len * x->dir[0], n->at * x->len * x->dir[1], ORI_VALLEY,
			  rule, parent, 0, node, &v, &c, &before);
	if (ret < 0)
		return ret;
	gi = (int)b->nnodes++;
	g = &b->nodes[gi];
	g->in = c;
	g->phi = n->phi[0] * VEC_PI / 180.0;
	g->psi = n->psi[0] * VEC_PI / 180.0;
	g->part = x->part;
	g->midrib = x->part == (int)b->d->nsides;
	dir_turn(x->dir, -n->phi[0], dc);
	if ((ret = ray(b, v, dc, ORI_VALLEY, ORI_RULE_NODE_VEIN, c, 0, gi, &g->vein[0])) < 0)
		return ret;
	dir_turn(x->dir, -n->psi[0], dc);
	if ((ret = ray(b, v, dc, ORI_MOUNTAIN, ORI_RULE_NODE_MOUNTAIN, c, 0, gi, &g->mountain[0])) < 0)
		return ret;
	g->out = (int)b->nc; /* the next crease made is the axis leaving v */
	if ((ret = axis(b, x, v, i + 1, c, gi)) < 0)
		return ret;
	g = &b->nodes[gi];
	dir_turn(x->dir, n->psi[1], dc);
	if ((ret = ray(b, v, dc, ORI_MOUNTAIN, ORI_RULE_NODE_MOUNTAIN, c, 0, gi, &g->mountain[1])) < 0)
		return ret;
	dir_turn(x->dir, n->phi[1], dc);
	if ((ret = ray(b, v, dc, ORI_VALLEY, ORI_RULE_NODE_VEIN, c, 0, gi, &g->vein[1])) < 0)
		return ret;
	return inner_end(b, s, c, &before);
}

/*
 * Where the axis's tip lies folded, by the map of the face the walk is in at O: the nodes'
 * side veins and mountains turn the folded axis, but their reflections do not depend on
 * the cut, so the tip's folded place is known before the walk (the face right of the last
 * segment maps it: each node's right vein and mountain, in the walk's order).
 */
static void axis_folded_tip(const struct ori_builder *b, const struct ori_axis *x, double out[2])
{
	double tip[2] = { x->len * x->dir[0], x->len * x->dir[1] };
	struct iso M = b->M;

	for (size_t i = 0; i < x->nnodes; i++) {
		double n[2] = { x->nodes[i].at * x->len * x->dir[0], x->nodes[i].at * x->len * x->dir[1] };
		double dv[2], dm[2];
		struct iso rv, rm;

		dir_turn(x->dir, -x->nodes[i].phi[0], dv);
		dir_turn(x->dir, -x->nodes[i].psi[0], dm);
		rv = iso_reflect(n, dv);
		rm = iso_reflect(n, dm);
		M = iso_mul(&M, &rv);
		M = iso_mul(&M, &rm);
	}
	iso_apply(&M, tip, out);
}

/* Sets the cut of the part the walk is at (the face at O, its edge along edge): through its
 * junction on that edge and the axis's tip, as both lie folded. */
static void set_cut_axis(struct ori_builder *b, const double edge[2], const struct ori_axis *x)
{
	double m = b->d->junction * b->d->size, j[2] = { m * edge[0], m * edge[1] };
	double o[2] = { 0, 0 }, oo[2];

	iso_apply(&b->M, j, b->cut_a);
	axis_folded_tip(b, x, b->cut_b);
	b->inside = 1.0;
	iso_apply(&b->M, o, oo);
	b->inside = cut_side(b, oo) >= 0 ? 1.0 : -1.0;
}

/* What a side part's walk may undo: the builder's lengths and the face being walked. */
struct ori_mark {
	size_t nv, nc, nf, nfi, nmargin, ncur, nnodes;
	int cur[ORI_MAX_CUR];
	struct iso M;
	int cur_across;
};

static void mark(const struct ori_builder *b, struct ori_mark *m)
{
	m->nv = b->nv;
	m->nc = b->nc;
	m->nf = b->nf;
	m->nfi = b->nfi;
	m->nmargin = b->nmargin;
	m->ncur = b->ncur;
	m->nnodes = b->nnodes;
	memcpy(m->cur, b->cur, b->ncur * sizeof(*b->cur));
	m->M = b->M;
	m->cur_across = b->cur_across;
}

static void undo_to(struct ori_builder *b, const struct ori_mark *m)
{
	b->nv = m->nv;
	b->nc = m->nc;
	b->nf = m->nf;
	b->nfi = m->nfi;
	b->nmargin = m->nmargin;
	b->ncur = m->ncur;
	b->nnodes = m->nnodes;
	memcpy(b->cur, m->cur, m->ncur * sizeof(*b->cur));
	b->M = m->M;
	b->cur_across = m->cur_across;
}

/* The part's vein from O with its cut's tip at r; its farthest margin point in *tip. */
static int walk_side(struct ori_builder *b, const struct ori_side *p, bool left,
		     const double edge[2], const double dv[2], double r, double *tip)
{
	size_t from = b->nmargin;
	int ret;

	set_cut(b, edge, dv, r);
	ret = vein(b, p, left, 0, dv, 0, ORI_RULE_BASE, -1, 0);
	*tip = 0;
	for (size_t i = from; ret == 0 && i < b->nmargin; i++)
		*tip = fmax(*tip, hypot(b->v[b->margin[i]][0], b->v[b->margin[i]][1]));
	return ret;
}

/*
 * The cut's tip r at which a part's walk puts its tip at target: secant steps from r =
 * target (trials undone; a trial that fails is no fault of the design while a better r
 * remains, so its message goes nowhere). far: where the cut crosses the part's edge (the
 * junction), below which r cannot go. What it cannot meet, the lobes report.
 */
#define ORI_FIT_STEPS 12
typedef int (*ori_trial)(struct ori_builder *b, const void *arg, double r, double *tip);

static double fit(struct ori_builder *b, double target, double far, const void *arg,
		  ori_trial trial)
{
	double r0 = target, t0 = 0, r1, t1, size = b->d->size;
	struct error scratch, *keep = b->err;
	struct ori_mark at;
	bool ok;

	mark(b, &at);
	b->err = &scratch;
	ok = trial(b, arg, r0, &t0) == 0 && t0 > far;
	undo_to(b, &at);
	/* first guess: the part scaled about its junction */
	r1 = ok ? far + (r0 - far) * (target - far) / (t0 - far) : r0;
	for (int i = 0; ok && i < ORI_FIT_STEPS && fabs(t0 - target) > 1e-9 * size; i++) {
		double r;

		ok = r1 > far * 1.01 && trial(b, arg, r1, &t1) == 0;
		undo_to(b, &at);
		if (!ok || fabs(t1 - t0) < 1e-15)
			break;
		r = r1;
		r1 = r1 + (target - t1) * (r1 - r0) / (t1 - t0);
		r0 = r;
		t0 = t1;
	}
	b->err = keep;
	return ok ? r0 : target;
}

struct side_walk {
	const struct ori_side *p;
	bool left;
	const double *edge, *dv;
};

static int side_trial(struct ori_builder *b, const void *arg, double r, double *tip)
{
	const struct side_walk *w = arg;

	return walk_side(b, w->p, w->left, w->edge, w->dv, r, tip);
}

/*
 * Side part j (right or left): its cut, then its vein from O. edge: its edge on the walk's
 * side of it (the one already walked). The spiral of section 2.1 is the target for the
 * lobe's tip: an unforked vein ends on the cut at r, so r is the target; a forked part's
 * farthest tooth lies beyond, so its r is fitted (secant steps on the right part, the
 * same r on the left) until that tooth meets the target; what it cannot meet, the lobes
 * report.
 */
static int side_part(struct ori_builder *b, size_t j, bool left, const double edge[2])
{
	const struct ori_design *d = b->d;
	const struct ori_side *p = &d->sides[j];
	double theta = d->middle[left] + ori_sides_angle(d, j) + p->angle / 2.0;
	double target = d->size * (1.0 - theta / d->theta0), m = d->junction * d->size;
	double r = target, dv[2], tip;

	b->part = left ? (int)(d->nsides + 1 + j) : (int)(d->nsides - 1 - j);
	b->part_line = p->line ? p->line : d->line;
	snprintf(b->what, sizeof(b->what), "sides: part %zu%s", j + 1, left ? " (on the left)" : "");
	b->part_what = b->what;
	if (target <= m * 1.01)
		return error_at(b->err, -EINVAL, b->name, b->part_line,
				"sides: part %zu: its vein, %.4g degrees from the midrib, reaches %.3g of "
				"the midrib by the spiral (theta0 %.4g), not past the junction (%.3g)",
				j + 1, theta, target / d->size, d->theta0, d->junction);
	dir_at(90.0 + (left ? theta : -theta), dv);
	if (p->nnodes > 0) { /* a vein with nodes ends on the cut at r, as the midrib does */
		char what[sizeof(b->what)];
		struct ori_axis x = { .dir = { dv[0], dv[1] }, .len = target, .nodes = p->nodes,
				      .nnodes = p->nnodes, .part = b->part, .what = what,
				      .line = b->part_line };

		memcpy(what, b->what, sizeof(what));
		set_cut_axis(b, edge, &x);
		return axis(b, &x, 0, 0, -1, -1);
	}
	if (p->forks == 0)
		return walk_side(b, p, left, edge, dv, r, &tip);
	if (left && b->fitted[j])
		return walk_side(b, p, left, edge, dv, b->fitted_r[j], &tip);
	r = fit(b, target, m, &(struct side_walk){ p, left, edge, dv }, side_trial);
	b->fitted[j] = true;
	b->fitted_r[j] = r;
	return walk_side(b, p, left, edge, dv, r, &tip);
}

/* A boundary mountain from O at deg: it ends at the junction, where neighbours meet. */
static int boundary(struct ori_builder *b, double deg)
{
	double d[2], m = b->d->junction * b->d->size;
	int e, c;
	struct iso r;

	dir_at(deg, d);
	e = add_vertex(b, m * d[0], m * d[1]);
	if (e < 0)
		return full(b);
	c = add_crease(b, 0, e, ORI_MOUNTAIN, ORI_RULE_BASE, -1, 0, -1);
	if (c < 0)
		return full(b);
	b->margin[b->nmargin++] = e;
	if (face_push(b, e) < 0 || face_close(b) < 0)
		return -EINVAL;
	r = iso_reflect(b->v[0], d);
	b->M = iso_mul(&b->M, &r);
	b->cur_across = c;
	if (face_push(b, e) < 0 || face_push(b, 0) < 0)
		return -EINVAL;
	return 0;
}

/* The middle part: its cut runs through its junction and the midrib's tip at (0, size) as
 * the tip lies folded. */
static int walk_middle(struct ori_builder *b, const double edge[2])
{
	const struct ori_design *d = b->d;
	struct ori_axis x = { .dir = { 0, 1 }, .len = d->size, .nodes = d->nodes,
			      .nnodes = d->nnodes, .part = (int)d->nsides, .what = "middle.nodes",
			      .line = d->line_middle ? d->line_middle : d->line };

	set_cut_axis(b, edge, &x);
	return axis(b, &x, 0, 0, -1, -1);
}

static int walk_fan(struct ori_builder *b)
{
	const struct ori_design *d = b->d;
	double half_r = d->middle[0] + ori_sides_angle(d, d->nsides);
	double half_l = d->middle[1] + ori_sides_angle(d, d->nsides);
	double edge[2], m = d->junction * d->size;
	int ret, e;

	b->M = iso_identity();
	b->cur_across = -1;
	if (add_vertex(b, 0, 0) != 0)
		return full(b);
	/* the right edge of the notch: on the margin from O to the outer part's junction */
	dir_at(90.0 - half_r, edge);
	b->part = 0;
	if ((e = add_vertex(b, m * edge[0], m * edge[1])) < 0)
		return full(b);
	b->margin[b->nmargin++] = 0;
	b->margin[b->nmargin++] = e;
	if ((ret = face_push(b, e)) < 0 || (ret = face_push(b, 0)) < 0)
		return ret;
	for (size_t j = d->nsides; j-- > 0;) {
		if ((ret = side_part(b, j, false, edge)) < 0)
			return ret;
		dir_at(90.0 - d->middle[0] - ori_sides_angle(d, j), edge);
		if ((ret = boundary(b, 90.0 - d->middle[0] - ori_sides_angle(d, j))) < 0)
			return ret;
	}
	/* the middle part: its tip on the midrib at r0 = size */
	b->part = (int)d->nsides;
	b->part_line = d->line_middle ? d->line_middle : d->line;
	b->part_what = "middle";
	b->root_face = (int)b->nf;
	if ((ret = walk_middle(b, edge)) < 0)
		return ret;
	b->part_line = d->line_middle ? d->line_middle : d->line;
	b->part_what = "middle";
	for (size_t j = 0; j < d->nsides; j++) {
		double deg = 90.0 + d->middle[1] + ori_sides_angle(d, j);

		if ((ret = boundary(b, deg)) < 0)
			return ret;
		dir_at(deg, edge);
		if ((ret = side_part(b, j, true, edge)) < 0)
			return ret;
	}
	dir_at(90.0 + half_l, edge);
	if ((e = add_vertex(b, m * edge[0], m * edge[1])) < 0)
		return full(b);
	b->part_of[e] = (int)(2 * d->nsides);
	b->margin[b->nmargin++] = e;
	if ((ret = face_push(b, e)) < 0)
		return ret;
	return face_close(b);
}

/* An entire leaf folded in two: the right half is cut on the curve, the left mirrors it. */
static int walk_half(struct ori_builder *b)
{
	const struct ori_design *d = b->d;
	int n = ORI_CURVE_POINTS, tip, c;
	double up[2] = { 0, 1 }, o[2] = { 0, 0 };
	struct iso r;

	b->M = iso_identity();
	b->cur_across = -1;
	b->part = 0;
	add_vertex(b, 0, 0);
	b->margin[b->nmargin++] = 0;
	if (face_push(b, 0) < 0)
		return -EINVAL;
	/* the right half, from O up its curve: root face */
	for (int i = 1; i <= n; i++) {
		double s = (double)i / (n + 1);
		int v = add_vertex(b, d->width * d->size * pow(sin(VEC_PI * s), d->power),
				   s * d->size);

		b->margin[b->nmargin++] = v;
		face_push(b, v);
	}
	tip = add_vertex(b, 0, d->size);
	b->margin[b->nmargin++] = tip;
	face_push(b, tip);
	c = add_crease(b, 0, tip, ORI_VALLEY, ORI_RULE_BASE, -1, 0, -1);
	b->root_face = 0;
	if (face_close(b) < 0)
		return -EINVAL;
	r = iso_reflect(o, up);
	b->M = r;
	b->cur_across = c;
	face_push(b, tip);
	for (int i = n; i >= 1; i--) {
		int v = add_vertex(b, -b->v[i][0], b->v[i][1]);

		b->margin[b->nmargin++] = v;
		face_push(b, v);
	}
	face_push(b, 0);
	return face_close(b);
}

static void lobes(struct ori_builder *b, struct ori_leaf *l)
{
	const struct ori_design *d = b->d;
	size_t np = d->fold == ORI_FOLD_HALF ? 1 : 2 * d->nsides + 1;

	l->nlobes = np;
	for (size_t p = 0; p < np; p++) {
		struct ori_lobe *lo = &l->lobes[p];
		double theta = 0;

		if (d->fold == ORI_FOLD_FAN && p != d->nsides) {
			size_t j = p < d->nsides ? d->nsides - 1 - p : p - d->nsides - 1;

			theta = d->middle[p > d->nsides] + ori_sides_angle(d, j) + d->sides[j].angle / 2;
		}
		lo->theta = theta;
		lo->target = d->fold == ORI_FOLD_HALF ? d->size : d->size * (1.0 - theta / d->theta0);
		lo->tip = 0;
		for (size_t i = 0; i < b->nmargin; i++)
			if (b->part_of[b->margin[i]] == (int)p)
				lo->tip = fmax(lo->tip, hypot(b->v[b->margin[i]][0], b->v[b->margin[i]][1]));
	}
}

void ori_leaf_init(struct ori_leaf *l)
{
	memset(l, 0, sizeof(*l));
	l->root_face = -1;
}

void ori_leaf_finish(struct ori_leaf *l)
{
	free(l->flat);
	free(l->folded);
	free(l->creases);
	free(l->margin);
	free(l->face_start);
	free(l->face_len);
	free(l->face_index);
	free(l->face_from);
	free(l->face_across);
	free(l->nodes);
	free(l->lobes);
	free(l->vertex_part);
	ori_leaf_init(l);
}

static int copy_out(struct ori_builder *b, struct ori_leaf *l)
{
	struct iso rebase = iso_inverse(&b->fmap[b->root_face]);
	double scale = 1.0;
	size_t nl = 2 * ORI_MAX_SIDES + 1;

	/* the midrib's tip at exactly size from O: nodes bend the folded midrib, so the cut
	 * through the straight one's tip lands it elsewhere (lobes report the difference) */
	for (size_t i = 0; i < b->nmargin; i++) {
		const double *p = b->v[b->margin[i]];

		if (fabs(p[0]) < 1e-12 && p[1] > 0)
			scale = b->d->size / p[1];
	}
	l->flat = calloc(b->nv, sizeof(*l->flat));
	l->folded = calloc(b->nv, sizeof(*l->folded));
	l->creases = calloc(b->nc, sizeof(*l->creases));
	l->margin = calloc(b->nmargin, sizeof(*l->margin));
	l->face_start = calloc(b->nf, sizeof(*l->face_start));
	l->face_len = calloc(b->nf, sizeof(*l->face_len));
	l->face_index = calloc(b->nfi, sizeof(*l->face_index));
	l->face_from = calloc(b->nf, sizeof(*l->face_from));
	l->face_across = calloc(b->nf, sizeof(*l->face_across));
	l->nodes = calloc(b->nnodes + 1, sizeof(*l->nodes));
	l->lobes = calloc(nl, sizeof(*l->lobes));
	l->vertex_part = calloc(b->nv, sizeof(*l->vertex_part));
	if (!l->vertex_part || !l->flat || !l->folded || !l->creases || !l->margin || !l->face_start ||
	    !l->face_len || !l->face_index || !l->face_from || !l->face_across || !l->nodes ||
	    !l->lobes) {
		ori_leaf_finish(l);
		return error_set(b->err, -ENOMEM, "out of memory");
	}
	for (size_t f = 0; f < b->nf; f++) {
		struct iso m = iso_mul(&rebase, &b->fmap[f]);

		for (size_t k = 0; k < b->flen[f]; k++) {
			int v = b->fidx[b->fstart[f] + k];

			iso_apply(&m, b->v[v], l->folded[v]);
		}
	}
	for (size_t v = 0; v < b->nv; v++)
		for (int i = 0; i < 2; i++) {
			l->flat[v][i] = b->v[v][i] * scale;
			l->folded[v][i] *= scale;
		}
	for (size_t v = 0; v < b->nv; v++)
		for (int i = 0; i < 2; i++)
			b->v[v][i] *= scale;
	l->nvertices = b->nv;
	memcpy(l->vertex_part, b->part_of, b->nv * sizeof(*b->part_of));
	l->tip = -1;
	for (size_t i = 0; i < b->nmargin; i++)
		if (fabs(l->flat[b->margin[i]][0]) < 1e-12 && l->flat[b->margin[i]][1] > 0)
			l->tip = b->margin[i];
	memcpy(l->creases, b->c, b->nc * sizeof(*b->c));
	l->ncreases = b->nc;
	memcpy(l->margin, b->margin, b->nmargin * sizeof(*b->margin));
	l->nmargin = b->nmargin;
	memcpy(l->face_start, b->fstart, b->nf * sizeof(*b->fstart));
	memcpy(l->face_len, b->flen, b->nf * sizeof(*b->flen));
	memcpy(l->face_index, b->fidx, b->nfi * sizeof(*b->fidx));
	memcpy(l->face_from, b->from, b->nf * sizeof(*b->from));
	memcpy(l->face_across, b->across, b->nf * sizeof(*b->across));
	l->nfaces = b->nf;
	l->root_face = b->root_face;
	memcpy(l->nodes, b->nodes, b->nnodes * sizeof(*b->nodes));
	l->nnodes = b->nnodes;
	l->size = b->d->size;
	l->rest = b->d->rest;
	lobes(b, l);
	return 0;
}

int ori_build(const struct ori_design *d, const char *name, struct ori_leaf *l,
	      struct error *err)
{
	struct ori_builder *b;
	int ret;

	ori_leaf_init(l);
	if ((ret = ori_check_design(d, name, err)) < 0)
		return ret;
	b = calloc(1, sizeof(*b));
	if (!b)
		return error_set(err, -ENOMEM, "out of memory");
	b->d = d;
	b->name = name;
	b->err = err;
	b->part_what = "";
	b->part_line = d->line;
	ret = d->fold == ORI_FOLD_HALF ? walk_half(b) : walk_fan(b);
	if (ret == 0)
		ret = ori_check_pattern(b);
	if (ret == 0)
		ret = copy_out(b, l);
	free(b);
	return ret;
}
