// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The light pen (LPEN_POS, LPEN_CTRL, LPEN_LATCH, STATUS.LPEN,
 * RDC_IRQ_LPEN): the strobe at the exact cycle the beam reaches the
 * pen's column, at two pixel clocks, in a short run and in a long one
 * processed late; never over a dark pixel, a pixel at the threshold, with
 * the pen off, off the screen or the panel dark; lit exactly where the
 * frame the CRTC converted is lit, in every format, with gamma and the
 * cursor, eager and on demand; and a program on sim: that finds where
 * the pen points by flashing halves of the screen, as light-pen software
 * did.
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
#include "rdc.h"

#define VRAM_SIZE (1u << 20)
#define SCR_W	  80u
#define SCR_H	  72u
#define FRAME_CAP (SCR_W * SCR_H)
#define CUR_BASE  0x80000u
#define WHITE	  0xffffffu

static int setup(void **state)
{
	return hw_fx_setup(state, VRAM_SIZE, FRAME_CAP);
}

/* SCR_W x SCR_H in `fmt` at VRAM 0, pixel clock `khz`. */
static void start_mode(struct rdc_hw *hw, uint32_t fmt, uint32_t khz)
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
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, khz);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, rdc_format_row_bytes(fmt, SCR_W));
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, fmt);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	/* the reset mode did not fit FRAME_CAP: error MODE, cleared */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

static void pen_at(struct rdc_hw *hw, uint32_t x, uint32_t y, uint32_t ctrl)
{
	rdc_hw_write(hw, RDC_REG_LPEN_POS,
		     FIELD_PREP(RDC_LPEN_X, x) | FIELD_PREP(RDC_LPEN_Y, y));
	rdc_hw_write(hw, RDC_REG_LPEN_CTRL, ctrl);
}

static bool strobed(struct rdc_hw *hw)
{
	return rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_LPEN;
}

/* I8 screen of CLUT entry 1 (white) with a black pixel (entry 0) at (x, y). */
static void white_but(struct hw_fx *f, uint32_t x, uint32_t y)
{
	rdc_hw_write(&f->hw, RDC_REG_CLUT_INDEX, 0);
	rdc_hw_write(&f->hw, RDC_REG_CLUT_DATA, 0);
	rdc_hw_write(&f->hw, RDC_REG_CLUT_DATA, WHITE);
	memset(f->vram, 1, SCR_W * SCR_H);
	if (x < SCR_W && y < SCR_H)
		f->vram[y * SCR_W + x] = 0;
}

struct pin_log {
	uint64_t irq_rise; /* time of the first IRQ pin rise, or 0 */
};

static void on_trace(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		     uint32_t b)
{
	struct pin_log *l = ctx;

	if (event == RDC_TRACE_PINS && (b & RDC_PIN_IRQ) && (a & RDC_PIN_IRQ) &&
	    !l->irq_rise)
		l->irq_rise = time;
}

/*
 * The strobe comes at line start + ceil(x * 100 MHz / pixel clock), the
 * first cycle BEAM reads the pen's column: not a cycle before.  10 MHz is
 * 10 cycles a pixel; 30 MHz 3 1/3, so the ceiling matters.
 */
static void test_strobe_cycle(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	static const uint32_t khz[] = { 10000, 30000 };
	static const uint32_t xs[] = { 0, 1, 37, 38, SCR_W - 1 };

	for (size_t k = 0; k < 2; k++) {
		start_mode(hw, RDC_FMT_I8, khz[k]);
		white_but(f, SCR_W, SCR_H);
		rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_LPEN);
		for (size_t i = 0; i < sizeof(xs) / sizeof(xs[0]); i++) {
			uint32_t x = xs[i], y = 20 + (uint32_t)i, bx, by;
			uint64_t pix = (uint64_t)khz[k] * 1000, start, t;

			pen_at(hw, x, y, RDC_LPEN_CTRL_EN);
			rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
			start = rdc_port_next_line(hw, y);
			t = start + (x * 100000000ull + pix - 1) / pix;
			rdc_hw_run_until(hw, t - 1);
			assert_false(strobed(hw));
			assert_false(rdc_hw_read(hw, RDC_REG_STATUS) &
				     RDC_STATUS_LPEN);
			assert_false(rdc_hw_pins(hw) & RDC_PIN_IRQ);
			rdc_hw_beam(hw, &bx, &by);
			if (x) { /* else t - 1 ends the line before */
				assert_int_equal(by, y);
				assert_int_equal(bx + 1, x);
			}
			rdc_hw_run_until(hw, t);
			assert_true(strobed(hw));
			assert_true(rdc_hw_read(hw, RDC_REG_STATUS) &
				    RDC_STATUS_LPEN);
			assert_true(rdc_hw_pins(hw) & RDC_PIN_IRQ);
			rdc_hw_beam(hw, &bx, &by);
			assert_int_equal(bx, x);
			assert_int_equal(by, y);
			assert_int_equal(rdc_hw_read(hw, RDC_REG_LPEN_LATCH),
					 FIELD_PREP(RDC_BEAM_X, x) |
						 FIELD_PREP(RDC_BEAM_Y, y));
		}
	}
}

/*
 * A long run processes the strobe late, in a catch-up: the IRQ pin's
 * edge still carries its cycle, and the strobe comes once a frame.
 */
static void test_strobe_late(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	struct pin_log log = { 0 };
	uint64_t start, frame;

	start_mode(hw, RDC_FMT_I8, 10000);
	white_but(f, SCR_W, SCR_H);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_LPEN);
	pen_at(hw, 50, 60, RDC_LPEN_CTRL_EN);
	rdc_hw_set_trace(hw, on_trace, &log);
	start = rdc_port_next_line(hw, 60);
	frame = (uint64_t)(SCR_W + 16) * (SCR_H + 4) * 10;
	rdc_hw_run_until(hw, start + 3 * frame);
	assert_int_equal(log.irq_rise, start + 500);
	/* cleared after the third frame's strobe: the fourth's comes */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN);
	log.irq_rise = 0;
	rdc_hw_run_until(hw, start + 4 * frame);
	assert_int_equal(log.irq_rise, start + 3 * frame + 500);
	rdc_hw_set_trace(hw, NULL, NULL);
}

/* Nothing strobes for five frames from now. */
static void assert_quiet(struct rdc_hw *hw)
{
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_hw_now(hw) + 5 * 96 * 76 * 10);
	assert_false(strobed(hw));
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_LPEN);
}

/*
 * The pen on a dark pixel never strobes, though its neighbours are lit;
 * nor at the threshold, nor with the pen off, off the screen, or the
 * panel dark.
 */
static void test_dark_never(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	start_mode(hw, RDC_FMT_I8, 10000);
	white_but(f, 33, 44);
	pen_at(hw, 33, 44, RDC_LPEN_CTRL_EN);
	assert_quiet(hw);
	/* its neighbours strobe */
	pen_at(hw, 34, 44, RDC_LPEN_CTRL_EN);
	rdc_hw_run_until(hw, rdc_hw_now(hw) + 96 * 76 * 10);
	assert_true(strobed(hw));
	pen_at(hw, 33, 43, RDC_LPEN_CTRL_EN);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_hw_now(hw) + 96 * 76 * 10);
	assert_true(strobed(hw));
	/* the pen lifted over white */
	pen_at(hw, 10, 10, 0);
	assert_quiet(hw);
	/* off the active area, in the blanking */
	pen_at(hw, SCR_W, 10, RDC_LPEN_CTRL_EN);
	assert_quiet(hw);
	pen_at(hw, 10, SCR_H, RDC_LPEN_CTRL_EN);
	assert_quiet(hw);
	/* luma 100 at threshold 100 is dark; at 99 lit */
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 1);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x646464);
	pen_at(hw, 10, 10,
	       RDC_LPEN_CTRL_EN | FIELD_PREP(RDC_LPEN_CTRL_THRESHOLD, 100));
	assert_quiet(hw);
	pen_at(hw, 10, 10,
	       RDC_LPEN_CTRL_EN | FIELD_PREP(RDC_LPEN_CTRL_THRESHOLD, 99));
	rdc_hw_run_until(hw, rdc_hw_now(hw) + 96 * 76 * 10);
	assert_true(strobed(hw));
	/* BL_EN low: the panel shows black */
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N);
	pen_at(hw, 10, 10, RDC_LPEN_CTRL_EN);
	assert_quiet(hw);
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	/* the registers read back; bits outside the fields drop */
	pen_at(hw, 5, 6, 0xffffffffu);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_LPEN_CTRL),
			 RDC_LPEN_CTRL_MASK);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_LPEN_POS), 6u << 16 | 5);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

static uint32_t luma(uint32_t v)
{
	return (77 * ((v >> 16) & 0xff) + 150 * ((v >> 8) & 0xff) +
		29 * (v & 0xff) + 128) >>
	       8;
}

/*
 * Random pictures in every format (gamma on the direct ones, the 2 bpp
 * and the ARGB8888 cursor over them): the pen strobes exactly where the
 * frame the CRTC converted has a pixel brighter than the threshold.
 */
static void as_scanned(struct hw_fx *f, bool on_demand)
{
	struct rdc_hw *hw = &f->hw;
	uint32_t seed = 12345, hits = 0, misses = 0;

	for (uint32_t fmt = 0; fmt < RDC_FMT_COUNT; fmt++) {
		for (uint32_t cur = 0; cur < 3; cur++) {
			const uint32_t *fr;
			uint32_t fw, fh;

			start_mode(hw, fmt, 10000);
			rdc_hw_set_on_demand(hw, on_demand);
			for (uint32_t i = 0; i < 0x90000; i++) {
				seed = seed * 1103515245u + 12345u;
				f->vram[i] = (uint8_t)(seed >> 16);
			}
			rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
			for (uint32_t i = 0; i < 256; i++) {
				seed = seed * 1103515245u + 12345u;
				rdc_hw_write(hw, RDC_REG_CLUT_DATA, seed >> 8);
			}
			rdc_hw_write(hw, RDC_REG_CURSOR_BASE, CUR_BASE);
			rdc_hw_write(hw, RDC_REG_CURSOR_POS, 30u << 16 | 20);
			rdc_hw_write(hw, RDC_REG_CURSOR_CTRL,
				     cur == 2 ? RDC_CURSOR_FMT_ARGB8888 : 0);
			rdc_hw_write(hw, RDC_REG_CONTROL,
				     RDC_CONTROL_RESET_VALUE |
					     (fmt > RDC_FMT_RGB565 ?
						      RDC_CONTROL_GAMMA_EN :
						      0) |
					     (cur ? RDC_CONTROL_CURSOR_EN : 0));
			rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
			for (uint32_t k = 0; k < 24; k++) {
				uint32_t x, y;

				seed = seed * 1103515245u + 12345u;
				/* half of them on the cursor */
				x = k & 1 ? 20 + (seed >> 8) % 32 :
					    (seed >> 8) % SCR_W;
				y = k & 1 ? 30 + (seed >> 20) % 32 :
					    (seed >> 20) % SCR_H;
				pen_at(hw, x, y,
				       RDC_LPEN_CTRL_EN |
					       FIELD_PREP(
						       RDC_LPEN_CTRL_THRESHOLD,
						       127));
				rdc_hw_write(hw, RDC_REG_IRQ_STATUS,
					     RDC_IRQ_ALL);
				rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
				fr = rdc_hw_frame(hw, &fw, &fh);
				assert_non_null(fr);
				assert_int_equal(strobed(hw),
						 luma(fr[y * SCR_W + x]) > 127);
				if (strobed(hw))
					hits++;
				else
					misses++;
			}
		}
	}
	/* both outcomes were seen often */
	assert_true(hits > 100 && misses > 100);
}

static void test_as_scanned(void **state)
{
	as_scanned(*state, false);
}

static void test_as_scanned_on_demand(void **state)
{
	as_scanned(*state, true);
}

/* ---- finding the pen by flashing, on sim: ------------------------------- */

/*
 * Light everything in [x0, x1) x [y0, y1) white and the rest black,
 * then watch a whole frame: did the pen see light?
 */
static bool flash(rdc_dev *dev, rdc_batch *b, uint32_t w, uint32_t h,
		  uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1)
{
	uint32_t st;

	assert_int_equal(rdc_batch_fg(b, 0), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 0, 0, w, h), 0);
	assert_int_equal(rdc_batch_fg(b, WHITE), 0);
	assert_int_equal(
		rdc_batch_fill_rect(b, (int)x0, (int)y0, x1 - x0, y1 - y0), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_LPEN),
			 0);
	/* from here to the second vblank: one frame whole */
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_IRQ_STATUS, &st), 0);
	return st & RDC_IRQ_LPEN;
}

/*
 * A picture, the pen held at a place the program does not know, then a
 * binary search: light the left half of what is left, and keep the half
 * the pen saw; then the same for the rows.  9 + 8 flashes find the pixel
 * on 320x200.
 */
static void test_find_by_flashing(void **state)
{
	static const struct {
		uint32_t x, y;
	} hidden[] = { { 211, 137 }, { 0, 0 }, { 319, 199 }, { 160, 1 } };
	rdc_dev *dev;
	rdc_batch *b = rdc_batch_new();
	uint32_t w, h, latch;

	(void)state;
	assert_non_null(b);
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_preset_size(RDC_PRESET_320x200_70, &w, &h), 0);
	for (size_t i = 0; i < sizeof(hidden) / sizeof(hidden[0]); i++) {
		uint32_t x0 = 0, x1 = w, y0 = 0, y1 = h, flashes = 0;

		/* something on the screen first: a circle and some text */
		assert_int_equal(rdc_batch_fg(b, 0x3080ff), 0);
		assert_int_equal(rdc_batch_fill_circle(b, 150, 100, 60), 0);
		assert_int_equal(rdc_batch_submit(dev, b), 0);
		assert_int_equal(
			rdc_reg_write(dev, RDC_REG_LPEN_POS,
				      FIELD_PREP(RDC_LPEN_X, hidden[i].x) |
					      FIELD_PREP(RDC_LPEN_Y,
							 hidden[i].y)),
			0);
		assert_int_equal(rdc_reg_write(dev, RDC_REG_LPEN_CTRL,
					       RDC_LPEN_CTRL_EN),
				 0);
		while (x1 - x0 > 1) {
			uint32_t mid = x0 + (x1 - x0) / 2;

			if (flash(dev, b, w, h, x0, 0, mid, h))
				x1 = mid;
			else
				x0 = mid;
			flashes++;
		}
		while (y1 - y0 > 1) {
			uint32_t mid = y0 + (y1 - y0) / 2;

			if (flash(dev, b, w, h, 0, y0, w, mid))
				y1 = mid;
			else
				y0 = mid;
			flashes++;
		}
		assert_int_equal(x0, hidden[i].x);
		assert_int_equal(y0, hidden[i].y);
		assert_true(flashes <= 17);
		/* the one pixel lit: the pen sees it, and the latch agrees */
		assert_true(flash(dev, b, w, h, x0, y0, x0 + 1, y0 + 1));
		assert_int_equal(rdc_reg_read(dev, RDC_REG_LPEN_LATCH, &latch),
				 0);
		assert_int_equal(latch, FIELD_PREP(RDC_BEAM_X, x0) |
						FIELD_PREP(RDC_BEAM_Y, y0));
		/* and every other one lit, not */
		assert_false(flash(dev, b, w, h, 0, 0, w, y0));
	}
	rdc_batch_free(b);
	rdc_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_strobe_cycle, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_strobe_late, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_dark_never, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_as_scanned, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_as_scanned_on_demand,
						setup, hw_fx_teardown),
		cmocka_unit_test(test_find_by_flashing),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
