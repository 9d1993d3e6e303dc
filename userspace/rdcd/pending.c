// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: requests that take simulated time (WAIT, STEP, SUBMIT), one
 * pending per client.  In stepped mode the controller's request moves
 * time itself, on the chip's stack (chip.c), a piece at a time; in paced
 * and fast modes time belongs to the loop and a pending request is only
 * checked after it moved.  A reset ends what is pending.
 */
#include <stdlib.h>
#include <string.h>

#include "serve.h"

/* A wait's budget as every backend of librdc defaults it: 0 = ten seconds. */
static uint64_t rdcd_wait_budget(uint64_t budget)
{
	return budget ? budget : RDC_WAIT_BUDGET_DEFAULT;
}

int rdcd_wait_from_proto(const uint8_t *pl, size_t len, struct rdc_hw_wait *w)
{
	struct rdc_proto_wait pw;
	int st = rdc_proto_wait_decode(pl, len, &pw);

	if (st)
		return st;
	memset(w, 0, sizeof(*w));
	if (pw.budget > (uint64_t)RDCD_MAX_BUDGET_S * RDC_DEFAULT_CORE_HZ)
		return RDC_ST_RANGE;
	w->budget = rdcd_wait_budget(pw.budget);
	w->needs_dp = pw.needs_dp;
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		if (pw.term[i].kind > RDC_WAIT_TEST_EQ)
			return RDC_ST_INVAL;
		if (pw.term[i].kind != RDC_WAIT_TEST_NONE &&
		    (!rdcd_reg_ok(pw.term[i].reg) ||
		     rdcd_reg_read_changes(pw.term[i].reg)))
			return RDC_ST_INVAL;
		w->term[i].test = pw.term[i].kind;
		w->term[i].reg = pw.term[i].reg;
		w->term[i].mask = pw.term[i].mask;
		w->term[i].value = pw.term[i].value;
	}
	return 0;
}

static bool rdcd_halted(struct rdcd *d)
{
	return rdc_hw_read(d->hw, RDC_REG_STATUS) & RDC_STATUS_DP_HALTED;
}

/*
 * Stepped mode: the controller's wait moves time itself, on the chip's
 * stack, a piece at a time with a yield point between (chip.c), so that
 * everyone else is served meanwhile; where it ends does not depend on the
 * pieces (hw-sim/wait.c).  The trace records the time it moved as steps,
 * between whatever the others did meanwhile.  A client that left stops
 * its wait: nobody is there to answer.
 */
static int rdcd_stepped_wait_run(struct rdcd *d, struct rdcd_client *c,
				 struct rdc_hw_wait *w)
{
	for (;;) {
		int ret;

		rdc_server_rec_time_moved(d->rec, rdc_hw_now(d->hw));
		ret = rdc_wait_result_error(
			rdc_hw_wait_run(d->hw, w, RDCD_WAIT_PIECE));
		if (ret != 1)
			return ret;
		if (c->dead)
			return RDC_E_IO;
		rdcd_chip_yield_point(d);
	}
}

/* Words of a SUBMIT go in through rdc_submit, so a recording sees them. */
static int rdcd_push(rdc_dev *dev, const uint32_t *words, uint32_t n)
{
	int ret = rdc_submit(dev, words, n);

	return ret ? ret : (int)n;
}

/*
 * One step of the library's FIFO feed (rdc_fifo_feed_step) with the next
 * words of the client's SUBMIT: how many went in, 0 with *room the wait
 * for room that comes next, or an error.
 */
static int rdcd_submit_step(struct rdcd *d, struct rdcd_client *c,
			    struct rdc_wait_cond *room)
{
	uint32_t w[RDC_FIFO_DEPTH];
	size_t k = RDC_MIN(c->pend_n - c->pend_done, (size_t)RDC_FIFO_DEPTH);
	int ret;

	for (size_t i = 0; i < k; i++)
		w[i] = rdc_proto_get32(c->pend_words + 4 * (c->pend_done + i));
	ret = rdc_fifo_feed_step(d->dev, w, k, rdcd_push, room);
	if (ret > 0)
		c->pend_done += (size_t)ret;
	return ret;
}

/*
 * Stepped mode: a SUBMIT feeds the FIFO as sim:'s rdc_submit does (the
 * library's feed, rdc_fifo_feed_step: the same reads of FIFO_FREE, the
 * same waits for room, so the same cycles), except that the waits of one
 * SUBMIT share one budget of RDCD_SUBMIT_BUDGET_S simulated seconds: then
 * TIMEOUT, the words not yet taken dropped.  Each wait gets sim:'s
 * default budget or what is left.
 */
static int rdcd_stepped_submit(struct rdcd *d, struct rdcd_client *c)
{
	const uint64_t total =
		(uint64_t)RDCD_SUBMIT_BUDGET_S * RDC_DEFAULT_CORE_HZ;
	uint64_t start = rdc_hw_now(d->hw);

	while (c->pend_done < c->pend_n) {
		struct rdc_wait_cond room_cond;
		int ret;

		if (c->dead)
			return RDC_E_IO;
		ret = rdcd_submit_step(d, c, &room_cond);
		if (ret < 0)
			return ret;
		if (!ret) {
			struct rdc_hw_wait *rw = &c->pend_hw;
			uint64_t used = rdc_hw_now(d->hw) - start;

			if (used >= total)
				return RDC_E_TIMEOUT;
			*rw = (struct rdc_hw_wait){
				.term[0] = room_cond,
				.needs_dp = true,
				.budget = rdcd_wait_budget(RDC_MIN(
					RDC_WAIT_BUDGET_DEFAULT, total - used)),
			};
			rdc_hw_wait_begin(d->hw, &c->pend_hw);
			ret = rdcd_stepped_wait_run(d, c, &c->pend_hw);
			if (ret)
				return ret;
		}
	}
	return 0;
}

/* The pending request is over: answer it (unless its client left). */
static void rdcd_pending_end(struct rdcd *d, struct rdcd_client *c, int ret)
{
	if (!c->dead)
		rdcd_reply_err(d, c, &c->pend_hdr, ret);
	c->pend = RDCD_PEND_NONE;
	free(c->pend_words);
	c->pend_words = NULL;
}

/* Stepped mode, on the chip's stack: the controller's request, whole. */
static void rdcd_stepped_job(struct rdcd *d, void *arg)
{
	struct rdcd_client *c = arg;
	int ret = 0;

	switch (c->pend) {
	case RDCD_PEND_WAIT:
		ret = rdcd_stepped_wait_run(d, c, &c->pend_hw);
		break;
	case RDCD_PEND_SUBMIT:
		ret = rdcd_stepped_submit(d, c);
		break;
	case RDCD_PEND_STEP:
		while (rdc_hw_now(d->hw) < c->pend_target && !c->dead) {
			rdc_server_rec_time_moved(d->rec, rdc_hw_now(d->hw));
			rdc_hw_run_until(d->hw, RDC_MIN(rdc_hw_now(d->hw) +
								RDCD_WAIT_PIECE,
							c->pend_target));
			rdcd_chip_yield_point(d);
		}
		break;
	default:
		break;
	}
	/* the answer depends on the time moved: a live trace has it first */
	rdc_server_rec_sync(d->rec);
	rdcd_pending_end(d, c, ret);
	d->chip_client = NULL;
}

int rdcd_stepped_start(struct rdcd *d)
{
	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->pend == RDCD_PEND_NONE)
			continue;
		d->chip_client = c;
		return rdcd_chip_run(d, rdcd_stepped_job, c);
	}
	return -1;
}

/*
 * Paced and fast modes: progress on a pending request after the loop
 * moved time.  Returns true when it finished and was answered.  A SUBMIT
 * that cannot get FIFO room (the DP in an endless list) ends with TIMEOUT
 * after RDCD_SUBMIT_BUDGET_S of simulated or of host time, whichever
 * comes first.
 */
bool rdcd_pending_step(struct rdcd *d, struct rdcd_client *c)
{
	int ret = 0;

	switch (c->pend) {
	case RDCD_PEND_SUBMIT:
		/* the feed's waits are the daemon's clock here */
		while (c->pend_done < c->pend_n) {
			struct rdc_wait_cond room;

			ret = rdcd_submit_step(d, c, &room);
			if (ret <= 0)
				break;
			ret = 0;
		}
		if (!ret && c->pend_done < c->pend_n) {
			uint64_t sim = (uint64_t)RDCD_SUBMIT_BUDGET_S *
				       RDC_DEFAULT_CORE_HZ;
			uint64_t wall =
				(uint64_t)RDCD_SUBMIT_BUDGET_S * 1000000000ull;

			if (rdcd_halted(d))
				ret = RDC_E_HALTED;
			else if (rdc_hw_now(d->hw) - c->pend_start >= sim ||
				 rdcd_wall_ns() - c->pend_wall_ns >= wall)
				ret = RDC_E_TIMEOUT;
			else
				return false;
		}
		break;
	case RDCD_PEND_WAIT: {
		struct rdc_hw_wait w = c->pend_wait;

		/* time moves with the daemon's clock: only the checks here */
		w.start = c->pend_start;
		ret = rdc_wait_result_error(rdc_hw_wait_check(d->hw, &w));
		if (ret == 1)
			return false;
		break;
	}
	case RDCD_PEND_STEP:
		if (rdc_hw_now(d->hw) < c->pend_target)
			return false;
		break;
	default:
		return false;
	}
	rdcd_pending_end(d, c, ret);
	return true;
}

bool rdcd_feed_pending(struct rdcd *d)
{
	bool more = false;

	for (struct rdcd_client *c = d->clients; c; c = c->next) {
		if (c->pend != RDCD_PEND_SUBMIT || c->dead)
			continue;
		if (!rdcd_pending_step(d, c))
			more = true;
	}
	return more;
}

bool rdcd_has_pending(const struct rdcd *d)
{
	for (const struct rdcd_client *c = d->clients; c; c = c->next)
		if (c->pend != RDCD_PEND_NONE)
			return true;
	return false;
}

void rdcd_after_advance(struct rdcd *d)
{
	/* (stepped: the chip's run answered its request itself) */
	for (struct rdcd_client *c = d->clients; c; c = c->next)
		if (d->mode != RDC_RUN_STEPPED && c->pend != RDCD_PEND_NONE &&
		    !c->dead)
			rdcd_pending_step(d, c);
	rdcd_irq_events(d);
}

/*
 * Before a reset: a run of the chip stops where it is (the reset replaces
 * what it was doing); the resetting client's own pending request ends
 * with RESET (it asked for it: the way to abort a submit stuck behind an
 * endless display list); after a power cycle time starts again at 0, so
 * every other client's pending wait, step or submit ends with RESET too.
 * A soft reset keeps time: the others' waits go on, on the reset chip.
 */
void rdcd_reset_pending(struct rdcd *d, struct rdcd_client *c, bool power)
{
	if (rdcd_chip_busy(d)) {
		rdcd_chip_abort(d);
		d->chip_client = NULL;
	}
	for (struct rdcd_client *o = d->clients; o; o = o->next)
		if (o->pend != RDCD_PEND_NONE && (o == c || power))
			rdcd_pending_end(d, o, RDC_E_RESET);
}
