/* SPDX-License-Identifier: MIT */
/* Tree parameters as one line of YAML in flow style: how a drawing stores a generated
 * tree (docs/document-format.md), read back by gen_read(). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "gen.h"

static void number(struct buf *b, double v)
{
	(void)buf_print_exact(b, v);
}

static void point(struct buf *b, struct vec3 v)
{
	buf_printf(b, "[");
	number(b, v.x);
	buf_printf(b, ", ");
	number(b, v.y);
	buf_printf(b, ", ");
	number(b, v.z);
	buf_printf(b, "]");
}

static void key_number(struct buf *b, const char *key, double v)
{
	buf_printf(b, ", %s: ", key);
	number(b, v);
}

static void branching(struct buf *b, const struct gen_params *p)
{
	buf_printf(b, ", levels: %d, children: %d", p->levels, p->children);
}

static void angles(struct buf *b, const struct gen_params *p)
{
	buf_printf(b, ", angle: {min: ");
	number(b, p->angle_min);
	buf_printf(b, ", max: ");
	number(b, p->angle_max);
	buf_printf(b, ", randomness: ");
	number(b, p->randomness);
	buf_printf(b, "}");
}

static void ratios(struct buf *b, const struct gen_params *p)
{
	buf_printf(b, ", ratios: [");
	for (int i = 0; i < p->children; i++) {
		if (i)
			buf_printf(b, ", ");
		number(b, p->ratios[i]);
	}
	buf_printf(b, "]");
	key_number(b, "spread", p->spread);
	key_number(b, "twist", p->twist);
}

static void clip(struct buf *b, const struct gen_params *p)
{
	key_number(b, "trunk_height", p->trunk_height);
	buf_printf(b, ", clip: {shape: %s, center: ", gen_clip_name(p->clip));
	point(b, p->clip_center);
	switch (p->clip) {
	case GEN_CLIP_SPHERE:
		key_number(b, "radius", p->clip_radius);
		break;
	case GEN_CLIP_BOX:
		buf_printf(b, ", size: ");
		point(b, p->clip_size);
		break;
	case GEN_CLIP_CONE:
		key_number(b, "radius", p->clip_radius);
		key_number(b, "height", p->clip_height);
		break;
	case GEN_CLIP_COUNT:
		break;
	}
	buf_printf(b, "}");
}

int gen_write(const struct gen_params *p, struct buf *out)
{
	size_t len = out->len;

	/* the order of docs/tree-params.md */
	buf_printf(out, "{edaha-tree: %d, type: %s, precision: %d, trunk: {start: ", GEN_PARAMS_VERSION,
		   gen_type_name(p->type), p->precision);
	point(out, p->trunk_start);
	if (p->type != GEN_SHRUB) {
		buf_printf(out, ", end: ");
		point(out, p->trunk_end);
	}
	buf_printf(out, "}");
	if (p->type != GEN_PALM)
		branching(out, p);
	angles(out, p);
	if (p->type != GEN_PALM)
		ratios(out, p);
	key_number(out, "thickness", p->thickness);
	key_number(out, "thickness_ratio", p->thickness_ratio);
	buf_printf(out, ", leaves: {amount: %d, size: ", p->leaf_amount);
	number(out, p->leaf_size);
	buf_printf(out, ", type: %s}, season: %s", gen_leaf_name(p->leaf_type), season_name(p->season));
	if (p->type == GEN_SHRUB)
		clip(out, p);
	if (p->type == GEN_PALM) {
		key_number(out, "height", p->height);
		buf_printf(out, ", fronds: %d", p->fronds);
		key_number(out, "frond_length", p->frond_length);
		key_number(out, "droop", p->droop);
	}
	buf_printf(out, "}");
	if (out->failed) {
		out->len = len < out->len ? len : out->len;
		return -ENOMEM;
	}
	return 0;
}
