/* SPDX-License-Identifier: MIT */
#include "export.h"
#include "numfmt.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double bark_color[3] = { MATERIAL_BARK_RGB };
static const double leaves_color[3] = { MATERIAL_LEAVES_RGB };

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

/* "f a//na b//nb c//nc": vertex and normal numbers are 1-based over the whole file. */
static int obj_faces(struct buf *obj, const struct mesh *m, uint32_t v0, uint32_t n0, bool back)
{
	for (size_t t = 0; t + 2 < m->nindices; t += 3) {
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

static int obj_write(const struct tree_mesh *tm, const char *mtl_name, struct buf *obj)
{
	uint32_t nv = 0, nn = 0; /* v and vn lines so far */
	int r;

	r = buf_printf(obj, "# edaha tree: metres, y up\nmtllib %s\n", mtl_name);
	if (r < 0)
		return r;

	if (tm->bark.nindices >= 3) {
		const struct mesh *m = &tm->bark;

		if ((r = buf_printf(obj, "o bark\nusemtl bark\n")) < 0 ||
		    (r = obj_vec3s(obj, "v", m->positions, m->nvertices, 1.0)) < 0 ||
		    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, 1.0)) < 0 ||
		    (r = obj_faces(obj, m, nv + 1, nn + 1, false)) < 0)
			return r;
		nv += (uint32_t)m->nvertices;
		nn += (uint32_t)m->nvertices;
	}

	if (tm->leaves.nindices >= 3) {
		const struct mesh *m = &tm->leaves;

		/* OBJ has no double-sided materials: the back side is its own faces and normals. */
		if ((r = buf_printf(obj, "o leaves\nusemtl leaves\n")) < 0 ||
		    (r = obj_vec3s(obj, "v", m->positions, m->nvertices, 1.0)) < 0 ||
		    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, 1.0)) < 0 ||
		    (r = obj_vec3s(obj, "vn", m->normals, m->nvertices, -1.0)) < 0 ||
		    (r = obj_faces(obj, m, nv + 1, nn + 1, false)) < 0 ||
		    (r = obj_faces(obj, m, nv + 1, nn + 1 + (uint32_t)m->nvertices, true)) < 0)
			return r;
	}
	return 0;
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

int export_obj(const struct tree_mesh *m, const char *mtl_name, struct buf *obj, struct buf *mtl)
{
	size_t obj_start = obj->len, mtl_start = mtl->len;
	int r;

	/* The name lands on the mtllib line: one line, not empty. */
	if (!mtl_name || !*mtl_name || strpbrk(mtl_name, "\r\n"))
		return -EINVAL;
	/* 1-based uint32 face numbers, leaves' normals counted twice. */
	if (m->bark.nvertices + 2 * m->leaves.nvertices >= UINT32_MAX)
		return -EFBIG;

	r = obj_write(m, mtl_name, obj);
	if (r >= 0)
		r = buf_printf(mtl, "# edaha tree materials\n");
	if (r >= 0)
		r = mtl_material(mtl, "bark", bark_color);
	if (r >= 0)
		r = buf_printf(mtl, "\n");
	if (r >= 0)
		r = mtl_material(mtl, "leaves", leaves_color);
	if (r < 0) {
		obj->len = obj_start;
		mtl->len = mtl_start;
	}
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
