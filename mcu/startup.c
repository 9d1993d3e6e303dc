// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Reset and fault handling for a Cortex-M3 (ARMv7-M), and the semihosting
 * calls the firmware talks through (QEMU: -semihosting-config enable=on).
 * No C library: the reset code copies .data, zeroes .bss and the PSRAM
 * section, paints the stack, and calls main(); its return value is the
 * exit status QEMU returns.
 */
#include <stddef.h>
#include <stdint.h>

#include "mcu.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __psram_start[], __psram_end[];
extern uint32_t __stack_limit[], __stack_top[];

int main(void);
void rdc_mcu_reset(void);
void rdc_mcu_fault(void);
void rdc_mcu_fault_report(const uint32_t *frame);

/* System control block: configuration and fault status (ARMv7-M ARM B3.2) */
#define SCB_CCR		     ((volatile uint32_t *)0xe000ed14u)
#define SCB_CCR_UNALIGN_TRP  (1u << 3)
#define SCB_CCR_DIV_0_TRP    (1u << 4)
#define SCB_SHCSR	     ((volatile uint32_t *)0xe000ed24u)
#define SCB_SHCSR_FAULTS_ENA (7u << 16) /* MemManage, BusFault, UsageFault */
#define SCB_CFSR	     ((volatile uint32_t *)0xe000ed28u)

#define SEMIHOST_SYS_WRITE0	      0x04u
#define SEMIHOST_SYS_EXIT	      0x18u
#define SEMIHOST_EXIT_APPLICATION     0x20026u /* ADP_Stopped_ApplicationExit */
#define SEMIHOST_EXIT_RUNTIME_UNKNOWN 0x20023u /* any other: status 1 */

#define STACK_PAINT 0x5a5aa5a5u

static uint32_t semihost(uint32_t op, const void *arg)
{
	register uint32_t r0 __asm__("r0") = op;
	register const void *r1 __asm__("r1") = arg;

	__asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
	return r0;
}

void mcu_puts(const char *s)
{
	semihost(SEMIHOST_SYS_WRITE0, s);
}

void mcu_exit(int status)
{
	/* on 32-bit Arm the reason itself is the argument */
	semihost(
		SEMIHOST_SYS_EXIT,
		(const void *)(uintptr_t)(status ?
						  SEMIHOST_EXIT_RUNTIME_UNKNOWN :
						  SEMIHOST_EXIT_APPLICATION));
	for (;;)
		;
}

uint32_t mcu_stack_used(void)
{
	const uint32_t *p = __stack_limit;

	while (p < __stack_top && *p == STACK_PAINT)
		p++;
	return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

uint32_t mcu_stack_size(void)
{
	return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit);
}

static void fill(uint32_t *p, const uint32_t *end, uint32_t v)
{
	while (p < end)
		*p++ = v;
}

/* The vector table's reset entry: runs on the stack the table names. */
void __attribute__((noreturn, used)) rdc_mcu_reset(void)
{
	const uint32_t *src = __data_load;
	uint32_t *dst = __data_start;
	uint32_t *sp;

	while (dst < __data_end)
		*dst++ = *src++;
	fill(__bss_start, __bss_end, 0);
	fill(__psram_start, __psram_end, 0);
	/* paint the stack below the reset code's own frame */
	__asm__ volatile("mov %0, sp" : "=r"(sp));
	fill(__stack_limit, sp - 16, STACK_PAINT);
	/*
	 * Trap what a host would let pass: unaligned word accesses (the core
	 * must not make them; the compiler makes none, -mno-unaligned-access)
	 * and division by zero; fault handlers of their own for each kind.
	 */
	*SCB_CCR |= SCB_CCR_UNALIGN_TRP | SCB_CCR_DIV_0_TRP;
	*SCB_SHCSR |= SCB_SHCSR_FAULTS_ENA;
	__asm__ volatile("dsb\n\tisb" ::: "memory");
	mcu_exit(main());
}

static void put_hex(char *d, uint32_t v)
{
	static const char hex[] = "0123456789abcdef";

	for (int i = 0; i < 8; i++)
		d[i] = hex[(v >> (28 - 4 * i)) & 15u];
}

/* Any fault: say which and where, and stop with a failure status. */
void __attribute__((noreturn, used)) rdc_mcu_fault_report(const uint32_t *frame)
{
	char msg[] = "fault: ipsr xxxxxxxx cfsr xxxxxxxx pc xxxxxxxx\n";
	uint32_t ipsr;

	__asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
	put_hex(msg + 12, ipsr);
	put_hex(msg + 26, *SCB_CFSR);
	/* the exception frame: r0-r3, r12, lr, pc, xpsr */
	put_hex(msg + 38, frame[6]);
	mcu_puts(msg);
	mcu_exit(1);
}

/* The handler proper: the frame the exception pushed, before any push. */
void __attribute__((naked, noreturn)) rdc_mcu_fault(void)
{
	__asm__ volatile("mrs r0, msp\n\tb rdc_mcu_fault_report");
}

/* ARMv7-M vector table: the initial stack pointer, then the handlers. */
#define VECTOR_SECTION __attribute__((section(".vectors"), used))
static void (*const vectors[16])(void) VECTOR_SECTION = {
	(void (*)(void))(uintptr_t)__stack_top,
	rdc_mcu_reset,
	rdc_mcu_fault, /* NMI */
	rdc_mcu_fault, /* HardFault */
	rdc_mcu_fault, /* MemManage */
	rdc_mcu_fault, /* BusFault */
	rdc_mcu_fault, /* UsageFault */
	NULL,	       /* reserved */
	NULL,	       /* reserved */
	NULL,	       /* reserved */
	NULL,	       /* reserved */
	rdc_mcu_fault, /* SVCall */
	rdc_mcu_fault, /* DebugMonitor */
	NULL,	       /* reserved */
	rdc_mcu_fault, /* PendSV */
	rdc_mcu_fault, /* SysTick */
};
