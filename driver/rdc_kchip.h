/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The kernel's chip host: one simulated RDC-1 (hw-sim + firmware-model,
 * compiled in unchanged) with its VRAM, its clocks, waits, the command
 * FIFO, interrupts, frames and pins, as rdcfb.ko and rdcdrm.ko both use
 * it (rdc_kchip.c, rdc_kgpio.c).  Each module hangs its own device off
 * it and sets the hooks below; no policy of the host is written twice.
 *
 * Locking: chip->lock (a mutex) guards the simulated chip and every field
 * below marked "lock": the simulation runs in process context, with
 * interrupts on, and gives way between slices.  snap_lock (a mutex)
 * guards the frame snapshot that FRAME and sysfs copy out of.
 */
#ifndef RDC_KCHIP_H
#define RDC_KCHIP_H

#include <linux/atomic.h>
#include <linux/device.h>
#include <linux/hrtimer.h>
#include <linux/mutex.h>
#include <linux/spinlock.h>
#include <linux/timekeeping.h>
#include <linux/wait.h>
#include <linux/workqueue.h>

#include "rdc_chip.h"
#include "rdc_dp_host.h"
#include "rdc_base.h"
#include "rdc_regs.h"
#include "rdcfb_ioctl.h"
#include "rdcfb_validate.h"

/* Every mode the CRTC can show fits the frame buffers (as sim:'s). */
#define RDC_KCHIP_FRAME_CAP ((u32)RDC_CRTC_MAX_DISPLAY * RDC_CRTC_MAX_DISPLAY)

struct rdc_kgpio;
struct rdc_kchip;

/* What the GPIO lines' deliverer counted (sysfs pin_*). */
struct rdc_kchip_pin_stats {
	u64 edges;		      /* TE and IRQ edges delivered */
	u64 lost;		      /* dropped at a full queue */
	u64 late_max_ns, late_avg_ns; /* delivery after the edge (paced) */
};

/*
 * The sections the driver ran with interrupts off, timed around every hold
 * of an irqsave spinlock: the longest (sysfs irqs_off_max_ns,
 * irqs_off_max_at) and how many took how long (debugfs irqs_off: bucket 0
 * under 1 us, bucket k from 2^(k-1) us, the last one open-ended).
 */
#define RDC_KCHIP_IRQOFF_BUCKETS 16

struct rdc_kchip_irqoff {
	atomic64_t max_ns;
	unsigned long max_at; /* the code that ended that section */
	atomic64_t hist[RDC_KCHIP_IRQOFF_BUCKETS];
};

static inline u64 rdc_kchip_irqoff_begin(void)
{
	return ktime_get_mono_fast_ns();
}

void rdc_kchip_irqoff_end(struct rdc_kchip_irqoff *st, u64 t0,
			  unsigned long at);
void rdc_kchip_irqoff_reset(struct rdc_kchip_irqoff *st);

/* An irqsave spinlock whose holds are timed: t0 is the lock's own field. */
#define rdc_kchip_spin_lock(lock, flags, t0) \
	do { \
		spin_lock_irqsave(lock, flags); \
		(t0) = rdc_kchip_irqoff_begin(); \
	} while (0)
#define rdc_kchip_spin_unlock(lock, flags, t0, st) \
	do { \
		rdc_kchip_irqoff_end(st, t0, _THIS_IP_); \
		spin_unlock_irqrestore(lock, flags); \
	} while (0)

/*
 * What a module hooks into the host; both optional, both called with
 * chip->lock held.
 *  - before_use: at every taking of the lock, before the taker does
 *    anything (rdcfb applies its fb-op queue there).
 *  - vblank: at every vertical blank, inside the simulation, in time
 *    order: `frame` counts frames since load (the COUNTERS frames after
 *    it), `sim` is the simulated time of the vblank and `wall` the wall
 *    time the paced clock maps it to (the time of the call when stepped).
 *    A catch-up that runs several frames calls it once for each.
 */
struct rdc_kchip_hooks {
	void (*before_use)(struct rdc_kchip *chip);
	void (*vblank)(struct rdc_kchip *chip, u64 frame, u64 sim,
		       ktime_t wall);
};

/* The performance counters and the clock, as both modules report them. */
struct rdc_kchip_counters {
	u64 now, busy, stall, pixels;
	u32 cmds, last_cycles, last_opcode, fence;
	u64 frames;
	/* wall time the host held the chip, and since init (sysfs host_*) */
	u64 host_busy_ns, host_up_ns;
	u64 throttled; /* pacing ticks the CPU budget put off */
};

struct rdc_kchip {
	struct mutex lock;
	struct rdc_kchip_irqoff irqoff;
	const struct rdc_kchip_hooks *hooks;
	struct rdc_hw *hw; /* lock; rdc_hw_size() bytes */
	struct rdc_dp *dp; /* lock; rdc_dp_size() bytes, vmalloc'ed */
	u8 *vram;	   /* vmalloc_user: mapped to user space as is */
	u32 *frame[2];
	struct device *dev;

	bool stepped;	 /* clock=stepped: time moves only in WAIT/STEP */
	bool on_demand;	 /* scanout=demand */
	bool grab_watch; /* lock: a snapshot found no frame, consumer held */
	u64 grab_at;	 /* lock: chip->frames at the last snapshot */
	bool dying;	 /* the device is going away: waits end with -ENODEV */
	bool submitting; /* lock: a SUBMIT has words still to push */

	/* paced clock: hw.now follows wall time from these */
	struct hrtimer timer;
	struct work_struct pace_work;
	struct rdc_pace pace; /* lock: simulated time against wall time */
	u32 cpu_budget;	      /* per cent of a CPU the pacing work may take */
	u64 throttled;	      /* lock: ticks the budget put off */
	u64 period_ns;

	wait_queue_head_t waitq; /* woken whenever simulated time moved */
	u64 frames;		 /* lock: frames completed since load */
	u64 irqs;		 /* lock: rising edges of the IRQ pin */
	bool irq_level;		 /* lock */
	/*
	 * lock: bumped by anything that may change the DP's drawing state
	 * behind the module's back (register writes, SUBMIT, RESET_N)
	 */
	u32 state_gen;
	struct rdc_kgpio *gpio; /* lock: the pins as GPIO lines, or NULL */

	/* lock: wall time spent holding the lock, and when it was taken */
	u64 busy_ns, held_at;
	u64 up_at; /* when the chip was made (ktime_get_ns) */

	struct mutex snap_lock;
	u32 *snap; /* a copy of the latest frame, snap_lock */
	u64 snap_seq;
	u32 snap_w, snap_h, snap_crc;
};

/* rdc_kchip.c */
/*
 * The module parameters both drivers take, checked the one way:
 * vram=SIZE (memparse, within [vram_min, vram_max], rounded up to whole
 * pages: mapped pages are handed out whole), clock=paced|stepped,
 * scanout=auto|demand|always, cpu_budget=1..100 and
 * devices=1..max_devices.  -EINVAL, logged under `name`, otherwise.
 */
struct rdc_kchip_params {
	u32 vram_bytes;
	bool stepped;
	bool on_demand; /* scanout=demand (rdc_hw_set_on_demand) */
	u32 cpu_budget; /* per device: cpu_budget / devices, at least 1 */
};

int rdc_kchip_params_parse(const char *name, const char *vram, u32 vram_min,
			   u32 vram_max, const char *clock, const char *scanout,
			   unsigned int cpu_budget, unsigned int devices,
			   unsigned int max_devices,
			   struct rdc_kchip_params *out);

void rdc_kchip_lock(struct rdc_kchip *chip);
void rdc_kchip_unlock(struct rdc_kchip *chip);
int rdc_kchip_init(struct rdc_kchip *chip, struct device *dev,
		   const struct rdc_kchip_params *p);
/* One more (or one fewer) frame consumer: see rdc_hw_set_on_demand. */
void rdc_kchip_consumer(struct rdc_kchip *chip, bool attach);
void rdc_kchip_start(struct rdc_kchip *chip);
void rdc_kchip_stop(struct rdc_kchip *chip);
void rdc_kchip_free(struct rdc_kchip *chip);
u32 rdc_kchip_reg_read(struct rdc_kchip *chip, u32 reg);
void rdc_kchip_reg_write(struct rdc_kchip *chip, u32 reg, u32 val);
int rdc_kchip_wait(struct rdc_kchip *chip, const struct rdcfb_wait *w);
int rdc_kchip_step(struct rdc_kchip *chip, u64 cycles);
int rdc_kchip_submit(struct rdc_kchip *chip, const u32 *words, u32 n);
int rdc_kchip_vsync(struct rdc_kchip *chip);
void rdc_kchip_counters(struct rdc_kchip *chip, struct rdc_kchip_counters *c);
int rdc_kchip_snapshot(struct rdc_kchip *chip);
/* The STATE ioctls' answer (rdc_state_uapi.h), taken under the lock. */
void rdc_kchip_state_get(struct rdc_kchip *chip, struct rdc_chip_state *st);
ssize_t rdc_kchip_scanout_show(struct rdc_kchip *chip, char *buf);
u32 rdc_kchip_crc(const u32 *px, size_t count);
/* With chip->lock held. */
ktime_t rdc_kchip_wall_of_locked(struct rdc_kchip *chip, u64 t);
bool rdc_kchip_dp_usable(struct rdc_kchip *chip);
/* The DP is enabled and not halted. */
bool rdc_kchip_dp_runs_locked(struct rdc_kchip *chip);
int rdc_kchip_push_locked(struct rdc_kchip *chip, const u32 *words, u32 n);
void rdc_kchip_drain_locked(struct rdc_kchip *chip);
void rdc_kchip_irq_check_locked(struct rdc_kchip *chip);
u32 rdc_kchip_pins_in(struct rdc_kchip *chip);
void rdc_kchip_set_pin(struct rdc_kchip *chip, u32 pin, bool high);

/* rdc_kgpio.c: without GPIOLIB_IRQCHIP the device has no GPIO lines */
#if IS_ENABLED(CONFIG_GPIOLIB_IRQCHIP)
int rdc_kgpio_register(struct rdc_kchip *chip, struct device *dev);
void rdc_kgpio_unregister(struct rdc_kchip *chip);
void rdc_kgpio_event_locked(struct rdc_kgpio *g, ktime_t wall, u32 levels);
void rdc_kgpio_deliver_now(struct rdc_kgpio *g);
void rdc_kgpio_stats(struct rdc_kgpio *g, struct rdc_kchip_pin_stats *s);
void rdc_kgpio_module_exit(void);
#else
static inline int rdc_kgpio_register(struct rdc_kchip *chip, struct device *dev)
{
	return -ENODEV;
}

static inline void rdc_kgpio_unregister(struct rdc_kchip *chip)
{
}

static inline void rdc_kgpio_event_locked(struct rdc_kgpio *g, ktime_t wall,
					  u32 levels)
{
}

static inline void rdc_kgpio_deliver_now(struct rdc_kgpio *g)
{
}

static inline void rdc_kgpio_stats(struct rdc_kgpio *g,
				   struct rdc_kchip_pin_stats *s)
{
	memset(s, 0, sizeof(*s));
}

static inline void rdc_kgpio_module_exit(void)
{
}
#endif

#endif /* RDC_KCHIP_H */
