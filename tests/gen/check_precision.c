/* SPDX-License-Identifier: MIT */
/* precision (docs/functional-trees.md, "Precision"): the sides of every branch's
 * cross-section. Bark triangles grow about linearly with it; leaves do not change. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gen_check.h"
#include "glb.h"

#define MAX_RUNS 16
/* "about linearly": each count within this of the straight line through the others' fit */
#define LINEAR_TOL 0.05

/* gen_check precision N GLB [N GLB]... (N increasing) */
int check_precision(int argc, char **argv)
{
	double n[MAX_RUNS], bark[MAX_RUNS], sn = 0, sb = 0, snn = 0, snb = 0, slope, icpt;
	size_t leaves0 = 0;
	int runs = argc / 2;

	if (argc % 2 || runs < 3 || runs > MAX_RUNS)
		return 2;
	for (int i = 0; i < runs; i++) {
		struct glb g;
		const struct glb_prim *b, *l;

		n[i] = atof(argv[2 * i]);
		if (glb_load(argv[2 * i + 1], &g) < 0)
			return 2;
		b = glb_prim(&g, "bark");
		l = glb_prim(&g, "leaves");
		bark[i] = b ? (double)b->ntriangles : 0;
		if (i == 0)
			leaves0 = l ? l->ntriangles : 0;
		else if ((l ? l->ntriangles : 0) != leaves0)
			bad("precision %g: %zu leaf triangles, %zu at precision %g", n[i],
			    l ? l->ntriangles : 0, leaves0, n[0]);
		printf("precision %2g: %7.0f bark triangles (%.1f a side), %zu leaf triangles\n", n[i],
		       bark[i], bark[i] / n[i], l ? l->ntriangles : 0);
		if (i > 0 && !(bark[i] > bark[i - 1]))
			bad("precision %g: %.0f bark triangles, no more than at %g", n[i], bark[i], n[i - 1]);
		glb_free(&g);
		sn += n[i];
		sb += bark[i];
		snn += n[i] * n[i];
		snb += n[i] * bark[i];
	}
	/* least squares: bark = slope n + icpt */
	slope = (runs * snb - sn * sb) / (runs * snn - sn * sn);
	icpt = (sb - slope * sn) / runs;
	printf("bark triangles ~ %.1f x precision %+.0f\n", slope, icpt);
	for (int i = 0; i < runs; i++) {
		double line = slope * n[i] + icpt;

		if (fabs(bark[i] - line) > LINEAR_TOL * line)
			bad("precision %g: %.0f bark triangles, %.1f%% off the line", n[i], bark[i],
			    100 * (bark[i] - line) / line);
	}
	/* linear, not just growing: what the sides do not multiply is a small part */
	if (fabs(icpt) > 0.1 * bark[runs - 1])
		bad("bark triangles ~ %.1f x precision %+.0f: far from proportional", slope, icpt);
	return finish("precision");
}
