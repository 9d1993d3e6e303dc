/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Plain references for the stroker and ARC (see ref.h): per-pixel tests
 * written from the definitions in docs/commands.md, no spans, no clipping.
 */
#ifndef RDC_REF_LINES_H
#define RDC_REF_LINES_H

#include "ref.h"

/*
 * Convex polygon of n vertices xy[2i], xy[2i + 1] in fixed point with
 * `frac` fractional bits (integers are pixel centres): every pixel whose
 * centre is inside, or on a left or top edge, by edge functions.
 */
void rdc_ref_convex(const int64_t *xy, uint32_t n, unsigned int frac,
		    rdc_ref_plot_fn plot, void *ctx);
/*
 * Midpoint line with a dash: step i from (x0, y0) is plotted when bit (i +
 * offset) % len of bits is set (len 0: all).
 */
void rdc_ref_dash_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
		       uint32_t bits, uint32_t len, uint32_t offset,
		       rdc_ref_plot_fn plot, void *ctx);
/*
 * ARC in mode (enum rdc_arc_mode), angles in 1/65536 turn: the pixels of
 * ELLIPSE (outline) or FILL_ELLIPSE (pie, chord) whose centre p lies in
 * the sector, i.e. p is the centre itself or no further counter-clockwise
 * from the start point's direction than the end point's (pie, outline),
 * or not left of the line from the start to the end point (chord).  For
 * angles that are not rdc_ref_arc_generic the sector is the documented
 * half-plane rule instead.
 */
void rdc_ref_arc(int32_t cx, int32_t cy, uint32_t rx, uint32_t ry,
		 uint32_t start, uint32_t end, uint32_t mode,
		 rdc_ref_plot_fn plot, void *ctx);
/*
 * False when the end points' rounding puts the end on the other side of
 * the start than the sweep says, where only ARC's half-plane rule
 * decides (docs/commands.md says this never happens; the tests check).
 */
bool rdc_ref_arc_generic(uint32_t rx, uint32_t ry, uint32_t start,
			 uint32_t end);
/* 65536 sin(a / 65536 turn) as docs/commands.md defines the table. */
int64_t rdc_ref_sin(uint32_t a);

#endif /* RDC_REF_LINES_H */
