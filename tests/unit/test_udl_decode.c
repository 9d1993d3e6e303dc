// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The DisplayLink personality's decoder and EDID (userspace/lib/
 * udl_decode.c), without USB: hand-built and random udl command streams,
 * drawn by the display processor of a sim: device and compared with a
 * plain interpreter of the same stream written here; every split of a
 * stream gives the same commands; hostile bytes never reach outside the
 * window; the mode registers through udl's own encoding (the LFSR
 * implemented here from its definition) program the presets; the EDID
 * parses back to them.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "rdc.h"
#include "udl_decode.h"

/* ---- Collecting what the decoder produces ------------------------------- */

struct sink {
	uint32_t *w;
	size_t n, cap;
	int blanks;
	bool dark;
};

static void sink_words(void *ctx, const uint32_t *w, size_t n)
{
	struct sink *s = ctx;

	if (s->n + n > s->cap) {
		s->cap = (s->n + n) * 2 + 1024;
		s->w = realloc(s->w, s->cap * sizeof(*s->w));
		assert_non_null(s->w);
	}
	memcpy(s->w + s->n, w, n * sizeof(*w));
	s->n += n;
}

static void sink_blank(void *ctx, bool dark)
{
	struct sink *s = ctx;

	s->blanks++;
	s->dark = dark;
}

static void decoder(struct rdc_udl *u, struct sink *s, uint32_t vram)
{
	struct rdc_udl_out out = { sink_words, sink_blank, s };

	memset(s, 0, sizeof(*s));
	rdc_udl_init(u, vram, &out);
}

/* ---- A stream builder: udl's encodings, written from the protocol ------- */

struct buf {
	uint8_t *p;
	size_t n, cap;
};

static void put(struct buf *b, const void *p, size_t n)
{
	if (b->n + n > b->cap) {
		b->cap = (b->n + n) * 2 + 4096;
		b->p = realloc(b->p, b->cap);
		assert_non_null(b->p);
	}
	memcpy(b->p + b->n, p, n);
	b->n += n;
}

static void put8(struct buf *b, unsigned int v)
{
	uint8_t c = (uint8_t)v;

	put(b, &c, 1);
}

static void put_addr(struct buf *b, uint32_t a)
{
	put8(b, a >> 16);
	put8(b, a >> 8);
	put8(b, a);
}

static void put_px(struct buf *b, uint16_t v)
{
	put8(b, v >> 8); /* big-endian on the wire */
	put8(b, v);
}

static void put_reg(struct buf *b, unsigned int reg, unsigned int val)
{
	put8(b, 0xaf);
	put8(b, 0x20);
	put8(b, reg);
	put8(b, val);
}

/*
 * The LFSR from its definition: a 16-bit register starting at all ones,
 * shifted left once per count, the new low bit the XOR of bits 15, 4, 2
 * and 1.
 */
static uint16_t lfsr(unsigned int count)
{
	unsigned int r = 0xffff;

	while (count--) {
		unsigned int fb = ((r >> 15) ^ (r >> 4) ^ (r >> 2) ^ (r >> 1)) &
				  1;

		r = ((r << 1) | fb) & 0xffff;
	}
	return (uint16_t)r;
}

static void put_reg16(struct buf *b, unsigned int reg, unsigned int v)
{
	put_reg(b, reg, v >> 8 & 0xff);
	put_reg(b, reg + 1, v & 0xff);
}

static void put_lfsr(struct buf *b, unsigned int reg, unsigned int count)
{
	put_reg16(b, reg, lfsr(count));
}

/* What udl_simple_display_pipe_enable sends for a mode (clock in kHz). */
static void put_mode(struct buf *b, const struct rdc_timing *t, uint32_t khz,
		     unsigned int blank)
{
	unsigned int xds = t->h_total - t->h_sync_start;
	unsigned int yds = t->v_total - t->v_sync_start;

	put_reg(b, 0xff, 0x00); /* lock */
	put_reg(b, 0x00, 0x00); /* 16 bpp */
	put_reg(b, 0x20, 0);
	put_reg(b, 0x21, 0);
	put_reg(b, 0x22, 0);
	put_reg(b, 0x26, 0);
	put_reg(b, 0x27, (2 * t->h_display * t->v_display) >> 8 & 0xff);
	put_reg(b, 0x28, 0);
	put_lfsr(b, 0x01, xds);
	put_lfsr(b, 0x03, xds + t->h_display);
	put_lfsr(b, 0x05, yds);
	put_lfsr(b, 0x07, yds + t->v_display);
	put_lfsr(b, 0x09, t->h_total - 1);
	put_lfsr(b, 0x0b, 1);
	put_lfsr(b, 0x0d, t->h_sync_end - t->h_sync_start + 1);
	put_reg16(b, 0x0f, t->h_display);
	put_lfsr(b, 0x11, t->v_total);
	put_lfsr(b, 0x13, 0);
	put_lfsr(b, 0x15, t->v_sync_end - t->v_sync_start);
	put_reg16(b, 0x17, t->v_display);
	put_reg(b, 0x1b, (khz / 5) & 0xff); /* little-endian, this one */
	put_reg(b, 0x1c, (khz / 5) >> 8);
	put_reg(b, 0x1f, blank);
	put_reg(b, 0xff, 0xff); /* unlock */
	/* the dummy copy udl ends with */
	put8(b, 0xaf);
	put8(b, 0x6a);
	put_addr(b, 0);
	put8(b, 1);
	put_addr(b, 0);
}

/*
 * One line of pixels as RLX16 commands of at most 256 pixels: raw spans,
 * each run of two or more equal pixels ending its span with a repeat
 * count (as udl_compress_hline16 does).
 */
static void put_rlx_line(struct buf *b, uint32_t addr, const uint16_t *px,
			 uint32_t n)
{
	while (n) {
		uint32_t k = n < 256 ? n : 256, i = 0;

		put8(b, 0xaf);
		put8(b, 0x6b);
		put_addr(b, addr);
		put8(b, k & 0xff);
		while (i < k) {
			uint32_t start = i, run;

			/* raw pixels up to and including a run's first */
			while (i + 1 < k && px[i + 1] != px[i])
				i++;
			i++;
			put8(b, (i - start) & 0xff);
			for (uint32_t j = start; j < i; j++)
				put_px(b, px[j]);
			run = 0;
			while (i < k && px[i] == px[i - 1])
				i++, run++;
			if (run)
				put8(b, run);
			else if (i < k)
				put8(b, 0); /* cannot happen: a run follows */
		}
		addr += 2 * k;
		px += k;
		n -= k;
	}
}

/* ---- The reference: the stream applied to memory, plainly --------------- */

static void ref_px(uint8_t *m, uint32_t win, uint32_t a, uint16_t v)
{
	if (a + 2 <= win) {
		m[a] = (uint8_t)v;
		m[a + 1] = (uint8_t)(v >> 8);
	}
}

static void ref_apply(uint8_t *m, uint32_t win, const uint8_t *s, size_t n)
{
	size_t i = 0;

	while (i < n) {
		uint32_t op, a, total, cnt, drawn = 0, decl = 0;

		if (s[i] != 0xaf || i + 1 >= n) {
			i++;
			continue;
		}
		op = s[i + 1];
		if (op == 0xaf) {
			i++;
			continue;
		}
		if (op == 0x20) {
			i += 4;
			continue;
		}
		if (op == 0x6a) {
			uint32_t src = s[i + 2] << 16 | s[i + 3] << 8 |
				       s[i + 4];
			uint32_t dst = s[i + 6] << 16 | s[i + 7] << 8 |
				       s[i + 8];
			uint32_t k = s[i + 5] ? s[i + 5] : 256;

			i += 9;
			if ((src | dst) & 1)
				continue;
			if (src >= win || dst >= win)
				continue;
			if (k > (win - src) / 2)
				k = (win - src) / 2;
			if (k > (win - dst) / 2)
				k = (win - dst) / 2;
			memmove(m + dst, m + src, 2 * k);
			continue;
		}
		if (op != 0x68 && op != 0x69 && op != 0x6b) {
			i += 2;
			continue;
		}
		a = s[i + 2] << 16 | s[i + 3] << 8 | s[i + 4];
		total = s[i + 5] ? s[i + 5] : 256;
		i += 6;
		if (op == 0x68) {
			for (uint32_t k = 0; k < total; k++)
				if (!(a & 1))
					ref_px(m, win, a + 2 * k,
					       s[i + 2 * k] << 8 |
						       s[i + 2 * k + 1]);
			i += 2 * total;
			continue;
		}
		if (op == 0x69) {
			while (decl < total) {
				cnt = s[i] ? s[i] : 256;
				for (uint32_t k = 0; k < cnt && drawn < total;
				     k++)
					if (!(a & 1))
						ref_px(m, win, a + 2 * drawn++,
						       s[i + 1] << 8 |
							       s[i + 2]);
				decl += cnt;
				i += 3;
			}
			continue;
		}
		for (;;) {
			uint16_t last = 0;

			cnt = s[i] ? s[i] : 256;
			for (uint32_t k = 0; k < cnt; k++) {
				last = (uint16_t)(s[i + 1 + 2 * k] << 8 |
						  s[i + 2 + 2 * k]);
				if (drawn < total && !(a & 1))
					ref_px(m, win, a + 2 * drawn, last);
				if (drawn < total)
					drawn++;
			}
			i += 1 + 2 * cnt;
			decl += cnt;
			if (decl >= total)
				break;
			cnt = s[i++];
			for (uint32_t k = 0; k < cnt && drawn < total; k++) {
				if (!(a & 1))
					ref_px(m, win, a + 2 * drawn, last);
				drawn++;
			}
			decl += cnt;
			if (decl >= total)
				break;
		}
	}
}

/* ---- Random streams ------------------------------------------------------ */

static uint32_t rng_state;

static uint32_t rnd(void)
{
	rng_state = rng_state * 1103515245u + 12345u;
	return rng_state >> 8;
}

static uint16_t rnd_px(void)
{
	/* few colours, so runs happen */
	static const uint16_t pal[] = { 0x0000, 0xffff, 0xf800,
					0x07e0, 0x001f, 0x1234 };

	return rnd() % 3 ? pal[rnd() % 6] : (uint16_t)rnd();
}

/* Well-formed commands, some of them outside the window or misaligned. */
static void rnd_stream(struct buf *b, uint32_t win, unsigned int ncmd)
{
	for (unsigned int c = 0; c < ncmd; c++) {
		uint32_t a = (rnd() % (win + 2048)) & ~1u;
		uint32_t n = 1 + rnd() % 256;
		uint16_t px[256];

		if (!(rnd() % 16))
			a |= 1; /* odd: an error, nothing drawn */
		for (uint32_t i = 0; i < n; i++)
			px[i] = i && rnd() % 3 ? px[i - 1] : rnd_px();
		switch (rnd() % 6) {
		case 0:
			put8(b, 0xaf);
			put8(b, 0x68);
			put_addr(b, a);
			put8(b, n & 0xff);
			for (uint32_t i = 0; i < n; i++)
				put_px(b, px[i]);
			break;
		case 1: {
			uint32_t left = n;

			put8(b, 0xaf);
			put8(b, 0x69);
			put_addr(b, a);
			put8(b, n & 0xff);
			while (left) {
				uint32_t k =
					1 + rnd() % (left < 40 ? left : 40);

				put8(b, k);
				put_px(b, rnd_px());
				left -= k;
			}
			break;
		}
		case 2:
			put8(b, 0xaf);
			put8(b, 0x6a);
			put_addr(b, (rnd() % win) & ~1u);
			put8(b, n & 0xff);
			put_addr(b, a);
			break;
		case 3:
			put_reg(b, 0x30 + rnd() % 16, rnd() & 0xff);
			break;
		case 4: {
			uint8_t pad[8];

			memset(pad, 0xaf, sizeof(pad));
			put(b, pad, 1 + rnd() % 8);
			break;
		}
		default:
			put_rlx_line(b, a, px, n);
			break;
		}
	}
}

/* ---- Running the produced commands on a sim: device --------------------- */

#define SIM_VRAM (512u << 10)

static rdc_dev *sim_open(uint32_t vram)
{
	char uri[64];
	rdc_dev *dev;

	snprintf(uri, sizeof(uri), "sim:vram=%uK", vram >> 10);
	assert_int_equal(rdc_open(uri, &dev), 0);
	return dev;
}

static void sim_run(rdc_dev *dev, const struct sink *s)
{
	uint32_t code = 0, info = 0;

	assert_int_equal(rdc_submit(dev, s->w, s->n), 0);
	assert_int_equal(rdc_finish(dev), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_ERR_CODE, &code), 0);
	if (code)
		rdc_dev_error(dev, &code, &info);
	assert_int_equal(code, 0);
}

/* The decoder drawn by the DP equals the reference, byte for byte. */
static void check_against_ref(const struct buf *b, uint32_t win, uint32_t vram)
{
	struct rdc_udl u;
	struct sink s;
	rdc_dev *dev = sim_open(vram);
	uint8_t *ref = calloc(1, vram), *got = malloc(vram);

	assert_non_null(ref);
	assert_non_null(got);
	decoder(&u, &s, win);
	rdc_udl_feed(&u, b->p, b->n);
	sim_run(dev, &s);
	ref_apply(ref, u.window, b->p, b->n);
	assert_int_equal(rdc_vram_read(dev, 0, got, vram), 0);
	for (uint32_t i = 0; i < vram; i++)
		if (ref[i] != got[i])
			fail_msg("VRAM byte 0x%x: decoder %02x, reference %02x",
				 i, got[i], ref[i]);
	free(ref);
	free(got);
	free(s.w);
	rdc_close(dev);
}

/* ---- Tests ---------------------------------------------------------------- */

static void test_lfsr(void **state)
{
	(void)state;
	/* by hand from the definition: ffff, then shifts in 0, 0, 1 */
	assert_int_equal(lfsr(0), 0xffff);
	assert_int_equal(lfsr(1), 0xfffe);
	assert_int_equal(lfsr(2), 0xfffc);
	assert_int_equal(lfsr(3), 0xfff9);
	for (unsigned int c = 0; c <= 4200; c++)
		if (rdc_udl_lfsr16_count(lfsr(c)) != (int32_t)c)
			fail_msg("count %u: lfsr %04x decodes to %d", c,
				 lfsr(c), rdc_udl_lfsr16_count(lfsr(c)));
	/* the all-zero state is never reached from all ones */
	assert_int_equal(rdc_udl_lfsr16_count(0), -1);
}

static void test_mode_presets(void **state)
{
	(void)state;
	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++) {
		struct rdc_timing t, back;
		struct rdc_udl u;
		struct sink s;
		struct buf b = { 0 };
		rdc_dev *dev = sim_open(8u << 20);
		uint32_t v;

		assert_int_equal(rdc_preset_timing(p, &t), 0);
		/* udl gets the clock from the EDID: 10 kHz steps */
		put_mode(&b, &t, (t.pixclk_khz + 5) / 10 * 10, 0);
		decoder(&u, &s, 8u << 20);
		rdc_udl_feed(&u, b.p, b.n);
		assert_int_equal(u.st.errors, 0);
		assert_int_equal(u.st.modes, 1);
		assert_int_equal(rdc_udl_decode_timing(u.reg, &back), 0);
		assert_int_equal(back.h_total, t.h_total);
		assert_int_equal(back.v_sync_end, t.v_sync_end);
		/* the device snapped to the preset: exact clock and flags */
		assert_memory_equal(&u.mode, &t, sizeof(t));
		sim_run(dev, &s);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_H_TOTAL, &v), 0);
		assert_int_equal(v, t.h_total);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_V_SYNC_START, &v),
				 0);
		assert_int_equal(v, t.v_sync_start);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_PIXCLK_KHZ, &v), 0);
		assert_int_equal(v, t.pixclk_khz);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_FB_STRIDE, &v), 0);
		assert_int_equal(v, 2 * t.h_display);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_FB_FORMAT, &v), 0);
		assert_int_equal(v, RDC_FMT_RGB565);
		assert_int_equal(s.blanks, 0);
		/* the same mode again programs nothing; blanking darkens */
		s.n = 0;
		b.n = 0;
		put_mode(&b, &t, (t.pixclk_khz + 5) / 10 * 10, 0x07);
		rdc_udl_feed(&u, b.p, b.n);
		assert_int_equal(u.st.modes, 1);
		assert_int_equal(s.blanks, 1);
		assert_true(s.dark);
		free(b.p);
		free(s.w);
		rdc_close(dev);
	}
}

/*
 * DRM adds the other refresh of a CTA-861 mode (clocks 1000/1001 apart,
 * docs/usb.md): a preset's geometry at such a clock scans at the clock
 * udl sends (5 kHz steps), with the preset's sync polarities.
 */
static void test_mode_twins(void **state)
{
	(void)state;
	for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++) {
		struct rdc_timing t;
		struct rdc_udl u;
		struct sink s;
		struct buf b = { 0 };
		rdc_dev *dev = sim_open(8u << 20);
		uint32_t khz, v;

		assert_int_equal(rdc_preset_timing(p, &t), 0);
		khz = p % 2 ? (t.pixclk_khz * 1001u + 500u) / 1000u :
			      (t.pixclk_khz * 1000u + 500u) / 1001u;
		put_mode(&b, &t, khz, 0);
		decoder(&u, &s, 8u << 20);
		rdc_udl_feed(&u, b.p, b.n);
		assert_int_equal(u.st.errors, 0);
		assert_int_equal(u.st.modes, 1);
		assert_int_equal(u.mode.pixclk_khz, khz / 5 * 5);
		assert_int_equal(u.mode.flags, t.flags);
		assert_int_equal(u.mode.h_sync_start, t.h_sync_start);
		assert_int_equal(u.mode.v_total, t.v_total);
		sim_run(dev, &s);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_PIXCLK_KHZ, &v), 0);
		assert_int_equal(v, khz / 5 * 5);
		assert_int_equal(rdc_reg_read(dev, RDC_REG_CRTC_FLAGS, &v), 0);
		assert_int_equal(v, t.flags);
		free(b.p);
		free(s.w);
		rdc_close(dev);
	}
}

static void test_mode_bad(void **state)
{
	struct rdc_timing t;
	struct rdc_udl u;
	struct sink s;
	struct buf b = { 0 };

	(void)state;
	assert_int_equal(rdc_preset_timing(RDC_PRESET_640x480_60, &t), 0);
	/* then a count that is no LFSR value: refused, the mode stays */
	put_mode(&b, &t, 25180, 0);
	put_reg(&b, 0xff, 0x00);
	put_reg16(&b, 0x01, 0x0000);
	put_reg(&b, 0xff, 0xff);
	decoder(&u, &s, 8u << 20);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.modes, 1);
	assert_int_equal(u.st.errors, 1);
	assert_int_equal(u.st.last_error, RDC_UDL_E_MODE);
	/* a mode whose frame does not fit the device's memory */
	free(s.w);
	b.n = 0;
	put_mode(&b, &t, 25180, 0);
	decoder(&u, &s, 256u << 10);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.modes, 0);
	assert_int_equal(u.st.last_error, RDC_UDL_E_ADDR);
	free(b.p);
	free(s.w);
}

static void test_hand_built(void **state)
{
	struct buf b = { 0 };
	uint16_t px[300];

	(void)state;
	for (unsigned int i = 0; i < 300; i++)
		px[i] = (uint16_t)(i * 0x111);
	/* raw, a long run, a copy overlapping forwards and backwards */
	put_rlx_line(&b, 4096 - 20, px, 300); /* crosses a row */
	for (unsigned int i = 0; i < 100; i++)
		px[i] = 0xf800;
	put_rlx_line(&b, 3 * 4096, px, 100);
	put8(&b, 0xaf);
	put8(&b, 0x6a);
	put_addr(&b, 4096 - 20);
	put8(&b, 0); /* 256 */
	put_addr(&b, 4096 - 10);
	put8(&b, 0xaf);
	put8(&b, 0x6a);
	put_addr(&b, 4096 + 100);
	put8(&b, 200);
	put_addr(&b, 4096 + 40);
	/* padding, and a lone 0xAF at the end as udl leaves it */
	put8(&b, 0xaf);
	put8(&b, 0xaf);
	put8(&b, 0xaf);
	check_against_ref(&b, SIM_VRAM, SIM_VRAM);
	free(b.p);
}

static void test_random_vs_ref(void **state)
{
	(void)state;
	rng_state = 20240101u;
	for (int round = 0; round < 20; round++) {
		struct buf b = { 0 };

		rnd_stream(&b, SIM_VRAM / 2, 300);
		/* window half the VRAM: the upper half must stay zero */
		check_against_ref(&b, SIM_VRAM / 2, SIM_VRAM);
		free(b.p);
	}
}

static void feed_collect(const struct buf *b, const size_t *cuts, size_t ncut,
			 struct sink *s, struct rdc_udl_stats *st)
{
	struct rdc_udl u;
	size_t at = 0;

	decoder(&u, s, SIM_VRAM);
	for (size_t i = 0; i <= ncut; i++) {
		size_t end = i < ncut ? cuts[i] : b->n;

		rdc_udl_feed(&u, b->p + at, end - at);
		at = end;
	}
	*st = u.st;
}

static void test_splits(void **state)
{
	struct buf b = { 0 };
	struct sink whole, part;
	struct rdc_udl_stats sw, sp;
	struct rdc_timing t;

	(void)state;
	rng_state = 77u;
	assert_int_equal(rdc_preset_timing(RDC_PRESET_640x480_60, &t), 0);
	put_mode(&b, &t, 25180, 0);
	rnd_stream(&b, SIM_VRAM, 40);
	put8(&b, 0x12); /* garbage, then a resync */
	put8(&b, 0x34);
	rnd_stream(&b, SIM_VRAM, 10);
	feed_collect(&b, NULL, 0, &whole, &sw);
	assert_true(whole.n > 100);
	/* one cut at every byte boundary */
	for (size_t k = 0; k <= b.n; k++) {
		feed_collect(&b, &k, 1, &part, &sp);
		if (part.n != whole.n ||
		    memcmp(part.w, whole.w, whole.n * sizeof(*whole.w)))
			fail_msg(
				"a cut at byte %zu of %zu changes the commands",
				k, b.n);
		assert_memory_equal(&sp, &sw, sizeof(sw));
		free(part.w);
	}
	/* one byte at a time */
	{
		size_t *cuts = malloc(b.n * sizeof(*cuts));

		assert_non_null(cuts);
		for (size_t k = 0; k < b.n; k++)
			cuts[k] = k;
		feed_collect(&b, cuts, b.n, &part, &sp);
		assert_int_equal(part.n, whole.n);
		assert_memory_equal(part.w, whole.w,
				    whole.n * sizeof(*whole.w));
		assert_memory_equal(&sp, &sw, sizeof(sw));
		free(part.w);
		free(cuts);
	}
	free(whole.w);
	free(b.p);
}

/*
 * Every drawing command the decoder produces stays inside the window,
 * whatever the bytes: checked on the words, and on a device whose VRAM
 * above the window must stay untouched.
 */
static void test_hostile(void **state)
{
	(void)state;
	rng_state = 4242u;
	for (int round = 0; round < 40; round++) {
		uint32_t win = SIM_VRAM / 4;
		size_t n = 2000 + rnd() % 20000;
		uint8_t *junk = malloc(n);
		struct rdc_udl u;
		struct sink s;
		rdc_dev *dev = sim_open(SIM_VRAM);
		uint8_t *got = malloc(SIM_VRAM);

		assert_non_null(junk);
		assert_non_null(got);
		for (size_t i = 0; i < n; i++) {
			/* lots of prefixes and opcodes, so commands form */
			uint32_t r = rnd() % 8;

			junk[i] = r == 0 ? 0xaf :
				  r == 1 ? (uint8_t)(0x60 + rnd() % 12) :
					   (uint8_t)rnd();
		}
		decoder(&u, &s, win);
		for (size_t at = 0; at < n;) {
			size_t k = 1 + rnd() % 700;

			if (k > n - at)
				k = n - at;
			rdc_udl_feed(&u, junk + at, k);
			at += k;
		}
		assert_true(u.st.errors > 0);
		for (size_t i = 0; i < s.n;) {
			uint32_t h = s.w[i], op = RDC_CMD_OP(h);

			if (op == RDC_OP_HOST_BLIT || op == RDC_OP_FILL_RECT) {
				uint32_t x = RDC_X(s.w[i + 1]),
					 y = RDC_Y(s.w[i + 1]);
				uint32_t w = RDC_W(s.w[i + 2]);

				assert_true(RDC_H(s.w[i + 2]) == 1);
				assert_true(y * 4096 + 2 * (x + w) <= win);
			} else if (op == RDC_OP_BLIT) {
				uint32_t w = RDC_W(s.w[i + 3]);

				for (int e = 1; e <= 2; e++)
					assert_true(
						RDC_Y(s.w[i + e]) * 4096 +
							2 * (RDC_X(s.w[i + e]) +
							     w) <=
						win);
			}
			i += 1 + RDC_CMD_LEN(h);
		}
		sim_run(dev, &s);
		assert_int_equal(rdc_vram_read(dev, 0, got, SIM_VRAM), 0);
		for (uint32_t i = win; i < SIM_VRAM; i++)
			if (got[i])
				fail_msg("byte 0x%x outside the window written",
					 i);
		free(got);
		free(junk);
		free(s.w);
		rdc_close(dev);
	}
}

static void test_errors(void **state)
{
	struct rdc_udl u;
	struct sink s;
	struct buf b = { 0 };

	(void)state;
	decoder(&u, &s, SIM_VRAM);
	put8(&b, 0x00); /* not a command */
	put8(&b, 0xaf);
	put8(&b, 0x99); /* unknown */
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.errors, 2);
	assert_int_equal(u.st.last_error, RDC_UDL_E_OPCODE);
	assert_int_equal(u.st.error_at, 1);
	/* a raw span longer than the command: the command's count is drawn */
	b.n = 0;
	put8(&b, 0xaf);
	put8(&b, 0x6b);
	put_addr(&b, 0);
	put8(&b, 2);
	put8(&b, 3);
	put_px(&b, 1);
	put_px(&b, 2);
	put_px(&b, 3);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.last_error, RDC_UDL_E_LENGTH);
	assert_int_equal(u.st.px_raw, 2);
	/* an address past the window: clipped to nothing */
	b.n = 0;
	put8(&b, 0xaf);
	put8(&b, 0x68);
	put_addr(&b, 0xfffffe);
	put8(&b, 1);
	put_px(&b, 7);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.last_error, RDC_UDL_E_ADDR);
	assert_int_equal(u.st.px_raw, 2);
	/* 8 bpp: walked over, not drawn */
	b.n = 0;
	put8(&b, 0xaf);
	put8(&b, 0x60);
	put_addr(&b, 0);
	put8(&b, 3);
	put8(&b, 1);
	put8(&b, 2);
	put8(&b, 3);
	put_reg(&b, 0x40, 1);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.last_error, RDC_UDL_E_DEPTH);
	assert_int_equal(u.reg[0x40], 1);
	free(b.p);
	free(s.w);
}

/* A whole frame as udl sends it, scanned out by the CRTC. */
static void test_frame(void **state)
{
	struct rdc_timing t;
	struct rdc_udl u;
	struct sink s;
	struct buf b = { 0 };
	rdc_dev *dev = sim_open(4u << 20);
	uint32_t w = 0, h = 0, *frame;
	uint16_t *pat;

	(void)state;
	assert_int_equal(rdc_preset_timing(RDC_PRESET_640x480_60, &t), 0);
	pat = malloc(640 * 480 * sizeof(*pat));
	frame = malloc(640 * 480 * sizeof(*frame));
	assert_non_null(pat);
	assert_non_null(frame);
	for (uint32_t y = 0; y < 480; y++)
		for (uint32_t x = 0; x < 640; x++)
			pat[y * 640 + x] =
				(uint16_t)((x / 40 + y / 30) % 2 ?
						   0x07e0 :
						   (x * 7) ^ (y * 131));
	for (uint32_t y = 0; y < 480; y++)
		put_rlx_line(&b, y * 1280, pat + y * 640, 640);
	put_mode(&b, &t, 25180, 0);
	decoder(&u, &s, 4u << 20);
	rdc_udl_feed(&u, b.p, b.n);
	assert_int_equal(u.st.errors, 0);
	assert_true(u.st.px_run > 0 && u.st.px_raw > 0);
	sim_run(dev, &s);
	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_grab(dev, frame, 640 * 480, &w, &h), 0);
	assert_int_equal(w, 640);
	assert_int_equal(h, 480);
	for (uint32_t i = 0; i < 640 * 480; i++) {
		uint32_t p = frame[i];
		uint16_t v =
			(uint16_t)((p >> 19 & 0x1f) << 11 |
				   (p >> 10 & 0x3f) << 5 | (p >> 3 & 0x1f));

		if (v != pat[i])
			fail_msg("pixel %u,%u: %04x, not %04x", i % 640,
				 i / 640, v, pat[i]);
	}
	free(pat);
	free(frame);
	free(b.p);
	free(s.w);
	rdc_close(dev);
}

/* ---- EDID ------------------------------------------------------------------ */

static void dtd_parse(const uint8_t *d, struct rdc_timing *t)
{
	uint32_t ha = d[2] | (d[4] >> 4) << 8, hb = d[3] | (d[4] & 0xf) << 8;
	uint32_t va = d[5] | (d[7] >> 4) << 8, vb = d[6] | (d[7] & 0xf) << 8;
	uint32_t hso = d[8] | (d[11] >> 6 & 3) << 8;
	uint32_t hsw = d[9] | (d[11] >> 4 & 3) << 8;
	uint32_t vso = (d[10] >> 4) | (d[11] >> 2 & 3) << 4;
	uint32_t vsw = (d[10] & 0xf) | (d[11] & 3) << 4;

	*t = (struct rdc_timing){
		.h_total = ha + hb,
		.h_display = ha,
		.h_sync_start = ha + hso,
		.h_sync_end = ha + hso + hsw,
		.v_total = va + vb,
		.v_display = va,
		.v_sync_start = va + vso,
		.v_sync_end = va + vso + vsw,
		.pixclk_khz = (uint32_t)(d[0] | d[1] << 8) * 10,
		.flags = (d[17] & 2 ? RDC_CRTC_HSYNC_POS : 0) |
			 (d[17] & 4 ? RDC_CRTC_VSYNC_POS : 0),
	};
}

/* The detailed timings of an EDID, in order: how many. */
static unsigned int edid_dtds(const uint8_t *e, struct rdc_timing *out)
{
	unsigned int n = 0;

	for (unsigned int i = 0; i < 4; i++) {
		const uint8_t *d = e + 54 + 18 * i;

		if (d[0] | d[1])
			dtd_parse(d, &out[n++]);
	}
	for (unsigned int off = e[128 + 2]; off + 18 <= 127; off += 18) {
		const uint8_t *d = e + 128 + off;

		if (d[0] | d[1])
			dtd_parse(d, &out[n++]);
	}
	return n;
}

static void check_edid(uint32_t preferred, uint32_t vram, uint32_t expect_first,
		       uint32_t expect_n)
{
	static const uint8_t head[8] = { 0,    0xff, 0xff, 0xff,
					 0xff, 0xff, 0xff, 0 };
	uint8_t e[RDC_UDL_EDID_SIZE];
	struct rdc_timing got[16], t;
	unsigned int n, seen = 0;

	assert_int_equal(rdc_udl_edid(e, preferred, vram), RDC_UDL_EDID_SIZE);
	assert_memory_equal(e, head, 8);
	assert_int_equal(e[18], 1);
	assert_int_equal(e[19], 3);
	assert_int_equal(e[126], 1);
	assert_int_equal(e[128], 0x02);
	assert_int_equal(e[24] & 1, 0); /* no continuous frequency */
	assert_int_equal(e[35] | e[36] | e[37], 0); /* no established */
	for (int blk = 0; blk < 2; blk++) {
		uint8_t sum = 0;

		for (int i = 0; i < 128; i++)
			sum = (uint8_t)(sum + e[128 * blk + i]);
		assert_int_equal(sum, 0);
	}
	n = edid_dtds(e, got);
	assert_int_equal(n, expect_n);
	assert_int_equal(rdc_preset_timing(expect_first, &t), 0);
	assert_int_equal(got[0].h_display, t.h_display);
	assert_int_equal(got[0].v_display, t.v_display);
	for (unsigned int i = 0; i < n; i++) {
		bool found = false;

		/* udl's framebuffers are at least 640x480 */
		assert_true(got[i].h_display >= 640 && got[i].v_display >= 480);

		for (uint32_t p = 0; p < RDC_PRESET_COUNT; p++) {
			assert_int_equal(rdc_preset_timing(p, &t), 0);
			t.pixclk_khz = (t.pixclk_khz + 5) / 10 * 10;
			if (!memcmp(&t, &got[i], sizeof(t))) {
				assert_false(seen & 1u << p);
				seen |= 1u << p;
				found = true;
			}
		}
		if (!found)
			fail_msg("DTD %u (%ux%u) is no preset", i,
				 got[i].h_display, got[i].v_display);
	}
}

static void test_edid(void **state)
{
	(void)state;
	/* every preset fits 16 MiB; 320x200 is below udl's smallest
	 * framebuffer: five timings, the preferred first */
	check_edid(RDC_PRESET_1024x768_60, 16u << 20, RDC_PRESET_1024x768_60,
		   RDC_PRESET_COUNT - 1);
	check_edid(RDC_PRESET_640x480_60, 16u << 20, RDC_PRESET_640x480_60,
		   RDC_PRESET_COUNT - 1);
	/* no preferred, or one udl cannot use: the largest */
	check_edid(~0u, 16u << 20, RDC_PRESET_1920x1080_60,
		   RDC_PRESET_COUNT - 1);
	check_edid(RDC_PRESET_320x200_70, 16u << 20, RDC_PRESET_1920x1080_60,
		   RDC_PRESET_COUNT - 1);
	/* 1 MiB holds 640x480 and 800x600 at 16 bpp only */
	check_edid(RDC_PRESET_1024x768_60, 1u << 20, RDC_PRESET_800x600_60, 2);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_lfsr),
		cmocka_unit_test(test_mode_presets),
		cmocka_unit_test(test_mode_twins),
		cmocka_unit_test(test_mode_bad),
		cmocka_unit_test(test_hand_built),
		cmocka_unit_test(test_random_vs_ref),
		cmocka_unit_test(test_splits),
		cmocka_unit_test(test_hostile),
		cmocka_unit_test(test_errors),
		cmocka_unit_test(test_frame),
		cmocka_unit_test(test_edid),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
