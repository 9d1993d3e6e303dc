// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Traces read while they are written, and traces cut short: the recorder
 * flushes whenever a client gets an answer, so a replay while it still
 * records gives the frames the client saw, and reports the trace as
 * truncated (no END record), not as damaged.  A damaged trace is
 * refused with where it went wrong.  The recording daemon: test_rdcd_proto.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "hw.h"
#include "rdc.h"
#include "rdc_priv.h" /* rdc_rec_*: what rdcd --record does */
#include "test_net_common.h"

#define VRAM (4u << 20)

static const char scene[] = "mode 320x200 xrgb8888\n"
			    "fg #102040\nfill 0 0 320 200\n"
			    "fg #ffc040\nfill-circle 160 100 60\n"
			    "fg #ffffff\nline 0 0 319 199\n";

static char dir[32];
static char trace[128], cut[128];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/rdc-replay-XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	snprintf(trace, sizeof(trace), "%s/trace", dir);
	snprintf(cut, sizeof(cut), "%s/cut", dir);
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	unlink(trace);
	unlink(cut);
	rmdir(dir);
	return 0;
}

/* The first `n` bytes of trace into cut, then `tail` (tail_len bytes). */
static void copy_cut(long n, const void *tail, size_t tail_len)
{
	FILE *in = fopen(trace, "rb"), *out = fopen(cut, "wb");
	char buf[4096];

	assert_non_null(in);
	assert_non_null(out);
	while (n > 0) {
		size_t k = fread(buf, 1, RDC_MIN(sizeof(buf), (size_t)n), in);

		assert_true(k > 0);
		assert_int_equal(fwrite(buf, 1, k, out), k);
		n -= (long)k;
	}
	if (tail_len)
		assert_int_equal(fwrite(tail, 1, tail_len, out), tail_len);
	fclose(in);
	assert_int_equal(fclose(out), 0);
}

static long file_size(const char *path)
{
	struct stat st;

	assert_int_equal(stat(path, &st), 0);
	return (long)st.st_size;
}

static void test_live_and_cut(void **state)
{
	struct rdc_replay_result res;
	struct rdc_rec *rec;
	struct rdc_hw *hw;
	rdc_dev *dev;
	uint32_t crc = 0;
	uint64_t t = 0;
	long size;

	(void)state;
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	hw = rdc_sim_hw(dev);
	assert_non_null(hw);
	rec = rdc_rec_open(trace, VRAM);
	assert_non_null(rec);
	rdc_rec_attach(rec, dev);
	assert_int_equal(rdc_script_run(dev, scene, strlen(scene), NULL), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);

	/* still recording: what the client saw is in the file already */
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.mismatches, 0);
	assert_true(res.frames > 0);
	assert_int_equal(res.frame_crc, crc);
	assert_int_equal(res.time, t);
	size = file_size(trace);

	/* time moved on the chip itself (as rdcd's waits do) is in the
	 * file once synced */
	rdc_rec_time_moved(rec, hw->now);
	rdc_hw_run_until(hw, t + 100000);
	rdc_rec_sync(rec);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.time, t + 100000);
	size = file_size(trace);

	/* closed: END is there, the trace is whole */
	assert_int_equal(rdc_rec_close(rec, dev), 0);
	rdc_close(dev);
	assert_true(file_size(trace) > size);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 0);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.frame_crc, crc);

	/* cut inside a record: replayed up to the one before */
	copy_cut(size - 3, NULL, 0);
	assert_int_equal(rdc_replay_file(cut, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.mismatches, 0);
	/* cut inside the header: not a trace */
	copy_cut(10, NULL, 0);
	assert_int_equal(rdc_replay_file(cut, &res, NULL), RDC_E_PARSE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE), cut));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE), "RDCTRACE"));
	/* an unknown record type is damage, even in the last bytes */
	copy_cut(size, "\x63", 1);
	assert_int_equal(rdc_replay_file(cut, &res, NULL), RDC_E_PARSE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE),
			       "unknown record type"));
	{
		char want[64];

		snprintf(want, sizeof(want), "at byte %ld", size);
		assert_non_null(
			strstr(rdc_last_error_detail(RDC_E_PARSE), want));
	}
	/* a missing file says which and why */
	unlink(cut);
	assert_int_equal(rdc_replay_file(cut, &res, NULL), RDC_E_FILE);
	assert_non_null(
		strstr(rdc_last_error_detail(RDC_E_FILE), "No such file"));
	/* a detail is only given for the error it belongs to */
	assert_string_equal(rdc_last_error_detail(RDC_E_PARSE), "");
}

/*
 * The README's session: rdcd records, a client runs a scene and leaves,
 * and the trace replays while rdcd is still up, to the client's frame.
 */
static void test_daemon_still_recording(void **state)
{
	const char *args[] = { "--stepped", "--record", trace, NULL };
	struct rdc_replay_result res;
	struct netd d;
	rdc_dev *dev;
	uint32_t crc = 0, n;

	(void)state;
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_script_run(dev, scene, strlen(scene), NULL), 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	/* the daemon moved time for the waits itself: a register read
	 * after them puts that time in the file */
	assert_int_equal(rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &n), 0);
	rdc_close(dev);

	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.frame_crc, crc);
	assert_int_equal(netd_stop(&d), 0);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 0);
	assert_int_equal(res.frame_crc, crc);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_live_and_cut, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_daemon_still_recording,
						setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
