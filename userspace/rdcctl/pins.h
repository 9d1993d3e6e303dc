/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_PINS_H
#define RDCCTL_PINS_H

/*
 * `rdcctl [--uri URI] pins ...`: returns the exit status, or -1 when argv
 * is not a pins command (rdcctl's own parser takes it then).
 */
int rdcctl_pins_main(int argc, char **argv);
/* The usage lines of the pins command. */
extern const char rdcctl_pins_usage[];

#endif
