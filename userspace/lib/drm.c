// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The "drm:" backend: an RDC-1 simulated in the kernel by rdcdrm.ko,
 * reached through its DRM card, "drm:/dev/dri/cardN" ("drm:" alone: the
 * first card whose DRM driver is "rdc").
 *
 * Registers, command buffers, waits, VRAM and frames go through the
 * private ioctls of driver/rdcdrm_ioctl.h, next to the KMS ioctls a
 * compositor uses on the same card; the pins are the same GPIO lines as
 * fbdev:'s (kchip.c).  The handle is no KMS client: it lets go of DRM
 * master at once, so a compositor can take the card beside it.  VRAM
 * goes through the VRAM ioctl, as bus traffic of the host aperture.
 * Whether simulated time follows the wall clock or moves only inside
 * waits is the module's clock, as for rdcfb.ko.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "kchip.h"
#include "rdc_priv.h"

#ifdef RDC_HAVE_DRM
#include <xf86drm.h>

#include "rdcdrm_ioctl.h"

/* Wall-clock slack on top of a wait's simulated budget when paced. */
#define DRM_WAIT_SLACK_MS 1000u
/* Card numbers looked at for "drm:" and rdc_list: the kernel's minors. */
#define DRM_CARDS_MAX 64

/* What to do when the card is not there. */
#define DRM_LOAD_HINT \
	"rdcdrm.ko is not loaded (load it with `modprobe rdcdrm`, or " \
	"`insmod rdcdrm.ko` from the build)"

struct drmdev {
	int fd;
	uint32_t vram_size;
	uint32_t core_khz;
	struct rdc_kchip_pins *gpio; /* opened on the first rdc_pins_* call */
};

static struct drmdev *drm_of(rdc_dev *dev)
{
	return dev->priv;
}

/*
 * ioctl() as a library error (rdcdrm_ioctl.h's errnos, the same as
 * rdcfb's, mapped by kchip.c); a signal does not abandon the request.
 */
static int drm_ioctl(struct drmdev *d, unsigned long req, void *arg)
{
	int r;

	do {
		r = ioctl(d->fd, req, arg);
	} while (r < 0 && errno == EINTR);
	return r < 0 ? rdc_kchip_error(errno) : 0;
}

static int drm_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	struct drm_rdc_reg r = { .reg = reg };
	int ret = drm_ioctl(drm_of(dev), DRM_IOCTL_RDC_REG_READ, &r);

	if (!ret)
		*val = r.val;
	return ret;
}

static int drm_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	struct drm_rdc_reg r = { .reg = reg, .val = val };

	return drm_ioctl(drm_of(dev), DRM_IOCTL_RDC_REG_WRITE, &r);
}

static void drm_free(struct drmdev *d)
{
	rdc_kchip_pins_free(d->gpio);
	if (d->fd >= 0)
		close(d->fd);
	free(d);
}

/* The DRM driver's name of the card open on fd, or "" if it is none. */
static void drm_driver_name(int fd, char *name, size_t cap)
{
	drmVersionPtr v = drmGetVersion(fd);

	name[0] = 0;
	if (!v)
		return;
	if (v->name)
		snprintf(name, cap, "%.*s", v->name_len, v->name);
	drmFreeVersion(v);
}

/*
 * Make sure d->fd is an rdcdrm card before anything is asked of it: the
 * private ioctl numbers mean something else to any other DRM driver, and
 * to any other device.
 */
static int drm_probe(struct drmdev *d, const char *path)
{
	struct drm_rdc_reg id = { .reg = RDC_REG_ID };
	struct drm_rdc_reg size = { .reg = RDC_REG_VRAM_SIZE };
	struct drm_rdc_reg khz = { .reg = RDC_REG_CORE_KHZ };
	char name[64];
	struct stat st;

	if (fstat(d->fd, &st))
		return rdc_err_detail(RDC_E_IO, "%s: %s", path,
				      strerror(errno));
	if (!S_ISCHR(st.st_mode))
		return rdc_err_detail(
			RDC_E_URI,
			"%s is not a DRM device (%s); rdcdrm.ko's "
			"cards are /dev/dri/cardN",
			path,
			S_ISREG(st.st_mode) ? "a regular file" :
					      "not a device node");
	if (drmGetNodeTypeFromFd(d->fd) < 0)
		return rdc_err_detail(RDC_E_URI,
				      "%s is not a DRM device (a character "
				      "device of another kind); rdcdrm.ko's "
				      "cards are /dev/dri/cardN",
				      path);
	drm_driver_name(d->fd, name, sizeof(name));
	if (strcmp(name, DRM_RDC_DRIVER_NAME))
		return rdc_err_detail(RDC_E_URI,
				      "%s is a DRM card of driver '%s', not "
				      "rdcdrm.ko's ('%s')",
				      path, name, DRM_RDC_DRIVER_NAME);
	if (drm_ioctl(d, DRM_IOCTL_RDC_REG_READ, &id) || id.val != RDC_ID_VALUE)
		return rdc_err_detail(RDC_E_URI,
				      "%s: driver 'rdc' without an RDC-1 "
				      "behind its register ioctl",
				      path);
	if (drm_ioctl(d, DRM_IOCTL_RDC_REG_READ, &size) ||
	    drm_ioctl(d, DRM_IOCTL_RDC_REG_READ, &khz) || !size.val)
		return rdc_err_detail(RDC_E_IO, "%s: VRAM_SIZE unreadable",
				      path);
	d->vram_size = size.val;
	d->core_khz = khz.val;
	return 0;
}

/* Open `path` for the backend: 0, or an error with its detail. */
static int drm_open_path(struct drmdev *d, const char *path)
{
	int ret;

	d->fd = open(path, O_RDWR | O_CLOEXEC | O_NOCTTY);
	if (d->fd < 0) {
		int err = errno;

		if (err == ENOENT || err == ENXIO || err == ENODEV)
			return rdc_err_detail(RDC_E_FILE,
					      "%s: %s; " DRM_LOAD_HINT, path,
					      strerror(err));
		if (err == EISDIR)
			return rdc_err_detail(RDC_E_URI,
					      "%s is a directory, not a DRM "
					      "device",
					      path);
		ret = rdc_kchip_error(err);
		return rdc_err_detail(ret == RDC_E_IO ? RDC_E_URI : ret,
				      "%s: %s", path, strerror(err));
	}
	ret = drm_probe(d, path);
	if (ret)
		return ret;
	/*
	 * Opening a card may have made this handle DRM master; a compositor
	 * on the same card needs it more than the chip's transport does.
	 */
	(void)drmDropMaster(d->fd);
	return 0;
}

/*
 * Call fn(path, arg) for each /dev/dri/cardN whose DRM driver is rdc, in
 * the order of N, until fn returns non-zero; returns how many it called.
 */
static int drm_each_card(int (*fn)(const char *path, void *arg), void *arg)
{
	int n = 0;

	for (int i = 0; i < DRM_CARDS_MAX; i++) {
		char path[32], name[64];
		int fd;

		snprintf(path, sizeof(path), DRM_DIR_NAME "/card%d", i);
		fd = open(path, O_RDWR | O_CLOEXEC | O_NOCTTY);
		if (fd < 0)
			continue;
		drm_driver_name(fd, name, sizeof(name));
		close(fd);
		if (strcmp(name, DRM_RDC_DRIVER_NAME))
			continue;
		n++;
		if (fn(path, arg))
			break;
	}
	return n;
}

static int drm_take_first(const char *path, void *arg)
{
	snprintf(arg, 32, "%s", path);
	return 1;
}

static int drm_open(rdc_dev *dev, const char *opts)
{
	char first[32] = "";
	struct drmdev *d;
	int ret;

	if (!opts[0]) {
		if (!drm_each_card(drm_take_first, first))
			return rdc_err_detail(RDC_E_FILE,
					      "drm: no DRM card of driver '%s' "
					      "in " DRM_DIR_NAME
					      "; " DRM_LOAD_HINT,
					      DRM_RDC_DRIVER_NAME);
		opts = first;
	} else if (opts[0] != '/') {
		/* a path to the device node, nothing else */
		return rdc_err_detail(RDC_E_URI,
				      "drm:%.64s: name the card by its path, "
				      "drm:/dev/dri/cardN (or drm: for the "
				      "first rdc card)",
				      opts);
	}
	d = calloc(1, sizeof(*d));
	if (!d)
		return RDC_E_NOMEM;
	ret = drm_open_path(d, opts);
	if (ret) {
		drm_free(d);
		return ret;
	}
	dev->priv = d;
	return 0;
}

static void drm_close(rdc_dev *dev)
{
	drm_free(drm_of(dev));
	dev->priv = NULL;
}

/* VRAM through the VRAM ioctl, in pieces the driver takes. */
static int drm_vram_io(rdc_dev *dev, uint32_t addr, void *buf, size_t len,
		       uint32_t flags)
{
	struct drmdev *d = drm_of(dev);
	uint8_t *p = buf;

	if (len > d->vram_size || addr > d->vram_size - len)
		return RDC_E_RANGE;
	while (len) {
		uint32_t k =
			(uint32_t)RDC_MIN(len, (size_t)DRM_RDC_VRAM_MAX_BYTES);
		struct drm_rdc_vram v = {
			.data = (uintptr_t)p,
			.addr = addr,
			.len = k,
			.flags = flags,
		};
		int ret = drm_ioctl(d, DRM_IOCTL_RDC_VRAM, &v);

		if (ret)
			return ret;
		p += k;
		addr += k;
		len -= k;
	}
	return 0;
}

static int drm_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	return drm_vram_io(dev, addr, buf, len, 0);
}

static int drm_vram_write(rdc_dev *dev, uint32_t addr, const void *buf,
			  size_t len)
{
	/* the ioctl only reads the buffer when it writes VRAM */
	return drm_vram_io(dev, addr, (void *)(uintptr_t)buf, len,
			   DRM_RDC_VRAM_WRITE);
}

static int drm_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	struct drmdev *d = drm_of(dev);

	while (n) {
		size_t k = rdc_kchip_piece(words, n, DRM_RDC_SUBMIT_MAX_WORDS);
		struct drm_rdc_submit s = {
			.words = (uintptr_t)words,
			.count = (uint32_t)k,
		};
		int ret = drm_ioctl(d, DRM_IOCTL_RDC_SUBMIT, &s);

		if (ret)
			return ret;
		words += k;
		n -= k;
	}
	return 0;
}

static uint32_t drm_wait_kind(enum rdc_wait_test k)
{
	switch (k) {
	case RDC_WAIT_TEST_GE:
		return DRM_RDC_WAIT_GE;
	case RDC_WAIT_TEST_WRAP_GE:
		return DRM_RDC_WAIT_WRAP_GE;
	case RDC_WAIT_TEST_EQ:
		return DRM_RDC_WAIT_EQ;
	default:
		return DRM_RDC_WAIT_NONE;
	}
}

_Static_assert(DRM_RDC_WAIT_TERMS == RDC_WAIT_TEST_TERMS,
	       "one DRM wait term for each of librdc's");

static int drm_wait(rdc_dev *dev, const struct rdc_wait *w)
{
	struct drmdev *d = drm_of(dev);
	struct drm_rdc_wait rw;
	uint64_t budget = w->budget ? w->budget : RDC_WAIT_BUDGET_DEFAULT;
	uint64_t ms;

	memset(&rw, 0, sizeof(rw));
	for (unsigned int i = 0; i < RDC_WAIT_TEST_TERMS; i++) {
		rw.term[i].kind = drm_wait_kind(w->term[i].kind);
		rw.term[i].reg = w->term[i].reg;
		rw.term[i].mask = w->term[i].mask;
		rw.term[i].value = w->term[i].value;
	}
	rw.flags = w->needs_dp ? DRM_RDC_WAIT_NEEDS_DP : 0;
	rw.budget = budget;
	/* Paced, the budget is wall time too: allow it, and a little more. */
	ms = d->core_khz ? budget / d->core_khz : 0;
	ms += DRM_WAIT_SLACK_MS;
	rw.timeout_ms = ms > UINT32_MAX ? UINT32_MAX : (uint32_t)ms;
	return drm_ioctl(d, DRM_IOCTL_RDC_WAIT, &rw);
}

static int drm_step(rdc_dev *dev, uint64_t cycles)
{
	struct drm_rdc_step s = { .cycles = cycles };

	return drm_ioctl(drm_of(dev), DRM_IOCTL_RDC_STEP, &s);
}

/* FRAME: 0, 1 if no frame has completed yet, or an error. */
static int drm_frame(struct drmdev *d, uint32_t *buf, size_t cap,
		     struct drm_rdc_frame *fr)
{
	int r;

	memset(fr, 0, sizeof(*fr));
	fr->pixels = (uintptr_t)buf;
	fr->cap = cap > UINT32_MAX ? UINT32_MAX : (uint32_t)cap;
	do {
		r = ioctl(d->fd, DRM_IOCTL_RDC_FRAME, fr);
	} while (r < 0 && errno == EINTR);
	if (r < 0)
		return errno == EAGAIN ? 1 : rdc_kchip_error(errno);
	return fr->seq ? 0 : 1;
}

static int drm_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap,
			  uint32_t *width, uint32_t *height)
{
	struct drmdev *d = drm_of(dev);
	struct drm_rdc_frame fr;
	int ret;

	if (buf && cap) {
		ret = drm_frame(d, buf, cap, &fr);
		if (!ret) {
			*width = fr.width;
			*height = fr.height;
			return 0;
		}
		if (ret > 0)
			return 1;
		/* Too small a buffer: say how big the frame is. */
		if (drm_frame(d, NULL, 0, &fr) == 0 &&
		    (size_t)fr.width * fr.height > cap) {
			*width = fr.width;
			*height = fr.height;
			return RDC_E_RANGE;
		}
		return ret;
	}
	ret = drm_frame(d, NULL, 0, &fr);
	if (ret)
		return ret;
	*width = fr.width;
	*height = fr.height;
	return (size_t)fr.width * fr.height > cap ? RDC_E_RANGE : 0;
}

/* ---- Pins: the device's GPIO chip (kchip.c) ----------------------------- */

static int drm_pins_get(rdc_dev *dev, uint32_t *levels)
{
	struct drmdev *d = drm_of(dev);

	return rdc_kchip_pins_get(dev, d->fd, &d->gpio, levels);
}

static int drm_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	struct drmdev *d = drm_of(dev);

	return rdc_kchip_pins_set(dev, d->fd, &d->gpio, mask, levels);
}

static int drm_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			 uint64_t budget_cycles, uint64_t timeout_us,
			 struct rdc_pin_edge *ev)
{
	struct drmdev *d = drm_of(dev);

	return rdc_kchip_pins_wait(dev, d->fd, &d->gpio, pins, edges,
				   budget_cycles, timeout_us, ev);
}

struct drm_list_ctx {
	rdc_found_fn fn;
	void *arg;
};

static int drm_list_one(const char *path, void *arg)
{
	struct drm_list_ctx *c = arg;
	const char *base = strrchr(path, '/') + 1;
	struct rdc_found f;

	memset(&f, 0, sizeof(f));
	snprintf(f.uri, sizeof(f.uri), "drm:%s", path);
	snprintf(f.info, sizeof(f.info), "rdcdrm.ko DRM card %s", base);
	c->fn(&f, c->arg);
	return 0;
}

/* rdcdrm's cards: /dev/dri/cardN whose DRM driver is rdc. */
static int drm_list(rdc_found_fn fn, void *arg)
{
	struct drm_list_ctx c = { .fn = fn, .arg = arg };

	return drm_each_card(drm_list_one, &c);
}

/* The chip's run beyond its registers, for a trace's start (record.c). */
static int drm_resume_get(rdc_dev *dev, struct rdc_hw_resume *s)
{
	struct rdc_chip_state st = { 0 };
	int ret = drm_ioctl(drm_of(dev), DRM_IOCTL_RDC_STATE, &st);

	if (ret)
		return ret;
	rdc_kchip_state_resume(&st, s);
	return 0;
}

const struct rdc_backend rdc_backend_drm = {
	.list = drm_list,
	.scheme = "drm",
	.open = drm_open,
	.close = drm_close,
	.reg_read = drm_reg_read,
	.reg_write = drm_reg_write,
	.vram_read = drm_vram_read,
	.vram_write = drm_vram_write,
	.submit = drm_submit,
	.wait = drm_wait,
	.step = drm_step,
	.frame_grab = drm_frame_grab,
	.pins_set = drm_pins_set,
	.pins_get = drm_pins_get,
	.pins_wait = drm_pins_wait,
	.resume_get = drm_resume_get,
};

#else /* !RDC_HAVE_DRM */

/* Known but not built: rdc_open answers RDC_E_NOSYS. */
const struct rdc_backend rdc_backend_drm = { .scheme = "drm" };

#endif /* RDC_HAVE_DRM */
