/* SPDX-License-Identifier: MIT */
#include "doc.h"
#include "gen.h"
#include "sketch.h"
#include "tree.h"
#include "vine.h"
#include "wood.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void doc_init(struct doc *d, uint64_t seed)
{
	memset(d, 0, sizeof(*d));
	d->seed = seed;
}

void doc_op_finish(struct doc_op *op)
{
	free(op->points);
	free(op->params);
	free(op->vine);
	free(op->wood);
	if (op->import)
		tree_finish(op->import);
	free(op->import);
	op->points = NULL;
	op->npoints = 0;
	op->params = NULL;
	op->vine = NULL;
	op->wood = NULL;
	op->import = NULL;
}

int doc_op_copy(struct doc_op *dst, const struct doc_op *src)
{
	*dst = *src;
	dst->points = NULL;
	dst->params = NULL;
	dst->vine = NULL;
	dst->wood = NULL;
	dst->import = NULL;
	if (src->npoints) {
		dst->points = malloc(src->npoints * sizeof(*dst->points));
		if (!dst->points)
			goto fail;
		memcpy(dst->points, src->points, src->npoints * sizeof(*dst->points));
	}
	if (src->params) {
		dst->params = malloc(sizeof(*dst->params));
		if (!dst->params)
			goto fail;
		memcpy(dst->params, src->params, sizeof(*dst->params));
	}
	if (src->vine) {
		dst->vine = malloc(sizeof(*dst->vine));
		if (!dst->vine)
			goto fail;
		*dst->vine = *src->vine;
	}
	if (src->wood) {
		dst->wood = malloc(sizeof(*dst->wood));
		if (!dst->wood)
			goto fail;
		*dst->wood = *src->wood;
	}
	if (src->import) {
		dst->import = malloc(sizeof(*dst->import));
		if (!dst->import)
			goto fail;
		tree_init(dst->import);
		if (tree_copy(dst->import, src->import) < 0)
			goto fail;
	}
	return 0;
fail:
	doc_op_finish(dst);
	return -ENOMEM;
}

void doc_finish(struct doc *d)
{
	for (size_t i = 0; i < d->nops; i++)
		doc_op_finish(&d->ops[i]);
	free(d->ops);
	doc_init(d, d->seed);
}

size_t doc_op_weight(const struct doc_op *op)
{
	size_t n = op->npoints;

	/* a generated tree costs what it makes: a hostile drawing of thousands of trees must
	 * not keep --load busy for an hour */
	if (op->params)
		n += gen_count_branches(op->params) + gen_count_leaves(op->params);
	if (op->vine)
		n += (size_t)op->vine->internodes * (size_t)op->vine->points_per_internode;
	if (op->kind == DOC_OP_GROW)
		n += DOC_GROW_WEIGHT;
	for (size_t i = 0; op->import && i < op->import->nbranches; i++)
		n += op->import->branches[i].npoints;
	return n;
}

size_t doc_total_points(const struct doc *d)
{
	size_t n = 0;

	for (size_t i = 0; i < d->nops; i++)
		n += doc_op_weight(&d->ops[i]);
	return n;
}

int doc_push(struct doc *d, struct doc_op *op)
{
	size_t kept = 0;

	for (size_t i = 0; i < d->cursor; i++)
		kept += doc_op_weight(&d->ops[i]);
	if (d->cursor >= DOC_MAX_OPS || op->npoints > DOC_MAX_STROKE_POINTS ||
	    kept + doc_op_weight(op) > DOC_MAX_POINTS)
		return -ENOSPC;
	/* A new edit after undo forgets the undone ones, as every editor does. */
	for (size_t i = d->cursor; i < d->nops; i++)
		doc_op_finish(&d->ops[i]);
	d->nops = d->cursor;

	if (d->nops == d->cap) {
		size_t cap = d->cap ? d->cap * 2 : 32;
		struct doc_op *ops = realloc(d->ops, cap * sizeof(*ops));

		if (!ops)
			return -ENOMEM;
		d->ops = ops;
		d->cap = cap;
	}
	d->ops[d->nops++] = *op;
	d->cursor = d->nops;
	op->points = NULL;
	op->npoints = 0;
	op->params = NULL;
	op->vine = NULL;
	op->wood = NULL;
	op->import = NULL;
	return 0;
}

bool doc_can_undo(const struct doc *d)
{
	return d->cursor > 0;
}

bool doc_can_redo(const struct doc *d)
{
	return d->cursor < d->nops;
}

bool doc_undo(struct doc *d)
{
	if (!doc_can_undo(d))
		return false;
	d->cursor--;
	return true;
}

bool doc_redo(struct doc *d)
{
	if (!doc_can_redo(d))
		return false;
	d->cursor++;
	return true;
}

int doc_apply_stroke(struct tree *t, const struct doc_op *op)
{
	struct sketch_stroke st = {
		.npoints = op->npoints,
		.tool = op->tool,
		.camera = op->camera,
		.time_us = op->time_us,
	};
	struct vec3 *p = NULL;
	int ret;

	if (op->kind != DOC_OP_STROKE || op->npoints == 0)
		return SKETCH_GREW;
	/* a pen's stroke of one point is a tap (nothing to draw): no copy needed */
	if (op->tool == EVENT_TOOL_ERASER || op->npoints >= 2) {
		p = malloc(op->npoints * sizeof(*p));
		if (!p)
			return -ENOMEM;
		for (size_t i = 0; i < op->npoints; i++)
			p[i] = vec3(op->points[i].x, op->points[i].y, 0.0);
	}
	st.points = p;
	st.end_us = op->time_us + op->points[op->npoints - 1].dt_us;
	ret = sketch_stroke(t, &st);
	free(p);
	return ret;
}
