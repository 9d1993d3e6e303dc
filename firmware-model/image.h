/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Scratch memory of the image commands (image.c, decode.c, filter.c),
 * part of struct rdc_dp: the caller's memory, as everything of the DP.
 */
#ifndef RDC_DP_IMAGE_H
#define RDC_DP_IMAGE_H

#include "../hw-sim/rdc_regs.h"

#define RDC_DP_IMG_IN_CHUNK 256u /* stream bytes read per span */
#define RDC_DP_HIST_BINS    256u
/* DCT's strip: pixels of a band of 8 rows decoded before they are written */
#define RDC_DP_DCT_STRIP 512u

/* A canonical Huffman code (rdc_image.h) as DECODE walks it. */
struct rdc_dp_huff {
	int32_t maxcode[RDC_IMG_HUFF_LENS + 1]; /* last code of a length, or -1 */
	uint32_t mincode[RDC_IMG_HUFF_LENS + 1]; /* first code of a length */
	uint32_t valptr[RDC_IMG_HUFF_LENS + 1];	 /* its symbol's index */
	uint8_t sym[RDC_IMG_HUFF_SYMS];
};

struct rdc_dp_img {
	/* DECODE's stream reader: bytes read, not yet used */
	uint8_t in[RDC_DP_IMG_IN_CHUNK];
	/* HISTOGRAM's counts; MAP_* keep the map in map[] */
	uint32_t hist[RDC_DP_HIST_BINS];
	uint8_t map[RDC_DP_HIST_BINS];
	union {
		/* DECODE: this row's and the last row's samples */
		uint8_t dec[2][RDC_IMG_MAX_WIDTH * 3];
		/* DECODE of HUFF: a row and the code */
		struct {
			uint8_t row[RDC_IMG_MAX_WIDTH * 3];
			struct rdc_dp_huff code;
		} huff;
		/* DECODE of DCT: a strip of 8 rows, the tables, a block */
		struct {
			uint8_t strip[RDC_IMG_DCT_BLOCK][RDC_DP_DCT_STRIP * 3];
			struct rdc_dp_huff dc, ac;
			int32_t blk[RDC_IMG_DCT_QBYTES];
			uint8_t q[RDC_IMG_DCT_QBYTES];
			int32_t pred[3];
		} dct;
		/* CONVOLVE: three SRC rows, one pixel more at each end */
		uint32_t conv[3][RDC_IMG_MAX_WIDTH + 2];
	} u;
	int32_t conv_row[3]; /* SRC row held by conv[i], or -1 */
};

#endif /* RDC_DP_IMAGE_H */
