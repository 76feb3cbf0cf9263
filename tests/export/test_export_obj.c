/* SPDX-License-Identifier: MIT */
/* export_obj: structure, face numbers in range, numbers as "%.6f", back faces for leaves. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "mesh.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

struct obj_stats {
	size_t v, vn, f, o, usemtl, mtllib;
	size_t f_in[2]; /* faces in "o bark", "o leaves" */
};

/* The next line (without '\n') as a fresh string; NULL at the end. */
static char *next_line(const struct buf *b, size_t *pos)
{
	size_t start = *pos, end = start;
	char *line;

	if (start >= b->len)
		return NULL;
	while (end < b->len && b->data[end] != '\n')
		end++;
	CHECK(end < b->len); /* every line ends with '\n' */
	line = malloc(end - start + 1);
	CHECK(line);
	memcpy(line, b->data + start, end - start);
	line[end - start] = '\0';
	*pos = end + 1;
	return line;
}

/* A "%.6f" number: optional '-', digits, '.', exactly six digits. */
static void check_number(const char *s)
{
	const char *dot = strchr(s, '.');

	CHECK(dot && strlen(dot + 1) == 6);
	CHECK(strspn(dot + 1, "0123456789") == 6);
	if (*s == '-') {
		s++;
		CHECK(strcmp(s, "0.000000") != 0); /* no negative zero */
	}
	CHECK(strspn(s, "0123456789") == (size_t)(dot - s) && dot > s);
}

static void parse_obj(const struct buf *b, struct obj_stats *st, const float *first_v)
{
	size_t pos = 0;
	char *line;
	int cur = -1;

	memset(st, 0, sizeof(*st));
	/* numbers are checked against the limits once all v / vn lines are counted */
	while ((line = next_line(b, &pos))) {
		char *save = NULL, *tok = strtok_r(line, " ", &save);

		if (!tok || tok[0] == '#') {
			/* comment or blank */
		} else if (!strcmp(tok, "mtllib")) {
			CHECK(!strcmp(strtok_r(NULL, " ", &save), "tree.mtl"));
			st->mtllib++;
		} else if (!strcmp(tok, "o")) {
			tok = strtok_r(NULL, " ", &save);
			cur = !strcmp(tok, "bark") ? 0 : !strcmp(tok, "leaves") ? 1 : -1;
			CHECK(cur >= 0);
			st->o++;
		} else if (!strcmp(tok, "usemtl")) {
			tok = strtok_r(NULL, " ", &save);
			CHECK(!strcmp(tok, cur == 0 ? "bark" : "leaves"));
			st->usemtl++;
		} else if (!strcmp(tok, "v") || !strcmp(tok, "vn")) {
			int k = 0;
			bool is_v = tok[1] == '\0';

			while ((tok = strtok_r(NULL, " ", &save))) {
				check_number(tok);
				if (is_v && st->v == 0 && first_v)
					CHECK_NEAR(strtod(tok, NULL), first_v[k], 5.1e-7);
				k++;
			}
			CHECK_INT(k, 3);
			if (is_v)
				st->v++;
			else
				st->vn++;
		} else if (!strcmp(tok, "f")) {
			int k = 0;

			CHECK(cur >= 0);
			while ((tok = strtok_r(NULL, " ", &save))) {
				char *end;
				long v = strtol(tok, &end, 10), n;

				CHECK(end[0] == '/' && end[1] == '/');
				n = strtol(end + 2, &end, 10);
				CHECK(*end == '\0');
				/* OBJ numbers are 1-based and refer back to lines already seen */
				CHECK(v >= 1 && (size_t)v <= st->v);
				CHECK(n >= 1 && (size_t)n <= st->vn);
				k++;
			}
			CHECK_INT(k, 3);
			st->f++;
			st->f_in[cur]++;
		} else {
			fprintf(stderr, "unexpected line: %s\n", line);
			CHECK(0);
		}
		free(line);
	}
}

static void export_tree(const struct tree *t, struct buf *obj, struct buf *mtl,
			struct tree_mesh *tm)
{
	CHECK_INT(tree_mesh_build(tm, t), 0);
	CHECK_INT(export_obj(t, tm, NULL, "tree.mtl", obj, mtl), 0);
}

static void test_tree(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct buf obj, mtl, obj2, mtl2;
	struct obj_stats st;
	const char *mtl_text;

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&obj);
	buf_init(&mtl);
	buf_init(&obj2);
	buf_init(&mtl2);
	CHECK_INT(synth_tree(&t, 30, 3, 5), 0);
	export_tree(&t, &obj, &mtl, &tm);
	parse_obj(&obj, &st, tm.bark.positions);
	CHECK_INT(st.mtllib, 1);
	CHECK_INT(st.o, 2);
	CHECK_INT(st.usemtl, 2);
	CHECK_INT(st.v, tm.bark.nvertices + tm.leaves.nvertices);
	/* the leaves' normals twice: front and back */
	CHECK_INT(st.vn, tm.bark.nvertices + 2 * tm.leaves.nvertices);
	CHECK_INT(st.f_in[0], tm.bark.nindices / 3);
	CHECK_INT(st.f_in[1], 2 * (tm.leaves.nindices / 3));

	/* the MTL names both materials with a diffuse colour */
	CHECK_INT(buf_append(&mtl, "", 1), 0);
	mtl_text = (const char *)mtl.data;
	CHECK(strstr(mtl_text, "newmtl bark\n"));
	CHECK(strstr(mtl_text, "newmtl leaves\n"));
	CHECK(strstr(strstr(mtl_text, "newmtl bark\n"), "\nKd "));
	CHECK(strstr(strstr(mtl_text, "newmtl leaves\n"), "\nKd "));

	/* deterministic */
	export_tree(&t, &obj2, &mtl2, &tm);
	CHECK_INT(obj.len, obj2.len);
	CHECK(!memcmp(obj.data, obj2.data, obj.len));

	/* renamed afterwards (the kiosk names its files once the obj is built): only the
	 * mtllib line changes, both ways, longer and shorter */
	{
		static const char head[] = "# edaha tree: metres, y up\nmtllib tree-10042.mtl\n";
		size_t was = obj.len;

		CHECK_INT(export_obj_mtllib(&obj2, "tree-10042.mtl"), 0);
		CHECK_INT(obj2.len, was + strlen("tree-10042.mtl") - strlen("tree.mtl"));
		CHECK(!memcmp(obj2.data, head, sizeof(head) - 1));
		CHECK(!memcmp(obj2.data + sizeof(head) - 1, obj.data + (sizeof(head) - 1) - 6,
			      was - (sizeof(head) - 1 - 6)));
		CHECK_INT(export_obj_mtllib(&obj2, "tree.mtl"), 0);
		CHECK_INT(obj2.len, obj.len);
		CHECK(!memcmp(obj.data, obj2.data, obj.len));
		CHECK_INT(export_obj_mtllib(&obj2, "a\nb"), -EINVAL);
		CHECK_INT(export_obj_mtllib(&obj2, ""), -EINVAL);
		CHECK_INT(export_obj_mtllib(&mtl2, "x.mtl"), -EINVAL); /* no mtllib line */
		CHECK(!memcmp(obj.data, obj2.data, obj.len));
	}

	/* bad names are refused, nothing written */
	buf_reset(&obj2);
	buf_reset(&mtl2);
	CHECK_INT(export_obj(&t, &tm, NULL, "a\nb", &obj2, &mtl2), -EINVAL);
	CHECK_INT(export_obj(&t, &tm, NULL, NULL, &obj2, &mtl2), -EINVAL);
	CHECK_INT(obj2.len + mtl2.len, 0);

	buf_finish(&obj);
	buf_finish(&mtl);
	buf_finish(&obj2);
	buf_finish(&mtl2);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

static void test_empty(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct buf obj, mtl;
	struct obj_stats st;

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&obj);
	buf_init(&mtl);
	export_tree(&t, &obj, &mtl, &tm);
	parse_obj(&obj, &st, NULL);
	CHECK_INT(st.mtllib, 1);
	CHECK_INT(st.v + st.vn + st.f + st.o, 0);
	CHECK(mtl.len > 0);
	buf_finish(&obj);
	buf_finish(&mtl);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Numbers: rounded like "%.6f", never "-0.000000". */
static void test_numbers(void)
{
	const float pos[] = { -0.0000001f, 1.5f, -2.25f, 123.456789f, -0.0000004f, 0.0000026f };
	const float nor[] = { 0, 1, 0, 0, 1, 0 };
	const uint32_t idx[] = { 0, 1, 0 };
	struct tree t;
	struct tree_mesh tm;
	struct buf obj, mtl;

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&obj);
	buf_init(&mtl);
	tm.bark.positions = (float *)pos;
	tm.bark.normals = (float *)nor;
	tm.bark.indices = (uint32_t *)idx;
	tm.bark.nvertices = 2;
	tm.bark.nindices = 3;
	CHECK_INT(export_obj(&t, &tm, NULL, "m.mtl", &obj, &mtl), 0);
	CHECK_INT(buf_append(&obj, "", 1), 0);
	CHECK(strstr((const char *)obj.data, "\nv 0.000000 1.500000 -2.250000\n"));
	/* 123.456789f is 123.4567871... as a float */
	CHECK(strstr((const char *)obj.data, "\nv 123.456787 0.000000 0.000003\n"));
	CHECK(strstr((const char *)obj.data, "\nf 1//1 2//2 1//1\n"));
	buf_finish(&obj);
	buf_finish(&mtl);
	tree_finish(&t);
}

int main(void)
{
	test_tree();
	test_empty();
	test_numbers();
	return 0;
}
