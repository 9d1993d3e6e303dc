/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The RDC-1 display processor's firmware: the command decoder, the drawing
 * state and the raster algorithms.  It reaches the chip only through the DP
 * port in hw-sim/hw.h; it never allocates (struct rdc_dp is the caller's).
 */
#ifndef RDC_DP_H
#define RDC_DP_H

#include "../hw-sim/hw.h"
#include "rdc_dp_host.h"
#include "image.h"
#include "geom3d.h"

#define RDC_DP_CHUNK	1024u /* pixels staged per span */
#define RDC_DP_RB_CHUNK 256u  /* READBACK words packed per span read */
/*
 * FILL_POLYGON / TRIANGLE scratch: vertices after Sutherland-Hodgman
 * clipping (a polygon whose clipped form would need more falls back to
 * clipping each scan line, which gives the same pixels), and the edge
 * table's capacity.  Polygon points must lie within +-RDC_POLY_COORD_LIMIT
 * (16.16 fixed point in 32 bits).
 */
#define RDC_DP_POLY_VERTS    (RDC_CMD_MAX_ARGS + 256u)
#define RDC_POLY_COORD_LIMIT 32767
/* FLOOD_FILL's span stack; when full, the fill rescans (flood.c). */
#define RDC_DP_FLOOD_STACK 4096u

/* A drawing surface in VRAM. */
struct rdc_surface {
	uint32_t base, stride;	/* bytes */
	uint32_t width, height; /* pixels */
	uint32_t format;	/* enum rdc_format */
};

/*
 * A piece of a wide stroke in 24.8 fixed point (integers are pixel
 * centres): a convex polygon of n = 3 or 4 vertices, or with n = 0 the
 * disk of centre (x[0], y[0]) and radius x[1].  y0..y1: its rows.
 */
#define RDC_DP_PEN_PIECES 256u
struct rdc_pen_piece {
	int64_t x[4], y[4];
	uint32_t n;
	int32_t y0, y1;
};

/* Clip rectangle: x0 <= x < x1, y0 <= y < y1. */
struct rdc_rect {
	int32_t x0, y0, x1, y1;
};

/* Drawing state set by the SET_* commands. */
struct rdc_dp_state {
	uint32_t fg, bg, rop;
	struct rdc_rect clip;
	struct rdc_surface dst, src;

	/* SET_PATTERN: the fill style of filled primitives (pattern.c) */
	uint32_t pat_mode; /* enum rdc_pattern_mode */
	uint8_t pat_mono[8];
	uint32_t pat_color[64];
	/*
	 * SET_PEN: width 1..RDC_PEN_MAX_WIDTH, enum rdc_cap, enum rdc_join.
	 * SET_DASH: bit (step + offset) % len of bits draws a step of a path;
	 * len 0 is solid.
	 */
	uint32_t pen_width, pen_cap, pen_join;
	uint32_t dash_bits, dash_len, dash_offset;
	/* SET_ALPHA, SET_COLORKEY, SET_AA_RAMP */
	uint32_t alpha;
	uint32_t colorkey, colorkey_on;
	uint32_t aa_ramp;
	/*
	 * SET_TRANSFORM / SET_VIEWPORT: m[row][col], signed 15.16, applied by
	 * dp_xform; xf_identity caches "xf is the identity" so the common case
	 * costs nothing
	 */
	int32_t xf[3][3];
	bool xf_identity;
	/* SET_ZBUF */
	/*
	 * SET_ZBUF: z_stride 0 = no depth surface; z_flags RDC_Z_TEST |
	 * RDC_Z_WRITE, 0 = the surface is only cleared (CLEAR_Z)
	 */
	uint32_t z_base, z_stride, z_flags;
};

enum rdc_dp_phase {
	RDC_DP_IDLE,	 /* between commands */
	RDC_DP_FETCH,	 /* header read, waiting for argument words */
	RDC_DP_READBACK, /* READBACK in progress, waiting for RDATA space */
	RDC_DP_WAIT,	 /* WAIT_VBLANK / WAIT_LINE until wait_time */
	RDC_DP_HALTED	 /* halted on error */
};

struct rdc_dp {
	struct rdc_hw *hw;
	struct rdc_dp_state st;
	/*
	 * Draw with the plain per-pixel loops only, never a fast path (set
	 * by tests, which check that both give the same pixels, cycles and
	 * counters; a chip reset keeps it).
	 */
	bool ref_paths;

	/* decoder */
	enum rdc_dp_phase phase;
	unsigned int src; /* RDC_SRC_* of the command being fetched */
	uint32_t cmd[1 + RDC_CMD_MAX_ARGS]; /* header + arguments */
	uint32_t cmd_len,
		cmd_have;   /* words expected / fetched (header incl.) */
	uint64_t cmd_start; /* time the command's header was fetched */
	uint64_t wait_time;

	/* display lists: the list being executed and the return stack */
	uint32_t list_depth; /* 0: commands come from the FIFO or ring */
	uint32_t list_pc;    /* VRAM byte address of the next list word */
	uint32_t list_ret[RDC_CALL_DEPTH];

	/* READBACK progress */
	uint32_t rb_row, rb_word, rb_words_per_row;

	/*
	 * Staging for rows whose pixels differ (blit, host data, mono, text): a
	 * row is written in pieces of at most RDC_DP_CHUNK pixels.
	 */
	uint32_t px[RDC_DP_CHUNK];
	uint8_t on[RDC_DP_CHUNK];
	/* READBACK words packed but not yet pushed to RDATA */
	uint32_t rb_buf[RDC_DP_RB_CHUNK];
	uint32_t rb_pos, rb_len;

	/*
	 * Wide strokes (pen.c): the convex pieces and disks waiting to be drawn
	 * as one union, row by row, and one row's spans of them
	 */
	struct rdc_pen_piece pen_piece[RDC_DP_PEN_PIECES];
	uint32_t pen_npieces;
	int32_t pen_span[RDC_DP_PEN_PIECES][2];

	/*
	 * AA_* (aa.c): 8-bit coverage of the pixels of the two runs a Wu line
	 * builds at once (0: pixel left alone, 255: full FG)
	 */
	uint8_t aa_cov[2][RDC_DP_CHUNK];

	/*
	 * FILL_POLYGON / TRIANGLE (poly.c): device-space points, the two
	 * Sutherland-Hodgman vertex lists (16.16; `parent` names the line the
	 * edge leaving the vertex lies on), the edge table (one bucket per clip
	 * row) and the active edge table.
	 */
	int32_t poly_xy[2 * RDC_CMD_MAX_ARGS];
	struct rdc_dp_pvert {
		int32_t x, y, parent;
	} poly_v[2][RDC_DP_POLY_VERTS];
	struct rdc_dp_edge {
		int32_t q, r, dq, dr, den, yend;
		uint16_t next;
		int16_t dir;
	} poly_e[RDC_DP_POLY_VERTS];
	uint16_t poly_et[RDC_SIZE_MAX];
	uint16_t poly_aet[RDC_DP_POLY_VERTS];

	/*
	 * FLOOD_FILL (flood.c): pending spans, and rows being scanned; TRIANGLE
	 * (tri.c) keeps a run's depths in flood_row[0]
	 */
	struct rdc_dp_fseg {
		int16_t y, xl, xr, dy;
	} flood_stk[RDC_DP_FLOOD_STACK];
	uint32_t flood_row[3][RDC_DP_CHUNK];

	/*
	 * Solid runs (lines, outlines, fills) queued for a port window;
	 * queue_spans: solid spans and columns go to the queue (span.c)
	 */
	struct rdc_port_run runs[RDC_DP_CHUNK];
	uint32_t nruns;
	bool queue_spans;

	/* DECODE, HISTOGRAM, MAP_*, CONVOLVE, THRESHOLD (image.h) */
	struct rdc_dp_img img;

	/*
	 * 3D (geom3d.c, light.c, patch.c): the state, the post-transform
	 * vertex cache, a MESH's or PATCH's triangles as indices, and the
	 * wireframe's edges (low index << 16 | high index)
	 */
	struct rdc_dp_3d g3;
	struct rdc_dp_v3 v3[RDC_MESH_MAX_VERTS];
	uint16_t v3_idx[3 * RDC_MESH_MAX_TRIS];
	uint32_t v3_edge[3 * RDC_MESH_MAX_TRIS];
	/*
	 * MESH with RDC_MESH_SCANLINE (mesh.c): the projected triangles in
	 * drawing order, chained per first row (from poly_et), and the
	 * active ones of the row being resolved
	 */
	struct rdc_dp_stri {
		int32_t x[3], y[3];
		uint32_t col[3];
		uint16_t z[3];
		uint16_t next;
		int32_t yend; /* first row below it */
	} v3_scan[RDC_MESH_SCAN_MAX_TRIS];
	uint16_t v3_act[RDC_MESH_SCAN_MAX_TRIS];
	/* MESHes culled whole by RDC_MESH_BOUNDS since the last reset */
	uint32_t meshes_culled;
};

#endif /* RDC_DP_H */
