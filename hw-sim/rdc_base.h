/* SPDX-License-Identifier: GPL-2.0-only OR LGPL-2.1-or-later */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
/*
 * The portable core's base: its view of its host (called rdc_base.h, not
 * a "port" header, since the DP port is the display processor's access to
 * the chip, rdc_port_* in hw.h).  hw-sim/ and firmware-model/ build
 * in three places: user space, the Linux kernel (Kbuild) and freestanding
 * (an MCU, or `make freestanding`).  This header is the only place that
 * knows which; the core includes nothing else from its environment.
 *
 * Only compiler-provided headers are used outside the kernel (stdint.h,
 * stddef.h, stdbool.h are part of a freestanding C implementation).
 * memcpy/memset/memmove map to the compiler builtins, which the kernel,
 * libc or an MCU's runtime resolve.
 */
#ifndef RDC_BASE_H
#define RDC_BASE_H

#ifdef __KERNEL__
#include <linux/types.h>
#include <linux/string.h>
#include <linux/bits.h>
#include <linux/bitfield.h>
#include <linux/limits.h>
/* The kernel spells the <stdint.h> limits U64_MAX and so on. */
#ifndef UINT64_MAX
#define UINT64_MAX U64_MAX
#endif
#else
#include <stdint.h>
#include <stddef.h>
#include <stdbool.h>
#endif

#define rdc_memcpy(d, s, n)  __builtin_memcpy((d), (s), (n))
#define rdc_memmove(d, s, n) __builtin_memmove((d), (s), (n))
#define rdc_memset(d, c, n)  __builtin_memset((d), (c), (n))

/*
 * Hide a value from the optimiser (the kernel's OPTIMIZER_HIDE_VAR): a
 * length it cannot bound keeps a memcpy a library call instead of an
 * inline expansion that is slower for rows of a few hundred bytes.
 */
#ifdef __KERNEL__
#define rdc_hide_var(v) OPTIMIZER_HIDE_VAR(v)
#else
#define rdc_hide_var(v) __asm__("" : "+r"(v))
#endif

/* RDC_ASAN: built with AddressSanitizer (GCC's word, then clang's) */
#if defined(__SANITIZE_ADDRESS__)
#define RDC_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RDC_ASAN 1
#endif
#endif

/* Inlining decisions the hot paths make on purpose. */
#ifdef __KERNEL__
#define rdc_noinline	  noinline
#define rdc_always_inline __always_inline
#else
#define rdc_noinline	  __attribute__((__noinline__))
#define rdc_always_inline inline __attribute__((__always_inline__))
#endif

/*
 * Stores that pass the CPU's caches by, for what is written once for
 * others to read later (scanout's frames), so that the caches keep what
 * the chip will touch again (VRAM).  x86-64 outside the kernel (which
 * keeps vector registers to itself): MOVNTDQ, 16 aligned bytes a store
 * (AddressSanitizer does not see these; their bounds are the mode's,
 * checked when it is set).  Elsewhere RDC_STREAM is 0 and callers store
 * plainly.  Streamed stores are weakly ordered: rdc_stream_fence() puts
 * them before every store after it (a frame is fenced before anyone is
 * given it).
 */
#if defined(__x86_64__) && !defined(__KERNEL__)
#define RDC_STREAM 1
typedef uint32_t rdc_u32x4 __attribute__((__vector_size__(16), __may_alias__));

static inline void rdc_stream16(void *p, rdc_u32x4 v)
{
	__asm__("movntdq %1, %0" : "=m"(*(rdc_u32x4 *)p) : "x"(v));
}

static inline void rdc_stream_fence(void)
{
	__asm__ __volatile__("sfence" : : : "memory");
}
#else
#define RDC_STREAM 0
static inline void rdc_stream_fence(void)
{
}
#endif

#define RDC_MIN(a, b)	  ((a) < (b) ? (a) : (b))
#define RDC_MAX(a, b)	  ((a) > (b) ? (a) : (b))
#define RDC_ARRAY_SIZE(a) (sizeof(a) / sizeof((a)[0]))

/* Little-endian loads and stores on byte pointers (VRAM is little-endian). */
static inline uint16_t rdc_ld16(const uint8_t *p)
{
	return (uint16_t)(p[0] | (p[1] << 8));
}

static inline uint32_t rdc_ld24(const uint8_t *p)
{
	return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16);
}

static inline uint32_t rdc_ld32(const uint8_t *p)
{
	return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
	       ((uint32_t)p[3] << 24);
}

static inline void rdc_st16(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static inline void rdc_st24(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
}

static inline void rdc_st32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/*
 * The pixel of `bpp` bits (1, 2, 4, 8, 16, 24 or 32) at bit offset `bit`
 * of p, laid out as the RDC-1's VRAM holds it: sub-byte pixels leftmost
 * in the most significant bits, wider ones little-endian.  Every reader
 * and writer of packed pixels goes through these: the display
 * processor's (firmware-model/raster.h) and the host's (script.c,
 * history.c).
 */
static inline uint32_t rdc_px_get(const uint8_t *p, unsigned int bpp,
				  uint64_t bit)
{
	p += bit / 8;
	switch (bpp) {
	case 32:
		return rdc_ld32(p);
	case 24:
		return rdc_ld24(p);
	case 16:
		return rdc_ld16(p);
	case 8:
		return *p;
	default:
		return (uint32_t)(*p >> (8 - bpp - bit % 8)) &
		       ((1u << bpp) - 1);
	}
}

static inline void rdc_px_put(uint8_t *p, unsigned int bpp, uint64_t bit,
			      uint32_t v)
{
	unsigned int sh;
	uint32_t m;

	p += bit / 8;
	switch (bpp) {
	case 32:
		rdc_st32(p, v);
		break;
	case 24:
		rdc_st24(p, v);
		break;
	case 16:
		rdc_st16(p, v);
		break;
	case 8:
		*p = (uint8_t)v;
		break;
	default:
		sh = 8 - bpp - (unsigned int)(bit % 8);
		m = ((1u << bpp) - 1) << sh;
		*p = (uint8_t)((*p & ~m) | ((v << sh) & m));
		break;
	}
}

#endif /* RDC_BASE_H */
