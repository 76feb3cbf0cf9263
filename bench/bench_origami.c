/* SPDX-License-Identifier: MIT */
/*
 * Origami leaves (seed 003): the time to build each preset's pattern (ori_build: walk,
 * cut, checks), to open it (ori_open at one opening, and the 8 keyframes the kiosk's
 * unfolding uses), to mesh it, and how the build grows with the pattern's creases on
 * designs with more and more forks. Prints medians.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "mesh.h"
#include "ori.h"

#define KEYFRAMES 8

struct job {
	struct ori_design d;
	struct ori_leaf l;
	double (*pos)[3];
	double (*frames)[3];
	struct mesh m;
};

static void build(void *arg)
{
	struct job *j = arg;
	struct ori_leaf l;
	struct error err;

	if (ori_build(&j->d, "bench", &l, &err) < 0) {
		fprintf(stderr, "bench_origami: %s\n", err.msg);
		exit(1);
	}
	ori_leaf_finish(&l);
}

static void open_half(void *arg)
{
	struct job *j = arg;

	if (ori_open(&j->l, 0.5, j->pos) < 0)
		exit(1);
}

static void keyframes(void *arg)
{
	struct job *j = arg;

	if (ori_open_frames(&j->l, KEYFRAMES + 1, j->frames) < 0)
		exit(1);
}

static void mesh(void *arg)
{
	struct job *j = arg;

	mesh_clear(&j->m);
	if (ori_mesh_append(&j->l, (const double(*)[3])j->pos, NULL, &j->m) < 0)
		exit(1);
}

static void prepare(struct job *j)
{
	struct error err;

	if (ori_build(&j->d, "bench", &j->l, &err) < 0) {
		fprintf(stderr, "bench_origami: %s\n", err.msg);
		exit(1);
	}
	j->pos = calloc(j->l.nvertices, sizeof(*j->pos));
	j->frames = calloc(j->l.nvertices * (KEYFRAMES + 1), sizeof(*j->frames));
	if (!j->pos || !j->frames || ori_rest(&j->l, j->pos) < 0)
		exit(1);
	mesh_init(&j->m);
}

static void release(struct job *j)
{
	mesh_finish(&j->m);
	free(j->pos);
	free(j->frames);
	ori_leaf_finish(&j->l);
}

static void presets(void)
{
	size_t n;
	const char *const *names = ori_preset_names(&n);

	printf("# the presets: median ms of ori_build, ori_open(0.5), %d+1 keyframes, the mesh\n",
	       KEYFRAMES);
	printf("%-8s %8s %6s %6s %9s %9s %11s %9s %12s\n", "preset", "creases", "faces", "tris",
	       "build", "open", "keyframes", "mesh", "tris@20000");
	for (size_t i = 0; i < n; i++) {
		struct job j;
		struct error err;

		if (ori_preset(names[i], &j.d, &err) < 0) {
			fprintf(stderr, "bench_origami: %s\n", err.msg);
			exit(1);
		}
		prepare(&j);
		/* the triangles a tree of 20,000 such leaves draws (docs/origami-leaves.md) */
		printf("%-8s %8zu %6zu %6zu %9.4f %9.4f %11.4f %9.4f %11zuk\n", names[i],
		       j.l.ncreases, j.l.nfaces, ori_mesh_triangles(&j.l),
		       1e3 * bench_run(build, &j, bench_reps(2001)),
		       1e3 * bench_run(open_half, &j, bench_reps(2001)),
		       1e3 * bench_run(keyframes, &j, bench_reps(501)),
		       1e3 * bench_run(mesh, &j, bench_reps(2001)), ori_mesh_triangles(&j.l) * 20);
		release(&j);
	}
}

/* Growth: a five-part fan whose side parts fork 0..3 times, then with midrib nodes. */
static void growth(void)
{
	printf("# growth: ori_build and %d+1 keyframes against the pattern's creases, side "
	       "parts forking 0..3 times, without and with 2 midrib nodes\n", KEYFRAMES);
	for (size_t nodes = 0; nodes <= 2; nodes += 2) {
		double ps = 0, pt = 0, po = 0, pot = 0;

		for (int forks = 0; forks <= (bench_quick ? 1 : 3); forks++) {
			struct job j;
			char name[64];
			double t;

			memset(&j.d, 0, sizeof(j.d));
			ori_design_default(&j.d, ORI_FOLD_FAN);
			j.d.middle[0] = j.d.middle[1] = 35;
			j.d.nsides = 2;
			j.d.sides[0] = (struct ori_side){ .angle = 60, .forks = forks, .fork_at = 0.45,
							  .fork_a = 25, .fork_b = 25 };
			j.d.sides[1] = (struct ori_side){ .angle = 55, .forks = forks, .fork_at = 0.5,
							  .fork_a = 25, .fork_b = 25 };
			j.d.junction = 0.5;
			j.d.theta0 = 360;
			j.d.nnodes = nodes;
			for (size_t k = 0; k < nodes; k++)
				j.d.nodes[k] = (struct ori_node){ .at = 0.3 + 0.25 * (double)k,
								  .phi = { 45, 45 },
								  .psi = { 32, 32 } };
			prepare(&j);
			snprintf(name, sizeof(name), "forks %d, nodes %zu, creases", forks, nodes);
			t = bench_run(build, &j, bench_reps(1001));
			bench_row(name, (double)j.l.ncreases, t, &ps, &pt);
			snprintf(name, sizeof(name), "  keyframes, creases");
			t = bench_run(keyframes, &j, bench_reps(201));
			bench_row(name, (double)j.l.ncreases, t, &po, &pot);
			release(&j);
		}
	}
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	presets();
	growth();
	return 0;
}
