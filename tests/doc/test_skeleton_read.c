/* SPDX-License-Identifier: MIT */
/*
 * skeleton_read (--skeleton): a valid file's branches read exactly, leaves and vines
 * ignored; the limits; every malformed file in tests/doc/skeleton/malformed refused with
 * -EINVAL at the line its EXPECT file names, the tree untouched; allocations failing.
 * argv[1]: tests/doc/skeleton (valid.json and malformed/ in it).
 */
#include <errno.h>
#include <json-c/json.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "doc.h"
#include "fail_alloc.h"
#include "fileio.h"
#include "skeleton_read.h"
#include "test.h"

static char *path_of(const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	char *p = malloc(n);

	CHECK(p);
	snprintf(p, n, "%s/%s", dir, name);
	return p;
}

static char *read_file(const char *dir, const char *name, size_t *len)
{
	struct error err = { { 0 } };
	char *path = path_of(dir, name), *data;

	if (fileio_read_all(path, 1 << 20, &data, len, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
	free(path);
	return data;
}

/* A tree holding one branch, to see that a refusal leaves it alone. */
static void one_branch(struct tree *t)
{
	struct vec3 p[2] = { { 1, 2, 3 }, { 4, 5, 6 } };
	double r[2] = { 0.5, 0.25 };

	tree_init(t);
	CHECK_INT(tree_add_branch(t, -1, 0, ORIGIN_CLONE, p, r, 2), 0);
}

static void check_untouched(const struct tree *t)
{
	CHECK_INT(t->nbranches, 1);
	CHECK(t->branches[0].origin == ORIGIN_CLONE && t->branches[0].points[1].z == 6 &&
	      t->branches[0].radii[1] == 0.25);
}

static void test_valid(const char *dir)
{
	struct error err = { { 0 } };
	struct tree t;
	size_t len;
	char *data = read_file(dir, "valid.json", &len);
	const struct branch *b;

	one_branch(&t);
	CHECK_INT(skeleton_read(data, len, "valid.json", &t, &err), 0);
	CHECK_INT(t.nbranches, 2);
	CHECK_INT(t.nleaves, 0);
	CHECK(!t.lifted);
	b = &t.branches[0];
	CHECK(b->id == 0 && b->parent == -1 && b->generation == 0 && b->parent_t == 0);
	CHECK(b->origin == ORIGIN_SKETCH && b->npoints == 3);
	CHECK(b->points[2].x == 0 && b->points[2].y == 2 && b->radii[1] == 0.08);
	b = &t.branches[1];
	CHECK(b->id == 1 && b->parent == 0 && b->generation == 1 && b->parent_t == 0.5);
	CHECK(b->npoints == 2 && b->points[1].x == 0.5 && b->points[1].y == 1.5);
	CHECK(b->radii[0] == 0.04 && b->radii[1] == 0.02);
	tree_finish(&t);
	free(data);
}

static int read_text(const char *text, struct tree *t, struct error *err)
{
	return skeleton_read(text, strlen(text), "s.json", t, err);
}

/* What is ignored, and what is taken: version 1, a top-level number's end, no branches. */
static void test_forms(void)
{
	static const char *ok[] = {
		"{\"format\":\"edaha-skeleton\",\"version\":1,\"branches\":[]}",
		"{\"format\":\"edaha-skeleton\",\"version\":2,\"branches\":[],\"leaves\":[{\"x\":1}],"
		"\"vines\":[{}],\"wood\":{\"grid\":64},\"future\":[1,[2,{\"a\":\"]}\"}]]}",
		"\r\n\t {\"branches\":[{\"radii\":[1,2],\"points\":[[1,2,3],[-1000,1000,0]],"
		"\"parent_t\":1,\"generation\":1000,\"parent\":-1,\"id\":0,\"level\":3,"
		"\"origin\":\"generate\"}],\"version\":2,\"format\":\"edaha-skeleton\"} \n",
	};
	struct error err = { { 0 } };
	struct tree t;

	for (size_t i = 0; i < sizeof(ok) / sizeof(*ok); i++) {
		tree_init(&t);
		if (read_text(ok[i], &t, &err) != 0) {
			fprintf(stderr, "refused: %s\n", err.msg);
			CHECK(0);
		}
		CHECK_INT(t.nbranches, i == 2);
		tree_finish(&t);
	}
	tree_init(&t);
	CHECK_INT(read_text(ok[2], &t, &err), 0);
	CHECK(t.branches[0].origin == ORIGIN_SKETCH && t.branches[0].level == 0);
	CHECK(t.branches[0].generation == 1000 && t.branches[0].points[1].x == -1000);
	tree_finish(&t);
}

/* A file of n branches of m points each, every branch a child of the one before. */
static char *chain(size_t n, size_t m)
{
	struct buf b;

	buf_init(&b);
	buf_printf(&b, "{\"format\":\"edaha-skeleton\",\"version\":2,\"branches\":[");
	for (size_t i = 0; i < n; i++) {
		buf_printf(&b, "%s{\"id\":%zu,\"parent\":%d,\"generation\":0,\"parent_t\":1,\"points\":[",
			   i ? "," : "", i, (int)i - 1);
		for (size_t k = 0; k < m; k++)
			buf_printf(&b, "%s[0,%zu,0]", k ? "," : "", k % 1000);
		buf_printf(&b, "],\"radii\":[");
		for (size_t k = 0; k < m; k++)
			buf_printf(&b, "%s0.1", k ? "," : "");
		buf_printf(&b, "]}");
	}
	buf_printf(&b, "]}");
	CHECK(!b.failed);
	CHECK(buf_append(&b, "", 1) == 0);
	return (char *)b.data;
}

static void limit(size_t n, size_t m, int want, const char *text)
{
	struct error err = { { 0 } };
	char *s = chain(n, m);
	struct tree t;

	tree_init(&t);
	CHECK_INT(read_text(s, &t, &err), want);
	if (want == 0)
		CHECK_INT(t.nbranches, n);
	else if (!strstr(err.msg, text) || strncmp(err.msg, "s.json:1: ", 10) != 0) {
		fprintf(stderr, "expected \"s.json:1: ...%s...\", got \"%s\"\n", text, err.msg);
		CHECK(0);
	}
	tree_finish(&t);
	free(s);
}

static void test_limits(void)
{
	struct error err = { { 0 } };
	struct tree t;

	limit(TREE_MAX_BRANCHES, 2, 0, NULL);
	limit(TREE_MAX_BRANCHES + 1, 2, -EINVAL, "branches: 10001, more than 10000");
	limit(1, DOC_MAX_STROKE_POINTS, 0, NULL);
	limit(1, DOC_MAX_STROKE_POINTS + 1, -EINVAL, "points: 100001, more than 100000");
	/* the size is checked before a byte is read */
	tree_init(&t);
	CHECK_INT(skeleton_read("", (size_t)SKELETON_READ_MAX_BYTES + 1, "big.json", &t, &err),
		  -EINVAL);
	CHECK(strcmp(err.msg, "big.json: larger than 64 MiB") == 0);
	tree_finish(&t);
}

static void check_malformed(const char *dir, const char *name, unsigned long at, const char *text)
{
	char *mdir = path_of(dir, "malformed"), *path = path_of(mdir, name), want[256], *file;
	struct error err = { { 0 } };
	struct tree t;
	size_t flen;
	int ret;

	file = read_file(mdir, name, &flen);
	one_branch(&t);
	ret = skeleton_read(file, flen, path, &t, &err);
	if (ret != -EINVAL) {
		fprintf(stderr, "%s: not refused with -EINVAL (%d)\n", path, ret);
		CHECK(0);
	}
	check_untouched(&t);
	snprintf(want, sizeof(want), "%s:%lu: ", path, at);
	if (strncmp(err.msg, want, strlen(want)) != 0 || !strstr(err.msg, text)) {
		fprintf(stderr, "%s: expected \"%s...%s...\", got \"%s\"\n", name, want, text, err.msg);
		CHECK(0);
	}
	printf("%s\n", err.msg);
	tree_finish(&t);
	free(file);
	free(path);
	free(mdir);
}

static void test_malformed(const char *dir)
{
	char *mdir = path_of(dir, "malformed"), *data;
	size_t len;
	int count = 0;

	data = read_file(mdir, "EXPECT", &len);
	for (char *line = strtok(data, "\n"); line; line = strtok(NULL, "\n")) {
		char name[128];
		unsigned long at;
		int skip = 0;

		if (line[0] == '#')
			continue;
		CHECK(sscanf(line, "%127s %lu %n", name, &at, &skip) == 2 && skip > 0);
		CHECK(line[skip]);
		check_malformed(dir, name, at, line + skip);
		count++;
	}
	CHECK(count >= 25);
	free(data);
	free(mdir);
}

/* The allocations json-c makes parsing data as skeleton_read has it parse. */
static long json_allocations(const char *data, size_t len)
{
	struct json_tokener *tok;
	struct json_object *o;
	long n;

	fail_alloc_at(LONG_MAX);
	tok = json_tokener_new();
	CHECK(tok);
	json_tokener_set_flags(tok, JSON_TOKENER_STRICT | JSON_TOKENER_VALIDATE_UTF8);
	o = json_tokener_parse_ex(tok, data, (int)len);
	n = fail_alloc_calls();
	fail_alloc_off();
	CHECK(o);
	json_object_put(o);
	json_tokener_free(tok);
	return n;
}

/* Each of edaha's allocations failing in turn: -ENOMEM, the tree untouched, nothing
 * leaked; then, none failing, it reads. json-c's own are left alone: json-c 0.16 crashes
 * when one fails (a failed strdup of a key goes to strlen), skeleton_read cannot help it. */
static void test_alloc(const char *dir)
{
	size_t len;
	char *data = read_file(dir, "valid.json", &len);
	long refused = 0;

	if (!FAIL_ALLOC_HOOK || !fail_alloc_hooked()) {
		free(data);
		return;
	}
	for (long n = json_allocations(data, len);; n++) {
		struct error err = { { 0 } };
		struct tree t;
		long live, calls;
		int ret;

		one_branch(&t);
		live = fail_alloc_live();
		fail_alloc_at(n);
		ret = skeleton_read(data, len, "valid.json", &t, &err);
		calls = fail_alloc_calls();
		fail_alloc_off();
		if (ret == 0) {
			CHECK_INT(t.nbranches, 2);
			CHECK(t.branches[0].npoints == 3 && t.branches[1].npoints == 2);
			CHECK(t.branches[1].radii[1] == 0.02);
			tree_finish(&t);
			CHECK(calls <= n); /* none failed: every one has been tried */
			printf("%ld allocations, %ld of edaha's failing refused\n", n, refused);
			break;
		}
		if (fail_alloc_live() != live)
			fprintf(stderr, "allocation %ld failing: %ld blocks leaked\n", n,
				fail_alloc_live() - live);
		CHECK_INT(fail_alloc_live(), live);
		CHECK_INT(ret, -ENOMEM);
		check_untouched(&t);
		tree_finish(&t);
		refused++;
	}
	CHECK(refused > 0);
	free(data);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	test_valid(argv[1]);
	test_forms();
	test_limits();
	test_malformed(argv[1]);
	test_alloc(argv[1]);
	return 0;
}
