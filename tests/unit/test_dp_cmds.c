// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The command decoder: bad input of every kind (nothing outside the target
 * touched, ERR_CODE/ERR_INFO/IRQ_STATUS right, skip versus halt), control
 * commands, the queues (FIFO back-pressure, the VRAM ring, READBACK larger
 * than RDATA), and exact cycle counts derived from bus.h's formulas.
 */
#include "test_dp_common.h"

static const struct rdc_surface scr = { 0, 640 * 4, 640, 480,
					RDC_FMT_XRGB8888 };

/* Reset state: FG all ones, COPY, no clip, DST = the 640x480 screen. */
static void test_reset_state(void **state)
{
	struct tdp *t = *state;
	const uint32_t end = 640 * 480 * 4;
	uint32_t i;

	for (i = 0; i < 2; i++) {
		memset(t->vram, 0x5a, end + 64);
		TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(-100, -100),
			RDC_WH(RDC_SIZE_MAX, RDC_SIZE_MAX));
		tdp_drain(t);
		assert_int_equal(t->vram[0], 0xff);
		assert_int_equal(t->vram[end - 1], 0xff);
		assert_int_equal(t->vram[end], 0x5a);
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO),
				 640 * 480);
		/* change everything, then a soft reset restores it */
		TDP_CMD(t, RDC_OP_SET_FG, 3);
		TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
		TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(1, 1), RDC_XY(2, 2));
		TDP_CMD(t, RDC_OP_SET_DST, 0x200000, 16, RDC_WH(16, 16),
			RDC_FMT_I8);
		tdp_drain(t);
		rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
		rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	}
}

/* ---- bad input ------------------------------------------------------- */

/*
 * Feed words, expect `err` with the given header in ERR_INFO, and VRAM
 * exactly as before (guard: the whole of it).
 */
static void expect_error(struct tdp *t, const uint32_t *w, unsigned int n,
			 uint32_t err, uint32_t hdr)
{
	uint8_t *keep = malloc(TDP_VRAM_SIZE);
	unsigned int i;

	assert_non_null(keep);
	memcpy(keep, t->vram, TDP_VRAM_SIZE);
	tdp_clear_err(t);
	for (i = 0; i < n; i++)
		tdp_push(t, w[i]);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), err);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO), hdr);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_ERROR);
	assert_memory_equal(keep, t->vram, TDP_VRAM_SIZE);
	free(keep);
	tdp_clear_err(t);
}

#define EXPECT_ERROR(t, err, ...) \
	do { \
		const uint32_t w_[] = { __VA_ARGS__ }; \
		expect_error((t), w_, RDC_ARRAY_SIZE(w_), (err), w_[0]); \
	} while (0)

/* A pixel drawn by a later command proves the stream stayed in sync. */
static void expect_pixel(struct tdp *t, int32_t x, int32_t y, uint32_t v)
{
	assert_int_equal(tdp_get(t->vram, &scr, x, y), v);
}

static void test_bad_opcodes(void **state)
{
	struct tdp *t = *state;
	uint32_t fill = RDC_CMD(RDC_OP_FILL_RECT, 0, 2);

	/* argument words that look like commands must be skipped */
	EXPECT_ERROR(t, RDC_ERR_OPCODE, RDC_CMD(0x77, 0, 3), fill, RDC_XY(0, 0),
		     RDC_WH(100, 100));
	EXPECT_ERROR(t, RDC_ERR_OPCODE, RDC_CMD(0x09, 0, 0));
	EXPECT_ERROR(t, RDC_ERR_OPCODE, RDC_CMD(0x39, 0, 2), fill, 0);
	/* display-list control with nothing to call or return to */
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_CALL, 0, 1), 2);
	EXPECT_ERROR(t, RDC_ERR_STACK, RDC_CMD(RDC_OP_RET, 0, 0));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_JUMP, 0, 1), 0xfffffffcu);
	EXPECT_ERROR(t, RDC_ERR_OPCODE, RDC_CMD(0xff, 0xff, 0));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(1, 1));
	tdp_drain(t);
	expect_pixel(t, 1, 1, 0xffffffffu);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

static void test_bad_lengths(void **state)
{
	struct tdp *t = *state;
	uint32_t px = RDC_CMD(RDC_OP_PIXEL, 0, 1);

	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_PIXEL, 0, 2), px,
		     RDC_XY(3, 3));
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_PIXEL, 0, 0));
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_LINE, 0, 3), 0, 0, 0);
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_POLYLINE, 0, 1), 0);
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_SET_DST, 0, 3), 0, 2560,
		     RDC_WH(640, 480));
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_LOAD_CLUT, 0, 1), 0);
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_WAIT_VBLANK, 0, 1), 0);
	/* HOST_BLIT 2x2 XRGB8888 needs 2 + 4 words */
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_HOST_BLIT, 0, 5),
		     RDC_XY(0, 0), RDC_WH(2, 2), 1, 2, 3);
	/* MONO 40x2 needs 2 words a row */
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_MONO, 0, 4),
		     RDC_XY(0, 0), RDC_WH(40, 2), ~0u, ~0u);
	/* TEXT of 5 chars needs 2 words */
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_TEXT, 0, 3),
		     RDC_XY(0, 0), 5, 0x41414141);
	/* the stream is still in sync */
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(2, 2));
	tdp_drain(t);
	expect_pixel(t, 2, 2, 0xffffffffu);
	expect_pixel(t, 3, 3, 0);
}

/* A header claiming more than RDC_CMD_MAX_ARGS: only it is dropped. */
static void test_huge_length(void **state)
{
	struct tdp *t = *state;
	uint32_t hdr = RDC_CMD(RDC_OP_NOP, 0, RDC_CMD_MAX_ARGS + 1);

	tdp_push(t, hdr);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(4, 4));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_ERR_INFO), hdr);
	expect_pixel(t, 4, 4, 0xffffffffu);
	tdp_clear_err(t);
	hdr = RDC_CMD(RDC_OP_FILL_RECT, 0, 0xffff);
	tdp_push(t, hdr);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5, 4));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	expect_pixel(t, 5, 4, 0xffffffffu);
	/* a long NOP within the limit is fine and skipped whole */
	tdp_clear_err(t);
	tdp_push(t, RDC_CMD(RDC_OP_NOP, 0, 300));
	{
		unsigned int i;

		for (i = 0; i < 300; i++)
			tdp_push(t, RDC_CMD(RDC_OP_FILL_RECT, 0, 2));
	}
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(6, 4));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	expect_pixel(t, 6, 4, 0xffffffffu);
}

static void test_bad_ranges(void **state)
{
	struct tdp *t = *state;
	uint32_t far = RDC_XY(RDC_COORD_MAX + 1, 0);
	uint32_t neg = RDC_XY(0, RDC_COORD_MIN - 1);

	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_PIXEL, 0, 1), far);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_LINE, 0, 2), 0, neg);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_POLYLINE, 0, 3), 0,
		     RDC_XY(5, 5), far);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_FILL_RECT, 0, 2), 0,
		     RDC_WH(RDC_SIZE_MAX + 1, 1));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_RECT, 0, 2), far,
		     RDC_WH(3, 3));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_CIRCLE, 0, 2),
		     RDC_XY(10, 10), RDC_SIZE_MAX + 1);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_FILL_CIRCLE, 0, 2),
		     RDC_XY(10, 10), 0xffffffffu);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_ELLIPSE, 0, 2),
		     RDC_XY(10, 10), RDC_WH(3, RDC_SIZE_MAX + 1));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_BLIT, 0, 3), 0, far,
		     RDC_WH(3, 3));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_READBACK, 0, 2), 0,
		     RDC_WH(RDC_SIZE_MAX + 1, 0));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_HOST_BLIT, 0, 3), far,
		     RDC_WH(1, 1), 0);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_MONO, 0, 3), 0,
		     RDC_WH(RDC_SIZE_MAX + 1, 1), 0);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_TEXT, 0, 3), neg, 1,
		     0x41);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_FILL_ELLIPSE, 0, 2), neg,
		     RDC_WH(3, 3));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_SET_CLIP, 0, 2),
		     RDC_XY(10, 10), RDC_XY(5, 20));
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_LOAD_CLUT, 0, 3), 255, 1,
		     2);
	EXPECT_ERROR(t, RDC_ERR_RANGE, RDC_CMD(RDC_OP_LOAD_CLUT, 0, 2),
		     0xffffffffu, 1);
	EXPECT_ERROR(t, RDC_ERR_ARG, RDC_CMD(RDC_OP_SET_ROP, 0, 1),
		     RDC_ROP_COUNT);
	EXPECT_ERROR(t, RDC_ERR_REG, RDC_CMD(RDC_OP_REG_WRITE, 0, 2),
		     RDC_REG_CONTROL, 0);
	EXPECT_ERROR(t, RDC_ERR_REG, RDC_CMD(RDC_OP_REG_WRITE, 0, 2),
		     RDC_REG_FIFO_DATA, 0);
	EXPECT_ERROR(t, RDC_ERR_REG, RDC_CMD(RDC_OP_REG_WRITE, 0, 2),
		     0x12345678u, 0);
	/* the rejected ROP and clip left the state alone */
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(20, 20));
	tdp_drain(t);
	expect_pixel(t, 0, 0, 0xffffffffu);
	expect_pixel(t, 19, 19, 0xffffffffu);
}

static void test_bad_surfaces(void **state)
{
	struct tdp *t = *state;
	uint32_t h = RDC_CMD(RDC_OP_SET_DST, 0, 4);
	uint32_t vs = TDP_VRAM_SIZE;

	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, vs - 100, 64, RDC_WH(16, 10),
		     RDC_FMT_XRGB8888);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0, 63, RDC_WH(16, 10),
		     RDC_FMT_XRGB8888);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0, 64, RDC_WH(16, 10),
		     RDC_FMT_COUNT);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0, 64, RDC_WH(0, 10), RDC_FMT_I8);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0, 64, RDC_WH(10, 0), RDC_FMT_I8);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0, 0x10000, RDC_WH(16, 16385),
		     RDC_FMT_I1);
	/* 32-bit wrap-around must not sneak past the check */
	EXPECT_ERROR(t, RDC_ERR_SURFACE, h, 0xffffff00u, 0xffffffffu,
		     RDC_WH(16, 3), RDC_FMT_I8);
	EXPECT_ERROR(t, RDC_ERR_SURFACE, RDC_CMD(RDC_OP_SET_SRC, 0, 4), 16,
		     0x80000000u, RDC_WH(16, 3), RDC_FMT_I8);
	/* exactly the last bytes of VRAM is fine */
	TDP_CMD(t, RDC_OP_SET_DST, vs - 64 * 9 - 16, 64, RDC_WH(16, 10),
		RDC_FMT_I8);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(-5, -5), RDC_WH(100, 100));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(t->vram[vs - 1], 0xff);
	assert_int_equal(t->vram[vs - 17], 0);
	/* the refused surfaces did not replace the screen */
	TDP_CMD(t, RDC_OP_SET_DST, scr.base, scr.stride,
		RDC_WH(scr.width, scr.height), scr.format);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(7, 7));
	tdp_drain(t);
	expect_pixel(t, 7, 7, 0xffffffffu);
}

/* Colours are masked to the destination's pixel size. */
static void test_colour_mask(void **state)
{
	struct tdp *t = *state;

	TDP_CMD(t, RDC_OP_SET_DST, 0x1000, 16, RDC_WH(16, 4), RDC_FMT_I4);
	TDP_CMD(t, RDC_OP_SET_FG, 0x12345);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(1, 0));
	tdp_drain(t);
	assert_int_equal(t->vram[0x1000], 0x05);
	assert_int_equal(t->vram[0x0fff], 0);
	assert_int_equal(t->vram[0x1001], 0);
}

/*
 * RDC_DRAW_FG against SET_FG and the command: for every opcode that
 * takes it, with arguments good and bad, the same VRAM, the same FG
 * after (even when refused) and the same error, one fetched word and
 * one decode less.  Each run starts from the same VRAM and the same open
 * DRAM row (a pixel drawn far away).
 */
#define FG_WIN (640u * 480u * 4u)

static uint64_t draw_fg_run(struct tdp *t, const uint32_t *w, uint32_t n,
			    uint32_t *err)
{
	uint64_t busy;
	uint32_t i;

	TDP_CMD(t, RDC_OP_SET_DST, 3u << 20, 64, RDC_WH(16, 16),
		RDC_FMT_XRGB8888);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(1, 1));
	tdp_set_surface(t, RDC_OP_SET_DST, &scr);
	tdp_drain(t);
	busy = t->hw.perf.busy;
	for (i = 0; i < n; i++)
		tdp_push(t, w[i]);
	tdp_drain(t);
	*err = tdp_err(t);
	tdp_clear_err(t);
	return t->hw.perf.busy - busy;
}

static void test_draw_fg(void **state)
{
	static const uint32_t ops[] = {
		RDC_OP_PIXEL,	    RDC_OP_LINE,	 RDC_OP_POLYLINE,
		RDC_OP_RECT,	    RDC_OP_FILL_RECT,	 RDC_OP_CIRCLE,
		RDC_OP_FILL_CIRCLE, RDC_OP_ELLIPSE,	 RDC_OP_FILL_ELLIPSE,
		RDC_OP_POLYGON,	    RDC_OP_FILL_POLYGON, RDC_OP_ARC,
		RDC_OP_AA_LINE,	    RDC_OP_AA_CIRCLE,	 RDC_OP_AA_ELLIPSE,
	};
	struct tdp *t = *state;
	uint8_t *orig = malloc(FG_WIN), *want = malloc(FG_WIN);
	uint32_t rng = 0xf6, k, i, w[2 + 2 + 16], len, err_a, err_b, c;
	uint32_t refused = 0;
	uint64_t busy;

	assert_non_null(orig);
	assert_non_null(want);
	for (k = 0; k < 600; k++) {
		uint32_t op = ops[k % RDC_ARRAY_SIZE(ops)];
		int fixed = rdc_cmd_args(op);

		assert_true(rdc_cmd_takes_fg(op));
		len = fixed >= 0 ? (uint32_t)fixed :
				   (uint32_t)tdp_range(&rng, 0, 16);
		if (tdp_rand(&rng) % 8 == 0)
			len = (uint32_t)tdp_range(&rng, 0, 16); /* LENGTH */
		c = tdp_rand(&rng);
		w[0] = RDC_CMD(RDC_OP_SET_FG, 0, 1);
		w[1] = c;
		w[2] = RDC_CMD(
			op, op == RDC_OP_FILL_POLYGON ? tdp_rand(&rng) % 2 : 0,
			len);
		for (i = 0; i < len; i++)
			w[3 + i] = tdp_rand(&rng) % 4 ?
					   RDC_XY(tdp_range(&rng, -40, 680),
						  tdp_range(&rng, -40, 520)) :
					   tdp_rand(&rng);
		for (i = 0; i < FG_WIN; i += 4)
			rdc_st32(t->vram + i, tdp_rand(&rng));
		memcpy(orig, t->vram, FG_WIN);
		busy = draw_fg_run(t, w, 3 + len, &err_a);
		assert_int_equal(t->dp.st.fg, c);
		memcpy(want, t->vram, FG_WIN);

		/* the one command, after another colour */
		memcpy(t->vram, orig, FG_WIN);
		TDP_CMD(t, RDC_OP_SET_FG, ~c);
		w[1] = w[2] | FIELD_PREP(RDC_CMD_FLAGS, RDC_DRAW_FG);
		w[1] += 1; /* the length: the colour word too */
		w[2] = c;
		busy -= draw_fg_run(t, w + 1, 2 + len, &err_b);
		assert_int_equal(err_b, err_a);
		assert_int_equal(t->dp.st.fg, c);
		if (memcmp(want, t->vram, FG_WIN))
			fail_msg("draw fg %u: op %#x len %u", k, op, len);
		assert_int_equal(busy, RDC_T_FIFO_WORD + RDC_T_DECODE);
		refused += err_a != RDC_ERR_NONE;
	}
	/* both kinds were met */
	assert_true(refused > 20 && refused < 500);
	/* no colour word: LENGTH, and FG untouched */
	TDP_CMD(t, RDC_OP_SET_FG, 0x123);
	EXPECT_ERROR(t, RDC_ERR_LENGTH, RDC_CMD(RDC_OP_LINE, RDC_DRAW_FG, 0));
	assert_int_equal(t->dp.st.fg, 0x123);
	free(want);
	free(orig);
}

static void test_halt_on_error(void **state)
{
	struct tdp *t = *state;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_HALT_ON_ERR);
	tdp_push(t, RDC_CMD(0x7e, 0, 0));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(8, 8));
	tdp_drain(t);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED);
	assert_int_equal(tdp_err(t), RDC_ERR_OPCODE);
	expect_pixel(t, 8, 8, 0);
	/* time passing does not un-halt it */
	rdc_hw_run_until(&t->hw, t->hw.now + 1000000);
	expect_pixel(t, 8, 8, 0);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_HALT_ON_ERR |
			     RDC_CONTROL_RESUME);
	tdp_drain(t);
	assert_false(rdc_hw_read(&t->hw, RDC_REG_STATUS) &
		     RDC_STATUS_DP_HALTED);
	expect_pixel(t, 8, 8, 0xffffffffu);

	/* halted again, then a soft reset also clears it */
	tdp_push(t, RDC_CMD(RDC_OP_SET_ROP, 0, 1));
	tdp_push(t, 99);
	tdp_drain(t);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	assert_false(rdc_hw_read(&t->hw, RDC_REG_STATUS) &
		     RDC_STATUS_DP_HALTED);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(9, 8));
	tdp_drain(t);
	expect_pixel(t, 9, 8, 0xffffffffu);
}

static void test_dp_disabled(void **state)
{
	struct tdp *t = *state;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL, 0);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(10, 8));
	rdc_hw_run_until(&t->hw, t->hw.now + 100000);
	expect_pixel(t, 10, 8, 0);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	tdp_drain(t);
	expect_pixel(t, 10, 8, 0xffffffffu);
}

/* ---- control --------------------------------------------------------- */

static void test_fence_clut_reg(void **state)
{
	struct tdp *t = *state;
	unsigned int i;

	TDP_CMD(t, RDC_OP_FENCE, 0xabcd);
	TDP_CMD(t, RDC_OP_LOAD_CLUT, 250, 0x111111, 0x222222, 0x333333,
		0x444444, 0x555555, 0x666666);
	TDP_CMD(t, RDC_OP_REG_WRITE, RDC_REG_LINE_COMPARE, 123);
	TDP_CMD(t, RDC_OP_NOP);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), 0xabcd);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_IRQ_STATUS) & RDC_IRQ_FENCE);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_LINE_COMPARE), 123);
	rdc_hw_write(&t->hw, RDC_REG_CLUT_INDEX, 250);
	for (i = 0; i < 6; i++)
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_CLUT_DATA),
				 0x111111u * (i + 1));
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS), 4);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_NOP);
}

/* With scanout off there is no vblank to wait for: done at once. */
static void test_wait_no_scanout(void **state)
{
	struct tdp *t = *state;

	TDP_CMD(t, RDC_OP_WAIT_VBLANK);
	TDP_CMD(t, RDC_OP_WAIT_LINE, 10);
	TDP_CMD(t, RDC_OP_FENCE, 1);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_FENCE), 1);
}

/* WAIT_VBLANK lasts from its fetch until the vblank the chip reports. */
static void test_wait_vblank_line(void **state)
{
	struct tdp *t = *state;
	uint64_t t0, tv, tl;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	rdc_hw_run_until(&t->hw, t->hw.now + 1000);
	t0 = t->hw.now;
	tv = rdc_port_next_vblank(&t->hw);
	assert_true(tv != RDC_NEVER && tv > t0);
	TDP_CMD(t, RDC_OP_WAIT_VBLANK);
	rdc_hw_run_until(&t->hw, tv - 1);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_WAIT);
	rdc_hw_run_until(&t->hw, tv + 1);
	assert_false(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_DP_WAIT);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_WAIT_VBLANK);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 tv - t0);

	t0 = t->hw.now;
	tl = rdc_port_next_line(&t->hw, 100);
	assert_true(tl != RDC_NEVER && tl > t0);
	TDP_CMD(t, RDC_OP_WAIT_LINE, 100);
	rdc_hw_run_until(&t->hw, tl + 1);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_WAIT_LINE);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 tl - t0);
}

/* ---- queues ---------------------------------------------------------- */

/* HOST_BLIT of 4002 words through the 256-word FIFO. */
static void test_fifo_backpressure(void **state)
{
	struct tdp *t = *state;
	uint32_t w = 100, h = 40, i, full = 0;
	int32_t x, y;

	tdp_push(t, RDC_CMD(RDC_OP_HOST_BLIT, 0, 2 + w * h));
	tdp_push(t, RDC_XY(20, 30));
	tdp_push(t, RDC_WH(w, h));
	for (i = 0; i < w * h; i++) {
		unsigned int spins = 0;

		while (!rdc_hw_read(&t->hw, RDC_REG_FIFO_FREE)) {
			full++;
			assert_true(++spins < TDP_RUN_LIMIT);
			rdc_hw_run_until(&t->hw, t->hw.now + 50);
		}
		rdc_hw_write(&t->hw, RDC_REG_FIFO_DATA, i * 0x01010101u);
	}
	tdp_drain(t);
	assert_true(full > 0);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	for (y = 0; y < 480; y++)
		for (x = 0; x < 640; x++) {
			uint32_t want = 0;

			if (x >= 20 && x < 120 && y >= 30 && y < 70)
				want = (uint32_t)((y - 30) * 100 + x - 20) *
				       0x01010101u;
			expect_pixel(t, x, y, want);
		}
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO), w * h);
}

static void ring_put(struct tdp *t, uint32_t base, uint32_t size,
		     uint32_t *tail, uint32_t w)
{
	assert_int_equal(rdc_hw_vram_write(&t->hw, base + *tail, &w, 4), 0);
	*tail = (*tail + 4) % size;
}

/* Commands from the VRAM ring, one of them wrapping around its end. */
static void test_ring(void **state)
{
	struct tdp *t = *state;
	uint32_t base = 0x300000, size = 64, tail = 40, k;

	rdc_hw_write(&t->hw, RDC_REG_RING_BASE, base);
	rdc_hw_write(&t->hw, RDC_REG_RING_SIZE, size);
	rdc_hw_write(&t->hw, RDC_REG_RING_HEAD, tail);
	rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, tail);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
	for (k = 0; k < 3; k++) {
		ring_put(t, base, size, &tail, RDC_CMD(RDC_OP_SET_FG, 0, 1));
		ring_put(t, base, size, &tail, 0x100 + k);
		ring_put(t, base, size, &tail, RDC_CMD(RDC_OP_FILL_RECT, 0, 2));
		ring_put(t, base, size, &tail, RDC_XY(10 * k, 0));
		ring_put(t, base, size, &tail, RDC_WH(3, 2));
		rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, tail);
		tdp_drain(t);
		for (;;) {
			rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
			if (rdc_hw_read(&t->hw, RDC_REG_RING_HEAD) == tail)
				break;
		}
	}
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	for (k = 0; k < 3; k++) {
		expect_pixel(t, 10 * (int32_t)k, 0, 0x100 + k);
		expect_pixel(t, 10 * (int32_t)k + 2, 1, 0x100 + k);
		expect_pixel(t, 10 * (int32_t)k + 3, 1, 0);
	}
}

/* A bad ring programming: the DP keeps serving the FIFO. */
static void test_ring_bad(void **state)
{
	struct tdp *t = *state;

	rdc_hw_write(&t->hw, RDC_REG_RING_BASE, TDP_VRAM_SIZE - 8);
	rdc_hw_write(&t->hw, RDC_REG_RING_SIZE, 64);
	rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, 8);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
	rdc_hw_run_until(&t->hw, t->hw.now + 1000);
	assert_int_equal(tdp_err(t), RDC_ERR_RING);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(11, 11));
	tdp_drain(t);
	expect_pixel(t, 11, 11, 0xffffffffu);
}

/* READBACK of 4096 words through the 1024-word RDATA FIFO. */
static void test_readback_large(void **state)
{
	struct tdp *t = *state;
	uint32_t i, got = 0, waited = 0;

	for (i = 0; i < 640 * 480; i++)
		rdc_st32(t->vram + 4 * i, i * 2654435761u);
	TDP_CMD(t, RDC_OP_SET_SRC, scr.base, scr.stride,
		RDC_WH(scr.width, scr.height), scr.format);
	TDP_CMD(t, RDC_OP_READBACK, RDC_XY(100, 50), RDC_WH(64, 64));
	while (got < 64 * 64) {
		uint32_t n = rdc_hw_read(&t->hw, RDC_REG_RDATA_COUNT);

		assert_true(n <= RDC_RDATA_DEPTH);
		if (n == RDC_RDATA_DEPTH && got + n < 64 * 64) {
			assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) &
				    RDC_STATUS_DP_WAIT);
			waited++;
		}
		if (!n) {
			rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
			continue;
		}
		while (n--) {
			uint32_t x = 100 + got % 64, y = 50 + got / 64;

			assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_RDATA),
					 (y * 640 + x) * 2654435761u);
			got++;
		}
	}
	tdp_drain(t);
	assert_true(waited > 0);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_RDATA_COUNT), 0);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_READBACK);
}

/* ---- decoder ----------------------------------------------------------- */

/* run() stops at the first command boundary at or after `until`. */
static void test_until_boundary(void **state)
{
	struct tdp *t = *state;
	uint32_t cmds = rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS);

	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(640, 480));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(0, 0));
	TDP_CMD(t, RDC_OP_SET_FG, 5);
	rdc_hw_run_until(&t->hw, t->hw.now + 1);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS), cmds + 1);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_FILL_RECT);
	expect_pixel(t, 639, 479, 0xffffffffu);
	assert_false(rdc_hw_read(&t->hw, RDC_REG_STATUS) &
		     RDC_STATUS_FIFO_EMPTY);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS), cmds + 3);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO),
			 640 * 480 + 1);
}

/* A command whose words come late waits in FETCH, BUSY and WAIT set. */
static void test_fetch_wait(void **state)
{
	struct tdp *t = *state;
	uint64_t t0;

	t0 = t->hw.now;
	tdp_push(t, RDC_CMD(RDC_OP_HOST_BLIT, 0, 4));
	tdp_push(t, RDC_XY(30, 40));
	tdp_push(t, RDC_WH(2, 1));
	rdc_hw_run_until(&t->hw, t->hw.now + 1000);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_STATUS) &
				 RDC_STATUS_IDLE_MASK,
			 RDC_STATUS_DP_BUSY | RDC_STATUS_DP_WAIT);
	expect_pixel(t, 30, 40, 0);
	tdp_push(t, 0x123456);
	tdp_push(t, 0x654321);
	tdp_drain(t);
	expect_pixel(t, 30, 40, 0x123456);
	expect_pixel(t, 31, 40, 0x654321);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES) >= 1000);
	assert_true(t->hw.now - t0 >= 1000);
}

/* The FIFO is served before the ring. */
static void test_fifo_before_ring(void **state)
{
	struct tdp *t = *state;
	uint32_t base = 0x200000, size = 64, tail = 0;

	ring_put(t, base, size, &tail, RDC_CMD(RDC_OP_SET_FG, 0, 1));
	ring_put(t, base, size, &tail, 0x22);
	ring_put(t, base, size, &tail, RDC_CMD(RDC_OP_PIXEL, 0, 1));
	ring_put(t, base, size, &tail, RDC_XY(50, 50));
	TDP_CMD(t, RDC_OP_SET_FG, 0x11);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(50, 50));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(51, 50));
	rdc_hw_write(&t->hw, RDC_REG_RING_BASE, base);
	rdc_hw_write(&t->hw, RDC_REG_RING_SIZE, size);
	rdc_hw_write(&t->hw, RDC_REG_RING_HEAD, 0);
	rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, tail);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
	tdp_drain(t);
	rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_RING_HEAD), tail);
	/* the FIFO's pixels first, then the ring's over (50, 50) */
	expect_pixel(t, 50, 50, 0x22);
	expect_pixel(t, 51, 50, 0x11);
}

/* A closed polyline drawn with XOR keeps every vertex pixel. */
static void test_polyline_closed_xor(void **state)
{
	struct tdp *t = *state;
	const uint32_t pts[] = { RDC_XY(10, 10), RDC_XY(60, 12), RDC_XY(30, 50),
				 RDC_XY(10, 10) };

	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	TDP_CMD(t, RDC_OP_SET_FG, 0xff);
	tdp_cmd(t, RDC_OP_POLYLINE, 0, 4, pts);
	tdp_drain(t);
	expect_pixel(t, 10, 10, 0xff);
	expect_pixel(t, 60, 12, 0xff);
	expect_pixel(t, 30, 50, 0xff);
	/* drawn again, it cancels out */
	tdp_cmd(t, RDC_OP_POLYLINE, 0, 4, pts);
	tdp_drain(t);
	expect_pixel(t, 10, 10, 0);
	expect_pixel(t, 60, 12, 0);
	expect_pixel(t, 30, 50, 0);
}

/* ---- cycle counts ---------------------------------------------------- */

static uint32_t last_cycles(struct tdp *t)
{
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

/* FILL_RECT of an aligned XRGB8888 rectangle, scanout off. */
static void test_cycles_fill(void **state)
{
	struct tdp *t = *state;
	uint32_t open, y;
	uint64_t want;

	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 0; y < 4; y++)
		want += tdp_bus_edges(&open, 64 * 4 + (uint64_t)(10 + y) * 2560,
				      32 * 4, TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(64, 10), RDC_WH(32, 4));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO), 128);
}

/* One pixel: a 4-byte write inside an 8-byte beat is merged (RMW). */
static void test_cycles_pixel(void **state)
{
	struct tdp *t = *state;
	uint32_t open;
	uint64_t want;

	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 2 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 5 * 4 + 7 * 2560, 4, TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5, 7));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
	/* and by hand: one beat, one row miss (row 8 was not open), merge */
	assert_int_equal(want, 2 + 4 + RDC_T_BEAT + RDC_T_ROW_MISS +
				       RDC_T_TURN + RDC_T_BEAT);
}

/* XOR fill: every beat read-modify-written; I4 fill with partial edges. */
static void test_cycles_rmw(void **state)
{
	struct tdp *t = *state;
	uint32_t open, y;
	uint64_t want;

	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 0; y < 3; y++)
		want += tdp_bus_edges(&open, 3 * 4 + (uint64_t)(100 + y) * 2560,
				      300 * 4, TDP_BUS_RMW, 0, 0);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(3, 100), RDC_WH(300, 3));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);

	/* I4, x = 3..40: first and last bytes half written */
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
	TDP_CMD(t, RDC_OP_SET_DST, 0x100000, 64, RDC_WH(128, 16), RDC_FMT_I4);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 0x100000 + 64 * 2 + 1, 20, TDP_BUS_WRITE, 1,
			     1);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(3, 2), RDC_WH(38, 1));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
}

/* A vertical line: one column access, `count` one-burst elements. */
static void test_cycles_column(void **state)
{
	struct tdp *t = *state;
	uint32_t open, y;
	uint64_t want;

	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 20; y <= 29; y++)
		want += tdp_bus_edges(&open, 5 * 4 + (uint64_t)y * 2560, 4,
				      TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(5, 20), RDC_XY(5, 29));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
}

/* A command from the ring: header and arguments are VRAM reads. */
static void test_cycles_ring(void **state)
{
	struct tdp *t = *state;
	uint32_t base = 0x300000, size = 256, tail = 0, open;
	uint64_t want;

	ring_put(t, base, size, &tail, RDC_CMD(RDC_OP_FILL_RECT, 0, 2));
	ring_put(t, base, size, &tail, RDC_XY(0, 0));
	ring_put(t, base, size, &tail, RDC_WH(16, 1));
	rdc_hw_write(&t->hw, RDC_REG_RING_BASE, base);
	rdc_hw_write(&t->hw, RDC_REG_RING_SIZE, size);
	rdc_hw_write(&t->hw, RDC_REG_RING_HEAD, 0);
	rdc_hw_write(&t->hw, RDC_REG_RING_TAIL, tail);
	open = t->hw.bus.open_row;
	/* the header is read on its own, then the two argument words */
	want = tdp_bus_edges(&open, base, 4, TDP_BUS_READ, 0, 0) +
	       tdp_bus_edges(&open, base + 4, 8, TDP_BUS_READ, 0, 0) +
	       RDC_T_DECODE +
	       tdp_bus_edges(&open, 0, 16 * 4, TDP_BUS_WRITE, 0, 0);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_RING_EN);
	rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_RING_HEAD), tail);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_FILL_RECT);
	assert_int_equal(last_cycles(t), want);
}

/* Drawing in vertical blanking: no scanout contention, no stall. */
static void test_cycles_vblank(void **state)
{
	struct tdp *t = *state;
	uint64_t tv, stall, want;
	uint32_t open, y;

	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	rdc_hw_run_until(&t->hw, t->hw.now + 10);
	tv = rdc_port_next_vblank(&t->hw);
	assert_true(tv != RDC_NEVER);
	rdc_hw_run_until(&t->hw, tv + 10);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	stall = t->hw.perf.stall;
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 0; y < 16; y++)
		want += tdp_bus_edges(&open, (uint64_t)(200 + y) * 2560,
				      640 * 4, TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 200), RDC_WH(640, 16));
	rdc_hw_run_until(&t->hw, t->hw.now + 5000);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_STATUS) & RDC_STATUS_VBLANK);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_FILL_RECT);
	assert_int_equal(last_cycles(t), want);
	assert_int_equal(t->hw.perf.stall, stall);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_reset_state),
		TDP_TEST(test_bad_opcodes),
		TDP_TEST(test_bad_lengths),
		TDP_TEST(test_huge_length),
		TDP_TEST(test_bad_ranges),
		TDP_TEST(test_bad_surfaces),
		TDP_TEST(test_colour_mask),
		TDP_TEST(test_draw_fg),
		TDP_TEST(test_halt_on_error),
		TDP_TEST(test_dp_disabled),
		TDP_TEST(test_fence_clut_reg),
		TDP_TEST(test_wait_no_scanout),
		TDP_TEST(test_wait_vblank_line),
		TDP_TEST(test_fifo_backpressure),
		TDP_TEST(test_ring),
		TDP_TEST(test_ring_bad),
		TDP_TEST(test_readback_large),
		TDP_TEST(test_until_boundary),
		TDP_TEST(test_fetch_wait),
		TDP_TEST(test_fifo_before_ring),
		TDP_TEST(test_polyline_closed_xor),
		TDP_TEST(test_cycles_fill),
		TDP_TEST(test_cycles_pixel),
		TDP_TEST(test_cycles_rmw),
		TDP_TEST(test_cycles_column),
		TDP_TEST(test_cycles_ring),
		TDP_TEST(test_cycles_vblank),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
