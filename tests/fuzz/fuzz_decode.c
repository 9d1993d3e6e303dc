// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * libFuzzer target for DECODE (firmware-model/decode.c): every codec's
 * bit stream on the chip core itself (hw-sim and the DP, no library in
 * between), 256 KiB of VRAM.
 *
 * Input: a mode byte, then the stream.  Mode bit 7 clear: the bytes are
 * a payload, and the target writes a valid header for it: codec 1 +
 * (mode & 7) % 6 (RLE, DPCM, BTC, HUFF, DPCMQ, DCT), channels 3 if bit 3
 * else 1, width 1 + the next byte % 64 and height 1 + the one after % 32
 * (so the fuzzer spends its time in the payload's decoders); set: the
 * bytes are the whole stream, header included.  Bit 4 picks DST's format
 * (XRGB8888 or I8), bit 5 a clip rectangle.  The stream lies at the end
 * of VRAM with DECODE's size reaching exactly there, so a read past it
 * leaves the allocation (ASan's business).
 *
 * Checked: DECODE ends with no error, RDC_ERR_DATA or RDC_ERR_ARG, never
 * by running away; no byte of VRAM outside the image's rectangle on DST
 * changes, and none at all when it fails; the DP then runs a FENCE.
 * Seeds (seeds/decode): librdc's streams of small pictures, every codec.
 */
#define RDC_CORE_INTERNAL /* the fuzz target reaches into the core: hw.h, dp.h */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hw.h"
#include "dp.h"

#define FZ_VRAM	   (256u << 10)
#define FZ_DST_W   128u
#define FZ_DST_H   64u
#define FZ_STEP	   100000u
#define FZ_LIMIT   2000u /* steps: 200 M cycles, far beyond any stream here */
#define FZ_MAX_LEN (FZ_VRAM - FZ_DST_W * FZ_DST_H * 4 - 64)

#define fz_assert(c) \
	do { \
		if (!(c)) { \
			fprintf(stderr, "fuzz_decode: %s:%d: %s\n", __FILE__, \
				__LINE__, #c); \
			abort(); \
		} \
	} while (0)

struct fz {
	struct rdc_hw hw;
	struct rdc_dp dp;
	uint8_t *vram, *save;
	uint32_t *frame[2];
};

static struct fz *fz;

static void fz_run(void)
{
	uint32_t st, i;

	for (i = 0; i < FZ_LIMIT; i++) {
		st = rdc_hw_read(&fz->hw, RDC_REG_STATUS);
		if ((st & RDC_STATUS_FIFO_EMPTY) &&
		    !(st & RDC_STATUS_IDLE_MASK))
			return;
		if (st & RDC_STATUS_DP_HALTED)
			return;
		rdc_hw_run_until(&fz->hw, fz->hw.now + FZ_STEP);
	}
	fz_assert(!"the DP ran away");
}

static void fz_cmd(uint32_t op, uint32_t n, const uint32_t *a)
{
	uint32_t i;

	rdc_hw_write(&fz->hw, RDC_REG_FIFO_DATA, RDC_CMD(op, 0, n));
	for (i = 0; i < n; i++)
		rdc_hw_write(&fz->hw, RDC_REG_FIFO_DATA, a[i]);
	fz_run();
}

static void fz_init(void)
{
	struct rdc_hw_config cfg = { .vram_size = FZ_VRAM };

	fz = calloc(1, sizeof(*fz));
	fz_assert(fz);
	fz->vram = calloc(1, FZ_VRAM);
	fz->save = malloc(FZ_VRAM);
	fz->frame[0] = calloc(640 * 480, 4);
	fz->frame[1] = calloc(640 * 480, 4);
	fz_assert(fz->vram && fz->save && fz->frame[0] && fz->frame[1]);
	rdc_hw_init(&fz->hw, &cfg, fz->vram, fz->frame[0], fz->frame[1],
		    640 * 480);
	rdc_dp_init(&fz->dp, &fz->hw);
	/* no scanout: the DP alone on the bus */
	rdc_hw_write(&fz->hw, RDC_REG_CONTROL, RDC_CONTROL_DP_EN);
	rdc_hw_run_until(&fz->hw, FZ_STEP);
}

static void put16(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static void put32(uint8_t *p, uint32_t v)
{
	put16(p, v);
	put16(p + 2, v >> 16);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	uint32_t mode, fmt, bpp, stride, at, len, a[4], err, i, x, y;
	uint32_t w, h, x0 = 3, y0 = 2;
	uint8_t *st;

	if (!fz)
		fz_init();
	if (size < 1)
		return 0;
	mode = data[0];
	data++;
	size--;
	fmt = mode & 0x10 ? RDC_FMT_I8 : RDC_FMT_XRGB8888;
	bpp = fmt == RDC_FMT_I8 ? 1 : 4;
	stride = FZ_DST_W * bpp;
	if (mode & 0x80) {
		if (size > FZ_MAX_LEN)
			return 0;
		len = (uint32_t)size;
	} else {
		if (size < 2 || size - 2 > FZ_MAX_LEN - RDC_IMG_HDR_BYTES)
			return 0;
		len = (uint32_t)size - 2 + RDC_IMG_HDR_BYTES;
	}
	at = FZ_VRAM - len;
	memset(fz->vram, 0x5a, FZ_VRAM);
	st = fz->vram + at;
	if (mode & 0x80) {
		memcpy(st, data, len);
	} else {
		memset(st, 0, RDC_IMG_HDR_BYTES);
		put32(st + RDC_IMG_OFF_MAGIC, RDC_IMG_MAGIC);
		st[RDC_IMG_OFF_CODEC] = (uint8_t)(RDC_IMG_RLE + (mode & 7) % 6);
		st[RDC_IMG_OFF_CHANNELS] = mode & 8 ? 3 : 1;
		put16(st + RDC_IMG_OFF_WIDTH, 1 + data[0] % 64);
		put16(st + RDC_IMG_OFF_HEIGHT, 1 + data[1] % 32);
		put32(st + RDC_IMG_OFF_PAYLOAD, len - RDC_IMG_HDR_BYTES);
		memcpy(st + RDC_IMG_HDR_BYTES, data + 2, size - 2);
	}
	/* the rectangle the header names (none if there is no header) */
	w = len < RDC_IMG_HDR_BYTES ?
		    0 :
		    st[RDC_IMG_OFF_WIDTH] | st[RDC_IMG_OFF_WIDTH + 1] << 8;
	h = len < RDC_IMG_HDR_BYTES ?
		    0 :
		    st[RDC_IMG_OFF_HEIGHT] | st[RDC_IMG_OFF_HEIGHT + 1] << 8;
	a[0] = 0;
	a[1] = stride;
	a[2] = RDC_WH(FZ_DST_W, FZ_DST_H);
	a[3] = fmt;
	fz_cmd(RDC_OP_SET_DST, 4, a);
	a[0] = RDC_XY(0, 0);
	a[1] = mode & 0x20 ? RDC_XY(40, 20) : RDC_XY(FZ_DST_W, FZ_DST_H);
	fz_cmd(RDC_OP_SET_CLIP, 2, a);
	rdc_hw_write(&fz->hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	memcpy(fz->save, fz->vram, FZ_VRAM);
	a[0] = at;
	a[1] = len;
	a[2] = RDC_XY((int32_t)x0, (int32_t)y0);
	fz_cmd(RDC_OP_DECODE, 3, a);
	err = rdc_hw_read(&fz->hw, RDC_REG_ERR_CODE);
	fz_assert(err == RDC_ERR_NONE || err == RDC_ERR_DATA ||
		  err == RDC_ERR_ARG);
	for (i = 0; i < FZ_VRAM; i++) {
		if (fz->vram[i] == fz->save[i])
			continue;
		fz_assert(err == RDC_ERR_NONE);
		fz_assert(i < stride * FZ_DST_H);
		y = i / stride;
		x = i % stride / bpp;
		fz_assert(x >= x0 && x < x0 + w && y >= y0 && y < y0 + h);
	}
	/* the DP goes on */
	rdc_hw_write(&fz->hw, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL);
	a[0] = (uint32_t)size;
	fz_cmd(RDC_OP_FENCE, 1, a);
	fz_assert(rdc_hw_read(&fz->hw, RDC_REG_FENCE) == (uint32_t)size);
	return 0;
}
