/* SPDX-License-Identifier: MIT */
/*
 * jsoncmp [--eps E] EXPECTED.json ACTUAL.json: same structure, same strings and numbers
 * within E (default 1e-4). Prints the path of the first difference. Exit 0 same, 1 differ,
 * 2 unreadable.
 */
#include <json-c/json.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double eps = 1e-4;

static int differ(const char *path, const char *what)
{
	fprintf(stderr, "jsoncmp: %s: %s\n", path[0] ? path : "(top)", what);
	return 1;
}

static int compare(json_object *a, json_object *b, char *path, size_t cap)
{
	size_t plen = strlen(path);
	json_type ta = json_object_get_type(a), tb = json_object_get_type(b);
	bool na = ta == json_type_int || ta == json_type_double;
	bool nb = tb == json_type_int || tb == json_type_double;

	if (na && nb) {
		double x = json_object_get_double(a), y = json_object_get_double(b);
		char msg[128];

		if (fabs(x - y) <= eps)
			return 0;
		snprintf(msg, sizeof(msg), "expected %.9g, got %.9g", x, y);
		return differ(path, msg);
	}
	if (ta != tb)
		return differ(path, "different types");
	switch (ta) {
	case json_type_null:
		return 0;
	case json_type_boolean:
		return json_object_get_boolean(a) == json_object_get_boolean(b) ? 0 :
										  differ(path, "different booleans");
	case json_type_string:
		return strcmp(json_object_get_string(a), json_object_get_string(b)) ? differ(path, "different strings") : 0;
	case json_type_array: {
		size_t n = json_object_array_length(a);

		if (n != json_object_array_length(b))
			return differ(path, "different array lengths");
		for (size_t i = 0; i < n; i++) {
			snprintf(path + plen, cap - plen, "[%zu]", i);
			if (compare(json_object_array_get_idx(a, i), json_object_array_get_idx(b, i), path, cap))
				return 1;
		}
		path[plen] = '\0';
		return 0;
	}
	case json_type_object:
		if (json_object_object_length(a) != json_object_object_length(b))
			return differ(path, "different number of keys");
		json_object_object_foreach(a, key, va) {
			json_object *vb;

			snprintf(path + plen, cap - plen, ".%s", key);
			if (!json_object_object_get_ex(b, key, &vb))
				return differ(path, "missing");
			if (compare(va, vb, path, cap))
				return 1;
		}
		path[plen] = '\0';
		return 0;
	default:
		return differ(path, "unexpected type");
	}
}

int main(int argc, char **argv)
{
	json_object *a, *b;
	char path[4096] = "";
	int i = 1, ret;

	if (argc == 5 && strcmp(argv[1], "--eps") == 0) {
		eps = atof(argv[2]);
		i = 3;
	}
	if (argc - i != 2) {
		fputs("usage: jsoncmp [--eps E] EXPECTED.json ACTUAL.json\n", stderr);
		return 2;
	}
	a = json_object_from_file(argv[i]);
	b = json_object_from_file(argv[i + 1]);
	if (!a || !b) {
		fprintf(stderr, "jsoncmp: cannot read %s\n", a ? argv[i + 1] : argv[i]);
		json_object_put(a);
		json_object_put(b);
		return 2;
	}
	ret = compare(a, b, path, sizeof(path));
	json_object_put(a);
	json_object_put(b);
	return ret;
}
