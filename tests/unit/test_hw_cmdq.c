// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Command queues: the FIFO (overflow, low-water interrupt, fetch cost),
 * the VRAM ring (validation, wrap, fetch cost through the bus model) and
 * the readback FIFO.
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

static int setup(void **state)
{
	struct hw_fx *f;

	if (hw_fx_setup(state, VRAM_SIZE, FRAME_CAP))
		return -1;
	f = *state;
	/* no scanout: fetch costs are the bare formulas */
	rdc_hw_write(&f->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(&f->hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	return 0;
}

static void test_fifo_overflow(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint32_t i, w[RDC_FIFO_DEPTH];

	for (i = 0; i < RDC_FIFO_DEPTH; i++) {
		assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE),
				 RDC_FIFO_DEPTH - i);
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, 1000 + i);
	}
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE), 0);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_FIFO_FULL);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_FIFO_EMPTY);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, 0xdead);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE),
			 RDC_ERR_FIFO_OVERFLOW);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), RDC_REG_FIFO_DATA);
	assert_true(rdc_hw_read(hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR);
	/* the word was dropped: the DP gets exactly the first 256 */
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_FIFO), RDC_FIFO_DEPTH);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 1000),
			 RDC_FIFO_DEPTH);
	for (i = 0; i < RDC_FIFO_DEPTH; i++)
		assert_int_equal(w[i], 1000 + i);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 1), 0);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_FIFO_EMPTY);
}

static void test_fifo_fetch_cost_and_order(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint32_t w[8], i, t0;

	/* wrap the FIFO's internal index around a few times */
	for (i = 0; i < 3 * RDC_FIFO_DEPTH / 2; i++) {
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, i);
		assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 1), 1);
		assert_int_equal(w[0], i);
	}
	for (i = 0; i < 5; i++)
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, 50 + i);
	t0 = (uint32_t)hw->now;
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 3), 3);
	assert_int_equal(hw->now - t0, 3 * RDC_T_FIFO_WORD);
	assert_int_equal(w[0], 50);
	assert_int_equal(w[2], 52);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 8), 2);
	assert_int_equal(w[1], 54);
	/* popping nothing costs nothing */
	t0 = (uint32_t)hw->now;
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 8), 0);
	assert_int_equal(hw->now, t0);
	/* unknown source */
	assert_int_equal(rdc_port_cmd_avail(hw, 7), 0);
	assert_int_equal(rdc_port_cmd_pop(hw, 7, w, 8), 0);
}

static void test_fifo_lowwater(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint32_t w[16], i;

	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 4);
	for (i = 0; i < 10; i++)
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, i);
	/* pushing never raises it */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 5); /* 10 -> 5 */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 1); /* 5 -> 4: falls to it */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_FIFO_LOW);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_FIFO_LOW);
	/* below the mark already: no new edge */
	rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 2);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), 0);
	/* refill above it, then one pop crossing from 6 straight to 1 */
	for (i = 0; i < 4; i++)
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, i);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_FIFO_FREE),
			 RDC_FIFO_DEPTH - 6);
	rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 5);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_IRQ_STATUS), RDC_IRQ_FIFO_LOW);
	/* and it drives the pin when enabled */
	rdc_hw_write(hw, RDC_REG_IRQ_ENABLE, RDC_IRQ_FIFO_LOW);
	assert_true(rdc_hw_pins(hw) & RDC_PIN_IRQ);
}

static void ring_program(struct rdc_hw *hw, uint32_t base, uint32_t size,
			 uint32_t head, uint32_t tail)
{
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(hw, RDC_REG_RING_BASE, base);
	rdc_hw_write(hw, RDC_REG_RING_SIZE, size);
	rdc_hw_write(hw, RDC_REG_RING_HEAD, head);
	rdc_hw_write(hw, RDC_REG_RING_TAIL, tail);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
}

static void expect_ring_error(struct rdc_hw *hw)
{
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_RING);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 0);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
}

static void test_ring_validation(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	uint32_t w[4];

	ring_program(hw, 0x1002, 64, 0, 8); /* base not 4-aligned */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 62, 0, 8); /* size not a word multiple */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 12, 0, 8); /* smaller than 16 bytes */
	expect_ring_error(hw);
	ring_program(hw, VRAM_SIZE - 60, 64, 0, 8); /* leaves VRAM */
	expect_ring_error(hw);
	ring_program(hw, 0xfffffff0u, 0x20, 0, 8); /* 32-bit wrap */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 64, 64, 8); /* head out of the ring */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 64, 2, 8); /* head unaligned */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 64, 0, 68); /* tail out of the ring */
	expect_ring_error(hw);
	ring_program(hw, 0x1000, 64, 0, 9); /* tail unaligned */
	expect_ring_error(hw);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 4), 0);

	/* valid: no error, two words */
	ring_program(hw, 0x1000, 64, 0, 8);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 2);
	/* a bad TAIL while running stops the ring ... */
	rdc_hw_write(hw, RDC_REG_RING_TAIL, 100);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_INFO), RDC_REG_RING_TAIL);
	expect_ring_error(hw);
	/* ... until reprogrammed */
	rdc_hw_write(hw, RDC_REG_RING_TAIL, 12);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 3);
	/* HEAD belongs to the DP while the ring runs */
	rdc_hw_write(hw, RDC_REG_RING_HEAD, 4);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_REG);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RING_HEAD), 0);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	/* disabled ring: no words */
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 0);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_RING_EMPTY);
}

static void put_words(struct hw_fx *f, uint32_t addr, uint32_t first,
		      uint32_t n)
{
	uint32_t i;

	for (i = 0; i < n; i++) {
		uint32_t v = first + i;

		f->vram[addr + 4 * i] = (uint8_t)v;
		f->vram[addr + 4 * i + 1] = (uint8_t)(v >> 8);
		f->vram[addr + 4 * i + 2] = (uint8_t)(v >> 16);
		f->vram[addr + 4 * i + 3] = (uint8_t)(v >> 24);
	}
}

static void test_ring_wrap_and_cost(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	const uint32_t base = 3 * RDC_DRAM_ROW_BYTES, size = 64;
	uint32_t w[16];
	uint64_t t0;

	/* 16 words in the ring; head at word 12, tail at word 4: words
	 * 12..15 then 0..3 (8 words) wait, in that order */
	put_words(f, base, 100, 16);
	ring_program(hw, base, size, 48, 16);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 8);
	assert_false(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_RING_EMPTY);

	/* 2 words at byte 48: one beat (8 bytes), row 3 not open: a miss */
	t0 = hw->now;
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 2), 2);
	assert_int_equal(hw->now - t0, 1 + RDC_T_ROW_MISS);
	assert_int_equal(w[0], 112);
	assert_int_equal(w[1], 113);
	/* the next 4 wrap: bytes 56..63 (1 beat) then 0..7 (1 beat), both
	 * in the open row: two reads, no miss */
	t0 = hw->now;
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 4), 4);
	assert_int_equal(hw->now - t0, 2);
	assert_int_equal(w[0], 114);
	assert_int_equal(w[1], 115);
	assert_int_equal(w[2], 100);
	assert_int_equal(w[3], 101);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RING_HEAD), 8);
	/* ask for more than there is */
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 16), 2);
	assert_int_equal(w[1], 103);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 0);
	assert_true(rdc_hw_read(hw, RDC_REG_STATUS) & RDC_STATUS_RING_EMPTY);
	/* the host adds words behind the head by moving TAIL */
	rdc_hw_write(hw, RDC_REG_RING_TAIL, 40);
	assert_int_equal(rdc_port_cmd_avail(hw, RDC_SRC_RING), 6);
	assert_int_equal(rdc_port_cmd_pop(hw, RDC_SRC_RING, w, 16), 6);
	assert_int_equal(w[0], 104);
	assert_int_equal(w[5], 109);
}

static void test_rdata(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	static uint32_t words[RDC_RDATA_DEPTH + 10];
	uint32_t i;

	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA), 0); /* empty */
	assert_int_equal(rdc_hw_read(hw, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	assert_int_equal(rdc_port_rdata_space(hw), RDC_RDATA_DEPTH);
	for (i = 0; i < RDC_RDATA_DEPTH + 10; i++)
		words[i] = 0x1000 + i;
	assert_int_equal(rdc_port_rdata_push(hw, words, 3), 3);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA_COUNT), 3);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA), 0x1000);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA_COUNT), 2);
	/* fill up: only what fits is taken */
	assert_int_equal(rdc_port_rdata_push(hw, words + 3,
					     RDC_RDATA_DEPTH + 5),
			 RDC_RDATA_DEPTH - 2);
	assert_int_equal(rdc_port_rdata_space(hw), 0);
	assert_int_equal(rdc_port_rdata_push(hw, words, 1), 0);
	for (i = 1; i <= RDC_RDATA_DEPTH; i++)
		assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA), 0x1000 + i);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA_COUNT), 0);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA), 0);
	/* reset empties it */
	rdc_port_rdata_push(hw, words, 5);
	rdc_hw_write(hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	assert_int_equal(rdc_hw_read(hw, RDC_REG_RDATA_COUNT), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_fifo_overflow, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fifo_fetch_cost_and_order,
						setup, hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fifo_lowwater, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_ring_validation, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_ring_wrap_and_cost, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_rdata, setup,
						hw_fx_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
