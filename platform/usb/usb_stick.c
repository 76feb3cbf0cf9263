/* SPDX-License-Identifier: MIT */
#include "usb_stick.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

enum usb_reason usb_stick_check(const struct usb_stick_info *info, char *text, size_t size)
{
	const char *fs = info->fs_type;

	text[0] = '\0';
	if (!info->on_usb) {
		snprintf(text, size, "not on the USB bus");
		return USB_REASON_NOT_USB;
	}
	if (!info->initialized) {
		snprintf(text, size, "udev has not probed it yet");
		return USB_REASON_NOT_READY;
	}
	if (!fs || !*fs) {
		snprintf(text, size, info->part_table ? "a %s partition table, no filesystem on the disk itself"
						      : "no filesystem",
			 info->part_table);
		return USB_REASON_UNFORMATTED;
	}
	if (strcmp(fs, "vfat") != 0 && strcmp(fs, "exfat") != 0 && strcmp(fs, "ext4") != 0) {
		snprintf(text, size, "%.40s (vfat, exfat or ext4 are used)", fs);
		return USB_REASON_UNSUPPORTED;
	}
	if (info->read_only) {
		snprintf(text, size, "write-protected");
		return USB_REASON_READ_ONLY;
	}
	return USB_REASON_NONE;
}

int usb_stick_mount_data(const char *fs_type, uid_t uid, gid_t gid, const char **type,
			 char *data, size_t size)
{
	int n;

	/* FAT and exFAT have no owners: the mount gives every file to the kiosk's user,
	 * to it alone. utf8 names; vfat's flush writes back early, as a stick may go. */
	if (strcmp(fs_type, "vfat") == 0)
		n = snprintf(data, size, "uid=%u,gid=%u,fmask=0177,dmask=0077,shortname=mixed,utf8,flush",
			     (unsigned)uid, (unsigned)gid);
	else if (strcmp(fs_type, "exfat") == 0)
		n = snprintf(data, size, "uid=%u,gid=%u,fmask=0177,dmask=0077,iocharset=utf8",
			     (unsigned)uid, (unsigned)gid);
	else if (strcmp(fs_type, "ext4") == 0)
		n = snprintf(data, size, "%s", "");
	else
		return -EINVAL;
	*type = fs_type;
	return n < 0 || (size_t)n >= size ? -EINVAL : 0;
}

unsigned long usb_stick_mount_flags(void)
{
	return MS_NOSUID | MS_NODEV | MS_NOEXEC | MS_NOATIME | MS_NOSYMFOLLOW;
}

enum usb_reason usb_stick_mount_reason(int err)
{
	switch (err) {
	case EROFS:
	case EACCES: /* a write-protected device opened for writing */
		return USB_REASON_READ_ONLY;
	case ENXIO:
	case ENODEV:
	case ENOENT:
	case ENOTBLK:
		return USB_REASON_NO_DEVICE;
	default:
		return USB_REASON_MOUNT_FAILED;
	}
}

/* Whether (uid, gid) may make files in a directory with st's owner and mode. */
static bool writable_by(const struct stat *st, uid_t uid, gid_t gid)
{
	if (uid == 0)
		return true;
	if (st->st_uid == uid)
		return (st->st_mode & S_IWUSR) && (st->st_mode & S_IXUSR);
	if (st->st_gid == gid)
		return (st->st_mode & S_IWGRP) && (st->st_mode & S_IXGRP);
	return (st->st_mode & S_IWOTH) && (st->st_mode & S_IXOTH);
}

enum usb_reason usb_stick_open_edaha(int rootfd, bool owners, uid_t uid, gid_t gid, int *dirfd,
				     char *text, size_t size)
{
	const int flags = O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC;
	struct stat st;
	int fd;

	*dirfd = -1;
	text[0] = '\0';
	fd = openat(rootfd, "edaha", flags);
	if (fd < 0 && errno == ENOENT) {
		if (mkdirat(rootfd, "edaha", 0755) < 0 && errno != EEXIST) {
			int e = errno;

			snprintf(text, size, "cannot make edaha/: %s", strerror(e));
			if (e == EROFS)
				return USB_REASON_READ_ONLY;
			return e == ENOSPC ? USB_REASON_FULL : USB_REASON_INTERNAL;
		}
		/* ours now: the kiosk's user may write in it */
		if (owners && fchownat(rootfd, "edaha", uid, gid, AT_SYMLINK_NOFOLLOW) < 0) {
			snprintf(text, size, "cannot give edaha/ to uid %u: %s", (unsigned)uid,
				 strerror(errno));
			return USB_REASON_INTERNAL;
		}
		fd = openat(rootfd, "edaha", flags);
	}
	if (fd < 0) {
		int e = errno;

		/* a symlink (ELOOP) or a file (ENOTDIR) in its place: not followed, not touched */
		snprintf(text, size, "edaha is not a directory: %s", strerror(e));
		return e == ELOOP || e == ENOTDIR ? USB_REASON_NOT_A_DIR : USB_REASON_INTERNAL;
	}
	if (fstat(fd, &st) < 0 || !S_ISDIR(st.st_mode)) {
		snprintf(text, size, "edaha is not a directory");
		close(fd);
		return USB_REASON_NOT_A_DIR;
	}
	if (owners && !writable_by(&st, uid, gid)) {
		snprintf(text, size, "edaha/ belongs to uid %u, mode %03o", (unsigned)st.st_uid,
			 (unsigned)(st.st_mode & 0777));
		close(fd);
		return USB_REASON_NOT_WRITABLE;
	}
	*dirfd = fd;
	return USB_REASON_NONE;
}
