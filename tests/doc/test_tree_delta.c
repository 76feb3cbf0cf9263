/* SPDX-License-Identifier: MIT */
/*
 * tree_delta.h and tree_mesh_update (src/doc/tree_delta.c, src/mesh/mesh_update.c) on 400 seeded
 * random trees and edits: whatever a journal saw (branches and leaves removed, cut,
 * appended, truncated, cleared and drawn anew, leaves re-attached and moved, vines added)
 * or a comparison found (points, radii and leaves changed in place, elements appended or
 * dropped at the end), swapping the tree to the delta's other side gives back the tree
 * before, bit for bit, and swapping again the tree after, any number of times. Meshes
 * updated in place at each swap (parts kept, stashed or built) are the bytes a full
 * build makes. An undo or redo that brings vines or a wood into a tree that never held
 * any sets their hooks on it (tree.h), so that the tree counts, copies and frees them.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "rng.h"
#include "synth_tree.h"
#include "synth_wood.h"
#include "same.h"
#include "test.h"
#include "tree_delta.h"
#include "vine.h"
#include "wood.h"

static long swaps, stashed_parts, built_parts, kept_parts;

static void copy(struct tree *dst, const struct tree *src)
{
	tree_init(dst);
	CHECK_INT(tree_copy(dst, src), 0);
}

static void add_vine(struct tree *t, struct rng *r)
{
	struct vine_params p = { .internode = 0.1, .radius = 0.002 };
	struct vine v;

	vine_init(&v, &p, vec3(rng_range(r, -1, 1), 0, 0));
	CHECK_INT(vine_attach(t, &v), 0);
	vine_finish(&v);
}

/* An edit the journal sees, at random: what the ops of tree.c and tree_edit.c do. */
static void journaled_edit(struct tree *t, struct rng *r)
{
	int n = 1 + (int)(rng_next(r) % 3);

	for (int e = 0; e < n && t->nbranches > 1; e++) {
		switch (rng_next(r) % 8) {
		case 0: { /* branches removed, with what hangs on them */
			bool *remove = calloc(t->nbranches, sizeof(*remove));

			CHECK(remove);
			for (int k = 0; k < 2; k++)
				remove[1 + rng_next(r) % (t->nbranches - 1)] = true;
			CHECK_INT(tree_remove_branches(t, remove), 0);
			free(remove);
			break;
		}
		case 1: { /* leaves removed */
			bool *remove = calloc(t->nleaves + 1, sizeof(*remove));

			CHECK(remove);
			for (size_t i = 0; i < t->nleaves; i++)
				remove[i] = rng_next(r) % 4 == 0;
			tree_remove_leaves(t, remove);
			free(remove);
			break;
		}
		case 2:
		case 3: { /* a cut */
			int b = (int)(rng_next(r) % t->nbranches);
			const struct branch *br = &t->branches[b];

			if (br->npoints >= 2)
				CHECK_INT(tree_cut_branch(t, b, rng_next(r) % (br->npoints - 1),
							  rng_uniform(r)), 0);
			break;
		}
		case 4: { /* appended: a copy of a branch on another, a leaf, then some cut back */
			const struct branch *src = &t->branches[rng_next(r) % t->nbranches];
			size_t nb = t->nbranches, nl = t->nleaves;

			CHECK(tree_add_branch(t, (int)(rng_next(r) % nb), rng_uniform(r), ORIGIN_CLONE,
					      src->points, src->radii, src->npoints) >= 0);
			if (nl)
				CHECK(tree_add_leaf(t, (int)nb, ORIGIN_SKETCH, t->leaves[0].points,
						    t->leaves[0].npoints) >= 0);
			if (rng_next(r) % 3 == 0)
				tree_truncate(t, nb, nl);
			break;
		}
		case 5: /* leaves attached to their branches again, and moved with them */
			for (size_t i = 0; i < t->nleaves; i++)
				if (rng_next(r) % 3 == 0)
					CHECK_INT(tree_leaf_attach(t, i), 0);
			if (rng_next(r) % 2)
				tree_leaves_follow(t, (int)(rng_next(r) % t->nbranches));
			break;
		case 6:
			add_vine(t, r);
			break;
		default: /* everything anew */
			tree_clear(t);
			CHECK_INT(synth_tree(t, 10 + (int)(rng_next(r) % 30), (int)(rng_next(r) % 2),
					     rng_next(r)), 0);
			if (rng_next(r) % 2)
				add_vine(t, r);
			break;
		}
	}
}

/* An edit in place that no journal sees (as lifting, arranging and growing wood do). */
static void in_place_edit(struct tree *t, struct rng *r)
{
	for (size_t i = 0; i < t->nbranches; i++) {
		struct branch *b = &t->branches[i];

		if (rng_next(r) % 4 == 0)
			for (size_t k = 0; k < b->npoints; k++)
				b->points[k].z += 0.1 * (double)(k + 1);
		else if (rng_next(r) % 5 == 0)
			b->radii[0] *= 0.9;
	}
	for (size_t i = 0; i < t->nleaves; i++)
		if (rng_next(r) % 3 == 0)
			t->leaves[i].points[0].x += 0.01;
	if (rng_next(r) % 2) {
		const struct branch *src = &t->branches[rng_next(r) % t->nbranches];

		CHECK(tree_add_branch(t, 0, 0.5, ORIGIN_CLONE, src->points, src->radii, src->npoints) >= 0);
	}
	if (rng_next(r) % 2)
		add_vine(t, r);
}

/*
 * t (at the side d does not hold, its meshes in tm/mk) moves to the other side; the
 * meshes follow in place: the parts of shared elements whose parent and grandparent are
 * shared too are kept, the others come from `stash` (the side's listed parts, if kept
 * earlier) or are built. The listed parts t leaves go to `leaving`.
 */
static void swap(struct tree_delta *d, struct tree *t, struct tree_mesh *tm,
		 struct tree_mesh_marks *mk, struct tree_mesh stash[2], struct tree_mesh_marks smk[2],
		 bool have_stash[2])
{
	int s = d->stored;
	const struct tree_delta_side *to = &d->side[s], *from = &d->side[!s];
	int *fb = malloc((to->nbranches + 1) * sizeof(*fb)), *fl = malloc((to->nleaves + 1) * sizeof(*fl));
	int *pb = malloc((to->nbranches + 1) * sizeof(*pb)), *pl = malloc((to->nleaves + 1) * sizeof(*pl));
	struct tree_mesh_plan plan = { pb, pl, have_stash[s] ? &stash[s] : NULL, &smk[s] };
	struct tree_mesh full;
	size_t q = 0, built = 0;

	CHECK(fb && fl && pb && pl);
	CHECK_INT(tree_mesh_copy_parts(&stash[!s], &smk[!s], tm, mk, from->branch_at, from->nb,
				       from->leaf_at, from->nl), 0);
	have_stash[!s] = true;
	CHECK_INT(tree_delta_swap(d, t, fb, fl), 0);
	CHECK_INT(d->stored, !s);
	swaps++;
	for (size_t i = 0; i < t->nbranches; i++) {
		int p = t->branches[i].parent;
		bool listed = q < to->nb && to->branch_at[q] == i;
		bool up_ok = p < 0 || (fb[p] >= 0 && (t->branches[p].parent < 0 ||
						      fb[t->branches[p].parent] >= 0));

		pb[i] = fb[i] >= 0 && up_ok ? fb[i] : listed && have_stash[s] ? -2 - (int)q : TREE_MESH_BUILD;
		kept_parts += pb[i] >= 0;
		stashed_parts += pb[i] <= -2;
		q += listed;
	}
	q = 0;
	for (size_t i = 0; i < t->nleaves; i++) {
		bool listed = q < to->nl && to->leaf_at[q] == i;

		pl[i] = fl[i] >= 0 ? fl[i] : listed && have_stash[s] ? -2 - (int)q : TREE_MESH_BUILD;
		q += listed;
	}
	CHECK_INT(tree_mesh_update(tm, mk, t, &plan, &built), 0);
	built_parts += (long)built;
	tree_mesh_init(&full);
	CHECK_INT(tree_mesh_build(&full, t), 0);
	same_mesh(&tm->bark, &full.bark);
	same_mesh(&tm->leaves, &full.leaves);
	CHECK_INT(mk->nbark, t->nbranches + 1);
	CHECK_INT(mk->nleaves, t->nleaves + 1);
	tree_mesh_finish(&full);
	free(fb);
	free(fl);
	free(pb);
	free(pl);
}

static void check(uint64_t seed, bool journaled)
{
	struct tree t, before, after;
	struct tree_delta d;
	struct tree_mesh tm, stash[2];
	struct tree_mesh_marks mk, smk[2];
	bool have_stash[2] = { false, false };
	struct rng r;

	rng_seed(&r, seed);
	tree_init(&t);
	CHECK_INT(synth_tree(&t, 10 + (int)(rng_next(&r) % 60), (int)(rng_next(&r) % 3), seed), 0);
	/* leaves along their branches, so that cuts drop some and rescale the others */
	for (size_t i = 0; i < t.nleaves; i++)
		t.leaves[i].branch_t = rng_uniform(&r);
	if (rng_next(&r) % 3 == 0)
		add_vine(&t, &r);
	copy(&before, &t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	tree_delta_init(&d);
	if (journaled) {
		CHECK_INT(tree_journal_begin(&t), 0);
		journaled_edit(&t, &r);
		CHECK_INT(tree_journal_end(&t, &d), 0);
		CHECK(t.journal == NULL);
	} else {
		struct tree was;

		copy(&was, &t);
		in_place_edit(&t, &r);
		CHECK_INT(tree_delta_diff(&d, &was, &t), 0);
	}
	CHECK_INT(d.stored, 0);
	copy(&after, &t);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	for (int k = 0; k < 2; k++)
		tree_mesh_init(&stash[k]), tree_mesh_marks_init(&smk[k]);
	/* back and forth, twice: the stashes made on the way are used on the way back */
	for (int round = 0; round < 2; round++) {
		swap(&d, &t, &tm, &mk, stash, smk, have_stash);
		same_tree(&t, &before);
		swap(&d, &t, &tm, &mk, stash, smk, have_stash);
		same_tree(&t, &after);
	}
	tree_delta_finish(&d);
	tree_finish(&t);
	tree_finish(&before);
	tree_finish(&after);
	tree_mesh_finish(&tm);
	tree_mesh_marks_finish(&mk);
	for (int k = 0; k < 2; k++) {
		tree_mesh_finish(&stash[k]);
		tree_mesh_marks_finish(&smk[k]);
	}
}

/* A delta is not for a tree at other counts: refused, the tree untouched. */
static void check_refused(void)
{
	struct tree t, other;
	struct tree_delta d;
	int from[256];

	tree_init(&t);
	tree_init(&other);
	CHECK_INT(synth_tree(&t, 20, 1, 3), 0);
	CHECK_INT(synth_tree(&other, 30, 1, 4), 0);
	tree_delta_init(&d);
	CHECK_INT(tree_journal_begin(&t), 0);
	tree_clear(&t);
	CHECK_INT(tree_journal_end(&t, &d), 0);
	CHECK_INT(tree_delta_swap(&d, &other, from, from), -EINVAL);
	CHECK_INT(other.nbranches, 30);
	tree_delta_finish(&d);
	tree_finish(&t);
	tree_finish(&other);
}

/*
 * d swapped into `fresh`, a tree at the other side's counts that
 * never held vines nor wood (one rebuilt from its drawing): what comes back is the tree's
 * to count, copy and free (ASan sees a leak or a bad read otherwise).
 */
static void swap_into_fresh(struct tree_delta *d, struct tree *fresh)
{
	int bf[64], lf[64];
	struct tree c, bare;

	CHECK(fresh->vine_ops == NULL && fresh->wood_ops == NULL);
	CHECK(fresh->nbranches <= 64 && fresh->nleaves <= 64);
	CHECK_INT(tree_delta_swap(d, fresh, bf, lf), 0);
	/* counted: more than the same tree's view without them */
	bare = *fresh;
	bare.nvines = bare.cap_vines = 0;
	bare.wood = NULL;
	CHECK(tree_bytes(fresh) > tree_bytes(&bare));
	copy(&c, fresh);
	CHECK_INT(c.nvines, fresh->nvines);
	CHECK((c.wood == NULL) == (fresh->wood == NULL));
	for (size_t i = 0; i < fresh->nbranches; i++)
		CHECK(tree_branch_in_wood(&c, i) == tree_branch_in_wood(fresh, i));
	tree_finish(&c);
}

static void check_hooks_come_back(void)
{
	struct tree t, fresh;
	struct tree_delta d;
	struct wood_params p;
	struct rng r;
	int bf[64], lf[64];

	/* a vine planted under a journal, undone, then redone into a fresh tree */
	rng_seed(&r, 5);
	tree_init(&t);
	tree_init(&fresh);
	CHECK_INT(synth_wood_tree(&t, 0, WOOD_BROADLEAF), 0);
	CHECK_INT(synth_wood_tree(&fresh, 0, WOOD_BROADLEAF), 0);
	tree_delta_init(&d);
	CHECK_INT(tree_journal_begin(&t), 0);
	add_vine(&t, &r);
	CHECK_INT(tree_journal_end(&t, &d), 0);
	CHECK_INT(tree_delta_swap(&d, &t, bf, lf), 0); /* undone: the delta holds the vine */
	CHECK_INT(t.nvines, 0);
	swap_into_fresh(&d, &fresh);
	CHECK_INT(fresh.nvines, 1);
	tree_delta_finish(&d);
	tree_finish(&t);
	tree_finish(&fresh);

	/* a year of wood found by comparison, undone, then redone into a fresh tree */
	tree_init(&t);
	tree_init(&fresh);
	CHECK_INT(synth_wood_tree(&t, 0, WOOD_BROADLEAF), 0);
	CHECK_INT(synth_wood_tree(&fresh, 0, WOOD_BROADLEAF), 0);
	{
		struct tree before;

		copy(&before, &t);
		wood_params_default(&p);
		CHECK_INT(wood_grow(&t, &p), 0);
		CHECK(t.wood != NULL);
		tree_delta_init(&d);
		CHECK_INT(tree_delta_diff(&d, &before, &t), 0);
	}
	CHECK_INT(tree_delta_swap(&d, &t, bf, lf), 0); /* undone: the delta holds the wood */
	CHECK(t.wood == NULL);
	swap_into_fresh(&d, &fresh);
	CHECK(fresh.wood != NULL && tree_branch_in_wood(&fresh, 0));
	tree_delta_finish(&d);
	tree_finish(&t);
	tree_finish(&fresh);
}

int main(void)
{
	for (uint64_t seed = 1; seed <= 200; seed++) {
		check(seed, true);
		check(seed, false);
	}
	check_refused();
	check_hooks_come_back();
	fprintf(stderr, "400 edits, %ld swaps; parts kept %ld, stashed %ld, built %ld\n", swaps,
		kept_parts, stashed_parts, built_parts);
	CHECK(kept_parts > 0 && stashed_parts > 0 && built_parts > 0);
	return 0;
}
