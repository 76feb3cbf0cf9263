/* SPDX-License-Identifier: MIT */
/*
 * The stick's gallery, index.html (gallery.c): three saves listed newest first, each
 * link naming a file of its set; another kiosk's index.html replaced; a symlink named
 * index.html replaced as a link, its target untouched; hostile names never listed nor
 * printed; a full disk (RLIMIT_FSIZE) leaving the old index whole and no temporary; the
 * words and dates of each language; the kiosk's paper. Then seeded random directories of
 * valid, misspelt and hostile names, symlinks and directories: every output passes a
 * strict check of its markup, and lists exactly the trees the directory holds, highest
 * number first, each link and picture a regular file there, each date the file's. And
 * every allocation failed in turn: -ENOMEM or a whole page, nothing leaked.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "export_names.h"
#include "export_set.h"
#include "fail_alloc.h"
#include "gallery.h"
#include "render_shaders.h"
#include "rng.h"
#include "dir_count.h"
#include "test.h"

static char root[] = "/tmp/edaha-gallery-XXXXXX";

/* ---- a strict reading of what gallery.c writes ------------------------------------ */

#define MAX_ITEMS 256

/* What the page shows, in order: each entry's link, picture ("" none), number, date. */
struct page {
	int n;
	char href[MAX_ITEMS][64], src[MAX_ITEMS][64], number[MAX_ITEMS][64], date[MAX_ITEMS][96];
	char lang[8], title[64];
};

static const char *const tags[] = { "html", "head", "meta", "title", "style", "body", "h1",
				    "p", "ul", "li", "a", "img", "span" };
static const char *const attrs[] = { "lang", "charset", "http-equiv", "content", "name", "href",
				     "src", "alt", "loading", "class" };

static bool one_of(const char *s, size_t n, const char *const *list, size_t count)
{
	for (size_t i = 0; i < count; i++)
		if (strlen(list[i]) == n && strncmp(s, list[i], n) == 0)
			return true;
	return false;
}

/* Text or an attribute's value: no markup, every '&' one of the five entities. Copies the
 * unescaped text to out (size bytes) when given. false: not so. */
static bool text_ok(const char *s, size_t n, char *out, size_t size)
{
	static const char *const ent[] = { "&amp;", "&lt;", "&gt;", "&quot;", "&#39;" };
	static const char plain[] = "&<>\"'";
	size_t o = 0;

	for (size_t i = 0; i < n; i++) {
		char c = s[i];

		if (c == '<' || c == '>' || c == '"')
			return false;
		if (c == '&') {
			size_t k = 0;

			while (k < 5 && strncmp(s + i, ent[k], strlen(ent[k])) != 0)
				k++;
			if (k == 5)
				return false;
			i += strlen(ent[k]) - 1;
			c = plain[k];
		}
		if (out && o + 1 < size)
			out[o++] = c;
	}
	if (out)
		out[o] = '\0';
	return true;
}

/* As much of v as fits in dst (a longer value then differs from any expected). */
static void keep(char *dst, size_t size, const char *v)
{
	size_t n = strnlen(v, size - 1);

	memcpy(dst, v, n);
	dst[n] = '\0';
}

/* Parses html strictly: the doctype, then only the tags and attributes above, every
 * attribute quoted, elements nested and closed, no markup in text, <style> holding no
 * '<'. Fills p. false (and why on stderr) when it is not so. */
static bool parse(const char *html, struct page *p)
{
	static const char doctype[] = "<!DOCTYPE html>\n";
	char stack[32][16], cls[32] = "";
	int depth = 0;
	const char *s = html + sizeof(doctype) - 1;

	memset(p, 0, sizeof(*p));
	if (strncmp(html, doctype, sizeof(doctype) - 1) != 0)
		return fprintf(stderr, "no doctype\n"), false;
	while (*s) {
		const char *lt = strchr(s, '<');
		size_t tn;
		bool closing;
		char tag[16];

		if (!lt)
			lt = s + strlen(s);
		if (!text_ok(s, (size_t)(lt - s), NULL, 0))
			return fprintf(stderr, "markup in text: %.40s\n", s), false;
		if (depth && !strcmp(stack[depth - 1], "span") && lt > s && p->n > 0) {
			char *dst = !strcmp(cls, "number") ? p->number[p->n - 1]
				    : !strcmp(cls, "date") ? p->date[p->n - 1] : NULL;

			if (dst)
				text_ok(s, (size_t)(lt - s), dst, 64);
		}
		if (depth && !strcmp(stack[depth - 1], "title"))
			text_ok(s, (size_t)(lt - s), p->title, sizeof(p->title));
		if (!*lt)
			break;
		s = lt + 1;
		closing = *s == '/';
		s += closing;
		tn = strspn(s, "abcdefghijklmnopqrstuvwxyz0123456789");
		if (!one_of(s, tn, tags, sizeof(tags) / sizeof(tags[0])))
			return fprintf(stderr, "tag not ours: %.40s\n", s - 1), false;
		snprintf(tag, sizeof(tag), "%.*s", (int)tn, s);
		s += tn;
		if (closing) {
			if (*s != '>' || depth == 0 || strcmp(stack[depth - 1], tag) != 0)
				return fprintf(stderr, "</%s> closes nothing open\n", tag), false;
			depth--;
			s++;
			continue;
		}
		cls[0] = '\0';
		if ((!strcmp(tag, "a") || !strcmp(tag, "img")) && p->n == 0)
			return fprintf(stderr, "<%s> outside an entry\n", tag), false;
		if (!strcmp(tag, "li")) {
			if (p->n == MAX_ITEMS)
				return fprintf(stderr, "too many entries\n"), false;
			p->n++;
		}
		while (*s == ' ') {
			size_t an = strspn(++s, "abcdefghijklmnopqrstuvwxyz-");
			const char *q;
			char value[512], name[16];

			if (!one_of(s, an, attrs, sizeof(attrs) / sizeof(attrs[0])))
				return fprintf(stderr, "attribute not ours: %.40s\n", s), false;
			snprintf(name, sizeof(name), "%.*s", (int)an, s);
			s += an;
			if (s[0] != '=' || s[1] != '"' || !(q = strchr(s + 2, '"')))
				return fprintf(stderr, "attribute %s not quoted\n", name), false;
			if (!text_ok(s + 2, (size_t)(q - s - 2), value, sizeof(value)))
				return fprintf(stderr, "markup in attribute %s\n", name), false;
			if (!strcmp(tag, "a") && !strcmp(name, "href"))
				keep(p->href[p->n - 1], sizeof(p->href[0]), value);
			if (!strcmp(tag, "img") && !strcmp(name, "src"))
				keep(p->src[p->n - 1], sizeof(p->src[0]), value);
			if (!strcmp(tag, "html") && !strcmp(name, "lang"))
				keep(p->lang, sizeof(p->lang), value);
			if (!strcmp(name, "class"))
				keep(cls, sizeof(cls), value);
			s = q + 1;
		}
		if (*s != '>')
			return fprintf(stderr, "<%s> not closed\n", tag), false;
		s++;
		if (!strcmp(tag, "style")) {
			const char *end = strstr(s, "</style>");

			if (!end || memchr(s, '<', (size_t)(end - s)))
				return fprintf(stderr, "markup in <style>\n"), false;
			s = end;
			depth++; /* closed by the </style> next */
			snprintf(stack[depth - 1], sizeof(stack[0]), "style");
			continue;
		}
		if (!strcmp(tag, "meta") || !strcmp(tag, "img"))
			continue; /* void elements */
		if (depth == 32)
			return fprintf(stderr, "too deep\n"), false;
		snprintf(stack[depth++], sizeof(stack[0]), "%s", tag);
	}
	if (depth != 0)
		return fprintf(stderr, "<%s> left open\n", stack[depth - 1]), false;
	return true;
}

/* ---- files ----------------------------------------------------------------------- */

static int fresh_dir(const char *name)
{
	char path[600];
	int fd;

	snprintf(path, sizeof(path), "%s/%s", root, name);
	CHECK_INT(mkdir(path, 0755), 0);
	fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	CHECK(fd >= 0);
	return fd;
}

static void put(int dirfd, const char *name, const char *text)
{
	int fd = openat(dirfd, name, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);

	if (fd < 0)
		fprintf(stderr, "%s: %s\n", name, strerror(errno));
	CHECK(fd >= 0);
	CHECK_INT(write(fd, text, strlen(text)), (long long)strlen(text));
	CHECK_INT(close(fd), 0);
}

static void set_mtime(int dirfd, const char *name, int64_t t)
{
	struct timespec ts[2] = { { (time_t)t, 0 }, { (time_t)t, 0 } };

	CHECK_INT(utimensat(dirfd, name, ts, AT_SYMLINK_NOFOLLOW), 0);
}

/* A file's bytes (not through a symlink), NUL-terminated; NULL when it cannot be read. */
static char *slurp(int dirfd, const char *name)
{
	int fd = openat(dirfd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
	size_t len = 0, cap = 1 << 16;
	char *s;
	ssize_t n;

	if (fd < 0)
		return NULL;
	s = malloc(cap);
	CHECK(s);
	while ((n = read(fd, s + len, cap - 1 - len)) > 0) {
		len += (size_t)n;
		if (len + 1 == cap) {
			cap *= 2;
			s = realloc(s, cap);
			CHECK(s);
		}
	}
	CHECK(n == 0);
	close(fd);
	s[len] = '\0';
	return s;
}

static bool is_regular(int dirfd, const char *name)
{
	struct stat st;

	return fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode);
}

/* Parses a gallery: every link and picture a regular file in dirfd. */
static void check_page(int dirfd, const char *html, size_t count, struct page *p)
{
	if (!parse(html, p)) {
		fputs(html, stderr);
		CHECK(!"index.html parses");
	}
	CHECK(!strstr(html, "<script") && !strstr(html, "<SCRIPT"));
	CHECK_INT(p->n, (long long)count);
	for (int i = 0; i < p->n; i++) {
		CHECK(is_regular(dirfd, p->href[i]));
		CHECK(!p->src[i][0] || is_regular(dirfd, p->src[i]));
	}
}

/* Writes the gallery, reads it back and checks it; no temporary left. */
static void write_and_read(int dirfd, enum config_language lang, struct page *p)
{
	struct error err = { { 0 } };
	size_t count = 0;
	char *html;

	CHECK_INT(gallery_write(dirfd, lang, &count, &err), 0);
	CHECK(is_regular(dirfd, "index.html"));
	CHECK(faccessat(dirfd, ".index.html.tmp", F_OK, AT_SYMLINK_NOFOLLOW) < 0);
	html = slurp(dirfd, "index.html");
	CHECK(html);
	check_page(dirfd, html, count, p);
	free(html);
}

/* The same in memory, without the write's fsyncs (each a few ms on a busy disk). */
static void list_and_read(int dirfd, struct page *p)
{
	struct error err = { { 0 } };
	struct gallery g;
	struct buf html;

	gallery_init(&g);
	buf_init(&html);
	CHECK_INT(gallery_list(dirfd, &g, &err), 0);
	CHECK_INT(gallery_html(&g, CONFIG_LANG_EN, &html), 0);
	CHECK_INT(buf_append(&html, "", 1), 0);
	check_page(dirfd, (const char *)html.data, g.count, p);
	buf_finish(&html);
	gallery_finish(&g);
}

/* ---- the cases ------------------------------------------------------------------- */

static void test_three_saves(struct app *app)
{
	static uint8_t rgba[64 * 64 * 4];
	struct error err = { { 0 } };
	struct export_set s;
	struct page p;
	char base[32], name[48];
	int dirfd = fresh_dir("three");

	export_set_init(&s);
	CHECK_INT(export_set_build(&s, app, rgba, &err), 0);
	for (int i = 1; i <= 3; i++) {
		/* as usb_export.c does: the set, then the gallery */
		CHECK_INT(export_set_save(dirfd, &s, base, sizeof(base), &err), 0);
		write_and_read(dirfd, CONFIG_LANG_EN, &p);
		CHECK_INT(p.n, i);
	}
	for (int i = 0; i < 3; i++) {
		unsigned number = (unsigned)(3 - i);
		char page[48];

		/* newest first; the set's page when it has one, else its model */
		snprintf(page, sizeof(page), "tree-%04u.html", number);
		snprintf(name, sizeof(name), "tree-%04u.%s", number,
			 is_regular(dirfd, page) ? "html" : "glb");
		CHECK(!strcmp(p.href[i], name));
		snprintf(name, sizeof(name), "tree-%04u.png", number);
		CHECK(!strcmp(p.src[i], name));
		snprintf(name, sizeof(name), "No. %u", number);
		CHECK(!strcmp(p.number[i], name));
		CHECK(p.date[i][0]); /* today */
	}
	export_set_finish(&s);
	close(dirfd);
}

/* Another kiosk's index.html, and one of an older edaha: replaced by ours. */
static void test_foreign(void)
{
	int dirfd = fresh_dir("foreign");
	struct page p;
	char *html;

	put(dirfd, "index.html", "<html><body>another kiosk<script>alert(1)</script></body></html>");
	put(dirfd, "tree-0007.html", "a page");
	put(dirfd, "tree-0007.png", "a picture");
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	html = slurp(dirfd, "index.html");
	CHECK(html && !strstr(html, "another kiosk"));
	free(html);
	CHECK_INT(p.n, 1);
	CHECK(!strcmp(p.href[0], "tree-0007.html") && !strcmp(p.src[0], "tree-0007.png"));
	close(dirfd);
}

/* A symlink named index.html (a hostile ext4 stick) is replaced as a link, its target
 * untouched; one at our temporary is removed unfollowed; a directory named index.html
 * makes the write fail, leaving it and no temporary. */
static void test_symlink(void)
{
	int dirfd = fresh_dir("symlink");
	char victim[600], *text;
	struct error err = { { 0 } };
	struct stat st;
	struct page p;
	int rootfd = open(root, O_RDONLY | O_DIRECTORY | O_CLOEXEC);

	CHECK(rootfd >= 0);
	put(rootfd, "victim", "the target's own bytes");
	snprintf(victim, sizeof(victim), "%s/victim", root);
	CHECK_INT(symlinkat(victim, dirfd, "index.html"), 0);
	CHECK_INT(symlinkat("../victim2", dirfd, ".index.html.tmp"), 0);
	put(dirfd, "tree-0001.glb", "a model");
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	CHECK_INT(fstatat(dirfd, "index.html", &st, AT_SYMLINK_NOFOLLOW), 0);
	CHECK(S_ISREG(st.st_mode));
	text = slurp(rootfd, "victim");
	CHECK(text && !strcmp(text, "the target's own bytes"));
	free(text);
	CHECK(faccessat(rootfd, "victim2", F_OK, AT_SYMLINK_NOFOLLOW) < 0 && errno == ENOENT);
	/* before pages: the model is the link */
	CHECK_INT(p.n, 1);
	CHECK(!strcmp(p.href[0], "tree-0001.glb") && !p.src[0][0]);
	close(dirfd);

	dirfd = fresh_dir("isdir");
	CHECK_INT(mkdirat(dirfd, "index.html", 0755), 0);
	CHECK(gallery_write(dirfd, CONFIG_LANG_EN, NULL, &err) < 0);
	CHECK(strstr(err.msg, "index.html"));
	CHECK_INT(fstatat(dirfd, "index.html", &st, AT_SYMLINK_NOFOLLOW), 0);
	CHECK(S_ISDIR(st.st_mode));
	CHECK_INT(dir_count(dirfd, ".", "."), 2); /* . and .., no temporary */
	close(dirfd);
	close(rootfd);
}

/* Names a hostile stick may hold: never listed, never printed. */
static const char *const hostile[] = {
	"<script>x.glb",
	"<script>alert(1)<script>.html", /* no '/' in a name */
	"tree-0001.html\"><script>alert(1)",
	"tree-0001.html'onerror='alert(1)",
	"tree-0002.png\" onerror=\"alert(1)",
	"tree-0002.html&amp;",
	"tree-0003.glb&<>\"'",
	"a&b.png",
	"\"quoted\".html",
	"it's.png",
	"tree-0004.html\n",
	"tree-0004.html ",
	"TREE-0005.HTML",
	"Tree-0005.Png",
	"tree-5.html",
	"tree-00005.html",
	"tree-0005.htm",
	"tree-0005.html.txt",
	"tree-100000.html",
	"tree-0000.html",
	"木-0006.html",
	".tree-0006.html.tmp",
	"index.htm",
};

static void test_hostile(void)
{
	int dirfd = fresh_dir("hostile");
	struct page p;
	char *html;

	for (size_t i = 0; i < sizeof(hostile) / sizeof(hostile[0]); i++)
		put(dirfd, hostile[i], "x");
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	CHECK_INT(p.n, 0);
	/* with trees of those numbers there: those listed, nothing else */
	put(dirfd, "tree-0001.html", "a page");
	put(dirfd, "tree-0002.png", "a picture");
	put(dirfd, "tree-0002.glb", "a model");
	put(dirfd, "tree-0005.png", "a picture alone: no tree");
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	CHECK_INT(p.n, 2);
	CHECK(!strcmp(p.href[0], "tree-0002.glb") && !strcmp(p.src[0], "tree-0002.png"));
	CHECK(!strcmp(p.href[1], "tree-0001.html") && !p.src[1][0]);
	html = slurp(dirfd, "index.html");
	CHECK(html);
	CHECK(!strstr(html, "alert") && !strstr(html, "onerror") && !strstr(html, "quoted"));
	free(html);
	close(dirfd);
}

/* A full disk, as a file size limit: the old index whole, no temporary. */
static void test_full(void)
{
	int dirfd = fresh_dir("full");
	struct error err = { { 0 } };
	struct rlimit old, lim;
	struct page p;
	char *before, *after;

	put(dirfd, "tree-0001.html", "a page");
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	before = slurp(dirfd, "index.html");
	CHECK(before);
	put(dirfd, "tree-0002.html", "a page");
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = 1000; /* less than the head alone */
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	CHECK_INT(gallery_write(dirfd, CONFIG_LANG_EN, NULL, &err), -EFBIG);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK(strstr(err.msg, "index.html") && strstr(err.msg, strerror(EFBIG)));
	after = slurp(dirfd, "index.html");
	CHECK(after && !strcmp(before, after));
	CHECK_INT(dir_count(dirfd, ".", ".index"), 0);
	/* with room again: both */
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	CHECK_INT(p.n, 2);
	free(before);
	free(after);
	close(dirfd);
}

/* Words and dates in each language, in local time; no date from a board without a clock. */
static void test_words(void)
{
	int dirfd = fresh_dir("words");
	struct page p;

	put(dirfd, "tree-0012.html", "a page");
	set_mtime(dirfd, "tree-0012.html", 1777777777); /* 2026-05-03 03:09:37 UTC */
	put(dirfd, "tree-0013.glb", "a model");
	set_mtime(dirfd, "tree-0013.glb", 315532800); /* 1980-01-01: FAT's first day */
	setenv("TZ", "JST-9", 1);
	tzset();
	write_and_read(dirfd, CONFIG_LANG_JA, &p);
	CHECK(!strcmp(p.lang, "ja") && !strcmp(p.title, "きみの 木"));
	CHECK_INT(p.n, 2);
	CHECK(!strcmp(p.number[0], "13ばん") && !p.date[0][0]);
	CHECK(!strcmp(p.number[1], "12ばん"));
	CHECK(!strcmp(p.date[1], "2026年5月3日 12:09"));
	setenv("TZ", "UTC0", 1);
	tzset();
	write_and_read(dirfd, CONFIG_LANG_EN, &p);
	CHECK(!strcmp(p.lang, "en") && !strcmp(p.title, "Your trees"));
	CHECK(!strcmp(p.number[1], "No. 12") && !strcmp(p.date[1], "3 May 2026, 03:09"));
	close(dirfd);
}

/* The gallery's background is the kiosk's paper. */
static void test_paper(void)
{
	char hex[8];

	snprintf(hex, sizeof(hex), "#%02x%02x%02x", (unsigned)(render_paper[0] * 255.0f + 0.5f),
		 (unsigned)(render_paper[1] * 255.0f + 0.5f),
		 (unsigned)(render_paper[2] * 255.0f + 0.5f));
	CHECK(!strcmp(hex, GALLERY_PAPER));
}

/* Each allocation of listing and page failed in turn (not under the sanitizers, which
 * bring their own malloc): -ENOMEM, or a whole page when the failure was not needed. */
static void test_oom(void)
{
#if FAIL_ALLOC_HOOK
	int dirfd = fresh_dir("oom");
	long n;
	char name[48];

	for (unsigned v = 1; v <= 300; v++) {
		snprintf(name, sizeof(name), "tree-%04u.html", v);
		put(dirfd, name, "a page");
		snprintf(name, sizeof(name), "tree-%04u.png", v);
		put(dirfd, name, "a picture");
	}
	if (!fail_alloc_hooked()) {
		close(dirfd);
		return;
	}
	for (n = 0;; n++) {
		struct error err = { { 0 } };
		long live = fail_alloc_live(), calls;
		struct gallery g;
		struct buf html;
		int r;

		gallery_init(&g);
		buf_init(&html);
		fail_alloc_at(n);
		r = gallery_list(dirfd, &g, &err);
		if (r == 0)
			r = gallery_html(&g, CONFIG_LANG_EN, &html);
		calls = fail_alloc_calls();
		fail_alloc_off();
		if (r == 0) {
			CHECK_INT(g.count, 300);
			CHECK(html.len > 40 && !strncmp((const char *)html.data, "<!DOCTYPE html>", 15));
			CHECK(!memcmp(html.data + html.len - 8, "</html>\n", 8));
		} else {
			CHECK_INT(r, -ENOMEM);
		}
		buf_finish(&html);
		gallery_finish(&g);
		CHECK_INT(fail_alloc_live(), live);
		if (r == 0 && calls <= n)
			break; /* the nth allocation was never made: every one has failed once */
	}
	printf("gallery: each of %ld allocations failed in turn, -ENOMEM or a whole page\n", n);
	close(dirfd);
#endif
}

/* ---- seeded random directories --------------------------------------------------- */

static const char *const months[] = { "Jan", "Feb", "Mar", "Apr", "May", "Jun",
				      "Jul", "Aug", "Sep", "Oct", "Nov", "Dec" };

/* A tree's names, in the order of its slots below. */
static const char *const kinds[3] = { "html", "glb", "png" };

/* What the test put at a tree's names, and so expects. */
enum slot { NONE, REGULAR, SYMLINK, DIRECTORY };

static enum slot random_slot(struct rng *r)
{
	uint64_t x = rng_next(r) % 10;

	return x < 4 ? NONE : x < 8 ? REGULAR : x < 9 ? SYMLINK : DIRECTORY;
}

/* Whether name is one a tree's files take: tree-NNNN.html, .glb or .png, NNNN as
 * export_names_format writes it. */
static bool canonical(const char *name)
{
	char want[64];
	unsigned v;

	if (sscanf(name, "tree-%5u.", &v) != 1 || v == 0)
		return false;
	for (int k = 0; k < 3; k++) {
		snprintf(want, sizeof(want), "tree-%04u.%s", v, kinds[k]);
		if (!strcmp(name, want))
			return true;
	}
	return false;
}

static void make(int dirfd, const char *name, enum slot s)
{
	if (s == REGULAR)
		put(dirfd, name, "bytes");
	else if (s == SYMLINK)
		CHECK_INT(symlinkat("/etc/passwd", dirfd, name), 0);
	else if (s == DIRECTORY)
		CHECK_INT(mkdirat(dirfd, name, 0755), 0);
}

static void test_random(void)
{
	const int cases = test_cases(300);
	long long names = 0, hostiles = 0, entries = 0, most = 0, undated = 0;

	setenv("TZ", "UTC0", 1);
	tzset();
	for (int c = 0; c < cases; c++) {
		struct rng r;
		unsigned numbers[40];
		enum slot page[40], model[40], picture[40];
		int64_t mtime[40];
		int n, expect = 0, dirfd;
		char dir[32], name[64];
		struct page p;

		rng_seed(&r, 0x6a11e7u + (uint64_t)c);
		snprintf(dir, sizeof(dir), "random-%d", c);
		dirfd = fresh_dir(dir);
		/* distinct numbers, mostly small, now and then five digits */
		n = (int)(rng_next(&r) % 25);
		for (int i = 0; i < n; i++) {
			bool again;

			do {
				numbers[i] = rng_next(&r) % 8 == 0
						     ? 10000 + (unsigned)(rng_next(&r) % 90000)
						     : 1 + (unsigned)(rng_next(&r) % 60);
				again = false;
				for (int j = 0; j < i; j++)
					again |= numbers[j] == numbers[i];
			} while (again);
			page[i] = random_slot(&r);
			model[i] = random_slot(&r);
			picture[i] = random_slot(&r);
			/* from before any clock to 2100; now and then no clock at all */
			mtime[i] = rng_next(&r) % 6 == 0 ? (int64_t)(rng_next(&r) % GALLERY_DATE_MIN)
							 : GALLERY_DATE_MIN +
								   (int64_t)(rng_next(&r) % 3155760000u);
			for (int k = 0; k < 3; k++) {
				snprintf(name, sizeof(name), "tree-%04u.%s", numbers[i], kinds[k]);
				make(dirfd, name, k == 0 ? page[i] : k == 1 ? model[i] : picture[i]);
				names += (k == 0 ? page[i] : k == 1 ? model[i] : picture[i]) != NONE;
			}
			if (page[i] == REGULAR || model[i] == REGULAR) {
				snprintf(name, sizeof(name), "tree-%04u.%s", numbers[i],
					 page[i] == REGULAR ? "html" : "glb");
				set_mtime(dirfd, name, mtime[i]);
			}
		}
		/* the rest of a set, misspellings and hostile names, of these numbers and others */
		for (int k = (int)(rng_next(&r) % 30); k > 0; k--) {
			unsigned v = n && rng_next(&r) % 2 ? numbers[rng_next(&r) % (uint64_t)n]
							 : 1 + (unsigned)(rng_next(&r) % 99);
			static const char *const forms[] = {
				"tree-%04u.obj", "tree-%04u.mtl", "tree-%04u.edaha", "TREE-%04u.HTML",
				"Tree-%04u.glb", "TREE-%04u.png", "tree-%04u.PNG", "tree-%u.html",
				"tree-0%04u.png", "tree-%04u.html.bak",
				".tree-%04u.html.tmp", "tree-%04u.html\"><img src=x onerror=alert(%u)>",
				"<script>%u.glb", "tree-%04u.png&amp;%u", "tree-%04u.glb'%u",
				"tree-%04u", "forest-2026-01-%02u.glb",
			};
			const char *form = forms[rng_next(&r) % (sizeof(forms) / sizeof(forms[0]))];

			snprintf(name, sizeof(name), form, v, v);
			/* taken, or a tree's own name after all ("tree-%u.html" of 12345) */
			if (faccessat(dirfd, name, F_OK, AT_SYMLINK_NOFOLLOW) == 0 || canonical(name))
				continue;
			make(dirfd, name, rng_next(&r) % 4 ? REGULAR : SYMLINK);
			names++;
			hostiles++;
		}
		if (rng_next(&r) % 3 == 0) /* another kiosk's, or an older one's */
			put(dirfd, "index.html", "<p>another kiosk's index</p>");
		if (rng_next(&r) % 5 == 0) /* a stick pulled while we wrote ours */
			put(dirfd, ".index.html.tmp", "<p>half");
		/* one in ten written as a Save writes it, over those */
		if (c % 10 == 0)
			write_and_read(dirfd, CONFIG_LANG_EN, &p);
		else
			list_and_read(dirfd, &p);

		/* what the test put there: highest number first, the page's link else the model's */
		for (unsigned v = 99999; v >= 1 && expect <= p.n; v--) {
			int i = 0;
			char want[96];

			while (i < n && numbers[i] != v)
				i++;
			if (i == n || (page[i] != REGULAR && model[i] != REGULAR))
				continue;
			CHECK(expect < p.n);
			snprintf(want, sizeof(want), "tree-%04u.%s", v,
				 page[i] == REGULAR ? "html" : "glb");
			CHECK(!strcmp(p.href[expect], want));
			if (picture[i] == REGULAR)
				snprintf(want, sizeof(want), "tree-%04u.png", v);
			else
				want[0] = '\0';
			CHECK(!strcmp(p.src[expect], want));
			snprintf(want, sizeof(want), "No. %u", v);
			CHECK(!strcmp(p.number[expect], want));
			if (mtime[i] < GALLERY_DATE_MIN) {
				want[0] = '\0';
				undated++;
			} else {
				time_t t = (time_t)mtime[i];
				struct tm tm;

				CHECK(gmtime_r(&t, &tm));
				snprintf(want, sizeof(want), "%d %s %d, %02d:%02d", tm.tm_mday,
					 months[tm.tm_mon], tm.tm_year + 1900, tm.tm_hour, tm.tm_min);
			}
			CHECK(!strcmp(p.date[expect], want));
			expect++;
		}
		CHECK_INT(p.n, expect);
		entries += expect;
		most = expect > most ? expect : most;
		close(dirfd);
	}
	printf("gallery: %d random directories, %lld names of trees and %lld others "
	       "(misspelt, hostile, symlinks): %lld entries checked (at most %lld in one, %lld "
	       "undated), every page parsed strictly, every link and picture a regular file, "
	       "the order and dates exact\n",
	       cases, names, hostiles, entries, most, undated);
}

int main(void)
{
	char cmd[128];
	struct app *app = app_create(64, 64, 1);

	CHECK(app);
	CHECK(mkdtemp(root));
	setenv("TZ", "UTC0", 1);
	tzset();
	test_paper();
	test_three_saves(app);
	test_foreign();
	test_symlink();
	test_hostile();
	test_full();
	test_words();
	test_oom();
	test_random();
	app_destroy(app);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	CHECK_INT(system(cmd), 0);
	return 0;
}
