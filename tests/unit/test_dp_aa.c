// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Anti-aliased lines, circles and ellipses: the display processor against
 * the per-pixel references of ref_aa.c through an independent pixel and
 * blend model, in every format, ROP and clip; circles' and ellipses'
 * coverage against the exact value of the definition; the intensity and
 * symmetry properties; the bus cost of AA runs; bad arguments.
 */
#include "test_dp_common.h"
#include "ref_aa.h"

#define AA_W 200
#define AA_H 150

/* ---- model --------------------------------------------------------- */

/* Channel fields (shift, width) of the RGB formats, from rdc_regs.h. */
static unsigned int aa_fields(uint32_t fmt, uint32_t f[4][2])
{
	static const uint32_t f565[3][2] = { { 11, 5 }, { 5, 6 }, { 0, 5 } };
	static const uint32_t f888[4][2] = {
		{ 24, 8 }, { 16, 8 }, { 8, 8 }, { 0, 8 }
	};

	if (fmt == RDC_FMT_RGB565) {
		memcpy(f, f565, sizeof(f565));
		return 3;
	}
	memcpy(f, f888, sizeof(f888));
	if (fmt == RDC_FMT_RGB888) {
		memmove(f, f[1], 3 * sizeof(f[0]));
		return 3;
	}
	return 4;
}

/* docs/commands.md: each channel (s a + d (255 - a) + 127) / 255. */
static uint32_t aa_model_blend(uint32_t fmt, uint32_t s, uint32_t d, uint32_t a)
{
	uint32_t f[4][2], r = 0, i, n = aa_fields(fmt, f);

	for (i = 0; i < n; i++) {
		uint32_t m = (1u << f[i][1]) - 1;
		uint32_t cs = (s >> f[i][0]) & m, cd = (d >> f[i][0]) & m;
		uint32_t num = cs * a + cd * (255 - a);

		/* round half up, by comparison rather than by the formula */
		uint32_t q = num / 255;

		if ((num % 255) * 2 >= 255)
			q++;
		r |= q << f[i][0];
	}
	return r;
}

struct aa_model {
	uint8_t *vram;
	struct rdc_surface s;
	struct rdc_rect clip;
	uint32_t fg, rop, ramp;
	uint32_t plots;
	uint32_t dup;
	uint8_t *seen;
};

static void aa_model_plot(void *ctx, int32_t x, int32_t y, uint32_t cov)
{
	struct aa_model *m = ctx;
	uint32_t mask = tdp_mask(m->s.format), d, v;

	if (x < m->clip.x0 || x >= m->clip.x1 || y < m->clip.y0 ||
	    y >= m->clip.y1 || x < 0 || y < 0 || x >= (int32_t)m->s.width ||
	    y >= (int32_t)m->s.height)
		return;
	if (m->seen[(size_t)y * m->s.width + x]++)
		m->dup++;

	d = tdp_get(m->vram, &m->s, x, y);
	if (m->s.format <= RDC_FMT_I8) {
		/* ramp: fg at full coverage, fg + ramp - 1 at the faintest */
		uint32_t num = (255 - cov) * (m->ramp - 1);
		uint32_t k = num / 255 + ((num % 255) * 2 >= 255);

		v = (m->fg + k) & mask;
	} else {
		v = aa_model_blend(m->s.format, m->fg & mask, d, cov);
	}
	tdp_put(m->vram, &m->s, x, y, tdp_rop(m->rop, v, d));
	m->plots++;
}

/* ---- coverage of circles and ellipses ---------------------------------- */

/* docs/commands.md: AA_ELLIPSE's coverage within 1 of the exact value */
#define AA_COV_TOL 1
/* where the DP's own coverage is captured: XRGB8888, well past the scenes */
#define AA_CAP_BASE (2u << 20)

/*
 * Draw AA_ELLIPSE (rx, ry >= 1) at (cx, cy) on a zeroed XRGB8888 surface
 * w x h at AA_CAP_BASE, FG white, COPY, no clip: each channel is then the
 * coverage itself, (255 c + 0 (255 - c) + 127) / 255 = c.  Returns the
 * largest difference from the exact coverage over the surface; cov (w x h)
 * gets the DP's coverages.  The caller restores the DP state it needs.
 */
static uint32_t aa_capture(struct tdp *t, int32_t cx, int32_t cy, uint32_t rx,
			   uint32_t ry, uint32_t w, uint32_t h, uint8_t *cov)
{
	struct rdc_surface s = { AA_CAP_BASE, 4 * w, w, h, RDC_FMT_XRGB8888 };
	uint32_t worst = 0;
	int32_t x, y;

	memset(t->vram + s.base, 0, (size_t)s.stride * h);
	tdp_set_surface(t, RDC_OP_SET_DST, &s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
		RDC_XY(RDC_COORD_MAX, RDC_COORD_MAX));
	TDP_CMD(t, RDC_OP_SET_FG, 0xffffffffu);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(cx, cy), RDC_WH(rx, ry));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	for (y = 0; y < (int32_t)h; y++)
		for (x = 0; x < (int32_t)w; x++) {
			uint32_t v = tdp_get(t->vram, &s, x, y), c = v & 0xff;
			int64_t dx = x - cx, dy = y - cy;
			uint32_t want = rdc_ref_aa_ellipse_cov(
				rx, ry, (uint32_t)(dx < 0 ? -dx : dx),
				(uint32_t)(dy < 0 ? -dy : dy));
			uint32_t diff = c > want ? c - want : want - c;

			/* the four channels agree */
			assert_int_equal(v, c * 0x01010101u);
			worst = RDC_MAX(worst, diff);
			if (cov)
				cov[(size_t)y * w + x] = (uint8_t)c;
		}
	return worst;
}

/*
 * Every rx, ry in 1..40, and flat and tall ones up to 400 x 6: the DP's
 * coverage against the exact one of the definition, pixel by pixel over
 * the whole bounding box (and one pixel round it).
 */
static void test_aa_ellipse_exact(void **state)
{
	static const uint32_t flat[] = { 8,   9,   31,	32,  33,  72,
					 100, 128, 200, 288, 314, 400 };
	struct tdp *t = *state;
	uint32_t rx, ry, i, worst = 0;

	for (rx = 1; rx <= 40; rx++)
		for (ry = 1; ry <= 40; ry++)
			worst = RDC_MAX(worst, aa_capture(t, 42, 42, rx, ry, 85,
							  85, NULL));
	for (i = 0; i < RDC_ARRAY_SIZE(flat); i++)
		for (ry = 1; ry <= 6; ry++) {
			rx = flat[i];
			worst = RDC_MAX(worst, aa_capture(t, 402, 8, rx, ry,
							  805, 17, NULL));
			worst = RDC_MAX(worst, aa_capture(t, 8, 402, ry, rx, 17,
							  805, NULL));
		}
	print_message("AA ellipse coverage: largest difference from exact %u\n",
		      worst);
	assert_true(worst <= AA_COV_TOL);
}

/* ---- random scenes vs reference -------------------------------------- */

enum { P_LINE, P_CIRCLE, P_ELLIPSE };

static void aa_scene(struct tdp *t, uint32_t *seed, uint32_t *hash)
{
	struct aa_model m = { 0 };
	uint32_t fmt = tdp_rand(seed) % RDC_FMT_COUNT, i, kind;
	int32_t x0 = tdp_range(seed, -60, AA_W + 60);
	int32_t y0 = tdp_range(seed, -60, AA_H + 60);
	int32_t x1 = tdp_range(seed, -60, AA_W + 60);
	int32_t y1 = tdp_range(seed, -60, AA_H + 60);
	uint32_t rx = (uint32_t)tdp_range(seed, 0, 130);
	uint32_t ry = (uint32_t)tdp_range(seed, 0, 130);
	uint8_t *cov = NULL;
	size_t bytes;

	/* now and then a very flat ellipse, long past the surface */
	if (tdp_rand(seed) % 6 == 0) {
		rx = (uint32_t)tdp_range(seed, 1, 3000);
		ry = (uint32_t)tdp_range(seed, 0, 4);
		if (tdp_rand(seed) & 1) {
			uint32_t sw = rx;

			rx = ry;
			ry = sw;
		}
	}

	m.s.base = 4096;
	m.s.width = AA_W;
	m.s.height = AA_H;
	m.s.format = fmt;
	m.s.stride = (AA_W * tdp_bpp(fmt) + 7) / 8 + 4 * (tdp_rand(seed) % 3);
	bytes = (size_t)m.s.stride * AA_H;
	m.fg = tdp_rand(seed);
	m.rop = tdp_rand(seed) % 3 ? RDC_ROP_COPY : tdp_rand(seed) % 16;
	m.ramp = (uint32_t)tdp_range(seed, 2, 20);
	m.clip.x0 = RDC_COORD_MIN;
	m.clip.y0 = RDC_COORD_MIN;
	m.clip.x1 = RDC_COORD_MAX + 1;
	m.clip.y1 = RDC_COORD_MAX + 1;
	if (tdp_rand(seed) % 3 == 0) {
		m.clip.x0 = tdp_range(seed, -10, AA_W / 2);
		m.clip.y0 = tdp_range(seed, -10, AA_H / 2);
		m.clip.x1 = tdp_range(seed, m.clip.x0, AA_W + 10);
		m.clip.y1 = tdp_range(seed, m.clip.y0, AA_H + 10);
	}
	kind = tdp_rand(seed) % 3;
	if (kind == P_CIRCLE)
		ry = rx %= 131;
	/*
	 * Circles and ellipses: the coverage is checked against the exact one
	 * first; the blend, ROP, format and clip are then checked with the
	 * DP's own coverage, which may differ from exact by AA_COV_TOL.
	 */
	if (kind != P_LINE && rx && ry) {
		cov = malloc((size_t)AA_W * AA_H);
		assert_non_null(cov);
		assert_true(aa_capture(t, x0, y0, rx, ry, AA_W, AA_H, cov) <=
			    AA_COV_TOL);
	}
	for (i = 0; i < bytes; i++)
		t->vram[m.s.base + i] = (uint8_t)tdp_rand(seed);
	m.vram = malloc(TDP_VRAM_SIZE);
	m.seen = calloc((size_t)AA_W * AA_H, 1);
	assert_non_null(m.vram);
	assert_non_null(m.seen);
	memcpy(m.vram, t->vram, TDP_VRAM_SIZE);

	tdp_set_surface(t, RDC_OP_SET_DST, &m.s);
	TDP_CMD(t, RDC_OP_SET_FG, m.fg);
	TDP_CMD(t, RDC_OP_SET_ROP, m.rop);
	TDP_CMD(t, RDC_OP_SET_AA_RAMP, m.ramp);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(m.clip.x0, m.clip.y0),
		RDC_XY(RDC_MIN(m.clip.x1, RDC_COORD_MAX),
		       RDC_MIN(m.clip.y1, RDC_COORD_MAX)));
	m.clip.x1 = RDC_MIN(m.clip.x1, RDC_COORD_MAX);
	m.clip.y1 = RDC_MIN(m.clip.y1, RDC_COORD_MAX);

	if (kind == P_LINE) {
		TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		rdc_ref_aa_line(x0, y0, x1, y1, aa_model_plot, &m);
	} else if (cov) {
		TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(x0, y0), RDC_WH(rx, ry));
		for (i = 0; i < (uint32_t)AA_W * AA_H; i++)
			if (cov[i])
				aa_model_plot(&m, (int32_t)(i % AA_W),
					      (int32_t)(i / AA_W), cov[i]);
	} else if (kind == P_CIRCLE) {
		/* (the reference visits the whole bounding box) */
		TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(x0, y0), rx);
		rdc_ref_aa_ellipse(x0, y0, rx, rx, aa_model_plot, &m);
	} else {
		TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(x0, y0), RDC_WH(rx, ry));
		rdc_ref_aa_ellipse(x0, y0, rx, ry, aa_model_plot, &m);
	}
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_equal(m.dup, 0);
	if (memcmp(m.vram, t->vram, TDP_VRAM_SIZE)) {
		for (i = 0; i < TDP_VRAM_SIZE; i++)
			if (m.vram[i] != t->vram[i])
				break;
		fail_msg("fmt %u kind %u (%d,%d)-(%d,%d) r %u,%u rop %u: "
			 "VRAM differs at %u (%02x, model %02x)",
			 fmt, kind, x0, y0, x1, y1, rx, ry, m.rop, i,
			 t->vram[i], m.vram[i]);
	}
	*hash = tdp_fnv(*hash, &m.plots, sizeof(m.plots));
	free(cov);
	free(m.seen);
	free(m.vram);
}

static void test_aa_random_vs_ref(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0x5eed0a0au, hash = 2166136261u, i;

	for (i = 0; i < 300; i++)
		aa_scene(t, &seed, &hash);
	/* the scenes covered pixels at all */
	assert_int_not_equal(hash, 2166136261u);
}

/* ---- properties ------------------------------------------------------- */

/* Sum of the blue channel over the default XRGB8888 screen. */
static uint64_t aa_blue_sum(struct tdp *t)
{
	uint64_t sum = 0;
	uint32_t i;

	for (i = 0; i < 640 * 480; i++)
		sum += t->vram[4 * i];
	return sum;
}

static void aa_clear(struct tdp *t)
{
	memset(t->vram, 0, 640 * 480 * 4);
}

/* Wu: every step along the major axis spreads exactly full intensity, so
 * a line sums to its major-axis length in pixels (255 each), which is its
 * Euclidean length up to the factor sqrt(2) of a diagonal. */
static void test_aa_line_intensity(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 77, i;

	TDP_CMD(t, RDC_OP_SET_FG, 0x00ffffffu);
	for (i = 0; i < 40; i++) {
		int32_t x0 = tdp_range(&seed, 20, 620);
		int32_t y0 = tdp_range(&seed, 20, 460);
		int32_t x1 = tdp_range(&seed, 20, 620);
		int32_t y1 = tdp_range(&seed, 20, 460);
		int64_t dx = x1 - x0, dy = y1 - y0;
		int64_t n = RDC_MAX(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
		uint64_t sum, len2 = (uint64_t)(dx * dx + dy * dy);

		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		tdp_drain(t);
		sum = aa_blue_sum(t);
		assert_int_equal(sum, 255 * (uint64_t)(n + 1));
		/* len / sqrt(2) <= sum / 255 <= len + 1 */
		assert_true(2 * (sum / 255) * (sum / 255) >= len2);
		assert_true((sum / 255 - 1) * (sum / 255 - 1) <= len2);
	}
}

/* A circle's coverage is a tent of width 2 across the curve, so it sums
 * to about the circumference. */
static void test_aa_circle_intensity(void **state)
{
	struct tdp *t = *state;
	static const uint32_t radii[] = { 8, 30, 100, 200 };
	uint32_t i;

	TDP_CMD(t, RDC_OP_SET_FG, 0x00ffffffu);
	for (i = 0; i < RDC_ARRAY_SIZE(radii); i++) {
		/* 2 pi r in 1/10000 pixel, against sum / 255 within 3% */
		uint64_t want = 62832ull * radii[i], got;

		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(320, 240), radii[i]);
		tdp_drain(t);
		got = aa_blue_sum(t) * 10000 / 255;
		assert_true(got * 100 >= want * 97);
		assert_true(got * 100 <= want * 103);
	}
}

static void test_aa_symmetry(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 4242, i;
	uint8_t *a = malloc(640 * 480 * 4);

	assert_non_null(a);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00c08040u);
	for (i = 0; i < 20; i++) {
		int32_t x0 = tdp_range(&seed, -30, 670);
		int32_t y0 = tdp_range(&seed, -30, 510);
		int32_t x1 = tdp_range(&seed, -30, 670);
		int32_t y1 = tdp_range(&seed, -30, 510);
		uint32_t rx = (uint32_t)tdp_range(&seed, 1, 150);
		uint32_t ry = (uint32_t)tdp_range(&seed, 1, 150);
		int32_t dx, dy;
		struct rdc_surface s = { 0, 2560, 640, 480, RDC_FMT_XRGB8888 };

		/* a line is the same pixels both ways round */
		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		tdp_drain(t);
		memcpy(a, t->vram, 640 * 480 * 4);
		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(x1, y1), RDC_XY(x0, y0));
		tdp_drain(t);
		assert_memory_equal(a, t->vram, 640 * 480 * 4);

		/* an ellipse is mirror symmetric about both axes, a circle
		 * about the diagonal too */
		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(320, 240),
			RDC_WH(rx % 200, ry % 200));
		tdp_drain(t);
		for (dy = 0; dy <= (int32_t)ry + 1 && dy < 240; dy++)
			for (dx = 0; dx <= (int32_t)rx + 1 && dx < 320; dx++) {
				uint32_t v = tdp_get(t->vram, &s, 320 + dx,
						     240 + dy);

				assert_int_equal(v,
						 tdp_get(t->vram, &s, 320 - dx,
							 240 + dy));
				assert_int_equal(v,
						 tdp_get(t->vram, &s, 320 + dx,
							 240 - dy));
			}
		aa_clear(t);
		TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(320, 240), rx);
		tdp_drain(t);
		for (dy = 0; dy <= (int32_t)rx + 1 && dy < 240; dy++)
			for (dx = 0; dx <= (int32_t)rx + 1 && dx < 240; dx++)
				assert_int_equal(tdp_get(t->vram, &s, 320 + dx,
							 240 + dy),
						 tdp_get(t->vram, &s, 320 + dy,
							 240 + dx));
	}
	free(a);
}

/* Both ends of a Wu line are full FG; so is a zero-radius circle. */
static void test_aa_ends(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = { 0, 2560, 640, 480, RDC_FMT_XRGB8888 };

	aa_clear(t);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00123456u);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(10, 10), RDC_XY(107, 43));
	TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(300, 300), 0);
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(400, 300), RDC_WH(0, 5));
	tdp_drain(t);
	assert_int_equal(tdp_get(t->vram, &s, 10, 10), 0x123456);
	assert_int_equal(tdp_get(t->vram, &s, 107, 43), 0x123456);
	assert_int_equal(tdp_get(t->vram, &s, 300, 300), 0x123456);
	assert_int_equal(tdp_get(t->vram, &s, 301, 300), 0);
	/* a zero-width ellipse is the vertical line through its centre */
	assert_int_equal(tdp_get(t->vram, &s, 400, 295), 0x123456);
	assert_int_equal(tdp_get(t->vram, &s, 400, 305), 0x123456);
	assert_int_equal(tdp_get(t->vram, &s, 401, 300), 0);
	assert_int_equal(tdp_get(t->vram, &s, 400, 306), 0);
}

/* A translation transform moves AA primitives by exactly its offset. */
static void test_aa_translate(void **state)
{
	struct tdp *t = *state;
	uint8_t *a = malloc(640 * 480 * 4);

	assert_non_null(a);
	aa_clear(t);
	TDP_CMD(t, RDC_OP_SET_FG, 0x00ffa040u);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(30, 40), RDC_XY(200, 97));
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(300, 200), RDC_WH(60, 25));
	tdp_drain(t);
	memcpy(a, t->vram, 640 * 480 * 4);
	aa_clear(t);
	TDP_CMD(t, RDC_OP_SET_TRANSFORM, 1 << 16, 0, 17 << 16, 0, 1 << 16,
		(uint32_t)(-9 * 65536), 0, 0, 1 << 16);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(13, 49), RDC_XY(183, 106));
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(283, 209), RDC_WH(60, 25));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_memory_equal(a, t->vram, 640 * 480 * 4);
	free(a);
}

/* ---- cycle counts ------------------------------------------------------ */

static uint32_t last_cycles(struct tdp *t)
{
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

/*
 * Horizontal: one RMW span (the row below has no coverage: no access).
 * Vertical: one column of single-burst RMW accesses.  Shallow (0,0)-(7,1):
 * steps 0..6 sit on row 0 (full at x 0, fading to x 6) with their
 * complement on row 1 at x 1..6, then step 7 alone on row 1.
 */
static void test_aa_cycles(void **state)
{
	struct tdp *t = *state;
	uint32_t open, y;
	uint64_t want;

	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 10 * 4 + 7 * 2560, 31 * 4, TDP_BUS_RMW, 0,
			     0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(10, 7), RDC_XY(40, 7));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);

	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 10; y <= 20; y++)
		want += tdp_bus_edges(&open, 5 * 4 + (uint64_t)y * 2560, 4,
				      TDP_BUS_RMW, 0, 0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(5, 20), RDC_XY(5, 10));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);

	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 0, 7 * 4, TDP_BUS_RMW, 0, 0) +
	       tdp_bus_edges(&open, 2560 + 4, 6 * 4, TDP_BUS_RMW, 0, 0) +
	       tdp_bus_edges(&open, 2560 + 7 * 4, 4, TDP_BUS_RMW, 0, 0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(7, 1), RDC_XY(0, 0));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
	assert_int_equal(rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_OPCODE),
			 RDC_OP_AA_LINE);
}

/* Indexed ramps need not read VRAM: a fully covered run is a plain write,
 * partial at its sub-byte edges. */
static void test_aa_cycles_indexed(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s8 = { 0, 640, 640, 480, RDC_FMT_I8 };
	struct rdc_surface s4 = { 0, 320, 640, 480, RDC_FMT_I4 };
	uint32_t open;
	uint64_t want;

	tdp_set_surface(t, RDC_OP_SET_DST, &s8);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 3 + 9 * 640, 50, TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(3, 9), RDC_XY(52, 9));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);

	tdp_set_surface(t, RDC_OP_SET_DST, &s4);
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE +
	       tdp_bus_edges(&open, 1 + 9 * 320, 25, TDP_BUS_WRITE, 1, 0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(3, 9), RDC_XY(52, 9));
	tdp_drain(t);
	assert_int_equal(last_cycles(t), want);
}

/* ---- bad arguments ----------------------------------------------------- */

static void aa_expect(struct tdp *t, uint32_t err, uint32_t h0)
{
	tdp_drain(t);
	assert_int_equal(tdp_err(t), err);
	tdp_clear_err(t);
	assert_int_equal(tdp_fnv(2166136261u, t->vram, 640 * 480 * 4), h0);
}

static void test_aa_bad_args(void **state)
{
	struct tdp *t = *state;
	const uint32_t one[1] = { RDC_XY(5, 5) };
	const uint32_t three[3] = { RDC_XY(5, 5), RDC_XY(9, 9), 0 };
	uint32_t h0;

	aa_clear(t);
	h0 = tdp_fnv(2166136261u, t->vram, 640 * 480 * 4);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(RDC_COORD_MAX + 1, 0),
		RDC_XY(10, 10));
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(0, 0), RDC_XY(10, -32768));
	aa_expect(t, RDC_ERR_RANGE, h0);
	tdp_cmd(t, RDC_OP_AA_LINE, 0, 1, one);
	aa_expect(t, RDC_ERR_LENGTH, h0);
	tdp_cmd(t, RDC_OP_AA_CIRCLE, 0, 3, three);
	aa_expect(t, RDC_ERR_LENGTH, h0);
	TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(100, 100), RDC_SIZE_MAX + 1);
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(100, 100), 0xffffffffu);
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(100, 100),
		RDC_WH(3, RDC_SIZE_MAX + 1));
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(-20000, 100), RDC_WH(3, 3));
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_SET_AA_RAMP, 1);
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_SET_AA_RAMP, RDC_AA_RAMP_MAX + 1);
	aa_expect(t, RDC_ERR_RANGE, h0);
	tdp_cmd(t, RDC_OP_SET_AA_RAMP, 0, 0, NULL);
	aa_expect(t, RDC_ERR_LENGTH, h0);
	/* a translation that pushes a vertex out of range */
	TDP_CMD(t, RDC_OP_SET_TRANSFORM, 1 << 16, 0, 16000u << 16, 0, 1 << 16,
		0, 0, 0, 1 << 16);
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(1000, 0), RDC_XY(0, 0));
	aa_expect(t, RDC_ERR_RANGE, h0);
	TDP_CMD(t, RDC_OP_SET_TRANSFORM);
	aa_expect(t, RDC_ERR_NONE, h0);

	/* extreme but legal: huge radii and far lines finish, clipped */
	TDP_CMD(t, RDC_OP_SET_FG, 0x00ffffffu);
	TDP_CMD(t, RDC_OP_AA_CIRCLE, RDC_XY(RDC_COORD_MIN, RDC_COORD_MAX),
		RDC_SIZE_MAX);
	TDP_CMD(t, RDC_OP_AA_ELLIPSE, RDC_XY(320, 240),
		RDC_WH(RDC_SIZE_MAX, 1));
	TDP_CMD(t, RDC_OP_AA_LINE, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
		RDC_XY(RDC_COORD_MAX, RDC_COORD_MAX));
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
	assert_int_not_equal(tdp_fnv(2166136261u, t->vram, 640 * 480 * 4), h0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_aa_ellipse_exact),
		TDP_TEST(test_aa_random_vs_ref),
		TDP_TEST(test_aa_line_intensity),
		TDP_TEST(test_aa_circle_intensity),
		TDP_TEST(test_aa_symmetry),
		TDP_TEST(test_aa_ends),
		TDP_TEST(test_aa_translate),
		TDP_TEST(test_aa_cycles),
		TDP_TEST(test_aa_cycles_indexed),
		TDP_TEST(test_aa_bad_args),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
