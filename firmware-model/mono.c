// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* HOST_BLIT, MONO and TEXT: rows of pixels from command data. */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "raster.h"

/* Byte k of a little-endian word stream. */
static inline uint32_t word_byte(const uint32_t *w, uint32_t k)
{
	return (w[k / 4] >> (8 * (k % 4))) & 0xff;
}

/* Pixel at bit offset `bit` of a row of host words (same packing as VRAM). */
static uint32_t word_px(const uint32_t *w, unsigned int bpp, uint32_t bit)
{
	uint32_t k = bit / 8, v = 0;
	unsigned int i;

	if (bpp < 8)
		return (word_byte(w, k) >> (8 - bpp - (bit & 7))) &
		       fmt_mask(bpp);
	for (i = 0; i < bpp / 8; i++)
		v |= word_byte(w, k + i) << (8 * i);
	return v;
}

/*
 * Rows of pixels produced from command data: get(x) gives pixel x of row r
 * (relative to the rectangle) and whether it is drawn.  Shared by
 * HOST_BLIT, MONO and TEXT.
 */
struct row_src {
	unsigned int kind;
	const uint32_t *data;
	uint32_t wpr; /* words a data row */
	unsigned int bpp;
	uint32_t fg, bg;
	bool transparent;
};

enum { SRC_HOST, SRC_MONO, SRC_TEXT };

/* Byte k (8 pixels, bit 7 leftmost) of row r of a MONO or TEXT source. */
static inline uint32_t bits_byte(const struct row_src *rs, uint32_t r,
				 uint32_t k)
{
	if (rs->kind == SRC_MONO)
		return word_byte(rs->data + (size_t)r * rs->wpr, k);
	return rdc_font8x16[word_byte(rs->data, k) * 16 + r];
}

/*
 * Stage pixels [bx, bx + n) of row r of a MONO or TEXT source as FG/BG
 * in dp->px (set bits in dp->on): a byte of bits is fetched once for its
 * eight pixels.
 */
static void bits_expand(struct rdc_dp *dp, const struct row_src *rs, uint32_t r,
			uint32_t bx, uint32_t n)
{
	uint32_t i = 0, fg = rs->fg, bg = rs->bg;

	while (i < n) {
		uint32_t byte = bits_byte(rs, r, (bx + i) / 8);
		unsigned int b = (bx + i) % 8;

		for (; b < 8 && i < n; b++, i++) {
			uint32_t set = (byte >> (7 - b)) & 1;

			dp->px[i] = set ? fg : bg;
			dp->on[i] = (uint8_t)set;
		}
	}
}

/*
 * Two XRGB8888 pixels, a then b, as the 8 bytes VRAM holds them (VRAM is
 * little-endian), for 8-byte stores.
 */
static inline uint64_t px_pair(uint32_t a, uint32_t b)
{
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	return (uint64_t)b << 32 | a;
#else
	return (uint64_t)__builtin_bswap32(a) << 32 | __builtin_bswap32(b);
#endif
}

/*
 * A byte of bits is two 4-pixel groups of 16 bytes.  Group u (a nibble,
 * bit 3 the leftmost pixel) is BG with FG where u's bits are set: BG ^
 * (FG ^ BG) & mask[u], the masks a constant table.  A row of many glyphs
 * builds the sixteen groups once (quads_table) and copies them; a single
 * glyph (a command each, the console's way) computes its groups from the
 * masks, as the 16-byte reads of a table just built would wait for its
 * stores to retire.  A vector of two 64-bit halves: SSE2 where there is
 * SSE2, pairs of 64-bit operations elsewhere (the kernel, the MCU); kept
 * inline, as a vector is never passed or returned.
 */
typedef uint64_t mono_u64x2 __attribute__((__vector_size__(16)));

#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define MONO_LANE(k) (0xffffffffull << (32 * (k))) /* pixel k of a pair */
#else
#define MONO_LANE(k) (0xffffffffull << (32 * (1 - (k))))
#endif
#define MONO_HALF(a, b) (((a) ? MONO_LANE(0) : 0) | ((b) ? MONO_LANE(1) : 0))
#define MONO_QUAD(u) \
	{ \
		MONO_HALF((u)&8, (u)&4), MONO_HALF((u)&2, (u)&1) \
	}

static const mono_u64x2 mono_masks[16] = {
	MONO_QUAD(0),  MONO_QUAD(1),  MONO_QUAD(2),  MONO_QUAD(3),
	MONO_QUAD(4),  MONO_QUAD(5),  MONO_QUAD(6),  MONO_QUAD(7),
	MONO_QUAD(8),  MONO_QUAD(9),  MONO_QUAD(10), MONO_QUAD(11),
	MONO_QUAD(12), MONO_QUAD(13), MONO_QUAD(14), MONO_QUAD(15),
};

/*
 * A whole byte's two masks side by side, for byte_masks32 (8 KiB, read
 * only): the byte, shifted, finds both, where its nibbles would need a
 * mask and a shift each.
 */
#define MONO_OCT(u) \
	{ \
		MONO_QUAD((u) >> 4), MONO_QUAD((u)&15) \
	}
#define MONO_OCTS(h) \
	MONO_OCT(16 * (h) + 0), MONO_OCT(16 * (h) + 1), \
		MONO_OCT(16 * (h) + 2), MONO_OCT(16 * (h) + 3), \
		MONO_OCT(16 * (h) + 4), MONO_OCT(16 * (h) + 5), \
		MONO_OCT(16 * (h) + 6), MONO_OCT(16 * (h) + 7), \
		MONO_OCT(16 * (h) + 8), MONO_OCT(16 * (h) + 9), \
		MONO_OCT(16 * (h) + 10), MONO_OCT(16 * (h) + 11), \
		MONO_OCT(16 * (h) + 12), MONO_OCT(16 * (h) + 13), \
		MONO_OCT(16 * (h) + 14), MONO_OCT(16 * (h) + 15)

static const mono_u64x2 mono_octs[256][2] = {
	MONO_OCTS(0),  MONO_OCTS(1),  MONO_OCTS(2),  MONO_OCTS(3),
	MONO_OCTS(4),  MONO_OCTS(5),  MONO_OCTS(6),  MONO_OCTS(7),
	MONO_OCTS(8),  MONO_OCTS(9),  MONO_OCTS(10), MONO_OCTS(11),
	MONO_OCTS(12), MONO_OCTS(13), MONO_OCTS(14), MONO_OCTS(15),
};

struct mono_quads {
	mono_u64x2 bg, diff; /* BG in both halves; FG ^ BG */
	mono_u64x2 quad[16]; /* quads_table's */
};

static rdc_always_inline void quads_fill(struct mono_quads *t, uint32_t fg,
					 uint32_t bg)
{
	const uint64_t b = px_pair(bg, bg), d = px_pair(fg, fg) ^ b;

	t->bg = (mono_u64x2){ b, b };
	t->diff = (mono_u64x2){ d, d };
}

static rdc_always_inline void quads_table(struct mono_quads *t)
{
	unsigned int u;

#pragma GCC unroll 16
	for (u = 0; u < 16; u++)
		t->quad[u] = t->bg ^ (t->diff & mono_masks[u]);
}

/*
 * The 8 pixels of a byte of bits (bit 7 leftmost) at q, from the table.
 * A group is found by its byte offset in the table (16 bytes a group):
 * the high nibble masked is that offset already.
 */
static inline void byte_write32(uint8_t *q, const struct mono_quads *t,
				uint32_t byte)
{
	const uint8_t *g = (const uint8_t *)t->quad;

	rdc_memcpy(q, g + (byte & 0xf0), 16);
	rdc_memcpy(q + 16, g + (byte & 0x0f) * 16, 16);
}

/*
 * byte_write32 from the masks, for a glyph with no table, both masks
 * found by the byte; bits 0-7 of `bits` are the byte, the bits above
 * them ignored.
 */
static rdc_always_inline void
byte_masks32(uint8_t *q, const struct mono_quads *t, uint32_t bits)
{
	const mono_u64x2 *m = mono_octs[bits & 0xff];
	const mono_u64x2 l = t->bg ^ (t->diff & m[0]);
	const mono_u64x2 r = t->bg ^ (t->diff & m[1]);

	rdc_memcpy(q, &l, 16);
	rdc_memcpy(q + 16, &r, 16);
}

/*
 * Pixels [bx, bx + n) of row r of a MONO or TEXT source as XRGB8888 at q,
 * FG and BG both written: whole bytes of bits as two 4-pixel groups
 * (byte_write32); at the ragged ends, pixel by pixel.
 */
static void bits_write32(uint8_t *q, const struct row_src *rs,
			 const struct mono_quads *t, uint32_t r, uint32_t bx,
			 uint32_t n)
{
	uint32_t i = 0, bg = rs->bg, diff = rs->fg ^ rs->bg;
	unsigned int b;

	while (i < n) {
		uint32_t byte = bits_byte(rs, r, (bx + i) / 8);

		b = (bx + i) % 8;
		if (b == 0 && n - i >= 8) {
			byte_write32(q, t, byte);
			q += 32;
			i += 8;
			continue;
		}
		/* a set bit turns BG into FG: bg ^ (diff & -bit) */
		for (; b < 8 && i < n; b++, i++, q += 4)
			rdc_st32(q, bg ^ (diff & -((byte >> (7 - b)) & 1)));
	}
}

/*
 * `rows` rows of exactly one whole byte of a MONO source (bx a multiple
 * of 8), the console's 8-pixel glyph rows: the row loop without a call
 * or the ragged-end tests per row.
 */
static inline void mono8_rows32(uint8_t *q, uint32_t stride,
				const struct row_src *rs,
				const struct mono_quads *t, uint32_t r,
				uint32_t bx, uint32_t rows)
{
	/* in registers: the stores may alias *rs */
	const uint32_t wpr = rs->wpr, kb = bx / 8, sh = 8 * (kb % 4);
	const uint32_t *d = rs->data + (size_t)r * wpr + kb / 4;
	uint32_t k = 0;

	/*
	 * The byte first in its word (a glyph of up to 8 pixels,
	 * unclipped) needs no shift.  A glyph's sixteen rows of a word
	 * each (the console's MONO glyph, one a command) are written
	 * unrolled, their words at fixed offsets, with no loop to keep;
	 * other rows four a pass.
	 */
	if (!sh && wpr == 1 && rows == 16) {
#pragma GCC unroll 16
		for (k = 0; k < 16; k++)
			byte_masks32(q + k * stride, t, d[k]);
		return;
	}
	if (!sh) {
		for (; k + 4 <= rows; k += 4, q += 4 * stride, d += 4 * wpr) {
			byte_masks32(q, t, d[0]);
			byte_masks32(q + stride, t, d[wpr]);
			byte_masks32(q + 2 * stride, t, d[2 * wpr]);
			byte_masks32(q + 3 * stride, t, d[3 * wpr]);
		}
	}
	for (; k < rows; k++, q += stride, d += wpr)
		byte_masks32(q, t, d[0] >> sh);
}

/*
 * bits_write32 for `rows` rows at q, a stride apart: the whole bytes of
 * bits a column at a time, a glyph's rows with its font byte found once;
 * the ragged ends row by row.  The bytes are bits_write32's, all charged
 * before any is written, so their order is free.  Not inlined: its setup,
 * hoisted, would cost the console's glyphs as much as their rows.
 */
static rdc_noinline void bits_rows32(uint8_t *q, uint32_t stride,
				     const struct row_src *rs,
				     const struct mono_quads *t, uint32_t r,
				     uint32_t bx, uint32_t n, uint32_t rows)
{
	uint32_t head = RDC_MIN((8 - bx % 8) % 8, n);
	uint32_t bytes = (n - head) / 8, tail = n - head - 8 * bytes;
	uint32_t j, k, k0 = (bx + head) / 8;
	uint8_t *col = q + 4 * head, *p;

	for (k = k0; k < k0 + bytes; k++, col += 32) {
		p = col;
		if (rs->kind == SRC_TEXT) {
			const uint8_t *f =
				&rdc_font8x16[word_byte(rs->data, k) * 16 + r];

			for (j = 0; j < rows; j++, p += stride)
				byte_write32(p, t, f[j]);
		} else {
			const uint32_t wpr = rs->wpr;
			const uint32_t *d = rs->data + (size_t)r * wpr;

			for (j = 0; j < rows; j++, p += stride, d += wpr)
				byte_write32(p, t, word_byte(d, k));
		}
	}
	if (!head && !tail)
		return;
	for (j = 0; j < rows; j++, q += stride) {
		bits_write32(q, rs, t, r + j, bx, head);
		bits_write32(q + 4 * (n - tail), rs, t, r + j, bx + n - tail,
			     tail);
	}
}

/*
 * One span of rows_text32's, charged in the window w as rdc_port_span
 * would charge it: where it fits (tried if `fits`), across the line
 * start that falls in it, or between the window's close and reopening.
 * Where to write its bytes, or NULL where it leaves VRAM; its pixels
 * counted.
 */
static uint8_t *text_span(struct rdc_hw *hw, struct rdc_port_window *w,
			  uint32_t addr, uint32_t px, bool fits,
			  uint64_t *pixels)
{
	struct rdc_port_run one = { .addr = addr, .len = px * 4, .count = 1 };
	uint8_t *p;

	if ((fits && rdc_port_window_span(hw, w, addr, px * 4)) ||
	    rdc_port_window_cross(hw, w, &one, 0, RDC_BUS_WRITE)) {
		*pixels += px;
		return w->vram + addr;
	}
	rdc_port_window_close(hw, w);
	hw->perf.pixels += *pixels;
	*pixels = 0;
	p = rdc_port_span(hw, addr, px * 4, RDC_BUS_WRITE);
	if (p)
		hw->perf.pixels += px;
	rdc_port_window_open(hw, w);
	return p;
}

/*
 * Opaque MONO and TEXT rows in XRGB8888 with ROP COPY, the console's
 * case, expanded straight into VRAM with each row's spans charged as
 * span_emit charges them: one a row of up to RDC_DP_CHUNK pixels, where
 * the rows go in a port window together (rdc_port_window_rows_all),
 * else row by row (text_span); a wider row, a span a chunk, as
 * span_emit's caller cuts it.  Same spans, same order, same bytes.
 */
static rdc_always_inline void rows_text32(struct rdc_dp *dp, int32_t x,
					  int32_t y, int64_t xa, int64_t xb,
					  int64_t ya, int64_t yb,
					  const struct row_src *rs)
{
	const struct rdc_surface *s = &dp->st.dst;
	struct rdc_hw *hw = dp->hw;
	uint32_t n = (uint32_t)(xb - xa), bx = (uint32_t)(xa - x);
	uint32_t addr, rows, done, r, c, m;
	struct rdc_port_window w;
	struct mono_quads t;
	uint64_t pixels = 0;
	bool mono8;
	uint8_t *p;

	if (ya >= yb)
		return;
	mono8 = rs->kind == SRC_MONO && n == 8 && bx % 8 == 0;
	quads_fill(&t, rs->fg, rs->bg);
	if (!mono8)
		quads_table(&t);
	addr = s->base + (uint32_t)ya * s->stride + (uint32_t)xa * 4;
	rows = (uint32_t)(yb - ya);
	r = (uint32_t)(ya - y);
	rdc_port_window_open_busy(hw, &w);
	while (rows) {
		done = n <= RDC_DP_CHUNK ?
			       rdc_port_window_rows_all(hw, &w, addr, n * 4,
							s->stride, rows) :
			       0;
		if (done && mono8)
			mono8_rows32(w.vram + addr, s->stride, rs, &t, r, bx,
				     done);
		else if (done)
			bits_rows32(w.vram + addr, s->stride, rs, &t, r, bx, n,
				    done);
		pixels += (uint64_t)done * n;
		r += done;
		addr += done * s->stride;
		rows -= done;
		if (!rows)
			break;
		/* the next row span by span: wide, or the window ends in it */
		for (c = 0; c < n; c += m) {
			m = RDC_MIN(n - c, RDC_DP_CHUNK);
			p = text_span(hw, &w, addr + 4 * c, m, n > RDC_DP_CHUNK,
				      &pixels);
			if (p && mono8)
				mono8_rows32(p, 0, rs, &t, r, bx, 1);
			else if (p)
				bits_write32(p, rs, &t, r, bx + c, m);
		}
		r++;
		addr += s->stride;
		rows--;
	}
	rdc_port_window_close(hw, &w);
	hw->perf.pixels += pixels;
}

/*
 * HOST_BLIT of 8, 16 or 32 bpp pixels with ROP COPY, no colour key and
 * nothing to blend, the case of a driver uploading a framebuffer: each
 * chunk's span is charged as dp_blit_span charges it (a plain write) and
 * the host's pixels are stored straight from its words, not staged in
 * dp->px first.  Same spans, same order, same bytes.
 */
static bool host_copy_ok(const struct rdc_dp *dp, unsigned int bpp)
{
	const struct rdc_dp_state *st = &dp->st;

	return !dp->ref_paths && st->rop == RDC_ROP_COPY && !st->colorkey_on &&
	       (st->alpha == RDC_ALPHA_OPAQUE ||
		rdc_format_indexed(st->dst.format)) &&
	       (bpp == 8 || bpp == 16 || bpp == 32);
}

static void host_rows_copy(struct rdc_dp *dp, int32_t x, int32_t y, int64_t xa,
			   int64_t xb, int64_t ya, int64_t yb,
			   const struct row_src *rs)
{
	const struct rdc_surface *s = &dp->st.dst;
	uint32_t bytes = rs->bpp / 8, n, i;
	int64_t row, col;
	uint8_t *p;

	for (row = ya; row < yb; row++) {
		const uint32_t *d = rs->data + (size_t)(row - y) * rs->wpr;

		for (col = xa; col < xb; col += RDC_DP_CHUNK) {
			uint32_t bx = (uint32_t)(col - x);

			n = (uint32_t)RDC_MIN(xb - col, (int64_t)RDC_DP_CHUNK);
			p = rdc_port_span(dp->hw,
					  s->base + (uint32_t)row * s->stride +
						  (uint32_t)col * bytes,
					  n * bytes, RDC_BUS_WRITE);
			if (!p)
				continue;
			switch (bytes) {
			case 4:
				for (i = 0; i < n; i++)
					rdc_st32(p + 4 * i, d[bx + i]);
				break;
			case 2:
				for (i = 0; i < n; i++)
					rdc_st16(p + 2 * i,
						 d[(bx + i) / 2] >>
							 (16 * ((bx + i) % 2)));
				break;
			default:
				for (i = 0; i < n; i++)
					p[i] = (uint8_t)word_byte(d, bx + i);
				break;
			}
			dp->hw->perf.pixels += n;
		}
	}
}

static void rows_draw(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const struct row_src *rs)
{
	/* where the clip is empty, xa >= xb or ya >= yb: nothing drawn */
	struct rdc_rect c = rdc_dp_clip_bounds(dp);
	int64_t xa = RDC_MAX((int64_t)x, (int64_t)c.x0);
	int64_t xb = RDC_MIN((int64_t)x + w, (int64_t)c.x1); /* exclusive */
	int64_t ya = RDC_MAX((int64_t)y, (int64_t)c.y0);
	int64_t yb = RDC_MIN((int64_t)y + h, (int64_t)c.y1);
	int64_t row, col;

	if (rs->kind != SRC_HOST && !rs->transparent && !dp->ref_paths &&
	    dp->st.rop == RDC_ROP_COPY &&
	    dp->st.dst.format == RDC_FMT_XRGB8888 && xa < xb) {
		rows_text32(dp, x, y, xa, xb, ya, yb, rs);
		return;
	}
	if (rs->kind == SRC_HOST && host_copy_ok(dp, rs->bpp)) {
		host_rows_copy(dp, x, y, xa, xb, ya, yb, rs);
		return;
	}

	for (row = ya; row < yb; row++) {
		uint32_t r = (uint32_t)(row - y);

		for (col = xa; col < xb; col += RDC_DP_CHUNK) {
			uint32_t n = (uint32_t)RDC_MIN(xb - col,
						       (int64_t)RDC_DP_CHUNK);
			uint32_t i;

			if (rs->kind != SRC_HOST && !dp->ref_paths) {
				bits_expand(dp, rs, r, (uint32_t)(col - x), n);
				rdc_dp_span_px(dp, (int32_t)row, (int32_t)col,
					       n, 0, dp->px,
					       rs->transparent ? dp->on : NULL);
				continue;
			}
			for (i = 0; i < n; i++) {
				uint32_t bx = (uint32_t)(col - x) + i;
				uint32_t bit;
				bool set;

				switch (rs->kind) {
				case SRC_HOST:
					dp->px[i] = word_px(
						rs->data + (size_t)r * rs->wpr,
						rs->bpp, bx * rs->bpp);
					dp->on[i] = 1;
					continue;
				case SRC_MONO:
					bit = word_byte(
						rs->data + (size_t)r * rs->wpr,
						bx / 8);
					break;
				default: /* SRC_TEXT: r is the glyph row */
					bit = rdc_font8x16[word_byte(rs->data,
								     bx / 8) *
								   16 +
							   r];
					break;
				}
				set = (bit >> (7 - bx % 8)) & 1;
				dp->px[i] = set ? rs->fg : rs->bg;
				dp->on[i] = set;
			}
			if (rs->kind == SRC_HOST)
				dp_blit_span(dp, (int32_t)row, (int32_t)col, n);
			else
				rdc_dp_span_px(dp, (int32_t)row, (int32_t)col,
					       n, 0, dp->px,
					       rs->transparent ? dp->on : NULL);
		}
	}
}

void rdc_dp_host_blit(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const uint32_t *data)
{
	unsigned int fmt = dp->st.dst.format;
	struct row_src rs = {
		.kind = SRC_HOST,
		.data = data,
		.wpr = rdc_dp_words_per_row(fmt, w),
		.bpp = rdc_format_bpp(fmt),
	};

	if (blit_drawn(dp))
		rows_draw(dp, x, y, w, h, &rs);
}

void rdc_dp_mono(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, const uint32_t *data, bool transparent)
{
	struct row_src rs = {
		.kind = SRC_MONO,
		.data = data,
		.wpr = rdc_dp_words_per_row(RDC_FMT_I1, w),
		.fg = dp->st.fg,
		.bg = dp->st.bg,
		.transparent = transparent,
	};

	rows_draw(dp, x, y, w, h, &rs);
}

#define RDC_GLYPH_W 8
#define RDC_GLYPH_H 16

/* One span per glyph row across the whole string. */
void rdc_dp_text(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t count,
		 const uint32_t *chars, bool transparent)
{
	struct row_src rs = {
		.kind = SRC_TEXT,
		.data = chars,
		.fg = dp->st.fg,
		.bg = dp->st.bg,
		.transparent = transparent,
	};

	rows_draw(dp, x, y, count * RDC_GLYPH_W, RDC_GLYPH_H, &rs);
}
