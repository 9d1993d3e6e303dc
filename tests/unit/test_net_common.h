/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Helpers for the tests that talk to a real rdcd: start the daemon built
 * next to the test program ($(O)/san/rdcd) on a UNIX socket in a fresh
 * temporary directory and a kernel-chosen loopback TCP port, stop it and
 * check it exited cleanly (the sanitizers turn leaks and memory errors
 * into a failing exit status), and speak the raw protocol.
 *
 * Everything here is static: the header is included by test programs
 * only, never linked into the others.
 */
#ifndef TEST_NET_COMMON_H
#define TEST_NET_COMMON_H

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "rdc_proto.h"

#define NETD_START_MS 20000 /* ASan start-up on a loaded host */
#define NETD_STOP_MS  20000
/* how long a reply may take: a stepped minute of waits under ASan on a
 * loaded host; only a failing test waits it out */
#define NETD_IO_MS 60000

struct netd {
	pid_t pid;
	char dir[64];
	char sock[128];
	char unix_uri[160];
	char tcp_uri[160];
	char ready[128];
	char log[128];
};

static inline void netd_sleep_ms(int ms)
{
	struct timespec ts = { ms / 1000, (long)(ms % 1000) * 1000000L };

	nanosleep(&ts, NULL);
}

/* $(O)/san/rdcd, found from this program's own path $(O)/san/tests/x. */
static inline int netd_daemon_path(char *buf, size_t cap)
{
	char exe[4096];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
	char *slash;

	if (n <= 0)
		return -1;
	exe[n] = 0;
	slash = strrchr(exe, '/');
	if (!slash)
		return -1;
	*slash = 0;
	if ((size_t)snprintf(buf, cap, "%s/../rdcd", exe) >= cap)
		return -1;
	return access(buf, X_OK);
}

/*
 * Start rdcd with `args` (NULL-terminated, may be NULL) plus a UNIX and
 * a TCP listener.  0, or -1 if it did not come up.
 */
static inline int netd_start(struct netd *d, const char *const *args)
{
	char daemon[4200], lis_unix[200];
	const char *argv[40];
	int n = 0, fd;

	memset(d, 0, sizeof(*d));
	if (netd_daemon_path(daemon, sizeof(daemon)))
		return -1;
	snprintf(d->dir, sizeof(d->dir), "/tmp/rdcd-test-XXXXXX");
	if (!mkdtemp(d->dir))
		return -1;
	snprintf(d->sock, sizeof(d->sock), "%s/rdc.sock", d->dir);
	snprintf(d->ready, sizeof(d->ready), "%s/ready", d->dir);
	snprintf(d->log, sizeof(d->log), "%s/log", d->dir);
	snprintf(lis_unix, sizeof(lis_unix), "unix:%s", d->sock);
	argv[n++] = daemon;
	argv[n++] = "--listen";
	argv[n++] = lis_unix;
	argv[n++] = "--listen";
	argv[n++] = "tcp:127.0.0.1:0";
	argv[n++] = "--ready-file";
	argv[n++] = d->ready;
	for (; args && *args && n < 38; args++)
		argv[n++] = *args;
	argv[n] = NULL;
	d->pid = fork();
	if (d->pid < 0)
		return -1;
	if (d->pid == 0) {
		/* a test that dies (failed assertion) takes its daemon along */
		prctl(PR_SET_PDEATHSIG, SIGKILL);
		if (getppid() == 1)
			_exit(127);
		/* nothing of the test's: a pipe held open stalls its reader */
		fd = open(d->log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
		if (fd >= 0) {
			dup2(fd, 1);
			dup2(fd, 2);
		}
		execv(daemon, (char *const *)argv);
		_exit(127);
	}
	for (int waited = 0; waited < NETD_START_MS; waited += 10) {
		FILE *f = fopen(d->ready, "r");
		int st;

		if (f) {
			char line[150];

			while (fgets(line, sizeof(line), f)) {
				line[strcspn(line, "\n")] = 0;
				if (!strncmp(line, "unix:", 5))
					snprintf(d->unix_uri,
						 sizeof(d->unix_uri), "%s",
						 line);
				else if (!strncmp(line, "tcp:", 4))
					snprintf(d->tcp_uri, sizeof(d->tcp_uri),
						 "%s", line);
			}
			fclose(f);
			return d->unix_uri[0] && d->tcp_uri[0] ? 0 : -1;
		}
		if (waitpid(d->pid, &st, WNOHANG) == d->pid) {
			d->pid = 0;
			return -1;
		}
		netd_sleep_ms(10);
	}
	return -1;
}

/* Print the daemon's log (for a failing test's output). */
static inline void netd_dump_log(const struct netd *d)
{
	FILE *f = fopen(d->log, "r");
	char line[512];

	if (!f)
		return;
	while (fgets(line, sizeof(line), f))
		fprintf(stderr, "  | %s", line);
	fclose(f);
}

/* Does the log contain `s`? */
static inline int netd_log_has(const struct netd *d, const char *s)
{
	FILE *f = fopen(d->log, "r");
	char line[512];
	int found = 0;

	if (!f)
		return 0;
	while (!found && fgets(line, sizeof(line), f))
		found = strstr(line, s) != NULL;
	fclose(f);
	return found;
}

/*
 * SIGTERM, wait; returns the exit status (0 = clean: no sanitizer
 * report, socket removed), or -1 on a timeout or a leftover socket.
 */
static inline int netd_stop(struct netd *d)
{
	int st = -1, ret = -1;
	char cmd[200];

	if (d->pid <= 0)
		goto clean;
	kill(d->pid, SIGTERM);
	for (int waited = 0; waited < NETD_STOP_MS; waited += 10) {
		if (waitpid(d->pid, &st, WNOHANG) == d->pid) {
			ret = WIFEXITED(st) ? WEXITSTATUS(st) : 128;
			break;
		}
		netd_sleep_ms(10);
	}
	if (ret == -1) {
		kill(d->pid, SIGKILL);
		waitpid(d->pid, &st, 0);
	}
	d->pid = 0;
	if (ret != 0 || access(d->sock, F_OK) == 0) {
		netd_dump_log(d);
		if (ret == 0)
			ret = -1;
	}
clean:
	/* only what netd_start made */
	snprintf(cmd, sizeof(cmd), "%s/ready", d->dir);
	unlink(cmd);
	unlink(d->log);
	unlink(d->sock);
	rmdir(d->dir);
	return ret;
}

/* ---- Raw protocol -------------------------------------------------------- */

static inline int netd_connect(const char *path)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);

	if (fd < 0 || strlen(path) >= sizeof(sa.sun_path)) {
		if (fd >= 0)
			close(fd);
		return -1;
	}
	memcpy(sa.sun_path, path, strlen(path) + 1);
	if (connect(fd, (struct sockaddr *)&sa, sizeof(sa))) {
		close(fd);
		return -1;
	}
	return fd;
}

static inline int netd_write(int fd, const void *p, size_t n)
{
	const uint8_t *b = p;

	while (n) {
		ssize_t k = send(fd, b, n, MSG_NOSIGNAL);

		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0)
			return -1;
		b += k;
		n -= (size_t)k;
	}
	return 0;
}

static inline int netd_send(int fd, uint16_t type, uint32_t seq, const void *pl,
			    uint32_t len)
{
	uint8_t h[RDC_PROTO_HDR_SIZE];
	struct rdc_proto_hdr hdr = { .len = len, .type = type, .seq = seq };

	rdc_proto_hdr_encode(h, &hdr);
	if (netd_write(fd, h, sizeof(h)))
		return -1;
	return len ? netd_write(fd, pl, len) : 0;
}

static inline int netd_read(int fd, void *p, size_t n)
{
	uint8_t *b = p;

	while (n) {
		struct pollfd pfd = { .fd = fd, .events = POLLIN };
		ssize_t k;

		if (poll(&pfd, 1, NETD_IO_MS) <= 0)
			return -1;
		k = recv(fd, b, n, 0);
		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0)
			return -1;
		b += k;
		n -= (size_t)k;
	}
	return 0;
}

/*
 * The next message that is not an event: header and up to `cap` payload
 * bytes (the rest is skipped).  0, or -1 on EOF/timeout.
 */
static inline int netd_reply(int fd, struct rdc_proto_hdr *h, void *buf,
			     size_t cap)
{
	for (;;) {
		uint8_t hb[RDC_PROTO_HDR_SIZE], skip[4096];
		uint32_t left;

		if (netd_read(fd, hb, sizeof(hb)))
			return -1;
		rdc_proto_hdr_decode(hb, h);
		left = h->len;
		if (!(h->flags & RDC_MSGF_EVENT) && buf) {
			size_t k = left < cap ? left : cap;

			if (netd_read(fd, buf, k))
				return -1;
			left -= (uint32_t)k;
		}
		while (left) {
			size_t k = left < sizeof(skip) ? left : sizeof(skip);

			if (netd_read(fd, skip, k))
				return -1;
			left -= (uint32_t)k;
		}
		if (!(h->flags & RDC_MSGF_EVENT))
			return 0;
	}
}

/* HELLO; returns the reply status, or -1. */
static inline int netd_hello(int fd, uint32_t flags, const char *token,
			     struct rdc_proto_hello_reply *r)
{
	uint8_t msg[RDC_PROTO_HELLO_FIXED + RDC_PROTO_MAX_TOKEN], rb[64];
	struct rdc_proto_hello h = {
		.magic = RDC_PROTO_MAGIC,
		.version = RDC_PROTO_VERSION,
		.caps = RDC_CAP_ALL,
		.flags = flags,
		.token_len = token ? (uint32_t)strlen(token) : 0,
		.token = (const uint8_t *)token,
	};
	struct rdc_proto_hdr hdr;
	size_t n = rdc_proto_hello_encode(msg, sizeof(msg), &h);

	if (netd_send(fd, RDC_MSG_HELLO, 1, msg, (uint32_t)n) ||
	    netd_reply(fd, &hdr, rb, sizeof(rb)))
		return -1;
	if (r && hdr.status == RDC_ST_OK &&
	    rdc_proto_hello_reply_decode(rb, hdr.len, r))
		return -1;
	return (int)hdr.status;
}

/* One request, its reply status (or -1); payload to out. */
static inline int netd_call(int fd, uint16_t type, uint32_t seq, const void *pl,
			    uint32_t len, void *out, size_t cap)
{
	struct rdc_proto_hdr h;

	if (netd_send(fd, type, seq, pl, len) || netd_reply(fd, &h, out, cap))
		return -1;
	if (h.seq != seq || h.type != type || !(h.flags & RDC_MSGF_REPLY))
		return -1;
	return (int)h.status;
}

/* Has the peer closed the connection (EOF within the I/O timeout)? */
static inline int netd_closed(int fd)
{
	uint8_t b[256];

	for (;;) {
		struct pollfd pfd = { .fd = fd, .events = POLLIN };
		ssize_t k;

		if (poll(&pfd, 1, NETD_IO_MS) <= 0)
			return 0;
		k = recv(fd, b, sizeof(b), 0);
		if (k == 0 || (k < 0 && errno != EINTR))
			return 1;
	}
}

#endif /* TEST_NET_COMMON_H */
