// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc's fbdev: backend without rdcfb.ko: every URI that does not name
 * an rdcfb framebuffer is refused with a clear error, and nothing is left
 * open behind it.  The backend's work on the real device is tested in the
 * VM (tests/vm/tests/rdcfb-*.sh).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"

static void fbdev_open_fails(const char *uri, int want)
{
	rdc_dev *dev = (rdc_dev *)&dev;

	assert_int_equal(rdc_open(uri, &dev), want);
	assert_null(dev);
}

/* The lowest free descriptor: a refused open must not leak one. */
static int fbdev_next_fd(void)
{
	int fd = dup(0);

	assert_true(fd >= 0);
	close(fd);
	return fd;
}

static void test_fbdev_no_path(void **state)
{
	(void)state;
	fbdev_open_fails("fbdev:", RDC_E_URI);
	fbdev_open_fails("fbdev", RDC_E_URI);
	/* a device node is named by its absolute path */
	fbdev_open_fails("fbdev:fb0", RDC_E_URI);
	fbdev_open_fails("fbdev:dev/fb0", RDC_E_URI);
}

static void test_fbdev_missing_node(void **state)
{
	(void)state;
	fbdev_open_fails("fbdev:/nonexistent-dir/fb0", RDC_E_FILE);
	fbdev_open_fails("fbdev:/dev/fb-rdc-test-none", RDC_E_FILE);
}

/* /dev/null is a character device, but not a framebuffer. */
static void test_fbdev_not_a_framebuffer(void **state)
{
	int fd0 = fbdev_next_fd();

	(void)state;
	fbdev_open_fails("fbdev:/dev/null", RDC_E_URI);
	fbdev_open_fails("fbdev:/dev/zero", RDC_E_URI);
	assert_int_equal(fbdev_next_fd(), fd0);
}

static void test_fbdev_regular_file(void **state)
{
	char path[] = "/tmp/rdc-fbdev-test-XXXXXX";
	char uri[sizeof(path) + 8];
	static const char junk[4096] = "not a framebuffer";
	int fd0, fd = mkstemp(path);

	(void)state;
	assert_true(fd >= 0);
	assert_int_equal(write(fd, junk, sizeof(junk)), (int)sizeof(junk));
	close(fd);
	fd0 = fbdev_next_fd();
	snprintf(uri, sizeof(uri), "fbdev:%s", path);
	fbdev_open_fails(uri, RDC_E_URI);
	assert_int_equal(fbdev_next_fd(), fd0);
	unlink(path);
}

static void test_fbdev_directory(void **state)
{
	(void)state;
	/* opening a directory read-write fails: not a device either way */
	fbdev_open_fails("fbdev:/", RDC_E_URI);
	fbdev_open_fails("fbdev:/tmp", RDC_E_URI);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_fbdev_no_path),
		cmocka_unit_test(test_fbdev_missing_node),
		cmocka_unit_test(test_fbdev_not_a_framebuffer),
		cmocka_unit_test(test_fbdev_regular_file),
		cmocka_unit_test(test_fbdev_directory),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
