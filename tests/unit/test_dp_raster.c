// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The DP's rasterisers against the plain reference versions in
 * tests/unit/ref.c, on seeded random input in every format and ROP,
 * plus the properties the command reference promises: line symmetry,
 * translation and clip invariance, each pixel drawn once.
 */
#include "test_dp_common.h"
#include "ref.h"

/* checksum of test_random_vs_ref's scenes and results (see there) */
#define TDP_RASTER_CRC 0x681c4c17u

enum prim {
	P_PIXEL,
	P_LINE,
	P_POLY,
	P_RECT,
	P_FRECT,
	P_CIRCLE,
	P_FCIRCLE,
	P_ELLIPSE,
	P_FELLIPSE,
	P_COUNT
};

/* Counts of how many times each pixel of the surface gets drawn. */
struct cmap {
	int32_t w, h;
	struct rdc_rect clip; /* effective: clip and surface */
	uint8_t *n, *seg;
};

static void seg_plot(void *ctx, int32_t x, int32_t y)
{
	struct cmap *m = ctx;

	if (x < m->clip.x0 || x >= m->clip.x1 || y < m->clip.y0 ||
	    y >= m->clip.y1)
		return;
	m->seg[y * m->w + x] = 1;
}

/* Add the pixel set gathered in seg (duplicates count once). */
static void seg_commit(struct cmap *m)
{
	int32_t i;

	for (i = 0; i < m->w * m->h; i++) {
		m->n[i] += m->seg[i];
		m->seg[i] = 0;
	}
}

static void seg_unplot(struct cmap *m, int32_t x, int32_t y)
{
	if (x >= m->clip.x0 && x < m->clip.x1 && y >= m->clip.y0 &&
	    y < m->clip.y1)
		m->seg[y * m->w + x] = 0;
}

struct scene {
	struct rdc_surface s;
	struct rdc_rect clip;
	uint32_t fg, rop;
	enum prim prim;
	uint32_t npts;
	int32_t px[8], py[8];
	uint32_t a, b; /* size or radii */
};

static void scene_random(uint32_t *rng, struct scene *sc, int prim)
{
	uint32_t fmt = tdp_rand(rng) % RDC_FMT_COUNT, i;
	int32_t w = tdp_range(rng, 16, 160), h = tdp_range(rng, 16, 120);

	sc->s.format = fmt;
	sc->s.width = (uint32_t)w;
	sc->s.height = (uint32_t)h;
	sc->s.base = (uint32_t)tdp_range(rng, 256, 4096);
	sc->s.stride = rdc_format_row_bytes(fmt, (uint32_t)w) +
		       (uint32_t)tdp_range(rng, 0, 9);
	if (tdp_rand(rng) % 3 == 0) {
		sc->clip = (struct rdc_rect){ RDC_COORD_MIN, RDC_COORD_MIN,
					      RDC_COORD_MAX + 1,
					      RDC_COORD_MAX + 1 };
	} else {
		sc->clip.x0 = tdp_range(rng, -10, w / 2);
		sc->clip.y0 = tdp_range(rng, -10, h / 2);
		sc->clip.x1 = tdp_range(rng, sc->clip.x0, w + 10);
		sc->clip.y1 = tdp_range(rng, sc->clip.y0, h + 10);
	}
	sc->fg = tdp_rand(rng);
	sc->rop = tdp_rand(rng) % RDC_ROP_COUNT;
	sc->prim = prim >= 0 ? (enum prim)prim :
			       (enum prim)(tdp_rand(rng) % P_COUNT);
	sc->npts = sc->prim == P_POLY ? (uint32_t)tdp_range(rng, 2, 8) : 2;
	for (i = 0; i < sc->npts; i++) {
		sc->px[i] = tdp_range(rng, -60, w + 60);
		sc->py[i] = tdp_range(rng, -60, h + 60);
	}
	if (sc->prim == P_POLY && sc->npts > 2 && tdp_rand(rng) % 2) {
		sc->px[sc->npts - 1] = sc->px[0];
		sc->py[sc->npts - 1] = sc->py[0];
	}
	sc->a = (uint32_t)tdp_range(rng, 0, 100);
	sc->b = (uint32_t)tdp_range(rng, 0, 100);
	if (tdp_rand(rng) % 8 == 0)
		sc->b = 0;
}

/* Reference pixel counts for the scene. */
static void scene_ref(const struct scene *sc, struct cmap *m)
{
	uint32_t i;

	switch (sc->prim) {
	case P_PIXEL:
		seg_plot(m, sc->px[0], sc->py[0]);
		break;
	case P_LINE:
		rdc_ref_line(sc->px[0], sc->py[0], sc->px[1], sc->py[1],
			     seg_plot, m);
		break;
	case P_POLY:
		/* Each segment after the first without its first pixel; a
		 * closed polyline without its closing pixel. */
		for (i = 0; i + 1 < sc->npts; i++) {
			rdc_ref_line(sc->px[i], sc->py[i], sc->px[i + 1],
				     sc->py[i + 1], seg_plot, m);
			if (i > 0)
				seg_unplot(m, sc->px[i], sc->py[i]);
			if (sc->npts > 2 && i + 2 == sc->npts &&
			    sc->px[i + 1] == sc->px[0] &&
			    sc->py[i + 1] == sc->py[0])
				seg_unplot(m, sc->px[0], sc->py[0]);
			seg_commit(m);
		}
		return;
	case P_RECT:
	case P_FRECT:
		rdc_ref_rect(sc->px[0], sc->py[0], sc->a, sc->b,
			     sc->prim == P_FRECT, seg_plot, m);
		break;
	case P_CIRCLE:
	case P_FCIRCLE:
		rdc_ref_circle(sc->px[0], sc->py[0], sc->a,
			       sc->prim == P_FCIRCLE, seg_plot, m);
		break;
	case P_ELLIPSE:
	case P_FELLIPSE:
		rdc_ref_ellipse(sc->px[0], sc->py[0], sc->a, sc->b,
				sc->prim == P_FELLIPSE, seg_plot, m);
		break;
	default:
		break;
	}
	seg_commit(m);
}

static void scene_draw(struct tdp *t, const struct scene *sc)
{
	uint32_t pts[8], i;

	tdp_set_surface(t, RDC_OP_SET_DST, &sc->s);
	TDP_CMD(t, RDC_OP_SET_CLIP, RDC_XY(sc->clip.x0, sc->clip.y0),
		RDC_XY(sc->clip.x1, sc->clip.y1));
	TDP_CMD(t, RDC_OP_SET_FG, sc->fg);
	TDP_CMD(t, RDC_OP_SET_ROP, sc->rop);
	for (i = 0; i < sc->npts; i++)
		pts[i] = RDC_XY(sc->px[i], sc->py[i]);
	switch (sc->prim) {
	case P_PIXEL:
		TDP_CMD(t, RDC_OP_PIXEL, pts[0]);
		break;
	case P_LINE:
		TDP_CMD(t, RDC_OP_LINE, pts[0], pts[1]);
		break;
	case P_POLY:
		tdp_cmd(t, RDC_OP_POLYLINE, 0, sc->npts, pts);
		break;
	case P_RECT:
		TDP_CMD(t, RDC_OP_RECT, pts[0], RDC_WH(sc->a, sc->b));
		break;
	case P_FRECT:
		TDP_CMD(t, RDC_OP_FILL_RECT, pts[0], RDC_WH(sc->a, sc->b));
		break;
	case P_CIRCLE:
		TDP_CMD(t, RDC_OP_CIRCLE, pts[0], sc->a);
		break;
	case P_FCIRCLE:
		TDP_CMD(t, RDC_OP_FILL_CIRCLE, pts[0], sc->a);
		break;
	case P_ELLIPSE:
		TDP_CMD(t, RDC_OP_ELLIPSE, pts[0], RDC_WH(sc->a, sc->b));
		break;
	case P_FELLIPSE:
		TDP_CMD(t, RDC_OP_FILL_ELLIPSE, pts[0], RDC_WH(sc->a, sc->b));
		break;
	default:
		break;
	}
	tdp_drain(t);
	assert_int_equal(tdp_err(t), RDC_ERR_NONE);
}

static void cmap_init(struct cmap *m, const struct scene *sc)
{
	m->w = (int32_t)sc->s.width;
	m->h = (int32_t)sc->s.height;
	m->clip.x0 = sc->clip.x0 > 0 ? sc->clip.x0 : 0;
	m->clip.y0 = sc->clip.y0 > 0 ? sc->clip.y0 : 0;
	m->clip.x1 = sc->clip.x1 < m->w ? sc->clip.x1 : m->w;
	m->clip.y1 = sc->clip.y1 < m->h ? sc->clip.y1 : m->h;
	m->n = calloc((size_t)m->w * m->h, 1);
	m->seg = calloc((size_t)m->w * m->h, 1);
	assert_non_null(m->n);
	assert_non_null(m->seg);
}

static void cmap_free(struct cmap *m)
{
	free(m->n);
	free(m->seg);
}

/* The bytes a scene may touch, and a margin of guard bytes around them. */
static size_t scene_window(const struct scene *sc)
{
	return sc->s.base + (size_t)sc->s.height * sc->s.stride + 256;
}

/* One random scene: DP output must equal the reference, byte for byte. */
static uint32_t run_scene(struct tdp *t, uint32_t *rng, int prim, uint32_t h)
{
	struct scene sc = { 0 };
	struct cmap m;
	size_t win, i;
	uint8_t *want;
	int32_t x, y;

	scene_random(rng, &sc, prim);
	win = scene_window(&sc);
	for (i = 0; i < win; i++)
		t->vram[i] = (uint8_t)tdp_rand(rng);
	want = malloc(win);
	assert_non_null(want);
	memcpy(want, t->vram, win);

	cmap_init(&m, &sc);
	scene_ref(&sc, &m);
	for (y = 0; y < m.h; y++)
		for (x = 0; x < m.w; x++) {
			uint32_t k, v = tdp_get(want, &sc.s, x, y);

			for (k = 0; k < m.n[y * m.w + x]; k++)
				v = tdp_rop(sc.rop,
					    sc.fg & tdp_mask(sc.s.format), v);
			tdp_put(want, &sc.s, x, y, v);
		}
	scene_draw(t, &sc);
	if (memcmp(want, t->vram, win)) {
		for (i = 0; i < win && want[i] == t->vram[i]; i++)
			;
		fail_msg("prim %d fmt %u rop %u: byte %zu differs "
			 "(want %02x got %02x)",
			 sc.prim, sc.s.format, sc.rop, i, want[i], t->vram[i]);
	}
	h = tdp_fnv(h, &sc, sizeof(sc));
	h = tdp_fnv(h, t->vram, win);
	cmap_free(&m);
	free(want);
	return h;
}

static void test_random_vs_ref(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 0x1234567u, h = 2166136261u;
	int p, k;

	for (p = 0; p < P_COUNT; p++)
		for (k = 0; k < 60; k++)
			h = run_scene(t, &rng, p, h);
	/*
	 * Pinned: a change here means some primitive draws different pixels
	 * for the same random inputs; the comparison above says which
	 * agrees with the reference.
	 */
	print_message("random scenes checksum %08x\n", h);
	assert_int_equal(h, TDP_RASTER_CRC);
}

/* ---- properties ---------------------------------------------------- */

static const struct rdc_surface sq = {
	.base = 0x10000,
	.stride = 512,
	.width = 512,
	.height = 512,
	.format = RDC_FMT_I8,
};

static void zero_surface(struct tdp *t)
{
	memset(t->vram + sq.base, 0, (size_t)sq.stride * sq.height);
}

static int surface_is_zero(struct tdp *t)
{
	size_t i;

	for (i = 0; i < (size_t)sq.stride * sq.height; i++)
		if (t->vram[sq.base + i])
			return 0;
	return 1;
}

/* line(a, b) and line(b, a) are the same pixels: XOR both, nothing left. */
static void test_line_symmetry(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 99, k;

	tdp_set_surface(t, RDC_OP_SET_DST, &sq);
	TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_XOR);
	zero_surface(t);
	for (k = 0; k < 400; k++) {
		uint32_t a = RDC_XY(tdp_range(&rng, -100, 600),
				    tdp_range(&rng, -100, 600));
		uint32_t b = RDC_XY(tdp_range(&rng, -100, 600),
				    tdp_range(&rng, -100, 600));

		TDP_CMD(t, RDC_OP_LINE, a, b);
		TDP_CMD(t, RDC_OP_LINE, b, a);
		tdp_drain(t);
		assert_true(surface_is_zero(t));
	}
}

/* Moving both endpoints moves the pixels and changes nothing else. */
static void test_line_translation(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 7, k;
	int32_t x, y;

	tdp_set_surface(t, RDC_OP_SET_DST, &sq);
	for (k = 0; k < 200; k++) {
		int32_t x0 = tdp_range(&rng, 0, 200);
		int32_t y0 = tdp_range(&rng, 0, 200);
		int32_t x1 = tdp_range(&rng, 0, 200);
		int32_t y1 = tdp_range(&rng, 0, 200);
		int32_t dx = tdp_range(&rng, 0, 300);
		int32_t dy = tdp_range(&rng, 0, 300);

		zero_surface(t);
		TDP_CMD(t, RDC_OP_SET_FG, 1);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0, y0), RDC_XY(x1, y1));
		TDP_CMD(t, RDC_OP_SET_FG, 2);
		TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_OR);
		TDP_CMD(t, RDC_OP_LINE, RDC_XY(x0 + dx, y0 + dy),
			RDC_XY(x1 + dx, y1 + dy));
		TDP_CMD(t, RDC_OP_SET_ROP, RDC_ROP_COPY);
		tdp_drain(t);
		for (y = 0; y < 512; y++)
			for (x = 0; x < 512; x++) {
				uint32_t v = tdp_get(t->vram, &sq, x, y);
				int in1 = (v & 1) != 0, in2 = 0;

				if (x + dx < 512 && y + dy < 512)
					in2 = (tdp_get(t->vram, &sq, x + dx,
						       y + dy) &
					       2) != 0;
				if (in1 != in2)
					fail_msg("line %d,%d-%d,%d moved by "
						 "%d,%d: pixel %d,%d",
						 x0, y0, x1, y1, dx, dy, x, y);
			}
	}
}

/*
 * Lines with far-away endpoints through a small clip window: exactly the
 * unclipped reference line's pixels inside the window.
 */
static void test_line_clip_invariance(void **state)
{
	struct tdp *t = *state;
	struct scene sc = { .s = sq,
			    .fg = 0x5a,
			    .rop = RDC_ROP_COPY,
			    .prim = P_LINE,
			    .npts = 2 };
	uint32_t rng = 4242, k;
	int32_t x, y;

	for (k = 0; k < 100; k++) {
		struct cmap m;

		sc.px[0] = tdp_range(&rng, RDC_COORD_MIN, RDC_COORD_MAX);
		sc.py[0] = tdp_range(&rng, RDC_COORD_MIN, RDC_COORD_MAX);
		/* aim through the window so most lines cross it */
		sc.px[1] = 2 * tdp_range(&rng, 100, 400) - sc.px[0];
		sc.py[1] = 2 * tdp_range(&rng, 100, 400) - sc.py[0];
		if (sc.px[1] < RDC_COORD_MIN || sc.px[1] > RDC_COORD_MAX ||
		    sc.py[1] < RDC_COORD_MIN || sc.py[1] > RDC_COORD_MAX)
			sc.px[1] = sc.py[1] = 250;
		sc.clip.x0 = tdp_range(&rng, 0, 250);
		sc.clip.y0 = tdp_range(&rng, 0, 250);
		sc.clip.x1 = tdp_range(&rng, sc.clip.x0, 512);
		sc.clip.y1 = tdp_range(&rng, sc.clip.y0, 512);
		zero_surface(t);
		cmap_init(&m, &sc);
		scene_ref(&sc, &m);
		scene_draw(t, &sc);
		for (y = 0; y < 512; y++)
			for (x = 0; x < 512; x++)
				assert_int_equal(tdp_get(t->vram, &sq, x, y),
						 m.n[y * 512 + x] ? 0x5a : 0);
		cmap_free(&m);
	}
}

/* Drawing any primitive twice with XOR restores the surface exactly. */
static void test_xor_twice(void **state)
{
	struct tdp *t = *state;
	uint32_t rng = 31337, k;

	for (k = 0; k < 300; k++) {
		struct scene sc;
		size_t win, i;
		uint8_t *keep;

		scene_random(&rng, &sc, -1);
		sc.rop = RDC_ROP_XOR;
		win = scene_window(&sc);
		for (i = 0; i < win; i++)
			t->vram[i] = (uint8_t)tdp_rand(&rng);
		keep = malloc(win);
		assert_non_null(keep);
		memcpy(keep, t->vram, win);
		scene_draw(t, &sc);
		scene_draw(t, &sc);
		assert_memory_equal(keep, t->vram, win);
		free(keep);
	}
}

/* r = 0 circles and zero-radius ellipses: one pixel, a line. */
static void test_degenerate(void **state)
{
	struct tdp *t = *state;
	int32_t x, y;

	tdp_set_surface(t, RDC_OP_SET_DST, &sq);
	zero_surface(t);
	TDP_CMD(t, RDC_OP_SET_FG, 9);
	TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(10, 10), 0);
	TDP_CMD(t, RDC_OP_FILL_CIRCLE, RDC_XY(20, 10), 0);
	TDP_CMD(t, RDC_OP_ELLIPSE, RDC_XY(100, 100), RDC_WH(5, 0));
	TDP_CMD(t, RDC_OP_FILL_ELLIPSE, RDC_XY(200, 100), RDC_WH(0, 4));
	tdp_drain(t);
	for (y = 0; y < 512; y++)
		for (x = 0; x < 512; x++) {
			int want = (x == 10 && y == 10) ||
				   (x == 20 && y == 10) ||
				   (y == 100 && x >= 95 && x <= 105) ||
				   (x == 200 && y >= 96 && y <= 104);

			assert_int_equal(tdp_get(t->vram, &sq, x, y),
					 want ? 9 : 0);
		}
}

/* A circle of radius r spans exactly 2r + 1 pixels each way. */
static void test_circle_extent(void **state)
{
	struct tdp *t = *state;
	uint32_t r;

	tdp_set_surface(t, RDC_OP_SET_DST, &sq);
	for (r = 1; r < 200; r += 7) {
		int32_t x, y, xmin = 999, xmax = -1, ymin = 999, ymax = -1;

		zero_surface(t);
		TDP_CMD(t, RDC_OP_CIRCLE, RDC_XY(256, 256), r);
		tdp_drain(t);
		for (y = 0; y < 512; y++)
			for (x = 0; x < 512; x++)
				if (tdp_get(t->vram, &sq, x, y)) {
					xmin = x < xmin ? x : xmin;
					xmax = x > xmax ? x : xmax;
					ymin = y < ymin ? y : ymin;
					ymax = y > ymax ? y : ymax;
				}
		assert_int_equal(xmin, 256 - (int32_t)r);
		assert_int_equal(xmax, 256 + (int32_t)r);
		assert_int_equal(ymin, 256 - (int32_t)r);
		assert_int_equal(ymax, 256 + (int32_t)r);
		/* the four extreme points are on it */
		assert_int_not_equal(tdp_get(t->vram, &sq, 256 + r, 256), 0);
		assert_int_not_equal(tdp_get(t->vram, &sq, 256, 256 - r), 0);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		TDP_TEST(test_random_vs_ref),
		TDP_TEST(test_line_symmetry),
		TDP_TEST(test_line_translation),
		TDP_TEST(test_line_clip_invariance),
		TDP_TEST(test_xor_twice),
		TDP_TEST(test_degenerate),
		TDP_TEST(test_circle_extent),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
