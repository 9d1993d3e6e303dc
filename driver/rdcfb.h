/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcfb: the RDC-1 (hw-sim + firmware-model, compiled in unchanged, on
 * the kernel chip host of rdc_kchip.h) as a Linux framebuffer device.
 * Internal interfaces between the driver's files.
 *
 * Locking: chip->lock (a mutex) guards the simulated chip and the fields
 * below marked "lock".  fbcon calls the drawing fb_ops in atomic context
 * too (kernel messages are printed with interrupts off), so those never
 * take it: they put their work on the fb-op queue (opq.lock, a spinlock
 * held for one bounded record), which whoever takes chip->lock next
 * applies in order (the host's before_use hook), the queue's worker if
 * nobody else.
 */
#ifndef RDCFB_H
#define RDCFB_H

#include <linux/fb.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include <linux/workqueue.h>

#include "rdc_kchip.h"

#define RDCFB_NAME	  "rdcfb"
#define RDCFB_MAX_DEVICES 8

/*
 * The fb-op queue: 1 MiB of records (a power of two, in words); a record
 * is a header and at most one DP command's data words.
 */
#define RDCFB_OPQ_WORDS	   (1u << 18)
#define RDCFB_OP_HDR_WORDS 16u
#define RDCFB_OP_MAX_WORDS (RDCFB_OP_HDR_WORDS + RDC_CMD_MAX_ARGS)

/* The pseudo palette fbcon's truecolor colours index. */
#define RDCFB_PSEUDO_COLOURS 16

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

/* One device: the chip host, and what rdcfb keeps beside it. */
struct rdcfb_dev {
	struct rdc_kchip chip;
	struct rdcfb_opq opq;
	struct fb_info *info; /* whose fb_ops fill opq */
};

static inline struct rdcfb_dev *rdcfb_dev_of(struct rdc_kchip *chip)
{
	return container_of(chip, struct rdcfb_dev, chip);
}

struct rdcfb_par {
	struct rdc_kchip *chip;
	struct platform_device *pdev;
	u32 pseudo_palette[RDCFB_PSEUDO_COLOURS];
	u32 fmt; /* enum rdc_format of the current var */
	u32 stride;
	/* chip->lock: the surface fb ops last set DST/SRC/CLIP to, and when */
	u32 dp_fmt, dp_stride, dp_wh;
	u32 state_gen; /* chip->state_gen then */
	bool state_valid;
	struct dentry *debugfs;
};

/* rdcfb_fb.c */
extern const struct fb_ops rdcfb_ops;
int rdcfb_fb_setup(struct fb_info *info, const char *mode);
void rdcfb_fill(struct fb_info *info, const struct fb_fillrect *r);
void rdcfb_copy(struct fb_info *info, const struct fb_copyarea *a);
void rdcfb_blit(struct fb_info *info, const struct fb_image *img);
int rdcfb_sync(struct fb_info *info);

int rdcfb_opq_init(struct rdcfb_dev *rd);
void rdcfb_opq_free(struct rdcfb_dev *rd);
extern const struct rdc_kchip_hooks rdcfb_hooks;
u64 rdcfb_ops_dropped(struct rdc_kchip *chip);

/*
 * A record of the fb-op queue (rdcfb_fb.c): what an fb_op meant when it
 * came, applied later in order under chip->lock.
 */
#define RDCFB_BITS_PER_WORD 32u

enum rdcfb_op_kind {
	RDCFB_OPK_FILL,
	RDCFB_OPK_COPY,
	RDCFB_OPK_IMAGE,
	RDCFB_OPK_REGS, /* data: register, value pairs */
	RDCFB_OPK_BLANK,
};

struct rdcfb_op {
	u32 kind;		 /* enum rdcfb_op_kind */
	u32 words;		 /* data words after the header */
	u32 fmt, stride, vw, vh; /* draw ops: the virtual screen */
	u32 rop, fg, bg;
	u32 sx, sy, dx, dy, w, h;
	u32 arg; /* IMAGE: 1 bpp rows (MONO), else pixels; BLANK: level */
};

/* rdcfb_cpu.c: a record drawn by the CPU (chip->lock held) */
void rdcfb_cpu_draw(struct rdc_kchip *chip, const struct rdcfb_op *op,
		    const u32 *data);

/* rdcfb_uapi.c: the private ioctls */
int rdcfb_ioctl(struct fb_info *info, unsigned int cmd, unsigned long arg);
int rdcfb_compat_ioctl(struct fb_info *info, unsigned int cmd,
		       unsigned long arg);

/* rdcfb_bench.c */
void rdcfb_bench_init(struct fb_info *info);
void rdcfb_bench_exit(struct fb_info *info);
void rdcfb_bench_module_init(void);
void rdcfb_bench_module_exit(void);

#endif /* RDCFB_H */
