/* SPDX-License-Identifier: MIT */
/* The vines a tree carries: how they get there, and the hooks through which the tree
 * (core, a floor below: src/FLOORS) frees, copies and counts them. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "tree.h"
#include "vine.h"

static void tree_vines_clear(struct tree *t)
{
	for (size_t i = 0; i < t->nvines; i++)
		vine_finish(&t->vines[i]);
}

static int tree_vines_copy(struct tree *dst, const struct tree *src)
{
	if (src->nvines > dst->cap_vines) {
		struct vine *v = realloc(dst->vines, src->nvines * sizeof(*v));

		if (!v)
			return -ENOMEM;
		dst->vines = v;
		dst->cap_vines = src->nvines;
	}
	for (size_t i = 0; i < src->nvines; i++) {
		if (vine_copy(&dst->vines[i], &src->vines[i]) < 0)
			return -ENOMEM;
		dst->nvines++;
	}
	return 0;
}

static size_t tree_vines_bytes(const struct tree *t)
{
	size_t n = t->cap_vines * sizeof(*t->vines);

	for (size_t i = 0; i < t->nvines; i++)
		n += vine_bytes(&t->vines[i]);
	return n;
}

static void tree_vines_each_point(struct tree *t,
				  void (*f)(struct vec3 *p, double radius, void *ctx), void *ctx)
{
	for (size_t i = 0; i < t->nvines; i++) {
		struct vine *v = &t->vines[i];

		/* the root too, where the main axis starts */
		f(&v->plant, v->p.radius, ctx);
		for (size_t j = 0; j < v->nshoots; j++) {
			struct vine_shoot *sh = &v->shoots[j];

			for (size_t k = 0; k < sh->n; k++)
				f(&sh->axis[k], v->p.radius, ctx);
		}
	}
}

const struct tree_vine_ops vine_tree_ops = {
	.clear = tree_vines_clear,
	.copy = tree_vines_copy,
	.bytes = tree_vines_bytes,
	.each_point = tree_vines_each_point,
};

int vine_attach(struct tree *t, struct vine *v)
{
	size_t ncap;
	struct vine *p;

	if (t->nvines >= TREE_MAX_VINES)
		return -ENOSPC;
	/* as the tree grows its other arrays: doubling from 16 */
	if (t->nvines + 1 >= t->cap_vines) {
		ncap = t->cap_vines ? t->cap_vines * 2 : 16;
		p = realloc(t->vines, ncap * sizeof(*p));
		if (!p)
			return -ENOMEM;
		t->vines = p;
		t->cap_vines = ncap;
	}
	t->vine_ops = &vine_tree_ops;
	t->vines[t->nvines++] = *v;
	memset(v, 0, sizeof(*v));
	v->active = -1;
	return 0;
}
