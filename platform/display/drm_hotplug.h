/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Tells when a display may have been plugged or unplugged: a udev monitor on the "drm"
 * subsystem, reporting change uevents of one card. The kernel sends one with HOTPLUG=1
 * when a connector's status changes; edaha re-probes on any change event of its card
 * (they are rare, and a synthetic one, `udevadm trigger --action=change`, then makes it
 * look). Events come through udevd when it runs, else straight from the kernel.
 */
#include <sys/types.h>

#include "error.h"

struct drm_hotplug;

/* card: the device number of the card's node (st_rdev). NULL with why in err. */
struct drm_hotplug *drm_hotplug_create(dev_t card, struct error *err);
void drm_hotplug_destroy(struct drm_hotplug *h);
int drm_hotplug_fd(const struct drm_hotplug *h);
/* Reads what the monitor has: 1 when the card changed, 0 when not; never blocks. */
int drm_hotplug_dispatch(struct drm_hotplug *h);
