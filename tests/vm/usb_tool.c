// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * usb_tool: what the usb: VM tests (tests/vm/tests/usb-*.sh) do through
 * librdc that rdcctl does not.
 *
 *   usb_tool submit URI   one long rdc_submit (small fills); prints
 *                         "submitting" first, so the test can unplug the
 *                         device meanwhile; exit 0 if the submit ends
 *                         with RDC_E_GONE and every later call returns
 *                         RDC_E_GONE at once
 *   usb_tool frames URI   a frame subscription (RLE), time moved by
 *                         vblank waits; prints "frames flowing" after a
 *                         few; exit 0 if it ends with RDC_E_GONE as above
 *   usb_tool irq URI      interrupt events (vblank) arrive through
 *                         rdc_event_next; exit 0 if three did, in order
 *
 * Times are printed as "# usb ..." lines: figures, never conditions.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rdc.h"

#define SUBMIT_WORDS   (16u << 20) /* 64 MB of commands: long on any link */
#define FRAMES_FLOWING 5
#define LOOP_MAX       100000
#define IRQ_WANT       3
#define IRQ_TRIES      60

static double now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

/* After RDC_E_GONE: every call answers RDC_E_GONE, and quickly. */
static int later_calls(rdc_dev *dev)
{
	uint32_t v, w = RDC_CMD(RDC_OP_NOP, 0, 0);
	struct rdc_event ev;
	uint8_t b[64];
	double t = now_ms();
	int r[6], bad = 0;

	r[0] = rdc_reg_read(dev, RDC_REG_STATUS, &v);
	r[1] = rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, 0);
	r[2] = rdc_submit(dev, &w, 1);
	r[3] = rdc_finish(dev);
	r[4] = rdc_vram_read(dev, 0, b, sizeof(b));
	r[5] = rdc_event_next(dev, &ev, NULL, 0, 5000);
	for (int i = 0; i < 6; i++) {
		if (r[i] != RDC_E_GONE) {
			printf("later call %d: %s, not \"device gone\"\n", i,
			       rdc_strerror(r[i]));
			bad = 1;
		}
	}
	printf("later calls: %s\n",
	       bad ? "not all gone" : "all \"device gone\"");
	printf("# usb six later calls took %.1f ms\n", now_ms() - t);
	return bad;
}

static int cmd_submit(rdc_dev *dev)
{
	uint32_t *w = malloc(SUBMIT_WORDS * sizeof(*w));
	double t;
	int ret;

	if (!w)
		return 2;
	/* 8x8 fills: little work per word, so the link is what is long */
	for (uint32_t i = 0; i + 4 <= SUBMIT_WORDS; i += 4) {
		w[i] = RDC_CMD(RDC_OP_FILL_RECT, 0, 2);
		w[i + 1] = RDC_XY((i / 4) % 600, (i / 4 / 600) % 400);
		w[i + 2] = RDC_WH(8, 8);
		w[i + 3] = RDC_CMD(RDC_OP_NOP, 0, 0);
	}
	printf("submitting %u words\n", SUBMIT_WORDS);
	fflush(stdout);
	t = now_ms();
	ret = rdc_submit(dev, w, SUBMIT_WORDS);
	free(w);
	printf("submit: %s\n", ret ? rdc_strerror(ret) : "finished");
	printf("# usb submit ended %.1f ms after it began\n", now_ms() - t);
	if (ret != RDC_E_GONE)
		return 1;
	return later_calls(dev);
}

static int cmd_frames(rdc_dev *dev)
{
	static uint32_t px[2048 * 2048];
	unsigned int frames = 0;
	int ret = rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_XRGB8888, 0);

	if (!ret)
		ret = rdc_subscribe(dev, RDC_EVENT_FRAME, 1, RDC_FRAME_RLE);
	for (int i = 0; !ret && i < LOOP_MAX; i++) {
		struct rdc_event ev;

		ret = rdc_vblank_wait(dev);
		while (!ret) {
			ret = rdc_event_next(dev, &ev, px, RDC_ARRAY_SIZE(px),
					     0);
			if (!ret && ev.type == RDC_EVENT_FRAME &&
			    ++frames == FRAMES_FLOWING) {
				printf("frames flowing (%ux%u)\n", ev.width,
				       ev.height);
				fflush(stdout);
			}
		}
		if (ret == RDC_E_TIMEOUT)
			ret = 0;
	}
	printf("subscription: %s after %u frames\n",
	       ret ? rdc_strerror(ret) : "still running", frames);
	if (ret != RDC_E_GONE)
		return 1;
	return later_calls(dev);
}

static int cmd_irq(rdc_dev *dev)
{
	unsigned int got = 0;
	uint64_t last = 0;
	int ret = rdc_mode_set(dev, RDC_PRESET_640x480_60, RDC_FMT_XRGB8888, 0);

	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK);
	if (!ret)
		ret = rdc_subscribe(dev, RDC_EVENT_IRQ, 0, RDC_FRAME_RAW);
	for (int i = 0; !ret && i < IRQ_TRIES && got < IRQ_WANT; i++) {
		struct rdc_event ev;

		ret = rdc_vblank_wait(dev);
		while (!ret && got < IRQ_WANT) {
			ret = rdc_event_next(dev, &ev, NULL, 0, 200);
			if (ret)
				break;
			if (ev.type != RDC_EVENT_IRQ)
				continue;
			printf("irq 0x%x at %llu\n", ev.irq,
			       (unsigned long long)ev.time);
			if ((ev.irq & RDC_IRQ_VBLANK) && ev.time >= last)
				got++;
			last = ev.time;
			/* status bits are W1C: a new event needs a new edge */
			ret = rdc_reg_write(dev, RDC_REG_IRQ_STATUS, ev.irq);
		}
		if (ret == RDC_E_TIMEOUT)
			ret = 0;
	}
	if (ret)
		printf("irq: %s\n", rdc_strerror(ret));
	printf("%u vblank events in order\n", got);
	return got >= IRQ_WANT ? 0 : 1;
}

int main(int argc, char **argv)
{
	rdc_dev *dev;
	int ret;

	setvbuf(stdout, NULL, _IOLBF, 0);
	if (argc != 3) {
		fprintf(stderr, "usage: usb_tool submit|frames|irq URI\n");
		return 2;
	}
	ret = rdc_open(argv[2], &dev);
	if (ret) {
		printf("cannot open %s: %s\n", argv[2], rdc_strerror(ret));
		return 2;
	}
	if (!strcmp(argv[1], "submit"))
		ret = cmd_submit(dev);
	else if (!strcmp(argv[1], "frames"))
		ret = cmd_frames(dev);
	else if (!strcmp(argv[1], "irq"))
		ret = cmd_irq(dev);
	else
		ret = 2;
	rdc_close(dev);
	return ret;
}
