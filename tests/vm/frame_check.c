// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * frame_check: does what a compositor believes it shows equal what the
 * RDC-1 scans out?  Reads the compositor's own screenshot (a PNG, as
 * weston-screenshooter and grim write, or an XWD dump, as `xwd -root`
 * writes), grabs the chip's latest frame through librdc (by default
 * drm:, any URI with --uri), and compares them pixel for pixel after the
 * format conversion (both as 0xRRGGBB).  Screenshots do not show a
 * hardware cursor; the chip's frame does.  With --cursor, the chip's
 * cursor, read from its registers and VRAM, is composited over the
 * screenshot first (as the chip documents it), so the comparison checks
 * the cursor's image and position too; --cursor-at X,Y also requires the
 * cursor's top-left corner there.  --expect-rect X,Y,W,H,RRGGBB checks
 * instead that the chip's frame is that one colour in that rectangle
 * (no screenshot then).
 *
 * Prints one line: "same WxH" or the first differing pixel, both values
 * and the number of differing pixels.  Exit status: 0 same, 1 differ,
 * 2 error.
 */
#include <errno.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rdc.h"
#include "rdc_regs.h"

struct img {
	uint32_t w, h;
	uint32_t *px; /* 0x00RRGGBB */
};

static int png_load(const char *path, struct img *im)
{
	png_image pi;

	memset(&pi, 0, sizeof(pi));
	pi.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&pi, path)) {
		fprintf(stderr, "frame_check: %s: %s\n", path, pi.message);
		return -1;
	}
	pi.format = PNG_FORMAT_BGRA; /* little-endian 0xAARRGGBB words */
	im->w = pi.width;
	im->h = pi.height;
	im->px = calloc((size_t)im->w * im->h, 4);
	if (!im->px) {
		png_image_free(&pi);
		return -1;
	}
	if (!png_image_finish_read(&pi, NULL, im->px, 0, NULL)) {
		fprintf(stderr, "frame_check: %s: %s\n", path, pi.message);
		return -1;
	}
	for (size_t i = 0; i < (size_t)im->w * im->h; i++)
		im->px[i] &= 0xffffff;
	return 0;
}

static uint32_t be32(const uint8_t *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 |
	       (uint32_t)p[2] << 8 | p[3];
}

/* The component of `v` under `mask`, scaled to 8 bits. */
static uint32_t xwd_comp(uint32_t v, uint32_t mask)
{
	unsigned int shift = 0, bits = 0;

	if (!mask)
		return 0;
	while (!(mask & 1u << shift))
		shift++;
	while (shift + bits < 32 && mask & 1u << (shift + bits))
		bits++;
	v = (v & mask) >> shift;
	return bits >= 8 ? v >> (bits - 8) : v << (8 - bits);
}

/*
 * X Window Dump, version 7, as xwd writes it: a header of big-endian
 * CARD32 fields, the window name, the colour map, then ZPixmap rows of
 * 24- or 32-bit TrueColor pixels in the dump's byte order.
 */
static int xwd_load(const char *path, struct img *im)
{
	FILE *f = fopen(path, "rb");
	uint8_t hdr[100], *row = NULL;
	uint32_t hsize, fmt, depth, w, h, version, bpp, bpl, ncolors, order;
	uint32_t rmask, gmask, bmask;
	int ret = -1;

	if (!f) {
		fprintf(stderr, "frame_check: %s: %s\n", path, strerror(errno));
		return -1;
	}
	if (fread(hdr, 1, sizeof(hdr), f) != sizeof(hdr))
		goto bad;
	hsize = be32(hdr);
	fmt = be32(hdr + 8);
	depth = be32(hdr + 12);
	w = be32(hdr + 16);
	h = be32(hdr + 20);
	order = be32(hdr + 28);
	bpp = be32(hdr + 44);
	bpl = be32(hdr + 48);
	rmask = be32(hdr + 56);
	gmask = be32(hdr + 60);
	bmask = be32(hdr + 64);
	ncolors = be32(hdr + 76);
	version = be32(hdr + 4);
	if (version != 7 || fmt != 2 || (bpp != 32 && bpp != 24) ||
	    depth < 15 || !w || !h || w > 16384 || h > 16384 ||
	    bpl < w * (bpp / 8) || hsize < sizeof(hdr) || ncolors > 65536)
		goto bad;
	if (fseek(f, (long)hsize + (long)ncolors * 12, SEEK_SET))
		goto bad;
	im->w = w;
	im->h = h;
	im->px = calloc((size_t)w * h, 4);
	row = malloc(bpl);
	if (!im->px || !row)
		goto out;
	for (uint32_t y = 0; y < h; y++) {
		if (fread(row, 1, bpl, f) != bpl)
			goto bad;
		for (uint32_t x = 0; x < w; x++) {
			const uint8_t *p = row + (size_t)x * (bpp / 8);
			uint32_t v;

			if (bpp == 32)
				v = order ? be32(p) :
					    (uint32_t)p[3] << 24 |
						    (uint32_t)p[2] << 16 |
						    (uint32_t)p[1] << 8 | p[0];
			else
				v = order ? (uint32_t)p[0] << 16 |
						    (uint32_t)p[1] << 8 | p[2] :
					    (uint32_t)p[2] << 16 |
						    (uint32_t)p[1] << 8 | p[0];
			im->px[(size_t)y * w + x] = xwd_comp(v, rmask) << 16 |
						    xwd_comp(v, gmask) << 8 |
						    xwd_comp(v, bmask);
		}
	}
	ret = 0;
	goto out;
bad:
	fprintf(stderr,
		"frame_check: %s: not a 24/32-bit TrueColor XWD v7 dump\n",
		path);
out:
	free(row);
	fclose(f);
	return ret;
}

static int load(const char *path, struct img *im)
{
	size_t n = strlen(path);

	if (n > 4 && !strcmp(path + n - 4, ".xwd"))
		return xwd_load(path, im);
	return png_load(path, im);
}

/*
 * The chip's cursor over `im` as the CRTC composites it: the ARGB8888
 * mode's premultiplied "over" (docs/hardware.md), or the 2 bpp mode's
 * transparent / FG / BG / invert.  *cx, *cy: its top-left corner, or
 * INT32_MIN when the cursor is off.
 */
static int cursor_over(rdc_dev *dev, struct img *im, int32_t *cx, int32_t *cy)
{
	uint32_t ctl, pos, base, fg, bg, size = RDC_CURSOR_SIZE;
	bool argb = false;
	uint8_t *img;
	int ret;

	*cx = *cy = INT32_MIN;
	ret = rdc_reg_read(dev, RDC_REG_CONTROL, &ctl);
	if (ret)
		return ret;
	if (!(ctl & RDC_CONTROL_CURSOR_EN))
		return 0;
	if ((ret = rdc_reg_read(dev, RDC_REG_CURSOR_POS, &pos)) ||
	    (ret = rdc_reg_read(dev, RDC_REG_CURSOR_BASE, &base)) ||
	    (ret = rdc_reg_read(dev, RDC_REG_CURSOR_FG, &fg)) ||
	    (ret = rdc_reg_read(dev, RDC_REG_CURSOR_BG, &bg)))
		return ret;
	{
		uint32_t cc;

		ret = rdc_reg_read(dev, RDC_REG_CURSOR_CTRL, &cc);
		if (ret)
			return ret;
		argb = FIELD_GET(RDC_CURSOR_CTRL_FMT, cc) ==
		       RDC_CURSOR_FMT_ARGB8888;
		size = rdc_cursor_size(cc);
	}
	*cx = (int16_t)(pos & 0xffff);
	*cy = (int16_t)(pos >> 16);
	img = malloc(argb ? (size_t)size * size * 4 : RDC_CURSOR_BYTES);
	if (!img)
		return RDC_E_NOMEM;
	ret = rdc_vram_read(dev, base, img,
			    argb ? (size_t)size * size * 4 : RDC_CURSOR_BYTES);
	for (uint32_t y = 0; !ret && y < size; y++) {
		int64_t sy = (int64_t)*cy + y;

		if (sy < 0 || sy >= im->h)
			continue;
		for (uint32_t x = 0; x < size; x++) {
			int64_t sx = (int64_t)*cx + x;
			uint32_t *d;

			if (sx < 0 || sx >= im->w)
				continue;
			d = &im->px[(size_t)sy * im->w + (size_t)sx];
			if (argb) {
				const uint8_t *s =
					img + ((size_t)y * size + x) * 4;
				uint32_t a = s[3], out = 0;

				/* premultiplied over, rounded as the chip does */
				for (int c = 0; c < 3; c++) {
					uint32_t dc = *d >> (8 * c) & 0xff;
					uint32_t v = s[c] + (dc * (255 - a) +
							     127) / 255;

					out |= (v > 255 ? 255 : v) << (8 * c);
				}
				*d = out;
			} else {
				uint32_t i = y * size + x;
				uint32_t v = img[i / 4] >> (2 * (i % 4)) & 3;

				if (v == 1)
					*d = fg & 0xffffff;
				else if (v == 2)
					*d = bg & 0xffffff;
				else if (v == 3)
					*d ^= 0xffffff;
			}
		}
	}
	free(img);
	return ret;
}

int main(int argc, char **argv)
{
	const char *uri = "drm:", *shot = NULL;
	bool cursor = false, want_at = false, rect = false;
	uint32_t rx = 0, ry = 0, rw = 0, rh = 0, rgb = 0;
	int32_t at_x = 0, at_y = 0, cx = INT32_MIN, cy = INT32_MIN;
	struct img im = { 0 };
	uint32_t *fr, w, h;
	uint64_t diffs = 0;
	size_t first = SIZE_MAX;
	rdc_dev *dev;
	int ret;

	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--uri") && i + 1 < argc) {
			uri = argv[++i];
		} else if (!strcmp(argv[i], "--cursor")) {
			cursor = true;
		} else if (!strcmp(argv[i], "--cursor-at") && i + 1 < argc &&
			   sscanf(argv[i + 1], "%d,%d", &at_x, &at_y) == 2) {
			cursor = want_at = true;
			i++;
		} else if (!strcmp(argv[i], "--expect-rect") && i + 1 < argc &&
			   sscanf(argv[i + 1], "%u,%u,%u,%u,%x", &rx, &ry, &rw,
				  &rh, &rgb) == 5) {
			rect = true;
			i++;
		} else if (argv[i][0] != '-' && !shot) {
			shot = argv[i];
		} else {
			fprintf(stderr,
				"usage: frame_check [--uri URI] [--cursor] "
				"[--cursor-at X,Y] SHOT.png|SHOT.xwd\n"
				"       frame_check [--uri URI] --expect-rect "
				"X,Y,W,H,RRGGBB\n");
			return 2;
		}
	}
	if (!shot && !rect)
		return 2;
	if (shot && load(shot, &im))
		return 2;
	ret = rdc_open(uri, &dev);
	if (ret) {
		fprintf(stderr, "frame_check: %s: %s\n", uri,
			rdc_strerror(ret));
		return 2;
	}
	fr = malloc((size_t)RDC_CRTC_MAX_DISPLAY * RDC_CRTC_MAX_DISPLAY * 4);
	ret = fr ? rdc_frame_wait(dev) : RDC_E_NOMEM;
	if (!ret)
		ret = rdc_frame_grab(dev, fr,
				     (size_t)RDC_CRTC_MAX_DISPLAY *
					     RDC_CRTC_MAX_DISPLAY,
				     &w, &h);
	if (!ret && cursor)
		ret = cursor_over(dev, &im, &cx, &cy);
	rdc_close(dev);
	if (ret) {
		fprintf(stderr, "frame_check: %s: %s\n", uri,
			rdc_strerror(ret));
		return 2;
	}
	if (rect) {
		uint64_t bad = 0;

		if ((uint64_t)rx + rw > w || (uint64_t)ry + rh > h) {
			printf("%u,%u %ux%u is not inside the %ux%u frame\n",
			       rx, ry, rw, rh, w, h);
			return 1;
		}
		for (uint32_t y = ry; y < ry + rh; y++)
			for (uint32_t x = rx; x < rx + rw; x++)
				if ((fr[(size_t)y * w + x] & 0xffffff) != rgb &&
				    !bad++)
					printf("%u,%u is %06x, not %06x\n", x,
					       y,
					       fr[(size_t)y * w + x] & 0xffffff,
					       rgb);
		printf("%llu of %u pixels differ\n", (unsigned long long)bad,
		       rw * rh);
		return bad ? 1 : 0;
	}
	if (cursor) {
		if (cx == INT32_MIN)
			printf("cursor off\n");
		else
			printf("cursor at %d,%d\n", cx, cy);
		if (want_at && (cx != at_x || cy != at_y)) {
			printf("the cursor is not at %d,%d\n", at_x, at_y);
			return 1;
		}
	}
	if (w != im.w || h != im.h) {
		printf("sizes differ: screenshot %ux%u, chip %ux%u\n", im.w,
		       im.h, w, h);
		return 1;
	}
	for (size_t i = 0; i < (size_t)w * h; i++) {
		if ((fr[i] & 0xffffff) != im.px[i]) {
			if (first == SIZE_MAX)
				first = i;
			diffs++;
		}
	}
	if (!diffs) {
		printf("same %ux%u\n", w, h);
		return 0;
	}
	printf("differ at %zu,%zu: screenshot %06x, chip %06x "
	       "(%llu pixels differ)\n",
	       first % w, first / w, im.px[first], fr[first] & 0xffffff,
	       (unsigned long long)diffs);
	return 1;
}
