// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Value Change Dump (IEEE 1364-2001, section 18) of the chip's signals,
 * written from its trace events as simulated time passes.
 *
 * Time: the file's unit is the coarsest of 1 ns, 100 ps, ... 1 fs in
 * which every core cycle is a whole number of units (1 ns per unit, 10 a
 * cycle, at the default 100 MHz), so cycles convert exactly with integer
 * arithmetic and the times read as real time in any viewer.  A core clock
 * with no such unit (one not of the form 2^a 5^b Hz) gets 1 ns, each
 * cycle's start rounded down to its nanosecond, and says so in a $comment.
 *
 * hblank has no trace event of its own: it follows from each line start
 * and the mode, as STATUS.HBLANK does (the beam's x, counted in pixel
 * clocks from the line start, reaches H_DISPLAY).  The rise is a time in
 * the future when its line starts, so it waits in `hb_rise` until an
 * event at or after it (or the next line start, which drops a rise that
 * the line is too short for) lets it out, and the file stays in order.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "rdc_priv.h"

#define VCD_BUF_BYTES (64u * 1024u)
/* room for the longest change: "#" + 20 digits + "\n" + "b" + 32 bits ... */
#define VCD_LINE_MAX 80u
#define HZ_PER_KHZ   1000u
#define NS_PER_S     1000000000ull
#define FIFO_BITS    9	/* 0 ... RDC_FIFO_DEPTH (256) */
#define LINE_BITS    12 /* 0 ... RDC_CRTC_MAX_TOTAL - 1 */

enum vcd_sig {
	SIG_TE,
	SIG_IRQ,
	SIG_RESET_N,
	SIG_BL_EN,
	SIG_DP,
	SIG_FIFO,
	SIG_LINE,
	SIG_VBLANK,
	SIG_HBLANK,
	SIG_COUNT
};

static const struct {
	const char *name;
	unsigned int bits;
} vcd_sigs[SIG_COUNT] = {
	[SIG_TE] = { "te", 1 },
	[SIG_IRQ] = { "irq", 1 },
	[SIG_RESET_N] = { "reset_n", 1 },
	[SIG_BL_EN] = { "bl_en", 1 },
	[SIG_DP] = { "dp_busy", 1 },
	[SIG_FIFO] = { "fifo_level", FIFO_BITS },
	[SIG_LINE] = { "line", LINE_BITS },
	[SIG_VBLANK] = { "vblank", 1 },
	[SIG_HBLANK] = { "hblank", 1 },
};

_Static_assert(RDC_FIFO_DEPTH < (1u << FIFO_BITS), "FIFO level width");
_Static_assert(RDC_CRTC_MAX_TOTAL <= (1u << LINE_BITS), "line width");

struct rdc_vcd {
	int fd;
	int err; /* a write failed: RDC_E_FILE at close */
	struct rdc_hw *const *hwp;
	const struct rdc_hw *seen; /* the chip the levels below are from */

	/* rdc_vcd_open: the hook it took, and what was on it before */
	struct rdc_hw *hooked;
	struct rdc_hw *own; /* what hwp points to for rdc_vcd_open */
	rdc_trace_fn next_fn;
	void *next_ctx;

	uint32_t core_hz;
	uint64_t per_cycle; /* units a cycle; 0: not exact (1 ns, floored) */
	uint64_t base;	    /* file cycles = chip cycles + base (mod 2^64) */
	uint64_t last;	    /* file cycles of the last event */
	uint64_t written;   /* file cycles of the last #time line */
	bool any_time;
	uint64_t hb_rise; /* file cycles hblank rises; RDC_NEVER: none */
	uint32_t val[SIG_COUNT];

	size_t len;
	char buf[VCD_BUF_BYTES];
};

/* ---- output -------------------------------------------------------------- */

static void vcd_flush(rdc_vcd *v)
{
	size_t off = 0;

	while (off < v->len && !v->err) {
		ssize_t n = write(v->fd, v->buf + off, v->len - off);

		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0)
			v->err = 1;
		else
			off += (size_t)n;
	}
	v->len = 0;
}

static void vcd_puts(rdc_vcd *v, const char *s)
{
	size_t n = strlen(s);

	while (n) {
		size_t k;

		if (v->len == sizeof(v->buf))
			vcd_flush(v);
		k = RDC_MIN(n, sizeof(v->buf) - v->len);
		memcpy(v->buf + v->len, s, k);
		v->len += k;
		s += k;
		n -= k;
	}
}

static void vcd_printf(rdc_vcd *v, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

static void vcd_printf(rdc_vcd *v, const char *fmt, ...)
{
	char line[256];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(line, sizeof(line), fmt, ap);
	va_end(ap);
	vcd_puts(v, line);
}

/* Identifier codes: one printable character each, from '!'. */
static char vcd_id(enum vcd_sig s)
{
	return (char)('!' + s);
}

/* A value as its change line: "1!" or "b1011 &". */
static void vcd_value(rdc_vcd *v, enum vcd_sig s, uint32_t x)
{
	char line[VCD_LINE_MAX], *p = line;
	int bit = (int)vcd_sigs[s].bits - 1;

	if (vcd_sigs[s].bits == 1) {
		*p++ = x ? '1' : '0';
	} else {
		*p++ = 'b';
		while (bit > 0 && !(x >> bit & 1)) /* leading zeros left out */
			bit--;
		for (; bit >= 0; bit--)
			*p++ = (char)('0' + (x >> bit & 1));
		*p++ = ' ';
	}
	*p++ = vcd_id(s);
	*p++ = '\n';
	*p = 0;
	vcd_puts(v, line);
}

/* File cycles to the file's unit. */
static uint64_t vcd_units(const rdc_vcd *v, uint64_t cycles)
{
	if (v->per_cycle)
		return cycles * v->per_cycle;
	return cycles / v->core_hz * NS_PER_S +
	       cycles % v->core_hz * NS_PER_S / v->core_hz;
}

/* "#units\n", formatted here: a line start writes one or two of them. */
static void vcd_stamp(rdc_vcd *v, uint64_t units)
{
	char line[24], *p = line + sizeof(line);

	*--p = 0;
	*--p = '\n';
	do {
		*--p = (char)('0' + units % 10);
		units /= 10;
	} while (units);
	*--p = '#';
	vcd_puts(v, p);
}

static void vcd_time(rdc_vcd *v, uint64_t t)
{
	/* never back in time: a late change goes under the present #time */
	if (v->any_time && t <= v->written)
		return;
	/* distinct cycles that round to one nanosecond share a #time */
	if (v->any_time && vcd_units(v, t) == vcd_units(v, v->written)) {
		v->written = t;
		return;
	}
	vcd_stamp(v, vcd_units(v, t));
	v->written = t;
	v->any_time = true;
}

static void vcd_set(rdc_vcd *v, enum vcd_sig s, uint32_t x, uint64_t t)
{
	if (v->val[s] == x)
		return;
	v->val[s] = x;
	vcd_time(v, t);
	vcd_value(v, s, x);
}

/* ---- the chip's state ---------------------------------------------------- */

/*
 * Cycles from a line's start to hblank: the first cycle whose beam x
 * (cycles * pixel clock / core clock, rounded down) reaches H_DISPLAY.
 */
static uint64_t vcd_hblank_offset(const struct rdc_hw *hw,
				  const struct rdc_timing *tm)
{
	uint64_t pix_hz = (uint64_t)tm->pixclk_khz * HZ_PER_KHZ;

	if (!pix_hz)
		return RDC_NEVER;
	return ((uint64_t)tm->h_display * rdc_hw_core_hz(hw) + pix_hz - 1) /
	       pix_hz;
}

/*
 * The levels of a chip as its trace events left them, read from its state
 * without catching up (that would move time and emit events): the pins
 * as last reported, the line last started and where its hblank stands.
 */
static void vcd_sync(rdc_vcd *v, const struct rdc_hw *hw, uint64_t t)
{
	struct rdc_hw_state cs, *c = &cs;
	struct rdc_timing cur;
	uint32_t pins, line = 0;

	rdc_hw_state(hw, c);
	rdc_hw_timing(hw, &cur);
	pins = c->pins_out;

	v->seen = hw;
	v->hb_rise = RDC_NEVER;
	vcd_set(v, SIG_TE, !!(pins & RDC_PIN_TE), t);
	vcd_set(v, SIG_IRQ, !!(pins & RDC_PIN_IRQ), t);
	vcd_set(v, SIG_RESET_N, !!(pins & RDC_PIN_RESET_N), t);
	vcd_set(v, SIG_BL_EN, !!(pins & RDC_PIN_BL_EN), t);
	vcd_set(v, SIG_DP, !!c->dp_active, t);
	vcd_set(v, SIG_FIFO, c->fifo_count, t);
	vcd_set(v, SIG_VBLANK, !!c->in_vblank, t);
	if (c->scanning && c->next_line && cur.pixclk_khz) {
		/* line n starts n * h_total pixel clocks into the frame */
		uint64_t start;

		line = c->next_line - 1;
		start = c->frame_start +
			(uint64_t)line * cur.h_total * rdc_hw_core_hz(hw) /
				((uint64_t)cur.pixclk_khz * HZ_PER_KHZ);
		start += vcd_hblank_offset(hw, &cur);
		if (start <= rdc_hw_now(hw)) {
			vcd_set(v, SIG_HBLANK, 1, t);
		} else {
			vcd_set(v, SIG_HBLANK, 0, t);
			v->hb_rise = start + v->base;
		}
	} else {
		vcd_set(v, SIG_HBLANK, 0, t);
	}
	vcd_set(v, SIG_LINE, line, t);
}

/* ---- events -------------------------------------------------------------- */

void rdc_vcd_trace(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		   uint32_t b)
{
	rdc_vcd *v = ctx;
	const struct rdc_hw *hw = v->hwp ? *v->hwp : NULL;
	uint64_t t;

	if (event != RDC_TRACE_PINS && event != RDC_TRACE_LINE &&
	    event != RDC_TRACE_DP && event != RDC_TRACE_FIFO)
		return;
	if (hw && hw != v->seen) {
		/* a new chip: its time goes on from the old one's */
		v->base = v->last - rdc_hw_now(hw);
		vcd_sync(v, hw, v->last);
	}
	t = time + v->base;
	if (t < v->last)
		t = v->last; /* never back in time */
	v->last = t;
	/*
	 * A rise due at this very line start is dropped: the beam is on the
	 * new line's first pixel then, not in blanking.
	 */
	if (v->hb_rise < t || (v->hb_rise == t && event != RDC_TRACE_LINE)) {
		vcd_set(v, SIG_HBLANK, 1, v->hb_rise);
		v->hb_rise = RDC_NEVER;
	}
	switch (event) {
	case RDC_TRACE_PINS:
		vcd_set(v, SIG_TE, !!(a & RDC_PIN_TE), t);
		vcd_set(v, SIG_IRQ, !!(a & RDC_PIN_IRQ), t);
		vcd_set(v, SIG_RESET_N, !!(a & RDC_PIN_RESET_N), t);
		vcd_set(v, SIG_BL_EN, !!(a & RDC_PIN_BL_EN), t);
		break;
	case RDC_TRACE_LINE:
		/* a rise still pending did not fit in the last line */
		v->hb_rise = RDC_NEVER;
		vcd_set(v, SIG_HBLANK, 0, t);
		vcd_set(v, SIG_LINE, a & ((1u << LINE_BITS) - 1), t);
		vcd_set(v, SIG_VBLANK, !!b, t);
		if (hw) {
			struct rdc_timing cur;
			uint64_t off;

			rdc_hw_timing(hw, &cur);
			off = vcd_hblank_offset(hw, &cur);

			if (off != RDC_NEVER)
				v->hb_rise = t + off;
		}
		break;
	case RDC_TRACE_DP:
		vcd_set(v, SIG_DP, !!a, t);
		break;
	default:
		vcd_set(v, SIG_FIFO, RDC_MIN(a, (uint32_t)RDC_FIFO_DEPTH), t);
		break;
	}
}

/* ---- opening and closing ------------------------------------------------- */

/* 10^k for k = 9 ... 15 and the $timescale that makes it the unit */
static const char *const vcd_scales[] = { "1 ns",   "100 ps", "10 ps", "1 ps",
					  "100 fs", "10 fs",  "1 fs" };

static const char *vcd_pick_unit(rdc_vcd *v)
{
	uint64_t per_s = NS_PER_S;

	for (size_t i = 0; i < RDC_ARRAY_SIZE(vcd_scales); i++, per_s *= 10)
		if (per_s % v->core_hz == 0) {
			v->per_cycle = per_s / v->core_hz;
			return vcd_scales[i];
		}
	v->per_cycle = 0;
	return vcd_scales[0];
}

/*
 * $date: now, or SOURCE_DATE_EPOCH when set (reproducible files: the
 * golden test sets it).
 */
static void vcd_date(char *out, size_t size)
{
	const char *env = getenv("SOURCE_DATE_EPOCH");
	time_t now = time(NULL);
	struct tm tm;

	if (env && *env) {
		char *end;
		unsigned long long s = strtoull(env, &end, 10);

		if (!*end)
			now = (time_t)s;
	}
	if (!gmtime_r(&now, &tm) ||
	    !strftime(out, size, "%Y-%m-%d %H:%M:%S UTC", &tm))
		snprintf(out, size, "unknown");
}

static void vcd_header(rdc_vcd *v, const struct rdc_hw *hw)
{
	const char *unit = vcd_pick_unit(v);
	char date[64];

	vcd_date(date, sizeof(date));
	vcd_printf(v, "$date\n\t%s\n$end\n", date);
	vcd_puts(v,
		 "$version\n\trdc RDC-1 simulator, librdc VCD writer\n$end\n");
	if (v->per_cycle)
		vcd_printf(v,
			   "$comment\n\tcore clock %u Hz: %llu units a cycle"
			   "\n$end\n",
			   v->core_hz, (unsigned long long)v->per_cycle);
	else
		vcd_printf(v,
			   "$comment\n\tcore clock %u Hz: cycle starts "
			   "rounded down to the nanosecond\n$end\n",
			   v->core_hz);
	vcd_printf(v, "$timescale %s $end\n", unit);
	vcd_puts(v, "$scope module rdc1 $end\n");
	for (unsigned int s = 0; s < SIG_COUNT; s++) {
		if (vcd_sigs[s].bits == 1)
			vcd_printf(v, "$var wire 1 %c %s $end\n", vcd_id(s),
				   vcd_sigs[s].name);
		else
			vcd_printf(v, "$var wire %u %c %s [%u:0] $end\n",
				   vcd_sigs[s].bits, vcd_id(s),
				   vcd_sigs[s].name, vcd_sigs[s].bits - 1);
	}
	vcd_puts(v, "$upscope $end\n$enddefinitions $end\n");

	/* every value once, at the chip's present time */
	v->last = rdc_hw_now(hw);
	vcd_time(v, v->last);
	vcd_puts(v, "$dumpvars\n");
	for (unsigned int s = 0; s < SIG_COUNT; s++)
		v->val[s] =
			UINT32_MAX; /* differs from any level: all written */
	vcd_sync(v, hw, v->last);
	vcd_puts(v, "$end\n");
}

int rdc_vcd_new(const char *path, struct rdc_hw *const *hw, rdc_vcd **out)
{
	rdc_vcd *v;

	if (!path || !hw || !*hw || !out)
		return RDC_E_INVAL;
	v = calloc(1, sizeof(*v));
	if (!v)
		return RDC_E_NOMEM;
	v->fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (v->fd < 0) {
		free(v);
		return rdc_err_detail(RDC_E_FILE, "%s: %s", path,
				      strerror(errno));
	}
	v->hwp = hw;
	v->core_hz = rdc_hw_core_hz(*hw) ? rdc_hw_core_hz(*hw) :
					   RDC_DEFAULT_CORE_HZ;
	vcd_header(v, *hw);
	*out = v;
	return 0;
}

static void vcd_chain(void *ctx, uint64_t time, unsigned int event, uint32_t a,
		      uint32_t b)
{
	rdc_vcd *v = ctx;

	rdc_vcd_trace(v, time, event, a, b);
	if (v->next_fn)
		v->next_fn(v->next_ctx, time, event, a, b);
}

int rdc_vcd_open(rdc_dev *dev, const char *path, rdc_vcd **out)
{
	struct rdc_hw *hw = rdc_dev_chip(dev);
	rdc_vcd *v;
	int ret;

	if (!dev || !path || !out)
		return RDC_E_INVAL;
	if (!hw)
		return RDC_E_NOSYS;
	/* hwp must outlive the call: it points into the dump itself */
	ret = rdc_vcd_new(path, &hw, &v);
	if (ret)
		return ret;
	v->own = hw;
	v->hwp = &v->own;
	v->hooked = hw;
	rdc_hw_get_trace(hw, &v->next_fn, &v->next_ctx);
	rdc_hw_set_trace(hw, vcd_chain, v);
	*out = v;
	return 0;
}

int rdc_vcd_close(rdc_vcd *v)
{
	const struct rdc_hw *hw;
	int ret;

	if (!v)
		return 0;
	hw = v->hwp ? *v->hwp : NULL;
	if (v->hooked) {
		rdc_trace_fn fn;
		void *ctx;

		rdc_hw_get_trace(v->hooked, &fn, &ctx);
		if (fn == vcd_chain && ctx == v)
			rdc_hw_set_trace(v->hooked, v->next_fn, v->next_ctx);
	}
	/* the dump ends at the chip's present time */
	if (hw && hw == v->seen) {
		uint64_t t = rdc_hw_now(hw) + v->base;

		if (t > v->last) {
			v->last = t;
			if (v->hb_rise <= t)
				vcd_set(v, SIG_HBLANK, 1, v->hb_rise);
			vcd_time(v, t);
		}
	}
	vcd_flush(v);
	ret = v->err ? RDC_E_FILE : 0;
	if (close(v->fd))
		ret = RDC_E_FILE;
	free(v);
	return ret;
}
