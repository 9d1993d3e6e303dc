// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdc-bench: the workloads of bench/README.md through the real command path
 * (librdc sim: -> command words -> display-processor firmware -> hw-sim,
 * cycle counting on), each against the plain-C limit of the same work and,
 * when built with them, the libraries a user would otherwise draw with.
 *
 *   rdc-bench [-w WORKLOAD[,WORKLOAD...]] [-r REPEATS] [--json] [--peers]
 *             [--full]
 *
 * Every drawing workload runs twice: with scanout on, against limits and
 * peers that also convert the frames the chip scanned out meanwhile, and
 * with CONTROL.SCANOUT_EN = 0, against the plain limits and peers.  `-w growth` times
 * fill, blit and flood fill against area on a 4096x4096 surface.
 *
 * One JSON object a workload on stdout, the workloads' keys first, then
 * the limits, the peers and the ratios; then, unless --json, a table.
 * Every wall time is the median of the repeats, measured around the
 * drawing only; crc32 is the zlib CRC-32 of the target surface after the
 * workload (of the last scanned-out frame for scanout and realtime).
 * bench/README.md explains the workloads, the limits and the table.
 */
#include <getopt.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <wchar.h>
#include <zlib.h>

#include "bench.h"
#include "hw.h"
#include "rdc.h"
#include "rdc_priv.h"
#include "rdc_sink.h"

#define BATCH_WORDS 65536u /* submit once a batch holds this many words */
#define MAX_REPEAT  99
/*
 * A measurement whose first run takes longer than this is not repeated
 * (unless --full): three runs of every slow workload would not fit the
 * five minutes a full `make bench-peers` may take.  The output says so.
 */
#define SLOW_S 4.0
/*
 * A peer whose whole workload would take longer than this (estimated from
 * a prefix of 1/PEER_PROBE of it) draws only the prefix that fits, and is
 * rated by its pixels a second over that prefix (the input is uniformly
 * random, so any prefix is like the whole).  --full draws everything.
 */
#define PEER_BUDGET_S 1.0
#define PEER_PROBE    32

/*
 * Targets (bench/README.md, "Reading the output").  Scanout on: fill,
 * blit, blit_xor and text against the limit that also converts the frames
 * the chip scanned out meanwhile; scanout (the workload) against its
 * lookup.  Scanout off: fill, blit and blit_xor against the plain limit,
 * text against the bit expand.  line wants SDL2_gfx's rate or better, the
 * other shapes the best peer's: with scanout on, the peers' with the same
 * frame conversions ("+scan").
 */
#define TARGET_SCAN	0.7
#define TARGET_OFF	0.8
#define TARGET_OFF_TEXT 0.7
#define LINE_PEER	"SDL2_gfx"
/* realtime: simulated frames per wall second wanted, 20x real time. */
#define RT_PRESET     RDC_PRESET_640x480_60
#define RT_W	      640u
#define RT_H	      480u
#define RT_HZ	      60u
#define RT_TARGET_FPS (20u * RT_HZ)
#define RT_FRAMES     RT_TARGET_FPS /* run this many frames ... */
#define RT_MAX_S      2.0	    /* ... or for this long at most */
#define RT_LINES      1000u
#define RT_FILLS      100u
#define RT_FILL_MAX   128u
#define RT_TEXT_ROWS  100u
#define RT_FIRST_CHAR 32u /* printable ASCII */
#define RT_CHARS      95u
/* A sink that discards: png writes only the frames asked for (never). */
#define RT_SINK "png:/nonexistent,every=0"
/*
 * teapot3d: examples/teapot.rdl's scene (run from the source tree), frame
 * after frame: the picture list into the buffer off screen, a flip, a
 * turn.  The figure that matters is the simulated chip's: frames a
 * simulated second its display processor draws, against the 60 Hz line.
 */
#define T3_SCRIPT "examples/teapot.rdl"
#define T3_FRAMES 120u
#define T3_DRAW	  0x410000u /* the picture list */
#define T3_BUF1	  0x130000u /* the second screen buffer */
#define T3_TURN	  1092u	    /* 6 degrees in 1/65536 turn */

/* Expected CRCs (bench/README.md); 0 where none is given. */
static const uint32_t expect_crc[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 0xcce4ceedu,	[BENCH_BLIT] = 0x039b2ef6u,
	[BENCH_BLIT_XOR] = 0x96d2b63du, [BENCH_TEXT] = 0x7c6efccau,
	[BENCH_SCANOUT] = 0x530c48eau,
};

static const char *const kind_name[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = "fill",
	[BENCH_BLIT] = "blit",
	[BENCH_BLIT_XOR] = "blit_xor",
	[BENCH_LINE] = "line",
	[BENCH_AALINE] = "aaline",
	[BENCH_CIRCLE] = "circle",
	[BENCH_FILL_CIRCLE] = "fill_circle",
	[BENCH_POLYGON] = "polygon",
	[BENCH_TEXT] = "text",
	[BENCH_SCANOUT] = "scanout",
	[BENCH_REALTIME] = "realtime",
	[BENCH_REALTIME_1080] = "realtime1080",
	[BENCH_TEAPOT3D] = "teapot3d",
	[BENCH_GROWTH] = "growth",
};

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

static const struct bench_peer *const peers[] = {
#ifdef BENCH_HAVE_PIXMAN
	&bench_peer_pixman,
#endif
#ifdef BENCH_HAVE_CAIRO
	&bench_peer_cairo,
#endif
#ifdef BENCH_HAVE_SDL2_GFX
	&bench_peer_sdl2_gfx,
#endif
	NULL,
};
#define NPEERS (sizeof(peers) / sizeof(peers[0]) - 1)

/*
 * Simulated cycles of each workload's drawing, scanout on and scanout off,
 * as first measured (bench/README.md, "Simulated cycles"); 0 where they
 * vary from run to run (realtime).  The simulator may get faster, never
 * different: a cycle count that changed fails the run, as a CRC does.
 */
static const uint64_t expect_cycles[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 1047362037u,	  [BENCH_BLIT] = 852290488u,
	[BENCH_BLIT_XOR] = 1267262678u,	  [BENCH_LINE] = 3465157430u,
	[BENCH_AALINE] = 1229723067u,	  [BENCH_CIRCLE] = 470645371u,
	[BENCH_FILL_CIRCLE] = 184788418u, [BENCH_POLYGON] = 222487413u,
	[BENCH_TEXT] = 254265450u,	  [BENCH_SCANOUT] = 999938688u,
	[BENCH_TEAPOT3D] = 162255342u,
};
static const uint64_t expect_cycles_off[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 789235900u,	  [BENCH_BLIT] = 642020749u,
	[BENCH_BLIT_XOR] = 951224529u,	  [BENCH_LINE] = 2622307538u,
	[BENCH_AALINE] = 930128316u,	  [BENCH_CIRCLE] = 356120550u,
	[BENCH_FILL_CIRCLE] = 139462850u, [BENCH_POLYGON] = 167959276u,
	[BENCH_TEXT] = 195000272u,
};

static bool byte_moving(enum bench_kind k)
{
	return k == BENCH_FILL || k == BENCH_BLIT || k == BENCH_BLIT_XOR ||
	       k == BENCH_TEXT || k == BENCH_SCANOUT;
}

/* The drawing workloads: measured with scanout on and with it off. */
static bool drawing(enum bench_kind k)
{
	return k <= BENCH_TEXT;
}

/* ---- helpers ------------------------------------------------------------- */

struct rng {
	uint32_t x;
};

static uint32_t r32(struct rng *g)
{
	uint32_t x = g->x;

	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	return g->x = x;
}

double bench_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/*
 * CPU time of the one thread that draws: what the ratios are made of.  On
 * a shared machine wall time also counts the time other processes had the
 * CPU, which moves each figure by its own amount.
 */
static double cpu_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double tic_cpu, toc_cpu;

double bench_tic(void)
{
	tic_cpu = cpu_now();
	return bench_now();
}

double bench_toc(double t0)
{
	toc_cpu = cpu_now() - tic_cpu;
	return bench_now() - t0;
}

double bench_cpu(void)
{
	return toc_cpu;
}

uint32_t bench_surface_crc(const void *px, size_t stride)
{
	const uint8_t *p = px;
	uLong crc = crc32(0, NULL, 0);
	uint32_t y;

	for (y = 0; y < BENCH_H; y++)
		crc = crc32(crc, p + y * stride, BENCH_W * 4);
	return (uint32_t)crc;
}

static uint32_t umin(uint32_t a, uint32_t b)
{
	return a < b ? a : b;
}

static void die(const char *what, int err)
{
	fprintf(stderr, "rdc-bench: %s: %s\n", what, rdc_strerror(err));
	exit(1);
}

static void *xcalloc(size_t n, size_t size)
{
	void *p = calloc(n, size);

	if (!p)
		die("memory", RDC_E_NOMEM);
	return p;
}

/* ---- inputs and the workloads' pixel counts ---------------------------- */

static void make_fills(uint32_t *arg, uint32_t seed, uint32_t ops, bool indexed)
{
	struct rng g = { seed };
	uint32_t i;

	for (i = 0; i < ops; i++, arg += BENCH_RECORD) {
		arg[0] = r32(&g) % BENCH_W;
		arg[1] = r32(&g) % BENCH_H;
		arg[2] = 1 + r32(&g) % BENCH_RECT_MAX;
		arg[3] = 1 + r32(&g) % BENCH_RECT_MAX;
		arg[4] = indexed ? r32(&g) % BENCH_CLUT_SIZE :
				   r32(&g) | BENCH_OPAQUE;
	}
}

/*
 * The classic incremental midpoint circle, octant x <= y from (0, r).
 * Outline: the distinct points of the eight reflections inside the
 * surface (reflections coincide only on the axes and the diagonal).
 * Filled: each row's span out to the farthest point on it, clipped.
 */
static uint64_t circle_pixels(int cx, int cy, int r, bool filled)
{
	int half[BENCH_W];
	int x = 0, y = r, d = 1 - r, k;
	uint64_t n = 0;

	for (k = 0; k <= r; k++)
		half[k] = -1;
	while (x <= y) {
		int pt[8][2] = {
			{ x, y }, { -x, y }, { x, -y }, { -x, -y },
			{ y, x }, { -y, x }, { y, -x }, { -y, -x },
		};
		int i, j;

		if (half[y] < x)
			half[y] = x;
		if (half[x] < y)
			half[x] = y;
		for (i = 0; !filled && i < 8; i++) {
			int px = cx + pt[i][0], py = cy + pt[i][1];

			for (j = 0; j < i; j++)
				if (pt[j][0] == pt[i][0] &&
				    pt[j][1] == pt[i][1])
					break;
			if (j == i && px >= 0 && px < BENCH_W && py >= 0 &&
			    py < BENCH_H)
				n++;
		}
		if (d < 0) {
			d += 2 * x + 3;
		} else {
			d += 2 * (x - y) + 5;
			y--;
		}
		x++;
	}
	for (k = -r; filled && k <= r; k++) {
		int h = half[k < 0 ? -k : k], py = cy + k;
		int x0 = cx - h < 0 ? 0 : cx - h;
		int x1 = cx + h >= BENCH_W ? BENCH_W - 1 : cx + h;

		if (py >= 0 && py < BENCH_H && x1 >= x0)
			n += (uint64_t)(x1 - x0 + 1);
	}
	return n;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* ceil(p / q) for q > 0 */
static long ceil_div(long p, long q)
{
	return p >= 0 ? (p + q - 1) / q : -(-p / q);
}

/*
 * Even-odd pixel-centre count: a row's centre line y + 1/2 crosses the
 * edges with min(y0, y1) <= y < max(y0, y1) (never at a vertex: centres
 * are half-integers); pixel x is inside when its centre x + 1/2 lies in
 * [left, right) of a pair of crossings, so a crossing at c starts or ends
 * the run at pixel ceil(c - 1/2), computed exactly in integers:
 * c = a0 + (2y + 1 - 2 a1) (b0 - a0) / (2 (b1 - a1)).
 */
static uint64_t polygon_pixels(const int *xy, uint32_t n)
{
	int ymin = xy[1], ymax = xy[1], y;
	long cross[BENCH_POLY_MAX];
	uint64_t cnt = 0;
	uint32_t i;

	for (i = 1; i < n; i++) {
		ymin = xy[2 * i + 1] < ymin ? xy[2 * i + 1] : ymin;
		ymax = xy[2 * i + 1] > ymax ? xy[2 * i + 1] : ymax;
	}
	for (y = ymin; y < ymax; y++) {
		uint32_t m = 0, k;

		for (i = 0; i < n; i++) {
			const int *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
			long dy = b[1] - a[1], num;

			if (y < (dy > 0 ? a[1] : b[1]) ||
			    y >= (dy > 0 ? b[1] : a[1]))
				continue;
			/* c - 1/2 = num / (2 dy) */
			num = 2L * a[0] * dy +
			      (2L * y + 1 - 2L * a[1]) * (b[0] - a[0]) - dy;
			cross[m++] = dy > 0 ? ceil_div(num, 2 * dy) :
					      ceil_div(-num, -2 * dy);
		}
		for (k = 1; k < m; k++) { /* a handful: insertion sort */
			long v = cross[k];
			uint32_t j = k;

			for (; j > 0 && cross[j - 1] > v; j--)
				cross[j] = cross[j - 1];
			cross[j] = v;
		}
		for (k = 0; k + 1 < m; k += 2)
			cnt += (uint64_t)(cross[k + 1] - cross[k]);
	}
	return cnt;
}

/* Primitive i drew px pixels. */
static void input_px(struct bench_input *in, uint32_t i, uint64_t px)
{
	in->cum[i + 1] = in->cum[i] + px;
	in->pixels = in->cum[i + 1];
}

static void input_make(struct bench_input *in, enum bench_kind kind)
{
	struct rng g = { BENCH_SEED };
	uint32_t i, *a;
	size_t nxy = 0;

	memset(in, 0, sizeof(*in));
	in->kind = kind;
	in->ops = kind_ops[kind];
	in->arg = xcalloc((size_t)in->ops + 1, BENCH_RECORD * 4);
	in->cum = xcalloc((size_t)in->ops + 1, sizeof(*in->cum));
	switch (kind) {
	case BENCH_FILL:
		make_fills(in->arg, BENCH_SEED, in->ops, false);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD)
			input_px(in, i,
				 (uint64_t)bench_fill_w(a) * bench_fill_h(a));
		break;
	case BENCH_BLIT:
	case BENCH_BLIT_XOR:
		in->prefill = xcalloc(BENCH_FILL_OPS, BENCH_RECORD * 4);
		make_fills(in->prefill, BENCH_PREFILL_SEED, BENCH_FILL_OPS,
			   false);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t sx = r32(&g) % BENCH_W, sy = r32(&g) % BENCH_H;
			uint32_t dx = r32(&g) % BENCH_W, dy = r32(&g) % BENCH_H;
			uint32_t w = 1 + r32(&g) % BENCH_RECT_MAX;
			uint32_t h = 1 + r32(&g) % BENCH_RECT_MAX;

			a[0] = sx;
			a[1] = sy;
			a[2] = dx;
			a[3] = dy;
			a[4] = umin(w, umin(BENCH_W - sx, BENCH_W - dx));
			a[5] = umin(h, umin(BENCH_H - sy, BENCH_H - dy));
			input_px(in, i, (uint64_t)a[4] * a[5]);
		}
		break;
	case BENCH_LINE:
	case BENCH_AALINE:
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t dx, dy;

			a[0] = r32(&g) % BENCH_W;
			a[1] = r32(&g) % BENCH_H;
			a[2] = r32(&g) % BENCH_W;
			a[3] = r32(&g) % BENCH_H;
			a[4] = r32(&g) | BENCH_OPAQUE;
			dx = a[2] > a[0] ? a[2] - a[0] : a[0] - a[2];
			dy = a[3] > a[1] ? a[3] - a[1] : a[1] - a[3];
			input_px(in, i, (dx > dy ? dx : dy) + 1);
		}
		break;
	case BENCH_CIRCLE:
	case BENCH_FILL_CIRCLE:
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			bool fill = kind == BENCH_FILL_CIRCLE;

			a[0] = r32(&g) % BENCH_W;
			a[1] = r32(&g) % BENCH_H;
			a[2] = 1 + r32(&g) % (fill ? BENCH_DISC_RADIUS_MAX :
						     BENCH_RADIUS_MAX);
			a[3] = r32(&g) | BENCH_OPAQUE;
			input_px(in, i,
				 circle_pixels((int)a[0], (int)a[1], (int)a[2],
					       fill));
		}
		break;
	case BENCH_POLYGON:
		in->xy = xcalloc((size_t)in->ops * BENCH_POLY_MAX,
				 2 * sizeof(int));
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t n = BENCH_POLY_MIN + r32(&g) % BENCH_POLY_MORE,
				 k;
			int ox = (int)(r32(&g) % BENCH_POLY_OX);
			int oy = (int)(r32(&g) % BENCH_POLY_OY);

			a[0] = n;
			a[1] = (uint32_t)nxy;
			for (k = 0; k < n; k++, nxy++) {
				in->xy[2 * nxy] =
					ox + (int)(r32(&g) % BENCH_POLY_SPAN);
				in->xy[2 * nxy + 1] =
					oy + (int)(r32(&g) % BENCH_POLY_SPAN);
			}
			a[2] = r32(&g) | BENCH_OPAQUE;
			input_px(in, i, polygon_pixels(in->xy + 2 * a[1], n));
		}
		break;
	case BENCH_TEXT: {
		struct rng f = { BENCH_FONT_SEED };

		for (i = 0; i < sizeof(in->font); i++)
			in->font[i] = (uint8_t)(r32(&f) >> 24);
		for (i = 0, a = in->arg; i < in->ops; i++, a += BENCH_RECORD) {
			uint32_t cell = i % (BENCH_COLS * BENCH_ROWS);

			a[0] = r32(&g) % BENCH_GLYPHS;
			a[1] = r32(&g) | BENCH_OPAQUE;
			a[2] = r32(&g) | BENCH_OPAQUE;
			a[3] = cell % BENCH_COLS * BENCH_GLYPH_W;
			a[4] = cell / BENCH_COLS * BENCH_GLYPH_H;
			input_px(in, i, BENCH_GLYPH_W * BENCH_GLYPH_H);
		}
		break;
	}
	case BENCH_SCANOUT:
		/* the CLUT first, from the workload's own stream */
		for (i = 0; i < BENCH_CLUT_SIZE; i++)
			in->clut[i] = r32(&g) & 0x00ffffffu;
		in->prefill = xcalloc(BENCH_FILL_OPS, BENCH_RECORD * 4);
		make_fills(in->prefill, BENCH_INDEX_SEED, BENCH_FILL_OPS, true);
		/* the indexed surface those fills draw, for limit and peers */
		in->index = xcalloc(BENCH_W, BENCH_H);
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

static void input_free(struct bench_input *in)
{
	free(in->arg);
	free(in->xy);
	free(in->prefill);
	free(in->index);
	free(in->cum);
}

/* ---- rdc: the workloads through librdc sim: ------------------------------ */

struct run {
	rdc_dev *dev;
	rdc_batch *b;
};

static void run_open(struct run *r, uint32_t preset, uint32_t format,
		     size_t bytes)
{
	uint8_t *zero = xcalloc(bytes, 1);
	int err = rdc_open("sim:", &r->dev);

	if (err)
		die("open", err);
	r->b = rdc_batch_new();
	if (!r->b)
		die("batch", RDC_E_NOMEM);
	err = rdc_mode_set(r->dev, preset, format, 0);
	if (!err)
		err = rdc_vram_write(r->dev, 0, zero, bytes);
	if (!err)
		err = rdc_finish(r->dev);
	if (err)
		die("setup", err);
	free(zero);
}

static void run_close(struct run *r)
{
	rdc_batch_free(r->b);
	rdc_close(r->dev);
}

/* Submit what the batch holds once it is big enough (or when forced). */
static void run_flush(struct run *r, bool force)
{
	size_t n;
	int err;

	rdc_batch_words(r->b, &n);
	if (!n || (!force && n < BATCH_WORDS))
		return;
	err = rdc_batch_submit(r->dev, r->b);
	if (err)
		die("submit", err);
}

static void run_finish(struct run *r)
{
	int err;

	run_flush(r, true);
	err = rdc_finish(r->dev);
	if (err)
		die("finish", err);
}

static uint32_t run_crc(struct run *r)
{
	uint8_t *buf = xcalloc(BENCH_W * BENCH_H, 4);
	uint32_t crc;
	int err;

	err = rdc_vram_read(r->dev, 0, buf, BENCH_W * BENCH_H * 4);
	if (err)
		die("vram read", err);
	crc = bench_surface_crc(buf, BENCH_W * 4);
	free(buf);
	return crc;
}

static void rdc_fills(struct run *r, const uint32_t *a, uint32_t ops)
{
	uint32_t i;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		rdc_batch_fg(r->b, a[4]);
		rdc_batch_fill_rect(r->b, (int)a[0], (int)a[1], a[2], a[3]);
		run_flush(r, false);
	}
}

static void rdc_draw(struct run *r, const struct bench_input *in)
{
	const uint32_t *a = in->arg;
	uint32_t i;

	switch (in->kind) {
	case BENCH_FILL:
		rdc_fills(r, a, in->ops);
		return;
	default:
		break;
	}
	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		switch (in->kind) {
		case BENCH_BLIT:
		case BENCH_BLIT_XOR:
			rdc_batch_blit(r->b, (int)a[0], (int)a[1], (int)a[2],
				       (int)a[3], a[4], a[5]);
			break;
		case BENCH_LINE:
			rdc_batch_fg(r->b, a[4]);
			rdc_batch_line(r->b, (int)a[0], (int)a[1], (int)a[2],
				       (int)a[3]);
			break;
		case BENCH_AALINE:
			rdc_batch_fg(r->b, a[4]);
			rdc_batch_aa_line(r->b, (int)a[0], (int)a[1], (int)a[2],
					  (int)a[3]);
			break;
		case BENCH_CIRCLE:
			rdc_batch_fg(r->b, a[3]);
			rdc_batch_circle(r->b, (int)a[0], (int)a[1], a[2]);
			break;
		case BENCH_FILL_CIRCLE:
			rdc_batch_fg(r->b, a[3]);
			rdc_batch_fill_circle(r->b, (int)a[0], (int)a[1], a[2]);
			break;
		case BENCH_POLYGON:
			rdc_batch_fg(r->b, a[2]);
			rdc_batch_fill_polygon(r->b, in->xy + 2 * a[1], a[0],
					       0);
			break;
		case BENCH_TEXT:
			rdc_batch_fg(r->b, a[1]);
			rdc_batch_bg(r->b, a[2]);
			rdc_batch_mono(r->b, (int)a[3], (int)a[4],
				       BENCH_GLYPH_W, BENCH_GLYPH_H,
				       in->font + a[0] * BENCH_GLYPH_H, 0);
			break;
		default:
			return;
		}
		run_flush(r, false);
	}
}

/* What the chip hands over at each vblank: count it, pass it on. */
struct frames {
	rdc_sink *sink;
	uint64_t seen;
	uint32_t num, den;
	uint32_t crc;
	bool want_crc;
};

static void frames_fn(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		      uint64_t number)
{
	struct frames *f = ctx;
	struct rdc_frame fr = { .xrgb = xrgb,
				.width = w,
				.height = h,
				.stride = w,
				.seq = number,
				.interval_num = f->num,
				.interval_den = f->den };

	f->seen++;
	if (f->sink)
		rdc_sink_frame(f->sink, &fr);
	if (f->want_crc)
		f->crc = (uint32_t)crc32(0, (const uint8_t *)xrgb,
					 (uInt)w * h * 4);
}

struct rdc_res {
	double wall;
	uint64_t cycles;
	uint64_t sim_pixels; /* pixels the DP wrote, by its own count */
	uint32_t crc;
	uint64_t frames;    /* scanned out while drawing (scanout on) */
	uint32_t frame_crc; /* of the first frame after the drawing */
};

/* CONTROL.SCANOUT_EN = 0: the CRTC stops, and with it its bus traffic. */
static void scanout_off(rdc_dev *dev)
{
	uint32_t ctl;

	if (rdc_reg_read(dev, RDC_REG_CONTROL, &ctl) ||
	    rdc_reg_write(dev, RDC_REG_CONTROL,
			  ctl & ~(uint32_t)RDC_CONTROL_SCANOUT_EN) ||
	    rdc_reg_read(dev, RDC_REG_CONTROL, &ctl) ||
	    (ctl & RDC_CONTROL_SCANOUT_EN))
		die("scanout off", RDC_E_IO);
}

/*
 * scanout: every frame the CRTC converts through the CLUT is handed to
 * the frame listener, as in rdcd; 600 of them are timed.
 */
static void rdc_scanout(const struct bench_input *in, struct rdc_res *res)
{
	struct frames f = { 0 };
	struct run r;
	struct rdc_hw *hw;
	uint64_t c0, c1;
	double t0;

	run_open(&r, RDC_PRESET_1024x768_60, RDC_FMT_I8, BENCH_W * BENCH_H);
	rdc_batch_load_clut(r.b, 0, in->clut, BENCH_CLUT_SIZE);
	rdc_fills(&r, in->prefill, BENCH_FILL_OPS);
	run_finish(&r);
	/* the mode is latched at a vblank: let it be in force first */
	if (rdc_frame_wait(r.dev))
		die("frame wait", RDC_E_TIMEOUT);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		die("sim hw", RDC_E_NOSYS);
	rdc_hw_set_frame_fn(hw, frames_fn, &f);
	rdc_sim_time(r.dev, &c0);
	t0 = bench_tic();
	while (f.seen < in->ops - 1)
		if (rdc_vblank_wait(r.dev))
			die("vblank", RDC_E_TIMEOUT);
	f.want_crc = true; /* outside the drawing proper, but cheap */
	while (f.seen < in->ops)
		if (rdc_vblank_wait(r.dev))
			die("vblank", RDC_E_TIMEOUT);
	res->wall = bench_toc(t0);
	rdc_sim_time(r.dev, &c1);
	res->cycles = c1 - c0;
	res->crc = f.crc;
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	run_close(&r);
}

/*
 * The prefill (blit, scanout) is drawn through the device on every run,
 * untimed: loading a saved image instead would start the timed part at
 * another simulated time, and sim_cycles must not depend on the repeat.
 */
/*
 * scan false: CONTROL.SCANOUT_EN is cleared before the prefill, so the
 * drawing runs without the CRTC's reads of VRAM (and their bus stalls).
 * scan true: the frames the CRTC completes during the drawing are counted
 * (the frame listener), and the frame after it is the one whose CRC the
 * limit with scanout must reproduce.  lazy (with scan): scanout on with
 * no frame consumer (scanout on demand, hw-sim/rdc_chip.h): the same bus
 * and cycles, no frame converted; the frames are counted by FRAME_COUNT,
 * and the frame after the drawing is taken with a consumer attached.
 */
static void rdc_run(const struct bench_input *in, struct rdc_res *res,
		    bool scan, bool lazy)
{
	uint32_t fc0 = 0, fc1 = 0;
	struct rdc_stats st0 = { 0 }, st1 = { 0 };
	struct frames f = { 0 };
	struct rdc_hw *hw;
	struct run r;
	uint64_t c0, c1;
	double t0;

	if (in->kind == BENCH_SCANOUT) {
		rdc_scanout(in, res);
		return;
	}
	run_open(&r, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888,
		 BENCH_W * BENCH_H * 4);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		die("sim hw", RDC_E_NOSYS);
	if (!scan)
		scanout_off(r.dev);
	if (lazy)
		rdc_hw_set_on_demand(hw, true);
	if (in->prefill) {
		rdc_fills(&r, in->prefill, BENCH_FILL_OPS);
		if (in->kind == BENCH_BLIT_XOR)
			rdc_batch_rop(r.b, RDC_ROP_XOR);
		run_finish(&r);
	}
	rdc_stats_get(r.dev, &st0);
	if (scan && !lazy)
		rdc_hw_set_frame_fn(hw, frames_fn, &f);
	if (lazy && rdc_reg_read(r.dev, RDC_REG_FRAME_COUNT, &fc0))
		die("frame count", RDC_E_IO);
	rdc_sim_time(r.dev, &c0);
	t0 = bench_tic();
	rdc_draw(&r, in);
	run_finish(&r);
	res->wall = bench_toc(t0);
	rdc_sim_time(r.dev, &c1);
	if (lazy && rdc_reg_read(r.dev, RDC_REG_FRAME_COUNT, &fc1))
		die("frame count", RDC_E_IO);
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	rdc_stats_get(r.dev, &st1);
	res->cycles = c1 - c0;
	res->sim_pixels = st1.pixels - st0.pixels;
	res->frames = lazy ? fc1 - fc0 : f.seen;
	res->frame_crc = 0;
	if (lazy)
		rdc_hw_consumer_attach(hw);
	if (scan &&
	    (rdc_frame_wait(r.dev) || rdc_frame_crc(r.dev, &res->frame_crc)))
		die("frame crc", RDC_E_IO);
	if (lazy)
		rdc_hw_consumer_detach(hw);
	res->crc = run_crc(&r);
	run_close(&r);
}

/*
 * realtime: rdcd's pipeline unpaced.  Each frame's drawing (1,000 lines,
 * 100 fills, 100 text rows) is submitted, then simulated time runs on to
 * the next vblank; every frame the chip completes goes to a frame sink
 * that discards it (png with every=0 writes only on request).
 */
struct rt_res {
	double wall;
	double cpu; /* CPU seconds of the drawing thread over the same span */
	uint64_t frames, drawn, cycles;
	uint32_t crc;
	uint32_t khz; /* teapot3d: the core clock */
};

/* The realtime workload's modes: 640x480 (20x real time wanted), 1080p. */
struct rt_mode {
	uint32_t preset, w, h;
	uint32_t target_fps; /* simulated frames a wall second wanted */
	uint32_t frames;     /* run this many frames or RT_MAX_S */
};

static const struct rt_mode rt_vga = { RT_PRESET, RT_W, RT_H, RT_TARGET_FPS,
				       RT_FRAMES };
static const struct rt_mode rt_1080 = { RDC_PRESET_1920x1080_60, 1920, 1080,
					RT_HZ, 2 * RT_HZ };
#define RT_MAX_COLS (1920 / BENCH_GLYPH_W)

static void rt_frame(struct run *r, struct rng *g, const struct rt_mode *m)
{
	char text[RT_MAX_COLS];
	uint32_t i, k, cols = m->w / BENCH_GLYPH_W, rows = m->h / BENCH_GLYPH_H;

	for (i = 0; i < RT_LINES; i++) {
		int x0 = (int)(r32(g) % m->w), y0 = (int)(r32(g) % m->h);
		int x1 = (int)(r32(g) % m->w), y1 = (int)(r32(g) % m->h);

		rdc_batch_fg(r->b, r32(g) | BENCH_OPAQUE);
		rdc_batch_line(r->b, x0, y0, x1, y1);
	}
	for (i = 0; i < RT_FILLS; i++) {
		int x = (int)(r32(g) % m->w), y = (int)(r32(g) % m->h);
		uint32_t w = 1 + r32(g) % RT_FILL_MAX;
		uint32_t h = 1 + r32(g) % RT_FILL_MAX;

		rdc_batch_fg(r->b, r32(g) | BENCH_OPAQUE);
		rdc_batch_fill_rect(r->b, x, y, w, h);
	}
	for (i = 0; i < RT_TEXT_ROWS; i++) {
		for (k = 0; k < cols; k++)
			text[k] = (char)(RT_FIRST_CHAR + r32(g) % RT_CHARS);
		rdc_batch_fg(r->b, r32(g) | BENCH_OPAQUE);
		rdc_batch_bg(r->b, r32(g) | BENCH_OPAQUE);
		rdc_batch_text(r->b, 0, (int)(i % rows * BENCH_GLYPH_H), text,
			       cols, 0);
	}
	run_flush(r, true);
}

static uint64_t t3_busy(rdc_dev *dev)
{
	uint32_t lo = 0, hi = 0;

	/* reading LO snapshots HI */
	if (rdc_reg_read(dev, RDC_REG_PERF_BUSY_LO, &lo) ||
	    rdc_reg_read(dev, RDC_REG_PERF_BUSY_HI, &hi))
		die("perf read", RDC_E_IO);
	return (uint64_t)hi << 32 | lo;
}

static void rdc_teapot3d(struct rt_res *res)
{
	struct rdc_script_result sres;
	struct run r;
	uint64_t b0, b1;
	double t0;
	uint32_t i;
	int err;

	run_open(&r, RT_PRESET, RDC_FMT_XRGB8888, RT_W * RT_H * 4);
	memset(&sres, 0, sizeof(sres));
	err = rdc_script_run_file(r.dev, T3_SCRIPT, &sres);
	if (err) {
		fprintf(stderr,
			"rdc-bench: %s:%u: %s (run from the source "
			"tree)\n",
			T3_SCRIPT, sres.error_line, sres.error_msg);
		exit(1);
	}
	if (rdc_reg_read(r.dev, RDC_REG_CORE_KHZ, &res->khz))
		die("core clock", RDC_E_IO);
	b0 = t3_busy(r.dev);
	t0 = bench_now();
	for (i = 0; i < T3_FRAMES; i++) {
		uint32_t buf = i & 1 ? 0 : T3_BUF1, turn = T3_TURN;

		rdc_batch_dst(r.b, buf, RT_W * 4, RT_W, RT_H, RDC_FMT_XRGB8888);
		rdc_batch_call(r.b, T3_DRAW);
		rdc_batch_reg_write(r.b, RDC_REG_FB_BASE, buf);
		rdc_batch_cmd(r.b, RDC_OP_ROTATE, RDC_AXIS_Z, &turn, 1);
		run_finish(&r);
	}
	res->wall = bench_now() - t0;
	b1 = t3_busy(r.dev);
	res->frames = T3_FRAMES;
	res->drawn = T3_FRAMES;
	res->cycles = b1 - b0;
	if (rdc_frame_wait(r.dev) || rdc_frame_crc(r.dev, &res->crc))
		res->crc = 0;
	run_close(&r);
}

/* Frames the chip completed: FRAME_COUNT, for a run without a listener. */
static uint64_t rt_frame_count(rdc_dev *dev)
{
	uint32_t fc;

	if (rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &fc))
		die("frame count", RDC_E_IO);
	return fc;
}

/*
 * lazy: the same drawing and time with no frame consumer at all (no
 * sink, no listener; scanout on demand): the bus is charged the same, no
 * frame is converted.  The frames are counted by FRAME_COUNT.
 */
static void rdc_realtime(struct rt_res *res, const struct rt_mode *m, bool lazy)
{
	struct frames f = { 0 };
	struct rng g = { BENCH_SEED };
	struct rdc_hw *hw;
	struct run r;
	uint64_t c0, c1, f0, seen;
	double t0;
	int err;

	run_open(&r, m->preset, RDC_FMT_XRGB8888, (size_t)m->w * m->h * 4);
	if (rdc_frame_wait(r.dev))
		die("frame wait", RDC_E_TIMEOUT);
	hw = rdc_sim_hw(r.dev);
	if (!hw)
		die("sim hw", RDC_E_NOSYS);
	if (lazy) {
		rdc_hw_set_on_demand(hw, true);
	} else {
		err = rdc_sink_open(RT_SINK, &f.sink);
		if (err)
			die("sink", err);
		if (rdc_sink_interval(r.dev, &f.num, &f.den))
			f.num = f.den = 0;
		rdc_hw_set_frame_fn(hw, frames_fn, &f);
	}
	res->drawn = 0;
	rdc_sim_time(r.dev, &c0);
	f0 = lazy ? rt_frame_count(r.dev) : f.seen;
	t0 = bench_now();
	res->cpu = cpu_now();
	do {
		rt_frame(&r, &g, m);
		res->drawn++;
		if (rdc_vblank_wait(r.dev))
			die("vblank", RDC_E_TIMEOUT);
		res->wall = bench_now() - t0;
		seen = lazy ? rt_frame_count(r.dev) : f.seen;
	} while (seen - f0 < m->frames && res->wall < RT_MAX_S);
	res->cpu = cpu_now() - res->cpu;
	rdc_sim_time(r.dev, &c1);
	res->frames = seen - f0;
	res->cycles = c1 - c0;
	rdc_hw_set_frame_fn(hw, NULL, NULL);
	if (lazy)
		rdc_hw_set_on_demand(hw, false); /* the CRC's frame: kept */
	if (rdc_frame_crc(r.dev, &res->crc))
		res->crc = 0;
	if (f.sink)
		rdc_sink_close(f.sink);
	run_close(&r);
}

/* ---- plain-C limits of the byte-moving workloads ------------------------- */

/* A limit draws into s (BENCH_W x BENCH_H words, cleared) and returns its
 * seconds; the CRC of s afterwards is checked against rdc's. */
struct limit {
	const char *name;
	double (*run)(const struct bench_input *in, uint32_t *s);
	const char *scan_name; /* the same with the frames' scanout */
};

static void c_fills(uint32_t *s, const uint32_t *a, uint32_t ops)
{
	uint32_t i, yy, xx;

	for (i = 0; i < ops; i++, a += BENCH_RECORD) {
		uint32_t w = bench_fill_w(a), h = bench_fill_h(a), c = a[4];

		for (yy = 0; yy < h; yy++) {
			uint32_t *p = s + (size_t)(a[1] + yy) * BENCH_W + a[0];

			for (xx = 0; xx < w; xx++)
				p[xx] = c;
		}
	}
}

static double limit_store(const struct bench_input *in, uint32_t *s)
{
	double t0 = bench_tic();

	c_fills(s, in->arg, in->ops);
	return bench_toc(t0);
}

/* glibc's memset for 32-bit units: the same bytes as the store loop. */
static double limit_wmemset(const struct bench_input *in, uint32_t *s)
{
	const uint32_t *a = in->arg;
	double t0 = bench_tic();
	uint32_t i, yy;

	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		uint32_t w = bench_fill_w(a), h = bench_fill_h(a);

		for (yy = 0; yy < h; yy++)
			wmemset((wchar_t *)(s + (size_t)(a[1] + yy) * BENCH_W +
					    a[0]),
				(wchar_t)a[4], w);
	}
	return bench_toc(t0);
}

/*
 * Row order makes overlapping copies read their source before writing
 * over it: bottom-up when moving down; within one row memmove, and for
 * xor a copy of the source row first when source and destination share
 * the row.
 */
static double limit_blit_any(const struct bench_input *in, uint32_t *s,
			     bool do_xor)
{
	const uint32_t *a = in->arg;
	uint32_t tmp[BENCH_RECT_MAX], i, yy, xx;
	double t0;

	c_fills(s, in->prefill, BENCH_FILL_OPS);
	t0 = bench_tic();
	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		uint32_t sx = a[0], sy = a[1], dx = a[2], dy = a[3];
		uint32_t w = a[4], h = a[5];
		bool up = dy <= sy;

		for (yy = 0; yy < h; yy++) {
			uint32_t row = up ? yy : h - 1 - yy;
			uint32_t *d = s + (size_t)(dy + row) * BENCH_W + dx;
			const uint32_t *src =
				s + (size_t)(sy + row) * BENCH_W + sx;

			if (!do_xor) {
				memmove(d, src, (size_t)w * 4);
				continue;
			}
			if (sy == dy) {
				memcpy(tmp, src, (size_t)w * 4);
				src = tmp;
			}
			for (xx = 0; xx < w; xx++)
				d[xx] ^= src[xx];
		}
	}
	return bench_toc(t0);
}

static double limit_blit(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, false);
}

static double limit_blit_xor(const struct bench_input *in, uint32_t *s)
{
	return limit_blit_any(in, s, true);
}

static double limit_text(const struct bench_input *in, uint32_t *s)
{
	const uint32_t *a = in->arg;
	double t0 = bench_tic();
	uint32_t i, row, bit;

	for (i = 0; i < in->ops; i++, a += BENCH_RECORD) {
		const uint8_t *glyph = in->font + a[0] * BENCH_GLYPH_H;
		uint32_t fg = a[1], bg = a[2];
		uint32_t *p = s + (size_t)a[4] * BENCH_W + a[3];

		for (row = 0; row < BENCH_GLYPH_H; row++, p += BENCH_W) {
			uint8_t bits = glyph[row];

			for (bit = 0; bit < BENCH_GLYPH_W; bit++)
				p[bit] = (bits & (0x80 >> bit)) ? fg : bg;
		}
	}
	return bench_toc(t0);
}

static double limit_scanout(const struct bench_input *in, uint32_t *s)
{
	const uint8_t *src = in->index;
	double t0 = bench_tic();
	uint32_t f, i;

	for (f = 0; f < in->ops; f++) {
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			s[i] = in->clut[src[i]];
		/* each frame is a new output: keep every one of them */
		__asm__ volatile("" : : "r"(s) : "memory");
	}
	return bench_toc(t0);
}

static const struct limit limits[BENCH_KIND_COUNT][2] = {
	[BENCH_FILL] = { { "store", limit_store, "store+scan" },
			 { "wmemset", limit_wmemset, "wmemset+scan" } },
	[BENCH_BLIT] = { { "memmove", limit_blit, "memmove+scan" } },
	[BENCH_BLIT_XOR] = { { "xor", limit_blit_xor, "xor+scan" } },
	[BENCH_TEXT] = { { "expand", limit_text, "expand+scan" } },
	[BENCH_SCANOUT] = { { "lookup", limit_scanout, NULL } },
};
#define MAX_LIMITS 2

/*
 * The limit with scanout: after the drawing, the chip's conversion of the
 * surface to an XRGB8888 frame (the X byte cleared, as the CRTC and the
 * sinks see it), done `frames` times: as many frames as the chip scanned
 * out while it drew.  (The chip converts while it draws, seeing the
 * picture half done; the bytes moved are the same.)  Returns the seconds
 * and sets *crc to the last frame's CRC, converted once more untimed when
 * frames is 0, which must equal the chip's frame after the drawing.
 */
static double scan_frames(const uint32_t *s, uint64_t frames, double *cpu,
			  uint32_t *crc)
{
	uint32_t *fb = xcalloc((size_t)BENCH_W * BENCH_H, 4);
	uint64_t f;
	double t0 = bench_tic(), t;
	uint32_t i;

	for (f = 0; f < frames; f++) {
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			fb[i] = s[i] & 0x00ffffffu;
		/* each frame is a new output: keep every one of them */
		__asm__ volatile("" : : "r"(fb) : "memory");
	}
	t = bench_toc(t0);
	*cpu = bench_cpu();
	if (!frames)
		for (i = 0; i < BENCH_W * BENCH_H; i++)
			fb[i] = s[i] & 0x00ffffffu;
	*crc = (uint32_t)crc32(0, (const uint8_t *)fb, BENCH_W * BENCH_H * 4);
	free(fb);
	return t;
}

/* ---- measuring ----------------------------------------------------------- */

struct figure {
	const char *name;
	uint32_t ops;	 /* primitives drawn: all, or a peer's prefix */
	uint64_t pixels; /* that many draw */
	double wall;	 /* median seconds */
	double cpu;	 /* median CPU seconds of the drawing thread */
	uint32_t crc;	 /* of the last run */
	bool crc_same;	 /* every run gave the same CRC */
	int runs;
	bool slow; /* repeats cut short: see SLOW_S */
	bool done;
	uint32_t frame_crc; /* a limit with scanout: its last frame's */
	uint64_t frames;    /* a peer with scanout: the frames it converts */
};

struct opts {
	int repeat;
	bool json, full, peers;
};

static double least(const double *v, int n)
{
	double m = v[0];
	int i;

	for (i = 1; i < n; i++)
		m = v[i] < m ? v[i] : m;
	return m;
}

static double median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof(double), cmp_double);
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* One contender in a workload: rdc, a limit or a peer. */
struct entrant {
	struct figure *fig;
	double (*one)(void *ctx, uint32_t ops, uint32_t *crc);
	void *ctx;
	double wall[MAX_REPEAT], cpu[MAX_REPEAT];
	bool failed;
};

/*
 * Run every entrant once per round, o->repeat rounds, and keep each one's
 * median.  Interleaving the rounds puts all of a workload's figures in the
 * same stretch of time, so that a shared machine's load shifts them alike
 * and their ratios hold.  An entrant whose first run was slow (SLOW_S)
 * sits out the later rounds.
 */
static void measure(struct entrant *e, size_t n, const struct opts *o)
{
	size_t i;
	int k;

	for (k = 0; k < o->repeat; k++) {
		for (i = 0; i < n; i++) {
			struct figure *f = e[i].fig;
			uint32_t crc = 0;
			double t;

			if (e[i].failed || f->slow)
				continue;
			t = e[i].one(e[i].ctx, f->ops, &crc);
			if (t < 0) {
				e[i].failed = true;
				continue;
			}
			e[i].cpu[f->runs] = bench_cpu();
			e[i].wall[f->runs++] = t;
			f->crc_same = f->crc_same && (!k || crc == f->crc);
			f->crc = crc;
			if (!k && t > SLOW_S && o->repeat > 1 && !o->full)
				f->slow = true;
		}
	}
	for (i = 0; i < n; i++) {
		struct figure *f = e[i].fig;

		if (f->runs) {
			f->wall = median(e[i].wall, f->runs);
			f->cpu = median(e[i].cpu, f->runs);
			f->done = true;
		}
	}
}

/* A figure for `name` over the first `ops` primitives of `in`. */
static void figure_init(struct figure *f, const char *name,
			const struct bench_input *in, uint32_t ops)
{
	memset(f, 0, sizeof(*f));
	f->name = name;
	f->ops = ops;
	f->pixels = in->cum[ops];
	f->crc_same = true;
}

struct rdc_ctx {
	const struct bench_input *in;
	bool scan; /* scanout on */
	bool lazy; /* and no frame consumer */
	uint64_t cycles, sim_pixels, frames;
	uint32_t frame_crc;
	bool cycles_differ; /* a run's simulated time was not the first's */
};

static double rdc_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct rdc_ctx *c = ctx;
	struct rdc_res res = { 0 };

	(void)ops; /* always all of it */
	rdc_run(c->in, &res, c->scan, c->lazy);
	*crc = res.crc;
	if (c->cycles && (c->cycles != res.cycles || c->frames != res.frames ||
			  c->frame_crc != res.frame_crc))
		c->cycles_differ = true;
	c->cycles = res.cycles;
	c->sim_pixels = res.sim_pixels;
	c->frames = res.frames;
	c->frame_crc = res.frame_crc;
	return res.wall;
}

struct limit_ctx {
	const struct bench_input *in;
	const struct limit *lim;
	const struct rdc_ctx *scan; /* with scanout: rdc's frame count */
	uint32_t frame_crc;	    /* of the last frame converted */
	bool frame_crc_same;	    /* every run's was the same */
	int runs;
};

static double limit_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct limit_ctx *c = ctx;
	uint32_t *s = xcalloc((size_t)BENCH_W * BENCH_H, 4);
	double t = c->lim->run(c->in, s);

	(void)ops; /* always all of it */
	if (c->scan) {
		double cpu = bench_cpu(), cpu2;
		uint32_t fcrc;

		t += scan_frames(s, c->scan->frames, &cpu2, &fcrc);
		toc_cpu = cpu + cpu2;
		c->frame_crc_same = !c->runs ||
				    (c->frame_crc_same && fcrc == c->frame_crc);
		c->frame_crc = fcrc;
		c->runs++;
	}
	*crc = bench_surface_crc(s, BENCH_W * 4);
	free(s);
	return t;
}

struct peer_ctx {
	const struct bench_input *in;
	const struct bench_peer *peer;
};

static double peer_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct peer_ctx *c = ctx;

	return c->peer->run(c->in, ops, crc);
}

/*
 * A peer with scanout: the peer's drawing, then as many frame conversions
 * as rdc's scanout made for the pixels the peer drew (a peer may draw a
 * prefix: the frames are prorated by pixels).  The conversions read a
 * surface of the peer's size that was written before (the peer keeps its
 * own), so they cost what the limits' do.
 */
struct peer_scan_ctx {
	const struct bench_input *in;
	const struct bench_peer *peer;
	const struct rdc_ctx *scan; /* rdc's frame count */
	struct figure *fig;
};

static double peer_scan_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct peer_scan_ctx *c = ctx;
	double t = c->peer->run(c->in, ops, crc), cpu, cpu2;
	uint32_t *s, fcrc;

	if (t < 0)
		return t;
	cpu = bench_cpu();
	c->fig->frames =
		(uint64_t)((double)c->scan->frames * (double)c->fig->pixels /
				   (double)c->in->pixels +
			   0.5);
	s = xcalloc((size_t)BENCH_W * BENCH_H, 4);
	memset(s, 0x5a, (size_t)BENCH_W * BENCH_H * 4);
	t += scan_frames(s, c->fig->frames, &cpu2, &fcrc);
	toc_cpu = cpu + cpu2;
	free(s);
	return t;
}

/* How much of the workload a peer draws: see PEER_BUDGET_S. */
static uint32_t peer_ops(const struct bench_input *in,
			 const struct bench_peer *peer, const struct opts *o)
{
	uint32_t probe = in->ops / PEER_PROBE ? in->ops / PEER_PROBE : 1;
	uint32_t crc, ops;
	double t, est;

	if (o->full)
		return in->ops;
	t = peer->run(in, probe, &crc);
	if (t < 0 || !in->cum[probe])
		return in->ops;
	est = t * (double)in->pixels / (double)in->cum[probe];
	if (est <= PEER_BUDGET_S)
		return in->ops;
	ops = (uint32_t)((double)in->ops * PEER_BUDGET_S / est);
	return ops > probe ? ops : probe;
}

/* ---- reporting ----------------------------------------------------------- */

/* rdc's figures one way (scanout on, or off) and how they compare. */
struct way {
	struct figure *fig;
	uint64_t cycles, sim_pixels;
	bool crc_ok, cycles_ok;
	double vs_limit, vs_peer; /* 0: none measured */
	const char *best_limit, *best_peer;
	/* scanout on: against the peers without their scanout */
	double vs_peer_plain;
	const char *best_peer_plain;
	double target;	       /* the ratio wanted; 0: none */
	const char *target_of; /* against what */
	double vs_target;
	bool met;
};

struct result {
	enum bench_kind kind;
	uint64_t ops, pixels;
	struct figure rdc, rdc_off;
	struct figure rdc_lazy; /* scanout on, no frame consumer */
	uint64_t lazy_cycles, lazy_frames;
	uint32_t lazy_frame_crc;
	bool lazy_ok;	 /* its cycles, frames, CRC and frame as rdc's */
	double fps_lazy; /* realtime with no frame consumer */
	/* realtime: frames a CPU second of the drawing thread, with its
	 * sink and with no consumer (what the ratio compares) */
	double cpu_fps, cpu_fps_lazy;
	struct figure lim[MAX_LIMITS];
	struct figure lim_scan[MAX_LIMITS];
	struct figure peer[NPEERS + 1];
	struct figure peer_scan[NPEERS + 1]; /* drawing workloads */
	struct way on, off;		     /* off: drawing workloads only */
	uint64_t frames;    /* scanned out during the drawing (scanout on) */
	uint32_t frame_crc; /* rdc's frame after the drawing */
	bool frame_crc_ok;  /* every limit with scanout made the same frame */
	double fps;	    /* realtime: simulated frames a wall second */
	double sim_fps;	    /* teapot3d: frames a simulated second */
	uint64_t rt_drawn;  /* realtime: frames' worth of drawing submitted */
	bool rt1080;	    /* realtime at 1920x1080 */
};

static double mpix(uint64_t pixels, double wall)
{
	return wall > 0 ? (double)pixels / wall / 1e6 : 0;
}

/* Pixels per CPU second: what rdc/limit and rdc/best-peer compare. */
static double rate(const struct figure *f)
{
	return f->cpu > 0 ? (double)f->pixels / f->cpu : 0;
}

static const char *crc_word(enum bench_kind k, uint32_t crc)
{
	if (!expect_crc[k])
		return "";
	return crc == expect_crc[k] ? "OK" : "MISMATCH";
}

static bool realtime(enum bench_kind k)
{
	return k == BENCH_REALTIME || k == BENCH_REALTIME_1080;
}

static const struct rt_mode *rt_mode_of(enum bench_kind k)
{
	return k == BENCH_REALTIME_1080 ? &rt_1080 : &rt_vga;
}

static void print_figures(const char *key, const struct figure *f, size_t n,
			  const struct result *res)
{
	size_t i;
	bool first = true;

	printf(",\"%s\":[", key);
	for (i = 0; i < n; i++) {
		if (!f[i].done)
			continue;
		printf("%s{\"name\":\"%s\",\"ops\":%u,\"pixels\":%llu,"
		       "\"wall_s\":%.6f,\"cpu_s\":%.6f,\"mpix_s\":%.1f,"
		       "\"crc32\":\"%08x\",\"runs\":%d",
		       first ? "" : ",", f[i].name, f[i].ops,
		       (unsigned long long)f[i].pixels, f[i].wall, f[i].cpu,
		       mpix(f[i].pixels, f[i].wall), f[i].crc, f[i].runs);
		if (expect_crc[res->kind] && f[i].ops == res->ops)
			printf(",\"crc_ok\":%s",
			       f[i].crc == expect_crc[res->kind] ? "true" :
								   "false");
		if (f == res->lim_scan)
			printf(",\"frames\":%llu,\"frame_crc32\":\"%08x\"",
			       (unsigned long long)res->frames, f[i].frame_crc);
		if (f == res->peer_scan)
			printf(",\"frames\":%llu",
			       (unsigned long long)f[i].frames);
		printf("}");
		first = false;
	}
	printf("]");
}

/* The keys one way of a drawing workload shares with the other. */
static void print_way(const struct result *res, const struct way *w)
{
	const struct figure *f = w->fig;

	printf("\"wall_s\":%.6f,\"mpix_s\":%.1f,\"ops_s\":%.0f,"
	       "\"sim_cycles\":%llu,\"crc32\":\"%08x\"",
	       f->wall, mpix(res->pixels, f->wall), (double)res->ops / f->wall,
	       (unsigned long long)w->cycles, f->crc);
	if (expect_crc[res->kind])
		printf(",\"crc_ok\":%s", w->crc_ok ? "true" : "false");
	printf(",\"cpu_s\":%.6f,\"runs\":%d", f->cpu, f->runs);
	if (w->sim_pixels)
		printf(",\"sim_pixels\":%llu",
		       (unsigned long long)w->sim_pixels);
	if (f->slow)
		printf(",\"note\":\"first run over %.0f s: not repeated\"",
		       SLOW_S);
}

static void print_target(const struct way *w)
{
	if (w->best_limit)
		printf(",\"vs_limit\":%.3f,\"best_limit\":\"%s\"", w->vs_limit,
		       w->best_limit);
	if (w->best_peer)
		printf(",\"vs_peer\":%.3f,\"best_peer\":\"%s\"", w->vs_peer,
		       w->best_peer);
	if (w->best_peer_plain)
		printf(",\"vs_peer_plain\":%.3f,\"best_peer_plain\":\"%s\"",
		       w->vs_peer_plain, w->best_peer_plain);
	if (w->target > 0)
		printf(",\"target\":%.1f,\"target_of\":\"%s\","
		       "\"vs_target\":%.3f",
		       w->target, w->target_of, w->vs_target);
	printf(",\"met\":%s", w->met ? "true" : "false");
}

/*
 * Scanout on with no frame consumer (bench/README.md, "Scanout on
 * demand"): its figures, and its CPU time over scanout off's and over
 * scanout on's with a consumer.
 */
static void print_lazy(const struct result *res)
{
	const struct figure *f = &res->rdc_lazy;

	printf(",\"scanout_no_consumer\":{\"wall_s\":%.6f,\"cpu_s\":%.6f,"
	       "\"runs\":%d,\"sim_cycles\":%llu,\"frames_scanned\":%llu,"
	       "\"frame_crc32\":\"%08x\",\"crc32\":\"%08x\",\"same_as_on\":%s,"
	       "\"cpu_vs_off\":%.3f,\"cpu_vs_on\":%.3f}",
	       f->wall, f->cpu, f->runs, (unsigned long long)res->lazy_cycles,
	       (unsigned long long)res->lazy_frames, res->lazy_frame_crc,
	       f->crc, res->lazy_ok ? "true" : "false",
	       res->rdc_off.cpu > 0 ? f->cpu / res->rdc_off.cpu : 0,
	       res->rdc.cpu > 0 ? f->cpu / res->rdc.cpu : 0);
}

static void print_json(const struct result *res)
{
	const struct figure *f = &res->rdc;

	printf("{\"workload\":\"%s\",\"ops\":%llu,\"pixels\":%llu,",
	       kind_name[res->kind], (unsigned long long)res->ops,
	       (unsigned long long)res->pixels);
	if (realtime(res->kind) || res->kind == BENCH_TEAPOT3D) {
		printf("\"wall_s\":%.6f,\"mpix_s\":%.1f,\"ops_s\":%.0f,"
		       "\"sim_cycles\":%llu,\"crc32\":\"%08x\",\"runs\":%d",
		       f->wall, mpix(res->pixels, f->wall),
		       (double)res->ops / f->wall,
		       (unsigned long long)res->on.cycles, f->crc, f->runs);
	} else {
		print_way(res, &res->on);
	}
	if (expect_cycles[res->kind])
		printf(",\"cycles_ok\":%s",
		       res->on.cycles_ok ? "true" : "false");
	if (realtime(res->kind)) {
		const struct rt_mode *m = rt_mode_of(res->kind);

		printf(",\"width\":%u,\"height\":%u,\"fps\":%.1f,"
		       "\"target_fps\":%u,\"vs_target\":%.3f,"
		       "\"frames_drawn\":%llu",
		       m->w, m->h, res->fps, m->target_fps,
		       res->fps / m->target_fps,
		       (unsigned long long)res->rt_drawn);
	}
	if (res->kind == BENCH_TEAPOT3D)
		printf(",\"wall_fps\":%.1f,\"sim_fps\":%.1f,\"target_fps\":%u,"
		       "\"vs_target\":%.3f",
		       res->fps, res->sim_fps, RT_HZ, res->sim_fps / RT_HZ);
	if (drawing(res->kind))
		printf(",\"scanout\":\"on\",\"frames_scanned\":%llu,"
		       "\"frame_crc32\":\"%08x\"",
		       (unsigned long long)res->frames, res->frame_crc);
	if (byte_moving(res->kind))
		print_figures("limits", res->lim, MAX_LIMITS, res);
	if (byte_moving(res->kind) && drawing(res->kind)) {
		print_figures("limits_scan", res->lim_scan, MAX_LIMITS, res);
		printf(",\"frame_crc_ok\":%s",
		       res->frame_crc_ok ? "true" : "false");
	}
	if (res->on.best_peer) {
		print_figures("peers", res->peer, NPEERS + 1, res);
		if (drawing(res->kind))
			print_figures("peers_scan", res->peer_scan, NPEERS + 1,
				      res);
	}
	if (realtime(res->kind) || res->kind == BENCH_TEAPOT3D)
		printf(",\"met\":%s", res->on.met ? "true" : "false");
	else
		print_target(&res->on);
	if (drawing(res->kind)) {
		printf(",\"scanout_off\":{");
		print_way(res, &res->off);
		if (expect_cycles_off[res->kind])
			printf(",\"cycles_ok\":%s",
			       res->off.cycles_ok ? "true" : "false");
		print_target(&res->off);
		printf("}");
		print_lazy(res);
	}
	if (realtime(res->kind))
		printf(",\"fps_no_consumer\":%.1f,\"cpu_fps\":%.1f,"
		       "\"cpu_fps_no_consumer\":%.1f,\"no_consumer_vs_sink\":%.3f",
		       res->fps_lazy, res->cpu_fps, res->cpu_fps_lazy,
		       res->cpu_fps > 0 ? res->cpu_fps_lazy / res->cpu_fps : 0);
	printf("}\n");
	fflush(stdout);
}

static void target_text(char *buf, size_t n, const struct result *r,
			const struct way *w)
{
	if (realtime(r->kind))
		snprintf(buf, n, ">=%u fps", rt_mode_of(r->kind)->target_fps);
	else if (r->kind == BENCH_TEAPOT3D)
		snprintf(buf, n, ">=%u sim fps", RT_HZ);
	else if (!strcmp(w->target_of, "limit_scan"))
		snprintf(buf, n, ">=%.1f lim+scan", w->target);
	else if (!strcmp(w->target_of, "limit"))
		snprintf(buf, n, ">=%.1f limit", w->target);
	else
		snprintf(buf, n, ">=%.1f %s", w->target,
			 strcmp(w->target_of, "best_peer") ? w->target_of :
							     "best peer");
}

static void print_row(const struct result *r, const struct way *w,
		      const char *scan)
{
	const struct figure *f = w->fig;
	char buf[64], frames[24];
	bool peer_target = !byte_moving(r->kind) && !realtime(r->kind) &&
			   r->kind != BENCH_TEAPOT3D;

	if (w == &r->on && drawing(r->kind))
		snprintf(frames, sizeof(frames), "%llu",
			 (unsigned long long)r->frames);
	else
		snprintf(frames, sizeof(frames), "-");
	printf("%-12s %-4s %6s %9.1f %10.0f %12llu %08x %-8s ",
	       kind_name[r->kind], scan, frames, mpix(r->pixels, f->wall),
	       (double)r->ops / f->wall, (unsigned long long)w->cycles, f->crc,
	       crc_word(r->kind, f->crc));
	if (w->vs_limit > 0)
		snprintf(buf, sizeof(buf), "%.3f (%s)", w->vs_limit,
			 w->best_limit);
	else
		snprintf(buf, sizeof(buf), "-");
	printf("%-22s ", buf);
	if (w->vs_peer > 0)
		snprintf(buf, sizeof(buf), "%.3f (%s)", w->vs_peer,
			 w->best_peer);
	else
		snprintf(buf, sizeof(buf), "-");
	printf("%-20s ", buf);
	target_text(buf, sizeof(buf), r, w);
	printf("%-18s %s%s\n", buf,
	       peer_target && w->vs_target <= 0 ? "n/a (no peer)" :
	       w->met				? "yes" :
						  "NO",
	       f->slow ? " *" : "");
}

/*
 * Scanout on demand: each drawing workload's CPU time with scanout on and
 * a frame consumer, on and none, and off; the realtime ones' frames a
 * second with their sink and with none.
 */
static void print_lazy_table(const struct result *res, size_t n)
{
	size_t i, rows = 0;

	for (i = 0; i < n; i++)
		rows += realtime(res[i].kind) || res[i].rdc_lazy.done;
	if (!rows)
		return;
	printf("\n%-12s %12s %12s %9s %12s %12s\n", "workload", "on+consumer",
	       "on, none", "off", "none/off", "consumer/off");
	for (i = 0; i < n; i++) {
		const struct result *r = &res[i];

		if (realtime(r->kind)) {
			printf("%-12s %8.0f fps %8.0f fps %9s %12s %12s  "
			       "(frames a CPU second: %.0f, %.0f; none/sink "
			       "%.3f)\n",
			       kind_name[r->kind], r->fps, r->fps_lazy, "-",
			       "-", "-", r->cpu_fps, r->cpu_fps_lazy,
			       r->cpu_fps > 0 ? r->cpu_fps_lazy / r->cpu_fps :
						0);
			continue;
		}
		if (!drawing(r->kind) || !r->rdc_lazy.done)
			continue;
		printf("%-12s %10.3f s %10.3f s %7.3f s %12.3f %12.3f%s\n",
		       kind_name[r->kind], r->rdc.cpu, r->rdc_lazy.cpu,
		       r->rdc_off.cpu,
		       r->rdc_off.cpu > 0 ? r->rdc_lazy.cpu / r->rdc_off.cpu :
					    0,
		       r->rdc_off.cpu > 0 ? r->rdc.cpu / r->rdc_off.cpu : 0,
		       r->lazy_ok ? "" : "  MISMATCH");
	}
}

static void print_table(const struct result *res, size_t n, bool peers_on)
{
	char buf[64];
	size_t i, k;
	bool slow = false, cycles_bad = false;

	printf("\n%-12s %-4s %6s %9s %10s %12s %-17s %-22s %-20s %-18s %s\n",
	       "workload", "scan", "frames", "Mpix/s", "ops/s", "sim cycles",
	       "CRC", "rdc/limit", "rdc/best-peer", "target", "met");
	for (i = 0; i < n; i++) {
		const struct result *r = &res[i];

		slow |= r->rdc.slow || r->rdc_off.slow;
		cycles_bad |= !r->on.cycles_ok ||
			      (drawing(r->kind) && !r->off.cycles_ok);
		print_row(r, &r->on, drawing(r->kind) ? "on" : "");
		if (drawing(r->kind))
			print_row(r, &r->off, "off");
	}
	printf("\n%-12s %-12s %9s %9s %9s %9s %-17s %-5s %s\n", "workload",
	       "who", "Mpix/s", "wall s", "Mpix/cpus", "cpu s", "CRC", "runs",
	       "drawn");
	for (i = 0; i < n; i++) {
		const struct result *r = &res[i];
		const struct figure *all[3 + 2 * MAX_LIMITS + 2 * NPEERS];
		size_t m = 0;

		all[m++] = &r->rdc;
		if (r->rdc_off.done)
			all[m++] = &r->rdc_off;
		if (r->rdc_lazy.done)
			all[m++] = &r->rdc_lazy;
		for (k = 0; k < MAX_LIMITS; k++)
			if (r->lim[k].done)
				all[m++] = &r->lim[k];
		for (k = 0; k < MAX_LIMITS; k++)
			if (r->lim_scan[k].done)
				all[m++] = &r->lim_scan[k];
		for (k = 0; peers[k]; k++)
			if (r->peer[k].done)
				all[m++] = &r->peer[k];
		for (k = 0; peers[k]; k++)
			if (r->peer_scan[k].done)
				all[m++] = &r->peer_scan[k];
		for (k = 0; k < m; k++) {
			const struct figure *f = all[k];
			bool part = !realtime(r->kind) &&
				    r->kind != BENCH_TEAPOT3D &&
				    f->ops < r->ops;
			bool scanned = f >= r->lim_scan &&
				       f < r->lim_scan + MAX_LIMITS;
			char drawn[48];

			if (realtime(r->kind))
				snprintf(buf, sizeof(buf),
					 "%.0f fps, %.0f drawn", r->fps,
					 r->fps * r->rt_drawn / r->ops);
			else if (r->kind == BENCH_TEAPOT3D)
				snprintf(buf, sizeof(buf),
					 "%.1f sim fps, %.0f fps wall",
					 r->sim_fps, r->fps);
			else if (part)
				snprintf(buf, sizeof(buf), "-");
			else
				snprintf(buf, sizeof(buf), "%08x %s", f->crc,
					 crc_word(r->kind, f->crc));
			if (part && f->frames)
				snprintf(drawn, sizeof(drawn),
					 "%u ops (%.0f%%) + %llu frames",
					 f->ops, 100.0 * f->ops / r->ops,
					 (unsigned long long)f->frames);
			else if (part)
				snprintf(drawn, sizeof(drawn),
					 "%u ops (%.0f%%)", f->ops,
					 100.0 * f->ops / r->ops);
			else if (f->frames)
				snprintf(drawn, sizeof(drawn),
					 "all + %llu frames",
					 (unsigned long long)f->frames);
			else if (scanned)
				snprintf(drawn, sizeof(drawn),
					 "all + %llu frames %08x %s",
					 (unsigned long long)r->frames,
					 f->frame_crc,
					 f->frame_crc == r->frame_crc ?
						 "OK" :
						 "MISMATCH");
			else if (f == &r->rdc && drawing(r->kind))
				snprintf(drawn, sizeof(drawn),
					 "all, %llu frames %08x",
					 (unsigned long long)r->frames,
					 r->frame_crc);
			else if (f == &r->rdc_lazy)
				snprintf(drawn, sizeof(drawn),
					 "all, %llu frames unseen, %08x %s",
					 (unsigned long long)r->lazy_frames,
					 r->lazy_frame_crc,
					 r->lazy_ok ? "OK" : "MISMATCH");
			else
				snprintf(drawn, sizeof(drawn), "all");
			printf("%-12s %-12s %9.1f %9.3f %9.1f %9.3f %-17s "
			       "%-2d%-3s %s\n",
			       k ? "" : kind_name[r->kind], f->name,
			       mpix(f->pixels, f->wall), f->wall, rate(f) / 1e6,
			       f->cpu, buf, f->runs, f->slow ? " *" : "",
			       drawn);
		}
	}
	print_lazy_table(res, n);
	if (slow)
		printf("\n* first run took over %.0f s: measured once, not the "
		       "median of %s (--full repeats it anyway)\n",
		       SLOW_S, "the repeats");
	printf("\nsim cycles: %s\n",
	       cycles_bad ? "CHANGED from the saved ones (see above)" :
			    "as saved, scanout on and off");
	if (!peers_on)
		printf("\npeers not run (make bench-peers, or rdc-bench-peers "
		       "--peers)\n");
}

/* ---- driver -------------------------------------------------------------- */

/* rdc against the limits and peers one way; then its target. */
static void way_compare(struct result *res, struct way *w,
			const struct figure *lim, bool on)
{
	enum bench_kind kind = res->kind;
	/* with scanout, the peers with the same conversions (as limits) */
	const struct figure *peer = on && drawing(kind) ? res->peer_scan :
							  res->peer;
	const struct figure *line_peer = NULL;
	size_t k;

	for (k = 0; k < MAX_LIMITS; k++) {
		double v;

		if (!lim[k].done)
			continue;
		v = rate(w->fig) / rate(&lim[k]);
		if (!w->best_limit || v < w->vs_limit) {
			w->vs_limit = v;
			w->best_limit = lim[k].name;
		}
	}
	for (k = 0; peers[k]; k++) {
		const struct figure *f = &peer[k];
		double v;

		if (!f->done)
			continue;
		if (!strcmp(peers[k]->name, LINE_PEER))
			line_peer = f;
		v = rate(w->fig) / rate(f);
		if (!w->best_peer || v < w->vs_peer) {
			w->vs_peer = v;
			w->best_peer = f->name;
		}
		if (peer == res->peer || !res->peer[k].done)
			continue;
		v = rate(w->fig) / rate(&res->peer[k]);
		if (!w->best_peer_plain || v < w->vs_peer_plain) {
			w->vs_peer_plain = v;
			w->best_peer_plain = res->peer[k].name;
		}
	}
	if (byte_moving(kind)) {
		w->target = !drawing(kind) || on ? TARGET_SCAN :
			    kind == BENCH_TEXT	 ? TARGET_OFF_TEXT :
						   TARGET_OFF;
		w->target_of = on && drawing(kind) ? "limit_scan" : "limit";
		w->vs_target = w->vs_limit;
		w->met = w->crc_ok && w->best_limit &&
			 w->vs_target >= w->target;
	} else if (kind == BENCH_LINE) {
		w->target = 1.0;
		w->target_of = line_peer ? line_peer->name : LINE_PEER;
		w->vs_target = line_peer ? rate(w->fig) / rate(line_peer) : 0;
		w->met = line_peer && w->vs_target >= w->target;
	} else {
		w->target = 1.0;
		w->target_of = "best_peer";
		w->vs_target = w->vs_peer;
		w->met = w->best_peer && w->vs_target >= w->target;
	}
}

static void run_rt(struct result *res, enum bench_kind kind,
		   const struct opts *o)
{
	double fps[MAX_REPEAT], fps_lazy[MAX_REPEAT];
	double cfps[MAX_REPEAT], cfps_lazy[MAX_REPEAT];
	struct rt_res rt = { 0 }, rt_lazy = { 0 };
	int runs;

	/* realtime: with its sink and with no frame consumer, by turns */
	for (runs = 0; runs < o->repeat; runs++) {
		if (kind == BENCH_TEAPOT3D) {
			rdc_teapot3d(&rt);
		} else {
			rdc_realtime(&rt_lazy, rt_mode_of(kind), true);
			fps_lazy[runs] = (double)rt_lazy.frames / rt_lazy.wall;
			cfps_lazy[runs] = (double)rt_lazy.frames / rt_lazy.cpu;
			rdc_realtime(&rt, rt_mode_of(kind), false);
			cfps[runs] = (double)rt.frames / rt.cpu;
		}
		fps[runs] = (double)rt.frames / rt.wall;
	}
	res->fps = median(fps, runs);
	if (kind != BENCH_TEAPOT3D) {
		res->fps_lazy = median(fps_lazy, runs);
		res->cpu_fps = median(cfps, runs);
		res->cpu_fps_lazy = median(cfps_lazy, runs);
	}
	res->ops = rt.frames;
	res->rt_drawn = rt.drawn;
	if (kind == BENCH_TEAPOT3D) {
		res->pixels = rt.frames * RT_W * RT_H;
		/* the busy cycles are the same every run: deterministic */
		res->sim_fps = (double)rt.khz * 1000.0 * rt.frames / rt.cycles;
		res->on.met = res->sim_fps >= RT_HZ;
	} else {
		const struct rt_mode *m = rt_mode_of(kind);

		res->pixels = rt.frames * m->w * m->h;
		res->on.met = res->fps >= m->target_fps;
	}
	res->on.cycles = rt.cycles;
	res->on.cycles_ok = !expect_cycles[kind] ||
			    rt.cycles == expect_cycles[kind];
	res->rdc.wall = (double)rt.frames / res->fps;
	res->rdc.ops = rt.frames;
	res->rdc.pixels = res->pixels;
	res->rdc.crc = rt.crc;
	res->rdc.runs = runs;
	res->rdc.done = true;
}

static void run_kind(struct result *res, enum bench_kind kind,
		     const struct opts *o)
{
	struct entrant e[3 + 2 * MAX_LIMITS + 2 * NPEERS];
	struct limit_ctx lc[MAX_LIMITS], ls[MAX_LIMITS];
	struct peer_ctx pc[NPEERS + 1];
	struct peer_scan_ctx psc[NPEERS + 1];
	static char scan_name[NPEERS + 1][48];
	struct bench_input in;
	struct rdc_ctx rc, rc_off, rc_lazy;
	size_t k, n = 0;

	memset(res, 0, sizeof(*res));
	res->kind = kind;
	res->rdc.name = "rdc";
	res->on.fig = &res->rdc;
	res->off.fig = &res->rdc_off;
	res->on.cycles_ok = res->off.cycles_ok = true;
	if (realtime(kind) || kind == BENCH_TEAPOT3D) {
		run_rt(res, kind, o);
		return;
	}
	input_make(&in, kind);
	res->ops = in.ops;
	res->pixels = in.pixels;
	memset(&rc, 0, sizeof(rc));
	rc.in = &in;
	rc.scan = true;
	rc_off = (struct rdc_ctx){ .in = &in };
	rc_lazy = (struct rdc_ctx){ .in = &in, .scan = true, .lazy = true };
	figure_init(&res->rdc, "rdc", &in, in.ops);
	e[n++] = (struct entrant){ .fig = &res->rdc,
				   .one = rdc_one,
				   .ctx = &rc };
	if (drawing(kind)) {
		figure_init(&res->rdc_off, "rdc-noscan", &in, in.ops);
		e[n++] = (struct entrant){ .fig = &res->rdc_off,
					   .one = rdc_one,
					   .ctx = &rc_off };
		figure_init(&res->rdc_lazy, "rdc-lazy", &in, in.ops);
		e[n++] = (struct entrant){ .fig = &res->rdc_lazy,
					   .one = rdc_one,
					   .ctx = &rc_lazy };
	}
	for (k = 0; k < MAX_LIMITS && limits[kind][k].name; k++) {
		lc[k] = (struct limit_ctx){ .in = &in,
					    .lim = &limits[kind][k] };
		figure_init(&res->lim[k], limits[kind][k].name, &in, in.ops);
		e[n++] = (struct entrant){ .fig = &res->lim[k],
					   .one = limit_one,
					   .ctx = &lc[k] };
	}
	/* after rdc with scanout, whose frame count they need */
	for (k = 0; k < MAX_LIMITS && limits[kind][k].scan_name; k++) {
		ls[k] = (struct limit_ctx){ .in = &in,
					    .lim = &limits[kind][k],
					    .scan = &rc };
		figure_init(&res->lim_scan[k], limits[kind][k].scan_name, &in,
			    in.ops);
		e[n++] = (struct entrant){ .fig = &res->lim_scan[k],
					   .one = limit_one,
					   .ctx = &ls[k] };
	}
	for (k = 0; o->peers && peers[k]; k++) {
		if (!peers[k]->has(kind))
			continue;
		pc[k] = (struct peer_ctx){ &in, peers[k] };
		figure_init(&res->peer[k], peers[k]->name, &in,
			    peer_ops(&in, peers[k], o));
		e[n++] = (struct entrant){ .fig = &res->peer[k],
					   .one = peer_one,
					   .ctx = &pc[k] };
		if (!drawing(kind))
			continue;
		/* after rdc with scanout, whose frame count it needs */
		snprintf(scan_name[k], sizeof(scan_name[k]), "%s+scan",
			 peers[k]->name);
		figure_init(&res->peer_scan[k], scan_name[k], &in,
			    res->peer[k].ops);
		psc[k] = (struct peer_scan_ctx){ &in, peers[k], &rc,
						 &res->peer_scan[k] };
		e[n++] = (struct entrant){ .fig = &res->peer_scan[k],
					   .one = peer_scan_one,
					   .ctx = &psc[k] };
	}
	measure(e, n, o);
	res->frames = rc.frames;
	res->frame_crc = rc.frame_crc;
	res->frame_crc_ok = true;
	for (k = 0; k < MAX_LIMITS; k++) {
		if (!res->lim_scan[k].done)
			continue;
		res->lim_scan[k].frame_crc = ls[k].frame_crc;
		res->frame_crc_ok = res->frame_crc_ok && ls[k].frame_crc_same &&
				    ls[k].frame_crc == rc.frame_crc;
	}
	res->on.cycles = rc.cycles;
	res->on.sim_pixels = rc.sim_pixels;
	res->on.crc_ok = expect_crc[kind] && res->rdc.crc == expect_crc[kind] &&
			 res->rdc.crc_same;
	res->on.cycles_ok =
		!expect_cycles[kind] ||
		(rc.cycles == expect_cycles[kind] && !rc.cycles_differ);
	way_compare(res, &res->on, drawing(kind) ? res->lim_scan : res->lim,
		    true);
	if (drawing(kind)) {
		res->off.cycles = rc_off.cycles;
		res->off.sim_pixels = rc_off.sim_pixels;
		res->off.crc_ok = expect_crc[kind] &&
				  res->rdc_off.crc == expect_crc[kind] &&
				  res->rdc_off.crc_same;
		res->off.cycles_ok =
			!expect_cycles_off[kind] ||
			(rc_off.cycles == expect_cycles_off[kind] &&
			 !rc_off.cycles_differ);
		way_compare(res, &res->off, res->lim, false);
		res->lazy_cycles = rc_lazy.cycles;
		res->lazy_frames = rc_lazy.frames;
		res->lazy_frame_crc = rc_lazy.frame_crc;
		res->lazy_ok = res->rdc_lazy.done && !rc_lazy.cycles_differ &&
			       rc_lazy.cycles == rc.cycles &&
			       rc_lazy.frames == rc.frames &&
			       rc_lazy.frame_crc == rc.frame_crc &&
			       res->rdc_lazy.crc == res->rdc.crc &&
			       res->rdc_lazy.crc_same;
		if (!expect_crc[kind] && res->rdc_off.crc != res->rdc.crc)
			fprintf(stderr,
				"rdc-bench: %s: scanout off drew %08x, on "
				"%08x\n",
				kind_name[kind], res->rdc_off.crc,
				res->rdc.crc);
	}
	if (rc.cycles_differ || rc_off.cycles_differ || rc_lazy.cycles_differ)
		fprintf(stderr,
			"rdc-bench: %s: sim_cycles differ between "
			"runs\n",
			kind_name[kind]);
	input_free(&in);
}

/*
 * A wrong CRC from rdc or from a limit means the work differs from the
 * workloads' (bench/README.md): the figures are void and the run fails.
 * So does a simulated cycle count that is not the saved one, a picture
 * that differs with scanout off, and a limit with scanout whose last frame
 * is not the chip's.  (Targets missed do not fail it.)
 */
static int check_failures(const struct result *res, size_t n)
{
	int bad = 0;
	size_t i, k;

	for (i = 0; i < n; i++) {
		const struct result *r = &res[i];
		const char *name = kind_name[r->kind];

		if (!r->on.cycles_ok) {
			fprintf(stderr,
				"rdc-bench: %s: sim_cycles %llu, saved %llu\n",
				name, (unsigned long long)r->on.cycles,
				(unsigned long long)expect_cycles[r->kind]);
			bad++;
		}
		if (drawing(r->kind) && !r->off.cycles_ok) {
			fprintf(stderr,
				"rdc-bench: %s: scanout off: sim_cycles %llu, "
				"saved %llu\n",
				name, (unsigned long long)r->off.cycles,
				(unsigned long long)expect_cycles_off[r->kind]);
			bad++;
		}
		if (drawing(r->kind) &&
		    (r->rdc_off.crc != r->rdc.crc || !r->rdc.crc_same ||
		     !r->rdc_off.crc_same)) {
			fprintf(stderr,
				"rdc-bench: %s: scanout off drew %08x, on "
				"%08x\n",
				name, r->rdc_off.crc, r->rdc.crc);
			bad++;
		}
		if (drawing(r->kind) && !r->lazy_ok) {
			fprintf(stderr,
				"rdc-bench: %s: with no frame consumer: cycles "
				"%llu, frames %llu, frame %08x, CRC %08x; with "
				"one %llu, %llu, %08x, %08x\n",
				name, (unsigned long long)r->lazy_cycles,
				(unsigned long long)r->lazy_frames,
				r->lazy_frame_crc, r->rdc_lazy.crc,
				(unsigned long long)r->on.cycles,
				(unsigned long long)r->frames, r->frame_crc,
				r->rdc.crc);
			bad++;
		}
		if (byte_moving(r->kind) && drawing(r->kind) &&
		    !r->frame_crc_ok) {
			fprintf(stderr,
				"rdc-bench: %s: a limit with scanout's last "
				"frame is not the chip's %08x\n",
				name, r->frame_crc);
			bad++;
		}
		if (!expect_crc[r->kind])
			continue;
		if (!r->on.crc_ok) {
			fprintf(stderr,
				"rdc-bench: %s: rdc CRC %08x, want %08x\n",
				name, r->rdc.crc, expect_crc[r->kind]);
			bad++;
		}
		for (k = 0; k < 2 * MAX_LIMITS; k++) {
			const struct figure *f =
				k < MAX_LIMITS ? &r->lim[k] :
						 &r->lim_scan[k - MAX_LIMITS];

			if (f->done &&
			    (f->crc != expect_crc[r->kind] || !f->crc_same)) {
				fprintf(stderr,
					"rdc-bench: %s: limit %s CRC %08x, "
					"want %08x\n",
					name, f->name, f->crc,
					expect_crc[r->kind]);
				bad++;
			}
		}
	}
	return bad;
}

/* ---- growth: cost against area and region size -------------------------- */

/*
 * Fill and blit of squares from 8x8 to the whole 4096x4096 XRGB8888
 * surface (64 MiB, in a sim: with 256 MiB of VRAM; the blits copy from a
 * second 4096x4096 surface of random pixels after it), G_PIXELS pixels at
 * each size; flood fill of a square region of each size, G_FLOOD_PIXELS
 * at each.  Scanout is off (no mode shows 4096x4096): the figures are
 * the command path's, the DP's and the bus model's.
 */
#define G_URI	       "sim:vram=256M"
#define G_SIDE	       4096u
#define G_MIN_SIDE     8u
#define G_SIZES	       10u /* 8, 16, ..., 4096 */
#define G_PIXELS       (64ull << 20)
#define G_FLOOD_PIXELS (32ull << 20)
#define G_BACK	       0xff203040u /* flood: the surface around the region */
#define G_REGION_A     0xff00c000u /* flood: the region, alternately */
#define G_REGION_B     0xffc00000u
#define G_LINEAR       0.25 /* every size within this of the fit */
#define G_SRC	       (G_SIDE * G_SIDE * 4) /* blit: the source surface */

enum { G_FILL, G_BLIT, G_FLOOD, G_WHATS };
static const char *const g_name[G_WHATS] = { "fill", "blit", "flood" };

struct g_row {
	uint32_t side, ops;
	double wall, cpu;    /* rdc, median of the repeats */
	double lim_cpu;	     /* the plain-C limit (fill, blit), median */
	uint64_t cycles, px; /* simulated cycles; pixels the DP counted */
	bool crc_ok;	     /* rdc's surface equals the limit's */
};

static uint32_t g_ops(uint32_t what, uint32_t side)
{
	uint64_t n = (what == G_FLOOD ? G_FLOOD_PIXELS : G_PIXELS) /
		     ((uint64_t)side * side);

	return n ? (uint32_t)n : 1;
}

static uint32_t g_vram_crc(rdc_dev *dev)
{
	uint8_t *buf = xcalloc(G_SIDE, 4);
	uLong crc = crc32(0, NULL, 0);
	uint32_t y;

	for (y = 0; y < G_SIDE; y++) {
		if (rdc_vram_read(dev, y * G_SIDE * 4, buf, G_SIDE * 4))
			die("vram read", RDC_E_IO);
		crc = crc32(crc, buf, G_SIDE * 4);
	}
	free(buf);
	return (uint32_t)crc;
}

static uint32_t g_buf_crc(const uint32_t *s)
{
	return (uint32_t)crc32(0, (const uint8_t *)s, G_SIDE * G_SIDE * 4);
}

/* Inputs of one size: fill x, y, colour; blit sx, sy, dx, dy. */
static uint32_t *g_input(uint32_t what, uint32_t side, uint32_t ops)
{
	uint32_t *a = xcalloc((size_t)ops * 4, 4), i, span = G_SIDE - side + 1;
	struct rng g = { BENCH_SEED ^ side };

	for (i = 0; i < ops; i++) {
		a[4 * i] = r32(&g) % span;
		a[4 * i + 1] = r32(&g) % span;
		a[4 * i + 2] = what == G_FILL ? r32(&g) | BENCH_OPAQUE :
						r32(&g) % span;
		a[4 * i + 3] = r32(&g) % span;
	}
	return a;
}

static uint32_t g_other(uint32_t c)
{
	return c == G_REGION_A ? G_REGION_B : G_REGION_A;
}

/* flood: cur is the region's colour; each op turns it to the other one. */
static void g_rdc(struct run *r, uint32_t what, uint32_t side,
		  const uint32_t *a, uint32_t ops, uint32_t cur)
{
	uint32_t i;

	for (i = 0; i < ops; i++, a += 4) {
		if (what == G_FILL) {
			rdc_batch_fg(r->b, a[2]);
			rdc_batch_fill_rect(r->b, (int)a[0], (int)a[1], side,
					    side);
		} else if (what == G_BLIT) {
			rdc_batch_blit(r->b, (int)a[0], (int)a[1], (int)a[2],
				       (int)a[3], side, side);
		} else {
			rdc_batch_fg(r->b, i & 1 ? cur : g_other(cur));
			rdc_batch_flood(r->b, (int)(a[0] + side / 2),
					(int)(a[1] + side / 2), 0, 0);
		}
		run_flush(r, false);
	}
}

static void g_limit(uint32_t *s, uint32_t what, uint32_t side,
		    const uint32_t *a, uint32_t ops)
{
	uint32_t i, y;

	for (i = 0; i < ops; i++, a += 4) {
		for (y = 0; y < side; y++) {
			if (what == G_FILL) {
				wmemset((wchar_t *)(s +
						    (size_t)(a[1] + y) *
							    G_SIDE +
						    a[0]),
					(wchar_t)a[2], side);
			} else { /* from the source surface after s */
				memcpy(s + (size_t)(a[3] + y) * G_SIDE + a[2],
				       s + (size_t)(G_SIDE + a[1] + y) * G_SIDE +
					       a[0],
				       (size_t)side * 4);
			}
		}
	}
}

/* The blits' source: random pixels, in VRAM and in the limit's copy. */
static void g_source(struct run *r, uint32_t *src)
{
	struct rng g = { BENCH_PREFILL_SEED };
	size_t i;

	for (i = 0; i < (size_t)G_SIDE * G_SIDE; i++)
		src[i] = r32(&g);
	if (rdc_vram_write(r->dev, G_SRC, src, (size_t)G_SIDE * G_SIDE * 4))
		die("vram write", RDC_E_IO);
}

/* Fill the whole surface with c (setup, untimed), and the limit's too. */
static void g_clear(struct run *r, uint32_t *s, uint32_t c)
{
	rdc_batch_fg(r->b, c);
	rdc_batch_fill_rect(r->b, 0, 0, G_SIDE, G_SIDE);
	run_finish(r);
	wmemset((wchar_t *)s, (wchar_t)c, (size_t)G_SIDE * G_SIDE);
}

static void g_measure(struct run *r, uint32_t *s, uint32_t what, uint32_t side,
		      const struct opts *o, struct g_row *row)
{
	uint32_t ops = g_ops(what, side), *a = g_input(what, side, ops);
	double wall[MAX_REPEAT] = { 0 }, cpu[MAX_REPEAT] = { 0 },
	       lim[MAX_REPEAT] = { 0 };
	struct rdc_stats st0 = { 0 }, st1 = { 0 };
	uint32_t cur = G_REGION_A; /* flood: the region's colour */
	uint64_t c0, c1;
	int k;

	memset(row, 0, sizeof(*row));
	row->side = side;
	row->ops = ops;
	row->crc_ok = true;
	if (what == G_FLOOD) {
		/* a square region of A on the background, alone */
		g_clear(r, s, G_BACK);
		rdc_batch_fg(r->b, G_REGION_A);
		rdc_batch_fill_rect(r->b, (int)a[0], (int)a[1], side, side);
		run_finish(r);
		for (k = 0; k < (int)side; k++)
			wmemset((wchar_t *)(s + (size_t)(a[1] + k) * G_SIDE +
					    a[0]),
				(wchar_t)G_REGION_A, side);
	}
	for (k = 0; k < o->repeat; k++) {
		uint32_t i, *aa = a;
		double t0;

		if (what == G_FLOOD) {
			/* every op at the one region's centre */
			aa = xcalloc((size_t)ops * 4, 4);
			for (i = 0; i < ops; i++)
				memcpy(aa + 4 * i, a, 16);
		}
		rdc_stats_get(r->dev, &st0);
		rdc_sim_time(r->dev, &c0);
		t0 = bench_tic();
		g_rdc(r, what, side, aa, ops, cur);
		run_finish(r);
		wall[k] = bench_toc(t0);
		cpu[k] = bench_cpu();
		rdc_sim_time(r->dev, &c1);
		rdc_stats_get(r->dev, &st1);
		if (k && c1 - c0 != row->cycles)
			fprintf(stderr,
				"rdc-bench: growth %s %u: sim_cycles differ "
				"between runs\n",
				g_name[what], side);
		row->cycles = c1 - c0;
		row->px = st1.pixels - st0.pixels;
		if (what == G_FLOOD) {
			/* the picture the floods leave: the region in the
			 * colour of the last one */
			if (ops & 1)
				cur = g_other(cur);
			for (i = 0; i < side; i++)
				wmemset((wchar_t *)(s +
						    (size_t)(a[1] + i) *
							    G_SIDE +
						    a[0]),
					(wchar_t)cur, side);
			free(aa);
			lim[k] = 0;
		} else {
			t0 = bench_tic();
			g_limit(s, what, side, a, ops);
			bench_toc(t0);
			lim[k] = bench_cpu();
		}
		if (g_vram_crc(r->dev) != g_buf_crc(s))
			row->crc_ok = false;
	}
	/*
	 * The fastest repeat: a size's runs are short (64 Mi pixels of
	 * fill take about 30 ms), and what a shared machine adds to one
	 * of them is an outlier a median of three still keeps.
	 */
	row->wall = least(wall, o->repeat);
	row->cpu = least(cpu, o->repeat);
	row->lim_cpu = least(lim, o->repeat);
	free(a);
}

/*
 * Fit CPU time per op = a + c * side + b * area (a rectangle's cost: per
 * operation, per row, per pixel), least squares on the relative error
 * (every size counts alike, 8x8 as much as 4096x4096).  The growth is
 * linear in area when every size lies within G_LINEAR of the fit.
 */
struct g_fit {
	double a, c, b; /* seconds per op, per row, per pixel */
	double worst;	/* largest |measured / fit - 1| */
	uint32_t worst_side;
};

static double g_fit_at(const struct g_fit *fit, uint32_t side)
{
	return fit->a + fit->c * side + fit->b * (double)side * side;
}

static void g_fit(const struct g_row *row, uint32_t n, struct g_fit *fit)
{
	double m[3][4] = { { 0 } }, x[3] = { 0 };
	uint32_t i, j, k;

	for (i = 0; i < n; i++) {
		double t = row[i].cpu / row[i].ops, s = row[i].side;
		double v[3] = { 1 / t, s / t, s * s / t }; /* each / t */

		for (j = 0; j < 3; j++) {
			for (k = 0; k < 3; k++)
				m[j][k] += v[j] * v[k];
			m[j][3] += v[j]; /* t / t */
		}
	}
	/* Gaussian elimination with partial pivoting */
	for (j = 0; j < 3; j++) {
		uint32_t p = j;

		for (k = j + 1; k < 3; k++)
			if (m[k][j] * m[k][j] > m[p][j] * m[p][j])
				p = k;
		for (k = 0; k < 4; k++) {
			double tmp = m[j][k];

			m[j][k] = m[p][k];
			m[p][k] = tmp;
		}
		for (k = j + 1; k < 3 && m[j][j]; k++) {
			double f = m[k][j] / m[j][j];
			uint32_t q;

			for (q = j; q < 4; q++)
				m[k][q] -= f * m[j][q];
		}
	}
	for (j = 3; j-- > 0;) {
		double v = m[j][3];

		for (k = j + 1; k < 3; k++)
			v -= m[j][k] * x[k];
		x[j] = m[j][j] ? v / m[j][j] : 0;
	}
	fit->a = x[0];
	fit->c = x[1];
	fit->b = x[2];
	fit->worst = 0;
	fit->worst_side = 0;
	for (i = 0; i < n; i++) {
		double t = row[i].cpu / row[i].ops,
		       f = g_fit_at(fit, row[i].side),
		       e = f > 0 ? t / f - 1 : 1;

		if (e < 0)
			e = -e;
		if (e >= fit->worst) {
			fit->worst = e;
			fit->worst_side = row[i].side;
		}
	}
}

static void run_growth(const struct opts *o)
{
	static struct g_row rows[G_WHATS][G_SIZES];
	struct g_fit fit[G_WHATS];
	uint32_t *s = xcalloc((size_t)G_SIDE * G_SIDE * 2, 4); /* dst, src */
	uint32_t w, i, n = 0, side;
	struct run r;
	int err = rdc_open(G_URI, &r.dev);

	if (err)
		die("open " G_URI, err);
	r.b = rdc_batch_new();
	if (!r.b)
		die("batch", RDC_E_NOMEM);
	scanout_off(r.dev);
	rdc_batch_dst(r.b, 0, G_SIDE * 4, G_SIDE, G_SIDE, RDC_FMT_XRGB8888);
	rdc_batch_src(r.b, G_SRC, G_SIDE * 4, G_SIDE, G_SIDE, RDC_FMT_XRGB8888);
	rdc_batch_clip(r.b, 0, 0, G_SIDE, G_SIDE);
	g_clear(&r, s, 0);
	g_source(&r, s + (size_t)G_SIDE * G_SIDE);
	for (side = G_MIN_SIDE, n = 0; n < G_SIZES; side *= 2, n++) {
		for (w = 0; w < G_WHATS; w++) {
			struct g_row *g = &rows[w][n];

			g_measure(&r, s, w, side, o, g);
			printf("{\"workload\":\"growth\",\"what\":\"%s\","
			       "\"side\":%u,\"area\":%u,\"ops\":%u,"
			       "\"wall_s\":%.6f,\"cpu_s\":%.6f,"
			       "\"ns_per_op\":%.1f,\"ns_per_pixel\":%.4f,"
			       "\"sim_cycles\":%llu,\"sim_pixels\":%llu,"
			       "\"crc_ok\":%s",
			       g_name[w], side, side * side, g->ops, g->wall,
			       g->cpu, g->cpu / g->ops * 1e9,
			       g->cpu / g->ops / side / side * 1e9,
			       (unsigned long long)g->cycles,
			       (unsigned long long)g->px,
			       g->crc_ok ? "true" : "false");
			if (w != G_FLOOD)
				printf(",\"limit_ns_per_pixel\":%.4f",
				       g->lim_cpu / g->ops / side / side * 1e9);
			printf("}\n");
			fflush(stdout);
		}
	}
	for (w = 0; w < G_WHATS; w++) {
		g_fit(rows[w], G_SIZES, &fit[w]);
		printf("{\"workload\":\"growth_fit\",\"what\":\"%s\","
		       "\"a_ns\":%.1f,\"c_ns_per_row\":%.3f,"
		       "\"b_ns_per_pixel\":%.4f,"
		       "\"worst_residual\":%.3f,\"worst_side\":%u,"
		       "\"linear\":%s}\n",
		       g_name[w], fit[w].a * 1e9, fit[w].c * 1e9,
		       fit[w].b * 1e9, fit[w].worst, fit[w].worst_side,
		       fit[w].worst <= G_LINEAR ? "true" : "false");
	}
	if (!o->json) {
		printf("\ngrowth: %ux%u XRGB8888, %s, scanout off; time is CPU "
		       "time per op (the least of %d)\n",
		       G_SIDE, G_SIDE, G_URI, o->repeat);
		printf("%-6s %9s %9s %8s %12s %10s %12s %7s %10s %10s %s\n",
		       "what", "side", "area", "ops", "ns/op", "ns/pixel",
		       "fit ns/op", "vs fit", "limit ns/px", "cycles/px",
		       "CRC");
		for (w = 0; w < G_WHATS; w++) {
			for (i = 0; i < G_SIZES; i++) {
				const struct g_row *g = &rows[w][i];
				double a = (double)g->side * g->side,
				       t = g->cpu / g->ops,
				       f = g_fit_at(&fit[w], g->side);
				char lim[16];

				if (w == G_FLOOD)
					snprintf(lim, sizeof(lim), "-");
				else
					snprintf(lim, sizeof(lim), "%.3f",
						 g->lim_cpu / g->ops / a * 1e9);
				printf("%-6s %4ux%-4u %9.0f %8u %12.1f "
				       "%10.3f %12.1f %+6.0f%% %10s %10.2f %s\n",
				       g_name[w], g->side, g->side, a, g->ops,
				       t * 1e9, t / a * 1e9, f * 1e9,
				       (t / f - 1) * 100, lim,
				       (double)g->cycles / g->ops / a,
				       g->crc_ok ? "OK" : "MISMATCH");
			}
		}
		printf("\n");
		for (w = 0; w < G_WHATS; w++)
			printf("%s: time per op = %.0f ns + %.2f ns x side + "
			       "%.3f ns x area; %s (every size within %.0f%% of "
			       "the fit: worst %.0f%% at %ux%u)\n",
			       g_name[w], fit[w].a * 1e9, fit[w].c * 1e9,
			       fit[w].b * 1e9,
			       fit[w].worst <= G_LINEAR ? "linear in area" :
							  "NOT linear in area",
			       G_LINEAR * 100, fit[w].worst * 100,
			       fit[w].worst_side, fit[w].worst_side);
	}
	rdc_batch_free(r.b);
	rdc_close(r.dev);
	free(s);
}

static int parse_only(bool *only, const char *arg)
{
	char *dup = strdup(arg), *tok, *save = NULL;
	int k, bad = 0;

	if (!dup)
		return -1;
	for (tok = strtok_r(dup, ",", &save); tok;
	     tok = strtok_r(NULL, ",", &save)) {
		for (k = 0; k < BENCH_KIND_COUNT; k++)
			if (!strcmp(tok, kind_name[k]))
				break;
		if (k == BENCH_KIND_COUNT) {
			fprintf(stderr, "rdc-bench: unknown workload %s\n",
				tok);
			bad = -1;
			continue;
		}
		only[k] = true;
	}
	free(dup);
	return bad;
}

static void usage(FILE *to)
{
	int k;

	fprintf(to, "usage: rdc-bench [-w WORKLOAD[,...]] [-r REPEATS] [--json]"
		    " [--peers] [--full]\nworkloads:");
	for (k = 0; k < BENCH_KIND_COUNT; k++)
		fprintf(to, " %s", kind_name[k]);
	fprintf(to, "\npeers built in:");
	for (k = 0; peers[k]; k++)
		fprintf(to, " %s", peers[k]->name);
	fprintf(to, "%s\n", NPEERS ? "" : " none");
}

int main(int argc, char **argv)
{
	static const struct option lopts[] = {
		{ "workload", required_argument, NULL, 'w' },
		{ "repeat", required_argument, NULL, 'r' },
		{ "json", no_argument, NULL, 'j' },
		{ "peers", no_argument, NULL, 'p' },
		{ "full", no_argument, NULL, 'f' },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	static struct result res[BENCH_KIND_COUNT];
	struct opts o = { .repeat = 3 };
	bool only[BENCH_KIND_COUNT] = { false }, any = false, growth = false;
	size_t n = 0;
	int c, k;

	while ((c = getopt_long(argc, argv, "w:r:jpfh", lopts, NULL)) != -1) {
		switch (c) {
		case 'w':
			if (parse_only(only, optarg))
				return 2;
			any = true;
			break;
		case 'r':
			o.repeat = atoi(optarg);
			if (o.repeat < 1 || o.repeat > MAX_REPEAT) {
				fprintf(stderr, "rdc-bench: repeat 1..%d\n",
					MAX_REPEAT);
				return 2;
			}
			break;
		case 'j':
			o.json = true;
			break;
		case 'p':
			o.peers = true;
			break;
		case 'f':
			o.full = true;
			break;
		case 'h':
			usage(stdout);
			return 0;
		default:
			usage(stderr);
			return 2;
		}
	}
	if (optind < argc) {
		usage(stderr);
		return 2;
	}
	if (o.peers && !NPEERS)
		fprintf(stderr, "rdc-bench: built without peers "
				"(make bench-peers builds rdc-bench-peers)\n");
	for (k = 0; k < BENCH_KIND_COUNT; k++) {
		if (any && !only[k])
			continue;
		if (k == BENCH_GROWTH) {
			growth = true;
			continue;
		}
		run_kind(&res[n], (enum bench_kind)k, &o);
		print_json(&res[n]);
		n++;
	}
	if (!o.json && n)
		print_table(res, n, o.peers && NPEERS);
	if (growth)
		run_growth(&o);
	return check_failures(res, n) ? 1 : 0;
}
