// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: PNG output read back with libpng equals the frame. */
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"

/* Read an 8-bit RGB PNG into XRGB8888 (libpng's simplified API). */
static uint32_t *png_load(const char *path, uint32_t *w, uint32_t *h)
{
	png_image img;
	uint8_t *rgb;
	uint32_t *out;

	memset(&img, 0, sizeof(img));
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&img, path))
		return NULL;
	img.format = PNG_FORMAT_RGB;
	rgb = malloc(PNG_IMAGE_SIZE(img));
	out = malloc((size_t)img.width * img.height * 4);
	if (!rgb || !out || !png_image_finish_read(&img, NULL, rgb, 0, NULL)) {
		free(rgb);
		free(out);
		png_image_free(&img);
		return NULL;
	}
	for (size_t i = 0; i < (size_t)img.width * img.height; i++)
		out[i] = (uint32_t)rgb[3 * i] << 16 |
			 (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];
	*w = img.width;
	*h = img.height;
	free(rgb);
	return out;
}

static void test_png_roundtrip_frame(void **state)
{
	static const char script[] = "mode 320x200 xrgb8888\n"
				     "host-blit 0 0 320 200 pattern noise 3\n"
				     "fg #ff8000\nfill-circle 160 100 50\n"
				     "text 10 10 \"png\"\n";
	char path[] = "/tmp/rdc_png_XXXXXX";
	uint32_t *frame, *back, w = 0, h = 0, bw = 0, bh = 0;
	rdc_dev *dev;
	int fd;

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_script_run(dev, script, strlen(script), NULL), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, &w, &h), RDC_E_RANGE);
	frame = malloc((size_t)w * h * 4);
	assert_non_null(frame);
	assert_int_equal(rdc_frame_grab(dev, frame, (size_t)w * h, &w, &h), 0);
	fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(rdc_png_write(path, frame, w, h, w), 0);
	back = png_load(path, &bw, &bh);
	unlink(path);
	assert_non_null(back);
	assert_int_equal(bw, w);
	assert_int_equal(bh, h);
	for (size_t i = 0; i < (size_t)w * h; i++)
		frame[i] &= 0xffffff; /* PNG has no X byte */
	assert_memory_equal(back, frame, (size_t)w * h * 4);
	free(back);
	free(frame);
	rdc_close(dev);
}

/* A pitch wider than the width: only w pixels of each row are written. */
static void test_png_pitch(void **state)
{
	uint32_t src[3 * 5], *back, w = 0, h = 0;
	char path[] = "/tmp/rdc_png_XXXXXX";
	int fd;

	(void)state;
	for (uint32_t i = 0; i < 15; i++)
		src[i] = 0x010203u * i;
	fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(rdc_png_write(path, src, 2, 3, 5), 0);
	back = png_load(path, &w, &h);
	unlink(path);
	assert_non_null(back);
	assert_int_equal(w, 2);
	assert_int_equal(h, 3);
	for (uint32_t y = 0; y < 3; y++)
		for (uint32_t x = 0; x < 2; x++)
			assert_int_equal(back[y * 2 + x], src[y * 5 + x]);
	free(back);
}

static void test_png_errors(void **state)
{
	uint32_t px[4] = { 0 };

	(void)state;
	assert_int_equal(rdc_png_write("/nonexistent/dir/x.png", px, 2, 2, 2),
			 RDC_E_FILE);
	assert_int_equal(rdc_png_write("/tmp/x.png", NULL, 2, 2, 2),
			 RDC_E_INVAL);
	assert_int_equal(rdc_png_write("/tmp/x.png", px, 0, 2, 2), RDC_E_INVAL);
	assert_int_equal(rdc_png_write("/tmp/x.png", px, 2, 2, 1), RDC_E_INVAL);
	assert_int_equal(rdc_png_write(NULL, px, 2, 2, 2), RDC_E_INVAL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_png_roundtrip_frame),
		cmocka_unit_test(test_png_pitch),
		cmocka_unit_test(test_png_errors),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
