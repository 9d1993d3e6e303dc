// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * rdcfb's private ioctls (rdcfb_ioctl.h, shared with user space) and
 * FBIO_WAITFORVSYNC: register access, SUBMIT (checked by
 * rdcfb_validate.c before anything is queued), WAIT, STEP, COUNTERS,
 * FRAME and STATE, each a call of the kernel chip host (rdc_kchip.c).
 */
#include <linux/compat.h>
#include <linux/fb.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/uaccess.h>

#include "rdcfb.h"

static int rdcfb_ioc_reg(struct rdc_kchip *chip, unsigned int cmd,
			 void __user *arg)
{
	struct rdcfb_reg r;

	if (copy_from_user(&r, arg, sizeof(r)))
		return -EFAULT;
	if (r.reg % sizeof(u32) || r.reg >= RDC_REG_WINDOW)
		return -EINVAL;
	if (cmd == RDCFB_IOC_REG_WRITE) {
		rdc_kchip_reg_write(chip, r.reg, r.val);
		return 0;
	}
	r.val = rdc_kchip_reg_read(chip, r.reg);
	return copy_to_user(arg, &r, sizeof(r)) ? -EFAULT : 0;
}

static int rdcfb_ioc_submit(struct rdc_kchip *chip, void __user *arg)
{
	struct rdcfb_submit s;
	u32 *words;
	int ret;

	if (copy_from_user(&s, arg, sizeof(s)))
		return -EFAULT;
	if (s.flags || s.reserved)
		return -EINVAL;
	if (s.count > RDCFB_SUBMIT_MAX_WORDS)
		return -E2BIG;
	if (!s.count)
		return 0;
	words = kvmalloc_array(s.count, sizeof(u32), GFP_KERNEL);
	if (!words)
		return -ENOMEM;
	if (copy_from_user(words, u64_to_user_ptr(s.words),
			   (size_t)s.count * sizeof(u32))) {
		ret = -EFAULT;
		goto out;
	}
	ret = rdcfb_validate(words, s.count, rdc_hw_vram_size(chip->hw),
			     &s.bad_word);
	if (ret) {
		dev_dbg(chip->dev, "submit refused at word %u of %u\n",
			s.bad_word, s.count);
		if (copy_to_user(arg, &s, sizeof(s)))
			ret = -EFAULT;
		goto out;
	}
	ret = rdc_kchip_submit(chip, words, s.count);
out:
	kvfree(words);
	return ret;
}

static int rdcfb_ioc_frame(struct rdc_kchip *chip, void __user *arg)
{
	struct rdcfb_frame f;
	size_t bytes;
	int ret;

	if (copy_from_user(&f, arg, sizeof(f)))
		return -EFAULT;
	if (f.reserved)
		return -EINVAL;
	mutex_lock(&chip->snap_lock);
	ret = rdc_kchip_snapshot(chip);
	if (ret) {
		f.seq = 0;
		f.width = 0;
		f.height = 0;
		f.crc32 = 0;
	} else {
		f.seq = (u32)chip->snap_seq;
		f.width = chip->snap_w;
		f.height = chip->snap_h;
		f.crc32 = chip->snap_crc;
		bytes = (size_t)f.width * f.height * sizeof(u32);
		if (f.pixels && f.cap < (u64)f.width * f.height)
			ret = -E2BIG;
		else if (f.pixels && copy_to_user(u64_to_user_ptr(f.pixels),
						  chip->snap, bytes))
			ret = -EFAULT;
	}
	mutex_unlock(&chip->snap_lock);
	if (copy_to_user(arg, &f, sizeof(f)))
		return -EFAULT;
	return ret;
}

/* Read-only: the chip's run beyond its registers, for a trace's start. */
static int rdcfb_ioc_state(struct rdc_kchip *chip, void __user *arg)
{
	struct rdc_chip_state st;

	if (copy_from_user(&st, arg, sizeof(st)))
		return -EFAULT;
	if (st.reserved)
		return -EINVAL;
	rdc_kchip_state_get(chip, &st);
	return copy_to_user(arg, &st, sizeof(st)) ? -EFAULT : 0;
}

int rdcfb_ioctl(struct fb_info *info, unsigned int cmd, unsigned long arg)
{
	struct rdcfb_par *par = info->par;
	struct rdc_kchip *chip = par->chip;
	void __user *argp = (void __user *)arg;
	struct rdc_kchip_counters kc;
	struct rdcfb_counters c;
	struct rdcfb_wait w;
	struct rdcfb_step st;
	u32 crtc;

	if (READ_ONCE(chip->dying))
		return -ENODEV;
	switch (cmd) {
	case FBIO_WAITFORVSYNC:
		if (get_user(crtc, (u32 __user *)argp))
			return -EFAULT;
		return crtc ? -ENODEV : rdc_kchip_vsync(chip);
	case RDCFB_IOC_REG_READ:
	case RDCFB_IOC_REG_WRITE:
		return rdcfb_ioc_reg(chip, cmd, argp);
	case RDCFB_IOC_SUBMIT:
		return rdcfb_ioc_submit(chip, argp);
	case RDCFB_IOC_WAIT:
		if (copy_from_user(&w, argp, sizeof(w)))
			return -EFAULT;
		/* the driver's own waits (vsync, SUBMIT) are not capped */
		if (w.budget > RDCFB_MAX_CYCLES)
			return -EINVAL;
		return rdc_kchip_wait(chip, &w);
	case RDCFB_IOC_STEP:
		if (copy_from_user(&st, argp, sizeof(st)))
			return -EFAULT;
		return rdc_kchip_step(chip, st.cycles);
	case RDCFB_IOC_COUNTERS:
		rdc_kchip_counters(chip, &kc);
		c = (struct rdcfb_counters){
			.now = kc.now,
			.busy = kc.busy,
			.stall = kc.stall,
			.pixels = kc.pixels,
			.cmds = kc.cmds,
			.last_cycles = kc.last_cycles,
			.last_opcode = kc.last_opcode,
			.fence = kc.fence,
			.frames = (u32)kc.frames,
		};
		return copy_to_user(argp, &c, sizeof(c)) ? -EFAULT : 0;
	case RDCFB_IOC_FRAME:
		return rdcfb_ioc_frame(chip, argp);
	case RDCFB_IOC_STATE:
		return rdcfb_ioc_state(chip, argp);
	default:
		return -ENOTTY;
	}
}

#ifdef CONFIG_COMPAT
/* The structs are the same for 32-bit callers; their pointers are not. */
int rdcfb_compat_ioctl(struct fb_info *info, unsigned int cmd,
		       unsigned long arg)
{
	return rdcfb_ioctl(info, cmd, (unsigned long)compat_ptr(arg));
}
#endif
