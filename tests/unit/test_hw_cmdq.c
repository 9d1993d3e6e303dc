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

static void no_trace(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		     uint32_t b)
{
	(void)ctx;
	(void)time;
	(void)event;
	(void)a;
	(void)b;
}

/*
 * A whole command in one pop against its header and then the rest in two
 * (on a twin chip): the same words, cycles and low-water interrupt, or
 * nothing popped where the two pops would differ from one.
 */
static void test_fifo_pop_whole(void **state)
{
	struct hw_fx *f = *state, twin;
	struct rdc_hw *hw = &f->hw, *tw = &twin.hw;
	uint32_t w[8], v[8], i;
	const uint32_t cmd[] = { RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
				 11,
				 22,
				 RDC_CMD(RDC_OP_SET_FG, 0, 1),
				 33,
				 RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
				 44,
				 55,
				 RDC_CMD(RDC_OP_SET_FG, 0, 1),
				 66 };

	assert_int_equal(hw_fx_init(&twin, VRAM_SIZE, FRAME_CAP), 0);
	rdc_hw_write(tw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(tw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	/* 10 words; low-water 7: the second command's header crosses it */
	for (i = 0; i < RDC_ARRAY_SIZE(cmd); i++) {
		rdc_hw_write(hw, RDC_REG_FIFO_DATA, cmd[i]);
		rdc_hw_write(tw, RDC_REG_FIFO_DATA, cmd[i]);
	}
	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 7);
	rdc_hw_write(tw, RDC_REG_FIFO_LOWWATER, 7);

	/* whole: 10 -> 7, the mark reached by the last argument word */
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 3);
	assert_int_equal(rdc_port_cmd_pop(tw, RDC_SRC_FIFO, v, 1), 1);
	assert_int_equal(rdc_port_cmd_pop(tw, RDC_SRC_FIFO, v + 1, 2), 2);
	assert_memory_equal(w, cmd, 3 * sizeof(*w));
	assert_memory_equal(v, cmd, 3 * sizeof(*v));
	assert_int_equal(hw->now, tw->now);
	assert_int_equal(hw->now, 3 * RDC_T_FIFO_WORD);
	assert_int_equal(hw->irq_status, RDC_IRQ_FIFO_LOW);
	assert_int_equal(tw->irq_status, RDC_IRQ_FIFO_LOW);
	rdc_hw_write(hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	rdc_hw_write(tw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);

	/* more than max_args: left to the header pop */
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 0), 0);
	assert_int_equal(hw->fifo_count, 7);
	/* traced: every pop is the tracer's event, so two of them */
	rdc_hw_set_trace(hw, no_trace, NULL);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 0);
	rdc_hw_set_trace(hw, NULL, NULL);
	assert_int_equal(hw->now, tw->now);
	assert_int_equal(hw->fifo_count, 7);

	/* 7 -> 5 below the mark already: no edge either way */
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 2);
	assert_int_equal(rdc_port_cmd_pop(tw, RDC_SRC_FIFO, v, 2), 2);
	assert_int_equal(w[1], 33);
	assert_int_equal(hw->now, tw->now);
	assert_int_equal(hw->irq_status, 0);

	/* refill to 9 with the mark at 8: the header's pop would cross it */
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, cmd[3]);
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, cmd[4]);
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, cmd[0]);
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, cmd[1]);
	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 8);
	assert_int_equal(hw->fifo_count, 9);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 0);
	assert_int_equal(hw->fifo_count, 9);
	assert_int_equal(hw->irq_status, 0);
	rdc_hw_write(hw, RDC_REG_FIFO_LOWWATER, 4);
	/* 9 -> 6 (FILL_RECT 44 55), 6 -> 4 (SET_FG 66) */
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 3);
	assert_int_equal(w[1], 44);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 2);
	assert_int_equal(w[1], 66);
	assert_int_equal(hw->irq_status, RDC_IRQ_FIFO_LOW);
	/* 4 words: SET_FG 33, then a FILL_RECT short of its last word */
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 2);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 0);
	assert_int_equal(hw->fifo_count, 2);
	rdc_port_cmd_pop(hw, RDC_SRC_FIFO, w, 2);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 0);
	hw_fx_fini(&twin);
}

#define SCAN_CAP (1024u * 768u) /* frames for any preset */

/* With scanout on: not when a line starts during the fetch. */
static void test_fifo_pop_whole_scanout(void **state)
{
	struct hw_fx *f = *state;
	struct rdc_hw *hw = &f->hw;
	struct rdc_hw_config cfg = { .vram_size = VRAM_SIZE };
	uint32_t *f0 = calloc(SCAN_CAP, 4), *f1 = calloc(SCAN_CAP, 4);
	uint32_t w[4];
	uint64_t line;

	assert_non_null(f0);
	assert_non_null(f1);
	/* the fixture's frames are too small for a preset: its own */
	rdc_hw_init(hw, &cfg, f->vram, f0, f1, SCAN_CAP);
	rdc_hw_write(hw, RDC_REG_MODE_PRESET, RDC_PRESET_320x200_70);
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, RDC_FMT_I8);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, 320);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_true(hw->crtc.running);
	/* past the first line's start, then up to two words' time before
	 * the next one */
	rdc_port_idle_until(hw, hw->now + 1);
	line = hw->crtc.next_line_time;
	assert_true(line > hw->now + 3 * RDC_T_FIFO_WORD);
	rdc_port_idle_until(hw, line - 3 * RDC_T_FIFO_WORD);
	assert_int_equal(hw->crtc.next_line_time, line);
	/* two words end a word before the line start: whole */
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, RDC_CMD(RDC_OP_SET_FG, 0, 1));
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, 7);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 2);
	assert_int_equal(w[1], 7);
	assert_int_equal(hw->now, line - RDC_T_FIFO_WORD);
	assert_int_equal(hw->crtc.next_line_time, line);
	/* two more would end a word after it: left to the two pops */
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, RDC_CMD(RDC_OP_SET_FG, 0, 1));
	rdc_hw_write(hw, RDC_REG_FIFO_DATA, 8);
	assert_int_equal(rdc_port_cmd_pop_whole(hw, w, 4), 0);
	assert_int_equal(hw->fifo_count, 2);
	assert_int_equal(hw->now, line - RDC_T_FIFO_WORD);
	free(f0);
	free(f1);
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
		cmocka_unit_test_setup_teardown(test_fifo_pop_whole, setup,
						hw_fx_teardown),
		cmocka_unit_test_setup_teardown(test_fifo_pop_whole_scanout,
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
