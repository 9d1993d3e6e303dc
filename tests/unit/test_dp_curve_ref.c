// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * BEZIER, HERMITE and BSPLINE against exact evaluation (ref_curve.c): the
 * curve's points at the documented steps, computed as exact fractions and
 * rounded, joined by reference lines, must be the DP's pixels.  A point
 * within 1/256 pixel of a half may round either way (the DP's 32.32
 * forward differences err by less than 2^-9, docs/commands.md): the lines
 * that end on one only need to be within a pixel of the DP's, every other
 * line's pixels must be drawn exactly, and the DP may draw nothing else.
 */
#include "test_dp_common.h"
#include "ref_curve.h"
#include "rdc_regs.h"

#define W	   640
#define H	   480
#define CV_MAX_PTS 8
#define CV_CAP	   (CV_MAX_PTS * (RDC_CURVE_MAX_STEPS + 1))

/* reference pixels: of lines between exact points, of the other lines */
#define CV_EXACT 1
#define CV_NEAR	 2
static uint8_t want[W * H];
static uint8_t cv_kind;

static void cv_plot(void *ctx, int32_t x, int32_t y)
{
	(void)ctx;
	if (x >= 0 && x < W && y >= 0 && y < H)
		want[y * W + x] |= cv_kind;
}

static bool got_px(struct tdp *t, int32_t x, int32_t y)
{
	return tdp_get(t->vram, &t->dp.st.dst, x, y) != 0;
}

/* Is a DP pixel (dp) or a CV_NEAR reference pixel within 1 of (x, y)? */
static bool near_any(struct tdp *t, bool dp, int32_t x, int32_t y)
{
	int32_t i, j;

	for (j = y - 1; j <= y + 1; j++)
		for (i = x - 1; i <= x + 1; i++) {
			if (i < 0 || i >= W || j < 0 || j >= H)
				continue;
			if (dp ? got_px(t, i, j) : want[j * W + i] & CV_NEAR)
				return true;
		}
	return false;
}

/* Random curves of every kind, step counts chosen and given. */
static void test_curves_vs_exact(void **state)
{
	static struct rdc_ref_curve_pt pts[CV_CAP];
	struct tdp *t = *state;
	uint32_t seed = 0xcc0e, k, exact = 0, near = 0;

	for (k = 0; k < 600; k++) {
		static const uint32_t ops[] = { RDC_OP_BEZIER, RDC_OP_HERMITE,
						RDC_OP_BSPLINE };
		uint32_t op = ops[k % 3], n = 4, steps = 0, words[CV_MAX_PTS];
		int32_t xy[2 * CV_MAX_PTS];
		uint32_t np, i;
		int32_t x, y;

		if (op == RDC_OP_BSPLINE)
			n = (uint32_t)tdp_range(&seed, 4, CV_MAX_PTS);
		if (k % 4 == 1)
			steps = (uint32_t)tdp_range(&seed, 1, 255);
		else if (k % 4 == 3)
			steps = (uint32_t)tdp_range(&seed, 1, 6);
		for (i = 0; i < n; i++) {
			xy[2 * i] = tdp_range(&seed, -60, W + 60);
			xy[2 * i + 1] = tdp_range(&seed, -60, H + 60);
			if (op == RDC_OP_HERMITE && i >= 2) {
				/* tangents: vectors of up to 3 screens */
				xy[2 * i] = tdp_range(&seed, -2000, 2000);
				xy[2 * i + 1] = tdp_range(&seed, -1500, 1500);
			}
			words[i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
		}
		memset(t->vram, 0, (size_t)W * H * 4);
		memset(want, 0, sizeof(want));
		tdp_cmd(t, op, steps, n, words);
		tdp_drain(t);
		assert_int_equal(tdp_err(t), RDC_ERR_NONE);

		np = rdc_ref_curve_points(op, steps, xy, n, pts, CV_CAP);
		assert_true(np >= 1 && np <= CV_CAP);
		cv_kind = pts[0].near_half ? CV_NEAR : CV_EXACT;
		if (np == 1)
			cv_plot(NULL, pts[0].x, pts[0].y);
		for (i = 0; i + 1 < np; i++) {
			cv_kind = pts[i].near_half || pts[i + 1].near_half ?
					  CV_NEAR :
					  CV_EXACT;
			rdc_ref_line(pts[i].x, pts[i].y, pts[i + 1].x,
				     pts[i + 1].y, cv_plot, NULL);
		}
		for (y = 0; y < H; y++)
			for (x = 0; x < W; x++) {
				bool g = got_px(t, x, y);
				uint8_t w = want[y * W + x];
				bool ok =
					(w & CV_EXACT) ?
						g :
					(w & CV_NEAR) ?
						g || near_any(t, true, x, y) :
						!g || near_any(t, false, x, y);

				if (!ok)
					fail_msg("op %#x steps %u curve %u: "
						 "pixel "
						 "%d,%d %s",
						 op, steps, k, x, y,
						 w ? "missing" : "extra");
				exact += (w & CV_EXACT) != 0;
				near += w == CV_NEAR;
			}
	}
	print_message("curve pixels compared exactly %u, within a pixel %u\n",
		      exact, near);
	/* most lines join points far from a half */
	assert_true(exact > 10 * near);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_curves_vs_exact),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
