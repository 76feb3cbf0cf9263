/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

/*
 * Tells the service manager how the kiosk is (sd_notify(3)): ready once its first frame
 * is on screen, alive while its main loop turns, stopping. Outside systemd (no
 * NOTIFY_SOCKET) each call does nothing, so the kiosk runs the same from a shell.
 */

void notify_ready(void);
void notify_stopping(void);
/* How often the main loop must call notify_watchdog(), in microseconds: half the
 * service's WatchdogSec=; 0 when no watchdog is asked for. */
uint64_t notify_watchdog_interval_us(void);
void notify_watchdog(void);
