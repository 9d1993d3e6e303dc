// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * A trace recorded on a chip that has run (rdc_record_start after a mode
 * change, CLUT and cursor writes, a raster list, drawing, fences,
 * simulated time mid-frame and a new format written for the next
 * vblank) starts with a STATE record: the replay's fresh
 * chip starts where the recording did, so every read (time, beam, frame
 * count, counters, FENCE, IRQ_STATUS, the CLUT) and every record's time
 * match, and the replay ends on the device's frame.  The same trace with
 * its STATE record cut out replays with mismatches.  A damaged STATE
 * record is refused, naming it; one cut short is a truncated trace.
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
#include "rdc_regs.h"

/* The STATE record's layout (userspace/lib/record.c, docs/protocol.md). */
#define HDR	   20u /* "RDCTRACE", version, VRAM size, flags */
#define ST_CORE	   156u
#define ST_NREGS   (HDR + 9u + 4u + ST_CORE)
#define VRAM_BYTES (4u << 20)

static char dir[32], trace[128], other[128];
static uint64_t start_time; /* the chip's as the recording started */

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/rdc-rstate-XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	snprintf(trace, sizeof(trace), "%s/s.trace", dir);
	snprintf(other, sizeof(other), "%s/o.trace", dir);
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	unlink(trace);
	unlink(other);
	rmdir(dir);
	return 0;
}

static void fill(rdc_dev *dev, uint32_t fg, int x, int y, int w, int h)
{
	const uint32_t cmd[] = {
		RDC_CMD(RDC_OP_SET_FG, 0, 1),
		fg,
		RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
		RDC_XY(x, y),
		RDC_WH(w, h),
	};

	assert_int_equal(rdc_submit(dev, cmd, sizeof(cmd) / sizeof(cmd[0])), 0);
}

static void fence(rdc_dev *dev, uint32_t v)
{
	const uint32_t cmd[] = { RDC_CMD(RDC_OP_FENCE, 0, 1), v };

	assert_int_equal(rdc_submit(dev, cmd, 2), 0);
	assert_int_equal(rdc_idle_wait(dev), 0);
}

/* Reads whose values depend on where the chip's run has got to. */
static void reads(rdc_dev *dev)
{
	static const uint32_t regs[] = {
		RDC_REG_TIME_LO,	RDC_REG_TIME_HI,
		RDC_REG_BEAM,		RDC_REG_FRAME_COUNT,
		RDC_REG_STATUS,		RDC_REG_IRQ_STATUS,
		RDC_REG_FENCE,		RDC_REG_PERF_BUSY_LO,
		RDC_REG_PERF_BUSY_HI,	RDC_REG_PERF_CMDS,
		RDC_REG_PERF_PIXELS_LO, RDC_REG_ERR_CODE,
		RDC_REG_FB_BASE,	RDC_REG_FB_FORMAT,
		RDC_REG_H_DISPLAY,	RDC_REG_CURSOR_POS,
		RDC_REG_RASTER_STATUS,	RDC_REG_CLUT_INDEX,
		RDC_REG_CLUT_DATA,	RDC_REG_CLUT_DATA,
		RDC_REG_CONTROL,
	};
	uint32_t v;

	for (size_t i = 0; i < sizeof(regs) / sizeof(regs[0]); i++)
		assert_int_equal(rdc_reg_read(dev, regs[i], &v), 0);
}

/*
 * A chip that has run: 320x200 in 8 bpp at 0x10000 with its own CLUT
 * entries, a cursor, a raster list changing entry 7 at line 100, a fence,
 * drawing, then time to the middle of a frame.  The recording reads it,
 * draws, waits for a vblank and reads again.  Returns the device's frame.
 */
static uint32_t record_after_run(void)
{
	const uint32_t rl[] = {
		(uint32_t)RDC_RL_WAIT << 28,
		100u << 16,
		((uint32_t)RDC_RL_CLUT << 28) | 7,
		0x00ff8000,
		(uint32_t)RDC_RL_REG << 28 | RDC_REG_CURSOR_FG,
		0x0000ff00,
		(uint32_t)RDC_RL_END << 28,
		0,
	};
	uint8_t le[sizeof(rl)];
	rdc_dev *dev = NULL;
	uint32_t crc, beam;

	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_MODE_PRESET,
				       RDC_PRESET_320x200_70),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_FORMAT, RDC_FMT_I8), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_STRIDE, 320), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_BASE, 0x10000), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CLUT_INDEX, 3), 0);
	for (uint32_t i = 0; i < 5; i++)
		assert_int_equal(rdc_reg_write(dev, RDC_REG_CLUT_DATA,
					       0x00102030u * (i + 1)),
				 0);
	assert_int_equal(
		rdc_reg_write(dev, RDC_REG_CURSOR_POS, 40u | (30u << 16)), 0);
	for (size_t i = 0; i < sizeof(rl) / sizeof(rl[0]); i++)
		rdc_st32(le + 4 * i, rl[i]);
	assert_int_equal(rdc_vram_write(dev, 0x300000, le, sizeof(le)), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_RASTER_BASE, 0x300000), 0);
	assert_int_equal(
		rdc_reg_write(dev, RDC_REG_RASTER_CTRL, RDC_RASTER_CTRL_EN), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_ENABLE,
				       RDC_IRQ_VBLANK | RDC_IRQ_FENCE),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL,
				       RDC_CONTROL_RESET_VALUE |
					       RDC_CONTROL_CURSOR_EN),
			 0);
	fill(dev, 0x11, 0, 0, 640, 480);
	fence(dev, 41);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	/* into the middle of a frame's active lines, between two lines */
	do {
		assert_int_equal(rdc_sim_step(dev, 1237), 0);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_BEAM, &beam), 0);
	} while (beam >> 16 < 40 || beam >> 16 > 60);
	/* a new format for the next vblank: scanout fetches 320 bytes a
	 * line until then, and the DP's fill below waits behind them */
	assert_int_equal(
		rdc_reg_write(dev, RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_STRIDE, 1280), 0);

	assert_int_equal(rdc_sim_time(dev, &start_time), 0);
	assert_int_equal(rdc_record_start(dev, trace), 0);
	reads(dev);
	fill(dev, 0x22, 10, 10, 300, 150);
	fence(dev, 42);
	reads(dev);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	assert_int_equal(rdc_vblank_wait(dev), 0);
	reads(dev);
	assert_int_equal(rdc_record_stop(dev), 0);
	assert_int_equal(rdc_frame_crc(dev, &crc), 0);
	rdc_close(dev);
	return crc;
}

static uint8_t *slurp(const char *path, size_t *n)
{
	FILE *f = fopen(path, "rb");
	uint8_t *b;
	long len;

	assert_non_null(f);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	len = ftell(f);
	assert_true(len > 0);
	rewind(f);
	b = malloc((size_t)len);
	assert_non_null(b);
	assert_true(fread(b, 1, (size_t)len, f) == (size_t)len);
	fclose(f);
	*n = (size_t)len;
	return b;
}

static void spill(const char *path, const uint8_t *b, size_t n)
{
	FILE *f = fopen(path, "wb");

	assert_non_null(f);
	assert_true(fwrite(b, 1, n, f) == n);
	assert_int_equal(fclose(f), 0);
}

/* Bytes of the STATE record at HDR in b. */
static size_t state_len(const uint8_t *b)
{
	uint32_t nregs = rdc_ld32(b + ST_NREGS);
	size_t at = ST_NREGS + 4 + 8 * nregs;

	assert_int_equal(rdc_ld32(b + at), 256);
	at += 4 + 4 * 256;
	return at + 4 + rdc_ld32(b + at) - HDR;
}

static void test_state_replays(void **state)
{
	struct rdc_replay_result res;
	uint32_t crc = record_after_run(), v;
	rdc_dev *dev = NULL;
	uint64_t t;
	size_t n, k;
	uint8_t *b;

	(void)state;
	assert_int_equal(rdc_replay_file(trace, &res, NULL), 0);
	assert_int_equal(res.untimed, 0);
	assert_int_equal(res.truncated, 0);
	assert_true(res.records > 60);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.frame_crc, crc);

	/* a device where the trace starts (rdcctl diff's script side): the
	 * recorder waited for nothing, the DP being idle */
	assert_int_equal(rdc_replay_open(trace, &dev), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	assert_int_equal(t, start_time);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_FENCE, &v), 0);
	assert_int_equal(v, 41);
	rdc_close(dev);

	/* without its STATE record (a version 3 trace), a fresh chip */
	b = slurp(trace, &n);
	assert_memory_equal(b, "RDCTRACE", 8);
	assert_int_equal(rdc_ld32(b + 8), 4);
	assert_int_equal(b[HDR], 10);
	k = state_len(b);
	rdc_st32(b + 8, 3);
	memmove(b + HDR, b + HDR + k, n - HDR - k);
	spill(other, b, n - k);
	free(b);
	assert_int_equal(rdc_replay_file(other, &res, NULL), 0);
	assert_true(res.mismatches > 20);
	assert_int_not_equal(res.frame_crc, crc);
	assert_int_equal(rdc_replay_open(other, &dev), 0);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	assert_int_equal(t, 0);
	rdc_close(dev);
	assert_int_equal(rdc_replay_open(other, NULL), RDC_E_INVAL);
}

/* The trace with `len` bytes at `at` replaced by v (1 or 4 bytes). */
static void patched(const uint8_t *b, size_t n, size_t at, uint32_t v,
		    size_t len)
{
	uint8_t *c = malloc(n);

	assert_non_null(c);
	memcpy(c, b, n);
	if (len == 1)
		c[at] = (uint8_t)v;
	else
		rdc_st32(c + at, v);
	spill(other, c, n);
	free(c);
}

static void refused(const char *why)
{
	struct rdc_replay_result res;

	assert_int_equal(rdc_replay_file(other, &res, NULL), RDC_E_PARSE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE),
			       "record 1 (STATE at byte 20)"));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE), why));
}

static void test_state_damaged(void **state)
{
	struct rdc_replay_result res;
	size_t n, k, clut, zat;
	uint8_t *b, *c;

	(void)state;
	record_after_run();
	b = slurp(trace, &n);
	k = state_len(b);
	clut = ST_NREGS + 4 + 8 * rdc_ld32(b + ST_NREGS);
	zat = clut + 4 + 4 * 256;

	patched(b, n, HDR + 9, 0x2, 4);
	refused("unknown sections");
	patched(b, n, HDR + 13 + 80, 0x8, 4);
	refused("unknown core flags");
	/* the frame starting after the time */
	patched(b, n, HDR + 13 + 12, 0x7fffffff, 4);
	refused("frame starts after");
	patched(b, n, ST_NREGS, 1000, 4);
	refused("more registers");
	patched(b, n, ST_NREGS + 4, RDC_REG_FIFO_DATA, 4);
	refused("a register a STATE does not restore");
	patched(b, n, clut, 255, 4);
	refused("not 256 CLUT entries");
	patched(b, n, zat, 0xffffffffu, 4);
	refused("larger than zlib makes");
	/* damaged deflate data, its length kept */
	patched(b, n, zat + 6, rdc_ld32(b + zat + 6) ^ 0x5a5a5a5au, 4);
	refused("does not inflate");
	/* a STATE in a trace of version 3 */
	patched(b, n, 8, 3, 4);
	refused("version 3 or before");

	/* a second STATE: only the first record may be one */
	c = malloc(n + k);
	assert_non_null(c);
	memcpy(c, b, HDR + k);
	memcpy(c + HDR + k, b + HDR, n - HDR);
	spill(other, c, n + k);
	free(c);
	assert_int_equal(rdc_replay_file(other, &res, NULL), RDC_E_PARSE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_PARSE),
			       "not the first record"));

	/* cut inside its VRAM: a truncated trace, nothing replayed */
	spill(other, b, HDR + k - 7);
	assert_int_equal(rdc_replay_file(other, &res, NULL), 0);
	assert_int_equal(res.truncated, 1);
	assert_int_equal(res.records, 0);
	free(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_state_replays, setup,
						teardown),
		cmocka_unit_test_setup_teardown(test_state_damaged, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
