// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The v4l2 sink's conversion cost per frame, each format against a memcpy
 * of the same XRGB8888 frame measured in the same run, at 1024x768 and
 * 1920x1080.  One JSON object per line:
 *   {"workload":"sink_convert","format":"yuyv","width":1024,"height":768,
 *    "frames":N,"ns_per_frame":X,"memcpy_ns_per_frame":M,"ratio":X/M}
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rdc_sink.h"

#define BENCH_MIN_NS  300000000ull /* measure each case for 0.3 s at least */
#define BENCH_REPEATS 3		   /* best of, against scheduler noise */
#define NS_PER_S      1000000000ull

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static volatile uint8_t bench_sink_byte;

/* fmt -1 is the memcpy baseline.  Returns the best ns per frame. */
static double run_case(int fmt, const struct rdc_frame *f, uint8_t *dst,
		       size_t bpl, uint64_t *frames_out)
{
	double best = 0;
	uint64_t frames = 0;

	for (int r = 0; r < BENCH_REPEATS; r++) {
		uint64_t t0 = now_ns(), t, n = 0;

		do {
			if (fmt < 0)
				memcpy(dst, f->xrgb,
				       (size_t)f->width * f->height * 4);
			else
				rdc_sink_convert(fmt, dst, bpl, f);
			bench_sink_byte = dst[n % bpl];
			n++;
			t = now_ns() - t0;
		} while (t < BENCH_MIN_NS / BENCH_REPEATS);
		if (!r || (double)t / (double)n < best)
			best = (double)t / (double)n;
		frames += n;
	}
	*frames_out = frames;
	return best;
}

int main(void)
{
	static const uint32_t sizes[][2] = { { 1024, 768 }, { 1920, 1080 } };

	for (size_t i = 0; i < sizeof(sizes) / sizeof(sizes[0]); i++) {
		uint32_t w = sizes[i][0], h = sizes[i][1], seed = 0x12345678;
		uint32_t *px = malloc((size_t)w * h * 4);
		uint8_t *dst = malloc((size_t)w * h * 4);
		struct rdc_frame f = {
			.xrgb = px, .width = w, .height = h, .stride = w
		};
		uint64_t n;
		double base;

		if (!px || !dst)
			return 1;
		for (size_t k = 0; k < (size_t)w * h; k++) {
			seed ^= seed << 13;
			seed ^= seed >> 17;
			seed ^= seed << 5;
			px[k] = seed & 0x00ffffff;
		}
		memset(dst, 0, (size_t)w * h * 4);
		base = run_case(-1, &f, dst, (size_t)w * 4, &n);
		for (int fmt = 0; fmt < RDC_SINK_FMT_COUNT; fmt++) {
			double ns = run_case(fmt, &f, dst,
					     rdc_sink_fmt_bytesperline(fmt, w),
					     &n);

			printf("{\"workload\":\"sink_convert\",\"format\":\"%s\","
			       "\"width\":%u,\"height\":%u,\"frames\":%llu,"
			       "\"ns_per_frame\":%.0f,\"memcpy_ns_per_frame\":%.0f,"
			       "\"ratio\":%.2f}\n",
			       rdc_sink_fmt_name(fmt), w, h,
			       (unsigned long long)n, ns, base, ns / base);
		}
		free(px);
		free(dst);
	}
	return 0;
}
