// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcctl stream: frames from any librdc device to frame sinks, paced to
 * the simulated refresh rate (or as fast as the device goes).
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "rdc.h"
#include "rdc_sink.h"
#include "report.h"
#include "stream.h"

#define STREAM_MAX_SINKS	 8
#define STREAM_PNG_EVERY_DEFAULT 60 /* rdcd's --png too */
#define STREAM_MAX_SCRIPTS	 16
#define STREAM_SPEC_MAX		 4200
#define NS_PER_S		 1000000000ull
/* Fallen this far behind the wall clock, start pacing afresh rather than
 * send a burst. */
#define STREAM_MAX_LAG_NS NS_PER_S

const char rdcctl_stream_usage[] =
	"  stream [OPTIONS]           stream frames to sinks until --frames\n"
	"                             or a signal:\n"
	"    --from URI               device (default: --uri, or sim:)\n"
	"    --script FILE.rdl        run before the first frame\n"
	"    --at N FILE.rdl          run before frame N (mode changes...)\n"
	"    --v4l2 /dev/videoN       v4l2loopback output\n"
	"    --format F               bgr32 (default), xrgb32, rgb24, yuyv\n"
	"    --png DIR                stills to DIR (every --png-every N)\n"
	"    --png-every N            every Nth frame (default 60, as rdcd's\n"
	"                             --png; 0: none)\n"
	"    --vnc PORT               VNC server on 127.0.0.1:PORT\n"
	"    --web [ADDR:]PORT        the display in a browser at\n"
	"                             http://ADDR:PORT/ (docs/web.md)\n"
	"    --sink SPEC              any sink spec (see rdc_sink.h)\n"
	"    --frames N               stop after N frames (default: never)\n"
	"    --fast                   do not pace to the refresh rate\n";

struct stream_script {
	uint64_t at;
	const char *path;
};

struct stream_opts {
	const char *uri;
	const char *v4l2, *format, *png, *vnc, *web;
	uint32_t png_every;
	bool png_every_set;
	const char *specs[STREAM_MAX_SINKS];
	int nspecs;
	struct stream_script scripts[STREAM_MAX_SCRIPTS];
	int nscripts;
	uint64_t frames;
	int fast;
};

static volatile sig_atomic_t stream_stop;

static void stream_on_signal(int sig)
{
	(void)sig;
	stream_stop = 1;
}

static int parse_u64(const char *s, uint64_t *out)
{
	char *end;

	if (!s || *s < '0' || *s > '9')
		return -1;
	errno = 0;
	*out = strtoull(s, &end, 10);
	return errno || *end ? -1 : 0;
}

static int stream_parse(int argc, char **argv, struct stream_opts *o)
{
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;
		uint64_t n;

		if (!strcmp(a, "--fast")) {
			o->fast = 1;
			continue;
		}
		if (!v) {
			fprintf(stderr, "rdcctl: stream: %s needs a value\n",
				a);
			return -1;
		}
		i++;
		if (!strcmp(a, "--from") || !strcmp(a, "--uri") ||
		    !strcmp(a, "--connect")) {
			o->uri = v;
		} else if (!strcmp(a, "--v4l2")) {
			o->v4l2 = v;
		} else if (!strcmp(a, "--format")) {
			o->format = v;
		} else if (!strcmp(a, "--png")) {
			o->png = v;
		} else if (!strcmp(a, "--vnc")) {
			o->vnc = v;
		} else if (!strcmp(a, "--web")) {
			o->web = v;
		} else if (!strcmp(a, "--png-every")) {
			if (parse_u64(v, &n) || n > UINT32_MAX)
				goto bad;
			o->png_every = (uint32_t)n;
			o->png_every_set = true;
		} else if (!strcmp(a, "--frames")) {
			if (parse_u64(v, &o->frames))
				goto bad;
		} else if (!strcmp(a, "--sink")) {
			if (o->nspecs == STREAM_MAX_SINKS)
				goto bad;
			o->specs[o->nspecs++] = v;
		} else if (!strcmp(a, "--script") || !strcmp(a, "--at")) {
			if (o->nscripts == STREAM_MAX_SCRIPTS)
				goto bad;
			n = 0;
			if (a[2] == 'a') {
				if (parse_u64(v, &n) || i + 1 >= argc)
					goto bad;
				v = argv[++i];
			}
			o->scripts[o->nscripts].at = n;
			o->scripts[o->nscripts++].path = v;
		} else {
			fprintf(stderr, "rdcctl: stream: unknown option '%s'\n",
				a);
			return -1;
		}
		continue;
bad:
		fprintf(stderr, "rdcctl: stream: bad or too many '%s'\n", a);
		return -1;
	}
	return 0;
}

static int stream_add(rdc_sink **sinks, int *n, const char *spec)
{
	int ret;

	if (*n == STREAM_MAX_SINKS) {
		fprintf(stderr, "rdcctl: stream: too many sinks\n");
		return RDC_E_INVAL;
	}
	ret = rdc_sink_open(spec, &sinks[*n]);
	if (ret) {
		char what[STREAM_SPEC_MAX + 32];

		snprintf(what, sizeof(what), "stream: sink '%s'", spec);
		rdcctl_report(what, NULL, ret);
		return ret;
	}
	(*n)++;
	return 0;
}

static int stream_open_sinks(const struct stream_opts *o, rdc_sink **sinks,
			     int *n)
{
	char spec[STREAM_SPEC_MAX];
	int ret = 0;

	if (o->v4l2) {
		snprintf(spec, sizeof(spec), "v4l2:%s,format=%s", o->v4l2,
			 o->format ? o->format : "bgr32");
		ret = stream_add(sinks, n, spec);
	}
	if (!ret && o->png) {
		snprintf(spec, sizeof(spec), "png:%s,every=%u", o->png,
			 o->png_every_set ? o->png_every :
					    STREAM_PNG_EVERY_DEFAULT);
		ret = stream_add(sinks, n, spec);
	}
	if (!ret && o->vnc) {
		snprintf(spec, sizeof(spec), "vnc:%s", o->vnc);
		ret = stream_add(sinks, n, spec);
	}
	if (!ret && o->web) {
		snprintf(spec, sizeof(spec), "web:%s", o->web);
		ret = stream_add(sinks, n, spec);
	}
	for (int i = 0; !ret && i < o->nspecs; i++)
		ret = stream_add(sinks, n, o->specs[i]);
	for (int i = 0; !ret && i < *n; i++) {
		char url[128];

		if (!rdc_sink_url(sinks[i], url, sizeof(url)))
			fprintf(stderr, "rdcctl: stream: web page at %s\n",
				url);
	}
	if (!ret && !*n) {
		fprintf(stderr, "rdcctl: stream: no sink (--v4l2, --png, "
				"--vnc, --web or --sink)\n");
		ret = RDC_E_INVAL;
	}
	return ret;
}

/* Run the scripts due before frame `seq`; 1 if any ran. */
static int stream_scripts(rdc_dev *dev, const struct stream_opts *o,
			  uint64_t seq, struct rdc_script_result *res)
{
	int ran = 0;

	for (int i = 0; i < o->nscripts; i++) {
		int ret;

		if (o->scripts[i].at != seq)
			continue;
		memset(res, 0, sizeof(*res));
		ret = rdc_script_run_file(dev, o->scripts[i].path, res);
		if (ret) {
			rdcctl_script_error(o->scripts[i].path, ret, res);
			return ret;
		}
		/* The next frame sent is the script's whole picture. */
		ret = rdc_script_frame_wait(dev, res);
		if (ret)
			return ret;
		ran = 1;
	}
	return ran;
}

/* What the web page shows beside the picture: what the device answers. */
static void stream_status(rdc_dev *dev, rdc_sink **sinks, int nsinks)
{
	struct rdc_sink_status st = { .size = sizeof(st) };
	uint32_t fmt;
	int web = 0;

	for (int i = 0; i < nsinks; i++)
		web |= !strcmp(rdc_sink_kind(sinks[i]), "web");
	if (!web)
		return;
	if (!rdc_sim_time(dev, &st.time) && !rdc_sim_core_hz(dev, &st.core_hz))
		st.have |= RDC_SINK_HAVE_TIME;
	if (!rdc_pins_get(dev, &st.pins))
		st.have |= RDC_SINK_HAVE_PINS;
	if (!rdc_reg_read(dev, RDC_REG_IRQ_STATUS, &st.irq_status) &&
	    !rdc_reg_read(dev, RDC_REG_IRQ_ENABLE, &st.irq_enable))
		st.have |= RDC_SINK_HAVE_IRQ;
	if (!rdc_reg_read(dev, RDC_REG_FB_FORMAT, &fmt)) {
		st.format = fmt;
		st.have |= RDC_SINK_HAVE_FORMAT;
	}
	for (int i = 0; i < nsinks; i++)
		rdc_sink_status_set(sinks[i], &st);
}

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static void sleep_until(uint64_t t)
{
	struct timespec ts = { .tv_sec = (time_t)(t / NS_PER_S),
			       .tv_nsec = (long)(t % NS_PER_S) };

	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) ==
		       EINTR &&
	       !stream_stop)
		;
}

static int stream_run(rdc_dev *dev, const struct stream_opts *o,
		      rdc_sink **sinks, int nsinks)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	uint32_t *px = NULL, w = 0, h = 0, num = 0, den = 0;
	uint64_t t0 = 0, k = 0;
	size_t cap = 0;
	int ret = 0;

	if (!res)
		return RDC_E_NOMEM;
	for (uint64_t seq = 0; !stream_stop && (!o->frames || seq < o->frames);
	     seq++) {
		struct rdc_frame f;
		uint32_t n2, d2;

		ret = stream_scripts(dev, o, seq, res);
		if (ret < 0)
			break;
		if (!ret)
			ret = rdc_vblank_wait(dev);
		else
			ret = 0;
		if (!ret)
			ret = rdc_frame_grab(dev, px, cap, &w, &h);
		if (ret == RDC_E_RANGE) {
			uint32_t *np = realloc(px, (size_t)w * h * sizeof(*px));

			ret = np ? 0 : RDC_E_NOMEM;
			if (np) {
				px = np;
				cap = (size_t)w * h;
				ret = rdc_frame_grab(dev, px, cap, &w, &h);
			}
		}
		if (ret) {
			char what[48];

			snprintf(what, sizeof(what), "stream: frame %llu",
				 (unsigned long long)seq);
			rdcctl_report(what, NULL, ret);
			break;
		}
		if (rdc_sink_interval(dev, &n2, &d2))
			n2 = d2 = 0;
		stream_status(dev, sinks, nsinks);
		memset(&f, 0, sizeof(f));
		f.xrgb = px;
		f.width = w;
		f.height = h;
		f.stride = w;
		f.seq = seq;
		f.interval_num = n2;
		f.interval_den = d2;
		/* A sink that cannot go on (a PNG that cannot be
		 * written) ends the stream: a failure, not a warning per
		 * frame. */
		for (int i = 0; !ret && i < nsinks; i++) {
			ret = rdc_sink_frame(sinks[i], &f);
			if (ret) {
				char what[64];

				snprintf(what, sizeof(what),
					 "stream: %s sink: frame %llu",
					 rdc_sink_kind(sinks[i]),
					 (unsigned long long)seq);
				rdcctl_report(what, NULL, ret);
			}
		}
		if (ret)
			break;
		if (o->fast || !n2 || !d2)
			continue;
		/* Pace: frame k of this rate leaves at t0 + k * interval. */
		if (n2 != num || d2 != den || !t0) {
			num = n2;
			den = d2;
			t0 = now_ns();
			k = 0;
		}
		k++;
		{
			uint64_t due = t0 + k * (uint64_t)num * NS_PER_S / den;
			uint64_t t = now_ns();

			if (t > due + STREAM_MAX_LAG_NS) {
				t0 = t;
				k = 0;
			} else {
				sleep_until(due);
			}
		}
	}
	free(res);
	free(px);
	return ret;
}

int rdcctl_stream_run(rdc_dev *dev, uint64_t frames, bool fast,
		      rdc_sink **sinks, int nsinks)
{
	struct stream_opts o = { .frames = frames, .fast = fast };

	return stream_run(dev, &o, sinks, nsinks);
}

static void stream_report(rdc_sink **sinks, int n)
{
	for (int i = 0; i < n; i++) {
		struct rdc_sink_stats st;

		if (rdc_sink_stats_get(sinks[i], &st))
			continue;
		printf("%s: frames %llu written %llu dropped %llu "
		       "renegotiations %llu reopens %llu\n",
		       rdc_sink_kind(sinks[i]), (unsigned long long)st.frames,
		       (unsigned long long)st.written,
		       (unsigned long long)st.dropped,
		       (unsigned long long)st.renegotiations,
		       (unsigned long long)st.reopens);
	}
}

int rdcctl_stream_main(int argc, char **argv)
{
	struct stream_opts o = { .uri = "sim:" };
	rdc_sink *sinks[STREAM_MAX_SINKS];
	int i, nsinks = 0, ret;
	struct sigaction sa;
	rdc_dev *dev;

	i = rdcctl_command_at(argc, argv, "stream", &o.uri);
	if (i < 0)
		return -1;
	if (stream_parse(argc - i - 1, argv + i + 1, &o))
		return 2;
	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = stream_on_signal;
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	signal(SIGPIPE, SIG_IGN);

	ret = rdcctl_open(o.uri, &dev);
	if (ret)
		return 1;
	ret = stream_open_sinks(&o, sinks, &nsinks);
	if (!ret)
		ret = stream_run(dev, &o, sinks, nsinks);
	stream_report(sinks, nsinks);
	for (int k = 0; k < nsinks; k++)
		rdc_sink_close(sinks[k]);
	rdc_close(dev);
	return ret ? 1 : 0;
}
