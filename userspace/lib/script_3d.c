// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * .rdl statements of the 3D commands (matrices and their stack, the view,
 * illumination, MESH, PATCH, BEZIER3) and the host statements that put
 * vertex and index buffers into VRAM.  docs/rdl.md describes them.
 * Decimal numbers become 15.16 exactly (rdl_fixed), as for `transform`.
 */
#include <stdlib.h>
#include <string.h>

#include "script.h"
#include "script_3d.h"

#define RDL_FIX_MIN INT32_MIN
#define RDL_FIX_MAX INT32_MAX

/* n decimal numbers from token `first` on, as 15.16 words */
static int rdl_fix_words(struct rdl *r, size_t first, size_t n, uint32_t *w)
{
	for (size_t i = 0; i < n; i++) {
		int64_t v;
		int ret = rdl_fixed(r, first + i, RDL_FIX_ONE, RDL_FIX_MIN,
				    RDL_FIX_MAX, &v);

		if (ret)
			return ret;
		w[i] = (uint32_t)(int32_t)v;
	}
	return 0;
}

/* matrix identity | matrix M00 .. M23 (12); matrix-mult M00 .. M23 */
int rdl_st_matrix(struct rdl *r, uint32_t op)
{
	uint32_t m[12];
	int ret;

	if (op == RDC_OP_MATRIX_LOAD && r->ntok == 2 &&
	    rdl_word(r, 1, "identity"))
		return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, NULL, 0));
	if (r->ntok != 13)
		return rdl_err(r, RDC_E_PARSE,
			       "%s: 12 numbers (rows 0..2 of "
			       "the 4x4)%s",
			       r->tok[0].s,
			       op == RDC_OP_MATRIX_LOAD ? " or 'identity'" :
							  "");
	ret = rdl_fix_words(r, 1, 12, m);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, m, 12));
}

/* translate X Y Z | scale X Y Z | scale S */
int rdl_st_vec3(struct rdl *r, uint32_t op)
{
	uint32_t v[3];
	int ret;

	if (op == RDC_OP_SCALE && r->ntok == 2) {
		ret = rdl_fix_words(r, 1, 1, v);
		v[1] = v[0];
		v[2] = v[0];
	} else if (r->ntok == 4) {
		ret = rdl_fix_words(r, 1, 3, v);
	} else {
		return rdl_err(r, RDC_E_PARSE, "%s: X Y Z%s", r->tok[0].s,
			       op == RDC_OP_SCALE ? " or one factor" : "");
	}
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, v, 3));
}

/* rotate x|y|z DEGREES */
int rdl_st_rotate(struct rdl *r, uint32_t op)
{
	static const char *const axes[] = { "x", "y", "z" };
	uint32_t a, axis;
	int ret;

	for (axis = 0; axis < 3; axis++)
		if (rdl_word(r, 1, axes[axis]))
			break;
	if (axis == 3)
		return rdl_err(r, RDC_E_PARSE, "rotate: axis x, y or z");
	ret = rdl_angle(r, 2, &a);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, axis, &a, 1));
}

/*
 * view parallel|perspective vrp X Y Z vpn X Y Z vup X Y Z prp U V N
 *      window UMIN UMAX VMIN VMAX front F back B
 */
int rdl_st_view(struct rdl *r, uint32_t op)
{
	static const struct {
		const char *name;
		size_t n;
	} part[] = { { "vrp", 3 }, { "vpn", 3 },    { "vup", 3 },
		     { "prp", 3 }, { "window", 4 }, { "front", 1 },
		     { "back", 1 } };
	uint32_t a[18], fl;
	size_t t = 2, w = 0;
	int ret;

	if (rdl_word(r, 1, "parallel"))
		fl = 0;
	else if (rdl_word(r, 1, "perspective"))
		fl = RDC_VIEW_PERSPECTIVE;
	else
		return rdl_err(r, RDC_E_PARSE,
			       "view: 'parallel' or 'perspective' first");
	for (size_t k = 0; k < RDC_ARRAY_SIZE(part); k++) {
		if (!rdl_word(r, t, part[k].name))
			return rdl_err(r, RDC_E_PARSE,
				       "view: '%s' expected "
				       "as argument %zu",
				       part[k].name, t);
		ret = rdl_fix_words(r, t + 1, part[k].n, a + w);
		if (ret)
			return ret;
		t += 1 + part[k].n;
		w += part[k].n;
	}
	if (t != r->ntok)
		return rdl_err(r, RDC_E_PARSE, "view: words after 'back B'");
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, fl, a, 18));
}

/* viewport3 X0 Y0 X1 Y1 */
int rdl_st_viewport3(struct rdl *r, uint32_t op)
{
	uint32_t a[2];
	int c[4];
	int ret = rdl_coords(r, 1, 4, c);

	if (ret)
		return ret;
	a[0] = RDC_XY(c[0], c[1]);
	a[1] = RDC_XY(c[2], c[3]);
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, 2));
}

/* light N COLOUR DX DY DZ | light N off */
int rdl_st_light(struct rdl *r, uint32_t op)
{
	int64_t n;
	uint32_t a[4];
	int ret = rdl_int(r, 1, 0, RDC_LIGHTS - 1, &n);

	if (ret)
		return ret;
	if (r->ntok == 3 && rdl_word(r, 2, "off"))
		return rdl_encoded(
			r, op, rdc_batch_cmd(r->b, op, (uint32_t)n, NULL, 0));
	if (r->ntok != 6)
		return rdl_err(r, RDC_E_PARSE,
			       "light: N COLOUR DX DY DZ, or N off");
	ret = rdl_rgb(r, 2, &a[0]);
	if (!ret)
		ret = rdl_fix_words(r, 3, 3, a + 1);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, (uint32_t)n, a, 4));
}

/* ambient COLOUR */
int rdl_st_ambient(struct rdl *r, uint32_t op)
{
	uint32_t c;
	int ret = rdl_rgb(r, 1, &c);

	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, &c, 1));
}

/* material AMBIENT DIFFUSE SPECULAR SHININESS */
int rdl_st_material(struct rdl *r, uint32_t op)
{
	uint32_t a[4];
	int64_t s;
	int ret = 0;

	for (size_t i = 0; !ret && i < 3; i++)
		ret = rdl_rgb(r, 1 + i, &a[i]);
	if (!ret)
		ret = rdl_int(r, 4, 1, 255, &s);
	if (ret)
		return ret;
	a[3] = (uint32_t)s;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, 4));
}

/*
 * The RDC_MESH_* words from token i while they are flags; *next after.
 * mesh: MESH's own words too (normals, scanline, bounds), else PATCH's.
 */
static int rdl_mesh_flags(struct rdl *r, size_t i, bool mesh, uint32_t *fl,
			  size_t *next)
{
	static const struct {
		const char *name;
		uint32_t bit;
	} f[] = { { "normals", RDC_MESH_NORMALS },
		  { "wire", RDC_MESH_WIRE },
		  { "cull", RDC_MESH_CULL },
		  { "lit", RDC_MESH_LIT },
		  { "gouraud", RDC_MESH_GOURAUD },
		  { "two-sided", RDC_MESH_TWO_SIDED },
		  { "sort", RDC_MESH_SORT },
		  { "scanline", RDC_MESH_SCANLINE },
		  { "bounds", RDC_MESH_BOUNDS } };
	size_t end = RDC_ARRAY_SIZE(f) - (mesh ? 0 : 2);

	*fl = 0;
	for (; i < r->ntok; i++) {
		size_t k;

		for (k = mesh ? 0 : 1; k < end; k++)
			if (rdl_word(r, i, f[k].name))
				break;
		if (k == end)
			break;
		*fl |= f[k].bit;
	}
	*next = i;
	return 0;
}

/*
 * mesh VBASE VCOUNT IBASE TCOUNT [normals] [wire] [cull] [lit] [gouraud]
 *      [two-sided] [sort] [scanline] [bounds]
 */
int rdl_st_mesh(struct rdl *r, uint32_t op)
{
	uint32_t a[4], fl;
	size_t next;
	int ret = 0;

	for (size_t i = 0; !ret && i < 4; i++)
		ret = rdl_u32(r, 1 + i, &a[i]);
	if (!ret)
		ret = rdl_mesh_flags(r, 5, true, &fl, &next);
	if (ret)
		return ret;
	if (next != r->ntok)
		return rdl_err(r, RDC_E_PARSE,
			       "mesh: '%.40s' is not normals, wire, cull, lit, "
			       "gouraud, two-sided, sort, scanline or bounds",
			       r->tok[next].s);
	/* bounds is a bit of the vcount word, not a flag */
	a[1] |= fl & RDC_MESH_BOUNDS;
	fl &= ~RDC_MESH_BOUNDS;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, fl, a, 4));
}

/* patch STEPS [wire] [cull] [lit] [gouraud] [two-sided] [sort] 16 x X Y Z */
int rdl_st_patch(struct rdl *r, uint32_t op)
{
	uint32_t a[49], fl;
	int64_t n;
	size_t next;
	int ret = rdl_int(r, 1, 1, RDC_PATCH_MAX_STEPS, &n);

	if (!ret)
		ret = rdl_mesh_flags(r, 2, false, &fl, &next);
	if (ret)
		return ret;
	if (r->ntok - next != 48)
		return rdl_err(r, RDC_E_PARSE,
			       "patch: 16 control points X Y Z "
			       "(48 numbers) after the steps and flags");
	ret = rdl_fix_words(r, next, 48, a + 1);
	if (ret)
		return ret;
	a[0] = fl | (uint32_t)n << 8;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, 0, a, 49));
}

/* bezier3 X0 Y0 Z0 .. X3 Y3 Z3 [steps N] */
int rdl_st_bezier3(struct rdl *r, uint32_t op)
{
	uint32_t a[12];
	int64_t n = 0;
	int ret;

	if (r->ntok == 15) {
		if (!rdl_word(r, 13, "steps"))
			return rdl_err(r, RDC_E_PARSE,
				       "bezier3: 'steps N' after the points");
		ret = rdl_int(r, 14, 1, RDC_CURVE_MAX_STEPS, &n);
		if (ret)
			return ret;
	} else if (r->ntok != 13) {
		return rdl_err(r, RDC_E_PARSE,
			       "bezier3: 4 points X Y Z [steps N]");
	}
	ret = rdl_fix_words(r, 1, 12, a);
	if (ret)
		return ret;
	return rdl_encoded(r, op, rdc_batch_cmd(r->b, op, (uint32_t)n, a, 12));
}

/* bspline3 X0 Y0 Z0 X1 Y1 Z1 .. (4 or more points) [steps N] */
int rdl_st_bspline3(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 1;
	uint32_t *a;
	int64_t steps = 0;
	int ret;

	if (n >= 2 && rdl_word(r, r->ntok - 2, "steps")) {
		ret = rdl_int(r, r->ntok - 1, 1, RDC_CURVE_MAX_STEPS, &steps);
		if (ret)
			return ret;
		n -= 2;
	}
	if (n % 3 || n < 12)
		return rdl_err(r, RDC_E_PARSE,
			       "bspline3: 4 or more points X Y Z [steps N]");
	if (n / 3 > RDC_BSPLINE3_MAX_POINTS)
		return rdl_err(r, RDC_E_PARSE, "bspline3: more than %d points",
			       (int)RDC_BSPLINE3_MAX_POINTS);
	a = malloc(n * sizeof(*a));
	if (!a)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	ret = rdl_fix_words(r, 1, n, a);
	if (!ret)
		ret = rdl_encoded(r, op,
				  rdc_batch_cmd(r->b, op, (uint32_t)steps, a,
						(uint32_t)n));
	free(a);
	return ret;
}

/* vertices ADDR X Y Z ...: 15.16 words into VRAM at ADDR */
int rdl_st_vertices(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 2;
	uint32_t addr, v = 0;
	uint8_t *b;
	int ret = rdl_u32(r, 1, &addr);

	(void)op;
	if (ret)
		return ret;
	b = malloc(n ? 4 * n : 1);
	if (!b)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	for (size_t i = 0; !ret && i < n; i++) {
		ret = rdl_fix_words(r, 2 + i, 1, &v);
		for (int k = 0; k < 4; k++)
			b[4 * i + k] = (uint8_t)(v >> (8 * k));
	}
	if (!ret) {
		ret = rdc_vram_write(r->dev, addr, b, 4 * n);
		if (ret)
			ret = rdl_fail(r, "vertices", ret);
	}
	free(b);
	return ret;
}

/* indices ADDR I0 I1 ...: 16-bit little-endian indices into VRAM at ADDR */
int rdl_st_indices(struct rdl *r, uint32_t op)
{
	size_t n = r->ntok - 2;
	uint32_t addr;
	uint8_t *b;
	int ret = rdl_u32(r, 1, &addr);

	(void)op;
	if (ret)
		return ret;
	b = malloc(n ? 2 * n : 1);
	if (!b)
		return rdl_err(r, RDC_E_NOMEM, "out of memory");
	for (size_t i = 0; !ret && i < n; i++) {
		int64_t v;

		ret = rdl_int(r, 2 + i, 0, 0xffff, &v);
		b[2 * i] = (uint8_t)v;
		b[2 * i + 1] = (uint8_t)(v >> 8);
	}
	if (!ret) {
		ret = rdc_vram_write(r->dev, addr, b, 2 * n);
		if (ret)
			ret = rdl_fail(r, "indices", ret);
	}
	free(b);
	return ret;
}

/*
 * spin ADDR: enter the display list at ADDR (JUMP from the FIFO) and go on
 * at once, without waiting for the DP: for a list that loops for ever
 * (an animation), as the last statement of a script.
 */
int rdl_st_spin(struct rdl *r, uint32_t op)
{
	uint32_t addr;
	int ret = rdl_u32(r, 1, &addr);

	(void)op;
	if (ret)
		return ret;
	ret = rdc_batch_jump(r->b, addr);
	if (!ret)
		ret = rdc_batch_submit(r->dev, r->b);
	return ret ? rdl_fail(r, "spin", ret) : 0;
}
