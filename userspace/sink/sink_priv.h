/* SPDX-License-Identifier: LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * Frame sink internals: the table of operations behind rdc_sink, and the
 * system-call table of the v4l2 sink (so tests can put a fake device
 * behind it).
 */
#ifndef RDC_SINK_PRIV_H
#define RDC_SINK_PRIV_H

#include <stdbool.h>
#include <sys/types.h>

#include "rdc_sink.h"

struct rdc_sink_ops {
	const char *kind;
	/* args: the spec after "kind:"; set s->priv. */
	int (*open)(rdc_sink *s, const char *args);
	int (*frame)(rdc_sink *s, const struct rdc_frame *f);
	/* Optional (NULL: RDC_E_NOSYS / nothing to do). */
	int (*snapshot)(rdc_sink *s);
	int (*poll)(rdc_sink *s);
	int (*status)(rdc_sink *s, const struct rdc_sink_status *st);
	int (*url)(const rdc_sink *s, char *buf, size_t len);
	void (*close)(rdc_sink *s);
};

struct rdc_sink {
	const struct rdc_sink_ops *ops;
	void *priv;
	struct rdc_sink_stats st;
};

extern const struct rdc_sink_ops rdc_sink_v4l2_ops;
extern const struct rdc_sink_ops rdc_sink_png_ops;
extern const struct rdc_sink_ops rdc_sink_vnc_ops;
extern const struct rdc_sink_ops rdc_sink_web_ops;

/*
 * Split "first,key=value,..." in place: *first gets the part before the
 * first comma; rdc_sink_opt_next walks the options.  Returns 1 with
 * key and val set, 0 at the end, RDC_E_URI for an option without '='.
 */
int rdc_sink_opt_next(char **cursor, char **key, char **val);
/* Parse a decimal number in [min, max]; RDC_E_URI otherwise. */
int rdc_sink_opt_u32(const char *val, uint32_t min, uint32_t max,
		     uint32_t *out);

/* The v4l2 sink's view of the kernel. */
struct rdc_v4l2_io {
	int (*open)(const char *path, int flags);
	int (*ioctl)(int fd, unsigned long req, void *arg);
	ssize_t (*write)(int fd, const void *buf, size_t len);
	int (*close)(int fd);
};

/*
 * Open a v4l2 sink with its system calls routed through io (copied).
 * Frames handed to a sink whose device is away retry the open every
 * RDC_V4L2_REOPEN_EVERY frames.
 */
int rdc_sink_v4l2_open_io(const char *args, const struct rdc_v4l2_io *io,
			  rdc_sink **out);
#define RDC_V4L2_REOPEN_EVERY 30

#endif /* RDC_SINK_PRIV_H */
