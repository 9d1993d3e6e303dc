// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pens and dashes: SET_PEN/SET_DASH validation, the geometry of wide
 * strokes (checked against distances computed here in floating point, not
 * against the DP's fixed-point code), dashes along lines and polylines,
 * POLYGON closing, and cycle counts from bus.h's formulas.
 */
#include "test_dp_common.h"

#define W 640
#define H 480

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

static void clear(struct tdp *t)
{
	memset(t->vram, 0, (size_t)W * H * 4);
}

static uint32_t pen_word(uint32_t w, uint32_t cap, uint32_t join)
{
	return w | (cap << 8) | (join << 10);
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

	TDP_CMD(t, RDC_OP_SET_PEN, 0);
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_PEN, RDC_PEN_MAX_WIDTH + 1);
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(3, 3, 0));
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(3, 0, 3));
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(3, 0, 0) | (1u << 20));
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_PEN, 1, 2);
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_SET_DASH, 0xff, 33);
	expect_err(t, RDC_ERR_ARG);
	TDP_CMD(t, RDC_OP_SET_DASH, 0xff);
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_SET_DASH, 0xff, 8 | (1u << 16));
	expect_err(t, RDC_ERR_ARG);
	/* a rejected SET_PEN changed nothing */
	assert_int_equal(t->dp.st.pen_width, 1);
	assert_int_equal(t->dp.st.dash_len, 0);

	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(1, 1));
	expect_err(t, RDC_ERR_LENGTH);
	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(9, RDC_CAP_ROUND, RDC_JOIN_MITER));
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(10, 10), RDC_XY(RDC_COORD_MAX + 1, 10));
	expect_err(t, RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(10, 10), RDC_XY(20, 10),
		RDC_XY(10, RDC_COORD_MIN - 1));
	expect_err(t, RDC_ERR_RANGE);
	assert_int_equal(count_set(t), 0);
	/* huge, self-crossing, degenerate: completes, stays in bounds */
	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
		RDC_XY(RDC_COORD_MAX, RDC_COORD_MAX),
		RDC_XY(RDC_COORD_MIN, RDC_COORD_MAX),
		RDC_XY(RDC_COORD_MAX, RDC_COORD_MIN), RDC_XY(5, 5),
		RDC_XY(5, 5));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_true(count_set(t) > 0);
	/* the longest polygon with the widest pen: many batches of pieces */
	{
		static uint32_t many[RDC_CMD_MAX_ARGS];
		uint32_t i, seed = 1;

		for (i = 0; i < RDC_CMD_MAX_ARGS; i++)
			many[i] = RDC_XY(tdp_range(&seed, -200, W + 200),
					 tdp_range(&seed, -200, H + 200));
		TDP_CMD(t, RDC_OP_SET_PEN,
			pen_word(RDC_PEN_MAX_WIDTH, RDC_CAP_ROUND,
				 RDC_JOIN_MITER));
		tdp_cmd(t, RDC_OP_POLYGON, 0, RDC_CMD_MAX_ARGS, many);
		TDP_CMD(t, RDC_OP_SET_DASH, 0x0f, 7);
		tdp_cmd(t, RDC_OP_POLYLINE, 0, RDC_CMD_MAX_ARGS / 8, many);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		TDP_CMD(t, RDC_OP_SET_DASH, 0, 0);
		TDP_CMD(t, RDC_OP_SET_PEN, 1);
		tdp_drain(t);
	}
}

/* A horizontal butt line of width w covers centres within w/2 of it:
 * rows y - w/2 .. y + (w - 1)/2 ... exactly w rows, columns x0..x1-1. */
static void test_thick_axis(void **state)
{
	struct tdp *t = *state;
	uint32_t w;
	int x, y;

	for (w = 2; w <= 9; w++) {
		int top = 50 - (int)w / 2, bot = top + (int)w - 1;

		clear(t);
		TDP_CMD(t, RDC_OP_SET_PEN, pen_word(w, RDC_CAP_BUTT, 0));
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(10, 50), RDC_XY(30, 50));
		tdp_drain(t);
		for (y = 40; y < 60; y++)
			for (x = 0; x < 40; x++)
				assert_int_equal(px(t, x, y) != 0,
						 y >= top && y <= bot &&
							 x >= 10 && x < 30);
		/* square caps reach w/2 further at both ends */
		clear(t);
		TDP_CMD(t, RDC_OP_SET_PEN, pen_word(w, RDC_CAP_SQUARE, 0));
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(10, 50), RDC_XY(10, 80));
		tdp_drain(t);
		assert_int_equal(count_set(t), w * (30 + w));
	}
}

/* Newton's square root: the tests do not link libm. */
static double pen_sqrt(double v)
{
	double r = v > 1 ? v : 1;
	int i;

	if (v <= 0)
		return 0;
	for (i = 0; i < 60; i++)
		r = (r + v / r) / 2;
	return r;
}

static double pen_hypot(double x, double y)
{
	return pen_sqrt(x * x + y * y);
}

/* Distance from the point to the segment a-b, and the projection's t. */
static double seg_dist(double x, double y, double ax, double ay, double bx,
		       double by, double *tp)
{
	double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t;

	t = l2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / l2 : 0;
	*tp = t;
	if (t < 0)
		t = 0;
	if (t > 1)
		t = 1;
	return pen_hypot(x - ax - t * dx, y - ay - t * dy);
}

/*
 * Random wide lines against their definition: a pixel whose centre lies
 * clearly inside the pen's rectangle (round caps: capsule) is drawn, one
 * clearly outside is not; "clearly" is 1/32 pixel, above the 1/256 grid
 * of the stroke geometry.
 */
static void test_thick_random(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0x5eed1234u;
	unsigned int k;
	int x, y;

	for (k = 0; k < 60; k++) {
		int ax = tdp_range(&seed, 20, 140),
		    ay = tdp_range(&seed, 20, 140);
		int bx = tdp_range(&seed, 20, 140),
		    by = tdp_range(&seed, 20, 140);
		uint32_t w = (uint32_t)tdp_range(&seed, 2, 20);
		uint32_t cap = k % 2 ? RDC_CAP_ROUND : RDC_CAP_BUTT;
		double h = w / 2.0, eps = 1.0 / 32;

		if (ax == bx && ay == by)
			continue;
		clear(t);
		TDP_CMD(t, RDC_OP_SET_PEN, pen_word(w, cap, 0));
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(ax, ay), RDC_XY(bx, by));
		tdp_drain(t);
		for (y = 0; y < 170; y++) {
			for (x = 0; x < 170; x++) {
				double tp,
					d = seg_dist(x, y, ax, ay, bx, by, &tp);
				double len = pen_hypot(bx - ax, by - ay);
				double along = tp * len; /* from a */
				bool in, out;

				if (cap == RDC_CAP_ROUND) {
					in = d < h - eps;
					out = d > h + eps;
				} else {
					in = d < h - eps && along > eps &&
					     along < len - eps;
					out = d > h + eps || along < -eps ||
					      along > len + eps;
				}
				if (in)
					assert_true(px(t, x, y));
				if (out)
					assert_false(px(t, x, y));
			}
		}
	}
}

/* line(a, b) and line(b, a) are the same pixels at any width. */
static void test_thick_symmetric(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 77, k;
	static uint32_t snap[200 * 200];
	int x, y;

	for (k = 0; k < 40; k++) {
		int ax = tdp_range(&seed, 10, 190),
		    ay = tdp_range(&seed, 10, 190);
		int bx = tdp_range(&seed, 10, 190),
		    by = tdp_range(&seed, 10, 190);
		uint32_t w = (uint32_t)tdp_range(&seed, 2, 16);

		TDP_CMD(t, RDC_OP_SET_PEN, pen_word(w, k % 3, 0));
		clear(t);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(ax, ay), RDC_XY(bx, by));
		tdp_drain(t);
		for (y = 0; y < 200; y++)
			for (x = 0; x < 200; x++)
				snap[y * 200 + x] = px(t, x, y);
		clear(t);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(bx, by), RDC_XY(ax, ay));
		tdp_drain(t);
		for (y = 0; y < 200; y++)
			for (x = 0; x < 200; x++)
				assert_int_equal(snap[y * 200 + x],
						 px(t, x, y));
	}
}

/* Width 1 dashes pick steps of the plain midpoint line: step i (from the
 * first endpoint) is drawn iff pattern bit (i + offset) % len is set. */
static void test_dash_line(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 99, k;
	static int col[W];
	int x, y;

	for (k = 0; k < 30; k++) {
		int x0 = tdp_range(&seed, 0, 300),
		    x1 = tdp_range(&seed, 0, 300);
		int y0 = tdp_range(&seed, 0, 100);
		int y1 = y0 + tdp_range(&seed, 0, abs(x1 - x0));
		uint32_t bits = tdp_rand(&seed), len = 1 + k % 32;
		uint32_t off = (uint32_t)tdp_range(&seed, 0, 63);
		int step = x1 >= x0 ? 1 : -1, i;

		/* the plain line: x-major, one pixel per column */
		clear(t);
		TDP_CMD(t, RDC_OP_SET_DASH, 0, 0);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		tdp_drain(t);
		for (x = 0; x < W; x++) {
			col[x] = -1;
			for (y = 0; y < H; y++)
				if (px(t, x, y))
					col[x] = y;
		}
		clear(t);
		TDP_CMD(t, RDC_OP_SET_DASH, bits, len | off << 8);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		tdp_drain(t);
		for (i = 0; i <= abs(x1 - x0); i++) {
			int cx = x0 + step * i;
			bool on = (bits >> ((i + off) % len)) & 1;

			assert_true(col[cx] >= 0);
			assert_int_equal(px(t, cx, col[cx]) != 0, on);
		}
		assert_int_equal(count_set(t) <= (unsigned int)abs(x1 - x0) + 1,
				 1);
	}
	TDP_CMD(t, RDC_OP_SET_DASH, 0, 0);
}

/* The phase runs on along a polyline: shared vertices count once. */
static void test_dash_polyline(void **state)
{
	struct tdp *t = *state;
	int i;

	/* 3 on, 2 off; the path is 10 steps right then 10 down */
	TDP_CMD(t, RDC_OP_SET_DASH, 0x07, 5);
	TDP_CMD(t, RDC_OP_POLYLINE, RDC_XY(100, 100), RDC_XY(110, 100),
		RDC_XY(110, 110));
	tdp_drain(t);
	for (i = 0; i <= 20; i++) {
		int x = i <= 10 ? 100 + i : 110, y = i <= 10 ? 100 : 90 + i;

		assert_int_equal(px(t, x, y) != 0, i % 5 < 3);
	}
	assert_int_equal(count_set(t), 13); /* i = 0..20: 5 full periods-ish */
	TDP_CMD(t, RDC_OP_SET_DASH, 0, 0);
}

/* POLYGON closes itself; drawn twice with XOR it restores the surface,
 * so each pixel of the width-1 outline is written exactly once. */
static void test_polygon_once(void **state)
{
	struct tdp *t = *state;

	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(10, 10), RDC_XY(50, 12),
		RDC_XY(40, 60));
	tdp_drain(t);
	/* the closing edge is there: the midpoint of (40,60)-(10,10) */
	assert_true(px(t, 25, 35));
	clear(t);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(10, 10), RDC_XY(50, 12),
		RDC_XY(40, 60), RDC_XY(5, 30));
	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(10, 10), RDC_XY(50, 12),
		RDC_XY(40, 60), RDC_XY(5, 30));
	tdp_drain(t);
	assert_int_equal(count_set(t), 0);
	/* once: the outline equals the closed POLYLINE's pixels */
	TDP_CMD(t, RDC_OP_POLYGON, RDC_XY(10, 10), RDC_XY(50, 12),
		RDC_XY(40, 60), RDC_XY(5, 30));
	TDP_CMD(t, RDC_OP_POLYLINE, RDC_XY(10, 10), RDC_XY(50, 12),
		RDC_XY(40, 60), RDC_XY(5, 30), RDC_XY(10, 10));
	tdp_drain(t);
	assert_int_equal(count_set(t), 0);
}

/* A wide RECT outline: a frame w wide centred on the 1-pixel outline. */
static void test_rect_frame(void **state)
{
	struct tdp *t = *state;
	int x, y;

	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(4, RDC_CAP_BUTT, RDC_JOIN_MITER));
	TDP_CMD(t, RDC_OP_RECT, RDC_XY(20, 30), RDC_WH(41, 21));
	tdp_drain(t);
	/* corner pixel centres (20,30)..(60,50), half width 2: centres with
	 * x in [18, 62) and y in [28, 52), minus the inside [22, 58) x
	 * [32, 48) */
	for (y = 0; y < 80; y++)
		for (x = 0; x < 80; x++) {
			bool outer = x >= 18 && x < 62 && y >= 28 && y < 52;
			bool inner = x >= 22 && x < 58 && y >= 32 && y < 48;

			assert_int_equal(px(t, x, y) != 0, outer && !inner);
		}
}

/*
 * A wide stroke is one union: drawn with XOR onto black it lights exactly
 * the pixels COPY lights (an overlap written twice would go dark again),
 * for every cap and join, dashed or not, across a self-crossing.
 */
static void test_thick_once(void **state)
{
	struct tdp *t = *state, *u = tdp_new();
	uint32_t k;
	int x, y;

	for (k = 0; k < 18; k++) {
		uint32_t pen = pen_word(3 + k % 11, k % 3, (k / 3) % 3);

		clear(t);
		clear(u);
		TDP_CMD(u, RDC_OP_SET_ROP, RDC_ROP_XOR);
		TDP_CMD(t, RDC_OP_SET_PEN, pen);
		TDP_CMD(u, RDC_OP_SET_PEN, pen);
		TDP_CMD(t, RDC_OP_SET_DASH, 0x3f, k >= 9 ? 9 : 0);
		TDP_CMD(u, RDC_OP_SET_DASH, 0x3f, k >= 9 ? 9 : 0);
		TDP_CMD(t, RDC_OP_POLYLINE, RDC_XY(20, 20), RDC_XY(200, 150),
			RDC_XY(60, 180), RDC_XY(150, 10), RDC_XY(160, 12));
		TDP_CMD(u, RDC_OP_POLYLINE, RDC_XY(20, 20), RDC_XY(200, 150),
			RDC_XY(60, 180), RDC_XY(150, 10), RDC_XY(160, 12));
		tdp_drain(t);
		tdp_drain(u);
		for (y = 0; y < 240; y++)
			for (x = 0; x < 240; x++)
				assert_int_equal(px(t, x, y) != 0,
						 px(u, x, y) != 0);
		assert_true(count_set(t) > 500);
	}
	tdp_free(u);
}

/* ---- cycle counts ------------------------------------------------------ */

/* A wide horizontal line is w spans, as FILL_RECT: decode, three FIFO
 * words, and one span per row; a dashed line one span per dash. */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	uint32_t open, y, stride = W * 4;
	uint64_t want;
	int d;

	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(4, RDC_CAP_BUTT, 0));
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 98; y < 102; y++)
		want += tdp_bus_span(&open, 16 * 4 + (uint64_t)y * stride,
				     64 * 4, TDP_BUS_WRITE);
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(16, 100), RDC_XY(80, 100));
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES), want);

	TDP_CMD(t, RDC_OP_SET_PEN, pen_word(1, 0, 0));
	TDP_CMD(t, RDC_OP_SET_DASH, 0x0f, 8);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (d = 0; d < 4; d++)
		want += tdp_bus_span(&open,
				     (uint64_t)(8 * d) * 4 + 200 * stride,
				     4 * 4, TDP_BUS_WRITE);
	TDP_CMD(t, RDC_OP_LINE, RDC_XY(0, 200), RDC_XY(31, 200));
	tdp_drain(t);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES), want);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_PIXELS_LO),
			 64 * 4 + 16);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_bad_args),     TDP_TEST(test_thick_axis),
		TDP_TEST(test_thick_random), TDP_TEST(test_thick_symmetric),
		TDP_TEST(test_dash_line),    TDP_TEST(test_dash_polyline),
		TDP_TEST(test_polygon_once), TDP_TEST(test_rect_frame),
		TDP_TEST(test_thick_once),   TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
