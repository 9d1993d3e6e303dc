// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Trace replay (rdc_replay_file, rdc_replay_history): the records of a
 * trace that record.c wrote (its layout: record.c and record.h) run in
 * order on a fresh sim: chip, each operation's result, and in a timed
 * trace its time, compared with the trace's (mismatches counted), and the
 * frames the chip scans out counted and checksummed.  A record that asks
 * for more than record_limits.h allows is refused.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "rdc_priv.h"
#include "rdc_proto.h"
#include "record.h"
#include "record_limits.h"

struct replay {
	FILE *f;
	const char *path;
	struct rdc_replay_result *res;
	rdc_dev *dev;
	uint32_t version;
	uint32_t vram;
	bool untimed; /* REC_F_UNTIMED: times are not compared */
	uint8_t *buf;
	uint32_t *words; /* a SUBMIT record's, REC_SUBMIT_MAX */
	uint64_t off;	 /* bytes read */
	bool cut;	 /* the file ended inside a record */
	uint64_t at;	 /* where the record replaying began */
	uint32_t powers; /* POWER records so far */
	/* rdc_replay_history: the history to keep across power cycles */
	const uint32_t *watch; /* x, y, w, h, flags; NULL: none */
	rdc_history *hist;
};

/* n bytes, or RDC_E_PARSE with p->cut set when the file ends first. */
static int rp_get(struct replay *p, void *b, size_t n)
{
	size_t got = fread(b, 1, n, p->f);

	p->off += got;
	if (got == n)
		return 0;
	p->cut = !ferror(p->f);
	return RDC_E_PARSE;
}

/* A trace that is not one, or is damaged: say where. */
static int rp_bad(struct replay *p, const char *why, uint64_t at)
{
	return rdc_err_detail(RDC_E_PARSE, "%s: %s at byte %" PRIu64, p->path,
			      why, at);
}

/* A record that asks for more than a replay gives one: say which. */
static int rp_too_much(struct replay *p, const char *op, const char *what,
		       uint64_t asked, uint64_t max)
{
	return rdc_err_detail(RDC_E_RANGE,
			      "%s: record %" PRIu64 " (%s at byte %" PRIu64
			      "): %s %" PRIu64 ", more than a replay allows "
			      "(%" PRIu64 ")",
			      p->path, p->res->records + 1, op, p->at, what,
			      asked, max);
}

static void rp_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t n)
{
	struct rdc_replay_result *res = ctx;
	uint8_t le[4];

	(void)n;
	res->frames++;
	res->width = w;
	res->height = h;
	res->frame_crc = rdc_crc32_xrgb(xrgb, (size_t)w * h);
	rdc_st32(le, res->frame_crc);
	res->frames_crc = (uint32_t)crc32(res->frames_crc, le, sizeof(le));
}

static int rp_open(struct replay *p)
{
	char uri[48];
	int ret;

	rdc_close(p->dev);
	p->dev = NULL;
	snprintf(uri, sizeof(uri), "sim:vram=%u", p->vram);
	ret = rdc_open(uri, &p->dev);
	if (ret)
		return ret == RDC_E_URI ? RDC_E_PARSE : ret;
	rdc_hw_set_frame_fn(rdc_sim_hw(p->dev), rp_frame, p->res);
	if (p->hist)
		return rdc_history_attach(p->hist, p->dev);
	if (p->watch)
		return rdc_history_open(p->dev, p->watch[0], p->watch[1],
					p->watch[2], p->watch[3], p->watch[4],
					&p->hist);
	return 0;
}

static int rp_one(struct replay *p, uint8_t op, uint64_t t)
{
	const struct rdc_backend *be = p->dev->be;
	struct rdc_hw *hw = rdc_sim_hw(p->dev);
	uint8_t b[RDC_PROTO_WAIT_SIZE + 4];
	uint32_t v;
	int ret;

	if (op != REC_POWER && !p->untimed && rdc_hw_now(hw) != t)
		p->res->mismatches++;
	switch (op) {
	case REC_REG_WRITE:
		if (rp_get(p, b, 8))
			return RDC_E_PARSE;
		return be->reg_write(p->dev, rdc_proto_get32(b),
				     rdc_proto_get32(b + 4)) < 0 ?
			       RDC_E_PARSE :
			       0;
	case REC_REG_READ:
		if (rp_get(p, b, 8))
			return RDC_E_PARSE;
		if (be->reg_read(p->dev, rdc_proto_get32(b), &v) ||
		    v != rdc_proto_get32(b + 4))
			p->res->mismatches++;
		return 0;
	case REC_VRAM_WRITE: {
		uint32_t addr, len;

		if (rp_get(p, b, 8))
			return RDC_E_PARSE;
		addr = rdc_proto_get32(b);
		len = rdc_proto_get32(b + 4);
		if (len > p->vram)
			return RDC_E_PARSE;
		if (rp_get(p, p->buf, len))
			return RDC_E_PARSE;
		return be->vram_write(p->dev, addr, p->buf, len) ? RDC_E_PARSE :
								   0;
	}
	case REC_WAIT: {
		struct rdc_proto_wait pw;
		struct rdc_wait w = { 0 };

		if (rp_get(p, b, sizeof(b)) ||
		    rdc_proto_wait_decode(b, RDC_PROTO_WAIT_SIZE, &pw))
			return RDC_E_PARSE;
		if (pw.budget > REC_MAX_CYCLES)
			return rp_too_much(p, "WAIT", "budget", pw.budget,
					   REC_MAX_CYCLES);
		w.budget = pw.budget;
		w.needs_dp = pw.needs_dp;
		for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
			if (pw.term[i].kind > RDC_WAIT_TEST_EQ)
				return RDC_E_PARSE;
			w.term[i].kind = (enum rdc_wait_test)pw.term[i].kind;
			w.term[i].reg = pw.term[i].reg;
			w.term[i].mask = pw.term[i].mask;
			w.term[i].value = pw.term[i].value;
		}
		ret = be->wait(p->dev, &w);
		if (ret != (int)rdc_proto_get32(b + RDC_PROTO_WAIT_SIZE))
			p->res->mismatches++;
		return 0;
	}
	case REC_STEP:
		if (rp_get(p, b, 8))
			return RDC_E_PARSE;
		if (rdc_proto_get64(b) > REC_MAX_CYCLES)
			return rp_too_much(p, "STEP", "cycles",
					   rdc_proto_get64(b), REC_MAX_CYCLES);
		if (be->step(p->dev, rdc_proto_get64(b)))
			p->res->mismatches++;
		return 0;
	case REC_POWER:
		if (++p->powers > REC_MAX_POWER)
			return rp_too_much(p, "POWER", "power cycle", p->powers,
					   REC_MAX_POWER);
		return rp_open(p);
	case REC_SUBMIT: {
		uint32_t n;

		if (p->version < REC_VERSION_FLAGS || rp_get(p, b, 4))
			return RDC_E_PARSE;
		n = rdc_proto_get32(b);
		if (!n || n > REC_SUBMIT_MAX)
			return RDC_E_PARSE;
		for (uint32_t i = 0; i < n; i++) {
			if (rp_get(p, b, 4))
				return RDC_E_PARSE;
			p->words[i] = rdc_proto_get32(b);
		}
		if (rp_get(p, b, 4))
			return RDC_E_PARSE;
		/* as on sim: the core's FIFO loop, with its waits */
		ret = rdc_submit(p->dev, p->words, n);
		if (ret != (int)rdc_proto_get32(b))
			p->res->mismatches++;
		return 0;
	}
	case REC_PINS: {
		uint32_t mask;

		if (p->version < 2 || rp_get(p, b, 8))
			return RDC_E_PARSE;
		mask = rdc_proto_get32(b);
		if (!mask || (mask & ~RDC_PINS_IN))
			return RDC_E_PARSE;
		if (be->pins_set(p->dev, mask, rdc_proto_get32(b + 4) & mask))
			p->res->mismatches++;
		return 0;
	}
	default:
		return RDC_E_PARSE;
	}
}

static int replay_file(const char *path, struct rdc_replay_result *res,
		       rdc_dev **dev_out, const uint32_t *watch,
		       rdc_history **hist)
{
	struct rdc_replay_result dummy;
	struct replay p = { .watch = watch };
	uint8_t hdr[REC_MAGIC_LEN + 8], rec[9], fl[4];
	int ret;

	if (!path)
		return RDC_E_INVAL;
	if (dev_out)
		*dev_out = NULL;
	p.res = res ? res : &dummy;
	memset(p.res, 0, sizeof(*p.res));
	rdc_err_detail_clear();
	p.path = path;
	p.f = fopen(path, "rb");
	if (!p.f)
		return rdc_err_detail(RDC_E_FILE, "%s: %s", path,
				      strerror(errno));
	ret = rp_get(&p, hdr, sizeof(hdr));
	p.version = ret ? 0 : rdc_proto_get32(hdr + REC_MAGIC_LEN);
	if (ret || memcmp(hdr, REC_MAGIC, REC_MAGIC_LEN))
		ret = rp_bad(&p, "not an rdcd trace (no RDCTRACE header)", 0);
	else if (p.version < REC_VERSION_MIN || p.version > REC_VERSION_MAX)
		ret = rdc_err_detail(RDC_E_PARSE,
				     "%s: trace version %u (this build reads "
				     "%u to %u)",
				     path, p.version, REC_VERSION_MIN,
				     REC_VERSION_MAX);
	if (!ret && p.version >= REC_VERSION_FLAGS) {
		if (rp_get(&p, fl, sizeof(fl)))
			ret = rp_bad(&p, "no flags in the header", p.off);
		else if (rdc_proto_get32(fl) & ~REC_F_KNOWN)
			ret = rp_bad(&p, "unknown header flags",
				     REC_MAGIC_LEN + 8);
		else
			p.untimed = rdc_proto_get32(fl) & REC_F_UNTIMED;
		p.res->untimed = p.untimed;
	}
	if (!ret) {
		p.vram = rdc_proto_get32(hdr + REC_MAGIC_LEN + 4);
		p.buf = p.vram <= REC_MAX_VRAM_WRITE ? malloc(p.vram + 1) :
						       NULL;
		p.words = p.version >= REC_VERSION_FLAGS ?
				  malloc(REC_SUBMIT_MAX * sizeof(*p.words)) :
				  NULL;
		if (p.version >= REC_VERSION_FLAGS && !p.words)
			ret = RDC_E_NOMEM;
		else
			ret = p.buf ? rp_open(&p) :
				      rp_bad(&p, "VRAM size out of range",
					     REC_MAGIC_LEN + 4);
	}
	while (!ret) {
		uint64_t t, at = p.off;

		ret = rp_get(&p, rec, sizeof(rec));
		/* Cut short (no END record): the recorder is still running,
		 * or was killed.  What is complete has been replayed; an
		 * unknown op in the last bytes is damage all the same. */
		if (ret && p.cut &&
		    (p.off == at ||
		     (rec[0] >= REC_REG_WRITE && rec[0] <= REC_SUBMIT))) {
			p.res->truncated = 1;
			ret = 0;
			break;
		}
		if (ret) {
			ret = p.cut ? rp_bad(&p, "unknown record type", at) :
				      rdc_err_detail(RDC_E_FILE, "%s: %s", path,
						     strerror(errno));
			break;
		}
		t = rdc_proto_get64(rec + 1);
		p.at = at;
		if (rec[0] == REC_END) {
			struct rdc_hw *hw = rdc_sim_hw(p.dev);

			/* untimed: the replay ends where its operations do */
			if (p.untimed)
				break;
			if (rdc_hw_now(hw) < t &&
			    t - rdc_hw_now(hw) > REC_MAX_CYCLES) {
				ret = rp_too_much(&p, "END",
						  "cycles to its time",
						  t - rdc_hw_now(hw),
						  REC_MAX_CYCLES);
				break;
			}
			if (rdc_hw_now(hw) < t)
				rdc_hw_run_until(hw, t);
			if (rdc_hw_now(hw) != t)
				p.res->mismatches++;
			break;
		}
		/* pixel history: the record that is replaying (1-based) */
		p.dev->src_line = (uint32_t)RDC_MIN(p.res->records + 1,
						    (uint64_t)UINT32_MAX);
		ret = rp_one(&p, rec[0], t);
		if (ret && p.cut) {
			/* the last record is incomplete: not replayed */
			p.res->truncated = 1;
			ret = 0;
			break;
		}
		if (ret == RDC_E_PARSE && !*rdc_last_error_detail(RDC_E_PARSE))
			rp_bad(&p, "bad record", at);
		p.res->records++;
	}
	if (p.dev)
		p.res->time = rdc_hw_now(rdc_sim_hw(p.dev));
	fclose(p.f);
	free(p.buf);
	free(p.words);
	if (p.dev)
		rdc_hw_set_frame_fn(rdc_sim_hw(p.dev), NULL, NULL);
	if (!ret && dev_out)
		*dev_out = p.dev;
	else
		rdc_close(p.dev);
	if (!ret && hist)
		*hist = p.hist;
	else
		rdc_history_close(p.hist);
	return ret;
}

/* The caller's result may be of another release (rdc.h). */
int rdc_replay_file_sized(const char *path, struct rdc_replay_result *res,
			  rdc_dev **dev_out)
{
	struct rdc_replay_result full;
	int ret = replay_file(path, &full, dev_out, NULL, NULL);

	if (res)
		rdc_struct_out(res, &full, sizeof(full));
	return ret;
}

int rdc_replay_history_sized(const char *path, uint32_t x, uint32_t y,
			     uint32_t w, uint32_t h, uint32_t flags,
			     rdc_history **hist, struct rdc_replay_result *res,
			     rdc_dev **dev_out)
{
	struct rdc_replay_result full;
	const uint32_t watch[5] = { x, y, w, h, flags };
	int ret;

	if (!hist)
		return RDC_E_INVAL;
	*hist = NULL;
	ret = replay_file(path, &full, dev_out, watch, hist);
	if (res)
		rdc_struct_out(res, &full, sizeof(full));
	return ret;
}
