// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * TRIANGLE, SET_ZBUF, CLEAR_Z: coverage against the reference polygon
 * test, shared edges drawn once, Gouraud colours against a floating-point
 * plane evaluated here, depth test and write, bad arguments, cycles.
 */
#include "tdp_poly.h"
#include "ref_poly.h"

#define W     96
#define H     72
#define ZBASE 0x100000u

static void tri_cmd(struct tdp *t, const int32_t *xy, const uint32_t *col,
		    const uint32_t *z, uint32_t flags)
{
	uint32_t a[9], i;

	for (i = 0; i < 3; i++) {
		a[3 * i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
		a[3 * i + 1] = col[i];
		a[3 * i + 2] = z[i];
	}
	tdp_cmd(t, RDC_OP_TRIANGLE, flags, 9, a);
	tdp_drain(t);
}

static uint32_t zget(struct tdp *t, uint32_t stride, int32_t x, int32_t y)
{
	const uint8_t *p = t->vram + ZBASE + (size_t)y * stride + 2 * (size_t)x;

	return (uint32_t)p[0] | (uint32_t)p[1] << 8;
}

/* Flat triangles: the reference polygon's pixels, vertex 0's colour. */
static void test_coverage(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 31337, iter;

	for (iter = 0; iter < 200; iter++) {
		uint32_t fmt = tdp_rand(&rng) % RDC_FMT_COUNT, i;
		struct rdc_surface s = tpp_surface(fmt, W, H);
		int32_t xy[6], x, y;
		uint32_t col[3], z[3] = { 0, 0, 0 };

		tpp_dst(t, &s);
		for (i = 0; i < 3; i++) {
			xy[2 * i] = tdp_range(&rng, -30, W + 30);
			xy[2 * i + 1] = tdp_range(&rng, -30, H + 30);
			col[i] = tdp_rand(&rng) | 1;
		}
		tri_cmd(t, xy, col, z, 0);
		assert_int_equal(tdp_err(t), 0);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				bool in =
					rdc_ref_poly_inside(xy, 3, false, x, y);

				assert_int_equal(tdp_get(t->vram, &s, x, y),
						 in ? col[0] & tdp_mask(fmt) :
						      0);
			}
	}
}

/* Fans of triangles around an inner point: every pixel once. */
static void test_shared_edges(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_I8, W, H);
	static uint8_t count[W * H];
	uint32_t rng = 2024, iter;

	tpp_dst(t, &s);
	for (iter = 0; iter < 20; iter++) {
		enum { N = 9 };
		int32_t ring[2 * N], cx = tdp_range(&rng, 35, 60);
		int32_t cy = tdp_range(&rng, 28, 44), k, x, y;
		uint32_t col[3] = { 1, 1, 1 }, z[3] = { 0, 0, 0 };

		memset(count, 0, sizeof(count));
		/* a star-shaped ring: angle steps of 40 degrees */
		for (k = 0; k < N; k++) {
			/* 1000 cos, 1000 sin of k * 40 degrees */
			static const int32_t cs[N][2] = {
				{ 1000, 0 },	{ 766, 643 },  { 174, 985 },
				{ -500, 866 },	{ -940, 342 }, { -940, -342 },
				{ -500, -866 }, { 174, -985 }, { 766, -643 }
			};
			int32_t r = tdp_range(&rng, 15, 30);

			ring[2 * k] = cx + r * cs[k][0] / 1000;
			ring[2 * k + 1] = cy + r * cs[k][1] / 1000;
		}
		for (k = 0; k < N; k++) {
			int32_t tri[6] = { cx,
					   cy,
					   ring[2 * k],
					   ring[2 * k + 1],
					   ring[2 * ((k + 1) % N)],
					   ring[2 * ((k + 1) % N) + 1] };

			tpp_clear(t, &s);
			tri_cmd(t, tri, col, z, iter % 2 ? RDC_TRI_GOURAUD : 0);
			for (y = 0; y < H; y++)
				for (x = 0; x < W; x++)
					count[y * W + x] +=
						tdp_get(t->vram, &s, x, y);
		}
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++)
				assert_int_equal(count[y * W + x],
						 rdc_ref_poly_inside(
							 ring, N, false, x, y));
	}
}

/* The plane through three values, at pixel centre (px, py). */
static double plane(const int32_t *xy, const double *a, int32_t px, int32_t py)
{
	double x = px + 0.5, y = py + 0.5;
	double x0 = xy[0], y0 = xy[1], x1 = xy[2], y1 = xy[3];
	double x2 = xy[4], y2 = xy[5];
	double d = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
	double l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / d;
	double l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / d;

	return a[0] + l1 * (a[1] - a[0]) + l2 * (a[2] - a[0]);
}

static double dabs(double v)
{
	return v < 0 ? -v : v;
}

static void test_gouraud(void **state)
{
	struct tdp *t = *state;
	static const uint32_t fmts[] = { RDC_FMT_I8, RDC_FMT_RGB565,
					 RDC_FMT_RGB888, RDC_FMT_XRGB8888 };
	uint32_t rng = 8, iter;

	for (iter = 0; iter < 60; iter++) {
		uint32_t fmt = fmts[iter % 4], i, ch, nch;
		struct rdc_surface s = tpp_surface(fmt, W, H);
		unsigned int sh[3], wd[3];
		int32_t xy[6], x, y;
		uint32_t col[3], z[3] = { 0, 0, 0 };

		if (fmt == RDC_FMT_I8) {
			nch = 1, sh[0] = 0, wd[0] = 8;
		} else if (fmt == RDC_FMT_RGB565) {
			nch = 3, sh[0] = 11, wd[0] = 5, sh[1] = 5, wd[1] = 6;
			sh[2] = 0, wd[2] = 5;
		} else {
			nch = 3, sh[0] = 16, sh[1] = 8, sh[2] = 0;
			wd[0] = wd[1] = wd[2] = 8;
		}
		tpp_dst(t, &s);
		for (i = 0; i < 3; i++) {
			xy[2 * i] = tdp_range(&rng, -10, W + 10);
			xy[2 * i + 1] = tdp_range(&rng, -10, H + 10);
			col[i] = tdp_rand(&rng) & tdp_mask(fmt) &
				 (fmt == RDC_FMT_XRGB8888 ? 0xffffff : ~0u);
		}
		if (iter < 4) /* all three alike: every pixel that colour */
			col[1] = col[2] = col[0];
		tri_cmd(t, xy, col, z, RDC_TRI_GOURAUD);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				uint32_t got = tdp_get(t->vram, &s, x, y);

				if (!rdc_ref_poly_inside(xy, 3, false, x, y)) {
					assert_int_equal(got, 0);
					continue;
				}
				for (ch = 0; ch < nch; ch++) {
					double a[3], want;
					uint32_t m = (1u << wd[ch]) - 1;
					int32_t g =
						(int32_t)((got >> sh[ch]) & m);

					for (i = 0; i < 3; i++)
						a[i] = (col[i] >> sh[ch]) & m;
					want = plane(xy, a, x, y);
					if (dabs(g - want) > 0.5 + 1e-6)
						fail_msg(
							"fmt %u (%d,%d) ch %u got %d "
							"want %.3f",
							fmt, x, y, ch, g, want);
				}
			}
	}
}

/* Depth: CLEAR_Z within the clip; nearer wins in either order; the
 * interpolated z that Z_WRITE stores. */
static void test_depth(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	const uint32_t zs = 2 * W + 8;
	const int32_t a[6] = { 5, 5, 90, 10, 20, 65 };
	const int32_t b[6] = { 80, 60, 10, 20, 70, 2 };
	const uint32_t ca[3] = { 0xff0000, 0xff0000, 0xff0000 };
	const uint32_t cb[3] = { 0x00ff00, 0x00ff00, 0x00ff00 };
	const uint32_t za[3] = { 100, 100, 100 }, zb[3] = { 50, 200, 150 };
	uint32_t order, h[2];
	int32_t x, y;

	for (order = 0; order < 2; order++) {
		tpp_dst(t, &s);
		memset(t->vram + ZBASE, 0, (size_t)zs * H);
		tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
			(const uint32_t[]){ ZBASE, zs });
		TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(W, H - 2));
		TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
		TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(0, 0), RDC_XY(W, H));
		tdp_drain(t);
		assert_int_equal(tdp_err(t), 0);
		/* clip applied: the last two rows are untouched */
		for (x = 0; x < W; x++) {
			assert_int_equal(zget(t, zs, x, 0), 0xffff);
			assert_int_equal(zget(t, zs, x, H - 3), 0xffff);
			assert_int_equal(zget(t, zs, x, H - 2), 0);
		}
		memset(t->vram + ZBASE + (size_t)(H - 2) * zs, 0xff, 2 * zs);
		if (order) {
			tri_cmd(t, b, cb, zb, RDC_TRI_GOURAUD);
			tri_cmd(t, a, ca, za, 0);
		} else {
			tri_cmd(t, a, ca, za, 0);
			tri_cmd(t, b, cb, zb, RDC_TRI_GOURAUD);
		}
		assert_int_equal(tdp_err(t), 0);
		h[order] = tpp_hash(t, &s);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				bool ina =
					rdc_ref_poly_inside(a, 3, false, x, y);
				bool inb =
					rdc_ref_poly_inside(b, 3, false, x, y);
				double zz[3] = { 50, 200, 150 };
				double bz = plane(b, zz, x, y);
				uint32_t px = tdp_get(t->vram, &s, x, y);
				uint32_t zv = zget(t, zs, x, y);

				if (!ina && !inb) {
					assert_int_equal(px, 0);
					assert_int_equal(zv, 0xffff);
				} else if (ina && (!inb || bz > 100.5)) {
					assert_int_equal(px, 0xff0000);
					assert_int_equal(zv, 100);
				} else if (inb && (!ina || bz < 99.5)) {
					assert_int_equal(px, 0x00ff00);
					assert_true(dabs(zv - bz) <=
						    0.5 + 1e-6);
				}
			}
	}
	assert_int_equal(h[0], h[1]);

	/* test without write: the depth surface is only read */
	{
		uint32_t zh = tdp_fnv(1, t->vram + ZBASE, (size_t)zs * H);
		const uint32_t zn[3] = { 0, 0, 0 };

		tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST, 2,
			(const uint32_t[]){ ZBASE, zs });
		tri_cmd(t, a, cb, zn, 0);
		assert_int_equal(tdp_fnv(1, t->vram + ZBASE, (size_t)zs * H),
				 zh);
		assert_int_equal(tdp_get(t->vram, &s, 30, 20), 0x00ff00);
		tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
		tdp_drain(t);
	}
}

static void test_bad_args(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	const uint32_t ok[9] = { RDC_XY(1, 1),	 5, 0, RDC_XY(50, 5), 5, 0,
				 RDC_XY(20, 40), 5, 0 };
	uint32_t a[9], h0, big = TDP_VRAM_SIZE - 100;
	const struct {
		uint32_t op, flags, n, a0, a1;
		uint32_t err;
	} bad[] = {
		{ RDC_OP_SET_ZBUF, 4, 2, ZBASE, 2 * W, RDC_ERR_ARG },
		{ RDC_OP_SET_ZBUF, 0, 1, ZBASE, 2 * W, RDC_ERR_LENGTH },
		{ RDC_OP_SET_ZBUF, RDC_Z_TEST, 0, 0, 0, RDC_ERR_ARG },
		{ RDC_OP_SET_ZBUF, 0, 2, ZBASE, 2 * W - 1, RDC_ERR_SURFACE },
		{ RDC_OP_SET_ZBUF, 0, 2, big, 2 * W, RDC_ERR_SURFACE },
		{ RDC_OP_SET_ZBUF, 0, 2, 0xffffffffu, 2 * W, RDC_ERR_SURFACE },
		{ RDC_OP_CLEAR_Z, 0, 1, 0, 0, RDC_ERR_SURFACE },
		{ RDC_OP_CLEAR_Z, 0, 0, 0, 0, RDC_ERR_LENGTH },
	};
	uint32_t i;

	tpp_dst(t, &s);
	h0 = tpp_hash(t, &s);
	for (i = 0; i < RDC_ARRAY_SIZE(bad); i++) {
		uint32_t args[2] = { bad[i].a0, bad[i].a1 };

		tdp_clear_err(t);
		tdp_cmd(t, bad[i].op, bad[i].flags, bad[i].n, args);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), bad[i].err);
	}
	/* TRIANGLE: length, flags, z, coordinates */
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_TRIANGLE, 0, 8, ok);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_LENGTH);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_TRIANGLE, 2, 9, ok);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	memcpy(a, ok, sizeof(a));
	a[5] = 0x10000;
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_TRIANGLE, 0, 9, a);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	memcpy(a, ok, sizeof(a));
	a[6] = RDC_XY(20, RDC_COORD_MAX + 1);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_TRIANGLE, RDC_TRI_GOURAUD, 9, a);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	assert_int_equal(tpp_hash(t, &s), h0);

	/* CLEAR_Z value, and a DST grown past the depth surface */
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_WRITE, 2,
		(const uint32_t[]){ TDP_VRAM_SIZE - 2 * W * H, 2 * W });
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0x10000);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_RANGE);
	s.height = H + 1;
	tdp_set_surface(t, RDC_OP_SET_DST, &s);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_TRIANGLE, 0, 9, ok);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_SURFACE);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 0);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_SURFACE);
	s.height = H;
	tdp_set_surface(t, RDC_OP_SET_DST, &s);

	/* a rejected SET_ZBUF keeps the depth surface it had */
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_WRITE, 2,
		(const uint32_t[]){ ZBASE, 2 * W });
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST, 0, NULL);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_ARG);
	tdp_clear_err(t);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 2, (const uint32_t[]){ big, 2 * W });
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_SURFACE);
	tdp_clear_err(t);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 7);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(zget(t, 2 * W, W - 1, H - 1), 7);
	tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
	tdp_drain(t);

	/* degenerate triangles: nothing, no error */
	tdp_clear_err(t);
	memcpy(a, ok, sizeof(a));
	a[3] = a[0];
	a[6] = RDC_XY(1, 80);
	tdp_cmd(t, RDC_OP_TRIANGLE, RDC_TRI_GOURAUD, 9, a);
	a[6] = a[0];
	tdp_cmd(t, RDC_OP_TRIANGLE, 0, 9, a);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tpp_hash(t, &s), h0);
}

/*
 * Cycles: fetch (10 words) + decode + per run of a row: the depth span
 * (read-modify-write for test + write) then the colour span.
 */
static void test_cycles(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	const uint32_t zs = 2 * W;
	uint32_t rng = 77, iter;

	for (iter = 0; iter < 20; iter++) {
		int32_t xy[6], x, y, i;
		uint32_t col[3] = { 7, 7, 7 }, z[3] = { 10, 10, 10 }, open;
		bool zon = iter % 2;
		uint64_t want = 10 * RDC_T_FIFO_WORD + RDC_T_DECODE;

		for (i = 0; i < 6; i++)
			xy[i] = tdp_range(&rng, -10, (i % 2 ? H : W) + 10);
		tpp_dst(t, &s);
		if (zon) {
			tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST | RDC_Z_WRITE, 2,
				(const uint32_t[]){ ZBASE, zs });
			TDP_CMD(t, RDC_OP_CLEAR_Z, 0xffff);
		} else {
			tdp_cmd(t, RDC_OP_SET_ZBUF, 0, 0, NULL);
		}
		tdp_drain(t);
		open = t->hw.bus.open_row;
		tri_cmd(t, xy, col, z, 0);
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				int32_t x1 = x;
				uint32_t n;

				if (!tdp_get(t->vram, &s, x, y))
					continue;
				while (x1 + 1 < W &&
				       tdp_get(t->vram, &s, x1 + 1, y))
					x1++;
				n = (uint32_t)(x1 - x + 1);
				if (zon)
					want += tdp_bus_edges(
						&open,
						ZBASE + (uint64_t)y * zs +
							2 * (uint64_t)x,
						2 * n, TDP_BUS_RMW, 0, 0);
				want += tpp_row_cost(&open, &s, x, y, n,
						     TDP_BUS_WRITE);
				x = x1;
			}
		assert_int_equal(tpp_last_cycles(t), want);
	}
}

/* CLEAR_Z: one write span of 2 bytes a pixel per clip row; SET_ZBUF
 * and SET_PATTERN: fetch and decode only. */
static void test_cycles_state(void **state)
{
	struct tdp *t = *state;
	struct rdc_surface s = tpp_surface(RDC_FMT_XRGB8888, W, H);
	const uint32_t zs = 2 * W + 16, pat[2] = { 1, 2 };
	uint32_t open;
	uint64_t want;
	int32_t y;

	tpp_dst(t, &s);
	tdp_cmd(t, RDC_OP_SET_ZBUF, RDC_Z_TEST, 2,
		(const uint32_t[]){ ZBASE + 6, zs });
	tdp_drain(t);
	assert_int_equal(tpp_last_cycles(t),
			 3 * RDC_T_FIFO_WORD + RDC_T_DECODE);
	tdp_cmd(t, RDC_OP_SET_PATTERN, RDC_PAT_MONO, 2, pat);
	tdp_drain(t);
	assert_int_equal(tpp_last_cycles(t),
			 3 * RDC_T_FIFO_WORD + RDC_T_DECODE);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(5, 7), RDC_XY(61, 20));
	tdp_drain(t);
	open = t->hw.bus.open_row;
	want = 2 * RDC_T_FIFO_WORD + RDC_T_DECODE;
	for (y = 7; y < 20; y++)
		want += tdp_bus_edges(&open,
				      ZBASE + 6 + (uint64_t)y * zs + 2 * 5,
				      2 * 56, TDP_BUS_WRITE, 0, 0);
	TDP_CMD(t, RDC_OP_CLEAR_Z, 1234);
	tdp_drain(t);
	assert_int_equal(tdp_err(t), 0);
	assert_int_equal(tpp_last_cycles(t), want);
	assert_int_equal(zget(t, zs, 3, 7), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_coverage),     TDP_TEST(test_shared_edges),
		TDP_TEST(test_gouraud),	     TDP_TEST(test_depth),
		TDP_TEST(test_bad_args),     TDP_TEST(test_cycles),
		TDP_TEST(test_cycles_state),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
