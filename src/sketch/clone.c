/* SPDX-License-Identifier: MIT */
/*
 * Example-based cloning (seed 000, sections 3.4 and 4.4).
 *
 * clone_add(t, P, rng) adds one child branch to P, learnt from P's child branches (the
 * examples), so the tree keeps its overall shape however many are added: a new child
 * interpolates its neighbours. Every child is described by its parent_t, its arc length,
 * its root radius and its direction, the unit chord from root to tip.
 *
 * Turtle frame. At parameter t on P (clone_turtle_at): head = P's unit tangent there;
 *   up = world up (0,1,0) minus its part along head, normalised; left = up x head. Where
 *   head is vertical (that part shorter than CLONE_VERTICAL_EPS, e.g. a straight drawn
 *   trunk, or a zero-length P whose head is taken as world up) up is world +z, towards
 *   the front viewer. A direction d then has a down angle (between head and d) and a
 *   rotation angle about head, from up towards left, in (-180, 180] degrees. Each child's
 *   angles are measured in the frame at its own parent_t.
 *
 * Position. Children in parent_t order (ties by id); the new one goes to the middle of
 *   the widest gap between two neighbours (the first one on a tie). With a single child
 *   there is no pair: it is paired with the end of P (root, t = 0, or tip, t = 1) that
 *   leaves the larger gap, the tip on a tie, and that end stands in as a copy of the
 *   child (same length, radius and angles), so the new child is the same size. With two
 *   or more children the ends are never used: their span is part of the tree's shape.
 *   The root is placed exactly on P's polyline at the new parent_t, where tree_locate
 *   puts it.
 *
 * Length, root radius, down angle: interpolated linearly in parent_t between the pair,
 *   which at the middle is their mean. A child with one point has length 0 and no
 *   direction; if one of the pair has no direction the other's down angle is used, if
 *   neither has, the mean over all children with one.
 *
 * Rotation angle: so that the children look evenly spread seen along head. On an
 *   upright parent (head at the new parent_t within CLONE_UPRIGHT_DEG, 30 degrees, of the
 *   vertical, up or down) the rotation angle does not change how far a child points
 *   down, and up is only world +z or the direction of a slight lean: the angle is the
 *   middle of the widest angular gap between the existing children's rotation angles,
 *   over the full circle (on a tie the gap starting at the lowest angle), so no side of
 *   a trunk stays bare. On an inclined parent it is never more than
 *   CLONE_MAX_ROTATION_DEG from up (branches do not grow downwards): the angle in
 *   [-120, 120] degrees farthest from every existing child's rotation angle. That is the
 *   middle of the widest angular gap between them when it is in range; otherwise another
 *   gap's middle or an end of the range, whichever is farther from its nearest child (gap
 *   middles first on a tie, then +120, then -120). Children along head have no rotation
 *   angle and do not count; with none at all the new one gets 0 (up).
 *
 * Shape: a sibling S picked with one rng draw among the children with a direction (two
 *   or more points, root apart from tip; there are none: -ENOENT). S's polyline is
 *   written in its own frame (x along its chord, y = head at its parent_t minus the part
 *   along the chord, or its up when the chord is along head, z = x cross y), scaled by
 *   new length / S's arc length and written back in the frame built the same way from the
 *   new direction and the new head. So the clone bends as S bends relative to the parent
 *   (a droop stays a droop), its chord is the new direction and its arc length the
 *   interpolated length. Its radii are S's times new root radius / S's root radius (as
 *   they are if S's root radius is 0).
 *
 * The branch is appended with tree_add_branch (ORIGIN_CLONE): ids stay dense, its
 * generation is P's + 1. Nothing else in the tree changes.
 *
 * clone_remove(t, P) removes P's child with the highest id and everything attached to
 * it, so n clone_add calls followed by n clone_remove calls give back the same tree.
 *
 * Cost: O(B + k log k + k (p + c)) for B branches, k children, p points on P and c
 * points a child.
 */
#include "clone.h"

#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>

#define MAX_ROTATION (CLONE_MAX_ROTATION_DEG * VEC_PI / 180.0)
#define UPRIGHT (CLONE_UPRIGHT_DEG * VEC_PI / 180.0)
/* A chord, or a direction's part across head, shorter than this has no direction. */
#define DIR_EPS 1e-12

/* What cloning needs to know of one existing child. */
struct child {
	int id;
	double t;      /* parent_t */
	double length; /* arc length */
	double radius; /* at the root */
	bool has_dir;  /* root and tip apart: a direction, and a shape to copy */
	struct vec3 dir;
	double down;  /* angle between head and dir */
	bool has_rot; /* dir not along head */
	double rot;   /* about head from up towards left, (-pi, pi] */
};

/* The unit direction of segment seg, or of the nearest one with a length (towards the
 * tip first): a repeated point must not turn the turtle to an arbitrary head. */
static struct vec3 segment_tangent(const struct branch *b, size_t seg)
{
	for (size_t i = seg; i + 1 < b->npoints; i++) {
		struct vec3 d = vec3_sub(b->points[i + 1], b->points[i]);

		if (vec3_len(d) > DIR_EPS)
			return vec3_scale(d, 1.0 / vec3_len(d));
	}
	for (size_t i = seg < b->npoints ? seg : b->npoints; i-- > 0;) {
		struct vec3 d = vec3_sub(b->points[i + 1], b->points[i]);

		if (vec3_len(d) > DIR_EPS)
			return vec3_scale(d, 1.0 / vec3_len(d));
	}
	return vec3(0, 1, 0);
}

struct clone_turtle clone_turtle_at(const struct branch *b, double t)
{
	struct clone_turtle tu = { .head = vec3(0, 1, 0) };
	struct vec3 up;
	size_t seg;
	double s;

	if (b->npoints > 0)
		tu.origin = b->points[0];
	if (b->npoints >= 2) {
		tree_locate(b, t, &seg, &s);
		tu.origin = vec3_lerp(b->points[seg], b->points[seg + 1], s);
		tu.head = segment_tangent(b, seg);
	}
	up = vec3_sub(vec3(0, 1, 0), vec3_scale(tu.head, tu.head.y));
	if (vec3_len(up) < CLONE_VERTICAL_EPS)
		up = vec3_sub(vec3(0, 0, 1), vec3_scale(tu.head, tu.head.z));
	tu.up = vec3_norm_or(up, vec3(0, 0, 1));
	tu.left = vec3_cross(tu.up, tu.head);
	return tu;
}

/* The down and rotation angles of unit direction d in turtle frame tu. */
static void angles(const struct clone_turtle *tu, struct vec3 d, double *down, bool *has_rot,
		   double *rot)
{
	double u = vec3_dot(d, tu->up), l = vec3_dot(d, tu->left);
	double across = sqrt(u * u + l * l);

	/* atan2 rather than acos: exact enough near 0 and 180 degrees */
	*down = atan2(across, vec3_dot(d, tu->head));
	*has_rot = across > DIR_EPS;
	*rot = *has_rot ? atan2(l, u) : 0.0;
}

static void measure(const struct tree *t, const struct branch *c, struct child *ch)
{
	struct clone_turtle tu;
	struct vec3 chord;
	double len;

	*ch = (struct child){
		.id = c->id,
		.t = c->parent_t,
		.length = tree_branch_length(c),
		.radius = c->npoints ? c->radii[0] : 0.0,
	};
	if (c->npoints < 2)
		return;
	chord = vec3_sub(c->points[c->npoints - 1], c->points[0]);
	len = vec3_len(chord);
	if (!(len > DIR_EPS))
		return;
	ch->has_dir = true;
	ch->dir = vec3_scale(chord, 1.0 / len);
	tu = clone_turtle_at(&t->branches[c->parent], c->parent_t);
	angles(&tu, ch->dir, &ch->down, &ch->has_rot, &ch->rot);
}

static int cmp_child(const void *pa, const void *pb)
{
	const struct child *a = pa, *b = pb;

	if (a->t != b->t)
		return a->t < b->t ? -1 : 1;
	return (a->id > b->id) - (a->id < b->id);
}

/* parent's children, measured, in parent_t order. 0, -ENOENT (none) or -ENOMEM. */
static int gather(const struct tree *t, int parent, struct child **out, size_t *n)
{
	struct child *c;
	size_t k = 0;

	*out = NULL;
	*n = 0;
	for (size_t i = 0; i < t->nbranches; i++)
		k += t->branches[i].parent == parent;
	if (k == 0)
		return -ENOENT;
	c = malloc(k * sizeof(*c));
	if (!c)
		return -ENOMEM;
	k = 0;
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent == parent)
			measure(t, &t->branches[i], &c[k++]);
	qsort(c, k, sizeof(*c), cmp_child);
	*out = c;
	*n = k;
	return 0;
}

/* The neighbours farthest apart along the parent, a before b. One child is paired with a
 * copy of itself standing at the end of the parent that leaves the larger gap. */
static void widest_pair(const struct child *c, size_t n, struct child *a, struct child *b)
{
	size_t best = 0;

	if (n == 1) {
		*a = *b = c[0];
		if (c[0].t > 0.5)
			a->t = 0.0;
		else
			b->t = 1.0;
		return;
	}
	for (size_t i = 1; i + 1 < n; i++)
		if (c[i + 1].t - c[i].t > c[best + 1].t - c[best].t)
			best = i;
	*a = c[best];
	*b = c[best + 1];
}

static double lerp(double a, double b, double w)
{
	return a + (b - a) * w;
}

static double down_angle(const struct child *a, const struct child *b, double w,
			 const struct child *c, size_t n)
{
	double sum = 0.0;
	size_t k = 0;

	if (a->has_dir && b->has_dir)
		return lerp(a->down, b->down, w);
	if (a->has_dir || b->has_dir)
		return a->has_dir ? a->down : b->down;
	for (size_t i = 0; i < n; i++)
		if (c[i].has_dir) {
			sum += c[i].down;
			k++;
		}
	return k ? sum / (double)k : 0.0;
}

static int cmp_double(const void *pa, const void *pb)
{
	double a = *(const double *)pa, b = *(const double *)pb;

	return (a > b) - (a < b);
}

static double angle_dist(double a, double b)
{
	return fabs(remainder(a - b, 2.0 * VEC_PI));
}

/* How far phi is from the nearest of m angles. */
static double clearance(const double *rot, size_t m, double phi)
{
	double d = HUGE_VAL;

	for (size_t i = 0; i < m; i++)
		d = fmin(d, angle_dist(phi, rot[i]));
	return d;
}

/*
 * The angle in [-limit, limit] farthest from all m angles in rot (sorted here); limit is
 * MAX_ROTATION or, for the full circle, VEC_PI. Within one gap between neighbouring
 * angles the distance to the nearest rises to the gap's middle and falls again, so the
 * best allowed angle is a gap's middle or an end of the range. On the full circle every
 * middle is in range and the widest gap's is as far as any angle gets: no ends.
 */
static double pick_rotation(double *rot, size_t m, double limit)
{
	const double ends[] = { limit, -limit };
	double best = -1.0, phi = 0.0;

	if (m == 0)
		return 0.0;
	qsort(rot, m, sizeof(*rot), cmp_double);
	for (size_t i = 0; i < m; i++) {
		double hi = i + 1 < m ? rot[i + 1] : rot[0] + 2.0 * VEC_PI;
		double half = 0.5 * (hi - rot[i]), mid = rot[i] + half;

		if (mid > VEC_PI)
			mid -= 2.0 * VEC_PI;
		if (fabs(mid) <= limit && half > best) {
			best = half;
			phi = mid;
		}
	}
	for (size_t i = 0; i < 2 && limit < VEC_PI; i++) {
		double d = clearance(rot, m, ends[i]);

		if (d > best) {
			best = d;
			phi = ends[i];
		}
	}
	return phi;
}

/* A branch's own frame: x its direction, y head made perpendicular to it (up when it
 * runs along head), z = x cross y. The same rule for the sibling and the clone is what
 * carries the sibling's bends over. */
static void chord_axes(const struct clone_turtle *tu, struct vec3 dir, struct vec3 ax[3])
{
	ax[0] = dir;
	ax[1] = vec3_norm_or(vec3_sub(tu->head, vec3_scale(dir, vec3_dot(tu->head, dir))), tu->up);
	ax[2] = vec3_cross(ax[0], ax[1]);
}

/* The sibling's points and radii, carried to root / dir at length len, root radius r. */
static void copy_shape(const struct tree *t, const struct child *sib, const struct clone_turtle *tu,
		       struct vec3 dir, double len, double r, struct vec3 *points, double *radii)
{
	const struct branch *s = &t->branches[sib->id];
	struct clone_turtle stu = clone_turtle_at(&t->branches[s->parent], s->parent_t);
	struct vec3 from[3], to[3];
	double scale = len / sib->length;
	double rscale = s->radii[0] > 0 ? r / s->radii[0] : 1.0;

	chord_axes(&stu, sib->dir, from);
	chord_axes(tu, dir, to);
	points[0] = tu->origin; /* exactly on the parent */
	radii[0] = s->radii[0] * rscale;
	for (size_t i = 1; i < s->npoints; i++) {
		struct vec3 v = vec3_sub(s->points[i], s->points[0]), p = tu->origin;

		for (int k = 0; k < 3; k++)
			p = vec3_add(p, vec3_scale(to[k], vec3_dot(v, from[k]) * scale));
		points[i] = p;
		radii[i] = s->radii[i] * rscale;
	}
}

/* The index-th child with a direction. */
static const struct child *nth_with_dir(const struct child *c, size_t n, size_t index)
{
	for (size_t i = 0; i < n; i++)
		if (c[i].has_dir && index-- == 0)
			return &c[i];
	return NULL;
}

int clone_add(struct tree *t, int parent, struct rng *rng)
{
	struct child *c, a, b;
	const struct child *sib;
	struct clone_turtle tu;
	struct vec3 dir, *points;
	double *rot, *radii, tnew, w, len, r, down, incline, phi;
	size_t n, m = 0, nshape = 0, pick;
	int ret;

	if (parent < 0 || (size_t)parent >= t->nbranches)
		return -ENOENT;
	if (t->nbranches >= TREE_MAX_BRANCHES)
		return -ENOSPC;
	ret = gather(t, parent, &c, &n);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < n; i++)
		nshape += c[i].has_dir;
	if (nshape == 0) {
		free(c);
		return -ENOENT;
	}
	rot = malloc(n * sizeof(*rot));
	if (!rot) {
		free(c);
		return -ENOMEM;
	}

	widest_pair(c, n, &a, &b);
	tnew = 0.5 * (a.t + b.t);
	w = b.t > a.t ? (tnew - a.t) / (b.t - a.t) : 0.5;
	len = lerp(a.length, b.length, w);
	r = lerp(a.radius, b.radius, w);
	down = down_angle(&a, &b, w, c, n);
	tu = clone_turtle_at(&t->branches[parent], tnew);
	for (size_t i = 0; i < n; i++)
		if (c[i].has_rot)
			rot[m++] = c[i].rot;
	/* from the vertical line: a hanging parent is upright too */
	incline = atan2(hypot(tu.head.x, tu.head.z), fabs(tu.head.y));
	phi = pick_rotation(rot, m, incline > UPRIGHT ? MAX_ROTATION : VEC_PI);
	free(rot);

	dir = vec3_add(vec3_scale(tu.head, cos(down)),
		       vec3_scale(vec3_add(vec3_scale(tu.up, cos(phi)), vec3_scale(tu.left, sin(phi))),
				  sin(down)));

	pick = (size_t)(rng_uniform(rng) * (double)nshape);
	sib = nth_with_dir(c, n, pick < nshape ? pick : nshape - 1);
	points = malloc(t->branches[sib->id].npoints * sizeof(*points));
	radii = malloc(t->branches[sib->id].npoints * sizeof(*radii));
	if (!points || !radii) {
		ret = -ENOMEM;
		goto out;
	}
	copy_shape(t, sib, &tu, dir, len, r, points, radii);
	/* may move t->branches: nothing above is used after it */
	ret = tree_add_branch(t, parent, tnew, ORIGIN_CLONE, points, radii,
			      t->branches[sib->id].npoints);
out:
	free(points);
	free(radii);
	free(c);
	return ret;
}

int clone_remove(struct tree *t, int parent)
{
	bool *remove;
	int last = -1, ret;

	if (parent < 0 || (size_t)parent >= t->nbranches)
		return -ENOENT;
	for (size_t i = t->nbranches; i-- > 0;)
		if (t->branches[i].parent == parent) {
			last = (int)i;
			break;
		}
	if (last < 0)
		return -ENOENT;
	remove = calloc(t->nbranches, sizeof(*remove));
	if (!remove)
		return -ENOMEM;
	remove[last] = true;
	ret = tree_remove_branches(t, remove);
	free(remove);
	return ret < 0 ? ret : last;
}
