// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * CONTROL.GAMMA_EN: a random CLUT and a random frame in each direct-colour
 * format (RGB565, RGB888, XRGB8888 and ARGB8888, its alias) against a
 * software reference that decodes the bytes from the format definitions
 * and looks each component up in its own channel; with the bit clear the
 * plain conversion; indexed formats the same either way.  The bit is
 * latched at vblank, CLUT writes reach the gamma as they reach a palette
 * (at once, or at vblank with CLUT_LATCH), and the lookups take no bus
 * time.  Dark and missing lines stay black.
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
#define SCR_W	  56u
#define SCR_H	  40u
#define FRAME_CAP (SCR_W * SCR_H)

struct fx {
	struct hw_fx sim;
	uint32_t lut[RDC_CLUT_ENTRIES];
	uint32_t seed;
};

static int setup(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));

	if (!f || hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP)) {
		free(f);
		return -1;
	}
	f->seed = 0x9e3779b9u;
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

static uint32_t stride_of(uint32_t fmt)
{
	return (SCR_W * rdc_format_bpp(fmt) / 8 + 3) & ~3u;
}

/* SCR_W x SCR_H in `fmt` at VRAM `base`, 10 core cycles a pixel. */
static void start_mode(struct rdc_hw *hw, uint32_t fmt, uint32_t base)
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
	rdc_hw_write(hw, RDC_REG_FB_BASE, base);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, stride_of(fmt));
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, fmt);
	rdc_hw_write(hw, RDC_REG_CONTROL, ctl);
	/* the reset mode did not fit FRAME_CAP: error MODE, cleared */
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

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

static const uint32_t *grab_settled(struct rdc_hw *hw)
{
	grab(hw);
	return grab(hw);
}

static void random_clut(struct fx *f)
{
	rdc_hw_write(&f->sim.hw, RDC_REG_CLUT_INDEX, 0);
	for (uint32_t i = 0; i < RDC_CLUT_ENTRIES; i++) {
		f->lut[i] = rnd(f) & 0xffffff;
		rdc_hw_write(&f->sim.hw, RDC_REG_CLUT_DATA, f->lut[i]);
	}
}

static void random_vram(struct fx *f, uint32_t base, uint32_t bytes)
{
	for (uint32_t i = 0; i < bytes; i++)
		f->sim.vram[base + i] = (uint8_t)rnd(f);
}

/*
 * Pixel (x, y) of the frame at `base` as rdc_regs.h defines the format:
 * 0x00RRGGBB, 5- and 6-bit components widened by repeating their top
 * bits; indexed pixels through `lut`.
 */
static uint32_t decode(const struct fx *f, uint32_t base, uint32_t fmt,
		       uint32_t x, uint32_t y)
{
	const uint8_t *l = f->sim.vram + base + y * stride_of(fmt);
	uint32_t v, r, g, b;

	switch (fmt) {
	case RDC_FMT_RGB565:
		v = l[2 * x] | (uint32_t)l[2 * x + 1] << 8;
		r = v >> 11;
		g = (v >> 5) & 0x3f;
		b = v & 0x1f;
		r = r << 3 | r >> 2;
		g = g << 2 | g >> 4;
		b = b << 3 | b >> 2;
		return r << 16 | g << 8 | b;
	case RDC_FMT_RGB888:
		return (uint32_t)l[3 * x + 2] << 16 |
		       (uint32_t)l[3 * x + 1] << 8 | l[3 * x];
	case RDC_FMT_XRGB8888:
		return (uint32_t)l[4 * x + 2] << 16 |
		       (uint32_t)l[4 * x + 1] << 8 | l[4 * x];
	case RDC_FMT_I8:
		return f->lut[l[x]];
	case RDC_FMT_I4:
		return f->lut[x % 2 ? l[x / 2] & 0xf : l[x / 2] >> 4];
	default:
		fail_msg("format %u", fmt);
		return 0;
	}
}

/* The red of the entry red indexes, and so on. */
static uint32_t ref_gamma(const uint32_t *lut, uint32_t rgb)
{
	uint32_t r = (lut[(rgb >> 16) & 0xff] >> 16) & 0xff;
	uint32_t g = (lut[(rgb >> 8) & 0xff] >> 8) & 0xff;
	uint32_t b = lut[rgb & 0xff] & 0xff;

	return r << 16 | g << 8 | b;
}

static void check(const struct fx *f, const uint32_t *p, uint32_t base,
		  uint32_t fmt, bool on)
{
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++) {
			uint32_t want = decode(f, base, fmt, x, y);

			if (on && !rdc_format_indexed(fmt))
				want = ref_gamma(f->lut, want);
			if (p[y * SCR_W + x] != want)
				fail_msg("format %u gamma %d: (%u, %u) is "
					 "%06x, want %06x",
					 fmt, on, x, y, p[y * SCR_W + x], want);
		}
}

static void test_formats(void **state)
{
	static const uint32_t fmts[] = {
		RDC_FMT_RGB565,	  RDC_FMT_RGB888, RDC_FMT_XRGB8888,
		RDC_FMT_ARGB8888, RDC_FMT_I8,	  RDC_FMT_I4,
	};
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t base = 0x1000;

	for (size_t i = 0; i < sizeof(fmts) / sizeof(fmts[0]); i++) {
		random_clut(f);
		random_vram(f, base, SCR_H * stride_of(fmts[i]));
		rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
		start_mode(hw, fmts[i], base);
		check(f, grab_settled(hw), base, fmts[i], false);
		rdc_hw_write(hw, RDC_REG_CONTROL,
			     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_GAMMA_EN);
		assert_int_equal(rdc_hw_read(hw, RDC_REG_CONTROL),
				 RDC_CONTROL_RESET_VALUE |
					 RDC_CONTROL_GAMMA_EN);
		check(f, grab_settled(hw), base, fmts[i], true);
		/* and back */
		rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
		check(f, grab_settled(hw), base, fmts[i], false);
	}
}

/*
 * GAMMA_EN in the middle of a frame takes effect at its vblank; a CLUT
 * write in the middle of a frame changes the lines fetched after it, or
 * with CLUT_LATCH the next frame.
 */
static void test_latch_and_clut_writes(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t fmt = RDC_FMT_RGB888, on = RDC_CONTROL_GAMMA_EN;
	const uint32_t *p;
	uint32_t old;

	random_clut(f);
	random_vram(f, 0, SCR_H * stride_of(fmt));
	start_mode(hw, fmt, 0);
	grab_settled(hw);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 17));
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE | on);
	check(f, grab(hw), 0, fmt, false);
	check(f, grab(hw), 0, fmt, true);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 23));
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE);
	check(f, grab(hw), 0, fmt, true);
	check(f, grab(hw), 0, fmt, false);

	/* all red components 0x40 from line 25 on: entry 0x40's red */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RESET_VALUE | on);
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++)
			f->sim.vram[y * stride_of(fmt) + 3 * x + 2] = 0x40;
	grab_settled(hw);
	old = f->lut[0x40];
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 25));
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0x40);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x00a1b2c3);
	p = grab(hw);
	for (uint32_t y = 0; y < SCR_H; y++)
		assert_int_equal(p[y * SCR_W + 5] >> 16,
				 y <= 25 ? (old >> 16) & 0xff : 0xa1);
	f->lut[0x40] = 0x00a1b2c3;
	check(f, grab(hw), 0, fmt, true);

	/* latched palette writes: the whole next frame */
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | on | RDC_CONTROL_CLUT_LATCH);
	rdc_hw_run_until(hw, rdc_port_next_line(hw, 25));
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0x40);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x00102030);
	check(f, grab(hw), 0, fmt, true);
	f->lut[0x40] = 0x00102030;
	check(f, grab(hw), 0, fmt, true);
}

/* Black stays black: a dark panel, and lines that leave VRAM. */
static void test_black(void **state)
{
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t fmt = RDC_FMT_XRGB8888;
	const uint32_t base = VRAM_SIZE - 10 * stride_of(fmt);
	const uint32_t *p;

	random_clut(f);
	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
	rdc_hw_write(hw, RDC_REG_CLUT_DATA, 0x00ffffff);
	f->lut[0] = 0xffffff;
	random_vram(f, base, 10 * stride_of(fmt));
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_GAMMA_EN);
	start_mode(hw, fmt, base);
	p = grab_settled(hw);
	for (uint32_t y = 0; y < SCR_H; y++)
		for (uint32_t x = 0; x < SCR_W; x++)
			assert_int_equal(
				p[y * SCR_W + x],
				y < 10 ? ref_gamma(f->lut,
						   decode(f, base, fmt, x, y)) :
					 0);
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N); /* BL_EN low */
	p = grab_settled(hw);
	for (uint32_t i = 0; i < SCR_W * SCR_H; i++)
		assert_int_equal(p[i], 0);
}

/*
 * docs/hardware.md's read cost from the model's words: bursts split at
 * multiples of 128 bytes, a cycle a beat of 8 bytes, 6 more for a burst
 * in another 2048-byte row than the open one.
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

/* The lookups are the CLUT's, on the chip: the fetch is all the bus sees. */
static void test_no_bus_time(void **state)
{
	static const uint32_t fmts[] = { RDC_FMT_RGB565, RDC_FMT_RGB888,
					 RDC_FMT_XRGB8888 };
	struct fx *f = *state;
	struct rdc_hw *hw = &f->sim.hw;
	const uint32_t base = 0x700;

	for (size_t i = 0; i < 3; i++) {
		uint32_t s = stride_of(fmts[i]),
			 bytes = SCR_W * rdc_format_bpp(fmts[i]) / 8;

		rdc_hw_write(hw, RDC_REG_CONTROL,
			     RDC_CONTROL_RESET_VALUE | RDC_CONTROL_GAMMA_EN);
		start_mode(hw, fmts[i], base);
		grab_settled(hw);
		for (uint32_t n = 1; n < SCR_H; n += 3) {
			uint32_t row = (base + (n - 1) * s + bytes - 1) / 2048;
			uint64_t before, want;

			want = read_cost(&row, base + (uint64_t)n * s, bytes);
			rdc_port_idle_until(hw, rdc_port_next_line(hw, n));
			before = rdc_hw_read(hw, RDC_REG_PERF_STALL_LO);
			assert_non_null(
				rdc_port_span(hw, 0x80000, 8, RDC_BUS_READ));
			assert_int_equal(
				rdc_hw_read(hw, RDC_REG_PERF_STALL_LO) - before,
				want);
		}
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_formats, setup, teardown),
		cmocka_unit_test_setup_teardown(test_latch_and_clut_writes,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_black, setup, teardown),
		cmocka_unit_test_setup_teardown(test_no_bus_time, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
