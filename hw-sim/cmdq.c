// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Command queues: the FIFO register port, the ring buffer in VRAM, and the
 * readback FIFO the DP fills for the host.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "hw_priv.h"

#define WORD_BYTES     4u
#define RING_MIN_BYTES 16u

void rdc_cmdq_reset(struct rdc_hw *hw)
{
	hw->fifo_head = 0;
	if (hw->fifo_count) {
		hw->fifo_count = 0;
		rdc_fifo_traced(hw);
	}
	hw->fifo_lowwater = RDC_FIFO_LOWWATER_RESET;
	hw->rdata_head = 0;
	hw->rdata_count = 0;
	hw->ring_base = 0;
	hw->ring_size = 0;
	hw->ring_head = 0;
	hw->ring_tail = 0;
	hw->ring_err = 0;
	hw->fence = 0;
}

void rdc_fifo_push(struct rdc_hw *hw, uint32_t word)
{
	if (hw->fifo_count >= RDC_FIFO_DEPTH) {
		rdc_port_error(hw, RDC_ERR_FIFO_OVERFLOW, RDC_REG_FIFO_DATA);
		return;
	}
	hw->fifo[(hw->fifo_head + hw->fifo_count) % RDC_FIFO_DEPTH] = word;
	hw->fifo_count++;
	rdc_fifo_traced(hw);
}

uint32_t rdc_hw_fifo_push(struct rdc_hw *hw, const uint32_t *words, uint32_t n)
{
	uint32_t i, tail;

	if (hw->in_reset)
		return n;
	n = RDC_MIN(n, RDC_FIFO_DEPTH - hw->fifo_count);
	if (hw->trace_fn) {
		for (i = 0; i < n; i++)
			rdc_hw_write(hw, RDC_REG_FIFO_DATA, words[i]);
		return n;
	}
	if (rdc_crtc_due(hw, hw->now))
		rdc_crtc_catch_up(hw, hw->now);
	/* copy into the ring in at most two pieces */
	tail = (hw->fifo_head + hw->fifo_count) % RDC_FIFO_DEPTH;
	i = RDC_MIN(n, RDC_FIFO_DEPTH - tail);
	rdc_memcpy(hw->fifo + tail, words, i * sizeof(*words));
	if (i < n)
		rdc_memcpy(hw->fifo, words + i, (n - i) * sizeof(*words));
	hw->fifo_count += n;
	return n;
}

uint32_t rdc_rdata_pop(struct rdc_hw *hw)
{
	uint32_t w;

	if (!hw->rdata_count)
		return 0;
	w = hw->rdata[hw->rdata_head];
	hw->rdata_head = (hw->rdata_head + 1) % RDC_RDATA_DEPTH;
	hw->rdata_count--;
	return w;
}

static bool ring_ok(const struct rdc_hw *hw)
{
	return hw->ring_base % WORD_BYTES == 0 &&
	       hw->ring_size % WORD_BYTES == 0 &&
	       hw->ring_size >= RING_MIN_BYTES &&
	       (uint64_t)hw->ring_base + hw->ring_size <= hw->vram_size &&
	       hw->ring_head < hw->ring_size &&
	       hw->ring_head % WORD_BYTES == 0 &&
	       hw->ring_tail < hw->ring_size && hw->ring_tail % WORD_BYTES == 0;
}

/*
 * Called when the ring is enabled or reprogrammed while enabled: bad
 * programming stops the ring (no words) until a valid reprogramming.
 */
void rdc_ring_validate(struct rdc_hw *hw, uint32_t reg)
{
	if (!(hw->control & RDC_CONTROL_RING_EN)) {
		hw->ring_err = 0;
		return;
	}
	hw->ring_err = !ring_ok(hw);
	if (hw->ring_err)
		rdc_port_error(hw, RDC_ERR_RING, reg);
}

uint32_t rdc_ring_words(const struct rdc_hw *hw)
{
	if (!(hw->control & RDC_CONTROL_RING_EN) || hw->ring_err ||
	    !ring_ok(hw))
		return 0;
	return (hw->ring_tail + hw->ring_size - hw->ring_head) % hw->ring_size /
	       WORD_BYTES;
}

uint32_t rdc_port_cmd_avail(struct rdc_hw *hw, unsigned int src)
{
	if (src == RDC_SRC_FIFO)
		return hw->fifo_count;
	if (src == RDC_SRC_RING)
		return rdc_ring_words(hw);
	return 0;
}

/* Commands are a few words: those by hand, not by a library call. */
static inline void words_copy(uint32_t *d, const uint32_t *s, uint32_t n)
{
	if (n >= 32) {
		rdc_memcpy(d, s, n * sizeof(*d));
		return;
	}
	if (n & 16) {
		rdc_memcpy(d, s, 16 * sizeof(*d));
		d += 16;
		s += 16;
	}
	if (n & 8) {
		rdc_memcpy(d, s, 8 * sizeof(*d));
		d += 8;
		s += 8;
	}
	if (n & 4) {
		rdc_memcpy(d, s, 4 * sizeof(*d));
		d += 4;
		s += 4;
	}
	if (n & 2) {
		rdc_memcpy(d, s, 2 * sizeof(*d));
		d += 2;
		s += 2;
	}
	if (n & 1)
		*d = *s;
}

/*
 * Take n words, 1 <= n <= fifo_count, whose fetch is charged.  Inline:
 * a whole command's pop is one for every command the DP runs.
 */
static rdc_always_inline uint32_t fifo_take(struct rdc_hw *hw, uint32_t *dst,
					    uint32_t n)
{
	uint32_t before = hw->fifo_count, i, h;

	/*
	 * The first word (a command's header) alone, so that the copy's
	 * wide stores start at the arguments: the DP reads two of them as
	 * one 8-byte load (a glyph's colours), which a store holding both
	 * serves at once, where two stores it straddles stall it until they
	 * retire.  Then the ring holds the rest in at most two pieces.
	 */
	dst[0] = hw->fifo[hw->fifo_head];
	h = (hw->fifo_head + 1) % RDC_FIFO_DEPTH;
	i = RDC_MIN(n - 1, RDC_FIFO_DEPTH - h);
	words_copy(dst + 1, hw->fifo + h, i);
	if (i < n - 1)
		words_copy(dst + 1 + i, hw->fifo, n - 1 - i);
	hw->fifo_head = (hw->fifo_head + n) % RDC_FIFO_DEPTH;
	hw->fifo_count -= n;
	rdc_fifo_traced(hw);
	if (before > hw->fifo_lowwater && hw->fifo_count <= hw->fifo_lowwater)
		rdc_port_irq(hw, RDC_IRQ_FIFO_LOW);
	return n;
}

static uint32_t fifo_pop(struct rdc_hw *hw, uint32_t *dst, uint32_t n)
{
	n = RDC_MIN(n, hw->fifo_count);
	if (!n)
		return 0;
	rdc_dp_active(hw, 1);
	rdc_hw_idle_to(hw, hw->now + n * RDC_T_FIFO_WORD);
	return fifo_take(hw, dst, n);
}

static uint32_t ring_pop(struct rdc_hw *hw, uint32_t *dst, uint32_t n)
{
	uint32_t got = 0;

	n = RDC_MIN(n, rdc_ring_words(hw));
	if (n)
		rdc_dp_active(hw, 1);
	while (got < n) {
		uint32_t words = RDC_MIN(
			n - got, (hw->ring_size - hw->ring_head) / WORD_BYTES);
		uint32_t addr = hw->ring_base + hw->ring_head, i;

		rdc_bus_charge(hw, addr, words * WORD_BYTES, RDC_BUS_READ);
		for (i = 0; i < words; i++)
			dst[got + i] =
				rdc_ld32(hw->vram + addr + i * WORD_BYTES);
		got += words;
		hw->ring_head =
			(hw->ring_head + words * WORD_BYTES) % hw->ring_size;
	}
	return got;
}

uint32_t rdc_port_cmd_pop_whole(struct rdc_hw *hw, uint32_t *dst,
				uint32_t max_args)
{
	uint32_t n, before = hw->fifo_count;

	if (!before || hw->trace_fn)
		return 0;
	n = 1 + RDC_CMD_LEN(hw->fifo[hw->fifo_head]);
	/*
	 * Popped apart, the header's pop could cross the low-water mark (an
	 * IRQ n - 1 words earlier) or let scanout events in (a frame
	 * listener reading FIFO_COUNT between the pops).
	 */
	if (n - 1 > max_args || n > before ||
	    (before > hw->fifo_lowwater && before - 1 <= hw->fifo_lowwater) ||
	    rdc_crtc_due(hw, hw->now + n * RDC_T_FIFO_WORD))
		return 0;
	/*
	 * fifo_pop's tests again would find what these did: words waiting,
	 * and no scanout event before the fetch ends.
	 */
	rdc_dp_active(hw, 1);
	hw->now += n * RDC_T_FIFO_WORD;
	return fifo_take(hw, dst, n);
}

uint32_t rdc_port_cmd_pop(struct rdc_hw *hw, unsigned int src, uint32_t *dst,
			  uint32_t n)
{
	if (src == RDC_SRC_FIFO)
		return fifo_pop(hw, dst, n);
	if (src == RDC_SRC_RING)
		return ring_pop(hw, dst, n);
	return 0;
}

uint32_t rdc_port_rdata_space(struct rdc_hw *hw)
{
	return RDC_RDATA_DEPTH - hw->rdata_count;
}

uint32_t rdc_port_rdata_push(struct rdc_hw *hw, const uint32_t *w, uint32_t n)
{
	uint32_t i;

	n = RDC_MIN(n, RDC_RDATA_DEPTH - hw->rdata_count);
	for (i = 0; i < n; i++) {
		hw->rdata[(hw->rdata_head + hw->rdata_count) % RDC_RDATA_DEPTH] =
			w[i];
		hw->rdata_count++;
	}
	return n;
}
