// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd speed, over a UNIX socket, one JSON line per figure:
 *  - batched submit throughput: small commands (1x1 FILL_RECT with its
 *    colour, 4 words) per wall second, the daemon running unpaced;
 *  - round trip of a register read: mean, median and 99th percentile;
 *  - a subscriber to 1024x768 frames, daemon unpaced: frames received
 *    per wall second and frames dropped for it, in each encoding;
 *  - the same, daemon paced: 60 frames per wall second expected;
 *  - an idle paced daemon at 1024x768@60, nobody connected: the share of
 *    a core it takes with no frame consumer, and with one (a sink).
 * Usage: net_bench PATH/TO/rdcd  (`make bench-net` builds and runs it).
 *
 * net_bench --uri URI measures a device that is already there (any
 * librdc URI; tests/vm/tests/usb-bench.sh gives it usb: and unix: on the
 * same rdcd --fast): the submit rate, the register round trip, frames
 * received in each encoding by the controlling client itself (a usb:
 * device has one session at a time: no observer beside it), and the
 * bytes a 1024x768 frame takes in each encoding, with the frame rate
 * that USB 2.0 high speed's practical 35-40 MB/s would carry.
 */
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "rdc.h"
#include "rdc_proto.h"

#define BENCH_BATCH	    1024  /* commands per submit */
#define BENCH_SUBMIT_S	    2.0	  /* seconds of submitting */
#define BENCH_RTT_N	    20000 /* register reads */
#define BENCH_FRAMES_S	    3.0	  /* seconds of watching frames */
#define BENCH_RTT_URI_N	    2000  /* register reads with --uri (slow links) */
#define BENCH_USB_HS_LO	    35e6  /* USB 2.0 high speed, bytes/s in practice */
#define BENCH_USB_HS_HI	    40e6
#define BENCH_IDLE_S	    4.0 /* seconds an idle daemon is watched */
#define BENCH_IDLE_SETTLE_S 1	/* after its start, before that */
#define BENCH_IDLE_ROUNDS   2	/* (--idle SECONDS: one) */

/* "unix", "usb"...: the JSON lines' transport */
static char bench_transport[16] = "unix";
static int bench_rtt_n = BENCH_RTT_N;

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static pid_t start_daemon(const char *rdcd, const char *dir, const char *mode,
			  char *uri, size_t cap)
{
	char sock[200], ready[200], lis[220];
	pid_t pid;

	snprintf(sock, sizeof(sock), "%s/rdc.sock", dir);
	snprintf(ready, sizeof(ready), "%s/ready", dir);
	snprintf(lis, sizeof(lis), "unix:%s", sock);
	snprintf(uri, cap, "unix:%s", sock);
	pid = fork();
	if (pid == 0) {
		execl(rdcd, rdcd, mode, "-q", "--listen", lis, "--ready-file",
		      ready, (char *)NULL);
		_exit(127);
	}
	for (int i = 0; i < 1000; i++) {
		struct timespec ts = { 0, 10000000 };

		if (access(ready, F_OK) == 0)
			return pid;
		nanosleep(&ts, NULL);
	}
	kill(pid, SIGTERM);
	return -1;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

static void bench_submit(rdc_dev *dev)
{
	rdc_batch *b = rdc_batch_new();
	double t0, t = 0;
	uint64_t cmds = 0;

	for (int i = 0; i < BENCH_BATCH; i++) {
		rdc_batch_fg(b, (uint32_t)i);
		rdc_batch_fill_rect(b, i % 1000, i % 700, 1, 1);
	}
	t0 = now_s();
	do {
		size_t n;
		const uint32_t *w = rdc_batch_words(b, &n);

		if (rdc_submit(dev, w, n))
			break;
		cmds += 2 * BENCH_BATCH;
		t = now_s();
	} while (t - t0 < BENCH_SUBMIT_S);
	rdc_finish(dev);
	t = now_s();
	printf("{\"bench\":\"submit\",\"transport\":\"%s\",\"batch_cmds\":%d,"
	       "\"commands\":%llu,\"seconds\":%.3f,\"commands_per_s\":%.0f}\n",
	       bench_transport, 2 * BENCH_BATCH, (unsigned long long)cmds,
	       t - t0, (double)cmds / (t - t0));
	rdc_batch_free(b);
}

static void bench_rtt(rdc_dev *dev)
{
	static double lat[BENCH_RTT_N];
	double sum = 0;
	uint32_t v;

	for (int i = 0; i < bench_rtt_n; i++) {
		double t0 = now_s();

		rdc_reg_read(dev, RDC_REG_ID, &v);
		lat[i] = now_s() - t0;
		sum += lat[i];
	}
	qsort(lat, (size_t)bench_rtt_n, sizeof(*lat), cmp_double);
	printf("{\"bench\":\"reg_read_rtt\",\"transport\":\"%s\",\"n\":%d,"
	       "\"mean_us\":%.2f,\"p50_us\":%.2f,\"p99_us\":%.2f}\n",
	       bench_transport, bench_rtt_n, sum / bench_rtt_n * 1e6,
	       lat[bench_rtt_n / 2] * 1e6, lat[bench_rtt_n * 99 / 100] * 1e6);
}

static void bench_frames(const char *uri)
{
	static uint32_t pix[1024 * 768];
	char obs_uri[320];
	rdc_dev *obs;
	struct rdc_event ev = { 0 };
	uint64_t first = 0, got = 0;
	double t0, t = 0;

	snprintf(obs_uri, sizeof(obs_uri), "%s?observe", uri);
	if (rdc_open(obs_uri, &obs))
		return;
	double sim_fps = 0;

	/*
	 * Every frame in each encoding, then raw at every Nth frame so that
	 * about 60 a second are asked for: can 60 fps arrive without drops?
	 */
	for (uint32_t run = 0; run <= RDC_FRAME_DELTA + 1; run++) {
		uint32_t enc = run <= RDC_FRAME_DELTA ? run : RDC_FRAME_RAW;
		uint32_t every = run <= RDC_FRAME_DELTA || sim_fps < 120 ?
					 1 :
					 (uint32_t)(sim_fps / 60);

		rdc_subscribe(obs, RDC_EVENT_FRAME, every, enc);
		got = 0;
		ev.dropped = 0;
		/* the first frame starts the clock */
		if (rdc_event_next(obs, &ev, pix, RDC_ARRAY_SIZE(pix), 5000))
			break;
		first = ev.number;
		{
			uint32_t d0 = ev.dropped;

			t0 = now_s();
			do {
				if (rdc_event_next(obs, &ev, pix,
						   RDC_ARRAY_SIZE(pix), 5000))
					break;
				got++;
				t = now_s();
			} while (t - t0 < BENCH_FRAMES_S);
			sim_fps = (double)(ev.number - first) / (t - t0);
			printf("{\"bench\":\"frames\",\"transport\":\"unix\","
			       "\"size\":\"1024x768\",\"every\":%u,"
			       "\"encoding\":\"%s\","
			       "\"received\":%llu,\"seconds\":%.3f,"
			       "\"received_fps\":%.1f,\"simulated_fps\":%.1f,"
			       "\"dropped\":%u,\"ok_60fps_no_drops\":%s}\n",
			       every,
			       enc == 0 ? "raw" :
			       enc == 1 ? "rle" :
					  "delta",
			       (unsigned long long)got, t - t0,
			       (double)got / (t - t0),
			       (double)(ev.number - first) / (t - t0),
			       ev.dropped - d0,
			       (double)got / (t - t0) >= 60.0 &&
					       ev.dropped == d0 ?
				       "true" :
				       "false");
		}
	}
	rdc_close(obs);
}

static void bench_paced(rdc_dev *dev, const char *uri)
{
	static uint32_t pix[1024 * 768];
	char obs_uri[320];
	struct rdc_event ev = { 0 };
	rdc_dev *obs;
	uint64_t got = 0, first;
	double t0, t = 0;

	(void)dev;
	snprintf(obs_uri, sizeof(obs_uri), "%s?observe", uri);
	if (rdc_open(obs_uri, &obs))
		return;
	rdc_subscribe(obs, RDC_EVENT_FRAME, 1, RDC_FRAME_DELTA);
	if (rdc_event_next(obs, &ev, pix, RDC_ARRAY_SIZE(pix), 5000)) {
		rdc_close(obs);
		return;
	}
	first = ev.number;
	t0 = now_s();
	do {
		if (rdc_event_next(obs, &ev, pix, RDC_ARRAY_SIZE(pix), 5000))
			break;
		got++;
		t = now_s();
	} while (t - t0 < BENCH_FRAMES_S);
	printf("{\"bench\":\"frames_paced\",\"transport\":\"unix\","
	       "\"size\":\"1024x768@60\",\"received_fps\":%.1f,"
	       "\"simulated_fps\":%.1f,\"dropped\":%u}\n",
	       (double)got / (t - t0), (double)(ev.number - first) / (t - t0),
	       ev.dropped);
	rdc_close(obs);
}

/*
 * Nanoseconds pid has run on a CPU: /proc/PID/schedstat's first field, or
 * (without schedstats) utime + stime of /proc/PID/stat, in clock ticks.
 */
static double cpu_ns_of(pid_t pid)
{
	char path[64], buf[1024], *p;
	unsigned long long ns, ut, st;
	FILE *f;
	int i;

	snprintf(path, sizeof(path), "/proc/%d/schedstat", (int)pid);
	f = fopen(path, "r");
	if (f) {
		i = fscanf(f, "%llu", &ns);
		fclose(f);
		if (i == 1)
			return (double)ns;
	}
	snprintf(path, sizeof(path), "/proc/%d/stat", (int)pid);
	f = fopen(path, "r");
	if (!f)
		return -1;
	p = fgets(buf, sizeof(buf), f);
	fclose(f);
	p = p ? strrchr(buf, ')') : NULL;
	/* after "pid (comm)": state and 10 fields, then utime, stime */
	for (i = 0; p && i < 12; i++)
		p = strchr(p + 1, ' ');
	if (!p || sscanf(p, "%llu %llu", &ut, &st) != 2)
		return -1;
	return (double)(ut + st) * 1e9 / (double)sysconf(_SC_CLK_TCK);
}

/*
 * An idle paced rdcd at 1024x768@60 (--mode), nobody connected, for
 * `seconds` after it settled: the share of one core it takes (its CPU
 * time over the wall time), with no frame consumer (scanout on demand
 * converts nothing) and with one (a png sink that writes only when asked,
 * so every frame is converted and nothing else is done), `rounds`
 * interleaved; each the least of its rounds (a shared machine only adds
 * to a share).
 */
static int bench_idle(const char *rdcd, const char *dir, double seconds,
		      int rounds)
{
	double share[2][BENCH_IDLE_ROUNDS];
	char ready[220], lis[220], png[220];

	rounds = RDC_MIN(rounds, BENCH_IDLE_ROUNDS); /* what share holds */
	snprintf(ready, sizeof(ready), "%s/ready", dir);
	snprintf(lis, sizeof(lis), "unix:%s/idle.sock", dir);
	snprintf(png, sizeof(png), "%s,every=0", dir);
	for (int r = 0; r < rounds; r++) {
		for (int w = 0; w < 2; w++) {
			struct timespec settle = { BENCH_IDLE_SETTLE_S, 0 }, ts;
			double c0, c1, t0, t1;
			bool up;
			pid_t pid;
			int st;

			unlink(ready);
			pid = fork();
			if (pid == 0) {
				if (w)
					execl(rdcd, rdcd, "-q", "--mode",
					      "1024x768", "--listen", lis,
					      "--ready-file", ready, "--png",
					      png, (char *)NULL);
				else
					execl(rdcd, rdcd, "-q", "--mode",
					      "1024x768", "--listen", lis,
					      "--ready-file", ready,
					      (char *)NULL);
				_exit(127);
			}
			if (pid < 0)
				return -1;
			nanosleep(&settle, NULL);
			up = access(ready, F_OK) == 0;
			c0 = cpu_ns_of(pid);
			t0 = now_s();
			ts.tv_sec = (time_t)seconds;
			ts.tv_nsec =
				(long)((seconds - (double)ts.tv_sec) * 1e9);
			nanosleep(&ts, NULL);
			c1 = cpu_ns_of(pid);
			t1 = now_s();
			kill(pid, SIGTERM);
			waitpid(pid, &st, 0);
			if (c0 < 0 || c1 < 0 || !up)
				return -1; /* it did not come up */
			share[w][r] = (c1 - c0) * 1e-9 / (t1 - t0);
		}
	}
	unlink(ready);
	qsort(share[0], (size_t)rounds, sizeof(double), cmp_double);
	qsort(share[1], (size_t)rounds, sizeof(double), cmp_double);
	printf("{\"bench\":\"rdcd_idle\",\"size\":\"1024x768@60\","
	       "\"seconds\":%.1f,\"rounds\":%d,"
	       "\"cpu_share_no_consumer\":%.5f,"
	       "\"cpu_share_with_consumer\":%.5f,\"ratio\":%.3f}\n",
	       seconds, rounds, share[0][0], share[1][0],
	       share[1][0] > 0 ? share[0][0] / share[1][0] : 0);
	return 0;
}

static void bench_draw(rdc_dev *dev)
{
	/* something on screen, so that frames are not uniform */
	rdc_batch *b = rdc_batch_new();

	for (int i = 0; i < 200; i++) {
		rdc_batch_fg(b, (uint32_t)i * 0x010203u);
		rdc_batch_line(b, i * 5, 0, 1023 - i * 5, 767);
	}
	rdc_batch_text(b, 10, 10, "rdcd bench", 10, 0);
	rdc_batch_submit(dev, b);
	rdc_batch_free(b);
	rdc_finish(dev);
}

/* Frames to the controlling client itself, each encoding in turn. */
static void bench_frames_self(rdc_dev *dev)
{
	static uint32_t pix[1024 * 768];
	static const char *const name[] = { "raw", "rle", "delta" };

	for (uint32_t enc = RDC_FRAME_RAW; enc <= RDC_FRAME_DELTA; enc++) {
		struct rdc_event ev = { 0 };
		uint64_t got = 0, first;
		uint32_t d0;
		double t0, t = 0;

		if (rdc_subscribe(dev, RDC_EVENT_FRAME, 1, enc) ||
		    rdc_event_next(dev, &ev, pix, RDC_ARRAY_SIZE(pix), 5000))
			break;
		first = ev.number;
		d0 = ev.dropped;
		t0 = now_s();
		do {
			if (rdc_event_next(dev, &ev, pix, RDC_ARRAY_SIZE(pix),
					   5000))
				break;
			got++;
			t = now_s();
		} while (t - t0 < BENCH_FRAMES_S);
		printf("{\"bench\":\"frames_self\",\"transport\":\"%s\","
		       "\"size\":\"1024x768\",\"encoding\":\"%s\","
		       "\"received\":%llu,\"seconds\":%.3f,"
		       "\"received_fps\":%.1f,\"simulated_fps\":%.1f,"
		       "\"dropped\":%u}\n",
		       bench_transport, name[enc], (unsigned long long)got,
		       t - t0, (double)got / (t - t0),
		       (double)(ev.number - first) / (t - t0), ev.dropped - d0);
	}
	rdc_subscribe(dev, 0, 1, RDC_FRAME_RAW);
}

/*
 * What one frame of the screen takes on the wire in each encoding, and
 * the frames per second a USB 2.0 high-speed link carries at that size.
 */
static void bench_frame_bytes(rdc_dev *dev)
{
	static uint32_t pix[1024 * 768];
	static uint8_t out[1024 * 768 * 4 + 1024 * 8];
	static const struct {
		const char *name;
		uint32_t enc;
		int prev;
	} e[] = {
		{ "raw", RDC_ENC_RAW, 0 },
		{ "rle", RDC_ENC_RLE, 0 },
		{ "delta_unchanged", RDC_ENC_DELTA, 1 },
		{ "delta_every_row", RDC_ENC_DELTA, 0 },
	};
	uint32_t w, h;

	if (rdc_frame_grab(dev, pix, RDC_ARRAY_SIZE(pix), &w, &h) ||
	    (size_t)w * h > RDC_ARRAY_SIZE(pix))
		return;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(e); i++) {
		size_t n = rdc_proto_frame_encode(out, sizeof(out), e[i].enc,
						  pix, e[i].prev ? pix : NULL,
						  w, h);
		double bytes =
			(double)(n + RDC_PROTO_FRAME_HDR + RDC_PROTO_HDR_SIZE);

		printf("{\"bench\":\"frame_bytes\",\"size\":\"%ux%u\","
		       "\"encoding\":\"%s\",\"bytes\":%.0f,"
		       "\"fps_at_35MBps\":%.1f,\"fps_at_40MBps\":%.1f}\n",
		       w, h, e[i].name, bytes, BENCH_USB_HS_LO / bytes,
		       BENCH_USB_HS_HI / bytes);
	}
}

static int bench_uri(const char *uri)
{
	rdc_dev *dev;
	size_t k = strcspn(uri, ":");
	int ret = rdc_open(uri, &dev);

	if (ret) {
		fprintf(stderr, "net_bench: %s: %s\n", uri, rdc_strerror(ret));
		return 1;
	}
	snprintf(bench_transport, sizeof(bench_transport), "%.*s",
		 (int)RDC_MIN(k, sizeof(bench_transport) - 1), uri);
	bench_rtt_n = BENCH_RTT_URI_N;
	rdc_mode_set(dev, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888, 0);
	rdc_finish(dev);
	bench_submit(dev);
	bench_rtt(dev);
	bench_draw(dev);
	rdc_vblank_wait(dev);
	rdc_vblank_wait(dev);
	bench_frames_self(dev);
	bench_frame_bytes(dev);
	rdc_close(dev);
	return 0;
}

int main(int argc, char **argv)
{
	char dir[] = "/tmp/rdc-bench-XXXXXX", uri[300], path[300];
	rdc_dev *dev;
	pid_t pid;
	int st;

	if (argc == 3 && !strcmp(argv[1], "--uri"))
		return bench_uri(argv[2]);
	if (argc == 4 && !strcmp(argv[1], "--idle")) {
		char *end;
		double s = strtod(argv[2], &end);

		if (*end || !(s >= 1 && s <= 3600)) {
			fprintf(stderr,
				"net_bench: --idle takes 1 to 3600 "
				"seconds, not '%s'\n",
				argv[2]);
			return 2;
		}
		if (!mkdtemp(dir))
			return 1;
		st = bench_idle(argv[3], dir, s, 1);
		rmdir(dir);
		if (st)
			fprintf(stderr, "net_bench: %s did not come up\n",
				argv[3]);
		return st ? 1 : 0;
	}
	if (argc != 2) {
		fprintf(stderr, "usage: net_bench PATH/TO/rdcd | --uri URI | "
				"--idle SECONDS PATH/TO/rdcd\n");
		return 2;
	}
	if (!mkdtemp(dir))
		return 1;
	pid = start_daemon(argv[1], dir, "--fast", uri, sizeof(uri));
	if (pid < 0 || rdc_open(uri, &dev)) {
		fprintf(stderr, "net_bench: cannot start %s\n", argv[1]);
		return 1;
	}
	rdc_mode_set(dev, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888, 0);
	rdc_finish(dev);
	bench_submit(dev);
	bench_rtt(dev);
	bench_draw(dev);
	bench_frames(uri);
	rdc_close(dev);
	kill(pid, SIGTERM);
	waitpid(pid, &st, 0);
	snprintf(path, sizeof(path), "%s/ready", dir);
	unlink(path);
	/* paced: a 60 Hz mode should give 60 frames per wall second */
	pid = start_daemon(argv[1], dir, "-q", uri, sizeof(uri));
	if (pid > 0 && !rdc_open(uri, &dev)) {
		rdc_mode_set(dev, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888, 0);
		bench_paced(dev, uri);
		rdc_close(dev);
	}
	if (pid > 0) {
		kill(pid, SIGTERM);
		waitpid(pid, &st, 0);
	}
	unlink(path);
	if (bench_idle(argv[1], dir, BENCH_IDLE_S, BENCH_IDLE_ROUNDS))
		fprintf(stderr, "net_bench: the idle rdcd did not come up\n");
	rmdir(dir);
	return 0;
}
