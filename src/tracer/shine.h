/*
 * shine.h - the Phong power: x^s for x in [0, 1] and an exponent s of a
 * material's highlight or of the sky (scene.h's shine_t), as a shading
 * weight, in each backend (r_pow_unit).
 *
 * Accuracy of the fixed build's power (tests/test_fx.c; ulp = 2^-F):
 *   fx_pow_unit(x, s)  within 2 ulp + 1e-7 * s relative of x^s for the
 *                      exact value of x (x itself carries 0.5 ulp); 0.5 ulp
 *                      + 2^-26 for s = 1, 2, 4, .., 64
 * The float build's is real_float.c's r_pow_float, with its accuracy.
 */
#ifndef SHINE_H
#define SHINE_H

#include "numeric/real.h"

#if RT_BACKEND_FIXED
fx_t fx_pow_unit(fx_t x, shine_t s);  /* x^s for x in [0,1]; 0 for x <= 0 (shine.c) */
/* fx_pow_unit's path for x in (0, 1) and an integer s, 1 <= s <= 128 (a
 * Phong exponent mostly is): its binary powers in Q.31, each product
 * rounded (within 2^-24 in all), one rounding to Q.F; inline, so the
 * highlight calls nothing (fx_pow_unit_fast) */
static inline bool fx_pow_unit_int_path(fx_t x, shine_t s)
{
    return x > 0 && x < FX_ONE && s != 0 && (s & ((1u << R_SHINE_FRAC_BITS) - 1)) == 0 &&
           s <= (128u << R_SHINE_FRAC_BITS);
}
static inline fx_t fx_pow_unit_int(fx_t x, shine_t s)
{
    uint32_t m = s >> R_SHINE_FRAC_BITS;
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
static inline fx_t fx_pow_unit_fast(fx_t x, shine_t s)
{
    return fx_pow_unit_int_path(x, s) ? fx_pow_unit_int(x, s) : fx_pow_unit(x, s);
}
/* (the integer path inline where the code has room: RT_INLINE_HOT) */
static inline real_t r_pow_unit(real_t x, shine_t s) { return RT_INLINE_HOT ? fx_pow_unit_fast(x, s) : fx_pow_unit(x, s); }
#elif RT_BACKEND_FLOAT
/* x^s for x in [0, 1] as a shading weight: r_pow_float's value, but for
 * an integer s a result below 2^-100 (a factor may have been subnormal)
 * is taken as it came, within 2^-100 of x^s (r_pow_float takes its
 * general path there): a weight that small adds nothing to any colour.
 * Inline, so a highlight with such an s calls nothing. */
static inline real_t r_pow_unit(real_t x, shine_t s)
{
    if (x <= 0) /* as r_pow_float (a highlight facing away) */
        return 0;
    return r_pow_float_small_int(s) ? r_pow_float_int(x, s) : r_pow_float(x, s);
}
#else
static inline real_t r_pow_unit(real_t x, shine_t s) { return x <= 0 ? 0 : R_FN(pow)(x, s); }
#endif

#endif
