/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What a host may read of the display processor's state: the command it
 * is running, where that came from, and the drawing state it runs with.
 * Pixel history names these for every write it records.  A copy, taken
 * between two of the DP's bus accesses; struct rdc_dp itself (dp.h)
 * stays private to firmware-model/ and its unit tests.
 */
#ifndef RDC_DP_VIEW_H
#define RDC_DP_VIEW_H

#include "../hw-sim/rdc_chip.h"
#include "../hw-sim/rdc_regs.h"

/* Where the command being run came from. */
enum rdc_dp_src {
	RDC_DP_SRC_FIFO, /* FIFO_DATA */
	RDC_DP_SRC_RING, /* the ring in VRAM */
	RDC_DP_SRC_LIST, /* a display list (CALL or JUMP) */
};

struct rdc_dp_view {
	uint32_t opcode; /* RDC_OP_* of the command being run */
	uint32_t rop, alpha, colorkey, colorkey_on, pattern, fg, bg;
	uint32_t src;	   /* enum rdc_dp_src */
	uint32_t depth;	   /* display lists nested, 0..RDC_CALL_DEPTH */
	uint32_t cmd_addr; /* RDC_DP_SRC_LIST: the command's VRAM address */
	/* RDC_DP_SRC_LIST: where each outer list resumes, outermost first */
	uint32_t calls[RDC_CALL_DEPTH];
};

/* The state of the DP connected to `hw`; false when none is. */
bool rdc_dp_view_get(const struct rdc_hw *hw, struct rdc_dp_view *s);

#endif /* RDC_DP_VIEW_H */
