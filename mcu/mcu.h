/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * What the firmware's main needs from its board: semihosting output and
 * exit, and the stack's high-water mark (startup.c).
 */
#ifndef RDC_MCU_H
#define RDC_MCU_H

#include <stdint.h>

/* Write a NUL-terminated string to the host's console. */
void mcu_puts(const char *s);
/* Stop; QEMU exits with 0 for status 0, else 1. */
void mcu_exit(int status) __attribute__((noreturn));
/* Bytes of the main stack ever used (painted at reset), and its size. */
uint32_t mcu_stack_used(void);
uint32_t mcu_stack_size(void);

#endif /* RDC_MCU_H */
