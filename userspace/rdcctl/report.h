/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_REPORT_H
#define RDCCTL_REPORT_H

#include <stdio.h>
#include <string.h>

#include "rdc.h"

/*
 * The exit status of every command (rdcctl(1), EXIT STATUS): 0 success,
 * 1 an error (said on stderr), 2 bad usage (said before any device is
 * opened), RDCCTL_EXIT_DIFFERS when a command that compares found a
 * difference: diff's two runs, replay's trace against its replay.
 */
#define RDCCTL_EXIT_DIFFERS 3

/*
 * "rdcctl: WHAT: ERROR: DETAIL" on stderr: the error's name, then what
 * librdc knows of its cause (rdc_last_error_detail: the system's reason,
 * a hint), when it knows something.  A detail that starts with `name`
 * (the path or URI already in WHAT) loses it, so it is not said twice.
 */
static inline void rdcctl_report(const char *what, const char *name, int err)
{
	const char *d = rdc_last_error_detail(err);
	size_t n = name ? strlen(name) : 0;

	if (n && !strncmp(d, name, n) && !strncmp(d + n, ": ", 2))
		d += n + 2;
	fprintf(stderr, "rdcctl: %s: %s%s%s\n", what, rdc_strerror(err),
		*d ? ": " : "", d);
}

/* An error about `what`, a file, a URI or a step. */
static inline void rdcctl_error(const char *what, int err)
{
	rdcctl_report(what, what, err);
}

/*
 * rdc_script_run_file(path) failed: "FILE:LINE:COL: error: ..." for an
 * error in the script, else what the interpreter said (a file it could
 * not read, with the system's reason), else the error's name.
 */
static inline void rdcctl_script_error(const char *path, int err,
				       const struct rdc_script_result *res)
{
	if (res->error_line && res->error_col)
		fprintf(stderr, "%s:%u:%u: error: %s\n", path, res->error_line,
			res->error_col, res->error_msg);
	else if (res->error_line)
		fprintf(stderr, "%s:%u: error: %s\n", path, res->error_line,
			res->error_msg);
	else if (res->error_msg[0])
		fprintf(stderr, "rdcctl: %s\n", res->error_msg);
	else
		rdcctl_error(path, err);
}

/*
 * Where subcommand `cmd` stands in argv after rdcctl's leading --uri /
 * --connect options (their URI to *uri), or -1 if argv is not that
 * subcommand or an option lacks its value.
 */
static inline int rdcctl_command_at(int argc, char **argv, const char *cmd,
				    const char **uri)
{
	int i = 1;

	while (i < argc) {
		const char *a = argv[i];

		if (!strncmp(a, "--uri=", 6) || !strncmp(a, "--connect=", 10)) {
			*uri = strchr(a, '=') + 1;
			i++;
		} else if (!strcmp(a, "--uri") || !strcmp(a, "--connect")) {
			if (i + 1 >= argc)
				return -1;
			*uri = argv[i + 1];
			i += 2;
		} else {
			break;
		}
	}
	if (i >= argc || strcmp(argv[i], cmd))
		return -1;
	return i;
}

/* rdcctl --record FILE (rdcctl.c): NULL when not given. */
extern const char *rdcctl_record_path;
/*
 * rdc_open(uri), and the handle recorded into rdcctl_record_path when
 * --record is given (rdc_close ends the trace); errors are reported.
 */
int rdcctl_open(const char *uri, rdc_dev **dev);

/* --record TRACE failed: "--record TRACE: ERROR: the reason". */
static inline void rdcctl_record_error(const char *path, int err)
{
	char what[300];

	snprintf(what, sizeof(what), "--record %s", path);
	rdcctl_report(what, path, err);
}

/* rdc_open(uri) failed. */
static inline void rdcctl_open_error(const char *uri, int err)
{
	char what[300];

	snprintf(what, sizeof(what), "cannot open '%s'", uri);
	rdcctl_report(what, uri, err);
}

#endif
