// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcdrm's private ioctls (rdcdrm_ioctl.h): the display processor and the
 * chip's registers, VRAM and frames, next to KMS.  They are rdcfb's
 * (rdcfb_fb.c) on the same chip host; SUBMIT is checked by the same
 * validator, and with DRM_RDC_SUBMIT_GEM draws into a dumb buffer staged
 * through VRAM.  DRM's ioctl code copies the structs in and out and
 * answers ENODEV once the device is unplugged.
 */
#include <drm/drm_drv.h>
#include <drm/drm_file.h>
#include <drm/drm_gem.h>
#include <drm/drm_ioctl.h>
#include <linux/iosys-map.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/uaccess.h>

#include "rdcdrm.h"
#include "rdcdrm_compat.h"

/* The words SUBMIT with DRM_RDC_SUBMIT_GEM puts ahead of the client's. */
#define RDCDRM_GEM_PRE_WORDS 8u

static int rdcdrm_reg_ok(u32 reg)
{
	return reg % sizeof(u32) || reg >= RDC_REG_WINDOW ? -EINVAL : 0;
}

int rdcdrm_ioctl_reg_read(struct drm_device *drm, void *data,
			  struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct drm_rdc_reg *r = data;

	if (rdcdrm_reg_ok(r->reg))
		return -EINVAL;
	r->val = rdc_kchip_reg_read(&rd->chip, r->reg);
	return 0;
}

int rdcdrm_ioctl_reg_write(struct drm_device *drm, void *data,
			   struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct drm_rdc_reg *r = data;

	if (rdcdrm_reg_ok(r->reg))
		return -EINVAL;
	rdc_kchip_reg_write(&rd->chip, r->reg, r->val);
	return 0;
}

/* The ioctl's wait as the chip host's (the same layout as rdcfb's). */
static int rdcdrm_wait(struct rdcdrm_device *rd, const struct drm_rdc_wait *dw)
{
	struct rdcfb_wait w;
	unsigned int i;

	BUILD_BUG_ON(sizeof(w) != sizeof(*dw));
	BUILD_BUG_ON(DRM_RDC_WAIT_TERMS != RDCFB_WAIT_TERMS);
	BUILD_BUG_ON(DRM_RDC_WAIT_EQ != RDCFB_WAIT_EQ);
	BUILD_BUG_ON(DRM_RDC_WAIT_NEEDS_DP != RDCFB_WAIT_NEEDS_DP);
	BUILD_BUG_ON(DRM_RDC_MAX_CYCLES != RDCFB_MAX_CYCLES);
	if (dw->budget > DRM_RDC_MAX_CYCLES)
		return -EINVAL;
	memset(&w, 0, sizeof(w));
	for (i = 0; i < DRM_RDC_WAIT_TERMS; i++) {
		w.term[i].kind = dw->term[i].kind;
		w.term[i].reg = dw->term[i].reg;
		w.term[i].mask = dw->term[i].mask;
		w.term[i].value = dw->term[i].value;
	}
	w.flags = dw->flags;
	w.timeout_ms = dw->timeout_ms;
	w.budget = dw->budget;
	return rdc_kchip_wait(&rd->chip, &w);
}

int rdcdrm_ioctl_wait(struct drm_device *drm, void *data, struct drm_file *file)
{
	return rdcdrm_wait(rdcdrm_of(drm), data);
}

int rdcdrm_ioctl_step(struct drm_device *drm, void *data, struct drm_file *file)
{
	struct drm_rdc_step *st = data;

	return rdc_kchip_step(&rdcdrm_of(drm)->chip, st->cycles);
}

int rdcdrm_ioctl_counters(struct drm_device *drm, void *data,
			  struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct drm_rdc_counters *c = data;
	struct rdc_kchip_counters kc;

	rdc_kchip_counters(&rd->chip, &kc);
	memset(c, 0, sizeof(*c));
	c->now = kc.now;
	c->busy = kc.busy;
	c->stall = kc.stall;
	c->pixels = kc.pixels;
	c->cmds = kc.cmds;
	c->last_cycles = kc.last_cycles;
	c->last_opcode = kc.last_opcode;
	c->fence = kc.fence;
	c->frames = kc.frames;
	rdc_kchip_lock(&rd->chip);
	c->flips = rd->flips;
	c->damage_cycles = rd->damage_cycles;
	rdc_kchip_unlock(&rd->chip);
	return 0;
}

/* Read-only: the chip's run beyond its registers, for a trace's start. */
int rdcdrm_ioctl_state(struct drm_device *drm, void *data,
		       struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct rdc_chip_state *st = data;

	if (st->reserved)
		return -EINVAL;
	rdc_kchip_state_get(&rd->chip, st);
	return 0;
}

int rdcdrm_ioctl_frame(struct drm_device *drm, void *data,
		       struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct rdc_kchip *chip = &rd->chip;
	struct drm_rdc_frame *f = data;
	int ret;

	mutex_lock(&chip->snap_lock);
	ret = rdc_kchip_snapshot(chip);
	if (ret) {
		f->seq = 0;
		f->width = 0;
		f->height = 0;
		f->crc32 = 0;
	} else {
		f->seq = chip->snap_seq;
		f->width = chip->snap_w;
		f->height = chip->snap_h;
		f->crc32 = chip->snap_crc;
		if (f->pixels && f->cap < (u64)f->width * f->height)
			ret = -E2BIG;
		else if (f->pixels &&
			 copy_to_user(u64_to_user_ptr(f->pixels), chip->snap,
				      (size_t)f->width * f->height *
					      sizeof(u32)))
			ret = -EFAULT;
	}
	mutex_unlock(&chip->snap_lock);
	/* DRM copies the struct out on errors too: seq 0 with EAGAIN */
	return ret;
}

int rdcdrm_ioctl_vram(struct drm_device *drm, void *data, struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct rdc_kchip *chip = &rd->chip;
	struct drm_rdc_vram *v = data;
	void __user *up = u64_to_user_ptr(v->data);
	void *buf;
	int ret = 0;

	if ((v->flags & ~DRM_RDC_VRAM_WRITE) || v->reserved)
		return -EINVAL;
	if (v->len > DRM_RDC_VRAM_MAX_BYTES)
		return -E2BIG;
	if ((u64)v->addr + v->len > rdc_hw_vram_size(chip->hw))
		return -EINVAL;
	if (!v->len)
		return 0;
	buf = kvmalloc(v->len, GFP_KERNEL);
	if (!buf)
		return -ENOMEM;
	if (v->flags & DRM_RDC_VRAM_WRITE) {
		if (copy_from_user(buf, up, v->len)) {
			ret = -EFAULT;
			goto out;
		}
		rdc_kchip_lock(chip);
		rdc_hw_vram_write(chip->hw, v->addr, buf, v->len);
		chip->state_gen++;
		rdc_kchip_unlock(chip);
	} else {
		rdc_kchip_lock(chip);
		rdc_hw_vram_read(chip->hw, v->addr, buf, v->len);
		rdc_kchip_unlock(chip);
		if (copy_to_user(up, buf, v->len))
			ret = -EFAULT;
	}
out:
	kvfree(buf);
	return ret;
}

/*
 * SUBMIT with DRM_RDC_SUBMIT_GEM: the buffer's rows go to the staging
 * area of VRAM, the DP draws there with the client's commands behind a
 * DST and clip of the buffer, and the rows come back, all through the
 * chip's host aperture and the DP, so their cycles are charged.
 */
static int rdcdrm_submit_gem(struct rdcdrm_device *rd, struct drm_file *file,
			     const struct drm_rdc_submit *s, u32 *words)
{
	struct rdc_kchip *chip = &rd->chip;
	struct drm_rdc_wait idle = {
		.term[0] = { .kind = DRM_RDC_WAIT_EQ,
			     .reg = RDC_REG_STATUS,
			     .mask = RDC_STATUS_DP_BUSY | RDC_STATUS_FIFO_EMPTY,
			     .value = RDC_STATUS_FIFO_EMPTY },
		.flags = DRM_RDC_WAIT_NEEDS_DP,
	};
	u32 fmt = rdcdrm_format_of(s->format), row, stride, y;
	struct drm_gem_object *obj;
	struct iosys_map map;
	u64 bytes;
	u8 *px;
	int ret;

	if (fmt == RDC_FMT_COUNT || !s->width || !s->height ||
	    s->width > RDC_SIZE_MAX || s->height > RDC_SIZE_MAX)
		return -EINVAL;
	row = rdc_format_row_bytes(fmt, s->width);
	if (s->pitch < row)
		return -EINVAL;
	stride = ALIGN(row, sizeof(u32));
	bytes = (u64)stride * s->height;
	if (bytes > rdc_hw_vram_size(chip->hw) - RDCDRM_STAGING_BASE)
		return -ENOSPC;
	obj = drm_gem_object_lookup(file, s->handle);
	if (!obj)
		return -ENOENT;
	if ((u64)s->pitch * (s->height - 1) + row > obj->size) {
		ret = -EINVAL;
		goto out_put;
	}
	ret = rdcdrm_gem_vmap(obj, &map);
	if (ret)
		goto out_put;
	px = map.vaddr;

	words[0] = RDC_CMD(RDC_OP_SET_DST, 0, 4);
	words[1] = RDCDRM_STAGING_BASE;
	words[2] = stride;
	words[3] = RDC_WH(s->width, s->height);
	words[4] = fmt;
	words[5] = RDC_CMD(RDC_OP_SET_CLIP, 0, 2);
	words[6] = RDC_XY(0, 0);
	words[7] = RDC_WH(s->width, s->height);
	rdc_kchip_lock(chip);
	for (y = 0; y < s->height; y++)
		rdc_hw_vram_write(chip->hw, RDCDRM_STAGING_BASE + y * stride,
				  px + (size_t)y * s->pitch, row);
	rdc_kchip_unlock(chip);
	ret = rdc_kchip_submit(chip, words, RDCDRM_GEM_PRE_WORDS + s->count);
	if (!ret)
		ret = rdcdrm_wait(rd, &idle);
	if (!ret) {
		rdc_kchip_lock(chip);
		for (y = 0; y < s->height; y++)
			rdc_hw_vram_read(chip->hw,
					 RDCDRM_STAGING_BASE + y * stride,
					 px + (size_t)y * s->pitch, row);
		rdc_kchip_unlock(chip);
	}
	rdcdrm_gem_vunmap(obj, &map);
out_put:
	drm_gem_object_put(obj);
	return ret;
}

int rdcdrm_ioctl_submit(struct drm_device *drm, void *data,
			struct drm_file *file)
{
	struct rdcdrm_device *rd = rdcdrm_of(drm);
	struct rdc_kchip *chip = &rd->chip;
	struct drm_rdc_submit *s = data;
	bool gem = s->flags & DRM_RDC_SUBMIT_GEM;
	u32 pre = gem ? RDCDRM_GEM_PRE_WORDS : 0;
	u32 *words;
	int ret;

	if ((s->flags & ~DRM_RDC_SUBMIT_GEM) || s->reserved[0] ||
	    s->reserved[1])
		return -EINVAL;
	if (s->count > DRM_RDC_SUBMIT_MAX_WORDS)
		return -E2BIG;
	if (!s->count && !gem)
		return 0;
	words = kvmalloc_array(pre + s->count, sizeof(u32), GFP_KERNEL);
	if (!words)
		return -ENOMEM;
	if (copy_from_user(words + pre, u64_to_user_ptr(s->words),
			   (size_t)s->count * sizeof(u32))) {
		ret = -EFAULT;
		goto out;
	}
	ret = rdcfb_validate(words + pre, s->count, rdc_hw_vram_size(chip->hw),
			     &s->bad_word);
	if (ret) {
		drm_dbg(drm, "submit refused at word %u of %u\n", s->bad_word,
			s->count);
		goto out;
	}
	if (gem)
		ret = rdcdrm_submit_gem(rd, file, s, words);
	else
		ret = rdc_kchip_submit(chip, words, s->count);
out:
	kvfree(words);
	return ret;
}
