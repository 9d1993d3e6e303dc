// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The pins API (rdc_pins_* in rdc.h) on top of the backend operations.
 *
 * A backend whose registers are the chip's needs nothing of its own to
 * read the pins or wait for an edge: PINS is a register, and an edge is
 * two levels in a row, which the backend's wait() can watch for on its
 * side of the transport.  Only driving the inputs needs an operation
 * (rdc_hw_set_pins, a protocol message, a GPIO line).
 */
#include <time.h>

#include "rdc_priv.h"

uint64_t rdc_pins_wall_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

int rdc_pins_get(rdc_dev *dev, uint32_t *levels)
{
	if (!dev || !levels)
		return RDC_E_INVAL;
	if (dev->be->pins_get)
		return dev->be->pins_get(dev, levels);
	return rdc_reg_read(dev, RDC_REG_PINS, levels);
}

/*
 * A chip reset (RESET_N changed) points the DP's surfaces back at the
 * scanout framebuffer, as rdc_reset does: what the submit-side tracking
 * believes (rdc_host_blit's row layout) follows.
 */
static int rdc_pins_track_reset(rdc_dev *dev)
{
	uint32_t fmt;
	int ret = rdc_reg_read(dev, RDC_REG_FB_FORMAT, &fmt);

	if (ret)
		return ret;
	dev->scan_left = 0;
	dev->scan_n = 0;
	dev->dst_format = fmt;
	dev->src_format = fmt;
	return 0;
}

int rdc_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	uint32_t before = 0, after = 0;
	int ret;

	if (!dev || (mask & ~RDC_PINS_IN))
		return RDC_E_INVAL;
	if (!dev->be->pins_set)
		return RDC_E_NOSYS;
	if (!mask)
		return 0;
	ret = rdc_pins_get(dev, &before);
	if (ret)
		return ret;
	ret = dev->be->pins_set(dev, mask, levels & mask);
	if (ret)
		return ret;
	after = (before & ~mask) | (levels & mask);
	if ((before ^ after) & RDC_PIN_RESET_N)
		return rdc_pins_track_reset(dev);
	return 0;
}

/*
 * Each turn waits until one watched pin differs from the level it had,
 * two terms at most (TE and IRQ: RDC_WAIT_TEST_TERMS), then looks at what
 * changed: an edge of an unwanted kind only moves the reference on.
 */
int rdc_pins_wait_regs(rdc_dev *dev, uint32_t pins, uint32_t edges,
		       uint64_t budget, struct rdc_pin_edge *ev)
{
	static const uint32_t order[] = { RDC_PIN_TE, RDC_PIN_IRQ };
	uint64_t start, now;
	uint32_t cur, next;
	int ret;

	_Static_assert(RDC_ARRAY_SIZE(order) <= RDC_WAIT_TEST_TERMS,
		       "one wait term per output pin");
	ret = rdc_sim_time(dev, &start);
	if (!ret)
		ret = rdc_pins_get(dev, &cur);
	if (ret)
		return ret;
	now = start;
	for (;;) {
		struct rdc_wait w = { .budget = budget - (now - start) };
		uint32_t changed, wanted = 0;
		unsigned int k = 0;

		for (unsigned int i = 0; i < RDC_ARRAY_SIZE(order); i++) {
			if (!(pins & order[i]))
				continue;
			w.term[k++] = (struct rdc_wait_term){
				.kind = RDC_WAIT_TEST_EQ,
				.reg = RDC_REG_PINS,
				.mask = order[i],
				.value = ~cur & order[i],
			};
		}
		ret = dev->be->wait(dev, &w);
		if (!ret)
			ret = rdc_pins_get(dev, &next);
		if (!ret)
			ret = rdc_sim_time(dev, &now);
		if (ret)
			return ret;
		changed = (next ^ cur) & pins;
		if (changed & next && edges & RDC_EDGE_RISING)
			wanted |= changed & next;
		if (changed & ~next && edges & RDC_EDGE_FALLING)
			wanted |= changed & ~next;
		cur = next;
		if (wanted) {
			ev->pins = wanted;
			ev->levels = next;
			ev->time = now;
			ev->wall_ns = rdc_pins_wall_ns();
			return 0;
		}
		if (now - start >= budget)
			return RDC_E_TIMEOUT;
	}
}

/* Core cycles in timeout_us microseconds (0: the default budget). */
static int rdc_pins_budget(rdc_dev *dev, uint64_t timeout_us, uint64_t *budget)
{
	uint32_t hz;
	int ret;

	if (!timeout_us) {
		*budget = RDC_WAIT_BUDGET_DEFAULT;
		return 0;
	}
	ret = rdc_sim_core_hz(dev, &hz);
	if (ret)
		return ret;
	/* a day is far past any daemon's cap: no overflow below */
	if (timeout_us > 86400ull * 1000000u)
		return RDC_E_RANGE;
	*budget = timeout_us * hz / 1000000u;
	if (!*budget)
		*budget = 1;
	return 0;
}

int rdc_pins_wait_edge_sized(rdc_dev *dev, uint32_t pins, uint32_t edges,
			     uint64_t timeout_us, struct rdc_pin_edge *out)
{
	struct rdc_pin_edge ev = { 0 };
	uint64_t budget = 0;
	int ret;

	if (!dev || !out || !pins || (pins & ~RDC_PINS_OUT) ||
	    !(edges & RDC_EDGE_BOTH) ||
	    (edges & ~(RDC_EDGE_BOTH | RDC_EDGE_QUEUED)))
		return RDC_E_INVAL;
	ret = rdc_pins_budget(dev, timeout_us, &budget);
	if (ret)
		return ret;
	if (dev->be->pins_wait)
		ret = dev->be->pins_wait(dev, pins, edges, budget, timeout_us,
					 &ev);
	else
		ret = rdc_pins_wait_regs(dev, pins, edges, budget, &ev);
	rdc_struct_out(out, &ev, sizeof(ev));
	return ret;
}

int rdc_pins_present_sized(rdc_dev *dev, rdc_batch *b, uint64_t timeout_us,
			   struct rdc_pin_edge *ev)
{
	struct rdc_pin_edge e;
	int ret;

	if (!dev || !b)
		return RDC_E_INVAL;
	ret = rdc_pins_wait_edge(dev, RDC_PIN_TE, RDC_EDGE_RISING, timeout_us,
				 &e);
	if (ret)
		return ret;
	if (ev)
		rdc_struct_out(ev, &e, sizeof(e));
	return rdc_batch_submit(dev, b);
}
