/* SPDX-License-Identifier: MIT */
/* Leaves grouped by shape for instanced drawing: how and why in leaf_instances.h. */
#include "leaf_instances.h"
#include "ori_kinds.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Outlines thinner than this fraction of their size have no frame to match by. */
#define LINE_LIKE 1e-9

void leaf_instances_init(struct leaf_instances *li)
{
	memset(li, 0, sizeof(*li));
	mesh_init(&li->loose);
}

static void free_frames(struct leaf_shape *s)
{
	if (!s->frames)
		return;
	for (size_t j = 0; j < ORI_UNFOLD_FRAMES; j++)
		mesh_finish(&s->frames[j]);
	free(s->frames);
	s->frames = NULL;
}

static void clear_shapes(struct leaf_instances *li)
{
	for (size_t i = 0; i < li->nshapes; i++) {
		mesh_finish(&li->shapes[i].mesh);
		free_frames(&li->shapes[i]);
	}
	li->nshapes = 0;
	li->ninstances = 0;
	li->ninstanced = 0;
	li->ninstanced_shapes = 0;
	li->ntriangles = 0;
	mesh_clear(&li->loose);
}

void leaf_instances_finish(struct leaf_instances *li)
{
	clear_shapes(li);
	free(li->shapes);
	free(li->instances);
	free(li->matrices);
	free(li->table);
	free(li->by_leaf);
	mesh_finish(&li->loose);
	leaf_instances_init(li);
}

/* Grows *p (of *cap elements of `size` bytes) to hold n. 0 or -ENOMEM. */
static int reserve(void **p, size_t *cap, size_t n, size_t size)
{
	size_t ncap = *cap ? *cap : 16;
	void *np;

	if (n <= *cap)
		return 0;
	while (ncap < n) {
		if (ncap > SIZE_MAX / 2)
			return -ENOMEM;
		ncap *= 2;
	}
	if (ncap > SIZE_MAX / size)
		return -ENOMEM;
	np = realloc(*p, ncap * size);
	if (!np)
		return -ENOMEM;
	*p = np;
	*cap = ncap;
	return 0;
}

static bool finite3(struct vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* One multiply a value: keys only spread candidates over the table. */
static uint64_t mix(uint64_t h, uint64_t v)
{
	h = (h ^ v) * 0x9e3779b97f4a7c15ull;
	return h ^ (h >> 29);
}

static uint64_t finalise(uint64_t h)
{
	h ^= h >> 30;
	h *= 0xbf58476d1ce4e5b9ull;
	h ^= h >> 27;
	h *= 0x94d049bb133111ebull;
	return h ^ (h >> 31);
}

/* What a leaf is matched by: its centroid, size (largest distance from the centroid),
 * sum of squared distances, key; false when it cannot be matched at all. */
struct leaf_facts {
	struct vec3 c;
	double size, norm2;
	uint64_t key;
};

static bool leaf_facts(const struct leaf *l, struct leaf_facts *f)
{
	const struct vec3 *p = l->points;
	size_t n = l->npoints;
	double edges2 = 0.0, steps;
	uint64_t h = 0xcbf29ce484222325ull;
	struct vec3 prev;

	f->c = vec3(0, 0, 0);
	f->size = f->norm2 = 0.0;
	f->key = 0;
	if (n < 3)
		return false;
	for (size_t k = 0; k < n; k++) {
		if (!finite3(p[k]))
			return false;
		f->c = vec3_add(f->c, p[k]);
	}
	f->c = vec3_scale(f->c, 1.0 / (double)n);
	prev = p[n - 1];
	for (size_t k = 0; k < n; k++) {
		struct vec3 e = vec3_sub(p[k], f->c), d = vec3_sub(p[k], prev);
		double e2 = vec3_dot(e, e);

		f->norm2 += e2;
		if (e2 > f->size)
			f->size = e2;
		edges2 += vec3_dot(d, d);
		prev = p[k];
	}
	f->size = sqrt(f->size);
	if (!(f->size > 0) || !(edges2 > 0) || !isfinite(f->norm2) || !isfinite(edges2))
		return false;
	/* squared edge lengths as fractions of their sum: no square roots, the same for
	 * every turn, scale and move of the outline */
	steps = LEAF_INSTANCES_KEY_STEPS / edges2;
	h = mix(h, (uint64_t)n);
	prev = p[n - 1];
	for (size_t k = 0; k < n; k++) {
		struct vec3 d = vec3_sub(p[k], prev);

		h = mix(h, (uint64_t)(vec3_dot(d, d) * steps + 0.5));
		prev = p[k];
	}
	f->key = finalise(h);
	return true;
}

/* A right-handed orthonormal frame from two points' offsets a, b (false: on a line). */
static bool frame_of(struct vec3 a, struct vec3 b, struct vec3 fr[3])
{
	struct vec3 x = vec3_cross(a, b);
	double la = vec3_len(a), lx = vec3_len(x);

	if (!(la > 0) || !(lx > LINE_LIKE * la * la))
		return false;
	fr[0] = vec3_scale(a, 1.0 / la);
	fr[2] = vec3_scale(x, 1.0 / lx);
	fr[1] = vec3_cross(fr[2], fr[0]);
	return true;
}

static struct vec3 apply(const double xf[12], struct vec3 d)
{
	return vec3(xf[0] * d.x + xf[1] * d.y + xf[2] * d.z + xf[3],
		    xf[4] * d.x + xf[5] * d.y + xf[6] * d.z + xf[7],
		    xf[8] * d.x + xf[9] * d.y + xf[10] * d.z + xf[11]);
}

static void identity_at(struct vec3 o, double xf[12])
{
	memset(xf, 0, 12 * sizeof(*xf));
	xf[0] = xf[5] = xf[10] = 1.0;
	xf[3] = o.x;
	xf[7] = o.y;
	xf[11] = o.z;
}

/* Leaf l (facts f) as an instance of shape s (base leaf `base`): true and its matrix when
 * every point fits. */
static bool fit(const struct leaf_shape *s, const struct leaf *base, const struct leaf *l,
		const struct leaf_facts *f, double xf[12])
{
	struct vec3 g[3];
	double scale, tol2;

	if (!frame_of(vec3_sub(l->points[s->anchor_a], f->c),
		      vec3_sub(l->points[s->anchor_b], f->c), g))
		return false;
	scale = sqrt(f->norm2 / s->norm2);
	/* M = scale * G F^T: takes the base's frame to the leaf's */
	{
		const double gm[3][3] = { { g[0].x, g[0].y, g[0].z },
					  { g[1].x, g[1].y, g[1].z },
					  { g[2].x, g[2].y, g[2].z } };
		const double fm[3][3] = { { s->frame[0].x, s->frame[0].y, s->frame[0].z },
					  { s->frame[1].x, s->frame[1].y, s->frame[1].z },
					  { s->frame[2].x, s->frame[2].y, s->frame[2].z } };

		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				xf[4 * r + c] = scale * (gm[0][r] * fm[0][c] + gm[1][r] * fm[1][c] +
							 gm[2][r] * fm[2][c]);
	}
	xf[3] = f->c.x;
	xf[7] = f->c.y;
	xf[11] = f->c.z;
	tol2 = LEAF_INSTANCES_TOLERANCE * f->size;
	tol2 *= tol2;
	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 p = apply(xf, vec3_sub(base->points[k], s->centroid));
		struct vec3 d = vec3_sub(p, l->points[k]);

		if (!(vec3_dot(d, d) <= tol2))
			return false;
	}
	return true;
}

/* A new shape based on leaf i. */
static int new_shape(struct leaf_instances *li, const struct tree *t, size_t i, bool ok,
		     const struct leaf_facts *f)
{
	const struct leaf *l = &t->leaves[i];
	struct leaf_shape *s;
	int r = reserve((void **)&li->shapes, &li->cap_shapes, li->nshapes + 1, sizeof(*s));

	if (r < 0)
		return r;
	s = &li->shapes[li->nshapes];
	memset(s, 0, sizeof(*s));
	mesh_init(&s->mesh);
	s->base = i;
	s->centroid = ok ? f->c : vec3(0, 0, 0);
	s->npoints = l->npoints;
	s->key = f->key;
	s->next_same_key = SIZE_MAX;
	s->norm2 = f->norm2;
	if (ok) {
		double best = -1.0;

		for (size_t k = 0; k < l->npoints; k++) {
			struct vec3 d = vec3_sub(l->points[k], f->c);
			double d2 = vec3_dot(d, d);

			if (d2 > best) {
				best = d2;
				s->anchor_a = k;
			}
		}
		best = -1.0;
		for (size_t k = 0; k < l->npoints; k++) {
			struct vec3 x = vec3_cross(vec3_sub(l->points[s->anchor_a], f->c),
						   vec3_sub(l->points[k], f->c));
			double x2 = vec3_dot(x, x);

			if (x2 > best) {
				best = x2;
				s->anchor_b = k;
			}
		}
		s->matchable = frame_of(vec3_sub(l->points[s->anchor_a], f->c),
					vec3_sub(l->points[s->anchor_b], f->c), s->frame);
	}
	li->nshapes++;
	return 0;
}

/* The table slot holding key's chain, or the empty slot where it would go. */
static size_t slot_of(const struct leaf_instances *li, uint64_t key)
{
	size_t mask = li->table_cap - 1, at = (size_t)key & mask;

	while (li->table[at] && li->shapes[li->table[at] - 1].key != key)
		at = (at + 1) & mask;
	return at;
}

/* Leaf i: an instance of an earlier shape, or the base of a new one. */
static int group_leaf(struct leaf_instances *li, const struct tree *t, size_t i)
{
	const struct leaf *l = &t->leaves[i];
	struct leaf_instance *inst = &li->by_leaf[i];
	struct leaf_facts f;
	bool ok = leaf_facts(l, &f);
	size_t at = 0;
	int r;

	inst->leaf = i;
	if (ok) {
		at = slot_of(li, f.key);
		for (size_t s = li->table[at] ? li->table[at] - 1 : SIZE_MAX; s != SIZE_MAX;
		     s = li->shapes[s].next_same_key) {
			struct leaf_shape *sh = &li->shapes[s];

			/* an outline's triangles are not an origami leaf's faces */
			if (sh->npoints == l->npoints && t->leaves[sh->base].kind == l->kind &&
			    fit(sh, &t->leaves[sh->base], l, &f, inst->xf)) {
				inst->shape = s;
				sh->count++;
				return 0;
			}
		}
	}
	r = new_shape(li, t, i, ok, &f);
	if (r < 0)
		return r;
	inst->shape = li->nshapes - 1;
	identity_at(li->shapes[inst->shape].centroid, inst->xf);
	li->shapes[inst->shape].count = 1;
	if (li->shapes[inst->shape].matchable) {
		if (!li->table[at]) {
			li->table[at] = inst->shape + 1;
		} else {
			size_t s = li->table[at] - 1;

			while (li->shapes[s].next_same_key != SIZE_MAX)
				s = li->shapes[s].next_same_key;
			li->shapes[s].next_same_key = inst->shape;
		}
	}
	return 0;
}

struct rank {
	size_t count, shape;
};

static int by_count(const void *a, const void *b)
{
	const struct rank *x = a, *y = b;

	if (x->count != y->count)
		return x->count > y->count ? -1 : 1;
	return x->shape < y->shape ? -1 : x->shape > y->shape;
}

/* Marks the shapes drawn instanced. 0 or -ENOMEM. */
static int choose_instanced(struct leaf_instances *li)
{
	struct rank *rk;
	size_t n = 0;

	for (size_t s = 0; s < li->nshapes; s++)
		n += li->shapes[s].count >= LEAF_INSTANCES_MIN_COPIES;
	if (n <= LEAF_INSTANCES_MAX_SHAPES) {
		for (size_t s = 0; s < li->nshapes; s++)
			li->shapes[s].instanced = li->shapes[s].count >= LEAF_INSTANCES_MIN_COPIES;
		li->ninstanced_shapes = n;
		return 0;
	}
	rk = malloc(n * sizeof(*rk));
	if (!rk)
		return -ENOMEM;
	n = 0;
	for (size_t s = 0; s < li->nshapes; s++) {
		if (li->shapes[s].count >= LEAF_INSTANCES_MIN_COPIES)
			rk[n++] = (struct rank){ li->shapes[s].count, s };
	}
	qsort(rk, n, sizeof(*rk), by_count);
	for (size_t k = 0; k < LEAF_INSTANCES_MAX_SHAPES; k++)
		li->shapes[rk[k].shape].instanced = true;
	li->ninstanced_shapes = LEAF_INSTANCES_MAX_SHAPES;
	free(rk);
	return 0;
}

/* An origami shape's keyframes, in the frame its mesh has: the base's points about the
 * centroid give it back. A shape whose leaves are not origami (or do not fit their kind:
 * meshed as outlines) has none. */
static int shape_frames(struct leaf_shape *s, const struct tree *t)
{
	const struct leaf *base = &t->leaves[s->base];
	const struct ori_kind *k = ori_kind_get(base->kind);
	struct vec3 *local;
	double xf[12];
	bool fits;

	free_frames(s);
	if (base->kind < 0 || !k)
		return base->kind < 0 || base->kind >= ORI_KIND_COUNT ? 0 : -ENOMEM;
	local = malloc(s->npoints * sizeof(*local));
	if (!local)
		return -ENOMEM;
	for (size_t i = 0; i < s->npoints; i++)
		local[i] = vec3_sub(base->points[i], s->centroid);
	fits = ori_kind_frame(k, local, s->npoints, xf);
	free(local);
	if (!fits)
		return 0;
	s->frames = calloc(ORI_UNFOLD_FRAMES, sizeof(*s->frames));
	if (!s->frames)
		return -ENOMEM;
	for (size_t j = 0; j < ORI_UNFOLD_FRAMES; j++) {
		int r = ori_mesh_append(&k->leaf,
					(const double (*)[3])(k->frames + j * k->leaf.nvertices), xf,
					&s->frames[j]);

		if (r < 0) {
			free_frames(s);
			return r;
		}
	}
	return 0;
}

/* Instanced shape s's outline about its centroid, triangulated by mesh.c. */
static int shape_mesh(struct leaf_shape *s, const struct tree *t)
{
	const struct leaf *base = &t->leaves[s->base];
	struct vec3 *local = malloc(s->npoints * sizeof(*local));
	struct leaf one;
	struct tree tr;
	struct tree_mesh tm;
	int r;

	if (!local)
		return -ENOMEM;
	for (size_t k = 0; k < s->npoints; k++)
		local[k] = vec3_sub(base->points[k], s->centroid);
	memset(&one, 0, sizeof(one));
	one.kind = base->kind; /* an origami leaf's faces, moved about the centroid too */
	one.points = local;
	one.npoints = s->npoints;
	memset(&tr, 0, sizeof(tr));
	tr.leaves = &one;
	tr.nleaves = 1;
	tree_mesh_init(&tm);
	r = tree_mesh_append(&tm, &tr, 0, 0);
	free(local);
	mesh_finish(&tm.bark);
	if (r < 0) {
		mesh_finish(&tm.leaves);
		return r;
	}
	mesh_finish(&s->mesh);
	s->mesh = tm.leaves;
	return shape_frames(s, t);
}

/* The leaves of shapes not instanced, merged by mesh.c in leaf order. */
static int loose_mesh(struct leaf_instances *li, const struct tree *t)
{
	struct tree tr;
	struct tree_mesh tm;
	size_t n = li->ninstances - li->ninstanced;
	struct leaf *leaves;
	int r;

	if (n == 0)
		return 0;
	leaves = malloc(n * sizeof(*leaves));
	if (!leaves)
		return -ENOMEM;
	n = 0;
	for (size_t i = 0; i < t->nleaves; i++) {
		if (!li->shapes[li->by_leaf[i].shape].instanced)
			leaves[n++] = t->leaves[i];
	}
	memset(&tr, 0, sizeof(tr));
	tr.leaves = leaves;
	tr.nleaves = n;
	tm.bark = (struct mesh){ 0 };
	tm.leaves = li->loose;
	r = tree_mesh_append(&tm, &tr, 0, 0);
	li->loose = tm.leaves;
	mesh_finish(&tm.bark);
	free(leaves);
	return r;
}

static int build(struct leaf_instances *li, const struct tree *t)
{
	size_t n = t->nleaves, cap = 16, at, at_loose;
	int r;

	if (n > SIZE_MAX / 4)
		return -ENOMEM;
	while (cap < 2 * n)
		cap *= 2;
	if (cap > li->table_cap) {
		size_t *tab = realloc(li->table, cap * sizeof(*tab));

		if (!tab)
			return -ENOMEM;
		li->table = tab;
		li->table_cap = cap;
	}
	memset(li->table, 0, li->table_cap * sizeof(*li->table));
	r = reserve((void **)&li->by_leaf, &li->cap_by_leaf, n, sizeof(*li->by_leaf));
	if (r == 0)
		r = reserve((void **)&li->instances, &li->cap_instances, n, sizeof(*li->instances));
	if (r == 0)
		r = reserve((void **)&li->matrices, &li->cap_matrices, n,
			    12 * sizeof(*li->matrices));
	for (size_t i = 0; i < n && r == 0; i++)
		r = group_leaf(li, t, i);
	if (r == 0)
		r = choose_instanced(li);
	if (r < 0)
		return r;

	/* instanced shapes' instances first, then the others', each shape's together */
	at = 0;
	for (size_t s = 0; s < li->nshapes; s++) {
		if (li->shapes[s].instanced) {
			li->shapes[s].first = at;
			at += li->shapes[s].count;
		}
	}
	li->ninstanced = at;
	at_loose = at;
	for (size_t s = 0; s < li->nshapes; s++) {
		if (!li->shapes[s].instanced) {
			li->shapes[s].first = at_loose;
			at_loose += li->shapes[s].count;
		}
		li->shapes[s].count = 0; /* counted again as they are placed */
	}
	li->ninstances = n;
	for (size_t i = 0; i < n; i++) {
		struct leaf_shape *s = &li->shapes[li->by_leaf[i].shape];
		size_t k = s->first + s->count++;

		li->instances[k] = li->by_leaf[i];
		for (int j = 0; j < 12; j++)
			li->matrices[12 * k + (size_t)j] = (float)li->by_leaf[i].xf[j];
	}
	for (size_t s = 0; s < li->nshapes && r == 0; s++) {
		if (li->shapes[s].instanced) {
			r = shape_mesh(&li->shapes[s], t);
			li->ntriangles += li->shapes[s].mesh.nindices / 3 * li->shapes[s].count;
		}
	}
	/* with nothing instanced it would be the tree's whole leaves mesh, built already */
	if (r == 0 && li->ninstanced_shapes > 0)
		r = loose_mesh(li, t);
	return r;
}

int leaf_instances_build(struct leaf_instances *li, const struct tree *t)
{
	int r;

	clear_shapes(li);
	r = build(li, t);
	if (r < 0)
		clear_shapes(li);
	return r;
}

struct vec3 leaf_instances_point(const struct leaf_instances *li, const struct tree *t,
				 size_t i, size_t k)
{
	const struct leaf_instance *inst = &li->instances[i];
	const struct leaf_shape *s = &li->shapes[inst->shape];

	return apply(inst->xf, vec3_sub(t->leaves[s->base].points[k], s->centroid));
}
