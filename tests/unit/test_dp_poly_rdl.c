// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The .rdl statements and batch encoders of polygons, flood fill,
 * patterns, triangles and the depth buffer, through librdc's sim backend:
 * what they draw, their encodings, and their parse and device errors.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "script_fx.h"

#define STRIDE (320 * 4)

static uint32_t dev_err(rdc_dev *dev)
{
	uint32_t code = 0, info = 0;

	rdc_dev_error(dev, &code, &info);
	return code;
}

static uint32_t px(rdc_dev *dev, int x, int y)
{
	uint32_t v = 0;

	assert_int_equal(
		rdc_vram_read(dev, (uint32_t)(y * STRIDE + x * 4), &v, 4), 0);
	return v & 0xffffff;
}

static void test_fill_polygon(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev,
			     "mode 320x200 xrgb8888\n"
			     "fg #112233\n"
			     "fill-polygon 0 0 4 0 4 2 0 2\n"
			     /* a square wound twice: a hole unless nonzero */
			     "fill-polygon 10 0 20 0 20 10 10 10 10 0 "
			     "13 3 17 3 17 7 13 7 13 3\n"
			     "fill-polygon nonzero 30 0 40 0 40 10 30 10 30 0 "
			     "33 3 37 3 37 7 33 7 33 3\n"),
			 0);
	assert_int_equal(px(dev, 0, 0), 0x112233);
	assert_int_equal(px(dev, 3, 1), 0x112233);
	assert_int_equal(px(dev, 4, 0), 0);
	assert_int_equal(px(dev, 0, 2), 0);
	assert_int_equal(px(dev, 11, 1), 0x112233);
	assert_int_equal(px(dev, 15, 5), 0);
	assert_int_equal(px(dev, 35, 5), 0x112233);
	assert_int_equal(run(dev, "fill-polygon 0 0 1 1\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "fill-polygon 0 0 1 1 2\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "fill-polygon nonzero 0 0 9 9 0 99999\n"),
			 RDC_E_PARSE);
}

static void test_pattern(void **state)
{
	rdc_dev *dev = *state;
	char buf[1024];
	size_t n = 0;
	int i;

	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n"
				  "fg #ffffff\nbg #000080\n"
				  "pattern mono 0x8000000000000001\n"
				  "fill 0 0 16 8\n"
				  "pattern mono 8000000000000000 transparent\n"
				  "fg #ff0000\n"
				  "fill 0 0 16 8\n"
				  "pattern none\n"),
			 0);
	/* row 0 bit 7 set at x = 0 and 8; row 7 bit 0 at x = 7 and 15 */
	assert_int_equal(px(dev, 0, 0), 0xff0000);
	assert_int_equal(px(dev, 8, 0), 0xff0000);
	assert_int_equal(px(dev, 1, 0), 0x000080);
	assert_int_equal(px(dev, 7, 7), 0xffffff);
	assert_int_equal(px(dev, 15, 7), 0xffffff);
	assert_int_equal(px(dev, 6, 7), 0x000080);
	n += (size_t)snprintf(buf, sizeof(buf), "pattern color");
	for (i = 0; i < 64; i++)
		n += (size_t)snprintf(buf + n, sizeof(buf) - n, " %d", i + 1);
	snprintf(buf + n, sizeof(buf) - n, "\nfill 8 8 8 8\npattern none\n");
	assert_int_equal(run(dev, buf), 0);
	assert_int_equal(px(dev, 8, 8), 1);
	assert_int_equal(px(dev, 15, 15), 64);
	assert_int_equal(px(dev, 9, 10), 2 * 8 + 2);
	assert_int_equal(run(dev, "pattern mono 123\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "pattern mono 00000000000000000\n"),
			 RDC_E_PARSE);
	assert_int_equal(run(dev, "pattern mono 0000000000000000 opaque\n"),
			 RDC_E_PARSE);
	assert_int_equal(run(dev, "pattern color 1 2 3\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "pattern stripes\n"), RDC_E_PARSE);
}

static void test_flood(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev,
			     "mode 320x200 xrgb8888\n"
			     "fg #ff0000\nrect 10 10 20 20\n"
			     "fg #00ff00\nflood 15 15\n"
			     "fg #0000ff\nflood 100 100 8 boundary #ff0000\n"),
			 0);
	assert_int_equal(px(dev, 11, 11), 0x00ff00);
	assert_int_equal(px(dev, 28, 28), 0x00ff00);
	assert_int_equal(px(dev, 10, 10), 0xff0000);
	assert_int_equal(px(dev, 9, 9), 0x0000ff);
	assert_int_equal(px(dev, 319, 199), 0x0000ff);
	assert_int_equal(run(dev, "flood 1 2 boundary\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "flood 1 2 4\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "flood 1\n"), RDC_E_PARSE);
	/* the device refuses a boundary fill with a ROP reading DST */
	assert_int_equal(run(dev, "rop xor\nflood 1 2 boundary 0\n"),
			 RDC_E_DEVICE);
	assert_int_equal(dev_err(dev), RDC_ERR_ARG);
	assert_int_equal(run(dev, "rop copy\n"), 0);
}

static void test_triangle_zbuf(void **state)
{
	rdc_dev *dev = *state;
	uint16_t z[2];

	assert_int_equal(
		run(dev, "mode 320x200 xrgb8888\n"
			 "zbuf 0x200000 640 test write\n"
			 "clear-z 500\n"
			 "triangle 0 0 #00ff00 400 40 0 0 400 0 40 0 400\n"
			 "triangle gouraud 0 0 #ff0000 600 40 0 #ff0000 600 "
			 "0 40 #ff0000 600\n"
			 "zbuf off\n"),
		0);
	assert_int_equal(px(dev, 1, 1), 0x00ff00);
	assert_int_equal(rdc_vram_read(dev, 0x200000 + 640 * 1 + 2, z, 4), 0);
	assert_int_equal(z[0], 400);
	assert_int_equal(
		rdc_vram_read(dev, 0x200000 + 640 * 199 + 2 * 318, z, 4), 0);
	assert_int_equal(z[0], 500);
	assert_int_equal(run(dev, "triangle 1 2 3\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "triangle 0 0 1 70000 1 1 1 0 2 2 1 0\n"),
			 RDC_E_PARSE);
	assert_int_equal(run(dev, "zbuf 0 640 read\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "zbuf off now\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "clear-z 65536\n"), RDC_E_PARSE);
	assert_int_equal(run(dev, "zbuf 0x3ffff0 640 test\n"), RDC_E_DEVICE);
	assert_int_equal(dev_err(dev), RDC_ERR_SURFACE);
	assert_int_equal(run(dev, "clear-z 0\n"), RDC_E_DEVICE);
	assert_int_equal(dev_err(dev), RDC_ERR_SURFACE);
}

/* The encoders, word by word, from the encodings in rdc_regs.h. */
static void test_batch_words(void **state)
{
	rdc_batch *b = rdc_batch_new();
	const int xy[6] = { 1, 2, -3, 4, 5, -6 };
	const uint32_t col[3] = { 7, 8, 9 }, z[3] = { 10, 11, 65535 };
	const uint8_t rows[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
	const uint32_t *w;
	size_t n;

	(void)state;
	assert_non_null(b);
	assert_int_equal(rdc_batch_fill_polygon(b, xy, 3, 1), 0);
	assert_int_equal(rdc_batch_flood(b, 9, 8, RDC_FLOOD_BOUNDARY, 0x55), 0);
	assert_int_equal(rdc_batch_flood(b, 9, 8, RDC_FLOOD_8, 0x55), 0);
	assert_int_equal(rdc_batch_pattern_mono(b, rows, 1), 0);
	assert_int_equal(rdc_batch_triangle(b, xy, col, z, 1), 0);
	assert_int_equal(rdc_batch_zbuf(b, 0x1000, 64, RDC_Z_TEST), 0);
	assert_int_equal(rdc_batch_zbuf_off(b), 0);
	assert_int_equal(rdc_batch_clear_z(b, 3), 0);
	assert_int_equal(rdc_batch_pattern_none(b), 0);
	w = rdc_batch_words(b, &n);
	assert_int_equal(n, 4 + 3 + 2 + 3 + 10 + 3 + 1 + 2 + 1);
	assert_int_equal(w[0], (0x2au << 24) | (1u << 16) | 3);
	assert_int_equal(w[2], 0x0004fffdu);
	assert_int_equal(w[4], (0x2bu << 24) | (2u << 16) | 2);
	assert_int_equal(w[5], (8u << 16) | 9);
	assert_int_equal(w[6], 0x55);
	assert_int_equal(w[7], (0x2bu << 24) | (1u << 16) | 1);
	assert_int_equal(w[9], (0x16u << 24) | (2u << 16) | 2);
	assert_int_equal(w[10], 0x04030201u);
	assert_int_equal(w[11], 0x08070605u);
	assert_int_equal(w[12], (0x38u << 24) | (1u << 16) | 9);
	assert_int_equal(w[14], 7);
	assert_int_equal(w[21], 65535);
	assert_int_equal(w[22], (0x1eu << 24) | (1u << 16) | 2);
	assert_int_equal(w[25], (0x1eu << 24) | 0);
	assert_int_equal(w[26], (0x1fu << 24) | 1);
	assert_int_equal(w[27], 3);
	assert_int_equal(w[28], 0x16u << 24);
	assert_int_equal(rdc_batch_pattern_mono(b, NULL, 0), RDC_E_INVAL);
	assert_int_equal(rdc_batch_pattern_color(b, NULL), RDC_E_INVAL);
	assert_int_equal(rdc_batch_triangle(b, xy, NULL, z, 0), RDC_E_INVAL);
	rdc_batch_free(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_fill_polygon, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_pattern, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_flood, dev_setup,
						dev_teardown),
		cmocka_unit_test_setup_teardown(test_triangle_zbuf, dev_setup,
						dev_teardown),
		cmocka_unit_test(test_batch_words),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
