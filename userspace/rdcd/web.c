// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd's side of the web sink (--web): the token rule of tcp: carried to
 * the page, its address in the log, and the device's state beside the
 * picture.  The state is read between runs of the chip, with calls that
 * leave no trace (no register read a --record or --vcd would see): the
 * time, the pin levels, and the IRQ status the loop reads anyway.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rdcd.h"

int rdcd_web_token(char **spec, const char *token_path)
{
	char *n;

	if (strncmp(*spec, "web:", 4) || !token_path ||
	    strstr(*spec, ",token="))
		return 0;
	if (asprintf(&n, "%s,token=%s", *spec, token_path) < 0)
		return RDC_E_NOMEM;
	free(*spec);
	*spec = n;
	return 0;
}

void rdcd_web_log(const struct rdcd *d, const rdc_sink *s)
{
	char url[128];

	if (!rdc_sink_url(s, url, sizeof(url)))
		rdcd_log(d, RDCD_LOG_INFO, "web page at %s%s", url,
			 d->have_token ? "#token=..." : "");
}

void rdcd_web_status(struct rdcd *d)
{
	struct rdc_sink_status st = { 0 };
	bool any = false;

	for (unsigned int i = 0; i < d->nsinks; i++)
		any |= !strcmp(rdc_sink_kind(d->sinks[i]), "web");
	if (!any || !d->hw)
		return;
	st.have = RDC_SINK_HAVE_TIME | RDC_SINK_HAVE_PINS | RDC_SINK_HAVE_IRQ;
	st.time = rdc_hw_now(d->hw);
	st.core_hz = RDC_DEFAULT_CORE_HZ;
	st.pins = rdc_hw_pins(d->hw);
	st.irq_status = d->last_irq;
	for (unsigned int i = 0; i < d->nsinks; i++)
		rdc_sink_status_set(d->sinks[i], &st);
}
