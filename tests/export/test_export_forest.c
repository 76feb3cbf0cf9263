/* SPDX-License-Identifier: MIT */
/*
 * export_glb_forest (issue 27, docs/forest.md, "Headless and for the teacher"): forest.glb
 * read back. On 300 seeded random forests of 1 to 40 small trees (live_trees_random: 1 to
 * 12 branches, 0 to 3 leaves a branch, 3 to 15 m, every season; a few vine and grown
 * trees, a tree whose mesh has no branches to sway and an empty one among them), at
 * random places, strengths, angles, some with float targets:
 *
 * - the scene's root nodes are the trees in order, each named "tree-N" after its number,
 *   translated to its place;
 * - each node's mesh is that tree's model.glb mesh (export_glb_wind at the same wind and
 *   the tree's seed): the same primitives, materials (by name), and accessor for accessor
 *   the same bytes and bounds, morph targets included (they do not depend on the loop);
 *   an empty tree's node has no mesh;
 * - one animation "wind", a channel (the node's weights) and a sampler a tree with
 *   branches, none for the others; every sampler over [0, 8 s] exactly, its first and last
 *   keys equal, so the whole animation loops as one;
 * - played as glTF says (the Hermite spline, the byte targets), every vertex of every
 *   tree moves as live_wind_offset of its tree's wind over the common loop (bound as the
 *   renderer binds it) at 6 moments of the loop, within test_export_wind's tolerance:
 *
 *     |played - live| <= sqrt(3) sum_j s_j (1/254 + (2 pi m_j / N)^4 / 384 + 3e-5) + 1e-7 m
 *
 *   and the worst share of it is printed;
 * - the same trees give the same bytes; KHR_mesh_quantization is required exactly when
 *   some tree sways with byte targets.
 *
 * Also: no tree is a valid empty scene (model.glb's empty drawing, byte for byte); a still
 * forest (no wind) has each tree's export_glb mesh and no animation; bad parameters are
 * refused with out as it was.
 */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "export_vines.h"
#include "glb_read.h"
#include "glb_wind.h"
#include "live.h"
#include "live_trees.h"
#include "mesh.h"
#include "rng.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "test.h"
#include "tree.h"
#include "wood.h"

#define NT LIVE_WIND_TARGETS
#define LOOP LIVE_WIND_COMMON_LOOP_S
#define RANDOM_FORESTS 300
#define MAX_TREES 40

static const double moments[] = { 0.0, 0.0137, 0.25, 0.5, 0.8333, 1.0 };
#define NMOMENTS (sizeof(moments) / sizeof(*moments))

enum bind_kind { BIND_BARK, BIND_LEAVES, BIND_NEAREST };

/* model.glb's primitives: their names, how they are bound (as test_export_wind). */
static const char *const prim_names[] = { "bark", "wood", "leaves", "vine", "vine-leaves" };
static const enum bind_kind prim_bind[] = { BIND_BARK, BIND_NEAREST, BIND_LEAVES, BIND_NEAREST,
					    BIND_NEAREST };
#define NPRIMS (sizeof(prim_names) / sizeof(*prim_names))

/* A tree of a forest, its meshes as the app keeps them. */
struct ftree {
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
};

static void ftree_build(struct ftree *f)
{
	tree_mesh_init(&f->tm);
	tree_mesh_marks_init(&f->mk);
	CHECK_INT(tree_mesh_build_marked(&f->tm, &f->t, &f->mk), 0);
}

static void ftree_finish(struct ftree *f)
{
	tree_mesh_marks_finish(&f->mk);
	tree_mesh_finish(&f->tm);
	tree_finish(&f->t);
}

/* What the forests showed. */
static struct {
	double err, tol, ratio;   /* the worst share of its tolerance, its error and tolerance */
	size_t forests, trees, channels, vertices, nomesh, still;
	size_t keys_lo, keys_hi;
	size_t bytes_max;
} seen = { .keys_lo = SIZE_MAX };

/* The mesh each primitive comes from; NULL where the tree has none. */
static void prim_meshes(const struct tree *t, const struct tree_mesh *tm,
			const struct export_vines *ev, const struct mesh *out[NPRIMS])
{
	out[0] = &tm->bark;
	out[1] = t->wood ? &t->wood->bark : NULL;
	out[2] = &tm->leaves;
	out[3] = &ev->stems;
	out[4] = &ev->leaves;
}

static bool prim_expected(const struct tree *t, const struct mesh *m, size_t i)
{
	bool leafy = i == 2 || i == 4;

	return m && m->nindices >= 3 && m->nvertices > 0 && !(leafy && t->season == SEASON_WINTER);
}

static void bind(struct live_attrs *a, const struct live_skeleton *sk, const struct tree *t,
		 const struct mesh *m, const struct tree_mesh_marks *mk, enum bind_kind how)
{
	live_attrs_init(a);
	if (how == BIND_BARK)
		CHECK_INT(live_attrs_bind_bark(a, sk, t, m, mk), 0);
	else if (how == BIND_LEAVES)
		CHECK_INT(live_attrs_bind_leaves(a, sk, t, m, mk), 0);
	else
		CHECK_INT(live_attrs_bind_nearest(a, sk, t, m), 0);
	CHECK_INT(a->n, m->nvertices);
}

/* The material's name of a primitive. */
static const char *material_name(const struct glb *g, struct json_object *prim)
{
	return get_str(at(get(g->json, "materials"), (size_t)get_int(prim, "material")), "name");
}

/* Two morph targets alike: the same bytes, or both zeros (an accessor without a view). */
static bool same_target(const struct glb *a, int64_t ia, const struct glb *b, int64_t ib)
{
	static const char *const keys[] = { "componentType", "count", "type", "min", "max" };
	struct json_object *ja = at(get(a->json, "accessors"), (size_t)ia);
	struct json_object *jb = at(get(b->json, "accessors"), (size_t)ib);
	bool va = json_object_object_get_ex(ja, "bufferView", NULL);

	if (va != json_object_object_get_ex(jb, "bufferView", NULL))
		return false;
	if (va)
		return glb_same_accessor(a, ia, b, ib);
	for (size_t k = 0; k < sizeof(keys) / sizeof(*keys); k++) {
		struct json_object *x = NULL, *y = NULL;

		json_object_object_get_ex(ja, keys[k], &x);
		json_object_object_get_ex(jb, keys[k], &y);
		if (!json_object_equal(x, y))
			return false;
	}
	return json_object_object_get_ex(jb, "sparse", NULL);
}

/* The forest's mesh `fm` is model.glb's one mesh (its first) accessor for accessor. */
static void check_same_mesh(const struct glb *forest, struct json_object *fm,
			    const struct glb *model)
{
	static const char *const attrs[] = { "POSITION", "NORMAL", "COLOR_0" };
	struct json_object *mm = at(get(model->json, "meshes"), 0);
	struct json_object *fp = get(fm, "primitives"), *mp = get(mm, "primitives");

	CHECK_INT(json_object_array_length(fp), json_object_array_length(mp));
	for (size_t p = 0; p < json_object_array_length(mp); p++) {
		struct json_object *a = at(fp, p), *b = at(mp, p);
		struct json_object *aa = get(a, "attributes"), *ba = get(b, "attributes");
		struct json_object *at_, *bt;

		CHECK(!strcmp(material_name(forest, a), material_name(model, b)));
		CHECK_INT(json_object_object_length(aa), json_object_object_length(ba));
		for (size_t k = 0; k < 3; k++) {
			struct json_object *ib;

			if (!json_object_object_get_ex(ba, attrs[k], &ib))
				continue;
			CHECK(glb_same_accessor(forest, get_int(aa, attrs[k]), model,
						json_object_get_int64(ib)));
		}
		CHECK(glb_same_accessor(forest, get_int(a, "indices"), model, get_int(b, "indices")));
		CHECK_INT(get_int(a, "mode"), get_int(b, "mode"));
		CHECK(json_object_object_get_ex(a, "targets", &at_) ==
		      json_object_object_get_ex(b, "targets", &bt));
		if (!json_object_object_get_ex(b, "targets", NULL))
			continue;
		CHECK_INT(json_object_array_length(at_), NT);
		CHECK_INT(json_object_array_length(bt), NT);
		for (size_t j = 0; j < NT; j++)
			CHECK(same_target(forest, get_int(at(at_, j), "POSITION"), model,
					  get_int(at(bt, j), "POSITION")));
	}
	CHECK(json_object_object_get_ex(fm, "weights", NULL) ==
	      json_object_object_get_ex(mm, "weights", NULL));
	if (json_object_object_get_ex(mm, "weights", NULL)) {
		CHECK(json_object_equal(get(fm, "weights"), get(mm, "weights")));
		CHECK(json_object_equal(get(fm, "extras"), get(mm, "extras")));
	}
}

/* The channel whose target is node i, or NULL. */
static struct json_object *channel_of(struct json_object *anim, size_t node)
{
	struct json_object *found = NULL;

	for (size_t c = 0; anim && c < count(anim, "channels"); c++) {
		struct json_object *ch = at(get(anim, "channels"), c);

		if ((size_t)get_int(get(ch, "target"), "node") != node)
			continue;
		CHECK(!found); /* one channel a node */
		CHECK(!strcmp(get_str(get(ch, "target"), "path"), "weights"));
		found = ch;
	}
	return found;
}

/*
 * Tree f's node's motion played back from the forest's sampler, against the screen's
 * functions with the common loop, at every moment; the worst share of the tolerance.
 */
static void check_playback(const struct glb *g, struct json_object *mesh, const struct keys *k,
			   const struct ftree *f, const struct export_wind *ew)
{
	struct live_wind_params wp = { .strength = export_wind_strength(ew), .angle = ew->angle,
				       .loop = LOOP };
	struct live_skeleton sk;
	struct live_wind w;
	struct live_attrs attrs[NPRIMS];
	struct targets tg[NPRIMS];
	const struct mesh *meshes[NPRIMS];
	bool used[NPRIMS];
	struct export_vines ev;
	double scale[NT] = { 0 }, tol = 0.0, err = 0.0;
	size_t p = 0;

	CHECK_INT(live_skeleton_init(&sk, &f->t, ew->seed), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &wp), 0);
	CHECK(w.loop == LOOP);
	CHECK(glb_float(k->times, k->n - 1) == (float)LOOP);
	CHECK_INT(export_vines_build(&ev, &f->t), 0);
	prim_meshes(&f->t, &f->tm, &ev, meshes);
	for (size_t i = 0; i < NPRIMS; i++) {
		used[i] = prim_expected(&f->t, meshes[i], i);
		if (!used[i])
			continue;
		bind(&attrs[i], &sk, &f->t, meshes[i], &f->mk, prim_bind[i]);
		read_targets(g, at(get(mesh, "primitives"), p++), meshes[i]->nvertices, &tg[i]);
		for (size_t v = 0; v < attrs[i].n; v++) {
			struct vec3 d[NT];

			live_wind_targets(&w, &attrs[i].v[v], d);
			for (int j = 0; j < NT; j++)
				scale[j] = fmax(scale[j], fmax(fabs(d[j].x),
							       fmax(fabs(d[j].y), fabs(d[j].z))));
		}
		seen.vertices += attrs[i].n;
	}
	CHECK_INT(p, json_object_array_length(get(mesh, "primitives")));
	for (int j = 0; j < NT; j++) {
		double e = pow(2.0 * VEC_PI * harmonic(&w, j) / (double)(k->n - 1), 4.0) / 384.0;

		tol += scale[j] * ((ew->floats ? 0.0 : 1.0 / 254.0) + e + 3e-5);
	}
	tol = sqrt(3.0) * tol + 1e-7;
	for (size_t m = 0; m < NMOMENTS; m++) {
		double weights[NT];

		play(k, moments[m] * LOOP, weights);
		for (size_t i = 0; i < NPRIMS; i++) {
			for (size_t v = 0; used[i] && v < attrs[i].n; v++) {
				const struct live_vertex *lv = &attrs[i].v[v];
				struct vec3 want = live_wind_offset(&w, lv, moments[m] * LOOP);
				struct vec3 got = vec3(0, 0, 0);

				for (int j = 0; j < NT; j++)
					got = vec3_add(got, vec3_scale(target_delta(&tg[i], j, v),
								       weights[j]));
				err = fmax(err, vec3_dist(got, want));
			}
		}
	}
	if (err > tol)
		fprintf(stderr, "tree played off by %.3g m, tolerance %.3g m\n", err, tol);
	CHECK(err <= tol);
	if (err / tol > seen.ratio) {
		seen.ratio = err / tol;
		seen.err = err;
		seen.tol = tol;
	}
	for (size_t i = 0; i < NPRIMS; i++)
		if (used[i])
			live_attrs_finish(&attrs[i]);
	export_vines_finish(&ev);
	live_skeleton_finish(&sk);
}

/*
 * Exports the forest (trees[i] made from fs[i]) with ew's wind (NULL: still), reads it
 * back and checks every property against each tree's model.glb.
 */
static void check_forest(const struct export_forest_tree *trees, const struct ftree *const *fs,
			 size_t n, const struct export_wind *ew)
{
	struct buf out, again;
	struct glb g;
	struct json_object *scene, *anim = NULL, *req = NULL;
	size_t channels = 0, sways = 0;

	buf_init(&out);
	buf_init(&again);
	CHECK_INT(export_glb_forest(trees, n, ew, LOOP, &out), 0);
	CHECK_INT(export_glb_forest(trees, n, ew, LOOP, &again), 0);
	CHECK(out.len == again.len && !memcmp(out.data, again.data, out.len));
	parse_glb(&out, &g);
	if (count(g.json, "accessors"))
		check_accessors(&g);
	scene = at(get(g.json, "scenes"), (size_t)get_int(g.json, "scene"));
	CHECK_INT(count(g.json, "scenes"), 1);
	CHECK_INT(count(scene, "nodes"), n);
	CHECK_INT(count(g.json, "nodes"), n);
	if (count(g.json, "animations")) {
		CHECK_INT(count(g.json, "animations"), 1);
		anim = at(get(g.json, "animations"), 0);
		CHECK(!strcmp(get_str(anim, "name"), "wind"));
		channels = count(anim, "channels");
		CHECK(channels > 0);
		CHECK_INT(count(anim, "samplers"), channels);
	}
	for (size_t i = 0; i < n; i++) {
		struct json_object *node = at(get(g.json, "nodes"), i), *ch;
		struct export_wind ewi = { 0 };
		struct buf model;
		struct glb gm;
		char name[32];

		CHECK_INT(json_object_get_int64(at(get(scene, "nodes"), i)), i);
		snprintf(name, sizeof(name), "tree-%" PRIu64, trees[i].number);
		CHECK(!strcmp(get_str(node, "name"), name));
		for (int c = 0; c < 3; c++) {
			double want = trees[i].position[c];
			double got = json_num(at(get(node, "translation"), (size_t)c));

			CHECK(fabs(got - want) <= 1e-8 * fmax(1.0, fabs(want)));
		}
		buf_init(&model);
		if (ew) {
			ewi = *ew;
			ewi.seed = trees[i].seed;
			CHECK_INT(export_glb_wind(&fs[i]->t, &fs[i]->tm, &fs[i]->mk, &ewi, &model), 0);
		} else {
			CHECK_INT(export_glb(&fs[i]->t, &fs[i]->tm, &fs[i]->mk, &model), 0);
		}
		parse_glb(&model, &gm);
		CHECK(json_object_object_get_ex(node, "mesh", NULL) == (count(gm.json, "meshes") == 1));
		ch = channel_of(anim, i);
		CHECK((ch != NULL) == (count(gm.json, "animations") == 1));
		if (count(gm.json, "meshes")) {
			struct json_object *mesh = at(get(g.json, "meshes"),
						      (size_t)get_int(node, "mesh"));

			CHECK(!strcmp(get_str(mesh, "name"), name));
			check_same_mesh(&g, mesh, &gm);
		} else {
			seen.nomesh++;
		}
		if (ch) {
			struct keys k;
			struct json_object *sampler = at(get(anim, "samplers"),
							 (size_t)get_int(ch, "sampler"));
			struct json_object *in = at(get(g.json, "accessors"),
						    (size_t)get_int(sampler, "input"));

			read_sampler_keys(&g, sampler, &k);
			CHECK(glb_float(k.times, k.n - 1) == (float)LOOP);
			CHECK((float)json_num(at(get(in, "max"), 0)) == (float)LOOP);
			seen.keys_lo = k.n < seen.keys_lo ? k.n : seen.keys_lo;
			seen.keys_hi = k.n > seen.keys_hi ? k.n : seen.keys_hi;
			check_playback(&g, at(get(g.json, "meshes"), (size_t)get_int(node, "mesh")),
				       &k, fs[i], &ewi);
			sways++;
		} else if (count(gm.json, "meshes")) {
			seen.still++;
		}
		json_object_put(gm.json);
		buf_finish(&model);
	}
	CHECK_INT(sways, channels);
	/* the extension exactly when some tree sways with byte targets */
	json_object_object_get_ex(g.json, "extensionsRequired", &req);
	CHECK((req != NULL) == (ew && !ew->floats && channels > 0));
	seen.forests++;
	seen.trees += n;
	seen.channels += channels;
	seen.bytes_max = out.len > seen.bytes_max ? out.len : seen.bytes_max;
	json_object_put(g.json);
	buf_finish(&out);
	buf_finish(&again);
}

/* A random small tree: 1 to 12 branches, 0 to 3 leaves each, 3 to 15 m, any season. */
static void random_tree(struct ftree *f, struct rng *r)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_SPRING, SEASON_AUTUMN,
					       SEASON_WINTER };
	int nb = 1 + (int)(rng_next(r) % 12), leaves = (int)(rng_next(r) % 4);
	uint64_t seed = rng_next(r);

	tree_init(&f->t);
	live_trees_random(&f->t, nb, leaves, seed, rng_range(r, 3.0, 15.0));
	f->t.season = seasons[rng_next(r) % 4];
	ftree_build(f);
}

/* The special trees a forest may take beside its random ones. */
enum { SPECIAL_VINES, SPECIAL_WOOD, SPECIAL_BRANCHLESS, SPECIAL_EMPTY, NSPECIAL };

/* A vine tree in autumn, a grown tree, a tree without branches whose mesh is another's
 * (a mesh without targets) and an empty drawing. */
static void special_trees(struct ftree sp[NSPECIAL])
{
	tree_init(&sp[SPECIAL_VINES].t);
	CHECK_INT(synth_vine_tree(&sp[SPECIAL_VINES].t, 2), 0);
	sp[SPECIAL_VINES].t.season = SEASON_AUTUMN;
	ftree_build(&sp[SPECIAL_VINES]);
	tree_init(&sp[SPECIAL_WOOD].t);
	CHECK_INT(synth_wood_tree(&sp[SPECIAL_WOOD].t, 1, WOOD_BROADLEAF), 0);
	CHECK(sp[SPECIAL_WOOD].t.wood);
	ftree_build(&sp[SPECIAL_WOOD]);
	/* no branches, the grown tree's meshes: what it draws has no skeleton to sway with */
	tree_init(&sp[SPECIAL_BRANCHLESS].t);
	tree_mesh_init(&sp[SPECIAL_BRANCHLESS].tm);
	tree_mesh_marks_init(&sp[SPECIAL_BRANCHLESS].mk);
	CHECK_INT(tree_mesh_build(&sp[SPECIAL_BRANCHLESS].tm, &sp[SPECIAL_WOOD].t), 0);
	tree_init(&sp[SPECIAL_EMPTY].t);
	ftree_build(&sp[SPECIAL_EMPTY]);
}

/* The property on seeded random forests. */
static void test_random(void)
{
	struct ftree sp[NSPECIAL], *pool = calloc(MAX_TREES, sizeof(*pool));
	struct export_forest_tree trees[MAX_TREES];
	const struct ftree *fs[MAX_TREES];
	int nforests = test_cases(RANDOM_FORESTS), floats = 0;
	struct rng r;

	CHECK(pool);
	special_trees(sp);
	rng_seed(&r, 27);
	for (int f = 0; f < nforests; f++) {
		size_t n = 1 + (size_t)(rng_next(&r) % MAX_TREES), nrandom = 0;
		uint64_t number = 1 + rng_next(&r) % 50;
		struct export_wind ew = {
			.strength = (f % 5) * 0.25, /* 0 (the breeze) .. 1 */
			.angle = rng_range(&r, -VEC_PI, VEC_PI),
			.seed = 99, /* not used: each tree's own */
			.floats = f % 10 == 9,
		};

		for (size_t i = 0; i < n; i++) {
			/* one tree in 12 a special one */
			if (rng_next(&r) % 12 == 0) {
				fs[i] = &sp[rng_next(&r) % NSPECIAL];
			} else {
				random_tree(&pool[nrandom], &r);
				fs[i] = &pool[nrandom++];
			}
			trees[i] = (struct export_forest_tree){
				.tree = &fs[i]->t, .mesh = &fs[i]->tm, .marks = &fs[i]->mk,
				.seed = rng_next(&r), .number = number,
				.position = { rng_range(&r, -40.0, 40.0), rng_range(&r, -0.5, 0.5),
					      rng_range(&r, -40.0, 40.0) },
			};
			number += 1 + rng_next(&r) % 3;
		}
		check_forest(trees, fs, n, &ew);
		/* every fifth a still forest too */
		if (f % 5 == 0)
			check_forest(trees, fs, n, NULL);
		floats += ew.floats;
		for (size_t i = 0; i < nrandom; i++)
			ftree_finish(&pool[i]);
	}
	for (int i = 0; i < NSPECIAL; i++)
		ftree_finish(&sp[i]);
	free(pool);
	printf("%d random forests (%d with float targets, every fifth also still): %zu forests, "
	       "%zu trees, %zu channels, %zu trees still (no branches), %zu without a mesh; "
	       "%zu vertices played at %zu moments of the 8 s loop: worst %.3f mm, %.0f%% of its "
	       "tolerance (%.3f mm); %zu to %zu keys a sampler; largest file %.1f KB\n",
	       nforests, floats, seen.forests, seen.trees, seen.channels, seen.still, seen.nomesh,
	       seen.vertices, NMOMENTS, seen.err * 1e3, 100.0 * seen.ratio, seen.tol * 1e3,
	       seen.keys_lo, seen.keys_hi, seen.bytes_max / 1e3);
}

/* No tree: a valid empty scene, the empty drawing's model.glb byte for byte. */
static void test_empty(void)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 1 };
	struct tree t;
	struct tree_mesh tm;
	struct buf a, b;
	struct glb g;

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&a);
	buf_init(&b);
	CHECK_INT(export_glb_forest(NULL, 0, &ew, LOOP, &a), 0);
	CHECK_INT(export_glb(&t, &tm, NULL, &b), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	parse_glb(&a, &g);
	CHECK_INT(g.bin_len, 0);
	CHECK_INT(count(g.json, "nodes"), 0);
	CHECK_INT(count(g.json, "animations"), 0);
	CHECK_INT(count(at(get(g.json, "scenes"), 0), "nodes"), 0);
	json_object_put(g.json);
	printf("no tree: an empty scene, %zu bytes\n", a.len);
	buf_finish(&a);
	buf_finish(&b);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Bad parameters are refused, out as it was. */
static void test_rules(void)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 1 };
	const struct export_wind bad_wind[] = { { .strength = -0.1 }, { .strength = 1.5 },
						 { .strength = NAN }, { .angle = INFINITY } };
	const double bad_loop[] = { 0.0, -8.0, 0.5, 60.5, NAN, INFINITY };
	struct ftree f;
	struct export_forest_tree tr[2];
	struct buf out;
	size_t refused = 0;

	tree_init(&f.t);
	live_trees_random(&f.t, 8, 2, 5, 7.0);
	ftree_build(&f);
	for (int i = 0; i < 2; i++)
		tr[i] = (struct export_forest_tree){ .tree = &f.t, .mesh = &f.tm, .marks = &f.mk,
						     .seed = 3, .number = 1 + (uint64_t)i,
						     .position = { 4.0 * i, 0, 0 } };
	buf_init(&out);
	CHECK_INT(buf_append(&out, "keep", 4), 0);
	for (size_t i = 0; i < sizeof(bad_loop) / sizeof(*bad_loop); i++, refused++)
		CHECK_INT(export_glb_forest(tr, 2, &ew, bad_loop[i], &out), -EINVAL);
	for (size_t i = 0; i < sizeof(bad_wind) / sizeof(*bad_wind); i++, refused++)
		CHECK_INT(export_glb_forest(tr, 2, &bad_wind[i], LOOP, &out), -EINVAL);
	/* even with no tree to sway */
	CHECK_INT(export_glb_forest(tr, 0, &bad_wind[0], LOOP, &out), -EINVAL);
	CHECK_INT(export_glb_forest(NULL, 2, &ew, LOOP, &out), -EINVAL);
	tr[1].position[1] = NAN;
	CHECK_INT(export_glb_forest(tr, 2, &ew, LOOP, &out), -EINVAL);
	tr[1].position[1] = 0.0;
	tr[1].mesh = NULL;
	CHECK_INT(export_glb_forest(tr, 2, &ew, LOOP, &out), -EINVAL);
	tr[1].mesh = &f.tm;
	tr[0].tree = NULL;
	CHECK_INT(export_glb_forest(tr, 2, &ew, LOOP, &out), -EINVAL);
	refused += 5;
	CHECK(out.len == 4 && !memcmp(out.data, "keep", 4));
	/* a still forest takes any loop: it has none */
	tr[0].tree = &f.t;
	CHECK_INT(export_glb_forest(tr, 2, NULL, 0.0, &out), 0);
	CHECK(out.len > 4 && !memcmp(out.data, "keep", 4));
	printf("%zu bad parameters refused, out as it was\n", refused);
	buf_finish(&out);
	ftree_finish(&f);
}

int main(void)
{
	test_rules();
	test_empty();
	test_random();
	return 0;
}
