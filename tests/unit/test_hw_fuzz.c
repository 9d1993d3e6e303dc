// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Hostile programming: seeded random register writes and reads, pin
 * changes, DP port calls with wild arguments and runs of simulated time.
 * The chip must survive all of it (ASan and UBSan watch every access),
 * never move time backwards, and keep its queues and frames in bounds.
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

#define VRAM_SIZE (1u << 20)	/* 640x480 XRGB8888 leaves it: black lines */
#define FRAME_CAP (640u * 480u) /* the reset mode fits */

struct fx {
	struct hw_fx sim;
	uint32_t seed;
	uint64_t frames;
};

static uint32_t rnd(struct fx *f)
{
	f->seed = f->seed * 1664525u + 1013904223u;
	return f->seed >> 8 | (f->seed << 24);
}

/* Mostly small or edge values, sometimes anything. */
static uint32_t value(struct fx *f)
{
	static const uint32_t edge[] = {
		0,
		1,
		2,
		3,
		4,
		16,
		255,
		256,
		640,
		4095,
		4096,
		4097,
		VRAM_SIZE - 4,
		VRAM_SIZE,
		0x7fffffff,
		0x80000000u,
		0xfffffffcu,
		0xffffffffu,
	};
	uint32_t r = rnd(f);

	switch (r % 4) {
	case 0:
		return edge[rnd(f) % (sizeof(edge) / sizeof(edge[0]))];
	case 1:
		return rnd(f) % 64;
	case 2:
		return rnd(f) % 4096;
	default:
		return rnd(f);
	}
}

static void on_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t n)
{
	struct fx *f = ctx;

	assert_non_null(xrgb);
	assert_true((uint64_t)w * h <= FRAME_CAP);
	assert_true(w >= 1 && h >= 1);
	/* touch the last pixel: ASan checks the buffer really holds it */
	assert_true(xrgb[w * h - 1] <= 0x00ffffffu);
	assert_int_equal(n, f->frames);
	f->frames++;
}

static void one_op(struct fx *f)
{
	struct rdc_hw *hw = &f->sim.hw;
	uint32_t op = rnd(f) % 16, reg, w[8];
	uint8_t buf[64];

	/* a register offset: usually one of the map's, sometimes not */
	reg = rnd(f) % 3 ? (rnd(f) % (RDC_REG_WINDOW / 4)) * 4 : rnd(f);
	switch (op) {
	case 0:
	case 1:
	case 2:
		if (reg == RDC_REG_CONTROL)
			/* keep RESET rare so that time gets to pass */
			rdc_hw_write(hw, reg,
				     value(f) &
					     ~(rnd(f) % 64 ?
						       RDC_CONTROL_SOFT_RESET :
						       0));
		else
			rdc_hw_write(hw, reg, value(f));
		break;
	case 3:
		rdc_hw_read(hw, reg);
		break;
	case 4:
		rdc_hw_write(hw, RDC_REG_MODE_PRESET,
			     rnd(f) % 2 ? RDC_PRESET_320x200_70 : value(f));
		rdc_hw_write(hw, RDC_REG_CONTROL,
			     RDC_CONTROL_RESET_VALUE |
				     (value(f) & GENMASK(5, 2)));
		break;
	case 5:
		rdc_hw_run_until(hw, hw->now + rnd(f) % 200000);
		break;
	case 6: {
		uint8_t *p = rdc_port_span(hw, value(f), value(f), rnd(f) % 16);

		if (p)
			*p ^= 1; /* must be in VRAM */
		break;
	}
	case 7: {
		uint32_t count = value(f), len = value(f);
		uint8_t *p;

		/* bound the work, not the range check */
		if (count > 4096)
			count = rnd(f) % 2 ? count : 4096;
		p = rdc_port_column(hw, value(f), value(f),
				    count > 100000 ? 100000 : count, len,
				    rnd(f) % 16);
		if (p)
			*p ^= 2;
		break;
	}
	case 8:
		rdc_port_cmd_pop(hw, rnd(f) % 3, w, rnd(f) % 9);
		break;
	case 9:
		rdc_port_rdata_push(hw, w, rnd(f) % 9);
		break;
	case 10:
		rdc_port_clut_write(hw, value(f), value(f));
		break;
	case 11:
		rdc_port_reg_write(hw, reg, value(f));
		break;
	case 12:
		rdc_hw_set_pins(hw, rnd(f) % 64 ? value(f) | RDC_PIN_RESET_N :
						  value(f));
		break;
	case 13:
		rdc_hw_vram_write(hw, value(f), buf, rnd(f) % 64);
		rdc_hw_vram_read(hw, value(f), buf, rnd(f) % 64);
		break;
	case 14:
		rdc_port_idle_until(hw, hw->now + rnd(f) % 50000);
		rdc_port_next_line(hw, value(f));
		rdc_port_next_vblank(hw);
		break;
	default:
		rdc_port_compute(hw, rnd(f) % 3000);
		rdc_port_irq(hw, value(f));
		if (rnd(f) % 8 == 0)
			rdc_port_error(hw, value(f), value(f));
		break;
	}
}

static void test_random_programming(void **state)
{
	struct fx *f = calloc(1, sizeof(*f));
	struct rdc_hw *hw;
	uint32_t seed;

	(void)state;
	assert_non_null(f);
	assert_int_equal(hw_fx_init(&f->sim, VRAM_SIZE, FRAME_CAP), 0);
	hw = &f->sim.hw;
	for (seed = 1; seed <= 12; seed++) {
		uint64_t last = 0;
		int i;

		f->seed = seed;
		f->frames = 0;
		hw_fx_reinit(&f->sim);
		rdc_hw_set_frame_fn(hw, seed % 2 ? on_frame : NULL, f);
		for (i = 0; i < 3000; i++) {
			const uint32_t *p;
			uint32_t fw, fh;

			one_op(f);
			assert_true(hw->now >= last);
			last = hw->now;
			assert_true(hw->fifo_count <= RDC_FIFO_DEPTH);
			assert_true(hw->rdata_count <= RDC_RDATA_DEPTH);
			assert_true(hw->clut_index < RDC_CLUT_ENTRIES);
			assert_int_equal(rdc_hw_read(hw, RDC_REG_ID),
					 RDC_ID_VALUE);
			p = rdc_hw_frame(hw, &fw, &fh);
			if (p)
				assert_true((uint64_t)fw * fh <= FRAME_CAP);
			/* frame numbers restart with a reset */
			f->frames = hw->crtc.frame_count;
		}
	}
	hw_fx_fini(&f->sim);
	free(f);
}

/* No VRAM and no frame buffers: nothing to scan out or draw, no crash. */
static void test_no_memory(void **state)
{
	struct rdc_hw *hw = calloc(1, sizeof(*hw));
	struct rdc_hw_config cfg = { .vram_size = VRAM_SIZE };
	uint8_t b[4] = { 0 };
	uint32_t w[4];

	(void)state;
	assert_non_null(hw);
	rdc_hw_init(hw, &cfg, NULL, NULL, NULL, FRAME_CAP);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_VRAM_SIZE), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_MODE);
	assert_int_equal(rdc_port_next_vblank(hw), RDC_NEVER);
	rdc_hw_run_until(hw, 10000000);
	assert_null(rdc_hw_frame(hw, NULL, NULL));
	assert_null(rdc_port_span(hw, 0, 1, RDC_BUS_WRITE));
	assert_null(rdc_port_column(hw, 0, 0, 1, 1, RDC_BUS_WRITE));
	assert_int_equal(rdc_hw_vram_write(hw, 0, b, 1), -1);
	assert_int_equal(rdc_hw_vram_write(hw, 0, b, 0), 0);
	assert_int_equal(rdc_hw_vram_read(hw, 0, b, 0), 0);
	rdc_hw_write(hw, RDC_REG_RING_SIZE, 16);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_RING_EN);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_RING);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 4), 0);
	free(hw);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_random_programming),
		cmocka_unit_test(test_no_memory),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
