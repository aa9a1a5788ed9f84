/*
 * fx_pow.h - powers of the fixed layer (fx.c): x^s for x in [0, 1] and an
 * unsigned exponent s in Q20.12 (FX_POW_FRAC_BITS), what the Phong
 * highlight and the sky weigh by (their exponents are real.h's shine_t;
 * tracer/shine.h picks the path).
 *
 * Accuracy (tests/unit/test_fx.c; ulp = 2^-F):
 *   fx_pow_unit(x, s)  within 2 ulp + 1e-7 * s relative of x^s for the
 *                      exact value of x (x itself carries 0.5 ulp); 0.5 ulp
 *                      + 2^-26 for s = 1, 2, 4, .., 64
 */
#ifndef FX_POW_H
#define FX_POW_H

#include "fx.h"

#define FX_POW_FRAC_BITS 12

fx_t fx_pow_unit(fx_t x, uint32_t s); /* x^s for x in [0,1]; 0 for x <= 0 */
/* fx_pow_unit's path for x in (0, 1) and an integer s, 1 <= s <= 128 (a
 * Phong exponent mostly is): its binary powers in Q.31, each product
 * rounded (within 2^-24 in all), one rounding to Q.F; inline, so the
 * highlight calls nothing (fx_pow_unit_fast) */
static inline bool fx_pow_unit_int_path(fx_t x, uint32_t s)
{
    return x > 0 && x < FX_ONE && s != 0 && (s & ((1u << FX_POW_FRAC_BITS) - 1)) == 0 &&
           s <= (128u << FX_POW_FRAC_BITS);
}
static inline fx_t fx_pow_unit_int(fx_t x, uint32_t s)
{
    uint32_t m = s >> FX_POW_FRAC_BITS;
    uint32_t u = (uint32_t)x << (31 - FX_FRAC_BITS); /* x < 1: u < 2^31 */
    for (; !(m & 1); m >>= 1)
        u = (uint32_t)((fx_umul64(u, u) + (1u << 30)) >> 31);
    uint32_t p = u; /* x^(lowest bit of s) */
    for (m >>= 1; m; m >>= 1) {
        u = (uint32_t)((fx_umul64(u, u) + (1u << 30)) >> 31);
        if (m & 1)
            p = (uint32_t)((fx_umul64(p, u) + (1u << 30)) >> 31);
    }
    return (fx_t)((p + (1u << (30 - FX_FRAC_BITS))) >> (31 - FX_FRAC_BITS));
}
static inline fx_t fx_pow_unit_fast(fx_t x, uint32_t s)
{
    return fx_pow_unit_int_path(x, s) ? fx_pow_unit_int(x, s) : fx_pow_unit(x, s);
}
#endif
