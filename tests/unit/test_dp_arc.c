// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * ARC: the sine table, sectors bounded by the axes (where the table is
 * exact, so the expected pixels follow from ELLIPSE/FILL_ELLIPSE and the
 * signs of the offsets), wrap-around, full turns, bad arguments and the
 * cycle count of a pie against FILL_ELLIPSE.
 */
#include "test_dp_common.h"
#include "dp_int.h"

#define W	  640
#define H	  480
#define DEG(d)	  ((uint32_t)((d)*65536u / 360u))
#define ANG(s, e) ((uint32_t)(s) | (uint32_t)(e) << 16)

static uint32_t px(struct tdp *t, int x, int y)
{
	return tdp_get(t->vram, &t->dp.st.dst, x, y);
}

static void clear(struct tdp *t)
{
	memset(t->vram, 0, (size_t)W * H * 4);
}

static unsigned int count_set(struct tdp *t)
{
	unsigned int n = 0;
	int x, y;

	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			n += px(t, x, y) != 0;
	return n;
}

static void test_sine(void **state)
{
	/* reference values, 65536 sin(2 pi a / 65536): a = 5461 (just under
	 * 30 degrees) 32766.19, a = 8192 (45) 46340.95, a = 10923 (just
	 * over 60) 56756.89, a = 38227 -32755.30 */
	(void)state;
	assert_int_equal(dp_sin(0), 0);
	assert_int_equal(dp_sin(16384), 65536);
	assert_int_equal(dp_sin(32768), 0);
	assert_int_equal(dp_sin(49152), -65536);
	assert_int_equal(dp_cos(0), 65536);
	assert_in_range(dp_sin(5461), 32765, 32767);
	assert_in_range(dp_sin(8192), 46340, 46342);
	assert_in_range(dp_sin(10923), 56756, 56758);
	assert_in_range(dp_sin(38227), -32756, -32754);
	for (uint32_t a = 0; a < 65536; a += 97) {
		int64_t s = dp_sin(a), c = dp_cos(a);
		int64_t e = s * s + c * c - (int64_t)65536 * 65536;

		/* |sin^2 + cos^2 - 1| below 2^-14 */
		assert_true(e < ((int64_t)1 << 18) && e > -((int64_t)1 << 18));
	}
}

/*
 * Snapshot of a reference primitive's pixels, filtered by the sector:
 * quadrant q = 0 keeps dx >= 0, dy <= 0 (y down); half h keeps dy <= 0.
 */
static void reference(struct tdp *t, uint32_t op, int cx, int cy, uint32_t rx,
		      uint32_t ry, int keep, uint8_t *out)
{
	int x, y;

	clear(t);
	TDP_CMD(t, op, RDC_XY(cx, cy), RDC_WH(rx, ry));
	tdp_drain(t);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++) {
			int dx = x - cx, dy = y - cy;
			bool k = keep == 0 ? dx >= 0 && dy <= 0 :
				 keep == 1 ? dy <= 0 :
					     true;

			out[y * W + x] = px(t, x, y) && k;
		}
	clear(t);
}

static void expect_same(struct tdp *t, const uint8_t *ref)
{
	int x, y;

	tdp_drain(t);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			assert_int_equal(px(t, x, y) != 0, ref[y * W + x]);
}

static void test_axis_sectors(void **state)
{
	struct tdp *t = *state;
	static uint8_t ref[W * H];
	uint32_t seed = 4242, k;

	for (k = 0; k < 12; k++) {
		int cx = tdp_range(&seed, 50, 590),
		    cy = tdp_range(&seed, 50, 430);
		uint32_t rx = (uint32_t)tdp_range(&seed, 1, 80);
		uint32_t ry = (uint32_t)tdp_range(&seed, 1, 80);

		/* quarter outline and pie: 0..90 degrees */
		reference(t, RDC_OP_ELLIPSE, cx, cy, rx, ry, 0, ref);
		tdp_cmd(t, RDC_OP_ARC, RDC_ARC_OUTLINE, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      ANG(0, 16384) });
		expect_same(t, ref);
		reference(t, RDC_OP_FILL_ELLIPSE, cx, cy, rx, ry, 0, ref);
		tdp_cmd(t, RDC_OP_ARC, RDC_ARC_PIE, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      ANG(0, 16384) });
		expect_same(t, ref);
		/* chord 0..180: the upper half, the diameter included */
		reference(t, RDC_OP_FILL_ELLIPSE, cx, cy, rx, ry, 1, ref);
		tdp_cmd(t, RDC_OP_ARC, RDC_ARC_CHORD, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      ANG(0, 32768) });
		expect_same(t, ref);
		/* start == end: the whole ellipse, in every mode */
		reference(t, RDC_OP_ELLIPSE, cx, cy, rx, ry, 2, ref);
		tdp_cmd(t, RDC_OP_ARC, RDC_ARC_OUTLINE, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      ANG(k * 1000, k * 1000) });
		expect_same(t, ref);
		reference(t, RDC_OP_FILL_ELLIPSE, cx, cy, rx, ry, 2, ref);
		tdp_cmd(t, RDC_OP_ARC, RDC_ARC_PIE + k % 2, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      ANG(k * 3000, k * 3000) });
		expect_same(t, ref);
	}
}

/* An arc across 0 degrees is the union of its two halves. */
static void test_wrap(void **state)
{
	struct tdp *t = *state;
	static uint8_t ref[W * H];
	uint32_t seed = 1717, k, mode;
	int x, y;

	for (k = 0; k < 10; k++) {
		int cx = tdp_range(&seed, 100, 500),
		    cy = tdp_range(&seed, 100, 380);
		uint32_t rx = (uint32_t)tdp_range(&seed, 2, 90);
		uint32_t ry = (uint32_t)tdp_range(&seed, 2, 90);
		uint32_t s = (uint32_t)tdp_range(&seed, 32768 + 1, 65535);
		uint32_t e = (uint32_t)tdp_range(&seed, 1, 32767);

		for (mode = RDC_ARC_OUTLINE; mode <= RDC_ARC_PIE; mode++) {
			clear(t);
			TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_OR);
			tdp_cmd(t, RDC_OP_ARC, mode, 3,
				(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
					      ANG(s, 0) });
			tdp_cmd(t, RDC_OP_ARC, mode, 3,
				(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
					      ANG(0, e) });
			TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
			tdp_drain(t);
			for (y = 0; y < H; y++)
				for (x = 0; x < W; x++)
					ref[y * W + x] = px(t, x, y) != 0;
			clear(t);
			tdp_cmd(t, RDC_OP_ARC, mode, 3,
				(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
					      ANG(s, e) });
			expect_same(t, ref);
		}
	}
}

static void expect_err(struct tdp *t, uint32_t err)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), err);
	tdp_clear_err(t);
}

static void test_bad_args(void **state)
{
	struct tdp *t = *state;

	tdp_cmd(t, RDC_OP_ARC, 3, 3,
		(uint32_t[]){ RDC_XY(50, 50), RDC_WH(10, 10), ANG(0, 100) });
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_ARC, RDC_XY(50, 50), RDC_WH(10, 10));
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_ARC, RDC_XY(50, 50), RDC_WH(RDC_SIZE_MAX + 1, 1), 0);
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_ARC, RDC_XY(RDC_COORD_MIN - 1, 50), RDC_WH(1, 1), 0);
	expect_err(t, RDC_ERR_RANGE);
	/* zero radii draw nothing */
	tdp_cmd(t, RDC_OP_ARC, RDC_ARC_PIE, 3,
		(uint32_t[]){ RDC_XY(50, 50), RDC_WH(0, 10), ANG(0, 100) });
	TDP_CMD(t, RDC_OP_ARC, RDC_XY(50, 50), RDC_WH(0, 0), 0);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(count_set(t), 0);
	/* the largest arcs, mostly off the surface, complete */
	tdp_cmd(t, RDC_OP_ARC, RDC_ARC_CHORD, 3,
		(uint32_t[]){ RDC_XY(RDC_COORD_MAX, RDC_COORD_MIN),
			      RDC_WH(RDC_SIZE_MAX, RDC_SIZE_MAX),
			      ANG(100, 40000) });
	tdp_cmd(t, RDC_OP_ARC, RDC_ARC_OUTLINE, 3,
		(uint32_t[]){ RDC_XY(0, 0), RDC_WH(RDC_SIZE_MAX, 700),
			      ANG(60000, 1000) });
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

/* A full pie writes FILL_ELLIPSE's spans: same cost plus one FIFO word
 * for the angle argument. */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	uint32_t fill, arc;

	TDP_CMD(t, RDC_OP_FILL_ELLIPSE, RDC_XY(200, 200), RDC_WH(50, 30));
	tdp_drain(t);
	fill = rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
	tdp_cmd(t, RDC_OP_ARC, RDC_ARC_PIE, 3,
		(uint32_t[]){ RDC_XY(200, 200), RDC_WH(50, 30), ANG(5, 5) });
	tdp_drain(t);
	arc = rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
	/* each starts with a row miss: the open DRAM row is elsewhere
	 * before the fill, and the bottom span's row before the pie */
	assert_int_equal(arc, fill + RDC_T_FIFO_WORD);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sine), TDP_TEST(test_axis_sectors),
		TDP_TEST(test_wrap),	     TDP_TEST(test_bad_args),
		TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
