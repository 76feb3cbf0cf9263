/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* DT_REG */
#include "gallery.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "export_names.h"
#include "fileio.h"

#define NAME_SIZE 48

/* What a number has, from the listing: the files that count, exactly named and regular. */
enum { HAS_PAGE = 1, HAS_MODEL = 2, HAS_PICTURE = 4 };

static const char *const kinds[] = { ".html", ".glb", ".png" };

struct words {
	const char *lang, *title, *hint, *none;
	const char *number; /* '#': the number */
	const char *model;  /* said of a tree from before pages: its link is the .glb */
	const char *months[12];
};

/* A child reads these: the kiosk's own way of speaking (ui/labels.c) */
static const struct words words[] = {
	[CONFIG_LANG_EN] = {
		.lang = "en",
		.title = "Your trees",
		.hint = "Click a tree to turn it and watch it sway.",
		.none = "No trees here yet.",
		.number = "No. #",
		.model = "3D file, for a 3D program",
		.months = { "Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct",
			    "Nov", "Dec" },
	},
	[CONFIG_LANG_JA] = {
		.lang = "ja",
		.title = "きみの 木",
		.hint = "木を クリックすると、 まわして みられるよ",
		.none = "まだ 木が ないよ",
		.number = "#ばん",
		.model = "3Dソフトで ひらく ファイル",
	},
};

/* No script, nothing from the network: the pictures beside it and its own style. Between
 * the parts: the language's code, its title, its title again. */
static const char *const head[] = {
	"<!DOCTYPE html>\n"
	"<html lang=\"",
	"\">\n"
	"<head>\n"
	"<meta charset=\"utf-8\">\n"
	"<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
	"img-src 'self' file:; style-src 'unsafe-inline'; base-uri 'none'; form-action 'none'\">\n"
	"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
	"<meta name=\"color-scheme\" content=\"light\">\n"
	"<meta name=\"generator\" content=\"edaha\">\n"
	"<title>",
	"</title>\n"
	"<style>\n"
	"body { margin: 0; padding: 24px 32px; background: " GALLERY_PAPER "; color: #3b2f24;\n"
	"  font-family: system-ui, sans-serif; }\n"
	"h1 { font-size: 2.4em; margin: 0 0 0.2em; }\n"
	"p { font-size: 1.3em; margin: 0 0 1.2em; }\n"
	"ul { list-style: none; margin: 0; padding: 0; display: grid; gap: 28px;\n"
	"  grid-template-columns: repeat(auto-fill, minmax(300px, 1fr)); }\n"
	"a { display: block; color: inherit; text-decoration: none; padding: 12px;\n"
	"  background: #fffdf8; border-radius: 14px; box-shadow: 0 2px 6px rgba(60, 40, 20, 0.18); }\n"
	"a:hover, a:focus { box-shadow: 0 3px 12px rgba(60, 40, 20, 0.4); }\n"
	"img, .blank { display: block; width: 100%; aspect-ratio: 4 / 3; object-fit: contain;\n"
	"  background: " GALLERY_PAPER "; border-radius: 8px; }\n"
	".number { display: block; font-size: 2.2em; font-weight: bold; margin-top: 8px; }\n"
	".date, .model { display: block; font-size: 1.1em; color: #6d5b48; }\n"
	"</style>\n"
	"</head>\n"
	"<body>\n"
	"<h1>",
	"</h1>\n",
};

/* s as HTML text or an attribute's value. An append that fails sets b->failed, which
 * gallery_html checks once at the end (buf.h). */
static void put_escaped(struct buf *b, const char *s)
{
	for (; *s; s++) {
		switch (*s) {
		case '&':
			buf_append(b, "&amp;", 5);
			break;
		case '<':
			buf_append(b, "&lt;", 4);
			break;
		case '>':
			buf_append(b, "&gt;", 4);
			break;
		case '"':
			buf_append(b, "&quot;", 6);
			break;
		case '\'':
			buf_append(b, "&#39;", 5);
			break;
		default:
			buf_append(b, s, 1);
		}
	}
}

/* The number in the language's words: "No. 12", "12ばん". */
static void put_number(struct buf *b, const struct words *w, unsigned number)
{
	char n[16], out[64];
	const char *hash = strchr(w->number, '#');

	snprintf(n, sizeof(n), "%u", number);
	snprintf(out, sizeof(out), "%.*s%s%s", (int)(hash - w->number), w->number, n, hash + 1);
	put_escaped(b, out);
}

/* The date and time in local time, as the language writes it; "" before
 * GALLERY_DATE_MIN (no clock) or when it cannot be had. */
static void format_date(char *out, size_t size, int64_t t, enum config_language lang)
{
	time_t tt = (time_t)t;
	struct tm tm;

	out[0] = '\0';
	if (t < GALLERY_DATE_MIN || !localtime_r(&tt, &tm))
		return;
	if (lang == CONFIG_LANG_JA)
		snprintf(out, size, "%d年%d月%d日 %02d:%02d", tm.tm_year + 1900, tm.tm_mon + 1,
			 tm.tm_mday, tm.tm_hour, tm.tm_min);
	else
		snprintf(out, size, "%d %s %d, %02d:%02d", tm.tm_mday,
			 words[CONFIG_LANG_EN].months[tm.tm_mon], tm.tm_year + 1900, tm.tm_hour,
			 tm.tm_min);
}

static void put_tree(struct buf *b, const struct gallery_tree *t, enum config_language lang)
{
	const struct words *w = &words[lang];
	char name[NAME_SIZE], date[96];

	buf_append(b, "<li><a href=\"", 13);
	/* the formats cannot fail: numbers are at most five digits */
	(void)export_names_format(name, sizeof(name), t->number, t->page ? ".html" : ".glb", false);
	put_escaped(b, name);
	buf_append(b, "\">", 2);
	if (t->picture) {
		(void)export_names_format(name, sizeof(name), t->number, ".png", false);
		buf_append(b, "<img src=\"", 10);
		put_escaped(b, name);
		buf_append(b, "\" alt=\"", 7);
		put_number(b, w, t->number);
		buf_append(b, "\" loading=\"lazy\">", 17);
	} else {
		buf_append(b, "<span class=\"blank\"></span>", 27);
	}
	buf_append(b, "<span class=\"number\">", 21);
	put_number(b, w, t->number);
	buf_append(b, "</span>", 7);
	format_date(date, sizeof(date), t->mtime, lang);
	if (date[0]) {
		buf_append(b, "<span class=\"date\">", 19);
		put_escaped(b, date);
		buf_append(b, "</span>", 7);
	}
	if (!t->page) {
		buf_append(b, "<span class=\"model\">", 20);
		put_escaped(b, w->model);
		buf_append(b, "</span>", 7);
	}
	buf_append(b, "</a></li>\n", 10);
}

int gallery_html(const struct gallery *g, enum config_language lang, struct buf *out)
{
	const struct words *w;

	lang = lang == CONFIG_LANG_JA ? CONFIG_LANG_JA : CONFIG_LANG_EN;
	w = &words[lang];
	for (size_t i = 0; i < sizeof(head) / sizeof(head[0]); i++) {
		buf_append(out, head[i], strlen(head[i]));
		if (i < 3)
			put_escaped(out, i == 0 ? w->lang : w->title);
	}
	buf_append(out, "<p>", 3);
	put_escaped(out, g->count ? w->hint : w->none);
	buf_append(out, "</p>\n<ul>\n", 10);
	for (size_t i = 0; i < g->count; i++)
		put_tree(out, &g->trees[i], lang);
	buf_append(out, "</ul>\n</body>\n</html>\n", 22);
	return out->failed ? -ENOMEM : 0;
}

void gallery_init(struct gallery *g)
{
	memset(g, 0, sizeof(*g));
}

void gallery_finish(struct gallery *g)
{
	free(g->trees);
	gallery_init(g);
}

/* Whether a listed name is a regular file: its d_type, or where the filesystem gives
 * none, an fstatat that does not follow a symlink. */
static bool regular(int dirfd, const struct dirent *d)
{
	struct stat st;

	if (d->d_type != DT_UNKNOWN)
		return d->d_type == DT_REG;
	return fstatat(dirfd, d->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode);
}

/* What one name adds to its number *v: the kind it is exactly named as, when regular;
 * 0 for any other name. */
static uint8_t kind_of(int dirfd, const struct dirent *d, unsigned *v)
{
	char name[NAME_SIZE];

	if (export_names_classify(d->d_name, v) != EXPORT_NAME_FINAL)
		return 0;
	for (size_t i = 0; i < sizeof(kinds) / sizeof(kinds[0]); i++)
		if (export_names_format(name, sizeof(name), *v, kinds[i], false) == 0 &&
		    strcmp(d->d_name, name) == 0)
			return regular(dirfd, d) ? (uint8_t)(1u << i) : 0;
	return 0;
}

static int add(struct gallery *g, const struct gallery_tree *t)
{
	if (g->count == g->cap) {
		size_t cap = g->cap ? 2 * g->cap : 64;
		struct gallery_tree *p = realloc(g->trees, cap * sizeof(*p));

		if (!p)
			return -ENOMEM;
		g->trees = p;
		g->cap = cap;
	}
	g->trees[g->count++] = *t;
	return 0;
}

/* The trees from what each number has, highest first, each dated by the file it links
 * to (gone since the listing, or no longer regular: the model then, else not listed). */
static int collect(int dirfd, const uint8_t *has, unsigned max, struct gallery *g)
{
	for (unsigned v = max; v >= 1; v--) {
		struct gallery_tree t = { .number = v, .picture = has[v] & HAS_PICTURE };
		char name[NAME_SIZE];
		struct stat st;
		bool found = false;

		for (int page = 1; page >= 0 && !found; page--) {
			if (!(has[v] & (page ? HAS_PAGE : HAS_MODEL)))
				continue;
			(void)export_names_format(name, sizeof(name), v, kinds[page ? 0 : 1], false);
			if (fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) == 0 &&
			    S_ISREG(st.st_mode)) {
				t.page = page;
				t.mtime = (int64_t)st.st_mtime;
				found = true;
			}
		}
		if (found && add(g, &t) < 0)
			return -ENOMEM;
	}
	return 0;
}

int gallery_list(int dirfd, struct gallery *g, struct error *err)
{
	uint8_t *has;
	unsigned max = 0;
	struct dirent *d;
	DIR *dir;
	int r;

	g->count = 0;
	r = fileio_opendir_at(dirfd, &dir, err);
	if (r < 0)
		return r;
	/* 100 KB, one byte a number: on the heap, as this runs on threads with small stacks */
	has = calloc(EXPORT_NAMES_MAX + 1, 1);
	if (!has) {
		closedir(dir);
		return error_set(err, -ENOMEM, "out of memory");
	}
	for (;;) {
		uint8_t k;
		unsigned v;

		errno = 0;
		d = readdir(dir);
		if (!d) {
			if (errno)
				r = error_set(err, -errno, "cannot list the directory: %s",
					      strerror(errno));
			break;
		}
		k = kind_of(dirfd, d, &v);
		if (k) {
			has[v] |= k;
			max = v > max ? v : max;
		}
	}
	closedir(dir);
	if (r == 0 && collect(dirfd, has, max, g) < 0)
		r = error_set(err, -ENOMEM, "out of memory");
	free(has);
	return r;
}

int gallery_write(int dirfd, enum config_language lang, size_t *count, struct error *err)
{
	struct gallery g;
	struct buf html;
	int r;

	gallery_init(&g);
	buf_init(&html);
	r = gallery_list(dirfd, &g, err);
	if (r == 0 && gallery_html(&g, lang, &html) < 0)
		r = error_set(err, -ENOMEM, "out of memory");
	/* its messages name the file */
	if (r == 0)
		r = fileio_write_atomic_at(dirfd, GALLERY_FILE, html.data, html.len, err);
	if (r == 0 && count)
		*count = g.count;
	buf_finish(&html);
	gallery_finish(&g);
	return r;
}
