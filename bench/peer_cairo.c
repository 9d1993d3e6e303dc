// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * cairo as a peer, on an ARGB32 image surface (opaque colours, so the
 * bytes are rdc's XRGB8888 with X 0xff): fill, one-pixel lines (antialias
 * NONE), anti-aliased lines (the default antialias), circle outlines and
 * discs (NONE), even-odd polygons (NONE).  Lines and outlines are stroked
 * one unit wide through pixel centres; fills take the integer vertices as
 * rdc does, so pixel centres decide.  Only fill has a CRC to match: the
 * other algorithms differ from rdc's in the pixels they pick.
 */
#include <math.h>

#include <cairo.h>

#include "bench.h"

#define CAIRO_HALF 0.5 /* a pixel's centre from its corner */

static int cr_has(enum bench_kind kind)
{
	return kind == BENCH_FILL || kind == BENCH_LINE ||
	       kind == BENCH_AALINE || kind == BENCH_CIRCLE ||
	       kind == BENCH_FILL_CIRCLE || kind == BENCH_POLYGON;
}

static void cr_colour(cairo_t *cr, uint32_t c)
{
	cairo_set_source_rgb(cr, ((c >> 16) & 0xff) / 255.0,
			     ((c >> 8) & 0xff) / 255.0, (c & 0xff) / 255.0);
}

static void cr_draw(cairo_t *cr, const struct bench_input *in, uint32_t ops)
{
	const uint32_t *a = in->arg;
	uint32_t i, k;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		switch (in->kind) {
		case BENCH_FILL:
			cairo_rectangle(cr, a[0], a[1], a[2], a[3]);
			cr_colour(cr, a[4]);
			cairo_fill(cr);
			break;
		case BENCH_LINE:
		case BENCH_AALINE:
			cairo_move_to(cr, a[0] + CAIRO_HALF, a[1] + CAIRO_HALF);
			cairo_line_to(cr, a[2] + CAIRO_HALF, a[3] + CAIRO_HALF);
			cr_colour(cr, a[4]);
			cairo_stroke(cr);
			break;
		case BENCH_CIRCLE:
		case BENCH_FILL_CIRCLE:
			cairo_new_path(cr);
			cairo_arc(cr, a[0] + CAIRO_HALF, a[1] + CAIRO_HALF,
				  a[2], 0, 2 * M_PI);
			cr_colour(cr, a[3]);
			if (in->kind == BENCH_CIRCLE)
				cairo_stroke(cr);
			else
				cairo_fill(cr);
			break;
		case BENCH_POLYGON: {
			const int *xy = in->xy + 2 * a[1];

			cairo_move_to(cr, xy[0], xy[1]);
			for (k = 1; k < a[0]; k++)
				cairo_line_to(cr, xy[2 * k], xy[2 * k + 1]);
			cairo_close_path(cr);
			cr_colour(cr, a[2]);
			cairo_fill(cr);
			break;
		}
		default:
			return;
		}
	}
}

static double cr_run(const struct bench_input *in, uint32_t ops, uint32_t *crc)
{
	cairo_surface_t *surf;
	cairo_t *cr;
	double t0, t;

	if (!cr_has(in->kind))
		return -1;
	surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, BENCH_W,
					  BENCH_H);
	cr = cairo_create(surf);
	cairo_set_line_width(cr, 1.0);
	cairo_set_antialias(cr, in->kind == BENCH_AALINE ?
					CAIRO_ANTIALIAS_DEFAULT :
					CAIRO_ANTIALIAS_NONE);
	cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
	t0 = bench_tic();
	cr_draw(cr, in, ops);
	cairo_surface_flush(surf);
	t = bench_toc(t0);
	*crc = bench_surface_crc(cairo_image_surface_get_data(surf),
				 (size_t)cairo_image_surface_get_stride(surf));
	cairo_destroy(cr);
	cairo_surface_destroy(surf);
	return t;
}

const struct bench_peer bench_peer_cairo = {
	.name = "cairo",
	.has = cr_has,
	.run = cr_run,
};
