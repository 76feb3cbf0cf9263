/* SPDX-License-Identifier: MIT */
#pragma once

#include <dirent.h>
#include <stddef.h>

#include "error.h"

/* Reads a whole regular file (at most max bytes) into a NUL-terminated malloc'ed buffer.
 * 0 or -errno, with a message naming the file. */
int fileio_read_all(const char *path, size_t max, char **data, size_t *len, struct error *err);

/* Creates dir and its parents as needed. 0 or -errno. */
int fileio_mkdirs(const char *dir, struct error *err);

/* Writes dir/name so that it is either the old file or the complete new one, never half:
 * a temporary name, fsync, rename, fsync of the directory. Never follows a symlink. */
int fileio_write_atomic(const char *dir, const char *name, const void *data, size_t len,
		      struct error *err);
/* The same in the directory dfd (a stick's edaha/, passed by the helper): the temporary
 * .NAME.tmp (a leftover of that name removed first), O_EXCL | O_NOFOLLOW, fsynced, renamed
 * over name (replacing it, a symlink itself rather than its target), dfd fsynced. On
 * failure name is as it was and no temporary is left. 0 or -errno. */
int fileio_write_atomic_at(int dfd, const char *name, const void *data, size_t len,
			   struct error *err);

/* *dir: a listing of the directory dfd through an open file description of its own, so
 * that dfd's offset stays where it is (closedir it). 0, or -errno with a message. */
int fileio_opendir_at(int dfd, DIR **dir, struct error *err);
