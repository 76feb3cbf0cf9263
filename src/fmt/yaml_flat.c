/* SPDX-License-Identifier: MIT */
/*
 * Flat settings files (yaml_flat.h): YAML read with libyaml's document loader, from memory
 * (no files here: platform/ reads them), as ori_read.c reads leaf designs. One mapping of
 * known keys; every refusal names the line.
 */
#include "yaml_flat.h"

#include <errno.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "yaml_in.h"
#include "yaml_node.h"

struct reader {
	struct yaml_in in;
	struct yaml_in_kind kind;
	const struct yaml_flat_format *f;
	void *p;
};

/* One of the key's words: its index. */
static int get_choice(struct reader *r, const yaml_node_t *n, const struct yaml_flat_key *k,
		      int *v)
{
	const char *w = ""; /* get_word sets it when it succeeds, which gcc cannot see */
	char buf[24], list[128];
	size_t at = 0;
	int ret = yaml_in_word(&r->in, n, k->key, &w);

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
	return yaml_in_fail(&r->in, n, "%s: \"%s\" is none of %s", k->key, yaml_node_shown(w, buf),
			    list);
}

/* Three numbers, as a flow ([x, y, z]) or block sequence. */
static int get_vec3(struct reader *r, const yaml_node_t *n, const char *what, double v[3])
{
	yaml_node_item_t *start, *top;
	double tmp[3];

	if (n->type != YAML_SEQUENCE_NODE)
		return yaml_in_fail(&r->in, n, "%s: expected three numbers [x, y, z], got %s", what,
			    yaml_node_kind(n));
	start = n->data.sequence.items.start;
	top = n->data.sequence.items.top;
	if (top - start != 3)
		return yaml_in_fail(&r->in, n,
				    "%s: expected three numbers [x, y, z], got a list of %ld", what,
				    (long)(top - start));
	for (int i = 0; i < 3; i++) {
		const yaml_node_t *item = yaml_document_get_node(&r->in.doc, start[i]);
		int ret;

		if (!item)
			return yaml_in_fail(&r->in, n, "%s: broken YAML node", what);
		if ((ret = yaml_in_number(&r->in, item, what, &tmp[i])) < 0)
			return ret;
	}
	memcpy(v, tmp, sizeof(tmp));
	return 0;
}

static int read_value(struct reader *r, const struct yaml_flat_key *k, const yaml_node_t *v)
{
	char *field = (char *)r->p + k->at;

	switch (k->kind) {
	case YAML_FLAT_NUMBER:
		return yaml_in_number(&r->in, v, k->key, (double *)(void *)field);
	case YAML_FLAT_WHOLE:
		return yaml_in_int(&r->in, v, k->key, (int *)(void *)field);
	case YAML_FLAT_WORD:
		return get_choice(r, v, k, (int *)(void *)field);
	case YAML_FLAT_SEED:
		return yaml_in_seed(&r->in, v, k->key, (uint64_t *)(void *)field);
	case YAML_FLAT_VEC3:
		return get_vec3(r, v, k->key, (double *)(void *)field);
	}
	return yaml_in_fail(&r->in, v, "%s: broken key table", k->key);
}

/* A pair of the top mapping: a known key. */
static int top_pair(void *ctx, const yaml_node_t *key, const char *k, const yaml_node_t *value)
{
	struct reader *r = ctx;
	size_t i;

	if (!strcmp(k, r->f->version_key))
		return 0; /* read first */
	for (i = 0; i < r->f->nkeys && strcmp(r->f->keys[i].key, k); i++)
		;
	if (i == r->f->nkeys)
		return yaml_in_unknown(&r->in, key, k, NULL);
	return read_value(r, &r->f->keys[i], value);
}

/* The version comes first: it says how to read the rest. Its key's line, in *line. */
static int read_head(struct reader *r, const yaml_node_t *root, unsigned long *line)
{
	const yaml_node_t *key = NULL;
	int ret = yaml_in_version_first(&r->in, &r->kind, root, &key);

	if (ret == 0)
		*line = yaml_in_line(&r->in, key);
	return ret;
}

/* The line the format's check's refusal of key is told at: its value's; else (a default
 * at fault, through a limit shared with another key) that key's; else the version's. */
static unsigned long fault_line(struct reader *r, const yaml_node_t *root, const char *key,
				unsigned long version_line)
{
	const yaml_node_t *v = key ? yaml_in_lookup(&r->in, root, key, NULL) : NULL;

	for (size_t i = 0; !v && key && i < r->f->nkeys; i++)
		if (!strcmp(r->f->keys[i].key, key) && r->f->keys[i].partner)
			v = yaml_in_lookup(&r->in, root, r->f->keys[i].partner, NULL);
	return v ? yaml_in_line(&r->in, v) : version_line;
}

static int read_root(struct reader *r, const yaml_node_t *root)
{
	const char *key = NULL;
	struct error why;
	unsigned long version_line = 0;
	int ret;

	if ((ret = read_head(r, root, &version_line)) < 0 ||
	    (ret = yaml_in_pairs(&r->in, root, "the top level", top_pair, r)) < 0)
		return ret;
	if ((ret = r->f->check(r->p, &key, &why)) < 0)
		return error_at(r->in.err, ret, r->in.name, fault_line(r, root, key, version_line),
				"%s", why.msg);
	return 0;
}

int yaml_flat_read(const struct yaml_flat_format *f, const char *data, size_t len,
		   const char *name, unsigned long line_offset, void *out, struct error *err)
{
	struct reader r = {
		.kind = { .what = f->what, .version_key = f->version_key, .version = f->version,
			  .second_key = f->keys[0].key, .max_bytes = f->max_bytes,
			  .max_depth = f->max_depth },
		.f = f,
	};
	const yaml_node_t *root;
	void *tmp;
	int ret;

	if ((ret = yaml_in_open(&r.in, &r.kind, data, len, name, line_offset, err, &root)) < 0)
		return ret;
	tmp = malloc(f->size);
	if (!tmp) {
		yaml_in_close(&r.in);
		return error_at(err, -ENOMEM, name, line_offset, "out of memory");
	}
	f->defaults(tmp);
	r.p = tmp;
	ret = read_root(&r, root);
	yaml_in_close(&r.in);
	if (ret == 0)
		memcpy(out, tmp, f->size);
	free(tmp);
	return ret;
}
