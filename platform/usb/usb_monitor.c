/* SPDX-License-Identifier: MIT */
#include "usb_monitor.h"

#include <errno.h>
#include <libudev.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct usb_monitor {
	struct udev *udev;
	struct udev_monitor *mon;
};

bool usb_monitor_is_stick(const char *devtype, bool on_usb, const char *fs_type,
			  const char *part_table, unsigned long long size)
{
	/* no medium (an empty card reader) is nothing to mount */
	if (!on_usb || !devtype || size == 0)
		return false;
	if (strcmp(devtype, "partition") == 0)
		return true;
	/* a disk with partitions and no filesystem of its own: they come on their own */
	return strcmp(devtype, "disk") == 0 &&
	       ((fs_type && *fs_type) || !part_table || !*part_table);
}

static bool is_stick(struct udev_device *dev)
{
	const char *size = udev_device_get_sysattr_value(dev, "size");
	bool usb = udev_device_get_parent_with_subsystem_devtype(dev, "usb", "usb_device") != NULL;

	return usb_proto_kname_valid(udev_device_get_sysname(dev)) &&
	       usb_monitor_is_stick(udev_device_get_devtype(dev), usb,
				    udev_device_get_property_value(dev, "ID_FS_TYPE"),
				    udev_device_get_property_value(dev, "ID_PART_TABLE_TYPE"),
				    size ? strtoull(size, NULL, 10) : 0);
}

static void emit(struct udev_device *dev, enum usb_monitor_action action, usb_monitor_fn fn,
		 void *data)
{
	struct usb_monitor_event ev = { .action = action };
	const char *name = udev_device_get_sysname(dev);

	if (!usb_proto_kname_valid(name))
		return;
	snprintf(ev.kname, sizeof(ev.kname), "%s", name);
	fn(data, &ev);
}

struct usb_monitor *usb_monitor_create(struct error *err)
{
	struct usb_monitor *m = calloc(1, sizeof(*m));

	if (!m) {
		error_set(err, -ENOMEM, "usb: out of memory");
		return NULL;
	}
	/* the kernel's own events lack the filesystem udev's blkid finds */
	if (access("/run/udev/control", F_OK) < 0) {
		error_set(err, -ENODEV, "usb: no udevd running, so no sticks are seen");
		goto fail;
	}
	m->udev = udev_new();
	if (!m->udev) {
		error_set(err, -ENOMEM, "usb: no udev context");
		goto fail;
	}
	m->mon = udev_monitor_new_from_netlink(m->udev, "udev");
	if (!m->mon) {
		error_set(err, -ENODEV, "usb: no udev monitor: %s", strerror(errno));
		goto fail;
	}
	if (udev_monitor_filter_add_match_subsystem_devtype(m->mon, "block", NULL) < 0 ||
	    udev_monitor_enable_receiving(m->mon) < 0) {
		error_set(err, -ENODEV, "usb: cannot listen for block devices");
		goto fail;
	}
	return m;

fail:
	usb_monitor_destroy(m);
	return NULL;
}

void usb_monitor_destroy(struct usb_monitor *m)
{
	if (!m)
		return;
	udev_monitor_unref(m->mon);
	udev_unref(m->udev);
	free(m);
}

int usb_monitor_fd(const struct usb_monitor *m)
{
	return udev_monitor_get_fd(m->mon);
}

int usb_monitor_enumerate(struct usb_monitor *m, usb_monitor_fn fn, void *data)
{
	struct udev_enumerate *e = udev_enumerate_new(m->udev);
	struct udev_list_entry *entry;
	int r;

	if (!e)
		return -ENOMEM;
	r = udev_enumerate_add_match_subsystem(e, "block");
	if (r >= 0)
		r = udev_enumerate_scan_devices(e);
	if (r < 0) {
		udev_enumerate_unref(e);
		return r;
	}
	udev_list_entry_foreach(entry, udev_enumerate_get_list_entry(e))
	{
		struct udev_device *dev =
			udev_device_new_from_syspath(m->udev, udev_list_entry_get_name(entry));

		if (!dev)
			continue;
		if (is_stick(dev))
			emit(dev, USB_MONITOR_ADDED, fn, data);
		udev_device_unref(dev);
	}
	udev_enumerate_unref(e);
	return 0;
}

int usb_monitor_dispatch(struct usb_monitor *m, usb_monitor_fn fn, void *data)
{
	struct udev_device *dev;

	/* the monitor's socket is non-blocking: NULL when it is empty */
	while ((dev = udev_monitor_receive_device(m->mon))) {
		const char *action = udev_device_get_action(dev);

		/* gone from sysfs: nothing to ask it any more, the kiosk matches the name */
		if (action && strcmp(action, "remove") == 0)
			emit(dev, USB_MONITOR_REMOVED, fn, data);
		else if (action && (strcmp(action, "add") == 0 || strcmp(action, "change") == 0) &&
			 is_stick(dev))
			emit(dev, USB_MONITOR_ADDED, fn, data);
		udev_device_unref(dev);
	}
	return 0;
}
