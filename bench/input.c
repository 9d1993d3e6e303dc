// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The workloads' inputs (bench/README.md, "The workloads"), drawn once
 * from their random streams before anything is timed, so that rdc, the
 * plain-C limits and every peer draw exactly the same primitives; with
 * each primitive's pixels, summed (pixels.c counts circles and polygons).
 */
#include <stdlib.h>
#include <string.h>

#include "parts.h"

static const uint32_t kind_ops[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = BENCH_FILL_OPS,
	[BENCH_BLIT] = BENCH_BLIT_OPS,
	[BENCH_BLIT_XOR] = BENCH_BLIT_OPS,
	[BENCH_LINE] = BENCH_LINE_OPS,
	[BENCH_AALINE] = BENCH_AALINE_OPS,
	[BENCH_CIRCLE] = BENCH_CIRCLE_OPS,
	[BENCH_FILL_CIRCLE] = BENCH_FILL_CIRCLE_OPS,
	[BENCH_POLYGON] = BENCH_POLYGON_OPS,
	[BENCH_TEXT] = BENCH_TEXT_OPS,
	[BENCH_SCANOUT] = BENCH_SCANOUT_FRAMES,
};

static void make_fills(uint32_t *arg, uint32_t seed, uint32_t ops, bool indexed)
{
	struct bench_rng g = { seed };
	uint32_t i;

	for (i = 0; i < ops; i++, arg += BENCH_RECORD) {
		arg[0] = bench_r32(&g) % BENCH_W;
		arg[1] = bench_r32(&g) % BENCH_H;
		arg[2] = 1 + bench_r32(&g) % BENCH_RECT_MAX;
		arg[3] = 1 + bench_r32(&g) % BENCH_RECT_MAX;
		arg[4] = indexed ? bench_r32(&g) % BENCH_CLUT_SIZE :
				   bench_r32(&g) | BENCH_OPAQUE;
	}
}

/* Primitive i drew px pixels. */
static void input_px(struct bench_input *in, uint32_t i, uint64_t px)
{
	in->cum[i + 1] = in->cum[i] + px;
	in->pixels = in->cum[i + 1];
}

void input_make(struct bench_input *in, enum bench_kind kind)
{
	struct bench_rng g = { BENCH_SEED };
	uint32_t i, *a;
	size_t nxy = 0;

	memset(in, 0, sizeof(*in));
	in->kind = kind;
	in->ops = kind_ops[kind];
	in->arg = bench_xcalloc((size_t)in->ops + 1, BENCH_RECORD * 4);
	in->cum = bench_xcalloc((size_t)in->ops + 1, sizeof(*in->cum));
	switch (kind) {
	case BENCH_FILL:
		make_fills(in->arg, BENCH_SEED, in->ops, false);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD)
			input_px(in, i,
				 (uint64_t)bench_fill_w(a) * bench_fill_h(a));
		break;
	case BENCH_BLIT:
	case BENCH_BLIT_XOR:
		in->prefill = bench_xcalloc(BENCH_FILL_OPS, BENCH_RECORD * 4);
		make_fills(in->prefill, BENCH_PREFILL_SEED, BENCH_FILL_OPS,
			   false);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t sx = bench_r32(&g) % BENCH_W,
				 sy = bench_r32(&g) % BENCH_H;
			uint32_t dx = bench_r32(&g) % BENCH_W,
				 dy = bench_r32(&g) % BENCH_H;
			uint32_t w = 1 + bench_r32(&g) % BENCH_RECT_MAX;
			uint32_t h = 1 + bench_r32(&g) % BENCH_RECT_MAX;

			a[0] = sx;
			a[1] = sy;
			a[2] = dx;
			a[3] = dy;
			a[4] = bench_umin(w, bench_umin(BENCH_W - sx,
							BENCH_W - dx));
			a[5] = bench_umin(h, bench_umin(BENCH_H - sy,
							BENCH_H - dy));
			input_px(in, i, (uint64_t)a[4] * a[5]);
		}
		break;
	case BENCH_LINE:
	case BENCH_AALINE:
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t dx, dy;

			a[0] = bench_r32(&g) % BENCH_W;
			a[1] = bench_r32(&g) % BENCH_H;
			a[2] = bench_r32(&g) % BENCH_W;
			a[3] = bench_r32(&g) % BENCH_H;
			a[4] = bench_r32(&g) | BENCH_OPAQUE;
			dx = a[2] > a[0] ? a[2] - a[0] : a[0] - a[2];
			dy = a[3] > a[1] ? a[3] - a[1] : a[1] - a[3];
			input_px(in, i, (dx > dy ? dx : dy) + 1);
		}
		break;
	case BENCH_CIRCLE:
	case BENCH_FILL_CIRCLE:
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			bool fill = kind == BENCH_FILL_CIRCLE;

			a[0] = bench_r32(&g) % BENCH_W;
			a[1] = bench_r32(&g) % BENCH_H;
			a[2] = 1 +
			       bench_r32(&g) % (fill ? BENCH_DISC_RADIUS_MAX :
						       BENCH_RADIUS_MAX);
			a[3] = bench_r32(&g) | BENCH_OPAQUE;
			input_px(in, i,
				 circle_pixels((int)a[0], (int)a[1], (int)a[2],
					       fill));
		}
		break;
	case BENCH_POLYGON:
		in->xy = bench_xcalloc((size_t)in->ops * BENCH_POLY_MAX,
				       2 * sizeof(int));
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t n = BENCH_POLY_MIN +
				     bench_r32(&g) % BENCH_POLY_MORE,
				 k;
			int ox = (int)(bench_r32(&g) % BENCH_POLY_OX);
			int oy = (int)(bench_r32(&g) % BENCH_POLY_OY);

			a[0] = n;
			a[1] = (uint32_t)nxy;
			for (k = 0; k < n; k++, nxy++) {
				in->xy[2 * nxy] = ox + (int)(bench_r32(&g) %
							     BENCH_POLY_SPAN);
				in->xy[2 * nxy + 1] =
					oy +
					(int)(bench_r32(&g) % BENCH_POLY_SPAN);
			}
			a[2] = bench_r32(&g) | BENCH_OPAQUE;
			input_px(in, i, polygon_pixels(in->xy + 2 * a[1], n));
		}
		break;
	case BENCH_TEXT: {
		struct bench_rng f = { BENCH_FONT_SEED };

		for (i = 0; i < sizeof(in->font); i++)
			in->font[i] = (uint8_t)(bench_r32(&f) >> 24);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t cell = i % (BENCH_COLS * BENCH_ROWS);

			a[0] = bench_r32(&g) % BENCH_GLYPHS;
			a[1] = bench_r32(&g) | BENCH_OPAQUE;
			a[2] = bench_r32(&g) | BENCH_OPAQUE;
			a[3] = cell % BENCH_COLS * BENCH_GLYPH_W;
			a[4] = cell / BENCH_COLS * BENCH_GLYPH_H;
			input_px(in, i, BENCH_GLYPH_W * BENCH_GLYPH_H);
		}
		break;
	}
	case BENCH_SCANOUT:
		/* the CLUT first, from the workload's own stream */
		for (i = 0; i < BENCH_CLUT_SIZE; i++)
			in->clut[i] = bench_r32(&g) & 0x00ffffffu;
		in->prefill = bench_xcalloc(BENCH_FILL_OPS, BENCH_RECORD * 4);
		make_fills(in->prefill, BENCH_INDEX_SEED, BENCH_FILL_OPS, true);
		/* the indexed surface those fills draw, for limit and peers */
		in->index = bench_xcalloc(BENCH_W, BENCH_H);
		for (i = 0, a = in->prefill; i < BENCH_FILL_OPS;
		     i++, a += BENCH_RECORD) {
			uint32_t y, h = bench_fill_h(a);

			for (y = 0; y < h; y++)
				memset(in->index + (a[1] + y) * BENCH_W + a[0],
				       (int)a[4], bench_fill_w(a));
		}
		for (i = 0; i < in->ops; i++)
			input_px(in, i, BENCH_W * BENCH_H);
		break;
	default:
		break;
	}
}

void input_free(struct bench_input *in)
{
	free(in->arg);
	free(in->xy);
	free(in->prefill);
	free(in->index);
	free(in->cum);
}
