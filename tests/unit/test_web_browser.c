// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web page in a real browser (tests/web/browser.py): rdcd --web with
 * a scene, headless Chromium through chromedriver, the screenshot's
 * canvas against the frame rdcctl saved, pixel for pixel, then again
 * after a second script changes part of the picture.  Skipped, saying
 * why, where Python 3, Chromium or chromedriver is missing (Debian:
 * python3, chromium, chromium-driver; scripts/deps.sh installs them).
 */
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

/* browser.py's exit status for "cannot run here" */
#define BROWSER_SKIP 77

static void test_browser(void **state)
{
	char exe[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
	char *slash;
	pid_t pid;
	int st;

	(void)state;
	assert_true(n > 0);
	exe[n] = '\0';
	/* $(O)/san/tests/test_web_browser: rdcd and rdcctl are in $(O)/san */
	for (int i = 0; i < 2; i++) {
		slash = strrchr(exe, '/');
		assert_non_null(slash);
		*slash = '\0';
	}
	if (access("tests/web/browser.py", R_OK)) {
		print_message("not run from the source tree: no "
			      "tests/web/browser.py\n");
		skip();
	}
	fflush(stdout);
	pid = fork();
	assert_true(pid >= 0);
	if (!pid) {
		execlp("python3", "python3", "tests/web/browser.py", exe,
		       (char *)NULL);
		printf("SKIP: python3: %s (Debian: python3)\n",
		       strerror(errno));
		fflush(stdout);
		_exit(BROWSER_SKIP);
	}
	assert_int_equal(waitpid(pid, &st, 0), pid);
	assert_true(WIFEXITED(st));
	if (WEXITSTATUS(st) == BROWSER_SKIP)
		skip();
	assert_int_equal(WEXITSTATUS(st), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_browser),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
