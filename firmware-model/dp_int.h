/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Display-processor internals shared by the decoder (dp.c) and the
 * rasterisers (span.c, line.c, shape.c, blit.c, mono.c and the others;
 * what only those five share is in raster.h).  Arguments reaching these
 * functions have been range-checked by the decoder: coordinates in
 * [RDC_COORD_MIN, RDC_COORD_MAX], sizes and radii in [0, RDC_SIZE_MAX],
 * surfaces inside VRAM.  Everything is clipped here against
 * rdc_dp_eff_clip().
 */
#ifndef RDC_DP_INT_H
#define RDC_DP_INT_H

#include "dp.h"

/*
 * The clip rectangle intersected with the destination surface, its
 * bounds only: where that is empty, x1 < x0 or y1 < y0 may hold.  For
 * callers that only bound a shape by it (a line, a glyph: every command
 * asks, so inline), an inverted rectangle bounds it to nothing as an
 * empty one does.
 */
static inline struct rdc_rect rdc_dp_clip_bounds(const struct rdc_dp *dp)
{
	struct rdc_rect r = dp->st.clip;

	r.x0 = RDC_MAX(r.x0, 0);
	r.y0 = RDC_MAX(r.y0, 0);
	r.x1 = RDC_MIN(r.x1, (int32_t)dp->st.dst.width);
	r.y1 = RDC_MIN(r.y1, (int32_t)dp->st.dst.height);
	return r;
}

/* The same, empty as x1 == x0 or y1 == y0: x0 <= x1 and y0 <= y1. */
static inline struct rdc_rect rdc_dp_eff_clip(const struct rdc_dp *dp)
{
	struct rdc_rect r = rdc_dp_clip_bounds(dp);

	if (r.x1 < r.x0)
		r.x1 = r.x0;
	if (r.y1 < r.y0)
		r.y1 = r.y0;
	return r;
}

void rdc_dp_pixel(struct rdc_dp *dp, int32_t x, int32_t y);
/*
 * skip_first/skip_last leave out the endpoint pixel (x0, y0) / (x1, y1);
 * POLYLINE uses them so shared vertices are drawn once.
 */
void rdc_dp_line(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		 int32_t y1, bool skip_first, bool skip_last);
/*
 * Steps [first, last] of the same line, step 0 being (x0, y0) and step
 * max(|dx|, |dy|) being (x1, y1): dashes draw their pieces with it.
 */
void rdc_dp_line_steps(struct rdc_dp *dp, int32_t x0, int32_t y0, int32_t x1,
		       int32_t y1, int64_t first, int64_t last);
/*
 * Between rdc_dp_queue_begin and rdc_dp_queue_end, solid FG spans and
 * columns (span_fill, col_fill, an unpatterned dp_fill_span) are queued
 * and charged in bulk (a port window's runs), in their order, with the same
 * pixels and cycles; begin does nothing where the queue cannot be used.
 * Nothing else may touch VRAM in between.  rdc_dp_queue_span is
 * dp_fill_span's way in: [xa, xb] of row y, inside the clip.
 */
void rdc_dp_queue_begin(struct rdc_dp *dp);
void rdc_dp_queue_end(struct rdc_dp *dp);
void rdc_dp_queue_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb);

/* Solid FG span [xa, xb] of row y, clipped. */
void rdc_dp_span(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb);
/*
 * Write pixels [xa, xa + n) of DST row y, already inside the effective
 * clip, as one bus span: vals == NULL gives every pixel `solid`, else
 * pixel i gets vals[i]; on != NULL writes only pixels with on[i] set (a
 * read-modify-write span).  The ROP applies.  n <= RDC_DP_CHUNK when vals
 * or on point at dp->px / dp->on.
 */
void rdc_dp_span_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t solid, const uint32_t *vals, const uint8_t *on);
/*
 * Read pixels [xa, xa + n) of DST row y (inside DST) as one read span; false
 * (out untouched) if the span leaves VRAM.
 */
bool rdc_dp_read_px(struct rdc_dp *dp, int32_t y, int32_t xa, uint32_t n,
		    uint32_t *out);
/* The same for row y of any surface s (inside s). */
bool rdc_dp_read_row(struct rdc_dp *dp, const struct rdc_surface *s, int32_t y,
		     int32_t xa, uint32_t n, uint32_t *out);
/*
 * Pixel at bit offset `bit` from p in a surface of `bpp` bits per pixel
 * (sub-byte pixels MSB first); the store masks v to bpp bits.
 */
uint32_t rdc_dp_px_load(const uint8_t *p, unsigned int bpp, uint32_t bit);
void rdc_dp_px_store(uint8_t *p, unsigned int bpp, uint32_t bit, uint32_t v);

/*
 * Anti-aliasing (aa.c).  rdc_dp_aa_cmd checks, transforms and draws
 * AA_LINE, AA_CIRCLE or AA_ELLIPSE with arguments a; returns an enum
 * rdc_err.  rdc_dp_blend mixes src over dst with weight a / 255 per
 * channel of an RGB format: (s * a + d * (255 - a) + 127) / 255; for an
 * indexed format it picks src when a >= RDC_ALPHA_THRESHOLD, else dst.
 */
uint32_t rdc_dp_aa_cmd(struct rdc_dp *dp, uint32_t op, const uint32_t *a);
uint32_t rdc_dp_blend(unsigned int fmt, uint32_t src, uint32_t dst, uint32_t a);

/*
 * Filled-primitive helpers (pattern.c, poly.c).  dp_fill_span fills
 * [x0, x1] of row y with the current fill style (solid FG, or the
 * SET_PATTERN pattern anchored at the DST origin), clipped; x0 > x1 draws
 * nothing.  dp_fill_poly scan-converts the polygon of n points xy[2i],
 * xy[2i + 1] in device coordinates (any int32; no transform applied) with
 * the fill style, even-odd or non-zero, pixel centres sampled with the
 * top-left rule; n > RDC_DP_POLY_VERTS or n < 3 draws nothing, and so do points beyond
 * +-RDC_POLY_COORD_LIMIT.
 */
void dp_fill_span(struct rdc_dp *dp, int32_t x0, int32_t x1, int32_t y);
void dp_fill_poly(struct rdc_dp *dp, const int32_t *xy, uint32_t n,
		  bool nonzero);
/* A run [xa, xb] of row y, inside the effective clip. */
typedef void (*dp_span_fn)(struct rdc_dp *dp, int32_t y, int32_t xa, int32_t xb,
			   void *ctx);
/* dp_fill_poly's pixels, one call per maximal run of a row. */
void dp_poly_scan(struct rdc_dp *dp, const int32_t *xy, uint32_t n,
		  bool nonzero, dp_span_fn span, void *ctx);
/*
 * The pattern (or FG) at (x, y); false where a transparent pattern leaves DST
 * alone.
 */
bool dp_pat_value(const struct rdc_dp *dp, int32_t x, int32_t y, uint32_t *v);
/*
 * Commands of pattern.c, poly.c, flood.c, tri.c; return an enum rdc_err. len is
 * the argument count, a the arguments, flags the header's.
 */
uint32_t dp_cmd_set_pattern(struct rdc_dp *dp, uint32_t mode, uint32_t len,
			    const uint32_t *a);
uint32_t dp_cmd_fill_polygon(struct rdc_dp *dp, uint32_t flags, uint32_t len,
			     const uint32_t *a);
uint32_t dp_cmd_flood(struct rdc_dp *dp, uint32_t flags, uint32_t len,
		      const uint32_t *a);
uint32_t dp_cmd_triangle(struct rdc_dp *dp, uint32_t flags, const uint32_t *a);
uint32_t dp_cmd_set_zbuf(struct rdc_dp *dp, uint32_t flags, uint32_t len,
			 const uint32_t *a);
uint32_t dp_cmd_clear_z(struct rdc_dp *dp, const uint32_t *a);
void rdc_dp_rect(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, bool fill);
void rdc_dp_circle(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t r,
		   bool fill);
void rdc_dp_ellipse(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx,
		    uint32_t ry, bool fill);
void rdc_dp_blit(struct rdc_dp *dp, int32_t sx, int32_t sy, int32_t dx,
		 int32_t dy, uint32_t w, uint32_t h);
/* data: h rows of `wpr` words each (wpr from rdc_dp_words_per_row). */
void rdc_dp_host_blit(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		      uint32_t h, const uint32_t *data);
void rdc_dp_mono(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		 uint32_t h, const uint32_t *data, bool transparent);
void rdc_dp_text(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t count,
		 const uint32_t *chars, bool transparent);
/*
 * Pack words [word, word + n) of READBACK row `row` (SRC-format pixels of
 * the w x h rectangle at x, y; pixels off the surface read as 0) into out.
 */
void rdc_dp_readback_pack(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
			  uint32_t row, uint32_t word, uint32_t n,
			  uint32_t *out);

/*
 * Transform unit (xform.c).  dp_xform maps a vertex through st.xf:
 * x' = (m00 x + m01 y + m02) / w, y' = (m10 x + m11 y + m12) / w with
 * w = m20 x + m21 y + m22, rounded to nearest (halves up).  Returns false,
 * leaving *x and *y alone, when w <= 0, the input is wider than 2^20 or the
 * result leaves [RDC_COORD_MIN, RDC_COORD_MAX]: the caller then fails the
 * command with RDC_ERR_RANGE.  With the identity it only checks the range.
 */
bool dp_xform(const struct rdc_dp *dp, int32_t *x, int32_t *y);
/*
 * Scale a size or radii pair by |m00| and |m11| (rounded; no rotation, no
 * projective division); false past RDC_SIZE_MAX.
 */
bool dp_xform_size(const struct rdc_dp *dp, uint32_t *w, uint32_t *h);
/*
 * A vector (HERMITE's tangents): the linear part over m22, no translation;
 * false when m22 <= 0 or the result passes 2^20.
 */
bool dp_xform_vec(const struct rdc_dp *dp, int32_t *x, int32_t *y);
void dp_xform_reset(struct rdc_dp_state *st);
/* SET_TRANSFORM and SET_VIEWPORT; return an enum rdc_err. */
uint32_t dp_cmd_set_transform(struct rdc_dp *dp, uint32_t len,
			      const uint32_t *a);
uint32_t dp_cmd_set_viewport(struct rdc_dp *dp, uint32_t len,
			     const uint32_t *a);

/*
 * The stroker (pen.c): feed it the vertices of a polyline one by one; it
 * draws with the pen and dash of dp->st.  closed: the last vertex equals
 * the first, which is then joined (wide pens) or drawn once (width 1).
 */
struct pen_vec {
	int64_t x, y; /* 24.8 fixed point; integers are pixel centres */
};

struct dp_stroke {
	struct rdc_dp *dp;
	bool thick, dashed, pending;
	uint32_t count, segs;
	int32_t x0, y0, px, py, qx, qy;
	int32_t fdx, fdy, ldx, ldy;
	struct pen_vec fnrm, fdir, lnrm, ldir;
	int64_t base; /* dash steps before the current segment */
};

void dp_stroke_begin(struct dp_stroke *sk, struct rdc_dp *dp);
void dp_stroke_point(struct dp_stroke *sk, int32_t x, int32_t y);
void dp_stroke_end(struct dp_stroke *sk, bool closed);
uint32_t dp_cmd_set_pen(struct rdc_dp *dp, uint32_t v);
uint32_t dp_cmd_set_dash(struct rdc_dp *dp, uint32_t bits, uint32_t v);
void dp_pen_reset(struct rdc_dp_state *st);
/* LINE, POLYLINE, POLYGON through the transform and the stroker. */
uint32_t dp_cmd_stroke(struct rdc_dp *dp, uint32_t op, uint32_t len,
		       const uint32_t *a);
void dp_stroke_rect(struct rdc_dp *dp, int32_t x, int32_t y, uint32_t w,
		    uint32_t h);
/* Width 1, no dash: the plain midpoint line. */
bool dp_pen_plain(const struct rdc_dp *dp);
uint64_t dp_isqrt(uint64_t v);
/*
 * Queue a convex polygon of 3 or 4 vertices in 24.8 for the stroke's union;
 * dp_pen_flush draws the queue by pixel centres, left and top edges inclusive,
 * each covered pixel once.
 */
void dp_pen_fill_convex(struct rdc_dp *dp, const struct pen_vec *v,
			unsigned int n);
void dp_pen_flush(struct rdc_dp *dp);

/*
 * The midpoint ellipse (shape.c), shared by ELLIPSE, FILL_ELLIPSE and ARC:
 * after dp_ellipse_begin (rx, ry >= 1) each dp_ellipse_row gives the next
 * row offset t (ry down to 0) and the outline's pixels amin..amax right of
 * the centre on it (the fill's row is -amax..amax), false after row 0.
 */
struct dp_ellipse {
	int64_t rx2, ry2, e1, e2; /* radii squared; the two tests, scaled */
	int64_t b, w1, w2, prev;  /* row; widest a of each test; last row's */
};

void dp_ellipse_begin(struct dp_ellipse *e, uint32_t rx, uint32_t ry);
bool dp_ellipse_row(struct dp_ellipse *e, uint32_t *t, uint32_t *amin,
		    uint32_t *amax);

/* ARC (arc.c): sine and cosine of a 1/65536-turn angle in 16.16. */
int32_t dp_sin(uint32_t a);
int32_t dp_cos(uint32_t a);
void dp_arc(struct rdc_dp *dp, int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
	    uint32_t start, uint32_t end, uint32_t mode);
uint32_t dp_cmd_arc(struct rdc_dp *dp, uint32_t fl, const uint32_t *a);
/* BEZIER, HERMITE, BSPLINE (curve.c) */
uint32_t dp_cmd_curve(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		      const uint32_t *a);

/*
 * Image commands (image.c, decode.c, filter.c): DECODE, HISTOGRAM,
 * MAP_BUILD, MAP_APPLY, MAP_CLUT, CONVOLVE, THRESHOLD; an enum rdc_err.
 */
uint32_t dp_cmd_image(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		      const uint32_t *a);

/*
 * 3D (geom3d.c): the commands 0x40..0x5f (an enum rdc_err) and the reset
 * state.  dp_tri_draw (tri.c) rasterises a triangle of device pixels with
 * DST pixel values and depths 0..65535, no transform, as TRIANGLE does;
 * dp_zbuf_ready says whether the depth surface, when in use, fits DST.
 */
uint32_t dp_cmd_3d(struct rdc_dp *dp, uint32_t op, uint32_t fl, uint32_t len,
		   const uint32_t *a);
void dp_3d_reset(struct rdc_dp *dp);
void dp_tri_draw(struct rdc_dp *dp, const int32_t *x, const int32_t *y,
		 const uint32_t *col, const uint32_t *z, bool gouraud);
bool dp_zbuf_ready(const struct rdc_dp *dp);
/*
 * A triangle's interpolation as dp_tri_draw fills it: dp_tri_setup
 * (false: zero area, no pixel), then the depth and the DST pixel value
 * dp_tri_draw gives pixel (px, py) (MESH's scan-line mode, mesh.c).
 */
#define DP_TRI_VERTS  3
#define DP_TRI_CH_MAX 4 /* colour channels + depth */
struct dp_tri {
	int32_t x[DP_TRI_VERTS], y[DP_TRI_VERTS];
	int64_t area2;
	unsigned int nch; /* channels interpolated: colour ones, then z */
	unsigned int shift[DP_TRI_CH_MAX - 1], width[DP_TRI_CH_MAX - 1];
	int64_t a0[DP_TRI_CH_MAX], d1[DP_TRI_CH_MAX], d2[DP_TRI_CH_MAX];
	int64_t lo[DP_TRI_CH_MAX], hi[DP_TRI_CH_MAX];
	bool gouraud, ztest, zwrite;
	uint32_t flat;
};

bool dp_tri_setup(const struct rdc_dp *dp, const int32_t *x, const int32_t *y,
		  const uint32_t *col, const uint32_t *z, bool gouraud,
		  struct dp_tri *t);
uint32_t dp_tri_depth(const struct dp_tri *t, int32_t px, int32_t py);
uint32_t dp_tri_pixel(const struct dp_tri *t, int32_t px, int32_t py);

/* Words a row of w pixels of `fmt` occupies, padded to a word. */
static inline uint32_t rdc_dp_words_per_row(unsigned int fmt, uint32_t w)
{
	return (uint32_t)(((uint64_t)w * rdc_format_bpp(fmt) + 31) / 32);
}

/*
 * Integer division rounded down, up and to nearest (halves up), for the
 * rasterisers' exact arithmetic (C's division truncates towards zero).
 * b > 0 for the first two; dp_div_round takes either sign of d.  None of
 * them overflows where the quotient fits.
 */
static inline int64_t dp_div_floor(int64_t a, int64_t b)
{
	int64_t q = a / b;

	if (a % b && a < 0)
		q--;
	return q;
}

static inline int64_t dp_div_ceil(int64_t a, int64_t b)
{
	int64_t q = a / b;

	if (a % b && a > 0)
		q++;
	return q;
}

static inline int64_t dp_div_round(int64_t n, int64_t d)
{
	int64_t q, r;

	if (d < 0)
		n = -n, d = -d;
	q = n / d;
	r = n % d;
	if (r < 0) {
		q--;
		r += d;
	}
	if (r >= d - r)
		q++;
	return q;
}

#endif /* RDC_DP_INT_H */
