/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdc-bench internals shared by the driver (rdc_bench.c) and the peer
 * libraries (peer_*.c): the workloads' inputs (bench/README.md), drawn
 * once from their random stream before anything is timed, so that rdc, the
 * plain-C limits and every peer draw exactly the same primitives.
 */
#ifndef RDC_BENCH_H
#define RDC_BENCH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define BENCH_W		   1024
#define BENCH_H		   768
#define BENCH_SEED	   0x12345678u /* every workload's own stream */
#define BENCH_PREFILL_SEED 0x9e3779b9u /* blit: the surface's prefill */
#define BENCH_FONT_SEED	   0x464f4e54u /* text: the glyph bitmaps */
#define BENCH_INDEX_SEED   7u	       /* scanout: the indexed surface */
#define BENCH_OPAQUE	   0xff000000u /* colours: r() | this */

#define BENCH_GLYPH_W	8
#define BENCH_GLYPH_H	16
#define BENCH_GLYPHS	256
#define BENCH_COLS	(BENCH_W / BENCH_GLYPH_W) /* 128 cells a row */
#define BENCH_ROWS	(BENCH_H / BENCH_GLYPH_H) /* 48 rows */
#define BENCH_CLUT_SIZE 256

#define BENCH_FILL_OPS	      100000u
#define BENCH_BLIT_OPS	      50000u
#define BENCH_LINE_OPS	      1000000u
#define BENCH_AALINE_OPS      200000u
#define BENCH_CIRCLE_OPS      200000u
#define BENCH_FILL_CIRCLE_OPS 50000u
#define BENCH_POLYGON_OPS     20000u
#define BENCH_TEXT_OPS	      1000000u
#define BENCH_SCANOUT_FRAMES  600u

/* the workloads' distributions (bench/README.md) */
#define BENCH_RECT_MAX	      256 /* fill, blit: w, h = 1 + r() % this */
#define BENCH_RADIUS_MAX      128 /* circle: radius = 1 + r() % this */
#define BENCH_DISC_RADIUS_MAX 64  /* fill_circle */
#define BENCH_POLY_MIN	      3	  /* polygon: n = 3 + r() % 14 vertices */
#define BENCH_POLY_MORE	      14
#define BENCH_POLY_MAX	      (BENCH_POLY_MIN + BENCH_POLY_MORE - 1)
#define BENCH_POLY_OX	      768 /* polygon origin: r() % these */
#define BENCH_POLY_OY	      512
#define BENCH_POLY_SPAN	      256 /* vertex: origin + r() % this */

#define BENCH_RECORD 8 /* words per primitive in bench_input.arg */

enum bench_kind {
	BENCH_FILL,
	BENCH_BLIT,
	BENCH_BLIT_XOR,
	BENCH_LINE,
	BENCH_AALINE,
	BENCH_CIRCLE,
	BENCH_FILL_CIRCLE,
	BENCH_POLYGON,
	BENCH_TEXT,
	BENCH_SCANOUT,
	BENCH_REALTIME,
	BENCH_REALTIME_1080, /* realtime at 1920x1080@60 */
	BENCH_TEAPOT3D,
	BENCH_GROWTH, /* cost against area and region size */
	BENCH_KIND_COUNT
};

/*
 * One workload's input.  arg holds `ops` records of BENCH_RECORD words:
 *   fill:        x, y, w, h (as drawn, unclipped), colour
 *   blit(_xor):  sx, sy, dx, dy, w, h (clipped to source and destination)
 *   line, aaline: x0, y0, x1, y1, colour
 *   circle, fill_circle: cx, cy, radius, colour
 *   polygon:     n, index of the first vertex in xy, colour
 *   text:        glyph, fg, bg, x, y (of its cell)
 * prefill (blit) holds BENCH_FILL_OPS fill records.  Colours carry
 * BENCH_OPAQUE as the workloads draw them.
 */
struct bench_input {
	enum bench_kind kind;
	uint32_t ops;
	uint32_t *arg;
	int *xy;
	uint32_t *prefill;
	uint8_t font[BENCH_GLYPHS * BENCH_GLYPH_H]; /* bit 7 leftmost */
	uint32_t clut[BENCH_CLUT_SIZE];		    /* 0x00RRGGBB */
	uint8_t *index;				    /* scanout: 8 bpp */
	uint64_t pixels; /* as the workloads' rules count */
	uint64_t *cum;	 /* pixels of the first i primitives, i = 0..ops */
};

/* The clipped size of a fill record (the workloads' clipping rule). */
static inline uint32_t bench_fill_w(const uint32_t *a)
{
	return a[2] < BENCH_W - a[0] ? a[2] : BENCH_W - a[0];
}

static inline uint32_t bench_fill_h(const uint32_t *a)
{
	return a[3] < BENCH_H - a[1] ? a[3] : BENCH_H - a[1];
}

/* Wall-clock seconds (CLOCK_MONOTONIC). */
double bench_now(void);
/*
 * Around a timed part: bench_tic() returns bench_now() and notes the
 * thread's CPU time; bench_toc(t0) returns the wall seconds since t0 and
 * notes the CPU seconds since the tic, which bench_cpu() returns.
 */
double bench_tic(void);
double bench_toc(double t0);
double bench_cpu(void);
/* CRC-32 (zlib) of a BENCH_W x BENCH_H XRGB8888 surface, rows `stride`
 * bytes apart. */
uint32_t bench_surface_crc(const void *px, size_t stride);

/*
 * A library a user would otherwise draw with.  run() draws the first `ops`
 * primitives (frames for scanout) of workload `in` once on a fresh
 * BENCH_W x BENCH_H surface cleared to 0 and returns the seconds the
 * drawing took (setup excluded), with the surface's CRC in *crc; a
 * negative value when the peer does not offer that workload.  A peer too
 * slow for the time budget is measured on a prefix of the workload.
 */
struct bench_peer {
	const char *name;
	int (*has)(enum bench_kind kind);
	double (*run)(const struct bench_input *in, uint32_t ops,
		      uint32_t *crc);
};

extern const struct bench_peer bench_peer_pixman;
extern const struct bench_peer bench_peer_cairo;
extern const struct bench_peer bench_peer_sdl2_gfx;

#endif /* RDC_BENCH_H */
