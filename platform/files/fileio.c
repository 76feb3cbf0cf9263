/* SPDX-License-Identifier: MIT */
#include "fileio.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int fileio_read_all(const char *path, size_t max, char **data, size_t *len, struct error *err)
{
	struct stat st;
	char *buf = NULL;
	size_t have = 0, cap = 0;
	int fd, ret = 0;

	*data = NULL;
	*len = 0;
	/* Non-blocking open: a FIFO without a writer must not hang the kiosk. */
	fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0)
		return error_at(err, -errno, path, 0, "%s", strerror(errno));
	if (fstat(fd, &st) < 0) {
		ret = error_at(err, -errno, path, 0, "%s", strerror(errno));
		goto out;
	}
	if (S_ISDIR(st.st_mode)) {
		ret = error_at(err, -EISDIR, path, 0, "%s", strerror(EISDIR));
		goto out;
	}
	/* Files and pipes (`--replay <(...)`); never devices such as /dev/zero. */
	if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode)) {
		ret = error_at(err, -EINVAL, path, 0, "not a regular file or a pipe");
		goto out;
	}
	/* A pipe without a writer reads as empty now; one with a writer is waited for. */
	if (fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) < 0) {
		ret = error_at(err, -errno, path, 0, "%s", strerror(errno));
		goto out;
	}
	/* Refuse early, before reading it all only to throw it away. */
	if (S_ISREG(st.st_mode) && (uintmax_t)st.st_size > (uintmax_t)max) {
		ret = error_at(err, -EFBIG, path, 0, "file too large (%jd bytes, limit %zu MiB)",
			       (intmax_t)st.st_size, max >> 20);
		goto out;
	}
	for (;;) {
		ssize_t n;

		if (cap - have < 2) {
			size_t ncap = cap ? cap * 2 : 65536;
			char *p;

			if (cap > max + 1) {
				ret = error_at(err, -EFBIG, path, 0, "file too large (limit %zu MiB)", max >> 20);
				goto out;
			}
			p = realloc(buf, ncap);
			if (!p) {
				ret = error_at(err, -ENOMEM, path, 0, "out of memory");
				goto out;
			}
			buf = p;
			cap = ncap;
		}
		n = read(fd, buf + have, cap - have - 1);
		if (n < 0) {
			if (errno == EINTR)
				continue;
			ret = error_at(err, -errno, path, 0, "read failed: %s", strerror(errno));
			goto out;
		}
		if (n == 0)
			break;
		have += (size_t)n;
		if (have > max) {
			ret = error_at(err, -EFBIG, path, 0, "file too large (limit %zu MiB)", max >> 20);
			goto out;
		}
	}
	if (!buf) {
		buf = malloc(1);
		if (!buf) {
			ret = error_at(err, -ENOMEM, path, 0, "out of memory");
			goto out;
		}
	}
	buf[have] = '\0';
	*data = buf;
	*len = have;
	buf = NULL;
out:
	free(buf);
	close(fd);
	return ret;
}

int fileio_mkdirs(const char *dir, struct error *err)
{
	char path[PATH_MAX];
	size_t n = strlen(dir);

	if (n == 0 || n >= sizeof(path))
		return error_set(err, -ENAMETOOLONG, "%s: bad directory name", dir);
	memcpy(path, dir, n + 1);
	for (char *p = path + 1;; p++) {
		if (*p == '/' || *p == '\0') {
			char c = *p;

			*p = '\0';
			if (mkdir(path, 0755) < 0 && errno != EEXIST)
				return error_at(err, -errno, path, 0, "cannot create directory: %s",
						strerror(errno));
			*p = c;
			if (c == '\0')
				break;
		}
	}
	return 0;
}

static int write_all(int fd, const unsigned char *p, size_t len)
{
	while (len > 0) {
		ssize_t n = write(fd, p, len);

		if (n < 0) {
			if (errno == EINTR)
				continue;
			return -errno;
		}
		if (n == 0)
			return -EIO;
		p += n;
		len -= (size_t)n;
	}
	return 0;
}

int fileio_write_atomic_at(int dfd, const char *name, const void *data, size_t len,
			   struct error *err)
{
	char tmp[NAME_MAX + 1];
	int fd, ret;

	if (strchr(name, '/') || snprintf(tmp, sizeof(tmp), ".%s.tmp", name) >= (int)sizeof(tmp))
		return error_set(err, -EINVAL, "%s: bad file name", name);
	(void)unlinkat(dfd, tmp, 0); /* a leftover from an interrupted run */
	fd = openat(dfd, tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
	if (fd < 0)
		return error_set(err, -errno, "cannot create %s: %s", tmp, strerror(errno));
	ret = write_all(fd, data, len);
	if (ret == 0 && fsync(fd) < 0)
		ret = -errno;
	if (close(fd) < 0 && ret == 0)
		ret = -errno;
	if (ret < 0) {
		error_set(err, ret, "cannot write %s: %s", name, strerror(-ret));
		(void)unlinkat(dfd, tmp, 0);
		return ret;
	}
	/* rename replaces name, a symlink there included, and never follows it */
	if (renameat(dfd, tmp, dfd, name) < 0) {
		ret = error_set(err, -errno, "cannot rename %s to %s: %s", tmp, name,
				strerror(errno));
		(void)unlinkat(dfd, tmp, 0);
		return ret;
	}
	if (fsync(dfd) < 0)
		return error_set(err, -errno, "fsync failed: %s", strerror(errno));
	return 0;
}

int fileio_write_atomic(const char *dir, const char *name, const void *data, size_t len,
		      struct error *err)
{
	int dfd, ret;

	dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd < 0)
		return error_at(err, -errno, dir, 0, "%s", strerror(errno));
	ret = fileio_write_atomic_at(dfd, name, data, len, err);
	close(dfd);
	if (ret < 0) {
		struct error why = *err;

		/* "dir: ...", as before there was an fd-relative half */
		error_at(err, ret, dir, 0, "%s", why.msg);
	}
	return ret;
}

int fileio_opendir_at(int dfd, DIR **dir, struct error *err)
{
	int fd = openat(dfd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	int r;

	*dir = NULL;
	if (fd < 0)
		return error_set(err, -errno, "cannot open the directory: %s", strerror(errno));
	*dir = fdopendir(fd);
	if (!*dir) {
		r = -errno;
		close(fd);
		return error_set(err, r, "cannot list the directory: %s", strerror(-r));
	}
	return 0;
}
