// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pixel-moving commands against a model written from the command
 * reference: BLIT (every overlap direction, ROPs, clipping), HOST_BLIT,
 * READBACK, MONO and TEXT in every format.
 */
#include "test_dp_common.h"

/* Host words as the byte stream they stand for (little-endian). */
static void words_to_bytes(const uint32_t *w, size_t n, uint8_t *b)
{
	size_t i;

	for (i = 0; i < n * 4; i++)
		b[i] = (uint8_t)(w[i / 4] >> (8 * (i % 4)));
}

static uint32_t wpr_of(uint32_t fmt, uint32_t w)
{
	return (w * tdp_bpp(fmt) + 31) / 32;
}

static void random_fill(struct tdp *t, uint32_t *rng, size_t n)
{
	size_t i;

	for (i = 0; i < n; i++)
		t->vram[i] = (uint8_t)tdp_rand(rng);
}

static void set_clip(struct tdp *t, int32_t x0, int32_t y0, int32_t x1,
		     int32_t y1)
{
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(x0, y0), RDC_XY(x1, y1));
}

static int in_rect(int64_t x, int64_t y, int64_t x0, int64_t y0, int64_t x1,
		   int64_t y1)
{
	return x >= x0 && x < x1 && y >= y0 && y < y1;
}

#define WIN 0x20000u /* bytes of VRAM the blit tests use */

/*
 * Random blits.  Expected: every source pixel read before anything is
 * written, copied where both its source position is on the source surface
 * and its destination inside clip and destination surface.  `copy_rows`:
 * ROP COPY in the whole-byte formats only, whose rows the fast path
 * copies as bytes.
 */
static void blit_rounds(struct tdp *t, uint32_t rng, uint32_t rounds,
			bool copy_rows)
{
	static const uint32_t byte_fmts[] = { RDC_FMT_I8, RDC_FMT_RGB565,
					      RDC_FMT_RGB888,
					      RDC_FMT_XRGB8888 };
	uint8_t *before = malloc(WIN), *want = malloc(WIN);
	uint32_t k;

	assert_non_null(before);
	assert_non_null(want);
	for (k = 0; k < rounds; k++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
		uint32_t rop = tdp_rand(&rng) % RDC_ROP_COUNT;
		uint32_t mode = tdp_rand(&rng) % 3;
		struct rdc_surface ss, ds;
		struct rdc_rect c;
		int32_t sx, sy, dx, dy, w, h, i, j;

		if (copy_rows) {
			fmt = byte_fmts[fmt % RDC_ARRAY_SIZE(byte_fmts)];
			rop = RDC_ROP_COPY;
		}
		ss.format = fmt;
		ss.width = (uint32_t)tdp_range(&rng, 8, 100);
		ss.height = (uint32_t)tdp_range(&rng, 8, 80);
		ss.stride = rdc_format_row_bytes(fmt, ss.width) +
			    (uint32_t)tdp_range(&rng, 0, 5);
		ss.base = (uint32_t)tdp_range(&rng, 64, 1024);
		ds = ss;
		if (mode == 1) {
			/* same stride, shifted a few bytes/rows: overlap */
			ds.base = ss.base +
				  (uint32_t)tdp_range(&rng, 0, 3 * ss.stride);
			if (tdp_rand(&rng) % 2) {
				uint32_t tmp = ds.base;

				ds.base = ss.base;
				ss.base = tmp;
			}
		} else if (mode == 2) {
			ds.width = (uint32_t)tdp_range(&rng, 8, 100);
			ds.height = (uint32_t)tdp_range(&rng, 8, 80);
			ds.stride = rdc_format_row_bytes(fmt, ds.width) + 3;
			ds.base = 0x10000;
		}
		w = tdp_range(&rng, 0, 120);
		h = tdp_range(&rng, 0, 90);
		sx = tdp_range(&rng, -30, 100);
		sy = tdp_range(&rng, -30, 80);
		dx = tdp_range(&rng, -30, 100);
		dy = tdp_range(&rng, -30, 80);
		c.x0 = tdp_range(&rng, -5, 20);
		c.y0 = tdp_range(&rng, -5, 20);
		c.x1 = tdp_range(&rng, c.x0, 110);
		c.y1 = tdp_range(&rng, c.y0, 90);

		random_fill(t, &rng, WIN);
		memcpy(before, t->vram, WIN);
		memcpy(want, t->vram, WIN);
		for (j = 0; j < h; j++)
			for (i = 0; i < w; i++) {
				uint32_t s, d;

				if (!in_rect(sx + i, sy + j, 0, 0, ss.width,
					     ss.height) ||
				    !in_rect(dx + i, dy + j, c.x0, c.y0, c.x1,
					     c.y1) ||
				    !in_rect(dx + i, dy + j, 0, 0, ds.width,
					     ds.height))
					continue;
				s = tdp_get(before, &ss, sx + i, sy + j);
				d = tdp_get(want, &ds, dx + i, dy + j);
				tdp_put(want, &ds, dx + i, dy + j,
					tdp_rop(rop, s, d));
			}

		tdp_set_surface(t, RDC_OP_SET_SRC, &ss);
		tdp_set_surface(t, RDC_OP_SET_DST, &ds);
		set_clip(t, c.x0, c.y0, c.x1, c.y1);
		TDP_CMD(t, RDC_OP_SET_ROP, rop);
		TDP_CMD(t, RDC_OP_BLIT, RDC_XY(sx, sy), RDC_XY(dx, dy),
			RDC_WH(w, h));
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		if (memcmp(want, t->vram, WIN)) {
			size_t b;

			for (b = 0; want[b] == t->vram[b]; b++)
				;
			fail_msg("blit %u: fmt %u rop %u mode %u byte %zu", k,
				 fmt, rop, mode, b);
		}
	}
	free(before);
	free(want);
}

static void test_blit_random(void **state)
{
	blit_rounds(*state, 2024, 400, false);
}

/* Rows copied as bytes, of every length and alignment, apart or not. */
static void test_blit_copy_rows(void **state)
{
	blit_rounds(*state, 7, 300, true);
}

/* Blits that overlap in the same rows, both directions, long rows. */
static void test_blit_overlap_rows(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = { 0, 8192 * 4, 8192, 4, RDC_FMT_XRGB8888 };
	int32_t shift;

	for (shift = -37; shift <= 37; shift += 74) {
		uint32_t x;

		for (x = 0; x < 8192; x++)
			rdc_st32(t->vram + 4 * x, x);
		tdp_set_surface(t, RDC_OP_SET_SRC, &s);
		tdp_set_surface(t, RDC_OP_SET_DST, &s);
		/* 3000 pixels: several staging pieces per row */
		TDP_CMD(t, RDC_OP_BLIT, RDC_XY(100, 0), RDC_XY(100 + shift, 0),
			RDC_WH(3000, 1));
		tdp_drain(t);
		for (x = 0; x < 8192; x++) {
			uint32_t want = x;

			if ((int32_t)x >= 100 + shift &&
			    (int32_t)x < 3100 + shift)
				want = (uint32_t)((int32_t)x - shift);
			assert_int_equal(rdc_ld32(t->vram + 4 * x), want);
		}
	}
}

static void test_blit_bpp_mismatch(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = { 0, 64, 64, 8, RDC_FMT_I8 };

	tdp_set_surface(t, RDC_OP_SET_SRC, &s);
	TDP_CMD(t, RDC_OP_BLIT, RDC_XY(0, 0), RDC_XY(0, 0), RDC_WH(4, 4));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
}

static void test_host_blit_random(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 77, k;
	uint8_t *want = malloc(WIN);
	uint32_t *data = malloc(4094 * 4);
	uint8_t *bytes = malloc(4094 * 4);

	assert_non_null(want);
	assert_non_null(data);
	assert_non_null(bytes);
	for (k = 0; k < 200; k++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
		uint32_t rop = tdp_rand(&rng) % RDC_ROP_COUNT;
		struct rdc_surface ds = { 128, 0, 0, 0, fmt };
		struct rdc_surface hs = { 0, 0, 0, 0, fmt };
		int32_t x, y, w, h, i, j;
		uint32_t wpr, n, args[2];

		ds.width = (uint32_t)tdp_range(&rng, 4, 90);
		ds.height = (uint32_t)tdp_range(&rng, 4, 60);
		ds.stride = rdc_format_row_bytes(fmt, ds.width) + 1;
		w = tdp_range(&rng, 0, 60);
		h = tdp_range(&rng, 0, 40);
		x = tdp_range(&rng, -20, 80);
		y = tdp_range(&rng, -20, 60);
		wpr = wpr_of(fmt, (uint32_t)w);
		n = wpr * (uint32_t)h;
		for (i = 0; i < (int32_t)n; i++)
			data[i] = tdp_rand(&rng);
		words_to_bytes(data, n, bytes);
		hs.stride = wpr * 4;

		random_fill(t, &rng, WIN);
		memcpy(want, t->vram, WIN);
		for (j = 0; j < h; j++)
			for (i = 0; i < w; i++) {
				if (!in_rect(x + i, y + j, 0, 0, ds.width,
					     ds.height))
					continue;
				tdp_put(want, &ds, x + i, y + j,
					tdp_rop(rop, tdp_get(bytes, &hs, i, j),
						tdp_get(want, &ds, x + i,
							y + j)));
			}
		tdp_set_surface(t, RDC_OP_SET_DST, &ds);
		TDP_CMD(t, RDC_OP_SET_ROP, rop);
		args[0] = RDC_XY(x, y);
		args[1] = RDC_WH(w, h);
		tdp_push(t, RDC_CMD(RDC_OP_HOST_BLIT, 0, 2 + n));
		tdp_push(t, args[0]);
		tdp_push(t, args[1]);
		for (i = 0; i < (int32_t)n; i++)
			tdp_push(t, data[i]);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_memory_equal(want, t->vram, WIN);
	}
	free(want);
	free(data);
	free(bytes);
}

/* Pop n words of RDATA, running the chip while the DP produces them. */
static void read_rdata(struct tdp *t, uint32_t *out, uint32_t n)
{
	uint32_t got = 0, spins = 0;

	while (got < n) {
		uint32_t avail = rdc_hw_read(&t->hw, RDC_REG_RDATA_COUNT);

		if (!avail) {
			assert_true(++spins < TDP_RUN_LIMIT);
			rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
			continue;
		}
		while (avail-- && got < n)
			out[got++] = rdc_hw_read(&t->hw, RDC_REG_RDATA);
	}
}

static void test_readback_random(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 5150, k;
	uint32_t *got = malloc(16384 * 4), *want = malloc(16384 * 4);
	uint8_t *bytes = malloc(16384 * 4);

	assert_non_null(got);
	assert_non_null(want);
	assert_non_null(bytes);
	for (k = 0; k < 200; k++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT, wpr, n, i;
		struct rdc_surface ss = { 64, 0, 0, 0, fmt };
		struct rdc_surface out = { 0, 0, 0, 0, fmt };
		int32_t x, y, w, h, c, r;

		ss.width = (uint32_t)tdp_range(&rng, 4, 90);
		ss.height = (uint32_t)tdp_range(&rng, 4, 60);
		ss.stride = rdc_format_row_bytes(fmt, ss.width) + 2;
		w = tdp_range(&rng, 0, 100);
		h = tdp_range(&rng, 0, 60);
		x = tdp_range(&rng, -20, 90);
		y = tdp_range(&rng, -20, 60);
		wpr = wpr_of(fmt, (uint32_t)w);
		n = wpr * (uint32_t)h;
		out.stride = wpr * 4;
		random_fill(t, &rng, WIN);
		memset(bytes, 0, (size_t)n * 4);
		for (r = 0; r < h; r++)
			for (c = 0; c < w; c++)
				if (in_rect(x + c, y + r, 0, 0, ss.width,
					    ss.height))
					tdp_put(bytes, &out, c, r,
						tdp_get(t->vram, &ss, x + c,
							y + r));
		for (i = 0; i < n; i++)
			want[i] = rdc_ld32(bytes + 4 * i);

		tdp_set_surface(t, RDC_OP_SET_SRC, &ss);
		TDP_CMD(t, RDC_OP_READBACK, RDC_XY(x, y), RDC_WH(w, h));
		read_rdata(t, got, n);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_RDATA_COUNT), 0);
		assert_memory_equal(want, got, (size_t)n * 4);
	}
	free(got);
	free(want);
	free(bytes);
}

/* MONO and TEXT: 1 = FG, 0 = BG or untouched when transparent. */
static void test_mono_text_random(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 8086, k;
	uint8_t *want = malloc(WIN);
	uint32_t data[512];

	assert_non_null(want);
	for (k = 0; k < 300; k++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
		uint32_t rop = tdp_rand(&rng) % RDC_ROP_COUNT;
		uint32_t fg = tdp_rand(&rng), bg = tdp_rand(&rng);
		bool tr = tdp_rand(&rng) % 2, text = tdp_rand(&rng) % 2;
		struct rdc_surface ds = { 256, 0, 0, 0, fmt };
		int32_t x, y, w, h, i, j;
		uint32_t n, wpr, cnt = 0;

		ds.width = (uint32_t)tdp_range(&rng, 4, 200);
		ds.height = (uint32_t)tdp_range(&rng, 4, 60);
		ds.stride = rdc_format_row_bytes(fmt, ds.width) + 1;
		x = tdp_range(&rng, -20, 150);
		y = tdp_range(&rng, -20, 60);
		if (text) {
			cnt = (uint32_t)tdp_range(&rng, 0, 30);
			w = (int32_t)cnt * 8;
			h = 16;
			n = (cnt + 3) / 4;
			wpr = 0;
		} else {
			w = tdp_range(&rng, 0, 100);
			h = tdp_range(&rng, 0, 40);
			wpr = ((uint32_t)w + 31) / 32;
			n = wpr * (uint32_t)h;
		}
		for (i = 0; i < (int32_t)n; i++)
			data[i] = tdp_rand(&rng);

		random_fill(t, &rng, WIN);
		memcpy(want, t->vram, WIN);
		for (j = 0; j < h; j++)
			for (i = 0; i < w; i++) {
				uint32_t byte, bit, v;

				if (!in_rect(x + i, y + j, 0, 0, ds.width,
					     ds.height))
					continue;
				if (text) {
					uint32_t ch = (data[i / 32] >>
						       (8 * ((i / 8) % 4))) &
						      0xff;

					byte = rdc_font8x16[ch * 16 + j];
				} else {
					uint32_t b = (uint32_t)i / 8;

					byte = (data[j * wpr + b / 4] >>
						(8 * (b % 4))) &
					       0xff;
				}
				bit = (byte >> (7 - i % 8)) & 1;
				if (!bit && tr)
					continue;
				v = bit ? fg : bg;
				tdp_put(want, &ds, x + i, y + j,
					tdp_rop(rop, v & tdp_mask(fmt),
						tdp_get(want, &ds, x + i,
							y + j)));
			}
		tdp_set_surface(t, RDC_OP_SET_DST, &ds);
		TDP_CMD(t, RDC_OP_SET_ROP, rop);
		TDP_CMD(t, RDC_OP_SET_FG, fg);
		TDP_CMD(t, RDC_OP_SET_BG, bg);
		if (text) {
			tdp_push(t,
				 RDC_CMD(RDC_OP_TEXT,
					 tr ? RDC_MONO_TRANSPARENT : 0, 2 + n));
			tdp_push(t, RDC_XY(x, y));
			tdp_push(t, cnt);
		} else {
			tdp_push(t,
				 RDC_CMD(RDC_OP_MONO,
					 tr ? RDC_MONO_TRANSPARENT : 0, 2 + n));
			tdp_push(t, RDC_XY(x, y));
			tdp_push(t, RDC_WH(w, h));
		}
		for (i = 0; i < (int32_t)n; i++)
			tdp_push(t, data[i]);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		if (memcmp(want, t->vram, WIN))
			fail_msg("%s %u: fmt %u rop %u tr %d",
				 text ? "text" : "mono", k, fmt, rop, tr);
	}
	free(want);
}

/*
 * MONO with RDC_MONO_COLORS against SET_FG, SET_BG, MONO: the same
 * pixels, the same FG and BG afterwards, and 10 cycles less (two FIFO
 * words of 1 cycle and two decodes of 4 fewer).  Each run starts from
 * the same VRAM and the same open DRAM row (a pixel drawn far away).
 * One a word short is refused: the colours are written if it holds them.
 */
static uint64_t mono_colors_run(struct tdp *t, const struct rdc_surface *ds,
				const uint32_t *cmd, uint32_t n)
{
	const struct rdc_surface far = { 3u << 20, 64, 16, 16,
					 RDC_FMT_XRGB8888 };
	uint64_t busy;
	uint32_t i;

	tdp_set_surface(t, RDC_OP_SET_DST, &far);
	TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(1, 1));
	tdp_set_surface(t, RDC_OP_SET_DST, ds);
	tdp_drain(t);
	busy = t->hw.perf.busy;
	for (i = 0; i < n; i++)
		tdp_push(t, cmd[i]);
	tdp_drain(t);
	return t->hw.perf.busy - busy;
}

static void test_mono_colors(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0x6c79, k, i, n;
	uint8_t *orig = malloc(WIN), *want = malloc(WIN);
	uint32_t cmd[4 + 6 + 128];
	uint64_t busy;

	assert_non_null(orig);
	assert_non_null(want);
	for (k = 0; k < 200; k++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
		uint32_t fg = tdp_rand(&rng), bg = tdp_rand(&rng);
		bool tr = tdp_rand(&rng) % 2;
		struct rdc_surface ds = { 256, 0, 0, 0, fmt };
		uint32_t w = (uint32_t)tdp_range(&rng, 0, 64);
		uint32_t h = (uint32_t)tdp_range(&rng, 0, 32);
		uint32_t words = (w + 31) / 32 * h;
		uint32_t fl = tr ? RDC_MONO_TRANSPARENT : 0;
		uint32_t xy = RDC_XY(tdp_range(&rng, -20, 150),
				     tdp_range(&rng, -20, 60));

		ds.width = (uint32_t)tdp_range(&rng, 4, 200);
		ds.height = (uint32_t)tdp_range(&rng, 4, 60);
		ds.stride = rdc_format_row_bytes(fmt, ds.width) + 1;
		random_fill(t, &rng, WIN);
		memcpy(orig, t->vram, WIN);
		TDP_CMD(t, RDC_OP_SET_ROP, tdp_rand(&rng) % RDC_ROP_COUNT);

		/* the three commands */
		n = 0;
		cmd[n++] = RDC_CMD(RDC_OP_SET_FG, 0, 1);
		cmd[n++] = fg;
		cmd[n++] = RDC_CMD(RDC_OP_SET_BG, 0, 1);
		cmd[n++] = bg;
		cmd[n++] = RDC_CMD(RDC_OP_MONO, fl, 2 + words);
		cmd[n++] = xy;
		cmd[n++] = RDC_WH(w, h);
		for (i = 0; i < words; i++)
			cmd[n++] = tdp_rand(&rng);
		busy = mono_colors_run(t, &ds, cmd, n);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->dp.st.fg, fg);
		assert_int_equal(t->dp.st.bg, bg);
		memcpy(want, t->vram, WIN);

		/* the one: other colours before it, the same VRAM */
		memcpy(t->vram, orig, WIN);
		TDP_CMD(t, RDC_OP_SET_FG, ~fg);
		TDP_CMD(t, RDC_OP_SET_BG, ~bg);
		cmd[2] = RDC_CMD(RDC_OP_MONO, fl | RDC_MONO_COLORS, 4 + words);
		cmd[3] = xy;
		cmd[4] = RDC_WH(w, h);
		cmd[5] = fg;
		cmd[6] = bg;
		busy -= mono_colors_run(t, &ds, cmd + 2, n - 2);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);
		assert_int_equal(t->dp.st.fg, fg);
		assert_int_equal(t->dp.st.bg, bg);
		if (memcmp(want, t->vram, WIN))
			fail_msg("mono colors %u: fmt %u tr %d", k, fmt, tr);
		/* the three's busy cycles less the one's: 2 + 2 * 4 */
		assert_int_equal(busy, 2 * RDC_T_FIFO_WORD + 2 * RDC_T_DECODE);

		/*
		 * a word short: refused, but the colours written, as the
		 * SET_FG and SET_BG before a refused MONO would write them;
		 * too short to hold them, nothing written
		 */
		memcpy(want, t->vram, WIN);
		cmd[2] = RDC_CMD(RDC_OP_MONO, fl | RDC_MONO_COLORS, 3 + words);
		cmd[5] = ~fg;
		cmd[6] = ~bg;
		mono_colors_run(t, &ds, cmd + 2, n - 3);
		assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
		tdp_clear_err(t);
		assert_int_equal(t->dp.st.fg, words ? ~fg : fg);
		assert_int_equal(t->dp.st.bg, words ? ~bg : bg);
		assert_memory_equal(want, t->vram, WIN);
	}
	free(want);
	free(orig);
}

/* A known glyph: 'A' in the built-in font, drawn at an odd position. */
static void test_text_glyph(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface ds = { 0, 64, 64, 32, RDC_FMT_I8 };
	int32_t x, y;

	memset(t->vram, 0, 64 * 32);
	tdp_set_surface(t, RDC_OP_SET_DST, &ds);
	TDP_CMD(t, RDC_OP_SET_FG, 7);
	TDP_CMD(t, RDC_OP_SET_BG, 1);
	TDP_CMD(t, RDC_OP_TEXT, RDC_XY(3, 5), 2, 'A' | ('B' << 8));
	tdp_drain(t);
	for (y = 0; y < 32; y++)
		for (x = 0; x < 64; x++) {
			uint8_t want = 0;

			if (x >= 3 && x < 19 && y >= 5 && y < 21) {
				uint32_t ch = x < 11 ? 'A' : 'B';
				uint32_t row = rdc_font8x16[ch * 16 + y - 5];

				want = (row >> (7 - (x - 3) % 8)) & 1 ? 7 : 1;
			}
			assert_int_equal(t->vram[y * 64 + x], want);
		}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_blit_random),
		TDP_TEST(test_blit_copy_rows),
		TDP_TEST(test_blit_overlap_rows),
		TDP_TEST(test_blit_bpp_mismatch),
		TDP_TEST(test_host_blit_random),
		TDP_TEST(test_readback_random),
		TDP_TEST(test_mono_text_random),
		TDP_TEST(test_mono_colors),
		TDP_TEST(test_text_glyph),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
