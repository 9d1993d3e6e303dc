// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * CRTC timing: each preset's frame period and refresh rate, beam position,
 * vblank and line-compare interrupts at their times, the frame listener,
 * mode validation and latching, scanout on/off, and the run loop's
 * interplay with a display processor.
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
#define CORE_HZ	  100000000ull

struct fx {
	struct hw_fx sim;
	/* frame listener */
	int frames;
	uint32_t fw, fh;
	uint64_t fnum[8];
	uint64_t ftime[8];
	/* fake DP */
	int runs;
	uint64_t dp_wake;
	uint32_t dp_step;
	uint64_t run_until[8];
};

/*
 * A small mode: 64 pixels a line at 10 MHz is 10 core cycles a pixel,
 * 640 a line; 60 lines make a 38400-cycle frame, 48 of them active.
 */
#define PX_CYCLES    10u
#define LINE_CYCLES  640u
#define FRAME_CYCLES (60u * LINE_CYCLES)

static const struct rdc_timing small_mode = {
	.h_total = 64,
	.h_display = 32,
	.h_sync_start = 40,
	.h_sync_end = 48,
	.v_total = 60,
	.v_display = 48,
	.v_sync_start = 50,
	.v_sync_end = 52,
	.pixclk_khz = 10000,
};

static void write_timing(struct rdc_hw *hw, const struct rdc_timing *t)
{
	rdc_hw_write(hw, RDC_REG_H_TOTAL, t->h_total);
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, t->h_display);
	rdc_hw_write(hw, RDC_REG_H_SYNC_START, t->h_sync_start);
	rdc_hw_write(hw, RDC_REG_H_SYNC_END, t->h_sync_end);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, t->v_total);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, t->v_display);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, t->v_sync_start);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, t->v_sync_end);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, t->pixclk_khz);
	rdc_hw_write(hw, RDC_REG_CRTC_FLAGS, t->flags);
}

/* Program a mode and start scanout with it at once. */
static void set_mode(struct rdc_hw *hw, const struct rdc_timing *t)
{
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	write_timing(hw, t);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, t->h_display * 4);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

static void on_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t n)
{
	struct fx *f = ctx;

	assert_non_null(xrgb);
	/* the chip is consistent from inside the listener */
	assert_int_equal(FIELD_GET(RDC_BEAM_Y,
				   rdc_hw_read(&f->sim.hw, RDC_REG_BEAM)),
			 h);
	assert_int_equal(rdc_hw_read(&f->sim.hw, RDC_REG_FRAME_COUNT), n + 1);
	assert_true(rdc_hw_pins(&f->sim.hw) & RDC_PIN_TE);
	assert_ptr_equal(rdc_hw_frame(&f->sim.hw, NULL, NULL), xrgb);
	if (f->frames < 8) {
		f->fnum[f->frames] = n;
		f->ftime[f->frames] = f->sim.hw.now;
	}
	f->frames++;
	f->fw = w;
	f->fh = h;
}

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	rdc_hw_set_frame_fn(&f->sim.hw, on_frame, f);
	set_mode(&f->sim.hw, &small_mode);
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

/* Frame period of every preset, from the VESA/CEA numbers. */
static void test_preset_periods(void **state)
{
	static const struct {
		uint32_t preset, w, h, htotal, vtotal, khz;
		uint32_t refresh_mhz; /* nominal, millihertz */
	} p[] = {
		{ RDC_PRESET_320x200_70, 320, 200, 400, 225, 6300, 70000 },
		{ RDC_PRESET_640x480_60, 640, 480, 800, 525, 25175, 59940 },
		{ RDC_PRESET_800x600_60, 800, 600, 1056, 628, 40000, 60317 },
		{ RDC_PRESET_1024x768_60, 1024, 768, 1344, 806, 65000, 60004 },
		{ RDC_PRESET_1280x720_60, 1280, 720, 1650, 750, 74250, 60000 },
		{ RDC_PRESET_1920x1080_60, 1920, 1080, 2200, 1125, 148500,
		  60000 },
	};
	struct hw_fx *x = calloc(1, sizeof(*x));
	struct rdc_hw *hw;
	size_t i;

	(void)state;
	assert_non_null(x);
	assert_int_equal(hw_fx_init(x, 1u << 20, 1920 * 1080), 0);
	hw = &x->hw;
	for (i = 0; i < sizeof(p) / sizeof(p[0]); i++) {
		uint64_t frame = (uint64_t)p[i].htotal * p[i].vtotal * CORE_HZ /
				 ((uint64_t)p[i].khz * 1000);
		uint64_t vb1, vb2, mhz;
		struct rdc_timing t;
		uint32_t w, h;

		assert_int_equal(rdc_preset_timing(p[i].preset, &t), 0);
		assert_int_equal(t.h_display, p[i].w);
		assert_int_equal(t.v_display, p[i].h);
		assert_int_equal(t.h_total, p[i].htotal);
		assert_int_equal(t.v_total, p[i].vtotal);
		assert_int_equal(t.pixclk_khz, p[i].khz);
		assert_true(t.h_sync_start >= t.h_display &&
			    t.h_sync_end > t.h_sync_start &&
			    t.h_total >= t.h_sync_end);
		assert_true(t.v_sync_start >= t.v_display &&
			    t.v_sync_end > t.v_sync_start &&
			    t.v_total >= t.v_sync_end);

		rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
		rdc_hw_write(hw, RDC_REG_MODE_PRESET, p[i].preset);
		rdc_hw_write(hw, RDC_REG_CONTROL,
			     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
		assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE),
				 RDC_ERR_NONE);
		vb1 = rdc_port_next_vblank(hw);
		rdc_hw_run_until(hw, vb1);
		vb2 = rdc_port_next_vblank(hw);
		assert_int_equal(vb2 - vb1, frame);
		/* the refresh rate the period gives, to a millihertz */
		mhz = (CORE_HZ * 1000 + frame / 2) / frame;
		assert_true(mhz + 1 >= p[i].refresh_mhz &&
			    mhz <= p[i].refresh_mhz + 1);
		assert_non_null(rdc_hw_frame(hw, &w, &h));
		assert_int_equal(w, p[i].w);
		assert_int_equal(h, p[i].h);
	}
	hw_fx_fini(x);
	free(x);
}

static void test_line_times(void **state)
{
	static const struct rdc_timing odd = {
		/* 7 pixels at 3 MHz: 233.33 cycles a line, so the line
		 * starts are floors of n * 700 / 3 */
		.h_total = 7,	   .h_display = 4,  .h_sync_start = 5,
		.h_sync_end = 6,   .v_total = 9,    .v_display = 6,
		.v_sync_start = 7, .v_sync_end = 8, .pixclk_khz = 3000,
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs;
	uint32_t n;

	set_mode(hw, &odd);
	fs = hw->now;
	for (n = 1; n < 9; n++)
		assert_int_equal(rdc_port_next_line(hw, n),
				 fs + (uint64_t)n * 700 / 3);
	/* frame length 9 * 700 / 3 = 2100; the next frame restarts the
	 * division from its own start, so no drift */
	assert_int_equal(rdc_port_next_line(hw, 0), fs + 2100);
	rdc_hw_run_until(hw, fs + 2100 + 1);
	assert_int_equal(rdc_port_next_line(hw, 1), fs + 2100 + 233);
	assert_int_equal(rdc_port_next_line(hw, 0), fs + 4200);
	assert_int_equal(rdc_port_next_vblank(hw), fs + 2100 + 1400);
	/* lines past V_TOTAL never come */
	assert_int_equal(rdc_port_next_line(hw, 9), RDC_NEVER);
}

static void test_beam(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs = hw->now;
	uint32_t x, y, v;

	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 0);
	assert_int_equal(y, 0);
	/* line 5, 123 cycles in: pixel 12 */
	rdc_hw_run_until(hw, fs + 5 * LINE_CYCLES + 123);
	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 123 / PX_CYCLES);
	assert_int_equal(y, 5);
	v = rdc_hw_read(hw, RDC_REG_BEAM);
	assert_int_equal(FIELD_GET(RDC_BEAM_X, v), 12);
	assert_int_equal(FIELD_GET(RDC_BEAM_Y, v), 5);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_HBLANK);
	/* pixel 33 of 32 displayed: horizontal blanking */
	rdc_hw_run_until(hw, fs + 5 * LINE_CYCLES + 33 * PX_CYCLES);
	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 33);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_HBLANK);
	/* last cycle of the line */
	rdc_hw_run_until(hw, fs + 6 * LINE_CYCLES - 1);
	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 63);
	assert_int_equal(y, 5);
	/* vertical blanking: y >= V_DISPLAY */
	rdc_hw_run_until(hw, fs + 50 * LINE_CYCLES + 7 * PX_CYCLES);
	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 7);
	assert_int_equal(y, 50);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	/* next frame */
	rdc_hw_run_until(hw, fs + FRAME_CYCLES + 2 * LINE_CYCLES);
	rdc_hw_beam(hw, &x, &y);
	assert_int_equal(x, 0);
	assert_int_equal(y, 2);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
}

static void test_vblank_and_line_irqs(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs = hw->now;

	rdc_hw_write(hw, RDC_REG_LINE_COMPARE, 7);
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_LINE);
	rdc_hw_run_until(hw, fs + 7 * LINE_CYCLES - 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	assert_false(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	rdc_hw_run_until(hw, fs + 7 * LINE_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_LINE);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_LINE);

	rdc_hw_run_until(hw, fs + 48 * LINE_CYCLES - 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	rdc_hw_run_until(hw, fs + 48 * LINE_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_VBLANK);
	/* VBLANK not enabled: the pin stays low */
	assert_false(rdc_hw_pins(hw) & RDC_PIN_IRQ);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_VBLANK);

	/* a compare line in vertical blanking works too */
	rdc_hw_write(hw, RDC_REG_LINE_COMPARE, 55);
	rdc_hw_run_until(hw, fs + 55 * LINE_CYCLES - 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	rdc_hw_run_until(hw, fs + 55 * LINE_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_LINE);
	/* and a line beyond V_TOTAL never fires */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_write(hw, RDC_REG_LINE_COMPARE, 60);
	rdc_hw_run_until(hw, fs + 3 * FRAME_CYCLES - LINE_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_VBLANK);
}

static void test_frame_listener(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs = hw->now;
	uint32_t w, h;
	int i;

	assert_null(rdc_hw_frame(hw, &w, &h));
	assert_int_equal(w, 0);
	rdc_hw_run_until(hw, fs + 48 * LINE_CYCLES - 1);
	assert_int_equal(f->frames, 0);
	rdc_hw_run_until(hw, fs + 4 * FRAME_CYCLES);
	/* vblanks at 48, 108, 168, 228 lines: four frames */
	assert_int_equal(f->frames, 4);
	assert_int_equal(f->fw, 32);
	assert_int_equal(f->fh, 48);
	for (i = 0; i < 4; i++) {
		assert_int_equal(f->fnum[i], i);
		assert_int_equal(f->ftime[i],
				 fs + i * FRAME_CYCLES + 48 * LINE_CYCLES);
	}
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FRAME_COUNT), 4);
	assert_non_null(rdc_hw_frame(hw, &w, &h));
	assert_int_equal(w, 32);
	assert_int_equal(h, 48);
}

static void test_invalid_timing_refused(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t vb, fs = hw->now;

	/* display wider than total */
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, 100);
	vb = rdc_port_next_vblank(hw);
	rdc_hw_run_until(hw, vb);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), RDC_REG_H_TOTAL);
	assert_true(rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	/* the old mode runs on: next vblank one frame later */
	assert_int_equal(rdc_port_next_vblank(hw), vb + FRAME_CYCLES);
	/* reported once, not every frame */
	rdc_hw_run_until(hw, vb + FRAME_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);

	/* larger than the frame buffers handed in (64 x 64 pixels) */
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, 40);
	rdc_hw_write(hw, RDC_REG_H_SYNC_START, 200);
	rdc_hw_write(hw, RDC_REG_H_SYNC_END, 200);
	rdc_hw_write(hw, RDC_REG_H_TOTAL, 200);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, 200);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, 200);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, 200);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, 201);
	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);

	/* pixel clock out of range, refused when scanout starts too */
	write_timing(hw, &small_mode);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, RDC_PIXCLK_MAX_KHZ + 1);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	/* ... and the last good mode starts instead */
	assert_int_equal(rdc_port_next_vblank(hw), hw->now + 48 * LINE_CYCLES);

	/* no vertical blanking, zero-sized displays, totals over the max */
	write_timing(hw, &small_mode);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, 60);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, 60);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, 60);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	write_timing(hw, &small_mode);
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, 0);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	write_timing(hw, &small_mode);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, RDC_CRTC_MAX_TOTAL + 1);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	/* an unknown format is refused at latch too */
	write_timing(hw, &small_mode);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_COUNT);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), RDC_REG_FB_FORMAT);
	assert_int_equal(hw->crtc.cur_format, RDC_FMT_XRGB8888);
	/* through all of it the chip kept producing frames of the old size */
	assert_int_equal(f->fw, 32);
	assert_int_equal(f->fh, 48);
	(void)fs;
}

/* A new timing latched at vblank starts with the next frame. */
static void test_mode_change_at_next_frame(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs = hw->now;

	rdc_hw_run_until(hw, fs + 10 * LINE_CYCLES);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, 70);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, 40);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, 41);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, 42);
	/* this frame's vblank still at line 48, the next frame at 60 */
	assert_int_equal(rdc_port_next_vblank(hw), fs + 48 * LINE_CYCLES);
	rdc_hw_run_until(hw, fs + 48 * LINE_CYCLES);
	assert_int_equal(f->frames, 1);
	assert_int_equal(f->fh, 48);
	assert_int_equal(rdc_port_next_line(hw, 0), fs + FRAME_CYCLES);
	/* the next vblank uses the new V_DISPLAY */
	assert_int_equal(rdc_port_next_vblank(hw),
			 fs + FRAME_CYCLES + 40 * LINE_CYCLES);
	assert_int_equal(rdc_port_next_line(hw, 65),
			 fs + FRAME_CYCLES + 65 * LINE_CYCLES);
	rdc_hw_run_until(hw, fs + FRAME_CYCLES + 40 * LINE_CYCLES);
	assert_int_equal(f->frames, 2);
	assert_int_equal(f->fh, 40);
	assert_int_equal(rdc_port_next_line(hw, 0),
			 fs + FRAME_CYCLES + 70 * LINE_CYCLES);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
}

static void test_scanout_off_and_on(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t t;

	rdc_hw_run_until(hw, hw->now + 5 * LINE_CYCLES + 5);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	assert_int_equal(rdc_port_next_vblank(hw), RDC_NEVER);
	assert_int_equal(rdc_port_next_line(hw, 3), RDC_NEVER);
	rdc_hw_write(hw, RDC_REG_LINE_COMPARE, 10);
	rdc_hw_run_until(hw, hw->now + 10 * FRAME_CYCLES);
	assert_int_equal(f->frames, 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_BEAM), 0);
	/* on again: a frame starts now */
	t = hw->now;
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_int_equal(rdc_port_next_line(hw, 10), t + 10 * LINE_CYCLES);
	assert_int_equal(rdc_port_next_vblank(hw), t + 48 * LINE_CYCLES);
	rdc_hw_run_until(hw, t + 48 * LINE_CYCLES);
	assert_int_equal(f->frames, 1);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS),
			 RDC_IRQ_LINE | RDC_IRQ_VBLANK);
}

/*
 * A stopped CRTC has no scanout event to come: its line and strobe times
 * are RDC_NEVER, which the hot paths' tests of those times rely on
 * rather than testing `running` too.
 */
static void assert_stopped(struct rdc_hw *hw)
{
	assert_false(hw->crtc.running);
	assert_int_equal(hw->crtc.next_line_time, RDC_NEVER);
	assert_int_equal(hw->crtc.lpen_time, RDC_NEVER);
	assert_false(rdc_crtc_due(hw, hw->now + 100 * FRAME_CYCLES));
}

static void test_stopped_has_no_events(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	struct hw_fx fresh;

	/* a chip just made, scanout never on */
	assert_int_equal(hw_fx_init(&fresh, VRAM_SIZE, FRAME_CAP), 0);
	assert_stopped(&fresh.hw);
	hw_fx_fini(&fresh);

	/*
	 * running mid-line, a light pen on a lit pixel of it whose strobe
	 * is still to come, then scanout off: the strobe never comes
	 */
	rdc_st32(hw->vram + 7 * small_mode.h_display * 4 + 31 * 4, 0xffffff);
	rdc_hw_write(hw, RDC_REG_LPEN_POS,
		     FIELD_PREP(RDC_LPEN_X, 31) | FIELD_PREP(RDC_LPEN_Y, 7));
	rdc_hw_write(hw, RDC_REG_LPEN_CTRL, RDC_LPEN_CTRL_EN);
	rdc_hw_run_until(hw, hw->now + 7 * LINE_CYCLES + 3);
	assert_true(hw->crtc.running);
	assert_int_equal(hw->crtc.lpen_time, hw->now - 3 + 31 * PX_CYCLES);
	assert_true(rdc_crtc_due(hw, hw->now + LINE_CYCLES));
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	assert_stopped(hw);
	rdc_hw_run_until(hw, hw->now + 3 * FRAME_CYCLES);
	assert_stopped(hw);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_LPEN);
	assert_false(rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_LPEN);

	/* on after a reset with a mode refused: none to fall back on */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, RDC_PIXCLK_MAX_KHZ + 1);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	assert_stopped(hw);
	assert_int_equal(f->frames, 0);
}

/* ---- run loop with a display processor ----------------------------------
 * The fake DP works in steps of dp_step cycles while it has work, then
 * waits until dp_wake.
 */
static uint64_t fake_run(void *dp, uint64_t until)
{
	struct fx *f = dp;
	struct rdc_hw *hw = &f->sim.hw;

	if (f->runs < 8)
		f->run_until[f->runs] = until;
	f->runs++;
	while (hw->now < f->dp_wake && hw->now < until)
		rdc_port_compute(hw, f->dp_step);
	return f->dp_wake > hw->now ? f->dp_wake : RDC_NEVER;
}

static void fake_reset(void *dp)
{
	(void)dp;
}

static const struct rdc_dp_ops fake_ops = { fake_reset, fake_run };

static void test_run_loop(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t t0 = hw->now;

	rdc_hw_set_dp(hw, &fake_ops, f);
	/* busy until t0 + 1000 in steps of 300: overshoots to t0 + 1200 */
	f->dp_wake = t0 + 1000;
	f->dp_step = 300;
	rdc_hw_run_until(hw, t0 + 1000);
	assert_int_equal(hw->now, t0 + 1200);
	assert_int_equal(f->runs, 1);
	assert_int_equal(f->run_until[0], t0 + 1000);

	/* a DP waiting for the host: one call, then the loop idles */
	f->runs = 0;
	f->dp_wake = 0;
	rdc_hw_run_until(hw, t0 + 5000);
	assert_int_equal(hw->now, t0 + 5000);
	assert_int_equal(f->runs, 1);

	/* DP disabled: never called */
	f->runs = 0;
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SCANOUT_EN);
	rdc_hw_run_until(hw, t0 + 6000);
	assert_int_equal(f->runs, 0);
	assert_int_equal(hw->now, t0 + 6000);
}

/* The DP reports a wake time; the loop sleeps until it, not past it. */
static uint64_t sleepy_run(void *dp, uint64_t until)
{
	struct fx *f = dp;

	(void)until;
	if (f->runs < 8)
		f->run_until[f->runs] = f->sim.hw.now;
	f->runs++;
	return f->runs < 3 ? f->sim.hw.now + 700 : RDC_NEVER;
}

static const struct rdc_dp_ops sleepy_ops = { fake_reset, sleepy_run };

static void test_run_loop_wakes(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t t0 = hw->now;

	rdc_hw_set_dp(hw, &sleepy_ops, f);
	rdc_hw_run_until(hw, t0 + 5000);
	assert_int_equal(f->runs, 3);
	assert_int_equal(f->run_until[0], t0);
	assert_int_equal(f->run_until[1], t0 + 700);
	assert_int_equal(f->run_until[2], t0 + 1400);
	assert_int_equal(hw->now, t0 + 5000);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_preset_periods),
		cmocka_unit_test_setup_teardown(test_line_times, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_beam, setup, teardown),
		cmocka_unit_test_setup_teardown(test_vblank_and_line_irqs,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_frame_listener, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_invalid_timing_refused,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_mode_change_at_next_frame,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_scanout_off_and_on, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_stopped_has_no_events,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_run_loop, setup, teardown),
		cmocka_unit_test_setup_teardown(test_run_loop_wakes, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
