/* SPDX-License-Identifier: MIT */
/*
 * The shrub type (seed 001, 3.2): a vertical trunk built apart, and a crown that fills a
 * clipping shape (sphere, box or cone) as a gardener's hedge or topiary does: grown out to
 * the shape everywhere and cut back at its surface. The shape, not `levels` and `ratios`,
 * decides how big the crown is (docs/functional-trees.md, "Shrub and palm"):
 *
 * - the crown's tips are aimed at points spread evenly by area over the whole surface:
 *   gen_shrub_tips() of them, as many as MakeTree's tips (children^(levels - 1)) but never
 *   fewer than the shape needs, so that a sparse file reaches its surface all round too;
 * - the trunk's top shares them among its children by azimuth round its axis, in the
 *   children's order and in equal counts; each child shares its own among its children the
 *   same way, round its own axis and turned by `twist`, down to one tip a branch. The crown
 *   is the MakeTree recursion, as deep as its tips need;
 * - a child leaves at the MakeTree angle, turned AIM of the way towards the middle of its
 *   share; it is as long as makes the path through its descendants, their lengths falling
 *   by the mean of `ratios` from one generation to the next, as long as the way to its
 *   share (child i gets ratios[i] / their mean of that). A tip runs to its own point, set in
 *   from the surface for its leaves and its bark;
 * - every branch is cut where its bark (GEN_CLIP_MARGIN radii round its axis) would touch
 *   the surface, less half a leaf's length; a branch cut shorter than 1 cm or 2 of its
 *   radii is left out and its share grows from its parent's tip instead. Leaves face out
 *   of the shape; those that would stick out are made smaller, or left out. So nothing
 *   sticks out.
 *
 * The shares are split by counts alone, so gen_count_branches() can count the crown's most
 * branches without growing it: every branch made is one part of that split.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "gen_private.h"

#define DEG (VEC_PI / 180.0)
#define GOLDEN_RAD 2.39996322972865332 /* the golden angle, 137.5 degrees */
/* The fewest tips: enough to reach the surface all round, however sparse the file; and
 * one for every square SHRUB_TIP_SPACING leaf lengths on a side of the surface, so that
 * their leaves cover it; but never more than SHRUB_MAX_TIPS (the cost of a hostile file). */
#define SHRUB_MIN_TIPS 256
#define SHRUB_TIP_SPACING 2.5
#define SHRUB_MAX_TIPS 2048
/* How far a child turns from its MakeTree direction towards its share of the surface. */
#define AIM 0.5
/* A branch cut shorter than this many of its radii, or 1 cm, is left out. */
#define CLIP_MIN_RADII 2.0
#define CLIP_MIN_M 0.01
/* A branch is cut this many leaf lengths, and a leaf's clearance, inside the surface: its
 * leaves reach out to it. */
#define CLIP_SETBACK_LEAVES 0.5
/* A leaf keeps this far inside the surface (metres). */
#define LEAF_CLEARANCE 0.002
/* A tip's leaves sit along its last this many leaf lengths (at most GEN_LEAF_REACH of it):
 * at the surface, where the gardener's shears keep them. */
#define TIP_LEAVES_REACH 1.5
#define LEAF_MIN_SCALE (1.0 / 3.0)
/* Halvings of the scale a leaf is shrunk by: to 0.07% of its length. */
#define LEAF_FIT_STEPS 10
/* Far above any limit: counts saturate here. */
#define COUNT_CAP ((size_t)1 << 40)

void gen_clip_shape_of(const struct gen_params *p, struct gen_clip_shape *s)
{
	s->kind = p->clip;
	s->center = p->clip_center;
	s->radius = p->clip_radius;
	s->height = p->clip_height;
	s->half = vec3_scale(p->clip_size, 0.5);
}

double gen_clip_distance(const struct gen_clip_shape *s, struct vec3 x)
{
	struct vec3 d = vec3_sub(x, s->center);

	switch (s->kind) {
	case GEN_CLIP_BOX: {
		double qx = fabs(d.x) - s->half.x, qy = fabs(d.y) - s->half.y, qz = fabs(d.z) - s->half.z;
		double out = vec3_len(vec3(fmax(qx, 0), fmax(qy, 0), fmax(qz, 0)));

		return out + fmin(fmax(qx, fmax(qy, qz)), 0.0);
	}
	case GEN_CLIP_CONE: {
		/* below the base, or beyond the slanted side (its distance in the meridian plane) */
		double slant = (hypot(d.x, d.z) - s->radius * (1.0 - d.y / s->height)) * s->height /
			       hypot(s->height, s->radius);

		return fmax(-d.y, slant);
	}
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	return vec3_len(d) - s->radius;
}

static double depth_needed(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			   double r1, double f)
{
	return gen_clip_distance(s, vec3_lerp(a, b, f)) + GEN_CLIP_MARGIN * (r0 + (r1 - r0) * f);
}

/* The largest f in [0, hi] with g(f) + extra <= 0, g convex and g(0) + extra <= 0. */
static double last_inside(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			  double r1, double extra, double hi)
{
	double lo = 0.0;

	for (int i = 0; i < 48; i++) {
		double mid = 0.5 * (lo + hi);

		if (depth_needed(s, a, b, r0, r1, mid) + extra <= 0)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

double gen_clip_segment(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			double r1, double setback)
{
	double inside;

	if (depth_needed(s, a, b, r0, r1, 0.0) > 0)
		return -1.0;
	/* convex along the segment: inside at both ends is inside all along */
	if (depth_needed(s, a, b, r0, r1, 1.0) <= 0)
		return 1.0;
	inside = last_inside(s, a, b, r0, r1, 0.0, 1.0);
	/* cut it back by the setback where it can be; a branch that starts nearer the surface
	 * than that goes to the surface */
	if (depth_needed(s, a, b, r0, r1, 0.0) + setback > 0)
		return inside;
	return last_inside(s, a, b, r0, r1, setback, inside);
}

static bool leaf_fits(const struct gen_clip_shape *s, const struct vec3 *p, size_t n, double k)
{
	for (size_t i = 0; i < n; i++)
		if (gen_clip_distance(s, vec3_lerp(p[0], p[i], k)) > -LEAF_CLEARANCE)
			return false;
	return true;
}

bool gen_clip_leaf(const struct gen_clip_shape *s, struct vec3 *p, size_t n)
{
	double lo = LEAF_MIN_SCALE, hi = 1.0;

	if (leaf_fits(s, p, n, 1.0))
		return true;
	if (!leaf_fits(s, p, n, lo))
		return false;
	for (int i = 0; i < LEAF_FIT_STEPS; i++) {
		double mid = 0.5 * (lo + hi);

		if (leaf_fits(s, p, n, mid))
			lo = mid;
		else
			hi = mid;
	}
	for (size_t i = 1; i < n; i++)
		p[i] = vec3_lerp(p[0], p[i], lo);
	return true;
}

/* The area of the shape's whole surface (m^2). */
static double surface_area(const struct gen_params *p)
{
	struct vec3 s = p->clip_size;

	switch (p->clip) {
	case GEN_CLIP_BOX:
		return 2.0 * (s.x * s.y + s.y * s.z + s.z * s.x);
	case GEN_CLIP_CONE:
		return VEC_PI * p->clip_radius * (p->clip_radius + hypot(p->clip_radius, p->clip_height));
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	return 4.0 * VEC_PI * p->clip_radius * p->clip_radius;
}

size_t gen_shrub_tips(const struct gen_params *p)
{
	double cover = surface_area(p) / pow(SHRUB_TIP_SPACING * p->leaf_size, 2);
	size_t full = 1, least = SHRUB_MAX_TIPS;

	for (int i = 1; i < p->levels && full <= COUNT_CAP; i++)
		full *= p->children == 3 ? 3 : 2;
	/* (NaN and out-of-range values are refused before a tree is built: any count will do) */
	if (cover < least)
		least = cover > SHRUB_MIN_TIPS ? (size_t)ceil(cover) : SHRUB_MIN_TIPS;
	/* within the limit of leaves: each tip has its own */
	if (p->leaf_amount > 0 && least > TREE_MAX_LEAVES / (size_t)p->leaf_amount)
		least = TREE_MAX_LEAVES / (size_t)p->leaf_amount;
	return full > least ? full : least;
}

size_t gen_shrub_branches(const struct gen_params *p)
{
	size_t c = p->children == 3 ? 3 : 2;
	/* the trunk's share is all the tips; at each depth the parts hold q or q + 1 tips
	 * (a of them and b), and a part of one tip is a tip: it splits no further */
	size_t q = gen_shrub_tips(p), a = 1, b = 0, total = 0;

	while (a + b > 0) {
		size_t lo = q / c, na = 0, nb = 0;

		total += (q >= 1 ? a : 0) + b;
		if (q >= 2) {
			na += a * (c - q % c);
			nb += a * (q % c);
		}
		if (q + 1 >= 2) {
			if ((q + 1) / c == lo) {
				na += b * (c - (q + 1) % c);
				nb += b * ((q + 1) % c);
			} else {
				nb += b * c;
			}
		}
		q = lo;
		a = lo > 0 ? na : 0; /* parts of no tips are no branches */
		b = nb;
	}
	return total;
}

/* n points shared among parts by their areas: the largest remainders get one more. */
static void share_by_area(const double *area, size_t nparts, size_t n, size_t *k)
{
	double sum = 0.0, rest[6];
	size_t given = 0;

	for (size_t i = 0; i < nparts; i++)
		sum += area[i];
	for (size_t i = 0; i < nparts; i++) {
		double want = n * area[i] / sum;

		k[i] = (size_t)floor(want);
		rest[i] = want - (double)k[i];
		given += k[i];
	}
	while (given < n) {
		size_t best = 0;

		for (size_t i = 1; i < nparts; i++)
			if (rest[i] > rest[best])
				best = i;
		k[best]++;
		rest[best] = -1.0;
		given++;
	}
}

/* The j-th point of the R2 sequence in [0, 1)^2: evenly spread, no clumps. */
static void r2(size_t j, double *u, double *v)
{
	*u = fmod(0.5 + (double)j * 0.7548776662466927, 1.0);
	*v = fmod(0.5 + (double)j * 0.5698402909980532, 1.0);
}

static double *axis_of(struct vec3 *v, int k)
{
	return k == 0 ? &v->x : k == 1 ? &v->y : &v->z;
}

/* A tip's point on the surface and the surface's outward normal there. */
struct spot {
	struct vec3 at, out;
};

static void box_points(const struct gen_clip_shape *s, struct spot *out, size_t n)
{
	struct vec3 half = s->half;
	double area[6];
	size_t k[6], at = 0;

	for (int f = 0; f < 6; f++) {
		int axis = f / 2;

		area[f] = *axis_of(&half, (axis + 1) % 3) * *axis_of(&half, (axis + 2) % 3);
	}
	share_by_area(area, 6, n, k);
	for (int f = 0; f < 6; f++) {
		int axis = f / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;

		for (size_t j = 0; j < k[f]; j++) {
			struct vec3 x = s->center, normal = vec3(0, 0, 0);
			double u, v;

			r2(j, &u, &v);
			*axis_of(&normal, axis) = f % 2 ? 1.0 : -1.0;
			*axis_of(&x, axis) += *axis_of(&normal, axis) * *axis_of(&half, axis);
			*axis_of(&x, a) += (2.0 * u - 1.0) * *axis_of(&half, a);
			*axis_of(&x, b) += (2.0 * v - 1.0) * *axis_of(&half, b);
			out[at++] = (struct spot){ x, normal };
		}
	}
}

static void cone_points(const struct gen_clip_shape *s, struct spot *out, size_t n)
{
	double slant = hypot(s->radius, s->height);
	double area[2] = { s->radius * s->radius, s->radius * slant };
	size_t k[2], at = 0;

	share_by_area(area, 2, n, k);
	/* the base: a sunflower; the side: uniform by area, so the distance from the apex goes
	 * as the square root */
	for (int part = 0; part < 2; part++) {
		for (size_t j = 0; j < k[part]; j++) {
			double t = sqrt((j + 0.5) / k[part]), phi = GOLDEN_RAD * j, rho = s->radius * t;
			struct vec3 x = vec3_add(s->center, vec3(rho * cos(phi), part ? s->height * (1.0 - t) : 0.0,
								 rho * sin(phi)));

			out[at++] = (struct spot){ x, part ? vec3(s->height * cos(phi) / slant, s->radius / slant,
								  s->height * sin(phi) / slant)
							   : vec3(0, -1, 0) };
		}
	}
}

static void sphere_points(const struct gen_clip_shape *s, struct spot *out, size_t n)
{
	/* a Fibonacci sphere: even in height is even by area */
	for (size_t j = 0; j < n; j++) {
		double y = 1.0 - 2.0 * (j + 0.5) / n, rho = sqrt(fmax(0.0, 1.0 - y * y));
		double phi = GOLDEN_RAD * j;
		struct vec3 normal = vec3(rho * cos(phi), y, rho * sin(phi));

		out[j] = (struct spot){ vec3_add(s->center, vec3_scale(normal, s->radius)), normal };
	}
}

/* n points spread evenly by area over the whole surface of the shape. */
static void surface_points(const struct gen_clip_shape *s, struct spot *out, size_t n)
{
	switch (s->kind) {
	case GEN_CLIP_BOX:
		box_points(s, out, n);
		return;
	case GEN_CLIP_CONE:
		cone_points(s, out, n);
		return;
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	sphere_points(s, out, n);
}

/* A tip's point, keyed for sorting (by azimuth, then by number: the same order always). */
struct aim {
	double key;
	size_t tip;
};

static int by_key(const void *a, const void *b)
{
	const struct aim *x = a, *y = b;

	if (x->key != y->key)
		return x->key < y->key ? -1 : 1;
	return (x->tip > y->tip) - (x->tip < y->tip);
}

struct shrub {
	struct gen_ctx *g;
	struct gen_clip_shape shape;
	/* the tips' points, each `setback` in from the surface (a tip's own bark is kept in
	 * too, when it grows) */
	const struct spot *tips;
	double setback;
	double mean_ratio;
};

/* Where a branch's children grow from: its tip z, its direction d, the reference e its
 * children's azimuths are measured from, and its radius r there. */
struct fork {
	int branch;
	struct vec3 z, d, e;
	double r;
};

/* The generations below a part of n tips: the least k with c^k >= n. */
static int depth_of(size_t n, int c)
{
	int k = 0;

	for (size_t m = 1; m < n; m *= (size_t)c)
		k++;
	return k;
}

/* How much of a branch from the fork along u, `len` long, keeps inside (gen_clip_segment). */
static double cut_of(const struct shrub *w, const struct fork *f, struct vec3 u, double len)
{
	return gen_clip_segment(&w->shape, f->z, vec3_add(f->z, vec3_scale(u, len)), f->r,
				f->r * w->g->p->thickness_ratio, w->setback);
}

/* A branch from the fork along u, `len` long, cut at the surface: its id in *id, -1 when it
 * is cut too short to keep. 0 or -ENOMEM. */
static int add_cut(struct shrub *w, const struct fork *f, struct vec3 u, double len, int level,
		   int *id, struct vec3 *end, double *r1)
{
	double tip_r = f->r * w->g->p->thickness_ratio, cut = cut_of(w, f, u, len), kept = cut * len;

	*id = -1;
	if (cut < 0 || kept < CLIP_MIN_M || kept < CLIP_MIN_RADII * f->r)
		return 0;
	/* the very point the cut was measured at: its children start inside by a hair */
	*end = vec3_lerp(f->z, vec3_add(f->z, vec3_scale(u, len)), cut);
	*r1 = f->r + (tip_r - f->r) * cut;
	*id = gen_add_branch(w->g, f->branch, f->z, *end, f->r, *r1, level);
	return *id < 0 ? *id : 0;
}

/* The outward normal of the surface nearest x (the distance's gradient). */
static struct vec3 outward(const struct gen_clip_shape *s, struct vec3 x)
{
	const double h = 1e-6;
	struct vec3 g = vec3(gen_clip_distance(s, vec3_add(x, vec3(h, 0, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(h, 0, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, h, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, h, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, 0, h))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, 0, h))));

	return vec3_norm_or(g, vec3(0, 1, 0));
}

/* A tip's leaves: near its end, turned out to the light at the surface. */
static int tip_leaves(struct shrub *w, int b, struct vec3 e)
{
	const struct branch *br = &w->g->t->branches[b];
	double len = vec3_dist(br->points[0], br->points[br->npoints - 1]);
	double reach = fmin(GEN_LEAF_REACH, TIP_LEAVES_REACH * w->g->p->leaf_size / len);

	return gen_tip_leaves(w->g, b, e, reach, outward(&w->shape, br->points[br->npoints - 1]),
			      &w->shape);
}

/*
 * Child i of the fork f, reaching the n tips of `part` (n >= 1): added to the tree, its own
 * fork in *kid. When it is cut too short to keep, kid->branch is -1 and *promoted says
 * whether its share (of more than one tip) is to grow from f instead, round *kid's axis.
 * 0 or -ENOMEM.
 */
static int add_child(struct shrub *w, const struct fork *f, struct vec3 turned, int i,
		     const struct aim *part, size_t n, struct fork *kid, bool *promoted)
{
	const struct gen_params *p = w->g->p;
	double phi = (i - 0.5 * (p->children - 1)) * p->spread * DEG, theta = gen_angle(w->g);
	struct vec3 di = vec3_add(vec3_scale(f->d, cos(theta)),
				  vec3_scale(gen_azimuth(f->d, f->e, phi), sin(theta)));
	struct vec3 mid = vec3(0, 0, 0), u, toward;
	double way = 0.0, len, sum = 0.0, term = 1.0;
	int depth = depth_of(n, p->children), id, ret;

	for (size_t k = 0; k < n; k++) {
		mid = vec3_add(mid, vec3_scale(w->tips[part[k].tip].at, 1.0 / n));
		way += vec3_dist(w->tips[part[k].tip].at, f->z) / n;
	}
	toward = vec3_norm_or(vec3_sub(mid, f->z), di);
	if (n == 1) {
		/* a tip: to its point, its bark (as thin as it tapers to) kept in */
		const struct spot *t = &w->tips[part[0].tip];
		struct vec3 end = vec3_sub(t->at, vec3_scale(t->out, GEN_CLIP_MARGIN * f->r * p->thickness_ratio));

		u = vec3_norm_or(vec3_sub(end, f->z), toward);
		len = vec3_dist(end, f->z);
	} else {
		u = vec3_norm_or(vec3_add(vec3_scale(di, 1.0 - AIM), vec3_scale(toward, AIM)), toward);
		for (int j = 0; j <= depth; j++, term *= w->mean_ratio)
			sum += term;
		/* never too short to keep: each generation thins the twigs that reach the
		 * surface, and a share grown from its parent's fork would keep them thick */
		len = fmax(way * p->ratios[i] / w->mean_ratio / sum,
			   1.000001 * fmax(CLIP_MIN_M, CLIP_MIN_RADII * f->r));
		/* one that would be cut at the surface would leave its share no room to branch
		 * in: it grows straight for the share's middle instead, no further */
		if (cut_of(w, f, u, len) < 1.0) {
			u = toward;
			len = fmin(len, vec3_dist(mid, f->z));
		}
	}
	if ((ret = add_cut(w, f, u, len, 1 + depth, &id, &kid->z, &kid->r)) < 0)
		return ret;
	*promoted = id < 0 && n > 1;
	if (*promoted) {
		/* cut too short: its share grows from this fork, round its own middle */
		u = toward;
		kid->z = f->z;
		kid->r = f->r;
	}
	kid->branch = *promoted ? f->branch : id;
	kid->d = u;
	kid->e = gen_transport(turned, f->d, u);
	return 0;
}

/*
 * Grows the part of the crown that reaches the tips of aims[0..n) from the fork f: its
 * children, theirs, ... *made counts the branches grown on f's branch.
 */
static int grow(struct shrub *w, const struct fork *f, struct aim *aims, size_t n, int *made)
{
	int c = w->g->p->children;
	struct vec3 side = vec3_cross(f->d, f->e), turned = gen_rotate(f->e, f->d, w->g->p->twist * DEG);
	struct fork kid[GEN_MAX_CHILDREN];
	size_t from[GEN_MAX_CHILDREN], count[GEN_MAX_CHILDREN], start = 0;
	bool promoted[GEN_MAX_CHILDREN];
	int ret;

	/* the shares: in order of azimuth round d, from behind e on, as the children are, and
	 * in counts as equal as they go */
	for (size_t k = 0; k < n; k++) {
		struct vec3 v = vec3_sub(w->tips[aims[k].tip].at, f->z);

		aims[k].key = atan2(vec3_dot(v, side), vec3_dot(v, f->e));
	}
	qsort(aims, n, sizeof(*aims), by_key);
	for (int i = 0; i < c; i++) {
		from[i] = start;
		count[i] = n / (size_t)c + ((size_t)i < n % (size_t)c);
		start += count[i];
		promoted[i] = false;
		kid[i].branch = -1;
		if (count[i] == 0)
			continue;
		if ((ret = add_child(w, f, turned, i, aims + from[i], count[i], &kid[i], &promoted[i])) < 0)
			return ret;
		*made += kid[i].branch >= 0 && !promoted[i];
	}
	/* every child is added before any grows, as MakeTree does */
	for (int i = 0; i < c; i++) {
		int below = 0;

		if (promoted[i]) {
			if ((ret = grow(w, &kid[i], aims + from[i], count[i], made)) < 0)
				return ret;
			continue;
		}
		if (kid[i].branch < 0)
			continue;
		if (count[i] > 1 && (ret = grow(w, &kid[i], aims + from[i], count[i], &below)) < 0)
			return ret;
		/* a tip, or a branch whose every child was cut away: its leaves */
		if (below == 0 && (ret = tip_leaves(w, kid[i].branch, kid[i].e)) < 0)
			return ret;
	}
	return 0;
}

int gen_shrub(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	struct vec3 up = vec3(0, 1, 0), top = vec3_add(p->trunk_start, vec3(0, p->trunk_height, 0));
	size_t n = gen_shrub_tips(p);
	struct shrub w = { .g = g };
	struct fork f = { .z = top, .d = up, .e = gen_reference(up), .r = p->thickness * p->thickness_ratio };
	struct spot *tips = malloc(n * sizeof(*tips));
	struct aim *aims = malloc(n * sizeof(*aims));
	int made = 0, ret;

	if (!tips || !aims) {
		ret = -ENOMEM;
		goto out;
	}
	if (p->leaf_amount)
		w.setback = CLIP_SETBACK_LEAVES * p->leaf_size + LEAF_CLEARANCE;
	gen_clip_shape_of(p, &w.shape);
	surface_points(&w.shape, tips, n);
	for (size_t k = 0; k < n; k++) {
		tips[k].at = vec3_sub(tips[k].at, vec3_scale(tips[k].out, w.setback));
		aims[k].tip = k;
	}
	w.tips = tips;
	w.mean_ratio = 0.0;
	for (int i = 0; i < p->children; i++)
		w.mean_ratio += p->ratios[i] / p->children;
	f.branch = gen_add_branch(g, -1, p->trunk_start, top, p->thickness, f.r, 1 + depth_of(n, p->children));
	ret = f.branch < 0 ? f.branch : grow(&w, &f, aims, n, &made);
	/* the trunk stays bare, whatever its crown */
out:
	free(tips);
	free(aims);
	return ret;
}
