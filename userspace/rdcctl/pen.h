/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_PEN_H
#define RDCCTL_PEN_H

/*
 * `rdcctl [--uri URI] pen ...`: returns the exit status, or -1 when argv
 * is not a pen command (rdcctl's own parser takes it then).
 */
int rdcctl_pen_main(int argc, char **argv);
/* The usage lines of the pen command. */
extern const char rdcctl_pen_usage[];

#endif
