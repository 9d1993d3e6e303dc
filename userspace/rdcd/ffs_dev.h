/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The FunctionFS plumbing that rdcd's USB listeners share (ffs.c: the
 * RDC-1's own personality, udl.c: the DisplayLink one): ep0 and its event
 * thread, the descriptors and strings written at start, the session as a
 * socketpair handed to rdcd's loop through an eventfd, the generation
 * counter that tells the data threads a session is gone, and shutdown.
 *
 * A listener embeds struct ffs_dev, runs its data threads as th[0 ..
 * ndata - 1] (th[ndata] is the ep0 thread) and answers ep0's events in
 * `event`.  Fields from `lock` down are guarded by `lock`.
 */
#ifndef RDCD_FFS_DEV_H
#define RDCD_FFS_DEV_H

#include <linux/usb/functionfs.h>
#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rdcd.h"

/* Threads at most: the data threads and ep0's. */
#define FFS_DEV_MAXT 4u

struct ffs_dev;
typedef void ffs_dev_event_fn(struct ffs_dev *v,
			      const struct usb_functionfs_event *e);

struct ffs_dev {
	const struct rdcd *d; /* for logging */
	const char *kind;     /* "ffs", "udl": the listener's prefix in logs */
	char dir[128];
	int kick;	    /* the signal that wakes a thread out of I/O */
	unsigned int ndata; /* data threads; th[ndata] is ep0's */
	ffs_dev_event_fn *event;
	int ep0;
	int wake;   /* eventfd: the listener's fd in rdcd's loop */
	int stopfd; /* eventfd: wakes the ep0 thread to stop */
	pthread_t th[FFS_DEV_MAXT];
	bool running[FFS_DEV_MAXT]; /* started, not yet joined */

	pthread_mutex_t lock; /* everything below */
	pthread_cond_t cond;
	bool stop, enabled;
	uint32_t gen;	  /* bumped when a session ends */
	uint32_t session; /* sessions started */
	int bfd;	  /* the bridge's end of the session, or -1 */
	int pending;	  /* the daemon's end, not yet accepted, or -1 */
	uint32_t seen[FFS_DEV_MAXT]; /* gen each data thread caught up to */
	bool exited[FFS_DEV_MAXT];   /* that thread has left its loop */
};

/* Fds to -1, the lock, the cond (CLOCK_MONOTONIC), the kick's handler and
 * both eventfds (wake, stopfd: < 0 if they could not be made).  `dir` is
 * the caller's to fill. */
void ffs_dev_init(struct ffs_dev *v, const struct rdcd *d, const char *kind,
		  int kick, unsigned int ndata, ffs_dev_event_fn *event);
/* In each of the listener's threads: only `kick` reaches it. */
void ffs_dev_thread_signals(const struct ffs_dev *v);
/* Lock held: wait up to ms for the cond. */
void ffs_dev_timed_wait(struct ffs_dev *v, long ms);
/* Lock held: until every data thread has let go of older sessions. */
void ffs_dev_wait_threads(struct ffs_dev *v);
/* Lock held: drop the current session, if any (false if there was none);
 * `reset`, if set, clears the listener's per-session state right after
 * the generation moved on, before the data threads run again.  The
 * caller logs the end. */
bool ffs_dev_session_end(struct ffs_dev *v, void (*reset)(struct ffs_dev *v));
/* Lock held: a new session, handed to rdcd's loop through `wake`; false
 * if it could not be made (logged). */
bool ffs_dev_session_start(struct ffs_dev *v);
/* The ep0 thread: events to v->event until stopped. */
void *ffs_dev_ep0_thread(void *arg);
/* Whether ep0's events can be read on after this errno (ffs_dev.c). */
bool ffs_dev_ep0_transient(int err);
/* DIR/name, opened read-write, or -1 (errno set). */
int ffs_dev_open_file(const struct ffs_dev *v, const char *name);
/* Opens DIR/ep0 and writes the descriptors and strings; -1 (logged) on
 * failure.  `hint`: how to mount functionfs there. */
int ffs_dev_open_ep0(struct ffs_dev *v, const void *descs, size_t dlen,
		     const void *strings, size_t slen, const char *hint);
/* Starts fn[0 .. ndata] (the last is ffs_dev_ep0_thread); -1 (logged). */
int ffs_dev_start(struct ffs_dev *v, void *(*const *fn)(void *), void *arg);
/* Stops and joins every thread; `shut`: shut the session's socket down
 * first. */
void ffs_dev_stop(struct ffs_dev *v, bool shut);
/* After ffs_dev_stop and the endpoint files: closes the session's
 * sockets, ep0 (the gadget leaves its UDC) and the eventfds. */
void ffs_dev_fini(struct ffs_dev *v);
/* rdcd's loop: the pending session becomes a client ("<peer> session N"). */
void ffs_dev_accept(struct rdcd *d, struct ffs_dev *v, const char *peer);

#endif
