/* SPDX-License-Identifier: MIT */
/*
 * Origami leaves unfolding as a tree grows in (issue 26, docs/living-trees.md): a leaf
 * the front has passed is drawn at the keyframe of ori_unfold_frames its pull has reached
 * (live_grow_unfold_bounds), so the leaves at one keyframe must be one range of instances.
 * The instances of each origami shape are sorted by their anchors' path length d, once,
 * when the living data is bound while the tree grows (render_live.c); the matrices and
 * tints go up again in that order. A frame then finds each keyframe's range with a binary
 * search (render_instanced.c): its cost does not grow with the number of leaves.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "leaf_tint.h"
#include "render_private.h"

struct keyed {
	float d;
	size_t i;
};

static int by_d(const void *a, const void *b)
{
	const struct keyed *x = a, *y = b;

	/* ties by instance, so the order is the same on every machine */
	if (x->d != y->d)
		return x->d < y->d ? -1 : 1;
	return x->i < y->i ? -1 : x->i > y->i;
}

static int reserve(struct render_instanced *in, size_t n)
{
	size_t *o;
	float *d;

	if (n <= in->grow_cap)
		return 0;
	if (n > SIZE_MAX / sizeof(*o))
		return -ENOMEM;
	o = realloc(in->grow_order, n * sizeof(*o));
	if (!o)
		return -ENOMEM;
	in->grow_order = o;
	d = realloc(in->grow_d, n * sizeof(*d));
	if (!d)
		return -ENOMEM;
	in->grow_d = d;
	in->grow_cap = n;
	return 0;
}

/* The order: shape by shape as uploaded, an origami shape's instances by d. */
static int order(struct render_instanced *in, const struct live_vertex *v, size_t n)
{
	struct keyed *k = NULL;
	size_t most = 0;

	for (size_t s = 0; s < in->nshapes; s++)
		most = in->has_frames[s] && in->count[s] > most ? in->count[s] : most;
	if (most && !(k = malloc(most * sizeof(*k))))
		return -ENOMEM;
	for (size_t i = 0; i < n; i++) {
		in->grow_order[i] = i;
		in->grow_d[i] = v[i].d;
	}
	for (size_t s = 0; s < in->nshapes; s++) {
		size_t first = in->first[s], count = in->count[s];

		if (!in->has_frames[s] || first > n || count > n - first)
			continue;
		for (size_t j = 0; j < count; j++)
			k[j] = (struct keyed){ v[first + j].d, first + j };
		qsort(k, count, sizeof(*k), by_d);
		for (size_t j = 0; j < count; j++) {
			in->grow_order[first + j] = k[j].i;
			in->grow_d[first + j] = k[j].d;
		}
	}
	free(k);
	return 0;
}

/* n rows of `width` floats from `from`, in the order, into buffer *name. */
static int upload_rows(struct render *r, GLuint *name, const float *from, size_t n, size_t width)
{
	const struct render_instanced *in = &r->inst;
	float *rows;

	if (n > SIZE_MAX / sizeof(float) / width || n * width * sizeof(float) > INT32_MAX)
		return -ENOMEM;
	rows = malloc(n * width * sizeof(float) + 1);
	if (!rows)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++)
		memcpy(&rows[i * width], &from[in->grow_order[i] * width], width * sizeof(float));
	if (!*name)
		glGenBuffers(1, name);
	glBindBuffer(GL_ARRAY_BUFFER, *name);
	glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * width * sizeof(float)), rows, GL_STATIC_DRAW);
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	r->upload_bytes += n * width * sizeof(float);
	free(rows);
	return 0;
}

int render_instanced_grow_order(struct render *r, const struct tree *t,
				const struct live_vertex *v, bool tinted)
{
	struct render_instanced *in = &r->inst;
	const struct leaf_instances *li = &in->li;
	size_t n = li->ninstanced;
	float *rgb;
	int ret;

	in->grow_ok = false;
	ret = reserve(in, n + 1);
	if (ret == 0)
		ret = order(in, v, n);
	if (ret == 0)
		ret = upload_rows(r, &in->grow_matrices, li->matrices, n, 12);
	if (ret == 0 && tinted) {
		rgb = n <= SIZE_MAX / 3 - 1 ? render_tint_scratch(r, 3 * n + 3) : NULL;
		if (!rgb)
			return -ENOMEM;
		leaf_tint_instances(t, li, rgb);
		ret = upload_rows(r, &in->grow_tints, rgb, n, 3);
	}
	in->grow_ok = ret == 0;
	return ret;
}

void render_instanced_grow_drop(struct render *r)
{
	struct render_instanced *in = &r->inst;

	glDeleteBuffers(1, &in->grow_matrices);
	glDeleteBuffers(1, &in->grow_tints);
	in->grow_matrices = in->grow_tints = 0;
	in->grow_ok = false;
}
