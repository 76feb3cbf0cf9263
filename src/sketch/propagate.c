/* SPDX-License-Identifier: MIT */
/*
 * Propagation by example (seed 000, section 3.6).
 *
 * The example is the set of children of the source branch S: its leaves and its child
 * branches, each child branch with its own leaves (grandchild branches are not part of
 * it). It is copied onto every target: every branch that existed before the call except
 * S, and except generation-0 branches (the trunk) unless S itself is one. Copies made by
 * the call are never targets. Everything copied has origin ORIGIN_PROPAGATE.
 *
 * Each child sits at an arc-length parameter u on S (a leaf's branch_t, a branch's
 * parent_t) and is expressed in S's frame at u (tree_frame_at: tangent, normal,
 * binormal): a leaf by its stored `local` outline (tree_leaf_attach), a child branch by
 * its polyline relative to its own root. On a target T of length Lt (S has length Ls):
 *
 *  - fixed count: every child goes to the same parameter u on T, scaled by Lt / Ls (a
 *    leaf's outline; a branch's polyline and radii, with its leaves' outlines);
 *  - fixed size: a child at distance d = (1 - u) Ls from S's tip goes at distance d from
 *    T's tip, parameter 1 - d / Lt, at the same size. Only those with d <= Lt (plus
 *    PROPAGATE_FIT_EPS_M) fit, so a shorter target gets the children nearest S's tip: a
 *    half-length target the tip-most half.
 *
 * The child is rebuilt in T's frame at its new parameter with the same local
 * coordinates (scaled), by the same sum tree_leaves_follow() uses, so a later
 * tree_leaves_follow() leaves copied leaves exactly where they are. A copied branch's
 * root is the frame's origin: exactly on T's polyline. Its leaves keep their branch_t
 * and local outline (scaled) and are placed in the copy's own frame there, as
 * tree_leaves_follow() would place them: in the sketch plane exactly as on the child; on
 * a 3D tree the copy's frame may be turned about its tangent relative to a rigid copy of
 * the child's (the normal is always chosen across the picture plane).
 *
 * A propagation that could take the tree past TREE_MAX_BRANCHES or TREE_MAX_LEAVES is
 * refused (-ENOSPC) and changes nothing.
 * Targets shorter than PROPAGATE_MIN_LENGTH_M get nothing (there is no size to match); a
 * source that short is refused like a childless one (-ENOENT).
 * Copies are appended target by target in id order: child branches first (in S's child
 * order), then leaves (in the order of the tree's leaves); ids stay dense and parents
 * come before their children. No randomness: same tree, same result. On -ENOMEM
 * everything added is removed again, so the tree is unchanged.
 */
#include "propagate.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "ori_place.h"

/* One leaf of the example: on S (child < 0) or on child branch `child`. */
struct ex_leaf {
	int child;
	double u;      /* branch_t on S or on the child */
	size_t first;  /* its local outline in example.pool */
	size_t npoints;
	int kind;      /* struct leaf's */
};

/* One child branch of S: its polyline relative to its root in S's frame at u. */
struct ex_branch {
	double u;     /* parent_t on S */
	size_t first; /* in example.pool and example.radii */
	size_t npoints;
};

struct example {
	double length; /* of S */
	struct ex_leaf *leaves;
	size_t nleaves;
	struct ex_branch *branches;
	size_t nbranches;
	struct vec3 *pool; /* local coordinates */
	double *radii;     /* indexed like pool; only child branches' entries are used */
	size_t npool, max_points;
	int *copy; /* per child branch: the id of its copy on the current target, or -1 */
};

static void example_finish(struct example *ex)
{
	free(ex->leaves);
	free(ex->branches);
	free(ex->pool);
	free(ex->radii);
	free(ex->copy);
}

/* d's coordinates in frame f (as tree_leaf_attach computes them). */
static struct vec3 to_local(struct tree_frame f, struct vec3 d)
{
	return vec3(vec3_dot(d, f.tangent), vec3_dot(d, f.normal), vec3_dot(d, f.binormal));
}

/* f's origin plus local coordinates l scaled by s, summed as tree_leaves_follow does. */
static struct vec3 from_local(struct tree_frame f, struct vec3 l)
{
	return vec3_add(f.origin, vec3_add(vec3_scale(f.tangent, l.x),
					   vec3_add(vec3_scale(f.normal, l.y),
						    vec3_scale(f.binormal, l.z))));
}

/* Collects S's children into ex. 0, -ENOENT (no children) or -ENOMEM. */
static int example_build(struct example *ex, const struct tree *t, int src)
{
	const struct branch *s = &t->branches[src];
	int *child_of = malloc((t->nbranches + 1) * sizeof(*child_of));
	size_t nl = 0, nb = 0, np = 0;
	int ret = -ENOMEM;

	memset(ex, 0, sizeof(*ex));
	if (!child_of)
		return -ENOMEM;
	for (size_t i = 0; i < t->nbranches; i++) {
		child_of[i] = -1;
		if (t->branches[i].parent == src) {
			child_of[i] = (int)nb++;
			np += t->branches[i].npoints;
		}
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		int b = t->leaves[i].branch;

		if (b == src || child_of[b] >= 0) {
			nl++;
			np += t->leaves[i].npoints;
		}
	}
	if (nl + nb == 0) {
		ret = -ENOENT;
		goto out;
	}

	ex->length = tree_branch_length(s);
	ex->leaves = calloc(nl + 1, sizeof(*ex->leaves));
	ex->branches = calloc(nb + 1, sizeof(*ex->branches));
	ex->copy = calloc(nb + 1, sizeof(*ex->copy));
	ex->pool = calloc(np + 1, sizeof(*ex->pool));
	ex->radii = calloc(np + 1, sizeof(*ex->radii));
	if (!ex->leaves || !ex->branches || !ex->copy || !ex->pool || !ex->radii)
		goto out;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *c = &t->branches[i];
		struct ex_branch *e;
		struct tree_frame f;

		if (child_of[i] < 0)
			continue;
		e = &ex->branches[ex->nbranches++];
		e->u = c->parent_t;
		e->first = ex->npool;
		e->npoints = c->npoints;
		f = tree_frame_at(s, c->parent_t);
		for (size_t k = 0; k < c->npoints; k++) {
			ex->pool[ex->npool + k] = to_local(f, vec3_sub(c->points[k], c->points[0]));
			ex->radii[ex->npool + k] = c->radii[k];
		}
		ex->npool += c->npoints;
		if (c->npoints > ex->max_points)
			ex->max_points = c->npoints;
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		struct ex_leaf *e;

		if (l->branch != src && child_of[l->branch] < 0)
			continue;
		e = &ex->leaves[ex->nleaves++];
		e->child = l->branch == src ? -1 : child_of[l->branch];
		e->u = l->branch_t;
		e->kind = l->kind;
		e->first = ex->npool;
		e->npoints = l->npoints;
		if (l->local) {
			memcpy(&ex->pool[ex->npool], l->local, l->npoints * sizeof(*l->local));
		} else {
			/* never attached: what tree_leaf_attach would record */
			struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);

			for (size_t k = 0; k < l->npoints; k++)
				ex->pool[ex->npool + k] = to_local(f, vec3_sub(l->points[k], f.origin));
		}
		ex->npool += l->npoints;
		if (l->npoints > ex->max_points)
			ex->max_points = l->npoints;
	}
	ret = 0;
out:
	free(child_of);
	if (ret < 0)
		example_finish(ex);
	return ret;
}

/* Where a child at parameter u on S goes on a target of length lt: false if it does
 * not fit there. */
static bool place(const struct example *ex, enum propagate_pattern p, double lt, double u,
		  double *v)
{
	double d;

	if (p == PROPAGATE_FIXED_COUNT) {
		*v = u;
		return true;
	}
	d = (1.0 - u) * ex->length;
	if (d > lt + PROPAGATE_FIT_EPS_M)
		return false;
	*v = fmin(fmax(1.0 - d / lt, 0.0), 1.0);
	return true;
}

/* Copies the example onto target `target`. Returns how many elements it added or
 * -ENOMEM (what it added stays; the caller truncates). */
static int copy_onto(struct tree *t, struct example *ex, int target,
		     enum propagate_pattern p, struct vec3 *pts, double *radii)
{
	double lt = tree_branch_length(&t->branches[target]);
	double scale = p == PROPAGATE_FIXED_COUNT ? lt / ex->length : 1.0;
	int added = 0;

	if (lt < PROPAGATE_MIN_LENGTH_M)
		return 0;

	for (size_t c = 0; c < ex->nbranches; c++) {
		const struct ex_branch *e = &ex->branches[c];
		struct tree_frame f;
		double v;
		int id;

		ex->copy[c] = -1;
		if (!place(ex, p, lt, e->u, &v))
			continue;
		/* t->branches may move with every branch added: look the target up again */
		f = tree_frame_at(&t->branches[target], v);
		for (size_t k = 0; k < e->npoints; k++) {
			pts[k] = from_local(f, vec3_scale(ex->pool[e->first + k], scale));
			radii[k] = ex->radii[e->first + k] * scale;
		}
		id = tree_add_branch(t, target, v, ORIGIN_PROPAGATE, pts, radii, e->npoints);
		if (id < 0)
			return id;
		ex->copy[c] = id;
		added++;
	}

	for (size_t i = 0; i < ex->nleaves; i++) {
		const struct ex_leaf *e = &ex->leaves[i];
		struct tree_frame f;
		struct vec3 *local;
		struct leaf *l;
		int on, id, ret;
		double v;

		if (e->child < 0) {
			if (!place(ex, p, lt, e->u, &v))
				continue;
			on = target;
		} else {
			/* the copy is similar to the child: the same parameter fits the same place */
			on = ex->copy[e->child];
			if (on < 0)
				continue;
			v = e->u;
		}
		local = malloc((e->npoints ? e->npoints : 1) * sizeof(*local));
		if (!local)
			return -ENOMEM;
		f = tree_frame_at(&t->branches[on], v);
		for (size_t k = 0; k < e->npoints; k++) {
			local[k] = vec3_scale(ex->pool[e->first + k], scale);
			pts[k] = from_local(f, local[k]);
		}
		id = tree_add_leaf(t, on, ORIGIN_PROPAGATE, pts, e->npoints);
		if (id < 0) {
			free(local);
			return id;
		}
		l = &t->leaves[id];
		l->branch_t = v;
		l->local = local;
		l->kind = e->kind;
		/* the leaf the visitor chose, in the frame of the copy it replaces */
		if ((ret = ori_place_leaf(t, (size_t)id, t->leaf_kind)) < 0)
			return ret;
		added++;
	}
	return added;
}

/* Branch i takes copies of src's children: not src, and not a trunk unless src is one. */
static bool is_target(const struct tree *t, size_t i, int src)
{
	return (int)i != src &&
	       (t->branches[i].generation > 0 || t->branches[src].generation == 0);
}

int propagate_apply(struct tree *t, int src, enum propagate_pattern p)
{
	size_t nb = t->nbranches, nl = t->nleaves, ntargets = 0, most;
	struct example ex;
	struct vec3 *pts = NULL;
	double *radii = NULL;
	int ret, added = 0;

	if (src < 0 || (size_t)src >= nb)
		return -ENOENT;
	ret = example_build(&ex, t, src);
	if (ret < 0)
		return ret;
	if (ex.length < PROPAGATE_MIN_LENGTH_M) {
		/* nothing to measure the targets against: as if it had no children */
		ret = -ENOENT;
		goto out;
	}

	for (size_t i = 0; i < nb; i++)
		if (is_target(t, i, src))
			ntargets++;
	/* ids are ints: refuse what could not be numbered */
	most = ex.nleaves + ex.nbranches;
	if (nb + nl >= (size_t)INT_MAX ||
	    (ntargets && most > ((size_t)INT_MAX - nb - nl) / ntargets)) {
		ret = -ENOMEM;
		goto out;
	}
	/* ...and what could grow past the tree's limits, counting every copy as fitting */
	if (nb + ntargets * ex.nbranches > TREE_MAX_BRANCHES ||
	    nl + ntargets * ex.nleaves > TREE_MAX_LEAVES) {
		ret = -ENOSPC;
		goto out;
	}

	pts = malloc((ex.max_points + 1) * sizeof(*pts));
	radii = malloc((ex.max_points + 1) * sizeof(*radii));
	if (!pts || !radii) {
		ret = -ENOMEM;
		goto out;
	}
	for (size_t i = 0; i < nb; i++) {
		if (!is_target(t, i, src))
			continue;
		ret = copy_onto(t, &ex, (int)i, p, pts, radii);
		if (ret < 0) {
			tree_truncate(t, nb, nl); /* undoes a failed call */
			goto out;
		}
		added += ret;
	}
	ret = added;
out:
	free(pts);
	free(radii);
	example_finish(&ex);
	return ret;
}
