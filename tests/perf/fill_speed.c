// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Host time of a full-screen 1024x768 XRGB8888 fill through the command
 * path (librdc sim: -> FIFO -> DP firmware -> bus model -> VRAM) against a
 * plain memset of the same bytes, in one run.  Timing is reported, never
 * asserted: `make speed`.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rdc.h"

#define W    1024
#define H    768
#define REPS 200

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

int main(void)
{
	static double t_rdc[REPS], t_mem[REPS];
	rdc_dev *dev;
	rdc_batch *b;
	uint64_t c0, c1;
	uint8_t *buf;
	int err, i;

	err = rdc_open("sim:", &dev);
	if (err) {
		fprintf(stderr, "rdc_open: %s\n", rdc_strerror(err));
		return 1;
	}
	err = rdc_mode_set(dev, RDC_PRESET_1024x768_60, RDC_FMT_XRGB8888, 0);
	b = rdc_batch_new();
	buf = malloc((size_t)W * H * 4);
	if (err || !b || !buf) {
		fprintf(stderr, "setup failed\n");
		return 1;
	}
	/* Let the mode latch so the fill runs against the 1024x768 surface. */
	rdc_vblank_wait(dev);
	rdc_vblank_wait(dev);
	for (i = 0; i < REPS; i++) {
		double t0;

		rdc_batch_fg(b, 0xff000000u | (uint32_t)i * 0x010203u);
		rdc_batch_fill_rect(b, 0, 0, W, H);
		t0 = now_s();
		rdc_sim_time(dev, &c0);
		err = rdc_batch_submit(dev, b);
		if (!err)
			err = rdc_finish(dev);
		rdc_sim_time(dev, &c1);
		t_rdc[i] = now_s() - t0;
		if (err) {
			fprintf(stderr, "fill: %s\n", rdc_strerror(err));
			return 1;
		}
		t0 = now_s();
		memset(buf, i, (size_t)W * H * 4);
		__asm__ volatile("" : : "r"(buf) : "memory");
		t_mem[i] = now_s() - t0;
	}
	qsort(t_rdc, REPS, sizeof(double), cmp_double);
	qsort(t_mem, REPS, sizeof(double), cmp_double);
	printf("{\"workload\":\"fullscreen_fill\",\"reps\":%d,"
	       "\"rdc_us\":%.1f,\"memset_us\":%.1f,\"ratio\":%.2f,"
	       "\"sim_cycles\":%llu}\n",
	       REPS, t_rdc[REPS / 2] * 1e6, t_mem[REPS / 2] * 1e6,
	       t_rdc[REPS / 2] / t_mem[REPS / 2],
	       (unsigned long long)(c1 - c0));
	free(buf);
	rdc_batch_free(b);
	rdc_close(dev);
	return 0;
}
