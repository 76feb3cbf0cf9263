/* SPDX-License-Identifier: MIT */
/*
 * Flat settings files (yaml_flat.h): YAML read with libyaml's document loader, from memory
 * (no files here: platform/ reads them), as ori_read.c reads leaf designs. One mapping of
 * known keys; every refusal names the line.
 */
#include "yaml_flat.h"

#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "yaml_node.h"

struct reader {
	const struct yaml_flat_format *f;
	const char *name;
	struct error *err;
	const char *data; /* the text read, for its lines */
	size_t len;
	unsigned long offset; /* lines before the text (a drawing's line) */
	yaml_document_t doc;
	void *p;
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

/* What a value that is not the plain scalar asked for is, in a message. */
static const char *got(const yaml_node_t *n)
{
	return n->type == YAML_SCALAR_NODE ? "a quoted string" : yaml_node_kind(n);
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
		return fail(r, n, "%s: expected a number, got %s", what, got(n));
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
		return fail(r, n, "%s: expected a word, got %s", what, got(n));
	*w = s;
	return 0;
}

/* Any 64-bit seed, exactly: decimal digits, read as an integer (a double would round
 * seeds above 2^53). */
static int get_seed(struct reader *r, const yaml_node_t *n, const char *what, uint64_t *v)
{
	const char *s = yaml_node_text(n);
	char buf[24], *end;
	unsigned long long x;
	size_t digits;

	if (!s || !yaml_node_plain(n))
		return fail(r, n, "%s: expected a whole number, got %s", what, got(n));
	if ((*s == '-' || *s == '+') && s[1] && strspn(s + 1, "0123456789") == strlen(s + 1))
		return fail(r, n, "%s: \"%s\" has a sign: a seed is 0..%" PRIu64, what,
			    shown(s, buf), UINT64_MAX);
	digits = strspn(s, "0123456789");
	if (digits == 0 || s[digits])
		return fail(r, n, "%s: \"%s\" is not a whole number", what, shown(s, buf));
	errno = 0;
	x = strtoull(s, &end, 10);
#if ULLONG_MAX > UINT64_MAX
	if (x > UINT64_MAX)
		errno = ERANGE;
#endif
	if (errno == ERANGE || *end)
		return fail(r, n, "%s: %s is over %" PRIu64, what, shown(s, buf), UINT64_MAX);
	*v = (uint64_t)x;
	return 0;
}

/* One of the key's words: its index. */
static int get_choice(struct reader *r, const yaml_node_t *n, const struct yaml_flat_key *k,
		      int *v)
{
	const char *w = ""; /* get_word sets it when it succeeds, which gcc cannot see */
	char buf[24], list[128];
	size_t at = 0;
	int ret = get_word(r, n, k->key, &w);

	if (ret < 0)
		return ret;
	for (int i = 0; k->words[i]; i++) {
		if (!strcmp(w, k->words[i])) {
			*v = i;
			return 0;
		}
		at += (size_t)snprintf(list + at, sizeof(list) - at, "%s%s", i ? ", " : "",
				       k->words[i]);
		at = at < sizeof(list) ? at : sizeof(list) - 1;
	}
	return fail(r, n, "%s: \"%s\" is none of %s", k->key, shown(w, buf), list);
}

/* Three numbers, as a flow ([x, y, z]) or block sequence. */
static int get_vec3(struct reader *r, const yaml_node_t *n, const char *what, double v[3])
{
	yaml_node_item_t *start, *top;
	double tmp[3];

	if (n->type != YAML_SEQUENCE_NODE)
		return fail(r, n, "%s: expected three numbers [x, y, z], got %s", what,
			    yaml_node_kind(n));
	start = n->data.sequence.items.start;
	top = n->data.sequence.items.top;
	if (top - start != 3)
		return fail(r, n, "%s: expected three numbers [x, y, z], got a list of %ld", what,
			    (long)(top - start));
	for (int i = 0; i < 3; i++) {
		const yaml_node_t *item = yaml_document_get_node(&r->doc, start[i]);
		int ret;

		if (!item)
			return fail(r, n, "%s: broken YAML node", what);
		if ((ret = get_number(r, item, what, &tmp[i])) < 0)
			return ret;
	}
	memcpy(v, tmp, sizeof(tmp));
	return 0;
}

/* The value of key k in mapping n, or NULL. */
static const yaml_node_t *lookup(struct reader *r, const yaml_node_t *n, const char *k,
				 const yaml_node_t **key)
{
	return yaml_node_lookup(&r->doc, n, k, key);
}

static int read_value(struct reader *r, const struct yaml_flat_key *k, const yaml_node_t *v)
{
	char *field = (char *)r->p + k->at;

	switch (k->kind) {
	case YAML_FLAT_NUMBER:
		return get_number(r, v, k->key, (double *)(void *)field);
	case YAML_FLAT_WHOLE:
		return get_int(r, v, k->key, (int *)(void *)field);
	case YAML_FLAT_WORD:
		return get_choice(r, v, k, (int *)(void *)field);
	case YAML_FLAT_SEED:
		return get_seed(r, v, k->key, (uint64_t *)(void *)field);
	case YAML_FLAT_VEC3:
		return get_vec3(r, v, k->key, (double *)(void *)field);
	}
	return fail(r, v, "%s: broken key table", k->key);
}

/* Every pair of the top mapping: known keys, once each. */
static int read_pairs(struct reader *r, const yaml_node_t *root)
{
	yaml_node_pair_t *start = root->data.mapping.pairs.start, *top = root->data.mapping.pairs.top;

	for (yaml_node_pair_t *pair = start; pair < top; pair++) {
		const yaml_node_t *key = yaml_document_get_node(&r->doc, pair->key);
		const yaml_node_t *value = yaml_document_get_node(&r->doc, pair->value), *other;
		const char *k;
		char buf[24];
		size_t i;
		int ret;

		if (!key || !value)
			return fail(r, root, "the top level: broken YAML node");
		k = yaml_node_text(key);
		if (!k || !yaml_node_plain(key))
			return fail(r, key, "the top level: expected a plain key, got %s", got(key));
		/* the pairs before are known keys, each once: a short look back */
		other = yaml_node_earlier_key(&r->doc, root, pair, k);
		if (other)
			return fail(r, key, "duplicate key \"%s\" (first on line %lu)", shown(k, buf),
				    line_of(r, other));
		if (!strcmp(k, r->f->version_key))
			continue; /* read first */
		for (i = 0; i < r->f->nkeys && strcmp(r->f->keys[i].key, k); i++)
			;
		if (i == r->f->nkeys)
			return fail(r, key, "unknown key \"%s\"", shown(k, buf));
		if ((ret = read_value(r, &r->f->keys[i], value)) < 0)
			return ret;
	}
	return 0;
}

/* The version comes first: it says how to read the rest. Its key's line, in *line. */
static int read_head(struct reader *r, const yaml_node_t *root, unsigned long *line)
{
	const struct yaml_flat_format *f = r->f;
	const yaml_node_t *key = NULL, *first, *v = lookup(r, root, f->version_key, &key);
	int version, ret;

	if (!v)
		return fail(r, root, "not a %s: \"%s: %d\" is missing", f->what, f->version_key,
			    f->version);
	first = yaml_document_get_node(&r->doc, root->data.mapping.pairs.start->key);
	if ((ret = get_int(r, v, f->version_key, &version)) < 0)
		return ret;
	if (version != f->version)
		return fail(r, v, "%s: version %d: this edaha reads %d", f->version_key, version,
			    f->version);
	if (key != first)
		return fail(r, key, "%s: not the first key: it says how to read the rest",
			    f->version_key);
	*line = line_of(r, key);
	return 0;
}

/* The line the format's check's refusal of key is told at: its value's; else (a default
 * at fault, through a limit shared with another key) that key's; else the version's. */
static unsigned long fault_line(struct reader *r, const yaml_node_t *root, const char *key,
				unsigned long version_line)
{
	const yaml_node_t *v = key ? lookup(r, root, key, NULL) : NULL;

	for (size_t i = 0; !v && key && i < r->f->nkeys; i++)
		if (!strcmp(r->f->keys[i].key, key) && r->f->keys[i].partner)
			v = lookup(r, root, r->f->keys[i].partner, NULL);
	return v ? line_of(r, v) : version_line;
}

static int yaml_fail(struct reader *r, const yaml_parser_t *y, const char *data, size_t len)
{
	return yaml_node_parse_error(r->err, r->name, r->offset, y, data, len);
}

static int read_root(struct reader *r, yaml_parser_t *y, const char *data, size_t len)
{
	yaml_node_t *root = yaml_document_get_root_node(&r->doc);
	yaml_document_t second;
	const char *key = NULL;
	struct error why;
	unsigned long second_at, version_line = 0;
	bool more;
	int ret;

	if (!root)
		return error_at(r->err, -EINVAL, r->name, r->offset + 1,
				"empty: a %s starts \"%s: %d\"", r->f->what, r->f->version_key,
				r->f->version);
	if (root->type != YAML_MAPPING_NODE)
		return fail(r, root, "expected a mapping (%s:, %s:, ...) at the top, got %s",
			    r->f->version_key, r->f->keys[0].key, yaml_node_kind(root));
	if (!yaml_parser_load(y, &second))
		return yaml_fail(r, y, data, len);
	more = yaml_document_get_root_node(&second) != NULL;
	second_at = more ? line_of(r, yaml_document_get_root_node(&second)) : 0;
	yaml_document_delete(&second);
	if (more)
		return error_at(r->err, -EINVAL, r->name, second_at,
				"a second YAML document; one is expected");
	if ((ret = read_head(r, root, &version_line)) < 0 || (ret = read_pairs(r, root)) < 0)
		return ret;
	if ((ret = r->f->check(r->p, &key, &why)) < 0)
		return error_at(r->err, ret, r->name, fault_line(r, root, key, version_line), "%s",
				why.msg);
	return 0;
}

/*
 * What the loader is not shown. A settings file has no use for YAML's aliases (*name), and
 * the loaded document shares an aliased node with its anchor, so a bad value there would
 * be told at the anchor's line: they are refused where they are. Nor for deep nesting,
 * which libyaml's loader takes seconds over. A syntax error is left to the loader to tell.
 */
static int prescan(struct reader *r, const char *data, size_t len)
{
	return yaml_node_prescan(data, len, r->name, r->offset, r->f->max_depth, r->f->what,
				 r->err);
}

int yaml_flat_read(const struct yaml_flat_format *f, const char *data, size_t len,
		   const char *name, unsigned long line_offset, void *out, struct error *err)
{
	struct reader r = { .f = f, .name = name, .err = err, .data = data, .len = len,
			    .offset = line_offset };
	yaml_parser_t y;
	void *tmp;
	int ret;

	if (len > f->max_bytes)
		return error_at(err, -EINVAL, name, line_offset + 1,
				"larger than %zu bytes: not a %s", f->max_bytes, f->what);
	if ((ret = prescan(&r, data, len)) < 0)
		return ret;
	tmp = malloc(f->size);
	if (!tmp)
		return error_at(err, -ENOMEM, name, line_offset, "out of memory");
	f->defaults(tmp);
	r.p = tmp;
	if (!yaml_parser_initialize(&y)) {
		free(tmp);
		return error_at(err, -ENOMEM, name, line_offset, "out of memory");
	}
	yaml_parser_set_input_string(&y, (const unsigned char *)data, len);
	if (!yaml_parser_load(&y, &r.doc)) {
		ret = yaml_fail(&r, &y, data, len);
	} else {
		ret = read_root(&r, &y, data, len);
		yaml_document_delete(&r.doc);
	}
	yaml_parser_delete(&y);
	if (ret == 0)
		memcpy(out, tmp, f->size);
	free(tmp);
	return ret;
}
