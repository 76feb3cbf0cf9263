/* SPDX-License-Identifier: MIT */
/*
 * edaha-usb-helper: mounts and ejects USB sticks for the unprivileged kiosk.
 *
 * Socket-activated per connection (systemd/edaha-usb.socket, Accept=yes): stdin is the
 * connected socket. One request line, one answer line (usb_proto.h); a mount's answer
 * carries the stick's edaha/ directory as an fd, so the kiosk never needs the mount's
 * path nor the right to mount. Only root and the kiosk's user may ask (SO_PEERCRED).
 * A stick is taken only when udev says it hangs off the USB bus and holds vfat, exfat
 * or ext4; it is mounted nosuid, nodev, noexec, noatime, nosymfollow under
 * /run/edaha/media/KNAME, in the host's mount namespace.
 *
 *   edaha-usb-helper [--user NAME] [--media DIR] [--listen PATH]
 *
 * --listen serves connections on PATH one after the other (tests, a system without
 * systemd) instead of the one on stdin.
 */
#define _GNU_SOURCE /* struct ucred */
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <libudev.h>
#include <limits.h>
#include <poll.h>
#include <pwd.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

#include "usb_fdpass.h"
#include "usb_proto.h"
#include "usb_stick.h"

#define HELPER_USER_DEFAULT "edaha"
#define HELPER_MEDIA_DEFAULT "/run/edaha/media"
/* a peer that says nothing for this long is dropped */
#define HELPER_READ_TIMEOUT_MS 10000
/* a busy mount is retried this often, 100 ms apart, before it is detached lazily */
#define HELPER_UMOUNT_TRIES 5

struct helper {
	const char *media, *user;
	uid_t user_uid; /* the kiosk's user; (uid_t)-1 when it does not exist */
	struct udev *udev;
};

static void log_line(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

static void log_line(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	fputs("edaha-usb-helper: ", stderr);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	va_end(ap);
}

static void sleep_ms(long ms)
{
	struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };

	while (nanosleep(&ts, &ts) < 0 && errno == EINTR)
		;
}

static enum usb_reason fail(struct usb_answer *ans, enum usb_reason r, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static enum usb_reason fail(struct usb_answer *ans, enum usb_reason r, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(ans->text, sizeof(ans->text), fmt, ap);
	va_end(ap);
	ans->reason = r;
	return r;
}

/* Whether path is a mount point: another filesystem than its parent's. */
static bool mounted_at(const char *path)
{
	char parent[PATH_MAX];
	struct stat st, pst;

	if (snprintf(parent, sizeof(parent), "%s/..", path) >= (int)sizeof(parent))
		return false;
	return lstat(path, &st) == 0 && S_ISDIR(st.st_mode) && stat(parent, &pst) == 0 &&
	       (st.st_dev != pst.st_dev || st.st_ino == pst.st_ino);
}

/* Detaches whatever is mounted at path (a stick pulled while the kiosk was down). */
static void detach_all(const char *path)
{
	for (int i = 0; i < 8 && mounted_at(path); i++)
		if (umount2(path, MNT_DETACH | UMOUNT_NOFOLLOW) < 0)
			break;
}

static int mount_point(const struct helper *h, const char *kname, char *mp, size_t size)
{
	if (snprintf(mp, size, "%s/%s", h->media, kname) >= (int)size)
		return -ENAMETOOLONG;
	if (mkdir(h->media, 0755) < 0 && errno != EEXIST)
		return -errno;
	if (mkdir(mp, 0700) < 0 && errno != EEXIST)
		return -errno;
	return 0;
}

static enum usb_reason do_mount(struct helper *h, const char *kname, uid_t uid, gid_t gid,
				struct usb_answer *ans, int *dirfd)
{
	struct udev_device *dev = udev_device_new_from_subsystem_sysname(h->udev, "block", kname);
	struct usb_stick_info info = { 0 };
	const char *node, *type, *ro;
	char data[160], mp[PATH_MAX];
	enum usb_reason r;
	struct stat st;
	int rootfd, e;

	*dirfd = -1;
	if (!dev)
		return fail(ans, USB_REASON_NO_DEVICE, "no block device %s", kname);
	info.on_usb = udev_device_get_parent_with_subsystem_devtype(dev, "usb", "usb_device") != NULL;
	info.initialized = udev_device_get_is_initialized(dev) > 0;
	info.fs_type = udev_device_get_property_value(dev, "ID_FS_TYPE");
	info.part_table = udev_device_get_property_value(dev, "ID_PART_TABLE_TYPE");
	ro = udev_device_get_sysattr_value(dev, "ro");
	info.read_only = ro && strcmp(ro, "1") == 0;
	r = usb_stick_check(&info, ans->text, sizeof(ans->text));
	if (r != USB_REASON_NONE) {
		udev_device_unref(dev);
		ans->reason = r;
		return r;
	}
	snprintf(ans->fstype, sizeof(ans->fstype), "%s", info.fs_type);
	node = udev_device_get_devnode(dev);
	/* the node must be the device udev describes, not something put in its place */
	if (!node || stat(node, &st) < 0 || !S_ISBLK(st.st_mode) ||
	    st.st_rdev != udev_device_get_devnum(dev)) {
		udev_device_unref(dev);
		return fail(ans, USB_REASON_NO_DEVICE, "no device node for %s", kname);
	}
	if (usb_stick_mount_data(ans->fstype, uid, gid, &type, data, sizeof(data)) < 0) {
		udev_device_unref(dev);
		return fail(ans, USB_REASON_INTERNAL, "no mount options for %s", ans->fstype);
	}
	e = mount_point(h, kname, mp, sizeof(mp));
	if (e < 0) {
		udev_device_unref(dev);
		return fail(ans, USB_REASON_INTERNAL, "mount point %s/%s: %s", h->media, kname,
			    strerror(-e));
	}
	detach_all(mp);
	if (mount(node, mp, type, usb_stick_mount_flags(), data) < 0) {
		e = errno;
		udev_device_unref(dev);
		(void)rmdir(mp);
		return fail(ans, usb_stick_mount_reason(e), "mount %s (%s): %s", node, type, strerror(e));
	}
	udev_device_unref(dev);
	rootfd = open(mp, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
	if (rootfd < 0) {
		r = fail(ans, USB_REASON_INTERNAL, "%s: %s", mp, strerror(errno));
	} else {
		r = usb_stick_open_edaha(rootfd, strcmp(type, "ext4") == 0, uid, gid, dirfd, ans->text,
					 sizeof(ans->text));
		ans->reason = r;
		/* the directory made reaches the stick now, not at some later eject */
		if (r == USB_REASON_NONE && syncfs(rootfd) < 0)
			r = fail(ans, USB_REASON_INTERNAL, "syncfs: %s", strerror(errno));
		close(rootfd);
	}
	if (r != USB_REASON_NONE) {
		if (*dirfd >= 0)
			close(*dirfd);
		*dirfd = -1;
		/* nothing of ours was written: a lazy detach is safe */
		(void)umount2(mp, MNT_DETACH | UMOUNT_NOFOLLOW);
		(void)rmdir(mp);
	}
	return r;
}

static enum usb_reason do_eject(struct helper *h, const char *kname, struct usb_answer *ans)
{
	struct udev_device *dev = udev_device_new_from_subsystem_sysname(h->udev, "block", kname);
	bool gone = dev == NULL;
	char mp[PATH_MAX];
	int fd;

	udev_device_unref(dev);
	if (snprintf(mp, sizeof(mp), "%s/%s", h->media, kname) >= (int)sizeof(mp))
		return fail(ans, USB_REASON_BAD_REQUEST, "name too long");
	if (!mounted_at(mp)) {
		(void)rmdir(mp);
		return USB_REASON_NONE; /* nothing to do: an eject is asked for twice, or late */
	}
	if (!gone) {
		fd = open(mp, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
		if (fd >= 0) {
			if (syncfs(fd) < 0)
				log_line("eject %s: syncfs: %s", kname, strerror(errno));
			close(fd);
		}
		/* busy: the kiosk still holds a file there (its writer on a dying stick) */
		for (int i = 0; i < HELPER_UMOUNT_TRIES; i++) {
			if (umount2(mp, UMOUNT_NOFOLLOW) == 0)
				break;
			if (errno != EBUSY) {
				log_line("eject %s: umount: %s", kname, strerror(errno));
				break;
			}
			sleep_ms(100);
		}
	}
	/* a pulled stick cannot be written back any more: just let go of it */
	if (mounted_at(mp)) {
		log_line("eject %s: %s, detached lazily", kname, gone ? "device gone" : "still busy");
		detach_all(mp);
	}
	(void)rmdir(mp);
	return USB_REASON_NONE;
}

/* Sends the answer line, with fd when it is not -1. */
static int send_answer(int sock, const struct usb_answer *ans, int fd)
{
	char line[USB_PROTO_LINE_MAX];

	if (usb_proto_format_answer(ans, line, sizeof(line)) < 0)
		snprintf(line, sizeof(line), "error internal cannot say why\n");
	return usb_fdpass_send(sock, line, fd);
}

/* Reads one line (up to its '\n' or the peer's end) within the timeout. */
static ssize_t read_line(int sock, char *line, size_t size)
{
	size_t have = 0;

	while (have < size) {
		struct pollfd p = { .fd = sock, .events = POLLIN };
		ssize_t n;
		int ret = poll(&p, 1, HELPER_READ_TIMEOUT_MS);

		if (ret < 0 && errno == EINTR)
			continue;
		if (ret <= 0)
			return ret < 0 ? -errno : -ETIMEDOUT;
		n = read(sock, line + have, size - have);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			return -errno;
		if (n == 0)
			break;
		have += (size_t)n;
		if (memchr(line + have - (size_t)n, '\n', (size_t)n))
			break;
	}
	return (ssize_t)have;
}

static int serve(struct helper *h, int sock)
{
	struct usb_answer ans = { 0 };
	struct usb_request req;
	struct ucred peer;
	socklen_t len = sizeof(peer);
	char line[USB_PROTO_LINE_MAX];
	ssize_t n;
	int dirfd = -1, ret;

	if (getsockopt(sock, SOL_SOCKET, SO_PEERCRED, &peer, &len) < 0) {
		log_line("not a unix socket: %s", strerror(errno));
		return -errno;
	}
	if (peer.uid != 0 && peer.uid != h->user_uid) {
		log_line("uid %u (pid %d) may not ask: neither root nor %s%s", (unsigned)peer.uid,
			 (int)peer.pid, h->user, h->user_uid == (uid_t)-1 ? " (no such user)" : "");
		fail(&ans, USB_REASON_DENIED, "uid %u may not ask", (unsigned)peer.uid);
		return send_answer(sock, &ans, -1);
	}
	n = read_line(sock, line, sizeof(line) - 1);
	if (n < 0 || usb_proto_parse_request(line, (size_t)n, &req) < 0) {
		/* the line is the peer's: not echoed */
		log_line("uid %u: %s", (unsigned)peer.uid, n < 0 ? strerror((int)-n) : "bad request");
		fail(&ans, USB_REASON_BAD_REQUEST, "expected \"mount KNAME\" or \"eject KNAME\"");
		return send_answer(sock, &ans, -1);
	}
	if (req.op == USB_OP_MOUNT)
		do_mount(h, req.kname, peer.uid, peer.gid, &ans, &dirfd);
	else
		do_eject(h, req.kname, &ans);
	if (ans.reason == USB_REASON_NONE)
		log_line("%s %s for uid %u: ok%s%s", usb_op_name(req.op), req.kname,
			 (unsigned)peer.uid, ans.fstype[0] ? " " : "", ans.fstype);
	else
		log_line("%s %s for uid %u: %s: %s", usb_op_name(req.op), req.kname,
			 (unsigned)peer.uid, usb_reason_name(ans.reason), ans.text);
	ret = send_answer(sock, &ans, dirfd);
	if (dirfd >= 0)
		close(dirfd);
	/* the peer went before taking the directory: no stick left mounted for nobody */
	if (ret < 0 && req.op == USB_OP_MOUNT && ans.reason == USB_REASON_NONE) {
		struct usb_answer ej = { 0 };

		log_line("mount %s: the answer did not go (%s); ejecting", req.kname, strerror(-ret));
		do_eject(h, req.kname, &ej);
	}
	return ret;
}

static int listen_on(struct helper *h, const char *path)
{
	struct sockaddr_un addr = { .sun_family = AF_UNIX };
	struct stat st;
	int s;

	if (strlen(path) >= sizeof(addr.sun_path)) {
		log_line("%s: name too long", path);
		return 2;
	}
	memcpy(addr.sun_path, path, strlen(path) + 1);
	/* a socket left by an earlier run; anything else there stays */
	if (lstat(path, &st) == 0 && S_ISSOCK(st.st_mode))
		(void)unlink(path);
	s = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	if (s < 0 || bind(s, (struct sockaddr *)&addr, sizeof(addr)) < 0 || listen(s, 8) < 0) {
		log_line("%s: %s", path, strerror(errno));
		return 1;
	}
	log_line("listening on %s", path);
	for (;;) {
		int c = accept4(s, NULL, NULL, SOCK_CLOEXEC);

		if (c < 0) {
			if (errno == EINTR || errno == ECONNABORTED)
				continue;
			log_line("accept: %s", strerror(errno));
			close(s);
			return 1;
		}
		(void)serve(h, c);
		close(c);
	}
}

static void usage(FILE *f)
{
	fputs("usage: edaha-usb-helper [--user NAME] [--media DIR] [--listen PATH]\n"
	      "  stdin: a connected unix socket (systemd's Accept=yes), unless --listen\n"
	      "  --user NAME   the kiosk's user, who may ask besides root (default " HELPER_USER_DEFAULT ")\n"
	      "  --media DIR   where sticks are mounted (default " HELPER_MEDIA_DEFAULT ")\n"
	      "  --listen PATH serve connections on PATH one after the other\n",
	      f);
}

int main(int argc, char **argv)
{
	static const struct option opts[] = {
		{ "user", required_argument, NULL, 'u' },
		{ "media", required_argument, NULL, 'm' },
		{ "listen", required_argument, NULL, 'l' },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	struct helper h = { .media = HELPER_MEDIA_DEFAULT, .user_uid = (uid_t)-1 };
	const char *user = HELPER_USER_DEFAULT, *listen_path = NULL;
	struct passwd *pw;
	int c, status;

	while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
		switch (c) {
		case 'u':
			user = optarg;
			break;
		case 'm':
			h.media = optarg;
			break;
		case 'l':
			listen_path = optarg;
			break;
		case 'h':
			usage(stdout);
			return 0;
		default:
			usage(stderr);
			return 2;
		}
	}
	if (optind < argc || h.media[0] != '/') {
		usage(stderr);
		return 2;
	}
	pw = getpwnam(user);
	if (pw)
		h.user_uid = pw->pw_uid;
	h.user = user;
	h.udev = udev_new();
	if (!h.udev) {
		log_line("no udev context: %s", strerror(errno));
		return 1;
	}
	if (listen_path)
		status = listen_on(&h, listen_path);
	else
		status = serve(&h, STDIN_FILENO) < 0 ? 1 : 0;
	udev_unref(h.udev);
	return status;
}
