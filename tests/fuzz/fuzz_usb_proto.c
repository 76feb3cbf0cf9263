/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the USB helper's line protocol on arbitrary bytes. edaha-usb-helper runs as
 * root and parses what an unprivileged peer sends: a request it accepts must name a
 * valid kernel name (no '/', no "..") and format back to the same request; an answer
 * the kiosk accepts must format and parse back to the same.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "usb_proto.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct usb_request req, again;
	struct usb_answer ans, ans2;
	char line[USB_PROTO_LINE_MAX];

	if (usb_proto_parse_request((const char *)data, size, &req) == 0) {
		if (!usb_proto_kname_valid(req.kname) || strchr(req.kname, '/') ||
		    strstr(req.kname, "..") || (req.op != USB_OP_MOUNT && req.op != USB_OP_EJECT))
			abort();
		if (usb_proto_format_request(&req, line, sizeof(line)) < 0 ||
		    usb_proto_parse_request(line, strlen(line), &again) < 0 ||
		    memcmp(&req, &again, sizeof(req)) != 0)
			abort();
	}
	if (usb_proto_parse_answer((const char *)data, size, &ans) == 0) {
		if (ans.reason < USB_REASON_NONE || ans.reason >= USB_REASON_COUNT ||
		    !memchr(ans.text, '\0', sizeof(ans.text)) ||
		    !memchr(ans.fstype, '\0', sizeof(ans.fstype)))
			abort();
		if (usb_proto_format_answer(&ans, line, sizeof(line)) < 0 ||
		    usb_proto_parse_answer(line, strlen(line), &ans2) < 0 ||
		    ans2.reason != ans.reason || strcmp(ans2.fstype, ans.fstype) != 0)
			abort();
	}
	return 0;
}
