// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Racing the beam: a fill that tears at the line the bus model predicts, a
 * page flip that never tears, palette and host VRAM writes that show in
 * exactly the lines fetched after them.
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
#include "bus.h"

#define VRAM_SIZE (2u << 20)
#define FRAME_CAP (64u * 64u)

/*
 * 64 pixels a line at 6.4 MHz: 1000 core cycles a line, 60 lines a frame,
 * 48 active lines of 32 XRGB8888 pixels (128 bytes, one burst).  With a
 * stride of one DRAM row, line L lives in row L.
 */
#define W	     32u
#define H	     48u
#define VTOTAL	     60u
#define LINE_CYCLES  1000u
#define FRAME_CYCLES (VTOTAL * LINE_CYCLES)
#define STRIDE	     RDC_DRAM_ROW_BYTES
#define LINE_BYTES   (W * 4)
#define BEATS	     (LINE_BYTES / RDC_BUS_BYTES)

#define OLD 0x00111111u
#define NEW 0x00eeddccu

struct fx {
	struct hw_fx sim;
	/* the fake DP's fill */
	int active;
	uint32_t row, compute;
};

static uint64_t fill_run(void *dp, uint64_t until)
{
	struct fx *f = dp;
	struct rdc_hw *hw = &f->sim.hw;

	while (f->active && f->row < H && hw->now < until) {
		uint8_t *p;
		uint32_t x;

		rdc_port_compute(hw, f->compute);
		p = rdc_port_span(hw, f->row * STRIDE, LINE_BYTES,
				  RDC_BUS_WRITE);
		assert_non_null(p);
		for (x = 0; x < W; x++)
			memcpy(p + 4 * x, &(uint32_t){ NEW }, 4);
		f->row++;
	}
	return f->active && f->row < H ? hw->now : RDC_NEVER;
}

static void fill_reset(void *dp)
{
	(void)dp;
}

static const struct rdc_dp_ops fill_ops = { fill_reset, fill_run };

static void fill_vram(struct fx *f, uint32_t base, uint32_t v)
{
	uint32_t y, x;

	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			memcpy(f->sim.vram + base + y * STRIDE + 4 * x, &v, 4);
}

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));
	struct rdc_hw *hw;

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	hw = &f->sim.hw;
	rdc_hw_set_dp(hw, &fill_ops, f);
	fill_vram(f, 0, OLD);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(hw, RDC_REG_H_DISPLAY, W);
	rdc_hw_write(hw, RDC_REG_H_SYNC_START, W + 8);
	rdc_hw_write(hw, RDC_REG_H_SYNC_END, W + 16);
	rdc_hw_write(hw, RDC_REG_H_TOTAL, 64);
	rdc_hw_write(hw, RDC_REG_V_DISPLAY, H);
	rdc_hw_write(hw, RDC_REG_V_SYNC_START, H + 2);
	rdc_hw_write(hw, RDC_REG_V_SYNC_END, H + 4);
	rdc_hw_write(hw, RDC_REG_V_TOTAL, VTOTAL);
	rdc_hw_write(hw, RDC_REG_PIXCLK_KHZ, 6400);
	rdc_hw_write(hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, STRIDE);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	/* a whole frame of OLD first, so the frame under test starts clean */
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 0));
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

/* Run to the vblank that ends the frame being scanned and return it. */
static const uint32_t *finish_frame(struct rdc_hw *hw)
{
	const uint32_t *p;
	uint32_t w, h;

	rdc_hw_run_until(hw, rdc_port_next_vblank(hw));
	p = rdc_hw_frame(hw, &w, &h);
	assert_non_null(p);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	return p;
}

/* The colour of a whole line, or 0xffffffff if it is mixed. */
static uint32_t line_colour(const uint32_t *p, uint32_t y)
{
	uint32_t x;

	for (x = 1; x < W; x++)
		if (p[y * W + x] != p[y * W])
			return 0xffffffff;
	return p[y * W];
}

/*
 * The model of bus.h applied to this fill, worked out independently of
 * the chip: each row costs `compute` cycles of DP work, then one 16-beat
 * burst (plus a miss unless its row is open); the CRTC fetches line L at
 * fs + L * LINE_CYCLES for 16 beats (plus a miss unless row L is open),
 * and a burst that would overlap such a window waits for its end.  Returns
 * the time each row's write completed.
 */
static void predict_fill(uint64_t fs, uint64_t t0, uint32_t compute,
			 uint64_t done[H])
{
	uint32_t open = ~0u, next = 0, r;
	uint64_t fetch_end = 0, t = t0;

	/* the fetches before t0 (the DP has not touched the bus yet) */
	while (next < H && fs + next * LINE_CYCLES <= t0) {
		fetch_end = fs + next * LINE_CYCLES + BEATS +
			    (open != next ? RDC_T_ROW_MISS : 0);
		open = next++;
	}
	for (r = 0; r < H; r++) {
		uint64_t cost;

		t += compute;
		for (;;) {
			uint64_t ls = fs + next * LINE_CYCLES;

			if (next < H && ls <= t) {
				fetch_end = RDC_MAX(ls, fetch_end) + BEATS +
					    (open != next ? RDC_T_ROW_MISS : 0);
				open = next++;
				continue;
			}
			if (t < fetch_end) {
				t = fetch_end;
				continue;
			}
			cost = BEATS + (open != r ? RDC_T_ROW_MISS : 0);
			if (next < H && ls < t + cost) {
				t = ls;
				continue;
			}
			break;
		}
		t += cost;
		open = r;
		done[r] = t;
	}
}

static void check_tear(struct fx *f, uint32_t start_line, uint32_t offset,
		       uint32_t compute, uint32_t *tear)
{
	struct rdc_hw *hw = &f->sim.hw;
	uint64_t fs = hw->crtc.frame_start;
	uint64_t t0 = fs + start_line * LINE_CYCLES + offset;
	uint64_t done[H];
	const uint32_t *p;
	uint32_t y, first_new = H;

	predict_fill(fs, t0, compute, done);
	rdc_hw_run_until(hw, t0);
	assert_int_equal(hw->now, t0);
	f->compute = compute;
	f->active = 1;
	p = finish_frame(hw);
	assert_int_equal(f->row, H);
	for (y = 0; y < H; y++) {
		/* new iff the row's write completed by the line's fetch */
		uint32_t want = done[y] <= fs + y * LINE_CYCLES ? NEW : OLD;

		assert_int_equal(line_colour(p, y), want);
		if (want == NEW && first_new == H)
			first_new = y;
	}
	/* the model's lines: before the start all old, then a tear */
	for (y = first_new; y < H; y++)
		assert_int_equal(line_colour(p, y), NEW);
	*tear = first_new;
	/* the next frame is all new */
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), NEW);
}

/* The DP starts mid-frame and overtakes the beam a few lines later. */
static void test_fill_tears_where_predicted(void **state)
{
	struct fx *f = *state;
	uint32_t tear;

	/* 100 cycles of work a row: ~122 a row against 1000 a line */
	check_tear(f, 10, 500, 100, &tear);
	/* by hand: row r is done near t0 + 122 (r + 1); the beam fetches
	 * line L at L * 1000: rows 11 and 12 come too late, 13 in time */
	assert_int_equal(tear, 13);
	/* the fill waited for fetch windows at least once */
	assert_true(f->sim.hw.perf.stall > 0);
}

/* A slower DP: the tear moves down accordingly. */
static void test_slow_fill_tears_lower(void **state)
{
	struct fx *f = *state;
	uint32_t tear;

	/* ~922 cycles a row: gains 78 cycles a line on the beam */
	check_tear(f, 2, 100, 900, &tear);
	assert_true(tear > 10 && tear < H);
}

/* Starting right on a line start: that line was fetched first. */
static void test_fill_from_line_start(void **state)
{
	struct fx *f = *state;
	uint32_t tear;

	check_tear(f, 20, 0, 0, &tear);
	assert_int_equal(tear, 21);
}

/* FB_BASE written mid-frame: this frame all old buffer, next all new. */
static void test_page_flip_never_tears(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint64_t fs = hw->crtc.frame_start;
	const uint32_t back = 0x40000;
	const uint32_t *p;
	uint32_t y;

	fill_vram(f, back, NEW);
	rdc_hw_run_until(hw, fs + 20 * LINE_CYCLES + 300);
	rdc_hw_write(hw, RDC_REG_FB_BASE, back);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), OLD);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), NEW);

	/* from the command stream, at an exact line: the same */
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 5));
	assert_int_equal(rdc_port_reg_write(hw, RDC_REG_FB_BASE, 0), 0);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), NEW);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), OLD);
}

static void set_i8(struct fx *f)
{
	struct rdc_hw *hw = &f->sim.hw;
	uint32_t y;

	for (y = 0; y < H; y++)
		memset(f->sim.vram + y * STRIDE, 5, W);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_I8);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 5);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, OLD);
	finish_frame(hw); /* latches the format */
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 0));
}

/* An immediate CLUT write shows in exactly the lines fetched after it. */
static void test_clut_mid_frame(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t *p;
	uint64_t fs;
	uint32_t y;

	set_i8(f);
	fs = hw->crtc.frame_start;
	rdc_hw_run_until(hw, fs + 20 * LINE_CYCLES + 1);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 5);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, NEW);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), y <= 20 ? OLD : NEW);

	/* from the DP at exactly the start of line 30: line 30 was fetched
	 * at that same moment, before the write */
	fs = rdc_port_next_line(hw, 0);
	rdc_hw_run_until(hw, fs + 30 * LINE_CYCLES);
	rdc_port_clut_write(hw, 5, OLD);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), y <= 30 ? NEW : OLD);
}

/* Host writes through the aperture race the beam too. */
static void test_host_write_races_beam(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint64_t fs = hw->crtc.frame_start;
	const uint32_t *p;
	uint32_t y, x;

	rdc_hw_run_until(hw, fs + 7 * LINE_CYCLES + 999);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			assert_int_equal(
				rdc_hw_vram_write(hw, y * STRIDE + 4 * x,
						  &(uint32_t){ NEW }, 4),
				0);
	p = finish_frame(hw);
	for (y = 0; y < H; y++)
		assert_int_equal(line_colour(p, y), y <= 7 ? OLD : NEW);
	/* out of range: refused, nothing copied */
	assert_int_equal(rdc_hw_vram_write(hw, VRAM_SIZE - 2, "abcd", 4), -1);
	assert_int_equal(rdc_hw_vram_write(hw, 0xffffffffu, "ab", 2), -1);
	{
		uint8_t b[4] = { 1, 2, 3, 4 };

		assert_int_equal(rdc_hw_vram_read(hw, VRAM_SIZE - 3, b, 4), -1);
		assert_int_equal(b[0], 1);
		assert_int_equal(rdc_hw_vram_read(hw, 0, b, 4), 0);
		assert_int_equal(b[0], NEW & 0xff);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_fill_tears_where_predicted,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_slow_fill_tears_lower,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_fill_from_line_start,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_page_flip_never_tears,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_clut_mid_frame, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_host_write_races_beam,
						setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
