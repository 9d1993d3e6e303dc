// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The kernel's host of the simulated RDC-1, shared by rdcfb.ko and
 * rdcdrm.ko: its memory, the two clocks that move its simulated time,
 * waits, command submission, frames, counters and pins.
 *
 * chip->lock is a mutex: the simulation runs in process context with
 * interrupts on (a slice of it takes milliseconds), and every lock hold
 * first runs the module's before_use hook (rdcfb applies what its fb_ops
 * queued meanwhile, rdcfb_fb.c).
 *
 * clock=paced: an hrtimer ticks a few times a frame and queues the pacing
 * work, which runs the chip up to the simulated time that wall time says
 * it should have reached, in bounded slices (simulating a frame takes
 * milliseconds: never in hrtimer context, never in one lock hold).  The
 * tick also comes at the wall time of each TE edge (and shortly before
 * it), and the slices stop at the edge, so that the GPIO line TE changes
 * close to the time it stands for (rdc_kgpio.c).
 * clock=stepped: time moves only inside WAIT, STEP and FBIO_WAITFORVSYNC,
 * with the core's own wait (hw-sim/wait.c, which librdc's sim: backend uses
 * too), so the same register writes, submits and waits give the same
 * frames and cycle counts bit for bit.
 */
#include <linux/crc32.h>
#include <linux/delay.h>
#include <linux/jiffies.h>
#include <linux/math64.h>
#include <linux/mm.h>
#include <linux/sched/signal.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/sysfs.h>
#include <linux/vmalloc.h>

#include "rdc_kchip.h"

/* Largest piece of a STEP or of a pacing catch-up in one lock hold. */
#define RDC_KCHIP_RUN_SLICE (1u << 17)
/* fb_ops run the DP for at most this long per FIFO-full, and this often. */
#define RDC_KCHIP_SYNC_SLICE (1u << 16)
#define RDC_KCHIP_SYNC_TRIES 64u
/* Pacing ticks per frame, and the tick's bounds. */
#define RDC_KCHIP_PACE_TICKS_PER_FRAME 4u
#define RDC_KCHIP_PACE_MIN_NS	       (1 * NSEC_PER_MSEC)
#define RDC_KCHIP_PACE_MAX_NS	       (50 * NSEC_PER_MSEC)
/*
 * A tick this long before each TE edge, so that the tick at the edge itself
 * has little simulation left to do before the edge reaches GPIO consumers;
 * and the shortest time to the next tick.
 */
#define RDC_KCHIP_EDGE_LEAD_NS (500 * NSEC_PER_USEC)
#define RDC_KCHIP_TICK_MIN_NS  (50 * NSEC_PER_USEC)
/* A host that cannot keep up lets simulated time slip past this lag. */
#define RDC_KCHIP_PACE_MAX_LAG_NS (100 * NSEC_PER_MSEC)
/* WAIT defaults: 10 s of wall time, 10 simulated seconds. */
#define RDC_KCHIP_WAIT_TIMEOUT_MS 10000u
#define RDC_KCHIP_WAIT_BUDGET_S	  10u
/* FBIO_WAITFORVSYNC gives up after this (a blanked screen never has one). */
#define RDC_KCHIP_VSYNC_TIMEOUT_MS 1000u
/* Frame snapshot: bytes copied per lock hold, attempts before one hold. */
#define RDC_KCHIP_SNAP_CHUNK (64u << 10)
#define RDC_KCHIP_SNAP_TRIES 4u
/* A frame grab keeps frames converted until this many frames pass without. */
#define RDC_KCHIP_GRAB_HOLD_FRAMES 30u

int rdc_kchip_params_parse(const char *name, const char *vram, u32 vram_min,
			   u32 vram_max, const char *clock, const char *scanout,
			   unsigned int cpu_budget, unsigned int devices,
			   unsigned int max_devices,
			   struct rdc_kchip_params *out)
{
	unsigned long long size;
	char *end;

	size = memparse(vram, &end);
	if (*end || size < vram_min || size > vram_max) {
		pr_err("%s: vram=%s: want %u..%u bytes\n", name, vram, vram_min,
		       vram_max);
		return -EINVAL;
	}
	out->vram_bytes = PAGE_ALIGN(size);
	if (!strcmp(clock, "stepped")) {
		out->stepped = true;
	} else if (!strcmp(clock, "paced")) {
		out->stepped = false;
	} else {
		pr_err("%s: clock=%s: want paced or stepped\n", name, clock);
		return -EINVAL;
	}
	/*
	 * auto: on demand when paced, where idle frames cost wall time;
	 * always when stepped, where time moves only in waits and a frame
	 * grab could otherwise find none until the next one.
	 */
	if (!strcmp(scanout, "auto")) {
		out->on_demand = !out->stepped;
	} else if (!strcmp(scanout, "demand")) {
		out->on_demand = true;
	} else if (!strcmp(scanout, "always")) {
		out->on_demand = false;
	} else {
		pr_err("%s: scanout=%s: want auto, demand or always\n", name,
		       scanout);
		return -EINVAL;
	}
	if (!cpu_budget || cpu_budget > 100) {
		pr_err("%s: cpu_budget=%u: want 1..100 (per cent)\n", name,
		       cpu_budget);
		return -EINVAL;
	}
	if (!devices || devices > max_devices) {
		pr_err("%s: devices=%u: want 1..%u\n", name, devices,
		       max_devices);
		return -EINVAL;
	}
	/*
	 * The budget is the module's, all its devices together: each paces
	 * within its share, so that N busy devices cannot take N budgets.
	 */
	out->cpu_budget = max(cpu_budget / devices, 1u);
	return 0;
}

/*
 * Take the chip.  The module's before_use hook runs first (what rdcfb's
 * fb_ops queued in atomic context, where they cannot take the mutex, goes
 * to the chip), so that it reaches the chip before anything the caller
 * does, as if it had run at once.
 */
void rdc_kchip_lock(struct rdc_kchip *chip)
{
	mutex_lock(&chip->lock);
	chip->held_at = ktime_get_ns();
	if (chip->hooks && chip->hooks->before_use)
		chip->hooks->before_use(chip);
}

/* The time held is the chip's cost to its host (sysfs host_busy_ns). */
void rdc_kchip_unlock(struct rdc_kchip *chip)
{
	chip->busy_ns += ktime_get_ns() - chip->held_at;
	mutex_unlock(&chip->lock);
}

void rdc_kchip_consumer(struct rdc_kchip *chip, bool attach)
{
	rdc_kchip_lock(chip);
	if (attach)
		rdc_hw_consumer_attach(chip->hw);
	else
		rdc_hw_consumer_detach(chip->hw);
	rdc_kchip_unlock(chip);
}

/* A section with interrupts off ended at `at`: count it, keep the longest. */
void rdc_kchip_irqoff_end(struct rdc_kchip_irqoff *st, u64 t0, unsigned long at)
{
	s64 d = ktime_get_mono_fast_ns() - t0;
	s64 old = atomic64_read(&st->max_ns);
	u64 us = d > 0 ? div_u64(d, NSEC_PER_USEC) : 0;

	atomic64_inc(&st->hist[min_t(u32, us ? ilog2(us) + 1 : 0,
				     RDC_KCHIP_IRQOFF_BUCKETS - 1)]);

	while (d > old) {
		if (atomic64_try_cmpxchg(&st->max_ns, &old, d)) {
			WRITE_ONCE(st->max_at, at);
			break;
		}
	}
}

void rdc_kchip_irqoff_reset(struct rdc_kchip_irqoff *st)
{
	unsigned int i;

	atomic64_set(&st->max_ns, 0);
	WRITE_ONCE(st->max_at, 0);
	for (i = 0; i < RDC_KCHIP_IRQOFF_BUCKETS; i++)
		atomic64_set(&st->hist[i], 0);
}

/* The wall time the paced clock maps simulated time t to (lock held). */
ktime_t rdc_kchip_wall_of_locked(struct rdc_kchip *chip, u64 t)
{
	ktime_t wall0 = ns_to_ktime(chip->pace.wall0_ns);

	if (t <= chip->pace.sim0)
		return wall0;
	return ktime_add_ns(wall0,
			    mul_u64_u32_div(t - chip->pace.sim0, NSEC_PER_SEC,
					    rdc_hw_core_hz(chip->hw)));
}

/* The vblank hook of the module, once per frame. */
static void rdc_kchip_vblank_locked(struct rdc_kchip *chip, u64 time)
{
	chip->frames++;
	if (chip->grab_watch &&
	    chip->frames - chip->grab_at > RDC_KCHIP_GRAB_HOLD_FRAMES) {
		rdc_hw_consumer_detach(chip->hw);
		chip->grab_watch = false;
	}
	if (!chip->hooks || !chip->hooks->vblank)
		return;
	chip->hooks->vblank(chip, chip->frames, time,
			    chip->stepped ?
				    ktime_get() :
				    rdc_kchip_wall_of_locked(chip, time));
}

/* Under chip->lock, inside the simulation. */
static void rdc_kchip_trace(void *ctx, u64 time, unsigned int event, u32 a,
			    u32 b)
{
	struct rdc_kchip *chip = ctx;

	if (event == RDC_TRACE_VBLANK)
		rdc_kchip_vblank_locked(chip, time);
	else if (event == RDC_TRACE_ERROR)
		dev_dbg(chip->dev, "error %u info %#x at %llu\n", a, b, time);
	else if (event == RDC_TRACE_PINS && chip->gpio)
		rdc_kgpio_event_locked(
			chip->gpio,
			chip->stepped ? 0 :
					rdc_kchip_wall_of_locked(chip, time),
			a);
}

/*
 * The interrupt controller's view: the IRQ pin's rising edges are the
 * interrupts.  Status stays for the client to read and clear (a driver
 * that cleared it would change what a client waiting on IRQ_STATUS sees
 * compared with sim:).
 */
void rdc_kchip_irq_check_locked(struct rdc_kchip *chip)
{
	struct rdc_hw_state st;
	u32 pending;

	rdc_hw_state(chip->hw, &st);
	pending = st.irq_status & st.irq_enable;
	if (pending && !chip->irq_level) {
		chip->irqs++;
		dev_dbg(chip->dev, "irq %#x at %llu\n", pending,
			rdc_hw_now(chip->hw));
	}
	chip->irq_level = pending != 0;
}

static u64 rdc_kchip_ns_to_cycles(struct rdc_kchip *chip, u64 ns)
{
	return mul_u64_u32_div(ns, rdc_hw_core_hz(chip->hw), NSEC_PER_SEC);
}

static void rdc_kchip_update_period(struct rdc_kchip *chip)
{
	u64 ns = RDC_KCHIP_PACE_MAX_NS, fc;
	struct rdc_hw_state st;

	rdc_hw_state(chip->hw, &st);
	fc = st.scanning ? st.frame_cycles : 0;
	if (fc)
		ns = div_u64(mul_u64_u32_div(fc, NSEC_PER_SEC,
					     rdc_hw_core_hz(chip->hw)),
			     RDC_KCHIP_PACE_TICKS_PER_FRAME);
	WRITE_ONCE(chip->period_ns, clamp_t(u64, ns, RDC_KCHIP_PACE_MIN_NS,
					    RDC_KCHIP_PACE_MAX_NS));
}

/* Simulated time of the next TE edge, or RDC_NEVER (lock held). */
static u64 rdc_kchip_next_te_locked(struct rdc_kchip *chip)
{
	struct rdc_hw_state st;

	rdc_hw_state(chip->hw, &st);
	if (st.in_reset || !st.scanning)
		return RDC_NEVER;
	return st.in_vblank ? rdc_hw_next_line(chip->hw, 0) :
			      rdc_hw_next_vblank(chip->hw);
}

/*
 * When the pacing tick comes next (lock held): a period on, or earlier at
 * the next TE edge's wall time, with a tick RDC_KCHIP_EDGE_LEAD_NS before it,
 * so that TE's GPIO edges leave close to the time they stand for.
 */
static ktime_t rdc_kchip_next_tick_locked(struct rdc_kchip *chip)
{
	ktime_t now = ktime_get();
	ktime_t soonest = ktime_add_ns(now, RDC_KCHIP_TICK_MIN_NS);
	ktime_t next = ktime_add_ns(now, chip->period_ns);
	u64 edge = rdc_kchip_next_te_locked(chip);
	ktime_t at;

	if (edge != RDC_NEVER) {
		at = rdc_kchip_wall_of_locked(chip, edge);
		if (ktime_after(ktime_sub_ns(at, RDC_KCHIP_EDGE_LEAD_NS),
				soonest))
			at = ktime_sub_ns(at, RDC_KCHIP_EDGE_LEAD_NS);
		if (ktime_before(at, next))
			next = at;
	}
	return ktime_before(next, soonest) ? soonest : next;
}

static void rdc_kchip_pace_work(struct work_struct *work)
{
	struct rdc_kchip *chip =
		container_of(work, struct rdc_kchip, pace_work);
	struct rdc_hw *hw = chip->hw;
	u64 target,
		spent = 0,
		lag = rdc_kchip_ns_to_cycles(chip, RDC_KCHIP_PACE_MAX_LAG_NS);
	ktime_t t0, held, next, rest;

	rdc_kchip_lock(chip);
	/* the budget counts the time the work holds the chip, not waits */
	held = t0 = ktime_get();
	/*
	 * Too far behind (a slow host, or one the budget holds back) or
	 * ahead (fb_ops ran the DP at once when the FIFO filled): the
	 * core's paced clock starts afresh from here.
	 */
	target = rdc_pace_target(&chip->pace, ktime_to_ns(t0), rdc_hw_now(hw),
				 rdc_hw_core_hz(hw), lag);
	while (rdc_hw_now(hw) < target && !chip->dying) {
		u64 stop = min_t(u64, target,
				 rdc_hw_now(hw) + RDC_KCHIP_RUN_SLICE);
		u64 edge = rdc_kchip_next_te_locked(chip);

		/* a TE edge goes out before the time after it is simulated */
		if (edge > rdc_hw_now(hw) && edge < stop)
			stop = edge;
		rdc_hw_run_until(hw, stop);
		rdc_kchip_irq_check_locked(chip);
		spent += ktime_to_ns(ktime_sub(ktime_get(), held));
		rdc_kchip_unlock(chip);
		wake_up_all(&chip->waitq);
		/* no detour: cancel_work_sync in rdc_kchip_stop keeps gpio */
		rdc_kgpio_deliver_now(chip->gpio);
		cond_resched();
		rdc_kchip_lock(chip);
		held = ktime_get();
	}
	rdc_kchip_update_period(chip);
	/*
	 * The CPU budget: after work that held the chip for `spent`, the
	 * next tick waits at least spent * (100 - budget) / budget (a wait
	 * for the lock, an upload holding it, is not the work's), so that
	 * pacing never
	 * runs back to back and takes at most cpu_budget per cent of a CPU;
	 * a host that cannot keep up lets simulated time fall behind.
	 */
	spent += ktime_to_ns(ktime_sub(ktime_get(), held));
	rest = ktime_add_ns(ktime_get(),
			    div_u64(spent * (100 - chip->cpu_budget),
				    chip->cpu_budget));
	next = rdc_kchip_next_tick_locked(chip);
	if (ktime_before(next, rest)) {
		next = rest;
		chip->throttled++;
	}
	/* rdc_kchip_stop sets dying under the lock, then cancels the timer */
	if (!chip->dying)
		hrtimer_start(&chip->timer, next, HRTIMER_MODE_ABS);
	rdc_kchip_unlock(chip);
	wake_up_all(&chip->waitq);
}

/* One-shot: the pacing work arms the next tick when it is done. */
static enum hrtimer_restart rdc_kchip_tick(struct hrtimer *t)
{
	struct rdc_kchip *chip = container_of(t, struct rdc_kchip, timer);

	if (!READ_ONCE(chip->dying))
		queue_work(system_highpri_wq, &chip->pace_work);
	return HRTIMER_NORESTART;
}

int rdc_kchip_init(struct rdc_kchip *chip, struct device *dev,
		   const struct rdc_kchip_params *p)
{
	struct rdc_hw_config cfg = { .vram_size = p->vram_bytes };
	u32 vram_size = p->vram_bytes;

	mutex_init(&chip->lock);
	init_waitqueue_head(&chip->waitq);
	mutex_init(&chip->snap_lock);
	INIT_WORK(&chip->pace_work, rdc_kchip_pace_work);
	hrtimer_init(&chip->timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	chip->timer.function = rdc_kchip_tick;
	chip->dev = dev;
	chip->stepped = p->stepped;
	chip->on_demand = p->on_demand;
	chip->cpu_budget = p->cpu_budget ? p->cpu_budget : 100;
	chip->up_at = ktime_get_ns();

	chip->vram = vmalloc_user(vram_size);
	chip->hw = vzalloc(rdc_hw_size());
	chip->dp = vzalloc(rdc_dp_size());
	chip->frame[0] = vzalloc(array_size(RDC_KCHIP_FRAME_CAP, sizeof(u32)));
	chip->frame[1] = vzalloc(array_size(RDC_KCHIP_FRAME_CAP, sizeof(u32)));
	chip->snap = vzalloc(array_size(RDC_KCHIP_FRAME_CAP, sizeof(u32)));
	if (!chip->vram || !chip->hw || !chip->dp || !chip->frame[0] ||
	    !chip->frame[1] || !chip->snap) {
		rdc_kchip_free(chip);
		return -ENOMEM;
	}
	rdc_hw_init(chip->hw, &cfg, chip->vram, chip->frame[0], chip->frame[1],
		    RDC_KCHIP_FRAME_CAP);
	rdc_dp_init(chip->dp, chip->hw);
	/* a frame is converted only while something looks (each module) */
	rdc_hw_set_on_demand(chip->hw, p->on_demand);
	rdc_hw_set_trace(chip->hw, rdc_kchip_trace, chip);
	rdc_kchip_update_period(chip);
	return 0;
}

void rdc_kchip_start(struct rdc_kchip *chip)
{
	if (chip->stepped)
		return;
	chip->pace = (struct rdc_pace){ .wall0_ns = ktime_get_ns(),
					.sim0 = rdc_hw_now(chip->hw) };
	hrtimer_start(&chip->timer, ns_to_ktime(chip->period_ns),
		      HRTIMER_MODE_REL);
}

/* Stop the clock and end every wait; the chip itself stays until free. */
void rdc_kchip_stop(struct rdc_kchip *chip)
{
	rdc_kchip_lock(chip);
	WRITE_ONCE(chip->dying, true);
	rdc_kchip_unlock(chip);
	hrtimer_cancel(&chip->timer);
	cancel_work_sync(&chip->pace_work);
	wake_up_all(&chip->waitq);
}

/* Nothing uses the chip any more (the module's device is unregistered). */
void rdc_kchip_free(struct rdc_kchip *chip)
{
	vfree(chip->snap);
	vfree(chip->frame[1]);
	vfree(chip->frame[0]);
	vfree(chip->dp);
	vfree(chip->hw);
	vfree(chip->vram);
	chip->snap = NULL;
	chip->frame[0] = NULL;
	chip->frame[1] = NULL;
	chip->dp = NULL;
	chip->hw = NULL;
	chip->vram = NULL;
}

/* RESET_N and BL_EN as the host drives them. */
u32 rdc_kchip_pins_in(struct rdc_kchip *chip)
{
	struct rdc_hw_state st;

	rdc_kchip_lock(chip);
	rdc_hw_state(chip->hw, &st);
	rdc_kchip_unlock(chip);
	return st.pins_in;
}

/* Drive one of the chip's input pins (the GPIO lines RESET_N and BL_EN). */
void rdc_kchip_set_pin(struct rdc_kchip *chip, u32 pin, bool high)
{
	struct rdc_hw *hw = chip->hw;
	struct rdc_hw_state st;
	u32 pins;

	rdc_kchip_lock(chip);
	rdc_hw_state(hw, &st);
	pins = high ? st.pins_in | pin : st.pins_in & ~pin;
	if (pins != st.pins_in) {
		rdc_hw_set_pins(hw, pins);
		/* RESET_N resets the DP's state behind fb_ops' back */
		chip->state_gen++;
		rdc_kchip_irq_check_locked(chip);
		if (!chip->stepped)
			rdc_kchip_update_period(chip);
	}
	rdc_kchip_unlock(chip);
	wake_up_all(&chip->waitq);
}

u32 rdc_kchip_reg_read(struct rdc_kchip *chip, u32 reg)
{
	u32 v;

	rdc_kchip_lock(chip);
	v = rdc_hw_read(chip->hw, reg);
	rdc_kchip_unlock(chip);
	return v;
}

void rdc_kchip_reg_write(struct rdc_kchip *chip, u32 reg, u32 val)
{
	rdc_kchip_lock(chip);
	rdc_hw_write(chip->hw, reg, val);
	/* CONTROL (reset), FIFO_DATA: the DP's state may no longer be ours */
	chip->state_gen++;
	rdc_kchip_irq_check_locked(chip);
	if (!chip->stepped)
		rdc_kchip_update_period(chip);
	rdc_kchip_unlock(chip);
}

/* ---- Waits --------------------------------------------------------------- */

/* The ioctl's wait as the core's (hw-sim/wait.c) */
static void rdc_kchip_wait_conv(const struct rdcfb_wait *w, u64 budget,
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
 * A wait's result (hw-sim/wait.c) as the ioctls' errno, the one mapping
 * of both modules: 0 a term holds, -EIO the DP halted (a needs-DP wait),
 * -ETIMEDOUT the budget is spent, 1 not yet.
 */
static int rdc_kchip_wait_errno(enum rdc_hw_wait_result r)
{
	switch (r) {
	case RDC_HW_WAIT_DONE:
		return 0;
	case RDC_HW_WAIT_MORE:
		return 1;
	case RDC_HW_WAIT_HALTED:
		return -EIO;
	default:
		return -ETIMEDOUT;
	}
}

/* One look at a paced wait's condition, with the lock held. */
static int rdc_kchip_wait_check(struct rdc_kchip *chip,
				const struct rdc_hw_wait *w)
{
	return rdc_kchip_wait_errno(rdc_hw_wait_check(chip->hw, w));
}

/*
 * Between two pieces of a long run of the chip: drop the lock and give way.
 * 0 with the lock taken again, or -EINTR (a fatal signal) or -ENODEV (the
 * device is going) with it dropped.
 */
static int rdc_kchip_pause(struct rdc_kchip *chip)
{
	rdc_kchip_unlock(chip);
	if (fatal_signal_pending(current))
		return -EINTR;
	if (READ_ONCE(chip->dying))
		return -ENODEV;
	cond_resched();
	rdc_kchip_lock(chip);
	return 0;
}

/*
 * Stepped: the core's wait, run in pieces of RDC_KCHIP_RUN_SLICE cycles with
 * the lock dropped between them (which never changes where it ends).
 */
static int rdc_kchip_wait_stepped(struct rdc_kchip *chip, struct rdc_hw_wait *w)
{
	struct rdc_hw *hw = chip->hw;
	enum rdc_hw_wait_result res;
	int err;

	rdc_kchip_lock(chip);
	rdc_hw_wait_begin(hw, w);
	for (;;) {
		res = rdc_hw_wait_run(hw, w, RDC_KCHIP_RUN_SLICE);
		rdc_kchip_irq_check_locked(chip);
		if (res != RDC_HW_WAIT_MORE)
			break;
		err = rdc_kchip_pause(chip);
		if (err)
			return err;
	}
	rdc_kchip_unlock(chip);
	wake_up_all(&chip->waitq);
	return rdc_kchip_wait_errno(res);
}

/*
 * Paced: sleep until the pacing work has moved time, and look again.
 * SUBMIT's waits for FIFO room take only fatal signals: words of the
 * buffer are in the FIFO already, and a restarted ioctl would queue them
 * twice.
 */
static int rdc_kchip_wait_paced(struct rdc_kchip *chip, struct rdc_hw_wait *w,
				u32 timeout_ms, bool interruptible)
{
	unsigned long deadline =
		jiffies + msecs_to_jiffies(timeout_ms ?
						   timeout_ms :
						   RDC_KCHIP_WAIT_TIMEOUT_MS);
	u64 seen;
	long left;
	int ret;

	rdc_kchip_lock(chip);
	rdc_hw_wait_begin(chip->hw, w);
	rdc_kchip_unlock(chip);
	for (;;) {
		rdc_kchip_lock(chip);
		seen = rdc_hw_now(chip->hw);
		ret = rdc_kchip_wait_check(chip, w);
		rdc_kchip_unlock(chip);
		if (ret <= 0)
			return ret;
		left = (long)(deadline - jiffies);
		if (left <= 0)
			return -ETIMEDOUT;
		if (interruptible)
			left = wait_event_interruptible_timeout(
				chip->waitq,
				rdc_hw_now(chip->hw) != seen ||
					READ_ONCE(chip->dying),
				left);
		else
			left = wait_event_killable_timeout(
				chip->waitq,
				rdc_hw_now(chip->hw) != seen ||
					READ_ONCE(chip->dying),
				left);
		if (left < 0)
			return left;
		if (READ_ONCE(chip->dying))
			return -ENODEV;
	}
}

static int rdc_kchip_wait_sig(struct rdc_kchip *chip,
			      const struct rdcfb_wait *w, bool interruptible)
{
	u64 budget = w->budget ? w->budget :
				 (u64)RDC_KCHIP_WAIT_BUDGET_S *
					 rdc_hw_core_hz(chip->hw);
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
	rdc_kchip_wait_conv(w, budget, &hw_w);
	return chip->stepped ? rdc_kchip_wait_stepped(chip, &hw_w) :
			       rdc_kchip_wait_paced(chip, &hw_w, w->timeout_ms,
						    interruptible);
}

int rdc_kchip_wait(struct rdc_kchip *chip, const struct rdcfb_wait *w)
{
	return rdc_kchip_wait_sig(chip, w, true);
}

int rdc_kchip_step(struct rdc_kchip *chip, u64 cycles)
{
	struct rdc_hw *hw = chip->hw;
	u64 end;
	int err;

	if (cycles > RDCFB_MAX_CYCLES)
		return -EINVAL;
	if (!chip->stepped)
		return -EPERM;
	rdc_kchip_lock(chip);
	if (cycles > U64_MAX - rdc_hw_now(hw)) {
		rdc_kchip_unlock(chip);
		return -ERANGE;
	}
	end = rdc_hw_now(hw) + cycles;
	/*
	 * In pieces, so one STEP never holds the lock for long; the chip
	 * gives the same result run in pieces as in one go.
	 */
	while (rdc_hw_now(hw) < end) {
		rdc_hw_run_until(hw,
				 min_t(u64, end,
				       rdc_hw_now(hw) + RDC_KCHIP_RUN_SLICE));
		rdc_kchip_irq_check_locked(chip);
		err = rdc_kchip_pause(chip);
		if (err)
			return err;
	}
	rdc_kchip_unlock(chip);
	wake_up_all(&chip->waitq);
	return 0;
}

int rdc_kchip_vsync(struct rdc_kchip *chip)
{
	struct rdcfb_wait w = {
		.term[0] = { .kind = RDCFB_WAIT_WRAP_GE,
			     .reg = RDC_REG_FRAME_COUNT,
			     .mask = ~0u },
		.timeout_ms = RDC_KCHIP_VSYNC_TIMEOUT_MS,
	};
	struct rdc_hw *hw = chip->hw;
	u64 next;

	rdc_kchip_lock(chip);
	next = rdc_hw_next_vblank(hw);
	w.term[0].value = rdc_hw_read(hw, RDC_REG_FRAME_COUNT) + 1;
	/* the budget reaches just past the next vblank */
	w.budget = next - rdc_hw_now(hw) + 1;
	rdc_kchip_unlock(chip);
	if (next == RDC_NEVER)
		return -ETIMEDOUT;
	return rdc_kchip_wait(chip, &w);
}

/* ---- Submission ---------------------------------------------------------- */

/*
 * Push validated words into the FIFO as librdc's core does for a backend
 * without a submit op: as many as FIFO_FREE says (in bulk, which is the
 * same as FIFO_DATA writes of each, at half the CPU), then wait (a
 * needs-DP wait) for half a FIFO.  The words of one SUBMIT go in under the lock in
 * runs, so fb_ops (which see chip->submitting) keep out of the middle of
 * a command.
 */
int rdc_kchip_submit(struct rdc_kchip *chip, const u32 *words, u32 n)
{
	struct rdc_hw *hw = chip->hw;
	u32 free_words, taken;
	int ret = 0;

	while (n) {
		rdc_kchip_lock(chip);
		chip->state_gen++;
		free_words = rdc_hw_read(hw, RDC_REG_FIFO_FREE);
		taken = rdc_hw_fifo_push(hw, words, min(n, free_words));
		words += taken;
		n -= taken;
		chip->submitting = n != 0;
		rdc_kchip_unlock(chip);
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

			ret = rdc_kchip_wait_sig(chip, &w, false);
			if (ret)
				break;
		}
	}
	rdc_kchip_lock(chip);
	chip->submitting = false;
	rdc_kchip_unlock(chip);
	return ret;
}

/* ---- fb_ops' side: the queue's records, chip->lock held ------------------ */

/*
 * Can the DP take fb_ops' commands: enabled, not halted, and no client's
 * command half in the FIFO?
 */
bool rdc_kchip_dp_runs_locked(struct rdc_kchip *chip)
{
	struct rdc_hw_state st;

	rdc_hw_state(chip->hw, &st);
	return !st.in_reset && (st.control & RDC_CONTROL_DP_EN) &&
	       !(st.dp_status & RDC_STATUS_DP_HALTED);
}

bool rdc_kchip_dp_usable(struct rdc_kchip *chip)
{
	return !chip->submitting && !chip->dying &&
	       rdc_kchip_dp_runs_locked(chip);
}

/*
 * Queue words; when the FIFO is full, run the DP for a bounded slice as a
 * driver would poll FIFO_FREE, giving way between slices (the lock is a
 * mutex, so none of this holds interrupts off).  The caller checked
 * rdc_kchip_dp_usable.
 */
int rdc_kchip_push_locked(struct rdc_kchip *chip, const u32 *words, u32 n)
{
	struct rdc_hw *hw = chip->hw;
	unsigned int tries = 0;
	u32 free_words;

	while (n) {
		free_words = rdc_hw_read(hw, RDC_REG_FIFO_FREE);
		if (!free_words) {
			if (++tries > RDC_KCHIP_SYNC_TRIES ||
			    !rdc_kchip_dp_runs_locked(chip))
				return -ETIMEDOUT;
			rdc_hw_run_until_idle(hw, rdc_hw_now(hw) +
							  RDC_KCHIP_SYNC_SLICE);
			rdc_kchip_irq_check_locked(chip);
			cond_resched();
			continue;
		}
		free_words = rdc_hw_fifo_push(hw, words, min(n, free_words));
		words += free_words;
		n -= free_words;
	}
	return 0;
}

/* Run the DP until it has nothing left it can do (bounded). */
void rdc_kchip_drain_locked(struct rdc_kchip *chip)
{
	struct rdc_hw *hw = chip->hw;
	unsigned int tries;

	for (tries = 0; tries < RDC_KCHIP_SYNC_TRIES; tries++) {
		if (rdc_hw_run_until_idle(hw, rdc_hw_now(hw) +
						      RDC_KCHIP_SYNC_SLICE))
			break;
		cond_resched();
	}
	rdc_kchip_irq_check_locked(chip);
}

/* sysfs scanout: "always", or "demand" and whether anything looks now. */
ssize_t rdc_kchip_scanout_show(struct rdc_kchip *chip, char *buf)
{
	bool on, watched;

	rdc_kchip_lock(chip);
	on = chip->on_demand;
	watched = rdc_hw_scanout_watched(chip->hw);
	rdc_kchip_unlock(chip);
	return sysfs_emit(buf, "%s\n",
			  !on	  ? "always" :
			  watched ? "demand watched" :
				    "demand idle");
}

/* ---- Counters and frames ------------------------------------------------- */

void rdc_kchip_counters(struct rdc_kchip *chip, struct rdc_kchip_counters *c)
{
	struct rdc_hw_state st;
	struct rdc_perf perf;

	rdc_kchip_lock(chip);
	rdc_hw_perf(chip->hw, &perf);
	rdc_hw_state(chip->hw, &st);
	c->now = rdc_hw_now(chip->hw);
	c->busy = perf.busy;
	c->stall = perf.stall;
	c->pixels = perf.pixels;
	c->cmds = perf.cmds;
	c->last_cycles = perf.last_cycles;
	c->last_opcode = perf.last_opcode;
	c->fence = st.fence;
	c->frames = chip->frames;
	c->host_busy_ns = chip->busy_ns + (ktime_get_ns() - chip->held_at);
	c->host_up_ns = ktime_get_ns() - chip->up_at;
	c->throttled = chip->throttled;
	rdc_kchip_unlock(chip);
}

/* zlib's CRC-32 of the pixels as little-endian bytes. */
u32 rdc_kchip_crc(const u32 *px, size_t count)
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
 * between pieces all the same.  Returns 0, or -EAGAIN with no frame yet
 * (before the first, or none kept by scanout on demand: then the next
 * whole frame is).
 */
int rdc_kchip_snapshot(struct rdc_kchip *chip)
{
	unsigned int tries;
	const u32 *f;
	u32 w, h;
	size_t bytes, off;
	u64 seq;

	lockdep_assert_held(&chip->snap_lock);
	for (tries = 0; tries < RDC_KCHIP_SNAP_TRIES; tries++) {
		rdc_kchip_lock(chip);
		f = rdc_hw_frame(chip->hw, &w, &h);
		seq = chip->frames;
		/*
		 * A look that finds no frame (scanout on demand kept none:
		 * nobody looked while the picture changed) attaches a
		 * consumer, so that the caller's retry after the next vblank
		 * finds the frame scanned whole; it stays while grabs come,
		 * and goes RDC_KCHIP_GRAB_HOLD_FRAMES frames after the last.
		 */
		chip->grab_at = chip->frames;
		if (!f && !chip->grab_watch) {
			rdc_hw_consumer_attach(chip->hw);
			chip->grab_watch = true;
		}
		if (!f) {
			rdc_kchip_unlock(chip);
			chip->snap_seq = 0;
			return -EAGAIN;
		}
		if (seq == chip->snap_seq && w == chip->snap_w &&
		    h == chip->snap_h) {
			rdc_kchip_unlock(chip);
			return 0;
		}
		bytes = (size_t)w * h * sizeof(u32);
		for (off = 0; off < bytes; off += RDC_KCHIP_SNAP_CHUNK) {
			size_t len = min_t(size_t, RDC_KCHIP_SNAP_CHUNK,
					   bytes - off);

			memcpy((u8 *)chip->snap + off, (const u8 *)f + off,
			       len);
			if (tries + 1 == RDC_KCHIP_SNAP_TRIES) {
				cond_resched();
				continue;
			}
			rdc_kchip_unlock(chip);
			cond_resched();
			rdc_kchip_lock(chip);
			if (chip->frames != seq)
				break;
		}
		if (chip->frames == seq) {
			rdc_kchip_unlock(chip);
			chip->snap_seq = seq;
			chip->snap_w = w;
			chip->snap_h = h;
			chip->snap_crc =
				rdc_kchip_crc(chip->snap, (size_t)w * h);
			return 0;
		}
		rdc_kchip_unlock(chip);
	}
	return -EAGAIN;
}

/* What the STATE ioctls answer: the chip's run beyond its registers. */
void rdc_kchip_state_get(struct rdc_kchip *chip, struct rdc_chip_state *st)
{
	struct rdc_hw_resume r;

	rdc_kchip_lock(chip);
	rdc_hw_resume_get(chip->hw, &r);
	rdc_kchip_unlock(chip);
	memset(st, 0, sizeof(*st));
	st->now = r.now;
	st->frame_start = r.frame_start;
	st->frame_count = r.frame_count;
	st->busy = r.perf.busy;
	st->stall = r.perf.stall;
	st->pixels = r.perf.pixels;
	st->cmds = r.perf.cmds;
	st->last_cycles = r.perf.last_cycles;
	st->last_opcode = r.perf.last_opcode;
	st->culled = r.perf.culled;
	st->fence = r.fence;
	st->irq_status = r.irq_status;
	st->err_code = r.err_code;
	st->err_info = r.err_info;
	st->open_row = r.open_row;
	st->h_total = r.timing.h_total;
	st->h_display = r.timing.h_display;
	st->h_sync_start = r.timing.h_sync_start;
	st->h_sync_end = r.timing.h_sync_end;
	st->v_total = r.timing.v_total;
	st->v_display = r.timing.v_display;
	st->v_sync_start = r.timing.v_sync_start;
	st->v_sync_end = r.timing.v_sync_end;
	st->pixclk_khz = r.timing.pixclk_khz;
	st->crtc_flags = r.timing.flags;
	st->fb_base = r.fb_base;
	st->fb_stride = r.fb_stride;
	st->fb_format = r.fb_format;
	st->cursor_ctrl = r.cursor_ctrl;
	st->cursor_base = r.cursor_base;
	st->raster_base = r.raster_base;
	st->raster_ctrl = r.raster_ctrl;
	st->flags = (r.scanning ? RDC_CHIP_STATE_SCANNING : 0) |
		    (r.dp_active ? RDC_CHIP_STATE_DP_ACTIVE : 0) |
		    (r.gamma ? RDC_CHIP_STATE_GAMMA : 0);
}
