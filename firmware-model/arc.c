// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * ARC: arcs of circles and ellipses between two angles, as an outline or
 * filled as a pie slice or a chord segment.
 *
 * Angles are 1/65536 turn, counter-clockwise from +x with y up on the
 * screen, and eccentric: angle a names the ellipse point
 * (cx + rx cos a, cy - ry sin a), so for a circle it is the plain angle.
 * A pixel belongs to the sector when its centre lies between the rays
 * from the centre through the start and end points (both rays included).
 * The outline is ELLIPSE's own outline restricted to the sector, the pie
 * FILL_ELLIPSE's pixels restricted to it, the chord FILL_ELLIPSE's pixels
 * on the arc's side of the line through the two end points (that line
 * included).  Everything is integer: sines from a quarter-wave table.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define ARC_TURN    65536u
#define ARC_HALF    (ARC_TURN / 2)
#define ARC_QUARTER (ARC_TURN / 4)
#define SIN_BITS    8 /* log2 of the table's steps per quarter turn */
#define SIN_STEP    (ARC_QUARTER >> SIN_BITS)
#define SIN_ONE	    65536 /* 1.0 in the table */
/*
 * The sector tests work with unit vectors of 14 fractional bits, so a radius (<
 * 2^15) times a vector and times a pixel offset stay far below 2^63 even in the
 * chord test's differences.
 */
#define ARC_VEC_SHIFT 2
#define ARC_PIX_ONE   (SIN_ONE >> ARC_VEC_SHIFT) /* a pixel, same scale */

/* sin(i / 1024 turn) * 65536, i = 0..256: a quarter wave. */
static const int32_t sin_tab[(1 << SIN_BITS) + 1] = {
	0,     402,   804,   1206,  1608,  2010,  2412,	 2814,	3216,  3617,
	4019,  4420,  4821,  5222,  5623,  6023,  6424,	 6824,	7224,  7623,
	8022,  8421,  8820,  9218,  9616,  10014, 10411, 10808, 11204, 11600,
	11996, 12391, 12785, 13180, 13573, 13966, 14359, 14751, 15143, 15534,
	15924, 16314, 16703, 17091, 17479, 17867, 18253, 18639, 19024, 19409,
	19792, 20175, 20557, 20939, 21320, 21699, 22078, 22457, 22834, 23210,
	23586, 23961, 24335, 24708, 25080, 25451, 25821, 26190, 26558, 26925,
	27291, 27656, 28020, 28383, 28745, 29106, 29466, 29824, 30182, 30538,
	30893, 31248, 31600, 31952, 32303, 32652, 33000, 33347, 33692, 34037,
	34380, 34721, 35062, 35401, 35738, 36075, 36410, 36744, 37076, 37407,
	37736, 38064, 38391, 38716, 39040, 39362, 39683, 40002, 40320, 40636,
	40951, 41264, 41576, 41886, 42194, 42501, 42806, 43110, 43412, 43713,
	44011, 44308, 44604, 44898, 45190, 45480, 45769, 46056, 46341, 46624,
	46906, 47186, 47464, 47741, 48015, 48288, 48559, 48828, 49095, 49361,
	49624, 49886, 50146, 50404, 50660, 50914, 51166, 51417, 51665, 51911,
	52156, 52398, 52639, 52878, 53114, 53349, 53581, 53812, 54040, 54267,
	54491, 54714, 54934, 55152, 55368, 55582, 55794, 56004, 56212, 56418,
	56621, 56823, 57022, 57219, 57414, 57607, 57798, 57986, 58172, 58356,
	58538, 58718, 58896, 59071, 59244, 59415, 59583, 59750, 59914, 60075,
	60235, 60392, 60547, 60700, 60851, 60999, 61145, 61288, 61429, 61568,
	61705, 61839, 61971, 62101, 62228, 62353, 62476, 62596, 62714, 62830,
	62943, 63054, 63162, 63268, 63372, 63473, 63572, 63668, 63763, 63854,
	63944, 64031, 64115, 64197, 64277, 64354, 64429, 64501, 64571, 64639,
	64704, 64766, 64827, 64884, 64940, 64993, 65043, 65091, 65137, 65180,
	65220, 65259, 65294, 65328, 65358, 65387, 65413, 65436, 65457, 65476,
	65492, 65505, 65516, 65525, 65531, 65535, 65536,
};

/* sin of a 1/65536-turn angle in 16.16, interpolated from the table. */
int32_t dp_sin(uint32_t a)
{
	uint32_t q = (a % ARC_TURN) / ARC_QUARTER, r = a % ARC_QUARTER, i, f;
	int32_t v;

	if (q & 1)
		r = ARC_QUARTER - r; /* second and fourth quarters mirror */
	i = r / SIN_STEP;
	f = r % SIN_STEP;
	v = sin_tab[i];
	if (f)
		v += (int32_t)(((int64_t)(sin_tab[i + 1] - sin_tab[i]) * f +
				SIN_STEP / 2) /
			       SIN_STEP);
	return q >= 2 ? -v : v;
}

int32_t dp_cos(uint32_t a)
{
	return dp_sin(a + ARC_QUARTER);
}

struct arc_ctx {
	struct rdc_dp *dp;
	uint32_t mode;
	bool full, wide; /* full turn; sweep over half a turn */
	bool narrow;	 /* end points rounded onto one ray: the sector is it */
	int64_t sx, sy, ex, ey; /* end points, y up, 14 fractional bits */
	int32_t cx, cy;
};

static int64_t arc_cross(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
	return ax * by - ay * bx;
}

/* Is the pixel at offset (dx, dy) from the centre (y down) drawn? */
static bool arc_in(const struct arc_ctx *ac, int32_t dx, int32_t dy)
{
	int64_t px = (int64_t)dx * ARC_PIX_ONE;
	int64_t py = -(int64_t)dy * ARC_PIX_ONE;
	bool a, b;

	if (ac->full)
		return true;
	if (ac->mode == RDC_ARC_CHORD)
		return arc_cross(ac->ex - ac->sx, ac->ey - ac->sy, px - ac->sx,
				 py - ac->sy) <= 0;
	a = arc_cross(ac->sx, ac->sy, px, py) >= 0;
	b = arc_cross(px, py, ac->ex, ac->ey) >= 0;
	if (ac->wide)
		return a || b;
	/*
	 * two half-planes meet in the sector, and in the opposite ray too when
	 * the end points' directions coincide
	 */
	if (ac->narrow && ac->sx * px + ac->sy * py < 0)
		return false;
	return a && b;
}

/* Pixels xa..xb of row cy + dy that pass the test, as spans. */
static void arc_run(const struct arc_ctx *ac, int32_t dy, int32_t xa,
		    int32_t xb)
{
	struct rdc_rect c = rdc_dp_eff_clip(ac->dp);
	int32_t x, start = 0;
	bool open = false;

	if (ac->cy + dy < c.y0 || ac->cy + dy >= c.y1)
		return;
	xa = RDC_MAX(xa, c.x0 - ac->cx);
	xb = RDC_MIN(xb, c.x1 - 1 - ac->cx);
	for (x = xa; x <= xb + 1; x++) {
		bool in = x <= xb && arc_in(ac, x, dy);

		if (in && !open) {
			start = x;
			open = true;
		} else if (!in && open) {
			/* fills take the pattern, the outline is FG */
			if (ac->mode == RDC_ARC_OUTLINE)
				rdc_dp_span(ac->dp, ac->cy + dy, ac->cx + start,
					    ac->cx + x - 1);
			else
				dp_fill_span(ac->dp, ac->cx + start,
					     ac->cx + x - 1, ac->cy + dy);
			open = false;
		}
	}
}

/* Row t of the symmetric shape, as shape.c's ELLIPSE emits it. */
static void arc_row(const struct arc_ctx *ac, uint32_t t, uint32_t amin,
		    uint32_t amax, bool fill)
{
	int32_t rows[2] = { -(int32_t)t, (int32_t)t };
	int32_t lo = (int32_t)amin, hi = (int32_t)amax;
	unsigned int k, n = t ? 2 : 1;

	for (k = 0; k < n; k++) {
		if (fill || !amin) {
			arc_run(ac, rows[k], -hi, hi);
		} else {
			arc_run(ac, rows[k], -hi, -lo);
			arc_run(ac, rows[k], lo, hi);
		}
	}
}

void dp_arc(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
	    uint32_t start, uint32_t end, uint32_t mode)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	uint32_t sweep = (end - start) % ARC_TURN;
	struct arc_ctx ac = {
		.dp = dp,
		.mode = mode,
		.full = sweep == 0,
		.wide = sweep > ARC_HALF,
		.cx = cx,
		.cy = cy,
	};
	struct dp_ellipse e;
	uint32_t t, amin, amax;

	if (!rx || !ry || c.x0 >= c.x1 || c.y0 >= c.y1)
		return;
	if (cx + (int32_t)rx < c.x0 || cx - (int32_t)rx >= c.x1 ||
	    cy + (int32_t)ry < c.y0 || cy - (int32_t)ry >= c.y1)
		return;
	/* exact division: the shift would round negative values down */
	ac.sx = (int64_t)rx * dp_cos(start) / (1 << ARC_VEC_SHIFT);
	ac.sy = (int64_t)ry * dp_sin(start) / (1 << ARC_VEC_SHIFT);
	ac.ex = (int64_t)rx * dp_cos(end) / (1 << ARC_VEC_SHIFT);
	ac.ey = (int64_t)ry * dp_sin(end) / (1 << ARC_VEC_SHIFT);
	ac.narrow = sweep < ARC_HALF &&
		    arc_cross(ac.sx, ac.sy, ac.ex, ac.ey) <= 0;
	dp_ellipse_begin(&e, rx, ry);
	while (dp_ellipse_row(&e, &t, &amin, &amax))
		arc_row(&ac, t, amin, amax, mode != RDC_ARC_OUTLINE);
}

uint32_t dp_cmd_arc(struct rdc_dp *dp, uint32_t fl, const uint32_t *a)
{
	int32_t x = RDC_X(a[0]), y = RDC_Y(a[0]);
	uint32_t rx = RDC_W(a[1]), ry = RDC_H(a[1]);

	if (fl > RDC_ARC_CHORD)
		return RDC_ERR_ARG;
	if (rx > RDC_SIZE_MAX || ry > RDC_SIZE_MAX || !dp_xform(dp, &x, &y) ||
	    !dp_xform_size(dp, &rx, &ry))
		return RDC_ERR_RANGE;
	dp_arc(dp, x, y, rx, ry, FIELD_GET(RDC_ARC_START, a[2]),
	       FIELD_GET(RDC_ARC_END, a[2]), fl);
	return RDC_ERR_NONE;
}
