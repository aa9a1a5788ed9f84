/*
 * fx.h - signed fixed point for the tracer, Q(31-F).F with F = FX_FRAC_BITS.
 *
 * Default F = 20 (rt_config.h): range +-2047.999999, resolution 2^-20 = 9.5e-7.
 * Products keep a 64-bit intermediate; every conversion back to fx_t rounds
 * to nearest and saturates to +-FX_MAX (never wraps). FX_ON_SATURATE() is
 * called on each saturation so a debug build can count them.
 *
 * Accuracy (measured by tests/test_fx.c over dense input sweeps; "ulp" is
 * one unit of the last place, 2^-F):
 *   fx_mul, fx_div        correctly rounded (<= 0.5 ulp)
 *   fx_recip              correctly rounded (<= 0.5 ulp)
 *   fx_wdiv               correctly rounded while |a| < 2^(62-F), else
 *                         both operands lose low bits first
 *   fx_wdiv_fx            truncated to 2^-2F while |w| < 2^(62-F)
 *   fx_sqrt, fx_wsqrt     correctly rounded (<= 0.5 ulp)
 *   fx_unit3              each component within 1 ulp of the true unit vector
 *   fx_pow_unit(x, s)     within 2 ulp + 1e-7 * s relative of x^s for the
 *                         exact value of x (x itself carries 0.5 ulp)
 *   fx_tan_deg_wide       relative error < 3e-7 for 0.5 <= deg <= 89 (the sine
 *                         is Q.30, so small angles carry the most)
 *   fx_from_decimal       correctly rounded (the nearest fx_t, ties away)
 *                         for inputs with at most 18 fraction digits
 */
#ifndef FX_H
#define FX_H

#include <stdbool.h>
#include <stdint.h>

#include "rt_config.h"
#include "rt_prefix.h"

typedef int32_t fx_t;       /* Q(31-F).F scalar */
typedef int64_t fx_wide_t;  /* Q(63-2F).2F: an exact product of two fx_t */
typedef uint32_t fx_shine_t;/* unsigned Q20.12: Phong exponents up to ~1e6 */

#define FX_SHINE_FRAC_BITS 12
#define FX_ONE ((fx_t)1 << FX_FRAC_BITS)
#define FX_HALF ((fx_t)1 << (FX_FRAC_BITS - 1))
#define FX_MAX ((fx_t)INT32_MAX)
#define FX_MIN (-(fx_t)INT32_MAX) /* symmetric: negation never overflows */

/* n/d as fx_t, rounded; an integer constant expression (no float). */
#define FX_RATIO(n, d) \
    ((fx_t)((((int64_t)(n) * FX_ONE) + ((((int64_t)(n) < 0) == ((int64_t)(d) < 0)) ? (d) / 2 : -(d) / 2)) / (d)))

/* Overflow is never silent: every conversion that would overflow clamps
 * to +-FX_MAX and calls FX_ON_SATURATE(). A build with
 * FX_COUNT_SATURATIONS=1 counts them (the stress suite asserts the count). */
#ifndef FX_COUNT_SATURATIONS
#define FX_COUNT_SATURATIONS 0
#endif
#if FX_COUNT_SATURATIONS
extern volatile uint32_t fx_saturations;
#define FX_ON_SATURATE() ((void)fx_saturations++)
#endif
#ifndef FX_ON_SATURATE
#define FX_ON_SATURATE() ((void)0)
#endif

static inline fx_t fx_sat64(int64_t v)
{
    if (v > FX_MAX) { FX_ON_SATURATE(); return FX_MAX; }
    if (v < FX_MIN) { FX_ON_SATURATE(); return FX_MIN; }
    return (fx_t)v;
}

/* Round a value with `shift` extra fraction bits to nearest (half up). */
static inline int64_t fx_round_shift(int64_t v, unsigned shift)
{
    return (v + ((int64_t)1 << (shift - 1))) >> shift;
}

static inline fx_t fx_from_int(int32_t i) { return fx_sat64((int64_t)i * FX_ONE); }

static inline fx_t fx_mul(fx_t a, fx_t b)
{
    return fx_sat64(fx_round_shift((int64_t)a * b, FX_FRAC_BITS));
}

static inline fx_wide_t fx_wmul(fx_t a, fx_t b) { return (int64_t)a * b; }

static inline fx_t fx_from_wide(fx_wide_t w) { return fx_sat64(fx_round_shift(w, FX_FRAC_BITS)); }

static inline fx_wide_t fx_to_wide(fx_t a) { return (int64_t)a * FX_ONE; }

fx_t fx_div(fx_t a, fx_t b);          /* b == 0 saturates by the sign of a */
fx_t fx_recip(fx_t b);                /* 1 / b */

/* (a - b) * c exactly, as Q.2F, the difference saturated to 32 bits:
 * one SMULL (slab tests). */
static inline fx_wide_t fx_wmul_diff(fx_t a, fx_t b, fx_t c)
{
    int32_t d;
#if defined(__GNUC__)
    if (__builtin_sub_overflow(a, b, &d))
        d = a > b ? FX_MAX : FX_MIN;
    /* an empty barrier: without it GCC 12 forgets d is 32-bit after the
     * select and multiplies 64x64 (three instructions for one SMULL) */
    __asm__("" : "+r"(d));
#else
    int64_t w = (int64_t)a - b;
    d = w > FX_MAX ? FX_MAX : w < FX_MIN ? FX_MIN : (int32_t)w;
#endif
    return (int64_t)d * c;
}

/* Sign of d . n for a Q.F vector d (|d_k| <= 2) and a Q.2F vector n, at
 * full precision: n is shifted right just enough for the products to fit
 * 64 bits (the same shift for the same n, so equal inputs give equal
 * answers: what watertight edge tests need). */
static inline int fx_wsign_dot(fx_t dx, fx_t dy, fx_t dz, fx_wide_t nx, fx_wide_t ny, fx_wide_t nz)
{
    uint64_t m = (uint64_t)(nx < 0 ? -nx : nx) | (uint64_t)(ny < 0 ? -ny : ny) | (uint64_t)(nz < 0 ? -nz : nz);
    int s = 0;
    while ((m >> s) >= ((uint64_t)1 << 40))
        s++;
    int64_t v = (int64_t)dx * (nx >> s) + (int64_t)dy * (ny >> s) + (int64_t)dz * (nz >> s);
    return (v > 0) - (v < 0);
}

/* w * a as Q.2F, rounded once: w is split at the binary point so both
 * partial products fit in 64 bits (|w| < 2^(31+F) and |w a| < 2^(63-F)). */
static inline fx_wide_t fx_wmul_fx(fx_wide_t w, fx_t a)
{
    int64_t hi = w >> FX_FRAC_BITS; /* floor */
    int64_t lo = (int64_t)((uint64_t)w & (uint64_t)(FX_ONE - 1));
    return hi * a + fx_round_shift(lo * a, FX_FRAC_BITS);
}
fx_t fx_wdiv(fx_wide_t a, fx_wide_t b); /* a / b of two Q.2F values, as Q.F */
fx_wide_t fx_wdiv_fx(fx_wide_t w, fx_t a); /* w / a, as Q.2F; a == 0 saturates */
fx_t fx_sqrt(fx_t a);                 /* a < 0 gives 0 */
fx_t fx_wsqrt(fx_wide_t w);           /* sqrt of a Q.2F value, as Q.F */
fx_t fx_pow_unit(fx_t x, fx_shine_t s);/* x^s for x in [0,1]; 0 for x <= 0 */

/* Unit vector along (x, y, z) given at any common scale; zero stays zero. */
void fx_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3]);

/* tan(deg degrees) as Q.2F, for 0 <= deg < 90. */
fx_wide_t fx_tan_deg_wide(fx_t deg);

/* sin and cos of deg degrees (any angle), each within 1 ulp. */
void fx_sincos_deg(fx_t deg, fx_t *sin_out, fx_t *cos_out);

/* Nearest value with `frac_bits` fraction bits to +-mant * 10^exp10
 * (exact for up to 18 fraction digits; digits beyond are truncated).
 * Returns false when the magnitude exceeds `max`. */
bool fx_from_decimal(bool neg, uint64_t mant, int32_t exp10, unsigned frac_bits,
                     uint32_t max, int32_t *out);

#endif
