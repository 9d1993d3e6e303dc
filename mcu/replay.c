// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Replay of a golden scene's operations on the portable core, exactly as
 * librdc's sim: backend made them (userspace/lib/sim.c): the same calls
 * into hw-sim in the same order, so the chip goes through the same states
 * and cycles on any host.  Freestanding: built for the MCU image and for
 * its host twin alike.
 */
#include "scene.h"

static uint64_t get64(const uint32_t *w)
{
	return (uint64_t)w[0] | (uint64_t)w[1] << 32;
}

static void power_on(struct mcu_chip *c, uint32_t vram_size)
{
	struct rdc_hw_config cfg = { .vram_size = vram_size };

	/* the sim: backend's VRAM comes from calloc */
	rdc_memset(c->vram, 0, vram_size);
	rdc_hw_init(&c->hw, &cfg, c->vram, c->frame[0], c->frame[1],
		    MCU_FRAME_CAP);
	rdc_dp_init(&c->dp, &c->hw);
}

/* A WAIT operation as sim_wait runs it; true if the result matches. */
static bool replay_wait(struct rdc_hw *hw, const uint32_t *a)
{
	struct rdc_hw_wait hw_w = { 0 };
	enum rdc_hw_wait_result res;
	uint32_t i;

	for (i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		hw_w.term[i].test = a[4 * i];
		hw_w.term[i].reg = a[4 * i + 1];
		hw_w.term[i].mask = a[4 * i + 2];
		hw_w.term[i].value = a[4 * i + 3];
	}
	a += 4 * RDC_WAIT_TEST_TERMS;
	hw_w.needs_dp = a[0] != 0;
	hw_w.budget = get64(a + 1);
	rdc_hw_wait_begin(hw, &hw_w);
	res = rdc_hw_wait_run(hw, &hw_w, RDC_NEVER);
	if (res == RDC_HW_WAIT_MORE)
		res = RDC_HW_WAIT_TIMEOUT;
	return (uint32_t)res == a[3];
}

/* One operation (its arguments a[0..n-1]); an error string or NULL. */
static const char *replay_op(struct mcu_chip *c, const struct mcu_scene *s,
			     uint32_t op, const uint32_t *a, uint32_t n,
			     struct mcu_result *r)
{
	struct rdc_hw *hw = &c->hw;
	uint32_t i;

	switch (op) {
	case MCU_OP_REG_WRITE:
		if (n < 2)
			return "REG_WRITE without a value";
		for (i = 1; i < n; i++)
			rdc_hw_write(hw, a[0], a[i]);
		return NULL;
	case MCU_OP_REG_READ:
		if (n != 2)
			return "REG_READ length";
		if (rdc_hw_read(hw, a[0]) != a[1])
			r->mismatches++;
		return NULL;
	case MCU_OP_VRAM_WRITE:
		if (n != 3 || a[2] > s->ndata || a[1] > s->ndata - a[2])
			return "VRAM_WRITE outside the scene's data";
		if (rdc_hw_vram_write(hw, a[0], s->data + a[2], a[1]))
			r->mismatches++;
		return NULL;
	case MCU_OP_WAIT:
		if (n != MCU_OP_WAIT_ARGS)
			return "WAIT length";
		if (!replay_wait(hw, a))
			r->mismatches++;
		return NULL;
	case MCU_OP_STEP:
		if (n != 2)
			return "STEP length";
		if (get64(a) > UINT64_MAX - hw->now)
			return "STEP past the end of time";
		rdc_hw_run_until(hw, hw->now + get64(a));
		return NULL;
	case MCU_OP_PINS:
		if (n != 2)
			return "PINS length";
		rdc_hw_set_pins(hw, (hw->pins_in & ~a[0]) | (a[1] & a[0]));
		return NULL;
	case MCU_OP_MARK:
		r->total = hw->now;
		return NULL;
	default:
		return "unknown operation";
	}
}

void mcu_replay(struct mcu_chip *c, const struct mcu_scene *s,
		struct mcu_result *r)
{
	const uint32_t *w = s->ops, *end = s->ops + s->nwords;
	const uint32_t *frame;
	bool powered = false;

	rdc_memset(r, 0, sizeof(*r));
	if (s->vram_size > MCU_VRAM_CAP || s->vram_size < 4 ||
	    (s->vram_size & 3)) {
		r->error = "VRAM size";
		return;
	}
	while (w != end && !r->error) {
		uint32_t op, n;
		uint64_t t;

		if ((uint32_t)(end - w) < MCU_OP_HEAD) {
			r->error = "operation cut short";
			break;
		}
		op = w[0] & 0xffu;
		n = w[0] >> 8;
		t = get64(w + 1);
		if (n > (uint32_t)(end - w) - MCU_OP_HEAD) {
			r->error = "operation cut short";
			break;
		}
		w += MCU_OP_HEAD;
		r->ops++;
		if (op == MCU_OP_POWER) {
			power_on(c, s->vram_size);
			powered = true;
		} else if (!powered) {
			r->error = "operation before POWER";
		} else if (op == MCU_OP_END) {
			if (c->hw.now < t)
				rdc_hw_run_until(&c->hw, t);
			if (c->hw.now != t)
				r->mismatches++;
			w = end;
			break;
		} else {
			if (c->hw.now != t)
				r->mismatches++;
			r->error = replay_op(c, s, op, w, n, r);
		}
		w += n;
	}
	if (!powered) {
		if (!r->error)
			r->error = "no operations";
		return;
	}
	r->time = c->hw.now;
	r->perf = c->hw.perf;
	frame = rdc_hw_frame(&c->hw, &r->width, &r->height);
	if (frame)
		r->crc = mcu_crc32_xrgb(frame, r->width * r->height);
	else
		r->width = r->height = 0;
}

uint32_t mcu_crc32_xrgb(const uint32_t *px, uint32_t n)
{
	/* the reflected polynomial 0xedb88320, four bits at a time */
	static const uint32_t nib[16] = {
		0x00000000, 0x1db71064, 0x3b6e20c8, 0x26d930ac,
		0x76dc4190, 0x6b6b51f4, 0x4db26158, 0x5005713c,
		0xedb88320, 0xf00f9344, 0xd6d6a3e8, 0xcb61b38c,
		0x9b64c2b0, 0x86d3d2d4, 0xa00ae278, 0xbdbdf21c,
	};
	uint32_t crc = 0xffffffffu, i, b;

	for (i = 0; i < n; i++) {
		uint32_t v = px[i];

		for (b = 0; b < 4; b++) {
			crc ^= (v >> (8 * b)) & 0xffu;
			crc = (crc >> 4) ^ nib[crc & 15u];
			crc = (crc >> 4) ^ nib[crc & 15u];
		}
	}
	return crc ^ 0xffffffffu;
}

/* ---- the output line, without libc ------------------------------------- */

struct out {
	char *p;
	uint32_t len, cap;
};

static void put_s(struct out *o, const char *s)
{
	while (*s && o->len + 1 < o->cap)
		o->p[o->len++] = *s++;
	o->p[o->len] = '\0';
}

static void put_u(struct out *o, uint64_t v)
{
	char d[21];
	uint32_t i = sizeof(d) - 1;

	d[i] = '\0';
	do {
		d[--i] = (char)('0' + v % 10u);
		v /= 10u;
	} while (v);
	put_s(o, d + i);
}

static void put_x32(struct out *o, uint32_t v)
{
	static const char hex[] = "0123456789abcdef";
	char d[9];
	uint32_t i;

	for (i = 0; i < 8; i++)
		d[i] = hex[(v >> (28 - 4 * i)) & 15u];
	d[8] = '\0';
	put_s(o, d);
}

static void put_kv(struct out *o, const char *k, uint64_t v)
{
	put_s(o, " ");
	put_s(o, k);
	put_s(o, " ");
	put_u(o, v);
}

void mcu_format(char *buf, uint32_t cap, const struct mcu_scene *s,
		const struct mcu_result *r)
{
	struct out o = { .p = buf, .cap = cap };

	if (!cap)
		return;
	buf[0] = '\0';
	put_s(&o, "scene ");
	put_s(&o, s->name);
	if (r->error) {
		put_s(&o, " error ");
		put_s(&o, r->error);
		return;
	}
	put_kv(&o, "vram", s->vram_size);
	put_kv(&o, "ops", r->ops);
	put_kv(&o, "total", r->total);
	put_kv(&o, "time", r->time);
	put_kv(&o, "frame", r->width);
	put_s(&o, "x");
	put_u(&o, r->height);
	put_s(&o, " crc32 ");
	put_x32(&o, r->crc);
	put_kv(&o, "busy", r->perf.busy);
	put_kv(&o, "stall", r->perf.stall);
	put_kv(&o, "pixels", r->perf.pixels);
	put_kv(&o, "cmds", r->perf.cmds);
	put_kv(&o, "mismatches", r->mismatches);
}
