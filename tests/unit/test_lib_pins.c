// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The pins API (rdc_pins_*): levels, TE and IRQ edges at the simulated
 * times the mode's timing says, RESET_N holding and releasing the chip,
 * BL_EN darkening the panel, and a batch presented on TE landing in
 * vertical blanking; on sim: and through a real rdcd (unix:), plus the
 * PINS_SET message against malformed, oversized and uncontrolled
 * requests, and a recording daemon's trace replaying a pin change.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "rdc.h"
#include "rdc_priv.h"
#include "test_net_common.h"

static const char *const args_stepped[] = { "--stepped", NULL };

/* The CRTC's timing as its registers say, and the core clock. */
struct pins_timing {
	uint64_t hz, h_total, v_total, v_display, khz;
};

static void pins_timing(rdc_dev *dev, struct pins_timing *t)
{
	uint32_t v;

	assert_int_equal(rdc_reg_read(dev, RDC_REG_H_TOTAL, &v), 0);
	t->h_total = v;
	assert_int_equal(rdc_reg_read(dev, RDC_REG_V_TOTAL, &v), 0);
	t->v_total = v;
	assert_int_equal(rdc_reg_read(dev, RDC_REG_V_DISPLAY, &v), 0);
	t->v_display = v;
	assert_int_equal(rdc_reg_read(dev, RDC_REG_PIXCLK_KHZ, &v), 0);
	t->khz = v;
	assert_int_equal(rdc_sim_core_hz(dev, &v), 0);
	t->hz = v;
}

/* Core cycles from a frame's start to the start of line n. */
static uint64_t line_at(const struct pins_timing *t, uint64_t n)
{
	return n * t->h_total * t->hz / (t->khz * 1000u);
}

static rdc_dev *open_sim(void)
{
	rdc_dev *dev;

	assert_int_equal(rdc_open("sim:", &dev), 0);
	return dev;
}

static void test_levels_and_args(void **state)
{
	rdc_dev *dev = open_sim();
	struct rdc_pin_edge ev;
	rdc_batch *b = rdc_batch_new();
	uint32_t p;

	(void)state;
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	/* out of reset, backlight on, the frame just started */
	assert_int_equal(p, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_TE, 0), RDC_E_INVAL);
	assert_int_equal(rdc_pins_set(dev, 0x10, 0), RDC_E_INVAL);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_BL_EN, RDC_EDGE_RISING,
					    0, &ev),
			 RDC_E_INVAL);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE, 0, 0, &ev),
			 RDC_E_INVAL);
	/* RDC_EDGE_QUEUED is no kind of edge; bits past it mean nothing */
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE, RDC_EDGE_QUEUED, 0,
					    &ev),
			 RDC_E_INVAL);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
					    RDC_EDGE_RISING | 0x8u, 0, &ev),
			 RDC_E_INVAL);
	assert_int_equal(rdc_pins_wait_edge(dev, 0, RDC_EDGE_BOTH, 0, &ev),
			 RDC_E_INVAL);
	assert_int_equal(rdc_pins_present(dev, NULL, 0, NULL), RDC_E_INVAL);
	assert_int_equal(rdc_pins_get(NULL, &p), RDC_E_INVAL);
	/* a set that changes nothing leaves everything as it was */
	assert_int_equal(rdc_pins_set(dev, 0, 0), 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	rdc_batch_free(b);
	rdc_close(dev);
}

/*
 * TE rises at the start of line V_DISPLAY of every frame and falls at the
 * next frame's start: the edges on sim: carry those exact cycles, in the
 * mode after reset and in another one set later.
 */
static void test_te_times(void **state)
{
	rdc_dev *dev = open_sim();
	struct pins_timing t;
	struct rdc_pin_edge ev;
	uint64_t frame, start = 0, now;

	(void)state;
	assert_int_equal(rdc_sim_time(dev, &now), 0);
	assert_int_equal(now, 0); /* the first frame starts at reset */
	pins_timing(dev, &t);
	frame = line_at(&t, t.v_total);
	for (uint64_t k = 0; k < 4; k++) {
		assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
						    RDC_EDGE_BOTH, 0, &ev),
				 0);
		assert_int_equal(ev.pins, RDC_PIN_TE);
		assert_true(ev.levels & RDC_PIN_TE);
		assert_int_equal(ev.time, k * frame + line_at(&t, t.v_display));
		/* a watcher's stream: on sim: the same next edge */
		assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
						    RDC_EDGE_BOTH |
							    RDC_EDGE_QUEUED,
						    0, &ev),
				 0);
		assert_false(ev.levels & RDC_PIN_TE);
		assert_int_equal(ev.time, (k + 1) * frame);
	}

	/* another mode: in force from the frame after the next vblank */
	assert_int_equal(rdc_mode_set(dev, RDC_PRESET_800x600_60,
				      RDC_FMT_XRGB8888, 0),
			 0);
	for (int i = 0; i < 2; i++)
		assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
						    RDC_EDGE_FALLING, 0, &ev),
				 0);
	start = ev.time; /* a frame of the new mode starts */
	pins_timing(dev, &t);
	assert_int_equal(t.v_display, 600);
	frame = line_at(&t, t.v_total);
	for (uint64_t k = 0; k < 3; k++) {
		assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
						    RDC_EDGE_RISING, 0, &ev),
				 0);
		assert_int_equal(ev.time,
				 start + k * frame + line_at(&t, t.v_display));
	}
	rdc_close(dev);
}

/* IRQ rises with the vblank interrupt it is enabled for, at TE's cycle. */
static void test_irq_edge(void **state)
{
	rdc_dev *dev = open_sim();
	struct pins_timing t;
	struct rdc_pin_edge ev, first;
	uint32_t p;

	(void)state;
	pins_timing(dev, &t);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_ENABLE, RDC_IRQ_VBLANK),
			 0);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PINS_OUT, RDC_EDGE_RISING,
					    0, &first),
			 0);
	/* both rise at the start of blanking: one event names both */
	assert_int_equal(first.pins, RDC_PIN_TE | RDC_PIN_IRQ);
	assert_int_equal(first.time, line_at(&t, t.v_display));
	/* acknowledged, IRQ falls; it rises again a frame later */
	assert_int_equal(rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_VBLANK),
			 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_false(p & RDC_PIN_IRQ);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_IRQ, RDC_EDGE_RISING,
					    0, &ev),
			 0);
	assert_int_equal(ev.pins, RDC_PIN_IRQ);
	assert_int_equal(ev.time, first.time + line_at(&t, t.v_total));
	rdc_close(dev);
}

/*
 * RESET_N low holds the chip: registers read their reset values, writes
 * are lost, TE stays low; released, the chip starts afresh and its first
 * frame starts at the release.
 */
static void test_reset_n(void **state)
{
	rdc_dev *dev = open_sim();
	struct pins_timing t;
	struct rdc_pin_edge ev;
	uint64_t released;
	uint32_t v, p;

	(void)state;
	pins_timing(dev, &t);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_LINE_COMPARE, 100), 0);
	assert_int_equal(rdc_sim_step(dev, 12345), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, 0), 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p, RDC_PIN_BL_EN);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_LINE_COMPARE, &v), 0);
	assert_int_equal(v, RDC_LINE_COMPARE_RESET);
	assert_int_equal(rdc_reg_write(dev, RDC_REG_LINE_COMPARE, 7), 0);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_LINE_COMPARE, &v), 0);
	assert_int_equal(v, RDC_LINE_COMPARE_RESET);
	/* held: no frame, so no TE for two frames' time */
	assert_int_equal(
		rdc_pins_wait_edge(dev, RDC_PIN_TE, RDC_EDGE_RISING,
				   2 * line_at(&t, t.v_total) * 1000000u / t.hz,
				   &ev),
		RDC_E_TIMEOUT);
	assert_int_equal(rdc_sim_time(dev, &released), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, RDC_PIN_RESET_N),
			 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p, RDC_PIN_RESET_N | RDC_PIN_BL_EN);
	assert_int_equal(rdc_reg_read(dev, RDC_REG_LINE_COMPARE, &v), 0);
	assert_int_equal(v, RDC_LINE_COMPARE_RESET);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE, RDC_EDGE_RISING, 0,
					    &ev),
			 0);
	assert_int_equal(ev.time, released + line_at(&t, t.v_display));
	rdc_close(dev);
}

static void fill_screen(rdc_dev *dev, uint32_t colour)
{
	rdc_batch *b = rdc_batch_new();

	assert_non_null(b);
	assert_int_equal(rdc_batch_fg(b, colour), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 0, 0, 640, 480), 0);
	assert_int_equal(rdc_batch_submit(dev, b), 0);
	assert_int_equal(rdc_finish(dev), 0);
	rdc_batch_free(b);
}

/* Pixels that are not black in the last frame. */
static size_t lit_pixels(rdc_dev *dev)
{
	uint32_t *pix = NULL, w = 0, h = 0;
	size_t lit = 0;

	assert_int_equal(rdc_frame_wait(dev), 0);
	assert_int_equal(rdc_frame_alloc(dev, &pix, &w, &h), 0);
	for (size_t i = 0; i < (size_t)w * h; i++)
		lit += (pix[i] & 0xffffffu) != 0;
	free(pix);
	return lit;
}

static void test_bl_en(void **state)
{
	rdc_dev *dev = open_sim();
	uint32_t p, crc0, crc1;

	(void)state;
	fill_screen(dev, 0xff40a0ff);
	assert_int_equal(lit_pixels(dev), 640 * 480);
	assert_int_equal(rdc_frame_crc(dev, &crc0), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, 0), 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p & RDC_PINS_IN, RDC_PIN_RESET_N);
	assert_int_equal(lit_pixels(dev), 0);
	/* VRAM is untouched: the picture comes back with the light */
	assert_int_equal(rdc_pins_set(dev, RDC_PINS_IN, RDC_PINS_IN), 0);
	assert_int_equal(lit_pixels(dev), 640 * 480);
	assert_int_equal(rdc_frame_crc(dev, &crc1), 0);
	assert_int_equal(crc0, crc1);
	rdc_close(dev);
}

/*
 * Present on TE: the words go in at TE's rising edge, and a short update
 * starts and ends while the beam is in blanking.
 */
static void present_in_vblank(rdc_dev *dev, uint32_t v_display)
{
	rdc_batch *b = rdc_batch_new();
	struct rdc_pin_edge ev;
	uint32_t p, x, y;
	uint64_t t;

	assert_non_null(b);
	/* start somewhere in the active picture */
	assert_int_equal(rdc_sim_step(dev, 700000), 0);
	assert_int_equal(rdc_batch_fg(b, 0xff00ff00), 0);
	assert_int_equal(rdc_batch_fill_rect(b, 100, 100, 64, 64), 0);
	assert_int_equal(rdc_pins_present(dev, b, 0, &ev), 0);
	assert_true(ev.levels & RDC_PIN_TE);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_true(p & RDC_PIN_TE);
	assert_int_equal(rdc_idle_wait(dev), 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_true(p & RDC_PIN_TE);
	if (rdc_sim_beam(dev, &x, &y) == 0)
		assert_true(y >= v_display);
	assert_int_equal(rdc_sim_time(dev, &t), 0);
	assert_true(t >= ev.time);
	rdc_batch_free(b);
}

static void test_present_on_te(void **state)
{
	rdc_dev *dev = open_sim();

	(void)state;
	present_in_vblank(dev, 480);
	assert_int_equal(lit_pixels(dev), 64 * 64);
	rdc_close(dev);
}

/* ---- Through rdcd -------------------------------------------------------- */

static void test_unix(void **state)
{
	struct netd d;
	rdc_dev *dev, *obs;
	struct pins_timing t;
	struct rdc_pin_edge ev, prev = { 0 };
	uint32_t p, v;
	char uri[200];

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	snprintf(uri, sizeof(uri), "%s?observe", d.unix_uri);
	assert_int_equal(rdc_open(uri, &obs), 0);

	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p & RDC_PINS_IN, RDC_PINS_IN);
	/* only the controlling client drives them */
	assert_int_equal(rdc_pins_set(obs, RDC_PIN_BL_EN, 0), RDC_E_BUSY);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, 0), 0);
	assert_int_equal(rdc_pins_get(obs, &p), 0);
	assert_int_equal(p & RDC_PINS_IN, RDC_PIN_RESET_N);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, RDC_PIN_BL_EN), 0);

	/* TE edges a frame apart, seen within a wait slice of the edge */
	pins_timing(dev, &t);
	for (int k = 0; k < 4; k++) {
		assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE,
						    RDC_EDGE_RISING, 0, &ev),
				 0);
		assert_int_equal(ev.pins, RDC_PIN_TE);
		assert_true(ev.time % line_at(&t, t.v_total) >=
			    line_at(&t, t.v_display));
		assert_true(ev.time % line_at(&t, t.v_total) -
				    line_at(&t, t.v_display) <=
			    RDC_WAIT_SLICE_MAX);
		if (k)
			assert_int_equal(ev.time / line_at(&t, t.v_total),
					 prev.time / line_at(&t, t.v_total) +
						 1);
		prev = ev;
	}

	/* RESET_N through the daemon */
	assert_int_equal(rdc_reg_write(dev, RDC_REG_LINE_COMPARE, 50), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, 0), 0);
	assert_int_equal(rdc_reg_read(obs, RDC_REG_LINE_COMPARE, &v), 0);
	assert_int_equal(v, RDC_LINE_COMPARE_RESET);
	assert_int_equal(rdc_pins_wait_edge(dev, RDC_PIN_TE, RDC_EDGE_RISING,
					    40000, &ev),
			 RDC_E_TIMEOUT);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_RESET_N, RDC_PIN_RESET_N),
			 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p, RDC_PIN_RESET_N | RDC_PIN_BL_EN);

	/* a frame drawn after the reset, presented on TE */
	fill_screen(dev, 0);
	present_in_vblank(dev, 480);
	assert_int_equal(lit_pixels(dev), 64 * 64);

	rdc_close(obs);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);
}

/* The PINS_SET message against bad requests; the daemon serves on. */
static void test_proto(void **state)
{
	struct netd d;
	uint8_t b[16] = { 0 }, out[8], hb[RDC_PROTO_HDR_SIZE];
	struct rdc_proto_hdr h;
	int ctl, obs, big;

	(void)state;
	assert_int_equal(netd_start(&d, args_stepped), 0);
	ctl = netd_connect(d.sock);
	obs = netd_connect(d.sock);
	assert_true(ctl >= 0 && obs >= 0);
	assert_int_equal(netd_hello(ctl, RDC_HELLO_CONTROL, NULL, NULL),
			 RDC_ST_OK);
	assert_int_equal(netd_hello(obs, 0, NULL, NULL), RDC_ST_OK);

	/* wrong sizes */
	assert_int_equal(netd_call(ctl, RDC_MSG_PINS_SET, 2, b, 4, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(ctl, RDC_MSG_PINS_SET, 3, b, 12, NULL, 0),
			 RDC_ST_MALFORMED);
	assert_int_equal(netd_call(ctl, RDC_MSG_PINS_SET, 4, NULL, 0, NULL, 0),
			 RDC_ST_MALFORMED);
	/* outputs are the chip's, unknown bits nobody's */
	rdc_proto_put32(b, RDC_PIN_TE);
	assert_int_equal(netd_call(ctl, RDC_MSG_PINS_SET, 5, b, 8, NULL, 0),
			 RDC_ST_INVAL);
	rdc_proto_put32(b, 0x80000000u);
	assert_int_equal(netd_call(ctl, RDC_MSG_PINS_SET, 6, b, 8, NULL, 0),
			 RDC_ST_INVAL);
	/* an observer may not */
	rdc_proto_put32(b, RDC_PIN_BL_EN);
	rdc_proto_put32(b + 4, 0);
	assert_int_equal(netd_call(obs, RDC_MSG_PINS_SET, 7, b, 8, NULL, 0),
			 RDC_ST_BUSY);
	/* the controller may: the reply is the levels after */
	memset(out, 0xee, sizeof(out));
	assert_int_equal(netd_send(ctl, RDC_MSG_PINS_SET, 8, b, 8), 0);
	assert_int_equal(netd_reply(ctl, &h, out, sizeof(out)), 0);
	assert_int_equal(h.status, RDC_ST_OK);
	assert_int_equal(h.len, 4);
	assert_int_equal(rdc_proto_get32(out) & RDC_PINS_IN, RDC_PIN_RESET_N);
	/* everyone sees it in PINS */
	rdc_proto_put32(b, RDC_REG_PINS);
	assert_int_equal(netd_call(obs, RDC_MSG_REG_READ, 9, b, 4, out, 4),
			 RDC_ST_OK);
	assert_int_equal(rdc_proto_get32(out) & RDC_PINS_IN, RDC_PIN_RESET_N);

	/* oversized: refused and hung up on, alone */
	big = netd_connect(d.sock);
	assert_true(big >= 0);
	assert_int_equal(netd_hello(big, 0, NULL, NULL), RDC_ST_OK);
	h = (struct rdc_proto_hdr){ .len = RDC_PROTO_MAX_REQUEST + 1,
				    .type = RDC_MSG_PINS_SET,
				    .seq = 10 };
	rdc_proto_hdr_encode(hb, &h);
	assert_int_equal(netd_write(big, hb, sizeof(hb)), 0);
	assert_int_equal(netd_reply(big, &h, NULL, 0), 0);
	assert_int_equal(h.status, RDC_ST_TOOBIG);
	assert_true(netd_closed(big));
	close(big);
	assert_int_equal(netd_call(ctl, RDC_MSG_PING, 11, NULL, 0, NULL, 0),
			 RDC_ST_OK);
	close(obs);
	close(ctl);
	assert_int_equal(netd_stop(&d), 0);
}

/*
 * A recording daemon drives the pins as any other does, and its trace
 * replays the change: the PINS read after it matches on replay, and the
 * chip is left with BL_EN low.
 */
static void test_record(void **state)
{
	char trace[128], dir[] = "/tmp/rdc-pins-XXXXXX";
	const char *args[] = { "--stepped", "--record", trace, NULL };
	struct rdc_replay_result res;
	struct netd d;
	rdc_dev *dev, *rep = NULL;
	uint32_t p;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(trace, sizeof(trace), "%s/trace", dir);
	assert_int_equal(netd_start(&d, args), 0);
	assert_int_equal(rdc_open(d.unix_uri, &dev), 0);
	assert_int_equal(rdc_pins_set(dev, RDC_PIN_BL_EN, 0), 0);
	assert_int_equal(rdc_pins_get(dev, &p), 0);
	assert_int_equal(p & RDC_PINS_IN, RDC_PIN_RESET_N);
	assert_int_equal(rdc_sim_step(dev, 1000), 0);
	rdc_close(dev);
	assert_int_equal(netd_stop(&d), 0);

	assert_int_equal(rdc_replay_file(trace, &res, &rep), 0);
	assert_int_equal(res.mismatches, 0);
	assert_int_equal(res.time, 1000);
	assert_int_equal(rdc_pins_get(rep, &p), 0);
	assert_int_equal(p & RDC_PINS_IN, RDC_PIN_RESET_N);
	rdc_close(rep);
	unlink(trace);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_levels_and_args),
		cmocka_unit_test(test_te_times),
		cmocka_unit_test(test_irq_edge),
		cmocka_unit_test(test_reset_n),
		cmocka_unit_test(test_bl_en),
		cmocka_unit_test(test_present_on_te),
		cmocka_unit_test(test_unix),
		cmocka_unit_test(test_proto),
		cmocka_unit_test(test_record),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
