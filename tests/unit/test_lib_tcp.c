// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The one rule for TCP addresses and token files (rdc_tcp_*,
 * rdc_token_read, rdc_server.h) that rdcd, the web sink and the tcp:
 * client share: :PORT is 127.0.0.1, brackets around IPv6, the loopback
 * test; a token file is a regular file of 1 to 256 bytes without its
 * trailing newlines, and anything else is refused with the file's name,
 * never cut.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "rdc_server.h"

static void test_split(void **state)
{
	char host[RDC_TCP_HOST_MAX], big[RDC_TCP_HOST_MAX + 8];
	const char *port;

	(void)state;
	assert_int_equal(rdc_tcp_split("example.org:7000", host, &port), 0);
	assert_string_equal(host, "example.org");
	assert_string_equal(port, "7000");
	/* :PORT is loopback's */
	assert_int_equal(rdc_tcp_split(":7000", host, &port), 0);
	assert_string_equal(host, "127.0.0.1");
	assert_string_equal(port, "7000");
	assert_int_equal(rdc_tcp_split("[::1]:0", host, &port), 0);
	assert_string_equal(host, "::1");
	assert_string_equal(port, "0");
	assert_int_equal(rdc_tcp_split("::1:80", host, &port), 0);
	assert_string_equal(host, "::1");

	assert_int_equal(rdc_tcp_split("7000", host, &port), RDC_E_URI);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_URI), "7000"));
	assert_int_equal(rdc_tcp_split("host:", host, &port), RDC_E_URI);
	assert_int_equal(rdc_tcp_split("", host, &port), RDC_E_URI);
	memset(big, 'a', sizeof(big));
	big[RDC_TCP_HOST_MAX] = ':';
	big[RDC_TCP_HOST_MAX + 1] = '1';
	big[RDC_TCP_HOST_MAX + 2] = 0;
	assert_int_equal(rdc_tcp_split(big, host, &port), RDC_E_URI);
	big[RDC_TCP_HOST_MAX - 1] = ':';
	big[RDC_TCP_HOST_MAX] = '1';
	big[RDC_TCP_HOST_MAX + 1] = 0;
	assert_int_equal(rdc_tcp_split(big, host, &port), 0);
	assert_int_equal(strlen(host), RDC_TCP_HOST_MAX - 1);
}

static void test_listen(void **state)
{
	struct sockaddr_storage ss;
	char name[RDC_TCP_NAME_MAX];
	int fd;

	(void)state;
	fd = rdc_tcp_listen(":0", 4, &ss);
	assert_true(fd >= 0);
	assert_true(rdc_tcp_is_loopback(&ss));
	rdc_tcp_name(&ss, name);
	assert_true(!strncmp(name, "127.0.0.1:", 10));
	assert_true(atoi(name + 10) > 0);
	close(fd);

	fd = rdc_tcp_listen("0.0.0.0:0", 4, &ss);
	assert_true(fd >= 0);
	assert_false(rdc_tcp_is_loopback(&ss));
	close(fd);

	/* IPv6 may be off here: then it says so, as an error */
	fd = rdc_tcp_listen("[::1]:0", 4, &ss);
	if (fd >= 0) {
		assert_true(rdc_tcp_is_loopback(&ss));
		rdc_tcp_name(&ss, name);
		assert_true(!strncmp(name, "[::1]:", 6));
		close(fd);
	}

	assert_int_equal(rdc_tcp_listen(":x", 4, &ss), RDC_E_URI);
	assert_int_equal(rdc_tcp_listen(":70000", 4, &ss), RDC_E_URI);
	assert_int_equal(rdc_tcp_listen(":-1", 4, &ss), RDC_E_URI);
	assert_int_equal(rdc_tcp_listen("1.2.3.4.5:0", 4, &ss), RDC_E_URI);
	assert_non_null(
		strstr(rdc_last_error_detail(RDC_E_URI), "1.2.3.4.5:0"));
}

static void test_loopback(void **state)
{
	struct sockaddr_storage ss = { 0 };
	struct sockaddr_in *in = (void *)&ss;
	struct sockaddr_in6 *in6 = (void *)&ss;

	(void)state;
	in->sin_family = AF_INET;
	inet_pton(AF_INET, "127.1.2.3", &in->sin_addr);
	assert_true(rdc_tcp_is_loopback(&ss));
	inet_pton(AF_INET, "128.0.0.1", &in->sin_addr);
	assert_false(rdc_tcp_is_loopback(&ss));
	memset(&ss, 0, sizeof(ss));
	in6->sin6_family = AF_INET6;
	inet_pton(AF_INET6, "::1", &in6->sin6_addr);
	assert_true(rdc_tcp_is_loopback(&ss));
	inet_pton(AF_INET6, "::ffff:127.0.0.9", &in6->sin6_addr);
	assert_true(rdc_tcp_is_loopback(&ss));
	inet_pton(AF_INET6, "::ffff:10.0.0.1", &in6->sin6_addr);
	assert_false(rdc_tcp_is_loopback(&ss));
	inet_pton(AF_INET6, "::", &in6->sin6_addr);
	assert_false(rdc_tcp_is_loopback(&ss));
	ss.ss_family = AF_UNIX;
	assert_false(rdc_tcp_is_loopback(&ss));
}

static void write_file(const char *path, const char *s, size_t n)
{
	FILE *f = fopen(path, "wb");

	assert_non_null(f);
	assert_int_equal(fwrite(s, 1, n, f), n);
	fclose(f);
}

static void test_token(void **state)
{
	uint8_t tok[RDC_PROTO_MAX_TOKEN];
	char path[64], fifo[64], big[RDC_PROTO_MAX_TOKEN + 8200];
	const char *why;
	uint32_t len;

	(void)state;
	snprintf(path, sizeof(path), "/tmp/rdc-tcp-tok-%d", (int)getpid());
	snprintf(fifo, sizeof(fifo), "/tmp/rdc-tcp-fifo-%d", (int)getpid());

	write_file(path, "s3cret\r\n \n", 10);
	assert_int_equal(rdc_token_read("--token", path, tok, &len), 0);
	assert_int_equal(len, 6);
	assert_memory_equal(tok, "s3cret", 6);

	/* exactly the limit, then trailing newlines past it: taken */
	memset(big, 'x', sizeof(big));
	write_file(path, big, RDC_PROTO_MAX_TOKEN);
	assert_int_equal(rdc_token_read("t", path, tok, &len), 0);
	assert_int_equal(len, RDC_PROTO_MAX_TOKEN);
	memset(big + RDC_PROTO_MAX_TOKEN, '\n', 100);
	write_file(path, big, RDC_PROTO_MAX_TOKEN + 100);
	assert_int_equal(rdc_token_read("t", path, tok, &len), 0);
	assert_int_equal(len, RDC_PROTO_MAX_TOKEN);

	/* one byte more: refused, not cut */
	memset(big, 'x', sizeof(big));
	write_file(path, big, RDC_PROTO_MAX_TOKEN + 1);
	assert_int_equal(rdc_token_read("--token", path, tok, &len),
			 RDC_E_FILE);
	assert_int_equal(len, 0);
	why = rdc_last_error_detail(RDC_E_FILE);
	assert_non_null(strstr(why, "--token "));
	assert_non_null(strstr(why, path));
	assert_non_null(strstr(why, "longer than 256 bytes"));
	/* far longer, past what is read */
	write_file(path, big, sizeof(big));
	assert_int_equal(rdc_token_read("t", path, tok, &len), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "longer than 256 bytes"));

	/* empty, or nothing but newlines */
	write_file(path, "\n\n", 2);
	assert_int_equal(rdc_token_read("t", path, tok, &len), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), "empty"));
	unlink(path);

	/* missing, a directory, a FIFO (at once: no writer is waited for) */
	assert_int_equal(rdc_token_read("t", path, tok, &len), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE), path));
	assert_int_equal(rdc_token_read("t", "/tmp", tok, &len), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "t /tmp: a directory, not a regular file"));
	unlink(fifo);
	assert_int_equal(mkfifo(fifo, 0600), 0);
	assert_int_equal(rdc_token_read("t", fifo, tok, &len), RDC_E_FILE);
	assert_non_null(strstr(rdc_last_error_detail(RDC_E_FILE),
			       "a FIFO, not a regular file"));
	unlink(fifo);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_split),
		cmocka_unit_test(test_listen),
		cmocka_unit_test(test_loopback),
		cmocka_unit_test(test_token),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
