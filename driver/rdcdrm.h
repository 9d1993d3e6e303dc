/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * rdcdrm: the RDC-1 (hw-sim + firmware-model, compiled in unchanged, on
 * the kernel chip host of rdc_kchip.h) as a DRM/KMS device, DRM driver
 * name "rdc".  Internal interfaces between the driver's files.
 *
 * Locking: chip.lock (a mutex) guards the simulated chip and the fields
 * below marked "lock"; the chip's vblank hook runs under it, inside the
 * simulation.  vbl_lock (a spinlock) guards what DRM's vblank code reads
 * with interrupts off: the frame count and the time of the last vblank.
 */
#ifndef RDCDRM_H
#define RDCDRM_H

#include <drm/drm_connector.h>
#include <drm/drm_crtc.h>
#include <drm/drm_device.h>
#include <drm/drm_encoder.h>
#include <drm/drm_plane.h>
#include <drm/drm_rect.h>
#include <linux/platform_device.h>

#include "rdc_kchip.h"
#include "rdcdrm_ioctl.h"

#define RDCDRM_NAME	   "rdcdrm"
#define RDCDRM_MAX_DEVICES 8

/*
 * VRAM (docs/driver.md, "rdcdrm"): two scanout buffers, each large enough
 * for the largest preset at 4 bytes a pixel; two cursor images (64x64
 * ARGB8888, one shown while the other is written); the rest is staging
 * for SUBMIT's GEM buffers.
 */
#define RDCDRM_SCANOUT_BYTES (8u << 20) /* 1920 * 1080 * 4 rounded up */
#define RDCDRM_CURSOR_SIZE   64u
#define RDCDRM_CURSOR_BYTES  (RDCDRM_CURSOR_SIZE * RDCDRM_CURSOR_SIZE * 4)
#define RDCDRM_CURSOR_BASE   (2 * RDCDRM_SCANOUT_BYTES)
#define RDCDRM_STAGING_BASE  (RDCDRM_CURSOR_BASE + (64u << 10))
#define RDCDRM_VRAM_MIN	     (RDCDRM_STAGING_BASE + (1u << 20))
#define RDCDRM_VRAM_MAX	     (256u << 20)

/* The command words of one upload, staged before they go to the FIFO. */
#define RDCDRM_STAGE_WORDS (RDC_CMD_MAX_ARGS + 2)

struct rdcdrm_device {
	struct drm_device drm;
	struct rdc_kchip chip;
	struct platform_device *pdev;
	struct drm_plane primary, cursor;
	struct drm_crtc crtc;
	struct drm_encoder encoder;
	struct drm_connector connector;

	/* vbl_lock: what DRM's vblank code reads with interrupts off */
	spinlock_t vbl_lock;
	u64 vbl_frames;	  /* frames since load, as the chip counted them */
	ktime_t vbl_time; /* wall time of the last vblank */

	/* lock: the KMS state as the chip has it */
	struct drm_pending_vblank_event *event; /* sent at the next vblank */
	bool crtc_on;
	bool crc_on;
	u32 front;	      /* the scanout buffer shown (0 or 1) */
	u32 fmt, stride;      /* of the primary plane, in VRAM */
	u32 width, height;    /* of the mode */
	struct drm_rect prev; /* the last commit's damage, screen coords */
	bool prev_valid;
	bool clut_dirty;   /* the CLUT needs loading at the next flush */
	u32 cursor_buf;	   /* the cursor image shown (0 or 1) */
	u64 flips;	   /* flips latched at a vblank */
	u64 damage_cycles; /* DP cycles spent uploading damage */
	u32 *stage;	   /* RDCDRM_STAGE_WORDS */
};

static inline struct rdcdrm_device *rdcdrm_of(struct drm_device *drm)
{
	return container_of(drm, struct rdcdrm_device, drm);
}

static inline struct rdcdrm_device *rdcdrm_of_chip(struct rdc_kchip *chip)
{
	return container_of(chip, struct rdcdrm_device, chip);
}

/* rdcdrm_kms.c */
int rdcdrm_kms_init(struct rdcdrm_device *rd);
u32 rdcdrm_format_of(u32 fourcc);

/* rdcdrm_vblank.c: vblank, events and CRCs from the simulated beam */
extern const struct rdc_kchip_hooks rdcdrm_hooks;
int rdcdrm_enable_vblank(struct drm_crtc *crtc);
void rdcdrm_disable_vblank(struct drm_crtc *crtc);
u32 rdcdrm_get_vblank_counter(struct drm_crtc *crtc);
bool rdcdrm_get_vblank_timestamp(struct drm_crtc *crtc, int *max_error,
				 ktime_t *vblank_time, bool in_vblank_irq);
int rdcdrm_verify_crc_source(struct drm_crtc *crtc, const char *source,
			     size_t *values_cnt);
int rdcdrm_set_crc_source(struct drm_crtc *crtc, const char *source);
const char *const *rdcdrm_get_crc_sources(struct drm_crtc *crtc, size_t *count);

/* rdcdrm_uapi.c: the private ioctls */
struct drm_file;
int rdcdrm_ioctl_reg_read(struct drm_device *drm, void *data,
			  struct drm_file *file);
int rdcdrm_ioctl_reg_write(struct drm_device *drm, void *data,
			   struct drm_file *file);
int rdcdrm_ioctl_submit(struct drm_device *drm, void *data,
			struct drm_file *file);
int rdcdrm_ioctl_wait(struct drm_device *drm, void *data,
		      struct drm_file *file);
int rdcdrm_ioctl_step(struct drm_device *drm, void *data,
		      struct drm_file *file);
int rdcdrm_ioctl_counters(struct drm_device *drm, void *data,
			  struct drm_file *file);
int rdcdrm_ioctl_frame(struct drm_device *drm, void *data,
		       struct drm_file *file);
int rdcdrm_ioctl_vram(struct drm_device *drm, void *data,
		      struct drm_file *file);
int rdcdrm_ioctl_state(struct drm_device *drm, void *data,
		       struct drm_file *file);

#endif /* RDCDRM_H */
