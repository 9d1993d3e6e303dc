/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_HISTORY_H
#define RDCCTL_HISTORY_H

/*
 * `rdcctl run FILE --history ...`, `rdcctl why X Y FILE` and `rdcctl diff
 * A B` (docs/history.md): returns the exit status, or -1 when argv is none
 * of them (rdcctl's own parser takes it then).
 */
int rdcctl_history_main(int argc, char **argv);
/* The usage lines of these commands. */
extern const char rdcctl_history_usage[];

#endif
