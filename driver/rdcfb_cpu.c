// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb's CPU fallback: an fb-op record drawn into VRAM by the CPU, as
 * the display processor would have drawn it, when the DP cannot take
 * commands (halted, disabled, or a client's SUBMIT half in the FIFO).
 * The caller reports the bytes written to scanout on demand.
 */
#include <linux/minmax.h>

#include "rdcfb.h"

static void rdcfb_cpu_pixel(u8 *p, u32 bytes, u32 v, bool do_xor)
{
	switch (bytes) {
	case 1:
		*p = do_xor ? *p ^ v : v;
		break;
	case 2:
		*(u16 *)p = do_xor ? *(u16 *)p ^ v : v;
		break;
	default:
		*(u32 *)p = do_xor ? *(u32 *)p ^ v : v;
		break;
	}
}

/* A pixel of an image record's row: a 1 bpp bit (MSB first) or a pixel. */
static u32 rdcfb_cpu_src(const struct rdcfb_op *op, const u32 *row, u32 x,
			 u32 bpp)
{
	u32 bit;

	if (op->arg) {
		bit = (row[x / 32] >> ((x / 8 % 4) * 8 + 7 - x % 8)) & 1;
		return bit ? op->fg : op->bg;
	}
	bit = x * bpp;
	return (row[bit / 32] >> (bit % 32)) & GENMASK(bpp - 1, 0);
}

/*
 * Draw a record with the CPU, as the DP would have: inside the op's
 * screen, which lies inside VRAM (check_var saw to it; checked again).
 */
void rdcfb_cpu_draw(struct rdc_kchip *chip, const struct rdcfb_op *op,
		    const u32 *data)
{
	u32 bpp = rdc_format_bpp(op->fmt), bytes = bpp / 8;
	u32 w = op->w, h = op->h, wpr, x, y, i;
	u8 *row;

	if (!bytes || (u64)op->stride * op->vh > rdc_hw_vram_size(chip->hw) ||
	    (u64)op->vw * bytes > op->stride || op->dx >= op->vw ||
	    op->dy >= op->vh)
		return;
	w = min(w, op->vw - op->dx);
	h = min(h, op->vh - op->dy);
	if (op->kind == RDCFB_OPK_COPY) {
		if (op->sx >= op->vw || op->sy >= op->vh)
			return;
		w = min(w, op->vw - op->sx);
		h = min(h, op->vh - op->sy);
		for (i = 0; i < h; i++) {
			/* rows in the order that never reads one written */
			y = op->dy <= op->sy ? i : h - 1 - i;
			memmove(chip->vram + (size_t)(op->dy + y) * op->stride +
					op->dx * bytes,
				chip->vram + (size_t)(op->sy + y) * op->stride +
					op->sx * bytes,
				(size_t)w * bytes);
		}
		return;
	}
	wpr = DIV_ROUND_UP(op->w * (op->arg ? 1 : bpp), RDCFB_BITS_PER_WORD);
	if (op->kind == RDCFB_OPK_IMAGE && (u64)wpr * op->h > op->words)
		return;
	for (y = 0; y < h; y++) {
		row = chip->vram + (size_t)(op->dy + y) * op->stride +
		      op->dx * bytes;
		for (x = 0; x < w; x++)
			rdcfb_cpu_pixel(row + x * bytes, bytes,
					op->kind == RDCFB_OPK_FILL ?
						op->fg :
						rdcfb_cpu_src(op,
							      data + y * wpr, x,
							      bpp),
					op->rop == RDC_ROP_XOR);
	}
}
