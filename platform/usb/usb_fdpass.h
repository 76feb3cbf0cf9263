/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The helper's half of passing a stick's edaha/ to the kiosk: an answer line on the
 * connection, with the directory's fd beside it (SCM_RIGHTS). The kiosk's half is
 * usb_client.c.
 */

/* Sends line, with fd when it is not -1. 0, or -errno (a short write is -EIO). */
int usb_fdpass_send(int sock, const char *line, int fd);
