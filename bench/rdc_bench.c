// SPDX-License-Identifier: GPL-2.0-only
/*
 * rdc-bench: the workloads of BENCHMARKS.md through the real command path
 * (librdc sim: -> command words -> display-processor firmware -> hw-sim,
 * cycle counting on), each against the plain-C limit of the same work.
 *
 *   rdc-bench [-w WORKLOAD] [-r REPEATS] [--json]
 *
 * One JSON object a workload and run on stdout:
 *   {"workload":..,"ops":..,"pixels":..,"wall_s":..,"mpix_s":..,
 *    "ops_s":..,"sim_cycles":..,"crc32":"..","limit_s":..,"vs_limit":..}
 * then, unless --json, a table.  Wall time is the median of the repeats,
 * measured around the drawing only; crc32 is the zlib CRC-32 of the target
 * surface after the workload (of the scanned-out frame for scanout).
 */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <zlib.h>

#include "rdc.h"

#define SW 1024
#define SH 768
#define SEED 0x12345678u
#define BATCH_WORDS 65536u

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

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
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

/* A device with a 1024x768 surface at VRAM 0, cleared. */
struct run {
	rdc_dev *dev;
	rdc_batch *b;
	uint32_t format;
	uint64_t pixels;
};

static void run_open(struct run *r, uint32_t format)
{
	static uint8_t zero[SW * SH * 4];
	int err = rdc_open("sim:", &r->dev);

	if (err)
		die("open", err);
	r->b = rdc_batch_new();
	if (!r->b)
		die("batch", RDC_E_NOMEM);
	r->format = format;
	r->pixels = 0;
	err = rdc_mode_set(r->dev, RDC_PRESET_1024x768_60, format, 0);
	if (!err)
		err = rdc_vram_write(r->dev, 0, zero, sizeof(zero));
	if (!err)
		err = rdc_finish(r->dev);
	if (err)
		die("setup", err);
}

static void run_close(struct run *r)
{
	rdc_batch_free(r->b);
	rdc_close(r->dev);
}

/* Submit what the batch holds once it is big enough (or when forced). */
static void run_flush(struct run *r, int force)
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

	run_flush(r, 1);
	err = rdc_finish(r->dev);
	if (err)
		die("finish", err);
}

static uint32_t surface_crc(struct run *r, uint32_t bytes)
{
	uint8_t *buf = malloc(bytes);
	uint32_t crc;
	int err;

	if (!buf)
		die("crc", RDC_E_NOMEM);
	err = rdc_vram_read(r->dev, 0, buf, bytes);
	if (err)
		die("vram read", err);
	crc = (uint32_t)crc32(0, buf, bytes);
	free(buf);
	return crc;
}

/* ---- the workloads ------------------------------------------------------ */

static void fill_ops(struct run *r, uint32_t seed, uint32_t ops, int indexed)
{
	struct rng g = { seed };
	uint32_t i;

	for (i = 0; i < ops; i++) {
		uint32_t x = r32(&g) % SW, y = r32(&g) % SH;
		uint32_t w = 1 + r32(&g) % 256, h = 1 + r32(&g) % 256;
		uint32_t c = indexed ? r32(&g) % 256 : r32(&g) | 0xff000000u;

		rdc_batch_fg(r->b, c);
		rdc_batch_fill_rect(r->b, (int)x, (int)y, w, h);
		r->pixels += (uint64_t)umin(w, SW - x) * umin(h, SH - y);
		run_flush(r, 0);
	}
}

static void blit_ops(struct run *r, uint32_t ops)
{
	struct rng g = { SEED };
	uint32_t i;

	for (i = 0; i < ops; i++) {
		uint32_t sx = r32(&g) % SW, sy = r32(&g) % SH;
		uint32_t dx = r32(&g) % SW, dy = r32(&g) % SH;
		uint32_t w = 1 + r32(&g) % 256, h = 1 + r32(&g) % 256;

		w = umin(w, umin(SW - sx, SW - dx));
		h = umin(h, umin(SH - sy, SH - dy));
		rdc_batch_blit(r->b, (int)sx, (int)sy, (int)dx, (int)dy, w, h);
		r->pixels += (uint64_t)w * h;
		run_flush(r, 0);
	}
}

static uint8_t text_font[256 * 16];

static void text_font_make(void)
{
	struct rng g = { 0x464f4e54u };
	uint32_t i;

	for (i = 0; i < sizeof(text_font); i++)
		text_font[i] = (uint8_t)(r32(&g) >> 24);
}

static void text_ops(struct run *r, uint32_t ops)
{
	struct rng g = { SEED };
	uint32_t i;

	for (i = 0; i < ops; i++) {
		uint32_t glyph = r32(&g) % 256;
		uint32_t fg = r32(&g) | 0xff000000u, bg = r32(&g) | 0xff000000u;
		uint32_t cell = i % (128 * 48);

		rdc_batch_fg(r->b, fg);
		rdc_batch_bg(r->b, bg);
		rdc_batch_mono(r->b, (int)(cell % 128) * 8, (int)(cell / 128) * 16,
			       8, 16, text_font + glyph * 16, 0);
		r->pixels += 128;
		run_flush(r, 0);
	}
}

static void line_ops(struct run *r, uint32_t ops)
{
	struct rng g = { SEED };
	uint32_t i;

	for (i = 0; i < ops; i++) {
		int x0 = (int)(r32(&g) % SW), y0 = (int)(r32(&g) % SH);
		int x1 = (int)(r32(&g) % SW), y1 = (int)(r32(&g) % SH);
		uint32_t dx = (uint32_t)abs(x1 - x0), dy = (uint32_t)abs(y1 - y0);

		rdc_batch_fg(r->b, r32(&g) | 0xff000000u);
		rdc_batch_line(r->b, x0, y0, x1, y1);
		r->pixels += (dx > dy ? dx : dy) + 1;
		run_flush(r, 0);
	}
}

static void circle_ops(struct run *r, uint32_t ops, int filled)
{
	struct rng g = { SEED };
	uint32_t i;

	for (i = 0; i < ops; i++) {
		int cx = (int)(r32(&g) % SW), cy = (int)(r32(&g) % SH);
		uint32_t rad = 1 + r32(&g) % (filled ? 64 : 128);

		rdc_batch_fg(r->b, r32(&g) | 0xff000000u);
		if (filled)
			rdc_batch_fill_circle(r->b, cx, cy, rad);
		else
			rdc_batch_circle(r->b, cx, cy, rad);
		run_flush(r, 0);
	}
}

/* ---- plain-C limits of the byte-moving workloads ------------------------ */

static double limit_fill(uint32_t *s, uint32_t seed, uint32_t ops)
{
	struct rng g = { seed };
	double t0 = now_s();
	uint32_t i, yy, xx;

	for (i = 0; i < ops; i++) {
		uint32_t x = r32(&g) % SW, y = r32(&g) % SH;
		uint32_t w = 1 + r32(&g) % 256, h = 1 + r32(&g) % 256;
		uint32_t c = r32(&g) | 0xff000000u;

		w = umin(w, SW - x);
		h = umin(h, SH - y);
		for (yy = y; yy < y + h; yy++) {
			uint32_t *p = s + (size_t)yy * SW + x;

			for (xx = 0; xx < w; xx++)
				p[xx] = c;
		}
	}
	return now_s() - t0;
}

static double limit_blit(uint32_t *s, uint32_t ops, int xor)
{
	struct rng g = { SEED };
	static uint32_t tmp[256];
	double t0 = now_s();
	uint32_t i, yy, xx;

	for (i = 0; i < ops; i++) {
		uint32_t sx = r32(&g) % SW, sy = r32(&g) % SH;
		uint32_t dx = r32(&g) % SW, dy = r32(&g) % SH;
		uint32_t w = 1 + r32(&g) % 256, h = 1 + r32(&g) % 256;
		int up = dy <= sy;

		w = umin(w, umin(SW - sx, SW - dx));
		h = umin(h, umin(SH - sy, SH - dy));
		for (yy = 0; yy < h; yy++) {
			uint32_t row = up ? yy : h - 1 - yy;
			uint32_t *d = s + (size_t)(dy + row) * SW + dx;
			const uint32_t *src = s + (size_t)(sy + row) * SW + sx;

			if (!xor) {
				memmove(d, src, (size_t)w * 4);
				continue;
			}
			memcpy(tmp, src, (size_t)w * 4);
			for (xx = 0; xx < w; xx++)
				d[xx] ^= tmp[xx];
		}
	}
	return now_s() - t0;
}

static double limit_text(uint32_t *s, uint32_t ops)
{
	struct rng g = { SEED };
	double t0 = now_s();
	uint32_t i, row, bit;

	for (i = 0; i < ops; i++) {
		uint32_t glyph = r32(&g) % 256;
		uint32_t fg = r32(&g) | 0xff000000u, bg = r32(&g) | 0xff000000u;
		uint32_t cell = i % (128 * 48);
		uint32_t *p = s + (size_t)(cell / 128) * 16 * SW + (cell % 128) * 8;

		for (row = 0; row < 16; row++, p += SW) {
			uint8_t bits = text_font[glyph * 16 + row];

			for (bit = 0; bit < 8; bit++)
				p[bit] = (bits & (0x80 >> bit)) ? fg : bg;
		}
	}
	return now_s() - t0;
}

static double limit_scanout(const uint8_t *src, const uint32_t *clut,
			    uint32_t *out, uint32_t frames)
{
	double t0 = now_s();
	uint32_t f, i;

	for (f = 0; f < frames; f++) {
		for (i = 0; i < SW * SH; i++)
			out[i] = clut[src[i]];
		__asm__ volatile("" : : "r"(out) : "memory");
	}
	return now_s() - t0;
}

/* ---- driver -------------------------------------------------------------- */

struct result {
	uint64_t ops, pixels, cycles;
	uint32_t crc;
	double wall, limit;
};

static struct result run_workload(const char *name)
{
	struct result res = { 0 };
	struct run r;
	uint64_t c0, c1;
	double t0;
	uint32_t *lim = calloc((size_t)SW * SH, 4);

	if (!lim)
		die("limit buffer", RDC_E_NOMEM);
	if (!strcmp(name, "scanout")) {
		static uint32_t clut[256];
		static uint8_t idx[SW * SH];
		struct rng g = { SEED };
		uint32_t i, w, h;
		uint32_t *frame = malloc((size_t)SW * SH * 4);

		run_open(&r, RDC_FMT_I8);
		for (i = 0; i < 256; i++)
			clut[i] = r32(&g) & 0x00ffffffu;
		rdc_batch_load_clut(r.b, 0, clut, 256);
		fill_ops(&r, 7, 100000, 1);
		run_finish(&r);
		rdc_vblank_wait(r.dev);
		rdc_vblank_wait(r.dev);
		res.ops = 600;
		res.pixels = 600ull * SW * SH;
		rdc_sim_time(r.dev, &c0);
		t0 = now_s();
		for (i = 0; i < 600; i++)
			if (rdc_frame_wait(r.dev) == 0)
				rdc_frame_grab(r.dev, frame, (size_t)SW * SH,
					       &w, &h);
		res.wall = now_s() - t0;
		rdc_sim_time(r.dev, &c1);
		res.cycles = c1 - c0;
		res.crc = (uint32_t)crc32(0, (const uint8_t *)frame,
					  (uInt)SW * SH * 4);
		rdc_vram_read(r.dev, 0, idx, sizeof(idx));
		res.limit = limit_scanout(idx, clut, lim, 600);
		free(frame);
		run_close(&r);
		free(lim);
		return res;
	}

	run_open(&r, RDC_FMT_XRGB8888);
	if (!strcmp(name, "blit") || !strcmp(name, "blit_xor")) {
		fill_ops(&r, 0x9e3779b9u, 100000, 0);
		run_finish(&r);
		limit_fill(lim, 0x9e3779b9u, 100000);
		r.pixels = 0;
		if (!strcmp(name, "blit_xor"))
			rdc_batch_rop(r.b, RDC_ROP_XOR);
	}
	if (!strcmp(name, "text"))
		text_font_make();
	rdc_sim_time(r.dev, &c0);
	t0 = now_s();
	if (!strcmp(name, "fill")) {
		res.ops = 100000;
		fill_ops(&r, SEED, 100000, 0);
	} else if (!strcmp(name, "blit") || !strcmp(name, "blit_xor")) {
		res.ops = 50000;
		blit_ops(&r, 50000);
	} else if (!strcmp(name, "text")) {
		res.ops = 1000000;
		text_ops(&r, 1000000);
	} else if (!strcmp(name, "line")) {
		res.ops = 1000000;
		line_ops(&r, 1000000);
	} else if (!strcmp(name, "circle")) {
		res.ops = 200000;
		circle_ops(&r, 200000, 0);
	} else if (!strcmp(name, "fill_circle")) {
		res.ops = 50000;
		circle_ops(&r, 50000, 1);
	}
	run_finish(&r);
	res.wall = now_s() - t0;
	rdc_sim_time(r.dev, &c1);
	res.cycles = c1 - c0;
	res.pixels = r.pixels;
	res.crc = surface_crc(&r, SW * SH * 4);
	if (!strcmp(name, "fill"))
		res.limit = limit_fill(lim, SEED, 100000);
	else if (!strcmp(name, "blit"))
		res.limit = limit_blit(lim, 50000, 0);
	else if (!strcmp(name, "blit_xor"))
		res.limit = limit_blit(lim, 50000, 1);
	else if (!strcmp(name, "text"))
		res.limit = limit_text(lim, 1000000);
	run_close(&r);
	free(lim);
	return res;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static const char *const workloads[] = {
	"fill", "blit", "blit_xor", "line", "circle", "fill_circle", "text",
	"scanout",
};

int main(int argc, char **argv)
{
	static const struct option opts[] = {
		{ "workload", required_argument, NULL, 'w' },
		{ "repeat", required_argument, NULL, 'r' },
		{ "json", no_argument, NULL, 'j' },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	const char *only = NULL;
	int repeat = 3, json = 0, c;
	size_t i;

	while ((c = getopt_long(argc, argv, "w:r:jh", opts, NULL)) != -1) {
		switch (c) {
		case 'w':
			only = optarg;
			break;
		case 'r':
			repeat = atoi(optarg);
			if (repeat < 1 || repeat > 99) {
				fprintf(stderr, "rdc-bench: repeat 1..99\n");
				return 2;
			}
			break;
		case 'j':
			json = 1;
			break;
		default:
			printf("usage: rdc-bench [-w WORKLOAD] [-r REPEATS] [--json]\n");
			return c == 'h' ? 0 : 2;
		}
	}
	for (i = 0; i < sizeof(workloads) / sizeof(workloads[0]); i++) {
		double wall[99], limit[99];
		struct result res = { 0 };
		int k;

		if (only && strcmp(only, workloads[i]))
			continue;
		for (k = 0; k < repeat; k++) {
			res = run_workload(workloads[i]);
			wall[k] = res.wall;
			limit[k] = res.limit;
		}
		qsort(wall, (size_t)repeat, sizeof(double), cmp_double);
		qsort(limit, (size_t)repeat, sizeof(double), cmp_double);
		res.wall = wall[repeat / 2];
		res.limit = limit[repeat / 2];
		printf("{\"workload\":\"%s\",\"ops\":%llu,\"pixels\":%llu,"
		       "\"wall_s\":%.6f,\"mpix_s\":%.1f,\"ops_s\":%.0f,"
		       "\"sim_cycles\":%llu,\"crc32\":\"%08x\"",
		       workloads[i], (unsigned long long)res.ops,
		       (unsigned long long)res.pixels, res.wall,
		       res.pixels / res.wall / 1e6, res.ops / res.wall,
		       (unsigned long long)res.cycles, res.crc);
		if (res.limit > 0)
			printf(",\"limit_s\":%.6f,\"vs_limit\":%.3f", res.limit,
			       res.limit / res.wall);
		printf("}\n");
		fflush(stdout);
	}
	(void)json;
	return 0;
}
