// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The VCD writer (userspace/lib/vcd.c): its exact output for a short scene
 * against a golden file, the file read back by a small reader written here
 * from IEEE 1364 (not from the writer), TE's period equal to the mode's
 * frame time in that reader and in sigrok-cli's, hblank and the line
 * vector against the timing, and the two front ends: rdcctl run --vcd
 * (and its refusal on a daemon) and rdcd --vcd.
 *
 * The golden file: tests/unit/data/vcd_tiny.vcd (RDC_VCD_GOLDEN names
 * another).  After a deliberate change to the writer or the scene,
 * regenerate it from the source root with `RDC_VCD_REGEN=1
 * $(O)/san/tests/test_vcd`, and look at the diff: the file is rewritten
 * only when every other test passed, never after a failure.
 */
#include <libgen.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc.h"
#include "hw.h"
#include "test_net_common.h"

#define GOLDEN	     "tests/unit/data/vcd_tiny.vcd"
#define CORE_HZ	     100000000ull
#define NS_PER_CYCLE 10u /* at CORE_HZ */
#define FS_PER_NS    1000000ull

static char bindir[4096];

/* ---- a reader, from the standard ------------------------------------- */

#define R_MAX_VARS 32

struct r_var {
	char id[8];
	char name[32];
	unsigned int width;
};

struct r_chg {
	uint64_t t; /* in the file's units */
	int var;
	uint32_t val;
};

struct r_vcd {
	uint64_t unit_fs;
	char scope[32];
	struct r_var var[R_MAX_VARS];
	int nvars;
	struct r_chg *c;
	size_t n, cap;
	int dumpvars;
};

static char *r_slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *buf;
	long n;

	assert_non_null(f);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	n = ftell(f);
	assert_true(n > 0 && n < (64l << 20));
	rewind(f);
	buf = malloc((size_t)n + 1);
	assert_non_null(buf);
	assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
	buf[n] = 0;
	fclose(f);
	*len = (size_t)n;
	return buf;
}

static int r_find(const struct r_vcd *v, const char *id)
{
	for (int i = 0; i < v->nvars; i++)
		if (!strcmp(v->var[i].id, id))
			return i;
	return -1;
}

static int r_var(const struct r_vcd *v, const char *name)
{
	for (int i = 0; i < v->nvars; i++)
		if (!strcmp(v->var[i].name, name))
			return i;
	fail_msg("no variable %s", name);
	return -1;
}

static void r_add(struct r_vcd *v, uint64_t t, int var, uint32_t val)
{
	if (v->n == v->cap) {
		v->cap = v->cap ? 2 * v->cap : 1024;
		v->c = realloc(v->c, v->cap * sizeof(*v->c));
		assert_non_null(v->c);
	}
	v->c[v->n++] = (struct r_chg){ t, var, val };
}

/* Skip to the $end closing a section; returns the token after it. */
static char *r_skip_end(char **save)
{
	char *tok;

	while ((tok = strtok_r(NULL, " \t\r\n", save)))
		if (!strcmp(tok, "$end"))
			return tok;
	fail_msg("section without $end");
	return NULL;
}

static uint64_t r_unit_fs(const char *num, const char *unit)
{
	static const struct {
		const char *name;
		uint64_t fs;
	} u[] = { { "s", 1000000000000000ull },
		  { "ms", 1000000000000ull },
		  { "us", 1000000000ull },
		  { "ns", 1000000ull },
		  { "ps", 1000ull },
		  { "fs", 1ull } };
	uint64_t k = strtoull(num, NULL, 10);

	assert_true(k == 1 || k == 10 || k == 100);
	for (size_t i = 0; i < sizeof(u) / sizeof(u[0]); i++)
		if (!strcmp(unit, u[i].name))
			return k * u[i].fs;
	fail_msg("bad time unit %s", unit);
	return 0;
}

static void r_parse(struct r_vcd *v, const char *path)
{
	size_t len;
	char *buf = r_slurp(path, &len), *save = NULL, *tok;
	int defs_done = 0, in_dumpvars = 0, have_time = 0;
	uint64_t t = 0;

	memset(v, 0, sizeof(*v));
	for (tok = strtok_r(buf, " \t\r\n", &save); tok;
	     tok = strtok_r(NULL, " \t\r\n", &save)) {
		if (!defs_done) {
			if (!strcmp(tok, "$date") || !strcmp(tok, "$version") ||
			    !strcmp(tok, "$comment") ||
			    !strcmp(tok, "$upscope")) {
				r_skip_end(&save);
			} else if (!strcmp(tok, "$timescale")) {
				char *num = strtok_r(NULL, " \t\r\n", &save);
				char *unit = strtok_r(NULL, " \t\r\n", &save);

				assert_non_null(unit);
				v->unit_fs = r_unit_fs(num, unit);
				assert_string_equal(strtok_r(NULL, " \t\r\n",
							     &save),
						    "$end");
			} else if (!strcmp(tok, "$scope")) {
				assert_string_equal(strtok_r(NULL, " \t\r\n",
							     &save),
						    "module");
				snprintf(v->scope, sizeof(v->scope), "%s",
					 strtok_r(NULL, " \t\r\n", &save));
				r_skip_end(&save);
			} else if (!strcmp(tok, "$var")) {
				struct r_var *x = &v->var[v->nvars++];

				assert_true(v->nvars <= R_MAX_VARS);
				assert_string_equal(strtok_r(NULL, " \t\r\n",
							     &save),
						    "wire");
				x->width = (unsigned int)strtoul(
					strtok_r(NULL, " \t\r\n", &save), NULL,
					10);
				assert_true(x->width >= 1 && x->width <= 32);
				snprintf(x->id, sizeof(x->id), "%s",
					 strtok_r(NULL, " \t\r\n", &save));
				snprintf(x->name, sizeof(x->name), "%s",
					 strtok_r(NULL, " \t\r\n", &save));
				r_skip_end(&save);
			} else if (!strcmp(tok, "$enddefinitions")) {
				r_skip_end(&save);
				defs_done = 1;
			} else {
				fail_msg("unexpected header token %s", tok);
			}
			continue;
		}
		if (tok[0] == '#') {
			uint64_t nt = strtoull(tok + 1, NULL, 10);

			/* times strictly increase */
			assert_true(!have_time || nt > t);
			t = nt;
			have_time = 1;
		} else if (!strcmp(tok, "$dumpvars")) {
			assert_true(have_time);
			in_dumpvars = 1;
			v->dumpvars++;
		} else if (!strcmp(tok, "$end")) {
			assert_true(in_dumpvars);
			in_dumpvars = 0;
		} else if (tok[0] == 'b') {
			char *id = strtok_r(NULL, " \t\r\n", &save);
			int k = r_find(v, id ? id : "");
			uint32_t val = 0;

			assert_true(k >= 0 && have_time);
			assert_true(strlen(tok + 1) <= v->var[k].width);
			for (const char *p = tok + 1; *p; p++) {
				assert_true(*p == '0' || *p == '1');
				val = val << 1 | (uint32_t)(*p - '0');
			}
			r_add(v, t, k, val);
		} else if (tok[0] == '0' || tok[0] == '1') {
			int k = r_find(v, tok + 1);

			assert_true(k >= 0 && have_time);
			assert_int_equal(v->var[k].width, 1);
			r_add(v, t, k, (uint32_t)(tok[0] - '0'));
		} else {
			fail_msg("unexpected token %s", tok);
		}
	}
	assert_true(defs_done);
	assert_int_equal(v->dumpvars, 1);
	free(buf);
}

/* Times (in ns) at which `name` changes to `val`. */
static size_t r_edges(const struct r_vcd *v, const char *name, uint32_t val,
		      uint64_t *out, size_t cap)
{
	int k = r_var(v, name);
	size_t n = 0;
	uint32_t cur = UINT32_MAX;

	for (size_t i = 0; i < v->n; i++) {
		if (v->c[i].var != k)
			continue;
		if (v->c[i].val == val && cur != val && cur != UINT32_MAX &&
		    n < cap)
			out[n++] = v->c[i].t * v->unit_fs / FS_PER_NS;
		cur = v->c[i].val;
	}
	return n;
}

static void r_free(struct r_vcd *v)
{
	free(v->c);
}

/* TE's rising edges are exactly one frame apart, from `from` on. */
static void check_te_period(const struct r_vcd *v, uint64_t frame_ns,
			    size_t from, size_t min_edges)
{
	uint64_t up[64];
	size_t n = r_edges(v, "te", 1, up, 64);

	assert_true(n >= min_edges);
	for (size_t i = from + 1; i < n; i++)
		assert_int_equal(up[i] - up[i - 1], frame_ns);
}

/* ---- scenes ------------------------------------------------------------ */

static uint64_t frame_cycles(const struct rdc_timing *t)
{
	return (uint64_t)t->v_total * t->h_total * CORE_HZ /
	       ((uint64_t)t->pixclk_khz * 1000);
}

/*
 * A tiny mode: 40 pixels a line at 10 MHz (400 cycles), 12 lines (4800
 * cycles a frame, 8 visible); hblank 32 pixels (320 cycles) into a line.
 */
static const struct rdc_timing tiny = {
	.h_total = 40,
	.h_display = 32,
	.h_sync_start = 34,
	.h_sync_end = 36,
	.v_total = 12,
	.v_display = 8,
	.v_sync_start = 9,
	.v_sync_end = 10,
	.pixclk_khz = 10000,
};

static void set_timing(rdc_dev *dev, const struct rdc_timing *t)
{
	static const uint32_t regs[] = {
		RDC_REG_H_TOTAL,      RDC_REG_H_DISPLAY,  RDC_REG_H_SYNC_START,
		RDC_REG_H_SYNC_END,   RDC_REG_V_TOTAL,	  RDC_REG_V_DISPLAY,
		RDC_REG_V_SYNC_START, RDC_REG_V_SYNC_END, RDC_REG_PIXCLK_KHZ,
	};
	const uint32_t vals[] = { t->h_total,	   t->h_display,
				  t->h_sync_start, t->h_sync_end,
				  t->v_total,	   t->v_display,
				  t->v_sync_start, t->v_sync_end,
				  t->pixclk_khz };

	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL, RDC_CONTROL_DP_EN),
			 0);
	for (size_t i = 0; i < sizeof(regs) / sizeof(regs[0]); i++)
		assert_int_equal(rdc_reg_write(dev, regs[i], vals[i]), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_FORMAT, RDC_FMT_I8), 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_FB_STRIDE, t->h_display),
			 0);
	/* scanout on: the new mode and a frame start now */
	assert_int_equal(rdc_reg_write(dev, RDC_REG_CONTROL,
				       RDC_CONTROL_DP_EN |
					       RDC_CONTROL_SCANOUT_EN),
			 0);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_ALL),
			 0);
}

static void run_script(rdc_dev *dev, const char *text)
{
	static struct rdc_script_result res;
	int ret = rdc_script_run(dev, text, strlen(text), &res);

	if (ret)
		fail_msg("script: %s (line %u: %s)", rdc_strerror(ret),
			 res.error_line, res.error_msg);
}

/* The golden scene: IRQ edges, drawing (DP, FIFO), BL_EN, a few frames. */
static void tiny_scene(const char *path)
{
	rdc_dev *dev;
	rdc_vcd *vcd;

	assert_int_equal(setenv("SOURCE_DATE_EPOCH", "0", 1), 0);
	assert_int_equal(rdc_open("sim:", &dev), 0);
	set_timing(dev, &tiny);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK),
			 0);
	assert_int_equal(rdc_vcd_open(dev, path, &vcd), 0);
	run_script(dev, "step 1000\n"
			"dst 0 32 32 8 i8\n"
			"fg 5\n"
			"fill 0 0 32 8\n"
			"fill 4 2 8 4\n"
			"finish\n"
			"vsync\n"
			"reg IRQ_STATUS 1\n"
			"step 700\n");
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, 0), 0);
	run_script(dev, "step 2500\n");
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, RDC_PIN_BL_EN), 0);
	run_script(dev, "vsync\nvsync\nstep 123\n");
	assert_int_equal(rdc_vcd_close(vcd), 0);
	rdc_close(dev);
}

static void tmp_path(char *buf, size_t cap, const char *what)
{
	snprintf(buf, cap, "/tmp/rdc-vcd-%s-%d.vcd", what, (int)getpid());
}

/* ---- tests --------------------------------------------------------------- */

/* RDC_VCD_REGEN: the new golden file, put in place once all passed. */
static char regen_path[128];

static const char *golden(void)
{
	const char *g = getenv("RDC_VCD_GOLDEN");

	return g && *g ? g : GOLDEN;
}

static void test_golden(void **state)
{
	char path[128];
	size_t a_len, b_len;
	char *a, *b;

	(void)state;
	tmp_path(path, sizeof(path), "tiny");
	tiny_scene(path);
	if (getenv("RDC_VCD_REGEN")) {
		/* kept aside: main() puts it in place if nothing fails */
		tmp_path(regen_path, sizeof(regen_path), "regen");
		assert_int_equal(rename(path, regen_path), 0);
		return;
	}
	a = r_slurp(path, &a_len);
	b = r_slurp(golden(), &b_len);
	if (a_len != b_len || memcmp(a, b, a_len))
		fail_msg("%s differs from %s (RDC_VCD_REGEN=1 rewrites it)",
			 path, golden());
	free(a);
	free(b);
	unlink(path);
}

/*
 * RDC_VCD_REGEN: the new file replaces the golden one only when every
 * test passed (the writer read back, the front ends run); else it is
 * dropped and the golden file stays as it was.
 */
static int regen_finish(int failed)
{
	char cmd[512];

	if (!regen_path[0])
		return failed;
	if (failed) {
		fprintf(stderr,
			"RDC_VCD_REGEN: %s not rewritten: %d test(s) failed\n",
			golden(), failed);
		unlink(regen_path);
		return failed;
	}
	/* cp, not rename: /tmp and the tree may be different filesystems */
	snprintf(cmd, sizeof(cmd), "cp %s %s", regen_path, golden());
	if (system(cmd)) {
		fprintf(stderr, "RDC_VCD_REGEN: cannot write %s\n", golden());
		unlink(regen_path);
		return 1;
	}
	unlink(regen_path);
	printf("RDC_VCD_REGEN: wrote %s\n", golden());
	return 0;
}

/* The tiny scene read back: every signal where the timing puts it. */
static void test_read_back(void **state)
{
	const uint64_t frame_ns = frame_cycles(&tiny) * NS_PER_CYCLE;
	const uint64_t line_ns = frame_ns / tiny.v_total;
	const uint64_t hoff_ns = 320 * NS_PER_CYCLE; /* 32 px at 10 cycles */
	uint64_t te_up[16], te_dn[16], vb_up[16], vb_dn[16], hb[256];
	uint64_t bl_dn[4], bl_up[4], irq_up[8], irq_dn[8], dp_up[8], dp_dn[8];
	size_t n_up, n_dn, n_hb, lines = 0;
	struct r_vcd v;
	char path[128];
	int line;

	(void)state;
	tmp_path(path, sizeof(path), "read");
	tiny_scene(path);
	r_parse(&v, path);
	assert_string_equal(v.scope, "rdc1");
	assert_int_equal(v.unit_fs, FS_PER_NS);
	assert_int_equal(v.var[r_var(&v, "fifo_level")].width, 9);
	assert_int_equal(v.var[r_var(&v, "line")].width, 12);

	check_te_period(&v, frame_ns, 0, 3);
	n_up = r_edges(&v, "te", 1, te_up, 16);
	n_dn = r_edges(&v, "te", 0, te_dn, 16);
	/* vblank is TE, edge for edge */
	assert_int_equal(r_edges(&v, "vblank", 1, vb_up, 16), n_up);
	assert_int_equal(r_edges(&v, "vblank", 0, vb_dn, 16), n_dn);
	assert_memory_equal(te_up, vb_up, n_up * sizeof(*te_up));
	assert_memory_equal(te_dn, vb_dn, n_dn * sizeof(*te_dn));
	/* TE rises V_DISPLAY lines into a frame, falls at the next start */
	for (size_t i = 0; i < n_dn; i++)
		assert_int_equal(te_dn[i] - te_up[i],
				 (tiny.v_total - tiny.v_display) * line_ns);

	/* one line change a line, and hblank 32 pixels into each */
	line = r_var(&v, "line");
	n_hb = r_edges(&v, "hblank", 1, hb, 256);
	for (size_t i = 0, h = 0; i < v.n; i++) {
		uint64_t t = v.c[i].t * v.unit_fs / FS_PER_NS;

		if (v.c[i].var != line || t < te_dn[0] || t >= te_dn[1])
			continue;
		lines++;
		while (h < n_hb && hb[h] < t)
			h++;
		assert_true(h < n_hb);
		assert_int_equal(hb[h], t + hoff_ns);
	}
	assert_int_equal(lines, tiny.v_total);

	/* the inputs and the interrupt line, as the scene drove them */
	assert_int_equal(r_edges(&v, "bl_en", 0, bl_dn, 4), 1);
	assert_int_equal(r_edges(&v, "bl_en", 1, bl_up, 4), 1);
	assert_int_equal(bl_up[0] - bl_dn[0], 2500 * NS_PER_CYCLE);
	/* VBLANK is enabled: up with TE, down at the W1C, up again */
	assert_int_equal(r_edges(&v, "irq", 1, irq_up, 8), 2);
	assert_int_equal(r_edges(&v, "irq", 0, irq_dn, 8), 1);
	assert_int_equal(irq_up[0], te_up[0]);
	assert_true(irq_dn[0] > irq_up[0] && irq_dn[0] < te_up[1]);
	assert_int_equal(irq_up[1], te_up[1]);
	/*
	 * The DP works in spans as the library feeds the FIFO, each span
	 * after words came, and ends idle.
	 */
	n_up = r_edges(&v, "dp_busy", 1, dp_up, 8);
	assert_true(n_up >= 1 && n_up < 8);
	assert_int_equal(r_edges(&v, "dp_busy", 0, dp_dn, 8), n_up);
	for (size_t i = 0; i < n_up; i++)
		assert_true(dp_dn[i] > dp_up[i]);
	r_free(&v);
	unlink(path);
}

/* 320x200@70 for a few frames through rdcctl run --vcd. */
static const char te_scene[] = "mode 320x200 i8\n"
			       "vsync\n"
			       "fg 3\n"
			       "fill 0 0 320 200\n"
			       "vsync\nvsync\nvsync\nvsync\n";

static int sh(const char *cmd, char *out, size_t cap)
{
	FILE *p = popen(cmd, "r");
	size_t n;
	int st;

	assert_non_null(p);
	n = fread(out, 1, cap - 1, p);
	out[n] = 0;
	st = pclose(p);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void write_file(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	assert_non_null(f);
	assert_int_equal(fputs(text, f) >= 0, 1);
	assert_int_equal(fclose(f), 0);
}

static uint64_t preset_frame_cycles(uint32_t preset)
{
	struct rdc_timing t;

	assert_int_equal(rdc_preset_timing(preset, &t), 0);
	return frame_cycles(&t);
}

static void rdcctl_vcd(char *path, size_t cap)
{
	char script[128], cmd[8192], out[4096];
	int rc;

	tmp_path(script, sizeof(script), "scene");
	write_file(script, te_scene);
	tmp_path(path, cap, "ctl");
	snprintf(cmd, sizeof(cmd), "%s/rdcctl run %s --vcd %s 2>&1", bindir,
		 script, path);
	rc = sh(cmd, out, sizeof(out));
	if (rc)
		fail_msg("rdcctl: %d: %s", rc, out);
	unlink(script);
}

static void test_rdcctl_te_period(void **state)
{
	char path[128];
	struct r_vcd v;

	(void)state;
	rdcctl_vcd(path, sizeof(path));
	r_parse(&v, path);
	/* the first frame is power-on's 640x480: periods from the second */
	check_te_period(
		&v, preset_frame_cycles(RDC_PRESET_320x200_70) * NS_PER_CYCLE,
		1, 5);
	r_free(&v);
	unlink(path);
}

/*
 * sigrok-cli reads the file and measures TE.  libsigrok 0.5's VCD input
 * stops at the first multi-bit value ("Unexpected vector format"), so it
 * gets a copy without the vector changes (fifo_level, line); the 1-bit
 * signals are untouched.  downsample=10: one sample a core cycle.
 */
static void test_sigrok_te_period(void **state)
{
	const uint64_t frame = preset_frame_cycles(RDC_PRESET_320x200_70);
	char path[128], bits[128], cmd[512], out[8192], line[512];
	unsigned long long a, b, prev_end = 0;
	int periods = 0;
	FILE *in, *o;
	char *p;

	(void)state;
	if (sh("command -v sigrok-cli >/dev/null 2>&1", out, sizeof(out))) {
		print_message("sigrok-cli not installed (scripts/deps.sh "
			      "installs it): skipped\n");
		skip();
	}
	rdcctl_vcd(path, sizeof(path));
	tmp_path(bits, sizeof(bits), "bits");
	in = fopen(path, "r");
	o = fopen(bits, "w");
	assert_non_null(in);
	assert_non_null(o);
	while (fgets(line, sizeof(line), in))
		if (line[0] != 'b')
			fputs(line, o);
	fclose(in);
	assert_int_equal(fclose(o), 0);
	snprintf(cmd, sizeof(cmd),
		 "sigrok-cli -I vcd:downsample=10 -i %s -P "
		 "timing:data=te:edge=rising -A timing=time "
		 "--protocol-decoder-samplenum 2>&1",
		 bits);
	assert_int_equal(sh(cmd, out, sizeof(out)), 0);
	/*
	 * "START-END timing-1: 14.286 ms (70.000 Hz)", one a period; the
	 * first spans the switch from power-on's 640x480 and is not checked.
	 */
	for (p = out; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL) {
		if (sscanf(p, "%llu-%llu", &a, &b) != 2)
			continue;
		if (prev_end) {
			assert_int_equal(a, prev_end);
			assert_int_equal(b - a, frame);
			periods++;
		}
		prev_end = b;
	}
	if (periods < 3)
		fail_msg("sigrok-cli measured %d periods: %s", periods, out);
	unlink(bits);
	unlink(path);
}

/* A power cycle of rdcd's chip, then `cycles` of the new one. */
static void power_cycle_and_run(const struct netd *d, uint64_t cycles)
{
	uint8_t b[16];
	int fd = netd_connect(d->sock);

	assert_true(fd >= 0);
	assert_int_equal(netd_hello(fd, RDC_HELLO_CONTROL, NULL, NULL),
			 RDC_ST_OK);
	rdc_proto_put32(b, RDC_RESET_POWER);
	assert_int_equal(netd_call(fd, RDC_MSG_RESET, 2, b, 4, NULL, 0),
			 RDC_ST_OK);
	rdc_proto_put64(b, cycles);
	assert_int_equal(netd_call(fd, RDC_MSG_STEP, 3, b, 8, NULL, 0),
			 RDC_ST_OK);
	close(fd);
}

/*
 * rdcd --vcd: a stepped daemon's waits, a power cycle, then the file;
 * rdcctl's refusal.
 */
static void test_rdcd_vcd(void **state)
{
	char path[128], script[128], cmd[8192], out[4096];
	const char *args[] = { "--stepped", "-q", "--vcd", path, NULL };
	rdc_dev *dev;
	struct netd d;
	struct r_vcd v;

	(void)state;
	tmp_path(path, sizeof(path), "rdcd");
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(
		rdc_mode_set(dev, RDC_PRESET_320x200_70, RDC_FMT_I8, 0), 0);
	for (int i = 0; i < 5; i++)
		assert_int_equal(rdc_frame_wait(dev), 0);
	rdc_close(dev);

	/* rdcctl --vcd wants the simulator in its own process */
	tmp_path(script, sizeof(script), "scene2");
	write_file(script, te_scene);
	snprintf(cmd, sizeof(cmd),
		 "%s/rdcctl --connect %s run %s --vcd %s.x 2>&1", bindir,
		 d.unix_uri, script, path);
	assert_int_equal(sh(cmd, out, sizeof(out)), 1);
	assert_non_null(strstr(out, "--vcd needs a sim: device"));
	unlink(script);
	power_cycle_and_run(&d, 4 * preset_frame_cycles(RDC_PRESET_640x480_60));

	assert_int_equal(netd_stop(&d), 0);
	r_parse(&v, path);
	{
		const uint64_t f320 =
			preset_frame_cycles(RDC_PRESET_320x200_70) *
			NS_PER_CYCLE;
		const uint64_t f640 =
			preset_frame_cycles(RDC_PRESET_640x480_60) *
			NS_PER_CYCLE;
		uint64_t up[64];
		size_t n = r_edges(&v, "te", 1, up, 64), i;

		/*
		 * 640x480 at power-on, 320x200 from the mode switch, then
		 * the new chip's 640x480 in the same file, its time going on
		 * (the reader checked that times only increase).
		 */
		assert_true(n >= 9);
		for (i = 2; i + 1 < n && up[i + 1] - up[i] == f320; i++)
			;
		assert_true(i >= 5);
		assert_int_equal(up[n - 1] - up[n - 2], f640);
		assert_int_equal(up[n - 2] - up[n - 3], f640);
	}
	r_free(&v);
	unlink(path);
}

/* Library errors: not sim:, a file that cannot be made. */
static void test_errors(void **state)
{
	rdc_dev *dev;
	rdc_vcd *vcd = NULL;

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	assert_int_equal(rdc_vcd_open(dev, "/nonexistent-dir/x.vcd", &vcd),
			 RDC_E_FILE);
	assert_null(vcd);
	assert_int_equal(rdc_vcd_open(dev, NULL, &vcd), RDC_E_INVAL);
	assert_int_equal(rdc_vcd_close(NULL), 0);
	rdc_close(dev);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_golden),
		cmocka_unit_test(test_read_back),
		cmocka_unit_test(test_rdcctl_te_period),
		cmocka_unit_test(test_sigrok_te_period),
		cmocka_unit_test(test_rdcd_vcd),
		cmocka_unit_test(test_errors),
	};
	char self[4096];

	(void)argc;
	/* rdcctl and rdcd are built next to the tests: $(O)/san */
	snprintf(self, sizeof(self), "%s", argv[0]);
	snprintf(bindir, sizeof(bindir), "%s/..", dirname(self));
	return regen_finish(cmocka_run_group_tests(tests, NULL, NULL));
}
