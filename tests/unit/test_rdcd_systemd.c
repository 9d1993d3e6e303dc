// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcd under systemd's socket activation: the test plays systemd, making
 * the listening sockets, passing them as descriptors 3, 4, ... with
 * LISTEN_PID, LISTEN_FDS and LISTEN_FDNAMES (sd_listen_fds(3)) and a
 * NOTIFY_SOCKET, then talks to the daemon through them.  A passed
 * descriptor that is not a listening stream socket, variables meant for
 * another process, or a non-loopback TCP socket without --token make
 * rdcd refuse to start with a message naming the cause.
 */
#include <netinet/in.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "rdc.h"
#include "test_net_common.h"

#define SD_MAX 4

struct sd_run {
	pid_t pid;
	char dir[64];
	char ready[128];
	char log[128];
	char uris[SD_MAX][160];
	int nuris;
};

/* A listening socket at dir/name, or -1. */
static int sd_unix_listener(const char *dir, const char *name, char *path,
			    size_t cap)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);

	snprintf(path, cap, "%s/%s", dir, name);
	snprintf(sa.sun_path, sizeof(sa.sun_path), "%s", path);
	if (fd < 0 || bind(fd, (struct sockaddr *)&sa, sizeof(sa)) ||
	    listen(fd, 8)) {
		if (fd >= 0)
			close(fd);
		return -1;
	}
	return fd;
}

/* A listening TCP socket on addr (network order), port chosen by the
 * kernel; its port in *port. */
static int sd_tcp_listener(uint32_t addr, int *port)
{
	struct sockaddr_in in = { .sin_family = AF_INET,
				  .sin_addr.s_addr = addr };
	socklen_t sl = sizeof(in);
	int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);

	if (fd < 0 || bind(fd, (struct sockaddr *)&in, sizeof(in)) ||
	    listen(fd, 8) || getsockname(fd, (struct sockaddr *)&in, &sl)) {
		if (fd >= 0)
			close(fd);
		return -1;
	}
	*port = ntohs(in.sin_port);
	return fd;
}

/*
 * Start rdcd with fds[0..n-1] as descriptors 3.. and the environment
 * systemd would give it; pid_env NULL means its own pid.  0 once its
 * ready file is there (uris filled), 1 if it exited first (its status
 * in *status), -1 on a failure of the test's own.
 */
static int sd_start(struct sd_run *r, const int *fds, int n, const char *names,
		    const char *pid_env, const char *notify,
		    const char *const *args, int *status)
{
	char daemon[4200];
	const char *argv[24];
	int k = 0;

	if (netd_daemon_path(daemon, sizeof(daemon)))
		return -1;
	snprintf(r->ready, sizeof(r->ready), "%s/ready", r->dir);
	snprintf(r->log, sizeof(r->log), "%s/log", r->dir);
	argv[k++] = daemon;
	argv[k++] = "--stepped";
	argv[k++] = "--ready-file";
	argv[k++] = r->ready;
	for (; args && *args && k < 22; args++)
		argv[k++] = *args;
	argv[k] = NULL;
	r->pid = fork();
	if (r->pid < 0)
		return -1;
	if (r->pid == 0) {
		char num[32];
		int hi[SD_MAX], fd;

		prctl(PR_SET_PDEATHSIG, SIGKILL);
		fd = open(r->log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
		if (fd < 0 || dup2(fd, 1) < 0 || dup2(fd, 2) < 0)
			_exit(127);
		/* out of the way of 3.., then into place, inheritable */
		for (int i = 0; i < n; i++)
			if ((hi[i] = fcntl(fds[i], F_DUPFD, 100)) < 0)
				_exit(127);
		for (int i = 0; i < n; i++)
			if (dup2(hi[i], 3 + i) < 0)
				_exit(127);
		snprintf(num, sizeof(num), "%ld", (long)getpid());
		setenv("LISTEN_PID", pid_env ? pid_env : num, 1);
		snprintf(num, sizeof(num), "%d", n);
		setenv("LISTEN_FDS", num, 1);
		if (names)
			setenv("LISTEN_FDNAMES", names, 1);
		else
			unsetenv("LISTEN_FDNAMES");
		if (notify)
			setenv("NOTIFY_SOCKET", notify, 1);
		else
			unsetenv("NOTIFY_SOCKET");
		execv(daemon, (char *const *)argv);
		_exit(127);
	}
	for (int waited = 0; waited < NETD_START_MS; waited += 10) {
		FILE *f = fopen(r->ready, "r");

		if (f) {
			char line[160];

			r->nuris = 0;
			while (r->nuris < SD_MAX &&
			       fgets(line, sizeof(line), f)) {
				line[strcspn(line, "\n")] = 0;
				snprintf(r->uris[r->nuris++],
					 sizeof(r->uris[0]), "%s", line);
			}
			fclose(f);
			return 0;
		}
		if (waitpid(r->pid, status, WNOHANG) == r->pid) {
			r->pid = 0;
			return 1;
		}
		netd_sleep_ms(10);
	}
	return -1;
}

/* SIGTERM and the exit status (0: clean, no sanitizer report). */
static int sd_stop(struct sd_run *r)
{
	int st, ret = -1;

	if (r->pid <= 0)
		return -1;
	kill(r->pid, SIGTERM);
	for (int waited = 0; waited < NETD_STOP_MS; waited += 10) {
		if (waitpid(r->pid, &st, WNOHANG) == r->pid) {
			ret = WIFEXITED(st) ? WEXITSTATUS(st) : 128;
			break;
		}
		netd_sleep_ms(10);
	}
	if (ret == -1) {
		kill(r->pid, SIGKILL);
		waitpid(r->pid, &st, 0);
	}
	r->pid = 0;
	return ret;
}

static void sd_dump_log(const struct sd_run *r)
{
	struct netd d;

	snprintf(d.log, sizeof(d.log), "%s", r->log);
	netd_dump_log(&d);
}

static int sd_log_has(const struct sd_run *r, const char *s)
{
	struct netd d;

	snprintf(d.log, sizeof(d.log), "%s", r->log);
	return netd_log_has(&d, s);
}

static int sd_setup(void **state)
{
	struct sd_run *r = calloc(1, sizeof(*r));

	if (!r)
		return -1;
	snprintf(r->dir, sizeof(r->dir), "/tmp/rdcd-sd-XXXXXX");
	if (!mkdtemp(r->dir)) {
		free(r);
		return -1;
	}
	*state = r;
	return 0;
}

static int sd_teardown(void **state)
{
	struct sd_run *r = *state;
	char cmd[200];

	if (r->pid > 0)
		sd_stop(r);
	/* only files this test made: the directory's whole contents */
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", r->dir);
	if (system(cmd))
		fprintf(stderr, "could not remove %s\n", r->dir);
	free(r);
	return 0;
}

/* The same small scene through uri and on sim:: the frame CRCs agree. */
static void sd_draw_and_compare(const char *uri)
{
	uint32_t crc[2];
	const char *uris[2] = { uri, "sim:" };

	for (int i = 0; i < 2; i++) {
		rdc_batch *b = rdc_batch_new();
		rdc_dev *dev;

		assert_non_null(b);
		assert_int_equal(rdc_open(uris[i], &dev), 0);
		assert_int_equal(rdc_mode_set(dev, RDC_PRESET_320x200_70,
					      RDC_FMT_XRGB8888, 0),
				 0);
		assert_int_equal(rdc_batch_fg(b, 0xff3080c0), 0);
		assert_int_equal(rdc_batch_fill_circle(b, 160, 100, 60), 0);
		assert_int_equal(rdc_batch_submit(dev, b), 0);
		assert_int_equal(rdc_finish(dev), 0);
		assert_int_equal(rdc_frame_wait(dev), 0);
		assert_int_equal(rdc_frame_crc(dev, &crc[i]), 0);
		rdc_close(dev);
		rdc_batch_free(b);
	}
	assert_int_equal(crc[0], crc[1]);
}

/* One UNIX socket, no --listen: rdcd takes it, serves it, leaves the
 * socket file (the socket unit's) in place at exit. */
static void test_unix_socket_passed(void **state)
{
	struct sd_run *r = *state;
	char path[128], uri[160];
	int fd = sd_unix_listener(r->dir, "rdc.sock", path, sizeof(path));
	int st = 0;

	assert_true(fd >= 0);
	if (sd_start(r, &fd, 1, "rdc", NULL, NULL, NULL, &st)) {
		sd_dump_log(r);
		fail_msg("rdcd did not come up on a passed socket");
	}
	snprintf(uri, sizeof(uri), "unix:%s", path);
	assert_int_equal(r->nuris, 1);
	assert_string_equal(r->uris[0], uri);
	sd_draw_and_compare(uri);
	assert_int_equal(sd_stop(r), 0);
	assert_int_equal(access(path, F_OK), 0);
	assert_true(sd_log_has(r, "systemd fd 3, rdc"));
	close(fd);
}

/* --listen systemd:NAME takes the socket of that name only; the other
 * is closed with a warning. */
static void test_named_socket(void **state)
{
	struct sd_run *r = *state;
	char pa[128], pb[128], uri[160];
	int fds[2], st = 0;
	static const char *const args[] = { "--listen", "systemd:obs", NULL };

	fds[0] = sd_unix_listener(r->dir, "a.sock", pa, sizeof(pa));
	fds[1] = sd_unix_listener(r->dir, "b.sock", pb, sizeof(pb));
	assert_true(fds[0] >= 0 && fds[1] >= 0);
	if (sd_start(r, fds, 2, "ctl:obs", NULL, NULL, args, &st)) {
		sd_dump_log(r);
		fail_msg("rdcd did not come up");
	}
	snprintf(uri, sizeof(uri), "unix:%s", pb);
	assert_int_equal(r->nuris, 1);
	assert_string_equal(r->uris[0], uri);
	assert_true(sd_log_has(r, "fd 3 (ctl), which no --listen takes"));
	sd_draw_and_compare(uri);
	assert_int_equal(sd_stop(r), 0);
	close(fds[0]);
	close(fds[1]);
}

/* A loopback TCP socket and a UNIX one, all taken, in order. */
static void test_tcp_and_unix(void **state)
{
	struct sd_run *r = *state;
	char path[128], uri[160];
	int fds[2], port = 0, st = 0;

	fds[0] = sd_tcp_listener(htonl(INADDR_LOOPBACK), &port);
	fds[1] = sd_unix_listener(r->dir, "rdc.sock", path, sizeof(path));
	assert_true(fds[0] >= 0 && fds[1] >= 0);
	if (sd_start(r, fds, 2, NULL, NULL, NULL, NULL, &st)) {
		sd_dump_log(r);
		fail_msg("rdcd did not come up");
	}
	assert_int_equal(r->nuris, 2);
	snprintf(uri, sizeof(uri), "tcp:127.0.0.1:%d", port);
	assert_string_equal(r->uris[0], uri);
	sd_draw_and_compare(uri);
	snprintf(uri, sizeof(uri), "unix:%s", path);
	assert_string_equal(r->uris[1], uri);
	assert_int_equal(sd_stop(r), 0);
	close(fds[0]);
	close(fds[1]);
}

/* READY=1 once listening, STOPPING=1 on the way out. */
static void test_notify(void **state)
{
	struct sd_run *r = *state;
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	char path[128], msg[64];
	int fd, nfd, st = 0;
	ssize_t n;
	struct pollfd p;

	fd = sd_unix_listener(r->dir, "rdc.sock", path, sizeof(path));
	nfd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	snprintf(sa.sun_path, sizeof(sa.sun_path), "%s/notify", r->dir);
	assert_true(fd >= 0 && nfd >= 0);
	assert_int_equal(bind(nfd, (struct sockaddr *)&sa, sizeof(sa)), 0);
	if (sd_start(r, &fd, 1, NULL, NULL, sa.sun_path, NULL, &st)) {
		sd_dump_log(r);
		fail_msg("rdcd did not come up");
	}
	p = (struct pollfd){ .fd = nfd, .events = POLLIN };
	assert_int_equal(poll(&p, 1, NETD_IO_MS), 1);
	n = recv(nfd, msg, sizeof(msg) - 1, 0);
	assert_true(n > 0);
	msg[n] = 0;
	assert_string_equal(msg, "READY=1");
	assert_int_equal(sd_stop(r), 0);
	assert_int_equal(poll(&p, 1, NETD_IO_MS), 1);
	n = recv(nfd, msg, sizeof(msg) - 1, 0);
	assert_true(n > 0);
	msg[n] = 0;
	assert_string_equal(msg, "STOPPING=1");
	close(nfd);
	close(fd);
}

/* Start with these descriptors; rdcd must exit 1 saying `why`. */
static void sd_expect_refusal(struct sd_run *r, const int *fds, int n,
			      const char *pid_env, const char *const *args,
			      const char *why)
{
	int st = 0, ret = sd_start(r, fds, n, NULL, pid_env, NULL, args, &st);

	if (ret != 1) {
		sd_dump_log(r);
		fail_msg("rdcd started (or the test failed: %d)", ret);
	}
	assert_true(WIFEXITED(st));
	assert_int_equal(WEXITSTATUS(st), 1);
	if (!sd_log_has(r, why)) {
		sd_dump_log(r);
		fail_msg("the log does not say '%s'", why);
	}
}

static void test_not_listening(void **state)
{
	struct sd_run *r = *state;
	int fds[1];

	/* a stream socket nobody called listen() on */
	fds[0] = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	assert_true(fds[0] >= 0);
	sd_expect_refusal(r, fds, 1, NULL, NULL,
			  "fd 3 (unknown): not listening");
	close(fds[0]);
}

static void test_not_a_socket(void **state)
{
	struct sd_run *r = *state;
	int fds[1];

	fds[0] = open("/dev/null", O_RDONLY | O_CLOEXEC);
	assert_true(fds[0] >= 0);
	sd_expect_refusal(r, fds, 1, NULL, NULL,
			  "fd 3 (unknown): not a socket");
	close(fds[0]);
}

static void test_datagram_socket(void **state)
{
	struct sd_run *r = *state;
	int fds[1];

	fds[0] = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	assert_true(fds[0] >= 0);
	sd_expect_refusal(r, fds, 1, NULL, NULL, "not a stream socket");
	close(fds[0]);
}

/* Variables for another process: --listen systemd has nothing to take. */
static void test_other_pid(void **state)
{
	struct sd_run *r = *state;
	static const char *const args[] = { "--listen", "systemd", NULL };
	char path[128];
	int fd = sd_unix_listener(r->dir, "rdc.sock", path, sizeof(path));

	assert_true(fd >= 0);
	sd_expect_refusal(r, &fd, 1, "1", args,
			  "LISTEN_PID=1 is not this process");
	close(fd);
}

/* A TCP socket on every address needs --token, as tcp: does. */
static void test_tcp_any_needs_token(void **state)
{
	struct sd_run *r = *state;
	int port, fd = sd_tcp_listener(htonl(INADDR_ANY), &port);

	assert_true(fd >= 0);
	sd_expect_refusal(r, &fd, 1, NULL, NULL, "--token FILE is required");
	close(fd);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_unix_socket_passed,
						sd_setup, sd_teardown),
		cmocka_unit_test_setup_teardown(test_named_socket, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_tcp_and_unix, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_notify, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_not_listening, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_not_a_socket, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_datagram_socket, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_other_pid, sd_setup,
						sd_teardown),
		cmocka_unit_test_setup_teardown(test_tcp_any_needs_token,
						sd_setup, sd_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
