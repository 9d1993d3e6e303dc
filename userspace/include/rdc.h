/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * librdc: the host library for the RDC-1 simulated raster display
 * controller.
 *
 * One device handle (rdc_dev) reached through a URI that picks a backend:
 *   "sim:", "sim" or ""     an RDC-1 simulated in this process (default);
 *                           options, joined by ',': "vram=16M" (64K..256M
 *                           bytes, K/M suffixes), "scanout=demand" (no
 *                           frame is converted while nothing looks: a
 *                           grab that finds none waits for the next
 *                           whole frame; hw-sim/rdc_chip.h)
 *   "unix:PATH", "unix:"   an RDC-1 served by rdcd on a UNIX socket (the
 *                           default path when PATH is empty)
 *   "tcp:HOST:PORT"         the same over TCP; options after '?', joined
 *                           by '&': "token=FILE" (else $RDC_TOKEN_FILE),
 *                           "observe" (do not ask for control)
 *                           (docs/protocol.md)
 *   "fbdev:/dev/fbN"        the RDC-1 that rdcfb.ko simulates in the
 *                           kernel, through its framebuffer device; VRAM
 *                           is mapped.  RDC_E_URI if the node is not an
 *                           rdcfb framebuffer, RDC_E_FILE if it cannot
 *                           be opened; rdc_sim_step needs the module's
 *                           clock=stepped (else RDC_E_NOSYS)
 *   "drm:/dev/dri/cardN", "drm:"
 *                           the RDC-1 that rdcdrm.ko simulates in the
 *                           kernel, through its DRM card (the private
 *                           ioctls of rdcdrm_ioctl.h beside KMS); "drm:"
 *                           alone: the first card whose DRM driver is
 *                           "rdc".  RDC_E_URI if the node is not a DRM
 *                           card of driver rdc (rdc_last_error_detail
 *                           names what it is), RDC_E_FILE if it cannot
 *                           be opened or no rdc card is there (the
 *                           module not loaded), RDC_E_NOSYS in a build
 *                           without libdrm; the handle drops DRM master,
 *                           so a compositor can drive the card beside
 *                           it; rdc_sim_step needs the module's stepped
 *                           clock (else RDC_E_NOSYS).  When the card's
 *                           last open file closes, DRM gives the display
 *                           back to the card's fbdev emulation, which
 *                           sets its own mode and picture: a picture
 *                           drawn through one handle stays while some
 *                           handle (rdcctl stream's, a compositor's)
 *                           holds the card open
 *   "usb:"                  an RDC-1 attached over USB (rdc_usb.h,
 *                           docs/usb.md), through libusb: the first
 *                           device with IDs 1209:0001 and the RDC-1
 *                           interface (class ff/52/01); "usb:VID:PID"
 *                           (hex) other IDs; "usb:BUS-PORT[.PORT...]"
 *                           the device at that port path, whatever its
 *                           IDs (as rdc_list and `rdcctl list` print
 *                           it); "usb:serial=S" the default IDs with
 *                           that serial string.  Options as for tcp:
 *                           ("?observe", "?token=FILE").  RDC_E_IO if
 *                           no device matches, RDC_E_PROTO if its INFO
 *                           answer is not an RDC-1's, RDC_E_NOSYS in a
 *                           build without libusb-1.0.  When the device
 *                           goes away (unplugged, its UDC unbound) the
 *                           call in progress and every later one on the
 *                           handle return RDC_E_GONE, without waiting
 *                           for anything
 *
 * Errors: every function that can fail returns 0 or a positive count on
 * success and a negative enum rdc_error on failure; rdc_strerror() names
 * it.  When the device itself reported an error (ERR_CODE), the call
 * returns RDC_E_DEVICE and rdc_dev_error() gives the device's code.
 *
 * Register offsets, formats, ROPs and command encodings are those of
 * <rdc_regs.h>, which this header includes.
 */
#ifndef RDC_LIB_H
#define RDC_LIB_H

#include <stddef.h>
#include <stdint.h>

#include "rdc_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * ---- Version --------------------------------------------------------------
 * librdc's release (not the chip's, which RDC_REG_VERSION reads): the
 * header's in these macros, the library's at run time from rdc_version().
 * The major number is the SONAME's (librdc.so.1).
 */
#define RDC_VERSION_MAJOR 1
#define RDC_VERSION_MINOR 0
#define RDC_VERSION_PATCH 0
/* A release as one number, in order: 1.2.3 is 0x010203. */
#define RDC_VERSION_ENCODE(major, minor, patch) \
	(((uint32_t)(major) << 16) | ((uint32_t)(minor) << 8) | \
	 (uint32_t)(patch))
#define RDC_VERSION_NUMBER \
	RDC_VERSION_ENCODE(RDC_VERSION_MAJOR, RDC_VERSION_MINOR, \
			   RDC_VERSION_PATCH)
#define RDC_VERSION_GET_MAJOR(v) (((uint32_t)(v) >> 16) & 0xffu)
#define RDC_VERSION_GET_MINOR(v) (((uint32_t)(v) >> 8) & 0xffu)
#define RDC_VERSION_GET_PATCH(v) ((uint32_t)(v)&0xffu)

/* The release of the librdc the program runs with (RDC_VERSION_ENCODE). */
uint32_t rdc_version(void);

/*
 * ---- Structures that grow ------------------------------------------------
 * The handles (rdc_dev, rdc_batch, rdc_vcd; rdc_sink in rdc_sink.h) are
 * opaque.  A structure a call fills in the caller's memory (rdc_stats,
 * rdc_pin_edge, rdc_event, rdc_script_result, rdc_replay_result;
 * rdc_sink_stats) begins with `size`: the call, an inline function here,
 * sets it to the structure's size as the program was compiled and passes
 * it to the library's rdc_..._sized function, which fills that many bytes
 * and no more (zeroing what it does not know of).  Later releases add
 * members at the end only, so a program built against an older header
 * keeps working with a newer librdc.so.1, and the other way round.  A
 * structure the caller fills for the library (rdc_frame) has `size`
 * too, where 0 (a zeroed or designated initialiser) means the layout of
 * librdc 1.0.  A structure the library hands to a callback (rdc_found) is
 * the library's memory and only grows at its end.  rdc_proto.h's
 * structures are the wire format's and change with RDC_PROTO_VERSION.
 */

enum rdc_error {
	RDC_OK = 0,
	RDC_E_INVAL = -1,   /* bad argument */
	RDC_E_NOMEM = -2,   /* out of memory */
	RDC_E_NOSYS = -3,   /* the backend does not offer this */
	RDC_E_URI = -4,	    /* unknown or malformed device URI */
	RDC_E_IO = -5,	    /* transport failure */
	RDC_E_TIMEOUT = -6, /* the wait ran past its simulated-time budget */
	RDC_E_DEVICE = -7,  /* the device reported an error (rdc_dev_error) */
	RDC_E_HALTED = -8,  /* the display processor is halted on an error */
	RDC_E_RANGE = -9,   /* address or size outside the device */
	RDC_E_PARSE = -10,  /* malformed script or trace */
	RDC_E_PROTO = -11,  /* protocol violation by the other side */
	RDC_E_BUSY = -12,   /* another client controls the device */
	RDC_E_FILE = -13,   /* file could not be read or written */
	RDC_E_AUTH = -14,   /* the daemon refused the token */
	RDC_E_GONE = -15,   /* the device went away (unplugged, unbound) */
	RDC_E_RESET = -16,  /* a reset ended the request (rdcd: RESET) */
	RDC_E_COUNT_ = -17
};

/* A short English description of an enum rdc_error value. */
const char *rdc_strerror(int err);
/*
 * What lies behind an error, when librdc knows more than the code says:
 * the file, socket or device concerned and the system's reason, e.g.
 * "unix:/tmp/rdc.sock: connect: No such file or directory (is rdcd
 * running? start it with rdcd --listen unix:/tmp/rdc.sock)".  Kept per
 * thread: the detail of the calling thread's most recent failure that
 * recorded one, returned only if that failure's code is `err` (so it never
 * describes some other error), else "".  Valid until the thread's next
 * librdc call.
 */
const char *rdc_last_error_detail(int err);
/* The name of a device error code (enum rdc_err), e.g. "RANGE". */
const char *rdc_dev_strerror(uint32_t code);

typedef struct rdc_dev rdc_dev;
typedef struct rdc_batch rdc_batch;

/* ---- Device -------------------------------------------------------------- */
int rdc_open(const char *uri, rdc_dev **out);

/* One device rdc_list found (the library's memory; grows at its end). */
struct rdc_found {
	char uri[160];	/* what rdc_open takes (rdcctl --connect) */
	char info[160]; /* what it is, for people */
};
typedef void (*rdc_found_fn)(const struct rdc_found *f, void *arg);
/*
 * Every RDC-1 this machine reaches: USB devices with the RDC-1 interface
 * (usb:BUS-PORT..., with IDs and serial), rdcd sockets in the default
 * directory that answer a HELLO (rdc_proto_default_path), and rdcfb.ko's
 * framebuffers.  Calls fn once for each; returns how many.
 */
int rdc_list(rdc_found_fn fn, void *arg);
void rdc_close(rdc_dev *dev);
/* Chip reset (RDC_CONTROL_SOFT_RESET). */
int rdc_reset(rdc_dev *dev);
/* The device error (enum rdc_err) behind the last RDC_E_DEVICE, and its
 * ERR_INFO word; reading clears the device's error status. */
int rdc_dev_error(rdc_dev *dev, uint32_t *code, uint32_t *info);

int rdc_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val);
int rdc_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val);

int rdc_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len);
int rdc_vram_write(rdc_dev *dev, uint32_t addr, const void *buf, size_t len);

/*
 * Program a preset mode with a framebuffer at `base` in `format`, stride
 * the packed row size rounded up to 4 bytes, and point the DP's destination
 * and source surfaces and clip at it.  Takes effect at the next vblank.
 */
int rdc_mode_set(rdc_dev *dev, uint32_t preset, uint32_t format, uint32_t base);
/* Mode size of a preset (no device needed); 0 or RDC_E_INVAL. */
int rdc_preset_size(uint32_t preset, uint32_t *width, uint32_t *height);
/*
 * Preset by name ("640x480", "640x480@60", "1080p", in any case); -1 if
 * unknown.
 */
int rdc_preset_by_name(const char *name);

/* ---- Command submission -------------------------------------------------- */
/*
 * Push command words into the FIFO.  When it is full the call waits
 * (advancing simulated time on sim:) until the DP makes room: that is the
 * back-pressure.  Returns RDC_E_HALTED if the DP halted.
 */
int rdc_submit(rdc_dev *dev, const uint32_t *words, size_t n);
/*
 * Submit a FENCE with a fresh value and wait until the DP has executed it
 * and is idle, i.e. every command submitted before has completed.
 * RDC_E_DEVICE if the device has a pending error (ERR_CODE), RDC_E_HALTED,
 * RDC_E_TIMEOUT after ten simulated seconds.
 */
int rdc_finish(rdc_dev *dev);
/* Wait until FENCE >= value (wrapping compare); RDC_E_DEVICE as above. */
int rdc_fence_wait(rdc_dev *dev, uint32_t value);
/* Wait for the start of the next vertical blanking (host side). */
int rdc_vblank_wait(rdc_dev *dev);
/*
 * Wait until the DP is idle: FIFO empty, no command in progress or
 * waiting.  Unlike rdc_finish it adds no command, so the performance
 * counters (PERF_LAST_*) still describe the last command submitted.
 * RDC_E_DEVICE if the device has a pending error.
 */
int rdc_idle_wait(rdc_dev *dev);
/*
 * Screen to host: read a w x h rectangle at (x, y) of the SRC surface
 * through the DP's READBACK command into buf (rows of SRC-format pixels,
 * each padded to 4 bytes); `cap` is buf's size in bytes.  Returns bytes
 * written, RDC_E_RANGE if they did not fit (the data is drained all the
 * same), or RDC_E_DEVICE if the device refused the rectangle.
 */
int rdc_readback(rdc_dev *dev, int x, int y, uint32_t w, uint32_t h, void *buf,
		 size_t cap);
/*
 * Host to screen: copy w x h pixels (DST format, rows `pitch` bytes apart)
 * to (x, y) of the DST surface, split into HOST_BLIT commands that fit
 * RDC_CMD_MAX_ARGS.  The DST format is the one of the last SET_DST this
 * handle sent (rdc_mode_set, batches), else the scanout format.  Returns
 * once the words are queued; rdc_finish waits for the drawing.
 */
int rdc_host_blit(rdc_dev *dev, int x, int y, uint32_t w, uint32_t h,
		  const void *pixels, size_t pitch);

/* ---- Frames -------------------------------------------------------------- */
/*
 * Copy the last complete scanned-out frame (XRGB8888, width*height words)
 * into buf of `cap` words.  Returns RDC_E_RANGE if cap is too small (so
 * cap 0 and buf NULL asks for the size), RDC_E_NOSYS if the backend cannot
 * see frames (never on sim:).  width and height are set whenever a frame
 * exists; before the first frame the call waits for one vblank, and for a
 * frame the chip did not keep (scanout on demand: nobody looked while it
 * was scanned, and the picture changed under it) for up to two.
 */
int rdc_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap, uint32_t *width,
		   uint32_t *height);
/* CRC-32 (zlib) of the last complete frame's XRGB8888 bytes (each pixel
 * as the little-endian word 0xXXRRGGBB, i.e. bytes B, G, R, X). */
int rdc_frame_crc(rdc_dev *dev, uint32_t *crc);
/*
 * Wait until a frame scanned out entirely after this call, with the
 * latched registers (mode, FB_BASE, ...) written before it in force, has
 * completed, so that rdc_frame_grab shows everything done before it: two
 * vblanks.
 */
int rdc_frame_wait(rdc_dev *dev);

/* ---- Batches: encode commands, then submit them -------------------------- */
/*
 * A batch is a growable array of command words.  Encoders do not check
 * arguments (the device validates, so bad commands can be sent on
 * purpose); they fail only with RDC_E_NOMEM, or RDC_E_INVAL for a NULL
 * pointer or a command whose length does not fit RDC_CMD_LENGTH.
 */
rdc_batch *rdc_batch_new(void);
void rdc_batch_free(rdc_batch *b);
void rdc_batch_reset(rdc_batch *b);
const uint32_t *rdc_batch_words(const rdc_batch *b, size_t *n);
int rdc_batch_submit(rdc_dev *dev, rdc_batch *b); /* then empties b */
/* Raw command: header from op/flags and `n` argument words. */
int rdc_batch_cmd(rdc_batch *b, uint32_t op, uint32_t flags,
		  const uint32_t *args, size_t n);

int rdc_batch_nop(rdc_batch *b);
int rdc_batch_fence(rdc_batch *b, uint32_t value);
int rdc_batch_wait_vblank(rdc_batch *b);
int rdc_batch_wait_line(rdc_batch *b, uint32_t line);
int rdc_batch_reg_write(rdc_batch *b, uint32_t reg, uint32_t val);
int rdc_batch_load_clut(rdc_batch *b, uint32_t first, const uint32_t *rgb,
			size_t n);
int rdc_batch_fg(rdc_batch *b, uint32_t pixel);
/*
 * FG for the command that comes next: carried in it (RDC_DRAW_FG, one
 * command where rdc_batch_fg and it are two, the same drawing and the
 * same FG after it) when it is a drawing command that takes it
 * (rdc_cmd_takes_fg: pixels, lines, rectangles, circles, ellipses,
 * arcs, polygons and their anti-aliased kinds); before any other, or
 * rdc_batch_cmd, the SET_FG rdc_batch_fg encodes.
 */
int rdc_batch_fg_next(rdc_batch *b, uint32_t pixel);
int rdc_batch_bg(rdc_batch *b, uint32_t pixel);
int rdc_batch_rop(rdc_batch *b, uint32_t rop);
int rdc_batch_clip(rdc_batch *b, int x0, int y0, int x1, int y1);
int rdc_batch_dst(rdc_batch *b, uint32_t base, uint32_t stride, uint32_t w,
		  uint32_t h, uint32_t format);
int rdc_batch_src(rdc_batch *b, uint32_t base, uint32_t stride, uint32_t w,
		  uint32_t h, uint32_t format);
int rdc_batch_pixel(rdc_batch *b, int x, int y);
int rdc_batch_line(rdc_batch *b, int x0, int y0, int x1, int y1);
/* xy: n points as x0, y0, x1, y1, ... */
int rdc_batch_polyline(rdc_batch *b, const int *xy, size_t n);
int rdc_batch_rect(rdc_batch *b, int x, int y, uint32_t w, uint32_t h);
int rdc_batch_fill_rect(rdc_batch *b, int x, int y, uint32_t w, uint32_t h);
int rdc_batch_circle(rdc_batch *b, int cx, int cy, uint32_t r);
int rdc_batch_fill_circle(rdc_batch *b, int cx, int cy, uint32_t r);
int rdc_batch_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx, uint32_t ry);
int rdc_batch_fill_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx,
			   uint32_t ry);
int rdc_batch_blit(rdc_batch *b, int sx, int sy, int dx, int dy, uint32_t w,
		   uint32_t h);
/* bits: h rows of ceil(w/8) bytes, bit 7 leftmost (padded into words here). */
int rdc_batch_mono(rdc_batch *b, int x, int y, uint32_t w, uint32_t h,
		   const uint8_t *bits, int transparent);
/*
 * rdc_batch_mono with its colours, in one command: fg and bg become the
 * DP's FG and BG, as rdc_batch_fg and rdc_batch_bg before it would set
 * them (a console's glyph, which comes with its colours).
 */
int rdc_batch_mono_colors(rdc_batch *b, int x, int y, uint32_t w, uint32_t h,
			  const uint8_t *bits, uint32_t fg, uint32_t bg,
			  int transparent);
int rdc_batch_text(rdc_batch *b, int x, int y, const char *s, size_t len,
		   int transparent);
/* Pens and dashes: width 1..RDC_PEN_MAX_WIDTH, enum rdc_cap, enum rdc_join;
 * dash pattern bit 0 first, len 0..32 (0 = solid), offset 0..63. */
int rdc_batch_pen(rdc_batch *b, uint32_t width, uint32_t cap, uint32_t join);
int rdc_batch_dash(rdc_batch *b, uint32_t pattern, uint32_t len,
		   uint32_t offset);
/* Closed outline through n points (xy as for polyline). */
int rdc_batch_polygon(rdc_batch *b, const int *xy, size_t n);
/* Angles in 1/65536 turn, counter-clockwise from +x, y up; enum
 * rdc_arc_mode. */
int rdc_batch_arc(rdc_batch *b, int cx, int cy, uint32_t rx, uint32_t ry,
		  uint32_t start, uint32_t end, uint32_t mode);
/* Curves: xy holds 4 points (HERMITE: p0, p1, tangent t0, tangent t1);
 * steps 0..RDC_CURVE_MAX_STEPS, 0 = chosen by the device. */
int rdc_batch_bezier(rdc_batch *b, const int *xy, uint32_t steps);
int rdc_batch_hermite(rdc_batch *b, const int *xy, uint32_t steps);
int rdc_batch_bspline(rdc_batch *b, const int *xy, size_t n, uint32_t steps);
/* m: 9 entries m00 m01 m02 m10 m11 m12 m20 m21 m22 in signed 15.16, or
 * NULL for the identity. */
int rdc_batch_transform(rdc_batch *b, const int32_t *m);
/* World window in signed 15.16 onto the viewport's corner pixels. */
int rdc_batch_viewport(rdc_batch *b, int32_t wx0, int32_t wy0, int32_t wx1,
		       int32_t wy1, int x0, int y0, int x1, int y1);
/* Filled polygon through n >= 3 points; even-odd unless nonzero. */
int rdc_batch_fill_polygon(rdc_batch *b, const int *xy, size_t n, int nonzero);
/* Flood fill from (x, y); flags RDC_FLOOD_8 | RDC_FLOOD_BOUNDARY, the
 * boundary pixel value used only with RDC_FLOOD_BOUNDARY. */
int rdc_batch_flood(rdc_batch *b, int x, int y, uint32_t flags,
		    uint32_t boundary);
/* Fill patterns, anchored at the DST origin: none (solid FG); 8 rows of
 * 8 bits, bit 7 leftmost, 1 = FG, 0 = BG or left alone; 64 pixel values
 * row by row. */
int rdc_batch_pattern_none(rdc_batch *b);
int rdc_batch_pattern_mono(rdc_batch *b, const uint8_t rows[8],
			   int transparent);
int rdc_batch_pattern_color(rdc_batch *b, const uint32_t px[64]);
/* Triangle: xy holds 3 points, colour and z (0..65535) one per vertex;
 * flat shading uses colour[0]. */
int rdc_batch_triangle(rdc_batch *b, const int *xy, const uint32_t *colour,
		       const uint32_t *z, int gouraud);
/* Depth buffer: 16-bit surface the size of DST at base, stride bytes a
 * row; flags RDC_Z_TEST | RDC_Z_WRITE.  zbuf_off turns it off. */
int rdc_batch_zbuf(rdc_batch *b, uint32_t base, uint32_t stride,
		   uint32_t flags);
int rdc_batch_zbuf_off(rdc_batch *b);
int rdc_batch_clear_z(rdc_batch *b, uint32_t value);
/* Anti-aliased line, circle and ellipse (blended in RGB formats, through
 * the CLUT ramp of aa_ramp entries from FG, 2..256, in indexed ones). */
int rdc_batch_aa_line(rdc_batch *b, int x0, int y0, int x1, int y1);
int rdc_batch_aa_circle(rdc_batch *b, int cx, int cy, uint32_t r);
int rdc_batch_aa_ellipse(rdc_batch *b, int cx, int cy, uint32_t rx,
			 uint32_t ry);
int rdc_batch_aa_ramp(rdc_batch *b, uint32_t n);
/* BLIT / HOST_BLIT: global alpha 0..255 (255 opaque), and the source
 * colour key (pixels equal to key are not drawn) when enable is set. */
int rdc_batch_alpha(rdc_batch *b, uint32_t alpha);
int rdc_batch_colorkey(rdc_batch *b, uint32_t key, int enable);
/* Display lists: command words stored in VRAM (rdc_vram_write) at a
 * 4-aligned byte address, run by CALL (back after the CALL at RET) or
 * JUMP; nesting up to RDC_CALL_DEPTH. */
int rdc_batch_call(rdc_batch *b, uint32_t addr);
int rdc_batch_ret(rdc_batch *b);
int rdc_batch_jump(rdc_batch *b, uint32_t addr);

/* ---- Pins ---------------------------------------------------------------- */
/*
 * The RDC-1's four pins (RDC_PIN_* of rdc_regs.h): TE (high during
 * vertical blanking) and IRQ (high while an enabled interrupt is raised)
 * are the chip's outputs; RESET_N (low holds the chip in reset, releasing
 * it resets it again) and BL_EN (low darkens the panel) are its inputs,
 * which the host drives.  They start high.
 *
 * sim:, unix:, tcp: and usb: reach them through the register PINS and the
 * wire protocol (a daemon lets only its controlling client drive them).
 * fbdev: and drm: reach them as GPIO lines, with libgpiod, on the
 * gpio_chip rdcfb.ko or rdcdrm.ko registers for the device (label
 * "rdcfb.N-pins" or "rdcdrm.N-pins" after the node's device, lines "TE",
 * "IRQ", "RESET_N", "BL_EN"); built without libgpiod, every rdc_pins_*
 * call on fbdev: and drm: returns RDC_E_NOSYS.
 */
#define RDC_PINS_OUT (RDC_PIN_TE | RDC_PIN_IRQ)	       /* driven by the chip */
#define RDC_PINS_IN  (RDC_PIN_RESET_N | RDC_PIN_BL_EN) /* driven by the host */
#define RDC_PINS_ALL (RDC_PINS_OUT | RDC_PINS_IN)

#define RDC_EDGE_RISING	 0x1u
#define RDC_EDGE_FALLING 0x2u
#define RDC_EDGE_BOTH	 (RDC_EDGE_RISING | RDC_EDGE_FALLING)
/*
 * With the kinds: a watcher's stream.  An edge that came after the
 * previous wait on this device returned counts too, though it came
 * before this call (fbdev: and drm: queue their GPIO lines' edges), so a
 * loop of waits sees every edge, as gpiomon does.  Without it a wait is
 * for an edge after the call.  sim: and the daemons start every wait
 * from the levels they find; there it changes nothing.
 */
#define RDC_EDGE_QUEUED 0x4u

/* rdc_pin_edge.time when the backend does not know the simulated time. */
#define RDC_PIN_TIME_NONE UINT64_MAX

struct rdc_pin_edge {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	/* pins (RDC_PINS_OUT bits) with a wanted edge at this moment: a pin
	 * rose if its bit is set in `levels`, else it fell */
	uint32_t pins;
	uint32_t levels; /* all four pins right after the edge */
	/*
	 * Simulated core cycles of the edge.  sim:: the exact cycle the pin
	 * changed.  unix:, tcp:, usb:: the time the daemon saw the new
	 * level, at most one wait slice (RDC_WAIT_SLICE_MAX cycles) after
	 * the edge on a stepped daemon, one turn of its loop (about a
	 * millisecond) on a paced or fast one.  fbdev:: RDC_PIN_TIME_NONE.
	 */
	uint64_t time;
	/* CLOCK_MONOTONIC nanoseconds: when the library learnt of the edge
	 * (fbdev:: the kernel's timestamp of the GPIO edge event) */
	uint64_t wall_ns;
};

/* The four levels as RDC_PIN_* bits. */
int rdc_pins_get(rdc_dev *dev, uint32_t *levels);
/*
 * Drive the inputs in `mask` (RDC_PINS_IN bits; others are RDC_E_INVAL)
 * to their bits in `levels`; the others keep theirs.  RDC_E_BUSY for a
 * daemon's observer.  fbdev: requests the lines it drives and holds them
 * until rdc_close (rdcfb.ko keeps their last level after).
 */
int rdc_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels);
/*
 * Wait for the next edge of a kind in `edges` (RDC_EDGE_*) on a pin of
 * `pins` (RDC_PINS_OUT bits, else RDC_E_INVAL) and describe it in *ev:
 * the next after the call, on every backend (fbdev: and drm: let the
 * edges their GPIO lines queued before it go by, unless RDC_EDGE_QUEUED).
 * timeout_us bounds the wait in the device's time: simulated time on
 * sim:, unix:, tcp:, usb: (wall time too on a paced daemon), wall time
 * on fbdev:; 0 means ten seconds.  RDC_E_TIMEOUT when it runs out.  On
 * sim: and a stepped daemon simulated time moves inside the wait.  The
 * register path sees levels, so a pulse shorter than a wait slice can
 * go unseen; TE's (a whole vertical blanking) and IRQ's (until the
 * status is cleared) cannot.
 */
int rdc_pins_wait_edge_sized(rdc_dev *dev, uint32_t pins, uint32_t edges,
			     uint64_t timeout_us, struct rdc_pin_edge *ev);
static inline int rdc_pins_wait_edge(rdc_dev *dev, uint32_t pins,
				     uint32_t edges, uint64_t timeout_us,
				     struct rdc_pin_edge *ev)
{
	if (ev)
		ev->size = sizeof(*ev);
	return rdc_pins_wait_edge_sized(dev, pins, edges, timeout_us, ev);
}
/*
 * Present on TE: wait for TE's rising edge (the start of vertical
 * blanking) as rdc_pins_wait_edge does, then submit the batch (and empty
 * it), so that drawing starts in blanking and a short update never
 * tears.  ev (may be NULL) receives the edge.
 */
int rdc_pins_present_sized(rdc_dev *dev, rdc_batch *b, uint64_t timeout_us,
			   struct rdc_pin_edge *ev);
static inline int rdc_pins_present(rdc_dev *dev, rdc_batch *b,
				   uint64_t timeout_us, struct rdc_pin_edge *ev)
{
	if (ev)
		ev->size = sizeof(*ev);
	return rdc_pins_present_sized(dev, b, timeout_us, ev);
}

/* ---- Introspection for hardware-model tests (sim: only) ------------------ */
struct rdc_stats {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	uint64_t time; /* simulated core cycles */
	uint64_t busy, stall, pixels;
	uint32_t cmds, last_cycles, last_opcode;
	uint64_t frames; /* vblanks since reset */
};

int rdc_sim_time(rdc_dev *dev, uint64_t *cycles);
/* Advance simulated time by `cycles` (the DP runs meanwhile). */
int rdc_sim_step(rdc_dev *dev, uint64_t cycles);
/* Advance simulated time to at least `t`. */
int rdc_sim_run_until(rdc_dev *dev, uint64_t t);
int rdc_sim_beam(rdc_dev *dev, uint32_t *x, uint32_t *y);
int rdc_stats_get_sized(rdc_dev *dev, struct rdc_stats *st);
static inline int rdc_stats_get(rdc_dev *dev, struct rdc_stats *st)
{
	if (st)
		st->size = sizeof(*st);
	return rdc_stats_get_sized(dev, st);
}
/* Core clock in Hz (for converting cycles to time). */
int rdc_sim_core_hz(rdc_dev *dev, uint32_t *hz);

/*
 * ---- Waveforms (sim: only) -----------------------------------------------
 * A Value Change Dump (IEEE 1364) of the chip's signals in simulated time:
 * TE, IRQ, RESET_N, BL_EN, DP busy, the FIFO level, the beam's line,
 * vertical and horizontal blanking (docs/vcd.md).  The
 * file is written as the chip runs, through a buffer.
 */
typedef struct rdc_vcd rdc_vcd;

/*
 * Start dumping dev's signals to `path` (created or truncated) from its
 * present time on.  The dump listens on the chip's trace hook and passes
 * every event on to a listener that was there before.  RDC_E_NOSYS on a
 * backend other than sim: (the signals are traced inside the simulator),
 * RDC_E_FILE if the file cannot be created.  Close it before dev, and
 * several dumps of one handle in the reverse order of opening.
 */
int rdc_vcd_open(rdc_dev *dev, const char *path, rdc_vcd **out);
/*
 * End the dump at the chip's present time, flush and close the file
 * (NULL is a no-op).  0, or RDC_E_FILE if any write failed.
 */
int rdc_vcd_close(rdc_vcd *vcd);

/* ---- .rdl scripts (docs/rdl.md) ------------------------------------------ */
struct rdc_script_result {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	/* cycles spent per command class ("fill", "line", ...), index by
	 * the opcode; counts likewise */
	uint64_t op_cycles[256];
	uint64_t op_count[256];
	uint32_t error_line; /* script line of a parse or device error */
	uint32_t error_col;  /* 1-based column of a lexical error, else 0 */
	char error_msg[160];
	/* readback statements: how many ran; CRC-32 (zlib) and word count
	 * of the data the last one read */
	uint32_t readbacks;
	uint32_t readback_crc;
	uint32_t readback_words;
	/* 1 if the last statement was `vsync`: the frame that just completed
	 * is the script's picture (mid-frame effects); else the picture is
	 * the next frame scanned entirely after the script (rdc_frame_wait) */
	uint32_t frame_ready;
};

/*
 * Make the script's picture current: rdc_frame_wait unless
 * res->frame_ready.  rdcctl run and the golden tests use this.
 */
int rdc_script_frame_wait(rdc_dev *dev, const struct rdc_script_result *res);

/*
 * Run a script: parse it line by line, encode and submit its commands, and
 * wait for the device to finish each statement.  Returns 0 or the error of
 * the first failing statement (RDC_E_PARSE for syntax, RDC_E_DEVICE when
 * the device flagged a command, ...), with res->error_line (1-based) and
 * res->error_msg set.  `screenshot` paths are relative to the current
 * directory.  res may be NULL.
 */
int rdc_script_run_sized(rdc_dev *dev, const char *text, size_t len,
			 struct rdc_script_result *res);
int rdc_script_run_file_sized(rdc_dev *dev, const char *path,
			      struct rdc_script_result *res);
static inline int rdc_script_run(rdc_dev *dev, const char *text, size_t len,
				 struct rdc_script_result *res)
{
	if (res)
		res->size = sizeof(*res);
	return rdc_script_run_sized(dev, text, len, res);
}
static inline int rdc_script_run_file(rdc_dev *dev, const char *path,
				      struct rdc_script_result *res)
{
	if (res)
		res->size = sizeof(*res);
	return rdc_script_run_file_sized(dev, path, res);
}
/* Name of an opcode ("fill-rect"), or NULL. */
const char *rdc_op_name(uint32_t op);

/* The register table: rdc_reg_count() entries; rdc_reg_info(i, &off)
 * gives the name ("CLUT_INDEX") and offset, NULL past the end. */
size_t rdc_reg_count(void);
const char *rdc_reg_info(size_t i, uint32_t *reg);
/* Offset of a register by name, case-insensitive, "RDC_REG_" optional;
 * 0 or RDC_E_INVAL. */
int rdc_reg_by_name(const char *name, uint32_t *reg);

/* ---- Events from a daemon (unix:, tcp:) ---------------------------------- */
#define RDC_EVENT_FRAME 0x1u /* a frame (every Nth) */
#define RDC_EVENT_IRQ	0x2u /* interrupt status bits that became set */

/* Frame encodings on the wire (docs/protocol.md); pixels arrive decoded. */
#define RDC_FRAME_RAW	0u
#define RDC_FRAME_RLE	1u
#define RDC_FRAME_DELTA 2u /* rows unchanged since the last frame skipped */

struct rdc_event {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	uint32_t type;		/* RDC_EVENT_FRAME or RDC_EVENT_IRQ */
	uint32_t irq;		/* IRQ: the new RDC_IRQ_* bits */
	uint64_t time;		/* IRQ: simulated time of the check */
	uint64_t number;	/* FRAME: frame number since reset */
	uint32_t width, height; /* FRAME: pixels stored in buf */
	uint32_t dropped;	/* FRAME: frames dropped for this client */
};

/*
 * Ask the daemon for events: `events` is a mask of RDC_EVENT_*, frames
 * come every `every`th frame (1 = all) in `encoding` (RDC_FRAME_*).  A
 * subscriber that does not keep up loses frames (counted in `dropped`),
 * never stalls the device.  RDC_E_NOSYS on backends without a daemon.
 */
int rdc_subscribe(rdc_dev *dev, uint32_t events, uint32_t every,
		  uint32_t encoding);
/*
 * The next event; a frame's XRGB8888 pixels go to buf (cap words,
 * RDC_E_RANGE if too small: the event is consumed).  Waits up to
 * timeout_ms of wall time (< 0: forever), else RDC_E_TIMEOUT.
 */
int rdc_event_next_sized(rdc_dev *dev, struct rdc_event *ev, uint32_t *buf,
			 size_t cap, int timeout_ms);
static inline int rdc_event_next(rdc_dev *dev, struct rdc_event *ev,
				 uint32_t *buf, size_t cap, int timeout_ms)
{
	if (ev)
		ev->size = sizeof(*ev);
	return rdc_event_next_sized(dev, ev, buf, cap, timeout_ms);
}

/* ---- Traces (rdcd --record) ---------------------------------------------- */
struct rdc_replay_result {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	uint64_t records;    /* operations replayed */
	uint64_t mismatches; /* times or register values that differ */
	uint64_t time;	     /* simulated time at the end */
	uint64_t frames;     /* frames completed during the replay */
	uint32_t frame_crc;  /* CRC-32 of the last frame (0 if none) */
	uint32_t width, height;
	/* CRC-32 of every frame's CRC-32 in order, as little-endian u32s */
	uint32_t frames_crc;
	/* 1: the trace ends without its END record (the recorder is still
	 * running, or was killed); everything up to its last complete
	 * record was replayed */
	uint32_t truncated;
	/* 1: the trace has no times (rdc_record_start on a device without
	 * a chip in this process): its operations ran in order, and only
	 * their results were compared; `time` is the replay's own */
	uint32_t untimed;
};

/*
 * Play a trace back on a fresh sim: device: the same operations at the
 * same simulated times give the same frames and cycle counts.  A trace
 * rdc_record_start wrote starts with the state of the device then (its
 * registers, CLUT, VRAM and, where the device tells, its time, frame
 * phase and counters: docs/protocol.md, "Traces"); the fresh device
 * starts there.  `dev_out`
 * (may be NULL) receives the device afterwards, for the caller to
 * inspect and rdc_close.  RDC_E_FILE, RDC_E_PARSE for a damaged trace
 * (rdc_last_error_detail says where); a trace cut short is not damaged:
 * 0 with res->truncated set.
 */
int rdc_replay_file_sized(const char *path, struct rdc_replay_result *res,
			  rdc_dev **dev_out);
static inline int rdc_replay_file(const char *path,
				  struct rdc_replay_result *res,
				  rdc_dev **dev_out)
{
	if (res)
		res->size = sizeof(*res);
	return rdc_replay_file_sized(path, res, dev_out);
}

/*
 * A fresh sim: device as the trace at `path` starts: its STATE record
 * replayed (rdc_record_start's traces), and nothing after it; of a trace
 * without one, a fresh sim: of its VRAM size.  For running something
 * else from the same start (`rdcctl diff` of a trace and a script).
 * RDC_E_FILE, RDC_E_PARSE as rdc_replay_file.
 */
int rdc_replay_open(const char *path, rdc_dev **dev);

/*
 * Record every operation this handle makes on its device, from now until
 * rdc_record_stop or rdc_close, into a trace at `path` (created or
 * truncated) that rdc_replay_file and `rdcctl replay`, `why`, `diff`
 * take, on any device: register writes, reads with the value read, VRAM
 * writes, command words, waits with their result, steps and pin changes
 * (docs/protocol.md, "Traces").  A sim: handle's trace carries the
 * simulated time of each; any other device's is untimed (its time would
 * cost an operation of its own to ask, and be late on a paced device):
 * replay runs its operations in order and compares what they returned,
 * not when.  Only this handle's operations are recorded, not another
 * client's of the same daemon, nor what rdcfb.ko's console draws; the
 * trace starts with the device's state (the DP first finishes what it
 * has queued), so a replay starts where the recording did.
 * RDC_E_BUSY if the handle is already recorded, RDC_E_FILE if the file
 * cannot be written (rdc_last_error_detail says why).  While recording,
 * rdc_pins_get and rdc_pins_wait read the register PINS through the
 * recorder (on fbdev: instead of the GPIO lines: the same levels).
 */
int rdc_record_start(rdc_dev *dev, const char *path);
/*
 * Write the trace's end and close it; the handle goes on unrecorded.
 * RDC_E_FILE if a write failed (the trace is incomplete), RDC_E_INVAL
 * if the handle was not recorded.  rdc_close ends a recording too.
 */
int rdc_record_stop(rdc_dev *dev);

/* ---- Compressed images (the DECODE command) ------------------------------ */
/*
 * Streams in the formats of rdc_image.h (RDC_IMG_RLE, RDC_IMG_DPCM,
 * RDC_IMG_BTC, RDC_IMG_HUFF, RDC_IMG_DPCMQ, RDC_IMG_DCT), for the DP to
 * decode from VRAM.  Samples are 8 bits, a
 * pixel is `channels` of them: 1 (grey or a CLUT index) or 3 (R, G, B);
 * w 1..RDC_IMG_MAX_WIDTH, h 1..RDC_IMG_MAX_HEIGHT.
 */
/* Largest stream rdc_image_encode can write for such an image; 0 if bad. */
size_t rdc_image_bound(uint32_t codec, uint32_t w, uint32_t h,
		       uint32_t channels);
/*
 * Encode w x h pixels (rows `pitch` bytes apart) into out (cap bytes);
 * *len gets the stream's size, header included.  RDC_E_INVAL for a bad
 * codec, size or channel count; RDC_E_RANGE if cap is too small (*len
 * says how much was needed); RDC_E_NOMEM.  RLE, DPCM and HUFF are
 * lossless; BTC keeps each 4x4 block's mean within 1/2 and every sample
 * within its block's range (max - min).  HUFF's code is built for the
 * picture (code lengths at most 16 bits).  DPCMQ quantises with the step
 * RDC_IMAGE_STEP_DEFAULT, DCT at the quality RDC_IMAGE_QUALITY_DEFAULT
 * (rdc_image_encode_lossy chooses another).
 */
int rdc_image_encode(uint32_t codec, const uint8_t *px, uint32_t w, uint32_t h,
		     uint32_t channels, size_t pitch, uint8_t *out, size_t cap,
		     size_t *len);

#define RDC_IMAGE_STEP_DEFAULT	  4u  /* DPCMQ: samples within 2 */
#define RDC_IMAGE_QUALITY_DEFAULT 75u /* DCT: as IJG's cjpeg */
/*
 * rdc_image_encode for a lossy codec with its level: for RDC_IMG_DPCMQ
 * the quantiser's step (1..255; every sample within step / 2 of the
 * original, 1 is lossless); for RDC_IMG_DCT the quality 1..100, which
 * scales JPEG's luminance quantisation table as IJG's libjpeg does (50:
 * the table itself, 100: all ones).  RDC_E_INVAL for another codec or a
 * level out of range.
 */
int rdc_image_encode_lossy(uint32_t codec, uint32_t level, const uint8_t *px,
			   uint32_t w, uint32_t h, uint32_t channels,
			   size_t pitch, uint8_t *out, size_t cap, size_t *len);
/*
 * XRGB8888 pixels (rows `pitch` words apart) to w * h * channels samples:
 * channels 3 gives R, G, B; 1 the luma (77 R + 150 G + 29 B + 128) >> 8.
 */
int rdc_image_samples(const uint32_t *xrgb, uint32_t w, uint32_t h,
		      size_t pitch, uint32_t channels, uint8_t *out);
/*
 * Read a PNG as XRGB8888 into a new buffer (*xrgb, to be released with
 * free()).  RDC_E_FILE (unreadable, not a PNG), RDC_E_RANGE past
 * RDC_IMG_MAX_WIDTH x RDC_IMG_MAX_HEIGHT, RDC_E_NOMEM.
 */
int rdc_image_png_read(const char *path, uint32_t **xrgb, uint32_t *w,
		       uint32_t *h);

/* ---- Pixel history (docs/history.md) ------------------------------------- */
/*
 * Every VRAM write that touches a watched rectangle of the screen (the
 * framebuffer as FB_BASE, FB_STRIDE, FB_FORMAT and the mode hold it at the
 * write, which the next vblank latches), one entry per pixel per write,
 * in the order the writes land.  sim: only (RDC_E_NOSYS elsewhere); off
 * until rdc_history_open, and then sizeof(struct rdc_history_entry) + 8
 * bytes an entry (RDC_HISTORY_LIMIT_DEFAULT entries, then they are
 * counted in rdc_history_dropped).
 */
typedef struct rdc_history rdc_history;

#define RDC_HISTORY_SCREEN	  UINT32_MAX /* w or h: to the screen's edge */
#define RDC_HISTORY_WRITES	  1u /* also log every write access (diff) */
#define RDC_HISTORY_LIMIT_DEFAULT (1u << 20)
#define RDC_HISTORY_OP_HOST	  0x100u /* opcode of a host aperture write */

enum rdc_history_source {
	RDC_HISTORY_SRC_FIFO, /* a command from FIFO_DATA */
	RDC_HISTORY_SRC_RING, /* from the ring */
	RDC_HISTORY_SRC_LIST, /* from a display list (calls[] the chain) */
	RDC_HISTORY_SRC_HOST, /* the host wrote VRAM through the aperture */
};

struct rdc_history_entry {
	/* sizeof(struct), set by the call (see "Structures that grow") */
	uint32_t size;
	uint32_t x, y;	 /* the pixel, screen coordinates */
	uint32_t format; /* the screen's RDC_FMT_* (before/after's) */
	uint32_t before; /* pixel value before the write, raw */
	uint32_t after;	 /* and after it (equal: written, unchanged) */
	uint64_t cycle;	 /* end of the bus access that wrote it */
	uint64_t frame;	 /* frames scanned out before this one */
	/*
	 * 1: scanout had already fetched line y of frame `frame`, which
	 * shows `before`; frame + 1 shows `after`.  0: not yet: frame
	 * `frame` shows `after`.  -1: scanout was stopped.
	 */
	int32_t fetched;
	uint32_t opcode;    /* RDC_OP_*, or RDC_HISTORY_OP_HOST */
	uint32_t cmd_index; /* commands the DP had finished (PERF_CMDS) */
	uint32_t source;    /* enum rdc_history_source */
	uint32_t line;	    /* .rdl line of the statement running, 0: none */
	uint32_t cmd_addr;  /* SRC_LIST: VRAM address of the command */
	/* SRC_LIST: lists entered, and the return address in each caller,
	 * outermost first (calls[0 .. depth - 2]) */
	uint32_t depth;
	uint32_t calls[8];
	/* the DP's drawing state the command ran with */
	uint32_t rop, alpha, colorkey, colorkey_on, pattern, fg, bg;
};

/* One write access (RDC_HISTORY_WRITES): `count` runs of `len` bytes,
 * `stride` apart; entry holds its command (x, y, before, after unused). */
struct rdc_history_write {
	uint32_t size;
	uint32_t addr, len, count, stride;
	uint64_t hash; /* FNV-1a of the bytes once written */
	struct rdc_history_entry entry;
};

/*
 * Watch the rectangle x, y, w, h of the screen (RDC_HISTORY_SCREEN for
 * w and h: all of it) from now on.  One history a device.  RDC_E_BUSY if
 * one is open already.
 */
int rdc_history_open(rdc_dev *dev, uint32_t x, uint32_t y, uint32_t w,
		     uint32_t h, uint32_t flags, rdc_history **out);
/* Keep at most max_entries entries (default RDC_HISTORY_LIMIT_DEFAULT). */
int rdc_history_set_limit(rdc_history *h, size_t max_entries);
size_t rdc_history_count(rdc_history *h);
/* Entries not kept (over the limit, out of memory). */
uint64_t rdc_history_dropped(rdc_history *h);
int rdc_history_get_sized(rdc_history *h, size_t i,
			  struct rdc_history_entry *e);
static inline int rdc_history_get(rdc_history *h, size_t i,
				  struct rdc_history_entry *e)
{
	if (e)
		e->size = sizeof(*e);
	return rdc_history_get_sized(h, i, e);
}
size_t rdc_history_write_count(rdc_history *h);
int rdc_history_write_get_sized(rdc_history *h, size_t i,
				struct rdc_history_write *w);
static inline int rdc_history_write_get(rdc_history *h, size_t i,
					struct rdc_history_write *w)
{
	if (w)
		w->size = sizeof(*w);
	return rdc_history_write_get_sized(h, i, w);
}
/*
 * Where two runs part (both opened with RDC_HISTORY_WRITES): *index gets
 * the first write access that differs in place or in the bytes written
 * (or the first one only one of them made).  1 if they differ, 0 if
 * they made the same writes.
 */
int rdc_history_first_diff(rdc_history *a, rdc_history *b, size_t *index);

/* Which write set the CLUT entry an indexed pixel shows (struct below). */
enum rdc_history_clut_source {
	/* no entry of the raster list in force writes it: the host's
	 * (CLUT_DATA, LOAD_CLUT) */
	RDC_HISTORY_CLUT_HOST,
	/* a raster-list entry, earlier in the frame than the pixel */
	RDC_HISTORY_CLUT_LIST,
	/* the list's last write of it, in the frame before (nothing in the
	 * list before the pixel writes it, and nothing puts it back) */
	RDC_HISTORY_CLUT_LIST_PREV,
};

struct rdc_history_clut {
	uint32_t size;	 /* sizeof(struct), set by the call */
	uint32_t x, y;	 /* the pixel, screen coordinates */
	uint32_t format; /* the screen's RDC_FMT_* */
	uint32_t index;	 /* the pixel's value: the CLUT entry it shows */
	uint32_t source; /* enum rdc_history_clut_source */
	/* LIST, LIST_PREV: the entry (0: the one at RASTER_BASE), its VRAM
	 * address, the beam position it runs at, and the colour it writes */
	uint32_t entry, addr;
	uint32_t beam_x, beam_y;
	uint32_t value; /* 0x00RRGGBB */
};

/*
 * Where the colour of the indexed pixel x, y of h's device comes from now:
 * the CLUT entry its VRAM holds, and the raster-list entry that wrote
 * that CLUT entry before the beam reached the pixel, read from the list
 * in force (RASTER_BASE, RASTER_CTRL) as the CRTC runs it every frame.
 * sim: and rdcd (register and VRAM reads); the device must be open.
 * RDC_HISTORY_CLUT_HOST does not say the host wrote it last: the history
 * watches VRAM, not CLUT writes.  1 for a pixel in direct colour (no CLUT
 * entry), RDC_E_RANGE off the screen.
 */
int rdc_history_clut_sized(rdc_history *h, uint32_t x, uint32_t y,
			   struct rdc_history_clut *c);
static inline int rdc_history_clut(rdc_history *h, uint32_t x, uint32_t y,
				   struct rdc_history_clut *c)
{
	if (c)
		c->size = sizeof(*c);
	return rdc_history_clut_sized(h, x, y, c);
}
/*
 * rdc_replay_file with a history open (rdc_history_open's x, y, w, h and
 * flags) from the trace's first record to its last, power cycles
 * included; an entry's `line` is then the trace record that was replaying
 * (1-based, as rdc_replay_result counts them).  *hist is NULL on an error.
 */
int rdc_replay_history_sized(const char *path, uint32_t x, uint32_t y,
			     uint32_t w, uint32_t h, uint32_t flags,
			     rdc_history **hist, struct rdc_replay_result *res,
			     rdc_dev **dev_out);
static inline int rdc_replay_history(const char *path, uint32_t x, uint32_t y,
				     uint32_t w, uint32_t h, uint32_t flags,
				     rdc_history **hist,
				     struct rdc_replay_result *res,
				     rdc_dev **dev_out)
{
	if (res)
		res->size = sizeof(*res);
	return rdc_replay_history_sized(path, x, y, w, h, flags, hist, res,
					dev_out);
}
/* Stop watching and free it (also after rdc_close of its device). */
void rdc_history_close(rdc_history *h);

/* ---- PNG ----------------------------------------------------------------- */
/* Write w x h XRGB8888 pixels (row `pitch` words) as an RGB PNG. */
int rdc_png_write(const char *path, const uint32_t *xrgb, uint32_t w,
		  uint32_t h, size_t pitch);

#ifdef __cplusplus
}
#endif

#endif /* RDC_LIB_H */
