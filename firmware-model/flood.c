// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Flood fill, span by span (Heckbert's seed fill, widened for 8-connected
 * regions), with a fixed-size stack of pending spans.
 *
 * A pixel is "inside" while it still has to be filled:
 *   interior mode: it holds the seed's colour S, and the fill would change
 *                  it there (W(x, y) != S);
 *   boundary mode: it is not the boundary colour, and does not already
 *                  hold the value the fill writes there (W(x, y)).
 * W is the fill style's value at (x, y) (FG or the pattern cell, through
 * the ROP applied to S, or to 0 in boundary mode, whose ROP may not read
 * DST); a transparent pattern's clear cells are never inside.  Filling a
 * pixel makes it not inside, so the fill ends whatever the shape.
 *
 * A stack entry (y, lo, hi, dir) says: row y - dir holds a filled run
 * whose neighbours in row y are [lo, hi]; exploring it fills every inside
 * run of row y meeting [lo, hi] and pushes its neighbours on: the next row
 * in the same direction, and in the row it came from the parts the parent
 * run did not cover.  When the stack is full the entry is dropped and the
 * box around the dropped entries remembered; once the stack is empty the
 * box is rescanned for inside pixels touching filled ones, which restart
 * the fill, until a rescan drops nothing.  (In the rescan a pixel holding
 * the fill value counts as filled, so a region touching such pixels that
 * were there before may also take in inside pixels next to them within
 * the box; without an overflow the fill is exact.)
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define FLOOD_READ  128u /* pixels read per span */
#define FLOOD_SLOTS 3u	 /* rows cached: y - 1, y, y + 1 */

struct flood {
	struct rdc_dp *dp;
	struct rdc_rect c;
	bool boundary;
	uint32_t key; /* S (interior) or the boundary colour */
	uint32_t mask;
	int32_t e; /* 1 for 8-connected */
	uint32_t sp;
	bool dropped;
	int32_t bx0, by0, bx1, by1; /* box of dropped entries, inclusive */
	struct {
		int32_t y, x0;
		uint32_t n;
	} slot[FLOOD_SLOTS];
};

static uint32_t slot_of(int32_t y)
{
	return (uint32_t)(((y % (int32_t)FLOOD_SLOTS) + (int32_t)FLOOD_SLOTS) %
			  (int32_t)FLOOD_SLOTS);
}

/*
 * DST pixel (x, y) inside the clip, read through the row cache; a read runs
 * FLOOD_READ pixels in the direction of travel.
 */
static uint32_t get(struct flood *fl, int32_t x, int32_t y, int dir)
{
	uint32_t s = slot_of(y);
	int32_t x0;
	uint32_t n;

	if (fl->slot[s].n && fl->slot[s].y == y && x >= fl->slot[s].x0 &&
	    x < fl->slot[s].x0 + (int32_t)fl->slot[s].n)
		return fl->dp->flood_row[s][x - fl->slot[s].x0];
	if (dir < 0)
		x0 = RDC_MAX(fl->c.x0, x - (int32_t)FLOOD_READ + 1);
	else
		x0 = x;
	n = (uint32_t)(RDC_MIN(fl->c.x1, x0 + (int32_t)FLOOD_READ) - x0);
	if (!rdc_dp_read_px(fl->dp, y, x0, n, fl->dp->flood_row[s])) {
		fl->slot[s].n = 0;
		return fl->boundary ? fl->key : ~fl->key;
	}
	fl->slot[s].y = y;
	fl->slot[s].x0 = x0;
	fl->slot[s].n = n;
	return fl->dp->flood_row[s][x - x0];
}

/* The fill's value at (x, y); false where it leaves DST alone. */
static bool fill_value(const struct flood *fl, int32_t x, int32_t y,
		       uint32_t *w)
{
	uint32_t v;

	if (!dp_pat_value(fl->dp, x, y, &v))
		return false;
	*w = rdc_rop_apply(fl->dp->st.rop, v, fl->boundary ? 0 : fl->key) &
	     fl->mask;
	return true;
}

static bool inside(struct flood *fl, int32_t x, int32_t y, int dir)
{
	uint32_t p = get(fl, x, y, dir), w;

	if (!fill_value(fl, x, y, &w))
		return false;
	if (fl->boundary)
		return p != fl->key && p != w;
	return p == fl->key && w != fl->key;
}

static bool filled(struct flood *fl, int32_t x, int32_t y)
{
	uint32_t w;

	if (x < fl->c.x0 || x >= fl->c.x1 || y < fl->c.y0 || y >= fl->c.y1)
		return false;
	return fill_value(fl, x, y, &w) && get(fl, x, y, 1) == w;
}

static void push(struct flood *fl, int32_t y, int32_t lo, int32_t hi,
		 int32_t dir)
{
	struct rdc_dp_fseg *s;

	if (y < fl->c.y0 || y >= fl->c.y1)
		return;
	lo = RDC_MAX(lo, fl->c.x0);
	hi = RDC_MIN(hi, fl->c.x1 - 1);
	if (lo > hi)
		return;
	if (fl->sp == RDC_DP_FLOOD_STACK) {
		if (!fl->dropped) {
			fl->bx0 = lo, fl->bx1 = hi, fl->by0 = y, fl->by1 = y;
			fl->dropped = true;
		}
		fl->bx0 = RDC_MIN(fl->bx0, lo);
		fl->bx1 = RDC_MAX(fl->bx1, hi);
		fl->by0 = RDC_MIN(fl->by0, y);
		fl->by1 = RDC_MAX(fl->by1, y);
		return;
	}
	s = &fl->dp->flood_stk[fl->sp++];
	s->y = (int16_t)y;
	s->xl = (int16_t)lo;
	s->xr = (int16_t)hi;
	s->dy = (int16_t)dir;
}

static void fill_run(struct flood *fl, int32_t l, int32_t r, int32_t y)
{
	uint32_t s = slot_of(y);

	dp_fill_span(fl->dp, l, r, y);
	if (fl->slot[s].y == y)
		fl->slot[s].n = 0;
}

/* Explore row y over [lo, hi] (see the top); dir 0 is the seed. */
static void explore(struct flood *fl, int32_t y, int32_t lo, int32_t hi,
		    int32_t dir)
{
	int32_t e = fl->e, x = lo, l, r;

	while (x <= hi) {
		while (x <= hi && !inside(fl, x, y, 1))
			x++;
		if (x > hi)
			break;
		l = x;
		if (l == lo)
			while (l > fl->c.x0 && inside(fl, l - 1, y, -1))
				l--;
		r = x;
		while (r + 1 < fl->c.x1 && inside(fl, r + 1, y, 1))
			r++;
		fill_run(fl, l, r, y);
		if (dir == 0) {
			push(fl, y + 1, l - e, r + e, 1);
			push(fl, y - 1, l - e, r + e, -1);
			return;
		}
		push(fl, y + dir, l - e, r + e, dir);
		/* the parent covered at least [lo + e, hi - e] */
		if (l - e < lo + e)
			push(fl, y - dir, l - e, lo + e - 1, -dir);
		if (r + e > hi - e)
			push(fl, y - dir, hi - e + 1, r + e, -dir);
		x = r + 2;
	}
}

static void drain(struct flood *fl)
{
	while (fl->sp) {
		struct rdc_dp_fseg s = fl->dp->flood_stk[--fl->sp];

		explore(fl, s.y, s.xl, s.xr, s.dy);
	}
}

static bool touches_filled(struct flood *fl, int32_t x, int32_t y)
{
	int32_t e = fl->e, dx;

	if (filled(fl, x - 1, y) || filled(fl, x + 1, y))
		return true;
	for (dx = -e; dx <= e; dx++)
		if (filled(fl, x + dx, y - 1) || filled(fl, x + dx, y + 1))
			return true;
	return false;
}

/* Rescan the box of dropped entries until nothing more is dropped. */
static void rescan(struct flood *fl)
{
	while (fl->dropped) {
		int32_t x0 = fl->bx0, x1 = fl->bx1, y0 = fl->by0, y1 = fl->by1;
		int32_t x, y;

		fl->dropped = false;
		for (y = y0; y <= y1; y++)
			for (x = x0; x <= x1; x++)
				if (inside(fl, x, y, 1) &&
				    touches_filled(fl, x, y)) {
					explore(fl, y, x, x, 0);
					drain(fl);
				}
	}
}

uint32_t dp_cmd_flood(struct rdc_dp *dp, uint32_t flags, uint32_t len,
		      const uint32_t *a)
{
	unsigned int bpp = rdc_format_bpp(dp->st.dst.format);
	struct flood fl = { .dp = dp };
	int32_t x, y;
	uint32_t i;

	if (flags & ~(RDC_FLOOD_8 | RDC_FLOOD_BOUNDARY))
		return RDC_ERR_ARG;
	fl.boundary = flags & RDC_FLOOD_BOUNDARY;
	if (len != (fl.boundary ? 2u : 1u))
		return RDC_ERR_LENGTH;
	x = RDC_X(a[0]);
	y = RDC_Y(a[0]);
	if (x < RDC_COORD_MIN || x > RDC_COORD_MAX || y < RDC_COORD_MIN ||
	    y > RDC_COORD_MAX || !dp_xform(dp, &x, &y))
		return RDC_ERR_RANGE;
	/* boundary mode knows no seed colour to apply a reading ROP to */
	if (fl.boundary && rdc_rop_reads_dst(dp->st.rop))
		return RDC_ERR_ARG;
	fl.mask = bpp >= 32 ? 0xffffffffu : (1u << bpp) - 1;
	fl.c = rdc_dp_eff_clip(dp);
	fl.e = flags & RDC_FLOOD_8 ? 1 : 0;
	if (x < fl.c.x0 || x >= fl.c.x1 || y < fl.c.y0 || y >= fl.c.y1)
		return RDC_ERR_NONE;
	for (i = 0; i < FLOOD_SLOTS; i++)
		fl.slot[i].n = 0;
	if (fl.boundary)
		fl.key = a[1] & fl.mask;
	else
		fl.key = get(&fl, x, y, 1);
	explore(&fl, y, x, x, 0);
	drain(&fl);
	rescan(&fl);
	return RDC_ERR_NONE;
}
