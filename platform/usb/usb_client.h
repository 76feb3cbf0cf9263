/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The kiosk's side of the helper's protocol (usb_proto.h): one request, one answer, on a
 * new connection to the helper's socket. Blocking, within a time limit: called on the
 * USB export thread (usb_export.c), never on the kiosk's main loop.
 */
#include "error.h"
#include "usb_proto.h"

/*
 * Sends req to the helper listening at socket_path and waits at most timeout_ms for its
 * answer. 0 with *ans filled (ans->reason says whether the helper did it) and, for an ok
 * to mount, *dirfd the stick's edaha/ (close-on-exec); -errno when the helper cannot be
 * reached or answers nonsense (err says which).
 */
int usb_client_call(const char *socket_path, const struct usb_request *req, int timeout_ms,
		    struct usb_answer *ans, int *dirfd, struct error *err);
