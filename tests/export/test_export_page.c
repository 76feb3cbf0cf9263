/* SPDX-License-Identifier: MIT */
/*
 * The take-home page's generator (export_page_html, docs/page.md) on seeded random inputs:
 * random bytes as the model, random scripts (with "</script", "<!--" and the like put in),
 * random text as the date and every word (markup, quotes, control characters, U+2028,
 * kana, emoji, bytes that are not UTF-8), random numbers and paper. Each page:
 *  - has the template's structure: the doctype, the Content-Security-Policy in the head
 *    before any script, and exactly the scripts it should, each ending at its own
 *    </script> (no "</script" nor "<!--" inside any, whatever case);
 *  - carries the text in the JSON blob alone: no <, > or & in it, and read back with
 *    json-c it is the text given (bytes that are not UTF-8 as U+FFFD);
 *  - carries the model in base64 that decodes back to its bytes, and the scripts as
 *    given once their two escapes are undone;
 *  - is the same bytes outside the JSON and the model's base64 as a page of other text,
 *    another number and another model: no text can change the markup;
 *  - is the same bytes made twice.
 * Then fixed hostile text (a date of "</script><script>alert(1)</script>"), the words of
 * both languages, the dates, and what is refused (-EINVAL, out as it was).
 */
#include <errno.h>
#include <json-c/json.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "numfmt.h"
#include "rng.h"
#include "test.h"

#define CASES 400
#define MAX_SCRIPTS 4

static const char data_open[] = "<script id=\"edaha-data\" type=\"application/json\">";
static const char model_open[] =
	"</script>\n<script id=\"edaha-model\" type=\"application/octet-stream\">";

/* ---- random inputs ----------------------------------------------------------------- */

struct text {
	struct buf in;  /* what the generator is given (NUL-terminated) */
	struct buf out; /* what the JSON must read back as */
};

static void put_utf8(struct buf *b, unsigned cp)
{
	unsigned char s[4];
	size_t n;

	if (cp < 0x80) {
		s[0] = (unsigned char)cp;
		n = 1;
	} else if (cp < 0x800) {
		s[0] = (unsigned char)(0xc0 | cp >> 6);
		s[1] = (unsigned char)(0x80 | (cp & 0x3f));
		n = 2;
	} else if (cp < 0x10000) {
		s[0] = (unsigned char)(0xe0 | cp >> 12);
		s[1] = (unsigned char)(0x80 | (cp >> 6 & 0x3f));
		s[2] = (unsigned char)(0x80 | (cp & 0x3f));
		n = 3;
	} else {
		s[0] = (unsigned char)(0xf0 | cp >> 18);
		s[1] = (unsigned char)(0x80 | (cp >> 12 & 0x3f));
		s[2] = (unsigned char)(0x80 | (cp >> 6 & 0x3f));
		s[3] = (unsigned char)(0x80 | (cp & 0x3f));
		n = 4;
	}
	CHECK_INT(buf_append(b, s, n), 0);
}

static void both(struct text *t, const char *s)
{
	CHECK_INT(buf_append(&t->in, s, strlen(s)), 0);
	CHECK_INT(buf_append(&t->out, s, strlen(s)), 0);
}

/* Random text: pieces of markup, characters that need escaping, kana and emoji, and
 * sequences that are not UTF-8 (each of whose bytes reads back as U+FFFD; an 'x' after
 * each, so none joins what follows into a character). */
static void random_text(struct rng *r, struct text *t)
{
	static const char *const pieces[] = {
		"</script>", "</SCRIPT", "<script>alert(1)</script>", "<!--", "-->", "]]>",
		"<img src=x onerror=alert(1)>", "&amp;", "&lt;", "\"", "'", "\\", "/", "\\u003c",
		"<\\/script", "#", "{\"a\":1}", "</style>", "\xe3\x81\x82", "\xe6\x9c\xa8",
	};
	static const struct { const char *s; size_t n; } bad[] = {
		{ "\x80", 1 }, { "\xc0\x80", 2 }, { "\xed\xa0\x80", 3 }, { "\xf5\x80\x80\x80", 4 },
		{ "\xe3\x81", 2 }, { "\xff", 1 }, { "\xf4\x90\x80\x80", 4 }, { "\xe0\x80\xaf", 3 },
	};
	size_t n = rng_next(r) % 40;

	buf_reset(&t->in);
	buf_reset(&t->out);
	for (size_t i = 0; i < n; i++) {
		unsigned k = (unsigned)(rng_next(r) % 8), cp;

		if (k == 0) {
			both(t, pieces[rng_next(r) % (sizeof(pieces) / sizeof(*pieces))]);
			continue;
		}
		if (k == 1) {
			size_t j = rng_next(r) % (sizeof(bad) / sizeof(*bad));

			CHECK_INT(buf_append(&t->in, bad[j].s, bad[j].n), 0);
			for (size_t m = 0; m < bad[j].n; m++)
				put_utf8(&t->out, 0xfffd);
			both(t, "x");
			continue;
		}
		if (k == 2)
			cp = 1 + (unsigned)(rng_next(r) % 31); /* control characters */
		else if (k == 3)
			cp = (const unsigned[]){ 0x7f, 0x2028, 0x2029, 0xfeff, 0xfffd }[rng_next(r) % 5];
		else if (k == 4)
			cp = 0x3041 + (unsigned)(rng_next(r) % 0x5f); /* hiragana */
		else if (k == 5)
			cp = 0x1f300 + (unsigned)(rng_next(r) % 0x300); /* emoji */
		else
			cp = 0x20 + (unsigned)(rng_next(r) % 0x5f); /* printable ASCII */
		put_utf8(&t->in, cp);
		put_utf8(&t->out, cp);
	}
	CHECK_INT(buf_append(&t->in, "", 1), 0);
	CHECK_INT(buf_append(&t->out, "", 1), 0);
}

/* A random script: bytes without a backslash (so every one in the page's copy is an
 * escape of ours) and pieces that must be escaped, or nearly. */
static void random_script(struct rng *r, struct buf *b)
{
	static const char *const pieces[] = {
		"</script>", "</SCRIPT>", "</ScRiPt", "<!--", "<!-", "</scrip", "<script>", "-->",
		"</script\n", "<</script",
	};
	size_t n = 1 + rng_next(r) % 600;

	buf_reset(b);
	for (size_t i = 0; i < n; i++) {
		if (rng_next(r) % 16 == 0) {
			const char *p = pieces[rng_next(r) % (sizeof(pieces) / sizeof(*pieces))];

			CHECK_INT(buf_append(b, p, strlen(p)), 0);
		} else {
			unsigned char c = (unsigned char)(1 + rng_next(r) % 255);

			if (c == '\\')
				c = '<';
			CHECK_INT(buf_append(b, &c, 1), 0);
		}
	}
}

/* ---- reading a page back ------------------------------------------------------------ */

static bool starts_nocase(const char *s, const char *end, const char *word)
{
	size_t k = strlen(word);

	if ((size_t)(end - s) < k)
		return false;
	for (size_t i = 0; i < k; i++) {
		char c = s[i];

		if (c >= 'A' && c <= 'Z')
			c = (char)(c - 'A' + 'a');
		if (c != word[i])
			return false;
	}
	return true;
}

static const char *find_nocase(const char *s, const char *end, const char *word)
{
	for (; s < end; s++)
		if (starts_nocase(s, end, word))
			return s;
	return NULL;
}

static const char *find(const char *s, const char *end, const char *word)
{
	size_t k = strlen(word);

	for (; s + k <= end; s++)
		if (memcmp(s, word, k) == 0)
			return s;
	return NULL;
}

/* Where the page's parts are: the JSON, the model's base64, the scripts' contents. */
struct page {
	const char *text, *end;
	const char *json, *json_end, *model, *model_end;
	const char *script[MAX_SCRIPTS + 3], *script_end[MAX_SCRIPTS + 3];
	size_t nscripts; /* every <script> element, the JSON's and the model's too */
};

/*
 * Reads the page as an HTML parser ends script elements: at the first "</script", in any
 * case, after the open tag's ">", which holds when no "<!--" is in between (after one, a
 * "<script" would hide the end tag). Checks that none is, that there are no other
 * "<script" outside, and that the CSP is in the head before the first script.
 */
static void read_page(const struct buf *b, struct page *p)
{
	const char *s = (const char *)b->data, *end = s + b->len, *at = s, *csp, *head_end;

	memset(p, 0, sizeof(*p));
	p->text = s;
	p->end = end;
	CHECK(b->len > 100 && !memcmp(s, "<!DOCTYPE html>\n<html>\n<head>\n<meta charset=\"utf-8\">\n", 52));
	head_end = find(s, end, "</head>");
	csp = find(s, end, "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
		       "script-src 'unsafe-inline'; style-src 'unsafe-inline'; base-uri 'none'; "
		       "form-action 'none'\">");
	CHECK(head_end && csp && csp < head_end);
	CHECK(!find_nocase(s, head_end, "<script"));
	/* one policy, and nothing may load from anywhere: no scheme, host nor wildcard in it */
	CHECK(!find(csp + 40, end, "Content-Security-Policy") && !find(s, csp, "Content-Security-Policy"));
	{
		const char *c = find(csp, head_end, "content=\""), *ce = memchr(c, '>', (size_t)(head_end - c));

		CHECK(!find(c, ce, ":") && !find(c, ce, "*") && !find(c, ce, "http"));
	}
	for (;;) {
		const char *open = find_nocase(at, end, "<script"), *gt, *close;

		if (!open)
			break;
		CHECK(p->nscripts < MAX_SCRIPTS + 3);
		gt = memchr(open, '>', (size_t)(end - open));
		CHECK(gt);
		close = find_nocase(gt + 1, end, "</script");
		CHECK(close);
		CHECK(!find(gt + 1, close, "<!--"));
		CHECK(starts_nocase(close, end, "</script>"));
		p->script[p->nscripts] = gt + 1;
		p->script_end[p->nscripts] = close;
		p->nscripts++;
		at = close + 9;
	}
	CHECK(p->nscripts >= 3);
	CHECK(!strncmp(p->script[0] - (sizeof(data_open) - 1), data_open, sizeof(data_open) - 1));
	p->json = p->script[0];
	p->json_end = p->script_end[0];
	CHECK(!strncmp(p->json_end, model_open, sizeof(model_open) - 1));
	p->model = p->script[1];
	p->model_end = p->script_end[1];
	CHECK(p->model == p->json_end + sizeof(model_open) - 1);
	CHECK(end - at == 17 && !memcmp(at, "\n</body>\n</html>\n", 17));
}

static int b64_value(char c)
{
	if (c >= 'A' && c <= 'Z')
		return c - 'A';
	if (c >= 'a' && c <= 'z')
		return c - 'a' + 26;
	if (c >= '0' && c <= '9')
		return c - '0' + 52;
	return c == '+' ? 62 : c == '/' ? 63 : -1;
}

/* Decodes strict base64 (padded, nothing else in it). */
static void b64_decode(const char *s, const char *end, struct buf *out)
{
	size_t n = (size_t)(end - s);

	buf_reset(out);
	CHECK(n % 4 == 0);
	for (size_t i = 0; i < n; i += 4) {
		int v[4];
		unsigned char o[3];
		size_t k = 3;

		for (int j = 0; j < 4; j++) {
			v[j] = b64_value(s[i + j]);
			if (v[j] < 0) {
				CHECK(s[i + j] == '=' && i + 4 == n && j >= 2);
				CHECK(j == 3 || s[i + 3] == '=');
				v[j] = 0;
				k = k < (size_t)j - 1 ? k : (size_t)j - 1;
			}
		}
		o[0] = (unsigned char)(v[0] << 2 | v[1] >> 4);
		o[1] = (unsigned char)(v[1] << 4 | v[2] >> 2);
		o[2] = (unsigned char)(v[2] << 6 | v[3]);
		CHECK_INT(buf_append(out, o, k), 0);
	}
}

/* A script's copy with the generator's two escapes undone. */
static void unescape(const char *s, const char *end, struct buf *out)
{
	buf_reset(out);
	while (s < end) {
		if (starts_nocase(s, end, "<\\/script")) {
			CHECK_INT(buf_append(out, "</", 2), 0);
			s += 3;
		} else if (starts_nocase(s, end, "\\x3c!--")) {
			CHECK(s[2] == '3' && s[3] == 'C'); /* as written */
			CHECK_INT(buf_append(out, "<", 1), 0);
			s += 4;
		} else {
			CHECK(*s != '\\');
			CHECK_INT(buf_append(out, s, 1), 0);
			s++;
		}
	}
}

static const char *json_str(struct json_object *o, const char *key)
{
	struct json_object *v;

	CHECK(json_object_object_get_ex(o, key, &v) && json_object_is_type(v, json_type_string));
	return json_object_get_string(v);
}

static unsigned paper_byte(float c)
{
	if (isnan(c) || c <= 0)
		return 0;
	return c >= 1 ? 255 : (unsigned)lroundf(c * 255);
}

/* ---- the property ------------------------------------------------------------------ */

struct input {
	struct buf glb, scripts[MAX_SCRIPTS];
	struct export_page_script s[MAX_SCRIPTS];
	struct text date, words[6];
	struct export_page_words w;
	struct export_page page;
};

static void input_init(struct input *in)
{
	memset(in, 0, sizeof(*in));
	buf_init(&in->glb);
	for (int i = 0; i < MAX_SCRIPTS; i++)
		buf_init(&in->scripts[i]);
	buf_init(&in->date.in);
	buf_init(&in->date.out);
	for (int i = 0; i < 6; i++) {
		buf_init(&in->words[i].in);
		buf_init(&in->words[i].out);
	}
}

static void input_finish(struct input *in)
{
	buf_finish(&in->glb);
	for (int i = 0; i < MAX_SCRIPTS; i++)
		buf_finish(&in->scripts[i]);
	buf_finish(&in->date.in);
	buf_finish(&in->date.out);
	for (int i = 0; i < 6; i++) {
		buf_finish(&in->words[i].in);
		buf_finish(&in->words[i].out);
	}
}

static void random_input(struct rng *r, struct input *in)
{
	static const float papers[] = { 0.975f, -1.0f, 2.0f, NAN, 0.0f, 1.0f, 0.5f, 0.002f };
	size_t glb_len = 1 + rng_next(r) % 3000;

	buf_reset(&in->glb);
	for (size_t i = 0; i < glb_len; i++) {
		unsigned char c = (unsigned char)rng_next(r);

		CHECK_INT(buf_append(&in->glb, &c, 1), 0);
	}
	in->page.nscripts = rng_next(r) % (MAX_SCRIPTS + 1);
	for (size_t i = 0; i < in->page.nscripts; i++) {
		random_script(r, &in->scripts[i]);
		in->s[i] = (struct export_page_script){ in->scripts[i].data, in->scripts[i].len };
	}
	random_text(r, &in->date);
	for (int i = 0; i < 6; i++)
		random_text(r, &in->words[i]);
	in->w = (struct export_page_words){
		.lang = rng_next(r) % 2 ? "ja" : "en",
		.number = (const char *)in->words[0].in.data,
		.title = (const char *)in->words[1].in.data,
		.untitled = (const char *)in->words[2].in.data,
		.hint = (const char *)in->words[3].in.data,
		.nogl = (const char *)in->words[4].in.data,
		.failed = (const char *)in->words[5].in.data,
	};
	in->page.glb = in->glb.data;
	in->page.glb_len = in->glb.len;
	in->page.scripts = in->s;
	in->page.number = (unsigned[]){ 0, 1, 42, 99999, UINT_MAX,
					(unsigned)rng_next(r) }[rng_next(r) % 6];
	in->page.date = (const char *)in->date.in.data;
	in->page.words = &in->w;
	for (int i = 0; i < 3; i++) {
		in->page.paper[i] = rng_next(r) % 2 ? papers[rng_next(r) % 8] : (float)rng_uniform(r);
		in->page.bark[i] = rng_next(r) % 2 ? papers[rng_next(r) % 8] : (float)rng_uniform(r);
		in->page.leaves[i] = rng_next(r) % 2 ? papers[rng_next(r) % 8] : (float)rng_uniform(r);
		in->page.stem[i] = rng_next(r) % 2 ? papers[rng_next(r) % 8] : (float)rng_uniform(r);
	}
}

/* data.tint: for each of the file's colours the power that takes it to the screen's, 1 where
 * either is no colour in (0, 1). */
static void check_tint(struct json_object *o, const struct export_page *page)
{
	static const double file[3][3] = { { MATERIAL_BARK_RGB }, { MATERIAL_LEAVES_RGB },
					   { MATERIAL_VINE_RGB } };
	static const char *const names[3] = { "bark", "leaves", "vine" };
	const float *screen[3] = { page->bark, page->leaves, page->stem };
	struct json_object *t, *v;

	CHECK(json_object_object_get_ex(o, "tint", &t) && json_object_object_length(t) == 3);
	for (int m = 0; m < 3; m++) {
		CHECK(json_object_object_get_ex(t, names[m], &v) && json_object_array_length(v) == 3);
		for (size_t c = 0; c < 3; c++) {
			double k = json_object_get_double(json_object_array_get_idx(v, c));
			float s = screen[m][c];

			CHECK(isfinite(k) && k > 0.0);
			if (s > 0.0f && s < 1.0f)
				CHECK(fabs(pow(file[m][c], k) - s) < 2e-6);
			else
				CHECK(k == 1.0);
		}
	}
}

/* Checks one page against its input; returns how many bytes of text it carried. */
static size_t check_page(const struct input *in, const struct buf *html, struct page *p,
			 struct buf *tmp)
{
	static const char *const keys[6] = { "number", "title", "untitled", "hint", "nogl", "failed" };
	struct json_object *o, *v, *w;
	size_t carried = 0;

	read_page(html, p);
	CHECK_INT(p->nscripts, 2 + in->page.nscripts + 1);
	/* the JSON: no markup character at all, and the text given */
	for (const char *c = p->json; c < p->json_end; c++)
		CHECK(*c != '<' && *c != '>' && *c != '&');
	buf_reset(tmp);
	CHECK_INT(buf_append(tmp, p->json, (size_t)(p->json_end - p->json)), 0);
	CHECK_INT(buf_append(tmp, "", 1), 0);
	o = json_tokener_parse((const char *)tmp->data);
	CHECK(o);
	CHECK(!strcmp(json_str(o, "lang"), in->w.lang));
	CHECK(!strcmp(json_str(o, "date"), (const char *)in->date.out.data));
	carried += strlen((const char *)in->date.out.data);
	CHECK(json_object_object_get_ex(o, "number", &v));
	CHECK(json_object_is_type(v, json_type_int));
	CHECK_INT(json_object_get_int64(v), in->page.number);
	CHECK(json_object_object_get_ex(o, "paper", &v) && json_object_array_length(v) == 3);
	for (size_t i = 0; i < 3; i++)
		CHECK_INT(json_object_get_int(json_object_array_get_idx(v, i)),
			  paper_byte(in->page.paper[i]));
	CHECK(json_object_object_get_ex(o, "pitch", &v) && json_object_array_length(v) == 2);
	CHECK_INT(json_object_get_int(json_object_array_get_idx(v, 0)), -20);
	CHECK_INT(json_object_get_int(json_object_array_get_idx(v, 1)), 75);
	check_tint(o, &in->page);
	CHECK(json_object_object_get_ex(o, "words", &w));
	for (int i = 0; i < 6; i++) {
		CHECK(!strcmp(json_str(w, keys[i]), (const char *)in->words[i].out.data));
		carried += strlen((const char *)in->words[i].out.data);
	}
	json_object_put(o);
	/* the model */
	b64_decode(p->model, p->model_end, tmp);
	CHECK(tmp->len == in->glb.len && !memcmp(tmp->data, in->glb.data, tmp->len));
	/* the scripts, in order, then edaha's viewer */
	for (size_t i = 0; i < in->page.nscripts; i++) {
		const char *s = p->script[2 + i], *e = p->script_end[2 + i];

		CHECK(*s == '\n');
		unescape(s + 1, e, tmp);
		if (in->scripts[i].data[in->scripts[i].len - 1] != '\n') {
			CHECK(tmp->len > 0 && tmp->data[tmp->len - 1] == '\n');
			tmp->len--;
		}
		CHECK(tmp->len == in->scripts[i].len &&
		      !memcmp(tmp->data, in->scripts[i].data, tmp->len));
	}
	CHECK(!strncmp(p->script[2 + in->page.nscripts], "\n/* SPDX-License-Identifier: MIT */", 35));
	return carried;
}

/* The bytes of a and b outside their JSON and their model's base64 are the same. */
static void check_same_markup(const struct page *a, const struct page *b)
{
	CHECK(a->json - a->text == b->json - b->text && !memcmp(a->text, b->text, (size_t)(a->json - a->text)));
	CHECK(a->model - a->json_end == b->model - b->json_end &&
	      !memcmp(a->json_end, b->json_end, (size_t)(a->model - a->json_end)));
	CHECK(a->end - a->model_end == b->end - b->model_end &&
	      !memcmp(a->model_end, b->model_end, (size_t)(a->end - a->model_end)));
}

static void test_random(void)
{
	struct input *in = malloc(sizeof(*in)), *ref = malloc(sizeof(*ref));
	struct buf html, again, ref_html, tmp;
	struct page p, rp;
	struct rng r;
	size_t carried = 0, bytes = 0, hostile_scripts = 0;
	int cases = test_cases(CASES);

	CHECK(in && ref);
	input_init(in);
	input_init(ref);
	buf_init(&html);
	buf_init(&again);
	buf_init(&ref_html);
	buf_init(&tmp);
	for (int c = 0; c < cases; c++) {
		rng_seed(&r, 0x9a9e0000u + (uint64_t)c);
		random_input(&r, in);
		buf_reset(&html);
		CHECK_INT(export_page_html(&in->page, &html), 0);
		carried += check_page(in, &html, &p, &tmp);
		bytes += html.len;
		for (size_t i = 0; i < in->page.nscripts; i++)
			hostile_scripts += find_nocase((const char *)in->scripts[i].data,
						       (const char *)in->scripts[i].data + in->scripts[i].len,
						       "</script") != NULL;
		/* the same input, the same bytes */
		buf_reset(&again);
		CHECK_INT(export_page_html(&in->page, &again), 0);
		CHECK(again.len == html.len && !memcmp(again.data, html.data, html.len));
		/* the same scripts with other text, number and model: the same markup */
		rng_seed(&r, 0x5eed0000u + (uint64_t)c);
		random_input(&r, ref);
		ref->page.nscripts = in->page.nscripts;
		ref->page.scripts = in->page.scripts;
		buf_reset(&ref_html);
		CHECK_INT(export_page_html(&ref->page, &ref_html), 0);
		read_page(&ref_html, &rp);
		check_same_markup(&p, &rp);
	}
	printf("export_page_html: %d random pages (%zu bytes), %zu bytes of random text read back "
	       "from the JSON alone, %zu scripts holding \"</script\" inlined whole; the markup "
	       "the same in every pair\n", cases, bytes, carried, hostile_scripts);
	CHECK(hostile_scripts > 0);
	input_finish(in);
	input_finish(ref);
	free(in);
	free(ref);
	buf_finish(&html);
	buf_finish(&again);
	buf_finish(&ref_html);
	buf_finish(&tmp);
}

/* ---- fixed cases ------------------------------------------------------------------- */

static void test_fixed(void)
{
	static const char glb[] = "</script><script>alert('glb')</script>";
	static const char hostile[] = "</script><script>alert(1)</script><!--";
	const struct export_page_script script = { "var a = '</script>';\n", 22 };
	struct export_page page = {
		.glb = glb, .glb_len = sizeof(glb) - 1, .scripts = &script, .nscripts = 1,
		.number = 7, .date = hostile, .words = export_page_words(EXPORT_PAGE_JA),
		.paper = { 0.975f, 0.953f, 0.898f },
		.bark = { 0.47f, 0.32f, 0.20f },
	};
	struct buf html, plain;
	struct page p, q;
	char date[64];

	buf_init(&html);
	buf_init(&plain);
	CHECK_INT(export_page_html(&page, &html), 0);
	read_page(&html, &p);
	CHECK_INT(p.nscripts, 4);
	CHECK(!find(p.text, p.end, hostile) && !find(p.text, p.end, "alert(1)</script>"));
	CHECK(find(p.json, p.json_end, "\\u003c/script\\u003e\\u003cscript\\u003ealert(1)"));
	CHECK(find(p.json, p.json_end, "\"paper\":[249,243,229]"));
	/* the screen's bark from the file's (0.33, 0.22, 0.13); no leaves or stem given: as is */
	CHECK(find(p.json, p.json_end, "\"tint\":{\"bark\":[0.681021,0.752535,0.788855],"
		   "\"leaves\":[1,1,1],\"vine\":[1,1,1]}"));
	CHECK(find(p.script[2], p.script_end[2], "var a = '<\\/script>';"));
	/* and the same markup as a page of plain words */
	page.date = "5 December 2026";
	page.words = export_page_words(EXPORT_PAGE_EN);
	CHECK_INT(export_page_html(&page, &plain), 0);
	read_page(&plain, &q);
	check_same_markup(&p, &q);

	/* the words of each language, and their dates */
	for (int l = 0; l < EXPORT_PAGE_NLANGS; l++) {
		const struct export_page_words *w = export_page_words((enum export_page_lang)l);

		CHECK(w && w->lang && w->number && strchr(w->number, '#') && w->title &&
		      strchr(w->title, '#') && w->untitled && w->hint && w->nogl && w->failed);
	}
	CHECK(!export_page_words(EXPORT_PAGE_NLANGS));
	CHECK(!strcmp(export_page_words(EXPORT_PAGE_JA)->lang, "ja"));
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2026, 12, 5, date, sizeof(date)), 0);
	CHECK(!strcmp(date, "5 December 2026"));
	CHECK_INT(export_page_date(EXPORT_PAGE_JA, 2026, 12, 5, date, sizeof(date)), 0);
	CHECK(!strcmp(date, "2026ねん 12がつ 5にち"));
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2024, 2, 29, date, sizeof(date)), 0);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2025, 2, 29, date, sizeof(date)), -EINVAL);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2100, 2, 29, date, sizeof(date)), -EINVAL);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2000, 2, 29, date, sizeof(date)), 0);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2026, 13, 1, date, sizeof(date)), -EINVAL);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2026, 4, 31, date, sizeof(date)), -EINVAL);
	CHECK_INT(export_page_date(EXPORT_PAGE_NLANGS, 2026, 4, 1, date, sizeof(date)), -EINVAL);
	CHECK_INT(export_page_date(EXPORT_PAGE_EN, 2026, 12, 5, date, 8), -ENOSPC);
	CHECK(!strcmp(date, ""));

	/* refused: out as it was */
	buf_reset(&html);
	CHECK_INT(buf_append(&html, "kept", 4), 0);
	page.glb_len = 0;
	CHECK_INT(export_page_html(&page, &html), -EINVAL);
	page.glb_len = sizeof(glb) - 1;
	page.words = NULL;
	CHECK_INT(export_page_html(&page, &html), -EINVAL);
	page.words = export_page_words(EXPORT_PAGE_EN);
	page.scripts = NULL;
	CHECK_INT(export_page_html(&page, &html), -EINVAL);
	page.scripts = &(const struct export_page_script){ "", 0 };
	CHECK_INT(export_page_html(&page, &html), -EINVAL);
	CHECK(html.len == 4 && !memcmp(html.data, "kept", 4) && !html.failed);
	buf_finish(&html);
	buf_finish(&plain);
}

int main(void)
{
	test_fixed();
	test_random();
	return 0;
}
