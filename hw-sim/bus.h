/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The RDC-1 VRAM bus cost model: the one place its formulas live.
 * docs/hardware.md quotes this comment; tests assert it.
 *
 * VRAM is one bank of DRAM behind a bus RDC_BUS_BYTES wide, clocked by the
 * core clock.  All costs are in core cycles.
 *
 *   beat    one bus word: bytes [k*B, (k+1)*B) for B = RDC_BUS_BYTES.
 *   row     one DRAM page: bytes [r*P, (r+1)*P) for P = RDC_DRAM_ROW_BYTES.
 *           The bank keeps one row open: an access to another row pays
 *           RDC_T_ROW_MISS (precharge + activate) before its beat.
 *   burst   at most RDC_BUS_BURST_BEATS consecutive beats, the unit of bus
 *           arbitration.  A span of bytes [a, a+n) is split into bursts at
 *           multiples of RDC_BUS_BURST_BEATS * B.
 *
 * One burst of `beats` beats that crosses into `misses` new rows costs
 *
 *   write:  beats * T_BEAT + misses * T_ROW_MISS
 *           + (rmw_beats ? T_TURN + rmw_beats * T_BEAT : 0)
 *   read:   beats * T_BEAT + misses * T_ROW_MISS
 *
 * where rmw_beats = beats for an RMW access (a ROP that reads the
 * destination), otherwise the number of partially written beats (the
 * first and last beat of a span not aligned to B, or whose edge byte is
 * only partly written, as sub-byte pixels are): those are read, merged and
 * written back.  `misses` counts the bursts's row changes, the first one
 * included when the open row differs.  A column access (rdc_port_column)
 * is `count` one-burst spans.
 *
 * Scanout: at the start of each active line (line < V_DISPLAY) the CRTC
 * reads the line's ceil(H_DISPLAY * bpp / 8) bytes starting at
 * FB_BASE + line * FB_STRIDE as read bursts by the formula above; the bus
 * is the CRTC's for that fetch window [line_start, line_start + cost).  A
 * DP burst that would overlap a fetch window waits until the window ends
 * (the wait counts as stall cycles).  Outside active lines (vertical
 * blanking) the DP has the bus to itself, so drawing in vblank is faster.
 * The fetch leaves its last row open.  A fetch that finds the previous
 * one still on the bus (a line that takes longer to read than to show)
 * starts when it ends; lines whose bytes would leave VRAM are not fetched
 * (they show black) and take no bus time.
 *
 * Command fetch: a FIFO word costs RDC_T_FIFO_WORD; ring words are VRAM
 * reads by the formula.  Each command costs RDC_T_DECODE once it is fetched.
 */
#ifndef RDC_BUS_H
#define RDC_BUS_H

#define RDC_BUS_BYTES 8u /* 64-bit bus */
#define RDC_BUS_BURST_BEATS 16u /* 128 bytes a burst */
#define RDC_DRAM_ROW_BYTES 2048u
#define RDC_T_BEAT 1u
#define RDC_T_ROW_MISS 6u
#define RDC_T_TURN 2u /* read-to-write turnaround of an RMW burst */
#define RDC_T_FIFO_WORD 1u
#define RDC_T_DECODE 4u

#endif /* RDC_BUS_H */
