/* SPDX-License-Identifier: MIT */
#include "json_out.h"

#include <errno.h>
#include <math.h>
#include <string.h>

#include "numfmt.h"

struct json_object *json_out_set(struct json_object *obj, const char *key, struct json_object *val)
{
	/* The key kept as it is, not copied: json-c (before its PR 962) leaks the copy when
	 * the object's table fails to grow, as a vine's 18 keys make it. */
	if (!obj || !val || json_object_object_add_ex(obj, key, val,
						     JSON_C_OBJECT_ADD_CONSTANT_KEY) < 0) {
		json_object_put(val);
		json_object_put(obj);
		return NULL;
	}
	return obj;
}

struct json_object *json_out_push(struct json_object *arr, struct json_object *val)
{
	if (!arr || !val || json_object_array_add(arr, val) < 0) {
		json_object_put(val);
		json_object_put(arr);
		return NULL;
	}
	return arr;
}

struct json_object *json_out_num(double v)
{
	char s[NUMFMT_MAX];

	numfmt_micro(s, v, true);
	return json_object_new_double_s(round(v * 1e6) / 1e6, s);
}

int json_out_append(struct json_object *root, const char *suffix, struct buf *out)
{
	size_t start = out->len, len;
	const char *json;
	int r;

	/*
	 * json-c's serialiser ignores most failed appends and returns a shortened text; a
	 * failed allocation still sets errno (POSIX), so that is the check.
	 */
	errno = 0;
	json = json_object_to_json_string_length(
		root, JSON_C_TO_STRING_PLAIN | JSON_C_TO_STRING_NOSLASHESCAPE, &len);
	if (!json || errno == ENOMEM)
		return -ENOMEM;
	r = buf_append(out, json, len);
	if (r == 0 && suffix)
		r = buf_append(out, suffix, strlen(suffix));
	if (r < 0)
		out->len = start;
	return r;
}
