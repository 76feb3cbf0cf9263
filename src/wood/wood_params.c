/* SPDX-License-Identifier: MIT */
/* Growing wood's settings: their defaults and limits (docs/wood-format.md is the contract
 * for both), and the settings file (`edaha-wood: 1`), a flat settings file (yaml_flat.h). */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "buf.h"
#include "wood.h"
#include "yaml_flat.h"

void wood_params_default(struct wood_params *p)
{
	memset(p, 0, sizeof(*p));
	/* a drawn tree is a broadleaf tree unless its file says otherwise */
	p->mode = WOOD_BROADLEAF;
	p->grid = 64;
	p->alpha = WOOD_ALPHA_DEFAULT;
	p->beta = 1.0;
	p->gravity = WOOD_GRAVITY_DEFAULT;
}

static bool in(double v, double lo, double hi)
{
	return v >= lo && v <= hi; /* false for NaN */
}

#define BAD(k, ...) (*key = (k), error_set(err, -EINVAL, __VA_ARGS__))

int wood_params_check(const struct wood_params *p, const char **key, struct error *err)
{
	const char *unused;

	if (!key)
		key = &unused;
	if (p->mode != WOOD_CONIFER && p->mode != WOOD_BROADLEAF)
		return BAD("mode", "mode: unknown");
	if (p->grid != 64 && p->grid != 128)
		return BAD("grid", "grid: %d is neither 64 nor 128", p->grid);
	if (!in(p->alpha, 0, 1e6))
		return BAD("alpha", "alpha: %g is not within 0..1e6", p->alpha);
	if (!in(p->beta, 0.1, 10))
		return BAD("beta", "beta: %g is not within 0.1..10", p->beta);
	if (!in(p->gravity, 0, 1))
		return BAD("gravity", "gravity: %g is not within 0..1", p->gravity);
	if (!in(p->wind[0], -1, 1) || !in(p->wind[1], -1, 1) || !in(p->wind[2], -1, 1))
		return BAD("wind", "wind: [%g, %g, %g] is not within -1..1 in each", p->wind[0],
			   p->wind[1], p->wind[2]);
	if (p->wind[1] != 0.0)
		return BAD("wind", "wind: %g up: the wind blows level (its y is 0)", p->wind[1]);
	return 0;
}

static void key_number(struct buf *b, const char *key, double v)
{
	buf_printf(b, ", %s: ", key);
	(void)buf_print_exact(b, v);
}

int wood_write(const struct wood_params *p, struct buf *out)
{
	size_t len = out->len;

	/* the order of docs/wood-format.md */
	buf_printf(out, "{edaha-wood: %d, mode: %s, grid: %d", WOOD_PARAMS_VERSION,
		   p->mode == WOOD_CONIFER ? "conifer" : "broadleaf", p->grid);
	key_number(out, "alpha", p->alpha);
	key_number(out, "beta", p->beta);
	key_number(out, "gravity", p->gravity);
	buf_printf(out, ", wind: [");
	for (int i = 0; i < 3; i++) {
		buf_printf(out, i ? ", " : "");
		(void)buf_print_exact(out, p->wind[i]);
	}
	buf_printf(out, "]}");
	if (out->failed) {
		out->len = len < out->len ? len : out->len;
		return -ENOMEM;
	}
	return 0;
}

static const char *const modes[] = { "conifer", "broadleaf", NULL }; /* enum wood_mode */
/* a word's index is stored as an int */
_Static_assert(sizeof(enum wood_mode) == sizeof(int), "enum wood_mode is not an int");

static const struct yaml_flat_key keys[] = {
	{ "mode", YAML_FLAT_WORD, offsetof(struct wood_params, mode), NULL, modes },
	{ "grid", YAML_FLAT_WHOLE, offsetof(struct wood_params, grid), NULL, NULL },
	{ "alpha", YAML_FLAT_NUMBER, offsetof(struct wood_params, alpha), NULL, NULL },
	{ "beta", YAML_FLAT_NUMBER, offsetof(struct wood_params, beta), NULL, NULL },
	{ "gravity", YAML_FLAT_NUMBER, offsetof(struct wood_params, gravity), NULL, NULL },
	{ "wind", YAML_FLAT_VEC3, offsetof(struct wood_params, wind), NULL, NULL },
};

static void defaults(void *p)
{
	wood_params_default(p);
}

static int check(const void *p, const char **key, struct error *err)
{
	return wood_params_check(p, key, err);
}

static const struct yaml_flat_format format = {
	.version_key = "edaha-wood",
	.version = WOOD_PARAMS_VERSION,
	.what = "wood settings file",
	.keys = keys,
	.nkeys = sizeof(keys) / sizeof(keys[0]),
	.max_bytes = WOOD_READ_MAX_BYTES,
	.max_depth = 4,
	.size = sizeof(struct wood_params),
	.defaults = defaults,
	.check = check,
};

int wood_read(const char *data, size_t len, const char *name, unsigned long line_offset,
	      struct wood_params *p, struct error *err)
{
	return yaml_flat_read(&format, data, len, name, line_offset, p, err);
}
