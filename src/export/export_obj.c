/* SPDX-License-Identifier: MIT */
#include "export.h"
#include "export_leaves.h"
#include "export_vines.h"
#include "numfmt.h"
#include "wood.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double bark_color[3] = { MATERIAL_BARK_RGB };
static const double leaves_color[3] = { MATERIAL_LEAVES_RGB };
static const double vine_color[3] = { MATERIAL_VINE_RGB };

#define OBJ_MATERIAL_NAME 32

/* "leaves-autumn-3": the season's palette entry 3, readable in any material list. */
static void obj_leaves_material_name(char name[OBJ_MATERIAL_NAME], enum season s, size_t k)
{
	snprintf(name, OBJ_MATERIAL_NAME, "leaves-%s-%zu", season_name(s), k);
}

static size_t fmt_u32(char *out, uint32_t v)
{
	char digits[10];
	size_t n = 0, len = 0;

	do {
		digits[n++] = (char)('0' + v % 10);
		v /= 10;
	} while (v);
	while (n)
		out[len++] = digits[--n];
	return len;
}

/* "<tag> x y z\n", each multiplied by sign (flips normals for the back faces). */
static int obj_vec3s(struct buf *obj, const char *tag, const float *v, size_t n, double sign)
{
	for (size_t i = 0; i < n; i++) {
		char line[128];
		size_t len = strlen(tag);
		int r;

		memcpy(line, tag, len);
		for (int c = 0; c < 3; c++) {
			line[len++] = ' ';
			len += numfmt_micro(line + len, sign * v[3 * i + (size_t)c], false);
		}
		line[len++] = '\n';
		r = buf_append(obj, line, len);
		if (r < 0)
			return r;
	}
	return 0;
}

/* "f a//na b//nb c//nc" for the triangles of indices [from, to): vertex and normal numbers
 * are 1-based over the whole file. */
static int obj_faces(struct buf *obj, const struct mesh *m, size_t from, size_t to, uint32_t v0,
		     uint32_t n0, bool back)
{
	for (size_t t = from; t + 2 < to; t += 3) {
		const uint32_t *tri = &m->indices[t];
		/* A back face runs the other way round. */
		uint32_t order[3] = { tri[0], back ? tri[2] : tri[1], back ? tri[1] : tri[2] };
		char line[96] = "f";
		size_t len = 1;
		int r;

		for (int c = 0; c < 3; c++) {
			line[len++] = ' ';
			len += fmt_u32(line + len, v0 + order[c]);
			line[len++] = '/';
			line[len++] = '/';
			len += fmt_u32(line + len, n0 + order[c]);
		}
		line[len++] = '\n';
		r = buf_append(obj, line, len);
		if (r < 0)
			return r;
	}
	return 0;
}

/* Spring's and autumn's leaf faces, front and back, a group a colour, each behind its
 * material: a few usemtl lines, however many leaves. */
static int obj_colored_faces(struct buf *obj, const struct export_leaves *el, uint32_t v0,
			     uint32_t n0)
{
	unsigned used = export_leaves_colors_used(el);
	size_t n = export_leaves_nparts(el);
	uint32_t n_back = n0 + (uint32_t)el->mesh->nvertices;

	for (size_t k = 0; k < el->ncolors; k++) {
		char name[OBJ_MATERIAL_NAME];
		int r;

		if (!(used & 1u << k))
			continue;
		obj_leaves_material_name(name, el->tree->season, k);
		if ((r = buf_printf(obj, "usemtl %s\n", name)) < 0)
			return r;
		for (int back = 0; back < 2; back++) {
			for (size_t i = 0; i < n; i++) {
				struct export_leaf_part p = export_leaves_part(el, i);

				if (p.color != k)
					continue;
				r = obj_faces(obj, el->mesh, p.first_index, p.end_index, v0,
					      back ? n_back : n0, back);
				if (r < 0)
					return r;
			}
		}
	}
	return 0;
}

/* What one OBJ and its MTL are made of: the tree's meshes (its wood's bark after the swept
 * bark), then its vines'; a part that is not there writes nothing, so a tree without wood
 * or vines has the bytes it had. */
struct obj_input {
	const struct mesh *bark, *wood, *leaves, *vine, *vine_leaves;
	enum export_look how;
	/* spring, autumn: the tree's leaves by their marks, the vines' in one part */
	const struct export_leaves *colors, *vine_colors;
};

/* Counts of v and vn lines written so far: the next object's numbers follow them. */
struct obj_count {
	uint32_t nv, nn;
};

/* A closed surface (the bark, the wood's bark, the vines' stems): its vertices, normals
 * and faces behind one material. m may be NULL: nothing. */
static int obj_solid(struct buf *obj, const struct mesh *m, const char *name, const char *mat,
		     struct obj_count *c)
{
	int r;

	if (!m || m->nindices < 3)
		return 0;
	if ((r = buf_printf(obj, "o %s\nusemtl %s\n", name, mat)) < 0 ||
	    (r = obj_vec3s(obj, "v", m->positions, m->nvertices, 1.0)) < 0 ||
	    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, 1.0)) < 0 ||
	    (r = obj_faces(obj, m, 0, m->nindices, c->nv + 1, c->nn + 1, false)) < 0)
		return r;
	c->nv += (uint32_t)m->nvertices;
	c->nn += (uint32_t)m->nvertices;
	return 0;
}

/* Leaves, both sides: summer's one material, or spring's and autumn's by colour. */
static int obj_leaves(struct buf *obj, const struct mesh *m, const char *name,
		      enum export_look how, const struct export_leaves *el, struct obj_count *c)
{
	uint32_t v0 = c->nv + 1, n0 = c->nn + 1, n_back = n0 + (uint32_t)m->nvertices;
	int r;

	if (m->nindices < 3 || how == EXPORT_LEAVES_NONE)
		return 0;
	/* OBJ has no double-sided materials: the back side is its own faces and normals. */
	if ((r = buf_printf(obj, how == EXPORT_LEAVES_GREEN ? "o %s\nusemtl leaves\n" : "o %s\n",
			    name)) < 0 ||
	    (r = obj_vec3s(obj, "v", m->positions, m->nvertices, 1.0)) < 0 ||
	    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, 1.0)) < 0 ||
	    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, -1.0)) < 0)
		return r;
	c->nv += (uint32_t)m->nvertices;
	c->nn += 2 * (uint32_t)m->nvertices;
	if (how == EXPORT_LEAVES_COLORED)
		return obj_colored_faces(obj, el, v0, n0);
	if ((r = obj_faces(obj, m, 0, m->nindices, v0, n0, false)) < 0 ||
	    (r = obj_faces(obj, m, 0, m->nindices, v0, n_back, true)) < 0)
		return r;
	return 0;
}

static int obj_write(const struct obj_input *in, const char *mtl_name, struct buf *obj)
{
	struct obj_count c = { 0, 0 };
	int r;

	r = buf_printf(obj, "# edaha tree: metres, y up\nmtllib %s\n", mtl_name);
	if (r >= 0)
		r = obj_solid(obj, in->bark, "bark", "bark", &c);
	if (r >= 0)
		r = obj_solid(obj, in->wood, "wood", "bark", &c);
	if (r >= 0)
		r = obj_leaves(obj, in->leaves, "leaves", in->how, in->colors, &c);
	if (r >= 0)
		r = obj_solid(obj, in->vine, "vine", "vine", &c);
	if (r >= 0)
		r = obj_leaves(obj, in->vine_leaves, "vine-leaves", in->how, in->vine_colors, &c);
	return r;
}

static int mtl_material(struct buf *mtl, const char *name, const double kd[3])
{
	/* Matte: no specular highlight, like the glTF's rough non-metal. */
	return buf_printf(mtl,
			  "newmtl %s\n"
			  "Ka 0.000000 0.000000 0.000000\n"
			  "Kd %.6f %.6f %.6f\n"
			  "Ks 0.000000 0.000000 0.000000\n"
			  "Ns 1.000000\n"
			  "d 1.000000\n"
			  "illum 1\n",
			  name, kd[0], kd[1], kd[2]);
}

/* Spring's and autumn's leaves' materials that the OBJ uses, the vines' leaves' too. */
static int mtl_colored(const struct obj_input *in, struct buf *mtl)
{
	const struct export_leaves *el = in->colors;
	unsigned used = export_leaves_colors_used(el) | export_leaves_colors_used(in->vine_colors);
	int r = 0;

	for (size_t k = 0; k < el->ncolors && r >= 0; k++) {
		const double kd[3] = { el->palette[k].r, el->palette[k].g, el->palette[k].b };
		char name[OBJ_MATERIAL_NAME];

		if (!(used & 1u << k))
			continue;
		obj_leaves_material_name(name, el->tree->season, k);
		if ((r = buf_printf(mtl, "\n")) >= 0)
			r = mtl_material(mtl, name, kd);
	}
	return r;
}

/* The MTL: bark, the leaves' materials that the OBJ uses (summer's one green always, as
 * before seasons), then the vines' stems' when there are any. */
static int mtl_write(const struct obj_input *in, struct buf *mtl)
{
	int r = buf_printf(mtl, "# edaha tree materials\n");

	if (r >= 0)
		r = mtl_material(mtl, "bark", bark_color);
	if (r >= 0 && in->how == EXPORT_LEAVES_GREEN && (r = buf_printf(mtl, "\n")) >= 0)
		r = mtl_material(mtl, "leaves", leaves_color);
	if (r >= 0 && in->how == EXPORT_LEAVES_COLORED)
		r = mtl_colored(in, mtl);
	if (r >= 0 && in->vine->nindices >= 3 && (r = buf_printf(mtl, "\n")) >= 0)
		r = mtl_material(mtl, "vine", vine_color);
	return r;
}

/* Whether every v and vn number fits: 1-based uint32, leaves' normals counted twice. */
static bool obj_fits(const struct obj_input *in)
{
	size_t leaf_normals = 0, n;

	if (in->how != EXPORT_LEAVES_NONE)
		leaf_normals = 2 * (in->leaves->nvertices + in->vine_leaves->nvertices);
	n = in->bark->nvertices + in->vine->nvertices + leaf_normals;
	if (in->wood)
		n += in->wood->nvertices;
	return n < UINT32_MAX;
}

int export_obj(const struct tree *t, const struct tree_mesh *m, const struct tree_mesh_marks *mk,
	       const char *mtl_name, struct buf *obj, struct buf *mtl)
{
	size_t obj_start = obj->len, mtl_start = mtl->len;
	/* m leaves the voxelised branches out: their bark is the wood's */
	struct obj_input in = { &m->bark, t->wood ? &t->wood->bark : NULL, &m->leaves, NULL, NULL,
				export_look(t->season), NULL, NULL };
	struct export_leaves el, vel;
	struct export_vines ev;
	int r;

	/* The name lands on the mtllib line: one line, not empty. */
	if (!mtl_name || !*mtl_name || strpbrk(mtl_name, "\r\n"))
		return -EINVAL;
	r = export_vines_build(&ev, t);
	if (r < 0)
		goto out;
	in.vine = &ev.stems;
	in.vine_leaves = &ev.leaves;
	if (!obj_fits(&in)) {
		r = -EFBIG;
		goto out;
	}
	if (in.how == EXPORT_LEAVES_COLORED) {
		export_leaves_init(&el, t, &m->leaves, mk);
		/* no marks: the vines' leaves one part, in the palette's first colour */
		export_leaves_init(&vel, t, &ev.leaves, NULL);
		in.colors = &el;
		in.vine_colors = &vel;
	}
	r = obj_write(&in, mtl_name, obj);
	if (r >= 0)
		r = mtl_write(&in, mtl);
out:
	if (r < 0) {
		obj->len = obj_start;
		mtl->len = mtl_start;
	}
	export_vines_finish(&ev);
	return r;
}

int export_obj_mtllib(struct buf *obj, const char *mtl_name)
{
	static const char key[] = "\nmtllib ";
	size_t klen = sizeof(key) - 1, nlen, start, end, old;
	unsigned char *p;
	int r;

	if (!mtl_name || !*mtl_name || strpbrk(mtl_name, "\r\n"))
		return -EINVAL;
	/* export_obj writes it as the second line, after one comment */
	p = obj->len ? memchr(obj->data, '\n', obj->len) : NULL;
	if (!p || (size_t)(p - obj->data) + klen > obj->len || memcmp(p, key, klen) != 0)
		return -EINVAL;
	start = (size_t)(p - obj->data) + klen;
	p = memchr(obj->data + start, '\n', obj->len - start);
	if (!p)
		return -EINVAL;
	end = (size_t)(p - obj->data);
	old = end - start;
	nlen = strlen(mtl_name);
	if (nlen > old && (r = buf_reserve(obj, nlen - old)) < 0)
		return r;
	memmove(obj->data + start + nlen, obj->data + end, obj->len - end);
	memcpy(obj->data + start, mtl_name, nlen);
	obj->len = obj->len - old + nlen;
	return 0;
}
