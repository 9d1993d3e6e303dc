// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * FILL_POLYGON and SET_PATTERN: the scan-line fill against the plain
 * per-pixel reference (ref_poly.c) on seeded random polygons, the tie rule
 * (tilings cover every pixel once), Sutherland-Hodgman clipping against
 * the unclipped fill, the transform, patterns on every filled primitive,
 * bad arguments and cycle counts.
 */
#include "tdp_poly.h"
#include "ref_poly.h"

#define W 96
#define H 72

static bool in_rect(const struct rdc_rect *c, int32_t x, int32_t y)
{
	return x >= c->x0 && x < c->x1 && y >= c->y0 && y < c->y1;
}

static void random_poly(uint32_t *rng, int32_t *xy, uint32_t n, int32_t span)
{
	uint32_t i;

	for (i = 0; i < n; i++) {
		xy[2 * i] = tdp_range(rng, -span, W + span);
		xy[2 * i + 1] = tdp_range(rng, -span, H + span);
	}
}

/* DP against the reference, every format, even-odd and non-zero. */
static void test_random_vs_ref(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0x9e3779b9u, iter;

	for (iter = 0; iter < 300; iter++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT;
		struct rdc_surface s = tpp_surface(fmt, W, H);
		uint32_t n = (uint32_t)tdp_range(&rng, 3, 14), fg, fl;
		int32_t xy[2 * 120], span = iter % 5 == 0 ? 16000 : 30;
		struct rdc_rect c = { 0, 0, W, H };
		int32_t x, y;

		if (iter % 7 == 3) /* many edges active on a row */
			n = 120;
		tpp_dst(t, &s);
		random_poly(&rng, xy, n, span);
		if (span > 1000) /* keep some of it on screen */
			xy[0] = W / 2, xy[1] = H / 2;
		if (tdp_rand(&rng) % 2) {
			c.x0 = tdp_range(&rng, -5, W / 2);
			c.y0 = tdp_range(&rng, -5, H / 2);
			c.x1 = tdp_range(&rng, c.x0, W + 5);
			c.y1 = tdp_range(&rng, c.y0, H + 5);
			TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(c.x0, c.y0),
				RDC_XY(c.x1, c.y1));
		}
		fg = (tdp_rand(&rng) | 1) & tdp_mask(fmt);
		fl = tdp_rand(&rng) % 2 ? RDC_FILL_NONZERO : 0;
		TDP_CMD(t, RDC_OP_SET_FG, fg);
		tpp_fill_poly(t, xy, n, fl);
		assert_int_equal(tdp_err(t), 0);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				bool in = in_rect(&c, x, y) &&
					  rdc_ref_poly_inside(xy, n, fl != 0, x,
							      y);

				if (tdp_get(t->vram, &s, x, y) != (in ? fg : 0))
					fail_msg(
						"iter %u fmt %u (%d,%d) want %d",
						iter, fmt, x, y, in);
			}
	}
}

static bool convex(const int32_t *q)
{
	int k, pos = 0, neg = 0;

	for (k = 0; k < 4; k++) {
		const int32_t *a = q + 2 * k, *b = q + 2 * ((k + 1) % 4);
		const int32_t *c = q + 2 * ((k + 2) % 4);
		int64_t cr = (int64_t)(b[0] - a[0]) * (c[1] - b[1]) -
			     (int64_t)(b[1] - a[1]) * (c[0] - b[0]);

		pos += cr > 0;
		neg += cr < 0;
	}
	return !(pos && neg);
}

/* Jittered grids of triangles and quads tile a rectangle exactly. */
static void test_tiling(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, W, H);
	enum { GX = 6, GY = 5, X0 = 7, Y0 = 5, CW = 13, CH = 11 };
	static uint8_t count[W * H];
	int32_t gx[GY + 1][GX + 1], gy[GY + 1][GX + 1];
	uint32_t rng = 12345, round;

	tpp_dst(t, &s);
	TDP_CMD(t, RDC_OP_SET_FG, 1);
	for (round = 0; round < 4; round++) {
		int32_t i, j, k;

		memset(count, 0, sizeof(count));
		for (j = 0; j <= GY; j++)
			for (i = 0; i <= GX; i++) {
				gx[j][i] = X0 + i * CW;
				gy[j][i] = Y0 + j * CH;
				if (i > 0 && i < GX)
					gx[j][i] += tdp_range(&rng, -5, 5);
				if (j > 0 && j < GY)
					gy[j][i] += tdp_range(&rng, -4, 4);
			}
		for (j = 0; j < GY; j++)
			for (i = 0; i < GX; i++) {
				int32_t q[8] = {
					gx[j][i],	  gy[j][i],
					gx[j][i + 1],	  gy[j][i + 1],
					gx[j + 1][i + 1], gy[j + 1][i + 1],
					gx[j + 1][i],	  gy[j + 1][i]
				};
				int32_t tri[2][6];
				uint32_t kind = tdp_rand(&rng) % 3, p;

				/* a diagonal may leave a concave quad */
				if (!convex(q))
					kind = 0;

				/* a quad, or two triangles either way round */
				for (k = 0; k < 6; k++) {
					tri[0][k] =
						q[kind == 1 ? (k + 2) % 8 : k];
					tri[1][k] = q[kind == 1 ? (k + 6) % 8 :
								  (k + 4) % 8];
				}
				for (p = 0; p < (kind ? 2u : 1u); p++) {
					int32_t x, y;

					tpp_clear(t, &s);
					if (kind)
						tpp_fill_poly(
							t, tri[p], 3,
							p ? RDC_FILL_NONZERO :
							    0);
					else
						tpp_fill_poly(t, q, 4, 0);
					for (y = 0; y < H; y++)
						for (x = 0; x < W; x++)
							count[y * W + x] +=
								tdp_get(t->vram,
									&s, x,
									y);
				}
			}
		for (k = 0; k < W * H; k++) {
			int32_t x = k % W, y = k / W;
			bool in = x >= X0 && x < X0 + GX * CW && y >= Y0 &&
				  y < Y0 + GY * CH;

			if (count[k] != (in ? 1 : 0))
				fail_msg("round %u (%d,%d) covered %u times",
					 round, x, y, count[k]);
		}
	}
}

/* Clipped fill == unclipped fill restricted to the clip. */
static void check_clip_equiv(struct tdp *t, const struct rdc_surface *s,
			     const int32_t *xy, uint32_t n, uint32_t fl,
			     const struct rdc_rect *c)
{
	size_t bytes = (size_t)s->stride * s->height;
	uint8_t *full = malloc(bytes);
	int32_t x, y;

	assert_non_null(full);
	tpp_dst(t, s);
	TDP_CMD(t, RDC_OP_SET_FG, 1);
	tpp_fill_poly(t, xy, n, fl);
	memcpy(full, t->vram + s->base, bytes);
	tpp_clear(t, s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(c->x0, c->y0), RDC_XY(c->x1, c->y1));
	tpp_fill_poly(t, xy, n, fl);
	assert_int_equal(tdp_err(t), 0);
	for (y = 0; y < (int32_t)s->height; y++)
		for (x = 0; x < (int32_t)s->width; x++) {
			uint32_t want =
				in_rect(c, x, y) ?
					full[(size_t)y * s->stride + x] :
					0;

			if (t->vram[s->base + (size_t)y * s->stride + x] !=
			    want)
				fail_msg("(%d,%d) clipped %u unclipped %u", x,
					 y,
					 t->vram[s->base +
						 (size_t)y * s->stride + x],
					 want);
		}
	free(full);
}

static void test_clip_equiv(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, W, H);
	uint32_t rng = 777, iter, i;
	int32_t *zig;

	for (iter = 0; iter < 200; iter++) {
		int32_t xy[2 * 12];
		uint32_t n = (uint32_t)tdp_range(&rng, 3, 12);
		struct rdc_rect c;

		random_poly(&rng, xy, n, iter % 3 ? 40 : 3000);
		c.x0 = tdp_range(&rng, 0, W / 2);
		c.y0 = tdp_range(&rng, 0, H / 2);
		c.x1 = tdp_range(&rng, c.x0, W);
		c.y1 = tdp_range(&rng, c.y0, H);
		check_clip_equiv(t, &s, xy, n, iter & 1 ? RDC_FILL_NONZERO : 0,
				 &c);
	}
	/*
	 * A comb of RDC_CMD_MAX_ARGS points whose teeth all cross the clip
	 * sides: clipping would need more vertices than the table holds, so
	 * the fill takes the per-row path; same pixels either way.
	 */
	zig = calloc(2 * RDC_CMD_MAX_ARGS, sizeof(*zig));
	assert_non_null(zig);
	for (i = 0; i < RDC_CMD_MAX_ARGS; i++) {
		zig[2 * i] = (int32_t)(i % 2 ? W + 20 : -20) +
			     (int32_t)(i % 4 == 1 ? 3 : 0);
		zig[2 * i + 1] =
			-10 + (int32_t)(i * (H + 20) / RDC_CMD_MAX_ARGS);
	}
	{
		struct rdc_rect c = { 10, 6, W - 10, H - 6 };

		check_clip_equiv(t, &s, zig, RDC_CMD_MAX_ARGS, 0, &c);
		check_clip_equiv(t, &s, zig, RDC_CMD_MAX_ARGS, RDC_FILL_NONZERO,
				 &c);
	}
	free(zig);
}

/* Translation through the transform == pre-translated integer points. */
static void test_transform_translate(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, W, H);
	uint32_t rng = 4242, iter, h1;

	for (iter = 0; iter < 40; iter++) {
		int32_t xy[16], moved[16];
		uint32_t n = (uint32_t)tdp_range(&rng, 3, 8), i;
		int32_t tx = tdp_range(&rng, -30, 30),
			ty = tdp_range(&rng, -30, 30);

		random_poly(&rng, xy, n, 20);
		for (i = 0; i < n; i++) {
			moved[2 * i] = xy[2 * i] + tx;
			moved[2 * i + 1] = xy[2 * i + 1] + ty;
		}
		tpp_dst(t, &s);
		TDP_CMD(t, RDC_OP_SET_FG, 9);
		tpp_fill_poly(t, moved, n, 0);
		h1 = tpp_hash(t, &s);
		tpp_clear(t, &s);
		TDP_CMD(t, RDC_OP_SET_TRANSFORM, 1u << 16, 0,
			(uint32_t)tx << 16, 0, 1u << 16, (uint32_t)ty << 16, 0,
			0, 1u << 16);
		tpp_fill_poly(t, xy, n, 0);
		TDP_CMD(t, RDC_OP_SET_TRANSFORM);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		assert_int_equal(tpp_hash(t, &s), h1);
	}
}

static uint32_t pat_mono_word(const uint8_t *rows, unsigned int k)
{
	return (uint32_t)rows[4 * k] | (uint32_t)rows[4 * k + 1] << 8 |
	       (uint32_t)rows[4 * k + 2] << 16 |
	       (uint32_t)rows[4 * k + 3] << 24;
}

/* Patterns on FILL_RECT, FILL_POLYGON, FILL_CIRCLE, FILL_ELLIPSE: the
 * pixels are the solid fill's, the values the pattern's cell. */
static void test_patterns(void **state)
{
	struct tdp *t = *state;
	static const uint8_t rows[8] = { 0x81, 0x42, 0x24, 0x18,
					 0xf0, 0x0f, 0xaa, 0x55 };
	uint32_t colors[64], fmt, mode, prim, i;
	uint32_t rng = 99;

	for (i = 0; i < 64; i++)
		colors[i] = tdp_rand(&rng);
	for (fmt = 0; fmt < RDC_FMT_COUNT; fmt++) {
		struct rdc_surface s = tpp_surface(fmt, W, H);
		size_t bytes = (size_t)s.stride * s.height;
		uint8_t *solid = malloc(bytes);
		uint32_t pre = 0x5a5a5a5a & tdp_mask(fmt);

		assert_non_null(solid);
		for (prim = 0; prim < 4; prim++) {
			for (mode = RDC_PAT_MONO; mode <= RDC_PAT_COLOR;
			     mode++) {
				const int32_t tri[6] = { 5, 3, 90, 20, 30, 70 };
				uint32_t fg = 0xfedcba98 & tdp_mask(fmt);
				uint32_t bg = 0x13579bdf & tdp_mask(fmt);
				int32_t x, y;

				tpp_dst(t, &s);
				tdp_cmd(t, RDC_OP_SET_PATTERN, RDC_PAT_NONE, 0,
					NULL);
				TDP_CMD(t, RDC_OP_SET_FG, 1);
				for (i = 0; i < 2; i++) {
					switch (prim) {
					case 0:
						TDP_CMD(t, RDC_OP_FILL_RECT,
							RDC_XY(3, 5),
							RDC_WH(70, 50));
						break;
					case 1:
						tpp_fill_poly(t, tri, 3, 0);
						break;
					case 2:
						TDP_CMD(t, RDC_OP_FILL_CIRCLE,
							RDC_XY(40, 35), 30);
						break;
					default:
						TDP_CMD(t, RDC_OP_FILL_ELLIPSE,
							RDC_XY(45, 33),
							RDC_WH(40, 20));
						break;
					}
					tdp_drain(t);
					if (i)
						break;
					/* the solid set, then the patterned
					 * fill over a known background */
					memcpy(solid, t->vram + s.base, bytes);
					memset(t->vram + s.base, 0, bytes);
					for (y = 0; y < H; y++)
						for (x = 0; x < W; x++)
							tdp_put(t->vram, &s, x,
								y, pre);
					TDP_CMD(t, RDC_OP_SET_FG, fg);
					TDP_CMD(t, RDC_OP_SET_BG, bg);
					if (mode == RDC_PAT_COLOR) {
						tdp_cmd(t, RDC_OP_SET_PATTERN,
							mode, 64, colors);
					} else {
						uint32_t w2[2] = {
							pat_mono_word(rows, 0),
							pat_mono_word(rows, 1)
						};

						tdp_cmd(t, RDC_OP_SET_PATTERN,
							mode, 2, w2);
					}
				}
				assert_int_equal(tdp_err(t), 0);
				for (y = 0; y < H; y++)
					for (x = 0; x < W; x++) {
						struct rdc_surface ss = s;
						uint32_t want = pre, bit;

						ss.base = 0;
						if (tdp_get(solid, &ss, x, y)) {
							bit = (rows[y & 7] >>
							       (7 - (x & 7))) &
							      1;
							if (mode ==
							    RDC_PAT_COLOR)
								want = colors[(y &
									       7) * 8 +
									      (x &
									       7)] &
								       tdp_mask(
									       fmt);
							else if (bit)
								want = fg;
							else if (mode ==
								 RDC_PAT_MONO)
								want = bg;
						}
						if (tdp_get(t->vram, &s, x,
							    y) != want)
							fail_msg(
								"fmt %u prim %u mode %u (%d,%d)",
								fmt, prim, mode,
								x, y);
					}
			}
		}
		free(solid);
	}
}

/* Every bad argument: the documented error, nothing drawn, no state. */
static void test_bad_args(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	uint32_t h0, big[RDC_CMD_MAX_ARGS], i;
	const uint32_t tri[3] = { RDC_XY(1, 1), RDC_XY(50, 5), RDC_XY(20, 40) };
	const uint32_t far[3] = { RDC_XY(1, 1), RDC_XY(16384, 5),
				  RDC_XY(20, 40) };
	const struct {
		uint32_t op, flags, n;
		const uint32_t *a;
		uint32_t err;
	} bad[] = {
		{ RDC_OP_FILL_POLYGON, 0, 2, tri, RDC_ERR_LENGTH },
		{ RDC_OP_FILL_POLYGON, 0, 0, tri, RDC_ERR_LENGTH },
		{ RDC_OP_FILL_POLYGON, 2, 3, tri, RDC_ERR_ARG },
		{ RDC_OP_FILL_POLYGON, 0, 3, far, RDC_ERR_RANGE },
		{ RDC_OP_SET_PATTERN, 4, 0, tri, RDC_ERR_ARG },
		{ RDC_OP_SET_PATTERN, RDC_PAT_NONE, 1, tri, RDC_ERR_LENGTH },
		{ RDC_OP_SET_PATTERN, RDC_PAT_MONO, 3, tri, RDC_ERR_LENGTH },
		{ RDC_OP_SET_PATTERN, RDC_PAT_MONO_TRANSPARENT, 1, tri,
		  RDC_ERR_LENGTH },
		{ RDC_OP_SET_PATTERN, RDC_PAT_COLOR, 3, tri, RDC_ERR_LENGTH },
	};

	tpp_dst(t, &s);
	h0 = tpp_hash(t, &s);
	for (i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		tdp_clear_err(t);
		tdp_cmd(t, bad[i].op, bad[i].flags, bad[i].n, bad[i].a);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), bad[i].err);
		/* the pattern stayed solid: a fill draws plain FG */
		TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(0, 0), RDC_WH(1, 1));
		tdp_drain(t);
		assert_int_equal(tdp_get(t->vram, &s, 0, 0), 0xffffffffu);
		assert_int_equal(tdp_get(t->vram, &s, 1, 0), 0);
		tpp_clear(t, &s);
	}
	assert_int_equal(tpp_hash(t, &s), h0);

	/* A transform that throws a vertex out of range: RDC_ERR_RANGE. */
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_SET_TRANSFORM, 1u << 16, 0, 16380u << 16, 0, 1u << 16,
		0, 0, 0, 1u << 16);
	tdp_cmd(t, RDC_OP_FILL_POLYGON, 0, 3, tri);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	TDP_CMD(t, RDC_OP_SET_TRANSFORM);
	tdp_drain(t);
	assert_int_equal(tpp_hash(t, &s), h0);

	/* Degenerate polygons draw nothing and are no error. */
	tdp_clear_err(t);
	for (i = 0; i < RDC_CMD_MAX_ARGS; i++)
		big[i] = RDC_XY(10 + (int32_t)(i % 7), 10 + (int32_t)(i % 7));
	tdp_cmd(t, RDC_OP_FILL_POLYGON, 0, RDC_CMD_MAX_ARGS, big);
	for (i = 0; i < 3; i++)
		big[i] = RDC_XY(5, 5);
	tdp_cmd(t, RDC_OP_FILL_POLYGON, RDC_FILL_NONZERO, 3, big);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tpp_hash(t, &s), h0);

	/* The most points a command holds, at the coordinate extremes. */
	for (i = 0; i < RDC_CMD_MAX_ARGS; i++)
		big[i] = RDC_XY(i % 2 ? RDC_COORD_MAX : RDC_COORD_MIN,
				i % 3 ? RDC_COORD_MIN : RDC_COORD_MAX);
	tdp_cmd(t, RDC_OP_FILL_POLYGON, 0, RDC_CMD_MAX_ARGS, big);
	tdp_cmd(t, RDC_OP_FILL_POLYGON, RDC_FILL_NONZERO, RDC_CMD_MAX_ARGS,
		big);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
}

/*
 * Cycles: fetch (a FIFO word each) + decode + one write span per maximal
 * run of each row, the runs read back from the image (solid), or one span
 * per row of at most RDC_DP_CHUNK pixels (patterned; read-modify-write
 * when transparent).
 */
static uint64_t image_runs_cost(struct tdp *t, const struct rdc_surface *s,
				uint32_t open, int kind)
{
	uint64_t cost = 0;
	int32_t x, y;

	for (y = 0; y < (int32_t)s->height; y++)
		for (x = 0; x < (int32_t)s->width; x++) {
			int32_t x1 = x;

			if (!tdp_get(t->vram, s, x, y))
				continue;
			while (x1 + 1 < (int32_t)s->width &&
			       tdp_get(t->vram, s, x1 + 1, y))
				x1++;
			cost += tpp_row_cost(&open, s, x, y,
					     (uint32_t)(x1 - x + 1), kind);
			x = x1;
		}
	return cost;
}

static void test_cycles(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	const int32_t star[10] = { 10, 60, 48, 2, 86, 60, 4, 22, 92, 22 };
	uint32_t rng = 5, iter, open;
	uint64_t want;

	tpp_dst(t, &s);
	for (iter = 0; iter < 30; iter++) {
		int32_t xy[16];
		uint32_t n = iter ? (uint32_t)tdp_range(&rng, 3, 8) : 5;

		if (iter)
			random_poly(&rng, xy, n, 10);
		else
			memcpy(xy, star, sizeof(star));
		tpp_clear(t, &s);
		tdp_drain(t);
		open = t->hw.bus.open_row;
		tpp_fill_poly(t, xy, n, iter % 2 ? RDC_FILL_NONZERO : 0);
		want = (1 + n) * RDC_T_FIFO_WORD + RDC_T_DECODE +
		       image_runs_cost(t, &s, open, TDP_BUS_WRITE);
		assert_int_equal(tpp_last_cycles(t), want);
	}

	/* patterned FILL_RECT: one span a row, opaque then transparent */
	{
		const uint32_t pat[2] = { 0x01020304, 0x10204080 };
		int32_t y;
		uint32_t mode;

		for (mode = RDC_PAT_MONO; mode <= RDC_PAT_MONO_TRANSPARENT;
		     mode++) {
			tdp_cmd(t, RDC_OP_SET_PATTERN, mode, 2, pat);
			tdp_drain(t);
			open = t->hw.bus.open_row;
			want = 3 * RDC_T_FIFO_WORD + RDC_T_DECODE;
			for (y = 4; y < 4 + 9; y++)
				want += tpp_row_cost(&open, &s, 3, y, 50,
						     mode == RDC_PAT_MONO ?
							     TDP_BUS_WRITE :
							     TDP_BUS_RMW);
			TDP_CMD(t, RDC_OP_FILL_RECT, RDC_XY(3, 4),
				RDC_WH(50, 9));
			tdp_drain(t);
			assert_int_equal(tpp_last_cycles(t), want);
		}
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_random_vs_ref),
		TDP_TEST(test_tiling),
		TDP_TEST(test_clip_equiv),
		TDP_TEST(test_transform_translate),
		TDP_TEST(test_patterns),
		TDP_TEST(test_bad_args),
		TDP_TEST(test_cycles),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
