// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The ARGB8888 hardware cursor (CURSOR_CTRL): a random premultiplied
 * image of 32x32 and 64x64 over a random screen at positions inside,
 * partly off every edge and corner and wholly off, against a composite
 * written here from docs/hardware.md's formula (a plain division, not the
 * chip's shifts); the gamma applied under the cursor and not to it; the
 * format and base latched at vblank while the rows are read live; rows
 * that leave VRAM; and the bus time of each line's cursor fetch against
 * the documented formula, worked out here from the bus model's words.
 * The 2 bpp cursor next to it: its frame as before and no fetch time.
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

#define VRAM_SIZE (1u << 20)
#define SCR_W	  80u
#define SCR_H	  72u
#define FRAME_CAP (SCR_W * SCR_H)
#define CUR_BASE  0x40040u /* not burst aligned: a 64-pixel row is 3 bursts */
#define CUR2_BASE 0x60000u /* the 2 bpp image */

struct fx {
	struct hw_fx sim;
	uint32_t seed;
};

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	f->seed = 0x2545f491u;
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fx *f = *state;

	hw_fx_fini(&f->sim);
	free(f);
	return 0;
}

static uint32_t rnd(struct fx *f)
{
	f->seed ^= f->seed << 13;
	f->seed ^= f->seed >> 17;
	f->seed ^= f->seed << 5;
	return f->seed;
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

static uint32_t get32(const uint8_t *p)
{
	return p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	       (uint32_t)p[3] << 24;
}

/* SCR_W x SCR_H XRGB8888 at VRAM 0, 10 core cycles a pixel. */
static void start_mode(struct rdc_hw *hw)
{
	uint32_t ctl = hw->control | RDC_CONTROL_SCANOUT_EN;

	rdc_hw_write(hw, RDC_REG_CONTROL, ctl & ~RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, SCR_W);
	rdc_hw_write(hw, RDC_REG_H_SYNC_START, SCR_W + 4);
	rdc_hw_write(hw, RDC_REG_H_SYNC_END, SCR_W + 8);
	rdc_hw_write(hw, RDC_REG_H_TOTAL, SCR_W + 16);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, SCR_H);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, SCR_H + 1);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, SCR_H + 2);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, SCR_H + 4);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, 10000);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, SCR_W * 4);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_ARGB8888);
	rdc_hw_write(hw, RDC_REG_CONTROL, ctl);
	/* the reset mode did not fit FRAME_CAP: error MODE, cleared */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

/* Run to the next vblank and return the frame completed there. */
static const uint32_t *grab(struct rdc_hw *hw)
{
	const uint32_t *p;
	uint32_t fw, fh;

	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	p = rdc_hw_frame(hw, &fw, &fh);
	assert_non_null(p);
	assert_int_equal(fw, SCR_W);
	assert_int_equal(fh, SCR_H);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	return p;
}

/* A frame scanned wholly with what is programmed now (two vblanks). */
static const uint32_t *grab_settled(struct rdc_hw *hw)
{
	grab(hw);
	return grab(hw);
}

/* Random screen: every byte random, the X byte included. */
static void random_screen(struct fx *f)
{
	for (uint32_t i = 0; i < SCR_W * SCR_H; i++)
		put32(f->sim.vram + 4 * i, rnd(f));
}

/*
 * A random premultiplied image: every alpha from 0 to 255 occurs, the
 * components at most the alpha, except every 61st pixel, whose
 * components are random (not premultiplied: the sum saturates).
 */
static void random_cursor(struct fx *f, uint32_t size)
{
	for (uint32_t i = 0; i < size * size; i++) {
		uint32_t a = i < 256 ? i : rnd(f) & 0xff, v = a << 24;

		if (i % 61 == 7)
			v |= rnd(f) & 0xffffff;
		else
			for (int k = 0; k < 3; k++)
				v |= (rnd(f) % (a + 1)) << (8 * k);
		put32(f->sim.vram + CUR_BASE + 4 * i, v);
	}
	/* shuffle so the alpha ramp is not all on the first rows */
	for (uint32_t i = size * size - 1; i > 0; i--) {
		uint32_t j = rnd(f) % (i + 1);
		uint32_t a = get32(f->sim.vram + CUR_BASE + 4 * i);

		put32(f->sim.vram + CUR_BASE + 4 * i,
		      get32(f->sim.vram + CUR_BASE + 4 * j));
		put32(f->sim.vram + CUR_BASE + 4 * j, a);
	}
}

/* docs/hardware.md: out = min(255, c + (d * (255 - a) + 127) / 255). */
static uint32_t over(uint32_t src, uint32_t dst)
{
	uint32_t a = src >> 24, out = 0;

	for (int k = 0; k < 24; k += 8) {
		uint32_t c = (src >> k) & 0xff, d = (dst >> k) & 0xff;
		uint32_t v = c + (d * (255 - a) + 127) / 255;

		out |= (v > 255 ? 255 : v) << k;
	}
	return out;
}

/*
 * The expected frame: the screen as XRGB (through `lut`, per component,
 * if not NULL), the cursor of `size` at (px, py) over it.
 */
static void check_frame(const struct fx *f, const uint32_t *p, uint32_t size,
			int32_t px, int32_t py, const uint32_t *lut)
{
	for (uint32_t y = 0; y < SCR_H; y++) {
		for (uint32_t x = 0; x < SCR_W; x++) {
			int32_t cx = (int32_t)x - px, cy = (int32_t)y - py;
			uint32_t want =
				get32(f->sim.vram + 4 * (y * SCR_W + x)) &
				0xffffff;

			if (lut)
				want = (lut[want >> 16] & 0xff0000) |
				       (lut[(want >> 8) & 0xff] & 0xff00) |
				       (lut[want & 0xff] & 0xff);
			if (cx >= 0 && cx < (int32_t)size && cy >= 0 &&
			    cy < (int32_t)size)
				want = over(get32(f->sim.vram + CUR_BASE +
						  4 * ((uint32_t)cy * size +
						       (uint32_t)cx)),
					    want);
			if (p[y * SCR_W + x] != want)
				fail_msg(
					"cursor %u at (%d, %d): pixel (%u, %u) "
					"is %06x, want %06x",
					size, px, py, x, y, p[y * SCR_W + x],
					want);
		}
	}
}

static uint32_t argb_ctrl(uint32_t size)
{
	return FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_ARGB8888) |
	       (size == 64 ? RDC_CURSOR_CTRL_SIZE64 : 0);
}

static void test_composite(void **state)
{
	static const int32_t pos[][2] = {
		{ 8, 5 },	   /* inside (the 64 one reaches x 71, y 68) */
		{ -20, 12 },	   /* left edge */
		{ SCR_W - 10, 3 }, /* right edge */
		{ 6, -25 },	   /* top edge */
		{ 2, SCR_H - 7 },  /* bottom edge */
		{ -30, -31 },	   /* top-left corner */
		{ SCR_W - 3, SCR_H - 2 }, /* bottom-right corner */
		{ SCR_W - 5, -9 },	  /* top-right corner */
		{ -1, SCR_H - 1 },	  /* bottom-left corner */
		{ -31, 0 },		  /* one column left (32) */
		{ -63, -63 },		  /* one pixel left (64) */
		{ -64, 10 },		  /* just off the left for 64 */
		{ -32, 10 },		  /* just off the left for 32 */
		{ SCR_W, 10 },		  /* just off the right */
		{ 10, -64 },		  /* just off the top for 64 */
		{ 10, SCR_H },		  /* just off the bottom */
		{ -32768, -32768 },
		{ 32767, 32767 },
		{ -32768, 4 },
	};
	static const uint32_t sizes[] = { 32, 64 };
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	random_screen(f);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	for (size_t s = 0; s < 2; s++) {
		random_cursor(f, sizes[s]);
		rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(sizes[s]));
		assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL),
				 argb_ctrl(sizes[s]));
		for (size_t i = 0; i < sizeof(pos) / sizeof(pos[0]); i++) {
			rdc_hw_write(hw, RDC_REG_CURSOR_POS,
				     RDC_XY(pos[i][0], pos[i][1]));
			check_frame(f, grab_settled(hw), sizes[s], pos[i][0],
				    pos[i][1], NULL);
		}
	}
	/* CURSOR_EN clear: the plain screen */
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(8, 5));
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	check_frame(f, grab_settled(hw), 64, -1000, -1000, NULL);
}

/* The gamma applies to the screen under the cursor, not to the cursor. */
static void test_over_gamma(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint32_t lut[RDC_CLUT_ENTRIES];

	random_screen(f);
	random_cursor(f, 32);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
	for (uint32_t i = 0; i < RDC_CLUT_ENTRIES; i++) {
		lut[i] = rnd(f) & 0xffffff;
		rdc_hw_write(hw, RDC_REG_CLUT_DATA, lut[i]);
	}
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(32));
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(-7, 50));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN |
			     RDC_CONTROL_GAMMA_EN);
	check_frame(f, grab_settled(hw), 32, -7, 50, lut);
}

/*
 * CURSOR_CTRL and CURSOR_BASE take effect at vblank; the image itself is
 * read at each line, as the framebuffer is, so a change to it shows in
 * the frame whose lines are fetched after it.
 */
static void test_latch(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t *p;

	random_screen(f);
	random_cursor(f, 64);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(4, 4));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(32));
	check_frame(f, grab_settled(hw), 32, 4, 4, NULL);

	/* in the middle of a frame: the size changes at its vblank */
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 20));
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(64));
	check_frame(f, grab(hw), 32, 4, 4, NULL);
	check_frame(f, grab(hw), 64, 4, 4, NULL);

	/* so does the base: a second image at CUR_BASE + 0x10000 */
	memcpy(f->sim.vram + CUR_BASE + 0x10000, f->sim.vram + CUR_BASE,
	       64 * 64 * 4);
	memset(f->sim.vram + CUR_BASE, 0, 64 * 64 * 4); /* wholly transparent */
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE + 0x10000);
	p = grab(hw); /* the old base's transparent image */
	check_frame(f, p, 64, -1000, -1000, NULL);
	p = grab(hw);
	memmove(f->sim.vram + CUR_BASE, f->sim.vram + CUR_BASE + 0x10000,
		64 * 64 * 4);
	check_frame(f, p, 64, 4, 4, NULL);

	/* the image: a row changed after its line's fetch shows a frame on */
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	grab_settled(hw);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 30));
	for (uint32_t i = 0; i < 64 * 64; i++) {
		uint8_t px[4];

		put32(px, 0xff000000u | i);
		assert_int_equal(rdc_hw_vram_write(hw, CUR_BASE + 4 * i, px, 4),
				 0);
	}
	p = grab(hw);
	for (uint32_t y = 0; y < SCR_H; y++) {
		uint32_t x = 10, cy = y - 4;

		if (y < 4 || y >= 68)
			continue;
		/* lines 0..30 fetched before the write, 31.. after */
		if (y > 30)
			assert_int_equal(p[y * SCR_W + x], cy * 64 + 6);
		else
			assert_int_not_equal(p[y * SCR_W + x], cy * 64 + 6);
	}
	check_frame(f, grab(hw), 64, 4, 4, NULL);
}

/* Rows that leave VRAM are neither fetched nor shown. */
static void test_rows_leaving_vram(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t base = VRAM_SIZE - 10 * 256 + 4; /* rows 0..8 fit */
	const uint32_t *p;

	random_screen(f);
	for (uint32_t i = 0; i < 9 * 64; i++)
		put32(f->sim.vram + base + 4 * i,
		      0xff000000u | ((i * 0x10101u) & 0xffffff));
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, base);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(64));
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(0, 0));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	p = grab_settled(hw);
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++) {
			uint32_t want =
				get32(f->sim.vram + 4 * (y * SCR_W + x)) &
				0xffffff;

			if (y < 9 && x < 64)
				want = ((y * 64 + x) * 0x10101u) & 0xffffff;
			assert_int_equal(p[y * SCR_W + x], want);
		}
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

/* ---- bus time ------------------------------------------------------------ */

/*
 * docs/hardware.md's read cost, from the model's words: the span split
 * into bursts at multiples of 128 bytes, a cycle for each 8-byte beat a
 * burst touches, 6 more for a burst in another 2048-byte DRAM row than
 * the open one, which it leaves open.
 */
static uint64_t read_cost(uint32_t *row, uint64_t a, uint64_t len)
{
	uint64_t cost = 0, end = a + len;

	while (a < end) {
		uint64_t be = (a / 128 + 1) * 128;

		if (be > end)
			be = end;
		cost += (be - 1) / 8 - a / 8 + 1;
		if (a / 2048 != *row) {
			cost += 6;
			*row = (uint32_t)(a / 2048);
		}
		a = be;
	}
	return cost;
}

/* The cursor of CURSOR_CTRL `ctrl` at (px, py) fetches a row on line n. */
static bool fetches_row(uint32_t ctrl, int32_t px, int32_t py, uint32_t n,
			uint32_t base, uint64_t *addr)
{
	uint32_t size = FIELD_GET(RDC_CURSOR_CTRL_SIZE64, ctrl) ? 64 : 32;
	int32_t dy = (int32_t)n - py;

	if (FIELD_GET(RDC_CURSOR_CTRL_FMT, ctrl) != RDC_CURSOR_FMT_ARGB8888 ||
	    dy < 0 || dy >= (int32_t)size || px + (int32_t)size <= 0 ||
	    px >= (int32_t)SCR_W)
		return false;
	*addr = base + (uint64_t)dy * size * 4;
	return *addr + size * 4 <= VRAM_SIZE;
}

/*
 * The fetch window of line n (n >= 1): the screen line from the row line
 * n - 1's window left open, then the cursor row on this line, if any.
 */
static uint64_t window(uint32_t ctrl, int32_t px, int32_t py, uint32_t n,
		       uint32_t base)
{
	uint32_t row;
	uint64_t a, cost;

	row = fetches_row(ctrl, px, py, n - 1, base, &a) ?
		      (uint32_t)((a + rdc_cursor_size(ctrl) * 4 - 1) / 2048) :
		      (uint32_t)(((n - 1) * SCR_W * 4 + SCR_W * 4 - 1) / 2048);
	cost = read_cost(&row, (uint64_t)n * SCR_W * 4, SCR_W * 4);
	if (fetches_row(ctrl, px, py, n, base, &a))
		cost += read_cost(&row, a, rdc_cursor_size(ctrl) * 4);
	return cost;
}

/*
 * The bus time of line n's window as the DP sees it: a DP read at the
 * line's start waits for the window to end, and PERF_STALL counts it.
 */
static uint64_t measured_window(struct rdc_hw *hw, uint32_t n)
{
	uint64_t before;

	rdc_port_idle_until(hw, rdc_port_next_line(hw, n));
	before = rdc_hw_read(hw, RDC_REG_PERF_STALL_LO);
	assert_non_null(rdc_port_span(hw, 0x80000, 8, RDC_BUS_READ));
	return rdc_hw_read(hw, RDC_REG_PERF_STALL_LO) - before;
}

static void test_fetch_cycles(void **state)
{
	static const int32_t pos[][2] = {
		{ 8, 5 },      { -20, 12 },	 { SCR_W - 10, 3 },
		{ 6, -25 },    { 2, SCR_H - 7 }, { -63, 40 },
		{ -64, 10 },   { SCR_W, 10 },	 { 10, -64 },
		{ 10, SCR_H }, { -31, -20 },
	};
	/*
	 * Not two in a row: the DP's read after a window opens a row of its
	 * own, which the next line's fetch would start from.
	 */
	static const uint32_t lines[] = { 1,  3,  5,  9,  12, 20, 33,
					  37, 40, 42, 50, 66, 68, 71 };
	const uint32_t ctrls[] = {
		argb_ctrl(32),
		argb_ctrl(64),
		FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_2BPP),
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	int cursor_lines = 0;

	random_screen(f);
	random_cursor(f, 64);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	for (size_t c = 0; c < 3; c++) {
		rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, ctrls[c]);
		for (size_t i = 0; i < sizeof(pos) / sizeof(pos[0]); i++) {
			rdc_hw_write(hw, RDC_REG_CURSOR_POS,
				     RDC_XY(pos[i][0], pos[i][1]));
			grab_settled(hw);
			for (size_t k = 0; k < sizeof(lines) / sizeof(*lines);
			     k++) {
				uint64_t a, want = window(ctrls[c], pos[i][0],
							  pos[i][1], lines[k],
							  CUR_BASE);

				assert_int_equal(measured_window(hw, lines[k]),
						 want);
				cursor_lines += fetches_row(ctrls[c], pos[i][0],
							    pos[i][1], lines[k],
							    CUR_BASE, &a);
			}
		}
	}
	assert_true(cursor_lines > 40);
	/* the 64-pixel row at CUR_BASE: 3 bursts of 8, 16 and 8 beats */
	{
		uint32_t row = 0;

		assert_int_equal(read_cost(&row, CUR_BASE, 256), 32 + 6);
	}

	/* cursor off: no fetch, whatever CURSOR_CTRL says */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(64));
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(0, 0));
	grab_settled(hw);
	assert_int_equal(measured_window(hw, 10), window(0, 0, 0, 10, 0));
}

/*
 * A framebuffer that leaves VRAM scans black and costs nothing; the
 * cursor over it is still fetched, over black, and its row alone takes
 * the bus.
 */
static void test_over_missing_lines(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const int32_t px = 10, py = 5;
	const uint32_t *p;

	random_cursor(f, 32);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0xfffff000u);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb_ctrl(32));
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(px, py));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	p = grab_settled(hw);
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++) {
			int32_t cx = (int32_t)x - px, cy = (int32_t)y - py;
			uint32_t want = 0;

			if (cx >= 0 && cx < 32 && cy >= 0 && cy < 32)
				want = over(get32(f->sim.vram + CUR_BASE +
						  4 * (uint32_t)(cy * 32 + cx)),
					    0);
			assert_int_equal(p[y * SCR_W + x], want);
		}
	/* lines 6..36 follow a line whose window was a cursor row */
	for (uint32_t n = 7; n < 37; n += 4) {
		uint32_t row = (CUR_BASE + (n - 1 - py) * 128 + 127) / 2048;
		uint64_t want = read_cost(&row, CUR_BASE + (n - py) * 128, 128);

		assert_int_equal(measured_window(hw, n), want);
	}
	/* no cursor on the line: no fetch at all */
	assert_int_equal(measured_window(hw, 40), 0);
}

/*
 * The 2 bpp cursor as it always was: latched at vblank, FG / BG / invert,
 * and its image costs no bus time (test_fetch_cycles).
 */
static void test_2bpp_unchanged(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t *p;

	random_screen(f);
	for (uint32_t i = 0; i < RDC_CURSOR_BYTES; i++)
		f->sim.vram[CUR2_BASE + i] = (uint8_t)rnd(f);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR2_BASE);
	rdc_hw_write(hw, RDC_REG_CURSOR_FG, 0x123456);
	rdc_hw_write(hw, RDC_REG_CURSOR_BG, 0xfedcba);
	/* SIZE64 means nothing to the 2 bpp cursor */
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL,
		     FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_2BPP) |
			     RDC_CURSOR_CTRL_SIZE64);
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(-9, SCR_H - 20));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	p = grab_settled(hw);
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++) {
			int32_t cx = (int32_t)x + 9;
			int32_t cy = (int32_t)y - (int32_t)(SCR_H - 20);
			uint32_t want =
				get32(f->sim.vram + 4 * (y * SCR_W + x)) &
				0xffffff;

			if (cx >= 0 && cx < 32 && cy >= 0 && cy < 32) {
				uint32_t b =
					f->sim.vram[CUR2_BASE + cy * 8 + cx / 4];

				switch ((b >> (6 - 2 * (cx % 4))) & 3) {
				case 1:
					want = 0x123456;
					break;
				case 2:
					want = 0xfedcba;
					break;
				case 3:
					want ^= 0xffffff;
					break;
				}
			}
			assert_int_equal(p[y * SCR_W + x], want);
		}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_composite, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_over_gamma, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_latch, setup, teardown),
		cmocka_unit_test_setup_teardown(test_rows_leaving_vram, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_fetch_cycles, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_over_missing_lines, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_2bpp_unchanged, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
