/* SPDX-License-Identifier: MIT */
#include "drm_kms.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <xf86drm.h>

/* Property ids, looked up by name once an output is picked. */
enum { CONN_CRTC_ID, CONN_PROPS };
enum { CRTC_MODE_ID, CRTC_ACTIVE, CRTC_PROPS };
enum {
	PLANE_FB_ID, PLANE_CRTC_ID,
	PLANE_SRC_X, PLANE_SRC_Y, PLANE_SRC_W, PLANE_SRC_H,
	PLANE_CRTC_X, PLANE_CRTC_Y, PLANE_CRTC_W, PLANE_CRTC_H,
	PLANE_PROPS
};
static const char *const conn_prop_names[CONN_PROPS] = { "CRTC_ID" };
static const char *const crtc_prop_names[CRTC_PROPS] = { "MODE_ID", "ACTIVE" };
static const char *const plane_prop_names[PLANE_PROPS] = {
	"FB_ID", "CRTC_ID", "SRC_X", "SRC_Y", "SRC_W", "SRC_H",
	"CRTC_X", "CRTC_Y", "CRTC_W", "CRTC_H",
};

struct drm_kms {
	int fd;
	bool atomic;
	bool picked;
	struct drm_kms_output out;
	uint32_t conn_prop[CONN_PROPS], crtc_prop[CRTC_PROPS], plane_prop[PLANE_PROPS];
	uint32_t mode_blob; /* the MODE_ID of the last atomic modeset; 0 none */
	drmModeCrtc *saved; /* what the CRTC showed before us */
	uint32_t saved_connector;
};

struct drm_kms *drm_kms_create(int fd, bool atomic)
{
	struct drm_kms *k = calloc(1, sizeof(*k));

	if (!k)
		return NULL;
	k->fd = fd;
	/* the atomic cap needs universal planes: a primary plane is what we flip */
	k->atomic = atomic && drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) == 0 &&
		    drmSetClientCap(fd, DRM_CLIENT_CAP_ATOMIC, 1) == 0;
	return k;
}

void drm_kms_destroy(struct drm_kms *k)
{
	if (!k)
		return;
	if (k->mode_blob)
		drmModeDestroyPropertyBlob(k->fd, k->mode_blob);
	drmModeFreeCrtc(k->saved);
	free(k);
}

const struct drm_kms_output *drm_kms_output(const struct drm_kms *k)
{
	return &k->out;
}

bool drm_kms_atomic(const struct drm_kms *k)
{
	return k->atomic;
}

/* ---- picking the output ---- */

const drmModeModeInfo *drm_kms_pick_mode(const drmModeModeInfo *modes, int n, int width,
					 int height, int refresh, bool fallback)
{
	const drmModeModeInfo *preferred = NULL;

	for (int i = 0; i < n; i++) {
		const drmModeModeInfo *m = &modes[i];

		if (width > 0 && m->hdisplay == width && m->vdisplay == height &&
		    (refresh <= 0 || (int)m->vrefresh == refresh))
			return m;
		if (!preferred || ((m->type & DRM_MODE_TYPE_PREFERRED) &&
				   !(preferred->type & DRM_MODE_TYPE_PREFERRED)))
			preferred = m;
	}
	return width > 0 && !fallback ? NULL : preferred;
}

static void connector_name(const drmModeConnector *c, char *out, size_t n)
{
	const char *type = drmModeGetConnectorTypeName(c->connector_type);

	snprintf(out, n, "%s-%u", type ? type : "Unknown", c->connector_type_id);
}

static int crtc_index(const drmModeRes *res, uint32_t crtc)
{
	for (int i = 0; i < res->count_crtcs && i < 32; i++)
		if (res->crtcs[i] == crtc)
			return i;
	return -1;
}

/* A CRTC the connector can use (its index): the one its encoder drives now, else the
 * first its encoders can reach. -1 when none. */
static int pick_crtc(int fd, const drmModeRes *res, const drmModeConnector *c)
{
	if (c->encoder_id) {
		drmModeEncoder *e = drmModeGetEncoder(fd, c->encoder_id);
		int i = e && e->crtc_id ? crtc_index(res, e->crtc_id) : -1;

		drmModeFreeEncoder(e);
		if (i >= 0)
			return i;
	}
	for (int i = 0; i < c->count_encoders; i++) {
		drmModeEncoder *e = drmModeGetEncoder(fd, c->encoders[i]);

		if (!e)
			continue;
		for (int j = 0; j < res->count_crtcs && j < 32; j++) {
			if (e->possible_crtcs & (1u << j)) {
				drmModeFreeEncoder(e);
				return j;
			}
		}
		drmModeFreeEncoder(e);
	}
	return -1;
}

/* The ids of the named properties of a KMS object; -ENOENT when one is missing. */
static int prop_ids(int fd, uint32_t obj, uint32_t type, const char *const *names, uint32_t *ids,
		    size_t n, uint64_t *plane_type)
{
	drmModeObjectProperties *props = drmModeObjectGetProperties(fd, obj, type);

	if (!props)
		return -ENOENT;
	memset(ids, 0, n * sizeof(*ids));
	for (uint32_t i = 0; i < props->count_props; i++) {
		drmModePropertyRes *p = drmModeGetProperty(fd, props->props[i]);

		if (!p)
			continue;
		for (size_t j = 0; j < n; j++)
			if (strcmp(p->name, names[j]) == 0)
				ids[j] = p->prop_id;
		if (plane_type && strcmp(p->name, "type") == 0)
			*plane_type = props->prop_values[i];
		drmModeFreeProperty(p);
	}
	drmModeFreeObjectProperties(props);
	for (size_t j = 0; j < n; j++)
		if (!ids[j])
			return -ENOENT;
	return 0;
}

/* The primary plane of the CRTC at index, with its properties: the one showing on the
 * CRTC now if there are several. 0 or -ENOENT. */
static int find_plane(struct drm_kms *k, int index, uint32_t crtc, uint32_t *plane)
{
	drmModePlaneRes *pr = drmModeGetPlaneResources(k->fd);
	uint32_t ids[PLANE_PROPS];

	*plane = 0;
	for (uint32_t i = 0; pr && i < pr->count_planes; i++) {
		drmModePlane *p = drmModeGetPlane(k->fd, pr->planes[i]);
		uint64_t type = (uint64_t)-1;
		bool on_crtc;

		if (!p)
			continue;
		on_crtc = p->crtc_id == crtc;
		if ((p->possible_crtcs & (1u << index)) &&
		    prop_ids(k->fd, p->plane_id, DRM_MODE_OBJECT_PLANE, plane_prop_names, ids,
			     PLANE_PROPS, &type) == 0 &&
		    type == DRM_PLANE_TYPE_PRIMARY && (!*plane || on_crtc)) {
			*plane = p->plane_id;
			memcpy(k->plane_prop, ids, sizeof(ids));
		}
		drmModeFreePlane(p);
		if (*plane && on_crtc)
			break;
	}
	drmModeFreePlaneResources(pr);
	return *plane ? 0 : -ENOENT;
}

/* Where atomic cannot drive this output, says so and uses the legacy calls. */
static void atomic_props(struct drm_kms *k, int index, struct drm_kms_output *out)
{
	const char *what = NULL;

	if (!k->atomic)
		return;
	if (prop_ids(k->fd, out->connector_id, DRM_MODE_OBJECT_CONNECTOR, conn_prop_names,
		     k->conn_prop, CONN_PROPS, NULL) < 0 ||
	    prop_ids(k->fd, out->crtc_id, DRM_MODE_OBJECT_CRTC, crtc_prop_names, k->crtc_prop,
		     CRTC_PROPS, NULL) < 0)
		what = "connector or CRTC properties";
	else if (find_plane(k, index, out->crtc_id, &out->plane_id) < 0)
		what = "primary plane";
	if (what) {
		fprintf(stderr, "edaha: display: no atomic %s for %s; legacy modesetting\n", what,
			out->connector);
		k->atomic = false;
		out->plane_id = 0;
	}
}

int drm_kms_pick(struct drm_kms *k, const struct drm_kms_want *want, const char *card,
		 struct error *err)
{
	drmModeRes *res = drmModeGetResources(k->fd);
	int ret = -ENODEV;

	/* render-only nodes (a Raspberry Pi's v3d) have no resources or no CRTCs */
	if (!res || res->count_crtcs <= 0 || res->count_connectors <= 0) {
		drmModeFreeResources(res);
		return error_set(err, -ENODEV, "%s cannot modeset", card);
	}
	error_set(err, -ENODEV, "%s: no connected connector%s%s", card, want->connector ? " " : "",
		  want->connector ? want->connector : "");
	for (int i = 0; i < res->count_connectors && ret < 0; i++) {
		drmModeConnector *c = drmModeGetConnector(k->fd, res->connectors[i]);
		struct drm_kms_output out = { 0 };
		const drmModeModeInfo *m;
		int index;

		if (!c)
			continue;
		connector_name(c, out.connector, sizeof(out.connector));
		if (c->connection != DRM_MODE_CONNECTED || c->count_modes <= 0 ||
		    (want->connector && strcmp(want->connector, out.connector) != 0)) {
			drmModeFreeConnector(c);
			continue;
		}
		m = drm_kms_pick_mode(c->modes, c->count_modes, want->width, want->height,
				      want->refresh, want->fallback);
		if (!m) {
			error_set(err, -ENODEV, "%s %s has no mode %dx%d@%d", card, out.connector,
				  want->width, want->height, want->refresh);
		} else if ((index = pick_crtc(k->fd, res, c)) < 0) {
			error_set(err, -ENODEV, "%s %s: no CRTC can drive it", card, out.connector);
		} else {
			out.connector_id = c->connector_id;
			out.crtc_id = res->crtcs[index];
			out.mode = *m;
			atomic_props(k, index, &out);
			k->out = out;
			ret = 0;
		}
		drmModeFreeConnector(c);
	}
	drmModeFreeResources(res);
	if (ret == 0 && !k->picked) {
		k->picked = true;
		k->saved = drmModeGetCrtc(k->fd, k->out.crtc_id);
		k->saved_connector = k->out.connector_id;
	}
	return ret;
}

/* ---- commits ---- */

static int add(drmModeAtomicReq *req, uint32_t obj, uint32_t prop, uint64_t value)
{
	return drmModeAtomicAddProperty(req, obj, prop, value) < 0 ? -ENOMEM : 0;
}

static int plane_props(struct drm_kms *k, drmModeAtomicReq *req, uint32_t fb)
{
	const struct drm_kms_output *o = &k->out;
	uint32_t p = o->plane_id, w = o->mode.hdisplay, h = o->mode.vdisplay;
	const uint64_t values[PLANE_PROPS] = {
		[PLANE_FB_ID] = fb, [PLANE_CRTC_ID] = o->crtc_id,
		[PLANE_SRC_X] = 0, [PLANE_SRC_Y] = 0,
		/* source rectangles are 16.16 fixed point */
		[PLANE_SRC_W] = (uint64_t)w << 16, [PLANE_SRC_H] = (uint64_t)h << 16,
		[PLANE_CRTC_X] = 0, [PLANE_CRTC_Y] = 0, [PLANE_CRTC_W] = w, [PLANE_CRTC_H] = h,
	};

	for (int i = 0; i < PLANE_PROPS; i++)
		if (add(req, p, k->plane_prop[i], values[i]) < 0)
			return -ENOMEM;
	return 0;
}

/* Errors that say nothing about atomic itself: not master (VT switch), interrupted. */
static bool transient(int err)
{
	return err == -EACCES || err == -EPERM || err == -EINTR || err == -EAGAIN || err == -EBUSY;
}

static int legacy_modeset(struct drm_kms *k, uint32_t fb)
{
	struct drm_kms_output *o = &k->out;

	if (drmModeSetCrtc(k->fd, o->crtc_id, fb, 0, 0, &o->connector_id, 1, &o->mode) < 0)
		return -errno;
	return 0;
}

int drm_kms_modeset(struct drm_kms *k, uint32_t fb)
{
	const struct drm_kms_output *o = &k->out;
	drmModeAtomicReq *req;
	uint32_t blob = 0;
	int ret;

	if (!k->atomic)
		return legacy_modeset(k, fb);
	req = drmModeAtomicAlloc();
	if (!req)
		return -ENOMEM;
	if (drmModeCreatePropertyBlob(k->fd, &o->mode, sizeof(o->mode), &blob) < 0) {
		ret = -errno;
		drmModeAtomicFree(req);
		return ret;
	}
	ret = add(req, o->connector_id, k->conn_prop[CONN_CRTC_ID], o->crtc_id);
	if (ret == 0)
		ret = add(req, o->crtc_id, k->crtc_prop[CRTC_MODE_ID], blob);
	if (ret == 0)
		ret = add(req, o->crtc_id, k->crtc_prop[CRTC_ACTIVE], 1);
	if (ret == 0)
		ret = plane_props(k, req, fb);
	if (ret == 0 && drmModeAtomicCommit(k->fd, req,
					    DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_ATOMIC_ALLOW_MODESET,
					    NULL) < 0) {
		ret = -errno;
		if (!transient(ret)) {
			fprintf(stderr, "edaha: display: the driver refused the atomic test commit "
				"(%s); legacy modesetting from now on\n", strerror(-ret));
			k->atomic = false;
			drmModeAtomicFree(req);
			drmModeDestroyPropertyBlob(k->fd, blob);
			return legacy_modeset(k, fb);
		}
	}
	/* blocking: the frame is on screen when it returns, as with SetCrtc */
	if (ret == 0 && drmModeAtomicCommit(k->fd, req, DRM_MODE_ATOMIC_ALLOW_MODESET, NULL) < 0)
		ret = -errno;
	drmModeAtomicFree(req);
	if (ret < 0) {
		drmModeDestroyPropertyBlob(k->fd, blob);
		return ret;
	}
	if (k->mode_blob)
		drmModeDestroyPropertyBlob(k->fd, k->mode_blob);
	k->mode_blob = blob;
	return 0;
}

int drm_kms_flip(struct drm_kms *k, uint32_t fb, void *data)
{
	drmModeAtomicReq *req;
	int ret;

	if (!k->atomic) {
		if (drmModePageFlip(k->fd, k->out.crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, data) < 0)
			return -errno;
		return 0;
	}
	req = drmModeAtomicAlloc();
	if (!req)
		return -ENOMEM;
	ret = add(req, k->out.plane_id, k->plane_prop[PLANE_FB_ID], fb);
	if (ret == 0 && drmModeAtomicCommit(k->fd, req,
					    DRM_MODE_ATOMIC_NONBLOCK | DRM_MODE_PAGE_FLIP_EVENT,
					    data) < 0)
		ret = -errno;
	drmModeAtomicFree(req);
	return ret;
}

int drm_kms_restore(struct drm_kms *k)
{
	drmModeCrtc *s = k->saved;

	if (!s)
		return 0;
	/* the legacy call for atomic clients too: the saved state is a legacy one */
	if (!s->mode_valid) /* it was off: off again */
		return drmModeSetCrtc(k->fd, s->crtc_id, 0, 0, 0, NULL, 0, NULL) < 0 ? -errno : 0;
	if (drmModeSetCrtc(k->fd, s->crtc_id, s->buffer_id, s->x, s->y, &k->saved_connector, 1,
			   &s->mode) < 0)
		return -errno;
	return 0;
}
