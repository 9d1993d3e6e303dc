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

#include "kchip.h"
#include "rdc_priv.h"
#include "rdcfb_ioctl.h"

/* Wall-clock slack on top of a wait's simulated budget when paced. */
#define FBDEV_WAIT_SLACK_MS 1000u

struct fbdev {
	int fd;
	uint8_t *vram;
	uint32_t vram_size;
	uint32_t core_khz;
	struct rdc_kchip_pins *gpio; /* opened on the first rdc_pins_* call */
};

static struct fbdev *fbdev_of(rdc_dev *dev)
{
	return dev->priv;
}

/*
 * ioctl() as a library error (rdcfb_ioctl.h's errnos, mapped by kchip.c);
 * a signal does not abandon the request.
 */
static int fbdev_ioctl(struct fbdev *f, unsigned long req, void *arg)
{
	int r;

	do {
		r = ioctl(f->fd, req, arg);
	} while (r < 0 && errno == EINTR);
	return r < 0 ? rdc_kchip_error(errno) : 0;
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

static void fbdev_free(struct fbdev *f)
{
	rdc_kchip_pins_free(f->gpio);
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

/*
 * No node at `path`: say whether rdcfb.ko is loaded at all, and how to
 * load it (docs/driver.md), or, loaded, that its node is another one.
 */
static int fbdev_missing(const char *path, int ret)
{
	struct stat st;

	if (stat("/sys/module/rdcfb", &st))
		return rdc_err_detail(ret,
				      "%s: %s: rdcfb.ko is not loaded (load it "
				      "with `modprobe rdcfb` from the "
				      "rdcfb-dkms package, or `insmod "
				      "build/kmod/rdcfb.ko` after `make "
				      "module`: docs/driver.md)",
				      path, strerror(ENOENT));
	return rdc_err_detail(ret,
			      "%s: %s: rdcfb.ko is loaded, its framebuffer "
			      "is another /dev/fbN (`rdcctl list` names it)",
			      path, strerror(ENOENT));
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
		int err = errno;

		ret = rdc_kchip_error(err);
		fbdev_free(f);
		if (err == ENOENT)
			return fbdev_missing(opts, ret);
		/* A missing node is a bad URI, not a bad transport. */
		ret = ret == RDC_E_IO ? RDC_E_URI : ret;
		return rdc_err_detail(ret, "%s: %s", opts, strerror(err));
	}
	ret = fbdev_probe(f);
	if (ret == RDC_E_URI) {
		fbdev_free(f);
		return rdc_err_detail(ret,
				      "%s is not rdcfb.ko's framebuffer "
				      "(`rdcctl list` names the RDC-1s "
				      "this machine has)",
				      opts);
	}
	if (ret) {
		fbdev_free(f);
		return ret;
	}
	map = mmap(NULL, f->vram_size, PROT_READ | PROT_WRITE, MAP_SHARED,
		   f->fd, 0);
	if (map == MAP_FAILED) {
		ret = rdc_kchip_error(errno);
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

static int fbdev_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	struct fbdev *f = fbdev_of(dev);

	while (n) {
		size_t k = rdc_kchip_piece(words, n, RDCFB_SUBMIT_MAX_WORDS);
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
		return errno == EAGAIN ? 1 : rdc_kchip_error(errno);
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
		ret = rdc_kchip_error(errno);
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

/* ---- Pins: the device's GPIO chip (kchip.c) ----------------------------- */

static int fbdev_pins_get(rdc_dev *dev, uint32_t *levels)
{
	struct fbdev *f = fbdev_of(dev);

	return rdc_kchip_pins_get(dev, f->fd, &f->gpio, levels);
}

static int fbdev_pins_set(rdc_dev *dev, uint32_t mask, uint32_t levels)
{
	struct fbdev *f = fbdev_of(dev);

	return rdc_kchip_pins_set(dev, f->fd, &f->gpio, mask, levels);
}

static int fbdev_pins_wait(rdc_dev *dev, uint32_t pins, uint32_t edges,
			   uint64_t budget_cycles, uint64_t timeout_us,
			   struct rdc_pin_edge *ev)
{
	struct fbdev *f = fbdev_of(dev);

	return rdc_kchip_pins_wait(dev, f->fd, &f->gpio, pins, edges,
				   budget_cycles, timeout_us, ev);
}

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

/* The chip's run beyond its registers, for a trace's start (record.c). */
static int fbdev_resume_get(rdc_dev *dev, struct rdc_hw_resume *s)
{
	struct rdc_chip_state st = { 0 };
	int ret = fbdev_ioctl(fbdev_of(dev), RDCFB_IOC_STATE, &st);

	if (ret)
		return ret;
	rdc_kchip_state_resume(&st, s);
	return 0;
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
	.resume_get = fbdev_resume_get,
};
