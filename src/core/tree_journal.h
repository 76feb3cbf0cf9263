/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "tree.h"

/*
 * The hooks through which tree.c and tree_edit.c tell an undo journal what their edits
 * take out or change. The journal (tree_delta.c, on the drawing's floor above the core)
 * sets t->journal and t->journal_ops when it begins (tree_journal_begin); t->journal is
 * NULL again once it ends, and without one every hook is a no-op. What each hook means is in
 * tree_delta.h ("Journals").
 */
struct tree_journal_ops {
	int (*branch)(struct tree *t, size_t i, bool keep);
	int (*leaf)(struct tree *t, size_t i, bool keep);
	void (*branches_moved)(struct tree *t, const int *map, size_t nold);
	void (*leaves_moved)(struct tree *t, const int *map, size_t nold);
	void (*clear)(struct tree *t);
	void (*truncate)(struct tree *t, size_t nb, size_t nl);
	int (*keep_cut)(struct tree *t, int b, double cut_t);
	void (*fail)(struct tree *t);
	bool (*take_wood)(struct tree *t);
	void (*discard)(struct tree *t);
};

static inline int tree_journal_branch(struct tree *t, size_t i, bool keep)
{
	return t->journal ? t->journal_ops->branch(t, i, keep) : 0;
}

static inline int tree_journal_leaf(struct tree *t, size_t i, bool keep)
{
	return t->journal ? t->journal_ops->leaf(t, i, keep) : 0;
}

static inline void tree_journal_branches_moved(struct tree *t, const int *map, size_t nold)
{
	if (t->journal)
		t->journal_ops->branches_moved(t, map, nold);
}

static inline void tree_journal_leaves_moved(struct tree *t, const int *map, size_t nold)
{
	if (t->journal)
		t->journal_ops->leaves_moved(t, map, nold);
}

static inline void tree_journal_clear(struct tree *t)
{
	if (t->journal)
		t->journal_ops->clear(t);
}

static inline void tree_journal_truncate(struct tree *t, size_t nb, size_t nl)
{
	if (t->journal)
		t->journal_ops->truncate(t, nb, nl);
}

static inline int tree_journal_keep_cut(struct tree *t, int b, double cut_t)
{
	return t->journal ? t->journal_ops->keep_cut(t, b, cut_t) : 0;
}

static inline void tree_journal_fail(struct tree *t)
{
	if (t->journal)
		t->journal_ops->fail(t);
}

static inline bool tree_journal_wood(struct tree *t)
{
	return t->journal ? t->journal_ops->take_wood(t) : false;
}

static inline void tree_journal_discard(struct tree *t)
{
	if (t->journal)
		t->journal_ops->discard(t);
}
