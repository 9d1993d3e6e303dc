/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_STREAM_H
#define RDCCTL_STREAM_H

#include <stdbool.h>
#include <stdint.h>

#include "rdc.h"
#include "rdc_sink.h"

/*
 * `rdcctl [--uri URI] stream ...`: returns the exit status, or -1 when
 * argv is not a stream command (rdcctl's own parser takes it then).
 */
int rdcctl_stream_main(int argc, char **argv);
/*
 * The stream command's loop, as it runs after its options: `frames`
 * frames (0: until SIGINT or SIGTERM) from dev to the sinks, paced to
 * the device's refresh unless `fast`; 0 or a negative RDC_E_* (reported
 * on stderr).  stream-bench measures this.
 */
int rdcctl_stream_run(rdc_dev *dev, uint64_t frames, bool fast,
		      rdc_sink **sinks, int nsinks);
/* The usage lines of the stream command. */
extern const char rdcctl_stream_usage[];

#endif
