// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The CRTC's raster list (RASTER_BASE, RASTER_CTRL, RASTER_STATUS): a
 * CLUT split that holds in every frame, eager and on demand; one at
 * columns of a line, from the line as fetched; a split
 * screen by FB_BASE and FB_STRIDE that the vblank latch undoes; the
 * cursor moved and recoloured down the frame; the list latched at vblank
 * and turned off; bad lists (unknown op, a register off the whitelist,
 * leaving VRAM, running past RASTER_CTRL.LEN) stopped with error RASTER
 * while the beam runs on; and the bus time of each line's window, the
 * entries it fetches and the line's read, and of a WAIT's column,
 * against docs/hardware.md's formula worked out here from the bus
 * model's words.
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
#define LINE	  SCR_W /* I8: a byte a pixel */
#define FRAME_CAP (SCR_W * SCR_H)
/* the list straddles a DRAM row: its third entry opens row 200 */
#define RL_BASE (200u * 2048 - 16)
#define FB2	0x30000u /* the second screen of the split */
#define SKY	0x2050c0u
#define GROUND	0xe07020u

static int setup(void **state)
{
	return hw_fx_setup(state, VRAM_SIZE, FRAME_CAP);
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* SCR_W x SCR_H I8 at VRAM 0, 10 core cycles a pixel. */
static void start_mode(struct rdc_hw *hw)
{
	rdc_hw_write(hw, RDC_REG_CONTROL, 0);
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
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, LINE);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_I8);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
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
	return p;
}

/* Entry k of a list at `base`: op, argument, value. */
static void entry(struct hw_fx *f, uint32_t base, uint32_t k, uint32_t op,
		  uint32_t arg, uint32_t val)
{
	put32(f->vram + base + 8 * k,
	      FIELD_PREP(RDC_RL_OP, op) | FIELD_PREP(RDC_RL_ARG, arg));
	put32(f->vram + base + 8 * k + 4, val);
}

static uint32_t wait_at(uint32_t y, uint32_t x)
{
	return FIELD_PREP(RDC_RL_Y, y) | FIELD_PREP(RDC_RL_X, x);
}

static void enable(struct rdc_hw *hw, uint32_t base, uint32_t len)
{
	rdc_hw_write(hw, RDC_REG_RASTER_BASE, base);
	rdc_hw_write(hw, RDC_REG_RASTER_CTRL,
		     RDC_RASTER_CTRL_EN | FIELD_PREP(RDC_RASTER_CTRL_LEN, len));
}

/* Index 1 everywhere but a column of index 2 at x = 7. */
static void fill_screen(struct hw_fx *f, uint32_t base)
{
	memset(f->vram + base, 1, SCR_W * SCR_H);
	for (uint32_t y = 0; y < SCR_H; y++)
		f->vram[base + y * LINE + 7] = 2;
}

/* The sky/ground list: entry 1 SKY at the top, GROUND from line `split`. */
static void split_list(struct hw_fx *f, uint32_t split)
{
	entry(f, RL_BASE, 0, RDC_RL_CLUT, 1, SKY);
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(split, 0));
	entry(f, RL_BASE, 2, RDC_RL_CLUT, 1, GROUND);
	entry(f, RL_BASE, 3, RDC_RL_END, 0, 0);
}

/* Ground from column `at` of line `split` on, sky before. */
static void assert_split_at(const uint32_t *p, uint32_t split, uint32_t at,
			    uint32_t col2)
{
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++)
			assert_int_equal(p[y * SCR_W + x],
					 x == 7 ? col2 :
					 y < split || (y == split && x < at) ?
						  SKY :
						  GROUND);
}

static void assert_split(const uint32_t *p, uint32_t split, uint32_t col2)
{
	assert_split_at(p, split, 0, col2);
}

/*
 * The split in frames 0, 1 and 100 after it is turned on, and every
 * frame between, with nothing written after the start: scanout eager,
 * on demand with nobody looking (each frame converted when grabbed), and
 * on demand with a look at only some frames.
 */
static void test_split_every_frame(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t col2 = 0x00aa00; /* VGA green, reset CLUT entry 2 */

	for (int mode = 0; mode < 3; mode++) {
		rdc_hw_reset(hw);
		rdc_hw_set_on_demand(hw, mode != 0);
		fill_screen(f, 0);
		split_list(f, 40);
		start_mode(hw);
		enable(hw, RL_BASE, 0);
		grab(hw); /* the frame in which the list was turned on */
		for (int k = 0; k <= 100; k++) {
			if (mode == 2 && k % 7 != 0 && k != 1 && k != 100) {
				rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
				continue;
			}
			assert_split(grab(hw), 40, col2);
		}
		/* the CLUT_DATA read-back holds the host's value */
		rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 1);
		assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x0000aa);
		assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE),
				 RDC_ERR_NONE);
	}
	rdc_hw_set_on_demand(hw, false);
}

/*
 * Two WAITs for columns of line 40 (30 and 50), a CLUT write after each:
 * the line in three parts, in every frame, eager and on demand.  A DP
 * write to line 40 after its start shows in the next frame only, the
 * columns after a split included (they come from the line as fetched).
 */
static void test_column_split(void **state)
{
	const uint32_t col2 = 0x00aa00, mid = 0x111111;
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	for (int mode = 0; mode < 3; mode++) {
		const uint32_t *p;

		rdc_hw_reset(hw);
		rdc_hw_set_on_demand(hw, mode != 0);
		fill_screen(f, 0);
		entry(f, RL_BASE, 0, RDC_RL_CLUT, 1, SKY);
		entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, 30));
		entry(f, RL_BASE, 2, RDC_RL_CLUT, 1, GROUND);
		entry(f, RL_BASE, 3, RDC_RL_WAIT, 0, wait_at(40, 50));
		entry(f, RL_BASE, 4, RDC_RL_CLUT, 1, mid);
		entry(f, RL_BASE, 5, RDC_RL_WAIT, 0, wait_at(41, 0));
		entry(f, RL_BASE, 6, RDC_RL_CLUT, 1, GROUND);
		entry(f, RL_BASE, 7, RDC_RL_END, 0, 0);
		start_mode(hw);
		enable(hw, RL_BASE, 0);
		grab(hw);
		for (int k = 0; k <= 20; k++) {
			if (mode == 2 && k % 7 != 0) {
				rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
				continue;
			}
			p = grab(hw);
			for (uint32_t y = 0; y < SCR_H; y++)
				for (uint32_t x = 0; x < SCR_W; x++)
					assert_int_equal(p[y * SCR_W + x],
							 x == 7 ? col2 :
							 y < 40 ? SKY :
							 y > 40 ? GROUND :
							 x < 30 ? SKY :
							 x < 50 ? GROUND :
								  mid);
		}
		/* index 2 at column 60 of line 40, after the line's fetch */
		rdc_port_idle_until(hw, rdc_port_next_line(hw, 40) + 10);
		memset(rdc_port_span(hw, 40 * LINE + 60, 1, RDC_BUS_WRITE), 2,
		       1);
		if (mode) { /* on demand, nobody looking: dropped */
			rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
		} else {
			p = grab(hw);
			assert_int_equal(p[40 * SCR_W + 60], mid);
			assert_int_equal(p[40 * SCR_W + 7], col2);
		}
		assert_int_equal(grab(hw)[40 * SCR_W + 60], col2);
		assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE),
				 RDC_ERR_NONE);
	}
	rdc_hw_set_on_demand(hw, false);
}

/*
 * The list latched at vblank: turned on or off mid-frame, the frame in
 * progress keeps what it had; a WAIT at a column is met at that column,
 * one past the line's end at the next line; a WAIT at a position passed
 * already is met at once.
 */
static void test_latch_and_off(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t col2 = 0x00aa00;
	const uint32_t *p;

	rdc_hw_reset(hw);
	fill_screen(f, 0);
	split_list(f, 40);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 1);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, SKY);
	grab(hw);
	rdc_port_idle_until(hw, rdc_port_next_line(hw, 20));
	/* the DP's REG_WRITE reaches the list's registers as the host does */
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_RASTER_BASE, RL_BASE),
			 0);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_RASTER_CTRL,
					    RDC_RASTER_CTRL_EN),
			 0);
	assert_split(grab(hw), SCR_H, col2); /* all sky: not latched yet */
	assert_split(grab(hw), 40, col2);
	/* ended at line 40 after 4 entries */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RASTER_STATUS),
			 FIELD_PREP(RDC_RASTER_STATUS_COUNT, 4));

	/* column 5 of line 40: the split from there on */
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, 5));
	grab(hw);
	assert_split_at(grab(hw), 40, 5, col2);
	/* H_TOTAL (96) and past: the next line's start */
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, SCR_W + 16));
	grab(hw);
	assert_split(grab(hw), 41, col2);
	/* the last column of the line: in hblank, the line shows none */
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, SCR_W + 15));
	grab(hw);
	assert_split(grab(hw), 41, col2);

	/* a WAIT for a position passed: met at once, at column 8 of 40 */
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, 8));
	entry(f, RL_BASE, 3, RDC_RL_WAIT, 0, wait_at(3, 0));
	entry(f, RL_BASE, 4, RDC_RL_CLUT, 2, 0x123456);
	entry(f, RL_BASE, 5, RDC_RL_WAIT, 0, wait_at(SCR_H + 4, 0));
	p = grab(hw);
	assert_int_equal(p[40 * SCR_W + 6], SKY);
	assert_int_equal(p[40 * SCR_W + 7], col2);
	assert_int_equal(p[40 * SCR_W + 8], GROUND);
	assert_int_equal(p[41 * SCR_W + 7], 0x123456);
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(40, 7));
	p = grab(hw);
	assert_int_equal(p[40 * SCR_W + 6], SKY);
	assert_int_equal(p[40 * SCR_W + 7], 0x123456);
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(41, 0));
	/* never met (y >= V_TOTAL): done for the frame, no error */
	assert_false(rdc_hw_read(hw, RDC_REG_RASTER_STATUS) &
		     RDC_RASTER_STATUS_RUN);
	assert_int_equal(FIELD_GET(RDC_RASTER_STATUS_COUNT,
				   rdc_hw_read(hw, RDC_REG_RASTER_STATUS)),
			 6);
	entry(f, RL_BASE, 3, RDC_RL_END, 0, 0);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 2); /* the list's write undone */
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, col2);

	/* off mid-frame: this frame keeps the list, the next has none */
	rdc_port_idle_until(hw, rdc_port_next_line(hw, 10));
	rdc_hw_write(hw, RDC_REG_RASTER_CTRL, 0);
	assert_split(grab(hw), 41, col2);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 1);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, SKY);
	assert_split(grab(hw), SCR_H, col2);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RASTER_STATUS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

/*
 * Split screen: the top 30 lines from VRAM 0, then FB2 with its own
 * stride and a scroll of 3 lines and 5 pixels; the cursor moved and
 * recoloured down the frame.  The registers read as the host wrote them,
 * and the next frame starts from them again.
 */
static void test_split_screen(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t stride2 = 128, scroll = FB2 + 3 * stride2 + 5;
	const uint32_t *p;

	rdc_hw_reset(hw);
	for (uint32_t i = 0; i < SCR_W * SCR_H; i++)
		f->vram[i] = (uint8_t)(i * 7 + 1);
	for (uint32_t i = 0; i < 128 * 128; i++)
		f->vram[FB2 + i] = (uint8_t)(i * 13 + 5);
	memset(f->vram + 0x20000, 0x55, RDC_CURSOR_BYTES); /* all FG */
	entry(f, RL_BASE, 0, RDC_RL_REG, RDC_REG_CURSOR_POS, RDC_XY(2, 0));
	entry(f, RL_BASE, 1, RDC_RL_REG, RDC_REG_CURSOR_FG, 0x00ff00);
	entry(f, RL_BASE, 2, RDC_RL_WAIT, 0, wait_at(30, 0));
	entry(f, RL_BASE, 3, RDC_RL_REG, RDC_REG_FB_BASE,
	      scroll - 30 * stride2);
	entry(f, RL_BASE, 4, RDC_RL_REG, RDC_REG_FB_STRIDE, stride2);
	entry(f, RL_BASE, 5, RDC_RL_REG, RDC_REG_CURSOR_POS, RDC_XY(40, 30));
	entry(f, RL_BASE, 6, RDC_RL_REG, RDC_REG_CURSOR_FG, 0xff00ff);
	entry(f, RL_BASE, 7, RDC_RL_END, 0, 0);
	start_mode(hw);
	rdc_hw_write(hw, RDC_REG_CURSOR_BASE, 0x20000);
	rdc_hw_write(hw, RDC_REG_CURSOR_FG, 0x00ff00);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_CURSOR_EN);
	enable(hw, RL_BASE, 0);
	grab(hw);
	for (int k = 0; k < 3; k++) {
		p = grab(hw);
		for (uint32_t y = 0; y < SCR_H; y++)
			for (uint32_t x = 0; x < SCR_W; x++) {
				uint32_t want;

				if (y < 30 && x >= 2 && x < 34)
					want = 0x00ff00;
				else if (y >= 30 && y < 62 && x >= 40 && x < 72)
					want = 0xff00ff;
				else if (y < 30)
					want = hw->clut[f->vram[y * LINE + x]];
				else
					want = hw->clut[f->vram[scroll +
								(y -
								 30) * stride2 +
								x]];
				assert_int_equal(p[y * SCR_W + x], want);
			}
	}
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_STRIDE), LINE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

/* The list at `base` stops with error RASTER at `info`; frames go on. */
static void assert_stops(struct hw_fx *f, uint32_t base, uint32_t len,
			 uint32_t info)
{
	struct rdc_hw *hw = &f->hw;
	uint32_t frames;

	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	enable(hw, base, len);
	grab(hw);
	grab(hw);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_RASTER);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), info);
	assert_true(rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RASTER_STATUS) &
				 ~RDC_RASTER_STATUS_COUNT,
			 RDC_RASTER_STATUS_ERROR);
	assert_int_equal(
		rdc_hw_read(hw, RDC_REG_RASTER_CTRL) & RDC_RASTER_CTRL_EN, 0);
	/* stopped for good: no second error, the beam runs on */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	frames = rdc_hw_read(hw, RDC_REG_FRAME_COUNT);
	grab(hw);
	grab(hw);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), frames + 2);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	/* RASTER_STATUS is read only; a write of RASTER_CTRL clears ERROR */
	rdc_hw_write(hw, RDC_REG_RASTER_STATUS, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_REG);
	assert_true(rdc_hw_read(hw, RDC_REG_RASTER_STATUS) &
		    RDC_RASTER_STATUS_ERROR);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_write(hw, RDC_REG_RASTER_CTRL, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RASTER_STATUS) &
				 RDC_RASTER_STATUS_ERROR,
			 0);
}

static void test_bad_lists(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t far = VRAM_SIZE - 16;

	rdc_hw_reset(hw);
	fill_screen(f, 0);
	start_mode(hw);

	/* an unknown op after a good entry */
	entry(f, RL_BASE, 0, RDC_RL_CLUT, 1, SKY);
	entry(f, RL_BASE, 1, RDC_RL_OP_COUNT, 0, 0);
	assert_stops(f, RL_BASE, 0, RL_BASE + 8);
	/* off the whitelist: CONTROL, the timing, the list's own registers */
	entry(f, RL_BASE, 1, RDC_RL_REG, RDC_REG_CONTROL, 0);
	assert_stops(f, RL_BASE, 0, RL_BASE + 8);
	entry(f, RL_BASE, 1, RDC_RL_REG, RDC_REG_V_TOTAL, 2);
	assert_stops(f, RL_BASE, 0, RL_BASE + 8);
	entry(f, RL_BASE, 1, RDC_RL_REG, RDC_REG_RASTER_BASE, 0);
	assert_stops(f, RL_BASE, 0, RL_BASE + 8);
	/* the list runs off the end of VRAM */
	entry(f, far, 0, RDC_RL_CLUT, 1, SKY);
	entry(f, far, 1, RDC_RL_WAIT, 0, wait_at(9, 0));
	assert_stops(f, far, 0, VRAM_SIZE);
	/* a base past VRAM */
	assert_stops(f, VRAM_SIZE + 64, 0, VRAM_SIZE + 64);
	/* runaway: CLUT writes with no END, LEN 5 */
	for (uint32_t k = 0; k < 64; k++)
		entry(f, RL_BASE, k, RDC_RL_CLUT, 200, k);
	assert_stops(f, RL_BASE, 5, RL_BASE + 5 * 8);
	/* LEN 0 is RDC_RASTER_MAX_ENTRIES: a WAIT-less loop of the whole */
	for (uint32_t k = 0; k < RDC_RASTER_MAX_ENTRIES; k++)
		entry(f, 0x80000, k, RDC_RL_WAIT, 0, wait_at(0, 0));
	assert_stops(f, 0x80000, 0, 0x80000 + RDC_RASTER_MAX_ENTRIES * 8);
	/* a good list then runs again */
	split_list(f, 40);
	enable(hw, RL_BASE, 0);
	grab(hw);
	assert_split(grab(hw), 40, 0x00aa00);
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

/*
 * window(n) = sum of read(entry, 8) over the entries line n fetches,
 * then read(line n): from the row line n - 1's read left open (no line
 * measured here follows a measured one, whose DP read opens a row).
 */
static uint64_t window(uint32_t n, uint32_t first, uint32_t count)
{
	uint32_t prev = n ? n - 1 : SCR_H - 1;
	uint32_t row = (prev * LINE + LINE - 1) / 2048;
	uint64_t cost = 0;

	for (uint32_t k = first; k < first + count; k++)
		cost += read_cost(&row, RL_BASE + 8 * k, 8);
	return cost + read_cost(&row, (uint64_t)n * LINE, LINE);
}

static void test_fetch_cycles(void **state)
{
	/* line, first entry fetched on it, entries fetched */
	static const uint32_t fetches[][3] = {
		{ 0, 0, 2 },   /* CLUT, WAIT 5 */
		{ 5, 2, 3 },   /* CLUT, CURSOR_FG, WAIT 9 (row 200 opens) */
		{ 9, 5, 2 },   /* FB_STRIDE, WAIT (20, 3) */
		{ 12, 7, 0 },  /* nothing */
		{ 20, 7, 0 },  /* nothing at the start: column 3's (below) */
		{ 40, 11, 0 }, /* nothing */
	};
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint64_t without[6];

	rdc_hw_reset(hw);
	fill_screen(f, 0);
	entry(f, RL_BASE, 0, RDC_RL_CLUT, 1, SKY);
	entry(f, RL_BASE, 1, RDC_RL_WAIT, 0, wait_at(5, 0));
	entry(f, RL_BASE, 2, RDC_RL_CLUT, 3, SKY);
	entry(f, RL_BASE, 3, RDC_RL_REG, RDC_REG_CURSOR_FG, 0x777777);
	entry(f, RL_BASE, 4, RDC_RL_WAIT, 0, wait_at(9, 0));
	entry(f, RL_BASE, 5, RDC_RL_REG, RDC_REG_FB_STRIDE, LINE);
	entry(f, RL_BASE, 6, RDC_RL_WAIT, 0, wait_at(20, 3));
	entry(f, RL_BASE, 7, RDC_RL_REG, RDC_REG_FB_STRIDE, LINE);
	entry(f, RL_BASE, 8, RDC_RL_CLUT, 1, GROUND);
	entry(f, RL_BASE, 9, RDC_RL_CLUT, 4, GROUND);
	entry(f, RL_BASE, 10, RDC_RL_END, 0, 0);
	start_mode(hw);

	/* the list off: the line's read alone */
	grab(hw);
	for (size_t i = 0; i < 6; i++) {
		without[i] = measured_window(hw, fetches[i][0]);
		assert_int_equal(without[i], window(fetches[i][0], 0, 0));
	}
	enable(hw, RL_BASE, 0);
	grab(hw);
	for (int frame = 0; frame < 3; frame++) {
		for (size_t i = 0; i < 6; i++)
			assert_int_equal(measured_window(hw, fetches[i][0]),
					 window(fetches[i][0], fetches[i][1],
						fetches[i][2]));
		grab(hw);
		assert_int_equal(
			FIELD_GET(RDC_RASTER_STATUS_COUNT,
				  rdc_hw_read(hw, RDC_REG_RASTER_STATUS)),
			11);
	}
	/*
	 * Column 3 of line 20 fetches FB_STRIDE, 2 x CLUT and END in a
	 * window of its own at the first core cycle BEAM reads 3 (30 cycles
	 * into the line): a beat each and a miss into row 200, from the row
	 * line 20's read left open.  A DP read there waits for all of it; one
	 * a cycle before, which would still run into it, waits a cycle more.
	 */
	for (int before = 0; before < 2; before++) {
		uint64_t t3 = rdc_port_next_line(hw, 20) + 30, stall;

		rdc_port_idle_until(hw, t3 - (uint64_t)before);
		stall = rdc_hw_read(hw, RDC_REG_PERF_STALL_LO);
		assert_non_null(rdc_port_span(hw, 0x80000, 8, RDC_BUS_READ));
		stall = rdc_hw_read(hw, RDC_REG_PERF_STALL_LO) - stall;
		assert_int_equal(stall, 4 + 6 + (uint64_t)before);
		assert_int_equal(rdc_hw_now(hw), t3 + 4 + 6 + 1 + 6);
		grab(hw);
	}

	/*
	 * the entries cost a beat each and a miss into their row, and the
	 * line's read a miss back
	 */
	assert_int_equal(window(5, 2, 3) - without[1], 3 + 6 + 6);
	/* line 0's read pays a miss from row 2 either way */
	assert_int_equal(window(0, 0, 2) - without[0], 2 + 6);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_split_every_frame, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_column_split, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_latch_and_off, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_split_screen, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_bad_lists, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fetch_cycles, setup,
						hw_fx_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
