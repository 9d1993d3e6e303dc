// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * What is installed beside the programs: the manual pages (man/), bash
 * completion, systemd units and the udev rule (dist/).  The pages must
 * format without a single groff or man warning and must name every
 * rdcctl command and option of `rdcctl --help`, every rdcd option of
 * `rdcd --help`, every statement of the .rdl interpreter's table and
 * every function of the public header, so they cannot drift from the
 * programs; the completion must offer the commands and options --help
 * lists; the units must pass `systemd-analyze verify`; the udev rule
 * must match rdc_usb.h's IDs.  Run from the source root (tests/run.sh).
 */
#include <ctype.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "rdc_usb.h"

#define OUT_MAX (4u << 20)

/* Run a shell command; its stdout (and stderr with 2>&1) as a string. */
static char *run(const char *cmd, int *status)
{
	FILE *p = popen(cmd, "r");
	char *buf = malloc(OUT_MAX + 1);
	size_t n = 0, k;

	assert_non_null(p);
	assert_non_null(buf);
	while (n < OUT_MAX && (k = fread(buf + n, 1, OUT_MAX - n, p)) > 0)
		n += k;
	buf[n] = 0;
	k = (size_t)pclose(p);
	if (status)
		*status = WIFEXITED((int)k) ? WEXITSTATUS((int)k) : 128;
	return buf;
}

static char *read_file(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *buf = malloc(OUT_MAX + 1);
	size_t n;

	if (!f)
		fail_msg("%s: cannot open", path);
	assert_non_null(buf);
	n = fread(buf, 1, OUT_MAX, f);
	buf[n] = 0;
	fclose(f);
	return buf;
}

static int have(const char *prog)
{
	char cmd[256];

	snprintf(cmd, sizeof(cmd), "command -v %s >/dev/null 2>&1", prog);
	return system(cmd) == 0;
}

/* $(O)/san/NAME, beside this program's directory $(O)/san/tests. */
static void sibling(const char *name, char *buf, size_t cap)
{
	char exe[4096];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
	char *slash;

	assert_true(n > 0);
	exe[n] = 0;
	slash = strrchr(exe, '/');
	assert_non_null(slash);
	*slash = 0;
	slash = strrchr(exe, '/');
	assert_non_null(slash);
	*slash = 0;
	snprintf(buf, cap, "%s/%s", exe, name);
	if (access(buf, X_OK))
		fail_msg("%s is not built", buf);
}

static const char *const pages[] = { "man/rdcctl.1", "man/rdcd.8", "man/rdl.5",
				     "man/librdc.3" };
#define NPAGES (sizeof(pages) / sizeof(pages[0]))

/* A page as plain text: no hyphenation or adjustment to split words. */
static char *render(const char *page)
{
	char cmd[512];
	int st;
	char *out;

	snprintf(cmd, sizeof(cmd),
		 "groff -man -Tascii -P-cbou -rLL=400n %s 2>&1", page);
	out = run(cmd, &st);
	assert_int_equal(st, 0);
	return out;
}

/* Is `word` in text with no letter, digit, '-' or '_' on either side? */
static int has_word(const char *text, const char *word)
{
	size_t len = strlen(word);

	for (const char *p = strstr(text, word); p; p = strstr(p + 1, word)) {
		char b = p == text ? ' ' : p[-1], a = p[len];

		if (!isalnum((unsigned char)b) && b != '-' && b != '_' &&
		    !isalnum((unsigned char)a) && a != '-' && a != '_')
			return 1;
	}
	return 0;
}

/* Is `word` the first word of a line (a command's tag or synopsis)? */
static int has_line_word(const char *text, const char *word)
{
	size_t len = strlen(word);

	for (const char *p = text; *p;) {
		const char *q = p;

		while (*q == ' ')
			q++;
		if (!strncmp(q, "rdcctl ", 7)) /* synopsis: rdcctl [..] cmd */
			q = strstr(q, word) ? strstr(q, word) : q;
		if (!strncmp(q, word, len) &&
		    (q[len] == ' ' || q[len] == '\n' || q[len] == '|' ||
		     q[len] == '['))
			return 1;
		p = strchr(p, '\n');
		if (!p)
			break;
		p++;
	}
	return 0;
}

/* A command of `rdcctl --help`: a word indented by exactly two spaces. */
static int command_at(const char *line, char word[32])
{
	return line[0] == ' ' && line[1] == ' ' &&
	       islower((unsigned char)line[2]) &&
	       sscanf(line + 2, "%31[a-z]", word) == 1;
}

/* Is the option at p one of rdcd's that the text mentions ("an rdcd
 * --record trace", "as rdcd's --png")? */
static int rdcd_option(const char *help, const char *p)
{
	const char *w = p;

	while (w > help && isspace((unsigned char)w[-1]))
		w--;
	while (w > help && !isspace((unsigned char)w[-1]))
		w--;
	return !strncmp(w, "rdcd", 4) && w + 4 < p &&
	       !isalnum((unsigned char)w[4]) && w[4] != 'c';
}

/* Every option (-x, --long-name) of a --help text, in order. */
static int options_of(const char *help, char opts[][32], int max)
{
	int n = 0;

	for (const char *p = help; *p && n < max; p++) {
		size_t len = 0;
		int dup = 0;

		if (*p != '-' || (p > help && (isalnum((unsigned char)p[-1]) ||
					       p[-1] == '-')))
			continue;
		while (p[len] == '-' || isalnum((unsigned char)p[len]))
			len++;
		if (len < 2 || len >= 32 || !isalpha((unsigned char)p[len - 1]))
			continue;
		if (p[1] != '-' && len != 2)
			continue; /* a word with a dash, not -x */
		if (rdcd_option(help, p))
			continue;
		for (int i = 0; i < n; i++)
			dup |= strlen(opts[i]) == len &&
			       !strncmp(opts[i], p, len);
		if (!dup) {
			memcpy(opts[n], p, len);
			opts[n++][len] = 0;
		}
		p += len - 1;
	}
	return n;
}

static void test_man_no_warnings(void **state)
{
	(void)state;
	if (!have("groff"))
		skip();
	for (size_t i = 0; i < NPAGES; i++) {
		char cmd[512];
		int st;
		char *out;

		snprintf(cmd, sizeof(cmd), "groff -man -ww -z -Tutf8 %s 2>&1",
			 pages[i]);
		out = run(cmd, &st);
		if (st || *out)
			fail_msg("%s: groff -ww: %s", pages[i], out);
		free(out);
		if (!have("man"))
			continue;
		snprintf(cmd, sizeof(cmd),
			 "LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -l %s "
			 "2>&1 >/dev/null",
			 pages[i]);
		out = run(cmd, &st);
		if (st || *out)
			fail_msg("%s: man --warnings: %s", pages[i], out);
		free(out);
	}
}

static void test_man_rdcctl_matches_help(void **state)
{
	char bin[4200], cmd[4300], opts[64][32];
	char *help, *page, *cmds;
	int st, n, missing = 0;

	(void)state;
	if (!have("groff"))
		skip();
	sibling("rdcctl", bin, sizeof(bin));
	snprintf(cmd, sizeof(cmd), "%s --help", bin);
	help = run(cmd, &st);
	assert_int_equal(st, 0);
	page = render("man/rdcctl.1");
	/* commands: the lines indented by two spaces under "commands:" */
	cmds = strstr(help, "commands:\n");
	assert_non_null(cmds);
	n = 0;
	for (char *p = strchr(cmds, '\n') + 1; p && *p != '\n' && *p;
	     p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
		char word[32];

		if (!command_at(p, word))
			continue;
		n++;
		if (!has_line_word(page, word)) {
			print_error("rdcctl.1 lacks the command '%s'\n", word);
			missing++;
		}
	}
	assert_true(n >= 8); /* run regs stats replay list stream pins image */
	n = options_of(help, opts, 64);
	assert_true(n >= 20);
	for (int i = 0; i < n; i++)
		if (!has_word(page, opts[i])) {
			print_error("rdcctl.1 lacks the option '%s'\n",
				    opts[i]);
			missing++;
		}
	assert_int_equal(missing, 0);
	free(help);
	free(page);
}

static void test_man_rdcd_matches_help(void **state)
{
	char bin[4200], cmd[4300], opts[64][32];
	char *help, *page;
	int st, n, missing = 0;

	(void)state;
	if (!have("groff"))
		skip();
	sibling("rdcd", bin, sizeof(bin));
	snprintf(cmd, sizeof(cmd), "%s --help", bin);
	help = run(cmd, &st);
	assert_int_equal(st, 0);
	page = render("man/rdcd.8");
	n = options_of(help, opts, 64);
	assert_true(n >= 15);
	for (int i = 0; i < n; i++)
		if (!has_word(page, opts[i])) {
			print_error("rdcd.8 lacks the option '%s'\n", opts[i]);
			missing++;
		}
	/* the listener kinds: "unix:PATH", "ffs:DIR", ... at a line's start
	 * or after "--listen URI" */
	for (const char *k = help; (k = strstr(k, ":")); k++) {
		const char *b = k;
		char kind[16];

		while (b > help && islower((unsigned char)b[-1]))
			b--;
		if (k - b < 3 || k - b > 8 || (b > help && b[-1] != ' ') ||
		    !isupper((unsigned char)k[1]))
			continue; /* kind:UPPER, as unix:PATH */
		snprintf(kind, sizeof(kind), "%.*s:", (int)(k - b), b);
		if (!strstr(page, kind)) {
			print_error("rdcd.8 lacks the listener '%s'\n", kind);
			missing++;
		}
	}
	assert_int_equal(missing, 0);
	free(help);
	free(page);
}

/* Every statement keyword of the interpreter's table (script.c). */
static void test_man_rdl_statements(void **state)
{
	char *src, *page, *t;
	int n = 0, missing = 0;

	(void)state;
	if (!have("groff"))
		skip();
	src = read_file("userspace/lib/script.c");
	page = render("man/rdl.5");
	t = strstr(src, "struct rdl_stmt {");
	assert_non_null(t);
	t = strstr(t, "= {");
	assert_non_null(t);
	for (char *p = t; p && strncmp(p, "\n};", 3); p = strchr(p + 1, '\n')) {
		char kw[64];

		if (sscanf(p, "\n\t{ \"%63[^\"]\",", kw) != 1)
			continue;
		n++;
		if (!has_word(page, kw)) {
			print_error("rdl.5 lacks the statement '%s'\n", kw);
			missing++;
		}
	}
	assert_true(n >= 90);
	assert_int_equal(missing, 0);
	free(src);
	free(page);
}

/* Every function the public header declares, and its version macros. */
static void test_man_librdc_api(void **state)
{
	static const char *const headers[] = { "userspace/include/rdc/rdc.h",
					       "userspace/include/rdc.h" };
	const char *hdr = NULL;
	char *src, *page;
	int n = 0, missing = 0;

	(void)state;
	if (!have("groff"))
		skip();
	for (size_t i = 0; i < sizeof(headers) / sizeof(headers[0]); i++)
		if (!hdr && !access(headers[i], R_OK))
			hdr = headers[i];
	assert_non_null(hdr);
	src = read_file(hdr);
	page = render("man/librdc.3");
	/* a declaration starts a line with its type: "int rdc_open(" */
	for (char *p = src; p; p = strchr(p + 1, '\n')) {
		char *line = *p == '\n' ? p + 1 : p, *name, *paren;
		char fn[64];

		if (!isalpha((unsigned char)*line) ||
		    !strncmp(line, "typedef", 7))
			continue;
		paren = strchr(line, '(');
		if (!paren ||
		    (strchr(line, '\n') && paren > strchr(line, '\n')))
			continue;
		name = paren;
		while (name > line &&
		       (isalnum((unsigned char)name[-1]) || name[-1] == '_'))
			name--;
		if (strncmp(name, "rdc_", 4) || paren - name >= 64)
			continue;
		snprintf(fn, sizeof(fn), "%.*s", (int)(paren - name), name);
		n++;
		if (!has_word(page, fn)) {
			print_error("librdc.3 lacks %s() of %s\n", fn, hdr);
			missing++;
		}
	}
	assert_true(n >= 100);
	assert_int_equal(missing, 0);
	free(src);
	free(page);
}

/* The words bash completion offers for a command line ending in `line`. */
static char *complete(const char *dir, const char *line)
{
	char cmd[2048], cwd[1024];
	int st;
	char *out;

	assert_non_null(getcwd(cwd, sizeof(cwd)));
	/* with bash-completion's helpers when installed, as a user has */
	snprintf(
		cmd, sizeof(cmd),
		"cd '%s' && bash --norc --noprofile -c '"
		"[ -r /usr/share/bash-completion/bash_completion ] && "
		". /usr/share/bash-completion/bash_completion; "
		". \"$0\" || exit 1; "
		"COMP_LINE=\"$1\"; COMP_POINT=${#1}; "
		"read -ra COMP_WORDS <<<\"$1\"; "
		"[ \"${1: -1}\" = \" \" ] && COMP_WORDS+=(\"\"); "
		"COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); "
		"_rdcctl rdcctl \"${COMP_WORDS[COMP_CWORD]}\" "
		"\"${COMP_WORDS[COMP_CWORD-1]}\"; "
		"printf \"%%s\\n\" \"${COMPREPLY[@]}\" | sort | tr \"\\n\" \" \"' "
		"'%s/dist/bash-completion/rdcctl' '%s' 2>&1",
		dir, cwd, line);
	out = run(cmd, &st);
	if (st)
		fail_msg("completing '%s': %s", line, out);
	return out;
}

static void expect_completion(const char *dir, const char *line,
			      const char *want)
{
	char *got = complete(dir, line);

	if (strcmp(got, want))
		fail_msg("completing '%s': got '%s', want '%s'", line, got,
			 want);
	free(got);
}

static void test_bash_completion(void **state)
{
	char dir[] = "/tmp/rdc-complete-XXXXXX", path[128], bin[4200];
	char cmd[4300], opts[64][32];
	char *help, *all;
	int st, n;

	(void)state;
	if (!have("bash"))
		skip();
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/scene.rdl", dir);
	fclose(fopen(path, "w"));
	snprintf(path, sizeof(path), "%s/shot.png", dir);
	fclose(fopen(path, "w"));
	snprintf(path, sizeof(path), "%s/scenes", dir);
	assert_int_equal(mkdir(path, 0700), 0);

	expect_completion(dir, "rdcctl r", "regs replay run ");
	expect_completion(dir, "rdcctl st", "stats stream ");
	expect_completion(dir, "rdcctl --connect sim: re", "regs replay ");
	expect_completion(dir, "rdcctl --c", "--connect ");
	expect_completion(dir, "rdcctl run sc", "scene.rdl scenes ");
	expect_completion(dir, "rdcctl run scene.rdl -o s", "scenes shot.png ");
	expect_completion(dir, "rdcctl stream --f",
			  "--fast --format --frames --from ");
	expect_completion(dir, "rdcctl stream --format y", "yuyv ");
	expect_completion(dir, "rdcctl image encode --format b", "btc ");
	expect_completion(dir, "rdcctl pins --set B", "BL_EN=0 BL_EN=1 ");
	expect_completion(dir, "rdcctl pins --edges f", "falling ");
	expect_completion(dir, "rdcctl pen o", "off ");

	/* everything --help lists is offered somewhere */
	sibling("rdcctl", bin, sizeof(bin));
	snprintf(cmd, sizeof(cmd), "%s --help", bin);
	help = run(cmd, &st);
	assert_int_equal(st, 0);
	{
		char *c = complete(dir, "rdcctl ");
		char *s = complete(dir, "rdcctl stream --");
		char *p = complete(dir, "rdcctl pins --");
		char *r = complete(dir, "rdcctl run scene.rdl -");
		char *t = complete(dir, "rdcctl -");
		char *e = complete(dir, "rdcctl image encode --");
		char *l = complete(dir, "rdcctl pen 1 2 --");
		size_t len = strlen(c) + strlen(s) + strlen(p) + strlen(r) +
			     strlen(t) + strlen(e) + strlen(l) + 8;

		all = malloc(len);
		assert_non_null(all);
		snprintf(all, len, "%s %s %s %s %s %s %s", c, s, p, r, t, e, l);
		free(c);
		free(s);
		free(p);
		free(r);
		free(t);
		free(e);
		free(l);
	}
	n = options_of(help, opts, 64);
	for (int i = 0; i < n; i++)
		if (!has_word(all, opts[i]))
			fail_msg("completion never offers %s", opts[i]);
	assert_non_null(strstr(help, "commands:\n"));
	for (const char *w = strstr(help, "commands:\n") + 10; w && *w;
	     w = strchr(w, '\n') ? strchr(w, '\n') + 1 : NULL) {
		char word[32];

		if (*w == '\n')
			break;
		if (command_at(w, word) && !has_word(all, word))
			fail_msg("completion never offers the command %s",
				 word);
	}
	free(all);
	free(help);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	assert_int_equal(system(cmd), 0);
}

static void test_udev_rule(void **state)
{
	char *rules = read_file("dist/udev/70-rdc.rules");
	char vid[64], pid[64];
	int found = 0;

	(void)state;
	snprintf(vid, sizeof(vid), "ATTR{idVendor}==\"%04x\"", RDC_USB_VID);
	snprintf(pid, sizeof(pid), "ATTR{idProduct}==\"%04x\"", RDC_USB_PID);
	for (char *line = strtok(rules, "\n"); line; line = strtok(NULL, "\n"))
		if (line[0] != '#' && strstr(line, vid) && strstr(line, pid) &&
		    strstr(line, "SUBSYSTEM==\"usb\"") &&
		    strstr(line, "TAG+=\"uaccess\""))
			found++;
	if (found != 1)
		fail_msg("70-rdc.rules: want one rule with %s, %s, "
			 "SUBSYSTEM==\"usb\" and TAG+=\"uaccess\"",
			 vid, pid);
	free(rules);
}

static void test_systemd_units(void **state)
{
	char dir[] = "/tmp/rdc-units-XXXXXX", bin[4200], cmd[9000];
	char *out;
	int st;

	(void)state;
	if (!have("systemd-analyze")) {
		print_message("systemd-analyze is not installed: the units "
			      "are not verified\n");
		skip();
	}
	sibling("rdcd", bin, sizeof(bin));
	assert_non_null(mkdtemp(dir));
	/* ExecStart=rdcd is found on the installed system's path; here it
	 * is the build's */
	snprintf(cmd, sizeof(cmd),
		 "sed 's|^ExecStart=rdcd|ExecStart=%s|' "
		 "dist/systemd/rdcd.service >%s/rdcd.service && "
		 "cp dist/systemd/rdcd.socket %s/ && "
		 "grep -q '^ExecStart=%s' %s/rdcd.service && "
		 "XDG_RUNTIME_DIR=%s systemd-analyze --user --man=no verify "
		 "%s/rdcd.service %s/rdcd.socket 2>&1",
		 bin, dir, dir, bin, dir, dir, dir, dir);
	out = run(cmd, &st);
	if (st || *out)
		fail_msg("systemd-analyze verify: %s", out);
	free(out);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	assert_int_equal(system(cmd), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_man_no_warnings),
		cmocka_unit_test(test_man_rdcctl_matches_help),
		cmocka_unit_test(test_man_rdcd_matches_help),
		cmocka_unit_test(test_man_rdl_statements),
		cmocka_unit_test(test_man_librdc_api),
		cmocka_unit_test(test_bash_completion),
		cmocka_unit_test(test_udev_rule),
		cmocka_unit_test(test_systemd_units),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
