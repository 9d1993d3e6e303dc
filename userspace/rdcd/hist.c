// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd: the pixel history (HIST_*, docs/history.md) one client keeps on
 * the chip.
 */
#include <string.h>

#include "serve.h"

/* A page of the client's history: entries [first, first + n). */
static void rdcd_hist_read(struct rdcd *d, struct rdcd_client *c,
			   const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	uint64_t first = rdc_proto_get64(pl), count;
	uint32_t max = rdc_proto_get32(pl + 8);
	struct rdc_proto_hist_page pg = { 0 };
	uint8_t *out;

	/* the client's buffer and the page bound, as VRAM_READ's length */
	if (max > RDC_PROTO_HIST_PAGE) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	count = rdc_history_count(d->hist);
	if (first > count) {
		rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
		return;
	}
	pg.count = count;
	pg.dropped = rdc_history_dropped(d->hist);
	pg.n = (uint32_t)RDC_MIN((uint64_t)max, count - first);
	out = rdcd_reply(d, c, h, RDC_ST_OK, NULL,
			 RDC_PROTO_HIST_PAGE_HDR +
				 (size_t)pg.n * RDC_PROTO_HIST_ENTRY_SIZE);
	if (!out)
		return;
	for (uint32_t i = 0; i < pg.n; i++) {
		struct rdc_history_entry e;
		struct rdc_proto_hist_entry pe;

		if (rdc_history_get(d->hist, first + i, &e)) {
			pg.n = i; /* cannot happen: counted above */
			break;
		}
		pe = (struct rdc_proto_hist_entry){
			.x = e.x,
			.y = e.y,
			.format = e.format,
			.before = e.before,
			.after = e.after,
			.cycle = e.cycle,
			.frame = e.frame,
			.fetched = e.fetched,
			.opcode = e.opcode,
			.cmd_index = e.cmd_index,
			.source = e.source,
			.line = e.line,
			.cmd_addr = e.cmd_addr,
			.depth = e.depth,
			.rop = e.rop,
			.alpha = e.alpha,
			.colorkey = e.colorkey,
			.colorkey_on = e.colorkey_on,
			.pattern = e.pattern,
			.fg = e.fg,
			.bg = e.bg,
		};
		memcpy(pe.calls, e.calls, sizeof(pe.calls));
		rdc_proto_hist_entry_encode(
			out + RDC_PROTO_HIST_PAGE_HDR +
				(size_t)i * RDC_PROTO_HIST_ENTRY_SIZE,
			&pe);
	}
	rdc_proto_hist_page_encode(out, &pg);
}

/*
 * HIST_*: one history on the chip at a time, the client's that opened it
 * (BUSY for anyone else), closed by HIST_END or when that client goes.
 */
void rdcd_hist(struct rdcd *d, struct rdcd_client *c,
	       const struct rdc_proto_hdr *h, const uint8_t *pl)
{
	struct rdc_proto_hist_open o;
	uint32_t what, value;
	int ret;

	if (h->type != RDC_MSG_HIST_OPEN && d->hist_client != c) {
		rdcd_log(d, RDCD_LOG_INFO, "client %u: no pixel history open",
			 c->id);
		rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
		return;
	}
	switch (h->type) {
	case RDC_MSG_HIST_OPEN:
		rdc_proto_hist_open_decode(pl, h->len, &o);
		if (d->hist) {
			rdcd_log(d, RDCD_LOG_INFO,
				 "client %u: client %u keeps the pixel history",
				 c->id, d->hist_client->id);
			rdcd_reply(d, c, h, RDC_ST_BUSY, NULL, 0);
			break;
		}
		if (o.flags & RDC_HISTORY_WRITES) {
			/* a write log of millions of accesses: not kept here */
			rdcd_reply(d, c, h, RDC_ST_NOSYS, NULL, 0);
			break;
		}
		if (o.flags || !o.w || !o.h) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		}
		ret = rdc_history_open(d->dev, o.x, o.y, o.w, o.h, 0, &d->hist);
		if (!ret)
			ret = rdc_history_set_limit(d->hist,
						    RDC_PROTO_HIST_LIMIT_MAX);
		if (ret) {
			rdc_history_close(d->hist);
			d->hist = NULL;
			rdcd_reply_err(d, c, h, ret);
			break;
		}
		d->hist_client = c;
		rdcd_log(d, RDCD_LOG_INFO,
			 "client %u: pixel history of %u,%u %ux%u", c->id, o.x,
			 o.y, o.w, o.h);
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	case RDC_MSG_HIST_READ:
		rdcd_hist_read(d, c, h, pl);
		break;
	case RDC_MSG_HIST_SET:
		what = rdc_proto_get32(pl);
		value = rdc_proto_get32(pl + 4);
		if (what == RDC_HIST_SET_LINE) {
			rdc_history_set_line(d->hist, value);
		} else if (what != RDC_HIST_SET_LIMIT || !value) {
			rdcd_reply(d, c, h, RDC_ST_INVAL, NULL, 0);
			break;
		} else if (value > RDC_PROTO_HIST_LIMIT_MAX) {
			rdcd_reply(d, c, h, RDC_ST_RANGE, NULL, 0);
			break;
		} else {
			rdc_history_set_limit(d->hist, value);
		}
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	default: /* RDC_MSG_HIST_END */
		rdc_history_close(d->hist);
		d->hist = NULL;
		d->hist_client = NULL;
		rdcd_reply(d, c, h, RDC_ST_OK, NULL, 0);
		break;
	}
}
