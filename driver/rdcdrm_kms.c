// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcdrm's display pipeline on the simulated RDC-1: one CRTC (the chip's
 * timing generator), a primary plane in the chip's formats, a cursor
 * plane on its ARGB8888 hardware cursor, one encoder and one connector
 * whose modes are the chip's presets.
 *
 * A plane update uploads the framebuffer's damaged rectangles into the
 * scanout buffer not shown (two in VRAM) as display-processor HOST_BLIT
 * commands, so their bus cycles are charged as on the hardware, then
 * writes FB_BASE, FB_STRIDE and FB_FORMAT, which the chip latches at its
 * next vblank: a flip never tears.  The buffer written is one flip old,
 * so it gets this commit's damage and the previous commit's (buffer age
 * two); a modeset or a new format uploads everything.
 *
 * vblank, flip events and CRCs come from the simulated beam:
 * rdcdrm_vblank.c.
 */
#include <drm/drm_atomic.h>
#include <drm/drm_atomic_helper.h>
#include <drm/drm_color_mgmt.h>
#include <drm/drm_damage_helper.h>
#include <drm/drm_debugfs_crc.h>
#include <drm/drm_fourcc.h>
#include <drm/drm_framebuffer.h>
#include <drm/drm_gem_atomic_helper.h>
#include <drm/drm_gem_framebuffer_helper.h>
#include <drm/drm_modeset_helper_vtables.h>
#include <drm/drm_probe_helper.h>
#include <drm/drm_simple_kms_helper.h>
#include <drm/drm_vblank.h>
#include <linux/iosys-map.h>
#include <linux/math64.h>
#include <linux/minmax.h>

#include "rdcdrm.h"

/* The argument words ahead of HOST_BLIT's pixels. */
#define RDCDRM_BLIT_ARGS   2u
#define RDCDRM_LUT_SIZE	   256u
#define RDCDRM_PREFERRED_W 1024
#define RDCDRM_PREFERRED_H 768

static const u32 rdcdrm_primary_formats[] = {
	DRM_FORMAT_XRGB8888, DRM_FORMAT_ARGB8888, DRM_FORMAT_RGB888,
	DRM_FORMAT_RGB565,   DRM_FORMAT_C8,
};

static const u32 rdcdrm_cursor_formats[] = {
	DRM_FORMAT_ARGB8888,
};

/* The chip's format of a DRM fourcc, or RDC_FMT_COUNT: none. */
u32 rdcdrm_format_of(u32 fourcc)
{
	switch (fourcc) {
	case DRM_FORMAT_C8:
		return RDC_FMT_I8;
	case DRM_FORMAT_RGB565:
		return RDC_FMT_RGB565;
	case DRM_FORMAT_RGB888:
		return RDC_FMT_RGB888;
	case DRM_FORMAT_XRGB8888:
	case DRM_FORMAT_ARGB8888: /* scanned out as XRGB8888 */
		return RDC_FMT_XRGB8888;
	default:
		return RDC_FMT_COUNT;
	}
}

/* ---- Modes --------------------------------------------------------------- */

/*
 * What the CRTC can scan (hw.h's timing validation at latch), and what the
 * driver's VRAM layout holds: a mode passing this is never refused by the
 * chip.
 */
static enum drm_mode_status rdcdrm_mode_check(const struct drm_display_mode *m)
{
	if (m->flags & DRM_MODE_FLAG_INTERLACE)
		return MODE_NO_INTERLACE;
	if (m->flags & DRM_MODE_FLAG_DBLSCAN)
		return MODE_NO_DBLESCAN;
	if (!m->hdisplay || m->hdisplay > RDC_CRTC_MAX_DISPLAY)
		return MODE_BAD_HVALUE;
	if (!m->vdisplay || m->vdisplay > RDC_CRTC_MAX_DISPLAY)
		return MODE_BAD_VVALUE;
	if (m->htotal > RDC_CRTC_MAX_TOTAL || m->vtotal > RDC_CRTC_MAX_TOTAL)
		return MODE_BAD;
	if (m->hsync_start < m->hdisplay || m->hsync_end < m->hsync_start ||
	    m->htotal < m->hsync_end)
		return MODE_HSYNC;
	if (m->vsync_start < m->vdisplay || m->vsync_end < m->vsync_start ||
	    m->vtotal < m->vsync_end || m->vtotal <= m->vdisplay)
		return MODE_VSYNC;
	if (m->clock < RDC_PIXCLK_MIN_KHZ)
		return MODE_CLOCK_LOW;
	if (m->clock > RDC_PIXCLK_MAX_KHZ)
		return MODE_CLOCK_HIGH;
	/* a line lasts at least one core cycle */
	if ((u64)m->htotal * RDC_DEFAULT_CORE_HZ < (u64)m->clock * 1000)
		return MODE_CLOCK_HIGH;
	if ((u64)m->hdisplay * m->vdisplay * sizeof(u32) > RDCDRM_SCANOUT_BYTES)
		return MODE_MEM;
	return MODE_OK;
}

static void rdcdrm_mode_of_timing(const struct rdc_timing *t,
				  struct drm_display_mode *m)
{
	m->clock = t->pixclk_khz;
	m->hdisplay = t->h_display;
	m->hsync_start = t->h_sync_start;
	m->hsync_end = t->h_sync_end;
	m->htotal = t->h_total;
	m->vdisplay = t->v_display;
	m->vsync_start = t->v_sync_start;
	m->vsync_end = t->v_sync_end;
	m->vtotal = t->v_total;
	m->flags = (t->flags & RDC_CRTC_HSYNC_POS ? DRM_MODE_FLAG_PHSYNC :
						    DRM_MODE_FLAG_NHSYNC) |
		   (t->flags & RDC_CRTC_VSYNC_POS ? DRM_MODE_FLAG_PVSYNC :
						    DRM_MODE_FLAG_NVSYNC);
	m->type = DRM_MODE_TYPE_DRIVER;
	if (t->h_display == RDCDRM_PREFERRED_W &&
	    t->v_display == RDCDRM_PREFERRED_H)
		m->type |= DRM_MODE_TYPE_PREFERRED;
	drm_mode_set_name(m);
}

/* The chip's presets, with their exact timings. */
static int rdcdrm_get_modes(struct drm_connector *connector)
{
	struct drm_display_mode *m;
	struct rdc_timing t;
	int n = 0;
	u32 p;

	for (p = 0; p < RDC_PRESET_COUNT; p++) {
		if (rdc_preset_timing(p, &t))
			continue;
		m = drm_mode_create(connector->dev);
		if (!m)
			break;
		rdcdrm_mode_of_timing(&t, m);
		drm_mode_probed_add(connector, m);
		n++;
	}
	return n;
}

static enum drm_mode_status
rdcdrm_connector_mode_valid(struct drm_connector *connector,
			    struct drm_display_mode *mode)
{
	return rdcdrm_mode_check(mode);
}

static const struct drm_connector_helper_funcs rdcdrm_connector_helpers = {
	.get_modes = rdcdrm_get_modes,
	.mode_valid = rdcdrm_connector_mode_valid,
};

static const struct drm_connector_funcs rdcdrm_connector_funcs = {
	.fill_modes = drm_helper_probe_single_connector_modes,
	.destroy = drm_connector_cleanup,
	.reset = drm_atomic_helper_connector_reset,
	.atomic_duplicate_state = drm_atomic_helper_connector_duplicate_state,
	.atomic_destroy_state = drm_atomic_helper_connector_destroy_state,
};

/* The DP's busy cycles so far (lock held). */
static u64 rdcdrm_busy(struct rdcdrm_device *rd)
{
	struct rdc_perf perf;

	rdc_hw_perf(rd->chip.hw, &perf);
	return perf.busy;
}

/* Drive BL_EN, the backlight, high or low (lock held). */
static void rdcdrm_backlight(struct rdcdrm_device *rd, bool on)
{
	struct rdc_hw_state st;

	rdc_hw_state(rd->chip.hw, &st);
	rdc_hw_set_pins(rd->chip.hw, on ? st.pins_in | RDC_PIN_BL_EN :
					  st.pins_in & ~RDC_PIN_BL_EN);
}

/* ---- Uploads: framebuffer rows to VRAM as HOST_BLIT --------------------- */

/*
 * The DP state an upload relies on, set before every upload (a client's
 * SUBMIT may have changed any of it): the back buffer as DST, a clip of
 * all of it, plain copies.
 */
static int rdcdrm_upload_begin(struct rdcdrm_device *rd, u32 base)
{
	u32 wh = RDC_WH(rd->width, rd->height);
	u32 w[] = {
		RDC_CMD(RDC_OP_SET_DST, 0, 4),
		base,
		rd->stride,
		wh,
		rd->fmt,
		RDC_CMD(RDC_OP_SET_CLIP, 0, 2),
		RDC_XY(0, 0),
		wh,
		RDC_CMD(RDC_OP_SET_ROP, 0, 1),
		RDC_ROP_COPY,
		RDC_CMD(RDC_OP_SET_PATTERN, RDC_PAT_NONE, 0),
		RDC_CMD(RDC_OP_SET_TRANSFORM, 0, 0),
		RDC_CMD(RDC_OP_SET_ALPHA, 0, 1),
		RDC_ALPHA_OPAQUE,
		RDC_CMD(RDC_OP_SET_COLORKEY, 0, 1),
		0,
	};

	return rdc_kchip_push_locked(&rd->chip, w, ARRAY_SIZE(w));
}

/*
 * Rectangle `r` of the screen (clipped to it) from the framebuffer rows at
 * `src` (`pitch` bytes apart, the screen's origin at src) into the buffer
 * at `base`: by the DP when it can take commands, else through the host
 * aperture (a client's SUBMIT half in the FIFO, the DP halted or off).
 */
static void rdcdrm_upload_rect(struct rdcdrm_device *rd, bool by_dp, u32 base,
			       const u8 *src, u32 pitch, u32 cpp,
			       struct drm_rect r)
{
	struct rdc_hw *hw = rd->chip.hw;
	u32 x, y, w, h, bytes, wpr, rows, max_rows, i;
	const u8 *row;

	if (!drm_rect_intersect(&r,
				&DRM_RECT_INIT(0, 0, rd->width, rd->height)))
		return;
	x = r.x1;
	y = r.y1;
	w = drm_rect_width(&r);
	h = drm_rect_height(&r);
	bytes = w * cpp;
	wpr = DIV_ROUND_UP(bytes, sizeof(u32));
	if (!by_dp || wpr > RDC_CMD_MAX_ARGS - RDCDRM_BLIT_ARGS) {
		for (i = 0; i < h; i++)
			rdc_hw_vram_write(
				hw, base + (y + i) * rd->stride + x * cpp,
				src + (size_t)(y + i) * pitch + x * cpp, bytes);
		return;
	}
	max_rows = (RDC_CMD_MAX_ARGS - RDCDRM_BLIT_ARGS) / wpr;
	for (; h; y += rows, h -= rows) {
		u32 *words = rd->stage;

		rows = min(h, max_rows);
		*words++ = RDC_CMD(RDC_OP_HOST_BLIT, 0,
				   RDCDRM_BLIT_ARGS + rows * wpr);
		*words++ = RDC_XY(x, y);
		*words++ = RDC_WH(w, rows);
		for (i = 0; i < rows; i++, words += wpr) {
			row = src + (size_t)(y + i) * pitch + x * cpp;
			words[wpr - 1] = 0;
			memcpy(words, row, bytes);
		}
		if (rdc_kchip_push_locked(&rd->chip, rd->stage,
					  words - rd->stage)) {
			/* the DP stopped taking words: the host writes */
			rdcdrm_upload_rect(rd, false, base, src, pitch, cpp,
					   DRM_RECT_INIT(x, y, w, h));
			return;
		}
	}
}

/* ---- Primary plane ------------------------------------------------------- */

static int rdcdrm_plane_check(struct drm_plane *plane,
			      struct drm_atomic_state *state, bool cursor)
{
	struct drm_plane_state *new =
		drm_atomic_get_new_plane_state(state, plane);
	struct drm_crtc_state *crtc_state;
	int ret;

	if (!new->fb || WARN_ON(!new->crtc))
		return 0;
	crtc_state = drm_atomic_get_crtc_state(state, new->crtc);
	if (IS_ERR(crtc_state))
		return PTR_ERR(crtc_state);
	ret = drm_atomic_helper_check_plane_state(new, crtc_state,
						  DRM_PLANE_NO_SCALING,
						  DRM_PLANE_NO_SCALING, cursor,
						  true);
	if (ret)
		return ret;
	if (!new->visible)
		return 0;
	/* a visible cursor lies within 64 pixels of the screen */
	if (cursor && (new->src_w >> 16 > RDCDRM_CURSOR_SIZE ||
		       new->src_h >> 16 > RDCDRM_CURSOR_SIZE))
		return -EINVAL;
	if (rdcdrm_format_of(new->fb->format->format) == RDC_FMT_COUNT)
		return -EINVAL;
	return 0;
}

static int rdcdrm_primary_check(struct drm_plane *plane,
				struct drm_atomic_state *state)
{
	return rdcdrm_plane_check(plane, state, false);
}

static void rdcdrm_primary_update(struct drm_plane *plane,
				  struct drm_atomic_state *state)
{
	struct drm_plane_state *new =
		drm_atomic_get_new_plane_state(state, plane);
	struct drm_shadow_plane_state *shadow = to_drm_shadow_plane_state(new);
	struct rdcdrm_device *rd = rdcdrm_of(plane->dev);
	struct drm_framebuffer *fb = new->fb;
	struct drm_crtc_state *crtc_state;
	struct drm_atomic_helper_damage_iter iter;
	struct drm_rect clip, cur = { 0 }, all;
	struct rdc_hw *hw = rd->chip.hw;
	u32 fmt, stride, w, h, cpp, back, base, pitch;
	bool full, by_dp, any = false;
	const u8 *src;
	u64 busy0;

	if (!fb || !new->visible || !new->crtc)
		return;
	crtc_state = drm_atomic_get_new_crtc_state(state, new->crtc);
	fmt = rdcdrm_format_of(fb->format->format);
	w = drm_rect_width(&new->dst);
	h = drm_rect_height(&new->dst);
	cpp = fb->format->cpp[0];
	stride = ALIGN(w * cpp, sizeof(u32));
	pitch = fb->pitches[0];
	/* the screen's origin in the framebuffer */
	src = (const u8 *)shadow->data[0].vaddr + fb->offsets[0] +
	      (size_t)(new->src.y1 >> 16) * pitch + (new->src.x1 >> 16) * cpp;
	all = DRM_RECT_INIT(0, 0, w, h);

	rdc_kchip_lock(&rd->chip);
	full = !rd->prev_valid || fmt != rd->fmt || stride != rd->stride ||
	       w != rd->width || h != rd->height ||
	       (crtc_state && drm_atomic_crtc_needs_modeset(crtc_state));
	if (fmt != rd->fmt)
		rd->clut_dirty = true;
	rd->fmt = fmt;
	rd->stride = stride;
	rd->width = w;
	rd->height = h;
	back = rd->front ^ 1;
	base = back * RDCDRM_SCANOUT_BYTES;
	busy0 = rdcdrm_busy(rd);
	by_dp = rdc_kchip_dp_usable(&rd->chip) &&
		!rdcdrm_upload_begin(rd, base);
	if (full) {
		rdcdrm_upload_rect(rd, by_dp, base, src, pitch, cpp, all);
		cur = all;
	} else {
		/* the back buffer missed the last commit's damage too */
		rdcdrm_upload_rect(rd, by_dp, base, src, pitch, cpp, rd->prev);
		drm_atomic_helper_damage_iter_init(
			&iter, drm_atomic_get_old_plane_state(state, plane),
			new);
		drm_atomic_for_each_plane_damage(&iter, &clip) {
			drm_rect_translate(&clip, -(new->src.x1 >> 16),
					   -(new->src.y1 >> 16));
			rdcdrm_upload_rect(rd, by_dp, base, src, pitch, cpp,
					   clip);
			if (!any)
				cur = clip;
			cur.x1 = min(cur.x1, clip.x1);
			cur.y1 = min(cur.y1, clip.y1);
			cur.x2 = max(cur.x2, clip.x2);
			cur.y2 = max(cur.y2, clip.y2);
			any = true;
		}
	}
	if (by_dp)
		rdc_kchip_drain_locked(&rd->chip);
	rd->damage_cycles += rdcdrm_busy(rd) - busy0;
	rd->prev = cur;
	rd->prev_valid = true;
	/* latched together at the next vblank */
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, fmt);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, stride);
	rdc_hw_write(hw, RDC_REG_FB_BASE, base);
	rd->front = back;
	rd->chip.state_gen++;
	rdc_kchip_irq_check_locked(&rd->chip);
	rdc_kchip_unlock(&rd->chip);
}

/*
 * The primary plane goes off while the CRTC stays on: the screen shows
 * black (the cursor, if on, over it), as a CRTC with no plane does.  The
 * chip has no background colour, so the DP fills the back buffer with 0
 * in XRGB8888 (black before gamma, whatever the plane's format was) and
 * it is flipped to at the next vblank like any update.
 */
static void rdcdrm_primary_disable(struct drm_plane *plane,
				   struct drm_atomic_state *state)
{
	struct drm_plane_state *old =
		drm_atomic_get_old_plane_state(state, plane);
	struct rdcdrm_device *rd = rdcdrm_of(plane->dev);
	struct rdc_hw *hw = rd->chip.hw;
	struct drm_crtc_state *cs;
	u32 base, w, h, y;

	if (!old->crtc)
		return;
	cs = drm_atomic_get_new_crtc_state(state, old->crtc);
	/* a CRTC going off goes dark by itself (rdcdrm_crtc_disable) */
	if (!cs || !cs->active)
		return;
	w = cs->mode.hdisplay;
	h = cs->mode.vdisplay;
	rdc_kchip_lock(&rd->chip);
	base = (rd->front ^ 1) * RDCDRM_SCANOUT_BYTES;
	rd->fmt = RDC_FMT_XRGB8888;
	rd->stride = w * 4;
	rd->width = w;
	rd->height = h;
	if (rdc_kchip_dp_usable(&rd->chip) && !rdcdrm_upload_begin(rd, base)) {
		u32 fill[] = {
			RDC_CMD(RDC_OP_SET_FG, 0, 1),
			0,
			RDC_CMD(RDC_OP_FILL_RECT, 0, 2),
			RDC_XY(0, 0),
			RDC_WH(w, h),
		};

		if (!rdc_kchip_push_locked(&rd->chip, fill, ARRAY_SIZE(fill)))
			rdc_kchip_drain_locked(&rd->chip);
	} else {
		/* the host clears it through the aperture, a row at a time */
		memset(rd->stage, 0, RDCDRM_STAGE_WORDS * sizeof(u32));
		for (y = 0; y < h; y++) {
			u32 x, n;

			for (x = 0; x < w; x += n) {
				n = min(w - x, RDCDRM_STAGE_WORDS);
				rdc_hw_vram_write(hw,
						  base + y * rd->stride + x * 4,
						  rd->stage, n * 4);
			}
		}
	}
	/* the next update finds no picture of its own to build on */
	rd->prev_valid = false;
	rdc_hw_write(hw, RDC_REG_FB_FORMAT, rd->fmt);
	rdc_hw_write(hw, RDC_REG_FB_STRIDE, rd->stride);
	rdc_hw_write(hw, RDC_REG_FB_BASE, base);
	rd->front ^= 1;
	rd->chip.state_gen++;
	rdc_kchip_irq_check_locked(&rd->chip);
	rdc_kchip_unlock(&rd->chip);
}

static const struct drm_plane_helper_funcs rdcdrm_primary_helpers = {
	DRM_GEM_SHADOW_PLANE_HELPER_FUNCS,
	.atomic_check = rdcdrm_primary_check,
	.atomic_update = rdcdrm_primary_update,
	.atomic_disable = rdcdrm_primary_disable,
};

static const struct drm_plane_funcs rdcdrm_plane_funcs = {
	.update_plane = drm_atomic_helper_update_plane,
	.disable_plane = drm_atomic_helper_disable_plane,
	.destroy = drm_plane_cleanup,
	DRM_GEM_SHADOW_PLANE_FUNCS,
};

/* ---- Cursor plane -------------------------------------------------------- */

#ifdef RDC_REG_CURSOR_CTRL

static int rdcdrm_cursor_check(struct drm_plane *plane,
			       struct drm_atomic_state *state)
{
	return rdcdrm_plane_check(plane, state, true);
}

static void rdcdrm_cursor_show(struct rdcdrm_device *rd, bool on)
{
	struct rdc_hw *hw = rd->chip.hw;
	u32 ctl = rdc_hw_read(hw, RDC_REG_CONTROL) &
		  ~(RDC_CONTROL_RESUME | RDC_CONTROL_SOFT_RESET);

	rdc_hw_write(hw, RDC_REG_CONTROL,
		     on ? ctl | RDC_CONTROL_CURSOR_EN :
			  ctl & ~RDC_CONTROL_CURSOR_EN);
}

/*
 * The image goes to the cursor area not shown (CURSOR_BASE is latched at
 * vblank), padded to 64x64 with transparent pixels; a move alone writes
 * only CURSOR_POS.
 */
static void rdcdrm_cursor_update(struct drm_plane *plane,
				 struct drm_atomic_state *state)
{
	struct drm_plane_state *new =
		drm_atomic_get_new_plane_state(state, plane);
	struct drm_plane_state *old =
		drm_atomic_get_old_plane_state(state, plane);
	struct drm_shadow_plane_state *shadow = to_drm_shadow_plane_state(new);
	struct rdcdrm_device *rd = rdcdrm_of(plane->dev);
	struct drm_framebuffer *fb = new->fb;
	struct rdc_hw *hw = rd->chip.hw;
	u32 row[RDCDRM_CURSOR_SIZE];
	u32 w, h, y, base;
	const u8 *src;

	if (!fb || !new->visible) {
		rdc_kchip_lock(&rd->chip);
		rdcdrm_cursor_show(rd, false);
		rdc_kchip_unlock(&rd->chip);
		return;
	}
	/*
	 * The image and position as asked, not as clipped to the screen:
	 * the chip clips the cursor itself, and a move alone uploads nothing
	 */
	w = min(new->src_w >> 16, RDCDRM_CURSOR_SIZE);
	h = min(new->src_h >> 16, RDCDRM_CURSOR_SIZE);
	src = (const u8 *)shadow->data[0].vaddr + fb->offsets[0] +
	      (size_t)(new->src_y >> 16) * fb->pitches[0] +
	      (new->src_x >> 16) * sizeof(u32);
	rdc_kchip_lock(&rd->chip);
	if (old->fb != fb || drm_plane_get_damage_clips_count(new) ||
	    !old->visible || old->src_x != new->src_x ||
	    old->src_y != new->src_y || old->src_w != new->src_w ||
	    old->src_h != new->src_h) {
		rd->cursor_buf ^= 1;
		base = RDCDRM_CURSOR_BASE +
		       rd->cursor_buf * RDCDRM_CURSOR_BYTES;
		for (y = 0; y < RDCDRM_CURSOR_SIZE; y++) {
			memset(row, 0, sizeof(row));
			if (y < h)
				memcpy(row, src + (size_t)y * fb->pitches[0],
				       w * sizeof(u32));
			rdc_hw_vram_write(hw, base + y * sizeof(row), row,
					  sizeof(row));
		}
		rdc_hw_write(hw, RDC_REG_CURSOR_CTRL,
			     FIELD_PREP(RDC_CURSOR_CTRL_FMT,
					RDC_CURSOR_FMT_ARGB8888) |
				     RDC_CURSOR_CTRL_SIZE64);
		rdc_hw_write(hw, RDC_REG_CURSOR_BASE, base);
	}
	rdc_hw_write(hw, RDC_REG_CURSOR_POS, RDC_XY(new->crtc_x, new->crtc_y));
	rdcdrm_cursor_show(rd, true);
	rdc_kchip_unlock(&rd->chip);
}

static void rdcdrm_cursor_disable(struct drm_plane *plane,
				  struct drm_atomic_state *state)
{
	struct rdcdrm_device *rd = rdcdrm_of(plane->dev);

	rdc_kchip_lock(&rd->chip);
	rdcdrm_cursor_show(rd, false);
	rdc_kchip_unlock(&rd->chip);
}

static const struct drm_plane_helper_funcs rdcdrm_cursor_helpers = {
	DRM_GEM_SHADOW_PLANE_HELPER_FUNCS,
	.atomic_check = rdcdrm_cursor_check,
	.atomic_update = rdcdrm_cursor_update,
	.atomic_disable = rdcdrm_cursor_disable,
};

#endif /* RDC_REG_CURSOR_CTRL */

/* ---- CRTC ---------------------------------------------------------------- */

/*
 * The CLUT: the palette of C8, the gamma of direct colour (through the
 * chip's gamma path); a grey ramp, and the gamma path off, without a
 * GAMMA_LUT.  Latched at vblank with the flip (CONTROL.CLUT_LATCH).
 */
static void rdcdrm_load_clut(struct rdcdrm_device *rd,
			     const struct drm_crtc_state *cs)
{
	const struct drm_color_lut *lut = cs->gamma_lut ? cs->gamma_lut->data :
							  NULL;
	struct rdc_hw *hw = rd->chip.hw;
	u32 i, r, g, b, ctl;

	rdc_hw_write(hw, RDC_REG_CLUT_INDEX, 0);
	for (i = 0; i < RDCDRM_LUT_SIZE; i++) {
		if (lut) {
			/* the high byte: v * 0x101 and v << 8 both give v */
			r = lut[i].red >> 8;
			g = lut[i].green >> 8;
			b = lut[i].blue >> 8;
		} else {
			r = i;
			g = i;
			b = i;
		}
		rdc_hw_write(hw, RDC_REG_CLUT_DATA, r << 16 | g << 8 | b);
	}
	ctl = rdc_hw_read(hw, RDC_REG_CONTROL) &
	      ~(RDC_CONTROL_RESUME | RDC_CONTROL_SOFT_RESET);
#ifdef RDC_CONTROL_GAMMA_EN
	if (lut && rd->fmt != RDC_FMT_I8)
		ctl |= RDC_CONTROL_GAMMA_EN;
	else
		ctl &= ~RDC_CONTROL_GAMMA_EN;
#endif
	rdc_hw_write(hw, RDC_REG_CONTROL, ctl);
	rd->clut_dirty = false;
}

static int rdcdrm_crtc_check(struct drm_crtc *crtc,
			     struct drm_atomic_state *state)
{
	struct drm_crtc_state *cs = drm_atomic_get_new_crtc_state(state, crtc);

	if (cs->gamma_lut &&
	    drm_color_lut_size(cs->gamma_lut) != RDCDRM_LUT_SIZE)
		return -EINVAL;
	if (cs->enable && rdcdrm_mode_check(&cs->mode) != MODE_OK)
		return -EINVAL;
	return 0;
}

static enum drm_mode_status
rdcdrm_crtc_mode_valid(struct drm_crtc *crtc,
		       const struct drm_display_mode *mode)
{
	return rdcdrm_mode_check(mode);
}

static void rdcdrm_crtc_enable(struct drm_crtc *crtc,
			       struct drm_atomic_state *state)
{
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	const struct drm_display_mode *m = &crtc->state->adjusted_mode;
	struct rdc_hw *hw = rd->chip.hw;
	const u32 regs[][2] = {
		{ RDC_REG_H_TOTAL, m->htotal },
		{ RDC_REG_H_DISPLAY, m->hdisplay },
		{ RDC_REG_H_SYNC_START, m->hsync_start },
		{ RDC_REG_H_SYNC_END, m->hsync_end },
		{ RDC_REG_V_TOTAL, m->vtotal },
		{ RDC_REG_V_DISPLAY, m->vdisplay },
		{ RDC_REG_V_SYNC_START, m->vsync_start },
		{ RDC_REG_V_SYNC_END, m->vsync_end },
		{ RDC_REG_PIXCLK_KHZ, m->clock },
		{ RDC_REG_CRTC_FLAGS,
		  (m->flags & DRM_MODE_FLAG_PHSYNC ? RDC_CRTC_HSYNC_POS : 0) |
			  (m->flags & DRM_MODE_FLAG_PVSYNC ?
				   RDC_CRTC_VSYNC_POS :
				   0) },
	};
	unsigned int i;
	u32 ctl;

	rdc_kchip_lock(&rd->chip);
	for (i = 0; i < ARRAY_SIZE(regs); i++)
		rdc_hw_write(hw, regs[i][0], regs[i][1]);
	ctl = rdc_hw_read(hw, RDC_REG_CONTROL) &
	      ~(RDC_CONTROL_RESUME | RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     ctl | RDC_CONTROL_SCANOUT_EN | RDC_CONTROL_CLUT_LATCH);
	rdcdrm_backlight(rd, true);
	rd->prev_valid = false;
	rd->clut_dirty = true;
	rd->crtc_on = true;
	rdc_kchip_irq_check_locked(&rd->chip);
	rdc_kchip_unlock(&rd->chip);
	drm_crtc_vblank_on(crtc);
}

static void rdcdrm_crtc_disable(struct drm_crtc *crtc,
				struct drm_atomic_state *state)
{
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	struct rdc_hw *hw = rd->chip.hw;
	struct drm_pending_vblank_event *ev;
	u32 ctl;

	drm_crtc_vblank_off(crtc);
	rdc_kchip_lock(&rd->chip);
	ctl = rdc_hw_read(hw, RDC_REG_CONTROL) &
	      ~(RDC_CONTROL_RESUME | RDC_CONTROL_SOFT_RESET);
	rdc_hw_write(hw, RDC_REG_CONTROL,
		     ctl & ~(RDC_CONTROL_SCANOUT_EN | RDC_CONTROL_CURSOR_EN));
	rdcdrm_backlight(rd, false);
	rd->crtc_on = false;
	ev = rd->event;
	rd->event = NULL;
	rdc_kchip_irq_check_locked(&rd->chip);
	rdc_kchip_unlock(&rd->chip);
	/* no vblank comes any more: what waits for one ends now */
	spin_lock_irq(&crtc->dev->event_lock);
	if (ev)
		drm_crtc_send_vblank_event(crtc, ev);
	if (crtc->state->event && !crtc->state->active) {
		drm_crtc_send_vblank_event(crtc, crtc->state->event);
		crtc->state->event = NULL;
	}
	spin_unlock_irq(&crtc->dev->event_lock);
}

/*
 * The event goes out at the next vblank, when the chip latches what the
 * plane updates wrote; with the stepped clock the commit moves simulated
 * time to that vblank itself, as a wait for it would.
 */
static void rdcdrm_crtc_flush(struct drm_crtc *crtc,
			      struct drm_atomic_state *state)
{
	struct drm_crtc_state *cs = drm_atomic_get_new_crtc_state(state, crtc);
	struct rdcdrm_device *rd = rdcdrm_of(crtc->dev);
	struct drm_pending_vblank_event *ev = cs->event;
	bool armed = false;

	cs->event = NULL;
	rdc_kchip_lock(&rd->chip);
	if (cs->active && (rd->clut_dirty || cs->color_mgmt_changed ||
			   drm_atomic_crtc_needs_modeset(cs)))
		rdcdrm_load_clut(rd, cs);
	if (ev && rd->crtc_on && !rd->event && !drm_crtc_vblank_get(crtc)) {
		rd->event = ev;
		armed = true;
		ev = NULL;
	}
	rdc_kchip_unlock(&rd->chip);
	if (ev) {
		spin_lock_irq(&crtc->dev->event_lock);
		drm_crtc_send_vblank_event(crtc, ev);
		spin_unlock_irq(&crtc->dev->event_lock);
	}
	if (armed && rd->chip.stepped)
		rdc_kchip_vsync(&rd->chip);
}

static const struct drm_crtc_helper_funcs rdcdrm_crtc_helpers = {
	.mode_valid = rdcdrm_crtc_mode_valid,
	.atomic_check = rdcdrm_crtc_check,
	.atomic_flush = rdcdrm_crtc_flush,
	.atomic_enable = rdcdrm_crtc_enable,
	.atomic_disable = rdcdrm_crtc_disable,
};

static const struct drm_crtc_funcs rdcdrm_crtc_funcs = {
	.reset = drm_atomic_helper_crtc_reset,
	.destroy = drm_crtc_cleanup,
	.set_config = drm_atomic_helper_set_config,
	.page_flip = drm_atomic_helper_page_flip,
	.atomic_duplicate_state = drm_atomic_helper_crtc_duplicate_state,
	.atomic_destroy_state = drm_atomic_helper_crtc_destroy_state,
	.enable_vblank = rdcdrm_enable_vblank,
	.disable_vblank = rdcdrm_disable_vblank,
	.get_vblank_counter = rdcdrm_get_vblank_counter,
	.get_vblank_timestamp = rdcdrm_get_vblank_timestamp,
	.set_crc_source = rdcdrm_set_crc_source,
	.verify_crc_source = rdcdrm_verify_crc_source,
	.get_crc_sources = rdcdrm_get_crc_sources,
};

/* ---- Mode config --------------------------------------------------------- */

/*
 * The helpers' tail, but waiting for the flip rather than for a vblank:
 * the stepped clock has no vblank unless a commit makes one.
 */
static void rdcdrm_commit_tail(struct drm_atomic_state *old_state)
{
	struct drm_device *dev = old_state->dev;

	drm_atomic_helper_commit_modeset_disables(dev, old_state);
	drm_atomic_helper_commit_modeset_enables(dev, old_state);
	drm_atomic_helper_commit_planes(dev, old_state, 0);
	drm_atomic_helper_commit_hw_done(old_state);
	drm_atomic_helper_wait_for_flip_done(dev, old_state);
	drm_atomic_helper_cleanup_planes(dev, old_state);
}

static const struct drm_mode_config_helper_funcs rdcdrm_mode_config_helpers = {
	.atomic_commit_tail = rdcdrm_commit_tail,
};

static const struct drm_mode_config_funcs rdcdrm_mode_config_funcs = {
	.fb_create = drm_gem_fb_create_with_dirty,
	.atomic_check = drm_atomic_helper_check,
	.atomic_commit = drm_atomic_helper_commit,
};

int rdcdrm_kms_init(struct rdcdrm_device *rd)
{
	struct drm_device *drm = &rd->drm;
	struct drm_plane *cursor = NULL;
	int ret;

	ret = drmm_mode_config_init(drm);
	if (ret)
		return ret;
	drm->mode_config.min_width = 1;
	drm->mode_config.min_height = 1;
	drm->mode_config.max_width = RDC_CRTC_MAX_DISPLAY;
	drm->mode_config.max_height = RDC_CRTC_MAX_DISPLAY;
	drm->mode_config.preferred_depth = 24;
	drm->mode_config.cursor_width = RDCDRM_CURSOR_SIZE;
	drm->mode_config.cursor_height = RDCDRM_CURSOR_SIZE;
	drm->mode_config.funcs = &rdcdrm_mode_config_funcs;
	drm->mode_config.helper_private = &rdcdrm_mode_config_helpers;
	/* the counter is the chip's: 32 bits of its frame count */
	drm->max_vblank_count = U32_MAX;

	ret = drm_universal_plane_init(drm, &rd->primary, 1,
				       &rdcdrm_plane_funcs,
				       rdcdrm_primary_formats,
				       ARRAY_SIZE(rdcdrm_primary_formats), NULL,
				       DRM_PLANE_TYPE_PRIMARY, NULL);
	if (ret)
		return ret;
	drm_plane_helper_add(&rd->primary, &rdcdrm_primary_helpers);
	drm_plane_enable_fb_damage_clips(&rd->primary);

#ifdef RDC_REG_CURSOR_CTRL
	ret = drm_universal_plane_init(drm, &rd->cursor, 1, &rdcdrm_plane_funcs,
				       rdcdrm_cursor_formats,
				       ARRAY_SIZE(rdcdrm_cursor_formats), NULL,
				       DRM_PLANE_TYPE_CURSOR, NULL);
	if (ret)
		return ret;
	drm_plane_helper_add(&rd->cursor, &rdcdrm_cursor_helpers);
	drm_plane_enable_fb_damage_clips(&rd->cursor);
	cursor = &rd->cursor;
#endif

	ret = drm_crtc_init_with_planes(drm, &rd->crtc, &rd->primary, cursor,
					&rdcdrm_crtc_funcs, NULL);
	if (ret)
		return ret;
	drm_crtc_helper_add(&rd->crtc, &rdcdrm_crtc_helpers);
	drm_mode_crtc_set_gamma_size(&rd->crtc, RDCDRM_LUT_SIZE);
	drm_crtc_enable_color_mgmt(&rd->crtc, 0, false, RDCDRM_LUT_SIZE);

	ret = drm_simple_encoder_init(drm, &rd->encoder, DRM_MODE_ENCODER_DAC);
	if (ret)
		return ret;
	rd->encoder.possible_crtcs = drm_crtc_mask(&rd->crtc);

	ret = drm_connector_init(drm, &rd->connector, &rdcdrm_connector_funcs,
				 DRM_MODE_CONNECTOR_VGA);
	if (ret)
		return ret;
	drm_connector_helper_add(&rd->connector, &rdcdrm_connector_helpers);
	ret = drm_connector_attach_encoder(&rd->connector, &rd->encoder);
	if (ret)
		return ret;

	ret = drm_vblank_init(drm, 1);
	if (ret)
		return ret;
	drm_mode_config_reset(drm);
	return 0;
}
