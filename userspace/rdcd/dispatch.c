// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: a client's request to its handler.  HELLO first; then the
 * checks every request passes (header, control of the device); then one
 * handler a message type, from a table.  WAIT, STEP and SUBMIT become
 * pending (pending.c); FRAME_GRAB is frames.c's, HIST_* hist.c's.
 */
#include <string.h>

#include "serve.h"

bool rdcd_reg_read_changes(uint32_t reg)
{
	return rdc_reg_read_has_effect(reg);
}

bool rdcd_reg_ok(uint32_t reg)
{
	return reg < RDC_REG_WINDOW && !(reg & 3);
}

static void rdcd_hello(struct rdcd *d, struct rdcd_client *c,
		       const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	struct rdc_proto_hello hello;
	struct rdc_proto_hello_reply r = {
		.version = RDC_PROTO_VERSION,
		.run_mode = d->mode,
		.vram_size = d->vram_size,
		.client_id = c->id,
	};
	uint8_t out[RDC_PROTO_HELLO_REPLY_SIZE];
	uint32_t st;

	if (c->hello) {
		rdcd_reply(d, c, h, RDC_ST_ORDER, NULL, 0);
		return;
	}
	st = (uint32_t)rdc_proto_hello_decode(pl, h->len, &hello);
	if (st) {
		rdcd_fatal(d, c, h, st);
		return;
	}
	if (c->tcp && d->have_token) {
		if (rdc_auth_locked(&d->auth, c->peer, rdcd_wall_ns())) {
			rdcd_fatal(d, c, h, RDC_ST_AUTH);
			return;
		}
		if (!rdc_auth_token_equal(d->token, d->token_len, hello.token,
					  hello.token_len)) {
			rdc_auth_failed(&d->auth, c->peer, rdcd_wall_ns());
			rdcd_fatal(d, c, h, RDC_ST_AUTH);
			return;
		}
		rdc_auth_passed(&d->auth, c->peer);
	}
	if (d->nclients >= RDCD_MAX_CLIENTS ||
	    rdcd_count_lis(d, c->lis, true, NULL) >=
		    RDCD_MAX_CLIENTS_PER_LISTENER) {
		rdcd_fatal(d, c, h, RDC_ST_BUSY);
		return;
	}
	c->hello = true;
	d->nclients++;
	rdcd_watch(d);
	rdcd_log(d, RDCD_LOG_INFO, "client %u said HELLO (%s)", c->id, c->peer);
	r.caps = RDC_CAP_ALL &
		 ~(d->mode == RDC_RUN_STEPPED ? 0u : RDC_CAP_STEP);
	r.caps &= hello.caps | RDC_CAP_STEP;
	if ((hello.flags & RDC_HELLO_CONTROL) && !d->ctl) {
		d->ctl = c;
		rdcd_log(d, RDCD_LOG_INFO, "client %u has control", c->id);
	}
	r.flags = d->ctl == c ? RDC_HELLO_CONTROL : 0;
	r.core_hz = RDC_DEFAULT_CORE_HZ;
	rdc_proto_hello_reply_encode(out, &r);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
}

/* Does this request need control of the device? */
static bool rdcd_needs_control(const struct rdcd *d,
			       const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	switch (h->type) {
	case RDC_MSG_REG_WRITE:
	case RDC_MSG_VRAM_WRITE:
	case RDC_MSG_SUBMIT:
	case RDC_MSG_STEP:
	case RDC_MSG_RESET:
	case RDC_MSG_PINS_SET:
		return true;
	case RDC_MSG_WAIT:
		/* in stepped mode a wait moves time */
		return d->mode == RDC_RUN_STEPPED;
	case RDC_MSG_REG_READ:
		return rdcd_reg_read_changes(rdc_proto_get32(pl));
	default:
		return false;
	}
}

/* The HI register whose value a read of `reg` snapshots, or 0. */
static uint32_t rdcd_snap_hi(uint32_t reg)
{
	switch (reg) {
	case RDC_REG_TIME_LO:
	case RDC_REG_PERF_BUSY_LO:
	case RDC_REG_PERF_STALL_LO:
	case RDC_REG_PERF_PIXELS_LO:
		return reg + 4;
	default:
		return 0;
	}
}

/* A chip reset drops the snapshots, the clients' as the chip's. */
static void rdcd_snap_forget(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		c->snap_reg = 0;
}

/*
 * A client's register read.  The chip keeps one *_HI snapshot, taken by
 * a *_LO read (docs/hardware.md); several clients reading 64-bit
 * counters would take each other's.  So each client has its own: a LO
 * read here reads its HI on the chip at once (the chip's snapshot used
 * up: the chip's state is as after a whole 64-bit read, and a trace
 * holds both reads), and that client's HI read is answered from it.
 */
static int rdcd_reg_read(struct rdcd *d, struct rdcd_client *c, uint32_t reg,
			 uint32_t *v)
{
	uint32_t hi = rdcd_snap_hi(reg);
	int ret;

	if (c->snap_reg && reg == c->snap_reg) {
		*v = c->snap_val;
		c->snap_reg = 0;
		return 0;
	}
	ret = rdc_reg_read(d->dev, reg, v);
	if (!ret && hi) {
		c->snap_reg = 0;
		if (!rdc_reg_read(d->dev, hi, &c->snap_val))
			c->snap_reg = hi;
	}
	return ret;
}

/*
 * A request's handler: the header was checked (rdc_proto_request_check:
 * the payload has the type's length), and so was control of the device.
 * *body is the payload; a handler may take it over (SUBMIT).
 */
typedef void rdcd_req_fn(struct rdcd *d, struct rdcd_client *c,
			 const struct rdc_proto_hdr *h, uint8_t **body);

static void rdcd_req_reg_read(struct rdcd *d, struct rdcd_client *c,
			      const struct rdc_proto_hdr *h, uint8_t **body)
{
	uint8_t out[4];
	uint32_t v = 0;
	int ret = rdcd_reg_read(d, c, rdc_proto_get32(*body), &v);

	rdc_proto_put32(out, v);
	if (ret)
		rdcd_reply_err(d, c, h, ret);
	else
		rdcd_reply(d, c, h, RDC_ST_OK, out, 4);
}

static void rdcd_req_reg_write(struct rdcd *d, struct rdcd_client *c,
			       const struct rdc_proto_hdr *h, uint8_t **body)
{
	const uint8_t *pl = *body;
	int ret;

	if (rdc_proto_get32(pl) == RDC_REG_CONTROL &&
	    (rdc_proto_get32(pl + 4) & RDC_CONTROL_SOFT_RESET))
		rdcd_snap_forget(d);
	ret = rdc_reg_write(d->dev, rdc_proto_get32(pl),
			    rdc_proto_get32(pl + 4));
	rdcd_reply_err(d, c, h, ret);
	/* a W1C of IRQ_STATUS (or a reset) lowers bits: the next raise
	 * of one of them is an event again */
	rdcd_irq_events(d);
}

static void rdcd_req_vram_read(struct rdcd *d, struct rdcd_client *c,
			       const struct rdc_proto_hdr *h, uint8_t **body)
{
	uint32_t addr = rdc_proto_get32(*body),
		 len = rdc_proto_get32(*body + 4);
	uint8_t *p;

	if (len > RDC_PROTO_VRAM_CHUNK) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	if ((uint64_t)addr + len > d->vram_size) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	p = rdcd_reply(d, c, h, RDC_ST_OK, NULL, len);
	if (p && rdc_vram_read(d->dev, addr, p, len))
		memset(p, 0, len); /* checked above: cannot happen */
}

static void rdcd_req_vram_write(struct rdcd *d, struct rdcd_client *c,
				const struct rdc_proto_hdr *h, uint8_t **body)
{
	int ret = rdc_vram_write(d->dev, rdc_proto_get32(*body), *body + 4,
				 h->len - 4);

	rdcd_reply_err(d, c, h, ret);
}

static void rdcd_req_submit(struct rdcd *d, struct rdcd_client *c,
			    const struct rdc_proto_hdr *h, uint8_t **body)
{
	size_t n = h->len / 4;

	c->pend = RDCD_PEND_SUBMIT;
	c->pend_hdr = *h;
	c->pend_words = *body; /* taken over */
	*body = NULL;
	c->pend_n = n;
	c->pend_done = 0;
	c->pend_start = rdc_hw_now(d->hw);
	c->pend_wall_ns = rdcd_wall_ns();
	/* stepped: the loop's next turn runs it on the chip */
	if (d->mode != RDC_RUN_STEPPED)
		rdcd_pending_step(d, c);
}

static void rdcd_req_wait(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, uint8_t **body)
{
	struct rdc_hw_wait w;
	int st = rdcd_wait_from_proto(*body, h->len, &w);

	if (st) {
		rdcd_reply(d, c, h, (uint32_t)st, NULL, 0);
		return;
	}
	c->pend = RDCD_PEND_WAIT;
	c->pend_hdr = *h;
	c->pend_wait = w;
	c->pend_start = rdc_hw_now(d->hw);
	c->pend_wall_ns = rdcd_wall_ns();
	if (d->mode == RDC_RUN_STEPPED) {
		c->pend_hw = w;
		rdc_hw_wait_begin(d->hw, &c->pend_hw);
	} else if (rdcd_pending_step(d, c)) {
		rdcd_irq_events(d);
	}
}

static void rdcd_req_step(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, uint8_t **body)
{
	uint64_t cyc = rdc_proto_get64(*body);

	if (cyc > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	c->pend = RDCD_PEND_STEP;
	c->pend_hdr = *h;
	c->pend_target = rdc_hw_now(d->hw) + cyc;
	c->pend_start = rdc_hw_now(d->hw);
	c->pend_wall_ns = rdcd_wall_ns();
	if (d->mode != RDC_RUN_STEPPED)
		rdcd_pending_step(d, c);
}

static void rdcd_req_frame_grab(struct rdcd *d, struct rdcd_client *c,
				const struct rdc_proto_hdr *h, uint8_t **body)
{
	rdcd_frame_grab(d, c, h, *body);
}

static void rdcd_req_subscribe(struct rdcd *d, struct rdcd_client *c,
			       const struct rdc_proto_hdr *h, uint8_t **body)
{
	const uint8_t *pl = *body;
	uint32_t ev = rdc_proto_get32(pl), every = rdc_proto_get32(pl + 4);
	uint32_t enc = rdc_proto_get32(pl + 8);

	if ((ev & ~(RDC_SUB_FRAMES | RDC_SUB_IRQ)) || enc >= RDC_ENC_COUNT_ ||
	    ((ev & RDC_SUB_FRAMES) && !every)) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	c->sub_events = ev;
	c->sub_every = every ? every : 1;
	c->sub_enc = enc;
	c->frame_tick = 0;
	rdcd_prev_free(d, c);
	rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
}

static void rdcd_req_stats(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *h, uint8_t **body)
{
	struct rdc_proto_stats ps = { 0 };
	struct rdc_stats st;
	uint8_t out[RDC_PROTO_STATS_SIZE];
	int ret = rdc_stats_get(d->dev, &st);

	(void)body;
	if (ret) {
		rdcd_reply_err(d, c, h, ret);
		return;
	}
	ps.time = st.time;
	ps.busy = st.busy;
	ps.stall = st.stall;
	ps.pixels = st.pixels;
	ps.frames = st.frames;
	ps.cmds = st.cmds;
	ps.last_cycles = st.last_cycles;
	ps.last_opcode = st.last_opcode;
	ps.clients = d->nclients;
	ps.frames_sent = c->frames_sent;
	ps.frames_dropped = c->frames_dropped;
	rdc_proto_stats_encode(out, &ps);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
}

static void rdcd_req_reset(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *h, uint8_t **body)
{
	uint32_t v = rdc_proto_get32(*body);
	int ret;

	if (v != RDC_RESET_SOFT && v != RDC_RESET_POWER) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	rdcd_reset_pending(d, c, v == RDC_RESET_POWER);
	rdcd_snap_forget(d);
	if (v == RDC_RESET_SOFT) {
		ret = rdc_reset(d->dev);
	} else {
		ret = rdcd_power_cycle(d);
		if (ret) {
			rdcd_log(d, RDCD_LOG_ERR, "power cycle failed: %s",
				 rdc_strerror(ret));
			rdcd_reply_err(d, c, h, ret);
			return;
		}
		d->pace = (struct rdc_pace){ 0 }; /* starts afresh */
	}
	rdcd_log(d, RDCD_LOG_INFO, "client %u: reset (%s)", c->id,
		 v == RDC_RESET_POWER ? "power" : "soft");
	rdcd_reply_err(d, c, h, ret);
}

static void rdcd_req_claim(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *h, uint8_t **body)
{
	(void)body;
	if (!d->ctl) {
		d->ctl = c;
		rdcd_log(d, RDCD_LOG_INFO, "client %u has control", c->id);
	}
	rdcd_reply(d, c, h, d->ctl == c ? RDC_ST_OK : RDC_ST_BUSY, NULL, 0);
}

static void rdcd_req_release(struct rdcd *d, struct rdcd_client *c,
			     const struct rdc_proto_hdr *h, uint8_t **body)
{
	(void)body;
	if (d->ctl == c) {
		d->ctl = NULL;
		rdcd_log(d, RDCD_LOG_INFO, "client %u released control", c->id);
	}
	rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
}

static void rdcd_req_ping(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, uint8_t **body)
{
	(void)body;
	rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
}

/*
 * Drive RESET_N and BL_EN as a wire to the chip would; the reply is the
 * four levels after.  A trace records the change (record.c).
 */
static void rdcd_req_pins_set(struct rdcd *d, struct rdcd_client *c,
			      const struct rdc_proto_hdr *h, uint8_t **body)
{
	const uint8_t *pl = *body;
	uint32_t mask = rdc_proto_get32(pl), levels = rdc_proto_get32(pl + 4);
	uint8_t out[4];
	uint32_t pins = 0;
	int ret;

	/* RESET_N moved resets the chip */
	if (mask & RDC_PIN_RESET_N)
		rdcd_snap_forget(d);
	if (mask & ~RDC_PINS_IN) {
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	ret = rdc_pins_set(d->dev, mask, levels);
	if (!ret)
		ret = rdc_pins_get(d->dev, &pins);
	if (ret) {
		rdcd_reply_err(d, c, h, ret);
		return;
	}
	if (mask)
		rdcd_log(d, RDCD_LOG_DEBUG, "client %u: pins %#x", c->id, pins);
	rdc_proto_put32(out, pins);
	rdcd_reply(d, c, h, RDC_ST_OK, out, sizeof(out));
	rdcd_irq_events(d);
}

static void rdcd_req_hist(struct rdcd *d, struct rdcd_client *c,
			  const struct rdc_proto_hdr *h, uint8_t **body)
{
	rdcd_hist(d, c, h, *body);
}

/* Every request after HELLO, by message type. */
static rdcd_req_fn *const rdcd_requests[RDC_MSG_REQUEST_LAST + 1] = {
	[RDC_MSG_REG_READ] = rdcd_req_reg_read,
	[RDC_MSG_REG_WRITE] = rdcd_req_reg_write,
	[RDC_MSG_VRAM_READ] = rdcd_req_vram_read,
	[RDC_MSG_VRAM_WRITE] = rdcd_req_vram_write,
	[RDC_MSG_SUBMIT] = rdcd_req_submit,
	[RDC_MSG_WAIT] = rdcd_req_wait,
	[RDC_MSG_STEP] = rdcd_req_step,
	[RDC_MSG_FRAME_GRAB] = rdcd_req_frame_grab,
	[RDC_MSG_SUBSCRIBE] = rdcd_req_subscribe,
	[RDC_MSG_STATS] = rdcd_req_stats,
	[RDC_MSG_RESET] = rdcd_req_reset,
	[RDC_MSG_CLAIM] = rdcd_req_claim,
	[RDC_MSG_RELEASE] = rdcd_req_release,
	[RDC_MSG_PING] = rdcd_req_ping,
	[RDC_MSG_PINS_SET] = rdcd_req_pins_set,
	[RDC_MSG_HIST_OPEN] = rdcd_req_hist,
	[RDC_MSG_HIST_READ] = rdcd_req_hist,
	[RDC_MSG_HIST_SET] = rdcd_req_hist,
	[RDC_MSG_HIST_END] = rdcd_req_hist,
};

void rdcd_dispatch(struct rdcd *d, struct rdcd_client *c,
		   const struct rdc_proto_hdr *h, uint8_t **body)
{
	const uint8_t *pl = *body;
	rdcd_req_fn *fn;
	int st;

	if (h->type == RDC_MSG_HELLO) {
		rdcd_hello(d, c, h, pl);
		return;
	}
	if (!c->hello) {
		rdcd_reply(d, c, h, RDC_ST_ORDER, NULL, 0);
		return;
	}
	st = rdc_proto_request_check(h);
	if (st) {
		rdcd_reply(d, c, h, (uint32_t)st, NULL, 0);
		return;
	}
	if (rdcd_needs_control(d, h, pl) && d->ctl != c) {
		rdcd_reply(d, c, h, RDC_ST_BUSY, NULL, 0);
		return;
	}
	fn = h->type < RDC_ARRAY_SIZE(rdcd_requests) ? rdcd_requests[h->type] :
						       NULL;
	if (fn)
		fn(d, c, h, body);
	else
		rdcd_reply(d, c, h, RDC_ST_TYPE, NULL, 0);
}

bool rdcd_touches_chip(const struct rdcd *d, const struct rdc_proto_hdr *h,
		       const uint8_t *pl)
{
	switch (h->type) {
	case RDC_MSG_REG_WRITE:
	case RDC_MSG_VRAM_WRITE:
	case RDC_MSG_SUBMIT:
	case RDC_MSG_WAIT:
	case RDC_MSG_STEP:
	case RDC_MSG_PINS_SET:
	case RDC_MSG_RESET:
		return true;
	case RDC_MSG_HIST_OPEN:
	case RDC_MSG_HIST_READ:
	case RDC_MSG_HIST_SET:
	case RDC_MSG_HIST_END:
		/* a history's entries are complete between commands only */
		return true;
	case RDC_MSG_REG_READ:
		/* a trace replays reads between commands, never inside */
		return (d->rec && !rdcd_chip_between(d)) || h->len < 4 ||
		       rdcd_reg_read_changes(rdc_proto_get32(pl));
	case RDC_MSG_VRAM_READ:
	case RDC_MSG_STATS:
		return d->rec && !rdcd_chip_between(d);
	default:
		return false;
	}
}
