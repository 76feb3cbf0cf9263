/* SPDX-License-Identifier: MIT */
/*
 * Generator versions (gen.h, GEN_VERSION; docs/functional-trees.md, "Generator versions"):
 * a tree built at version V is the tree that edaha's generators of version V built, bit for
 * bit, so that a drawing keeps its trees whatever edaha loads it. RANDOM_FILES random valid
 * parameter files (lsystem, shrubs of each shape, palms; a fifth each) are read at each
 * version by the real reader (gen_read_version) and grown (gen_build); a digest of each tree
 * (every branch's parent, level, points and radii, every leaf's branch, place and points)
 * is compared with the one recorded in versions/random-trees.txt:
 *
 *   version 1  what edaha at 4394a65 (the last before issue 24's shrubs) grew
 *   version 2  what edaha at 9753074 (issue 24's shrubs merged) grew
 *
 * and a file that edaha refused (over its limits) is refused at the same version now, and
 * only such a file. Every tree is within the counts gen_count_branches and gen_count_leaves
 * give at its version (the drawing's limits rest on them): the least margins are printed.
 *
 * The table was recorded by this very file, built with -DGEN_VERSION_RECORD against those
 * commits' core library (whose gen_read gave their one version), where it prints a digest
 * or "-" for each file:
 *
 *   git worktree add --detach /tmp/old 4394a65
 *   (cd /tmp/old && meson setup build && meson compile -C build src/libedaha_core.a)
 *   cc -std=c11 -O2 -DGEN_VERSION_RECORD -I/tmp/old/src -Itests/lib -Ibuild/tests/lib \
 *      tests/gen/test_gen_version.c tests/gen/shape.c tests/gen/draw.c \
 *      /tmp/old/build/src/libedaha_core.a -lyaml -lm -o /tmp/record-1
 *   /tmp/record-1 > /tmp/v1.txt
 *
 * and the same at 9753074 for the second column (paste, with the type in the middle).
 */
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "draw.h"
#include "gen.h"
#include "shape.h"
#include "test.h"
#include "tree.h"

#define RANDOM_FILES 500
#define RECORDED_VERSIONS 2

static const char *const leaf_types[] = { "oval", "pointed", "round", "needle", "leaflet",
					  "entire", "hop", "maple" };
static const char *const seasons[] = { "spring", "summer", "autumn", "winter" };
static const char *const kinds[] = { "lsystem", "sphere", "box", "cone", "palm" };

/* Leaves: mostly few a tip, sometimes many (the limits refuse some). */
static void put_leaves(uint64_t *s, char *yaml, size_t size, double lo, double hi)
{
	double u = draw_uni(s);
	int amount = u < 0.15 ? 0 : u < 0.85 ? 1 + (int)(draw_uni(s) * 8) : (int)draw_span(s, 9, 80);

	draw_put(yaml, size, "leaves: {amount: %d, size: %.17g, type: %s}\nseason: %s\n", amount,
	         draw_logspan(s, lo, hi), leaf_types[draw_mix(s) % 8], seasons[draw_mix(s) % 4]);
}

/* The branching keys of lsystem and shrub. */
static void put_branching(uint64_t *s, char *yaml, size_t size, int max_levels)
{
	int children = draw_uni(s) < 0.5 ? 2 : 3;
	double amin = draw_span(s, 0, 120), amax = draw_span(s, amin, 130);

	draw_put(yaml, size, "levels: %d\nchildren: %d\nangle: {min: %.17g, max: %.17g, randomness: %.17g}\n",
	         1 + (int)(draw_uni(s) * max_levels), children, amin, amax, draw_uni(s));
	draw_put(yaml, size, "ratios: [%.17g, %.17g", draw_span(s, 0.3, 1.0), draw_span(s, 0.3, 1.0));
	if (children == 3)
		draw_put(yaml, size, ", %.17g", draw_span(s, 0.3, 1.0));
	draw_put(yaml, size, "]\nspread: %.17g\ntwist: %.17g\n", draw_span(s, 0, 360), draw_span(s, -360, 360));
}

/* A random point at least `margin` inside the shape (false when none was found). */
static bool inside_point(uint64_t *s, const struct shape *sh, double margin, double x[3])
{
	for (int tries = 0; tries < 1000; tries++) {
		for (int k = 0; k < 3; k++) {
			double ext = sh->kind == SHAPE_BOX ? sh->half[k] : sh->r;

			x[k] = draw_span(s, sh->c[k] - ext, sh->c[k] + ext);
		}
		if (sh->kind == SHAPE_CONE)
			x[1] = draw_span(s, sh->c[1], sh->c[1] + sh->h);
		if (shape_distance(sh, x) < -margin)
			return true;
	}
	return false;
}

static void draw_shrub(uint64_t *s, enum shape_kind kind, char *yaml, size_t size)
{
	struct shape sh = { .kind = kind };
	double top[3], ratio = draw_span(s, 0.4, 0.95), thickness, trunk_h, in;

	for (int k = 0; k < 3; k++)
		sh.c[k] = draw_uni(s) < 0.1 ? draw_span(s, -900, 900) : draw_span(s, -3, 3);
	switch (kind) {
	case SHAPE_SPHERE:
		sh.r = draw_logspan(s, 0.2, 4);
		break;
	case SHAPE_BOX:
		for (int k = 0; k < 3; k++)
			sh.half[k] = 0.5 * draw_logspan(s, 0.2, 6);
		break;
	case SHAPE_CONE:
	default:
		sh.r = draw_logspan(s, 0.2, 4);
		sh.h = draw_logspan(s, 0.3, 6);
		break;
	}
	in = shape_inradius(&sh);
	thickness = draw_logspan(s, 0.002, fmin(0.3, in / 10 / ratio));
	/* the trunk's top well inside (2.2 of the crown's radii), else anywhere: a file that
	 * is refused is recorded so */
	if (!inside_point(s, &sh, 2.2 * thickness * ratio * 1.01, top))
		top[0] = sh.c[0], top[1] = sh.c[1], top[2] = sh.c[2];
	trunk_h = draw_logspan(s, 0.05, 5);
	draw_put(yaml, size, "edaha-tree: 1\ntype: shrub\nprecision: %d\n", 3 + (int)(draw_uni(s) * 14));
	draw_put(yaml, size, "trunk: {start: [%.17g, %.17g, %.17g]}\ntrunk_height: %.17g\n", top[0],
	         top[1] - trunk_h, top[2], trunk_h);
	put_branching(s, yaml, size, 10);
	draw_put(yaml, size, "thickness: %.17g\nthickness_ratio: %.17g\n", thickness, ratio);
	put_leaves(s, yaml, size, 0.01, fmin(0.5, in / 3));
	draw_put_clip(yaml, size, &sh);
}

static void draw_lsystem(uint64_t *s, char *yaml, size_t size)
{
	double x = draw_span(s, -3, 3), y = draw_span(s, -1, 1), z = draw_span(s, -3, 3);

	draw_put(yaml, size, "edaha-tree: 1\ntype: lsystem\nprecision: %d\n", 3 + (int)(draw_uni(s) * 14));
	draw_put(yaml, size, "trunk: {start: [%.17g, %.17g, %.17g], end: [%.17g, %.17g, %.17g]}\n", x, y, z,
	         x + draw_span(s, -1, 1), y + draw_span(s, 0.2, 5), z + draw_span(s, -1, 1));
	put_branching(s, yaml, size, 10);
	draw_put(yaml, size, "thickness: %.17g\nthickness_ratio: %.17g\n", draw_logspan(s, 0.005, 0.5),
		 draw_span(s, 0.3, 1));
	put_leaves(s, yaml, size, 0.01, 0.5);
}

static void draw_palm(uint64_t *s, char *yaml, size_t size)
{
	double lean = draw_span(s, 0, 19) * 3.14159265358979323846 / 180, az = draw_span(s, 0, 6.283);
	double amin = draw_span(s, 0, 120), amax = draw_span(s, amin, 130), x = draw_span(s, -3, 3),
	       z = draw_span(s, -3, 3);

	draw_put(yaml, size, "edaha-tree: 1\ntype: palm\nprecision: %d\n", 3 + (int)(draw_uni(s) * 14));
	draw_put(yaml, size, "trunk: {start: [%.17g, 0, %.17g], end: [%.17g, %.17g, %.17g]}\n", x, z,
	         x + sin(lean) * cos(az), cos(lean), z + sin(lean) * sin(az));
	draw_put(yaml, size, "height: %.17g\nfronds: %d\nfrond_length: %.17g\ndroop: %.17g\n",
		 draw_span(s, 0.5, 15), 1 + (int)(draw_uni(s) * 40), draw_logspan(s, 0.1, 6),
		 draw_span(s, 0, 180));
	draw_put(yaml, size, "angle: {min: %.17g, max: %.17g, randomness: %.17g}\n", amin, amax, draw_uni(s));
	draw_put(yaml, size, "thickness: %.17g\nthickness_ratio: %.17g\n", draw_logspan(s, 0.02, 0.5),
		 draw_span(s, 0.3, 1));
	put_leaves(s, yaml, size, 0.05, 1.5);
}

/* File i of the set: its kind (an index of kinds[]) and its text. */
static int draw(unsigned i, char *yaml, size_t size)
{
	uint64_t s = 0x5eed0000ULL + i;
	int kind = (int)(i % 5);

	yaml[0] = '\0';
	if (kind == 0)
		draw_lsystem(&s, yaml, size);
	else if (kind == 4)
		draw_palm(&s, yaml, size);
	else
		draw_shrub(&s, (enum shape_kind)(kind - 1), yaml, size);
	return kind;
}

static void fnv(uint64_t *h, const void *data, size_t len)
{
	const unsigned char *b = data;

	for (size_t i = 0; i < len; i++)
		*h = (*h ^ b[i]) * 0x100000001b3ULL;
}

static void fnv_int(uint64_t *h, long long v)
{
	int64_t x = v;

	fnv(h, &x, sizeof(x));
}

/* Every number of the tree's elements that the generator made, bit for bit. */
static uint64_t digest(const struct tree *t)
{
	uint64_t h = 0xcbf29ce484222325ULL;

	fnv_int(&h, (long long)t->nbranches);
	fnv_int(&h, (long long)t->nleaves);
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		fnv_int(&h, b->parent);
		fnv_int(&h, b->level);
		fnv(&h, &b->parent_t, sizeof(b->parent_t));
		fnv_int(&h, (long long)b->npoints);
		fnv(&h, b->points, b->npoints * sizeof(*b->points));
		fnv(&h, b->radii, b->npoints * sizeof(*b->radii));
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];

		fnv_int(&h, l->branch);
		fnv(&h, &l->branch_t, sizeof(l->branch_t));
		fnv_int(&h, (long long)l->npoints);
		fnv(&h, l->points, l->npoints * sizeof(*l->points));
	}
	return h;
}

/* The seed a file's tree grows from. */
static uint64_t seed_of(unsigned i)
{
	uint64_t s = 0xb1d0000ULL + i;

	return draw_mix(&s);
}

#ifdef GEN_VERSION_RECORD
/* The digests of this edaha (its one generator version): "I KIND DIGEST", or "I KIND -"
 * refused. */
int main(void)
{
	static char yaml[4096];
	static struct tree t;

	tree_init(&t);
	for (unsigned i = 0; i < RANDOM_FILES; i++) {
		struct gen_params p;
		struct error err;

		int kind = draw(i, yaml, sizeof(yaml));

		if (gen_read(yaml, strlen(yaml), "random.yaml", 0, &p, &err) < 0) {
			fprintf(stderr, "%u %s: %s\n", i, kinds[kind], err.msg);
			printf("%u %s -\n", i, kinds[kind]);
			continue;
		}
		CHECK_INT(gen_build(&t, &p, seed_of(i)), 0);
		printf("%u %s %016" PRIx64 "\n", i, kinds[kind], digest(&t));
	}
	tree_finish(&t);
	return 0;
}
#else
struct recorded {
	char kind[16];
	char digest[RECORDED_VERSIONS][24]; /* hex, or "-": refused */
};

/* versions/random-trees.txt: "I KIND DIGEST_V1 DIGEST_V2" a line, # comments. */
static void read_table(const char *path, struct recorded *rec)
{
	FILE *f = fopen(path, "r");
	char line[256];
	unsigned n = 0;

	if (!f) {
		perror(path);
		exit(1);
	}
	while (fgets(line, sizeof(line), f)) {
		unsigned i;

		if (line[0] == '#' || line[0] == '\n')
			continue;
		CHECK(sscanf(line, "%u %15s %23s %23s", &i, rec[n].kind, rec[n].digest[0], rec[n].digest[1]) == 4);
		CHECK_INT(i, n);
		n++;
		CHECK(n <= RANDOM_FILES);
	}
	fclose(f);
	CHECK_INT(n, RANDOM_FILES);
}

struct margins {
	long long branches, leaves; /* the least count - grown */
	unsigned built, refused;
};

static void print_margins(int v, const char *what, const struct margins *m)
{
	printf("version %d, %s: %u grown as recorded, %u refused as recorded; the least margins of "
	       "gen_count_branches and gen_count_leaves over the tree grown: %lld branches, %lld leaves\n",
	       v, what, m->built, m->refused, m->branches, m->leaves);
}

int main(int argc, char **argv)
{
	static char yaml[4096];
	static struct recorded rec[RANDOM_FILES];
	static struct tree t;
	struct margins m[RECORDED_VERSIONS + 1][2]; /* lsystem and palm; shrubs */
	unsigned shrubs_differ = 0, shrubs_both = 0, failures = 0;

	CHECK(argc == 2);
	/* a new version records its column (above) before it is released */
	CHECK(RECORDED_VERSIONS == GEN_VERSION);
	read_table(argv[1], rec);
	tree_init(&t);
	for (int v = 1; v <= GEN_VERSION; v++)
		for (int k = 0; k < 2; k++)
			m[v][k] = (struct margins){ LLONG_MAX, LLONG_MAX, 0, 0 };
	for (unsigned i = 0; i < RANDOM_FILES; i++) {
		int kind = draw(i, yaml, sizeof(yaml));
		char got[GEN_VERSION + 1][24];

		CHECK(!strcmp(rec[i].kind, kinds[kind]));
		/* what the first version made of an lsystem tree or a palm, the second did too */
		if (kind == 0 || kind == 4)
			CHECK(!strcmp(rec[i].digest[0], rec[i].digest[1]));
		for (int v = 1; v <= GEN_VERSION; v++) {
			struct margins *mv = &m[v][kind >= 1 && kind <= 3];
			struct gen_params p;
			struct error err;
			size_t nb, nl;

			if (gen_read_version(yaml, strlen(yaml), "random.yaml", 0, v, &p, &err) < 0) {
				/* only the limits refuse these files */
				CHECK(strstr(err.msg, "the tree would have") || strstr(err.msg, "not well inside"));
				snprintf(got[v], sizeof(got[v]), "-");
				mv->refused++;
			} else {
				CHECK_INT(p.gen_version, v);
				CHECK_INT(gen_build(&t, &p, seed_of(i)), 0);
				snprintf(got[v], sizeof(got[v]), "%016" PRIx64, digest(&t));
				nb = gen_count_branches(&p);
				nl = gen_count_leaves(&p);
				CHECK(t.nbranches <= nb && t.nleaves <= nl);
				/* an lsystem tree's and a palm's are exact */
				if (kind == 0 || kind == 4)
					CHECK(t.nbranches == nb && t.nleaves == nl);
				if ((long long)(nb - t.nbranches) < mv->branches)
					mv->branches = (long long)(nb - t.nbranches);
				if ((long long)(nl - t.nleaves) < mv->leaves)
					mv->leaves = (long long)(nl - t.nleaves);
				mv->built++;
			}
			if (strcmp(got[v], rec[i].digest[v - 1])) {
				fprintf(stderr, "file %u (%s) at version %d: %s, recorded %s\n%s\n", i, kinds[kind],
					v, got[v], rec[i].digest[v - 1], yaml);
				failures++;
			}
		}
		if (kind >= 1 && kind <= 3 && strcmp(got[1], "-") && strcmp(got[2], "-")) {
			shrubs_both++;
			shrubs_differ += !!strcmp(got[1], got[2]);
		}
	}
	for (int v = 1; v <= GEN_VERSION; v++) {
		print_margins(v, "lsystem and palm", &m[v][0]);
		print_margins(v, "shrubs", &m[v][1]);
	}
	printf("shrubs grown at both versions: %u, %u of them different trees\n", shrubs_both, shrubs_differ);
	tree_finish(&t);
	CHECK_INT(failures, 0);
	return 0;
}
#endif
