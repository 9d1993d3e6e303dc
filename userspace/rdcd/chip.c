// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The chip on its own stack (rdcd.h, chip.c's part).
 *
 * A display-processor command runs to its end inside the core (a flood
 * fill of a large pattern can take minutes of host time), and the core
 * cannot be cut between two of its VRAM accesses without rewriting every
 * algorithm as a resumable state machine.  What the core does offer is a
 * poll hook at each VRAM access (rdc_hw_set_poll): the one place where
 * the DP holds no pointer into VRAM and the chip's time is current.  So
 * whatever moves simulated time runs here, on a second stack, and the
 * hook switches back to the daemon's loop once a slice of host time is
 * spent; the loop serves the sockets and switches back.  Nothing about
 * the simulation changes: the same calls run in the same order, only
 * paused, so every cycle and pixel is what it would have been.
 *
 * One chip, one stack, one thread: the switch is ucontext's, with the
 * sanitizer told about each stack change.
 */
#include <setjmp.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include "rdcd.h"

#ifdef RDC_ASAN /* rdc_base.h: built with AddressSanitizer */
#include <sanitizer/common_interface_defs.h>
#endif

/*
 * The chip's stack: the core is kernel code (small frames), librdc's
 * calls on top of it are shallow, but the frame sinks (a PNG encoder)
 * run on it too, and the sanitizer's frames are larger.  Pages are
 * touched only as used.
 */
#define CHIP_STACK (4u << 20)
#define NS_PER_US  1000u

struct rdcd_chip {
	struct rdcd *d;
	ucontext_t loop_ctx, chip_ctx;
	void *stack; /* mmap'd, a guard page below */
	size_t stack_len;
	jmp_buf abort_jb;

	rdcd_chip_fn fn;
	void *arg;
	bool running; /* a run began and has not ended */
	bool on_chip; /* executing on the chip's stack */
	bool aborting;
	/* suspended at a yield point of the chip function's own, between
	 * pieces of time (not inside a DP command) */
	bool between;
	uint64_t slice_end_ns;

#ifdef RDC_ASAN
	void *fake_loop, *fake_chip;
	const void *loop_bottom;
	size_t loop_size;
#endif
};

/* The loop hands the chip its stack and waits until it yields or ends. */
static void to_chip(struct rdcd_chip *ch)
{
#ifdef RDC_ASAN
	__sanitizer_start_switch_fiber(&ch->fake_loop,
				       (char *)ch->stack + getpagesize(),
				       ch->stack_len - (size_t)getpagesize());
#endif
	swapcontext(&ch->loop_ctx, &ch->chip_ctx);
#ifdef RDC_ASAN
	__sanitizer_finish_switch_fiber(ch->fake_loop, NULL, NULL);
#endif
}

/* The chip gives the loop its stack back, until the loop switches again. */
static void to_loop(struct rdcd_chip *ch)
{
	ch->on_chip = false;
#ifdef RDC_ASAN
	__sanitizer_start_switch_fiber(&ch->fake_chip, ch->loop_bottom,
				       ch->loop_size);
#endif
	swapcontext(&ch->chip_ctx, &ch->loop_ctx);
#ifdef RDC_ASAN
	__sanitizer_finish_switch_fiber(ch->fake_chip, &ch->loop_bottom,
					&ch->loop_size);
#endif
	ch->on_chip = true;
}

static struct rdcd_chip *chip_entry_arg;

static void chip_main(void)
{
	struct rdcd_chip *ch = chip_entry_arg;

#ifdef RDC_ASAN
	__sanitizer_finish_switch_fiber(NULL, &ch->loop_bottom, &ch->loop_size);
#endif
	ch->on_chip = true;
	for (;;) {
		if (!setjmp(ch->abort_jb))
			ch->fn(ch->d, ch->arg);
		ch->running = false;
		ch->aborting = false;
		to_loop(ch);
	}
}

/* The core's poll hook: the slice is over, let the loop serve. */
static void chip_poll(void *ctx)
{
	struct rdcd_chip *ch = ctx;

	if (!ch->on_chip || rdcd_wall_ns() < ch->slice_end_ns)
		return;
	to_loop(ch);
	if (ch->aborting)
		longjmp(ch->abort_jb, 1);
}

int rdcd_chip_open(struct rdcd *d)
{
	struct rdcd_chip *ch = calloc(1, sizeof(*ch));
	size_t page = (size_t)getpagesize();

	if (!ch)
		return -1;
	ch->d = d;
	ch->stack_len = CHIP_STACK + page;
	ch->stack = mmap(NULL, ch->stack_len, PROT_READ | PROT_WRITE,
			 MAP_PRIVATE | MAP_ANONYMOUS | MAP_STACK, -1, 0);
	if (ch->stack == MAP_FAILED) {
		free(ch);
		return -1;
	}
	mprotect(ch->stack, page, PROT_NONE); /* an overflow faults */
	if (getcontext(&ch->chip_ctx)) {
		munmap(ch->stack, ch->stack_len);
		free(ch);
		return -1;
	}
	ch->chip_ctx.uc_stack.ss_sp = (char *)ch->stack + page;
	ch->chip_ctx.uc_stack.ss_size = CHIP_STACK;
	ch->chip_ctx.uc_link = NULL;
	chip_entry_arg = ch;
	makecontext(&ch->chip_ctx, chip_main, 0);
	d->chip = ch;
	rdcd_chip_attach(d);
	return 0;
}

void rdcd_chip_close(struct rdcd *d)
{
	struct rdcd_chip *ch = d->chip;

	if (!ch)
		return;
	rdcd_chip_abort(d);
	if (d->hw)
		rdc_hw_set_poll(d->hw, NULL, NULL);
	munmap(ch->stack, ch->stack_len);
	free(ch);
	d->chip = NULL;
}

void rdcd_chip_attach(struct rdcd *d)
{
	if (d->chip && d->hw)
		rdc_hw_set_poll(d->hw, chip_poll, d->chip);
}

int rdcd_chip_run(struct rdcd *d, rdcd_chip_fn fn, void *arg)
{
	struct rdcd_chip *ch = d->chip;

	rdcd_watch(d); /* sinks open after the chip: before its first run */
	if (!ch) {
		fn(d, arg);
		return 0;
	}
	if (ch->running)
		return 1; /* one run at a time: the caller should have asked */
	ch->fn = fn;
	ch->arg = arg;
	ch->running = true;
	return rdcd_chip_resume(d);
}

int rdcd_chip_resume(struct rdcd *d)
{
	struct rdcd_chip *ch = d->chip;

	if (!ch || !ch->running)
		return 0;
	ch->slice_end_ns = rdcd_wall_ns() + RDCD_SLICE_US * NS_PER_US;
	to_chip(ch);
	return ch->running ? 1 : 0;
}

bool rdcd_chip_busy(const struct rdcd *d)
{
	return d->chip && d->chip->running;
}

void rdcd_chip_abort(struct rdcd *d)
{
	struct rdcd_chip *ch = d->chip;

	if (!ch || !ch->running)
		return;
	ch->aborting = true;
	to_chip(ch); /* it longjmps out of the run and comes back */
}

/* For chip functions that move time in pieces of their own (a step). */
void rdcd_chip_yield_point(struct rdcd *d)
{
	if (!d->chip)
		return;
	d->chip->between = true;
	chip_poll(d->chip);
	d->chip->between = false;
}

bool rdcd_chip_between(const struct rdcd *d)
{
	return d->chip && d->chip->running && d->chip->between;
}
