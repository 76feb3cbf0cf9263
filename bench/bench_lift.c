/* SPDX-License-Identifier: MIT */
/*
 * Lifting a sketch to 3D (the 3D button) for drawings of 30..1,000 branches, with the
 * front/back merge, as the kiosk does it, on one core. Medians; the growth between
 * sizes as an exponent, and overall per doubling. Aims (issue 4): <= 20 ms at 100
 * branches, <= 300 ms at 1,000, close to linear.
 */
#include <math.h>
#include <stdio.h>

#include "bench_draw.h"
#include "bench_util.h"
#include "doc.h"
#include "lift.h"
#include "sketch.h"

#define REPS 9

int main(int argc, char **argv)
{
	static const int sizes[] = { 30, 100, 300, 1000 };
	double pn = 0, pt = 0, first = 0;
	int reps;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);
	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, sizes[s]);
		double t[REPS];
		char name[64];

		if (!app)
			return 1;
		for (int r = 0; r < reps; r++) {
			struct tree tree;
			struct rng rng;
			double t0;

			/* the same sketch each time, rebuilt outside the timing */
			tree_init(&tree);
			rng_seed(&rng, app->doc.seed);
			for (size_t i = 0; i < app->doc.cursor; i++)
				if (doc_apply_stroke(&tree, &app->doc.ops[i]) < 0)
					return 1;
			t0 = bench_now();
			if (lift_tree(&tree, &rng, true) < 0)
				return 1;
			t[r] = bench_now() - t0;
			if (r == 0)
				snprintf(name, sizeof(name), "lift %zu -> %zu branches", app->tree.nbranches,
					 tree.nbranches);
			tree_finish(&tree);
		}
		bench_row(name, sizes[s], bench_median(t, (size_t)reps), &pn, &pt);
		if (s == 0)
			first = pt;
		app_destroy(app);
	}
	{
		double k = log(pt / first) / log(pn / sizes[0]);

		printf("growth %d -> %d branches: ~n^%.2f, x%.2f per doubling\n", sizes[0], (int)pn, k,
		       pow(2, k));
	}
	return 0;
}
