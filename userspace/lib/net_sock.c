// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The "unix:" and "tcp:" backends: the protocol client of net.c
 * (rdc_client.h) over a stream socket.  The socket transport's send,
 * receive and close, connecting (with what to try when nothing listens),
 * and listing the sockets in the default socket's directory.
 */
#include <dirent.h>
#include <errno.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <sys/un.h>
#include <unistd.h>

#include "rdc_client.h"
#include "rdc_priv.h"
#include "rdc_proto.h"

struct sock_xport {
	struct rdc_xport x;
	int fd;
};

static int sock_send(struct rdc_xport *x, const struct iovec *iov, int n)
{
	struct sock_xport *s = (struct sock_xport *)x;
	struct iovec v[4];
	struct msghdr mh = { .msg_iov = v, .msg_iovlen = (size_t)n };

	if (n < 0 || (size_t)n > RDC_ARRAY_SIZE(v))
		return RDC_E_INVAL;
	memcpy(v, iov, sizeof(*v) * (size_t)n);
	while (mh.msg_iovlen) {
		ssize_t k = sendmsg(s->fd, &mh, MSG_NOSIGNAL);

		if (k < 0) {
			if (errno == EINTR)
				continue;
			return rdc_err_detail(RDC_E_IO, "sending to rdcd: %s",
					      strerror(errno));
		}
		while (mh.msg_iovlen && (size_t)k >= mh.msg_iov->iov_len) {
			k -= (ssize_t)mh.msg_iov->iov_len;
			mh.msg_iov++;
			mh.msg_iovlen--;
		}
		if (mh.msg_iovlen) {
			mh.msg_iov->iov_base =
				(uint8_t *)mh.msg_iov->iov_base + k;
			mh.msg_iov->iov_len -= (size_t)k;
		}
	}
	return 0;
}

static ssize_t sock_recv(struct rdc_xport *x, void *buf, size_t len,
			 int timeout_ms)
{
	struct sock_xport *s = (struct sock_xport *)x;

	for (;;) {
		ssize_t k;

		if (timeout_ms >= 0) {
			struct pollfd pfd = { .fd = s->fd, .events = POLLIN };
			int r = poll(&pfd, 1, timeout_ms);

			if (r < 0 && errno == EINTR)
				continue;
			if (r == 0)
				return RDC_E_TIMEOUT;
			if (r < 0)
				return rdc_err_detail(RDC_E_IO, "poll: %s",
						      strerror(errno));
		}
		k = read(s->fd, buf, len);
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0)
			return rdc_err_detail(RDC_E_IO,
					      "receiving from rdcd: %s",
					      strerror(errno));
		if (k == 0)
			return rdc_err_detail(RDC_E_IO,
					      "rdcd closed the connection");
		return k;
	}
}

static void sock_close(struct rdc_xport *x)
{
	struct sock_xport *s = (struct sock_xport *)x;

	close(s->fd);
	free(s);
}

static const struct rdc_xport_ops sock_ops = {
	.send = sock_send,
	.recv = sock_recv,
	.close = sock_close,
};

/*
 * A connect() that failed: the address, the reason, and what to try.
 * For a socket path other than rdcd's default, the hint names the
 * default too (the path rdcd listens on without --listen), which a
 * path written from a variable unset here ($XDG_RUNTIME_DIR) misses.
 */
static int net_connect_failed(const char *uri)
{
	int err = errno;
	bool absent = err == ENOENT || err == ECONNREFUSED;
	char def[sizeof(((struct sockaddr_un *)0)->sun_path)];

	if (!absent)
		return rdc_err_detail(RDC_E_IO, "%s: connect: %s", uri,
				      strerror(err));
	if (!strncmp(uri, "unix:", 5) &&
	    !rdc_proto_default_path(def, sizeof(def)) && strcmp(uri + 5, def))
		return rdc_err_detail(
			RDC_E_IO,
			"%s: connect: %s (is rdcd running? without --listen "
			"it listens on unix:%s, which plain unix: reaches; or "
			"start it with rdcd --listen %s)",
			uri, strerror(err), def, uri);
	if (!strncmp(uri, "unix:", 5))
		return rdc_err_detail(RDC_E_IO,
				      "%s: connect: %s (is rdcd running? start "
				      "it with rdcd: without --listen it "
				      "listens there)",
				      uri, strerror(err));
	return rdc_err_detail(RDC_E_IO,
			      "%s: connect: %s (is rdcd running? start it with "
			      "rdcd --listen %s)",
			      uri, strerror(err), uri);
}

static int net_connect_unix(const char *path)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	char def[sizeof(sa.sun_path)];
	int fd;

	if (!*path) {
		if (rdc_proto_default_path(def, sizeof(def)))
			return RDC_E_URI;
		path = def;
	}
	if (strlen(path) >= sizeof(sa.sun_path))
		return rdc_err_detail(RDC_E_URI,
				      "unix:%.200s: a socket path has at most "
				      "%zu bytes",
				      path, sizeof(sa.sun_path) - 1);
	strcpy(sa.sun_path, path);
	fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	if (fd < 0)
		return rdc_err_detail(RDC_E_IO, "socket: %s", strerror(errno));
	if (connect(fd, (struct sockaddr *)&sa, sizeof(sa))) {
		char uri[300]; /* "unix:" and up to 255 bytes */
		int ret;

		snprintf(uri, sizeof(uri), "unix:%s", path);
		ret = net_connect_failed(uri);
		close(fd);
		return ret;
	}
	return fd;
}

static int net_connect_tcp(const char *hostport)
{
	char host[RDC_TCP_HOST_MAX];
	struct addrinfo hints = { .ai_socktype = SOCK_STREAM }, *res, *ai;
	const char *whole = hostport, *port;
	char uri[300]; /* "tcp:" and up to 255 bytes */
	int fd = RDC_E_IO, ret;

	ret = rdc_tcp_split(hostport, host, &port);
	if (ret) {
		snprintf(uri, sizeof(uri), "%s", rdc_last_error_detail(ret));
		return rdc_err_detail(ret, "tcp:%s", uri);
	}
	ret = getaddrinfo(host, port, &hints, &res);
	if (ret)
		return rdc_err_detail(RDC_E_URI, "tcp:%.200s: %s", whole,
				      gai_strerror(ret));
	for (ai = res; ai; ai = ai->ai_next) {
		int one = 1;

		fd = socket(ai->ai_family, ai->ai_socktype | SOCK_CLOEXEC,
			    ai->ai_protocol);
		if (fd < 0) {
			fd = rdc_err_detail(RDC_E_IO, "socket: %s",
					    strerror(errno));
			continue;
		}
		if (!connect(fd, ai->ai_addr, ai->ai_addrlen)) {
			/* requests are small and synchronous */
			setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one,
				   sizeof(one));
			break;
		}
		snprintf(uri, sizeof(uri), "tcp:%s", whole);
		net_connect_failed(uri);
		close(fd);
		fd = RDC_E_IO;
	}
	freeaddrinfo(res);
	return fd;
}

static int net_open(rdc_dev *dev, const char *opts, bool tcp)
{
	const char *q = strchr(opts, '?');
	size_t alen = q ? (size_t)(q - opts) : strlen(opts);
	struct rdc_client_opts o;
	struct sock_xport *s;
	char addr[256]; /* path, or host:port */
	int ret;

	if (alen >= sizeof(addr))
		return RDC_E_URI;
	memcpy(addr, opts, alen);
	addr[alen] = 0;
	ret = rdc_client_parse_opts(q ? q + 1 : NULL, &o);
	if (ret)
		return ret;
	s = calloc(1, sizeof(*s));
	if (!s)
		return RDC_E_NOMEM;
	s->x.ops = &sock_ops;
	s->fd = tcp ? net_connect_tcp(addr) : net_connect_unix(addr);
	if (s->fd < 0) {
		ret = s->fd;
		free(s);
		return ret;
	}
	return rdc_client_open(dev, &s->x, &o);
}

static int net_open_unix(rdc_dev *dev, const char *opts)
{
	return net_open(dev, opts, false);
}

static int net_open_tcp(rdc_dev *dev, const char *opts)
{
	return net_open(dev, opts, true);
}

/*
 * The sockets in the default socket's directory that answer a HELLO (as
 * an observer: listing takes nobody's control away).
 */
static int net_list_unix(rdc_found_fn fn, void *arg)
{
	static const char *const mode[] = { "paced", "fast", "stepped" };
	char dir[sizeof(((struct sockaddr_un *)0)->sun_path)], *slash;
	struct dirent *e;
	int found = 0;
	DIR *d;

	if (rdc_proto_default_path(dir, sizeof(dir)))
		return 0;
	slash = strrchr(dir, '/');
	if (!slash)
		return 0;
	*slash = 0;
	d = opendir(dir);
	if (!d)
		return 0;
	while ((e = readdir(d))) {
		const struct rdc_proto_hello_reply *hr;
		struct rdc_found f;
		char path[sizeof(dir) + 256];
		struct stat st;
		rdc_dev *dev;

		memset(&f, 0, sizeof(f));
		if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir,
				     e->d_name) >= sizeof(path) ||
		    stat(path, &st) || !S_ISSOCK(st.st_mode) ||
		    (size_t)snprintf(f.uri, sizeof(f.uri), "unix:%s?observe",
				     path) >= sizeof(f.uri) ||
		    rdc_open(f.uri, &dev))
			continue;
		hr = rdc_client_hello(dev);
		*strrchr(f.uri, '?') = 0; /* the URI to control it */
		snprintf(f.info, sizeof(f.info),
			 "rdcd socket, %s, VRAM %u bytes",
			 hr->run_mode < RDC_ARRAY_SIZE(mode) ?
				 mode[hr->run_mode] :
				 "unknown mode",
			 hr->vram_size);
		rdc_close(dev);
		fn(&f, arg);
		found++;
	}
	closedir(d);
	return found;
}

const struct rdc_backend rdc_backend_unix = {
	.scheme = "unix",
	.open = net_open_unix,
	.list = net_list_unix,
	RDC_CLIENT_OPS,
};

const struct rdc_backend rdc_backend_tcp = {
	.scheme = "tcp",
	.open = net_open_tcp,
	RDC_CLIENT_OPS,
};
