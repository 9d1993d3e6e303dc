// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Pixel history (docs/history.md): every VRAM write that touches a watched
 * rectangle of the screen, with the command that made it, its cycle, the
 * drawing state, the value before and after, and where the beam was.
 *
 * The chip calls rdc_hw_set_vram_hook's function once per span, column or
 * run the DP charges (and per host aperture write), before the bytes
 * change: the DP writes them after the port call returns and before its
 * next one.  So each call first completes the entries the previous call
 * left open (their "after" is in VRAM now), then opens entries for the
 * watched pixels the new access covers, with their "before".  Nothing of
 * this runs while no history is open: the chip tests one pointer.
 *
 * On a device rdcd serves, the daemon keeps the history on its chip
 * (this same code, there) and the handle here fetches its entries a page
 * at a time (the backend's hist_* operations, rdc_proto.h's HIST_*).
 */
#include <stdlib.h>
#include <string.h>

#include "rdc_dp_host.h"
#include "rdc_priv.h"
#include "rdc_proto.h"

#define HIST_MAX_DEFAULT (1u << 20) /* entries kept; later ones are counted */
#define WRITES_MAX	 (1u << 22) /* write accesses logged (RDC_HISTORY_WRITES) */
#define REMOTE_PAGE	 4096u	    /* entries fetched from a daemon at once */

struct hist_rec {
	struct rdc_history_entry e;
	uint32_t addr; /* the byte holding the pixel (the first, if several) */
	uint8_t bit;   /* sub-byte pixels: bit offset in that byte (MSB 0) */
	uint8_t bpp;   /* bits per pixel */
	uint8_t partial; /* sub-byte pixel in a run's first or last byte */
};

struct rdc_history {
	rdc_dev *dev;
	struct rdc_hw *hw;
	uint32_t x0, y0, x1, y1; /* watched: [x0, x1) x [y0, y1), screen */
	uint32_t flags;
	struct hist_rec *rec;
	size_t n, cap, max, open; /* rec[open, n) wait for their "after" */
	uint64_t dropped;
	struct rdc_history_write *wr;
	size_t nw, wcap, wopen;
	uint64_t wdropped;
	/* the line entries carry, when the program says (rdcd) */
	bool line_set;
	uint32_t line;
	/*
	 * Kept by a daemon (dev->be->hist_*): entries [page_first, page_first
	 * + page_n) fetched; once its device is closed, all of them.
	 */
	bool remote;
	struct rdc_history_entry *page;
	size_t page_cap, page_n;
	uint64_t page_first, rcount, rdropped;
};

static uint32_t px_get(const uint8_t *vram, const struct hist_rec *r)
{
	return rdc_px_get(vram + r->addr, r->bpp, r->bit);
}

/* FNV-1a over the bytes of a write access, as they are now. */
static uint64_t bytes_hash(const uint8_t *vram,
			   const struct rdc_history_write *w)
{
	uint64_t h = 0xcbf29ce484222325ull;

	for (uint32_t i = 0; i < w->count; i++) {
		const uint8_t *p = vram + w->addr + (uint64_t)i * w->stride;

		for (uint32_t j = 0; j < w->len; j++) {
			h ^= p[j];
			h *= 0x100000001b3ull;
		}
	}
	return h;
}

/* The writes of the last access have landed: complete what they opened. */
static void hist_settle(struct rdc_history *h)
{
	const uint8_t *vram = rdc_hw_vram(h->hw);
	size_t i, k = h->open;

	for (i = h->open; i < h->n; i++) {
		struct hist_rec *r = &h->rec[i];

		r->e.after = px_get(vram, r);
		/*
		 * A sub-byte pixel that shares a run's edge byte may not have
		 * been written at all (the DP changed its neighbours' bits):
		 * only a change says it was.
		 */
		if (r->partial && r->e.after == r->e.before)
			continue;
		if (k != i)
			h->rec[k] = *r;
		k++;
	}
	h->n = k;
	h->open = k;
	for (i = h->wopen; i < h->nw; i++)
		h->wr[i].hash = bytes_hash(vram, &h->wr[i]);
	h->wopen = h->nw;
}

/* What the DP is doing now: the command, its source and state. */
static void hist_context(const struct rdc_history *h,
			 struct rdc_history_entry *e, uint64_t time,
			 unsigned int who)
{
	const struct rdc_hw *hw = h->hw;
	struct rdc_dp_view dp;
	struct rdc_hw_state st;
	struct rdc_perf perf;

	e->size = sizeof(*e);
	e->cycle = time;
	rdc_hw_perf(hw, &perf);
	rdc_hw_state(hw, &st);
	e->cmd_index = perf.cmds;
	e->line = h->line_set ? h->line : h->dev->src_line;
	e->frame = st.frame_count;
	if (who == RDC_VRAM_BY_HOST || !rdc_dp_view_get(hw, &dp)) {
		e->opcode = RDC_HISTORY_OP_HOST;
		e->source = RDC_HISTORY_SRC_HOST;
		return;
	}
	e->opcode = dp.opcode;
	e->rop = dp.rop;
	e->alpha = dp.alpha;
	e->colorkey = dp.colorkey;
	e->colorkey_on = dp.colorkey_on;
	e->pattern = dp.pattern;
	e->fg = dp.fg;
	e->bg = dp.bg;
	e->depth = dp.depth;
	e->cmd_addr = dp.cmd_addr;
	for (uint32_t d = 0; d + 1 < e->depth; d++)
		e->calls[d] = dp.calls[d];
	e->source = dp.src == RDC_DP_SRC_LIST ? RDC_HISTORY_SRC_LIST :
		    dp.src == RDC_DP_SRC_RING ? RDC_HISTORY_SRC_RING :
						RDC_HISTORY_SRC_FIFO;
}

static struct hist_rec *hist_add(struct rdc_history *h)
{
	if (h->n >= h->max) {
		h->dropped++;
		return NULL;
	}
	if (h->n == h->cap) {
		size_t cap = h->cap ? h->cap * 2 : 256;
		struct hist_rec *r;

		if (cap > h->max)
			cap = h->max;
		r = realloc(h->rec, cap * sizeof(*r));
		if (!r) {
			h->dropped++;
			return NULL;
		}
		h->rec = r;
		h->cap = cap;
	}
	return &h->rec[h->n++];
}

/* One run [a, a + len) against the watched rectangle of the screen. */
static void hist_run(struct rdc_history *h, const struct rdc_history_entry *ctx,
		     uint64_t a, uint64_t len)
{
	struct rdc_hw_state cs, *c = &cs;
	uint64_t base, st, end = a + len;
	uint32_t bpp, x1, y1, vram_size = rdc_hw_vram_size(h->hw);
	const uint8_t *vram = rdc_hw_vram(h->hw);
	uint64_t y, ylo, yhi;

	rdc_hw_state(h->hw, c);
	base = c->fb_base;
	st = c->fb_stride;
	bpp = rdc_format_bpp(c->fb_format);
	x1 = RDC_MIN(h->x1, c->width);
	y1 = RDC_MIN(h->y1, c->height);

	if (!bpp || !st || end <= base || h->x0 >= x1 || h->y0 >= y1)
		return;
	ylo = a > base ? (a - base) / st : 0;
	yhi = (end - 1 - base) / st;
	if (ylo < h->y0)
		ylo = h->y0;
	if (yhi >= y1)
		yhi = y1 - 1;
	for (y = ylo; y <= yhi; y++) {
		uint64_t row = base + y * st;
		uint64_t lo = a > row ? a - row : 0;
		uint64_t hi = RDC_MIN(end - row, st);
		uint64_t xa = lo * 8 / bpp, xb = (hi * 8 + bpp - 1) / bpp;
		uint64_t x;

		if (hi <= lo)
			continue;
		if (xa < h->x0)
			xa = h->x0;
		if (xb > x1)
			xb = x1;
		for (x = xa; x < xb; x++) {
			uint64_t bit = x * bpp;
			uint64_t at = row + bit / 8;
			struct hist_rec *r;

			if (at + (bpp + 7) / 8 > vram_size)
				break;
			r = hist_add(h);
			if (!r)
				continue; /* counted in dropped */
			r->e = *ctx;
			r->e.x = (uint32_t)x;
			r->e.y = (uint32_t)y;
			r->e.format = c->fb_format;
			r->addr = (uint32_t)at;
			r->bpp = (uint8_t)bpp;
			r->bit = (uint8_t)(bit % 8);
			r->partial = bpp < 8 && (at == a || at == end - 1);
			r->e.fetched = !c->scanning	? -1 :
				       c->next_line > y ? 1 :
							  0;
			r->e.before = px_get(vram, r);
			r->e.after = r->e.before;
		}
	}
}

/* The bytes [lo, hi) the watched pixels of the screen occupy now. */
static bool watch_bytes(const struct rdc_history *h, uint64_t *lo, uint64_t *hi)
{
	struct rdc_hw_state cs, *c = &cs;
	uint32_t bpp, x1, y1;

	rdc_hw_state(h->hw, c);
	bpp = rdc_format_bpp(c->fb_format);
	x1 = RDC_MIN(h->x1, c->width);
	y1 = RDC_MIN(h->y1, c->height);
	if (!bpp || h->x0 >= x1 || h->y0 >= y1)
		return false;
	*lo = c->fb_base + (uint64_t)h->y0 * c->fb_stride +
	      (uint64_t)h->x0 * bpp / 8;
	*hi = c->fb_base + (uint64_t)(y1 - 1) * c->fb_stride +
	      ((uint64_t)x1 * bpp + 7) / 8;
	return true;
}

static void hist_hook(void *ctx, uint64_t time, uint32_t addr, uint32_t len,
		      uint32_t count, uint32_t stride, unsigned int who)
{
	struct rdc_history *h = ctx;
	struct rdc_history_entry e = { 0 };
	uint64_t last, lo, hi;

	/* the runs of one rdc_port_runs land together, after all of them */
	if (!(who & RDC_VRAM_MORE))
		hist_settle(h);
	who &= RDC_VRAM_BY_HOST;
	if (!count || !len)
		return;
	if (h->flags & RDC_HISTORY_WRITES) {
		if (h->nw == h->wcap && h->nw < WRITES_MAX) {
			size_t cap = h->wcap ? h->wcap * 2 : 256;
			void *p = realloc(h->wr, cap * sizeof(*h->wr));

			if (p) {
				h->wr = p;
				h->wcap = cap;
			}
		}
		if (h->nw < h->wcap) {
			struct rdc_history_write *w = &h->wr[h->nw++];

			memset(w, 0, sizeof(*w));
			hist_context(h, &e, time, who);
			w->size = sizeof(*w);
			w->entry = e;
			w->addr = addr;
			w->len = len;
			w->count = count;
			w->stride = stride;
		} else {
			h->wdropped++;
		}
	}
	/* the watched bytes, for the chip to call only for what reaches them */
	if (!watch_bytes(h, &lo, &hi)) {
		if (!(h->flags & RDC_HISTORY_WRITES))
			rdc_hw_set_vram_watch(h->hw, 0, 0);
		return;
	}
	if (!(h->flags & RDC_HISTORY_WRITES))
		rdc_hw_set_vram_watch(h->hw, (uint32_t)RDC_MIN(lo, UINT32_MAX),
				      (uint32_t)RDC_MIN(hi, UINT32_MAX));
	/* the access's extent against them */
	last = (uint64_t)addr + (uint64_t)(count - 1) * stride + len;
	if (last <= lo || addr >= hi)
		return;
	if (!e.size)
		hist_context(h, &e, time, who);
	for (uint32_t i = 0; i < count; i++) {
		uint64_t a = addr + (uint64_t)i * stride;

		if (a + len > lo && a < hi)
			hist_run(h, &e, a, len);
	}
}

/* A history the daemon serving dev keeps: only the handle is here. */
static int remote_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
		       uint32_t h, uint32_t flags, rdc_history **out)
{
	struct rdc_history *hi;
	int ret;

	if (dev->hist)
		return rdc_err_detail(RDC_E_BUSY,
				      "a history is already open on this "
				      "device");
	if (flags & RDC_HISTORY_WRITES)
		return rdc_err_detail(RDC_E_NOSYS,
				      "rdcd keeps no write log "
				      "(RDC_HISTORY_WRITES): run the diff on "
				      "sim:, or on the daemon's trace");
	hi = calloc(1, sizeof(*hi));
	if (!hi)
		return RDC_E_NOMEM;
	ret = dev->be->hist_open(dev, x, y, w, h, flags);
	if (ret) {
		free(hi);
		if (ret == RDC_E_BUSY)
			return rdc_err_detail(ret, "rdcd keeps another "
						   "client's history: one "
						   "at a time");
		return ret;
	}
	hi->dev = dev;
	hi->remote = true;
	hi->x0 = x;
	hi->y0 = y;
	hi->flags = flags;
	hi->max = HIST_MAX_DEFAULT;
	dev->hist = hi;
	*out = hi;
	return 0;
}

int rdc_history_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
		     uint32_t h, uint32_t flags, rdc_history **out)
{
	struct rdc_history *hi;
	struct rdc_hw *hw;

	if (!out)
		return RDC_E_INVAL;
	*out = NULL;
	if (!dev || (flags & ~RDC_HISTORY_WRITES))
		return RDC_E_INVAL;
	/* under a trace recorder too (rdcd --record) */
	hw = rdc_dev_chip(dev);
	if (!hw && dev->be->hist_open)
		return remote_open(dev, x, y, w, h, flags, out);
	if (!hw)
		return rdc_err_detail(RDC_E_NOSYS,
				      "pixel history needs a sim: device (the "
				      "writes are watched inside the "
				      "simulator)");
	if (dev->hist || rdc_hw_vram_hooked(hw))
		return rdc_err_detail(RDC_E_BUSY,
				      "a history is already open on this "
				      "device");
	hi = calloc(1, sizeof(*hi));
	if (!hi)
		return RDC_E_NOMEM;
	hi->dev = dev;
	hi->hw = hw;
	hi->x0 = x;
	hi->y0 = y;
	hi->x1 = w > UINT32_MAX - x ? UINT32_MAX : x + w;
	hi->y1 = h > UINT32_MAX - y ? UINT32_MAX : y + h;
	hi->flags = flags;
	hi->max = HIST_MAX_DEFAULT;
	dev->hist = hi;
	rdc_hw_set_vram_hook(hw, hist_hook, hi);
	*out = hi;
	return 0;
}

int rdc_history_attach(rdc_history *h, rdc_dev *dev)
{
	struct rdc_hw *hw = rdc_dev_chip(dev);

	if (!h || h->dev || h->remote || !hw)
		return RDC_E_INVAL;
	if (dev->hist || rdc_hw_vram_hooked(hw))
		return RDC_E_BUSY;
	h->dev = dev;
	h->hw = hw;
	dev->hist = h;
	rdc_hw_set_vram_hook(hw, hist_hook, h);
	return 0;
}

int rdc_history_set_limit(rdc_history *h, size_t max_entries)
{
	if (!h || !max_entries)
		return RDC_E_INVAL;
	if (h->remote && h->dev) {
		int ret;

		if (max_entries > RDC_PROTO_HIST_LIMIT_MAX)
			return rdc_err_detail(RDC_E_RANGE,
					      "rdcd keeps at most %u entries",
					      RDC_PROTO_HIST_LIMIT_MAX);
		ret = h->dev->be->hist_set(h->dev, RDC_HIST_SET_LIMIT,
					   (uint32_t)max_entries);
		if (ret)
			return ret;
	}
	h->max = max_entries;
	return 0;
}

void rdc_history_set_line(rdc_history *h, uint32_t line)
{
	if (!h)
		return;
	h->line_set = true;
	h->line = line;
}

/* Everything written so far has landed once the chip is between calls. */
static void hist_sync(rdc_history *h)
{
	if (h->hw)
		hist_settle(h);
}

/*
 * Entries [first, first + max) of a daemon's history into h->page (max
 * at most its capacity), and how many it keeps now.
 */
static int remote_fetch(rdc_history *h, uint64_t first, uint32_t max)
{
	uint32_t n = 0;
	uint64_t count = 0, dropped = 0;
	int ret;

	if (max > h->page_cap) {
		struct rdc_history_entry *p =
			realloc(h->page, (size_t)max * sizeof(*p));

		if (!p)
			return RDC_E_NOMEM;
		h->page = p;
		h->page_cap = max;
	}
	ret = h->dev->be->hist_read(h->dev, first, max, h->page, &n, &count,
				    &dropped);
	if (ret)
		return ret;
	h->rcount = count;
	h->rdropped = dropped;
	if (max) {
		h->page_first = first;
		h->page_n = n;
	}
	return 0;
}

size_t rdc_history_count(rdc_history *h)
{
	if (!h)
		return 0;
	if (h->remote) {
		if (h->dev && remote_fetch(h, 0, 0))
			return 0;
		return h->dev ? (size_t)h->rcount : h->page_n;
	}
	hist_sync(h);
	return h->n;
}

uint64_t rdc_history_dropped(rdc_history *h)
{
	if (h && h->remote && h->dev)
		remote_fetch(h, 0, 0); /* on an error: the last known */
	if (h && h->remote)
		return h->rdropped;
	return h ? h->dropped + h->wdropped : 0;
}

static int remote_get(rdc_history *h, size_t i, struct rdc_history_entry *e,
		      size_t sz)
{
	if (i < h->page_first || i - h->page_first >= h->page_n) {
		int ret;

		if (!h->dev)
			return RDC_E_RANGE;
		ret = remote_fetch(h, i, REMOTE_PAGE);
		if (ret)
			return ret;
		if (!h->page_n || h->page_first != i)
			return RDC_E_RANGE;
	}
	memcpy((char *)e + sizeof(uint32_t),
	       (char *)&h->page[i - h->page_first] + sizeof(uint32_t),
	       sz - sizeof(uint32_t));
	return 0;
}

int rdc_history_get_sized(rdc_history *h, size_t i, struct rdc_history_entry *e)
{
	size_t sz;

	if (!h || !e || e->size < sizeof(uint32_t))
		return RDC_E_INVAL;
	sz = RDC_MIN((size_t)e->size, sizeof(*e));
	if (h->remote) {
		int ret = remote_get(h, i, e, sz);

		if (ret)
			return ret;
	} else {
		hist_sync(h);
		if (i >= h->n)
			return RDC_E_RANGE;
		memcpy((char *)e + sizeof(uint32_t),
		       (char *)&h->rec[i].e + sizeof(uint32_t),
		       sz - sizeof(uint32_t));
	}
	if (e->size > sizeof(*e))
		memset((char *)e + sizeof(*e), 0, e->size - sizeof(*e));
	return 0;
}

size_t rdc_history_write_count(rdc_history *h)
{
	if (!h)
		return 0;
	hist_sync(h);
	return h->nw;
}

int rdc_history_write_get_sized(rdc_history *h, size_t i,
				struct rdc_history_write *w)
{
	size_t sz;

	if (!h || !w || w->size < sizeof(uint32_t))
		return RDC_E_INVAL;
	hist_sync(h);
	if (i >= h->nw)
		return RDC_E_RANGE;
	sz = RDC_MIN((size_t)w->size, sizeof(*w));
	memcpy((char *)w + sizeof(uint32_t),
	       (char *)&h->wr[i] + sizeof(uint32_t), sz - sizeof(uint32_t));
	if (w->size > sizeof(*w))
		memset((char *)w + sizeof(*w), 0, w->size - sizeof(*w));
	return 0;
}

static bool write_same(const struct rdc_history_write *a,
		       const struct rdc_history_write *b)
{
	return a->addr == b->addr && a->len == b->len && a->count == b->count &&
	       a->stride == b->stride && a->hash == b->hash;
}

int rdc_history_first_diff(rdc_history *a, rdc_history *b, size_t *index)
{
	size_t i, n;

	if (!a || !b || !index || !(a->flags & RDC_HISTORY_WRITES) ||
	    !(b->flags & RDC_HISTORY_WRITES))
		return RDC_E_INVAL;
	hist_sync(a);
	hist_sync(b);
	n = RDC_MIN(a->nw, b->nw);
	for (i = 0; i < n; i++)
		if (!write_same(&a->wr[i], &b->wr[i]))
			break;
	*index = i;
	return i < n || a->nw != b->nw ? 1 : 0;
}

/* ---- the CLUT entry a pixel shows ---------------------------------------- */

/* A beam position, ordered as the beam passes them. */
#define BEAM_POS(y, x) ((uint64_t)(y) << 32 | (uint32_t)(x))

/*
 * The position a WAIT for (y, x) is met at, the list having reached
 * `at`: that column of that line, a column past the line's end (h_total)
 * the next line's start, a position passed already at once
 * (docs/hardware.md, "Raster list").
 */
static uint64_t wait_met(uint64_t at, uint32_t y, uint32_t x, uint32_t h_total)
{
	uint64_t p = x >= h_total ? BEAM_POS((uint64_t)y + 1, 0) :
				    BEAM_POS(y, x);

	return p > at ? p : at;
}

static int reg_reads(rdc_dev *dev, const uint32_t *regs, uint32_t *vals,
		     size_t n)
{
	for (size_t i = 0; i < n; i++) {
		int ret = rdc_reg_read(dev, regs[i], &vals[i]);

		if (ret)
			return ret;
	}
	return 0;
}

/*
 * Walk the list in force as the CRTC runs it from line 0: the last entry
 * that writes CLUT entry c->index at or before the pixel's position, or
 * failing one the last in the frame.  The walk stops where the chip's
 * does (END, a WAIT never met, an unknown op, LEN entries, the end of
 * VRAM); a list the chip found bad has RASTER_CTRL.EN cleared already.
 */
static int clut_walk(rdc_dev *dev, uint32_t rbase, uint32_t rctrl,
		     uint32_t vram_size, uint32_t h_total, uint32_t v_total,
		     struct rdc_history_clut *c)
{
	uint32_t len = FIELD_GET(RDC_RASTER_CTRL_LEN, rctrl), n, k;
	uint64_t at = 0, pixel = BEAM_POS(c->y, c->x);
	uint8_t *list;
	bool before = false, any = false;
	int ret;

	if (!len || len > RDC_RASTER_MAX_ENTRIES)
		len = RDC_RASTER_MAX_ENTRIES;
	rbase &= RDC_RASTER_BASE_MASK;
	if (rbase >= vram_size)
		return 0;
	n = RDC_MIN(len, (vram_size - rbase) / RDC_RASTER_ENTRY_BYTES);
	list = malloc((size_t)n * RDC_RASTER_ENTRY_BYTES + 1);
	if (!list)
		return RDC_E_NOMEM;
	ret = rdc_vram_read(dev, rbase, list,
			    (size_t)n * RDC_RASTER_ENTRY_BYTES);
	for (k = 0; !ret && k < n; k++) {
		const uint8_t *e = list + (size_t)k * RDC_RASTER_ENTRY_BYTES;
		uint32_t w0 = rdc_ld32(e), w1 = rdc_ld32(e + 4);
		uint32_t op = FIELD_GET(RDC_RL_OP, w0);

		if (op == RDC_RL_WAIT) {
			uint32_t wy = FIELD_GET(RDC_RL_Y, w1);

			if (wy >= v_total)
				break;
			at = wait_met(at, wy, FIELD_GET(RDC_RL_X, w1), h_total);
			if (at >= BEAM_POS(v_total, 0))
				break;
			continue;
		}
		if (op == RDC_RL_REG)
			continue;
		if (op != RDC_RL_CLUT)
			break; /* END, or a bad entry */
		if (FIELD_GET(RDC_RL_ARG, w0) % RDC_CLUT_ENTRIES != c->index)
			continue;
		/* the last write before the pixel wins; else the frame's last */
		if (at > pixel && before)
			continue;
		any = true;
		before = at <= pixel;
		c->entry = k;
		c->addr = rbase + k * RDC_RASTER_ENTRY_BYTES;
		c->beam_x = (uint32_t)at;
		c->beam_y = (uint32_t)(at >> 32);
		c->value = w1 & 0x00ffffffu;
	}
	free(list);
	if (!ret && any)
		c->source = before ? RDC_HISTORY_CLUT_LIST :
				     RDC_HISTORY_CLUT_LIST_PREV;
	return ret;
}

int rdc_history_clut_sized(rdc_history *h, uint32_t x, uint32_t y,
			   struct rdc_history_clut *out)
{
	enum {
		FMT,
		BASE,
		STRIDE,
		HDISP,
		VDISP,
		HTOTAL,
		VTOTAL,
		RBASE,
		RCTRL,
		VSIZE
	};
	static const uint32_t regs[] = {
		[FMT] = RDC_REG_FB_FORMAT,     [BASE] = RDC_REG_FB_BASE,
		[STRIDE] = RDC_REG_FB_STRIDE,  [HDISP] = RDC_REG_H_DISPLAY,
		[VDISP] = RDC_REG_V_DISPLAY,   [HTOTAL] = RDC_REG_H_TOTAL,
		[VTOTAL] = RDC_REG_V_TOTAL,    [RBASE] = RDC_REG_RASTER_BASE,
		[RCTRL] = RDC_REG_RASTER_CTRL, [VSIZE] = RDC_REG_VRAM_SIZE,
	};
	struct rdc_history_clut c = { 0 };
	uint32_t v[RDC_ARRAY_SIZE(regs)], bpp;
	uint64_t addr;
	uint8_t b[4] = { 0 }; /* one byte read: an indexed pixel is <= 8 bits */
	int ret;

	if (!h || !out || out->size < sizeof(uint32_t) || !h->dev)
		return RDC_E_INVAL;
	ret = reg_reads(h->dev, regs, v, RDC_ARRAY_SIZE(regs));
	if (ret)
		return ret;
	if (x >= v[HDISP] || y >= v[VDISP])
		return RDC_E_RANGE;
	if (!rdc_format_indexed(v[FMT]))
		return 1;
	bpp = rdc_format_bpp(v[FMT]);
	addr = v[BASE] + (uint64_t)y * v[STRIDE] + (uint64_t)x * bpp / 8;
	if (addr >= v[VSIZE])
		return RDC_E_RANGE;
	ret = rdc_vram_read(h->dev, (uint32_t)addr, b, 1);
	if (ret)
		return ret;
	c.x = x;
	c.y = y;
	c.format = v[FMT];
	c.index = rdc_px_get(b, bpp, (x * bpp) % 8);
	c.source = RDC_HISTORY_CLUT_HOST;
	if (v[RCTRL] & RDC_RASTER_CTRL_EN)
		ret = clut_walk(h->dev, v[RBASE], v[RCTRL], v[VSIZE], v[HTOTAL],
				v[VTOTAL], &c);
	if (ret)
		return ret;
	c.size = RDC_MIN(out->size, (uint32_t)sizeof(c));
	memcpy(out, &c, c.size);
	if (out->size > sizeof(c))
		memset((char *)out + sizeof(c), 0, out->size - sizeof(c));
	return 0;
}

/*
 * A daemon's history whose device closes: every entry comes over first
 * (what cannot, for want of memory or a connection, is counted dropped).
 */
static void remote_detach(rdc_history *h)
{
	rdc_dev *dev = h->dev;
	uint64_t count = 0;

	if (!remote_fetch(h, 0, 0))
		count = h->rcount;
	if (count > SIZE_MAX / sizeof(*h->page))
		count = 0;
	if (count > h->page_cap) {
		struct rdc_history_entry *p =
			realloc(h->page, (size_t)count * sizeof(*p));

		if (p) {
			h->page = p;
			h->page_cap = (size_t)count;
		} else {
			count = 0;
		}
	}
	h->page_n = 0;
	h->page_first = 0;
	while (h->page_n < count) {
		uint32_t n = 0, max = (uint32_t)RDC_MIN(count - h->page_n,
							(uint64_t)REMOTE_PAGE);
		uint64_t c, d;

		if (dev->be->hist_read(dev, h->page_n, max, h->page + h->page_n,
				       &n, &c, &d) ||
		    !n)
			break;
		h->page_n += n;
		h->rdropped = d;
	}
	h->rdropped += h->rcount - h->page_n;
	dev->be->hist_close(dev);
	h->dev = NULL;
	dev->hist = NULL;
}

/* The device goes away first (rdc_close): keep what was recorded. */
void rdc_history_detach(rdc_dev *dev)
{
	struct rdc_history *h = dev ? dev->hist : NULL;

	if (!h)
		return;
	if (h->remote) {
		remote_detach(h);
		return;
	}
	hist_settle(h);
	rdc_hw_set_vram_hook(h->hw, NULL, NULL);
	h->hw = NULL;
	h->dev = NULL;
	dev->hist = NULL;
}

void rdc_history_close(rdc_history *h)
{
	if (!h)
		return;
	if (h->remote && h->dev) {
		h->dev->be->hist_close(h->dev);
		h->dev->hist = NULL;
	} else if (h->dev) {
		rdc_history_detach(h->dev);
	}
	free(h->page);
	free(h->rec);
	free(h->wr);
	free(h);
}
