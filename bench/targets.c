// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * What a run must give and what it aims for: the saved CRCs and simulated
 * cycles (a change fails the run), and each workload's target against
 * the limits or the peers (a miss is reported, not failed).
 */
#include <stdio.h>
#include <string.h>

#include "parts.h"

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

/* Expected CRCs (bench/README.md); 0 where none is given. */
const uint32_t expect_crc[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 0xcce4ceedu,	[BENCH_BLIT] = 0x039b2ef6u,
	[BENCH_BLIT_XOR] = 0x96d2b63du, [BENCH_TEXT] = 0x7c6efccau,
	[BENCH_SCANOUT] = 0x530c48eau,
};

/*
 * Simulated cycles of each workload's drawing, scanout on and scanout off,
 * as first measured (bench/README.md, "Simulated cycles"); 0 where they
 * vary from run to run (realtime).  The simulator may get faster, never
 * different: a cycle count that changed fails the run, as a CRC does.
 */
const uint64_t expect_cycles[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 1046691488u,	  [BENCH_BLIT] = 852261319u,
	[BENCH_BLIT_XOR] = 1267234621u,	  [BENCH_LINE] = 3459568377u,
	[BENCH_AALINE] = 1228372199u,	  [BENCH_CIRCLE] = 469315241u,
	[BENCH_FILL_CIRCLE] = 184455458u, [BENCH_POLYGON] = 222355743u,
	[BENCH_TEXT] = 243880404u,	  [BENCH_SCANOUT] = 999938688u,
	[BENCH_TEAPOT3D] = 162255342u,
};
const uint64_t expect_cycles_off[BENCH_KIND_COUNT] = {
	[BENCH_FILL] = 788735905u,	  [BENCH_BLIT] = 642020749u,
	[BENCH_BLIT_XOR] = 951224529u,	  [BENCH_LINE] = 2617307543u,
	[BENCH_AALINE] = 929128321u,	  [BENCH_CIRCLE] = 355120555u,
	[BENCH_FILL_CIRCLE] = 139212855u, [BENCH_POLYGON] = 167859281u,
	[BENCH_TEXT] = 185000282u,
};

/* rdc against the limits and peers one way; then its target. */
void way_compare(struct result *res, struct way *w, const struct figure *lim,
		 bool on)
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

/*
 * A wrong CRC from rdc or from a limit means the work differs from the
 * workloads' (bench/README.md): the figures are void and the run fails.
 * So does a simulated cycle count that is not the saved one, a picture
 * that differs with scanout off, and a limit with scanout whose last frame
 * is not the chip's.  (Targets missed do not fail it.)
 */
int check_failures(const struct result *res, size_t n)
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
