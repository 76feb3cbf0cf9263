/* SPDX-License-Identifier: MIT */
#include "skel.h"

#include <json-c/json.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int bad(const char *path, const char *what, size_t i)
{
	fprintf(stderr, "%s: %s (element %zu)\n", path, what, i);
	return -1;
}

static json_object *field(json_object *o, const char *k)
{
	json_object *v = NULL;

	return json_object_object_get_ex(o, k, &v) ? v : NULL;
}

static int get_int(json_object *o, const char *k, int *v)
{
	json_object *f = field(o, k);

	if (!f || !json_object_is_type(f, json_type_int))
		return -1;
	*v = json_object_get_int(f);
	return 0;
}

static int get_string(json_object *o, const char *k, char *out, size_t cap)
{
	json_object *f = field(o, k);

	if (!f || !json_object_is_type(f, json_type_string) ||
	    strlen(json_object_get_string(f)) >= cap)
		return -1;
	strcpy(out, json_object_get_string(f));
	return 0;
}

static int number(json_object *v, double *x)
{
	if (!v || !(json_object_is_type(v, json_type_int) || json_object_is_type(v, json_type_double)))
		return -1;
	*x = json_object_get_double(v);
	return 0;
}

/* [[x, y, z], ...] into a new array. */
static int get_points(json_object *o, double (**out)[3], size_t *n)
{
	json_object *a = field(o, "points");

	*out = NULL;
	*n = 0;
	if (!a || !json_object_is_type(a, json_type_array))
		return -1;
	*n = json_object_array_length(a);
	*out = calloc(*n ? *n : 1, sizeof(**out));
	if (!*out)
		return -1;
	for (size_t i = 0; i < *n; i++) {
		json_object *p = json_object_array_get_idx(a, i);

		if (!p || !json_object_is_type(p, json_type_array) || json_object_array_length(p) != 3)
			return -1;
		for (int k = 0; k < 3; k++)
			if (number(json_object_array_get_idx(p, k), &(*out)[i][k]) < 0)
				return -1;
	}
	return 0;
}

static int read_branch(json_object *o, struct skel_branch *b)
{
	json_object *r = field(o, "radii");

	b->level = -1;
	if (get_int(o, "id", &b->id) < 0 || get_int(o, "parent", &b->parent) < 0 ||
	    get_int(o, "generation", &b->generation) < 0 ||
	    get_string(o, "origin", b->origin, sizeof(b->origin)) < 0 ||
	    number(field(o, "parent_t"), &b->parent_t) < 0 || get_points(o, &b->points, &b->npoints) < 0)
		return -1;
	if (field(o, "level") && get_int(o, "level", &b->level) < 0)
		return -1;
	if (!r || !json_object_is_type(r, json_type_array) || json_object_array_length(r) != b->npoints)
		return -1;
	b->radii = calloc(b->npoints ? b->npoints : 1, sizeof(double));
	if (!b->radii)
		return -1;
	for (size_t i = 0; i < b->npoints; i++)
		if (number(json_object_array_get_idx(r, i), &b->radii[i]) < 0)
			return -1;
	return 0;
}

static int read_leaf(json_object *o, struct skel_leaf *l)
{
	if (get_int(o, "id", &l->id) < 0 || get_int(o, "branch", &l->branch) < 0 ||
	    get_string(o, "origin", l->origin, sizeof(l->origin)) < 0)
		return -1;
	return get_points(o, &l->points, &l->npoints);
}

int skel_load(const char *path, struct skel *s)
{
	json_object *root = json_object_from_file(path), *br, *lv;
	int ret = -1;

	memset(s, 0, sizeof(*s));
	if (!root) {
		fprintf(stderr, "%s: not readable JSON\n", path);
		return -1;
	}
	br = field(root, "branches");
	lv = field(root, "leaves");
	if (!br || !lv || !json_object_is_type(br, json_type_array) ||
	    !json_object_is_type(lv, json_type_array)) {
		bad(path, "no branches or leaves arrays", 0);
		goto out;
	}
	if (field(root, "season"))
		get_string(root, "season", s->season, sizeof(s->season));
	s->nbranches = json_object_array_length(br);
	s->nleaves = json_object_array_length(lv);
	s->branches = calloc(s->nbranches + 1, sizeof(*s->branches));
	s->leaves = calloc(s->nleaves + 1, sizeof(*s->leaves));
	if (!s->branches || !s->leaves)
		goto out;
	for (size_t i = 0; i < s->nbranches; i++) {
		if (read_branch(json_object_array_get_idx(br, i), &s->branches[i]) < 0) {
			bad(path, "a branch without its fields", i);
			goto out;
		}
		/* ids are indices, parents come first: the tests index by them */
		if (s->branches[i].id != (int)i || s->branches[i].parent >= (int)i ||
		    s->branches[i].parent < -1) {
			bad(path, "branch id or parent out of order", i);
			goto out;
		}
	}
	for (size_t i = 0; i < s->nleaves; i++) {
		if (read_leaf(json_object_array_get_idx(lv, i), &s->leaves[i]) < 0) {
			bad(path, "a leaf without its fields", i);
			goto out;
		}
		if (s->leaves[i].id != (int)i || s->leaves[i].branch < 0 ||
		    s->leaves[i].branch >= (int)s->nbranches) {
			bad(path, "leaf id or branch out of range", i);
			goto out;
		}
	}
	ret = 0;
out:
	json_object_put(root);
	if (ret < 0)
		skel_free(s);
	return ret;
}

void skel_free(struct skel *s)
{
	for (size_t i = 0; s->branches && i < s->nbranches; i++) {
		free(s->branches[i].points);
		free(s->branches[i].radii);
	}
	for (size_t i = 0; s->leaves && i < s->nleaves; i++)
		free(s->leaves[i].points);
	free(s->branches);
	free(s->leaves);
	memset(s, 0, sizeof(*s));
}

double skel_length(const struct skel_branch *b)
{
	double len = 0;

	for (size_t i = 1; i < b->npoints; i++)
		len += sqrt(pow(b->points[i][0] - b->points[i - 1][0], 2) +
			    pow(b->points[i][1] - b->points[i - 1][1], 2) +
			    pow(b->points[i][2] - b->points[i - 1][2], 2));
	return len;
}

void skel_direction(const struct skel_branch *b, double d[3])
{
	double len = 0;

	for (int k = 0; k < 3; k++) {
		d[k] = b->npoints ? b->points[b->npoints - 1][k] - b->points[0][k] : 0;
		len += d[k] * d[k];
	}
	len = sqrt(len);
	for (int k = 0; k < 3; k++)
		d[k] = len > 0 ? d[k] / len : 0;
}
