// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * `rdcctl stream` as a program: the PNG stills it writes are the frames
 * the library itself gives for the same scripts, a mode change with --at
 * included, and its errors are reported.  The binary is found next to
 * this test's directory ($(O)/san/rdcctl); scripts are read from the
 * source root, where tests run.
 */
#include <libgen.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"

#define SCENE_A "tests/vm/scenes/stream_a.rdl"
#define SCENE_B "tests/vm/scenes/stream_b.rdl"

static char strm_rdcctl[512];
static char strm_dir[64];

static int strm_run(const char *args)
{
	char cmd[1024];
	int st;

	snprintf(cmd, sizeof(cmd), "%s stream %s >/dev/null 2>&1", strm_rdcctl,
		 args);
	st = system(cmd);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* The picture of the scripts run in order on a fresh sim:. */
static uint32_t *strm_expect(const char *const *scripts, int n, uint32_t *w,
			     uint32_t *h)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	uint32_t *px = NULL;
	rdc_dev *dev;

	assert_non_null(res);
	assert_int_equal(rdc_open("sim:", &dev), 0);
	for (int i = 0; i < n; i++) {
		memset(res, 0, sizeof(*res));
		assert_int_equal(rdc_script_run_file(dev, scripts[i], res), 0);
		assert_int_equal(rdc_script_frame_wait(dev, res), 0);
	}
	assert_int_equal(rdc_frame_grab(dev, NULL, 0, w, h), RDC_E_RANGE);
	px = malloc((size_t)*w * *h * 4);
	assert_non_null(px);
	assert_int_equal(rdc_frame_grab(dev, px, (size_t)*w * *h, w, h), 0);
	rdc_close(dev);
	free(res);
	return px;
}

static void strm_check_png(uint64_t seq, const uint32_t *want, uint32_t w,
			   uint32_t h)
{
	char path[128];
	png_image img;
	uint8_t *rgb;

	snprintf(path, sizeof(path), "%s/frame-%08llu.png", strm_dir,
		 (unsigned long long)seq);
	memset(&img, 0, sizeof(img));
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&img, path))
		fail_msg("%s: not readable", path);
	assert_int_equal(img.width, w);
	assert_int_equal(img.height, h);
	img.format = PNG_FORMAT_RGB;
	rgb = malloc(PNG_IMAGE_SIZE(img));
	assert_non_null(rgb);
	assert_true(png_image_finish_read(&img, NULL, rgb, 0, NULL));
	for (size_t i = 0; i < (size_t)w * h; i++) {
		uint32_t got = (uint32_t)rgb[3 * i] << 16 |
			       (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];

		if (got != (want[i] & 0xffffff))
			fail_msg("%s: pixel %zu is %06x, not %06x", path, i,
				 got, want[i] & 0xffffff);
	}
	free(rgb);
	unlink(path);
}

static int strm_setup(void **state)
{
	(void)state;
	strcpy(strm_dir, "/tmp/rdc_stream_XXXXXX");
	return mkdtemp(strm_dir) ? 0 : -1;
}

static int strm_teardown(void **state)
{
	(void)state;
	/* Every expected file was checked and removed: anything left over
	 * (an extra frame) makes rmdir fail the test. */
	return rmdir(strm_dir);
}

static void test_stream_png_every(void **state)
{
	static const char *const a[] = { SCENE_A };
	uint32_t w, h, *px = strm_expect(a, 1, &w, &h);
	char args[512];

	(void)state;
	snprintf(args, sizeof(args),
		 "--fast --script " SCENE_A
		 " --png %s --png-every 5 --frames 12",
		 strm_dir);
	assert_int_equal(strm_run(args), 0);
	assert_int_equal(w, 320);
	for (uint64_t seq = 0; seq < 12; seq += 5)
		strm_check_png(seq, px, w, h);
	free(px);
}

static void test_stream_mode_change(void **state)
{
	static const char *const a[] = { SCENE_A };
	static const char *const ab[] = { SCENE_A, SCENE_B };
	uint32_t wa, ha, wb, hb;
	uint32_t *pa = strm_expect(a, 1, &wa, &ha);
	uint32_t *pb = strm_expect(ab, 2, &wb, &hb);
	char args[512];

	(void)state;
	snprintf(args, sizeof(args),
		 "--fast --script " SCENE_A " --at 6 " SCENE_B
		 " --png %s --png-every 3 --frames 9",
		 strm_dir);
	assert_int_equal(strm_run(args), 0);
	assert_int_equal(wb, 640);
	strm_check_png(0, pa, wa, ha);
	strm_check_png(3, pa, wa, ha);
	strm_check_png(6, pb, wb, hb);
	free(pa);
	free(pb);
}

static void test_stream_errors(void **state)
{
	(void)state;
	assert_int_equal(strm_run("--frames 1 --script " SCENE_A), 1);
	assert_int_equal(strm_run("--frames"), 2);
	assert_int_equal(strm_run("--bogus 1"), 2);
	assert_int_equal(strm_run("--frames 1 --script " SCENE_A
				  " --v4l2 /nonexistent/video9"),
			 1);
	assert_int_equal(strm_run("--frames 1 --sink nosuch:x"), 1);
	assert_int_equal(strm_run("--frames 1 --script /nonexistent.rdl "
				  "--png /tmp"),
			 1);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_stream_png_every,
						strm_setup, strm_teardown),
		cmocka_unit_test_setup_teardown(test_stream_mode_change,
						strm_setup, strm_teardown),
		cmocka_unit_test(test_stream_errors),
	};
	char self[400];

	(void)argc;
	snprintf(self, sizeof(self), "%s", argv[0]);
	snprintf(strm_rdcctl, sizeof(strm_rdcctl), "%s/../rdcctl",
		 dirname(self));
	if (access(strm_rdcctl, X_OK)) {
		fprintf(stderr, "test_sink_stream: %s not built\n",
			strm_rdcctl);
		return 1;
	}
	return cmocka_run_group_tests(tests, NULL, NULL);
}
