// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * stream-bench: `rdcctl stream` of the demo at 1920x1080 into a v4l2
 * sink, measured where no v4l2loopback device can be loaded.
 *
 * The loop is rdcctl stream's own (rdcctl_stream_run, userspace/rdcctl/
 * stream.c): sim:, the demo script, then for every frame rdc_vblank_wait,
 * rdc_frame_grab, rdc_sink_interval and rdc_sink_frame into the v4l2 sink
 * (its format conversion and its one write() a frame), paced to the
 * simulated refresh, or unpaced (--fast).  Only the device is replaced: the
 * sink's system calls go to a pipe whose other end a child process reads
 * and discards (so every frame's bytes are copied through the kernel, as
 * a write() to v4l2loopback copies them), and the ioctls answer as
 * v4l2loopback does.
 *
 * With --v4l2 /dev/videoN the frames go to that device (v4l2loopback)
 * through the sink's own system calls instead (tests/vm/tests/
 * stream-1080-bench.sh); --frames N sets the frames of each run.
 *
 * The demo is examples/demo.rdl with its mode line set to 1920x1080 (run
 * from the source tree, as `make bench` does).  One JSON object a run:
 *   {"workload":"stream_v4l2","width":1920,"height":1080,"paced":true,
 *    "frames":N,"wall_s":S,"fps":F,"target_fps":60,"cpu_s":C,
 *    "cpu_share":C/S,"reader_cpu_s":R,"written":W,"dropped":D,"met":B}
 * fps counts the frames written a second, from the first to the last; cpu_share is this process's user + system time (getrusage)
 * over the wall time: the share of one core the stream takes (the
 * simulator included); reader_cpu_s is the reader's, the device's part.
 */
#include <errno.h>
#include <linux/videodev2.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "rdc.h"
#include "rdc_sink.h"
#include "sink_priv.h"
#include "report.h" /* rdcctl_open */
#include "stream.h"

#define DEMO	     "examples/demo.rdl"
#define DEMO_MODE    "mode 640x480 i8"
#define DEMO_MODE_HD "mode 1920x1080 i8"
#define HD_W	     1920u
#define HD_H	     1080u
#define HD_HZ	     60u
#define FRAMES	     180u    /* 3 s paced; --frames N */
#define FORMAT	     "bgr32" /* rdcctl stream's default */
#define NS_PER_S     1000000000ull
#define PAGE	     4096u
#define READ_CHUNK   (1u << 16)

static int pipe_w = -1;
static const char *v4l2_dev; /* --v4l2 DEV: a real device, no pipe */
static uint32_t n_frames = FRAMES;

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static double cpu_s(int who)
{
	struct rusage ru;

	getrusage(who, &ru);
	return (double)ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 +
	       (double)ru.ru_stime.tv_sec + ru.ru_stime.tv_usec * 1e-6;
}

/* ---- the device: a pipe to a reader that discards, v4l2loopback's ioctls */

static int dev_open(const char *path, int flags)
{
	(void)path;
	(void)flags; /* blocking: the reader keeps up, nothing is dropped */
	return dup(pipe_w);
}

static int dev_ioctl(int fd, unsigned long req, void *arg)
{
	(void)fd;
	if (req == VIDIOC_QUERYCAP) {
		struct v4l2_capability *c = arg;

		memset(c, 0, sizeof(*c));
		strcpy((char *)c->driver, "v4l2 loopback");
		c->capabilities = V4L2_CAP_DEVICE_CAPS | V4L2_CAP_READWRITE |
				  V4L2_CAP_VIDEO_OUTPUT;
		c->device_caps = V4L2_CAP_READWRITE | V4L2_CAP_VIDEO_OUTPUT;
		return 0;
	}
	if (req == VIDIOC_S_FMT) {
		struct v4l2_pix_format *p =
			&((struct v4l2_format *)arg)->fmt.pix;

		/* what was asked, sizeimage page-rounded as v4l2loopback */
		p->sizeimage = (p->bytesperline * p->height + PAGE - 1) &
			       ~(PAGE - 1);
		return 0;
	}
	if (req == VIDIOC_S_PARM || req == VIDIOC_STREAMON)
		return 0;
	errno = ENOTTY;
	return -1;
}

/* when the first and the last frame of a run were written */
static uint64_t t_first, t_last;
static uint32_t n_written;

static ssize_t dev_write(int fd, const void *buf, size_t len)
{
	ssize_t n = write(fd, buf, len);

	t_last = now_ns();
	if (!n_written++)
		t_first = t_last;
	return n;
}

static int dev_close(int fd)
{
	return close(fd);
}

static const struct rdc_v4l2_io dev_io = {
	.open = dev_open,
	.ioctl = dev_ioctl,
	.write = dev_write,
	.close = dev_close,
};

/* --v4l2 DEV: the device's own system calls, the writes timed */
static int real_open(const char *path, int flags)
{
	return open(path, flags);
}

static int real_ioctl(int fd, unsigned long req, void *arg)
{
	return ioctl(fd, req, arg);
}

static const struct rdc_v4l2_io real_io = {
	.open = real_open,
	.ioctl = real_ioctl,
	.write = dev_write,
	.close = dev_close,
};

/* The reader: a child that drains the pipe until the writer closes it. */
static pid_t reader_start(void)
{
	int fd[2];
	pid_t pid;

	if (pipe(fd))
		return -1;
	pid = fork();
	if (pid == 0) {
		static char buf[READ_CHUNK];

		close(fd[1]);
		while (read(fd[0], buf, sizeof(buf)) > 0)
			;
		_exit(0);
	}
	close(fd[0]);
	if (pid < 0) {
		close(fd[1]);
		return -1;
	}
	pipe_w = fd[1];
	return pid;
}

/* ---- the demo at 1920x1080 ------------------------------------------------ */

/* DEMO with its mode line set to 1080p, in a temporary file. */
static int demo_hd(char *path, size_t cap)
{
	FILE *in = fopen(DEMO, "r"), *out;
	char line[1024];
	bool moded = false;
	int fd;

	snprintf(path, cap, "/tmp/rdc-stream-bench-XXXXXX");
	fd = mkstemp(path);
	if (!in || fd < 0) {
		fprintf(stderr,
			"stream-bench: %s: %s (run from the source "
			"tree)\n",
			in ? path : DEMO, strerror(errno));
		if (in)
			fclose(in);
		return -1;
	}
	out = fdopen(fd, "w");
	if (!out) {
		fclose(in);
		close(fd);
		return -1;
	}
	while (fgets(line, sizeof(line), in)) {
		if (!strncmp(line, DEMO_MODE, strlen(DEMO_MODE))) {
			fputs(DEMO_MODE_HD "\n", out);
			moded = true;
		} else {
			fputs(line, out);
		}
	}
	fclose(in);
	if (fclose(out) || !moded) {
		fprintf(stderr, "stream-bench: %s: no '%s' line\n", DEMO,
			DEMO_MODE);
		unlink(path);
		return -1;
	}
	return 0;
}

/* ---- rdcctl stream's loop ------------------------------------------------- */

struct result {
	bool paced;
	uint32_t frames, w, h;
	double wall, cpu, reader_cpu;
	double fps; /* frames written a second, from the first to the last */
	struct rdc_sink_stats st;
};

/* rdcctl's own: the stream loop opens nothing but through librdc. */
int rdcctl_open(const char *uri, rdc_dev **dev)
{
	return rdc_open(uri, dev);
}

static int stream(rdc_dev *dev, bool paced, struct result *r)
{
	uint64_t t_start;
	double c0, rc0;
	rdc_sink *sink;
	pid_t reader;
	int ret, status;

	memset(r, 0, sizeof(*r));
	r->paced = paced;
	reader = v4l2_dev ? 0 : reader_start();
	if (reader < 0)
		return RDC_E_NOMEM;
	if (v4l2_dev) {
		char spec[256];

		snprintf(spec, sizeof(spec), "%s,format=" FORMAT, v4l2_dev);
		ret = rdc_sink_v4l2_open_io(spec, &real_io, &sink);
	} else {
		ret = rdc_sink_v4l2_open_io("/dev/video-bench,format=" FORMAT,
					    &dev_io, &sink);
	}
	n_written = 0;
	if (ret)
		return ret;
	rc0 = cpu_s(RUSAGE_CHILDREN);
	c0 = cpu_s(RUSAGE_SELF);
	t_start = now_ns();
	ret = rdcctl_stream_run(dev, n_frames, !paced, &sink, 1);
	r->wall = (double)(now_ns() - t_start) / 1e9;
	r->cpu = cpu_s(RUSAGE_SELF) - c0;
	rdc_sink_stats_get(sink, &r->st);
	r->frames = (uint32_t)r->st.frames;
	r->fps = n_written > 1 && t_last > t_first ?
			 (n_written - 1) * 1e9 / (double)(t_last - t_first) :
			 0;
	/* the frames' size: the device's (a grab with no room says it) */
	rdc_frame_grab(dev, NULL, 0, &r->w, &r->h);
	rdc_sink_close(sink);
	if (!v4l2_dev) {
		close(pipe_w);
		pipe_w = -1;
		waitpid(reader, &status, 0);
	}
	r->reader_cpu = cpu_s(RUSAGE_CHILDREN) - rc0;
	return ret;
}

int main(int argc, char **argv)
{
	struct rdc_script_result sres;
	struct result res[2];
	char path[64];
	rdc_dev *dev;
	int ret, i, bad = 0;

	for (i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--v4l2") && i + 1 < argc) {
			v4l2_dev = argv[++i];
		} else if (!strcmp(argv[i], "--frames") && i + 1 < argc &&
			   atoi(argv[i + 1]) > 1) {
			n_frames = (uint32_t)atoi(argv[++i]);
		} else {
			fprintf(stderr,
				"usage: stream-bench [--v4l2 /dev/videoN]"
				" [--frames N]\n");
			return 2;
		}
	}
	signal(SIGPIPE, SIG_IGN);
	if (demo_hd(path, sizeof(path)))
		return 1;
	ret = rdc_open("sim:", &dev);
	if (ret) {
		fprintf(stderr, "stream-bench: sim: %s\n", rdc_strerror(ret));
		unlink(path);
		return 1;
	}
	memset(&sres, 0, sizeof(sres));
	ret = rdc_script_run_file(dev, path, &sres);
	if (!ret)
		ret = rdc_script_frame_wait(dev, &sres);
	unlink(path);
	if (ret) {
		fprintf(stderr, "stream-bench: %s:%u: %s\n", DEMO,
			sres.error_line,
			sres.error_msg[0] ? sres.error_msg : rdc_strerror(ret));
		rdc_close(dev);
		return 1;
	}
	for (i = 0; i < 2; i++) {
		struct result *r = &res[i];
		double fps;
		bool met;

		ret = stream(dev, i == 0, r);
		if (ret) {
			fprintf(stderr, "stream-bench: %s\n",
				rdc_last_error_detail(ret));
			bad = 1;
			break;
		}
		fps = r->fps;
		/* paced: 60 fps (within 1%), every frame written, less than
		 * the whole of one core */
		met = r->w == HD_W && r->h == HD_H &&
		      r->st.written == r->frames && fps >= HD_HZ * 0.99 &&
		      r->cpu / r->wall < 1.0;
		printf("{\"workload\":\"stream_v4l2\",\"width\":%u,"
		       "\"height\":%u,\"format\":\"%s\",\"paced\":%s,"
		       "\"frames\":%u,\"wall_s\":%.3f,\"fps\":%.1f,"
		       "\"target_fps\":%u,\"cpu_s\":%.3f,\"cpu_share\":%.3f,"
		       "\"reader_cpu_s\":%.3f,\"written\":%llu,"
		       "\"dropped\":%llu",
		       r->w, r->h, FORMAT, r->paced ? "true" : "false",
		       r->frames, r->wall, fps, HD_HZ, r->cpu, r->cpu / r->wall,
		       r->reader_cpu, (unsigned long long)r->st.written,
		       (unsigned long long)r->st.dropped);
		if (r->paced)
			printf(",\"met\":%s", met ? "true" : "false");
		printf("}\n");
		fflush(stdout);
		if (r->w != HD_W || r->h != HD_H ||
		    (!v4l2_dev && r->st.written != r->frames)) {
			fprintf(stderr,
				"stream-bench: %ux%u frames, %llu of %u "
				"written\n",
				r->w, r->h, (unsigned long long)r->st.written,
				r->frames);
			bad = 1;
		}
	}
	rdc_close(dev);
	if (!bad) {
		printf("\nrdcctl stream of the demo at %ux%u@%u into v4l2 "
		       "(%s; %s)\n",
		       HD_W, HD_H, HD_HZ, FORMAT,
		       v4l2_dev ? v4l2_dev :
				  "a pipe to a reader stands for the device");
		printf("%-8s %7s %8s %8s %10s %12s %s\n", "", "frames", "fps",
		       "cpu s", "cpu share", "reader cpu s", "kept up");
		for (i = 0; i < 2; i++) {
			const struct result *r = &res[i];
			double fps = r->fps;

			printf("%-8s %7u %8.1f %8.3f %9.0f%% %12.3f %s\n",
			       r->paced ? "paced" : "unpaced", r->frames, fps,
			       r->cpu, 100 * r->cpu / r->wall, r->reader_cpu,
			       !r->paced ? "-" :
			       fps >= HD_HZ * 0.99 && r->cpu / r->wall < 1.0 ?
					   "yes" :
					   "NO");
		}
	}
	return bad;
}
