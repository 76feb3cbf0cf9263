/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "error.h"

/*
 * Settings files that are one flat YAML mapping of known keys, its version key first
 * (`edaha-vine: 1`, `edaha-wood: 1`): read with libyaml's document loader from memory
 * into a struct, every key optional (the struct's defaults stand), every refusal told at
 * its line. A format is a table of its keys; vine_read.c and wood_params.c are two.
 */

enum yaml_flat_kind {
	YAML_FLAT_NUMBER, /* double: a decimal number, finite */
	YAML_FLAT_WHOLE,  /* int: a whole number within +-1e6 */
	YAML_FLAT_WORD,   /* int: the index of the word among `words` */
	YAML_FLAT_SEED,   /* uint64_t: any 64-bit seed, exactly */
	YAML_FLAT_VEC3,   /* double[3]: a flow or block sequence of three numbers */
};

struct yaml_flat_key {
	const char *key;
	enum yaml_flat_kind kind;
	size_t at; /* the field's offset in the struct */
	/* The other key of a limit the two share, whose line a refusal of this key is told at
	 * when the file leaves this one out; or NULL. */
	const char *partner;
	const char *const *words; /* YAML_FLAT_WORD: the choices, NULL-terminated */
};

struct yaml_flat_format {
	const char *version_key; /* "edaha-vine" */
	int version;
	const char *what;        /* "vine parameter file": "not a vine parameter file" */
	const struct yaml_flat_key *keys;
	size_t nkeys;
	size_t max_bytes;
	int max_depth;
	size_t size; /* sizeof the struct */
	void (*defaults)(void *p);
	/* The limits, once every key is read: 0, or -EINVAL with err and *key (the key told). */
	int (*check)(const void *p, const char **key, struct error *err);
};

/* Reads data (the text of name, after line_offset lines of it) into out: 0, or -EINVAL /
 * -ENOMEM with err "NAME:LINE: what is wrong" (*out unchanged). */
int yaml_flat_read(const struct yaml_flat_format *f, const char *data, size_t len,
		   const char *name, unsigned long line_offset, void *out, struct error *err);
