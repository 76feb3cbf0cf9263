/* SPDX-License-Identifier: MIT */
#include "tree_delta.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "tree_index.h"
#include "vine.h"
#include "wood.h"

/* ---- deltas ---- */

void tree_delta_init(struct tree_delta *d)
{
	memset(d, 0, sizeof(*d));
	for (int s = 0; s < 2; s++) {
		tree_mesh_init(&d->side[s].mesh);
		tree_mesh_marks_init(&d->side[s].mk);
	}
}

void tree_delta_drop_stash(struct tree_delta_side *s)
{
	tree_mesh_finish(&s->mesh);
	tree_mesh_marks_finish(&s->mk);
	s->stash = TREE_STASH_NONE;
}

/* Frees what a side holds of its elements (the stored side's). */
static void side_free_elements(struct tree_delta_side *s)
{
	for (size_t i = 0; s->branches && i < s->nb; i++) {
		free(s->branches[i].points);
		free(s->branches[i].radii);
	}
	for (size_t i = 0; s->leaves && i < s->nl; i++) {
		free(s->leaves[i].points);
		free(s->leaves[i].local);
	}
	for (size_t i = 0; s->vines && i < s->nvines - s->vines_from; i++)
		vine_finish(&s->vines[i]);
	if (s->wood) {
		wood_finish(s->wood);
		free(s->wood);
	}
	free(s->branches);
	free(s->leaves);
	free(s->vines);
	s->branches = NULL;
	s->leaves = NULL;
	s->vines = NULL;
	s->wood = NULL;
}

void tree_delta_finish(struct tree_delta *d)
{
	for (int k = 0; k < 2; k++) {
		struct tree_delta_side *s = &d->side[k];

		side_free_elements(s);
		free(s->branch_at);
		free(s->leaf_at);
		free(s->branch_kept);
		free(s->leaf_kept);
		tree_delta_drop_stash(s);
	}
	tree_delta_init(d);
}

static size_t mesh_bytes(const struct mesh *m)
{
	return m->cap_vertices * 6 * sizeof(float) + m->cap_indices * sizeof(uint32_t);
}

size_t tree_delta_bytes(const struct tree_delta *d, size_t *stash_bytes)
{
	size_t n = sizeof(*d), stash = 0;

	for (int k = 0; k < 2; k++) {
		const struct tree_delta_side *s = &d->side[k];

		n += (s->nb + s->nl) * (sizeof(size_t) + sizeof(bool));
		for (size_t i = 0; s->branches && i < s->nb; i++)
			n += sizeof(struct branch) +
			     s->branches[i].npoints * (sizeof(struct vec3) + sizeof(double));
		for (size_t i = 0; s->leaves && i < s->nl; i++)
			n += sizeof(struct leaf) + s->leaves[i].npoints * sizeof(struct vec3) *
							    (s->leaves[i].local ? 2 : 1);
		for (size_t i = 0; s->vines && i < s->nvines - s->vines_from; i++)
			n += sizeof(struct vine) + vine_bytes(&s->vines[i]);
		if (s->wood)
			n += sizeof(*s->wood) + wood_bytes(s->wood);
		if (s->stash != TREE_STASH_NONE)
			stash += mesh_bytes(&s->mesh.bark) + mesh_bytes(&s->mesh.leaves) +
				 (s->mk.cap_bark + s->mk.cap_leaves) * sizeof(struct tree_mesh_mark);
	}
	if (stash_bytes)
		*stash_bytes = stash;
	return n + stash;
}

bool tree_delta_appended_only(const struct tree_delta *d)
{
	const struct tree_delta_side *a = &d->side[0];

	return a->nb == 0 && a->nl == 0 && !d->wood && a->nvines == a->vines_from;
}

/* Room for the lists of a side: nb branches and nl leaves. 0 or -ENOMEM. */
static int side_lists(struct tree_delta_side *s, size_t nb, size_t nl)
{
	s->branch_at = malloc((nb ? nb : 1) * sizeof(*s->branch_at));
	s->branch_kept = malloc((nb ? nb : 1) * sizeof(*s->branch_kept));
	s->leaf_at = malloc((nl ? nl : 1) * sizeof(*s->leaf_at));
	s->leaf_kept = malloc((nl ? nl : 1) * sizeof(*s->leaf_kept));
	return s->branch_at && s->branch_kept && s->leaf_at && s->leaf_kept ? 0 : -ENOMEM;
}

static void *dup_array(const void *src, size_t n, size_t size)
{
	void *p;

	if (!src)
		return NULL;
	p = malloc(n ? n * size : 1);
	if (p && n)
		memcpy(p, src, n * size);
	return p;
}

/* ---- journals ---- */

struct tree_journal {
	const struct tree *owner;
	size_t nb0, nl0, nv0; /* the tree's counts when it began */
	struct wood *wood0;
	bool touched; /* the arrays below are there */
	bool failed;
	bool wood_taken, vines_taken;
	/* current branch (leaf) i < ncur: its index when the journal began, or -1 (new); the
	 * ones from ncur on are all new */
	int *cur_b, *cur_l;
	size_t ncur_b, ncur_l;
	/* per element when the journal began: 1 + its place in sb (sl), or 0 */
	size_t *saved_b, *saved_l;
	struct branch *sb; /* as they were: their ids, parents and arrays then */
	size_t nsb, cap_sb;
	struct leaf *sl;
	size_t nsl, cap_sl;
	struct vine *vines; /* the vines a clear took, nv0 of them */
};

static struct tree_journal *journal_of(const struct tree *t)
{
	struct tree_journal *j = t->journal;

	return j && j->owner == t && !j->failed ? j : NULL;
}

/* What the journal holds goes: the elements it kept, the vines and wood it took. */
static void journal_free(struct tree_journal *j)
{
	for (size_t i = 0; i < j->nsb; i++) {
		free(j->sb[i].points);
		free(j->sb[i].radii);
	}
	for (size_t i = 0; i < j->nsl; i++) {
		free(j->sl[i].points);
		free(j->sl[i].local);
	}
	for (size_t i = 0; j->vines && i < j->nv0; i++)
		vine_finish(&j->vines[i]);
	if (j->wood_taken && j->wood0) {
		wood_finish(j->wood0);
		free(j->wood0);
	}
	free(j->vines);
	free(j->cur_b);
	free(j->cur_l);
	free(j->saved_b);
	free(j->saved_l);
	free(j->sb);
	free(j->sl);
	free(j);
}

static void journal_discard(struct tree *t)
{
	struct tree_journal *j = t->journal;

	t->journal = NULL;
	if (j && j->owner == t)
		journal_free(j);
}

/* Out of memory: the journal stops keeping anything; its op will have no delta. What it
 * kept so far stays until the end (the tree no longer refers to it). */
static void give_up(struct tree_journal *j)
{
	j->failed = true;
}

/* The bookkeeping starts at the first edit of an element that was there. */
static bool touch(struct tree_journal *j, const struct tree *t)
{
	if (j->touched)
		return true;
	j->cur_b = malloc((t->nbranches ? t->nbranches : 1) * sizeof(*j->cur_b));
	j->cur_l = malloc((t->nleaves ? t->nleaves : 1) * sizeof(*j->cur_l));
	j->saved_b = calloc(j->nb0 + 1, sizeof(*j->saved_b));
	j->saved_l = calloc(j->nl0 + 1, sizeof(*j->saved_l));
	if (!j->cur_b || !j->cur_l || !j->saved_b || !j->saved_l) {
		give_up(j);
		return false;
	}
	/* nothing was renumbered yet: the first elements are the ones there at the start */
	for (size_t i = 0; i < t->nbranches; i++)
		j->cur_b[i] = i < j->nb0 ? (int)i : -1;
	for (size_t i = 0; i < t->nleaves; i++)
		j->cur_l[i] = i < j->nl0 ? (int)i : -1;
	j->ncur_b = t->nbranches;
	j->ncur_l = t->nleaves;
	j->touched = true;
	return true;
}

static int origin_b(const struct tree_journal *j, size_t i)
{
	return i < j->ncur_b ? j->cur_b[i] : -1;
}

static int origin_l(const struct tree_journal *j, size_t i)
{
	return i < j->ncur_l ? j->cur_l[i] : -1;
}

static bool grow_array(void **a, size_t *cap, size_t n, size_t size)
{
	size_t ncap;
	void *p;

	if (n < *cap)
		return true;
	ncap = *cap ? *cap * 2 : 16;
	p = realloc(*a, ncap * size);
	if (!p)
		return false;
	*a = p;
	*cap = ncap;
	return true;
}

static int journal_branch(struct tree *t, size_t i, bool keep)
{
	struct tree_journal *j = journal_of(t);
	struct branch *b, was;
	int o;

	if (!j || !touch(j, t) || (o = origin_b(j, i)) < 0 || j->saved_b[o])
		return 0;
	b = &t->branches[i];
	was = *b;
	was.id = o;
	was.parent = b->parent >= 0 ? origin_b(j, (size_t)b->parent) : -1;
	if ((b->parent >= 0 && was.parent < 0) ||
	    !grow_array((void **)&j->sb, &j->cap_sb, j->nsb, sizeof(*j->sb))) {
		give_up(j);
		return 0;
	}
	if (keep) {
		struct vec3 *p = dup_array(b->points, b->npoints, sizeof(*b->points));
		double *r = dup_array(b->radii, b->npoints, sizeof(*b->radii));

		if ((b->points && !p) || (b->radii && !r)) {
			free(p);
			free(r);
			return -ENOMEM;
		}
		b->points = p;
		b->radii = r;
	} else {
		b->points = NULL;
		b->radii = NULL;
	}
	j->sb[j->nsb++] = was;
	j->saved_b[o] = j->nsb;
	return 0;
}

static int journal_leaf(struct tree *t, size_t i, bool keep)
{
	struct tree_journal *j = journal_of(t);
	struct leaf *l, was;
	int o;

	if (!j || !touch(j, t) || (o = origin_l(j, i)) < 0 || j->saved_l[o])
		return 0;
	l = &t->leaves[i];
	was = *l;
	was.id = o;
	was.branch = l->branch >= 0 ? origin_b(j, (size_t)l->branch) : -1;
	if ((l->branch >= 0 && was.branch < 0) ||
	    !grow_array((void **)&j->sl, &j->cap_sl, j->nsl, sizeof(*j->sl))) {
		give_up(j);
		return 0;
	}
	if (keep) {
		struct vec3 *p = dup_array(l->points, l->npoints, sizeof(*l->points));
		struct vec3 *q = dup_array(l->local, l->npoints, sizeof(*l->local));

		if ((l->points && !p) || (l->local && !q)) {
			free(p);
			free(q);
			return -ENOMEM;
		}
		l->points = p;
		l->local = q;
	} else {
		l->points = NULL;
		l->local = NULL;
	}
	j->sl[j->nsl++] = was;
	j->saved_l[o] = j->nsl;
	return 0;
}

/* cur (ncur entries) after a compaction that sent old i to map[i] or nowhere. */
static void moved(int *cur, size_t *ncur, const int *map, size_t nold)
{
	size_t kept = 0;

	for (size_t i = 0; i < *ncur && i < nold; i++) {
		if (map[i] < 0)
			continue;
		cur[map[i]] = cur[i]; /* map[i] <= i: in place, forwards */
		kept++;
	}
	*ncur = kept;
}

static void journal_branches_moved(struct tree *t, const int *map, size_t nold)
{
	struct tree_journal *j = journal_of(t);

	if (j && j->touched)
		moved(j->cur_b, &j->ncur_b, map, nold);
}

static void journal_leaves_moved(struct tree *t, const int *map, size_t nold)
{
	struct tree_journal *j = journal_of(t);

	if (j && j->touched)
		moved(j->cur_l, &j->ncur_l, map, nold);
}

static void journal_truncate(struct tree *t, size_t nb, size_t nl)
{
	struct tree_journal *j = journal_of(t);

	if (!j || (nb >= t->nbranches && nl >= t->nleaves) || !touch(j, t))
		return;
	for (size_t i = nb; i < t->nbranches; i++)
		journal_branch(t, i, false);
	for (size_t i = nl; i < t->nleaves; i++)
		journal_leaf(t, i, false);
	if ((j = journal_of(t)) == NULL)
		return;
	if (j->ncur_b > nb)
		j->ncur_b = nb;
	if (j->ncur_l > nl)
		j->ncur_l = nl;
}

static void journal_clear(struct tree *t)
{
	struct tree_journal *j = journal_of(t);
	size_t nv;

	if (!j)
		return;
	journal_truncate(t, 0, 0);
	if ((j = journal_of(t)) == NULL || j->vines_taken)
		return;
	/* the vines there at the start are the first ones (vines are only appended) */
	nv = j->nv0 < t->nvines ? j->nv0 : t->nvines;
	if (nv != j->nv0) {
		give_up(j);
		return;
	}
	if (nv) {
		j->vines = malloc(nv * sizeof(*j->vines));
		if (!j->vines) {
			give_up(j);
			return;
		}
		memcpy(j->vines, t->vines, nv * sizeof(*j->vines));
		for (size_t i = 0; i < nv; i++) {
			memset(&t->vines[i], 0, sizeof(t->vines[i])); /* nothing for the clear to free */
			t->vines[i].active = -1;
		}
	}
	j->vines_taken = true;
}

static int journal_keep_cut(struct tree *t, int b, double cut_t)
{
	int ret;

	if (!journal_of(t))
		return 0;
	ret = journal_branch(t, (size_t)b, true);
	for (size_t i = 0; i < t->nleaves && ret == 0; i++)
		if (t->leaves[i].branch == b && t->leaves[i].branch_t <= cut_t)
			ret = journal_leaf(t, i, true);
	for (size_t i = 0; i < t->nbranches && ret == 0; i++)
		if (t->branches[i].parent == b && t->branches[i].parent_t <= cut_t)
			ret = journal_branch(t, i, true);
	return ret;
}

static void journal_fail(struct tree *t)
{
	struct tree_journal *j = journal_of(t);

	if (j)
		give_up(j);
}

static bool journal_take_wood(struct tree *t)
{
	struct tree_journal *j = journal_of(t);

	if (!j || j->wood_taken || !t->wood || t->wood != j->wood0)
		return false;
	j->wood_taken = true;
	return true;
}

/* What tree.c and tree_edit.c call while a journal watches (tree_journal.h). */
static const struct tree_journal_ops journal_ops = {
	.branch = journal_branch,
	.leaf = journal_leaf,
	.branches_moved = journal_branches_moved,
	.leaves_moved = journal_leaves_moved,
	.clear = journal_clear,
	.truncate = journal_truncate,
	.keep_cut = journal_keep_cut,
	.fail = journal_fail,
	.take_wood = journal_take_wood,
	.discard = journal_discard,
};

int tree_journal_begin(struct tree *t)
{
	struct tree_journal *j;

	journal_discard(t);
	j = calloc(1, sizeof(*j));
	if (!j)
		return -ENOMEM;
	j->owner = t;
	j->nb0 = t->nbranches;
	j->nl0 = t->nleaves;
	j->nv0 = t->nvines;
	j->wood0 = t->wood;
	t->journal = j;
	t->journal_ops = &journal_ops;
	return 0;
}

int tree_journal_end(struct tree *t, struct tree_delta *d)
{
	struct tree_journal *j = t->journal && t->journal->owner == t ? t->journal : NULL;
	struct tree_delta_side *b0 = &d->side[0], *b1 = &d->side[1];
	bool *alive_b = NULL, *alive_l = NULL;
	size_t n0b = 0, n0l = 0, n1b = 0, n1l = 0, vfrom;
	int ret = -ENOMEM;

	t->journal = NULL;
	if (!j)
		return -EINVAL;
	if (j->failed)
		goto out;
	vfrom = j->vines_taken ? 0 : j->nv0;
	/* what the journal did not see go cannot be undone: vines only appended, the wood
	 * only dropped or taken */
	if (t->nvines < vfrom || (t->wood != j->wood0 && j->wood0 && !j->wood_taken))
		goto out;
	if (j->touched) {
		alive_b = calloc(j->nb0 + 1, sizeof(*alive_b));
		alive_l = calloc(j->nl0 + 1, sizeof(*alive_l));
		if (!alive_b || !alive_l)
			goto out;
		for (size_t i = 0; i < j->ncur_b; i++)
			if (j->cur_b[i] >= 0)
				alive_b[j->cur_b[i]] = true;
		for (size_t i = 0; i < j->ncur_l; i++)
			if (j->cur_l[i] >= 0)
				alive_l[j->cur_l[i]] = true;
		/* every element gone was kept on its way out */
		for (size_t o = 0; o < j->nb0; o++)
			if (!alive_b[o] && !j->saved_b[o])
				goto out;
		for (size_t o = 0; o < j->nl0; o++)
			if (!alive_l[o] && !j->saved_l[o])
				goto out;
		n0b = j->nsb;
		n0l = j->nsl;
		for (size_t i = 0; i < t->nbranches; i++)
			n1b += origin_b(j, i) < 0 || j->saved_b[origin_b(j, i)];
		for (size_t i = 0; i < t->nleaves; i++)
			n1l += origin_l(j, i) < 0 || j->saved_l[origin_l(j, i)];
	} else {
		if (t->nbranches < j->nb0 || t->nleaves < j->nl0)
			goto out;
		n1b = t->nbranches - j->nb0;
		n1l = t->nleaves - j->nl0;
	}
	if (side_lists(b0, n0b, n0l) < 0 || side_lists(b1, n1b, n1l) < 0)
		goto out;
	b0->branches = malloc((n0b ? n0b : 1) * sizeof(*b0->branches));
	b0->leaves = malloc((n0l ? n0l : 1) * sizeof(*b0->leaves));
	if (!b0->branches || !b0->leaves)
		goto out;

	/* nothing can fail from here on: the kept elements move to the delta */
	b0->nbranches = j->nb0;
	b0->nleaves = j->nl0;
	b0->nvines = j->nv0;
	b0->vines_from = vfrom;
	b1->nbranches = t->nbranches;
	b1->nleaves = t->nleaves;
	b1->nvines = t->nvines;
	b1->vines_from = vfrom;
	if (j->touched) {
		for (size_t o = 0; o < j->nb0; o++) {
			if (!j->saved_b[o])
				continue;
			b0->branch_at[b0->nb] = o;
			b0->branch_kept[b0->nb] = alive_b[o];
			b0->branches[b0->nb++] = j->sb[j->saved_b[o] - 1];
		}
		for (size_t o = 0; o < j->nl0; o++) {
			if (!j->saved_l[o])
				continue;
			b0->leaf_at[b0->nl] = o;
			b0->leaf_kept[b0->nl] = alive_l[o];
			b0->leaves[b0->nl++] = j->sl[j->saved_l[o] - 1];
		}
		j->nsb = j->nsl = 0;
		for (size_t i = 0; i < t->nbranches; i++) {
			int o = origin_b(j, i);

			if (o >= 0 && !j->saved_b[o])
				continue;
			b1->branch_at[b1->nb] = i;
			b1->branch_kept[b1->nb++] = o >= 0;
		}
		for (size_t i = 0; i < t->nleaves; i++) {
			int o = origin_l(j, i);

			if (o >= 0 && !j->saved_l[o])
				continue;
			b1->leaf_at[b1->nl] = i;
			b1->leaf_kept[b1->nl++] = o >= 0;
		}
	} else {
		for (size_t i = j->nb0; i < t->nbranches; i++) {
			b1->branch_at[b1->nb] = i;
			b1->branch_kept[b1->nb++] = false;
		}
		for (size_t i = j->nl0; i < t->nleaves; i++) {
			b1->leaf_at[b1->nl] = i;
			b1->leaf_kept[b1->nl++] = false;
		}
	}
	if (j->vines_taken) {
		b0->vines = j->vines;
		j->vines = NULL;
	}
	d->wood = j->wood_taken || t->wood != j->wood0;
	if (j->wood_taken)
		b0->wood = j->wood0;
	j->wood_taken = false;
	d->stored = 0;
	ret = 0;
out:
	if (ret < 0)
		tree_delta_finish(d);
	free(alive_b);
	free(alive_l);
	journal_free(j);
	return ret;
}

/* ---- deltas of edits in place ---- */

static bool same_bytes(const void *a, const void *b, size_t n)
{
	return (a == NULL) == (b == NULL) && (!a || n == 0 || memcmp(a, b, n) == 0);
}

static bool same_double(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

static bool same_branch(const struct branch *a, const struct branch *b)
{
	return a->id == b->id && a->parent == b->parent && same_double(a->parent_t, b->parent_t) &&
	       a->generation == b->generation && a->level == b->level && a->origin == b->origin &&
	       a->npoints == b->npoints && same_bytes(a->points, b->points, a->npoints * sizeof(*a->points)) &&
	       same_bytes(a->radii, b->radii, a->npoints * sizeof(*a->radii));
}

static bool same_leaf(const struct leaf *a, const struct leaf *b)
{
	return a->id == b->id && a->branch == b->branch && same_double(a->branch_t, b->branch_t) &&
	       a->origin == b->origin && a->kind == b->kind && a->npoints == b->npoints &&
	       same_bytes(a->points, b->points, a->npoints * sizeof(*a->points)) &&
	       same_bytes(a->local, b->local, a->npoints * sizeof(*a->local));
}

static bool same_vine(const struct vine *a, const struct vine *b)
{
	if (memcmp(&a->p, &b->p, sizeof(a->p)) != 0 || memcmp(&a->plant, &b->plant, sizeof(a->plant)) != 0 ||
	    a->nshoots != b->nshoots || a->active != b->active || a->next_bud != b->next_bud ||
	    a->points != b->points || a->steps != b->steps)
		return false;
	for (size_t i = 0; i < a->nshoots; i++) {
		const struct vine_shoot *x = &a->shoots[i], *y = &b->shoots[i];

		if (x->parent != y->parent || x->node != y->node || x->n != y->n ||
		    x->free_until != y->free_until || x->pivot != y->pivot ||
		    !same_double(x->azimuth, y->azimuth) || x->since_touch != y->since_touch ||
		    x->leaves_lost != y->leaves_lost || x->stopped != y->stopped ||
		    !same_bytes(x->axis, y->axis, x->n * sizeof(*x->axis)) ||
		    !same_bytes(x->contact, y->contact, x->n * sizeof(*x->contact)))
			return false;
	}
	return true;
}

static bool same_vines(const struct tree *a, const struct tree *b)
{
	if (a->nvines != b->nvines)
		return false;
	for (size_t i = 0; i < a->nvines; i++)
		if (!same_vine(&a->vines[i], &b->vines[i]))
			return false;
	return true;
}

int tree_delta_diff(struct tree_delta *d, struct tree *before, const struct tree *t)
{
	struct tree_delta_side *b0 = &d->side[0], *b1 = &d->side[1];
	size_t mb = before->nbranches < t->nbranches ? before->nbranches : t->nbranches;
	size_t ml = before->nleaves < t->nleaves ? before->nleaves : t->nleaves;
	bool *diff_b = calloc(mb + 1, sizeof(*diff_b)), *diff_l = calloc(ml + 1, sizeof(*diff_l));
	size_t nb = 0, nl = 0;
	bool vines;
	int ret = -ENOMEM;

	if (!diff_b || !diff_l)
		goto out;
	for (size_t i = 0; i < mb; i++)
		nb += diff_b[i] = !same_branch(&before->branches[i], &t->branches[i]);
	for (size_t i = 0; i < ml; i++)
		nl += diff_l[i] = !same_leaf(&before->leaves[i], &t->leaves[i]);
	if (side_lists(b0, nb + before->nbranches - mb, nl + before->nleaves - ml) < 0 ||
	    side_lists(b1, nb + t->nbranches - mb, nl + t->nleaves - ml) < 0)
		goto out;
	b0->branches = malloc((nb + before->nbranches - mb + 1) * sizeof(*b0->branches));
	b0->leaves = malloc((nl + before->nleaves - ml + 1) * sizeof(*b0->leaves));
	vines = same_vines(before, t);
	if (!b0->branches || !b0->leaves)
		goto out;

	/* from here on nothing fails: before's differing elements move to the delta */
	b0->nbranches = before->nbranches;
	b0->nleaves = before->nleaves;
	b0->nvines = before->nvines;
	b1->nbranches = t->nbranches;
	b1->nleaves = t->nleaves;
	b1->nvines = t->nvines;
	b0->vines_from = b1->vines_from = vines ? t->nvines : 0;
	for (size_t i = 0; i < t->nbranches; i++)
		if (i >= mb || diff_b[i]) {
			b1->branch_at[b1->nb] = i;
			b1->branch_kept[b1->nb++] = i < mb;
		}
	for (size_t i = 0; i < t->nleaves; i++)
		if (i >= ml || diff_l[i]) {
			b1->leaf_at[b1->nl] = i;
			b1->leaf_kept[b1->nl++] = i < ml;
		}
	for (size_t i = 0; i < before->nbranches; i++) {
		struct branch *b = &before->branches[i];

		if (i < mb && !diff_b[i]) {
			free(b->points);
			free(b->radii);
			continue;
		}
		b0->branch_at[b0->nb] = i;
		b0->branch_kept[b0->nb] = i < mb;
		b0->branches[b0->nb++] = *b;
	}
	for (size_t i = 0; i < before->nleaves; i++) {
		struct leaf *l = &before->leaves[i];

		if (i < ml && !diff_l[i]) {
			free(l->points);
			free(l->local);
			continue;
		}
		b0->leaf_at[b0->nl] = i;
		b0->leaf_kept[b0->nl] = i < ml;
		b0->leaves[b0->nl++] = *l;
	}
	before->nbranches = 0;
	before->nleaves = 0;
	if (!vines && before->nvines) {
		b0->vines = before->vines; /* its array: the delta's now */
		before->vines = NULL;
		before->nvines = before->cap_vines = 0;
	}
	/* the wood is not compared: either side's, if there is one, is the side's own */
	d->wood = before->wood || t->wood;
	b0->wood = before->wood;
	before->wood = NULL;
	d->stored = 0;
	ret = 0;
out:
	if (ret < 0)
		tree_delta_finish(d);
	free(diff_b);
	free(diff_l);
	tree_finish(before);
	return ret;
}

int tree_delta_take_appended(struct tree_delta *d, struct tree *t, size_t nb, size_t nl)
{
	struct tree_delta_side *b0 = &d->side[0], *b1 = &d->side[1];
	size_t mb, ml;

	if (nb > t->nbranches || nl > t->nleaves)
		return -EINVAL;
	mb = t->nbranches - nb;
	ml = t->nleaves - nl;
	if (side_lists(b0, 0, 0) < 0 || side_lists(b1, mb, ml) < 0)
		goto fail;
	b1->branches = malloc((mb ? mb : 1) * sizeof(*b1->branches));
	b1->leaves = malloc((ml ? ml : 1) * sizeof(*b1->leaves));
	if (!b1->branches || !b1->leaves)
		goto fail;
	b0->nbranches = nb;
	b0->nleaves = nl;
	b1->nbranches = t->nbranches;
	b1->nleaves = t->nleaves;
	b0->nvines = b1->nvines = b0->vines_from = b1->vines_from = t->nvines;
	for (size_t i = 0; i < mb; i++) {
		b1->branch_at[i] = nb + i;
		b1->branch_kept[i] = false;
	}
	for (size_t i = 0; i < ml; i++) {
		b1->leaf_at[i] = nl + i;
		b1->leaf_kept[i] = false;
	}
	b1->nb = mb;
	b1->nl = ml;
	if (mb)
		memcpy(b1->branches, t->branches + nb, mb * sizeof(*b1->branches));
	if (ml)
		memcpy(b1->leaves, t->leaves + nl, ml * sizeof(*b1->leaves));
	t->nbranches = nb;
	t->nleaves = nl;
	tree_index_truncated(t, nb);
	d->stored = 1;
	return 0;
fail:
	tree_delta_finish(d);
	return -ENOMEM;
}

/* ---- moving the tree between the sides ---- */

/*
 * For each element of side r (n_r of them, `at`/`kept` its list) the index of the same
 * element on side s, or -1 if r has it alone. False if the two lists do not describe one
 * correspondence: a different number of elements on both sides, or an element changed on
 * one side and shared on the other.
 */
static bool counterparts(const size_t *r_at, const bool *r_kept, size_t r_nl, size_t n_r,
			 const size_t *s_at, const bool *s_kept, size_t s_nl, size_t n_s, int *map)
{
	size_t p = 0, q = 0, i = 0;

	for (size_t j = 0; j < n_r; j++) {
		bool r_listed = p < r_nl && r_at[p] == j, s_listed;

		if (r_listed && !r_kept[p++]) {
			map[j] = -1;
			continue;
		}
		while (q < s_nl && s_at[q] == i && !s_kept[q]) {
			q++;
			i++;
		}
		if (i >= n_s)
			return false;
		s_listed = q < s_nl && s_at[q] == i;
		if (s_listed != r_listed)
			return false;
		q += s_listed;
		map[j] = (int)i++;
	}
	while (q < s_nl && s_at[q] == i && !s_kept[q]) {
		q++;
		i++;
	}
	return p == r_nl && q == s_nl && i == n_s;
}

void tree_delta_map(const struct tree_delta *d, int to, int *branch_from, int *leaf_from)
{
	const struct tree_delta_side *a = &d->side[to], *b = &d->side[!to];

	counterparts(a->branch_at, a->branch_kept, a->nb, a->nbranches, b->branch_at, b->branch_kept,
		     b->nb, b->nbranches, branch_from);
	counterparts(a->leaf_at, a->leaf_kept, a->nl, a->nleaves, b->leaf_at, b->leaf_kept, b->nl,
		     b->nleaves, leaf_from);
	for (size_t p = 0; p < a->nb; p++)
		branch_from[a->branch_at[p]] = -1;
	for (size_t p = 0; p < a->nl; p++)
		leaf_from[a->leaf_at[p]] = -1;
}

int tree_delta_swap(struct tree_delta *d, struct tree *t, int *branch_from, int *leaf_from)
{
	struct tree_delta_side *s = &d->side[d->stored], *r = &d->side[!d->stored];
	int *map_b = NULL, *map_l = NULL, *index_map = NULL;
	struct branch *nb = NULL, *rb = NULL;
	struct leaf *nl = NULL, *rl = NULL;
	struct vine *rv = NULL;
	size_t nrv = r->nvines - r->vines_from, nsv = s->nvines - s->vines_from;
	int ret = -ENOMEM;

	if (t->nbranches != r->nbranches || t->nleaves != r->nleaves || t->nvines != r->nvines ||
	    r->vines_from != s->vines_from || r->vines_from > r->nvines || s->vines_from > s->nvines)
		return -EINVAL;
	map_b = malloc((r->nbranches + 1) * sizeof(*map_b));
	map_l = malloc((r->nleaves + 1) * sizeof(*map_l));
	index_map = malloc((r->nbranches + 1) * sizeof(*index_map));
	nb = malloc((s->nbranches + 1) * sizeof(*nb));
	nl = malloc((s->nleaves + 1) * sizeof(*nl));
	rb = malloc((r->nb + 1) * sizeof(*rb));
	rl = malloc((r->nl + 1) * sizeof(*rl));
	rv = malloc((nrv + 1) * sizeof(*rv));
	if (!map_b || !map_l || !index_map || !nb || !nl || !rb || !rl || !rv)
		goto out;
	if (s->nvines > t->cap_vines) {
		struct vine *v = realloc(t->vines, s->nvines * sizeof(*v));

		if (!v)
			goto out;
		t->vines = v;
		t->cap_vines = s->nvines;
	}
	if (s->nvines) /* the tree frees and copies them from now on, if it never had any */
		t->vine_ops = &vine_tree_ops;
	ret = -EINVAL;
	if (!counterparts(r->branch_at, r->branch_kept, r->nb, r->nbranches, s->branch_at,
			  s->branch_kept, s->nb, s->nbranches, map_b) ||
	    !counterparts(r->leaf_at, r->leaf_kept, r->nl, r->nleaves, s->leaf_at, s->leaf_kept, s->nl,
			  s->nleaves, map_l))
		goto out;
	/* what is shared hangs on what is on both sides */
	for (size_t p = 0, j = 0; j < r->nbranches; j++) {
		int parent = t->branches[j].parent;

		if (p < r->nb && r->branch_at[p] == j) {
			p++;
			continue;
		}
		if (parent >= 0 && ((size_t)parent >= j || map_b[parent] < 0))
			goto out;
	}
	for (size_t p = 0, j = 0; j < r->nleaves; j++) {
		int b = t->leaves[j].branch;

		if (p < r->nl && r->leaf_at[p] == j) {
			p++;
			continue;
		}
		if (b < 0 || (size_t)b >= r->nbranches || map_b[b] < 0)
			goto out;
	}

	/* nothing fails from here on */
	for (size_t j = 0; j < r->nbranches; j++)
		index_map[j] = map_b[j];
	for (size_t i = 0; i < s->nbranches; i++)
		branch_from[i] = -1;
	for (size_t i = 0; i < s->nleaves; i++)
		leaf_from[i] = -1;
	for (size_t p = 0, j = 0; j < r->nbranches; j++) {
		struct branch b = t->branches[j];

		if (p < r->nb && r->branch_at[p] == j) {
			rb[p++] = b;
			index_map[j] = -1; /* its points may differ */
			continue;
		}
		b.id = map_b[j];
		b.parent = b.parent >= 0 ? map_b[b.parent] : -1;
		nb[map_b[j]] = b;
		branch_from[map_b[j]] = (int)j;
	}
	for (size_t q = 0; q < s->nb; q++)
		nb[s->branch_at[q]] = s->branches[q];
	for (size_t p = 0, j = 0; j < r->nleaves; j++) {
		struct leaf l = t->leaves[j];

		if (p < r->nl && r->leaf_at[p] == j) {
			rl[p++] = l;
			continue;
		}
		l.id = map_l[j];
		l.branch = map_b[l.branch];
		nl[map_l[j]] = l;
		leaf_from[map_l[j]] = (int)j;
	}
	for (size_t q = 0; q < s->nl; q++)
		nl[s->leaf_at[q]] = s->leaves[q];
	if (nrv)
		memcpy(rv, t->vines + r->vines_from, nrv * sizeof(*rv));
	if (nsv)
		memcpy(t->vines + s->vines_from, s->vines, nsv * sizeof(*s->vines));
	if (d->wood) {
		struct wood *w = t->wood;

		t->wood = s->wood;
		s->wood = NULL;
		r->wood = w;
		if (t->wood)
			t->wood_ops = &wood_tree_ops;
	}

	free(t->branches);
	free(t->leaves);
	t->branches = nb;
	t->leaves = nl;
	t->nbranches = t->cap_branches = s->nbranches;
	t->nleaves = t->cap_leaves = s->nleaves;
	t->nvines = s->nvines;
	nb = NULL;
	nl = NULL;
	free(s->branches);
	free(s->leaves);
	free(s->vines);
	s->branches = NULL;
	s->leaves = NULL;
	s->vines = NULL;
	r->branches = rb;
	r->leaves = rl;
	r->vines = rv;
	rb = NULL;
	rl = NULL;
	rv = NULL;
	d->stored = !d->stored;
	tree_index_replaced(t, index_map, r->nbranches);
	ret = 0;
out:
	free(map_b);
	free(map_l);
	free(index_map);
	free(nb);
	free(nl);
	free(rb);
	free(rl);
	free(rv);
	return ret;
}
