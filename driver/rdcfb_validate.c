// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * SUBMIT's gate: a command buffer from user space is walked command by
 * command before one word of it reaches the FIFO.  The display processor
 * itself survives any word (it skips or halts on a bad command), so what
 * is checked here is what makes a buffer well formed as a whole: every
 * command complete inside the buffer, an opcode the DP knows, the argument
 * count the opcode takes, surfaces and display-list addresses inside VRAM,
 * counts under their caps.  Everything the DP judges from its state at
 * execution time (coordinates against the clip, the transform) stays with
 * the DP.  A command split across two SUBMITs is refused: a buffer is
 * whole commands, so one client's half command never meets another's.
 */
#include <linux/errno.h>
#include <linux/types.h>

#include "rdcfb_validate.h"

/* Points a POLYLINE/POLYGON, FILL_POLYGON and BSPLINE take at least. */
#define RDCFB_MIN_STROKE_POINTS 2u
#define RDCFB_MIN_FILL_POINTS	3u
#define RDCFB_MIN_SPLINE_POINTS 4u
/* Argument words of SET_PATTERN by mode, SET_TRANSFORM, SET_ZBUF. */
#define RDCFB_PAT_MONO_WORDS  2u
#define RDCFB_PAT_COLOR_WORDS 64u
#define RDCFB_TRANSFORM_WORDS 9u
#define RDCFB_ZBUF_WORDS      2u
/* HOST_BLIT/MONO/TEXT: the position and size (or count) before the data */
#define RDCFB_DATA_HDR_WORDS 2u
/* The widest pixel there is, for HOST_BLIT when DST is not known here. */
#define RDCFB_MAX_BPP 32u

static u32 rdcfb_words_per_row(u32 bpp, u32 w)
{
	return (u32)(((u64)w * bpp + 31) / 32);
}

/* base, stride, wh, format: the rows lie inside VRAM. */
static bool rdcfb_surface_ok(const u32 *a, u32 vram_size)
{
	u32 fmt = a[3], w = RDC_W(a[2]), h = RDC_H(a[2]), row;

	if (fmt >= RDC_FMT_COUNT || !w || !h || w > RDC_SIZE_MAX ||
	    h > RDC_SIZE_MAX)
		return false;
	row = rdc_format_row_bytes(fmt, w);
	return a[1] >= row &&
	       (u64)a[0] + (u64)(h - 1) * a[1] + row <= vram_size;
}

/*
 * One command's arguments (len words at a).  Returns the index in a of
 * the offending word, len for "the header", or -1 if the command is good.
 * *dst_bpp follows SET_DST, so HOST_BLIT's length is checked exactly once
 * the buffer has said what it draws on.
 */
static int rdcfb_check_args(u32 hdr, const u32 *a, u32 len, u32 vram_size,
			    u32 *dst_bpp)
{
	u32 op = RDC_CMD_OP(hdr), fl = RDC_CMD_FL(hdr), wpr, lo, hi, hdr_words;

	switch (op) {
	case RDC_OP_SET_DST:
	case RDC_OP_SET_SRC:
		if (!rdcfb_surface_ok(a, vram_size))
			return 0;
		if (op == RDC_OP_SET_DST)
			*dst_bpp = rdc_format_bpp(a[3]);
		return -1;
	case RDC_OP_CALL:
	case RDC_OP_JUMP:
		return a[0] % sizeof(u32) ||
				       (u64)a[0] + sizeof(u32) > vram_size ?
			       0 :
			       -1;
	case RDC_OP_REG_WRITE:
		return a[0] % sizeof(u32) || a[0] >= RDC_REG_WINDOW ? 0 : -1;
	case RDC_OP_SET_ROP:
		return a[0] >= RDC_ROP_COUNT ? 0 : -1;
	case RDC_OP_LOAD_CLUT:
		if (len < 2 || len > RDC_CLUT_ENTRIES + 1)
			return len;
		return (u64)a[0] + len - 1 > RDC_CLUT_ENTRIES ? 0 : -1;
	case RDC_OP_SET_TRANSFORM:
		return len && len != RDCFB_TRANSFORM_WORDS ? (int)len : -1;
	case RDC_OP_SET_ZBUF:
		return len && len != RDCFB_ZBUF_WORDS ? (int)len : -1;
	case RDC_OP_SET_PATTERN:
		switch (fl) {
		case RDC_PAT_NONE:
			return len ? (int)len : -1;
		case RDC_PAT_MONO:
		case RDC_PAT_MONO_TRANSPARENT:
			return len != RDCFB_PAT_MONO_WORDS ? (int)len : -1;
		case RDC_PAT_COLOR:
			return len != RDCFB_PAT_COLOR_WORDS ? (int)len : -1;
		default:
			return len;
		}
	case RDC_OP_POLYLINE:
	case RDC_OP_POLYGON:
		return len < RDCFB_MIN_STROKE_POINTS ? (int)len : -1;
	case RDC_OP_FILL_POLYGON:
		return len < RDCFB_MIN_FILL_POINTS ? (int)len : -1;
	case RDC_OP_BSPLINE:
		return len < RDCFB_MIN_SPLINE_POINTS ? (int)len : -1;
	case RDC_OP_FLOOD_FILL:
		return len != (fl & RDC_FLOOD_BOUNDARY ? 2u : 1u) ? (int)len :
								    -1;
	case RDC_OP_MONO:
	case RDC_OP_HOST_BLIT:
		hdr_words = rdc_cmd_data_at(op, fl);
		if (len < hdr_words)
			return len;
		if (op == RDC_OP_MONO) {
			lo = rdcfb_words_per_row(1, RDC_W(a[1]));
			hi = lo;
		} else if (*dst_bpp) {
			lo = rdcfb_words_per_row(*dst_bpp, RDC_W(a[1]));
			hi = lo;
		} else {
			/* DST was set by an earlier buffer: any format */
			lo = rdcfb_words_per_row(1, RDC_W(a[1]));
			hi = rdcfb_words_per_row(RDCFB_MAX_BPP, RDC_W(a[1]));
		}
		wpr = len - hdr_words;
		return wpr < (u64)RDC_H(a[1]) * lo ||
				       wpr > (u64)RDC_H(a[1]) * hi ?
			       1 :
			       -1;
	case RDC_OP_TEXT:
		if (len < RDCFB_DATA_HDR_WORDS)
			return len;
		return len != RDCFB_DATA_HDR_WORDS + ((u64)a[1] + 3) / 4 ? 1 :
									   -1;
	default:
		return -1;
	}
}

int rdcfb_validate(const u32 *w, u32 n, u32 vram_size, u32 *bad_word)
{
	u32 dst_bpp = 0, i = 0;

	while (i < n) {
		u32 hdr = w[i], len = RDC_CMD_LEN(hdr), op = RDC_CMD_OP(hdr);
		int fixed = rdc_cmd_args(op), at;
		/* a colour carried ahead of the arguments (RDC_DRAW_FG) */
		u32 fg = (RDC_CMD_FL(hdr) & RDC_DRAW_FG) &&
			 rdc_cmd_takes_fg(op);

		if (fixed == RDC_ARGS_UNKNOWN || len > RDC_CMD_MAX_ARGS ||
		    len > n - i - 1 || len < fg ||
		    (fixed >= 0 && len - fg != (u32)fixed)) {
			*bad_word = i;
			return -EPROTO;
		}
		at = rdcfb_check_args(hdr, w + i + 1 + fg, len - fg, vram_size,
				      &dst_bpp);
		if (at >= 0) {
			/* "len" names the header: the count is what is wrong */
			*bad_word = (u32)at == len - fg ? i : i + 1 + fg + at;
			return -EPROTO;
		}
		i += 1 + len;
	}
	return 0;
}
