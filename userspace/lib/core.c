// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * librdc core: the public device API on top of a backend's operations.
 * Nothing here knows which backend it runs on.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <zlib.h>

#include "rdc_priv.h"

/*
 * A backend whose open() is NULL (usb: built without libusb) is known to
 * rdc_open (RDC_E_NOSYS), unlike a typo (RDC_E_URI).
 */
static const struct rdc_backend *const rdc_backends[] = {
	&rdc_backend_sim, &rdc_backend_unix,  &rdc_backend_tcp,
	&rdc_backend_usb, &rdc_backend_fbdev, &rdc_backend_drm,
};

static const char *const rdc_error_str[] = {
	[0] = "success",
	[-RDC_E_INVAL] = "invalid argument",
	[-RDC_E_NOMEM] = "out of memory",
	[-RDC_E_NOSYS] = "not supported by this backend",
	[-RDC_E_URI] = "unknown or malformed device URI",
	[-RDC_E_IO] = "transport failure",
	[-RDC_E_TIMEOUT] = "timed out (simulated-time budget exhausted)",
	[-RDC_E_DEVICE] = "the device reported an error",
	[-RDC_E_HALTED] = "the display processor is halted",
	[-RDC_E_RANGE] = "address or size out of range",
	[-RDC_E_PARSE] = "malformed script or trace",
	[-RDC_E_PROTO] = "protocol violation",
	[-RDC_E_BUSY] = "device busy",
	[-RDC_E_FILE] = "file could not be read or written",
	[-RDC_E_AUTH] = "token missing or refused",
	[-RDC_E_GONE] = "device gone",
	[-RDC_E_RESET] = "ended by a device reset",
};

const char *rdc_strerror(int err)
{
	if (err > 0 || err <= RDC_E_COUNT_)
		return "unknown error";
	return rdc_error_str[-err];
}

/* The thread's last recorded detail (rdc_last_error_detail). */
static __thread struct {
	int err;
	char msg[320];
} rdc_detail;

int rdc_err_detail(int err, const char *fmt, ...)
{
	int saved = errno;
	va_list ap;

	rdc_detail.err = err;
	va_start(ap, fmt);
	vsnprintf(rdc_detail.msg, sizeof(rdc_detail.msg), fmt, ap);
	va_end(ap);
	errno = saved;
	return err;
}

void rdc_err_detail_clear(void)
{
	rdc_detail.err = 0;
	rdc_detail.msg[0] = 0;
}

const char *rdc_last_error_detail(int err)
{
	return err && rdc_detail.err == err ? rdc_detail.msg : "";
}

static const char *const rdc_dev_error_str[RDC_ERR_COUNT] = {
	[RDC_ERR_NONE] = "NONE",
	[RDC_ERR_OPCODE] = "OPCODE",
	[RDC_ERR_LENGTH] = "LENGTH",
	[RDC_ERR_RANGE] = "RANGE",
	[RDC_ERR_SURFACE] = "SURFACE",
	[RDC_ERR_RING] = "RING",
	[RDC_ERR_FIFO_OVERFLOW] = "FIFO_OVERFLOW",
	[RDC_ERR_REG] = "REG",
	[RDC_ERR_ARG] = "ARG",
	[RDC_ERR_MODE] = "MODE",
	[RDC_ERR_STACK] = "STACK",
	[RDC_ERR_DATA] = "DATA",
	[RDC_ERR_RASTER] = "RASTER",
};

const char *rdc_dev_strerror(uint32_t code)
{
	return code < RDC_ERR_COUNT ? rdc_dev_error_str[code] : "UNKNOWN";
}

/* ---- Device -------------------------------------------------------------- */

static int rdc_track_reset(rdc_dev *dev);

int rdc_open(const char *uri, rdc_dev **out)
{
	const struct rdc_backend *be = NULL;
	const char *colon, *opts;
	size_t slen;
	rdc_dev *dev;
	int ret;

	rdc_err_detail_clear();
	if (!out)
		return RDC_E_INVAL;
	*out = NULL;
	if (!uri || !*uri)
		uri = "sim:";
	colon = strchr(uri, ':');
	slen = colon ? (size_t)(colon - uri) : strlen(uri);
	opts = colon ? colon + 1 : "";
	for (size_t i = 0; i < sizeof(rdc_backends) / sizeof(*rdc_backends);
	     i++) {
		const char *s = rdc_backends[i]->scheme;

		if (strlen(s) == slen && !strncmp(uri, s, slen))
			be = rdc_backends[i];
	}
	if (!be)
		return rdc_err_detail(RDC_E_URI,
				      "'%.*s:' is not a device kind (sim:, "
				      "unix:, tcp:, usb:, fbdev:, drm:)",
				      (int)RDC_MIN(slen, (size_t)40), uri);
	if (!be->open)
		return rdc_err_detail(RDC_E_NOSYS,
				      "%s: this librdc was built without it",
				      be->scheme);
	dev = calloc(1, sizeof(*dev));
	if (!dev)
		return RDC_E_NOMEM;
	dev->be = be;
	ret = be->open(dev, opts);
	if (ret) {
		free(dev);
		return ret;
	}
	ret = rdc_track_reset(dev);
	if (ret) {
		rdc_close(dev);
		return ret;
	}
	*out = dev;
	return 0;
}

int rdc_list(rdc_found_fn fn, void *arg)
{
	int total = 0;

	if (!fn)
		return RDC_E_INVAL;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(rdc_backends); i++) {
		int n;

		if (!rdc_backends[i]->list)
			continue;
		/* a scheme that cannot look (no permission, no libusb
		 * devices) leaves the others to report theirs */
		n = rdc_backends[i]->list(fn, arg);
		if (n > 0)
			total += n;
	}
	return total;
}

void rdc_close(rdc_dev *dev)
{
	if (!dev)
		return;
	rdc_history_detach(dev);
	dev->be->close(dev);
	free(dev);
}

int rdc_reg_read(rdc_dev *dev, uint32_t reg, uint32_t *val)
{
	if (!dev || !val)
		return RDC_E_INVAL;
	if (reg >= RDC_REG_WINDOW || (reg & 3))
		return RDC_E_RANGE;
	return dev->be->reg_read(dev, reg, val);
}

int rdc_reg_write(rdc_dev *dev, uint32_t reg, uint32_t val)
{
	if (!dev)
		return RDC_E_INVAL;
	if (reg >= RDC_REG_WINDOW || (reg & 3))
		return RDC_E_RANGE;
	return dev->be->reg_write(dev, reg, val);
}

/* A 64-bit counter: LO first, which snapshots HI. */
static int rdc_reg_read64(rdc_dev *dev, uint32_t lo, uint64_t *v)
{
	uint32_t l, h;
	int ret;

	ret = rdc_reg_read(dev, lo, &l);
	if (!ret)
		ret = rdc_reg_read(dev, lo + 4, &h);
	if (!ret)
		*v = ((uint64_t)h << 32) | l;
	return ret;
}

/*
 * The DP's destination surface as the host last programmed it, learned by
 * watching the command words that go out (rdc_submit): rdc_host_blit needs
 * its format to lay out rows.  After a reset the DP draws to the scanout
 * framebuffer.
 */
static int rdc_track_reset(rdc_dev *dev)
{
	uint32_t fmt;
	int ret;

	dev->scan_left = 0;
	dev->scan_n = 0;
	ret = rdc_reg_read(dev, RDC_REG_FB_FORMAT, &fmt);
	if (ret)
		return ret;
	dev->dst_format = fmt;
	dev->src_format = fmt;
	return 0;
}

static void rdc_track_words(rdc_dev *dev, const uint32_t *w, size_t n)
{
	uint32_t op = dev->scan_op, left = dev->scan_left;
	size_t i = 0;

	/* the header walk runs in locals: most commands are a few words */
	while (i < n) {
		if (!left) {
			op = RDC_CMD_OP(w[i]);
			left = RDC_CMD_LEN(w[i]);
			dev->scan_n = 0;
			i++;
			continue;
		}
		/* only the surfaces are tracked: other arguments skip whole */
		if (op != RDC_OP_SET_DST && op != RDC_OP_SET_SRC) {
			uint32_t k = (uint32_t)RDC_MIN((size_t)left, n - i);

			left -= k;
			i += k;
			continue;
		}
		if (dev->scan_n < RDC_ARRAY_SIZE(dev->scan_args))
			dev->scan_args[dev->scan_n] = w[i];
		dev->scan_n++;
		i++;
		if (--left)
			continue;
		/* SET_DST/SET_SRC: base, stride, wh, format */
		if (dev->scan_n == 4 && dev->scan_args[3] < RDC_FMT_COUNT) {
			if (op == RDC_OP_SET_DST)
				dev->dst_format = dev->scan_args[3];
			else
				dev->src_format = dev->scan_args[3];
		}
	}
	dev->scan_op = op;
	dev->scan_left = left;
}

int rdc_reset(rdc_dev *dev)
{
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_reg_write(dev, RDC_REG_CONTROL, RDC_CONTROL_SOFT_RESET);
	if (ret)
		return ret;
	return rdc_track_reset(dev);
}

int rdc_dev_error(rdc_dev *dev, uint32_t *code, uint32_t *info)
{
	uint32_t c, i;
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_ERR_CODE, &c);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_ERR_INFO, &i);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_IRQ_STATUS, RDC_IRQ_ERROR);
	if (ret)
		return ret;
	if (code)
		*code = c;
	if (info)
		*info = i;
	return 0;
}

int rdc_check_error(rdc_dev *dev)
{
	uint32_t st;
	int ret = rdc_reg_read(dev, RDC_REG_IRQ_STATUS, &st);

	if (ret)
		return ret;
	return (st & RDC_IRQ_ERROR) ? RDC_E_DEVICE : 0;
}

int rdc_vram_read(rdc_dev *dev, uint32_t addr, void *buf, size_t len)
{
	if (!dev || (!buf && len))
		return RDC_E_INVAL;
	return dev->be->vram_read(dev, addr, buf, len);
}

int rdc_vram_write(rdc_dev *dev, uint32_t addr, const void *buf, size_t len)
{
	if (!dev || (!buf && len))
		return RDC_E_INVAL;
	return dev->be->vram_write(dev, addr, buf, len);
}

/* ---- Modes --------------------------------------------------------------- */

int rdc_preset_size(uint32_t preset, uint32_t *width, uint32_t *height)
{
	struct rdc_timing t;

	if (rdc_preset_timing(preset, &t))
		return RDC_E_INVAL;
	if (width)
		*width = t.h_display;
	if (height)
		*height = t.v_display;
	return 0;
}

static const struct {
	const char *name;
	uint32_t preset;
} rdc_preset_names[] = {
	{ "320x200@70", RDC_PRESET_320x200_70 },
	{ "640x480@60", RDC_PRESET_640x480_60 },
	{ "800x600@60", RDC_PRESET_800x600_60 },
	{ "1024x768@60", RDC_PRESET_1024x768_60 },
	{ "1280x720@60", RDC_PRESET_1280x720_60 },
	{ "1920x1080@60", RDC_PRESET_1920x1080_60 },
	{ "720p", RDC_PRESET_1280x720_60 },
	{ "1080p", RDC_PRESET_1920x1080_60 },
};

int rdc_preset_by_name(const char *name)
{
	if (!name)
		return -1;
	for (size_t i = 0; i < RDC_ARRAY_SIZE(rdc_preset_names); i++) {
		const char *n = rdc_preset_names[i].name;
		const char *at = strchr(n, '@');

		if (!strcasecmp(name, n) ||
		    (at && strlen(name) == (size_t)(at - n) &&
		     !strncasecmp(name, n, (size_t)(at - n))))
			return (int)rdc_preset_names[i].preset;
	}
	return -1;
}

int rdc_mode_set(rdc_dev *dev, uint32_t preset, uint32_t format, uint32_t base)
{
	uint32_t w, h, stride, vram, cmd[16];
	size_t n = 0;
	int ret;

	if (!dev || format >= RDC_FMT_COUNT || (base & 3) ||
	    rdc_preset_size(preset, &w, &h))
		return RDC_E_INVAL;
	stride = (rdc_format_row_bytes(format, w) + 3) & ~3u;
	ret = rdc_reg_read(dev, RDC_REG_VRAM_SIZE, &vram);
	if (ret)
		return ret;
	if (base > vram || (uint64_t)stride * h > vram - base)
		return RDC_E_RANGE;
	/* FORMAT first: MODE_PRESET derives its stride from it. */
	ret = rdc_reg_write(dev, RDC_REG_FB_FORMAT, format);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_FB_BASE, base);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_MODE_PRESET, preset);
	if (!ret)
		ret = rdc_reg_write(dev, RDC_REG_FB_STRIDE, stride);
	if (ret)
		return ret;
	cmd[n++] = RDC_CMD(RDC_OP_SET_DST, 0, 4);
	cmd[n++] = base;
	cmd[n++] = stride;
	cmd[n++] = RDC_WH(w, h);
	cmd[n++] = format;
	cmd[n++] = RDC_CMD(RDC_OP_SET_SRC, 0, 4);
	cmd[n++] = base;
	cmd[n++] = stride;
	cmd[n++] = RDC_WH(w, h);
	cmd[n++] = format;
	cmd[n++] = RDC_CMD(RDC_OP_SET_CLIP, 0, 2);
	cmd[n++] = RDC_XY(0, 0);
	cmd[n++] = RDC_XY(w, h);
	return rdc_submit(dev, cmd, n);
}

/* ---- Waits and submission ------------------------------------------------ */

int rdc_wait_one(rdc_dev *dev, enum rdc_wait_test kind, uint32_t reg,
		 uint32_t mask, uint32_t value, bool needs_dp)
{
	struct rdc_wait w = {
		.term[0] = { .kind = kind,
			     .reg = reg,
			     .mask = mask,
			     .value = value },
		.needs_dp = needs_dp,
	};

	return dev->be->wait(dev, &w);
}

static int fifo_push_words(rdc_dev *dev, const uint32_t *words, uint32_t n)
{
	for (uint32_t i = 0; i < n; i++) {
		int ret = rdc_reg_write(dev, RDC_REG_FIFO_DATA, words[i]);

		if (ret)
			return ret;
	}
	return (int)n;
}

int rdc_fifo_feed_step(rdc_dev *dev, const uint32_t *words, size_t n,
		       rdc_fifo_push_fn push, struct rdc_wait_cond *room)
{
	uint32_t free_words;
	int ret;

	if (!push)
		push = fifo_push_words;
	ret = rdc_reg_read(dev, RDC_REG_FIFO_FREE, &free_words);
	if (ret)
		return ret;
	if (!free_words) {
		/* Wait for half a FIFO, not one word: fewer checks. */
		*room = (struct rdc_wait_cond){
			.test = RDC_WAIT_TEST_GE,
			.reg = RDC_REG_FIFO_FREE,
			.mask = ~0u,
			.value = n < RDC_FIFO_DEPTH / 2 ? (uint32_t)n :
							  RDC_FIFO_DEPTH / 2,
		};
		return 0;
	}
	return push(dev, words, (uint32_t)RDC_MIN(n, (size_t)free_words));
}

int rdc_fifo_feed(rdc_dev *dev, const uint32_t *words, size_t n,
		  rdc_fifo_push_fn push)
{
	struct rdc_wait_cond room = { 0 };
	int ret;

	while (n) {
		ret = rdc_fifo_feed_step(dev, words, n, push, &room);
		if (ret < 0)
			return ret;
		if (!ret) {
			ret = rdc_wait_one(dev, room.test, room.reg, room.mask,
					   room.value, true);
			if (ret)
				return ret;
			continue;
		}
		words += ret;
		n -= (size_t)ret;
	}
	return 0;
}

int rdc_submit_whole(rdc_dev *dev, const uint32_t *words, size_t n,
		     bool surfaces)
{
	if (!dev || (!words && n))
		return RDC_E_INVAL;
	/*
	 * The walk only follows SET_DST and SET_SRC: words of whole
	 * commands without them, after a whole command, leave nothing
	 * for it to find.
	 */
	if (surfaces || dev->scan_left)
		rdc_track_words(dev, words, n);
	if (dev->be->submit)
		return dev->be->submit(dev, words, n);
	return rdc_fifo_feed(dev, words, n, NULL);
}

int rdc_submit(rdc_dev *dev, const uint32_t *words, size_t n)
{
	return rdc_submit_whole(dev, words, n, true);
}

int rdc_fence_wait(rdc_dev *dev, uint32_t value)
{
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_wait_one(dev, RDC_WAIT_TEST_WRAP_GE, RDC_REG_FENCE, ~0u,
			   value, true);
	return ret ? ret : rdc_check_error(dev);
}

/*
 * A FENCE value for the library's own use: different from what FENCE
 * reads now, so seeing it there means our fence ran (the application may
 * use any values of its own, so no ordering can be assumed).
 */
static int rdc_fence_next(rdc_dev *dev, uint32_t *seq)
{
	uint32_t cur;
	int ret = rdc_reg_read(dev, RDC_REG_FENCE, &cur);

	if (ret)
		return ret;
	if (++dev->fence_seq == cur)
		dev->fence_seq++;
	*seq = dev->fence_seq;
	return 0;
}

int rdc_finish(rdc_dev *dev)
{
	uint32_t cmd[2];
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	cmd[0] = RDC_CMD(RDC_OP_FENCE, 0, 1);
	ret = rdc_fence_next(dev, &cmd[1]);
	if (!ret)
		ret = rdc_submit(dev, cmd, 2);
	if (!ret)
		ret = rdc_wait_one(dev, RDC_WAIT_TEST_EQ, RDC_REG_FENCE, ~0u,
				   cmd[1], true);
	/* An application fence with the same value may have matched first;
	 * nothing is queued behind ours, so idle settles it. */
	return ret ? ret : rdc_idle_wait(dev);
}

int rdc_idle_wait(rdc_dev *dev)
{
	const uint32_t mask = RDC_STATUS_IDLE_MASK | RDC_STATUS_FIFO_EMPTY;
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_wait_one(dev, RDC_WAIT_TEST_EQ, RDC_REG_STATUS, mask,
			   RDC_STATUS_FIFO_EMPTY, true);
	return ret ? ret : rdc_check_error(dev);
}

int rdc_vblank_wait(rdc_dev *dev)
{
	uint32_t fc;
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &fc);
	if (ret)
		return ret;
	return rdc_wait_one(dev, RDC_WAIT_TEST_WRAP_GE, RDC_REG_FRAME_COUNT,
			    ~0u, fc + 1, false);
}

int rdc_frame_wait(rdc_dev *dev)
{
	uint32_t fc;
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &fc);
	if (ret)
		return ret;
	/*
	 * Two vblanks from anywhere: the first latches what the host wrote
	 * (mode, base, format are latched registers), the frame scanned after
	 * it with that state in force completes at the second.  From
	 * vertical blanking one would do for VRAM contents, but not for a
	 * mode set there, which is latched only at the next vblank.
	 */
	return rdc_wait_one(dev, RDC_WAIT_TEST_WRAP_GE, RDC_REG_FRAME_COUNT,
			    ~0u, fc + 2, false);
}

/* ---- Host <-> screen ---------------------------------------------------- */

static void rdc_rb_store(uint8_t *out, size_t cap, size_t *got, bool *overflow,
			 uint32_t v)
{
	if (*got + 4 > cap) {
		/* keep draining so the FIFO is left empty */
		*overflow = true;
		return;
	}
	rdc_st32(out + *got, v);
	*got += 4;
}

int rdc_readback(rdc_dev *dev, int x, int y, uint32_t w, uint32_t h, void *buf,
		 size_t cap)
{
	uint8_t *out = buf;
	size_t got = 0;
	bool overflow = false;
	uint32_t cmd[5], seq;
	int ret;

	if (!dev || (!buf && cap))
		return RDC_E_INVAL;
	ret = rdc_fence_next(dev, &seq);
	if (ret)
		return ret;
	cmd[0] = RDC_CMD(RDC_OP_READBACK, 0, 2);
	cmd[1] = RDC_XY(x, y);
	cmd[2] = RDC_WH(w, h);
	cmd[3] = RDC_CMD(RDC_OP_FENCE, 0, 1);
	cmd[4] = seq;
	ret = rdc_submit(dev, cmd, 5);
	if (ret)
		return ret;
	/*
	 * The data is popped as it arrives (the RDATA FIFO is smaller than
	 * most rectangles); the fence behind the READBACK says it is all
	 * there.
	 */
	for (;;) {
		uint32_t fence, count;
		struct rdc_wait wt = {
			.term = {
				{RDC_WAIT_TEST_GE, RDC_REG_RDATA_COUNT,
				 ~0u, 1},
				{RDC_WAIT_TEST_EQ, RDC_REG_FENCE, ~0u,
				 seq},
			},
			.needs_dp = true,
		};

		ret = rdc_reg_read(dev, RDC_REG_FENCE, &fence);
		if (!ret)
			ret = rdc_reg_read(dev, RDC_REG_RDATA_COUNT, &count);
		if (ret)
			return ret;
		for (; count; count--) {
			uint32_t v;

			ret = rdc_reg_read(dev, RDC_REG_RDATA, &v);
			if (ret)
				return ret;
			rdc_rb_store(out, cap, &got, &overflow, v);
		}
		if (fence == seq)
			break;
		ret = dev->be->wait(dev, &wt);
		if (ret)
			return ret;
	}
	/* Words pushed after the fence was read are still ours. */
	for (;;) {
		uint32_t count, v;

		ret = rdc_reg_read(dev, RDC_REG_RDATA_COUNT, &count);
		if (ret)
			return ret;
		if (!count)
			break;
		ret = rdc_reg_read(dev, RDC_REG_RDATA, &v);
		if (ret)
			return ret;
		rdc_rb_store(out, cap, &got, &overflow, v);
	}
	ret = rdc_check_error(dev);
	if (ret)
		return ret;
	if (overflow)
		return RDC_E_RANGE;
	return (int)got;
}

/*
 * Widest piece of a host blit: a multiple of 32 pixels, so every piece
 * starts on a byte (and word) boundary in every format, whose row fits one
 * command with its two position words.
 */
static uint32_t rdc_blit_piece_width(uint32_t fmt)
{
	uint32_t max_words = RDC_CMD_MAX_ARGS - 2;
	uint32_t px = max_words * 32 / rdc_format_bpp(fmt);

	return px & ~31u;
}

int rdc_host_blit_encode(uint32_t fmt, int x, int y, uint32_t w, uint32_t h,
			 const void *pixels, size_t pitch,
			 int (*emit)(void *ctx, const uint32_t *cmd, size_t n),
			 void *ctx)
{
	const uint8_t *src = pixels;
	uint32_t piece_w, *cmd;
	int ret = 0;

	if (!pixels || !emit || w > RDC_SIZE_MAX || h > RDC_SIZE_MAX ||
	    fmt >= RDC_FMT_COUNT)
		return RDC_E_INVAL;
	if (!w || !h)
		return 0;
	if (pitch < rdc_format_row_bytes(fmt, w))
		return RDC_E_INVAL;
	cmd = malloc((1 + RDC_CMD_MAX_ARGS) * sizeof(*cmd));
	if (!cmd)
		return RDC_E_NOMEM;
	piece_w = rdc_blit_piece_width(fmt);
	for (uint32_t px = 0; px < w && !ret; px += piece_w) {
		uint32_t pw = RDC_MIN(piece_w, w - px);
		uint32_t row_bytes = rdc_format_row_bytes(fmt, pw);
		uint32_t row_words = (row_bytes + 3) / 4;
		uint32_t rows_max = (RDC_CMD_MAX_ARGS - 2) / row_words;
		size_t src_off = (size_t)px * rdc_format_bpp(fmt) / 8;

		for (uint32_t py = 0; py < h && !ret; py += rows_max) {
			uint32_t ph = RDC_MIN(rows_max, h - py);
			size_t n = 0;

			cmd[n++] = RDC_CMD(RDC_OP_HOST_BLIT, 0,
					   2 + ph * row_words);
			cmd[n++] = RDC_XY(x + (int)px, y + (int)py);
			cmd[n++] = RDC_WH(pw, ph);
			for (uint32_t r = 0; r < ph; r++) {
				const uint8_t *row = src +
						     (size_t)(py + r) * pitch +
						     src_off;
				uint32_t whole = row_bytes / 4;
				uint8_t pad[4] = { 0 };

				for (uint32_t k = 0; k < whole; k++)
					cmd[n++] = rdc_ld32(row + k * 4);
				if (whole < row_words) {
					memcpy(pad, row + whole * 4,
					       row_bytes - whole * 4);
					cmd[n++] = rdc_ld32(pad);
				}
			}
			ret = emit(ctx, cmd, n);
		}
	}
	free(cmd);
	return ret;
}

static int rdc_host_blit_submit(void *ctx, const uint32_t *cmd, size_t n)
{
	return rdc_submit(ctx, cmd, n);
}

int rdc_host_blit(rdc_dev *dev, int x, int y, uint32_t w, uint32_t h,
		  const void *pixels, size_t pitch)
{
	if (!dev)
		return RDC_E_INVAL;
	return rdc_host_blit_encode(dev->dst_format, x, y, w, h, pixels, pitch,
				    rdc_host_blit_submit, dev);
}

/* ---- Frames -------------------------------------------------------------- */

int rdc_frame_grab(rdc_dev *dev, uint32_t *buf, size_t cap, uint32_t *width,
		   uint32_t *height)
{
	uint32_t w = 0, h = 0, tries;
	int ret;

	if (!dev || (!buf && cap))
		return RDC_E_INVAL;
	if (!dev->be->frame_grab)
		return RDC_E_NOSYS;
	ret = dev->be->frame_grab(dev, buf, cap, &w, &h);
	/*
	 * No frame: before the first, or one that scanout on demand dropped
	 * (hw-sim/rdc_chip.h); the one scanned whole after the look began
	 * completes at the second vblank at the latest.
	 */
	for (tries = 0; ret == 1 && tries < 2; tries++) {
		ret = rdc_vblank_wait(dev);
		if (ret)
			return ret;
		ret = dev->be->frame_grab(dev, buf, cap, &w, &h);
	}
	if (ret == 1)
		ret = RDC_E_TIMEOUT;
	if (ret == 0 || ret == RDC_E_RANGE) {
		if (width)
			*width = w;
		if (height)
			*height = h;
	}
	return ret;
}

/* The frame and its size, in a buffer of the caller's to free. */
int rdc_frame_alloc(rdc_dev *dev, uint32_t **pix, uint32_t *width,
		    uint32_t *height)
{
	uint32_t w = 0, h = 0, *buf;
	int ret;

	ret = rdc_frame_grab(dev, NULL, 0, &w, &h);
	if (ret != RDC_E_RANGE && ret != 0)
		return ret;
	buf = malloc(((size_t)w * h + 1) * sizeof(*buf));
	if (!buf)
		return RDC_E_NOMEM;
	ret = rdc_frame_grab(dev, buf, (size_t)w * h, &w, &h);
	if (ret) {
		free(buf);
		return ret;
	}
	*pix = buf;
	*width = w;
	*height = h;
	return 0;
}

uint32_t rdc_crc32_xrgb(const uint32_t *pix, size_t n)
{
	uLong crc = crc32(0L, Z_NULL, 0);
	uint8_t chunk[1024];

	/* Bytes in memory order of little-endian XRGB8888, on any host. */
	while (n) {
		size_t k = RDC_MIN(n, sizeof(chunk) / 4);

		for (size_t i = 0; i < k; i++)
			rdc_st32(chunk + 4 * i, pix[i]);
		crc = crc32(crc, chunk, (uInt)(k * 4));
		pix += k;
		n -= k;
	}
	return (uint32_t)crc;
}

int rdc_frame_crc(rdc_dev *dev, uint32_t *crc)
{
	uint32_t *pix, w, h;
	int ret;

	if (!dev || !crc)
		return RDC_E_INVAL;
	ret = rdc_frame_alloc(dev, &pix, &w, &h);
	if (ret)
		return ret;
	*crc = rdc_crc32_xrgb(pix, (size_t)w * h);
	free(pix);
	return 0;
}

/* ---- Introspection ------------------------------------------------------- */

int rdc_sim_time(rdc_dev *dev, uint64_t *cycles)
{
	if (!dev || !cycles)
		return RDC_E_INVAL;
	return rdc_reg_read64(dev, RDC_REG_TIME_LO, cycles);
}

int rdc_sim_step(rdc_dev *dev, uint64_t cycles)
{
	if (!dev)
		return RDC_E_INVAL;
	if (!dev->be->step)
		return RDC_E_NOSYS;
	return dev->be->step(dev, cycles);
}

int rdc_sim_run_until(rdc_dev *dev, uint64_t t)
{
	uint64_t now;
	int ret;

	ret = rdc_sim_time(dev, &now);
	if (ret)
		return ret;
	return t > now ? rdc_sim_step(dev, t - now) : 0;
}

int rdc_sim_beam(rdc_dev *dev, uint32_t *x, uint32_t *y)
{
	uint32_t b;
	int ret;

	if (!dev)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_BEAM, &b);
	if (ret)
		return ret;
	if (x)
		*x = FIELD_GET(RDC_BEAM_X, b);
	if (y)
		*y = FIELD_GET(RDC_BEAM_Y, b);
	return 0;
}

int rdc_sim_core_hz(rdc_dev *dev, uint32_t *hz)
{
	uint32_t khz;
	int ret;

	if (!dev || !hz)
		return RDC_E_INVAL;
	ret = rdc_reg_read(dev, RDC_REG_CORE_KHZ, &khz);
	if (!ret)
		*hz = khz * 1000u;
	return ret;
}

int rdc_stats_get_sized(rdc_dev *dev, struct rdc_stats *out)
{
	struct rdc_stats full, *st = &full;
	uint32_t frames;
	int ret;

	if (!dev || !out)
		return RDC_E_INVAL;
	memset(st, 0, sizeof(*st));
	ret = rdc_reg_read64(dev, RDC_REG_TIME_LO, &st->time);
	if (!ret)
		ret = rdc_reg_read64(dev, RDC_REG_PERF_BUSY_LO, &st->busy);
	if (!ret)
		ret = rdc_reg_read64(dev, RDC_REG_PERF_STALL_LO, &st->stall);
	if (!ret)
		ret = rdc_reg_read64(dev, RDC_REG_PERF_PIXELS_LO, &st->pixels);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_PERF_CMDS, &st->cmds);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_PERF_LAST_CYCLES,
				   &st->last_cycles);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_PERF_LAST_OPCODE,
				   &st->last_opcode);
	if (!ret)
		ret = rdc_reg_read(dev, RDC_REG_FRAME_COUNT, &frames);
	if (!ret)
		st->frames = frames;
	rdc_struct_out(out, st, sizeof(*st));
	return ret;
}

/* ---- Events -------------------------------------------------------------- */

int rdc_subscribe(rdc_dev *dev, uint32_t events, uint32_t every,
		  uint32_t encoding)
{
	if (!dev || (events & ~(RDC_EVENT_FRAME | RDC_EVENT_IRQ)) ||
	    encoding > RDC_FRAME_DELTA ||
	    ((events & RDC_EVENT_FRAME) && !every))
		return RDC_E_INVAL;
	if (!dev->be->subscribe)
		return RDC_E_NOSYS;
	return dev->be->subscribe(dev, events, every, encoding);
}

int rdc_event_next_sized(rdc_dev *dev, struct rdc_event *out, uint32_t *buf,
			 size_t cap, int timeout_ms)
{
	struct rdc_event ev = { 0 };
	int ret;

	if (!dev || !out || (!buf && cap))
		return RDC_E_INVAL;
	if (!dev->be->event_next)
		return RDC_E_NOSYS;
	ret = dev->be->event_next(dev, &ev, buf, cap, timeout_ms);
	rdc_struct_out(out, &ev, sizeof(ev));
	return ret;
}
