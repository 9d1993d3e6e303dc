/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * TAP output for the VM test programs (one per program: the counters are
 * the program's own).  tap_done() prints the plan and gives the exit code.
 */
#ifndef RDC_VM_TAP_H
#define RDC_VM_TAP_H

#include <stdarg.h>
#include <stdio.h>

static unsigned int tap_n, tap_failed;

static inline void tap(int ok, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

static inline void tap(int ok, const char *fmt, ...)
{
	va_list ap;

	printf("%s %u - ", ok ? "ok" : "not ok", ++tap_n);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n");
	if (!ok)
		tap_failed++;
}

static inline void tap_skip(const char *why)
{
	printf("ok %u - # SKIP %s\n", ++tap_n, why);
}

static inline int tap_done(void)
{
	printf("1..%u\n", tap_n);
	return tap_failed ? 1 : 0;
}

#endif /* RDC_VM_TAP_H */
