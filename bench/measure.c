// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Measuring: the clocks, the contenders (rdc, a limit, a peer) run in
 * interleaved rounds, and each one's median.
 */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <zlib.h>

#include "parts.h"

/*
 * A peer whose whole workload would take longer than this (estimated from
 * a prefix of 1/PEER_PROBE of it) draws only the prefix that fits, and is
 * rated by its pixels a second over that prefix (the input is uniformly
 * random, so any prefix is like the whole).  --full draws everything.
 */
#define PEER_BUDGET_S 1.0
#define PEER_PROBE    32

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
double bench_cpu_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double tic_cpu, toc_cpu;

double bench_tic(void)
{
	tic_cpu = bench_cpu_now();
	return bench_now();
}

double bench_toc(double t0)
{
	toc_cpu = bench_cpu_now() - tic_cpu;
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

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* ---- measuring ----------------------------------------------------------- */

double bench_least(const double *v, int n)
{
	double m = v[0];
	int i;

	for (i = 1; i < n; i++)
		m = v[i] < m ? v[i] : m;
	return m;
}

double bench_median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof(double), cmp_double);
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/*
 * Run every entrant once per round, o->repeat rounds, and keep each one's
 * median.  Interleaving the rounds puts all of a workload's figures in the
 * same stretch of time, so that a shared machine's load shifts them alike
 * and their ratios hold.  An entrant whose first run was slow (SLOW_S)
 * sits out the later rounds.
 */
void bench_measure(struct entrant *e, size_t n, const struct bench_opts *o)
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
			f->wall = bench_median(e[i].wall, f->runs);
			f->cpu = bench_median(e[i].cpu, f->runs);
			f->done = true;
		}
	}
}

/* A figure for `name` over the first `ops` primitives of `in`. */
void figure_init(struct figure *f, const char *name,
		 const struct bench_input *in, uint32_t ops)
{
	memset(f, 0, sizeof(*f));
	f->name = name;
	f->ops = ops;
	f->pixels = in->cum[ops];
	f->crc_same = true;
}

double bench_rdc_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct bench_rdc_ctx *c = ctx;
	struct bench_rdc_res res = { 0 };

	(void)ops; /* always all of it */
	bench_rdc_run(c->in, &res, c->scan, c->lazy);
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

double limit_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct limit_ctx *c = ctx;
	uint32_t *s = bench_xcalloc((size_t)BENCH_W * BENCH_H, 4);
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

double peer_one(void *ctx, uint32_t ops, uint32_t *crc)
{
	struct peer_ctx *c = ctx;

	return c->peer->run(c->in, ops, crc);
}

double peer_scan_one(void *ctx, uint32_t ops, uint32_t *crc)
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
	s = bench_xcalloc((size_t)BENCH_W * BENCH_H, 4);
	memset(s, 0x5a, (size_t)BENCH_W * BENCH_H * 4);
	t += scan_frames(s, c->fig->frames, &cpu2, &fcrc);
	toc_cpu = cpu + cpu2;
	free(s);
	return t;
}

/* How much of the workload a peer draws: see PEER_BUDGET_S. */
uint32_t peer_ops(const struct bench_input *in, const struct bench_peer *peer,
		  const struct bench_opts *o)
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
