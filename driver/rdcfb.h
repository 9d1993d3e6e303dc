/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcfb: the RDC-1 (hw-sim + firmware-model, compiled in unchanged) as a
 * Linux framebuffer device.  Internal interfaces between the driver's files.
 *
 * Locking: chip->lock (a mutex) guards the simulated chip and every field
 * below marked "lock": the simulation runs in process context, with
 * interrupts on, and gives way between slices.  fbcon calls the drawing
 * fb_ops in atomic context too (kernel messages are printed with
 * interrupts off), so those never take it: they put their work on the
 * fb-op queue (opq.lock, a spinlock held for one bounded record), which
 * whoever takes chip->lock next applies in order, the queue's worker if
 * nobody else.  snap_lock (a mutex) guards the frame snapshot that FRAME
 * and sysfs copy out of.
 */
#ifndef RDCFB_H
#define RDCFB_H

#include <linux/atomic.h>
#include <linux/fb.h>
#include <linux/hrtimer.h>
#include <linux/mutex.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include <linux/timekeeping.h>
#include <linux/wait.h>
#include <linux/workqueue.h>

#include "hw.h"
#include "dp.h"
#include "rdcfb_ioctl.h"
#include "rdcfb_validate.h"

#define RDCFB_NAME	  "rdcfb"
#define RDCFB_MAX_DEVICES 8

/* Every mode the CRTC can show fits the frame buffers (as sim:'s). */
#define RDCFB_FRAME_CAP ((u32)RDC_CRTC_MAX_DISPLAY * RDC_CRTC_MAX_DISPLAY)

/*
 * The fb-op queue: 1 MiB of records (a power of two, in words); a record
 * is a header and at most one DP command's data words.
 */
#define RDCFB_OPQ_WORDS	   (1u << 18)
#define RDCFB_OP_HDR_WORDS 16u
#define RDCFB_OP_MAX_WORDS (RDCFB_OP_HDR_WORDS + RDC_CMD_MAX_ARGS)

/* The pseudo palette fbcon's truecolor colours index. */
#define RDCFB_PSEUDO_COLOURS 16

struct rdcfb_gpio;

/* What the GPIO lines' deliverer counted (sysfs pin_*). */
struct rdcfb_pin_stats {
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
#define RDCFB_IRQOFF_BUCKETS 16

struct rdcfb_irqoff {
	atomic64_t max_ns;
	unsigned long max_at; /* the code that ended that section */
	atomic64_t hist[RDCFB_IRQOFF_BUCKETS];
};

static inline u64 rdcfb_irqoff_begin(void)
{
	return ktime_get_mono_fast_ns();
}

void rdcfb_irqoff_end(struct rdcfb_irqoff *st, u64 t0, unsigned long at);
void rdcfb_irqoff_reset(struct rdcfb_irqoff *st);

/* An irqsave spinlock whose holds are timed: t0 is the lock's own field. */
#define rdcfb_spin_lock(lock, flags, t0) \
	do { \
		spin_lock_irqsave(lock, flags); \
		(t0) = rdcfb_irqoff_begin(); \
	} while (0)
#define rdcfb_spin_unlock(lock, flags, t0, st) \
	do { \
		rdcfb_irqoff_end(st, t0, _THIS_IP_); \
		spin_unlock_irqrestore(lock, flags); \
	} while (0)

/*
 * fb_ops' work on its way to the chip: records (struct rdcfb_op and its
 * data words) in a ring of words, applied in order under chip->lock.
 */
struct rdcfb_opq {
	spinlock_t lock;
	u64 t0;		 /* lock: when it was taken */
	u32 *ring;	 /* RDCFB_OPQ_WORDS */
	u32 head, count; /* lock: in words */
	u64 dropped;	 /* lock: records refused at a full queue */
	u32 *buf;	 /* chip->lock: the record being applied */
	struct work_struct work;
};

struct rdcfb_chip {
	struct mutex lock;
	struct rdcfb_irqoff irqoff;
	struct rdcfb_opq opq;
	struct fb_info *info; /* whose fb_ops fill opq */
	struct rdc_hw hw;     /* lock */
	struct rdc_dp *dp;    /* lock; large, so vmalloc'ed */
	u8 *vram;	      /* vmalloc_user: mapped to user space as is */
	u32 *frame[2];
	struct device *dev;

	bool stepped;	 /* clock=stepped: time moves only in WAIT/STEP */
	bool dying;	 /* the device is going away: waits end with -ENODEV */
	bool submitting; /* lock: a SUBMIT has words still to push */

	/* paced clock: hw.now follows wall time from these */
	struct hrtimer timer;
	struct work_struct pace_work;
	ktime_t wall_base; /* lock */
	u64 sim_base;	   /* lock */
	u64 period_ns;

	wait_queue_head_t waitq; /* woken whenever simulated time moved */
	u64 frames;		 /* lock: frames completed since load */
	u64 irqs;		 /* lock: rising edges of the IRQ pin */
	bool irq_level;		 /* lock */
	/* lock: bumped by anything that may change the DP's drawing state
	 * behind fb_ops' back
	 */
	u32 fb_state_gen;
	struct rdcfb_gpio *gpio; /* lock: the pins as GPIO lines, or NULL */

	struct mutex snap_lock;
	u32 *snap; /* a copy of the latest frame, snap_lock */
	u64 snap_seq;
	u32 snap_w, snap_h, snap_crc;
};

struct rdcfb_par {
	struct rdcfb_chip *chip;
	struct platform_device *pdev;
	u32 pseudo_palette[RDCFB_PSEUDO_COLOURS];
	u32 fmt; /* enum rdc_format of the current var */
	u32 stride;
	/* chip->lock: the surface fb ops last set DST/SRC/CLIP to, and when */
	u32 dp_fmt, dp_stride, dp_wh;
	u32 state_gen; /* chip->fb_state_gen then */
	bool state_valid;
	struct dentry *debugfs;
};

/* rdcfb_chip.c */
void rdcfb_chip_lock(struct rdcfb_chip *chip);
void rdcfb_chip_unlock(struct rdcfb_chip *chip);
int rdcfb_chip_init(struct rdcfb_chip *chip, struct device *dev, u32 vram_size,
		    bool stepped);
void rdcfb_chip_start(struct rdcfb_chip *chip);
void rdcfb_chip_stop(struct rdcfb_chip *chip);
void rdcfb_chip_free(struct rdcfb_chip *chip);
u32 rdcfb_reg_read(struct rdcfb_chip *chip, u32 reg);
void rdcfb_reg_write(struct rdcfb_chip *chip, u32 reg, u32 val);
int rdcfb_chip_wait(struct rdcfb_chip *chip, const struct rdcfb_wait *w);
int rdcfb_chip_step(struct rdcfb_chip *chip, u64 cycles);
int rdcfb_chip_submit(struct rdcfb_chip *chip, const u32 *words, u32 n);
int rdcfb_chip_vsync(struct rdcfb_chip *chip);
void rdcfb_chip_counters(struct rdcfb_chip *chip, struct rdcfb_counters *c);
int rdcfb_chip_snapshot(struct rdcfb_chip *chip);
/* For the fb-op queue's records, with chip->lock held. */
bool rdcfb_dp_usable(struct rdcfb_chip *chip);
int rdcfb_push_locked(struct rdcfb_chip *chip, const u32 *words, u32 n);
void rdcfb_drain_locked(struct rdcfb_chip *chip);
void rdcfb_irq_check_locked(struct rdcfb_chip *chip);
u32 rdcfb_chip_pins_in(struct rdcfb_chip *chip);
void rdcfb_chip_set_pin(struct rdcfb_chip *chip, u32 pin, bool high);

/* rdcfb_gpio.c: without GPIOLIB_IRQCHIP the device has no GPIO lines */
#if IS_ENABLED(CONFIG_GPIOLIB_IRQCHIP)
int rdcfb_gpio_register(struct rdcfb_chip *chip, struct device *dev, int id);
void rdcfb_gpio_unregister(struct rdcfb_chip *chip);
void rdcfb_gpio_event_locked(struct rdcfb_gpio *g, ktime_t wall, u32 levels);
void rdcfb_gpio_deliver_now(struct rdcfb_gpio *g);
void rdcfb_gpio_stats(struct rdcfb_gpio *g, struct rdcfb_pin_stats *s);
void rdcfb_gpio_module_exit(void);
#else
static inline int rdcfb_gpio_register(struct rdcfb_chip *chip,
				      struct device *dev, int id)
{
	return -ENODEV;
}

static inline void rdcfb_gpio_unregister(struct rdcfb_chip *chip)
{
}
static inline void rdcfb_gpio_event_locked(struct rdcfb_gpio *g, ktime_t wall,
					   u32 levels)
{
}
static inline void rdcfb_gpio_deliver_now(struct rdcfb_gpio *g)
{
}
static inline void rdcfb_gpio_stats(struct rdcfb_gpio *g,
				    struct rdcfb_pin_stats *s)
{
	memset(s, 0, sizeof(*s));
}

static inline void rdcfb_gpio_module_exit(void)
{
}
#endif

/* rdcfb_fb.c */
extern const struct fb_ops rdcfb_ops;
int rdcfb_fb_setup(struct fb_info *info, const char *mode);
void rdcfb_fill(struct fb_info *info, const struct fb_fillrect *r);
void rdcfb_copy(struct fb_info *info, const struct fb_copyarea *a);
void rdcfb_blit(struct fb_info *info, const struct fb_image *img);
int rdcfb_sync(struct fb_info *info);
void rdcfb_ops_apply_locked(struct rdcfb_chip *chip);
u64 rdcfb_ops_dropped(struct rdcfb_chip *chip);

/* rdcfb_bench.c */
void rdcfb_bench_init(struct fb_info *info);
void rdcfb_bench_exit(struct fb_info *info);
void rdcfb_bench_module_init(void);
void rdcfb_bench_module_exit(void);

#endif /* RDCFB_H */
