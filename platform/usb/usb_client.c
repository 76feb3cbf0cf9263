/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* MSG_CMSG_CLOEXEC */
#include "usb_client.h"

#include <errno.h>
#include <poll.h>
#include <stdint.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

static int64_t now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/* Takes the fds a message carried: the first one into *fd (if none yet), others closed. */
static void take_fds(struct msghdr *msg, int *fd)
{
	for (struct cmsghdr *c = CMSG_FIRSTHDR(msg); c; c = CMSG_NXTHDR(msg, c)) {
		size_t n;

		if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_RIGHTS)
			continue;
		n = (c->cmsg_len - CMSG_LEN(0)) / sizeof(int);
		for (size_t i = 0; i < n; i++) {
			int f;

			memcpy(&f, CMSG_DATA(c) + i * sizeof(int), sizeof(int));
			if (*fd < 0)
				*fd = f;
			else
				close(f);
		}
	}
}

static int converse(int s, const char *line, int64_t deadline, struct usb_answer *ans,
		    int *fd, struct error *err)
{
	char in[USB_PROTO_LINE_MAX + 1];
	size_t have = 0, len = strlen(line);

	if (send(s, line, len, MSG_NOSIGNAL) != (ssize_t)len)
		return error_set(err, -errno, "cannot send to the helper: %s", strerror(errno));
	while (have < sizeof(in) - 1) {
		union {
			struct cmsghdr h;
			char buf[CMSG_SPACE(4 * sizeof(int))];
		} cmsg;
		struct iovec iov = { in + have, sizeof(in) - 1 - have };
		struct msghdr msg = { .msg_iov = &iov, .msg_iovlen = 1, .msg_control = cmsg.buf,
				      .msg_controllen = sizeof(cmsg.buf) };
		struct pollfd p = { .fd = s, .events = POLLIN };
		int64_t left = deadline - now_ms();
		ssize_t n;
		int ret;

		if (left <= 0)
			return error_set(err, -ETIMEDOUT, "the helper did not answer in time");
		ret = poll(&p, 1, (int)left);
		if (ret < 0 && errno == EINTR)
			continue;
		if (ret < 0)
			return error_set(err, -errno, "poll: %s", strerror(errno));
		if (ret == 0)
			continue;
		n = recvmsg(s, &msg, MSG_CMSG_CLOEXEC);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			return error_set(err, -errno, "cannot read the helper's answer: %s",
					 strerror(errno));
		take_fds(&msg, fd);
		if (n == 0)
			break;
		have += (size_t)n;
		if (memchr(in, '\n', have))
			break;
	}
	if (usb_proto_parse_answer(in, have, ans) < 0)
		return error_set(err, -EPROTO, "the helper's answer makes no sense");
	return 0;
}

int usb_client_call(const char *socket_path, const struct usb_request *req, int timeout_ms,
		    struct usb_answer *ans, int *dirfd, struct error *err)
{
	struct sockaddr_un addr = { .sun_family = AF_UNIX };
	char line[USB_PROTO_LINE_MAX];
	int64_t deadline = now_ms() + timeout_ms;
	int s, fd = -1, ret;

	*dirfd = -1;
	memset(ans, 0, sizeof(*ans));
	if (usb_proto_format_request(req, line, sizeof(line)) < 0)
		return error_set(err, -EINVAL, "bad device name");
	if (strlen(socket_path) >= sizeof(addr.sun_path))
		return error_set(err, -ENAMETOOLONG, "%s: name too long", socket_path);
	memcpy(addr.sun_path, socket_path, strlen(socket_path) + 1);
	s = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	if (s < 0)
		return error_set(err, -errno, "socket: %s", strerror(errno));
	if (connect(s, (struct sockaddr *)&addr, sizeof(addr)) < 0) {
		ret = error_set(err, -errno, "cannot reach the USB helper at %s: %s", socket_path,
				strerror(errno));
		close(s);
		return ret;
	}
	ret = converse(s, line, deadline, ans, &fd, err);
	close(s);
	if (ret == 0 && req->op == USB_OP_MOUNT && ans->reason == USB_REASON_NONE && fd < 0)
		ret = error_set(err, -EPROTO, "the helper said ok but sent no directory");
	if (ret < 0 || ans->reason != USB_REASON_NONE || req->op != USB_OP_MOUNT) {
		if (fd >= 0)
			close(fd);
		return ret;
	}
	*dirfd = fd;
	return 0;
}
