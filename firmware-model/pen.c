// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pens and dashes: the stroker behind LINE, POLYLINE, POLYGON, RECT
 * outlines and the curves.
 *
 * Width 1 without a dash is the midpoint line of line.c, unchanged.  A
 * dash selects which steps of those same lines are drawn.  Wider pens
 * build each segment, cap and join as a convex piece (or a disk) in 24.8
 * fixed point and queue it; at the end of the stroke the queue is drawn
 * row by row as the union of its pieces' spans by pixel centres (a centre
 * exactly on an edge belongs to a piece when the edge is a left or top
 * one), so joins, caps and self-crossings write each pixel once.  A stroke
 * of more than RDC_DP_PEN_PIECES pieces is drawn in batches of that many;
 * only pieces of different batches may overlap.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define PEN_FRAC 8 /* fractional bits of the stroke geometry */
#define PEN_ONE	 (1 << PEN_FRAC)
/*
 * Miters longer than this many half-widths turn into bevels: with unit normals
 * n1, n2 the miter is h * sqrt(2 / (1 + n1.n2)), so a limit of 4 is 1 + n1.n2
 * >= 1/8.
 */
#define PEN_MITER_DIV 8

uint64_t dp_isqrt(uint64_t v)
{
	uint64_t r = 0, bit = (uint64_t)1 << 62;

	while (bit > v)
		bit >>= 2;
	while (bit) {
		if (v >= r + bit) {
			v -= r + bit;
			r = (r >> 1) + bit;
		} else {
			r >>= 1;
		}
		bit >>= 2;
	}
	return r;
}

/*
 * Row y of a convex polygon, by pixel centres: row y samples Y = y *
 * PEN_ONE; each edge counts for ya <= Y < yb (its top end in, its bottom
 * end out) and the row covers the pixels with xl <= X < xr between its
 * leftmost and rightmost crossing: the top-left rule, so two pieces
 * sharing an edge do not both take the pixels on it.  Returns the pixel
 * range [*xa, *xb), false when empty.
 */
static bool convex_row(const int64_t *vx, const int64_t *vy, unsigned int n,
		       int64_t y, int64_t *xa, int64_t *xb)
{
	int64_t sy = y * PEN_ONE, xl = 0, xr = 0;
	bool any = false;
	unsigned int i;

	for (i = 0; i < n; i++) {
		unsigned int a = i, b = (i + 1) % n, t;
		int64_t dy, x;

		if (vy[a] == vy[b])
			continue;
		if (vy[a] > vy[b]) {
			t = a;
			a = b;
			b = t;
		}
		if (sy < vy[a] || sy >= vy[b])
			continue;
		dy = vy[b] - vy[a];
		/*
		 * first pixel whose centre is at or right of the crossing:
		 * ceil(x_cross / PEN_ONE)
		 */
		x = dp_div_ceil(vx[a] * dy + (sy - vy[a]) * (vx[b] - vx[a]),
				dy * PEN_ONE);
		xl = any ? RDC_MIN(xl, x) : x;
		xr = any ? RDC_MAX(xr, x) : x;
		any = true;
	}
	*xa = xl;
	*xb = xr;
	return any && xl < xr;
}

/*
 * Row y of the disk of radius r at (px, py): the centres strictly inside it, as
 * [*xa, *xb).
 */
static bool disk_row(int64_t px, int64_t py, int64_t r, int64_t y, int64_t *xa,
		     int64_t *xb)
{
	int64_t dy = y * PEN_ONE - py, d = r * r - dy * dy, s;

	if (d <= 0)
		return false;
	s = (int64_t)dp_isqrt((uint64_t)d);
	if (s * s == d)
		s--; /* |dx| < sqrt(d) */
	*xa = dp_div_ceil(px - s, PEN_ONE);
	*xb = dp_div_floor(px + s, PEN_ONE) + 1;
	return *xa < *xb;
}

static bool piece_row(const struct rdc_pen_piece *pc, int64_t y, int64_t *xa,
		      int64_t *xb)
{
	if (!pc->n)
		return disk_row(pc->x[0], pc->y[0], pc->x[1], y, xa, xb);
	return convex_row(pc->x, pc->y, pc->n, y, xa, xb);
}

/*
 * Draw the buffered pieces as one union: row by row, their spans sorted
 * and merged, so a pixel covered by several pieces is written once.
 */
void dp_pen_flush(struct rdc_dp *dp)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	uint32_t n = dp->pen_npieces, i, k, m;
	int32_t y, y0 = 0, y1 = -1;

	dp->pen_npieces = 0;
	for (i = 0; i < n; i++) {
		const struct rdc_pen_piece *pc = &dp->pen_piece[i];

		if (pc->y0 > pc->y1)
			continue;
		y0 = y1 < y0 ? pc->y0 : RDC_MIN(y0, pc->y0);
		y1 = RDC_MAX(y1, pc->y1);
	}
	for (y = y0; y <= y1; y++) {
		int32_t(*sp)[2] = dp->pen_span;

		for (i = 0, m = 0; i < n; i++) {
			const struct rdc_pen_piece *pc = &dp->pen_piece[i];
			int64_t xa, xb;

			if (y < pc->y0 || y > pc->y1 ||
			    !piece_row(pc, y, &xa, &xb))
				continue;
			xa = RDC_MAX(xa, (int64_t)c.x0);
			xb = RDC_MIN(xb, (int64_t)c.x1);
			if (xa >= xb)
				continue;
			/* insertion by start: a few spans a row */
			for (k = m; k > 0 && sp[k - 1][0] > xa; k--) {
				sp[k][0] = sp[k - 1][0];
				sp[k][1] = sp[k - 1][1];
			}
			sp[k][0] = (int32_t)xa;
			sp[k][1] = (int32_t)xb;
			m++;
		}
		for (i = 0; i < m; i = k) {
			int32_t xa = sp[i][0], xb = sp[i][1];

			for (k = i + 1; k < m && sp[k][0] <= xb; k++)
				xb = RDC_MAX(xb, sp[k][1]);
			rdc_dp_span(dp, y, xa, xb - 1);
		}
	}
}

/*
 * Queue a piece; its rows are limited to the clip, so pieces off the surface
 * cost nothing.
 */
static struct rdc_pen_piece *pen_queue(struct rdc_dp *dp, int64_t ymin,
				       int64_t ymax)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	struct rdc_pen_piece *pc;
	int64_t y0 = RDC_MAX(ymin, (int64_t)c.y0);
	int64_t y1 = RDC_MIN(ymax, (int64_t)c.y1 - 1);

	if (y0 > y1 || c.x0 >= c.x1)
		return NULL;
	if (dp->pen_npieces == RDC_DP_PEN_PIECES)
		dp_pen_flush(dp);
	pc = &dp->pen_piece[dp->pen_npieces++];
	pc->y0 = (int32_t)y0;
	pc->y1 = (int32_t)y1;
	return pc;
}

void dp_pen_fill_convex(struct rdc_dp *dp, const struct pen_vec *v,
			unsigned int n)
{
	int64_t ymin = v[0].y, ymax = v[0].y;
	struct rdc_pen_piece *pc;
	unsigned int i;

	if (n < 3 || n > RDC_ARRAY_SIZE(pc->x))
		return;
	for (i = 1; i < n; i++) {
		ymin = RDC_MIN(ymin, v[i].y);
		ymax = RDC_MAX(ymax, v[i].y);
	}
	pc = pen_queue(dp, dp_div_ceil(ymin, PEN_ONE),
		       dp_div_ceil(ymax, PEN_ONE) - 1);
	if (!pc)
		return;
	pc->n = n;
	for (i = 0; i < n; i++) {
		pc->x[i] = v[i].x;
		pc->y[i] = v[i].y;
	}
}

/* Disk of radius r (24.8) at p. */
static void pen_disk(struct rdc_dp *dp, struct pen_vec p, int64_t r)
{
	struct rdc_pen_piece *pc = pen_queue(dp, dp_div_floor(p.y - r, PEN_ONE),
					     dp_div_ceil(p.y + r, PEN_ONE));

	if (!pc)
		return;
	pc->n = 0;
	pc->x[0] = p.x;
	pc->y[0] = p.y;
	pc->x[1] = r;
}

static int64_t pen_half(const struct rdc_dp *dp)
{
	return (int64_t)dp->st.pen_width * PEN_ONE / 2;
}

/* Normal (nx, ny) and direction (ex, ey) of a -> b, each h long. */
static void pen_axes(struct pen_vec a, struct pen_vec b, int64_t h,
		     struct pen_vec *nrm, struct pen_vec *dir)
{
	int64_t dx = b.x - a.x, dy = b.y - a.y;
	/*
	 * |d| in 24.8 units; the operands are below 2^25 so the square fits 64
	 * bits with room
	 */
	int64_t len = (int64_t)dp_isqrt((uint64_t)(dx * dx + dy * dy));

	if (!len)
		len = 1;
	nrm->x = dp_div_round(-dy * h, len);
	nrm->y = dp_div_round(dx * h, len);
	dir->x = dp_div_round(dx * h, len);
	dir->y = dp_div_round(dy * h, len);
}

static struct pen_vec pt_add(struct pen_vec a, struct pen_vec b, int s)
{
	struct pen_vec r = { a.x + s * b.x, a.y + s * b.y };

	return r;
}

/*
 * A cap at p for a stroke leaving p in direction -dir (dir points into the
 * segment's outside).
 */
static void pen_cap(struct rdc_dp *dp, struct pen_vec p, struct pen_vec nrm,
		    struct pen_vec dir)
{
	struct pen_vec q[4];

	switch (dp->st.pen_cap) {
	case RDC_CAP_ROUND:
		pen_disk(dp, p, pen_half(dp));
		break;
	case RDC_CAP_SQUARE:
		q[0] = pt_add(p, nrm, 1);
		q[1] = pt_add(q[0], dir, 1);
		q[3] = pt_add(p, nrm, -1);
		q[2] = pt_add(q[3], dir, 1);
		dp_pen_fill_convex(dp, q, 4);
		break;
	default:
		break;
	}
}

/* The body of a -> b: a rectangle of the pen's width, butt ends. */
static void pen_body(struct rdc_dp *dp, struct pen_vec a, struct pen_vec b,
		     struct pen_vec nrm)
{
	struct pen_vec q[4] = { pt_add(a, nrm, 1), pt_add(b, nrm, 1),
				pt_add(b, nrm, -1), pt_add(a, nrm, -1) };

	dp_pen_fill_convex(dp, q, 4);
}

/*
 * A dot where a stroke has no length: round and square pens leave their cap
 * shape, butt pens nothing.
 */
static void pen_dot(struct rdc_dp *dp, struct pen_vec p)
{
	struct pen_vec nrm = { 0, pen_half(dp) }, dir = { pen_half(dp), 0 };

	if (dp->st.pen_cap == RDC_CAP_SQUARE) {
		struct pen_vec q[4] = {
			pt_add(pt_add(p, nrm, 1), dir, -1),
			pt_add(pt_add(p, nrm, 1), dir, 1),
			pt_add(pt_add(p, nrm, -1), dir, 1),
			pt_add(pt_add(p, nrm, -1), dir, -1),
		};

		dp_pen_fill_convex(dp, q, 4);
	} else if (dp->st.pen_cap == RDC_CAP_ROUND) {
		pen_disk(dp, p, pen_half(dp));
	}
}

/* A capped piece a -> b (a whole open line, or one dash). */
static void pen_piece(struct rdc_dp *dp, struct pen_vec a, struct pen_vec b)
{
	struct pen_vec nrm, dir;

	if (a.x == b.x && a.y == b.y) {
		pen_dot(dp, a);
		return;
	}
	pen_axes(a, b, pen_half(dp), &nrm, &dir);
	pen_body(dp, a, b, nrm);
	pen_cap(dp, a, nrm, pt_add((struct pen_vec){ 0, 0 }, dir, -1));
	pen_cap(dp, b, nrm, dir);
}

/*
 * The join at v between a segment with normal n1 and one with n2, both h long;
 * turn = cross(d1, d2) tells the outer side.
 */
static void pen_join(struct rdc_dp *dp, struct pen_vec v, struct pen_vec n1,
		     struct pen_vec n2, int64_t turn)
{
	int64_t h = pen_half(dp), h2 = h * h, dot = n1.x * n2.x + n1.y * n2.y;
	int s = turn > 0 ? -1 : 1;
	struct pen_vec q[4];

	if (dp->st.pen_join == RDC_JOIN_ROUND) {
		pen_disk(dp, v, h);
		return;
	}
	if (!turn && dot > 0)
		return; /* straight on */
	q[0] = v;
	q[1] = pt_add(v, n1, s);
	if (dp->st.pen_join == RDC_JOIN_MITER && turn &&
	    (h2 + dot) * PEN_MITER_DIV >= h2) {
		q[2].x = v.x + s * dp_div_round((n1.x + n2.x) * h2, h2 + dot);
		q[2].y = v.y + s * dp_div_round((n1.y + n2.y) * h2, h2 + dot);
		q[3] = pt_add(v, n2, s);
		dp_pen_fill_convex(dp, q, 4);
		return;
	}
	q[2] = pt_add(v, n2, s);
	dp_pen_fill_convex(dp, q, 3);
}

static bool dash_on(const struct rdc_dp *dp, int64_t g)
{
	const struct rdc_dp_state *st = &dp->st;

	return (st->dash_bits >>
		((uint64_t)(g + st->dash_offset) % st->dash_len)) &
	       1;
}

static struct pen_vec pen_at(struct pen_vec a, struct pen_vec b, int64_t i,
			     int64_t n)
{
	struct pen_vec r = {
		a.x + dp_div_round((b.x - a.x) * i, n),
		a.y + dp_div_round((b.y - a.y) * i, n),
	};

	return r;
}

static struct pen_vec pen_pixel(int32_t x, int32_t y)
{
	struct pen_vec r = { (int64_t)x * PEN_ONE, (int64_t)y * PEN_ONE };

	return r;
}

/*
 * Draw one segment of a stroke.  Steps count along the major axis as for
 * the midpoint line: [first, last] of 0..n, dash index g = base + step.
 */
static void seg_draw(struct dp_stroke *sk, int32_t x0, int32_t y0, int32_t x1,
		     int32_t y1, bool skip_first, bool skip_last)
{
	struct rdc_dp *dp = sk->dp;
	int64_t adx = x1 > x0 ? (int64_t)x1 - x0 : (int64_t)x0 - x1;
	int64_t ady = y1 > y0 ? (int64_t)y1 - y0 : (int64_t)y0 - y1;
	int64_t n = RDC_MAX(adx, ady), first = skip_first ? 1 : 0;
	int64_t last = n - (skip_last && !sk->thick ? 1 : 0), i, j;

	if (!sk->dashed) {
		rdc_dp_line(dp, x0, y0, x1, y1, skip_first, skip_last);
		sk->base += n;
		return;
	}
	for (i = first; i <= last; i = j) {
		bool on = dash_on(dp, sk->base + i);

		for (j = i + 1; j <= last && dash_on(dp, sk->base + j) == on;
		     j++)
			;
		if (!on)
			continue;
		if (!sk->thick) {
			rdc_dp_line_steps(dp, x0, y0, x1, y1, i, j - 1);
		} else {
			struct pen_vec a = pen_pixel(x0, y0);
			struct pen_vec b = pen_pixel(x1, y1);

			/*
			 * A dash running on through the vertex starts at it,
			 * not one step past it.
			 */
			int64_t s = i == 1 && skip_first &&
						    dash_on(dp, sk->base) ?
					    0 :
					    i;

			if (!n)
				pen_dot(dp, a);
			else
				pen_piece(dp, pen_at(a, b, s, n),
					  pen_at(a, b, RDC_MIN(j, n), n));
		}
	}
	sk->base += n;
}

void dp_stroke_begin(struct dp_stroke *sk, struct rdc_dp *dp)
{
	rdc_memset(sk, 0, sizeof(*sk));
	sk->dp = dp;
	sk->thick = dp->st.pen_width > 1;
	sk->dashed = dp->st.dash_len > 0;
}

/* Thick, undashed: bodies, and joins as each vertex is passed. */
static void thick_point(struct dp_stroke *sk, int32_t x, int32_t y)
{
	struct pen_vec a = pen_pixel(sk->px, sk->py), b = pen_pixel(x, y);
	struct pen_vec nrm, dir;

	pen_axes(a, b, pen_half(sk->dp), &nrm, &dir);
	pen_body(sk->dp, a, b, nrm);
	if (sk->segs) {
		int64_t turn = (int64_t)sk->ldx * (y - sk->py) -
			       (int64_t)sk->ldy * (x - sk->px);

		pen_join(sk->dp, a, sk->lnrm, nrm, turn);
	} else {
		sk->fnrm = nrm;
		sk->fdir = dir;
		sk->fdx = x - sk->px;
		sk->fdy = y - sk->py;
	}
	sk->lnrm = nrm;
	sk->ldir = dir;
	sk->ldx = x - sk->px;
	sk->ldy = y - sk->py;
	sk->segs++;
}

void dp_stroke_point(struct dp_stroke *sk, int32_t x, int32_t y)
{
	if (!sk->count) {
		sk->x0 = x;
		sk->y0 = y;
	} else if (sk->thick && !sk->dashed) {
		if (x != sk->px || y != sk->py)
			thick_point(sk, x, y);
	} else {
		/*
		 * Width 1 draws a segment once the next point shows it is not
		 * the closing one; dashed thick segments likewise.
		 */
		if (sk->pending)
			seg_draw(sk, sk->qx, sk->qy, sk->px, sk->py,
				 sk->count > 2, false);
		sk->qx = sk->px;
		sk->qy = sk->py;
		sk->pending = true;
	}
	sk->px = x;
	sk->py = y;
	sk->count++;
}

/* The end of a stroke: draw, then flush the queued pieces. */
static void stroke_finish(struct dp_stroke *sk, bool closed)
{
	struct rdc_dp *dp = sk->dp;

	if (!sk->count)
		return;
	if (!sk->thick || sk->dashed) {
		if (sk->pending)
			seg_draw(sk, sk->qx, sk->qy, sk->px, sk->py,
				 sk->count > 2, closed);
		else if (sk->thick)
			pen_dot(dp, pen_pixel(sk->px, sk->py));
		else if (!sk->dashed || dash_on(dp, 0))
			rdc_dp_pixel(dp, sk->px, sk->py);
		return;
	}
	if (!sk->segs) {
		pen_dot(dp, pen_pixel(sk->px, sk->py));
		return;
	}
	if (closed && sk->segs > 1) {
		int64_t turn =
			(int64_t)sk->ldx * sk->fdy - (int64_t)sk->ldy * sk->fdx;

		pen_join(dp, pen_pixel(sk->x0, sk->y0), sk->lnrm, sk->fnrm,
			 turn);
		return;
	}
	pen_cap(dp, pen_pixel(sk->x0, sk->y0), sk->fnrm,
		pt_add((struct pen_vec){ 0, 0 }, sk->fdir, -1));
	pen_cap(dp, pen_pixel(sk->px, sk->py), sk->lnrm, sk->ldir);
}

uint32_t dp_cmd_set_pen(struct rdc_dp *dp, uint32_t v)
{
	uint32_t w = v & RDC_PEN_WIDTH, cap = FIELD_GET(RDC_PEN_CAP, v);
	uint32_t join = FIELD_GET(RDC_PEN_JOIN, v);

	if (w < 1 || w > RDC_PEN_MAX_WIDTH || cap > RDC_CAP_SQUARE ||
	    join > RDC_JOIN_BEVEL ||
	    (v & ~(RDC_PEN_WIDTH | RDC_PEN_CAP | RDC_PEN_JOIN)))
		return RDC_ERR_ARG;
	dp->st.pen_width = w;
	dp->st.pen_cap = cap;
	dp->st.pen_join = join;
	return RDC_ERR_NONE;
}

uint32_t dp_cmd_set_dash(struct rdc_dp *dp, uint32_t bits, uint32_t v)
{
	uint32_t len = FIELD_GET(RDC_DASH_LEN, v);

	if (len > RDC_DASH_MAX_LEN || (v & ~(RDC_DASH_LEN | RDC_DASH_OFFSET)))
		return RDC_ERR_ARG;
	dp->st.dash_bits = bits;
	dp->st.dash_len = len;
	dp->st.dash_offset = FIELD_GET(RDC_DASH_OFFSET, v);
	return RDC_ERR_NONE;
}

void dp_pen_reset(struct rdc_dp_state *st)
{
	st->pen_width = 1;
	st->pen_cap = RDC_CAP_BUTT;
	st->pen_join = RDC_JOIN_MITER;
	st->dash_bits = 0;
	st->dash_len = 0;
	st->dash_offset = 0;
}

/* Transform and check every vertex first: a rejected command draws nothing. */
static bool pts_ok(const struct rdc_dp *dp, const uint32_t *a, uint32_t n)
{
	uint32_t i;

	for (i = 0; i < n; i++) {
		int32_t x = RDC_X(a[i]), y = RDC_Y(a[i]);

		if (!dp_xform(dp, &x, &y))
			return false;
	}
	return true;
}

static void stroke_word(struct dp_stroke *sk, uint32_t w)
{
	int32_t x = RDC_X(w), y = RDC_Y(w);

	dp_xform(sk->dp, &x, &y);
	dp_stroke_point(sk, x, y);
}

uint32_t dp_cmd_stroke(struct rdc_dp *dp, uint32_t op, uint32_t len,
		       const uint32_t *a)
{
	struct dp_stroke sk;
	bool closed = false;
	uint32_t i;

	if (len < 2)
		return RDC_ERR_LENGTH;
	if (op == RDC_OP_LINE && len == 2 && dp_pen_plain(dp) &&
	    !dp->pen_npieces) {
		/* what the stroke below comes to: one whole segment */
		int32_t x0 = RDC_X(a[0]), y0 = RDC_Y(a[0]);
		int32_t x1 = RDC_X(a[1]), y1 = RDC_Y(a[1]);

		if (!dp_xform(dp, &x0, &y0) || !dp_xform(dp, &x1, &y1))
			return RDC_ERR_RANGE;
		rdc_dp_line(dp, x0, y0, x1, y1, false, false);
		return RDC_ERR_NONE;
	}
	if (!pts_ok(dp, a, len))
		return RDC_ERR_RANGE;
	dp_stroke_begin(&sk, dp);
	for (i = 0; i < len; i++)
		stroke_word(&sk, a[i]);
	if (op == RDC_OP_POLYGON) {
		/* Close it unless it already is; two points are one line. */
		if (len > 2 && a[len - 1] != a[0])
			stroke_word(&sk, a[0]);
		closed = len > 2 || a[len - 1] == a[0];
	} else {
		closed = len > 2 && a[len - 1] == a[0];
	}
	dp_stroke_end(&sk, closed);
	return RDC_ERR_NONE;
}

/*
 * A RECT outline drawn by a wide or dashed pen: its corner pixels' centres as a
 * closed path, clockwise on screen from the top left.
 */
void dp_stroke_rect(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		    uint32_t h)
{
	int32_t xr = x + (int32_t)w - 1, yb = y + (int32_t)h - 1;
	struct dp_stroke sk;

	if (!w || !h)
		return;
	dp_stroke_begin(&sk, dp);
	dp_stroke_point(&sk, x, y);
	dp_stroke_point(&sk, xr, y);
	dp_stroke_point(&sk, xr, yb);
	dp_stroke_point(&sk, x, yb);
	dp_stroke_point(&sk, x, y);
	dp_stroke_end(&sk, true);
}

bool dp_pen_plain(const struct rdc_dp *dp)
{
	return dp->st.pen_width <= 1 && !dp->st.dash_len;
}

void dp_stroke_end(struct dp_stroke *sk, bool closed)
{
	stroke_finish(sk, closed);
	dp_pen_flush(sk->dp);
}
