/* SPDX-License-Identifier: MIT */
#pragma once

/* Reading back the OBJ and skeleton.json the exporters wrote, for the export tests
 * (header-only, static). Texts are NUL-terminated. */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "glb_read.h"
#include "season.h"
#include "test.h"

/* The OBJ's text from its first line starting with `from` to the first starting with `to`
 * after it (or the end); NULL if there is no `from` line. */
static inline char *section(const struct buf *b, const char *from, const char *to)
{
	const char *text = (const char *)b->data, *s, *e;
	char key[64];
	char *out;

	snprintf(key, sizeof(key), "\n%s", from);
	s = strstr(text, key);
	if (!s)
		return NULL;
	s++;
	snprintf(key, sizeof(key), "\n%s", to);
	e = to ? strstr(s, key) : NULL;
	e = e ? e + 1 : text + b->len;
	out = malloc((size_t)(e - s) + 1);
	CHECK(out);
	memcpy(out, s, (size_t)(e - s));
	out[e - s] = '\0';
	return out;
}

/* The lines of text starting with `tag` and a space, in order, as one string. */
static inline char *lines_of(const char *text, const char *tag)
{
	size_t tlen = strlen(tag), n = 0;
	char *out = malloc(strlen(text) + 1);

	CHECK(out);
	for (const char *l = text; *l;) {
		const char *e = strchr(l, '\n');
		size_t len = e ? (size_t)(e - l) + 1 : strlen(l);

		if (!strncmp(l, tag, tlen) && l[tlen] == ' ') {
			memcpy(out + n, l, len);
			n += len;
		}
		l += len;
	}
	out[n] = '\0';
	return out;
}

static inline int cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The lines of text, sorted: to compare faces whatever their order. */
static inline char *sorted_lines(const char *text)
{
	size_t n = 0, len = strlen(text), pos = 0;
	char *copy = strdup(text), **lines, *out = malloc(len + 1);

	CHECK(copy && out);
	for (const char *c = text; *c; c++)
		n += *c == '\n';
	lines = malloc((n + 1) * sizeof(*lines));
	CHECK(lines);
	n = 0;
	for (char *save = NULL, *l = strtok_r(copy, "\n", &save); l; l = strtok_r(NULL, "\n", &save))
		lines[n++] = l;
	qsort(lines, n, sizeof(*lines), cmp_str);
	for (size_t i = 0; i < n; i++)
		pos += (size_t)sprintf(out + pos, "%s\n", lines[i]);
	out[pos] = '\0';
	free(lines);
	free(copy);
	return out;
}

/* Only the top-level "season" differs; the branches and leaves are the same. */
static inline void check_skeleton_season(const struct buf *skel, const struct buf *summer, enum season s)
{
	struct json_object *a = json_tokener_parse((const char *)skel->data);
	struct json_object *b = json_tokener_parse((const char *)summer->data);
	char key[32];
	const char *text = (const char *)skel->data, *stext = (const char *)summer->data;
	const char *at_s = strstr(text, "\"season\":\""), *at_summer = strstr(stext, "\"season\":\"");
	size_t head = (size_t)(at_s - text), name_len = strlen(season_name(s));

	CHECK(a && b && at_s && at_summer);
	CHECK(!strcmp(get_str(a, "season"), season_name(s)));
	CHECK(json_object_equal(get(a, "branches"), get(b, "branches")));
	CHECK(json_object_equal(get(a, "leaves"), get(b, "leaves")));
	/* and byte for byte but the season's name */
	snprintf(key, sizeof(key), "\"season\":\"%s\"", season_name(s));
	CHECK(!strncmp(at_s, key, strlen(key)));
	CHECK_INT(head, at_summer - stext);
	CHECK(!memcmp(text, stext, head));
	CHECK(!strcmp(at_s + strlen(key), at_summer + strlen("\"season\":\"summer\"")));
	CHECK_INT(skel->len, summer->len - strlen("summer") + name_len);
	json_object_put(a);
	json_object_put(b);
}
