/* SPDX-License-Identifier: MIT */
/*
 * The take-home page (export.h, docs/page.md): the HTML around the model and the scripts.
 * The markup is fixed; all that varies is in the JSON blob (escaped so it holds no <, >
 * or &) and the model's base64 (an alphabet without them), so nothing a visitor or a stick
 * brings can become markup.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "camera.h"
#include "export.h"
#include "export_page_parts.h"
#include "numfmt.h"

/*
 * No request may leave the page: nothing from anywhere but its own inline scripts and
 * style. No data: or blob: either, as nothing needs them (the model is read with atob,
 * the GLB holds no images).
 */
#define PAGE_CSP "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; " \
		 "base-uri 'none'; form-action 'none'"

/*
 * English as the kiosk's labels say things (ui/labels.c); Japanese in hiragana, as the
 * kiosk's, 木 being the one kanji a child there reads (the screen's "きみの 木は").
 */
static const struct export_page_words page_words[EXPORT_PAGE_NLANGS] = {
	[EXPORT_PAGE_EN] = {
		.lang = "en",
		.number = "Tree No. #",
		.title = "My tree, No. #",
		.untitled = "My tree",
		.hint = "Drag to turn the tree. Scroll or pinch to come closer.",
		.nogl = "This browser cannot show the tree in 3D. Try another one.",
		.failed = "The tree could not be opened.",
	},
	[EXPORT_PAGE_JA] = {
		.lang = "ja",
		.number = "#ばんの 木",
		.title = "#ばんの 木",
		.untitled = "わたしの 木",
		.hint = "ゆびや マウスで うごかすと 木が まわるよ",
		.nogl = "この ブラウザでは 木が みられないよ。ほかの ブラウザで ひらいてね",
		.failed = "木が ひらけなかったよ",
	},
};

static const char *const months_en[12] = {
	"January", "February", "March", "April", "May", "June", "July", "August", "September",
	"October", "November", "December",
};

const struct export_page_words *export_page_words(enum export_page_lang lang)
{
	return (int)lang >= 0 && lang < EXPORT_PAGE_NLANGS ? &page_words[lang] : NULL;
}

static bool leap(int y)
{
	return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

int export_page_date(enum export_page_lang lang, int year, int month, int day, char *out,
		     size_t size)
{
	static const int mdays[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
	int n;

	if (size)
		out[0] = '\0';
	if (year < 1 || year > 9999 || month < 1 || month > 12 || day < 1 ||
	    day > mdays[month - 1] + (month == 2 && leap(year)))
		return -EINVAL;
	if (lang == EXPORT_PAGE_EN)
		n = snprintf(out, size, "%d %s %d", day, months_en[month - 1], year);
	else if (lang == EXPORT_PAGE_JA)
		n = snprintf(out, size, "%dねん %dがつ %dにち", year, month, day);
	else
		return -EINVAL;
	if (n < 0 || (size_t)n >= size) {
		if (size)
			out[0] = '\0';
		return -ENOSPC;
	}
	return 0;
}

static const struct export_page_part_text *part(const char *name)
{
	for (size_t i = 0; i < export_page_part_ntexts; i++)
		if (strcmp(export_page_part_texts[i].name, name) == 0)
			return &export_page_part_texts[i];
	return NULL;
}

static int put(struct buf *b, const char *s)
{
	return buf_append(b, s, strlen(s));
}

/* The length of the UTF-8 sequence at s (n bytes left), 0 when it is not one: overlong
 * forms, surrogates and code points past U+10FFFF are not. *cp is its code point. */
static size_t utf8_at(const unsigned char *s, size_t n, unsigned *cp)
{
	unsigned c = s[0], len, min;

	if (c < 0x80) {
		*cp = c;
		return 1;
	}
	if (c >= 0xc2 && c <= 0xdf)
		len = 2, min = 0x80, c &= 0x1f;
	else if (c >= 0xe0 && c <= 0xef)
		len = 3, min = 0x800, c &= 0x0f;
	else if (c >= 0xf0 && c <= 0xf4)
		len = 4, min = 0x10000, c &= 0x07;
	else
		return 0;
	if (n < len)
		return 0;
	for (unsigned i = 1; i < len; i++) {
		if ((s[i] & 0xc0) != 0x80)
			return 0;
		c = c << 6 | (s[i] & 0x3f);
	}
	if (c < min || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
		return 0;
	*cp = c;
	return len;
}

/*
 * A JSON string that is safe anywhere in HTML: <, >, & and the quotes as \u escapes (no
 * tag, comment or entity can start in it), control characters and U+2028/2029 escaped,
 * bytes that are not UTF-8 as U+FFFD. NULL is "".
 */
static int json_string(struct buf *b, const char *text)
{
	const unsigned char *s = (const unsigned char *)(text ? text : "");
	size_t n = strlen((const char *)s);
	int r = buf_append(b, "\"", 1);

	while (r == 0 && n > 0) {
		unsigned cp = 0;
		size_t len = utf8_at(s, n, &cp);

		if (len == 0)
			r = put(b, "\\ufffd");
		else if (cp == '"')
			r = put(b, "\\\"");
		else if (cp == '\\')
			r = put(b, "\\\\");
		else if (cp < 0x20 || cp == '<' || cp == '>' || cp == '&' || cp == '\'' ||
			 cp == 0x7f || cp == 0x2028 || cp == 0x2029)
			r = buf_printf(b, "\\u%04x", cp);
		else
			r = buf_append(b, s, len);
		s += len ? len : 1;
		n -= len ? len : 1;
	}
	return r ? r : buf_append(b, "\"", 1);
}

static int json_key(struct buf *b, const char *key, const char *value, bool last)
{
	int r = buf_printf(b, "\"%s\":", key);

	if (r == 0)
		r = json_string(b, value);
	return r ? r : put(b, last ? "" : ",");
}

/* 0..1 as the byte a framebuffer holds (GL rounds to nearest). */
static unsigned channel(float c)
{
	if (!(c > 0.0f))
		return 0;
	return c >= 1.0f ? 255u : (unsigned)lroundf(c * 255.0f);
}

/* k of c^k, taking the file's channel to the screen's; 1 where either is no colour. */
static double tint_power(double file, float screen)
{
	if (!(file > 0.0 && file < 1.0 && screen > 0.0f && screen < 1.0f))
		return 1.0;
	return log((double)screen) / log(file);
}

static int json_tint(struct buf *b, const char *name, const double file[3],
		     const float screen[3], bool last)
{
	char k[3][NUMFMT_MAX];

	for (int c = 0; c < 3; c++)
		numfmt_micro(k[c], tint_power(file[c], screen[c]), true);
	return buf_printf(b, "\"%s\":[%s,%s,%s]%s", name, k[0], k[1], k[2], last ? "}," : ",");
}

static int json_tints(struct buf *b, const struct export_page *p)
{
	static const double bark[3] = { MATERIAL_BARK_RGB }, leaves[3] = { MATERIAL_LEAVES_RGB },
			    vine[3] = { MATERIAL_VINE_RGB };
	int r = put(b, "\"tint\":{");

	if (r == 0)
		r = json_tint(b, "bark", bark, p->bark, false);
	if (r == 0)
		r = json_tint(b, "leaves", leaves, p->leaves, false);
	return r ? r : json_tint(b, "vine", vine, p->stem, true);
}

static int json_data(struct buf *b, const struct export_page *p)
{
	const struct export_page_words *w = p->words;
	char lo[NUMFMT_MAX], hi[NUMFMT_MAX];
	int r;

	numfmt_micro(lo, CAMERA_PITCH_MIN_DEG, true);
	numfmt_micro(hi, CAMERA_PITCH_MAX_DEG, true);
	r = put(b, "{");
	if (r == 0)
		r = json_key(b, "lang", w->lang, false);
	if (r == 0)
		r = buf_printf(b, "\"number\":%u,", p->number);
	if (r == 0)
		r = json_key(b, "date", p->date, false);
	if (r == 0)
		r = buf_printf(b, "\"paper\":[%u,%u,%u],\"pitch\":[%s,%s],",
			       channel(p->paper[0]), channel(p->paper[1]), channel(p->paper[2]), lo,
			       hi);
	if (r == 0)
		r = json_tints(b, p);
	if (r == 0)
		r = put(b, "\"words\":{");
	if (r == 0)
		r = json_key(b, "number", w->number, false);
	if (r == 0)
		r = json_key(b, "title", w->title, false);
	if (r == 0)
		r = json_key(b, "untitled", w->untitled, false);
	if (r == 0)
		r = json_key(b, "hint", w->hint, false);
	if (r == 0)
		r = json_key(b, "nogl", w->nogl, false);
	if (r == 0)
		r = json_key(b, "failed", w->failed, true);
	return r ? r : put(b, "}}");
}

static int base64(struct buf *b, const unsigned char *s, size_t n)
{
	static const char abc[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	size_t i = 0, len = (n + 2) / 3 * 4;
	char *o;
	int r = buf_reserve(b, len);

	if (r < 0)
		return r;
	o = (char *)b->data + b->len;
	for (; i + 3 <= n; i += 3) {
		unsigned v = (unsigned)s[i] << 16 | (unsigned)s[i + 1] << 8 | s[i + 2];

		*o++ = abc[v >> 18];
		*o++ = abc[v >> 12 & 63];
		*o++ = abc[v >> 6 & 63];
		*o++ = abc[v & 63];
	}
	if (i < n) {
		unsigned v = (unsigned)s[i] << 16 | (i + 1 < n ? (unsigned)s[i + 1] << 8 : 0);

		*o++ = abc[v >> 18];
		*o++ = abc[v >> 12 & 63];
		*o++ = i + 1 < n ? abc[v >> 6 & 63] : '=';
		*o++ = '=';
	}
	b->len += len;
	return 0;
}

static bool starts_nocase(const unsigned char *s, size_t n, const char *word)
{
	size_t k = strlen(word);

	if (n < k)
		return false;
	for (size_t i = 0; i < k; i++) {
		unsigned char c = s[i];

		if (c >= 'A' && c <= 'Z')
			c = (unsigned char)(c - 'A' + 'a');
		if (c != (unsigned char)word[i])
			return false;
	}
	return true;
}

/*
 * A script inline. Its text ends at the first "</script" whatever the case, and after a
 * "<!--" a "<script" would keep it from ending there at all; so each "</script" becomes
 * "<\/script" and each "<!--" "\x3C!--", the same text in a JavaScript string, template
 * or regular expression (where libraries have such things). three.js r111 has neither.
 */
static int script(struct buf *b, const void *data, size_t len)
{
	const unsigned char *s = data, *run = s;
	int r = put(b, "<script>\n");

	for (size_t i = 0; r == 0 && i < len; i++) {
		const char *with = NULL;
		size_t skip = 0;

		if (s[i] != '<')
			continue;
		if (starts_nocase(s + i, len - i, "</script"))
			with = "<\\/", skip = 2;
		else if (starts_nocase(s + i, len - i, "<!--"))
			with = "\\x3C", skip = 1;
		else
			continue;
		r = buf_append(b, run, (size_t)(s + i - run));
		if (r == 0)
			r = put(b, with);
		run = s + i + skip;
		i += skip - 1;
	}
	if (r == 0)
		r = buf_append(b, run, (size_t)(s + len - run));
	/* a script without its last newline still ends on a line of its own */
	if (r == 0 && (len == 0 || s[len - 1] != '\n'))
		r = put(b, "\n");
	return r ? r : put(b, "</script>\n");
}

static int page_write(struct buf *b, const struct export_page *p,
		      const struct export_page_part_text *style,
		      const struct export_page_part_text *viewer,
		      const struct export_page_part_text *notice)
{
	int r = put(b, "<!DOCTYPE html>\n<html>\n<head>\n<meta charset=\"utf-8\">\n"
		       "<meta http-equiv=\"Content-Security-Policy\" content=\"" PAGE_CSP "\">\n"
		       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
		       "<meta name=\"generator\" content=\"edaha\">\n"
		       "<title>edaha</title>\n<style>\n");

	if (r == 0)
		r = buf_append(b, style->text, style->len);
	if (r == 0)
		r = put(b, "</style>\n</head>\n<body>\n"
			   "<div id=\"label\"><div id=\"number\" hidden></div>"
			   "<div id=\"date\" hidden></div><div id=\"hint\" hidden></div></div>\n"
			   "<div id=\"note\" hidden></div>\n<!--\n");
	if (r == 0)
		r = buf_append(b, notice->text, notice->len);
	if (r == 0)
		r = put(b, "-->\n<script id=\"edaha-data\" type=\"application/json\">");
	if (r == 0)
		r = json_data(b, p);
	if (r == 0)
		r = put(b, "</script>\n<script id=\"edaha-model\" type=\"application/octet-stream\">");
	if (r == 0)
		r = base64(b, p->glb, p->glb_len);
	if (r == 0)
		r = put(b, "</script>\n");
	for (size_t i = 0; r == 0 && i < p->nscripts; i++)
		r = script(b, p->scripts[i].data, p->scripts[i].len);
	if (r == 0)
		r = script(b, viewer->text, viewer->len);
	return r ? r : put(b, "</body>\n</html>\n");
}

int export_page_html(const struct export_page *p, struct buf *out)
{
	const struct export_page_part_text *style = part("page-style"), *viewer = part("page-viewer"),
					   *notice = part("page-notice");
	size_t start = out->len;
	bool failed = out->failed;
	int r;

	if (!p || !p->glb || !p->glb_len || !p->words || (p->nscripts && !p->scripts))
		return -EINVAL;
	for (size_t i = 0; i < p->nscripts; i++)
		if (!p->scripts[i].data || !p->scripts[i].len)
			return -EINVAL;
	if (!style || !viewer || !notice)
		return -EINVAL;
	r = page_write(out, p, style, viewer, notice);
	if (r < 0) {
		out->len = start;
		out->failed = failed;
	}
	return r;
}
