// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The client's trace recorder (rdc_record_start, rdcctl --record) on sim:
 * and on a unix: rdcd: the trace replays on sim: with no mismatch, to the
 * frame the script makes; its VRAM writes are the script's, write for
 * write (what rdcctl diff compares), and a script with one statement
 * changed parts from it at that statement's write.  sim:'s trace is timed,
 * the daemon's untimed (its command words in SUBMIT records); both are
 * version 4, a STATE record first (test_lib_record_state.c).  Bad use: a file that cannot
 * be written, a second start, a stop without a start; damaged untimed
 * traces refused.  fbdev:'s: tests/vm/tests/rdcfb-record.sh.
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
#include "rdc_base.h"
#include "test_history_common.h"
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", NULL };

/* The docs/history.md scene, with a display list written to VRAM. */
static const char scene[] = HISTORY_SCENE /* lines 1 to 9 */
	"list 0x200000\n"
	"fg #2040ff\n"
	"fill-rect 100 100 40 30\n"
	"ret\n"
	"end\n"
	"call 0x200000\n"; /* 15 */
/* The same with line 9's text changed. */
static const char scene_b[] = "mode 640x480 xrgb8888\n"
			      "fg #ff0000\n"
			      "fill 8 8 32 32\n"
			      "rop xor\n"
			      "fg #00ffff\n"
			      "blit 8 8 12 10 16 16\n"
			      "rop copy\n"
			      "fg #ffffff\n"
			      "text 12 10 \"B\"\n" /* 9 */
			      "list 0x200000\n"
			      "fg #2040ff\n"
			      "fill-rect 100 100 40 30\n"
			      "ret\n"
			      "end\n"
			      "call 0x200000\n";

static char dir[32];
static char trace[128];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/rdc-record-XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	snprintf(trace, sizeof(trace), "%s/s.trace", dir);
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	unlink(trace);
	rmdir(dir);
	return 0;
}

/* Run `text` on dev and wait for the frame after it; its CRC-32. */
static uint32_t run_text(rdc_dev *dev, const char *text)
{
	struct rdc_script_result res;
	uint32_t crc = 0;

	history_script_res(dev, text, &res);
	assert_int_equal(rdc_script_frame_wait(dev, &res), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	return crc;
}

/* Record `text` run on `uri` into trace; the device's frame CRC. */
static uint32_t record(const char *uri)
{
	rdc_dev *dev = NULL;
	uint32_t crc;

	assert_int_equal(rdc_open(uri, &dev), 0);
	assert_int_equal(rdc_record_start(dev, trace), 0);
	crc = run_text(dev, scene);
	assert_int_equal(rdc_record_stop(dev), 0);
	rdc_close(dev);
	return crc;
}

/* The write log of `text` run on a fresh sim:, its time and frame. */
static rdc_history *script_writes(const char *text, uint64_t *time,
				  uint32_t *crc)
{
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;

	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(
		rdc_history_open(dev, 0, 0, 0, 0, RDC_HISTORY_WRITES, &h), 0);
	*crc = run_text(dev, text);
	assert_int_equal(rdc_sim_time(dev, time), 0);
	rdc_close(dev);
	return h;
}

/* The header's version and, from version 3 on, flags. */
static void header(uint32_t *version, uint32_t *flags)
{
	FILE *f = fopen(trace, "rb");
	uint8_t b[20];
	size_t n;

	assert_non_null(f);
	n = fread(b, 1, sizeof(b), f);
	fclose(f);
	assert_true(n == sizeof(b));
	assert_memory_equal(b, "RDCTRACE", 8);
	*version = rdc_ld32(b + 8);
	*flags = *version >= 3 ? rdc_ld32(b + 16) : 0;
}

/*
 * The trace just recorded against scene and scene_b: replayed with no
 * mismatch to the script's frame, the same writes as the script, and
 * scene_b parting at line 9's text.
 */
static void check_trace(uint32_t dev_crc, int untimed)
{
	struct rdc_replay_result res;
	struct rdc_history_write wt, ws;
	rdc_history *ht = NULL, *ha, *hb;
	rdc_dev *dev = NULL;
	uint64_t ta, tb;
	uint32_t ca, cb;
	size_t i;

	ha = script_writes(scene, &ta, &ca);
	hb = script_writes(scene_b, &tb, &cb);
	assert_int_equal(dev_crc, ca);
	assert_int_not_equal(ca, cb);

	assert_int_equal(rdc_replay_history(trace, 0, 0, 0, 0,
					    RDC_HISTORY_WRITES, &ht, &res,
					    &dev),
			 0);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.truncated, 0);
	assert_int_equal(res.untimed, untimed);
	assert_int_equal(res.frame_crc, ca);
	if (!untimed)
		assert_int_equal(res.time, ta);
	rdc_close(dev);

	/* the same writes as the script, in the same order */
	assert_true(rdc_history_write_count(ht) > 20);
	assert_int_equal(rdc_history_write_count(ht),
			 rdc_history_write_count(ha));
	assert_int_equal(rdc_history_first_diff(ht, ha, &i), 0);
	/* the list went to VRAM through rdc_vram_write: a host write */
	for (i = 0; i < rdc_history_write_count(ht); i++) {
		assert_int_equal(rdc_history_write_get(ht, i, &wt), 0);
		if (wt.entry.opcode == RDC_HISTORY_OP_HOST &&
		    wt.addr == 0x200000)
			break;
	}
	assert_true(i < rdc_history_write_count(ht));

	/* the changed text is found at its write */
	assert_int_equal(rdc_history_first_diff(ht, hb, &i), 1);
	assert_true(i < rdc_history_write_count(ht));
	assert_int_equal(rdc_history_write_get(ht, i, &wt), 0);
	assert_int_equal(rdc_history_write_get(hb, i, &ws), 0);
	assert_int_equal(ws.entry.line, 9);
	assert_int_equal(wt.entry.opcode, ws.entry.opcode);
	assert_int_equal(wt.entry.cmd_index, ws.entry.cmd_index);
	assert_int_equal(wt.addr, ws.addr);
	if (!untimed)
		assert_int_equal(wt.entry.cycle, ws.entry.cycle);

	rdc_history_close(ht);
	rdc_history_close(ha);
	rdc_history_close(hb);
}

static void test_record_sim(void **state)
{
	uint32_t version, flags;

	(void)state;
	check_trace(record("sim:"), 0);
	/* timed, with a STATE record first (rdcd --record writes version 2) */
	header(&version, &flags);
	assert_int_equal(version, 4);
	assert_int_equal(flags, 0);
}

static void test_record_unix(void **state)
{
	struct netd d;
	uint32_t version, flags, crc;

	(void)state;
	if (netd_start(&d, args_stepped)) {
		netd_dump_log(&d);
		fail_msg("rdcd did not start");
	}
	crc = record(d.unix_uri);
	assert_int_equal(netd_stop(&d), 0);
	check_trace(crc, 1);
	header(&version, &flags);
	assert_int_equal(version, 4);
	assert_int_equal(flags, 1);
}

static void test_record_errors(void **state)
{
	struct rdc_replay_result res;
	rdc_dev *dev = NULL;
	char bad[160];

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_record_start(NULL, trace), RDC_E_INVAL);
	assert_int_equal(rdc_record_start(dev, NULL), RDC_E_INVAL);
	assert_int_equal(rdc_record_start(dev, ""), RDC_E_INVAL);
	assert_int_equal(rdc_record_stop(dev), RDC_E_INVAL);
	assert_int_equal(rdc_record_stop(NULL), RDC_E_INVAL);

	/* a file that cannot be written: said, and the device goes on */
	snprintf(bad, sizeof(bad), "%s/no/such/dir/t", dir);
	assert_int_equal(rdc_record_start(dev, bad), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), bad));
	assert_int_equal(rdc_record_stop(dev), RDC_E_INVAL);
	run_text(dev, "fill 0 0 8 8\n");

	/* one recorder a handle */
	assert_int_equal(rdc_record_start(dev, trace), 0);
	assert_int_equal(rdc_record_start(dev, trace), RDC_E_BUSY);
	assert_non_null(
		strstr(rdc_last_error_detail(RDC_E_BUSY), "already recorded"));
	run_text(dev, scene);
	assert_int_equal(rdc_record_stop(dev), 0);
	assert_int_equal(rdc_record_stop(dev), RDC_E_INVAL);

	rdc_close(dev);

	/* a fresh device's, ended by rdc_close: the trace is whole */
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_record_start(dev, trace), 0);
	run_text(dev, scene);
	rdc_close(dev);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 0);
	assert_int_equal(res.mismatches, 0);
	assert_true(res.records > 10);
}

/* Write a trace: its header (flags from version 3 on), then `body`. */
static void write_trace(uint32_t version, uint32_t flags, const uint8_t *body,
			size_t n)
{
	FILE *f = fopen(trace, "wb");
	uint8_t b[12];
	size_t hn = version >= 3 ? 12 : 8;

	assert_non_null(f);
	rdc_st32(b, version);
	rdc_st32(b + 4, 1u << 20);
	rdc_st32(b + 8, flags);
	assert_true(fwrite("RDCTRACE", 1, 8, f) == 8);
	assert_true(fwrite(b, 1, hn, f) == hn);
	assert_true(!n || fwrite(body, 1, n, f) == n);
	assert_int_equal(fclose(f), 0);
}

/* A SUBMIT record of n (claimed) words, `have` of them NOP, result 0. */
static size_t submit_rec(uint8_t *b, uint32_t n, uint32_t have)
{
	size_t k = 0;

	b[k++] = 9;
	memset(b + k, 0, 8);
	k += 8;
	rdc_st32(b + k, n);
	k += 4;
	for (uint32_t i = 0; i < have; i++, k += 4)
		rdc_st32(b + k, RDC_CMD(RDC_OP_NOP, 0, 0));
	rdc_st32(b + k, 0);
	return k + 4;
}

static void test_record_damaged(void **state)
{
	struct rdc_replay_result res;
	uint8_t b[64], end[9] = { 7 };
	size_t n;

	(void)state;
	/* a well-formed untimed trace: two NOPs, END */
	n = submit_rec(b, 2, 2);
	memcpy(b + n, end, sizeof(end));
	write_trace(3, 1, b, n + sizeof(end));
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.untimed, 1);
	assert_int_equal(res.records, 1);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.truncated, 0);

	/* an unknown header flag */
	write_trace(3, 2, b, n + sizeof(end));
	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_PARSE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE), "flags"));
	/* no SUBMIT of 0 words, nor of more than 65536 */
	n = submit_rec(b, 0, 0);
	write_trace(3, 1, b, n);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_PARSE);
	n = submit_rec(b, 65537, 0);
	write_trace(3, 1, b, n);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_PARSE);
	/* a SUBMIT cut short: truncated, not damaged */
	n = submit_rec(b, 2, 2);
	write_trace(3, 1, b, n - 6);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.records, 0);
	/* SUBMIT is version 3's */
	n = submit_rec(b, 2, 2);
	write_trace(2, 0, b, n);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_PARSE);
	/* a version 3 header without its flags */
	write_trace(3, 1, NULL, 0);
	assert_int_equal(truncate(trace, 16), 0);
	assert_int_equal(rdc_replay_file(trace, &res, NULL), RDC_E_PARSE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_record_sim, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_record_unix, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_record_errors, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_record_damaged, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
