/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * The VCD writer's side for programs that own a chip themselves (rdcd):
 * they put rdc_vcd_trace on the chip's trace hook, or fan it out to it,
 * instead of letting rdc_vcd_open (rdc.h) take the hook of a sim: handle.
 * docs/vcd.md describes the file.
 */
#ifndef RDC_VCD_H
#define RDC_VCD_H

#include "hw.h"
#include "rdc.h"

/*
 * Start a dump at `path` (created or truncated) of the chip *hw points to.
 * *hw is read again at every event: a program that replaces its chip (a
 * power cycle) keeps one file, whose time goes on from where the old chip
 * stopped, and the new chip's levels are written at that time.  Returns 0
 * and *out, RDC_E_INVAL, RDC_E_NOMEM or RDC_E_FILE.  Nothing is hooked:
 * the caller routes the chip's trace events to rdc_vcd_trace(*out, ...)
 * and closes with rdc_vcd_close after unhooking it.
 */
int rdc_vcd_new(const char *path, struct rdc_hw *const *hw, rdc_vcd **out);

/* An rdc_trace_fn: the signal events become value changes. */
void rdc_vcd_trace(void *vcd, uint64_t time, unsigned int event, uint32_t a,
		   uint32_t b);

#endif /* RDC_VCD_H */
