/* SPDX-License-Identifier: MIT */
/*
 * Origami leaf design files (docs/leaf-format.md): YAML read with libyaml's document loader,
 * from memory (no files here: platform/ reads them), as gen_read.c reads tree parameters.
 * Every refusal names the line; a design that reads but cannot fold is refused too.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "ori_design.h"
#include "yaml_in.h"
#include "yaml_node.h"

/* the most nodes or side parts: a row of ori_fault's lines */
#define ITEMS (ORI_MAX_NODES > ORI_MAX_SIDES ? ORI_MAX_NODES : ORI_MAX_SIDES)

struct reader {
	struct yaml_in in;
	struct ori_design *d;
	/* the line of each value read, by ori_design_check's names and node or side part:
	 * ori_design_check's refusal is told there */
	unsigned long value_line[ORI_VALUE_COUNT][ITEMS];
	/* a side part's nodes' values: [part][node][at, phi, psi] */
	unsigned long side_node_line[ORI_MAX_SIDES][ORI_MAX_NODES][3];
	/* the node or side part being read: its index, its name in messages, its keys seen */
	size_t item;
	char item_name[64];
	unsigned seen;
	/* the nodes being read: the midrib's, or side part side's (-1: the midrib's) */
	struct ori_node *nodes;
	int side;
};

/* Where a value was read, for ori_design_check's refusal. */
static void note(struct reader *r, enum ori_value v, const yaml_node_t *n)
{
	if (r->side >= 0 && v >= ORI_VALUE_NODE_AT && v <= ORI_VALUE_NODE_PSI)
		r->side_node_line[r->side][r->item][v - ORI_VALUE_NODE_AT] = yaml_in_line(&r->in, n);
	else
		r->value_line[v][r->item] = yaml_in_line(&r->in, n);
}

/* One number for both sides of the midrib, or [right, left]; a number is halved when it
 * is the two sides' sum (middle.angle). */
static int get_pair(struct reader *r, const yaml_node_t *n, const char *what, bool sum,
		    double v[2])
{
	int ret;

	if (n->type != YAML_SEQUENCE_NODE) {
		if ((ret = yaml_in_number(&r->in, n, what, &v[0])) < 0)
			return ret;
		if (sum)
			v[0] /= 2;
		v[1] = v[0];
		return 0;
	}
	if (n->data.sequence.items.top - n->data.sequence.items.start != 2)
		return yaml_in_fail(&r->in, n,
				    "%s: expected a number or [right, left], two numbers", what);
	for (int i = 0; i < 2; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->in.doc, n->data.sequence.items.start[i]);

		if (!item)
			return yaml_in_fail(&r->in, n, "%s: broken YAML node", what);
		if ((ret = yaml_in_number(&r->in, item, what, &v[i])) < 0)
			return ret;
	}
	return 0;
}

/* "middle.nodes: node 2: at", the item's key named in a message. */
static const char *item_key(struct reader *r, const char *k, char out[96])
{
	snprintf(out, 96, "%s: %s", r->item_name, k);
	return out;
}

/* ---- the sections --------------------------------------------------------------- */

/* The keys a node or a side part must give. */
enum { SEEN_AT = 1, SEEN_PHI = 2, SEEN_PSI = 4, SEEN_ANGLE = 8 };
static const struct {
	unsigned bit;
	const char *key;
} needed[] = {
	{ SEEN_AT, "at" }, { SEEN_PHI, "phi" }, { SEEN_PSI, "psi" }, { SEEN_ANGLE, "angle" },
};

static int node_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	struct ori_node *n = &r->nodes[r->item];
	char what[96];

	if (!strcmp(k, "at")) {
		r->seen |= SEEN_AT;
		note(r, ORI_VALUE_NODE_AT, v);
		return yaml_in_number(&r->in, v, item_key(r, k, what), &n->at);
	}
	if (!strcmp(k, "phi")) {
		r->seen |= SEEN_PHI;
		note(r, ORI_VALUE_NODE_PHI, v);
		return get_pair(r, v, item_key(r, k, what), false, n->phi);
	}
	if (!strcmp(k, "psi")) {
		r->seen |= SEEN_PSI;
		note(r, ORI_VALUE_NODE_PSI, v);
		return get_pair(r, v, item_key(r, k, what), false, n->psi);
	}
	return yaml_in_unknown(&r->in, key, k, "a node (at, phi, psi)");
}

static int fork_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	struct ori_side *s = &r->d->sides[r->item];
	char what[96];

	if (!strcmp(k, "at")) {
		note(r, ORI_VALUE_FORK_AT, v);
		return yaml_in_number(&r->in, v, item_key(r, "fork.at", what), &s->fork_at);
	}
	if (!strcmp(k, "a")) {
		note(r, ORI_VALUE_FORK_A, v);
		return yaml_in_number(&r->in, v, item_key(r, "fork.a", what), &s->fork_a);
	}
	if (!strcmp(k, "b")) {
		note(r, ORI_VALUE_FORK_B, v);
		return yaml_in_number(&r->in, v, item_key(r, "fork.b", what), &s->fork_b);
	}
	return yaml_in_unknown(&r->in, key, k, "fork (at, a, b)");
}

static int read_side_nodes(struct reader *r, const yaml_node_t *v);

static int side_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	struct ori_side *s = &r->d->sides[r->item];
	char what[96];

	if (!strcmp(k, "angle")) {
		r->seen |= SEEN_ANGLE;
		note(r, ORI_VALUE_SIDE_ANGLE, v);
		return yaml_in_number(&r->in, v, item_key(r, k, what), &s->angle);
	}
	if (!strcmp(k, "forks")) {
		note(r, ORI_VALUE_SIDE_FORKS, v);
		return yaml_in_int(&r->in, v, item_key(r, k, what), &s->forks);
	}
	if (!strcmp(k, "fork"))
		return yaml_in_pairs(&r->in, v, item_key(r, k, what), fork_pair, r);
	if (!strcmp(k, "nodes"))
		return read_side_nodes(r, v);
	return yaml_in_unknown(&r->in, key, k, "a side part (angle, forks, fork, nodes)");
}

/* A list of at most max mappings, each read by fn into item i: the list's entries all
 * replace the defaults'. */
static int read_list(struct reader *r, const yaml_node_t *v, const char *what, const char *one,
		     size_t max, size_t *n, yaml_in_pair_fn fn, unsigned required,
		     unsigned long *lines)
{
	size_t count;

	if (v->type != YAML_SEQUENCE_NODE)
		return yaml_in_fail(&r->in, v, "%s: expected a list, got %s", what,
				    yaml_node_kind(v));
	count = (size_t)(v->data.sequence.items.top - v->data.sequence.items.start);
	if (count > max)
		return yaml_in_fail(&r->in,
				    yaml_document_get_node(&r->in.doc,
							   v->data.sequence.items.start[max]),
				    "%s: %zu %ss given; at most %zu", what, count, one, max);
	*n = count;
	for (size_t i = 0; i < count; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->in.doc, v->data.sequence.items.start[i]);
		int ret;

		if (!item)
			return yaml_in_fail(&r->in, v, "%s: broken YAML node", what);
		r->item = i;
		r->seen = 0;
		snprintf(r->item_name, sizeof(r->item_name), "%s: %s %zu", what, one, i + 1);
		lines[i] = yaml_in_line(&r->in, item);
		if ((ret = yaml_in_pairs(&r->in, item, r->item_name, fn, r)) < 0)
			return ret;
		for (size_t j = 0; j < sizeof(needed) / sizeof(needed[0]); j++)
			if ((required & needed[j].bit) && !(r->seen & needed[j].bit))
				return yaml_in_fail(&r->in, item, "%s: %s is missing", r->item_name,
						    needed[j].key);
	}
	r->item = 0;
	return 0;
}

static int read_nodes(struct reader *r, const yaml_node_t *v)
{
	unsigned long lines[ORI_MAX_NODES] = { 0 };
	int ret;

	memset(r->d->nodes, 0, sizeof(r->d->nodes));
	r->nodes = r->d->nodes;
	r->side = -1;
	if ((ret = read_list(r, v, "middle.nodes", "node", ORI_MAX_NODES, &r->d->nnodes, node_pair,
			     SEEN_AT | SEEN_PHI | SEEN_PSI, lines)) < 0)
		return ret;
	for (size_t i = 0; i < r->d->nnodes; i++)
		r->d->nodes[i].line = lines[i];
	return 0;
}

/* A side part's nodes, read inside the part's own mapping: the part's place kept. */
static int read_side_nodes(struct reader *r, const yaml_node_t *v)
{
	struct ori_side *p = &r->d->sides[r->item];
	unsigned long lines[ORI_MAX_NODES] = { 0 };
	size_t part = r->item;
	unsigned seen = r->seen;
	char what[80], name[64];
	int ret;

	memcpy(name, r->item_name, sizeof(name));
	snprintf(what, sizeof(what), "%s: nodes", r->item_name);
	memset(p->nodes, 0, sizeof(p->nodes));
	r->nodes = p->nodes;
	r->side = (int)part;
	ret = read_list(r, v, what, "node", ORI_MAX_NODES, &p->nnodes, node_pair,
			SEEN_AT | SEEN_PHI | SEEN_PSI, lines);
	r->side = -1;
	r->item = part;
	r->seen = seen;
	memcpy(r->item_name, name, sizeof(name));
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < p->nnodes; i++)
		p->nodes[i].line = lines[i];
	return 0;
}

static int read_sides(struct reader *r, const yaml_node_t *v)
{
	unsigned long lines[ORI_MAX_SIDES] = { 0 };
	int ret;

	/* a part takes the defaults of what it leaves out, but its angle: required */
	for (size_t i = 0; i < ORI_MAX_SIDES; i++)
		ori_side_default(&r->d->sides[i]);
	if ((ret = read_list(r, v, "sides", "part", ORI_MAX_SIDES, &r->d->nsides, side_pair,
			     SEEN_ANGLE, lines)) < 0)
		return ret;
	/* past nsides, zero as in ori_design_default */
	for (size_t i = 0; i < ORI_MAX_SIDES; i++) {
		if (i < r->d->nsides)
			r->d->sides[i].line = lines[i];
		else
			memset(&r->d->sides[i], 0, sizeof(r->d->sides[i]));
	}
	return 0;
}

static int middle_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	if (!strcmp(k, "angle")) {
		note(r, ORI_VALUE_MIDDLE, v);
		return get_pair(r, v, "middle.angle", true, r->d->middle);
	}
	if (!strcmp(k, "nodes")) {
		if (r->d->fold != ORI_FOLD_FAN)
			return yaml_in_fail(&r->in, key,
					    "middle.nodes: only a fan's midrib has nodes (a half fold's "
					    "is its one crease)");
		return read_nodes(r, v);
	}
	return yaml_in_unknown(&r->in, key, k, "middle");
}

static int cut_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	bool fan = r->d->fold == ORI_FOLD_FAN;

	if (!strcmp(k, "junction") || !strcmp(k, "theta0")) {
		if (!fan)
			return yaml_in_fail(&r->in, key,
					    "cut.%s: only a fan's straight cuts have a %s (a half fold's "
					    "curved cut has width and power)",
					    k, k);
		if (!strcmp(k, "junction")) {
			note(r, ORI_VALUE_JUNCTION, v);
			return yaml_in_number(&r->in, v, "cut.junction", &r->d->junction);
		}
		note(r, ORI_VALUE_THETA0, v);
		return yaml_in_number(&r->in, v, "cut.theta0", &r->d->theta0);
	}
	if (!strcmp(k, "width") || !strcmp(k, "power")) {
		if (fan)
			return yaml_in_fail(&r->in, key,
					    "cut.%s: only a half fold's curved cut has a %s (a fan's "
					    "straight cuts have junction and theta0)",
					    k, k);
		if (!strcmp(k, "width")) {
			note(r, ORI_VALUE_WIDTH, v);
			return yaml_in_number(&r->in, v, "cut.width", &r->d->width);
		}
		note(r, ORI_VALUE_POWER, v);
		return yaml_in_number(&r->in, v, "cut.power", &r->d->power);
	}
	return yaml_in_unknown(&r->in, key, k, "cut");
}

static int read_name(struct reader *r, const yaml_node_t *v)
{
	const char *w;
	char buf[24];
	int ret;

	note(r, ORI_VALUE_NAME, v);
	if ((ret = yaml_in_word(&r->in, v, "name", &w)) < 0)
		return ret;
	if (strlen(w) >= ORI_NAME_MAX)
		return yaml_in_fail(&r->in, v, "name: \"%s\" is longer than %d characters",
				    yaml_node_shown(w, buf), ORI_NAME_MAX - 1);
	for (const char *c = w; *c; c++)
		if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '-'))
			return yaml_in_fail(&r->in, v, "name: \"%s\" is not made of a-z, 0-9 and -",
					    yaml_node_shown(w, buf));
	if (!*w)
		return yaml_in_fail(&r->in, v, "name: empty");
	memset(r->d->name, 0, sizeof(r->d->name));
	memcpy(r->d->name, w, strlen(w));
	return 0;
}

static int top_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	/* read before the rest */
	if (!strcmp(k, "edaha-leaf") || !strcmp(k, "fold"))
		return 0;
	if (!strcmp(k, "name"))
		return read_name(r, v);
	if (!strcmp(k, "size")) {
		note(r, ORI_VALUE_SIZE, v);
		return yaml_in_number(&r->in, v, "size", &r->d->size);
	}
	if (!strcmp(k, "rest")) {
		note(r, ORI_VALUE_REST, v);
		return yaml_in_number(&r->in, v, "rest", &r->d->rest);
	}
	if (!strcmp(k, "middle")) {
		r->d->line_middle = yaml_in_line(&r->in, key);
		return yaml_in_pairs(&r->in, v, "middle", middle_pair, r);
	}
	if (!strcmp(k, "sides")) {
		if (r->d->fold != ORI_FOLD_FAN)
			return yaml_in_fail(&r->in, key,
					    "sides: only a fan has side parts (a half fold is one "
					    "entire leaf)");
		return read_sides(r, v);
	}
	if (!strcmp(k, "cut")) {
		r->d->line_cut = yaml_in_line(&r->in, key);
		return yaml_in_pairs(&r->in, v, "cut", cut_pair, r);
	}
	return yaml_in_unknown(&r->in, key, k, NULL);
}

static const struct yaml_in_kind kind = {
	.what = "leaf design file", .version_key = "edaha-leaf", .version = ORI_DESIGN_VERSION,
	.second_key = "fold", .max_bytes = ORI_READ_MAX_BYTES, .max_depth = ORI_READ_MAX_DEPTH,
};

/* The version comes first, then the fold: it decides the defaults and which keys exist. */
static int read_head(struct reader *r, const yaml_node_t *root)
{
	const yaml_node_t *key = NULL, *v;
	enum ori_fold fold = ORI_FOLD_FAN;
	const char *w;
	char buf[24];
	int ret;

	if ((ret = yaml_in_version_first(&r->in, &kind, root, &key)) < 0)
		return ret;
	if ((v = yaml_in_lookup(&r->in, root, "fold", NULL))) {
		if ((ret = yaml_in_word(&r->in, v, "fold", &w)) < 0)
			return ret;
		if (!strcmp(w, "fan"))
			fold = ORI_FOLD_FAN;
		else if (!strcmp(w, "half"))
			fold = ORI_FOLD_HALF;
		else
			return yaml_in_fail(&r->in, v, "fold: \"%s\" is none of fan, half",
					    yaml_node_shown(w, buf));
	}
	ori_design_default(r->d, fold);
	r->d->line = yaml_in_line(&r->in, key);
	return 0;
}

/* The line ori_design_check's fault is told at: its value's, else (a default's fault) its
 * element's, else the file's. */
static unsigned long fault_line(const struct reader *r, const struct ori_fault *f)
{
	const struct ori_design *d = r->d;
	size_t i = f->index < ITEMS ? f->index : 0;
	unsigned long line = (unsigned)f->value < ORI_VALUE_COUNT ? r->value_line[f->value][i] : 0;

	if (f->side >= 0 && f->side < ORI_MAX_SIDES) { /* a side part's node: its value, its item */
		const struct ori_side *p = &d->sides[f->side];

		line = 0;
		if (i < ORI_MAX_NODES && f->value >= ORI_VALUE_NODE_AT && f->value <= ORI_VALUE_NODE_PSI)
			line = r->side_node_line[f->side][i][f->value - ORI_VALUE_NODE_AT];
		if (!line && i < ORI_MAX_NODES)
			line = p->nodes[i].line;
		if (!line)
			line = p->line;
	}
	if (line)
		return line;
	switch (f->value) {
	case ORI_VALUE_MIDDLE:
		line = d->line_middle;
		break;
	case ORI_VALUE_NODE_AT:
	case ORI_VALUE_NODE_PHI:
	case ORI_VALUE_NODE_PSI:
		line = i < ORI_MAX_NODES ? d->nodes[i].line : 0;
		break;
	case ORI_VALUE_SIDE_NODES:
	case ORI_VALUE_SIDE_ANGLE:
	case ORI_VALUE_SIDE_FORKS:
	case ORI_VALUE_FORK_AT:
	case ORI_VALUE_FORK_A:
	case ORI_VALUE_FORK_B:
		line = i < ORI_MAX_SIDES ? d->sides[i].line : 0;
		break;
	case ORI_VALUE_JUNCTION:
	case ORI_VALUE_THETA0:
	case ORI_VALUE_WIDTH:
	case ORI_VALUE_POWER:
		line = d->line_cut;
		break;
	default:
		break;
	}
	return line ? line : d->line;
}

static int read_root(struct reader *r, const yaml_node_t *root)
{
	struct ori_design *d = r->d;
	struct ori_fault fault;
	struct error why;
	int ret;

	if ((ret = read_head(r, root)) < 0 ||
	    (ret = yaml_in_pairs(&r->in, root, "the top level", top_pair, r)) < 0)
		return ret;
	/* what the file leaves out is the file's: refusals of it are told at its first line */
	if (!d->line_middle)
		d->line_middle = d->line;
	if (!d->line_cut)
		d->line_cut = d->line;
	for (size_t i = 0; i < d->nnodes; i++)
		if (!d->nodes[i].line)
			d->nodes[i].line = d->line;
	for (size_t i = 0; i < d->nsides; i++) {
		if (!d->sides[i].line)
			d->sides[i].line = d->line;
		for (size_t k = 0; k < d->sides[i].nnodes; k++)
			if (!d->sides[i].nodes[k].line)
				d->sides[i].nodes[k].line = d->sides[i].line;
	}
	if ((ret = ori_design_check(d, &fault, &why)) < 0)
		return error_at(r->in.err, ret, r->in.name, fault_line(r, &fault), "%s", why.msg);
	return 0;
}

int ori_read(const char *data, size_t len, const char *name, struct ori_design *d,
	     struct error *err)
{
	struct ori_design tmp;
	struct reader r = { .d = &tmp, .side = -1 };
	const yaml_node_t *root;
	struct ori_leaf leaf;
	int ret;

	ori_design_default(&tmp, ORI_FOLD_FAN);
	if ((ret = yaml_in_open(&r.in, &kind, data, len, name, 0, err, &root)) < 0)
		return ret;
	ret = read_root(&r, root);
	yaml_in_close(&r.in);
	if (ret < 0)
		return ret;
	/* a design that cannot fold is refused here, at its element's line */
	ori_leaf_init(&leaf);
	ret = ori_build(&tmp, name, &leaf, err);
	ori_leaf_finish(&leaf);
	if (ret == 0)
		*d = tmp;
	return ret;
}
