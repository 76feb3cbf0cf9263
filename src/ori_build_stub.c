/* SPDX-License-Identifier: MIT */
/*
 * THROWAWAY (issue 15): stands in for src/ori_build.c, written in parallel on another
 * branch, so that ori_read links and its tests run. It refuses only what ori_read's tests
 * need refused (an asymmetric middle, a span of 360 degrees or more) and builds nothing.
 * Removed before the branch is merged: src/ori_build.c replaces it.
 */
#include <errno.h>
#include <string.h>

#include "ori.h"

void ori_leaf_init(struct ori_leaf *l)
{
	memset(l, 0, sizeof(*l));
}

void ori_leaf_finish(struct ori_leaf *l)
{
	memset(l, 0, sizeof(*l));
}

int ori_build(const struct ori_design *d, const char *name, struct ori_leaf *l,
	      struct error *err)
{
	double span = d->middle[0] + d->middle[1];

	(void)l;
	if (d->middle[0] != d->middle[1])
		return error_at(err, -EINVAL, name, d->line_middle,
				"the middle part is not symmetric: %g degrees right of the midrib, "
				"%g left", d->middle[0], d->middle[1]);
	for (size_t i = 0; i < d->nsides; i++)
		span += 2 * d->sides[i].angle;
	if (span >= 360)
		return error_at(err, -EINVAL, name,
				d->nsides ? d->sides[d->nsides - 1].line : d->line_middle,
				"the parts span %g degrees round O: 360 or more cannot fold flat", span);
	return 0;
}
