// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Reporting: one JSON object a workload (the workloads' keys first, then
 * the limits, the peers and the ratios), and unless --json the tables
 * (bench/README.md, "Reading the output").
 */
#include <stdio.h>
#include <string.h>

#include "parts.h"

static double mpix(uint64_t pixels, double wall)
{
	return wall > 0 ? (double)pixels / wall / 1e6 : 0;
}

static const char *crc_word(enum bench_kind k, uint32_t crc)
{
	if (!expect_crc[k])
		return "";
	return crc == expect_crc[k] ? "OK" : "MISMATCH";
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

void print_json(const struct result *res)
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

void print_table(const struct result *res, size_t n, bool peers_on)
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
