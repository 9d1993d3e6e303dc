// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The v4l2 sink: frames to a V4L2 output device, in practice a
 * v4l2loopback device that cameras' readers (ffmpeg, OBS, browsers)
 * capture from.  docs/v4l2.md says what readers see with each
 * v4l2loopback; what shapes this file:
 * - The sequence is OBS's virtual camera's: S_FMT, S_PARM, STREAMON,
 *   write() each frame, STREAMOFF, close.  v4l2loopback counts an opener
 *   as its writer only after STREAMON (0.12.7 announces OUTPUT again once
 *   such a writer closes, which a later S_FMT needs), and 0.13 counts
 *   writers by STREAMON less STREAMOFF: a writer gone without STREAMOFF
 *   keeps the format fixed until every opener has closed.
 * - A new mode: STREAMOFF, then S_FMT.  0.13 then takes the new size at
 *   once, unless a streaming (mmap) reader or keep_format holds the old
 *   one (S_FMT answers with it) or it still counts a writer gone without
 *   STREAMOFF (EBUSY); 0.12.7 ignores STREAMOFF and answers
 *   S_FMT with the format in force until every opener, readers included,
 *   has closed.  When S_FMT does not give the new size, the sink closes
 *   its own descriptor (so the device can come free when the readers let
 *   go) and tries again every RDC_V4L2_REOPEN_EVERY frames.
 * - 0.13 reallocates its buffers in S_FMT but keeps counting frames: a
 *   reader a frame behind may be handed a buffer not yet rewritten until
 *   the next write().  The new frame is converted before S_FMT, so that
 *   write() follows S_FMT at once.
 * - sizeimage comes back page-aligned; readers (ffmpeg) expect exactly
 *   bytesperline * height bytes in a buffer, so that is what one write()
 *   carries, never sizeimage.
 * - write() takes the whole frame or fails; the descriptor is non-blocking
 *   so a device that cannot take a frame costs a dropped frame, not a
 *   stalled simulation.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "rdc_priv.h"
#include "sink_priv.h"

#define V4L2LOOPBACK_DRIVER "v4l2 loopback"

struct v4l2_sink {
	struct rdc_v4l2_io io;
	char *path;
	int fmt;	/* enum rdc_sink_fmt */
	int fd;		/* -1 while the device is away */
	bool streaming; /* STREAMON on fd, not yet undone */
	uint32_t away_frames;
	/* Negotiated: 0 x 0 until S_FMT gave what was asked. */
	uint32_t width, height;
	size_t bpl, frame_bytes;
	uint32_t ival_num, ival_den;
	uint8_t *buf;
	size_t buf_cap;
};

static int sys_open(const char *path, int flags)
{
	return open(path, flags);
}

static int sys_ioctl(int fd, unsigned long req, void *arg)
{
	int ret;

	do
		ret = ioctl(fd, req, arg);
	while (ret < 0 && errno == EINTR);
	return ret;
}

static ssize_t sys_write(int fd, const void *buf, size_t len)
{
	return write(fd, buf, len);
}

static int sys_close(int fd)
{
	return close(fd);
}

static const struct rdc_v4l2_io sys_io = {
	.open = sys_open,
	.ioctl = sys_ioctl,
	.write = sys_write,
	.close = sys_close,
};

/* Undo our STREAMON: v4l2loopback 0.13 keeps the format fixed while it
 * counts a writer. */
static void v4l2_stream_off(struct v4l2_sink *v)
{
	int out_type = V4L2_BUF_TYPE_VIDEO_OUTPUT;

	if (v->streaming)
		v->io.ioctl(v->fd, VIDIOC_STREAMOFF, &out_type);
	v->streaming = false;
}

static void v4l2_drop_fd(struct v4l2_sink *v)
{
	if (v->fd >= 0) {
		v4l2_stream_off(v);
		v->io.close(v->fd);
	}
	v->fd = -1;
	v->away_frames = 0;
	v->width = v->height = 0;
	v->ival_num = v->ival_den = 0;
}

/* Open the device and check it is a V4L2 output that takes write(). */
static int v4l2_connect(struct v4l2_sink *v)
{
	struct v4l2_capability cap;
	uint32_t caps;
	int fd = v->io.open(v->path, O_WRONLY | O_NONBLOCK | O_CLOEXEC);

	if (fd < 0 && errno == ENOENT)
		return rdc_err_detail(
			RDC_E_FILE,
			"%s: %s: no such V4L2 device; v4l2loopback makes one "
			"(`modprobe v4l2loopback exclusive_caps=1`, Debian's "
			"v4l2loopback-dkms; `v4l2-ctl --list-devices` names "
			"its /dev/videoN)",
			v->path, strerror(ENOENT));
	if (fd < 0)
		return rdc_err_detail(RDC_E_FILE, "%s: %s", v->path,
				      strerror(errno));
	memset(&cap, 0, sizeof(cap));
	if (v->io.ioctl(fd, VIDIOC_QUERYCAP, &cap) < 0) {
		v->io.close(fd);
		return rdc_err_detail(RDC_E_NOSYS, "%s: not a V4L2 device",
				      v->path);
	}
	caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps :
							   cap.capabilities;
	/* v4l2loopback's caps tell its state, not what it can do: with
	 * exclusive_caps=1 it stops announcing OUTPUT once a write() writer
	 * has been, and a new writer must still get in. */
	if (!strncmp((const char *)cap.driver, V4L2LOOPBACK_DRIVER,
		     sizeof(cap.driver)))
		caps |= V4L2_CAP_VIDEO_OUTPUT;
	if (!(caps & V4L2_CAP_VIDEO_OUTPUT) || !(caps & V4L2_CAP_READWRITE)) {
		v->io.close(fd);
		return rdc_err_detail(RDC_E_NOSYS,
				      "%s: not a V4L2 output that takes "
				      "write() (a v4l2loopback device?)",
				      v->path);
	}
	v->fd = fd;
	v->streaming = false;
	v->away_frames = 0;
	v->width = v->height = 0;
	v->ival_num = v->ival_den = 0;
	return 0;
}

static void v4l2_set_interval(rdc_sink *s, const struct rdc_frame *f)
{
	struct v4l2_sink *v = s->priv;
	struct v4l2_streamparm parm;

	if (!f->interval_num || !f->interval_den)
		return;
	if (f->interval_num == v->ival_num && f->interval_den == v->ival_den)
		return;
	memset(&parm, 0, sizeof(parm));
	parm.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
	parm.parm.output.timeperframe.numerator = f->interval_num;
	parm.parm.output.timeperframe.denominator = f->interval_den;
	/* A device without frame-interval support still streams. */
	v->io.ioctl(v->fd, VIDIOC_S_PARM, &parm);
	v->ival_num = f->interval_num;
	v->ival_den = f->interval_den;
}

/* S_FMT; true when the device took exactly this size and fourcc. */
static bool v4l2_try_fourcc(struct v4l2_sink *v, const struct rdc_frame *f,
			    uint32_t w, size_t bpl, uint32_t fourcc,
			    struct v4l2_format *vf)
{
	memset(vf, 0, sizeof(*vf));
	vf->type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
	vf->fmt.pix.width = w;
	vf->fmt.pix.height = f->height;
	vf->fmt.pix.pixelformat = fourcc;
	vf->fmt.pix.field = V4L2_FIELD_NONE;
	vf->fmt.pix.bytesperline = (uint32_t)bpl;
	vf->fmt.pix.sizeimage = (uint32_t)(bpl * f->height);
	vf->fmt.pix.colorspace = V4L2_COLORSPACE_SRGB;
	if (v->io.ioctl(v->fd, VIDIOC_S_FMT, vf) < 0)
		return false;
	return vf->fmt.pix.width == w && vf->fmt.pix.height == f->height &&
	       vf->fmt.pix.pixelformat == fourcc;
}

/* The frame buffer for rows of bpl bytes; rows padded by the device stay
 * zero rather than stale. */
static int v4l2_fit(struct v4l2_sink *v, size_t bpl, uint32_t height)
{
	if (bpl * height > v->buf_cap) {
		uint8_t *nb = realloc(v->buf, bpl * height);

		if (!nb)
			return RDC_E_NOMEM;
		v->buf = nb;
		v->buf_cap = bpl * height;
	}
	memset(v->buf, 0, bpl * height);
	v->bpl = bpl;
	v->frame_bytes = bpl * height;
	return 0;
}

/*
 * A new size: the frame converted first, then STREAMOFF, S_FMT, S_PARM,
 * STREAMON.  Returns 0 when the device took it, 1 when it did not (held
 * in another format by readers of the previous mode, or refused), a
 * negative error otherwise.
 */
static int v4l2_negotiate(rdc_sink *s, const struct rdc_frame *f)
{
	struct v4l2_sink *v = s->priv;
	size_t bpl = rdc_sink_fmt_bytesperline(v->fmt, f->width);
	uint32_t w =
		f->width + (v->fmt == RDC_SINK_FMT_YUYV ? f->width & 1 : 0);
	uint32_t alt = rdc_sink_fmt_fourcc_alt(v->fmt);
	int out_type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
	struct v4l2_format vf;
	int ret;

	v->width = v->height = 0;
	ret = v4l2_fit(v, bpl, f->height);
	if (!ret)
		ret = rdc_sink_convert(v->fmt, v->buf, bpl, f);
	if (ret)
		return ret;
	v4l2_stream_off(v);
	if (!v4l2_try_fourcc(v, f, w, bpl, rdc_sink_fmt_fourcc(v->fmt), &vf) &&
	    (!alt || !v4l2_try_fourcc(v, f, w, bpl, alt, &vf)))
		return 1;
	/* Keep the device's row pitch when it pads rows; never less. */
	if (vf.fmt.pix.bytesperline > bpl &&
	    vf.fmt.pix.bytesperline <= bpl + RDC_CRTC_MAX_DISPLAY) {
		bpl = vf.fmt.pix.bytesperline;
		ret = v4l2_fit(v, bpl, f->height);
		if (!ret)
			ret = rdc_sink_convert(v->fmt, v->buf, bpl, f);
		if (ret)
			return ret;
	}
	/* The interval before STREAMON: once that makes the device ready,
	 * readers may ask for it. */
	v->ival_num = v->ival_den = 0;
	v4l2_set_interval(s, f);
	/* Frames still go by write(); devices without streaming ignore it. */
	v->streaming = !v->io.ioctl(v->fd, VIDIOC_STREAMON, &out_type);
	v->width = f->width;
	v->height = f->height;
	s->st.renegotiations++;
	return 0;
}

static bool v4l2_gone(int err)
{
	return err == ENODEV || err == ENXIO || err == EIO || err == EPIPE ||
	       err == EBADF;
}

static int v4l2_frame(rdc_sink *s, const struct rdc_frame *f)
{
	struct v4l2_sink *v = s->priv;
	ssize_t n;
	int ret;

	if (v->fd < 0) {
		/* Retry only now and then: open() on a vanished node is
		 * cheap, but S_FMT on a held device is not worth every
		 * frame. */
		if (++v->away_frames < RDC_V4L2_REOPEN_EVERY) {
			s->st.dropped++;
			return 0;
		}
		v->away_frames = 0;
		if (v4l2_connect(v)) {
			s->st.dropped++;
			return 0;
		}
		s->st.reopens++;
	}
	if (f->width != v->width || f->height != v->height) {
		ret = v4l2_negotiate(s, f);
		if (ret < 0)
			return ret;
		if (ret) {
			/* Held in the old format, or refused: let go so the
			 * device can come free, and try again later. */
			v4l2_drop_fd(v);
			s->st.dropped++;
			return 0;
		}
	} else {
		v4l2_set_interval(s, f);
		ret = rdc_sink_convert(v->fmt, v->buf, v->bpl, f);
		if (ret)
			return ret;
	}
	n = v->io.write(v->fd, v->buf, v->frame_bytes);
	if (n == (ssize_t)v->frame_bytes) {
		s->st.written++;
		return 0;
	}
	s->st.dropped++;
	if (n < 0 && v4l2_gone(errno))
		v4l2_drop_fd(v);
	return 0;
}

static void v4l2_close(rdc_sink *s)
{
	struct v4l2_sink *v = s->priv;

	if (!v)
		return;
	v4l2_drop_fd(v);
	free(v->buf);
	free(v->path);
	free(v);
	s->priv = NULL;
}

static int v4l2_parse(struct v4l2_sink *v, const char *args)
{
	char *dup = strdup(args), *cur, *key, *val;
	int ret;

	if (!dup)
		return RDC_E_NOMEM;
	cur = strchr(dup, ',');
	if (cur)
		*cur++ = '\0';
	if (!dup[0]) {
		free(dup);
		return RDC_E_URI;
	}
	v->path = strdup(dup);
	ret = v->path ? 0 : RDC_E_NOMEM;
	while (!ret && (ret = rdc_sink_opt_next(&cur, &key, &val)) > 0) {
		if (!strcmp(key, "format"))
			v->fmt = rdc_sink_fmt_by_name(val);
		else
			v->fmt = -1;
		ret = v->fmt < 0 ? RDC_E_URI : 0;
	}
	free(dup);
	return ret;
}

int rdc_sink_v4l2_open_io(const char *args, const struct rdc_v4l2_io *io,
			  rdc_sink **out)
{
	struct v4l2_sink *v;
	rdc_sink *s;
	int ret;

	if (!args || !io || !out)
		return RDC_E_INVAL;
	*out = NULL;
	s = calloc(1, sizeof(*s));
	v = calloc(1, sizeof(*v));
	if (!s || !v) {
		free(s);
		free(v);
		return RDC_E_NOMEM;
	}
	s->ops = &rdc_sink_v4l2_ops;
	s->priv = v;
	v->io = *io;
	v->fd = -1;
	v->fmt = RDC_SINK_FMT_BGR32;
	ret = v4l2_parse(v, args);
	/* A missing or wrong device at start is the user's mistake: say so
	 * now rather than drop every frame. */
	if (!ret)
		ret = v4l2_connect(v);
	if (ret) {
		rdc_sink_close(s);
		return ret;
	}
	*out = s;
	return 0;
}

static int v4l2_open(rdc_sink *s, const char *args)
{
	rdc_sink *tmp;
	int ret = rdc_sink_v4l2_open_io(args, &sys_io, &tmp);

	if (ret)
		return ret;
	/* Move the state into the sink the factory made. */
	s->priv = tmp->priv;
	tmp->priv = NULL;
	free(tmp);
	return 0;
}

const struct rdc_sink_ops rdc_sink_v4l2_ops = {
	.kind = "v4l2",
	.open = v4l2_open,
	.frame = v4l2_frame,
	.close = v4l2_close,
};
