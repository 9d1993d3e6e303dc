/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * RDC-1 register map and command encodings.
 *
 * The one copy, used by hw-sim, the display-processor firmware, librdc, the
 * daemon and the kernel driver.  Registers are 32 bits wide at byte offsets
 * (an MMIO window of RDC_REG_WINDOW bytes).  Access is noted per register:
 *   R    read only (writes are ignored and logged as a host error)
 *   RW   read/write
 *   W    write only (reads return 0)
 *   W1C  read; writing 1 to a bit clears it
 * "latched" registers are shadows: the CRTC copies them to its working set
 * at the start of vertical blanking, so a page flip never tears.
 *
 * docs/hardware.md is the prose reference; hw-sim/bus.h holds the cycle
 * model's formulas.
 */
#ifndef RDC_REGS_H
#define RDC_REGS_H

#include "rdc_bits.h"

/* the map is laid out by hand, a bit under its register */
/* clang-format off */

#define RDC_ID_VALUE 0x31434452u /* "RDC1" little-endian */
/*
 * 1.1 added the ARGB8888 cursor (CURSOR_CTRL) and the gamma of direct
 * colour (CONTROL.GAMMA_EN); on 1.0 CURSOR_CTRL is a hole in the map and
 * CONTROL bit 6 reads 0.  1.2 added the raster list (RASTER_*), holes in
 * the map before it.  1.3 added the light pen (LPEN_*, RDC_IRQ_LPEN,
 * STATUS.LPEN), holes in the map and IRQ bit 5 reading 0 before it.
 * 1.4 added PERF_CULLED (a hole before it) and raster-list WAITs for a
 * column (before it, a WAIT for column x > 0 held until the next line).
 */
#define RDC_VERSION_VALUE 0x00010004u
#define RDC_REG_WINDOW 0x400u

/* ---- Identification and control ------------------------------------- */
#define RDC_REG_ID 0x000 /* R   RDC_ID_VALUE */
#define RDC_REG_VERSION 0x004 /* R   [31:16] major, [15:0] minor */
#define RDC_REG_VRAM_SIZE 0x008 /* R   bytes of VRAM */
#define RDC_REG_CORE_KHZ 0x00c /* R   core clock in kHz */

#define RDC_REG_CONTROL 0x010 /* RW */
#define   RDC_CONTROL_DP_EN BIT(0) /* display processor runs */
#define   RDC_CONTROL_SCANOUT_EN BIT(1) /* CRTC runs; 0 = no frames */
#define   RDC_CONTROL_RING_EN BIT(2) /* DP fetches from the VRAM ring */
#define   RDC_CONTROL_HALT_ON_ERR BIT(3) /* bad command halts the DP */
#define   RDC_CONTROL_CLUT_LATCH BIT(4) /* CLUT writes apply at vblank */
#define   RDC_CONTROL_CURSOR_EN BIT(5) /* hardware cursor overlay */
/*
 * latched at vblank: RGB565, RGB888 and XRGB8888 pixels go through the
 * CLUT a component at a time, R' = CLUT[R].r, G' = CLUT[G].g, B' =
 * CLUT[B].b (565's components widened first); no effect on indexed formats
 */
#define   RDC_CONTROL_GAMMA_EN BIT(6)
#define   RDC_CONTROL_RESUME BIT(30) /* W: leave the halted state */
#define   RDC_CONTROL_SOFT_RESET BIT(31) /* W: reset the chip, self-clearing */
#define   RDC_CONTROL_RESET_VALUE \
	(RDC_CONTROL_DP_EN | RDC_CONTROL_SCANOUT_EN)

#define RDC_REG_STATUS 0x014 /* R */
#define   RDC_STATUS_DP_BUSY BIT(0) /* a command is in progress */
#define   RDC_STATUS_DP_HALTED BIT(1) /* halted on error */
#define   RDC_STATUS_DP_WAIT BIT(2) /* waiting (vblank, line, data) */
#define   RDC_STATUS_FIFO_EMPTY BIT(3)
#define   RDC_STATUS_FIFO_FULL BIT(4)
#define   RDC_STATUS_RING_EMPTY BIT(5) /* head == tail */
#define   RDC_STATUS_VBLANK BIT(6) /* beam in vertical blanking */
#define   RDC_STATUS_HBLANK BIT(7) /* beam in horizontal blanking */
#define   RDC_STATUS_IRQ BIT(8) /* level of the IRQ pin */
#define   RDC_STATUS_LPEN BIT(9) /* the light pen latched (LPEN_CTRL clears) */
#define   RDC_STATUS_IDLE_MASK \
	(RDC_STATUS_DP_BUSY | RDC_STATUS_DP_WAIT) /* 0 and queues empty = idle */

#define RDC_REG_IRQ_STATUS 0x018 /* W1C  raised events */
#define RDC_REG_IRQ_ENABLE 0x01c /* RW   events that drive the IRQ pin */
#define   RDC_IRQ_VBLANK BIT(0) /* start of vertical blanking */
#define   RDC_IRQ_LINE BIT(1) /* beam reached LINE_COMPARE */
#define   RDC_IRQ_FENCE BIT(2) /* FENCE command executed */
#define   RDC_IRQ_FIFO_LOW BIT(3) /* FIFO level fell to FIFO_LOWWATER */
#define   RDC_IRQ_ERROR BIT(4) /* ERR_CODE was set */
#define   RDC_IRQ_LPEN BIT(5) /* the light pen latched the beam */
#define   RDC_IRQ_ALL GENMASK(5, 0)

/*
 * R   last error (enum rdc_err); cleared by writing RDC_IRQ_ERROR to IRQ_STATUS
 */
#define RDC_REG_ERR_CODE 0x020
/*
 * R   header word of the offending command, the register offset for host
 * errors, or the VRAM address of a display-list word that could not be fetched
 */
#define RDC_REG_ERR_INFO 0x024
#define RDC_REG_PINS 0x028 /* R   pin levels */
#define   RDC_PIN_TE BIT(0) /* out: high during vertical blanking */
#define   RDC_PIN_IRQ BIT(1) /* out: high while an enabled IRQ is raised */
#define   RDC_PIN_RESET_N BIT(2) /* in: low holds the chip in reset */
#define   RDC_PIN_BL_EN BIT(3) /* in: backlight enable */

/* ---- CRTC: timing (latched), framebuffer (latched), beam ---------------- */
/*
 * Horizontal values count pixels, vertical values count lines, both from 0
 * at the first active pixel/line:  1 <= DISPLAY <= SYNC_START <= SYNC_END
 * <= TOTAL <= RDC_CRTC_MAX_TOTAL, DISPLAY <= RDC_CRTC_MAX_DISPLAY,
 * V_DISPLAY < V_TOTAL, pixel clock RDC_PIXCLK_MIN_KHZ..RDC_PIXCLK_MAX_KHZ.
 * Invalid timing is refused at latch time with RDC_ERR_MODE and the CRTC
 * keeps its previous mode.
 */
#define RDC_REG_H_TOTAL 0x100 /* RW latched */
#define RDC_REG_H_DISPLAY 0x104 /* RW latched */
#define RDC_REG_H_SYNC_START 0x108 /* RW latched */
#define RDC_REG_H_SYNC_END 0x10c /* RW latched */
#define RDC_REG_V_TOTAL 0x110 /* RW latched */
#define RDC_REG_V_DISPLAY 0x114 /* RW latched */
#define RDC_REG_V_SYNC_START 0x118 /* RW latched */
#define RDC_REG_V_SYNC_END 0x11c /* RW latched */
#define RDC_REG_PIXCLK_KHZ 0x120 /* RW latched  pixel clock */
#define RDC_REG_CRTC_FLAGS 0x124 /* RW latched */
#define   RDC_CRTC_HSYNC_POS BIT(0) /* hsync active high */
#define   RDC_CRTC_VSYNC_POS BIT(1) /* vsync active high */
#define   RDC_CRTC_LCD BIT(2) /* panel timing (informative) */
#define RDC_REG_FB_BASE 0x128 /* RW latched  VRAM byte address of line 0 */
#define RDC_REG_FB_STRIDE 0x12c /* RW latched  bytes from line to line */
#define RDC_REG_FB_FORMAT 0x130 /* RW latched  enum rdc_format */
#define RDC_REG_LINE_COMPARE 0x134 /* RW  raise RDC_IRQ_LINE at this line */
#define RDC_REG_BEAM 0x138 /* R   current beam position */
#define   RDC_BEAM_X GENMASK(15, 0)
#define   RDC_BEAM_Y GENMASK(31, 16)
#define RDC_REG_FRAME_COUNT 0x13c /* R   vblanks since reset */
/*
 * RW  write: load enum rdc_preset into the timing shadows (and FB_STRIDE
 * for the current FB_FORMAT); read: the last preset loaded
 */
#define RDC_REG_MODE_PRESET 0x140

/*
 * Raster list: entries of two words in VRAM (RDC_RL_*) that the CRTC runs
 * every frame, restarting at RASTER_BASE at the start of line 0, before
 * the line's fetch.  RASTER_BASE and RASTER_CTRL are latched at vblank;
 * the CRTC fetches an entry only when the beam has reached the WAIT
 * before it, each one an 8-byte read in the fetch window of the line's
 * start or of the WAIT's column.  A bad
 * entry, an entry leaving VRAM or more entries in a frame than
 * RASTER_CTRL.LEN stop the list: RDC_ERR_RASTER with ERR_INFO the entry's
 * VRAM address, RASTER_STATUS.ERROR set and RASTER_CTRL.EN cleared.
 */
#define RDC_REG_RASTER_BASE 0x144 /* RW latched  VRAM byte address, [2:0] 0 */
#define   RDC_RASTER_BASE_MASK GENMASK(31, 3)
#define RDC_REG_RASTER_CTRL 0x148 /* RW latched */
#define   RDC_RASTER_CTRL_EN BIT(0) /* run the list every frame */
/* entries a frame may fetch, 1..RDC_RASTER_MAX_ENTRIES; 0 = the maximum */
#define   RDC_RASTER_CTRL_LEN GENMASK(28, 16)
#define   RDC_RASTER_CTRL_MASK (RDC_RASTER_CTRL_EN | RDC_RASTER_CTRL_LEN)
#define RDC_REG_RASTER_STATUS 0x14c /* R */
#define   RDC_RASTER_STATUS_RUN BIT(0) /* this frame's list has not ended */
/* a bad list stopped; cleared by a write of RASTER_CTRL */
#define   RDC_RASTER_STATUS_ERROR BIT(1)
#define   RDC_RASTER_STATUS_COUNT GENMASK(31, 16) /* entries this frame */
#define RDC_RASTER_MAX_ENTRIES 4096u
#define RDC_RASTER_ENTRY_BYTES 8u
/*
 * An entry: word 0 [31:28] the op, [11:0] its argument; word 1 the value.
 *  END   the list is done for this frame (zeroed VRAM ends a list)
 *  WAIT  word 1 [15:0] x, [31:16] y (as BEAM): hold until the beam is at
 *        or past line y, column x: line start + ceil(x * core clock /
 *        pixel clock), a CLUT write after it changing line y from column x
 *        on; x >= H_TOTAL is line y + 1's start; y >= V_TOTAL is never met
 *  REG   word 0 [11:0] a register offset: FB_BASE and FB_STRIDE (the
 *        latched copies, in force from the next line fetched until the
 *        next vblank latch), CURSOR_POS, CURSOR_FG, CURSOR_BG; any other
 *        offset is a bad entry
 *  CLUT  word 0 [7:0] a CLUT entry, word 1 0x00RRGGBB: written to the
 *        CLUT in force (not to the CLUT_DATA read-back)
 */
#define RDC_RL_OP GENMASK(31, 28)
#define RDC_RL_ARG GENMASK(11, 0)
#define RDC_RL_X GENMASK(15, 0)
#define RDC_RL_Y GENMASK(31, 16)
enum rdc_rl_op {
	RDC_RL_END = 0,
	RDC_RL_WAIT = 1,
	RDC_RL_REG = 2,
	RDC_RL_CLUT = 3,
	RDC_RL_OP_COUNT
};

/*
 * Light pen, as the uPD7220's: the host says where the pen is held
 * (LPEN_POS) and puts it on the screen (LPEN_CTRL.EN).  At the start of
 * active line LPEN_POS.y the CRTC takes the pen's pixel from the line it
 * fetches, through the line's own conversion (format, CLUT, gamma, the
 * cursor, BL_EN low: black); it is lit when its luma (77 R + 150 G + 29 B
 * + 128) >> 8 is above LPEN_CTRL.THRESHOLD.  A lit pixel strobes the latch
 * at the first core cycle BEAM reads the pen's column on that line, line
 * start + ceil(x * core clock / pixel clock): LPEN_LATCH takes the beam's
 * position, STATUS.LPEN sets and RDC_IRQ_LPEN is raised, once a frame.
 * A pen off the active area never strobes.  A write of LPEN_POS or
 * LPEN_CTRL applies from the next line start and cancels a strobe still to
 * come on the current line; a write of LPEN_CTRL clears STATUS.LPEN.
 */
#define RDC_REG_LPEN_POS 0x150 /* RW  where the pen is held */
#define   RDC_LPEN_X GENMASK(15, 0)
#define   RDC_LPEN_Y GENMASK(31, 16)
#define RDC_REG_LPEN_CTRL 0x154 /* RW */
#define   RDC_LPEN_CTRL_EN BIT(0) /* the pen is on the screen */
#define   RDC_LPEN_CTRL_THRESHOLD GENMASK(15, 8) /* lit: luma above this */
#define   RDC_LPEN_CTRL_MASK (RDC_LPEN_CTRL_EN | RDC_LPEN_CTRL_THRESHOLD)
/* R   the beam at the last strobe, as BEAM: [15:0] x, [31:16] y */
#define RDC_REG_LPEN_LATCH 0x158

#define RDC_CRTC_MAX_TOTAL 4096
#define RDC_CRTC_MAX_DISPLAY 2048
#define RDC_PIXCLK_MIN_KHZ 1000
#define RDC_PIXCLK_MAX_KHZ 400000

/* ---- Colour lookup table ------------------------------------------------ */
#define RDC_REG_CLUT_INDEX 0x180 /* RW  next entry for CLUT_DATA, 0..255 */
/* RW  0x00RRGGBB; index++ (wraps at 256) after each read or write */
#define RDC_REG_CLUT_DATA 0x184
#define RDC_CLUT_ENTRIES 256

/* ---- Hardware cursor ---------------------------------------------------- */
/*
 * CURSOR_CTRL's format, latched at vblank with CURSOR_BASE:
 *  2BPP (reset): 32x32 pixels, 2 bpp (8 bytes a row, pixel 0 in bits 7:6
 *    of byte 0), the image read from VRAM at CURSOR_BASE when the CRTC
 *    latches at vblank:
 *      0 transparent, 1 CURSOR_FG, 2 CURSOR_BG, 3 invert the screen pixel.
 *  ARGB8888: S x S pixels, S = 32, or 64 with SIZE64, each the 32-bit
 *    word 0xAARRGGBB with premultiplied alpha, row r at CURSOR_BASE +
 *    r * S * 4.  The row a line shows is fetched from VRAM at that line's
 *    start (as the framebuffer is) and laid over the line after the CLUT
 *    and gamma, per component: out = min(255, c + (dst * (255 - a) + 127)
 *    / 255).  CURSOR_FG and CURSOR_BG play no part.
 * A format value of RDC_CURSOR_FMT_COUNT or more is refused with
 * RDC_ERR_REG (the register keeps its value).
 */
#define RDC_REG_CURSOR_BASE 0x1a0 /* RW latched */
#define RDC_REG_CURSOR_POS 0x1a4 /* RW  [15:0] x, [31:16] y, signed */
#define RDC_REG_CURSOR_FG 0x1a8 /* RW  0x00RRGGBB */
#define RDC_REG_CURSOR_BG 0x1ac /* RW  0x00RRGGBB */
#define RDC_REG_CURSOR_CTRL 0x1b0 /* RW latched  image format and size */
#define   RDC_CURSOR_CTRL_FMT GENMASK(1, 0) /* enum rdc_cursor_format */
#define   RDC_CURSOR_CTRL_SIZE64 BIT(8) /* ARGB8888: 64x64, else 32x32 */
#define   RDC_CURSOR_CTRL_MASK (RDC_CURSOR_CTRL_FMT | RDC_CURSOR_CTRL_SIZE64)
#define RDC_CURSOR_SIZE 32
#define RDC_CURSOR_BYTES (RDC_CURSOR_SIZE * RDC_CURSOR_SIZE / 4)
#define RDC_CURSOR_ARGB_MAX 64 /* the larger ARGB8888 size */

enum rdc_cursor_format {
	RDC_CURSOR_FMT_2BPP = 0,
	RDC_CURSOR_FMT_ARGB8888 = 1,
	RDC_CURSOR_FMT_COUNT
};

/* Width and height of the cursor CURSOR_CTRL value `ctrl` shows. */
static inline uint32_t rdc_cursor_size(uint32_t ctrl)
{
	if (FIELD_GET(RDC_CURSOR_CTRL_FMT, ctrl) == RDC_CURSOR_FMT_ARGB8888 &&
	    (ctrl & RDC_CURSOR_CTRL_SIZE64))
		return RDC_CURSOR_ARGB_MAX;
	return RDC_CURSOR_SIZE;
}

/* ---- Command queue ------------------------------------------------------ */
/*
 * W   push one command word; a write to a full FIFO is dropped:
 * RDC_ERR_FIFO_OVERFLOW
 */
#define RDC_REG_FIFO_DATA 0x200
#define RDC_REG_FIFO_FREE 0x204 /* R   free words */
#define RDC_REG_FIFO_LOWWATER 0x208 /* RW  RDC_IRQ_FIFO_LOW at this level */
#define RDC_REG_RING_BASE 0x20c /* RW  VRAM byte address, 4-aligned */
#define RDC_REG_RING_SIZE 0x210 /* RW  bytes, multiple of 4, >= 16 */
/* RW  byte offset the DP reads next; host writes only while RING_EN is 0 */
#define RDC_REG_RING_HEAD 0x214
/* RW  byte offset after the last word the host has written */
#define RDC_REG_RING_TAIL 0x218
#define RDC_REG_FENCE 0x21c /* R   value of the last FENCE executed */
#define RDC_REG_RDATA 0x220 /* R   pop one readback word (0 if empty) */
#define RDC_REG_RDATA_COUNT 0x224 /* R   readback words waiting */

#define RDC_FIFO_DEPTH 256 /* words */
#define RDC_RDATA_DEPTH 1024 /* words */

/* ---- Performance counters (64-bit counters as LO/HI pairs) ------------- */
/* Reading a LO register snapshots its HI half, so LO then HI is coherent. */
#define RDC_REG_TIME_LO 0x300 /* R   simulated time, core cycles */
#define RDC_REG_TIME_HI 0x304 /* R */
#define RDC_REG_PERF_BUSY_LO 0x308 /* R   cycles the DP spent on commands */
#define RDC_REG_PERF_BUSY_HI 0x30c /* R */
#define RDC_REG_PERF_STALL_LO 0x310 /* R   cycles the DP waited for the bus */
#define RDC_REG_PERF_STALL_HI 0x314 /* R */
#define RDC_REG_PERF_PIXELS_LO 0x318 /* R   pixels the DP wrote */
#define RDC_REG_PERF_PIXELS_HI 0x31c /* R */
#define RDC_REG_PERF_CMDS 0x320 /* R   commands executed */
#define RDC_REG_PERF_LAST_CYCLES 0x324 /* R   cycles of the last command */
#define RDC_REG_PERF_LAST_OPCODE 0x328 /* R   opcode of the last command */
#define RDC_REG_PERF_CTRL 0x32c /* W   write 1 to bit 0: zero the counters */
#define   RDC_PERF_CTRL_CLEAR BIT(0)
/* R   MESH commands whose RDC_MESH_BOUNDS box was outside the view volume */
#define RDC_REG_PERF_CULLED 0x330

/*
 * Registers a host read of which is not a plain read: RDATA pops a word,
 * CLUT_DATA advances CLUT_INDEX, and FIFO_DATA and PERF_CTRL are write
 * only (0, meaning nothing).  A register dump skips them; rdcd lets only
 * the controlling client read them and takes none as a wait's term.
 */
static inline int rdc_reg_read_has_effect(uint32_t reg)
{
	return reg == RDC_REG_RDATA || reg == RDC_REG_CLUT_DATA ||
	       reg == RDC_REG_FIFO_DATA || reg == RDC_REG_PERF_CTRL;
}

/* ---- Pixel formats ------------------------------------------------------ */
/*
 * Sub-byte formats pack the leftmost pixel in the most significant bits.
 * Multi-byte pixels are little-endian: RGB565 is bits 15:11 red; RGB888 is
 * bytes B, G, R; XRGB8888 is the 32-bit word 0xXXRRGGBB.
 */
enum rdc_format {
	RDC_FMT_I1 = 0,
	RDC_FMT_I2 = 1,
	RDC_FMT_I4 = 2,
	RDC_FMT_I8 = 3,
	RDC_FMT_RGB565 = 4,
	RDC_FMT_RGB888 = 5,
	RDC_FMT_XRGB8888 = 6,
	RDC_FMT_COUNT
};
/*
 * ARGB8888 (0xAARRGGBB) scans out as XRGB8888, the alpha byte ignored, as
 * a KMS primary plane shows it: the same format, not a value of its own
 */
#define RDC_FMT_ARGB8888 RDC_FMT_XRGB8888

static inline unsigned int rdc_format_bpp(unsigned int fmt)
{
	static const unsigned char bpp[RDC_FMT_COUNT] = { 1, 2, 4, 8, 16, 24, 32 };

	return fmt < RDC_FMT_COUNT ? bpp[fmt] : 0;
}

static inline int rdc_format_indexed(unsigned int fmt)
{
	return fmt <= RDC_FMT_I8;
}

/* Bytes a row of `width` pixels occupies (sub-byte rows round up). */
static inline uint32_t rdc_format_row_bytes(unsigned int fmt, uint32_t width)
{
	return (uint32_t)(((uint64_t)width * rdc_format_bpp(fmt) + 7) / 8);
}

/*
 * ---- Mode presets --------------------------------------------------------
 * Pixel clock = H_TOTAL * V_TOTAL * refresh.  VESA DMT / CEA-861 timings;
 * 320x200 is VGA mode 13h's 70 Hz frame without line doubling (400 * 225 * 70
 * Hz = 6.3 MHz).
 */
enum rdc_preset {
	RDC_PRESET_320x200_70 = 0,
	RDC_PRESET_640x480_60 = 1,
	RDC_PRESET_800x600_60 = 2,
	RDC_PRESET_1024x768_60 = 3,
	RDC_PRESET_1280x720_60 = 4,
	RDC_PRESET_1920x1080_60 = 5,
	RDC_PRESET_COUNT
};

/* ---- Errors (RDC_REG_ERR_CODE) ------------------------------------------ */
enum rdc_err {
	RDC_ERR_NONE = 0,
	RDC_ERR_OPCODE = 1, /* unknown opcode */
	RDC_ERR_LENGTH = 2, /* argument count wrong for the opcode */
	RDC_ERR_RANGE = 3, /* coordinate, size or radius out of range */
	RDC_ERR_SURFACE = 4, /* surface leaves VRAM, or bad format/stride */
	RDC_ERR_RING = 5, /* ring base/size/head/tail out of range */
	RDC_ERR_FIFO_OVERFLOW = 6, /* host wrote FIFO_DATA while full */
	/*
	 * bad register in a REG_WRITE command, or a host access outside the
	 * register window / to a R reg / to RING_HEAD while RING_EN is set
	 */
	RDC_ERR_REG = 7,
	RDC_ERR_ARG = 8, /* bad enumerated argument (ROP, format, ...) */
	RDC_ERR_MODE = 9, /* CRTC timing refused at latch */
	/*
	 * display-list nesting too deep, or RET outside a list; PUSH_MATRIX
	 * on a full matrix stack, POP_MATRIX on an empty one
	 */
	RDC_ERR_STACK = 10,
	/*
	 * DECODE: the image stream is corrupt (bad header, truncated, a run
	 * past the image, bytes left over); nothing is drawn
	 */
	RDC_ERR_DATA = 11,
	/* a raster list stopped: bad op or register, out of VRAM, too long */
	RDC_ERR_RASTER = 12,
	RDC_ERR_COUNT
};

/*
 * ---- Commands ------------------------------------------------------------
 * docs/commands.md is the full reference (semantics and cycle costs). A command
 * is a header word followed by RDC_CMD_LEN(header) argument words.  Points pack
 * x in [15:0] and y in [31:16], both signed 16-bit; sizes pack w in [15:0] and
 * h in [31:16], unsigned.  Coordinates must lie in [RDC_COORD_MIN,
 * RDC_COORD_MAX] and sizes/radii in [0, RDC_SIZE_MAX], else RDC_ERR_RANGE.
 * Colours are raw pixel values of the target format (a CLUT index for indexed
 * formats). On error the DP sets ERR_CODE/ERR_INFO, raises RDC_IRQ_ERROR and
 * skips the command (its argument words are consumed), or with
 * RDC_CONTROL_HALT_ON_ERR set, halts until RESUME or reset.  A header
 * announcing more than RDC_CMD_MAX_ARGS words is the exception: only the header
 * is consumed.  A rejected command draws nothing and changes no state.  Drawing
 * is clipped to the clip rectangle intersected with the DST surface; colours
 * are masked to DST's bits per pixel; every primitive writes each pixel at most
 * once (XOR twice restores the surface).
 */
#define RDC_CMD_OPCODE GENMASK(31, 24)
#define RDC_CMD_FLAGS GENMASK(23, 16)
#define RDC_CMD_LENGTH GENMASK(15, 0)
#define RDC_CMD(op, flags, len) \
	(FIELD_PREP(RDC_CMD_OPCODE, (op)) | FIELD_PREP(RDC_CMD_FLAGS, (flags)) | \
	 FIELD_PREP(RDC_CMD_LENGTH, (len)))
#define RDC_CMD_OP(hdr) FIELD_GET(RDC_CMD_OPCODE, (hdr))
#define RDC_CMD_FL(hdr) FIELD_GET(RDC_CMD_FLAGS, (hdr))
#define RDC_CMD_LEN(hdr) FIELD_GET(RDC_CMD_LENGTH, (hdr))

#define RDC_CMD_MAX_ARGS 4096 /* longer commands: RDC_ERR_LENGTH */
#define RDC_COORD_MIN (-16384)
#define RDC_COORD_MAX 16383
#define RDC_SIZE_MAX 16384

#define RDC_XY(x, y) (((uint32_t)(uint16_t)(int16_t)(x)) | \
		      ((uint32_t)(uint16_t)(int16_t)(y) << 16))
#define RDC_X(w) ((int32_t)(int16_t)((w) & 0xffff))
#define RDC_Y(w) ((int32_t)(int16_t)((w) >> 16))
#define RDC_WH(w, h) (((uint32_t)(uint16_t)(w)) | ((uint32_t)(uint16_t)(h) << 16))
#define RDC_W(v) ((uint32_t)((v) & 0xffff))
#define RDC_H(v) ((uint32_t)((v) >> 16))

/*   opcode                     args (words)                  flags */
enum rdc_opcode {
	/* Control */
	RDC_OP_NOP = 0x00, /* any number, ignored */
	RDC_OP_FENCE = 0x01, /* value: FENCE = value, RDC_IRQ_FENCE */
	RDC_OP_WAIT_VBLANK = 0x02, /* none; no-op while scanout is off */
	RDC_OP_WAIT_LINE = 0x03, /* line: wait until the beam starts it */
	RDC_OP_REG_WRITE = 0x04, /* reg, value (CRTC, CLUT, cursor, IRQ regs) */
	RDC_OP_LOAD_CLUT = 0x05, /* first, then 1..256 entries 0x00RRGGBB */
	/*
	 * addr: run the display list at VRAM byte address addr (4-aligned); its
	 * RET resumes after this CALL.  At most RDC_CALL_DEPTH lists nest:
	 * deeper is RDC_ERR_STACK
	 */
	RDC_OP_CALL = 0x06,
	/* none: return from a display list; outside one: RDC_ERR_STACK */
	RDC_OP_RET = 0x07,
	/*
	 * addr: continue the current display list at addr; from the FIFO or
	 * ring it enters a list as CALL does
	 */
	RDC_OP_JUMP = 0x08,

	/* Drawing state */
	RDC_OP_SET_FG = 0x10, /* pixel value */
	RDC_OP_SET_BG = 0x11, /* pixel value */
	RDC_OP_SET_ROP = 0x12, /* enum rdc_rop */
	/*
	 * xy0, xy1: x0 <= x < x1, y0 <= y < y1; x1, y1 may be RDC_COORD_MAX + 1
	 */
	RDC_OP_SET_CLIP = 0x13,
	RDC_OP_SET_DST = 0x14, /* base, stride, wh, format */
	RDC_OP_SET_SRC = 0x15, /* base, stride, wh, format */
	/*
	 * flags = enum rdc_pattern_mode; MONO*: 2 words, 8 rows of 8 bits (row
	 * 0 in byte 0 of word 0, bit 7 leftmost); COLOR: 64 pixel values row by
	 * row; NONE: no words.  Anchored at the DST origin; used by the filled
	 * primitives
	 */
	RDC_OP_SET_PATTERN = 0x16,
	/*
	 * [7:0] width 1..RDC_PEN_MAX_WIDTH, [9:8] enum rdc_cap, [11:10] enum
	 * rdc_join
	 */
	RDC_OP_SET_PEN = 0x17,
	/*
	 * pattern (bit 0 first, 1 = drawn), then [5:0] length 0..32 (0 = solid)
	 * and [13:8] offset; the dash continues along a polyline
	 */
	RDC_OP_SET_DASH = 0x18,
	/*
	 * 0..255: global alpha of BLIT and HOST_BLIT (255 = opaque): the ROP's
	 * result is blended over DST per channel in RGB formats; indexed
	 * formats draw only at >= RDC_ALPHA_THRESHOLD
	 */
	RDC_OP_SET_ALPHA = 0x19,
	/*
	 * key pixel value; flags RDC_COLORKEY_ENABLE: source pixels equal to
	 * the key (compared in the source format, before the ROP) are not drawn
	 */
	RDC_OP_SET_COLORKEY = 0x1a,
	/*
	 * 9 words m00 m01 m02 m10 m11 m12 m20 m21 m22, signed 15.16 fixed
	 * point, or none for the identity
	 */
	RDC_OP_SET_TRANSFORM = 0x1b,
	/*
	 * wx0 wy0 wx1 wy1 (world window, signed 15.16), xy0 xy1 (viewport,
	 * pixels): sets the transform
	 */
	RDC_OP_SET_VIEWPORT = 0x1c,
	/*
	 * 2..256 CLUT entries from the FG index for anti-aliasing in indexed
	 * formats: FG at full coverage, FG + n - 1 the faintest
	 */
	RDC_OP_SET_AA_RAMP = 0x1d,
	/*
	 * base, stride: 16-bit depth surface the size of DST; flags RDC_Z_TEST
	 * | RDC_Z_WRITE; no words: depth buffering off
	 */
	RDC_OP_SET_ZBUF = 0x1e,
	/* value: fill the depth surface (clip applies) */
	RDC_OP_CLEAR_Z = 0x1f,

	/* Primitives (first set) */
	RDC_OP_PIXEL = 0x20, /* xy */
	RDC_OP_LINE = 0x21, /* xy0, xy1: both endpoints drawn */
	/*
	 * 2..RDC_CMD_MAX_ARGS points; a shared vertex is drawn once, and so is
	 * the start of a closed one (last == first)
	 */
	RDC_OP_POLYLINE = 0x22,
	RDC_OP_RECT = 0x23, /* xy, wh: outline */
	RDC_OP_FILL_RECT = 0x24, /* xy, wh */
	RDC_OP_CIRCLE = 0x25, /* xy centre, radius */
	RDC_OP_FILL_CIRCLE = 0x26, /* xy centre, radius */
	/* xy centre, wh = (rx, ry); a zero radius draws a line */
	RDC_OP_ELLIPSE = 0x27,
	RDC_OP_FILL_ELLIPSE = 0x28, /* xy centre, wh = (rx, ry) */
	RDC_OP_POLYGON = 0x29, /* 2..n points: closed outline */
	/*
	 * 3..n points, scan-line fill; flags RDC_FILL_NONZERO (else even-odd)
	 */
	RDC_OP_FILL_POLYGON = 0x2a,
	/*
	 * xy seed, then with RDC_FLOOD_BOUNDARY the boundary colour; flags
	 * RDC_FLOOD_*
	 */
	RDC_OP_FLOOD_FILL = 0x2b,
	/*
	 * xy centre, wh = (rx, ry), angles: [15:0] start, [31:16] end in
	 * 1/65536 turn counter-clockwise from +x (y up on screen); flags = enum
	 * rdc_arc_mode
	 */
	RDC_OP_ARC = 0x2c,
	/* 4 points; flags: steps (0 = chosen from the control polygon) */
	RDC_OP_BEZIER = 0x2d,
	/* p0, p1, tangent t0, tangent t1 (as xy); flags: steps (0 = chosen) */
	RDC_OP_HERMITE = 0x2e,
	/*
	 * 4..n control points, uniform cubic; flags: steps per segment (0 =
	 * chosen)
	 */
	RDC_OP_BSPLINE = 0x2f,
	/* src xy, dst xy, wh: SRC surface to DST, overlap-safe, ROP applies */
	RDC_OP_BLIT = 0x30,
	/* xy, wh, then rows of DST-format pixels, each row padded to a word */
	RDC_OP_HOST_BLIT = 0x31,
	/*
	 * xy, wh: rows of SRC-format pixels to RDATA, each row padded to a word
	 */
	RDC_OP_READBACK = 0x32,
	/*
	 * xy, wh, [fg, bg,] then 1 bpp rows (bit 7 of byte 0 leftmost), each
	 * row padded to a word; 1 = FG, 0 = BG
	 * flags: RDC_MONO_TRANSPARENT, RDC_MONO_COLORS
	 */
	RDC_OP_MONO = 0x33,
	/*
	 * xy, count, then count chars 4 to a word (byte 0 first), built-in 8x16
	 * font; flags: RDC_MONO_TRANSPARENT
	 */
	RDC_OP_TEXT = 0x34,
	RDC_OP_AA_LINE = 0x35, /* xy0, xy1: Wu line */
	RDC_OP_AA_CIRCLE = 0x36, /* xy centre, radius */
	RDC_OP_AA_ELLIPSE = 0x37, /* xy centre, wh = (rx, ry) */
	/*
	 * 3 vertices of (xy, colour, z [15:0]): 9 words; flags RDC_TRI_GOURAUD
	 * (else flat, the first vertex's colour)
	 */
	RDC_OP_TRIANGLE = 0x38,

	/*
	 * 3D geometry (docs/commands.md, "3D").  Matrices are the top three
	 * rows of a 4x4 (bottom row 0 0 0 1), row by row, signed 15.16; a
	 * new matrix M applies to vertices first: CTM = CTM * M.
	 */
	RDC_OP_MATRIX_LOAD = 0x40, /* 12 words, or none for the identity */
	RDC_OP_MATRIX_MULT = 0x41, /* 12 words: CTM = CTM * M */
	RDC_OP_TRANSLATE = 0x42, /* tx ty tz (15.16) */
	RDC_OP_SCALE = 0x43, /* sx sy sz (15.16) */
	/* angle in 1/65536 turn, counter-clockwise; flags enum rdc_axis */
	RDC_OP_ROTATE = 0x44,
	RDC_OP_PUSH_MATRIX = 0x45, /* none: save the CTM */
	RDC_OP_POP_MATRIX = 0x46, /* none: restore the CTM */
	/*
	 * VRP xyz, VPN xyz, VUP xyz (world), PRP uvn (view reference
	 * coordinates), umin umax vmin vmax (window), F, B: 18 words, 15.16;
	 * flags RDC_VIEW_PERSPECTIVE (else parallel)
	 */
	RDC_OP_SET_VIEW = 0x48,
	/* xy0, xy1: the corner pixels canonical (-1, -1) and (1, 1) land on */
	RDC_OP_SET_VIEWPORT3 = 0x49,
	/*
	 * colour 0x00RRGGBB, dx dy dz (towards the light, 15.16), or none:
	 * off; flags: the light's number 0..RDC_LIGHTS - 1
	 */
	RDC_OP_SET_LIGHT = 0x4a,
	RDC_OP_SET_AMBIENT = 0x4b, /* colour 0x00RRGGBB of the ambient light */
	/* ambient, diffuse, specular (0x00RRGGBB reflectances), shininess */
	RDC_OP_SET_MATERIAL = 0x4c,
	/*
	 * vbase, vcount, ibase, tcount: triangles of 16-bit indices at ibase
	 * into vertices of 3 (or with RDC_MESH_NORMALS 6) 15.16 words at vbase;
	 * flags RDC_MESH_*
	 */
	RDC_OP_MESH = 0x50,
	/* mode (RDC_MESH_* | steps << 8), 16 control points xyz: 49 words */
	RDC_OP_PATCH = 0x51,
	/* 4 control points xyz (12 words, 15.16); flags: steps (0 = 16) */
	RDC_OP_BEZIER3 = 0x52,
	/*
	 * 4..RDC_BSPLINE3_MAX_POINTS control points xyz (15.16): a uniform
	 * cubic B-spline; flags: steps per segment (0 = 16)
	 */
	RDC_OP_BSPLINE3 = 0x53,

	/*
	 * Image decompression and processing (docs/commands.md, "Images";
	 * stream formats in rdc_image.h)
	 */
	/* addr, size (bytes the stream may span), xy: decode it into DST */
	RDC_OP_DECODE = 0x60,
	/*
	 * xy, wh (of SRC), table: 256 32-bit bins; flags RDC_CHAN_* and
	 * RDC_HIST_ACCUM
	 */
	RDC_OP_HISTOGRAM = 0x61,
	/* hist, map (256 bytes), param; flags enum rdc_map_mode */
	RDC_OP_MAP_BUILD = 0x62,
	/* xy, wh (of DST), map: every pixel (each channel) through the map */
	RDC_OP_MAP_APPLY = 0x63,
	/* map: CLUT[i] = grey map[i] for i = 0..255 */
	RDC_OP_MAP_CLUT = 0x64,
	/*
	 * sxy, dxy, wh, then 3 kernel rows and div/bias (KERNEL), or div/bias
	 * alone (SOBEL): 3x3 convolution SRC to DST; flags RDC_CONV_*
	 */
	RDC_OP_CONVOLVE = 0x65,
	/* xy, wh (of DST), level: intensity >= level: FG, else BG; RDC_CHAN_* */
	RDC_OP_THRESHOLD = 0x66,
	RDC_OP_COUNT = 0x100
};

/*
 * Argument words a command takes: the exact count for fixed-length ones,
 * RDC_ARGS_VARIABLE for those whose header gives it (each checked by its
 * own rules), RDC_ARGS_UNKNOWN for an opcode the DP does not know.  The
 * DP and the kernel driver's SUBMIT check both read it here.
 */
#define RDC_ARGS_VARIABLE (-1)
#define RDC_ARGS_UNKNOWN (-2)
static inline int rdc_cmd_args(uint32_t op)
{
	switch (op) {
	case RDC_OP_WAIT_VBLANK:
	case RDC_OP_RET:
	case RDC_OP_PUSH_MATRIX:
	case RDC_OP_POP_MATRIX:
		return 0;
	case RDC_OP_FENCE:
	case RDC_OP_WAIT_LINE:
	case RDC_OP_SET_FG:
	case RDC_OP_SET_BG:
	case RDC_OP_SET_ROP:
	case RDC_OP_PIXEL:
	case RDC_OP_SET_PEN:
	case RDC_OP_CALL:
	case RDC_OP_JUMP:
	case RDC_OP_SET_ALPHA:
	case RDC_OP_SET_COLORKEY:
	case RDC_OP_SET_AA_RAMP:
	case RDC_OP_CLEAR_Z:
	case RDC_OP_ROTATE:
	case RDC_OP_SET_AMBIENT:
	case RDC_OP_MAP_CLUT:
		return 1;
	case RDC_OP_REG_WRITE:
	case RDC_OP_SET_CLIP:
	case RDC_OP_LINE:
	case RDC_OP_RECT:
	case RDC_OP_FILL_RECT:
	case RDC_OP_CIRCLE:
	case RDC_OP_FILL_CIRCLE:
	case RDC_OP_ELLIPSE:
	case RDC_OP_FILL_ELLIPSE:
	case RDC_OP_READBACK:
	case RDC_OP_SET_DASH:
	case RDC_OP_AA_LINE:
	case RDC_OP_AA_CIRCLE:
	case RDC_OP_AA_ELLIPSE:
	case RDC_OP_SET_VIEWPORT3:
		return 2;
	case RDC_OP_BLIT:
	case RDC_OP_ARC:
	case RDC_OP_DECODE:
	case RDC_OP_HISTOGRAM:
	case RDC_OP_MAP_BUILD:
	case RDC_OP_MAP_APPLY:
	case RDC_OP_THRESHOLD:
		return 3;
	case RDC_OP_SET_DST:
	case RDC_OP_SET_SRC:
	case RDC_OP_SET_MATERIAL:
	case RDC_OP_MESH:
	case RDC_OP_BEZIER:
	case RDC_OP_HERMITE:
		return 4;
	case RDC_OP_SET_VIEWPORT:
		return 6;
	case RDC_OP_TRANSLATE:
	case RDC_OP_SCALE:
		return 3;
	case RDC_OP_TRIANGLE:
		return 9;
	case RDC_OP_MATRIX_MULT:
	case RDC_OP_BEZIER3:
		return 12;
	case RDC_OP_SET_VIEW:
		return 18;
	case RDC_OP_PATCH:
		return 49;
	case RDC_OP_NOP:
	case RDC_OP_LOAD_CLUT:
	case RDC_OP_SET_TRANSFORM:
	case RDC_OP_SET_PATTERN:
	case RDC_OP_MATRIX_LOAD:
	case RDC_OP_SET_LIGHT:
	case RDC_OP_SET_ZBUF:
	case RDC_OP_POLYLINE:
	case RDC_OP_POLYGON:
	case RDC_OP_FILL_POLYGON:
	case RDC_OP_FLOOD_FILL:
	case RDC_OP_BSPLINE:
	case RDC_OP_HOST_BLIT:
	case RDC_OP_MONO:
	case RDC_OP_TEXT:
	case RDC_OP_CONVOLVE:
	case RDC_OP_BSPLINE3:
		return RDC_ARGS_VARIABLE;
	default:
		return RDC_ARGS_UNKNOWN;
	}
}

/* Does op take RDC_DRAW_FG? */
static inline int rdc_cmd_takes_fg(uint32_t op)
{
	switch (op) {
	case RDC_OP_PIXEL:
	case RDC_OP_LINE:
	case RDC_OP_POLYLINE:
	case RDC_OP_RECT:
	case RDC_OP_FILL_RECT:
	case RDC_OP_CIRCLE:
	case RDC_OP_FILL_CIRCLE:
	case RDC_OP_ELLIPSE:
	case RDC_OP_FILL_ELLIPSE:
	case RDC_OP_POLYGON:
	case RDC_OP_FILL_POLYGON:
	case RDC_OP_ARC:
	case RDC_OP_AA_LINE:
	case RDC_OP_AA_CIRCLE:
	case RDC_OP_AA_ELLIPSE:
		return 1;
	default:
		return 0;
	}
}

#define RDC_CALL_DEPTH 8 /* nested display lists */
#define RDC_ALPHA_OPAQUE 255u /* SET_ALPHA: 0..255, reset 255 */
#define RDC_ALPHA_THRESHOLD 128u /* indexed DST: alpha >= this draws */
#define RDC_AA_RAMP_MIN 2u /* SET_AA_RAMP range */
#define RDC_AA_RAMP_MAX 256u
#define RDC_AA_RAMP_RESET 8u
#define RDC_PEN_MAX_WIDTH 64
#define RDC_PEN_WIDTH GENMASK(7, 0) /* SET_PEN word fields */
#define RDC_PEN_CAP GENMASK(9, 8)
#define RDC_PEN_JOIN GENMASK(11, 10)
#define RDC_DASH_LEN GENMASK(5, 0) /* SET_DASH second word fields */
#define RDC_DASH_OFFSET GENMASK(13, 8)
#define RDC_DASH_MAX_LEN 32
#define RDC_ARC_START GENMASK(15, 0) /* ARC angle word fields */
#define RDC_ARC_END GENMASK(31, 16)
#define RDC_CURVE_MAX_STEPS 255 /* steps in the flags of BEZIER & co. */
#define RDC_COLORKEY_ENABLE BIT(0)
/*
 * A drawing command whose flags leave bit 7 free and that draws in FG
 * (rdc_cmd_takes_fg) may carry its colour: with RDC_DRAW_FG its first
 * argument word is written to FG, as a SET_FG before it would, and its
 * own arguments follow.  A blitter's solid fill that carries its colour
 * (Intel's XY_COLOR_BLT) rather than a register write ahead of it.
 */
#define RDC_DRAW_FG BIT(7)
#define RDC_FILL_NONZERO BIT(0)
#define RDC_FLOOD_8 BIT(0) /* 8-connected (else 4-connected) */
/* fill up to the boundary colour (else replace the seed's colour) */
#define RDC_FLOOD_BOUNDARY BIT(1)
#define RDC_Z_TEST BIT(0) /* draw only where z < stored depth */
#define RDC_Z_WRITE BIT(1) /* store z where drawn */
#define RDC_TRI_GOURAUD BIT(0)
/*
 * 3D (docs/commands.md, "3D"; cycle constants in docs/hardware.md).
 * Limits: the matrix stack, lights, a MESH's vertices and triangles, a
 * PATCH's subdivision.
 */
#define RDC_MATRIX_STACK_DEPTH 16
#define RDC_LIGHTS 4
#define RDC_MESH_MAX_VERTS 2048u
#define RDC_MESH_MAX_TRIS 4096u
#define RDC_PATCH_MAX_STEPS 32u
#define RDC_BEZIER3_STEPS 16u /* BEZIER3 and BSPLINE3 with steps 0 */
/* BSPLINE3: 3 words a point, at most RDC_CMD_MAX_ARGS words */
#define RDC_BSPLINE3_MAX_POINTS (RDC_CMD_MAX_ARGS / 3)
enum rdc_axis { RDC_AXIS_X = 0, RDC_AXIS_Y = 1, RDC_AXIS_Z = 2 };
#define RDC_VIEW_PERSPECTIVE BIT(0)
#define RDC_MESH_NORMALS BIT(0) /* vertices carry a normal: 6 words */
#define RDC_MESH_WIRE BIT(1) /* each edge once, FG lines (else filled) */
#define RDC_MESH_CULL BIT(2) /* leave out back faces (clockwise on screen) */
#define RDC_MESH_LIT BIT(3) /* illumination (else FG) */
#define RDC_MESH_GOURAUD BIT(4) /* lit per vertex (else per face, flat) */
#define RDC_MESH_TWO_SIDED BIT(5) /* normals turned towards the viewer */
/* filled: draw the triangles farthest first (painter's algorithm) */
#define RDC_MESH_SORT BIT(6)
#define RDC_MESH_FLAGS GENMASK(6, 0)
#define RDC_PATCH_STEPS GENMASK(15, 8) /* PATCH mode word: 1..32 */
/*
 * MESH's vcount word, bit 31 (BOUNDS): the RDC_MESH_BOUNDS_WORDS words at
 * vbase are the model's box xmin ymin zmin xmax ymax zmax (15.16), the
 * vertices follow; a box outside the view volume culls the mesh before a
 * vertex is read.
 */
#define RDC_MESH_BOUNDS BIT(31)
#define RDC_MESH_BOUNDS_WORDS 6u
/*
 * MESH only (PATCH's mode word keeps RDC_MESH_FLAGS): filled, visibility
 * resolved a scan line at a time, no depth buffer; at most
 * RDC_MESH_SCAN_MAX_TRIS triangles after clipping.
 */
#define RDC_MESH_SCANLINE BIT(7)
#define RDC_MESH_CMD_FLAGS GENMASK(7, 0)
#define RDC_MESH_SCAN_MAX_TRIS 4096u
/*
 * Geometry engine cycles (one multiply-accumulate a cycle): a vertex
 * through the CTM and the view (21 MACs and the checks), its lighting
 * (normal through the cofactor matrix and normalised, then per light
 * diffuse, reflection, power, colour), a triangle's setup (facing, screen
 * mapping), each vertex a clip plane makes, and a tessellated patch or
 * curve point (forward differences), and the painter's sort (per
 * triangle and per halving).
 */
#define RDC_T_VERTEX3 24u
#define RDC_T_LIGHT3 16u
#define RDC_T_LIGHT3_EACH 32u
#define RDC_T_TRI3 8u
#define RDC_T_CLIP3 8u
#define RDC_T_TESS3 12u
#define RDC_T_SORT3 2u /* per triangle and level of the depth sort */
/*
 * HISTOGRAM and THRESHOLD: what a pixel's value is.  Indexed formats: the
 * index (RDC_CHAN_LUMA only).  RGB formats: the channel widened to 8 bits
 * (v << 3 | v >> 2 for 5 bits, v << 2 | v >> 4 for 6), or the luma
 * (77 R + 150 G + 29 B + 128) >> 8 of the widened channels.
 */
#define RDC_CHAN_SEL GENMASK(1, 0)
#define RDC_CHAN_LUMA 0u
#define RDC_CHAN_RED 1u
#define RDC_CHAN_GREEN 2u
#define RDC_CHAN_BLUE 3u
#define RDC_HIST_ACCUM BIT(2) /* add to the table's counts */
/* MAP_BUILD modes (flags) */
enum rdc_map_mode {
	RDC_MAP_STRETCH = 0, /* param [7:0] lo, [15:8] hi: linear lo..hi to 0..255 */
	/* lo, hi: the first and last bins with a count above param */
	RDC_MAP_STRETCH_AUTO = 1,
	RDC_MAP_EQUALIZE = 2, /* (255 cdf(v) + N / 2) / N; param 0 */
	RDC_MAP_MODE_COUNT
};
/*
 * CONVOLVE: flags [3:0] the mode, RDC_CONV_ABS; a kernel row word holds
 * three signed 8-bit coefficients, left in [7:0]; the scale word the
 * divisor (1..65535) in [15:0] and a signed bias in [31:16]
 */
#define RDC_CONV_MODE GENMASK(3, 0)
#define RDC_CONV_KERNEL 0u /* 7 words: sxy, dxy, wh, row0..row2, scale */
#define RDC_CONV_SOBEL 1u /* 4 words: sxy, dxy, wh, scale; |Gx| + |Gy| */
#define RDC_CONV_ABS BIT(4) /* KERNEL: the sum's absolute value */
#define RDC_CONV_KERNEL_WORDS 7u
#define RDC_CONV_SOBEL_WORDS 4u
#define RDC_CONV_DIV GENMASK(15, 0)
#define RDC_CONV_BIAS GENMASK(31, 16)

enum rdc_pattern_mode {
	RDC_PAT_NONE = 0, /* solid FG */
	RDC_PAT_MONO = 1, /* 1 = FG, 0 = BG */
	RDC_PAT_MONO_TRANSPARENT = 2, /* 1 = FG, 0 left alone */
	RDC_PAT_COLOR = 3 /* 64 pixel values */
};

enum rdc_cap { RDC_CAP_BUTT = 0, RDC_CAP_ROUND = 1, RDC_CAP_SQUARE = 2 };
enum rdc_join { RDC_JOIN_MITER = 0, RDC_JOIN_ROUND = 1, RDC_JOIN_BEVEL = 2 };
enum rdc_arc_mode { RDC_ARC_OUTLINE = 0, RDC_ARC_PIE = 1, RDC_ARC_CHORD = 2 };

#define RDC_MONO_TRANSPARENT BIT(0) /* 0 bits leave the destination alone */
/*
 * MONO: fg and bg follow wh and are written to FG and BG, as a SET_FG
 * and a SET_BG before it would, then the bitmap is drawn: a glyph with
 * its colours, as a console hands them over (fbdev's struct fb_image),
 * in one command.
 */
#define RDC_MONO_COLORS BIT(1)

/*
 * The argument words of HOST_BLIT and MONO (with flags fl) before their
 * data rows: xy, wh, and MONO's fg, bg with RDC_MONO_COLORS.
 */
static inline uint32_t rdc_cmd_data_at(uint32_t op, uint32_t fl)
{
	return op == RDC_OP_MONO && (fl & RDC_MONO_COLORS) ? 4 : 2;
}

/*
 * Raster operations: X11's GXclear..GXset.  Bit n of the code is the result for
 * (src, dst) = (!(n >> 1), !(n & 1)), so 3 (GXcopy) is src.
 */
enum rdc_rop {
	RDC_ROP_CLEAR = 0x0,
	RDC_ROP_AND = 0x1,
	RDC_ROP_AND_REVERSE = 0x2,
	RDC_ROP_COPY = 0x3,
	RDC_ROP_AND_INVERTED = 0x4,
	RDC_ROP_NOOP = 0x5,
	RDC_ROP_XOR = 0x6,
	RDC_ROP_OR = 0x7,
	RDC_ROP_NOR = 0x8,
	RDC_ROP_EQUIV = 0x9,
	RDC_ROP_INVERT = 0xa,
	RDC_ROP_OR_REVERSE = 0xb,
	RDC_ROP_COPY_INVERTED = 0xc,
	RDC_ROP_OR_INVERTED = 0xd,
	RDC_ROP_NAND = 0xe,
	RDC_ROP_SET = 0xf,
	RDC_ROP_COUNT
};

/* Apply ROP to 32 bits of source and destination at once. */
static inline uint32_t rdc_rop_apply(unsigned int rop, uint32_t s, uint32_t d)
{
	uint32_t r = 0;

	if (rop & 1)
		r |= s & d;
	if (rop & 2)
		r |= s & ~d;
	if (rop & 4)
		r |= ~s & d;
	if (rop & 8)
		r |= ~s & ~d;
	return r;
}

/* Does the ROP read the destination (a read-modify-write on the bus)? */
static inline int rdc_rop_reads_dst(unsigned int rop)
{
	return rop != RDC_ROP_CLEAR && rop != RDC_ROP_COPY &&
	       rop != RDC_ROP_COPY_INVERTED && rop != RDC_ROP_SET;
}

#include "rdc_image.h"

/* clang-format on */

#endif /* RDC_REGS_H */
