/* SPDX-License-Identifier: MIT */
#include "notify.h"

#include <stdio.h>
#include <string.h>

#include "config.h"

#if HAVE_SYSTEMD
#include <systemd/sd-daemon.h>

static void notify_send(const char *state)
{
	int ret = sd_notify(0, state);

	/* 0: not under a service manager that listens; only a failure is worth a line */
	if (ret < 0)
		fprintf(stderr, "edaha: cannot tell systemd %s: %s\n", state, strerror(-ret));
}

void notify_ready(void)
{
	notify_send("READY=1");
}

void notify_stopping(void)
{
	notify_send("STOPPING=1");
}

uint64_t notify_watchdog_interval_us(void)
{
	uint64_t usec = 0;

	/* pinging at half the timeout leaves a whole slow frame of margin */
	if (sd_watchdog_enabled(0, &usec) <= 0)
		return 0;
	return usec / 2 ? usec / 2 : 1;
}

void notify_watchdog(void)
{
	notify_send("WATCHDOG=1");
}
#else
void notify_ready(void)
{
}

void notify_stopping(void)
{
}

uint64_t notify_watchdog_interval_us(void)
{
	return 0;
}

void notify_watchdog(void)
{
}
#endif
