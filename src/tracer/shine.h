/*
 * shine.h - the Phong power as a shading weight: x^s for x in [0, 1] and
 * the exponent s of a material's highlight or of the sky (shine_t), in
 * each backend (r_pow_unit): the fixed build's fx_pow_unit (fx_pow.h),
 * the float build's r_pow_float (real_float.c), the double build's pow.
 */
#ifndef SHINE_H
#define SHINE_H

#include "numeric/real.h"

#if RT_BACKEND_FIXED
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
