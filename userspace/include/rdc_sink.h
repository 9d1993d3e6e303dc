/* SPDX-License-Identifier: GPL-2.0-only */
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
 *       source is never stalled.  Default format bgr32.
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
/* The kind ("v4l2", "png", "vnc"). */
const char *rdc_sink_kind(const rdc_sink *s);

struct rdc_sink_stats {
	uint64_t frames;	 /* handed to rdc_sink_frame */
	uint64_t written;	 /* delivered (written, encoded, sent) */
	uint64_t dropped;	 /* not delivered: EAGAIN, device away, ... */
	uint64_t renegotiations; /* format (re)negotiations (v4l2) */
	uint64_t reopens;	 /* device reopened after going away */
};
int rdc_sink_stats_get(const rdc_sink *s, struct rdc_sink_stats *st);

/* 1 if this build has the vnc sink (libvncserver), else 0. */
int rdc_sink_have_vnc(void);

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
