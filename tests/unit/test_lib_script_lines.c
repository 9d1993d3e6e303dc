// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: the pen, dash, polygon, arc, curve, transform and viewport
 * statements and their batch encoders. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"

static struct rdc_script_result sl_res;

static int sl_setup(void **state)
{
	rdc_dev *dev;

	if (rdc_open("sim:vram=4M", &dev))
		return -1;
	*state = dev;
	return 0;
}

static int sl_teardown(void **state)
{
	rdc_close(*state);
	return 0;
}

static int sl_run(rdc_dev *dev, const char *text)
{
	return rdc_script_run(dev, text, strlen(text), &sl_res);
}

/* XRGB8888 320x200 screen at VRAM 0: stride 1280 */
static uint32_t sl_px(rdc_dev *dev, int x, int y)
{
	uint32_t v = 0;

	assert_int_equal(
		rdc_vram_read(dev, (uint32_t)(y * 1280 + x * 4), &v, 4), 0);
	return v & 0xffffff;
}

static void test_transform_decimals(void **state)
{
	rdc_dev *dev = *state;

	/* m02 = 10.5: x' = 5 + 10.5 = 15.5, rounded up to 16; y' = 5 - 3 */
	assert_int_equal(sl_run(dev, "mode 320x200 xrgb8888\n"
				     "transform 1 0 10.5 0 1.0 -3 0 0 1\n"
				     "pixel 5 5\n"
				     "transform identity\n"
				     "pixel 7 7\n"),
			 0);
	assert_true(sl_px(dev, 16, 2));
	assert_true(sl_px(dev, 7, 7));
	assert_false(sl_px(dev, 15, 2));
	/* the window [-1, 1] x [-1, 1] onto 0..100, y flipped */
	assert_int_equal(sl_run(dev, "mode 320x200 xrgb8888\n"
				     "viewport -1 -1 1 1 0 0 100 100\n"
				     "pixel -1 -1\n"
				     "pixel 1 1\n"
				     "transform identity\n"),
			 0);
	assert_true(sl_px(dev, 0, 100));
	assert_true(sl_px(dev, 100, 0));
	assert_false(sl_px(dev, 0, 0));
}

static void test_arc_degrees(void **state)
{
	rdc_dev *dev = *state;

	/* 90 .. -90 (= 270) counter-clockwise: the left half */
	assert_int_equal(sl_run(dev, "mode 320x200 xrgb8888\n"
				     "arc 50 50 10 10 90 -90 pie\n"
				     "arc 150 50 10 10 0 360\n"),
			 0);
	assert_true(sl_px(dev, 41, 50));
	assert_true(sl_px(dev, 50, 41));
	assert_true(sl_px(dev, 50, 59));
	assert_false(sl_px(dev, 52, 50));
	/* 0 .. 360 is the whole outline */
	assert_true(sl_px(dev, 160, 50));
	assert_true(sl_px(dev, 140, 50));
	assert_true(sl_px(dev, 150, 40));
	assert_false(sl_px(dev, 150, 50));
}

static void test_pen_dash_curves(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(sl_run(dev,
				"mode 320x200 xrgb8888\n"
				"pen 5 square bevel\n"
				"line 20 20 40 20\n"
				"pen 1\n"
				"dash 0x1 2 1\n"
				"line 20 40 30 40\n"
				"dash off\n"
				"polygon 60 60 80 60 70 80\n"
				"bezier 100 100 110 90 120 90 130 100 steps 8\n"
				"hermite 100 120 130 120 0 0 0 0\n"
				"bspline 150 10 150 10 150 10 150 10\n"),
			 0);
	/* square caps: 2.5 px past the ends, rows 18..22 */
	assert_true(sl_px(dev, 18, 18) && sl_px(dev, 42, 22));
	assert_false(sl_px(dev, 17, 20) || sl_px(dev, 20, 23));
	/* offset 1 of pattern 01: odd steps drawn */
	assert_false(sl_px(dev, 20, 40));
	assert_true(sl_px(dev, 21, 40));
	assert_false(sl_px(dev, 70, 70)); /* inside: outline only */
	assert_true(sl_px(dev, 65, 70));  /* the closing edge 70,80 - 60,60 */
	assert_true(sl_px(dev, 100, 100) && sl_px(dev, 130, 100));
	assert_true(sl_px(dev, 115, 120));
	assert_true(sl_px(dev, 150, 10));
}

static void test_parse_errors(void **state)
{
	rdc_dev *dev = *state;
	static const char *const bad[] = {
		"pen 3 wobbly\n",
		"pen 3 round sharp\n",
		"pen 256\n",
		"dash 1 33\n",
		"dash 1\n",
		"dash 1 8 64\n",
		"dash off 3\n",
		"polygon 1 2 3\n",
		"arc 1 2 3 4 5 6 slice\n",
		"arc 1 2 3 4 5 x\n",
		"bezier 1 2 3 4 5 6 7\n",
		"bezier 1 2 3 4 5 6 7 8 9 10\n",
		"hermite 1 2 3 4 5 6 7 8 steps 0\n",
		"bspline 1 2 3 4 5 6 7 8 steps 256\n",
		"bspline 1 2 3 4 5 6\n",
		"transform 1 2\n",
		"transform 1 0 0 0 1 0 0 0 x\n",
		"transform 1 0 0 0 1 0 0 0 1.2.3\n",
		"transform 99999 0 0 0 1 0 0 0 1\n",
		"viewport 0 0 1 1 0 0 10\n",
	};

	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		assert_int_not_equal(sl_run(dev, bad[i]), 0);
		assert_int_equal(sl_res.error_line, 1);
	}
	/* the device refuses what the script cannot know: a 0-wide pen, a
	 * degenerate window */
	assert_int_equal(sl_run(dev, "pen 0\n"), RDC_E_DEVICE);
	assert_int_equal(sl_run(dev, "viewport 1 0 1 1 0 0 10 10\n"),
			 RDC_E_DEVICE);
}

static void test_batch_words(void **state)
{
	rdc_batch *b = rdc_batch_new();
	const int xy[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
	const int32_t m[9] = { 65536, 0, -1, 0, 65536, 0, 0, 0, 65536 };
	const uint32_t *w;
	size_t n;

	(void)state;
	assert_non_null(b);
	assert_int_equal(rdc_batch_pen(b, 5, RDC_CAP_ROUND, RDC_JOIN_BEVEL), 0);
	assert_int_equal(rdc_batch_dash(b, 0xf0f0, 16, 3), 0);
	assert_int_equal(rdc_batch_arc(b, -1, 2, 3, 4, 0x1234, 0xfedc,
				       RDC_ARC_CHORD),
			 0);
	assert_int_equal(rdc_batch_bezier(b, xy, 9), 0);
	assert_int_equal(rdc_batch_transform(b, m), 0);
	assert_int_equal(rdc_batch_transform(b, NULL), 0);
	assert_int_equal(rdc_batch_viewport(b, -65536, 0, 65536, 1, 0, 0, 9, 9),
			 0);
	assert_int_equal(rdc_batch_bspline(b, NULL, 4, 0), RDC_E_INVAL);
	w = rdc_batch_words(b, &n);
	assert_int_equal(n, 2 + 3 + 4 + 5 + 10 + 1 + 7);
	assert_int_equal(w[0], RDC_CMD(RDC_OP_SET_PEN, 0, 1));
	assert_int_equal(w[1], 5 | 1 << 8 | 2 << 10);
	assert_int_equal(w[2], RDC_CMD(RDC_OP_SET_DASH, 0, 2));
	assert_int_equal(w[3], 0xf0f0);
	assert_int_equal(w[4], 16 | 3 << 8);
	assert_int_equal(w[5], RDC_CMD(RDC_OP_ARC, RDC_ARC_CHORD, 3));
	assert_int_equal(w[6], 0x0002ffff);
	assert_int_equal(w[7], 0x00040003);
	assert_int_equal(w[8], 0xfedc1234);
	assert_int_equal(w[9], RDC_CMD(RDC_OP_BEZIER, 9, 4));
	assert_int_equal(w[10], 0x00020001);
	assert_int_equal(w[14], RDC_CMD(RDC_OP_SET_TRANSFORM, 0, 9));
	assert_int_equal(w[17], 0xffffffff);
	assert_int_equal(w[24], RDC_CMD(RDC_OP_SET_TRANSFORM, 0, 0));
	assert_int_equal(w[25], RDC_CMD(RDC_OP_SET_VIEWPORT, 0, 6));
	assert_int_equal(w[26], 0xffff0000);
	assert_int_equal(w[31], 0x00090009);
	rdc_batch_free(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_transform_decimals,
						sl_setup, sl_teardown),
		cmocka_unit_test_setup_teardown(test_arc_degrees, sl_setup,
						sl_teardown),
		cmocka_unit_test_setup_teardown(test_pen_dash_curves, sl_setup,
						sl_teardown),
		cmocka_unit_test_setup_teardown(test_parse_errors, sl_setup,
						sl_teardown),
		cmocka_unit_test(test_batch_words),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
