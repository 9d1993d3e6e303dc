// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * CIRCLE, FILL_CIRCLE, ELLIPSE, FILL_ELLIPSE and ARC against the
 * inequalities of docs/commands.md, pixel by pixel (ref.c, ref_lines.c):
 * every radius pair in 0..40, flat and tall ellipses up to 400 x 6, shapes
 * cut by the surface's edges and by clip rectangles, arcs at axis,
 * wrapping and random angles.  Any pixel a stepper leaves out or adds is
 * reported with its offset from the centre.
 */
#include "test_dp_common.h"
#include "ref.h"
#include "ref_lines.h"

/* an I8 surface in the middle of VRAM, padded so stray writes show */
#define CS_W	840
#define CS_H	840
#define CS_PAD	16
#define CS_BASE 65536u

static const struct rdc_surface cs = {
	.base = CS_BASE,
	.stride = CS_W + CS_PAD,
	.width = CS_W,
	.height = CS_H,
	.format = RDC_FMT_I8,
};

/* long radii of the flat ellipses; each with ry = 1..6, and transposed */
static const uint32_t flat_rx[] = { 8,	 9,   31,  32,	33,  71, 72,
				    100, 128, 200, 288, 314, 400 };

enum shape { S_CIRCLE, S_FCIRCLE, S_ELLIPSE, S_FELLIPSE, S_ARC };

struct conic {
	enum shape shape;
	int32_t cx, cy;
	uint32_t rx, ry;	   /* a circle's radius is rx */
	uint32_t start, end, mode; /* ARC */
};

static bool conic_has(const struct conic *c, int64_t x, int64_t y)
{
	switch (c->shape) {
	case S_CIRCLE:
		return rdc_ref_circle_has(c->rx, x, y);
	case S_FCIRCLE:
		return rdc_ref_circle_fill_has(c->rx, x, y);
	case S_ELLIPSE:
		return rdc_ref_ellipse_has(c->rx, c->ry, x, y);
	case S_FELLIPSE:
		return rdc_ref_ellipse_fill_has(c->rx, c->ry, x, y);
	default:
		return false;
	}
}

static uint8_t arc_map[CS_W * CS_H];

static void arc_plot(void *ctx, int32_t x, int32_t y)
{
	(void)ctx;
	if (x >= 0 && x < CS_W && y >= 0 && y < CS_H)
		arc_map[y * CS_W + x] = 1;
}

static void conic_draw(struct tdp *t, const struct conic *c)
{
	uint32_t xy = RDC_XY(c->cx, c->cy);

	switch (c->shape) {
	case S_CIRCLE:
		TDP_CMD(t, RDC_OP_CIRCLE, xy, c->rx);
		break;
	case S_FCIRCLE:
		TDP_CMD(t, RDC_OP_FILL_CIRCLE, xy, c->rx);
		break;
	case S_ELLIPSE:
		TDP_CMD(t, RDC_OP_ELLIPSE, xy, RDC_WH(c->rx, c->ry));
		break;
	case S_FELLIPSE:
		TDP_CMD(t, RDC_OP_FILL_ELLIPSE, xy, RDC_WH(c->rx, c->ry));
		break;
	case S_ARC:
		tdp_cmd(t, RDC_OP_ARC, c->mode, 3,
			(uint32_t[]){ xy, RDC_WH(c->rx, c->ry),
				      c->start | c->end << 16 });
		break;
	}
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

/*
 * Draw c with FG 1 on the zeroed surface inside clip (x0, y0)-(x1, y1)
 * (exclusive), then compare the box (bx0, by0)-(bx1, by1) of the surface
 * and every padding byte; clear what was drawn.  Returns the pixels drawn.
 */
static uint32_t conic_check(struct tdp *t, const struct conic *c,
			    struct rdc_rect clip)
{
	int32_t bx0 = RDC_MAX(c->cx - (int32_t)c->rx - 2, 0);
	int32_t bx1 = RDC_MIN(c->cx + (int32_t)c->rx + 3, CS_W);
	int32_t by0 = RDC_MAX(
		c->cy - (int32_t)(c->shape >= S_ELLIPSE ? c->ry : c->rx) - 2,
		0);
	int32_t by1 = RDC_MIN(
		c->cy + (int32_t)(c->shape >= S_ELLIPSE ? c->ry : c->rx) + 3,
		CS_H);
	uint32_t n = 0;
	int32_t x, y;

	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(clip.x0, clip.y0),
		RDC_XY(clip.x1, clip.y1));
	conic_draw(t, c);
	if (c->shape == S_ARC) {
		memset(arc_map, 0, sizeof(arc_map));
		rdc_ref_arc(c->cx, c->cy, c->rx, c->ry, c->start, c->end,
			    c->mode, arc_plot, NULL);
	}
	for (y = by0; y < by1; y++) {
		uint8_t *row = t->vram + cs.base + (size_t)y * cs.stride;

		for (x = bx0; x < bx1; x++) {
			bool in = x >= clip.x0 && x < clip.x1 && y >= clip.y0 &&
				  y < clip.y1;
			bool want = in &&
				    (c->shape == S_ARC ? arc_map[y * CS_W + x] :
							 conic_has(c, x - c->cx,
								   y - c->cy));

			if ((row[x] != 0) != want)
				fail_msg("shape %d r %u,%u at %d,%d angles "
					 "%u..%u mode %u: offset %d,%d %s",
					 c->shape, c->rx, c->ry, c->cx, c->cy,
					 c->start, c->end, c->mode, x - c->cx,
					 y - c->cy, want ? "missing" : "extra");
			n += row[x] != 0;
			row[x] = 0;
		}
	}
	for (y = 0; y < CS_H; y++) {
		const uint8_t *pad =
			t->vram + cs.base + (size_t)y * cs.stride + CS_W;

		for (x = 0; x < CS_PAD; x++)
			if (pad[x])
				fail_msg("shape %d r %u,%u: padding of row %d "
					 "written",
					 c->shape, c->rx, c->ry, y);
	}
	return n;
}

static const struct rdc_rect no_clip = { RDC_COORD_MIN, RDC_COORD_MIN,
					 RDC_COORD_MAX, RDC_COORD_MAX };

static int conic_setup(void **state)
{
	struct tdp *t;

	tdp_setup(state);
	t = *state;
	memset(t->vram, 0, TDP_VRAM_SIZE);
	tdp_set_surface(t, RDC_OP_SET_DST, &cs);
	TDP_CMD(t, RDC_OP_SET_FG, 1);
	return 0;
}

#define CONIC_TEST(fn) \
	cmocka_unit_test_setup_teardown(fn, conic_setup, tdp_teardown)

/* Every rx, ry in 0..40, outline and fill. */
static void test_ellipse_sweep(void **state)
{
	struct tdp *t = *state;
	struct conic c = { .cx = 100, .cy = 100 };

	for (c.rx = 0; c.rx <= 40; c.rx++)
		for (c.ry = 0; c.ry <= 40; c.ry++)
			for (c.shape = S_ELLIPSE; c.shape <= S_FELLIPSE;
			     c.shape++)
				conic_check(t, &c, no_clip);
}

/*
 * Flat ellipses (rx >= 8 ry^2 among them, where a one-region stepper
 * reaches row 0 early) and their tall transposes: the full 2 rx + 1 width.
 */
static void test_ellipse_flat(void **state)
{
	struct tdp *t = *state;
	struct conic c;
	uint32_t i, ry, k;

	for (i = 0; i < RDC_ARRAY_SIZE(flat_rx); i++)
		for (ry = 1; ry <= 6; ry++)
			for (k = 0; k < 4; k++) {
				bool tall = k & 1;

				c = (struct conic){
					.shape = k & 2 ? S_FELLIPSE : S_ELLIPSE,
					.cx = tall ? 20 : 410,
					.cy = tall ? 410 : 20,
					.rx = tall ? ry : flat_rx[i],
					.ry = tall ? flat_rx[i] : ry,
				};
				conic_check(t, &c, no_clip);
				/* the extreme pixels are drawn */
				TDP_CMD(t, RDC_OP_ELLIPSE, RDC_XY(c.cx, c.cy),
					RDC_WH(c.rx, c.ry));
				tdp_drain(t);
				assert_int_equal(tdp_get(t->vram, &cs,
							 c.cx + (int32_t)c.rx,
							 c.cy),
						 1);
				assert_int_equal(tdp_get(t->vram, &cs,
							 c.cx - (int32_t)c.rx,
							 c.cy),
						 1);
				assert_int_equal(tdp_get(t->vram, &cs, c.cx,
							 c.cy + (int32_t)c.ry),
						 1);
				memset(t->vram + cs.base, 0,
				       (size_t)cs.stride * CS_H);
			}
}

/* Circles: 0..40 and a few large ones; ELLIPSE (r, r) is CIRCLE (r). */
static void test_circle_sweep(void **state)
{
	static const uint32_t big[] = { 63, 100, 255, 400 };
	struct tdp *t = *state;
	struct conic c = { .cx = 410, .cy = 410 };
	uint32_t i, n;

	for (c.rx = 0; c.rx <= 40 + RDC_ARRAY_SIZE(big); c.rx++) {
		if (c.rx > 40)
			c.rx = big[c.rx - 41];
		c.ry = c.rx;
		c.shape = S_CIRCLE;
		n = conic_check(t, &c, no_clip);
		c.shape = S_ELLIPSE;
		assert_int_equal(conic_check(t, &c, no_clip), n);
		if (c.rx <= 100) {
			c.shape = S_FCIRCLE;
			n = conic_check(t, &c, no_clip);
			c.shape = S_FELLIPSE;
			assert_int_equal(conic_check(t, &c, no_clip), n);
		}
		for (i = 0; i < RDC_ARRAY_SIZE(big); i++)
			if (c.rx == big[i])
				c.rx = 41 + i;
	}
}

/*
 * Shapes hanging over the surface's edges (the DP clips to the surface)
 * and cut by clip rectangles: exactly the reference's pixels inside.
 */
static void test_conic_clipped(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xc11c, k;

	for (k = 0; k < 400; k++) {
		struct conic c = {
			.shape = (enum shape)(k % 5),
			.rx = (uint32_t)tdp_range(&seed, 0, 60),
			.ry = (uint32_t)tdp_range(&seed, 0, 60),
			.start = tdp_rand(&seed) & 0xffff,
			.end = tdp_rand(&seed) & 0xffff,
			.mode = tdp_rand(&seed) % 3,
		};
		struct rdc_rect clip = no_clip;

		if (k % 7 == 0)
			c.rx = (uint32_t)tdp_range(&seed, 100, 400);
		if (k % 7 == 0)
			c.ry = (uint32_t)tdp_range(&seed, 1, 6);
		/* near an edge or a corner of the surface */
		c.cx = tdp_rand(&seed) % 2 ?
			       tdp_range(&seed, -40, 40) :
			       tdp_range(&seed, CS_W - 40, CS_W + 40);
		c.cy = tdp_rand(&seed) % 2 ?
			       tdp_range(&seed, -40, 40) :
			       tdp_range(&seed, CS_H - 40, CS_H + 40);
		if (k % 3 == 0) {
			/* a clip rectangle across the shape instead */
			c.cx = tdp_range(&seed, 100, CS_W - 100);
			c.cy = tdp_range(&seed, 100, CS_H - 100);
			clip.x0 = c.cx + tdp_range(&seed, -30, 30);
			clip.y0 = c.cy + tdp_range(&seed, -30, 30);
			clip.x1 = clip.x0 + tdp_range(&seed, 0, 80);
			clip.y1 = clip.y0 + tdp_range(&seed, 0, 80);
		}
		conic_check(t, &c, clip);
	}
}

/*
 * ARC, every mode, over every rx, ry in 0..40 and the flat ones, at angles
 * on the axes, across +x, whole turns and random ones.
 */
static void test_arc_sweep(void **state)
{
	static const uint32_t fixed[][2] = {
		{ 0, 16384 },	 { 16384, 49152 }, { 49152, 8192 },
		{ 60000, 1000 }, { 1234, 1234 },   { 32768, 0 },
	};
	struct tdp *t = *state;
	struct conic c = { .shape = S_ARC, .cx = 410, .cy = 410 };
	uint32_t seed = 0xa2c5, k = 0, i, rounded = 0, checked = 0;

	for (c.rx = 0; c.rx <= 40 + RDC_ARRAY_SIZE(flat_rx); c.rx++) {
		uint32_t rx = c.rx;

		for (c.ry = 0; c.ry <= (rx > 40 ? 6 : 40); c.ry++) {
			if (rx > 40)
				c.rx = flat_rx[rx - 41];
			for (i = 0; i < 2; i++, k++) {
				if (k % 3 == 0) {
					c.start = fixed[k / 3 % 6][0];
					c.end = fixed[k / 3 % 6][1];
				} else {
					c.start = tdp_rand(&seed) & 0xffff;
					c.end = tdp_rand(&seed) & 0xffff;
				}
				c.mode = k % 3;
				rounded += !rdc_ref_arc_generic(c.rx, c.ry,
								c.start, c.end);
				conic_check(t, &c, no_clip);
				checked++;
			}
			c.rx = rx;
		}
	}
	print_message("arcs checked %u\n", checked);
	assert_true(checked > 3000);
	assert_int_equal(rounded, 0);
}

/*
 * Sweeps closest to none, half and a whole turn, where the end points'
 * rounding could put the end ray on the wrong side of the start ray: it
 * never does (so the documented half-plane rule and the angle order
 * agree), and the pixels are the reference's.
 */
static void test_arc_rounded(void **state)
{
	static const uint32_t near[] = { 1,	 2,	 3,	 5,	 0x7ffd,
					 0x7ffe, 0x7fff, 0x8000, 0x8001, 0x8002,
					 0xfffd, 0xfffe, 0xffff };
	struct tdp *t = *state;
	struct conic c = { .shape = S_ARC, .cx = 410, .cy = 410 };
	uint32_t s, i, rounded = 0, seed = 0x5eed;

	for (s = 0; s < 0x10000; s += 0x100 + 7)
		for (i = 0; i < RDC_ARRAY_SIZE(near); i++) {
			/* small radii: the end vectors' truncation counts */
			c.rx = (uint32_t)tdp_range(&seed, 1, i % 2 ? 4 : 40);
			c.ry = (uint32_t)tdp_range(&seed, 1, i % 2 ? 4 : 40);
			c.start = s;
			c.end = (s + near[i]) & 0xffff;
			c.mode = (s + i) % 3;
			rounded += !rdc_ref_arc_generic(c.rx, c.ry, c.start,
							c.end);
			conic_check(t, &c, no_clip);
		}
	assert_int_equal(rounded, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		CONIC_TEST(test_ellipse_sweep), CONIC_TEST(test_ellipse_flat),
		CONIC_TEST(test_circle_sweep),	CONIC_TEST(test_conic_clipped),
		CONIC_TEST(test_arc_sweep),	CONIC_TEST(test_arc_rounded),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
