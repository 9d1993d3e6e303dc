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
#include "rdc_priv.h" /* rdc_server_rec_*: what rdcd --record does */
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
	struct rdc_server_rec *rec;
	struct rdc_hw *hw;
	rdc_dev *dev;
	uint32_t crc = 0;
	uint64_t t = 0;
	long size;

	(void)state;
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	hw = rdc_sim_hw(dev);
	assert_non_null(hw);
	rec = rdc_server_rec_open(trace, VRAM);
	assert_non_null(rec);
	rdc_server_rec_attach(rec, dev);
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
	rdc_server_rec_time_moved(rec, hw->now);
	rdc_hw_run_until(hw, t + 100000);
	rdc_server_rec_sync(rec);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.time, t + 100000);
	size = file_size(trace);

	/* closed: END is there, the trace is whole */
	assert_int_equal(rdc_server_rec_close(rec, dev), 0);
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

/* One record: op, time, then `n` bytes of body. */
static void put_rec(FILE *f, uint8_t op, uint64_t t, const void *body, size_t n)
{
	uint8_t h[9];

	h[0] = op;
	rdc_proto_put64(h + 1, t);
	assert_int_equal(fwrite(h, 1, 9, f), 9);
	if (n)
		assert_int_equal(fwrite(body, 1, n, f), n);
}

/* A version 2 trace of `vram` bytes of VRAM, its header only. */
static FILE *trace_head(uint32_t vram)
{
	uint8_t h[16];
	FILE *f = fopen(trace, "wb");

	assert_non_null(f);
	memcpy(h, "RDCTRACE", 8);
	rdc_proto_put32(h + 8, 2);
	rdc_proto_put32(h + 12, vram);
	assert_int_equal(fwrite(h, 1, 16, f), 16);
	return f;
}

/* Replayed both ways, the trace is refused naming `record`. */
static void refused(const char *record)
{
	struct rdc_replay_result res;
	rdc_history *h = NULL;

	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_RANGE);
	if (!strstr(rdc_last_error_detail(RDC_E_RANGE), record))
		fail_msg("%s", rdc_last_error_detail(RDC_E_RANGE));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_RANGE),
			       "more than a replay allows"));
	assert_int_equal(rdc_replay_history(trace, 0, 0, 4, 4, 0, &h, &res,
					    NULL),
			 RDC_E_RANGE);
	assert_null(h);
}

/*
 * 3. Tiny traces that ask for endless work are refused, naming the
 * record: a STEP of 2^64-1 cycles (42 bytes), an END timed 2^63, a WAIT
 * with a budget of 2^64-1, 300 POWER records (before: each ran with no
 * end, or 100,000 POWER records for minutes).  The same as the seeds
 * tests/fuzz/seeds/trace/bound-*.trace.
 */
static void test_bounded(void **state)
{
	uint8_t b[RDC_PROTO_WAIT_SIZE + 4];
	struct rdc_proto_wait pw = { .budget = UINT64_MAX };
	struct stat st;
	FILE *f;

	(void)state;
	f = trace_head(16u << 20);
	rdc_proto_put64(b, UINT64_MAX);
	put_rec(f, 5, 0, b, 8);
	put_rec(f, 7, 0, NULL, 0);
	fclose(f);
	assert_int_equal(stat(trace, &st), 0);
	assert_int_equal(st.st_size, 42);
	refused("record 1 (STEP at byte 16)");

	f = trace_head(16u << 20);
	put_rec(f, 7, 1ull << 63, NULL, 0);
	fclose(f);
	refused("record 1 (END at byte 16)");

	f = trace_head(16u << 20);
	rdc_proto_wait_encode(b, &pw);
	rdc_proto_put32(b + RDC_PROTO_WAIT_SIZE, (uint32_t)RDC_E_TIMEOUT);
	put_rec(f, 4, 0, b, sizeof(b));
	put_rec(f, 7, 0, NULL, 0);
	fclose(f);
	refused("record 1 (WAIT at byte 16)");

	f = trace_head(64u << 10); /* small chips */
	for (int i = 0; i < 300; i++)
		put_rec(f, 6, 0, NULL, 0);
	put_rec(f, 7, 0, NULL, 0);
	fclose(f);
	refused("record 257 (POWER at byte 2320)");
}

/* 4. The recorder writes a step longer than a minute in pieces that replay. */
static void test_long_step_recorded(void **state)
{
	const uint64_t minute = 60ull * RDC_DEFAULT_CORE_HZ;
	struct rdc_replay_result res;
	rdc_dev *dev;

	(void)state;
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	assert_int_equal(rdc_record_start(dev, trace), 0);
	assert_int_equal(rdc_sim_step(dev, minute + 5), 0);
	rdc_close(dev);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.records, 3); /* STATE, two STEPs */
	assert_int_equal(res.time, minute + 5);
	assert_int_equal(res.mismatches, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_live_and_cut, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_daemon_still_recording,
						setup, teardown),
		cmocka_unit_test_setup_teardown(test_bounded, setup, teardown),
		cmocka_unit_test_setup_teardown(test_long_step_recorded, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
