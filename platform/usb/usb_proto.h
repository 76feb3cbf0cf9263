/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The line protocol between the kiosk and edaha-usb-helper, over a unix stream socket
 * (/run/edaha/usb.sock): one request line, one answer line, per connection.
 *
 *   mount KNAME    ->  ok FSTYPE              + edaha/'s directory fd (SCM_RIGHTS)
 *   eject KNAME    ->  ok
 *   either         ->  error REASON TEXT      (REASON one of usb_reason_name's)
 *
 * KNAME is a block device's kernel name (sda1, sdb): 1..31 of [a-z0-9], a letter first.
 * Pure: parsing and formatting only; the helper parses requests from an unprivileged
 * peer, so the parser takes any bytes (tests/fuzz/fuzz_usb_proto.c).
 */
#include <stdbool.h>
#include <stddef.h>

#define USB_PROTO_LINE_MAX 256 /* an answer line, with its text; a request is shorter */
#define USB_PROTO_KNAME_MAX 32 /* with the NUL */
#define USB_PROTO_FSTYPE_MAX 16

enum usb_op { USB_OP_MOUNT = 0, USB_OP_EJECT };

/* Why the helper refused; the kiosk tells the visitor by it (usb_outcome_of). */
enum usb_reason {
	USB_REASON_NONE = 0,
	USB_REASON_BAD_REQUEST,   /* bad-request: not a request line */
	USB_REASON_DENIED,        /* denied: the peer is neither root nor the kiosk's user */
	USB_REASON_NO_DEVICE,     /* no-device: no such block device (pulled) */
	USB_REASON_NOT_USB,       /* not-usb: not on the USB bus */
	USB_REASON_NOT_READY,     /* not-ready: udev has not looked at it yet */
	USB_REASON_UNFORMATTED,   /* unformatted: no filesystem udev knows */
	USB_REASON_UNSUPPORTED,   /* unsupported-filesystem: not vfat, exfat or ext4 */
	USB_REASON_READ_ONLY,     /* read-only: write-protected, or mounting rw refused */
	USB_REASON_NOT_A_DIR,     /* edaha-not-a-directory: a file or symlink named edaha */
	USB_REASON_NOT_WRITABLE,  /* edaha-not-writable: ext4, edaha/ someone else's */
	USB_REASON_MOUNT_FAILED,  /* mount-failed: the kernel refused (a damaged filesystem) */
	USB_REASON_FULL,          /* full: no room even for edaha/ */
	USB_REASON_INTERNAL,      /* internal: anything else */
	USB_REASON_COUNT,
};

struct usb_request {
	enum usb_op op;
	char kname[USB_PROTO_KNAME_MAX];
};

struct usb_answer {
	enum usb_reason reason; /* NONE: ok */
	char fstype[USB_PROTO_FSTYPE_MAX]; /* of an ok to mount, "" otherwise */
	char text[USB_PROTO_LINE_MAX];     /* of an error */
};

/* Whether s is a kernel name the helper takes. */
bool usb_proto_kname_valid(const char *s);
/* "mount" / "eject", and the reasons' words ("read-only"). */
const char *usb_op_name(enum usb_op op);
const char *usb_reason_name(enum usb_reason r);

/* One request line (its '\n' optional, nothing after it). 0 or -EINVAL. */
int usb_proto_parse_request(const char *line, size_t len, struct usb_request *req);
/* "mount sda1\n". 0 or -EINVAL (a bad kname) / -ENAMETOOLONG. */
int usb_proto_format_request(const struct usb_request *req, char *out, size_t size);
/* One answer line. 0 or -EINVAL. An unknown reason word is USB_REASON_INTERNAL. */
int usb_proto_parse_answer(const char *line, size_t len, struct usb_answer *ans);
/* "ok vfat\n" or "error read-only TEXT\n" (TEXT cut to fit, control bytes as '?'). */
int usb_proto_format_answer(const struct usb_answer *ans, char *out, size_t size);

/*
 * What became of an export or a look at a stick, as the kiosk tells the visitor: from
 * the helper's reason, or the errno of writing (ENOSPC: full), and whether the stick
 * was still there afterwards.
 */
enum usb_outcome {
	USB_OUTCOME_OK = 0,
	USB_OUTCOME_PULLED,    /* the stick went during it */
	USB_OUTCOME_FULL,      /* no room */
	USB_OUTCOME_READ_ONLY, /* locked */
	USB_OUTCOME_UNUSABLE,  /* unformatted, unsupported, a hostile layout */
	USB_OUTCOME_FAILED,    /* anything else: the helper missing, a damaged stick */
};

enum usb_outcome usb_outcome_of(enum usb_reason reason, int err, bool still_there);
const char *usb_outcome_name(enum usb_outcome o);
