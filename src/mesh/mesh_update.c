/* SPDX-License-Identifier: MIT */
/*
 * Meshing a tree in place from the meshes of another (undo and redo, app_history.c):
 * every part is a run of vertices and of indices of one element, laid out in the tree's
 * order (mesh.h), so the new meshes are the old ones with runs taken out, put in (from a
 * stash or built) and the runs between shifted. The runs kept move with memmove, those
 * moving towards the start first and from the start, the others from the end, so none is
 * overwritten before it has moved; their indices shift by how far their vertices moved.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"

/* Where one part comes from. */
struct run {
	const struct mesh *from; /* NULL: the meshes being updated (an old part) */
	size_t v0, nv, i0, ni;   /* in `from` */
};

struct one {
	struct mesh *m;
	size_t n;                   /* elements afterwards */
	struct run *runs;           /* n of them */
	struct tree_mesh_mark *marks; /* n + 1, afterwards */
};

static struct run part(const struct mesh *from, const struct tree_mesh_mark *marks, size_t i)
{
	return (struct run){ from, marks[i].nvertices, marks[i + 1].nvertices - marks[i].nvertices,
			     marks[i].nindices, marks[i + 1].nindices - marks[i].nindices };
}

/* Checks a plan for one mesh and works out where everything goes; reserves room. */
static int prepare(struct one *o, struct mesh *m, const struct tree_mesh_mark *old_marks,
		   size_t nold, size_t n, const int *plan, const struct mesh *stash,
		   const struct tree_mesh_mark *stash_marks, size_t nstash, const struct mesh *built,
		   const struct tree_mesh_mark *built_marks, size_t *next_built)
{
	size_t v = 0, x = 0;
	long last = -1;

	o->m = m;
	o->n = n;
	o->runs = malloc((n + 1) * sizeof(*o->runs));
	o->marks = malloc((n + 1) * sizeof(*o->marks));
	if (!o->runs || !o->marks)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++) {
		int p = plan[i];

		if (p >= 0) {
			if ((size_t)p >= nold || p <= last)
				return -EINVAL;
			last = p;
			o->runs[i] = part(NULL, old_marks, (size_t)p);
		} else if (p == TREE_MESH_BUILD) {
			o->runs[i] = part(built, built_marks, (*next_built)++);
		} else {
			if (!stash || (size_t)(-2 - (long)p) >= nstash)
				return -EINVAL;
			o->runs[i] = part(stash, stash_marks, (size_t)(-2 - (long)p));
		}
		o->marks[i] = (struct tree_mesh_mark){ v, x };
		v += o->runs[i].nv;
		x += o->runs[i].ni;
	}
	o->marks[n] = (struct tree_mesh_mark){ v, x };
	if (v > UINT32_MAX)
		return -ENOMEM;
	return mesh_reserve(m, v > m->nvertices ? v - m->nvertices : 0,
			    x > m->nindices ? x - m->nindices : 0);
}

static void move_vertices(struct mesh *m, size_t to, size_t from, size_t n)
{
	if (n == 0)
		return;
	memmove(&m->positions[3 * to], &m->positions[3 * from], n * 3 * sizeof(float));
	memmove(&m->normals[3 * to], &m->normals[3 * from], n * 3 * sizeof(float));
}

/* n indices from `from` to `to` in m, each shifted by `shift` (mod 2^32). */
static void move_indices(struct mesh *m, size_t to, size_t from, size_t n, uint32_t shift)
{
	uint32_t *idx = m->indices;

	if (to <= from)
		for (size_t k = 0; k < n; k++)
			idx[to + k] = idx[from + k] + shift;
	else
		for (size_t k = n; k-- > 0;)
			idx[to + k] = idx[from + k] + shift;
}

/* Moves the kept runs to their places, then copies the others in. Cannot fail. */
static void commit(struct one *o)
{
	struct mesh *m = o->m;

	/* vertices: towards the start in order, towards the end in reverse */
	for (size_t i = 0; i < o->n; i++) {
		const struct run *r = &o->runs[i];

		if (!r->from && o->marks[i].nvertices < r->v0)
			move_vertices(m, o->marks[i].nvertices, r->v0, r->nv);
	}
	for (size_t i = o->n; i-- > 0;) {
		const struct run *r = &o->runs[i];

		if (!r->from && o->marks[i].nvertices > r->v0)
			move_vertices(m, o->marks[i].nvertices, r->v0, r->nv);
	}
	/* indices alike, on their own places, shifted as their vertices moved */
	for (size_t i = 0; i < o->n; i++) {
		const struct run *r = &o->runs[i];
		uint32_t shift = (uint32_t)o->marks[i].nvertices - (uint32_t)r->v0;

		if (!r->from && o->marks[i].nindices <= r->i0 && (shift || o->marks[i].nindices != r->i0))
			move_indices(m, o->marks[i].nindices, r->i0, r->ni, shift);
	}
	for (size_t i = o->n; i-- > 0;) {
		const struct run *r = &o->runs[i];
		uint32_t shift = (uint32_t)o->marks[i].nvertices - (uint32_t)r->v0;

		if (!r->from && o->marks[i].nindices > r->i0)
			move_indices(m, o->marks[i].nindices, r->i0, r->ni, shift);
	}
	for (size_t i = 0; i < o->n; i++) {
		const struct run *r = &o->runs[i];
		size_t v = o->marks[i].nvertices, x = o->marks[i].nindices;
		uint32_t shift = (uint32_t)v - (uint32_t)r->v0;

		if (!r->from || r->nv == 0)
			continue; /* (no vertices: no indices either) */
		memcpy(&m->positions[3 * v], &r->from->positions[3 * r->v0], r->nv * 3 * sizeof(float));
		memcpy(&m->normals[3 * v], &r->from->normals[3 * r->v0], r->nv * 3 * sizeof(float));
		for (size_t k = 0; k < r->ni; k++)
			m->indices[x + k] = r->from->indices[r->i0 + k] + shift;
	}
	m->nvertices = o->marks[o->n].nvertices;
	m->nindices = o->marks[o->n].nindices;
}

static size_t count_builds(const int *plan, size_t n, size_t **list)
{
	size_t k = 0;

	for (size_t i = 0; i < n; i++)
		k += plan[i] == TREE_MESH_BUILD;
	*list = malloc((k ? k : 1) * sizeof(**list));
	if (!*list)
		return SIZE_MAX;
	k = 0;
	for (size_t i = 0; i < n; i++)
		if (plan[i] == TREE_MESH_BUILD)
			(*list)[k++] = i;
	return k;
}

int tree_mesh_update(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
		     const struct tree_mesh_plan *plan, size_t *parts_built)
{
	struct one bark = { 0 }, leaves = { 0 };
	struct tree_mesh built;
	struct tree_mesh_marks built_mk;
	size_t *bl = NULL, *ll = NULL, nbl, nll, nb = 0, nl = 0;
	size_t nstash_b = 0, nstash_l = 0;
	const struct mesh *sb = NULL, *sl = NULL;
	int r = -EINVAL;

	tree_mesh_init(&built);
	tree_mesh_marks_init(&built_mk);
	if (mk->nbark == 0 || mk->nleaves == 0)
		goto out; /* the old parts are not known */
	if (plan->stash) {
		if (plan->stash_mk->nbark == 0 || plan->stash_mk->nleaves == 0)
			goto out;
		sb = &plan->stash->bark;
		sl = &plan->stash->leaves;
		nstash_b = plan->stash_mk->nbark - 1;
		nstash_l = plan->stash_mk->nleaves - 1;
	}
	r = -ENOMEM;
	nbl = count_builds(plan->branch, t->nbranches, &bl);
	nll = count_builds(plan->leaf, t->nleaves, &ll);
	if (nbl == SIZE_MAX || nll == SIZE_MAX)
		goto out;
	r = tree_mesh_build_parts(&built, &built_mk, t, bl, nbl, ll, nll);
	if (r < 0)
		goto out;
	r = prepare(&bark, &tm->bark, mk->bark, mk->nbark - 1, t->nbranches, plan->branch, sb,
		    plan->stash ? plan->stash_mk->bark : NULL, nstash_b, &built.bark, built_mk.bark, &nb);
	if (r == 0)
		r = prepare(&leaves, &tm->leaves, mk->leaves, mk->nleaves - 1, t->nleaves, plan->leaf,
			    sl, plan->stash ? plan->stash_mk->leaves : NULL, nstash_l, &built.leaves,
			    built_mk.leaves, &nl);
	if (r < 0)
		goto out;
	/* nothing fails from here on */
	commit(&bark);
	commit(&leaves);
	free(mk->bark);
	free(mk->leaves);
	mk->bark = bark.marks;
	mk->leaves = leaves.marks;
	mk->nbark = mk->cap_bark = t->nbranches + 1;
	mk->nleaves = mk->cap_leaves = t->nleaves + 1;
	bark.marks = leaves.marks = NULL;
	if (parts_built)
		*parts_built = nbl + nll;
out:
	free(bark.runs);
	free(bark.marks);
	free(leaves.runs);
	free(leaves.marks);
	free(bl);
	free(ll);
	tree_mesh_finish(&built);
	tree_mesh_marks_finish(&built_mk);
	return r;
}

/* Room for exactly nv vertices and ni indices in m (emptied): a stash holds what it
 * needs, no more. 0 or -ENOMEM. */
static int reserve_exact(struct mesh *m, size_t nv, size_t ni)
{
	mesh_clear(m);
	if (m->cap_vertices < nv || m->cap_vertices > 2 * nv + 256) {
		mesh_finish(m);
		m->positions = malloc((nv ? nv : 1) * 3 * sizeof(float));
		m->normals = malloc((nv ? nv : 1) * 3 * sizeof(float));
		m->indices = malloc((ni ? ni : 1) * sizeof(uint32_t));
		if (!m->positions || !m->normals || !m->indices) {
			mesh_finish(m);
			return -ENOMEM;
		}
		m->cap_vertices = nv;
		m->cap_indices = ni;
	}
	return mesh_reserve(m, nv, ni);
}

/* A quarter more than m uses: room to append to once it is the meshes again, without
 * moving them all (a realloc of tens of MB is a press's worth of time). */
static void shrink(struct mesh *m)
{
	size_t nv = m->nvertices + m->nvertices / 4 + 256, ni = m->nindices + m->nindices / 4 + 256;
	void *p;

	/* failing to shrink leaves it as it was */
	if (m->cap_vertices > nv && (p = realloc(m->positions, nv * 3 * sizeof(float)))) {
		m->positions = p;
		if ((p = realloc(m->normals, nv * 3 * sizeof(float)))) {
			m->normals = p;
			m->cap_vertices = nv;
		}
	}
	if (m->cap_indices > ni && (p = realloc(m->indices, ni * sizeof(uint32_t)))) {
		m->indices = p;
		m->cap_indices = ni;
	}
}

void tree_mesh_shrink(struct tree_mesh *tm)
{
	shrink(&tm->bark);
	shrink(&tm->leaves);
}

/* Parts `which` of m (marked in marks, nmarks of them) one after the other into out. */
static int copy_runs(struct mesh *out, struct tree_mesh_mark **out_marks, size_t *nout,
		     size_t *cap, const struct mesh *m, const struct tree_mesh_mark *marks,
		     size_t nmarks, const size_t *which, size_t n)
{
	size_t v = 0, x = 0;
	struct tree_mesh_mark *om;

	mesh_clear(out);
	for (size_t k = 0; k < n; k++) {
		if (which[k] + 1 >= nmarks)
			return -EINVAL;
		v += marks[which[k] + 1].nvertices - marks[which[k]].nvertices;
		x += marks[which[k] + 1].nindices - marks[which[k]].nindices;
	}
	om = malloc((n + 1) * sizeof(*om));
	if (!om || reserve_exact(out, v, x) < 0) {
		free(om);
		return -ENOMEM;
	}
	v = x = 0;
	for (size_t k = 0; k < n; k++) {
		struct run r = part(m, marks, which[k]);
		uint32_t shift = (uint32_t)v - (uint32_t)r.v0;

		om[k] = (struct tree_mesh_mark){ v, x };
		if (r.nv) {
			memcpy(&out->positions[3 * v], &m->positions[3 * r.v0], r.nv * 3 * sizeof(float));
			memcpy(&out->normals[3 * v], &m->normals[3 * r.v0], r.nv * 3 * sizeof(float));
		}
		for (size_t i = 0; i < r.ni; i++)
			out->indices[x + i] = m->indices[r.i0 + i] + shift;
		v += r.nv;
		x += r.ni;
	}
	om[n] = (struct tree_mesh_mark){ v, x };
	out->nvertices = v;
	out->nindices = x;
	free(*out_marks);
	*out_marks = om;
	*nout = *cap = n + 1;
	return 0;
}

int tree_mesh_copy_parts(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
			 const struct tree_mesh *tm, const struct tree_mesh_marks *mk,
			 const size_t *branches, size_t nb, const size_t *leaves, size_t nl)
{
	int r;

	if (mk->nbark == 0 || mk->nleaves == 0)
		return -EINVAL;
	r = copy_runs(&out->bark, &out_mk->bark, &out_mk->nbark, &out_mk->cap_bark, &tm->bark,
		      mk->bark, mk->nbark, branches, nb);
	if (r == 0)
		r = copy_runs(&out->leaves, &out_mk->leaves, &out_mk->nleaves, &out_mk->cap_leaves,
			      &tm->leaves, mk->leaves, mk->nleaves, leaves, nl);
	if (r < 0) {
		mesh_clear(&out->bark);
		mesh_clear(&out->leaves);
		out_mk->nbark = out_mk->nleaves = 0;
	}
	return r;
}
