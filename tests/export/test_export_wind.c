/* SPDX-License-Identifier: MIT */
/*
 * export_glb_wind and export_skeleton_wind (issue 26, docs/living-trees.md, "The wind in
 * model.glb"): the file read back and played as glTF says (the CUBICSPLINE sampler's
 * Hermite spline, the normalised byte targets) moves every vertex as the screen's
 * functions do (live_wind_offset, the vertex bound as the renderer binds it), within the
 * tolerance the rounding to bytes and the spline allow:
 *
 *   |played - live| <= sqrt(3) sum_j s_j (1/254 + (2 pi m_j / N)^4 / 384 + 3e-5) + 1e-7 m
 *
 * s_j the largest component of target j (metres), m_j its harmonic, N the keys'
 * intervals; 1/254 is half a byte step (0 with float targets), the second term the cubic
 * Hermite bound for a sine with exact tangents, the third the floats' rounding. Checked
 * at 9 moments of the loop on the demo (as drawn and in 3D), cherry, a 1,000-branch tree
 * and 200 seeded random trees (some in winter, spring, with float targets); the worst
 * error and its share of the tolerance are printed. The weights alone, sharper: at 97
 * moments each played weight (over its scale) is within (2 pi m_j / N)^4 / 384 + 3e-5 of
 * live_wind_weights_at's. Also: the rest pose is export_glb's
 * byte for byte (the BIN chunk starts with it), the loop's first and last keys are equal,
 * winter, a tree without leaves, the 2D sketch, vines and a grown tree export valid
 * files, bad parameters are refused, skeleton.json's "wind" holds the numbers used.
 *
 * Usage: test_export_wind DATA_DIR (tests/data: the demo's trace).
 */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "export_vines.h"
#include "glb_read.h"
#include "glb_wind.h"
#include "live.h"
#include "live_trees.h"
#include "mesh.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "test.h"
#include "tree.h"
#include "wood.h"

#define NT LIVE_WIND_TARGETS
#define RANDOM_TREES 200

static const double moments[] = { 0.0, 0.0137, 0.25, 0.3711, 0.5, 0.618, 0.8333, 0.9999, 1.0 };
#define NMOMENTS (sizeof(moments) / sizeof(*moments))

enum bind_kind { BIND_BARK, BIND_LEAVES, BIND_NEAREST };

/* The exporter's primitives: their names, how they are bound, whether they are leaves. */
static const char *const prim_names[] = { "bark", "wood", "leaves", "vine", "vine-leaves" };
static const enum bind_kind prim_bind[] = { BIND_BARK, BIND_NEAREST, BIND_LEAVES, BIND_NEAREST,
					    BIND_NEAREST };
#define NPRIMS (sizeof(prim_names) / sizeof(*prim_names))

/* What one file showed. */
struct result {
	double err, tol;      /* the worst error seen, m, and the tolerance */
	double ratio;         /* err / tol */
	double weight_ratio;  /* the weights' worst error over their spline's bound */
	size_t vertices, keys;
	double loop;
	size_t still_bytes, wind_bytes;
};

static void worst_of(struct result *acc, const struct result *r)
{
	if (r->ratio > acc->ratio) {
		acc->ratio = r->ratio;
		acc->tol = r->tol;
	}
	acc->err = fmax(acc->err, r->err);
	acc->weight_ratio = fmax(acc->weight_ratio, r->weight_ratio);
	acc->vertices += r->vertices;
}

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

/* One animation "wind": the node's weights by one CUBICSPLINE sampler, its keys from 0 to
 * the loop, the last the first (weights and tangents). */
static void read_keys(const struct glb *g, struct keys *k)
{
	struct json_object *anim, *channel, *target;

	CHECK_INT(count(g->json, "animations"), 1);
	anim = at(get(g->json, "animations"), 0);
	CHECK(!strcmp(get_str(anim, "name"), "wind"));
	CHECK_INT(count(anim, "channels"), 1);
	CHECK_INT(count(anim, "samplers"), 1);
	channel = at(get(anim, "channels"), 0);
	target = get(channel, "target");
	CHECK_INT(get_int(target, "node"), 0);
	CHECK(!strcmp(get_str(target, "path"), "weights"));
	read_sampler_keys(g, at(get(anim, "samplers"), (size_t)get_int(channel, "sampler")), k);
}

/* The rest pose is export_glb's: the same accessors, bytes and offsets, the BIN chunk its
 * prefix; the mesh's weights 0 and its targets named. */
static void check_rest(const struct glb *still, const struct glb *wind)
{
	struct json_object *ps = glb_prims(still), *pw = glb_prims(wind), *mesh;
	static const char *const attrs[] = { "POSITION", "NORMAL", "COLOR_0" };

	CHECK(wind->bin_len > still->bin_len);
	CHECK(!memcmp(still->bin, wind->bin, still->bin_len));
	CHECK_INT(json_object_array_length(ps), json_object_array_length(pw));
	for (size_t p = 0; p < json_object_array_length(ps); p++) {
		struct json_object *as = get(at(ps, p), "attributes");
		struct json_object *aw = get(at(pw, p), "attributes");

		CHECK_INT(json_object_object_length(as), json_object_object_length(aw));
		for (size_t a = 0; a < 3; a++) {
			struct json_object *is;

			if (!json_object_object_get_ex(as, attrs[a], &is))
				continue;
			CHECK_INT(json_object_get_int64(is), get_int(aw, attrs[a]));
			CHECK(glb_same_accessor(still, json_object_get_int64(is), wind,
						get_int(aw, attrs[a])));
		}
		CHECK_INT(get_int(at(ps, p), "indices"), get_int(at(pw, p), "indices"));
		CHECK(glb_same_accessor(still, get_int(at(ps, p), "indices"), wind,
					get_int(at(pw, p), "indices")));
		CHECK_INT(get_int(at(ps, p), "material"), get_int(at(pw, p), "material"));
	}
	mesh = at(get(wind->json, "meshes"), 0);
	CHECK_INT(count(mesh, "weights"), NT);
	for (int j = 0; j < NT; j++)
		CHECK(json_num(at(get(mesh, "weights"), (size_t)j)) == 0.0);
	CHECK_INT(json_object_array_length(get(get(mesh, "extras"), "targetNames")), NT);
	CHECK(json_object_equal(get(still->json, "materials"), get(wind->json, "materials")));
	CHECK(json_object_equal(get(still->json, "nodes"), get(wind->json, "nodes")));
}

/*
 * Exports t with ew's wind, reads it back and plays it at every moment, against the
 * screen's functions at the same moments; r gets the worst error and the sizes.
 */
static void check_wind(const struct tree *t, const struct tree_mesh *tm,
		       const struct tree_mesh_marks *mk, const struct export_wind *ew,
		       struct result *r)
{
	struct live_wind_params wp = { .strength = export_wind_strength(ew), .angle = ew->angle };
	struct live_skeleton sk;
	struct live_wind w;
	struct live_attrs attrs[NPRIMS];
	struct targets tg[NPRIMS];
	const struct mesh *meshes[NPRIMS];
	bool used[NPRIMS];
	struct export_vines ev;
	struct buf still, wind;
	struct glb gs, gw;
	struct keys k;
	double scale[NT] = { 0 }, tol = 0.0;
	struct json_object *req = NULL;

	memset(r, 0, sizeof(*r));
	buf_init(&still);
	buf_init(&wind);
	CHECK_INT(export_glb(t, tm, mk, &still), 0);
	CHECK_INT(export_glb_wind(t, tm, mk, ew, &wind), 0);
	parse_glb(&still, &gs);
	parse_glb(&wind, &gw);
	check_accessors(&gw);
	check_rest(&gs, &gw);
	read_keys(&gw, &k);
	CHECK(json_object_object_get_ex(gw.json, "extensionsRequired", &req) == !ew->floats);
	if (!ew->floats) {
		CHECK_INT(json_object_array_length(req), 1);
		CHECK(!strcmp(json_object_get_string(at(req, 0)), "KHR_mesh_quantization"));
		CHECK(json_object_equal(req, get(gw.json, "extensionsUsed")));
	}

	CHECK_INT(live_skeleton_init(&sk, t, ew->seed), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &wp), 0);
	CHECK(w.loop <= LIVE_WIND_LOOP_MAX_S);
	CHECK(glb_float(k.times, k.n - 1) == (float)w.loop);
	CHECK_INT(export_vines_build(&ev, t), 0);
	prim_meshes(t, tm, &ev, meshes);
	for (size_t p = 0; p < NPRIMS; p++) {
		struct json_object *prim = glb_prim_named(&gw, prim_names[p]);

		used[p] = prim_expected(t, meshes[p], p);
		CHECK(used[p] == (prim != NULL));
		if (!used[p])
			continue;
		bind(&attrs[p], &sk, t, meshes[p], mk, prim_bind[p]);
		read_targets(&gw, prim, meshes[p]->nvertices, &tg[p]);
		for (size_t v = 0; v < attrs[p].n; v++) {
			struct vec3 d[NT];

			live_wind_targets(&w, &attrs[p].v[v], d);
			for (int j = 0; j < NT; j++)
				scale[j] = fmax(scale[j], fmax(fabs(d[j].x),
							       fmax(fabs(d[j].y), fabs(d[j].z))));
		}
		r->vertices += attrs[p].n;
	}
	for (int j = 0; j < NT; j++) {
		double e = pow(2.0 * VEC_PI * harmonic(&w, j) / (double)(k.n - 1), 4.0) / 384.0;

		tol += scale[j] * ((ew->floats ? 0.0 : 1.0 / 254.0) + e + 3e-5);
	}
	tol = sqrt(3.0) * tol + 1e-7;
	/* the weights alone, 97 moments: each within its spline's bound of g_j, times its
	 * scale with bytes (the exporter's scales are these: the same bindings) */
	for (int m = 0; m <= 96; m++) {
		double f = m / 96.0, played[NT], want[NT];

		play(&k, f * glb_float(k.times, k.n - 1), played);
		live_wind_weights_at(&w, f, want);
		for (int j = 0; j < NT; j++) {
			double unit = ew->floats ? 1.0 : scale[j];
			double bound = pow(2.0 * VEC_PI * harmonic(&w, j) / (double)(k.n - 1), 4.0) /
					       384.0 + 3e-5;

			if (unit == 0.0) {
				CHECK(played[j] == 0.0);
				continue;
			}
			r->weight_ratio = fmax(r->weight_ratio,
					       fabs(played[j] / unit - want[j]) / bound);
		}
	}
	if (r->weight_ratio > 1.0)
		fprintf(stderr, "a weight off by %.3g of its bound\n", r->weight_ratio);
	CHECK(r->weight_ratio <= 1.0);
	for (size_t m = 0; m < NMOMENTS; m++) {
		double weights[NT];

		play(&k, moments[m] * glb_float(k.times, k.n - 1), weights);
		for (size_t p = 0; p < NPRIMS; p++) {
			for (size_t v = 0; used[p] && v < attrs[p].n; v++) {
				const struct live_vertex *lv = &attrs[p].v[v];
				struct vec3 want = live_wind_offset(&w, lv, moments[m] * w.loop);
				struct vec3 got = vec3(0, 0, 0);

				for (int j = 0; j < NT; j++)
					got = vec3_add(got, vec3_scale(target_delta(&tg[p], j, v),
								       weights[j]));
				r->err = fmax(r->err, vec3_dist(got, want));
			}
		}
	}
	r->tol = tol;
	r->ratio = r->err / tol;
	r->keys = k.n;
	r->loop = w.loop;
	r->still_bytes = still.len;
	r->wind_bytes = wind.len;
	if (r->err > tol)
		fprintf(stderr, "played wind off by %.3g m, tolerance %.3g m\n", r->err, tol);
	CHECK(r->err <= tol);

	for (size_t p = 0; p < NPRIMS; p++)
		if (used[p])
			live_attrs_finish(&attrs[p]);
	export_vines_finish(&ev);
	live_skeleton_finish(&sk);
	json_object_put(gs.json);
	json_object_put(gw.json);
	buf_finish(&still);
	buf_finish(&wind);
}

/* skeleton.json's "wind": after export_skeleton's keys, the numbers the animation uses. */
static void check_skeleton(const struct tree *t, const struct export_wind *ew)
{
	static const char *const names[] = { "trunk", "trunk-across", "limbs", "branches", "twigs",
					      "flutter" };
	struct live_wind_params wp = { .strength = export_wind_strength(ew), .angle = ew->angle };
	struct live_skeleton sk;
	struct live_wind w;
	struct buf a, b;
	struct json_object *root, *wind, *motions;
	int harmonics[6];
	double amps[6];

	buf_init(&a);
	buf_init(&b);
	CHECK_INT(export_skeleton(t, &a), 0);
	CHECK_INT(export_skeleton_wind(t, ew, &b), 0);
	CHECK(b.len > a.len && a.len > 2);
	CHECK(!memcmp(a.data, b.data, a.len - 2));
	CHECK(!memcmp(b.data + a.len - 2, ",\"wind\":{", 9));
	CHECK(!memcmp(b.data + b.len - 4, "]}}\n", 4));
	CHECK_INT(live_skeleton_init(&sk, t, ew->seed), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &wp), 0);
	root = json_text(&b);
	wind = get(root, "wind");
	CHECK_NEAR(json_num(get(wind, "strength")), w.strength, 6e-7);
	CHECK_NEAR(json_num(get(wind, "angle")), ew->angle * 180.0 / VEC_PI, 6e-7);
	CHECK(json_object_get_uint64(get(wind, "seed")) == ew->seed);
	CHECK_NEAR(json_num(get(wind, "height")), w.height, 6e-7);
	CHECK_NEAR(json_num(get(wind, "period")), w.period, 6e-7);
	CHECK_NEAR(json_num(get(wind, "loop")), w.loop, 6e-7);
	harmonics[0] = w.harmonic[0];
	harmonics[1] = 2 * w.harmonic[0];
	amps[0] = w.amp0;
	amps[1] = LIVE_WIND_FIGURE_EIGHT * w.amp0;
	for (int i = 1; i < LIVE_BANDS; i++) {
		harmonics[i + 1] = w.harmonic[i];
		amps[i + 1] = w.amp[i];
	}
	harmonics[5] = w.harmonic[LIVE_BANDS];
	amps[5] = w.amp_leaf;
	motions = get(wind, "motions");
	CHECK_INT(json_object_array_length(motions), 6);
	for (size_t i = 0; i < 6; i++) {
		struct json_object *m = at(motions, i);

		CHECK(!strcmp(get_str(m, "name"), names[i]));
		CHECK_INT(get_int(m, "harmonic"), harmonics[i]);
		CHECK_NEAR(json_num(get(m, "hz")), live_wind_hz(&w, harmonics[i]), 6e-7);
		CHECK_NEAR(json_num(get(m, "amplitude")), amps[i], 6e-7);
	}
	json_object_put(root);
	live_skeleton_finish(&sk);
	buf_finish(&a);
	buf_finish(&b);
}

/* A tree's meshes and marks, as the app keeps them. */
struct meshes {
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
};

static void build(struct meshes *m, const struct tree *t)
{
	tree_mesh_init(&m->tm);
	tree_mesh_marks_init(&m->mk);
	CHECK_INT(tree_mesh_build_marked(&m->tm, t, &m->mk), 0);
}

static void unbuild(struct meshes *m)
{
	tree_mesh_marks_finish(&m->mk);
	tree_mesh_finish(&m->tm);
}

/* One named tree: the file checked with byte and float targets, and its skeleton.json. */
static void named_tree(const char *name, const struct tree *t, uint64_t seed)
{
	struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = seed };
	struct meshes m;
	struct result rb, rf;

	build(&m, t);
	check_wind(t, &m.tm, &m.mk, &ew, &rb);
	ew.floats = true;
	check_wind(t, &m.tm, &m.mk, &ew, &rf);
	ew.floats = false;
	check_skeleton(t, &ew);
	printf("%-16s %7zu vertices, T_loop %.2f s, %3zu keys: worst %.3f mm, tolerance %.3f mm "
	       "(%.0f%%); floats worst %.4f mm of %.4f mm; weights %.0f%% of their bound\n",
	       name, rb.vertices, rb.loop, rb.keys, rb.err * 1e3, rb.tol * 1e3, 100.0 * rb.ratio,
	       rf.err * 1e3, rf.tol * 1e3, 100.0 * fmax(rb.weight_ratio, rf.weight_ratio));
	printf("%-16s model.glb %.1f KB still, %.1f KB with the wind (+%.0f%%); float targets "
	       "%.1f KB (+%.0f%%)\n",
	       "", rb.still_bytes / 1e3, rb.wind_bytes / 1e3,
	       100.0 * ((double)rb.wind_bytes / (double)rb.still_bytes - 1.0), rf.wind_bytes / 1e3,
	       100.0 * ((double)rf.wind_bytes / (double)rf.still_bytes - 1.0));
	unbuild(&m);
}

/* The demo as drawn (a 2D sketch: exported as a tree all the same) and in 3D, cherry and a
 * 1,000-branch tree. */
static void test_named(const char *data_dir)
{
	struct tree t;

	tree_init(&t);
	live_trees_demo(&t, data_dir, false);
	CHECK(!t.lifted);
	named_tree("demo (2D)", &t, 1);
	tree_clear(&t);
	live_trees_demo(&t, data_dir, true);
	named_tree("demo (3D)", &t, 1);
	tree_clear(&t);
	live_trees_preset(&t, GEN_PRESET_CHERRY);
	named_tree("cherry", &t, 1);
	tree_clear(&t);
	live_trees_random(&t, 1000, 10, 26, 12.0);
	named_tree("1,000 branches", &t, 26);
	tree_finish(&t);
}

/* Winter, a tree without leaves, vines and a grown tree: valid files that play right. */
static void test_kinds(void)
{
	struct export_wind ew = { .angle = 0.4, .seed = 7 };
	struct tree t;
	struct meshes m;
	struct result r;

	tree_init(&t);
	live_trees_random(&t, 40, 6, 3, 8.0);
	t.season = SEASON_WINTER;
	build(&m, &t);
	check_wind(&t, &m.tm, &m.mk, &ew, &r);
	printf("winter: %zu vertices, no leaves primitive, worst %.3f mm (%.0f%%)\n", r.vertices,
	       r.err * 1e3, 100.0 * r.ratio);
	unbuild(&m);
	t.season = SEASON_AUTUMN; /* COLOR_0 on the leaves */
	build(&m, &t);
	check_wind(&t, &m.tm, &m.mk, &ew, &r);
	unbuild(&m);

	tree_clear(&t);
	live_trees_random(&t, 30, 0, 4, 6.0);
	build(&m, &t);
	check_wind(&t, &m.tm, &m.mk, &ew, &r);
	printf("no leaves: %zu vertices, worst %.3f mm (%.0f%%)\n", r.vertices, r.err * 1e3,
	       100.0 * r.ratio);
	check_skeleton(&t, &ew);
	unbuild(&m);

	tree_clear(&t);
	CHECK_INT(synth_vine_tree(&t, 2), 0);
	for (int s = 0; s < 2; s++) {
		t.season = s ? SEASON_WINTER : SEASON_SUMMER;
		build(&m, &t);
		check_wind(&t, &m.tm, &m.mk, &ew, &r);
		printf("vines in %s: %zu vertices, worst %.3f mm (%.0f%%)\n", season_name(t.season),
		       r.vertices, r.err * 1e3, 100.0 * r.ratio);
		unbuild(&m);
	}
	check_skeleton(&t, &ew);

	tree_clear(&t);
	CHECK_INT(synth_wood_tree(&t, 1, WOOD_BROADLEAF), 0);
	CHECK(t.wood);
	for (int s = 0; s < 2; s++) {
		t.season = s ? SEASON_WINTER : SEASON_SUMMER;
		build(&m, &t);
		check_wind(&t, &m.tm, &m.mk, &ew, &r);
		printf("grown tree in %s: %zu vertices, worst %.3f mm (%.0f%%)\n",
		       season_name(t.season), r.vertices, r.err * 1e3, 100.0 * r.ratio);
		unbuild(&m);
	}
	check_skeleton(&t, &ew);
	tree_finish(&t);
}

/* An empty drawing has nothing to sway: the still files. Bad parameters are refused and
 * write nothing; 0 is the default breeze; the seed makes the phases; same input, same
 * bytes; without marks (found again) the same file. */
static void test_rules(void)
{
	struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 1 };
	const double bad[][2] = { { -0.1, 0 }, { 1.01, 0 }, { NAN, 0 }, { 0.5, INFINITY },
				  { 0.5, NAN } };
	struct tree t;
	struct meshes m;
	struct buf a, b;

	tree_init(&t);
	buf_init(&a);
	buf_init(&b);
	build(&m, &t);
	CHECK_INT(export_glb(&t, &m.tm, &m.mk, &a), 0);
	CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &ew, &b), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	buf_reset(&a);
	buf_reset(&b);
	CHECK_INT(export_skeleton(&t, &a), 0);
	CHECK_INT(export_skeleton_wind(&t, &ew, &b), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	unbuild(&m);

	live_trees_random(&t, 25, 4, 9, 7.0);
	build(&m, &t);
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		struct export_wind e = { .strength = bad[i][0], .angle = bad[i][1] };

		buf_reset(&a);
		CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &e, &a), -EINVAL);
		CHECK_INT(export_skeleton_wind(&t, &e, &a), -EINVAL);
		CHECK_INT(a.len, 0);
	}
	/* 0: the breeze */
	buf_reset(&a);
	buf_reset(&b);
	CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &ew, &a), 0);
	ew.strength = LIVE_WIND_DEFAULT_STRENGTH;
	CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &ew, &b), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	/* without marks: the bark and leaves found again, the same file */
	buf_reset(&b);
	CHECK_INT(export_glb_wind(&t, &m.tm, NULL, &ew, &b), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	/* another seed: other phases */
	buf_reset(&b);
	ew.seed = 2;
	CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &ew, &b), 0);
	CHECK(a.len != b.len || memcmp(a.data, b.data, a.len));
	/* a stronger wind: other targets, the same rest pose */
	buf_reset(&b);
	ew.seed = 1;
	ew.strength = 1.0;
	CHECK_INT(export_glb_wind(&t, &m.tm, &m.mk, &ew, &b), 0);
	CHECK(a.len != b.len || memcmp(a.data, b.data, a.len));
	unbuild(&m);
	buf_finish(&a);
	buf_finish(&b);
	tree_finish(&t);
	printf("an empty drawing keeps the still files; %zu bad parameters refused\n",
	       sizeof(bad) / sizeof(*bad));
}

/* The property: seeded random trees of every size, strength and season export a valid
 * file whose played wind is the screen's within the tolerance. */
static void test_random(void)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_SPRING, SEASON_WINTER };
	struct result worst = { 0 };
	int n = test_cases(RANDOM_TREES), floats = 0;

	for (int i = 0; i < n; i++) {
		struct export_wind ew = {
			.strength = (i % 5) * 0.25, /* 0 (the breeze) .. 1 */
			.angle = 0.37 * i - 3.0,
			.seed = 5000 + (uint64_t)i,
			.floats = i % 10 == 9,
		};
		struct tree t;
		struct meshes m;
		struct result r;

		tree_init(&t);
		live_trees_random(&t, 2 + i % 120, i % 7, 100 + (uint64_t)i, 3.0 + i % 13);
		t.season = seasons[i % 3];
		build(&m, &t);
		check_wind(&t, &m.tm, &m.mk, &ew, &r);
		if (i % 20 == 0)
			check_skeleton(&t, &ew);
		worst_of(&worst, &r);
		floats += ew.floats;
		unbuild(&m);
		tree_finish(&t);
	}
	printf("%d random trees (%d with float targets), %zu vertices, 9 moments each: worst "
	       "error %.3f mm; worst share of its tolerance %.0f%% (of %.3f mm); the weights at "
	       "97 moments at most %.0f%% of their spline's bound\n",
	       n, floats, worst.vertices, worst.err * 1e3, 100.0 * worst.ratio, worst.tol * 1e3,
	       100.0 * worst.weight_ratio);
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		fprintf(stderr, "usage: test_export_wind DATA_DIR\n");
		return 2;
	}
	test_rules();
	test_kinds();
	test_named(argv[1]);
	test_random();
	return 0;
}
