// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The reference docs against the code, mechanically: every register row of
 * docs/hardware.md against rdc_regs.h (offset, name, access) and librdc's
 * register names; every opcode of rdc_regs.h in docs/commands.md with the
 * same number; the device error codes, formats and presets of
 * docs/hardware.md; the status codes, message types and the statuses that
 * close a connection of docs/protocol.md against rdc_proto.h; every .rdl
 * statement of docs/rdl.md's tables known to the interpreter and every
 * statement it knows documented, with argument counts that fit; the names
 * rdl.md calls case-insensitive; the options of `rdcd --help` and
 * `rdcctl --help` in the synopses of docs/protocol.md and docs/rdl.md;
 * every named constant the docs give a number for (`RDC_X` (N)) against
 * its #define; and the README's C example compiling as the README says.
 *
 * Run from the source root (tests/run.sh does); rdcd and rdcctl are found
 * next to this test's directory ($(O)/san).
 */
#include <ctype.h>
#include <dirent.h>
#include <libgen.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "hw.h"
#include "rdc.h"
#include "rdc_proto.h"
#include "script.h"

static char bindir[400];

/* A whole file, NUL-terminated. */
static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *s = NULL;
	long n;

	if (!f)
		fail_msg("cannot open %s (run from the source root)", path);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	n = ftell(f);
	assert_true(n > 0);
	rewind(f);
	s = malloc((size_t)n + 1);
	assert_non_null(s);
	assert_int_equal(fread(s, 1, (size_t)n, f), (size_t)n);
	s[n] = 0;
	fclose(f);
	return s;
}

/* The text from `from` up to (not including) `to`, or to the end. */
static char *section(const char *text, const char *from, const char *to)
{
	const char *a = strstr(text, from), *b;
	char *s;

	if (!a)
		fail_msg("no '%s' in the document", from);
	b = to ? strstr(a + strlen(from), to) : NULL;
	if (!b)
		b = a + strlen(a);
	s = strndup(a, (size_t)(b - a));
	assert_non_null(s);
	return s;
}

/* The next line of *p (without its newline) into buf; false at the end. */
static bool next_line(const char **p, char *buf, size_t cap)
{
	const char *s = *p, *nl;
	size_t n;

	if (!*s)
		return false;
	nl = strchr(s, '\n');
	n = nl ? (size_t)(nl - s) : strlen(s);
	if (n >= cap)
		n = cap - 1;
	memcpy(buf, s, n);
	buf[n] = 0;
	*p = nl ? nl + 1 : s + strlen(s);
	return true;
}

/* Table cell k (0 = the first after the leading '|'), trimmed; a '|'
 * escaped as "\|" stays in the cell. */
static bool cell(const char *row, int k, char *out, size_t cap)
{
	const char *p = row;
	size_t n = 0;

	if (*p != '|')
		return false;
	p++;
	for (int i = 0; i < k; i++) {
		while (*p && !(*p == '|' && p[-1] != '\\'))
			p++;
		if (!*p)
			return false;
		p++;
	}
	while (*p == ' ')
		p++;
	while (*p && !(*p == '|' && p[-1] != '\\') && n + 1 < cap)
		out[n++] = *p++;
	if (!*p)
		return false;
	while (n && out[n - 1] == ' ')
		n--;
	out[n] = 0;
	return true;
}

static bool is_name(int c)
{
	return isupper(c) || isdigit(c) || c == '_';
}

/* ---- Registers ----------------------------------------------------------- */

#define MAX_REGS 128

struct reg {
	char name[32];
	uint32_t off;
	char access[8];
};

/* "#define RDC_REG_NAME 0xOFF" with its access from the comment on the
 * line or from the first word of the block comment above it. */
static size_t header_regs(struct reg *r)
{
	char *h = slurp("hw-sim/rdc_regs.h");
	const char *p = h, *block = NULL;
	char line[256], prev[256] = "";
	size_t n = 0;

	for (; next_line(&p, line, sizeof(line)); strcpy(prev, line)) {
		const char *s = line + strlen("#define RDC_REG_");
		char *end;
		size_t k = 0;

		if (!strncmp(line, "/*", 2) && !strstr(line, "*/"))
			block = p; /* the block's first text line follows */
		if (strncmp(line, "#define RDC_REG_", 16))
			continue;
		while (is_name(s[k]))
			k++;
		if (strncmp(s + k, " 0x", 3))
			continue;
		assert_true(n < MAX_REGS);
		assert_true(k < sizeof(r[n].name));
		memcpy(r[n].name, s, k);
		r[n].name[k] = 0;
		r[n].off = (uint32_t)strtoul(s + k + 1, &end, 16);
		if (*end && *end != ' ' && *end != '\t')
			continue; /* RDC_REG_WINDOW 0x400u: not a register */
		while (*end == ' ' || *end == '\t')
			end++;
		if (!strncmp(end, "/*", 2)) {
			sscanf(end + 2, "%7s", r[n].access);
		} else if (!strncmp(prev, "/*", 2)) { /* one line above */
			sscanf(prev + 2, "%7s", r[n].access);
		} else {
			char first[256];

			assert_non_null(block);
			assert_true(next_line(&block, first, sizeof(first)));
			assert_int_equal(sscanf(first, " * %7s", r[n].access),
					 1);
		}
		n++;
	}
	free(h);
	return n;
}

/* hardware.md's register table; a row "0xA-0xB | N1, N2, ..." is
 * consecutive registers. */
static size_t doc_regs(struct reg *r)
{
	char *doc = slurp("docs/hardware.md");
	char *tab = section(doc, "## Registers", "\n## ");
	const char *p = tab;
	char line[1024], c0[64], c1[512], c2[64];
	size_t n = 0;

	while (next_line(&p, line, sizeof(line))) {
		char *name, *save = NULL;
		uint32_t off;

		if (strncmp(line, "| 0x", 4) ||
		    !cell(line, 0, c0, sizeof(c0)) ||
		    !cell(line, 1, c1, sizeof(c1)) ||
		    !cell(line, 2, c2, sizeof(c2)))
			continue;
		off = (uint32_t)strtoul(c0, NULL, 16);
		for (name = strtok_r(c1, ", ", &save); name;
		     name = strtok_r(NULL, ", ", &save)) {
			assert_true(n < MAX_REGS);
			snprintf(r[n].name, sizeof(r[n].name), "%s", name);
			r[n].off = off;
			sscanf(c2, "%7s", r[n].access);
			off += 4;
			n++;
		}
		if (strchr(c0, '-'))
			assert_int_equal(off - 4, strtoul(strchr(c0, '-') + 1,
							  NULL, 16));
	}
	free(tab);
	free(doc);
	return n;
}

static const struct reg *find_reg(const struct reg *r, size_t n,
				  const char *name)
{
	for (size_t i = 0; i < n; i++)
		if (!strcmp(r[i].name, name))
			return &r[i];
	return NULL;
}

static void test_registers(void **state)
{
	static struct reg hr[MAX_REGS], dr[MAX_REGS];
	size_t nh = header_regs(hr), nd = doc_regs(dr);

	(void)state;
	assert_true(nh > 50);
	for (size_t i = 0; i < nh; i++) {
		const struct reg *d = find_reg(dr, nd, hr[i].name);
		uint32_t off = 0;

		if (!d)
			fail_msg("register %s is not in docs/hardware.md",
				 hr[i].name);
		if (d->off != hr[i].off || strcmp(d->access, hr[i].access))
			fail_msg("%s: rdc_regs.h 0x%03x %s, hardware.md "
				 "0x%03x %s",
				 hr[i].name, hr[i].off, hr[i].access, d->off,
				 d->access);
		/* librdc's names (rdcctl regs, .rdl) are the same */
		assert_int_equal(rdc_reg_by_name(hr[i].name, &off), 0);
		assert_int_equal(off, hr[i].off);
	}
	for (size_t i = 0; i < nd; i++)
		if (!find_reg(hr, nh, dr[i].name))
			fail_msg("hardware.md names %s, rdc_regs.h does not",
				 dr[i].name);
	for (size_t i = 0; i < rdc_reg_count(); i++)
		if (!find_reg(hr, nh, rdc_reg_info(i, NULL)))
			fail_msg("librdc names %s, rdc_regs.h does not",
				 rdc_reg_info(i, NULL));
	assert_int_equal(rdc_reg_count(), nh);
}

/* ---- Opcodes ------------------------------------------------------------- */

static void test_opcodes(void **state)
{
	char *h = slurp("hw-sim/rdc_regs.h");
	char *doc = slurp("docs/commands.md");
	static uint8_t in_header[256];
	const char *p;
	int n = 0;

	(void)state;
	/* "RDC_OP_NAME = 0xNN": named in commands.md with that number, as
	 * `RDC_OP_NAME` 0xNN or (the 3D tables) `NAME` 0xNN */
	for (p = strstr(h, "RDC_OP_"); p; p = strstr(p + 1, "RDC_OP_")) {
		char name[40], want[64], want3[64];
		unsigned int v;
		size_t k = 0;

		while (is_name(p[7 + k]) && k + 1 < sizeof(name)) {
			name[k] = p[7 + k];
			k++;
		}
		name[k] = 0;
		if (sscanf(p + 7 + k, " = 0x%x", &v) != 1 ||
		    !strcmp(name, "COUNT"))
			continue;
		assert_true(v < 256);
		in_header[v] = 1;
		n++;
		snprintf(want, sizeof(want), "`RDC_OP_%s` 0x%02x", name, v);
		snprintf(want3, sizeof(want3), "`%s` 0x%02x", name, v);
		if (!strstr(doc, want) && !strstr(doc, want3))
			fail_msg(
				"commands.md does not give RDC_OP_%s as 0x%02x",
				name, v);
		if (!rdc_op_name(v))
			fail_msg("RDC_OP_%s 0x%02x has no .rdl name", name, v);
	}
	assert_true(n > 60);
	/* no opcode the header does not have */
	for (unsigned int v = 0; v < 256; v++)
		if (!in_header[v] && rdc_op_name(v))
			fail_msg("rdc_op_name(0x%02x) = %s, not in rdc_regs.h",
				 v, rdc_op_name(v));
	/* every "`RDC_OP_X` 0xNN" in commands.md agrees with the header */
	for (p = strstr(doc, "`RDC_OP_"); p; p = strstr(p + 1, "`RDC_OP_")) {
		char name[40], def[64];
		unsigned int v;
		const char *q;
		size_t k = 0;

		while (is_name(p[8 + k]) && k + 1 < sizeof(name)) {
			name[k] = p[8 + k];
			k++;
		}
		name[k] = 0;
		if (sscanf(p + 8 + k, "` 0x%x", &v) != 1)
			continue;
		snprintf(def, sizeof(def), "RDC_OP_%s = 0x%02x,", name, v);
		q = strstr(h, def);
		if (!q)
			fail_msg("commands.md: RDC_OP_%s 0x%02x is not in "
				 "rdc_regs.h",
				 name, v);
	}
	free(doc);
	free(h);
}

/* ---- Device errors, formats, presets --------------------------------- */

static void test_device_errors(void **state)
{
	char *h = slurp("hw-sim/rdc_regs.h");
	char *doc = slurp("docs/hardware.md");
	char *tab = section(doc, "## Errors", "\n## ");
	const char *p = tab;
	char line[512], c0[16], c1[64];
	int rows = 0;

	(void)state;
	while (next_line(&p, line, sizeof(line))) {
		char def[80];
		unsigned int v;

		if (!cell(line, 0, c0, sizeof(c0)) ||
		    sscanf(c0, "%u", &v) != 1 || !cell(line, 1, c1, sizeof(c1)))
			continue;
		snprintf(def, sizeof(def), "RDC_ERR_%s = %u,", c1, v);
		if (!strstr(h, def))
			fail_msg("hardware.md: error %u %s is not rdc_regs.h's",
				 v, c1);
		assert_string_equal(rdc_dev_strerror(v), c1);
		rows++;
	}
	/* and the table has every code from 1 to the last */
	assert_int_equal(rows, RDC_ERR_COUNT - 1);
	assert_string_equal(rdc_dev_strerror(RDC_ERR_COUNT), "UNKNOWN");
	free(tab);
	free(doc);
	free(h);
}

static void test_formats_and_presets(void **state)
{
	char *doc = slurp("docs/hardware.md");
	char *fmt = section(doc, "### Formats", "\n### ");
	char *pre = section(doc, "| preset | mode |", "\n\n");
	const char *p = fmt;
	char line[512], c[5][128];
	int rows = 0;

	(void)state;
	while (next_line(&p, line, sizeof(line))) {
		unsigned int v, bits;
		char lower[16];

		if (!cell(line, 0, c[0], sizeof(c[0])) ||
		    sscanf(c[0], "%u", &v) != 1 ||
		    !cell(line, 1, c[1], sizeof(c[1])) ||
		    !cell(line, 2, c[2], sizeof(c[2])))
			continue;
		assert_true(v < RDC_FMT_COUNT);
		assert_int_equal(sscanf(c[2], "%u", &bits), 1);
		assert_int_equal(bits, rdc_format_bpp(v));
		for (size_t k = 0; k < sizeof(lower); k++) {
			lower[k] = (char)tolower((unsigned char)c[1][k]);
			if (!lower[k])
				break;
		}
		lower[sizeof(lower) - 1] = 0;
		assert_string_equal(lower, rdl_fmt_names[v]);
		rows++;
	}
	assert_int_equal(rows, RDC_FMT_COUNT);

	rows = 0;
	p = pre;
	while (next_line(&p, line, sizeof(line))) {
		struct rdc_timing t;
		unsigned int v, mhz, frac = 0, hv[4], vv[4], w, h;
		char sfrac[8] = "";

		if (!cell(line, 0, c[0], sizeof(c[0])) ||
		    sscanf(c[0], "%u", &v) != 1)
			continue;
		for (int k = 1; k < 5; k++)
			assert_true(cell(line, k, c[k], sizeof(c[k])));
		assert_int_equal(rdc_preset_timing(v, &t), 0);
		assert_int_equal(sscanf(c[1], "%ux%u", &w, &h), 2);
		assert_int_equal(w, t.h_display);
		assert_int_equal(h, t.v_display);
		/* "25.175 MHz" */
		assert_true(sscanf(c[2], "%u.%7[0-9]", &mhz, sfrac) >= 1);
		for (size_t k = 0; k < 3; k++)
			frac = frac * 10 +
			       (k < strlen(sfrac) ?
					(unsigned int)(sfrac[k] - '0') :
					0);
		assert_int_equal(mhz * 1000 + frac, t.pixclk_khz);
		assert_int_equal(sscanf(c[3], "%u/%u/%u/%u", &hv[0], &hv[1],
					&hv[2], &hv[3]),
				 4);
		assert_int_equal(sscanf(c[4], "%u/%u/%u/%u", &vv[0], &vv[1],
					&vv[2], &vv[3]),
				 4);
		assert_int_equal(hv[0], t.h_display);
		assert_int_equal(hv[1], t.h_sync_start);
		assert_int_equal(hv[2], t.h_sync_end);
		assert_int_equal(hv[3], t.h_total);
		assert_int_equal(vv[0], t.v_display);
		assert_int_equal(vv[1], t.v_sync_start);
		assert_int_equal(vv[2], t.v_sync_end);
		assert_int_equal(vv[3], t.v_total);
		rows++;
	}
	assert_int_equal(rows, RDC_PRESET_COUNT);
	free(pre);
	free(fmt);
	free(doc);
}

/* ---- The wire protocol --------------------------------------------------- */

/* "RDC_<pfx>NAME = N," of rdc_proto.h; -1 if there is none. */
static int proto_value(const char *h, const char *pfx, const char *name)
{
	char def[64];
	const char *p;
	int v;

	snprintf(def, sizeof(def), "RDC_%s%s = ", pfx, name);
	p = strstr(h, def);
	if (!p || sscanf(p + strlen(def), "%d", &v) != 1)
		return -1;
	return v;
}

static void test_protocol(void **state)
{
	char *h = slurp("userspace/include/rdc_proto.h");
	char *doc = slurp("docs/protocol.md");
	char *st = section(doc, "### Status codes", "librdc turns");
	char *cl = section(doc, "closes the connection after", "\n\n");
	char line[512], c0[64], name[32];
	const char *p;
	int n = 0, v, off;
	uint32_t named = 0;

	(void)state;
	/* "0 OK, 1 INVAL, ...": every code, in the header's numbers */
	for (p = st; *p; p++) {
		if (!isdigit((unsigned char)*p) ||
		    sscanf(p, "%d %31[A-Z]%n", &v, name, &off) != 2)
			continue;
		if (proto_value(h, "ST_", name) != v)
			fail_msg("protocol.md: status %d %s, rdc_proto.h %d", v,
				 name, proto_value(h, "ST_", name));
		assert_int_equal(v, n);
		n++;
		p += off - 1;
	}
	assert_int_equal(n, RDC_ST_COUNT_);

	/* the message table: "| N NAME | ..." */
	n = 0;
	p = doc;
	while (next_line(&p, line, sizeof(line))) {
		if (!cell(line, 0, c0, sizeof(c0)) ||
		    sscanf(c0, "%d %31[A-Z_]", &v, name) != 2)
			continue;
		if (proto_value(h, "MSG_", name) != v)
			fail_msg("protocol.md: message %d %s, rdc_proto.h %d",
				 v, name, proto_value(h, "MSG_", name));
		n++;
	}
	assert_int_equal(n, RDC_MSG_REQUEST_LAST + 2); /* and two events */

	/*
	 * The statuses after which the daemon hangs up, by the rule the
	 * daemon closes by (rdc_proto_reply_closes): the paragraph names
	 * them before ORDER, which it names as leaving the connection open;
	 * TOOBIG closes after any request, nothing else but a refused HELLO
	 * does, and a HELLO answered anything but OK or ORDER is refused.
	 */
	*strstr(cl, "ORDER") = 0;
	for (p = cl; *p; p++) {
		if (!isupper((unsigned char)*p) ||
		    sscanf(p, "%31[A-Z]%n", name, &off) != 1)
			continue;
		v = proto_value(h, "ST_", name);
		if (v > RDC_ST_OK) /* "any status but OK" */
			named |= 1u << v;
		p += off - 1;
	}
	for (uint32_t s = 0; s < RDC_ST_COUNT_; s++) {
		if ((named >> s & 1) &&
		    !rdc_proto_reply_closes(RDC_MSG_HELLO, s))
			fail_msg("status %u: protocol.md closes, the code not",
				 s);
		assert_int_equal(rdc_proto_reply_closes(RDC_MSG_HELLO, s),
				 s != RDC_ST_OK && s != RDC_ST_ORDER);
		for (uint32_t t = RDC_MSG_REG_READ; t <= RDC_MSG_REQUEST_LAST;
		     t++)
			assert_int_equal(rdc_proto_reply_closes(t, s),
					 s == RDC_ST_TOOBIG);
	}
	assert_true(named & 1u << RDC_ST_TOOBIG);
	assert_true(named & 1u << RDC_ST_MALFORMED);
	free(cl);
	free(st);
	free(doc);
	free(h);
}

/* ---- .rdl statements ----------------------------------------------------- */

#define MAX_FORMS 256

static size_t rdl_doc_forms(char (*forms)[160])
{
	char *doc = slurp("docs/rdl.md");
	const char *p = doc;
	char line[2048], c0[1024];
	size_t n = 0;

	while (next_line(&p, line, sizeof(line))) {
		const char *q;

		if (strncmp(line, "| `", 3) || !cell(line, 0, c0, sizeof(c0)))
			continue;
		for (q = strchr(c0, '`'); q; q = strchr(q + 1, '`')) {
			const char *e = strchr(q + 1, '`');

			assert_non_null(e);
			assert_true(n < MAX_FORMS);
			snprintf(forms[n], sizeof(forms[n]), "%.*s",
				 (int)(e - q - 1), q + 1);
			n++;
			q = e;
		}
	}
	free(doc);
	return n;
}

static void test_rdl_statements(void **state)
{
	static char forms[MAX_FORMS][160];
	size_t nf = rdl_doc_forms(forms), i;
	uint32_t min, max;
	const char *name;
	rdc_dev *dev;

	(void)state;
	assert_true(nf > 80);
	/* every statement the interpreter knows is in a table */
	for (i = 0; (name = rdl_stmt_info(i, &min, &max)); i++) {
		size_t k, len = strlen(name);

		for (k = 0; k < nf; k++)
			if (!strncmp(forms[k], name, len) &&
			    (!forms[k][len] || forms[k][len] == ' '))
				break;
		if (k == nf)
			fail_msg("statement '%s' is not in docs/rdl.md", name);
	}
	assert_true(i > 80);
	/* every documented keyword is known, and a form without optional
	 * or repeated parts has an argument count the statement takes */
	assert_int_equal(rdc_open("sim:", &dev), 0);
	for (size_t k = 0; k < nf; k++) {
		static struct rdc_script_result res;
		char kw[40];
		size_t words = 0;
		bool simple = !strpbrk(forms[k], "[|.");

		for (const char *q = forms[k]; *q;) {
			while (*q == ' ')
				q++;
			if (!*q)
				break;
			words++;
			while (*q && *q != ' ')
				q++;
		}
		assert_int_equal(sscanf(forms[k], "%39s", kw), 1);
		for (i = 0; (name = rdl_stmt_info(i, &min, &max)); i++)
			if (!strcmp(name, kw))
				break;
		if (!name)
			fail_msg("docs/rdl.md: '%s': no such statement",
				 forms[k]);
		if (simple && (words - 1 < min || words - 1 > max))
			fail_msg("docs/rdl.md: '%s': %zu arguments, the "
				 "statement takes %u to %u",
				 forms[k], words - 1, min, max);
		/* and the interpreter reads it as that statement */
		rdc_script_run(dev, kw, strlen(kw), &res);
		assert_null(strstr(res.error_msg, "unknown statement"));
	}
	rdc_close(dev);
}

/* docs/rdl.md: "Keywords are lower case. Register, format, preset and ROP
 * names are case-insensitive." */
static void test_rdl_names_case(void **state)
{
	static const char ok[] = "mode 720P XRGB8888\n"
				 "mode 1280X720 Rgb565\n"
				 "mode 640X480@60 i8\n"
				 "rop GXCOPY\n"
				 "rop And-Reverse\n"
				 "reg line_compare 5\n"
				 "expect LINE_COMPARE 5\n"
				 "cmd-reg Rdc_Reg_Line_Compare 6\n"
				 "expect line_compare 6\n";
	static struct rdc_script_result res;
	rdc_dev *dev;

	(void)state;
	assert_int_equal(rdc_open("sim:", &dev), 0);
	if (rdc_script_run(dev, ok, strlen(ok), &res))
		fail_msg("line %u: %s", res.error_line, res.error_msg);
	assert_int_equal(rdc_script_run(dev, "FILL 0 0 1 1", 12, &res),
			 RDC_E_PARSE);
	assert_non_null(strstr(res.error_msg, "unknown statement"));
	rdc_close(dev);
}

/* ---- Command-line options ------------------------------------------------ */

/* `prog --help`'s output into out. */
static void help_text(const char *prog, char *out, size_t cap)
{
	char cmd[600];
	FILE *f;
	size_t n;

	snprintf(cmd, sizeof(cmd), "%s/%s --help 2>&1", bindir, prog);
	f = popen(cmd, "r");
	assert_non_null(f);
	n = fread(out, 1, cap - 1, f);
	out[n] = 0;
	assert_int_equal(pclose(f), 0);
	assert_non_null(strstr(out, "usage"));
}

/* Every --option in `a` is in `b` (options of another program, after
 * "rdcd ", are not `a`'s own). */
static void options_in(const char *a, const char *b, const char *what)
{
	int n = 0;

	for (const char *p = strstr(a, "--"); p; p = strstr(p + 2, "--")) {
		char opt[40];
		const char *q;
		size_t k = 2;

		if (!islower((unsigned char)p[2]) || (p > a && p[-1] == '-'))
			continue;
		if (p - a >= 5 && !strncmp(p - 5, "rdcd ", 5))
			continue;
		while ((islower((unsigned char)p[k]) ||
			isdigit((unsigned char)p[k]) || p[k] == '-') &&
		       k + 1 < sizeof(opt))
			k++;
		snprintf(opt, sizeof(opt), "%.*s", (int)k, p);
		for (q = strstr(b, opt); q; q = strstr(q + 1, opt))
			if (!islower((unsigned char)q[k]) && q[k] != '-')
				break;
		if (!q)
			fail_msg("%s: %s is missing", what, opt);
		n++;
	}
	assert_true(n > 3);
}

static void test_options(void **state)
{
	static char help[16384];
	char *proto = slurp("docs/protocol.md");
	char *rdl = slurp("docs/rdl.md");
	char *s_rdcd = section(proto, "```\nrdcd ", "```\n\n");
	char *s_ctl = section(rdl, "\n## rdcctl", "\n## ");

	(void)state;
	help_text("rdcd", help, sizeof(help));
	options_in(help, s_rdcd, "rdcd --help against protocol.md's synopsis");
	options_in(s_rdcd, help, "protocol.md's synopsis against rdcd --help");
	help_text("rdcctl", help, sizeof(help));
	options_in(help, s_ctl, "rdcctl --help against rdl.md's rdcctl");
	options_in(s_ctl, help, "rdl.md's rdcctl against rdcctl --help");
	free(s_ctl);
	free(s_rdcd);
	free(rdl);
	free(proto);
}

/* ---- Named constants ---------------------------------------------------- */

#define MAX_DEFS 4096

struct def {
	char name[48];
	long long v;
};

/* "#define RDC_NAME 123" (or (-123), 0x1fu ...) in one source file. */
static size_t file_defs(const char *path, struct def *d, size_t n)
{
	char *text = slurp(path);
	const char *p = text;
	char line[512];

	while (next_line(&p, line, sizeof(line))) {
		char name[48], *end;
		const char *q;
		long long v;
		int k;

		if (sscanf(line, "#define %47s%n", name, &k) != 1 ||
		    strncmp(name, "RDC", 3) || strchr(name, '('))
			continue;
		q = line + k;
		while (*q == ' ' || *q == '\t' || *q == '(')
			q++;
		if (!isdigit((unsigned char)*q) && *q != '-')
			continue;
		v = strtoll(q, &end, 0);
		if (end == q)
			continue;
		while (*end == 'u' || *end == 'U' || *end == ')')
			end++;
		while (*end == ' ' || *end == '\t')
			end++;
		if (*end && strncmp(end, "/*", 2))
			continue; /* an expression, not a plain number */
		if (n < MAX_DEFS) {
			snprintf(d[n].name, sizeof(d[n].name), "%s", name);
			d[n++].v = v;
		}
	}
	free(text);
	return n;
}

static size_t all_defs(struct def *d)
{
	static const char *const dirs[] = {
		"hw-sim",	  "firmware-model", "userspace/include",
		"userspace/lib",  "userspace/rdcd", "userspace/rdcctl",
		"userspace/sink", "driver",
	};
	size_t n = 0;

	for (size_t i = 0; i < sizeof(dirs) / sizeof(dirs[0]); i++) {
		DIR *dir = opendir(dirs[i]);
		struct dirent *e;

		if (!dir)
			continue;
		while ((e = readdir(dir))) {
			size_t len = strlen(e->d_name);
			char path[600];

			if (len < 3 || (strcmp(e->d_name + len - 2, ".h") &&
					strcmp(e->d_name + len - 2, ".c")))
				continue;
			snprintf(path, sizeof(path), "%s/%s", dirs[i],
				 e->d_name);
			n = file_defs(path, d, n);
		}
		closedir(dir);
	}
	return n;
}

/*
 * Every "`RDC_NAME` (N" or "`RDC_NAME` = N" in the docs, where RDC_NAME
 * is defined as a plain number, gives that number.
 */
static void test_constants(void **state)
{
	static struct def d[MAX_DEFS];
	static const char *const docs[] = {
		"docs/commands.md", "docs/hardware.md", "docs/protocol.md",
		"docs/rdl.md",	    "docs/usb.md",	"docs/driver.md",
		"docs/pins.md",	    "docs/vcd.md",	"README.md",
	};
	size_t nd = all_defs(d);
	int checked = 0;
	char *cmd;

	(void)state;
	assert_true(nd > 100);
	for (size_t i = 0; i < sizeof(docs) / sizeof(docs[0]); i++) {
		char *text;

		if (access(docs[i], R_OK))
			continue;
		text = slurp(docs[i]);
		for (const char *p = strstr(text, "`RDC"); p;
		     p = strstr(p + 1, "`RDC")) {
			const char *q = strchr(p + 1, '`');
			char name[48], num[32];
			size_t k = 0, j;
			long long v;

			if (!q || q - p - 1 >= (long)sizeof(name))
				continue;
			snprintf(name, sizeof(name), "%.*s", (int)(q - p - 1),
				 p + 1);
			q++;
			while (*q == ' ')
				q++;
			if (*q != '(' && *q != '=')
				continue;
			q++;
			while (*q == ' ')
				q++;
			/* "1,539" is 1539 */
			while ((isxdigit((unsigned char)*q) || *q == ',' ||
				*q == 'x' || *q == '-') &&
			       k + 1 < sizeof(num)) {
				if (*q != ',')
					num[k++] = *q;
				q++;
			}
			num[k] = 0;
			if (!k ||
			    (!isdigit((unsigned char)num[0]) && num[0] != '-'))
				continue;
			v = strtoll(num, NULL, 0);
			for (j = 0; j < nd; j++)
				if (!strcmp(d[j].name, name))
					break;
			if (j == nd)
				continue; /* an enum, or an expression */
			if (d[j].v != v)
				fail_msg("%s: %s is %lld, the code says %lld",
					 docs[i], name, v, d[j].v);
			checked++;
		}
		free(text);
	}
	assert_true(checked >= 10);

	/* the coordinate and size ranges, in numbers */
	cmd = slurp("docs/commands.md");
	{
		const char *p =
			strstr(cmd, "`[RDC_COORD_MIN, RDC_COORD_MAX]` = ");
		int lo, hi, smax;

		assert_non_null(p);
		assert_int_equal(sscanf(p,
					"`[RDC_COORD_MIN, RDC_COORD_MAX]` = "
					"[%d, %d]",
					&lo, &hi),
				 2);
		assert_int_equal(lo, RDC_COORD_MIN);
		assert_int_equal(hi, RDC_COORD_MAX);
		p = strstr(cmd, "`[0, RDC_SIZE_MAX]` = [0, ");
		assert_non_null(p);
		assert_int_equal(
			sscanf(p, "`[0, RDC_SIZE_MAX]` = [0, %d]", &smax), 1);
		assert_int_equal(smax, RDC_SIZE_MAX);
	}
	free(cmd);
}

/* ---- The README's example ------------------------------------------------ */

static void test_readme_example(void **state)
{
	char *readme = slurp("README.md");
	char *code = section(readme, "```c\n", "```\n");
	char *how = section(readme, "compile with `", "`,");
	char path[] = "/tmp/rdc_readme_XXXXXX.c", cmd[600];
	FILE *f;
	int fd, st;

	(void)state;
	if (system("command -v cc > /dev/null 2>&1")) {
		free(how);
		free(code);
		free(readme);
		skip(); /* no compiler on this machine */
	}
	fd = mkstemps(path, 2);
	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	fprintf(f, "#include \"rdc.h\"\nint main(void)\n{\n%s\treturn 0;\n}\n",
		code + strlen("```c\n"));
	assert_int_equal(fclose(f), 0);
	/* the flags exactly as the README gives them */
	snprintf(cmd, sizeof(cmd),
		 "cc -std=gnu11 -Wall -Werror -fsyntax-only %s %s",
		 how + strlen("compile with `"), path);
	st = system(cmd);
	unlink(path);
	if (!WIFEXITED(st) || WEXITSTATUS(st))
		fail_msg("README's example does not compile: %s", cmd);
	free(how);
	free(code);
	free(readme);
}

/* ---- The README's commands ---------------------------------------------- */

/* The whole line of `text` that holds `what`, without its newline. */
static char *line_with(const char *text, const char *what)
{
	const char *p = strstr(text, what), *a, *b;
	char *s;

	if (!p)
		fail_msg("no '%s' in the document", what);
	for (a = p; a > text && a[-1] != '\n'; a--)
		;
	b = strchr(p, '\n');
	s = strndup(a, b ? (size_t)(b - a) : strlen(a));
	assert_non_null(s);
	return s;
}

/* `line` with each "build/rel/" made this build's directory. */
static char *this_build(const char *line)
{
	size_t cap = strlen(line) * 4 + sizeof(bindir) * 8 + 1, n = 0;
	char *s = malloc(cap);

	assert_non_null(s);
	for (const char *p = line; *p;) {
		if (!strncmp(p, "build/rel/", 10)) {
			n += (size_t)snprintf(s + n, cap - n, "%s/", bindir);
			p += 10;
		} else {
			s[n++] = *p++;
		}
	}
	s[n] = 0;
	return s;
}

/*
 * The README's still on demand, its two lines as they are (with this
 * build's rdcd), three times in a fresh directory: rdcd survives the
 * signal, writes one PNG and exits 0 on SIGTERM.  The wait for the PNG
 * is bounded only so that a broken rdcd cannot hang the test.
 */
static void test_readme_still(void **state)
{
	char *readme = slurp("README.md");
	char *l1 = line_with(readme, "--png shots,every=0");
	char *l2 = line_with(readme, "kill -USR1 $!");
	char *a = this_build(l1), *b = this_build(l2);
	char dir[] = "/tmp/rdc-still-XXXXXX", script[600], cmd[800];
	static char bad[8192];
	FILE *f;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(script, sizeof(script), "%s/still.sh", dir);
	f = fopen(script, "w");
	assert_non_null(f);
	fprintf(f,
		"cd %s/t || exit 9\n"
		"XDG_RUNTIME_DIR=%s/t/run; export XDG_RUNTIME_DIR\n"
		"%s\n%s\n"
		"n=0\n"
		"until [ -n \"$(ls shots 2>/dev/null)\" ] || [ $n -ge 1200 ]; do\n"
		"\tn=$((n + 1)); sleep 0.1; done\n"
		"kill -TERM $!; wait $!; echo \"exit $?\"\n"
		"ls shots | grep -c '^frame-[0-9]*\\.png$'\n"
		"[ -e rdcd.up ] && echo 'rdcd.up left behind'\n",
		dir, dir, a, b);
	assert_int_equal(fclose(f), 0);
	for (int k = 0; k < 3; k++) {
		char out[4096] = "";
		size_t n;
		FILE *p;

		snprintf(cmd, sizeof(cmd),
			 "rm -rf %s/t && mkdir -p %s/t/run && "
			 "timeout 300 sh %s 2>&1",
			 dir, dir, script);
		p = popen(cmd, "r");
		assert_non_null(p);
		n = fread(out, 1, sizeof(out) - 1, p);
		out[n] = 0;
		pclose(p);
		if (!strstr(out, "exit 0\n1\n") || strstr(out, "left behind")) {
			snprintf(bad, sizeof(bad),
				 "run %d of the README's\n%s\n%s\n%s", k + 1,
				 l1, l2, out);
			break;
		}
	}
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
	free(b);
	free(a);
	free(l2);
	free(l1);
	free(readme);
	if (bad[0])
		fail_msg("%s", bad);
}

/* --version: the release of the headers and of the library, as rdc.h's. */
static void test_versions(void **state)
{
	static const char *const progs[] = { "rdcctl", "rdcd" };
	char want[200], out[400], cmd[600];

	(void)state;
	for (size_t i = 0; i < 2; i++) {
		FILE *f;
		size_t n;

		snprintf(cmd, sizeof(cmd), "%s/%s --version", bindir, progs[i]);
		f = popen(cmd, "r");
		assert_non_null(f);
		n = fread(out, 1, sizeof(out) - 1, f);
		out[n] = 0;
		assert_int_equal(pclose(f), 0);
		snprintf(want, sizeof(want), "%s %d.%d.%d (librdc %d.%d.%d)\n",
			 progs[i], RDC_VERSION_MAJOR, RDC_VERSION_MINOR,
			 RDC_VERSION_PATCH, RDC_VERSION_MAJOR,
			 RDC_VERSION_MINOR, RDC_VERSION_PATCH);
		assert_string_equal(out, want);
	}
}

/* ---- rdcctl's exit status ---------------------------------------------- */

/* Run `bindir`/rdcctl with `args`; stdout and stderr into out. */
static int ctl_status(const char *args, char *out, size_t cap)
{
	char cmd[1200];
	size_t n;
	FILE *p;
	int st;

	snprintf(cmd, sizeof(cmd), "%s/rdcctl %s 2>&1", bindir, args);
	p = popen(cmd, "r");
	assert_non_null(p);
	n = fread(out, 1, cap - 1, p);
	out[n] = 0;
	st = pclose(p);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* `text` with roff's font escapes and \- taken out, lines joined. */
static char *plain(const char *text)
{
	char *s = malloc(strlen(text) + 1), *o = s;

	assert_non_null(s);
	for (const char *p = text; *p;) {
		if (p[0] == '\\' && p[1] == 'f' && p[2]) {
			p += 3;
		} else if (p[0] == '\\' && p[1] == '-') {
			*o++ = '-';
			p += 2;
		} else if ((p == text || p[-1] == '\n') && *p == '.') {
			while (*p && *p != ' ' && *p != '\n')
				p++; /* a request: .B, .RB ... */
			if (*p == ' ')
				p++;
		} else {
			*o++ = *p == '\n' ? ' ' : *p;
			p++;
		}
	}
	*o = 0;
	return s;
}

/*
 * rdcctl's exit status is one rule, stated in rdl.md's rdcctl section
 * and in rdcctl(1)'s EXIT STATUS and nowhere else in them: each of its
 * codes is said there and is what rdcctl does, for every kind of
 * command.  A missing file keeps its name and the system's reason.
 */
static void test_exit_status(void **state)
{
	static const struct {
		int code;
		const char *said; /* how both documents put it */
	} rule[] = {
		{ 0, "0 on success" },
		{ 1, "1 on an error" },
		{ 2, "2 for bad usage" },
		{ 3, "3 when a command that compares found a difference" },
	};
	static char out[65536];
	char *rdl = slurp("docs/rdl.md"), *man = slurp("man/rdcctl.1");
	char *sec_rdl = section(rdl, "Exit status, of every command:", "\n\n");
	char *sec_man = section(man, ".SH EXIT STATUS", "\n.SH ");
	char *p_man = plain(sec_man), *p_rdl = plain(sec_rdl);
	char dir[] = "/tmp/rdc-exit-XXXXXX", a[300], b[300], args[1000];
	const char *missing = "/nonexistent-dir/missing.rdl";
	FILE *f;

	(void)state;
	for (size_t i = 0; i < sizeof(rule) / sizeof(rule[0]); i++) {
		if (!strstr(p_rdl, rule[i].said))
			fail_msg("docs/rdl.md's exit status lacks '%s'",
				 rule[i].said);
		if (!strstr(p_man, rule[i].said))
			fail_msg("rdcctl(1)'s EXIT STATUS lacks '%s'",
				 rule[i].said);
	}
	/* stated once: no other exit status in either */
	for (const char *q = rdl; (q = strcasestr(q, "exit")); q++)
		if (q < strstr(rdl, sec_rdl) ||
		    q >= strstr(rdl, sec_rdl) + strlen(sec_rdl))
			fail_msg(
				"docs/rdl.md speaks of exits outside its rule: "
				"%.60s",
				q);
	for (const char *q = man; (q = strcasestr(q, "exit")); q++)
		if ((q < strstr(man, sec_man) ||
		     q >= strstr(man, sec_man) + strlen(sec_man)) &&
		    strncmp(q, "exit.", 5))
			fail_msg("rdcctl(1) speaks of exits outside EXIT "
				 "STATUS: %.60s",
				 q);

	assert_non_null(mkdtemp(dir));
	snprintf(a, sizeof(a), "%s/a.rdl", dir);
	snprintf(b, sizeof(b), "%s/b.rdl", dir);
	f = fopen(a, "w");
	assert_non_null(f);
	fputs("mode 320x200 i8\nfg 1\nfill 0 0 8 8\n", f);
	assert_int_equal(fclose(f), 0);
	f = fopen(b, "w");
	assert_non_null(f);
	fputs("mode 320x200 i8\nfg 2\nfill 0 0 8 8\n", f);
	assert_int_equal(fclose(f), 0);

	/* 0 */
	snprintf(args, sizeof(args), "run %s", a);
	assert_int_equal(ctl_status(args, out, sizeof(out)), 0);
	snprintf(args, sizeof(args), "diff %s %s", a, a);
	assert_int_equal(ctl_status(args, out, sizeof(out)), 0);
	/* 1, a missing file named with its reason by every command */
	for (int i = 0; i < 8; i++) {
		char fa[1000];
		int st;

		switch (i) {
		case 0:
			snprintf(fa, sizeof(fa), "run %s", missing);
			break;
		case 1:
			snprintf(fa, sizeof(fa), "regs %s", missing);
			break;
		case 2:
			snprintf(fa, sizeof(fa), "stats %s", missing);
			break;
		case 3:
			snprintf(fa, sizeof(fa), "why 1 1 %s", missing);
			break;
		case 4:
			snprintf(fa, sizeof(fa), "run %s --history 1,1",
				 missing);
			break;
		case 5:
			snprintf(fa, sizeof(fa), "diff %s %s", missing, a);
			break;
		case 6:
			snprintf(fa, sizeof(fa), "diff %s %s", a, missing);
			break;
		default:
			snprintf(fa, sizeof(fa), "replay %s", missing);
			break;
		}
		st = ctl_status(fa, out, sizeof(out));
		if (st != 1 || !strstr(out, missing) ||
		    !strstr(out, "No such file or directory"))
			fail_msg("rdcctl %s: exit %d, '%s' (want 1, the file "
				 "and the system's reason)",
				 fa, st, out);
	}
	snprintf(args, sizeof(args), "--record %s run %s", missing, a);
	if (ctl_status(args, out, sizeof(out)) != 1 || !strstr(out, missing) ||
	    !strstr(out, "No such file or directory"))
		fail_msg("rdcctl %s: '%s' (want 1, the file and the system's "
			 "reason)",
			 args, out);
	/* 2 */
	assert_int_equal(ctl_status("frobnicate", out, sizeof(out)), 2);
	snprintf(args, sizeof(args), "diff %s", a);
	assert_int_equal(ctl_status(args, out, sizeof(out)), 2);
	assert_int_equal(ctl_status("run --bogus", out, sizeof(out)), 2);
	/* 3 */
	snprintf(args, sizeof(args), "diff %s %s", a, b);
	assert_int_equal(ctl_status(args, out, sizeof(out)), 3);
	assert_non_null(strstr(out, "first divergence"));

	unlink(a);
	unlink(b);
	rmdir(dir);
	free(p_rdl);
	free(p_man);
	free(sec_man);
	free(sec_rdl);
	free(man);
	free(rdl);
}

/* ---- docs/vcd.md's golden regeneration --------------------------------- */

/* Run `cmd` through sh; its exit status. */
static int sh_status(const char *cmd)
{
	int st = system(cmd);

	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/*
 * `RDC_VCD_REGEN=1 test_vcd` never rewrites the golden file after a
 * failure: a copy of test_vcd alone in a directory (no rdcctl, rdcd
 * beside it, so its front-end tests fail) leaves a golden file it was
 * pointed at as it was; the test_vcd of this build, all passing,
 * rewrites it to the tree's.
 */
static void test_vcd_regen(void **state)
{
	char dir[] = "/tmp/rdc-regen-XXXXXX", cmd[2400], vcd[600];
	const char *tree = "tests/unit/data/vcd_tiny.vcd";
	int st;

	(void)state;
	snprintf(vcd, sizeof(vcd), "%s/tests/test_vcd", bindir);
	if (access(vcd, X_OK)) {
		print_message("test_vcd is not built: %s\n", vcd);
		skip();
	}
	assert_non_null(mkdtemp(dir));
	snprintf(cmd, sizeof(cmd),
		 "mkdir %s/tests && cp %s %s/tests/ && "
		 "printf 'not a VCD\\n' >%s/golden.vcd",
		 dir, vcd, dir, dir);
	assert_int_equal(sh_status(cmd), 0);
	snprintf(cmd, sizeof(cmd),
		 "RDC_VCD_REGEN=1 RDC_VCD_GOLDEN=%s/golden.vcd "
		 "%s/tests/test_vcd >%s/log 2>&1",
		 dir, dir, dir);
	st = sh_status(cmd);
	if (!st)
		fail_msg("test_vcd without rdcctl and rdcd passed (%s/log)",
			 dir);
	snprintf(cmd, sizeof(cmd), "grep -qx 'not a VCD' %s/golden.vcd", dir);
	if (sh_status(cmd))
		fail_msg("RDC_VCD_REGEN rewrote the golden file after a "
			 "failure (%s)",
			 dir);
	snprintf(cmd, sizeof(cmd),
		 "RDC_VCD_REGEN=1 RDC_VCD_GOLDEN=%s/golden.vcd %s "
		 ">%s/log 2>&1 && cmp -s %s/golden.vcd %s",
		 dir, vcd, dir, dir, tree);
	if (sh_status(cmd))
		fail_msg("RDC_VCD_REGEN with every test passing did not "
			 "write the tree's golden file (%s/log)",
			 dir);
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	assert_int_equal(sh_status(cmd), 0);
}

/* ---- docs/web.md's rdcctl and the unix: hint --------------------------- */

/*
 * web.md's rdcctl line works wherever rdcd listens by default: it names
 * no $XDG_RUNTIME_DIR (unset for root, in containers and CI), and, as
 * written, reaches a default rdcd.  A failed unix: connect names the
 * path rdcd listens on without --listen, XDG_RUNTIME_DIR set or not.
 */
static void test_web_doc(void **state)
{
	char *web = slurp("docs/web.md");
	char *line = line_with(web, "rdcctl --connect");
	char *cmd_line = this_build(line);
	char dir[] = "/tmp/rdc-web-XXXXXX", cmd[4000], want[200];
	static char out[16384];
	size_t n;
	FILE *p;

	(void)state;
	if (strstr(line, "XDG_RUNTIME_DIR"))
		fail_msg("docs/web.md: '%s' depends on $XDG_RUNTIME_DIR", line);
	assert_non_null(mkdtemp(dir));
	snprintf(cmd, sizeof(cmd),
		 "XDG_RUNTIME_DIR=%s; export XDG_RUNTIME_DIR; "
		 "%s/rdcd --stepped -q --ready-file %s/up & "
		 "until [ -e %s/up ] || ! kill -0 $!; do sleep 0.1; done; "
		 "%s\necho \"status $?\"; kill $!; wait $!",
		 dir, bindir, dir, dir, cmd_line);
	p = popen(cmd, "r");
	assert_non_null(p);
	n = fread(out, 1, sizeof(out) - 1, p);
	out[n] = 0;
	pclose(p);
	if (!strstr(out, "status 0\n"))
		fail_msg("docs/web.md's '%s' with rdcd's default socket: %s",
			 line, out);

	/* the hint, with and without XDG_RUNTIME_DIR */
	for (int xdg = 0; xdg < 2; xdg++) {
		int st;

		if (xdg) {
			snprintf(cmd, sizeof(cmd),
				 "env XDG_RUNTIME_DIR=%s %s/rdcctl --connect "
				 "unix:%s/none/rdc.sock stats 2>&1",
				 dir, bindir, dir);
			snprintf(want, sizeof(want),
				 "listens on unix:%s/rdc/rdc.sock", dir);
		} else {
			snprintf(cmd, sizeof(cmd),
				 "env -u XDG_RUNTIME_DIR %s/rdcctl --connect "
				 "unix:%s/none/rdc.sock stats 2>&1",
				 bindir, dir);
			snprintf(want, sizeof(want),
				 "listens on unix:/tmp/rdc-%u/rdc.sock",
				 (unsigned int)getuid());
		}
		p = popen(cmd, "r");
		assert_non_null(p);
		n = fread(out, 1, sizeof(out) - 1, p);
		out[n] = 0;
		st = pclose(p);
		if (!WIFEXITED(st) || WEXITSTATUS(st) != 1 ||
		    !strstr(out, want))
			fail_msg("%s: '%s', not '%s'", cmd, out, want);
	}
	rmdir(dir);
	free(cmd_line);
	free(line);
	free(web);
}

/* ---- Documented sessions: "$ command" and its output ------------------- */

#define SESSION_MAX_LINES 256
#define SESSION_MARK	  "@@rdc-doc-session@@"

/* A growing string. */
struct sbuf {
	char *s;
	size_t n, cap;
};

static void sb_add(struct sbuf *b, const char *s, size_t n)
{
	if (b->n + n + 1 > b->cap) {
		b->cap = (b->n + n + 1) * 2;
		b->s = realloc(b->s, b->cap);
		assert_non_null(b->s);
	}
	memcpy(b->s + b->n, s, n);
	b->n += n;
	b->s[b->n] = 0;
}

static void sb_line(struct sbuf *b, const char *s)
{
	sb_add(b, s, strlen(s));
	sb_add(b, "\n", 1);
}

/* The lines of `text` (modified in place) into v; their count. */
static size_t split_lines(char *text, char **v, size_t cap)
{
	size_t n = 0;

	for (char *p = text; *p && n < cap;) {
		char *nl = strchr(p, '\n');

		v[n++] = p;
		if (!nl)
			break;
		*nl = 0;
		p = nl + 1;
	}
	return n;
}

/* A line of "..." alone (indented or not) stands for any lines. */
static bool is_dots(const char *line)
{
	return !strcmp(line + strspn(line, " "), "...");
}

/*
 * Does `got` (n lines) show as `want` (m lines)?  A "..." line in want
 * stands for any lines, none included.
 */
static bool lines_match(char **got, size_t n, char **want, size_t m)
{
	size_t k;

	for (k = 0; k < m && !is_dots(want[k]); k++)
		if (k >= n || strcmp(got[k], want[k]))
			return false;
	if (k == m)
		return n == m;
	/* the lines after "..." are the last ones */
	if (n < m - 1)
		return false;
	for (size_t j = k + 1; j < m; j++)
		if (strcmp(got[n - (m - j)], want[j]))
			return false;
	return true;
}

/*
 * Run one session (the lines of a ``` block from a "$ " line on) in a
 * scratch directory where build/rel is this build and examples/ the
 * tree's, the commands in one shell; each command's output, stdout and
 * stderr, against the lines after it.  With `regen`, *out gets the
 * block as the commands print it ("..." kept where it was, standing for
 * the same number of lines from the end).  false if one differs.
 */
static bool run_session(char **blk, size_t nb, struct sbuf *out, char *why,
			size_t whycap)
{
	char dir[] = "/tmp/rdc-session-XXXXXX", cmd[PATH_MAX + 1200];
	char root[PATH_MAX];
	static char got[1 << 20];
	char *gl[SESSION_MAX_LINES * 4];
	struct sbuf sh = { 0 };
	size_t ng, n, g = 0, i = 0;
	bool ok = true;
	FILE *p;

	assert_non_null(getcwd(root, sizeof(root)));
	assert_non_null(mkdtemp(dir));
	snprintf(cmd, sizeof(cmd),
		 "mkdir %s/build && ln -s %s %s/build/rel && "
		 "ln -s %s/examples %s/examples",
		 dir, bindir, dir, root, dir);
	assert_int_equal(sh_status(cmd), 0);
	sb_line(&sh, "exec 2>&1");
	snprintf(cmd, sizeof(cmd), "cd %s || exit 1", dir);
	sb_line(&sh, cmd);
	for (size_t k = 0; k < nb; k++) {
		if (strncmp(blk[k], "$ ", 2))
			continue;
		sb_line(&sh, blk[k] + 2);
		/* what runs in the background is stopped at the end */
		sb_line(&sh, "[ -z \"$!\" ] || bgs=\"$bgs $!\"");
		sb_line(&sh, "echo " SESSION_MARK);
	}
	sb_line(&sh, "for p in $bgs; do kill $p 2>/dev/null; done; wait");
	snprintf(cmd, sizeof(cmd), "%s/session.sh", dir);
	p = fopen(cmd, "w");
	assert_non_null(p);
	fputs(sh.s, p);
	assert_int_equal(fclose(p), 0);
	snprintf(cmd, sizeof(cmd), "timeout 120 sh %s/session.sh", dir);
	p = popen(cmd, "r");
	assert_non_null(p);
	n = fread(got, 1, sizeof(got) - 1, p);
	got[n] = 0;
	pclose(p);
	ng = split_lines(got, gl, sizeof(gl) / sizeof(gl[0]));
	/* this build's own noise (the sanitizers' notes), not the program's */
	for (size_t k = 0; k < ng;) {
		if (!strncmp(gl[k], "==", 2) && strstr(gl[k], "==WARNING: ")) {
			memmove(gl + k, gl + k + 1, (ng - k - 1) * sizeof(*gl));
			ng--;
		} else {
			k++;
		}
	}

	while (i < nb) {
		size_t w0, wn, g0;

		if (strncmp(blk[i], "$ ", 2)) {
			i++;
			continue;
		}
		sb_line(out, blk[i]);
		w0 = ++i;
		while (i < nb && strncmp(blk[i], "$ ", 2))
			i++;
		wn = i - w0;
		g0 = g;
		while (g < ng && strcmp(gl[g], SESSION_MARK))
			g++;
		if (g == ng) {
			snprintf(why, whycap, "'%s' did not finish",
				 blk[w0 - 1]);
			ok = false;
			break;
		}
		if (!lines_match(gl + g0, g - g0, blk + w0, wn)) {
			if (ok)
				snprintf(
					why, whycap,
					"'%s' prints\n%.*s\nnot as documented",
					blk[w0 - 1],
					(int)(g > g0 ?
						      gl[g - 1] +
							      strlen(gl[g - 1]) -
							      gl[g0] :
						      0),
					g > g0 ? gl[g0] : "");
			ok = false;
		}
		/* what the block becomes */
		{
			size_t dots = wn, after = 0;

			for (size_t k = 0; k < wn; k++)
				if (is_dots(blk[w0 + k])) {
					dots = k;
					after = wn - k - 1;
				}
			if (dots == wn || g - g0 <= dots + after) {
				for (size_t k = g0; k < g; k++)
					sb_line(out, gl[k]);
			} else {
				for (size_t k = 0; k < dots; k++)
					sb_line(out, gl[g0 + k]);
				sb_line(out, blk[w0 + dots]);
				for (size_t k = g - after; k < g; k++)
					sb_line(out, gl[k]);
			}
		}
		g++;
	}
	free(sh.s);
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	assert_int_equal(sh_status(cmd), 0);
	return ok;
}

/*
 * Every ``` block of README.md and docs/history.md that starts with a
 * "$ " line is a session whose output is the code's: run as written (on
 * this build), each command prints what the document shows.
 * RDC_DOCS_REGEN=1 rewrites the documents with what they print.  Also,
 * the scene history.md lists is examples/scene.rdl.
 */
static void test_doc_sessions(void **state)
{
	static const char *const docs[] = { "README.md", "docs/history.md" };
	bool regen = getenv("RDC_DOCS_REGEN") != NULL;
	static char why[8192];
	int sessions = 0;

	(void)state;
	for (size_t d = 0; d < sizeof(docs) / sizeof(docs[0]); d++) {
		char *text = slurp(docs[d]);
		struct sbuf out = { 0 };
		const char *p = text, *q;
		bool changed = false;

		while ((q = strstr(p, "```\n$ "))) {
			const char *b = q + 4, *e = strstr(b, "```\n");
			char *blk_text, *blk[SESSION_MAX_LINES];
			struct sbuf nb = { 0 };
			size_t n;

			assert_non_null(e);
			sb_add(&out, p, (size_t)(b - p));
			blk_text = strndup(b, (size_t)(e - b));
			assert_non_null(blk_text);
			if (*blk_text && blk_text[strlen(blk_text) - 1] == '\n')
				blk_text[strlen(blk_text) - 1] = 0;
			n = split_lines(blk_text, blk, SESSION_MAX_LINES);
			why[0] = 0;
			if (!run_session(blk, n, &nb, why, sizeof(why))) {
				if (!regen)
					fail_msg("%s: %s (RDC_DOCS_REGEN=1 "
						 "rewrites it)",
						 docs[d], why);
				changed = true;
				print_message("%s: rewrote: %s\n", docs[d],
					      why);
			}
			sb_add(&out, nb.s ? nb.s : "", nb.n);
			free(nb.s);
			free(blk_text);
			p = e;
			sessions++;
		}
		sb_add(&out, p, strlen(p));
		if (changed) {
			FILE *f = fopen(docs[d], "w");

			assert_non_null(f);
			fputs(out.s, f);
			assert_int_equal(fclose(f), 0);
		}
		if (d == 1) {
			char *scene = slurp("examples/scene.rdl");

			if (!strstr(text, scene))
				fail_msg("docs/history.md does not list "
					 "examples/scene.rdl as it is");
			free(scene);
		}
		free(out.s);
		free(text);
	}
	assert_true(sessions >= 6);
}

/* ---- make bench BENCH_ARGS=... (bench/README.md) ----------------------- */

/*
 * With BENCH_ARGS, `make bench` runs rdc-bench with them and nothing
 * else: make -n neither builds nor runs net_bench, sink-bench or
 * stream-bench (the shell line that says they are left out names them);
 * without, it does both.
 */
static void test_bench_args(void **state)
{
	static const char *const rest[] = { "net_bench", "sink-bench",
					    "stream-bench" };
	static char out[1 << 18];
	char dir[] = "/tmp/rdc-bench-XXXXXX", cmd[600], want[200];

	(void)state;
	if (sh_status("command -v make >/dev/null 2>&1"))
		skip();
	assert_non_null(mkdtemp(dir));
	for (int with = 1; with >= 0; with--) {
		FILE *p;
		size_t n;

		snprintf(cmd, sizeof(cmd),
			 "make -n -s --no-print-directory O=%s bench %s 2>&1",
			 dir, with ? "BENCH_ARGS='-w growth'" : "");
		p = popen(cmd, "r");
		assert_non_null(p);
		n = fread(out, 1, sizeof(out) - 1, p);
		out[n] = 0;
		assert_int_equal(pclose(p), 0);
		snprintf(want, sizeof(want), "\n%s/rel/rdc-bench%s\n", dir,
			 with ? " -w growth" : " ");
		if (!strstr(out, want))
			fail_msg("%s: no '%s'", cmd, want + 1);
		for (size_t i = 0; i < sizeof(rest) / sizeof(rest[0]); i++) {
			char built[300], run[300];
			bool b, r;

			snprintf(built, sizeof(built), "-o %s/rel/%s\n", dir,
				 rest[i]);
			snprintf(run, sizeof(run), "\n%s/rel/%s", dir, rest[i]);
			b = strstr(out, built);
			r = strstr(out, run);
			if (with && (b || r))
				fail_msg("%s builds or runs %s", cmd, rest[i]);
			if (!with && !b)
				fail_msg("%s does not build %s", cmd, rest[i]);
		}
	}
	rmdir(dir);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_registers),
		cmocka_unit_test(test_opcodes),
		cmocka_unit_test(test_device_errors),
		cmocka_unit_test(test_formats_and_presets),
		cmocka_unit_test(test_protocol),
		cmocka_unit_test(test_rdl_statements),
		cmocka_unit_test(test_rdl_names_case),
		cmocka_unit_test(test_options),
		cmocka_unit_test(test_constants),
		cmocka_unit_test(test_readme_example),
		cmocka_unit_test(test_readme_still),
		cmocka_unit_test(test_versions),
		cmocka_unit_test(test_exit_status),
		cmocka_unit_test(test_vcd_regen),
		cmocka_unit_test(test_bench_args),
		cmocka_unit_test(test_web_doc),
		cmocka_unit_test(test_doc_sessions),
	};
	char self[PATH_MAX], abs[PATH_MAX];

	(void)argc;
	/* $(O)/san/tests/test_docs -> $(O)/san, absolute: the README's
	 * commands run in directories of their own */

	snprintf(self, sizeof(self), "%s/..", dirname(argv[0]));
	snprintf(bindir, sizeof(bindir), "%.399s",
		 realpath(self, abs) ? abs : self);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
