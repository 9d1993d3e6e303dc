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
	bool state;	 /* a STATE record was replayed */
	bool watching;	 /* the first chip's history is open (rp_watch) */
	bool start_only; /* rdc_replay_open: the STATE record, no more */
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

/* A STATE record that cannot be one: say which and why. */
static int rp_state_bad(struct replay *p, const char *why)
{
	return rdc_err_detail(RDC_E_PARSE,
			      "%s: record %" PRIu64 " (STATE at byte %" PRIu64
			      "): %s",
			      p->path, p->res->records + 1, p->at, why);
}

static bool rp_state_reg(uint32_t reg)
{
	for (size_t i = 0; i < REC_STATE_REGS; i++)
		if (rec_state_regs[i] == reg)
			return true;
	return false;
}

/* The core section of a STATE record (REC_STATE_CORE_LEN bytes at b). */
static void rp_state_core(const uint8_t *b, struct rdc_hw_resume *s)
{
	uint32_t fl = rdc_proto_get32(b + 80);

	s->now = rdc_proto_get64(b);
	s->frame_start = rdc_proto_get64(b + 8);
	s->frame_count = rdc_proto_get64(b + 16);
	s->perf.busy = rdc_proto_get64(b + 24);
	s->perf.stall = rdc_proto_get64(b + 32);
	s->perf.pixels = rdc_proto_get64(b + 40);
	s->perf.cmds = rdc_proto_get32(b + 48);
	s->perf.last_cycles = rdc_proto_get32(b + 52);
	s->perf.last_opcode = rdc_proto_get32(b + 56);
	s->fence = rdc_proto_get32(b + 60);
	s->irq_status = rdc_proto_get32(b + 64);
	s->err_code = rdc_proto_get32(b + 68);
	s->err_info = rdc_proto_get32(b + 72);
	s->open_row = rdc_proto_get32(b + 76);
	s->scanning = fl & REC_STATE_SCANNING;
	s->dp_active = fl & REC_STATE_DP_ACTIVE;
	s->gamma = fl & REC_STATE_GAMMA;
	for (size_t i = 0; i < REC_STATE_INFORCE; i++)
		*rec_state_inforce(s, i) = rdc_proto_get32(b + 84 + 4 * i);
	s->perf.culled = rdc_proto_get32(b + 152);
}

/*
 * What a latched register had in force at the start (`s`, its core
 * section, while scanning) in *v, in place of the value read back;
 * false for a register whose value read back is in force.
 */
static bool rp_state_inforce(struct rdc_hw_resume *s, uint32_t reg, uint32_t *v)
{
	if (!s->scanning)
		return false;
	if (reg == RDC_REG_CONTROL) {
		*v = (*v & ~RDC_CONTROL_GAMMA_EN) |
		     (s->gamma ? RDC_CONTROL_GAMMA_EN : 0);
		return true;
	}
	for (size_t i = 0; i < REC_STATE_INFORCE; i++) {
		if (rec_state_latched[i] == reg) {
			*v = *rec_state_inforce(s, i);
			return true;
		}
	}
	return false;
}

/*
 * STATE (record.c): the fresh chip becomes the one the recording started
 * on.  VRAM and the CLUT first, then the registers in their order, then
 * the core's run (rdc_hw_resume), which restarts the frame where the
 * recorded one started and latches what was written.  Only as the first
 * record, once; every size is checked before it is used.
 */
static int rp_state(struct replay *p)
{
	const struct rdc_backend *be = p->dev->be;
	struct rdc_hw_resume hs = { 0 };
	uint8_t b[REC_STATE_CORE_LEN];
	uint32_t what, n, regs[REC_STATE_REGS][2], zl;
	uint8_t *z;
	uLongf got;
	int ret = 0;

	if (p->version < REC_VERSION_STATE)
		return rp_state_bad(p, "a STATE record in a trace of version 3 "
				       "or before");
	if (p->state || p->res->records)
		return rp_state_bad(p, "not the first record");
	if (rp_get(p, b, 4))
		return RDC_E_PARSE;
	what = rdc_proto_get32(b);
	if (what & ~REC_STATE_KNOWN)
		return rp_state_bad(p, "unknown sections");
	if (what & REC_STATE_CORE) {
		if (rp_get(p, b, REC_STATE_CORE_LEN))
			return RDC_E_PARSE;
		rp_state_core(b, &hs);
		if (rdc_proto_get32(b + 80) & ~REC_STATE_CORE_FLAGS_ALL)
			return rp_state_bad(p, "unknown core flags");
		if (hs.frame_start > hs.now)
			return rp_state_bad(p,
					    "its frame starts after its time");
		if (hs.now - hs.frame_start > REC_MAX_CYCLES)
			return rp_too_much(p, "STATE", "cycles into its frame",
					   hs.now - hs.frame_start,
					   REC_MAX_CYCLES);
	}
	if (rp_get(p, b, 4))
		return RDC_E_PARSE;
	n = rdc_proto_get32(b);
	if (n > REC_STATE_REGS)
		return rp_state_bad(p, "more registers than a STATE names");
	for (uint32_t i = 0; i < n; i++) {
		if (rp_get(p, b, 8))
			return RDC_E_PARSE;
		regs[i][0] = rdc_proto_get32(b);
		regs[i][1] = rdc_proto_get32(b + 4);
		if (!rp_state_reg(regs[i][0]))
			return rp_state_bad(p, "a register a STATE does not "
					       "restore");
	}
	if (rp_get(p, b, 4))
		return RDC_E_PARSE;
	if (rdc_proto_get32(b) != REC_STATE_CLUT)
		return rp_state_bad(p, "not 256 CLUT entries");
	ret = be->reg_write(p->dev, RDC_REG_CLUT_INDEX, 0);
	for (uint32_t i = 0; i < REC_STATE_CLUT && !ret; i++) {
		if (rp_get(p, b, 4))
			return RDC_E_PARSE;
		ret = be->reg_write(p->dev, RDC_REG_CLUT_DATA,
				    rdc_proto_get32(b));
	}
	if (ret || rp_get(p, b, 4))
		return RDC_E_PARSE;
	zl = rdc_proto_get32(b);
	if (zl > compressBound(p->vram) || zl > REC_STATE_MAX_Z)
		return rp_state_bad(p, "its VRAM is larger than zlib makes "
				       "the trace's VRAM size");
	z = malloc(zl ? zl : 1);
	if (!z)
		return RDC_E_NOMEM;
	if (rp_get(p, z, zl)) {
		free(z);
		return RDC_E_PARSE;
	}
	got = p->vram;
	if (uncompress(p->buf, &got, z, zl) != Z_OK || got != p->vram)
		ret = rp_state_bad(p, "its VRAM does not inflate to the "
				      "trace's VRAM size");
	free(z);
	if (!ret && be->vram_write(p->dev, 0, p->buf, p->vram))
		ret = RDC_E_PARSE;
	/* the latched registers as they were in force, for the latch */
	for (uint32_t i = 0; i < n && !ret; i++) {
		uint32_t v = regs[i][1];

		if (regs[i][0] == RDC_REG_CONTROL)
			v &= ~(RDC_CONTROL_SOFT_RESET | RDC_CONTROL_RESUME);
		regs[i][1] = v;
		if (what & REC_STATE_CORE)
			rp_state_inforce(&hs, regs[i][0], &v);
		ret = be->reg_write(p->dev, regs[i][0], v);
	}
	if (ret)
		return ret < 0 ? ret : RDC_E_PARSE;
	if (!(what & REC_STATE_CORE)) {
		p->state = true;
		return 0;
	}
	if (rdc_hw_resume(rdc_sim_hw(p->dev), &hs))
		return rp_state_bad(p, "the chip cannot start there");
	/* and what was written for the next vblank */
	for (uint32_t i = 0; i < n && !ret; i++) {
		uint32_t v = regs[i][1];

		if (rp_state_inforce(&hs, regs[i][0], &v) && v != regs[i][1])
			ret = be->reg_write(p->dev, regs[i][0], regs[i][1]);
	}
	if (ret)
		return ret < 0 ? ret : RDC_E_PARSE;
	p->state = true;
	return 0;
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

static int rp_watch(struct replay *p);

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
	/* the first chip's history starts after a STATE record (rp_watch) */
	if (!p->powers)
		return 0;
	return rp_watch(p);
}

/* The history to keep (rdc_replay_history), on the chip replaying. */
static int rp_watch(struct replay *p)
{
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

	if (op != REC_POWER && op != REC_STATE && !p->untimed &&
	    rdc_hw_now(hw) != t)
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
	case REC_STATE:
		return rp_state(p);
	default:
		return RDC_E_PARSE;
	}
}

static int replay_file(const char *path, struct rdc_replay_result *res,
		       rdc_dev **dev_out, const uint32_t *watch,
		       rdc_history **hist, bool start_only)
{
	struct rdc_replay_result dummy;
	struct replay p = { .watch = watch, .start_only = start_only };
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
		     (rec[0] >= REC_REG_WRITE && rec[0] <= REC_STATE))) {
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
		if (p.start_only && (rec[0] != REC_STATE || p.res->records))
			break;
		/* the chip as the recording started is no write of it */
		if (!ret && !p.watching && rec[0] != REC_STATE) {
			p.watching = true;
			ret = rp_watch(&p);
			if (ret)
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
	if (!ret && p.dev && !p.watching)
		ret = rp_watch(&p);
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
	int ret = replay_file(path, &full, dev_out, NULL, NULL, false);

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
	ret = replay_file(path, &full, dev_out, watch, hist, false);
	if (res)
		rdc_struct_out(res, &full, sizeof(full));
	return ret;
}

int rdc_replay_open(const char *path, rdc_dev **dev)
{
	if (!dev)
		return RDC_E_INVAL;
	return replay_file(path, NULL, dev, NULL, NULL, true);
}
