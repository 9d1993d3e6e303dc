// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The "fbdev:" backend: an RDC-1 simulated in the kernel by rdcfb.ko,
 * reached through its framebuffer device, "fbdev:/dev/fbN".
 *
 * Registers, command buffers, waits and frames go through the private
 * ioctls of driver/rdcfb_ioctl.h; VRAM is the framebuffer's own mapping,
 * so reading and writing it costs no system call and, like sim:'s
 * rdc_hw_vram_read/write, no simulated cycles.  Whether simulated time
 * follows the wall clock or moves only inside waits is the module's
 * `clock=` parameter: with clock=stepped the same operations give the
 * same frames and cycle counts as sim:.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef RDC_HAVE_GPIOD
#include <dirent.h>
#include <gpiod.h>
#include <stdio.h>
#include <sys/sysmacros.h>
#endif

#include "rdc_priv.h"
#include "rdcfb_ioctl.h"

/* Wall-clock slack on top of a wait's simulated budget when paced. */
#define FBDEV_WAIT_SLACK_MS 1000u

/* Edge events read from the GPIO chip at once. */
#define FBDEV_EDGE_BUF 16u
/* Stepped clock: simulated cycles a pins wait moves between looks. */
#define FBDEV_PINS_STEP RDC_WAIT_SLICE_MAX
/* Stepped clock: how long an edge PINS already shows may take to arrive. */
#define FBDEV_EDGE_LATE_NS 1000000000ll

/* The pins as GPIO lines: TE, IRQ, RESET_N, BL_EN, in RDC_PIN_* order. */
#define FBDEV_NPINS 4u

struct fbdev_gpio;

struct fbdev {
	int fd;
	uint8_t *vram;
	uint32_t vram_size;
	uint32_t core_khz;
	struct fbdev_gpio *gpio; /* opened on the first rdc_pins_* call */
};

static struct fbdev *fbdev_of(rdc_dev *dev)
{
	return dev->priv;
}

/*
 * The one place an errno from the device becomes a library error.  The
 * meanings follow rdcfb_ioctl.h's list; anything else is a transport
 * failure.
 */
static int fbdev_error(int err)
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

/* ioctl() as a library error; a signal does not abandon the request. */
static int fbdev_ioctl(struct fbdev *f, unsigned long req, void *arg)
{
	int r;

	do {
		r = ioctl(f->fd, req, arg);
	} while (r < 0 && errno == EINTR);
	return r < 0 ? fbdev_error(errno) : 0;
}

static int fbdev_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	struct rdcfb_reg r = { .reg = reg };
	int ret = fbdev_ioctl(fbdev_of(dev), RDCFB_IOC_REG_READ, &r);

	if (!ret)
		*val = r.val;
	return ret;
}

static int fbdev_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	struct rdcfb_reg r = { .reg = reg, .val = val };

	return fbdev_ioctl(fbdev_of(dev), RDCFB_IOC_REG_WRITE, &r);
}

static void fbdev_gpio_free(struct fbdev_gpio *g);

static void fbdev_free(struct fbdev *f)
{
	fbdev_gpio_free(f->gpio);
	if (f->vram)
		munmap(f->vram, f->vram_size);
	if (f->fd >= 0)
		close(f->fd);
	free(f);
}

/*
 * Make sure `f->fd` is an rdcfb framebuffer before anything is asked of
 * it: any other character device could take our ioctl numbers to mean
 * something else.
 */
static int fbdev_probe(struct fbdev *f)
{
	struct fb_fix_screeninfo fix;
	struct stat st;
	struct rdcfb_reg id = { .reg = RDC_REG_ID };
	struct rdcfb_reg size = { .reg = RDC_REG_VRAM_SIZE };
	struct rdcfb_reg khz = { .reg = RDC_REG_CORE_KHZ };
	size_t idlen = sizeof(RDCFB_ID);

	if (fstat(f->fd, &st) || !S_ISCHR(st.st_mode))
		return RDC_E_URI;
	memset(&fix, 0, sizeof(fix));
	if (ioctl(f->fd, FBIOGET_FSCREENINFO, &fix))
		return RDC_E_URI;
	if (idlen > sizeof(fix.id) || memcmp(fix.id, RDCFB_ID, idlen))
		return RDC_E_URI;
	if (fbdev_ioctl(f, RDCFB_IOC_REG_READ, &id) || id.val != RDC_ID_VALUE)
		return RDC_E_URI;
	if (fbdev_ioctl(f, RDCFB_IOC_REG_READ, &size) ||
	    fbdev_ioctl(f, RDCFB_IOC_REG_READ, &khz))
		return RDC_E_IO;
	/* The mapping is the framebuffer's; the chip may own less of it. */
	f->vram_size = RDC_MIN(size.val, fix.smem_len);
	f->core_khz = khz.val;
	if (!f->vram_size)
		return RDC_E_IO;
	return 0;
}

static int fbdev_open(rdc_dev *dev, const char *opts)
{
	struct fbdev *f;
	void *map;
	int ret;

	/* A path to the device node, nothing else. */
	if (opts[0] != '/')
		return RDC_E_URI;
	f = calloc(1, sizeof(*f));
	if (!f)
		return RDC_E_NOMEM;
	f->fd = open(opts, O_RDWR | O_CLOEXEC | O_NOCTTY);
	if (f->fd < 0) {
		ret = fbdev_error(errno);
		fbdev_free(f);
		/* A missing node is a bad URI, not a bad transport. */
		return ret == RDC_E_IO ? RDC_E_URI : ret;
	}
	ret = fbdev_probe(f);
	if (ret) {
		fbdev_free(f);
		return ret;
	}
	map = mmap(NULL, f->vram_size, PROT_READ | PROT_WRITE, MAP_SHARED,
		   f->fd, 0);
	if (map == MAP_FAILED) {
		ret = fbdev_error(errno);
		fbdev_free(f);
		return ret == RDC_E_NOMEM ? ret : RDC_E_IO;
	}
	f->vram = map;
	dev->priv = f;
	return 0;
}

static void fbdev_close(rdc_dev *dev)
{
	fbdev_free(fbdev_of(dev));
	dev->priv = NULL;
}

static int fbdev_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	struct fbdev *f = fbdev_of(dev);

	if (len > f->vram_size || addr > f->vram_size - len)
		return RDC_E_RANGE;
	if (len)
		memcpy(buf, f->vram + addr, len);
	return 0;
}

static int fbdev_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			    size_t len)
{
	struct fbdev *f = fbdev_of(dev);

	if (len > f->vram_size || addr > f->vram_size - len)
		return RDC_E_RANGE;
	if (len)
		memcpy(f->vram + addr, buf, len);
	return 0;
}

/*
 * Words up to the last command boundary at or before `max` (the driver
 * checks each buffer command by command, so a command must not be split
 * between two of them).  A command longer than RDC_CMD_MAX_ARGS is one
 * word: the DP consumes only its header.
 */
static size_t fbdev_piece(const uint32_t *w, size_t n, size_t max)
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

static int fbdev_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	struct fbdev *f = fbdev_of(dev);

	while (n) {
		size_t k = fbdev_piece(words, n, RDCFB_SUBMIT_MAX_WORDS);
		struct rdcfb_submit s = {
			.words = (uintptr_t)words,
			.count = (uint32_t)k,
		};
		int ret = fbdev_ioctl(f, RDCFB_IOC_SUBMIT, &s);

		if (ret)
			return ret;
		words += k;
		n -= k;
	}
	return 0;
}

static uint32_t fbdev_wait_kind(enum rdc_wait_test k)
{
	switch (k) {
	case RDC_WAIT_TEST_GE:
		return RDCFB_WAIT_GE;
	case RDC_WAIT_TEST_WRAP_GE:
		return RDCFB_WAIT_WRAP_GE;
	case RDC_WAIT_TEST_EQ:
		return RDCFB_WAIT_EQ;
	default:
		return RDCFB_WAIT_NONE;
	}
}

static int fbdev_wait(rdc_dev *dev, const struct rdc_wait *w)
{
	struct fbdev *f = fbdev_of(dev);
	struct rdcfb_wait rw;
	uint64_t budget = w->budget ? w->budget : RDC_WAIT_BUDGET_DEFAULT;
	uint64_t ms;

	memset(&rw, 0, sizeof(rw));
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		rw.term[i].kind = fbdev_wait_kind(w->term[i].kind);
		rw.term[i].reg = w->term[i].reg;
		rw.term[i].mask = w->term[i].mask;
		rw.term[i].value = w->term[i].value;
	}
	rw.flags = w->needs_dp ? RDCFB_WAIT_NEEDS_DP : 0;
	rw.budget = budget;
	/* Paced, the budget is wall time too: allow it, and a little more. */
	ms = f->core_khz ? budget / f->core_khz : 0;
	ms += FBDEV_WAIT_SLACK_MS;
	rw.timeout_ms = ms > UINT32_MAX ? UINT32_MAX : (uint32_t)ms;
	return fbdev_ioctl(f, RDCFB_IOC_WAIT, &rw);
}

static int fbdev_step(rdc_dev *dev, uint64_t cycles)
{
	struct rdcfb_step s = { .cycles = cycles };

	return fbdev_ioctl(fbdev_of(dev), RDCFB_IOC_STEP, &s);
}

/* Size of the latest frame: 0, 1 if none has completed yet. */
static int fbdev_frame_size(struct fbdev *f, uint32_t *width, uint32_t *height)
{
	struct rdcfb_frame fr;
	int r;

	memset(&fr, 0, sizeof(fr));
	do {
		r = ioctl(f->fd, RDCFB_IOC_FRAME, &fr);
	} while (r < 0 && errno == EINTR);
	if (r < 0)
		return errno == EAGAIN ? 1 : fbdev_error(errno);
	if (!fr.seq)
		return 1;
	*width = fr.width;
	*height = fr.height;
	return 0;
}

static int fbdev_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			    uint32_t *width, uint32_t *height)
{
	struct fbdev *f = fbdev_of(dev);
	struct rdcfb_frame fr;
	int r, ret;

	if (buf && cap) {
		memset(&fr, 0, sizeof(fr));
		fr.pixels = (uintptr_t)buf;
		fr.cap = cap > UINT32_MAX ? UINT32_MAX : (uint32_t)cap;
		do {
			r = ioctl(f->fd, RDCFB_IOC_FRAME, &fr);
		} while (r < 0 && errno == EINTR);
		if (!r && fr.seq) {
			*width = fr.width;
			*height = fr.height;
			return 0;
		}
		if (!r || errno == EAGAIN)
			return 1;
		ret = fbdev_error(errno);
		/* Too small a buffer: say how big the frame is. */
		if (fbdev_frame_size(f, width, height) == 0 &&
		    (size_t)*width * *height > cap)
			return RDC_E_RANGE;
		return ret;
	}
	ret = fbdev_frame_size(f, width, height);
	if (ret)
		return ret;
	return (size_t)*width * *height > cap ? RDC_E_RANGE : 0;
}

/* ---- Pins: the device's GPIO chip, through libgpiod ---------------------- */
#ifdef RDC_HAVE_GPIOD

static const char *const fbdev_pin_name[FBDEV_NPINS] = {
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
struct fbdev_gpio {
	struct gpiod_chip *chip;
	unsigned int off[FBDEV_NPINS];
	struct gpiod_line_request *in;
	struct gpiod_line_request *out[FBDEV_NPINS];
	uint32_t driven; /* levels of the lines we drive */
	struct gpiod_edge_event_buffer *buf;
	int buf_n, buf_next; /* events read and not yet looked at */
	uint32_t levels;     /* TE and IRQ as the last event left them */
	bool stepped;	     /* the module's clock=stepped: waits move time */
};

static void fbdev_gpio_free(struct fbdev_gpio *g)
{
	if (!g)
		return;
	for (unsigned int i = 0; i < FBDEV_NPINS; i++)
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
 * The chip's label names the framebuffer's platform device: "rdcfb.N"
 * (/sys/dev/char/MAJ:MIN/device) gives "rdcfb.N-pins".
 */
static int fbdev_gpio_label(struct fbdev *f, char *label, size_t cap)
{
	char link[128], target[256];
	const char *base;
	struct stat st;
	ssize_t n;

	if (fstat(f->fd, &st))
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

static struct gpiod_chip *fbdev_gpio_find(const char *label)
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

static struct gpiod_line_request *fbdev_gpio_request(struct gpiod_chip *chip,
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

/* TE, IRQ and the chip's levels (the inputs from PINS until we drive). */
static int fbdev_gpio_sample(struct fbdev *f)
{
	struct fbdev_gpio *g = f->gpio;
	enum gpiod_line_value v[2];

	if (gpiod_line_request_get_values(g->in, v))
		return fbdev_error(errno);
	g->levels = (v[0] == GPIOD_LINE_VALUE_ACTIVE ? RDC_PIN_TE : 0) |
		    (v[1] == GPIOD_LINE_VALUE_ACTIVE ? RDC_PIN_IRQ : 0);
	return 0;
}

static int fbdev_gpio_open(struct fbdev *f)
{
	struct fbdev_gpio *g;
	char label[160];
	int ret;

	if (f->gpio)
		return 0;
	ret = fbdev_gpio_label(f, label, sizeof(label));
	if (ret)
		return ret;
	g = calloc(1, sizeof(*g));
	if (!g)
		return RDC_E_NOMEM;
	/* a module without the pins' chip offers no pins */
	ret = RDC_E_NOSYS;
	g->chip = fbdev_gpio_find(label);
	if (!g->chip)
		goto fail;
	for (unsigned int i = 0; i < FBDEV_NPINS; i++) {
		int o = gpiod_chip_get_line_offset_from_name(g->chip,
							     fbdev_pin_name[i]);

		if (o < 0)
			goto fail;
		g->off[i] = (unsigned int)o;
	}
	ret = RDC_E_NOMEM;
	g->buf = gpiod_edge_event_buffer_new(FBDEV_EDGE_BUF);
	if (!g->buf)
		goto fail;
	g->in = fbdev_gpio_request(g->chip, g->off, 2, false, false);
	if (!g->in) {
		ret = errno == EBUSY ? RDC_E_BUSY : fbdev_error(errno);
		goto fail;
	}
	f->gpio = g;
	/* a step of nothing: refused (EPERM) on the paced clock */
	g->stepped = !fbdev_ioctl(f, RDCFB_IOC_STEP,
				  &(struct rdcfb_step){ .cycles = 0 });
	ret = fbdev_gpio_sample(f);
	if (ret) {
		f->gpio = NULL;
		goto fail;
	}
	return 0;
fail:
	fbdev_gpio_free(g);
	return ret;
}

_Static_assert(RDC_PIN_TE == 1u && RDC_PIN_IRQ == 2u && RDC_PIN_RESET_N == 4u &&
		       RDC_PIN_BL_EN == 8u,
	       "fbdev_pin_name is in RDC_PIN_* bit order");

static uint32_t fbdev_bit(unsigned int i)
{
	return 1u << i;
}

static int fbdev_pins_get(rdc_dev *dev, uint32_t *levels)
{
	struct fbdev *f = fbdev_of(dev);
	uint32_t in = 0, mine = 0;
	int ret = fbdev_gpio_open(f);

	if (!ret)
		ret = fbdev_gpio_sample(f);
	if (ret)
		return ret;
	for (unsigned int i = 2; i < FBDEV_NPINS; i++)
		if (f->gpio->out[i])
			mine |= fbdev_bit(i);
	/* lines this handle does not drive: as the chip sees them */
	if (mine != RDC_PINS_IN) {
		ret = fbdev_reg_read(dev, RDC_REG_PINS, &in);
		if (ret)
			return ret;
	}
	*levels = f->gpio->levels | (in & RDC_PINS_IN & ~mine) |
		  (f->gpio->driven & mine);
	return 0;
}

static int fbdev_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	struct fbdev *f = fbdev_of(dev);
	struct fbdev_gpio *g;
	int ret = fbdev_gpio_open(f);

	if (ret)
		return ret;
	g = f->gpio;
	for (unsigned int i = 2; i < FBDEV_NPINS; i++) {
		uint32_t bit = fbdev_bit(i);
		bool high = levels & bit;

		if (!(mask & bit))
			continue;
		if (!g->out[i]) {
			g->out[i] = fbdev_gpio_request(g->chip, &g->off[i], 1,
						       true, high);
			if (!g->out[i])
				return errno == EBUSY ? RDC_E_BUSY :
							fbdev_error(errno);
		} else if (gpiod_line_request_set_value(
				   g->out[i], g->off[i],
				   high ? GPIOD_LINE_VALUE_ACTIVE :
					  GPIOD_LINE_VALUE_INACTIVE)) {
			return fbdev_error(errno);
		}
		g->driven = (g->driven & ~bit) | (high ? bit : 0);
	}
	return 0;
}

/* The next buffered edge event, reading more within `ns`; 0 on timeout. */
static int fbdev_gpio_next(struct fbdev_gpio *g, int64_t ns,
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
		return r < 0 ? fbdev_error(errno) : 0;
	r = gpiod_line_request_read_edge_events(g->in, g->buf, FBDEV_EDGE_BUF);
	if (r < 0)
		return fbdev_error(errno);
	g->buf_n = r;
	g->buf_next = 0;
	if (!r)
		return 0;
	*out = gpiod_edge_event_buffer_get_event(g->buf,
						 (unsigned long)g->buf_next++);
	return 1;
}

/*
 * Note an edge event in the levels; 1 if it is one the caller wants (ev
 * filled in), 0 if not, or an error.
 */
static int fbdev_gpio_take(rdc_dev *dev, struct fbdev_gpio *g,
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
	g->levels = (g->levels & ~bit) | (rising ? bit : 0);
	if (!(pins & bit) ||
	    !(edges & (rising ? RDC_EDGE_RISING : RDC_EDGE_FALLING)))
		return 0;
	ev->pins = bit;
	ev->time = RDC_PIN_TIME_NONE;
	ev->wall_ns = gpiod_edge_event_get_timestamp_ns(e);
	ret = fbdev_reg_read(dev, RDC_REG_PINS, &in);
	if (ret)
		return ret;
	ev->levels = g->levels | (in & RDC_PINS_IN);
	return 1;
}

/*
 * Paced, the chip runs by itself: wait for the lines' events in wall
 * time.  Stepped, nothing moves unless asked, so the wait moves simulated
 * time as waits on sim: do, a slice at a time up to the budget; when PINS
 * shows TE or IRQ where the last event did not leave them, the edge's
 * event is on its way (the driver hands edges over from a worker), and
 * the wait takes it before time moves on.
 */
static int fbdev_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			   uint64_t budget_cycles, uint64_t timeout_us,
			   struct rdc_pin_edge *ev)
{
	struct fbdev *f = fbdev_of(dev);
	uint64_t deadline, now, moved = 0;
	struct fbdev_gpio *g;
	int ret = fbdev_gpio_open(f);

	if (ret)
		return ret;
	g = f->gpio;
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
		ret = fbdev_gpio_next(g, ns, &e);
		if (ret > 0)
			ret = fbdev_gpio_take(dev, g, e, pins, edges, ev);
		if (ret < 0)
			return ret;
		if (ret > 0)
			return 0;
		if (e)
			continue; /* an edge nobody asked for */
		if (!g->stepped)
			return RDC_E_TIMEOUT;
		ret = fbdev_reg_read(dev, RDC_REG_PINS, &in);
		if (ret)
			return ret;
		if ((in ^ g->levels) & RDC_PINS_OUT) {
			ret = fbdev_gpio_next(g, FBDEV_EDGE_LATE_NS, &e);
			if (ret > 0)
				ret = fbdev_gpio_take(dev, g, e, pins, edges,
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
		ns = (int64_t)RDC_MIN(FBDEV_PINS_STEP, budget_cycles - moved);
		ret = fbdev_step(dev, (uint64_t)ns);
		if (ret)
			return ret;
		moved += (uint64_t)ns;
	}
}

#else /* !RDC_HAVE_GPIOD: no GPIO lines, no pins */

static void fbdev_gpio_free(struct fbdev_gpio *g)
{
	(void)g;
}

static int fbdev_pins_get(rdc_dev *dev, uint32_t *levels)
{
	(void)dev;
	(void)levels;
	return RDC_E_NOSYS;
}

static int fbdev_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	(void)dev;
	(void)mask;
	(void)levels;
	return RDC_E_NOSYS;
}

static int fbdev_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			   uint64_t budget_cycles, uint64_t timeout_us,
			   struct rdc_pin_edge *ev)
{
	(void)dev;
	(void)pins;
	(void)edges;
	(void)budget_cycles;
	(void)timeout_us;
	(void)ev;
	return RDC_E_NOSYS;
}

#endif /* RDC_HAVE_GPIOD */

/* rdcfb's framebuffers: /sys/class/graphics/fbN whose name is RDCFB_ID. */
static int fbdev_list(rdc_found_fn fn, void *arg)
{
	DIR *d = opendir("/sys/class/graphics");
	struct dirent *e;
	int found = 0;

	if (!d)
		return 0;
	while ((e = readdir(d))) {
		struct rdc_found f;
		char path[300], name[32] = "";
		FILE *nf;

		if (strncmp(e->d_name, "fb", 2) || strlen(e->d_name) > 12)
			continue;
		snprintf(path, sizeof(path), "/sys/class/graphics/%.12s/name",
			 e->d_name);
		nf = fopen(path, "r");
		if (!nf)
			continue;
		if (!fgets(name, sizeof(name), nf))
			name[0] = 0;
		fclose(nf);
		name[strcspn(name, "\n")] = 0;
		if (strcmp(name, RDCFB_ID))
			continue;
		memset(&f, 0, sizeof(f));
		snprintf(f.uri, sizeof(f.uri), "fbdev:/dev/%.12s", e->d_name);
		snprintf(f.info, sizeof(f.info), "rdcfb.ko framebuffer %.12s",
			 e->d_name);
		fn(&f, arg);
		found++;
	}
	closedir(d);
	return found;
}

const struct rdc_backend rdc_backend_fbdev = {
	.list = fbdev_list,
	.scheme = "fbdev",
	.open = fbdev_open,
	.close = fbdev_close,
	.reg_read = fbdev_reg_read,
	.reg_write = fbdev_reg_write,
	.vram_read = fbdev_vram_read,
	.vram_write = fbdev_vram_write,
	.submit = fbdev_submit,
	.wait = fbdev_wait,
	.step = fbdev_step,
	.frame_grab = fbdev_frame_grab,
	.pins_set = fbdev_pins_set,
	.pins_get = fbdev_pins_get,
	.pins_wait = fbdev_pins_wait,
};
