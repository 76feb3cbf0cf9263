/* SPDX-License-Identifier: MIT */
#include "sketch_seen.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tree_index.h"

struct vec3 sketch_seen_pivot(const struct tree *t)
{
	if (t->nbranches == 0 || t->branches[0].npoints == 0)
		return vec3(0, 0, 0);
	return t->branches[0].points[0];
}

/* Turns branch i's points, or leaf i's, into the pool. */
static void show_one(struct sketch_seen *sv, bool leaf, size_t i)
{
	struct vec3 *to, **points;
	const struct vec3 *from;
	size_t n;

	if (leaf) {
		points = &sv->shadow.leaves[i].points;
		from = sv->world->leaves[i].points;
		n = sv->shadow.leaves[i].npoints;
		to = sv->pool + sv->at[sv->nbranches + i];
	} else {
		points = &sv->shadow.branches[i].points;
		from = sv->world->branches[i].points;
		n = sv->shadow.branches[i].npoints;
		to = sv->pool + sv->at[i];
	}
	if (*points)
		return;
	for (size_t j = 0; j < n; j++)
		to[j] = camera_to_view(&sv->xf, from[j]);
	*points = to;
}

void sketch_seen_show_all(struct sketch_seen *sv)
{
	if (!sv->lazy)
		return;
	for (size_t i = 0; i < sv->shadow.nbranches; i++)
		show_one(sv, false, i);
	for (size_t i = 0; i < sv->shadow.nleaves; i++)
		show_one(sv, true, i);
	sv->lazy = false;
}

/* tree_index asks for a branch it found, or for all of them before a scan. */
static void show(void *ctx, int branch)
{
	struct sketch_seen *sv = ctx;

	if (branch < 0)
		sketch_seen_show_all(sv);
	else if (sv->lazy && (size_t)branch < sv->shadow.nbranches)
		show_one(sv, false, (size_t)branch);
}

int sketch_seen_init(struct sketch_seen *sv, const struct tree *t, struct camera c)
{
	size_t n = 0, k = 0;
	struct tree *s = &sv->shadow;

	memset(sv, 0, sizeof(*sv));
	camera_xf_init(&sv->xf, c, sketch_seen_pivot(t));
	sv->tree = t;
	sv->world = t;
	if (sv->xf.identity)
		return 0;
	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].npoints;
	for (size_t i = 0; i < t->nleaves; i++)
		n += t->leaves[i].npoints;
	*s = *t;
	s->index = NULL; /* t's, not the copy's */
	s->vines = NULL; /* t's, and no stroke lands on a vine */
	s->nvines = s->cap_vines = 0;
	s->branches = malloc((t->nbranches ? t->nbranches : 1) * sizeof(*s->branches));
	s->leaves = malloc((t->nleaves ? t->nleaves : 1) * sizeof(*s->leaves));
	sv->pool = malloc((n ? n : 1) * sizeof(*sv->pool));
	sv->at = malloc((t->nbranches + t->nleaves + 1) * sizeof(*sv->at));
	if (!s->branches || !s->leaves || !sv->pool || !sv->at) {
		sketch_seen_finish(sv);
		return -ENOMEM;
	}
	s->cap_branches = t->nbranches;
	s->cap_leaves = t->nleaves;
	for (size_t i = 0; i < t->nbranches; i++) {
		s->branches[i] = t->branches[i];
		s->branches[i].points = NULL;
		sv->at[i] = k;
		k += t->branches[i].npoints;
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		s->leaves[i] = t->leaves[i];
		s->leaves[i].local = NULL;
		s->leaves[i].points = NULL;
		sv->at[t->nbranches + i] = k;
		k += t->leaves[i].npoints;
	}
	sv->tree = s;
	sv->nbranches = t->nbranches;
	sv->lazy = true;
	if (!tree_index_keep_view(s, t, &sv->xf, show, sv)) {
		sketch_seen_show_all(sv); /* no grid to ask: turned all at once, as scans need */
		return 0;
	}
	/* the two-outline test reads the last branch and what it hangs on */
	for (int b = (int)t->nbranches - 1, up = 0; b >= 0 && (size_t)up < t->nbranches; up++) {
		show_one(sv, false, (size_t)b);
		b = t->branches[b].parent < b ? t->branches[b].parent : -1;
	}
	return 0;
}

void sketch_seen_finish(struct sketch_seen *sv)
{
	/* the shadow borrows radii from the tree: only its own arrays are freed */
	tree_index_destroy(&sv->shadow);
	free(sv->shadow.branches);
	free(sv->shadow.leaves);
	free(sv->pool);
	free(sv->at);
	memset(&sv->shadow, 0, sizeof(sv->shadow));
	sv->pool = NULL;
	sv->at = NULL;
	sv->tree = NULL;
}

void sketch_seen_drop_last_branch(struct sketch_seen *sv)
{
	if (sv->tree == &sv->shadow && sv->shadow.nbranches > 0)
		sv->shadow.nbranches--;
}

/* Distance in x/y from q to segment a-b. */
static double segment_distance(struct vec3 q, struct vec3 a, struct vec3 b)
{
	double dx = b.x - a.x, dy = b.y - a.y, dd = dx * dx + dy * dy;
	double s = dd > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / dd : 0.0;

	s = s < 0 ? 0 : s > 1 ? 1 : s;
	return hypot(a.x + s * dx - q.x, a.y + s * dy - q.y);
}

static bool inside(const struct vec3 *p, size_t n, struct vec3 q)
{
	bool in = false;

	for (size_t i = 0, j = n - 1; i < n; j = i++)
		if ((p[i].y > q.y) != (p[j].y > q.y) &&
		    q.x < (p[j].x - p[i].x) * (q.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
			in = !in;
	return in;
}

static bool polyline_near(const struct camera_xf *xf, const struct vec3 *pts, size_t n, bool closed,
			  struct vec3 p, double r)
{
	struct vec3 first, prev;

	if (n == 0)
		return false;
	first = prev = camera_to_view(xf, pts[0]);
	if (n == 1)
		return hypot(first.x - p.x, first.y - p.y) <= r;
	for (size_t i = 1; i <= n; i++) {
		struct vec3 q;

		if (i == n && !closed)
			break;
		q = i == n ? first : camera_to_view(xf, pts[i]);
		if (segment_distance(p, prev, q) <= r)
			return true;
		prev = q;
	}
	return false;
}

bool sketch_seen_near(const struct tree *t, struct camera c, struct vec3 p, double r)
{
	struct camera_xf xf;

	camera_xf_init(&xf, c, sketch_seen_pivot(t));
	for (size_t i = 0; i < t->nbranches; i++)
		if (polyline_near(&xf, t->branches[i].points, t->branches[i].npoints, false, p, r))
			return true;
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];

		if (polyline_near(&xf, l->points, l->npoints, true, p, r))
			return true;
		if (l->npoints >= 3) {
			/* inside a leaf counts as on it; a leaf is small, so copying it is cheap */
			struct vec3 poly[64];
			size_t n = l->npoints < 64 ? l->npoints : 64;

			for (size_t k = 0; k < n; k++)
				poly[k] = camera_to_view(&xf, l->points[k * l->npoints / n]);
			if (inside(poly, n, p))
				return true;
		}
	}
	return false;
}

double sketch_seen_clearance(struct sketch_seen *sv, struct vec3 p)
{
	const struct tree *t = sv->tree;
	double best = INFINITY;

	sketch_seen_show_all(sv);
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		if (b->npoints == 1)
			best = fmin(best, hypot(b->points[0].x - p.x, b->points[0].y - p.y));
		for (size_t j = 0; j + 1 < b->npoints; j++)
			best = fmin(best, segment_distance(p, b->points[j], b->points[j + 1]));
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];

		if (l->npoints == 0)
			continue;
		if (l->npoints >= 3 && inside(l->points, l->npoints, p))
			return 0.0;
		for (size_t j = 0; j < l->npoints; j++)
			best = fmin(best, segment_distance(p, l->points[j], l->points[(j + 1) % l->npoints]));
	}
	return best;
}
