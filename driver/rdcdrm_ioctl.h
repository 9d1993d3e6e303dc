/* SPDX-License-Identifier: GPL-2.0-only WITH Linux-syscall-note */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcdrm private ioctls: the one header shared by rdcdrm.ko (DRM driver
 * name "rdc") and its user space (librdc's drm: backend, the VM tests).
 * Issued on a /dev/dri/cardN (or renderD) file descriptor next to the
 * standard DRM/KMS ioctls, numbered from DRM_COMMAND_BASE as every DRM
 * driver's own are.
 *
 * They are the chip's transport, as rdcfb_ioctl.h is on /dev/fbN: the
 * same register window, command words and encodings of
 * hw-sim/rdc_regs.h, the same wait terms, caps and errors.  Every pointer
 * travels as a __u64; every struct is a multiple of 8 bytes, and its
 * reserved fields must be zero (else EINVAL).
 *
 * Errors are negative errnos through ioctl()'s -1/errno:
 *   EINVAL    malformed request (reserved bits, alignment, bad kind or
 *             flags, simulated time past DRM_RDC_MAX_CYCLES)
 *   E2BIG     a count past its cap below
 *   EFAULT    a user pointer that cannot be read or written
 *   ENOENT    SUBMIT with DRM_RDC_SUBMIT_GEM: no such GEM handle
 *   ENOSPC    SUBMIT with DRM_RDC_SUBMIT_GEM: the buffer does not fit the
 *             VRAM the driver keeps for staging
 *   EPROTO    SUBMIT: the buffer failed validation; nothing was queued,
 *             `bad_word` says where
 *   ETIMEDOUT WAIT: the simulated-time budget or wall timeout ran out
 *   EIO       WAIT: the display processor halted on an error
 *   EPERM     STEP on a paced clock
 *   ENODEV    the device is going away (unbind, module unload)
 */
#ifndef RDCDRM_IOCTL_H
#define RDCDRM_IOCTL_H

#ifdef __KERNEL__
#include <linux/types.h>
#include <drm/drm.h>
#else
#include <linux/types.h>
#include <drm.h> /* libdrm's copy, in pkg-config --cflags libdrm */
#endif

#include "rdc_state_uapi.h"

/* drm_version.name of an rdcdrm device. */
#define DRM_RDC_DRIVER_NAME "rdc"

/* Largest command buffer one SUBMIT takes, in 32-bit words (256 KiB). */
#define DRM_RDC_SUBMIT_MAX_WORDS 65536u
/* Largest VRAM transfer one VRAM ioctl takes, in bytes (16 MiB). */
#define DRM_RDC_VRAM_MAX_BYTES (16u << 20)
/* The most simulated time one WAIT or STEP may ask for (60 s at 100 MHz). */
#define DRM_RDC_MAX_CYCLES 6000000000ull

/* One 32-bit register access at a byte offset of the register window. */
struct drm_rdc_reg {
	__u32 reg; /* RDC_REG_*, 4-aligned, < RDC_REG_WINDOW */
	__u32 val; /* written, or read back */
};

/*
 * A command buffer: `count` words at `words`, validated whole before any
 * of it reaches the display processor (a rejected buffer changes nothing).
 *
 * flags 0: the commands run against the chip as it is (their own DST).
 *
 * DRM_RDC_SUBMIT_GEM: the commands draw into the GEM buffer `handle`
 * (a dumb buffer, `width` x `height` pixels of DRM fourcc `format`, rows
 * `pitch` bytes apart).  The driver copies the buffer into VRAM it keeps
 * for staging, sets the DP's target surface and clip to it, runs the
 * commands to their end, and copies the result back, all charged as bus
 * cycles; a KMS framebuffer on that buffer then shows the drawing at its
 * next commit.
 */
#define DRM_RDC_SUBMIT_GEM (1u << 0)

struct drm_rdc_submit {
	__u64 words;	/* user pointer to __u32[count] */
	__u32 count;	/* <= DRM_RDC_SUBMIT_MAX_WORDS */
	__u32 flags;	/* DRM_RDC_SUBMIT_* */
	__u32 bad_word; /* out, on EPROTO: index of the offending word */
	__u32 handle;	/* DRM_RDC_SUBMIT_GEM: the GEM handle */
	__u32 format;	/* DRM_RDC_SUBMIT_GEM: DRM_FORMAT_* */
	__u32 width, height;
	__u32 pitch;
	__u32 reserved[2];
};

/* Wait terms: the wait ends when ANY term holds. */
#define DRM_RDC_WAIT_NONE    0
#define DRM_RDC_WAIT_GE	     1 /* (reg & mask) >= value, unsigned */
#define DRM_RDC_WAIT_WRAP_GE 2 /* (__s32)((reg & mask) - value) >= 0 */
#define DRM_RDC_WAIT_EQ	     3 /* (reg & mask) == value */
#define DRM_RDC_WAIT_TERMS   2

/* Fail with EIO if the display processor halts (a DP-only condition). */
#define DRM_RDC_WAIT_NEEDS_DP (1u << 0)

struct drm_rdc_wait_term {
	__u32 kind; /* DRM_RDC_WAIT_* */
	__u32 reg;
	__u32 mask;
	__u32 value;
};

struct drm_rdc_wait {
	struct drm_rdc_wait_term term[DRM_RDC_WAIT_TERMS];
	__u32 flags;	  /* DRM_RDC_WAIT_NEEDS_DP */
	__u32 timeout_ms; /* wall-time cap when paced; 0 = 10 s */
	__u64 budget;	  /* core cycles, <= DRM_RDC_MAX_CYCLES; 0 = 10 s */
};

/* Advance simulated time by `cycles`; stepped clock only (else EPERM). */
struct drm_rdc_step {
	__u64 cycles;
};

/* The performance counters and the clock (RDC_REG_PERF_*, RDC_REG_TIME_*). */
struct drm_rdc_counters {
	__u64 now; /* simulated time, core cycles */
	__u64 busy;
	__u64 stall;
	__u64 pixels;
	__u32 cmds;
	__u32 last_cycles;
	__u32 last_opcode;
	__u32 fence;	     /* RDC_REG_FENCE */
	__u64 frames;	     /* frames scanned out since load */
	__u64 flips;	     /* KMS flips latched at a vblank since load */
	__u64 damage_cycles; /* bus cycles spent uploading damage since load */
};

/*
 * The latest complete scanned-out frame, as XRGB8888 after the CLUT,
 * gamma and cursor: what the beam showed.
 */
struct drm_rdc_frame {
	__u64 pixels; /* user pointer to __u32[cap], or 0 for the CRC only */
	__u32 cap;    /* in pixels */
	__u32 width;  /* out */
	__u32 height; /* out */
	__u32 crc32; /* out: zlib CRC-32 of the pixels as little-endian bytes */
	__u64 seq;   /* out: frame number; 0 = none completed yet (EAGAIN) */
};

/* Read or write VRAM through the host aperture (as bus traffic). */
#define DRM_RDC_VRAM_WRITE (1u << 0)

struct drm_rdc_vram {
	__u64 data;  /* user pointer to `len` bytes */
	__u32 addr;  /* byte address in VRAM; addr + len <= VRAM size */
	__u32 len;   /* <= DRM_RDC_VRAM_MAX_BYTES */
	__u32 flags; /* DRM_RDC_VRAM_WRITE, or 0 to read */
	__u32 reserved;
};

#define DRM_RDC_REG_READ  0x00
#define DRM_RDC_REG_WRITE 0x01
#define DRM_RDC_SUBMIT	  0x02
#define DRM_RDC_WAIT	  0x03
#define DRM_RDC_STEP	  0x04
#define DRM_RDC_COUNTERS  0x05
#define DRM_RDC_FRAME	  0x06
#define DRM_RDC_VRAM	  0x07
#define DRM_RDC_STATE	  0x08

#define DRM_IOCTL_RDC_REG_READ \
	DRM_IOWR(DRM_COMMAND_BASE + DRM_RDC_REG_READ, struct drm_rdc_reg)
#define DRM_IOCTL_RDC_REG_WRITE \
	DRM_IOW(DRM_COMMAND_BASE + DRM_RDC_REG_WRITE, struct drm_rdc_reg)
#define DRM_IOCTL_RDC_SUBMIT \
	DRM_IOWR(DRM_COMMAND_BASE + DRM_RDC_SUBMIT, struct drm_rdc_submit)
#define DRM_IOCTL_RDC_WAIT \
	DRM_IOW(DRM_COMMAND_BASE + DRM_RDC_WAIT, struct drm_rdc_wait)
#define DRM_IOCTL_RDC_STEP \
	DRM_IOW(DRM_COMMAND_BASE + DRM_RDC_STEP, struct drm_rdc_step)
#define DRM_IOCTL_RDC_COUNTERS \
	DRM_IOR(DRM_COMMAND_BASE + DRM_RDC_COUNTERS, struct drm_rdc_counters)
#define DRM_IOCTL_RDC_FRAME \
	DRM_IOWR(DRM_COMMAND_BASE + DRM_RDC_FRAME, struct drm_rdc_frame)
#define DRM_IOCTL_RDC_VRAM \
	DRM_IOW(DRM_COMMAND_BASE + DRM_RDC_VRAM, struct drm_rdc_vram)
#define DRM_IOCTL_RDC_STATE \
	DRM_IOWR(DRM_COMMAND_BASE + DRM_RDC_STATE, struct rdc_chip_state)

#endif /* RDCDRM_IOCTL_H */
