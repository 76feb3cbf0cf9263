/* SPDX-License-Identifier: MIT */
/*
 * gen_check: the rules of docs/functional-trees.md, asserted on what the real binary
 * wrote (skeleton.json, model.glb). gen.sh runs edaha and calls one of these:
 *
 *   gen_check tree SKEL LEVELS CHILDREN RATIOS LEAVES
 *       an lsystem tree: counts, children at their parent's tip, lengths by the ratios
 *       (RATIOS "0.8,0.6"), levels, leaves.amount on each tip and nowhere else
 *   gen_check angles MIN MAX RANDOMNESS COVER SKEL...
 *       every parent-child angle within mid +- randomness (max - min) / 2; with COVER > 0
 *       the angles seen come within COVER of that range's ends
 *   gen_check spread SPREAD SKEL
 *       siblings SPREAD apart about their parent's axis; for a vertical trunk, the angle
 *       at its foot between the ground projections of its first two children's ends
 *   gen_check radii TYPE THICKNESS RATIO SKEL
 *       the thickness rules (TYPE lsystem, shrub or palm)
 *   gen_check palm FRONDS LEAVES SKEL
 *       fronds at the trunk's top, a bare trunk, leaflets on each frond
 *   gen_check clip SKEL SHAPE... [glb FULL.glb TRUNK.glb] [fill DELTA FRACTION]
 *       a shrub's crown inside its shape (SHAPE "sphere CX CY CZ R", "box CX CY CZ SX SY
 *       SZ", "cone CX CY CZ R H"), model.glb's crown vertices within 1 mm of it, and the
 *       crown filling it (gen_fill.c)
 *   gen_check precision N GLB [N GLB]...
 *       bark triangles about linear in the sides N, leaves the same
 *   gen_check param FILE KEY [DEFAULT]
 *       prints a parameter file's value (check_param.c)
 *
 * Exit 0 when the rule holds, 1 with what broke it on stderr, 2 on bad use.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_check.h"

int failures;

void bad(const char *fmt, ...)
{
	va_list ap;

	/* the first few say what broke; the count says how much */
	if (failures++ < 10) {
		fputs("FAIL: ", stderr);
		va_start(ap, fmt);
		vfprintf(stderr, fmt, ap);
		va_end(ap);
		fputc('\n', stderr);
	}
}

int finish(const char *what)
{
	if (failures) {
		fprintf(stderr, "%s: %d failures\n", what, failures);
		return 1;
	}
	return 0;
}

static int usage(void)
{
	fprintf(stderr, "usage: gen_check tree|angles|spread|radii|palm|clip|precision|param ... "
			"(tests/gen/gen_check.c)\n");
	return 2;
}

int main(int argc, char **argv)
{
	static const struct {
		const char *name;
		int (*run)(int argc, char **argv);
	} cmds[] = {
		{ "tree", check_tree },	    { "angles", check_angles }, { "spread", check_spread },
		{ "radii", check_radii },   { "palm", check_palm },	{ "clip", check_clip },
		{ "precision", check_precision }, { "param", check_param },
	};

	if (argc < 2)
		return usage();
	for (size_t i = 0; i < sizeof(cmds) / sizeof(cmds[0]); i++)
		if (!strcmp(argv[1], cmds[i].name))
			return cmds[i].run(argc - 2, argv + 2);
	return usage();
}

void load_skel(const char *path, struct skel *s)
{
	if (skel_load(path, s) < 0)
		exit(2);
}

int parse_list(const char *s, double *v, int max)
{
	int n = 0;
	char *end;

	while (n < max && *s) {
		v[n++] = strtod(s, &end);
		if (end == s)
			return -1;
		s = *end == ',' ? end + 1 : end;
	}
	return n;
}

double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double dist3(const double a[3], const double b[3])
{
	return sqrt(pow(a[0] - b[0], 2) + pow(a[1] - b[1], 2) + pow(a[2] - b[2], 2));
}

double angle_deg(const double a[3], const double b[3])
{
	double c = dot3(a, b);

	return acos(c > 1 ? 1 : c < -1 ? -1 : c) * DEG_PER_RAD;
}

double azimuth_deg(const double a[3], const double b[3], const double k[3])
{
	double pa[3], pb[3], cross[3], deg;

	for (int i = 0; i < 3; i++) {
		pa[i] = a[i] - dot3(a, k) * k[i];
		pb[i] = b[i] - dot3(b, k) * k[i];
	}
	cross[0] = pa[1] * pb[2] - pa[2] * pb[1];
	cross[1] = pa[2] * pb[0] - pa[0] * pb[2];
	cross[2] = pa[0] * pb[1] - pa[1] * pb[0];
	deg = atan2(dot3(cross, k), dot3(pa, pb)) * DEG_PER_RAD;
	return deg < 0 ? deg + 360 : deg;
}

void family(const struct skel *s, int **rank, int **nkids)
{
	*rank = calloc(s->nbranches + 1, sizeof(int));
	*nkids = calloc(s->nbranches + 1, sizeof(int));
	if (!*rank || !*nkids)
		exit(2);
	for (size_t i = 0; i < s->nbranches; i++) {
		int p = s->branches[i].parent;

		if (p >= 0)
			(*rank)[i] = (*nkids)[p]++;
	}
}
