// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The chip has one trace hook; rdcd has several listeners (the VCD
 * writer, the GPIO bridge).  This fans the hook out to them, and puts
 * itself back on every chip rdcd opens (a power cycle makes a new one).
 */
#include "rdcd.h"

static void rdcd_trace_fan(void *ctx, uint64_t time, unsigned int event,
			   uint32_t a, uint32_t b)
{
	struct rdcd *d = ctx;

	for (unsigned int i = 0; i < d->ntrace; i++)
		d->trace[i].fn(d->trace[i].ctx, time, event, a, b);
}

void rdcd_trace_attach(struct rdcd *d)
{
	if (d->hw)
		rdc_hw_set_trace(d->hw, d->ntrace ? rdcd_trace_fan : NULL, d);
}

int rdcd_trace_add(struct rdcd *d, rdc_trace_fn fn, void *ctx)
{
	if (d->ntrace == RDCD_MAX_TRACE)
		return RDC_E_NOMEM;
	d->trace[d->ntrace].fn = fn;
	d->trace[d->ntrace].ctx = ctx;
	d->ntrace++;
	rdcd_trace_attach(d);
	return 0;
}

void rdcd_trace_remove(struct rdcd *d, rdc_trace_fn fn, void *ctx)
{
	for (unsigned int i = 0; i < d->ntrace; i++) {
		if (d->trace[i].fn != fn || d->trace[i].ctx != ctx)
			continue;
		d->trace[i] = d->trace[--d->ntrace];
		break;
	}
	rdcd_trace_attach(d);
}
