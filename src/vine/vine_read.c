/* SPDX-License-Identifier: MIT */
/*
 * Vine parameter files (docs/vine-format.md): a flat settings file (yaml_flat.h) whose
 * keys are these, in the file format's order.
 */
#include <stddef.h>

#include "vine.h"
#include "yaml_flat.h"

static const char *const twinings[] = { "left", "right", NULL }; /* enum vine_twining */
/* a word's index is stored as an int */
_Static_assert(sizeof(enum vine_twining) == sizeof(int), "enum vine_twining is not an int");

/* partner: the other key of a limit the two share (radius below internode / 4, sweep x
 * step_time at most 45), whose line a refusal of this key is told at when the file
 * leaves this one out. */
static const struct yaml_flat_key keys[] = {
	{ "internode", YAML_FLAT_NUMBER, offsetof(struct vine_params, internode), NULL, NULL },
	{ "radius", YAML_FLAT_NUMBER, offsetof(struct vine_params, radius), "internode", NULL },
	{ "step_time", YAML_FLAT_NUMBER, offsetof(struct vine_params, step_time), NULL, NULL },
	{ "angle", YAML_FLAT_NUMBER, offsetof(struct vine_params, angle), NULL, NULL },
	{ "free_nodes", YAML_FLAT_WHOLE, offsetof(struct vine_params, free_nodes), NULL, NULL },
	{ "twining", YAML_FLAT_WORD, offsetof(struct vine_params, twining), NULL, twinings },
	{ "leaves_per_node", YAML_FLAT_WHOLE, offsetof(struct vine_params, leaves_per_node), NULL,
	  NULL },
	{ "cotyledons", YAML_FLAT_WHOLE, offsetof(struct vine_params, cotyledons), NULL, NULL },
	{ "leaf_size", YAML_FLAT_NUMBER, offsetof(struct vine_params, leaf_size), NULL, NULL },
	{ "points_per_internode", YAML_FLAT_WHOLE,
	  offsetof(struct vine_params, points_per_internode), NULL, NULL },
	{ "ring_sides", YAML_FLAT_WHOLE, offsetof(struct vine_params, ring_sides), NULL, NULL },
	{ "sweep", YAML_FLAT_NUMBER, offsetof(struct vine_params, sweep), "step_time", NULL },
	{ "internodes", YAML_FLAT_WHOLE, offsetof(struct vine_params, internodes), NULL, NULL },
	{ "seed", YAML_FLAT_SEED, offsetof(struct vine_params, seed), NULL, NULL },
};

static void defaults(void *p)
{
	vine_params_default(p);
}

static int check(const void *p, const char **key, struct error *err)
{
	return vine_params_check(p, key, err);
}

static const struct yaml_flat_format format = {
	.version_key = "edaha-vine",
	.version = VINE_PARAMS_VERSION,
	.what = "vine parameter file",
	.keys = keys,
	.nkeys = sizeof(keys) / sizeof(keys[0]),
	.max_bytes = VINE_READ_MAX_BYTES,
	.max_depth = VINE_READ_MAX_DEPTH,
	.size = sizeof(struct vine_params),
	.defaults = defaults,
	.check = check,
};

int vine_read(const char *data, size_t len, const char *name, struct vine_params *p,
	      struct error *err)
{
	return vine_read_at(data, len, name, 0, p, err);
}

int vine_read_at(const char *data, size_t len, const char *name, unsigned long line_offset,
		 struct vine_params *p, struct error *err)
{
	return yaml_flat_read(&format, data, len, name, line_offset, p, err);
}
