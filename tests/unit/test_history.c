// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pixel history (userspace/lib/history.c): small scenes whose histories
 * are worked out by hand, the beam's side of a torn pixel checked against
 * the frames scanout made, display-list chains, sub-byte pixels, host
 * writes, first divergence of two long scripts, and the golden scenes
 * with a history open giving their golden frames and cycle counts.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include <unistd.h>

#include "dp.h"
#include "rdc.h"
#include "rdc_priv.h" /* rdc_server_rec_*: what rdcd --record does */
#include "test_history_common.h"

#define GOLDEN_LIST "tests/golden/golden.txt"
#define SCENE_DIR   "tests/golden/scenes"

static struct rdc_script_result res;

static rdc_dev *open_sim(void)
{
	rdc_dev *dev = NULL;

	assert_int_equal(rdc_open("sim:", &dev), 0);
	return dev;
}

static void run_text(rdc_dev *dev, const char *text)
{
	int ret = rdc_script_run(dev, text, strlen(text), &res);

	if (ret)
		print_error("line %u: %s\n", res.error_line, res.error_msg);
	assert_int_equal(ret, 0);
}

static void get(rdc_history *h, size_t i, struct rdc_history_entry *e)
{
	assert_int_equal(rdc_history_get(h, i, e), 0);
}

/*
 * A pixel drawn by a fill, XORed by an overlapping blit, then covered by
 * text: three entries, in order, with their before and after values.
 */
static void test_history_fill_xor_text(void **state)
{
	static const char scene[] = HISTORY_SCENE;
	struct rdc_history_entry e[3];
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();
	/* (14,12) is the glyph's column 2 of row 2; opaque text: fg or bg */
	uint32_t glyph = rdc_font8x16['A' * 16 + 2] & (0x80 >> 2) ? 0xffffff :
								    0;

	(void)state;
	assert_int_equal(rdc_history_open(dev, 14, 12, 1, 1, 0, &h), 0);
	run_text(dev, scene);
	assert_int_equal(rdc_history_count(h), 3);
	for (size_t i = 0; i < 3; i++)
		get(h, i, &e[i]);
	/* the fill: black to red */
	assert_int_equal(e[0].opcode, RDC_OP_FILL_RECT);
	assert_int_equal(e[0].line, 3);
	assert_int_equal(e[0].before, 0);
	assert_int_equal(e[0].after, 0xff0000);
	assert_int_equal(e[0].rop, RDC_ROP_COPY);
	/* the blit reads (10,10), red, and XORs it onto red: black */
	assert_int_equal(e[1].opcode, RDC_OP_BLIT);
	assert_int_equal(e[1].line, 6);
	assert_int_equal(e[1].rop, RDC_ROP_XOR);
	assert_int_equal(e[1].before, 0xff0000);
	assert_int_equal(e[1].after, 0);
	/* the text */
	assert_int_equal(e[2].opcode, RDC_OP_TEXT);
	assert_int_equal(e[2].line, 9);
	assert_int_equal(e[2].before, 0);
	assert_int_equal(e[2].after, glyph);
	assert_int_equal(e[2].fg, 0xffffff);
	for (size_t i = 0; i < 3; i++) {
		assert_int_equal(e[i].x, 14);
		assert_int_equal(e[i].y, 12);
		assert_int_equal(e[i].source, RDC_HISTORY_SRC_FIFO);
		assert_int_equal(e[i].format, RDC_FMT_XRGB8888);
		/* all drawn while the beam is still above line 12 */
		assert_int_equal(e[i].fetched, 0);
		assert_int_equal(e[i].frame, 0);
		if (i) {
			assert_true(e[i].cycle > e[i - 1].cycle);
			assert_true(e[i].cmd_index > e[i - 1].cmd_index);
		}
	}
	/* the last entry's value is what VRAM holds */
	{
		uint32_t px = 1;

		assert_int_equal(rdc_vram_read(dev, 12 * 2560 + 14 * 4, &px, 4),
				 0);
		assert_int_equal(px & 0xffffff, e[2].after);
	}
	rdc_close(dev);
	/* the history outlives its device */
	assert_int_equal(rdc_history_count(h), 3);
	rdc_history_close(h);
}

/*
 * The same scene recorded as an rdcd trace and replayed with a history:
 * the same three writes at the same cycles, each with its trace record;
 * and the trace's writes against the script's: no divergence.
 */
static void test_history_trace(void **state)
{
	static const char scene[] = "mode 640x480 xrgb8888\n"
				    "fg #ff0000\nfill 8 8 32 32\n"
				    "rop xor\nblit 8 8 12 10 16 16\n"
				    "rop copy\nfg #ffffff\ntext 12 10 \"A\"\n";
	char path[] = "/tmp/rdc-history-XXXXXX";
	struct rdc_history_entry es[3], et;
	struct rdc_replay_result rr;
	rdc_history *hs = NULL, *ht = NULL, *ws = NULL, *wt = NULL;
	struct rdc_server_rec *rec;
	rdc_dev *dev, *rdev = NULL;
	size_t i = 0;
	int fd;

	(void)state;
	fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	/* the script, recorded, with both kinds of history */
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	assert_int_equal(rdc_history_open(dev, 14, 12, 1, 1, 0, &hs), 0);
	rec = rdc_server_rec_open(path, 4u << 20);
	assert_non_null(rec);
	rdc_server_rec_attach(rec, dev);
	run_text(dev, scene);
	assert_int_equal(rdc_server_rec_close(rec, dev), 0);
	rdc_close(dev);
	assert_int_equal(rdc_history_count(hs), 3);
	for (i = 0; i < 3; i++)
		get(hs, i, &es[i]);

	assert_int_equal(
		rdc_replay_history(path, 14, 12, 1, 1, 0, &ht, &rr, &rdev), 0);
	assert_non_null(ht);
	assert_int_equal(rr.mismatches, 0);
	assert_int_equal(rdc_history_count(ht), 3);
	for (i = 0; i < 3; i++) {
		get(ht, i, &et);
		assert_int_equal(et.opcode, es[i].opcode);
		assert_int_equal(et.cycle, es[i].cycle);
		assert_int_equal(et.before, es[i].before);
		assert_int_equal(et.after, es[i].after);
		/* a record of the trace, not past its end */
		assert_true(et.line >= 1 && et.line <= rr.records);
	}
	rdc_close(rdev);
	rdc_history_close(ht);

	/* the trace against the script: the same writes */
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	assert_int_equal(
		rdc_history_open(dev, 0, 0, 0, 0, RDC_HISTORY_WRITES, &ws), 0);
	run_text(dev, scene);
	rdc_close(dev);
	assert_int_equal(rdc_replay_history(path, 0, 0, 0, 0,
					    RDC_HISTORY_WRITES, &wt, NULL,
					    NULL),
			 0);
	assert_true(rdc_history_write_count(wt) > 3);
	assert_int_equal(rdc_history_first_diff(ws, wt, &i), 0);
	/* a trace that is not one: no history */
	assert_true(rdc_replay_history("/nonexistent/trace", 0, 0, 1, 1, 0, &ht,
				       NULL, NULL) < 0);
	assert_null(ht);
	rdc_history_close(hs);
	rdc_history_close(ws);
	rdc_history_close(wt);
	unlink(path);
}

/*
 * A history and a trace recorder in either order (rdcd --record wraps its
 * device before any client asks for a history): the same entries as
 * without a recorder, and each trace replays without a mismatch.
 */
static void test_history_recorder_order(void **state)
{
	static const char scene[] = "mode 640x480 xrgb8888\n"
				    "fg #ff0000\nfill 8 8 32 32\n"
				    "rop xor\nfg #00ffff\n"
				    "blit 8 8 12 10 16 16\n"
				    "rop copy\nfg #ffffff\ntext 12 10 \"A\"\n";
	struct rdc_history_entry ref[64], e;
	size_t n;
	rdc_history *h = NULL;
	rdc_dev *dev;

	(void)state;
	assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
	assert_int_equal(rdc_history_open(dev, 10, 10, 4, 4, 0, &h), 0);
	run_text(dev, scene);
	n = rdc_history_count(h);
	assert_true(n > 16 && n <= 64);
	for (size_t i = 0; i < n; i++)
		get(h, i, &ref[i]);
	rdc_close(dev);
	rdc_history_close(h);

	for (int order = 0; order < 2; order++) {
		char path[] = "/tmp/rdc-history-XXXXXX";
		struct rdc_replay_result rr;
		struct rdc_server_rec *rec;
		int fd = mkstemp(path);

		assert_true(fd >= 0);
		close(fd);
		assert_int_equal(rdc_open("sim:vram=4M", &dev), 0);
		rec = rdc_server_rec_open(path, 4u << 20);
		assert_non_null(rec);
		if (order == 0) {
			assert_int_equal(
				rdc_history_open(dev, 10, 10, 4, 4, 0, &h), 0);
			rdc_server_rec_attach(rec, dev);
		} else {
			rdc_server_rec_attach(rec, dev);
			assert_int_equal(
				rdc_history_open(dev, 10, 10, 4, 4, 0, &h), 0);
		}
		/* one a device, recorder or not */
		{
			rdc_history *h2 = NULL;

			assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0,
							  &h2),
					 RDC_E_BUSY);
		}
		run_text(dev, scene);
		assert_int_equal(rdc_history_count(h), n);
		for (size_t i = 0; i < n; i++) {
			get(h, i, &e);
			assert_entry_equal(&e, &ref[i]);
		}
		/* the recorder goes first: the history goes on, and after
		 * the device too */
		assert_int_equal(rdc_server_rec_close(rec, dev), 0);
		run_text(dev, "fill 10 10 1 1\n");
		assert_int_equal(rdc_history_count(h), n + 1);
		rdc_close(dev);
		assert_int_equal(rdc_history_count(h), n + 1);
		rdc_history_close(h);
		assert_int_equal(rdc_replay_file(path, &rr, NULL), 0);
		assert_int_equal(rr.mismatches, 0);
		unlink(path);
	}
}

/* Nothing outside the watched pixels is recorded. */
static void test_history_untouched(void **state)
{
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();

	(void)state;
	assert_int_equal(rdc_history_open(dev, 100, 100, 2, 2, 0, &h), 0);
	run_text(dev, "fg #ff0000\nfill 8 8 32 32\nfill 102 99 1 1\n"
		      "line 90 90 99 99\nfill 98 102 2 2\n");
	/* the line ends at (99,99), the fills miss by one pixel */
	assert_int_equal(rdc_history_count(h), 0);
	run_text(dev, "fill 101 101 1 1\n");
	assert_int_equal(rdc_history_count(h), 1);
	rdc_history_close(h);
	rdc_close(dev);
}

/*
 * A pixel written after the beam fetched its line: the frame in progress
 * shows the old value, the next the new one, as the entry says.
 */
static void test_history_torn(void **state)
{
	struct rdc_history_entry e;
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();
	uint32_t *pix = NULL, w = 0, hh = 0;
	size_t cap = 640 * 480;

	(void)state;
	pix = calloc(cap, sizeof(*pix));
	assert_non_null(pix);
	run_text(dev, "mode 640x480 xrgb8888\nwait-frame\n");
	assert_int_equal(rdc_history_open(dev, 5, 5, 1, 1, 0, &h), 0);
	run_text(dev, "wait-line 100\nfg #00ff00\npixel 5 5\nvsync\n");
	assert_int_equal(rdc_history_count(h), 1);
	get(h, 0, &e);
	assert_int_equal(e.opcode, RDC_OP_PIXEL);
	assert_int_equal(e.fetched, 1);
	assert_int_equal(e.before, 0);
	assert_int_equal(e.after, 0x00ff00);
	/* frame e.frame is complete now: it has the old value */
	assert_int_equal(rdc_frame_grab(dev, pix, cap, &w, &hh), 0);
	assert_int_equal(pix[5 * 640 + 5] & 0xffffff, e.before);
	run_text(dev, "vsync\n");
	assert_int_equal(rdc_frame_grab(dev, pix, cap, &w, &hh), 0);
	assert_int_equal(pix[5 * 640 + 5] & 0xffffff, e.after);
	/* and a pixel written before the beam reaches its line */
	rdc_history_close(h);
	assert_int_equal(rdc_history_open(dev, 5, 400, 1, 1, 0, &h), 0);
	run_text(dev, "wait-line 100\nfg #0000ff\npixel 5 400\nvsync\n");
	get(h, 0, &e);
	assert_int_equal(e.fetched, 0);
	assert_int_equal(rdc_frame_grab(dev, pix, cap, &w, &hh), 0);
	assert_int_equal(pix[400 * 640 + 5] & 0xffffff, e.after);
	free(pix);
	rdc_history_close(h);
	rdc_close(dev);
}

/* A fill inside a list called from a list: the CALL chain. */
static void test_history_list_chain(void **state)
{
	static const char scene[] = "mode 640x480 xrgb8888\n"
				    "list 0x200000\n"
				    "fill 20 20 4 4\n"
				    "ret\n"
				    "end\n"
				    "list 0x201000\n"
				    "call 0x200000\n"
				    "ret\n"
				    "end\n"
				    "fg #0000ff\n"
				    "call 0x201000\n"; /* 11 */
	struct rdc_history_entry e;
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();

	(void)state;
	assert_int_equal(rdc_history_open(dev, 21, 21, 1, 1, 0, &h), 0);
	run_text(dev, scene);
	assert_int_equal(rdc_history_count(h), 1);
	get(h, 0, &e);
	assert_int_equal(e.opcode, RDC_OP_FILL_RECT);
	assert_int_equal(e.source, RDC_HISTORY_SRC_LIST);
	assert_int_equal(e.line, 11);
	assert_int_equal(e.cmd_addr, 0x200000);
	assert_int_equal(e.depth, 2);
	/* the outer list resumes after its CALL (header and address) */
	assert_int_equal(e.calls[0], 0x201000 + 8);
	assert_int_equal(e.after, 0x0000ff);
	rdc_history_close(h);
	rdc_close(dev);
}

/*
 * 4-bit pixels: a fill of one pixel rewrites its byte; the neighbour that
 * shares it, unchanged, has no entry.
 */
static void test_history_subbyte(void **state)
{
	struct rdc_history_entry e;
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();

	(void)state;
	run_text(dev, "mode 640x480 i4\nwait-frame\n");
	assert_int_equal(rdc_history_open(dev, 0, 0, 4, 1, 0, &h), 0);
	run_text(dev, "fg 5\nfill 0 0 1 1\nfill 3 0 1 1\n");
	assert_int_equal(rdc_history_count(h), 2);
	get(h, 0, &e);
	assert_int_equal(e.x, 0);
	assert_int_equal(e.format, RDC_FMT_I4);
	assert_int_equal(e.before, 0);
	assert_int_equal(e.after, 5);
	assert_int_equal(e.line, 2);
	get(h, 1, &e);
	assert_int_equal(e.x, 3);
	assert_int_equal(e.after, 5);
	assert_int_equal(e.line, 3);
	rdc_history_close(h);
	rdc_close(dev);
}

/*
 * Every pixel format, sub-byte ones included, and the DP's error
 * recovery: three pixels of a row written by fills of known values (the
 * neighbours on either side, sharing their bytes in i1..i4, have no
 * entry), then a command the DP refuses (no entry: it wrote nothing), a
 * soft reset, and a fill after it, recorded as before.
 */
static void test_history_formats_errors(void **state)
{
	static const struct {
		const char *name;
		uint32_t fmt, n, m, k;
	} f[] = {
		{ "i1", RDC_FMT_I1, 1, 0, 0 },
		{ "i2", RDC_FMT_I2, 3, 1, 2 },
		{ "i4", RDC_FMT_I4, 9, 6, 15 },
		{ "i8", RDC_FMT_I8, 200, 7, 99 },
		{ "rgb565", RDC_FMT_RGB565, 0xf81f, 0x07e0, 0x1234 },
		{ "rgb888", RDC_FMT_RGB888, 0x123456, 0xabcdef, 0xfedcba },
		{ "xrgb8888", RDC_FMT_XRGB8888, 0x654321, 0x00ff00, 0x0000ff },
	};
	char text[256];

	(void)state;
	for (size_t i = 0; i < sizeof(f) / sizeof(f[0]); i++) {
		/* per pixel 3..8: the values written, in order */
		const uint32_t want[6][3] = {
			{ 0 },
			{ f[i].n },
			{ f[i].n, f[i].m },
			{ f[i].n, f[i].k },
			{ 0 },
			{ 0 },
		};
		const size_t nwant[6] = { 0, 1, 2, 2, 0, 0 };
		size_t seen[6] = { 0 };
		uint32_t last[6] = { 0 };
		struct rdc_history_entry e;
		rdc_history *h = NULL;
		rdc_dev *dev = open_sim();
		uint32_t st = 0;
		size_t n;
		int ret;

		snprintf(text, sizeof(text), "mode 640x480 %s\nwait-frame\n",
			 f[i].name);
		run_text(dev, text);
		assert_int_equal(rdc_history_open(dev, 3, 2, 6, 1, 0, &h), 0);
		snprintf(text, sizeof(text),
			 "fg %u\nfill 4 2 3 1\nfg %u\nfill 5 2 1 1\n", f[i].n,
			 f[i].m);
		run_text(dev, text);
		/* an unknown opcode: the DP stops with ERR_CODE set */
		ret = rdc_script_run(dev, "raw 0xfe000000\nfinish\n", 22, &res);
		assert_true(ret == RDC_E_DEVICE || ret == RDC_E_HALTED);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_ERR_CODE, &st), 0);
		assert_int_equal(st, RDC_ERR_OPCODE);
		/* the reset takes the CRTC back to its defaults: the mode
		 * again, over what VRAM holds */
		snprintf(text, sizeof(text),
			 "reset\nmode 640x480 %s\nfg %u\nfill 6 2 1 1\n"
			 "finish\n",
			 f[i].name, f[i].k);
		run_text(dev, text);
		n = rdc_history_count(h);
		for (size_t j = 0; j < n; j++) {
			size_t x;

			get(h, j, &e);
			assert_int_equal(e.y, 2);
			assert_true(e.x >= 3 && e.x < 9);
			assert_int_equal(e.format, f[i].fmt);
			x = e.x - 3;
			assert_true(seen[x] < nwant[x]);
			/* each entry starts where the last one left */
			assert_int_equal(e.before, last[x]);
			assert_int_equal(e.after, want[x][seen[x]]);
			assert_int_not_equal(e.opcode, 0xfe);
			last[x] = e.after;
			seen[x]++;
		}
		for (size_t x = 0; x < 6; x++)
			if (seen[x] != nwant[x])
				fail_msg("%s: pixel %zu: %zu entries, not %zu",
					 f[i].name, x + 3, seen[x], nwant[x]);
		rdc_history_close(h);
		rdc_close(dev);
	}
}

/*
 * The watched pixel moves with the framebuffer: a mode change after the
 * history opened (another format, another address for the same pixel),
 * and FB_BASE written from the command stream.
 */
static void test_history_fb_moves(void **state)
{
	struct rdc_history_entry e;
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();

	(void)state;
	assert_int_equal(rdc_history_open(dev, 320, 240, 1, 1, 0, &h), 0);
	run_text(dev, "fg #ffffff\nfill 0 0 8 8\nmode 640x480 i8\n"
		      "fg 7\nfill 300 230 40 20\n");
	assert_int_equal(rdc_history_count(h), 1);
	get(h, 0, &e);
	assert_int_equal(e.format, RDC_FMT_I8);
	assert_int_equal(e.after, 7);
	/* the framebuffer one line further on: screen line 240 is VRAM's
	 * line 241 (the DP still draws at 0, SET_DST is apart) */
	run_text(dev, "cmd-reg FB_BASE 640\nfg 9\nfill 320 240 1 1\n"
		      "fill 320 241 1 1\n");
	assert_int_equal(rdc_history_count(h), 2);
	get(h, 1, &e);
	assert_int_equal(e.after, 9);
	assert_int_equal(e.line, 4);
	rdc_history_close(h);
	rdc_close(dev);
}

/* A host aperture write is an entry too. */
static void test_history_host_write(void **state)
{
	static const uint8_t px[4] = { 0x56, 0x34, 0x12, 0 };
	struct rdc_history_entry e;
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();

	(void)state;
	assert_int_equal(rdc_history_open(dev, 1, 1, 1, 1, 0, &h), 0);
	assert_int_equal(rdc_vram_write(dev, 2560 + 4, px, 4), 0);
	assert_int_equal(rdc_history_count(h), 1);
	get(h, 0, &e);
	assert_int_equal(e.opcode, RDC_HISTORY_OP_HOST);
	assert_int_equal(e.source, RDC_HISTORY_SRC_HOST);
	assert_int_equal(e.before, 0);
	assert_int_equal(e.after, 0x123456);
	rdc_history_close(h);
	rdc_close(dev);
}

static void test_history_api(void **state)
{
	rdc_history *h = NULL, *h2 = (rdc_history *)1;
	struct rdc_history_entry e;
	rdc_dev *dev = open_sim();
	size_t i;

	(void)state;
	assert_int_equal(rdc_history_open(NULL, 0, 0, 1, 1, 0, &h),
			 RDC_E_INVAL);
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0x80, &h),
			 RDC_E_INVAL);
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0, &h), 0);
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0, &h2), RDC_E_BUSY);
	assert_null(h2);
	assert_int_equal(rdc_history_get(h, 0, &e), RDC_E_RANGE);
	assert_int_equal(rdc_history_first_diff(h, h, &i), RDC_E_INVAL);
	/* a limit keeps the first entries and counts the rest */
	assert_int_equal(rdc_history_set_limit(h, 2), 0);
	run_text(dev, "fg #ffffff\nfill 0 0 1 1\nfill 0 0 1 1\nfill 0 0 1 1\n");
	assert_int_equal(rdc_history_count(h), 2);
	assert_int_equal(rdc_history_dropped(h), 1);
	rdc_history_close(h);
	/* closed: another may open */
	assert_int_equal(rdc_history_open(dev, 0, 0, 1, 1, 0, &h), 0);
	rdc_history_close(h);
	rdc_close(dev);
}

/* A long script of fills; `change` >= 0 gives statement `change` another
 * colour.  Returns its history of writes. */
static rdc_history *long_run(int change, uint32_t *line_of_change)
{
	size_t cap = 64 * 1024, n = 0;
	char *text = malloc(cap);
	rdc_history *h = NULL;
	rdc_dev *dev = open_sim();
	uint32_t line = 1;

	assert_non_null(text);
	n += (size_t)snprintf(text + n, cap - n, "mode 640x480 xrgb8888\n");
	for (int i = 0; i < 400; i++) {
		uint32_t c = (uint32_t)i * 0x010305u & 0xffffff;

		if (i == change) {
			c ^= 0x000100;
			*line_of_change = line + 2; /* its fill */
		}
		n += (size_t)snprintf(text + n, cap - n,
				      "fg #%06x\nfill %d %d %d %d\n", c,
				      (i * 37) % 600, (i * 53) % 440,
				      5 + i % 30, 3 + i % 20);
		line += 2;
	}
	assert_true(n < cap);
	assert_int_equal(
		rdc_history_open(dev, 0, 0, 0, 0, RDC_HISTORY_WRITES, &h), 0);
	run_text(dev, text);
	rdc_close(dev);
	free(text);
	return h;
}

static void test_history_first_diff(void **state)
{
	struct rdc_history_write wa, wb;
	uint32_t line = 0, unused = 0;
	rdc_history *a = long_run(-1, &unused);
	rdc_history *b = long_run(-1, &unused);
	rdc_history *c = long_run(271, &line);
	size_t i = 0;

	(void)state;
	assert_true(rdc_history_write_count(a) >= 400);
	assert_int_equal(rdc_history_first_diff(a, b, &i), 0);
	assert_int_equal(i, rdc_history_write_count(a));
	assert_int_equal(rdc_history_first_diff(a, c, &i), 1);
	assert_int_equal(rdc_history_write_get(a, i, &wa), 0);
	assert_int_equal(rdc_history_write_get(c, i, &wb), 0);
	/* the fill after the changed colour, at the same command and cycle */
	assert_int_equal(wb.entry.line, line);
	assert_int_equal(wa.entry.line, line);
	assert_int_equal(wb.entry.opcode, RDC_OP_FILL_RECT);
	assert_int_equal(wa.entry.cmd_index, wb.entry.cmd_index);
	assert_int_equal(wa.entry.cycle, wb.entry.cycle);
	rdc_history_close(a);
	rdc_history_close(b);
	rdc_history_close(c);
}

/*
 * Every golden scene with a history of the whole screen and the write log
 * open: the golden frame and cycle count, and something recorded.
 */
static void test_history_golden_unchanged(void **state)
{
	FILE *f = fopen(GOLDEN_LIST, "r");
	char line[256];
	size_t scenes = 0, failed = 0;

	(void)state;
	assert_non_null(f);
	while (fgets(line, sizeof(line), f)) {
		char name[64], path[160];
		unsigned int crc_want, crc = 0;
		unsigned long long cyc_want;
		rdc_history *h = NULL;
		rdc_dev *dev;
		uint64_t t = 0;
		uint32_t c = 0;
		int ret;

		if (line[0] == '#' || sscanf(line, "%63s %x %llu", name,
					     &crc_want, &cyc_want) != 3)
			continue;
		snprintf(path, sizeof(path), SCENE_DIR "/%s.rdl", name);
		dev = open_sim();
		assert_int_equal(rdc_history_open(dev, 0, 0, RDC_HISTORY_SCREEN,
						  RDC_HISTORY_SCREEN,
						  RDC_HISTORY_WRITES, &h),
				 0);
		assert_int_equal(rdc_history_set_limit(h, 4096), 0);
		ret = rdc_script_run_file(dev, path, &res);
		if (!ret)
			ret = rdc_sim_time(dev, &t);
		if (!ret)
			ret = rdc_script_frame_wait(dev, &res);
		if (!ret)
			ret = rdc_frame_crc(dev, &c);
		crc = c;
		if (ret || crc != crc_want || t != cyc_want ||
		    !rdc_history_write_count(h)) {
			print_error("%s with history: %s crc32 %08x cycles "
				    "%llu writes %zu, golden %08x %llu\n",
				    name, rdc_strerror(ret), crc,
				    (unsigned long long)t,
				    rdc_history_write_count(h), crc_want,
				    cyc_want);
			failed++;
		}
		rdc_history_close(h);
		rdc_close(dev);
		scenes++;
	}
	fclose(f);
	assert_true(scenes > 0);
	assert_int_equal(failed, 0);
}

/* Pixel (x, y) of the framebuffer the registers describe now. */
static uint32_t fb_pixel(rdc_dev *dev, uint32_t x, uint32_t y)
{
	uint32_t base = 0, stride = 0, fmt = 0, bpp;
	uint8_t b[4] = { 0 };
	uint64_t bit;

	assert_int_equal(rdc_reg_read(dev, RDC_REG_FB_BASE, &base), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_FB_STRIDE, &stride), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_FB_FORMAT, &fmt), 0);
	bpp = rdc_format_bpp(fmt);
	bit = (uint64_t)x * bpp;
	assert_int_equal(rdc_vram_read(dev,
				       base + y * stride + (uint32_t)(bit / 8),
				       b, (bpp + 7) / 8),
			 0);
	if (bpp < 8)
		return (uint32_t)(b[0] >> (8 - bpp - bit % 8)) &
		       ((1u << bpp) - 1);
	return ((uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
		(uint32_t)b[3] << 24) &
	       (bpp < 32 ? (1u << bpp) - 1 : ~0u);
}

/*
 * Every golden scene (every primitive, format and path of the DP) with a
 * block of the screen watched: each pixel's entries chain (each `before`
 * is the last `after`, from the zeroed VRAM on), and the last `after` is
 * what VRAM holds at the end.  A write the history missed breaks one.
 */
#define CHAIN_X 100u
#define CHAIN_Y 60u
#define CHAIN_W 64u
#define CHAIN_H 48u
static void test_history_chain_golden(void **state)
{
	FILE *f = fopen(GOLDEN_LIST, "r");
	char line[256];
	size_t scenes = 0, failed = 0, checked = 0;
	static uint32_t last[CHAIN_W * CHAIN_H];
	static uint32_t fmt[CHAIN_W * CHAIN_H];

	(void)state;
	assert_non_null(f);
	while (fgets(line, sizeof(line), f)) {
		char name[64], path[160];
		unsigned int crc;
		unsigned long long cyc;
		struct rdc_history_entry e;
		rdc_history *h = NULL;
		rdc_dev *dev;
		size_t n, bad = 0;
		uint32_t w = 0, hh = 0, mode_fmt = 0;

		if (line[0] == '#' ||
		    sscanf(line, "%63s %x %llu", name, &crc, &cyc) != 3)
			continue;
		snprintf(path, sizeof(path), SCENE_DIR "/%s.rdl", name);
		dev = open_sim();
		assert_int_equal(rdc_history_open(dev, CHAIN_X, CHAIN_Y,
						  CHAIN_W, CHAIN_H, 0, &h),
				 0);
		assert_int_equal(rdc_history_set_limit(h, 1u << 21), 0);
		assert_int_equal(rdc_script_run_file(dev, path, &res), 0);
		scenes++;
		n = rdc_history_count(h);
		assert_int_equal(rdc_history_dropped(h), 0);
		memset(last, 0, sizeof(last));
		memset(fmt, 0xff, sizeof(fmt));
		for (size_t i = 0; i < n; i++) {
			size_t k;

			get(h, i, &e);
			k = (e.y - CHAIN_Y) * CHAIN_W + (e.x - CHAIN_X);
			/* a new format reads the same bytes otherwise */
			if (fmt[k] != e.format && fmt[k] != 0xffffffffu)
				last[k] = e.before;
			fmt[k] = e.format;
			if (e.before != last[k] && bad++ < 3)
				print_error("%s: (%u,%u) entry %zu line %u op "
					    "0x%x: before 0x%x, last after "
					    "0x%x\n",
					    name, e.x, e.y, i, e.line, e.opcode,
					    e.before, last[k]);
			last[k] = e.after;
		}
		assert_int_equal(
			rdc_reg_read(dev, RDC_REG_FB_FORMAT, &mode_fmt), 0);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_H_DISPLAY, &w), 0);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_V_DISPLAY, &hh), 0);
		for (uint32_t y = CHAIN_Y; y < CHAIN_Y + CHAIN_H && y < hh; y++)
			for (uint32_t x = CHAIN_X;
			     x < CHAIN_X + CHAIN_W && x < w; x++) {
				size_t k =
					(y - CHAIN_Y) * CHAIN_W + (x - CHAIN_X);
				uint32_t v = fb_pixel(dev, x, y);

				if (fmt[k] != 0xffffffffu && fmt[k] != mode_fmt)
					continue;
				checked++;
				if (v != last[k] && bad++ < 3)
					print_error("%s: (%u,%u) holds 0x%x, "
						    "history ends at 0x%x\n",
						    name, x, y, v, last[k]);
			}
		if (bad)
			failed++;
		rdc_history_close(h);
		rdc_close(dev);
	}
	fclose(f);
	assert_true(scenes > 0);
	assert_true(checked > 0);
	assert_int_equal(failed, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_history_fill_xor_text),
		cmocka_unit_test(test_history_untouched),
		cmocka_unit_test(test_history_trace),
		cmocka_unit_test(test_history_recorder_order),
		cmocka_unit_test(test_history_torn),
		cmocka_unit_test(test_history_list_chain),
		cmocka_unit_test(test_history_subbyte),
		cmocka_unit_test(test_history_formats_errors),
		cmocka_unit_test(test_history_fb_moves),
		cmocka_unit_test(test_history_host_write),
		cmocka_unit_test(test_history_api),
		cmocka_unit_test(test_history_first_diff),
		cmocka_unit_test(test_history_golden_unchanged),
		cmocka_unit_test(test_history_chain_golden),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
