// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* The sink object: spec parsing, dispatch to a kind, counters. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "rdc_priv.h"
#include "sink_priv.h"

static const struct rdc_sink_ops *const sink_kinds[] = {
	&rdc_sink_v4l2_ops,
	&rdc_sink_png_ops,
	&rdc_sink_vnc_ops,
	&rdc_sink_web_ops,
};

#define SINK_SPEC_MAX 4096

int rdc_sink_opt_next(char **cursor, char **key, char **val)
{
	char *p = *cursor, *comma, *eq;

	if (!p || !*p)
		return 0;
	comma = strchr(p, ',');
	if (comma) {
		*comma = '\0';
		*cursor = comma + 1;
	} else {
		*cursor = p + strlen(p);
	}
	eq = strchr(p, '=');
	if (!eq || eq == p)
		return RDC_E_URI;
	*eq = '\0';
	*key = p;
	*val = eq + 1;
	return 1;
}

int rdc_sink_opt_u32(const char *val, uint32_t min, uint32_t max, uint32_t *out)
{
	unsigned long long v;
	char *end;

	if (!val || *val < '0' || *val > '9')
		return RDC_E_URI;
	errno = 0;
	v = strtoull(val, &end, 10);
	if (errno || *end || v < min || v > max)
		return RDC_E_URI;
	*out = (uint32_t)v;
	return 0;
}

int rdc_sink_open(const char *spec, rdc_sink **out)
{
	const char *colon;
	size_t klen;

	rdc_err_detail_clear();
	if (!spec || !out)
		return RDC_E_INVAL;
	*out = NULL;
	if (strnlen(spec, SINK_SPEC_MAX) >= SINK_SPEC_MAX)
		return rdc_err_detail(RDC_E_URI,
				      "sink spec longer than %d bytes",
				      SINK_SPEC_MAX - 1);
	colon = strchr(spec, ':');
	if (!colon)
		return rdc_err_detail(RDC_E_URI,
				      "'%.60s': KIND:ARGS expected (v4l2:, "
				      "png:, vnc:, web:)",
				      spec);
	klen = (size_t)(colon - spec);
	for (size_t i = 0; i < sizeof(sink_kinds) / sizeof(sink_kinds[0]);
	     i++) {
		const struct rdc_sink_ops *ops = sink_kinds[i];
		rdc_sink *s;
		int ret;

		if (strlen(ops->kind) != klen || strncmp(ops->kind, spec, klen))
			continue;
		s = calloc(1, sizeof(*s));
		if (!s)
			return RDC_E_NOMEM;
		s->ops = ops;
		ret = ops->open(s, colon + 1);
		if (ret) {
			free(s);
			if (ret == RDC_E_URI && !*rdc_last_error_detail(ret))
				rdc_err_detail(ret,
					       "'%.200s': bad %s sink spec "
					       "(rdc_sink.h)",
					       spec, ops->kind);
			return ret;
		}
		*out = s;
		return 0;
	}
	return rdc_err_detail(RDC_E_URI,
			      "'%.*s': not a sink kind (v4l2, png, vnc, web)",
			      (int)RDC_MIN(klen, (size_t)40), spec);
}

int rdc_sink_frame(rdc_sink *s, const struct rdc_frame *f)
{
	if (!s || !f || !f->xrgb || !f->width || !f->height ||
	    f->width > RDC_CRTC_MAX_DISPLAY ||
	    f->height > RDC_CRTC_MAX_DISPLAY || f->stride < f->width)
		return RDC_E_INVAL;
	s->st.frames++;
	return s->ops->frame(s, f);
}

int rdc_sink_snapshot(rdc_sink *s)
{
	if (!s)
		return RDC_E_INVAL;
	return s->ops->snapshot ? s->ops->snapshot(s) : RDC_E_NOSYS;
}

int rdc_sink_poll(rdc_sink *s)
{
	if (!s)
		return RDC_E_INVAL;
	return s->ops->poll ? s->ops->poll(s) : 0;
}

int rdc_sink_status_set(rdc_sink *s, const struct rdc_sink_status *st)
{
	struct rdc_sink_status full = { 0 };

	if (!s || !st)
		return RDC_E_INVAL;
	/* what an older or newer caller's layout holds of ours */
	memcpy(&full, st,
	       st->size ? RDC_MIN((size_t)st->size, sizeof(full)) :
			  sizeof(full));
	full.size = sizeof(full);
	return s->ops->status ? s->ops->status(s, &full) : 0;
}

int rdc_sink_url(const rdc_sink *s, char *buf, size_t len)
{
	if (!s || !buf || !len)
		return RDC_E_INVAL;
	return s->ops->url ? s->ops->url(s, buf, len) : RDC_E_NOSYS;
}

void rdc_sink_close(rdc_sink *s)
{
	if (!s)
		return;
	s->ops->close(s);
	free(s);
}

const char *rdc_sink_kind(const rdc_sink *s)
{
	return s ? s->ops->kind : NULL;
}

int rdc_sink_stats_get_sized(const rdc_sink *s, struct rdc_sink_stats *st)
{
	if (!s || !st)
		return RDC_E_INVAL;
	rdc_struct_out(st, &s->st, sizeof(s->st));
	return 0;
}

static uint64_t gcd64(uint64_t a, uint64_t b)
{
	while (b) {
		uint64_t t = a % b;

		a = b;
		b = t;
	}
	return a;
}

#define HZ_PER_KHZ 1000u

int rdc_sink_interval_timing(uint32_t h_total, uint32_t v_total,
			     uint32_t pixclk_khz, uint32_t *num, uint32_t *den)
{
	uint64_t n, d, g;

	if (!num || !den)
		return RDC_E_INVAL;
	if (!h_total || !v_total || !pixclk_khz ||
	    h_total > RDC_CRTC_MAX_TOTAL || v_total > RDC_CRTC_MAX_TOTAL)
		return RDC_E_RANGE;
	n = (uint64_t)h_total * v_total;
	d = (uint64_t)pixclk_khz * HZ_PER_KHZ;
	g = gcd64(n, d);
	/* 4096 * 4096 fits 32 bits; so does any pixel clock in Hz below
	 * 4.29 GHz, and reducing only makes both smaller. */
	if (n / g > UINT32_MAX || d / g > UINT32_MAX)
		return RDC_E_RANGE;
	*num = (uint32_t)(n / g);
	*den = (uint32_t)(d / g);
	return 0;
}

int rdc_sink_interval(rdc_dev *dev, uint32_t *num, uint32_t *den)
{
	uint32_t ht, vt, khz;
	int ret;

	if (!dev || !num || !den)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_H_TOTAL, &ht);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_V_TOTAL, &vt);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_PIXCLK_KHZ, &khz);
	if (ret)
		return ret;
	return rdc_sink_interval_timing(ht, vt, khz, num, den);
}
