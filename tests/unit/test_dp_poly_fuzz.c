// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Random streams of the polygon, flood, pattern, triangle and depth
 * commands: random lengths, flags and arguments, surfaces and depth
 * surfaces flush against the end of VRAM, odd clips and ROPs.  ASan and
 * UBSan abort on any out-of-bounds access or overflow; afterwards the DP
 * must still draw.
 */
#include "test_dp_common.h"

static const uint8_t ops[] = {
	RDC_OP_FILL_POLYGON,  RDC_OP_FLOOD_FILL,  RDC_OP_SET_PATTERN,
	RDC_OP_TRIANGLE,      RDC_OP_SET_ZBUF,	  RDC_OP_CLEAR_Z,
	RDC_OP_SET_DST,	      RDC_OP_SET_CLIP,	  RDC_OP_SET_ROP,
	RDC_OP_FILL_RECT,     RDC_OP_FILL_CIRCLE, RDC_OP_RECT,
	RDC_OP_SET_TRANSFORM,
};

static uint32_t rnd_xy(uint32_t *rng, int32_t lo, int32_t hi)
{
	switch (tdp_rand(rng) % 16) {
	case 0:
		return tdp_rand(rng);
	case 1:
		return RDC_XY(tdp_rand(rng) % 2 ? RDC_COORD_MIN : RDC_COORD_MAX,
			      tdp_rand(rng) % 2 ? RDC_COORD_MIN :
						  RDC_COORD_MAX);
	default:
		return RDC_XY(tdp_range(rng, lo, hi), tdp_range(rng, lo, hi));
	}
}

static void fuzz_push(struct tdp *t, uint32_t w)
{
	unsigned int i;

	for (i = 0; i < TDP_RUN_LIMIT; i++) {
		if (rdc_hw_read(&t->hw, RDC_REG_FIFO_FREE))
			break;
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	assert_true(i < TDP_RUN_LIMIT);
	rdc_hw_write(&t->hw, RDC_REG_FIFO_DATA, w);
}

static void test_fuzz_stream(void **state)
{
	struct tdp *t = *state;
	static uint32_t args[RDC_CMD_MAX_ARGS];
	uint32_t rng = 0xbadc0deu, k, i;

	for (k = 0; k < 4000; k++) {
		uint32_t op = ops[tdp_rand(&rng) % sizeof(ops)];
		uint32_t len = (uint32_t)tdp_range(&rng, 0, 12), fl;
		uint32_t fmt, w, h, row;

		fl = tdp_rand(&rng) % 3 == 0 ? tdp_rand(&rng) & 0xff :
					       tdp_rand(&rng) % 4;
		for (i = 0; i < 12; i++)
			args[i] = rnd_xy(&rng, -300, 700);
		switch (op) {
		case RDC_OP_FILL_POLYGON:
			if (tdp_rand(&rng) % 50 == 0) {
				len = RDC_CMD_MAX_ARGS;
				for (i = 0; i < len; i++)
					args[i] = rnd_xy(&rng, -3000, 3000);
			}
			break;
		case RDC_OP_FLOOD_FILL:
			len = 1 + (tdp_rand(&rng) % 8 == 0) +
			      ((fl & RDC_FLOOD_BOUNDARY) != 0);
			args[1] = tdp_rand(&rng) % 4;
			break;
		case RDC_OP_SET_PATTERN:
			fl = tdp_rand(&rng) % 5;
			len = fl == RDC_PAT_COLOR ? 64 : fl ? 2 : 0;
			if (tdp_rand(&rng) % 8 == 0)
				len = (uint32_t)tdp_range(&rng, 0, 70);
			for (i = 0; i < len; i++)
				args[i] = tdp_rand(&rng);
			break;
		case RDC_OP_TRIANGLE:
			len = tdp_rand(&rng) % 8 ? 9 : len;
			for (i = 1; i < 9; i += 3) {
				args[i] = tdp_rand(&rng);
				args[i + 1] = tdp_rand(&rng) % 4 ?
						      tdp_rand(&rng) & 0xffff :
						      tdp_rand(&rng);
			}
			break;
		case RDC_OP_SET_ZBUF:
			len = tdp_rand(&rng) % 4 ? 2 : len % 3;
			args[1] = (uint32_t)tdp_range(&rng, 0, 3000);
			args[0] = tdp_rand(&rng) % 2 ?
					  TDP_VRAM_SIZE - args[1] * 500 :
					  tdp_rand(&rng) % TDP_VRAM_SIZE;
			break;
		case RDC_OP_CLEAR_Z:
			len = 1;
			args[0] = tdp_rand(&rng) % 0x11000;
			break;
		case RDC_OP_SET_DST:
			len = 4;
			fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
			w = (uint32_t)tdp_range(&rng, 1, 700);
			h = (uint32_t)tdp_range(&rng, 1, 500);
			row = rdc_format_row_bytes(fmt, w);
			args[0] = TDP_VRAM_SIZE - (h - 1) * row - row;
			args[1] = row;
			args[2] = RDC_WH(w, h);
			args[3] = fmt;
			break;
		case RDC_OP_SET_CLIP:
			len = 2;
			break;
		case RDC_OP_SET_ROP:
			len = 1;
			args[0] = tdp_rand(&rng) % RDC_ROP_COUNT;
			break;
		case RDC_OP_FILL_CIRCLE:
			len = 2;
			args[1] = tdp_rand(&rng) % 400;
			break;
		case RDC_OP_SET_TRANSFORM:
			len = tdp_rand(&rng) % 3 ? 0 : 9;
			for (i = 0; i < 9; i++)
				args[i] = i % 4 == 0	     ? 1u << 16 :
					  tdp_rand(&rng) % 2 ? 0 :
							       tdp_rand(&rng);
			break;
		default:
			len = 2;
			args[1] = RDC_WH(tdp_range(&rng, 0, 300),
					 tdp_range(&rng, 0, 300));
			break;
		}
		fuzz_push(t, RDC_CMD(op, fl, len));
		for (i = 0; i < len; i++)
			fuzz_push(t, args[i]);
		if (k % 32 == 0)
			rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	}
	tdp_drain(t);
	assert_true(rdc_hw_read(&t->hw, RDC_REG_PERF_CMDS) >= 4000);

	/* the DP still works after a reset */
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00c0ffee);
	TDP_CMD(t, RDC_OP_FILL_POLYGON, RDC_XY(3, 2), RDC_XY(4, 2),
		RDC_XY(4, 3));
	TDP_CMD(t, RDC_OP_FILL_POLYGON, RDC_XY(3, 2), RDC_XY(4, 3),
		RDC_XY(3, 3));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(rdc_ld32(t->vram + 2 * 2560 + 3 * 4), 0x00c0ffee);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_fuzz_stream),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
