/* SPDX-License-Identifier: MIT */
#include "yaml_node.h"

#include <errno.h>
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
