/* SPDX-License-Identifier: MIT */
/* Origami leaf designs that cannot fold flat, refused at the design file's line
 * (docs/origami-leaves.md, "The crease pattern"). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ori_private.h"

double ori_sides_angle(const struct ori_design *d, size_t upto)
{
	double a = 0;

	for (size_t j = 0; j < upto; j++)
		a += d->sides[j].angle;
	return a;
}

/* Proper crossing of segments pq and rs (sharing no end). */
static bool segments_cross(const double p[2], const double q[2], const double r[2],
			   const double s[2])
{
	double pq[2] = { q[0] - p[0], q[1] - p[1] }, rs[2] = { s[0] - r[0], s[1] - r[1] };
	double pr[2] = { r[0] - p[0], r[1] - p[1] }, ps[2] = { s[0] - p[0], s[1] - p[1] };
	double rp[2] = { p[0] - r[0], p[1] - r[1] }, rq[2] = { q[0] - r[0], q[1] - r[1] };
	double d1 = cross2(pq, pr), d2 = cross2(pq, ps), d3 = cross2(rs, rp), d4 = cross2(rs, rq);

	return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
	       ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* Where the design says part p (counted right to left): its line and name. */
static unsigned long part_where(const struct ori_design *d, int p, char what[64])
{
	size_t n = d->nsides;

	if (p < 0 || (size_t)p == n || (size_t)p > 2 * n) {
		snprintf(what, 64, "middle");
		return d->line_middle ? d->line_middle : d->line;
	}
	if ((size_t)p < n) {
		snprintf(what, 64, "sides: part %zu", n - (size_t)p);
		return d->sides[n - 1 - (size_t)p].line ? d->sides[n - 1 - (size_t)p].line : d->line;
	}
	snprintf(what, 64, "sides: part %zu (on the left)", (size_t)p - n);
	return d->sides[(size_t)p - n - 1].line ? d->sides[(size_t)p - n - 1].line : d->line;
}

/* Crossing creases, overlapping lobes, faces that are not convex: refused. */
int ori_check_pattern(struct ori_builder *b)
{
	const struct ori_design *d = b->d;
	unsigned long line = d->line_middle ? d->line_middle : d->line;
	char what[64];

	for (size_t i = 0; i < b->nc; i++)
		for (size_t j = i + 1; j < b->nc; j++) {
			const struct ori_crease *x = &b->c[i], *y = &b->c[j];

			if (x->a == y->a || x->a == y->b || x->b == y->a || x->b == y->b)
				continue;
			if (segments_cross(b->v[x->a], b->v[x->b], b->v[y->a], b->v[y->b])) {
				line = part_where(d, b->part_of[y->b], what);
				return error_at(b->err, -EINVAL, b->name, line,
						"%s: creases cross: its forks' or nodes' angles send a vein "
						"or a mountain over another", what);
			}
		}
	for (size_t i = 0; i < b->nmargin; i++) {
		const double *p = b->v[b->margin[i]], *q = b->v[b->margin[(i + 1) % b->nmargin]];

		for (size_t j = i + 2; j < b->nmargin; j++) {
			if ((j + 1) % b->nmargin == i)
				continue;
			if (segments_cross(p, q, b->v[b->margin[j]],
					   b->v[b->margin[(j + 1) % b->nmargin]]))
				return error_at(b->err, -EINVAL, b->name, line,
						"the lobes overlap when the leaf lies flat: "
						"narrow the parts or lengthen theta0");
		}
	}
	for (size_t f = 0; f < b->nf; f++) {
		size_t n = b->flen[f], s = b->fstart[f];
		double area = 0;

		for (size_t k = 0; k < n; k++) {
			const double *p = b->v[b->fidx[s + k]], *q = b->v[b->fidx[s + (k + 1) % n]];

			area += cross2(p, q);
		}
		if (area < 0) /* the walk goes clockwise round each face: turn it */
			for (size_t k = 0; k < n / 2; k++) {
				int t = b->fidx[s + k];

				b->fidx[s + k] = b->fidx[s + n - 1 - k];
				b->fidx[s + n - 1 - k] = t;
			}
		if (fabs(area) < 1e-12 * d->size * d->size)
			return error_at(b->err, -EINVAL, b->name, line,
					"a face of the pattern has no area: creases meet the cut "
					"at one point");
		for (size_t k = 0; k < n; k++) {
			const double *p = b->v[b->fidx[s + k]], *q = b->v[b->fidx[s + (k + 1) % n]];
			const double *r = b->v[b->fidx[s + (k + 2) % n]];
			double pq[2] = { q[0] - p[0], q[1] - p[1] }, qr[2] = { r[0] - q[0], r[1] - q[1] };

			if (cross2(pq, qr) < -1e-9 * d->size * d->size) {
				line = part_where(d, b->part_of[b->fidx[s + (k + 1) % n]], what);
				return error_at(b->err, -EINVAL, b->name, line,
						"%s: a face of the pattern is not convex: creases "
						"cross or run out of their part", what);
			}
		}
	}
	return 0;
}

/* A vein's nodes (the midrib's or a side part's, named where, told at line if a node has
 * none): symmetric, the extra mountain between the vein and the side vein, outwards. */
static int check_nodes(const struct ori_node *nodes, size_t nn, const char *where,
		       unsigned long line, const char *name, struct error *err)
{
	if (nn > ORI_MAX_NODES)
		return error_at(err, -EINVAL, name, line, "%s: %zu nodes, over %d", where, nn,
				ORI_MAX_NODES);
	for (size_t i = 0; i < nn; i++) {
		const struct ori_node *n = &nodes[i];
		unsigned long at = n->line ? n->line : line;

		if (n->phi[0] != n->phi[1] || n->psi[0] != n->psi[1])
			return error_at(err, -EINVAL, name, at,
					"%s: node %zu is not symmetric: its right and left angles "
					"differ (the pattern mirrors about %s)", where, i + 1,
					strcmp(where, "middle.nodes") ? "each vein" : "the midrib");
		if (!(n->psi[0] > 0 && n->psi[0] < n->phi[0] && n->phi[0] < 90))
			return error_at(err, -EINVAL, name, at,
					"%s: node %zu: the extra mountain must lie between the %s "
					"and the side vein, 0 < psi < phi < 90", where, i + 1,
					strcmp(where, "middle.nodes") ? "vein" : "midrib");
		if (n->at <= (i ? nodes[i - 1].at : 0.0) || n->at >= 1)
			return error_at(err, -EINVAL, name, at,
					"%s: node %zu: `at` must grow from O and stay below 1", where,
					i + 1);
	}
	return 0;
}

int ori_check_design(const struct ori_design *d, const char *name, struct error *err)
{
	int ret;
	double span = d->middle[0] + d->middle[1] + 2.0 * ori_sides_angle(d, d->nsides);
	unsigned long line = d->line_middle ? d->line_middle : d->line;

	if (d->middle[0] != d->middle[1])
		return error_at(err, -EINVAL, name, line,
				"the middle part is not symmetric: %.4g degrees right of the midrib, "
				"%.4g left (the pattern mirrors about the midrib)",
				d->middle[0], d->middle[1]);
	if ((ret = check_nodes(d->nodes, d->nnodes, "middle.nodes", line, name, err)) < 0)
		return ret;
	for (size_t j = 0; j < d->nsides; j++) {
		const struct ori_side *p = &d->sides[j];
		char where[40];

		snprintf(where, sizeof(where), "sides: part %zu", j + 1);
		if (p->nnodes > 0 && p->forks > 0)
			return error_at(err, -EINVAL, name, p->line ? p->line : d->line,
					"%s: a vein either forks or has nodes, not both", where);
		if ((ret = check_nodes(p->nodes, p->nnodes, where, p->line ? p->line : d->line,
				       name, err)) < 0)
			return ret;
	}
	if (span >= 360.0)
		return error_at(err, -EINVAL, name, line,
				"the parts span %.4g degrees round O: 360 or more cannot fold flat "
				"(the petiole's notch must stay open)", span);
	if (d->fold == ORI_FOLD_HALF && (d->middle[0] < 90.0 || d->nsides || d->nnodes))
		return error_at(err, -EINVAL, name, line,
				"a half fold is the midrib alone, 180 degrees at O: its curve "
				"leaves O square to the midrib");
	return 0;
}

