/* SPDX-License-Identifier: MIT */
/* An origami leaf's design: its defaults and its limits. docs/leaf-format.md is the
 * contract for both. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "ori_design.h"

void ori_side_default(struct ori_side *s)
{
	memset(s, 0, sizeof(*s));
	s->angle = 55;
	s->forks = 0;
	s->fork_at = 0.5;
	s->fork_a = 30;
	s->fork_b = 30;
	s->nnodes = 0;
}

void ori_design_default(struct ori_design *d, enum ori_fold fold)
{
	/* entries past nnodes and nsides stay zero */
	memset(d, 0, sizeof(*d));
	strcpy(d->name, "leaf");
	d->fold = fold;
	d->size = 0.08;
	d->rest = 0.9;
	d->middle[0] = d->middle[1] = fold == ORI_FOLD_HALF ? 90 : 30;
	if (fold != ORI_FOLD_HALF) {
		d->nsides = 2;
		for (size_t i = 0; i < d->nsides; i++)
			ori_side_default(&d->sides[i]);
	}
	d->junction = 0.4;
	d->theta0 = 200;
	d->width = 0.35;
	d->power = 0.8;
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi; /* false for NaN */
}

/* Names the value at fault and says what is wrong with it. */
#define BAD(v, i, ...)                                                                \
	(at->value = (v), at->index = (i), at->side = -1, error_set(why, -EINVAL, __VA_ARGS__))

static bool name_ok(const char *s)
{
	size_t n = strnlen(s, ORI_NAME_MAX);

	if (n == 0 || n == ORI_NAME_MAX)
		return false;
	for (size_t i = 0; i < n; i++)
		if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= '0' && s[i] <= '9') || s[i] == '-'))
			return false;
	return true;
}

/* "right", "left", or nothing when the two are the same: as a file gives one number. */
static const char *which(const double pair[2], int i)
{
	if (pair[0] == pair[1])
		return "";
	return i == 0 ? " (right)" : " (left)";
}

/* A node's or side part's value at fault, i its index, named from 1. */
#define BAD_NODE(v, fmt, ...)                                                         \
	(BAD(v, i, "%s: node %zu: " fmt, where, i + 1, __VA_ARGS__), at->side = side, -EINVAL)
#define BAD_SIDE(v, fmt, ...) BAD(v, i, "sides: part %zu: " fmt, i + 1, __VA_ARGS__)

/* The nodes of the midrib (side -1, where "middle.nodes") or of side part side's vein. */
static int check_nodes(const struct ori_node *nodes, size_t nn, int side, const char *where,
		       struct ori_fault *at, struct error *why)
{
	for (size_t i = 0; i < nn; i++) {
		const struct ori_node *n = &nodes[i];

		if (!(n->at > 0 && n->at < 1))
			return BAD_NODE(ORI_VALUE_NODE_AT, "at %g is not strictly between 0 and 1",
					n->at);
		if (i > 0 && !(n->at > nodes[i - 1].at))
			return BAD_NODE(ORI_VALUE_NODE_AT, "at %g is not beyond node %zu's %g: nodes "
					"go outwards from O", n->at, i, nodes[i - 1].at);
		for (int s = 0; s < 2; s++) {
			if (!(n->phi[s] > 0 && n->phi[s] < 90))
				return BAD_NODE(ORI_VALUE_NODE_PHI, "phi %g%s is not strictly between 0 "
						"and 90 degrees", n->phi[s], which(n->phi, s));
			if (!(n->psi[s] > 0))
				return BAD_NODE(ORI_VALUE_NODE_PSI, "psi %g%s is not above 0 degrees",
						n->psi[s], which(n->psi, s));
			if (!(n->psi[s] < n->phi[s]))
				return BAD_NODE(ORI_VALUE_NODE_PSI, "psi %g%s is not below phi %g: the "
						"extra mountain lies between the side vein and the "
						"%s", n->psi[s], which(n->psi, s), n->phi[s],
						side < 0 ? "midrib" : "vein");
		}
	}
	return 0;
}

static int check_sides(const struct ori_design *d, struct ori_fault *at, struct error *why)
{
	for (size_t i = 0; i < d->nsides; i++) {
		const struct ori_side *p = &d->sides[i];

		if (!in(p->angle, 5, 170))
			return BAD_SIDE(ORI_VALUE_SIDE_ANGLE, "angle %g is not within 5..170 degrees",
					p->angle);
		if (p->forks < 0 || p->forks > ORI_MAX_FORKS)
			return BAD_SIDE(ORI_VALUE_SIDE_FORKS, "forks %d is not within 0..%d", p->forks,
					ORI_MAX_FORKS);
		if (!in(p->fork_at, 0.1, 0.9))
			return BAD_SIDE(ORI_VALUE_FORK_AT, "fork.at %g is not within 0.1..0.9",
					p->fork_at);
		if (!in(p->fork_a, 1, 80))
			return BAD_SIDE(ORI_VALUE_FORK_A, "fork.a %g is not within 1..80 degrees",
					p->fork_a);
		if (!in(p->fork_b, 1, 80))
			return BAD_SIDE(ORI_VALUE_FORK_B, "fork.b %g is not within 1..80 degrees",
					p->fork_b);
		if (p->nnodes > ORI_MAX_NODES)
			return BAD_SIDE(ORI_VALUE_SIDE_NODES, "nodes: %zu, over %d", p->nnodes,
					ORI_MAX_NODES);
		if (p->nnodes > 0 && p->forks > 0)
			return BAD_SIDE(ORI_VALUE_SIDE_NODES, "nodes with forks %d: a vein either "
					"forks or has nodes", p->forks);
	}
	for (size_t j = 0; j < d->nsides; j++) {
		char where[40];
		int ret;

		snprintf(where, sizeof(where), "sides: part %zu", j + 1);
		if ((ret = check_nodes(d->sides[j].nodes, d->sides[j].nnodes, (int)j, where, at,
				       why)) < 0)
			return ret;
	}
	return 0;
}

int ori_design_check(const struct ori_design *d, struct ori_fault *at, struct error *why)
{
	int ret;

	if (d->fold != ORI_FOLD_FAN && d->fold != ORI_FOLD_HALF)
		return BAD(ORI_VALUE_DESIGN, 0, "fold: unknown");
	if (!name_ok(d->name))
		return BAD(ORI_VALUE_NAME, 0, "name: not 1..%d of a-z, 0-9 and -",
			   ORI_NAME_MAX - 1);
	if (!in(d->size, 0.005, 0.5))
		return BAD(ORI_VALUE_SIZE, 0, "size: %g is not within 0.005..0.5 m", d->size);
	if (!in(d->rest, 0.5, 1))
		return BAD(ORI_VALUE_REST, 0, "rest: %g is not within 0.5..1", d->rest);
	for (int s = 0; s < 2; s++)
		if (!in(d->middle[s], 2, 170))
			return BAD(ORI_VALUE_MIDDLE, 0, "middle.angle: %g degrees %s of the midrib is "
				   "not within 2..170", d->middle[s],
				   d->middle[0] == d->middle[1] ? "each side" : s == 0 ? "right" : "left");
	if (d->nnodes > ORI_MAX_NODES)
		return BAD(ORI_VALUE_DESIGN, 0, "middle.nodes: %zu, over %d", d->nnodes,
			   ORI_MAX_NODES);
	if (d->nsides > ORI_MAX_SIDES)
		return BAD(ORI_VALUE_DESIGN, 0, "sides: %zu, over %d", d->nsides, ORI_MAX_SIDES);
	if (d->fold == ORI_FOLD_HALF && d->nnodes > 0)
		return BAD(ORI_VALUE_DESIGN, 0, "middle.nodes: only a fan's midrib has nodes");
	if (d->fold == ORI_FOLD_HALF && d->nsides > 0)
		return BAD(ORI_VALUE_DESIGN, 0, "sides: only a fan has side parts");
	if ((ret = check_nodes(d->nodes, d->nnodes, -1, "middle.nodes", at, why)) < 0 ||
	    (ret = check_sides(d, at, why)) < 0)
		return ret;
	/* a fold's own keys; the other fold's keep their defaults, in range too */
	if (!in(d->junction, 0.05, 0.95))
		return BAD(ORI_VALUE_JUNCTION, 0, "cut.junction: %g is not within 0.05..0.95",
			   d->junction);
	if (!in(d->theta0, 30, 720))
		return BAD(ORI_VALUE_THETA0, 0, "cut.theta0: %g is not within 30..720 degrees",
			   d->theta0);
	if (!in(d->width, 0.05, 1))
		return BAD(ORI_VALUE_WIDTH, 0, "cut.width: %g is not within 0.05..1", d->width);
	if (!in(d->power, 0.2, 1))
		return BAD(ORI_VALUE_POWER, 0, "cut.power: %g is not within 0.2..1", d->power);
	return 0;
}
