// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * TCP addresses and token files (rdc_server.h): the one rule of rdcd's
 * tcp: and --token, the web sink's address and token=FILE, and the
 * client's tcp:HOST:PORT?token=FILE.  Written once so that the three
 * cannot drift apart: a token file one of them cut and another refused,
 * an address one of them took and another did not, were what came of
 * three copies.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rdc_priv.h"

/* Bytes read past the limit, so that trailing newlines are dropped and
 * a token that really is longer is told apart from one with them. */
#define TOKEN_SLACK 4096u

int rdc_tcp_split(const char *hostport, char host[RDC_TCP_HOST_MAX],
		  const char **port)
{
	const char *colon = strrchr(hostport, ':'), *h = hostport;
	size_t hl;

	if (!colon || !colon[1])
		return rdc_err_detail(RDC_E_URI, "%.200s: HOST:PORT expected",
				      hostport);
	hl = (size_t)(colon - hostport);
	/* [::1]:7000 */
	if (hl >= 2 && h[0] == '[' && h[hl - 1] == ']') {
		h++;
		hl -= 2;
	}
	if (hl >= RDC_TCP_HOST_MAX)
		return rdc_err_detail(RDC_E_URI, "%.200s: host too long",
				      hostport);
	if (!hl) {
		strcpy(host, "127.0.0.1");
	} else {
		memcpy(host, h, hl);
		host[hl] = '\0';
	}
	*port = colon + 1;
	return 0;
}

int rdc_tcp_listen(const char *hostport, int backlog,
		   struct sockaddr_storage *bound)
{
	struct addrinfo hints = { .ai_socktype = SOCK_STREAM,
				  .ai_flags = AI_PASSIVE | AI_NUMERICSERV };
	char host[RDC_TCP_HOST_MAX], *end;
	socklen_t sl = sizeof(*bound);
	struct addrinfo *res;
	const char *port;
	unsigned long pn;
	int fd, one = 1, ret;

	ret = rdc_tcp_split(hostport, host, &port);
	if (ret)
		return ret;
	errno = 0;
	pn = strtoul(port, &end, 10);
	if (*port < '0' || *port > '9' || *end || errno || pn > 65535)
		return rdc_err_detail(RDC_E_URI,
				      "%.200s: PORT is a number up to 65535",
				      hostport);
	if (getaddrinfo(host, port, &hints, &res))
		return rdc_err_detail(RDC_E_URI, "%.200s: cannot resolve",
				      hostport);
	fd = socket(res->ai_family,
		    res->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC,
		    res->ai_protocol);
	if (fd < 0) {
		freeaddrinfo(res);
		return rdc_err_detail(RDC_E_IO, "%.200s: socket: %s", hostport,
				      strerror(errno));
	}
	setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
	if (bind(fd, res->ai_addr, res->ai_addrlen) || listen(fd, backlog) ||
	    getsockname(fd, (struct sockaddr *)bound, &sl)) {
		ret = rdc_err_detail(RDC_E_IO, "%.200s: %s", hostport,
				     strerror(errno));
		freeaddrinfo(res);
		close(fd);
		return ret;
	}
	freeaddrinfo(res);
	return fd;
}

bool rdc_tcp_is_loopback(const struct sockaddr_storage *ss)
{
	if (ss->ss_family == AF_INET) {
		const struct sockaddr_in *in = (const void *)ss;

		return (ntohl(in->sin_addr.s_addr) >> 24) == 127;
	}
	if (ss->ss_family == AF_INET6) {
		const struct sockaddr_in6 *in6 = (const void *)ss;

		return IN6_IS_ADDR_LOOPBACK(&in6->sin6_addr) ||
		       (IN6_IS_ADDR_V4MAPPED(&in6->sin6_addr) &&
			in6->sin6_addr.s6_addr[12] == 127);
	}
	return false;
}

void rdc_tcp_name(const struct sockaddr_storage *ss,
		  char name[RDC_TCP_NAME_MAX])
{
	char addr[INET6_ADDRSTRLEN] = "?";

	if (ss->ss_family == AF_INET6) {
		const struct sockaddr_in6 *in6 = (const void *)ss;

		inet_ntop(AF_INET6, &in6->sin6_addr, addr, sizeof(addr));
		snprintf(name, RDC_TCP_NAME_MAX, "[%s]:%u", addr,
			 ntohs(in6->sin6_port));
	} else if (ss->ss_family == AF_INET) {
		const struct sockaddr_in *in = (const void *)ss;

		inet_ntop(AF_INET, &in->sin_addr, addr, sizeof(addr));
		snprintf(name, RDC_TCP_NAME_MAX, "%s:%u", addr,
			 ntohs(in->sin_port));
	} else {
		snprintf(name, RDC_TCP_NAME_MAX, "?");
	}
}

/* What a file that is not a regular one is, for a refusal. */
static const char *token_file_kind(mode_t m)
{
	return S_ISDIR(m)  ? "a directory" :
	       S_ISFIFO(m) ? "a FIFO" :
	       S_ISSOCK(m) ? "a socket" :
	       S_ISCHR(m)  ? "a character device" :
	       S_ISBLK(m)  ? "a block device" :
			     "of another kind";
}

/*
 * A longer file is refused, not cut: a client that sent the first
 * RDC_PROTO_MAX_TOKEN bytes of it would be told its token is wrong, and
 * a server that kept them would take a token its owner never meant.
 */
int rdc_token_read(const char *what, const char *path,
		   uint8_t tok[RDC_PROTO_MAX_TOKEN], uint32_t *len)
{
	uint8_t buf[RDC_PROTO_MAX_TOKEN + TOKEN_SLACK];
	int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
	struct stat st;
	size_t n = 0;
	bool more;

	*len = 0;
	if (fd < 0 || fstat(fd, &st)) {
		int ret = rdc_err_detail(RDC_E_FILE, "%s %s: %s", what, path,
					 strerror(errno));

		if (fd >= 0)
			close(fd);
		return ret;
	}
	if (!S_ISREG(st.st_mode)) {
		close(fd);
		return rdc_err_detail(RDC_E_FILE,
				      "%s %s: %s, not a regular file: refused",
				      what, path, token_file_kind(st.st_mode));
	}
	for (;;) {
		ssize_t k = read(fd, buf + n, sizeof(buf) - n);

		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0) {
			int ret = rdc_err_detail(RDC_E_FILE, "%s %s: %s", what,
						 path, strerror(errno));

			close(fd);
			return ret;
		}
		n += (size_t)k;
		if (!k || n == sizeof(buf))
			break;
	}
	more = n == sizeof(buf) && read(fd, &(uint8_t){ 0 }, 1) > 0;
	close(fd);
	while (n &&
	       (buf[n - 1] == '\n' || buf[n - 1] == '\r' || buf[n - 1] == ' '))
		n--;
	if (!n)
		return rdc_err_detail(RDC_E_FILE, "%s %s: empty", what, path);
	if (more || n > RDC_PROTO_MAX_TOKEN)
		return rdc_err_detail(RDC_E_FILE,
				      "%s %s: longer than %u bytes (a HELLO "
				      "carries no more): refused",
				      what, path, RDC_PROTO_MAX_TOKEN);
	memcpy(tok, buf, n);
	*len = (uint32_t)n;
	return 0;
}
