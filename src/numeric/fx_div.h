/*
 * fx_div.h - quotients (fx.c): of wide values, the BVH's reciprocals,
 * and 64-bit long division for set-up code. fx_div and fx_recip, the
 * general quotient and reciprocal, are declared in fx.h.
 *
 * Accuracy (tests/unit/test_fx.c; ulp = 2^-F):
 *   fx_wdiv      correctly rounded while |a| < 2^(62-F), else both
 *                operands lose low bits first
 *   fx_wdiv_fx   truncated to 2^-2F while |w| < 2^(62-F)
 */
#ifndef FX_DIV_H
#define FX_DIV_H

#include "fx.h"

fx_t fx_wdiv(fx_wide_t a, fx_wide_t b);        /* a / b of two Q.2F values, as Q.F */
fx_wide_t fx_wdiv_fx(fx_wide_t w, fx_t a);     /* w / a, as Q.2F; a == 0 saturates */
fx_wide_t fx_wdiv_int(fx_wide_t w, int32_t n); /* w / n truncated, n != 0 (C's w / n) */

/* n / d (d != 0), truncated like C's, by binary long division: a few
 * dozen bytes where libgcc's 64-bit division is 700 on the M3, for
 * set-up code (camera, sines, tangents). */
int64_t fx_div64(int64_t n, int64_t d);

/* Cores without a 32-bit divide instruction (ARMv6-M, where it is a
 * libgcc call of 40 to 130 instructions) seed reciprocals from a table. */
#ifndef FX_RECIP_TABLE
#if (defined(__arm__) && !defined(__ARM_FEATURE_IDIV)) || (defined(__riscv) && !defined(__riscv_div))
#define FX_RECIP_TABLE 1
#else
#define FX_RECIP_TABLE 0
#endif
#endif

/* Towards 2^63 / d for d in [2^31, 2^32) from y under it by less than
 * 2^-13.8: one Newton step y + y (1 - d y), where 2^31 - d y / 2^32 =
 * 2^31 (1 - d y / 2^63) is at most 1 over; 2 units off keep it under. */
static inline uint32_t fx_recip_step(uint32_t d, uint32_t y)
{
    uint32_t e = 0x80000000u - (uint32_t)(fx_umul64(d, y) >> 32);
    return y + ((uint32_t)(fx_umul64(y, e) >> 32) << 1) - 2;
}

/* 2^63 / d from a 32-bit divide (UDIV, 2..12 cycles on the M3) */
static inline uint32_t fx_recip_q63_div(uint32_t d) { return fx_recip_step(d, (0xFFFFFFFFu / ((d >> 16) + 1)) << 15); }

/* 2^62 / x for x in [2^31, 2^32), never above it and less than 2^-27
 * relative under: the reciprocal before rounding, for callers that scale
 * it themselves (the BVH's slabs, three a ray: inline where it is a
 * divide). */
#if FX_RECIP_TABLE
uint32_t fx_recip_q31(uint32_t x);
#else
static inline uint32_t fx_recip_q31(uint32_t x) { return fx_recip_q63_div(x) >> 1; }
#endif

#endif
