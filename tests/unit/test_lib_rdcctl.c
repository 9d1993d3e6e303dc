// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
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
	/* a command without the argument it needs, or with one too many, is
	 * bad usage, told before a device is opened (the device is not
	 * there) */
	assert_int_equal(ctl("run"), 2);
	assert_non_null(strstr(out, "run needs a script"));
	assert_int_equal(ctl("--connect unix:/nonexistent-dir/x run"), 2);
	assert_int_equal(ctl("replay"), 2);
	assert_int_equal(ctl("list extra"), 2);
	assert_int_equal(ctl("regs a.rdl b.rdl"), 2);
	assert_int_equal(ctl("run /nonexistent.rdl"), 1);
	/* no such device on USB, or no libusb in this build */
	assert_int_equal(ctl("--uri usb:fffe:fffd stats"), 1);
#ifdef RDC_HAVE_USB
	assert_non_null(strstr(out, "transport failure"));
#else
	assert_non_null(strstr(out, "not supported"));
#endif
	/* nobody listening there: the reason, and what to do */
	assert_int_equal(ctl("--connect unix:/nonexistent-dir/x stats"), 1);
	assert_non_null(strstr(out, "transport failure"));
	assert_non_null(strstr(out, "No such file or directory"));
	assert_non_null(strstr(out, "is rdcd running?"));
	assert_int_equal(ctl("--uri nope: stats"), 1);
	/* no framebuffer node: whether rdcfb.ko is loaded, and how to load
	 * it; a node that is not rdcfb's: said so */
	assert_int_equal(ctl("--connect fbdev:/nonexistent-dir/fb9 stats"), 1);
	assert_non_null(strstr(out, "/nonexistent-dir/fb9: No such file or "
				    "directory"));
	if (access("/sys/module/rdcfb", F_OK)) {
		assert_non_null(strstr(out, "rdcfb.ko is not loaded"));
		assert_non_null(strstr(out, "modprobe rdcfb"));
	} else {
		assert_non_null(strstr(out, "rdcctl list"));
	}
	assert_int_equal(ctl("--connect fbdev:/dev/null stats"), 1);
	assert_non_null(strstr(out, "/dev/null is not rdcfb.ko's framebuffer"));

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

/*
 * A file that cannot be written fails the command with its name and the
 * system's reason, before any figures are printed.
 */
static void test_output_errors(void **state)
{
	char dir[] = "/tmp/rdcctl_out_XXXXXX", args[256], path[128];
	int n;

	(void)state;
	assert_int_equal(ctl("run examples/demo.rdl -o /nonexistent-dir/x.png"),
			 1);
	assert_non_null(strstr(out, "/nonexistent-dir/x.png"));
	assert_non_null(strstr(out, "No such file or directory"));
	assert_null(strstr(out, "crc32"));
	assert_null(strstr(out, "cycles"));
	assert_int_equal(
		ctl("run examples/demo.rdl --vcd /nonexistent-dir/x.vcd"), 1);
	assert_non_null(strstr(out, "/nonexistent-dir/x.vcd"));
	assert_non_null(strstr(out, "No such file or directory"));

	/* stream --png makes its directory, parents too */
	assert_non_null(mkdtemp(dir));
	snprintf(args, sizeof(args),
		 "stream --fast --script examples/demo.rdl --png %s/a/shots "
		 "--png-every 2 --frames 5",
		 dir);
	assert_int_equal(ctl(args), 0);
	for (n = 0; n < 6; n++) {
		snprintf(path, sizeof(path), "%s/a/shots/frame-%08d.png", dir,
			 n);
		assert_int_equal(access(path, R_OK), n % 2 || n == 5 ? -1 : 0);
		if (!access(path, R_OK))
			unlink(path);
	}
	snprintf(path, sizeof(path), "%s/a/shots", dir);
	assert_int_equal(rmdir(path), 0);
	/* --png alone: every 60th frame, as rdcd's --png */
	snprintf(args, sizeof(args),
		 "stream --fast --script examples/demo.rdl --png %s/a "
		 "--frames 61",
		 dir);
	assert_int_equal(ctl(args), 0);
	assert_non_null(strstr(out, "written 2 "));
	for (n = 0; n <= 60; n += 60) {
		snprintf(path, sizeof(path), "%s/a/frame-%08d.png", dir, n);
		assert_int_equal(unlink(path), 0);
	}
	/* where it cannot: the command fails once, saying why */
	snprintf(path, sizeof(path), "%s/a/file", dir);
	{
		FILE *f = fopen(path, "w");

		assert_non_null(f);
		fclose(f);
	}
	snprintf(args, sizeof(args),
		 "stream --fast --script examples/demo.rdl --png %s/shots "
		 "--png-every 1 --frames 5",
		 path);
	assert_int_equal(ctl(args), 1);
	assert_non_null(strstr(out, "Not a directory"));
	assert_non_null(strstr(out, path));
	assert_null(
		strstr(strstr(out, "Not a directory") + 1, "Not a directory"));
	unlink(path);
	snprintf(path, sizeof(path), "%s/a", dir);
	assert_int_equal(rmdir(path), 0);
	assert_int_equal(rmdir(dir), 0);
}

/* A script error names the file, line and column; English plurals. */
static void test_script_messages(void **state)
{
	char path[] = "/tmp/rdcctl_rdl_XXXXXX", args[128], want[64];
	int fd = mkstemp(path);
	FILE *f;

	(void)state;
	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	fputs("mode 320x200 xrgb8888\n  fg #gg0000\n", f);
	fclose(f);
	snprintf(args, sizeof(args), "run %s", path);
	assert_int_equal(ctl(args), 1);
	snprintf(want, sizeof(want), "%s:2:6: error: bad colour '#gg0000'",
		 path);
	assert_non_null(strstr(out, want));
	f = fopen(path, "w");
	assert_non_null(f);
	fputs("fill 1\n", f);
	fclose(f);
	assert_int_equal(ctl(args), 1);
	assert_non_null(strstr(out, "fill: 1 argument (takes 4)"));
	unlink(path);
}

/*
 * A trace cut short (rdcd still recording, or killed) is replayed up to
 * its last complete record and said to be truncated; one that is not a
 * trace is refused as such.
 */
static void test_replay_messages(void **state)
{
	char path[] = "/tmp/rdcctl_trace_XXXXXX", args[128];
	int fd = mkstemp(path);
	FILE *f;

	(void)state;
	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	/* a header (version 2, 64 KiB of VRAM) and half a record */
	fwrite("RDCTRACE\x02\0\0\0\0\0\x01\0\x05\0\0", 1, 19, f);
	fclose(f);
	snprintf(args, sizeof(args), "replay %s", path);
	assert_int_equal(ctl(args), 0);
	assert_non_null(strstr(out, "truncated trace"));
	assert_non_null(strstr(out, "records 0"));
	f = fopen(path, "w");
	assert_non_null(f);
	fputs("fill 0 0 1 1\n", f);
	fclose(f);
	assert_int_equal(ctl(args), 1);
	assert_non_null(strstr(out, "not an rdcd trace"));
	assert_null(strstr(out, "syntax"));
	unlink(path);
}

static void test_regs_and_stats(void **state)
{
	(void)state;
	assert_int_equal(ctl("regs"), 0);
	assert_non_null(strstr(out, "CLUT_INDEX"));
	/* reads that pop or advance something are left out */
	assert_non_null(strstr(out, "RDATA              (not read)"));
	assert_non_null(strstr(out, "CLUT_DATA          (not read)"));
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
		cmocka_unit_test(test_output_errors),
		cmocka_unit_test(test_script_messages),
		cmocka_unit_test(test_replay_messages),
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
