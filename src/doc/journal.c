/* SPDX-License-Identifier: MIT */
#include "journal.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#define JOURNAL_MAGIC "edaha-journal"
/* "@ FROM CURSOR BYTES CRC\n": never longer than this */
#define JOURNAL_LINE_MAX 128

int journal_header(struct buf *out)
{
	return buf_printf(out, "%s %d\n", JOURNAL_MAGIC, JOURNAL_VERSION);
}

static uint32_t crc_of(const char *data, size_t len)
{
	uLong crc = crc32(0L, Z_NULL, 0);

	/* zlib takes uInt lengths: feed it in pieces */
	while (len) {
		uInt n = len > (1u << 30) ? (1u << 30) : (uInt)len;

		crc = crc32(crc, (const Bytef *)data, n);
		data += n;
		len -= n;
	}
	return (uint32_t)crc;
}

int journal_record(const struct doc *d, size_t from, struct buf *out)
{
	/* the ops from `from` on as a drawing of their own: same seed and view, all in
	 * effect (the record carries the real cursor) */
	struct doc part = {
		.seed = d->seed,
		/* an empty drawing has no array: NULL + 0 is undefined */
		.ops = from < d->nops ? d->ops + from : NULL,
		.nops = from < d->nops ? d->nops - from : 0,
		.view = d->view,
	};
	struct buf body;
	int ret;

	part.cursor = part.nops;
	buf_init(&body);
	ret = doc_serialize(&part, NULL, &body);
	if (ret == 0)
		ret = buf_printf(out, "@ %zu %zu %zu %08" PRIx32 "\n", from, d->cursor, body.len,
				 crc_of((const char *)body.data, body.len));
	if (ret == 0)
		ret = buf_append(out, body.data, body.len);
	buf_finish(&body);
	return ret;
}

static unsigned long line_at(const char *data, size_t off)
{
	unsigned long line = 1;

	for (size_t i = 0; i < off; i++)
		line += data[i] == '\n';
	return line;
}

/* Parses "@ FROM CURSOR BYTES CRC" (the line without its '\n'). */
static bool parse_head(const char *line, size_t *from, size_t *cursor, size_t *bytes,
		       uint32_t *crc)
{
	unsigned long long f, c, b;
	unsigned long x;
	int used = 0;

	if (sscanf(line, "@ %llu %llu %llu %8lx%n", &f, &c, &b, &x, &used) != 4 ||
	    line[used] != '\0' || f > DOC_MAX_OPS || c > DOC_MAX_OPS || b > JOURNAL_MAX_RECORD)
		return false;
	*from = (size_t)f;
	*cursor = (size_t)c;
	*bytes = (size_t)b;
	*crc = (uint32_t)x;
	return true;
}

/* Whether d's ops[0..from) followed by part's stay within a drawing's limits. */
static bool fits(const struct doc *d, size_t from, const struct doc *part)
{
	size_t points = doc_total_points(part);

	for (size_t i = 0; i < from; i++)
		points += doc_op_weight(&d->ops[i]);
	return from + part->nops <= DOC_MAX_OPS && points <= DOC_MAX_POINTS;
}

/* d's ops from `from` on become part's (taken, part left empty). 0 or -ENOMEM, and then
 * d is unchanged. */
static int splice(struct doc *d, size_t from, struct doc *part)
{
	size_t n = from + part->nops;

	if (n > d->cap) {
		size_t cap = d->cap ? d->cap : 32;
		struct doc_op *ops;

		while (cap < n)
			cap *= 2;
		ops = realloc(d->ops, cap * sizeof(*ops));
		if (!ops)
			return -ENOMEM;
		d->ops = ops;
		d->cap = cap;
	}
	for (size_t i = from; i < d->nops; i++)
		doc_op_finish(&d->ops[i]);
	if (part->nops) /* an undo's record has none, and no array */
		memcpy(d->ops + from, part->ops, part->nops * sizeof(*part->ops));
	d->nops = n;
	free(part->ops);
	part->ops = NULL;
	part->nops = part->cap = part->cursor = 0;
	return 0;
}

static int tail(struct journal_replay *r, const char *data, size_t off, const char *name,
		const char *what)
{
	r->torn = true;
	error_at(&r->tail, -EINVAL, name, line_at(data, off), "%s", what);
	return 0;
}

int journal_replay(const char *data, size_t len, const char *name, struct doc *d,
		   struct journal_replay *r, struct error *err)
{
	char line[JOURNAL_LINE_MAX + 1], want[32];
	const char *nl = memchr(data, '\n', len);
	size_t off;

	memset(r, 0, sizeof(*r));
	doc_finish(d);
	snprintf(want, sizeof(want), "%s %d", JOURNAL_MAGIC, JOURNAL_VERSION);
	if (!nl || (size_t)(nl - data) != strlen(want) || memcmp(data, want, strlen(want)) != 0) {
		if (len >= strlen(JOURNAL_MAGIC) && memcmp(data, JOURNAL_MAGIC, strlen(JOURNAL_MAGIC)) == 0)
			return error_at(err, -EINVAL, name, 1,
					"unsupported journal version (this edaha reads %d)",
					JOURNAL_VERSION);
		return error_at(err, -EINVAL, name, 1, "not an edaha journal");
	}
	off = r->good = (size_t)(nl - data) + 1;
	while (off < len) {
		size_t from, cursor, bytes, hl;
		uint32_t crc;
		struct doc part;
		struct error perr;
		int ret;

		nl = memchr(data + off, '\n', len - off);
		if (!nl)
			return tail(r, data, off, name, "record cut short");
		hl = (size_t)(nl - (data + off));
		if (hl > JOURNAL_LINE_MAX)
			return tail(r, data, off, name, "not a record");
		memcpy(line, data + off, hl);
		line[hl] = '\0';
		if (!parse_head(line, &from, &cursor, &bytes, &crc))
			return tail(r, data, off, name, "not a record");
		if (bytes > len - off - hl - 1)
			return tail(r, data, off, name, "record cut short");
		if (crc_of(nl + 1, bytes) != crc)
			return tail(r, data, off, name, "record damaged (CRC mismatch)");
		if (from > d->nops)
			return tail(r, data, off, name, "record starts past the drawing");
		doc_init(&part, 0);
		ret = doc_parse(nl + 1, bytes, name, &part, &perr);
		if (ret == -ENOMEM) {
			doc_finish(d);
			return error_set(err, ret, "%s: out of memory", name);
		}
		if (ret < 0)
			return tail(r, data, off, name, "record holds no drawing");
		if (!fits(d, from, &part) || cursor > from + part.nops) {
			doc_finish(&part);
			return tail(r, data, off, name,
				    cursor > from + part.nops ? "record's cursor past its ops"
							     : "record takes the drawing past its limits");
		}
		d->seed = part.seed;
		d->view = part.view;
		ret = splice(d, from, &part);
		doc_finish(&part);
		if (ret < 0) {
			doc_finish(d);
			return error_set(err, ret, "%s: out of memory", name);
		}
		d->cursor = cursor;
		off += hl + 1 + bytes;
		r->good = off;
		r->records++;
	}
	return 0;
}
