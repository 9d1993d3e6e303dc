// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* The png sink: numbered stills, every Nth frame and on demand. */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "rdc_priv.h"
#include "sink_priv.h"

#define PNG_PREFIX_MAX 64
#define PNG_PATH_MAX   4096

struct png_sink {
	char *dir;
	char prefix[PNG_PREFIX_MAX];
	uint32_t every;	   /* 0: on demand only */
	uint64_t received; /* frames seen, for every= */
	bool want;	   /* snapshot requested */
};

static int png_frame(rdc_sink *s, const struct rdc_frame *f)
{
	struct png_sink *p = s->priv;
	char path[PNG_PATH_MAX];
	bool due = p->every && p->received % p->every == 0;
	int ret, n;

	p->received++;
	if (!due && !p->want)
		return 0;
	p->want = false;
	n = snprintf(path, sizeof(path), "%s/%s-%08" PRIu64 ".png", p->dir,
		     p->prefix, f->seq);
	if (n < 0 || (size_t)n >= sizeof(path))
		return rdc_err_detail(RDC_E_FILE, "%.200s/...: path too long",
				      p->dir);
	ret = rdc_png_write(path, f->xrgb, f->width, f->height, f->stride);
	if (ret) {
		s->st.dropped++;
		return ret;
	}
	s->st.written++;
	return 0;
}

static int png_snapshot(rdc_sink *s)
{
	struct png_sink *p = s->priv;

	p->want = true;
	return 0;
}

static void png_close(rdc_sink *s)
{
	struct png_sink *p = s->priv;

	if (!p)
		return;
	free(p->dir);
	free(p);
	s->priv = NULL;
}

/*
 * The directory and its parents, as mkdir -p makes them (the mode is
 * 0777 less the umask).  Created at open, so a sink that could never
 * write fails there, before the first frame.
 */
static int png_mkdir_p(const char *dir)
{
	char *d = strdup(dir), *p;
	struct stat st;
	int ret = 0;

	if (!d)
		return RDC_E_NOMEM;
	for (p = d + 1;; p++) {
		bool last = !*p;

		if (*p != '/' && !last)
			continue;
		*p = 0;
		if (mkdir(d, 0777) && errno != EEXIST) {
			ret = rdc_err_detail(RDC_E_FILE,
					     "png sink: cannot create '%s': %s",
					     d, strerror(errno));
			break;
		}
		if (last)
			break;
		*p = '/';
	}
	if (!ret && stat(dir, &st))
		ret = rdc_err_detail(RDC_E_FILE, "png sink: '%s': %s", dir,
				     strerror(errno));
	else if (!ret && !S_ISDIR(st.st_mode))
		ret = rdc_err_detail(RDC_E_FILE,
				     "png sink: '%s' is not a directory", dir);
	free(d);
	return ret;
}

/* A prefix becomes part of a file name: keep it to a safe alphabet. */
static bool png_prefix_ok(const char *v)
{
	size_t n = strlen(v);

	if (!n || n >= PNG_PREFIX_MAX)
		return false;
	return strspn(v, "abcdefghijklmnopqrstuvwxyz"
			 "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") == n &&
	       v[0] != '.';
}

static int png_open(rdc_sink *s, const char *args)
{
	struct png_sink *p = calloc(1, sizeof(*p));
	char *dup = strdup(args), *cur, *key, *val;
	int ret = 0;

	if (!p || !dup) {
		free(p);
		free(dup);
		return RDC_E_NOMEM;
	}
	s->priv = p;
	strcpy(p->prefix, "frame");
	cur = strchr(dup, ',');
	if (cur)
		*cur++ = '\0';
	if (!dup[0])
		ret = RDC_E_URI;
	if (!ret) {
		p->dir = strdup(dup);
		if (!p->dir)
			ret = RDC_E_NOMEM;
	}
	while (!ret && (ret = rdc_sink_opt_next(&cur, &key, &val)) > 0) {
		ret = 0;
		if (!strcmp(key, "every"))
			ret = rdc_sink_opt_u32(val, 0, UINT32_MAX, &p->every);
		else if (!strcmp(key, "prefix") && png_prefix_ok(val))
			strcpy(p->prefix, val);
		else
			ret = RDC_E_URI;
	}
	free(dup);
	if (ret == RDC_E_URI)
		rdc_err_detail(ret,
			       "png:%.200s: png:DIR[,every=N][,prefix=NAME] "
			       "expected (NAME: letters, digits, _-.)",
			       args);
	if (!ret)
		ret = png_mkdir_p(p->dir);
	if (ret)
		png_close(s);
	return ret;
}

const struct rdc_sink_ops rdc_sink_png_ops = {
	.kind = "png",
	.open = png_open,
	.frame = png_frame,
	.snapshot = png_snapshot,
	.close = png_close,
};
