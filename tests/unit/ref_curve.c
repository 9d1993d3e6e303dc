// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Reference curve points (see ref_curve.h): every step i of n is the
 * curve at t = i / n, a fraction num / den of exact integers, rounded.
 */
#include "ref_curve.h"
#include "rdc_regs.h"

#define RC_CHOSEN_PX 4 /* docs: one step per 4 pixels of control polygon */

static int64_t rc_abs(int64_t v)
{
	return v < 0 ? -v : v;
}

/* max(|dx|, |dy|): a leg's length in midpoint-line steps */
static int64_t rc_leg(int64_t dx, int64_t dy)
{
	return RDC_MAX(rc_abs(dx), rc_abs(dy));
}

static uint32_t rc_steps(uint32_t flags, int64_t len)
{
	int64_t n = (len + RC_CHOSEN_PX - 1) / RC_CHOSEN_PX;

	if (flags)
		return flags;
	return (uint32_t)RDC_MIN(RDC_MAX(n, 1), (int64_t)RDC_CURVE_MAX_STEPS);
}

/* num / den (den > 0) to the nearest integer, halves up; near a half? */
static int32_t rc_round(int64_t num, int64_t den, bool *near)
{
	/* floor((2 num + den) / (2 den)) */
	int64_t a = 2 * num + den, b = 2 * den, q = a / b;
	/* distance of num / den from the half below q + 1/2: (a - q b) / b */
	int64_t r;

	if (a % b && a < 0)
		q--;
	r = a - q * b; /* 0 <= r < b: num / den = q - 1/2 + r / b */
	/* within 1/256 of q - 1/2 or of q + 1/2 */
	if (256 * r < b || 256 * (b - r) <= b)
		*near = true;
	return (int32_t)q;
}

struct rc_out {
	struct rdc_ref_curve_pt *out;
	uint32_t cap, n;
};

static void rc_emit(struct rc_out *o, int64_t nx, int64_t ny, int64_t den)
{
	struct rdc_ref_curve_pt p = { 0, 0, false };

	p.x = rc_round(nx, den, &p.near_half);
	p.y = rc_round(ny, den, &p.near_half);
	if (o->n) {
		struct rdc_ref_curve_pt *l = &o->out[RDC_MIN(o->n, o->cap) - 1];

		if (o->n <= o->cap && l->x == p.x && l->y == p.y) {
			l->near_half |= p.near_half;
			return;
		}
	}
	if (o->n < o->cap)
		o->out[o->n] = p;
	o->n++;
}

/* (n - i)^3 p0 + 3 i (n - i)^2 p1 + 3 i^2 (n - i) p2 + i^3 p3, over n^3 */
static int64_t rc_bezier(const int64_t *p, int64_t i, int64_t n)
{
	int64_t u = n - i;

	return u * u * u * p[0] + 3 * i * u * u * p[1] + 3 * i * i * u * p[2] +
	       i * i * i * p[3];
}

/* h00 p0 + h10 t0 + h01 p1 + h11 t1 at t = i / n, over n^3 */
static int64_t rc_hermite(const int64_t *p, int64_t i, int64_t n)
{
	int64_t i2 = i * i, i3 = i2 * i, n2 = n * n, n3 = n2 * n;

	return (2 * i3 - 3 * i2 * n + n3) * p[0] +
	       (-2 * i3 + 3 * i2 * n) * p[1] +
	       (i3 - 2 * i2 * n + i * n2) * p[2] + (i3 - i2 * n) * p[3];
}

/* the uniform cubic B-spline's basis at t = i / n, over 6 n^3 */
static int64_t rc_bspline(const int64_t *q, int64_t i, int64_t n)
{
	int64_t i2 = i * i, i3 = i2 * i, n2 = n * n, n3 = n2 * n, u = n - i;

	return u * u * u * q[0] + (3 * i3 - 6 * i2 * n + 4 * n3) * q[1] +
	       (-3 * i3 + 3 * i2 * n + 3 * i * n2 + n3) * q[2] + i3 * q[3];
}

uint32_t rdc_ref_curve_points(uint32_t op, uint32_t steps, const int32_t *xy,
			      uint32_t n, struct rdc_ref_curve_pt *out,
			      uint32_t cap)
{
	struct rc_out o = { out, cap, 0 };
	int64_t px[4], py[4], len, i, ns, k;

	if (op != RDC_OP_BSPLINE) {
		if (n != 4)
			return 0;
		for (k = 0; k < 4; k++) {
			px[k] = xy[2 * k];
			py[k] = xy[2 * k + 1];
		}
		if (op == RDC_OP_BEZIER)
			len = rc_leg(px[1] - px[0], py[1] - py[0]) +
			      rc_leg(px[2] - px[1], py[2] - py[1]) +
			      rc_leg(px[3] - px[2], py[3] - py[2]);
		else /* the equivalent Bezier's legs, the tangents' floored */
			len = rc_leg(px[1] - px[0], py[1] - py[0]) +
			      (rc_leg(px[2], py[2]) + rc_leg(px[3], py[3])) / 3;
		ns = rc_steps(steps, len);
		for (i = 0; i <= ns; i++) {
			if (op == RDC_OP_BEZIER)
				rc_emit(&o, rc_bezier(px, i, ns),
					rc_bezier(py, i, ns), ns * ns * ns);
			else
				rc_emit(&o, rc_hermite(px, i, ns),
					rc_hermite(py, i, ns), ns * ns * ns);
		}
		return o.n;
	}
	for (k = 0; k + 3 < n; k++) {
		uint32_t j;

		for (j = 0; j < 4; j++) {
			px[j] = xy[2 * (k + j)];
			py[j] = xy[2 * (k + j) + 1];
		}
		len = rc_leg(px[1] - px[0], py[1] - py[0]) +
		      rc_leg(px[2] - px[1], py[2] - py[1]) +
		      rc_leg(px[3] - px[2], py[3] - py[2]);
		ns = rc_steps(steps, len);
		/* a later segment starts where the previous one ended */
		for (i = k ? 1 : 0; i <= ns; i++) {
			bool end = i == ns;
			size_t before = o.n;

			rc_emit(&o, rc_bspline(px, i, ns),
				rc_bspline(py, i, ns), 6 * ns * ns * ns);
			/* the segment's end is rounded exactly by the DP too */
			if (end && o.n > before && o.n <= o.cap)
				o.out[o.n - 1].near_half = false;
		}
	}
	return o.n;
}
