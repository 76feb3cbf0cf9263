/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The names an export set takes in a directory (a USB stick's edaha/, kiosk.export_dir):
 * tree-NNNN.glb, .obj, .mtl, .png, .edaha and .html, the take-home page (NNNN at least
 * four digits), written through temporaries .tree-NNNN.EXT.tmp. The next number is found
 * from one listing of the directory, the names fed in one by one: pure, so thousands of
 * files cost one readdir and no stat each. Names compare without case, as FAT does.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Numbers stay below this (five digits); a directory that holds them all is full. */
#define EXPORT_NAMES_MAX 99999u
/* The files of a set, in the order they are written. */
#define EXPORT_NAMES_NSUFFIXES 6
extern const char *const export_names_suffixes[EXPORT_NAMES_NSUFFIXES];

enum export_name_kind {
	EXPORT_NAME_OTHER = 0, /* takes no number */
	EXPORT_NAME_FINAL,     /* tree-N or tree-N.anything: N is taken */
	EXPORT_NAME_TEMP,      /* .tree-N.EXT.tmp of one of ours, left by an interrupted write */
};

/* What a directory's names say about the numbers taken. */
struct export_names {
	unsigned max; /* the highest number taken, 0: none */
	uint8_t used[EXPORT_NAMES_MAX / 8 + 1];
};

void export_names_init(struct export_names *n);
/* One name from the directory: its kind, and *number for FINAL and TEMP (numbers past
 * EXPORT_NAMES_MAX are OTHER: no name of ours can be theirs). */
enum export_name_kind export_names_classify(const char *name, unsigned *number);
/* Classifies name and marks its number taken. */
enum export_name_kind export_names_add(struct export_names *n, const char *name);
/* The next set's number: one past the highest taken, so the newest tree sorts last;
 * after EXPORT_NAMES_MAX the lowest free one. 0 or -ENOSPC (all taken). */
int export_names_next(const struct export_names *n, unsigned *number);
/* "tree-0042" + suffix (".glb"), or the temporary ".tree-0042.glb.tmp". 0 or -ENAMETOOLONG. */
int export_names_format(char *out, size_t size, unsigned number, const char *suffix, bool temp);
