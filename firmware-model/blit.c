// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* BLIT through the ROPs, the colour key and global alpha; READBACK. */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "raster.h"

/*
 * Clip a source rectangle against [0, sw) x [0, sh) and its destination
 * against the clip, shrinking both together.  False if nothing remains.
 */
static bool clip_pair(const struct rdc_rect *c, int64_t sw, int64_t sh,
		      int64_t *sx, int64_t *sy, int64_t *dx, int64_t *dy,
		      int64_t *w, int64_t *h)
{
	int64_t d;

	if (*sx < 0)
		*dx -= *sx, *w += *sx, *sx = 0;
	if (*sy < 0)
		*dy -= *sy, *h += *sy, *sy = 0;
	*w = RDC_MIN(*w, sw - *sx);
	*h = RDC_MIN(*h, sh - *sy);
	if (*dx < c->x0)
		d = c->x0 - *dx, *sx += d, *dx += d, *w -= d;
	if (*dy < c->y0)
		d = c->y0 - *dy, *sy += d, *dy += d, *h -= d;
	*w = RDC_MIN(*w, c->x1 - *dx);
	*h = RDC_MIN(*h, c->y1 - *dy);
	return *w > 0 && *h > 0;
}

/*
 * Screen-to-screen copy.  Pieces of at most RDC_DP_CHUNK pixels are read
 * whole before they are written, and visited in descending address order
 * when the destination lies above the source (ascending otherwise), as
 * memmove does, so any overlap of the two rectangles copies correctly.
 */
/*
 * Write the staged pixels dp->px[0, n) of a BLIT or HOST_BLIT to DST row y
 * from xa (inside the clip), in this order: the colour key drops source
 * pixels equal to it (compared in the source format, masked to its pixel
 * size), the ROP combines the others with the destination, and a global
 * alpha below opaque blends that result over the destination
 * (rdc_dp_blend; one read-modify-write span).  Indexed formats have no
 * blend: blit_drawn() lets them draw only at alpha >= RDC_ALPHA_THRESHOLD.
 */
void dp_blit_span(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n)
{
	const struct rdc_dp_state *st = &dp->st;
	unsigned int fmt = st->dst.format, bpp = rdc_format_bpp(fmt);
	uint32_t mask = fmt_mask(bpp), key = st->colorkey & mask, i, cnt = 0;
	bool blend = st->alpha != RDC_ALPHA_OPAQUE && !rdc_format_indexed(fmt);
	uint64_t bit0 = (uint64_t)xa * bpp, bit1 = bit0 + (uint64_t)n * bpp;
	uint8_t *p;

	if (st->colorkey_on)
		for (i = 0; i < n; i++)
			dp->on[i] = dp->px[i] != key;
	if (!blend) {
		rdc_dp_span_px(dp, y, xa, n, 0, dp->px,
			       st->colorkey_on ? dp->on : NULL);
		return;
	}
	p = rdc_port_span(dp->hw,
			  st->dst.base + (uint32_t)y * st->dst.stride +
				  (uint32_t)(bit0 / 8),
			  (uint32_t)((bit1 + 7) / 8 - bit0 / 8), RDC_BUS_RMW);
	if (!p)
		return;
	for (i = 0; i < n; i++) {
		uint32_t bit = (uint32_t)(bit0 & 7) + i * bpp, d;

		if (st->colorkey_on && !dp->on[i])
			continue;
		d = rdc_px_get(p, bpp, bit);
		rdc_px_put(p, bpp, bit,
			   rdc_dp_blend(fmt,
					rdc_rop_apply(st->rop, dp->px[i], d) &
						mask,
					d, st->alpha) &
				   mask);
		cnt++;
	}
	dp->hw->perf.pixels += cnt;
}

/*
 * d[i] = rop(s[i], d[i]) for len bytes.  The ROPs are bitwise, so for
 * pixels of whole bytes this is the per-pixel ROP; the switch is outside
 * the loop so each case is a plain loop the compiler can widen.
 */
#define ROP_BLOCK 32u
static rdc_always_inline void rop_bytes_as(unsigned int r, uint8_t *restrict d,
					   const uint8_t *restrict s,
					   uint32_t len)
{
	uint32_t i;

	for (; len >= ROP_BLOCK; len -= ROP_BLOCK) {
		for (i = 0; i < ROP_BLOCK; i++)
			d[i] = (uint8_t)rdc_rop_apply(r, s[i], d[i]);
		d += ROP_BLOCK;
		s += ROP_BLOCK;
	}
	/* the rest a 32-bit word at a time (a row's last pixels), not bytes */
	for (; len >= 4; len -= 4, d += 4, s += 4) {
		uint32_t a, b;

		rdc_memcpy(&a, s, 4);
		rdc_memcpy(&b, d, 4);
		b = rdc_rop_apply(r, a, b);
		rdc_memcpy(d, &b, 4);
	}
	for (i = 0; i < len; i++)
		d[i] = (uint8_t)rdc_rop_apply(r, s[i], d[i]);
}

/*
 * d and s do not overlap; blocks of a fixed size with restrict let the
 * compiler use wide registers (kept out of line, where restrict holds).
 */
static rdc_noinline void rop_bytes(uint8_t *restrict d,
				   const uint8_t *restrict s, uint32_t len,
				   unsigned int rop)
{
	switch (rop) {
	case RDC_ROP_COPY:
		rdc_memcpy(d, s, len);
		break;
	case RDC_ROP_CLEAR:
		rop_bytes_as(RDC_ROP_CLEAR, d, s, len);
		break;
	case RDC_ROP_AND:
		rop_bytes_as(RDC_ROP_AND, d, s, len);
		break;
	case RDC_ROP_AND_REVERSE:
		rop_bytes_as(RDC_ROP_AND_REVERSE, d, s, len);
		break;
	case RDC_ROP_AND_INVERTED:
		rop_bytes_as(RDC_ROP_AND_INVERTED, d, s, len);
		break;
	case RDC_ROP_NOOP:
		rop_bytes_as(RDC_ROP_NOOP, d, s, len);
		break;
	case RDC_ROP_XOR:
		rop_bytes_as(RDC_ROP_XOR, d, s, len);
		break;
	case RDC_ROP_OR:
		rop_bytes_as(RDC_ROP_OR, d, s, len);
		break;
	case RDC_ROP_NOR:
		rop_bytes_as(RDC_ROP_NOR, d, s, len);
		break;
	case RDC_ROP_EQUIV:
		rop_bytes_as(RDC_ROP_EQUIV, d, s, len);
		break;
	case RDC_ROP_INVERT:
		rop_bytes_as(RDC_ROP_INVERT, d, s, len);
		break;
	case RDC_ROP_OR_REVERSE:
		rop_bytes_as(RDC_ROP_OR_REVERSE, d, s, len);
		break;
	case RDC_ROP_COPY_INVERTED:
		rop_bytes_as(RDC_ROP_COPY_INVERTED, d, s, len);
		break;
	case RDC_ROP_OR_INVERTED:
		rop_bytes_as(RDC_ROP_OR_INVERTED, d, s, len);
		break;
	case RDC_ROP_NAND:
		rop_bytes_as(RDC_ROP_NAND, d, s, len);
		break;
	default:
		rop_bytes_as(RDC_ROP_SET, d, s, len);
		break;
	}
}

/* len bytes from src to p through the ROP, overlap-safe. */
static inline void blit_bytes(struct rdc_dp *dp, uint8_t *p, const uint8_t *src,
			      uint32_t len)
{
	unsigned int rop = dp->st.rop;

	if (rop == RDC_ROP_COPY) {
		/*
		 * The C library's copy, the length hidden so that it stays
		 * a call: its vector loop outran the core's own 16-byte
		 * copy of a row on one machine (rdc-bench blit with scanout
		 * off in 0.78 to 0.84 of the time) and is within the noise
		 * of it on another (an AMD EPYC), and memmove's test for
		 * overlap is its own.
		 */
		size_t n = len;

		rdc_hide_var(n);
		rdc_memmove(p, src, n);
	} else if (src + len <= p || p + len <= src) {
		rop_bytes(p, src, len, rop);
	} else {
		rdc_memcpy(dp->px, src, len);
		rop_bytes(p, (const uint8_t *)dp->px, len, rop);
	}
}

/*
 * BLIT's fast path, for SRC and DST of the same whole-byte format with no
 * colour key and no blend: n pixels read from saddr go to DST row y from
 * xa through the ROP byte by byte, charged as the read span and the write
 * span, then moved straight from SRC to DST when the two do not
 * overlap (memmove for COPY even when they do); an overlapping ROP stages
 * the source first, as the per-pixel path does.
 */
static void blit_row(struct rdc_dp *dp, uint32_t saddr, int32_t y, int32_t xa,
		     uint32_t n)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rdc_format_bpp(s->format) / 8, len = n * bytes;
	unsigned int rop = dp->st.rop;
	const uint8_t *src;
	uint8_t *p;

	p = rdc_port_span_pair(
		dp->hw, saddr,
		s->base + (uint32_t)y * s->stride + (uint32_t)xa * bytes, len,
		rdc_rop_reads_dst(rop) ? RDC_BUS_RMW : RDC_BUS_WRITE, &src);
	if (!p)
		return;
	blit_bytes(dp, p, src, len);
	dp->hw->perf.pixels += n;
}

/*
 * The row blit_rows' window refuses, daddr its destination: the pair
 * charged in the window across the line start that falls in it
 * (rdc_port_window_cross), or as blit_row's port calls charge it, and
 * the bytes moved.  The window may have charged some of it already
 * (win->parted, rdc_port_window_pairs_through).
 */
static void blit_row_window(struct rdc_dp *dp, struct rdc_port_window *win,
			    uint32_t saddr, uint32_t daddr, int32_t y,
			    int32_t xa, uint32_t n, unsigned int kind)
{
	struct rdc_hw *hw = dp->hw;
	uint32_t len = n * (rdc_format_bpp(dp->st.dst.format) / 8);
	const struct rdc_port_run rr = { saddr, len, 1 },
				  wr = { daddr, len, 1 };
	uint8_t *p;
	bool moved;

	if (win->parted == RDC_PARTED_WRITE) {
		/* blit_rows' window charged the read, and the write in part */
		moved = rdc_port_window_cross(hw, win, &wr, 0, kind);
	} else {
		if (win->parted == RDC_PARTED_READ) {
			win->parted = 0; /* blit_rows' window charged it */
		} else if (!rdc_port_window_cross(hw, win, &rr, 0,
						  RDC_BUS_READ)) {
			rdc_port_window_close(hw, win);
			blit_row(dp, saddr, y, xa, n);
			rdc_port_window_open(hw, win);
			return;
		}
		moved = rdc_port_window_charge(hw, win, &wr, 0, kind) ||
			rdc_port_window_cross(hw, win, &wr, 0, kind);
	}
	if (moved) {
		blit_bytes(dp, win->vram + daddr, win->vram + saddr, len);
		hw->perf.pixels += n;
		return;
	}
	/* the read charged: the write as rdc_port_span_pair's second call */
	rdc_port_window_close(hw, win);
	p = rdc_port_span(hw, daddr, len, kind);
	if (p) {
		blit_bytes(dp, p, hw->vram + saddr, len);
		hw->perf.pixels += n;
	}
	rdc_port_window_open(hw, win);
}

/*
 * n rows of COPY, as blit_bytes moves them, with the ROP's test made once
 * for them all: the rows are most of a blit's time beside memmove's.
 * Out of line, the loop has the callee-saved registers to itself and
 * reloads nothing from the stack around each call.  The source is kept
 * as its offset from the destination, which memmove returns: one
 * pointer to carry across the call.
 */
static rdc_noinline void blit_copies(uint8_t *p, const uint8_t *src,
				     uint32_t len, int64_t sstep, int64_t dstep,
				     uint32_t n)
{
	int64_t off = src - p;
	size_t bytes = len;

	rdc_hide_var(bytes);
	if (!n)
		return;
	for (;;) {
		p = rdc_memmove(p, p + off, bytes);
		if (!--n)
			break;
		off += sstep - dstep;
		p += dstep;
	}
}

/*
 * The fast path's rows, each one piece (w <= RDC_DP_CHUNK) and no VRAM
 * watcher: the pairs the window takes are charged together and their
 * bytes moved row by row in the same order; the row the window stops at
 * goes to blit_row, as it would one row at a time.
 */
static void blit_rows(struct rdc_dp *dp, uint32_t saddr, uint32_t daddr,
		      int32_t dy, int32_t dx, uint32_t n, uint32_t h, bool back)
{
	const struct rdc_surface *ss = &dp->st.src, *ds = &dp->st.dst;
	uint32_t len = n * (rdc_format_bpp(ds->format) / 8), k = 0, done, i;
	int64_t sstep = back ? -(int64_t)ss->stride : (int64_t)ss->stride;
	int64_t dstep = back ? -(int64_t)ds->stride : (int64_t)ds->stride;
	unsigned int kind = rdc_rop_reads_dst(dp->st.rop) ? RDC_BUS_RMW :
							    RDC_BUS_WRITE;
	bool copy = dp->st.rop == RDC_ROP_COPY;
	struct rdc_hw *hw = dp->hw;
	struct rdc_port_window win;

	rdc_port_window_open(hw, &win);
	for (;;) {
		done = rdc_port_window_pairs_through(
			hw, &win, saddr, daddr, len, sstep, dstep, h - k, kind);
		if (copy) {
			blit_copies(win.vram + daddr, win.vram + saddr, len,
				    sstep, dstep, done);
			saddr += (uint32_t)(sstep * done);
			daddr += (uint32_t)(dstep * done);
		} else {
			for (i = 0; i < done; i++) {
				blit_bytes(dp, win.vram + daddr,
					   win.vram + saddr, len);
				saddr += (uint32_t)sstep;
				daddr += (uint32_t)dstep;
			}
		}
		hw->perf.pixels += (uint64_t)done * n;
		k += done;
		if (k == h)
			break;
		blit_row_window(dp, &win, saddr, daddr,
				dy + (int32_t)(back ? h - 1 - k : k), dx, n,
				kind);
		saddr += (uint32_t)sstep;
		daddr += (uint32_t)dstep;
		if (++k == h)
			break;
	}
	rdc_port_window_close(hw, &win);
}

/*
 * rdc_dp_blit's rows piece by piece, the clipped rectangles from (sx, sy)
 * and (dx, dy): those of the fast path (a ROP byte by byte) in a port
 * window, the others pixel by pixel.  Out of line, as blit_rows takes
 * most blits: rdc_dp_blit keeps fewer values across its calls.
 */
static rdc_noinline void blit_pieces(struct rdc_dp *dp, int64_t sx, int64_t sy,
				     int64_t dx, int64_t dy, int64_t w,
				     int64_t h, bool back, bool fast)
{
	const struct rdc_surface *ss = &dp->st.src, *ds = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(ss->format);
	unsigned int kind = rdc_rop_reads_dst(dp->st.rop) ? RDC_BUS_RMW :
							    RDC_BUS_WRITE;
	struct rdc_hw *hw = dp->hw;
	struct rdc_port_window win;
	int64_t k;

	if (fast)
		rdc_port_window_open(hw, &win);
	for (k = 0; k < h; k++) {
		int64_t row = back ? h - 1 - k : k;
		int64_t done;

		for (done = 0; done < w; done += RDC_DP_CHUNK) {
			uint32_t n = (uint32_t)RDC_MIN(w - done,
						       (int64_t)RDC_DP_CHUNK);
			int64_t off = back ? w - done - n : done;
			uint64_t b0 = (uint64_t)(sx + off) * bpp;
			uint64_t b1 = b0 + (uint64_t)n * bpp;
			uint32_t addr = ss->base +
					(uint32_t)(sy + row) * ss->stride +
					(uint32_t)(b0 / 8);
			const uint8_t *p;
			uint32_t i;

			if (fast) {
				uint32_t len = n * (bpp / 8);
				uint32_t daddr =
					ds->base +
					(uint32_t)(dy + row) * ds->stride +
					(uint32_t)(dx + off) * (bpp / 8);

				if (rdc_port_window_pair(hw, &win, addr, daddr,
							 len, kind)) {
					blit_bytes(dp, win.vram + daddr,
						   win.vram + addr, len);
					hw->perf.pixels += n;
					continue;
				}
				rdc_port_window_close(hw, &win);
				blit_row(dp, addr, (int32_t)(dy + row),
					 (int32_t)(dx + off), n);
				rdc_port_window_open(hw, &win);
				continue;
			}
			p = rdc_port_span(dp->hw, addr,
					  (uint32_t)((b1 + 7) / 8 - b0 / 8),
					  RDC_BUS_READ);
			if (!p)
				continue;
			for (i = 0; i < n; i++)
				dp->px[i] = rdc_px_get(
					p, bpp, (uint32_t)(b0 & 7) + i * bpp);
			dp_blit_span(dp, (int32_t)(dy + row),
				     (int32_t)(dx + off), n);
		}
	}
	if (fast)
		rdc_port_window_close(hw, &win);
}

void rdc_dp_blit(struct rdc_dp *dp, int32_t sx32, int32_t sy32, int32_t dx32,
		 int32_t dy32, uint32_t w32, uint32_t h32)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	const struct rdc_surface *ss = &dp->st.src, *ds = &dp->st.dst;
	unsigned int bpp = rdc_format_bpp(ss->format);
	int64_t sx = sx32, sy = sy32, dx = dx32, dy = dy32, w = w32, h = h32;
	struct rdc_hw *hw = dp->hw;
	uint64_t sbit, dbit;
	bool back, fast;

	if (!blit_drawn(dp) ||
	    !clip_pair(&c, ss->width, ss->height, &sx, &sy, &dx, &dy, &w, &h))
		return;
	sbit = (uint64_t)ss->base * 8 + (uint64_t)sy * ss->stride * 8 +
	       (uint64_t)sx * bpp;
	dbit = (uint64_t)ds->base * 8 + (uint64_t)dy * ds->stride * 8 +
	       (uint64_t)dx * bpp;
	back = dbit > sbit;
	fast = !dp->ref_paths && ss->format == ds->format && bpp >= 8 &&
	       !dp->st.colorkey_on &&
	       (dp->st.alpha == RDC_ALPHA_OPAQUE ||
		rdc_format_indexed(ds->format));

	/*
	 * The fast rows are charged as read/write pairs in a port window
	 * and their bytes moved at once; a pair the window refuses goes to
	 * blit_row's rdc_port_span_pair, as every row otherwise would.
	 */
	if (fast && w <= RDC_DP_CHUNK && !hw->vram_hook) {
		int64_t row0 = back ? h - 1 : 0;

		blit_rows(dp,
			  ss->base + (uint32_t)(sy + row0) * ss->stride +
				  (uint32_t)sx * (bpp / 8),
			  ds->base + (uint32_t)(dy + row0) * ds->stride +
				  (uint32_t)dx * (bpp / 8),
			  (int32_t)dy, (int32_t)dx, (uint32_t)w, (uint32_t)h,
			  back);
		return;
	}
	blit_pieces(dp, sx, sy, dx, dy, w, h, back, fast);
}

void rdc_dp_readback_pack(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
			  uint32_t row, uint32_t word, uint32_t n,
			  uint32_t *out)
{
	const struct rdc_surface *s = &dp->st.src;
	unsigned int bpp = rdc_format_bpp(s->format);
	uint64_t byte0 = (uint64_t)word * 4, byte1 = byte0 + (uint64_t)n * 4;
	int64_t k0 = (int64_t)(byte0 * 8 / bpp);
	int64_t k1 =
		RDC_MIN((int64_t)((byte1 * 8 + bpp - 1) / bpp), (int64_t)w);
	int64_t sy = (int64_t)y + row, va, vb, k;
	const uint8_t *p = NULL;
	uint64_t pbit0 = 0;

	rdc_memset(out, 0, (size_t)n * 4);
	if (sy < 0 || sy >= s->height)
		return;
	/* the part of pixels [k0, k1) that lies on the surface */
	va = RDC_MAX(k0, -(int64_t)x);
	vb = RDC_MIN(k1, (int64_t)s->width - x);
	if (va >= vb)
		return;
	pbit0 = (uint64_t)(x + va) * bpp;
	p = rdc_port_span(
		dp->hw,
		s->base + (uint32_t)sy * s->stride + (uint32_t)(pbit0 / 8),
		(uint32_t)(((uint64_t)(x + vb) * bpp + 7) / 8 - pbit0 / 8),
		RDC_BUS_READ);
	if (!p)
		return;
	for (k = va; k < vb; k++) {
		uint32_t v = rdc_px_get(
			p, bpp, (uint32_t)((pbit0 & 7) + (k - va) * bpp));
		uint64_t kb = (uint64_t)k * bpp;
		unsigned int i;

		if (bpp < 8) {
			uint64_t byte = kb / 8 - byte0;

			out[byte / 4] |= (v << (8 - bpp - (kb & 7)))
					 << (8 * (byte % 4));
			continue;
		}
		for (i = 0; i < bpp / 8; i++) {
			uint64_t byte = kb / 8 + i;

			if (byte < byte0 || byte >= byte1)
				continue;
			byte -= byte0;
			out[byte / 4] |= ((v >> (8 * i)) & 0xff)
					 << (8 * (byte % 4));
		}
	}
}
