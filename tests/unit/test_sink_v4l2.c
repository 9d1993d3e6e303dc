// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The v4l2 sink against a fake device that behaves as v4l2loopback 0.12.7
 * does: S_FMT answers with the format in force while the device is held,
 * sizeimage comes back page-aligned, write() can fail with EAGAIN or with
 * ENODEV once the device is gone.  With v013 set it behaves as 0.13: it
 * counts writers by STREAMON less STREAMOFF, and S_FMT for another size
 * fails with EBUSY while it counts one or a streaming reader holds it.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>
#include <zlib.h>

#include <cmocka.h>

#include "../../userspace/sink/sink_priv.h"

#define FAKE_FD	  42
#define FAKE_PAGE 4096u

static struct fake_dev {
	bool present;	/* the node exists */
	bool output;	/* announces VIDEO_OUTPUT */
	bool held;	/* a reader holds the format in force */
	bool old_names; /* knows XRGB32 only as RGB32, as 0.12.7 */
	bool loopback;	/* driver "v4l2 loopback" */
	bool v013;	/* 0.13: STREAMOFF frees, EBUSY while held */
	int writers;	/* 0.13: STREAMON less STREAMOFF */
	int streamoffs;
	int write_errno; /* next write fails with this, once */
	int opens, closes, s_fmts, s_parms, writes, streamons;
	int parms_at_streamon; /* S_PARMs done when STREAMON came */
	bool open_now;
	struct v4l2_pix_format pix; /* in force */
	struct v4l2_fract tpf;
	size_t last_len;
	uint32_t last_crc;
} fk;

static int fake_open(const char *path, int flags)
{
	assert_string_equal(path, "/dev/video7");
	assert_true(flags & O_NONBLOCK);
	if (!fk.present) {
		errno = ENOENT;
		return -1;
	}
	assert_false(fk.open_now);
	fk.opens++;
	fk.open_now = true;
	return FAKE_FD;
}

static int fake_ioctl(int fd, unsigned long req, void *arg)
{
	assert_int_equal(fd, FAKE_FD);
	assert_true(fk.open_now);
	if (!fk.present) {
		errno = ENODEV;
		return -1;
	}
	if (req == VIDIOC_QUERYCAP) {
		struct v4l2_capability *c = arg;

		if (fk.loopback)
			strcpy((char *)c->driver, "v4l2 loopback");
		c->capabilities = V4L2_CAP_DEVICE_CAPS | V4L2_CAP_READWRITE |
				  V4L2_CAP_VIDEO_OUTPUT |
				  V4L2_CAP_VIDEO_CAPTURE;
		c->device_caps = V4L2_CAP_READWRITE |
				 (fk.output ? V4L2_CAP_VIDEO_OUTPUT :
					      V4L2_CAP_VIDEO_CAPTURE);
		return 0;
	}
	if (req == VIDIOC_S_FMT) {
		struct v4l2_format *f = arg;

		assert_int_equal(f->type, V4L2_BUF_TYPE_VIDEO_OUTPUT);
		fk.s_fmts++;
		if (fk.old_names &&
		    f->fmt.pix.pixelformat == V4L2_PIX_FMT_XRGB32)
			f->fmt.pix.pixelformat = V4L2_PIX_FMT_BGR32;
		if (fk.v013 && (fk.writers || fk.held) &&
		    (f->fmt.pix.width != fk.pix.width ||
		     f->fmt.pix.height != fk.pix.height ||
		     f->fmt.pix.pixelformat != fk.pix.pixelformat)) {
			errno = EBUSY;
			return -1;
		}
		if (!fk.held) {
			fk.pix = f->fmt.pix;
			fk.pix.bytesperline = 0;
		}
		f->fmt.pix = fk.pix;
		/* v4l2loopback's own arithmetic, then its page rounding. */
		if (f->fmt.pix.pixelformat == V4L2_PIX_FMT_RGB24)
			f->fmt.pix.bytesperline = f->fmt.pix.width * 3;
		else if (f->fmt.pix.pixelformat == V4L2_PIX_FMT_YUYV)
			f->fmt.pix.bytesperline = f->fmt.pix.width * 2;
		else
			f->fmt.pix.bytesperline = f->fmt.pix.width * 4;
		f->fmt.pix.sizeimage =
			(f->fmt.pix.bytesperline * f->fmt.pix.height +
			 FAKE_PAGE - 1) &
			~(FAKE_PAGE - 1);
		return 0;
	}
	if (req == VIDIOC_STREAMON) {
		assert_int_equal(*(int *)arg, V4L2_BUF_TYPE_VIDEO_OUTPUT);
		fk.streamons++;
		fk.writers++;
		fk.parms_at_streamon = fk.s_parms;
		return 0;
	}
	if (req == VIDIOC_STREAMOFF) {
		assert_int_equal(*(int *)arg, V4L2_BUF_TYPE_VIDEO_OUTPUT);
		fk.streamoffs++;
		if (!fk.v013) {
			errno = ENOTTY; /* 0.12.7: accepted, and nothing done */
			return -1;
		}
		if (fk.writers)
			fk.writers--;
		return 0;
	}
	if (req == VIDIOC_S_PARM) {
		struct v4l2_streamparm *p = arg;

		assert_int_equal(p->type, V4L2_BUF_TYPE_VIDEO_OUTPUT);
		fk.s_parms++;
		fk.tpf = p->parm.output.timeperframe;
		return 0;
	}
	errno = ENOTTY;
	return -1;
}

static ssize_t fake_write(int fd, const void *buf, size_t len)
{
	assert_int_equal(fd, FAKE_FD);
	assert_true(fk.open_now);
	fk.writes++;
	if (!fk.present) {
		errno = ENODEV;
		return -1;
	}
	if (fk.write_errno) {
		errno = fk.write_errno;
		fk.write_errno = 0;
		return -1;
	}
	fk.last_len = len;
	fk.last_crc = (uint32_t)crc32(0, buf, (uInt)len);
	return (ssize_t)len;
}

static int fake_close(int fd)
{
	assert_int_equal(fd, FAKE_FD);
	assert_true(fk.open_now);
	fk.open_now = false;
	fk.closes++;
	return 0;
}

static const struct rdc_v4l2_io fake_io = {
	.open = fake_open,
	.ioctl = fake_ioctl,
	.write = fake_write,
	.close = fake_close,
};

static int setup(void **state)
{
	(void)state;
	memset(&fk, 0, sizeof(fk));
	fk.present = true;
	fk.output = true;
	return 0;
}

/* 640x480@60 timing: 800 x 525 pixels at 25.175 MHz. */
#define VGA_NUM (800u * 525u)
#define VGA_DEN 25175000u

struct pic {
	uint32_t *px;
	struct rdc_frame f;
};

static void pic_make(struct pic *p, uint32_t w, uint32_t h, uint32_t seed)
{
	p->px = malloc((size_t)w * h * 4);
	assert_non_null(p->px);
	for (size_t i = 0; i < (size_t)w * h; i++) {
		seed = seed * 1103515245u + 12345u;
		p->px[i] = seed >> 8;
	}
	memset(&p->f, 0, sizeof(p->f));
	p->f.xrgb = p->px;
	p->f.width = w;
	p->f.height = h;
	p->f.stride = w;
	p->f.interval_num = VGA_NUM;
	p->f.interval_den = VGA_DEN;
}

/* The CRC of what the device should receive, converted independently. */
static uint32_t pic_crc(const struct pic *p, int fmt)
{
	size_t bpl = rdc_sink_fmt_bytesperline(fmt, p->f.width);
	uint8_t *b = malloc(bpl * p->f.height);
	uint32_t crc;

	assert_non_null(b);
	assert_int_equal(rdc_sink_convert(fmt, b, bpl, &p->f), 0);
	crc = (uint32_t)crc32(0, b, (uInt)(bpl * p->f.height));
	free(b);
	return crc;
}

static void test_v4l2_open_errors(void **state)
{
	rdc_sink *s = NULL;

	(void)state;
	fk.present = false;
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s),
			 RDC_E_FILE);
	assert_null(s);
	/* no such node: the file, the reason, and where one comes from */
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "/dev/video7: No such file or directory"));
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "modprobe v4l2loopback"));
	fk.present = true;
	fk.output = false; /* a camera, not an output */
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s),
			 RDC_E_NOSYS);
	assert_int_equal(fk.opens, fk.closes);
	/* v4l2loopback (exclusive_caps=1) hides OUTPUT after a write()
	 * writer has been; it still takes one. */
	fk.loopback = true;
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	rdc_sink_close(s);
	fk.loopback = false;
	fk.output = true;
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7,format=nv12",
					       &fake_io, &s),
			 RDC_E_URI);
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7,colour=yuyv",
					       &fake_io, &s),
			 RDC_E_URI);
	assert_int_equal(rdc_sink_v4l2_open_io("", &fake_io, &s), RDC_E_URI);
	assert_int_equal(rdc_sink_open("v4l2:", &s), RDC_E_URI);
	assert_int_equal(rdc_sink_open("nosuch:x", &s), RDC_E_URI);
	assert_int_equal(rdc_sink_open("v4l2", &s), RDC_E_URI);
	assert_int_equal(fk.opens, fk.closes);
}

/* Every format: S_FMT as asked, exactly bytesperline*height per write
 * (not the page-aligned sizeimage), the pixels converted, S_PARM once. */
static void test_v4l2_formats_and_size(void **state)
{
	static const struct {
		const char *spec;
		int fmt;
		uint32_t bpp;
	} fm[] = {
		{ "/dev/video7", RDC_SINK_FMT_BGR32, 4 },
		{ "/dev/video7,format=xrgb32", RDC_SINK_FMT_XRGB32, 4 },
		{ "/dev/video7,format=rgb24", RDC_SINK_FMT_RGB24, 3 },
		{ "/dev/video7,format=yuyv", RDC_SINK_FMT_YUYV, 2 },
	};
	struct pic p;

	(void)state;
	pic_make(&p, 320, 240, 5);
	for (size_t i = 0; i < sizeof(fm) / sizeof(fm[0]); i++) {
		struct rdc_sink_stats st;
		rdc_sink *s;

		setup(NULL);
		assert_int_equal(
			rdc_sink_v4l2_open_io(fm[i].spec, &fake_io, &s), 0);
		for (uint64_t n = 0; n < 3; n++) {
			p.f.seq = n;
			assert_int_equal(rdc_sink_frame(s, &p.f), 0);
		}
		assert_int_equal(fk.s_fmts, 1);
		/* v4l2loopback takes the writer for one after STREAMON,
		 * and readers may come at once: the interval is set by then */
		assert_int_equal(fk.streamons, 1);
		assert_int_equal(fk.parms_at_streamon, 1);
		assert_int_equal(fk.pix.width, 320);
		assert_int_equal(fk.pix.height, 240);
		assert_int_equal(fk.pix.pixelformat,
				 rdc_sink_fmt_fourcc(fm[i].fmt));
		assert_int_equal(fk.writes, 3);
		assert_int_equal(fk.last_len, 320u * 240u * fm[i].bpp);
		assert_int_equal(fk.last_crc, pic_crc(&p, fm[i].fmt));
		assert_int_equal(fk.s_parms, 1);
		assert_int_equal(fk.tpf.numerator, VGA_NUM);
		assert_int_equal(fk.tpf.denominator, VGA_DEN);
		assert_int_equal(rdc_sink_stats_get(s, &st), 0);
		assert_int_equal(st.frames, 3);
		assert_int_equal(st.written, 3);
		assert_int_equal(st.dropped, 0);
		assert_int_equal(st.renegotiations, 1);
		rdc_sink_close(s);
		assert_false(fk.open_now);
	}
	free(p.px);
}

/* A new mode: S_FMT again with the new size, S_PARM for the new rate. */
static void test_v4l2_mode_change(void **state)
{
	struct rdc_sink_stats st;
	struct pic a, b;
	rdc_sink *s;

	(void)state;
	pic_make(&a, 320, 200, 1);
	pic_make(&b, 64, 48, 2);
	b.f.interval_num = 1;
	b.f.interval_den = 70;
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_int_equal(fk.s_fmts, 2);
	assert_int_equal(fk.pix.width, 64);
	assert_int_equal(fk.last_len, 64u * 48u * 4u);
	assert_int_equal(fk.last_crc, pic_crc(&b, RDC_SINK_FMT_BGR32));
	assert_int_equal(fk.s_parms, 2);
	assert_int_equal(fk.parms_at_streamon, 2);
	assert_int_equal(fk.tpf.denominator, 70);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(fk.last_crc, pic_crc(&a, RDC_SINK_FMT_BGR32));
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.renegotiations, 3);
	assert_int_equal(st.written, 3);
	rdc_sink_close(s);
	free(a.px);
	free(b.px);
}

/*
 * 0.13: a new mode on the same descriptor (STREAMOFF, S_FMT, STREAMON),
 * the new frame written at once; STREAMOFF again before close, so the
 * device counts no writer after it.
 */
static void test_v4l2_mode_change_013(void **state)
{
	struct rdc_sink_stats st;
	struct pic a, b;
	rdc_sink *s;

	(void)state;
	fk.v013 = true;
	pic_make(&a, 320, 200, 1);
	pic_make(&b, 640, 480, 2);
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(fk.writers, 1);
	assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_true(fk.open_now);
	assert_int_equal(fk.opens, 1);
	assert_int_equal(fk.streamoffs, 1);
	assert_int_equal(fk.streamons, 2);
	assert_int_equal(fk.writers, 1);
	assert_int_equal(fk.pix.width, 640);
	assert_int_equal(fk.last_len, 640u * 480u * 4u);
	assert_int_equal(fk.last_crc, pic_crc(&b, RDC_SINK_FMT_BGR32));
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.renegotiations, 2);
	assert_int_equal(st.written, 2);
	assert_int_equal(st.dropped, 0);
	assert_int_equal(st.reopens, 0);
	rdc_sink_close(s);
	assert_false(fk.open_now);
	assert_int_equal(fk.writers, 0);
	assert_int_equal(fk.streamoffs, 2);
	free(a.px);
	free(b.px);
}

/* Held in the old size by a reader: the sink lets the device go, drops
 * frames without writing, and takes the new size once it is free; 0.12.7
 * answers S_FMT with the old format, 0.13 (a streaming reader) EBUSY. */
static void held_format(bool v013)
{
	struct rdc_sink_stats st;
	struct pic a, b;
	rdc_sink *s;
	int writes;

	setup(NULL);
	fk.v013 = v013;
	pic_make(&a, 320, 200, 1);
	pic_make(&b, 640, 480, 2);
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	fk.held = true;
	assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_false(fk.open_now); /* let go, so the device can come free */
	writes = fk.writes;
	for (int i = 0; i < RDC_V4L2_REOPEN_EVERY - 1; i++)
		assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_int_equal(fk.writes, writes);
	assert_false(fk.open_now);
	/* The next retry finds it still held. */
	assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_false(fk.open_now);
	assert_int_equal(fk.writes, writes);
	fk.held = false; /* the reader closed */
	for (int i = 0; i < RDC_V4L2_REOPEN_EVERY; i++)
		assert_int_equal(rdc_sink_frame(s, &b.f), 0);
	assert_true(fk.open_now);
	assert_int_equal(fk.pix.width, 640);
	assert_int_equal(fk.writes, writes + 1);
	assert_int_equal(fk.last_len, 640u * 480u * 4u);
	assert_int_equal(fk.last_crc, pic_crc(&b, RDC_SINK_FMT_BGR32));
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.frames, 2 * RDC_V4L2_REOPEN_EVERY + 2);
	assert_int_equal(st.written, 2);
	assert_int_equal(st.dropped, 2 * RDC_V4L2_REOPEN_EVERY);
	assert_int_equal(st.reopens, 2);
	rdc_sink_close(s);
	if (v013)
		assert_int_equal(fk.writers, 0);
	free(a.px);
	free(b.px);
}

static void test_v4l2_held_format(void **state)
{
	(void)state;
	held_format(false);
	held_format(true);
}

/* EAGAIN drops one frame and keeps the device; ENODEV closes it, frames
 * are dropped without system calls until it is back. */
static void test_v4l2_eagain_and_gone(void **state)
{
	struct rdc_sink_stats st;
	struct pic a;
	rdc_sink *s;
	int writes;

	(void)state;
	pic_make(&a, 32, 8, 1);
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	fk.write_errno = EAGAIN;
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_true(fk.open_now);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.written, 2);
	assert_int_equal(st.dropped, 1);

	fk.present = false; /* module unloaded */
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_false(fk.open_now);
	writes = fk.writes;
	for (int i = 0; i < 3 * RDC_V4L2_REOPEN_EVERY; i++)
		assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(fk.writes, writes);
	fk.present = true;
	for (int i = 0; i < RDC_V4L2_REOPEN_EVERY; i++)
		assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_true(fk.open_now);
	assert_int_equal(fk.writes, writes + 1);
	assert_int_equal(fk.last_crc, pic_crc(&a, RDC_SINK_FMT_BGR32));
	assert_int_equal(rdc_sink_stats_get(s, &st), 0);
	assert_int_equal(st.reopens, 1);
	assert_int_equal(st.written, 3);
	rdc_sink_close(s);
	assert_int_equal(fk.opens, fk.closes);
	free(a.px);
}

/* A device that knows XRGB32's bytes only as RGB32 gets RGB32. */
static void test_v4l2_xrgb32_old_name(void **state)
{
	struct pic a;
	rdc_sink *s;

	(void)state;
	fk.old_names = true;
	pic_make(&a, 16, 4, 3);
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7,format=xrgb32",
					       &fake_io, &s),
			 0);
	assert_int_equal(rdc_sink_frame(s, &a.f), 0);
	assert_int_equal(fk.pix.pixelformat, V4L2_PIX_FMT_RGB32);
	assert_int_equal(fk.writes, 1);
	assert_int_equal(fk.last_crc, pic_crc(&a, RDC_SINK_FMT_XRGB32));
	assert_int_equal(rdc_sink_fmt_by_fourcc(V4L2_PIX_FMT_RGB32),
			 RDC_SINK_FMT_XRGB32);
	rdc_sink_close(s);
	free(a.px);
}

static void test_v4l2_bad_frames(void **state)
{
	uint32_t px[4] = { 0 };
	struct rdc_frame f = {
		.xrgb = px, .width = 2, .height = 2, .stride = 1
	};
	rdc_sink *s;

	(void)state;
	assert_int_equal(rdc_sink_v4l2_open_io("/dev/video7", &fake_io, &s), 0);
	assert_int_equal(rdc_sink_frame(s, &f), RDC_E_INVAL); /* stride */
	f.stride = 2;
	f.height = 0;
	assert_int_equal(rdc_sink_frame(s, &f), RDC_E_INVAL);
	f.height = RDC_CRTC_MAX_DISPLAY + 1;
	assert_int_equal(rdc_sink_frame(s, &f), RDC_E_INVAL);
	assert_int_equal(rdc_sink_frame(s, NULL), RDC_E_INVAL);
	assert_int_equal(fk.writes, 0);
	assert_int_equal(rdc_sink_snapshot(s), RDC_E_NOSYS);
	assert_string_equal(rdc_sink_kind(s), "v4l2");
	rdc_sink_close(s);
}

/* The interval helper reads the CRTC: 640x480@60 is 800 x 525 at
 * 25.175 MHz, 320x200@70 is 400 x 225 at 6.3 MHz. */
static void test_v4l2_interval_from_device(void **state)
{
	uint32_t num, den;
	rdc_dev *dev;

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_640x480_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_sink_interval(dev, &num, &den), 0);
	/* 420000 / 25175000, reduced by their gcd 2^3 * 5^4 = 5000. */
	assert_int_equal((uint64_t)num * VGA_DEN, (uint64_t)den * VGA_NUM);
	assert_int_equal(num, 84);
	assert_int_equal(den, 5035);
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
				      RDC_FMT_XRGB8888, 0),
			 0);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_sink_interval(dev, &num, &den), 0);
	assert_int_equal(num, 1);
	assert_int_equal(den, 70);
	rdc_close(dev);
	/* CEA-861 1080p60: 2200 x 1125 at 148.5 MHz is exactly 1/60 s. */
	assert_int_equal(
		rdc_sink_interval_timing(2200, 1125, 148500, &num, &den), 0);
	assert_int_equal(num, 1);
	assert_int_equal(den, 60);
	assert_int_equal(rdc_sink_interval_timing(0, 1125, 148500, &num, &den),
			 RDC_E_RANGE);
	assert_int_equal(rdc_sink_interval_timing(2200, 1125, 0, &num, &den),
			 RDC_E_RANGE);
	assert_int_equal(rdc_sink_interval_timing(RDC_CRTC_MAX_TOTAL + 1, 1,
						  1000, &num, &den),
			 RDC_E_RANGE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_v4l2_open_errors, setup),
		cmocka_unit_test_setup(test_v4l2_formats_and_size, setup),
		cmocka_unit_test_setup(test_v4l2_mode_change, setup),
		cmocka_unit_test_setup(test_v4l2_mode_change_013, setup),
		cmocka_unit_test_setup(test_v4l2_held_format, setup),
		cmocka_unit_test_setup(test_v4l2_eagain_and_gone, setup),
		cmocka_unit_test_setup(test_v4l2_xrgb32_old_name, setup),
		cmocka_unit_test_setup(test_v4l2_bad_frames, setup),
		cmocka_unit_test(test_v4l2_interval_from_device),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
