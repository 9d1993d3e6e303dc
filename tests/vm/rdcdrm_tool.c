// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcdrm_tool: what the rdcdrm VM tests (tests/vm/tests/rdcdrm-*.sh) do
 * to /dev/dri/cardN that a shell cannot.  Every check compares what the
 * chip scanned out (the FRAME ioctl) with what the client drew.
 *
 *   rdcdrm_tool frame DEV [RRGGBB]  print "W H CRC SEQ" of the latest
 *                                   frame, check its CRC against the
 *                                   pixels; with RRGGBB, wait (10 s) until
 *                                   every pixel is that colour
 *   rdcdrm_tool kms DEV             dumb buffers and a mode set with a
 *                                   known pattern, a damaged rectangle
 *                                   through DIRTYFB (and what it cost), a
 *                                   page flip with its event, vblank
 *                                   counts against the chip's frames, the
 *                                   private ioctls and their bad input
 *   rdcdrm_tool formats DEV         RGB565, RGB888, ARGB8888 and C8 (with
 *                                   its palette through the legacy gamma
 *                                   ioctl), and a gamma LUT on XRGB8888
 *   rdcdrm_tool cursor DEV          an ARGB8888 cursor with alpha, drawn by
 *                                   the chip, against the same composited
 *                                   in software
 *   rdcdrm_tool crc DEV DEBUGFS     the debugfs CRCs (source auto) against
 *                                   the FRAME ioctl's, frame by frame
 *   rdcdrm_tool fuzz DEV N          N random private ioctls with random
 *                                   arguments (REG_WRITE aside): each
 *                                   answers 0 or its errno; a mode set
 *                                   draws after
 *   rdcdrm_tool stepped DEV         on the stepped clock: a mode set, a
 *                                   damaged rectangle, a flip and a STEP;
 *                                   print the counters and the frame's CRC
 *   rdcdrm_tool hold DEV            a mode set from a mapped dumb buffer;
 *                                   print "held", wait for a signal
 *   rdcdrm_tool unbind DEV PDEV     with DEV open and a dumb buffer mapped,
 *                                   unbind platform device PDEV: the
 *                                   client's ioctls answer ENODEV, its
 *                                   mapping stays readable
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#include <zlib.h>

#include "rdc_regs.h"
#include "rdcdrm_ioctl.h"

#ifndef DRM_FORMAT_XRGB8888
#include <drm_fourcc.h>
#endif

#define WAIT_MS	    10000
#define POLL_MS	    20
#define DAMAGE_X    100
#define DAMAGE_Y    60
#define DAMAGE_W    64
#define DAMAGE_H    32
#define VBLANKS	    30
#define CURSOR_SIZE 64
#define CURSOR_X    200
#define CURSOR_Y    150
#define BAD_REG	    0x401u

static int failures;

#define FAIL(...) \
	do { \
		printf("FAIL: " __VA_ARGS__); \
		failures++; \
	} while (0)

struct pipe_info {
	uint32_t conn, crtc, crtc_idx;
	drmModeModeInfo mode;
};

struct dumb {
	uint32_t handle, pitch, fb, w, h, format, bpp;
	uint64_t size;
	uint8_t *map;
};

static uint64_t now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

static int open_dev(const char *dev)
{
	int fd = open(dev, O_RDWR | O_CLOEXEC);
	drmVersionPtr v;

	if (fd < 0) {
		perror(dev);
		exit(1);
	}
	v = drmGetVersion(fd);
	if (!v || strcmp(v->name, DRM_RDC_DRIVER_NAME)) {
		fprintf(stderr, "%s: not an rdc device\n", dev);
		exit(1);
	}
	drmFreeVersion(v);
	return fd;
}

/* The connector, its CRTC and its preferred mode (or WxH if given). */
static int find_pipe(int fd, struct pipe_info *p, int w, int h)
{
	drmModeRes *res = drmModeGetResources(fd);
	drmModeConnector *c;
	int i, found = 0;

	if (!res || !res->count_connectors || !res->count_crtcs)
		return -1;
	c = drmModeGetConnector(fd, res->connectors[0]);
	if (!c)
		return -1;
	for (i = 0; i < c->count_modes; i++) {
		if (w ? (c->modes[i].hdisplay == w &&
			 c->modes[i].vdisplay == h) :
			(c->modes[i].type & DRM_MODE_TYPE_PREFERRED)) {
			p->mode = c->modes[i];
			found = 1;
			break;
		}
	}
	p->conn = c->connector_id;
	p->crtc = res->crtcs[0];
	p->crtc_idx = 0;
	drmModeFreeConnector(c);
	drmModeFreeResources(res);
	return found ? 0 : -1;
}

static int dumb_new(int fd, struct dumb *d, uint32_t w, uint32_t h,
		    uint32_t format, uint32_t bpp)
{
	struct drm_mode_create_dumb c = { .width = w, .height = h, .bpp = bpp };
	struct drm_mode_map_dumb m = { 0 };
	uint32_t handles[4] = { 0 }, pitches[4] = { 0 }, offsets[4] = { 0 };

	if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &c))
		return -errno;
	d->handle = c.handle;
	d->pitch = c.pitch;
	d->size = c.size;
	d->w = w;
	d->h = h;
	d->format = format;
	d->bpp = bpp;
	m.handle = c.handle;
	if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
		return -errno;
	d->map = mmap(NULL, d->size, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		      m.offset);
	if (d->map == MAP_FAILED)
		return -errno;
	handles[0] = d->handle;
	pitches[0] = d->pitch;
	if (drmModeAddFB2(fd, w, h, format, handles, pitches, offsets, &d->fb,
			  0))
		return -errno;
	return 0;
}

static void dumb_free(int fd, struct dumb *d)
{
	struct drm_mode_destroy_dumb x = { .handle = d->handle };

	drmModeRmFB(fd, d->fb);
	munmap(d->map, d->size);
	drmIoctl(fd, DRM_IOCTL_MODE_DESTROY_DUMB, &x);
}

/* The test pattern: every pixel differs from its neighbours. */
static uint32_t pattern(uint32_t x, uint32_t y, uint32_t salt)
{
	return ((x * 7 + salt) & 0xff) << 16 | ((y * 5 + salt) & 0xff) << 8 |
	       ((x ^ y ^ salt) & 0xff);
}

static void fill_xrgb(struct dumb *d, uint32_t salt, uint32_t x0, uint32_t y0,
		      uint32_t w, uint32_t h)
{
	uint32_t x, y;

	for (y = y0; y < y0 + h; y++)
		for (x = x0; x < x0 + w; x++)
			((uint32_t *)(d->map + (size_t)y * d->pitch))[x] =
				0xff000000u | pattern(x, y, salt);
}

/* The latest frame; NULL before the first. */
static uint32_t *get_frame(int fd, struct drm_rdc_frame *f)
{
	uint32_t cap = 2048 * 2048;
	uint32_t *px = malloc((size_t)cap * 4);

	memset(f, 0, sizeof(*f));
	f->pixels = (uintptr_t)px;
	f->cap = cap;
	if (drmIoctl(fd, DRM_IOCTL_RDC_FRAME, f) || !f->seq) {
		free(px);
		return NULL;
	}
	return px;
}

typedef uint32_t (*expect_fn)(uint32_t x, uint32_t y, void *ctx);

/*
 * Wait until the frame is WxH and every pixel is what `want` says; print
 * the first difference on failure.
 */
static int wait_frame(int fd, uint32_t w, uint32_t h, expect_fn want, void *ctx,
		      const char *what)
{
	uint64_t end = now_ms() + WAIT_MS;
	struct drm_rdc_frame f;
	uint32_t x = 0, y = 0, got = 0, exp = 0;
	uint32_t *px;
	int ok;

	do {
		px = get_frame(fd, &f);
		ok = px && f.width == w && f.height == h;
		for (y = 0; ok && y < h; y++)
			for (x = 0; ok && x < w; x++) {
				got = px[(size_t)y * w + x] & 0xffffff;
				exp = want(x, y, ctx) & 0xffffff;
				ok = got == exp;
			}
		free(px);
		if (ok) {
			printf("%s: frame %llu %ux%u crc %08x as drawn\n", what,
			       (unsigned long long)f.seq, w, h, f.crc32);
			return 0;
		}
		usleep(POLL_MS * 1000);
	} while (now_ms() < end);
	FAIL("%s: frame %ux%u (want %ux%u), pixel (%u,%u) %06x, want %06x\n",
	     what, f.width, f.height, w, h, x ? x - 1 : 0, y ? y - 1 : 0, got,
	     exp);
	return -1;
}

static uint32_t want_pattern(uint32_t x, uint32_t y, void *ctx)
{
	return pattern(x, y, *(uint32_t *)ctx);
}

struct damaged {
	uint32_t salt, salt2;
};

static uint32_t want_damaged(uint32_t x, uint32_t y, void *ctx)
{
	struct damaged *d = ctx;

	if (x >= DAMAGE_X && x < DAMAGE_X + DAMAGE_W && y >= DAMAGE_Y &&
	    y < DAMAGE_Y + DAMAGE_H)
		return pattern(x, y, d->salt2);
	return pattern(x, y, d->salt);
}

static void counters(int fd, struct drm_rdc_counters *c)
{
	memset(c, 0, sizeof(*c));
	if (drmIoctl(fd, DRM_IOCTL_RDC_COUNTERS, c))
		FAIL("COUNTERS: %s\n", strerror(errno));
}

static int set_crtc(int fd, struct pipe_info *p, uint32_t fb)
{
	if (drmModeSetCrtc(fd, p->crtc, fb, 0, 0, &p->conn, 1, &p->mode)) {
		FAIL("SETCRTC %ux%u: %s\n", p->mode.hdisplay, p->mode.vdisplay,
		     strerror(errno));
		return -1;
	}
	return 0;
}

static void flip_handler(int fd, unsigned int seq, unsigned int sec,
			 unsigned int usec, void *data)
{
	(void)fd;
	(void)sec;
	(void)usec;
	*(unsigned int *)data = seq ? seq : 1;
}

/* A page flip with its event; the frame shows the new buffer. */
static void check_flip(int fd, struct pipe_info *p, struct dumb *b,
		       uint32_t salt)
{
	drmEventContext ev = { .version = 2,
			       .page_flip_handler = flip_handler };
	struct pollfd pfd = { .fd = fd, .events = POLLIN };
	struct drm_rdc_counters c0, c1;
	unsigned int seq = 0;

	counters(fd, &c0);
	if (drmModePageFlip(fd, p->crtc, b->fb, DRM_MODE_PAGE_FLIP_EVENT,
			    &seq)) {
		FAIL("PAGE_FLIP: %s\n", strerror(errno));
		return;
	}
	while (!seq && poll(&pfd, 1, WAIT_MS) > 0)
		drmHandleEvent(fd, &ev);
	counters(fd, &c1);
	if (!seq)
		FAIL("no flip event\n");
	else
		printf("flip event at vblank %u; flips %llu -> %llu\n", seq,
		       (unsigned long long)c0.flips,
		       (unsigned long long)c1.flips);
	if (c1.flips <= c0.flips)
		FAIL("the flip was not counted\n");
	wait_frame(fd, b->w, b->h, want_pattern, &salt, "page flip");
}

/* drmWaitVBlank N times: DRM's count moves as the chip's frames do. */
static void check_vblank(int fd)
{
	drmVBlank vb;
	struct drm_rdc_counters c0, c1;
	unsigned int first = 0, last = 0;
	int i;

	for (i = 0; i <= VBLANKS; i++) {
		memset(&vb, 0, sizeof(vb));
		vb.request.type = DRM_VBLANK_RELATIVE;
		vb.request.sequence = 1;
		if (drmWaitVBlank(fd, &vb)) {
			FAIL("WAIT_VBLANK: %s\n", strerror(errno));
			return;
		}
		if (!i) {
			counters(fd, &c0);
			first = vb.reply.sequence;
		}
		last = vb.reply.sequence;
	}
	counters(fd, &c1);
	printf("vblank %u -> %u (%u), chip frames %llu -> %llu, ts %ld.%06ld\n",
	       first, last, last - first, (unsigned long long)c0.frames,
	       (unsigned long long)c1.frames, vb.reply.tval_sec,
	       vb.reply.tval_usec);
	/* a loaded host may come back after the next vblank: more, not less */
	if (last - first < VBLANKS)
		FAIL("%u vblanks in %u waits\n", last - first, VBLANKS);
	/* the counters are read just after the vblank each wait ended at */
	if (c1.frames - c0.frames != last - first)
		FAIL("DRM counted %u vblanks, the chip %llu frames\n",
		     last - first, (unsigned long long)(c1.frames - c0.frames));
}

/* The private ioctls' bad input gets clean errors. */
static void check_bad_input(int fd)
{
	struct drm_rdc_reg r = { .reg = BAD_REG };
	struct drm_rdc_vram v = { 0 };
	struct drm_rdc_submit s = { 0 };
	struct drm_rdc_wait w = { 0 };
	uint32_t bad[] = { RDC_CMD(0xff, 0, 0) };
	uint32_t fill[] = {
		RDC_CMD(RDC_OP_FENCE, 0, 1),
		0x5eed,
	};

	if (!drmIoctl(fd, DRM_IOCTL_RDC_REG_READ, &r) || errno != EINVAL)
		FAIL("REG_READ of an unaligned register: %s\n",
		     strerror(errno));
	r.reg = RDC_REG_ID;
	if (drmIoctl(fd, DRM_IOCTL_RDC_REG_READ, &r) || r.val != RDC_ID_VALUE)
		FAIL("REG_READ ID: %08x\n", r.val);
	v.addr = 0xfffffff0u;
	v.len = 64;
	v.data = (uintptr_t)fill;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_VRAM, &v) || errno != EINVAL)
		FAIL("VRAM past its end: %s\n", strerror(errno));
	v.addr = 0;
	v.len = DRM_RDC_VRAM_MAX_BYTES + 1;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_VRAM, &v) || errno != E2BIG)
		FAIL("VRAM too long: %s\n", strerror(errno));
	v.len = 8;
	v.data = 1;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_VRAM, &v) || errno != EFAULT)
		FAIL("VRAM to a bad pointer: %s\n", strerror(errno));
	s.words = (uintptr_t)bad;
	s.count = 1;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s) || errno != EPROTO ||
	    s.bad_word != 0)
		FAIL("SUBMIT of a bad opcode: %s word %u\n", strerror(errno),
		     s.bad_word);
	s.count = DRM_RDC_SUBMIT_MAX_WORDS + 1;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s) || errno != E2BIG)
		FAIL("SUBMIT too long: %s\n", strerror(errno));
	s.count = 1;
	s.flags = 1u << 7;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s) || errno != EINVAL)
		FAIL("SUBMIT with unknown flags: %s\n", strerror(errno));
	s.flags = DRM_RDC_SUBMIT_GEM;
	s.handle = 0xdead;
	s.format = DRM_FORMAT_XRGB8888;
	s.width = 16;
	s.height = 16;
	s.pitch = 64;
	s.words = (uintptr_t)fill;
	s.count = 2;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s) || errno != ENOENT)
		FAIL("SUBMIT to no GEM handle: %s\n", strerror(errno));
	w.term[0].kind = 9;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_WAIT, &w) || errno != EINVAL)
		FAIL("WAIT of an unknown kind: %s\n", strerror(errno));
	w.term[0].kind = DRM_RDC_WAIT_GE;
	w.budget = DRM_RDC_MAX_CYCLES + 1;
	if (!drmIoctl(fd, DRM_IOCTL_RDC_WAIT, &w) || errno != EINVAL)
		FAIL("WAIT past the cap: %s\n", strerror(errno));
	s.flags = 0;
	s.words = (uintptr_t)fill;
	s.count = 2;
	if (drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s))
		FAIL("SUBMIT of a fence: %s\n", strerror(errno));
	memset(&w, 0, sizeof(w));
	w.term[0].kind = DRM_RDC_WAIT_EQ;
	w.term[0].reg = RDC_REG_FENCE;
	w.term[0].mask = ~0u;
	w.term[0].value = 0x5eed;
	w.flags = DRM_RDC_WAIT_NEEDS_DP;
	if (drmIoctl(fd, DRM_IOCTL_RDC_WAIT, &w))
		FAIL("WAIT for the fence: %s\n", strerror(errno));
	printf("private ioctls: bad input refused, a fence waited for\n");
}

/* SUBMIT with DRM_RDC_SUBMIT_GEM draws into a dumb buffer. */
static void check_submit_gem(int fd)
{
	struct dumb d;
	uint32_t words[] = {
		RDC_CMD(RDC_OP_SET_FG, 0, 1),
		0x00123456,
		RDC_CMD(RDC_OP_SET_ROP, 0, 1),
		RDC_ROP_COPY,
		RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
		RDC_XY(10, 20),
		RDC_WH(30, 40),
	};
	struct drm_rdc_submit s = {
		.words = (uintptr_t)words,
		.count = sizeof(words) / 4,
		.flags = DRM_RDC_SUBMIT_GEM,
		.format = DRM_FORMAT_XRGB8888,
	};
	uint32_t x, y, v, bad = 0;

	if (dumb_new(fd, &d, 128, 96, DRM_FORMAT_XRGB8888, 32)) {
		FAIL("dumb buffer: %s\n", strerror(errno));
		return;
	}
	memset(d.map, 0x11, d.size);
	s.handle = d.handle;
	s.width = d.w;
	s.height = d.h;
	s.pitch = d.pitch;
	if (drmIoctl(fd, DRM_IOCTL_RDC_SUBMIT, &s)) {
		FAIL("SUBMIT to a GEM buffer: %s\n", strerror(errno));
	} else {
		for (y = 0; y < d.h; y++)
			for (x = 0; x < d.w; x++) {
				v = ((uint32_t *)(d.map + y * d.pitch))[x] &
				    0xffffff;
				if (v !=
				    (x >= 10 && x < 40 && y >= 20 && y < 60 ?
					     0x123456u :
					     0x111111u))
					bad++;
			}
		if (bad)
			FAIL("SUBMIT to a GEM buffer: %u pixels wrong\n", bad);
		else
			printf("SUBMIT to a GEM buffer: the DP drew into it\n");
	}
	dumb_free(fd, &d);
}

static int cmd_kms(const char *dev)
{
	int fd = open_dev(dev);
	struct drm_rdc_counters c0, c1, c2;
	struct damaged dm = { .salt = 3, .salt2 = 77 };
	drmModeClip clip = { DAMAGE_X, DAMAGE_Y, DAMAGE_X + DAMAGE_W,
			     DAMAGE_Y + DAMAGE_H };
	struct pipe_info p;
	struct dumb a, b;
	uint32_t salt_b = 11;
	uint64_t cap = 0;
	uint64_t full, part;

	if (drmGetCap(fd, DRM_CAP_DUMB_BUFFER, &cap) || !cap)
		FAIL("no dumb buffers\n");
	if (drmGetCap(fd, DRM_CAP_TIMESTAMP_MONOTONIC, &cap) || !cap)
		FAIL("no monotonic timestamps\n");
	if (drmSetMaster(fd))
		FAIL("not master: %s\n", strerror(errno));
	if (find_pipe(fd, &p, 0, 0)) {
		FAIL("no connector with a preferred mode\n");
		return 1;
	}
	printf("preferred mode %s %ux%u %u kHz\n", p.mode.name, p.mode.hdisplay,
	       p.mode.vdisplay, p.mode.clock);
	if (p.mode.hdisplay != 1024 || p.mode.vdisplay != 768)
		FAIL("1024x768 is not the preferred mode\n");
	if (dumb_new(fd, &a, p.mode.hdisplay, p.mode.vdisplay,
		     DRM_FORMAT_XRGB8888, 32) ||
	    dumb_new(fd, &b, p.mode.hdisplay, p.mode.vdisplay,
		     DRM_FORMAT_XRGB8888, 32)) {
		FAIL("dumb buffers: %s\n", strerror(errno));
		return 1;
	}
	fill_xrgb(&a, dm.salt, 0, 0, a.w, a.h);
	fill_xrgb(&b, salt_b, 0, 0, b.w, b.h);
	counters(fd, &c0);
	if (!set_crtc(fd, &p, a.fb))
		wait_frame(fd, a.w, a.h, want_pattern, &dm.salt, "mode set");
	counters(fd, &c1);
	full = c1.damage_cycles - c0.damage_cycles;

	/*
	 * The buffer a commit writes is one flip old: the first damage after
	 * the mode set uploads the whole screen again, the second its own
	 * rectangle and the first's.
	 */
	fill_xrgb(&a, dm.salt2, DAMAGE_X, DAMAGE_Y, DAMAGE_W, DAMAGE_H);
	if (drmModeDirtyFB(fd, a.fb, &clip, 1))
		FAIL("DIRTYFB: %s\n", strerror(errno));
	wait_frame(fd, a.w, a.h, want_damaged, &dm, "damage");
	counters(fd, &c1);
	dm.salt2 = 78;
	fill_xrgb(&a, dm.salt2, DAMAGE_X, DAMAGE_Y, DAMAGE_W, DAMAGE_H);
	if (drmModeDirtyFB(fd, a.fb, &clip, 1))
		FAIL("DIRTYFB: %s\n", strerror(errno));
	wait_frame(fd, a.w, a.h, want_damaged, &dm, "damage again");
	counters(fd, &c2);
	part = c2.damage_cycles - c1.damage_cycles;
	printf("upload cycles: whole screen %llu, %ux%u damage %llu\n",
	       (unsigned long long)full, DAMAGE_W, DAMAGE_H,
	       (unsigned long long)part);
	if (!full || !part || part * 16 > full)
		FAIL("a damaged rectangle cost %llu cycles, the screen %llu\n",
		     (unsigned long long)part, (unsigned long long)full);

	check_flip(fd, &p, &b, salt_b);
	check_vblank(fd);
	check_bad_input(fd);
	check_submit_gem(fd);

	/* every preset through a mode set */
	{
		drmModeConnector *c = drmModeGetConnector(fd, p.conn);
		int i;

		for (i = 0; c && i < c->count_modes; i++) {
			struct pipe_info q = p;
			struct dumb d;
			uint32_t salt = i;

			q.mode = c->modes[i];
			if (dumb_new(fd, &d, q.mode.hdisplay, q.mode.vdisplay,
				     DRM_FORMAT_XRGB8888, 32)) {
				FAIL("dumb %ux%u\n", q.mode.hdisplay,
				     q.mode.vdisplay);
				continue;
			}
			fill_xrgb(&d, salt, 0, 0, d.w, d.h);
			if (!set_crtc(fd, &q, d.fb))
				wait_frame(fd, d.w, d.h, want_pattern, &salt,
					   q.mode.name);
			dumb_free(fd, &d);
		}
		drmModeFreeConnector(c);
	}
	dumb_free(fd, &a);
	dumb_free(fd, &b);
	close(fd);
	return failures ? 1 : 0;
}

static int cmd_frame(const char *dev, const char *colour)
{
	int fd = open_dev(dev);
	struct drm_rdc_frame f;
	uint64_t end = now_ms() + WAIT_MS;
	uint32_t want = colour ? strtoul(colour, NULL, 16) : 0, *px;
	size_t i, n;
	int ok;

	for (;;) {
		px = get_frame(fd, &f);
		if (!px) {
			fprintf(stderr, "no frame yet\n");
			if (now_ms() > end)
				return 1;
			usleep(POLL_MS * 1000);
			continue;
		}
		n = (size_t)f.width * f.height;
		ok = crc32(0, (const uint8_t *)px, n * 4) == f.crc32;
		if (!ok) {
			printf("CRC %08x is not the pixels'\n", f.crc32);
			return 1;
		}
		for (i = 0; colour && i < n; i++)
			if ((px[i] & 0xffffff) != want)
				break;
		if (!colour || i == n)
			break;
		if (now_ms() > end) {
			printf("pixel %zu is %06x, want %06x\n", i,
			       px[i] & 0xffffff, want);
			free(px);
			return 1;
		}
		free(px);
		usleep(POLL_MS * 1000);
	}
	printf("%u %u %08x %llu\n", f.width, f.height, f.crc32,
	       (unsigned long long)f.seq);
	free(px);
	close(fd);
	return 0;
}

/* ---- formats ------------------------------------------------------------- */

/* An identity gamma LUT: what a previous test left is undone. */
static void gamma_identity(int fd, uint32_t crtc)
{
	uint16_t ramp[256];
	int i;

	for (i = 0; i < 256; i++)
		ramp[i] = i * 0x101;
	if (drmModeCrtcSetGamma(fd, crtc, 256, ramp, ramp, ramp))
		FAIL("identity gamma: %s\n", strerror(errno));
}

struct fmt_case {
	uint32_t format, bpp;
	const char *name;
};

static uint32_t fmt_pixel(uint32_t x, uint32_t y)
{
	return pattern(x, y, 5);
}

static void fill_fmt(struct dumb *d)
{
	uint32_t x, y, v, r, g, b;
	uint8_t *row;

	for (y = 0; y < d->h; y++) {
		row = d->map + (size_t)y * d->pitch;
		for (x = 0; x < d->w; x++) {
			v = fmt_pixel(x, y);
			r = v >> 16 & 0xff;
			g = v >> 8 & 0xff;
			b = v & 0xff;
			switch (d->format) {
			case DRM_FORMAT_RGB565:
				((uint16_t *)row)[x] = (r >> 3) << 11 |
						       (g >> 2) << 5 | b >> 3;
				break;
			case DRM_FORMAT_RGB888:
				row[3 * x] = b;
				row[3 * x + 1] = g;
				row[3 * x + 2] = r;
				break;
			case DRM_FORMAT_C8:
				row[x] = v & 0xff;
				break;
			default:
				((uint32_t *)row)[x] = (x & 0xff) << 24 | v;
				break;
			}
		}
	}
}

struct fmt_ctx {
	uint32_t format;
	/* a gamma LUT in force (XRGB8888), or none */
	const uint16_t *lr, *lg, *lb;
};

static uint32_t want_fmt(uint32_t x, uint32_t y, void *ctx)
{
	struct fmt_ctx *c = ctx;
	uint32_t v = fmt_pixel(x, y), r = v >> 16 & 0xff, g = v >> 8 & 0xff,
		 b = v & 0xff;

	switch (c->format) {
	case DRM_FORMAT_RGB565:
		r >>= 3;
		g >>= 2;
		b >>= 3;
		return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 |
		       (b << 3 | b >> 2);
	case DRM_FORMAT_C8:
		/* the palette: index i is (255 - i, i, i / 2) */
		b = v & 0xff;
		return (255 - b) << 16 | b << 8 | b / 2;
	default:
		if (c->lr)
			return (uint32_t)(c->lr[r] >> 8) << 16 |
			       (uint32_t)(c->lg[g] >> 8) << 8 | c->lb[b] >> 8;
		return v;
	}
}

static int cmd_formats(const char *dev)
{
	static const struct fmt_case cases[] = {
		{ DRM_FORMAT_XRGB8888, 32, "XRGB8888" },
		{ DRM_FORMAT_ARGB8888, 32, "ARGB8888" },
		{ DRM_FORMAT_RGB888, 24, "RGB888" },
		{ DRM_FORMAT_RGB565, 16, "RGB565" },
		{ DRM_FORMAT_C8, 8, "C8" },
	};
	uint16_t red[256], green[256], blue[256];
	int fd = open_dev(dev);
	struct pipe_info p;
	struct fmt_ctx ctx = { 0 };
	unsigned int i;
	struct dumb d;

	if (find_pipe(fd, &p, 640, 480)) {
		FAIL("no 640x480 mode\n");
		return 1;
	}
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		if (dumb_new(fd, &d, 640, 480, cases[i].format, cases[i].bpp)) {
			FAIL("%s: dumb buffer: %s\n", cases[i].name,
			     strerror(errno));
			continue;
		}
		fill_fmt(&d);
		if (!set_crtc(fd, &p, d.fb) && cases[i].format != DRM_FORMAT_C8)
			gamma_identity(fd, p.crtc);
		if (cases[i].format == DRM_FORMAT_C8) {
			int k;

			for (k = 0; k < 256; k++) {
				red[k] = (255 - k) * 0x101;
				green[k] = k * 0x101;
				blue[k] = k / 2 * 0x101;
			}
			if (drmModeCrtcSetGamma(fd, p.crtc, 256, red, green,
						blue))
				FAIL("C8: legacy gamma: %s\n", strerror(errno));
		}
		ctx.format = cases[i].format;
		wait_frame(fd, d.w, d.h, want_fmt, &ctx, cases[i].name);
		dumb_free(fd, &d);
	}
	/* a gamma LUT on direct colour: an inverting ramp */
	for (i = 0; i < 256; i++) {
		red[i] = (255 - i) * 0x101;
		green[i] = (255 - i) * 0x101;
		blue[i] = i * 0x101;
	}
	if (!dumb_new(fd, &d, 640, 480, DRM_FORMAT_XRGB8888, 32)) {
		fill_fmt(&d);
		if (!set_crtc(fd, &p, d.fb)) {
			if (drmModeCrtcSetGamma(fd, p.crtc, 256, red, green,
						blue))
				FAIL("gamma LUT: %s\n", strerror(errno));
			ctx.format = DRM_FORMAT_XRGB8888;
			ctx.lr = red;
			ctx.lg = green;
			ctx.lb = blue;
			wait_frame(fd, d.w, d.h, want_fmt, &ctx,
				   "XRGB8888 through a gamma LUT");
			gamma_identity(fd, p.crtc);
		}
		dumb_free(fd, &d);
	}
	close(fd);
	return failures ? 1 : 0;
}

/* ---- cursor -------------------------------------------------------------- */

struct cursor_ctx {
	const uint32_t *img; /* premultiplied ARGB8888, 64x64 */
};

static uint32_t blend(uint32_t src, uint32_t dst)
{
	uint32_t a = src >> 24, out = 0, s, d, c;
	int k;

	for (k = 0; k < 24; k += 8) {
		s = src >> k & 0xff;
		d = dst >> k & 0xff;
		c = s + (d * (255 - a) + 127) / 255;
		out |= (c > 255 ? 255 : c) << k;
	}
	return out;
}

static uint32_t want_cursor(uint32_t x, uint32_t y, void *ctx)
{
	struct cursor_ctx *c = ctx;
	uint32_t bg = pattern(x, y, 9);

	if (x >= CURSOR_X && x < CURSOR_X + CURSOR_SIZE && y >= CURSOR_Y &&
	    y < CURSOR_Y + CURSOR_SIZE)
		return blend(
			c->img[(y - CURSOR_Y) * CURSOR_SIZE + (x - CURSOR_X)],
			bg);
	return bg;
}

static int cmd_cursor(const char *dev)
{
	int fd = open_dev(dev);
	uint32_t img[CURSOR_SIZE * CURSOR_SIZE], x, y, a, salt = 9;
	struct cursor_ctx ctx = { img };
	struct pipe_info p;
	struct dumb d, cur;

	if (find_pipe(fd, &p, 640, 480) ||
	    dumb_new(fd, &d, 640, 480, DRM_FORMAT_XRGB8888, 32) ||
	    dumb_new(fd, &cur, CURSOR_SIZE, CURSOR_SIZE, DRM_FORMAT_ARGB8888,
		     32)) {
		FAIL("cursor: setup: %s\n", strerror(errno));
		return 1;
	}
	fill_xrgb(&d, salt, 0, 0, d.w, d.h);
	for (y = 0; y < CURSOR_SIZE; y++)
		for (x = 0; x < CURSOR_SIZE; x++) {
			/* alpha across, colour down, premultiplied */
			a = x * 4;
			img[y * CURSOR_SIZE + x] =
				a << 24 | (a * (y * 4) / 255) << 16 |
				(a * (255 - y * 4) / 255) << 8 | a / 3;
			((uint32_t *)(cur.map + y * cur.pitch))[x] =
				img[y * CURSOR_SIZE + x];
		}
	if (set_crtc(fd, &p, d.fb))
		return 1;
	gamma_identity(fd, p.crtc);
	if (drmModeSetCursor(fd, p.crtc, cur.handle, CURSOR_SIZE,
			     CURSOR_SIZE) ||
	    drmModeMoveCursor(fd, p.crtc, CURSOR_X, CURSOR_Y)) {
		FAIL("cursor: %s\n", strerror(errno));
		return 1;
	}
	wait_frame(fd, d.w, d.h, want_cursor, &ctx,
		   "ARGB cursor against software compositing");
	drmModeSetCursor(fd, p.crtc, 0, 0, 0);
	wait_frame(fd, d.w, d.h, want_pattern, &salt, "cursor off");
	close(fd);
	return failures ? 1 : 0;
}

/* ---- crc ----------------------------------------------------------------- */

static int cmd_crc(const char *dev, const char *dir)
{
	char path[512], line[128];
	int fd = open_dev(dev), cfd, dfd, i, matched = 0;
	struct drm_rdc_frame f;
	unsigned int frame, crc, prev = 0;
	uint32_t *px;
	ssize_t r;

	snprintf(path, sizeof(path), "%s/crtc-0/crc/control", dir);
	cfd = open(path, O_WRONLY);
	if (cfd < 0 || write(cfd, "auto", 4) != 4) {
		FAIL("%s: %s\n", path, strerror(errno));
		return 1;
	}
	close(cfd);
	snprintf(path, sizeof(path), "%s/crtc-0/crc/data", dir);
	dfd = open(path, O_RDONLY);
	if (dfd < 0) {
		FAIL("%s: %s\n", path, strerror(errno));
		return 1;
	}
	px = get_frame(fd, &f);
	free(px);
	for (i = 0; i < 10; i++) {
		r = read(dfd, line, sizeof(line) - 1);
		if (r <= 0) {
			FAIL("crc data: %s\n", r ? strerror(errno) : "EOF");
			break;
		}
		line[r] = 0;
		if (sscanf(line, "%x %x", &frame, &crc) != 2) {
			FAIL("crc data: \"%s\"\n", line);
			break;
		}
		if (i && frame != prev + 1)
			FAIL("crc frames %u then %u\n", prev, frame);
		prev = frame;
		/* a still picture: every frame's CRC is the FRAME ioctl's */
		if (crc == f.crc32)
			matched++;
		printf("crc frame %u %08x (FRAME %08x)\n", frame, crc, f.crc32);
	}
	close(dfd);
	if (matched != 10)
		FAIL("%d of 10 CRCs are the frame's\n", matched);
	close(fd);
	return failures ? 1 : 0;
}

/* ---- fuzz ---------------------------------------------------------------- */

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static uint32_t rnd(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 7;
	rng_state ^= rng_state << 17;
	return (uint32_t)(rng_state >> 16);
}

/* A word that is often near a boundary. */
static uint32_t rnd_word(void)
{
	static const uint32_t edge[] = {
		0,	     1,		  3,	       4,	  0xff,
		0x3ff,	     0x400,	  0xffff,      0x10000,	  0x7fffffff,
		0x80000000u, 0xfffffffcu, 0xffffffffu, 32u << 20, 16u << 20,
	};

	return rnd() % 3 ? rnd() : edge[rnd() % (sizeof(edge) / 4)];
}

/*
 * Random private ioctls with random arguments (REG_WRITE aside: a random
 * register write may switch scanout off, which is allowed and not what
 * is being looked for): each answers 0 or an errno, never hangs, and the
 * card draws a mode set after.
 */
static int cmd_fuzz(const char *dev, unsigned int n)
{
	int fd = open_dev(dev), ret;
	uint32_t words[64], *big = malloc(4u << 20), errs[160] = { 0 };
	struct pipe_info p;
	struct dumb d, g;
	uint32_t salt = 42;
	unsigned int i, k, ok = 0;

	if (!big || find_pipe(fd, &p, 320, 200) ||
	    dumb_new(fd, &g, 64, 48, DRM_FORMAT_XRGB8888, 32))
		return 1;
	for (i = 0; i < n; i++) {
		union {
			struct drm_rdc_reg r;
			struct drm_rdc_submit s;
			struct drm_rdc_wait w;
			struct drm_rdc_step st;
			struct drm_rdc_counters c;
			struct drm_rdc_frame f;
			struct drm_rdc_vram v;
			uint32_t raw[32];
		} a;
		unsigned long req;

		for (k = 0; k < 32; k++)
			a.raw[k] = rnd_word();
		for (k = 0; k < 64; k++)
			words[k] = rnd_word();
		switch (rnd() % 7) {
		case 0:
			req = DRM_IOCTL_RDC_REG_READ;
			break;
		case 1:
			req = DRM_IOCTL_RDC_SUBMIT;
			a.s.words = rnd() % 8 ? (uintptr_t)words : rnd_word();
			a.s.count %= rnd() % 4 ? 65 : 0x20000;
			if (a.s.count > 64)
				a.s.words = (uintptr_t)big;
			if (rnd() % 2) {
				a.s.flags = DRM_RDC_SUBMIT_GEM;
				a.s.reserved[0] = a.s.reserved[1] = 0;
				if (rnd() % 2) {
					a.s.handle = g.handle;
					a.s.format = DRM_FORMAT_XRGB8888;
					a.s.width %= 100;
					a.s.height %= 100;
					a.s.pitch %= 1024;
				}
			}
			break;
		case 2:
			req = DRM_IOCTL_RDC_WAIT;
			a.w.timeout_ms %= 20;
			a.w.budget %= 200000;
			if (rnd() % 2)
				a.w.term[0].kind %= 5;
			break;
		case 3:
			req = DRM_IOCTL_RDC_STEP;
			break;
		case 4:
			req = DRM_IOCTL_RDC_COUNTERS;
			break;
		case 5:
			req = DRM_IOCTL_RDC_FRAME;
			if (rnd() % 2) {
				a.f.pixels = (uintptr_t)big;
				a.f.cap %= (4u << 20) / 4;
			}
			break;
		default:
			req = DRM_IOCTL_RDC_VRAM;
			a.v.data = rnd() % 4 ? (uintptr_t)big : rnd_word();
			a.v.len %= rnd() % 2 ? 4096 : (4u << 20);
			a.v.flags &= rnd() % 2 ? DRM_RDC_VRAM_WRITE : ~0u;
			if (rnd() % 2)
				a.v.reserved = 0;
			break;
		}
		ret = ioctl(fd, req, &a);
		if (!ret)
			ok++;
		else
			errs[errno < 160 ? errno : 0]++;
	}
	printf("%u random ioctls: %u done, errors:", n, ok);
	for (k = 0; k < 160; k++)
		if (errs[k])
			printf(" %s %u", strerrorname_np(k), errs[k]);
	printf("\n");
	if (errs[0] || errs[ENOTTY])
		FAIL("an error that is no errno of the ioctls\n");
	/* the card still shows what it is given */
	if (dumb_new(fd, &d, 320, 200, DRM_FORMAT_XRGB8888, 32)) {
		FAIL("dumb buffer after fuzzing: %s\n", strerror(errno));
		return 1;
	}
	fill_xrgb(&d, salt, 0, 0, d.w, d.h);
	if (!set_crtc(fd, &p, d.fb))
		wait_frame(fd, d.w, d.h, want_pattern, &salt,
			   "a mode set after fuzzing");
	free(big);
	close(fd);
	return failures ? 1 : 0;
}

/* ---- stepped clock ------------------------------------------------------- */

/*
 * On the stepped clock: a mode set from a pattern, a damaged rectangle
 * and a page flip, then STEP a million cycles; print the counters and the
 * frame's CRC, which must come out the same on every load.
 */
static int cmd_stepped(const char *dev)
{
	int fd = open_dev(dev);
	drmModeClip clip = { 8, 8, 40, 24 };
	struct drm_rdc_step st = { .cycles = 1000000 };
	struct drm_rdc_counters c;
	struct drm_rdc_frame f;
	struct pipe_info p;
	struct dumb a, b;
	uint32_t *px;

	if (find_pipe(fd, &p, 640, 480) ||
	    dumb_new(fd, &a, 640, 480, DRM_FORMAT_XRGB8888, 32) ||
	    dumb_new(fd, &b, 640, 480, DRM_FORMAT_XRGB8888, 32))
		return 1;
	fill_xrgb(&a, 7, 0, 0, a.w, a.h);
	fill_xrgb(&b, 8, 0, 0, b.w, b.h);
	if (set_crtc(fd, &p, a.fb))
		return 1;
	fill_xrgb(&a, 9, 8, 8, 32, 16);
	if (drmModeDirtyFB(fd, a.fb, &clip, 1) ||
	    drmModeSetCrtc(fd, p.crtc, b.fb, 0, 0, &p.conn, 1, &p.mode) ||
	    drmIoctl(fd, DRM_IOCTL_RDC_STEP, &st)) {
		FAIL("stepped: %s\n", strerror(errno));
		return 1;
	}
	counters(fd, &c);
	px = get_frame(fd, &f);
	free(px);
	printf("now %llu frames %llu flips %llu damage %llu busy %llu crc %08x\n",
	       (unsigned long long)c.now, (unsigned long long)c.frames,
	       (unsigned long long)c.flips, (unsigned long long)c.damage_cycles,
	       (unsigned long long)c.busy, f.crc32);
	close(fd);
	return failures ? 1 : 0;
}

/* ---- hold and unbind ----------------------------------------------------- */

static volatile sig_atomic_t stop;

static void on_signal(int sig)
{
	(void)sig;
	stop = 1;
}

static int setup_screen(int fd, struct dumb *d)
{
	struct pipe_info p;
	uint32_t salt = 1;

	if (find_pipe(fd, &p, 640, 480) ||
	    dumb_new(fd, d, 640, 480, DRM_FORMAT_XRGB8888, 32))
		return -1;
	fill_xrgb(d, salt, 0, 0, d->w, d->h);
	return set_crtc(fd, &p, d->fb);
}

static int cmd_hold(const char *dev)
{
	int fd = open_dev(dev);
	struct dumb d;

	signal(SIGTERM, on_signal);
	signal(SIGINT, on_signal);
	if (setup_screen(fd, &d))
		return 1;
	printf("held\n");
	fflush(stdout);
	while (!stop)
		pause();
	return 0;
}

static int cmd_unbind(const char *dev, const char *pdev)
{
	int fd = open_dev(dev), ufd;
	struct drm_rdc_reg r = { .reg = RDC_REG_ID };
	struct dumb d;
	uint32_t sum = 0;
	size_t i;

	if (setup_screen(fd, &d))
		return 1;
	ufd = open("/sys/bus/platform/drivers/rdcdrm/unbind", O_WRONLY);
	if (ufd < 0 || write(ufd, pdev, strlen(pdev)) < 0) {
		FAIL("unbind %s: %s\n", pdev, strerror(errno));
		return 1;
	}
	close(ufd);
	if (!drmIoctl(fd, DRM_IOCTL_RDC_REG_READ, &r) || errno != ENODEV)
		FAIL("REG_READ after unbind: %s\n", strerror(errno));
	for (i = 0; i < d.size; i += 4096)
		sum += d.map[i];
	printf("unbound under the client: ioctls ENODEV, mapping read (%u)\n",
	       sum);
	munmap(d.map, d.size);
	close(fd);
	return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
	if (argc >= 3 && !strcmp(argv[1], "frame"))
		return cmd_frame(argv[2], argc > 3 ? argv[3] : NULL);
	if (argc == 3 && !strcmp(argv[1], "kms"))
		return cmd_kms(argv[2]);
	if (argc == 3 && !strcmp(argv[1], "formats"))
		return cmd_formats(argv[2]);
	if (argc == 3 && !strcmp(argv[1], "cursor"))
		return cmd_cursor(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "crc"))
		return cmd_crc(argv[2], argv[3]);
	if (argc == 3 && !strcmp(argv[1], "stepped"))
		return cmd_stepped(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "fuzz"))
		return cmd_fuzz(argv[2], strtoul(argv[3], NULL, 0));
	if (argc == 3 && !strcmp(argv[1], "hold"))
		return cmd_hold(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "unbind"))
		return cmd_unbind(argv[2], argv[3]);
	fprintf(stderr, "usage: rdcdrm_tool frame|kms|formats|cursor|crc|"
			"fuzz|stepped|hold|unbind DEV [...]\n");
	return 2;
}
