/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The display processor as its host sees it: the memory it takes, how it
 * is connected to the chip, and what a host may read of its state (the
 * command it is running, where that came from, and the drawing state it
 * runs with: pixel history names these for every write it records).
 * struct rdc_dp itself (dp.h) stays private to firmware-model/ and its
 * unit tests.
 */
#ifndef RDC_DP_HOST_H
#define RDC_DP_HOST_H

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
	/* MESHes culled whole by RDC_MESH_BOUNDS since the last reset */
	uint32_t meshes_culled;
};

struct rdc_dp;

/* Bytes of memory struct rdc_dp takes: the host allocates them. */
size_t rdc_dp_size(void);
/* Initialise the DP in `dp` and connect it to the chip (rdc_hw_set_dp). */
void rdc_dp_init(struct rdc_dp *dp, struct rdc_hw *hw);

/* The state of the DP connected to `hw`, a copy; false when none is. */
bool rdc_dp_view_get(const struct rdc_hw *hw, struct rdc_dp_view *s);

/* The built-in 8x16 font, code page 437 order, bit 7 leftmost. */
extern const uint8_t rdc_font8x16[256 * 16];

#endif /* RDC_DP_HOST_H */
