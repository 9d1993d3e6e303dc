// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * Why is this pixel that colour: `rdcctl run FILE --history SPEC`,
 * `rdcctl why X Y FILE` and where two runs part, `rdcctl diff A B`
 * (docs/history.md).
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "history.h"
#include "rdc.h"
#include "rdc_server.h"
#include "report.h"

#define DEFAULT_URI "sim:"

const char rdcctl_history_usage[] =
	"  run FILE.rdl --history SPEC   every VRAM write to the pixels of\n"
	"      [--json] [--limit N]      SPEC (X,Y or X,Y,W,H or screen):\n"
	"                                command, line, cycle, state, value\n"
	"                                before and after (sim:, rdcd)\n"
	"  why X Y FILE.rdl [--json]     the same for the pixel X,Y\n"
	"  diff A.rdl B.rdl [-o D.png]   run both and report the first\n"
	"                                command and cycle where VRAM\n"
	"                                differs, the region of the frames\n"
	"                                that differs, and a PNG of it\n"
	"                                (each FILE a script or a trace of\n"
	"                                rdcd --record: then its records)\n";

static const char *const rop_names[16] = {
	"clear",	 "and",		"and-reverse", "copy",
	"and-inverted",	 "noop",	"xor",	       "or",
	"nor",		 "equiv",	"invert",      "or-reverse",
	"copy-inverted", "or-inverted", "nand",	       "set",
};

static const char *const pat_names[4] = { "solid", "mono", "mono-transparent",
					  "color" };

static const char *const src_names[4] = { "fifo", "ring", "list", "host" };

static const char *op_str(uint32_t op, char *buf, size_t cap)
{
	const char *n = op == RDC_HISTORY_OP_HOST ? "host-write" :
						    rdc_op_name(op);

	if (n)
		return n;
	snprintf(buf, cap, "op-0x%02x", op);
	return buf;
}

struct hopts {
	const char *uri;
	const char *script;
	const char *script_b;
	const char *png;
	uint32_t x, y, w, h;
	size_t limit;
	int json;
	int trace; /* the input is an rdcd trace: `line` is its record */
};

/* "X,Y", "X,Y,W,H" or "screen". */
static int parse_spec(const char *s, struct hopts *o)
{
	unsigned long v[4];
	int n;
	char tail;

	if (!strcmp(s, "screen")) {
		o->x = o->y = 0;
		o->w = o->h = RDC_HISTORY_SCREEN;
		return 0;
	}
	n = sscanf(s, "%lu,%lu,%lu,%lu%c", &v[0], &v[1], &v[2], &v[3], &tail);
	if (n == 2) {
		v[2] = v[3] = 1;
	} else if (n != 4) {
		return -1;
	}
	for (int i = 0; i < 4; i++)
		if (v[i] > 65535)
			return -1;
	if (!v[2] || !v[3])
		return -1;
	o->x = (uint32_t)v[0];
	o->y = (uint32_t)v[1];
	o->w = (uint32_t)v[2];
	o->h = (uint32_t)v[3];
	return 0;
}

static void print_entry(const struct hopts *o, size_t i,
			const struct rdc_history_entry *e)
{
	char ob[16];

	printf("(%u,%u) #%zu cycle %" PRIu64 " frame %" PRIu64 ": ", e->x, e->y,
	       i + 1, e->cycle, e->frame);
	if (e->line && o->trace)
		printf("%s record %u ", o->script, e->line);
	else if (e->line)
		printf("%s:%u ", o->script, e->line);
	printf("%s", op_str(e->opcode, ob, sizeof(ob)));
	if (e->source == RDC_HISTORY_SRC_HOST) {
		printf(" (host aperture)\n");
	} else {
		printf(" (command %u, %s", e->cmd_index,
		       src_names[e->source & 3]);
		if (e->source == RDC_HISTORY_SRC_LIST) {
			printf(" at 0x%08x, depth %u", e->cmd_addr, e->depth);
			for (uint32_t d = e->depth - 1; d-- > 0;)
				printf(", called from 0x%08x", e->calls[d]);
		}
		printf(")\n    rop %s alpha %u colorkey %s",
		       rop_names[e->rop & 15], e->alpha,
		       e->colorkey_on ? "on" : "off");
		if (e->colorkey_on)
			printf(" 0x%08x", e->colorkey);
		printf(" pattern %s fg 0x%08x bg 0x%08x\n",
		       pat_names[e->pattern & 3], e->fg, e->bg);
	}
	printf("    0x%08x -> 0x%08x%s; ", e->before, e->after,
	       e->before == e->after ? " (unchanged)" : "");
	if (e->fetched > 0)
		printf("line %u already scanned: frame %" PRIu64
		       " shows the old value, frame %" PRIu64 " the new\n",
		       e->y, e->frame, e->frame + 1);
	else if (!e->fetched)
		printf("line %u not yet scanned: frame %" PRIu64
		       " shows the new value\n",
		       e->y, e->frame);
	else
		printf("scanout stopped\n");
}

static void json_entry(const struct hopts *o, const struct rdc_history_entry *e,
		       int last)
{
	char ob[16];

	printf("  {\"x\": %u, \"y\": %u, \"cycle\": %" PRIu64
	       ", \"frame\": %" PRIu64 ", \"fetched\": %d, "
	       "\"opcode\": %u, \"op\": \"%s\", \"command\": %u, "
	       "\"source\": \"%s\", ",
	       e->x, e->y, e->cycle, e->frame, e->fetched, e->opcode,
	       op_str(e->opcode, ob, sizeof(ob)), e->cmd_index,
	       src_names[e->source & 3]);
	if (e->line) {
		printf("\"file\": \"");
		for (const char *p = o->script; *p; p++) {
			if (*p == '"' || *p == '\\')
				putchar('\\');
			if ((unsigned char)*p < 0x20)
				printf("\\u%04x", *p);
			else
				putchar(*p);
		}
		printf("\", \"%s\": %u, ", o->trace ? "record" : "line",
		       e->line);
	}
	if (e->source == RDC_HISTORY_SRC_LIST) {
		printf("\"cmd_addr\": %u, \"calls\": [", e->cmd_addr);
		for (uint32_t d = 0; d + 1 < e->depth; d++)
			printf("%s%u", d ? ", " : "", e->calls[d]);
		printf("], ");
	}
	printf("\"rop\": %u, \"alpha\": %u, \"colorkey_on\": %u, "
	       "\"colorkey\": %u, \"pattern\": %u, \"fg\": %u, \"bg\": %u, "
	       "\"format\": %u, \"before\": %u, \"after\": %u}%s\n",
	       e->rop, e->alpha, e->colorkey_on, e->colorkey, e->pattern, e->fg,
	       e->bg, e->format, e->before, e->after, last ? "" : ",");
}

/*
 * The CLUT entry an indexed pixel shows, and the raster-list entry that
 * wrote it this frame (or the frame before), for one watched pixel.
 */
static void print_clut(const struct hopts *o, rdc_history *h)
{
	struct rdc_history_clut c;

	if (rdc_history_clut(h, o->x, o->y, &c))
		return;
	printf("(%u,%u) shows CLUT entry %u", c.x, c.y, c.index);
	if (c.source == RDC_HISTORY_CLUT_HOST) {
		printf(" as the host wrote it (no raster-list entry writes "
		       "it)\n");
		return;
	}
	printf(" = 0x%06x: raster-list entry %u (VRAM 0x%08x) at line %u, column %u "
	       "%s\n",
	       c.value, c.entry, c.addr, c.beam_y, c.beam_x,
	       c.source == RDC_HISTORY_CLUT_LIST ?
		       "this frame" :
		       "in the frame before (none earlier writes it)");
}

static void json_clut(const struct hopts *o, rdc_history *h)
{
	static const char *const names[] = { "host", "list", "list-prev" };
	struct rdc_history_clut c;

	if (rdc_history_clut(h, o->x, o->y, &c))
		return;
	printf(", \"clut\": {\"index\": %u, \"source\": \"%s\"", c.index,
	       names[c.source % 3]);
	if (c.source != RDC_HISTORY_CLUT_HOST)
		printf(", \"entry\": %u, \"addr\": %u, \"beam_x\": %u, "
		       "\"beam_y\": %u, \"value\": %u",
		       c.entry, c.addr, c.beam_x, c.beam_y, c.value);
	printf("}");
}

/*
 * The frames scanout made while a script ran on sim: (diff): a CRC-32 of
 * each, size included, with the cycle it completed at.
 */
#define FRAMES_MAX (1u << 22)

struct frames {
	struct rdc_hw *hw;
	uint32_t *crc;
	uint64_t *time;
	size_t n, cap;
	int lost;     /* out of memory or over FRAMES_MAX: not compared */
	uint64_t end; /* when the script's last statement ended, as run's */
};

static void on_frame(void *ctx, const uint32_t *xrgb, uint32_t w, uint32_t h,
		     uint64_t number)
{
	struct frames *f = ctx;
	uint8_t wh[8];
	uLong c;

	(void)number;
	if (f->lost)
		return;
	if (f->n == f->cap) {
		size_t cap = f->cap ? f->cap * 2 : 64;
		uint32_t *nc = cap <= FRAMES_MAX ?
				       realloc(f->crc, cap * sizeof(*nc)) :
				       NULL;
		uint64_t *nt;

		if (nc)
			f->crc = nc;
		nt = nc ? realloc(f->time, cap * sizeof(*nt)) : NULL;
		if (!nt) {
			f->lost = 1;
			return;
		}
		f->time = nt;
		f->cap = cap;
	}
	for (int i = 0; i < 4; i++) {
		wh[i] = (uint8_t)(w >> (8 * i));
		wh[4 + i] = (uint8_t)(h >> (8 * i));
	}
	c = crc32(crc32(0L, Z_NULL, 0), wh, sizeof(wh));
	for (size_t row = 0; row < h; row++)
		c = crc32(c, (const Bytef *)(xrgb + row * w), w * 4u);
	f->crc[f->n] = (uint32_t)c;
	f->time[f->n] = rdc_hw_now(f->hw);
	f->n++;
}

/* *end (may be NULL): the time the last statement ended, run's "total". */
static int run_file(rdc_dev *dev, const char *path, uint64_t *end)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	int ret;

	if (!res)
		return RDC_E_NOMEM;
	ret = rdc_script_run_file(dev, path, res);
	if (ret)
		rdcctl_script_error(path, ret, res);
	if (end)
		rdc_sim_time(dev, end);
	if (!ret)
		ret = rdc_script_frame_wait(dev, res);
	free(res);
	return ret;
}

static void save_frame(rdc_dev *dev, const char *path)
{
	uint32_t *pix = NULL, w = 0, h = 0;
	int ret = rdc_frame_grab(dev, NULL, 0, &w, &h);

	if (ret == RDC_E_RANGE) {
		pix = malloc(((size_t)w * h + 1) * sizeof(*pix));
		ret = pix ? rdc_frame_grab(dev, pix, (size_t)w * h, &w, &h) :
			    RDC_E_NOMEM;
	}
	if (!ret)
		ret = rdc_png_write(path, pix, w, h, w);
	if (ret)
		rdcctl_error(path, ret);
	free(pix);
}

/* An rdcd trace (rdcd --record) rather than a script? */
static int is_trace(const char *path)
{
	FILE *f = fopen(path, "rb");
	char m[8];
	int t = f && fread(m, 1, sizeof(m), f) == sizeof(m) &&
		!memcmp(m, "RDCTRACE", sizeof(m));

	if (f)
		fclose(f);
	return t;
}

/*
 * Run a script on a device of `uri`, or replay a trace on the fresh sim:
 * it brings, with a history open.  A script's device error is no failure:
 * its history up to there is what is wanted.  *ret_run gets it; *untimed
 * (may be NULL) whether the trace has no times (rdc_record_start's on a
 * device other than sim:).  A script runs from where the trace `start`
 * starts (may be NULL: a fresh device of `uri`) when `uri` is sim:'s
 * default (diff: the two from the same chip).
 */
static int open_run(const char *uri, const char *path, const uint32_t *spec,
		    uint32_t flags, size_t limit, rdc_history **h,
		    rdc_dev **dev, int *ret_run, struct frames *fr,
		    int *untimed, const char *start)
{
	int ret;

	*ret_run = 0;
	if (is_trace(path)) {
		struct rdc_replay_result rr;

		if (rdcctl_record_path) {
			fprintf(stderr,
				"rdcctl: --record: %s is a trace, replayed on "
				"a fresh sim: (nothing of --connect's to "
				"record)\n",
				path);
			return RDC_E_INVAL;
		}
		ret = rdc_replay_history(path, spec[0], spec[1], spec[2],
					 spec[3], flags, h, &rr, dev);
		if (untimed)
			*untimed = !ret && rr.untimed;
		if (ret)
			rdcctl_error(path, ret);
		else if (rr.truncated)
			fprintf(stderr,
				"rdcctl: %s: truncated trace, "
				"replayed up to its last complete "
				"record\n",
				path);
		return ret;
	}
	if (start && !strcmp(uri, DEFAULT_URI)) {
		ret = rdc_replay_open(start, dev);
		if (ret) {
			rdcctl_error(start, ret);
			return ret;
		}
	} else {
		ret = rdcctl_open(uri, dev);
		if (ret)
			return ret;
	}
	ret = rdc_history_open(*dev, spec[0], spec[1], spec[2], spec[3], flags,
			       h);
	if (ret) {
		rdcctl_error("history", ret);
		rdc_close(*dev);
		*dev = NULL;
		return ret;
	}
	if (limit)
		rdc_history_set_limit(*h, limit);
	if (fr) {
		fr->hw = rdc_sim_hw(*dev);
		if (fr->hw)
			rdc_hw_set_frame_fn(fr->hw, on_frame, fr);
	}
	*ret_run = run_file(*dev, path, fr ? &fr->end : NULL);
	if (fr && fr->hw)
		rdc_hw_set_frame_fn(fr->hw, NULL, NULL);
	if (*ret_run && *ret_run != RDC_E_DEVICE && *ret_run != RDC_E_HALTED) {
		rdc_history_close(*h);
		rdc_close(*dev);
		*h = NULL;
		*dev = NULL;
		return *ret_run;
	}
	return 0;
}

static int cmd_history(struct hopts *o)
{
	const uint32_t spec[4] = { o->x, o->y, o->w, o->h };
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;
	/* one pixel: what its CLUT entry is, and who wrote it */
	int one = o->w == 1 && o->h == 1;
	size_t n;
	int ret;

	o->trace = is_trace(o->script);
	if (open_run(o->uri, o->script, spec, 0, o->limit, &h, &dev, &ret, NULL,
		     NULL, NULL))
		return 1;
	if (o->png)
		save_frame(dev, o->png);
	n = rdc_history_count(h);
	if (o->json)
		printf("{\"entries\": [\n");
	for (size_t i = 0; i < n; i++) {
		struct rdc_history_entry e;

		if (rdc_history_get(h, i, &e))
			break;
		if (o->json)
			json_entry(o, &e, i + 1 == n);
		else
			print_entry(o, i, &e);
	}
	if (o->json) {
		printf("], \"dropped\": %" PRIu64, rdc_history_dropped(h));
		if (one)
			json_clut(o, h);
		printf("}\n");
	} else if (!n) {
		printf("no write touched %u,%u (%ux%u)\n", o->x, o->y,
		       o->w == RDC_HISTORY_SCREEN ? 0 : o->w,
		       o->h == RDC_HISTORY_SCREEN ? 0 : o->h);
	}
	if (!o->json && one)
		print_clut(o, h);
	if (!o->json && rdc_history_dropped(h))
		printf("%" PRIu64 " more entries not kept (--limit)\n",
		       rdc_history_dropped(h));
	rdc_history_close(h);
	rdc_close(dev);
	return ret ? 1 : 0;
}

/* ---- diff ---------------------------------------------------------------- */

struct side {
	const char *path;
	int trace;
	int untimed;	/* a trace without times: its cycles are the replay's */
	rdc_history *h; /* kept after its device closes */
	struct rdc_history_write *w;
	size_t n;
	uint32_t *pix, width, height;
	uint64_t time;
	int ret;
	struct frames fr; /* a script's every frame; none for a trace */
};

/* `start`: the other side's trace, where a script starts (open_run) */
static int side_run(const char *uri, struct side *s, const char *start)
{
	static const uint32_t none[4] = { 0, 0, 0, 0 };
	rdc_history *h = NULL;
	rdc_dev *dev = NULL;
	int ret;

	s->trace = is_trace(s->path);
	ret = open_run(uri, s->path, none, RDC_HISTORY_WRITES, 0, &h, &dev,
		       &s->ret, &s->fr, &s->untimed, start);
	if (ret)
		return ret;
	s->n = rdc_history_write_count(h);
	s->w = calloc(s->n + 1, sizeof(*s->w));
	if (!s->w) {
		ret = RDC_E_NOMEM;
		goto out;
	}
	for (size_t i = 0; i < s->n; i++)
		rdc_history_write_get(h, i, &s->w[i]);
	/* as run's and replay's "total": a script's until its last
	 * statement ended, before the wait for its frame */
	if (s->trace)
		rdc_sim_time(dev, &s->time);
	else
		s->time = s->fr.end;
	ret = rdc_frame_grab(dev, NULL, 0, &s->width, &s->height);
	if (ret == RDC_E_RANGE) {
		s->pix = malloc(((size_t)s->width * s->height + 1) *
				sizeof(*s->pix));
		ret = s->pix ? rdc_frame_grab(dev, s->pix,
					      (size_t)s->width * s->height,
					      &s->width, &s->height) :
			       RDC_E_NOMEM;
	} else if (ret == 1) {
		ret = 0; /* no frame */
	}
	if (ret)
		rdcctl_error("frame", ret);
out:
	s->h = h;
	rdc_close(dev);
	return ret;
}

static void diff_write(const char *tag, const struct side *s, size_t i)
{
	const struct rdc_history_write *w = &s->w[i];
	const struct rdc_history_entry *e = &w->entry;
	char ob[16];

	printf("  %s: ", tag);
	if (i >= s->n) {
		printf("no such write (%zu writes in all)\n", s->n);
		return;
	}
	printf("cycle %" PRIu64 " ", e->cycle);
	if (e->line && s->trace)
		printf("%s record %u ", s->path, e->line);
	else if (e->line)
		printf("%s:%u ", s->path, e->line);
	printf("%s", op_str(e->opcode, ob, sizeof(ob)));
	if (e->source != RDC_HISTORY_SRC_HOST)
		printf(" (command %u, %s", e->cmd_index,
		       src_names[e->source & 3]);
	if (e->source == RDC_HISTORY_SRC_LIST) {
		printf(" at 0x%08x", e->cmd_addr);
		for (uint32_t d = e->depth - 1; d-- > 0;)
			printf(", called from 0x%08x", e->calls[d]);
	}
	if (e->source != RDC_HISTORY_SRC_HOST)
		printf(")");
	printf(" VRAM 0x%08x", w->addr);
	if (w->count > 1)
		printf(" %u x %u bytes, stride %u\n", w->count, w->len,
		       w->stride);
	else
		printf(" %u bytes\n", w->len);
}

static int cmd_diff(const struct hopts *o)
{
	struct side a = { .path = o->script }, b = { .path = o->script_b };
	size_t i, n, timing = SIZE_MAX;
	uint32_t w, h, x0 = UINT32_MAX, y0 = UINT32_MAX, x1 = 0, y1 = 0;
	uint64_t ndiff = 0;
	uint32_t *out = NULL;
	int ret, differs = 0;

	/* a script against a trace runs from where the trace starts */
	ret = side_run(o->uri, &a, is_trace(b.path) ? b.path : NULL);
	if (!ret)
		ret = side_run(o->uri, &b, is_trace(a.path) ? a.path : NULL);
	if (ret)
		goto out;
	differs = rdc_history_first_diff(a.h, b.h, &i) == 1;
	n = a.n < b.n ? a.n : b.n;
	for (size_t k = 0; k < n && k < i; k++)
		if (a.w[k].entry.cycle != b.w[k].entry.cycle) {
			timing = k;
			break;
		}
	if (differs) {
		differs = 1;
		printf("first divergence: VRAM write %zu\n", i + 1);
		diff_write("A", &a, i);
		diff_write("B", &b, i);
	} else {
		printf("VRAM writes: the same %zu writes\n", a.n);
	}
	if (a.untimed || b.untimed)
		/* the cycles are sim:'s replay's, not the device's */
		printf("timing: not compared (%s is an untimed trace: the "
		       "device's time was not recorded)\n",
		       a.untimed ? a.path : b.path);
	else if (timing != SIZE_MAX && timing < i)
		printf("timing parts first at write %zu: cycle %" PRIu64
		       " in A, %" PRIu64 " in B\n",
		       timing + 1, a.w[timing].entry.cycle,
		       b.w[timing].entry.cycle);
	if (!a.untimed && !b.untimed)
		printf("total cycles: A %" PRIu64 ", B %" PRIu64
		       " (as run or replay prints each)\n",
		       a.time, b.time);
	/* the scanned-out frames, each (scripts on sim:; a trace: its last) */
	if (a.fr.hw && b.fr.hw && !a.fr.lost && !b.fr.lost) {
		size_t nf = a.fr.n < b.fr.n ? a.fr.n : b.fr.n, k;

		for (k = 0; k < nf && a.fr.crc[k] == b.fr.crc[k]; k++)
			;
		if (k < nf) {
			differs = 1;
			printf("first frame that differs: frame %zu, completed "
			       "at cycle %" PRIu64 " in A, %" PRIu64 " in B\n",
			       k, a.fr.time[k], b.fr.time[k]);
		} else if (a.fr.n != b.fr.n) {
			printf("frames: the first %zu the same; A made %zu, B "
			       "%zu\n",
			       nf, a.fr.n, b.fr.n);
		}
	}
	w = a.width > b.width ? a.width : b.width;
	h = a.height > b.height ? a.height : b.height;
	if (a.width != b.width || a.height != b.height) {
		differs = 1;
		printf("frame: %ux%u in A, %ux%u in B\n", a.width, a.height,
		       b.width, b.height);
	}
	if (w && h) {
		out = calloc((size_t)w * h, sizeof(*out));
		if (!out) {
			ret = RDC_E_NOMEM;
			goto out;
		}
	}
	for (uint32_t y = 0; out && y < h; y++)
		for (uint32_t x = 0; x < w; x++) {
			int ina = a.pix && x < a.width && y < a.height;
			int inb = b.pix && x < b.width && y < b.height;
			uint32_t pa = ina ? a.pix[(size_t)y * a.width + x] : 0;
			uint32_t pb = inb ? b.pix[(size_t)y * b.width + x] : 0;

			if (ina == inb && (pa & 0xffffff) == (pb & 0xffffff)) {
				/* the same: A's pixel, a quarter as bright */
				out[(size_t)y * w + x] = (pa >> 2) & 0x3f3f3f;
				continue;
			}
			out[(size_t)y * w + x] = 0xff00ff;
			ndiff++;
			x0 = x < x0 ? x : x0;
			y0 = y < y0 ? y : y0;
			x1 = x > x1 ? x : x1;
			y1 = y > y1 ? y : y1;
		}
	if (ndiff) {
		differs = 1;
		printf("frame: %" PRIu64 " pixels differ in %u,%u .. %u,%u "
		       "(%ux%u)\n",
		       ndiff, x0, y0, x1, y1, x1 - x0 + 1, y1 - y0 + 1);
	} else if (w && h) {
		printf("frame: the same\n");
	}
	if (o->png && out) {
		ret = rdc_png_write(o->png, out, w, h, w);
		if (ret)
			rdcctl_error(o->png, ret);
		else
			printf("difference written to %s (magenta: differs)\n",
			       o->png);
	}
out:
	free(out);
	free(a.w);
	free(b.w);
	free(a.pix);
	free(b.pix);
	free(a.fr.crc);
	free(a.fr.time);
	free(b.fr.crc);
	free(b.fr.time);
	rdc_history_close(a.h);
	rdc_history_close(b.h);
	if (ret)
		return 1;
	return differs ? RDCCTL_EXIT_DIFFERS : 0;
}

static int need(int argc, char **argv, int i)
{
	if (i + 1 < argc)
		return 0;
	fprintf(stderr, "rdcctl: %s needs a value\n", argv[i]);
	return -1;
}

int rdcctl_history_main(int argc, char **argv)
{
	struct hopts o = { .uri = DEFAULT_URI };
	const char *pos[4];
	int npos = 0, history = 0, at = -1;
	const char *cmd = NULL;

	/* the command is the first word that is not an option or its value */
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--uri") ||
		    !strcmp(argv[i], "--connect") || !strcmp(argv[i], "-o") ||
		    !strcmp(argv[i], "--vcd") ||
		    !strcmp(argv[i], "--history") ||
		    !strcmp(argv[i], "--limit")) {
			i++;
		} else if (argv[i][0] != '-' || !argv[i][1]) {
			cmd = argv[i];
			at = i;
			break;
		}
	}
	if (!cmd)
		return -1;
	for (int i = 1; i < argc; i++)
		if (!strcmp(argv[i], "--history") ||
		    !strncmp(argv[i], "--history=", 10))
			history = 1;
	if (strcmp(cmd, "why") && strcmp(cmd, "diff") &&
	    !(history && !strcmp(cmd, "run")))
		return -1;
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];

		if (i == at)
			continue;
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			printf("usage: rdcctl [--connect URI] COMMAND ...\n%s",
			       rdcctl_history_usage);
			return 0;
		} else if (!strcmp(a, "--uri") || !strcmp(a, "--connect")) {
			if (need(argc, argv, i))
				return 2;
			o.uri = argv[++i];
		} else if (!strncmp(a, "--uri=", 6) ||
			   !strncmp(a, "--connect=", 10)) {
			o.uri = strchr(a, '=') + 1;
		} else if (!strcmp(a, "-o")) {
			if (need(argc, argv, i))
				return 2;
			o.png = argv[++i];
		} else if (!strcmp(a, "--json")) {
			o.json = 1;
		} else if (!strcmp(a, "--limit")) {
			char *end;

			if (need(argc, argv, i))
				return 2;
			o.limit = strtoul(argv[++i], &end, 10);
			if (*end || !o.limit) {
				fprintf(stderr, "rdcctl: bad --limit '%s'\n",
					argv[i]);
				return 2;
			}
		} else if (!strcmp(a, "--history") ||
			   !strncmp(a, "--history=", 10)) {
			const char *spec = a[9] == '=' ? a + 10 : NULL;

			if (!spec) {
				if (need(argc, argv, i))
					return 2;
				spec = argv[++i];
			}
			if (parse_spec(spec, &o)) {
				fprintf(stderr,
					"rdcctl: --history wants X,Y, X,Y,W,H "
					"or screen, not '%s'\n",
					spec);
				return 2;
			}
		} else if (a[0] == '-' && a[1]) {
			fprintf(stderr, "rdcctl: %s: unknown option '%s'\n",
				cmd, a);
			return 2;
		} else if (npos < 4) {
			pos[npos++] = a;
		} else {
			fprintf(stderr, "rdcctl: unexpected argument '%s'\n",
				a);
			return 2;
		}
	}
	if (!strcmp(cmd, "run")) {
		if (npos != 1) {
			fprintf(stderr, "rdcctl: run --history needs one "
					"script\n");
			return 2;
		}
		o.script = pos[0];
		return cmd_history(&o);
	}
	if (!strcmp(cmd, "why")) {
		char spec[64];

		if (npos != 3) {
			fprintf(stderr, "rdcctl: usage: why X Y FILE.rdl\n");
			return 2;
		}
		snprintf(spec, sizeof(spec), "%s,%s", pos[0], pos[1]);
		if (parse_spec(spec, &o)) {
			fprintf(stderr, "rdcctl: why: bad pixel %s %s\n",
				pos[0], pos[1]);
			return 2;
		}
		o.script = pos[2];
		return cmd_history(&o);
	}
	if (npos != 2) {
		fprintf(stderr, "rdcctl: usage: diff A.rdl B.rdl [-o D.png]\n");
		return 2;
	}
	o.script = pos[0];
	o.script_b = pos[1];
	return cmd_diff(&o);
}
