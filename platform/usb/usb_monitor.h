/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * USB sticks coming and going, from udev (the "udev" netlink group: events after udevd's
 * rules ran, so its blkid and usb_id properties are there). A stick is a partition on
 * the USB bus, or a whole USB disk without a partition table (a "superfloppy" FAT stick,
 * or an unformatted one). Its fd joins the kiosk's poll.
 */
#include <stdbool.h>

#include "error.h"
#include "usb_proto.h"

enum usb_monitor_action { USB_MONITOR_ADDED, USB_MONITOR_REMOVED };

struct usb_monitor_event {
	enum usb_monitor_action action;
	char kname[USB_PROTO_KNAME_MAX];
};

typedef void (*usb_monitor_fn)(void *data, const struct usb_monitor_event *ev);

struct usb_monitor;

/* NULL with a message when udev cannot be listened to (no udevd: no sticks). */
struct usb_monitor *usb_monitor_create(struct error *err);
void usb_monitor_destroy(struct usb_monitor *m);
int usb_monitor_fd(const struct usb_monitor *m);
/* The sticks already there, each as an ADDED. 0 or -errno. */
int usb_monitor_enumerate(struct usb_monitor *m, usb_monitor_fn fn, void *data);
/* The events waiting (non-blocking). REMOVED comes for every block device that goes (the
 * kiosk knows which are its sticks); "change" comes as ADDED (a card reader's medium
 * put in; one already known is ignored there). 0 or -errno. */
int usb_monitor_dispatch(struct usb_monitor *m, usb_monitor_fn fn, void *data);

/* Whether a block device is a stick by these properties (devtype "disk" or
 * "partition"; ID_FS_TYPE and ID_PART_TABLE_TYPE, NULL when none; sysfs size in
 * sectors). A whole disk is one when it has no partition table or a filesystem of its
 * own: an exFAT superfloppy's boot sector reads as an (empty) DOS table too. */
bool usb_monitor_is_stick(const char *devtype, bool on_usb, const char *fs_type,
			  const char *part_table, unsigned long long size);
