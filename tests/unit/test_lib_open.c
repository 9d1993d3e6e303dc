// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/* librdc: device URIs, error strings, presets, register names. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"

static void open_ok(const char *uri, uint32_t want_vram)
{
	rdc_dev *dev = NULL;
	uint32_t v = 0;

	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_non_null(dev);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_ID, &v), 0);
	assert_int_equal(v, RDC_ID_VALUE);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_VRAM_SIZE, &v), 0);
	assert_int_equal(v, want_vram);
	rdc_close(dev);
}

static void test_open_good(void **state)
{
	(void)state;
	open_ok("sim:", 16u << 20);
	open_ok("", 16u << 20);
	open_ok(NULL, 16u << 20);
	open_ok("sim", 16u << 20);
	open_ok("sim:vram=4M", 4u << 20);
	open_ok("sim:vram=64K", 64u << 10);
	open_ok("sim:vram=256M", 256u << 20);
	open_ok("sim:vram=131072", 128u << 10);
}

static void open_fails(const char *uri, int want)
{
	rdc_dev *dev = (rdc_dev *)&dev;

	assert_int_equal(rdc_open(uri, &dev), want);
	assert_null(dev);
}

static void test_open_bad(void **state)
{
	(void)state;
	/* malformed options of a known scheme */
	open_fails("sim:vram=", RDC_E_URI);
	open_fails("sim:vram=4G", RDC_E_URI);
	open_fails("sim:vram=1K", RDC_E_URI);	 /* below 64 KiB */
	open_fails("sim:vram=512M", RDC_E_URI);	 /* above 256 MiB */
	open_fails("sim:vram=65537", RDC_E_URI); /* not a multiple of 4 */
	open_fails("sim:vram=4MB", RDC_E_URI);
	open_fails("sim:vram=x", RDC_E_URI);
	open_fails("sim:colour=blue", RDC_E_URI);
	open_fails("sim:vram=99999999999999999999", RDC_E_URI);
	/* unknown schemes */
	open_fails("simulator:", RDC_E_URI);
	open_fails("http://x", RDC_E_URI);
	open_fails(":", RDC_E_URI);
	/* socket transports: nobody listening, or a malformed address */
	open_fails("unix:/nonexistent-dir/rdc.sock", RDC_E_IO);
	open_fails("tcp:localhost", RDC_E_URI);
	open_fails("tcp:localhost:", RDC_E_URI);
	open_fails("unix:/tmp/x.sock?colour=blue", RDC_E_URI);
	/* usb: (test_usb_open.c): no device with these IDs, a bad address */
#ifdef RDC_HAVE_USB
	open_fails("usb:fffe:fffd", RDC_E_IO);
	open_fails("usb:12345:1", RDC_E_URI);
#else
	open_fails("usb:fffe:fffd", RDC_E_NOSYS);
#endif
	/* fbdev: (test_fbdev_backend.c): a node that does not exist */
	open_fails("fbdev:/nonexistent-dir/fb0", RDC_E_FILE);
	assert_int_equal(rdc_open("sim:", NULL), RDC_E_INVAL);
}

static void test_strerror_every_code(void **state)
{
	const char *seen[-RDC_E_COUNT_];

	(void)state;
	for (int e = 0; e > RDC_E_COUNT_; e--) {
		const char *s = rdc_strerror(e);

		assert_non_null(s);
		assert_true(strlen(s) > 3);
		assert_string_not_equal(s, "unknown error");
		/* each code has its own text */
		for (int k = 0; k > e; k--)
			assert_string_not_equal(s, seen[-k]);
		seen[-e] = s;
	}
	assert_string_equal(rdc_strerror(RDC_E_COUNT_), "unknown error");
	assert_string_equal(rdc_strerror(1), "unknown error");
	assert_string_equal(rdc_strerror(-1000), "unknown error");
}

static void test_dev_strerror(void **state)
{
	(void)state;
	assert_string_equal(rdc_dev_strerror(RDC_ERR_NONE), "NONE");
	assert_string_equal(rdc_dev_strerror(RDC_ERR_RANGE), "RANGE");
	assert_string_equal(rdc_dev_strerror(RDC_ERR_MODE), "MODE");
	for (uint32_t c = 0; c < RDC_ERR_COUNT; c++)
		assert_string_not_equal(rdc_dev_strerror(c), "UNKNOWN");
	assert_string_equal(rdc_dev_strerror(RDC_ERR_COUNT), "UNKNOWN");
}

static void test_presets(void **state)
{
	uint32_t w = 0, h = 0;

	(void)state;
	assert_int_equal(rdc_preset_by_name("640x480"), RDC_PRESET_640x480_60);
	assert_int_equal(rdc_preset_by_name("640x480@60"),
			 RDC_PRESET_640x480_60);
	assert_int_equal(rdc_preset_by_name("320x200"), RDC_PRESET_320x200_70);
	assert_int_equal(rdc_preset_by_name("1080p"), RDC_PRESET_1920x1080_60);
	assert_int_equal(rdc_preset_by_name("720p"), RDC_PRESET_1280x720_60);
	/* names are case-insensitive (docs/rdl.md) */
	assert_int_equal(rdc_preset_by_name("720P"), RDC_PRESET_1280x720_60);
	assert_int_equal(rdc_preset_by_name("1280X720"),
			 RDC_PRESET_1280x720_60);
	assert_int_equal(rdc_preset_by_name("1920X1080@60"),
			 RDC_PRESET_1920x1080_60);
	assert_int_equal(rdc_preset_by_name("640x480@75"), -1);
	assert_int_equal(rdc_preset_by_name("640x48"), -1);
	assert_int_equal(rdc_preset_by_name(""), -1);
	assert_int_equal(rdc_preset_by_name(NULL), -1);
	assert_int_equal(rdc_preset_size(RDC_PRESET_800x600_60, &w, &h), 0);
	assert_int_equal(w, 800);
	assert_int_equal(h, 600);
	assert_int_equal(rdc_preset_size(RDC_PRESET_1920x1080_60, &w, &h), 0);
	assert_int_equal(w, 1920);
	assert_int_equal(h, 1080);
	assert_int_equal(rdc_preset_size(RDC_PRESET_COUNT, &w, &h),
			 RDC_E_INVAL);
}

static void test_reg_names(void **state)
{
	uint32_t reg = 0;
	size_t n = rdc_reg_count();

	(void)state;
	assert_int_equal(rdc_reg_by_name("CLUT_INDEX", &reg), 0);
	assert_int_equal(reg, RDC_REG_CLUT_INDEX);
	assert_int_equal(rdc_reg_by_name("rdc_reg_fifo_free", &reg), 0);
	assert_int_equal(reg, RDC_REG_FIFO_FREE);
	assert_int_equal(rdc_reg_by_name("NOPE", &reg), RDC_E_INVAL);
	assert_true(n > 50);
	for (size_t i = 0; i < n; i++) {
		uint32_t r = ~0u, back = ~0u;
		const char *name = rdc_reg_info(i, &r);

		assert_non_null(name);
		assert_true(r < RDC_REG_WINDOW);
		assert_int_equal(r & 3, 0);
		assert_int_equal(rdc_reg_by_name(name, &back), 0);
		assert_int_equal(back, r);
	}
	assert_null(rdc_reg_info(n, &reg));
}

static void test_reg_access_bounds(void **state)
{
	rdc_dev *dev;
	uint32_t v;

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_WINDOW, &v), RDC_E_RANGE);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_ID + 2, &v), RDC_E_RANGE);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_WINDOW + 4, 0),
			 RDC_E_RANGE);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_LINE_COMPARE, 123), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_LINE_COMPARE, &v), 0);
	assert_int_equal(v, 123);
	rdc_close(dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_open_good),
		cmocka_unit_test(test_open_bad),
		cmocka_unit_test(test_strerror_every_code),
		cmocka_unit_test(test_dev_strerror),
		cmocka_unit_test(test_presets),
		cmocka_unit_test(test_reg_names),
		cmocka_unit_test(test_reg_access_bounds),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
