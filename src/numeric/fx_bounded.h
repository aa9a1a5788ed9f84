/*
 * fx_bounded.h - products that are cheaper than the general ones of fx.h
 * because their callers keep their operands within a bound. Each states
 * its precondition and why it holds where it is called (through real.h's
 * r_* and vec3.h's v3_* wrappers, which name the same condition).
 *
 * Names: fx_<operation>_<guarantee>. The operation is the general one
 * (mul, dot3, norm2; a w after fx_ marks a Q.2F operand or result, as in
 * fx.h); the suffix is one word for what the callers guarantee:
 *   small   |a| <= 2 and a correction |e| <= 2^-10
 *   weight  one factor is a weight in [0, 1]
 *   unit    vectors of length at most 1.4
 *   short   vectors whose components are within +-2
 *   cut     components shifted down by s; the caller bounds the sum
 *   fits    the exact result fits its type: no saturation test
 *
 * Accuracy (tests/unit/test_fx.c; ulp = 2^-F):
 *   fx_norm2_short          correctly rounded (the 64-bit sum's bits)
 *   fx_dot3_negative_short  exact
 *   fx_mul_weight(c, w)     within |c| 2^-16 + 0.5 ulp (w in [0, 1] to Q.15)
 *   fx_mul_small(a, e)      within 0.5 ulp + 4 |e| (|e| <= 2^-10)
 *   fx_dot3_unit            within 2^-13 for unit vectors (a shading weight)
 *   fx_wdot3_sign_short     exact for |d_k| <= 2
 *   fx_wmul_fits            rounded once (to 2^-2F)
 */
#ifndef FX_BOUNDED_H
#define FX_BOUNDED_H

#include "fx.h"

/* a e for |a| <= 2 and a small |e| <= 2^-10 (a correction term, such
 * as a Newton step's): one 32-bit product of a / 4 and e, whose product
 * stays under 2^(2F-11), within half a unit plus 4 |e| units of a e. e is
 * held to +-2^-10, so no input overflows.
 * Callers: v3_renorm (vec3.h), the one Newton step that makes a unit
 * again a vector within 2^-10 of unit (the mirror direction, trace.c), so
 * |a_k| <= 1 + 2^-10 and e = (1 - |a|^2) / 2 is within 2^-10. */
static inline fx_t fx_mul_small(fx_t a, fx_t e)
{
#if FX_FRAC_BITS >= 12
    const fx_t lim = (fx_t)1 << (FX_FRAC_BITS - 10);
    e = e > lim ? lim : e < -lim ? -lim : e;
    return ((a >> 2) * e + ((fx_t)1 << (FX_FRAC_BITS - 3))) >> (FX_FRAC_BITS - 2);
#else /* 2^-10 is a few units: the plain product */
    return fx_mul(a, e);
#endif
}

/* c w for a weight 0 <= w <= 1 (a cosine, a reflectance, a blend factor)
 * in two 32-bit products, no 64-bit one (on ARMv6-M a third of fx_mul's
 * instructions): w rounded to Q.15, c split into its signed high and
 * unsigned low 16 bits, c w15 / 2^15 = 2 ch w15 + cl w15 / 2^15, rounded
 * once. Within |c| 2^-16 + 1/2 unit of c w. No saturation test: with w15
 * held to 2^15 (a cosine a few units over 1 still counts as 1), |2 ch
 * w15| <= 2^31 - 2^16 and the low part adds under 2^16. Cores with a
 * long multiply take the same bits from it.
 * Callers: c3_scale_weight (vec3.h) with N.L (> 0, a cosine of unit
 * vectors), the Phong power and the sky's (x^s of x in [0, 1]), and in
 * trace.c's colour scaling only where r_is_weight(k) said k is in [0, 1]. */
static inline fx_t fx_mul_weight(fx_t c, fx_t w)
{
#if FX_FRAC_BITS > 15
    int32_t w15 = (w + ((fx_t)1 << (FX_FRAC_BITS - 16))) >> (FX_FRAC_BITS - 15);
#else
    int32_t w15 = w * ((fx_t)1 << (15 - FX_FRAC_BITS));
#endif
    w15 = w15 < ((int32_t)1 << 15) ? w15 : (int32_t)1 << 15;
#if FX_MUL64_PARTIAL
    int32_t ch = c >> 16;
    uint32_t cl = (uint32_t)c & 0xFFFFu;
    return 2 * ch * w15 + (int32_t)((cl * (uint32_t)w15 + (1u << 14)) >> 15);
#else /* the same bits from one long product */
    return (fx_t)(((int64_t)c * w15 + (1 << 14)) >> 15);
#endif
}

/* a . b, exact (Q.2F), for components within +-2: each product is below
 * 2^(2F+2), the sum below 2^(2F+4), far inside 64 bits.
 * Callers: the 64-bit paths of the three functions below, whose own
 * bounds are at least as tight. */
static inline fx_wide_t fx_wdot3_short(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
    return fx_mul64(ax, bx) + fx_mul64(ay, by) + fx_mul64(az, bz);
}

/* a . b from components cut to Q(F - s) (arithmetic shifts), in 32-bit
 * products: the sum must fit 32 bits.
 * Callers: fx_dot3_unit (s = F - 15, the sum within |a| |b| 2^30 <
 * 2^31) and fx_dot3_negative_short (s = F - 13, each product below
 * 2^28, the sum below 2^30). */
static inline int32_t fx_dot3_cut(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz, int s)
{
    return (ax >> s) * (bx >> s) + (ay >> s) * (by >> s) + (az >> s) * (bz >> s);
}

/* |a|^2 for |a| <= 2, rounded once: the bits of the 64-bit sum. Without a
 * long multiply, from 32-bit products: each component split at bit k =
 * F/2 into h = a >> k and l = a - h 2^k in [0, 2^k), so a^2 = h^2 2^F + 2
 * h l 2^k + l^2, and the rounding's floors nest: (2 M 2^k + L + 2^(F-1))
 * >> F = (2 M + ((L + 2^(F-1)) >> k)) >> k, M = sum h l, L = sum l^2.
 * Callers: v3_renorm (vec3.h), on vectors within 2^-10 of unit. */
static inline fx_t fx_norm2_short(fx_t ax, fx_t ay, fx_t az)
{
#if FX_MUL64_PARTIAL && FX_FRAC_BITS % 2 == 0 && FX_FRAC_BITS >= 12
    const int k = FX_FRAC_BITS / 2;
    const uint32_t low = ((uint32_t)1 << k) - 1;
    int32_t hx = ax >> k, hy = ay >> k, hz = az >> k;
    int32_t lx = (int32_t)((uint32_t)ax & low), ly = (int32_t)((uint32_t)ay & low), lz = (int32_t)((uint32_t)az & low);
    int32_t l2 = lx * lx + ly * ly + lz * lz + ((int32_t)1 << (FX_FRAC_BITS - 1));
    return hx * hx + hy * hy + hz * hz + ((2 * (hx * lx + hy * ly + hz * lz) + (l2 >> k)) >> k);
#else
    return (fx_t)fx_round_shift(fx_wdot3_short(ax, ay, az, ax, ay, az), FX_FRAC_BITS);
#endif
}

/* a . b for unit vectors a and b (or up to 1.4 long), good to 2^-13 (a
 * cosine that weighs a colour): 32-bit products of the components cut to
 * Q.15, each within (|a_k| + |b_k|) 2^-15 of the exact one; every partial
 * sum of |a_k b_k| is at most |a| |b| (Cauchy-Schwarz), under 2^31.
 * Callers: v3_cos (vec3.h), N.L in the shading (trace.c): N and L are
 * unit vectors from fx_unit3 or a primitive's normal. */
static inline fx_t fx_dot3_unit(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
#if FX_FRAC_BITS > 15
    int32_t q = fx_dot3_cut(ax, ay, az, bx, by, bz, FX_FRAC_BITS - 15); /* Q.30 */
    return (q + ((int32_t)1 << (29 - FX_FRAC_BITS))) >> (30 - FX_FRAC_BITS);
#else
    return (fx_t)fx_round_shift(fx_wdot3_short(ax, ay, az, bx, by, bz), FX_FRAC_BITS);
#endif
}

/* Whether a . b < 0 for |a_k|, |b_k| <= 2, exactly. Without a long
 * multiply, 32-bit products of a and b cut to Q.13 first: each cut
 * product is within |a'| + |b'| + 1 <= 2^15 + 1 of the exact one (in
 * their units, 2^-26), so a sum beyond 3 (2^15 + 1) has the exact sum's
 * sign; only near-perpendicular pairs (|a . b| below 2^-9.4) take the
 * 64-bit products.
 * Callers: v3_dot_negative (vec3.h), the ray's unit direction against a
 * primitive's geometric normal (trace.c), a unit vector or one a few
 * units long. */
static inline bool fx_dot3_negative_short(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
#if FX_MUL64_PARTIAL && FX_FRAC_BITS > 13
    const int32_t sure = 3 * (((int32_t)1 << 15) + 1);
    int32_t q = fx_dot3_cut(ax, ay, az, bx, by, bz, FX_FRAC_BITS - 13);
    if (q > sure || q < -sure)
        return q < 0;
#endif
    return fx_wdot3_short(ax, ay, az, bx, by, bz) < 0;
}

/* Sign of d . n for a Q.F vector d (|d_k| <= 2) and a Q.2F vector n, at
 * full precision: n is shifted right just enough for the products to fit
 * 64 bits (the same shift for the same n, so equal inputs give equal
 * answers: what watertight edge tests need).
 * Callers: r_wsign_dot, the polygon's edge test (polygon.c), d the ray's
 * unit direction. */
static inline int fx_wdot3_sign_short(fx_t dx, fx_t dy, fx_t dz, fx_wide_t nx, fx_wide_t ny, fx_wide_t nz)
{
    uint64_t m = (uint64_t)(nx < 0 ? -nx : nx) | (uint64_t)(ny < 0 ? -ny : ny) | (uint64_t)(nz < 0 ? -nz : nz);
    int s = 0;
#if defined(__GNUC__)
    if (m >> 40) /* the bit length of m, less 40 */
        s = 24 - __builtin_clzll(m);
#else
    while ((m >> s) >= ((uint64_t)1 << 40))
        s++;
#endif
    int64_t v = fx_mul64x(dx, nx >> s) + fx_mul64x(dy, ny >> s) + fx_mul64x(dz, nz >> s);
    return (v > 0) - (v < 0);
}

/* w * a as Q.2F, rounded once: w is split at the binary point, w = hi
 * 2^F + lo, into two products: lo a is below 2^(31+F), and hi a is w a
 * as Q.2F, which fits 64 bits while |w a| < 2^(63-2F) (2^23 for F = 20).
 * Callers: r_wmul_real, in the camera's set-up (camera.c: tan(angle/2)
 * up to 64 times a distance within 16, the half span, under 256, times a
 * unit vector) and the texture footprint (texture.c: a squared cosine
 * times 1 - N_a^2, both in [0, 1]). */
static inline fx_wide_t fx_wmul_fits(fx_wide_t w, fx_t a)
{
    int64_t hi = w >> FX_FRAC_BITS; /* floor */
    int64_t lo = (int64_t)((uint64_t)w & (uint64_t)(FX_ONE - 1));
    return fx_mul64x(a, hi) + fx_round_shift(fx_mul64x(a, lo), FX_FRAC_BITS);
}

#endif
