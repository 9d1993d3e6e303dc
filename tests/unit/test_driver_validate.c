// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb.ko's SUBMIT validation (driver/rdcfb_validate.c), built here in
 * user space: every command stream librdc produces for the golden scenes
 * passes it whole; malformed buffers are refused at the word that is
 * wrong; random buffers never make it read outside the buffer (ASan), and
 * whatever it accepts is whole commands.
 */
#include <dirent.h>
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hw.h"
#include "rdc.h"
#include "rdc_priv.h"

/* The kernel's names for the fixed-width types the driver uses. */
typedef uint32_t u32;
typedef uint64_t u64;

#include "../../driver/rdcfb_validate.c"

#define TV_VRAM		  (16u << 20)
#define TV_SCENES	  "tests/golden/scenes"
#define TV_FUZZ_RUNS	  10000u
#define TV_FUZZ_MAX_WORDS 64u

/* ---- librdc's own command streams pass ------------------------------------ */

struct tv_capture {
	u32 *w;
	size_t n, cap;
};

/* Every word the host writes to FIFO_DATA, in order. */
static void tv_trace(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		     uint32_t b)
{
	struct tv_capture *c = ctx;

	(void)time;
	if (event != RDC_TRACE_REG_WRITE || a != RDC_REG_FIFO_DATA)
		return;
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 4096;
		c->w = realloc(c->w, c->cap * sizeof(*c->w));
		assert_non_null(c->w);
	}
	c->w[c->n++] = b;
}

static void tv_golden_streams(void **state)
{
	DIR *d = opendir(TV_SCENES);
	struct dirent *e;
	unsigned int scenes = 0;

	(void)state;
	assert_non_null(d);
	while ((e = readdir(d))) {
		struct tv_capture c = { 0 };
		char path[512];
		rdc_dev *dev;
		u32 bad = 0;
		size_t len = strlen(e->d_name);
		int ret;

		if (len < 5 || strcmp(e->d_name + len - 4, ".rdl"))
			continue;
		snprintf(path, sizeof(path), "%s/%s", TV_SCENES, e->d_name);
		assert_int_equal(rdc_open("sim:", &dev), 0);
		rdc_hw_set_trace(rdc_sim_hw(dev), tv_trace, &c);
		rdc_script_run_file(dev, path, NULL);
		rdc_close(dev);
		ret = rdcfb_validate(c.w, (u32)c.n, TV_VRAM, &bad);
		if (ret)
			fprintf(stderr,
				"%s: refused at word %u of %zu (%08x)\n",
				e->d_name, bad, c.n, c.w[bad]);
		assert_int_equal(ret, 0);
		assert_true(c.n > 0);
		free(c.w);
		scenes++;
	}
	closedir(d);
	assert_true(scenes > 10);
}

/* ---- malformed buffers are refused at the right word ---------------------- */

static void tv_expect_at(const u32 *w, u32 n, u32 at, int line)
{
	u32 bad = ~0u;
	int ret = rdcfb_validate(w, n, TV_VRAM, &bad);

	if (ret != -EPROTO || bad != at)
		fprintf(stderr, "line %d: %d at word %u, expected word %u\n",
			line, ret, bad, at);
	assert_int_equal(ret, -EPROTO);
	assert_int_equal(bad, at);
}

#define tv_expect(w, n, at) tv_expect_at(w, n, at, __LINE__)

static void tv_malformed(void **state)
{
	const u32 fg = RDC_CMD(RDC_OP_SET_FG, 0, 1);
	u32 bad;

	(void)state;
	/* a good prefix, then each fault at index 2 or in its arguments */
	u32 unknown[] = { fg, 1, RDC_CMD(0x09, 0, 0) };
	tv_expect(unknown, 3, 2);
	u32 unknown_hi[] = { fg, 1, RDC_CMD(0x39, 0, 0) };
	tv_expect(unknown_hi, 3, 2);
	u32 past_end[] = { fg, 1, RDC_CMD(RDC_OP_NOP, 0, 5), 0, 0 };
	tv_expect(past_end, 5, 2);
	u32 too_long[] = { fg, 1,
			   RDC_CMD(RDC_OP_NOP, 0, RDC_CMD_MAX_ARGS + 1) };
	tv_expect(too_long, 3, 2);
	u32 fixed[] = { fg, 1, RDC_CMD(RDC_OP_LINE, 0, 3), 0, 0, 0 };
	tv_expect(fixed, 6, 2);
	u32 cut[] = { fg };
	tv_expect(cut, 1, 0);
	/* SET_DST whose last row leaves VRAM: the first argument */
	u32 dst[] = { fg,
		      1,
		      RDC_CMD(RDC_OP_SET_DST, 0, 4),
		      TV_VRAM - 2560 * 479,
		      2560,
		      RDC_WH(640, 480),
		      RDC_FMT_XRGB8888 };
	tv_expect(dst, 7, 3);
	u32 dst_fmt[] = { RDC_CMD(RDC_OP_SET_SRC, 0, 4), 0, 2560,
			  RDC_WH(640, 480), RDC_FMT_COUNT };
	tv_expect(dst_fmt, 5, 1);
	u32 stride[] = { RDC_CMD(RDC_OP_SET_DST, 0, 4), 0, 2556,
			 RDC_WH(640, 480), RDC_FMT_XRGB8888 };
	tv_expect(stride, 5, 1);
	u32 call[] = { fg, 1, RDC_CMD(RDC_OP_CALL, 0, 1), 2 };
	tv_expect(call, 4, 3);
	u32 jump[] = { RDC_CMD(RDC_OP_JUMP, 0, 1), TV_VRAM };
	tv_expect(jump, 2, 1);
	u32 reg[] = { RDC_CMD(RDC_OP_REG_WRITE, 0, 2), RDC_REG_WINDOW, 0 };
	tv_expect(reg, 3, 1);
	u32 rop[] = { RDC_CMD(RDC_OP_SET_ROP, 0, 1), RDC_ROP_COUNT };
	tv_expect(rop, 2, 1);
	u32 clut[] = { RDC_CMD(RDC_OP_LOAD_CLUT, 0, 3), 255, 0, 0 };
	tv_expect(clut, 4, 1);
	/* MONO 9x2: one word a row, so 2 + 2 words; 2 + 3 is wrong, and
	 * the size word is named */
	u32 mono[] = { RDC_CMD(RDC_OP_MONO, 0, 5), 0, RDC_WH(9, 2), 0, 0, 0 };
	tv_expect(mono, 6, 2);
	/* with its colours, MONO 9x2 is 4 + 2 words: 4 + 1 is short */
	u32 monoc[] = { RDC_CMD(RDC_OP_MONO, RDC_MONO_COLORS, 5),
			0,
			RDC_WH(9, 2),
			0,
			0,
			0 };
	tv_expect(monoc, 6, 2);
	/* a carried colour is not one of LINE's 2 words; POLYGON's 1 point
	 * after its colour is too few, named by the header */
	u32 line_fg[] = { RDC_CMD(RDC_OP_LINE, RDC_DRAW_FG, 2), 0xff, 0 };
	tv_expect(line_fg, 3, 0);
	u32 line_nofg[] = { RDC_CMD(RDC_OP_LINE, RDC_DRAW_FG, 0) };
	tv_expect(line_nofg, 1, 0);
	u32 poly_fg[] = { RDC_CMD(RDC_OP_POLYGON, RDC_DRAW_FG, 2), 0xff, 0 };
	tv_expect(poly_fg, 3, 0);
	/* TEXT of 5 characters is 2 words of them */
	u32 text[] = { RDC_CMD(RDC_OP_TEXT, 0, 3), 0, 5, 0 };
	tv_expect(text, 4, 2);
	u32 pat[] = { RDC_CMD(RDC_OP_SET_PATTERN, RDC_PAT_MONO, 1), 0 };
	tv_expect(pat, 2, 0);
	u32 flood[] = { RDC_CMD(RDC_OP_FLOOD_FILL, RDC_FLOOD_BOUNDARY, 1), 0 };
	tv_expect(flood, 2, 0);
	/* HOST_BLIT after a SET_DST in RGB565: 3 pixels a row are 2 words */
	u32 hb[] = { RDC_CMD(RDC_OP_SET_DST, 0, 4),
		     0,
		     1280,
		     RDC_WH(640, 480),
		     RDC_FMT_RGB565,
		     RDC_CMD(RDC_OP_HOST_BLIT, 0, 3),
		     0,
		     RDC_WH(3, 1),
		     0,
		     0 };
	tv_expect(hb, 9, 7);

	/* and their good twins pass */
	u32 mono_ok[] = { RDC_CMD(RDC_OP_MONO, 0, 4), 0, RDC_WH(9, 2), 0, 0 };
	assert_int_equal(rdcfb_validate(mono_ok, 5, TV_VRAM, &bad), 0);
	u32 line_fg_ok[] = { RDC_CMD(RDC_OP_LINE, RDC_DRAW_FG, 3), 0xff, 0,
			     RDC_XY(9, 9) };
	assert_int_equal(rdcfb_validate(line_fg_ok, 4, TV_VRAM, &bad), 0);
	u32 monoc_ok[] = { RDC_CMD(RDC_OP_MONO, RDC_MONO_COLORS, 6),
			   0,
			   RDC_WH(9, 2),
			   0xff0000,
			   0x00ff00,
			   0,
			   0 };
	assert_int_equal(rdcfb_validate(monoc_ok, 7, TV_VRAM, &bad), 0);
	u32 text_ok[] = { RDC_CMD(RDC_OP_TEXT, 0, 4), 0, 5, 0, 0 };
	assert_int_equal(rdcfb_validate(text_ok, 5, TV_VRAM, &bad), 0);
	hb[5] = RDC_CMD(RDC_OP_HOST_BLIT, 0, 4);
	assert_int_equal(rdcfb_validate(hb, 10, TV_VRAM, &bad), 0);
	u32 dst_ok[] = { RDC_CMD(RDC_OP_SET_DST, 0, 4), TV_VRAM - 2560 * 480,
			 2560, RDC_WH(640, 480), RDC_FMT_XRGB8888 };
	assert_int_equal(rdcfb_validate(dst_ok, 5, TV_VRAM, &bad), 0);
	assert_int_equal(rdcfb_validate(NULL, 0, TV_VRAM, &bad), 0);
}

/* ---- random buffers -------------------------------------------------------- */

static uint32_t tv_rand(uint64_t *s)
{
	*s = *s * 6364136223846793005ull + 1442695040888963407ull;
	return (uint32_t)(*s >> 32);
}

/*
 * Whole commands of real opcodes, mostly with the length the opcode takes
 * and small arguments, then now and then a word overwritten at random.
 */
static u32 tv_fill(uint64_t *s, u32 *w, u32 n)
{
	u32 i = 0, len, k;
	int fixed;

	while (i < n) {
		u32 op = tv_rand(s) % (RDC_OP_TRIANGLE + 2);

		fixed = rdc_cmd_args(op);
		len = fixed >= 0 && tv_rand(s) % 4 ? (u32)fixed :
						     tv_rand(s) % 12;
		if (len > n - i - 1)
			len = n - i - 1;
		w[i++] = RDC_CMD(op, tv_rand(s) % 4, len);
		for (k = 0; k < len; k++)
			w[i++] = tv_rand(s) % 8 ? tv_rand(s) % 64 : tv_rand(s);
	}
	if (n && tv_rand(s) % 8 == 0)
		w[tv_rand(s) % n] = tv_rand(s);
	return n;
}

static void tv_fuzz(void **state)
{
	uint64_t seed = 0x5eed;
	unsigned int accepted = 0;

	(void)state;
	for (unsigned int run = 0; run < TV_FUZZ_RUNS; run++) {
		u32 n = tv_rand(&seed) % TV_FUZZ_MAX_WORDS, bad = ~0u, i;
		/* exactly n words on the heap: ASan sees any read past them */
		u32 *w = malloc((n ? n : 1) * sizeof(*w));
		int ret;

		assert_non_null(w);
		tv_fill(&seed, w, n);
		ret = rdcfb_validate(w, n, TV_VRAM, &bad);
		if (ret) {
			assert_int_equal(ret, -EPROTO);
			assert_true(bad < n);
		} else {
			/* accepted: the headers tile the buffer exactly */
			for (i = 0; i < n; i += 1 + RDC_CMD_LEN(w[i]))
				;
			assert_int_equal(i, n);
			accepted++;
		}
		free(w);
	}
	/* the generator makes some good buffers, or this proves little */
	assert_true(accepted > 100);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(tv_golden_streams),
		cmocka_unit_test(tv_malformed),
		cmocka_unit_test(tv_fuzz),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
