/* SPDX-License-Identifier: MIT */
/*
 * Functional trees (issue 14): what makes their triangles, and how that compares with
 * ez-tree (npm @dgreenheck/ez-tree 1.1.0 under node, bench/eztree/bench.mjs).
 *
 *   sizes      cherry-like trees (presets/cherry.yaml with other levels and
 *              leaves.amount) of about 5k, 20k and 100k triangles at precision 8:
 *              gen_build, tree_mesh_build and the two together, each run from an empty
 *              tree and mesh (as ez-tree's generate() starts from nothing); medians,
 *              per tree and per triangle, growth with size
 *   presets    each of the six once as the kiosk builds it, and gen_read of its file
 *              (median)
 *   templates  the New strip's thumbnails: the New button on a fresh app (median), and
 *              then a tap on the cherry
 *   ez-tree    trees of its presets matched to ours within 10% in triangles, timed in the
 *              same run; ours faster per triangle by N x (the aim: 10x)
 *
 * Times are printed, never judged.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "bench_eztree.h"
#include "bench_draw.h"
#include "bench_util.h"
#include "gen.h"
#include "gen_presets.h"
#include "mesh.h"

#define REPS 21
#define PRESET_READS 201
#define APP_REPS 7
#define SEED 1 /* a template tap's on an empty canvas of seed 1: the kiosk's first tree */
#define PRECISION 8
#define MATCH 0.10 /* ez-tree's triangles within this fraction of ours */

/* The three sizes: levels and leaves on each tip, the rest cherry.yaml's. At precision 8 a
 * branch makes 48 triangles (its fork point keeps a third ring; the trunk 32), an oval
 * leaf 10. */
static const struct size_case {
	const char *label;
	int levels, leaves;
} sizes[] = {
	{ "5k", 6, 6 },
	{ "20k", 8, 6 },
	{ "100k", 10, 10 },
};
#define NSIZES (sizeof(sizes) / sizeof(sizes[0]))

struct figures {
	size_t branches, leaves, bark_tris, leaf_tris;
	double gen_s, mesh_s, total_s; /* medians; total is of whole runs, not a sum */
	double cpu_s; /* the whole run's CPU time: what other people's load leaves alone */
	double remesh_s; /* tree_mesh_build into a mesh used before, as the kiosk's rebuilds */
};

static size_t tris(const struct figures *f)
{
	return f->bark_tris + f->leaf_tris;
}

static double cpu_now(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0)
		return NAN;
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* One run from nothing: gen_build then tree_mesh_build. 0 or < 0. */
static int build_once(const struct gen_params *p, double *gen_s, double *mesh_s, double *cpu_s,
		      struct figures *f)
{
	struct tree t;
	struct tree_mesh tm;
	double t0, t1, t2, c0;
	int ret;

	tree_init(&t);
	tree_mesh_init(&tm);
	c0 = cpu_now();
	t0 = bench_now();
	ret = gen_build(&t, p, SEED);
	t1 = bench_now();
	if (ret == 0)
		ret = tree_mesh_build(&tm, &t);
	t2 = bench_now();
	*cpu_s = cpu_now() - c0;
	if (ret == 0 && f) {
		f->branches = t.nbranches;
		f->leaves = t.nleaves;
		f->bark_tris = tm.bark.nindices / 3;
		f->leaf_tris = tm.leaves.nindices / 3;
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
	*gen_s = t1 - t0;
	*mesh_s = t2 - t1;
	return ret;
}

/* Median seconds of tree_mesh_build of p's tree into one mesh, again and again (one run
 * first). 0 or < 0. */
static int measure_remesh(const struct gen_params *p, int reps, double *s)
{
	double t[REPS];
	struct tree tr;
	struct tree_mesh tm;
	int ret;

	tree_init(&tr);
	tree_mesh_init(&tm);
	ret = gen_build(&tr, p, SEED);
	if (ret == 0)
		ret = tree_mesh_build(&tm, &tr);
	for (int i = 0; i < reps && ret == 0; i++) {
		double t0 = bench_now();

		ret = tree_mesh_build(&tm, &tr);
		t[i] = bench_now() - t0;
	}
	tree_mesh_finish(&tm);
	tree_finish(&tr);
	*s = ret == 0 ? bench_median(t, (size_t)reps) : 0.0;
	return ret;
}

/* reps runs after one to warm the allocator and caches. 0 or < 0. */
static int measure(const struct gen_params *p, int reps, struct figures *f)
{
	double gen[REPS], mesh[REPS], total[REPS], cpu[REPS], g, m, c;
	int ret = build_once(p, &g, &m, &c, f);

	for (int i = 0; i < reps && ret == 0; i++) {
		ret = build_once(p, &gen[i], &mesh[i], &cpu[i], NULL);
		total[i] = gen[i] + mesh[i];
	}
	if (ret < 0)
		return ret;
	f->gen_s = bench_median(gen, (size_t)reps);
	f->mesh_s = bench_median(mesh, (size_t)reps);
	f->total_s = bench_median(total, (size_t)reps);
	f->cpu_s = bench_median(cpu, (size_t)reps);
	return measure_remesh(p, reps, &f->remesh_s);
}

static int cherry(int levels, int leaves, struct gen_params *p)
{
	struct error err;
	int ret = gen_preset(GEN_PRESET_CHERRY, p, &err);

	if (ret < 0) {
		fprintf(stderr, "bench_generate: %s\n", err.msg);
		return ret;
	}
	p->precision = PRECISION;
	p->levels = levels;
	p->leaf_amount = leaves;
	return 0;
}

struct series {
	double size, s; /* the previous row's, for the growth */
};

/* As bench_row, with the time per triangle and a wider name. */
static void row(const char *what, const struct figures *f, double s, struct series *prev)
{
	double n = (double)tris(f);

	printf("  %-28s %9.3f ms %7.1f ns/tri", what, 1e3 * s, 1e9 * s / n);
	if (prev->size > 0 && prev->s > 0)
		printf("   x%.2f for x%.1f size (~n^%.2f)", s / prev->s, n / prev->size,
		       log(s / prev->s) / log(n / prev->size));
	printf("\n");
	prev->size = n;
	prev->s = s;
}

static int by_size(struct figures *out)
{
	struct series gen = { 0 }, mesh = { 0 }, both = { 0 }, remesh = { 0 };

	printf("cherry-like trees (presets/cherry.yaml, precision %d, seed %d), median of %d runs "
	       "each from an empty tree and mesh;\ngrowth: time vs the size before, in triangles\n",
	       PRECISION, SEED, bench_reps(REPS));
	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		struct gen_params p;
		struct figures *f = &out[s];
		int ret = cherry(sizes[s].levels, sizes[s].leaves, &p);

		if (ret < 0 || (ret = measure(&p, bench_reps(REPS), f)) < 0) {
			fprintf(stderr, "bench_generate: ~%s: %s\n", sizes[s].label, strerror(-ret));
			return ret;
		}
		printf("~%s: levels %d, leaves.amount %d: %zu branches, %zu leaves; %zu triangles "
		       "(bark %zu, leaves %zu)\n",
		       sizes[s].label, p.levels, p.leaf_amount, f->branches, f->leaves, tris(f),
		       f->bark_tris, f->leaf_tris);
		row("gen_build", f, f->gen_s, &gen);
		row("tree_mesh_build", f, f->mesh_s, &mesh);
		row("both", f, f->total_s, &both);
		row("tree_mesh_build, used mesh", f, f->remesh_s, &remesh);
	}
	return 0;
}

static const struct gen_preset_text *preset_text(enum gen_preset which)
{
	for (size_t i = 0; i < gen_preset_ntexts; i++)
		if (!strcmp(gen_preset_texts[i].name, gen_preset_name(which)))
			return &gen_preset_texts[i];
	return NULL;
}

/* Median seconds of gen_read of a preset's compiled-in text. < 0 if it does not read. */
static double time_read(const struct gen_preset_text *text)
{
	double t[PRESET_READS];
	int reps = bench_reps(PRESET_READS);

	for (int i = 0; i < reps; i++) {
		struct gen_params p;
		struct error err;
		double t0 = bench_now();
		int ret = gen_read(text->text, text->len, text->name, 0, &p, &err);

		t[i] = bench_now() - t0;
		if (ret < 0) {
			fprintf(stderr, "bench_generate: %s\n", err.msg);
			return -1;
		}
	}
	return bench_median(t, (size_t)reps);
}

static int presets(void)
{
	printf("\nthe presets as the kiosk builds them, once each; gen_read of the file: median of "
	       "%d\n%-8s %-8s %4s %8s %7s %9s %10s %10s %10s %10s %8s\n",
	       bench_reps(PRESET_READS), "preset", "type", "prec", "branches", "leaves", "triangles", "read us",
	       "gen ms", "mesh ms", "both ms", "ns/tri");
	for (int i = 0; i < GEN_PRESET_COUNT; i++) {
		const struct gen_preset_text *text = preset_text((enum gen_preset)i);
		struct gen_params p;
		struct figures f;
		struct error err;
		double read_s, g, m, c;
		int ret = gen_preset((enum gen_preset)i, &p, &err);

		if (ret < 0 || !text) {
			fprintf(stderr, "bench_generate: preset %s: %s\n",
				gen_preset_name((enum gen_preset)i), ret < 0 ? err.msg : "no text");
			return -EINVAL;
		}
		read_s = time_read(text);
		if (read_s < 0)
			return -EINVAL;
		if ((ret = build_once(&p, &g, &m, &c, &f)) < 0) {
			fprintf(stderr, "bench_generate: %s: %s\n", text->name, strerror(-ret));
			return ret;
		}
		printf("%-8s %-8s %4d %8zu %7zu %9zu %10.1f %10.3f %10.3f %10.3f %8.1f\n",
		       text->name, gen_type_name(p.type), p.precision, f.branches, f.leaves, tris(&f),
		       read_s * 1e6, g * 1e3, m * 1e3, (g + m) * 1e3, 1e9 * (g + m) / (double)tris(&f));
	}
	return 0;
}

static int templates(void)
{
	double fresh[APP_REPS], tap[APP_REPS];
	size_t nb = 0, nl = 0;
	char what[96];
	int reps = bench_reps(APP_REPS);

	for (int i = 0; i < reps; i++) {
		struct app *app = app_create(1280, 800, SEED);

		if (!app)
			return -ENOMEM;
		/* on an empty canvas New only opens the strip: its time is the thumbnails' */
		fresh[i] = bench_press(app, BUTTON_NEW);
		if (!app->templates_ready) {
			fprintf(stderr, "bench_generate: New made no thumbnails\n");
			app_destroy(app);
			return -EINVAL;
		}
		tap[i] = bench_press(app, BUTTON_TPL_CHERRY);
		nb = app->tree.nbranches;
		nl = app->tree.nleaves;
		app_destroy(app);
	}
	printf("\nthe kiosk (app_handle_event), median of %d fresh apps\n", reps);
	snprintf(what, sizeof(what), "New: the %d template thumbnails (app_templates_build)",
		 GEN_PRESET_COUNT);
	printf("  %-70s %9.3f ms\n", what, 1e3 * bench_median(fresh, (size_t)reps));
	snprintf(what, sizeof(what),
		 "then tpl-cherry: the preset on the canvas (%zu branches, %zu leaves)", nb, nl);
	printf("  %-70s %9.3f ms\n", what, 1e3 * bench_median(tap, (size_t)reps));
	return 0;
}

static int eztree(const struct figures *ours)
{
	const char *labels[NSIZES];
	size_t targets[NSIZES];
	struct eztree_result ez[NSIZES];
	int n;

	printf("\nez-tree 1.1.0 (npm @dgreenheck/ez-tree, three.js, node), trees matched to ours "
	       "within %.0f%% in triangles;\nits Tree.generate(), median of %d after warm-up, "
	       "against our gen_build + tree_mesh_build above\n",
	       100 * MATCH, REPS);
	for (size_t s = 0; s < NSIZES; s++) {
		labels[s] = sizes[s].label;
		targets[s] = tris(&ours[s]);
	}
	n = eztree_run(labels, targets, NSIZES, REPS, ez);
	/* ez-tree missing or failing is said above; our figures stand without it */
	if (n <= 0)
		return 0;
	printf("%-5s %9s %9s %7s %9s %9s %8s %8s %7s %7s\n", "size", "ours tri", "ez-tree",
	       "diff", "ours ms", "ez ms", "ours ns", "ez ns", "wall x", "cpu x");
	for (size_t s = 0; s < NSIZES; s++) {
		const struct figures *f = &ours[s];
		double n = (double)tris(f), nez = (double)ez[s].triangles, diff = (nez - n) / n;

		printf("~%-4s %9zu %9zu %+6.1f%% %9.3f %9.3f %8.1f %8.1f %6.1fx %6.1fx%s\n",
		       sizes[s].label, tris(f), ez[s].triangles, 100 * diff, 1e3 * f->total_s,
		       1e3 * ez[s].median_s, 1e9 * f->total_s / n, 1e9 * ez[s].median_s / nez,
		       (ez[s].median_s / nez) / (f->total_s / n), (ez[s].cpu_s / nez) / (f->cpu_s / n),
		       diff > MATCH || diff < -MATCH ? "  (not matched)" : "");
	}
	printf("(ms per tree, ns per triangle, wall time; wall x, cpu x: how many times faster ours\n"
	       " is per triangle, by wall time and by CPU time (node's all threads: GC, JIT))\n");
	for (size_t s = 0; s < NSIZES; s++)
		printf("  ez-tree ~%s: %s; bark %zu, leaves %zu triangles\n", sizes[s].label,
		       ez[s].options, ez[s].bark, ez[s].leaves);
	return 0;
}

int main(int argc, char **argv)
{
	struct figures ours[NSIZES];

	if (bench_init(&argc, argv, NULL))
		return 1;
	/* --quick leaves ez-tree out: node, and not edaha's code */
	if (by_size(ours) < 0 || presets() < 0 || templates() < 0 ||
	    (!bench_quick && eztree(ours) < 0))
		return 1;
	return 0;
}
