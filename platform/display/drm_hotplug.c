/* SPDX-License-Identifier: MIT */
#include "drm_hotplug.h"

#include <errno.h>
#include <libudev.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct drm_hotplug {
	struct udev *udev;
	struct udev_monitor *mon;
	dev_t card;
};

struct drm_hotplug *drm_hotplug_create(dev_t card, struct error *err)
{
	struct drm_hotplug *h = calloc(1, sizeof(*h));
	/* udevd's events come after its rules ran; without udevd only the kernel's come */
	const char *source = access("/run/udev/control", F_OK) == 0 ? "udev" : "kernel";

	if (!h) {
		error_set(err, -ENOMEM, "hotplug: out of memory");
		return NULL;
	}
	h->card = card;
	h->udev = udev_new();
	if (!h->udev) {
		error_set(err, -ENOMEM, "hotplug: no udev context");
		goto fail;
	}
	h->mon = udev_monitor_new_from_netlink(h->udev, source);
	if (!h->mon) {
		error_set(err, -ENODEV, "hotplug: no %s monitor: %s", source, strerror(errno));
		goto fail;
	}
	if (udev_monitor_filter_add_match_subsystem_devtype(h->mon, "drm", "drm_minor") < 0 ||
	    udev_monitor_enable_receiving(h->mon) < 0) {
		error_set(err, -ENODEV, "hotplug: cannot listen for drm events");
		goto fail;
	}
	return h;

fail:
	drm_hotplug_destroy(h);
	return NULL;
}

void drm_hotplug_destroy(struct drm_hotplug *h)
{
	if (!h)
		return;
	udev_monitor_unref(h->mon);
	udev_unref(h->udev);
	free(h);
}

int drm_hotplug_fd(const struct drm_hotplug *h)
{
	return udev_monitor_get_fd(h->mon);
}

int drm_hotplug_dispatch(struct drm_hotplug *h)
{
	struct udev_device *dev;
	int changed = 0;

	/* the monitor's socket is non-blocking: NULL when it is empty */
	while ((dev = udev_monitor_receive_device(h->mon))) {
		const char *action = udev_device_get_action(dev);

		if (action && strcmp(action, "change") == 0 && udev_device_get_devnum(dev) == h->card)
			changed = 1;
		udev_device_unref(dev);
	}
	return changed;
}
