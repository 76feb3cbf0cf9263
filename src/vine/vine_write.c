/* SPDX-License-Identifier: MIT */
/* A vine's parameters as one line of YAML in flow style: how a drawing stores a planted
 * vine (docs/document-format.md), read back by vine_read_at(). */
#include <errno.h>
#include <inttypes.h>

#include "buf.h"
#include "vine.h"

static void key_number(struct buf *b, const char *key, double v)
{
	buf_printf(b, ", %s: ", key);
	(void)buf_print_exact(b, v);
}

int vine_write(const struct vine_params *p, struct buf *out)
{
	size_t len = out->len;

	/* the order of docs/vine-format.md */
	buf_printf(out, "{edaha-vine: %d", VINE_PARAMS_VERSION);
	key_number(out, "internode", p->internode);
	key_number(out, "radius", p->radius);
	key_number(out, "step_time", p->step_time);
	key_number(out, "angle", p->angle);
	buf_printf(out, ", free_nodes: %d, twining: %s, leaves_per_node: %d, cotyledons: %d",
		   p->free_nodes, p->twining == VINE_RIGHT ? "right" : "left", p->leaves_per_node,
		   p->cotyledons);
	key_number(out, "leaf_size", p->leaf_size);
	buf_printf(out, ", points_per_internode: %d, ring_sides: %d", p->points_per_internode,
		   p->ring_sides);
	key_number(out, "sweep", p->sweep);
	buf_printf(out, ", internodes: %d, seed: %" PRIu64 "}", p->internodes, p->seed);
	if (out->failed) {
		out->len = len < out->len ? len : out->len;
		return -ENOMEM;
	}
	return 0;
}
