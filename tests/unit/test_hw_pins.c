// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The RDC-1's input pins.  BL_EN low darkens the panel: the frames are
 * black while it is low and show the picture again once it is high, and
 * nothing else changes (the same fetches, bus contention and cycles, the
 * same vblanks, IRQs and TE as a chip with the backlight on), down to the
 * line it changed at.  RESET_N low holds the chip in reset (reset values,
 * writes ignored, the DP idle, no frames); released, the chip draws a
 * golden scene exactly as a chip fresh from power-on does.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/param.h>

#include <cmocka.h>

#include "hw.h"
#include "rdc.h"
#include "rdc_priv.h"

#define GOLDEN_LIST    "tests/golden/golden.txt"
#define SCENE_DIR      "tests/golden/scenes"
#define W	       320
#define H	       200
#define PICTURE_COLOUR 0x00ff8000u
#define SPLIT_LINE     100u
#define FILLS	       20

static const uint32_t pins_on = RDC_PIN_RESET_N | RDC_PIN_BL_EN;

static rdc_dev *open_sim(void)
{
	rdc_dev *dev;

	assert_int_equal(rdc_open("sim:", &dev), 0);
	return dev;
}

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

static void grab(rdc_dev *dev, uint32_t *px)
{
	uint32_t w = 0, h = 0;

	assert_int_equal(rdc_frame_grab(dev, px, (size_t)W * H, &w, &h), 0);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
}

static size_t count_black(const uint32_t *px, size_t from, size_t to)
{
	size_t i, n = 0;

	for (i = from; i < to; i++)
		n += px[i] == 0;
	return n;
}

/*
 * A scene that keeps the DP busy through active scanout: full-screen
 * fills in turn, so the bus is contended by the fetches, then a picture.
 */
static void draw(rdc_dev *dev)
{
	rdc_batch *b = rdc_batch_new();
	int i;

	assert_non_null(b);
	for (i = 0; i < FILLS; i++) {
		rdc_batch_fg(b, 0x00010101u * (uint32_t)i);
		rdc_batch_fill_rect(b, 0, 0, W, H);
	}
	rdc_batch_fg(b, PICTURE_COLOUR);
	rdc_batch_fill_circle(b, W / 2, H / 2, 80);
	rdc_batch_fg(b, 0x000000ffu);
	rdc_batch_line(b, 0, 0, W - 1, H - 1);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	rdc_batch_free(b);
	assert_int_equal(rdc_finish(dev), 0);
}

/* Everything a host can observe about the chip except the picture. */
struct observed {
	uint64_t time;
	uint32_t busy_lo, stall_lo, pixels_lo, cmds, frames, irq_status,
		pins_out, status;
};

static void observe(rdc_dev *dev, struct observed *o)
{
	assert_int_equal(rdc_sim_time(dev, &o->time), 0);
	o->busy_lo = reg(dev, RDC_REG_PERF_BUSY_LO);
	o->stall_lo = reg(dev, RDC_REG_PERF_STALL_LO);
	o->pixels_lo = reg(dev, RDC_REG_PERF_PIXELS_LO);
	o->cmds = reg(dev, RDC_REG_PERF_CMDS);
	o->frames = reg(dev, RDC_REG_FRAME_COUNT);
	o->irq_status = reg(dev, RDC_REG_IRQ_STATUS);
	o->pins_out = reg(dev, RDC_REG_PINS) & (RDC_PIN_TE | RDC_PIN_IRQ);
	o->status = reg(dev, RDC_REG_STATUS);
}

static void assert_same(const struct observed *a, const struct observed *b)
{
	assert_int_equal(a->time, b->time);
	assert_int_equal(a->busy_lo, b->busy_lo);
	assert_int_equal(a->stall_lo, b->stall_lo);
	assert_int_equal(a->pixels_lo, b->pixels_lo);
	assert_int_equal(a->cmds, b->cmds);
	assert_int_equal(a->frames, b->frames);
	assert_int_equal(a->irq_status, b->irq_status);
	assert_int_equal(a->pins_out, b->pins_out);
	assert_int_equal(a->status, b->status);
}

static void setup_mode(rdc_dev *dev)
{
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL,
				       RDC_CONTROL_RESET_VALUE |
					       RDC_CONTROL_CURSOR_EN),
			 0);
}

/*
 * Two chips run the same program; one has BL_EN low.  Its frames are
 * black, every other observable is the same, and with BL_EN high again
 * its next frame is the other's picture.
 */
static void test_bl_en_dark(void **state)
{
	static uint32_t lit[W * H], dark[W * H];
	rdc_dev *a = open_sim(), *d = open_sim();
	struct observed oa, od;
	uint32_t crc_a, crc_d;

	(void)state;
	setup_mode(a);
	setup_mode(d);
	rdc_hw_set_pins(rdc_sim_hw(d), RDC_PIN_RESET_N);
	assert_int_equal(reg(d, RDC_REG_PINS) & pins_on, RDC_PIN_RESET_N);
	draw(a);
	draw(d);
	observe(a, &oa);
	observe(d, &od);
	assert_same(&oa, &od);
	/* the fills raced the beam: the fetches were charged in both */
	assert_true(oa.stall_lo > 0);

	assert_int_equal(rdc_frame_wait(a), 0);
	assert_int_equal(rdc_frame_wait(d), 0);
	grab(a, lit);
	grab(d, dark);
	assert_true(count_black(lit, 0, W * H) < W * H / 2);
	assert_int_equal(count_black(dark, 0, W * H), W * H);
	observe(a, &oa);
	observe(d, &od);
	assert_same(&oa, &od);
	assert_true(oa.irq_status & RDC_IRQ_VBLANK);

	/* backlight back on: the next whole frame is the picture */
	rdc_hw_set_pins(rdc_sim_hw(d), pins_on);
	assert_int_equal(rdc_frame_wait(a), 0);
	assert_int_equal(rdc_frame_wait(d), 0);
	assert_int_equal(rdc_frame_wait(a), 0);
	assert_int_equal(rdc_frame_wait(d), 0);
	assert_int_equal(rdc_frame_crc(a, &crc_a), 0);
	assert_int_equal(rdc_frame_crc(d, &crc_d), 0);
	assert_int_equal(crc_a, crc_d);
	grab(d, dark);
	assert_memory_equal(lit, dark, sizeof(lit));
	observe(a, &oa);
	observe(d, &od);
	assert_same(&oa, &od);
	rdc_close(a);
	rdc_close(d);
}

/*
 * BL_EN is sampled as each line starts: switched off at the start of
 * line SPLIT_LINE, the lines above it keep the picture.
 */
static void test_bl_en_mid_frame(void **state)
{
	static uint32_t px[W * H];
	rdc_dev *dev = open_sim();
	struct rdc_hw *hw = rdc_sim_hw(dev);
	uint32_t x, y;

	(void)state;
	setup_mode(dev);
	draw(dev);
	assert_int_equal(rdc_frame_wait(dev), 0);
	/* to the start of line SPLIT_LINE of the next frame */
	assert_int_equal(
		rdc_sim_run_until(dev, rdc_port_next_line(hw, SPLIT_LINE) - 1),
		0);
	rdc_hw_set_pins(hw, RDC_PIN_RESET_N);
	assert_int_equal(rdc_sim_beam(dev, &x, &y), 0);
	assert_int_equal(y, SPLIT_LINE - 1);
	/* to the end of that frame */
	assert_int_equal(rdc_sim_run_until(dev, rdc_port_next_vblank(hw)), 0);
	grab(dev, px);
	assert_true(count_black(px, 0, (size_t)SPLIT_LINE * W) <
		    (size_t)SPLIT_LINE * W / 2);
	assert_int_equal(count_black(px, (size_t)SPLIT_LINE * W, W * H),
			 (size_t)(H - SPLIT_LINE) * W);
	rdc_close(dev);
}

/* The golden line of scene `name`: its CRC and its time from power-on. */
static int golden_of(const char *name, uint32_t *crc, uint64_t *cycles)
{
	FILE *f = fopen(GOLDEN_LIST, "r");
	char line[256], n[64];
	unsigned long long c;
	unsigned int k;
	int found = -1;

	if (!f)
		return -1;
	while (found && fgets(line, sizeof(line), f)) {
		if (sscanf(line, "%63s %x %llu", n, &k, &c) == 3 &&
		    !strcmp(n, name)) {
			*crc = k;
			*cycles = c;
			found = 0;
		}
	}
	fclose(f);
	return found;
}

static void assert_reset_values(rdc_dev *dev)
{
	uint32_t st = reg(dev, RDC_REG_STATUS);

	assert_int_equal(reg(dev, RDC_REG_CONTROL), RDC_CONTROL_RESET_VALUE);
	assert_int_equal(reg(dev, RDC_REG_IRQ_ENABLE), 0);
	assert_int_equal(reg(dev, RDC_REG_IRQ_STATUS), 0);
	assert_int_equal(reg(dev, RDC_REG_FB_BASE), 0);
	assert_int_equal(reg(dev, RDC_REG_LINE_COMPARE),
			 RDC_LINE_COMPARE_RESET);
	assert_int_equal(reg(dev, RDC_REG_FIFO_FREE), RDC_FIFO_DEPTH);
	assert_int_equal(reg(dev, RDC_REG_FIFO_LOWWATER),
			 RDC_FIFO_LOWWATER_RESET);
	assert_int_equal(reg(dev, RDC_REG_PERF_CMDS), 0);
	assert_int_equal(reg(dev, RDC_REG_FRAME_COUNT), 0);
	/* the DP idle, its queue empty */
	assert_int_equal(st & (RDC_STATUS_DP_BUSY | RDC_STATUS_DP_HALTED |
			       RDC_STATUS_DP_WAIT),
			 0);
	assert_true(st & RDC_STATUS_FIFO_EMPTY);
}

static void test_reset_n(void **state)
{
	static struct rdc_script_result res;
	static uint8_t zero[1u << 20];
	rdc_dev *dev = open_sim();
	struct rdc_hw *hw = rdc_sim_hw(dev);
	uint32_t crc = 0, want_crc = 0, vram = reg(dev, RDC_REG_VRAM_SIZE);
	uint64_t t0, t1, want_cycles = 0, a;
	const uint32_t fill[] = {
		RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
		RDC_XY(0, 0),
		RDC_WH(W, H),
	};

	(void)state;
	assert_int_equal(golden_of("circles", &want_crc, &want_cycles), 0);
	setup_mode(dev);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_LINE_COMPARE, 7), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_BASE, 4096), 0);
	/* the DP in the middle of work when the reset comes */
	for (a = 0; a < 8; a++)
		rdc_hw_fifo_push(hw, fill, 3);
	assert_int_equal(rdc_sim_step(dev, 1000), 0);
	assert_true(reg(dev, RDC_REG_FIFO_FREE) < RDC_FIFO_DEPTH);

	rdc_hw_set_pins(hw, RDC_PIN_BL_EN);
	assert_int_equal(reg(dev, RDC_REG_PINS),
			 RDC_PIN_BL_EN); /* TE, IRQ low; RESET_N low */
	assert_reset_values(dev);
	/* held: writes are ignored, the DP and scanout do not run */
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, RDC_IRQ_ALL),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_BASE, 8192), 0);
	assert_int_equal(rdc_hw_fifo_push(hw, fill, 3), 3);
	assert_int_equal(rdc_sim_step(dev, 3000000), 0);
	assert_reset_values(dev);
	assert_null(rdc_hw_frame(hw, NULL, NULL));

	/* released: reset again, then a golden scene as from power-on */
	rdc_hw_set_pins(hw, pins_on);
	assert_int_equal(reg(dev, RDC_REG_PINS) & pins_on, pins_on);
	assert_reset_values(dev);
	assert_int_equal(rdc_sim_time(dev, &t0), 0);
	for (a = 0; a < vram; a += sizeof(zero))
		assert_int_equal(rdc_vram_write(dev, (uint32_t)a, zero,
						MIN(sizeof(zero), vram - a)),
				 0);
	assert_int_equal(
		rdc_script_run_file(dev, SCENE_DIR "/circles.rdl", &res), 0);
	assert_int_equal(rdc_sim_time(dev, &t1), 0);
	assert_int_equal(rdc_script_frame_wait(dev, &res), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	assert_int_equal(crc, want_crc);
	assert_int_equal(t1 - t0, want_cycles);
	rdc_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_bl_en_dark),
		cmocka_unit_test(test_bl_en_mid_frame),
		cmocka_unit_test(test_reset_n),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
