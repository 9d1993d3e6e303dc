// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * gen_scenes: compile golden scenes (.rdl) into the operation words that
 * the firmware image replays (mcu/scene.h), at build time, on the host.
 *
 *   gen_scenes OUT.c SCENE.rdl...
 *
 * For each scene:
 *  - the VRAM size: the smallest of 256 KiB, 512 KiB, ... MCU_VRAM_CAP on
 *    which the script runs and gives the picture and total cycles it gives
 *    on the sim: backend's default VRAM (an MCU has no 16 MiB to spare);
 *    a scene that fits none, or whose mode is larger than MCU_FRAME_CAP,
 *    is an error;
 *  - the script runs once more on a sim: device of that size with librdc's
 *    trace recorder attached, and then, as `rdcctl run` does, until its
 *    picture is on screen (rdc_script_frame_wait);
 *  - the trace (userspace/lib/record.c's format) becomes MCU_OP_* words,
 *    with MARK where the script's last statement finished, and the bytes
 *    of its VRAM writes.
 * OUT.c defines mcu_scenes[] and mcu_nscenes; "name vram" lines go to
 * stdout for the test, which runs `rdcctl run --uri sim:vram=N` on them.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "rdc_priv.h"
#include "rdc_proto.h"
#include "record.h"
#include "scene.h"

#define VRAM_LADDER_MIN (256u << 10)
#define OP_MAX_ARGS	0xffffffu

struct words {
	uint32_t *w;
	size_t n, cap;
};

struct gen {
	const char *name;
	struct words ops;
	uint8_t *data;
	size_t ndata, data_cap;
	size_t last_op; /* index of the last header in ops, or SIZE_MAX */
};

/* "gen_scenes: WHAT: WHY" and exit */
__attribute__((noreturn)) static void die(const char *what, const char *why)
{
	fprintf(stderr, "gen_scenes: %s: %s\n", what, why);
	exit(1);
}

static void *xrealloc(void *p, size_t n)
{
	p = realloc(p, n ? n : 1);
	if (!p)
		die("memory", "out of memory");
	return p;
}

static void put(struct gen *g, uint32_t v)
{
	if (g->ops.n == g->ops.cap) {
		g->ops.cap = g->ops.cap ? 2 * g->ops.cap : 4096;
		g->ops.w = xrealloc(g->ops.w, g->ops.cap * sizeof(uint32_t));
	}
	g->ops.w[g->ops.n++] = v;
}

static void put64(struct gen *g, uint64_t v)
{
	put(g, (uint32_t)v);
	put(g, (uint32_t)(v >> 32));
}

static void op_head(struct gen *g, uint32_t op, uint32_t nargs, uint64_t t)
{
	g->last_op = g->ops.n;
	put(g, op | nargs << 8);
	put64(g, t);
}

static void op_reg_write(struct gen *g, uint64_t t, uint32_t reg, uint32_t val)
{
	uint32_t *h = g->last_op != SIZE_MAX ? g->ops.w + g->last_op : NULL;

	/* a run of writes to one register at one time (FIFO_DATA) */
	if (h && g->last_op + MCU_OP_HEAD + (h[0] >> 8) == g->ops.n &&
	    (h[0] & 0xffu) == MCU_OP_REG_WRITE && h[0] >> 8 < OP_MAX_ARGS &&
	    h[1] == (uint32_t)t && h[2] == (uint32_t)(t >> 32) &&
	    h[MCU_OP_HEAD] == reg) {
		h[0] += 1u << 8;
		put(g, val);
		return;
	}
	op_head(g, MCU_OP_REG_WRITE, 2, t);
	put(g, reg);
	put(g, val);
}

static int wait_result(int32_t ret)
{
	if (!ret)
		return RDC_HW_WAIT_DONE;
	return ret == RDC_E_HALTED ? RDC_HW_WAIT_HALTED : RDC_HW_WAIT_TIMEOUT;
}

static void op_wait(struct gen *g, uint64_t t, const uint8_t *b)
{
	struct rdc_proto_wait pw;
	struct rdc_wait w = { 0 };
	struct rdc_hw_wait hw_w;

	if (rdc_proto_wait_decode(b, RDC_PROTO_WAIT_SIZE, &pw))
		die(g->name, "bad WAIT record");
	w.budget = pw.budget;
	w.needs_dp = pw.needs_dp;
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		w.term[i].kind = (enum rdc_wait_test)pw.term[i].kind;
		w.term[i].reg = pw.term[i].reg;
		w.term[i].mask = pw.term[i].mask;
		w.term[i].value = pw.term[i].value;
	}
	rdc_wait_to_hw(&w, &hw_w);
	op_head(g, MCU_OP_WAIT, MCU_OP_WAIT_ARGS, t);
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		put(g, hw_w.term[i].test);
		put(g, hw_w.term[i].reg);
		put(g, hw_w.term[i].mask);
		put(g, hw_w.term[i].value);
	}
	put(g, hw_w.needs_dp);
	put64(g, hw_w.budget);
	put(g, (uint32_t)wait_result(
		       (int32_t)rdc_proto_get32(b + RDC_PROTO_WAIT_SIZE)));
}

static void op_vram_write(struct gen *g, uint64_t t, uint32_t addr,
			  const uint8_t *p, uint32_t len)
{
	if (g->ndata + len > UINT32_MAX)
		die(g->name, "too much VRAM data");
	if (g->ndata + len > g->data_cap) {
		g->data_cap = 2 * (g->ndata + len);
		g->data = xrealloc(g->data, g->data_cap);
	}
	memcpy(g->data + g->ndata, p, len);
	op_head(g, MCU_OP_VRAM_WRITE, 3, t);
	put(g, addr);
	put(g, len);
	put(g, (uint32_t)g->ndata);
	g->ndata += len;
}

/* The trace in buf[0..n) into g's words; MARK at byte `mark` (time total). */
static void convert(struct gen *g, const uint8_t *buf, size_t n, size_t mark,
		    uint64_t total)
{
	size_t off = REC_HEAD_LEN;
	bool marked = false;

	if (n < REC_HEAD_LEN || memcmp(buf, REC_MAGIC, REC_MAGIC_LEN))
		die(g->name, "not a trace");
	/* sim:'s recorder writes timed traces: no flags word, no SUBMIT */
	if (rdc_proto_get32(buf + REC_MAGIC_LEN) != REC_VERSION)
		die(g->name, "not a timed trace");
	g->last_op = SIZE_MAX;
	op_head(g, MCU_OP_POWER, 0, 0);
	for (;;) {
		const uint8_t *r = buf + off;
		uint64_t t;
		size_t need;

		if (off == mark) {
			op_head(g, MCU_OP_MARK, 0, total);
			marked = true;
		}
		if (n - off < REC_RECORD_HEAD)
			die(g->name, "trace without END");
		t = rdc_proto_get64(r + 1);
		switch (r[0]) {
		case REC_REG_WRITE:
		case REC_REG_READ:
		case REC_VRAM_WRITE:
		case REC_PINS:
		case REC_STEP:
			need = 8;
			break;
		case REC_WAIT:
			need = RDC_PROTO_WAIT_SIZE + 4;
			break;
		case REC_POWER:
		case REC_END:
			need = 0;
			break;
		case REC_SUBMIT:
			die(g->name, "SUBMIT record in a timed trace");
		default:
			die(g->name, "unknown trace record");
		}
		if (n - off - REC_RECORD_HEAD < need)
			die(g->name, "trace cut short");
		r += REC_RECORD_HEAD;
		off += REC_RECORD_HEAD + need;
		switch (buf[off - REC_RECORD_HEAD - need]) {
		case REC_REG_WRITE:
			op_reg_write(g, t, rdc_proto_get32(r),
				     rdc_proto_get32(r + 4));
			break;
		case REC_REG_READ:
			op_head(g, MCU_OP_REG_READ, 2, t);
			put(g, rdc_proto_get32(r));
			put(g, rdc_proto_get32(r + 4));
			break;
		case REC_VRAM_WRITE: {
			uint32_t len = rdc_proto_get32(r + 4);

			if (n - off < len)
				die(g->name, "trace cut short");
			op_vram_write(g, t, rdc_proto_get32(r), buf + off, len);
			off += len;
			break;
		}
		case REC_WAIT:
			op_wait(g, t, r);
			break;
		case REC_STEP:
			op_head(g, MCU_OP_STEP, 2, t);
			put64(g, rdc_proto_get64(r));
			break;
		case REC_PINS:
			op_head(g, MCU_OP_PINS, 2, t);
			put(g, rdc_proto_get32(r));
			put(g, rdc_proto_get32(r + 4));
			break;
		case REC_POWER:
			op_head(g, MCU_OP_POWER, 0, t);
			break;
		case REC_END:
			if (!marked)
				die(g->name, "no end of script");
			op_head(g, MCU_OP_END, 0, t);
			return;
		}
	}
}

struct outcome {
	uint64_t total;
	uint32_t crc, w, h;
};

/*
 * Run the script as `rdcctl run` does on sim:vram=vram (0: the default);
 * with `trace`, record it there, and *mark gets the trace's length when
 * the script had finished.  0, or the librdc error.
 */
static int run(const char *path, uint32_t vram, const char *trace,
	       struct outcome *o, size_t *mark)
{
	struct rdc_script_result *res = calloc(1, sizeof(*res));
	struct rdc_server_rec *rec = NULL;
	rdc_dev *dev = NULL;
	char uri[48] = "sim:";
	struct stat st;
	int ret;

	if (!res)
		return RDC_E_NOMEM;
	if (vram)
		snprintf(uri, sizeof(uri), "sim:vram=%u", vram);
	ret = rdc_open(uri, &dev);
	if (!ret && trace) {
		rec = rdc_server_rec_open(trace, vram);
		if (rec)
			rdc_server_rec_attach(rec, dev);
		else
			ret = RDC_E_FILE;
	}
	if (!ret)
		ret = rdc_script_run_file(dev, path, res);
	if (!ret)
		ret = rdc_sim_time(dev, &o->total);
	if (!ret && rec) {
		rdc_server_rec_sync(rec);
		ret = stat(trace, &st) ? RDC_E_FILE : 0;
		*mark = (size_t)st.st_size;
	}
	if (!ret)
		ret = rdc_script_frame_wait(dev, res);
	if (!ret)
		ret = rdc_frame_grab(dev, NULL, 0, &o->w, &o->h);
	if (ret == RDC_E_RANGE)
		ret = 0;
	if (!ret)
		ret = rdc_frame_crc(dev, &o->crc);
	if (rec) {
		int err = rdc_server_rec_close(rec, dev);

		if (!ret)
			ret = err;
	}
	rdc_close(dev);
	free(res);
	return ret;
}

static uint8_t *slurp(const char *path, size_t *n)
{
	FILE *f = fopen(path, "rb");
	uint8_t *buf = NULL;
	size_t cap = 0, got;

	*n = 0;
	if (!f)
		die(path, strerror(errno));
	do {
		if (*n == cap) {
			cap = cap ? 2 * cap : 1 << 16;
			buf = xrealloc(buf, cap);
		}
		got = fread(buf + *n, 1, cap - *n, f);
		*n += got;
	} while (got);
	if (ferror(f))
		die(path, "read error");
	fclose(f);
	return buf;
}

static void emit(FILE *out, struct gen *g, size_t idx)
{
	fprintf(out, "static const uint32_t ops%zu[] = {\t/* %s */", idx,
		g->name);
	for (size_t i = 0; i < g->ops.n; i++)
		fprintf(out, "%s0x%x,", i % 8 ? " " : "\n\t", g->ops.w[i]);
	fprintf(out, "\n};\n");
	fprintf(out, "static const uint8_t data%zu[] = {", idx);
	for (size_t i = 0; i < g->ndata; i++)
		fprintf(out, "%s%u,", i % 16 ? "" : "\n", g->data[i]);
	fprintf(out, "%s};\n\n", g->ndata ? "\n" : "0");
}

int main(int argc, char **argv)
{
	FILE *out;
	char *tmp;
	char **names;
	uint32_t *vrams;
	size_t *nwords, *ndata;
	int i;

	if (argc < 3)
		die("usage", "gen_scenes OUT.c SCENE.rdl...");
	tmp = xrealloc(NULL, strlen(argv[1]) + 8);
	sprintf(tmp, "%s.trace", argv[1]);
	names = xrealloc(NULL, (size_t)argc * sizeof(*names));
	vrams = xrealloc(NULL, (size_t)argc * sizeof(*vrams));
	nwords = xrealloc(NULL, (size_t)argc * sizeof(*nwords));
	ndata = xrealloc(NULL, (size_t)argc * sizeof(*ndata));
	out = fopen(tmp, "w");
	if (!out)
		die(tmp, strerror(errno));
	fclose(out);
	out = fopen(argv[1], "w");
	if (!out)
		die(argv[1], strerror(errno));
	fprintf(out, "// SPDX-License-Identifier: GPL-2.0-only\n"
		     "/* Generated by mcu/gen_scenes from golden scenes: do "
		     "not edit. */\n#include \"scene.h\"\n\n");
	for (i = 2; i < argc; i++) {
		struct gen g = { 0 };
		struct outcome ref, o;
		const char *base = strrchr(argv[i], '/');
		char *dot;
		uint32_t vram;
		size_t n, mark = 0;
		uint8_t *buf;
		int ret;

		base = base ? base + 1 : argv[i];
		g.name = names[i] = strdup(base);
		if (!g.name)
			die("memory", "out of memory");
		dot = strrchr(names[i], '.');
		if (dot)
			*dot = '\0';
		ret = run(argv[i], 0, NULL, &ref, NULL);
		if (ret)
			die(argv[i], rdc_strerror(ret));
		if ((uint64_t)ref.w * ref.h > MCU_FRAME_CAP)
			die(argv[i], "frame larger than MCU_FRAME_CAP");
		for (vram = VRAM_LADDER_MIN; vram <= MCU_VRAM_CAP; vram *= 2) {
			if (!run(argv[i], vram, NULL, &o, NULL) &&
			    o.total == ref.total && o.crc == ref.crc &&
			    o.w == ref.w && o.h == ref.h)
				break;
		}
		if (vram > MCU_VRAM_CAP)
			die(argv[i], "needs more than MCU_VRAM_CAP");
		ret = run(argv[i], vram, tmp, &o, &mark);
		if (ret)
			die(argv[i], rdc_strerror(ret));
		buf = slurp(tmp, &n);
		convert(&g, buf, n, mark, o.total);
		emit(out, &g, (size_t)i);
		vrams[i] = vram;
		nwords[i] = g.ops.n;
		ndata[i] = g.ndata;
		printf("%s %u\n", names[i], vram);
		free(buf);
		free(g.ops.w);
		free(g.data);
	}
	fprintf(out, "const struct mcu_scene mcu_scenes[] = {\n");
	for (i = 2; i < argc; i++)
		fprintf(out, "\t{\"%s\", %u, ops%d, %zu, data%d, %zu},\n",
			names[i], vrams[i], i, nwords[i], i, ndata[i]);
	fprintf(out, "};\n\nconst uint32_t mcu_nscenes = %d;\n", argc - 2);
	if (fclose(out))
		die(argv[1], "write error");
	remove(tmp);
	return 0;
}
