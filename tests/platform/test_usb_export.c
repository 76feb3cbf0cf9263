/* SPDX-License-Identifier: MIT */
/*
 * The kiosk's side of USB export (usb_export.c, usb_client.c) against a stand-in for
 * edaha-usb-helper on a unix socket, which "mounts" a stick by passing a temporary
 * directory's fd: a stick put in is looked at; an export goes to it and to the local
 * copy, each with its gallery (index.html) rewritten; with no stick the visitor is told
 * to put one in; a locked stick, a full one (its gallery as it was), one pulled while
 * saving, a second press while saving, no USB at all, and a gallery that cannot be
 * written (the tree saved all the same).
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "app.h"
#include "usb_export.h"
#include "usb_fdpass.h"
#include "usb_proto.h"
#include "dir_count.h"
#include "test.h"

static char root[] = "/tmp/edaha-usb-export-XXXXXX";
static char sock_path[128], sys_block[256], stick_dir[256], local_dir[256];

/* ---- the helper's stand-in ---- */

static pthread_mutex_t fake_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t fake_cond = PTHREAD_COND_INITIALIZER;
static const char *fake_mount_answer = "ok vfat\n"; /* what "mount" gets */
static bool fake_stall, fake_stalled;             /* "mount" waits until released */
static int fake_mounts, fake_ejects;
static int listen_fd;

static void answer(int c, const char *line, int fd)
{
	CHECK_INT(usb_fdpass_send(c, line, fd), 0);
}

static void *fake_helper(void *unused)
{
	(void)unused;
	for (;;) {
		struct usb_request req;
		char line[USB_PROTO_LINE_MAX];
		ssize_t n;
		int c = accept(listen_fd, NULL, NULL);

		if (c < 0)
			return NULL; /* closed: the test is over */
		n = read(c, line, sizeof(line));
		CHECK(n > 0);
		CHECK_INT(usb_proto_parse_request(line, (size_t)n, &req), 0);
		pthread_mutex_lock(&fake_lock);
		if (req.op == USB_OP_MOUNT) {
			fake_mounts++;
			fake_stalled = fake_stall;
			pthread_cond_broadcast(&fake_cond);
			while (fake_stall)
				pthread_cond_wait(&fake_cond, &fake_lock);
			fake_stalled = false;
			if (!strncmp(fake_mount_answer, "ok", 2)) {
				int fd = open(stick_dir, O_RDONLY | O_DIRECTORY);

				CHECK(fd >= 0);
				answer(c, fake_mount_answer, fd);
				close(fd);
			} else {
				answer(c, fake_mount_answer, -1);
			}
		} else {
			fake_ejects++;
			answer(c, "ok\n", -1);
		}
		pthread_mutex_unlock(&fake_lock);
		close(c);
	}
}

/* ---- the kiosk's side ---- */

static enum app_status told[64];
static bool told_held[64];
static size_t ntold;

static void on_status(void *data, enum app_status s, bool held)
{
	(void)data;
	CHECK(ntold < 64);
	told_held[ntold] = held;
	told[ntold++] = s;
}

static enum app_status last(void)
{
	CHECK(ntold > 0);
	return told[ntold - 1];
}

/* Runs the kiosk's side of the poll until a result came in. */
static void wait_result(struct usb_export *ux)
{
	struct kiosk_source src[2];
	size_t n = usb_export_sources(ux, src, 2);
	struct pollfd p = { .fd = src[0].fd, .events = POLLIN };

	CHECK_INT(n, 1); /* no monitor here: the results alone */
	CHECK_INT(poll(&p, 1, 20000), 1);
	CHECK_INT(src[0].dispatch(src[0].data), 0);
}

/* dir/index.html's bytes, NUL-terminated; NULL when there is none. */
static char *gallery_of(const char *dir)
{
	char path[300], *s;
	size_t len = 0;
	FILE *f;

	snprintf(path, sizeof(path), "%s/index.html", dir);
	f = fopen(path, "r");
	if (!f)
		return NULL;
	s = malloc(1 << 16);
	CHECK(s);
	len = fread(s, 1, (1 << 16) - 1, f);
	CHECK(feof(f));
	fclose(f);
	s[len] = '\0';
	return s;
}

/* How many entries a gallery lists, and that the first (newest) links to set first. */
static int entries(const char *html, const char *first)
{
	const char *p = strstr(html, "<li><a href=\"");
	int n = 0;

	CHECK(p && !strncmp(p + 13, first, strlen(first)));
	for (; p; p = strstr(p + 1, "<li><a href=\""))
		n++;
	return n;
}

static void stick_there(const char *kname, bool there)
{
	char path[300];

	snprintf(path, sizeof(path), "%s/%s", sys_block, kname);
	if (there) {
		FILE *f = fopen(path, "w");

		CHECK(f);
		fclose(f);
	} else {
		CHECK_INT(unlink(path), 0);
	}
}

static void set_answer(const char *a)
{
	pthread_mutex_lock(&fake_lock);
	fake_mount_answer = a;
	pthread_mutex_unlock(&fake_lock);
}

static void test_sticks(struct app *app)
{
	struct usb_export_config cfg = { .usb = true, .helper_socket = sock_path,
					 .local_dir = local_dir, .sys_block = sys_block,
					 .status = on_status };
	struct error err = { { 0 } };
	struct usb_export *ux = usb_export_create(&cfg, &err);
	static uint8_t rgba[64 * 64 * 4];
	char path[300], *gallery, *html;
	struct rlimit old, lim;

	CHECK(ux);
	/* put in: looked at (mounted and ejected), ready */
	stick_there("sdz1", true);
	usb_export_added(ux, "sdz1");
	usb_export_added(ux, "sdz1"); /* a change event for it: nothing more */
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_STICK_READY);
	CHECK_INT(fake_mounts, 1);
	CHECK_INT(fake_ejects, 1);
	/* saved: "saving" held until the result, then safe to pull; the copy kept too */
	usb_export_start(ux, app, rgba, NULL, NULL);
	CHECK_INT(last(), APP_STATUS_SAVING);
	CHECK(told_held[ntold - 1]);
	CHECK(usb_export_busy(ux));
	usb_export_start(ux, app, rgba, NULL, NULL); /* pressed again meanwhile: ignored */
	CHECK_INT(last(), APP_STATUS_SAVING);
	wait_result(ux);
	CHECK(!usb_export_busy(ux));
	CHECK_INT(last(), APP_STATUS_SAVED_USB);
	CHECK(!told_held[ntold - 1]);
	CHECK_INT(fake_ejects, 2);
	snprintf(path, sizeof(path), "%s/tree-0001.png", stick_dir);
	CHECK(access(path, F_OK) == 0);
	CHECK_INT(dir_count(AT_FDCWD, stick_dir, "tree-0001."), 5);
	CHECK_INT(dir_count(AT_FDCWD, local_dir, "tree-0001."), 5);
	CHECK_INT(dir_count(AT_FDCWD, stick_dir, "tree-0002."), 0); /* the second press */
	/* the gallery beside the set, on the stick and in the copy */
	gallery = gallery_of(stick_dir);
	CHECK(gallery && entries(gallery, "tree-0001.") == 1);
	CHECK(strstr(gallery, "<img src=\"tree-0001.png\""));
	html = gallery_of(local_dir);
	CHECK(html && entries(html, "tree-0001.") == 1);
	free(html);

	/* full: nothing of the set left on it, the visitor told so */
	CHECK_INT(getrlimit(RLIMIT_FSIZE, &old), 0);
	lim = old;
	lim.rlim_cur = 200;
	signal(SIGXFSZ, SIG_IGN);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &lim), 0);
	usb_export_start(ux, app, rgba, NULL, NULL);
	wait_result(ux);
	CHECK_INT(setrlimit(RLIMIT_FSIZE, &old), 0);
	CHECK_INT(last(), APP_STATUS_STICK_FULL);
	CHECK_INT(dir_count(AT_FDCWD, stick_dir, "tree-0002"), 0);
	CHECK_INT(dir_count(AT_FDCWD, stick_dir, ".tree-"), 0);
	/* its gallery as it was, whole */
	html = gallery_of(stick_dir);
	CHECK(html && !strcmp(html, gallery));
	free(html);
	free(gallery);
	CHECK_INT(dir_count(AT_FDCWD, stick_dir, ".index"), 0);

	/* pulled while saving: told at once, and again by the result */
	pthread_mutex_lock(&fake_lock);
	fake_stall = true;
	pthread_mutex_unlock(&fake_lock);
	usb_export_start(ux, app, rgba, NULL, NULL);
	CHECK_INT(last(), APP_STATUS_SAVING);
	pthread_mutex_lock(&fake_lock);
	while (!fake_stalled)
		pthread_cond_wait(&fake_cond, &fake_lock);
	fake_mount_answer = "error no-device no block device sdz1\n";
	pthread_mutex_unlock(&fake_lock);
	stick_there("sdz1", false);
	usb_export_removed(ux, "sdz1");
	CHECK_INT(last(), APP_STATUS_STICK_PULLED);
	pthread_mutex_lock(&fake_lock);
	fake_stall = false;
	pthread_cond_broadcast(&fake_cond);
	pthread_mutex_unlock(&fake_lock);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_STICK_PULLED);
	CHECK(!usb_export_busy(ux));

	/* no stick: put one in, says the kiosk; the copy is still kept */
	usb_export_start(ux, app, rgba, NULL, NULL);
	CHECK_INT(last(), APP_STATUS_NO_STICK);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_NO_STICK);
	/* 0001 the first save, 0002 the one whose stick was pulled (a full disk has none) */
	CHECK_INT(dir_count(AT_FDCWD, local_dir, "tree-0003."), 5);

	/* a locked stick: said when it comes, and again on save */
	set_answer("error read-only write-protected\n");
	stick_there("sdz2", true);
	usb_export_added(ux, "sdz2");
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_STICK_LOCKED);
	usb_export_start(ux, app, NULL, NULL, NULL);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_STICK_LOCKED);
	/* one with a file named edaha */
	set_answer("error edaha-not-a-directory edaha is not a directory\n");
	usb_export_start(ux, app, NULL, NULL, NULL);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_STICK_UNUSABLE);
	stick_there("sdz2", false);
	usb_export_removed(ux, "sdz2");
	set_answer("ok vfat\n");
	usb_export_destroy(ux);

	/* a helper that is not there: the save failed, the kiosk goes on */
	cfg.helper_socket = "/nonexistent/edaha/usb.sock";
	cfg.local_dir = NULL;
	ux = usb_export_create(&cfg, &err);
	CHECK(ux);
	stick_there("sdz3", true);
	usb_export_added(ux, "sdz3");
	wait_result(ux);
	usb_export_start(ux, app, NULL, NULL, NULL);
	CHECK_INT(last(), APP_STATUS_SAVING);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_SAVE_FAILED);
	/* gone with a save queued: destroy waits for it, nothing leaks */
	usb_export_start(ux, app, NULL, NULL, NULL);
	usb_export_destroy(ux);
}

/* usb.enabled false: the local directory is the export, as before sticks */
static void test_local_only(struct app *app)
{
	struct usb_export_config cfg = { .usb = false, .local_dir = local_dir, .status = on_status };
	struct error err = { { 0 } };
	struct usb_export *ux = usb_export_create(&cfg, &err);
	char file[300], *html;
	FILE *f;

	CHECK(ux);
	usb_export_added(ux, "sdz1"); /* no sticks without usb */
	usb_export_start(ux, app, NULL, NULL, NULL);
	CHECK(usb_export_busy(ux));
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_SAVED);
	CHECK_INT(dir_count(AT_FDCWD, local_dir, "tree-0006."), 4); /* after the locked stick's two */
	html = gallery_of(local_dir);
	CHECK(html && entries(html, "tree-0006.") == 6);
	free(html);
	/* a gallery that cannot be written (a directory of its name): the tree is saved */
	snprintf(file, sizeof(file), "%s/index.html", local_dir);
	CHECK_INT(unlink(file), 0);
	CHECK_INT(mkdir(file, 0755), 0);
	usb_export_start(ux, app, NULL, NULL, NULL);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_SAVED);
	CHECK_INT(dir_count(AT_FDCWD, local_dir, "tree-0007."), 4);
	CHECK_INT(dir_count(AT_FDCWD, local_dir, ".index"), 0);
	CHECK_INT(rmdir(file), 0);
	usb_export_destroy(ux);
	/* a file where the directory should be */
	snprintf(file, sizeof(file), "%s/plain", root);
	f = fopen(file, "w");
	CHECK(f);
	fclose(f);
	cfg.local_dir = file;
	ux = usb_export_create(&cfg, &err);
	CHECK(ux);
	usb_export_start(ux, app, NULL, NULL, NULL);
	wait_result(ux);
	CHECK_INT(last(), APP_STATUS_SAVE_FAILED);
	usb_export_destroy(ux);
}

int main(void)
{
	struct sockaddr_un addr = { .sun_family = AF_UNIX };
	struct app *app = app_create(64, 64, 1);
	pthread_t helper;
	char cmd[300];

	CHECK(app);
	CHECK(mkdtemp(root));
	snprintf(sock_path, sizeof(sock_path), "%s/usb.sock", root);
	snprintf(sys_block, sizeof(sys_block), "%s/sys", root);
	snprintf(stick_dir, sizeof(stick_dir), "%s/stick", root);
	snprintf(local_dir, sizeof(local_dir), "%s/local/export", root);
	CHECK_INT(mkdir(sys_block, 0755), 0);
	CHECK_INT(mkdir(stick_dir, 0755), 0);
	memcpy(addr.sun_path, sock_path, strlen(sock_path) + 1);
	listen_fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	CHECK(listen_fd >= 0);
	CHECK_INT(bind(listen_fd, (struct sockaddr *)&addr, sizeof(addr)), 0);
	CHECK_INT(listen(listen_fd, 4), 0);
	CHECK_INT(pthread_create(&helper, NULL, fake_helper, NULL), 0);

	test_sticks(app);
	test_local_only(app);

	shutdown(listen_fd, SHUT_RDWR);
	close(listen_fd);
	pthread_join(helper, NULL);
	app_destroy(app);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	CHECK_INT(system(cmd), 0);
	return 0;
}
