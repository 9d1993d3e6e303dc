// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * v4l2_read: the capture side of the VM tests.  Reads frames from a V4L2
 * capture device (v4l2loopback) or from a raw file another reader wrote
 * (ffmpeg -f rawvideo), and checks each one, byte for byte through its
 * CRC-32, against frames this program simulates itself: it runs the same
 * .rdl scripts on an in-process RDC-1 (sim:) and converts the scanned-out
 * frames to the capture format with the sinks' converters.
 *
 *   v4l2_read --expect A.rdl [--expect B.rdl ...] (--device /dev/videoN |
 *             --raw FILE --format F) [--frames N] [--need-all]
 *             [--check-rate] [--settle] [--timeout S] [--stall-ms MS]
 *             [--sequence N --format F] [--in-order]
 *
 * Scripts run one after the other on one device; after each, its picture
 * is one expected frame (with the CRTC's frame interval).  Every frame
 * read must equal one of them, exactly bytesperline * height bytes;
 * --need-all asks that each was seen (--each N: N times); --settle
 * ignores the frames before the first that matches (a source that starts
 * before its scene is drawn).  A device that stops delivering for
 * --stall-ms is closed and opened again, so a writer that renegotiates
 * (mode change) or restarts is followed.  Exit 0 when all is well.
 *
 * --sequence N: after the scripts' pictures, the N frames that follow at
 * each vertical blanking (what `rdcctl stream --script A --at 1 B` sends
 * after A's and B's pictures while the display processor animates on its
 * own) are expected too, as CRC-32s in --format.  --in-order: each frame
 * matched must come later in that order than the one matched before it
 * (no frame twice, none out of order).  "expected: ..." is printed once
 * the references are made, so a test can start its writer then.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>
#include <zlib.h>

#include "rdc.h"
#include "rdc_sink.h"

#define MAX_EXPECT 8
#define NS_PER_S   1000000000ull
#define NS_PER_MS  1000000ull
#define RETRY_NS   (50 * NS_PER_MS)
#define POLL_NS	   (2 * NS_PER_MS)
#define RATE_MIN   0.3
#define RATE_SLOW  5.0
#define SEQ_MAX	   100000u /* --sequence: frames simulated at most */

struct expect {
	const char *script;
	uint32_t *px, w, h;
	uint32_t num, den;
	uint32_t crc; /* in the current capture format */
	uint64_t seen;
};

struct ropts {
	const char *device, *raw, *format;
	struct expect ex[MAX_EXPECT];
	int nex;
	uint64_t frames;
	int need_all, check_rate, settle;
	uint64_t each; /* --need-all: times each expected frame is seen */
	uint64_t timeout_ns, stall_ns;
	uint32_t nseq;	   /* --sequence: frames after the scripts' */
	uint32_t *seq_crc; /* their CRC-32s in --format */
	uint32_t seq_w, seq_h;
	int seq_fmt, in_order;
	uint64_t seq_seen, order_bad;
	int64_t last; /* --in-order: the place of the frame matched last */
};

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static void nap(uint64_t ns)
{
	struct timespec ts = { .tv_sec = (time_t)(ns / NS_PER_S),
			       .tv_nsec = (long)(ns % NS_PER_S) };

	nanosleep(&ts, NULL);
}

/*
 * --sequence: the frames after the scripts' pictures, one at each
 * vertical blanking as rdcctl stream grabs them, in the last script's
 * mode, converted to --format and kept as CRC-32s only.
 */
static int simulate_seq(struct ropts *o, rdc_dev *dev)
{
	const struct expect *last = &o->ex[o->nex - 1];
	size_t npx = (size_t)last->w * last->h, bpl;
	uint32_t *px = malloc(npx * 4), w, h;
	uint8_t *b;
	int ret = 0;

	o->seq_fmt = rdc_sink_fmt_by_name(o->format);
	o->seq_w = last->w;
	o->seq_h = last->h;
	bpl = rdc_sink_fmt_bytesperline(o->seq_fmt, last->w);
	b = malloc(bpl * last->h);
	o->seq_crc = calloc(o->nseq, sizeof(*o->seq_crc));
	if (o->seq_fmt < 0 || !px || !b || !o->seq_crc)
		ret = RDC_E_NOMEM;
	for (uint32_t k = 0; k < o->nseq && !ret; k++) {
		struct rdc_frame f = { .xrgb = px };

		ret = rdc_vblank_wait(dev);
		if (!ret)
			ret = rdc_frame_grab(dev, px, npx, &w, &h);
		if (!ret && (w != last->w || h != last->h))
			ret = RDC_E_RANGE; /* a mode change: not followed */
		f.width = w;
		f.height = h;
		f.stride = w;
		if (!ret)
			ret = rdc_sink_convert(o->seq_fmt, b, bpl, &f);
		if (!ret)
			o->seq_crc[k] =
				(uint32_t)crc32(0, b, (uInt)(bpl * last->h));
	}
	if (ret)
		fprintf(stderr, "v4l2_read: --sequence: %s\n",
			rdc_strerror(ret));
	free(b);
	free(px);
	return ret;
}

static int simulate(struct ropts *o)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	rdc_dev *dev;
	int ret = rdc_open("sim:", &dev);

	if (ret || !res) {
		free(res);
		return -1;
	}
	for (int i = 0; i < o->nex && !ret; i++) {
		struct expect *e = &o->ex[i];

		memset(res, 0, sizeof(*res));
		ret = rdc_script_run_file(dev, e->script, res);
		if (!ret)
			ret = rdc_script_frame_wait(dev, res);
		if (!ret)
			ret = rdc_frame_grab(dev, NULL, 0, &e->w, &e->h);
		if (ret == RDC_E_RANGE) {
			e->px = malloc((size_t)e->w * e->h * 4);
			ret = e->px ? rdc_frame_grab(dev, e->px,
						     (size_t)e->w * e->h, &e->w,
						     &e->h) :
				      RDC_E_NOMEM;
		}
		if (!ret)
			ret = rdc_sink_interval(dev, &e->num, &e->den);
		if (ret)
			fprintf(stderr, "v4l2_read: %s: %s %s\n", e->script,
				rdc_strerror(ret), res->error_msg);
	}
	if (!ret && o->nseq)
		ret = simulate_seq(o, dev);
	rdc_close(dev);
	free(res);
	return ret ? -1 : 0;
}

/* Expected CRCs for this capture format; -1 if a row pitch is off. */
static int expect_crcs(struct ropts *o, int fmt, uint32_t bpl)
{
	for (int i = 0; i < o->nex; i++) {
		struct expect *e = &o->ex[i];
		struct rdc_frame f = { .xrgb = e->px,
				       .width = e->w,
				       .height = e->h,
				       .stride = e->w };
		size_t want = rdc_sink_fmt_bytesperline(fmt, e->w);
		uint8_t *b;

		e->crc = 0;
		if (bpl && bpl != want)
			continue; /* another size */
		b = malloc(want * e->h);
		if (!b || rdc_sink_convert(fmt, b, want, &f)) {
			free(b);
			return -1;
		}
		e->crc = (uint32_t)crc32(0, b, (uInt)(want * e->h));
		free(b);
	}
	return 0;
}

static struct expect *match(struct ropts *o, uint32_t w, uint32_t h,
			    uint32_t crc)
{
	for (int i = 0; i < o->nex; i++)
		if (o->ex[i].w == w && o->ex[i].h == h && o->ex[i].crc == crc)
			return &o->ex[i];
	return NULL;
}

/*
 * A frame's place in the order simulated: a script's index, or nex + k
 * for the k-th --sequence frame (whose interval is the last script's, in
 * *e); -1 when it matches nothing.  Counts it as seen and, with
 * --in-order, whether it came after the frame matched before it.
 */
static int64_t place(struct ropts *o, int fmt, uint32_t w, uint32_t h,
		     uint32_t crc, struct expect **e)
{
	int64_t at = -1;

	*e = match(o, w, h, crc);
	if (*e) {
		(*e)->seen++;
		at = *e - o->ex;
	} else if (o->nseq && fmt == o->seq_fmt && w == o->seq_w &&
		   h == o->seq_h) {
		for (uint32_t k = 0; k < o->nseq && at < 0; k++)
			if (o->seq_crc[k] == crc)
				at = o->nex + (int64_t)k;
		if (at >= 0) {
			o->seq_seen++;
			*e = &o->ex[o->nex - 1];
		}
	}
	if (at >= 0 && o->in_order) {
		if (at <= o->last) {
			o->order_bad++;
			fprintf(stderr,
				"v4l2_read: frame %lld after frame "
				"%lld: out of order\n",
				(long long)at, (long long)o->last);
		}
		o->last = at;
	}
	return at;
}

static int all_seen(const struct ropts *o)
{
	for (int i = 0; i < o->nex; i++)
		if (o->ex[i].seen < o->each)
			return 0;
	return 1;
}

static int check_raw(struct ropts *o)
{
	int fmt = rdc_sink_fmt_by_name(o->format);
	FILE *f = fopen(o->raw, "rb");
	uint64_t n = 0, bad = 0;
	size_t bpl, size;
	uint8_t *buf;

	if (fmt < 0 || !f) {
		fprintf(stderr, "v4l2_read: bad --format or --raw\n");
		if (f)
			fclose(f);
		return 1;
	}
	expect_crcs(o, fmt, 0);
	bpl = rdc_sink_fmt_bytesperline(fmt, o->ex[0].w);
	size = bpl * o->ex[0].h;
	buf = malloc(size);
	while (buf && fread(buf, 1, size, f) == size) {
		uint32_t crc = (uint32_t)crc32(0, buf, (uInt)size);
		struct expect *e;

		if (place(o, fmt, o->ex[0].w, o->ex[0].h, crc, &e) < 0)
			bad++;
		n++;
	}
	fclose(f);
	free(buf);
	printf("raw: %llu frames of %zu bytes, %llu not matching\n",
	       (unsigned long long)n, size, (unsigned long long)bad);
	if (o->nseq)
		printf("sequence: %llu of its %u frames seen, %llu out of "
		       "order\n",
		       (unsigned long long)o->seq_seen, o->nseq,
		       (unsigned long long)o->order_bad);
	return !buf || bad || o->order_bad || n != o->frames ||
	       (o->need_all && !all_seen(o));
}

struct session {
	int fd, fmt;
	uint32_t w, h, bpl, sizeimage, fourcc;
	struct v4l2_fract tpf;
};

/*
 * Whether a writer has given the device its format.  v4l2loopback with
 * exclusive_caps=1 announces CAPTURE only while it counts a writer; and
 * before any writer 0.13 answers G_FMT with its default size (640x480,
 * BGR32) and bytesperline and sizeimage 0, where 0.12.7 fails.
 */
static int writer_format(int fd, struct v4l2_format *vf)
{
	struct v4l2_capability cap;
	uint32_t caps;
	int fmt;

	memset(&cap, 0, sizeof(cap));
	if (ioctl(fd, VIDIOC_QUERYCAP, &cap) < 0)
		return 0;
	caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps :
							   cap.capabilities;
	memset(vf, 0, sizeof(*vf));
	vf->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
	if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || ioctl(fd, VIDIOC_G_FMT, vf) < 0)
		return 0;
	fmt = rdc_sink_fmt_by_fourcc(vf->fmt.pix.pixelformat);
	if (!vf->fmt.pix.width || !vf->fmt.pix.height)
		return 0;
	/* Not ours, but complete: said by the caller. */
	if (fmt < 0)
		return 1;
	return vf->fmt.pix.bytesperline >=
		       rdc_sink_fmt_bytesperline(fmt, vf->fmt.pix.width) &&
	       (uint64_t)vf->fmt.pix.sizeimage >=
		       (uint64_t)vf->fmt.pix.bytesperline * vf->fmt.pix.height;
}

/* Open the device once a writer has given it a format. */
static int session_open(struct ropts *o, struct session *s, uint64_t deadline)
{
	while (now_ns() < deadline) {
		struct v4l2_format vf;
		struct v4l2_streamparm parm = {
			.type = V4L2_BUF_TYPE_VIDEO_CAPTURE
		};
		int fd = open(o->device, O_RDONLY | O_NONBLOCK | O_CLOEXEC);

		if (fd < 0 || !writer_format(fd, &vf)) {
			if (fd >= 0)
				close(fd);
			nap(RETRY_NS);
			continue;
		}
		memset(s, 0, sizeof(*s));
		s->fd = fd;
		s->w = vf.fmt.pix.width;
		s->h = vf.fmt.pix.height;
		s->bpl = vf.fmt.pix.bytesperline;
		s->sizeimage = vf.fmt.pix.sizeimage;
		s->fourcc = vf.fmt.pix.pixelformat;
		s->fmt = rdc_sink_fmt_by_fourcc(vf.fmt.pix.pixelformat);
		if (!ioctl(fd, VIDIOC_G_PARM, &parm))
			s->tpf = parm.parm.capture.timeperframe;
		if (s->fmt < 0 || expect_crcs(o, s->fmt, s->bpl)) {
			fprintf(stderr, "v4l2_read: format %.4s not ours\n",
				(const char *)&vf.fmt.pix.pixelformat);
			close(fd);
			return -1;
		}
		printf("session: %ux%u %s bytesperline %u sizeimage %u "
		       "interval %u/%u\n",
		       s->w, s->h, rdc_sink_fmt_name(s->fmt), s->bpl,
		       s->sizeimage, s->tpf.numerator, s->tpf.denominator);
		return 0;
	}
	return -1;
}

/*
 * Whether the format in force is no longer the session's: v4l2loopback
 * 0.13 lets a writer set another one while read() readers hold the
 * device (0.12.7 never does).
 */
static int format_changed(const struct session *s)
{
	struct v4l2_format vf = { .type = V4L2_BUF_TYPE_VIDEO_CAPTURE };

	if (ioctl(s->fd, VIDIOC_G_FMT, &vf) < 0)
		return 1;
	return vf.fmt.pix.width != s->w || vf.fmt.pix.height != s->h ||
	       vf.fmt.pix.pixelformat != s->fourcc ||
	       vf.fmt.pix.bytesperline != s->bpl;
}

static int read_device(struct ropts *o)
{
	uint64_t deadline = now_ns() + o->timeout_ns, n = 0, bad = 0;
	uint64_t sessions = 0, rate_bad = 0, ival_bad = 0, matched = 0;
	uint64_t across = 0;
	struct session s = { .fd = -1 };
	uint8_t *buf = NULL;

	while (n < o->frames || (o->need_all && !all_seen(o))) {
		uint64_t t_first = 0, t_last = 0, in_session = 0;
		size_t cap, want;
		struct expect *e = NULL;

		if (now_ns() >= deadline || session_open(o, &s, deadline))
			break;
		sessions++;
		want = (size_t)s.bpl * s.h;
		cap = (s.sizeimage > want ? s.sizeimage : want) + 1;
		free(buf);
		buf = malloc(cap);
		if (!buf)
			break;
		t_last = now_ns();
		while (n < o->frames || (o->need_all && !all_seen(o))) {
			ssize_t got;
			uint32_t crc;

			/* v4l2loopback's poll() answers only streaming
			 * readers: a read() reader polls by trying. */
			got = read(s.fd, buf, cap);
			if (got < 0 && errno == EAGAIN) {
				uint64_t t = now_ns();

				if (t - t_last > o->stall_ns || t >= deadline)
					break; /* stalled: reopen */
				nap(POLL_NS);
				continue;
			}
			if (got < 0)
				break;
			/*
			 * Another size: the writer may have set a new format
			 * (0.13), and this frame was read with the old one's
			 * buffer.  Not judged: the session starts again on a
			 * new descriptor, which 0.13 hands the newest frame,
			 * not one of the buffers it reallocated with the
			 * format and the writer has not yet rewritten.
			 */
			if ((size_t)got != want && format_changed(&s)) {
				across++;
				break;
			}
			crc = (uint32_t)crc32(0, buf, (uInt)got);
			e = NULL;
			if ((size_t)got == want &&
			    place(o, s.fmt, s.w, s.h, crc, &e) >= 0) {
				matched++;
			} else if (o->settle && !matched) {
				continue; /* the scene is still being drawn */
			} else {
				bad++;
				fprintf(stderr,
					"v4l2_read: frame %llu: %zd "
					"bytes (want %zu), crc %08x "
					"matches nothing\n",
					(unsigned long long)n, got, want, crc);
			}
			n++;
			t_last = now_ns();
			if (!in_session++)
				t_first = t_last;
		}
		close(s.fd);
		s.fd = -1;
		/* The interval the writer announced is the mode's. */
		if (e && (uint64_t)s.tpf.numerator * e->den !=
				 (uint64_t)s.tpf.denominator * e->num) {
			ival_bad++;
			fprintf(stderr,
				"v4l2_read: interval %u/%u, mode's "
				"%u/%u\n",
				s.tpf.numerator, s.tpf.denominator, e->num,
				e->den);
		}
		if (e && in_session > 2) {
			double got_ms = (double)(t_last - t_first) /
					(double)(in_session - 1) / 1e6;
			double want_ms = 1e3 * e->num / e->den;

			printf("session: %llu frames, %.2f ms apart "
			       "(mode: %.2f ms)\n",
			       (unsigned long long)in_session, got_ms, want_ms);
			/*
			 * A reader that falls behind is moved on to the
			 * newest frame, so under emulation on a busy host it
			 * sees fewer frames than were sent: frames closer
			 * together than the mode's interval mean an unpaced
			 * writer, which is a fault whatever the load (a
			 * reader catching up reads a few frames back to back,
			 * so the bound is loose: unpaced is far faster).  Much
			 * farther apart may be a stalled writer or only a
			 * busy host: that is said, not failed.
			 */
			if (o->check_rate && got_ms < RATE_MIN * want_ms)
				rate_bad++;
			if (got_ms > RATE_SLOW * want_ms)
				printf("# frames %.1fx the mode's interval "
				       "apart: a stalled writer or a busy "
				       "host\n",
				       got_ms / want_ms);
		}
	}
	free(buf);
	if (s.fd >= 0)
		close(s.fd);
	printf("device: %llu frames in %llu sessions, %llu not matching, "
	       "%llu read across a format change",
	       (unsigned long long)n, (unsigned long long)sessions,
	       (unsigned long long)bad, (unsigned long long)across);
	for (int i = 0; i < o->nex; i++)
		printf(", %s seen %llu", o->ex[i].script,
		       (unsigned long long)o->ex[i].seen);
	if (o->nseq)
		printf(", sequence: %llu of its %u frames seen, %llu out of "
		       "order",
		       (unsigned long long)o->seq_seen, o->nseq,
		       (unsigned long long)o->order_bad);
	printf("\n");
	return bad || ival_bad || rate_bad || o->order_bad || n < o->frames ||
	       (o->need_all && !all_seen(o));
}

static int parse(int argc, char **argv, struct ropts *o)
{
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(a, "--need-all")) {
			o->need_all = 1;
			o->each = o->each ? o->each : 1;
			continue;
		}
		if (!strcmp(a, "--check-rate")) {
			o->check_rate = 1;
			continue;
		}
		if (!strcmp(a, "--settle")) {
			o->settle = 1;
			continue;
		}
		if (!strcmp(a, "--in-order")) {
			o->in_order = 1;
			continue;
		}
		if (!v)
			return -1;
		i++;
		if (!strcmp(a, "--expect") && o->nex < MAX_EXPECT)
			o->ex[o->nex++].script = v;
		else if (!strcmp(a, "--device"))
			o->device = v;
		else if (!strcmp(a, "--raw"))
			o->raw = v;
		else if (!strcmp(a, "--format"))
			o->format = v;
		else if (!strcmp(a, "--frames"))
			o->frames = strtoull(v, NULL, 10);
		else if (!strcmp(a, "--timeout"))
			o->timeout_ns = strtoull(v, NULL, 10) * NS_PER_S;
		else if (!strcmp(a, "--each")) {
			o->need_all = 1;
			o->each = strtoull(v, NULL, 10);
		} else if (!strcmp(a, "--stall-ms"))
			o->stall_ns = strtoull(v, NULL, 10) * NS_PER_MS;
		else if (!strcmp(a, "--sequence"))
			o->nseq = (uint32_t)strtoul(v, NULL, 10);
		else
			return -1;
	}
	if (!o->nex || (!o->device == !o->raw) ||
	    ((o->raw || o->nseq) && !o->format) || o->nseq > SEQ_MAX)
		return -1;
	return 0;
}

int main(int argc, char **argv)
{
	struct ropts o = { .frames = 10,
			   .timeout_ns = 60 * NS_PER_S,
			   .stall_ns = 1000 * NS_PER_MS };
	int ret;

	o.last = -1;
	setvbuf(stdout, NULL, _IOLBF, 0);
	if (parse(argc, argv, &o)) {
		fprintf(stderr, "usage: v4l2_read --expect A.rdl [--expect "
				"B.rdl...] (--device DEV | --raw FILE --format "
				"F) [--frames N] [--need-all] [--each N] "
				"[--check-rate] "
				"[--settle] [--timeout S] [--stall-ms MS] "
				"[--sequence N --format F] [--in-order]\n");
		return 2;
	}
	if (simulate(&o))
		return 1;
	printf("expected: %d pictures, then %u frames\n", o.nex, o.nseq);
	ret = o.raw ? check_raw(&o) : read_device(&o);
	for (int i = 0; i < o.nex; i++)
		free(o.ex[i].px);
	free(o.seq_crc);
	return ret ? 1 : 0;
}
