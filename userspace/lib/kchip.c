// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The RDC-1 simulated in the kernel, as librdc's fbdev: and drm: backends
 * both reach it: errors, command pieces and the pins as GPIO lines
 * (kchip.h).
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#ifdef RDC_HAVE_GPIOD
#include <dirent.h>
#include <gpiod.h>
#include <stdio.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#endif

#include "kchip.h"
#include "rdc_state_uapi.h"

/* Edge events read from the GPIO chip at once. */
#define KCHIP_EDGE_BUF 16u
/* Stepped clock: simulated cycles a pins wait moves between looks. */
#define KCHIP_PINS_STEP RDC_WAIT_SLICE_MAX
/* Stepped clock: how long an edge PINS already shows may take to arrive. */
#define KCHIP_EDGE_LATE_NS 1000000000ll

/* The pins as GPIO lines: TE, IRQ, RESET_N, BL_EN, in RDC_PIN_* order. */
#define KCHIP_NPINS 4u

int rdc_kchip_error(int err)
{
	switch (err) {
	case 0:
		return 0;
	case EINVAL:
	case EFAULT:
		return RDC_E_INVAL;
	case E2BIG:
	case ERANGE:
	case ENOSPC:
	case EOVERFLOW:
		return RDC_E_RANGE;
	case ENOMEM:
		return RDC_E_NOMEM;
	case EPROTO:
		return RDC_E_PROTO;
	case ETIMEDOUT:
		return RDC_E_TIMEOUT;
	case EIO:
		return RDC_E_HALTED;
	case EBUSY:
		return RDC_E_BUSY;
	case EPERM: /* STEP on a paced clock */
	case ENOTTY:
	case EOPNOTSUPP:
		return RDC_E_NOSYS;
	case ENOENT:
	case EACCES:
	case EROFS:
		return RDC_E_FILE;
	default: /* ENODEV (module going away), ENXIO, ... */
		return RDC_E_IO;
	}
}

/*
 * A command longer than RDC_CMD_MAX_ARGS is one word: the DP consumes
 * only its header.
 */
size_t rdc_kchip_piece(const uint32_t *w, size_t n, size_t max)
{
	size_t i = 0;

	if (n <= max)
		return n;
	for (;;) {
		size_t len = RDC_CMD_LEN(w[i]);
		size_t next = i + 1 + (len > RDC_CMD_MAX_ARGS ? 0 : len);

		if (next > max)
			break;
		i = next;
	}
	/* cannot happen while max > RDC_CMD_MAX_ARGS; never loop forever */
	return i ? i : max;
}

void rdc_kchip_state_resume(const struct rdc_chip_state *st,
			    struct rdc_hw_resume *s)
{
	s->now = st->now;
	s->frame_start = st->frame_start;
	s->frame_count = st->frame_count;
	s->perf.busy = st->busy;
	s->perf.stall = st->stall;
	s->perf.pixels = st->pixels;
	s->perf.cmds = st->cmds;
	s->perf.last_cycles = st->last_cycles;
	s->perf.last_opcode = st->last_opcode;
	s->perf.culled = st->culled;
	s->fence = st->fence;
	s->irq_status = st->irq_status;
	s->err_code = st->err_code;
	s->err_info = st->err_info;
	s->open_row = st->open_row;
	s->scanning = st->flags & RDC_CHIP_STATE_SCANNING;
	s->dp_active = st->flags & RDC_CHIP_STATE_DP_ACTIVE;
	s->timing.h_total = st->h_total;
	s->timing.h_display = st->h_display;
	s->timing.h_sync_start = st->h_sync_start;
	s->timing.h_sync_end = st->h_sync_end;
	s->timing.v_total = st->v_total;
	s->timing.v_display = st->v_display;
	s->timing.v_sync_start = st->v_sync_start;
	s->timing.v_sync_end = st->v_sync_end;
	s->timing.pixclk_khz = st->pixclk_khz;
	s->timing.flags = st->crtc_flags;
	s->fb_base = st->fb_base;
	s->fb_stride = st->fb_stride;
	s->fb_format = st->fb_format;
	s->cursor_ctrl = st->cursor_ctrl;
	s->cursor_base = st->cursor_base;
	s->raster_base = st->raster_base;
	s->raster_ctrl = st->raster_ctrl;
	s->gamma = st->flags & RDC_CHIP_STATE_GAMMA;
}

/* ---- Pins: the device's GPIO chip, through libgpiod ---------------------- */
#ifdef RDC_HAVE_GPIOD

static const char *const kchip_pin_name[KCHIP_NPINS] = {
	"TE",
	"IRQ",
	"RESET_N",
	"BL_EN",
};

/*
 * TE and IRQ are requested once as inputs with edge detection; RESET_N and
 * BL_EN each as an output the first time they are driven (requesting an
 * output drives it, so a line nobody set is left alone), then held.
 */
struct rdc_kchip_pins {
	struct gpiod_chip *chip;
	unsigned int off[KCHIP_NPINS];
	struct gpiod_line_request *in;
	struct gpiod_line_request *out[KCHIP_NPINS];
	uint32_t driven; /* levels of the lines we drive */
	struct gpiod_edge_event_buffer *buf;
	int buf_n, buf_next; /* events read and not yet looked at */
	uint32_t levels;     /* TE and IRQ as the last event left them */
	bool stepped;	     /* the module's clock=stepped: waits move time */
	bool waited;	     /* a wait has returned: RDC_EDGE_QUEUED's start */
};

void rdc_kchip_pins_free(struct rdc_kchip_pins *g)
{
	if (!g)
		return;
	for (unsigned int i = 0; i < KCHIP_NPINS; i++)
		if (g->out[i])
			gpiod_line_request_release(g->out[i]);
	if (g->in)
		gpiod_line_request_release(g->in);
	if (g->buf)
		gpiod_edge_event_buffer_free(g->buf);
	if (g->chip)
		gpiod_chip_close(g->chip);
	free(g);
}

/*
 * The chip's label names the device node's device: "rdcfb.N" or
 * "rdcdrm.N" (/sys/dev/char/MAJ:MIN/device) gives "rdcfb.N-pins" or
 * "rdcdrm.N-pins".
 */
static int kchip_gpio_label(int fd, char *label, size_t cap)
{
	char link[128], target[256];
	const char *base;
	struct stat st;
	ssize_t n;

	if (fstat(fd, &st))
		return RDC_E_IO;
	snprintf(link, sizeof(link), "/sys/dev/char/%u:%u/device",
		 major(st.st_rdev), minor(st.st_rdev));
	n = readlink(link, target, sizeof(target) - 1);
	if (n <= 0)
		return RDC_E_NOSYS;
	target[n] = 0;
	base = strrchr(target, '/');
	base = base ? base + 1 : target;
	if ((size_t)snprintf(label, cap, "%s-pins", base) >= cap)
		return RDC_E_NOSYS;
	return 0;
}

static struct gpiod_chip *kchip_gpio_find(const char *label)
{
	struct gpiod_chip *found = NULL;
	struct dirent *de;
	DIR *dir = opendir("/dev");

	if (!dir)
		return NULL;
	while (!found && (de = readdir(dir))) {
		char path[300];
		struct gpiod_chip *c;
		struct gpiod_chip_info *info;

		if (strncmp(de->d_name, "gpiochip", 8))
			continue;
		snprintf(path, sizeof(path), "/dev/%s", de->d_name);
		c = gpiod_chip_open(path);
		if (!c)
			continue;
		info = gpiod_chip_get_info(c);
		if (info && !strcmp(gpiod_chip_info_get_label(info), label))
			found = c;
		else
			gpiod_chip_close(c);
		if (info)
			gpiod_chip_info_free(info);
	}
	closedir(dir);
	return found;
}

static struct gpiod_line_request *kchip_gpio_request(struct gpiod_chip *chip,
						     const unsigned int *off,
						     size_t n, bool output,
						     bool high)
{
	struct gpiod_line_settings *ls = gpiod_line_settings_new();
	struct gpiod_line_config *lc = gpiod_line_config_new();
	struct gpiod_request_config *rc = gpiod_request_config_new();
	struct gpiod_line_request *req = NULL;

	if (!ls || !lc || !rc)
		goto out;
	if (output) {
		gpiod_line_settings_set_direction(ls,
						  GPIOD_LINE_DIRECTION_OUTPUT);
		gpiod_line_settings_set_output_value(
			ls, high ? GPIOD_LINE_VALUE_ACTIVE :
				   GPIOD_LINE_VALUE_INACTIVE);
	} else {
		gpiod_line_settings_set_direction(ls,
						  GPIOD_LINE_DIRECTION_INPUT);
		gpiod_line_settings_set_edge_detection(ls,
						       GPIOD_LINE_EDGE_BOTH);
		gpiod_line_settings_set_event_clock(ls,
						    GPIOD_LINE_CLOCK_MONOTONIC);
	}
	if (gpiod_line_config_add_line_settings(lc, off, n, ls))
		goto out;
	gpiod_request_config_set_consumer(rc, "librdc");
	gpiod_request_config_set_event_buffer_size(rc, 64);
	req = gpiod_chip_request_lines(chip, rc, lc);
out:
	gpiod_request_config_free(rc);
	gpiod_line_config_free(lc);
	gpiod_line_settings_free(ls);
	return req;
}

/* TE and IRQ as the lines show them now. */
static int kchip_gpio_sample(struct rdc_kchip_pins *g)
{
	enum gpiod_line_value v[2];

	if (gpiod_line_request_get_values(g->in, v))
		return rdc_kchip_error(errno);
	g->levels = (v[0] == GPIOD_LINE_VALUE_ACTIVE ? RDC_PIN_TE : 0) |
		    (v[1] == GPIOD_LINE_VALUE_ACTIVE ? RDC_PIN_IRQ : 0);
	return 0;
}

static int kchip_gpio_open(rdc_dev *dev, int fd, struct rdc_kchip_pins **p)
{
	struct rdc_kchip_pins *g;
	char label[160];
	int ret;

	if (*p)
		return 0;
	ret = kchip_gpio_label(fd, label, sizeof(label));
	if (ret)
		return ret;
	g = calloc(1, sizeof(*g));
	if (!g)
		return RDC_E_NOMEM;
	/* a module without the pins' chip offers no pins */
	ret = RDC_E_NOSYS;
	g->chip = kchip_gpio_find(label);
	if (!g->chip)
		goto fail;
	for (unsigned int i = 0; i < KCHIP_NPINS; i++) {
		int o = gpiod_chip_get_line_offset_from_name(g->chip,
							     kchip_pin_name[i]);

		if (o < 0)
			goto fail;
		g->off[i] = (unsigned int)o;
	}
	ret = RDC_E_NOMEM;
	g->buf = gpiod_edge_event_buffer_new(KCHIP_EDGE_BUF);
	if (!g->buf)
		goto fail;
	g->in = kchip_gpio_request(g->chip, g->off, 2, false, false);
	if (!g->in) {
		ret = errno == EBUSY ? RDC_E_BUSY : rdc_kchip_error(errno);
		goto fail;
	}
	/* a step of nothing: refused (EPERM) on the paced clock */
	g->stepped = dev->be->step && !dev->be->step(dev, 0);
	ret = kchip_gpio_sample(g);
	if (ret)
		goto fail;
	*p = g;
	return 0;
fail:
	rdc_kchip_pins_free(g);
	return ret;
}

_Static_assert(RDC_PIN_TE == 1u && RDC_PIN_IRQ == 2u && RDC_PIN_RESET_N == 4u &&
		       RDC_PIN_BL_EN == 8u,
	       "kchip_pin_name is in RDC_PIN_* bit order");

static uint32_t kchip_bit(unsigned int i)
{
	return 1u << i;
}

int rdc_kchip_pins_get(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t *levels)
{
	struct rdc_kchip_pins *g;
	uint32_t in = 0, mine = 0;
	int ret = kchip_gpio_open(dev, fd, p);

	if (!ret)
		ret = kchip_gpio_sample(*p);
	if (ret)
		return ret;
	g = *p;
	for (unsigned int i = 2; i < KCHIP_NPINS; i++)
		if (g->out[i])
			mine |= kchip_bit(i);
	/* lines this handle does not drive: as the chip sees them */
	if (mine != RDC_PINS_IN) {
		ret = dev->be->reg_read(dev, RDC_REG_PINS, &in);
		if (ret)
			return ret;
	}
	*levels = g->levels | (in & RDC_PINS_IN & ~mine) | (g->driven & mine);
	return 0;
}

int rdc_kchip_pins_set(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t mask, uint32_t levels)
{
	struct rdc_kchip_pins *g;
	int ret = kchip_gpio_open(dev, fd, p);

	if (ret)
		return ret;
	g = *p;
	for (unsigned int i = 2; i < KCHIP_NPINS; i++) {
		uint32_t bit = kchip_bit(i);
		bool high = levels & bit;

		if (!(mask & bit))
			continue;
		if (!g->out[i]) {
			g->out[i] = kchip_gpio_request(g->chip, &g->off[i], 1,
						       true, high);
			if (!g->out[i])
				return errno == EBUSY ? RDC_E_BUSY :
							rdc_kchip_error(errno);
		} else if (gpiod_line_request_set_value(
				   g->out[i], g->off[i],
				   high ? GPIOD_LINE_VALUE_ACTIVE :
					  GPIOD_LINE_VALUE_INACTIVE)) {
			return rdc_kchip_error(errno);
		}
		g->driven = (g->driven & ~bit) | (high ? bit : 0);
	}
	return 0;
}

/* The next buffered edge event, reading more within `ns`; 0 on timeout. */
static int kchip_gpio_next(struct rdc_kchip_pins *g, int64_t ns,
			   struct gpiod_edge_event **out)
{
	int r;

	if (g->buf_next < g->buf_n) {
		*out = gpiod_edge_event_buffer_get_event(
			g->buf, (unsigned long)g->buf_next++);
		return 1;
	}
	r = gpiod_line_request_wait_edge_events(g->in, ns);
	if (r <= 0)
		return r < 0 ? rdc_kchip_error(errno) : 0;
	r = gpiod_line_request_read_edge_events(g->in, g->buf, KCHIP_EDGE_BUF);
	if (r < 0)
		return rdc_kchip_error(errno);
	g->buf_n = r;
	g->buf_next = 0;
	if (!r)
		return 0;
	*out = gpiod_edge_event_buffer_get_event(g->buf,
						 (unsigned long)g->buf_next++);
	return 1;
}

/* Note an edge event in the levels and nothing more. */
static void kchip_gpio_note(struct rdc_kchip_pins *g,
			    struct gpiod_edge_event *e)
{
	uint32_t bit = gpiod_edge_event_get_line_offset(e) == g->off[0] ?
			       RDC_PIN_TE :
			       RDC_PIN_IRQ;

	if (gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE)
		g->levels |= bit;
	else
		g->levels &= ~bit;
}

/*
 * Note an edge event in the levels; 1 if it is one the caller wants (ev
 * filled in), 0 if not, or an error.
 */
static int kchip_gpio_take(rdc_dev *dev, struct rdc_kchip_pins *g,
			   struct gpiod_edge_event *e, uint32_t pins,
			   uint32_t edges, struct rdc_pin_edge *ev)
{
	uint32_t bit, in = 0;
	bool rising;
	int ret;

	bit = gpiod_edge_event_get_line_offset(e) == g->off[0] ? RDC_PIN_TE :
								 RDC_PIN_IRQ;
	rising = gpiod_edge_event_get_event_type(e) ==
		 GPIOD_EDGE_EVENT_RISING_EDGE;
	kchip_gpio_note(g, e);
	if (!(pins & bit) ||
	    !(edges & (rising ? RDC_EDGE_RISING : RDC_EDGE_FALLING)))
		return 0;
	ev->pins = bit;
	ev->time = RDC_PIN_TIME_NONE;
	ev->wall_ns = gpiod_edge_event_get_timestamp_ns(e);
	ret = dev->be->reg_read(dev, RDC_REG_PINS, &in);
	if (ret)
		return ret;
	ev->levels = g->levels | (in & RDC_PINS_IN);
	return 1;
}

/*
 * A wait is for the next edge after the call, as on every other backend
 * (rdc_pins_wait_regs starts from the levels the call finds): the edges
 * the lines' queue holds happened before it, and go into the levels only.
 * Stepped, an edge of the last step can still be on its way (PINS shows
 * it, the queue not yet): it is waited for and dropped too.
 */
static int kchip_gpio_drain(rdc_dev *dev, struct rdc_kchip_pins *g)
{
	struct gpiod_edge_event *e;
	uint32_t in;
	int ret;

	while ((ret = kchip_gpio_next(g, 0, &e)) > 0)
		kchip_gpio_note(g, e);
	if (ret < 0 || !g->stepped)
		return ret;
	ret = dev->be->reg_read(dev, RDC_REG_PINS, &in);
	if (ret)
		return ret;
	while ((in ^ g->levels) & RDC_PINS_OUT) {
		ret = kchip_gpio_next(g, KCHIP_EDGE_LATE_NS, &e);
		if (ret < 0)
			return ret;
		if (!ret) { /* never came (a full queue): go by PINS */
			g->levels = in & RDC_PINS_OUT;
			break;
		}
		kchip_gpio_note(g, e);
	}
	return 0;
}

/*
 * Paced, the chip runs by itself: wait for the lines' events in wall
 * time.  Stepped, nothing moves unless asked, so the wait moves simulated
 * time as waits on sim: do, a slice at a time up to the budget; when PINS
 * shows TE or IRQ where the last event did not leave them, the edge's
 * event is on its way (the modules hand edges over from a worker), and
 * the wait takes it before time moves on.
 */
int rdc_kchip_pins_wait(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
			uint32_t pins, uint32_t edges, uint64_t budget_cycles,
			uint64_t timeout_us, struct rdc_pin_edge *ev)
{
	uint64_t deadline, now, moved = 0;
	struct rdc_kchip_pins *g;
	int ret = kchip_gpio_open(dev, fd, p);

	if (ret)
		return ret;
	g = *p;
	if (!(edges & RDC_EDGE_QUEUED) || !g->waited) {
		ret = kchip_gpio_drain(dev, g);
		if (ret)
			return ret;
	}
	g->waited = true;
	if (!timeout_us)
		timeout_us = RDC_WAIT_BUDGET_DEFAULT /
			     (RDC_DEFAULT_CORE_HZ / 1000000u);
	deadline = rdc_pins_wall_ns() + timeout_us * 1000u;
	for (;;) {
		struct gpiod_edge_event *e = NULL;
		int64_t ns = 0;
		uint32_t in;

		if (!g->stepped) {
			now = rdc_pins_wall_ns();
			ns = now < deadline ? (int64_t)(deadline - now) : 0;
		}
		ret = kchip_gpio_next(g, ns, &e);
		if (ret > 0)
			ret = kchip_gpio_take(dev, g, e, pins, edges, ev);
		if (ret < 0)
			return ret;
		if (ret > 0)
			return 0;
		if (e)
			continue; /* an edge nobody asked for */
		if (!g->stepped)
			return RDC_E_TIMEOUT;
		ret = dev->be->reg_read(dev, RDC_REG_PINS, &in);
		if (ret)
			return ret;
		if ((in ^ g->levels) & RDC_PINS_OUT) {
			ret = kchip_gpio_next(g, KCHIP_EDGE_LATE_NS, &e);
			if (ret > 0)
				ret = kchip_gpio_take(dev, g, e, pins, edges,
						      ev);
			if (ret < 0)
				return ret;
			if (ret > 0)
				return 0;
			if (!e) /* never came (a full queue): go by PINS */
				g->levels = in & RDC_PINS_OUT;
			continue;
		}
		if (moved >= budget_cycles)
			return RDC_E_TIMEOUT;
		ns = (int64_t)RDC_MIN(KCHIP_PINS_STEP, budget_cycles - moved);
		ret = dev->be->step(dev, (uint64_t)ns);
		if (ret)
			return ret;
		moved += (uint64_t)ns;
	}
}

#else /* !RDC_HAVE_GPIOD: no GPIO lines, no pins */

void rdc_kchip_pins_free(struct rdc_kchip_pins *p)
{
	(void)p;
}

int rdc_kchip_pins_get(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t *levels)
{
	(void)dev;
	(void)fd;
	(void)p;
	(void)levels;
	return RDC_E_NOSYS;
}

int rdc_kchip_pins_set(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
		       uint32_t mask, uint32_t levels)
{
	(void)dev;
	(void)fd;
	(void)p;
	(void)mask;
	(void)levels;
	return RDC_E_NOSYS;
}

int rdc_kchip_pins_wait(rdc_dev *dev, int fd, struct rdc_kchip_pins **p,
			uint32_t pins, uint32_t edges, uint64_t budget_cycles,
			uint64_t timeout_us, struct rdc_pin_edge *ev)
{
	(void)dev;
	(void)fd;
	(void)p;
	(void)pins;
	(void)edges;
	(void)budget_cycles;
	(void)timeout_us;
	(void)ev;
	return RDC_E_NOSYS;
}

#endif /* RDC_HAVE_GPIOD */
