/* SPDX-License-Identifier: MIT */
/*
 * Twining vines (seed 004): the time to grow a vine of 100 and 1,000 internodes (d = 8,
 * contact bisected to 0.01 r) around a pole tessellated into about 1k and 100k triangles,
 * the support's index built in the time, then the smoothing, leaves and meshes. Prints
 * medians and how each grows with the internodes and with the triangles. Then the kiosk's
 * vine mode on drawn 3D trees of 10 to 160 branches: a tap at the trunk's foot (where it
 * plants, the vine grown on the bark, its meshes) and a frame of its growth on screen.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_draw.h"
#include "bench_util.h"
#include "mesh.h"
#include "vine.h"
#include "vine_support.h"

/* A pole of radius R, height h, `sides` around and `rows` along, capped. */
struct pole {
	float *p;
	uint32_t *t;
	size_t np, nt;
};

static void pole_make(struct pole *m, double R, double h, int sides, int rows)
{
	size_t nv = (size_t)sides * (size_t)(rows + 1) + 2, nt = 2 * (size_t)sides * (size_t)rows
								 + 2 * (size_t)sides;

	m->p = malloc(3 * nv * sizeof(*m->p));
	m->t = malloc(3 * nt * sizeof(*m->t));
	if (!m->p || !m->t)
		exit(1);
	m->np = m->nt = 0;
	for (int j = 0; j <= rows; j++)
		for (int i = 0; i < sides; i++) {
			double a = 2 * VEC_PI * i / sides;
			float *q = m->p + 3 * m->np++;

			q[0] = (float)(R * cos(a));
			q[1] = (float)(h * j / rows);
			q[2] = (float)(R * sin(a));
		}
	for (int e = 0; e < 2; e++) {
		float *q = m->p + 3 * m->np++;

		q[0] = 0;
		q[1] = (float)(e * h);
		q[2] = 0;
	}
	for (int j = 0; j < rows; j++)
		for (int i = 0; i < sides; i++) {
			uint32_t a0 = (uint32_t)(j * sides + i), b0 = (uint32_t)(j * sides + (i + 1) % sides);
			uint32_t a1 = a0 + (uint32_t)sides, b1 = b0 + (uint32_t)sides;
			uint32_t tri[6] = { a0, b0, a1, a1, b0, b1 };

			memcpy(m->t + 3 * m->nt, tri, sizeof(tri));
			m->nt += 2;
		}
	for (int i = 0; i < sides; i++) {
		uint32_t a = (uint32_t)i, b = (uint32_t)((i + 1) % sides);
		uint32_t top = (uint32_t)(rows * sides), c0 = (uint32_t)(m->np - 2), c1 = c0 + 1;
		uint32_t tri[6] = { c0, b, a, c1, top + a, top + b };

		memcpy(m->t + 3 * m->nt, tri, sizeof(tri));
		m->nt += 2;
	}
}

struct job {
	struct pole pole;
	struct vine_params p;
	struct mesh stem, leaves;
};

static void grow(void *arg)
{
	struct job *j = arg;
	struct vine_support *s;
	struct vine v;

	if (vine_support_create(j->pole.p, j->pole.np, j->pole.t, j->pole.nt, &s) < 0)
		exit(1);
	vine_init(&v, &j->p, vec3(0.035, 0, 0));
	if (vine_grow(&v, s, 1e12) < 0)
		exit(1);
	vine_finish(&v);
	vine_support_destroy(s);
}

static void index_only(void *arg)
{
	struct job *j = arg;
	struct vine_support *s;

	if (vine_support_create(j->pole.p, j->pole.np, j->pole.t, j->pole.nt, &s) < 0)
		exit(1);
	vine_support_destroy(s);
}

static void shape(void *arg)
{
	struct job *j = arg;
	struct vine_support *s;
	struct vine v;

	if (vine_support_create(j->pole.p, j->pole.np, j->pole.t, j->pole.nt, &s) < 0)
		exit(1);
	vine_init(&v, &j->p, vec3(0.035, 0, 0));
	if (vine_grow(&v, s, 1e12) < 0)
		exit(1);
	mesh_clear(&j->stem);
	mesh_clear(&j->leaves);
	if (vine_mesh_append(&v, &j->stem, &j->leaves) < 0)
		exit(1);
	vine_finish(&v);
	vine_support_destroy(s);
}

/* The vine button and a tap at the foot of the tree bench_draw_tree draws (its trunk
 * rises from x = 560 on the ground, y = 736). Seconds the tap took. */
static double plant(struct app *app, struct bench_pen *bp)
{
	double t0;

	(void)bench_press(app, BUTTON_VINE);
	pen_event(&bp->pen, app, EVENT_PROXIMITY_IN, EVENT_TOOL_PEN, 590, 730, 0.0);
	pen_event(&bp->pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, 590, 730, 0.5);
	t0 = bench_now();
	pen_event(&bp->pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, 590, 730, 0.0);
	t0 = bench_now() - t0;
	pen_event(&bp->pen, app, EVENT_PROXIMITY_OUT, EVENT_TOOL_PEN, 590, 730, 0.0);
	(void)bench_press(app, BUTTON_VINE);
	return t0;
}

static void kiosk(void)
{
	static const int branches[] = { 10, 40, 160 };
	double pn = 0, pt = 0;

	printf("the vine mode on a drawn 3D tree: a tap planting a vine (the kiosk's preset "
	       "scaled, 40 internodes), median of 5, ms\n");
	for (size_t i = 0; i < BENCH_COUNT(branches); i++) {
		static double frames[2000];
		double taps[5], worst = 0.0;
		size_t nframes = 0, bark = 0;
		int reps = bench_reps(5);
		uint64_t t0;

		for (int r = 0; r < reps; r++) {
			struct bench_pen bp = { .pen = { .now_us = 1000, .steps = 8,
							 .pause_us = PEN_PAUSE_US } };
			struct app *app = bench_draw_tree(&bp, branches[i]);

			if (!app)
				exit(1);
			(void)bench_press(app, BUTTON_3D);
			bark = app->mesh.bark.nindices / 3;
			taps[r] = plant(app, &bp);
			if (app->tree.nvines != 1) {
				fprintf(stderr, "bench_vine: no vine planted on %d branches\n",
					branches[i]);
				exit(1);
			}
			/* its growth on screen, at 60 frames a second (the last run's) */
			t0 = app->doc.ops[app->doc.cursor - 1].time_us;
			nframes = 0;
			for (uint64_t t = t0; nframes < 2000; t += 16667) {
				double s = bench_now();
				bool on = app_vines_advance(app, t);

				frames[nframes++] = bench_now() - s;
				if (!on)
					break;
			}
			app_destroy(app);
		}
		for (size_t f = 0; f < nframes; f++)
			worst = frames[f] > worst ? frames[f] : worst;
		bench_row("  plant, tree branches", branches[i], bench_median(taps, (size_t)reps), &pn, &pt);
		printf("    (bark %zu triangles) growth on screen: %zu frames, median %.3f ms, "
		       "worst %.3f ms a frame\n", bark, nframes,
		       1e3 * bench_median(frames, nframes), 1e3 * worst);
	}
}

int main(int argc, char **argv)
{
	static const int internodes[] = { 100, 1000 };
	/* 1k and 100k triangles: 16 x 31 and 200 x 250 quads, the pole tall enough for 1,000
	 * internodes of climbing */
	static const int tess[][2] = { { 16, 31 }, { 200, 250 } };
	double grown[2][2], indexed[2], tris[2];
	/* --quick: the small support only */
	size_t ntess;

	if (bench_init(&argc, argv, NULL))
		return 1;
	ntess = bench_quick ? 1 : 2;
	printf("bench_vine: a vine planted 15 mm from a pole (R = 20 mm, 70 m), d = 8, median "
	       "ms; the support's index built each time\n");
	for (size_t k = 0; k < ntess; k++) {
		double pn = 0, pt = 0;

		for (size_t i = 0; i < 2; i++) {
			struct job j;
			char name[64];
			double t;
			int reps = bench_reps(internodes[i] > 100 || k ? 5 : 21);

			memset(&j, 0, sizeof(j));
			pole_make(&j.pole, 0.02, 70, tess[k][0], tess[k][1]);
			vine_params_default(&j.p);
			j.p.internodes = internodes[i];
			mesh_init(&j.stem);
			mesh_init(&j.leaves);
			tris[k] = (double)j.pole.nt;
			if (i == 0) {
				indexed[k] = bench_run(index_only, &j, reps);
				printf("  the index of %zu triangles alone: %.3f ms\n", j.pole.nt,
				       1e3 * indexed[k]);
			}
			t = grown[k][i] = bench_run(grow, &j, reps);
			snprintf(name, sizeof(name), "grow, %zu triangles, internodes", j.pole.nt);
			bench_row(name, internodes[i], t, &pn, &pt);
			t = bench_run(shape, &j, reps);
			printf("  the same and its smoothing, leaves and meshes: %.3f ms (stems %zu, leaves "
			       "%zu triangles)\n", 1e3 * t, j.stem.nindices / 3, j.leaves.nindices / 3);
			mesh_finish(&j.stem);
			mesh_finish(&j.leaves);
			free(j.pole.p);
			free(j.pole.t);
		}
	}
	if (ntess > 1)
		printf("how it grows with the support, x%.0f triangles:\n", tris[1] / tris[0]);
	for (size_t i = 0; ntess > 1 && i < 2; i++) {
		double with = grown[1][i] / grown[0][i];
		double alone = (grown[1][i] - indexed[1]) / (grown[0][i] - indexed[0]);

		printf("  %d internodes: x%.2f with the index (~n^%.2f), the growth alone x%.2f "
		       "(~n^%.2f)\n", internodes[i], with, log(with) / log(tris[1] / tris[0]),
		       alone, log(alone) / log(tris[1] / tris[0]));
	}
	kiosk();
	return 0;
}
