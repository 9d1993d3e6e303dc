/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_STREAM_H
#define RDCCTL_STREAM_H

/*
 * `rdcctl [--uri URI] stream ...`: returns the exit status, or -1 when
 * argv is not a stream command (rdcctl's own parser takes it then).
 */
int rdcctl_stream_main(int argc, char **argv);
/* The usage lines of the stream command. */
extern const char rdcctl_stream_usage[];

#endif
