// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb_tool: what the rdcfb VM tests (tests/vm/tests/rdcfb-*.sh) do to
 * /dev/fbN that a shell cannot.
 *
 *   rdcfb_tool use DEV            draw through SUBMIT and the mapping, read
 *                                 a frame back, check it (and a refused
 *                                 submit); exit 0 if all held
 *   rdcfb_tool hold DEV open|map  hold the device open, or only mapped (fd
 *                                 closed), print "held", wait for a signal
 *   rdcfb_tool unbind DEV PDEV    with DEV open and mapped, unbind platform
 *                                 device PDEV; the client survives
 *   rdcfb_tool modes DEV          every preset size at 8, 16 and 32 bpp
 *                                 through FBIOPUT_VSCREENINFO, a mode from
 *                                 its own timings, the CLUT through
 *                                 FBIOPUTCMAP, a page flip through
 *                                 FBIOPAN_DISPLAY: each seen in the frames
 *   rdcfb_tool counters DEV       print the counters
 *   rdcfb_tool frame DEV OUT      write the latest frame (XRGB8888 LE) to
 *                                 OUT; print "W H CRC" and check the CRC
 *   rdcfb_tool rawcrc FILE        CRC-32 of a 4-byte-per-pixel file with
 *                                 the 4th byte of each pixel zeroed
 *   rdcfb_tool text DEV TTY ROW COL S
 *                                 the frame shows S at text cell (ROW, COL)
 *                                 in the 8x16 font the console on TTY draws
 *                                 with (read back through KDFONTOP), in one
 *                                 FG on one BG
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <linux/kd.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>
#include <zlib.h>

#include "rdc_chip.h"
#include "rdc_regs.h"
#include "rdcfb_ioctl.h"

#define GLYPH_W	       8
#define GLYPH_H	       16
#define FENCE_VALUE    0x5eed
#define RECT_X	       100
#define RECT_Y	       100
#define RECT_W	       50
#define RECT_H	       40
#define RECT_COLOUR    0x00ff0000u
#define STRIPE_X       300
#define STRIPE_Y       200
#define STRIPE_W       100
#define STRIPE_H       10
#define FRAMES_TO_WAIT 2
#define FRAME_TRIES    200

static int fail(const char *what)
{
	fprintf(stderr, "%s: %s\n", what, strerror(errno));
	return 1;
}

static uint32_t stripe_px(uint32_t x, uint32_t y)
{
	return (0x00123456u ^ (x << 8) ^ (y << 16)) & 0x00ffffffu;
}

static int open_fb(const char *dev, struct fb_fix_screeninfo *fix,
		   struct fb_var_screeninfo *var)
{
	int fd = open(dev, O_RDWR);

	if (fd < 0)
		return -1;
	if (ioctl(fd, FBIOGET_FSCREENINFO, fix) ||
	    ioctl(fd, FBIOGET_VSCREENINFO, var)) {
		close(fd);
		return -1;
	}
	return fd;
}

/*
 * The latest frame into *px (malloc'ed); 0 or -1.  Its size comes from a
 * first call; a frame that grew before the second (another client set a
 * bigger mode) answers E2BIG with the new size, and is asked for again.
 */
static int get_frame(int fd, struct rdcfb_frame *f, uint32_t **px)
{
	int tries;

	memset(f, 0, sizeof(*f));
	if (ioctl(fd, RDCFB_IOC_FRAME, f))
		return -1;
	for (tries = 0; tries < 10; tries++) {
		*px = malloc((size_t)f->width * f->height * 4);
		if (!*px)
			return -1;
		f->pixels = (uintptr_t)*px;
		f->cap = f->width * f->height;
		if (!ioctl(fd, RDCFB_IOC_FRAME, f))
			return 0;
		free(*px);
		if (errno != E2BIG)
			return -1;
	}
	return -1;
}

static uint32_t crc_le(const uint32_t *px, size_t n)
{
	uLong crc = crc32(0, NULL, 0);

	for (size_t i = 0; i < n; i++) {
		uint8_t b[4] = { px[i], px[i] >> 8, px[i] >> 16, px[i] >> 24 };

		crc = crc32(crc, b, 4);
	}
	return (uint32_t)crc;
}

/* Wait until the frame number has moved on by n (vsyncs, paced or not). */
static int wait_frames(int fd, uint32_t n)
{
	struct rdcfb_frame f = { 0 };
	uint32_t start, tries;
	uint32_t crtc = 0;

	ioctl(fd, RDCFB_IOC_FRAME, &f);
	start = f.seq;
	for (tries = 0; tries < FRAME_TRIES; tries++) {
		if (ioctl(fd, FBIO_WAITFORVSYNC, &crtc) && errno != ETIMEDOUT)
			return -1;
		memset(&f, 0, sizeof(f));
		if (ioctl(fd, RDCFB_IOC_FRAME, &f) && errno != EAGAIN)
			return -1;
		if (f.seq - start >= n && f.seq)
			return 0;
	}
	errno = ETIMEDOUT;
	return -1;
}

static int cmd_use(const char *dev)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	struct rdcfb_counters c0, c1;
	struct rdcfb_frame f;
	uint32_t *px, *map, cmds[32], n = 0;
	int fd = open_fb(dev, &fix, &var), bad = 0;

	if (fd < 0)
		return fail("open");
	if (strcmp(fix.id, RDCFB_ID) || var.bits_per_pixel != 32 ||
	    fix.smem_len < fix.line_length * var.yres_virtual) {
		fprintf(stderr, "unexpected device: id %s bpp %u smem %u\n",
			fix.id, var.bits_per_pixel, fix.smem_len);
		return 1;
	}
	map = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		   0);
	if (map == MAP_FAILED)
		return fail("mmap");
	/* the mapping: a stripe written by the CPU, as in VRAM at yoffset 0 */
	for (uint32_t y = 0; y < STRIPE_H; y++)
		for (uint32_t x = 0; x < STRIPE_W; x++)
			map[(STRIPE_Y + y) * (fix.line_length / 4) + STRIPE_X +
			    x] = stripe_px(x, y);

	/* the DP: a filled rectangle and a fence */
	cmds[n++] = RDC_CMD(RDC_OP_SET_DST, 0, 4);
	cmds[n++] = 0;
	cmds[n++] = fix.line_length;
	cmds[n++] = RDC_WH(var.xres, var.yres);
	cmds[n++] = RDC_FMT_XRGB8888;
	cmds[n++] = RDC_CMD(RDC_OP_SET_CLIP, 0, 2);
	cmds[n++] = RDC_XY(0, 0);
	cmds[n++] = RDC_XY(var.xres, var.yres);
	cmds[n++] = RDC_CMD(RDC_OP_SET_ROP, 0, 1);
	cmds[n++] = RDC_ROP_COPY;
	cmds[n++] = RDC_CMD(RDC_OP_SET_FG, 0, 1);
	cmds[n++] = RECT_COLOUR;
	cmds[n++] = RDC_CMD(RDC_OP_FILL_RECT, 0, 2);
	cmds[n++] = RDC_XY(RECT_X, RECT_Y);
	cmds[n++] = RDC_WH(RECT_W, RECT_H);
	cmds[n++] = RDC_CMD(RDC_OP_FENCE, 0, 1);
	cmds[n++] = FENCE_VALUE;
	struct rdcfb_submit s = { .words = (uintptr_t)cmds, .count = n };
	struct rdcfb_wait w = {
		.term[0] = { RDCFB_WAIT_WRAP_GE, RDC_REG_FENCE, ~0u,
			     FENCE_VALUE },
		.flags = RDCFB_WAIT_NEEDS_DP,
	};
	if (ioctl(fd, RDCFB_IOC_SUBMIT, &s))
		return fail("submit");
	if (ioctl(fd, RDCFB_IOC_WAIT, &w))
		return fail("wait for the fence");

	/* a refused buffer: a good command, then an unknown opcode */
	uint32_t badbuf[] = { RDC_CMD(RDC_OP_SET_FG, 0, 1), 0,
			      RDC_CMD(0xee, 0, 0) };
	struct rdcfb_submit sb = { .words = (uintptr_t)badbuf, .count = 3 };
	if (ioctl(fd, RDCFB_IOC_COUNTERS, &c0))
		return fail("counters");
	if (!ioctl(fd, RDCFB_IOC_SUBMIT, &sb) || errno != EPROTO ||
	    sb.bad_word != 2) {
		fprintf(stderr, "bad buffer not refused (errno %d, word %u)\n",
			errno, sb.bad_word);
		bad = 1;
	}

	if (wait_frames(fd, FRAMES_TO_WAIT))
		return fail("frames");
	if (ioctl(fd, RDCFB_IOC_COUNTERS, &c1))
		return fail("counters");
	if (c1.cmds != c0.cmds) {
		/* fbcon's cursor may draw: allow only its commands */
		fprintf(stderr, "note: %u commands ran meanwhile\n",
			c1.cmds - c0.cmds);
	}
	if (get_frame(fd, &f, &px))
		return fail("frame");
	if (f.width != var.xres || f.height != var.yres) {
		fprintf(stderr, "frame %ux%u\n", f.width, f.height);
		bad = 1;
	}
	if (crc_le(px, (size_t)f.width * f.height) != f.crc32) {
		fprintf(stderr, "CRC %08x, zlib says %08x\n", f.crc32,
			crc_le(px, (size_t)f.width * f.height));
		bad = 1;
	}
	for (uint32_t y = 0; y < RECT_H; y++)
		for (uint32_t x = 0; x < RECT_W; x++)
			if (px[(RECT_Y + y) * f.width + RECT_X + x] !=
			    RECT_COLOUR)
				bad |= 2;
	for (uint32_t y = 0; y < STRIPE_H; y++)
		for (uint32_t x = 0; x < STRIPE_W; x++)
			if (px[(STRIPE_Y + y) * f.width + STRIPE_X + x] !=
			    stripe_px(x, y))
				bad |= 4;
	if (bad & 2)
		fprintf(stderr, "the rectangle is not in the frame\n");
	if (bad & 4)
		fprintf(stderr, "the mapped stripe is not in the frame\n");
	printf("frame %u: %ux%u crc %08x, %u cmds, %llu busy cycles\n", f.seq,
	       f.width, f.height, f.crc32, c1.cmds,
	       (unsigned long long)c1.busy);
	free(px);
	munmap(map, fix.smem_len);
	close(fd);
	return bad ? 1 : 0;
}

static const uint32_t preset_size[][2] = {
	{ 320, 200 },  { 640, 480 },  { 800, 600 },
	{ 1024, 768 }, { 1280, 720 }, { 1920, 1080 },
};
static const uint32_t depths[] = { 8, 16, 32 };

#define CMAP_INDEX  5
#define CMAP_R	    0x1234
#define CMAP_G	    0xabcd
#define CMAP_B	    0x8000
#define FLIP_COLOUR 0x0000ff00u

/* Put var, read it back: the mode in force and the frames it gives. */
static int set_mode(int fd, struct fb_var_screeninfo *var,
		    struct fb_fix_screeninfo *fix, uint32_t w, uint32_t h,
		    uint32_t bpp)
{
	struct rdcfb_frame f;
	uint32_t *px;
	int ok;

	var->activate = FB_ACTIVATE_NOW;
	if (ioctl(fd, FBIOPUT_VSCREENINFO, var))
		return fail("FBIOPUT_VSCREENINFO");
	if (ioctl(fd, FBIOGET_VSCREENINFO, var) ||
	    ioctl(fd, FBIOGET_FSCREENINFO, fix))
		return fail("FBIOGET_*SCREENINFO");
	if (var->xres != w || var->yres != h || var->bits_per_pixel != bpp ||
	    fix->line_length < w * bpp / 8 ||
	    fix->visual !=
		    (bpp == 8 ? FB_VISUAL_PSEUDOCOLOR : FB_VISUAL_TRUECOLOR)) {
		fprintf(stderr, "asked %ux%u-%u, got %ux%u-%u stride %u\n", w,
			h, bpp, var->xres, var->yres, var->bits_per_pixel,
			fix->line_length);
		return 1;
	}
	/* the new timing is in force from the frame after the next vblank */
	if (wait_frames(fd, 3) || get_frame(fd, &f, &px))
		return fail("frames");
	ok = f.width == w && f.height == h;
	free(px);
	if (!ok) {
		fprintf(stderr, "%ux%u-%u: frames are %ux%u\n", w, h, bpp,
			f.width, f.height);
		return 1;
	}
	return 0;
}

static int cmd_modes(const char *dev)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var, orig;
	struct rdcfb_frame f;
	uint32_t *px;
	uint8_t *map;
	int fd = open_fb(dev, &fix, &var);

	if (fd < 0)
		return fail("open");
	orig = var;
	for (size_t m = 0; m < sizeof(preset_size) / sizeof(preset_size[0]);
	     m++) {
		for (size_t d = 0; d < sizeof(depths) / sizeof(depths[0]);
		     d++) {
			var = orig;
			var.xres = var.xres_virtual = preset_size[m][0];
			var.yres = var.yres_virtual = preset_size[m][1];
			var.bits_per_pixel = depths[d];
			var.pixclock = 0; /* the preset of that size */
			if (set_mode(fd, &var, &fix, preset_size[m][0],
				     preset_size[m][1], depths[d]))
				return 1;
			printf("%ux%u-%u: pixclock %u ps, stride %u\n",
			       var.xres, var.yres, var.bits_per_pixel,
			       var.pixclock, fix.line_length);
		}
	}

	/* its own timings: 640x480 with wider porches and a slower clock */
	var = orig;
	var.bits_per_pixel = 32;
	var.pixclock = 50000; /* 20 MHz */
	var.left_margin = 60;
	var.right_margin = 20;
	var.hsync_len = 100;
	var.upper_margin = 30;
	var.lower_margin = 10;
	var.vsync_len = 5;
	if (set_mode(fd, &var, &fix, 640, 480, 32))
		return 1;
	if (var.pixclock != 50000 || var.left_margin != 60 ||
	    var.vsync_len != 5) {
		fprintf(stderr, "own timings not kept: pixclock %u\n",
			var.pixclock);
		return 1;
	}
	printf("640x480 own timings: pixclock %u, margins %u %u %u / %u %u %u\n",
	       var.pixclock, var.left_margin, var.right_margin, var.hsync_len,
	       var.upper_margin, var.lower_margin, var.vsync_len);

	/* 8 bpp: a CLUT entry through FBIOPUTCMAP, shown where VRAM has it */
	var = orig;
	var.bits_per_pixel = 8;
	var.pixclock = 0;
	if (set_mode(fd, &var, &fix, orig.xres, orig.yres, 8))
		return 1;
	uint16_t r = CMAP_R, g = CMAP_G, b = CMAP_B, rr, gg, bb;
	struct fb_cmap cmap = { .start = CMAP_INDEX,
				.len = 1,
				.red = &r,
				.green = &g,
				.blue = &b };
	if (ioctl(fd, FBIOPUTCMAP, &cmap))
		return fail("FBIOPUTCMAP");
	cmap.red = &rr;
	cmap.green = &gg;
	cmap.blue = &bb;
	if (ioctl(fd, FBIOGETCMAP, &cmap) || rr != r || gg != g || bb != b) {
		fprintf(stderr, "FBIOGETCMAP: %04x %04x %04x\n", rr, gg, bb);
		return 1;
	}
	map = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		   0);
	if (map == MAP_FAILED)
		return fail("mmap");
	memset(map, CMAP_INDEX, (size_t)fix.line_length * var.yres);
	if (wait_frames(fd, 2) || get_frame(fd, &f, &px))
		return fail("frames");
	uint32_t want = (uint32_t)(CMAP_R >> 8) << 16 | (CMAP_G >> 8) << 8 |
			CMAP_B >> 8;
	if (px[0] != want || px[f.width * f.height - 1] != want) {
		fprintf(stderr, "CLUT entry: frame has %06x, want %06x\n",
			px[0], want);
		return 1;
	}
	free(px);
	printf("8 bpp: CLUT %d = %06x in the frame\n", CMAP_INDEX, want);

	/* a page flip: two pages, the second green, panned to */
	var = orig;
	var.bits_per_pixel = 32;
	var.yres_virtual = orig.yres * 2;
	var.pixclock = 0;
	if (set_mode(fd, &var, &fix, orig.xres, orig.yres, 32))
		return 1;
	if (var.yres_virtual != orig.yres * 2) {
		fprintf(stderr, "yres_virtual %u\n", var.yres_virtual);
		return 1;
	}
	for (size_t i = 0; i < (size_t)fix.line_length / 4 * var.yres_virtual;
	     i++)
		((uint32_t *)map)[i] =
			i < (size_t)fix.line_length / 4 * var.yres ?
				0 :
				FLIP_COLOUR;
	var.yoffset = var.yres;
	if (ioctl(fd, FBIOPAN_DISPLAY, &var))
		return fail("FBIOPAN_DISPLAY");
	if (wait_frames(fd, 2) || get_frame(fd, &f, &px))
		return fail("frames");
	if (px[0] != FLIP_COLOUR || px[f.width * f.height - 1] != FLIP_COLOUR) {
		fprintf(stderr, "after the flip the frame has %06x\n", px[0]);
		return 1;
	}
	free(px);
	printf("page flip to yoffset %u shown\n", var.yoffset);

	/* blanking stops the frames; unblanking brings them back */
	if (ioctl(fd, FBIOBLANK, FB_BLANK_POWERDOWN))
		return fail("FBIOBLANK");
	uint32_t crtc = 0;
	if (!ioctl(fd, FBIO_WAITFORVSYNC, &crtc) || errno != ETIMEDOUT) {
		fprintf(stderr, "a vsync while blanked\n");
		return 1;
	}
	if (ioctl(fd, FBIOBLANK, FB_BLANK_UNBLANK) || wait_frames(fd, 1))
		return fail("unblank");
	printf("blank: no vsync; unblank: frames again\n");

	var = orig;
	var.activate = FB_ACTIVATE_NOW;
	if (ioctl(fd, FBIOPUT_VSCREENINFO, &var))
		return fail("restore the mode");
	munmap(map, fix.smem_len);
	close(fd);
	return 0;
}

static void on_signal(int sig)
{
	(void)sig;
	_exit(0);
}

static int cmd_hold(const char *dev, const char *how)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	int fd = open_fb(dev, &fix, &var);
	void *map;

	if (fd < 0)
		return fail("open");
	signal(SIGTERM, on_signal);
	if (!strcmp(how, "map")) {
		map = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE,
			   MAP_SHARED, fd, 0);
		if (map == MAP_FAILED)
			return fail("mmap");
		close(fd);
		memset(map, 0x5a, 4096);
	}
	printf("held\n");
	fflush(stdout);
	for (;;)
		pause();
}

static int cmd_unbind(const char *dev, const char *pdev)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	struct rdcfb_counters c;
	int fd = open_fb(dev, &fix, &var), ufd;
	uint8_t *map;

	if (fd < 0)
		return fail("open");
	map = mmap(NULL, fix.smem_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd,
		   0);
	if (map == MAP_FAILED)
		return fail("mmap");
	ufd = open("/sys/bus/platform/drivers/rdcfb/unbind", O_WRONLY);
	if (ufd < 0 || write(ufd, pdev, strlen(pdev)) != (ssize_t)strlen(pdev))
		return fail("unbind");
	close(ufd);
	/* the device is gone; the client's memory and fd are still good */
	memset(map, 0xa5, fix.smem_len);
	if (!ioctl(fd, RDCFB_IOC_COUNTERS, &c) || errno != ENODEV) {
		fprintf(stderr, "ioctl after unbind: errno %d\n", errno);
		return 1;
	}
	munmap(map, fix.smem_len);
	close(fd);
	printf("unbound while open and mapped: ioctls say ENODEV\n");
	return 0;
}

static int cmd_counters(const char *dev)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	struct rdcfb_counters c;
	int fd = open_fb(dev, &fix, &var);

	if (fd < 0 || ioctl(fd, RDCFB_IOC_COUNTERS, &c))
		return fail("counters");
	printf("now %llu busy %llu stall %llu pixels %llu cmds %u frames %u fence %u\n",
	       (unsigned long long)c.now, (unsigned long long)c.busy,
	       (unsigned long long)c.stall, (unsigned long long)c.pixels,
	       c.cmds, c.frames, c.fence);
	close(fd);
	return 0;
}

static int cmd_frame(const char *dev, const char *out)
{
	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	struct rdcfb_frame f;
	uint32_t *px;
	int fd = open_fb(dev, &fix, &var);
	FILE *o;

	if (fd < 0 || get_frame(fd, &f, &px))
		return fail("frame");
	o = fopen(out, "wb");
	if (!o)
		return fail(out);
	for (size_t i = 0; i < (size_t)f.width * f.height; i++) {
		uint8_t b[4] = { px[i], px[i] >> 8, px[i] >> 16, px[i] >> 24 };

		fwrite(b, 1, 4, o);
	}
	fclose(o);
	printf("%u %u %08x\n", f.width, f.height, f.crc32);
	return crc_le(px, (size_t)f.width * f.height) == f.crc32 ? 0 : 1;
}

static int cmd_rawcrc(const char *file)
{
	FILE *in = fopen(file, "rb");
	uLong crc = crc32(0, NULL, 0);
	uint8_t b[4];

	if (!in)
		return fail(file);
	while (fread(b, 1, 4, in) == 4) {
		b[3] = 0;
		crc = crc32(crc, b, 4);
	}
	fclose(in);
	printf("%08lx\n", crc);
	return 0;
}

/*
 * The console's own font, as fbcon draws it: glyphs of 8x16 pixels, 32
 * bytes apart (KDFONTOP's layout for widths up to 8).
 */
static int console_font(const char *tty, uint8_t *font, unsigned int count)
{
	struct console_font_op op = {
		.op = KD_FONT_OP_GET,
		.width = GLYPH_W,
		.height = 32,
		.charcount = count,
		.data = font,
	};
	int fd = open(tty, O_RDONLY), ret;

	if (fd < 0)
		return -1;
	ret = ioctl(fd, KDFONTOP, &op);
	close(fd);
	if (ret)
		return -1;
	if (op.width != GLYPH_W || op.height != GLYPH_H) {
		fprintf(stderr, "console font is %ux%u, not 8x16\n", op.width,
			op.height);
		errno = EINVAL;
		return -1;
	}
	return 0;
}

/*
 * The cells hold s's glyphs: every pixel a glyph sets is one colour (FG),
 * every other pixel of the cells another (BG).
 */
static int cmd_text(const char *dev, const char *tty, int row, int col,
		    const char *s)
{
	static uint8_t font[512 * 32];

	struct fb_fix_screeninfo fix;
	struct fb_var_screeninfo var;
	struct rdcfb_frame f;
	uint32_t *px, fg = 0, bg = 0;
	int fd = open_fb(dev, &fix, &var), have = 0, bad = 0;

	if (console_font(tty, font, 512))
		return fail("KDFONTOP");
	if (fd < 0 || get_frame(fd, &f, &px))
		return fail("frame");
	for (size_t k = 0; s[k]; k++) {
		for (int y = 0; y < GLYPH_H; y++) {
			uint8_t bits = font[(uint8_t)s[k] * 32 + y];

			for (int x = 0; x < GLYPH_W; x++) {
				uint32_t X =
					(uint32_t)((col + (int)k) * GLYPH_W +
						   x);
				uint32_t Y = (uint32_t)(row * GLYPH_H + y);
				uint32_t p, on = bits >> (7 - x) & 1;

				if (X >= f.width || Y >= f.height)
					return 1;
				p = px[Y * f.width + X];
				if (!(have & (1 << on))) {
					have |= 1 << on;
					if (on)
						fg = p;
					else
						bg = p;
				}
				if (p != (on ? fg : bg))
					bad++;
			}
		}
	}
	printf("text \"%s\" at %d,%d: fg %06x bg %06x, %d pixels differ\n", s,
	       row, col, fg, bg, bad);
	return bad || fg == bg ? 1 : 0;
}

int main(int argc, char **argv)
{
	if (argc == 3 && !strcmp(argv[1], "use"))
		return cmd_use(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "hold"))
		return cmd_hold(argv[2], argv[3]);
	if (argc == 4 && !strcmp(argv[1], "unbind"))
		return cmd_unbind(argv[2], argv[3]);
	if (argc == 3 && !strcmp(argv[1], "modes"))
		return cmd_modes(argv[2]);
	if (argc == 3 && !strcmp(argv[1], "counters"))
		return cmd_counters(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "frame"))
		return cmd_frame(argv[2], argv[3]);
	if (argc == 3 && !strcmp(argv[1], "rawcrc"))
		return cmd_rawcrc(argv[2]);
	if (argc == 7 && !strcmp(argv[1], "text"))
		return cmd_text(argv[2], argv[3], atoi(argv[4]), atoi(argv[5]),
				argv[6]);
	fprintf(stderr, "usage: see the top of tests/vm/rdcfb_tool.c\n");
	return 2;
}
