/* SPDX-License-Identifier: MIT */
/*
 * Tree parameter files (docs/tree-params.md): YAML read with libyaml's document loader,
 * from memory (no files here: platform/ reads them). Every refusal names the line.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "gen.h"
#include "yaml_node.h"

/* A parameter file is a few dozen lines; anything much larger is not one. */
#define GEN_READ_MAX_BYTES (64u << 10)

struct reader {
	const char *name;
	unsigned long offset;
	struct error *err;
	const char *data; /* the text read, for its lines */
	size_t len;
	yaml_document_t doc;
	struct gen_params *p;
};

static unsigned long line_of(const struct reader *r, const yaml_node_t *n)
{
	return n ? yaml_node_line(&n->start_mark, r->data, r->len) + r->offset : 0;
}

static int fail(struct reader *r, const yaml_node_t *n, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static int fail(struct reader *r, const yaml_node_t *n, const char *fmt, ...)
{
	char msg[sizeof(r->err->msg)];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	return error_at(r->err, -EINVAL, r->name, line_of(r, n), "%s", msg);
}

/* The user's text in a message (yaml_node_shown). */
static const char *shown(const char *s, char out[24])
{
	return yaml_node_shown(s, out);
}

/* A decimal number: digits with an optional sign, point and exponent; finite. */
static int get_number(struct reader *r, const yaml_node_t *n, const char *what, double *v)
{
	const char *s = yaml_node_text(n);
	char buf[24];
	double x;

	if (!s || !yaml_node_plain(n))
		return fail(r, n, "%s: expected a number, got %s", what,
			    n->type == YAML_SCALAR_NODE ? "a quoted string" : yaml_node_kind(n));
	if (!yaml_node_number(s, &x))
		return fail(r, n, "%s: \"%s\" is not a number", what, shown(s, buf));
	*v = x;
	return 0;
}

static int get_int(struct reader *r, const yaml_node_t *n, const char *what, int *v)
{
	double x;
	int ret = get_number(r, n, what, &x);

	if (ret < 0)
		return ret;
	if (x != floor(x) || fabs(x) > 1e6)
		return fail(r, n, "%s: expected a whole number, got %g", what, x);
	*v = (int)x;
	return 0;
}

static int get_word(struct reader *r, const yaml_node_t *n, const char *what, const char **w)
{
	const char *s = yaml_node_text(n);

	if (!s || !yaml_node_plain(n))
		return fail(r, n, "%s: expected a word, got %s", what,
			    n->type == YAML_SCALAR_NODE ? "a quoted string" : yaml_node_kind(n));
	*w = s;
	return 0;
}

static int get_point(struct reader *r, const yaml_node_t *n, const char *what, struct vec3 *v)
{
	double c[3];

	if (n->type != YAML_SEQUENCE_NODE)
		return fail(r, n, "%s: expected [x, y, z], got %s", what, yaml_node_kind(n));
	if (n->data.sequence.items.top - n->data.sequence.items.start != 3)
		return fail(r, n, "%s: expected [x, y, z], three numbers", what);
	for (int i = 0; i < 3; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->doc, n->data.sequence.items.start[i]);
		int ret;

		if (!item)
			return fail(r, n, "%s: broken YAML node", what);
		if ((ret = get_number(r, item, what, &c[i])) < 0)
			return ret;
	}
	*v = vec3(c[0], c[1], c[2]);
	return 0;
}

typedef int (*pair_fn)(struct reader *r, const yaml_node_t *key, const char *k,
		       const yaml_node_t *value);

static int for_each_pair(struct reader *r, const yaml_node_t *n, const char *what, pair_fn fn)
{
	yaml_node_pair_t *start, *top;

	if (n->type != YAML_MAPPING_NODE)
		return fail(r, n, "%s: expected a mapping, got %s", what, yaml_node_kind(n));
	start = n->data.mapping.pairs.start;
	top = n->data.mapping.pairs.top;
	for (yaml_node_pair_t *pair = start; pair < top; pair++) {
		const yaml_node_t *key = yaml_document_get_node(&r->doc, pair->key);
		const yaml_node_t *value = yaml_document_get_node(&r->doc, pair->value), *other;
		const char *k;
		char buf[24];
		int ret;

		if (!key || !value)
			return fail(r, n, "%s: broken YAML node", what);
		k = yaml_node_text(key);
		if (!k || !yaml_node_plain(key))
			return fail(r, key, "%s: expected a plain key, got %s", what, yaml_node_kind(key));
		other = yaml_node_earlier_key(&r->doc, n, pair, k);
		if (other)
			return fail(r, key, "duplicate key \"%s\" (first on line %lu)", shown(k, buf),
				    line_of(r, other));
		if ((ret = fn(r, key, k, value)) < 0)
			return ret;
	}
	return 0;
}

/* The value of key k in mapping n, or NULL. */
static const yaml_node_t *lookup(struct reader *r, const yaml_node_t *n, const char *k,
				 const yaml_node_t **key)
{
	return yaml_node_lookup(&r->doc, n, k, key);
}

static int unknown(struct reader *r, const yaml_node_t *key, const char *k, const char *in)
{
	char buf[24];

	return fail(r, key, "unknown key \"%s\"%s%s", shown(k, buf), in ? " in " : "", in ? in : "");
}

static int not_for(struct reader *r, const yaml_node_t *key, const char *k)
{
	static const char *const a_type[GEN_TYPE_COUNT] = {
		[GEN_LSYSTEM] = "an lsystem tree", [GEN_SHRUB] = "a shrub", [GEN_PALM] = "a palm",
	};

	return fail(r, key, "%s: not a parameter of %s (docs/tree-params.md)", k,
		    (unsigned)r->p->type < GEN_TYPE_COUNT ? a_type[r->p->type] : "this type");
}

/* ---- the sections --------------------------------------------------------------- */

static int trunk_pair(struct reader *r, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	if (!strcmp(k, "start"))
		return get_point(r, v, "trunk.start", &r->p->trunk_start);
	if (!strcmp(k, "end")) {
		if (r->p->type == GEN_SHRUB)
			return fail(r, key, "trunk.end: a shrub's trunk is vertical, trunk_height long");
		return get_point(r, v, "trunk.end", &r->p->trunk_end);
	}
	return unknown(r, key, k, "trunk");
}

static int angle_pair(struct reader *r, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	if (!strcmp(k, "min"))
		return get_number(r, v, "angle.min", &r->p->angle_min);
	if (!strcmp(k, "max"))
		return get_number(r, v, "angle.max", &r->p->angle_max);
	if (!strcmp(k, "randomness"))
		return get_number(r, v, "angle.randomness", &r->p->randomness);
	return unknown(r, key, k, "angle");
}

static int leaves_pair(struct reader *r, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	const char *w;
	char buf[24];
	int ret;

	if (!strcmp(k, "amount"))
		return get_int(r, v, "leaves.amount", &r->p->leaf_amount);
	if (!strcmp(k, "size"))
		return get_number(r, v, "leaves.size", &r->p->leaf_size);
	if (!strcmp(k, "type")) {
		if ((ret = get_word(r, v, "leaves.type", &w)) < 0)
			return ret;
		if (!gen_leaf_from_name(w, &r->p->leaf_type))
			return fail(r, v, "leaves.type: \"%s\" is none of oval, pointed, round, needle, "
				    "leaflet, entire, hop, maple", shown(w, buf));
		return 0;
	}
	return unknown(r, key, k, "leaves");
}

static int clip_pair(struct reader *r, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	enum gen_clip c = r->p->clip;

	if (!strcmp(k, "shape"))
		return 0; /* read first */
	if (!strcmp(k, "center"))
		return get_point(r, v, "clip.center", &r->p->clip_center);
	if (!strcmp(k, "radius") && (c == GEN_CLIP_SPHERE || c == GEN_CLIP_CONE))
		return get_number(r, v, "clip.radius", &r->p->clip_radius);
	if (!strcmp(k, "size") && c == GEN_CLIP_BOX)
		return get_point(r, v, "clip.size", &r->p->clip_size);
	if (!strcmp(k, "height") && c == GEN_CLIP_CONE)
		return get_number(r, v, "clip.height", &r->p->clip_height);
	if (!strcmp(k, "radius") || !strcmp(k, "size") || !strcmp(k, "height"))
		return fail(r, key, "clip.%s: not a measure of a %s", k, gen_clip_name(c));
	return unknown(r, key, k, "clip");
}

static int read_clip(struct reader *r, const yaml_node_t *v)
{
	const yaml_node_t *key, *shape = lookup(r, v, "shape", &key);
	const char *w;
	char buf[24];
	int ret;

	if (v->type != YAML_MAPPING_NODE)
		return fail(r, v, "clip: expected a mapping, got %s", yaml_node_kind(v));
	if (shape) {
		if ((ret = get_word(r, shape, "clip.shape", &w)) < 0)
			return ret;
		if (!strcmp(w, "sphere"))
			r->p->clip = GEN_CLIP_SPHERE;
		else if (!strcmp(w, "box"))
			r->p->clip = GEN_CLIP_BOX;
		else if (!strcmp(w, "cone"))
			r->p->clip = GEN_CLIP_CONE;
		else
			return fail(r, shape, "clip.shape: \"%s\" is none of sphere, box, cone",
				    shown(w, buf));
	}
	return for_each_pair(r, v, "clip", clip_pair);
}

static int read_ratios(struct reader *r, const yaml_node_t *v)
{
	size_t n;

	if (v->type != YAML_SEQUENCE_NODE)
		return fail(r, v, "ratios: expected a list of numbers, got %s", yaml_node_kind(v));
	n = (size_t)(v->data.sequence.items.top - v->data.sequence.items.start);
	if (n != (size_t)r->p->children)
		return fail(r, v, "ratios: %zu given for %d children; one a child", n, r->p->children);
	for (size_t i = 0; i < n; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&r->doc, v->data.sequence.items.start[i]);
		int ret;

		if (!item)
			return fail(r, v, "ratios: broken YAML node");
		if ((ret = get_number(r, item, "ratios", &r->p->ratios[i])) < 0)
			return ret;
	}
	return 0;
}

static int season_of(struct reader *r, const yaml_node_t *v)
{
	const char *w;
	char buf[24];
	int ret = get_word(r, v, "season", &w);

	if (ret < 0)
		return ret;
	if (!season_from_name(w, &r->p->season))
		return fail(r, v, "season: \"%s\" is none of spring, summer, autumn, winter",
			    shown(w, buf));
	return 0;
}

static int top_pair(struct reader *r, const yaml_node_t *key, const char *k, const yaml_node_t *v)
{
	enum gen_type t = r->p->type;
	bool branching = t != GEN_PALM;

	/* read before the rest */
	if (!strcmp(k, "edaha-tree") || !strcmp(k, "type") || !strcmp(k, "children"))
		return 0;
	if (!strcmp(k, "precision"))
		return get_int(r, v, "precision", &r->p->precision);
	if (!strcmp(k, "trunk"))
		return for_each_pair(r, v, "trunk", trunk_pair);
	if (!strcmp(k, "angle"))
		return for_each_pair(r, v, "angle", angle_pair);
	if (!strcmp(k, "thickness"))
		return get_number(r, v, "thickness", &r->p->thickness);
	if (!strcmp(k, "thickness_ratio"))
		return get_number(r, v, "thickness_ratio", &r->p->thickness_ratio);
	if (!strcmp(k, "leaves"))
		return for_each_pair(r, v, "leaves", leaves_pair);
	if (!strcmp(k, "season"))
		return season_of(r, v);
	if (!strcmp(k, "levels"))
		return branching ? get_int(r, v, "levels", &r->p->levels) : not_for(r, key, k);
	if (!strcmp(k, "ratios"))
		return branching ? read_ratios(r, v) : not_for(r, key, k);
	if (!strcmp(k, "spread"))
		return branching ? get_number(r, v, "spread", &r->p->spread) : not_for(r, key, k);
	if (!strcmp(k, "twist"))
		return branching ? get_number(r, v, "twist", &r->p->twist) : not_for(r, key, k);
	if (!strcmp(k, "trunk_height"))
		return t == GEN_SHRUB ? get_number(r, v, "trunk_height", &r->p->trunk_height)
				      : not_for(r, key, k);
	if (!strcmp(k, "clip"))
		return t == GEN_SHRUB ? read_clip(r, v) : not_for(r, key, k);
	if (!strcmp(k, "height"))
		return t == GEN_PALM ? get_number(r, v, "height", &r->p->height) : not_for(r, key, k);
	if (!strcmp(k, "fronds"))
		return t == GEN_PALM ? get_int(r, v, "fronds", &r->p->fronds) : not_for(r, key, k);
	if (!strcmp(k, "frond_length"))
		return t == GEN_PALM ? get_number(r, v, "frond_length", &r->p->frond_length)
				     : not_for(r, key, k);
	if (!strcmp(k, "droop"))
		return t == GEN_PALM ? get_number(r, v, "droop", &r->p->droop) : not_for(r, key, k);
	return unknown(r, key, k, NULL);
}

/* The version and type come first: the type decides the defaults and which keys exist. */
static int read_head(struct reader *r, const yaml_node_t *root)
{
	const yaml_node_t *key, *v = lookup(r, root, "edaha-tree", &key);
	enum gen_type type = GEN_LSYSTEM;
	const char *w;
	char buf[24];
	int version, ret;

	if (!v)
		return fail(r, root, "not a tree parameter file: \"edaha-tree: %d\" is missing",
			    GEN_PARAMS_VERSION);
	if ((ret = get_int(r, v, "edaha-tree", &version)) < 0)
		return ret;
	if (version != GEN_PARAMS_VERSION)
		return fail(r, v, "edaha-tree: version %d; this edaha reads version %d", version,
			    GEN_PARAMS_VERSION);
	if ((v = lookup(r, root, "type", &key))) {
		if ((ret = get_word(r, v, "type", &w)) < 0)
			return ret;
		for (type = 0; type < GEN_TYPE_COUNT && strcmp(w, gen_type_name(type)); type++)
			;
		if (type == GEN_TYPE_COUNT)
			return fail(r, v, "type: \"%s\" is none of lsystem, shrub, palm", shown(w, buf));
	}
	gen_params_default(r->p, type);
	if ((v = lookup(r, root, "children", &key))) {
		if (type == GEN_PALM)
			return not_for(r, key, "children");
		if ((ret = get_int(r, v, "children", &r->p->children)) < 0)
			return ret;
		if (r->p->children < 2 || r->p->children > GEN_MAX_CHILDREN)
			return fail(r, v, "children: %d is neither 2 nor 3", r->p->children);
	}
	return 0;
}

static int yaml_fail(struct reader *r, const yaml_parser_t *y, const char *data, size_t len)
{
	return yaml_node_parse_error(r->err, r->name, r->offset, y, data, len);
}

static int read_root(struct reader *r, yaml_parser_t *y, const char *data, size_t len)
{
	yaml_node_t *root = yaml_document_get_root_node(&r->doc);
	const yaml_node_t *line = root, *at = root;
	yaml_document_t second;
	const char *key = "";
	struct error why;
	char path[32];
	unsigned long second_at;
	bool more;
	int ret;

	if (!root)
		return error_at(r->err, -EINVAL, r->name, r->offset + 1,
				"empty: a tree parameter file starts \"edaha-tree: %d\"",
				GEN_PARAMS_VERSION);
	if (root->type != YAML_MAPPING_NODE)
		return fail(r, root, "expected a mapping (edaha-tree:, type:, ...) at the top, got %s",
			    yaml_node_kind(root));
	if (!yaml_parser_load(y, &second))
		return yaml_fail(r, y, data, len);
	more = yaml_document_get_root_node(&second) != NULL;
	second_at = more ? line_of(r, yaml_document_get_root_node(&second)) : 0;
	yaml_document_delete(&second);
	if (more)
		return error_at(r->err, -EINVAL, r->name, second_at,
				"a second YAML document; one is expected");
	if ((ret = read_head(r, root)) < 0 || (ret = for_each_pair(r, root, "the top level", top_pair)) < 0)
		return ret;
	if ((ret = gen_params_check(r->p, &key, &why)) == 0)
		return 0;
	/* the line of the value at fault; a default's fault is the file's */
	snprintf(path, sizeof(path), "%s", key);
	for (char *part = path, *dot; part; part = dot ? dot + 1 : NULL) {
		dot = strchr(part, '.');
		if (dot)
			*dot = '\0';
		if (!(at = lookup(r, at, part, NULL)))
			break;
		line = at;
	}
	return error_at(r->err, ret, r->name, line_of(r, line), "%s", why.msg);
}

/* A parameter file nests three deep (trunk: {start: [x, y, z]}); far deeper is not one. */
#define GEN_READ_MAX_DEPTH 8

/*
 * What the loader is not shown. A parameter file has no use for YAML's aliases (*name), and
 * the loaded document shares an aliased node with its anchor, so a bad value there would be
 * told at the anchor's line: they are refused where they are. Nor for deep nesting, which
 * libyaml's loader takes seconds over (40 KB of brackets: 2.4 s under the fuzzer's ASan).
 * A syntax error is left to the loader to tell.
 */
static int prescan(struct reader *r, const char *data, size_t len)
{
	return yaml_node_prescan(data, len, r->name, r->offset, GEN_READ_MAX_DEPTH, "tree parameter file",
				 r->err);
}

int gen_read(const char *data, size_t len, const char *name, unsigned long line_offset,
	     struct gen_params *p, struct error *err)
{
	struct reader r = {
		.name = name, .offset = line_offset, .err = err, .data = data, .len = len
	};
	struct gen_params tmp;
	yaml_parser_t y;
	int ret;

	if (len > GEN_READ_MAX_BYTES)
		return error_at(err, -EINVAL, name, line_offset + 1,
				"larger than %u bytes: not a tree parameter file", GEN_READ_MAX_BYTES);
	if ((ret = prescan(&r, data, len)) < 0)
		return ret;
	gen_params_default(&tmp, GEN_LSYSTEM);
	r.p = &tmp;
	if (!yaml_parser_initialize(&y))
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	yaml_parser_set_input_string(&y, (const unsigned char *)data, len);
	if (!yaml_parser_load(&y, &r.doc)) {
		ret = yaml_fail(&r, &y, data, len);
		yaml_parser_delete(&y);
		return ret;
	}
	ret = read_root(&r, &y, data, len);
	yaml_document_delete(&r.doc);
	yaml_parser_delete(&y);
	if (ret == 0)
		*p = tmp;
	return ret;
}
