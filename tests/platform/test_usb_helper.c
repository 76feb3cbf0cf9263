/* SPDX-License-Identifier: MIT */
/*
 * edaha-usb-helper's decisions without a stick or root: the protocol's lines (what is a
 * request, kernel names that could climb out of /dev), what udev's view of a device
 * makes of it, the mount options, and opening edaha/ on a stick whose root holds a file
 * or a symlink of that name; which block devices the kiosk takes for sticks. Then the
 * helper itself on a socketpair, as systemd's Accept=yes starts it: a bad request, a
 * name that is no device, not on USB, a peer that may not ask; and with --listen, asked
 * by the kiosk's client.
 *   test_usb_helper [EDAHA_USB_HELPER]
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <pwd.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config.h"
#include "usb_client.h"
#include "usb_proto.h"
#include "usb_stick.h"
#include "test.h"
#if HAVE_USB_MONITOR
#include "usb_monitor.h"
#endif

static void test_proto(void)
{
	static const char *const bad[] = {
		"", "\n", "mount\n", "mount \n", "mount sda1 \n", "mount  sda1\n", "MOUNT sda1\n",
		"mount ../sda\n", "mount sda/1\n", "mount 1sda\n", "mount sdA1\n", "mount sda1\r\n",
		"mount sda1\nmount sdb1\n", "format sda1\n", "eject .\n", "mount sda1\n\n",
		"eject aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\n",
	};
	struct usb_request req;
	struct usb_answer ans = { 0 };
	char line[USB_PROTO_LINE_MAX];

	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		if (usb_proto_parse_request(bad[i], strlen(bad[i]), &req) == 0)
			fprintf(stderr, "accepted: %s", bad[i]);
		CHECK_INT(usb_proto_parse_request(bad[i], strlen(bad[i]), &req), -EINVAL);
	}
	CHECK_INT(usb_proto_parse_request("mount sda1\0x", 12, &req), -EINVAL); /* a NUL */
	CHECK_INT(usb_proto_parse_request("mount sda1\n", 11, &req), 0);
	CHECK(req.op == USB_OP_MOUNT && !strcmp(req.kname, "sda1"));
	CHECK_INT(usb_proto_parse_request("eject mmcblk0p1", 15, &req), 0);
	CHECK(req.op == USB_OP_EJECT && !strcmp(req.kname, "mmcblk0p1"));
	CHECK_INT(usb_proto_format_request(&req, line, sizeof(line)), 0);
	CHECK(!strcmp(line, "eject mmcblk0p1\n"));
	CHECK(usb_proto_kname_valid("sdb") && !usb_proto_kname_valid("") &&
	      !usb_proto_kname_valid("sd-b") && !usb_proto_kname_valid(NULL));

	CHECK_INT(usb_proto_parse_answer("ok vfat\n", 8, &ans), 0);
	CHECK(ans.reason == USB_REASON_NONE && !strcmp(ans.fstype, "vfat"));
	CHECK_INT(usb_proto_parse_answer("ok\n", 3, &ans), 0);
	CHECK(ans.reason == USB_REASON_NONE && !ans.fstype[0]);
	CHECK_INT(usb_proto_parse_answer("error read-only write-protected\n", 32, &ans), 0);
	CHECK(ans.reason == USB_REASON_READ_ONLY && !strcmp(ans.text, "write-protected"));
	CHECK_INT(usb_proto_parse_answer("error brand-new what\n", 21, &ans), 0);
	CHECK(ans.reason == USB_REASON_INTERNAL); /* a newer helper's reason */
	CHECK_INT(usb_proto_parse_answer("ok ../x\n", 8, &ans), -EINVAL);
	CHECK_INT(usb_proto_parse_answer("fine\n", 5, &ans), -EINVAL);
	/* every reason goes over the wire and back */
	for (int r = USB_REASON_BAD_REQUEST; r < USB_REASON_COUNT; r++) {
		struct usb_answer a = { .reason = (enum usb_reason)r }, b;

		snprintf(a.text, sizeof(a.text), "a\nstick\x01 said");
		CHECK_INT(usb_proto_format_answer(&a, line, sizeof(line)), 0);
		CHECK_INT(usb_proto_parse_answer(line, strlen(line), &b), 0);
		CHECK_INT(b.reason, r);
		CHECK(!strcmp(b.text, "a?stick? said"));
	}
	/* what the visitor hears */
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, 0, true), USB_OUTCOME_OK);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, 0, false), USB_OUTCOME_OK);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, -ENOSPC, true), USB_OUTCOME_FULL);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, -EFBIG, true), USB_OUTCOME_FULL);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, -EIO, false), USB_OUTCOME_PULLED);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, -EIO, true), USB_OUTCOME_FAILED);
	CHECK_INT(usb_outcome_of(USB_REASON_NONE, -EROFS, true), USB_OUTCOME_READ_ONLY);
	CHECK_INT(usb_outcome_of(USB_REASON_READ_ONLY, 0, true), USB_OUTCOME_READ_ONLY);
	CHECK_INT(usb_outcome_of(USB_REASON_NOT_A_DIR, 0, true), USB_OUTCOME_UNUSABLE);
	CHECK_INT(usb_outcome_of(USB_REASON_UNFORMATTED, 0, true), USB_OUTCOME_UNUSABLE);
	CHECK_INT(usb_outcome_of(USB_REASON_NO_DEVICE, 0, true), USB_OUTCOME_PULLED);
	CHECK_INT(usb_outcome_of(USB_REASON_FULL, 0, true), USB_OUTCOME_FULL);
	CHECK_INT(usb_outcome_of(USB_REASON_DENIED, 0, true), USB_OUTCOME_FAILED);
}

#if HAVE_USB_MONITOR
/* Which block devices the kiosk takes for sticks. */
static void test_is_stick(void)
{
	CHECK(usb_monitor_is_stick("partition", true, "vfat", NULL, 30000000));
	CHECK(usb_monitor_is_stick("partition", true, NULL, NULL, 30000000)); /* says why not */
	CHECK(usb_monitor_is_stick("disk", true, "vfat", NULL, 32768));      /* superfloppy */
	CHECK(usb_monitor_is_stick("disk", true, "exfat", "dos", 32768));    /* reads as both */
	CHECK(usb_monitor_is_stick("disk", true, NULL, NULL, 16384));        /* unformatted */
	CHECK(!usb_monitor_is_stick("disk", true, NULL, "gpt", 30000000)); /* its partitions */
	CHECK(!usb_monitor_is_stick("disk", true, "vfat", NULL, 0));       /* no medium */
	CHECK(!usb_monitor_is_stick("disk", false, "vfat", NULL, 32768));  /* not USB */
	CHECK(!usb_monitor_is_stick(NULL, true, "vfat", NULL, 32768));
}
#endif

static void test_check(void)
{
	struct usb_stick_info i = { .on_usb = true, .initialized = true, .fs_type = "vfat" };
	const char *type;
	char text[128], data[160];

	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_NONE);
	i.fs_type = "exfat";
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_NONE);
	i.fs_type = "ext4";
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_NONE);
	i.fs_type = "ntfs";
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_UNSUPPORTED);
	CHECK(strstr(text, "ntfs"));
	i.fs_type = "";
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_UNFORMATTED);
	i.fs_type = NULL;
	i.part_table = "dos";
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_UNFORMATTED);
	i.fs_type = "vfat";
	i.read_only = true;
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_READ_ONLY);
	i.initialized = false;
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_NOT_READY);
	i.on_usb = false;
	CHECK_INT(usb_stick_check(&i, text, sizeof(text)), USB_REASON_NOT_USB);

	CHECK_INT(usb_stick_mount_data("vfat", 998, 997, &type, data, sizeof(data)), 0);
	CHECK(!strcmp(type, "vfat") && strstr(data, "uid=998,gid=997") && strstr(data, "flush"));
	CHECK_INT(usb_stick_mount_data("exfat", 1, 2, &type, data, sizeof(data)), 0);
	CHECK(strstr(data, "uid=1,gid=2"));
	CHECK_INT(usb_stick_mount_data("ext4", 1, 2, &type, data, sizeof(data)), 0);
	CHECK(!data[0]);
	CHECK_INT(usb_stick_mount_data("ntfs", 1, 2, &type, data, sizeof(data)), -EINVAL);
	CHECK_INT(usb_stick_mount_reason(EACCES), USB_REASON_READ_ONLY);
	CHECK_INT(usb_stick_mount_reason(EROFS), USB_REASON_READ_ONLY);
	CHECK_INT(usb_stick_mount_reason(EINVAL), USB_REASON_MOUNT_FAILED);
}

/* A directory standing in for a mounted stick's root. */
static int stick_root(const char *base, const char *name)
{
	char path[512];
	int fd;

	snprintf(path, sizeof(path), "%s/%s", base, name);
	CHECK_INT(mkdir(path, 0755), 0);
	fd = open(path, O_RDONLY | O_DIRECTORY);
	CHECK(fd >= 0);
	return fd;
}

static void test_open_edaha(const char *base)
{
	char text[128];
	struct stat st;
	int root, dir;

	/* missing: made */
	root = stick_root(base, "fresh");
	CHECK_INT(usb_stick_open_edaha(root, false, 0, 0, &dir, text, sizeof(text)), USB_REASON_NONE);
	CHECK(dir >= 0 && fstat(dir, &st) == 0 && S_ISDIR(st.st_mode));
	close(dir);
	/* there: opened */
	CHECK_INT(usb_stick_open_edaha(root, false, 0, 0, &dir, text, sizeof(text)), USB_REASON_NONE);
	close(dir);
	close(root);
	/* a file named edaha */
	root = stick_root(base, "file");
	close(openat(root, "edaha", O_WRONLY | O_CREAT, 0644));
	CHECK_INT(usb_stick_open_edaha(root, false, 0, 0, &dir, text, sizeof(text)),
		  USB_REASON_NOT_A_DIR);
	CHECK_INT(dir, -1);
	CHECK(fstatat(root, "edaha", &st, 0) == 0 && S_ISREG(st.st_mode)); /* left alone */
	close(root);
	/* a symlink to a directory elsewhere: not followed */
	root = stick_root(base, "link");
	CHECK_INT(symlinkat("/tmp", root, "edaha"), 0);
	CHECK_INT(usb_stick_open_edaha(root, false, 0, 0, &dir, text, sizeof(text)),
		  USB_REASON_NOT_A_DIR);
	CHECK(strstr(text, "not a directory"));
	close(root);
	/* ext4: someone else's edaha/ that the kiosk's user cannot write in */
	root = stick_root(base, "owned");
	CHECK_INT(mkdirat(root, "edaha", 0755), 0);
	CHECK_INT(fstatat(root, "edaha", &st, 0), 0);
	CHECK_INT(usb_stick_open_edaha(root, true, st.st_uid + 1000, st.st_gid + 1000, &dir, text,
				       sizeof(text)),
		  USB_REASON_NOT_WRITABLE);
	CHECK_INT(usb_stick_open_edaha(root, true, st.st_uid, st.st_gid, &dir, text, sizeof(text)),
		  USB_REASON_NONE);
	close(dir);
	close(root);
}

/* Runs the helper with stdin a socketpair's end, sends line, returns its answer. */
static void ask(const char *helper, const char *user, const char *line, char *out, size_t size)
{
	int sv[2];
	pid_t pid;
	ssize_t n;
	int status;

	CHECK_INT(socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv), 0);
	pid = fork();
	CHECK(pid >= 0);
	if (pid == 0) {
		dup2(sv[1], 0);
		execl(helper, helper, "--user", user, "--media", "/nonexistent/edaha-media",
		      (char *)NULL);
		_exit(127);
	}
	close(sv[1]);
	/* a helper that refuses the peer answers and goes without reading: the request may
	 * then meet a closed socket (EPIPE, and no SIGPIPE to kill the test) */
	n = send(sv[0], line, strlen(line), MSG_NOSIGNAL);
	CHECK(n == (ssize_t)strlen(line) || (n < 0 && errno == EPIPE));
	/* to the end: the answer need not come in one read (a busy machine, a signal); a
	 * helper that refuses the peer closes without reading the request, which ends the
	 * stream with ECONNRESET once its answer has been read */
	for (size_t got = 0;;) {
		n = read(sv[0], out + got, size - 1 - got);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0 && errno == ECONNRESET && got > 0)
			n = 0;
		CHECK(n >= 0);
		got += (size_t)n;
		out[got] = '\0';
		if (n == 0 || got == size - 1)
			break;
	}
	CHECK(out[0] != '\0');
	close(sv[0]);
	CHECK_INT(waitpid(pid, &status, 0), pid);
	CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

static void test_helper(const char *helper)
{
	struct passwd *pw = getpwuid(getuid());
	const char *me = pw ? pw->pw_name : "root";
	char out[USB_PROTO_LINE_MAX];

	ask(helper, me, "bogus\n", out, sizeof(out));
	CHECK(!strncmp(out, "error bad-request ", 18));
	ask(helper, me, "mount ../../dev/sda\n", out, sizeof(out));
	CHECK(!strncmp(out, "error bad-request ", 18));
	ask(helper, me, "mount sdzz9\n", out, sizeof(out));
	CHECK(!strncmp(out, "error no-device ", 16));
	ask(helper, me, "eject sdzz9\n", out, sizeof(out)); /* nothing mounted: fine */
	CHECK(!strcmp(out, "ok\n"));
	/* a block device that is not on USB, where there is one to ask about */
	if (access("/sys/class/block/loop0", F_OK) == 0) {
		ask(helper, me, "mount loop0\n", out, sizeof(out));
		CHECK(!strncmp(out, "error not-usb ", 14));
	}
	/* neither root nor the kiosk's user: as root, asked by nobody (the socketpair's
	 * peer is whoever made it) */
	if (getuid() != 0) {
		ask(helper, "nonexistent-edaha-user", "mount sda1\n", out, sizeof(out));
		CHECK(!strncmp(out, "error denied ", 13));
	} else {
		pid_t pid = fork();
		int status;

		CHECK(pid >= 0);
		if (pid == 0) {
			CHECK_INT(setresgid(65534, 65534, 65534), 0);
			CHECK_INT(setresuid(65534, 65534, 65534), 0);
			ask(helper, "root", "mount sda1\n", out, sizeof(out));
			CHECK(!strncmp(out, "error denied ", 13));
			_exit(0);
		}
		CHECK_INT(waitpid(pid, &status, 0), pid);
		CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
	}
}

/* --listen, for a system without systemd: the kiosk's client against the real helper. */
static void test_listen(const char *helper, const char *base)
{
	struct passwd *pw = getpwuid(getuid());
	struct usb_request req = { .op = USB_OP_EJECT, .kname = "sdzz9" };
	struct error err = { { 0 } };
	struct usb_answer ans;
	char path[512];
	pid_t pid;
	int fd = -1, ret = -1, status;

	snprintf(path, sizeof(path), "%s/usb.sock", base);
	pid = fork();
	CHECK(pid >= 0);
	if (pid == 0) {
		execl(helper, helper, "--user", pw ? pw->pw_name : "root", "--media",
		      "/nonexistent/edaha-media", "--listen", path, (char *)NULL);
		_exit(127);
	}
	/* until it listens (bounded: 10 s) */
	for (int i = 0; i < 200 && ret < 0; i++) {
		ret = usb_client_call(path, &req, 5000, &ans, &fd, &err);
		if (ret < 0)
			usleep(50000);
	}
	CHECK_INT(ret, 0);
	CHECK(ans.reason == USB_REASON_NONE && fd == -1);
	req.op = USB_OP_MOUNT;
	CHECK_INT(usb_client_call(path, &req, 5000, &ans, &fd, &err), 0);
	CHECK_INT(ans.reason, USB_REASON_NO_DEVICE);
	CHECK_INT(fd, -1);
	CHECK_INT(kill(pid, SIGTERM), 0);
	CHECK_INT(waitpid(pid, &status, 0), pid);
	/* nobody there any more */
	CHECK(usb_client_call(path, &req, 1000, &ans, &fd, &err) < 0);
	CHECK(strstr(err.msg, "cannot reach the USB helper"));
}

int main(int argc, char **argv)
{
	char base[] = "/tmp/edaha-usb-helper-XXXXXX", cmd[128];

	test_proto();
#if HAVE_USB_MONITOR
	test_is_stick();
#endif
	test_check();
	CHECK(mkdtemp(base));
	test_open_edaha(base);
	if (argc > 1) {
		test_helper(argv[1]);
		test_listen(argv[1], base);
	}
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", base);
	CHECK_INT(system(cmd), 0);
	return 0;
}
