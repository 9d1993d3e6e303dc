// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * How the .rdl interpreter's statements run, and its errors: the layer
 * under the statements (script.c, script_img.c, script_3d.c), which call
 * it with their batch once it is encoded.
 *
 * Each statement is parsed completely before anything is sent, so a
 * syntax error never leaves half a command in the FIFO.  Every statement
 * that issues commands runs to completion (the DP idle) before the next
 * one: the busy-cycle and command counters read around it then belong to
 * that statement alone, which makes the per-class accounting in struct
 * rdc_script_result exact without any help from the device.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "script.h"

int rdl_err(struct rdl *r, int code, const char *fmt, ...)
{
	va_list ap;

	r->res->error_line = r->line;
	va_start(ap, fmt);
	vsnprintf(r->res->error_msg, sizeof(r->res->error_msg), fmt, ap);
	va_end(ap);
	return code;
}

/*
 * An error at `at` in r->buf: its physical line and 1-based column, found
 * by walking the statement's source lines as rdl_next_line joined them.
 */
int rdl_err_at(struct rdl *r, const char *at, int code, const char *fmt, ...)
{
	size_t off = (size_t)(at - r->buf);
	const char *p = r->src;
	uint32_t line = r->line;
	va_list ap;

	while (p && p < r->src_end) {
		const char *nl = memchr(p, '\n', (size_t)(r->src_end - p));
		size_t len = nl ? (size_t)(nl - p) : (size_t)(r->src_end - p);

		if (len && p[len - 1] == '\r')
			len--;
		if (len && p[len - 1] == '\\')
			len--;
		if (off <= len || !nl)
			break;
		off -= len + 1; /* the blank that joined the lines */
		line++;
		p = nl + 1;
	}
	r->res->error_line = line;
	r->res->error_col = (uint32_t)RDC_MIN(off + 1, (size_t)UINT32_MAX);
	va_start(ap, fmt);
	vsnprintf(r->res->error_msg, sizeof(r->res->error_msg), fmt, ap);
	va_end(ap);
	return code;
}

/* A library call failed: describe it, with the device's code if any. */
int rdl_fail(struct rdl *r, const char *what, int ret)
{
	uint32_t code = 0, info = 0;

	if (ret == RDC_E_DEVICE &&
	    !rdc_reg_read(r->dev, RDC_REG_ERR_CODE, &code) &&
	    !rdc_reg_read(r->dev, RDC_REG_ERR_INFO, &info))
		return rdl_err(r, ret, "%s: device error %s (info 0x%08x)",
			       what, rdc_dev_strerror(code), info);
	return rdl_err(r, ret, "%s: %s", what, rdc_strerror(ret));
}

uint32_t rdl_dst_format(struct rdl *r)
{
	return r->dev->dst_format;
}

/* The counters that the accounting reads around a statement. */
int rdl_counters(struct rdl *r, uint64_t *busy, uint32_t *cmds)
{
	uint32_t lo, hi;
	int ret;

	ret = rdc_reg_read(r->dev, RDC_REG_PERF_BUSY_LO, &lo);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_PERF_BUSY_HI, &hi);
	if (!ret)
		ret = rdc_reg_read(r->dev, RDC_REG_PERF_CMDS, cmds);
	if (ret)
		return rdl_fail(r, "reading counters", ret);
	*busy = (uint64_t)hi << 32 | lo;
	return 0;
}

void rdl_account(struct rdl *r, uint32_t op, uint64_t busy0, uint32_t cmds0,
		 uint64_t busy1, uint32_t cmds1)
{
	op &= 0xff;
	r->res->op_cycles[op] += busy1 - busy0;
	r->res->op_count[op] += cmds1 - cmds0;
}

/* Submit the statement's batch, run the DP dry, charge it to `op`. */
static int rdl_run_batch(struct rdl *r, uint32_t op)
{
	uint64_t busy0, busy1;
	uint32_t cmds0, cmds1;
	int ret;

	ret = rdl_counters(r, &busy0, &cmds0);
	if (ret)
		return ret;
	ret = rdc_batch_submit(r->dev, r->b);
	if (!ret)
		ret = rdc_idle_wait(r->dev);
	if (ret)
		return rdl_fail(r, rdc_op_name(op) ? rdc_op_name(op) : "cmd",
				ret);
	ret = rdl_counters(r, &busy1, &cmds1);
	if (ret)
		return ret;
	rdl_account(r, op, busy0, cmds0, busy1, cmds1);
	return 0;
}

/* Inside `list`: append the statement's words to the list instead. */
static int rdl_list_add(struct rdl *r)
{
	size_t n;
	const uint32_t *w = rdc_batch_words(r->b, &n);

	if (n > RDL_MAX_LIST_WORDS - r->list_n)
		return rdl_err(r, RDC_E_PARSE, "list longer than %u words",
			       RDL_MAX_LIST_WORDS);
	if (r->list_n + n > r->list_cap) {
		size_t cap = RDC_MAX(r->list_cap * 2, r->list_n + n);
		uint32_t *nw = realloc(r->list_w, cap * sizeof(*nw));

		if (!nw)
			return rdl_err(r, RDC_E_NOMEM, "out of memory");
		r->list_w = nw;
		r->list_cap = cap;
	}
	memcpy(r->list_w + r->list_n, w, n * sizeof(*w));
	r->list_n += n;
	rdc_batch_reset(r->b);
	return 0;
}

int rdl_encoded(struct rdl *r, uint32_t op, int enc)
{
	if (enc)
		return rdl_err(r, enc, "encoding: %s", rdc_strerror(enc));
	if (r->list_on)
		return rdl_list_add(r);
	return rdl_run_batch(r, op);
}
