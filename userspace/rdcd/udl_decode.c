// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The DisplayLink command stream as RDC-1 work (udl_decode.h): a streaming
 * decoder, the timing registers' LFSR, and the EDID of the presets.
 *
 * Pixels become display-processor commands on a surface that lays the
 * device's memory out as rows of RDC_UDL_ROW_BYTES, so every decoded
 * span is a rectangle one row high: raw pixels a HOST_BLIT, runs of at
 * least RDC_UDL_RUN_FILL_MIN pixels a FILL_RECT in their colour, copies a
 * BLIT.  The DP charges each by the bus model like any other command; the
 * CRTC scans the same VRAM out through FB_BASE and FB_STRIDE, which the
 * mode registers set.  Every address is clipped to the window before a
 * command is produced, and the DP clips again to the surface.
 */
#include <string.h>

#include "rdc_regs.h"
#include "udl_decode.h"

#define UDL_PREFIX	    0xafu
#define UDL_OP_REG	    0x20u
#define UDL_OP_RAW8	    0x60u
#define UDL_OP_RL8	    0x61u
#define UDL_OP_COPY8	    0x62u
#define UDL_OP_RLX8	    0x63u
#define UDL_OP_RAW16	    0x68u
#define UDL_OP_RL16	    0x69u
#define UDL_OP_COPY16	    0x6au
#define UDL_OP_RLX16	    0x6bu
#define UDL_HDR		    6u /* AF op addr[3] count */
#define UDL_COPY_LEN	    9u /* AF op src[3] count dst[3] */
#define UDL_REG_LEN	    4u
#define UDL_LFSR_SEED	    0xffffu
#define UDL_LFSR_PERIOD_MAX 65535u
#define UDL_CLOCK_STEP_KHZ  5u
#define UDL_MAX_DISPLAY	    2048u /* udl's mode_config limits */
#define UDL_BLANK_ON	    0x00u

/* udl's smallest framebuffer: it sends rows at the framebuffer's width,
 * so a smaller mode could only show a larger buffer at the wrong stride */
#define UDL_MIN_WIDTH  640u
#define UDL_MIN_HEIGHT 480u

static uint32_t udl_count(uint8_t c)
{
	return c ? c : 256u; /* 0 means 256 */
}

static uint32_t udl_addr(const uint8_t *p)
{
	return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

static uint16_t udl_be16(const uint8_t *p)
{
	return (uint16_t)(p[0] << 8 | p[1]);
}

static void udl_error(struct rdc_udl *u, enum rdc_udl_err e, uint64_t at)
{
	u->st.errors++;
	u->st.last_error = e;
	u->st.error_at = at;
}

static void udl_emit(struct rdc_udl *u, const uint32_t *w, size_t n)
{
	u->st.dp_words += n;
	u->out.words(u->out.ctx, w, n);
}

/* ---- Drawing: spans one row high on the DP surface ---------------------- */

/* Pixels of [a, a + 2n) inside the window. */
static uint32_t udl_clip(const struct rdc_udl *u, uint32_t a, uint32_t n)
{
	uint32_t room;

	if (a >= u->window)
		return 0;
	room = (u->window - a) / 2u;
	return n < room ? n : room;
}

static uint32_t udl_x(uint32_t a)
{
	return a % RDC_UDL_ROW_BYTES / 2u;
}

static uint32_t udl_y(uint32_t a)
{
	return a / RDC_UDL_ROW_BYTES;
}

static void udl_draw_raw(struct rdc_udl *u, uint32_t a, const uint16_t *px,
			 uint32_t n)
{
	n = udl_clip(u, a, n);
	u->st.px_raw += n;
	while (n) {
		uint32_t x = udl_x(a), k = RDC_UDL_ROW_PIXELS - x;
		uint32_t w[3 + 128];
		uint32_t nw;

		if (k > n)
			k = n;
		if (k > 256u)
			k = 256u;
		nw = (k + 1u) / 2u;
		w[0] = RDC_CMD(RDC_OP_HOST_BLIT, 0, 2u + nw);
		w[1] = RDC_XY(x, udl_y(a));
		w[2] = RDC_WH(k, 1);
		for (uint32_t i = 0; i < nw; i++) {
			uint32_t lo = px[2 * i];
			uint32_t hi = 2 * i + 1 < k ? px[2 * i + 1] : 0;

			w[3 + i] = lo |
				   hi << 16; /* VRAM order: first pixel low */
		}
		udl_emit(u, w, 3u + nw);
		px += k;
		n -= k;
		a += 2u * k;
	}
}

static void udl_draw_fill(struct rdc_udl *u, uint32_t a, uint16_t v, uint32_t n)
{
	n = udl_clip(u, a, n);
	if (!n)
		return;
	u->st.px_run += n;
	if (!u->fg_valid || u->fg != v) {
		uint32_t w[2] = { RDC_CMD(RDC_OP_SET_FG, 0, 1), v };

		udl_emit(u, w, 2);
		u->fg = v;
		u->fg_valid = true;
	}
	while (n) {
		uint32_t x = udl_x(a), k = RDC_UDL_ROW_PIXELS - x;
		uint32_t w[3];

		if (k > n)
			k = n;
		w[0] = RDC_CMD(RDC_OP_FILL_RECT, 0, 2);
		w[1] = RDC_XY(x, udl_y(a));
		w[2] = RDC_WH(k, 1);
		udl_emit(u, w, 3);
		n -= k;
		a += 2u * k;
	}
}

static void udl_blit(struct rdc_udl *u, uint32_t s, uint32_t d, uint32_t k)
{
	uint32_t w[4] = {
		RDC_CMD(RDC_OP_BLIT, 0, 3),
		RDC_XY(udl_x(s), udl_y(s)),
		RDC_XY(udl_x(d), udl_y(d)),
		RDC_WH(k, 1),
	};

	udl_emit(u, w, 4);
}

/*
 * A copy of n pixels, in pieces that stay within a row at both ends; each
 * BLIT is overlap-safe, and the pieces go back to front when the
 * destination lies after the source, so the whole behaves as memmove.
 */
static void udl_draw_copy(struct rdc_udl *u, uint32_t s, uint32_t d, uint32_t n)
{
	uint32_t m = udl_clip(u, s, n), md = udl_clip(u, d, n);

	if (md < m)
		m = md;
	u->st.px_copy += m;
	if (d <= s) {
		while (m) {
			uint32_t k = RDC_UDL_ROW_PIXELS - udl_x(s);
			uint32_t kd = RDC_UDL_ROW_PIXELS - udl_x(d);

			if (kd < k)
				k = kd;
			if (k > m)
				k = m;
			udl_blit(u, s, d, k);
			s += 2u * k;
			d += 2u * k;
			m -= k;
		}
		return;
	}
	s += 2u * m;
	d += 2u * m;
	while (m) {
		/* pixels of the row before each end, up to that end */
		uint32_t k = udl_x(s - 2u) + 1u, kd = udl_x(d - 2u) + 1u;

		if (kd < k)
			k = kd;
		if (k > m)
			k = m;
		s -= 2u * k;
		d -= 2u * k;
		udl_blit(u, s, d, k);
		m -= k;
	}
}

/* ---- The raw span of the current command -------------------------------- */

static void udl_span_flush(struct rdc_udl *u)
{
	if (u->span_n)
		udl_draw_raw(u, u->span_addr, u->span, u->span_n);
	u->span_n = 0;
}

/* Pixel v at address a (the next after the span, within one command). */
static void udl_span_push(struct rdc_udl *u, uint32_t a, uint16_t v)
{
	if (!u->span_n)
		u->span_addr = a;
	if (u->span_n == RDC_ARRAY_SIZE(u->span))
		return; /* cannot happen: a command draws at most 256 */
	u->span[u->span_n++] = v;
}

/* n copies of v from address a: a fill if long enough, else raw. */
static void udl_run(struct rdc_udl *u, uint32_t a, uint16_t v, uint32_t n)
{
	if (n >= RDC_UDL_RUN_FILL_MIN) {
		udl_span_flush(u);
		udl_draw_fill(u, a, v, n);
		return;
	}
	for (uint32_t i = 0; i < n; i++)
		udl_span_push(u, a + 2u * i, v);
}

/* ---- Mode registers ------------------------------------------------------ */

int32_t rdc_udl_lfsr16_count(uint16_t value)
{
	uint32_t lv = UDL_LFSR_SEED;

	for (uint32_t c = 0; c < UDL_LFSR_PERIOD_MAX; c++) {
		if (lv == value)
			return (int32_t)c;
		lv = ((lv << 1) |
		      (((lv >> 15) ^ (lv >> 4) ^ (lv >> 2) ^ (lv >> 1)) & 1u)) &
		     0xffffu;
	}
	return -1;
}

static int32_t udl_lfsr_reg(const uint8_t reg[256], unsigned int r)
{
	return rdc_udl_lfsr16_count(udl_be16(reg + r));
}

int rdc_udl_decode_timing(const uint8_t reg[256], struct rdc_timing *t)
{
	static const uint8_t lfsr_regs[] = {
		RDC_UDL_REG_XDS, RDC_UDL_REG_XDE, RDC_UDL_REG_YDS,
		RDC_UDL_REG_YDE, RDC_UDL_REG_XEC, RDC_UDL_REG_HSS,
		RDC_UDL_REG_HSE, RDC_UDL_REG_YEC, RDC_UDL_REG_VSS,
		RDC_UDL_REG_VSE,
	};
	int32_t v[RDC_ARRAY_SIZE(lfsr_regs)];
	int32_t xds, xde, yds, yde, xec, hss, hse, yec, vss, vse;
	int32_t htotal, hdisp, hs, he, vtotal, vdisp, vs, ve;

	for (size_t i = 0; i < RDC_ARRAY_SIZE(lfsr_regs); i++) {
		v[i] = udl_lfsr_reg(reg, lfsr_regs[i]);
		if (v[i] < 0)
			return -1;
	}
	xds = v[0], xde = v[1], yds = v[2], yde = v[3], xec = v[4];
	hss = v[5], hse = v[6], yec = v[7], vss = v[8], vse = v[9];
	/*
	 * udl_set_vid_cmds: xds = htotal - hsync_start, xde = xds + hdisplay,
	 * xec = htotal - 1, hss = 1, hse = hsync width + 1; yds = vtotal -
	 * vsync_start, yde = yds + vdisplay, yec = vtotal, vss = 0, vse =
	 * vsync width.  Sync starts other than 1 and 0 move the sync by as
	 * much.
	 */
	htotal = xec + 1;
	hdisp = xde - xds;
	hs = htotal - xds + hss - 1;
	he = hs + hse - hss;
	vtotal = yec;
	vdisp = yde - yds;
	vs = vtotal - yds + vss;
	ve = vs + vse - vss;
	if (hdisp != udl_be16(reg + RDC_UDL_REG_HPIX) ||
	    vdisp != udl_be16(reg + RDC_UDL_REG_VPIX))
		return -1;
	if (hdisp < 1 || hs < hdisp || he < hs || htotal < he || vdisp < 1 ||
	    vs < vdisp || ve < vs || vtotal < ve)
		return -1;
	*t = (struct rdc_timing){
		.h_total = (uint32_t)htotal,
		.h_display = (uint32_t)hdisp,
		.h_sync_start = (uint32_t)hs,
		.h_sync_end = (uint32_t)he,
		.v_total = (uint32_t)vtotal,
		.v_display = (uint32_t)vdisp,
		.v_sync_start = (uint32_t)vs,
		.v_sync_end = (uint32_t)ve,
		.pixclk_khz = (uint32_t)(reg[RDC_UDL_REG_CLOCK] |
					 reg[RDC_UDL_REG_CLOCK + 1] << 8) *
			      UDL_CLOCK_STEP_KHZ,
		.flags = 0,
	};
	return 0;
}

static bool udl_same_geometry(const struct rdc_timing *a,
			      const struct rdc_timing *b)
{
	return a->h_total == b->h_total && a->h_display == b->h_display &&
	       a->h_sync_start == b->h_sync_start &&
	       a->h_sync_end == b->h_sync_end && a->v_total == b->v_total &&
	       a->v_display == b->v_display &&
	       a->v_sync_start == b->v_sync_start &&
	       a->v_sync_end == b->v_sync_end;
}

/*
 * A timing with a preset's geometry takes the preset's sync polarities
 * (udl sends none); with the preset's clock as the EDID rounded it (10
 * kHz steps) it is the preset, exact clock included.  Any other clock
 * stays: DRM's CTA-861 twins of a preset (1000/1001 apart) scan at theirs.
 */
static void udl_snap_preset(struct rdc_timing *t)
{
	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++) {
		struct rdc_timing pt;
		uint32_t d;

		if (rdc_preset_timing(p, &pt) || !udl_same_geometry(t, &pt))
			continue;
		d = t->pixclk_khz > pt.pixclk_khz ?
			    t->pixclk_khz - pt.pixclk_khz :
			    pt.pixclk_khz - t->pixclk_khz;
		if (d < 10u)
			*t = pt;
		else
			t->flags = pt.flags;
		return;
	}
}

static bool udl_timing_ok(const struct rdc_timing *t)
{
	return t->h_display <= RDC_CRTC_MAX_DISPLAY &&
	       t->v_display <= RDC_CRTC_MAX_DISPLAY &&
	       t->h_total <= RDC_CRTC_MAX_TOTAL &&
	       t->v_total <= RDC_CRTC_MAX_TOTAL &&
	       t->pixclk_khz >= RDC_PIXCLK_MIN_KHZ &&
	       t->pixclk_khz <= RDC_PIXCLK_MAX_KHZ;
}

static void udl_reg_write(struct rdc_udl *u, uint32_t reg, uint32_t val)
{
	uint32_t w[3] = { RDC_CMD(RDC_OP_REG_WRITE, 0, 2), reg, val };

	udl_emit(u, w, 3);
}

static bool udl_timing_regs_blank(const uint8_t reg[256])
{
	for (unsigned int r = RDC_UDL_REG_XDS; r < RDC_UDL_REG_CLOCK + 2; r++)
		if (reg[r])
			return false;
	return true;
}

/* The unlock: the registers written since take effect together. */
static void udl_apply(struct rdc_udl *u, uint64_t at)
{
	struct rdc_timing t;
	uint32_t base, stride;
	bool dark = u->reg[RDC_UDL_REG_BLANK] != UDL_BLANK_ON;

	if (u->reg[RDC_UDL_REG_DEPTH])
		udl_error(u, RDC_UDL_E_DEPTH, at); /* stays at 16 bpp */
	if (rdc_udl_decode_timing(u->reg, &t)) {
		if (!udl_timing_regs_blank(u->reg))
			udl_error(u, RDC_UDL_E_MODE, at);
		goto blank;
	}
	udl_snap_preset(&t);
	base = udl_addr(u->reg + RDC_UDL_REG_BASE16);
	stride = 2u * t.h_display;
	if (!udl_timing_ok(&t)) {
		udl_error(u, RDC_UDL_E_MODE, at);
		goto blank;
	}
	if (base % 4u || base >= u->window ||
	    (u->window - base) / stride < t.v_display) {
		udl_error(u, RDC_UDL_E_ADDR, at);
		goto blank;
	}
	if (u->have_mode && !memcmp(&t, &u->mode, sizeof(t)) &&
	    base == u->fb_base && stride == u->fb_stride)
		goto blank;
	udl_reg_write(u, RDC_REG_H_TOTAL, t.h_total);
	udl_reg_write(u, RDC_REG_H_DISPLAY, t.h_display);
	udl_reg_write(u, RDC_REG_H_SYNC_START, t.h_sync_start);
	udl_reg_write(u, RDC_REG_H_SYNC_END, t.h_sync_end);
	udl_reg_write(u, RDC_REG_V_TOTAL, t.v_total);
	udl_reg_write(u, RDC_REG_V_DISPLAY, t.v_display);
	udl_reg_write(u, RDC_REG_V_SYNC_START, t.v_sync_start);
	udl_reg_write(u, RDC_REG_V_SYNC_END, t.v_sync_end);
	udl_reg_write(u, RDC_REG_PIXCLK_KHZ, t.pixclk_khz);
	udl_reg_write(u, RDC_REG_CRTC_FLAGS, t.flags);
	udl_reg_write(u, RDC_REG_FB_FORMAT, RDC_FMT_RGB565);
	udl_reg_write(u, RDC_REG_FB_STRIDE, stride);
	udl_reg_write(u, RDC_REG_FB_BASE, base);
	u->mode = t;
	u->fb_base = base;
	u->fb_stride = stride;
	u->have_mode = true;
	u->st.modes++;
blank:
	if (dark != u->dark) {
		u->dark = dark;
		if (u->out.blank)
			u->out.blank(u->out.ctx, dark);
	}
}

/* ---- Commands ------------------------------------------------------------ */

/*
 * Walk the command at p (p[0] is 0xAF, n bytes available): its length, or
 * 0 if more bytes are needed.  With `u`, also do it; the same walk
 * decides both, so the split of a stream cannot change what is drawn.
 */
static size_t udl_walk(struct rdc_udl *u, const uint8_t *p, size_t n,
		       uint64_t at)
{
	uint32_t op, bpp, total, a, drawn = 0, decl = 0, pos;
	bool odd, over = false;

	if (n < 2)
		return 0;
	op = p[1];
	switch (op) {
	case UDL_PREFIX:
		if (u)
			u->st.noops++;
		return 1;
	case UDL_OP_REG:
		if (n < UDL_REG_LEN)
			return 0;
		if (u) {
			u->st.cmds++;
			u->st.reg_writes++;
			u->reg[p[2]] = p[3];
			if (p[2] == RDC_UDL_REG_LOCK) {
				u->locked = !p[3];
				if (!u->locked)
					udl_apply(u, at);
			}
		}
		return UDL_REG_LEN;
	case UDL_OP_COPY8:
	case UDL_OP_COPY16:
		if (n < UDL_COPY_LEN)
			return 0;
		if (!u)
			return UDL_COPY_LEN;
		u->st.cmds++;
		if (op == UDL_OP_COPY8) {
			udl_error(u, RDC_UDL_E_DEPTH, at);
			return UDL_COPY_LEN;
		}
		a = udl_addr(p + 2);
		total = udl_count(p[5]);
		if ((a | udl_addr(p + 6)) & 1u ||
		    udl_clip(u, a, total) < total ||
		    udl_clip(u, udl_addr(p + 6), total) < total)
			udl_error(u, RDC_UDL_E_ADDR, at);
		if (!((a | udl_addr(p + 6)) & 1u))
			udl_draw_copy(u, a, udl_addr(p + 6), total);
		return UDL_COPY_LEN;
	case UDL_OP_RAW8:
	case UDL_OP_RL8:
	case UDL_OP_RLX8:
	case UDL_OP_RAW16:
	case UDL_OP_RL16:
	case UDL_OP_RLX16:
		break;
	default:
		if (u) {
			u->st.cmds++;
			udl_error(u, RDC_UDL_E_OPCODE, at);
		}
		return 2;
	}
	if (n < UDL_HDR)
		return 0;
	bpp = op >= UDL_OP_RAW16 ? 2u : 1u;
	a = udl_addr(p + 2);
	total = udl_count(p[5]);
	odd = bpp == 2 && (a & 1u);
	if (u) {
		u->st.cmds++;
		if (bpp == 1)
			udl_error(u, RDC_UDL_E_DEPTH, at);
		else if (odd || udl_clip(u, a, total) < total)
			udl_error(u, RDC_UDL_E_ADDR, at);
		/* 8 bpp and odd addresses are walked, never drawn */
		if (bpp == 1 || odd)
			u = NULL;
	}
	pos = UDL_HDR;
	if (op == UDL_OP_RAW8 || op == UDL_OP_RAW16) {
		pos += total * bpp;
		if (pos > n)
			return 0;
		for (uint32_t i = 0; u && i < total; i++)
			udl_span_push(u, a + 2u * i,
				      udl_be16(p + UDL_HDR + 2 * i));
		drawn = decl = total;
	} else if (op == UDL_OP_RL8 || op == UDL_OP_RL16) {
		while (decl < total) {
			uint32_t c;

			if (pos + 1 + bpp > n)
				return 0;
			c = udl_count(p[pos]);
			decl += c;
			if (u) {
				uint32_t k = c < total - drawn ? c :
								 total - drawn;

				over |= k < c;
				udl_run(u, a + 2u * drawn,
					udl_be16(p + pos + 1), k);
				drawn += k;
			}
			pos += 1 + bpp;
		}
	} else {
		for (;;) {
			uint32_t r, rep;

			if (pos + 1 > n)
				return 0;
			r = udl_count(p[pos]);
			if (pos + 1 + r * bpp > n)
				return 0;
			for (uint32_t i = 0; u && i < r; i++) {
				if (drawn == total) {
					over = true;
					break;
				}
				udl_span_push(u, a + 2u * drawn,
					      udl_be16(p + pos + 1 + 2 * i));
				drawn++;
			}
			pos += 1 + r * bpp;
			decl += r;
			if (decl >= total)
				break;
			if (pos + 1 > n)
				return 0;
			rep = p[pos++];
			if (u && rep) {
				uint32_t k = rep < total - drawn ?
						     rep :
						     total - drawn;

				over |= k < rep;
				udl_run(u, a + 2u * drawn,
					u->span_n ? u->span[u->span_n - 1] : 0,
					k);
				drawn += k;
			}
			decl += rep;
			if (decl >= total)
				break;
		}
	}
	if (u) {
		udl_span_flush(u);
		if (over || decl > total)
			udl_error(u, RDC_UDL_E_LENGTH, at);
	}
	return pos;
}

/* Skip bytes up to the next 0xAF: how many. */
static size_t udl_resync(struct rdc_udl *u, const uint8_t *p, size_t n)
{
	size_t k = 0;

	while (k < n && p[k] != UDL_PREFIX)
		k++;
	if (k && !u->in_garbage)
		udl_error(u, RDC_UDL_E_SYNC, u->st.bytes);
	u->in_garbage = k == n;
	return k;
}

void rdc_udl_feed(struct rdc_udl *u, const uint8_t *p, size_t n)
{
	while (n) {
		size_t used;

		if (u->part_len) {
			/* complete the carried command from the new bytes */
			size_t take = RDC_UDL_CMD_MAX - u->part_len, len;
			uint64_t at = u->st.bytes - u->part_len;

			if (take > n)
				take = n;
			if (!take) {
				/* cannot happen (no command is longer) */
				udl_error(u, RDC_UDL_E_LENGTH, at);
				u->part_len = 0;
				continue;
			}
			memcpy(u->part + u->part_len, p, take);
			len = udl_walk(NULL, u->part, u->part_len + take, 0);
			if (!len) {
				/* still incomplete: all of it is kept */
				u->part_len += take;
				u->st.bytes += take;
				p += take;
				n -= take;
				continue;
			}
			used = len - u->part_len;
			u->part_len = 0;
			u->st.bytes += used;
			udl_walk(u, u->part, len, at);
			p += used;
			n -= used;
			continue;
		}
		used = udl_resync(u, p, n);
		if (used) {
			u->st.bytes += used;
			p += used;
			n -= used;
			continue;
		}
		used = udl_walk(NULL, p, n, 0);
		if (!used) {
			/* at most RDC_UDL_CMD_MAX - 1 bytes: a command's start */
			memcpy(u->part, p, n);
			u->part_len = n;
			u->st.bytes += n;
			return;
		}
		udl_walk(u, p, used, u->st.bytes);
		u->st.bytes += used;
		p += used;
		n -= used;
	}
}

void rdc_udl_init(struct rdc_udl *u, uint32_t vram_size,
		  const struct rdc_udl_out *out)
{
	uint32_t win = vram_size < RDC_UDL_ADDR_SPACE ? vram_size :
							RDC_UDL_ADDR_SPACE;
	uint32_t surf[] = { 0, RDC_UDL_ROW_BYTES, 0, RDC_FMT_RGB565 };

	memset(u, 0, sizeof(*u));
	u->out = *out;
	u->rows = win / RDC_UDL_ROW_BYTES;
	u->window = u->rows * RDC_UDL_ROW_BYTES;
	if (!u->rows)
		return; /* no memory to draw in: every address is outside */
	surf[2] = RDC_WH(RDC_UDL_ROW_PIXELS, u->rows);
	{
		uint32_t w[] = {
			RDC_CMD(RDC_OP_SET_DST, 0, 4),
			surf[0],
			surf[1],
			surf[2],
			surf[3],
			RDC_CMD(RDC_OP_SET_SRC, 0, 4),
			surf[0],
			surf[1],
			surf[2],
			surf[3],
			RDC_CMD(RDC_OP_SET_CLIP, 0, 2),
			RDC_XY(0, 0),
			RDC_XY(RDC_UDL_ROW_PIXELS, u->rows),
			RDC_CMD(RDC_OP_SET_ROP, 0, 1),
			RDC_ROP_COPY,
			RDC_CMD(RDC_OP_SET_ALPHA, 0, 1),
			RDC_ALPHA_OPAQUE,
			RDC_CMD(RDC_OP_SET_COLORKEY, 0, 1),
			0,
			RDC_CMD(RDC_OP_SET_PATTERN, RDC_PAT_NONE, 0),
			RDC_CMD(RDC_OP_SET_TRANSFORM, 0, 0),
			RDC_CMD(RDC_OP_SET_ZBUF, 0, 0),
		};

		udl_emit(u, w, RDC_ARRAY_SIZE(w));
	}
}

/* ---- EDID ---------------------------------------------------------------- */

#define EDID_BLOCK		   128u
#define EDID_DTD		   18u
#define EDID_DTD_BASE		   54u
#define EDID_BASE_DTDS		   3u /* the fourth descriptor is the name */
#define EDID_CTA_DTD_OFF	   4u
#define EDID_CTA_DTDS		   6u /* (127 - 4) / 18 */
#define EDID_SYNC_DIGITAL_SEPARATE 0x18u
#define EDID_SYNC_VPOS		   0x04u
#define EDID_SYNC_HPOS		   0x02u

static void edid_dtd(uint8_t *d, const struct rdc_timing *t)
{
	uint32_t clk = (t->pixclk_khz + 5u) / 10u; /* 10 kHz steps */
	uint32_t hb = t->h_total - t->h_display, vb = t->v_total - t->v_display;
	uint32_t hso = t->h_sync_start - t->h_display;
	uint32_t hsw = t->h_sync_end - t->h_sync_start;
	uint32_t vso = t->v_sync_start - t->v_display;
	uint32_t vsw = t->v_sync_end - t->v_sync_start;

	memset(d, 0, EDID_DTD);
	d[0] = (uint8_t)clk;
	d[1] = (uint8_t)(clk >> 8);
	d[2] = (uint8_t)t->h_display;
	d[3] = (uint8_t)hb;
	d[4] = (uint8_t)((t->h_display >> 8) << 4 | (hb >> 8 & 0xfu));
	d[5] = (uint8_t)t->v_display;
	d[6] = (uint8_t)vb;
	d[7] = (uint8_t)((t->v_display >> 8) << 4 | (vb >> 8 & 0xfu));
	d[8] = (uint8_t)hso;
	d[9] = (uint8_t)hsw;
	d[10] = (uint8_t)((vso & 0xfu) << 4 | (vsw & 0xfu));
	d[11] = (uint8_t)((hso >> 8 & 3u) << 6 | (hsw >> 8 & 3u) << 4 |
			  (vso >> 4 & 3u) << 2 | (vsw >> 4 & 3u));
	d[17] = (uint8_t)(EDID_SYNC_DIGITAL_SEPARATE |
			  (t->flags & RDC_CRTC_VSYNC_POS ? EDID_SYNC_VPOS : 0) |
			  (t->flags & RDC_CRTC_HSYNC_POS ? EDID_SYNC_HPOS : 0));
}

static void edid_checksum(uint8_t *b)
{
	uint8_t s = 0;

	for (unsigned int i = 0; i < EDID_BLOCK - 1; i++)
		s = (uint8_t)(s + b[i]);
	b[EDID_BLOCK - 1] = (uint8_t)(0x100u - s);
}

static bool edid_fits(uint32_t p, uint32_t vram_size, struct rdc_timing *t)
{
	uint32_t win = vram_size < RDC_UDL_ADDR_SPACE ? vram_size :
							RDC_UDL_ADDR_SPACE;

	return !rdc_preset_timing(p, t) && t->h_display <= UDL_MAX_DISPLAY &&
	       t->v_display <= UDL_MAX_DISPLAY &&
	       t->h_display >= UDL_MIN_WIDTH &&
	       t->v_display >= UDL_MIN_HEIGHT &&
	       2ull * t->h_display * t->v_display <= win;
}

size_t rdc_udl_edid(uint8_t out[RDC_UDL_EDID_SIZE], uint32_t preferred,
		    uint32_t vram_size)
{
	static const uint8_t head[] = { 0x00, 0xff, 0xff, 0xff,
					0xff, 0xff, 0xff, 0x00 };
	/* sRGB primaries and white point, as monitors commonly give them */
	static const uint8_t chroma[] = { 0xee, 0x91, 0xa3, 0x54, 0x4c,
					  0x99, 0x26, 0x0f, 0x50, 0x54 };
	static const char name[13] = "RDC-1\n      ";
	uint32_t order[RDC_PRESET_COUNT], n = 0, best = RDC_PRESET_COUNT;
	uint64_t best_area = 0;
	struct rdc_timing t;
	uint8_t *b = out, *x = out + EDID_BLOCK;

	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++) {
		if (!edid_fits(p, vram_size, &t))
			continue;
		if ((uint64_t)t.h_display * t.v_display > best_area) {
			best_area = (uint64_t)t.h_display * t.v_display;
			best = p;
		}
	}
	if (preferred < RDC_PRESET_COUNT && edid_fits(preferred, vram_size, &t))
		best = preferred;
	if (best < RDC_PRESET_COUNT)
		order[n++] = best;
	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++)
		if (p != best && edid_fits(p, vram_size, &t))
			order[n++] = p;

	memset(out, 0, RDC_UDL_EDID_SIZE);
	memcpy(b, head, sizeof(head));
	b[8] = 0x48; /* "RDC": ('R'-'@') << 10 | ('D'-'@') << 5 | 'C'-'@' */
	b[9] = 0x83;
	b[10] = 0x01; /* product 1 */
	b[16] = 1;    /* week 1 */
	b[17] = 34;   /* 2024 - 1990 */
	b[18] = 1;    /* EDID 1.3 */
	b[19] = 3;
	b[20] = 0x80; /* digital input */
	b[23] = 0x78; /* gamma 2.2 */
	b[24] = 0x0a; /* RGB colour, first DTD preferred, no GTF */
	memcpy(b + 25, chroma, sizeof(chroma));
	for (unsigned int i = 38; i < 54; i++)
		b[i] = 0x01; /* standard timings unused */
	for (uint32_t i = 0; i < n; i++) {
		uint8_t *d = i < EDID_BASE_DTDS ?
				     b + EDID_DTD_BASE + EDID_DTD * i :
				     x + EDID_CTA_DTD_OFF +
					     EDID_DTD * (i - EDID_BASE_DTDS);

		if (i >= EDID_BASE_DTDS + EDID_CTA_DTDS)
			break;
		rdc_preset_timing(order[i], &t);
		edid_dtd(d, &t);
	}
	{
		uint8_t *d = b + EDID_DTD_BASE + EDID_DTD * EDID_BASE_DTDS;

		d[3] = 0xfc; /* monitor name */
		memcpy(d + 5, name, sizeof(name));
	}
	b[126] = 1; /* one extension */
	edid_checksum(b);
	x[0] = 0x02; /* CTA-861 */
	x[1] = 0x03;
	x[2] = EDID_CTA_DTD_OFF; /* no data blocks */
	edid_checksum(x);
	return RDC_UDL_EDID_SIZE;
}

void rdc_udl_stats_encode(uint8_t out[RDC_UDL_STATS_SIZE],
			  const struct rdc_udl_stats *s)
{
	const uint64_t v[] = {
		s->bytes,  s->cmds,   s->noops,	     s->reg_writes,
		s->px_raw, s->px_run, s->px_copy,    s->dp_words,
		s->modes,  s->errors, s->last_error, s->error_at,
	};

	_Static_assert(sizeof(v) == RDC_UDL_STATS_SIZE, "stats layout");
	for (size_t i = 0; i < RDC_ARRAY_SIZE(v); i++)
		for (unsigned int k = 0; k < 8; k++)
			out[8 * i + k] = (uint8_t)(v[i] >> (8 * k));
}
