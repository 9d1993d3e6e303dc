// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The fast paths against the plain ones.  Two chips get the same command
 * stream, one with the display processor's fast paths (queued runs for
 * lines and glyph rows, byte-wise blits, staged-pixel stores) and one with
 * dp.ref_paths set, which keeps it on the per-pixel loops.  Scanout runs
 * on both, so fetch windows and line starts interrupt the queued runs at
 * random points.  After every batch the two must agree on every VRAM
 * byte, the simulated time, every performance counter and the last
 * scanned-out frame (which shows exactly when each pixel was written).
 *
 * The bus model's bulk entries are checked the same way against the
 * per-access calls they stand for, and the XRGB8888 scanout conversion and
 * the solid fill against a pixel model written from rdc_regs.h.
 */
#include "test_dp_common.h"
#include "rdc.h"

#define TP_CHIPS  2
#define TP_W	  320
#define TP_H	  200
#define TP_BATCH  40
#define TP_ROUNDS 12

struct tp_pair {
	struct tdp *c[TP_CHIPS]; /* [0] fast paths, [1] reference */
};

/* A chip with scanout on and the DP enabled: 320x200 XRGB8888 at 0. */
static struct tdp *tp_chip(bool ref)
{
	struct tdp *t = tdp_new();

	t->dp.ref_paths = ref;
	rdc_hw_write(&t->hw, RDC_REG_MODE_PRESET, RDC_PRESET_320x200_70);
	rdc_hw_write(&t->hw, RDC_REG_FB_BASE, 0);
	rdc_hw_write(&t->hw, RDC_REG_FB_FORMAT, RDC_FMT_XRGB8888);
	rdc_hw_write(&t->hw, RDC_REG_FB_STRIDE, TP_W * 4);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	return t;
}

static int tp_setup(void **state)
{
	struct tp_pair *p = calloc(1, sizeof(*p));

	assert_non_null(p);
	p->c[0] = tp_chip(false);
	p->c[1] = tp_chip(true);
	*state = p;
	return 0;
}

static int tp_teardown(void **state)
{
	struct tp_pair *p = *state;

	tdp_free(p->c[0]);
	tdp_free(p->c[1]);
	free(p);
	return 0;
}

static void tp_cmd(struct tp_pair *p, uint32_t op, uint32_t flags,
		   unsigned int n, const uint32_t *a)
{
	unsigned int i;

	for (i = 0; i < TP_CHIPS; i++)
		tdp_cmd(p->c[i], op, flags, n, a);
}

#define TP_CMD(p, op, ...) \
	do { \
		const uint32_t tp_a_[] = { __VA_ARGS__ }; \
		tp_cmd((p), (op), 0, RDC_ARRAY_SIZE(tp_a_), tp_a_); \
	} while (0)

/* Drain both and compare everything observable. */
static void tp_check(struct tp_pair *p)
{
	struct tdp *a = p->c[0], *b = p->c[1];
	const uint32_t *fa, *fb;
	uint32_t wa, ha, wb, hb;

	tdp_drain(a);
	tdp_drain(b);
	assert_memory_equal(a->vram, b->vram, TDP_VRAM_SIZE);
	assert_int_equal(a->hw.now, b->hw.now);
	assert_int_equal(a->hw.perf.busy, b->hw.perf.busy);
	assert_int_equal(a->hw.perf.stall, b->hw.perf.stall);
	assert_int_equal(a->hw.perf.pixels, b->hw.perf.pixels);
	assert_int_equal(a->hw.perf.cmds, b->hw.perf.cmds);
	assert_int_equal(a->hw.bus.open_row, b->hw.bus.open_row);
	assert_int_equal(tdp_err(a), tdp_err(b));
	fa = rdc_hw_frame(&a->hw, &wa, &ha);
	fb = rdc_hw_frame(&b->hw, &wb, &hb);
	assert_int_equal(wa, wb);
	assert_int_equal(ha, hb);
	if (fa && fb)
		assert_memory_equal(fa, fb, (size_t)wa * ha * 4);
}

/* Scanout must have been seen racing the DP, or the test proves less. */
static void tp_assert_raced(struct tp_pair *p)
{
	assert_true(p->c[0]->hw.perf.stall > 0);
}

/*
 * A random DST: the screen, or an offscreen surface of a random format
 * (whole-byte ones mostly, sub-byte and 24 bpp too, whose runs take the
 * per-pixel path), sometimes at a base that is not pixel-aligned.
 */
static void tp_random_dst(struct tp_pair *p, uint32_t *seed, uint32_t op)
{
	static const uint32_t fmts[] = {
		RDC_FMT_XRGB8888, RDC_FMT_XRGB8888, RDC_FMT_RGB565,
		RDC_FMT_I8,	  RDC_FMT_RGB888,   RDC_FMT_I4,
	};
	struct rdc_surface s = { 0, TP_W * 4, TP_W, TP_H, RDC_FMT_XRGB8888 };

	if (tdp_rand(seed) % 3) {
		s.format = fmts[tdp_rand(seed) % RDC_ARRAY_SIZE(fmts)];
		s.width = (uint32_t)tdp_range(seed, 16, TP_W);
		s.height = (uint32_t)tdp_range(seed, 16, TP_H);
		s.stride = (s.width * tdp_bpp(s.format) + 7) / 8 +
			   (uint32_t)tdp_range(seed, 0, 9);
		s.base = (1u << 20) + (uint32_t)tdp_range(seed, 0, 3) *
					      (tdp_rand(seed) % 2 ? 1 : 4);
	}
	/* rows whole DRAM rows apart: filled rectangles' closed form; rows
	 * more than a DRAM row apart (a 640-pixel screen's): lines' */
	if (s.format == RDC_FMT_XRGB8888) {
		switch (tdp_rand(seed) % 3) {
		case 0:
			s.stride = RDC_DRAM_ROW_BYTES *
				   (s.width * 4 > 2048 ? 2 : 1);
			break;
		case 1:
			s.stride = 640 * 4;
			break;
		default:
			break;
		}
	}
	tdp_set_surface(p->c[0], op, &s);
	tdp_set_surface(p->c[1], op, &s);
}

static void tp_random_state(struct tp_pair *p, uint32_t *seed)
{
	int32_t x0 = tdp_range(seed, -20, 100), y0 = tdp_range(seed, -20, 80);

	TP_CMD(p, RDC_OP_SET_FG, tdp_rand(seed));
	TP_CMD(p, RDC_OP_SET_BG, tdp_rand(seed));
	/* COPY half the time: the fast stores; any ROP otherwise */
	TP_CMD(p, RDC_OP_SET_ROP,
	       tdp_rand(seed) % 2 ? RDC_ROP_COPY : tdp_rand(seed) % 16);
	if (tdp_rand(seed) % 2)
		TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(x0, y0),
		       RDC_XY(x0 + tdp_range(seed, 0, 300),
			      y0 + tdp_range(seed, 0, 200)));
	else
		TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(TP_W, TP_H));
}

static uint32_t tp_xy(uint32_t *seed)
{
	return RDC_XY(tdp_range(seed, -40, TP_W + 40),
		      tdp_range(seed, -40, TP_H + 40));
}

static void test_lines_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0x11e5u;
	unsigned int round, i;

	for (round = 0; round < TP_ROUNDS; round++) {
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		tp_random_state(p, &seed);
		for (i = 0; i < TP_BATCH; i++) {
			uint32_t a = tp_xy(&seed), b = tp_xy(&seed);

			/* some axis-parallel and diagonal ones */
			if (i % 7 == 1)
				b = RDC_XY(RDC_X(a), RDC_Y(b));
			if (i % 7 == 2)
				b = RDC_XY(RDC_X(a) + 50, RDC_Y(a) + 50);
			TP_CMD(p, RDC_OP_LINE, a, b);
			if (i % 5 == 0)
				TP_CMD(p, RDC_OP_SET_FG, tdp_rand(&seed));
		}
		tp_check(p);
	}
	/*
	 * A 1024-pixel screen of 4096-byte rows, as rdc-bench's: x-major
	 * runs cross a DRAM row at x = 512 (line_fast's run cost table);
	 * then runs longer than a row, which it leaves to span_cost32.
	 */
	TP_CMD(p, RDC_OP_SET_DST, 1u << 20, 4096, RDC_WH(1024, 200),
	       RDC_FMT_XRGB8888);
	TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(1024, 200));
	TP_CMD(p, RDC_OP_SET_ROP, RDC_ROP_COPY);
	for (round = 0; round < 4; round++) {
		for (i = 0; i < TP_BATCH; i++) {
			int32_t x0 = tdp_range(&seed, -20, 1044),
				y0 = tdp_range(&seed, -20, 220);
			int32_t x1 = tdp_range(&seed, -20, 1044),
				y1 = i % 3 ? tdp_range(&seed, -20, 220) :
					     y0 + tdp_range(&seed, -2, 2);

			TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		}
		tp_check(p);
	}
	/*
	 * Lines between 26.6 and 63.4 degrees from an axis (runs of one
	 * pixel or two), and a quarter of them between 11.3 and 26.6
	 * (runs of two to five), on a screen 700 rows tall, long enough
	 * that line starts fall inside line_stretches32's stretches, both
	 * axes, both directions.
	 */
	TP_CMD(p, RDC_OP_SET_DST, 1u << 20, 4096, RDC_WH(1024, 700),
	       RDC_FMT_XRGB8888);
	TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(1024, 700));
	for (round = 0; round < 6; round++) {
		for (i = 0; i < TP_BATCH; i++) {
			int32_t n = tdp_range(&seed, 10, 600);
			int32_t m =
				i % 4 < 3 ?
					n / 2 + 1 +
						tdp_range(&seed, 0, n / 2 - 1) :
					n / 5 + tdp_range(&seed, 1,
							  n / 2 - n / 5);
			int32_t du = tdp_rand(&seed) % 2 ? n : -n;
			int32_t dv = tdp_rand(&seed) % 2 ? m : -m;
			int32_t x0 = tdp_range(&seed, 0, 1023),
				y0 = tdp_range(&seed, 0, 699);

			if (tdp_rand(&seed) % 2)
				TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, y0),
				       RDC_XY(x0 + du, y0 + dv));
			else
				TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, y0),
				       RDC_XY(x0 + dv, y0 + du));
		}
		tp_check(p);
	}
	/*
	 * Shallow lines across x = 512, where a DRAM row ends: runs of two
	 * to eight pixels that cross it cost a row miss more than any
	 * run's base, which a stretch's bound must allow for.
	 */
	for (round = 0; round < 25; round++) {
		for (i = 0; i < TP_BATCH; i++) {
			int32_t n = tdp_range(&seed, 20, 160);
			int32_t m = n / 9 + tdp_range(&seed, 1, n / 2 - n / 9);
			int32_t x0 = tdp_range(&seed, 512 - n, 511),
				y0 = tdp_range(&seed, 0, 699 - m);

			TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, y0),
			       RDC_XY(x0 + n, y0 + m));
		}
		tp_check(p);
	}
	/* 4096 pixels wide: whole middle runs longer than a DRAM row */
	TP_CMD(p, RDC_OP_SET_DST, 1u << 20, 16384, RDC_WH(4096, 16),
	       RDC_FMT_XRGB8888);
	TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(4096, 16));
	for (i = 0; i < TP_BATCH; i++) {
		int32_t y0 = tdp_range(&seed, 0, 10);

		TP_CMD(p, RDC_OP_LINE, RDC_XY(tdp_range(&seed, 0, 200), y0),
		       RDC_XY(tdp_range(&seed, 3800, 4095),
			      y0 + tdp_range(&seed, 2, 5)));
	}
	tp_check(p);
	tp_assert_raced(p);
}

/*
 * A line start's fetch leaves open the DRAM row its last bytes are in,
 * and a run drawn just after it in that row costs no row miss.  On a
 * surface at 0 with 4096-byte rows, row 5 is DRAM row 10 (its first 512
 * pixels), which the fetch of screen line 16 (1280-byte lines) ends in
 * and no other line's does.  One line at a time crosses row 5, started
 * a little earlier each round before line 16 starts, so that the event
 * falls in its runs before, at and after row 5: x-major (runs of one
 * pixel or two, within a burst) and y-major.
 */
static void test_lines_fetch_row(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t seed = 0xf37c4u, early;

	assert_int_equal((16 * TP_W * 4 + TP_W * 4 - 1) / RDC_DRAM_ROW_BYTES,
			 5 * 4096 / RDC_DRAM_ROW_BYTES);
	TP_CMD(p, RDC_OP_SET_DST, 0, 4096, RDC_WH(512, 12), RDC_FMT_XRGB8888);
	TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(512, 12));
	TP_CMD(p, RDC_OP_SET_ROP, RDC_ROP_COPY);
	tp_check(p);
	for (early = 0; early < 1200; early += 4) {
		uint64_t t = rdc_port_next_line(a, 16) - early;
		int32_t x0 = tdp_range(&seed, 0, 400);

		rdc_hw_run_until(a, RDC_MAX(t, a->now));
		rdc_hw_run_until(b, a->now);
		TP_CMD(p, RDC_OP_SET_FG, tdp_rand(&seed));
		if (early % 8)
			TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, 0),
			       RDC_XY(x0 + tdp_range(&seed, 10, 19), 10));
		else
			TP_CMD(p, RDC_OP_LINE, RDC_XY(x0, 0),
			       RDC_XY(x0 + tdp_range(&seed, 2, 9), 10));
		tp_check(p);
	}
	tp_assert_raced(p);
}

/* A trace that only counts line starts. */
static void tp_trace_lines(void *ctx, uint64_t time, unsigned int event,
			   uint32_t a, uint32_t b)
{
	(void)time;
	(void)a;
	(void)b;
	if (event == RDC_TRACE_LINE)
		(*(uint64_t *)ctx)++;
}

/*
 * The quiet line starts the DP's windows and bursts take themselves
 * (rdc_crtc_next_quiet, rdc_crtc_quiet_line) against the CRTC's own
 * catch-up: chip 1 is traced, so that none is quiet and every line start
 * goes through rdc_crtc_catch_up.  Lines, fills, blits and glyphs keep
 * the DP busy over many frames (now and then idling to anywhere in one),
 * so that frame starts, the vblank and the blank lines after it fall
 * inside DP accesses: the same VRAM, time, stalls, open row and frame.
 */
static void quiet_lines(struct tp_pair *p, uint32_t seed, uint32_t stride)
{
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t round, i, k, g[4 + 16];
	uint64_t lines = 0, frames0 = a->crtc.frame_count;

	p->c[1]->dp.ref_paths = false;
	rdc_hw_set_trace(b, tp_trace_lines, &lines);
	for (round = 0; round < 64; round++) {
		TP_CMD(p, RDC_OP_SET_DST, 0, stride, RDC_WH(TP_W, TP_H),
		       RDC_FMT_XRGB8888);
		TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(TP_W, TP_H));
		TP_CMD(p, RDC_OP_SET_ROP,
		       round % 3 ? RDC_ROP_COPY : RDC_ROP_XOR);
		for (i = 0; i < TP_BATCH; i++) {
			TP_CMD(p, RDC_OP_SET_FG, tdp_rand(&seed));
			switch (i % 4) {
			case 0:
				TP_CMD(p, RDC_OP_LINE, tp_xy(&seed),
				       tp_xy(&seed));
				break;
			case 1:
				TP_CMD(p, RDC_OP_FILL_RECT, tp_xy(&seed),
				       RDC_WH(tdp_range(&seed, 1, 300),
					      tdp_range(&seed, 1, 200)));
				break;
			case 2:
				TP_CMD(p, RDC_OP_BLIT, tp_xy(&seed),
				       tp_xy(&seed),
				       RDC_WH(tdp_range(&seed, 1, 200),
					      tdp_range(&seed, 1, 120)));
				break;
			default: /* a glyph with its colours */
				g[0] = tp_xy(&seed);
				g[1] = RDC_WH(8, 16);
				for (k = 2; k < RDC_ARRAY_SIZE(g); k++)
					g[k] = tdp_rand(&seed);
				tp_cmd(p, RDC_OP_MONO, RDC_MONO_COLORS,
				       RDC_ARRAY_SIZE(g), g);
				break;
			}
		}
		tp_check(p);
		/* now and then, idle to anywhere in the next frame */
		if (round % 8 == 7) {
			rdc_hw_run_until(a, a->now + tdp_rand(&seed) % 1500000);
			rdc_hw_run_until(b, a->now);
		}
	}
	assert_true(a->crtc.frame_count - frames0 >= 10);
	assert_true(lines > 2000); /* the reference saw them all */
	tp_assert_raced(p);
}

static void test_quiet_lines_match(void **state)
{
	quiet_lines(*state, 0x9a1e7u, TP_W * 4);
}

/*
 * The same with scanout on demand and no frame consumer, drawing rows a
 * DRAM row apart: the lines wait unconverted, so a fill's rows go on
 * through runs of quiet line starts in one call
 * (rdc_port_window_rows_through).
 */
static void test_quiet_lines_lazy_match(void **state)
{
	struct tp_pair *p = *state;

	rdc_hw_set_on_demand(&p->c[0]->hw, true);
	rdc_hw_set_on_demand(&p->c[1]->hw, true);
	assert_true(p->c[0]->hw.lazy && p->c[1]->hw.lazy);
	quiet_lines(p, 0x1a2e7u, RDC_DRAM_ROW_BYTES);
}

static void test_blits_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0xb117u;
	unsigned int round, i;

	/* something to copy */
	for (i = 0; i < 60; i++) {
		TP_CMD(p, RDC_OP_SET_FG, tdp_rand(&seed));
		TP_CMD(p, RDC_OP_FILL_RECT, tp_xy(&seed),
		       RDC_WH(tdp_range(&seed, 1, 120),
			      tdp_range(&seed, 1, 90)));
	}
	for (round = 0; round < TP_ROUNDS; round++) {
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		/* same format as DST mostly (the fast path), else the screen */
		if (tdp_rand(&seed) % 4)
			tp_random_dst(p, &seed, RDC_OP_SET_SRC);
		tp_random_state(p, &seed);
		if (tdp_rand(&seed) % 4 == 0) {
			uint32_t key = tdp_rand(&seed);

			tp_cmd(p, RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 1,
			       &key);
		} else {
			TP_CMD(p, RDC_OP_SET_COLORKEY, 0);
		}
		TP_CMD(p, RDC_OP_SET_ALPHA,
		       tdp_rand(&seed) % 4 ?
			       RDC_ALPHA_OPAQUE :
			       (uint32_t)tdp_range(&seed, 0, 255));
		for (i = 0; i < TP_BATCH; i++) {
			/* near each other, so they overlap either way */
			int32_t sx = tdp_range(&seed, -20, TP_W),
				sy = tdp_range(&seed, -20, TP_H);

			TP_CMD(p, RDC_OP_BLIT, RDC_XY(sx, sy),
			       RDC_XY(sx + tdp_range(&seed, -8, 8),
				      sy + tdp_range(&seed, -8, 8)),
			       RDC_WH(tdp_range(&seed, 0, 200),
				      tdp_range(&seed, 0, 120)));
		}
		tp_check(p);
	}
	tp_assert_raced(p);
}

/*
 * HOST_BLIT: random rectangles of random host words into random surfaces,
 * with and without the colour key and global alpha, any ROP: the fast
 * stores of a plain copy must charge and write as the staged pixels do.
 */
static void test_host_blits_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0x4057u, a[2 + 1200];
	unsigned int round, i, k;

	for (round = 0; round < TP_ROUNDS; round++) {
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		tp_random_state(p, &seed);
		if (tdp_rand(&seed) % 4 == 0) {
			uint32_t key = tdp_rand(&seed);

			tp_cmd(p, RDC_OP_SET_COLORKEY, RDC_COLORKEY_ENABLE, 1,
			       &key);
		} else {
			TP_CMD(p, RDC_OP_SET_COLORKEY, 0);
		}
		TP_CMD(p, RDC_OP_SET_ALPHA,
		       tdp_rand(&seed) % 4 ?
			       RDC_ALPHA_OPAQUE :
			       (uint32_t)tdp_range(&seed, 0, 255));
		/* the DST format the words are packed for, once it is set */
		tdp_drain(p->c[0]);
		tdp_drain(p->c[1]);
		for (i = 0; i < TP_BATCH; i++) {
			uint32_t fmt = p->c[0]->dp.st.dst.format;
			uint32_t w = (uint32_t)tdp_range(&seed, 1, 120);
			uint32_t wpr = (w * tdp_bpp(fmt) + 31) / 32;
			uint32_t h = (uint32_t)tdp_range(&seed, 1, 40);

			while (wpr * h > RDC_ARRAY_SIZE(a) - 2)
				h--;
			if (!h)
				continue;
			a[0] = tp_xy(&seed);
			a[1] = RDC_WH(w, h);
			for (k = 0; k < wpr * h; k++)
				a[2 + k] = tdp_rand(&seed);
			tp_cmd(p, RDC_OP_HOST_BLIT, 0, 2 + wpr * h, a);
		}
		tp_check(p);
	}
	tp_assert_raced(p);
}

/*
 * A destination wider than RDC_DP_CHUNK pixels, clipped to itself: a
 * TEXT row across it is cut into spans a chunk long.
 */
static void tp_wide_dst(struct tp_pair *p, uint32_t *seed)
{
	struct rdc_surface s = { 1u << 20, 0, 0, 96, RDC_FMT_XRGB8888 };
	unsigned int i;

	s.width = (uint32_t)tdp_range(seed, RDC_DP_CHUNK + 8, 1800);
	s.stride = tdp_rand(seed) % 2 ? s.width * 4 : 4 * RDC_DRAM_ROW_BYTES;
	for (i = 0; i < TP_CHIPS; i++) {
		tdp_set_surface(p->c[i], RDC_OP_SET_DST, &s);
		TDP_CMD(p->c[i], RDC_OP_SET_CLIP, RDC_XY(0, 0),
			RDC_XY(s.width, s.height));
	}
}

static void test_glyphs_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0x7e47u, a[2 + 64];
	unsigned int round, i, k;
	bool wide;

	for (round = 0; round < TP_ROUNDS; round++) {
		wide = round % 3 == 2;
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		tp_random_state(p, &seed);
		if (wide)
			tp_wide_dst(p, &seed);
		for (i = 0; i < TP_BATCH; i++) {
			uint32_t fl =
				tdp_rand(&seed) % 3 ? 0 : RDC_MONO_TRANSPARENT;
			uint32_t w = (uint32_t)tdp_range(&seed, 1, 40);
			uint32_t h = (uint32_t)tdp_range(&seed, 1, 32);
			uint32_t words = (w + 31) / 32 * h;

			a[0] = tp_xy(&seed);
			if (i % 2) { /* TEXT: 1..8 characters, or a wide row */
				uint32_t n = (uint32_t)tdp_range(&seed, 1, 8);

				if (wide && i % 4 == 1)
					n = (uint32_t)tdp_range(&seed, 120,
								4 * 62);

				a[1] = n;
				for (k = 0; k < (n + 3) / 4; k++)
					a[2 + k] = tdp_rand(&seed);
				tp_cmd(p, RDC_OP_TEXT, fl, 2 + (n + 3) / 4, a);
				continue;
			}
			if (i % 4 ==
			    2) { /* a console glyph: 8 wide, 1..16 rows */
				w = 8;
				h = (uint32_t)tdp_range(&seed, 1, 16);
				words = h;
			}
			if (i % 8 == 6) {
				/* wider, cut by the left edge to its last 8 */
				int32_t cut = 8 * tdp_range(&seed, 1, 3);

				w += (uint32_t)cut;
				a[0] = RDC_XY(-cut, tdp_range(&seed, 0, TP_H));
			}
			a[1] = RDC_WH(w, h);
			for (k = 0; k < words; k++)
				a[2 + k] = tdp_rand(&seed);
			tp_cmd(p, RDC_OP_MONO, fl, 2 + words, a);
		}
		tp_check(p);
	}
	tp_assert_raced(p);
}

/*
 * Console glyphs that begin while a line's fetch holds the bus: the
 * window opens at the fetch's end (rdc_port_window_open_busy), the wait
 * a stall, against the reference's port calls, which wait in the first
 * row's charge.  Each round starts a little later around screen line
 * 16's start, so that glyphs begin before, inside and after its fetch;
 * on 4096-byte rows, row 5 is in the DRAM row the fetch ends in, and
 * some glyphs start there.  Each glyph has a second one under it whose
 * first row shares a DRAM row with its last (no row miss: it costs less
 * than the rows after it), and which the line start falls in, in some
 * rounds.  With scanout converting at the fetch and on demand.
 */
static void test_glyphs_in_fetch_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t seed = 0x91f3bu, g[4 + 16], k, lazy, under;
	int32_t late, x, y;

	for (lazy = 0; lazy < 2; lazy++) {
		rdc_hw_set_on_demand(a, lazy);
		rdc_hw_set_on_demand(b, lazy);
		TP_CMD(p, RDC_OP_SET_DST, 0, 4096, RDC_WH(512, 40),
		       RDC_FMT_XRGB8888);
		TP_CMD(p, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(512, 40));
		TP_CMD(p, RDC_OP_SET_ROP, RDC_ROP_COPY);
		tp_check(p);
		for (late = -400; late < 200; late += 5) {
			uint64_t t = rdc_port_next_line(a, 16) + late;

			rdc_hw_run_until(a, RDC_MAX(t, a->now));
			rdc_hw_run_until(b, a->now);
			x = 8 * tdp_range(&seed, 0, 63);
			y = late % 2 ? 5 : tdp_range(&seed, 0, 9);
			for (under = 0; under < 2; under++) {
				g[0] = RDC_XY(x, y + 15 * (int32_t)under);
				g[1] = RDC_WH(8, 16);
				for (k = 2; k < RDC_ARRAY_SIZE(g); k++)
					g[k] = tdp_rand(&seed);
				tp_cmd(p, RDC_OP_MONO, RDC_MONO_COLORS,
				       RDC_ARRAY_SIZE(g), g);
			}
			tp_check(p);
		}
	}
	tp_assert_raced(p);
}

/*
 * Rectangles, circles, ellipses and polygons, whose solid spans and
 * columns are queued; a mono pattern now and then keeps them on the
 * per-span path.
 */
static void test_shapes_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0x5a9e5u, a[1 + 16];
	unsigned int round, i, k, n;

	for (round = 0; round < TP_ROUNDS; round++) {
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		tp_random_state(p, &seed);
		if (tdp_rand(&seed) % 4 == 0)
			tp_cmd(p, RDC_OP_SET_PATTERN, RDC_PAT_MONO, 2,
			       (const uint32_t[]){ tdp_rand(&seed),
						   tdp_rand(&seed) });
		else
			tp_cmd(p, RDC_OP_SET_PATTERN, RDC_PAT_NONE, 0, a);
		for (i = 0; i < TP_BATCH; i++) {
			uint32_t xy = tp_xy(&seed);
			uint32_t wh = RDC_WH(tdp_range(&seed, 0, 150),
					     tdp_range(&seed, 0, 150));
			uint32_t r = (uint32_t)tdp_range(&seed, 0, 90);

			switch (i % 7) {
			case 0:
				TP_CMD(p, RDC_OP_RECT, xy, wh);
				break;
			case 1:
				TP_CMD(p, RDC_OP_FILL_RECT, xy, wh);
				break;
			case 2:
				TP_CMD(p, RDC_OP_CIRCLE, xy, r);
				break;
			case 3:
				TP_CMD(p, RDC_OP_FILL_CIRCLE, xy, r);
				break;
			case 4:
				TP_CMD(p, RDC_OP_ELLIPSE, xy, wh);
				break;
			case 5:
				TP_CMD(p, RDC_OP_FILL_ELLIPSE, xy, wh);
				break;
			default:
				n = (uint32_t)tdp_range(&seed, 3, 16);
				for (k = 0; k < n; k++)
					a[k] = tp_xy(&seed);
				tp_cmd(p, RDC_OP_FILL_POLYGON,
				       tdp_rand(&seed) % 2 ? RDC_FILL_NONZERO :
							     0,
				       n, a);
				break;
			}
		}
		tp_check(p);
	}
	tp_assert_raced(p);
}

/* Anti-aliased lines, circles and ellipses (the XRGB8888 blend). */
static void test_aa_match(void **state)
{
	struct tp_pair *p = *state;
	uint32_t seed = 0xaa11u;
	unsigned int round, i;

	/* blend over noise, so every channel value meets every coverage */
	for (i = 0; i < TDP_VRAM_SIZE; i++)
		p->c[0]->vram[i] = p->c[1]->vram[i] = (uint8_t)tdp_rand(&seed);
	for (round = 0; round < TP_ROUNDS; round++) {
		tp_random_dst(p, &seed, RDC_OP_SET_DST);
		tp_random_state(p, &seed);
		for (i = 0; i < TP_BATCH; i++) {
			uint32_t xy = tp_xy(&seed);

			switch (i % 4) {
			case 0:
			case 1:
				TP_CMD(p, RDC_OP_AA_LINE, xy, tp_xy(&seed));
				break;
			case 2:
				TP_CMD(p, RDC_OP_AA_CIRCLE, xy,
				       (uint32_t)tdp_range(&seed, 0, 80));
				break;
			default:
				TP_CMD(p, RDC_OP_AA_ELLIPSE, xy,
				       RDC_WH(tdp_range(&seed, 0, 90),
					      tdp_range(&seed, 0, 90)));
				break;
			}
			if (i % 3 == 0)
				TP_CMD(p, RDC_OP_SET_FG, tdp_rand(&seed));
		}
		tp_check(p);
	}
	tp_assert_raced(p);
}

/* The access kinds the bus-model checks draw from. */
static const unsigned int tp_kinds[] = {
	RDC_BUS_READ,
	RDC_BUS_WRITE,
	RDC_BUS_RMW,
	RDC_BUS_WRITE | RDC_BUS_HEAD_PARTIAL,
	RDC_BUS_WRITE | RDC_BUS_TAIL_PARTIAL,
};

/*
 * The two chips' bus states agree (time, stalls, the open DRAM row, the
 * scanout fetch); then both idle a little, so the next round starts in
 * another place.
 */
static void tp_bus_same_then_idle(struct rdc_hw *a, struct rdc_hw *b,
				  uint32_t *seed)
{
	assert_int_equal(a->now, b->now);
	assert_int_equal(a->perf.stall, b->perf.stall);
	assert_int_equal(a->bus.open_row, b->bus.open_row);
	assert_int_equal(a->crtc.fetch_end, b->crtc.fetch_end);
	rdc_port_idle_until(a, a->now + tdp_rand(seed) % 3000);
	rdc_port_idle_until(b, a->now);
}

/*
 * rdc_port_runs against the per-access calls: chip 0 charges random runs
 * in bulk (and the run it stops at one by one, as a caller does), chip 1
 * charges each with rdc_port_span / rdc_port_column.  Same time, same
 * stalls, same open row, and scanout fetches in between.
 */
static void test_port_runs_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	struct rdc_port_run r[32];
	uint32_t seed = 0x4a45u, round, i, n, done, stride;
	unsigned int kind;

	for (round = 0; round < 2000; round++) {
		kind = tp_kinds[tdp_rand(&seed) % RDC_ARRAY_SIZE(tp_kinds)];
		/* strides below and above a DRAM row, multiples of a beat
		 * (the closed form) and not */
		stride = tdp_rand(&seed) % 2 ?
				 (uint32_t)tdp_range(&seed, 1, 512) * 8 :
				 (uint32_t)tdp_range(&seed, 1, 5000);
		n = (uint32_t)tdp_range(&seed, 1, 32);
		for (i = 0; i < n; i++) {
			r[i].addr = tdp_rand(&seed) % (TDP_VRAM_SIZE + 64);
			r[i].len = (uint32_t)tdp_range(&seed, 0, 300);
			if (tdp_rand(&seed) % 2)
				r[i].len = (uint32_t)tdp_range(&seed, 1, 8);
			r[i].count = tdp_rand(&seed) % 2 ?
					     1 :
					     (uint32_t)tdp_range(&seed, 0, 40);
		}
		i = 0;
		while (i < n) {
			rdc_port_runs(a, r + i, n - i, stride, kind, &done);
			i += done;
			if (i == n)
				break;
			if (r[i].count == 1)
				rdc_port_span(a, r[i].addr, r[i].len, kind);
			else
				rdc_port_column(a, r[i].addr, stride,
						r[i].count, r[i].len, kind);
			i++;
		}
		for (i = 0; i < n; i++) {
			if (r[i].count == 1)
				rdc_port_span(b, r[i].addr, r[i].len, kind);
			else
				rdc_port_column(b, r[i].addr, stride,
						r[i].count, r[i].len, kind);
		}
		tp_bus_same_then_idle(a, b, &seed);
	}
	assert_true(a->perf.stall > 0);
}

/*
 * rdc_port_window against the per-access calls, as test_port_runs_match:
 * chip 0 charges random runs one at a time in a window (rdc_port_window_
 * charge) and random row blocks in bulk (rdc_port_window_rows, whose
 * closed form takes strides that are whole DRAM rows, 0 included), each
 * refused one through the port call after closing the window; chip 1
 * charges every run and row with rdc_port_span / rdc_port_column.
 */
static void test_port_window_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	struct rdc_port_window w;
	struct rdc_port_run r;
	uint32_t seed = 0x3b1du, round, i, n, k, done, stride, addr, len;
	bool rows;

	for (round = 0; round < 3000; round++) {
		rows = tdp_rand(&seed) % 2;
		switch (tdp_rand(&seed) % 4) {
		case 0:
			stride = (uint32_t)tdp_range(&seed, 0, 3) *
				 RDC_DRAM_ROW_BYTES;
			break;
		case 1:
			stride = (uint32_t)tdp_range(&seed, 1, 512) * 8;
			break;
		default:
			stride = (uint32_t)tdp_range(&seed, 1, 5000);
			break;
		}
		n = (uint32_t)tdp_range(&seed, 1, 40);
		addr = tdp_rand(&seed) % (TDP_VRAM_SIZE + 64);
		if (tdp_rand(&seed) % 4 == 0) /* rows running out of VRAM */
			addr = TDP_VRAM_SIZE -
			       (uint32_t)tdp_range(&seed, 0, 8) * stride;
		len = (uint32_t)tdp_range(&seed, 0, 300);
		if (tdp_rand(&seed) % 2)
			len = (uint32_t)tdp_range(&seed, 1, 8);
		rdc_port_window_open(a, &w);
		for (i = 0; i < n;) {
			r.addr = addr + i * stride;
			r.len = len;
			r.count = 1;
			if (rows) {
				done = rdc_port_window_rows(a, &w, r.addr, len,
							    stride, n - i);
				i += done;
				if (i == n)
					break;
				r.addr = addr + i * stride;
			} else {
				/* spans and columns */
				if (tdp_rand(&seed) % 2)
					r.count = (uint32_t)tdp_range(&seed, 0,
								      40);
				if (rdc_port_window_charge(a, &w, &r, stride,
							   RDC_BUS_WRITE)) {
					if (r.count == 1)
						rdc_port_span(b, r.addr, len,
							      RDC_BUS_WRITE);
					else
						rdc_port_column(b, r.addr,
								stride, r.count,
								len,
								RDC_BUS_WRITE);
					i++;
					continue;
				}
			}
			rdc_port_window_close(a, &w);
			if (r.count == 1)
				rdc_port_span(a, r.addr, len, RDC_BUS_WRITE);
			else
				rdc_port_column(a, r.addr, stride, r.count, len,
						RDC_BUS_WRITE);
			if (!rows) {
				if (r.count == 1)
					rdc_port_span(b, r.addr, len,
						      RDC_BUS_WRITE);
				else
					rdc_port_column(b, r.addr, stride,
							r.count, len,
							RDC_BUS_WRITE);
			}
			rdc_port_window_open(a, &w);
			i++;
		}
		rdc_port_window_close(a, &w);
		if (rows)
			for (k = 0; k < n; k++)
				rdc_port_span(b, addr + k * stride, len,
					      RDC_BUS_WRITE);
		tp_bus_same_then_idle(a, b, &seed);
	}
	assert_true(a->perf.stall > 0);
}

/*
 * A run the window refuses, taken across the line start in it: chip 0
 * charges random runs (spans and columns, every access kind) in a
 * window, a refused one by rdc_port_window_cross, a refused one-beat
 * span also by waiting out line starts with rdc_port_window_event, as
 * line_events does, and only when both refuse by the port call after
 * closing the window; chip 1 charges each with rdc_port_span /
 * rdc_port_column.  Same time, stalls, open row and fetch windows.
 */
static void test_port_window_cross_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t seed = 0x7c05u, round, i, n, stride, crossed = 0, waited = 0;
	struct rdc_port_window w;
	struct rdc_port_run r;
	unsigned int kind;
	bool ok;

	for (round = 0; round < 3000; round++) {
		stride = tdp_rand(&seed) % 2 ?
				 (uint32_t)tdp_range(&seed, 1, 600) * 8 :
				 (uint32_t)tdp_range(&seed, 1, 5000);
		/* odd rounds: a line's worth of pixels */
		n = (uint32_t)tdp_range(&seed, 1, round % 2 ? 400 : 40);
		rdc_port_window_open(a, &w);
		for (i = 0; i < n; i++) {
			kind = tp_kinds[tdp_rand(&seed) %
					RDC_ARRAY_SIZE(tp_kinds)];
			r.addr = tdp_rand(&seed) % (TDP_VRAM_SIZE + 64);
			r.len = (uint32_t)tdp_range(&seed, 1, 2000);
			if (tdp_rand(&seed) % 2)
				r.len = (uint32_t)tdp_range(&seed, 1, 8);
			else if (tdp_rand(&seed) % 8 == 0)
				/* over several DRAM rows: misses in the walk */
				r.len = (uint32_t)tdp_range(&seed, 2000, 9000);
			r.count = tdp_rand(&seed) % 2 ?
					  1 :
					  (uint32_t)tdp_range(&seed, 0, 400);
			if (round % 2 || tdp_rand(&seed) % 3 == 0) {
				/* a pixel of a line: one beat, one burst */
				r.addr &= ~7u;
				r.len = (uint32_t)tdp_range(&seed, 1, 8);
				r.count = 1;
			}
			if (r.count == 1)
				rdc_port_span(b, r.addr, r.len, kind);
			else
				rdc_port_column(b, r.addr, stride, r.count,
						r.len, kind);
			if (rdc_port_window_charge(a, &w, &r, stride, kind))
				continue;
			if (r.count == 1 && r.addr % 8 + r.len <= 8 &&
			    r.addr + r.len <= TDP_VRAM_SIZE &&
			    tdp_rand(&seed) % 2) {
				while (!(ok = rdc_port_window_charge(
						 a, &w, &r, stride, kind)) &&
				       w.t <= w.lim &&
				       rdc_port_window_event(a, &w))
					waited++;
				if (ok)
					continue;
			}
			if (rdc_port_window_cross(a, &w, &r, stride, kind)) {
				crossed++;
				continue;
			}
			rdc_port_window_close(a, &w);
			if (r.count == 1)
				rdc_port_span(a, r.addr, r.len, kind);
			else
				rdc_port_column(a, r.addr, stride, r.count,
						r.len, kind);
			rdc_port_window_open(a, &w);
		}
		rdc_port_window_close(a, &w);
		tp_bus_same_then_idle(a, b, &seed);
	}
	assert_true(crossed > 100);
	assert_true(waited > 100);
	assert_true(a->perf.stall > 0);
}

/* A bulk FIFO push is the register writes it stands for. */
static void test_fifo_push_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t w[RDC_FIFO_DEPTH + 10], i, n, took;

	/* stop the DP so the FIFO fills */
	rdc_hw_write(a, RDC_REG_CONTROL, RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(b, RDC_REG_CONTROL, RDC_CONTROL_SCANOUT_EN);
	for (i = 0; i < RDC_ARRAY_SIZE(w); i++)
		w[i] = RDC_CMD(RDC_OP_NOP, 0, 0);
	n = 100;
	took = rdc_hw_fifo_push(a, w, n);
	assert_int_equal(took, n);
	for (i = 0; i < n; i++)
		rdc_hw_write(b, RDC_REG_FIFO_DATA, w[i]);
	assert_int_equal(a->fifo_count, b->fifo_count);
	/* past full: takes what fits and raises no overflow */
	took = rdc_hw_fifo_push(a, w, RDC_ARRAY_SIZE(w));
	assert_int_equal(took, RDC_FIFO_DEPTH - n);
	assert_int_equal(a->fifo_count, RDC_FIFO_DEPTH);
	assert_int_equal(rdc_hw_read(a, RDC_REG_ERR_CODE), RDC_ERR_NONE);
	for (i = 0; i < RDC_FIFO_DEPTH - n; i++)
		rdc_hw_write(b, RDC_REG_FIFO_DATA, w[i]);
	assert_memory_equal(a->fifo, b->fifo, sizeof(a->fifo));
	assert_int_equal(a->fifo_head, b->fifo_head);
	/* both run the same words to the same cycle */
	rdc_hw_write(a, RDC_REG_CONTROL,
		     RDC_CONTROL_SCANOUT_EN | RDC_CONTROL_DP_EN);
	rdc_hw_write(b, RDC_REG_CONTROL,
		     RDC_CONTROL_SCANOUT_EN | RDC_CONTROL_DP_EN);
	tdp_drain(p->c[0]);
	tdp_drain(p->c[1]);
	assert_int_equal(a->now, b->now);
	assert_int_equal(a->perf.cmds, RDC_FIFO_DEPTH);
	assert_int_equal(a->perf.cmds, b->perf.cmds);
}

/*
 * Bulk FIFO pushes and pops across the ring's end are the word-by-word
 * ones: the same words in the same order, the same head, count, FIFO_LOW
 * interrupt and cycles charged.
 */
static void test_fifo_ring_match(void **state)
{
	struct tp_pair *p = *state;
	struct rdc_hw *a = &p->c[0]->hw, *b = &p->c[1]->hw;
	uint32_t w[RDC_FIFO_DEPTH], da[RDC_FIFO_DEPTH], db[RDC_FIFO_DEPTH];
	uint32_t i, n, took, round;

	rdc_hw_write(a, RDC_REG_CONTROL, RDC_CONTROL_SCANOUT_EN);
	rdc_hw_write(b, RDC_REG_CONTROL, RDC_CONTROL_SCANOUT_EN);
	for (round = 0; round < 5; round++) {
		n = 90 + 37 * round; /* the head moves round the ring */
		for (i = 0; i < n; i++)
			w[i] = 0x10000u * round + i;
		took = rdc_hw_fifo_push(a, w, n);
		assert_int_equal(took, n);
		for (i = 0; i < n; i++)
			rdc_hw_write(b, RDC_REG_FIFO_DATA, w[i]);
		assert_memory_equal(a->fifo, b->fifo, sizeof(a->fifo));
		assert_int_equal(a->fifo_count, b->fifo_count);
		assert_int_equal(rdc_port_cmd_pop(a, RDC_SRC_FIFO, da, n + 5),
				 n);
		for (i = 0; i < n; i++)
			assert_int_equal(rdc_port_cmd_pop(b, RDC_SRC_FIFO,
							  db + i, 1),
					 1);
		assert_memory_equal(da, w, n * sizeof(*w));
		assert_memory_equal(db, w, n * sizeof(*w));
		assert_int_equal(a->fifo_head, b->fifo_head);
		assert_int_equal(a->fifo_count, 0);
		assert_int_equal(b->fifo_count, 0);
		assert_int_equal(a->now, b->now);
		assert_int_equal(a->irq_status, b->irq_status);
		assert_true(a->irq_status & RDC_IRQ_FIFO_LOW);
	}
	assert_true(a->fifo_head != 0);
}

/* What a frame listener sees: when each frame came, and the FIFO then. */
struct tp_frames {
	struct rdc_hw *hw;
	unsigned int n;
	uint64_t at[64];
	uint32_t fifo[64];
};

static void tp_frame_seen(void *ctx, const uint32_t *xrgb, uint32_t width,
			  uint32_t height, uint64_t frame_number)
{
	struct tp_frames *f = ctx;

	(void)xrgb;
	(void)width;
	(void)height;
	(void)frame_number;
	if (f->n < RDC_ARRAY_SIZE(f->at)) {
		f->at[f->n] = f->hw->now;
		f->fifo[f->n] = f->hw->fifo_count;
	}
	f->n++;
}

static void tp_trace_none(void *ctx, uint64_t time, unsigned int event,
			  uint32_t a, uint32_t b)
{
	(void)ctx;
	(void)time;
	(void)event;
	(void)a;
	(void)b;
}

/*
 * n words into the FIFO as rdc_fifo_feed does, waiting for a varying
 * FIFO_FREE; each wait's end cycle goes into *hash.  Returns the waits.
 */
static unsigned int tp_feed(struct rdc_hw *hw, const uint32_t *words,
			    uint32_t n, uint64_t *hash)
{
	unsigned int waits = 0;
	uint32_t i = 0;

	while (i < n) {
		uint32_t free_words = rdc_hw_read(hw, RDC_REG_FIFO_FREE);
		struct rdc_hw_wait w = { 0 };

		if (free_words) {
			i += rdc_hw_fifo_push(hw, words + i,
					      RDC_MIN(n - i, free_words));
			continue;
		}
		w.term[0].test = RDC_WAIT_TEST_GE;
		w.term[0].reg = RDC_REG_FIFO_FREE;
		w.term[0].mask = ~0u;
		/* thresholds of every size, so some fall on an exact level */
		w.term[0].value = 1 + (waits * 37 + i) % RDC_FIFO_DEPTH;
		w.needs_dp = true;
		w.budget = 1u << 30;
		rdc_hw_wait_begin(hw, &w);
		assert_int_equal(rdc_hw_wait_run(hw, &w, RDC_NEVER),
				 RDC_HW_WAIT_DONE);
		*hash = *hash * 1000003u + hw->now;
		waits++;
	}
	return waits;
}

/*
 * A host feeding glyphs the way librdc's rdc_fifo_feed does: push what
 * FIFO_FREE allows, else wait for half the FIFO.  The traced chip takes
 * the register file for every read and word (the reference); the other
 * the bulk push and the wait's direct FIFO_FREE and DP_HALTED reads.
 * Both must end every wait at the same cycle, with frame listeners seeing
 * the same frames at the same cycles and FIFO levels.
 */
static void test_wait_feed_match(void **state)
{
	struct tp_pair *p = *state;
	struct tp_frames f[TP_CHIPS] = { { 0 } };
	uint32_t seed = 0xfeedu, words[4096], n = 0, k, pass;
	uint64_t ends[TP_CHIPS] = { 0 }; /* a hash of each wait's end */
	unsigned int c, waits[TP_CHIPS] = { 0 };

	rdc_hw_set_trace(&p->c[1]->hw, tp_trace_none, NULL);
	for (c = 0; c < TP_CHIPS; c++) {
		f[c].hw = &p->c[c]->hw;
		rdc_hw_set_frame_fn(&p->c[c]->hw, tp_frame_seen, &f[c]);
	}
	while (n + 23 <= RDC_ARRAY_SIZE(words)) {
		words[n++] = RDC_CMD(RDC_OP_SET_FG, 0, 1);
		words[n++] = tdp_rand(&seed);
		words[n++] = RDC_CMD(RDC_OP_SET_BG, 0, 1);
		words[n++] = tdp_rand(&seed);
		words[n++] = RDC_CMD(RDC_OP_MONO, 0, 2 + 16);
		words[n++] = tp_xy(&seed);
		words[n++] = RDC_WH(8, 16);
		for (k = 0; k < 16; k++)
			words[n++] = tdp_rand(&seed) >> 24;
	}
	/* some 2M cycles: a few frames at 70 Hz */
	for (c = 0; c < TP_CHIPS; c++)
		for (pass = 0; pass < 48; pass++)
			waits[c] += tp_feed(&p->c[c]->hw, words, n, &ends[c]);
	assert_int_equal(waits[0], waits[1]);
	assert_true(waits[0] > 8);
	assert_int_equal(ends[0], ends[1]);
	tp_check(p);
	assert_int_equal(f[0].n, f[1].n);
	assert_true(f[0].n > 0);
	k = RDC_MIN(f[0].n, RDC_ARRAY_SIZE(f[0].at));
	assert_memory_equal(f[0].at, f[1].at, k * sizeof(f[0].at[0]));
	assert_memory_equal(f[0].fifo, f[1].fifo, k * sizeof(f[0].fifo[0]));
	tp_assert_raced(p);
}

/*
 * Solid fills of every width up to a few blocks, colours with equal and
 * unequal bytes: the model writes each pixel.
 */
static void test_fill_model(void **state)
{
	struct tp_pair *p = *state;
	struct tdp *t = p->c[0];
	struct rdc_surface s = { 0, TP_W * 4, TP_W, TP_H, RDC_FMT_XRGB8888 };
	uint8_t *model = malloc(TDP_VRAM_SIZE);
	uint32_t seed = 0xf111u, w, y;
	int32_t x;

	assert_non_null(model);
	tdp_set_surface(t, RDC_OP_SET_DST, &s);
	tdp_drain(t);
	memcpy(model, t->vram, TDP_VRAM_SIZE);
	for (w = 1; w <= 300; w++) {
		uint32_t c = w % 3 ? tdp_rand(&seed) : 0x5a5a5a5au;
		int32_t x0 = tdp_range(&seed, 0, TP_W - 1);
		int32_t y0 = tdp_range(&seed, 0, TP_H - 3);

		TDP_CMD(t, RDC_OP_SET_FG, c);
		TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(x0, y0), RDC_WH(w, 2));
		for (y = 0; y < 2; y++)
			for (x = x0; x < x0 + (int32_t)w && x < TP_W; x++)
				tdp_put(model, &s, x, y0 + (int32_t)y, c);
	}
	tdp_drain(t);
	assert_memory_equal(model, t->vram, TDP_VRAM_SIZE);
	free(model);
}

/*
 * XRGB8888 scanout of a width that is not a multiple of the conversion's
 * block: every pixel is the VRAM word with its X byte cleared.
 */
static void test_scanout_xrgb_model(void **state)
{
	struct tp_pair *p = *state;
	struct tdp *t = p->c[0];
	const uint32_t w = 333, h = 100;
	uint32_t seed = 0x5ca7u, i, fw, fh;
	const uint32_t *f;
	uint64_t start;

	for (i = 0; i < w * h * 4; i++)
		t->vram[i] = (uint8_t)tdp_rand(&seed);
	rdc_hw_write(&t->hw, RDC_REG_H_TOTAL, 400);
	rdc_hw_write(&t->hw, RDC_REG_H_DISPLAY, w);
	rdc_hw_write(&t->hw, RDC_REG_H_SYNC_START, 340);
	rdc_hw_write(&t->hw, RDC_REG_H_SYNC_END, 360);
	rdc_hw_write(&t->hw, RDC_REG_V_TOTAL, 120);
	rdc_hw_write(&t->hw, RDC_REG_V_DISPLAY, h);
	rdc_hw_write(&t->hw, RDC_REG_V_SYNC_START, 105);
	rdc_hw_write(&t->hw, RDC_REG_V_SYNC_END, 110);
	rdc_hw_write(&t->hw, RDC_REG_FB_STRIDE, w * 4);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_write(&t->hw, RDC_REG_CONTROL,
		     RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	start = rdc_hw_read(&t->hw, RDC_REG_FRAME_COUNT);
	for (i = 0; i < TDP_RUN_LIMIT &&
		    rdc_hw_read(&t->hw, RDC_REG_FRAME_COUNT) < start + 2;
	     i++)
		rdc_hw_run_until(&t->hw, t->hw.now + TDP_RUN_STEP);
	f = rdc_hw_frame(&t->hw, &fw, &fh);
	assert_non_null(f);
	assert_int_equal(fw, w);
	assert_int_equal(fh, h);
	for (i = 0; i < w * h; i++) {
		const uint8_t *v = t->vram + 4 * i;

		assert_int_equal(f[i], (uint32_t)v[0] | (uint32_t)v[1] << 8 |
					       (uint32_t)v[2] << 16);
	}
}

/*
 * MONO rows of at most 8 pixels are encoded a byte to a word: the row's
 * byte in byte 0 (bit 7 leftmost), the rest zero, as for any width.
 */
static void test_batch_mono_narrow(void **state)
{
	uint8_t bits[16];
	uint32_t seed = 0x6e61u, w, r;
	const uint32_t *words;
	size_t n;

	(void)state;
	for (r = 0; r < sizeof(bits); r++)
		bits[r] = (uint8_t)tdp_rand(&seed);
	for (w = 1; w <= 8; w++) {
		rdc_batch *b = rdc_batch_new();

		assert_non_null(b);
		assert_int_equal(rdc_batch_mono(b, 3, 4, w, 16, bits, 0), 0);
		words = rdc_batch_words(b, &n);
		assert_int_equal(n, 3 + 16);
		assert_int_equal(words[0], RDC_CMD(RDC_OP_MONO, 0, 2 + 16));
		assert_int_equal(words[2], RDC_WH(w, 16));
		for (r = 0; r < 16; r++)
			assert_int_equal(words[3 + r], (uint32_t)bits[r]);
		rdc_batch_free(b);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_lines_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_lines_fetch_row, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_blits_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_host_blits_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_glyphs_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_glyphs_in_fetch_match,
						tp_setup, tp_teardown),
		cmocka_unit_test_setup_teardown(test_shapes_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_aa_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_port_runs_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_port_window_match,
						tp_setup, tp_teardown),
		cmocka_unit_test_setup_teardown(test_quiet_lines_match,
						tp_setup, tp_teardown),
		cmocka_unit_test_setup_teardown(test_quiet_lines_lazy_match,
						tp_setup, tp_teardown),
		cmocka_unit_test_setup_teardown(test_port_window_cross_match,
						tp_setup, tp_teardown),
		cmocka_unit_test_setup_teardown(test_fifo_push_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_fifo_ring_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_wait_feed_match, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_fill_model, tp_setup,
						tp_teardown),
		cmocka_unit_test_setup_teardown(test_scanout_xrgb_model,
						tp_setup, tp_teardown),
		cmocka_unit_test(test_batch_mono_narrow),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
