// SPDX-License-Identifier: GPL-2.0-only
/*
 * rdcctl as a program: what `run` prints agrees with the library (the
 * golden list is written from it), exit codes, errors with line numbers.
 * The binary is found next to this test's directory ($(O)/san/rdcctl).
 */
#include <libgen.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"

static char rdcctl[512];
static char out[16384];

/* Run rdcctl with `args`, stdout and stderr into out; exit status. */
static int ctl(const char *args)
{
	char cmd[1024];
	FILE *p;
	size_t n;
	int st;

	snprintf(cmd, sizeof(cmd), "%s %s 2>&1", rdcctl, args);
	p = popen(cmd, "r");
	assert_non_null(p);
	n = fread(out, 1, sizeof(out) - 1, p);
	out[n] = 0;
	st = pclose(p);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void test_run_matches_library(void **state)
{
	static const char scene[] = "tests/golden/scenes/circles.rdl";
	static struct rdc_script_result res;
	unsigned int crc_ctl = 0;
	unsigned long long t_ctl = 0;
	uint32_t crc = 0;
	uint64_t t = 0;
	rdc_dev *dev;
	char *p;

	(void)state;
	assert_int_equal(ctl("run tests/golden/scenes/circles.rdl"), 0);
	p = strstr(out, "\ncrc32 ");
	assert_non_null(p);
	assert_int_equal(sscanf(p, "\ncrc32 %x", &crc_ctl), 1);
	p = strstr(out, "\ntotal ");
	assert_non_null(p);
	assert_int_equal(sscanf(p, "\ntotal %llu", &t_ctl), 1);
	assert_non_null(strstr(out, "fill-circle"));

	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_script_run_file(dev, scene, &res), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	assert_int_equal(rdc_script_frame_wait(dev, &res), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	rdc_close(dev);
	assert_int_equal(crc_ctl, crc);
	assert_int_equal(t_ctl, t);
}

static void test_errors_and_exit_codes(void **state)
{
	char path[] = "/tmp/rdcctl_XXXXXX";
	char args[128];
	FILE *f;
	int fd;

	(void)state;
	assert_int_equal(ctl("--help"), 0);
	assert_non_null(strstr(out, "usage"));
	assert_int_equal(ctl(""), 2);
	assert_int_equal(ctl("frobnicate"), 2);
	assert_int_equal(ctl("run --bogus x"), 2);
	assert_int_equal(ctl("run /nonexistent.rdl"), 1);
	/* no such device on USB, or no libusb in this build */
	assert_int_equal(ctl("--uri usb:fffe:fffd stats"), 1);
#ifdef RDC_HAVE_USB
	assert_non_null(strstr(out, "transport failure"));
#else
	assert_non_null(strstr(out, "not supported"));
#endif
	/* nobody listening there */
	assert_int_equal(ctl("--connect unix:/nonexistent-dir/x stats"), 1);
	assert_non_null(strstr(out, "transport failure"));
	assert_int_equal(ctl("--uri nope: stats"), 1);

	fd = mkstemp(path);
	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	fputs("# ok\nfill 0 0 4 4\n\nline 1 2 3\n", f);
	fclose(f);
	snprintf(args, sizeof(args), "run %s", path);
	assert_int_equal(ctl(args), 1);
	/* file:line: error: ... */
	{
		char want[64];

		snprintf(want, sizeof(want), "%s:4: error:", path);
		assert_non_null(strstr(out, want));
	}
	unlink(path);
}

static void test_regs_and_stats(void **state)
{
	(void)state;
	assert_int_equal(ctl("regs"), 0);
	assert_non_null(strstr(out, "CLUT_INDEX"));
	assert_non_null(strstr(out, "0x31434452")); /* ID */
	assert_int_equal(ctl("stats tests/golden/scenes/lines.rdl"), 0);
	assert_non_null(strstr(out, "commands"));
	assert_int_equal(ctl("--uri sim:vram=4M regs"), 0);
	assert_non_null(strstr(out, "VRAM_SIZE          0x00400000"));
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_run_matches_library),
		cmocka_unit_test(test_errors_and_exit_codes),
		cmocka_unit_test(test_regs_and_stats),
	};
	char self[400];

	(void)argc;
	snprintf(self, sizeof(self), "%s", argv[0]);
	/* $(O)/san/tests/test_lib_rdcctl -> $(O)/san/rdcctl */
	snprintf(rdcctl, sizeof(rdcctl), "%s/../rdcctl", dirname(self));
	if (access(rdcctl, X_OK)) {
		fprintf(stderr, "test_lib_rdcctl: %s not built\n", rdcctl);
		return 1;
	}
	return cmocka_run_group_tests(tests, NULL, NULL);
}
