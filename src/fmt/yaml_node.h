/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <yaml.h>

#include "error.h"

/*
 * What the YAML files read with libyaml's document loader share (the tree, leaf and
 * settings files through yaml_in.c; the kiosk's configuration, platform/files/config_file.c): a
 * node's kind and text, and a parser's error told at FILE:LINE.
 */

/* A plain scalar's text as a number, strictly: decimal digits with an optional sign,
 * point and exponent (no hex, nan, inf, "1,5", nor leading point without a digit), finite
 * and in range. false for anything else. */
bool yaml_node_number(const char *s, double *out);
/* The user's text for a message: its first 20 characters, ".." after, anything
 * unprintable as '?'. Returns out. */
const char *yaml_node_shown(const char *s, char out[24]);
/*
 * What no edaha file uses and what would cost the loader dearly, refused before it reads
 * the data: aliases (an alias bomb) and nesting deeper than max_depth. `what` names the
 * kind of file ("tree parameter file"). 0, or -EINVAL/-ENOMEM with err "NAME:LINE: ...",
 * offset added to the line.
 */
int yaml_node_prescan(const char *data, size_t len, const char *name, unsigned long offset,
		      int max_depth, const char *what, struct error *err);

/* The value of key k in mapping n of doc (and its key node in *key, may be NULL), or NULL. */
const yaml_node_t *yaml_node_lookup(yaml_document_t *doc, const yaml_node_t *n, const char *k,
				    const yaml_node_t **key);
/* An earlier key of mapping n, before `pair`, with the text k (a duplicate), or NULL. */
const yaml_node_t *yaml_node_earlier_key(yaml_document_t *doc, const yaml_node_t *n,
					 const yaml_node_pair_t *pair, const char *k);

/* "a scalar", "a list", "a mapping": for messages. */
const char *yaml_node_kind(const yaml_node_t *n);
/* A scalar's text; NULL if n is no scalar or holds a NUL byte. */
const char *yaml_node_text(const yaml_node_t *n);
/* A plain (unquoted) scalar. */
bool yaml_node_plain(const yaml_node_t *n);
/*
 * The loader's failure as "NAME:LINE: ..." in err: -ENOMEM, or -EINVAL for bytes that are
 * not YAML text or YAML that does not parse. offset is added to the line (a document that
 * is one line of a larger file); a mark past the data's last line (libyaml's at the end of
 * data without a last line end) is told at the last line.
 */
/*
 * The line (from 1) of a mark in data: libyaml puts the marks of the stream's end, and of
 * an empty value there, on a line after the last when the data ends without a line end;
 * those are told at the last line, which is where the reader sees them.
 */
unsigned long yaml_node_line(const yaml_mark_t *m, const char *data, size_t len);
int yaml_node_parse_error(struct error *err, const char *name, unsigned long offset,
			  const yaml_parser_t *y, const char *data, size_t len);
