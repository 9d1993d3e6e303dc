// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * CRTC: mode presets and validation, the line-by-line scanout state machine
 * (fetch, vblank latch, line compare), pixel format conversion through the
 * CLUT, the gamma of direct colour and the hardware cursor overlay (2 bpp
 * or ARGB8888).
 *
 * Scanout is lazy: nothing happens until someone looks (a register read,
 * a DP bus access, the run loop), and then every event whose time has come
 * is processed in order.  Every path that touches VRAM or observes the
 * CRTC catches up first, so the result is the same as a beam that runs
 * continuously.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

#define HZ_PER_KHZ	 1000u
#define RGB_MASK	 0x00ffffffu
#define CURSOR_ROW_BYTES (RDC_CURSOR_SIZE / 4) /* 2 bpp */

static const struct rdc_timing rdc_presets[RDC_PRESET_COUNT] = {
	[RDC_PRESET_320x200_70] = { 400, 320, 328, 376, 225, 200, 206, 207,
				    6300, 0 },
	[RDC_PRESET_640x480_60] = { 800, 640, 656, 752, 525, 480, 490, 492,
				    25175, 0 },
	[RDC_PRESET_800x600_60] = { 1056, 800, 840, 968, 628, 600, 601, 605,
				    40000,
				    RDC_CRTC_HSYNC_POS | RDC_CRTC_VSYNC_POS },
	[RDC_PRESET_1024x768_60] = { 1344, 1024, 1048, 1184, 806, 768, 771, 777,
				     65000, 0 },
	[RDC_PRESET_1280x720_60] = { 1650, 1280, 1390, 1430, 750, 720, 725, 730,
				     74250,
				     RDC_CRTC_HSYNC_POS | RDC_CRTC_VSYNC_POS },
	[RDC_PRESET_1920x1080_60] = { 2200, 1920, 2008, 2052, 1125, 1080, 1084,
				      1089, 148500,
				      RDC_CRTC_HSYNC_POS | RDC_CRTC_VSYNC_POS },
};

int rdc_preset_timing(uint32_t preset, struct rdc_timing *t)
{
	if (preset >= RDC_PRESET_COUNT)
		return -1;
	*t = rdc_presets[preset];
	return 0;
}

/* Core cycles from the start of a frame to the start of line n. */
static uint64_t line_offset(const struct rdc_hw *hw,
			    const struct rdc_timing *tm, uint32_t n)
{
	return (uint64_t)n * tm->h_total * hw->core_hz /
	       ((uint64_t)tm->pixclk_khz * HZ_PER_KHZ);
}

/*
 * line_offset of c->next_line in `cur`, and one line's step, for
 * crtc_line_step: after every change of `cur` or of next_line other than
 * the step itself.
 */
static void crtc_line_sync(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t num = (uint64_t)c->cur.h_total * hw->core_hz;
	uint64_t den = (uint64_t)c->cur.pixclk_khz * HZ_PER_KHZ;

	if (!den) {
		c->line_den = 0;
		return;
	}
	c->line_den = den;
	c->step_q = num / den;
	c->step_r = num % den;
	c->line_q = (uint64_t)c->next_line * num / den;
	c->line_r = (uint64_t)c->next_line * num % den;
}

/* line_offset(hw, &c->cur, c->next_line + 1), from the last one. */
static inline uint64_t crtc_line_step(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;

	if (!c->line_den) /* no mode in force: as line_offset divides */
		return line_offset(hw, &c->cur, c->next_line + 1);
	c->line_q += c->step_q;
	c->line_r += c->step_r;
	if (c->line_r >= c->line_den) {
		c->line_r -= c->line_den;
		c->line_q++;
	}
	return c->line_q;
}

static bool timing_axis_ok(uint32_t disp, uint32_t ss, uint32_t se,
			   uint32_t total)
{
	return disp >= 1 && disp <= RDC_CRTC_MAX_DISPLAY && disp <= ss &&
	       ss <= se && se <= total && total <= RDC_CRTC_MAX_TOTAL;
}

static bool timing_ok(const struct rdc_hw *hw, const struct rdc_timing *tm)
{
	if (!timing_axis_ok(tm->h_display, tm->h_sync_start, tm->h_sync_end,
			    tm->h_total) ||
	    !timing_axis_ok(tm->v_display, tm->v_sync_start, tm->v_sync_end,
			    tm->v_total))
		return false;
	if (tm->v_display >= tm->v_total) /* no vertical blanking */
		return false;
	if (tm->pixclk_khz < RDC_PIXCLK_MIN_KHZ ||
	    tm->pixclk_khz > RDC_PIXCLK_MAX_KHZ)
		return false;
	if (line_offset(hw, tm, 1) < 1) /* a line shorter than a core cycle */
		return false;
	return (uint64_t)tm->h_display * tm->v_display <= hw->frame_cap &&
	       hw->frame[0] && hw->frame[1];
}

static bool timing_same(const struct rdc_timing *a, const struct rdc_timing *b)
{
	return a->h_total == b->h_total && a->h_display == b->h_display &&
	       a->h_sync_start == b->h_sync_start &&
	       a->h_sync_end == b->h_sync_end && a->v_total == b->v_total &&
	       a->v_display == b->v_display &&
	       a->v_sync_start == b->v_sync_start &&
	       a->v_sync_end == b->v_sync_end &&
	       a->pixclk_khz == b->pixclk_khz && a->flags == b->flags;
}

/*
 * Copy the shadows to the working set.  At vblank a new timing waits for
 * the next frame start (the blank lines of this frame keep the old one);
 * when scanout starts it goes in force at once.
 */
static void crtc_latch(struct rdc_hw *hw, bool at_vblank)
{
	struct rdc_crtc *c = &hw->crtc;

	if (c->shadow_dirty || !c->mode_valid) {
		const struct rdc_timing *in_force =
			c->mode_pending ? &c->pending : &c->cur;

		if (!timing_ok(hw, &c->shadow)) {
			rdc_port_error(hw, RDC_ERR_MODE, RDC_REG_H_TOTAL);
		} else if (!c->mode_valid || !at_vblank) {
			c->cur = c->shadow;
			c->mode_valid = 1;
			c->mode_pending = 0;
			crtc_line_sync(hw);
		} else if (!timing_same(in_force, &c->shadow)) {
			c->pending = c->shadow;
			c->mode_pending = !timing_same(&c->cur, &c->shadow);
		}
		if (c->fb_format < RDC_FMT_COUNT)
			c->cur_format = c->fb_format;
		else
			rdc_port_error(hw, RDC_ERR_MODE, RDC_REG_FB_FORMAT);
		c->shadow_dirty = 0;
	}
	c->cur_base = c->fb_base;
	c->cur_stride = c->fb_stride;
	c->cur_gamma = (hw->control & RDC_CONTROL_GAMMA_EN) != 0;
	c->cur_cursor_ctrl = c->cursor_ctrl;
	c->cur_cursor_base = c->cursor_base;
	c->cur_raster_base = c->raster_base;
	c->cur_raster_ctrl = c->raster_ctrl;
	/*
	 * The 2 bpp image is latched whole; ARGB8888 rows are fetched a line
	 * at a time (cursor_argb_row).
	 */
	if (FIELD_GET(RDC_CURSOR_CTRL_FMT, c->cur_cursor_ctrl) ==
	    RDC_CURSOR_FMT_2BPP) {
		if ((uint64_t)c->cursor_base + RDC_CURSOR_BYTES <=
		    hw->vram_size)
			rdc_memcpy(c->cursor_img, hw->vram + c->cursor_base,
				   RDC_CURSOR_BYTES);
		else
			rdc_memset(c->cursor_img, 0, RDC_CURSOR_BYTES);
	}
	rdc_clut_latch(hw);
}

/* Is the cursor on, with ARGB8888 latched? */
static inline bool cursor_argb(const struct rdc_hw *hw)
{
	return (hw->control & RDC_CONTROL_CURSOR_EN) &&
	       FIELD_GET(RDC_CURSOR_CTRL_FMT, hw->crtc.cur_cursor_ctrl) ==
		       RDC_CURSOR_FMT_ARGB8888;
}

/*
 * The VRAM address of the ARGB8888 cursor row that active line n of `tm`
 * shows, fetched at the line's start; false if the line shows none: the
 * cursor off or 2 bpp, not on this line, wholly left or right of the
 * display, or the row leaving VRAM (then it is not fetched and shows
 * nothing).
 */
static inline bool cursor_argb_row(const struct rdc_hw *hw,
				   const struct rdc_timing *tm, uint32_t n,
				   uint64_t *addr)
{
	const struct rdc_crtc *c = &hw->crtc;
	int32_t size, cx, cy;
	int64_t dy;

	if (!cursor_argb(hw))
		return false;
	size = (int32_t)rdc_cursor_size(c->cur_cursor_ctrl);
	cx = (int16_t)(c->cursor_pos & 0xffff);
	cy = (int16_t)(c->cursor_pos >> 16);
	dy = (int64_t)n - cy;
	if (dy < 0 || dy >= size || cx <= -size || cx >= (int32_t)tm->h_display)
		return false;
	*addr = c->cur_cursor_base + (uint64_t)dy * (uint32_t)size * 4;
	return *addr + (uint32_t)size * 4 <= hw->vram_size;
}

/* VRAM range of active line n; false if it leaves VRAM (scans black). */
static bool line_range(const struct rdc_hw *hw, const struct rdc_timing *tm,
		       uint32_t n, uint64_t *addr, uint32_t *bytes)
{
	const struct rdc_crtc *c = &hw->crtc;

	*bytes = rdc_format_row_bytes(c->cur_format, tm->h_display);
	*addr = c->cur_base + (uint64_t)n * c->cur_stride;
	return *addr + *bytes <= hw->vram_size;
}

/* Does the raster list fetch at the start of line n (the next one)? */
static bool raster_fetches_at(const struct rdc_hw *hw, uint32_t n)
{
	const struct rdc_crtc *c = &hw->crtc;

	if (n == 0) /* it restarts */
		return (c->cur_raster_ctrl & RDC_RASTER_CTRL_EN) &&
		       rdc_crtc_raster_fetches(
			       hw, c->cur_raster_base & RDC_RASTER_BASE_MASK,
			       0);
	return (c->rl_wait < n || (c->rl_wait == n && !c->rl_wait_x)) &&
	       rdc_crtc_raster_fetches(hw, c->rl_addr, c->rl_count);
}

int rdc_crtc_next_fetches(const struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	const struct rdc_timing *tm = &c->cur;
	uint32_t n = c->next_line, bytes;
	uint64_t addr;

	if (!c->running)
		return 0;
	if (c->rl_mid) /* a raster-list WAIT's column */
		return rdc_crtc_raster_fetches(hw, c->rl_addr, c->rl_count);
	if (n >= tm->v_total) { /* line 0 of the next frame */
		n = 0;
		if (c->mode_pending)
			tm = &c->pending;
	}
	if (raster_fetches_at(hw, n))
		return 1;
	return n < tm->v_display && (line_range(hw, tm, n, &addr, &bytes) ||
				     cursor_argb_row(hw, tm, n, &addr));
}

/*
 * Sub-byte indexed pixels, leftmost in the most significant bits: one byte
 * at a time, so that with bpp a constant the inner loop unrolls.
 */
static inline void convert_indexed(const uint32_t *clut, uint32_t *out,
				   const uint8_t *src, uint32_t w,
				   unsigned int bpp)
{
	const unsigned int per_byte = 8 / bpp, mask = (1u << bpp) - 1;
	uint32_t x = 0, k;

	for (; x + per_byte <= w; x += per_byte) {
		uint32_t b = *src++;

		for (k = 0; k < per_byte; k++)
			out[x + k] = clut[(b >> (8 - bpp * (k + 1))) & mask];
	}
	for (k = 0; x < w; x++, k++)
		out[x] = clut[(*src >> (8 - bpp * (k + 1))) & mask];
}

/*
 * XRGB8888 lines are the common case: blocks of a fixed pixel count with
 * no aliasing let the compiler use its widest loads and stores with no
 * run-time checks, so a line costs about a memcpy.  Kept out of line:
 * inlined, the restrict qualifiers are lost and the loop stays scalar.
 * Where the port streams stores (RDC_STREAM), the frame is streamed past
 * the caches, which then keep VRAM for the drawing that goes on while the
 * beam runs (rdc-bench, scanout on: fill, blit and line about 5% less
 * CPU); crtc_vblank fences the frame before it hands it on.
 */
#define XRGB_BLOCK 16u

static rdc_noinline void convert_xrgb(uint32_t *restrict out,
				      const uint8_t *restrict src, uint32_t w)
{
	uint32_t k;
#if RDC_STREAM
	const rdc_u32x4 mask = { RGB_MASK, RGB_MASK, RGB_MASK, RGB_MASK };

	for (; w && ((uintptr_t)out & 15); w--, out++, src += 4)
		*out = rdc_ld32(src) & RGB_MASK;
	for (; w >= 4; w -= 4, out += 4, src += 16) {
		rdc_u32x4 v;

		rdc_memcpy(&v, src, 16);
		rdc_stream16(out, v & mask);
	}
#endif

	for (; w >= XRGB_BLOCK; w -= XRGB_BLOCK) {
		for (k = 0; k < XRGB_BLOCK; k++)
			out[k] = rdc_ld32(src + 4 * k) & RGB_MASK;
		out += XRGB_BLOCK;
		src += 4 * XRGB_BLOCK;
	}
	for (k = 0; k < w; k++)
		out[k] = rdc_ld32(src + 4 * k) & RGB_MASK;
}

/*
 * 8 bpp indexed lines (the CLUT's common case): the indices of eight
 * pixels from two 32-bit loads rather than a byte load each; out of line
 * for the same reason as convert_xrgb.
 */
static rdc_noinline void convert_i8(const uint32_t *restrict clut,
				    uint32_t *restrict out,
				    const uint8_t *restrict src, uint32_t w)
{
	uint32_t x = 0;

	for (; x + 8 <= w; x += 8) {
		uint32_t lo = rdc_ld32(src + x), hi = rdc_ld32(src + x + 4);

		out[x] = clut[lo & 0xff];
		out[x + 1] = clut[(lo >> 8) & 0xff];
		out[x + 2] = clut[(lo >> 16) & 0xff];
		out[x + 3] = clut[lo >> 24];
		out[x + 4] = clut[hi & 0xff];
		out[x + 5] = clut[(hi >> 8) & 0xff];
		out[x + 6] = clut[(hi >> 16) & 0xff];
		out[x + 7] = clut[hi >> 24];
	}
	for (; x < w; x++)
		out[x] = clut[src[x]];
}

static void convert_line(const struct rdc_hw *hw, uint32_t *out,
			 const uint8_t *src, uint32_t w, uint32_t fmt)
{
	const uint32_t *clut = hw->clut;
	uint32_t x, v, r, g, b;

	switch (fmt) {
	case RDC_FMT_I1:
		convert_indexed(clut, out, src, w, 1);
		break;
	case RDC_FMT_I2:
		convert_indexed(clut, out, src, w, 2);
		break;
	case RDC_FMT_I4:
		convert_indexed(clut, out, src, w, 4);
		break;
	case RDC_FMT_I8:
		convert_i8(clut, out, src, w);
		break;
	case RDC_FMT_RGB565:
		for (x = 0; x < w; x++) {
			v = rdc_ld16(src + 2 * x);
			r = (v >> 11) & 0x1f;
			g = (v >> 5) & 0x3f;
			b = v & 0x1f;
			out[x] = ((r << 3 | r >> 2) << 16) |
				 ((g << 2 | g >> 4) << 8) | (b << 3 | b >> 2);
		}
		break;
	case RDC_FMT_RGB888:
		for (x = 0; x < w; x++)
			out[x] = rdc_ld24(src + 3 * x);
		break;
	case RDC_FMT_XRGB8888:
		convert_xrgb(out, src, w);
		break;
	default:
		rdc_memset(out, 0, (size_t)w * sizeof(*out));
		break;
	}
}

/*
 * GAMMA_EN: each component of a direct-colour pixel through the CLUT's
 * entry of its value, in that entry's own component.
 */
static void gamma_line(const uint32_t *clut, uint32_t *out, uint32_t w)
{
	uint32_t x;

	for (x = 0; x < w; x++) {
		uint32_t v = out[x];

		out[x] = (clut[(v >> 16) & 0xff] & 0xff0000u) |
			 (clut[(v >> 8) & 0xff] & 0x00ff00u) |
			 (clut[v & 0xff] & 0x0000ffu);
	}
}

/*
 * One component of a premultiplied cursor pixel over the screen's: c +
 * d (255 - a) / 255 rounded to nearest, saturated at 255 (a component
 * above its alpha is not premultiplied).  With t = d (255 - a) + 128,
 * ((t >> 8) + t) >> 8 is (d (255 - a) + 127) / 255 for every 8-bit d and
 * a, without the division.
 */
static inline uint32_t cursor_over(uint32_t c, uint32_t d, uint32_t a)
{
	uint32_t t = d * (255 - a) + 128;
	uint32_t v = c + (((t >> 8) + t) >> 8);

	return v > 255 ? 255 : v;
}

/*
 * The ARGB8888 cursor's row at VRAM `addr` over pixels [x0, x0 + w) of a
 * line, out[0] being pixel x0, clipped.
 */
static void cursor_argb_line(const struct rdc_hw *hw, uint32_t *out, int32_t x0,
			     uint32_t w, uint64_t addr)
{
	const struct rdc_crtc *c = &hw->crtc;
	const uint8_t *row = hw->vram + addr;
	int32_t size = (int32_t)rdc_cursor_size(c->cur_cursor_ctrl);
	int32_t cx = (int16_t)(c->cursor_pos & 0xffff) - x0;
	int32_t i = cx < 0 ? -cx : 0;
	int32_t end = RDC_MIN(size, (int32_t)w - cx);

	for (; i < end; i++) {
		uint32_t p = rdc_ld32(row + 4 * i), a = p >> 24;
		uint32_t d = out[cx + i], r, g, b;

		r = cursor_over((p >> 16) & 0xff, (d >> 16) & 0xff, a);
		g = cursor_over((p >> 8) & 0xff, (d >> 8) & 0xff, a);
		b = cursor_over(p & 0xff, d & 0xff, a);
		out[cx + i] = r << 16 | g << 8 | b;
	}
}

/* The ARGB8888 cursor row's fetch: after the line's, in its window. */
static void cursor_argb_fetch(struct rdc_hw *hw, uint64_t when, uint64_t addr)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t start = RDC_MAX(when, c->fetch_end);
	uint32_t bytes = rdc_cursor_size(c->cur_cursor_ctrl) * 4;

	c->fetch_end =
		start + rdc_bus_read_cost(&hw->bus.open_row, addr, bytes);
}

/* The 2 bpp cursor over pixels [x0, x0 + w) of line n, out[0] pixel x0. */
static void cursor_line(const struct rdc_hw *hw, uint32_t *out, uint32_t n,
			int32_t x0, uint32_t w)
{
	const struct rdc_crtc *c = &hw->crtc;
	int32_t cx = (int16_t)(c->cursor_pos & 0xffff) - x0;
	int32_t cy = (int16_t)(c->cursor_pos >> 16);
	int32_t dy = (int32_t)n - cy;
	const uint8_t *row;
	int32_t i;

	if (dy < 0 || dy >= RDC_CURSOR_SIZE)
		return;
	row = c->cursor_img + dy * CURSOR_ROW_BYTES;
	for (i = 0; i < RDC_CURSOR_SIZE; i++) {
		int32_t x = cx + i;
		uint32_t v;

		if (x < 0 || x >= (int32_t)w)
			continue;
		v = (row[i / 4] >> (6 - 2 * (i % 4))) & 3;
		if (v == 1)
			out[x] = c->cursor_fg & RGB_MASK;
		else if (v == 2)
			out[x] = c->cursor_bg & RGB_MASK;
		else if (v == 3)
			out[x] ^= RGB_MASK;
	}
}

/*
 * Convert active line n of the frame in buffer `buf` as the CRTC fetched
 * it (crtc_fetch, or later for a line that waited: then nothing it reads
 * has changed since, or the write barrier would have dropped it).  While
 * BL_EN is low the panel is dark: the line shows black, cursor included.
 */
static void crtc_convert(struct rdc_hw *hw, unsigned int buf, uint32_t n)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t w = c->cur.h_display, bytes;
	uint32_t *out = hw->frame[buf] + (size_t)n * w;
	uint64_t addr, cursor_addr = 0;
	bool lit = hw->pins_in & RDC_PIN_BL_EN;
	bool argb = cursor_argb_row(hw, &c->cur, n, &cursor_addr);

	if (lit && line_range(hw, &c->cur, n, &addr, &bytes)) {
		convert_line(hw, out, hw->vram + addr, w, c->cur_format);
		if (c->cur_gamma && !rdc_format_indexed(c->cur_format)) {
			rdc_stream_fence(); /* read after the stores */
			gamma_line(hw->clut, out, w);
		}
	} else {
		rdc_memset(out, 0, (size_t)w * sizeof(*out));
	}
	if (lit && (hw->control & RDC_CONTROL_CURSOR_EN)) {
		rdc_stream_fence(); /* the cursor's stores after the line's */
		if (argb)
			cursor_argb_line(hw, out, 0, w, cursor_addr);
		else if (FIELD_GET(RDC_CURSOR_CTRL_FMT, c->cur_cursor_ctrl) ==
			 RDC_CURSOR_FMT_2BPP)
			cursor_line(hw, out, n, 0, w);
	}
}

/* ---- light pen ------------------------------------------------------------ */

/*
 * Pixel x of active line n as crtc_convert makes it, at the line's fetch:
 * the one pixel through the same conversion, gamma and cursor.
 */
static uint32_t crtc_pixel(const struct rdc_hw *hw, uint32_t n, uint32_t x)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t fmt = c->cur_format, bpp = rdc_format_bpp(fmt), bytes, v = 0;
	uint64_t addr, cursor_addr = 0;
	bool argb = cursor_argb_row(hw, &c->cur, n, &cursor_addr);

	if (!(hw->pins_in & RDC_PIN_BL_EN))
		return 0;
	if (line_range(hw, &c->cur, n, &addr, &bytes)) {
		const uint8_t *p = hw->vram + addr + (uint64_t)x * bpp / 8;

		if (rdc_format_indexed(fmt)) {
			unsigned int k = x % (8 / bpp);

			v = hw->clut[(*p >> (8 - bpp * (k + 1))) &
				     ((1u << bpp) - 1)];
		} else {
			convert_line(hw, &v, p, 1, fmt);
			if (c->cur_gamma)
				gamma_line(hw->clut, &v, 1);
		}
	}
	if (hw->control & RDC_CONTROL_CURSOR_EN) {
		if (argb)
			cursor_argb_line(hw, &v, (int32_t)x, 1, cursor_addr);
		else if (FIELD_GET(RDC_CURSOR_CTRL_FMT, c->cur_cursor_ctrl) ==
			 RDC_CURSOR_FMT_2BPP)
			cursor_line(hw, &v, n, (int32_t)x, 1);
	}
	return v;
}

/*
 * Line n, the pen's, starts at `when`: is the pen's pixel lit?  Then the
 * strobe comes when the beam reaches its column.
 */
static rdc_noinline void crtc_lpen_line(struct rdc_hw *hw, uint32_t n,
					uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t x = FIELD_GET(RDC_LPEN_X, c->lpen_pos), v, luma;
	uint64_t pix_hz = (uint64_t)c->cur.pixclk_khz * HZ_PER_KHZ;

	if (n >= c->cur.v_display || x >= c->cur.h_display || !pix_hz)
		return;
	v = crtc_pixel(hw, n, x);
	luma = (77 * ((v >> 16) & 0xff) + 150 * ((v >> 8) & 0xff) +
		29 * (v & 0xff) + 128) >>
	       8;
	if (luma <= FIELD_GET(RDC_LPEN_CTRL_THRESHOLD, c->lpen_ctrl))
		return;
	c->lpen_time = when + ((uint64_t)x * hw->core_hz + pix_hz - 1) / pix_hz;
}

/* The strobe: the latch takes the beam, at its own time. */
static rdc_noinline void crtc_lpen_strobe(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t when = c->lpen_time;

	c->lpen_time = RDC_NEVER;
	if (hw->now < when)
		hw->now = when;
	c->lpen_latch = c->lpen_pos;
	c->lpen_hit = 1;
	rdc_irq_raise(hw, RDC_IRQ_LPEN);
	rdc_pins_update(hw, when);
}

/* ---- scanout on demand (rdc_hw_set_on_demand) ---------------------------- */

/* VRAM bytes the waiting lines of buffer b read: [*lo, *hi), or false. */
static bool scan_bytes(const struct rdc_hw *hw, unsigned int b, uint64_t *lo,
		       uint64_t *hi)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t first = hw->pend_lo[b], last = hw->pend_hi[b], bytes;
	uint64_t a0, a1;

	if (first == last)
		return false;
	*lo = UINT64_MAX;
	*hi = 0;
	bytes = rdc_format_row_bytes(c->cur_format, c->cur.h_display);
	a0 = c->cur_base + (uint64_t)first * c->cur_stride;
	a1 = c->cur_base + (uint64_t)(last - 1) * c->cur_stride + bytes;
	if (a0 < hw->vram_size) {
		*lo = a0;
		*hi = RDC_MIN(a1, (uint64_t)hw->vram_size);
	}
	if (cursor_argb(hw)) {
		uint64_t size = rdc_cursor_size(c->cur_cursor_ctrl);
		uint64_t e = c->cur_cursor_base + size * size * 4;

		*lo = RDC_MIN(*lo, (uint64_t)c->cur_cursor_base);
		*hi = RDC_MAX(*hi, RDC_MIN(e, (uint64_t)hw->vram_size));
	}
	return *lo < *hi;
}

/* The write barrier's bounds, after the waiting lines changed. */
static void scan_bounds(struct rdc_hw *hw)
{
	uint64_t lo = UINT64_MAX, hi = 0, l, h;
	unsigned int b;

	for (b = 0; b < 2; b++) {
		if (scan_bytes(hw, b, &l, &h)) {
			lo = RDC_MIN(lo, l);
			hi = RDC_MAX(hi, h);
		}
	}
	if (lo >= hi)
		lo = hi = 0;
	hw->scan_lo = lo;
	hw->scan_hi = hi;
}

/* Drop the waiting lines of the buffers in mask `bufs`, and their frames. */
static void scan_drop(struct rdc_hw *hw, unsigned int bufs)
{
	unsigned int b;

	for (b = 0; b < 2; b++) {
		if (!(bufs & (1u << b)) || hw->pend_lo[b] == hw->pend_hi[b])
			continue;
		hw->frame_ok[b] = false;
		hw->pend_lo[b] = hw->pend_hi[b] = 0;
	}
	scan_bounds(hw);
}

void rdc_scan_drop_all(struct rdc_hw *hw)
{
	scan_drop(hw, 3);
}

rdc_noinline void rdc_scan_write(struct rdc_hw *hw, uint64_t lo, uint64_t hi)
{
	uint64_t l, h;
	unsigned int b, bufs = 0;

	for (b = 0; b < 2; b++)
		if (scan_bytes(hw, b, &l, &h) && lo < h && hi > l)
			bufs |= 1u << b;
	scan_drop(hw, bufs);
}

/* Convert the waiting lines of the buffers in mask `bufs`. */
void rdc_scan_convert(struct rdc_hw *hw, unsigned int bufs)
{
	unsigned int b;
	uint32_t n;

	for (b = 0; b < 2; b++) {
		if (!(bufs & (1u << b)))
			continue;
		for (n = hw->pend_lo[b]; n < hw->pend_hi[b]; n++)
			crtc_convert(hw, b, n);
		hw->pend_lo[b] = hw->pend_hi[b] = 0;
	}
	rdc_stream_fence();
	scan_bounds(hw);
}

void rdc_scan_update(struct rdc_hw *hw)
{
	hw->lazy = hw->on_demand && !hw->consumers && !hw->frame_fn;
	if (!hw->lazy)
		rdc_scan_convert(hw, 3);
}

void rdc_scan_front(struct rdc_hw *hw)
{
	unsigned int front = hw->frame_back ^ 1;

	if (hw->pend_lo[front] != hw->pend_hi[front])
		rdc_scan_convert(hw, 1u << front);
}

/* A new frame goes into buffer b: nothing of it fetched, nothing lost. */
static void scan_new_frame(struct rdc_hw *hw, unsigned int b)
{
	hw->frame_ok[b] = true;
	if (hw->pend_lo[b] != hw->pend_hi[b]) {
		hw->pend_lo[b] = hw->pend_hi[b] = 0;
		scan_bounds(hw);
	}
}

/* Line n, fetched into the back buffer, waits for a look. */
static void scan_defer(struct rdc_hw *hw, uint32_t n)
{
	unsigned int b = hw->frame_back;

	if (!hw->frame_ok[b])
		return;
	if (hw->pend_lo[b] == hw->pend_hi[b])
		hw->pend_lo[b] = n;
	hw->pend_hi[b] = n + 1;
	scan_bounds(hw);
}

/* ---- raster list (run by raster.c) --------------------------------------- */

uint64_t rdc_crtc_column_time(const struct rdc_hw *hw, uint32_t x)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint64_t pix_hz = (uint64_t)c->cur.pixclk_khz * HZ_PER_KHZ;

	return c->rl_line_start +
	       ((uint64_t)x * hw->core_hz + pix_hz - 1) / pix_hz;
}

/*
 * A raster-list CLUT write at column x of line n changed an entry: the
 * line was converted with the CLUT it had before (eagerly at its fetch,
 * or by raster_settle just now), so its pixels from x on are converted
 * again from the bytes its fetch read (rl_line), through the new CLUT,
 * gamma and the cursor as crtc_convert does.  Only when the frame is
 * kept and the list waited for this column from the line's start.
 */
void rdc_crtc_raster_split(struct rdc_hw *hw, uint32_t n, uint32_t x)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t w = c->cur.h_display, fmt = c->cur_format;
	uint32_t bpp = rdc_format_bpp(fmt), x0 = x, keep[8], i;
	bool indexed = rdc_format_indexed(fmt);
	uint64_t cursor_addr = 0;
	uint32_t *out;

	if (n >= c->cur.v_display || x >= w || c->rl_line_n != n ||
	    !hw->frame_ok[hw->frame_back] || !(hw->pins_in & RDC_PIN_BL_EN) ||
	    (!indexed && !c->cur_gamma))
		return;
	out = hw->frame[hw->frame_back] + (size_t)n * w;
	if (bpp <
	    8) /* from the byte that holds pixel x, the ones before kept */
		x0 = x - x % (8 / bpp);
	for (i = x0; i < x; i++)
		keep[i - x0] = out[i];
	convert_line(hw, out + x0, c->rl_line + (uint64_t)x0 * bpp / 8, w - x0,
		     fmt);
	for (i = x0; i < x; i++)
		out[i] = keep[i - x0];
	if (!indexed)
		gamma_line(hw->clut, out + x, w - x);
	if (!(hw->control & RDC_CONTROL_CURSOR_EN))
		return;
	if (cursor_argb_row(hw, &c->cur, n, &cursor_addr))
		cursor_argb_line(hw, out + x, (int32_t)x, w - x, cursor_addr);
	else if (FIELD_GET(RDC_CURSOR_CTRL_FMT, c->cur_cursor_ctrl) ==
		 RDC_CURSOR_FMT_2BPP)
		cursor_line(hw, out + x, n, (int32_t)x, w - x);
}

/*
 * Line n starts: the list restarts at line 0 and runs if its WAIT is met.
 * Left waiting for a column of an active line, it keeps the bytes the
 * line's fetch reads, for rdc_crtc_raster_split.
 */
static inline void raster_line(struct rdc_hw *hw, uint32_t n, uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t addr;
	uint32_t bytes;

	if (n == 0) {
		c->rl_count = 0;
		c->rl_wait = RDC_NEVER_LINE;
		c->rl_line_n = RDC_NEVER_LINE;
		if (!(c->cur_raster_ctrl & RDC_RASTER_CTRL_EN))
			return;
		c->rl_addr = c->cur_raster_base & RDC_RASTER_BASE_MASK;
		c->rl_wait = 0;
		c->rl_wait_x = 0;
	}
	if (c->rl_wait > n)
		return;
	c->rl_line_start = when;
	rdc_raster_run(hw, n, 0, when);
	if (c->rl_mid && n < c->cur.v_display &&
	    line_range(hw, &c->cur, n, &addr, &bytes)) {
		rdc_memcpy(c->rl_line, hw->vram + addr, bytes);
		c->rl_line_n = n;
	}
}

/* The beam reaches the column a WAIT of the list holds at, on this line. */
static rdc_noinline void raster_column(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t when = c->next_line_time;

	c->rl_mid = 0;
	c->next_line_time = c->rl_next_line;
	if (hw->now < when)
		hw->now = when;
	rdc_raster_run(hw, c->next_line - 1, c->rl_wait_x, when);
}

/*
 * The bus's side of active line n's fetch: its bytes read from VRAM,
 * from the line's start or the end of a fetch still running, moving
 * fetch_end.  Inline: with scanout put off, a quiet line start
 * (rdc_crtc_quiet_line), the DP's most frequent event, is little more
 * than this.
 */
static rdc_always_inline void crtc_read_line(struct rdc_hw *hw, uint32_t n,
					     uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t bytes;
	uint64_t addr;

	if (line_range(hw, &c->cur, n, &addr, &bytes)) {
		uint64_t start = RDC_MAX(when, c->fetch_end);

		c->fetch_end = start + rdc_bus_read_cost(&hw->bus.open_row,
							 addr, bytes);
	}
}

/*
 * Start of active line n: the CRTC reads it (and the ARGB8888 cursor's
 * row on it, in the same window) and converts it at once.  The bus sees
 * every fetch; the conversion is skipped (`hidden`) for a frame that
 * nobody can ever look at, and put off while nobody looks (hw->lazy).
 */
static rdc_always_inline void crtc_fetch(struct rdc_hw *hw, uint32_t n,
					 uint64_t when, bool hidden)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t cursor_addr = 0;
	bool argb = cursor_argb_row(hw, &c->cur, n, &cursor_addr);

	crtc_read_line(hw, n, when);
	if (argb)
		cursor_argb_fetch(hw, when, cursor_addr);
	if (hidden) {
		hw->frame_ok[hw->frame_back] = false;
		return;
	}
	if (hw->lazy) {
		scan_defer(hw, n);
		return;
	}
	crtc_convert(hw, hw->frame_back, n);
}

/*
 * Would the latch at this vblank change how a line of the frame just
 * completed converts?  (Its waiting lines are dropped then.)
 */
static bool crtc_latch_changes(const struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	uint32_t i;

	if (c->shadow_dirty || !c->mode_valid || c->mode_pending ||
	    hw->clut_dirty || c->cur_base != c->fb_base ||
	    c->cur_stride != c->fb_stride ||
	    c->cur_gamma != ((hw->control & RDC_CONTROL_GAMMA_EN) != 0) ||
	    c->cur_cursor_ctrl != c->cursor_ctrl ||
	    c->cur_cursor_base != c->cursor_base)
		return true;
	if (FIELD_GET(RDC_CURSOR_CTRL_FMT, c->cursor_ctrl) !=
	    RDC_CURSOR_FMT_2BPP)
		return false;
	if ((uint64_t)c->cursor_base + RDC_CURSOR_BYTES > hw->vram_size) {
		for (i = 0; i < RDC_CURSOR_BYTES; i++)
			if (c->cursor_img[i])
				return true;
		return false;
	}
	for (i = 0; i < RDC_CURSOR_BYTES; i++)
		if (c->cursor_img[i] != hw->vram[c->cursor_base + i])
			return true;
	return false;
}

static void crtc_vblank(struct rdc_hw *hw, uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t w = c->cur.h_display, h = c->cur.v_display;
	uint64_t number = c->frame_count;

	c->in_vblank = 1;
	rdc_irq_raise(hw, RDC_IRQ_VBLANK);
	rdc_pins_update(hw, when); /* TE rises, IRQ with it if enabled */
	hw->frame_back ^= 1;
	hw->front_w = w;
	hw->front_h = h;
	hw->have_frame = 1;
	c->frame_count++;
	rdc_trace(hw, RDC_TRACE_VBLANK, (uint32_t)number, 0);
	scan_new_frame(hw, hw->frame_back);
	/*
	 * A raster list that changed the base, stride, cursor or CLUT this
	 * frame changes them at every vblank: what waits is converted, as
	 * raster_settle does, rather than the frame lost each time.
	 */
	if (hw->pend_lo[hw->frame_back ^ 1] !=
		    hw->pend_hi[hw->frame_back ^ 1] &&
	    crtc_latch_changes(hw)) {
		if (c->rl_touched)
			rdc_scan_convert(hw, 1u << (hw->frame_back ^ 1));
		else
			scan_drop(hw, 1u << (hw->frame_back ^ 1));
	}
	c->rl_touched = 0;
	crtc_latch(hw, true);
	rdc_stream_fence(); /* the frame whole before anyone reads it */
	if (hw->frame_fn && hw->frame_ok[hw->frame_back ^ 1])
		hw->frame_fn(hw->frame_ctx, hw->frame[hw->frame_back ^ 1], w, h,
			     number);
}

/*
 * When the frame after this one will be complete: the frame scanned now is
 * on show from its own vblank until then.  Only this frame's active lines
 * ask, so its vblank latch is still to come, and as registers cannot change
 * during a catch-up, what that latch will do is known in advance.
 */
static uint64_t crtc_next_frame_vblank(const struct rdc_hw *hw)
{
	const struct rdc_crtc *c = &hw->crtc;
	const struct rdc_timing *next = c->mode_pending ? &c->pending : &c->cur;

	if (c->shadow_dirty && timing_ok(hw, &c->shadow))
		next = &c->shadow;
	return c->frame_start + c->frame_cycles +
	       line_offset(hw, next, next->v_display);
}

/*
 * What the catch-up to t compares with t: crtc_next_frame_vblank, or,
 * when t comes before the next frame starts (and so before its vblank),
 * that start, which compares the same and needs no division.
 */
static inline uint64_t crtc_shown_until(const struct rdc_hw *hw, uint64_t t)
{
	const struct rdc_crtc *c = &hw->crtc;

	if (t < c->frame_start + c->frame_cycles)
		return c->frame_start + c->frame_cycles;
	return crtc_next_frame_vblank(hw);
}

/*
 * A line start's signals for the trace and the pins, out of line: the
 * loop below carries only a test and a branch a line for them when nobody
 * traces (the frame-skip path runs millions of line starts a second).
 */
static rdc_noinline void crtc_line_signals(struct rdc_hw *hw, uint32_t n,
					   uint64_t when)
{
	rdc_trace_at(hw, when, RDC_TRACE_LINE, n, n >= hw->crtc.cur.v_display);
	if (n == 0) {
		hw->crtc.in_vblank = 0;
		rdc_pins_update(hw, when);
	}
}

static rdc_noinline void crtc_line_compare(struct rdc_hw *hw, uint64_t when)
{
	rdc_irq_raise(hw, RDC_IRQ_LINE);
	rdc_pins_update(hw, when);
}

/*
 * Step past the start of line n, at `when`: the next event is line n + 1's
 * start, and simulated time has reached this one.
 */
static inline void crtc_step_past(struct rdc_hw *hw, uint32_t n, uint64_t when)
{
	struct rdc_crtc *c = &hw->crtc;

	c->next_line_time = c->frame_start + crtc_line_step(hw);
	c->next_line = n + 1;
	if (hw->now < when)
		hw->now = when;
}

/*
 * rdc_crtc_quiet_line's fetch where crtc_fetch has more to do than read
 * the line (the ARGB8888 cursor's row, a frame converted at its fetch),
 * and its put-off line where the frame is kept: calls out of line, made
 * last, so that the common line start saves no registers.
 */
static rdc_noinline bool quiet_fetch(struct rdc_hw *hw, uint32_t n,
				     uint64_t when, uint64_t end)
{
	crtc_fetch(hw, n, when, false);
	return hw->crtc.fetch_end != end;
}

static rdc_noinline bool quiet_defer(struct rdc_hw *hw, uint32_t n,
				     bool fetched)
{
	scan_defer(hw, n);
	return fetched;
}

bool rdc_crtc_quiet_line(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t n = c->next_line;
	uint64_t when = c->next_line_time, end = c->fetch_end;
	bool fetched;

	/*
	 * rdc_crtc_catch_up's loop for one line start with nothing but the
	 * fetch to do: n is an active line of this frame (so before its
	 * vblank, and shown: not `hidden`), or with nothing at all: a blank
	 * line after the vblank's.
	 */
	crtc_step_past(hw, n, when);
	if (n >= c->cur.v_display)
		return false;
	if (!hw->lazy || cursor_argb(hw))
		return quiet_fetch(hw, n, when, end);
	/* crtc_fetch with no cursor row, the line put off */
	crtc_read_line(hw, n, when);
	fetched = c->fetch_end != end;
	if (hw->frame_ok[hw->frame_back])
		return quiet_defer(hw, n, fetched);
	return fetched;
}

void rdc_crtc_catch_up(struct rdc_hw *hw, uint64_t t)
{
	struct rdc_crtc *c = &hw->crtc;
	uint64_t shown_until = 0;

	/*
	 * Without a frame listener, a frame that is replaced before this
	 * catch-up ends is never seen: skip converting it, so that running
	 * far ahead costs little more than the bus bookkeeping.
	 */
	if (c->next_line_time <= t && !hw->frame_fn)
		shown_until = crtc_shown_until(hw, t);
	if (c->lpen_time <= t) /* before the next line start */
		crtc_lpen_strobe(hw);
	while (c->next_line_time <= t) {
		uint32_t n = c->next_line;
		uint64_t when = c->next_line_time;

		if (c->rl_mid) {
			raster_column(hw);
			continue;
		}
		if (n >= c->cur.v_total) {
			c->frame_start += c->frame_cycles;
			if (c->mode_pending) {
				rdc_scan_drop_all(hw);
				c->cur = c->pending;
				c->mode_pending = 0;
				c->frame_cycles = line_offset(hw, &c->cur,
							      c->cur.v_total);
			}
			n = 0;
			c->next_line = 0;
			crtc_line_sync(hw);
			if (!hw->frame_fn)
				shown_until = crtc_shown_until(hw, t);
		}
		/*
		 * Step past the event before acting on it: the frame listener
		 * may read registers, which catches up again.
		 */
		crtc_step_past(hw, n, when);
		if (hw->trace_fn || n == 0)
			crtc_line_signals(hw, n, when);
		if (n == 0 || c->rl_wait <= n)
			raster_line(hw, n, when);
		if (n < c->cur.v_display)
			crtc_fetch(hw, n, when,
				   !hw->frame_fn && t >= shown_until);
		else if (n == c->cur.v_display)
			crtc_vblank(hw, when);
		if (n == c->line_compare)
			crtc_line_compare(hw, when);
		if (n == c->lpen_line) {
			crtc_lpen_line(hw, n, when);
			if (c->lpen_time <= t)
				crtc_lpen_strobe(hw);
		}
	}
}

void rdc_crtc_lpen_write(struct rdc_hw *hw, uint32_t reg, uint32_t val)
{
	struct rdc_crtc *c = &hw->crtc;

	if (reg == RDC_REG_LPEN_POS) {
		c->lpen_pos = val;
	} else {
		c->lpen_ctrl = val & RDC_LPEN_CTRL_MASK;
		c->lpen_hit = 0;
	}
	c->lpen_time = RDC_NEVER;
	c->lpen_line = (c->lpen_ctrl & RDC_LPEN_CTRL_EN) ?
			       FIELD_GET(RDC_LPEN_Y, c->lpen_pos) :
			       RDC_NEVER_LINE;
}

void rdc_crtc_start(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;

	/* the latch and a new timing: what waits is not shown as fetched */
	rdc_scan_drop_all(hw);
	scan_new_frame(hw, hw->frame_back);
	if (c->mode_pending) {
		c->cur = c->pending;
		c->mode_pending = 0;
	}
	crtc_latch(hw, false);
	c->running = c->mode_valid;
	c->in_vblank = 0;
	c->lpen_time = RDC_NEVER;
	c->rl_mid = 0;
	rdc_pins_update(hw, hw->now);
	c->next_line = 0;
	if (!c->running) {
		c->next_line_time = RDC_NEVER;
		return;
	}
	c->frame_start = hw->now;
	c->frame_cycles = line_offset(hw, &c->cur, c->cur.v_total);
	crtc_line_sync(hw);
	c->next_line_time = hw->now;
}

void rdc_crtc_stop(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;

	c->running = 0;
	c->in_vblank = 0;
	c->next_line_time = RDC_NEVER;
	c->rl_mid = 0;
	c->lpen_time = RDC_NEVER;
	rdc_pins_update(hw, hw->now);
}

void rdc_crtc_reset(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;

	rdc_memset(c, 0, sizeof(*c));
	c->preset = RDC_PRESET_640x480_60;
	c->shadow = rdc_presets[c->preset];
	c->fb_format = RDC_FMT_XRGB8888;
	c->fb_stride = rdc_format_row_bytes(c->fb_format, c->shadow.h_display);
	c->line_compare = RDC_LINE_COMPARE_RESET;
	c->cursor_fg = RDC_CURSOR_FG_RESET;
	c->cursor_bg = RDC_CURSOR_BG_RESET;
	c->next_line_time = RDC_NEVER;
	c->shadow_dirty = 1;
	c->rl_wait = RDC_NEVER_LINE;
	c->rl_line_n = RDC_NEVER_LINE;
	c->lpen_line = RDC_NEVER_LINE;
	c->lpen_time = RDC_NEVER;
}

/* Beam at hw->now; scanout must have caught up. */
static void crtc_beam(struct rdc_hw *hw, uint32_t *x, uint32_t *y)
{
	struct rdc_crtc *c = &hw->crtc;
	uint32_t line;
	uint64_t px;

	if (!c->running || !c->next_line) {
		*x = 0;
		*y = 0;
		return;
	}
	line = c->next_line - 1;
	px = (hw->now - c->frame_start - line_offset(hw, &c->cur, line)) *
	     c->cur.pixclk_khz * HZ_PER_KHZ / hw->core_hz;
	*x = (uint32_t)RDC_MIN(px, (uint64_t)c->cur.h_total - 1);
	*y = line;
}

void rdc_hw_beam(struct rdc_hw *hw, uint32_t *x, uint32_t *y)
{
	rdc_crtc_catch_up(hw, hw->now);
	crtc_beam(hw, x, y);
}

uint32_t rdc_crtc_status(struct rdc_hw *hw)
{
	uint32_t s = 0, x, y;

	rdc_hw_beam(hw, &x, &y);
	if (hw->crtc.in_vblank)
		s |= RDC_STATUS_VBLANK;
	if (hw->crtc.running && x >= hw->crtc.cur.h_display)
		s |= RDC_STATUS_HBLANK;
	return s;
}

uint64_t rdc_port_next_vblank(struct rdc_hw *hw)
{
	struct rdc_crtc *c = &hw->crtc;
	const struct rdc_timing *tm;

	rdc_crtc_catch_up(hw, hw->now);
	if (!c->running)
		return RDC_NEVER;
	if (c->next_line <= c->cur.v_display)
		return c->frame_start +
		       line_offset(hw, &c->cur, c->cur.v_display);
	tm = c->mode_pending ? &c->pending : &c->cur;
	return c->frame_start + c->frame_cycles +
	       line_offset(hw, tm, tm->v_display);
}

uint64_t rdc_port_next_line(struct rdc_hw *hw, uint32_t line)
{
	struct rdc_crtc *c = &hw->crtc;
	const struct rdc_timing *tm;

	rdc_crtc_catch_up(hw, hw->now);
	if (!c->running)
		return RDC_NEVER;
	if (line < c->cur.v_total && line >= c->next_line)
		return c->frame_start + line_offset(hw, &c->cur, line);
	tm = c->mode_pending ? &c->pending : &c->cur;
	if (line >= tm->v_total)
		return RDC_NEVER;
	return c->frame_start + c->frame_cycles + line_offset(hw, tm, line);
}

void rdc_port_idle_until(struct rdc_hw *hw, uint64_t t)
{
	rdc_hw_idle_to(hw, t);
}
