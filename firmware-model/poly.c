// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Polygons: scan-line fill with an edge table and an
 * active edge table, even-odd or non-zero.
 *
 * Sampling.  Pixel (px, py) is inside when its centre (px + 1/2, py + 1/2)
 * is, and a centre exactly on an edge counts for the polygon on the edge's
 * right (top-left rule): an edge covers the rows whose centre y lies in
 * [y_top, y_bottom), and in a row it puts the pixels with centre x >= the
 * crossing on its right.  With integer vertices the crossing of the line
 * (x0, y0)-(x1, y1), y0 < y1, with row py splits the row at
 *
 *   B(py) = ceil(((2 py + 1 - 2 y0) (x1 - x0) + (2 x0 - 1) (y1 - y0))
 *                / (2 (y1 - y0)))
 *
 * (pixels px >= B lie right of it), computed exactly and stepped from row
 * to row as a quotient and remainder.  Two polygons sharing an edge split
 * every row at the same B, so a tiling covers each pixel once.
 *
 * Clipping.  The polygon is first clipped by Sutherland-Hodgman against
 * the effective clip, in 16.16 fixed point.  Each clipped vertex remembers
 * the line its outgoing edge lies on (an original edge or a clip side),
 * and crossings are taken from that line, never from rounded vertices:
 * rounding only decides which of two edges meeting on a clip side owns a
 * row, and there both put the split at the clip side (the rounding error
 * is below 2^-17, so an original edge is within 1/4 pixel of the side on
 * such a row).  The fill is thus exactly the unclipped fill restricted to
 * the clip; a polygon whose clipped form would not fit RDC_DP_POLY_VERTS
 * is scan-converted unclipped with rows and spans clipped instead, which
 * gives the same pixels.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define FX_SHIFT 16
#define FX_ONE	 ((int64_t)1 << FX_SHIFT)
#define FX_HALF	 (FX_ONE / 2)
#define ET_NONE	 0xffffu

/* parent codes of the clip sides (>= 0: an edge of the input polygon) */
enum { SIDE_X0 = -1, SIDE_X1 = -2, SIDE_Y0 = -3, SIDE_Y1 = -4 };

struct pline {
	int32_t x0, y0, x1, y1;
};

struct pctx {
	const int32_t *xy;
	uint32_t n;
	struct rdc_rect c;
};

static void parent_line(const struct pctx *pc, int32_t parent, struct pline *l)
{
	uint32_t i, j;

	switch (parent) {
	case SIDE_X0:
	case SIDE_X1:
		l->x0 = l->x1 = parent == SIDE_X0 ? pc->c.x0 : pc->c.x1;
		l->y0 = 0;
		l->y1 = 1;
		return;
	case SIDE_Y0:
	case SIDE_Y1:
		l->y0 = l->y1 = parent == SIDE_Y0 ? pc->c.y0 : pc->c.y1;
		l->x0 = 0;
		l->x1 = 1;
		return;
	default:
		i = (uint32_t)parent;
		j = i + 1 == pc->n ? 0 : i + 1;
		l->x0 = pc->xy[2 * i];
		l->y0 = pc->xy[2 * i + 1];
		l->x1 = pc->xy[2 * j];
		l->y1 = pc->xy[2 * j + 1];
		return;
	}
}

/* plane: 0 x >= c.x0, 1 x <= c.x1, 2 y >= c.y0, 3 y <= c.y1 */
static int32_t plane_bound(const struct rdc_rect *c, unsigned int plane)
{
	switch (plane) {
	case 0:
		return c->x0;
	case 1:
		return c->x1;
	case 2:
		return c->y0;
	default:
		return c->y1;
	}
}

static bool plane_in(const struct rdc_dp_pvert *v, unsigned int plane,
		     int64_t b)
{
	switch (plane) {
	case 0:
		return v->x >= b;
	case 1:
		return v->x <= b;
	case 2:
		return v->y >= b;
	default:
		return v->y <= b;
	}
}

/* Where the edge S -> P, lying on `parent`, crosses the plane. */
static struct rdc_dp_pvert plane_cross(const struct pctx *pc,
				       const struct rdc_dp_pvert *s,
				       unsigned int plane, int32_t bound)
{
	struct rdc_dp_pvert r = *s;
	struct pline l;
	int64_t d;

	parent_line(pc, s->parent, &l);
	if (plane < 2) {
		r.x = (int32_t)((int64_t)bound * FX_ONE);
		d = (int64_t)l.x1 - l.x0;
		if (d)
			r.y = (int32_t)((int64_t)l.y0 * FX_ONE +
					dp_div_round(((int64_t)bound - l.x0) *
							     (l.y1 - l.y0) *
							     FX_ONE,
						     d));
	} else {
		r.y = (int32_t)((int64_t)bound * FX_ONE);
		d = (int64_t)l.y1 - l.y0;
		if (d)
			r.x = (int32_t)((int64_t)l.x0 * FX_ONE +
					dp_div_round(((int64_t)bound - l.y0) *
							     (l.x1 - l.x0) *
							     FX_ONE,
						     d));
	}
	return r;
}

/*
 * One Sutherland-Hodgman pass.  Returns the output count, or -1 if it
 * would not fit.  The vertex emitted where the polygon leaves the plane
 * starts an edge along the clip side; the one where it re-enters keeps
 * the parent of the edge it lies on.
 */
static int32_t sh_pass(const struct pctx *pc, const struct rdc_dp_pvert *in,
		       uint32_t m, struct rdc_dp_pvert *out, unsigned int plane)
{
	static const int32_t side[4] = { SIDE_X0, SIDE_X1, SIDE_Y0, SIDE_Y1 };
	int32_t bound = plane_bound(&pc->c, plane);
	int64_t b = (int64_t)bound * FX_ONE;
	uint32_t i, k = 0;

	for (i = 0; i < m; i++) {
		const struct rdc_dp_pvert *s = &in[i];
		const struct rdc_dp_pvert *p = &in[i + 1 == m ? 0 : i + 1];
		bool sin = plane_in(s, plane, b), pin = plane_in(p, plane, b);

		if (k + 2 > RDC_DP_POLY_VERTS)
			return -1;
		if (sin && pin) {
			out[k++] = *p;
		} else if (sin) {
			out[k] = plane_cross(pc, s, plane, bound);
			out[k++].parent = side[plane];
		} else if (pin) {
			out[k++] = plane_cross(pc, s, plane, bound);
			out[k++] = *p;
		}
	}
	return (int32_t)k;
}

/* ceil((v - 1/2) / 1): the first row whose centre is at or below v */
static int32_t fx_row(int64_t v)
{
	return (int32_t)dp_div_floor(v - FX_HALF + FX_ONE - 1, FX_ONE);
}

/*
 * Put the edge a -> b into the edge table's bucket of its first row (no
 * entry if it covers no row of the clip), widening [*ylo, *yhi) to its
 * rows.
 */
static void et_add(struct rdc_dp *dp, const struct pctx *pc,
		   const struct rdc_dp_pvert *a, const struct rdc_dp_pvert *b,
		   uint32_t *ne, int32_t *ylo, int32_t *yhi)
{
	const struct rdc_rect *c = &pc->c;
	struct rdc_dp_edge *e;
	struct pline l;
	int64_t top, bot, dx, dy, den, num, q, step, dq;
	int32_t r0, r1, t;

	if (a->y == b->y)
		return;
	top = RDC_MIN(a->y, b->y);
	bot = RDC_MAX(a->y, b->y);
	r0 = RDC_MAX(fx_row(top), c->y0);
	r1 = RDC_MIN(fx_row(bot), c->y1);
	if (r0 >= r1)
		return;
	parent_line(pc, a->parent, &l);
	if (l.y0 == l.y1)
		return;
	if (l.y0 > l.y1) {
		t = l.x0, l.x0 = l.x1, l.x1 = t;
		t = l.y0, l.y0 = l.y1, l.y1 = t;
	}
	dx = (int64_t)l.x1 - l.x0;
	dy = (int64_t)l.y1 - l.y0;
	den = 2 * dy;
	/* B(r0) = floor((N + den - 1) / den), kept as quotient, remainder */
	num = (2 * (int64_t)r0 + 1 - 2 * (int64_t)l.y0) * dx +
	      (2 * (int64_t)l.x0 - 1) * dy + den - 1;
	q = dp_div_floor(num, den);
	step = 2 * dx;
	dq = dp_div_floor(step, den);
	e = &dp->poly_e[*ne];
	e->q = (int32_t)q;
	e->r = (int32_t)(num - q * den);
	e->dq = (int32_t)dq;
	e->dr = (int32_t)(step - dq * den);
	e->den = (int32_t)den;
	e->yend = r1;
	e->dir = a->y < b->y ? 1 : -1;
	e->next = dp->poly_et[r0 - c->y0];
	dp->poly_et[r0 - c->y0] = (uint16_t)*ne;
	(*ne)++;
	*ylo = RDC_MIN(*ylo, r0);
	*yhi = RDC_MAX(*yhi, r1);
}

static bool pts_ok(const int32_t *xy, uint32_t n)
{
	uint32_t i;

	for (i = 0; i < 2 * n; i++)
		if (xy[i] < -RDC_POLY_COORD_LIMIT ||
		    xy[i] > RDC_POLY_COORD_LIMIT)
			return false;
	return true;
}

static void emit(struct rdc_dp *dp, const struct rdc_rect *c, int32_t y,
		 int32_t xa, int32_t xb, dp_span_fn span, void *ctx)
{
	xa = RDC_MAX(xa, c->x0);
	xb = RDC_MIN(xb, c->x1 - 1);
	if (xa <= xb)
		span(dp, y, xa, xb, ctx);
}

/*
 * Scan-convert: call span(dp, y, xa, xb, ctx) for every maximal run
 * [xa, xb] of covered pixels inside the clip, rows top to bottom.
 */
void dp_poly_scan(struct rdc_dp *dp, const int32_t *xy, uint32_t n,
		  bool nonzero, dp_span_fn span, void *ctx)
{
	struct pctx pc = { xy, n, rdc_dp_eff_clip(dp) };
	struct rdc_dp_pvert *v;
	uint32_t m, i, ne = 0, na = 0, rows;
	unsigned int plane, cur = 0;
	int32_t y, ylo, yhi;

	if (n < 3 || n > RDC_DP_POLY_VERTS || !pts_ok(xy, n))
		return;
	if (pc.c.x0 >= pc.c.x1 || pc.c.y0 >= pc.c.y1)
		return;
	for (i = 0; i < n; i++) {
		dp->poly_v[0][i].x = (int32_t)(xy[2 * i] * FX_ONE);
		dp->poly_v[0][i].y = (int32_t)(xy[2 * i + 1] * FX_ONE);
		dp->poly_v[0][i].parent = (int32_t)i;
	}
	m = n;
	for (plane = 0; plane < 4 && m; plane++) {
		int32_t k = sh_pass(&pc, dp->poly_v[cur], m,
				    dp->poly_v[cur ^ 1], plane);

		if (k < 0) {
			/* unclipped instead: rows and spans clip below */
			cur = 0;
			m = n;
			for (i = 0; i < n; i++) {
				dp->poly_v[0][i].x =
					(int32_t)(xy[2 * i] * FX_ONE);
				dp->poly_v[0][i].y =
					(int32_t)(xy[2 * i + 1] * FX_ONE);
				dp->poly_v[0][i].parent = (int32_t)i;
			}
			break;
		}
		m = (uint32_t)k;
		cur ^= 1;
	}
	if (m < 2)
		return;
	v = dp->poly_v[cur];

	rows = (uint32_t)(pc.c.y1 - pc.c.y0);
	for (i = 0; i < rows; i++)
		dp->poly_et[i] = ET_NONE;
	ylo = pc.c.y1;
	yhi = pc.c.y0;
	for (i = 0; i < m; i++)
		et_add(dp, &pc, &v[i], &v[i + 1 == m ? 0 : i + 1], &ne, &ylo,
		       &yhi);
	if (!ne)
		return;

	for (y = ylo; y < yhi; y++) {
		uint32_t k, j, e;
		int32_t w = 0, start = 0, ps = 0, pe = 0;
		bool open = false;

		/* new edges in, finished edges out */
		for (e = dp->poly_et[y - pc.c.y0]; e != ET_NONE;
		     e = dp->poly_e[e].next)
			dp->poly_aet[na++] = (uint16_t)e;
		for (k = 0, j = 0; k < na; k++)
			if (dp->poly_e[dp->poly_aet[k]].yend > y)
				dp->poly_aet[j++] = dp->poly_aet[k];
		na = j;
		if (!na)
			continue;
		/* insertion sort by crossing: the order barely changes */
		for (k = 1; k < na; k++) {
			uint16_t t = dp->poly_aet[k];
			int32_t tq = dp->poly_e[t].q;

			for (j = k;
			     j > 0 && dp->poly_e[dp->poly_aet[j - 1]].q > tq;
			     j--)
				dp->poly_aet[j] = dp->poly_aet[j - 1];
			dp->poly_aet[j] = t;
		}
		for (k = 0; k < na; k++) {
			const struct rdc_dp_edge *ed =
				&dp->poly_e[dp->poly_aet[k]];
			bool was = nonzero ? w != 0 : (w & 1);
			bool now;

			w += nonzero ? ed->dir : 1;
			now = nonzero ? w != 0 : (w & 1);
			if (!was && now) {
				start = ed->q;
			} else if (was && !now && ed->q > start) {
				/* runs [start, q - 1], merged when touching */
				if (open && start == pe + 1) {
					pe = ed->q - 1;
				} else {
					if (open)
						emit(dp, &pc.c, y, ps, pe, span,
						     ctx);
					ps = start;
					pe = ed->q - 1;
					open = true;
				}
			}
		}
		if (open)
			emit(dp, &pc.c, y, ps, pe, span, ctx);
		for (k = 0; k < na; k++) {
			struct rdc_dp_edge *ed = &dp->poly_e[dp->poly_aet[k]];
			int32_t carry;

			/* the carry without a branch: edges step unevenly */
			ed->q += ed->dq;
			ed->r += ed->dr;
			carry = ed->r >= ed->den;
			ed->r -= ed->den & -carry;
			ed->q += carry;
		}
	}
}

static void fill_span_cb(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb,
			 void *ctx)
{
	(void)ctx;
	/* the run is inside the clip: queued as is when it can be */
	if (dp->queue_spans)
		rdc_dp_queue_span(dp, y, xa, xb);
	else
		dp_fill_span(dp, xa, xb, y);
}

void dp_fill_poly(struct rdc_dp *dp, const int32_t *xy, uint32_t n,
		  bool nonzero)
{
	rdc_dp_queue_begin(dp);
	dp_poly_scan(dp, xy, n, nonzero, fill_span_cb, NULL);
	rdc_dp_queue_end(dp);
}

/* Transform the command's points into dp->poly_xy. */
static uint32_t load_points(struct rdc_dp *dp, uint32_t len, const uint32_t *a)
{
	uint32_t i;

	for (i = 0; i < len; i++) {
		int32_t x = RDC_X(a[i]), y = RDC_Y(a[i]);

		if (x < RDC_COORD_MIN || x > RDC_COORD_MAX ||
		    y < RDC_COORD_MIN || y > RDC_COORD_MAX)
			return RDC_ERR_RANGE;
		if (!dp_xform(dp, &x, &y))
			return RDC_ERR_RANGE;
		dp->poly_xy[2 * i] = x;
		dp->poly_xy[2 * i + 1] = y;
	}
	return RDC_ERR_NONE;
}

uint32_t dp_cmd_fill_polygon(struct rdc_dp *dp, uint32_t flags, uint32_t len,
			     const uint32_t *a)
{
	uint32_t err;

	if (len < 3)
		return RDC_ERR_LENGTH;
	if (flags & ~RDC_FILL_NONZERO)
		return RDC_ERR_ARG;
	err = load_points(dp, len, a);
	if (err)
		return err;
	dp_fill_poly(dp, dp->poly_xy, len, flags & RDC_FILL_NONZERO);
	return RDC_ERR_NONE;
}
