/* SPDX-License-Identifier: MIT */
/*
 * A skeleton.json's branches (docs/skeleton-format.md), as `--skeleton` starts from
 * (docs/wood.md, "Starting from a skeleton"). json-c parses (strictly); json-c keeps no
 * positions, so for a value it refuses the reader walks the text again to the value's
 * path (branches, i, key, ...) and names its line: a file that json-c accepted is plain
 * JSON, so a small scanner that skips strings and brackets finds it.
 */
#include "skeleton_read.h"

#include <errno.h>
#include <json-c/json.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "doc.h"

#define SKELETON_FORMAT "edaha-skeleton"
#define MAX_GENERATION 1000 /* what an import's line reads back (doc_format.c) */
#define NONE SIZE_MAX

struct sk {
	const char *s;
	size_t len;
	const char *name;
	struct error *err;
	size_t root;  /* where the top-level value starts */
	size_t total; /* points of the branches read so far */
};

/* One step of a path into the text: a member's key, or (key NULL) an element's index. */
struct step {
	const char *key;
	size_t index;
};

static unsigned long line_of(const struct sk *r, size_t off)
{
	unsigned long line = 1;

	for (size_t i = 0; i < off && i < r->len; i++)
		line += r->s[i] == '\n';
	return line;
}

__attribute__((format(printf, 3, 4)))
static int fail(const struct sk *r, size_t off, const char *fmt, ...)
{
	char msg[400];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	return error_at(r->err, -EINVAL, r->name, line_of(r, off), "%s", msg);
}

static bool is_ws(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

static size_t skip_ws(const struct sk *r, size_t i)
{
	while (i < r->len && is_ws(r->s[i]))
		i++;
	return i;
}

/* i at a string's opening quote: just past its closing one. */
static size_t skip_string(const struct sk *r, size_t i)
{
	for (i++; i < r->len; i++) {
		if (r->s[i] == '\\')
			i++;
		else if (r->s[i] == '"')
			return i + 1;
	}
	return r->len;
}

/* Just past the value starting at i. */
static size_t skip_value(const struct sk *r, size_t i)
{
	int depth = 0;

	if (i >= r->len)
		return r->len;
	if (r->s[i] == '"')
		return skip_string(r, i);
	if (r->s[i] != '{' && r->s[i] != '[') {
		while (i < r->len && !is_ws(r->s[i]) && !strchr(",:]}", r->s[i]))
			i++;
		return i;
	}
	for (; i < r->len; i++) {
		char c = r->s[i];

		if (c == '"')
			i = skip_string(r, i) - 1;
		else if (c == '{' || c == '[')
			depth++;
		else if ((c == '}' || c == ']') && --depth == 0)
			return i + 1;
	}
	return r->len;
}

/* Where the value of obj's member key starts (the last one, as json-c keeps the last of
 * duplicate keys), or NONE. A key written with escapes is not recognised. */
static size_t find_member(const struct sk *r, size_t obj, const char *key)
{
	size_t klen = strlen(key), found = NONE, i;

	if (obj >= r->len || r->s[obj] != '{')
		return NONE;
	i = skip_ws(r, obj + 1);
	while (i < r->len && r->s[i] == '"') {
		size_t kend = skip_string(r, i), v;
		bool match = kend - i == klen + 2 && !memcmp(r->s + i + 1, key, klen);

		i = skip_ws(r, kend);
		if (i >= r->len || r->s[i] != ':')
			break;
		v = skip_ws(r, i + 1);
		if (match)
			found = v;
		i = skip_ws(r, skip_value(r, v));
		if (i >= r->len || r->s[i] != ',')
			break;
		i = skip_ws(r, i + 1);
	}
	return found;
}

/* Where element k of the array at arr starts, or NONE. */
static size_t find_index(const struct sk *r, size_t arr, size_t k)
{
	size_t i;

	if (arr >= r->len || r->s[arr] != '[')
		return NONE;
	i = skip_ws(r, arr + 1);
	for (size_t n = 0; i < r->len && r->s[i] != ']'; n++) {
		if (n == k)
			return i;
		i = skip_ws(r, skip_value(r, i));
		if (i >= r->len || r->s[i] != ',')
			break;
		i = skip_ws(r, i + 1);
	}
	return NONE;
}

/* The offset of the value at path from the root, or of the deepest part of it found. */
static size_t locate(const struct sk *r, const struct step *path, size_t n)
{
	size_t at = r->root;

	for (size_t i = 0; i < n; i++) {
		size_t next = path[i].key ? find_member(r, at, path[i].key)
					  : find_index(r, at, path[i].index);

		if (next == NONE)
			break;
		at = next;
	}
	return at;
}

/* branches[b].key[k][j], as far as given (key NULL, k or j NONE: stop there). */
static size_t where(const struct sk *r, size_t b, const char *key, size_t k, size_t j)
{
	struct step path[5] = { { "branches", 0 }, { NULL, b }, { key, 0 }, { NULL, k }, { NULL, j } };
	size_t n = b == NONE ? 1 : !key ? 2 : k == NONE ? 3 : j == NONE ? 4 : 5;

	return locate(r, path, n);
}

static size_t where_key(const struct sk *r, const char *key)
{
	struct step path[1] = { { key, 0 } };

	return locate(r, path, 1);
}

/* The first single quote outside a string, or len: json-c takes 'strings' even when
 * strict, JSON does not. */
static size_t single_quote(const struct sk *r)
{
	for (size_t i = 0; i < r->len; i++) {
		if (r->s[i] == '"')
			i = skip_string(r, i) - 1;
		else if (r->s[i] == '\'')
			return i;
	}
	return r->len;
}

/* The whole text as one JSON value; refused at the line json-c stopped at. */
static int parse_json(struct sk *r, struct json_object **root)
{
	const char *nul = memchr(r->s, '\0', r->len);
	struct json_tokener *tok;
	enum json_tokener_error e;
	size_t end;

	if (nul)
		return fail(r, (size_t)(nul - r->s), "not valid JSON: a NUL byte");
	tok = json_tokener_new();
	if (!tok)
		return error_at(r->err, -ENOMEM, r->name, 0, "out of memory");
	json_tokener_set_flags(tok, JSON_TOKENER_STRICT | JSON_TOKENER_VALIDATE_UTF8);
	*root = json_tokener_parse_ex(tok, r->s, (int)r->len);
	e = json_tokener_get_error(tok);
	end = json_tokener_get_parse_end(tok);
	if (e == json_tokener_continue) {
		/* the text's end: a number at the top level ends here, else it is cut short */
		*root = json_tokener_parse_ex(tok, "", 1);
		e = json_tokener_get_error(tok);
		end = r->len; /* cut short: the line of the text's last character */
		while (end > 0 && is_ws(r->s[end - 1]))
			end--;
	}
	json_tokener_free(tok);
	if (e != json_tokener_success) {
		json_object_put(*root);
		return fail(r, end, "not valid JSON: %s", json_tokener_error_desc(e));
	}
	end = skip_ws(r, end);
	if (end >= r->len)
		end = single_quote(r);
	if (end < r->len) {
		json_object_put(*root);
		return fail(r, end, "not valid JSON: %s", r->s[end] == '\'' ?
			    "a string in single quotes" : "more text after the value");
	}
	r->root = skip_ws(r, 0);
	return 0;
}

static bool get_int(struct json_object *o, const char *key, int64_t *v)
{
	struct json_object *m;

	if (!json_object_object_get_ex(o, key, &m) || !json_object_is_type(m, json_type_int))
		return false;
	*v = json_object_get_int64(m);
	return true;
}

static bool get_number(struct json_object *m, double *v)
{
	if (!json_object_is_type(m, json_type_int) && !json_object_is_type(m, json_type_double))
		return false;
	*v = json_object_get_double(m);
	return true;
}

static int check_header(const struct sk *r, struct json_object *root, struct json_object **branches)
{
	struct json_object *f;
	int64_t version;

	if (!json_object_is_type(root, json_type_object))
		return fail(r, r->root, "expected a JSON object (a skeleton.json)");
	if (!json_object_object_get_ex(root, "format", &f) || !json_object_is_type(f, json_type_string) ||
	    json_object_get_string_len(f) != (int)strlen(SKELETON_FORMAT) ||
	    strcmp(json_object_get_string(f), SKELETON_FORMAT) != 0)
		return fail(r, where_key(r, "format"), "format: expected \"%s\"", SKELETON_FORMAT);
	if (!get_int(root, "version", &version) || version < 1 || version > 2)
		return fail(r, where_key(r, "version"), "version: expected 1 or 2");
	if (!json_object_object_get_ex(root, "branches", branches) ||
	    !json_object_is_type(*branches, json_type_array))
		return fail(r, where_key(r, "branches"), "branches: expected an array");
	if (json_object_array_length(*branches) > TREE_MAX_BRANCHES)
		return fail(r, where_key(r, "branches"), "branches: %zu, more than %u",
			    json_object_array_length(*branches), TREE_MAX_BRANCHES);
	return 0;
}

/* id, parent, generation and parent_t of branch i. */
static int read_head(const struct sk *r, struct json_object *b, size_t i, int *parent,
		     double *pt, int *gen)
{
	struct json_object *m;
	int64_t v;

	if (!get_int(b, "id", &v) || v != (int64_t)i)
		return fail(r, where(r, i, "id", NONE, NONE), "branch %zu: id: expected %zu", i, i);
	if (!get_int(b, "parent", &v) || v < -1 || v >= (int64_t)i)
		return fail(r, where(r, i, "parent", NONE, NONE),
			    "branch %zu: parent: expected -1 or an earlier branch's id", i);
	*parent = (int)v;
	if (!get_int(b, "generation", &v) || v < 0 || v > MAX_GENERATION)
		return fail(r, where(r, i, "generation", NONE, NONE),
			    "branch %zu: generation: expected a whole number 0..%d", i, MAX_GENERATION);
	*gen = (int)v;
	if (!json_object_object_get_ex(b, "parent_t", &m) || !get_number(m, pt) || !isfinite(*pt) ||
	    *pt < 0 || *pt > 1)
		return fail(r, where(r, i, "parent_t", NONE, NONE),
			    "branch %zu: parent_t: expected a number within 0..1", i);
	return 0;
}

/* A number within lo..hi at branches[i].key[k][j] (j NONE: [k]). */
static int read_number(const struct sk *r, struct json_object *m, double lo, double hi,
		       size_t i, const char *key, size_t k, size_t j, double *v)
{
	const char *wrong = NULL;
	char what[64];

	if (!get_number(m, v))
		wrong = "expected a number";
	else if (!isfinite(*v))
		wrong = "not a finite number";
	else if (*v >= lo && *v <= hi)
		return 0;
	/* only now: finding the value's line walks the text */
	if (j == NONE)
		snprintf(what, sizeof(what), "branch %zu: radius %zu", i, k);
	else
		snprintf(what, sizeof(what), "branch %zu: point %zu: %c", i, k, "xyz"[j % 3]);
	if (wrong)
		return fail(r, where(r, i, key, k, j), "%s: %s", what, wrong);
	return fail(r, where(r, i, key, k, j), "%s: %g is out of range %g..%g", what, *v, lo, hi);
}

static int read_point(const struct sk *r, struct json_object *a, size_t i, size_t k,
		      struct vec3 *p)
{
	double v[3];
	int ret;

	if (!json_object_is_type(a, json_type_array) || json_object_array_length(a) != 3)
		return fail(r, where(r, i, "points", k, NONE),
			    "branch %zu: point %zu: expected [x, y, z]", i, k);
	for (size_t j = 0; j < 3; j++) {
		ret = read_number(r, json_object_array_get_idx(a, j), -DOC_MAX_COORD_M,
				  DOC_MAX_COORD_M, i, "points", k, j, &v[j]);
		if (ret < 0)
			return ret;
	}
	*p = (struct vec3){ v[0], v[1], v[2] };
	return 0;
}

/* The points and radii arrays of branch i: their sizes (*n). */
static int read_sizes(struct sk *r, struct json_object *b, size_t i, struct json_object **pts,
		      struct json_object **rad, size_t *n)
{
	if (!json_object_object_get_ex(b, "points", pts) || !json_object_is_type(*pts, json_type_array))
		return fail(r, where(r, i, "points", NONE, NONE),
			    "branch %zu: points: expected an array", i);
	*n = json_object_array_length(*pts);
	if (*n < 2)
		return fail(r, where(r, i, "points", NONE, NONE),
			    "branch %zu: points: %zu, a branch needs 2 or more", i, *n);
	if (*n > DOC_MAX_STROKE_POINTS)
		return fail(r, where(r, i, "points", NONE, NONE),
			    "branch %zu: points: %zu, more than %u", i, *n, DOC_MAX_STROKE_POINTS);
	r->total += *n;
	if (r->total > DOC_MAX_POINTS)
		return fail(r, where(r, i, "points", NONE, NONE),
			    "branch %zu: points: more than %u in all branches", i, DOC_MAX_POINTS);
	if (!json_object_object_get_ex(b, "radii", rad) || !json_object_is_type(*rad, json_type_array))
		return fail(r, where(r, i, "radii", NONE, NONE),
			    "branch %zu: radii: expected an array", i);
	if (json_object_array_length(*rad) != *n)
		return fail(r, where(r, i, "radii", NONE, NONE),
			    "branch %zu: radii: %zu for %zu points", i,
			    json_object_array_length(*rad), *n);
	return 0;
}

static int read_axis(const struct sk *r, struct json_object *pts, struct json_object *rad,
		     size_t i, size_t n, struct vec3 *p, double *radii)
{
	for (size_t k = 0; k < n; k++) {
		int ret = read_point(r, json_object_array_get_idx(pts, k), i, k, &p[k]);

		if (ret < 0)
			return ret;
	}
	for (size_t k = 0; k < n; k++) {
		int ret = read_number(r, json_object_array_get_idx(rad, k), 0, DOC_MAX_COORD_M, i,
				      "radii", k, NONE, &radii[k]);

		if (ret < 0)
			return ret;
	}
	return 0;
}

static int read_branch(struct sk *r, struct json_object *b, size_t i, struct tree *t)
{
	struct json_object *pts, *rad;
	struct vec3 *p = NULL;
	double *radii = NULL, pt = 0;
	int parent = -1, gen = 0, ret;
	size_t n = 0;

	if (!json_object_is_type(b, json_type_object))
		return fail(r, where(r, i, NULL, NONE, NONE), "branch %zu: expected an object", i);
	if ((ret = read_head(r, b, i, &parent, &pt, &gen)) < 0 ||
	    (ret = read_sizes(r, b, i, &pts, &rad, &n)) < 0)
		return ret;
	p = malloc(n * sizeof(*p));
	radii = malloc(n * sizeof(*radii));
	if (!p || !radii)
		ret = error_at(r->err, -ENOMEM, r->name, 0, "out of memory");
	else if ((ret = read_axis(r, pts, rad, i, n, p, radii)) == 0)
		ret = tree_add_branch(t, parent, pt, ORIGIN_SKETCH, p, radii, n);
	if (ret >= 0) {
		t->branches[ret].generation = gen;
		ret = 0;
	} else if (ret == -ENOMEM) {
		ret = error_at(r->err, -ENOMEM, r->name, 0, "out of memory");
	}
	free(p);
	free(radii);
	return ret;
}

int skeleton_read(const char *data, size_t len, const char *name, struct tree *out,
		  struct error *err)
{
	struct sk r = { .s = data, .len = len, .name = name, .err = err };
	struct json_object *root = NULL, *branches;
	struct tree t;
	int ret;

	if (len > SKELETON_READ_MAX_BYTES)
		return error_at(err, -EINVAL, name, 0, "larger than %u MiB", SKELETON_READ_MAX_BYTES >> 20);
	if ((ret = parse_json(&r, &root)) < 0)
		return ret;
	tree_init(&t);
	ret = check_header(&r, root, &branches);
	for (size_t i = 0; ret == 0 && i < json_object_array_length(branches); i++)
		ret = read_branch(&r, json_object_array_get_idx(branches, i), i, &t);
	json_object_put(root);
	if (ret == 0)
		tree_swap(out, &t);
	tree_finish(&t);
	return ret;
}
