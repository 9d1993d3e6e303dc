// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcdrm's vblank, events and CRCs, from the simulated beam: the chip
 * host calls rdcdrm_vblank at every simulated vblank (once per frame even
 * when pacing catches up several at once); it hands DRM the vblank and
 * sends the pending flip event, whose registers the chip latches at that
 * same vblank.  DRM's counter is the chip's frame count, its timestamps
 * the wall times the paced clock maps each vblank's end to.  The debugfs
 * CRC is of every frame scanned out, through the chip's frame listener.
 */
#include <drm/drm_crtc.h>
#include <drm/drm_debugfs_crc.h>
#include <drm/drm_vblank.h>
#include <linux/math64.h>

#include "rdcdrm.h"

/* ---- vblank: DRM's counter and timestamps from the chip --------------- */

int rdcdrm_enable_vblank(struct drm_crtc *crtc)
{
	return 0;
}

void rdcdrm_disable_vblank(struct drm_crtc *crtc)
{
}

/* The chip's frame count (DRM counts the difference). */
u32 rdcdrm_get_vblank_counter(struct drm_crtc *crtc)
{
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	unsigned long flags;
	u32 n;

	spin_lock_irqsave(&rd->vbl_lock, flags);
	n = (u32)rd->vbl_frames;
	spin_unlock_irqrestore(&rd->vbl_lock, flags);
	return n;
}

/* When the frame after the last simulated vblank starts (wall time). */
bool rdcdrm_get_vblank_timestamp(struct drm_crtc *crtc, int *max_error,
				 ktime_t *vblank_time, bool in_vblank_irq)
{
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	unsigned long flags;

	spin_lock_irqsave(&rd->vbl_lock, flags);
	*vblank_time = rd->vbl_time;
	spin_unlock_irqrestore(&rd->vbl_lock, flags);
	*max_error = 0;
	return *vblank_time != 0;
}

static const char *const rdcdrm_crc_sources[] = { "auto" };

/* ---- CRC: of every frame the chip scans out ------------------------------ */

/* The chip's frame listener, chip lock held, after the vblank hook. */
static void rdcdrm_frame(void *ctx, const u32 *xrgb, u32 width, u32 height,
			 u64 frame_number)
{
	struct rdcdrm_device *rd = ctx;
	u32 crc = rdc_kchip_crc(xrgb, (size_t)width * height);

	if (rd->crtc_on)
		drm_crtc_add_crc_entry(&rd->crtc, true,
				       (u32)drm_crtc_vblank_count(&rd->crtc),
				       &crc);
}

int rdcdrm_verify_crc_source(struct drm_crtc *crtc, const char *source,
			     size_t *values_cnt)
{
	if (source && *source && strcmp(source, "auto"))
		return -EINVAL;
	*values_cnt = 1;
	return 0;
}

int rdcdrm_set_crc_source(struct drm_crtc *crtc, const char *source)
{
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	bool on = source && *source;
	size_t n;
	int ret;

	ret = rdcdrm_verify_crc_source(crtc, source, &n);
	if (ret)
		return ret;
	rdc_kchip_lock(&rd->chip);
	if (on == rd->crc_on) {
		rdc_kchip_unlock(&rd->chip);
		return 0;
	}
	rdc_kchip_unlock(&rd->chip);
	/* the frames carry vblank numbers: vblanks on while CRCs are */
	if (on) {
		ret = drm_crtc_vblank_get(crtc);
		if (ret)
			return ret;
	}
	rdc_kchip_lock(&rd->chip);
	rd->crc_on = on;
	rdc_hw_set_frame_fn(rd->chip.hw, on ? rdcdrm_frame : NULL,
			    on ? rd : NULL);
	rdc_kchip_unlock(&rd->chip);
	if (!on)
		drm_crtc_vblank_put(crtc);
	return 0;
}

const char *const *rdcdrm_get_crc_sources(struct drm_crtc *crtc, size_t *count)
{
	*count = ARRAY_SIZE(rdcdrm_crc_sources);
	return rdcdrm_crc_sources;
}

/* ---- The chip's vblank hook ---------------------------------------------- */

/*
 * DRM's vblank timestamp is when the frame after the vblank starts to
 * scan out: the vblank's own time plus its lines, in the timing in force.
 */
static ktime_t rdcdrm_scanout_start(struct rdc_kchip *chip, u64 sim,
				    ktime_t wall)
{
	u32 hz = rdc_hw_core_hz(chip->hw);
	struct rdc_timing t;
	u64 cycles;

	rdc_hw_timing(chip->hw, &t);
	if (!t.pixclk_khz || t.v_total <= t.v_display)
		return wall;
	cycles = div_u64((u64)(t.v_total - t.v_display) * t.h_total * hz,
			 t.pixclk_khz * 1000);
	if (chip->stepped)
		return ktime_add_ns(wall,
				    mul_u64_u32_div(cycles, NSEC_PER_SEC, hz));
	return rdc_kchip_wall_of_locked(chip, sim + cycles);
}

/*
 * Chip lock held, inside the simulation, once per frame.  The registers a
 * commit wrote before this vblank are latched at it: its event goes now.
 */
static void rdcdrm_vblank(struct rdc_kchip *chip, u64 frame, u64 sim,
			  ktime_t wall)
{
	struct rdcdrm_device *rd = rdcdrm_of_chip(chip);
	struct drm_pending_vblank_event *ev = rd->event;
	ktime_t ts = rdcdrm_scanout_start(chip, sim, wall);
	unsigned long flags;

	spin_lock_irqsave(&rd->vbl_lock, flags);
	rd->vbl_frames = frame;
	rd->vbl_time = ts;
	spin_unlock_irqrestore(&rd->vbl_lock, flags);
	if (!rd->crtc_on)
		return;
	drm_crtc_handle_vblank(&rd->crtc);
	if (!ev)
		return;
	rd->event = NULL;
	rd->flips++;
	spin_lock_irqsave(&rd->drm.event_lock, flags);
	drm_crtc_send_vblank_event(&rd->crtc, ev);
	spin_unlock_irqrestore(&rd->drm.event_lock, flags);
	drm_crtc_vblank_put(&rd->crtc);
}

const struct rdc_kchip_hooks rdcdrm_hooks = {
	.vblank = rdcdrm_vblank,
};
