// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The "sim:" backend: an RDC-1 (hw-sim) and its display processor
 * (firmware-model) in this process.  Simulated time moves only inside
 * wait() and step(), so a host that never waits sees a frozen chip.
 */
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "rdc_dp_host.h"
#include "rdc_priv.h"

#define SIM_VRAM_DEFAULT (16u << 20)
#define SIM_VRAM_MIN	 (64u << 10)
#define SIM_VRAM_MAX	 (256u << 20)
#define SIM_FRAME_CAP	 ((uint32_t)RDC_CRTC_MAX_DISPLAY * RDC_CRTC_MAX_DISPLAY)

/*
 * A wait checks its condition between slices of simulated time.  Waits on
 * the DP (fence, idle, FIFO room, readback data) stop a slice at the exact
 * cycle the DP runs out of work (rdc_hw_run_until_idle), so a host that
 * waits for the DP resumes at the cycle it finished and a script's
 * statements follow each other without gaps.  Other waits (on the beam: a
 * frame is ~1.7 M cycles at 640x480) return up to one slice after the
 * event; slices start short and double up to a cap.
 */

struct sim {
	struct rdc_hw *hw; /* rdc_hw_size() bytes */
	struct rdc_dp *dp; /* rdc_dp_size() bytes */
	uint8_t *vram;
	uint32_t *frame[2];
	size_t vram_len;
	/*
	 * scanout=demand: a grab that found no frame attached a consumer,
	 * kept until a grab finds one (the frame scanned whole after it)
	 */
	bool grab_watch;
};

/*
 * VRAM and the frame buffers: zeroed blocks, in 2 MiB pages where the
 * kernel grants them (MADV_HUGEPAGE), since drawing walks VRAM a row
 * (4 KiB at 1024 pixels of XRGB8888) a step along a steep line and a
 * 4 KiB page a pixel costs a TLB miss each.  Under AddressSanitizer they
 * stay heap blocks, whose bounds it checks.
 */
#ifdef RDC_ASAN /* rdc_base.h */
static void *sim_big_alloc(size_t len)
{
	return calloc(len, 1);
}

static void sim_big_free(void *p, size_t len)
{
	(void)len;
	free(p);
}
#else
#define SIM_HUGE (2u << 20)

static size_t sim_big_len(size_t len)
{
	return (len + SIM_HUGE - 1) / SIM_HUGE * SIM_HUGE;
}

static void *sim_big_alloc(size_t len)
{
	size_t n = sim_big_len(len);
	uint8_t *p = mmap(NULL, n + SIM_HUGE, PROT_READ | PROT_WRITE,
			  MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	uintptr_t a;

	if (p == MAP_FAILED)
		return NULL;
	/* keep the 2 MiB-aligned n bytes, give back the rest */
	a = ((uintptr_t)p + SIM_HUGE - 1) & ~(uintptr_t)(SIM_HUGE - 1);
	if (a > (uintptr_t)p)
		munmap(p, a - (uintptr_t)p);
	munmap((uint8_t *)a + n, (uintptr_t)p + SIM_HUGE - a);
	madvise((void *)a, n, MADV_HUGEPAGE); /* a hint: may be refused */
	return (void *)a;
}

static void sim_big_free(void *p, size_t len)
{
	if (p)
		munmap(p, sim_big_len(len));
}
#endif

static struct sim *sim_of(rdc_dev *dev)
{
	return dev->priv;
}

/* "4M", "65536", "64K": bytes, or 0 if malformed or overflowing. */
static uint64_t sim_parse_size(const char *s, size_t len)
{
	uint64_t v = 0;
	size_t i = 0;

	if (len == 0)
		return 0;
	for (; i < len && s[i] >= '0' && s[i] <= '9'; i++) {
		v = v * 10 + (uint64_t)(s[i] - '0');
		if (v > SIM_VRAM_MAX)
			return 0;
	}
	if (i == 0)
		return 0;
	if (i + 1 == len) {
		switch (s[i]) {
		case 'k':
		case 'K':
			v <<= 10;
			break;
		case 'm':
		case 'M':
			v <<= 20;
			break;
		default:
			return 0;
		}
	} else if (i != len) {
		return 0;
	}
	return v;
}

static int sim_parse_opts(const char *opts, uint32_t *vram_size,
			  bool *on_demand)
{
	const char *p = opts;

	*vram_size = SIM_VRAM_DEFAULT;
	*on_demand = false;
	while (*p) {
		const char *end = strchr(p, ',');
		size_t len = end ? (size_t)(end - p) : strlen(p);

		if (len > 5 && !strncmp(p, "vram=", 5)) {
			uint64_t v = sim_parse_size(p + 5, len - 5);

			if (v < SIM_VRAM_MIN || v > SIM_VRAM_MAX || (v & 3))
				return RDC_E_URI;
			*vram_size = (uint32_t)v;
		} else if (len == 14 && !strncmp(p, "scanout=demand", 14)) {
			*on_demand = true;
		} else if (len) {
			return RDC_E_URI;
		}
		p += len;
		if (*p == ',')
			p++;
	}
	return 0;
}

static void sim_free(struct sim *s)
{
	if (!s)
		return;
	sim_big_free(s->vram, s->vram_len);
	sim_big_free(s->frame[0], SIM_FRAME_CAP * sizeof(uint32_t));
	sim_big_free(s->frame[1], SIM_FRAME_CAP * sizeof(uint32_t));
	free(s->dp);
	free(s->hw);
	free(s);
}

static int sim_open(rdc_dev *dev, const char *opts)
{
	struct rdc_hw_config cfg = { 0 };
	struct sim *s;
	bool on_demand;
	int ret;

	ret = sim_parse_opts(opts, &cfg.vram_size, &on_demand);
	if (ret)
		return ret;
	s = calloc(1, sizeof(*s));
	if (!s)
		return RDC_E_NOMEM;
	s->vram_len = cfg.vram_size;
	s->vram = sim_big_alloc(cfg.vram_size);
	s->frame[0] = sim_big_alloc(SIM_FRAME_CAP * sizeof(uint32_t));
	s->frame[1] = sim_big_alloc(SIM_FRAME_CAP * sizeof(uint32_t));
	s->hw = calloc(1, rdc_hw_size());
	s->dp = calloc(1, rdc_dp_size());
	if (!s->vram || !s->frame[0] || !s->frame[1] || !s->hw || !s->dp) {
		sim_free(s);
		return RDC_E_NOMEM;
	}
	rdc_hw_init(s->hw, &cfg, s->vram, s->frame[0], s->frame[1],
		    SIM_FRAME_CAP);
	rdc_dp_init(s->dp, s->hw);
	rdc_hw_set_on_demand(s->hw, on_demand);
	dev->priv = s;
	return 0;
}

static void sim_close(rdc_dev *dev)
{
	sim_free(sim_of(dev));
	dev->priv = NULL;
}

static int sim_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	*val = rdc_hw_read(sim_of(dev)->hw, reg);
	return 0;
}

static int sim_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	rdc_hw_write(sim_of(dev)->hw, reg, val);
	return 0;
}

static int sim_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	struct rdc_hw *hw = sim_of(dev)->hw;

	if (len > rdc_hw_vram_size(hw) || addr > rdc_hw_vram_size(hw) - len)
		return RDC_E_RANGE;
	return rdc_hw_vram_read(hw, addr, buf, (uint32_t)len) ? RDC_E_RANGE : 0;
}

static int sim_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len)
{
	struct rdc_hw *hw = sim_of(dev)->hw;

	if (len > rdc_hw_vram_size(hw) || addr > rdc_hw_vram_size(hw) - len)
		return RDC_E_RANGE;
	return rdc_hw_vram_write(hw, addr, buf, (uint32_t)len) ? RDC_E_RANGE :
								 0;
}

/* FIFO_DATA in bulk: the chip takes the words as rdc_hw_write would. */
static int sim_fifo_push(rdc_dev *dev, const uint32_t *words, uint32_t n)
{
	return (int)rdc_hw_fifo_push(sim_of(dev)->hw, words, n);
}

static int sim_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	return rdc_fifo_feed(dev, words, n, sim_fifo_push);
}

static int sim_wait(rdc_dev *dev, const struct rdc_wait *w)
{
	struct rdc_hw *hw = sim_of(dev)->hw;
	struct rdc_hw_wait hw_w;

	rdc_wait_to_hw(w, &hw_w);
	rdc_hw_wait_begin(hw, &hw_w);
	return rdc_wait_result_error(rdc_hw_wait_run(hw, &hw_w, RDC_NEVER));
}

static int sim_step(rdc_dev *dev, uint64_t cycles)
{
	struct rdc_hw *hw = sim_of(dev)->hw;

	if (cycles > UINT64_MAX - rdc_hw_now(hw))
		return RDC_E_RANGE;
	rdc_hw_run_until(hw, rdc_hw_now(hw) + cycles);
	return 0;
}

/*
 * A grab is a look: with scanout=demand, one that finds no frame (none
 * was kept: nobody looked while the picture changed) keeps a consumer
 * attached until a grab finds one, so that rdc_frame_grab's vblank
 * waits end with the frame scanned whole after it.
 */
static int sim_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height)
{
	struct sim *s = sim_of(dev);
	uint32_t w = 0, h = 0;
	const uint32_t *f = rdc_hw_frame(s->hw, &w, &h);

	if (!f) {
		if (!s->grab_watch)
			rdc_hw_consumer_attach(s->hw);
		s->grab_watch = true;
		return 1;
	}
	if (s->grab_watch)
		rdc_hw_consumer_detach(s->hw);
	s->grab_watch = false;
	*width = w;
	*height = h;
	if (cap < (size_t)w * h)
		return RDC_E_RANGE;
	memcpy(buf, f, (size_t)w * h * sizeof(*buf));
	return 0;
}

static int sim_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	struct rdc_hw *hw = sim_of(dev)->hw;
	struct rdc_hw_state st;

	rdc_hw_state(hw, &st);
	rdc_hw_set_pins(hw, (st.pins_in & ~mask) | (levels & mask));
	return 0;
}

/*
 * The chip reports every pin change at the cycle it happens
 * (RDC_TRACE_PINS); the wait sees the new level up to a slice later.  So
 * for the length of the wait the backend listens on the trace hook too,
 * passing everything on to whoever listened before, and gives the edge
 * the time the chip reported for it.
 */
struct sim_pins_watch {
	rdc_trace_fn fn;
	void *ctx;
	uint64_t changed[2]; /* last change of TE, IRQ; RDC_NEVER: none */
};

static void sim_pins_trace(void *ctx, uint64_t time, unsigned int event,
			   uint32_t a, uint32_t b)
{
	struct sim_pins_watch *w = ctx;

	if (event == RDC_TRACE_PINS) {
		if (b & RDC_PIN_TE)
			w->changed[0] = time;
		if (b & RDC_PIN_IRQ)
			w->changed[1] = time;
	}
	if (w->fn)
		w->fn(w->ctx, time, event, a, b);
}

static int sim_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			 uint64_t budget_cycles, uint64_t timeout_us,
			 struct rdc_pin_edge *ev)
{
	struct rdc_hw *hw = sim_of(dev)->hw;
	struct sim_pins_watch w = {
		.changed = { RDC_NEVER, RDC_NEVER },
	};
	uint64_t t = RDC_NEVER;
	int ret;

	rdc_hw_get_trace(hw, &w.fn, &w.ctx);
	(void)timeout_us;
	rdc_hw_set_trace(hw, sim_pins_trace, &w);
	ret = rdc_pins_wait_regs(dev, pins, edges, budget_cycles, ev);
	rdc_hw_set_trace(hw, w.fn, w.ctx);
	if (ret)
		return ret;
	/* the reported pins changed last at their edge */
	if (ev->pins & RDC_PIN_TE)
		t = w.changed[0];
	if ((ev->pins & RDC_PIN_IRQ) && w.changed[1] != RDC_NEVER &&
	    (t == RDC_NEVER || w.changed[1] > t))
		t = w.changed[1];
	if (t != RDC_NEVER)
		ev->time = t;
	return 0;
}

struct rdc_hw *rdc_sim_hw(rdc_dev *dev)
{
	return dev && dev->be == &rdc_backend_sim ? sim_of(dev)->hw : NULL;
}

static int sim_resume_get(rdc_dev *dev, struct rdc_hw_resume *s)
{
	rdc_hw_resume_get(rdc_sim_hw(dev), s);
	return 0;
}

const struct rdc_backend rdc_backend_sim = {
	.scheme = "sim",
	.open = sim_open,
	.close = sim_close,
	.reg_read = sim_reg_read,
	.reg_write = sim_reg_write,
	.vram_read = sim_vram_read,
	.vram_write = sim_vram_write,
	.submit = sim_submit,
	.wait = sim_wait,
	.step = sim_step,
	.frame_grab = sim_frame_grab,
	.pins_set = sim_pins_set,
	.pins_wait = sim_pins_wait,
	.resume_get = sim_resume_get,
};
