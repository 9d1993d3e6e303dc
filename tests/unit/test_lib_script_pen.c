// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc: the .rdl statements of the light pen (lpen, lpen-expect) and
 * the lossy codecs' levels (encode dpcmq ... step N, encode dct ...
 * quality N): the registers they write, the latch they check, the
 * streams they write byte for byte against rdc_image_encode_lossy, and
 * their parse errors.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#define SCRIPT_FX_SAY_ERRORS
#include "script_fx.h"

/* The picture on show (calloc'd, 640x480 here). */
static uint32_t *frame(rdc_dev *dev, uint32_t *fw)
{
	uint32_t *pix = calloc(640 * 480, sizeof(*pix)), fh;

	assert_non_null(pix);
	assert_int_equal(rdc_frame_grab(dev, pix, 640 * 480, fw, &fh), 0);
	return pix;
}

static uint32_t reg(rdc_dev *dev, uint32_t r)
{
	uint32_t v = 0;

	assert_int_equal(rdc_reg_read(dev, r, &v), 0);
	return v;
}

/* A white square at 100,100 on black: lit inside, dark outside. */
static const char square[] = "mode 640x480 i8\n"
			     "load-clut 0 #000000 #ffffff #808080\n"
			     "fg 1\n"
			     "fill 100 100 50 50\n";

static void test_lpen(void **state)
{
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, square), 0);
	assert_int_equal(run(dev, "lpen 120 130 7\n"), 0);
	assert_int_equal(reg(dev, RDC_REG_LPEN_POS), 130u << 16 | 120);
	assert_int_equal(reg(dev, RDC_REG_LPEN_CTRL),
			 RDC_LPEN_CTRL_EN |
				 FIELD_PREP(RDC_LPEN_CTRL_THRESHOLD, 7));
	assert_int_equal(run(dev, "lpen-expect 120 130\n"), 0);
	assert_int_equal(res.frame_ready, 1);
	assert_int_equal(reg(dev, RDC_REG_LPEN_LATCH), 130u << 16 | 120);
	/* each lpen-expect watches a frame of its own */
	assert_int_equal(run(dev, "lpen-expect 120 130\nlpen-expect 120 130\n"),
			 0);
	/* lit where it is not expected, at another place, or dark */
	assert_int_equal(run(dev, "lpen-expect dark\n"), RDC_E_DEVICE);
	assert_non_null(strstr(res.error_msg, "latched at 120,130"));
	assert_int_equal(run(dev, "lpen-expect 121 130\n"), RDC_E_DEVICE);
	assert_non_null(strstr(res.error_msg, "expected 121,130"));
	assert_int_equal(run(dev, "lpen 10 10\nlpen-expect dark\n"), 0);
	assert_int_equal(run(dev, "lpen-expect 10 10\n"), RDC_E_DEVICE);
	assert_non_null(strstr(res.error_msg, "saw no light"));
	assert_int_equal(res.error_line, 1);
	/* the threshold: grey (luma 128) lit above 127, not above 128 */
	assert_int_equal(run(dev, "fg 2\nfill 200 200 10 10\n"
				  "lpen 205 205 127\nlpen-expect 205 205\n"
				  "lpen 205 205 128\nlpen-expect dark\n"),
			 0);
	/* off */
	assert_int_equal(run(dev, "lpen 120 130\nlpen off\nlpen-expect dark\n"),
			 0);
	assert_int_equal(reg(dev, RDC_REG_LPEN_CTRL), 0);
}

static void test_lpen_errors(void **state)
{
	static const char *const bad[] = {
		"lpen 1\n",
		"lpen 70000 1\n",
		"lpen 1 1 256\n",
		"lpen off 1\n",
		"lpen x y\n",
		"lpen-expect 1\n",
		"lpen-expect dark 1\n",
		"lpen 1 2 3 4\n",
		"lpen-expect\n",
	};
	rdc_dev *dev = *state;

	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		assert_int_equal(run(dev, bad[i]), RDC_E_PARSE);
		assert_int_equal(res.error_line, 1);
	}
}

/* The stream at addr is rdc_image_encode_lossy's of the screen's corner. */
static void check_stream(rdc_dev *dev, uint32_t addr, uint32_t codec,
			 uint32_t level, uint32_t ch)
{
	uint32_t *pix, fw;
	uint8_t smp[64 * 64 * 3], *want, *have;
	size_t cap = rdc_image_bound(codec, 64, 64, ch), len;

	want = malloc(cap);
	have = malloc(cap);
	assert_non_null(want);
	assert_non_null(have);
	pix = frame(dev, &fw);
	assert_int_equal(rdc_image_samples(pix, 64, 64, fw, ch, smp), 0);
	if (level)
		assert_int_equal(rdc_image_encode_lossy(codec, level, smp, 64,
							64, ch, 64 * ch, want,
							cap, &len),
				 0);
	else
		assert_int_equal(rdc_image_encode(codec, smp, 64, 64, ch,
						  64 * ch, want, cap, &len),
				 0);
	assert_int_equal(rdc_vram_read(dev, addr, have, len), 0);
	assert_memory_equal(have, want, len);
	free(pix);
	free(want);
	free(have);
}

static void test_encode_levels(void **state)
{
	static const char picture[] = "mode 640x480 xrgb8888\n"
				      "fg #204080\n"
				      "fill 0 0 64 64\n"
				      "fg #f0c010\n"
				      "fill-circle 32 32 20\n"
				      "fg #ffffff\n"
				      "line 0 63 63 0\n";
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, picture), 0);
	assert_int_equal(run(dev, "encode dpcmq 0x100000 0 0 64 64 grey "
				  "step 16\n"),
			 0);
	check_stream(dev, 0x100000, RDC_IMG_DPCMQ, 16, 1);
	assert_int_equal(run(dev, "encode dpcmq 0x100000 0 0 64 64 step 1\n"),
			 0);
	check_stream(dev, 0x100000, RDC_IMG_DPCMQ, 1, 3);
	assert_int_equal(run(dev, "encode dct 0x200000 0 0 64 64 quality 20\n"),
			 0);
	check_stream(dev, 0x200000, RDC_IMG_DCT, 20, 3);
	assert_int_equal(run(dev, "encode dct 0x200000 0 0 64 64 gray "
				  "quality 100\n"),
			 0);
	check_stream(dev, 0x200000, RDC_IMG_DCT, 100, 1);
	/* no level: the defaults, as rdc_image_encode */
	assert_int_equal(run(dev, "encode dct 0x200000 0 0 64 64\n"), 0);
	check_stream(dev, 0x200000, RDC_IMG_DCT, 0, 3);
	check_stream(dev, 0x200000, RDC_IMG_DCT, RDC_IMAGE_QUALITY_DEFAULT, 3);
	/* what draws: the coarser step, the more the picture moves */
	assert_int_equal(run(dev, "encode dpcmq 0x100000 0 0 64 64 step 64\n"
				  "decode 0x100000 100 0\n"
				  "encode dpcmq 0x100000 0 0 64 64 step 1\n"
				  "decode 0x100000 200 0\nwait-frame\n"),
			 0);
	{
		uint32_t fw, coarse = 0, exact = 0, *pix = frame(dev, &fw);

		for (uint32_t y = 0; y < 64; y++)
			for (uint32_t x = 0; x < 64; x++) {
				uint32_t p = pix[y * fw + x] & 0xffffff;

				coarse += (pix[y * fw + 100 + x] & 0xffffff) !=
					  p;
				exact += (pix[y * fw + 200 + x] & 0xffffff) !=
					 p;
			}
		free(pix);
		assert_int_equal(exact, 0);
		assert_true(coarse > 100);
	}
}

static void test_encode_level_errors(void **state)
{
	static const char *const bad[] = {
		"encode dpcmq 0 0 0 8 8 step 0\n",
		"encode dpcmq 0 0 0 8 8 step 256\n",
		"encode dct 0 0 0 8 8 quality 0\n",
		"encode dct 0 0 0 8 8 quality 101\n",
		"encode dct 0 0 0 8 8 step 4\n",
		"encode dpcmq 0 0 0 8 8 quality 50\n",
		"encode rle 0 0 0 8 8 step 4\n",
		"encode dct 0 0 0 8 8 quality\n",
		"encode dct 0 0 0 8 8 quality 50 grey\n",
	};
	rdc_dev *dev = *state;

	assert_int_equal(run(dev, "mode 640x480 xrgb8888\n"), 0);
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		assert_int_equal(run(dev, bad[i]), RDC_E_PARSE);
		assert_int_equal(res.error_line, 1);
	}
}

#define T(f) cmocka_unit_test_setup_teardown(f, dev_setup, dev_teardown)

int main(void)
{
	const struct CMUnitTest tests[] = {
		T(test_lpen),
		T(test_lpen_errors),
		T(test_encode_levels),
		T(test_encode_level_errors),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
