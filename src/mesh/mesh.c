/* SPDX-License-Identifier: MIT */
#include "mesh.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_private.h"

void tree_mesh_init(struct tree_mesh *tm)
{
	mesh_init(&tm->bark);
	mesh_init(&tm->leaves);
}

void tree_mesh_finish(struct tree_mesh *tm)
{
	mesh_finish(&tm->bark);
	mesh_finish(&tm->leaves);
}

size_t mesh_grow_cap(size_t cap, size_t need)
{
	size_t ncap = cap ? cap : 256;

	while (ncap < need)
		ncap *= 2;
	return ncap;
}

uint32_t mesh_push_vertex(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *pos = &m->positions[3 * m->nvertices];
	float *nor = &m->normals[3 * m->nvertices];

	pos[0] = (float)p.x;
	pos[1] = (float)p.y;
	pos[2] = (float)p.z;
	nor[0] = (float)n.x;
	nor[1] = (float)n.y;
	nor[2] = (float)n.z;
	return (uint32_t)m->nvertices++;
}

void mesh_push_tri(struct mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t *idx = &m->indices[m->nindices];

	idx[0] = a;
	idx[1] = b;
	idx[2] = c;
	m->nindices += 3;
}

bool mesh_vec3_finite(struct vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* A tree's fixed ring sides within what the tables hold, or 0 (by radius). */
static int tree_sides(const struct tree *t)
{
	if (t->sides <= 0)
		return 0;
	return t->sides < MESH_MIN_SIDES ? MESH_MIN_SIDES : t->sides > MESH_MAX_SIDES ? MESH_MAX_SIDES : t->sides;
}

void mesh_scratch_finish(struct mesh_scratch *s)
{
	free(s->p);
	free(s->t);
	free(s->n);
	free(s->r);
	free(s->sides);
	free(s->x);
	free(s->y);
	free(s->live);
	free(s->host_at);
	free(s->host_n);
	free(s->hp);
	free(s->hx);
	free(s->hy);
	memset(s, 0, sizeof(*s));
}

#define SCRATCH_GROW(field, cap)                                                  \
	do {                                                                      \
		void *p_ = realloc(s->field, (cap) * sizeof(*s->field));          \
		if (!p_)                                                          \
			return -ENOMEM;                                           \
		s->field = p_;                                                    \
	} while (0)

int mesh_scratch_reserve(struct mesh_scratch *s, size_t n)
{
	size_t cap;

	if (n <= s->cap)
		return 0;
	if (n > SIZE_MAX / 2 / sizeof(struct vec3))
		return -ENOMEM;
	cap = mesh_grow_cap(s->cap, n);
	/* s->cap only moves once every array has the new size. */
	SCRATCH_GROW(p, cap);
	SCRATCH_GROW(t, cap);
	SCRATCH_GROW(n, cap);
	SCRATCH_GROW(r, cap);
	SCRATCH_GROW(sides, cap);
	SCRATCH_GROW(x, cap);
	SCRATCH_GROW(y, cap);
	SCRATCH_GROW(live, cap);
	s->cap = cap;
	return 0;
}

void tree_mesh_marks_init(struct tree_mesh_marks *mk)
{
	memset(mk, 0, sizeof(*mk));
}

void tree_mesh_marks_finish(struct tree_mesh_marks *mk)
{
	free(mk->bark);
	free(mk->leaves);
	tree_mesh_marks_init(mk);
}

/* Marks from element `first` on, in step with m: keeps what is known, or forgets it all. */
static void mark_start(struct tree_mesh_mark **marks, size_t *n, size_t first, const struct mesh *m)
{
	if (first == 0) {
		*n = 0;
		if (*marks) {
			(*marks)[0] = (struct tree_mesh_mark){ 0, 0 };
			*n = 1;
		}
		return;
	}
	if (*n != first + 1 || (*marks)[first].nvertices != m->nvertices ||
	    (*marks)[first].nindices != m->nindices)
		*n = 0;
}

static void mark_next(struct tree_mesh_mark **marks, size_t *n, size_t *cap, const struct mesh *m)
{
	if (*n == 0)
		return;
	if (*n == *cap) {
		size_t ncap = *cap ? *cap * 2 : 64;
		struct tree_mesh_mark *p = realloc(*marks, ncap * sizeof(*p));

		if (!p) {
			*n = 0; /* unknown: undo meshes the tree again */
			return;
		}
		*marks = p;
		*cap = ncap;
	}
	(*marks)[(*n)++] = (struct tree_mesh_mark){ m->nvertices, m->nindices };
}

static void marks_reserve_first(struct tree_mesh_mark **marks, size_t *cap)
{
	if (*cap == 0) {
		*marks = malloc(64 * sizeof(**marks));
		*cap = *marks ? 64 : 0;
	}
}

int tree_mesh_append_marked(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
			    size_t first_leaf, struct tree_mesh_marks *mk)
{
	struct mesh_scratch sc;
	int r = 0;

	memset(&sc, 0, sizeof(sc));
	mesh_lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	if (mk) {
		marks_reserve_first(&mk->bark, &mk->cap_bark);
		marks_reserve_first(&mk->leaves, &mk->cap_leaves);
		mark_start(&mk->bark, &mk->nbark, first_branch, &tm->bark);
		mark_start(&mk->leaves, &mk->nleaves, first_leaf, &tm->leaves);
	}
	for (size_t i = first_branch; i < t->nbranches && r == 0; i++) {
		/* a branch the wood holds has the wood's bark (wood.h): an empty part here */
		if (!tree_branch_in_wood(t, i))
			r = mesh_tube_build(&tm->bark, t, i, &sc);
		if (mk)
			mark_next(&mk->bark, &mk->nbark, &mk->cap_bark, &tm->bark);
	}
	for (size_t i = first_leaf; i < t->nleaves && r == 0; i++) {
		r = mesh_leaf_build(&tm->leaves, &t->leaves[i], &sc);
		if (mk)
			mark_next(&mk->leaves, &mk->nleaves, &mk->cap_leaves, &tm->leaves);
	}

	mesh_scratch_finish(&sc);
	if (r < 0) {
		/* Half a tree is no tree. */
		mesh_clear(&tm->bark);
		mesh_clear(&tm->leaves);
		if (mk)
			mk->nbark = mk->nleaves = 0;
	}
	return r;
}

/* Appends part i of src (between marks i and i + 1) to m, its indices moved along. */
static int copy_part(struct mesh *m, const struct mesh *src, const struct tree_mesh_mark *marks,
		     size_t i)
{
	size_t v0 = marks[i].nvertices, nv = marks[i + 1].nvertices - v0;
	size_t i0 = marks[i].nindices, ni = marks[i + 1].nindices - i0;
	uint32_t base;
	int r = mesh_reserve(m, nv, ni);

	if (r < 0)
		return r;
	base = (uint32_t)m->nvertices;
	memcpy(&m->positions[3 * m->nvertices], &src->positions[3 * v0], nv * 3 * sizeof(float));
	memcpy(&m->normals[3 * m->nvertices], &src->normals[3 * v0], nv * 3 * sizeof(float));
	/* a part's triangles use its own vertices only: they move with them */
	if (base == v0) {
		memcpy(&m->indices[m->nindices], &src->indices[i0], ni * sizeof(*m->indices));
	} else {
		const uint32_t *restrict from = &src->indices[i0];
		uint32_t *restrict to = &m->indices[m->nindices];
		uint32_t shift = base - (uint32_t)v0;

		for (size_t k = 0; k < ni; k++)
			to[k] = from[k] + shift;
	}
	m->nvertices += nv;
	m->nindices += ni;
	return 0;
}

int tree_mesh_build_reusing(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
			    const struct tree_mesh *from, const struct tree_mesh_marks *from_mk,
			    const int *reuse_branch, const int *reuse_leaf)
{
	struct mesh_scratch sc;
	int r = 0;

	mesh_clear(&tm->bark);
	mesh_clear(&tm->leaves);
	/* about as large as from: room at once, not by doubling */
	if (mesh_reserve(&tm->bark, from->bark.nvertices, from->bark.nindices) < 0 ||
	    mesh_reserve(&tm->leaves, from->leaves.nvertices, from->leaves.nindices) < 0)
		return -ENOMEM;
	memset(&sc, 0, sizeof(sc));
	mesh_lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	marks_reserve_first(&mk->bark, &mk->cap_bark);
	marks_reserve_first(&mk->leaves, &mk->cap_leaves);
	mark_start(&mk->bark, &mk->nbark, 0, &tm->bark);
	mark_start(&mk->leaves, &mk->nleaves, 0, &tm->leaves);
	for (size_t i = 0; i < t->nbranches && r == 0; i++) {
		if (reuse_branch[i] >= 0)
			r = copy_part(&tm->bark, &from->bark, from_mk->bark, (size_t)reuse_branch[i]);
		else
			r = mesh_tube_build(&tm->bark, t, i, &sc);
		mark_next(&mk->bark, &mk->nbark, &mk->cap_bark, &tm->bark);
	}
	for (size_t i = 0; i < t->nleaves && r == 0; i++) {
		if (reuse_leaf[i] >= 0)
			r = copy_part(&tm->leaves, &from->leaves, from_mk->leaves, (size_t)reuse_leaf[i]);
		else
			r = mesh_leaf_build(&tm->leaves, &t->leaves[i], &sc);
		mark_next(&mk->leaves, &mk->nleaves, &mk->cap_leaves, &tm->leaves);
	}
	mesh_scratch_finish(&sc);
	if (r < 0) {
		mesh_clear(&tm->bark);
		mesh_clear(&tm->leaves);
		mk->nbark = mk->nleaves = 0;
	}
	return r;
}

int tree_mesh_build_parts_coarse(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
				 const struct tree *t, const size_t *branches, size_t nb,
				 const size_t *leaves, size_t nl, const struct mesh_coarse *c)
{
	struct mesh_scratch sc;
	int r = 0;

	mesh_clear(&out->bark);
	mesh_clear(&out->leaves);
	memset(&sc, 0, sizeof(sc));
	mesh_lod_init(&sc.lod);
	sc.lod.fixed = tree_sides(t);
	mesh_lod_coarsen(&sc.lod, c);
	marks_reserve_first(&out_mk->bark, &out_mk->cap_bark);
	marks_reserve_first(&out_mk->leaves, &out_mk->cap_leaves);
	mark_start(&out_mk->bark, &out_mk->nbark, 0, &out->bark);
	mark_start(&out_mk->leaves, &out_mk->nleaves, 0, &out->leaves);
	for (size_t k = 0; k < nb && r == 0; k++) {
		if (branches[k] >= t->nbranches)
			r = -EINVAL;
		else if (!tree_branch_in_wood(t, branches[k]))
			r = mesh_tube_build(&out->bark, t, branches[k], &sc);
		mark_next(&out_mk->bark, &out_mk->nbark, &out_mk->cap_bark, &out->bark);
	}
	for (size_t k = 0; k < nl && r == 0; k++) {
		if (leaves[k] >= t->nleaves)
			r = -EINVAL;
		else
			r = mesh_leaf_build(&out->leaves, &t->leaves[leaves[k]], &sc);
		mark_next(&out_mk->leaves, &out_mk->nleaves, &out_mk->cap_leaves, &out->leaves);
	}
	mesh_scratch_finish(&sc);
	/* every part must be marked: a mark that could not be kept is a failure here */
	if (r == 0 && (out_mk->nbark != nb + 1 || out_mk->nleaves != nl + 1))
		r = -ENOMEM;
	if (r < 0) {
		mesh_clear(&out->bark);
		mesh_clear(&out->leaves);
		out_mk->nbark = out_mk->nleaves = 0;
	}
	return r;
}

int tree_mesh_build_parts(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
			  const struct tree *t, const size_t *branches, size_t nb, const size_t *leaves,
			  size_t nl)
{
	return tree_mesh_build_parts_coarse(out, out_mk, t, branches, nb, leaves, nl, NULL);
}

int tree_mesh_append(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
		     size_t first_leaf)
{
	return tree_mesh_append_marked(tm, t, first_branch, first_leaf, NULL);
}

int tree_mesh_build_marked(struct tree_mesh *tm, const struct tree *t, struct tree_mesh_marks *mk)
{
	mesh_clear(&tm->bark);
	mesh_clear(&tm->leaves);
	return tree_mesh_append_marked(tm, t, 0, 0, mk);
}

int tree_mesh_build(struct tree_mesh *tm, const struct tree *t)
{
	return tree_mesh_build_marked(tm, t, NULL);
}

bool tree_mesh_truncate(struct tree_mesh *tm, struct tree_mesh_marks *mk, size_t nb, size_t nl)
{
	if (nb >= mk->nbark || nl >= mk->nleaves)
		return false;
	tm->bark.nvertices = mk->bark[nb].nvertices;
	tm->bark.nindices = mk->bark[nb].nindices;
	tm->leaves.nvertices = mk->leaves[nl].nvertices;
	tm->leaves.nindices = mk->leaves[nl].nindices;
	mk->nbark = nb + 1;
	mk->nleaves = nl + 1;
	return true;
}
