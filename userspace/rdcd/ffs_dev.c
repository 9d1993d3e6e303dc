// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * FunctionFS plumbing shared by rdcd's USB listeners (ffs_dev.h).
 *
 * FunctionFS endpoint files do not poll and block in read and write, so
 * a listener's threads are woken out of their calls by a signal (`kick`)
 * whose handler does nothing: only the interrupted call matters.
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "ffs_dev.h"

static void ffs_dev_on_kick(int sig)
{
	(void)sig;
}

void ffs_dev_init(struct ffs_dev *v, const struct rdcd *d, const char *kind,
		  int kick, unsigned int ndata, ffs_dev_event_fn *event)
{
	struct sigaction sa = { .sa_handler = ffs_dev_on_kick };
	pthread_condattr_t ca;

	v->d = d;
	v->kind = kind;
	v->kick = kick;
	v->ndata = ndata;
	v->event = event;
	v->ep0 = v->wake = v->stopfd = v->bfd = v->pending = -1;
	pthread_mutex_init(&v->lock, NULL);
	pthread_condattr_init(&ca);
	pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
	pthread_cond_init(&v->cond, &ca);
	pthread_condattr_destroy(&ca);
	/* no SA_RESTART: the kick must interrupt blocking I/O */
	sigaction(kick, &sa, NULL);
	v->wake = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	v->stopfd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
}

void ffs_dev_thread_signals(const struct ffs_dev *v)
{
	sigset_t set;

	sigfillset(&set);
	sigdelset(&set, v->kick);
	pthread_sigmask(SIG_SETMASK, &set, NULL);
}

void ffs_dev_timed_wait(struct ffs_dev *v, long ms)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	ts.tv_nsec += ms * 1000000L;
	if (ts.tv_nsec >= 1000000000L) {
		ts.tv_sec++;
		ts.tv_nsec -= 1000000000L;
	}
	pthread_cond_timedwait(&v->cond, &v->lock, &ts);
}

void ffs_dev_wait_threads(struct ffs_dev *v)
{
	for (unsigned int tries = 0;; tries++) {
		bool all = true;

		for (unsigned int t = 0; t < v->ndata; t++) {
			if (v->running[t] && !v->exited[t] &&
			    v->seen[t] != v->gen) {
				all = false;
				pthread_kill(v->th[t], v->kick);
			}
		}
		if (all)
			return;
		if (tries == 200)
			rdcd_log(v->d, RDCD_LOG_WARN,
				 "%s:%s: a bridge thread is slow to let go",
				 v->kind, v->dir);
		ffs_dev_timed_wait(v, 10);
	}
}

bool ffs_dev_session_end(struct ffs_dev *v, void (*reset)(struct ffs_dev *v))
{
	int old = v->bfd;

	if (old < 0 && v->pending < 0)
		return false;
	v->gen++;
	v->bfd = -1;
	if (reset)
		reset(v);
	if (v->pending >= 0) {
		close(v->pending); /* never accepted */
		v->pending = -1;
	}
	if (old >= 0)
		shutdown(old, SHUT_RDWR); /* serve.c sees the client leave */
	pthread_cond_broadcast(&v->cond);
	ffs_dev_wait_threads(v);
	if (old >= 0)
		close(old);
	return true;
}

bool ffs_dev_session_start(struct ffs_dev *v)
{
	uint64_t one = 1;
	int sv[2];

	if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv)) {
		rdcd_log(v->d, RDCD_LOG_ERR, "%s:%s: socketpair: %s", v->kind,
			 v->dir, strerror(errno));
		return false;
	}
	fcntl(sv[0], F_SETFL, O_NONBLOCK); /* the daemon's end */
	v->pending = sv[0];
	v->bfd = sv[1];
	v->session++;
	pthread_cond_broadcast(&v->cond);
	if (write(v->wake, &one, sizeof(one)) < 0)
		rdcd_log(v->d, RDCD_LOG_ERR, "%s:%s: eventfd: %s", v->kind,
			 v->dir, strerror(errno));
	rdcd_log(v->d, RDCD_LOG_INFO, "%s:%s: session %u", v->kind, v->dir,
		 v->session);
	return true;
}

/*
 * An error reading ep0's events that the next event recovers from:
 * EINTR, EAGAIN; EIDRM, a pending setup the host cancelled; EL2HLT, a
 * setup still pending when its answer failed (the link went down under
 * it, ESHUTDOWN), which FunctionFS then stalls on the next read;
 * ESHUTDOWN, the link down.  Anything else ends the thread.
 */
bool ffs_dev_ep0_transient(int err)
{
	switch (err) {
	case EINTR:
	case EAGAIN:
	case EIDRM:
	case EL2HLT:
	case ESHUTDOWN:
		return true;
	default:
		return false;
	}
}

void *ffs_dev_ep0_thread(void *arg)
{
	struct ffs_dev *v = arg;

	ffs_dev_thread_signals(v);
	for (;;) {
		struct pollfd p[2] = { { .fd = v->ep0, .events = POLLIN },
				       { .fd = v->stopfd, .events = POLLIN } };
		struct usb_functionfs_event ev[4];
		ssize_t n;

		if (poll(p, 2, -1) < 0 && errno != EINTR)
			break;
		if (p[1].revents)
			break;
		if (!(p[0].revents & POLLIN))
			continue;
		n = read(v->ep0, ev, sizeof(ev));
		if (n < 0) {
			if (ffs_dev_ep0_transient(errno)) {
				/* the link went down under an answer: the
				 * next bind starts clean (a short pause
				 * keeps a storm of them cheap)
				 */
				if (errno != EINTR && errno != EAGAIN)
					rdcd_log(v->d, RDCD_LOG_DEBUG,
						 "%s:%s: ep0: %s", v->kind,
						 v->dir, strerror(errno));
				if (errno == ESHUTDOWN)
					usleep(10000);
				continue;
			}
			rdcd_log(v->d, RDCD_LOG_ERR, "%s:%s: ep0: %s", v->kind,
				 v->dir, strerror(errno));
			break;
		}
		for (size_t i = 0; i < (size_t)n / sizeof(ev[0]); i++)
			v->event(v, &ev[i]);
	}
	return NULL;
}

int ffs_dev_open_file(const struct ffs_dev *v, const char *name)
{
	char path[sizeof(v->dir) + 8];

	snprintf(path, sizeof(path), "%s/%s", v->dir, name);
	return open(path, O_RDWR | O_CLOEXEC);
}

int ffs_dev_open_ep0(struct ffs_dev *v, const void *descs, size_t dlen,
		     const void *strings, size_t slen, const char *hint)
{
	v->ep0 = ffs_dev_open_file(v, "ep0");
	if (v->ep0 < 0) {
		rdcd_log(v->d, RDCD_LOG_ERR,
			 "%s:%s: ep0: %s (is functionfs mounted there? %s)",
			 v->kind, v->dir, strerror(errno), hint);
		return -1;
	}
	if (write(v->ep0, descs, dlen) != (ssize_t)dlen ||
	    write(v->ep0, strings, slen) != (ssize_t)slen) {
		rdcd_log(v->d, RDCD_LOG_ERR,
			 "%s:%s: writing descriptors: %s (in use by another "
			 "program?)",
			 v->kind, v->dir, strerror(errno));
		return -1;
	}
	return 0;
}

int ffs_dev_start(struct ffs_dev *v, void *(*const *fn)(void *), void *arg)
{
	for (unsigned int t = 0; t <= v->ndata; t++) {
		int err = pthread_create(&v->th[t], NULL, fn[t], arg);

		if (err) {
			rdcd_log(v->d, RDCD_LOG_ERR, "%s:%s: thread: %s",
				 v->kind, v->dir, strerror(err));
			return -1;
		}
		v->running[t] = true;
	}
	return 0;
}

void ffs_dev_stop(struct ffs_dev *v, bool shut)
{
	uint64_t one = 1;

	pthread_mutex_lock(&v->lock);
	v->stop = true;
	pthread_cond_broadcast(&v->cond);
	pthread_mutex_unlock(&v->lock);
	if (v->running[v->ndata]) {
		if (write(v->stopfd, &one, sizeof(one)) < 0)
			rdcd_log(v->d, RDCD_LOG_WARN, "%s:%s: eventfd: %s",
				 v->kind, v->dir, strerror(errno));
		pthread_kill(v->th[v->ndata], v->kick); /* if in ep0 I/O */
		pthread_join(v->th[v->ndata], NULL);
		v->running[v->ndata] = false;
	}
	/* the ep0 thread is gone: nothing starts a session now */
	pthread_mutex_lock(&v->lock);
	if (shut && v->bfd >= 0)
		shutdown(v->bfd, SHUT_RDWR);
	v->gen++; /* wakes every data thread out of its call */
	pthread_cond_broadcast(&v->cond);
	ffs_dev_wait_threads(v);
	pthread_mutex_unlock(&v->lock);
	for (unsigned int t = 0; t < v->ndata; t++)
		if (v->running[t]) {
			pthread_join(v->th[t], NULL);
			v->running[t] = false;
		}
}

void ffs_dev_fini(struct ffs_dev *v)
{
	if (v->pending >= 0)
		close(v->pending);
	if (v->bfd >= 0)
		close(v->bfd);
	/* closing ep0 withdraws the function: the gadget leaves its UDC */
	if (v->ep0 >= 0)
		close(v->ep0);
	if (v->wake >= 0)
		close(v->wake);
	if (v->stopfd >= 0)
		close(v->stopfd);
	pthread_cond_destroy(&v->cond);
	pthread_mutex_destroy(&v->lock);
}

void ffs_dev_accept(struct rdcd *d, struct ffs_dev *v, const char *peer)
{
	char name[64];
	uint64_t n;
	uint32_t s;
	int fd;

	if (read(v->wake, &n, sizeof(n)) < 0 && errno != EAGAIN)
		rdcd_log(d, RDCD_LOG_WARN, "%s:%s: eventfd: %s", v->kind,
			 v->dir, strerror(errno));
	pthread_mutex_lock(&v->lock);
	fd = v->pending;
	v->pending = -1;
	s = v->session;
	pthread_mutex_unlock(&v->lock);
	if (fd < 0)
		return; /* it ended before we came to it */
	/* admitted as any connection: the HELLO decides (serve.c) */
	snprintf(name, sizeof(name), "%s session %u", peer, s);
	if (!rdcd_client_new(d, fd, false, name)) {
		rdcd_log(d, RDCD_LOG_ERR, "out of memory");
		close(fd);
	}
}
