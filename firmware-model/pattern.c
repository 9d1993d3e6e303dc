// SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The fill style: solid FG, or an 8x8 pattern anchored at the DST origin
 * (pixel (x, y) takes pattern cell (x & 7, y & 7)), so fills drawn
 * separately line up.  Every filled primitive reaches DST through
 * dp_fill_span: a solid span is one bus span, a patterned one a span per
 * RDC_DP_CHUNK pixels.
 */
#define RDC_CORE_INTERNAL /* a source of the core: hw.h, dp.h */
#include "dp_int.h"

#define PAT_SIZE	8
#define PAT_MASK	(PAT_SIZE - 1)
#define PAT_MONO_WORDS	2 /* 8 rows of 8 bits */
#define PAT_COLOR_WORDS (PAT_SIZE * PAT_SIZE)

/*
 * The pattern's pixel at (x, y): true and *v = the value to draw, or false
 * where a transparent mono pattern leaves DST alone.
 */
bool dp_pat_value(const struct rdc_dp *dp, int32_t x, int32_t y, uint32_t *v)
{
	const struct rdc_dp_state *st = &dp->st;
	uint32_t cx = (uint32_t)x & PAT_MASK, cy = (uint32_t)y & PAT_MASK;
	bool set;

	switch (st->pat_mode) {
	case RDC_PAT_MONO:
	case RDC_PAT_MONO_TRANSPARENT:
		set = (st->pat_mono[cy] >> (PAT_MASK - cx)) & 1;
		*v = set ? st->fg : st->bg;
		return set || st->pat_mode == RDC_PAT_MONO;
	case RDC_PAT_COLOR:
		*v = st->pat_color[cy * PAT_SIZE + cx];
		return true;
	default:
		*v = st->fg;
		return true;
	}
}

void dp_fill_span(struct rdc_dp *dp, int32_t x0, int32_t x1, int32_t y)
{
	struct rdc_rect c = rdc_dp_eff_clip(dp);
	bool transparent = dp->st.pat_mode == RDC_PAT_MONO_TRANSPARENT;
	int32_t x;

	if (y < c.y0 || y >= c.y1)
		return;
	x0 = RDC_MAX(x0, c.x0);
	x1 = RDC_MIN(x1, c.x1 - 1);
	if (x0 > x1)
		return;
	if (dp->st.pat_mode == RDC_PAT_NONE) {
		if (dp->queue_spans)
			rdc_dp_queue_span(dp, y, x0, x1);
		else
			rdc_dp_span_px(dp, y, x0, (uint32_t)(x1 - x0 + 1),
				       dp->st.fg, NULL, NULL);
		return;
	}
	for (x = x0; x <= x1; x += (int32_t)RDC_DP_CHUNK) {
		uint32_t n = (uint32_t)RDC_MIN((int64_t)x1 - x + 1,
					       (int64_t)RDC_DP_CHUNK);
		uint32_t i;

		for (i = 0; i < n; i++)
			dp->on[i] =
				dp_pat_value(dp, x + (int32_t)i, y, &dp->px[i]);
		rdc_dp_span_px(dp, y, x, n, 0, dp->px,
			       transparent ? dp->on : NULL);
	}
}

uint32_t dp_cmd_set_pattern(struct rdc_dp *dp, uint32_t mode, uint32_t len,
			    const uint32_t *a)
{
	struct rdc_dp_state *st = &dp->st;
	uint32_t i;

	switch (mode) {
	case RDC_PAT_NONE:
		if (len)
			return RDC_ERR_LENGTH;
		break;
	case RDC_PAT_MONO:
	case RDC_PAT_MONO_TRANSPARENT:
		if (len != PAT_MONO_WORDS)
			return RDC_ERR_LENGTH;
		for (i = 0; i < PAT_SIZE; i++)
			st->pat_mono[i] = (uint8_t)(a[i / 4] >> (8 * (i % 4)));
		break;
	case RDC_PAT_COLOR:
		if (len != PAT_COLOR_WORDS)
			return RDC_ERR_LENGTH;
		for (i = 0; i < PAT_COLOR_WORDS; i++)
			st->pat_color[i] = a[i];
		break;
	default:
		return RDC_ERR_ARG;
	}
	st->pat_mode = mode;
	return RDC_ERR_NONE;
}
