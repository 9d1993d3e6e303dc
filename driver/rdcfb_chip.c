// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The simulated RDC-1 inside the kernel: its memory, the two clocks that
 * move its simulated time, waits, command submission, frames and counters.
 *
 * chip->lock is a mutex: the simulation runs in process context with
 * interrupts on (a slice of it takes milliseconds), and every lock hold
 * first applies what fb_ops queued meanwhile (rdcfb_fb.c), in order.
 *
 * clock=paced: an hrtimer ticks a few times a frame and queues the pacing
 * work, which runs the chip up to the simulated time that wall time says
 * it should have reached, in bounded slices (simulating a frame takes
 * milliseconds: never in hrtimer context, never in one lock hold).  The
 * tick also comes at the wall time of each TE edge (and shortly before
 * it), and the slices stop at the edge, so that the GPIO line TE changes
 * close to the time it stands for (rdcfb_gpio.c).
 * clock=stepped: time moves only inside WAIT, STEP and FBIO_WAITFORVSYNC,
 * with the core's own wait (hw-sim/wait.c, which librdc's sim: backend uses
 * too), so the same register writes, submits and waits give the same
 * frames and cycle counts bit for bit.
 */
#include <linux/crc32.h>
#include <linux/delay.h>
#include <linux/jiffies.h>
#include <linux/math64.h>
#include <linux/sched/signal.h>
#include <linux/slab.h>
#include <linux/vmalloc.h>

#include "rdcfb.h"

/* Largest piece of a STEP or of a pacing catch-up in one lock hold. */
#define RDCFB_RUN_SLICE (1u << 17)
/* fb_ops run the DP for at most this long per FIFO-full, and this often. */
#define RDCFB_SYNC_SLICE (1u << 16)
#define RDCFB_SYNC_TRIES 64u
/* Pacing ticks per frame, and the tick's bounds. */
#define RDCFB_PACE_TICKS_PER_FRAME 4u
#define RDCFB_PACE_MIN_NS	   (1 * NSEC_PER_MSEC)
#define RDCFB_PACE_MAX_NS	   (50 * NSEC_PER_MSEC)
/*
 * A tick this long before each TE edge, so that the tick at the edge itself
 * has little simulation left to do before the edge reaches GPIO consumers;
 * and the shortest time to the next tick.
 */
#define RDCFB_EDGE_LEAD_NS (500 * NSEC_PER_USEC)
#define RDCFB_TICK_MIN_NS  (50 * NSEC_PER_USEC)
/* A host that cannot keep up lets simulated time slip past this lag. */
#define RDCFB_PACE_MAX_LAG_NS (100 * NSEC_PER_MSEC)
/* WAIT defaults: 10 s of wall time, 10 simulated seconds. */
#define RDCFB_WAIT_TIMEOUT_MS 10000u
#define RDCFB_WAIT_BUDGET_S   10u
/* FBIO_WAITFORVSYNC gives up after this (a blanked screen never has one). */
#define RDCFB_VSYNC_TIMEOUT_MS 1000u
/* Frame snapshot: bytes copied per lock hold, attempts before one hold. */
#define RDCFB_SNAP_CHUNK (64u << 10)
#define RDCFB_SNAP_TRIES 4u

/*
 * Take the chip.  What fb_ops queued (in atomic context, where they cannot
 * take the mutex) goes to the chip first, so it reaches the chip before
 * anything the caller does, as if they had run at once.
 */
void rdcfb_chip_lock(struct rdcfb_chip *chip)
{
	mutex_lock(&chip->lock);
	if (READ_ONCE(chip->opq.count) && chip->info)
		rdcfb_ops_apply_locked(chip);
}

void rdcfb_chip_unlock(struct rdcfb_chip *chip)
{
	mutex_unlock(&chip->lock);
}

/* The fb-op queue's worker: for work queued where nobody could apply it. */
static void rdcfb_opq_work(struct work_struct *work)
{
	struct rdcfb_chip *chip =
		container_of(work, struct rdcfb_chip, opq.work);

	rdcfb_chip_lock(chip);
	rdcfb_chip_unlock(chip);
}

/* A section with interrupts off ended at `at`: count it, keep the longest. */
void rdcfb_irqoff_end(struct rdcfb_irqoff *st, u64 t0, unsigned long at)
{
	s64 d = ktime_get_mono_fast_ns() - t0;
	s64 old = atomic64_read(&st->max_ns);
	u64 us = d > 0 ? div_u64(d, NSEC_PER_USEC) : 0;

	atomic64_inc(&st->hist[min_t(u32, us ? ilog2(us) + 1 : 0,
				     RDCFB_IRQOFF_BUCKETS - 1)]);

	while (d > old) {
		if (atomic64_try_cmpxchg(&st->max_ns, &old, d)) {
			WRITE_ONCE(st->max_at, at);
			break;
		}
	}
}

void rdcfb_irqoff_reset(struct rdcfb_irqoff *st)
{
	unsigned int i;

	atomic64_set(&st->max_ns, 0);
	WRITE_ONCE(st->max_at, 0);
	for (i = 0; i < RDCFB_IRQOFF_BUCKETS; i++)
		atomic64_set(&st->hist[i], 0);
}

/* The wall time the paced clock maps simulated time t to (lock held). */
static ktime_t rdcfb_wall_of_locked(struct rdcfb_chip *chip, u64 t)
{
	if (t <= chip->sim_base)
		return chip->wall_base;
	return ktime_add_ns(chip->wall_base,
			    mul_u64_u32_div(t - chip->sim_base, NSEC_PER_SEC,
					    chip->hw.core_hz));
}

/* Under chip->lock, inside the simulation. */
static void rdcfb_trace(void *ctx, u64 time, unsigned int event, u32 a, u32 b)
{
	struct rdcfb_chip *chip = ctx;

	if (event == RDC_TRACE_VBLANK)
		chip->frames++;
	else if (event == RDC_TRACE_ERROR)
		dev_dbg(chip->dev, "error %u info %#x at %llu\n", a, b, time);
	else if (event == RDC_TRACE_PINS && chip->gpio)
		rdcfb_gpio_event_locked(
			chip->gpio,
			chip->stepped ? 0 : rdcfb_wall_of_locked(chip, time),
			a);
}

/*
 * The interrupt controller's view: the IRQ pin's rising edges are the
 * interrupts.  Status stays for the client to read and clear (a driver
 * that cleared it would change what a client waiting on IRQ_STATUS sees
 * compared with sim:).
 */
void rdcfb_irq_check_locked(struct rdcfb_chip *chip)
{
	struct rdc_hw *hw = &chip->hw;
	u32 pending = hw->irq_status & hw->irq_enable;

	if (pending && !chip->irq_level) {
		chip->irqs++;
		dev_dbg(chip->dev, "irq %#x at %llu\n", pending, hw->now);
	}
	chip->irq_level = pending != 0;
}

static u64 rdcfb_ns_to_cycles(struct rdcfb_chip *chip, u64 ns)
{
	return mul_u64_u32_div(ns, chip->hw.core_hz, NSEC_PER_SEC);
}

static void rdcfb_update_period(struct rdcfb_chip *chip)
{
	u64 fc = chip->hw.crtc.running ? chip->hw.crtc.frame_cycles : 0;
	u64 ns = RDCFB_PACE_MAX_NS;

	if (fc)
		ns = div_u64(mul_u64_u32_div(fc, NSEC_PER_SEC,
					     chip->hw.core_hz),
			     RDCFB_PACE_TICKS_PER_FRAME);
	WRITE_ONCE(chip->period_ns,
		   clamp_t(u64, ns, RDCFB_PACE_MIN_NS, RDCFB_PACE_MAX_NS));
}

/* Simulated time of the next TE edge, or RDC_NEVER (lock held). */
static u64 rdcfb_next_te_locked(struct rdcfb_chip *chip)
{
	struct rdc_hw *hw = &chip->hw;

	if (hw->in_reset || !hw->crtc.running)
		return RDC_NEVER;
	return hw->crtc.in_vblank ? rdc_port_next_line(hw, 0) :
				    rdc_port_next_vblank(hw);
}

/*
 * When the pacing tick comes next (lock held): a period on, or earlier at
 * the next TE edge's wall time, with a tick RDCFB_EDGE_LEAD_NS before it,
 * so that TE's GPIO edges leave close to the time they stand for.
 */
static ktime_t rdcfb_next_tick_locked(struct rdcfb_chip *chip)
{
	ktime_t now = ktime_get();
	ktime_t soonest = ktime_add_ns(now, RDCFB_TICK_MIN_NS);
	ktime_t next = ktime_add_ns(now, chip->period_ns);
	u64 edge = rdcfb_next_te_locked(chip);
	ktime_t at;

	if (edge != RDC_NEVER) {
		at = rdcfb_wall_of_locked(chip, edge);
		if (ktime_after(ktime_sub_ns(at, RDCFB_EDGE_LEAD_NS), soonest))
			at = ktime_sub_ns(at, RDCFB_EDGE_LEAD_NS);
		if (ktime_before(at, next))
			next = at;
	}
	return ktime_before(next, soonest) ? soonest : next;
}

static void rdcfb_pace_work(struct work_struct *work)
{
	struct rdcfb_chip *chip =
		container_of(work, struct rdcfb_chip, pace_work);
	struct rdc_hw *hw = &chip->hw;
	u64 target, lag = rdcfb_ns_to_cycles(chip, RDCFB_PACE_MAX_LAG_NS);
	ktime_t now = ktime_get();

	rdcfb_chip_lock(chip);
	target = chip->sim_base +
		 rdcfb_ns_to_cycles(
			 chip, ktime_to_ns(ktime_sub(now, chip->wall_base)));
	/*
	 * Too far behind (a slow host) or ahead (fb_ops ran the DP
	 * at once when the FIFO filled): start pacing afresh from here.
	 */
	if (target > hw->now + lag || hw->now > target + lag) {
		chip->wall_base = now;
		chip->sim_base = hw->now;
		target = hw->now;
	}
	while (hw->now < target && !chip->dying) {
		u64 stop = min_t(u64, target, hw->now + RDCFB_RUN_SLICE);
		u64 edge = rdcfb_next_te_locked(chip);

		/* a TE edge goes out before the time after it is simulated */
		if (edge > hw->now && edge < stop)
			stop = edge;
		rdc_hw_run_until(hw, stop);
		rdcfb_irq_check_locked(chip);
		rdcfb_chip_unlock(chip);
		wake_up_all(&chip->waitq);
		/* no detour: cancel_work_sync in rdcfb_chip_stop keeps gpio */
		rdcfb_gpio_deliver_now(chip->gpio);
		cond_resched();
		rdcfb_chip_lock(chip);
	}
	rdcfb_update_period(chip);
	/* rdcfb_chip_stop sets dying under the lock, then cancels the timer */
	if (!chip->dying)
		hrtimer_start(&chip->timer, rdcfb_next_tick_locked(chip),
			      HRTIMER_MODE_ABS);
	rdcfb_chip_unlock(chip);
	wake_up_all(&chip->waitq);
}

/* One-shot: the pacing work arms the next tick when it is done. */
static enum hrtimer_restart rdcfb_tick(struct hrtimer *t)
{
	struct rdcfb_chip *chip = container_of(t, struct rdcfb_chip, timer);

	if (!READ_ONCE(chip->dying))
		queue_work(system_highpri_wq, &chip->pace_work);
	return HRTIMER_NORESTART;
}

int rdcfb_chip_init(struct rdcfb_chip *chip, struct device *dev, u32 vram_size,
		    bool stepped)
{
	struct rdc_hw_config cfg = { .vram_size = vram_size };

	mutex_init(&chip->lock);
	init_waitqueue_head(&chip->waitq);
	mutex_init(&chip->snap_lock);
	spin_lock_init(&chip->opq.lock);
	INIT_WORK(&chip->opq.work, rdcfb_opq_work);
	INIT_WORK(&chip->pace_work, rdcfb_pace_work);
	hrtimer_init(&chip->timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	chip->timer.function = rdcfb_tick;
	chip->dev = dev;
	chip->stepped = stepped;

	chip->vram = vmalloc_user(vram_size);
	chip->dp = vzalloc(sizeof(*chip->dp));
	chip->frame[0] = vzalloc(array_size(RDCFB_FRAME_CAP, sizeof(u32)));
	chip->frame[1] = vzalloc(array_size(RDCFB_FRAME_CAP, sizeof(u32)));
	chip->snap = vzalloc(array_size(RDCFB_FRAME_CAP, sizeof(u32)));
	chip->opq.ring = vmalloc(array_size(RDCFB_OPQ_WORDS, sizeof(u32)));
	chip->opq.buf =
		kmalloc_array(RDCFB_OP_MAX_WORDS, sizeof(u32), GFP_KERNEL);
	if (!chip->vram || !chip->dp || !chip->frame[0] || !chip->frame[1] ||
	    !chip->snap || !chip->opq.ring || !chip->opq.buf) {
		rdcfb_chip_free(chip);
		return -ENOMEM;
	}
	rdc_hw_init(&chip->hw, &cfg, chip->vram, chip->frame[0], chip->frame[1],
		    RDCFB_FRAME_CAP);
	rdc_dp_init(chip->dp, &chip->hw);
	rdc_hw_set_trace(&chip->hw, rdcfb_trace, chip);
	rdcfb_update_period(chip);
	return 0;
}

void rdcfb_chip_start(struct rdcfb_chip *chip)
{
	if (chip->stepped)
		return;
	chip->wall_base = ktime_get();
	chip->sim_base = chip->hw.now;
	hrtimer_start(&chip->timer, ns_to_ktime(chip->period_ns),
		      HRTIMER_MODE_REL);
}

/* Stop the clock and end every wait; the chip itself stays until free. */
void rdcfb_chip_stop(struct rdcfb_chip *chip)
{
	rdcfb_chip_lock(chip);
	WRITE_ONCE(chip->dying, true);
	rdcfb_chip_unlock(chip);
	hrtimer_cancel(&chip->timer);
	cancel_work_sync(&chip->pace_work);
	wake_up_all(&chip->waitq);
}

/* No fb_ops can come any more (the framebuffer is unregistered). */
void rdcfb_chip_free(struct rdcfb_chip *chip)
{
	cancel_work_sync(&chip->opq.work);
	kfree(chip->opq.buf);
	vfree(chip->opq.ring);
	chip->opq.buf = NULL;
	chip->opq.ring = NULL;
	vfree(chip->snap);
	vfree(chip->frame[1]);
	vfree(chip->frame[0]);
	vfree(chip->dp);
	vfree(chip->vram);
	chip->snap = NULL;
	chip->frame[0] = NULL;
	chip->frame[1] = NULL;
	chip->dp = NULL;
	chip->vram = NULL;
}

/* RESET_N and BL_EN as the host drives them. */
u32 rdcfb_chip_pins_in(struct rdcfb_chip *chip)
{
	u32 v;

	rdcfb_chip_lock(chip);
	v = chip->hw.pins_in;
	rdcfb_chip_unlock(chip);
	return v;
}

/* Drive one of the chip's input pins (the GPIO lines RESET_N and BL_EN). */
void rdcfb_chip_set_pin(struct rdcfb_chip *chip, u32 pin, bool high)
{
	struct rdc_hw *hw = &chip->hw;
	u32 pins;

	rdcfb_chip_lock(chip);
	pins = high ? hw->pins_in | pin : hw->pins_in & ~pin;
	if (pins != hw->pins_in) {
		rdc_hw_set_pins(hw, pins);
		/* RESET_N resets the DP's state behind fb_ops' back */
		chip->fb_state_gen++;
		rdcfb_irq_check_locked(chip);
		if (!chip->stepped)
			rdcfb_update_period(chip);
	}
	rdcfb_chip_unlock(chip);
	wake_up_all(&chip->waitq);
}

u32 rdcfb_reg_read(struct rdcfb_chip *chip, u32 reg)
{
	u32 v;

	rdcfb_chip_lock(chip);
	v = rdc_hw_read(&chip->hw, reg);
	rdcfb_chip_unlock(chip);
	return v;
}

void rdcfb_reg_write(struct rdcfb_chip *chip, u32 reg, u32 val)
{
	rdcfb_chip_lock(chip);
	rdc_hw_write(&chip->hw, reg, val);
	/* CONTROL (reset), FIFO_DATA: the DP's state may no longer be ours */
	chip->fb_state_gen++;
	rdcfb_irq_check_locked(chip);
	if (!chip->stepped)
		rdcfb_update_period(chip);
	rdcfb_chip_unlock(chip);
}

/* ---- Waits --------------------------------------------------------------- */

/* The ioctl's wait as the core's (hw-sim/wait.c) */
static void rdcfb_wait_conv(const struct rdcfb_wait *w, u64 budget,
			    struct rdc_hw_wait *hw_w)
{
	unsigned int i;

	BUILD_BUG_ON(RDCFB_WAIT_TERMS != RDC_WAIT_TEST_TERMS);
	BUILD_BUG_ON(RDCFB_WAIT_GE != RDC_WAIT_TEST_GE);
	BUILD_BUG_ON(RDCFB_WAIT_WRAP_GE != RDC_WAIT_TEST_WRAP_GE);
	BUILD_BUG_ON(RDCFB_WAIT_EQ != RDC_WAIT_TEST_EQ);
	memset(hw_w, 0, sizeof(*hw_w));
	for (i = 0; i < RDCFB_WAIT_TERMS; i++) {
		hw_w->term[i].test = w->term[i].kind;
		hw_w->term[i].reg = w->term[i].reg;
		hw_w->term[i].mask = w->term[i].mask;
		hw_w->term[i].value = w->term[i].value;
	}
	hw_w->needs_dp = w->flags & RDCFB_WAIT_NEEDS_DP;
	hw_w->budget = budget;
}

/*
 * One look at a paced wait's condition, with the lock held: 0 it holds,
 * -EIO the DP halted (a needs-DP wait), -ETIMEDOUT the budget is spent,
 * 1 not yet.  The order is the core's (hw-sim/wait.c).
 */
static int rdcfb_wait_check(struct rdcfb_chip *chip,
			    const struct rdc_hw_wait *w)
{
	switch (rdc_hw_wait_check(&chip->hw, w)) {
	case RDC_HW_WAIT_DONE:
		return 0;
	case RDC_HW_WAIT_HALTED:
		return -EIO;
	case RDC_HW_WAIT_TIMEOUT:
		return -ETIMEDOUT;
	default:
		return 1;
	}
}

/*
 * Between two pieces of a long run of the chip: drop the lock and give way.
 * 0 with the lock taken again, or -EINTR (a fatal signal) or -ENODEV (the
 * device is going) with it dropped.
 */
static int rdcfb_chip_pause(struct rdcfb_chip *chip)
{
	rdcfb_chip_unlock(chip);
	if (fatal_signal_pending(current))
		return -EINTR;
	if (READ_ONCE(chip->dying))
		return -ENODEV;
	cond_resched();
	rdcfb_chip_lock(chip);
	return 0;
}

/*
 * Stepped: the core's wait, run in pieces of RDCFB_RUN_SLICE cycles with
 * the lock dropped between them (which never changes where it ends).
 */
static int rdcfb_wait_stepped(struct rdcfb_chip *chip, struct rdc_hw_wait *w)
{
	struct rdc_hw *hw = &chip->hw;
	enum rdc_hw_wait_result res;
	int err;

	rdcfb_chip_lock(chip);
	rdc_hw_wait_begin(hw, w);
	for (;;) {
		res = rdc_hw_wait_run(hw, w, RDCFB_RUN_SLICE);
		rdcfb_irq_check_locked(chip);
		if (res != RDC_HW_WAIT_MORE)
			break;
		err = rdcfb_chip_pause(chip);
		if (err)
			return err;
	}
	rdcfb_chip_unlock(chip);
	wake_up_all(&chip->waitq);
	switch (res) {
	case RDC_HW_WAIT_DONE:
		return 0;
	case RDC_HW_WAIT_HALTED:
		return -EIO;
	default:
		return -ETIMEDOUT;
	}
}

/*
 * Paced: sleep until the pacing work has moved time, and look again.
 * SUBMIT's waits for FIFO room take only fatal signals: words of the
 * buffer are in the FIFO already, and a restarted ioctl would queue them
 * twice.
 */
static int rdcfb_wait_paced(struct rdcfb_chip *chip, struct rdc_hw_wait *w,
			    u32 timeout_ms, bool interruptible)
{
	unsigned long deadline =
		jiffies + msecs_to_jiffies(timeout_ms ? timeout_ms :
							RDCFB_WAIT_TIMEOUT_MS);
	u64 seen;
	long left;
	int ret;

	rdcfb_chip_lock(chip);
	rdc_hw_wait_begin(&chip->hw, w);
	rdcfb_chip_unlock(chip);
	for (;;) {
		rdcfb_chip_lock(chip);
		seen = chip->hw.now;
		ret = rdcfb_wait_check(chip, w);
		rdcfb_chip_unlock(chip);
		if (ret <= 0)
			return ret;
		left = (long)(deadline - jiffies);
		if (left <= 0)
			return -ETIMEDOUT;
		if (interruptible)
			left = wait_event_interruptible_timeout(
				chip->waitq,
				READ_ONCE(chip->hw.now) != seen ||
					READ_ONCE(chip->dying),
				left);
		else
			left = wait_event_killable_timeout(
				chip->waitq,
				READ_ONCE(chip->hw.now) != seen ||
					READ_ONCE(chip->dying),
				left);
		if (left < 0)
			return left;
		if (READ_ONCE(chip->dying))
			return -ENODEV;
	}
}

static int rdcfb_chip_wait_sig(struct rdcfb_chip *chip,
			       const struct rdcfb_wait *w, bool interruptible)
{
	u64 budget = w->budget ? w->budget :
				 (u64)RDCFB_WAIT_BUDGET_S * chip->hw.core_hz;
	struct rdc_hw_wait hw_w;
	unsigned int i;

	/* a NONE term's other fields are never read */
	for (i = 0; i < RDCFB_WAIT_TERMS; i++)
		if (w->term[i].kind > RDCFB_WAIT_EQ ||
		    (w->term[i].kind != RDCFB_WAIT_NONE &&
		     (w->term[i].reg % sizeof(u32) ||
		      w->term[i].reg >= RDC_REG_WINDOW)))
			return -EINVAL;
	if (w->flags & ~RDCFB_WAIT_NEEDS_DP)
		return -EINVAL;
	if (READ_ONCE(chip->dying))
		return -ENODEV;
	rdcfb_wait_conv(w, budget, &hw_w);
	return chip->stepped ? rdcfb_wait_stepped(chip, &hw_w) :
			       rdcfb_wait_paced(chip, &hw_w, w->timeout_ms,
						interruptible);
}

int rdcfb_chip_wait(struct rdcfb_chip *chip, const struct rdcfb_wait *w)
{
	return rdcfb_chip_wait_sig(chip, w, true);
}

int rdcfb_chip_step(struct rdcfb_chip *chip, u64 cycles)
{
	struct rdc_hw *hw = &chip->hw;
	u64 end;
	int err;

	if (cycles > RDCFB_MAX_CYCLES)
		return -EINVAL;
	if (!chip->stepped)
		return -EPERM;
	rdcfb_chip_lock(chip);
	if (cycles > U64_MAX - hw->now) {
		rdcfb_chip_unlock(chip);
		return -ERANGE;
	}
	end = hw->now + cycles;
	/*
	 * In pieces, so one STEP never holds the lock for long; the chip
	 * gives the same result run in pieces as in one go.
	 */
	while (hw->now < end) {
		rdc_hw_run_until(hw,
				 min_t(u64, end, hw->now + RDCFB_RUN_SLICE));
		rdcfb_irq_check_locked(chip);
		err = rdcfb_chip_pause(chip);
		if (err)
			return err;
	}
	rdcfb_chip_unlock(chip);
	wake_up_all(&chip->waitq);
	return 0;
}

int rdcfb_chip_vsync(struct rdcfb_chip *chip)
{
	struct rdcfb_wait w = {
		.term[0] = { .kind = RDCFB_WAIT_WRAP_GE,
			     .reg = RDC_REG_FRAME_COUNT,
			     .mask = ~0u },
		.timeout_ms = RDCFB_VSYNC_TIMEOUT_MS,
	};
	struct rdc_hw *hw = &chip->hw;
	u64 next;

	rdcfb_chip_lock(chip);
	next = rdc_port_next_vblank(hw);
	w.term[0].value = rdc_hw_read(hw, RDC_REG_FRAME_COUNT) + 1;
	/* the budget reaches just past the next vblank */
	w.budget = next - hw->now + 1;
	rdcfb_chip_unlock(chip);
	if (next == RDC_NEVER)
		return -ETIMEDOUT;
	return rdcfb_chip_wait(chip, &w);
}

/* ---- Submission ---------------------------------------------------------- */

/*
 * Push validated words into the FIFO as librdc's core does for a backend
 * without a submit op: as many as FIFO_FREE says, then wait (a needs-DP
 * wait) for half a FIFO.  The words of one SUBMIT go in under the lock in
 * runs, so fb_ops (which see chip->submitting) keep out of the middle of
 * a command.
 */
int rdcfb_chip_submit(struct rdcfb_chip *chip, const u32 *words, u32 n)
{
	struct rdc_hw *hw = &chip->hw;
	u32 free_words;
	int ret = 0;

	while (n) {
		rdcfb_chip_lock(chip);
		chip->fb_state_gen++;
		free_words = rdc_hw_read(hw, RDC_REG_FIFO_FREE);
		for (; free_words && n; free_words--, n--, words++)
			rdc_hw_write(hw, RDC_REG_FIFO_DATA, *words);
		chip->submitting = n != 0;
		rdcfb_chip_unlock(chip);
		if (n) {
			struct rdcfb_wait w = {
				.term[0] = { .kind = RDCFB_WAIT_GE,
					     .reg = RDC_REG_FIFO_FREE,
					     .mask = ~0u,
					     .value = min_t(u32, n,
							    RDC_FIFO_DEPTH /
								    2) },
				.flags = RDCFB_WAIT_NEEDS_DP,
			};

			ret = rdcfb_chip_wait_sig(chip, &w, false);
			if (ret)
				break;
		}
	}
	rdcfb_chip_lock(chip);
	chip->submitting = false;
	rdcfb_chip_unlock(chip);
	return ret;
}

/* ---- fb_ops' side: the queue's records, chip->lock held ------------------ */

/*
 * Can the DP take fb_ops' commands: enabled, not halted, and no client's
 * command half in the FIFO?
 */
bool rdcfb_dp_usable(struct rdcfb_chip *chip)
{
	struct rdc_hw *hw = &chip->hw;

	return !chip->submitting && !hw->in_reset &&
	       (hw->control & RDC_CONTROL_DP_EN) &&
	       !(hw->dp_status & RDC_STATUS_DP_HALTED) && !chip->dying;
}

/*
 * Queue words; when the FIFO is full, run the DP for a bounded slice as a
 * driver would poll FIFO_FREE, giving way between slices (the lock is a
 * mutex, so none of this holds interrupts off).  The caller checked
 * rdcfb_dp_usable.
 */
int rdcfb_push_locked(struct rdcfb_chip *chip, const u32 *words, u32 n)
{
	struct rdc_hw *hw = &chip->hw;
	unsigned int tries = 0;
	u32 free_words;

	while (n) {
		free_words = rdc_hw_read(hw, RDC_REG_FIFO_FREE);
		if (!free_words) {
			if (++tries > RDCFB_SYNC_TRIES ||
			    (hw->dp_status & RDC_STATUS_DP_HALTED))
				return -ETIMEDOUT;
			rdc_hw_run_until_idle(hw, hw->now + RDCFB_SYNC_SLICE);
			rdcfb_irq_check_locked(chip);
			cond_resched();
			continue;
		}
		for (; free_words && n; free_words--, n--, words++)
			rdc_hw_write(hw, RDC_REG_FIFO_DATA, *words);
	}
	return 0;
}

/* Run the DP until it has nothing left it can do (bounded). */
void rdcfb_drain_locked(struct rdcfb_chip *chip)
{
	struct rdc_hw *hw = &chip->hw;
	unsigned int tries;

	for (tries = 0; tries < RDCFB_SYNC_TRIES; tries++) {
		if (rdc_hw_run_until_idle(hw, hw->now + RDCFB_SYNC_SLICE))
			break;
		cond_resched();
	}
	rdcfb_irq_check_locked(chip);
}

/* ---- Counters and frames ------------------------------------------------- */

void rdcfb_chip_counters(struct rdcfb_chip *chip, struct rdcfb_counters *c)
{
	struct rdc_hw *hw = &chip->hw;

	rdcfb_chip_lock(chip);
	c->now = hw->now;
	c->busy = hw->perf.busy;
	c->stall = hw->perf.stall;
	c->pixels = hw->perf.pixels;
	c->cmds = hw->perf.cmds;
	c->last_cycles = hw->perf.last_cycles;
	c->last_opcode = hw->perf.last_opcode;
	c->fence = hw->fence;
	c->frames = (u32)chip->frames;
	c->reserved = 0;
	rdcfb_chip_unlock(chip);
}

/* zlib's CRC-32 of the pixels as little-endian bytes. */
static u32 rdcfb_crc(const u32 *px, size_t count)
{
	__le32 buf[64];
	u32 crc = ~0u;
	size_t i, k;

	for (i = 0; i < count; i += k) {
		for (k = 0; k < ARRAY_SIZE(buf) && i + k < count; k++)
			buf[k] = cpu_to_le32(px[i + k]);
		crc = crc32_le(crc, (const u8 *)buf, k * sizeof(buf[0]));
	}
	return ~crc;
}

/*
 * Copy the latest complete frame to chip->snap (snap_lock held).  It is
 * copied in pieces with the lock dropped between them; a frame completed
 * meanwhile (the buffers swap) means a retry, the last one in one hold of
 * the lock (which stops the simulation, not interrupts), giving way
 * between pieces all the same.  Returns 0, or -EAGAIN before the first
 * frame.
 */
int rdcfb_chip_snapshot(struct rdcfb_chip *chip)
{
	unsigned int tries;
	const u32 *f;
	u32 w, h;
	size_t bytes, off;
	u64 seq;

	lockdep_assert_held(&chip->snap_lock);
	for (tries = 0; tries < RDCFB_SNAP_TRIES; tries++) {
		rdcfb_chip_lock(chip);
		f = rdc_hw_frame(&chip->hw, &w, &h);
		seq = chip->frames;
		if (!f) {
			rdcfb_chip_unlock(chip);
			chip->snap_seq = 0;
			return -EAGAIN;
		}
		if (seq == chip->snap_seq && w == chip->snap_w &&
		    h == chip->snap_h) {
			rdcfb_chip_unlock(chip);
			return 0;
		}
		bytes = (size_t)w * h * sizeof(u32);
		for (off = 0; off < bytes; off += RDCFB_SNAP_CHUNK) {
			size_t len =
				min_t(size_t, RDCFB_SNAP_CHUNK, bytes - off);

			memcpy((u8 *)chip->snap + off, (const u8 *)f + off,
			       len);
			if (tries + 1 == RDCFB_SNAP_TRIES) {
				cond_resched();
				continue;
			}
			rdcfb_chip_unlock(chip);
			cond_resched();
			rdcfb_chip_lock(chip);
			if (chip->frames != seq)
				break;
		}
		if (chip->frames == seq) {
			rdcfb_chip_unlock(chip);
			chip->snap_seq = seq;
			chip->snap_w = w;
			chip->snap_h = h;
			chip->snap_crc = rdcfb_crc(chip->snap, (size_t)w * h);
			return 0;
		}
		rdcfb_chip_unlock(chip);
	}
	return -EAGAIN;
}
