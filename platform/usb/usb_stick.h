/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What edaha-usb-helper decides about a stick, apart from the mounting itself (so that
 * it is tested without root or a stick): whether udev's view of the device is one to
 * mount, the mount's options, what a failed mount means, and opening edaha/ on it.
 */
#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

#include "usb_proto.h"

/* udev's view of a block device (properties of its database entry, sysfs). */
struct usb_stick_info {
	bool on_usb;      /* a usb_device among its parents */
	bool initialized; /* udev has processed it (its properties are there) */
	bool read_only;   /* sysfs "ro": a write-protect switch */
	const char *fs_type;    /* ID_FS_TYPE, NULL or "" when none */
	const char *part_table; /* ID_PART_TABLE_TYPE of a whole disk, NULL when none */
};

/* USB_REASON_NONE when it is one to mount; else why not, with text for the journal. */
enum usb_reason usb_stick_check(const struct usb_stick_info *info, char *text, size_t size);
/* The mount's filesystem type (the kernel's name) and data for a checked fs_type, with
 * the files the peer's (uid, gid) on filesystems without owners. 0 or -EINVAL. */
int usb_stick_mount_data(const char *fs_type, uid_t uid, gid_t gid, const char **type,
			 char *data, size_t size);
/* The mount flags: nosuid, nodev, noexec, noatime, nosymfollow. */
unsigned long usb_stick_mount_flags(void);
/* The reason for mount(2)'s errno. */
enum usb_reason usb_stick_mount_reason(int err);
/*
 * Opens edaha/ in the stick's root directory rootfd (O_DIRECTORY | O_NOFOLLOW), making it
 * when missing; on a filesystem with owners (owners) a new one is made the peer's, an
 * old one must be writable by it. A file or a symlink named edaha is refused
 * (USB_REASON_NOT_A_DIR), as is a read-only filesystem (USB_REASON_READ_ONLY).
 * USB_REASON_NONE and *dirfd, or a reason with text.
 */
enum usb_reason usb_stick_open_edaha(int rootfd, bool owners, uid_t uid, gid_t gid, int *dirfd,
				     char *text, size_t size);
