/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>
#include <yaml.h>

#include "error.h"

/*
 * One YAML file being read by edaha's document readers (tree parameters, gen_read.c; leaf
 * designs, ori_read.c; flat settings files, yaml_flat.c): its one document loaded from
 * memory by libyaml, and what every reader does alike with it: the refusals before its
 * keys, the typed values, the walk over a mapping's keys. Every refusal is -EINVAL with
 * "NAME:LINE: what is wrong" in err, at the line of the node at fault.
 */

/* What a kind of file is called and how it starts, for the refusals before its keys. */
struct yaml_in_kind {
	const char *what;        /* "tree parameter file" */
	const char *version_key; /* "edaha-tree" */
	int version;
	const char *second_key;  /* the key after it in the example of a mapping ("type") */
	size_t max_bytes;        /* anything larger is not one */
	int max_depth;           /* nesting deeper is refused before the loader sees it */
};

struct yaml_in {
	const char *name;     /* the file's name in messages */
	unsigned long offset; /* lines before the text (a line of a drawing) */
	struct error *err;
	const char *data;     /* the text, for its lines */
	size_t len;
	yaml_parser_t parser;
	yaml_document_t doc;
};

/*
 * Loads data (the text of name, after offset lines of it) as a file of kind k. Refuses a
 * text over k->max_bytes, aliases and deep nesting (yaml_node_prescan), text that is not
 * YAML, an empty document, a top that is no mapping and a second document. 0 with *root
 * the top mapping (yaml_in_close frees it all), or a negative errno with err set and
 * nothing left to close.
 */
int yaml_in_open(struct yaml_in *in, const struct yaml_in_kind *k, const char *data, size_t len,
		 const char *name, unsigned long offset, struct error *err,
		 const yaml_node_t **root);
void yaml_in_close(struct yaml_in *in);

/* The line of n in the file (0 for no node). */
unsigned long yaml_in_line(const struct yaml_in *in, const yaml_node_t *n);
/* Refuses at n's line: always -EINVAL. */
int yaml_in_fail(struct yaml_in *in, const yaml_node_t *n, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* What a value that is not the plain scalar asked for is, in a message. */
const char *yaml_in_got(const yaml_node_t *n);

/* A decimal number, strictly (yaml_node_number), into *v. `what` names it in messages. */
int yaml_in_number(struct yaml_in *in, const yaml_node_t *n, const char *what, double *v);
/* A whole number within +-1e6. */
int yaml_in_int(struct yaml_in *in, const yaml_node_t *n, const char *what, int *v);
/* A plain scalar's text, in the document (valid until yaml_in_close). */
int yaml_in_word(struct yaml_in *in, const yaml_node_t *n, const char *what, const char **w);
/* Any 64-bit seed, exactly: decimal digits read as an integer (a double rounds above 2^53). */
int yaml_in_seed(struct yaml_in *in, const yaml_node_t *n, const char *what, uint64_t *v);

/*
 * The version key of kind k, first in the top mapping root (it says how to read the
 * rest), holding k->version: 0 with its key node in *key, or a refusal (missing, not a
 * whole number, another version, not first).
 */
int yaml_in_version_first(struct yaml_in *in, const struct yaml_in_kind *k,
			  const yaml_node_t *root, const yaml_node_t **key);

/* The value of key k in mapping n (and its key node in *key, may be NULL), or NULL. */
const yaml_node_t *yaml_in_lookup(struct yaml_in *in, const yaml_node_t *n, const char *k,
				  const yaml_node_t **key);
/* Refuses an unknown key k, "in WHERE" when where is not NULL. */
int yaml_in_unknown(struct yaml_in *in, const yaml_node_t *key, const char *k, const char *where);

/* Called with each key of a mapping: 0 to go on, or a negative errno to stop with. */
typedef int (*yaml_in_pair_fn)(void *ctx, const yaml_node_t *key, const char *k,
			       const yaml_node_t *value);
/* Calls fn on each pair of mapping n in order, each key plain and given once; `what`
 * names the mapping in messages. Stops at fn's first failure and returns it. */
int yaml_in_pairs(struct yaml_in *in, const yaml_node_t *n, const char *what, yaml_in_pair_fn fn,
		  void *ctx);
