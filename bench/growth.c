// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdc-bench -w growth: how the cost of fill, blit and flood fill grows
 * with area (bench/README.md, "Growth").
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>
#include <zlib.h>

#include "parts.h"

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
	uint8_t *buf = bench_xcalloc(G_SIDE, 4);
	uLong crc = crc32(0, NULL, 0);
	uint32_t y;

	for (y = 0; y < G_SIDE; y++) {
		if (rdc_vram_read(dev, y * G_SIDE * 4, buf, G_SIDE * 4))
			bench_die("vram read", RDC_E_IO);
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
	uint32_t *a = bench_xcalloc((size_t)ops * 4, 4), i,
		 span = G_SIDE - side + 1;
	struct bench_rng g = { BENCH_SEED ^ side };

	for (i = 0; i < ops; i++) {
		a[4 * i] = bench_r32(&g) % span;
		a[4 * i + 1] = bench_r32(&g) % span;
		a[4 * i + 2] = what == G_FILL ? bench_r32(&g) | BENCH_OPAQUE :
						bench_r32(&g) % span;
		a[4 * i + 3] = bench_r32(&g) % span;
	}
	return a;
}

static uint32_t g_other(uint32_t c)
{
	return c == G_REGION_A ? G_REGION_B : G_REGION_A;
}

/* flood: cur is the region's colour; each op turns it to the other one. */
static void g_rdc(struct bench_run *r, uint32_t what, uint32_t side,
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
		bench_run_flush(r, false);
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
static void g_source(struct bench_run *r, uint32_t *src)
{
	struct bench_rng g = { BENCH_PREFILL_SEED };
	size_t i;

	for (i = 0; i < (size_t)G_SIDE * G_SIDE; i++)
		src[i] = bench_r32(&g);
	if (rdc_vram_write(r->dev, G_SRC, src, (size_t)G_SIDE * G_SIDE * 4))
		bench_die("vram write", RDC_E_IO);
}

/* Fill the whole surface with c (setup, untimed), and the limit's too. */
static void g_clear(struct bench_run *r, uint32_t *s, uint32_t c)
{
	rdc_batch_fg(r->b, c);
	rdc_batch_fill_rect(r->b, 0, 0, G_SIDE, G_SIDE);
	bench_run_finish(r);
	wmemset((wchar_t *)s, (wchar_t)c, (size_t)G_SIDE * G_SIDE);
}

static void g_measure(struct bench_run *r, uint32_t *s, uint32_t what,
		      uint32_t side, const struct bench_opts *o,
		      struct g_row *row)
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
		bench_run_finish(r);
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
			aa = bench_xcalloc((size_t)ops * 4, 4);
			for (i = 0; i < ops; i++)
				memcpy(aa + 4 * i, a, 16);
		}
		rdc_stats_get(r->dev, &st0);
		rdc_sim_time(r->dev, &c0);
		t0 = bench_tic();
		g_rdc(r, what, side, aa, ops, cur);
		bench_run_finish(r);
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
	row->wall = bench_least(wall, o->repeat);
	row->cpu = bench_least(cpu, o->repeat);
	row->lim_cpu = bench_least(lim, o->repeat);
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

void bench_growth(const struct bench_opts *o)
{
	static struct g_row rows[G_WHATS][G_SIZES];
	struct g_fit fit[G_WHATS];
	uint32_t *s =
		bench_xcalloc((size_t)G_SIDE * G_SIDE * 2, 4); /* dst, src */
	uint32_t w, i, n = 0, side;
	struct bench_run r;
	int err = rdc_open(G_URI, &r.dev);

	if (err)
		bench_die("open " G_URI, err);
	r.b = rdc_batch_new();
	if (!r.b)
		bench_die("batch", RDC_E_NOMEM);
	bench_scanout_off(r.dev);
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
