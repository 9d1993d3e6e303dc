// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements of the drawing state and the later primitives: pens,
 * dashes, arcs, curves, transforms and viewports, filled polygons,
 * flood fill, patterns, triangles, the Z buffer and the colour key.
 * docs/rdl.md describes them.
 */
#include <stdlib.h>

#include "script.h"
#include "script_draw.h"

/* pen WIDTH [butt|round|square] [miter|round|bevel] */
int rdl_st_pen(struct rdl *r, uint32_t op)
{
	static const char *const caps[] = { "butt", "round", "square" };
	static const char *const joins[] = { "miter", "round", "bevel" };
	uint32_t cap = RDC_CAP_BUTT, join = RDC_JOIN_MITER, k;
	int64_t w;
	int ret = rdl_int(r, 1, 0, UINT8_MAX, &w);

	if (ret)
		return ret;
	if (r->ntok > 2) {
		for (k = 0; k < 3 && !rdl_word(r, 2, caps[k]); k++)
			;
		if (k == 3)
			return rdl_err(r, RDC_E_PARSE, "unknown cap '%.40s'",
				       r->tok[2].s);
		cap = k;
	}
	if (r->ntok > 3) {
		for (k = 0; k < 3 && !rdl_word(r, 3, joins[k]); k++)
			;
		if (k == 3)
			return rdl_err(r, RDC_E_PARSE, "unknown join '%.40s'",
				       r->tok[3].s);
		join = k;
	}
	return rdl_encoded(r, op, rdc_batch_pen(r->b, (uint32_t)w, cap, join));
}

/* dash PATTERN LENGTH [OFFSET] | dash off */
int rdl_st_dash(struct rdl *r, uint32_t op)
{
	uint32_t bits;
	int64_t len, off = 0;
	int ret;

	if (rdl_word(r, 1, "off")) {
		if (r->ntok != 2)
			return rdl_err(r, RDC_E_PARSE,
				       "dash off: no arguments");
		return rdl_encoded(r, op, rdc_batch_dash(r->b, 0, 0, 0));
	}
	if (r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE, "dash PATTERN LENGTH [OFFSET]");
	ret = rdl_u32(r, 1, &bits);
	if (!ret)
		ret = rdl_int(r, 2, 0, RDC_DASH_MAX_LEN, &len);
	if (!ret && r->ntok > 3)
		ret = rdl_int(r, 3, 0,
			      FIELD_GET(RDC_DASH_OFFSET, RDC_DASH_OFFSET),
			      &off);
	if (ret)
		return ret;
	return rdl_encoded(r, op,
			   rdc_batch_dash(r->b, bits, (uint32_t)len,
					  (uint32_t)off));
}

/* arc CX CY RX RY START END [pie|chord] */
int rdl_st_arc(struct rdl *r, uint32_t op)
{
	int c[2];
	uint32_t rx, ry, a0, a1, mode = RDC_ARC_OUTLINE;
	int ret = rdl_coords(r, 1, 2, c);

	if (!ret)
		ret = rdl_size(r, 3, &rx);
	if (!ret)
		ret = rdl_size(r, 4, &ry);
	if (!ret)
		ret = rdl_angle(r, 5, &a0);
	if (!ret)
		ret = rdl_angle(r, 6, &a1);
	if (ret)
		return ret;
	if (r->ntok > 7) {
		if (rdl_word(r, 7, "pie"))
			mode = RDC_ARC_PIE;
		else if (rdl_word(r, 7, "chord"))
			mode = RDC_ARC_CHORD;
		else
			return rdl_err(r, RDC_E_PARSE,
				       "arc mode '%.40s': pie or chord",
				       r->tok[7].s);
	}
	return rdl_encoded(
		r, op, rdc_batch_arc(r->b, c[0], c[1], rx, ry, a0, a1, mode));
}

/* bezier|hermite X0 Y0 ... [steps N]; bspline takes 4 or more points */
int rdl_st_curve(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 1;
	int64_t steps = 0;
	int *c;
	int ret;

	if (n >= 2 && rdl_word(r, r->ntok - 2, "steps")) {
		ret = rdl_int(r, r->ntok - 1, 1, RDC_CURVE_MAX_STEPS, &steps);
		if (ret)
			return ret;
		n -= 2;
	}
	if (n % 2 || n < 8 || (op != RDC_OP_BSPLINE && n != 8))
		return rdl_err(r, RDC_E_PARSE, "%s needs %s X Y pairs",
			       rdc_op_name(op),
			       op == RDC_OP_BSPLINE ? "4 or more" : "4");
	if (n / 2 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d points",
			       RDC_CMD_MAX_ARGS);
	c = malloc(n * sizeof(*c));
	if (!c)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_coords(r, 1, n, c);
	if (!ret) {
		if (op == RDC_OP_BEZIER)
			ret = rdc_batch_bezier(r->b, c, (uint32_t)steps);
		else if (op == RDC_OP_HERMITE)
			ret = rdc_batch_hermite(r->b, c, (uint32_t)steps);
		else
			ret = rdc_batch_bspline(r->b, c, n / 2,
						(uint32_t)steps);
		ret = rdl_encoded(r, op, ret);
	}
	free(c);
	return ret;
}

/* transform M00 M01 M02 M10 M11 M12 M20 M21 M22 | transform identity */
int rdl_st_transform(struct rdl *r, uint32_t op)
{
	int32_t m[9];
	int64_t v;

	if (rdl_word(r, 1, "identity") && r->ntok == 2)
		return rdl_encoded(r, op, rdc_batch_transform(r->b, NULL));
	if (r->ntok != 10)
		return rdl_err(r, RDC_E_PARSE,
			       "transform: 9 numbers or 'identity'");
	for (size_t i = 0; i < 9; i++) {
		int ret = rdl_fixed(r, 1 + i, RDL_FIX_ONE, INT32_MIN, INT32_MAX,
				    &v);

		if (ret)
			return ret;
		m[i] = (int32_t)v;
	}
	return rdl_encoded(r, op, rdc_batch_transform(r->b, m));
}

/* viewport WX0 WY0 WX1 WY1 X0 Y0 X1 Y1 */
int rdl_st_viewport(struct rdl *r, uint32_t op)
{
	int64_t w[4];
	int c[4], ret = 0;

	for (size_t i = 0; !ret && i < 4; i++)
		ret = rdl_fixed(r, 1 + i, RDL_FIX_ONE, INT32_MIN, INT32_MAX,
				&w[i]);
	if (!ret)
		ret = rdl_coords(r, 5, 4, c);
	if (ret)
		return ret;
	return rdl_encoded(r, op,
			   rdc_batch_viewport(r->b, (int32_t)w[0],
					      (int32_t)w[1], (int32_t)w[2],
					      (int32_t)w[3], c[0], c[1], c[2],
					      c[3]));
}

/* fill-polygon [nonzero] X0 Y0 X1 Y1 X2 Y2 ... */
int rdl_st_fill_polygon(struct rdl *r, uint32_t op)
{
	size_t first = rdl_word(r, 1, "nonzero") ? 2 : 1;
	size_t n = r->ntok - first;
	int *c;
	int ret;

	if (n % 2 || n < 6)
		return rdl_err(r, RDC_E_PARSE,
			       "fill-polygon needs 3 or more X Y pairs");
	if (n / 2 > RDC_CMD_MAX_ARGS)
		return rdl_err(r, RDC_E_PARSE, "more than %d points",
			       RDC_CMD_MAX_ARGS);
	c = malloc(n * sizeof(*c));
	if (!c)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_coords(r, first, n, c);
	if (!ret)
		ret = rdl_encoded(r, op,
				  rdc_batch_fill_polygon(r->b, c, n / 2,
							 first == 2));
	free(c);
	return ret;
}

/* flood X Y [8] [boundary COLOUR] */
int rdl_st_flood(struct rdl *r, uint32_t op)
{
	uint32_t flags = 0, boundary = 0;
	size_t i = 3;
	int xy[2];
	int ret = rdl_coords(r, 1, 2, xy);

	if (ret)
		return ret;
	if (i < r->ntok && rdl_word(r, i, "8")) {
		flags |= RDC_FLOOD_8;
		i++;
	}
	if (i < r->ntok && rdl_word(r, i, "boundary")) {
		flags |= RDC_FLOOD_BOUNDARY;
		ret = rdl_colour(r, i + 1, rdl_dst_format(r), &boundary);
		if (ret)
			return ret;
		i += 2;
	}
	if (i != r->ntok)
		return rdl_err(r, RDC_E_PARSE,
			       "flood X Y [8] [boundary COLOUR]");
	return rdl_encoded(
		r, op, rdc_batch_flood(r->b, xy[0], xy[1], flags, boundary));
}

/* pattern none | mono HEX16 [transparent] | color C0 ... C63 */
int rdl_st_pattern(struct rdl *r, uint32_t op)
{
	uint32_t px[64];
	uint8_t rows[8] = { 0 };
	const char *h;
	size_t k;

	if (rdl_word(r, 1, "none") && r->ntok == 2)
		return rdl_encoded(r, op, rdc_batch_pattern_none(r->b));
	if (rdl_word(r, 1, "mono") && (r->ntok == 3 || r->ntok == 4)) {
		if (r->ntok == 4 && !rdl_word(r, 3, "transparent"))
			return rdl_err(r, RDC_E_PARSE,
				       "pattern mono HEX16 [transparent]");
		h = r->tok[2].s;
		if (h[0] == '0' && (h[1] == 'x' || h[1] == 'X'))
			h += 2;
		for (k = 0; k < 16; k++) {
			int d = rdl_hex(h[k]);

			if (d < 0)
				break;
			rows[k / 2] = (uint8_t)(rows[k / 2] << 4 | d);
		}
		if (k != 16 || h[16])
			return rdl_err(r, RDC_E_PARSE,
				       "pattern mono: 16 hex digits, row 0 "
				       "first");
		return rdl_encoded(r, op,
				   rdc_batch_pattern_mono(r->b, rows,
							  r->ntok == 4));
	}
	if (rdl_word(r, 1, "color") && r->ntok == 2 + 64) {
		for (k = 0; k < 64; k++) {
			int ret =
				rdl_colour(r, 2 + k, rdl_dst_format(r), &px[k]);

			if (ret)
				return ret;
		}
		return rdl_encoded(r, op, rdc_batch_pattern_color(r->b, px));
	}
	return rdl_err(r, RDC_E_PARSE,
		       "pattern none | mono HEX16 [transparent] | "
		       "color C0 ... C63");
}

/* triangle [gouraud] X Y COLOUR Z  X Y COLOUR Z  X Y COLOUR Z */
int rdl_st_triangle(struct rdl *r, uint32_t op)
{
	size_t first = rdl_word(r, 1, "gouraud") ? 2 : 1;
	uint32_t colour[3], z[3];
	int xy[6];

	if (r->ntok - first != 12)
		return rdl_err(r, RDC_E_PARSE,
			       "triangle [gouraud] then X Y COLOUR Z three "
			       "times");
	for (size_t v = 0; v < 3; v++) {
		size_t i = first + 4 * v;
		int64_t zv;
		int ret = rdl_coords(r, i, 2, &xy[2 * v]);

		if (!ret)
			ret = rdl_colour(r, i + 2, rdl_dst_format(r),
					 &colour[v]);
		if (!ret)
			ret = rdl_int(r, i + 3, 0, UINT16_MAX, &zv);
		if (ret)
			return ret;
		z[v] = (uint32_t)zv;
	}
	return rdl_encoded(r, op,
			   rdc_batch_triangle(r->b, xy, colour, z, first == 2));
}

/* zbuf BASE STRIDE [test] [write] | zbuf off */
int rdl_st_zbuf(struct rdl *r, uint32_t op)
{
	uint32_t base, stride, flags = 0;
	int ret;

	if (rdl_word(r, 1, "off")) {
		if (r->ntok != 2)
			return rdl_err(r, RDC_E_PARSE,
				       "zbuf off: no arguments");
		return rdl_encoded(r, op, rdc_batch_zbuf_off(r->b));
	}
	if (r->ntok < 3)
		return rdl_err(r, RDC_E_PARSE,
			       "zbuf BASE STRIDE [test] [write] | zbuf off");
	ret = rdl_u32(r, 1, &base);
	if (!ret)
		ret = rdl_u32(r, 2, &stride);
	if (ret)
		return ret;
	for (size_t i = 3; i < r->ntok; i++) {
		if (rdl_word(r, i, "test"))
			flags |= RDC_Z_TEST;
		else if (rdl_word(r, i, "write"))
			flags |= RDC_Z_WRITE;
		else
			return rdl_err(r, RDC_E_PARSE,
				       "zbuf: '%.40s' is not test or write",
				       r->tok[i].s);
	}
	return rdl_encoded(r, op, rdc_batch_zbuf(r->b, base, stride, flags));
}

/* clear-z VALUE */
int rdl_st_clear_z(struct rdl *r, uint32_t op)
{
	int64_t v;
	int ret = rdl_int(r, 1, 0, UINT16_MAX, &v);

	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_clear_z(r->b, (uint32_t)v));
}

/* colorkey COLOUR | colorkey off */
int rdl_st_colorkey(struct rdl *r, uint32_t op)
{
	uint32_t key;
	int ret;

	if (rdl_word(r, 1, "off"))
		return rdl_encoded(r, op, rdc_batch_colorkey(r->b, 0, 0));
	ret = rdl_colour(r, 1, rdl_dst_format(r), &key);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_colorkey(r->b, key, 1));
}
