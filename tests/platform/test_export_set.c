/* SPDX-License-Identifier: MIT */
/*
 * Export sets into a directory fd, as on a USB stick: the numbering from one listing
 * (thousands of files, names in any case, our leftovers), never over a name or through
 * a symlink planted at a temporary or a final name, and on failure (a full disk,
 * simulated with RLIMIT_FSIZE) nothing of the set left behind. The take-home page
 * (tree-NNNN.html, issue 28) with the set: its temporary ours by name and every other
 * name classified as before (seeded random names against the rules written as regular
 * expressions), written and renamed with the others, showing the set's number, the same
 * bytes whatever else the stick holds (a file named "<script>x.glb"), never over a name,
 * nothing of it left on failure; with the viewer's scripts (Debian's libjs-three) when
 * they are installed, else those parts are skipped, said on stdout.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <regex.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"
#include "export_names.h"
#include "export_set.h"
#include "dir_count.h"
#include "page_viewer.h"
#include "rng.h"
#include "test.h"

/* The viewer's scripts, when installed (NULL: the page's parts are skipped). */
static struct page_viewer viewer;
static const struct page_viewer *has_viewer;

static void test_classify(void)
{
	unsigned n = 0;

	CHECK_INT(export_names_classify("tree-0001.glb", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 1);
	CHECK_INT(export_names_classify("TREE-0042.GLB", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 42);
	CHECK_INT(export_names_classify("Tree-7", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 7);
	CHECK_INT(export_names_classify("tree-12345.whatever.txt", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 12345);
	CHECK_INT(export_names_classify("tree-000000000000000003.png", &n), EXPORT_NAME_FINAL);
	CHECK_INT(n, 3);
	/* not ours, or numbers no name of ours has */
	CHECK_INT(export_names_classify("tree-0001x.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-0000.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-100000.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("tree-99999999999999999999999.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("mytree-0001.glb", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("..", &n), EXPORT_NAME_OTHER);
	/* temporaries: exactly ours */
	CHECK_INT(export_names_classify(".tree-0009.glb.tmp", &n), EXPORT_NAME_TEMP);
	CHECK_INT(n, 9);
	CHECK_INT(export_names_classify(".TREE-0009.EDAHA.TMP", &n), EXPORT_NAME_TEMP);
	CHECK_INT(export_names_classify(".tree-0009.txt.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0009.glb.tmp2", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0009.glb", &n), EXPORT_NAME_OTHER);
	/* the page's: its temporary is ours, nothing near it is */
	CHECK_INT(export_names_classify(".tree-0010.html.tmp", &n), EXPORT_NAME_TEMP);
	CHECK_INT(n, 10);
	CHECK_INT(export_names_classify(".Tree-0010.HTML.Tmp", &n), EXPORT_NAME_TEMP);
	CHECK_INT(export_names_classify("tree-0010.html", &n), EXPORT_NAME_FINAL);
	CHECK_INT(export_names_classify(".tree-0010.htm.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0010.html", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0010.html.tmp.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".tree-0010.htmlx.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify(".index.html.tmp", &n), EXPORT_NAME_OTHER);
	CHECK_INT(export_names_classify("index.html", &n), EXPORT_NAME_OTHER);
}

/*
 * Seeded random names made of the pieces names are made of, classified against the
 * rules as regular expressions: before the page, FINAL is tree-N[.anything] and TEMP
 * .tree-N.{glb,obj,mtl,png,edaha}.tmp (any case, 1 <= N <= 99999); the page adds .html to
 * TEMP's list and changes nothing else. Counts the names of each kind seen.
 */
static void test_classify_random(void)
{
	static const char *const pieces[] = {
		".", "tree-", "TREE-", "Tree-", "-", "0", "1", "7", "42", "0001", "99999", "100000",
		".glb", ".obj", ".mtl", ".png", ".edaha", ".html", ".HTML", ".htm", ".tmp", ".TMP",
		"x", "<script>", " ", "index", ".txt", "..",
	};
	regex_t final, temp_old, temp_new;
	regmatch_t m[2];
	struct rng r;
	char name[256];
	int counts[3] = { 0 }, changed = 0, cases = test_cases(20000);

	CHECK_INT(regcomp(&final, "^tree-0*([1-9][0-9]{0,4})(\\..*)?$", REG_EXTENDED | REG_ICASE), 0);
	CHECK_INT(regcomp(&temp_old, "^\\.tree-0*([1-9][0-9]{0,4})\\.(glb|obj|mtl|png|edaha)\\.tmp$",
			  REG_EXTENDED | REG_ICASE), 0);
	CHECK_INT(regcomp(&temp_new, "^\\.tree-0*([1-9][0-9]{0,4})\\.(glb|obj|mtl|png|edaha|html)\\.tmp$",
			  REG_EXTENDED | REG_ICASE), 0);
	rng_seed(&r, 28);
	for (int c = 0; c < cases; c++) {
		size_t len = 0, n = 1 + rng_next(&r) % 7;
		enum export_name_kind want = EXPORT_NAME_OTHER, got;
		unsigned number = 0, want_number = 0;

		name[0] = '\0';
		/* half shaped as ours are (a number, a suffix, .tmp, each maybe), so the rules'
		 * edges are what is drawn; the rest pieces anyhow */
		if (rng_next(&r) % 2) {
			static const char *const numbers[] = { "1", "0042", "99999", "100000", "0", "", "7x" };
			static const char *const ends[] = { "", ".tmp", ".TMP", ".tmp2", ".tmp.tmp" };

			len = (size_t)snprintf(name, sizeof(name), "%s%s%s%s%s",
					       rng_next(&r) % 2 ? "." : "",
					       rng_next(&r) % 2 ? "tree-" : "TrEe-",
					       numbers[rng_next(&r) % (sizeof(numbers) / sizeof(*numbers))],
					       pieces[12 + rng_next(&r) % 10],
					       ends[rng_next(&r) % (sizeof(ends) / sizeof(*ends))]);
			n = rng_next(&r) % 2;
		}
		for (size_t i = 0; i < n; i++) {
			const char *p = pieces[rng_next(&r) % (sizeof(pieces) / sizeof(*pieces))];

			if (len + strlen(p) < sizeof(name))
				len += (size_t)snprintf(name + len, sizeof(name) - len, "%s", p);
		}
		if (regexec(&final, name, 2, m, 0) == 0 || regexec(&temp_new, name, 2, m, 0) == 0) {
			want = name[0] == '.' ? EXPORT_NAME_TEMP : EXPORT_NAME_FINAL;
			want_number = (unsigned)strtoul(name + m[1].rm_so, NULL, 10);
		}
		got = export_names_classify(name, &number);
		if (got != want)
			fprintf(stderr, "\"%s\": %d, want %d\n", name, got, want);
		CHECK_INT(got, want);
		if (want != EXPORT_NAME_OTHER)
			CHECK_INT(number, want_number);
		/* the page's temporaries are the only names that are not what they were */
		if ((regexec(&temp_old, name, 0, NULL, 0) == 0) != (regexec(&temp_new, name, 0, NULL, 0) == 0))
			changed++;
		counts[got]++;
	}
	printf("export_names: %d random names (%d other, %d final, %d temporaries, %d of them "
	       "the page's), each as the rules say\n", cases, counts[EXPORT_NAME_OTHER],
	       counts[EXPORT_NAME_FINAL], counts[EXPORT_NAME_TEMP], changed);
	CHECK(changed > 0 && counts[EXPORT_NAME_TEMP] > changed && counts[EXPORT_NAME_FINAL] > 0);
	regfree(&final);
	regfree(&temp_old);
	regfree(&temp_new);
}

static void test_next(void)
{
	struct export_names *names = malloc(sizeof(*names));
	char s[48];
	unsigned n;

	CHECK(names);
	export_names_init(names);
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 1);
	export_names_add(names, "tree-0003.png");
	export_names_add(names, "notes.txt");
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 4); /* the newest sorts last, a gap stays a gap */
	export_names_add(names, "tree-99999.glb");
	CHECK_INT(export_names_next(names, &n), 0);
	CHECK_INT(n, 1); /* at the top: the lowest free one */
	for (unsigned v = 1; v <= EXPORT_NAMES_MAX; v++) {
		snprintf(s, sizeof(s), "tree-%u", v);
		export_names_add(names, s);
	}
	CHECK_INT(export_names_next(names, &n), -ENOSPC);
	CHECK_INT(export_names_format(s, sizeof(s), 7, ".glb", false), 0);
	CHECK(!strcmp(s, "tree-0007.glb"));
	CHECK_INT(export_names_format(s, sizeof(s), 12345, ".edaha", true), 0);
	CHECK(!strcmp(s, ".tree-12345.edaha.tmp"));
	CHECK_INT(export_names_format(s, 8, 1, ".glb", false), -ENAMETOOLONG);
	free(names);
}

static void touch(int dirfd, const char *name)
{
	int fd = openat(dirfd, name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);

	CHECK(fd >= 0);
	CHECK_INT(write(fd, "x", 1), 1);
	close(fd);
}

static bool exists(int dirfd, const char *name)
{
	struct stat st;

	return fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0;
}

static void set_of(struct app *app, struct export_set *s, bool picture)
{
	static uint8_t rgba[64 * 64 * 4];
	struct error err = { { 0 } };

	CHECK_INT(export_set_build(s, app, picture ? rgba : NULL, &err), 0);
}

static void test_save(struct app *app, const char *root)
{
	char path[600], base[32], line[256];
	struct error err = { { 0 } };
	struct export_set s;
	int dirfd;
	FILE *f;
	bool found = false;

	snprintf(path, sizeof(path), "%s/save", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, true);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001"));
	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
		snprintf(path, sizeof(path), "tree-0001%s", export_names_suffixes[i]);
		CHECK(exists(dirfd, path) == (i != EXPORT_SET_HTML || has_viewer));
	}
	CHECK_INT(dir_count(dirfd, ".", "."), 2); /* . and .., no temporaries */
	/* the obj names its own mtl */
	snprintf(path, sizeof(path), "%s/save/tree-0001.obj", root);
	f = fopen(path, "r");
	CHECK(f);
	while (fgets(line, sizeof(line), f))
		found |= strcmp(line, "mtllib tree-0001.mtl\n") == 0;
	fclose(f);
	CHECK(found);
	/* no picture: four files */
	set_of(app, &s, false);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0002"));
	CHECK(!exists(dirfd, "tree-0002.png"));
	CHECK(exists(dirfd, "tree-0002.edaha"));

	/* a symlink planted at a final name (a hostile ext4 stick) is a taken name, and
	 * stays as it was; the set goes past it */
	CHECK_INT(symlinkat("/etc/passwd", dirfd, "tree-0003.glb"), 0);
	/* one at the next set's temporary: ours by name, so removed unfollowed */
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".tree-0004.obj.tmp"), 0);
	set_of(app, &s, true);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0005"));
	{
		char target[64] = { 0 };

		CHECK(readlinkat(dirfd, "tree-0003.glb", target, sizeof(target) - 1) > 0);
		CHECK(!strcmp(target, "/etc/passwd"));
	}
	CHECK(!exists(dirfd, ".tree-0004.obj.tmp"));
	CHECK_INT(dir_count(dirfd, ".", "."), 2);

	/* a symlink planted at a temporary after the listing: O_EXCL | O_NOFOLLOW refuses
	 * it, it is not followed nor removed, and nothing of the set is left */
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".tree-0006.mtl.tmp"), 0);
	CHECK_INT(export_set_write(dirfd, &s, 6, &err), -EEXIST);
	CHECK(strstr(err.msg, "tree-0006.mtl"));
	CHECK(exists(dirfd, ".tree-0006.mtl.tmp"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0006"), 0);
	CHECK_INT(dir_count(dirfd, ".", "."), 3);
	CHECK_INT(unlinkat(dirfd, ".tree-0006.mtl.tmp", 0), 0);

	/* a final name that turned up after the listing: the rename refuses to replace
	 * it, the renamed ones are taken back */
	touch(dirfd, "tree-0006.png");
	CHECK_INT(export_set_write(dirfd, &s, 6, &err), -EEXIST);
	CHECK_INT(dir_count(dirfd, ".", "tree-0006"), 1);
	CHECK_INT(dir_count(dirfd, ".", "."), 2);
	/* and save goes round once more, past it */
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0007"));

	/* the fallback without RENAME_NOREPLACE refuses too */
	touch(dirfd, "a");
	touch(dirfd, "b");
	CHECK_INT(export_set_rename(dirfd, "a", "b", false), -EEXIST);
	CHECK_INT(export_set_rename(dirfd, "a", "c", false), 0);
	CHECK(exists(dirfd, "c") && !exists(dirfd, "a"));
	CHECK_INT(export_set_rename(dirfd, "c", "b", true), -EEXIST);
	export_set_finish(&s);
	close(dirfd);
}

static void test_many(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	int dirfd;

	snprintf(path, sizeof(path), "%s/many", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	/* thousands of files, as a well-used stick's, in the cases other systems write */
	for (int i = 1; i <= 3000; i++) {
		static const char *const forms[] = { "tree-%04d.glb", "TREE-%04d.PNG", "Tree-%d.Obj",
						     "photo-%d.jpg" };

		snprintf(path, sizeof(path), forms[i % 4], i);
		touch(dirfd, path);
	}
	export_set_init(&s);
	set_of(app, &s, false);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-3001")); /* past tree-3000.glb; 2999 is a photo */
	CHECK(exists(dirfd, "tree-3001.glb"));
	export_set_finish(&s);
	close(dirfd);
}

/* A full disk, as a file size limit: the first file is written, a later one fails. */
static void test_full(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct rlimit old, lim;
	int dirfd;

	snprintf(path, sizeof(path), "%s/full", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, true);
	/* the glb fits, a larger file after it does not */
	CHECK(s.files[EXPORT_SET_PNG].len > s.files[EXPORT_SET_GLB].len);
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = s.files[EXPORT_SET_GLB].len;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "tree-0001.") && strstr(err.msg, strerror(EFBIG)));
	CHECK_INT(dir_count(dirfd, ".", "tree-"), 0);
	CHECK_INT(dir_count(dirfd, ".", "."), 2);
	/* with room again, the same set goes in whole */
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001"));
	export_set_finish(&s);
	close(dirfd);
}

/* Save on today's forest (docs/forest.md): forest-DATE.glb beside the set, never over a
 * name (the same day again: -2, -3, ...), never through a symlink, a stale temporary of
 * ours removed, a bad date refused, a full stick leaving nothing of it. */
static void test_forest(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct rlimit old, lim;
	int dirfd;

	snprintf(path, sizeof(path), "%s/forest", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0);
	export_set_init(&s);
	set_of(app, &s, false);
	CHECK_INT(buf_append(&s.forest, "glTF forest bytes", 17), 0);
	snprintf(s.forest_date, sizeof(s.forest_date), "2026-12-05");
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0001") && !strcmp(s.forest_name, "forest-2026-12-05.glb"));
	CHECK(exists(dirfd, "forest-2026-12-05.glb"));
	/* the same day again, with a symlink at -2 (a hostile stick): past both */
	CHECK_INT(symlinkat("/etc/passwd", dirfd, "forest-2026-12-05-2.glb"), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0002") && !strcmp(s.forest_name, "forest-2026-12-05-3.glb"));
	{
		char target[64] = { 0 };

		CHECK(readlinkat(dirfd, "forest-2026-12-05-2.glb", target, sizeof(target) - 1) > 0);
		CHECK(!strcmp(target, "/etc/passwd"));
	}
	/* a temporary a pulled stick left (another day's too): gone at the next save */
	touch(dirfd, ".forest-2026-11-30.glb.tmp");
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".forest-2026-12-05.glb.tmp"), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(s.forest_name, "forest-2026-12-05-4.glb"));
	CHECK(!exists(dirfd, ".forest-2026-11-30.glb.tmp") && !exists(dirfd, ".forest-2026-12-05.glb.tmp"));
	CHECK_INT(dir_count(dirfd, ".", ".forest"), 0);
	/* a date that is not one: refused, nothing written */
	snprintf(s.forest_date, sizeof(s.forest_date), "../../etc");
	CHECK_INT(export_set_write_forest(dirfd, &s, &err), -EINVAL);
	CHECK_INT(dir_count(dirfd, ".", "forest-"), 4);
	/* a full stick: no temporary, no final name of it */
	snprintf(s.forest_date, sizeof(s.forest_date), "2026-12-06");
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = 8;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(export_set_write_forest(dirfd, &s, &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "forest-2026-12-06.glb"));
	CHECK_INT(dir_count(dirfd, ".", "forest-2026-12-06"), 0);
	CHECK_INT(dir_count(dirfd, ".", ".forest"), 0);
	/* an empty canvas on the forest: the forest alone */
	s.forest_only = true;
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "forest-2026-12-06.glb") && exists(dirfd, base));
	/* three sets of four, as before, and their pages */
	CHECK_INT(dir_count(dirfd, ".", "tree-"), has_viewer ? 15 : 12);
	export_set_finish(&s);
	close(dirfd);
}

static void read_whole(int dirfd, const char *name, struct buf *b)
{
	int fd = openat(dirfd, name, O_RDONLY | O_CLOEXEC);
	char chunk[65536];
	ssize_t n;

	CHECK(fd >= 0);
	buf_reset(b);
	while ((n = read(fd, chunk, sizeof(chunk))) > 0)
		CHECK_INT(buf_append(b, chunk, (size_t)n), 0);
	CHECK(n == 0);
	close(fd);
}

/* The page a set of this number must carry: its .glb's, as export_set_write makes it. */
static void page_of(const struct export_set *s, unsigned number, struct buf *out)
{
	const struct buf *glb = &s->files[EXPORT_SET_GLB];

	buf_reset(out);
	CHECK_INT(page_viewer_html(&s->page, glb->data, glb->len, number, s->page_date, out), 0);
}

/*
 * tree-NNNN.html: with the set, under its number, the same bytes whatever the stick
 * holds besides (hostile names, a page's leftover temporary), never over a name nor
 * through a symlink, nothing of it left when the stick fills; no viewer, no page.
 */
static void test_page(struct app *app, const char *root)
{
	char path[600], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct buf got, want, clean;
	struct rlimit old, lim;
	int dirfd, cleanfd;

	if (!has_viewer) {
		printf("test_page: skipped: no viewer's scripts in %s (libjs-three)\n",
		       page_viewer_dir());
		return;
	}
	buf_init(&got);
	buf_init(&want);
	buf_init(&clean);
	snprintf(path, sizeof(path), "%s/page", root);
	CHECK_INT(mkdir(path, 0755), 0);
	dirfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	snprintf(path, sizeof(path), "%s/page-clean", root);
	CHECK_INT(mkdir(path, 0755), 0);
	cleanfd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(dirfd >= 0 && cleanfd >= 0);
	/* a hostile stick's names, and tree-0004 another kiosk's; a page's leftover */
	touch(dirfd, "<script>x.glb");
	touch(dirfd, "<script>alert(1)<script>.html"); /* no / in a name */
	touch(dirfd, "tree-0003<script>.glb");
	touch(dirfd, "TREE-0004.HTML");
	touch(dirfd, ".tree-0002.html.tmp");
	for (int i = 1; i <= 4; i++) {
		snprintf(path, sizeof(path), "tree-%04d.glb", i);
		touch(cleanfd, path);
	}
	export_set_init(&s);
	CHECK(s.page.viewer == has_viewer); /* the default, as the kiosk sets it */
	set_of(app, &s, true);
	CHECK(s.page_date[0]); /* today, by the local clock */
	snprintf(s.page_date, sizeof(s.page_date), "5 December 2026");
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0005"));
	CHECK(!exists(dirfd, ".tree-0002.html.tmp"));
	read_whole(dirfd, "tree-0005.html", &got);
	page_of(&s, 5, &want);
	CHECK(got.len == want.len && !memcmp(got.data, want.data, got.len));
	{
		const char *said = "\"number\":5,\"date\":\"5 December 2026\"";

		CHECK(memmem(got.data, got.len, said, strlen(said)));
	}
	CHECK(!memmem(got.data, got.len, "alert", 5));
	/* the same set on a stick of plain names: the same page */
	CHECK_INT(export_set_save(cleanfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0005"));
	read_whole(cleanfd, "tree-0005.html", &clean);
	CHECK(clean.len == got.len && !memcmp(clean.data, got.data, got.len));

	/* the page's name taken after the listing: refused, nothing of set 6 left but that
	 * name; save goes on to 7, and that page says 7 */
	touch(dirfd, "tree-0006.html");
	CHECK_INT(export_set_write(dirfd, &s, 6, &err), -EEXIST);
	CHECK(strstr(err.msg, "tree-0006.html"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0006"), 1);
	CHECK_INT(dir_count(dirfd, ".", ".tree-"), 0);
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0007"));
	read_whole(dirfd, "tree-0007.html", &got);
	page_of(&s, 7, &want);
	CHECK(got.len == want.len && !memcmp(got.data, want.data, got.len));

	/* a symlink at the page's temporary after the listing: not followed, not removed */
	CHECK_INT(symlinkat("/nonexistent-edaha-target", dirfd, ".tree-0008.html.tmp"), 0);
	CHECK_INT(export_set_write(dirfd, &s, 8, &err), -EEXIST);
	CHECK(strstr(err.msg, "tree-0008.html"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0008"), 0);
	CHECK_INT(dir_count(dirfd, ".", ".tree-"), 1);
	CHECK_INT(unlinkat(dirfd, ".tree-0008.html.tmp", 0), 0);

	/* a stick with room for all but the page (written last): nothing of the set left */
	CHECK(s.files[EXPORT_SET_HTML].len > s.files[EXPORT_SET_PNG].len &&
	      s.files[EXPORT_SET_HTML].len > s.files[EXPORT_SET_GLB].len);
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = s.files[EXPORT_SET_HTML].len - 1;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(export_set_write(dirfd, &s, 9, &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "tree-0009.html"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0009"), 0);
	CHECK_INT(dir_count(dirfd, ".", ".tree-"), 0);

	/* without the viewer's scripts: the set without its page */
	s.page.viewer = NULL;
	CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
	CHECK(!strcmp(base, "tree-0008")); /* 8 and 9 left no name */
	CHECK(exists(dirfd, "tree-0008.glb") && exists(dirfd, "tree-0008.edaha"));
	CHECK(!exists(dirfd, "tree-0008.html"));
	CHECK_INT(dir_count(dirfd, ".", "tree-0008"), 5);
	printf("test_page: tree-NNNN.html (%zu bytes, its .glb %zu) with its set, the same bytes "
	       "beside hostile names\n", got.len, s.files[EXPORT_SET_GLB].len);
	export_set_finish(&s);
	buf_finish(&got);
	buf_finish(&want);
	buf_finish(&clean);
	close(dirfd);
	close(cleanfd);
}

int main(void)
{
	char root[] = "/tmp/edaha-export-set-XXXXXX", cmd[128];
	struct app *app = app_create(64, 64, 1);

	struct error err = { { 0 } };
	struct page_look look = { .lang = EXPORT_PAGE_EN, .paper = { 0.975f, 0.953f, 0.898f } };

	CHECK(app);
	/* every set carries the page when the viewer's scripts are there, as on the kiosk */
	page_viewer_init(&viewer);
	if (page_viewer_load(&viewer, NULL, &err) == 0)
		look.viewer = has_viewer = &viewer;
	else
		printf("no viewer's scripts (%s): the sets carry no page\n", err.msg);
	export_set_page_default(&look);
	test_classify();
	test_classify_random();
	test_next();
	CHECK(mkdtemp(root));
	test_save(app, root);
	test_many(app, root);
	test_full(app, root);
	test_forest(app, root);
	test_page(app, root);
	export_set_page_default(NULL);
	page_viewer_finish(&viewer);
	app_destroy(app);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	CHECK_INT(system(cmd), 0);
	return 0;
}
