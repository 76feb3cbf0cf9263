/* SPDX-License-Identifier: MIT */
/*
 * Tree parameter files (docs/tree-params.md): YAML read with libyaml's document loader,
 * from memory (no files here: platform/ reads them). Every refusal names the line.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "gen.h"
#include "yaml_in.h"
#include "yaml_node.h"

/* A parameter file is a few dozen lines; anything much larger is not one. */
#define GEN_READ_MAX_BYTES (64u << 10)

struct reader {
	struct yaml_in in;
	struct gen_params *p;
	int version; /* the generators' version the tree is for */
};

static int get_point(struct reader *r, const yaml_node_t *n, const char *what, struct vec3 *v)
{
	double c[3];

	if (n->type != YAML_SEQUENCE_NODE)
		return yaml_in_fail(&r->in, n, "%s: expected [x, y, z], got %s", what,
				    yaml_node_kind(n));
	if (n->data.sequence.items.top - n->data.sequence.items.start != 3)
		return yaml_in_fail(&r->in, n, "%s: expected [x, y, z], three numbers", what);
	for (int i = 0; i < 3; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->in.doc, n->data.sequence.items.start[i]);
		int ret;

		if (!item)
			return yaml_in_fail(&r->in, n, "%s: broken YAML node", what);
		if ((ret = yaml_in_number(&r->in, item, what, &c[i])) < 0)
			return ret;
	}
	*v = vec3(c[0], c[1], c[2]);
	return 0;
}

static int not_for(struct reader *r, const yaml_node_t *key, const char *k)
{
	static const char *const a_type[GEN_TYPE_COUNT] = {
		[GEN_LSYSTEM] = "an lsystem tree", [GEN_SHRUB] = "a shrub", [GEN_PALM] = "a palm",
	};

	return yaml_in_fail(&r->in, key, "%s: not a parameter of %s (docs/tree-params.md)", k,
		    (unsigned)r->p->type < GEN_TYPE_COUNT ? a_type[r->p->type] : "this type");
}

/* ---- the sections --------------------------------------------------------------- */

static int trunk_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	if (!strcmp(k, "start"))
		return get_point(r, v, "trunk.start", &r->p->trunk_start);
	if (!strcmp(k, "end")) {
		if (r->p->type == GEN_SHRUB)
			return yaml_in_fail(&r->in, key,
					    "trunk.end: a shrub's trunk is vertical, trunk_height long");
		return get_point(r, v, "trunk.end", &r->p->trunk_end);
	}
	return yaml_in_unknown(&r->in, key, k, "trunk");
}

static int angle_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	if (!strcmp(k, "min"))
		return yaml_in_number(&r->in, v, "angle.min", &r->p->angle_min);
	if (!strcmp(k, "max"))
		return yaml_in_number(&r->in, v, "angle.max", &r->p->angle_max);
	if (!strcmp(k, "randomness"))
		return yaml_in_number(&r->in, v, "angle.randomness", &r->p->randomness);
	return yaml_in_unknown(&r->in, key, k, "angle");
}

static int leaves_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	const char *w;
	char buf[24];
	int ret;

	if (!strcmp(k, "amount"))
		return yaml_in_int(&r->in, v, "leaves.amount", &r->p->leaf_amount);
	if (!strcmp(k, "size"))
		return yaml_in_number(&r->in, v, "leaves.size", &r->p->leaf_size);
	if (!strcmp(k, "type")) {
		if ((ret = yaml_in_word(&r->in, v, "leaves.type", &w)) < 0)
			return ret;
		if (!gen_leaf_from_name(w, &r->p->leaf_type))
			return yaml_in_fail(&r->in, v,
					    "leaves.type: \"%s\" is none of oval, pointed, round, needle, "
					    "leaflet, entire, hop, maple",
					    yaml_node_shown(w, buf));
		return 0;
	}
	return yaml_in_unknown(&r->in, key, k, "leaves");
}

static int clip_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	enum gen_clip c = r->p->clip;

	if (!strcmp(k, "shape"))
		return 0; /* read first */
	if (!strcmp(k, "center"))
		return get_point(r, v, "clip.center", &r->p->clip_center);
	if (!strcmp(k, "radius") && (c == GEN_CLIP_SPHERE || c == GEN_CLIP_CONE))
		return yaml_in_number(&r->in, v, "clip.radius", &r->p->clip_radius);
	if (!strcmp(k, "size") && c == GEN_CLIP_BOX)
		return get_point(r, v, "clip.size", &r->p->clip_size);
	if (!strcmp(k, "height") && c == GEN_CLIP_CONE)
		return yaml_in_number(&r->in, v, "clip.height", &r->p->clip_height);
	if (!strcmp(k, "radius") || !strcmp(k, "size") || !strcmp(k, "height"))
		return yaml_in_fail(&r->in, key, "clip.%s: not a measure of a %s", k,
				    gen_clip_name(c));
	return yaml_in_unknown(&r->in, key, k, "clip");
}

static int read_clip(struct reader *r, const yaml_node_t *v)
{
	const yaml_node_t *key, *shape = yaml_in_lookup(&r->in, v, "shape", &key);
	const char *w;
	char buf[24];
	int ret;

	if (v->type != YAML_MAPPING_NODE)
		return yaml_in_fail(&r->in, v, "clip: expected a mapping, got %s",
				    yaml_node_kind(v));
	if (shape) {
		if ((ret = yaml_in_word(&r->in, shape, "clip.shape", &w)) < 0)
			return ret;
		if (!strcmp(w, "sphere"))
			r->p->clip = GEN_CLIP_SPHERE;
		else if (!strcmp(w, "box"))
			r->p->clip = GEN_CLIP_BOX;
		else if (!strcmp(w, "cone"))
			r->p->clip = GEN_CLIP_CONE;
		else
			return yaml_in_fail(&r->in, shape,
					    "clip.shape: \"%s\" is none of sphere, box, cone",
					    yaml_node_shown(w, buf));
	}
	return yaml_in_pairs(&r->in, v, "clip", clip_pair, r);
}

static int read_ratios(struct reader *r, const yaml_node_t *v)
{
	size_t n;

	if (v->type != YAML_SEQUENCE_NODE)
		return yaml_in_fail(&r->in, v, "ratios: expected a list of numbers, got %s",
				    yaml_node_kind(v));
	n = (size_t)(v->data.sequence.items.top - v->data.sequence.items.start);
	if (n != (size_t)r->p->children)
		return yaml_in_fail(&r->in, v, "ratios: %zu given for %d children; one a child", n,
				    r->p->children);
	for (size_t i = 0; i < n; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->in.doc, v->data.sequence.items.start[i]);
		int ret;

		if (!item)
			return yaml_in_fail(&r->in, v, "ratios: broken YAML node");
		if ((ret = yaml_in_number(&r->in, item, "ratios", &r->p->ratios[i])) < 0)
			return ret;
	}
	return 0;
}

static int season_of(struct reader *r, const yaml_node_t *v)
{
	const char *w;
	char buf[24];
	int ret = yaml_in_word(&r->in, v, "season", &w);

	if (ret < 0)
		return ret;
	if (!season_from_name(w, &r->p->season))
		return yaml_in_fail(&r->in, v,
				    "season: \"%s\" is none of spring, summer, autumn, winter",
				    yaml_node_shown(w, buf));
	return 0;
}

static int top_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	struct reader *r = ctx;
	enum gen_type t = r->p->type;
	bool branching = t != GEN_PALM;

	/* read before the rest */
	if (!strcmp(k, "edaha-tree") || !strcmp(k, "type") || !strcmp(k, "children"))
		return 0;
	if (!strcmp(k, "precision"))
		return yaml_in_int(&r->in, v, "precision", &r->p->precision);
	if (!strcmp(k, "trunk"))
		return yaml_in_pairs(&r->in, v, "trunk", trunk_pair, r);
	if (!strcmp(k, "angle"))
		return yaml_in_pairs(&r->in, v, "angle", angle_pair, r);
	if (!strcmp(k, "thickness"))
		return yaml_in_number(&r->in, v, "thickness", &r->p->thickness);
	if (!strcmp(k, "thickness_ratio"))
		return yaml_in_number(&r->in, v, "thickness_ratio", &r->p->thickness_ratio);
	if (!strcmp(k, "leaves"))
		return yaml_in_pairs(&r->in, v, "leaves", leaves_pair, r);
	if (!strcmp(k, "season"))
		return season_of(r, v);
	if (!strcmp(k, "levels"))
		return branching ? yaml_in_int(&r->in, v, "levels", &r->p->levels)
				 : not_for(r, key, k);
	if (!strcmp(k, "ratios"))
		return branching ? read_ratios(r, v) : not_for(r, key, k);
	if (!strcmp(k, "spread"))
		return branching ? yaml_in_number(&r->in, v, "spread", &r->p->spread)
				 : not_for(r, key, k);
	if (!strcmp(k, "twist"))
		return branching ? yaml_in_number(&r->in, v, "twist", &r->p->twist)
				 : not_for(r, key, k);
	if (!strcmp(k, "trunk_height"))
		return t == GEN_SHRUB
			       ? yaml_in_number(&r->in, v, "trunk_height", &r->p->trunk_height)
			       : not_for(r, key, k);
	if (!strcmp(k, "clip"))
		return t == GEN_SHRUB ? read_clip(r, v) : not_for(r, key, k);
	if (!strcmp(k, "height"))
		return t == GEN_PALM ? yaml_in_number(&r->in, v, "height", &r->p->height)
				     : not_for(r, key, k);
	if (!strcmp(k, "fronds"))
		return t == GEN_PALM ? yaml_in_int(&r->in, v, "fronds", &r->p->fronds)
				     : not_for(r, key, k);
	if (!strcmp(k, "frond_length"))
		return t == GEN_PALM
			       ? yaml_in_number(&r->in, v, "frond_length", &r->p->frond_length)
			       : not_for(r, key, k);
	if (!strcmp(k, "droop"))
		return t == GEN_PALM ? yaml_in_number(&r->in, v, "droop", &r->p->droop)
				     : not_for(r, key, k);
	return yaml_in_unknown(&r->in, key, k, NULL);
}

/* The version and type come first: the type decides the defaults and which keys exist. */
static int read_head(struct reader *r, const yaml_node_t *root)
{
	const yaml_node_t *key, *v = yaml_in_lookup(&r->in, root, "edaha-tree", &key);
	enum gen_type type = GEN_LSYSTEM;
	const char *w;
	char buf[24];
	int version, ret;

	if (!v)
		return yaml_in_fail(&r->in, root,
				    "not a tree parameter file: \"edaha-tree: %d\" is missing",
				    GEN_PARAMS_VERSION);
	if ((ret = yaml_in_int(&r->in, v, "edaha-tree", &version)) < 0)
		return ret;
	if (version != GEN_PARAMS_VERSION)
		return yaml_in_fail(&r->in, v,
				    "edaha-tree: version %d; this edaha reads version %d", version,
				    GEN_PARAMS_VERSION);
	if ((v = yaml_in_lookup(&r->in, root, "type", &key))) {
		if ((ret = yaml_in_word(&r->in, v, "type", &w)) < 0)
			return ret;
		for (type = 0; type < GEN_TYPE_COUNT && strcmp(w, gen_type_name(type)); type++)
			;
		if (type == GEN_TYPE_COUNT)
			return yaml_in_fail(&r->in, v,
					    "type: \"%s\" is none of lsystem, shrub, palm",
					    yaml_node_shown(w, buf));
	}
	gen_params_default(r->p, type);
	if ((v = yaml_in_lookup(&r->in, root, "children", &key))) {
		if (type == GEN_PALM)
			return not_for(r, key, "children");
		if ((ret = yaml_in_int(&r->in, v, "children", &r->p->children)) < 0)
			return ret;
		if (r->p->children < 2 || r->p->children > GEN_MAX_CHILDREN)
			return yaml_in_fail(&r->in, v, "children: %d is neither 2 nor 3",
					    r->p->children);
	}
	return 0;
}

/* A parameter file nests three deep (trunk: {start: [x, y, z]}); far deeper is not one. */
static const struct yaml_in_kind kind = {
	.what = "tree parameter file", .version_key = "edaha-tree", .version = GEN_PARAMS_VERSION,
	.second_key = "type", .max_bytes = GEN_READ_MAX_BYTES, .max_depth = 8,
};

static int read_root(struct reader *r, const yaml_node_t *root)
{
	const yaml_node_t *line = root, *at = root;
	const char *key = "";
	struct error why;
	char path[32];
	int ret;

	if ((ret = read_head(r, root)) < 0)
		return ret;
	/* the head set the type's defaults; the limits are the version's */
	r->p->gen_version = r->version;
	if ((ret = yaml_in_pairs(&r->in, root, "the top level", top_pair, r)) < 0)
		return ret;
	if ((ret = gen_params_check(r->p, &key, &why)) == 0)
		return 0;
	/* the line of the value at fault; a default's fault is the file's */
	snprintf(path, sizeof(path), "%s", key);
	for (char *part = path, *dot; part; part = dot ? dot + 1 : NULL) {
		dot = strchr(part, '.');
		if (dot)
			*dot = '\0';
		if (!(at = yaml_in_lookup(&r->in, at, part, NULL)))
			break;
		line = at;
	}
	return error_at(r->in.err, ret, r->in.name, yaml_in_line(&r->in, line), "%s", why.msg);
}

int gen_read(const char *data, size_t len, const char *name, unsigned long line_offset,
	     struct gen_params *p, struct error *err)
{
	return gen_read_version(data, len, name, line_offset, GEN_VERSION, p, err);
}

int gen_read_version(const char *data, size_t len, const char *name, unsigned long line_offset,
		     int version, struct gen_params *p, struct error *err)
{
	struct gen_params tmp;
	struct reader r = { .p = &tmp, .version = version };
	const yaml_node_t *root;
	int ret;

	if (version < 1 || version > GEN_VERSION)
		return error_at(err, -EINVAL, name, line_offset + 1,
				"generator version %d is not supported (this edaha has 1 to %d)",
				version, GEN_VERSION);
	gen_params_default(&tmp, GEN_LSYSTEM);
	if ((ret = yaml_in_open(&r.in, &kind, data, len, name, line_offset, err, &root)) < 0)
		return ret;
	ret = read_root(&r, root);
	yaml_in_close(&r.in);
	if (ret == 0)
		*p = tmp;
	return ret;
}
