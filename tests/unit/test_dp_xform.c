// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The transform unit: SET_TRANSFORM/SET_VIEWPORT validation, where known
 * matrices send known points, and the property that drawing through a
 * translation equals drawing the translated integer coordinates, for
 * every primitive that takes the transform.
 */
#include "test_dp_common.h"

#define W   640
#define H   480
#define ONE 65536 /* 1.0 in 15.16 */

static uint32_t px(struct tdp *t, int x, int y)
{
	return tdp_get(t->vram, &t->dp.st.dst, x, y);
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

static void set_matrix(struct tdp *t, int32_t m00, int32_t m01, int32_t m02,
		       int32_t m10, int32_t m11, int32_t m12, int32_t m20,
		       int32_t m21, int32_t m22)
{
	TDP_CMD(t, RDC_OP_SET_TRANSFORM, (uint32_t)m00, (uint32_t)m01,
		(uint32_t)m02, (uint32_t)m10, (uint32_t)m11, (uint32_t)m12,
		(uint32_t)m20, (uint32_t)m21, (uint32_t)m22);
}

static void identity(struct tdp *t)
{
	tdp_cmd(t, RDC_OP_SET_TRANSFORM, 0, 0, NULL);
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
	const uint32_t five[5] = { 1, 2, 3, 4, 5 };

	tdp_cmd(t, RDC_OP_SET_TRANSFORM, 0, 5, five);
	expect_err(t, RDC_ERR_LENGTH);
	tdp_cmd(t, RDC_OP_SET_VIEWPORT, 0, 5, five);
	expect_err(t, RDC_ERR_LENGTH);
	/* degenerate windows */
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 0, 0, ONE, RDC_XY(0, 0),
		RDC_XY(10, 10));
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 5, ONE, 5, RDC_XY(0, 0),
		RDC_XY(10, 10));
	expect_err(t, RDC_ERR_ARG);
	/* a scale that does not fit 15.16: 1/65536 world unit to 16000 px */
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 0, 1, 1, RDC_XY(0, 0),
		RDC_XY(16000, 16000));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 0, ONE, ONE, RDC_XY(0, 0),
		RDC_XY(RDC_COORD_MAX + 1, 10));
	expect_err(t, RDC_ERR_RANGE);
	assert_true(t->dp.st.xf_identity);

	/* results off the coordinate range, and w <= 0 */
	set_matrix(t, 4 * ONE, 0, 0, 0, 4 * ONE, 0, 0, 0, ONE);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5000, 1));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(1, 1), RDC_XY(-5000, 1));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(1, 1), RDC_WH(5000, 2));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(10, 10), 5000);
	expect_err(t, RDC_ERR_RANGE);
	set_matrix(t, ONE, 0, 0, 0, ONE, 0, -ONE, 0, 10 * ONE);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(10, 1)); /* w = 0 */
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_POLYLINE, RDC_XY(1, 1), RDC_XY(2, 2),
		RDC_XY(30, 1)); /* w < 0 at the last point */
	expect_err(t, RDC_ERR_RANGE);
	assert_int_equal(count_set(t), 0);
	/* the extreme matrix entries neither crash nor overflow */
	set_matrix(t, INT32_MAX, INT32_MIN, INT32_MAX, INT32_MIN, INT32_MAX,
		   INT32_MIN, INT32_MAX, INT32_MAX, INT32_MAX);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN));
	tdp_drain(t);
	tdp_clear_err(t);
	identity(t);
	tdp_drain(t);
	assert_true(t->dp.st.xf_identity);
}

/* Known matrices, known images of points (worked out by hand). */
static void test_known_points(void **state)
{
	struct tdp *t = *state;

	/* rotation by 90 degrees about (100, 100): (10, 0) -> (100, 110) */
	set_matrix(t, 0, -ONE, 100 * ONE, ONE, 0, 100 * ONE, 0, 0, ONE);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(10, 0));
	tdp_drain(t);
	assert_int_equal(count_set(t), 1);
	assert_true(px(t, 100, 110));
	/* projective: w = 2 halves everything; 0.5 rounds up */
	set_matrix(t, ONE, 0, 0, 0, ONE, 0, 0, 0, 2 * ONE);
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(201, 300));
	tdp_drain(t);
	assert_true(px(t, 101, 150));
	/* scale 2, 3: FILL_RECT anchor and size both scale */
	memset(t->vram, 0, (size_t)W * H * 4);
	set_matrix(t, 2 * ONE, 0, 0, 0, 3 * ONE, 0, 0, 0, ONE);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(10, 10), RDC_WH(5, 4));
	tdp_drain(t);
	assert_int_equal(count_set(t), 10 * 12);
	assert_true(px(t, 20, 30));
	assert_true(px(t, 29, 41));
	/* a circle under unequal scales is the ellipse of the scaled radii */
	memset(t->vram, 0, (size_t)W * H * 4);
	set_matrix(t, 2 * ONE, 0, 0, 0, -ONE, 0, 0, 0, ONE);
	TDP_CMD(t, RDC_OP_FILL_CIRCLE, RDC_XY(100, -100), 10);
	tdp_drain(t);
	assert_true(px(t, 180, 100) && px(t, 220, 100));
	assert_false(px(t, 179, 100) || px(t, 221, 100));
	assert_true(px(t, 200, 90) && px(t, 200, 110));
	assert_false(px(t, 200, 89) || px(t, 200, 111));
	identity(t);
	tdp_drain(t);
}

/*
 * SET_VIEWPORT: the window's corners land on the viewport's corner
 * pixels, world y up: (wx0, wy0) on (x0, y1), (wx1, wy1) on (x1, y0).
 */
static void test_viewport(void **state)
{
	struct tdp *t = *state;

	TDP_CMD(t, RDC_OP_SET_VIEWPORT, (uint32_t)(-10 * ONE),
		(uint32_t)(-10 * ONE), 10 * ONE, 10 * ONE, RDC_XY(100, 50),
		RDC_XY(300, 250));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(-10, -10));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(10, 10));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(0, 0));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(5, -5)); /* (250, 200) */
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(count_set(t), 4);
	assert_true(px(t, 100, 250));
	assert_true(px(t, 300, 50));
	assert_true(px(t, 200, 150));
	assert_true(px(t, 250, 200));
	/* a fractional window: [0, 0.5] onto 0..100: one unit is 200 px */
	memset(t->vram, 0, (size_t)W * H * 4);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 0, ONE / 2, ONE / 2, RDC_XY(0, 0),
		RDC_XY(100, 100));
	TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(1, 0));
	tdp_drain(t);
	assert_true(px(t, 200, 100));
	identity(t);
	tdp_drain(t);
}

/* Draw the same random scene through a translation and pre-translated. */
static void scene(struct tdp *t, uint32_t seed, int dx, int dy)
{
	unsigned int k;

	for (k = 0; k < 40; k++) {
		int x0 = tdp_range(&seed, 0, 300),
		    y0 = tdp_range(&seed, 0, 200);
		int x1 = tdp_range(&seed, 0, 300),
		    y1 = tdp_range(&seed, 0, 200);
		int x2 = tdp_range(&seed, 0, 300),
		    y2 = tdp_range(&seed, 0, 200);
		int x3 = tdp_range(&seed, 0, 300),
		    y3 = tdp_range(&seed, 0, 200);
		uint32_t r = (uint32_t)tdp_range(&seed, 0, 40);
		uint32_t r2 = (uint32_t)tdp_range(&seed, 0, 40);
		uint32_t ang = tdp_rand(&seed);

		TDP_CMD(t, RDC_OP_SET_FG, tdp_rand(&seed));
		switch (k % 12) {
		case 0:
			TDP_CMD(t, RDC_OP_PIXEL, RDC_XY(x0 + dx, y0 + dy));
			break;
		case 1:
			TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy));
			break;
		case 2:
			TDP_CMD(t, RDC_OP_POLYLINE, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy),
				RDC_XY(x2 + dx, y2 + dy));
			break;
		case 3:
			TDP_CMD(t, RDC_OP_RECT, RDC_XY(x0 + dx, y0 + dy),
				RDC_WH(r, r2));
			break;
		case 4:
			TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(x0 + dx, y0 + dy),
				RDC_WH(r, r2));
			break;
		case 5:
			TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(x0 + dx, y0 + dy), r);
			break;
		case 6:
			TDP_CMD(t, RDC_OP_FILL_ELLIPSE,
				RDC_XY(x0 + dx, y0 + dy), RDC_WH(r, r2));
			break;
		case 7:
			TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy),
				RDC_XY(x2 + dx, y2 + dy));
			break;
		case 8:
			TDP_CMD(t, RDC_OP_ARC, RDC_XY(x0 + dx, y0 + dy),
				RDC_WH(r, r2), ang);
			break;
		case 9:
			TDP_CMD(t, RDC_OP_BEZIER, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy),
				RDC_XY(x2 + dx, y2 + dy),
				RDC_XY(x3 + dx, y3 + dy));
			break;
		case 10:
			TDP_CMD(t, RDC_OP_BSPLINE, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy),
				RDC_XY(x2 + dx, y2 + dy),
				RDC_XY(x3 + dx, y3 + dy));
			break;
		default:
			/* tangents are vectors: not translated */
			TDP_CMD(t, RDC_OP_HERMITE, RDC_XY(x0 + dx, y0 + dy),
				RDC_XY(x1 + dx, y1 + dy),
				RDC_XY(x2 - 150, y2 - 100),
				RDC_XY(x3 - 150, y3 - 100));
			break;
		}
		if (k == 20)
			TDP_CMD(t, RDC_OP_SET_PEN, 5 | RDC_CAP_ROUND << 8);
	}
	TDP_CMD(t, RDC_OP_SET_PEN, 1);
}

static void test_translation_property(void **state)
{
	struct tdp *t = *state, *u = tdp_new();
	uint32_t seed;

	for (seed = 1; seed <= 6; seed++) {
		int dx = (int)(seed * 37 % 150), dy = (int)(seed * 53 % 120);

		memset(t->vram, 0, (size_t)W * H * 4);
		memset(u->vram, 0, (size_t)W * H * 4);
		set_matrix(t, ONE, 0, dx * ONE, 0, ONE, dy * ONE, 0, 0, ONE);
		scene(t, seed, 0, 0);
		identity(t);
		scene(u, seed, dx, dy);
		tdp_drain(t);
		tdp_drain(u);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(tdp_err(u), RDC_ERR_NONE);
		assert_true(count_set(t) > 1000);
		assert_memory_equal(t->vram, u->vram, (size_t)W * H * 4);
	}
	tdp_free(u);
}

/* State commands cost their fetch and decode only. */
static void test_cycles(void **state)
{
	struct tdp *t = *state;

	set_matrix(t, ONE, 0, 0, 0, ONE, 0, 0, 0, ONE);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 10 * RDC_T_FIFO_WORD + RDC_T_DECODE);
	TDP_CMD(t, RDC_OP_SET_VIEWPORT, 0, 0, ONE, ONE, RDC_XY(0, 0),
		RDC_XY(10, 10));
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 7 * RDC_T_FIFO_WORD + RDC_T_DECODE);
	TDP_CMD(t, RDC_OP_SET_PEN, 3);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 2 * RDC_T_FIFO_WORD + RDC_T_DECODE);
	TDP_CMD(t, RDC_OP_SET_DASH, 3, 2);
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES),
			 3 * RDC_T_FIFO_WORD + RDC_T_DECODE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_bad_args), TDP_TEST(test_known_points),
		TDP_TEST(test_viewport), TDP_TEST(test_translation_property),
		TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
