// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The vnc sink: a live view for any VNC viewer through libvncserver.
 *
 * The server's framebuffer holds the last frame sent; a new frame is
 * compared with it row by row and only the rows that differ are copied
 * and marked modified, so viewers get the damaged rows alone.  The pixel
 * format is declared with red at bit 16 so frame rows copy as they are.
 * Built without libvncserver (RDC_HAVE_VNC undefined), opening one says
 * RDC_E_NOSYS.
 */
#include <stdlib.h>
#include <string.h>

#include "rdc_priv.h"
#include "sink_priv.h"

#ifdef RDC_HAVE_VNC
#include <arpa/inet.h>
#include <netinet/in.h>
#include <rfb/rfb.h>

#define VNC_BITS_PER_SAMPLE   8
#define VNC_SAMPLES_PER_PIXEL 3
#define VNC_BYTES_PER_PIXEL   4
#define VNC_RED_SHIFT	      16
#define VNC_GREEN_SHIFT	      8
#define VNC_BLUE_SHIFT	      0
#define VNC_PORT_MIN	      1
#define VNC_PORT_MAX	      65535
#define VNC_ADDR_MAX	      64

struct vnc_sink {
	rfbScreenInfoPtr screen;
	uint32_t *fb;
	uint32_t width, height;
	uint32_t port;
	in_addr_t listen;
	char listen6[VNC_ADDR_MAX];
};

int rdc_sink_have_vnc(void)
{
	return 1;
}

static void vnc_set_format(rfbScreenInfoPtr scr)
{
	scr->serverFormat.redShift = VNC_RED_SHIFT;
	scr->serverFormat.greenShift = VNC_GREEN_SHIFT;
	scr->serverFormat.blueShift = VNC_BLUE_SHIFT;
}

static uint32_t *vnc_alloc_fb(uint32_t w, uint32_t h)
{
	return calloc((size_t)w * h, sizeof(uint32_t));
}

static int vnc_start(struct vnc_sink *v, uint32_t w, uint32_t h)
{
	rfbScreenInfoPtr scr;

	v->fb = vnc_alloc_fb(w, h);
	if (!v->fb)
		return RDC_E_NOMEM;
	scr = rfbGetScreen(NULL, NULL, (int)w, (int)h, VNC_BITS_PER_SAMPLE,
			   VNC_SAMPLES_PER_PIXEL, VNC_BYTES_PER_PIXEL);
	if (!scr)
		return RDC_E_NOMEM;
	v->screen = scr;
	vnc_set_format(scr);
	scr->frameBuffer = (char *)v->fb;
	scr->desktopName = "rdc";
	scr->alwaysShared = TRUE;
	/* No server-drawn cursor: it would be painted into the picture. */
	scr->cursor = NULL;
	scr->autoPort = FALSE;
	scr->port = (int)v->port;
	scr->ipv6port = (int)v->port;
	scr->listenInterface = v->listen;
	scr->listen6Interface = v->listen6;
	rfbInitServer(scr);
	if (scr->listenSock == RFB_INVALID_SOCKET)
		return rdc_err_detail(RDC_E_IO,
				      "vnc sink: cannot listen on port %u",
				      v->port);
	v->width = w;
	v->height = h;
	return 0;
}

static int vnc_resize(struct vnc_sink *v, uint32_t w, uint32_t h)
{
	uint32_t *nfb = vnc_alloc_fb(w, h);

	if (!nfb)
		return RDC_E_NOMEM;
	/* Viewers that know the DesktopSize pseudo-encoding follow. */
	rfbNewFramebuffer(v->screen, (char *)nfb, (int)w, (int)h,
			  VNC_BITS_PER_SAMPLE, VNC_SAMPLES_PER_PIXEL,
			  VNC_BYTES_PER_PIXEL);
	vnc_set_format(v->screen);
	free(v->fb);
	v->fb = nfb;
	v->width = w;
	v->height = h;
	return 0;
}

static int vnc_frame(rdc_sink *s, const struct rdc_frame *f)
{
	struct vnc_sink *v = s->priv;
	size_t row_bytes = (size_t)f->width * sizeof(uint32_t);
	int ret;

	if (!v->screen) {
		ret = vnc_start(v, f->width, f->height);
		if (ret)
			return ret;
		/* A fresh server has no old frame: everything is damage. */
		memset(v->fb, 0xff, (size_t)f->width * f->height * 4);
	} else if (f->width != v->width || f->height != v->height) {
		ret = vnc_resize(v, f->width, f->height);
		if (ret)
			return ret;
		memset(v->fb, 0xff, (size_t)f->width * f->height * 4);
	}
	for (uint32_t y = 0; y < f->height;) {
		uint32_t y0;

		while (y < f->height &&
		       !memcmp(v->fb + (size_t)y * f->width,
			       f->xrgb + y * f->stride, row_bytes))
			y++;
		if (y == f->height)
			break;
		y0 = y;
		while (y < f->height &&
		       memcmp(v->fb + (size_t)y * f->width,
			      f->xrgb + y * f->stride, row_bytes)) {
			memcpy(v->fb + (size_t)y * f->width,
			       f->xrgb + y * f->stride, row_bytes);
			y++;
		}
		rfbMarkRectAsModified(v->screen, 0, (int)y0, (int)f->width,
				      (int)y);
	}
	rfbProcessEvents(v->screen, 0);
	s->st.written++;
	return 0;
}

static int vnc_poll(rdc_sink *s)
{
	struct vnc_sink *v = s->priv;

	if (v->screen)
		rfbProcessEvents(v->screen, 0);
	return 0;
}

static void vnc_close(rdc_sink *s)
{
	struct vnc_sink *v = s->priv;

	if (!v)
		return;
	if (v->screen) {
		rfbShutdownServer(v->screen, TRUE);
		rfbScreenCleanup(v->screen);
	}
	free(v->fb);
	free(v);
	s->priv = NULL;
}

static int vnc_open(rdc_sink *s, const char *args)
{
	struct vnc_sink *v = calloc(1, sizeof(*v));
	char *dup = strdup(args), *cur, *key, *val;
	int ret;

	if (!v || !dup) {
		free(v);
		free(dup);
		return RDC_E_NOMEM;
	}
	s->priv = v;
	v->listen = htonl(INADDR_LOOPBACK);
	strcpy(v->listen6, "::1");
	cur = strchr(dup, ',');
	if (cur)
		*cur++ = '\0';
	ret = rdc_sink_opt_u32(dup, VNC_PORT_MIN, VNC_PORT_MAX, &v->port);
	while (!ret && (ret = rdc_sink_opt_next(&cur, &key, &val)) > 0) {
		struct in_addr a;

		ret = RDC_E_URI;
		if (strcmp(key, "listen") || inet_pton(AF_INET, val, &a) != 1)
			continue;
		v->listen = a.s_addr;
		/* An explicit IPv4 address: IPv6 follows it to "any" only
		 * when IPv4 is "any". */
		strcpy(v->listen6,
		       a.s_addr == htonl(INADDR_ANY) ? "::" : "::1");
		ret = 0;
	}
	free(dup);
	if (ret)
		vnc_close(s);
	return ret;
}

const struct rdc_sink_ops rdc_sink_vnc_ops = {
	.kind = "vnc",
	.open = vnc_open,
	.frame = vnc_frame,
	.poll = vnc_poll,
	.close = vnc_close,
};

#else /* !RDC_HAVE_VNC */

int rdc_sink_have_vnc(void)
{
	return 0;
}

static int vnc_open(rdc_sink *s, const char *args)
{
	(void)s;
	(void)args;
	return rdc_err_detail(RDC_E_NOSYS,
			      "vnc sink: built without libvncserver (Debian: "
			      "libvncserver-dev)");
}

static int vnc_frame(rdc_sink *s, const struct rdc_frame *f)
{
	(void)s;
	(void)f;
	return RDC_E_NOSYS;
}

static void vnc_close(rdc_sink *s)
{
	(void)s;
}

const struct rdc_sink_ops rdc_sink_vnc_ops = {
	.kind = "vnc",
	.open = vnc_open,
	.frame = vnc_frame,
	.close = vnc_close,
};
#endif
