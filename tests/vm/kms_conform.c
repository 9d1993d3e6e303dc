// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * KMS conformance of rdcdrm.ko's card, written with libdrm: what a
 * compositor relies on, checked against the chip's own frames (the
 * FRAME ioctl of rdcdrm_ioctl.h: what the beam showed, after the CLUT,
 * gamma and cursor) and counters.
 *
 *   kms_conform [--list] [SUBTEST...]      (no SUBTEST: all of them)
 *
 * It opens the first card whose DRM driver is "rdc", becomes DRM master
 * and enables the atomic and universal-planes client caps.  Output is
 * TAP, one line per check, figures as '#' comments; the exit status is 0
 * when every check passed, 1 when one failed, 77 when nothing could run
 * (no rdc card, or every subtest asked for skipped, saying why).
 *
 * Subtests:
 *   atomic-test-only  TEST_ONLY commits: a mode and framebuffer accepted
 *                     and nothing changed; zero-size, oversized and
 *                     malformed modes, sources outside the framebuffer,
 *                     unknown objects and properties, bad flags refused
 *                     with their documented errno
 *   flip-legacy       300 page flips (drmModePageFlip with
 *   flip-atomic       DRM_MODE_PAGE_FLIP_EVENT; atomic NONBLOCK commits;
 *   flip-damage       those with FB_DAMAGE_CLIPS of the one patch where
 *                     the buffers differ, so that each flip uploads a
 *                     patch, not a frame):
 *                     no vblank missed (each event's sequence the
 *                     previous one's + 1), no frame torn (each a whole
 *                     buffer's colour, by the chip's CRC), the events as
 *                     many as the chip's frame counter advanced
 *   vblank            drmWaitVBlank relative and absolute, CRTC
 *                     GET_SEQUENCE and QUEUE_SEQUENCE: sequences as asked,
 *                     timestamps increasing about a frame period apart
 *   cursor            the cursor (legacy SetCursor/MoveCursor and the
 *                     atomic cursor plane): 64, 32 and 48 pixels, moved,
 *                     partly and wholly off-screen, hidden; each frame
 *                     equal to the ARGB cursor composited in software
 *   gamma             a legacy gamma ramp and a GAMMA_LUT blob on
 *                     XRGB8888 change the frame as computed; removing the
 *                     LUT restores it; a LUT of the wrong size is refused
 *   clut-c8           C8 with GAMMA_LUT as its palette, and a palette
 *                     change alone
 *   crc               debugfs CRCs: equal for identical frames, different
 *                     for frames one pixel apart, equal to FRAME's CRC-32
 *   damage            FB_DAMAGE_CLIPS of a small rectangle costs fewer
 *                     upload cycles than a full update; the frame shows it
 *   bad-input         framebuffers of bad format, pitch, size, handle and
 *                     flags, dumb buffers, flips and vblank requests
 *                     refused cleanly; the card still shows a picture
 *   primary-off       the primary plane off with the CRTC on: the frame is
 *                     black and frames go on; back on, its picture whole
 *   host-cost         (paced clock) the chip's share of a CPU at
 *                     1024x768@60 idle, with the CRC looking, and flipping
 *                     every frame, with flips a second: figures; checked:
 *                     the counters move with time, scanout on demand is
 *                     idle exactly while nothing looks
 *
 * Frames are checked at the smallest mode the connector offers (the
 * chip's scanout is simulated, and smaller is faster under emulation).
 */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <poll.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <time.h>
#include <unistd.h>

#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#include <zlib.h>

#include "rdc_regs.h"
#include "rdcdrm_ioctl.h"
#include "tap.h"

#define FLIP_FRAMES   300
#define FLIP_BUFS     3
#define EVENT_MS      5000 /* an event later than this is lost */
#define SETTLE_FRAMES 2	   /* frames after a commit before its frame */
#define SETTLE_MAX    400  /* vblanks waited for a frame at most */
#define RGB_MASK      0x00ffffffu

struct plane_props {
	uint32_t fb_id, crtc_id, src_x, src_y, src_w, src_h;
	uint32_t crtc_x, crtc_y, crtc_w, crtc_h, damage;
};

struct kms {
	int fd;
	char debugfs[128]; /* /sys/kernel/debug/dri/N, or "" */
	uint32_t conn_id, crtc_id, crtc_idx, primary_id, cursor_id;
	uint32_t conn_crtc, mode_id, active, gamma_lut, gamma_size;
	struct plane_props pp, cp;
	drmModeModeInfo mode;
	uint32_t mode_blob;
	uint32_t w, h;
	uint32_t *frame; /* w * h, the last grab */
	uint64_t max_w, max_h;
	bool has_c8;
	bool stepped;	 /* rdcdrm's clock=stepped */
	char sysdev[64]; /* /sys/class/drm/cardN/device */
};

struct dumb {
	uint32_t w, h, pitch, handle, fb, fourcc;
	uint64_t size;
	uint8_t *map;
};

/* The event handlers' record. */
struct events {
	unsigned int flips, seqs;
	unsigned int seq;   /* last flip event's */
	uint64_t ns;	    /* its time */
	uint64_t qseq, qns; /* last sequence event's */
	uint64_t quser;
};

static struct events ev;

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* ---- Setup ------------------------------------------------------------- */

static uint32_t prop_id(int fd, uint32_t obj, uint32_t type, const char *name,
			uint64_t *value)
{
	drmModeObjectPropertiesPtr p =
		drmModeObjectGetProperties(fd, obj, type);
	uint32_t id = 0;

	if (!p)
		return 0;
	for (uint32_t i = 0; i < p->count_props && !id; i++) {
		drmModePropertyPtr d = drmModeGetProperty(fd, p->props[i]);

		if (d && !strcmp(d->name, name)) {
			id = d->prop_id;
			if (value)
				*value = p->prop_values[i];
		}
		drmModeFreeProperty(d);
	}
	drmModeFreeObjectProperties(p);
	return id;
}

static void plane_props(int fd, uint32_t plane, struct plane_props *pp)
{
	uint32_t t = DRM_MODE_OBJECT_PLANE;

	pp->fb_id = prop_id(fd, plane, t, "FB_ID", NULL);
	pp->crtc_id = prop_id(fd, plane, t, "CRTC_ID", NULL);
	pp->src_x = prop_id(fd, plane, t, "SRC_X", NULL);
	pp->src_y = prop_id(fd, plane, t, "SRC_Y", NULL);
	pp->src_w = prop_id(fd, plane, t, "SRC_W", NULL);
	pp->src_h = prop_id(fd, plane, t, "SRC_H", NULL);
	pp->crtc_x = prop_id(fd, plane, t, "CRTC_X", NULL);
	pp->crtc_y = prop_id(fd, plane, t, "CRTC_Y", NULL);
	pp->crtc_w = prop_id(fd, plane, t, "CRTC_W", NULL);
	pp->crtc_h = prop_id(fd, plane, t, "CRTC_H", NULL);
	pp->damage = prop_id(fd, plane, t, "FB_DAMAGE_CLIPS", NULL);
}

/* The first card of DRM driver "rdc", opened; -1 if none. */
static int open_rdc(char *path, size_t cap)
{
	for (int i = 0; i < 64; i++) {
		drmVersionPtr v;
		int fd;

		snprintf(path, cap, DRM_DIR_NAME "/card%d", i);
		fd = open(path, O_RDWR | O_CLOEXEC);
		if (fd < 0)
			continue;
		v = drmGetVersion(fd);
		if (v && v->name && !strcmp(v->name, DRM_RDC_DRIVER_NAME)) {
			drmFreeVersion(v);
			return fd;
		}
		drmFreeVersion(v);
		close(fd);
	}
	return -1;
}

/* debugfs's directory of the card (its "name" file names the driver). */
static void find_debugfs(struct kms *k)
{
	struct stat st;
	char minor_dir[64];
	FILE *f;

	if (stat("/sys/kernel/debug/dri", &st))
		mount("debugfs", "/sys/kernel/debug", "debugfs", 0, NULL);
	if (fstat(k->fd, &st))
		return;
	snprintf(minor_dir, sizeof(minor_dir), "/sys/kernel/debug/dri/%u",
		 minor(st.st_rdev));
	snprintf(k->debugfs, sizeof(k->debugfs), "%s/name", minor_dir);
	f = fopen(k->debugfs, "r");
	k->debugfs[0] = 0;
	if (f) {
		char line[256] = "";

		if (fgets(line, sizeof(line), f) &&
		    !strncmp(line, DRM_RDC_DRIVER_NAME " ", 4))
			snprintf(k->debugfs, sizeof(k->debugfs), "%s",
				 minor_dir);
		fclose(f);
	}
}

static int kms_setup(struct kms *k)
{
	drmModeResPtr res;
	drmModePlaneResPtr pres;
	drmModeConnectorPtr conn = NULL;
	char path[64];
	uint64_t cap = 0;

	memset(k, 0, sizeof(*k));
	k->fd = open_rdc(path, sizeof(path));
	if (k->fd < 0) {
		printf("# no DRM card of driver '%s' (rdcdrm.ko not loaded?)\n",
		       DRM_RDC_DRIVER_NAME);
		return 77;
	}
	printf("# %s\n", path);
	snprintf(k->sysdev, sizeof(k->sysdev), "/sys/class/drm/%s/device",
		 strrchr(path, '/') + 1);
	if (drmSetMaster(k->fd) && !drmIsMaster(k->fd)) {
		printf("# cannot become DRM master: %s\n", strerror(errno));
		return 1;
	}
	if (drmSetClientCap(k->fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) ||
	    drmSetClientCap(k->fd, DRM_CLIENT_CAP_ATOMIC, 1)) {
		printf("# atomic client caps refused: %s\n", strerror(errno));
		return 1;
	}
	res = drmModeGetResources(k->fd);
	if (!res)
		return 1;
	k->max_w = res->max_width;
	k->max_h = res->max_height;
	{
		FILE *f = fopen("/sys/module/rdcdrm/parameters/clock", "r");
		char clk[16] = "";

		if (f) {
			if (!fgets(clk, sizeof(clk), f))
				clk[0] = 0;
			fclose(f);
		}
		k->stepped = !strncmp(clk, "stepped", 7);
		printf("# clock %s\n", k->stepped ? "stepped" : "paced");
	}
	for (int i = 0; i < res->count_connectors && !k->conn_id; i++) {
		conn = drmModeGetConnector(k->fd, res->connectors[i]);
		if (conn && conn->connection == DRM_MODE_CONNECTED &&
		    conn->count_modes > 0)
			k->conn_id = conn->connector_id;
		else
			drmModeFreeConnector(conn);
	}
	if (!k->conn_id || !res->count_crtcs) {
		printf("# no connected connector with modes\n");
		drmModeFreeResources(res);
		return 1;
	}
	/* the smallest mode: frames are simulated, smaller is faster */
	k->mode = conn->modes[0];
	for (int i = 1; i < conn->count_modes; i++)
		if ((uint32_t)conn->modes[i].hdisplay *
			    conn->modes[i].vdisplay <
		    (uint32_t)k->mode.hdisplay * k->mode.vdisplay)
			k->mode = conn->modes[i];
	drmModeFreeConnector(conn);
	k->crtc_idx = 0;
	k->crtc_id = res->crtcs[0];
	drmModeFreeResources(res);
	k->w = k->mode.hdisplay;
	k->h = k->mode.vdisplay;
	printf("# mode %s %ux%u@%u (clock %u kHz, total %ux%u)\n", k->mode.name,
	       k->w, k->h, k->mode.vrefresh, k->mode.clock, k->mode.htotal,
	       k->mode.vtotal);

	pres = drmModeGetPlaneResources(k->fd);
	for (uint32_t i = 0; pres && i < pres->count_planes; i++) {
		drmModePlanePtr p = drmModeGetPlane(k->fd, pres->planes[i]);
		uint64_t type = 0;

		if (!p)
			continue;
		if (p->possible_crtcs & (1u << k->crtc_idx) &&
		    prop_id(k->fd, p->plane_id, DRM_MODE_OBJECT_PLANE, "type",
			    &type)) {
			if (type == DRM_PLANE_TYPE_PRIMARY && !k->primary_id) {
				k->primary_id = p->plane_id;
				for (uint32_t f = 0; f < p->count_formats; f++)
					if (p->formats[f] == DRM_FORMAT_C8)
						k->has_c8 = true;
			}
			if (type == DRM_PLANE_TYPE_CURSOR && !k->cursor_id)
				k->cursor_id = p->plane_id;
		}
		drmModeFreePlane(p);
	}
	drmModeFreePlaneResources(pres);
	if (!k->primary_id) {
		printf("# no primary plane\n");
		return 1;
	}
	plane_props(k->fd, k->primary_id, &k->pp);
	if (k->cursor_id)
		plane_props(k->fd, k->cursor_id, &k->cp);
	k->conn_crtc = prop_id(k->fd, k->conn_id, DRM_MODE_OBJECT_CONNECTOR,
			       "CRTC_ID", NULL);
	k->mode_id = prop_id(k->fd, k->crtc_id, DRM_MODE_OBJECT_CRTC, "MODE_ID",
			     NULL);
	k->active = prop_id(k->fd, k->crtc_id, DRM_MODE_OBJECT_CRTC, "ACTIVE",
			    NULL);
	k->gamma_lut = prop_id(k->fd, k->crtc_id, DRM_MODE_OBJECT_CRTC,
			       "GAMMA_LUT", NULL);
	cap = 0;
	if (prop_id(k->fd, k->crtc_id, DRM_MODE_OBJECT_CRTC, "GAMMA_LUT_SIZE",
		    &cap))
		k->gamma_size = (uint32_t)cap;
	if (drmModeCreatePropertyBlob(k->fd, &k->mode, sizeof(k->mode),
				      &k->mode_blob))
		return 1;
	k->frame = calloc((size_t)k->w * k->h, sizeof(uint32_t));
	if (!k->frame)
		return 1;
	find_debugfs(k);
	return 0;
}

/* ---- Buffers ----------------------------------------------------------- */

static int dumb_new(struct kms *k, uint32_t w, uint32_t h, uint32_t fourcc,
		    struct dumb *d)
{
	uint32_t bpp = fourcc == DRM_FORMAT_C8 ? 8 : 32;
	struct drm_mode_create_dumb c = { .width = w, .height = h, .bpp = bpp };
	struct drm_mode_map_dumb m = { 0 };
	uint32_t handles[4] = { 0 }, pitches[4] = { 0 }, offsets[4] = { 0 };
	void *p;

	memset(d, 0, sizeof(*d));
	if (drmIoctl(k->fd, DRM_IOCTL_MODE_CREATE_DUMB, &c))
		return -errno;
	d->w = w;
	d->h = h;
	d->fourcc = fourcc;
	d->pitch = c.pitch;
	d->handle = c.handle;
	d->size = c.size;
	m.handle = c.handle;
	if (drmIoctl(k->fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
		return -errno;
	p = mmap(NULL, d->size, PROT_READ | PROT_WRITE, MAP_SHARED, k->fd,
		 (off_t)m.offset);
	if (p == MAP_FAILED)
		return -errno;
	d->map = p;
	memset(d->map, 0, d->size);
	handles[0] = d->handle;
	pitches[0] = d->pitch;
	if (drmModeAddFB2(k->fd, w, h, fourcc, handles, pitches, offsets,
			  &d->fb, 0))
		return -errno;
	return 0;
}

static void dumb_free(struct kms *k, struct dumb *d)
{
	if (d->fb)
		drmModeRmFB(k->fd, d->fb);
	if (d->map)
		munmap(d->map, d->size);
	if (d->handle) {
		struct drm_mode_destroy_dumb x = { .handle = d->handle };

		drmIoctl(k->fd, DRM_IOCTL_MODE_DESTROY_DUMB, &x);
	}
	memset(d, 0, sizeof(*d));
}

static uint32_t *px(struct dumb *d, uint32_t x, uint32_t y)
{
	return (uint32_t *)(d->map + (size_t)y * d->pitch) + x;
}

/* A picture of its own for each seed: gradients and a seeded grid. */
static void paint(struct dumb *d, uint32_t seed)
{
	for (uint32_t y = 0; y < d->h; y++)
		for (uint32_t x = 0; x < d->w; x++) {
			uint32_t r = (x * 255 / (d->w ? d->w : 1)) ^ seed;
			uint32_t g = (y * 255 / (d->h ? d->h : 1)) + seed * 7;
			uint32_t b = ((x / 8 + y / 8) & 1) ? 0xc0 : 0x30;

			*px(d, x, y) = 0xff000000u | (r & 255) << 16 |
				       (g & 255) << 8 | ((b + seed) & 255);
		}
}

static void fill(struct dumb *d, uint32_t rgb)
{
	for (uint32_t y = 0; y < d->h; y++)
		for (uint32_t x = 0; x < d->w; x++)
			*px(d, x, y) = 0xff000000u | rgb;
}

/* ---- Commits ----------------------------------------------------------- */

static void add(drmModeAtomicReqPtr r, uint32_t obj, uint32_t prop, uint64_t v)
{
	if (prop)
		drmModeAtomicAddProperty(r, obj, prop, v);
}

/* The primary plane showing fb (full screen) on the CRTC at k->mode. */
static void add_primary(struct kms *k, drmModeAtomicReqPtr r, uint32_t fb,
			uint32_t fw, uint32_t fh)
{
	add(r, k->conn_id, k->conn_crtc, k->crtc_id);
	add(r, k->crtc_id, k->mode_id, k->mode_blob);
	add(r, k->crtc_id, k->active, 1);
	add(r, k->primary_id, k->pp.fb_id, fb);
	add(r, k->primary_id, k->pp.crtc_id, k->crtc_id);
	add(r, k->primary_id, k->pp.src_x, 0);
	add(r, k->primary_id, k->pp.src_y, 0);
	add(r, k->primary_id, k->pp.src_w, (uint64_t)fw << 16);
	add(r, k->primary_id, k->pp.src_h, (uint64_t)fh << 16);
	add(r, k->primary_id, k->pp.crtc_x, 0);
	add(r, k->primary_id, k->pp.crtc_y, 0);
	add(r, k->primary_id, k->pp.crtc_w, k->w);
	add(r, k->primary_id, k->pp.crtc_h, k->h);
}

/* Commit r with flags: 0 or -errno.  Frees r. */
static int commit(struct kms *k, drmModeAtomicReqPtr r, uint32_t flags)
{
	int ret = drmModeAtomicCommit(k->fd, r, flags, NULL) ? -errno : 0;

	drmModeAtomicFree(r);
	return ret;
}

/* Show fb on the primary plane (a blocking commit). */
static int show(struct kms *k, struct dumb *d)
{
	drmModeAtomicReqPtr r = drmModeAtomicAlloc();

	add_primary(k, r, d->fb, d->w, d->h);
	return commit(k, r, DRM_MODE_ATOMIC_ALLOW_MODESET);
}

/* ---- The chip's side ----------------------------------------------------- */

static int rdc_frame(struct kms *k, uint32_t *buf, struct drm_rdc_frame *fr)
{
	memset(fr, 0, sizeof(*fr));
	fr->pixels = (uintptr_t)buf;
	fr->cap = buf ? k->w * k->h : 0;
	return drmIoctl(k->fd, DRM_IOCTL_RDC_FRAME, fr) ? -errno : 0;
}

static int rdc_counters(struct kms *k, struct drm_rdc_counters *c)
{
	memset(c, 0, sizeof(*c));
	return drmIoctl(k->fd, DRM_IOCTL_RDC_COUNTERS, c) ? -errno : 0;
}

static int wait_vblank_rel(struct kms *k, unsigned int n, drmVBlank *out)
{
	drmVBlank v;

	memset(&v, 0, sizeof(v));
	v.request.type = DRM_VBLANK_RELATIVE;
	v.request.sequence = n;
	if (drmWaitVBlank(k->fd, &v))
		return -errno;
	if (out)
		*out = v;
	return 0;
}

static int rdc_reg_read(struct kms *k, uint32_t reg, uint32_t *val)
{
	struct drm_rdc_reg r = { .reg = reg };

	if (drmIoctl(k->fd, DRM_IOCTL_RDC_REG_READ, &r))
		return -errno;
	*val = r.val;
	return 0;
}

/*
 * Until the chip's next vblank: a DRM vblank wait on the paced clock; on
 * the stepped one, where only the chip's own waits move time, a WAIT for
 * FRAME_COUNT to pass its value now.
 */
static int next_frame(struct kms *k)
{
	struct drm_rdc_wait w = { 0 };
	uint32_t n = 0;
	int ret;

	if (!k->stepped)
		return wait_vblank_rel(k, 1, NULL);
	ret = rdc_reg_read(k, RDC_REG_FRAME_COUNT, &n);
	if (ret)
		return ret;
	w.term[0].kind = DRM_RDC_WAIT_WRAP_GE;
	w.term[0].reg = RDC_REG_FRAME_COUNT;
	w.term[0].mask = ~0u;
	w.term[0].value = n + 1;
	return drmIoctl(k->fd, DRM_IOCTL_RDC_WAIT, &w) ? -errno : 0;
}

/*
 * The chip's frame once SETTLE_FRAMES whole frames have been scanned out
 * after now, into k->frame: what a commit that has returned shows.
 */
static int settle(struct kms *k, struct drm_rdc_frame *fr)
{
	uint64_t want;
	int ret = rdc_frame(k, NULL, fr);

	if (ret && ret != -EAGAIN)
		return ret;
	want = (ret ? 0 : fr->seq) + SETTLE_FRAMES;
	for (int i = 0; i < SETTLE_MAX; i++) {
		ret = rdc_frame(k, NULL, fr);
		if (!ret && fr->seq >= want)
			break;
		if (next_frame(k))
			usleep(5000); /* the CRTC is off: no vblank to wait for */
	}
	ret = rdc_frame(k, k->frame, fr);
	if (!ret && (fr->width != k->w || fr->height != k->h))
		return -EBADMSG;
	return ret;
}

/*
 * Compare k->frame with `want` (w * h, RGB only): the number of pixels
 * that differ; the first is described as a comment.
 */
static size_t frame_diff(struct kms *k, const uint32_t *want, const char *what)
{
	size_t bad = 0;

	for (uint32_t y = 0; y < k->h; y++)
		for (uint32_t x = 0; x < k->w; x++) {
			uint32_t a = k->frame[(size_t)y * k->w + x] & RGB_MASK;
			uint32_t b = want[(size_t)y * k->w + x] & RGB_MASK;

			if (a != b && !bad++)
				printf("#   %s: first difference at (%u,%u): "
				       "frame %06x, expected %06x\n",
				       what, x, y, a, b);
		}
	if (bad)
		printf("#   %s: %zu pixels differ\n", what, bad);
	return bad;
}

/* The expected frame of an XRGB8888 buffer shown whole. */
static void expect_xrgb(struct kms *k, struct dumb *d, uint32_t *want)
{
	for (uint32_t y = 0; y < k->h; y++)
		for (uint32_t x = 0; x < k->w; x++)
			want[(size_t)y * k->w + x] = *px(d, x, y) & RGB_MASK;
}

static uint32_t *want_new(struct kms *k)
{
	uint32_t *w = calloc((size_t)k->w * k->h, sizeof(uint32_t));

	if (!w) {
		perror("kms_conform");
		exit(1);
	}
	return w;
}

/* ---- Events ------------------------------------------------------------ */

static void on_flip(int fd, unsigned int seq, unsigned int sec,
		    unsigned int usec, unsigned int crtc, void *data)
{
	(void)fd;
	(void)crtc;
	(void)data;
	ev.flips++;
	ev.seq = seq;
	ev.ns = (uint64_t)sec * 1000000000u + (uint64_t)usec * 1000u;
}

static void on_seq(int fd, uint64_t seq, uint64_t ns, uint64_t user)
{
	(void)fd;
	ev.seqs++;
	ev.qseq = seq;
	ev.qns = ns;
	ev.quser = user;
}

/* Handle events until *count grows, at most EVENT_MS: 0 or -ETIMEDOUT. */
static int wait_event(struct kms *k, unsigned int *count)
{
	drmEventContext ctx = {
		.version = 4,
		.page_flip_handler2 = on_flip,
		.sequence_handler = on_seq,
	};
	unsigned int c0 = *count;
	uint64_t end = now_ns() + (uint64_t)EVENT_MS * 1000000u;

	while (*count == c0) {
		struct pollfd p = { .fd = k->fd, .events = POLLIN };
		uint64_t t = now_ns();
		int r;

		if (t >= end)
			return -ETIMEDOUT;
		r = poll(&p, 1, (int)((end - t) / 1000000u) + 1);
		if (r < 0 && errno != EINTR)
			return -errno;
		if (r > 0 && drmHandleEvent(k->fd, &ctx))
			return -EIO;
	}
	return 0;
}

/* ---- atomic-test-only ---------------------------------------------------- */

static int expect_err(int got, int want, const char *what)
{
	tap(got == want, "%s: %s (%s expected)", what,
	    got ? strerror(-got) : "accepted",
	    want ? strerror(-want) : "accepted");
	return got == want;
}

/* A TEST_ONLY commit of the primary with `mode`: 0 or -errno. */
static int test_mode(struct kms *k, const drmModeModeInfo *mode, struct dumb *d)
{
	drmModeAtomicReqPtr r = drmModeAtomicAlloc();
	uint32_t blob = 0;
	int ret;

	if (drmModeCreatePropertyBlob(k->fd, mode, sizeof(*mode), &blob)) {
		drmModeAtomicFree(r);
		return -errno;
	}
	add_primary(k, r, d->fb, d->w, d->h);
	add(r, k->crtc_id, k->mode_id, blob);
	add(r, k->primary_id, k->pp.crtc_w, mode->hdisplay);
	add(r, k->primary_id, k->pp.crtc_h, mode->vdisplay);
	ret = commit(k, r,
		     DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_ATOMIC_ALLOW_MODESET);
	drmModeDestroyPropertyBlob(k->fd, blob);
	return ret;
}

static int st_atomic_test_only(struct kms *k)
{
	struct dumb a, b;
	drmModeModeInfo m;
	drmModeAtomicReqPtr r;
	struct drm_rdc_counters c0, c1;
	drmModePlanePtr pl;
	int ret;

	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &a) ||
	    dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &b))
		return tap(0, "atomic-test-only: buffers"), 1;
	paint(&a, 1);
	paint(&b, 2);
	tap(show(k, &a) == 0, "atomic-test-only: a real commit to start from");
	rdc_counters(k, &c0);

	/* the valid mode and buffer: accepted, nothing changes */
	expect_err(test_mode(k, &k->mode, &b), 0,
		   "TEST_ONLY of the connector's mode with a new buffer");
	pl = drmModeGetPlane(k->fd, k->primary_id);
	tap(pl && pl->fb_id == a.fb,
	    "TEST_ONLY left the primary plane on its buffer (%u, not %u)",
	    pl ? pl->fb_id : 0, b.fb);
	drmModeFreePlane(pl);
	rdc_counters(k, &c1);
	tap(c1.flips == c0.flips,
	    "TEST_ONLY latched no flip (%" PRIu64 " -> %" PRIu64 ")",
	    (uint64_t)c0.flips, (uint64_t)c1.flips);

	/* modes */
	m = k->mode;
	m.hdisplay = m.vdisplay = 0;
	expect_err(test_mode(k, &m, &a), -EINVAL, "zero-size mode");
	m = k->mode;
	m.clock = 0;
	expect_err(test_mode(k, &m, &a), -EINVAL, "mode of pixel clock 0");
	m = k->mode;
	m.hsync_start = m.hdisplay - 1; /* sync inside the picture */
	expect_err(test_mode(k, &m, &a), -EINVAL,
		   "mode with hsync_start < hdisplay");
	m = k->mode;
	m.vtotal = m.vdisplay - 1;
	expect_err(test_mode(k, &m, &a), -EINVAL,
		   "mode with vtotal < vdisplay");
	m = k->mode;
	m.hdisplay = m.hsync_start = m.hsync_end = m.htotal = 16000;
	m.vdisplay = m.vsync_start = m.vsync_end = m.vtotal = 12000;
	m.clock = 1000000;
	snprintf(m.name, sizeof(m.name), "16000x12000");
	expect_err(test_mode(k, &m, &a), -EINVAL, "oversized mode 16000x12000");
	/* sources and objects */
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w + 16, a.h);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -ENOSPC,
		   "a source wider than the framebuffer");
	r = drmModeAtomicAlloc();
	add_primary(k, r, 0xfffff0u, a.w, a.h);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -EINVAL,
		   "FB_ID of no framebuffer");
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w, a.h);
	drmModeAtomicAddProperty(r, 0xfffff1u, k->pp.fb_id, a.fb);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -ENOENT,
		   "a property of no object");
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w, a.h);
	drmModeAtomicAddProperty(r, k->primary_id, 0xfffff2u, 1);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -ENOENT,
		   "a property id that does not exist");
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w, a.h);
	add(r, k->crtc_id, k->mode_id, 0xfffff3u);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -EINVAL,
		   "MODE_ID of no blob");

	/* a framebuffer that does not fit the plane */
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w / 2, a.h / 2);
	ret = commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY);
	tap(ret == -ERANGE || ret == -EINVAL,
	    "half the framebuffer scaled to the whole CRTC: %s (ERANGE or "
	    "EINVAL expected: the chip does not scale)",
	    ret ? strerror(-ret) : "accepted");
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w / 2, a.h / 2);
	add(r, k->primary_id, k->pp.crtc_w, k->w / 2);
	add(r, k->primary_id, k->pp.crtc_h, k->h / 2);
	ret = commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY);
	tap(ret == -EINVAL || ret == -ERANGE,
	    "a primary plane covering a quarter of the CRTC: %s (EINVAL "
	    "expected: the chip's picture is the whole screen)",
	    ret ? strerror(-ret) : "accepted");
	if (k->cursor_id) {
		r = drmModeAtomicAlloc();
		add_primary(k, r, a.fb, a.w, a.h);
		add(r, k->cursor_id, k->cp.fb_id, a.fb); /* XRGB8888 */
		add(r, k->cursor_id, k->cp.crtc_id, k->crtc_id);
		add(r, k->cursor_id, k->cp.src_w, 64u << 16);
		add(r, k->cursor_id, k->cp.src_h, 64u << 16);
		add(r, k->cursor_id, k->cp.crtc_w, 64);
		add(r, k->cursor_id, k->cp.crtc_h, 64);
		expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY), -EINVAL,
			   "an XRGB8888 framebuffer on the ARGB8888 cursor "
			   "plane");
	}

	/* flags */
	r = drmModeAtomicAlloc();
	add_primary(k, r, a.fb, a.w, a.h);
	expect_err(commit(k, r, DRM_MODE_ATOMIC_TEST_ONLY | 0x40000000u),
		   -EINVAL, "an unknown flag");
	r = drmModeAtomicAlloc();
	add_primary(k, r, b.fb, b.w, b.h);
	expect_err(commit(k, r,
			  DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_PAGE_FLIP_EVENT),
		   -EINVAL, "TEST_ONLY with PAGE_FLIP_EVENT");
	r = drmModeAtomicAlloc();
	add_primary(k, r, b.fb, b.w, b.h);
	expect_err(commit(k, r,
			  DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_PAGE_FLIP_ASYNC),
		   -EINVAL, "PAGE_FLIP_ASYNC (no async flips)");

	pl = drmModeGetPlane(k->fd, k->primary_id);
	tap(pl && pl->fb_id == a.fb, "after all that the plane still shows "
				     "the first buffer");
	drmModeFreePlane(pl);
	dumb_free(k, &b);
	dumb_free(k, &a);
	return 0;
}

/* ---- Flips ---------------------------------------------------------------- */

static uint64_t period_ns(struct kms *k)
{
	return (uint64_t)k->mode.htotal * k->mode.vtotal * 1000000u /
	       (k->mode.clock ? k->mode.clock : 1);
}

/* The chip's frame counter and the CRTC's vblank count, read together. */
static int frames_vs_vblank(struct kms *k, int64_t *offset)
{
	for (int i = 0; i < 20; i++) {
		struct drm_rdc_counters c;
		uint64_t s0, s1, ns;

		if (drmCrtcGetSequence(k->fd, k->crtc_id, &s0, &ns) ||
		    rdc_counters(k, &c) ||
		    drmCrtcGetSequence(k->fd, k->crtc_id, &s1, &ns))
			return -errno;
		if (s0 == s1) {
			*offset = (int64_t)(c.frames - s0);
			return 0;
		}
	}
	return -EAGAIN;
}

/* How the flips go: legacy or atomic, whole pictures or a damaged patch. */
enum flip_kind { FLIP_LEGACY, FLIP_ATOMIC, FLIP_DAMAGE };

/* The patch that tells the buffers of flip-damage apart. */
#define FLIP_PATCH 16

/* A flip to d with an event; damage: the FB_DAMAGE_CLIPS blob, or 0. */
static int flip_to(struct kms *k, struct dumb *d, enum flip_kind kind,
		   uint32_t damage)
{
	if (kind != FLIP_LEGACY) {
		drmModeAtomicReqPtr r = drmModeAtomicAlloc();

		add(r, k->primary_id, k->pp.fb_id, d->fb);
		if (damage)
			add(r, k->primary_id, k->pp.damage, damage);
		return commit(k, r,
			      DRM_MODE_ATOMIC_NONBLOCK |
				      DRM_MODE_PAGE_FLIP_EVENT);
	}
	return drmModePageFlip(k->fd, k->crtc_id, d->fb,
			       DRM_MODE_PAGE_FLIP_EVENT, NULL) ?
		       -errno :
		       0;
}

/*
 * FLIP_FRAMES flips through FLIP_BUFS buffers, each flip issued as soon as
 * the previous one's event arrives.  FLIP_LEGACY and FLIP_ATOMIC flip
 * between whole pictures of their own colour, so each flip uploads a
 * whole frame; FLIP_DAMAGE between buffers that differ only in a patch of
 * their own colour, each flip saying so in FB_DAMAGE_CLIPS (as a
 * compositor does), so each uploads the patch: whether a flip makes the
 * next vblank then does not hang on how fast the machine simulates a
 * whole frame's upload.
 */
static int st_flip(struct kms *k, enum flip_kind kind)
{
	const char *name = kind == FLIP_LEGACY ? "flip-legacy" :
			   kind == FLIP_ATOMIC ? "flip-atomic" :
						 "flip-damage";
	struct drm_mode_rect patch = { 8, 8, 8 + FLIP_PATCH, 8 + FLIP_PATCH };
	uint32_t damage = 0;
	static const uint32_t colour[FLIP_BUFS] = { 0xc03020, 0x20c040,
						    0x3050d0 };
	struct dumb d[FLIP_BUFS];
	uint32_t crc[FLIP_BUFS];
	uint32_t *want = want_new(k);
	unsigned int missed = 0, torn = 0, events = 0, shown[FLIP_BUFS] = { 0 };
	unsigned int first = 0, prev = 0, late = 0;
	uint64_t chip_first = 0, chip_last = 0, t0, lat = 0, prev_ns = 0;
	uint64_t flips_first = 0, flips_last = 0;
	int64_t off0 = 0, off1 = 0;
	struct drm_rdc_frame fr;
	struct drm_rdc_counters c;
	int ret = 0, ok = 1;

	for (int i = 0; i < FLIP_BUFS; i++) {
		if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &d[i])) {
			tap(0, "%s: buffers", name);
			return 1;
		}
		if (kind == FLIP_DAMAGE) {
			fill(&d[i], 0x404040);
			for (int y = patch.y1; y < patch.y2; y++)
				for (int x = patch.x1; x < patch.x2; x++)
					*px(&d[i], (uint32_t)x, (uint32_t)y) =
						0xff000000u | colour[i];
		} else {
			fill(&d[i], colour[i]);
		}
		/* the chip's CRC of each picture, its pixels checked once */
		expect_xrgb(k, &d[i], want);
		if (show(k, &d[i]) || settle(k, &fr) ||
		    frame_diff(k, want, name)) {
			ok = 0;
			crc[i] = 0;
		} else {
			crc[i] = fr.crc32;
		}
	}
	tap(ok,
	    "%s: each buffer shown alone is its picture (CRCs %08x "
	    "%08x %08x)",
	    name, crc[0], crc[1], crc[2]);
	free(want);
	if (!ok)
		goto out;
	if (kind == FLIP_DAMAGE &&
	    drmModeCreatePropertyBlob(k->fd, &patch, sizeof(patch), &damage)) {
		tap(0, "%s: the damage blob: %s", name, strerror(errno));
		goto out;
	}

	ev.flips = 0;
	t0 = now_ns();
	for (unsigned int i = 1; i <= FLIP_FRAMES; i++) {
		uint64_t t = now_ns();

		ret = flip_to(k, &d[i % FLIP_BUFS], kind, damage);
		if (ret) {
			printf("#   flip %u: %s\n", i, strerror(-ret));
			break;
		}
		ret = wait_event(k, &ev.flips);
		lat += now_ns() - t;
		if (ret) {
			printf("#   flip %u: no event within %d ms\n", i,
			       EVENT_MS);
			break;
		}
		events++;
		if (i == 1) {
			first = ev.seq;
			if (frames_vs_vblank(k, &off0))
				off0 = INT64_MIN;
			rdc_counters(k, &c);
			chip_first = c.frames;
			flips_first = c.flips;
		} else if (ev.seq != prev + 1) {
			/* when it was asked for, against the vblank it
			 * missed (the previous event's time + a frame) */
			int64_t early =
				(int64_t)(prev_ns + period_ns(k)) - (int64_t)t;

			if (early <= 0)
				late++;
			if (missed < 5)
				printf("#   flip %u: event sequence %u after "
				       "%u; asked for %.2f ms %s the vblank "
				       "it missed\n",
				       i, ev.seq, prev,
				       (double)(early < 0 ? -early : early) /
					       1e6,
				       early > 0 ? "before" : "after");
			missed += ev.seq > prev ? ev.seq - prev - 1 : 1;
		}
		prev = ev.seq;
		prev_ns = ev.ns;
		/* the last whole frame: one buffer's picture, no mix */
		if (!rdc_frame(k, NULL, &fr)) {
			int b = -1;

			for (int j = 0; j < FLIP_BUFS; j++)
				if (fr.crc32 == crc[j])
					b = j;
			if (b < 0) {
				if (torn < 5)
					printf("#   flip %u: frame %" PRIu64
					       " (CRC %08x) is no buffer's "
					       "picture\n",
					       i, (uint64_t)fr.seq, fr.crc32);
				torn++;
			} else {
				shown[b]++;
			}
		} else {
			torn++;
		}
	}
	if (!ret) {
		if (frames_vs_vblank(k, &off1))
			off1 = INT64_MAX;
		rdc_counters(k, &c);
		chip_last = c.frames;
		flips_last = c.flips;
	}
	printf("#   %u flips in %.2f s wall, %.2f ms from a flip's ioctl to "
	       "its event on average (a frame: %.2f ms); frames of each "
	       "buffer %u %u %u; chip frames %" PRIu64 " -> %" PRIu64 "\n",
	       events, (double)(now_ns() - t0) / 1e9,
	       events ? (double)lat / events / 1e6 : 0.0,
	       (double)period_ns(k) / 1e6, shown[0], shown[1], shown[2],
	       chip_first, chip_last);
	tap(!ret && events == FLIP_FRAMES,
	    "%s: %u flips completed with an event each", name, events);
	if (missed)
		printf("#   of the flips that missed a vblank, %u were asked "
		       "for only after it (the paced clock catching up, or "
		       "this program late), the others before it\n",
		       late);
	/*
	 * On the paced clock whether a flip makes its vblank depends on
	 * how fast this machine simulates the upload against wall time
	 * (under QEMU's TCG a whole 320x200 frame takes longer than a
	 * frame): a figure, not a verdict.  On the stepped clock wall time
	 * plays no part, and every flip must make the next vblank.
	 */
	if (k->stepped)
		tap(!ret && missed == 0,
		    "%s: 0 missed (each event's sequence the previous + "
		    "1): %u missed, sequences %u..%u",
		    name, missed, first, prev);
	else
		printf("#   %s: %u vblanks missed over %u flips on the paced "
		       "clock (a figure), sequences %u..%u\n",
		       name, missed, events, first, prev);
	tap(!ret && torn == 0,
	    "%s: 0 torn (every frame one buffer's picture): %u torn", name,
	    torn);
	tap(!ret && events && flips_last - flips_first + 1 == events,
	    "%s: the chip latched one flip an event (COUNTERS.flips %" PRIu64
	    " -> %" PRIu64 ")",
	    name, flips_first, flips_last);
	tap(!ret && off0 == off1 && (!k->stepped || prev - first + 1 == events),
	    "%s: %u events over %u vblanks, and the chip's frame counter "
	    "advanced %" PRId64 " frames over them (vblank offset %" PRId64
	    " -> %" PRId64 ")",
	    name, events, prev - first + 1,
	    (int64_t)(prev - first) + 1 + (off1 - off0), off0, off1);
out:
	if (damage)
		drmModeDestroyPropertyBlob(k->fd, damage);
	for (int i = 0; i < FLIP_BUFS; i++)
		dumb_free(k, &d[i]);
	return 0;
}

static int st_flip_legacy(struct kms *k)
{
	return st_flip(k, FLIP_LEGACY);
}

static int st_flip_atomic(struct kms *k)
{
	return st_flip(k, FLIP_ATOMIC);
}

static int st_flip_damage(struct kms *k)
{
	if (!k->pp.damage) {
		tap_skip("flip-damage: the primary plane has no "
			 "FB_DAMAGE_CLIPS");
		return 77;
	}
	return st_flip(k, FLIP_DAMAGE);
}

/* ---- vblank ----------------------------------------------------------------- */

/* An interval of n frames: within a factor of 4 of n periods. */
static bool about(uint64_t dt, uint64_t n, uint64_t period)
{
	return dt * 4 >= n * period && dt <= 4 * n * period;
}

static uint64_t tv_ns(const drmVBlank *v)
{
	return (uint64_t)v->reply.tval_sec * 1000000000u +
	       (uint64_t)v->reply.tval_usec * 1000u;
}

static int st_vblank(struct kms *k)
{
	struct dumb d;
	drmVBlank v0, v, va;
	uint64_t per = period_ns(k), s, ns, s2, ns2, queued = 0;
	uint64_t dmin = UINT64_MAX, dmax = 0;
	unsigned int nonmono = 0, n = 30;
	int ret;

	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &d))
		return tap(0, "vblank: buffer"), 1;
	paint(&d, 3);
	tap(show(k, &d) == 0, "vblank: the CRTC on");

	/* relative waits, one frame each */
	ret = wait_vblank_rel(k, 1, &v0);
	v = v0;
	for (unsigned int i = 0; !ret && i < n; i++) {
		drmVBlank w;
		uint64_t dt;

		ret = wait_vblank_rel(k, 1, &w);
		if (ret)
			break;
		if (w.reply.sequence <= v.reply.sequence ||
		    tv_ns(&w) <= tv_ns(&v)) {
			nonmono++;
		} else {
			dt = (tv_ns(&w) - tv_ns(&v)) /
			     (w.reply.sequence - v.reply.sequence);
			dmin = dt < dmin ? dt : dmin;
			dmax = dt > dmax ? dt : dmax;
		}
		v = w;
	}
	tap(!ret && !nonmono,
	    "vblank: %u relative waits, sequences and timestamps increasing "
	    "(%u not)",
	    n, nonmono);
	if (!ret) {
		uint64_t frames = v.reply.sequence - v0.reply.sequence;
		uint64_t dt = tv_ns(&v) - tv_ns(&v0);

		printf("#   %" PRIu64 " frames in %" PRIu64 " us: %" PRIu64
		       " us a frame (mode: %" PRIu64 " us), each %" PRIu64
		       "..%" PRIu64 " us\n",
		       frames, dt / 1000, frames ? dt / frames / 1000 : 0,
		       per / 1000, dmin / 1000, dmax / 1000);
		tap(frames >= n && about(dt, frames, per),
		    "vblank: timestamps a frame period apart on average "
		    "(within a factor of 4)");
	}

	/*
	 * absolute: three frames on.  The reply names the vblank the event
	 * went out at: on a host too slow for the paced clock (its CPU
	 * budget holds the chip back) DRM's count can step over that one,
	 * so a later one is right too, never an earlier one.
	 */
	memset(&va, 0, sizeof(va));
	va.request.type = DRM_VBLANK_ABSOLUTE;
	va.request.sequence = v.reply.sequence + 3;
	ret = drmWaitVBlank(k->fd, &va) ? -errno : 0;
	tap(!ret && va.reply.sequence >= v.reply.sequence + 3 &&
		    tv_ns(&va) > tv_ns(&v) &&
		    about(tv_ns(&va) - tv_ns(&v),
			  va.reply.sequence - v.reply.sequence, per),
	    "vblank: absolute wait for sequence %u returns at %u, %" PRIu64
	    " us on",
	    v.reply.sequence + 3, va.reply.sequence,
	    (tv_ns(&va) - tv_ns(&v)) / 1000);

	/* GET_SEQUENCE: where the waits left it, and moving */
	ret = drmCrtcGetSequence(k->fd, k->crtc_id, &s, &ns) ? -errno : 0;
	tap(!ret && s >= va.reply.sequence && ns >= tv_ns(&va),
	    "vblank: CRTC_GET_SEQUENCE %" PRIu64 " at or after the wait's %u",
	    s, va.reply.sequence);
	wait_vblank_rel(k, 2, NULL);
	ret = drmCrtcGetSequence(k->fd, k->crtc_id, &s2, &ns2) ? -errno : 0;
	tap(!ret && s2 >= s + 2 && ns2 > ns,
	    "vblank: GET_SEQUENCE %" PRIu64 " -> %" PRIu64
	    " over a wait of two frames, its time increasing",
	    s, s2);

	/* QUEUE_SEQUENCE: an event at the sequence asked for */
	ev.seqs = 0;
	ret = drmCrtcQueueSequence(k->fd, k->crtc_id,
				   DRM_CRTC_SEQUENCE_RELATIVE, 3, &queued,
				   0x5eed) ?
		      -errno :
		      0;
	if (!ret)
		ret = wait_event(k, &ev.seqs);
	tap(!ret && ev.qseq == queued && ev.quser == 0x5eed &&
		    queued >= s2 + 3 && ev.qns > ns2,
	    "vblank: QUEUE_SEQUENCE +3 queued for %" PRIu64
	    ", its event at %" PRIu64 " (%s)",
	    queued, ev.qseq, ret ? strerror(-ret) : "delivered");
	ret = drmCrtcQueueSequence(k->fd, k->crtc_id,
				   DRM_CRTC_SEQUENCE_RELATIVE, 0, &queued, 1) ?
		      -errno :
		      0;
	if (!ret)
		ret = wait_event(k, &ev.seqs);
	tap(!ret, "vblank: QUEUE_SEQUENCE +0 is delivered too");
	expect_err(drmCrtcQueueSequence(k->fd, 0xfffff4u,
					DRM_CRTC_SEQUENCE_RELATIVE, 1, &queued,
					1) ?
			   -errno :
			   0,
		   -ENOENT, "vblank: QUEUE_SEQUENCE on no CRTC");
	expect_err(drmCrtcQueueSequence(k->fd, k->crtc_id, 0x80, 1, &queued,
					1) ?
			   -errno :
			   0,
		   -EINVAL, "vblank: QUEUE_SEQUENCE with an unknown flag");
	memset(&va, 0, sizeof(va));
	va.request.type =
		(drmVBlankSeqType)(DRM_VBLANK_RELATIVE |
				   (5u << DRM_VBLANK_HIGH_CRTC_SHIFT));
	va.request.sequence = 1;
	expect_err(
		drmWaitVBlank(k->fd, &va) ? -errno : 0, -EINVAL,
		"vblank: WAIT_VBLANK on a CRTC index the card does not have");
	dumb_free(k, &d);
	return 0;
}

/* ---- cursor ----------------------------------------------------------------- */

/* A premultiplied ARGB cursor: every alpha from clear to opaque. */
static void cursor_paint(struct dumb *c, uint32_t seed)
{
	uint32_t s = c->w;

	for (uint32_t y = 0; y < s; y++)
		for (uint32_t x = 0; x < s; x++) {
			uint32_t a = (x * 255 / (s - 1) + seed) & 255;
			uint32_t r = (y * 255 / (s - 1)) * a / 255;
			uint32_t g = ((x ^ y) * 4 & 255) * a / 255;
			uint32_t b = (seed * 37 & 255) * a / 255;

			if (x == 0 || y == 0 || x == s - 1 || y == s - 1)
				a = 255, r = 255, g = 255, b = 255; /* frame */
			if (x > s / 4 && x < s / 2 && y > s / 4 && y < s / 2)
				a = r = g = b = 0; /* a clear hole */
			*px(c, x, y) = a << 24 | r << 16 | g << 8 | b;
		}
}

/* The chip's blend: out = min(255, c + (dst * (255 - a) + 127) / 255). */
static void composite(struct kms *k, uint32_t *want, struct dumb *cur, int cx,
		      int cy)
{
	uint32_t s = cur->w;

	for (uint32_t j = 0; j < s; j++)
		for (uint32_t i = 0; i < s; i++) {
			int x = cx + (int)i, y = cy + (int)j;
			uint32_t c = *px(cur, i, j), a = c >> 24, out = 0;
			uint32_t *d;

			if (x < 0 || y < 0 || x >= (int)k->w || y >= (int)k->h)
				continue;
			d = &want[(size_t)y * k->w + (uint32_t)x];
			for (int sh = 0; sh <= 16; sh += 8) {
				uint32_t cc = c >> sh & 255,
					 dc = *d >> sh & 255;
				uint32_t o = cc + (dc * (255 - a) + 127) / 255;

				out |= (o > 255 ? 255 : o) << sh;
			}
			*d = out;
		}
}

static int cursor_atomic(struct kms *k, struct dumb *cur, int x, int y)
{
	drmModeAtomicReqPtr r = drmModeAtomicAlloc();
	uint32_t s = cur ? cur->w : 0;

	add(r, k->cursor_id, k->cp.fb_id, cur ? cur->fb : 0);
	add(r, k->cursor_id, k->cp.crtc_id, cur ? k->crtc_id : 0);
	add(r, k->cursor_id, k->cp.src_x, 0);
	add(r, k->cursor_id, k->cp.src_y, 0);
	add(r, k->cursor_id, k->cp.src_w, (uint64_t)s << 16);
	add(r, k->cursor_id, k->cp.src_h, (uint64_t)s << 16);
	add(r, k->cursor_id, k->cp.crtc_x, (uint64_t)(int64_t)x);
	add(r, k->cursor_id, k->cp.crtc_y, (uint64_t)(int64_t)y);
	add(r, k->cursor_id, k->cp.crtc_w, s);
	add(r, k->cursor_id, k->cp.crtc_h, s);
	return commit(k, r, 0);
}

static int st_cursor(struct kms *k)
{
	struct dumb bg, c64, c32, c48;
	uint32_t *want = want_new(k);
	struct drm_rdc_frame fr;
	int W = (int)k->w, H = (int)k->h;
	const struct {
		const char *what;
		int size, x, y;
	} pos[] = {
		{ "64x64 inside", 64, 40, 30 },
		{ "64x64 moved", 64, W / 2, H / 3 },
		{ "64x64 partly off the left and top", 64, -20, -33 },
		{ "64x64 partly off the right and bottom", 64, W - 24, H - 40 },
		{ "64x64 wholly off the right", 64, W + 5, 10 },
		{ "64x64 wholly off the top left", 64, -64, -64 },
		{ "resized to 32x32", 32, 70, 50 },
		{ "32x32 partly off the bottom", 32, 7, H - 9 },
		{ "32x32 at the last pixel", 32, W - 1, H - 1 },
		{ "48x48, between the chip's sizes", 48, 100, 20 },
	};

	if (!k->cursor_id) {
		free(want);
		tap_skip("cursor: the CRTC has no cursor plane");
		return 77;
	}
	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &bg) ||
	    dumb_new(k, 64, 64, DRM_FORMAT_ARGB8888, &c64) ||
	    dumb_new(k, 32, 32, DRM_FORMAT_ARGB8888, &c32) ||
	    dumb_new(k, 48, 48, DRM_FORMAT_ARGB8888, &c48)) {
		free(want);
		return tap(0, "cursor: buffers"), 1;
	}
	paint(&bg, 5);
	cursor_paint(&c64, 11);
	cursor_paint(&c32, 90);
	cursor_paint(&c48, 150);
	tap(show(k, &bg) == 0, "cursor: the primary plane on");
	for (int atomic = 0; atomic < 2; atomic++) {
		const char *how = atomic ? "atomic" : "legacy";

		for (size_t i = 0; i < sizeof(pos) / sizeof(pos[0]); i++) {
			struct dumb *cur = pos[i].size == 64 ? &c64 :
					   pos[i].size == 32 ? &c32 :
							       &c48;
			char what[128];
			int ret;

			snprintf(what, sizeof(what),
				 "cursor (%s): %s at (%d,%d)", how, pos[i].what,
				 pos[i].x, pos[i].y);
			if (atomic) {
				ret = cursor_atomic(k, cur, pos[i].x, pos[i].y);
			} else {
				ret = drmModeSetCursor(k->fd, k->crtc_id,
						       cur->handle, cur->w,
						       cur->h) ?
					      -errno :
					      0;
				if (!ret)
					ret = drmModeMoveCursor(k->fd,
								k->crtc_id,
								pos[i].x,
								pos[i].y) ?
						      -errno :
						      0;
			}
			if (ret) {
				tap(0, "%s: %s", what, strerror(-ret));
				continue;
			}
			expect_xrgb(k, &bg, want);
			composite(k, want, cur, pos[i].x, pos[i].y);
			ret = settle(k, &fr);
			tap(!ret && !frame_diff(k, want, what), "%s", what);
		}
		/* hidden */
		if (atomic)
			cursor_atomic(k, NULL, 0, 0);
		else
			drmModeSetCursor(k->fd, k->crtc_id, 0, 0, 0);
		expect_xrgb(k, &bg, want);
		tap(!settle(k, &fr) && !frame_diff(k, want, "hidden"),
		    "cursor (%s): hidden, the frame is the primary plane's",
		    how);
	}
	expect_err(drmModeSetCursor(k->fd, k->crtc_id, c64.handle, 65, 64) ?
			   -errno :
			   0,
		   -EINVAL,
		   "cursor: a 65x64 cursor, wider than DRM_CAP_CURSOR_WIDTH");
	expect_err(drmModeSetCursor(k->fd, k->crtc_id, 0xfffff5u, 64, 64) ?
			   -errno :
			   0,
		   -ENOENT, "cursor: a GEM handle that does not exist");
	cursor_atomic(k, NULL, 0, 0);
	dumb_free(k, &c48);
	dumb_free(k, &c32);
	dumb_free(k, &c64);
	dumb_free(k, &bg);
	free(want);
	return 0;
}

/* ---- gamma and CLUT ----------------------------------------------------------- */

/*
 * LUT values of the form v << 8: what the driver's conversion to the
 * chip's 8-bit entries gives back as v, by truncation or by rounding.
 */
static uint16_t lut16(uint32_t v)
{
	return (uint16_t)(v << 8);
}

static int gamma_blob(struct kms *k, const uint8_t *r, const uint8_t *g,
		      const uint8_t *b, uint32_t n, uint32_t *blob)
{
	struct drm_color_lut lut[256];

	for (uint32_t i = 0; i < n && i < 256; i++)
		lut[i] = (struct drm_color_lut){ .red = lut16(r[i]),
						 .green = lut16(g[i]),
						 .blue = lut16(b[i]) };
	return drmModeCreatePropertyBlob(k->fd, lut, n * sizeof(lut[0]), blob) ?
		       -errno :
		       0;
}

static int set_gamma_lut(struct kms *k, uint32_t blob)
{
	drmModeAtomicReqPtr r = drmModeAtomicAlloc();

	add(r, k->crtc_id, k->gamma_lut, blob);
	return commit(k, r, 0);
}

static void expect_gamma(struct kms *k, struct dumb *d, const uint8_t *r,
			 const uint8_t *g, const uint8_t *b, uint32_t *want)
{
	for (uint32_t y = 0; y < k->h; y++)
		for (uint32_t x = 0; x < k->w; x++) {
			uint32_t p = *px(d, x, y);

			want[(size_t)y * k->w + x] =
				(uint32_t)r[p >> 16 & 255] << 16 |
				(uint32_t)g[p >> 8 & 255] << 8 | b[p & 255];
		}
}

static int st_gamma(struct kms *k)
{
	uint8_t r[256], g[256], b[256];
	uint16_t r16[256], g16[256], b16[256];
	uint32_t *want = want_new(k);
	struct drm_rdc_frame fr;
	struct dumb d;
	uint32_t blob = 0;
	int ret;

	if (!k->gamma_lut || k->gamma_size != 256) {
		free(want);
		tap_skip("gamma: no GAMMA_LUT of 256 entries on the CRTC");
		return 77;
	}
	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &d)) {
		free(want);
		return tap(0, "gamma: buffer"), 1;
	}
	paint(&d, 7);
	tap(show(k, &d) == 0, "gamma: XRGB8888 on the primary plane");

	/* legacy ramp: red inverted, green halved, blue doubled */
	for (uint32_t i = 0; i < 256; i++) {
		r[i] = (uint8_t)(255 - i);
		g[i] = (uint8_t)(i / 2);
		b[i] = (uint8_t)(i * 2 > 255 ? 255 : i * 2);
		r16[i] = lut16(r[i]);
		g16[i] = lut16(g[i]);
		b16[i] = lut16(b[i]);
	}
	ret = drmModeCrtcSetGamma(k->fd, k->crtc_id, 256, r16, g16, b16) ?
		      -errno :
		      0;
	expect_gamma(k, &d, r, g, b, want);
	tap(!ret && !settle(k, &fr) && !frame_diff(k, want, "legacy ramp"),
	    "gamma: a legacy gamma ramp (drmModeCrtcSetGamma) changes the "
	    "frame as computed (%s)",
	    ret ? strerror(-ret) : "set");

	/* GAMMA_LUT: a different curve per component */
	for (uint32_t i = 0; i < 256; i++) {
		r[i] = (uint8_t)(i * i / 255);
		g[i] = (uint8_t)(255 - i / 3);
		b[i] = (uint8_t)((i & 0xf0) | 0x08);
	}
	ret = gamma_blob(k, r, g, b, 256, &blob);
	if (!ret)
		ret = set_gamma_lut(k, blob);
	expect_gamma(k, &d, r, g, b, want);
	tap(!ret && !settle(k, &fr) && !frame_diff(k, want, "GAMMA_LUT"),
	    "gamma: a GAMMA_LUT blob changes the frame as computed (%s)",
	    ret ? strerror(-ret) : "set");
	if (blob)
		drmModeDestroyPropertyBlob(k->fd, blob);

	/* no LUT: the picture itself */
	ret = set_gamma_lut(k, 0);
	expect_xrgb(k, &d, want);
	tap(!ret && !settle(k, &fr) && !frame_diff(k, want, "no LUT"),
	    "gamma: GAMMA_LUT 0 brings the picture back unchanged");

	/* a LUT of the wrong size */
	blob = 0;
	ret = gamma_blob(k, r, g, b, 255, &blob);
	if (!ret)
		ret = set_gamma_lut(k, blob);
	expect_err(ret, -EINVAL, "gamma: a GAMMA_LUT of 255 entries");
	if (blob)
		drmModeDestroyPropertyBlob(k->fd, blob);
	dumb_free(k, &d);
	free(want);
	return 0;
}

static int st_clut_c8(struct kms *k)
{
	uint8_t r[256], g[256], b[256];
	uint32_t *want = want_new(k);
	struct drm_rdc_frame fr;
	struct dumb d;
	uint32_t blob = 0;
	drmModeAtomicReqPtr rq;
	int ret;

	if (!k->has_c8 || !k->gamma_lut || k->gamma_size != 256) {
		free(want);
		tap_skip("clut-c8: the primary plane offers no C8, or no "
			 "256-entry GAMMA_LUT");
		return 77;
	}
	if (dumb_new(k, k->w, k->h, DRM_FORMAT_C8, &d)) {
		free(want);
		return tap(0, "clut-c8: buffer"), 1;
	}
	for (uint32_t y = 0; y < d.h; y++)
		for (uint32_t x = 0; x < d.w; x++)
			d.map[(size_t)y * d.pitch + x] = (uint8_t)(x + 3 * y);
	for (int pass = 0; pass < 2; pass++) {
		for (uint32_t i = 0; i < 256; i++) {
			r[i] = (uint8_t)(pass ? 255 - i : i * 7);
			g[i] = (uint8_t)(pass ? i : i * 13 + 5);
			b[i] = (uint8_t)(pass ? i ^ 0x5a : 255 - i);
		}
		blob = 0;
		ret = gamma_blob(k, r, g, b, 256, &blob);
		rq = drmModeAtomicAlloc();
		if (!pass)
			add_primary(k, rq, d.fb, d.w, d.h);
		add(rq, k->crtc_id, k->gamma_lut, blob);
		if (!ret)
			ret = commit(k, rq, DRM_MODE_ATOMIC_ALLOW_MODESET);
		else
			drmModeAtomicFree(rq);
		for (uint32_t y = 0; y < k->h; y++)
			for (uint32_t x = 0; x < k->w; x++) {
				uint8_t i = d.map[(size_t)y * d.pitch + x];

				want[(size_t)y * k->w + x] =
					(uint32_t)r[i] << 16 |
					(uint32_t)g[i] << 8 | b[i];
			}
		tap(!ret && !settle(k, &fr) && !frame_diff(k, want, "C8"),
		    pass ? "clut-c8: a new palette alone recolours the frame" :
			   "clut-c8: C8 pixels through GAMMA_LUT as the "
			   "palette (%s)",
		    ret ? strerror(-ret) : "committed");
		if (blob)
			drmModeDestroyPropertyBlob(k->fd, blob);
	}
	set_gamma_lut(k, 0);
	dumb_free(k, &d);
	free(want);
	return 0;
}

/* ---- crc --------------------------------------------------------------------- */

/* One entry of crc/data: its frame and first value; 0 or -errno. */
static int crc_read(int fd, uint32_t *frame, uint32_t *crc)
{
	char line[256];
	struct pollfd p = { .fd = fd, .events = POLLIN };
	ssize_t n;

	/* an entry a frame: a few frames' wait at most */
	if (poll(&p, 1, EVENT_MS) == 0)
		return -ETIMEDOUT;
	do {
		n = read(fd, line, sizeof(line) - 1);
	} while (n < 0 && (errno == EINTR || errno == EAGAIN));
	if (n <= 0)
		return n < 0 ? -errno : -ENODATA;
	line[n] = 0;
	if (sscanf(line, "%x %x", frame, crc) != 2)
		return -EBADMSG;
	return 0;
}

/* The CRC of the frames once it holds still: 3 entries alike, in order. */
static int crc_steady(int fd, uint32_t *crc, uint32_t avoid, int *entries)
{
	uint32_t fprev = 0, c, f, same = 0, last = 0;

	for (int i = 0; i < 200; i++) {
		int ret = crc_read(fd, &f, &c);

		if (ret)
			return ret;
		(*entries)++;
		if (i && f <= fprev)
			return -EILSEQ;
		fprev = f;
		if (c == avoid) {
			same = 0;
			continue;
		}
		same = c == last ? same + 1 : 1;
		last = c;
		if (same == 3) {
			*crc = c;
			return 0;
		}
	}
	return -ETIMEDOUT;
}

static int st_crc(struct kms *k)
{
	char ctl[192], data[192];
	struct dumb a, b;
	struct drm_rdc_frame fr;
	uint32_t crc_a = 0, crc_b = 0, fcrc_a = 0, fcrc_b = 0;
	int fd, ret, n = 0;
	FILE *f;

	if (!k->debugfs[0]) {
		tap_skip("crc: no debugfs directory of the card");
		return 77;
	}
	snprintf(ctl, sizeof(ctl), "%s/crtc-%u/crc/control", k->debugfs,
		 k->crtc_idx);
	snprintf(data, sizeof(data), "%s/crtc-%u/crc/data", k->debugfs,
		 k->crtc_idx);
	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &a) ||
	    dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &b))
		return tap(0, "crc: buffers"), 1;
	paint(&a, 9);
	paint(&b, 9);
	*px(&b, k->w / 3, k->h / 2) ^= 0x000100; /* one pixel, one bit */
	tap(show(k, &a) == 0, "crc: a picture shown");
	f = fopen(ctl, "w");
	ret = f && fputs("auto", f) >= 0 && !fclose(f) ? 0 : -errno;
	if (!f || ret) {
		tap(0, "crc: %s: %s", ctl, strerror(errno));
		goto out;
	}
	fd = open(data, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0) {
		tap(0, "crc: %s: %s", data, strerror(errno));
		goto out;
	}
	ret = crc_steady(fd, &crc_a, 0, &n);
	if (!ret)
		ret = rdc_frame(k, NULL, &fr);
	fcrc_a = ret ? 0 : fr.crc32;
	tap(!ret && crc_a == fcrc_a,
	    "crc: identical frames give equal CRCs (%08x, three in a row), "
	    "and FRAME's CRC-32 of the frame is the same (%08x)",
	    crc_a, fcrc_a);
	ret = show(k, &b);
	if (!ret)
		ret = crc_steady(fd, &crc_b, crc_a, &n);
	if (!ret)
		ret = rdc_frame(k, NULL, &fr);
	fcrc_b = ret ? 0 : fr.crc32;
	tap(!ret && crc_b != crc_a && crc_b == fcrc_b,
	    "crc: a frame one pixel apart gives another CRC (%08x, not "
	    "%08x), FRAME's too (%08x)",
	    crc_b, crc_a, fcrc_b);
	ret = show(k, &a);
	if (!ret)
		ret = crc_steady(fd, &crc_a, crc_b, &n);
	tap(!ret && crc_a == fcrc_a,
	    "crc: the first picture again, its CRC again (%08x)", crc_a);
	printf("#   %d CRC entries read\n", n);
	close(fd);
out:
	dumb_free(k, &b);
	dumb_free(k, &a);
	return 0;
}

/* ---- damage ------------------------------------------------------------------ */

/* Commit d again with the damage `clip` (NULL: none, the whole plane). */
static int damage_commit(struct kms *k, struct dumb *d,
			 const struct drm_mode_rect *clip, uint64_t *cycles,
			 uint64_t *busy, uint64_t *wall)
{
	struct drm_rdc_counters c0, c1;
	struct drm_rdc_frame fr;
	drmModeAtomicReqPtr r = drmModeAtomicAlloc();
	uint32_t blob = 0;
	uint64_t t;
	int ret;

	if (clip &&
	    drmModeCreatePropertyBlob(k->fd, clip, sizeof(*clip), &blob)) {
		drmModeAtomicFree(r);
		return -errno;
	}
	rdc_counters(k, &c0);
	add(r, k->primary_id, k->pp.fb_id, d->fb);
	add(r, k->primary_id, k->pp.damage, blob);
	t = now_ns();
	ret = commit(k, r, 0);
	*wall = now_ns() - t;
	if (!ret)
		ret = settle(k, &fr);
	rdc_counters(k, &c1);
	*cycles = c1.damage_cycles - c0.damage_cycles;
	*busy = c1.busy - c0.busy;
	if (blob)
		drmModeDestroyPropertyBlob(k->fd, blob);
	return ret;
}

static int st_damage(struct kms *k)
{
	uint32_t *want = want_new(k);
	struct drm_mode_rect clip = { 40, 24, 40 + 16, 24 + 16 };
	uint64_t full = 0, small = 0, busy_full = 0, busy_small = 0;
	uint64_t wall_full = 0, wall_small = 0;
	struct dumb d;
	int ret = 0;

	if (!k->pp.damage) {
		free(want);
		tap_skip("damage: the primary plane has no FB_DAMAGE_CLIPS");
		return 77;
	}
	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &d)) {
		free(want);
		return tap(0, "damage: buffer"), 1;
	}
	paint(&d, 13);
	tap(show(k, &d) == 0, "damage: a picture shown");
	/* full updates, twice: the second is a full one's own cost */
	for (int i = 0; i < 2 && !ret; i++) {
		paint(&d, 20 + (uint32_t)i);
		ret = damage_commit(k, &d, NULL, &full, &busy_full, &wall_full);
	}
	expect_xrgb(k, &d, want);
	tap(!ret && !frame_diff(k, want, "full"),
	    "damage: a full update shows the new picture");
	/* small ones, three: the last carries no earlier damage with it */
	for (int i = 0; i < 3 && !ret; i++) {
		for (int y = clip.y1; y < clip.y2; y++)
			for (int x = clip.x1; x < clip.x2; x++)
				*px(&d, (uint32_t)x, (uint32_t)y) =
					0xff000000u | (0x102030u * (i + 1));
		ret = damage_commit(k, &d, &clip, &small, &busy_small,
				    &wall_small);
	}
	expect_xrgb(k, &d, want);
	tap(!ret && !frame_diff(k, want, "damaged"),
	    "damage: a 16x16 damage clip's change is in the frame");
	printf("#   upload cycles: full %" PRIu64 ", 16x16 %" PRIu64
	       "; busy cycles: full %" PRIu64 ", 16x16 %" PRIu64
	       "; a blocking commit's wall time: full %.2f ms, 16x16 %.2f ms "
	       "(a frame: %.2f ms)\n",
	       full, small, busy_full, busy_small, (double)wall_full / 1e6,
	       (double)wall_small / 1e6, (double)period_ns(k) / 1e6);
	tap(!ret && small > 0 && small < full,
	    "damage: the 16x16 update charges fewer upload cycles (%" PRIu64
	    ") than a full one (%" PRIu64 ")",
	    small, full);
	dumb_free(k, &d);
	free(want);
	return 0;
}

/* ---- bad input ------------------------------------------------------------- */

static int addfb(struct kms *k, uint32_t w, uint32_t h, uint32_t fourcc,
		 uint32_t handle, uint32_t pitch, uint32_t flags)
{
	uint32_t handles[4] = { handle }, pitches[4] = { pitch };
	uint32_t offsets[4] = { 0 }, fb = 0;
	uint64_t mods[4] = { 0 };
	int ret = drmModeAddFB2WithModifiers(
			  k->fd, w, h, fourcc, handles, pitches, offsets,
			  flags & DRM_MODE_FB_MODIFIERS ? mods : NULL, &fb,
			  flags) ?
			  -errno :
			  0;

	if (!ret)
		drmModeRmFB(k->fd, fb);
	return ret;
}

static int st_bad_input(struct kms *k)
{
	struct dumb d;
	struct drm_mode_create_dumb c;
	uint32_t *want = want_new(k);
	struct drm_rdc_frame fr;
	uint32_t w = k->w, h = k->h, p;
	int ret;

	if (dumb_new(k, w, h, DRM_FORMAT_XRGB8888, &d)) {
		free(want);
		return tap(0, "bad-input: buffer"), 1;
	}
	p = d.pitch;
	expect_err(addfb(k, w, h, DRM_FORMAT_XRGB8888, d.handle, p, 0), 0,
		   "bad-input: a good framebuffer, to compare with");
	expect_err(addfb(k, w, h, fourcc_code('Q', 'Q', 'Q', 'Q'), d.handle, p,
			 0),
		   -EINVAL, "bad-input: an unknown format");
	expect_err(addfb(k, w, h, DRM_FORMAT_NV12, d.handle, p, 0), -EINVAL,
		   "bad-input: NV12, which no plane takes");
	expect_err(addfb(k, w, h, DRM_FORMAT_XRGB8888, d.handle, w * 4 - 4, 0),
		   -EINVAL, "bad-input: a pitch below width * 4");
	expect_err(addfb(k, w, h * 2, DRM_FORMAT_XRGB8888, d.handle, p, 0),
		   -EINVAL, "bad-input: a framebuffer larger than its buffer");
	expect_err(addfb(k, 0, h, DRM_FORMAT_XRGB8888, d.handle, p, 0), -EINVAL,
		   "bad-input: width 0");
	expect_err(addfb(k, (uint32_t)k->max_w + 1, 1, DRM_FORMAT_XRGB8888,
			 d.handle, ((uint32_t)k->max_w + 1) * 4, 0),
		   -EINVAL, "bad-input: wider than the mode config's maximum");
	expect_err(addfb(k, w, h, DRM_FORMAT_XRGB8888, 0xfffff6u, p, 0),
		   -ENOENT, "bad-input: a GEM handle that does not exist");
	expect_err(addfb(k, w, h, DRM_FORMAT_XRGB8888, d.handle, p,
			 0x80000000u),
		   -EINVAL, "bad-input: an unknown ADDFB2 flag");
	memset(&c, 0, sizeof(c));
	c.width = 64;
	c.height = 64;
	c.bpp = 0;
	expect_err(drmIoctl(k->fd, DRM_IOCTL_MODE_CREATE_DUMB, &c) ? -errno : 0,
		   -EINVAL, "bad-input: a dumb buffer of 0 bpp");
	c.bpp = 32;
	c.width = 0xffffffu;
	c.height = 0xffffffu;
	ret = drmIoctl(k->fd, DRM_IOCTL_MODE_CREATE_DUMB, &c) ? -errno : 0;
	tap(ret == -EINVAL || ret == -ENOMEM,
	    "bad-input: a dumb buffer of 2^24 x 2^24 is refused (%s)",
	    ret ? strerror(-ret) : "accepted");
	if (!ret) {
		struct drm_mode_destroy_dumb x = { .handle = c.handle };

		drmIoctl(k->fd, DRM_IOCTL_MODE_DESTROY_DUMB, &x);
	}

	paint(&d, 17);
	tap(show(k, &d) == 0, "bad-input: a picture shown");
	expect_err(drmModePageFlip(k->fd, k->crtc_id, d.fb, 0x80000000u, NULL) ?
			   -errno :
			   0,
		   -EINVAL, "bad-input: a page flip with an unknown flag");
	expect_err(drmModePageFlip(k->fd, k->crtc_id, 0xfffff7u,
				   DRM_MODE_PAGE_FLIP_EVENT, NULL) ?
			   -errno :
			   0,
		   -ENOENT, "bad-input: a page flip to no framebuffer");
	expect_err(drmModePageFlip(k->fd, 0xfffff8u, d.fb,
				   DRM_MODE_PAGE_FLIP_EVENT, NULL) ?
			   -errno :
			   0,
		   -ENOENT, "bad-input: a page flip of no CRTC");

	/* the card still works */
	paint(&d, 18);
	ret = show(k, &d);
	expect_xrgb(k, &d, want);
	tap(!ret && !settle(k, &fr) && !frame_diff(k, want, "after"),
	    "bad-input: afterwards a commit shows its picture exactly");
	dumb_free(k, &d);
	free(want);
	return 0;
}

/* ---- primary-off ------------------------------------------------------------ */

/*
 * The primary plane off with the CRTC on: the screen is black (as a CRTC
 * with no plane shows, and vkms composes), the vblanks go on; turned on
 * again, the plane's picture is back whole.
 */
static int st_primary_off(struct kms *k)
{
	uint32_t *want = want_new(k);
	drmModeAtomicReqPtr r;
	struct drm_rdc_frame fr;
	struct dumb d;
	uint64_t seq0;
	int ret;

	if (dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &d)) {
		free(want);
		return tap(0, "primary-off: buffer"), 1;
	}
	paint(&d, 31);
	expect_xrgb(k, &d, want);
	ret = show(k, &d);
	if (!ret)
		ret = settle(k, &fr);
	tap(!ret && !frame_diff(k, want, "shown"),
	    "primary-off: a picture shown is in the frame");
	seq0 = fr.seq;
	r = drmModeAtomicAlloc();
	add(r, k->primary_id, k->pp.fb_id, 0);
	add(r, k->primary_id, k->pp.crtc_id, 0);
	if (k->cursor_id) {
		add(r, k->cursor_id, k->cp.fb_id, 0);
		add(r, k->cursor_id, k->cp.crtc_id, 0);
	}
	ret = commit(k, r, 0);
	if (!ret)
		ret = settle(k, &fr);
	memset(want, 0, (size_t)k->w * k->h * sizeof(*want));
	tap(!ret && !frame_diff(k, want, "plane off") && fr.seq > seq0,
	    "primary-off: the plane off, the CRTC on: the frame is black and "
	    "frames go on (%s, frame %" PRIu64 " after %" PRIu64 ")",
	    ret ? strerror(-ret) : "committed", (uint64_t)fr.seq, seq0);
	expect_xrgb(k, &d, want);
	ret = show(k, &d);
	if (!ret)
		ret = settle(k, &fr);
	tap(!ret && !frame_diff(k, want, "plane on"),
	    "primary-off: the plane on again: its picture whole");
	dumb_free(k, &d);
	free(want);
	return 0;
}

/* ---- host-cost ---------------------------------------------------------------- */

#define COST_S	   3 /* seconds each figure is measured over */
#define COST_PATCH 64

static int sys_read(struct kms *k, const char *name, char *buf, size_t cap)
{
	char path[128];
	FILE *f;
	int ok;

	snprintf(path, sizeof(path), "%s/%s", k->sysdev, name);
	f = fopen(path, "r");
	if (!f)
		return -errno;
	ok = fgets(buf, (int)cap, f) != NULL;
	fclose(f);
	if (!ok)
		return -EIO;
	buf[strcspn(buf, "\n")] = 0;
	return 0;
}

/* The chip host's busy and up time (sysfs host_busy_ns, host_up_ns). */
struct cost {
	uint64_t busy, up, wall;
};

static int cost_read(struct kms *k, struct cost *c)
{
	char b[32], u[32];
	int ret = sys_read(k, "host_busy_ns", b, sizeof(b));

	if (!ret)
		ret = sys_read(k, "host_up_ns", u, sizeof(u));
	if (ret)
		return ret;
	c->busy = strtoull(b, NULL, 10);
	c->up = strtoull(u, NULL, 10);
	c->wall = now_ns();
	return 0;
}

/* busy over up between a and b, in per cent; -1 when they make no sense */
static double cost_share(const struct cost *a, const struct cost *b)
{
	if (b->up <= a->up || b->busy < a->busy ||
	    b->busy - a->busy > b->up - a->up)
		return -1;
	return 100.0 * (double)(b->busy - a->busy) / (double)(b->up - a->up);
}

static bool scanout_is(struct kms *k, const char *want, char *got, size_t cap)
{
	return !sys_read(k, "scanout", got, cap) && !strcmp(got, want);
}

/* Flips to d[0], d[1], ... for COST_S seconds: how many, 0 on an error. */
static unsigned int cost_flips(struct kms *k, struct dumb *d,
			       enum flip_kind kind, uint32_t damage)
{
	uint64_t end = now_ns() + COST_S * 1000000000ull;
	unsigned int n = 0;

	while (now_ns() < end) {
		if (flip_to(k, &d[n % 2], kind, damage) ||
		    wait_event(k, &ev.flips))
			return 0;
		n++;
	}
	return n;
}

/*
 * What the chip costs the machine it runs on, at 1024x768@60 on the
 * paced clock, as figures (they depend on this machine): the share of a
 * CPU that the host held the chip for (sysfs host_busy_ns over
 * host_up_ns), idle with nothing looking at frames, idle with the CRC
 * looking, and flipping every frame (a 64x64 damaged patch, and whole
 * frames), with the flips reached per second.  The checks: the counters
 * move as time does, and scanout on demand is idle exactly while
 * nothing looks.
 */
static int st_host_cost(struct kms *k)
{
	struct kms big;
	drmModeConnectorPtr conn;
	struct dumb d[2];
	struct cost c0, c1;
	char got[32], ctl[192], data[192], mode[16] = "";
	struct drm_mode_rect patch = { 0, 0, COST_PATCH, COST_PATCH };
	uint32_t damage = 0;
	double idle, watched = -1, fdmg = -1, ffull = -1;
	unsigned int ndmg = 0, nfull = 0;
	bool demand, found = false;
	FILE *f;
	int fd, ret;

	if (k->stepped) {
		tap_skip("host-cost: figures of the paced clock");
		return 77;
	}
	if (sys_read(k, "host_busy_ns", got, sizeof(got))) {
		tap_skip("host-cost: no sysfs host_busy_ns");
		return 77;
	}
	if (sys_read(k, "scanout", mode, sizeof(mode)))
		mode[0] = 0;
	demand = !strncmp(mode, "demand", 6);
	mode[strcspn(mode, " ")] = 0;
	conn = drmModeGetConnector(k->fd, k->conn_id);
	big = *k;
	for (int i = 0; conn && i < conn->count_modes; i++)
		if (conn->modes[i].hdisplay == 1024 &&
		    conn->modes[i].vdisplay == 768 &&
		    conn->modes[i].vrefresh == 60) {
			big.mode = conn->modes[i];
			found = true;
		}
	drmModeFreeConnector(conn);
	if (!found) {
		tap(0, "host-cost: the connector offers 1024x768@60");
		return 1;
	}
	big.w = 1024;
	big.h = 768;
	big.frame = NULL;
	if (drmModeCreatePropertyBlob(k->fd, &big.mode, sizeof(big.mode),
				      &big.mode_blob) ||
	    dumb_new(&big, big.w, big.h, DRM_FORMAT_XRGB8888, &d[0]) ||
	    dumb_new(&big, big.w, big.h, DRM_FORMAT_XRGB8888, &d[1]))
		return tap(0, "host-cost: 1024x768 buffers"), 1;
	paint(&d[0], 41);
	paint(&d[1], 42);
	ret = show(&big, &d[0]);
	tap(!ret, "host-cost: 1024x768@60 set (%s)",
	    ret ? strerror(-ret) : "committed");
	if (ret)
		goto out;
	sleep(1); /* the modeset's upload done, the clock steady */

	/* idle, nothing looking */
	if (demand)
		tap(scanout_is(k, "demand idle", got, sizeof(got)),
		    "host-cost: nothing looks at frames: scanout is \"%s\"",
		    got);
	ret = cost_read(k, &c0);
	sleep(COST_S);
	ret = ret ? ret : cost_read(k, &c1);
	idle = ret ? -1 : cost_share(&c0, &c1);
	tap(!ret && idle >= 0 && c1.up - c0.up >= (c1.wall - c0.wall) / 2,
	    "host-cost: host_busy_ns and host_up_ns move with time "
	    "(up %.2f s over %.2f s wall)",
	    (double)(c1.up - c0.up) / 1e9, (double)(c1.wall - c0.wall) / 1e9);

	/* idle, the CRC looking at every frame */
	if (k->debugfs[0]) {
		snprintf(ctl, sizeof(ctl), "%s/crtc-%u/crc/control", k->debugfs,
			 k->crtc_idx);
		snprintf(data, sizeof(data), "%s/crtc-%u/crc/data", k->debugfs,
			 k->crtc_idx);
		f = fopen(ctl, "w");
		if (f && fputs("auto", f) >= 0 && !fclose(f) &&
		    (fd = open(data, O_RDONLY | O_CLOEXEC | O_NONBLOCK)) >= 0) {
			if (demand)
				tap(scanout_is(k, "demand watched", got,
					       sizeof(got)),
				    "host-cost: with the CRC on, scanout is "
				    "\"%s\"",
				    got);
			if (!cost_read(k, &c0)) {
				char line[256];
				uint64_t end =
					now_ns() + COST_S * 1000000000ull;

				/* read the entries as a CRC client does */
				while (now_ns() < end) {
					struct pollfd p = { fd, POLLIN, 0 };

					if (poll(&p, 1, 100) > 0 &&
					    read(fd, line, sizeof(line)) < 0 &&
					    errno != EAGAIN)
						break;
				}
				if (!cost_read(k, &c1))
					watched = cost_share(&c0, &c1);
			}
			close(fd);
			if (demand)
				tap(scanout_is(k, "demand idle", got,
					       sizeof(got)),
				    "host-cost: the CRC off, scanout is \"%s\" "
				    "again",
				    got);
		}
	}

	/* flipping every frame: a damaged patch, then whole frames */
	if (k->pp.damage &&
	    !drmModeCreatePropertyBlob(k->fd, &patch, sizeof(patch), &damage) &&
	    !cost_read(k, &c0)) {
		ndmg = cost_flips(&big, d, FLIP_DAMAGE, damage);
		if (!cost_read(k, &c1))
			fdmg = cost_share(&c0, &c1);
	}
	if (damage)
		drmModeDestroyPropertyBlob(k->fd, damage);
	if (!cost_read(k, &c0)) {
		nfull = cost_flips(&big, d, FLIP_ATOMIC, 0);
		if (!cost_read(k, &c1))
			ffull = cost_share(&c0, &c1);
	}
	tap(ndmg > 0 && nfull > 0,
	    "host-cost: flips of a 64x64 patch and of whole frames went "
	    "through (%u and %u)",
	    ndmg, nfull);
	printf("# host-cost: the chip's share of a CPU at 1024x768@60, paced, "
	       "scanout %s, over %d s each (sysfs host_busy_ns / "
	       "host_up_ns):\n"
	       "#   idle, nothing looking: %.3f%%\n"
	       "#   idle, the CRC looking: %.3f%%\n"
	       "#   flipping a 64x64 damaged patch: %.3f%%, %.1f flips/s\n"
	       "#   flipping whole frames: %.3f%%, %.1f flips/s\n",
	       mode[0] ? mode : "?", COST_S, idle, watched, fdmg,
	       (double)ndmg / COST_S, ffull, (double)nfull / COST_S);
out:
	/* back to the subtests' mode before the buffers shown go */
	{
		struct dumb b;

		if (!dumb_new(k, k->w, k->h, DRM_FORMAT_XRGB8888, &b)) {
			fill(&b, 0);
			show(k, &b);
			dumb_free(k, &b);
		}
	}
	dumb_free(&big, &d[0]);
	dumb_free(&big, &d[1]);
	drmModeDestroyPropertyBlob(k->fd, big.mode_blob);
	return 0;
}

/* ---- main ------------------------------------------------------------------ */

static const struct {
	const char *name;
	int (*fn)(struct kms *k);
} subtests[] = {
	{ "atomic-test-only", st_atomic_test_only },
	{ "flip-legacy", st_flip_legacy },
	{ "flip-atomic", st_flip_atomic },
	{ "flip-damage", st_flip_damage },
	{ "vblank", st_vblank },
	{ "cursor", st_cursor },
	{ "gamma", st_gamma },
	{ "clut-c8", st_clut_c8 },
	{ "crc", st_crc },
	{ "damage", st_damage },
	{ "bad-input", st_bad_input },
	{ "primary-off", st_primary_off },
	{ "host-cost", st_host_cost },
};

#define NSUB (sizeof(subtests) / sizeof(subtests[0]))

int main(int argc, char **argv)
{
	bool want[NSUB] = { false }, any = false;
	int ran = 0, ret;
	struct kms k;

	setvbuf(stdout, NULL, _IOLBF, 0);
	for (int i = 1; i < argc; i++) {
		size_t j;

		if (!strcmp(argv[i], "--list")) {
			for (j = 0; j < NSUB; j++)
				printf("%s\n", subtests[j].name);
			return 0;
		}
		for (j = 0; j < NSUB; j++)
			if (!strcmp(argv[i], subtests[j].name))
				break;
		if (j == NSUB) {
			fprintf(stderr,
				"usage: kms_conform [--list] [SUBTEST...]\n"
				"kms_conform: no subtest '%s'\n",
				argv[i]);
			return 2;
		}
		want[j] = any = true;
	}
	ret = kms_setup(&k);
	if (ret == 77) {
		printf("1..0 # SKIP no rdc card\n");
		return ret;
	}
	if (ret) {
		tap(0, "the rdc card set up for KMS");
		return tap_done();
	}
	for (size_t j = 0; j < NSUB; j++) {
		if (any && !want[j])
			continue;
		printf("# subtest %s\n", subtests[j].name);
		if (subtests[j].fn(&k) != 77)
			ran++;
	}
	ret = tap_done();
	return ret ? ret : ran ? 0 : 77;
}
