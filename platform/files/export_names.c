/* SPDX-License-Identifier: MIT */
#include "export_names.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

const char *const export_names_suffixes[EXPORT_NAMES_NSUFFIXES] = {
	".glb", ".obj", ".mtl", ".png", ".edaha", ".html",
};

void export_names_init(struct export_names *n)
{
	memset(n, 0, sizeof(*n));
}

static char lower(char c)
{
	return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

/* Whether s starts with the lower-case word, in any case; advances *s past it. */
static bool starts(const char **s, const char *word)
{
	const char *p = *s;

	for (; *word; word++, p++)
		if (lower(*p) != *word)
			return false;
	*s = p;
	return true;
}

/* Decimal digits; false when there are none. A value past EXPORT_NAMES_MAX is
 * EXPORT_NAMES_MAX + 1 (however many digits: leading zeros do not count). */
static bool number_at(const char **s, unsigned *v)
{
	const char *p = *s;
	unsigned x = 0;

	if (*p < '0' || *p > '9')
		return false;
	for (; *p >= '0' && *p <= '9'; p++)
		x = x > EXPORT_NAMES_MAX ? x : x * 10 + (unsigned)(*p - '0');
	*v = x > EXPORT_NAMES_MAX ? EXPORT_NAMES_MAX + 1 : x;
	*s = p;
	return true;
}

enum export_name_kind export_names_classify(const char *name, unsigned *number)
{
	const char *p = name;
	unsigned v;

	if (*p == '.') {
		/* exactly ".tree-N" + one of our suffixes + ".tmp": nothing else is ours */
		p++;
		if (!starts(&p, "tree-") || !number_at(&p, &v) || v == 0 || v > EXPORT_NAMES_MAX)
			return EXPORT_NAME_OTHER;
		for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++) {
			const char *q = p;

			if (starts(&q, export_names_suffixes[i]) && starts(&q, ".tmp") && !*q) {
				*number = v;
				return EXPORT_NAME_TEMP;
			}
		}
		return EXPORT_NAME_OTHER;
	}
	if (!starts(&p, "tree-") || !number_at(&p, &v) || (*p && *p != '.'))
		return EXPORT_NAME_OTHER;
	if (v == 0 || v > EXPORT_NAMES_MAX)
		return EXPORT_NAME_OTHER;
	*number = v;
	return EXPORT_NAME_FINAL;
}

enum export_name_kind export_names_add(struct export_names *n, const char *name)
{
	unsigned v = 0;
	enum export_name_kind k = export_names_classify(name, &v);

	if (k != EXPORT_NAME_OTHER) {
		n->used[v / 8] |= (uint8_t)(1u << (v % 8));
		if (v > n->max)
			n->max = v;
	}
	return k;
}

int export_names_next(const struct export_names *n, unsigned *number)
{
	if (n->max < EXPORT_NAMES_MAX) {
		*number = n->max + 1;
		return 0;
	}
	for (unsigned v = 1; v <= EXPORT_NAMES_MAX; v++) {
		if (!(n->used[v / 8] & (1u << (v % 8)))) {
			*number = v;
			return 0;
		}
	}
	return -ENOSPC;
}

int export_names_format(char *out, size_t size, unsigned number, const char *suffix, bool temp)
{
	int len = snprintf(out, size, "%stree-%04u%s%s", temp ? "." : "", number, suffix,
			   temp ? ".tmp" : "");

	return len < 0 || (size_t)len >= size ? -ENAMETOOLONG : 0;
}
