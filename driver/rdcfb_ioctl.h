/* SPDX-License-Identifier: GPL-2.0-only WITH Linux-syscall-note */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcfb private ioctls: the one header shared by rdcfb.ko and its user
 * space (librdc's fbdev: backend, the VM tests).  Issued on the /dev/fbN
 * file descriptor next to the standard fbdev ioctls.
 *
 * Register offsets, command words and their encodings are those of
 * hw-sim/rdc_regs.h; this header adds only the transport.  Every pointer
 * travels as a __u64 so 32- and 64-bit callers share one layout; every
 * struct is padded to a multiple of 8 bytes with reserved fields that must
 * be zero (the driver answers -EINVAL otherwise, so they can gain a
 * meaning later).
 *
 * Errors are negative errnos through ioctl()'s -1/errno:
 *   EINVAL   malformed request (reserved bits, bad alignment, bad kind,
 *            simulated time past RDCFB_MAX_CYCLES)
 *   E2BIG    a count past its cap below
 *   EFAULT   a user pointer that cannot be read or written
 *   EPROTO   SUBMIT: the buffer failed validation; nothing was queued,
 *            `bad_word` says where
 *   ETIMEDOUT WAIT: the simulated-time budget or wall timeout ran out
 *   EIO      WAIT: the display processor halted on an error
 *   ENODEV   the device is going away (module unload)
 */
#ifndef RDCFB_IOCTL_H
#define RDCFB_IOCTL_H

#ifdef __KERNEL__
#include <linux/ioctl.h>
#include <linux/types.h>
#else
#include <sys/ioctl.h>
#include <linux/types.h>
#endif

#include "rdc_state_uapi.h"

#define RDCFB_IOC_MAGIC 'R'

/* fb_fix_screeninfo.id of an rdcfb device, so clients can recognise it. */
#define RDCFB_ID "rdcfb"

/* Largest command buffer one SUBMIT takes, in 32-bit words (256 KiB). */
#define RDCFB_SUBMIT_MAX_WORDS 65536u

/*
 * The most simulated time one WAIT (`budget`) or STEP (`cycles`) may ask
 * for: 60 simulated seconds at the RDC-1's default 100 MHz core clock, as
 * rdcd allows its clients.  Beyond it: EINVAL.
 */
#define RDCFB_MAX_CYCLES 6000000000ull

/* One 32-bit register access at a byte offset of the register window. */
struct rdcfb_reg {
	__u32 reg; /* RDC_REG_*, 4-aligned, < RDC_REG_WINDOW */
	__u32 val; /* written, or read back */
};

/*
 * A command buffer: `count` words at `words`, in the encoding of
 * hw-sim/rdc_regs.h.  The driver copies the buffer in, walks it command by
 * command (opcode known, length right for the opcode, surfaces and ring
 * pointers inside VRAM, counts under their caps) and only then hands it to
 * the display processor.  A rejected buffer changes nothing.
 */
struct rdcfb_submit {
	__u64 words;	/* user pointer to __u32[count] */
	__u32 count;	/* <= RDCFB_SUBMIT_MAX_WORDS */
	__u32 flags;	/* 0 */
	__u32 bad_word; /* out, on EPROTO: index of the offending word */
	__u32 reserved;
};

/* Wait terms, as librdc's: the wait ends when ANY term holds. */
#define RDCFB_WAIT_NONE	   0
#define RDCFB_WAIT_GE	   1 /* (reg & mask) >= value, unsigned */
#define RDCFB_WAIT_WRAP_GE 2 /* (__s32)((reg & mask) - value) >= 0 */
#define RDCFB_WAIT_EQ	   3 /* (reg & mask) == value */
#define RDCFB_WAIT_TERMS   2

/* Fail with EIO if the display processor halts (a DP-only condition). */
#define RDCFB_WAIT_NEEDS_DP (1u << 0)

struct rdcfb_wait_term {
	__u32 kind; /* RDCFB_WAIT_* */
	__u32 reg;
	__u32 mask;
	__u32 value;
};

struct rdcfb_wait {
	struct rdcfb_wait_term term[RDCFB_WAIT_TERMS];
	__u32 flags;	  /* RDCFB_WAIT_NEEDS_DP */
	__u32 timeout_ms; /* wall-time cap when paced; 0 = 10 s */
	/* simulated core cycles, <= RDCFB_MAX_CYCLES; 0 = 10 simulated s */
	__u64 budget;
};

/*
 * Advance simulated time by `cycles`, at most RDCFB_MAX_CYCLES (else
 * EINVAL); stepped clock only (else EPERM).
 */
struct rdcfb_step {
	__u64 cycles;
};

/* The performance counters and the clock (RDC_REG_PERF_*, RDC_REG_TIME_*). */
struct rdcfb_counters {
	__u64 now; /* simulated time, core cycles */
	__u64 busy;
	__u64 stall;
	__u64 pixels;
	__u32 cmds;
	__u32 last_cycles;
	__u32 last_opcode;
	__u32 fence;  /* RDC_REG_FENCE */
	__u32 frames; /* frames scanned out since load */
	__u32 reserved;
};

/* The latest complete scanned-out frame (XRGB8888). */
struct rdcfb_frame {
	__u64 pixels; /* user pointer to __u32[cap], or 0 for the CRC only */
	__u32 cap;    /* in pixels */
	__u32 width;  /* out */
	__u32 height; /* out */
	__u32 crc32; /* out: zlib CRC-32 of the pixels as little-endian bytes */
	__u32 seq;   /* out: frame number; 0 = none completed yet (EAGAIN) */
	__u32 reserved;
};

#define RDCFB_IOC_REG_READ  _IOWR(RDCFB_IOC_MAGIC, 0x00, struct rdcfb_reg)
#define RDCFB_IOC_REG_WRITE _IOW(RDCFB_IOC_MAGIC, 0x01, struct rdcfb_reg)
#define RDCFB_IOC_SUBMIT    _IOWR(RDCFB_IOC_MAGIC, 0x02, struct rdcfb_submit)
#define RDCFB_IOC_WAIT	    _IOW(RDCFB_IOC_MAGIC, 0x03, struct rdcfb_wait)
#define RDCFB_IOC_STEP	    _IOW(RDCFB_IOC_MAGIC, 0x04, struct rdcfb_step)
#define RDCFB_IOC_COUNTERS  _IOR(RDCFB_IOC_MAGIC, 0x05, struct rdcfb_counters)
#define RDCFB_IOC_FRAME	    _IOWR(RDCFB_IOC_MAGIC, 0x06, struct rdcfb_frame)
#define RDCFB_IOC_STATE	    _IOWR(RDCFB_IOC_MAGIC, 0x07, struct rdc_chip_state)

#endif /* RDCFB_IOCTL_H */
