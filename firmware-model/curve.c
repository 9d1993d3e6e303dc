// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * BEZIER, HERMITE and BSPLINE: cubic curves traced by forward differencing
 * and drawn as a polyline through the stroker, so the pen and the dash
 * apply and a dash runs on from one curve step to the next.
 *
 * Each curve (each B-spline segment) is a cubic a t^3 + b t^2 + c t + d
 * with integer coefficients over a common divisor (6 for the B-spline).
 * With N steps the differences are kept in 32.32 fixed point; the error
 * of the third difference grows like N^3 / 6 * 2^-32, under a hundredth
 * of a pixel at the step cap.  Bezier and Hermite curves end exactly on
 * their end points, and a B-spline segment exactly on its join
 * (q1 + 4 q2 + q3) / 6 rounded, whatever the rounding on the way.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define CV_FRAC 32
#define CV_ONE	((int64_t)1 << CV_FRAC)
#define CV_HALF (CV_ONE / 2)
/* Chosen step counts: one step per this many pixels of control polygon */
#define CV_PX_PER_STEP 4

struct cv_poly {
	int64_t a, b, c, d; /* numerators */
	int64_t div;
};

static int32_t cv_abs(int32_t v)
{
	return v < 0 ? -v : v;
}

/* Length of a leg, in the midpoint line's steps. */
static int64_t cv_leg(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	return RDC_MAX(cv_abs(x1 - x0), cv_abs(y1 - y0));
}

/* Length of the control polygon x[0..3], y[0..3]. */
static int64_t cv_polygon(const int32_t *x, const int32_t *y)
{
	return cv_leg(x[0], y[0], x[1], y[1]) + cv_leg(x[1], y[1], x[2], y[2]) +
	       cv_leg(x[2], y[2], x[3], y[3]);
}

/*
 * Steps for a control polygon of length len: from the flags, else one per
 * CV_PX_PER_STEP pixels, at least 1 and at most the cap.
 */
static uint32_t cv_steps(uint32_t fl, int64_t len)
{
	int64_t n;

	if (fl)
		return fl;
	n = (len + CV_PX_PER_STEP - 1) / CV_PX_PER_STEP;
	return (uint32_t)RDC_MAX((int64_t)1,
				 RDC_MIN(n, (int64_t)RDC_CURVE_MAX_STEPS));
}

struct cv_trace {
	struct dp_stroke sk;
	bool any;
	int32_t lx, ly;
};

static void cv_emit(struct cv_trace *tr, int32_t x, int32_t y)
{
	if (tr->any && x == tr->lx && y == tr->ly)
		return;
	dp_stroke_point(&tr->sk, x, y);
	tr->any = true;
	tr->lx = x;
	tr->ly = y;
}

/*
 * Trace one cubic per axis over n steps, emitting steps skip..n-1 by
 * forward differencing and step n as (ex, ey) exactly.
 */
static void cv_trace_poly(struct cv_trace *tr, const struct cv_poly *px,
			  const struct cv_poly *py, uint32_t n, uint32_t skip,
			  int32_t ex, int32_t ey)
{
	const struct cv_poly *p[2] = { px, py };
	int64_t f[2], d1[2], d2[2], d3[2];
	int64_t n1 = n, n2 = n1 * n1, n3 = n2 * n1;
	uint32_t i, k;

	for (k = 0; k < 2; k++) {
		int64_t a3 = dp_div_round(p[k]->a * CV_ONE, n3 * p[k]->div);
		int64_t b2 = dp_div_round(p[k]->b * CV_ONE, n2 * p[k]->div);
		int64_t c1 = dp_div_round(p[k]->c * CV_ONE, n1 * p[k]->div);

		f[k] = dp_div_round(p[k]->d * CV_ONE, p[k]->div);
		d1[k] = a3 + b2 + c1;
		d2[k] = 6 * a3 + 2 * b2;
		d3[k] = 6 * a3;
	}
	for (i = 0; i < n; i++) {
		if (i >= skip)
			cv_emit(tr, (int32_t)((f[0] + CV_HALF) >> CV_FRAC),
				(int32_t)((f[1] + CV_HALF) >> CV_FRAC));
		for (k = 0; k < 2; k++) {
			f[k] += d1[k];
			d1[k] += d2[k];
			d2[k] += d3[k];
		}
	}
	cv_emit(tr, ex, ey);
}

static void cv_bezier(struct cv_poly *p, int64_t p0, int64_t p1, int64_t p2,
		      int64_t p3)
{
	p->a = -p0 + 3 * p1 - 3 * p2 + p3;
	p->b = 3 * p0 - 6 * p1 + 3 * p2;
	p->c = -3 * p0 + 3 * p1;
	p->d = p0;
	p->div = 1;
}

static void cv_hermite(struct cv_poly *p, int64_t p0, int64_t p1, int64_t t0,
		       int64_t t1)
{
	p->a = 2 * p0 - 2 * p1 + t0 + t1;
	p->b = -3 * p0 + 3 * p1 - 2 * t0 - t1;
	p->c = t0;
	p->d = p0;
	p->div = 1;
}

static void cv_bspline(struct cv_poly *p, int64_t q0, int64_t q1, int64_t q2,
		       int64_t q3)
{
	p->a = -q0 + 3 * q1 - 3 * q2 + q3;
	p->b = 3 * q0 - 6 * q1 + 3 * q2;
	p->c = -3 * q0 + 3 * q2;
	p->d = q0 + 4 * q1 + q2;
	p->div = 6;
}

uint32_t dp_cmd_curve(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		      const uint32_t *a)
{
	int32_t x[4], y[4];
	struct cv_poly px, py;
	struct cv_trace tr;
	int64_t plen;
	uint32_t i, k, n, np = op == RDC_OP_HERMITE ? 2 : len;

	if (op == RDC_OP_BSPLINE ? len < 4 : len != 4)
		return RDC_ERR_LENGTH;
	/*
	 * every control point must transform; HERMITE's tangents are vectors
	 * and take the linear part only
	 */
	for (i = 0; i < len; i++) {
		int32_t vx = RDC_X(a[i]), vy = RDC_Y(a[i]);

		if (i < np ? !dp_xform(dp, &vx, &vy) :
			     !dp_xform_vec(dp, &vx, &vy))
			return RDC_ERR_RANGE;
	}
	dp_stroke_begin(&tr.sk, dp);
	tr.any = false;
	if (op != RDC_OP_BSPLINE) {
		for (k = 0; k < 4; k++) {
			x[k] = RDC_X(a[k]);
			y[k] = RDC_Y(a[k]);
			if (k < np)
				dp_xform(dp, &x[k], &y[k]);
			else
				dp_xform_vec(dp, &x[k], &y[k]);
		}
		if (op == RDC_OP_BEZIER) {
			cv_bezier(&px, x[0], x[1], x[2], x[3]);
			cv_bezier(&py, y[0], y[1], y[2], y[3]);
			n = cv_steps(fl, cv_polygon(x, y));
			cv_trace_poly(&tr, &px, &py, n, 0, x[3], y[3]);
		} else {
			/* the Bezier legs of the same curve: t0/3, t1/3 */
			cv_hermite(&px, x[0], x[1], x[2], x[3]);
			cv_hermite(&py, y[0], y[1], y[2], y[3]);
			plen = cv_leg(x[0], y[0], x[1], y[1]) +
			       (cv_leg(0, 0, x[2], y[2]) +
				cv_leg(0, 0, x[3], y[3])) /
				       3;
			n = cv_steps(fl, plen);
			cv_trace_poly(&tr, &px, &py, n, 0, x[1], y[1]);
		}
		dp_stroke_end(&tr.sk, false);
		return RDC_ERR_NONE;
	}
	/* B-spline: a window of four points slides along the list */
	for (k = 0; k < 3; k++) {
		x[k + 1] = RDC_X(a[k]);
		y[k + 1] = RDC_Y(a[k]);
		dp_xform(dp, &x[k + 1], &y[k + 1]);
	}
	for (i = 3; i < len; i++) {
		int32_t ex, ey;

		for (k = 0; k < 3; k++) {
			x[k] = x[k + 1];
			y[k] = y[k + 1];
		}
		x[3] = RDC_X(a[i]);
		y[3] = RDC_Y(a[i]);
		dp_xform(dp, &x[3], &y[3]);
		cv_bspline(&px, x[0], x[1], x[2], x[3]);
		cv_bspline(&py, y[0], y[1], y[2], y[3]);
		n = cv_steps(fl, cv_polygon(x, y));
		ex = (int32_t)dp_div_round(
			(int64_t)x[1] + 4 * (int64_t)x[2] + x[3], 6);
		ey = (int32_t)dp_div_round(
			(int64_t)y[1] + 4 * (int64_t)y[2] + y[3], 6);
		/* the first point of later segments is the previous end */
		cv_trace_poly(&tr, &px, &py, n, i > 3, ex, ey);
	}
	dp_stroke_end(&tr.sk, false);
	return RDC_ERR_NONE;
}
