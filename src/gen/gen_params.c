/* SPDX-License-Identifier: MIT */
/* The parameters of the functional trees: names, defaults, limits, what they make, and
 * the kiosk's parameter buttons. docs/tree-params.md is the contract for all of it. */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "gen_private.h"

static const char *const type_names[GEN_TYPE_COUNT] = {
	[GEN_LSYSTEM] = "lsystem",
	[GEN_SHRUB] = "shrub",
	[GEN_PALM] = "palm",
};

static const char *const clip_names[GEN_CLIP_COUNT] = {
	[GEN_CLIP_SPHERE] = "sphere",
	[GEN_CLIP_BOX] = "box",
	[GEN_CLIP_CONE] = "cone",
};

static const char *const leaf_names[GEN_LEAF_COUNT] = {
	[GEN_LEAF_OVAL] = "oval",
	[GEN_LEAF_POINTED] = "pointed",
	[GEN_LEAF_ROUND] = "round",
	[GEN_LEAF_NEEDLE] = "needle",
	[GEN_LEAF_LEAFLET] = "leaflet",
	[GEN_LEAF_ENTIRE] = "entire",
	[GEN_LEAF_HOP] = "hop",
	[GEN_LEAF_MAPLE] = "maple",
};

const char *gen_type_name(enum gen_type t)
{
	return (unsigned)t < GEN_TYPE_COUNT ? type_names[t] : "?";
}

const char *gen_clip_name(enum gen_clip c)
{
	return (unsigned)c < GEN_CLIP_COUNT ? clip_names[c] : "?";
}

const char *gen_leaf_name(enum gen_leaf l)
{
	return (unsigned)l < GEN_LEAF_COUNT ? leaf_names[l] : "?";
}

bool gen_leaf_from_name(const char *name, enum gen_leaf *l)
{
	for (int i = 0; i < GEN_LEAF_COUNT; i++) {
		if (!strcmp(name, leaf_names[i])) {
			*l = (enum gen_leaf)i;
			return true;
		}
	}
	return false;
}

void gen_params_default(struct gen_params *p, enum gen_type type)
{
	memset(p, 0, sizeof(*p));
	p->type = type;
	p->gen_version = GEN_VERSION;
	p->precision = 8;
	p->trunk_start = vec3(0, 0, 0);
	p->trunk_end = vec3(0, 2.5, 0);
	p->levels = 7;
	p->children = 2;
	p->angle_min = 20;
	p->angle_max = 45;
	p->randomness = 0.5;
	p->ratios[0] = 0.75;
	p->ratios[1] = 0.7;
	p->ratios[2] = 0.65;
	p->spread = 140;
	p->twist = 90;
	p->thickness = 0.15;
	p->thickness_ratio = 0.7;
	p->leaf_amount = 6;
	p->leaf_size = 0.15;
	p->leaf_type = GEN_LEAF_OVAL;
	p->season = SEASON_SUMMER;
	p->trunk_height = 0.8;
	p->clip = GEN_CLIP_SPHERE;
	p->clip_center = vec3(0, 1.5, 0);
	p->clip_radius = 1.0;
	p->clip_size = vec3(2, 1, 1);
	p->clip_height = 2;
	p->height = 6;
	p->fronds = 12;
	p->frond_length = 2.5;
	p->droop = 70;
	switch (type) {
	case GEN_SHRUB:
		p->precision = 6;
		p->levels = 7;
		p->children = 3;
		p->angle_min = 30;
		p->angle_max = 70;
		p->randomness = 0.8;
		p->ratios[0] = 0.8;
		p->ratios[1] = 0.75;
		p->ratios[2] = 0.7;
		p->spread = 120;
		p->twist = 60;
		p->thickness = 0.06;
		p->thickness_ratio = 0.75;
		p->leaf_amount = 5;
		p->leaf_size = 0.15;
		p->leaf_type = GEN_LEAF_ROUND;
		break;
	case GEN_PALM:
		p->trunk_end = vec3(0, 1, 0);
		p->angle_min = 50;
		p->angle_max = 80;
		p->randomness = 0.5;
		p->thickness = 0.2;
		p->thickness_ratio = 0.7;
		p->leaf_amount = 40;
		p->leaf_size = 0.5;
		p->leaf_type = GEN_LEAF_LEAFLET;
		break;
	case GEN_LSYSTEM:
	case GEN_TYPE_COUNT:
		break;
	}
}

/* 1 + c + c^2 + ... + c^(levels-1), saturating far above any limit. */
static size_t full_tree(int children, int levels)
{
	size_t n = 0, layer = 1;

	for (int i = 0; i < levels; i++) {
		n += layer;
		if (n > (size_t)1 << 40)
			return n;
		layer *= (size_t)children;
	}
	return n;
}

static size_t tips(int children, int levels)
{
	size_t layer = 1;

	for (int i = 1; i < levels && layer <= (size_t)1 << 40; i++)
		layer *= (size_t)children;
	return layer;
}

size_t gen_count_branches(const struct gen_params *p)
{
	if (p->type == GEN_PALM)
		return 1 + (size_t)p->fronds;
	/* a shrub's crown is cut to its shape: this is the most it can have (version 1's is
	 * the L-system's, clipped) */
	if (p->type == GEN_SHRUB && p->gen_version != 1)
		return gen_shrub_branches(p);
	return full_tree(p->children, p->levels);
}

size_t gen_count_leaves(const struct gen_params *p)
{
	if (p->type == GEN_PALM)
		return (size_t)p->fronds * (size_t)p->leaf_amount;
	/* version 1's clipping makes tips of branches cut short: at most every branch but the
	 * trunk */
	if (p->type == GEN_SHRUB && p->gen_version == 1)
		return (full_tree(p->children, p->levels) - 1) * (size_t)p->leaf_amount;
	/* a shrub's leaves are its tips' (a branch cut short of its tips takes their place) */
	if (p->type == GEN_SHRUB)
		return gen_shrub_tips(p) * (size_t)p->leaf_amount;
	return tips(p->children, p->levels) * (size_t)p->leaf_amount;
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi; /* false for NaN */
}

static bool point_ok(struct vec3 v)
{
	const double m = TREE_MAX_COORD_M;

	return in(v.x, -m, m) && in(v.y, -m, m) && in(v.z, -m, m);
}

/* Names the parameter at fault (its key path) and says what is wrong with it. */
#define BAD(k, ...) (*key = (k), error_set(err, -EINVAL, __VA_ARGS__))

static int check_shape(const struct gen_params *p, const char **key, struct error *err)
{
	struct vec3 top = vec3_add(p->trunk_start, vec3(0, p->trunk_height, 0));
	struct gen_clip_shape shape;

	if (!in(p->trunk_height, 0.05, 20))
		return BAD("trunk_height", "trunk_height: %g is not within 0.05..20 m", p->trunk_height);
	if (!point_ok(p->clip_center))
		return BAD("clip.center", "clip.center: not within %g m of the origin",
			   (double)TREE_MAX_COORD_M);
	switch (p->clip) {
	case GEN_CLIP_SPHERE:
		if (!in(p->clip_radius, 0.1, 20))
			return BAD("clip.radius", "clip.radius: %g is not within 0.1..20 m", p->clip_radius);
		break;
	case GEN_CLIP_BOX:
		if (!in(p->clip_size.x, 0.1, 40) || !in(p->clip_size.y, 0.1, 40) ||
		    !in(p->clip_size.z, 0.1, 40))
			return BAD("clip.size", "clip.size: each edge must be within 0.1..40 m");
		break;
	case GEN_CLIP_CONE:
		if (!in(p->clip_radius, 0.1, 20))
			return BAD("clip.radius", "clip.radius: %g is not within 0.1..20 m", p->clip_radius);
		if (!in(p->clip_height, 0.1, 40))
			return BAD("clip.height", "clip.height: %g is not within 0.1..40 m", p->clip_height);
		break;
	case GEN_CLIP_COUNT:
		return BAD("clip.shape", "clip.shape: unknown");
	}
	/* the crown's first branches start there, their bark inside the shape */
	gen_clip_shape_of(p, &shape);
	if (gen_clip_distance(&shape, top) > -GEN_CLIP_MARGIN * p->thickness * p->thickness_ratio)
		return BAD("trunk_height", "trunk_height: the trunk's top (%g, %g, %g) is not well "
			   "inside the %s: the crown grows from there",
			   top.x, top.y, top.z, gen_clip_name(p->clip));
	return 0;
}

static int check_palm(const struct gen_params *p, const char **key, struct error *err)
{
	struct vec3 d = vec3_sub(p->trunk_end, p->trunk_start);
	double len = vec3_len(d);

	if (!in(p->height, 0.5, 50))
		return BAD("height", "height: %g is not within 0.5..50 m", p->height);
	if (!(len > 1e-6) || d.y <= 0 || acos(d.y / len) > 20.0 * VEC_PI / 180.0 + 1e-12)
		return BAD("trunk", "trunk: a palm's trunk leans at most 20 degrees (trunk.end - trunk.start "
			   "gives its direction)");
	if (p->fronds < 1 || p->fronds > 64)
		return BAD("fronds", "fronds: %d is not within 1..64", p->fronds);
	if (!in(p->frond_length, 0.1, 20))
		return BAD("frond_length", "frond_length: %g is not within 0.1..20 m", p->frond_length);
	if (!in(p->droop, 0, 180))
		return BAD("droop", "droop: %g is not within 0..180 degrees", p->droop);
	return 0;
}

int gen_params_check(const struct gen_params *p, const char **key, struct error *err)
{
	size_t nb, nl;
	int ret;

	if (p->gen_version < 1 || p->gen_version > GEN_VERSION)
		return BAD("generator", "generator version %d is not supported (this edaha has 1 to %d)",
			   p->gen_version, GEN_VERSION);
	if ((unsigned)p->type >= GEN_TYPE_COUNT)
		return BAD("type", "type: unknown");
	if (p->precision < GEN_MIN_PRECISION || p->precision > GEN_MAX_PRECISION)
		return BAD("precision", "precision: %d is not within %d..%d sides", p->precision,
			   GEN_MIN_PRECISION, GEN_MAX_PRECISION);
	if (!point_ok(p->trunk_start) || !point_ok(p->trunk_end))
		return BAD("trunk", "trunk: a point is not within %g m of the origin", (double)TREE_MAX_COORD_M);
	if (p->type == GEN_LSYSTEM) {
		double len = vec3_dist(p->trunk_start, p->trunk_end);

		if (!in(len, 0.01, 100))
			return BAD("trunk", "trunk: its length %g is not within 0.01..100 m", len);
	}
	if (p->type != GEN_PALM) {
		if (p->levels < 1 || p->levels > GEN_MAX_LEVELS)
			return BAD("levels", "levels: %d is not within 1..%d", p->levels, GEN_MAX_LEVELS);
		if (p->children < 2 || p->children > GEN_MAX_CHILDREN)
			return BAD("children", "children: %d is neither 2 nor 3", p->children);
		for (int i = 0; i < p->children; i++)
			if (!in(p->ratios[i], 0.01, 1.5))
				return BAD("ratios", "ratios: %g is not within 0.01..1.5", p->ratios[i]);
		if (!in(p->spread, 0, 360))
			return BAD("spread", "spread: %g is not within 0..360 degrees", p->spread);
		if (!in(p->twist, -360, 360))
			return BAD("twist", "twist: %g is not within -360..360 degrees", p->twist);
	}
	if (!in(p->angle_min, 0, 180))
		return BAD("angle.min", "angle.min: %g is not within 0..180 degrees", p->angle_min);
	if (!in(p->angle_max, 0, 180))
		return BAD("angle.max", "angle.max: %g is not within 0..180 degrees", p->angle_max);
	if (p->angle_min > p->angle_max)
		return BAD("angle.min", "angle: min %g is over max %g", p->angle_min, p->angle_max);
	if (!in(p->randomness, 0, 1))
		return BAD("angle.randomness", "angle.randomness: %g is not within 0..1", p->randomness);
	if (!in(p->thickness, 0.001, 5))
		return BAD("thickness", "thickness: %g is not within 0.001..5 m", p->thickness);
	if (!in(p->thickness_ratio, 0.01, 1))
		return BAD("thickness_ratio", "thickness_ratio: %g is not within 0.01..1", p->thickness_ratio);
	if (p->leaf_amount < 0 || p->leaf_amount > 200)
		return BAD("leaves.amount", "leaves.amount: %d is not within 0..200", p->leaf_amount);
	if (!in(p->leaf_size, 0.005, 5))
		return BAD("leaves.size", "leaves.size: %g is not within 0.005..5 m", p->leaf_size);
	if ((unsigned)p->leaf_type >= GEN_LEAF_COUNT)
		return BAD("leaves.type", "leaves.type: unknown");
	if ((unsigned)p->season >= SEASON_COUNT)
		return BAD("season", "season: unknown");
	if (p->type == GEN_SHRUB && (ret = check_shape(p, key, err)) < 0)
		return ret;
	if (p->type == GEN_PALM && (ret = check_palm(p, key, err)) < 0)
		return ret;
	nb = gen_count_branches(p);
	nl = gen_count_leaves(p);
	if (nb > TREE_MAX_BRANCHES)
		return BAD("levels", "the tree would have %zu branches, over edaha's %u (src/core/tree.h): fewer "
			   "levels or children", nb, TREE_MAX_BRANCHES);
	if (nl > TREE_MAX_LEAVES)
		return BAD("leaves.amount", "the tree would have %zu leaves, over edaha's %u (src/core/tree.h): fewer "
			   "leaves.amount or levels", nl, TREE_MAX_LEAVES);
	return 0;
}

/* Steps of the kiosk's buttons. */
#define ADJUST_ANGLE_DEG 8.0
#define ADJUST_SPREAD_DEG 20.0
#define ADJUST_SCALE 1.15
#define ADJUST_LEAVES 2
#define ADJUST_FRONDS 2
#define ADJUST_LEAFLETS 8
#define ADJUST_MAX_ANGLE 110.0 /* wider than this a crown turns inside out */
#define ADJUST_MIN_RATIO 0.2
#define ADJUST_MAX_RATIO 1.2

static bool scale_ratios(struct gen_params *q, double k)
{
	for (int i = 0; i < q->children; i++) {
		double r = q->ratios[i] * k;

		if (r < ADJUST_MIN_RATIO || r > ADJUST_MAX_RATIO)
			return false;
		q->ratios[i] = r;
	}
	return true;
}

/* A shrub grows taller by its shape (and its trunk), keeping its foot on the ground. */
static void scale_shape(struct gen_params *q, double k)
{
	double foot = q->trunk_start.y;

	q->trunk_height *= k;
	q->clip_center.y = foot + (q->clip_center.y - foot) * k;
	q->clip_size.y *= k;
	q->clip_height *= k;
	if (q->clip == GEN_CLIP_SPHERE)
		q->clip_radius *= k;
}

/* A shrub grows wider by its shape, about its centre: the shape decides its crown. */
static void widen_shape(struct gen_params *q, double k)
{
	if (q->clip == GEN_CLIP_BOX) {
		q->clip_size.x *= k;
		q->clip_size.z *= k;
	} else {
		q->clip_radius *= k;
	}
}

static bool widen(struct gen_params *q, double sign)
{
	if (q->type == GEN_PALM) {
		q->frond_length *= sign > 0 ? ADJUST_SCALE : 1.0 / ADJUST_SCALE;
		return true;
	}
	if (q->type == GEN_SHRUB) {
		widen_shape(q, sign > 0 ? ADJUST_SCALE : 1.0 / ADJUST_SCALE);
		return true;
	}
	q->angle_min += sign * ADJUST_ANGLE_DEG;
	q->angle_max += sign * ADJUST_ANGLE_DEG;
	if (q->angle_min < 0 || q->angle_max > ADJUST_MAX_ANGLE)
		return false;
	q->spread = fmin(360.0 / q->children, fmax(0.0, q->spread + sign * ADJUST_SPREAD_DEG));
	return true;
}

bool gen_adjust(const struct gen_params *p, enum gen_adjust what, struct gen_params *q)
{
	struct error err;
	const char *bad;
	bool ok = true;

	*q = *p;
	/* a new tree: this edaha's, whatever p's version */
	q->gen_version = GEN_VERSION;
	switch (what) {
	case GEN_MORE:
	case GEN_FEWER: {
		int step = what == GEN_MORE ? 1 : -1;

		if (q->type == GEN_PALM)
			q->fronds += step * ADJUST_FRONDS;
		else
			q->levels += step;
		/* a shrub has as many tips as its shape needs, and more only with more levels:
		 * levels that change none change nothing */
		if (q->type == GEN_SHRUB && q->levels >= 1 && gen_shrub_tips(q) == gen_shrub_tips(p))
			ok = false;
		break;
	}
	case GEN_WIDER:
	case GEN_NARROWER:
		ok = widen(q, what == GEN_WIDER ? 1.0 : -1.0);
		break;
	case GEN_TALLER:
	case GEN_SHORTER: {
		double k = what == GEN_TALLER ? ADJUST_SCALE : 1.0 / ADJUST_SCALE;

		if (q->type == GEN_PALM)
			q->height *= k;
		else if (q->type == GEN_SHRUB)
			scale_shape(q, k);
		else
			ok = scale_ratios(q, k);
		break;
	}
	case GEN_LEAFIER:
	case GEN_BARER: {
		int step = q->type == GEN_PALM ? ADJUST_LEAFLETS : ADJUST_LEAVES;

		q->leaf_amount += what == GEN_LEAFIER ? step : -step;
		if (q->leaf_amount < 0)
			q->leaf_amount = 0;
		break;
	}
	case GEN_ADJUST_COUNT:
		ok = false;
		break;
	}
	if (!ok || !memcmp(p, q, sizeof(*p)) || gen_params_check(q, &bad, &err) < 0) {
		*q = *p;
		return false;
	}
	return true;
}
