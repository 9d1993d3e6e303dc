// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/* .rdl tokens (quotes, escapes, comments) and the values they stand for. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "script.h"

static bool rdl_is_space(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

int rdl_hex(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

/* "#rrggbb" exactly, as opposed to a comment. */
static bool rdl_is_colour(const char *p)
{
	for (int i = 1; i <= 6; i++)
		if (rdl_hex(p[i]) < 0)
			return false;
	return !p[7] || rdl_is_space(p[7]);
}

static int rdl_push_tok(struct rdl *r, const char *s, size_t len, bool quoted)
{
	if (r->ntok == r->tok_cap) {
		size_t cap = r->tok_cap ? r->tok_cap * 2 : 32;
		struct rdl_tok *t = realloc(r->tok, cap * sizeof(*t));

		if (!t)
			return rdl_err(r, RDC_E_NOMEM, "out of memory");
		r->tok = t;
		r->tok_cap = cap;
	}
	r->tok[r->ntok++] = (struct rdl_tok){ s, len, quoted };
	return 0;
}

/* The escape after a backslash at *p: one byte to *out, both advance. */
static int rdl_escape(struct rdl *r, char **p, char **out)
{
	static const char from[] = "ntr0\\\"", to[] = "\n\t\r\0\\\"";
	const char *e;
	int hi, lo;

	if (**p == 'x') {
		hi = rdl_hex((*p)[1]);
		lo = hi < 0 ? -1 : rdl_hex((*p)[2]);
		if (lo < 0)
			return rdl_err(r, RDC_E_PARSE,
				       "bad \\x escape: two hex digits needed");
		*(*out)++ = (char)(hi << 4 | lo);
		*p += 3;
		return 0;
	}
	e = **p ? strchr(from, **p) : NULL;
	if (!e)
		return rdl_err(r, RDC_E_PARSE, "unknown escape in string");
	*(*out)++ = to[e - from];
	(*p)++;
	return 0;
}

/*
 * Split r->buf into tokens in place: words end at white space (a NUL is
 * written there), quoted strings are unescaped where they stand (the
 * result is never longer than the source).
 */
int rdl_tokenize(struct rdl *r)
{
	char *p = r->buf;
	int ret;

	r->ntok = 0;
	for (;;) {
		while (rdl_is_space(*p))
			p++;
		/* '#' starts a comment at the start of a statement or before
		 * a blank; after a keyword, '#' and a word is a colour. */
		if (!*p ||
		    (*p == '#' && (!r->ntok || !p[1] || rdl_is_space(p[1]))))
			return 0;
		if (*p == '#' && !rdl_is_colour(p)) {
			size_t n = 1;

			while (p[n] && !rdl_is_space(p[n]))
				n++;
			return rdl_err_at(
				r, p, RDC_E_PARSE,
				"bad colour '%.*s': #rrggbb takes six "
				"hex digits (a comment needs a blank "
				"after '#')",
				(int)RDC_MIN(n, 40), p);
		}
		if (*p == '"') {
			char *out = ++p, *start = out;

			for (;;) {
				if (!*p)
					return rdl_err(r, RDC_E_PARSE,
						       "unterminated string");
				if (*p == '"')
					break;
				if (*p != '\\') {
					*out++ = *p++;
					continue;
				}
				p++;
				ret = rdl_escape(r, &p, &out);
				if (ret)
					return ret;
			}
			p++; /* closing quote */
			if (*p && !rdl_is_space(*p))
				return rdl_err(r, RDC_E_PARSE,
					       "text after closing quote");
			ret = rdl_push_tok(r, start, (size_t)(out - start),
					   true);
			if (ret)
				return ret;
			*out = 0;
			continue;
		}
		{
			char *start = p;

			while (*p && !rdl_is_space(*p) && *p != '"')
				p++;
			if (*p == '"')
				return rdl_err(r, RDC_E_PARSE,
					       "quote inside a word");
			ret = rdl_push_tok(r, start, (size_t)(p - start),
					   false);
			if (ret)
				return ret;
			if (*p)
				*p++ = 0;
		}
	}
}

/* Integer in [lo, hi]: decimal or 0x hex, optional sign. */
int rdl_int(struct rdl *r, size_t i, int64_t lo, int64_t hi, int64_t *out)
{
	const char *s, *what = "number";
	bool neg = false;
	uint64_t v = 0;
	int base = 10, digits = 0;

	if (i >= r->ntok)
		return rdl_err(r, RDC_E_PARSE, "missing argument %zu", i);
	s = r->tok[i].s;
	if (r->tok[i].quoted)
		goto bad;
	if (*s == '-' || *s == '+')
		neg = *s++ == '-';
	if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
		base = 16;
		s += 2;
	}
	for (; *s; s++, digits++) {
		int d = rdl_hex(*s);

		if (d < 0 || d >= base)
			goto bad;
		v = v * (uint64_t)base + (uint64_t)d;
		if (v > ((uint64_t)1 << 40))
			goto range;
	}
	if (!digits)
		goto bad;
	*out = neg ? -(int64_t)v : (int64_t)v;
	if (*out < lo || *out > hi)
		goto range;
	return 0;
bad:
	return rdl_err(r, RDC_E_PARSE, "argument %zu: '%.40s' is not a %s", i,
		       r->tok[i].s, what);
range:
	return rdl_err(r, RDC_E_PARSE,
		       "argument %zu: '%.40s' out of range [%lld, %lld]", i,
		       r->tok[i].s, (long long)lo, (long long)hi);
}

int rdl_u32(struct rdl *r, size_t i, uint32_t *out)
{
	int64_t v;
	int ret = rdl_int(r, i, INT32_MIN, UINT32_MAX, &v);

	*out = (uint32_t)v; /* negative numbers wrap: 0xffffffff == -1 */
	return ret;
}

/* Coordinates are signed 16-bit on the wire. */
static int rdl_coord(struct rdl *r, size_t i, int *out)
{
	int64_t v;
	int ret = rdl_int(r, i, INT16_MIN, INT16_MAX, &v);

	*out = (int)v;
	return ret;
}

/* Sizes and radii are unsigned 16-bit on the wire. */
int rdl_size(struct rdl *r, size_t i, uint32_t *out)
{
	int64_t v;
	int ret = rdl_int(r, i, 0, UINT16_MAX, &v);

	*out = (uint32_t)v;
	return ret;
}

int rdl_coords(struct rdl *r, size_t first, size_t n, int *out)
{
	for (size_t k = 0; k < n; k++) {
		int ret = rdl_coord(r, first + k, &out[k]);

		if (ret)
			return ret;
	}
	return 0;
}

/* 8-bit-per-channel RGB to a pixel of an RGB format, rounding. */
uint32_t rdl_rgb_to_pixel(uint32_t rgb, uint32_t fmt)
{
	uint32_t red = (rgb >> 16) & 0xff, green = (rgb >> 8) & 0xff;
	uint32_t blue = rgb & 0xff;

	if (fmt == RDC_FMT_RGB565)
		return ((red * 31 + 127) / 255) << 11 |
		       ((green * 63 + 127) / 255) << 5 |
		       ((blue * 31 + 127) / 255);
	return rgb & 0xffffff;
}

/* A colour: a raw pixel value, or #rrggbb in an RGB format `fmt`. */
int rdl_colour(struct rdl *r, size_t i, uint32_t fmt, uint32_t *out)
{
	const char *s;
	uint32_t rgb = 0;

	if (i >= r->ntok)
		return rdl_err(r, RDC_E_PARSE, "missing colour");
	s = r->tok[i].s;
	if (s[0] != '#' || r->tok[i].quoted)
		return rdl_u32(r, i, out);
	if (r->tok[i].len != 7 || !rdl_is_colour(s))
		return rdl_err(r, RDC_E_PARSE, "bad colour '%.40s'", s);
	if (fmt >= RDC_FMT_COUNT || rdc_format_indexed(fmt))
		return rdl_err(r, RDC_E_PARSE,
			       "#rrggbb needs an RGB destination; indexed "
			       "formats take a CLUT index");
	for (int k = 1; k <= 6; k++)
		rgb = rgb << 4 | (uint32_t)rdl_hex(s[k]);
	*out = rdl_rgb_to_pixel(rgb, fmt);
	return 0;
}

/* A CLUT entry: 0x00RRGGBB or #rrggbb. */
int rdl_rgb(struct rdl *r, size_t i, uint32_t *out)
{
	int ret = rdl_colour(r, i, RDC_FMT_XRGB8888, out);

	if (!ret && *out > 0xffffff)
		return rdl_err(r, RDC_E_PARSE, "CLUT colour above 0xffffff");
	return ret;
}

int rdl_format(struct rdl *r, size_t i, uint32_t *out)
{
	for (uint32_t f = 0; f < RDC_FMT_COUNT; f++) {
		if (!strcasecmp(r->tok[i].s, rdl_fmt_names[f])) {
			*out = f;
			return 0;
		}
	}
	return rdl_err(r, RDC_E_PARSE, "unknown format '%.40s'", r->tok[i].s);
}

int rdl_reg(struct rdl *r, size_t i, uint32_t *out)
{
	int64_t v;

	if (!rdc_reg_by_name(r->tok[i].s, out))
		return 0;
	if (rdl_hex(r->tok[i].s[0]) >= 0 &&
	    !rdl_int(r, i, 0, RDC_REG_WINDOW - 4, &v)) {
		*out = (uint32_t)v;
		return 0;
	}
	return rdl_err(r, RDC_E_PARSE, "unknown register '%.40s'", r->tok[i].s);
}

bool rdl_word(struct rdl *r, size_t i, const char *w)
{
	return i < r->ntok && !r->tok[i].quoted && !strcmp(r->tok[i].s, w);
}

/*
 * A decimal number with optional sign and fraction, times `scale`, rounded
 * to nearest (halves away from zero), in [lo, hi].  Exact: no floating
 * point, so "0.5" is 32768 in 15.16 on every host.
 */
int rdl_fixed(struct rdl *r, size_t i, int64_t scale, int64_t lo, int64_t hi,
	      int64_t *out)
{
	const char *s;
	bool neg = false;
	uint64_t ip = 0, fp = 0, den = 1;
	int digits = 0;
	int64_t v;

	if (i >= r->ntok)
		return rdl_err(r, RDC_E_PARSE, "missing argument %zu", i);
	s = r->tok[i].s;
	if (r->tok[i].quoted)
		goto bad;
	if (*s == '-' || *s == '+')
		neg = *s++ == '-';
	for (; *s >= '0' && *s <= '9'; s++, digits++) {
		ip = ip * 10 + (uint64_t)(*s - '0');
		if (ip > ((uint64_t)1 << 32))
			goto range;
	}
	if (*s == '.') {
		for (s++; *s >= '0' && *s <= '9'; s++, digits++) {
			/* digits past the ninth cannot move the result */
			if (den < 1000000000u) {
				fp = fp * 10 + (uint64_t)(*s - '0');
				den *= 10;
			}
		}
	}
	if (*s || !digits)
		goto bad;
	v = (int64_t)(ip * (uint64_t)scale +
		      (fp * (uint64_t)scale * 2 + den) / (2 * den));
	*out = neg ? -v : v;
	if (*out < lo || *out > hi)
		goto range;
	return 0;
bad:
	return rdl_err(r, RDC_E_PARSE, "argument %zu: '%.40s' is not a number",
		       i, r->tok[i].s);
range:
	return rdl_err(r, RDC_E_PARSE, "argument %zu: '%.40s' out of range", i,
		       r->tok[i].s);
}

/* Degrees (decimals allowed) to 1/65536 turn, modulo a turn. */
int rdl_angle(struct rdl *r, size_t i, uint32_t *out)
{
	int64_t v;
	/* 65536 / 360 = 8192 / 45: scale by 8192, then divide by 45 */
	int ret = rdl_fixed(r, i, 8192, -((int64_t)1 << 40), (int64_t)1 << 40,
			    &v);
	int64_t q;

	if (ret)
		return ret;
	q = v >= 0 ? (v + 22) / 45 : -((-v + 22) / 45);
	*out = (uint32_t)(((q % 65536) + 65536) % 65536);
	return 0;
}
