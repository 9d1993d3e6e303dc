// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Frame sinks: XRGB8888 to BGR32, XRGB32, RGB24 and YUYV, byte for byte
 * against a model written from the V4L2 format descriptions and the
 * BT.601 equations.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>

#include <cmocka.h>

#include "rdc_sink.h"

#define CONV_SENTINEL 0xa5
#define CONV_PAD      13 /* extra bytes per destination row, left untouched */

static uint32_t conv_rng(uint32_t *x)
{
	*x ^= *x << 13;
	*x ^= *x >> 17;
	*x ^= *x << 5;
	return *x;
}

/* A frame of random pixels with a stride wider than the row. */
static uint32_t *conv_frame(struct rdc_frame *f, uint32_t w, uint32_t h,
			    uint32_t seed)
{
	size_t stride = w + 3;
	uint32_t *px = malloc(stride * h * sizeof(*px));

	assert_non_null(px);
	for (size_t i = 0; i < stride * h; i++)
		px[i] = conv_rng(&seed) & 0x00ffffff;
	memset(f, 0, sizeof(*f));
	f->xrgb = px;
	f->width = w;
	f->height = h;
	f->stride = stride;
	return px;
}

static unsigned comp(uint32_t p, int shift)
{
	return (p >> shift) & 0xff;
}

/* V4L2 BGR32 / XRGB32 / RGB24 byte orders (Documentation/userspace-api/
 * media/v4l/pixfmt-rgb.rst), one pixel at a time. */
static void model_rgb(int fmt, uint32_t p, uint8_t *out)
{
	unsigned r = comp(p, 16), g = comp(p, 8), b = comp(p, 0);

	switch (fmt) {
	case RDC_SINK_FMT_BGR32:
		out[0] = (uint8_t)b, out[1] = (uint8_t)g, out[2] = (uint8_t)r;
		out[3] = 0;
		break;
	case RDC_SINK_FMT_XRGB32:
		out[0] = 0, out[1] = (uint8_t)r, out[2] = (uint8_t)g;
		out[3] = (uint8_t)b;
		break;
	default:
		out[0] = (uint8_t)r, out[1] = (uint8_t)g, out[2] = (uint8_t)b;
		break;
	}
}

static uint8_t *conv_run(int fmt, const struct rdc_frame *f, size_t *bpl_out)
{
	size_t bpl = rdc_sink_fmt_bytesperline(fmt, f->width) + CONV_PAD;
	uint8_t *dst = malloc(bpl * f->height);

	assert_non_null(dst);
	memset(dst, CONV_SENTINEL, bpl * f->height);
	assert_int_equal(rdc_sink_convert(fmt, dst, bpl, f), 0);
	*bpl_out = bpl;
	return dst;
}

static void check_rgb_format(int fmt, unsigned bytes_pp)
{
	static const uint32_t widths[] = { 1, 2, 7, 64, 321 };

	for (size_t i = 0; i < sizeof(widths) / sizeof(widths[0]); i++) {
		struct rdc_frame f;
		uint32_t *px =
			conv_frame(&f, widths[i], 5, 0x1234u + (uint32_t)i);
		size_t bpl;
		uint8_t *dst = conv_run(fmt, &f, &bpl);

		assert_int_equal(bpl - CONV_PAD, (size_t)widths[i] * bytes_pp);
		for (uint32_t y = 0; y < f.height; y++) {
			const uint8_t *row = dst + y * bpl;

			for (uint32_t x = 0; x < f.width; x++) {
				uint8_t want[4];
				uint32_t p = px[y * f.stride + x];

				model_rgb(fmt, p, want);
				/* The X byte of BGR32 may carry the source's
				 * unused byte; it is 0 in our frames. */
				assert_memory_equal(row + x * bytes_pp, want,
						    bytes_pp);
			}
			for (size_t k = bpl - CONV_PAD; k < bpl; k++)
				assert_int_equal(row[k], CONV_SENTINEL);
		}
		free(dst);
		free(px);
	}
}

static void test_convert_bgr32(void **state)
{
	(void)state;
	check_rgb_format(RDC_SINK_FMT_BGR32, 4);
}

static void test_convert_xrgb32(void **state)
{
	(void)state;
	check_rgb_format(RDC_SINK_FMT_XRGB32, 4);
}

static void test_convert_rgb24(void **state)
{
	(void)state;
	check_rgb_format(RDC_SINK_FMT_RGB24, 3);
}

/*
 * BT.601 limited range from the standard's own equations (E'Y = 0.299 R +
 * 0.587 G + 0.114 B; Cb, Cr scaled by 0.5/(1-Kb), 0.5/(1-Kr); 219 and 224
 * levels above 16 and around 128), in floating point; the integer
 * converter may differ by its rounding, one level at most.
 */
static double ref_y(double r, double g, double b)
{
	return 16.0 + 219.0 * (0.299 * r + 0.587 * g + 0.114 * b) / 255.0;
}

static double ref_u(double r, double g, double b)
{
	return 128.0 + 224.0 * (-0.168736 * r - 0.331264 * g + 0.5 * b) / 255.0;
}

static double ref_v(double r, double g, double b)
{
	return 128.0 + 224.0 * (0.5 * r - 0.418688 * g - 0.081312 * b) / 255.0;
}

static void near(int got, double want)
{
	double d = got - want;

	if (d < -1.0 || d > 1.0)
		fail_msg("got %d, BT.601 says %.3f", got, want);
}

static void test_convert_yuyv_model(void **state)
{
	struct rdc_frame f;
	uint32_t *px;
	uint8_t *dst;
	size_t bpl;

	(void)state;
	px = conv_frame(&f, 33, 9, 0xbeef); /* odd width: last pixel alone */
	dst = conv_run(RDC_SINK_FMT_YUYV, &f, &bpl);
	assert_int_equal(bpl - CONV_PAD, 34 * 2);
	for (uint32_t y = 0; y < f.height; y++) {
		const uint8_t *row = dst + y * bpl;

		for (uint32_t x = 0; x < f.width; x += 2) {
			uint32_t p0 = px[y * f.stride + x];
			uint32_t p1 =
				x + 1 < f.width ? px[y * f.stride + x + 1] : p0;
			double r = (comp(p0, 16) + comp(p1, 16)) / 2.0;
			double g = (comp(p0, 8) + comp(p1, 8)) / 2.0;
			double b = (comp(p0, 0) + comp(p1, 0)) / 2.0;
			const uint8_t *m = row + x * 2;

			near(m[0],
			     ref_y(comp(p0, 16), comp(p0, 8), comp(p0, 0)));
			near(m[2],
			     ref_y(comp(p1, 16), comp(p1, 8), comp(p1, 0)));
			near(m[1], ref_u(r, g, b));
			near(m[3], ref_v(r, g, b));
		}
		for (size_t k = bpl - CONV_PAD; k < bpl; k++)
			assert_int_equal(row[k], CONV_SENTINEL);
	}
	free(dst);
	free(px);
}

/* Where BT.601 gives whole numbers there is no rounding to excuse. */
static void test_convert_yuyv_exact_points(void **state)
{
	static const struct {
		uint32_t rgb;
		uint8_t y, u, v;
	} pts[] = {
		{ 0x000000, 16, 128, 128 },  /* black: foot of the range */
		{ 0xffffff, 235, 128, 128 }, /* white: top of Y, no chroma */
		{ 0x0000ff, 41, 240, 110 },  /* blue: Cb at its top, 240 */
		{ 0xff0000, 82, 90, 240 },   /* red: Cr at its top, 240 */
	};

	(void)state;
	for (size_t i = 0; i < sizeof(pts) / sizeof(pts[0]); i++) {
		uint32_t two[2] = { pts[i].rgb, pts[i].rgb };
		struct rdc_frame f = {
			.xrgb = two, .width = 2, .height = 1, .stride = 2
		};
		uint8_t out[4];

		assert_int_equal(
			rdc_sink_convert(RDC_SINK_FMT_YUYV, out, 4, &f), 0);
		/* Red's Y is 81.48 in BT.601: the 8-bit integer matrix
		 * rounds it up; accept the model's one level. */
		near(out[0], ref_y(comp(pts[i].rgb, 16), comp(pts[i].rgb, 8),
				   comp(pts[i].rgb, 0)));
		if (pts[i].rgb != 0xff0000)
			assert_int_equal(out[0], pts[i].y);
		assert_int_equal(out[2], out[0]);
		assert_int_equal(out[1], pts[i].u);
		assert_int_equal(out[3], pts[i].v);
	}
}

/*
 * A long row (the converter's wide path, where the host has one) gives
 * for every pair what a row of just that pair gives (its plain path),
 * byte for byte: extremes of every channel as well as random pixels.
 */
static void test_convert_yuyv_wide_equals_pairs(void **state)
{
	struct rdc_frame f, one;
	uint32_t *px;
	uint8_t *dst, out[4 + CONV_PAD];
	size_t bpl;

	(void)state;
	px = conv_frame(&f, 333, 4, 0x5eed);
	for (uint32_t k = 0; k < f.width; k += 3) /* channel extremes */
		px[f.stride + k] = (k & 8 ? 0x00ffffffu : 0) ^
				   (0xffu << (8 * (k % 3)));
	dst = conv_run(RDC_SINK_FMT_YUYV, &f, &bpl);
	for (uint32_t y = 0; y < f.height; y++)
		for (uint32_t x = 0; x < f.width; x += 2) {
			one = (struct rdc_frame){
				.xrgb = px + y * f.stride + x,
				.width = x + 1 < f.width ? 2 : 1,
				.height = 1,
				.stride = 2,
			};
			assert_int_equal(rdc_sink_convert(RDC_SINK_FMT_YUYV,
							  out, sizeof(out),
							  &one),
					 0);
			assert_memory_equal(dst + y * bpl + x * 2, out, 4);
		}
	free(dst);
	free(px);
}

static void test_convert_args(void **state)
{
	uint32_t px[4] = { 0 };
	uint8_t out[64];
	struct rdc_frame f = {
		.xrgb = px, .width = 4, .height = 1, .stride = 4
	};

	(void)state;
	assert_int_equal(rdc_sink_convert(RDC_SINK_FMT_BGR32, out, 15, &f),
			 RDC_E_INVAL); /* row does not fit */
	assert_int_equal(rdc_sink_convert(RDC_SINK_FMT_COUNT, out, 64, &f),
			 RDC_E_INVAL);
	assert_int_equal(rdc_sink_convert(-1, out, 64, &f), RDC_E_INVAL);
	assert_int_equal(rdc_sink_convert(RDC_SINK_FMT_BGR32, NULL, 64, &f),
			 RDC_E_INVAL);
	f.stride = 3;
	assert_int_equal(rdc_sink_convert(RDC_SINK_FMT_BGR32, out, 64, &f),
			 RDC_E_INVAL);
	assert_int_equal(rdc_sink_fmt_by_name("YUYV"), RDC_SINK_FMT_YUYV);
	assert_int_equal(rdc_sink_fmt_by_name("nv12"), -1);
	assert_string_equal(rdc_sink_fmt_name(RDC_SINK_FMT_RGB24), "rgb24");
	/* The fourccs spelled out, as videodev2.h defines them. */
	assert_int_equal(rdc_sink_fmt_fourcc(RDC_SINK_FMT_BGR32),
			 'B' | 'G' << 8 | 'R' << 16 | (uint32_t)'4' << 24);
	assert_int_equal(rdc_sink_fmt_fourcc(RDC_SINK_FMT_XRGB32),
			 'B' | 'X' << 8 | '2' << 16 | (uint32_t)'4' << 24);
	assert_int_equal(rdc_sink_fmt_fourcc(RDC_SINK_FMT_RGB24),
			 'R' | 'G' << 8 | 'B' << 16 | (uint32_t)'3' << 24);
	assert_int_equal(rdc_sink_fmt_fourcc(RDC_SINK_FMT_YUYV),
			 'Y' | 'U' << 8 | 'Y' << 16 | (uint32_t)'V' << 24);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_convert_bgr32),
		cmocka_unit_test(test_convert_xrgb32),
		cmocka_unit_test(test_convert_rgb24),
		cmocka_unit_test(test_convert_yuyv_model),
		cmocka_unit_test(test_convert_yuyv_exact_points),
		cmocka_unit_test(test_convert_yuyv_wide_equals_pairs),
		cmocka_unit_test(test_convert_args),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
