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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "parts.h"

/* ---- driver -------------------------------------------------------------- */

static void run_rt(struct result *res, enum bench_kind kind,
		   const struct bench_opts *o)
{
	double fps[MAX_REPEAT], fps_lazy[MAX_REPEAT];
	double cfps[MAX_REPEAT], cfps_lazy[MAX_REPEAT];
	struct rt_res rt = { 0 }, rt_lazy = { 0 };
	int runs;

	/* realtime: with its sink and with no frame consumer, by turns */
	for (runs = 0; runs < o->repeat; runs++) {
		if (kind == BENCH_TEAPOT3D) {
			bench_teapot3d(&rt);
		} else {
			bench_realtime(&rt_lazy, rt_mode_of(kind), true);
			fps_lazy[runs] = (double)rt_lazy.frames / rt_lazy.wall;
			cfps_lazy[runs] = (double)rt_lazy.frames / rt_lazy.cpu;
			bench_realtime(&rt, rt_mode_of(kind), false);
			cfps[runs] = (double)rt.frames / rt.cpu;
		}
		fps[runs] = (double)rt.frames / rt.wall;
	}
	res->fps = bench_median(fps, runs);
	if (kind != BENCH_TEAPOT3D) {
		res->fps_lazy = bench_median(fps_lazy, runs);
		res->cpu_fps = bench_median(cfps, runs);
		res->cpu_fps_lazy = bench_median(cfps_lazy, runs);
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
		     const struct bench_opts *o)
{
	struct entrant e[3 + 2 * MAX_LIMITS + 2 * NPEERS];
	struct limit_ctx lc[MAX_LIMITS], ls[MAX_LIMITS];
	struct peer_ctx pc[NPEERS + 1];
	struct peer_scan_ctx psc[NPEERS + 1];
	static char scan_name[NPEERS + 1][48];
	struct bench_input in;
	struct bench_rdc_ctx rc, rc_off, rc_lazy;
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
	rc_off = (struct bench_rdc_ctx){ .in = &in };
	rc_lazy =
		(struct bench_rdc_ctx){ .in = &in, .scan = true, .lazy = true };
	figure_init(&res->rdc, "rdc", &in, in.ops);
	e[n++] = (struct entrant){ .fig = &res->rdc,
				   .one = bench_rdc_one,
				   .ctx = &rc };
	if (drawing(kind)) {
		figure_init(&res->rdc_off, "rdc-noscan", &in, in.ops);
		e[n++] = (struct entrant){ .fig = &res->rdc_off,
					   .one = bench_rdc_one,
					   .ctx = &rc_off };
		figure_init(&res->rdc_lazy, "rdc-lazy", &in, in.ops);
		e[n++] = (struct entrant){ .fig = &res->rdc_lazy,
					   .one = bench_rdc_one,
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
	bench_measure(e, n, o);
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
	struct bench_opts o = { .repeat = 3 };
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
		bench_growth(&o);
	return check_failures(res, n) ? 1 : 0;
}
