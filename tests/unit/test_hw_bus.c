// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The VRAM bus cost model (hw-sim/bus.h): exact cycles of spans and
 * columns, worked out here from the formulas, a beat-by-beat reference
 * model on random spans, contention with scanout fetch windows, the DRAM
 * row shared with scanout, and out-of-range accesses.
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
#define BURST	  (RDC_BUS_BURST_BEATS * RDC_BUS_BYTES) /* 128 bytes */
#define ROW	  RDC_DRAM_ROW_BYTES
#define MISS	  RDC_T_ROW_MISS
#define TURN	  RDC_T_TURN

/*
 * A small mode: 64 pixels a line at 6.4 MHz is 1000 core cycles at
 * 100 MHz; 60 lines make a 60000-cycle frame, 48 of them active.  Each
 * active line is 32 XRGB8888 pixels = 128 bytes = one burst, and with a
 * stride of one DRAM row every line lives in its own row (line L in row
 * L), so each fetch costs 16 beats + a row miss = 22 cycles.
 */
#define LINE_CYCLES  1000u
#define ACTIVE_LINES 48u
#define FETCH_CYCLES (BURST / RDC_BUS_BYTES * RDC_T_BEAT + MISS)

static const struct rdc_timing small_mode = {
	.h_total = 64,
	.h_display = 32,
	.h_sync_start = 40,
	.h_sync_end = 48,
	.v_total = 60,
	.v_display = 48,
	.v_sync_start = 50,
	.v_sync_end = 52,
	.pixclk_khz = 6400,
};

static void set_mode(struct rdc_hw *hw, const struct rdc_timing *t,
		     uint32_t base, uint32_t stride, uint32_t fmt)
{
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
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
	rdc_hw_write(hw, RDC_REG_FB_BASE, base);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, stride);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, fmt);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

static int setup(void **state)
{
	struct hw_fx *f;

	if (hw_fx_setup(state, VRAM_SIZE, FRAME_CAP))
		return -1;
	f = *state;
	/* no scanout: the DP has the bus to itself */
	rdc_hw_write(&f->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(&f->hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	return 0;
}

/* Cycles one span takes from hw->now. */
static uint64_t span(struct rdc_hw *hw, uint32_t addr, uint32_t len,
		     unsigned int kind)
{
	uint64_t t0 = hw->now;

	assert_non_null(rdc_port_span(hw, addr, len, kind));
	return hw->now - t0;
}

static uint64_t column(struct rdc_hw *hw, uint32_t addr, uint32_t stride,
		       uint32_t count, uint32_t len, unsigned int kind)
{
	uint64_t t0 = hw->now;

	assert_non_null(rdc_port_column(hw, addr, stride, count, len, kind));
	return hw->now - t0;
}

/* Worked cases, each from the formula by hand. */
static void test_span_costs(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	/* aligned burst, first access (no open row): 16 beats + miss */
	assert_int_equal(span(hw, 0, 128, RDC_BUS_WRITE), 16 + MISS);
	/* next burst in the same row: no miss */
	assert_int_equal(span(hw, 128, 128, RDC_BUS_WRITE), 16);
	/* reads cost the same beats */
	assert_int_equal(span(hw, 256, 128, RDC_BUS_READ), 16);
	/* 4 KiB aligned write from row 0: 512 beats, rows 0->1 change,
	 * row 0 is open: one miss */
	assert_int_equal(span(hw, 0, 4096, RDC_BUS_WRITE), 512 + MISS);
	/* now row 1 is open; back to row 0 costs a miss again */
	assert_int_equal(span(hw, 8, 8, RDC_BUS_WRITE), 1 + MISS);
	/* unaligned both ends, one burst: bytes 3..12 touch beats 0 and 1,
	 * both partial: T_TURN + 2 beats of read-back */
	assert_int_equal(span(hw, 3, 10, RDC_BUS_WRITE), 2 + TURN + 2);
	/* within one beat, partial: one beat merged once */
	assert_int_equal(span(hw, 17, 2, RDC_BUS_WRITE), 1 + TURN + 1);
	/* the same span read: no merge */
	assert_int_equal(span(hw, 17, 2, RDC_BUS_READ), 1);
	/* [100, 300): beats 12..37 = 26, bursts 0, 1, 2; head partial in
	 * burst 0, tail (300 % 8 = 4) partial in burst 2: two turnarounds */
	assert_int_equal(span(hw, 100, 200, RDC_BUS_WRITE),
			 26 + 2 * (TURN + 1));
	/* [2000, 2100): beats 250..262 = 13, crosses from row 0 into row 1
	 * (row 0 open): 1 miss; head aligned, tail partial */
	assert_int_equal(span(hw, 2000, 100, RDC_BUS_WRITE),
			 13 + MISS + TURN + 1);
	/* RMW of 256 aligned bytes in row 1: 32 beats, 2 bursts, each
	 * reads all its beats back after a turnaround */
	assert_int_equal(span(hw, 2048, 256, RDC_BUS_RMW), 32 + 2 * TURN + 32);
	/* aligned write flagged partial at the edges (sub-byte pixels) */
	assert_int_equal(span(hw, 2048, 64,
			      RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL),
			 8 + TURN + 1);
	assert_int_equal(span(hw, 2048, 64,
			      RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL |
				      RDC_BUS_TAIL_PARTIAL),
			 8 + TURN + 2);
	/* the flags on a span of several bursts: each edge its own burst */
	assert_int_equal(span(hw, 2048, 256,
			      RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL |
				      RDC_BUS_TAIL_PARTIAL),
			 32 + 2 * (TURN + 1));
	/* flags mean nothing to reads */
	assert_int_equal(span(hw, 2048, 64,
			      RDC_BUS_READ | RDC_BUS_HEAD_PARTIAL |
				      RDC_BUS_TAIL_PARTIAL),
			 8);
	/* a span over three rows from a fourth: 3 misses */
	assert_int_equal(span(hw, 10 * ROW, 3 * ROW, RDC_BUS_READ),
			 3 * ROW / 8 + 3 * MISS);
	/* the bus is idle between accesses: nothing charged for stalls */
	assert_int_equal(hw->perf.stall, 0);
}

static void test_column_costs(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	/* 4 pixels of 4 bytes, one row apart: each its own row (miss) and
	 * a partial beat (4 of 8 bytes): 1 + MISS + TURN + 1 each */
	assert_int_equal(column(hw, 0, ROW, 4, 4, RDC_BUS_WRITE),
			 4 * (1 + MISS + TURN + 1));
	/* 8 bytes apart in one row: only the first misses (row 3 open) */
	assert_int_equal(column(hw, 0, 8, 5, 8, RDC_BUS_WRITE),
			 (1 + MISS) + 4 * 1);
	/* reads of 2 bytes at stride 640 starting in row 0 (open):
	 * addresses 0, 640, 1280, 1920, 2560 -> row 1 at the last */
	assert_int_equal(column(hw, 0, 640, 5, 2, RDC_BUS_READ), 5 * 1 + MISS);
	/* RMW column: every element is one burst with its turnaround */
	assert_int_equal(column(hw, 2 * ROW, 8, 3, 8, RDC_BUS_RMW),
			 3 * (1 + TURN + 1) + MISS);
	/* an element that crosses a beat boundary: 2 beats, both partial */
	assert_int_equal(column(hw, 2 * ROW + 6, 16, 2, 4, RDC_BUS_WRITE),
			 2 * (2 + TURN + 2));
}

/*
 * A reference written from bus.h's words, beat by beat: walk the beats of
 * the span, open a new burst at each 128-byte boundary, pay a miss when a
 * beat's row differs from the open one, and charge each burst's merged
 * beats with one turnaround.
 */
static uint64_t ref_cost(uint32_t *open_row, uint32_t a, uint32_t n,
			 unsigned int kind)
{
	uint32_t first = a / RDC_BUS_BYTES, last = (a + n - 1) / RDC_BUS_BYTES;
	uint64_t cost = 0;
	uint32_t rmw_in_burst = 0, b;
	int head = (a % RDC_BUS_BYTES) || (kind & RDC_BUS_HEAD_PARTIAL);
	int tail = ((a + n) % RDC_BUS_BYTES) || (kind & RDC_BUS_TAIL_PARTIAL);

	for (b = first; b <= last; b++) {
		uint32_t addr = b * RDC_BUS_BYTES;
		int merged;

		if (b != first && addr % BURST == 0 && rmw_in_burst) {
			cost += TURN + rmw_in_burst;
			rmw_in_burst = 0;
		}
		if (addr / ROW != *open_row) {
			cost += MISS;
			*open_row = addr / ROW;
		}
		cost += RDC_T_BEAT;
		switch (kind & RDC_BUS_KIND_MASK) {
		case RDC_BUS_RMW:
			merged = 1;
			break;
		case RDC_BUS_WRITE:
			merged = (b == first && head) || (b == last && tail);
			break;
		default:
			merged = 0;
			break;
		}
		rmw_in_burst += merged;
	}
	if (rmw_in_burst)
		cost += TURN + rmw_in_burst;
	return cost;
}

static void test_random_spans_match_reference(void **state)
{
	static const unsigned int kinds[] = {
		RDC_BUS_READ,
		RDC_BUS_WRITE,
		RDC_BUS_RMW,
		RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL,
		RDC_BUS_WRITE | RDC_BUS_TAIL_PARTIAL,
		RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL | RDC_BUS_TAIL_PARTIAL,
	};
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint32_t seed = 12345, row = ~0u;
	int i;

	for (i = 0; i < 3000; i++) {
		uint32_t a, n;
		unsigned int kind;

		seed = seed * 1103515245u + 12345u;
		a = (seed >> 8) % (VRAM_SIZE - 20000);
		seed = seed * 1103515245u + 12345u;
		n = 1 + (seed >> 8) % (i % 3 ? 300 : 9000);
		kind = kinds[(seed >> 4) % 6];
		assert_int_equal(span(hw, a, n, kind),
				 ref_cost(&row, a, n, kind));
		assert_int_equal(hw->bus.open_row, row);
	}
}

static void test_out_of_range(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint64_t t0 = hw->now;

	assert_null(rdc_port_span(hw, 0, 0, RDC_BUS_WRITE));
	assert_null(rdc_port_span(hw, VRAM_SIZE, 1, RDC_BUS_WRITE));
	assert_null(rdc_port_span(hw, VRAM_SIZE - 4, 5, RDC_BUS_WRITE));
	assert_null(rdc_port_span(hw, 0xfffffff0u, 0x20, RDC_BUS_READ));
	assert_null(rdc_port_span(hw, 16, 0xffffffffu, RDC_BUS_READ));
	assert_null(rdc_port_column(hw, 0, ROW, 0, 4, RDC_BUS_WRITE));
	assert_null(rdc_port_column(hw, 0, ROW, 4, 0, RDC_BUS_WRITE));
	/* the last element leaves VRAM by one byte */
	assert_null(rdc_port_column(hw, 0, ROW, VRAM_SIZE / ROW, ROW + 1,
				    RDC_BUS_WRITE));
	/* 32-bit wrap of count * stride must not pass */
	assert_null(
		rdc_port_column(hw, 0, 0x10000u, 0x10001u, 4, RDC_BUS_WRITE));
	assert_null(rdc_port_column(hw, 0xfffffffcu, 0, 1, 8, RDC_BUS_READ));
	assert_int_equal(hw->now, t0);
	assert_int_equal(hw->bus.open_row, ~0u);
	/* the last bytes are in range */
	assert_ptr_equal(rdc_port_span(hw, VRAM_SIZE - 4, 4, RDC_BUS_WRITE),
			 hw->vram + VRAM_SIZE - 4);
	assert_ptr_equal(rdc_port_column(hw, 0, ROW, VRAM_SIZE / ROW, ROW,
					 RDC_BUS_READ),
			 hw->vram);
}

static void test_compute_and_idle(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	rdc_port_compute(hw, 17);
	assert_int_equal(hw->now, 17);
	rdc_port_idle_until(hw, 100);
	assert_int_equal(hw->now, 100);
	rdc_port_idle_until(hw, 50); /* never backwards */
	assert_int_equal(hw->now, 100);
	/* compute does not touch the bus */
	assert_int_equal(hw->bus.open_row, ~0u);
}

/* ---- contention with scanout -------------------------------------------- */

static uint64_t line_time(const struct rdc_hw *hw, uint32_t line)
{
	return hw->crtc.frame_start + (uint64_t)line * LINE_CYCLES;
}

static void test_burst_waits_for_fetch_window(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint64_t lt;

	set_mode(hw, &small_mode, 0, ROW, RDC_FMT_XRGB8888);
	lt = line_time(hw, 10);

	/* 5 cycles before line 10 a 22-cycle burst (row 100, miss) would
	 * overlap the fetch window [lt, lt + 22): it waits for its end */
	rdc_port_idle_until(hw, lt - 5);
	assert_int_equal(span(hw, 100 * ROW, 128, RDC_BUS_WRITE),
			 5 + FETCH_CYCLES + 16 + MISS);
	assert_int_equal(hw->perf.stall, 5 + FETCH_CYCLES);
	assert_int_equal(hw->now, lt + FETCH_CYCLES + 16 + MISS);

	/* a burst that ends right at the next window's start goes first */
	lt = line_time(hw, 11);
	rdc_port_idle_until(hw, lt - (16 + MISS));
	assert_int_equal(span(hw, 200 * ROW, 128, RDC_BUS_WRITE), 16 + MISS);
	assert_int_equal(hw->perf.stall, 5 + FETCH_CYCLES);

	/* inside a window: wait for the rest of it */
	lt = line_time(hw, 12);
	rdc_port_idle_until(hw, lt + 10);
	assert_int_equal(span(hw, 300 * ROW, 128, RDC_BUS_WRITE),
			 FETCH_CYCLES - 10 + 16 + MISS);
	assert_int_equal(hw->perf.stall, 5 + FETCH_CYCLES + FETCH_CYCLES - 10);

	/* the fetch left row 13 open: a DP burst there right after it is a
	 * row hit, one elsewhere a miss */
	lt = line_time(hw, 13);
	rdc_port_idle_until(hw, lt + FETCH_CYCLES);
	assert_int_equal(span(hw, 13 * ROW + 256, 128, RDC_BUS_WRITE), 16);
	lt = line_time(hw, 14);
	rdc_port_idle_until(hw, lt + FETCH_CYCLES);
	assert_int_equal(span(hw, 15 * ROW, 128, RDC_BUS_WRITE), 16 + MISS);
	/* and the DP's row is the one the next fetch finds open: the fetch
	 * of line 15 right after the DP touched row 15 is a hit (16 cycles),
	 * which a DP beat at the line start waits for */
	lt = line_time(hw, 15);
	rdc_port_idle_until(hw, lt - 3);
	assert_int_equal(span(hw, 15 * ROW + 512, 8, RDC_BUS_WRITE), 1);
	rdc_port_idle_until(hw, lt);
	assert_int_equal(span(hw, 15 * ROW + 1024, 8, RDC_BUS_WRITE), 16 + 1);
}

static void test_column_waits_for_fetch_window(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint64_t lt;

	set_mode(hw, &small_mode, 0, ROW, RDC_FMT_XRGB8888);
	lt = line_time(hw, 20);
	/* three 1-beat reads one row apart from lt - 9, 7 cycles each (a
	 * beat and a miss): the first fits, the second would end at lt + 5,
	 * so it waits for the window to close */
	rdc_port_idle_until(hw, lt - 9);
	assert_int_equal(column(hw, 500 * ROW, ROW, 3, 8, RDC_BUS_READ),
			 7 + 2 + FETCH_CYCLES + 7 + 7);
	assert_int_equal(hw->perf.stall, 2 + FETCH_CYCLES);
}

static void test_vblank_faster_than_active(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t len = 64 * 1024, addr = 256 * ROW;
	uint64_t blank, active, stall, base, lines;

	set_mode(hw, &small_mode, 0, ROW, RDC_FMT_XRGB8888);
	/* by the formula: 8192 beats over 32 rows, all of them misses */
	base = len / RDC_BUS_BYTES + len / ROW * MISS;

	rdc_port_idle_until(hw, line_time(hw, ACTIVE_LINES));
	blank = span(hw, addr, len, RDC_BUS_WRITE);
	assert_int_equal(blank, base);
	assert_int_equal(hw->perf.stall, 0);

	rdc_port_idle_until(hw, line_time(hw, 60) + 30);
	active = span(hw, addr, len, RDC_BUS_WRITE);
	stall = hw->perf.stall;
	assert_true(active > blank);
	assert_true(stall > 0);
	/* every line start the span overlaps costs at most the window, a
	 * wait for it and a second row miss afterwards */
	lines = (active + 30) / LINE_CYCLES + 1;
	assert_true(stall <= lines * (FETCH_CYCLES + 16 + MISS));
	assert_true(active >= base + stall);
	assert_int_equal((active - base - stall) % MISS, 0);
	assert_true(active - base - stall <= lines * MISS);
}

/* Scanout off: no fetch windows, no contention. */
static void test_no_contention_when_scanout_off(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;

	set_mode(hw, &small_mode, 0, ROW, RDC_FMT_XRGB8888);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_port_idle_until(hw, hw->now + 5 * LINE_CYCLES);
	assert_int_equal(span(hw, 256 * ROW, 64 * 1024, RDC_BUS_WRITE),
			 64 * 1024 / RDC_BUS_BYTES + 32 * MISS);
	assert_int_equal(hw->perf.stall, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_span_costs, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_column_costs, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(
			test_random_spans_match_reference, setup,
			hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_out_of_range, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_compute_and_idle, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(
			test_burst_waits_for_fetch_window, setup,
			hw_fx_teardown),
		cmocka_unit_test_setup_teardown(
			test_column_waits_for_fetch_window, setup,
			hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_vblank_faster_than_active,
						setup, hw_fx_teardown),
		cmocka_unit_test_setup_teardown(
			test_no_contention_when_scanout_off, setup,
			hw_fx_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
