// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * BEZIER, HERMITE, BSPLINE: end points, straight curves, single steps
 * against LINE, bounded work for the longest lists, bad arguments and a
 * cycle count.
 */
#include "test_dp_common.h"

#define W 640
#define H 480

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

/* Bezier and Hermite curves pass through their end points. */
static void test_end_points(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 31337, k;

	for (k = 0; k < 200; k++) {
		int x[4], y[4], i;
		uint32_t steps = k % 3 ? 0 : (uint32_t)tdp_range(&seed, 1, 255);

		for (i = 0; i < 4; i++) {
			x[i] = tdp_range(&seed, 0, W - 1);
			y[i] = tdp_range(&seed, 0, H - 1);
		}
		clear(t);
		if (k % 2) {
			tdp_cmd(t, RDC_OP_BEZIER, steps, 4,
				(uint32_t[]){ RDC_XY(x[0], y[0]),
					      RDC_XY(x[1], y[1]),
					      RDC_XY(x[2], y[2]),
					      RDC_XY(x[3], y[3]) });
			tdp_drain(t);
			assert_true(px(t, x[3], y[3]));
		} else {
			tdp_cmd(t, RDC_OP_HERMITE, steps, 4,
				(uint32_t[]){ RDC_XY(x[0], y[0]),
					      RDC_XY(x[1], y[1]),
					      RDC_XY(x[2] - 320, y[2] - 240),
					      RDC_XY(x[3] - 320, y[3] - 240) });
			tdp_drain(t);
			assert_true(px(t, x[1], y[1]));
		}
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_true(px(t, x[0], y[0]));
	}
}

/* One step is the chord: exactly LINE's pixels. */
static void test_one_step(void **state)
{
	struct tdp *t = *state, *u = tdp_new();
	uint32_t seed = 5, k;

	for (k = 0; k < 30; k++) {
		int x0 = tdp_range(&seed, 0, W - 1),
		    y0 = tdp_range(&seed, 0, H - 1);
		int x1 = tdp_range(&seed, 0, W - 1),
		    y1 = tdp_range(&seed, 0, H - 1);
		int cx = tdp_range(&seed, 0, W - 1),
		    cy = tdp_range(&seed, 0, H - 1);

		clear(t);
		clear(u);
		TDP_CMD(u, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		if (k % 2)
			tdp_cmd(t, RDC_OP_BEZIER, 1, 4,
				(uint32_t[]){ RDC_XY(x0, y0), RDC_XY(cx, cy),
					      RDC_XY(cy, cx), RDC_XY(x1, y1) });
		else
			tdp_cmd(t, RDC_OP_HERMITE, 1, 4,
				(uint32_t[]){ RDC_XY(x0, y0), RDC_XY(x1, y1),
					      RDC_XY(cx, cy), RDC_XY(cy, cx) });
		tdp_drain(t);
		tdp_drain(u);
		assert_memory_equal(t->vram, u->vram, (size_t)W * H * 4);
	}
	tdp_free(u);
}

/* Collinear control points: the curve stays on their line. */
static void test_straight(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 8, k;
	int x, y;

	for (k = 0; k < 20; k++) {
		int y0 = tdp_range(&seed, 0, H - 1);
		int a = tdp_range(&seed, 0, 200), b = tdp_range(&seed, 0, 200);
		int c = tdp_range(&seed, 0, 200), d = tdp_range(&seed, 0, 200);
		int e = tdp_range(&seed, 0, 200);

		clear(t);
		TDP_CMD(t, RDC_OP_BSPLINE, RDC_XY(a, y0), RDC_XY(b, y0),
			RDC_XY(c, y0), RDC_XY(d, y0), RDC_XY(e, y0));
		/* on the diagonal x - y = 300 */
		TDP_CMD(t, RDC_OP_BEZIER, RDC_XY(a + 300, a),
			RDC_XY(b + 300, b), RDC_XY(c + 300, c),
			RDC_XY(d + 300, d));
		tdp_drain(t);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++)
				if (px(t, x, y))
					assert_true(y == y0 || x - y == 300);
	}
	/* four equal points: one pixel */
	clear(t);
	TDP_CMD(t, RDC_OP_BSPLINE, RDC_XY(9, 9), RDC_XY(9, 9), RDC_XY(9, 9),
		RDC_XY(9, 9));
	tdp_drain(t);
	assert_int_equal(count_set(t), 1);
	assert_true(px(t, 9, 9));
}

/* B-spline of points on a parabola y = x^2 / 64 reproduces the parabola
 * closely: uniform cubic B-splines reproduce quadratics up to a shift of
 * 1/3 * second difference / 2 (here 1/3 * 2 * 8^2/64 / 2 = 1/3 px). */
static void test_bspline_parabola(void **state)
{
	struct tdp *t = *state;
	int x, y;

	TDP_CMD(t, RDC_OP_BSPLINE, RDC_XY(0, 0), RDC_XY(8, 1), RDC_XY(16, 4),
		RDC_XY(24, 9), RDC_XY(32, 16), RDC_XY(40, 25), RDC_XY(48, 36),
		RDC_XY(56, 49), RDC_XY(64, 64));
	tdp_drain(t);
	for (y = 0; y < 80; y++)
		for (x = 0; x < 80; x++)
			if (px(t, x, y)) {
				int want = (x * x + 32) / 64;

				assert_true(abs(y - want) <= 2);
			}
	assert_true(count_set(t) >= 48);
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
	static uint32_t many[RDC_CMD_MAX_ARGS];
	uint32_t i, seed = 3;

	TDP_CMD(t, RDC_OP_BEZIER, 0, 0, 0);
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_HERMITE, 0, 0, 0, 0, 0);
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_BSPLINE, 0, 0, 0);
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_BEZIER, 0, 0, 0, RDC_XY(RDC_COORD_MAX + 1, 0));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_BSPLINE, 0, 0, 0, 0, RDC_XY(0, RDC_COORD_MIN - 1));
	expect_err(t, RDC_ERR_RANGE);
	assert_int_equal(count_set(t), 0);
	/* the longest B-spline, at the step cap, with a wide pen */
	for (i = 0; i < RDC_CMD_MAX_ARGS; i++)
		many[i] =
			RDC_XY(tdp_range(&seed, RDC_COORD_MIN, RDC_COORD_MAX),
			       tdp_range(&seed, RDC_COORD_MIN, RDC_COORD_MAX));
	TDP_CMD(t, RDC_OP_SET_PEN, 3);
	tdp_cmd(t, RDC_OP_BSPLINE, 0, RDC_CMD_MAX_ARGS, many);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	/* huge tangents */
	TDP_CMD(t, RDC_OP_HERMITE, RDC_XY(0, 0), RDC_XY(600, 400),
		RDC_XY(-32768, 32767), RDC_XY(32767, -32768));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

/* A one-step horizontal Bezier costs LINE's span plus two more FIFO
 * words; the span is bus.h's: aligned 32 pixels = 128 bytes, one burst. */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	uint32_t c;

	/* open the DRAM row of line 100 first, so the span does not miss */
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(0, 100));
	tdp_cmd(t, RDC_OP_BEZIER, 1, 4,
		(uint32_t[]){ RDC_XY(32, 100), RDC_XY(5, 5), RDC_XY(7, 7),
			      RDC_XY(63, 100) });
	tdp_drain(t);
	c = rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
	assert_int_equal(c, 5 * RDC_T_FIFO_WORD + RDC_T_DECODE +
				    128 / RDC_BUS_BYTES * RDC_T_BEAT);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_end_points), TDP_TEST(test_one_step),
		TDP_TEST(test_straight),   TDP_TEST(test_bspline_parabola),
		TDP_TEST(test_bad_args),   TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
