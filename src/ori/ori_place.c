/* SPDX-License-Identifier: MIT */
/* An origami leaf in the frame of the outline it replaces: see ori_place.h. */
#include "ori_place.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "tree.h"

int ori_place(const struct ori_kind *k, const struct vec3 *outline, size_t n,
	      struct vec3 attach, double xf[12])
{
	size_t base = 0, far = 0;
	double best = INFINITY, len = -1.0, s;
	struct vec3 nrm = vec3(0, 0, 0), x, y, z;

	if (n < 3)
		return -EINVAL;
	for (size_t i = 0; i < n; i++) {
		double d = vec3_dist(outline[i], attach);

		if (!isfinite(d))
			return -EINVAL;
		if (d < best) {
			best = d;
			base = i;
		}
	}
	for (size_t i = 0; i < n; i++) {
		double d = vec3_dist(outline[i], outline[base]);

		if (d > len) {
			len = d;
			far = i;
		}
	}
	/* Newell's normal: the polygon's area vector, whatever its shape */
	for (size_t i = 0; i < n; i++) {
		struct vec3 p = outline[i], q = outline[(i + 1) % n];

		nrm.x += (p.y - q.y) * (p.z + q.z);
		nrm.y += (p.z - q.z) * (p.x + q.x);
		nrm.z += (p.x - q.x) * (p.y + q.y);
	}
	if (!(len > 0))
		return -EINVAL;
	y = vec3_scale(vec3_sub(outline[far], outline[base]), 1.0 / len);
	z = vec3_sub(nrm, vec3_scale(y, vec3_dot(nrm, y)));
	if (!(vec3_len(z) > 1e-12 * vec3_len(nrm)) || !(vec3_len(nrm) > 0))
		return -EINVAL;
	z = vec3_scale(z, 1.0 / vec3_len(z));
	x = vec3_cross(y, z);
	s = len / k->leaf.size;
	/* columns x, y, z scaled: the design's +x, +y, +z */
	xf[0] = s * x.x, xf[1] = s * y.x, xf[2] = s * z.x, xf[3] = outline[base].x;
	xf[4] = s * x.y, xf[5] = s * y.y, xf[6] = s * z.y, xf[7] = outline[base].y;
	xf[8] = s * x.z, xf[9] = s * y.z, xf[10] = s * z.z, xf[11] = outline[base].z;
	for (int i = 0; i < 12; i++)
		if (!isfinite(xf[i]))
			return -EINVAL;
	return 0;
}

int ori_place_outline(int kind, const struct vec3 *outline, size_t n, struct vec3 attach,
		      struct vec3 **out, size_t *nout)
{
	const struct ori_kind *k = ori_kind_get(kind);
	double xf[12];
	int ret;

	*out = NULL;
	*nout = 0;
	if (!k)
		return kind >= 0 && kind < ORI_KIND_COUNT ? -ENOMEM : -EINVAL;
	if ((ret = ori_place(k, outline, n, attach, xf)) < 0)
		return ret;
	*out = malloc(k->leaf.nmargin * sizeof(**out));
	if (!*out)
		return -ENOMEM;
	ori_kind_outline(k, xf, *out);
	*nout = k->leaf.nmargin;
	return 0;
}

int ori_place_leaf(struct tree *t, size_t i, int kind)
{
	struct leaf *l = &t->leaves[i];
	struct vec3 attach, *pts, *old;
	size_t n, nold;
	int ret;

	if (kind < 0 || l->kind == kind)
		return 0;
	attach = tree_frame_at(&t->branches[l->branch], l->branch_t).origin;
	ret = ori_place_outline(kind, l->points, l->npoints, attach, &pts, &n);
	if (ret == -EINVAL)
		return 0;
	if (ret < 0)
		return ret;
	old = l->points;
	nold = l->npoints;
	l->points = pts;
	l->npoints = n;
	if ((ret = tree_leaf_attach(t, i)) < 0) {
		l->points = old;
		l->npoints = nold;
		free(pts);
		return ret;
	}
	free(old);
	l->kind = kind;
	return 0;
}
