/* SPDX-License-Identifier: MIT */
/*
 * check_seasons SPRING SUMMER AUTUMN WINTER: compares the exports edaha wrote of one tree
 * in each season (each a directory with model.glb, model.obj, model.mtl, skeleton.json;
 * seasons.sh makes them). Without the app's marks it cannot tell the leaves apart, so it
 * checks what the files say of each other: the bark the same everywhere, the leaves'
 * geometry summer's, spring's and autumn's leaf vertices palette colours (every shade,
 * one a triangle), each OBJ face under the material of its vertices' glTF colour, winter
 * bare, the skeletons the same but for the season's name. Exits non-zero on the first
 * difference, saying where.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "export_text.h"
#include "glb_read.h"
#include "season.h"
#include "test.h"

static const enum season order[] = { SEASON_SPRING, SEASON_SUMMER, SEASON_AUTUMN, SEASON_WINTER };
#define NSEASONS (sizeof(order) / sizeof(*order))

struct files {
	struct buf glb, obj, mtl, skel;
	struct glb g;
};

/* The whole file, NUL-terminated (not counted in len). */
static void read_all(const char *dir, const char *name, struct buf *b)
{
	char path[4096], chunk[65536];
	FILE *f;
	size_t n;

	buf_init(b);
	CHECK(snprintf(path, sizeof(path), "%s/%s", dir, name) < (int)sizeof(path));
	f = fopen(path, "rb");
	if (!f) {
		fprintf(stderr, "check_seasons: %s: %s\n", path, strerror(errno));
		exit(1);
	}
	while ((n = fread(chunk, 1, sizeof(chunk), f)) > 0)
		CHECK_INT(buf_append(b, chunk, n), 0);
	CHECK(!ferror(f));
	fclose(f);
	CHECK_INT(buf_append(b, "", 1), 0);
	b->len--;
}

static unsigned char byte_of(float c)
{
	long v = lround((double)c * 255.0);

	return (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
}

/* Which palette entry an RGBA is (exactly its bytes), or -1. */
static int entry_of(const unsigned char *rgba, const struct season_rgb *pal, size_t n)
{
	for (size_t k = 0; k < n; k++) {
		if (rgba[0] == byte_of(pal[k].r) && rgba[1] == byte_of(pal[k].g) &&
		    rgba[2] == byte_of(pal[k].b) && rgba[3] == 255)
			return (int)k;
	}
	return -1;
}

static int64_t attr(struct json_object *prim, const char *name)
{
	struct json_object *v;

	if (!json_object_object_get_ex(get(prim, "attributes"), name, &v))
		return -1;
	return json_object_get_int64(v);
}

static void check_bark(const struct files *f, const struct files *summer)
{
	struct json_object *p = glb_prim_of(&f->g, "bark"), *ps = glb_prim_of(&summer->g, "bark");
	char *bark = section(&f->obj, "o bark", "o "), *sbark = section(&summer->obj, "o bark", "o ");
	size_t head = (size_t)(strstr((const char *)summer->mtl.data, "\n\nnewmtl leaves\n") -
			       (const char *)summer->mtl.data) + 1;

	CHECK(p && ps && bark && sbark);
	CHECK(glb_same_accessor(&f->g, attr(p, "POSITION"), &summer->g, attr(ps, "POSITION")));
	CHECK(glb_same_accessor(&f->g, attr(p, "NORMAL"), &summer->g, attr(ps, "NORMAL")));
	CHECK(glb_same_accessor(&f->g, get_int(p, "indices"), &summer->g, get_int(ps, "indices")));
	CHECK(!strcmp(bark, sbark));
	CHECK(f->mtl.len >= head && !memcmp(f->mtl.data, summer->mtl.data, head));
	free(bark);
	free(sbark);
}

/*
 * Spring's or autumn's leaves: summer's geometry; a palette colour a vertex, all of
 * them used, one a triangle; each OBJ face under the material of its glTF colour; the MTL
 * the materials used with their Kd.
 */
static void check_colored(const struct files *f, const struct files *summer, enum season s)
{
	const struct season_rgb *pal;
	size_t npal = season_palette(s, &pal), len, nidx, nb, nv, used = 0, nmat = 0;
	char name[32], prefix[32];
	struct json_object *p, *ps = glb_prim_of(&summer->g, "leaves");
	const unsigned char *rgba, *idx;
	char *leaves = section(&f->obj, "o leaves", "o ");
	char *sleaves = section(&summer->obj, "o leaves", "o ");
	char *v = lines_of(leaves, "v"), *sv = lines_of(sleaves, "v");
	char *vn = lines_of(leaves, "vn"), *svn = lines_of(sleaves, "vn");
	char *fa = lines_of(leaves, "f"), *sfa = lines_of(sleaves, "f");
	char *sorted = sorted_lines(fa), *ssorted = sorted_lines(sfa);
	bool seen[SEASON_MAX_COLORS] = { false }, group[SEASON_MAX_COLORS] = { false };
	long cur = -1;

	snprintf(name, sizeof(name), "leaves-%s", season_name(s));
	p = glb_prim_of(&f->g, name);
	CHECK(p && ps);
	CHECK(glb_same_accessor(&f->g, attr(p, "POSITION"), &summer->g, attr(ps, "POSITION")));
	CHECK(glb_same_accessor(&f->g, attr(p, "NORMAL"), &summer->g, attr(ps, "NORMAL")));
	CHECK(glb_same_accessor(&f->g, get_int(p, "indices"), &summer->g, get_int(ps, "indices")));
	rgba = glb_accessor_bytes(&f->g, attr(p, "COLOR_0"), &len);
	nv = len / 4;
	CHECK_INT(nv, get_int(at(get(f->g.json, "accessors"), (size_t)attr(p, "POSITION")), "count"));
	for (size_t i = 0; i < nv; i++) {
		int k = entry_of(rgba + 4 * i, pal, npal);

		CHECK(k >= 0);
		used += !seen[k];
		seen[k] = true;
	}
	CHECK_INT(used, npal);
	idx = glb_accessor_bytes(&f->g, get_int(p, "indices"), &nidx);
	for (size_t t = 0; t + 12 <= nidx; t += 12)
		for (int c = 1; c < 3; c++)
			CHECK(!memcmp(rgba + 4 * u32(idx + t), rgba + 4 * u32(idx + t + 4 * c), 4));

	/* OBJ: summer's vertices, normals and faces, grouped under palette materials */
	CHECK(leaves && sleaves);
	CHECK(!strcmp(v, sv) && !strcmp(vn, svn) && !strcmp(sorted, ssorted));
	nb = (size_t)get_int(at(get(f->g.json, "accessors"), 0), "count");
	snprintf(prefix, sizeof(prefix), "leaves-%s-", season_name(s));
	for (const char *l = leaves; *l; l = strchr(l, '\n') + 1) {
		unsigned long vi[3], ni[3];

		if (!strncmp(l, "usemtl ", 7)) {
			CHECK(!strncmp(l + 7, prefix, strlen(prefix)));
			cur = strtol(l + 7 + strlen(prefix), NULL, 10);
			CHECK(cur >= 0 && (size_t)cur < npal && !group[cur]);
			group[cur] = true;
			continue;
		}
		if (strncmp(l, "f ", 2))
			continue;
		CHECK(sscanf(l, "f %lu//%lu %lu//%lu %lu//%lu", &vi[0], &ni[0], &vi[1], &ni[1],
			     &vi[2], &ni[2]) == 6);
		for (int c = 0; c < 3; c++) {
			CHECK(vi[c] > nb && vi[c] - 1 - nb < nv);
			CHECK_INT(entry_of(rgba + 4 * (vi[c] - 1 - nb), pal, npal), cur);
		}
	}
	for (size_t k = 0; k < npal; k++) {
		char key[64];
		const char *m;
		double kd[3];

		CHECK(group[k]);
		snprintf(key, sizeof(key), "\nnewmtl %s%zu\n", prefix, k);
		m = strstr((const char *)f->mtl.data, key);
		CHECK(m && (m = strstr(m + 1, "\nKd ")));
		CHECK(sscanf(m, "\nKd %lf %lf %lf", &kd[0], &kd[1], &kd[2]) == 3);
		CHECK_NEAR(kd[0], pal[k].r, 5e-7);
		CHECK_NEAR(kd[1], pal[k].g, 5e-7);
		CHECK_NEAR(kd[2], pal[k].b, 5e-7);
	}
	for (const char *m = strstr((const char *)f->mtl.data, "newmtl "); m;
	     m = strstr(m + 1, "newmtl "))
		nmat++;
	CHECK_INT(nmat, npal + 1);
	free(leaves);
	free(sleaves);
	free(v);
	free(sv);
	free(vn);
	free(svn);
	free(fa);
	free(sfa);
	free(sorted);
	free(ssorted);
}

static void check_summer(const struct files *f)
{
	struct json_object *p = glb_prim_of(&f->g, "leaves");

	CHECK(p);
	CHECK_INT(attr(p, "COLOR_0"), -1);
	CHECK(strstr((const char *)f->obj.data, "\no leaves\nusemtl leaves\n"));
}

static void check_winter(const struct files *f, const struct files *summer)
{
	const char *cut = strstr((const char *)summer->obj.data, "\no leaves\n");

	CHECK_INT(json_object_array_length(get(at(get(f->g.json, "meshes"), 0), "primitives")), 1);
	CHECK_INT(count(f->g.json, "materials"), 1);
	CHECK(!strstr(json_object_to_json_string(f->g.json), "leaves"));
	CHECK(cut);
	CHECK_INT(f->obj.len, cut + 1 - (const char *)summer->obj.data);
	CHECK(!memcmp(f->obj.data, summer->obj.data, f->obj.len));
	CHECK(!strstr((const char *)f->mtl.data, "leaves"));
}

int main(int argc, char **argv)
{
	struct files f[NSEASONS];
	const struct files *summer = &f[1];

	if (argc != 1 + (int)NSEASONS) {
		fprintf(stderr, "usage: check_seasons SPRING SUMMER AUTUMN WINTER\n");
		return 2;
	}
	for (size_t i = 0; i < NSEASONS; i++) {
		read_all(argv[1 + i], "model.glb", &f[i].glb);
		read_all(argv[1 + i], "model.obj", &f[i].obj);
		read_all(argv[1 + i], "model.mtl", &f[i].mtl);
		read_all(argv[1 + i], "skeleton.json", &f[i].skel);
		parse_glb(&f[i].glb, &f[i].g);
		check_accessors(&f[i].g);
	}
	for (size_t i = 0; i < NSEASONS; i++) {
		printf("%s: %zu bytes of glb, %zu of OBJ, %zu of MTL\n", season_name(order[i]),
		       f[i].glb.len, f[i].obj.len, f[i].mtl.len);
		check_bark(&f[i], summer);
		check_skeleton_season(&f[i].skel, &summer->skel, order[i]);
		if (order[i] == SEASON_SUMMER)
			check_summer(&f[i]);
		else if (order[i] == SEASON_WINTER)
			check_winter(&f[i], summer);
		else
			check_colored(&f[i], summer, order[i]);
	}
	for (size_t i = 0; i < NSEASONS; i++) {
		json_object_put(f[i].g.json);
		buf_finish(&f[i].glb);
		buf_finish(&f[i].obj);
		buf_finish(&f[i].mtl);
		buf_finish(&f[i].skel);
	}
	printf("check_seasons: the four seasons agree\n");
	return 0;
}
