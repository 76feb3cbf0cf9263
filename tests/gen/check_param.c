/* SPDX-License-Identifier: MIT */
/*
 * gen_check param FILE KEY [DEFAULT]: a value of a parameter file as the tests need it
 * (KEY a path such as clip.center; a list printed as its items, space-separated), or
 * DEFAULT when the file leaves it out. The tests read the presets rather than copy their
 * numbers, so tuning a preset does not break them. libyaml directly: not edaha's reader.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "gen_check.h"

static yaml_node_t *child(yaml_document_t *doc, yaml_node_t *map, const char *key, size_t len)
{
	if (!map || map->type != YAML_MAPPING_NODE)
		return NULL;
	for (yaml_node_pair_t *p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
		yaml_node_t *k = yaml_document_get_node(doc, p->key);

		if (k && k->type == YAML_SCALAR_NODE && k->data.scalar.length == len &&
		    !memcmp(k->data.scalar.value, key, len))
			return yaml_document_get_node(doc, p->value);
	}
	return NULL;
}

static void print_node(yaml_document_t *doc, yaml_node_t *n)
{
	if (n->type == YAML_SCALAR_NODE) {
		printf("%s", (const char *)n->data.scalar.value);
		return;
	}
	for (yaml_node_item_t *i = n->data.sequence.items.start;
	     n->type == YAML_SEQUENCE_NODE && i < n->data.sequence.items.top; i++) {
		yaml_node_t *item = yaml_document_get_node(doc, *i);

		if (item && item->type == YAML_SCALAR_NODE)
			printf("%s%s", i > n->data.sequence.items.start ? " " : "",
			       (const char *)item->data.scalar.value);
	}
}

int check_param(int argc, char **argv)
{
	yaml_parser_t parser;
	yaml_document_t doc;
	yaml_node_t *n;
	FILE *f;
	int ret = 1;

	if (argc != 2 && argc != 3)
		return 2;
	f = fopen(argv[0], "rb");
	if (!f || !yaml_parser_initialize(&parser)) {
		fprintf(stderr, "%s: cannot read\n", argv[0]);
		if (f)
			fclose(f);
		return 2;
	}
	yaml_parser_set_input_file(&parser, f);
	if (!yaml_parser_load(&parser, &doc)) {
		fprintf(stderr, "%s: not YAML\n", argv[0]);
		yaml_parser_delete(&parser);
		fclose(f);
		return 2;
	}
	n = yaml_document_get_root_node(&doc);
	for (const char *k = argv[1]; n && *k;) {
		size_t len = strcspn(k, ".");

		n = child(&doc, n, k, len);
		k += len + (k[len] == '.');
	}
	if (n) {
		print_node(&doc, n);
		printf("\n");
		ret = 0;
	} else if (argc == 3) {
		printf("%s\n", argv[2]);
		ret = 0;
	}
	yaml_document_delete(&doc);
	yaml_parser_delete(&parser);
	fclose(f);
	return ret;
}
