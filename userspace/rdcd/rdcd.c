// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: a simulated RDC-1 served over UNIX and TCP sockets
 * (docs/protocol.md).  One thread, one poll() loop, non-blocking sockets:
 * the loop accepts clients, reads and answers requests, writes queued
 * replies and frames, and between those moves simulated time (paced to
 * the wall clock, as fast as possible, or, stepped, not at all).
 */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "rdcd.h"

#define NS_PER_S 1000000000ull
/* Paced mode: wake this often to move time (1 ms). */
#define RDCD_TICK_MS 1
/* ... and with nobody looking at frames (rdcd_watch): 50 ms, within
 * RDCD_PACE_SLACK, so that an idle daemon wakes 20 times a second. */
#define RDCD_IDLE_TICK_MS 50
/* Fast mode: simulated cycles between looks at the sockets (1 ms). */
#define RDCD_FAST_SLICE (RDC_DEFAULT_CORE_HZ / 1000u)
/* Paced mode: a host this far behind the wall clock starts over from now
 * instead of racing to catch up (100 ms). */
#define RDCD_PACE_SLACK (RDC_DEFAULT_CORE_HZ / 10u)
/* Paced and fast modes: while a SUBMIT waits for FIFO room, the advance
 * moves time in pieces this long and refills the FIFO after each, so the
 * feed keeps up with the display processor (a FIFO of host-blit data
 * drains in about 800 cycles) instead of 256 words a turn of the loop. */
#define RDCD_FEED_PIECE 256u

static volatile sig_atomic_t rdcd_stop;
static volatile sig_atomic_t rdcd_snap;

static void rdcd_on_signal(int sig)
{
	rdcd_stop = sig;
}

static void rdcd_on_snapshot(int sig)
{
	(void)sig;
	rdcd_snap = 1;
}

/* SIGUSR1: the next frame as a still, in every sink that makes stills. */
static void rdcd_snapshot(struct rdcd *d)
{
	unsigned int n = 0;

	rdcd_snap = 0;
	for (unsigned int i = 0; i < d->nsinks; i++)
		if (!rdc_sink_snapshot(d->sinks[i]))
			n++;
	rdcd_log(d, n ? RDCD_LOG_INFO : RDCD_LOG_WARN,
		 "snapshot requested: %u sink%s will keep the next frame", n,
		 n == 1 ? "" : "s");
}

void rdcd_log(const struct rdcd *d, int level, const char *fmt, ...)
{
	static const char *const name[] = { "error", "warning", "info",
					    "debug" };
	va_list ap;

	if (level > d->log_level)
		return;
	flockfile(stderr); /* one line at a time: ffs.c logs from threads */
	fprintf(stderr, "rdcd: %s: ", name[level]);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	funlockfile(stderr);
}

static void usage(FILE *f)
{
	fputs("usage: rdcd [OPTIONS]\n"
	      "\n"
	      "Serve a simulated RDC-1 over sockets (docs/protocol.md).\n"
	      "\n"
	      "  --listen URI     unix:PATH or tcp:HOST:PORT (repeatable); default\n"
	      "                   unix: at $XDG_RUNTIME_DIR/rdc/rdc.sock, else\n"
	      "                   /tmp/rdc-$UID/rdc.sock.  TCP with an empty HOST\n"
	      "                   is 127.0.0.1; any other than loopback needs\n"
	      "                   --token.  PORT 0: the kernel picks one.\n"
	      "                   ffs:DIR: the RDC-1 as a USB device on the\n"
	      "                   functionfs mounted at DIR (docs/usb.md)\n"
	      "                   udl:DIR[?pad=N]: the same with DisplayLink's\n"
	      "                   command set, for Linux's udl DRM driver\n"
	      "                   systemd[:NAME]: the listening sockets\n"
	      "                   systemd passed (LISTEN_FDS; those named\n"
	      "                   NAME), the default when there are any\n"
	      "  --fast           run unpaced, as fast as the host allows\n"
	      "  --stepped        time moves only when the controlling client\n"
	      "                   waits or steps, as on sim: (reproducible)\n"
	      "                   default: paced to the pixel clock\n"
	      "  --mode NAME      program a preset at start (e.g. 640x480)\n"
	      "  --vram SIZE      VRAM bytes, K/M suffixes (default 16M)\n"
	      "  --record FILE    write a trace for `rdcctl replay`\n"
	      "  --vcd FILE       the chip's signals as a Value Change Dump\n"
	      "  --token FILE     TCP clients must present this file's contents\n"
	      "  --group          socket mode 0660 instead of 0600\n"
	      "  --ready-file F   once listening, write the listen URIs to F\n"
	      "  --v4l2 DEV       frames to a v4l2loopback device (DEV[,format=\n"
	      "                   bgr32|xrgb32|rgb24|yuyv])\n"
	      "  --png DIR        every 60th frame as DIR/frame-N.png\n"
	      "                   (DIR,every=N for another N; every=0: only\n"
	      "                   on SIGUSR1, which asks every sink for the\n"
	      "                   next frame as a still)\n"
	      "  --vnc PORT       a VNC server on 127.0.0.1:PORT\n"
	      "  --web [ADDR:]PORT  the live display in a browser at\n"
	      "                   http://ADDR:PORT/ (docs/web.md); ADDR\n"
	      "                   127.0.0.1 unless given, any other than\n"
	      "                   loopback needs --token (the page then\n"
	      "                   wants #token=... after its address)\n"
	      "  --sink SPEC      any frame sink (userspace/include/rdc_sink.h)\n"
	      "  --gpio-sim NAME  the pins TE, IRQ, RESET_N, BL_EN as the lines\n"
	      "                   of the gpio-sim chip NAME, made in configfs\n"
	      "                   (/sys/kernel/config/gpio-sim/NAME) and taken\n"
	      "                   down on exit (needs gpio-sim.ko; docs/pins.md)\n"
	      "  -v, -q           more, less logging (stderr)\n"
	      "  -h, --help       this text\n"
	      "  --version        rdcd's release and librdc's\n",
	      f);
}

/* The release rdcd was built as, and the librdc it runs on. */
static void rdcd_version(void)
{
	uint32_t v = rdc_version();

	printf("rdcd %u.%u.%u (librdc %u.%u.%u)\n", RDC_VERSION_MAJOR,
	       RDC_VERSION_MINOR, RDC_VERSION_PATCH, RDC_VERSION_GET_MAJOR(v),
	       RDC_VERSION_GET_MINOR(v), RDC_VERSION_GET_PATCH(v));
}

uint64_t rdcd_wall_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

/* ---- Listeners ----------------------------------------------------------- */

static int rdcd_mkdir_parent(const char *path)
{
	char dir[sizeof(((struct sockaddr_un *)0)->sun_path)];
	struct stat st;
	char *slash;

	snprintf(dir, sizeof(dir), "%s", path);
	slash = strrchr(dir, '/');
	if (!slash || slash == dir)
		return 0;
	*slash = 0;
	if (mkdir(dir, 0700) && errno != EEXIST)
		return -1;
	/* /tmp is shared: a directory someone else made is not ours to use */
	if (lstat(dir, &st))
		return -1;
	if (!S_ISDIR(st.st_mode) || st.st_uid != geteuid() ||
	    (st.st_mode & 0022)) {
		errno = EPERM;
		return -1;
	}
	return 0;
}

static int rdcd_listen_unix(struct rdcd *d, struct rdcd_listener *l,
			    const char *path, bool group)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	struct stat st;
	mode_t old;
	int fd;

	if (!*path) {
		if (rdc_proto_default_path(l->path, sizeof(l->path))) {
			rdcd_log(d, RDCD_LOG_ERR,
				 "default socket path too long");
			return -1;
		}
		if (rdcd_mkdir_parent(l->path)) {
			rdcd_log(d, RDCD_LOG_ERR, "%s: %s", l->path,
				 strerror(errno));
			return -1;
		}
	} else if (strlen(path) >= sizeof(l->path)) {
		rdcd_log(d, RDCD_LOG_ERR, "socket path too long: %s", path);
		return -1;
	} else {
		strcpy(l->path, path);
	}
	strcpy(sa.sun_path, l->path);
	/*
	 * Only a socket file nobody answers on (left over from a crash) is
	 * replaced; anything else at the path, a symlink included, is not
	 * ours to delete.
	 */
	if (!lstat(l->path, &st)) {
		if (!S_ISSOCK(st.st_mode)) {
			rdcd_log(
				d, RDCD_LOG_ERR,
				"%s exists and is not a socket: not replacing it",
				l->path);
			l->path[0] = 0;
			return -1;
		}
		fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC,
			    0);
		if (fd < 0)
			return -1;
		if (!connect(fd, (struct sockaddr *)&sa, sizeof(sa)) ||
		    errno == EAGAIN || errno == EINPROGRESS) {
			rdcd_log(d, RDCD_LOG_ERR,
				 "%s: another daemon is listening", l->path);
			close(fd);
			l->path[0] = 0;
			return -1;
		}
		if (errno != ECONNREFUSED) {
			rdcd_log(d, RDCD_LOG_ERR, "%s: %s: not replacing it",
				 l->path, strerror(errno));
			close(fd);
			l->path[0] = 0;
			return -1;
		}
		close(fd);
		if (unlink(l->path) && errno != ENOENT) {
			rdcd_log(d, RDCD_LOG_ERR, "%s: %s", l->path,
				 strerror(errno));
			l->path[0] = 0;
			return -1;
		}
		rdcd_log(d, RDCD_LOG_INFO, "%s: replacing a stale socket",
			 l->path);
	}
	fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (fd < 0)
		return -1;
	/* Born with the final mode: no window where others may connect. */
	old = umask(group ? 0117 : 0177);
	if (bind(fd, (struct sockaddr *)&sa, sizeof(sa)) || listen(fd, 64)) {
		umask(old);
		rdcd_log(d, RDCD_LOG_ERR, "%s: %s", l->path, strerror(errno));
		close(fd);
		l->path[0] = 0;
		return -1;
	}
	umask(old);
	chmod(l->path, group ? 0660 : 0600);
	{
		struct stat bound;

		if (!lstat(l->path, &bound)) {
			l->path_dev = (uint64_t)bound.st_dev;
			l->path_ino = (uint64_t)bound.st_ino;
		}
	}
	l->fd = fd;
	/* uri holds "unix:" and any sun_path */
	strcpy(l->uri, "unix:");
	strcat(l->uri, l->path);
	return 0;
}

static int rdcd_listen_tcp(struct rdcd *d, struct rdcd_listener *l,
			   const char *hostport)
{
	struct sockaddr_storage ss;
	char name[RDC_TCP_NAME_MAX];
	int fd = rdc_tcp_listen(hostport, 64, &ss);

	if (fd < 0) {
		rdcd_log(d, RDCD_LOG_ERR, "tcp:%s", rdc_last_error_detail(fd));
		return -1;
	}
	l->fd = fd;
	l->tcp = true;
	l->need_token = !rdc_tcp_is_loopback(&ss);
	if (l->need_token && !d->have_token) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "tcp:%s is not loopback: --token FILE is required",
			 hostport);
		close(fd);
		l->fd = -1;
		return -1;
	}
	rdc_tcp_name(&ss, name);
	snprintf(l->uri, sizeof(l->uri), "tcp:%s", name);
	return 0;
}

static int rdcd_add_listener(struct rdcd *d, const char *uri, bool group)
{
	struct rdcd_listener *l;
	int ret;

	if (d->nlis == RDCD_MAX_LISTEN) {
		rdcd_log(d, RDCD_LOG_ERR, "too many --listen");
		return -1;
	}
	l = &d->lis[d->nlis];
	memset(l, 0, sizeof(*l));
	l->fd = -1;
	if (!strcmp(uri, "systemd") || !strncmp(uri, "systemd:", 8))
		return rdcd_systemd_add(d, uri[7] ? uri + 8 : "");
	if (!strncmp(uri, "unix:", 5)) {
		ret = rdcd_listen_unix(d, l, uri + 5, group);
	} else if (!strncmp(uri, "tcp:", 4)) {
		ret = rdcd_listen_tcp(d, l, uri + 4);
	} else if (!strncmp(uri, "ffs:", 4)) {
		l->fd = rdcd_ffs_open(d, uri + 4, &l->ffs);
		snprintf(l->uri, sizeof(l->uri), "%s", uri);
		ret = l->fd < 0 ? -1 : 0;
	} else if (!strncmp(uri, "udl:", 4)) {
		l->fd = rdcd_udl_open(d, uri + 4, &l->udl);
		snprintf(l->uri, sizeof(l->uri), "%s", uri);
		ret = l->fd < 0 ? -1 : 0;
	} else {
		rdcd_log(d, RDCD_LOG_ERR,
			 "%s: want unix:PATH, tcp:HOST:PORT, ffs:DIR, udl:DIR "
			 "or systemd[:NAME]",
			 uri);
		return -1;
	}
	if (ret)
		return ret;
	rdcd_log(d, RDCD_LOG_INFO, "listening on %s%s", l->uri,
		 l->need_token ? " (token required)" : "");
	d->nlis++;
	return 0;
}

/*
 * New connections, at most RDCD_MAX_PENDING a turn: the loop reads them
 * (a HELLO has usually come with them) before it takes more, so a flood
 * waits in the backlog rather than pushing out those already taken.
 * Admission is rdcd_client_new's (connections without HELLO per
 * listener, the oldest silent one evicted) and the HELLO's
 * (RDCD_MAX_CLIENTS, RDCD_MAX_CLIENTS_PER_LISTENER); so a connection is
 * always accepted, and at most a few listeners' worth of silent ones cost
 * anything.
 */
static void rdcd_accept(struct rdcd *d, struct rdcd_listener *l)
{
	d->accept_lis = (int)(l - d->lis);
	if (l->ffs) {
		rdcd_ffs_accept(d, l->ffs);
		d->accept_lis = -1;
		return;
	}
	if (l->udl) {
		rdcd_udl_accept(d, l->udl);
		d->accept_lis = -1;
		return;
	}
	for (unsigned int n = 0; n < RDCD_MAX_PENDING; n++) {
		struct sockaddr_storage ss;
		socklen_t sl = sizeof(ss);
		char peer[64] = "local", addr[INET6_ADDRSTRLEN] = "?";
		int fd = accept4(l->fd, (struct sockaddr *)&ss, &sl,
				 SOCK_NONBLOCK | SOCK_CLOEXEC);
		int one = 1;

		if (fd < 0) {
			if (errno != EAGAIN && errno != EWOULDBLOCK &&
			    errno != EINTR)
				rdcd_log_limited(d, &d->connlog, RDCD_LOG_WARN,
						 "accept: %s", strerror(errno));
			d->accept_lis = -1;
			return;
		}
		if (l->tcp) {
			setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one,
				   sizeof(one));
			if (ss.ss_family == AF_INET)
				inet_ntop(
					AF_INET,
					&((struct sockaddr_in *)&ss)->sin_addr,
					addr, sizeof(addr));
			else if (ss.ss_family == AF_INET6)
				inet_ntop(
					AF_INET6,
					&((struct sockaddr_in6 *)&ss)->sin6_addr,
					addr, sizeof(addr));
			snprintf(peer, sizeof(peer), "tcp %s", addr);
		}
		if (!rdcd_client_new(d, fd, l->tcp && d->have_token, peer)) {
			rdcd_log(d, RDCD_LOG_ERR, "out of memory");
			close(fd);
		}
	}
	d->accept_lis = -1;
}

/* The token: rdc_token_read's rule (rdc_server.h), the client's too. */
static int rdcd_read_token(struct rdcd *d, const char *path)
{
	int ret = rdc_token_read("--token", path, d->token, &d->token_len);

	if (ret) {
		rdcd_log(d, RDCD_LOG_ERR, "%s", rdc_last_error_detail(ret));
		return -1;
	}
	d->have_token = true;
	return 0;
}

static int rdcd_write_ready(struct rdcd *d, const char *path)
{
	char tmp[4096];
	FILE *f;

	snprintf(tmp, sizeof(tmp), "%s.tmp", path);
	f = fopen(tmp, "w");
	if (!f)
		return -1;
	for (unsigned int i = 0; i < d->nlis; i++)
		fprintf(f, "%s\n", d->lis[i].uri);
	if (fclose(f) || rename(tmp, path))
		return -1;
	return 0;
}

/* ---- Time ---------------------------------------------------------------- */

/* On the chip's stack: the loop's advance (paced, fast). */
static void rdcd_advance_job(struct rdcd *d, void *arg)
{
	bool feeding = rdcd_feed_pending(d);

	(void)arg;
	while (d->adv_target > rdc_hw_now(d->hw)) {
		uint64_t n = d->adv_target - rdc_hw_now(d->hw);

		if (feeding && n > RDCD_FEED_PIECE)
			n = RDCD_FEED_PIECE;
		if (rdc_sim_step(d->dev, n))
			break;
		if (feeding)
			feeding = rdcd_feed_pending(d);
	}
}

/*
 * Move simulated time as the mode says, on the chip's stack (chip.c): a
 * run that does not end within RDCD_SLICE_US goes on at the next turn,
 * the sockets served between.  Returns true when a run ended.
 */
static bool rdcd_advance(struct rdcd *d)
{
	uint64_t now = rdc_hw_now(d->hw), target;

	if (rdcd_chip_busy(d))
		return !rdcd_chip_resume(d);

	switch (d->mode) {
	case RDC_RUN_FAST:
		target = now + RDCD_FAST_SLICE;
		break;
	case RDC_RUN_PACED:
		/* a host that fell behind keeps the rate and drops the debt */
		target = rdc_pace_target(&d->pace, rdcd_wall_ns(), now,
					 RDC_DEFAULT_CORE_HZ, RDCD_PACE_SLACK);
		break;
	default:
		/* stepped: time moves only in the controller's request */
		return rdcd_stepped_start(d) == 0;
	}
	if (target <= now)
		return false;
	d->adv_target = target;
	return !rdcd_chip_run(d, rdcd_advance_job, NULL);
}

/* ---- Main ---------------------------------------------------------------- */

struct rdcd_opts {
	const char *listen[RDCD_MAX_LISTEN];
	unsigned int nlisten;
	const char *mode, *record, *token, *ready, *vcd;
	uint32_t vram;
	bool group;
	const char *gpio_sim;
	char *sinks[RDCD_MAX_SINKS];
	unsigned int nsinks;
};

/* A PNG a second at 60 Hz unless the spec says otherwise. */
#define RDCD_PNG_EVERY 60

static int rdcd_sink_opt(struct rdcd_opts *o, const char *opt, const char *val)
{
	const char *kind = !strcmp(opt, "--v4l2") ? "v4l2:" :
			   !strcmp(opt, "--png")  ? "png:" :
			   !strcmp(opt, "--vnc")  ? "vnc:" :
			   !strcmp(opt, "--web")  ? "web:" :
						    "";
	bool png_every = kind[0] == 'p' && !strstr(val, "every=");
	char *spec;

	if (o->nsinks == RDCD_MAX_SINKS) {
		fprintf(stderr, "rdcd: too many frame sinks\n");
		return -1;
	}
	if ((png_every ? asprintf(&spec, "%s%s,every=%d", kind, val,
				  RDCD_PNG_EVERY) :
			 asprintf(&spec, "%s%s", kind, val)) < 0)
		return -1;
	o->sinks[o->nsinks++] = spec;
	return 0;
}

static int parse_size(const char *s, uint32_t *out)
{
	char *end;
	unsigned long long v = strtoull(s, &end, 10);

	if (end == s)
		return -1;
	if (*end == 'K' || *end == 'k')
		v <<= 10, end++;
	else if (*end == 'M' || *end == 'm')
		v <<= 20, end++;
	if (*end || v > UINT32_MAX)
		return -1;
	*out = (uint32_t)v;
	return 0;
}

static int parse_args(struct rdcd *d, int argc, char **argv,
		      struct rdcd_opts *o)
{
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		const char *val = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			exit(0);
		} else if (!strcmp(a, "--version")) {
			rdcd_version();
			exit(0);
		} else if (!strcmp(a, "--fast")) {
			d->mode = RDC_RUN_FAST;
		} else if (!strcmp(a, "--stepped")) {
			d->mode = RDC_RUN_STEPPED;
		} else if (!strcmp(a, "--group")) {
			o->group = true;
		} else if (!strcmp(a, "-v")) {
			d->log_level++;
		} else if (!strcmp(a, "-q")) {
			d->log_level--;
		} else if (!strcmp(a, "--gpio-sim")) {
			if (!val) {
				fprintf(stderr, "rdcd: %s needs a value\n", a);
				return -1;
			}
			o->gpio_sim = argv[++i];
		} else if (!strcmp(a, "--v4l2") || !strcmp(a, "--png") ||
			   !strcmp(a, "--vnc") || !strcmp(a, "--web") ||
			   !strcmp(a, "--sink")) {
			if (!val) {
				fprintf(stderr, "rdcd: %s needs a value\n", a);
				return -1;
			}
			i++;
			if (rdcd_sink_opt(o, a, val))
				return -1;
		} else if (!strcmp(a, "--listen") || !strcmp(a, "--mode") ||
			   !strcmp(a, "--vram") || !strcmp(a, "--record") ||
			   !strcmp(a, "--token") ||
			   !strcmp(a, "--ready-file") || !strcmp(a, "--vcd")) {
			if (!val) {
				fprintf(stderr, "rdcd: %s needs a value\n", a);
				return -1;
			}
			i++;
			if (!strcmp(a, "--listen")) {
				if (o->nlisten == RDCD_MAX_LISTEN) {
					fprintf(stderr,
						"rdcd: too many --listen\n");
					return -1;
				}
				o->listen[o->nlisten++] = val;
			} else if (!strcmp(a, "--mode")) {
				o->mode = val;
			} else if (!strcmp(a, "--record")) {
				o->record = val;
			} else if (!strcmp(a, "--vcd")) {
				o->vcd = val;
			} else if (!strcmp(a, "--token")) {
				o->token = val;
			} else if (!strcmp(a, "--ready-file")) {
				o->ready = val;
			} else if (parse_size(val, &o->vram)) {
				fprintf(stderr, "rdcd: bad --vram '%s'\n", val);
				return -1;
			}
		} else {
			fprintf(stderr, "rdcd: unknown argument '%s'\n", a);
			usage(stderr);
			return -1;
		}
	}
	if (d->log_level < RDCD_LOG_ERR)
		d->log_level = RDCD_LOG_ERR;
	if (d->log_level > RDCD_LOG_DEBUG)
		d->log_level = RDCD_LOG_DEBUG;
	return 0;
}

/* Connections at the top of a loop turn: HELLO'd and not yet. */
#define RDCD_MAX_CONNS \
	(RDCD_MAX_CLIENTS + RDCD_MAX_LISTEN * RDCD_MAX_PENDING_YOUNG)

static void rdcd_loop(struct rdcd *d)
{
	struct pollfd pfd[RDCD_MAX_LISTEN + RDCD_MAX_CONNS];
	struct rdcd_client *cl[RDCD_MAX_CONNS];
	sigset_t none;

	sigemptyset(&none);
	while (!rdcd_stop) {
		unsigned int n = 0, nc = 0;
		struct timespec ts = { 0 }, *tmo = NULL;
		uint64_t hello_ns = rdcd_hello_deadlines(d);
		int r;

		for (unsigned int i = 0; i < d->nlis; i++)
			pfd[n++] = (struct pollfd){ .fd = d->lis[i].fd,
						    .events = POLLIN };
		for (struct rdcd_client *c = d->clients; c; c = c->next) {
			short ev = 0;

			if (nc == RDCD_MAX_CONNS)
				break; /* cannot be: admission bounds them */
			if (rdcd_client_wants_read(c))
				ev |= POLLIN;
			if (c->out_head)
				ev |= POLLOUT;
			cl[nc++] = c;
			pfd[n++] = (struct pollfd){ .fd = c->fd, .events = ev };
		}
		if (rdcd_chip_busy(d)) {
			tmo = &ts; /* zero: the chip goes on at once */
		} else if (d->mode == RDC_RUN_PACED) {
			ts.tv_nsec = (d->watched || d->gpiosim ?
					      RDCD_TICK_MS :
					      RDCD_IDLE_TICK_MS) *
				     1000000L;
			tmo = &ts;
		} else if (d->mode == RDC_RUN_FAST || rdcd_has_pending(d)) {
			tmo = &ts; /* zero: just look */
		} else if (d->gpiosim) {
			/* a GPIO consumer's RESET_N/BL_EN has no fd to wake us */
			ts.tv_nsec = RDCD_GPIOSIM_POLL_MS * 1000000L;
			tmo = &ts;
		}
		if (hello_ns != UINT64_MAX &&
		    (!tmo ||
		     (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec >
			     hello_ns)) {
			/* wake for the next HELLO deadline (and a ms more) */
			hello_ns += 1000000u;
			ts.tv_sec = (time_t)(hello_ns / NS_PER_S);
			ts.tv_nsec = (long)(hello_ns % NS_PER_S);
			tmo = &ts;
		}
		/* Signals are blocked except inside ppoll: none is missed. */
		r = ppoll(pfd, n, tmo, &none);
		if (r < 0 && errno != EINTR) {
			rdcd_log(d, RDCD_LOG_ERR, "poll: %s", strerror(errno));
			break;
		}
		if (r > 0) {
			unsigned int k = 0;

			for (unsigned int i = 0; i < d->nlis; i++, k++)
				if (pfd[k].revents & POLLIN)
					rdcd_accept(d, &d->lis[i]);
			for (unsigned int i = 0; i < nc; i++, k++) {
				struct rdcd_client *c = cl[i];

				if (pfd[k].revents & POLLOUT)
					rdcd_client_flush(d, c);
				if (pfd[k].revents &
				    (POLLIN | POLLHUP | POLLERR))
					rdcd_client_read(d, c);
				if ((pfd[k].revents & (POLLHUP | POLLERR)) &&
				    !(pfd[k].revents & POLLIN))
					c->dead = true;
			}
		}
		if (rdcd_snap)
			rdcd_snapshot(d);
		if (!rdcd_chip_busy(d))
			rdcd_gpiosim_poll(d); /* drives pins: between runs */
		if (rdcd_advance(d))
			rdcd_after_advance(d);
		/* what waited for a run or a pending request to end */
		rdcd_release_held(d);
		if (!rdcd_chip_busy(d))
			rdcd_web_status(d); /* what the web page shows */
		for (unsigned int i = 0; i < d->nsinks; i++)
			rdc_sink_poll(d->sinks[i]); /* VNC clients */
		/* Replies go out at once: most clients wait for them. */
		for (struct rdcd_client *c = d->clients; c; c = c->next)
			if (c->out_head)
				rdcd_client_flush(d, c);
		rdcd_out_bound(d);
		for (struct rdcd_client *c = d->clients, *next; c; c = next) {
			next = c->next;
			/* the chip's run still holds its client: later */
			if (c->dead &&
			    !(rdcd_chip_busy(d) && d->chip_client == c))
				rdcd_client_free(d, c);
		}
	}
}

int main(int argc, char **argv)
{
	struct rdcd d = { .log_level = RDCD_LOG_INFO,
			  .vram_size = 16u << 20,
			  .mode = RDC_RUN_PACED,
			  .accept_lis = -1 };
	struct rdcd_opts o = { 0 };
	struct sigaction sa = { .sa_handler = rdcd_on_signal };
	struct sigaction snap = { .sa_handler = rdcd_on_snapshot };
	rdc_vcd *vcd = NULL;
	sigset_t block;
	bool ready = false;
	int ret = 1;

	/*
	 * Before anything else: a SIGUSR1 sent as rdcd starts (`rdcd ... &
	 * kill -USR1 $!`) is held until the loop's ppoll lets it in, rather
	 * than ending the process by its default action.  One that reaches
	 * the shell's child before it has become rdcd is out of rdcd's
	 * reach: the README waits for --ready-file.
	 */
	sigemptyset(&block);
	sigaddset(&block, SIGINT);
	sigaddset(&block, SIGTERM);
	sigaddset(&block, SIGUSR1);
	sigprocmask(SIG_BLOCK, &block, NULL);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGUSR1, &snap, NULL);
	signal(SIGPIPE, SIG_IGN);

	if (parse_args(&d, argc, argv, &o))
		return 2;
	if (o.vram)
		d.vram_size = o.vram;
	if (o.token && rdcd_read_token(&d, o.token))
		return 1;

	if (o.record) {
		d.rec = rdc_server_rec_open(o.record, d.vram_size);
		if (!d.rec) {
			rdcd_log(&d, RDCD_LOG_ERR, "--record %s: %s", o.record,
				 strerror(errno));
			return 1;
		}
	}
	ret = rdcd_device_open(&d);
	if (ret) {
		rdcd_log(&d, RDCD_LOG_ERR, "device: %s (vram %u bytes?)",
			 rdc_strerror(ret), d.vram_size);
		rdc_server_rec_close(d.rec, NULL);
		return 1;
	}
	ret = 1;
	if (rdcd_chip_open(&d)) {
		rdcd_log(&d, RDCD_LOG_ERR, "no memory for the chip's stack");
		goto out;
	}
	if (o.vcd) {
		/* &d.hw: a power cycle's new chip goes on in the same file */
		int err = rdc_vcd_new(o.vcd, &d.hw, &vcd);

		if (!err)
			err = rdcd_trace_add(&d, rdc_vcd_trace, vcd);
		if (err) {
			rdcd_log(&d, RDCD_LOG_ERR, "--vcd %s: %s", o.vcd,
				 rdc_strerror(err));
			goto out;
		}
	}
	for (unsigned int i = 0; i < o.nsinks; i++) {
		int err = rdcd_web_token(&o.sinks[i], o.token);

		if (!err)
			err = rdc_sink_open(o.sinks[i], &d.sinks[d.nsinks]);
		if (err) {
			rdcd_log(&d, RDCD_LOG_ERR, "sink %s: %s: %s",
				 o.sinks[i], rdc_strerror(err),
				 rdc_last_error_detail(err));
			goto out;
		}
		rdcd_web_log(&d, d.sinks[d.nsinks]);
		d.nsinks++;
	}
	if (o.mode) {
		int p = rdc_preset_by_name(o.mode);
		int err = p < 0 ? RDC_E_INVAL :
				  rdc_mode_set(d.dev, (uint32_t)p,
					       RDC_FMT_XRGB8888, 0);

		if (err) {
			rdcd_log(&d, RDCD_LOG_ERR, "--mode %s: %s", o.mode,
				 rdc_strerror(err));
			goto out;
		}
	}
	if (o.gpio_sim && rdcd_gpiosim_open(&d, o.gpio_sim))
		goto out;
	if (!o.nlisten)
		o.listen[o.nlisten++] = rdcd_systemd_passed() ? "systemd" :
								"unix:";
	for (unsigned int i = 0; i < o.nlisten; i++)
		if (rdcd_add_listener(&d, o.listen[i], o.group))
			goto out;
	rdcd_systemd_done(&d);
	if (o.ready && rdcd_write_ready(&d, o.ready)) {
		rdcd_log(&d, RDCD_LOG_ERR, "--ready-file %s: %s", o.ready,
			 strerror(errno));
		goto out;
	}
	ready = o.ready != NULL;
	rdcd_log(&d, RDCD_LOG_INFO, "%s, vram %u bytes",
		 d.mode == RDC_RUN_STEPPED ? "stepped" :
		 d.mode == RDC_RUN_FAST	   ? "fast" :
					     "paced",
		 d.vram_size);
	rdcd_systemd_notify(&d, "READY=1");
	rdcd_loop(&d);
	rdcd_log(&d, RDCD_LOG_INFO,
		 "%llu frames; for subscribers %llu encodings, %llu queued, "
		 "%llu dropped",
		 (unsigned long long)d.frames,
		 (unsigned long long)d.sub_encodings,
		 (unsigned long long)d.sub_queued,
		 (unsigned long long)d.sub_dropped);
	if (rdcd_stop)
		rdcd_log(&d, RDCD_LOG_INFO, "signal %d: shutting down",
			 (int)rdcd_stop);
	rdcd_systemd_notify(&d, "STOPPING=1");
	ret = 0;
out:
	/* no longer ready: a script waiting for the file waits for a new one */
	if (ready)
		unlink(o.ready);
	rdcd_chip_close(&d); /* a run in progress stops where it is */
	while (d.clients) {
		/* let the last replies go if the sockets take them */
		rdcd_client_flush(&d, d.clients);
		rdcd_client_free(&d, d.clients);
	}
	for (unsigned int i = 0; i < d.nlis; i++) {
		if (d.lis[i].ffs)
			rdcd_ffs_close(d.lis[i].ffs); /* closes fd */
		else if (d.lis[i].udl)
			rdcd_udl_close(d.lis[i].udl); /* closes fd */
		else
			close(d.lis[i].fd);
		if (d.lis[i].path[0]) {
			struct stat st;

			/* not a socket another rdcd has bound there since */
			if (!lstat(d.lis[i].path, &st) &&
			    (uint64_t)st.st_dev == d.lis[i].path_dev &&
			    (uint64_t)st.st_ino == d.lis[i].path_ino)
				unlink(d.lis[i].path);
		}
	}
	rdcd_gpiosim_close(&d);
	if (vcd) {
		rdcd_trace_remove(&d, rdc_vcd_trace, vcd);
		if (rdc_vcd_close(vcd)) {
			rdcd_log(&d, RDCD_LOG_ERR, "--vcd %s: write error",
				 o.vcd);
			ret = 1;
		}
	}
	rdcd_device_close(&d);
	for (unsigned int i = 0; i < d.nsinks; i++)
		rdc_sink_close(d.sinks[i]);
	for (unsigned int i = 0; i < o.nsinks; i++)
		free(o.sinks[i]);
	return ret;
}
