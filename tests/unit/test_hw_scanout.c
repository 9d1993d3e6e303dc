// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Scanout: every pixel format from known VRAM bytes to XRGB8888 pixels
 * (worked out here from the format definitions in rdc_regs.h), the CLUT in
 * immediate and latched modes, the hardware cursor (all four values,
 * partly off-screen, latched at vblank) and framebuffers that leave VRAM.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "hw.h"
#include "hw_fx.h"

#define VRAM_SIZE (2u << 20)
#define FRAME_CAP (64u * 64u)

static int setup(void **state)
{
	return hw_fx_setup(state, VRAM_SIZE, FRAME_CAP);
}

/* A w x h mode with blanking around it at 10 core cycles a pixel. */
static void start_mode(struct rdc_hw *hw, uint32_t w, uint32_t h, uint32_t base,
		       uint32_t stride, uint32_t fmt)
{
	uint32_t ctl = hw->control | RDC_CONTROL_SCANOUT_EN;

	rdc_hw_write(hw, RDC_REG_CONTROL, ctl & ~RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, w);
	rdc_hw_write(hw, RDC_REG_H_SYNC_START, w + 4);
	rdc_hw_write(hw, RDC_REG_H_SYNC_END, w + 8);
	rdc_hw_write(hw, RDC_REG_H_TOTAL, w + 16);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, h);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, h + 1);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, h + 2);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, h + 4);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, 10000);
	rdc_hw_write(hw, RDC_REG_FB_BASE, base);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, stride);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, fmt);
	rdc_hw_write(hw, RDC_REG_CONTROL, ctl);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

/* Run to the next vblank and return the frame completed there. */
static const uint32_t *grab(struct rdc_hw *hw, uint32_t w, uint32_t h)
{
	const uint32_t *p;
	uint32_t fw, fh;

	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	p = rdc_hw_frame(hw, &fw, &fh);
	assert_non_null(p);
	assert_int_equal(fw, w);
	assert_int_equal(fh, h);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	return p;
}

static uint32_t test_clut(uint32_t i)
{
	return (i << 16) | ((255 - i) << 8) | (i ^ 0x5a);
}

static void load_test_clut(struct rdc_hw *hw)
{
	uint32_t i;

	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
	for (i = 0; i < RDC_CLUT_ENTRIES; i++)
		rdc_hw_write(hw, RDC_REG_CLUT_DATA, test_clut(i));
}

static uint8_t pattern(uint32_t y, uint32_t k)
{
	return (uint8_t)(y * 37 + k * 11 + 5 + (k >> 3) * 101);
}

/* The pixel x of a line of bytes b in format fmt, from rdc_regs.h. */
static uint32_t expect_pixel(const uint8_t *b, uint32_t x, uint32_t fmt)
{
	uint32_t v, r, g, bl;

	switch (fmt) {
	case RDC_FMT_I1:
		return test_clut((b[x / 8] >> (7 - x % 8)) & 1);
	case RDC_FMT_I2:
		return test_clut((b[x / 4] >> (6 - 2 * (x % 4))) & 3);
	case RDC_FMT_I4:
		return test_clut(x % 2 ? b[x / 2] & 0xf : b[x / 2] >> 4);
	case RDC_FMT_I8:
		return test_clut(b[x]);
	case RDC_FMT_RGB565:
		v = b[2 * x] | (uint32_t)b[2 * x + 1] << 8;
		r = v >> 11;
		g = (v >> 5) & 63;
		bl = v & 31;
		/* widen by replicating the top bits into the new low bits */
		return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 |
		       (bl << 3 | bl >> 2);
	case RDC_FMT_RGB888:
		return (uint32_t)b[3 * x + 2] << 16 | b[3 * x + 1] << 8 |
		       b[3 * x];
	case RDC_FMT_XRGB8888:
		return (uint32_t)b[4 * x + 2] << 16 | b[4 * x + 1] << 8 |
		       b[4 * x];
	}
	return 0xdeadbeef;
}

static void test_all_formats(void **state)
{
	static const uint32_t widths[] = { 24, 13 }; /* whole bytes, or not */
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t h = 5, stride = 100, base = 0x1234;
	uint32_t fmt, i;

	load_test_clut(hw);
	for (i = 0; i < 2; i++) {
		for (fmt = 0; fmt < RDC_FMT_COUNT; fmt++) {
			const uint32_t w = widths[i];
			const uint32_t *p;
			uint32_t x, y;

			for (y = 0; y < h; y++)
				for (x = 0; x < stride; x++)
					f->vram[base + y * stride + x] =
						pattern(y + fmt + i, x);
			start_mode(hw, w, h, base, stride, fmt);
			p = grab(hw, w, h);
			for (y = 0; y < h; y++)
				for (x = 0; x < w; x++)
					assert_int_equal(
						p[y * w + x],
						expect_pixel(f->vram + base +
								     y * stride,
							     x, fmt));
		}
	}
}

/* Known values, so the expectations above are not only self-consistent. */
static void test_known_pixels(void **state)
{
	static const struct {
		uint32_t fmt;
		uint8_t bytes[8];
		uint32_t px[2];
	} k[] = {
		{ RDC_FMT_RGB565,
		  { 0x00, 0xf8, 0xe0, 0x07 },
		  { 0xff0000, 0x00ff00 } },
		{ RDC_FMT_RGB565,
		  { 0x1f, 0x00, 0x10, 0x84 },
		  { 0x0000ff, 0x848284 } },
		{ RDC_FMT_RGB888,
		  { 0x11, 0x22, 0x33, 0xff, 0x00, 0x80 },
		  { 0x332211, 0x8000ff } },
		{ RDC_FMT_XRGB8888,
		  { 0x44, 0x33, 0x22, 0x11, 1, 2, 3, 0xff },
		  { 0x223344, 0x030201 } },
		{ RDC_FMT_I1, { 0x40 }, { 0x000000, 0x0000aa } },
		{ RDC_FMT_I2, { 0x6c }, { 0x0000aa, 0x00aa00 } },
		{ RDC_FMT_I4, { 0xf8 }, { 0xffffff, 0x555555 } },
		{ RDC_FMT_I8, { 9, 12 }, { 0x5555ff, 0xff5555 } },
	};
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	size_t i;

	/* default palette: the VGA colours */
	for (i = 0; i < sizeof(k) / sizeof(k[0]); i++) {
		const uint32_t *p;

		memcpy(f->vram + 4096, k[i].bytes, sizeof(k[i].bytes));
		start_mode(hw, 2, 1, 4096, 8, k[i].fmt);
		p = grab(hw, 2, 1);
		assert_int_equal(p[0], k[i].px[0]);
		assert_int_equal(p[1], k[i].px[1]);
	}
}

static void test_clut_immediate_and_latched(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t *p;
	uint32_t i;

	memset(f->vram, 7, 64);
	start_mode(hw, 8, 2, 0, 8, RDC_FMT_I8);
	p = grab(hw, 8, 2);
	assert_int_equal(p[0], 0xaaaaaa); /* VGA light grey */
	/* immediate: in force for the next frame's fetches at once */
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 7);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x102030);
	p = grab(hw, 8, 2);
	for (i = 0; i < 16; i++)
		assert_int_equal(p[i], 0x102030);
	/* latched: not in the frame that sees the vblank after the write
	 * began before it ... */
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CLUT_LATCH);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 1) - 1); /* line 0 done */
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 7);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x405060);
	/* reads back the new value at once */
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 7);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x405060);
	p = grab(hw, 8, 2);
	for (i = 0; i < 16; i++)
		assert_int_equal(p[i], 0x102030);
	/* ... but in every line of the next */
	p = grab(hw, 8, 2);
	for (i = 0; i < 16; i++)
		assert_int_equal(p[i], 0x405060);
	/* the DP's CLUT writes honour the latch bit too */
	rdc_port_clut_write(hw, 7, 0x708090);
	assert_int_equal(hw->clut[7], 0x405060);
	p = grab(hw, 8, 2); /* the vblank latches it */
	p = grab(hw, 8, 2);
	assert_int_equal(p[0], 0x708090);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	rdc_port_clut_write(hw, 7 + RDC_CLUT_ENTRIES, 0xff0a0b0c);
	assert_int_equal(hw->clut[7], 0x0a0b0c);
}

/* ---- cursor ------------------------------------------------------------- */

#define CUR_BASE 0x10000u
#define SCR_W	 48u
#define SCR_H	 40u

static uint32_t cursor_value(uint32_t cx, uint32_t cy)
{
	return (cx / 3 + cy) % 4;
}

static void write_cursor(uint8_t *img, uint32_t flip)
{
	uint32_t x, y;

	memset(img, 0, RDC_CURSOR_BYTES);
	for (y = 0; y < RDC_CURSOR_SIZE; y++)
		for (x = 0; x < RDC_CURSOR_SIZE; x++)
			img[y * 8 + x / 4] |=
				(uint8_t)(((cursor_value(x, y) ^ flip) & 3)
					  << (6 - 2 * (x % 4)));
}

static uint32_t screen_px(uint32_t x, uint32_t y)
{
	return (x * 0x050301u + y * 0x010507u) & 0xffffff;
}

static void check_cursor_frame(const uint32_t *p, int32_t px, int32_t py,
			       uint32_t flip)
{
	const uint32_t fg = 0x00ff8000, bg = 0x000080ff;
	uint32_t x, y;

	for (y = 0; y < SCR_H; y++) {
		for (x = 0; x < SCR_W; x++) {
			int32_t cx = (int32_t)x - px, cy = (int32_t)y - py;
			uint32_t want = screen_px(x, y);

			if (cx >= 0 && cx < RDC_CURSOR_SIZE && cy >= 0 &&
			    cy < RDC_CURSOR_SIZE) {
				switch ((cursor_value(cx, cy) ^ flip) & 3) {
				case 1:
					want = fg;
					break;
				case 2:
					want = bg;
					break;
				case 3:
					want ^= 0xffffff;
					break;
				}
			}
			assert_int_equal(p[y * SCR_W + x], want);
		}
	}
}

static void test_cursor(void **state)
{
	static const int32_t pos[][2] = {
		{ 3, 2 },     { -5, -3 },	  { SCR_W - 10, SCR_H - 2 },
		{ -31, 20 },  { SCR_W - 1, -31 }, { -40, 0 },
		{ 0, SCR_H },
	};
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t *p;
	uint32_t x, y;
	size_t i;

	for (y = 0; y < SCR_H; y++)
		for (x = 0; x < SCR_W; x++) {
			uint32_t v = screen_px(x, y) | 0xab000000u;

			memcpy(f->vram + (y * SCR_W + x) * 4, &v, 4);
		}
	write_cursor(f->vram + CUR_BASE, 0);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CURSOR_FG, 0xff8000);
	rdc_hw_write(hw, RDC_REG_CURSOR_BG, 0x0080ff);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	start_mode(hw, SCR_W, SCR_H, 0, SCR_W * 4, RDC_FMT_XRGB8888);
	for (i = 0; i < sizeof(pos) / sizeof(pos[0]); i++) {
		rdc_hw_write(hw, RDC_REG_CURSOR_POS,
			     RDC_XY(pos[i][0], pos[i][1]));
		p = grab(hw, SCR_W, SCR_H);
		/* the position applies from the next frame's first line */
		p = grab(hw, SCR_W, SCR_H);
		check_cursor_frame(p, pos[i][0], pos[i][1], 0);
	}

	/* a new image in VRAM shows only after the next vblank latches it */
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(4, 4));
	grab(hw, SCR_W, SCR_H);
	write_cursor(f->vram + CUR_BASE, 1);
	p = grab(hw, SCR_W, SCR_H); /* scanned with the old image */
	check_cursor_frame(p, 4, 4, 0);
	p = grab(hw, SCR_W, SCR_H);
	check_cursor_frame(p, 4, 4, 1);

	/* cursor off: the plain screen */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	grab(hw, SCR_W, SCR_H);
	p = grab(hw, SCR_W, SCR_H);
	check_cursor_frame(p, -100, -100, 0);

	/* an image address out of VRAM: transparent, no stray reads */
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, VRAM_SIZE - 8);
	grab(hw, SCR_W, SCR_H);
	p = grab(hw, SCR_W, SCR_H);
	check_cursor_frame(p, -100, -100, 0);
}

/* ---- framebuffers out of VRAM -------------------------------------------- */

static void test_fb_leaving_vram_scans_black(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t w = 16, h = 6, stride = 64;
	const uint32_t *p;
	uint32_t x, y;

	memset(f->vram, 0xff, VRAM_SIZE);
	/* two lines fit, the third would end one byte past VRAM */
	start_mode(hw, w, h, VRAM_SIZE - 2 * stride - w * 4 + 1, stride,
		   RDC_FMT_XRGB8888);
	p = grab(hw, w, h);
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++)
			assert_int_equal(p[y * w + x], y < 2 ? 0xffffff : 0);
	/* a base past the end */
	start_mode(hw, w, h, 0xfffffff0u, stride, RDC_FMT_RGB888);
	p = grab(hw, w, h);
	for (x = 0; x < w * h; x++)
		assert_int_equal(p[x], 0);
	/* a stride that wraps 32 bits: line 0 only */
	start_mode(hw, w, h, 0, 0xfffffffcu, RDC_FMT_I8);
	p = grab(hw, w, h);
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++)
			assert_int_equal(p[y * w + x], y == 0 ? 0xeeeeee : 0);
	/* stride 0 repeats line 0 */
	memset(f->vram, 9, 64);
	start_mode(hw, w, h, 0, 0, RDC_FMT_I8);
	p = grab(hw, w, h);
	for (x = 0; x < w * h; x++)
		assert_int_equal(p[x], 0x5555ff);
}

/* The framebuffer registers are latched: a new base shows a frame later. */
static void test_fb_latched(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t *p;

	memset(f->vram, 1, 256);
	memset(f->vram + 0x8000, 2, 256);
	start_mode(hw, 8, 4, 0, 8, RDC_FMT_I8);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x8000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0x8000);
	p = grab(hw, 8, 4);
	assert_int_equal(p[0], 0x0000aa);
	assert_int_equal(p[31], 0x0000aa);
	p = grab(hw, 8, 4);
	assert_int_equal(p[0], 0x00aa00);
	assert_int_equal(p[31], 0x00aa00);
	/* the format too */
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_I4);
	p = grab(hw, 8, 4);
	assert_int_equal(p[0], 0x00aa00);
	p = grab(hw, 8, 4);
	/* 0x02 = pixels 0 and 2 */
	assert_int_equal(p[0], 0x000000);
	assert_int_equal(p[1], 0x00aa00);
}

/*
 * Running many frames in one go: the frame on show at the end is complete
 * and right, also across a mode change latched on the way.
 */
static void test_run_far_ahead(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t *p;
	uint32_t w, h, i;

	for (i = 0; i < 64 * 64; i++)
		f->vram[i] = (uint8_t)(i % 251);
	start_mode(hw, 16, 8, 0, 16, RDC_FMT_I8);
	load_test_clut(hw);
	/* 100 frames ahead, stopping mid-frame */
	rdc_hw_run_until(hw, hw->now + 100 * (16 + 16) * (8 + 4) * 10 + 500);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), 100);
	p = rdc_hw_frame(hw, &w, &h);
	assert_non_null(p);
	assert_int_equal(w, 16);
	assert_int_equal(h, 8);
	for (i = 0; i < 16 * 8; i++)
		assert_int_equal(p[i], test_clut(i % 251));
	/* a new, smaller mode latched at the next vblank, then far ahead */
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, 8);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, 6);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, 8);
	rdc_hw_run_until(hw, hw->now + 50 * (16 + 16) * (8 + 4) * 10);
	p = rdc_hw_frame(hw, &w, &h);
	assert_non_null(p);
	assert_int_equal(w, 8);
	assert_int_equal(h, 6);
	for (i = 0; i < 8 * 6; i++)
		assert_int_equal(p[i], test_clut(i % 251));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_all_formats, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_known_pixels, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_clut_immediate_and_latched,
						setup, hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_cursor, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fb_leaving_vram_scans_black,
						setup, hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fb_latched, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_run_far_ahead, setup,
						hw_fx_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
