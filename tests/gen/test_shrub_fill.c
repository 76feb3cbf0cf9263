/* SPDX-License-Identifier: MIT */
/*
 * A clipped shrub fills its shape whatever its parameters (issue 24, item 3;
 * docs/functional-trees.md, "Shrub and palm"): random valid parameter files of each shape,
 * written as YAML and read by the real reader (gen_read), grown by the real generator
 * (gen_build), and measured with the tests' own geometry (shape.c):
 *
 * - inside: every crown branch with its radius round each point, and every leaf, is inside
 *   the shape within INSIDE_TOL;
 * - reach: REACH_DIRS points spread evenly by area over the shape's whole surface (for a
 *   sphere, that many directions spread evenly over it: reach_points); a leaf whose centre
 *   lies within two leaf lengths of the surface reaches the nearest of them on that part
 *   of the surface (reach_at); at least REACH_WANT of the points are reached. A bare shrub
 *   (leaves.amount 0) is measured by its twigs' ends;
 * - honest counts: no more branches and leaves than gen_count_branches and
 *   gen_count_leaves say (the drawing's and the tree's limits rest on them);
 * - deterministic: every tenth file grown again with the same seed gives the same tree.
 *
 * Files span the format's ranges: spheres of 0.1 to 20 m, boxes of 0.1 to 40 m edges each
 * (slabs and rods too), cones of every proportion, a fifth of them far from the origin;
 * the trunk's top anywhere well inside the shape (off its centre, near its surface); 1 to
 * 12 levels, 2 or 3 children, 0 to 200 leaves a tip (mostly few), any angles, ratios,
 * spread, twist, precision and leaf outline. Two things no crown can do are left out, as
 * docs/functional-trees.md says: leaves longer than a third of the shape's inradius (the
 * largest ball inside it) do not fit inside it near its surface, and twigs whose bark is
 * thick against their leaves keep them too deep (the bark keeps 2.2 radii from the
 * surface). So leaves are 5 mm to a third of the inradius long (at most 5 m), and the
 * crown's first branches (thickness x thickness_ratio) at most a tenth of the inradius
 * thick, and its fifth generation's (a crown has at least five) at most half a leaf.
 * The fewest directions reached, and the file that gave them, are printed for each shape.
 */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw.h"
#include "gen.h"
#include "shape.h"
#include "test.h"
#include "tree.h"

#define FILES_PER_SHAPE 300
#define REACH_DIRS 100
#define REACH_WANT 85
#define PI 3.14159265358979323846
#define INSIDE_TOL 1e-9 /* metres: rounding (the generator keeps bark 2.2 radii in, leaves 2 mm) */

struct file {
	char yaml[2048];
	struct shape sh;
	double leaf_size;
	int amount;
};

/* A random point at least `margin` inside the shape (false when none was found). */
static bool inside_point(uint64_t *s, const struct shape *sh, double margin, double x[3])
{
	double lo[3], hi[3];

	for (int k = 0; k < 3; k++) {
		double ext = sh->kind == SHAPE_BOX ? sh->half[k] : sh->r;

		lo[k] = sh->c[k] - ext;
		hi[k] = sh->c[k] + ext;
	}
	if (sh->kind == SHAPE_CONE) {
		lo[1] = sh->c[1];
		hi[1] = sh->c[1] + sh->h;
	}
	for (int tries = 0; tries < 1000; tries++) {
		for (int k = 0; k < 3; k++)
			x[k] = draw_span(s, lo[k], hi[k]);
		if (shape_distance(sh, x) < -margin)
			return true;
	}
	return false;
}

static const char *const leaf_types[] = { "oval", "pointed", "round", "needle", "leaflet" };

/* A random valid file of the shape kind; false to draw again. */
static bool draw_file(uint64_t *s, enum shape_kind kind, struct file *f)
{
	struct shape *sh = &f->sh;
	double top[3], ratio, thickness, amin, amax, in, trunk_h;
	char ratios[96];
	int levels = 1 + (int)(draw_uni(s) * 12), children = draw_uni(s) < 0.5 ? 2 : 3, len;
	double u = draw_uni(s);

	memset(sh, 0, sizeof(*sh));
	sh->kind = kind;
	for (int k = 0; k < 3; k++)
		sh->c[k] = draw_uni(s) < 0.2 ? draw_span(s, -900, 900) : draw_span(s, -3, 3);
	switch (kind) {
	case SHAPE_SPHERE:
		sh->r = draw_logspan(s, 0.1, 20);
		break;
	case SHAPE_BOX:
		for (int k = 0; k < 3; k++)
			sh->half[k] = 0.5 * draw_logspan(s, 0.1, 40);
		break;
	case SHAPE_CONE:
		sh->r = draw_logspan(s, 0.1, 20);
		sh->h = draw_logspan(s, 0.1, 40);
		break;
	}
	in = shape_inradius(sh);
	/* sparse settings often: one leaf a tip, few levels */
	f->amount = u < 0.3 ? 1 : u < 0.4 ? 0 : u < 0.9 ? 1 + (int)(draw_uni(s) * 10) : (int)draw_span(s, 11, 201);
	/* leaves at most a third of the shape's inradius long (and 5 m) */
	f->leaf_size = draw_logspan(s, 0.005, fmin(5.0, in / 3.0));
	ratio = draw_span(s, 0.01, 1.0);
	/* the crown's first twigs at most a tenth of the inradius thick, and its fifth
	 * generation's at most half a leaf */
	thickness = draw_logspan(s, 0.001, fmin(5.0, fmin(in / 10.0 / ratio, 0.5 * f->leaf_size / pow(ratio, 6))));
	/* the trunk's top well inside (2.2 of the crown's radii: tree-params.md) */
	if (!inside_point(s, sh, 2.2 * thickness * ratio * 1.01, top))
		return false;
	trunk_h = draw_logspan(s, 0.05, 20);
	amin = draw_span(s, 0, 180);
	amax = draw_span(s, amin, 180);
	len = snprintf(ratios, sizeof(ratios), "%.17g, %.17g", draw_span(s, 0.01, 1.5), draw_span(s, 0.01, 1.5));
	if (children == 3)
		len = snprintf(ratios + len, sizeof(ratios) - (size_t)len, ", %.17g", draw_span(s, 0.01, 1.5));
	len = snprintf(f->yaml, sizeof(f->yaml),
		       "edaha-tree: 1\ntype: shrub\nprecision: %d\n"
		       "trunk: {start: [%.17g, %.17g, %.17g]}\ntrunk_height: %.17g\n"
		       "levels: %d\nchildren: %d\n"
		       "angle: {min: %.17g, max: %.17g, randomness: %.17g}\n"
		       "ratios: [%s]\nspread: %.17g\ntwist: %.17g\n"
		       "thickness: %.17g\nthickness_ratio: %.17g\n"
		       "leaves: {amount: %d, size: %.17g, type: %s}\n",
		       3 + (int)(draw_uni(s) * 14), top[0], top[1] - trunk_h, top[2], trunk_h, levels, children,
		       amin, amax, draw_uni(s), ratios, draw_span(s, 0, 360), draw_span(s, -360, 360),
		       thickness, ratio, f->amount, f->leaf_size, leaf_types[draw_mix(s) % 5]);
	CHECK(len > 0 && (size_t)len < sizeof(f->yaml));
	draw_put_clip(f->yaml, sizeof(f->yaml), sh);
	return true;
}

/* The most points nothing is outside by, over the crown's bark and every leaf. */
static double outermost(const struct tree *t, const struct shape *sh)
{
	double worst = -INFINITY;

	for (size_t i = 1; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		for (size_t k = 0; k < b->npoints; k++) {
			double x[3] = { b->points[k].x, b->points[k].y, b->points[k].z };

			worst = fmax(worst, shape_distance(sh, x) + b->radii[k]);
		}
	}
	for (size_t i = 0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++) {
			struct vec3 p = t->leaves[i].points[k];
			double x[3] = { p.x, p.y, p.z };

			worst = fmax(worst, shape_distance(sh, x));
		}
	return worst;
}

/* The radical inverse of j in base b: the Halton sequence. */
static double halton(unsigned j, unsigned b)
{
	double f = 1.0, r = 0.0;

	for (; j > 0; j /= b) {
		f /= b;
		r += f * (j % b);
	}
	return r;
}

/* n points shared among parts by their areas: the largest remainders get one more. */
static void share(const double *area, int parts, int n, int *k)
{
	double sum = 0, rest[6];
	int given = 0;

	for (int i = 0; i < parts; i++)
		sum += area[i];
	for (int i = 0; i < parts; i++) {
		k[i] = (int)floor(n * area[i] / sum);
		rest[i] = n * area[i] / sum - k[i];
		given += k[i];
	}
	for (; given < n; given++) {
		int best = 0;

		for (int i = 1; i < parts; i++)
			if (rest[i] > rest[best])
				best = i;
		k[best]++;
		rest[best] = -1;
	}
}

/*
 * REACH_DIRS points spread evenly by area over the whole surface, and the outward normal at
 * each: a sphere's are shape_sample's (a Fibonacci sphere: evenly spread directions); a
 * box's faces and a cone's base and side each get their share by area, spread by the
 * Halton sequence (bases 2 and 3): a sequence of the tests' own, not the generator's.
 */
static void reach_points(const struct shape *sh, double (*p)[3], double (*nrm)[3])
{
	int k[6], at = 0;

	if (sh->kind == SHAPE_SPHERE) {
		for (int j = 0; j < REACH_DIRS; j++)
			shape_sample(sh, (unsigned)j, REACH_DIRS, p[j], nrm[j]);
		return;
	}
	if (sh->kind == SHAPE_BOX) {
		const double *h = sh->half;
		double area[6];

		for (int f = 0; f < 6; f++)
			area[f] = h[(f / 2 + 1) % 3] * h[(f / 2 + 2) % 3];
		share(area, 6, REACH_DIRS, k);
		for (int f = 0; f < 6; f++) {
			int axis = f / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;

			for (int j = 0; j < k[f]; j++, at++) {
				double sign = f % 2 ? 1.0 : -1.0;

				nrm[at][0] = nrm[at][1] = nrm[at][2] = 0;
				nrm[at][axis] = sign;
				p[at][axis] = sh->c[axis] + sign * h[axis];
				p[at][a] = sh->c[a] + (2 * halton((unsigned)j + 1, 2) - 1) * h[a];
				p[at][b] = sh->c[b] + (2 * halton((unsigned)j + 1, 3) - 1) * h[b];
			}
		}
		return;
	}
	{
		double slant = hypot(sh->r, sh->h), area[2] = { sh->r * sh->r, sh->r * slant };

		share(area, 2, REACH_DIRS, k);
		for (int part = 0; part < 2; part++) {
			for (int j = 0; j < k[part]; j++, at++) {
				/* uniform by area: the radius (from the apex, on the side) as a root */
				double t = sqrt(halton((unsigned)j + 1, 2)), phi = 2 * PI * halton((unsigned)j + 1, 3);
				double rho = sh->r * t;

				p[at][0] = sh->c[0] + rho * cos(phi);
				p[at][1] = sh->c[1] + (part ? sh->h * (1 - t) : 0);
				p[at][2] = sh->c[2] + rho * sin(phi);
				if (part) {
					nrm[at][0] = sh->h * cos(phi) / slant;
					nrm[at][1] = sh->r / slant;
					nrm[at][2] = sh->h * sin(phi) / slant;
				} else {
					nrm[at][0] = nrm[at][2] = 0;
					nrm[at][1] = -1;
				}
			}
		}
	}
}

/* The outward normal of the surface nearest x (the distance's gradient). */
static void normal_at(const struct shape *sh, const double x[3], double n[3])
{
	const double h = 1e-6;
	double len = 0;

	for (int k = 0; k < 3; k++) {
		double a[3] = { x[0], x[1], x[2] }, b[3] = { x[0], x[1], x[2] };

		a[k] += h;
		b[k] -= h;
		n[k] = shape_distance(sh, a) - shape_distance(sh, b);
		len += n[k] * n[k];
	}
	for (int k = 0; k < 3; k++)
		n[k] = len > 0 ? n[k] / sqrt(len) : 0;
}

/* A point x within `near` of the surface reaches the nearest of the points on that part of
 * the surface (their normals within 60 degrees of the one nearest x): so a thin slab's
 * leaves under its top do not count for its bottom. */
static void reach_at(const struct shape *sh, const double (*dirs)[3], const double (*normals)[3],
		     bool *hit, const double x[3], double near)
{
	double best = INFINITY, n[3];
	int j_best = -1;

	if (shape_distance(sh, x) < -near)
		return;
	normal_at(sh, x, n);
	for (int j = 0; j < REACH_DIRS; j++) {
		double d = pow(x[0] - dirs[j][0], 2) + pow(x[1] - dirs[j][1], 2) + pow(x[2] - dirs[j][2], 2);

		if (n[0] * normals[j][0] + n[1] * normals[j][1] + n[2] * normals[j][2] >= 0.5 && d < best) {
			best = d;
			j_best = j;
		}
	}
	if (j_best >= 0)
		hit[j_best] = true;
}

/* How many of the REACH_DIRS points have a leaf (a bare shrub: a twig's end) reaching them. */
static int reached(const struct tree *t, const struct shape *sh, double leaf_size)
{
	double dirs[REACH_DIRS][3], normals[REACH_DIRS][3];
	bool hit[REACH_DIRS] = { false }, parent[TREE_MAX_BRANCHES] = { false };
	int n = 0;

	reach_points(sh, dirs, normals);
	for (size_t i = 0; i < t->nleaves; i++) {
		double c[3] = { 0, 0, 0 };

		for (size_t k = 0; k < t->leaves[i].npoints; k++) {
			c[0] += t->leaves[i].points[k].x / (double)t->leaves[i].npoints;
			c[1] += t->leaves[i].points[k].y / (double)t->leaves[i].npoints;
			c[2] += t->leaves[i].points[k].z / (double)t->leaves[i].npoints;
		}
		reach_at(sh, (const double (*)[3])dirs, (const double (*)[3])normals, hit, c, 2 * leaf_size);
	}
	if (t->nleaves == 0) {
		for (size_t i = 1; i < t->nbranches; i++)
			parent[t->branches[i].parent] = true;
		for (size_t i = 1; i < t->nbranches; i++) {
			const struct branch *b = &t->branches[i];
			struct vec3 e = b->points[b->npoints - 1];
			double x[3] = { e.x, e.y, e.z };

			if (!parent[i])
				reach_at(sh, (const double (*)[3])dirs, (const double (*)[3])normals, hit, x,
					 2 * leaf_size);
		}
	}
	for (int j = 0; j < REACH_DIRS; j++)
		n += hit[j];
	return n;
}

static bool same_tree(const struct tree *a, const struct tree *b)
{
	if (a->nbranches != b->nbranches || a->nleaves != b->nleaves)
		return false;
	for (size_t i = 0; i < a->nbranches; i++)
		if (a->branches[i].npoints != b->branches[i].npoints ||
		    memcmp(a->branches[i].points, b->branches[i].points,
			   a->branches[i].npoints * sizeof(*a->branches[i].points)) ||
		    memcmp(a->branches[i].radii, b->branches[i].radii,
			   a->branches[i].npoints * sizeof(*a->branches[i].radii)))
			return false;
	for (size_t i = 0; i < a->nleaves; i++)
		if (a->leaves[i].npoints != b->leaves[i].npoints ||
		    memcmp(a->leaves[i].points, b->leaves[i].points,
			   a->leaves[i].npoints * sizeof(*a->leaves[i].points)))
			return false;
	return true;
}

static const char *const kind_names[] = { "sphere", "box", "cone" };

static int property(enum shape_kind kind, uint64_t seed)
{
	static struct tree t, again;
	uint64_t s = seed, seed_of_tree;
	int worst = REACH_DIRS + 1, drawn = 0, refused = 0, bare = 0, histogram[REACH_DIRS + 1] = { 0 };
	double out_worst = -INFINITY;
	size_t most_branches = 0, most_leaves = 0;
	char worst_file[2048] = "";
	int failures = 0;

	tree_init(&t);
	tree_init(&again);
	while (drawn < test_cases(FILES_PER_SHAPE)) {
		struct gen_params p;
		struct file f;
		struct error err;
		double out;
		int n;

		if (!draw_file(&s, kind, &f))
			continue;
		if (gen_read(f.yaml, strlen(f.yaml), "random.yaml", 0, &p, &err) < 0) {
			/* only the tree's limits refuse these (too many branches or leaves) */
			if (!strstr(err.msg, "the tree would have")) {
				fprintf(stderr, "refused: %s\n%s", err.msg, f.yaml);
				CHECK(false);
			}
			refused++;
			continue;
		}
		drawn++;
		bare += f.amount == 0;
		seed_of_tree = draw_mix(&s);
		CHECK_INT(gen_build(&t, &p, seed_of_tree), 0);
		/* deterministic: the same file and seed, the same tree (every tenth file) */
		if (drawn % 10 == 0) {
			CHECK_INT(gen_build(&again, &p, seed_of_tree), 0);
			CHECK(same_tree(&t, &again));
		}
		if (t.nbranches > gen_count_branches(&p) || t.nleaves > gen_count_leaves(&p)) {
			fprintf(stderr, "%zu branches and %zu leaves, over the counts %zu and %zu:\n%s\n",
				t.nbranches, t.nleaves, gen_count_branches(&p), gen_count_leaves(&p), f.yaml);
			CHECK(false);
		}
		most_branches = t.nbranches > most_branches ? t.nbranches : most_branches;
		most_leaves = t.nleaves > most_leaves ? t.nleaves : most_leaves;
		out = outermost(&t, &f.sh);
		out_worst = fmax(out_worst, out);
		n = reached(&t, &f.sh, f.leaf_size);
		if (out > INSIDE_TOL || n < REACH_WANT) {
			fprintf(stderr, "%s: %d of %d reached, %.3g m outside (%zu branches, %zu leaves):\n%s\n",
				kind_names[kind], n, REACH_DIRS, out, t.nbranches, t.nleaves, f.yaml);
			failures++;
		}
		histogram[n]++;
		if (n < worst) {
			worst = n;
			snprintf(worst_file, sizeof(worst_file), "%s", f.yaml);
		}
	}
	printf("%s: %d files (%d bare; %d more drawn were over the tree's limits): the fewest reached "
	       "%d of %d (want %d), the outermost point %.2g m from the surface; at most %zu branches, "
	       "%zu leaves\nthe file of the fewest:\n%s\n",
	       kind_names[kind], drawn, bare, refused, worst, REACH_DIRS, REACH_WANT, out_worst,
	       most_branches, most_leaves, worst_file);
	printf("%s: files by directions reached:", kind_names[kind]);
	for (int j = 0; j <= REACH_DIRS; j++)
		if (histogram[j])
			printf(" %d: %d", j, histogram[j]);
	printf("\n");
	tree_finish(&t);
	tree_finish(&again);
	return failures;
}

int main(void)
{
	/* every shape measured before any failure is told */
	int failures = property(SHAPE_SPHERE, 1) + property(SHAPE_BOX, 2) + property(SHAPE_CONE, 3);

	CHECK_INT(failures, 0);
	return 0;
}
