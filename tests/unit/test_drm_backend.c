// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc's drm: backend without rdcdrm.ko: every URI that does not name
 * an rdc card is refused with the right error and a detail that says what
 * the node is (or that the module is not loaded, and how to load it), and
 * nothing is left open behind it.  Any DRM card this machine has that is
 * not rdc is refused by its driver's name.  The backend's work on the
 * real card is tested in the VM (tests/vm/tests/rdcdrm-*.sh).
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"

/* The lowest free descriptor: a refused open must not leak one. */
static int drm_next_fd(void)
{
	int fd = dup(0);

	assert_true(fd >= 0);
	close(fd);
	return fd;
}

/* rdc_open(uri) fails with `want`, its detail holds `says`, no fd kept. */
static void drm_open_fails(const char *uri, int want, const char *says)
{
	rdc_dev *dev = (rdc_dev *)&dev;
	int fd0 = drm_next_fd();
	int ret = rdc_open(uri, &dev);

	print_message("%s: %s (%s)\n", uri, rdc_strerror(ret),
		      rdc_last_error_detail(ret));
#ifndef RDC_HAVE_DRM
	/* a build without libdrm knows the scheme and has no backend */
	want = RDC_E_NOSYS;
	says = "built without";
#endif
	assert_int_equal(ret, want);
	assert_null(dev);
	if (says)
		assert_non_null(strstr(rdc_last_error_detail(ret), says));
	assert_int_equal(drm_next_fd(), fd0);
}

static void drm_count(const struct rdc_found *f, void *arg)
{
	if (!strncmp(f->uri, "drm:", 4))
		++*(int *)arg;
}

/* How many rdc cards rdc_list finds here (none, without the module). */
static int drm_rdc_cards(void)
{
	int n = 0;

	assert_true(rdc_list(drm_count, &n) >= 0);
	return n;
}

static void test_drm_no_path(void **state)
{
	(void)state;
	/* a device node is named by its absolute path */
	drm_open_fails("drm:card0", RDC_E_URI, "drm:/dev/dri/cardN");
	drm_open_fails("drm:dev/dri/card0", RDC_E_URI, "drm:/dev/dri/cardN");
	drm_open_fails("drm:?x", RDC_E_URI, NULL);
}

/* No rdc card at all: "drm:" says the module is not loaded and how. */
static void test_drm_no_card(void **state)
{
	(void)state;
	if (drm_rdc_cards()) {
		skip();
		return;
	}
	drm_open_fails("drm:", RDC_E_FILE, "modprobe rdcdrm");
	drm_open_fails("drm", RDC_E_FILE, "insmod rdcdrm.ko");
}

static void test_drm_missing_node(void **state)
{
	(void)state;
	drm_open_fails("drm:/nonexistent-dir/card0", RDC_E_FILE,
		       "rdcdrm.ko is not loaded");
	drm_open_fails("drm:/dev/dri/card-rdc-test-none", RDC_E_FILE,
		       "modprobe rdcdrm");
}

/* /dev/null and /dev/zero are character devices, but not DRM's. */
static void test_drm_not_drm(void **state)
{
	(void)state;
	drm_open_fails("drm:/dev/null", RDC_E_URI, "not a DRM device");
	drm_open_fails("drm:/dev/zero", RDC_E_URI, "not a DRM device");
}

static void test_drm_regular_file(void **state)
{
	char path[] = "/tmp/rdc-drm-test-XXXXXX";
	char uri[sizeof(path) + 8];
	static const char junk[4096] = "not a DRM card";
	int fd = mkstemp(path);

	(void)state;
	assert_true(fd >= 0);
	assert_int_equal(write(fd, junk, sizeof(junk)), (int)sizeof(junk));
	close(fd);
	snprintf(uri, sizeof(uri), "drm:%s", path);
	drm_open_fails(uri, RDC_E_URI, "a regular file");
	unlink(path);
}

static void test_drm_directory(void **state)
{
	(void)state;
	drm_open_fails("drm:/", RDC_E_URI, "not a DRM device");
	drm_open_fails("drm:/tmp", RDC_E_URI, "not a DRM device");
}

/*
 * Every DRM card of this machine that rdc_list does not name (a GPU,
 * vkms, a virtual display): refused by its driver's name, and nothing
 * kept open.  None here: nothing to check.
 */
static void test_drm_other_cards(void **state)
{
	DIR *d = opendir("/dev/dri");
	struct dirent *e;
	int tried = 0;

	(void)state;
	if (!d) {
		skip();
		return;
	}
	while ((e = readdir(d))) {
		char uri[300];
		rdc_dev *dev = NULL;
		int ret;

		if (strncmp(e->d_name, "card", 4))
			continue;
		snprintf(uri, sizeof(uri), "drm:/dev/dri/%.200s", e->d_name);
		ret = rdc_open(uri, &dev);
		if (!ret) { /* an rdc card: listed, and opens */
			rdc_close(dev);
			continue;
		}
		if (ret == RDC_E_FILE) /* no permission to open it */
			continue;
		drm_open_fails(uri, RDC_E_URI, "not rdcdrm.ko's");
		tried++;
	}
	closedir(d);
	print_message("%d DRM card(s) of other drivers refused\n", tried);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_drm_no_path),
		cmocka_unit_test(test_drm_no_card),
		cmocka_unit_test(test_drm_missing_node),
		cmocka_unit_test(test_drm_not_drm),
		cmocka_unit_test(test_drm_regular_file),
		cmocka_unit_test(test_drm_directory),
		cmocka_unit_test(test_drm_other_cards),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
