/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Helpers shared by the polygon, flood and triangle tests: a small DST,
 * VRAM snapshots, and bus.h's span cost transcribed for cycle checks.
 * Header-only (static inline), on top of test_dp_common.h.
 */
#ifndef TDP_POLY_H
#define TDP_POLY_H

#include "test_dp_common.h"

#define TPP_BASE 0x1000u

static inline struct rdc_surface tpp_surface(uint32_t fmt, uint32_t w,
					     uint32_t h)
{
	struct rdc_surface s = {
		.base = TPP_BASE,
		.width = w,
		.height = h,
		.format = fmt,
		.stride = rdc_format_row_bytes(fmt, w),
	};

	return s;
}

/* Make s the DST with a full clip, and zero its pixels. */
static inline void tpp_dst(struct tdp *t, const struct rdc_surface *s)
{
	tdp_set_surface(t, RDC_OP_SET_DST, s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(RDC_COORD_MIN, RDC_COORD_MIN),
		RDC_XY(RDC_COORD_MAX + 1, RDC_COORD_MAX + 1));
	tdp_drain(t);
	memset(t->vram + s->base, 0, (size_t)s->stride * s->height);
}

static inline void tpp_clear(struct tdp *t, const struct rdc_surface *s)
{
	memset(t->vram + s->base, 0, (size_t)s->stride * s->height);
}

static inline uint32_t tpp_hash(struct tdp *t, const struct rdc_surface *s)
{
	return tdp_fnv(2166136261u, t->vram + s->base,
		       (size_t)s->stride * s->height);
}

/* Pack n points of xy[] into words (RDC_XY). */
static inline void tpp_pts(uint32_t *w, const int32_t *xy, uint32_t n)
{
	uint32_t i;

	for (i = 0; i < n; i++)
		w[i] = RDC_XY(xy[2 * i], xy[2 * i + 1]);
}

static inline void tpp_fill_poly(struct tdp *t, const int32_t *xy, uint32_t n,
				 uint32_t flags)
{
	uint32_t *w = calloc(n + 1, sizeof(*w));

	assert_non_null(w);
	tpp_pts(w, xy, n);
	tdp_cmd(t, RDC_OP_FILL_POLYGON, flags, n, w);
	tdp_drain(t);
	free(w);
}

/* Cost of writing pixels [x, x + n) of row y of s (32 bpp or 8 bpp). */
static inline uint64_t tpp_row_cost(uint32_t *open, const struct rdc_surface *s,
				    int32_t x, int32_t y, uint32_t n, int kind)
{
	uint32_t bpp = tdp_bpp(s->format);

	return tdp_bus_edges(
		open, s->base + (uint64_t)y * s->stride + (uint64_t)x * bpp / 8,
		(uint64_t)n * bpp / 8, kind, 0, 0);
}

static inline uint32_t tpp_last_cycles(struct tdp *t)
{
	return rdc_hw_read(&t->hw, RDC_REG_PERF_LAST_CYCLES);
}

#endif /* TDP_POLY_H */
