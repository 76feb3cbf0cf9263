/* SPDX-License-Identifier: MIT */
/*
 * edaha --headless --support FILE.obj --vine NAME|FILE --plant X,Y,Z: a twining vine
 * (issue 16, seed 004) grown to its end on a support alone, written to --out as
 * skeleton.json (its "vines"), model.glb, model.obj, model.mtl and screen.png, as a tree
 * run writes them. Everything is read, grown and drawn before the folder is touched, so
 * bad input writes nothing.
 */
#include "headless.h"
#include "headless_one.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "buf.h"
#include "export.h"
#include "fileio.h"
#include "mesh.h"
#include "render.h"
#include "support_obj.h"
#include "tree.h"
#include "vine.h"
#include "vine_presets.h"
#include "vine_support.h"

/* The parameters: a preset's, else a file's, read through fileio and named by its path. */
static int read_params(const char *arg, struct vine_params *p)
{
	size_t n;
	const char *const *names = vine_preset_names(&n);
	struct error err = { { 0 } };
	struct stat st;
	size_t len;
	char *data;
	int ret;

	if (headless_is_preset(names, n, arg)) {
		ret = vine_preset(arg, p, &err);
		if (ret < 0) /* compiled in and tested: not the visitor's fault */
			fprintf(stderr, "edaha: vine preset %s: %s\n", arg, err.msg);
		return ret < 0 ? 1 : 0;
	}
	if (stat(arg, &st) < 0 && (errno == ENOENT || errno == ENOTDIR))
		return headless_no_such_preset("--vine", "vine", arg, names, n);
	/* vine_read tells a longer file at its first line; past this it is not read at all */
	ret = fileio_read_all(arg, 2 * VINE_READ_MAX_BYTES, &data, &len, &err);
	if (ret == 0) {
		ret = vine_read(data, len, arg, p, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return headless_input_status(ret);
	}
	return 0;
}

/*
 * The support as a mesh to show and export: each triangle its own three vertices and its
 * face's normal, so a faceted support reads as faceted and a cap's rim stays sharp; a
 * triangle without area (kept for the contact queries) shows nothing and is left out.
 */
static int support_mesh(const struct support_obj *s, struct mesh *m)
{
	int ret = mesh_reserve(m, 3 * s->ntriangles, 3 * s->ntriangles);

	if (ret < 0)
		return ret;
	for (size_t t = 0; t < s->ntriangles; t++) {
		struct vec3 p[3], n;

		for (int k = 0; k < 3; k++) {
			const float *q = s->positions + 3 * (size_t)s->indices[3 * t + (size_t)k];

			p[k] = vec3(q[0], q[1], q[2]);
		}
		n = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		if (!(vec3_len(n) > 0.0))
			continue;
		n = vec3_scale(n, 1.0 / vec3_len(n));
		for (int k = 0; k < 3; k++) {
			float *pos = m->positions + 3 * m->nvertices;
			float *nor = m->normals + 3 * m->nvertices;

			pos[0] = (float)p[k].x;
			pos[1] = (float)p[k].y;
			pos[2] = (float)p[k].z;
			nor[0] = (float)n.x;
			nor[1] = (float)n.y;
			nor[2] = (float)n.z;
			m->indices[m->nindices++] = (uint32_t)m->nvertices++;
		}
	}
	return 0;
}

/* What the picture shows: the support, and the vine's stems and leaves. */
struct picture {
	const struct mesh *support;
	const struct tree_mesh *vine;
};

static int draw(struct render *r, const void *ctx, int width, int height)
{
	const struct picture *p = ctx;

	return render_vine(r, p->support, &p->vine->bark, &p->vine->leaves, width, height);
}

enum { OUT_SKELETON, OUT_GLB, OUT_OBJ, OUT_MTL, OUT_PNG, OUT_N };
static const char *const out_names[OUT_N] = {
	"skeleton.json", "model.glb", "model.obj", "model.mtl", "screen.png",
};

/* The support and the vine as a tree's meshes for the exporters: the support and the stems
 * are the bark, the vine's leaves the leaves. */
static int export_all(const struct vine *v, const struct support_obj *obj, struct buf *files)
{
	struct tree t;
	struct tree_mesh all;
	int ret;

	tree_init(&t); /* no tree: an empty drawing's skeleton, summer's materials */
	tree_mesh_init(&all);
	ret = support_mesh(obj, &all.bark);
	if (ret == 0)
		ret = vine_mesh_append(v, &all.bark, &all.leaves);
	if (ret == 0)
		ret = export_skeleton_vines(&t, v, 1, &files[OUT_SKELETON]);
	if (ret == 0)
		ret = export_glb(&t, &all, NULL, &files[OUT_GLB]);
	if (ret == 0)
		ret = export_obj(&t, &all, NULL, out_names[OUT_MTL], &files[OUT_OBJ],
				 &files[OUT_MTL]);
	tree_mesh_finish(&all);
	tree_finish(&t);
	return ret;
}

int headless_vine_run(const struct options *o)
{
	struct error err = { { 0 } };
	struct vine_params p;
	struct support_obj obj;
	struct vine_support *support = NULL;
	struct vine v;
	struct mesh sm;
	struct tree_mesh vm;
	struct buf files[OUT_N];
	struct picture pic = { &sm, &vm };
	bool planted = false;
	int ret, status;

	memset(&obj, 0, sizeof(obj));
	mesh_init(&sm);
	tree_mesh_init(&vm);
	for (int i = 0; i < OUT_N; i++)
		buf_init(&files[i]);
	status = read_params(o->vine, &p);
	if (status)
		goto out;
	ret = support_obj_read(o->support, &obj, &err);
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", ret == -ENOMEM ? "out of memory" : err.msg);
		status = headless_input_status(ret);
		goto out;
	}
	ret = vine_support_create(obj.positions, obj.nvertices, obj.indices, obj.ntriangles,
				  &support);
	if (ret == 0) {
		vine_init(&v, &p, vec3(o->plant[0], o->plant[1], o->plant[2]));
		planted = true;
		/* to the end: the budget spent, or no apex nor bud left */
		ret = vine_grow(&v, support, INFINITY);
	}
	if (ret == 0)
		ret = vine_mesh_append(&v, &vm.bark, &vm.leaves);
	if (ret == 0)
		ret = support_mesh(&obj, &sm);
	if (ret == 0)
		ret = export_all(&v, &obj, files);
	if (ret < 0) {
		/* support_obj_read let no bad coordinate or index through: the machine's fault */
		fprintf(stderr, "edaha: %s\n", ret == -ENOMEM ? "out of memory" : "internal error");
		status = 1;
		goto out;
	}
	status = headless_one_picture(o, draw, &pic, &files[OUT_PNG]);
	if (status)
		goto out;
	status = headless_one_write(o->out_dir, out_names, files, OUT_N);
	if (status == 0)
		printf("edaha: wrote skeleton.json, model.glb, model.obj, model.mtl and screen.png "
		       "to %s (a vine of %zu shoots on %zu triangles)\n", o->out_dir, v.nshoots,
		       obj.ntriangles);
out:
	for (int i = 0; i < OUT_N; i++)
		buf_finish(&files[i]);
	tree_mesh_finish(&vm);
	mesh_finish(&sm);
	if (planted)
		vine_finish(&v);
	vine_support_destroy(support);
	support_obj_finish(&obj);
	return status;
}
