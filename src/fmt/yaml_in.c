/* SPDX-License-Identifier: MIT */
/*
 * One YAML file being read (yaml_in.h): libyaml's document loader from memory (no files
 * here: platform/ reads them), and what the tree, leaf and settings readers share.
 */
#include "yaml_in.h"

#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "yaml_node.h"

unsigned long yaml_in_line(const struct yaml_in *in, const yaml_node_t *n)
{
	return n ? yaml_node_line(&n->start_mark, in->data, in->len) + in->offset : 0;
}

int yaml_in_fail(struct yaml_in *in, const yaml_node_t *n, const char *fmt, ...)
{
	char msg[sizeof(in->err->msg)];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	return error_at(in->err, -EINVAL, in->name, yaml_in_line(in, n), "%s", msg);
}

const char *yaml_in_got(const yaml_node_t *n)
{
	return n->type == YAML_SCALAR_NODE ? "a quoted string" : yaml_node_kind(n);
}

static int parse_error(struct yaml_in *in)
{
	return yaml_node_parse_error(in->err, in->name, in->offset, &in->parser, in->data, in->len);
}

/* The one document's top: a mapping, and no document after it. */
static int check_root(struct yaml_in *in, const struct yaml_in_kind *k, const yaml_node_t *root)
{
	yaml_document_t second;
	unsigned long second_at;
	bool more;

	if (!root)
		return error_at(in->err, -EINVAL, in->name, in->offset + 1,
				"empty: a %s starts \"%s: %d\"", k->what, k->version_key,
				k->version);
	if (root->type != YAML_MAPPING_NODE)
		return yaml_in_fail(in, root,
				    "expected a mapping (%s:, %s:, ...) at the top, got %s",
				    k->version_key, k->second_key, yaml_node_kind(root));
	if (!yaml_parser_load(&in->parser, &second))
		return parse_error(in);
	more = yaml_document_get_root_node(&second) != NULL;
	second_at = more ? yaml_in_line(in, yaml_document_get_root_node(&second)) : 0;
	yaml_document_delete(&second);
	if (more)
		return error_at(in->err, -EINVAL, in->name, second_at,
				"a second YAML document; one is expected");
	return 0;
}

int yaml_in_open(struct yaml_in *in, const struct yaml_in_kind *k, const char *data, size_t len,
		 const char *name, unsigned long offset, struct error *err,
		 const yaml_node_t **root)
{
	int ret;

	*in = (struct yaml_in){ .name = name, .offset = offset, .err = err, .data = data,
				.len = len };
	if (len > k->max_bytes)
		return error_at(err, -EINVAL, name, offset + 1, "larger than %zu bytes: not a %s",
				k->max_bytes, k->what);
	/* What the loader is not shown. These files have no use for YAML's aliases (*name),
	 * and the loaded document shares an aliased node with its anchor, so a bad value
	 * there would be told at the anchor's line: they are refused where they are. Nor for
	 * deep nesting, which libyaml's loader takes seconds over (40 KB of brackets: 2.4 s
	 * under the fuzzer's ASan). A syntax error is left to the loader to tell. */
	if ((ret = yaml_node_prescan(data, len, name, offset, k->max_depth, k->what, err)) < 0)
		return ret;
	if (!yaml_parser_initialize(&in->parser))
		return error_at(err, -ENOMEM, name, offset, "out of memory");
	yaml_parser_set_input_string(&in->parser, (const unsigned char *)data, len);
	if (!yaml_parser_load(&in->parser, &in->doc)) {
		ret = parse_error(in);
		yaml_parser_delete(&in->parser);
		return ret;
	}
	*root = yaml_document_get_root_node(&in->doc);
	if ((ret = check_root(in, k, *root)) < 0)
		yaml_in_close(in);
	return ret;
}

void yaml_in_close(struct yaml_in *in)
{
	yaml_document_delete(&in->doc);
	yaml_parser_delete(&in->parser);
}

/* A decimal number: digits with an optional sign, point and exponent; finite. */
int yaml_in_number(struct yaml_in *in, const yaml_node_t *n, const char *what, double *v)
{
	const char *s = yaml_node_text(n);
	char buf[24];
	double x;

	if (!s || !yaml_node_plain(n))
		return yaml_in_fail(in, n, "%s: expected a number, got %s", what, yaml_in_got(n));
	if (!yaml_node_number(s, &x))
		return yaml_in_fail(in, n, "%s: \"%s\" is not a number", what,
				    yaml_node_shown(s, buf));
	*v = x;
	return 0;
}

int yaml_in_int(struct yaml_in *in, const yaml_node_t *n, const char *what, int *v)
{
	double x;
	int ret = yaml_in_number(in, n, what, &x);

	if (ret < 0)
		return ret;
	if (x != floor(x) || fabs(x) > 1e6)
		return yaml_in_fail(in, n, "%s: expected a whole number, got %g", what, x);
	*v = (int)x;
	return 0;
}

int yaml_in_word(struct yaml_in *in, const yaml_node_t *n, const char *what, const char **w)
{
	const char *s = yaml_node_text(n);

	if (!s || !yaml_node_plain(n))
		return yaml_in_fail(in, n, "%s: expected a word, got %s", what, yaml_in_got(n));
	*w = s;
	return 0;
}

int yaml_in_seed(struct yaml_in *in, const yaml_node_t *n, const char *what, uint64_t *v)
{
	const char *s = yaml_node_text(n);
	char buf[24], *end;
	unsigned long long x;
	size_t digits;

	if (!s || !yaml_node_plain(n))
		return yaml_in_fail(in, n, "%s: expected a whole number, got %s", what,
				    yaml_in_got(n));
	if ((*s == '-' || *s == '+') && s[1] && strspn(s + 1, "0123456789") == strlen(s + 1))
		return yaml_in_fail(in, n, "%s: \"%s\" has a sign: a seed is 0..%" PRIu64, what,
				    yaml_node_shown(s, buf), UINT64_MAX);
	digits = strspn(s, "0123456789");
	if (digits == 0 || s[digits])
		return yaml_in_fail(in, n, "%s: \"%s\" is not a whole number", what,
				    yaml_node_shown(s, buf));
	errno = 0;
	x = strtoull(s, &end, 10);
#if ULLONG_MAX > UINT64_MAX
	if (x > UINT64_MAX)
		errno = ERANGE;
#endif
	if (errno == ERANGE || *end)
		return yaml_in_fail(in, n, "%s: %s is over %" PRIu64, what, yaml_node_shown(s, buf),
				    UINT64_MAX);
	*v = (uint64_t)x;
	return 0;
}

int yaml_in_version_first(struct yaml_in *in, const struct yaml_in_kind *k,
			  const yaml_node_t *root, const yaml_node_t **key)
{
	const yaml_node_t *first, *v = yaml_in_lookup(in, root, k->version_key, key);
	int version, ret;

	if (!v)
		return yaml_in_fail(in, root, "not a %s: \"%s: %d\" is missing", k->what,
				    k->version_key, k->version);
	first = yaml_document_get_node(&in->doc, root->data.mapping.pairs.start->key);
	if ((ret = yaml_in_int(in, v, k->version_key, &version)) < 0)
		return ret;
	if (version != k->version)
		return yaml_in_fail(in, v, "%s: version %d: this edaha reads %d", k->version_key,
				    version, k->version);
	if (*key != first)
		return yaml_in_fail(in, *key, "%s: not the first key: it says how to read the rest",
				    k->version_key);
	return 0;
}

const yaml_node_t *yaml_in_lookup(struct yaml_in *in, const yaml_node_t *n, const char *k,
				  const yaml_node_t **key)
{
	return yaml_node_lookup(&in->doc, n, k, key);
}

int yaml_in_unknown(struct yaml_in *in, const yaml_node_t *key, const char *k, const char *where)
{
	char buf[24];

	return yaml_in_fail(in, key, "unknown key \"%s\"%s%s", yaml_node_shown(k, buf),
			    where ? " in " : "", where ? where : "");
}

int yaml_in_pairs(struct yaml_in *in, const yaml_node_t *n, const char *what, yaml_in_pair_fn fn,
		  void *ctx)
{
	yaml_node_pair_t *start, *top;

	if (n->type != YAML_MAPPING_NODE)
		return yaml_in_fail(in, n, "%s: expected a mapping, got %s", what,
				    yaml_node_kind(n));
	start = n->data.mapping.pairs.start;
	top = n->data.mapping.pairs.top;
	for (yaml_node_pair_t *pair = start; pair < top; pair++) {
		const yaml_node_t *key = yaml_document_get_node(&in->doc, pair->key);
		const yaml_node_t *value = yaml_document_get_node(&in->doc, pair->value), *other;
		const char *k;
		char buf[24];
		int ret;

		if (!key || !value)
			return yaml_in_fail(in, n, "%s: broken YAML node", what);
		k = yaml_node_text(key);
		if (!k || !yaml_node_plain(key))
			return yaml_in_fail(in, key, "%s: expected a plain key, got %s", what,
					    yaml_in_got(key));
		/* the keys before are each once: a short look back */
		other = yaml_node_earlier_key(&in->doc, n, pair, k);
		if (other)
			return yaml_in_fail(in, key, "duplicate key \"%s\" (first on line %lu)",
					    yaml_node_shown(k, buf), yaml_in_line(in, other));
		if ((ret = fn(ctx, key, k, value)) < 0)
			return ret;
	}
	return 0;
}
