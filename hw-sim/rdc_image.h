/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * RDC-1 compressed image streams, as the DECODE command reads them from
 * VRAM and librdc's rdc_image_encode() writes them.  Included by
 * rdc_regs.h; docs/commands.md ("Image streams") is the prose reference.
 *
 * A stream is a 16-byte header and a payload, little-endian:
 *
 *   0   u32  RDC_IMG_MAGIC
 *   4   u8   codec (enum rdc_img_codec)
 *   5   u8   channels: 1 (grey or CLUT index) or 3 (R, G, B)
 *   6   u16  0
 *   8   u16  width  1..RDC_IMG_MAX_WIDTH
 *   10  u16  height 1..RDC_IMG_MAX_HEIGHT
 *   12  u32  payload bytes that follow the header
 *
 * Samples are 8 bits, a pixel is `channels` samples (R, G, B in that
 * order), pixels in raster order.
 *
 * RLE (PackBits on pixels): a control byte c, then for c < 128 a literal
 * of c + 1 pixels, for c >= 128 one pixel repeated c - 126 (2..129) times.
 * Runs and literals may cross rows; they must end exactly at the last
 * pixel, and the payload exactly there.
 *
 * DPCM (lossless predictive coding): a bit stream, most significant bit of
 * each byte first.  Each row starts with RDC_IMG_DPCM_KBITS bits k (the
 * Rice parameter, 0..7), then codes for its samples in order (pixel by
 * pixel, channel by channel).  A sample v is predicted from its neighbours
 * in the same channel, a left, b above, c above-left:
 *   row 0: a (128 for the first pixel); column 0: b; else the median
 *   predictor: min(a, b) if c >= max(a, b), max(a, b) if c <= min(a, b),
 *   else a + b - c.
 * The residual e = (v - P) mod 256 as a signed byte, zigzagged to
 * m = 2e (e >= 0) or -2e - 1 (e < 0), is coded as q = m >> k one bits, a
 * zero bit and the k low bits of m when q < RDC_IMG_DPCM_ESCAPE; else as
 * RDC_IMG_DPCM_ESCAPE one bits and the 8 bits of m.  The decoder takes
 * v = (P + e) mod 256.  The payload is the bits rounded up to a byte.
 *
 * BTC (block truncation coding, lossy): 4x4 blocks in raster order,
 * ceil(w / 4) x ceil(h / 4) of them (pixels past the image's edge are
 * not stored); per block and channel 4 bytes: low level, high level, a
 * 16-bit bitmap (bit 4 * row + column, 1 = high).  Payload: exactly
 * blocks * channels * 4 bytes.
 *
 * HUFF (canonical Huffman coding of the samples, lossless): a code table,
 * then a bit stream, most significant bit of each byte first.  The table
 * is RDC_IMG_HUFF_LENS bytes: n[l], the number of codes of length l for
 * l = 1..16, then N = n[1] + ... + n[16] (1..256) symbol bytes in the
 * order of their codes.  Codes are canonical (as JPEG's DHT): the first
 * code of length 1 is 0; each next code of the same length is one more,
 * and the first of length l + 1 is (last of length l + 1) << 1; a table
 * whose codes would not fit their lengths is bad.  The bit stream holds a
 * code per sample in raster order, the last byte zero-padded; a bit
 * pattern that is no code, or bytes after the last sample, are bad.
 *
 * DPCMQ (lossy predictive coding: DPCM with a uniform quantiser): one
 * byte, the step s (1..255), then a bit stream as DPCM's: per row k, per
 * sample a code of m, the zigzag of a quantised residual q, in DPCM's
 * Rice code but with RDC_IMG_DPCMQ_MBITS bits after an escape (m <=
 * 511).  The prediction P is DPCM's median predictor on the decoded
 * samples, and a sample decodes to v = min(max(P + q * s, 0), 255).
 * librdc's encoder picks q = the residual v - P divided by s, rounded to
 * nearest (halves toward 0): every sample within s / 2 of the
 * original; s = 1 is lossless.
 *
 * DCT (transform coding, lossy, as JPEG's baseline): 8x8 blocks in
 * raster order, ceil(w / 8) x ceil(h / 8) of them, each a block per
 * channel in channel order (no colour transform: R, G, B as they are).
 * The payload: a quantisation table of 64 bytes (1..255) in zigzag order,
 * two Huffman tables as HUFF's (DC, then AC), then a bit stream (MSB
 * first, the last byte zero-padded) with per block JPEG's codes: the DC
 * difference from the channel's last block (0 at the start) as a
 * category s (0..11, the DC table's symbol) and s bits, and AC
 * coefficients 1..63 in zigzag order as symbols r << 4 | s (a run r of
 * zeros, then a coefficient of s = 1..10 bits), 0xf0 for 16 zeros and
 * 0x00 for "the rest are zero".  s bits v are the value v if its top bit
 * is set, else v - 2^s + 1.  A quantised DC beyond +-RDC_IMG_DCT_DC_MAX,
 * a symbol of another form, coefficients past 63 or bytes after the last
 * block are bad.  A coefficient is its value times its table entry,
 * limited to -RDC_IMG_DCT_COEF_MAX - 1..RDC_IMG_DCT_COEF_MAX; the
 * samples are the 2D inverse DCT
 *   f(x, y) = 1/4 sum_u sum_v C(u) C(v) F(u, v) cos((2x + 1) u pi / 16)
 *             cos((2y + 1) v pi / 16),  C(0) = 1 / sqrt(2), else 1,
 * plus 128, rounded and limited to 0..255.  The DP computes it in
 * integers (docs/commands.md says how and how close it comes).
 */
#ifndef RDC_IMAGE_H
#define RDC_IMAGE_H

#define RDC_IMG_MAGIC		0x49434452u /* "RDCI" little-endian */
#define RDC_IMG_HDR_BYTES	16u
#define RDC_IMG_MAX_WIDTH	4096u /* also CONVOLVE's widest rectangle */
#define RDC_IMG_MAX_HEIGHT	16384u
#define RDC_IMG_DPCM_KBITS	3u
#define RDC_IMG_DPCM_KMAX	7u
#define RDC_IMG_DPCM_ESCAPE	16u
#define RDC_IMG_BTC_BLOCK	4u
#define RDC_IMG_BTC_BYTES	4u /* per block and channel */
#define RDC_IMG_RLE_LITERAL_MAX 128u
#define RDC_IMG_RLE_RUN_MAX	129u
#define RDC_IMG_HUFF_LENS	16u /* longest code; the table's counts */
#define RDC_IMG_HUFF_SYMS	256u
#define RDC_IMG_DPCMQ_MBITS	9u /* an escaped m of DPCMQ */
#define RDC_IMG_DPCMQ_MMAX	511u
#define RDC_IMG_DCT_BLOCK	8u
#define RDC_IMG_DCT_QBYTES	64u /* the quantisation table */
#define RDC_IMG_DCT_DC_MAX	2047u
#define RDC_IMG_DCT_COEF_MAX	2047 /* a coefficient after quantisation */
#define RDC_IMG_DCT_EOB		0x00u
#define RDC_IMG_DCT_ZRL		0xf0u

enum rdc_img_codec {
	RDC_IMG_RLE = 1,
	RDC_IMG_DPCM = 2,
	RDC_IMG_BTC = 3,
	RDC_IMG_HUFF = 4,
	RDC_IMG_DPCMQ = 5,
	RDC_IMG_DCT = 6,
	RDC_IMG_CODEC_END
};

/* Header field offsets */
#define RDC_IMG_OFF_MAGIC    0
#define RDC_IMG_OFF_CODEC    4
#define RDC_IMG_OFF_CHANNELS 5
#define RDC_IMG_OFF_RESERVED 6
#define RDC_IMG_OFF_WIDTH    8
#define RDC_IMG_OFF_HEIGHT   10
#define RDC_IMG_OFF_PAYLOAD  12

#endif /* RDC_IMAGE_H */
