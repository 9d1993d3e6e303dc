// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink: the live display in a browser (docs/web.md).
 *
 * The caller's thread only compares each frame with the last and notes
 * which rows changed and between which columns; the server thread
 * (web_server.c) asks rdc_web_pump for each viewer's next message when
 * its socket has room.  Those rectangles, as zlib-compressed RGBA, then
 * a status, are made once, into a log that every viewer reads at its own
 * pace, so a picture that does not change sends nothing, and a viewer
 * costs a copy of the messages, not their making.  A new viewer, or one
 * the log left behind, first gets a snapshot of the whole picture (one
 * for all of them) and goes on in the log from there.
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

/* The row table sized to the frame, all of it marked; false without
 * memory (then nothing is marked: the log tells no pixels). */
static bool web_damage_all(struct web_sink *w)
{
	uint32_t *a, *b;

	if (w->dh != w->h || !w->dx0) {
		a = realloc(w->dx0, (w->h ? w->h : 1) * sizeof(*a));
		if (a)
			w->dx0 = a;
		b = realloc(w->dx1, (w->h ? w->h : 1) * sizeof(*b));
		if (b)
			w->dx1 = b;
		if (!a || !b) {
			w->dh = 0;
			w->dirty = false;
			return false;
		}
		w->dh = w->h;
	}
	for (uint32_t y = 0; y < w->dh; y++) {
		w->dx0[y] = 0;
		w->dx1[y] = w->w;
	}
	w->dirty = w->dh > 0;
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

/* ---- Messages, made once for every viewer ----------------------------- */

static struct web_msg *web_msg_new(uint8_t op, const void *p, size_t n)
{
	uint8_t hdr[WEB_WS_HDR_MAX];
	size_t hl = rdc_web_ws_header(hdr, op, n);
	struct web_msg *m = malloc(sizeof(*m) + hl + n);

	if (!m)
		return NULL;
	memcpy(m->data, hdr, hl);
	memcpy(m->data + hl, p, n);
	m->len = hl + n;
	return m;
}

static struct web_msg *web_status_msg(struct web_sink *w)
{
	char json[WEB_JSON_MAX];
	size_t jn;

	pthread_mutex_lock(&w->mu);
	jn = web_status_json(w, json, sizeof(json));
	pthread_mutex_unlock(&w->mu);
	return jn ? web_msg_new(WEB_WS_TEXT, json, jn) : NULL;
}

/* Rows [y, y1), columns [x0, x1) of the frame into w->rgba, as RGBA. */
static void web_copy_band(struct web_sink *w, const uint32_t r[4])
{
	for (uint32_t yy = 0; yy < r[3]; yy++) {
		const uint32_t *src = w->fb + (size_t)(r[1] + yy) * w->w + r[0];
		uint8_t *dst = w->rgba + (size_t)yy * r[2] * 4;

		for (uint32_t x = 0; x < r[2]; x++) {
			dst[4 * x] = (uint8_t)(src[x] >> 16);
			dst[4 * x + 1] = (uint8_t)(src[x] >> 8);
			dst[4 * x + 2] = (uint8_t)src[x];
			dst[4 * x + 3] = 0xff;
		}
	}
}

/*
 * Take the next band of damage: consecutive dirty rows, their columns'
 * union, at most WEB_BAND_BYTES of RGBA; copy it out of the frame.
 */
static bool web_take_band(struct web_sink *w, uint32_t r[4])
{
	uint32_t y = 0, x0 = UINT32_MAX, x1 = 0, y1;

	while (y < w->dh && !w->dx1[y])
		y++;
	if (y == w->dh) {
		w->dirty = false;
		return false;
	}
	for (y1 = y; y1 < w->dh && w->dx1[y1]; y1++) {
		uint32_t nx0 = RDC_MIN(x0, w->dx0[y1]);
		uint32_t nx1 = RDC_MAX(x1, w->dx1[y1]);

		if (y1 > y &&
		    (size_t)(nx1 - nx0) * (y1 - y + 1) * 4 > WEB_BAND_BYTES)
			break;
		x0 = nx0;
		x1 = nx1;
	}
	for (uint32_t yy = y; yy < y1; yy++)
		w->dx0[yy] = w->dx1[yy] = 0;
	r[0] = x0;
	r[1] = y;
	r[2] = x1 - x0;
	r[3] = y1 - y;
	web_copy_band(w, r);
	return true;
}

static void put32le(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* The rectangle r of w->rgba as a message: its one compression. */
static struct web_msg *web_rect_msg(struct web_sink *w, const uint32_t r[4])
{
	uLong raw = (uLong)r[2] * r[3] * 4;
	uLongf zlen;
	size_t need = WEB_RECT_HDR + compressBound(raw);

	if (need > w->zcap) {
		uint8_t *nz = realloc(w->zbuf, need);

		if (!nz)
			return NULL;
		w->zbuf = nz;
		w->zcap = need;
	}
	put32le(w->zbuf, WEB_RECT_TYPE);
	for (int i = 0; i < 4; i++)
		put32le(w->zbuf + 4 + 4 * i, r[i]);
	zlen = (uLongf)(w->zcap - WEB_RECT_HDR);
	if (compress2(w->zbuf + WEB_RECT_HDR, &zlen, w->rgba, raw, 1) != Z_OK)
		return NULL;
	w->encodings++;
	return web_msg_new(WEB_WS_BINARY, w->zbuf, WEB_RECT_HDR + zlen);
}

static void web_log_append(struct web_sink *w, struct web_msg *m)
{
	while (w->log_end > w->log_first &&
	       (w->log_end - w->log_first == WEB_LOG_MSGS ||
		w->log_bytes + m->len > WEB_LOG_BYTES)) {
		struct web_msg **o = &w->log[w->log_first++ % WEB_LOG_MSGS];

		w->log_bytes -= (*o)->len;
		free(*o);
		*o = NULL;
	}
	w->log[w->log_end++ % WEB_LOG_MSGS] = m;
	w->log_bytes += m->len;
}

/*
 * The next message into the log: a new size before its pixels, a band
 * of damage, then a status saying the picture is whole; or a status
 * alone at most every WEB_STATUS_NS.  False if nothing is due.
 */
static bool web_log_next(struct web_sink *w, uint64_t now)
{
	struct web_msg *m = NULL;
	uint32_t r[4];
	bool size = false, rect = false, status = false;

	pthread_mutex_lock(&w->mu);
	if (w->dirty && (w->log_w != w->w || w->log_h != w->h)) {
		size = true;
		w->log_w = w->w;
		w->log_h = w->h;
	} else if (w->dirty) {
		rect = web_take_band(w, r);
		w->sync_due |= rect;
	}
	if (!size && !rect &&
	    (w->sync_due ||
	     (w->status_due && now >= w->status_ns + WEB_STATUS_NS))) {
		status = true;
		w->status_due = w->sync_due = false;
	}
	pthread_mutex_unlock(&w->mu);
	if (rect)
		m = web_rect_msg(w, r);
	else if (size || status)
		m = web_status_msg(w);
	if (size || status)
		w->status_ns = now;
	if (!m)
		return false;
	web_log_append(w, m);
	return true;
}

static bool web_snap_add(struct web_sink *w, struct web_msg *m)
{
	if (!m)
		return false;
	if (w->nsnap == w->snap_cap) {
		size_t cap = w->snap_cap ? w->snap_cap * 2 : 16;
		struct web_msg **ns = realloc(w->snap, cap * sizeof(*ns));

		if (!ns) {
			free(m);
			return false;
		}
		w->snap = ns;
		w->snap_cap = cap;
	}
	w->snap[w->nsnap++] = m;
	return true;
}

static void web_snap_free(struct web_sink *w)
{
	for (size_t i = 0; i < w->nsnap; i++)
		free(w->snap[i]);
	w->nsnap = 0;
}

/*
 * The whole picture as of the log's end: its size, its bands, a status
 * saying it is whole.  Damage after a band was copied goes into the log
 * after snap_pos, so a viewer that goes on from there misses nothing.
 * With no viewer following the log, the damage waiting for it is in the
 * snapshot already: it is dropped, not made twice.
 */
static bool web_snapshot(struct web_sink *w, bool followed)
{
	uint32_t h, y = 0;

	web_snap_free(w);
	w->snap_gen++;
	w->snap_pos = w->log_end;
	pthread_mutex_lock(&w->mu);
	if (!followed) {
		for (uint32_t yy = 0; yy < w->dh; yy++)
			w->dx0[yy] = w->dx1[yy] = 0;
		w->dirty = w->sync_due = false;
		w->log_w = w->w;
		w->log_h = w->h;
	}
	h = w->h;
	pthread_mutex_unlock(&w->mu);
	if (!web_snap_add(w, web_status_msg(w)))
		return false;
	while (y < h) {
		struct web_msg *m;
		uint32_t r[4];

		pthread_mutex_lock(&w->mu);
		if (w->h != h) { /* a new size: the log tells it */
			pthread_mutex_unlock(&w->mu);
			break;
		}
		r[0] = 0;
		r[1] = y;
		r[2] = w->w;
		r[3] = RDC_MIN(h - y, RDC_MAX(1u, WEB_BAND_BYTES / 4 / w->w));
		web_copy_band(w, r);
		pthread_mutex_unlock(&w->mu);
		m = web_rect_msg(w, r);
		if (!web_snap_add(w, m))
			return false;
		y += r[3];
	}
	return web_snap_add(w, web_status_msg(w));
}

/* Queue one message for a viewer whose queue is empty. */
void rdc_web_pump(struct web_sink *w, struct web_conn *c, uint64_t now)
{
	const struct web_msg *m;

	if (!c->snap && c->pos < w->log_first) {
		c->snap = true; /* left behind */
		c->snap_gen = 0;
	}
	if (c->snap) {
		if (c->snap_gen != w->snap_gen) {
			bool followed = false;

			if (!w->nsnap || w->snap_pos < w->log_first) {
				for (struct web_conn *o = w->conns; o;
				     o = o->next)
					followed |= o->authed && !o->snap;
				if (!web_snapshot(w, followed)) {
					web_snap_free(w);
					c->dead = true;
					return;
				}
			}
			c->snap_gen = w->snap_gen;
			c->snap_i = 0;
		}
		if (c->snap_i < w->nsnap) {
			m = w->snap[c->snap_i++];
			if (!rdc_web_conn_send_raw(c, m->data, m->len))
				c->dead = true;
			return;
		}
		c->snap = false;
		c->pos = w->snap_pos;
	}
	if (c->pos == w->log_end && !web_log_next(w, now))
		return;
	m = w->log[c->pos++ % WEB_LOG_MSGS];
	if (!rdc_web_conn_send_raw(c, m->data, m->len))
		c->dead = true;
}

uint64_t rdc_web_next(struct web_sink *w, const struct web_conn *c)
{
	uint64_t next = UINT64_MAX;

	if (c->snap || c->pos != w->log_end)
		return 0;
	pthread_mutex_lock(&w->mu);
	if (w->dirty || w->sync_due)
		next = 0;
	else if (w->status_due)
		next = w->status_ns + WEB_STATUS_NS;
	pthread_mutex_unlock(&w->mu);
	return next;
}

void rdc_web_log_free(struct web_sink *w)
{
	while (w->log_first < w->log_end) {
		free(w->log[w->log_first % WEB_LOG_MSGS]);
		w->log[w->log_first++ % WEB_LOG_MSGS] = NULL;
	}
	w->log_bytes = 0;
	web_snap_free(w);
	free(w->snap);
	w->snap = NULL;
	w->snap_cap = 0;
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
		web_damage_all(w);
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
			if (w->dh == w->h) {
				if (!w->dx1[y]) {
					w->dx0[y] = x0;
					w->dx1[y] = x1;
				} else {
					w->dx0[y] = RDC_MIN(w->dx0[y], x0);
					w->dx1[y] = RDC_MAX(w->dx1[y], x1);
				}
				w->dirty = true;
			}
			changed = true;
		}
	}
	w->seq = f->seq;
	w->inum = f->interval_num;
	w->iden = f->interval_den;
	w->status_due = true;
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
	rdc_web_log_free(w);
	free(w->dx0);
	free(w->dx1);
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
