/* SPDX-License-Identifier: MIT */
#include "usb_proto.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

static const char *const op_names[] = { [USB_OP_MOUNT] = "mount", [USB_OP_EJECT] = "eject" };

static const char *const reason_names[USB_REASON_COUNT] = {
	[USB_REASON_NONE] = "none",
	[USB_REASON_BAD_REQUEST] = "bad-request",
	[USB_REASON_DENIED] = "denied",
	[USB_REASON_NO_DEVICE] = "no-device",
	[USB_REASON_NOT_USB] = "not-usb",
	[USB_REASON_NOT_READY] = "not-ready",
	[USB_REASON_UNFORMATTED] = "unformatted",
	[USB_REASON_UNSUPPORTED] = "unsupported-filesystem",
	[USB_REASON_READ_ONLY] = "read-only",
	[USB_REASON_NOT_A_DIR] = "edaha-not-a-directory",
	[USB_REASON_NOT_WRITABLE] = "edaha-not-writable",
	[USB_REASON_MOUNT_FAILED] = "mount-failed",
	[USB_REASON_FULL] = "full",
	[USB_REASON_INTERNAL] = "internal",
};

bool usb_proto_kname_valid(const char *s)
{
	size_t n = 0;

	if (!s || s[0] < 'a' || s[0] > 'z')
		return false;
	for (; s[n]; n++)
		if (!((s[n] >= 'a' && s[n] <= 'z') || (s[n] >= '0' && s[n] <= '9')) ||
		    n + 1 >= USB_PROTO_KNAME_MAX)
			return false;
	return true;
}

const char *usb_op_name(enum usb_op op)
{
	return op == USB_OP_EJECT ? op_names[USB_OP_EJECT] : op_names[USB_OP_MOUNT];
}

const char *usb_reason_name(enum usb_reason r)
{
	return r >= 0 && r < USB_REASON_COUNT ? reason_names[r] : reason_names[USB_REASON_INTERNAL];
}

/* The line without its '\n'; -EINVAL for NUL bytes, a '\r', or bytes after the '\n'. */
static int one_line(const char *line, size_t len, size_t *n)
{
	if (len > 0 && line[len - 1] == '\n')
		len--;
	for (size_t i = 0; i < len; i++)
		if (line[i] == '\0' || line[i] == '\n' || line[i] == '\r')
			return -EINVAL;
	*n = len;
	return 0;
}

/* Whether line[0..n) starts with word and a space; advances past them. */
static bool word(const char **line, size_t *n, const char *w)
{
	size_t k = strlen(w);

	if (*n < k + 1 || memcmp(*line, w, k) != 0 || (*line)[k] != ' ')
		return false;
	*line += k + 1;
	*n -= k + 1;
	return true;
}

int usb_proto_parse_request(const char *line, size_t len, struct usb_request *req)
{
	size_t n;

	memset(req, 0, sizeof(*req));
	if (len >= USB_PROTO_LINE_MAX || one_line(line, len, &n) < 0)
		return -EINVAL;
	if (word(&line, &n, "mount"))
		req->op = USB_OP_MOUNT;
	else if (word(&line, &n, "eject"))
		req->op = USB_OP_EJECT;
	else
		return -EINVAL;
	if (n == 0 || n >= sizeof(req->kname))
		return -EINVAL;
	memcpy(req->kname, line, n);
	req->kname[n] = '\0';
	if (!usb_proto_kname_valid(req->kname)) {
		memset(req, 0, sizeof(*req));
		return -EINVAL;
	}
	return 0;
}

int usb_proto_format_request(const struct usb_request *req, char *out, size_t size)
{
	int n;

	if (!usb_proto_kname_valid(req->kname) || (req->op != USB_OP_MOUNT && req->op != USB_OP_EJECT))
		return -EINVAL;
	n = snprintf(out, size, "%s %s\n", usb_op_name(req->op), req->kname);
	return n < 0 || (size_t)n >= size ? -ENAMETOOLONG : 0;
}

static bool fstype_valid(const char *s, size_t n)
{
	if (n == 0 || n >= USB_PROTO_FSTYPE_MAX)
		return false;
	for (size_t i = 0; i < n; i++)
		if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= '0' && s[i] <= '9')))
			return false;
	return true;
}

int usb_proto_parse_answer(const char *line, size_t len, struct usb_answer *ans)
{
	size_t n, k;

	memset(ans, 0, sizeof(*ans));
	if (len > USB_PROTO_LINE_MAX || one_line(line, len, &n) < 0)
		return -EINVAL;
	if (n == 2 && memcmp(line, "ok", 2) == 0)
		return 0;
	if (word(&line, &n, "ok")) {
		if (!fstype_valid(line, n))
			return -EINVAL;
		memcpy(ans->fstype, line, n);
		return 0;
	}
	if (!word(&line, &n, "error"))
		return -EINVAL;
	for (k = 0; k < n && line[k] != ' '; k++)
		;
	ans->reason = USB_REASON_INTERNAL;
	for (int r = USB_REASON_BAD_REQUEST; r < USB_REASON_COUNT; r++)
		if (strlen(reason_names[r]) == k && memcmp(line, reason_names[r], k) == 0)
			ans->reason = (enum usb_reason)r;
	if (k == 0)
		return -EINVAL;
	if (k < n) {
		size_t t = n - k - 1 < sizeof(ans->text) - 1 ? n - k - 1 : sizeof(ans->text) - 1;

		memcpy(ans->text, line + k + 1, t);
		ans->text[t] = '\0';
	}
	return 0;
}

int usb_proto_format_answer(const struct usb_answer *ans, char *out, size_t size)
{
	char text[USB_PROTO_LINE_MAX / 2];
	size_t i;
	int n;

	if (ans->reason == USB_REASON_NONE) {
		if (ans->fstype[0] && !fstype_valid(ans->fstype, strlen(ans->fstype)))
			return -EINVAL;
		n = snprintf(out, size, ans->fstype[0] ? "ok %s\n" : "ok\n", ans->fstype);
	} else {
		/* the text may hold what a stick calls itself: one printable line */
		for (i = 0; ans->text[i] && i < sizeof(text) - 1; i++)
			text[i] = (unsigned char)ans->text[i] < 0x20 || ans->text[i] == 0x7f
					  ? '?' : ans->text[i];
		text[i] = '\0';
		n = snprintf(out, size, "error %s %s\n", usb_reason_name(ans->reason),
			     text[0] ? text : "-");
	}
	return n < 0 || (size_t)n >= size ? -ENAMETOOLONG : 0;
}

enum usb_outcome usb_outcome_of(enum usb_reason reason, int err, bool still_there)
{
	/* whatever failed, a stick that is gone was pulled: that is what to tell */
	if (!still_there && (reason != USB_REASON_NONE || err != 0))
		return USB_OUTCOME_PULLED;
	switch (reason) {
	case USB_REASON_NONE:
		break;
	case USB_REASON_NO_DEVICE:
		return USB_OUTCOME_PULLED;
	case USB_REASON_READ_ONLY:
		return USB_OUTCOME_READ_ONLY;
	case USB_REASON_FULL:
		return USB_OUTCOME_FULL;
	case USB_REASON_NOT_USB:
	case USB_REASON_UNFORMATTED:
	case USB_REASON_UNSUPPORTED:
	case USB_REASON_NOT_A_DIR:
	case USB_REASON_NOT_WRITABLE:
	case USB_REASON_MOUNT_FAILED:
		return USB_OUTCOME_UNUSABLE;
	default:
		return USB_OUTCOME_FAILED;
	}
	switch (err) {
	case 0:
		return USB_OUTCOME_OK;
	case -ENOSPC:
	case -EDQUOT:
	case -EFBIG: /* FAT's 4 GiB a file, or a file size limit */
		return USB_OUTCOME_FULL;
	case -EROFS: /* gone read-only under us: the filesystem found damage */
		return USB_OUTCOME_READ_ONLY;
	case -EACCES:
	case -EPERM:
		return USB_OUTCOME_UNUSABLE;
	default:
		return USB_OUTCOME_FAILED;
	}
}

const char *usb_outcome_name(enum usb_outcome o)
{
	switch (o) {
	case USB_OUTCOME_OK:
		return "ok";
	case USB_OUTCOME_PULLED:
		return "pulled";
	case USB_OUTCOME_FULL:
		return "full";
	case USB_OUTCOME_READ_ONLY:
		return "read-only";
	case USB_OUTCOME_UNUSABLE:
		return "unusable";
	case USB_OUTCOME_FAILED:
		break;
	}
	return "failed";
}
