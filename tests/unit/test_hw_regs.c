// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * RDC-1 register file: reset values, access semantics (R, RW, W, W1C),
 * bad offsets, the IRQ pin, the pins register and RESET_N, the CLUT port,
 * counters and MODE_PRESET, CURSOR_CTRL and CONTROL.GAMMA_EN (1.1).
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
#define FRAME_CAP (640u * 480u) /* the reset mode fits */

struct fx {
	struct hw_fx sim;
	int dp_resets;
};

static void fake_reset(void *dp)
{
	((struct fx *)dp)->dp_resets++;
}

static uint64_t fake_run(void *dp, uint64_t until)
{
	(void)dp;
	(void)until;
	return RDC_NEVER;
}

static const struct rdc_dp_ops fake_ops = { fake_reset, fake_run };

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	rdc_hw_set_dp(&f->sim.hw, &fake_ops, f);
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

static void test_reset_values(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	struct rdc_timing t;

	assert_int_equal(rdc_hw_read(hw, RDC_REG_ID), RDC_ID_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_VERSION), RDC_VERSION_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_VRAM_SIZE), VRAM_SIZE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CORE_KHZ),
			 RDC_DEFAULT_CORE_HZ / 1000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_ENABLE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);

	/* 640x480@60, VESA DMT: 25.175 MHz, 800 x 525 */
	assert_int_equal(rdc_preset_timing(RDC_PRESET_640x480_60, &t), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_DISPLAY), 640);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_SYNC_START), 656);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_SYNC_END), 752);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_TOTAL), 800);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_DISPLAY), 480);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_SYNC_START), 490);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_SYNC_END), 492);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_TOTAL), 525);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PIXCLK_KHZ), 25175);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CRTC_FLAGS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_STRIDE), 640 * 4);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_FORMAT), RDC_FMT_XRGB8888);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_MODE_PRESET),
			 RDC_PRESET_640x480_60);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_LOWWATER),
			 RDC_FIFO_LOWWATER_RESET);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA_COUNT), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_CMDS), 0);
	/* the mode is in force at once: the beam is on line 0 */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_BEAM), 0);
	assert_true(hw->crtc.running);
	/* STATUS: queues empty, in active video, no IRQ */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_STATUS),
			 RDC_STATUS_FIFO_EMPTY | RDC_STATUS_RING_EMPTY);
	/* reads have no side effect on the error state */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

/* The documented default palette: VGA 16, 6x6x6 cube, grey ramp. */
static void test_default_palette(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x000000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x0000aa);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 6);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xaa5500);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 15);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xffffff);
	/* cube entry 16 + 36 r + 6 g + b, levels 0x33 apart */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x000000);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 16 + 36 * 5 + 6 * 2 + 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xff6633);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 231);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xffffff);
	/* grey ramp from 8 in steps of 10 */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x080808);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 255);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xeeeeee);
	/* index wrapped after 255 */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_INDEX), 0);
}

static void test_clut_port(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 254);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0xff123456); /* X byte dropped */
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x00abcdef);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x00010203); /* wraps to 0 */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_INDEX), 1);
	assert_int_equal(hw->clut[254], 0x123456);
	assert_int_equal(hw->clut[255], 0xabcdef);
	assert_int_equal(hw->clut[0], 0x010203);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 254);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x123456);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0xabcdef);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_DATA), 0x010203);
	/* an index beyond 255 wraps */
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 256 + 7);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CLUT_INDEX), 7);
}

static void expect_reg_error(struct rdc_hw *hw, uint32_t off)
{
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_REG);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), off);
	assert_true(rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ERROR);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
}

static void test_bad_offsets(void **state)
{
	static const uint32_t bad[] = {
		0x002,		/* unaligned */
		0x011,		/* unaligned CONTROL */
		0x02c,		/* hole after PINS */
		0x15c,		/* hole after LPEN_LATCH */
		0x188,		/* hole after CLUT_DATA */
		0x228,		/* hole after RDATA_COUNT */
		0x334,		/* after PERF_CULLED */
		RDC_REG_WINDOW, /* outside the window */
		0xfffffffc,	/* far outside */
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	size_t i;

	for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(rdc_hw_read(hw, bad[i]), 0);
		expect_reg_error(hw, bad[i]);
		rdc_hw_write(hw, bad[i], 0xffffffff);
		expect_reg_error(hw, bad[i]);
	}
	/* the chip survived and still works */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ID), RDC_ID_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE);
}

static void test_read_only(void **state)
{
	static const uint32_t ro[] = {
		RDC_REG_ID,	     RDC_REG_VERSION,
		RDC_REG_VRAM_SIZE,   RDC_REG_CORE_KHZ,
		RDC_REG_STATUS,	     RDC_REG_ERR_INFO,
		RDC_REG_PINS,	     RDC_REG_BEAM,
		RDC_REG_FRAME_COUNT, RDC_REG_FIFO_FREE,
		RDC_REG_FENCE,	     RDC_REG_RDATA,
		RDC_REG_RDATA_COUNT, RDC_REG_TIME_LO,
		RDC_REG_TIME_HI,     RDC_REG_PERF_BUSY_LO,
		RDC_REG_PERF_CMDS,   RDC_REG_PERF_LAST_OPCODE,
		RDC_REG_PERF_CULLED,
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	size_t i;

	for (i = 0; i < sizeof(ro) / sizeof(ro[0]); i++) {
		uint32_t before = rdc_hw_read(hw, ro[i]);

		rdc_hw_write(hw, ro[i], before ^ 0x5a5a5a5a);
		expect_reg_error(hw, ro[i]);
		if (ro[i] != RDC_REG_RDATA && ro[i] != RDC_REG_TIME_LO &&
		    ro[i] != RDC_REG_TIME_HI && ro[i] != RDC_REG_STATUS &&
		    ro[i] != RDC_REG_PINS)
			assert_int_equal(rdc_hw_read(hw, ro[i]), before);
	}
	/* ERR_CODE is read-only too: the write is an error of its own */
	rdc_hw_write(hw, RDC_REG_ERR_CODE, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_REG);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), RDC_REG_ERR_CODE);
}

static void test_write_only_read_zero(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_hw_write(hw, RDC_REG_FIFO_DATA, 0x12345678);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_DATA), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_CTRL), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE),
			 RDC_FIFO_DEPTH - 1);
}

static void test_irq_w1c_and_pin(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_port_irq(hw, RDC_IRQ_FENCE | RDC_IRQ_LINE | 0xffffff00u);
	/* only defined bits latch */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS),
			 RDC_IRQ_FENCE | RDC_IRQ_LINE);
	/* not enabled: pin low */
	assert_false(rdc_hw_read(hw, RDC_REG_PINS) & RDC_PIN_IRQ);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_IRQ);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, 0xffffffff);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_ENABLE), RDC_IRQ_ALL);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_IRQ);
	/* writing 0 clears nothing; writing 1 clears only that bit */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS),
			 RDC_IRQ_FENCE | RDC_IRQ_LINE);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_FENCE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_LINE);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_LINE);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_IRQ);
}

static void test_errors_and_fence(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_port_fence(hw, 0xfeed);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FENCE), 0xfeed);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_FENCE);
	rdc_port_error(hw, RDC_ERR_OPCODE, 0x7f000000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_OPCODE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), 0x7f000000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS),
			 RDC_IRQ_FENCE | RDC_IRQ_ERROR);
	/* clearing FENCE leaves the error alone */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_FENCE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_OPCODE);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ERROR);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), 0);
}

static void test_rw_registers(void **state)
{
	static const uint32_t rw[] = {
		RDC_REG_H_TOTAL,      RDC_REG_H_DISPLAY,   RDC_REG_H_SYNC_START,
		RDC_REG_H_SYNC_END,   RDC_REG_V_TOTAL,	   RDC_REG_V_DISPLAY,
		RDC_REG_V_SYNC_START, RDC_REG_V_SYNC_END,  RDC_REG_PIXCLK_KHZ,
		RDC_REG_CRTC_FLAGS,   RDC_REG_FB_BASE,	   RDC_REG_FB_STRIDE,
		RDC_REG_LINE_COMPARE, RDC_REG_CURSOR_BASE, RDC_REG_CURSOR_POS,
		RDC_REG_RING_BASE,    RDC_REG_RING_SIZE,   RDC_REG_RING_HEAD,
		RDC_REG_RING_TAIL,
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	size_t i;

	for (i = 0; i < sizeof(rw) / sizeof(rw[0]); i++) {
		uint32_t v = 0x100 + (uint32_t)i * 4;

		rdc_hw_write(hw, rw[i], v);
		assert_int_equal(rdc_hw_read(hw, rw[i]), v);
	}
	rdc_hw_write(hw, RDC_REG_CURSOR_FG, 0xff112233);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_FG), 0x112233);
	rdc_hw_write(hw, RDC_REG_CURSOR_BG, 0x80445566);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_BG), 0x445566);
	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 10);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_LOWWATER), 10);
	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 100000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_LOWWATER),
			 RDC_FIFO_DEPTH);
	/* CONTROL keeps only its RW bits; RESUME / SOFT_RESET never read */
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_CURSOR_EN |
			     RDC_CONTROL_RESUME | BIT(20));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_DP_EN | RDC_CONTROL_CURSOR_EN);
	assert_int_equal(hw->dp_resume, 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

static void test_mode_preset(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_RGB888);
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_1024x768_60);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_MODE_PRESET),
			 RDC_PRESET_1024x768_60);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_DISPLAY), 1024);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_SYNC_START), 1048);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_SYNC_END), 1184);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_TOTAL), 1344);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_DISPLAY), 768);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_SYNC_START), 771);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_SYNC_END), 777);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_V_TOTAL), 806);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PIXCLK_KHZ), 65000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_STRIDE), 1024 * 3);

	/* 320 pixels at 1 bpp are 40 bytes: already a multiple of 4 */
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_I1);
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_320x200_70);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_STRIDE), 40);
	/* 800 x 3 bytes = 2400 */
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_RGB888);
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_800x600_60);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_STRIDE), 2400);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CRTC_FLAGS),
			 RDC_CRTC_HSYNC_POS | RDC_CRTC_VSYNC_POS);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);

	/* unknown preset: refused, shadows untouched */
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_COUNT);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_DISPLAY), 800);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_MODE_PRESET),
			 RDC_PRESET_800x600_60);
}

static void test_time_and_counters(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t t = (5ull << 32) | 0xfffffff0u;

	/* no scanout, so running that far is cheap; the idle DP lets the
	 * run loop land exactly on t */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_run_until(hw, t);
	assert_true(hw->now == t);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_TIME_LO), 0xfffffff0u);
	/* time moves on past a carry between the halves ... */
	rdc_hw_run_until(hw, t + 0x20);
	/* ... but HI still reads the snapshot taken with LO */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_TIME_HI), 5);
	/* a HI read without its LO is live */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_TIME_HI), 6);

	hw->perf.stall = (7ull << 32) | 9;
	hw->perf.busy = 3;
	hw->perf.pixels = (1ull << 32) | 2;
	hw->perf.cmds = 11;
	hw->perf.last_cycles = 12;
	hw->perf.last_opcode = 0x24;
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_STALL_LO), 9);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_STALL_HI), 7);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_BUSY_LO), 3);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_BUSY_HI), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_PIXELS_LO), 2);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_PIXELS_HI), 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_CMDS), 11);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_LAST_CYCLES), 12);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_LAST_OPCODE), 0x24);
	rdc_hw_write(hw, RDC_REG_PERF_CTRL, 0); /* bit 0 clear: nothing */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_CMDS), 11);
	rdc_hw_write(hw, RDC_REG_PERF_CTRL, RDC_PERF_CTRL_CLEAR);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_STALL_LO), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_STALL_HI), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_CMDS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_PERF_LAST_OPCODE), 0);
	/* time is not a counter: it keeps running */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_TIME_LO), 0x10);
}

static void test_soft_reset(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	int resets = f->dp_resets;

	rdc_hw_run_until(hw, 1000);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x1000);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_ALL);
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, 1);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 3);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x123456);
	rdc_port_error(hw, RDC_ERR_RANGE, 1);
	hw->vram[5] = 0x77;
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	assert_int_equal(f->dp_resets, resets + 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_ENABLE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);
	assert_int_equal(hw->clut[3], 0x00aaaa);
	/* time kept, VRAM kept, a new frame starts now */
	assert_int_equal(hw->now, 1000);
	assert_int_equal(hw->vram[5], 0x77);
	assert_int_equal(hw->crtc.frame_start, 1000);
}

static void test_pins_and_reset_n(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	int resets = f->dp_resets;
	uint32_t p;

	p = rdc_hw_read(hw, RDC_REG_PINS);
	assert_int_equal(p, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N | RDC_PIN_TE | RDC_PIN_IRQ);
	/* outputs cannot be driven from outside */
	assert_int_equal(rdc_hw_pins(hw), RDC_PIN_RESET_N);
	assert_int_equal(f->dp_resets, resets);

	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x2000);
	rdc_hw_set_pins(hw, RDC_PIN_BL_EN); /* RESET_N low */
	assert_int_equal(f->dp_resets, resets + 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0);
	/* held in reset: writes ignored, nothing runs */
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x3000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_ALL);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_ENABLE), 0);
	rdc_hw_run_until(hw, 10 * RDC_DEFAULT_CORE_HZ / 60);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), 0);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_TE);
	assert_int_equal(rdc_hw_pins(hw), RDC_PIN_BL_EN);
	/* release: a fresh reset, the first frame starts now */
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N);
	assert_int_equal(f->dp_resets, resets + 2);
	assert_int_equal(hw->crtc.frame_start, hw->now);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x3000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0x3000);
}

/* TE is high from the start of vblank to line 0, mirrored in STATUS. */
static void test_te_pin(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t vb = rdc_port_next_vblank(hw);

	assert_int_not_equal(vb, RDC_NEVER);
	rdc_hw_run_until(hw, vb - 1);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_TE);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	rdc_hw_run_until(hw, vb);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_TE);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 0) - 1);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_TE);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 0));
	assert_false(rdc_hw_pins(hw) & RDC_PIN_TE);
	/* scanout off: TE low, no vblank */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	assert_int_equal(rdc_port_next_vblank(hw), RDC_NEVER);
	rdc_hw_run_until(hw, hw->now + RDC_DEFAULT_CORE_HZ / 10);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_TE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), 1);
}

static void test_port_reg_write(void **state)
{
	static const uint32_t refused[] = {
		RDC_REG_CONTROL,
		RDC_REG_FIFO_DATA,
		RDC_REG_FIFO_LOWWATER,
		RDC_REG_RING_BASE,
		RDC_REG_RING_SIZE,
		RDC_REG_RING_HEAD,
		RDC_REG_RING_TAIL,
		RDC_REG_PERF_CTRL,
		RDC_REG_ID,
		RDC_REG_BEAM,
		RDC_REG_FRAME_COUNT,
		RDC_REG_STATUS,
		0x002,
		RDC_REG_WINDOW,
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	size_t i;

	for (i = 0; i < sizeof(refused) / sizeof(refused[0]); i++)
		assert_int_equal(rdc_port_reg_write(hw, refused[i], 1), -1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);

	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_FB_BASE, 0x4000), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0x4000);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_H_TOTAL, 900), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_H_TOTAL), 900);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_LINE_COMPARE, 7), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_LINE_COMPARE), 7);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_CURSOR_POS, 9), 0);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_CLUT_INDEX, 9), 0);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_CLUT_DATA, 0xabc), 0);
	assert_int_equal(hw->clut[9], 0xabc);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_IRQ_ENABLE, 4), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_ENABLE), 4);
	rdc_port_irq(hw, RDC_IRQ_FENCE);
	assert_int_equal(
		rdc_port_reg_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_FENCE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	/* refusals are the DP's to report: the chip logs nothing */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

/*
 * The 1.1 registers: CURSOR_CTRL keeps its two fields and refuses an
 * unknown format whole, from the host and from REG_WRITE; GAMMA_EN is a
 * CONTROL bit like the others; a soft reset clears both.
 */
static void test_cursor_ctrl_and_gamma_bit(void **state)
{
	const uint32_t argb64 =
		FIELD_PREP(RDC_CURSOR_CTRL_FMT, RDC_CURSOR_FMT_ARGB8888) |
		RDC_CURSOR_CTRL_SIZE64;
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;

	assert_true(rdc_hw_read(hw, RDC_REG_VERSION) >= 0x00010001); /* 1.1+ */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), 0);
	/* bits outside the fields drop */
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb64 | 0xfffffe00u | BIT(4));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), argb64);
	assert_int_equal(rdc_cursor_size(argb64), 64);
	assert_int_equal(rdc_cursor_size(argb64 & ~RDC_CURSOR_CTRL_SIZE64), 32);
	/* SIZE64 does not make the 2 bpp cursor larger */
	assert_int_equal(rdc_cursor_size(RDC_CURSOR_CTRL_SIZE64), 32);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	/* formats 2 and 3 do not exist: refused, the old value stays */
	for (uint32_t fmt = RDC_CURSOR_FMT_COUNT; fmt < 4; fmt++) {
		rdc_hw_write(hw, RDC_REG_CURSOR_CTRL,
			     FIELD_PREP(RDC_CURSOR_CTRL_FMT, fmt));
		assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), argb64);
		expect_reg_error(hw, RDC_REG_CURSOR_CTRL);
	}
	/* the command stream reaches it as it reaches the other cursor regs */
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_CURSOR_CTRL, 0), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), 0);
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_CURSOR_CTRL, 3), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), 0);
	expect_reg_error(hw, RDC_REG_CURSOR_CTRL);

	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_GAMMA_EN);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE | RDC_CONTROL_GAMMA_EN);
	rdc_hw_write(hw, RDC_REG_CURSOR_CTRL, argb64);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
			 RDC_CONTROL_RESET_VALUE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_CURSOR_CTRL), 0);
	assert_int_equal(hw->crtc.cur_cursor_ctrl, 0);
	assert_int_equal(hw->crtc.cur_gamma, 0);
}

struct trace_log {
	int n;
	uint64_t t[16];
	unsigned int ev[16];
	uint32_t a[16], b[16];
};

static void on_trace(void *ctx, uint64_t t, unsigned int ev, uint32_t a,
		     uint32_t b)
{
	struct trace_log *l = ctx;

	/* the signal events have their own test (test_hw_trace.c) */
	if (ev == RDC_TRACE_PINS || ev == RDC_TRACE_LINE ||
	    ev == RDC_TRACE_DP || ev == RDC_TRACE_FIFO)
		return;
	if (l->n < 16) {
		l->t[l->n] = t;
		l->ev[l->n] = ev;
		l->a[l->n] = a;
		l->b[l->n] = b;
	}
	l->n++;
}

static void test_trace(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	struct trace_log log = { 0 };
	uint64_t vb = rdc_port_next_vblank(hw);

	rdc_hw_set_trace(hw, on_trace, &log);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0x40);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FB_BASE), 0x40);
	assert_int_equal(rdc_hw_vram_write(hw, 8, "xy", 2), 0);
	rdc_hw_write(hw, RDC_REG_ID, 1);
	rdc_hw_run_until(hw, vb + 5);
	assert_int_equal(log.n, 6);
	assert_int_equal(log.ev[0], RDC_TRACE_REG_WRITE);
	assert_int_equal(log.a[0], RDC_REG_FB_BASE);
	assert_int_equal(log.b[0], 0x40);
	assert_int_equal(log.ev[1], RDC_TRACE_REG_READ);
	assert_int_equal(log.b[1], 0x40);
	assert_int_equal(log.ev[2], RDC_TRACE_VRAM_WRITE);
	assert_int_equal(log.a[2], 8);
	assert_int_equal(log.b[2], 2);
	assert_int_equal(log.ev[3], RDC_TRACE_REG_WRITE);
	assert_int_equal(log.ev[4], RDC_TRACE_ERROR);
	assert_int_equal(log.a[4], RDC_ERR_REG);
	assert_int_equal(log.b[4], RDC_REG_ID);
	assert_int_equal(log.ev[5], RDC_TRACE_VBLANK);
	assert_int_equal(log.t[5], vb);
	assert_int_equal(log.a[5], 0);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	assert_int_equal(log.ev[7], RDC_TRACE_RESET);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_reset_values, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_default_palette, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_clut_port, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_bad_offsets, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_read_only, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_write_only_read_zero,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_irq_w1c_and_pin, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_errors_and_fence, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_rw_registers, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_mode_preset, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_time_and_counters, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_soft_reset, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_pins_and_reset_n, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_te_pin, setup, teardown),
		cmocka_unit_test_setup_teardown(test_port_reg_write, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_trace, setup, teardown),
		cmocka_unit_test_setup_teardown(test_cursor_ctrl_and_gamma_bit,
						setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
