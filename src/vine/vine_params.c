/* SPDX-License-Identifier: MIT */
/* A twining vine's parameters: their defaults and their limits. docs/vine-format.md is the
 * contract for both. */
#include <errno.h>
#include <string.h>

#include "vine.h"

void vine_params_default(struct vine_params *p)
{
	memset(p, 0, sizeof(*p));
	/* Table 4.1 (one thesis unit = 1 mm) */
	p->internode = 0.060;
	p->radius = 0.002;
	p->step_time = 10;
	p->angle = 18;
	p->free_nodes = 1;
	p->twining = VINE_LEFT;
	p->leaves_per_node = 1;
	p->cotyledons = 1;
	p->leaf_size = 0.012;
	/* edaha's own */
	p->points_per_internode = 8;
	p->ring_sides = 8;
	p->sweep = 2.25; /* 22.5 degrees a new point at t = 10: a turn every two internodes */
	p->internodes = 40;
	p->seed = 1;
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi; /* false for NaN */
}

static bool in_int(int v, int lo, int hi)
{
	return v >= lo && v <= hi;
}

#define BAD(k, ...) (*key = (k), error_set(err, -EINVAL, __VA_ARGS__))

int vine_params_check(const struct vine_params *p, const char **key, struct error *err)
{
	const char *unused;

	if (!key)
		key = &unused;
	if (!in(p->internode, 0.005, VINE_INTERNODE_MAX))
		return BAD("internode", "internode: %g is not within 0.005..%g m", p->internode,
			   VINE_INTERNODE_MAX);
	if (!in(p->radius, 0.0005, VINE_RADIUS_MAX))
		return BAD("radius", "radius: %g is not within 0.0005..%g m", p->radius,
			   VINE_RADIUS_MAX);
	/* a stem thicker than that would swallow its own internodes' bends */
	if (!(p->radius < p->internode / 4))
		return BAD("radius", "radius: %g is not below internode / 4 (%g m)", p->radius,
			   p->internode / 4);
	if (!in(p->step_time, 1, 100))
		return BAD("step_time", "step_time: %g is not within 1..100", p->step_time);
	if (!in(p->angle, 5, 60))
		return BAD("angle", "angle: %g is not within 5..60 degrees", p->angle);
	if (!in_int(p->free_nodes, 0, 5))
		return BAD("free_nodes", "free_nodes: %d is not within 0..5", p->free_nodes);
	if (p->twining != VINE_LEFT && p->twining != VINE_RIGHT)
		return BAD("twining", "twining: unknown");
	if (!in_int(p->leaves_per_node, 0, 2))
		return BAD("leaves_per_node", "leaves_per_node: %d is not within 0..2",
			   p->leaves_per_node);
	if (!in_int(p->cotyledons, 0, 2))
		return BAD("cotyledons", "cotyledons: %d is not within 0..2", p->cotyledons);
	if (!in(p->leaf_size, 0.001, VINE_LEAF_SIZE_MAX))
		return BAD("leaf_size", "leaf_size: %g is not within 0.001..%g m", p->leaf_size,
			   VINE_LEAF_SIZE_MAX);
	if (!in_int(p->points_per_internode, 2, 32))
		return BAD("points_per_internode", "points_per_internode: %d is not within 2..32",
			   p->points_per_internode);
	if (!in_int(p->ring_sides, 3, 16))
		return BAD("ring_sides", "ring_sides: %d is not within 3..16", p->ring_sides);
	if (!in(p->sweep, 0.1, 30))
		return BAD("sweep", "sweep: %g is not within 0.1..30 degrees per unit of time",
			   p->sweep);
	/* A new point must not jump past a support. Divided, not multiplied: 45 / step_time
	 * rounds once, to what the file writes for it (0.45 at 100), so the limit is exact. */
	if (!(p->sweep <= 45 / p->step_time))
		return BAD("sweep", "sweep: %g degrees per unit of time is %g degrees a new point "
			   "at step_time %g; at most 45", p->sweep, p->sweep * p->step_time,
			   p->step_time);
	if (!in_int(p->internodes, 1, 2000))
		return BAD("internodes", "internodes: %d is not within 1..2000", p->internodes);
	/* seed: any uint64_t */
	return 0;
}
