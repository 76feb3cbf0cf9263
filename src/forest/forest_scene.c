/* SPDX-License-Identifier: MIT */
/*
 * The forest as the screen draws it (docs/forest.md, "Drawing it fast enough"): each
 * tree's level of detail with its living data (a part, built once on the planting
 * thread), and the standing trees placed and merged into one bark and one leaves mesh
 * (the scene, rebuilt when a tree joins or leaves: a concatenation).
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "rng.h"

void forest_part_init(struct forest_part *p)
{
	memset(p, 0, sizeof(*p));
	tree_mesh_init(&p->mesh);
	live_attrs_init(&p->bark);
	live_attrs_init(&p->leaves);
}

void forest_part_finish(struct forest_part *p)
{
	tree_mesh_finish(&p->mesh);
	free(p->colors.rgb);
	live_attrs_finish(&p->bark);
	live_attrs_finish(&p->leaves);
	forest_part_init(p);
}

/* The trunk's foot: the first point of the first branch without a parent. */
static struct vec3 foot_of(const struct tree *t)
{
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent < 0 && t->branches[i].npoints)
			return t->branches[i].points[0];
	return t->branches[0].points[0];
}

int forest_part_build(struct forest_part *p, const struct tree *t, uint64_t seed,
		      size_t budget, double strength)
{
	struct live_skeleton sk;
	struct live_wind_params wp = { .strength = strength, .angle = 0.0,
				       .loop = LIVE_WIND_COMMON_LOOP_S };
	struct forest_lod_stats st;
	struct vec3 foot;
	struct rng r;
	int ret;

	forest_part_finish(p);
	if (t->nbranches == 0 || !(strength >= 0.0 && strength <= 1.0))
		return -EINVAL;
	ret = forest_lod_build_colors(t, budget, &p->mesh, &p->colors, &st);
	if (ret < 0)
		goto fail;
	ret = live_skeleton_init(&sk, t, seed);
	if (ret < 0)
		goto fail;
	ret = live_wind_setup(&p->wind, &sk, &wp);
	if (ret == 0)
		ret = live_attrs_bind_nearest(&p->bark, &sk, t, &p->mesh.bark);
	if (ret == 0)
		ret = live_attrs_bind_nearest(&p->leaves, &sk, t, &p->mesh.leaves);
	live_skeleton_finish(&sk);
	if (ret < 0)
		goto fail;
	foot = foot_of(t);
	p->foot[0] = foot.x;
	p->foot[1] = foot.y;
	p->foot[2] = foot.z;
	p->height = forest_tree_height(t);
	p->crown_width = forest_tree_crown_width(t);
	p->branches = t->nbranches;
	p->leaves_drawn = t->nleaves;
	p->bark_stems = st.stem_vertices <= p->mesh.bark.nvertices ? st.stem_vertices : 0;
	p->amp0 = p->wind.amp0;
	p->harmonic0 = p->wind.harmonic[0];
	/* the trunk's phase from the drawing's seed: trees side by side do not sway as one */
	rng_seed(&r, seed ^ 0x6f72657374ull);
	p->phase0 = (uint8_t)(rng_next(&r) >> 56);
	return 0;
fail:
	forest_part_finish(p);
	return ret;
}

void forest_scene_init(struct forest_scene *s)
{
	memset(s, 0, sizeof(*s));
	tree_mesh_init(&s->mesh);
	live_attrs_init(&s->bark);
	live_attrs_init(&s->leaves);
}

void forest_scene_finish(struct forest_scene *s)
{
	uint64_t serial = s->serial;

	free(s->trees);
	tree_mesh_finish(&s->mesh);
	free(s->leaf_rgb);
	live_attrs_finish(&s->bark);
	live_attrs_finish(&s->leaves);
	free(s->bark_trunk);
	free(s->leaves_trunk);
	free(s->bark_vine);
	forest_scene_init(s);
	s->serial = serial;
}

static int grow(void **p, size_t *cap, size_t n, size_t size)
{
	void *q;

	if (n <= *cap)
		return 0;
	if (n > SIZE_MAX / size)
		return -ENOMEM;
	q = realloc(*p, n * size);
	if (!q)
		return -ENOMEM;
	*p = q;
	*cap = n;
	return 0;
}

/* Part mesh `from` placed by `shift` onto `to`; its living data onto `live` with w0 scaled,
 * its trunk's numbers onto trunk. */
static int place(struct mesh *to, struct live_attrs *live, uint8_t **trunk, size_t *cap_trunk,
		 const struct mesh *from, const struct live_attrs *data, const double shift[3],
		 double w0_scale, const struct forest_part *p)
{
	size_t v0 = to->nvertices, i0 = to->nindices;
	int ret;

	if (from->nvertices > UINT32_MAX - v0 || data->n != from->nvertices)
		return -EINVAL;
	ret = mesh_reserve(to, from->nvertices, from->nindices);
	if (ret == 0)
		ret = grow((void **)&live->v, &live->cap, v0 + from->nvertices + 1, sizeof(*live->v));
	if (ret == 0)
		ret = grow((void **)trunk, cap_trunk, 2 * (v0 + from->nvertices) + 2, 1);
	if (ret < 0)
		return ret;
	for (size_t v = 0; v < from->nvertices; v++) {
		struct live_vertex lv = data->v[v];

		for (int k = 0; k < 3; k++) {
			to->positions[3 * (v0 + v) + k] = (float)(from->positions[3 * v + k] + shift[k]);
			to->normals[3 * (v0 + v) + k] = from->normals[3 * v + k];
			lv.point[k] = (float)(lv.point[k] + shift[k]);
		}
		lv.w[0] = (float)(lv.w[0] * w0_scale);
		live->v[v0 + v] = lv;
		(*trunk)[2 * (v0 + v)] = (uint8_t)(p->harmonic0 > 255 ? 255 : p->harmonic0);
		(*trunk)[2 * (v0 + v) + 1] = p->phase0;
	}
	for (size_t i = 0; i < from->nindices; i++)
		to->indices[i0 + i] = from->indices[i] + (uint32_t)v0;
	to->nvertices = v0 + from->nvertices;
	to->nindices = i0 + from->nindices;
	live->n = to->nvertices;
	return 0;
}

/*
 * A part's growing in: live_grow_setup's rule from the farthest path length any of its
 * vertices is bound to (what the screen draws of the tree: its level of detail may have
 * left the skeleton's farthest twig out). A float d is what the shader compares, so the
 * growth's end is past every one of them.
 */
static void grow_of(const struct forest_part *p, struct live_grow *g)
{
	struct live_skeleton sk = { .d_max = 0.0 }; /* live_grow_setup reads its d_max only */

	for (size_t v = 0; v < p->bark.n; v++)
		sk.d_max = fmax(sk.d_max, p->bark.v[v].d);
	for (size_t v = 0; v < p->leaves.n; v++)
		sk.d_max = fmax(sk.d_max, p->leaves.v[v].d);
	live_grow_setup(g, &sk);
}

int forest_scene_build(struct forest_scene *s, const struct forest_part *const *parts,
		       const uint64_t *numbers, const double *positions, size_t n)
{
	double ref, lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bool colored = false, vines = false;
	int ret = 0;

	forest_scene_finish(s);
	s->serial++;
	if (n == 0)
		return 0;
	ret = grow((void **)&s->trees, &s->cap_trees, n, sizeof(*s->trees));
	for (size_t i = 0; i < n; i++) {
		colored = colored || parts[i]->colors.n > 0;
		vines = vines || parts[i]->bark_stems > 0;
	}
	/* the frame's wind is the tree that sways most's: every other w0 scales down to its
	 * own sway (a weight stays within 0..1, as the screen packs it) */
	{
		size_t most = 0;

		for (size_t i = 1; i < n; i++)
			if (parts[i]->amp0 > parts[most]->amp0)
				most = i;
		s->wind = parts[most]->wind;
		ref = parts[most]->amp0 > 0.0 ? parts[most]->amp0 : 1.0;
	}
	for (size_t i = 0; i < n && ret == 0; i++) {
		const struct forest_part *p = parts[i];
		struct forest_scene_tree *t = &s->trees[i];
		double shift[3];
		size_t l0 = s->mesh.leaves.nvertices;

		for (int k = 0; k < 3; k++)
			shift[k] = positions[3 * i + k] - p->foot[k];
		*t = (struct forest_scene_tree){ .number = numbers[i], .height = p->height,
						 .crown_width = p->crown_width };
		memcpy(t->position, &positions[3 * i], sizeof(t->position));
		grow_of(p, &t->grow);
		t->bark_vertices[0] = s->mesh.bark.nvertices;
		t->bark_indices[0] = s->mesh.bark.nindices;
		t->leaves_vertices[0] = l0;
		t->leaves_indices[0] = s->mesh.leaves.nindices;
		ret = place(&s->mesh.bark, &s->bark, &s->bark_trunk, &s->cap_bark_trunk,
			    &p->mesh.bark, &p->bark, shift, p->amp0 / ref, p);
		if (ret == 0)
			ret = place(&s->mesh.leaves, &s->leaves, &s->leaves_trunk,
				    &s->cap_leaves_trunk, &p->mesh.leaves, &p->leaves, shift,
				    p->amp0 / ref, p);
		if (ret == 0 && colored) {
			size_t nv = s->mesh.leaves.nvertices, cap = nv;
			float *rgb = realloc(s->leaf_rgb, 3 * cap * sizeof(*rgb) + 1);

			if (!rgb) {
				ret = -ENOMEM;
				break;
			}
			s->leaf_rgb = rgb;
			for (size_t v = l0; v < nv; v++)
				for (int k = 0; k < 3; k++)
					rgb[3 * v + k] = p->colors.n == p->mesh.leaves.nvertices
								 ? p->colors.rgb[3 * (v - l0) + k]
								 : 0.0f;
		}
		if (ret == 0 && vines) {
			size_t nv = s->mesh.bark.nvertices, b0 = t->bark_vertices[0];
			uint8_t *flag = realloc(s->bark_vine, nv + 1);

			if (!flag) {
				ret = -ENOMEM;
				break;
			}
			s->bark_vine = flag;
			for (size_t v = b0; v < nv; v++)
				flag[v] = v >= nv - p->bark_stems;
		}
		t->bark_vertices[1] = s->mesh.bark.nvertices;
		t->bark_indices[1] = s->mesh.bark.nindices;
		t->leaves_vertices[1] = s->mesh.leaves.nvertices;
		t->leaves_indices[1] = s->mesh.leaves.nindices;
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], positions[3 * i + k]);
			hi[k] = fmax(hi[k], positions[3 * i + k]);
		}
		s->top = fmax(s->top, positions[3 * i + 1] + p->height);
	}
	if (ret < 0) {
		forest_scene_finish(s);
		return ret;
	}
	s->ntrees = n;
	for (int k = 0; k < 3; k++)
		s->center[k] = 0.5 * (lo[k] + hi[k]);
	for (size_t i = 0; i < n; i++)
		s->radius = fmax(s->radius, hypot(positions[3 * i] - s->center[0],
						  positions[3 * i + 2] - s->center[2]) +
						    0.5 * parts[i]->crown_width);
	return 0;
}
