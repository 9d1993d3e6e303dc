/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdc-bench's parts, shared between its own files (the peer libraries
 * see bench.h only):
 *
 *   rdc_bench.c  options, each workload's contenders in turn, main
 *   common.c     the workloads' names, the peers built in, dying on errors
 *   input.c      the workloads' inputs, drawn from their random streams
 *   pixels.c     a second geometry: the pixels a circle or polygon covers
 *   draw.c       the workloads through librdc sim:, realtime, teapot3d
 *   limits.c     the plain-C limits of the byte-moving workloads
 *   measure.c    clocks, interleaved repeats and medians, the contenders
 *   report.c     the JSON lines and the tables
 *   targets.c    saved CRCs and cycles, the targets, what fails a run
 *   growth.c     cost against area and region size (-w growth)
 */
#ifndef RDC_BENCH_PARTS_H
#define RDC_BENCH_PARTS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "bench.h"
#include "rdc.h"

#define MAX_REPEAT 99
/*
 * A measurement whose first run takes longer than this is not repeated
 * (unless --full): three runs of every slow workload would not fit the
 * five minutes a full `make bench-peers` may take.  The output says so.
 */
#define SLOW_S 4.0

/* realtime: simulated frames per wall second wanted, 20x real time. */
#define RT_PRESET     RDC_PRESET_640x480_60
#define RT_W	      640u
#define RT_H	      480u
#define RT_HZ	      60u
#define RT_TARGET_FPS (20u * RT_HZ)

/* The peer libraries built in (make bench-peers), and their table. */
#ifdef BENCH_HAVE_PIXMAN
#define NPEERS_PIXMAN 1
#else
#define NPEERS_PIXMAN 0
#endif
#ifdef BENCH_HAVE_CAIRO
#define NPEERS_CAIRO 1
#else
#define NPEERS_CAIRO 0
#endif
#ifdef BENCH_HAVE_SDL2_GFX
#define NPEERS_SDL2_GFX 1
#else
#define NPEERS_SDL2_GFX 0
#endif
#define NPEERS (NPEERS_PIXMAN + NPEERS_CAIRO + NPEERS_SDL2_GFX)

extern const struct bench_peer *const peers[NPEERS + 1]; /* NULL ended */
extern const char *const kind_name[BENCH_KIND_COUNT];

static inline bool byte_moving(enum bench_kind k)
{
	return k == BENCH_FILL || k == BENCH_BLIT || k == BENCH_BLIT_XOR ||
	       k == BENCH_TEXT || k == BENCH_SCANOUT;
}

/* The drawing workloads: measured with scanout on and with it off. */
static inline bool drawing(enum bench_kind k)
{
	return k <= BENCH_TEXT;
}

static inline bool realtime(enum bench_kind k)
{
	return k == BENCH_REALTIME || k == BENCH_REALTIME_1080;
}

static inline uint32_t bench_umin(uint32_t a, uint32_t b)
{
	return a < b ? a : b;
}

void bench_die(const char *what, int err);
void *bench_xcalloc(size_t n, size_t size);

/* ---- inputs (input.c, pixels.c) ------------------------------------------ */

struct bench_rng {
	uint32_t x;
};

static inline uint32_t bench_r32(struct bench_rng *g)
{
	uint32_t x = g->x;

	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	return g->x = x;
}

void input_make(struct bench_input *in, enum bench_kind kind);
void input_free(struct bench_input *in);
uint64_t circle_pixels(int cx, int cy, int r, bool filled);
uint64_t polygon_pixels(const int *xy, uint32_t n);

/* ---- rdc: the workloads through librdc sim: (draw.c) --------------------- */

struct bench_run {
	rdc_dev *dev;
	rdc_batch *b;
};

struct bench_rdc_res {
	double wall;
	uint64_t cycles;
	uint64_t sim_pixels; /* pixels the DP wrote, by its own count */
	uint32_t crc;
	uint64_t frames;    /* scanned out while drawing (scanout on) */
	uint32_t frame_crc; /* of the first frame after the drawing */
};

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

void bench_run_flush(struct bench_run *r, bool force);
void bench_run_finish(struct bench_run *r);
void bench_scanout_off(rdc_dev *dev);
void bench_rdc_run(const struct bench_input *in, struct bench_rdc_res *res,
		   bool scan, bool lazy);
const struct rt_mode *rt_mode_of(enum bench_kind k);
void bench_realtime(struct rt_res *res, const struct rt_mode *m, bool lazy);
void bench_teapot3d(struct rt_res *res);

/* ---- plain-C limits (limits.c) ------------------------------------------- */

/* A limit draws into s (BENCH_W x BENCH_H words, cleared) and returns its
 * seconds; the CRC of s afterwards is checked against rdc's. */
struct limit {
	const char *name;
	double (*run)(const struct bench_input *in, uint32_t *s);
	const char *scan_name; /* the same with the frames' scanout */
};

#define MAX_LIMITS 2
extern const struct limit limits[BENCH_KIND_COUNT][MAX_LIMITS];

double scan_frames(const uint32_t *s, uint64_t frames, double *cpu,
		   uint32_t *crc);

/* ---- measuring (measure.c) ----------------------------------------------- */

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

struct bench_opts {
	int repeat;
	bool json, full, peers;
};

/* One contender in a workload: rdc, a limit or a peer. */
struct entrant {
	struct figure *fig;
	double (*one)(void *ctx, uint32_t ops, uint32_t *crc);
	void *ctx;
	double wall[MAX_REPEAT], cpu[MAX_REPEAT];
	bool failed;
};

struct bench_rdc_ctx {
	const struct bench_input *in;
	bool scan; /* scanout on */
	bool lazy; /* and no frame consumer */
	uint64_t cycles, sim_pixels, frames;
	uint32_t frame_crc;
	bool cycles_differ; /* a run's simulated time was not the first's */
};

struct limit_ctx {
	const struct bench_input *in;
	const struct limit *lim;
	const struct bench_rdc_ctx *scan; /* with scanout: rdc's frame count */
	uint32_t frame_crc;		  /* of the last frame converted */
	bool frame_crc_same;		  /* every run's was the same */
	int runs;
};

struct peer_ctx {
	const struct bench_input *in;
	const struct bench_peer *peer;
};

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
	const struct bench_rdc_ctx *scan; /* rdc's frame count */
	struct figure *fig;
};

double bench_cpu_now(void);
double bench_least(const double *v, int n);
double bench_median(double *v, int n);
void bench_measure(struct entrant *e, size_t n, const struct bench_opts *o);
void figure_init(struct figure *f, const char *name,
		 const struct bench_input *in, uint32_t ops);
double bench_rdc_one(void *ctx, uint32_t ops, uint32_t *crc);
double limit_one(void *ctx, uint32_t ops, uint32_t *crc);
double peer_one(void *ctx, uint32_t ops, uint32_t *crc);
double peer_scan_one(void *ctx, uint32_t ops, uint32_t *crc);
uint32_t peer_ops(const struct bench_input *in, const struct bench_peer *peer,
		  const struct bench_opts *o);

/* ---- results, targets and reporting (targets.c, report.c) ---------------- */

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

/* Pixels per CPU second: what rdc/limit and rdc/best-peer compare. */
static inline double rate(const struct figure *f)
{
	return f->cpu > 0 ? (double)f->pixels / f->cpu : 0;
}

extern const uint32_t expect_crc[BENCH_KIND_COUNT];
extern const uint64_t expect_cycles[BENCH_KIND_COUNT];
extern const uint64_t expect_cycles_off[BENCH_KIND_COUNT];

void way_compare(struct result *res, struct way *w, const struct figure *lim,
		 bool on);
int check_failures(const struct result *res, size_t n);
void print_json(const struct result *res);
void print_table(const struct result *res, size_t n, bool peers_on);

/* ---- growth (growth.c) --------------------------------------------------- */

void bench_growth(const struct bench_opts *o);

#endif /* RDC_BENCH_PARTS_H */
