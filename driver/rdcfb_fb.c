// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * fb_ops on the simulated RDC-1: modes program the CRTC, the palette is
 * the CLUT, pan writes the latched base, blank drives the scanout enable,
 * and fbcon's fillrect, copyarea and imageblit become display-processor
 * commands (FILL_RECT, BLIT, MONO / HOST_BLIT), so the console is drawn by
 * the DP and its cycles are counted.  fbcon may call them in atomic
 * context, so they queue their work for the chip (the fb-op queue, below).
 * The private ioctls of rdcfb_ioctl.h live here too.
 */
#include <linux/compat.h>
#include <linux/fb.h>
#include <linux/minmax.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/vmalloc.h>

#include "rdcfb.h"

#define RDCFB_PS_PER_KHZ 1000000000u /* picoseconds times kHz */
/* A var's pixel clock within this many per mille of a preset's is it. */
#define RDCFB_PIXCLK_SLACK_PERMILLE 5u
/* Command words staged on the stack before they go to the FIFO. */
#define RDCFB_STAGE_WORDS 32u
/* The argument words ahead of the data: HOST_BLIT's; MONO's, colours carried */
#define RDCFB_DATA_ARGS rdc_cmd_data_at(RDC_OP_HOST_BLIT, 0)
#define RDCFB_MONO_ARGS rdc_cmd_data_at(RDC_OP_MONO, RDC_MONO_COLORS)

static u32 rdcfb_fmt_of(const struct fb_var_screeninfo *var)
{
	if (var->bits_per_pixel <= 8)
		return RDC_FMT_I8;
	if (var->bits_per_pixel <= 16)
		return RDC_FMT_RGB565;
	return RDC_FMT_XRGB8888;
}

static u32 rdcfb_stride(u32 fmt, u32 width)
{
	return ALIGN(rdc_format_row_bytes(fmt, width), sizeof(u32));
}

static void rdcfb_set_bitfields(struct fb_var_screeninfo *var, u32 fmt)
{
	static const struct fb_bitfield none = { 0 };

	var->transp = none;
	var->grayscale = 0;
	var->nonstd = 0;
	switch (fmt) {
	case RDC_FMT_I8:
		var->bits_per_pixel = 8;
		var->red = (struct fb_bitfield){ 0, 8, 0 };
		var->green = var->red;
		var->blue = var->red;
		break;
	case RDC_FMT_RGB565:
		var->bits_per_pixel = 16;
		var->red = (struct fb_bitfield){ 11, 5, 0 };
		var->green = (struct fb_bitfield){ 5, 6, 0 };
		var->blue = (struct fb_bitfield){ 0, 5, 0 };
		break;
	default:
		var->bits_per_pixel = 32;
		var->red = (struct fb_bitfield){ 16, 8, 0 };
		var->green = (struct fb_bitfield){ 8, 8, 0 };
		var->blue = (struct fb_bitfield){ 0, 8, 0 };
		break;
	}
}

static void rdcfb_timing_to_var(const struct rdc_timing *t,
				struct fb_var_screeninfo *var)
{
	var->xres = t->h_display;
	var->yres = t->v_display;
	var->pixclock = DIV_ROUND_CLOSEST(RDCFB_PS_PER_KHZ, t->pixclk_khz);
	var->right_margin = t->h_sync_start - t->h_display;
	var->hsync_len = t->h_sync_end - t->h_sync_start;
	var->left_margin = t->h_total - t->h_sync_end;
	var->lower_margin = t->v_sync_start - t->v_display;
	var->vsync_len = t->v_sync_end - t->v_sync_start;
	var->upper_margin = t->v_total - t->v_sync_end;
	var->sync = 0;
	if (t->flags & RDC_CRTC_HSYNC_POS)
		var->sync |= FB_SYNC_HOR_HIGH_ACT;
	if (t->flags & RDC_CRTC_VSYNC_POS)
		var->sync |= FB_SYNC_VERT_HIGH_ACT;
	var->vmode = FB_VMODE_NONINTERLACED;
}

/* The preset of this size, 0, or -ENOENT. */
static int rdcfb_preset_of(u32 xres, u32 yres, struct rdc_timing *t)
{
	u32 p;

	for (p = 0; p < RDC_PRESET_COUNT; p++)
		if (!rdc_preset_timing(p, t) && t->h_display == xres &&
		    t->v_display == yres)
			return 0;
	return -ENOENT;
}

/*
 * The CRTC timing a var asks for: its own (pixclock, margins, sync
 * lengths) when it gives a pixel clock, else the preset of its size.  The
 * checks are the chip's (hw.h: timing validation at latch), so a mode
 * check_var accepts is never refused at the latch.
 */
static int rdcfb_var_timing(const struct fb_var_screeninfo *var,
			    struct rdc_timing *t)
{
	struct rdc_timing p;
	u64 h[4], v[4];
	u32 khz;

	if (!var->pixclock)
		return rdcfb_preset_of(var->xres, var->yres, t) ? -EINVAL : 0;
	khz = DIV_ROUND_CLOSEST(RDCFB_PS_PER_KHZ, var->pixclock);
	h[0] = var->xres;
	h[1] = h[0] + var->right_margin;
	h[2] = h[1] + var->hsync_len;
	h[3] = h[2] + var->left_margin;
	v[0] = var->yres;
	v[1] = v[0] + var->lower_margin;
	v[2] = v[1] + var->vsync_len;
	v[3] = v[2] + var->upper_margin;
	if (!h[0] || !v[0] || h[0] > RDC_CRTC_MAX_DISPLAY ||
	    v[0] > RDC_CRTC_MAX_DISPLAY || h[3] > RDC_CRTC_MAX_TOTAL ||
	    v[3] > RDC_CRTC_MAX_TOTAL || v[0] >= v[3] ||
	    khz < RDC_PIXCLK_MIN_KHZ || khz > RDC_PIXCLK_MAX_KHZ ||
	    h[0] * v[0] > RDC_KCHIP_FRAME_CAP)
		return -EINVAL;
	/* a line must last at least one core cycle */
	if (h[3] * RDC_DEFAULT_CORE_HZ < (u64)khz * 1000)
		return -EINVAL;
	*t = (struct rdc_timing){
		.h_display = h[0],
		.h_sync_start = h[1],
		.h_sync_end = h[2],
		.h_total = h[3],
		.v_display = v[0],
		.v_sync_start = v[1],
		.v_sync_end = v[2],
		.v_total = v[3],
		.pixclk_khz = khz,
	};
	if (var->sync & FB_SYNC_HOR_HIGH_ACT)
		t->flags |= RDC_CRTC_HSYNC_POS;
	if (var->sync & FB_SYNC_VERT_HIGH_ACT)
		t->flags |= RDC_CRTC_VSYNC_POS;
	/* picoseconds lose the preset's exact kHz: give it back */
	if (!rdcfb_preset_of(t->h_display, t->v_display, &p) &&
	    p.h_total == t->h_total && p.v_total == t->v_total &&
	    p.h_sync_start == t->h_sync_start &&
	    p.h_sync_end == t->h_sync_end &&
	    p.v_sync_start == t->v_sync_start &&
	    p.v_sync_end == t->v_sync_end &&
	    abs((int)p.pixclk_khz - (int)khz) * 1000 <=
		    (int)(p.pixclk_khz * RDCFB_PIXCLK_SLACK_PERMILLE))
		t->pixclk_khz = p.pixclk_khz;
	return 0;
}

static int rdcfb_check_var(struct fb_var_screeninfo *var, struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	u32 vram = rdc_hw_vram_size(par->chip->hw), fmt, stride;
	struct rdc_timing t;

	if ((var->vmode & FB_VMODE_MASK) != FB_VMODE_NONINTERLACED ||
	    var->bits_per_pixel > 32)
		return -EINVAL;
	if (rdcfb_var_timing(var, &t))
		return -EINVAL;
	fmt = rdcfb_fmt_of(var);
	var->xres_virtual = max(var->xres_virtual, var->xres);
	var->yres_virtual = max(var->yres_virtual, var->yres);
	if (var->xres_virtual > RDC_SIZE_MAX)
		return -EINVAL;
	stride = rdcfb_stride(fmt, var->xres_virtual);
	if ((u64)stride * var->yres > vram)
		return -ENOMEM;
	/* a taller virtual screen than VRAM (or the DP) holds shrinks */
	var->yres_virtual =
		min3(var->yres_virtual, vram / stride, (u32)RDC_SIZE_MAX);
	if (var->xoffset > var->xres_virtual - var->xres ||
	    var->yoffset > var->yres_virtual - var->yres)
		return -EINVAL;
	rdcfb_set_bitfields(var, fmt);
	var->vmode = FB_VMODE_NONINTERLACED;
	var->height = -1;
	var->width = -1;
	var->accel_flags = 0;
	rdcfb_timing_to_var(&t, var);
	return 0;
}

static u32 rdcfb_base(const struct rdcfb_par *par,
		      const struct fb_var_screeninfo *var)
{
	return var->yoffset * par->stride +
	       rdc_format_row_bytes(par->fmt, var->xoffset);
}

/* ---- The fb-op queue ----------------------------------------------------- */

/*
 * fbcon calls fb_ops in atomic context too: kernel messages are printed
 * with interrupts off, an oops may print from an interrupt, and the
 * console is unblanked from there.  So no fb_op takes chip->lock (a mutex)
 * or runs the chip itself.  Each puts a record on the queue under
 * opq.lock (held for one record: a header and at most one DP command's
 * data) and the records are applied in order under chip->lock: at once
 * where the caller may sleep (preemptible(): a tty write, an ioctl), else
 * by the queue's worker or whoever takes the chip next.  A record keeps
 * what the op meant when it came: colours looked up, image rows packed,
 * the screen's format and size.  A full queue is applied first where the
 * caller may sleep; in atomic context the record is dropped and counted
 * (fb_dropped in sysfs).
 */
/* An image record holds about this many data words, one row at least. */
#define RDCFB_OP_BAND_WORDS 512u

/* A record being written: opq.lock is held from begin to end. */
struct rdcfb_qw {
	struct rdc_kchip *chip;
	unsigned long flags;
	u32 start, tail; /* ring positions of its header, of the next word */
	u32 acc;	 /* a data word being filled bits at a time */
	u32 acc_bits;
};

static void rdcfb_q_put(struct rdcfb_qw *q, u32 word)
{
	rdcfb_dev_of(q->chip)->opq.ring[q->tail++ % RDCFB_OPQ_WORDS] = word;
}

/* Data bits go into words little-endian (byte 0 in bits 7:0). */
static void rdcfb_q_put_bits(struct rdcfb_qw *q, u32 v, u32 bits)
{
	q->acc |= v << q->acc_bits;
	q->acc_bits += bits;
	if (q->acc_bits == RDCFB_BITS_PER_WORD) {
		rdcfb_q_put(q, q->acc);
		q->acc = 0;
		q->acc_bits = 0;
	}
}

/* End a data row: it is padded to a word. */
static void rdcfb_q_end_row(struct rdcfb_qw *q)
{
	if (q->acc_bits)
		rdcfb_q_put(q, q->acc);
	q->acc = 0;
	q->acc_bits = 0;
}

/* Take the chip, which applies the queue, where the caller may sleep. */
static void rdcfb_q_apply(struct rdc_kchip *chip)
{
	rdc_kchip_lock(chip);
	rdc_kchip_unlock(chip);
}

/*
 * Start a record (true, opq.lock held until rdcfb_q_end), or drop it
 * (false) when the queue has no room for it and the caller cannot wait.
 */
static bool rdcfb_q_begin(struct rdc_kchip *chip, struct rdcfb_qw *q,
			  const struct rdcfb_op *op)
{
	struct rdcfb_opq *oq = &rdcfb_dev_of(chip)->opq;
	u32 need = RDCFB_OP_HDR_WORDS + op->words;
	const u32 *hdr = (const u32 *)op;
	bool can_wait = preemptible(); /* asked before the lock is taken */
	u32 i;

	BUILD_BUG_ON(sizeof(*op) != RDCFB_OP_HDR_WORDS * sizeof(u32));
	q->chip = chip;
	q->acc = 0;
	q->acc_bits = 0;
	if (WARN_ON_ONCE(op->words > RDC_CMD_MAX_ARGS))
		return false;
	rdc_kchip_spin_lock(&oq->lock, q->flags, oq->t0);
	if (RDCFB_OPQ_WORDS - oq->count < need && can_wait) {
		rdc_kchip_spin_unlock(&oq->lock, q->flags, oq->t0,
				      &chip->irqoff);
		rdcfb_q_apply(chip);
		rdc_kchip_spin_lock(&oq->lock, q->flags, oq->t0);
	}
	if (RDCFB_OPQ_WORDS - oq->count < need) {
		oq->dropped++;
		rdc_kchip_spin_unlock(&oq->lock, q->flags, oq->t0,
				      &chip->irqoff);
		return false;
	}
	q->start = oq->head + oq->count;
	q->tail = q->start;
	for (i = 0; i < RDCFB_OP_HDR_WORDS; i++)
		rdcfb_q_put(q, hdr[i]);
	return true;
}

/* Commit the record, then see that it is applied. */
static void rdcfb_q_end(struct rdcfb_qw *q)
{
	struct rdc_kchip *chip = q->chip;
	struct rdcfb_opq *oq = &rdcfb_dev_of(chip)->opq;

	rdcfb_q_end_row(q);
	/* the header says how many data words there really are */
	oq->ring[(q->start + 1) % RDCFB_OPQ_WORDS] =
		q->tail - q->start - RDCFB_OP_HDR_WORDS;
	oq->count = q->tail - oq->head;
	rdc_kchip_spin_unlock(&oq->lock, q->flags, oq->t0, &chip->irqoff);
	if (preemptible())
		rdcfb_q_apply(chip);
	else
		queue_work(system_highpri_wq, &oq->work);
}

/* A record with nothing but a header. */
static void rdcfb_q_op(struct rdc_kchip *chip, const struct rdcfb_op *op)
{
	struct rdcfb_qw q;

	if (rdcfb_q_begin(chip, &q, op))
		rdcfb_q_end(&q);
}

/* Register writes, in order: `n` pairs of register and value. */
static void rdcfb_q_regs(struct rdc_kchip *chip, const u32 *pairs, u32 n)
{
	struct rdcfb_op op = { .kind = RDCFB_OPK_REGS, .words = 2 * n };
	struct rdcfb_qw q;
	u32 i;

	if (!rdcfb_q_begin(chip, &q, &op))
		return;
	for (i = 0; i < 2 * n; i++)
		rdcfb_q_put(&q, pairs[i]);
	rdcfb_q_end(&q);
}

u64 rdcfb_ops_dropped(struct rdc_kchip *chip)
{
	struct rdcfb_opq *oq = &rdcfb_dev_of(chip)->opq;
	unsigned long flags;
	u64 n;

	rdc_kchip_spin_lock(&oq->lock, flags, oq->t0);
	n = oq->dropped;
	rdc_kchip_spin_unlock(&oq->lock, flags, oq->t0, &chip->irqoff);
	return n;
}

/* ---- fb_ops: the mode, the palette, panning and blanking ------------- */

static int rdcfb_set_par(struct fb_info *info)
{
	static const u32 timing_regs[] = {
		RDC_REG_H_TOTAL,      RDC_REG_H_DISPLAY,  RDC_REG_H_SYNC_START,
		RDC_REG_H_SYNC_END,   RDC_REG_V_TOTAL,	  RDC_REG_V_DISPLAY,
		RDC_REG_V_SYNC_START, RDC_REG_V_SYNC_END, RDC_REG_PIXCLK_KHZ,
		RDC_REG_CRTC_FLAGS,
	};
	struct rdcfb_par *par = info->par;
	struct rdc_kchip *chip = par->chip;
	struct rdc_timing t;
	u32 regs[2 * (3 + ARRAY_SIZE(timing_regs))], *r = regs;
	u32 val[ARRAY_SIZE(timing_regs)];
	unsigned int i;

	if (rdcfb_var_timing(&info->var, &t))
		return -EINVAL;
	par->fmt = rdcfb_fmt_of(&info->var);
	par->stride = rdcfb_stride(par->fmt, info->var.xres_virtual);
	info->fix.line_length = par->stride;
	info->fix.visual = par->fmt == RDC_FMT_I8 ? FB_VISUAL_PSEUDOCOLOR :
						    FB_VISUAL_TRUECOLOR;
	val[0] = t.h_total;
	val[1] = t.h_display;
	val[2] = t.h_sync_start;
	val[3] = t.h_sync_end;
	val[4] = t.v_total;
	val[5] = t.v_display;
	val[6] = t.v_sync_start;
	val[7] = t.v_sync_end;
	val[8] = t.pixclk_khz;
	val[9] = t.flags;

	*r++ = RDC_REG_FB_FORMAT;
	*r++ = par->fmt;
	*r++ = RDC_REG_FB_STRIDE;
	*r++ = par->stride;
	*r++ = RDC_REG_FB_BASE;
	*r++ = rdcfb_base(par, &info->var);
	for (i = 0; i < ARRAY_SIZE(timing_regs); i++) {
		*r++ = timing_regs[i];
		*r++ = val[i];
	}
	rdcfb_q_regs(chip, regs, ARRAY_SIZE(regs) / 2);
	dev_dbg(chip->dev, "mode %ux%u (%ux%u virtual) format %u stride %u\n",
		t.h_display, t.v_display, info->var.xres_virtual,
		info->var.yres_virtual, par->fmt, par->stride);
	return 0;
}

static u32 rdcfb_pack(u32 fmt, u32 r, u32 g, u32 b)
{
	if (fmt == RDC_FMT_RGB565)
		return (r >> 11) << 11 | (g >> 10) << 5 | b >> 11;
	return (r >> 8) << 16 | (g >> 8) << 8 | b >> 8;
}

static int rdcfb_setcolreg(unsigned int regno, unsigned int red,
			   unsigned int green, unsigned int blue,
			   unsigned int transp, struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	u32 regs[] = { RDC_REG_CLUT_INDEX, regno, RDC_REG_CLUT_DATA,
		       rdcfb_pack(RDC_FMT_XRGB8888, red, green, blue) };

	if (regno >= RDC_CLUT_ENTRIES)
		return -EINVAL;
	if (info->fix.visual == FB_VISUAL_PSEUDOCOLOR) {
		rdcfb_q_regs(par->chip, regs, ARRAY_SIZE(regs) / 2);
	} else if (regno < RDCFB_PSEUDO_COLOURS) {
		par->pseudo_palette[regno] =
			rdcfb_pack(par->fmt, red, green, blue);
	}
	return 0;
}

/* The whole map in one record: one CLUT_INDEX write, then the data. */
static int rdcfb_setcmap(struct fb_cmap *cmap, struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_op op = { .kind = RDCFB_OPK_REGS };
	struct rdcfb_qw q;
	u32 i;

	if (cmap->start >= RDC_CLUT_ENTRIES ||
	    cmap->len > RDC_CLUT_ENTRIES - cmap->start)
		return -EINVAL;
	if (info->fix.visual != FB_VISUAL_PSEUDOCOLOR) {
		for (i = 0; i < cmap->len; i++)
			rdcfb_setcolreg(cmap->start + i, cmap->red[i],
					cmap->green[i], cmap->blue[i], 0, info);
		return 0;
	}
	op.words = 2 * (1 + cmap->len);
	if (!rdcfb_q_begin(par->chip, &q, &op))
		return 0;
	rdcfb_q_put(&q, RDC_REG_CLUT_INDEX);
	rdcfb_q_put(&q, cmap->start);
	for (i = 0; i < cmap->len; i++) {
		rdcfb_q_put(&q, RDC_REG_CLUT_DATA);
		rdcfb_q_put(&q, rdcfb_pack(RDC_FMT_XRGB8888, cmap->red[i],
					   cmap->green[i], cmap->blue[i]));
	}
	rdcfb_q_end(&q);
	return 0;
}

static int rdcfb_pan_display(struct fb_var_screeninfo *var,
			     struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	u32 regs[] = { RDC_REG_FB_BASE, rdcfb_base(par, var) };

	if (var->xoffset > info->var.xres_virtual - info->var.xres ||
	    var->yoffset > info->var.yres_virtual - info->var.yres)
		return -EINVAL;
	rdcfb_q_regs(par->chip, regs, ARRAY_SIZE(regs) / 2);
	return 0;
}

/* Unblank sets SCANOUT_EN and drives BL_EN high; the rest clear both. */
static int rdcfb_blank(int blank, struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_op op = { .kind = RDCFB_OPK_BLANK, .arg = blank };

	rdcfb_q_op(par->chip, &op);
	return 0;
}

/*
 * An open by user space is a frame consumer (scanout on demand converts
 * frames while one is open): it may read frames, and it may write VRAM
 * through read/write or a mapping (which holds the file open) with no
 * barrier.  fbcon's opens are not: its drawing goes through fb_ops.
 */
static int rdcfb_open(struct fb_info *info, int user)
{
	struct rdcfb_par *par = info->par;

	if (user)
		rdc_kchip_consumer(par->chip, true);
	return 0;
}

static int rdcfb_release(struct fb_info *info, int user)
{
	struct rdcfb_par *par = info->par;

	if (user)
		rdc_kchip_consumer(par->chip, false);
	return 0;
}

static int rdcfb_mmap(struct fb_info *info, struct vm_area_struct *vma)
{
	struct rdcfb_par *par = info->par;

	return remap_vmalloc_range(vma, par->chip->vram, vma->vm_pgoff);
}

/* ---- Drawing: records to DP commands ------------------------------------- */

/* Command words on their way to the FIFO, staged a few at a time. */
struct rdcfb_stage {
	struct rdc_kchip *chip;
	u32 w[RDCFB_STAGE_WORDS];
	u32 n;
	int err;
};

static void rdcfb_flush(struct rdcfb_stage *s)
{
	if (s->n && !s->err)
		s->err = rdc_kchip_push_locked(s->chip, s->w, s->n);
	s->n = 0;
}

static void rdcfb_put(struct rdcfb_stage *s, u32 word)
{
	if (s->n == RDCFB_STAGE_WORDS)
		rdcfb_flush(s);
	s->w[s->n++] = word;
}

/*
 * The DP state fb_ops rely on is set again whenever a client may have
 * changed it, or the screen changed: the op's screen as DST and SRC, a
 * clip of all of it, and no pattern, transform, alpha or colour key.
 */
static void rdcfb_begin(struct rdcfb_par *par, const struct rdcfb_op *op,
			struct rdcfb_stage *s)
{
	struct rdc_kchip *chip = par->chip;
	u32 wh = RDC_WH(op->vw, op->vh);
	int k;

	s->chip = chip;
	s->n = 0;
	s->err = 0;
	if (par->state_valid && par->state_gen == chip->state_gen &&
	    par->dp_fmt == op->fmt && par->dp_stride == op->stride &&
	    par->dp_wh == wh)
		return;
	for (k = 0; k < 2; k++) {
		rdcfb_put(s,
			  RDC_CMD(k ? RDC_OP_SET_SRC : RDC_OP_SET_DST, 0, 4));
		rdcfb_put(s, 0);
		rdcfb_put(s, op->stride);
		rdcfb_put(s, wh);
		rdcfb_put(s, op->fmt);
	}
	rdcfb_put(s, RDC_CMD(RDC_OP_SET_CLIP, 0, 2));
	rdcfb_put(s, RDC_XY(0, 0));
	rdcfb_put(s, wh);
	rdcfb_put(s, RDC_CMD(RDC_OP_SET_PATTERN, RDC_PAT_NONE, 0));
	rdcfb_put(s, RDC_CMD(RDC_OP_SET_TRANSFORM, 0, 0));
	rdcfb_put(s, RDC_CMD(RDC_OP_SET_ALPHA, 0, 1));
	rdcfb_put(s, RDC_ALPHA_OPAQUE);
	rdcfb_put(s, RDC_CMD(RDC_OP_SET_COLORKEY, 0, 1));
	rdcfb_put(s, 0);
	par->state_valid = true;
	par->state_gen = chip->state_gen;
	par->dp_fmt = op->fmt;
	par->dp_stride = op->stride;
	par->dp_wh = wh;
}

static void rdcfb_end(struct rdcfb_par *par, struct rdcfb_stage *s)
{
	rdcfb_flush(s);
	if (s->err) {
		/* a command may be cut short: set everything again next time */
		par->state_valid = false;
		dev_dbg(par->chip->dev, "fb op dropped: %d\n", s->err);
	}
}

static void rdcfb_dp_draw(struct rdcfb_par *par, const struct rdcfb_op *op,
			  const u32 *data)
{
	struct rdcfb_stage s;

	rdcfb_begin(par, op, &s);
	rdcfb_put(&s, RDC_CMD(RDC_OP_SET_ROP, 0, 1));
	rdcfb_put(&s, op->rop);
	switch (op->kind) {
	case RDCFB_OPK_FILL:
		/* the colour carried in the fill, as fb_fillrect carries it */
		rdcfb_put(&s, RDC_CMD(RDC_OP_FILL_RECT, RDC_DRAW_FG, 3));
		rdcfb_put(&s, op->fg);
		rdcfb_put(&s, RDC_XY(op->dx, op->dy));
		rdcfb_put(&s, RDC_WH(op->w, op->h));
		break;
	case RDCFB_OPK_COPY:
		rdcfb_put(&s, RDC_CMD(RDC_OP_BLIT, 0, 3));
		rdcfb_put(&s, RDC_XY(op->sx, op->sy));
		rdcfb_put(&s, RDC_XY(op->dx, op->dy));
		rdcfb_put(&s, RDC_WH(op->w, op->h));
		break;
	default:
		/* a glyph carries its colours: one command, as fb_image does */
		if (op->arg)
			rdcfb_put(&s, RDC_CMD(RDC_OP_MONO, RDC_MONO_COLORS,
					      RDCFB_MONO_ARGS + op->words));
		else
			rdcfb_put(&s, RDC_CMD(RDC_OP_HOST_BLIT, 0,
					      RDCFB_DATA_ARGS + op->words));
		rdcfb_put(&s, RDC_XY(op->dx, op->dy));
		rdcfb_put(&s, RDC_WH(op->w, op->h));
		if (op->arg) {
			rdcfb_put(&s, op->fg);
			rdcfb_put(&s, op->bg);
		}
		rdcfb_flush(&s);
		if (!s.err)
			s.err = rdc_kchip_push_locked(s.chip, data, op->words);
		break;
	}
	rdcfb_end(par, &s);
}

/* ---- Applying the queue (chip->lock held) -------------------------------- */

static void rdcfb_blank_locked(struct rdc_kchip *chip, int blank)
{
	struct rdc_hw *hw = chip->hw;
	struct rdc_hw_state st;
	u32 ctl, pins;

	ctl = rdc_hw_read(hw, RDC_REG_CONTROL) &
	      ~(RDC_CONTROL_RESUME | RDC_CONTROL_SOFT_RESET);
	rdc_hw_state(hw, &st);
	pins = st.pins_in;
	if (blank == FB_BLANK_UNBLANK) {
		ctl |= RDC_CONTROL_SCANOUT_EN;
		pins |= RDC_PIN_BL_EN;
	} else {
		ctl &= ~RDC_CONTROL_SCANOUT_EN;
		pins &= ~RDC_PIN_BL_EN;
	}
	rdc_hw_write(hw, RDC_REG_CONTROL, ctl);
	rdc_hw_set_pins(hw, pins);
}

static void rdcfb_op_run(struct rdcfb_par *par, const struct rdcfb_op *op,
			 const u32 *data)
{
	struct rdc_kchip *chip = par->chip;
	struct rdc_hw *hw = chip->hw;
	u64 lo;
	u32 i;

	switch (op->kind) {
	case RDCFB_OPK_REGS:
		for (i = 0; i + 1 < op->words; i += 2)
			rdc_hw_write(hw, data[i], data[i + 1]);
		rdc_kchip_irq_check_locked(chip);
		return;
	case RDCFB_OPK_BLANK:
		rdcfb_blank_locked(chip, op->arg);
		rdc_kchip_irq_check_locked(chip);
		return;
	}
	if (rdc_kchip_dp_usable(chip)) {
		rdcfb_dp_draw(par, op, data);
		return;
	}
	/* the CPU draws: after what the DP has queued */
	if (rdc_kchip_dp_runs_locked(chip))
		rdc_kchip_drain_locked(chip);
	rdcfb_cpu_draw(chip, op, data);
	/* the CPU's writes pass no barrier: scanout on demand hears of them */
	lo = min_t(u64, (u64)op->dy * op->stride, rdc_hw_vram_size(hw));
	rdc_hw_vram_touched(hw, lo,
			    min_t(u64, (u64)op->h * op->stride,
				  rdc_hw_vram_size(hw) - lo));
}

/* Apply every queued record, in order (rdc_kchip_lock does). */
static void rdcfb_ops_apply_locked(struct rdc_kchip *chip)
{
	struct rdcfb_opq *oq = &rdcfb_dev_of(chip)->opq;
	struct rdcfb_op op;
	unsigned long flags;
	u32 i, n;

	lockdep_assert_held(&chip->lock);
	for (;;) {
		rdc_kchip_spin_lock(&oq->lock, flags, oq->t0);
		n = oq->count ?
			    RDCFB_OP_HDR_WORDS +
				    oq->ring[(oq->head + 1) % RDCFB_OPQ_WORDS] :
			    0;
		n = min3(n, oq->count, RDCFB_OP_MAX_WORDS);
		for (i = 0; i < n; i++)
			oq->buf[i] = oq->ring[(oq->head + i) % RDCFB_OPQ_WORDS];
		oq->head = (oq->head + n) % RDCFB_OPQ_WORDS;
		oq->count -= n;
		rdc_kchip_spin_unlock(&oq->lock, flags, oq->t0, &chip->irqoff);
		if (n < RDCFB_OP_HDR_WORDS)
			break;
		memcpy(&op, oq->buf, sizeof(op));
		op.words = n - RDCFB_OP_HDR_WORDS;
		rdcfb_op_run(rdcfb_dev_of(chip)->info->par, &op,
			     oq->buf + RDCFB_OP_HDR_WORDS);
		cond_resched();
	}
}

/* The host's before_use hook: the queue goes to the chip first. */
static void rdcfb_before_use(struct rdc_kchip *chip)
{
	struct rdcfb_dev *rd = rdcfb_dev_of(chip);

	if (READ_ONCE(rd->opq.count) && rd->info)
		rdcfb_ops_apply_locked(chip);
}

const struct rdc_kchip_hooks rdcfb_hooks = {
	.before_use = rdcfb_before_use,
};

/* The fb-op queue's worker: for work queued where nobody could apply it. */
static void rdcfb_opq_work(struct work_struct *work)
{
	struct rdcfb_dev *rd = container_of(work, struct rdcfb_dev, opq.work);

	rdc_kchip_lock(&rd->chip);
	rdc_kchip_unlock(&rd->chip);
}

int rdcfb_opq_init(struct rdcfb_dev *rd)
{
	struct rdcfb_opq *oq = &rd->opq;

	spin_lock_init(&oq->lock);
	INIT_WORK(&oq->work, rdcfb_opq_work);
	oq->ring = vmalloc(array_size(RDCFB_OPQ_WORDS, sizeof(u32)));
	oq->buf = kmalloc_array(RDCFB_OP_MAX_WORDS, sizeof(u32), GFP_KERNEL);
	if (!oq->ring || !oq->buf) {
		rdcfb_opq_free(rd);
		return -ENOMEM;
	}
	return 0;
}

/* No fb_ops can come any more (the framebuffer is unregistered). */
void rdcfb_opq_free(struct rdcfb_dev *rd)
{
	struct rdcfb_opq *oq = &rd->opq;

	cancel_work_sync(&oq->work);
	kfree(oq->buf);
	vfree(oq->ring);
	oq->buf = NULL;
	oq->ring = NULL;
}

/* ---- fb_ops: drawing ----------------------------------------------------- */

/* A draw record on the current screen. */
static struct rdcfb_op rdcfb_op_of(struct fb_info *info, u32 kind)
{
	struct rdcfb_par *par = info->par;

	return (struct rdcfb_op){
		.kind = kind,
		.fmt = par->fmt,
		.stride = par->stride,
		.vw = info->var.xres_virtual,
		.vh = info->var.yres_virtual,
		.rop = RDC_ROP_COPY,
	};
}

static u32 rdcfb_colour(struct fb_info *info, u32 idx)
{
	struct rdcfb_par *par = info->par;
	u32 n = info->pseudo_palette == par->pseudo_palette ?
			RDCFB_PSEUDO_COLOURS :
			RDC_CLUT_ENTRIES;

	if (info->fix.visual != FB_VISUAL_TRUECOLOR)
		return idx;
	return idx < n ? ((const u32 *)info->pseudo_palette)[idx] : 0;
}

void rdcfb_fill(struct fb_info *info, const struct fb_fillrect *r)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_op op = rdcfb_op_of(info, RDCFB_OPK_FILL);

	if (!r->width || !r->height)
		return;
	op.rop = r->rop == ROP_XOR ? RDC_ROP_XOR : RDC_ROP_COPY;
	op.fg = rdcfb_colour(info, r->color);
	op.dx = r->dx;
	op.dy = r->dy;
	op.w = r->width;
	op.h = r->height;
	rdcfb_q_op(par->chip, &op);
}

void rdcfb_copy(struct fb_info *info, const struct fb_copyarea *a)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_op op = rdcfb_op_of(info, RDCFB_OPK_COPY);

	if (!a->width || !a->height)
		return;
	op.sx = a->sx;
	op.sy = a->sy;
	op.dx = a->dx;
	op.dy = a->dy;
	op.w = a->width;
	op.h = a->height;
	rdcfb_q_op(par->chip, &op);
}

/*
 * A 1 bpp image (glyphs) is MONO with FG/BG; any other depth is bytes of
 * colour indices (the logo), looked up as sys_imageblit does and sent as
 * HOST_BLIT pixels.  Tall images go as several records, one DP command
 * each, so that a record is written in a short hold of opq.lock.
 */
void rdcfb_blit(struct fb_info *info, const struct fb_image *img)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_op op = rdcfb_op_of(info, RDCFB_OPK_IMAGE);
	bool mono = img->depth == 1;
	u32 bpp = mono ? 1 : rdc_format_bpp(par->fmt);
	u32 wpr = DIV_ROUND_UP(img->width * bpp, RDCFB_BITS_PER_WORD);
	u32 src_pitch = mono ? DIV_ROUND_UP(img->width, 8) : img->width;
	u32 args = mono ? RDCFB_MONO_ARGS : RDCFB_DATA_ARGS;
	u32 max_rows, rows, y0, y, x;
	struct rdcfb_qw q;

	/* wider than one DP command takes: wider than any screen */
	if (!img->width || !img->height || wpr > RDC_CMD_MAX_ARGS - args)
		return;
	max_rows = (RDC_CMD_MAX_ARGS - args) / wpr;
	max_rows = clamp(RDCFB_OP_BAND_WORDS / wpr, 1u, max_rows);
	op.arg = mono;
	op.fg = rdcfb_colour(info, img->fg_color);
	op.bg = rdcfb_colour(info, img->bg_color);
	op.dx = img->dx;
	op.w = img->width;
	for (y0 = 0; y0 < img->height; y0 += rows) {
		rows = min(max_rows, img->height - y0);
		op.dy = img->dy + y0;
		op.h = rows;
		op.words = rows * wpr;
		if (!rdcfb_q_begin(par->chip, &q, &op))
			return;
		for (y = y0; y < y0 + rows; y++) {
			const u8 *src = (const u8 *)img->data + y * src_pitch;

			if (mono) {
				for (x = 0; x < src_pitch; x++)
					rdcfb_q_put_bits(&q, src[x], 8);
			} else {
				for (x = 0; x < img->width; x++)
					rdcfb_q_put_bits(
						&q,
						rdcfb_colour(info, src[x]) &
							GENMASK(bpp - 1, 0),
						bpp);
			}
			rdcfb_q_end_row(&q);
		}
		rdcfb_q_end(&q);
	}
}

/*
 * Before the CPU touches VRAM (read/write on /dev/fbN): let the DP finish.
 * fbcon may ask in atomic context, for its pixmap, whose data every
 * record has copied already: nothing to wait for there.
 */
int rdcfb_sync(struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	struct rdc_kchip *chip = par->chip;

	if (!preemptible())
		return 0;
	rdc_kchip_lock(chip);
	if (rdc_kchip_dp_runs_locked(chip))
		rdc_kchip_drain_locked(chip);
	rdc_kchip_unlock(chip);
	return 0;
}

static void rdcfb_destroy(struct fb_info *info)
{
	struct rdcfb_par *par = info->par;
	struct rdcfb_dev *rd = rdcfb_dev_of(par->chip);

	rdcfb_opq_free(rd);
	rdc_kchip_free(&rd->chip);
	kfree(rd);
	fb_dealloc_cmap(&info->cmap);
	framebuffer_release(info);
}

const struct fb_ops rdcfb_ops = {
	.owner = THIS_MODULE,
	.fb_open = rdcfb_open,
	.fb_release = rdcfb_release,
	.fb_read = fb_sys_read,
	.fb_write = fb_sys_write,
	.fb_check_var = rdcfb_check_var,
	.fb_set_par = rdcfb_set_par,
	.fb_setcolreg = rdcfb_setcolreg,
	.fb_setcmap = rdcfb_setcmap,
	.fb_blank = rdcfb_blank,
	.fb_pan_display = rdcfb_pan_display,
	.fb_fillrect = rdcfb_fill,
	.fb_copyarea = rdcfb_copy,
	.fb_imageblit = rdcfb_blit,
	.fb_sync = rdcfb_sync,
	.fb_ioctl = rdcfb_ioctl,
#ifdef CONFIG_COMPAT
	.fb_compat_ioctl = rdcfb_compat_ioctl,
#endif
	.fb_mmap = rdcfb_mmap,
	.fb_destroy = rdcfb_destroy,
};

/* "640x480", "800x600-16": a size with a preset, and bits per pixel. */
int rdcfb_fb_setup(struct fb_info *info, const char *mode)
{
	struct rdcfb_par *par = info->par;
	struct fb_var_screeninfo var = { 0 };
	struct rdc_timing t;
	u32 w, h, bpp = 32;
	int ret;

	if (sscanf(mode, "%ux%u-%u", &w, &h, &bpp) < 2 ||
	    rdcfb_preset_of(w, h, &t))
		return -EINVAL;
	rdcfb_dev_of(par->chip)->info = info;
	info->fbops = &rdcfb_ops;
	info->screen_buffer = par->chip->vram;
	info->screen_size = rdc_hw_vram_size(par->chip->hw);
	info->pseudo_palette = par->pseudo_palette;
	info->flags = FBINFO_VIRTFB | FBINFO_READS_FAST |
		      FBINFO_HWACCEL_FILLRECT | FBINFO_HWACCEL_COPYAREA |
		      FBINFO_HWACCEL_IMAGEBLIT | FBINFO_HWACCEL_YPAN;
	strscpy(info->fix.id, RDCFB_ID, sizeof(info->fix.id));
	info->fix.type = FB_TYPE_PACKED_PIXELS;
	info->fix.ypanstep = 1;
	info->fix.accel = FB_ACCEL_NONE;
	info->fix.smem_len = rdc_hw_vram_size(par->chip->hw);
	ret = fb_alloc_cmap(&info->cmap, RDC_CLUT_ENTRIES, 0);
	if (ret)
		return ret;
	rdcfb_timing_to_var(&t, &var);
	var.bits_per_pixel = bpp;
	var.activate = FB_ACTIVATE_NOW;
	ret = rdcfb_check_var(&var, info);
	if (!ret) {
		info->var = var;
		ret = rdcfb_set_par(info);
	}
	if (ret)
		fb_dealloc_cmap(&info->cmap);
	return ret;
}
