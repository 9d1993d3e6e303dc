// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink: the live display in a browser (docs/web.md).
 *
 * The caller's thread only compares each frame with the last and notes,
 * per viewer, which rows changed and between which columns; the server
 * thread (web_server.c) asks rdc_web_pump for each viewer's next message
 * when its socket has room, and gets those rectangles as zlib-compressed
 * RGBA, then a status, so a picture that does not change sends nothing.
 *
 * Safe by default: loopback unless an address is given; with a token
 * (token=FILE) every viewer must present it, and an address other than
 * loopback needs one (rdcd's rule for tcp:; addresses and token files
 * are read as rdc_tcp_listen and rdc_token_read, rdc_server.h, read
 * them).
 */
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>
#include <zlib.h>

#include "web.h"

/* ---- Damage (under the mutex) ------------------------------------------ */

void rdc_web_damage_all(struct web_sink *w, struct web_conn *c)
{
	for (uint32_t y = 0; y < c->dh; y++) {
		c->dx0[y] = 0;
		c->dx1[y] = w->w;
	}
	c->dirty = c->dh > 0;
	c->status_due = c->sync_due = true;
	c->status_ns = 0;
}

bool rdc_web_damage_size(struct web_sink *w, struct web_conn *c)
{
	uint32_t *a, *b;

	if (c->dh == w->h && c->dx0)
		return true;
	a = realloc(c->dx0, (w->h ? w->h : 1) * sizeof(*a));
	if (a)
		c->dx0 = a;
	b = realloc(c->dx1, (w->h ? w->h : 1) * sizeof(*b));
	if (b)
		c->dx1 = b;
	if (!a || !b) {
		c->dh = 0;
		return false;
	}
	c->dh = w->h;
	return true;
}

/* ---- Status ------------------------------------------------------------ */

static const char *const web_fmt_names[RDC_FMT_COUNT] = {
	"I1", "I2", "I4", "I8", "RGB565", "RGB888", "XRGB8888",
};

static size_t web_status_json(const struct web_sink *w, char *b, size_t cap)
{
	const struct rdc_sink_status *st = &w->st;
	int n;

	n = snprintf(b, cap,
		     "{\"type\":\"status\",\"seq\":%llu,\"width\":%u,"
		     "\"height\":%u,\"interval\":[%u,%u]",
		     (unsigned long long)w->seq, w->w, w->h, w->inum, w->iden);
	if (w->have_st && (st->have & RDC_SINK_HAVE_TIME))
		n += snprintf(b + n, cap - (size_t)n,
			      ",\"time\":%llu,\"core_hz\":%u",
			      (unsigned long long)st->time, st->core_hz);
	if (w->have_st && (st->have & RDC_SINK_HAVE_PINS))
		n += snprintf(b + n, cap - (size_t)n, ",\"pins\":%u", st->pins);
	if (w->have_st && (st->have & RDC_SINK_HAVE_IRQ))
		n += snprintf(b + n, cap - (size_t)n,
			      ",\"irq_status\":%u,\"irq_enable\":%u",
			      st->irq_status, st->irq_enable);
	if (w->have_st && (st->have & RDC_SINK_HAVE_FORMAT) &&
	    st->format < RDC_FMT_COUNT)
		n += snprintf(b + n, cap - (size_t)n, ",\"format\":\"%s\"",
			      web_fmt_names[st->format]);
	n += snprintf(b + n, cap - (size_t)n, "}");
	return (size_t)n < cap ? (size_t)n : 0;
}

/* ---- The next message for a viewer ------------------------------------- */

/*
 * Take the next band of damage: consecutive dirty rows, their columns'
 * union, at most WEB_BAND_BYTES of RGBA; copy it out of the frame.
 */
static bool web_take_band(struct web_sink *w, struct web_conn *c, uint32_t r[4])
{
	uint32_t y = 0, x0 = UINT32_MAX, x1 = 0, y1;

	while (y < c->dh && !c->dx1[y])
		y++;
	if (y == c->dh) {
		c->dirty = false;
		return false;
	}
	for (y1 = y; y1 < c->dh && c->dx1[y1]; y1++) {
		uint32_t nx0 = RDC_MIN(x0, c->dx0[y1]);
		uint32_t nx1 = RDC_MAX(x1, c->dx1[y1]);

		if (y1 > y &&
		    (size_t)(nx1 - nx0) * (y1 - y + 1) * 4 > WEB_BAND_BYTES)
			break;
		x0 = nx0;
		x1 = nx1;
	}
	for (uint32_t yy = y; yy < y1; yy++) {
		const uint32_t *src = w->fb + (size_t)yy * w->w + x0;
		uint8_t *dst = w->rgba + (size_t)(yy - y) * (x1 - x0) * 4;

		for (uint32_t x = 0; x < x1 - x0; x++) {
			dst[4 * x] = (uint8_t)(src[x] >> 16);
			dst[4 * x + 1] = (uint8_t)(src[x] >> 8);
			dst[4 * x + 2] = (uint8_t)src[x];
			dst[4 * x + 3] = 0xff;
		}
		c->dx0[yy] = c->dx1[yy] = 0;
	}
	r[0] = x0;
	r[1] = y;
	r[2] = x1 - x0;
	r[3] = y1 - y;
	return true;
}

static void put32le(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

static bool web_send_rect(struct web_sink *w, struct web_conn *c,
			  const uint32_t r[4])
{
	uLong raw = (uLong)r[2] * r[3] * 4;
	uLongf zlen;
	size_t need = WEB_RECT_HDR + compressBound(raw);

	if (need > w->zcap) {
		uint8_t *nz = realloc(w->zbuf, need);

		if (!nz)
			return false;
		w->zbuf = nz;
		w->zcap = need;
	}
	put32le(w->zbuf, WEB_RECT_TYPE);
	for (int i = 0; i < 4; i++)
		put32le(w->zbuf + 4 + 4 * i, r[i]);
	zlen = (uLongf)(w->zcap - WEB_RECT_HDR);
	if (compress2(w->zbuf + WEB_RECT_HDR, &zlen, w->rgba, raw, 1) != Z_OK)
		return false;
	return rdc_web_conn_send(c, WEB_WS_BINARY, w->zbuf,
				 WEB_RECT_HDR + zlen);
}

/* Queue one message for a viewer whose queue is empty. */
void rdc_web_pump(struct web_sink *w, struct web_conn *c, uint64_t now)
{
	char json[WEB_JSON_MAX];
	size_t jn = 0;
	uint32_t r[4];
	bool rect = false;

	pthread_mutex_lock(&w->mu);
	if (c->dh != w->h && rdc_web_damage_size(w, c))
		rdc_web_damage_all(w, c);
	if (c->status_due && c->dirty && c->status_ns == 0) {
		/* a new size goes before its pixels */
		jn = web_status_json(w, json, sizeof(json));
		c->status_due = false;
		c->status_ns = now;
	} else if (c->dirty) {
		rect = web_take_band(w, c, r);
		c->sync_due |= rect;
	}
	if (!jn && !rect &&
	    (c->sync_due ||
	     (c->status_due && now >= c->status_ns + WEB_STATUS_NS))) {
		/* the picture is complete up to seq: say so at once */
		jn = web_status_json(w, json, sizeof(json));
		c->status_due = c->sync_due = false;
		c->status_ns = now;
	}
	pthread_mutex_unlock(&w->mu);
	if (rect) {
		if (!web_send_rect(w, c, r))
			c->dead = true;
	} else if (jn && !rdc_web_conn_send(c, WEB_WS_TEXT, json, jn)) {
		c->dead = true;
	}
}

/* ---- The sink ---------------------------------------------------------- */

int rdc_sink_have_web(void)
{
	return 1;
}

static int web_frame(rdc_sink *s, const struct rdc_frame *f)
{
	struct web_sink *w = s->priv;
	size_t row = (size_t)f->width * sizeof(uint32_t);
	bool changed = false;

	pthread_mutex_lock(&w->mu);
	if (f->width != w->w || f->height != w->h) {
		uint32_t *fb = malloc((size_t)f->width * f->height * 4);

		if (!fb) {
			pthread_mutex_unlock(&w->mu);
			return RDC_E_NOMEM;
		}
		free(w->fb);
		w->fb = fb;
		w->w = f->width;
		w->h = f->height;
		for (uint32_t y = 0; y < f->height; y++)
			memcpy(fb + (size_t)y * f->width,
			       f->xrgb + (size_t)y * f->stride, row);
		/* (no room for a viewer's damage: its thread tries again) */
		for (struct web_conn *c = w->conns; c; c = c->next)
			if (c->authed && rdc_web_damage_size(w, c))
				rdc_web_damage_all(w, c);
		changed = true;
	} else {
		for (uint32_t y = 0; y < f->height; y++) {
			const uint32_t *src = f->xrgb + (size_t)y * f->stride;
			uint32_t *dst = w->fb + (size_t)y * w->w;
			uint32_t x0 = 0, x1 = f->width;

			if (!memcmp(src, dst, row))
				continue;
			while (src[x0] == dst[x0])
				x0++;
			while (src[x1 - 1] == dst[x1 - 1])
				x1--;
			memcpy(dst + x0, src + x0, (x1 - x0) * sizeof(*dst));
			for (struct web_conn *c = w->conns; c; c = c->next) {
				if (!c->authed || c->dh != w->h)
					continue;
				if (!c->dx1[y]) {
					c->dx0[y] = x0;
					c->dx1[y] = x1;
				} else {
					c->dx0[y] = RDC_MIN(c->dx0[y], x0);
					c->dx1[y] = RDC_MAX(c->dx1[y], x1);
				}
				c->dirty = true;
			}
			changed = true;
		}
	}
	w->seq = f->seq;
	w->inum = f->interval_num;
	w->iden = f->interval_den;
	for (struct web_conn *c = w->conns; c; c = c->next)
		c->status_due = true;
	if (w->nviewers)
		rdc_web_wake(w);
	pthread_mutex_unlock(&w->mu);
	if (changed)
		s->st.written++;
	return 0;
}

static int web_status(rdc_sink *s, const struct rdc_sink_status *st)
{
	struct web_sink *w = s->priv;

	pthread_mutex_lock(&w->mu);
	w->st = *st;
	w->have_st = true;
	pthread_mutex_unlock(&w->mu);
	return 0;
}

static int web_url(const rdc_sink *s, char *buf, size_t len)
{
	const struct web_sink *w = s->priv;

	if ((size_t)snprintf(buf, len, "%s", w->url) >= len)
		return RDC_E_RANGE;
	return 0;
}

static void web_close(rdc_sink *s)
{
	struct web_sink *w = s->priv;

	if (!w)
		return;
	if (w->thr_started) {
		pthread_mutex_lock(&w->mu);
		w->stop = true;
		pthread_mutex_unlock(&w->mu);
		rdc_web_wake(w);
		pthread_join(w->thr, NULL);
	}
	if (w->lfd >= 0)
		close(w->lfd);
	if (w->wake_fd >= 0)
		close(w->wake_fd);
	pthread_mutex_destroy(&w->mu);
	free(w->fb);
	free(w->rgba);
	free(w->zbuf);
	memset(w->token, 0, sizeof(w->token));
	free(w);
	s->priv = NULL;
}

/* Listen on [ADDR:]PORT: PORT alone, as :PORT, is 127.0.0.1's. */
static int web_listen(struct web_sink *w, const char *spec)
{
	char hostport[RDC_TCP_HOST_MAX + 8], why[320], name[RDC_TCP_NAME_MAX];
	struct sockaddr_storage ss;
	int fd;

	if ((size_t)snprintf(hostport, sizeof(hostport), "%s%s",
			     strchr(spec, ':') ? "" : ":",
			     spec) >= sizeof(hostport))
		return rdc_err_detail(RDC_E_URI, "web sink: %.200s: too long",
				      spec);
	fd = rdc_tcp_listen(hostport, 16, &ss);
	if (fd < 0) {
		snprintf(why, sizeof(why), "%s", rdc_last_error_detail(fd));
		return rdc_err_detail(fd, "web sink: %s", why);
	}
	w->lfd = fd;
	w->loopback = rdc_tcp_is_loopback(&ss);
	if (!w->loopback && !w->have_token)
		return rdc_err_detail(RDC_E_AUTH,
				      "web sink: %s is not loopback: a token "
				      "is required (token=FILE; rdcd --token)",
				      spec);
	rdc_tcp_name(&ss, name);
	snprintf(w->url, sizeof(w->url), "http://%s/", name);
	return 0;
}

static int web_open(rdc_sink *s, const char *args)
{
	struct web_sink *w = calloc(1, sizeof(*w));
	char *dup = strdup(args), *cur, *key, *val;
	const char *token = NULL;
	int ret = 0;

	if (!w || !dup) {
		free(w);
		free(dup);
		return RDC_E_NOMEM;
	}
	w->lfd = w->wake_fd = -1;
	pthread_mutex_init(&w->mu, NULL);
	s->priv = w;
	cur = strchr(dup, ',');
	if (cur)
		*cur++ = '\0';
	while (!ret && (ret = rdc_sink_opt_next(&cur, &key, &val)) > 0) {
		ret = 0;
		if (!strcmp(key, "token") && *val)
			token = val;
		else
			ret = RDC_E_URI;
	}
	if (!ret && token) {
		ret = rdc_token_read("web sink: token", token, w->token,
				     &w->token_len);
		w->have_token = !ret;
	}
	if (!ret) {
		w->rgba = malloc(WEB_BAND_BYTES);
		if (!w->rgba)
			ret = RDC_E_NOMEM;
	}
	if (!ret)
		ret = web_listen(w, dup);
	if (!ret) {
		w->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
		if (w->wake_fd < 0)
			ret = rdc_err_detail(RDC_E_IO, "web sink: eventfd: %s",
					     strerror(errno));
	}
	if (!ret) {
		if (pthread_create(&w->thr, NULL, rdc_web_serve, w))
			ret = RDC_E_NOMEM;
		else
			w->thr_started = true;
	}
	free(dup);
	if (ret)
		web_close(s);
	return ret;
}

const struct rdc_sink_ops rdc_sink_web_ops = {
	.kind = "web",
	.open = web_open,
	.frame = web_frame,
	.status = web_status,
	.url = web_url,
	.close = web_close,
};
