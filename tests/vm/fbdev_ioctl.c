// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * fbdev_ioctl: rdcfb.ko's standard framebuffer ioctls as fbdev clients
 * use them, checked against the chip's own registers (read through the
 * private REG_READ ioctl) and against the frames it scans out.  Prints TAP.
 *
 *   fbdev_ioctl [--device /dev/fbN]             run the checks
 *   fbdev_ioctl --prepare [--device /dev/fbN]   put the chip in its
 *       power-on state (soft reset, VRAM zeroed) and print
 *       "time T vram N", so a run on it can be compared with a fresh sim:
 *   fbdev_ioctl --get [--device /dev/fbN]       print "XRESxYRES-BPP"
 *   fbdev_ioctl --fbset-mode PRESET BPP         print an fbset mode-file
 *       entry "rdc" for a preset (its index in enum rdc_preset)
 *
 * Expect fbcon to be unbound from the device: a console drawing on it
 * would change what the frames show.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>
#include <zlib.h>

#include "rdc_chip.h"
#include "rdc_regs.h"
#include "rdc.h"
#include "rdcfb_ioctl.h"
#include "tap.h"

#define PS_PER_KHZ 1000000000ull /* picoseconds per period of 1 kHz */
#define CMAP_SHIFT 8		 /* fbdev colour maps are 16 bits a channel */
#define PAN_PRESET RDC_PRESET_640x480_60

static int fd = -1;

static int xioctl(unsigned long req, void *arg)
{
	int r;

	do {
		r = ioctl(fd, req, arg);
	} while (r < 0 && errno == EINTR);
	return r;
}

static uint32_t reg(uint32_t r)
{
	struct rdcfb_reg rr = { .reg = r };

	if (xioctl(RDCFB_IOC_REG_READ, &rr)) {
		printf("# REG_READ 0x%03x: %s\n", r, strerror(errno));
		return 0xdeadbeef;
	}
	return rr.val;
}

static int reg_write(uint32_t r, uint32_t v)
{
	struct rdcfb_reg rr = { .reg = r, .val = v };

	return xioctl(RDCFB_IOC_REG_WRITE, &rr);
}

static int vsync(void)
{
	__u32 crtc = 0;

	return xioctl(FBIO_WAITFORVSYNC, &crtc);
}

/*
 * The first frame scanned entirely after now: two vblanks, the first
 * latching what was programmed (base, format, mode are latched), the
 * second ending a frame made with it.
 */
static int next_frame(void)
{
	return vsync() || vsync() ? -1 : 0;
}

/* zlib CRC-32 of pixels as little-endian bytes, on any host. */
static uint32_t crc_le(const uint32_t *pix, size_t n)
{
	uLong crc = crc32(0L, Z_NULL, 0);

	for (size_t i = 0; i < n; i++) {
		uint8_t b[4] = { (uint8_t)pix[i], (uint8_t)(pix[i] >> 8),
				 (uint8_t)(pix[i] >> 16),
				 (uint8_t)(pix[i] >> 24) };

		crc = crc32(crc, b, sizeof(b));
	}
	return (uint32_t)crc;
}

/* The last complete frame into *pix (malloc'd); its CRC is checked. */
static int frame(uint32_t **pix, uint32_t *w, uint32_t *h)
{
	struct rdcfb_frame f;
	uint32_t *buf;

	memset(&f, 0, sizeof(f));
	if (xioctl(RDCFB_IOC_FRAME, &f) || !f.seq)
		return -1;
	buf = malloc((size_t)f.width * f.height * sizeof(*buf) + 1);
	if (!buf)
		return -1;
	f.pixels = (uintptr_t)buf;
	f.cap = f.width * f.height;
	if (xioctl(RDCFB_IOC_FRAME, &f)) {
		free(buf);
		return -1;
	}
	*pix = buf;
	*w = f.width;
	*h = f.height;
	/* The driver's CRC is over the pixels as little-endian bytes. */
	if (f.crc32 != crc_le(buf, (size_t)f.width * f.height)) {
		printf("# FRAME crc32 %08x does not match its pixels\n",
		       f.crc32);
		free(buf);
		return -1;
	}
	return 0;
}

/* ---- Modes --------------------------------------------------------------- */

struct fmt {
	uint32_t rdc; /* enum rdc_format */
	uint32_t bpp, visual;
	struct fb_bitfield red, green, blue;
	const char *name;
};

/* What an fbdev client expects of each format the device offers. */
static const struct fmt fmts[] = {
	{ RDC_FMT_I8,
	  8,
	  FB_VISUAL_PSEUDOCOLOR,
	  { 0, 8, 0 },
	  { 0, 8, 0 },
	  { 0, 8, 0 },
	  "8 bpp indexed" },
	{ RDC_FMT_RGB565,
	  16,
	  FB_VISUAL_TRUECOLOR,
	  { 11, 5, 0 },
	  { 5, 6, 0 },
	  { 0, 5, 0 },
	  "RGB565" },
	{ RDC_FMT_XRGB8888,
	  32,
	  FB_VISUAL_TRUECOLOR,
	  { 16, 8, 0 },
	  { 8, 8, 0 },
	  { 0, 8, 0 },
	  "XRGB8888" },
};

static void var_from_preset(struct fb_var_screeninfo *v, uint32_t preset,
			    uint32_t bpp)
{
	struct rdc_timing t;

	rdc_preset_timing(preset, &t);
	v->xres = v->xres_virtual = t.h_display;
	v->yres = v->yres_virtual = t.v_display;
	v->xoffset = v->yoffset = 0;
	v->bits_per_pixel = bpp;
	v->grayscale = 0;
	memset(&v->red, 0, sizeof(v->red));
	memset(&v->green, 0, sizeof(v->green));
	memset(&v->blue, 0, sizeof(v->blue));
	memset(&v->transp, 0, sizeof(v->transp));
	v->nonstd = 0;
	v->activate = FB_ACTIVATE_NOW;
	v->pixclock = (uint32_t)(PS_PER_KHZ / t.pixclk_khz);
	v->right_margin = t.h_sync_start - t.h_display;
	v->hsync_len = t.h_sync_end - t.h_sync_start;
	v->left_margin = t.h_total - t.h_sync_end;
	v->lower_margin = t.v_sync_start - t.v_display;
	v->vsync_len = t.v_sync_end - t.v_sync_start;
	v->upper_margin = t.v_total - t.v_sync_end;
	v->sync = ((t.flags & RDC_CRTC_HSYNC_POS) ? FB_SYNC_HOR_HIGH_ACT : 0) |
		  ((t.flags & RDC_CRTC_VSYNC_POS) ? FB_SYNC_VERT_HIGH_ACT : 0);
	v->vmode = FB_VMODE_NONINTERLACED;
}

static int bitfield_eq(const struct fb_bitfield *a, const struct fb_bitfield *b)
{
	return a->offset == b->offset && a->length == b->length &&
	       a->msb_right == b->msb_right;
}

/* Set a preset in a format; 0 if the device took it. */
static int set_mode(uint32_t preset, const struct fmt *f, uint32_t vmul)
{
	struct fb_var_screeninfo v;

	if (xioctl(FBIOGET_VSCREENINFO, &v))
		return -1;
	var_from_preset(&v, preset, f->bpp);
	v.yres_virtual *= vmul;
	return xioctl(FBIOPUT_VSCREENINFO, &v);
}

static void check_mode(uint32_t preset, const struct fmt *f, uint32_t smem_len)
{
	struct fb_var_screeninfo v;
	struct fb_fix_screeninfo fix;
	struct rdc_timing t;
	uint32_t row, *pix = NULL, w = 0, h = 0, khz;
	char name[64];

	rdc_preset_timing(preset, &t);
	snprintf(name, sizeof(name), "%ux%u %s", t.h_display, t.v_display,
		 f->name);
	row = rdc_format_row_bytes(f->rdc, t.h_display);
	if ((uint64_t)row * t.v_display > smem_len) {
		printf("ok %u - # SKIP %s: %u bytes of VRAM\n", ++tap_n, name,
		       smem_len);
		return;
	}
	if (set_mode(preset, f, 1)) {
		tap(0, "%s: FBIOPUT_VSCREENINFO: %s", name, strerror(errno));
		return;
	}
	if (xioctl(FBIOGET_VSCREENINFO, &v) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		tap(0, "%s: FBIOGET_*SCREENINFO: %s", name, strerror(errno));
		return;
	}
	tap(v.xres == t.h_display && v.yres == t.v_display &&
		    v.bits_per_pixel == f->bpp,
	    "%s: var reads back %ux%u-%u", name, v.xres, v.yres,
	    v.bits_per_pixel);
	tap(bitfield_eq(&v.red, &f->red) && bitfield_eq(&v.green, &f->green) &&
		    bitfield_eq(&v.blue, &f->blue) && !v.transp.length,
	    "%s: colour bitfields r %u/%u g %u/%u b %u/%u a %u/%u", name,
	    v.red.offset, v.red.length, v.green.offset, v.green.length,
	    v.blue.offset, v.blue.length, v.transp.offset, v.transp.length);
	tap(v.right_margin == t.h_sync_start - t.h_display &&
		    v.hsync_len == t.h_sync_end - t.h_sync_start &&
		    v.left_margin == t.h_total - t.h_sync_end &&
		    v.lower_margin == t.v_sync_start - t.v_display &&
		    v.vsync_len == t.v_sync_end - t.v_sync_start &&
		    v.upper_margin == t.v_total - t.v_sync_end,
	    "%s: var keeps the timings", name);
	tap(fix.visual == f->visual && fix.type == FB_TYPE_PACKED_PIXELS,
	    "%s: visual %u type %u", name, fix.visual, fix.type);
	tap(fix.line_length >= row && !(fix.line_length & 3) &&
		    fix.line_length == reg(RDC_REG_FB_STRIDE),
	    "%s: line_length %u (row %u bytes, FB_STRIDE %u)", name,
	    fix.line_length, row, reg(RDC_REG_FB_STRIDE));
	tap(fix.smem_len == smem_len, "%s: smem_len stays %u", name,
	    fix.smem_len);
	tap(reg(RDC_REG_FB_FORMAT) == f->rdc, "%s: FB_FORMAT %u", name,
	    reg(RDC_REG_FB_FORMAT));
	khz = reg(RDC_REG_PIXCLK_KHZ);
	tap(reg(RDC_REG_H_DISPLAY) == t.h_display &&
		    reg(RDC_REG_H_SYNC_START) == t.h_sync_start &&
		    reg(RDC_REG_H_SYNC_END) == t.h_sync_end &&
		    reg(RDC_REG_H_TOTAL) == t.h_total &&
		    reg(RDC_REG_V_DISPLAY) == t.v_display &&
		    reg(RDC_REG_V_SYNC_START) == t.v_sync_start &&
		    reg(RDC_REG_V_SYNC_END) == t.v_sync_end &&
		    reg(RDC_REG_V_TOTAL) == t.v_total,
	    "%s: CRTC timing registers hold the preset", name);
	/* The picosecond period loses a little: within 0.1 %. */
	tap(khz * 1000ull >= t.pixclk_khz * 999ull &&
		    khz * 1000ull <= t.pixclk_khz * 1001ull,
	    "%s: PIXCLK_KHZ %u (preset %u)", name, khz, t.pixclk_khz);
	if (next_frame() || frame(&pix, &w, &h)) {
		tap(0, "%s: a frame after two vsyncs: %s", name,
		    strerror(errno));
		return;
	}
	tap(w == t.h_display && h == t.v_display, "%s: frames are %ux%u", name,
	    w, h);
	free(pix);
}

/* ---- Colour map, mapping, pan, vsync, blank ------------------------------ */

static uint16_t cm_r(unsigned int i)
{
	return (uint16_t)(i * 257);
}
static uint16_t cm_g(unsigned int i)
{
	return (uint16_t)((255 - i) * 257);
}
static uint16_t cm_b(unsigned int i)
{
	return (uint16_t)((i * 7 & 255) * 257);
}

static uint32_t cm_rgb(unsigned int i)
{
	return (uint32_t)(cm_r(i) >> CMAP_SHIFT) << 16 |
	       (uint32_t)(cm_g(i) >> CMAP_SHIFT) << 8 |
	       (uint32_t)(cm_b(i) >> CMAP_SHIFT);
}

static void check_cmap(uint8_t *vram)
{
	static uint16_t r[RDC_CLUT_ENTRIES], g[RDC_CLUT_ENTRIES],
		b[RDC_CLUT_ENTRIES], r2[RDC_CLUT_ENTRIES], g2[RDC_CLUT_ENTRIES],
		b2[RDC_CLUT_ENTRIES];
	struct fb_cmap cm = { 0, RDC_CLUT_ENTRIES, r, g, b, NULL };
	struct fb_cmap back = { 0, RDC_CLUT_ENTRIES, r2, g2, b2, NULL };
	struct fb_fix_screeninfo fix;
	uint32_t bad = 0, *pix = NULL, w, h, stride;
	unsigned int i;

	if (set_mode(PAN_PRESET, &fmts[0], 1) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		tap(0, "cmap: 640x480 8 bpp: %s", strerror(errno));
		return;
	}
	for (i = 0; i < RDC_CLUT_ENTRIES; i++) {
		r[i] = cm_r(i);
		g[i] = cm_g(i);
		b[i] = cm_b(i);
	}
	tap(!xioctl(FBIOPUTCMAP, &cm), "FBIOPUTCMAP 256 entries");
	tap(!xioctl(FBIOGETCMAP, &back) && !memcmp(r, r2, sizeof(r)) &&
		    !memcmp(g, g2, sizeof(g)) && !memcmp(b, b2, sizeof(b)),
	    "FBIOGETCMAP gives them back");
	reg_write(RDC_REG_CLUT_INDEX, 0);
	for (i = 0; i < RDC_CLUT_ENTRIES; i++)
		if (reg(RDC_REG_CLUT_DATA) != cm_rgb(i))
			bad++;
	tap(!bad, "the CLUT holds the map (%u entries differ)", bad);

	/* A partial map changes only its own entries. */
	cm.start = 10;
	cm.len = 5;
	for (i = 0; i < 5; i++)
		r[i] = g[i] = b[i] = 0xffff;
	tap(!xioctl(FBIOPUTCMAP, &cm), "FBIOPUTCMAP entries 10..14");
	reg_write(RDC_REG_CLUT_INDEX, 9);
	bad = reg(RDC_REG_CLUT_DATA) != cm_rgb(9);
	for (i = 10; i < 15; i++)
		bad += reg(RDC_REG_CLUT_DATA) != 0xffffff;
	bad += reg(RDC_REG_CLUT_DATA) != cm_rgb(15);
	tap(!bad, "CLUT 9..15 after the partial map");

	/* Pixels written through the mapping, looked up in the CLUT. */
	stride = fix.line_length;
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++)
			vram[y * stride + x] = (uint8_t)(x + y);
	if (next_frame() || frame(&pix, &w, &h) || w != 640 || h != 480) {
		tap(0, "8 bpp frame: %s", strerror(errno));
		free(pix);
		return;
	}
	bad = 0;
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++) {
			uint8_t k = (uint8_t)(x + y);
			uint32_t want = k >= 10 && k < 15 ? 0xffffff :
							    cm_rgb(k);

			bad += pix[y * 640 + x] != want;
		}
	tap(!bad,
	    "8 bpp pixels written through mmap show in the next frame "
	    "through the CLUT (%u differ)",
	    bad);
	free(pix);
}

static void check_direct(uint8_t *vram)
{
	struct fb_fix_screeninfo fix;
	uint32_t bad = 0, *pix = NULL, w, h;
	/* Full-intensity channels expand to 0xff whatever the rounding. */
	static const uint16_t p565[] = { 0xf800, 0x07e0, 0x001f, 0xffff, 0 };
	static const uint32_t x565[] = { 0xff0000, 0x00ff00, 0x0000ff, 0xffffff,
					 0 };

	if (set_mode(PAN_PRESET, &fmts[2], 1) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		tap(0, "640x480 XRGB8888: %s", strerror(errno));
		return;
	}
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++) {
			uint32_t v = 0xff000000u |
				     (x * 0x010203u + y * 0x0301u);

			memcpy(vram + y * fix.line_length + x * 4, &v, 4);
		}
	if (next_frame() || frame(&pix, &w, &h) || w != 640 || h != 480) {
		tap(0, "XRGB8888 frame: %s", strerror(errno));
		free(pix);
		return;
	}
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++)
			bad += pix[y * 640 + x] !=
			       ((x * 0x010203u + y * 0x0301u) & 0xffffff);
	free(pix);
	tap(!bad,
	    "XRGB8888 pixels written through mmap show in the next "
	    "frame (%u differ)",
	    bad);

	if (set_mode(PAN_PRESET, &fmts[1], 1) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		tap(0, "640x480 RGB565: %s", strerror(errno));
		return;
	}
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++)
			memcpy(vram + y * fix.line_length + x * 2,
			       &p565[(x / 8) % 5], 2);
	if (next_frame() || frame(&pix, &w, &h) || w != 640 || h != 480) {
		tap(0, "RGB565 frame: %s", strerror(errno));
		free(pix);
		return;
	}
	bad = 0;
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++)
			bad += pix[y * 640 + x] != x565[(x / 8) % 5];
	free(pix);
	tap(!bad,
	    "RGB565 pixels written through mmap show in the next frame "
	    "(%u differ)",
	    bad);
}

static void fill32(uint8_t *p, uint32_t stride, uint32_t rows, uint32_t v)
{
	for (uint32_t y = 0; y < rows; y++)
		for (uint32_t x = 0; x < 640; x++)
			memcpy(p + y * stride + x * 4, &v, 4);
}

static int frame_is(uint32_t want)
{
	uint32_t *pix = NULL, w, h, bad = 0;

	if (frame(&pix, &w, &h))
		return 0;
	for (size_t i = 0; i < (size_t)w * h; i++)
		bad += pix[i] != want;
	free(pix);
	return !bad && w == 640 && h == 480;
}

static void check_pan(uint8_t *vram, uint32_t smem_len)
{
	struct fb_var_screeninfo v;
	struct fb_fix_screeninfo fix;
	const uint32_t page0 = 0x112233, page1 = 0x445566;
	uint32_t base;

	if ((uint64_t)640 * 4 * 480 * 2 > smem_len) {
		tap_skip("pan: VRAM too small for two 640x480x32 pages");
		return;
	}
	if (set_mode(PAN_PRESET, &fmts[2], 2) ||
	    xioctl(FBIOGET_VSCREENINFO, &v) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		tap(0, "pan: 640x480 virtual 640x960: %s", strerror(errno));
		return;
	}
	tap(v.yres_virtual == 960 && fix.ypanstep >= 1,
	    "pan: yres_virtual %u, ypanstep %u", v.yres_virtual, fix.ypanstep);
	fill32(vram, fix.line_length, 480, page0);
	fill32(vram + 480 * fix.line_length, fix.line_length, 480, page1);
	tap(!next_frame() && frame_is(page0), "pan: page 0 shows");
	v.xoffset = 0;
	v.yoffset = 480;
	tap(!xioctl(FBIOPAN_DISPLAY, &v), "FBIOPAN_DISPLAY to y 480");
	base = reg(RDC_REG_FB_BASE);
	tap(base == 480 * fix.line_length, "pan: FB_BASE %u (want %u)", base,
	    480 * fix.line_length);
	tap(!next_frame() && frame_is(page1),
	    "pan: page 1 shows after the next vblank");
	tap(!xioctl(FBIOGET_VSCREENINFO, &v) && v.yoffset == 480,
	    "pan: var's yoffset reads 480");
	v.yoffset = 481 + 480; /* past the virtual screen */
	tap(xioctl(FBIOPAN_DISPLAY, &v) && errno == EINVAL,
	    "pan past the virtual screen: EINVAL");
	v.yoffset = 0;
	tap(!xioctl(FBIOPAN_DISPLAY, &v) && !next_frame() && frame_is(page0),
	    "pan back to y 0: page 0 shows");
}

static void check_vsync_blank(void)
{
	uint32_t fc0, fc1, ctl;
	int bad = 0;

	for (int i = 0; i < 3; i++) {
		fc0 = reg(RDC_REG_FRAME_COUNT);
		if (vsync())
			bad++;
		fc1 = reg(RDC_REG_FRAME_COUNT);
		bad += fc1 != fc0 + 1;
	}
	tap(!bad, "FBIO_WAITFORVSYNC: FRAME_COUNT advances by one, 3 times");

	tap(!xioctl(FBIOBLANK, (void *)(uintptr_t)FB_BLANK_POWERDOWN),
	    "FBIOBLANK powerdown");
	ctl = reg(RDC_REG_CONTROL);
	tap(!(ctl & RDC_CONTROL_SCANOUT_EN),
	    "blanked: CONTROL 0x%08x has no "
	    "SCANOUT_EN",
	    ctl);
	tap(!xioctl(FBIOBLANK, (void *)(uintptr_t)FB_BLANK_UNBLANK),
	    "FBIOBLANK unblank");
	ctl = reg(RDC_REG_CONTROL);
	tap(ctl & RDC_CONTROL_SCANOUT_EN,
	    "unblanked: CONTROL 0x%08x has "
	    "SCANOUT_EN",
	    ctl);
	fc0 = reg(RDC_REG_FRAME_COUNT);
	tap(!vsync() && reg(RDC_REG_FRAME_COUNT) == fc0 + 1,
	    "unblanked: frames run again");
}

/* STATE: read-only, its reserved word must be 0, its pointer readable */
static void check_state(void)
{
	struct rdc_chip_state st = { .reserved = 1 };
	uint32_t fc = reg(RDC_REG_FRAME_COUNT);
	bool ok;

	tap(xioctl(RDCFB_IOC_STATE, &st) && errno == EINVAL,
	    "STATE with reserved set: EINVAL");
	tap(ioctl(fd, RDCFB_IOC_STATE, NULL) && errno == EFAULT,
	    "STATE at a NULL pointer: EFAULT");
	memset(&st, 0, sizeof(st));
	ok = !xioctl(RDCFB_IOC_STATE, &st);
	tap(ok && (uint32_t)st.frame_count >= fc &&
		    (st.flags & RDC_CHIP_STATE_SCANNING) && !st.reserved,
	    "STATE: frame %llu (FRAME_COUNT was %u), scanning",
	    (unsigned long long)st.frame_count, fc);
}

static void check_refusals(void)
{
	struct fb_var_screeninfo v, keep;
	uint32_t fmt;

	xioctl(FBIOGET_VSCREENINFO, &keep);
	v = keep;
	v.xres = v.xres_virtual = RDC_CRTC_MAX_DISPLAY * 2;
	tap(xioctl(FBIOPUT_VSCREENINFO, &v) && errno == EINVAL,
	    "xres %u: EINVAL", v.xres);
	fmt = reg(RDC_REG_FB_FORMAT);
	v = keep;
	var_from_preset(&v, RDC_PRESET_800x600_60,
			keep.bits_per_pixel == 8 ? 16 : 8);
	v.activate = FB_ACTIVATE_TEST;
	tap(!xioctl(FBIOPUT_VSCREENINFO, &v), "FB_ACTIVATE_TEST accepted");
	tap(!xioctl(FBIOGET_VSCREENINFO, &v) && v.xres == keep.xres &&
		    v.bits_per_pixel == keep.bits_per_pixel &&
		    reg(RDC_REG_FB_FORMAT) == fmt,
	    "FB_ACTIVATE_TEST changes nothing");
	check_state();
}

/* ---- Entry points -------------------------------------------------------- */

static int run_checks(void)
{
	struct fb_var_screeninfo v, saved;
	struct fb_fix_screeninfo fix;
	uint8_t *vram;
	uint32_t vsize;

	if (xioctl(FBIOGET_VSCREENINFO, &saved) ||
	    xioctl(FBIOGET_FSCREENINFO, &fix)) {
		printf("Bail out! FBIOGET_*SCREENINFO: %s\n", strerror(errno));
		return 1;
	}
	tap(!strncmp(fix.id, RDCFB_ID, sizeof(fix.id)), "fix.id \"%.16s\"",
	    fix.id);
	vsize = reg(RDC_REG_VRAM_SIZE);
	tap(fix.smem_len == vsize, "smem_len %u == VRAM_SIZE %u", fix.smem_len,
	    vsize);
	tap(saved.xres == reg(RDC_REG_H_DISPLAY) &&
		    saved.yres == reg(RDC_REG_V_DISPLAY),
	    "var %ux%u matches H_DISPLAY x V_DISPLAY", saved.xres, saved.yres);
	tap(fix.line_length == reg(RDC_REG_FB_STRIDE),
	    "line_length %u == FB_STRIDE", fix.line_length);
	vram = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		    0);
	if (vram == MAP_FAILED) {
		printf("Bail out! mmap %u bytes: %s\n", fix.smem_len,
		       strerror(errno));
		return 1;
	}
	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++)
		for (size_t i = 0; i < RDC_ARRAY_SIZE(fmts); i++)
			check_mode(p, &fmts[i], fix.smem_len);
	check_cmap(vram);
	check_direct(vram);
	check_pan(vram, fix.smem_len);
	check_vsync_blank();
	check_refusals();
	saved.activate = FB_ACTIVATE_NOW;
	tap(!xioctl(FBIOPUT_VSCREENINFO, &saved) &&
		    !xioctl(FBIOGET_VSCREENINFO, &v) && v.xres == saved.xres &&
		    v.bits_per_pixel == saved.bits_per_pixel,
	    "the first mode restored");
	munmap(vram, fix.smem_len);
	return tap_done();
}

/* Soft reset and zeroed VRAM: the state of a fresh sim: device. */
static int prepare(void)
{
	struct fb_fix_screeninfo fix;
	struct rdcfb_reg lo = { .reg = RDC_REG_TIME_LO };
	struct rdcfb_reg hi = { .reg = RDC_REG_TIME_HI };
	uint8_t *vram;

	if (xioctl(FBIOGET_FSCREENINFO, &fix))
		return 1;
	vram = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		    0);
	if (vram == MAP_FAILED)
		return 1;
	memset(vram, 0, fix.smem_len);
	munmap(vram, fix.smem_len);
	if (reg_write(RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET) ||
	    xioctl(RDCFB_IOC_REG_READ, &lo) || xioctl(RDCFB_IOC_REG_READ, &hi))
		return 1;
	printf("time %llu vram %u\n",
	       (unsigned long long)((uint64_t)hi.val << 32 | lo.val),
	       reg(RDC_REG_VRAM_SIZE));
	return 0;
}

static int fbset_mode(const char *p, const char *b)
{
	struct fb_var_screeninfo v;

	memset(&v, 0, sizeof(v));
	var_from_preset(&v, (uint32_t)atoi(p), (uint32_t)atoi(b));
	printf("mode \"rdc\"\n"
	       "    geometry %u %u %u %u %u\n"
	       "    timings %u %u %u %u %u %u %u\n"
	       "%s%s"
	       "endmode\n",
	       v.xres, v.yres, v.xres_virtual, v.yres_virtual, v.bits_per_pixel,
	       v.pixclock, v.left_margin, v.right_margin, v.upper_margin,
	       v.lower_margin, v.hsync_len, v.vsync_len,
	       (v.sync & FB_SYNC_HOR_HIGH_ACT) ? "    hsync high\n" : "",
	       (v.sync & FB_SYNC_VERT_HIGH_ACT) ? "    vsync high\n" : "");
	return 0;
}

int main(int argc, char **argv)
{
	const char *dev = "/dev/fb0", *mode = "check";

	setvbuf(stdout, NULL, _IOLBF, 0);
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--device") && i + 1 < argc) {
			dev = argv[++i];
		} else if (!strcmp(argv[i], "--prepare")) {
			mode = "prepare";
		} else if (!strcmp(argv[i], "--get")) {
			mode = "get";
		} else if (!strcmp(argv[i], "--fbset-mode") && i + 2 < argc) {
			if (atoi(argv[i + 1]) < 0 ||
			    atoi(argv[i + 1]) >= RDC_PRESET_COUNT)
				return 2;
			return fbset_mode(argv[i + 1], argv[i + 2]);
		} else {
			fprintf(stderr,
				"usage: fbdev_ioctl [--device DEV] "
				"[--prepare | --get | --fbset-mode PRESET "
				"BPP]\n");
			return 2;
		}
	}
	fd = open(dev, O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		printf("Bail out! %s: %s\n", dev, strerror(errno));
		return 1;
	}
	if (!strcmp(mode, "prepare"))
		return prepare();
	if (!strcmp(mode, "get")) {
		struct fb_var_screeninfo v;

		if (xioctl(FBIOGET_VSCREENINFO, &v))
			return 1;
		printf("%ux%u-%u\n", v.xres, v.yres, v.bits_per_pixel);
		return 0;
	}
	return run_checks();
}
