// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc's image side: rdc_image_encode's argument checks and bounds,
 * rdc_image_png_read against rdc_png_write, and the .rdl image
 * statements end to end on a sim: device (encode from the screen, decode
 * back, compared on the frame; vram-load of a stream file; errors).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>
#include <cmocka.h>

#include "rdc.h"

static rdc_dev *open_sim(void)
{
	rdc_dev *dev = NULL;

	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	return dev;
}

static int run(rdc_dev *dev, const char *text, struct rdc_script_result *res)
{
	memset(res, 0, sizeof(*res));
	return rdc_script_run(dev, text, strlen(text), res);
}

static void test_encode_args(void **state)
{
	uint8_t px[12 * 5 * 3], out[4096];
	size_t len = 0;

	(void)state;
	for (size_t i = 0; i < sizeof(px); i++)
		px[i] = (uint8_t)(i * 7);
	assert_int_equal(rdc_image_bound(RDC_IMG_BTC, 12, 5, 3),
			 16 + 3 * 2 * 3 * 4);
	assert_int_equal(rdc_image_bound(0, 12, 5, 3), 0);
	assert_int_equal(rdc_image_bound(RDC_IMG_RLE, 0, 5, 3), 0);
	assert_int_equal(rdc_image_bound(RDC_IMG_RLE, 4097, 5, 3), 0);
	assert_int_equal(rdc_image_bound(RDC_IMG_RLE, 12, 5, 2), 0);
	assert_int_equal(rdc_image_encode(RDC_IMG_CODEC_END, px, 12, 5, 3, 36,
					  out, sizeof(out), &len),
			 RDC_E_INVAL);
	assert_int_equal(rdc_image_encode(RDC_IMG_RLE, px, 12, 5, 3, 35, out,
					  sizeof(out), &len),
			 RDC_E_INVAL);
	/* too small: RDC_E_RANGE, and the size it needed */
	assert_int_equal(rdc_image_encode(RDC_IMG_DPCM, px, 12, 5, 3, 36, out,
					  20, &len),
			 RDC_E_RANGE);
	assert_true(len > 20);
	assert_int_equal(rdc_image_encode(RDC_IMG_DPCM, px, 12, 5, 3, 36, out,
					  len, &len),
			 0);
	for (uint32_t c = RDC_IMG_RLE; c < RDC_IMG_CODEC_END; c++) {
		assert_true(rdc_image_bound(c, 12, 5, 3) <= sizeof(out));
		assert_int_equal(rdc_image_encode(c, px, 12, 5, 3, 36, out,
						  sizeof(out), &len),
				 0);
		assert_true(len <= rdc_image_bound(c, 12, 5, 3));
		assert_int_equal(out[4], c);
		assert_int_equal(out[5], 3);
		assert_int_equal(out[8] | out[9] << 8, 12);
		assert_int_equal(out[10] | out[11] << 8, 5);
	}
}

static void test_png_read(void **state)
{
	char path[] = "/tmp/rdc-image-XXXXXX";
	uint32_t pix[7 * 3], *got = NULL, w = 0, h = 0;
	int fd = mkstemp(path);

	(void)state;
	assert_true(fd >= 0);
	close(fd);
	for (uint32_t i = 0; i < 21; i++)
		pix[i] = (i * 0x1f3a5bu) & 0xffffffu;
	assert_int_equal(rdc_png_write(path, pix, 7, 3, 7), 0);
	assert_int_equal(rdc_image_png_read(path, &got, &w, &h), 0);
	assert_int_equal(w, 7);
	assert_int_equal(h, 3);
	assert_memory_equal(got, pix, sizeof(pix));
	free(got);
	/* not a PNG */
	fd = open(path, O_WRONLY | O_TRUNC);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, "nope", 4), 4);
	close(fd);
	assert_int_equal(rdc_image_png_read(path, &got, &w, &h), RDC_E_FILE);
	unlink(path);
}

/* Frame rectangles (x0, y0) and (x1, y1), w x h, equal? */
static int same_rect(rdc_dev *dev, uint32_t x0, uint32_t y0, uint32_t x1,
		     uint32_t y1, uint32_t w, uint32_t h)
{
	uint32_t *pix, fw, fh, x, y;
	int same = 1;

	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, &fw, &fh), RDC_E_RANGE);
	pix = malloc((size_t)fw * fh * 4);
	assert_non_null(pix);
	assert_int_equal(rdc_frame_grab(dev, pix, (size_t)fw * fh, &fw, &fh),
			 0);
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++)
			if (pix[(y0 + y) * fw + x0 + x] !=
			    pix[(y1 + y) * fw + x1 + x])
				same = 0;
	free(pix);
	return same;
}

static void test_rdl_encode_decode(void **state)
{
	struct rdc_script_result res;
	rdc_dev *dev = open_sim();
	static const char *const codecs[] = { "rle", "dpcm", "btc" };
	char text[512];

	(void)state;
	for (int c = 0; c < 3; c++) {
		for (int grey = 0; grey < 2; grey++) {
			snprintf(text, sizeof(text),
				 "mode 320x200 %s\n"
				 "host-blit 0 0 40 30 pattern gradient\n"
				 "fill 10 10 8 8\n"
				 "encode %s 0x100000 0 0 40 30%s\n"
				 "decode 0x100000 100 50\n",
				 grey ? "i8" : "xrgb8888", codecs[c],
				 grey ? " grey" : "");
			assert_int_equal(run(dev, text, &res), 0);
			assert_int_equal(res.op_count[RDC_OP_DECODE], 1);
			if (c < 2 && !grey)
				assert_true(
					same_rect(dev, 0, 0, 100, 50, 40, 30));
		}
	}
	rdc_close(dev);
}

static void test_rdl_vram_load(void **state)
{
	struct rdc_script_result res;
	rdc_dev *dev = open_sim();
	char path[] = "/tmp/rdc-stream-XXXXXX", text[256];
	uint8_t px[16 * 8], st[512];
	size_t len;
	FILE *f;
	int fd = mkstemp(path);

	(void)state;
	assert_true(fd >= 0);
	close(fd);
	for (size_t i = 0; i < sizeof(px); i++)
		px[i] = (uint8_t)(i / 5);
	assert_int_equal(rdc_image_encode(RDC_IMG_RLE, px, 16, 8, 1, 16, st,
					  sizeof(st), &len),
			 0);
	f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(st, 1, len, f), len);
	fclose(f);
	snprintf(text, sizeof(text),
		 "mode 320x200 i8\nvram-load 0x100000 %s\n"
		 "decode 0x100000 4 4 %zu\n",
		 path, len);
	assert_int_equal(run(dev, text, &res), 0);
	/* the stream cut short by SIZE: the device says DATA */
	snprintf(text, sizeof(text), "decode 0x100000 4 4 %zu\n", len - 1);
	assert_int_equal(run(dev, text, &res), RDC_E_DEVICE);
	{
		uint32_t code = 0;

		assert_int_equal(rdc_dev_error(dev, &code, NULL), 0);
		assert_int_equal(code, RDC_ERR_DATA);
		assert_string_equal(rdc_dev_strerror(code), "DATA");
	}
	unlink(path);
	assert_int_equal(run(dev, "vram-load 0 /nonexistent/x\n", &res),
			 RDC_E_FILE);
	rdc_close(dev);
}

static void test_rdl_statements(void **state)
{
	struct rdc_script_result res;
	rdc_dev *dev = open_sim();
	static const char *const good[] = {
		"histogram 0 0 10 10 0x100000\n",
		"histogram 0 0 10 10 0x100000 green accum\n",
		"map-build equalize 0x100000 0x100400\n",
		"map-build stretch-auto 0x100000 0x100400 3\n",
		"map-build stretch 10 200 0x100400\n",
		"map-apply 0 0 10 10 0x100400\n",
		"map-clut 0x100400\n",
		"convolve 0 0 20 20 8 8 gauss\n",
		"convolve 0 0 20 20 8 8 sobel 2 10\n",
		"convolve 0 0 20 20 8 8 0 -1 0 -1 4 -1 0 -1 0 1 0 abs\n",
		/* DIV and BIAS are optional after a kernel too (rdl.md) */
		"convolve 0 0 20 20 8 8 0 0 0 0 1 0 0 0 0\n",
		"convolve 0 0 20 20 8 8 0 -1 0 -1 4 -1 0 -1 0 abs\n",
		"convolve 0 0 20 20 8 8 laplace abs\n",
		"threshold 0 0 10 10 128 red\n",
		"histogram-plot 0x100000 0 100 64 40\n",
	};
	static const char *const bad[] = {
		"histogram 0 0 10 10 0x100000 purple\n",
		"map-build median 0x100000 0x100400\n",
		"map-build stretch 10 300 0x100400\n",
		"convolve 0 0 20 20 8 8 blur\n",
		"convolve 0 0 20 20 8 8 1 1 1 1 1 1 1 1 300 9\n",
		"convolve 0 0 20 20 8 8 sobel abs\n",
		"convolve 0 0 20 20 8 8 0 0 0 0 1 0 0 0\n",
		"encode jpeg 0x100000 0 0 8 8\n",
		"encode rle 0x100000 0 0 8 8 purple\n",
	};

	(void)state;
	assert_int_equal(run(dev, "mode 320x200 xrgb8888\n", &res), 0);
	for (size_t i = 0; i < sizeof(good) / sizeof(good[0]); i++) {
		if (run(dev, good[i], &res))
			fail_msg("'%s': %s", good[i], res.error_msg);
	}
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		if (run(dev, bad[i], &res) != RDC_E_PARSE)
			fail_msg("'%s' was accepted", bad[i]);
	/* a kernel without DIV is the kernel with DIV 1, BIAS 0 */
	{
		uint32_t w0[8], w1[8];

		assert_int_equal(
			run(dev,
			    "list 0x200000\n"
			    "convolve 0 0 20 20 8 8 1 2 1 2 4 2 1 2 1\n"
			    "end\n"
			    "list 0x200100\n"
			    "convolve 0 0 20 20 8 8 1 2 1 2 4 2 1 2 1 1 0\n"
			    "end\n",
			    &res),
			0);
		assert_int_equal(rdc_vram_read(dev, 0x200000, w0, sizeof(w0)),
				 0);
		assert_int_equal(rdc_vram_read(dev, 0x200100, w1, sizeof(w1)),
				 0);
		assert_int_equal(RDC_CMD_OP(w0[0]), RDC_OP_CONVOLVE);
		assert_memory_equal(w0, w1, sizeof(w0));
	}
	/* a rectangle off the screen */
	assert_int_equal(run(dev, "encode rle 0x100000 300 0 40 8\n", &res),
			 RDC_E_RANGE);
	rdc_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_encode_args),
		cmocka_unit_test(test_png_read),
		cmocka_unit_test(test_rdl_encode_decode),
		cmocka_unit_test(test_rdl_vram_load),
		cmocka_unit_test(test_rdl_statements),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
