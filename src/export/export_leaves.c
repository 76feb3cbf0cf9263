/* SPDX-License-Identifier: MIT */
#include "export_leaves.h"

#include "leaf_colors.h"

_Static_assert(SEASON_MAX_COLORS <= 16, "export_leaves_colors_used keeps a bit a colour");

enum export_look export_look(enum season s)
{
	if (!season_shows_leaves(s))
		return EXPORT_LEAVES_NONE;
	/* a palette of one colour is summer's green: the material the files always had */
	return leaf_colors_vary(s) ? EXPORT_LEAVES_COLORED : EXPORT_LEAVES_GREEN;
}

/* Whether mk cuts m into t's leaves, in order, each of whole triangles. Checked once per
 * export so that a part never reaches outside the mesh, whatever the marks say. */
static bool marks_describe(const struct tree_mesh_marks *mk, const struct tree *t,
			   const struct mesh *m)
{
	if (!mk || mk->nleaves != t->nleaves + 1 || !mk->leaves)
		return false;
	if (mk->leaves[0].nvertices != 0 || mk->leaves[0].nindices != 0 ||
	    mk->leaves[t->nleaves].nvertices != m->nvertices ||
	    mk->leaves[t->nleaves].nindices != m->nindices)
		return false;
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct tree_mesh_mark *a = &mk->leaves[i], *b = &mk->leaves[i + 1];

		if (a->nvertices > b->nvertices || a->nindices > b->nindices ||
		    (b->nindices - a->nindices) % 3 != 0)
			return false;
	}
	return true;
}

void export_leaves_init(struct export_leaves *el, const struct tree *t, const struct mesh *leaves,
			const struct tree_mesh_marks *mk)
{
	el->tree = t;
	el->mesh = leaves;
	el->ncolors = season_palette(t->season, &el->palette);
	el->marks = marks_describe(mk, t, leaves) ? mk : NULL;
}

size_t export_leaves_nparts(const struct export_leaves *el)
{
	return el->marks ? el->tree->nleaves : 1;
}

struct export_leaf_part export_leaves_part(const struct export_leaves *el, size_t i)
{
	const struct tree_mesh_mark *a, *b;

	if (!el->marks)
		return (struct export_leaf_part){ 0, el->mesh->nvertices, 0, el->mesh->nindices, 0 };
	a = &el->marks->leaves[i];
	b = &el->marks->leaves[i + 1];
	return (struct export_leaf_part){
		a->nvertices, b->nvertices, a->nindices, b->nindices,
		season_leaf_color(el->tree->season, &el->tree->leaves[i]),
	};
}

unsigned export_leaves_colors_used(const struct export_leaves *el)
{
	unsigned used = 0;
	size_t n = export_leaves_nparts(el);

	if (el->ncolors == 0)
		return 0;
	for (size_t i = 0; i < n; i++) {
		struct export_leaf_part p = export_leaves_part(el, i);

		if (p.end_index > p.first_index)
			used |= 1u << p.color;
	}
	return used;
}
