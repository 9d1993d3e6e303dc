// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * A small DRM/KMS client for the DisplayLink personality's VM tests
 * (tests/vm/tests/udl-*.sh): on the udl card it sets a mode with a dumb
 * XRGB8888 buffer holding a known pattern, and checks through rdcd's
 * socket (an observer) that the RDC-1 scans out exactly that pattern in
 * RGB565 (what udl sends: each channel truncated).
 *
 *   drm_pattern --uri URI --mode WxH [--clock KHZ] [--rect X,Y,W,H]
 *               [--bench N] [--loop] [--exec CMD [--raw FILE FMT]]
 *   drm_pattern --crc URI      print the CRC-32 of rdcd's last frame
 *   drm_pattern --ink URI X,Y,W,H
 *
 * The mode is the connector's mode named WxH (with --clock, the one of
 * that pixel clock in kHz: DRM offers CTA-861 twins of some modes under
 * the same name); once its frame is right, the CRTC's pixel clock must be
 * the mode's (within the 5 kHz steps udl sends it in, or the preset's own
 * clock when the EDID rounded it).
 * --rect: then change that rectangle, flush it with DIRTYFB, check the
 * frame again (only the rectangle changed) and print the bytes the device
 * took for it (its statistics request, when built with libusb) and the
 * display processor's busy cycles.  --bench N: N full-screen updates and
 * 10 N updates of a 64x64 rectangle, timed (figures as '#' lines, not
 * conditions).  --loop: update until the card goes away (unplug test):
 * exit 0 when it did, with no check.  --exec CMD: with the mode still set
 * (this program holds the card), run CMD through the shell; its status
 * counts.  --raw FILE FMT: then FILE must hold whole frames (rgb24 or
 * bgr32, as ffmpeg's rawvideo writes them) each equal to the pattern
 * through RGB565 and the CRTC's expansion of it (bit replication).
 *
 * --ink: until rdcd's frame has pixels other than black inside the
 * rectangle and none outside it (W or H 0: none anywhere), at most
 * CHECK_MS; prints the counts (the console test).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

#include "rdc.h"
#ifdef RDC_HAVE_USB
#include <libusb.h>

#include "udl_decode.h"
#endif

#define CHECK_MS 180000 /* at most this long for a frame to show up */

struct fb {
	uint32_t w, h, pitch, handle, id;
	uint64_t size;
	uint32_t *px;
};

static uint64_t now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u;
}

/* Pattern `seed`: flat bands (runs on the wire) and gradients (raw). */
static uint32_t pattern(uint32_t x, uint32_t y, uint32_t seed)
{
	if ((x / 64 + y / 48 + seed) % 3 == 0)
		return 0x00ff8040u ^ (seed * 0x103050u);
	return ((x * 5 + seed * 17) & 0xff) << 16 | ((y * 3) & 0xff) << 8 |
	       ((x ^ y ^ seed) & 0xff);
}

static uint16_t to565(uint32_t p)
{
	return (uint16_t)((p >> 19 & 0x1f) << 11 | (p >> 10 & 0x3f) << 5 |
			  (p >> 3 & 0x1f));
}

static int open_udl(void)
{
	for (int i = 0; i < 16; i++) {
		char path[32];
		drmVersionPtr v;
		int fd;

		snprintf(path, sizeof(path), "/dev/dri/card%d", i);
		fd = open(path, O_RDWR | O_CLOEXEC);
		if (fd < 0)
			continue;
		v = drmGetVersion(fd);
		if (v && !strcmp(v->name, "udl")) {
			drmFreeVersion(v);
			printf("# %s is udl\n", path);
			return fd;
		}
		if (v)
			drmFreeVersion(v);
		close(fd);
	}
	return -1;
}

static int fb_create(int fd, struct fb *f, uint32_t w, uint32_t h)
{
	struct drm_mode_create_dumb c = { .width = w, .height = h, .bpp = 32 };
	struct drm_mode_map_dumb m = { 0 };

	if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &c))
		return -1;
	f->w = w;
	f->h = h;
	f->pitch = c.pitch;
	f->handle = c.handle;
	f->size = c.size;
	if (drmModeAddFB(fd, w, h, 24, 32, c.pitch, c.handle, &f->id))
		return -1;
	m.handle = c.handle;
	if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &m))
		return -1;
	f->px = mmap(NULL, c.size, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		     m.offset);
	return f->px == MAP_FAILED ? -1 : 0;
}

static void fb_draw(struct fb *f, uint32_t x0, uint32_t y0, uint32_t w,
		    uint32_t h, uint32_t seed, uint16_t *expect)
{
	for (uint32_t y = y0; y < y0 + h; y++)
		for (uint32_t x = x0; x < x0 + w; x++) {
			uint32_t p = pattern(x, y, seed);

			f->px[y * (f->pitch / 4) + x] = p;
			expect[y * f->w + x] = to565(p);
		}
}

static int dirty(int fd, struct fb *f, uint32_t x, uint32_t y, uint32_t w,
		 uint32_t h)
{
	drmModeClip c = { (uint16_t)x, (uint16_t)y, (uint16_t)(x + w),
			  (uint16_t)(y + h) };

	return drmModeDirtyFB(fd, f->id, &c, 1);
}

/* Until rdcd's frame equals expect: pixels that differ at the end. */
static long wait_frame(rdc_dev *dev, const uint16_t *expect, uint32_t w,
		       uint32_t h, uint64_t *ms)
{
	size_t cap = (size_t)w * h;
	uint32_t *frame = malloc(cap * 4);
	uint64_t t0 = now_ms();
	long bad = -1;

	if (!frame)
		return -1;
	while (now_ms() - t0 < CHECK_MS) {
		uint32_t fw = 0, fh = 0;
		int err = rdc_frame_grab(dev, frame, cap, &fw, &fh);

		if (err == 0 && fw == w && fh == h) {
			bad = 0;
			for (size_t i = 0; i < cap; i++)
				bad += to565(frame[i]) != expect[i];
			if (!bad)
				break;
		}
		usleep(20000);
	}
	*ms = now_ms() - t0;
	free(frame);
	return bad;
}

/* The device's statistics: bytes taken from the bulk stream, or -1. */
static long long dev_bytes(void)
{
#ifdef RDC_HAVE_USB
	libusb_context *ctx;
	libusb_device_handle *h;
	uint8_t st[RDC_UDL_STATS_SIZE];
	long long v = -1;

	if (libusb_init(&ctx))
		return -1;
	h = libusb_open_device_with_vid_pid(ctx, 0x17e9, 0x5244);
	if (h && libusb_control_transfer(h, 0xc0, RDC_UDL_REQ_STATS, 0, 0, st,
					 sizeof(st), 1000) == sizeof(st)) {
		v = 0;
		for (int k = 7; k >= 0; k--)
			v = v << 8 | st[k];
	}
	if (h)
		libusb_close(h);
	libusb_exit(ctx);
	return v;
#else
	return -1;
#endif
}

static uint64_t dp_busy(rdc_dev *dev)
{
	struct rdc_stats st;

	return rdc_stats_get(dev, &st) ? 0 : st.busy;
}

/* The chip's time (core cycles): what an update spans, idle included. */
static uint64_t sim_time(rdc_dev *dev)
{
	struct rdc_stats st;

	return rdc_stats_get(dev, &st) ? 0 : st.time;
}

/* The CRTC's 8-bit channels of an RGB565 pixel (hw-sim/crtc.c). */
static uint32_t from565(uint16_t v)
{
	uint32_t r = v >> 11 & 0x1f, g = v >> 5 & 0x3f, b = v & 0x1f;

	return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 |
	       (b << 3 | b >> 2);
}

/* Every frame of a raw file equals expect in fmt: 0, or -1 (said why). */
static int check_raw(const char *path, const char *fmt, const uint16_t *expect,
		     uint32_t w, uint32_t h)
{
	size_t bpp = !strcmp(fmt, "rgb24") ? 3 : !strcmp(fmt, "bgr32") ? 4 : 0;
	size_t fsize = (size_t)w * h * bpp, n = 0, got;
	uint8_t *buf;
	FILE *f;
	int ret = 0;

	if (!bpp) {
		fprintf(stderr, "drm_pattern: --raw: format rgb24 or bgr32\n");
		return -1;
	}
	f = fopen(path, "rb");
	buf = malloc(fsize);
	if (!f || !buf) {
		fprintf(stderr, "drm_pattern: %s: %s\n", path, strerror(errno));
		if (f)
			fclose(f);
		free(buf);
		return -1;
	}
	while ((got = fread(buf, 1, fsize, f)) == fsize) {
		long bad = 0;

		for (size_t i = 0; i < (size_t)w * h; i++) {
			uint32_t p = from565(expect[i]);
			const uint8_t *q = buf + i * bpp;
			uint8_t r = (uint8_t)(p >> 16), g = (uint8_t)(p >> 8),
				b = (uint8_t)p;

			if (bpp == 3)
				bad += q[0] != r || q[1] != g || q[2] != b;
			else
				bad += q[0] != b || q[1] != g || q[2] != r;
		}
		printf("# %s frame %zu (%s %ux%u): %ld pixels differ\n", path,
		       n, fmt, w, h, bad);
		if (bad)
			ret = -1;
		n++;
	}
	if (got || !n) {
		printf("# %s: %zu whole frames and %zu bytes more\n", path, n,
		       got);
		ret = -1;
	}
	fclose(f);
	free(buf);
	return ret;
}

/* --ink: see the top of the file. */
static int ink_main(const char *uri, const char *rect)
{
	uint32_t x0 = 0, y0 = 0, w = 0, h = 0, fw = 0, fh = 0;
	uint32_t *frame = malloc((size_t)2048 * 2048 * 4);
	uint64_t t0 = now_ms();
	long in = -1, out = -1;
	rdc_dev *dev;
	int ok = 0;

	if (!frame || sscanf(rect, "%u,%u,%u,%u", &x0, &y0, &w, &h) != 4 ||
	    rdc_open(uri, &dev)) {
		fprintf(stderr, "drm_pattern: --ink URI X,Y,W,H\n");
		free(frame);
		return 2;
	}
	while (!ok && now_ms() - t0 < CHECK_MS) {
		if (rdc_frame_grab(dev, frame, (size_t)2048 * 2048, &fw, &fh)) {
			usleep(20000);
			continue;
		}
		in = out = 0;
		for (uint32_t y = 0; y < fh; y++)
			for (uint32_t x = 0; x < fw; x++) {
				int inside = x >= x0 && x - x0 < w && y >= y0 &&
					     y - y0 < h;

				if (frame[(size_t)y * fw + x] & 0xffffffu)
					*(inside ? &in : &out) += 1;
			}
		ok = (w && h ? in > 0 : 1) && out == 0;
		if (!ok)
			usleep(20000);
	}
	printf("# %ux%u frame after %llu ms: %ld lit pixels in %ux%u at "
	       "%u,%u, %ld outside\n",
	       fw, fh, (unsigned long long)(now_ms() - t0), in, w, h, x0, y0,
	       out);
	rdc_close(dev);
	free(frame);
	return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
	const char *uri = NULL, *mode = NULL, *cmd = NULL, *raw = NULL;
	const char *raw_fmt = NULL;
	uint32_t rx = 0, ry = 0, rw = 0, rh = 0, bench = 0, clock = 0, pixclk;
	int loop = 0, fd, ret = 1;
	drmModeRes *res;
	drmModeConnector *conn = NULL;
	drmModeModeInfo *mi = NULL;
	uint32_t crtc;
	struct fb f;
	uint16_t *expect;
	rdc_dev *dev = NULL;
	uint64_t ms;
	long bad;

	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--uri") && i + 1 < argc)
			uri = argv[++i];
		else if (!strcmp(argv[i], "--mode") && i + 1 < argc)
			mode = argv[++i];
		else if (!strcmp(argv[i], "--rect") && i + 1 < argc)
			sscanf(argv[++i], "%u,%u,%u,%u", &rx, &ry, &rw, &rh);
		else if (!strcmp(argv[i], "--bench") && i + 1 < argc)
			bench = (uint32_t)atoi(argv[++i]);
		else if (!strcmp(argv[i], "--loop"))
			loop = 1;
		else if (!strcmp(argv[i], "--clock") && i + 1 < argc)
			clock = (uint32_t)atoi(argv[++i]);
		else if (!strcmp(argv[i], "--exec") && i + 1 < argc)
			cmd = argv[++i];
		else if (!strcmp(argv[i], "--raw") && i + 2 < argc) {
			raw = argv[++i];
			raw_fmt = argv[++i];
		} else if (!strcmp(argv[i], "--ink") && i + 2 < argc)
			return ink_main(argv[i + 1], argv[i + 2]);
		else if (!strcmp(argv[i], "--crc") && i + 1 < argc) {
			/* the CRC-32 of rdcd's last frame, nothing else */
			uint32_t crc = 0;

			if (rdc_open(argv[++i], &dev) ||
			    rdc_frame_crc(dev, &crc))
				return 1;
			printf("%08x\n", crc);
			rdc_close(dev);
			return 0;
		} else {
			fprintf(stderr,
				"usage: drm_pattern --uri URI --mode WxH "
				"[--clock KHZ] [--rect X,Y,W,H] [--bench N] "
				"[--loop] [--exec CMD [--raw FILE FMT]]\n"
				"       drm_pattern --crc URI\n"
				"       drm_pattern --ink URI X,Y,W,H\n");
			return 2;
		}
	}
	if (!mode || (!uri && !loop)) {
		fprintf(stderr, "drm_pattern: --mode and --uri are needed\n");
		return 2;
	}
	fd = open_udl();
	if (fd < 0) {
		fprintf(stderr, "drm_pattern: no udl card in /dev/dri\n");
		return 1;
	}
	res = drmModeGetResources(fd);
	for (int i = 0; res && i < res->count_connectors && !mi; i++) {
		conn = drmModeGetConnector(fd, res->connectors[i]);
		if (!conn || conn->connection != DRM_MODE_CONNECTED)
			continue;
		for (int m = 0; m < conn->count_modes && !mi; m++)
			if (!strcmp(conn->modes[m].name, mode) &&
			    (!clock || conn->modes[m].clock == clock))
				mi = &conn->modes[m];
	}
	if (!mi || !res->count_crtcs) {
		fprintf(stderr,
			"drm_pattern: no connected connector with %s "
			"(clock %u kHz)\n",
			mode, clock);
		return 1;
	}
	crtc = res->crtcs[0];
	if (fb_create(fd, &f, mi->hdisplay, mi->vdisplay)) {
		fprintf(stderr, "drm_pattern: dumb buffer: %s\n",
			strerror(errno));
		return 1;
	}
	expect = calloc((size_t)f.w * f.h, sizeof(*expect));
	if (!expect)
		return 1;
	fb_draw(&f, 0, 0, f.w, f.h, 0, expect);
	if (drmModeSetCrtc(fd, crtc, f.id, 0, 0, &conn->connector_id, 1, mi)) {
		fprintf(stderr, "drm_pattern: SetCrtc %s: %s\n", mode,
			strerror(errno));
		return 1;
	}
	if (loop) {
		/* until the card is unplugged under us */
		for (uint32_t s = 1;; s++) {
			fb_draw(&f, 0, 0, f.w, f.h, s, expect);
			if (dirty(fd, &f, 0, 0, f.w, f.h)) {
				printf("# DIRTYFB failed after %u updates: %s\n",
				       s, strerror(errno));
				return errno == ENODEV || errno == EIO ? 0 : 1;
			}
		}
	}
	if (rdc_open(uri, &dev)) {
		fprintf(stderr, "drm_pattern: cannot open %s\n", uri);
		return 1;
	}
	bad = wait_frame(dev, expect, f.w, f.h, &ms);
	printf("# %s (%u kHz, %.2f Hz): frame %s the pattern (%ld pixels "
	       "differ) after %llu ms\n",
	       mode, mi->clock,
	       mi->clock * 1000.0 / ((double)mi->htotal * mi->vtotal),
	       bad ? "DIFFERS FROM" : "equals", bad, (unsigned long long)ms);
	if (bad)
		goto out;
	/* udl sends the clock in 5 kHz steps; a preset's is its own */
	if (rdc_reg_read(dev, RDC_REG_PIXCLK_KHZ, &pixclk)) {
		fprintf(stderr, "drm_pattern: cannot read PIXCLK_KHZ\n");
		goto out;
	}
	printf("# CRTC pixel clock %u kHz (the mode's %u kHz)\n", pixclk,
	       mi->clock);
	if (pixclk + 10 <= (uint32_t)mi->clock ||
	    pixclk >= (uint32_t)mi->clock + 10)
		goto out;
	if (rw && rh) {
		long long b0 = dev_bytes(), b1;
		uint64_t c0 = dp_busy(dev), c1;

		fb_draw(&f, rx, ry, rw, rh, 7, expect);
		if (dirty(fd, &f, rx, ry, rw, rh)) {
			fprintf(stderr, "drm_pattern: DIRTYFB: %s\n",
				strerror(errno));
			goto out;
		}
		bad = wait_frame(dev, expect, f.w, f.h, &ms);
		b1 = dev_bytes();
		c1 = dp_busy(dev);
		printf("# %ux%u at %u,%u: frame %s (%ld pixels differ) after "
		       "%llu ms\n",
		       rw, rh, rx, ry, bad ? "DIFFERS" : "equals the update",
		       bad, (unsigned long long)ms);
		printf("# bytes on the bus for it: %lld (a full frame is about "
		       "%u as raw RGB565); DP busy cycles %llu\n",
		       b0 >= 0 && b1 >= 0 ? b1 - b0 : -1LL, 2 * f.w * f.h,
		       (unsigned long long)(c1 - c0));
		if (bad)
			goto out;
	}
	for (uint32_t pass = 0; bench && pass < 2; pass++) {
		uint32_t bw = pass ? 64 : f.w, bh = pass ? 64 : f.h;
		uint32_t count = pass ? 10 * bench : bench;
		long long b0 = dev_bytes(), b1;
		uint64_t c0 = dp_busy(dev), c1, t0 = now_ms(), t;
		uint64_t s0 = sim_time(dev), s1;

		for (uint32_t s = 0; s < count; s++) {
			fb_draw(&f, 0, 0, bw, bh, 100 + s, expect);
			if (dirty(fd, &f, 0, 0, bw, bh)) {
				fprintf(stderr, "drm_pattern: DIRTYFB: %s\n",
					strerror(errno));
				goto out;
			}
		}
		bad = wait_frame(dev, expect, f.w, f.h, &ms);
		t = now_ms() - t0;
		b1 = dev_bytes();
		c1 = dp_busy(dev);
		s1 = sim_time(dev);
		printf("# bench %s %ux%u updates: %u in %llu ms (%.1f/s, the "
		       "last shown), %lld bytes, %llu DP busy cycles and %llu "
		       "simulated cycles each%s\n",
		       mode, bw, bh, count, (unsigned long long)t,
		       t ? 1000.0 * count / (double)t : 0.0,
		       b0 >= 0 && b1 >= 0 ? (b1 - b0) / count : -1LL,
		       (unsigned long long)((c1 - c0) / count),
		       (unsigned long long)((s1 - s0) / count),
		       bad ? " -- FINAL FRAME DIFFERS" : "");
		if (bad)
			goto out;
	}
	if (cmd) {
		int st;

		fflush(stdout);
		st = system(cmd);
		if (st) {
			printf("# '%s' ended with status %d\n", cmd, st);
			goto out;
		}
		if (raw && check_raw(raw, raw_fmt, expect, f.w, f.h))
			goto out;
	}
	ret = 0;
out:
	if (dev)
		rdc_close(dev);
	return ret;
}
