/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The DisplayLink personality of the RDC-1 (docs/usb.md, "DisplayLink
 * personality"): a streaming decoder of the bulk command stream Linux's
 * udl DRM driver sends, turned into RDC-1 display-processor commands, and
 * the EDID the device answers with.  No USB here and no allocation: the
 * caller owns the state and takes the command words through a callback,
 * so the decoder runs the same in rdcd (userspace/rdcd/udl.c) and in the
 * unit tests (tests/unit/test_udl_decode.c).
 *
 * The stream: every command starts with 0xAF; an 0xAF followed by
 * another is a no-op (udl pads buffers with 0xAF).  Commands may be split
 * anywhere across transfers; the decoder keeps at most one partial command
 * (RDC_UDL_CMD_MAX bytes).  Device addresses are 24-bit byte addresses
 * into the RDC-1's VRAM from 0, bounded by the window (VRAM, at most 16
 * MiB): nothing is ever drawn outside it.
 *
 *   AF 20 reg val              register write (mode, blank, base)
 *   AF 68 addr[3] n px[n]      16 bpp raw write (n 0 = 256, px big-endian)
 *   AF 69 addr[3] n {c px}..   16 bpp run lengths until n pixels (c 0 = 256)
 *   AF 6A src[3] n dst[3]      16 bpp copy of n pixels
 *   AF 6B addr[3] n {r px[r] [rep]}..
 *                              16 bpp raw spans, each followed (unless the
 *                              n pixels are complete) by a count of further
 *                              copies of its last pixel (udl's only pixel
 *                              command in 6.1 and 6.12)
 *   AF 60..63                  the 8 bpp forms: decoded and skipped (the
 *                              8 bpp segment serves 24 bpp modes, which
 *                              this device does not offer)
 */
#ifndef RDC_UDL_DECODE_H
#define RDC_UDL_DECODE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rdc_chip.h"

/* DisplayLink device addresses are 24 bits wide. */
#define RDC_UDL_ADDR_SPACE (1u << 24)
/*
 * The longest command: RLX16 (6 header bytes) whose 256 pixels come as
 * 255 spans of one raw pixel and a zero repeat count (4 bytes each), then
 * a span that declares 256 raw pixels (count byte 0) and so carries them
 * all although one is drawn: 6 + 255 * 4 + 1 + 512 = 1539 bytes.
 */
#define RDC_UDL_CMD_MAX 1539u
/*
 * The DP surface the device's memory is drawn through: VRAM from 0 as
 * rows of RDC_UDL_ROW_BYTES, so a linear address a is pixel
 * (a % ROW_BYTES / 2, a / ROW_BYTES) and spans split at row ends.
 */
#define RDC_UDL_ROW_BYTES  4096u
#define RDC_UDL_ROW_PIXELS (RDC_UDL_ROW_BYTES / 2u)
/* Runs shorter than this are drawn with the raw pixels around them. */
#define RDC_UDL_RUN_FILL_MIN 8u
/* Two blocks: the base EDID and one CTA-861 extension. */
#define RDC_UDL_EDID_SIZE 256u

/* DisplayLink registers udl writes (AF 20 reg val). */
#define RDC_UDL_REG_DEPTH  0x00 /* 0: 16 bpp; 1: 24 bpp (not offered) */
#define RDC_UDL_REG_XDS	   0x01 /* the timing counters, LFSR16, big-endian */
#define RDC_UDL_REG_XDE	   0x03
#define RDC_UDL_REG_YDS	   0x05
#define RDC_UDL_REG_YDE	   0x07
#define RDC_UDL_REG_XEC	   0x09
#define RDC_UDL_REG_HSS	   0x0b
#define RDC_UDL_REG_HSE	   0x0d
#define RDC_UDL_REG_HPIX   0x0f /* plain, big-endian */
#define RDC_UDL_REG_YEC	   0x11
#define RDC_UDL_REG_VSS	   0x13
#define RDC_UDL_REG_VSE	   0x15
#define RDC_UDL_REG_VPIX   0x17 /* plain, big-endian */
#define RDC_UDL_REG_CLOCK  0x1b /* pixel clock / 5 kHz, little-endian */
#define RDC_UDL_REG_BLANK  0x1f /* 0 on; 1, 3, 5, 7 blanked */
#define RDC_UDL_REG_BASE16 0x20 /* 24-bit big-endian: 0x20..0x22 */
#define RDC_UDL_REG_BASE8  0x26 /* 0x26..0x28 */
#define RDC_UDL_REG_LOCK   0xff /* 0x00 lock, 0xff unlock: apply */

/* The vendor control requests udl makes (bmRequestType 0x40 / 0xc0). */
#define RDC_UDL_REQ_EDID    0x02 /* IN 2 bytes: status 0, EDID byte */
#define RDC_UDL_REQ_CHANNEL 0x12 /* OUT 16 bytes: select a channel */
/* Ours, not DisplayLink's: IN, RDC_UDL_STATS_SIZE bytes (docs/usb.md). */
#define RDC_UDL_REQ_STATS 0x52

/* What went wrong last (stats.last_error). */
enum rdc_udl_err {
	RDC_UDL_OK = 0,
	RDC_UDL_E_SYNC = 1,   /* bytes that do not start with 0xAF: skipped */
	RDC_UDL_E_OPCODE = 2, /* unknown command after 0xAF: both skipped */
	RDC_UDL_E_ADDR = 3,   /* odd, or outside the window: clipped */
	RDC_UDL_E_LENGTH = 4, /* spans past the command's pixel count */
	RDC_UDL_E_MODE = 5,   /* timing the CRTC cannot scan: ignored */
	RDC_UDL_E_DEPTH = 6,  /* 24 bpp or 8 bpp commands: not offered */
};

struct rdc_udl_stats {
	uint64_t bytes; /* stream bytes fed */
	uint64_t cmds;	/* commands decoded (no-ops excluded) */
	uint64_t noops; /* 0xAF padding bytes */
	uint64_t reg_writes;
	uint64_t px_raw;   /* pixels written as raw pixels */
	uint64_t px_run;   /* ... as runs (fills) */
	uint64_t px_copy;  /* ... by copies (blits) */
	uint64_t dp_words; /* display-processor words produced */
	uint64_t modes;	   /* timings programmed */
	uint64_t errors;
	uint32_t last_error; /* enum rdc_udl_err */
	uint64_t error_at;   /* stream offset of the command at fault */
};

/* Where the decoded work goes. */
struct rdc_udl_out {
	/* display-processor command words, in order */
	void (*words)(void *ctx, const uint32_t *w, size_t n);
	/* the blank register changed at an unlock: dark (BL_EN low) or lit */
	void (*blank)(void *ctx, bool dark);
	void *ctx;
};

struct rdc_udl {
	struct rdc_udl_out out;
	uint32_t window; /* bytes of device memory (VRAM from 0) */
	uint32_t rows;	 /* of the DP surface */
	uint8_t reg[256];
	bool locked;
	bool dark;
	bool have_mode;
	struct rdc_timing mode; /* last programmed */
	uint32_t fb_base, fb_stride;
	uint32_t fg;
	bool fg_valid;
	/* a partial command carried over to the next transfer */
	uint8_t part[RDC_UDL_CMD_MAX];
	size_t part_len;
	bool in_garbage; /* inside a run of bytes that are not 0xAF */
	/* raw pixels of the current command waiting to be drawn */
	uint32_t span_addr, span_n;
	uint16_t span[256]; /* a command draws at most 256 */
	struct rdc_udl_stats st;
};

/*
 * Start a device over `vram_size` bytes of VRAM: registers cleared,
 * unlocked, lit.  Emits the display-processor state the decoder relies on
 * (DST and SRC surfaces, clip, ROP COPY, opaque, no key, no pattern, no
 * transform, no depth buffer): call it at the start of every session.
 */
void rdc_udl_init(struct rdc_udl *u, uint32_t vram_size,
		  const struct rdc_udl_out *out);
/* Decode n more stream bytes (any split of the stream gives the same). */
void rdc_udl_feed(struct rdc_udl *u, const uint8_t *p, size_t n);

/*
 * The count c that udl's LFSR16 encoding turned into `value` (the 16-bit
 * register starts at 0xffff and shifts c times), or -1 if no count below
 * 65535 gives it.
 */
int32_t rdc_udl_lfsr16_count(uint16_t value);

/*
 * The timing programmed by the registers as written (the inverse of
 * udl_set_vid_cmds): 0, or -1 if they do not describe one (the counts
 * are not LFSR values, display sizes disagree, a sync ends before it
 * starts).  The clock is the register's 5 kHz steps; CRTC flags are 0.
 */
int rdc_udl_decode_timing(const uint8_t reg[256], struct rdc_timing *t);

/*
 * The EDID of the device: a base block and a CTA-861 extension whose
 * detailed timings are the RDC-1's mode presets that fit `vram_size`
 * (at 16 bpp) and udl's limits (640x480 to 2048x2048), `preferred`
 * first (any other value: the largest that fits first), then the others
 * in preset order.
 * No established or standard timings, no range limits and no continuous
 * frequency flag, so a host offers these modes and no other.  Returns
 * RDC_UDL_EDID_SIZE.
 */
size_t rdc_udl_edid(uint8_t out[RDC_UDL_EDID_SIZE], uint32_t preferred,
		    uint32_t vram_size);

/* The answer to RDC_UDL_REQ_STATS: little-endian u64 fields of stats. */
#define RDC_UDL_STATS_SIZE 96u
void rdc_udl_stats_encode(uint8_t out[RDC_UDL_STATS_SIZE],
			  const struct rdc_udl_stats *s);

#endif /* RDC_UDL_DECODE_H */
