/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Frame sinks: where scanned-out frames go to be watched.
 *
 * Every frame source (the in-process simulator, rdcd, a kernel
 * framebuffer read back by librdc) hands each complete frame to one or
 * more sinks through rdc_sink_frame().  A sink is opened from a spec
 * string "KIND:ARGS[,OPTION=VALUE...]":
 *
 *   v4l2:/dev/videoN[,format=bgr32|xrgb32|rgb24|yuyv]
 *       V4L2 output device (v4l2loopback).  The OUTPUT format is set
 *       (VIDIOC_S_FMT) on the first frame and again whenever the frame
 *       size changes; the frame interval (VIDIOC_S_PARM) follows the
 *       source's refresh rate.  Each frame is one write() of exactly
 *       bytesperline * height bytes.  The device is non-blocking: a frame
 *       the device cannot take now (EAGAIN) is dropped, and a device that
 *       went away (ENODEV, EIO, ...) is closed and reopened later, so the
 *       source is never stalled.  Default format bgr32.  What a reader
 *       sees with v4l2loopback 0.12.7 and 0.13, and how a size change
 *       goes on each: docs/v4l2.md.
 *   png:DIR[,every=N][,prefix=NAME]
 *       PNG files DIR/NAME-NNNNNNNN.png (NAME default "frame", NNNNNNNN
 *       the frame's sequence number): every Nth frame handed to the sink
 *       (the first, the N+1th, ...; N 0, the default, means none), plus
 *       the next frame after each rdc_sink_snapshot().  DIR and its
 *       parents are created at open when missing (as mkdir -p does);
 *       RDC_E_FILE there, or from a frame whose file cannot be written,
 *       with rdc_last_error_detail naming the path and the reason.
 *   vnc:PORT[,listen=ADDR]
 *       A VNC server (libvncserver) on TCP PORT, loopback only unless
 *       listen= says otherwise; only rows that changed since the previous
 *       frame are sent.  RDC_E_NOSYS when built without libvncserver.
 *   web:[ADDR:]PORT[,token=FILE]
 *       A web page with the live display (docs/web.md): http://ADDR:PORT/
 *       (rdc_sink_url), the picture over a WebSocket, only what changed,
 *       and beside it what rdc_sink_status_set last said.  ADDR defaults
 *       to 127.0.0.1 ("[::1]" for IPv6); PORT 0 lets the kernel pick.
 *       With token=FILE every viewer must present the file's contents
 *       (open the page as http://ADDR:PORT/#token=...); an ADDR other
 *       than loopback needs one (RDC_E_AUTH otherwise).
 *
 * Sinks take XRGB8888 frames: 32-bit words 0x00RRGGBB in host order, the
 * format of rdc_frame_grab().  Errors are librdc's (enum rdc_error).
 */
#ifndef RDC_SINK_H
#define RDC_SINK_H

#include <stddef.h>
#include <stdint.h>

#include "rdc.h"

#ifdef __cplusplus
extern "C" {
#endif

struct rdc_frame {
	/* 0 (a zeroed or designated initialiser): the layout of librdc 1.0;
	 * a later release's members past it are read only if size covers
	 * them (rdc.h, "Structures that grow") */
	uint32_t size;
	const uint32_t *xrgb; /* height rows of width XRGB8888 words */
	uint32_t width, height;
	size_t stride; /* words from row to row, >= width */
	uint64_t seq;  /* frame number at the source */
	/* Seconds per frame as a fraction (the simulated refresh period);
	 * 0/0 when unknown. */
	uint32_t interval_num, interval_den;
};

typedef struct rdc_sink rdc_sink;

/* Open a sink from a spec (see above); RDC_E_URI for a bad spec. */
int rdc_sink_open(const char *spec, rdc_sink **out);
/*
 * Hand a frame to the sink.  Returns 0 when the frame was taken or
 * deliberately dropped (no room, device gone: see rdc_sink_stats), a
 * negative enum rdc_error for bad arguments or a failure the sink cannot
 * recover from (a PNG that cannot be written).
 */
int rdc_sink_frame(rdc_sink *s, const struct rdc_frame *f);
/* Ask for the next frame as a still (png); RDC_E_NOSYS for other kinds. */
int rdc_sink_snapshot(rdc_sink *s);
/* Let the sink do idle work (serve VNC clients) between frames. */
int rdc_sink_poll(rdc_sink *s);
void rdc_sink_close(rdc_sink *s);
/* The kind ("v4l2", "png", "vnc", "web"). */
const char *rdc_sink_kind(const rdc_sink *s);

struct rdc_sink_stats {
	/* sizeof(struct), set by rdc_sink_stats_get (rdc.h, "Structures that
	 * grow") */
	uint32_t size;
	uint64_t frames;	 /* handed to rdc_sink_frame */
	uint64_t written;	 /* delivered (written, encoded, sent) */
	uint64_t dropped;	 /* not delivered: EAGAIN, device away, ... */
	uint64_t renegotiations; /* format (re)negotiations (v4l2) */
	uint64_t reopens;	 /* device reopened after going away */
};
int rdc_sink_stats_get_sized(const rdc_sink *s, struct rdc_sink_stats *st);
static inline int rdc_sink_stats_get(const rdc_sink *s,
				     struct rdc_sink_stats *st)
{
	if (st)
		st->size = sizeof(*st);
	return rdc_sink_stats_get_sized(s, st);
}

/* 1 if this build has the vnc sink (libvncserver), else 0. */
int rdc_sink_have_vnc(void);
/* 1 if this build has the web sink, else 0. */
int rdc_sink_have_web(void);

/*
 * What a source knows of the device beside the picture, for sinks that
 * show it (web); `have` says which fields are filled.
 */
#define RDC_SINK_HAVE_TIME   0x1u /* time, core_hz */
#define RDC_SINK_HAVE_PINS   0x2u /* pins */
#define RDC_SINK_HAVE_IRQ    0x4u /* irq_status, irq_enable */
#define RDC_SINK_HAVE_FORMAT 0x8u /* format */
struct rdc_sink_status {
	/* sizeof(struct), or 0 (a zeroed or designated initialiser): this
	 * layout; members a later release adds past it are read only if size
	 * covers them (rdc.h, "Structures that grow") */
	uint32_t size;
	uint32_t have;
	uint64_t time; /* simulated core cycles */
	uint32_t core_hz;
	uint32_t pins; /* RDC_PIN_* levels */
	/* the registers IRQ_STATUS and IRQ_ENABLE */
	uint32_t irq_status, irq_enable;
	uint32_t format; /* enum rdc_format of the scanout */
};
/* Tell the sink the device's state (kept until the next call); sinks that
 * do not show it ignore it. */
int rdc_sink_status_set(rdc_sink *s, const struct rdc_sink_status *st);
/* The address a viewer opens ("http://127.0.0.1:8080/" for web);
 * RDC_E_NOSYS for kinds without one, RDC_E_RANGE if len is too small. */
int rdc_sink_url(const rdc_sink *s, char *buf, size_t len);

/*
 * The refresh period of the device's current CRTC timing as the fraction
 * H_TOTAL * V_TOTAL / (PIXCLK_KHZ * 1000) seconds, reduced; works through
 * any backend (register reads only).
 */
int rdc_sink_interval(rdc_dev *dev, uint32_t *num, uint32_t *den);
/* The same from the timing itself (a source that holds the chip). */
int rdc_sink_interval_timing(uint32_t h_total, uint32_t v_total,
			     uint32_t pixclk_khz, uint32_t *num, uint32_t *den);

/* ---- Pixel conversion (the v4l2 sink's, exposed for tests and bench) ---- */
enum rdc_sink_fmt {
	RDC_SINK_FMT_BGR32,  /* V4L2_PIX_FMT_BGR32: bytes B, G, R, X */
	RDC_SINK_FMT_XRGB32, /* V4L2_PIX_FMT_XRGB32: bytes X, R, G, B */
	RDC_SINK_FMT_RGB24,  /* V4L2_PIX_FMT_RGB24: bytes R, G, B */
	RDC_SINK_FMT_YUYV,   /* V4L2_PIX_FMT_YUYV: Y0 U Y1 V, BT.601
				limited range */
	RDC_SINK_FMT_COUNT
};

/* Format by name ("bgr32", ...); -1 if unknown. */
int rdc_sink_fmt_by_name(const char *name);
const char *rdc_sink_fmt_name(int fmt);
/* The V4L2 fourcc of a format, 0 if unknown. */
uint32_t rdc_sink_fmt_fourcc(int fmt);
/* Another fourcc with the same bytes (RGB32 for XRGB32), tried when a
 * device does not know the first; 0 if none. */
uint32_t rdc_sink_fmt_fourcc_alt(int fmt);
/* The format whose bytes a fourcc describes; -1 if none. */
int rdc_sink_fmt_by_fourcc(uint32_t fourcc);
/* Bytes per row for a width (YUYV rounds the width up to even). */
size_t rdc_sink_fmt_bytesperline(int fmt, uint32_t width);
/*
 * Convert a frame to `fmt` in dst, rows `dst_bpl` bytes apart (at least
 * rdc_sink_fmt_bytesperline).  YUYV: BT.601 limited range with the
 * usual 8-bit integer coefficients; each pair of pixels shares the U and V
 * of the pair's summed R, G, B; an odd last pixel is paired with itself.
 */
int rdc_sink_convert(int fmt, void *dst, size_t dst_bpl,
		     const struct rdc_frame *f);

#ifdef __cplusplus
}
#endif

#endif /* RDC_SINK_H */
