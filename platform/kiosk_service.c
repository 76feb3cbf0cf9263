/* SPDX-License-Identifier: MIT */
/* The kiosk as a service: SIGINT and SIGTERM stop the loop (through a signalfd in its
 * poll), and the loop pings systemd's watchdog from a timer of its own. */
#include "kiosk_private.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/signalfd.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "notify.h"

int kiosk_open_signals(struct kiosk *k)
{
	sigset_t mask;

	/* blocked before the display opens: GL driver threads inherit the mask, so the
	 * signals wait for our signalfd instead of landing in a random thread */
	sigemptyset(&mask);
	sigaddset(&mask, SIGINT);
	sigaddset(&mask, SIGTERM);
	if (sigprocmask(SIG_BLOCK, &mask, &k->old_mask) < 0)
		return -errno;
	k->mask_set = true;
	k->signal_fd = signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);
	return k->signal_fd < 0 ? -errno : 0;
}

/* A periodic timer at half the service's WatchdogSec=: each expiry the loop is still
 * turning pings systemd; a loop stuck anywhere stops the pings and gets restarted. */
int kiosk_open_watchdog(struct kiosk *k)
{
	uint64_t us = notify_watchdog_interval_us();
	struct itimerspec it;

	if (!us)
		return 0;
	k->watchdog_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
	if (k->watchdog_fd < 0)
		return -errno;
	it.it_value = (struct timespec){ (time_t)(us / 1000000u), (long)(us % 1000000u) * 1000 };
	it.it_interval = it.it_value;
	if (timerfd_settime(k->watchdog_fd, 0, &it, NULL) < 0)
		return -errno;
	fprintf(stderr, "edaha: watchdog: the loop checks in every %.1f s\n", (double)us / 1e6);
	return 0;
}

void kiosk_on_signal(struct kiosk *k)
{
	struct signalfd_siginfo si;

	if (read(k->signal_fd, &si, sizeof(si)) == (ssize_t)sizeof(si))
		fprintf(stderr, "edaha: %s, stopping\n", strsignal((int)si.ssi_signo));
	k->quit = true;
}

void kiosk_on_watchdog(struct kiosk *k)
{
	uint64_t expirations;

	if (read(k->watchdog_fd, &expirations, sizeof(expirations)) == (ssize_t)sizeof(expirations))
		notify_watchdog();
}
