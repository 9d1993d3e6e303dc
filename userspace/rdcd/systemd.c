// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Listening sockets passed by systemd (socket activation) and readiness
 * notification, by their documented protocols rather than libsystemd:
 * sd_listen_fds(3) (LISTEN_PID, LISTEN_FDS, LISTEN_FDNAMES; the sockets
 * are the descriptors from 3 on) and sd_notify(3) (a datagram to
 * NOTIFY_SOCKET).  A passed descriptor is distrusted like any input: it
 * must be a listening stream socket, UNIX or TCP, or rdcd refuses to
 * start and names it.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rdcd.h"

#define SD_FDS_START 3
/* systemd's own limit on a FileDescriptorName= */
#define SD_NAME_MAX 255

static struct rdcd_sd {
	bool parsed;
	unsigned int n; /* descriptors passed to this process */
	bool used[RDCD_MAX_LISTEN];
	char names[RDCD_MAX_LISTEN][SD_NAME_MAX + 1];
	/* why none were taken, for an explicit --listen systemd */
	char why[160];
	bool bad; /* the variables are malformed: an error, not "none" */
} rdcd_sd;

static int sd_parse_uint(const char *s, unsigned long *out)
{
	char *end;

	if (!s || *s < '0' || *s > '9')
		return -1;
	errno = 0;
	*out = strtoul(s, &end, 10);
	return errno || *end ? -1 : 0;
}

/* Read the variables once, then take them out of the environment. */
static void sd_parse(void)
{
	struct rdcd_sd *s = &rdcd_sd;
	const char *pid = getenv("LISTEN_PID");
	const char *fds = getenv("LISTEN_FDS");
	const char *names = getenv("LISTEN_FDNAMES");
	unsigned long p, n;

	if (s->parsed)
		return;
	s->parsed = true;
	if (!pid || !fds) {
		snprintf(s->why, sizeof(s->why),
			 "LISTEN_PID and LISTEN_FDS are not set");
		goto out;
	}
	if (sd_parse_uint(pid, &p) || p != (unsigned long)getpid()) {
		snprintf(s->why, sizeof(s->why),
			 "LISTEN_PID=%.20s is not this process (%ld)", pid,
			 (long)getpid());
		goto out;
	}
	if (sd_parse_uint(fds, &n) || n > RDCD_MAX_LISTEN) {
		snprintf(s->why, sizeof(s->why),
			 "LISTEN_FDS=%.20s: want 0 to %d sockets", fds,
			 RDCD_MAX_LISTEN);
		s->bad = true;
		goto out;
	}
	if (!n) {
		snprintf(s->why, sizeof(s->why), "LISTEN_FDS=0");
		goto out;
	}
	for (unsigned int i = 0; i < n; i++)
		strcpy(s->names[i], "unknown"); /* systemd's name for none */
	if (names) {
		const char *p0 = names;
		unsigned int i = 0;

		for (;;) {
			size_t len = strcspn(p0, ":");

			if (i == n || len > SD_NAME_MAX) {
				snprintf(s->why, sizeof(s->why),
					 "LISTEN_FDNAMES does not name the %lu "
					 "sockets of LISTEN_FDS",
					 n);
				s->bad = true;
				goto out;
			}
			memcpy(s->names[i], p0, len);
			s->names[i][len] = 0;
			i++;
			if (!p0[len])
				break;
			p0 += len + 1;
		}
		if (i != n) {
			snprintf(s->why, sizeof(s->why),
				 "LISTEN_FDNAMES names %u sockets, LISTEN_FDS "
				 "passes %lu",
				 i, n);
			s->bad = true;
			goto out;
		}
	}
	s->n = (unsigned int)n;
out:
	unsetenv("LISTEN_PID");
	unsetenv("LISTEN_FDS");
	unsetenv("LISTEN_FDNAMES");
}

bool rdcd_systemd_passed(void)
{
	sd_parse();
	return rdcd_sd.n > 0 || rdcd_sd.bad;
}

/* What is wrong with a passed descriptor as a listener, or NULL. */
static const char *sd_check(int fd, struct sockaddr_storage *ss, socklen_t *sl)
{
	socklen_t il = sizeof(int);
	int type = 0, acc = 0;
	struct stat st;

	if (fstat(fd, &st))
		return "not open";
	if (!S_ISSOCK(st.st_mode))
		return "not a socket";
	if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &il) ||
	    type != SOCK_STREAM)
		return "not a stream socket (want ListenStream=)";
	il = sizeof(int);
	if (getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &acc, &il) || !acc)
		return "not listening (want ListenStream= and Accept=no)";
	if (getsockname(fd, (struct sockaddr *)ss, sl))
		return "no address";
	if (ss->ss_family != AF_UNIX && ss->ss_family != AF_INET &&
	    ss->ss_family != AF_INET6)
		return "not a UNIX or TCP socket";
	return NULL;
}

/* A passed descriptor as a listener, or -1 with the reason logged. */
static int sd_take(struct rdcd *d, struct rdcd_listener *l, int fd,
		   const char *name)
{
	struct sockaddr_storage ss;
	socklen_t sl = sizeof(ss);
	char host[NI_MAXHOST], port[NI_MAXSERV];
	const char *why = sd_check(fd, &ss, &sl);
	int flags;

	if (why) {
		rdcd_log(d, RDCD_LOG_ERR, "systemd: fd %d (%s): %s", fd, name,
			 why);
		return -1;
	}
	memset(l, 0, sizeof(*l));
	l->fd = fd;
	if (ss.ss_family == AF_UNIX) {
		const struct sockaddr_un *un = (const void *)&ss;
		size_t len =
			sl > offsetof(struct sockaddr_un, sun_path) ?
				sl - offsetof(struct sockaddr_un, sun_path) :
				0;
		char path[sizeof(un->sun_path) + 1];

		if (len > sizeof(un->sun_path))
			len = sizeof(un->sun_path);
		memcpy(path, un->sun_path, len);
		path[len] = 0;
		if (len && !path[0])
			path[0] = '@'; /* abstract, as systemd writes it */
		/* l->path stays empty: the file is the socket unit's */
		snprintf(l->uri, sizeof(l->uri), "unix:%s", path);
	} else {
		l->tcp = true;
		l->need_token = !rdc_tcp_is_loopback(&ss);
		if (l->need_token && !d->have_token) {
			rdcd_log(d, RDCD_LOG_ERR,
				 "systemd: fd %d (%s) is not loopback: "
				 "--token FILE is required",
				 fd, name);
			return -1;
		}
		if (getnameinfo((struct sockaddr *)&ss, sl, host, sizeof(host),
				port, sizeof(port),
				NI_NUMERICHOST | NI_NUMERICSERV)) {
			strcpy(host, "?");
			strcpy(port, "?");
		}
		snprintf(l->uri, sizeof(l->uri),
			 ss.ss_family == AF_INET6 ? "tcp:[%s]:%s" : "tcp:%s:%s",
			 host, port);
	}
	/* the loop accepts until EAGAIN; nothing of ours survives an exec */
	flags = fcntl(fd, F_GETFL);
	if (flags < 0 || fcntl(fd, F_SETFL, flags | O_NONBLOCK) ||
	    fcntl(fd, F_SETFD, FD_CLOEXEC)) {
		rdcd_log(d, RDCD_LOG_ERR, "systemd: fd %d (%s): %s", fd, name,
			 strerror(errno));
		return -1;
	}
	return 0;
}

int rdcd_systemd_add(struct rdcd *d, const char *name)
{
	struct rdcd_sd *s = &rdcd_sd;
	unsigned int taken = 0;

	sd_parse();
	if (s->bad || !s->n) {
		rdcd_log(d, RDCD_LOG_ERR,
			 "--listen systemd: no socket passed by systemd: %s",
			 s->why);
		return -1;
	}
	for (unsigned int i = 0; i < s->n; i++) {
		int fd = SD_FDS_START + (int)i;

		if (s->used[i] || (*name && strcmp(name, s->names[i])))
			continue;
		if (d->nlis == RDCD_MAX_LISTEN) {
			rdcd_log(d, RDCD_LOG_ERR, "too many listeners");
			return -1;
		}
		if (sd_take(d, &d->lis[d->nlis], fd, s->names[i]))
			return -1;
		s->used[i] = true;
		taken++;
		rdcd_log(d, RDCD_LOG_INFO,
			 "listening on %s (systemd fd %d, %s)%s",
			 d->lis[d->nlis].uri, fd, s->names[i],
			 d->lis[d->nlis].need_token ? " (token required)" : "");
		d->nlis++;
	}
	if (!taken) {
		char have[256] = "";
		size_t off = 0;

		for (unsigned int i = 0; i < s->n && off < sizeof(have); i++)
			off += (size_t)snprintf(have + off, sizeof(have) - off,
						"%s%s", i ? ", " : "",
						s->names[i]);
		if (*name)
			rdcd_log(d, RDCD_LOG_ERR,
				 "--listen systemd:%s: no such socket among "
				 "those systemd passed (%s)",
				 name, have);
		else
			rdcd_log(d, RDCD_LOG_ERR,
				 "--listen systemd: every socket systemd "
				 "passed (%s) is taken already",
				 have);
		return -1;
	}
	return 0;
}

void rdcd_systemd_done(struct rdcd *d)
{
	struct rdcd_sd *s = &rdcd_sd;

	sd_parse();
	for (unsigned int i = 0; i < s->n; i++) {
		if (s->used[i])
			continue;
		rdcd_log(d, RDCD_LOG_WARN,
			 "systemd passed fd %d (%s), which no --listen takes: "
			 "closing it",
			 SD_FDS_START + (int)i, s->names[i]);
		close(SD_FDS_START + (int)i);
		s->used[i] = true;
	}
}

void rdcd_systemd_notify(const struct rdcd *d, const char *state)
{
	const char *path = getenv("NOTIFY_SOCKET");
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	size_t len = path ? strlen(path) : 0;
	int fd;

	if (!len)
		return;
	if ((path[0] != '/' && path[0] != '@') || len > sizeof(sa.sun_path)) {
		rdcd_log(d, RDCD_LOG_WARN,
			 "NOTIFY_SOCKET=%.40s: not a socket path; not telling "
			 "systemd %s",
			 path, state);
		return;
	}
	memcpy(sa.sun_path, path, len);
	if (path[0] == '@')
		sa.sun_path[0] = 0; /* abstract namespace */
	fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (fd < 0 ||
	    sendto(fd, state, strlen(state), MSG_NOSIGNAL,
		   (struct sockaddr *)&sa,
		   (socklen_t)(offsetof(struct sockaddr_un, sun_path) + len)) <
		    0)
		rdcd_log(d, RDCD_LOG_WARN, "NOTIFY_SOCKET %s: %s: %s", path,
			 state, strerror(errno));
	if (fd >= 0)
		close(fd);
}
