/* SPDX-License-Identifier: MIT */
#include "yaml_node.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *yaml_node_kind(const yaml_node_t *n)
{
	switch (n->type) {
	case YAML_SCALAR_NODE:
		return "a scalar";
	case YAML_SEQUENCE_NODE:
		return "a list";
	case YAML_MAPPING_NODE:
		return "a mapping";
	default:
		return "nothing";
	}
}

const char *yaml_node_text(const yaml_node_t *n)
{
	if (n->type != YAML_SCALAR_NODE)
		return NULL;
	if (strlen((const char *)n->data.scalar.value) != n->data.scalar.length)
		return NULL;
	return (const char *)n->data.scalar.value;
}

bool yaml_node_plain(const yaml_node_t *n)
{
	return n->type == YAML_SCALAR_NODE && n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
}

/* The lines of data as YAML counts them (breaks: \n, \r, \r\n, U+0085, U+2028, U+2029),
 * a last one without its break included. */
static unsigned long lines(const char *data, size_t len)
{
	const unsigned char *d = (const unsigned char *)data;
	unsigned long n = 1;

	for (size_t i = 0; i < len; i++) {
		size_t at = i;

		if (d[i] == '\r' && i + 1 < len && d[i + 1] == '\n')
			at = ++i;
		else if (d[i] == 0xc2 && i + 1 < len && d[i + 1] == 0x85)
			at = ++i;
		else if (d[i] == 0xe2 && i + 2 < len && d[i + 1] == 0x80 &&
			 (d[i + 2] == 0xa8 || d[i + 2] == 0xa9))
			at = (i += 2);
		else if (d[i] != '\n' && d[i] != '\r')
			continue;
		/* a break ends a line; one that ends the data starts none */
		if (at + 1 < len)
			n++;
	}
	return n;
}

unsigned long yaml_node_line(const yaml_mark_t *m, const char *data, size_t len)
{
	unsigned long line = (unsigned long)m->line + 1, last = lines(data, len);

	return line > last ? last : line;
}

int yaml_node_parse_error(struct error *err, const char *name, unsigned long offset,
			  const yaml_parser_t *y, const char *data, size_t len)
{
	unsigned long line;

	if (y->error == YAML_MEMORY_ERROR)
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	if (y->error == YAML_READER_ERROR) {
		size_t end = y->problem_offset < len ? y->problem_offset : len;

		line = 1;
		for (size_t i = 0; i < end; i++)
			line += data[i] == '\n';
		return error_at(err, -EINVAL, name, line + offset, "not YAML text: %s",
				y->problem ? y->problem : "unreadable");
	}
	line = yaml_node_line(&y->problem_mark, data, len) + offset;
	return error_at(err, -EINVAL, name, line, "YAML error: %s%s%s",
			y->problem ? y->problem : "error", y->context ? " " : "",
			y->context ? y->context : "");
}

bool yaml_node_number(const char *s, double *out)
{
	const char *q = s + (*s == '-' || *s == '+');
	char *end;
	double x;

	if (!((*q >= '0' && *q <= '9') || (*q == '.' && q[1] >= '0' && q[1] <= '9')))
		return false;
	for (; *q; q++)
		if (!strchr("0123456789.eE+-", *q))
			return false;
	errno = 0;
	x = strtod(s, &end);
	if (*end || !isfinite(x) || errno == ERANGE)
		return false;
	*out = x;
	return true;
}

const char *yaml_node_shown(const char *s, char out[24])
{
	size_t i = 0;

	for (; s[i] && i < 20; i++)
		out[i] = (unsigned char)s[i] >= 0x20 && (unsigned char)s[i] < 0x7f ? s[i] : '?';
	if (s[i]) {
		out[i++] = '.';
		out[i++] = '.';
	}
	out[i] = '\0';
	return out;
}

int yaml_node_prescan(const char *data, size_t len, const char *name, unsigned long offset,
		      int max_depth, const char *what, struct error *err)
{
	yaml_parser_t y;
	yaml_event_t ev;
	int ret = 0, depth = 0;

	if (!yaml_parser_initialize(&y))
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	yaml_parser_set_input_string(&y, (const unsigned char *)data, len);
	while (ret == 0 && yaml_parser_parse(&y, &ev)) {
		yaml_event_type_t type = ev.type;
		unsigned long line = yaml_node_line(&ev.start_mark, data, len) + offset;

		if (type == YAML_ALIAS_EVENT)
			ret = error_at(err, -EINVAL, name, line,
				       "an alias (*name): %ss do not use them", what);
		else if ((type == YAML_MAPPING_START_EVENT || type == YAML_SEQUENCE_START_EVENT) &&
			 ++depth > max_depth)
			ret = error_at(err, -EINVAL, name, line, "nested more than %d deep: not a %s",
				       max_depth, what);
		else if (type == YAML_MAPPING_END_EVENT || type == YAML_SEQUENCE_END_EVENT)
			depth--;
		yaml_event_delete(&ev);
		if (type == YAML_STREAM_END_EVENT)
			break;
	}
	yaml_parser_delete(&y);
	return ret;
}

const yaml_node_t *yaml_node_lookup(yaml_document_t *doc, const yaml_node_t *n, const char *k,
				    const yaml_node_t **key)
{
	if (n->type != YAML_MAPPING_NODE)
		return NULL;
	for (yaml_node_pair_t *pair = n->data.mapping.pairs.start; pair < n->data.mapping.pairs.top;
	     pair++) {
		const yaml_node_t *kn = yaml_document_get_node(doc, pair->key);
		const char *s = kn ? yaml_node_text(kn) : NULL;

		if (s && !strcmp(s, k)) {
			if (key)
				*key = kn;
			return yaml_document_get_node(doc, pair->value);
		}
	}
	return NULL;
}

const yaml_node_t *yaml_node_earlier_key(yaml_document_t *doc, const yaml_node_t *n,
					 const yaml_node_pair_t *pair, const char *k)
{
	for (const yaml_node_pair_t *q = n->data.mapping.pairs.start; q < pair; q++) {
		const yaml_node_t *other = yaml_document_get_node(doc, q->key);
		const char *o = other ? yaml_node_text(other) : NULL;

		if (o && !strcmp(o, k))
			return other;
	}
	return NULL;
}
