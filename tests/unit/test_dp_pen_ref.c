// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The stroker's fast paths against ref_lines.c on seeded random input:
 * convex pieces (scan-line crossings against edge functions), dashed
 * lines (spans of the midpoint line against a per-step walk) and arcs
 * (half-plane tests against directions ordered by exact cross products,
 * end points from the reference's own sine table).
 */
#include "test_dp_common.h"
#include "dp_int.h"
#include "ref_lines.h"

#define W 640
#define H 480

static uint8_t pr_ref[W * H];

static void pr_plot(void *ctx, int32_t x, int32_t y)
{
	uint8_t *m = ctx;

	if (x >= 0 && x < W && y >= 0 && y < H)
		m[y * W + x] = 1;
}

static void pr_compare(struct tdp *t)
{
	int x, y;

	tdp_drain(t);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			if ((tdp_get(t->vram, &t->dp.st.dst, x, y) != 0) !=
			    pr_ref[y * W + x])
				fail_msg("pixel %d,%d differs", x, y);
}

static void pr_clear(struct tdp *t)
{
	memset(t->vram, 0, (size_t)W * H * 4);
	memset(pr_ref, 0, sizeof(pr_ref));
}

static void test_convex(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xc0ffee, k, i;

	for (k = 0; k < 150; k++) {
		struct pen_vec v[4];
		int64_t xy[8];
		uint32_t n = k % 2 ? 3 : 4;

		/* triangles, and parallelograms (always convex); on odd
		 * rounds the vertices sit on whole and half pixels, so the
		 * tie rule is exercised */
		for (i = 0; i < 3; i++) {
			v[i].x = tdp_range(&seed, -20 * 256, (W + 20) * 256);
			v[i].y = tdp_range(&seed, -20 * 256, (H + 20) * 256);
			if (k % 4 < 2) {
				v[i].x &= ~(int64_t)127;
				v[i].y &= ~(int64_t)127;
			}
		}
		/* 0, 1, 2, 3 goes round the parallelogram */
		v[3].x = v[0].x + v[2].x - v[1].x;
		v[3].y = v[0].y + v[2].y - v[1].y;
		for (i = 0; i < n; i++) {
			xy[2 * i] = v[i].x;
			xy[2 * i + 1] = v[i].y;
		}
		pr_clear(t);
		dp_pen_fill_convex(&t->dp, v, n);
		dp_pen_flush(&t->dp);
		rdc_ref_convex(xy, n, 8, pr_plot, pr_ref);
		pr_compare(t);
	}
}

static void test_dash(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xda54, k;

	for (k = 0; k < 120; k++) {
		int x0 = tdp_range(&seed, -50, W + 50);
		int y0 = tdp_range(&seed, -50, H + 50);
		int x1 = tdp_range(&seed, -50, W + 50);
		int y1 = tdp_range(&seed, -50, H + 50);
		uint32_t bits = tdp_rand(&seed), len = tdp_rand(&seed) % 33;
		uint32_t off = tdp_rand(&seed) % 64;

		pr_clear(t);
		TDP_CMD(t, RDC_OP_SET_DASH, bits, len | off << 8);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		rdc_ref_dash_line(x0, y0, x1, y1, bits, len, off, pr_plot,
				  pr_ref);
		pr_compare(t);
	}
}

static void test_arc(void **state)
{
	struct tdp *t = *state;
	uint32_t seed = 0xa4c, k;

	for (k = 0; k < 80; k++) {
		int cx = tdp_range(&seed, -20, W + 20);
		int cy = tdp_range(&seed, -20, H + 20);
		uint32_t rx = (uint32_t)tdp_range(&seed, 0, 150);
		uint32_t ry = (uint32_t)tdp_range(&seed, 0, 150);
		uint32_t s = tdp_rand(&seed) & 0xffff;
		uint32_t e = tdp_rand(&seed) & 0xffff, mode = k % 3;

		pr_clear(t);
		tdp_cmd(t, RDC_OP_ARC, mode, 3,
			(uint32_t[]){ RDC_XY(cx, cy), RDC_WH(rx, ry),
				      s | e << 16 });
		rdc_ref_arc(cx, cy, rx, ry, s, e, mode, pr_plot, pr_ref);
		pr_compare(t);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_convex),
		TDP_TEST(test_dash),
		TDP_TEST(test_arc),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
