/* SPDX-License-Identifier: MIT */
#include "export.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <json-c/json.h>

#define SKELETON_FORMAT "edaha-skeleton"
#define SKELETON_VERSION 1

/*
 * json-c helpers that propagate allocation failure as NULL: a failing add frees the parent
 * too, so one check on the root covers the whole document and nothing leaks.
 */
static struct json_object *jset(struct json_object *obj, const char *key, struct json_object *val)
{
	if (!obj || !val || json_object_object_add(obj, key, val) < 0) {
		json_object_put(val);
		json_object_put(obj);
		return NULL;
	}
	return obj;
}

static struct json_object *jpush(struct json_object *arr, struct json_object *val)
{
	if (!arr || !val || json_object_array_add(arr, val) < 0) {
		json_object_put(val);
		json_object_put(arr);
		return NULL;
	}
	return arr;
}

/*
 * A coordinate or radius, rounded to micrometres and printed as short as it goes:
 * 0.1 not 0.10000000000000001, 2 not 2.000000, 0 not -0. JSON has no NaN or infinity;
 * the model never holds one, and a 0 keeps the file readable if it ever did.
 */
static struct json_object *jnum(double v)
{
	char s[48], digits[24];
	unsigned long long a;
	long long q;
	size_t len = 0, n = 0;
	int frac = 6;

	if (!isfinite(v))
		v = 0.0;
	if (fabs(v) >= 1e12) {
		/* Not a tree any more, but keep it a plain JSON number. */
		snprintf(s, sizeof(s), "%.0f", v);
		return json_object_new_double_s(v, s);
	}
	q = llround(v * 1e6);
	if (q == 0)
		return json_object_new_double_s(0.0, "0");

	/* Integer digits, not printf: exact, fast (a tree has ~10^5 numbers), no locale. */
	a = q < 0 ? (unsigned long long)-q : (unsigned long long)q;
	while (frac > 0 && a % 10 == 0) {
		a /= 10;
		frac--;
	}
	do {
		digits[n++] = (char)('0' + a % 10);
		a /= 10;
	} while (a || (int)n <= frac);
	if (q < 0)
		s[len++] = '-';
	while (n) {
		if ((int)n == frac)
			s[len++] = '.';
		s[len++] = digits[--n];
	}
	s[len] = '\0';
	return json_object_new_double_s((double)q / 1e6, s);
}

static struct json_object *jpoints(const struct vec3 *p, size_t n)
{
	struct json_object *arr = json_object_new_array();

	for (size_t i = 0; i < n; i++) {
		struct json_object *xyz = json_object_new_array_ext(3);

		xyz = jpush(xyz, jnum(p[i].x));
		xyz = jpush(xyz, jnum(p[i].y));
		xyz = jpush(xyz, jnum(p[i].z));
		arr = jpush(arr, xyz);
	}
	return arr;
}

static struct json_object *jbranch(const struct branch *b)
{
	struct json_object *o = json_object_new_object();
	struct json_object *radii = json_object_new_array();

	for (size_t i = 0; i < b->npoints; i++)
		radii = jpush(radii, jnum(b->radii[i]));
	o = jset(o, "id", json_object_new_int(b->id));
	o = jset(o, "parent", json_object_new_int(b->parent));
	o = jset(o, "generation", json_object_new_int(b->generation));
	o = jset(o, "origin", json_object_new_string(origin_name(b->origin)));
	o = jset(o, "parent_t", jnum(b->parent_t));
	o = jset(o, "points", jpoints(b->points, b->npoints));
	return jset(o, "radii", radii);
}

static struct json_object *jleaf(const struct leaf *l)
{
	struct json_object *o = json_object_new_object();

	o = jset(o, "id", json_object_new_int(l->id));
	o = jset(o, "branch", json_object_new_int(l->branch));
	o = jset(o, "origin", json_object_new_string(origin_name(l->origin)));
	return jset(o, "points", jpoints(l->points, l->npoints));
}

int export_skeleton(const struct tree *t, struct buf *out)
{
	struct json_object *root = json_object_new_object();
	struct json_object *view = json_object_new_array_ext(3);
	struct json_object *branches = json_object_new_array();
	struct json_object *leaves = json_object_new_array();
	size_t start = out->len, len;
	const char *json;
	int r;

	/* The front view looks along -z (src/view.h). */
	view = jpush(view, json_object_new_int(0));
	view = jpush(view, json_object_new_int(0));
	view = jpush(view, json_object_new_int(-1));
	for (size_t i = 0; i < t->nbranches; i++)
		branches = jpush(branches, jbranch(&t->branches[i]));
	for (size_t i = 0; i < t->nleaves; i++)
		leaves = jpush(leaves, jleaf(&t->leaves[i]));

	root = jset(root, "format", json_object_new_string(SKELETON_FORMAT));
	root = jset(root, "version", json_object_new_int(SKELETON_VERSION));
	root = jset(root, "up", json_object_new_string("y"));
	root = jset(root, "units", json_object_new_string("m"));
	root = jset(root, "view", view);
	root = jset(root, "branches", branches);
	root = jset(root, "leaves", leaves);
	if (!root)
		return -ENOMEM;

	/* Compact: a big tree is hundreds of thousands of numbers; one per line would bloat it. */
	/*
	 * json-c's serialiser ignores most failed appends and returns a shortened text; a
	 * failed allocation still sets errno (POSIX), so that is the check.
	 */
	errno = 0;
	json = json_object_to_json_string_length(
		root, JSON_C_TO_STRING_PLAIN | JSON_C_TO_STRING_NOSLASHESCAPE, &len);
	if (!json || errno == ENOMEM) {
		json_object_put(root);
		return -ENOMEM;
	}
	r = buf_append(out, json, len);
	if (r >= 0)
		r = buf_append(out, "\n", 1);
	json_object_put(root);
	if (r < 0)
		out->len = start;
	return r;
}
