// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Random command streams: every opcode, random lengths and arguments,
 * surfaces near the end of VRAM.  Under ASan and UBSan any out-of-bounds
 * access or overflow aborts the program; the test then checks the DP still
 * works after a soft reset.
 */
#include "test_dp_common.h"

static const uint8_t ops[] = {
	RDC_OP_NOP,	    RDC_OP_FENCE,     RDC_OP_WAIT_VBLANK,
	RDC_OP_WAIT_LINE,   RDC_OP_REG_WRITE, RDC_OP_LOAD_CLUT,
	RDC_OP_CALL,	    RDC_OP_RET,	      RDC_OP_JUMP,
	RDC_OP_SET_FG,	    RDC_OP_SET_BG,    RDC_OP_SET_ROP,
	RDC_OP_SET_CLIP,    RDC_OP_SET_DST,   RDC_OP_SET_SRC,
	RDC_OP_PIXEL,	    RDC_OP_LINE,      RDC_OP_POLYLINE,
	RDC_OP_RECT,	    RDC_OP_FILL_RECT, RDC_OP_CIRCLE,
	RDC_OP_FILL_CIRCLE, RDC_OP_ELLIPSE,   RDC_OP_FILL_ELLIPSE,
	RDC_OP_BLIT,	    RDC_OP_HOST_BLIT, RDC_OP_READBACK,
	RDC_OP_MONO,	    RDC_OP_TEXT,      0x7f,
};

/* A coordinate that is usually in range and sometimes far outside. */
static uint32_t rnd_xy(uint32_t *rng)
{
	if (tdp_rand(rng) % 16 == 0)
		return tdp_rand(rng);
	return RDC_XY(tdp_range(rng, -2000, 2000), tdp_range(rng, -2000, 2000));
}

static uint32_t rnd_wh(uint32_t *rng)
{
	if (tdp_rand(rng) % 16 == 0)
		return tdp_rand(rng);
	return RDC_WH(tdp_range(rng, 0, 700), tdp_range(rng, 0, 500));
}

static void fuzz_surface(uint32_t *rng, uint32_t *a)
{
	uint32_t fmt = tdp_rand(rng) % (RDC_FMT_COUNT + 1);
	uint32_t w = (uint32_t)tdp_range(rng, 0, 1100);
	uint32_t h = (uint32_t)tdp_range(rng, 0, 600);
	uint32_t row = rdc_format_row_bytes(fmt < RDC_FMT_COUNT ? fmt : 0, w);

	a[1] = row + (uint32_t)tdp_range(rng, -2, 64);
	/* often flush against the end of VRAM, sometimes just past it */
	if (tdp_rand(rng) % 2 && h)
		a[0] = TDP_VRAM_SIZE - (h - 1) * a[1] - row +
		       (uint32_t)tdp_range(rng, -3, 1);
	else
		a[0] = tdp_rand(rng) % TDP_VRAM_SIZE;
	a[2] = RDC_WH(w, h);
	a[3] = fmt;
	if (tdp_rand(rng) % 32 == 0)
		a[tdp_rand(rng) % 4] = tdp_rand(rng);
}

static void drain_rdata(struct tdp *t)
{
	while (rdc_hw_read(&t->hw, RDC_REG_RDATA_COUNT))
		rdc_hw_read(&t->hw, RDC_REG_RDATA);
}

/* tdp_push, but the host also reads whatever READBACK produces. */
static void fuzz_push(struct tdp *t, uint32_t w)
{
	unsigned int i;

	for (i = 0; i < TDP_RUN_LIMIT; i++) {
		if (rdc_hw_read(&t->hw, RDC_REG_FIFO_FREE))
			break;
		drain_rdata(t);
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	assert_true(i < TDP_RUN_LIMIT);
	rdc_hw_write(&t->hw, RDC_REG_FIFO_DATA, w);
}

static void test_fuzz_stream(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0xfeedu, k, i;
	uint32_t args[64];

	for (k = 0; k < 20000; k++) {
		uint32_t op = ops[tdp_rand(&rng) % sizeof(ops)];
		uint32_t len = (uint32_t)tdp_range(&rng, 0, 6), fl;

		fl = tdp_rand(&rng) % 4 == 0 ? tdp_rand(&rng) & 0xff : 0;
		for (i = 0; i < RDC_ARRAY_SIZE(args); i++)
			args[i] = i % 2 ? rnd_wh(&rng) : rnd_xy(&rng);
		switch (op) {
		case RDC_OP_SET_DST:
		case RDC_OP_SET_SRC:
			len = 4;
			fuzz_surface(&rng, args);
			break;
		case RDC_OP_SET_ROP:
			args[0] = tdp_rand(&rng) % 20;
			break;
		case RDC_OP_CIRCLE:
		case RDC_OP_FILL_CIRCLE:
			args[1] = tdp_rand(&rng) % 3000;
			break;
		case RDC_OP_HOST_BLIT:
		case RDC_OP_MONO:
			args[1] = RDC_WH(tdp_range(&rng, 0, 40),
					 tdp_range(&rng, 0, 12));
			len = 2 + (uint32_t)tdp_range(&rng, 0, 60);
			break;
		case RDC_OP_TEXT:
			args[1] = (uint32_t)tdp_range(&rng, 0, 200);
			len = 2 + (args[1] + 3) / 4 - (tdp_rand(&rng) % 8 == 0);
			break;
		case RDC_OP_READBACK:
			args[1] = RDC_WH(tdp_range(&rng, 0, 60),
					 tdp_range(&rng, 0, 20));
			break;
		case RDC_OP_WAIT_LINE:
		case RDC_OP_WAIT_VBLANK:
			args[0] = tdp_rand(&rng) % 600;
			break;
		default:
			break;
		}
		if (len > RDC_ARRAY_SIZE(args))
			len = RDC_ARRAY_SIZE(args);
		if (tdp_rand(&rng) % 500 == 0)
			len = RDC_CMD_MAX_ARGS + 1 + tdp_rand(&rng) % 100;
		fuzz_push(t, RDC_CMD(op, fl, len));
		for (i = 0; i < len && i < RDC_ARRAY_SIZE(args); i++)
			fuzz_push(t, args[i]);
		drain_rdata(t);
		if (k % 64 == 0)
			rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	for (i = 0; i < TDP_RUN_LIMIT && !tdp_idle(t); i++) {
		drain_rdata(t);
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	assert_true(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS) > 10000);

	/* the DP still works after a reset */
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00c0ffee);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(3, 2));
	tdp_drain(t);
	assert_int_equal(rdc_ld32(t->vram + 2 * 2560 + 3 * 4), 0x00c0ffee);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_fuzz_stream),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
