/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Something the kiosk loop waits on besides the display: a libinput context, a GPIO
 * chip, a hotplug monitor. The loop puts every source's fd into its one poll() and calls
 * dispatch(data) when the fd is readable; dispatch reads what is there without blocking
 * and feeds the events it makes to the app (kiosk_feed). It returns 0, or a negative
 * errno when the source is broken for good: the loop then stops polling that source,
 * says so on stderr and keeps running (a kiosk without its tablet still shows the tree).
 */
struct kiosk_source {
	int fd;
	int (*dispatch)(void *data);
	void *data;
};
