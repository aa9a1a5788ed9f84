/*
 * real.h - the scalar the algorithm is written in, and its two backends.
 *
 * The tracer source uses real_t with the ordinary + - < > operators and
 * the r_* functions below for everything else, so the same code builds as
 *   fixed point (the default): real_t = fx_t, Q(31-F).F, the product;
 *   double      (RT_BACKEND_DOUBLE=1): the reference the fixed build is
 *               measured against;
 *   float       (RT_BACKEND_FLOAT=1): single precision, for comparison.
 * real_wide_t holds exact products (Q.2F in the fixed build) so that
 * discriminants and dot products lose nothing before the final rounding.
 *
 * The floating-point backends use the compiler's sqrt/tan/sin/cos/floor
 * builtins; the double backend also its pow. The float backend's pow is
 * its own (real_float.c: float arithmetic alone, no libm), so a render
 * on an IEEE single-precision FPU is bit for bit the host's: the render
 * calls no other libm function (tan, sin, cos and floor are the reader's
 * and the BVH builder's, and rt_camera_from_view's tan), and sqrt is
 * correctly rounded everywhere (an instruction with -fno-math-errno).
 */
#ifndef REAL_H
#define REAL_H

#include <stdbool.h>
#include <stdint.h>

#include "rt_config.h"
#include "rt_prefix.h"

#if RT_BACKEND_DOUBLE || RT_BACKEND_FLOAT

/* Floating point: double (the reference) or float (what a user of single
 * precision would run); the same code with the type and builtins swapped. */
#if RT_BACKEND_FLOAT
typedef float real_t;
#define R_BACKEND_NAME "float"
#define R_UNIT_LEN_FREE 0
#define R_FN(name) __builtin_##name##f
#define R_EPSILON 0x1p-23f
#else
typedef double real_t;
#define R_BACKEND_NAME "double"
#define R_UNIT_LEN_FREE 0
#define R_FN(name) __builtin_##name
#define R_EPSILON 0x1p-52
#endif
typedef real_t real_wide_t;
typedef real_t shine_t;

#define R_RATIO(n, d) ((real_t)(n) / (real_t)(d))
#define R_ONE ((real_t)1)
#define R_BIG ((real_t)1e30)                   /* "no hit yet" distance */
/* n units of the fixed build's last place (margins match across builds) */
#define R_ULPS(n) ((real_t)(n) / (real_t)((int32_t)1 << FX_FRAC_BITS))

static inline real_t r_from_int(int32_t i) { return (real_t)i; }
static inline real_t r_mul(real_t a, real_t b) { return a * b; }
static inline real_t r_mul_in_range(real_t a, real_t b) { return a * b; }
static inline real_t r_mul_weight(real_t c, real_t w) { return c * w; }
/* whether r_mul_weight may take k: any k, a product is a product here */
static inline bool r_is_weight(real_t k) { return (void)k, true; }
static inline bool r_dot3_negative(real_t ax, real_t ay, real_t az, real_t bx, real_t by, real_t bz)
{
    return ax * bx + ay * by + az * bz < 0;
}
static inline real_t r_cos3(real_t ax, real_t ay, real_t az, real_t bx, real_t by, real_t bz)
{
    return ax * bx + ay * by + az * bz;
}
static inline real_t r_div(real_t a, real_t b) { return a / b; }
static inline real_t r_recip(real_t b) { return R_ONE / b; }
/* BVH slab distances (scene_hit.c): plain products here; see the fixed
 * backend for the scaled form. */
typedef real_t real_slab_t;
static inline int r_slab_inverse(const real_t d[3], unsigned skip, real_t inv[3])
{
    for (int a = 0; a < 3; a++)
        inv[a] = (skip >> a) & 1u ? 0 : R_ONE / d[a];
    return 0;
}
static inline real_slab_t r_slab_dist(real_t bound, real_t o, real_t inv) { return (bound - o) * inv; }
static inline real_slab_t r_slab_from_t_down(real_t t, int shift) { (void)shift; return t; }
static inline real_slab_t r_slab_from_t_up(real_t t, int shift) { (void)shift; return t; }
/* sign of (dx, dy, dz) . (nx, ny, nz) */
static inline int r_wsign_dot(real_t dx, real_t dy, real_t dz, real_wide_t nx, real_wide_t ny, real_wide_t nz)
{
    real_wide_t s = dx * nx + dy * ny + dz * nz;
    return (s > 0) - (s < 0);
}
static inline real_t r_sqrt(real_t a) { return a > 0 ? R_FN(sqrt)(a) : 0; }
static inline real_wide_t r_wmul(real_t a, real_t b) { return a * b; }
static inline real_wide_t r_to_wide(real_t a) { return a; }
static inline real_t r_from_wide(real_wide_t w) { return w; }
static inline real_t r_from_wide_in_range(real_wide_t w) { return w; }
static inline real_t r_wsqrt(real_wide_t w) { return w > 0 ? R_FN(sqrt)(w) : 0; }
static inline real_t r_wdiv(real_wide_t a, real_wide_t b) { return a / b; }
static inline real_wide_t r_wdiv_real(real_wide_t w, real_t a) { return w / a; }
static inline real_wide_t r_wdiv_int(real_wide_t w, int32_t n) { return w / n; }
static inline real_wide_t r_wmul_real(real_wide_t w, real_t a) { return w * a; }
static inline int32_t r_floor_int(real_t a) { return (int32_t)R_FN(floor)(a); }
/* floor(w), and w - floor(w) in [0, 1) to *frac; |w| < 2^23. No libm
 * call: the render's (textures) */
static inline int32_t r_wsplit(real_wide_t w, real_t *frac)
{
    int32_t i = (int32_t)w; /* toward zero */
    i -= (real_t)i > w;
    *frac = w - (real_t)i;
    return i;
}
static inline real_t r_add_sat(real_t a, real_t b) { return a + b; }
/* a b and a + b, which the fixed build holds within [-lim, lim] (its
 * range, for quantities that may outgrow it harmlessly); here as they are */
static inline real_t r_mul_bounded(real_t a, real_t b, real_t lim) { return (void)lim, a * b; }
static inline real_t r_add_bounded(real_t a, real_t b, real_t lim) { return (void)lim, a + b; }
/* the next value above a (a > 0) */
static inline real_t r_next_up(real_t a) { return a + a * R_EPSILON; }
#if RT_BACKEND_FLOAT
/* x^s in float arithmetic alone, 0 for x <= 0 (real_float.c, with its accuracy) */
float r_pow_float(float x, float s);
/* Whether s is an integer, 2 <= s <= 64: x^s is then its binary powers,
 * each product rounded once (relative error below s 2^-24 while no factor
 * is subnormal), a tenth of the general path's work (r_pow_float), for
 * the exponents scenes pick by hand. */
static inline bool r_pow_float_small_int(float s) { return s >= 2 && s <= 64 && s == (float)(int32_t)s; }
static inline float r_pow_float_int(float x, float s)
{
    uint32_t m = (uint32_t)s;
    float u = x;
    for (; !(m & 1); m >>= 1)
        u *= u;
    float p = u; /* x^(lowest bit of s) */
    for (m >>= 1; m; m >>= 1) {
        u *= u;
        if (m & 1)
            p *= u;
    }
    return p;
}
#endif
static inline real_wide_t r_tan_deg_wide(real_t deg)
{
    return R_FN(tan)(deg * (real_t)(3.14159265358979323846 / 180.0));
}
static inline void r_sincos_deg(real_t deg, real_t *s, real_t *c)
{
    real_t rad = deg * (real_t)(3.14159265358979323846 / 180.0);
    *s = R_FN(sin)(rad);
    *c = R_FN(cos)(rad);
}
static inline void r_unit3(real_wide_t x, real_wide_t y, real_wide_t z, real_t out[3])
{
    real_t l = R_FN(sqrt)(x * x + y * y + z * z);
    if (l == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
#if RT_BACKEND_FLOAT
    real_t inv = 1 / l; /* one division and three products: a division is 14 cycles on an M4F */
    out[0] = x * inv;
    out[1] = y * inv;
    out[2] = z * inv;
#else
    out[0] = x / l; /* the reference: each component correctly rounded */
    out[1] = y / l;
    out[2] = z / l;
#endif
}
static inline void r_unit3_narrow(real_t x, real_t y, real_t z, real_t out[3]) { r_unit3(x, y, z, out); }
/* the unit vector and the length as (x, y, z) . unit: the reference's
 * measure (the fixed build has the length at hand) */
static inline void r_unit3_narrow_len(real_t x, real_t y, real_t z, real_t out[3], real_t *len)
{
    r_unit3(x, y, z, out);
    *len = x * out[0] + y * out[1] + z * out[2];
}
/* round(255 c) of c clamped to [0, 1] */
static RT_INLINE uint8_t r_to_u8(real_t c)
{
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 255;
    return (uint8_t)(c * 255 + (real_t)0.5);
}
/* +-mant * 10^exp10 * 2^scale_log2 */
bool r_from_decimal_scaled(bool neg, uint64_t mant, int32_t exp10, int32_t scale_log2, real_t *out);
bool shine_from_decimal(bool neg, uint64_t mant, int32_t exp10, shine_t *out);
/* v * 2^k, false if out of range */
static inline bool r_ldexp(real_t v, int32_t k, real_t *out)
{
    for (; k > 0; k--)
        v *= 2;
    for (; k < 0; k++)
        v /= 2;
    if (v > (real_t)1e30 || v < (real_t)-1e30)
        return false;
    *out = v;
    return true;
}

#else /* fixed point */

#include "fx.h"
#include "fx_bounded.h"
#include "fx_div.h"
#include "fx_pow.h"
#include "fx_root.h"
#include "fx_setup.h"

typedef fx_t real_t;
typedef fx_wide_t real_wide_t;
/* a Phong exponent (the material's and the sky's): fx_pow_unit's, unsigned
 * Q20.12, up to ~5e5 (the reader's limit) in steps of 2^-12 */
typedef uint32_t shine_t;
#define R_SHINE_FRAC_BITS FX_POW_FRAC_BITS

#define R_RATIO(n, d) FX_RATIO(n, d)
#define R_ONE FX_ONE
#define R_BIG FX_MAX
#define R_ULPS(n) ((fx_t)(n))
#define R_BACKEND_NAME "fixed"
/* a unit vector's length comes with it (r_unit3_narrow_len) */
#define R_UNIT_LEN_FREE 1

static inline real_t r_from_int(int32_t i) { return fx_from_int(i); }
static inline real_t r_mul(real_t a, real_t b) { return fx_mul(a, b); }
/* r_mul and r_from_wide where the caller knows the result is inside the
 * range (vec3.h's _in_range helpers): the same rounding, no saturation
 * test, so the same bits in 4 to 6 fewer instructions. */
static inline real_t r_from_wide_in_range(real_wide_t w) { return (fx_t)fx_round_shift(w, FX_FRAC_BITS); }
static inline real_t r_mul_in_range(real_t a, real_t b) { return r_from_wide_in_range(fx_mul64(a, b)); }
/* c w for a weight w in [0, 1]: within |c| 2^-16 of it (fx_mul_weight) */
static inline real_t r_mul_weight(real_t c, real_t w) { return fx_mul_weight(c, w); }
/* whether r_mul_weight may take k: k in [0, 1] */
static inline bool r_is_weight(real_t k) { return k >= 0 && k <= R_ONE; }
/* a e for |a| <= 2 and |e| <= 2^-10 (a correction): fx_mul_small */
static inline real_t r_mul_small(real_t a, real_t e) { return fx_mul_small(a, e); }
/* whether a . b < 0 for |a_k|, |b_k| <= 2: fx_dot3_negative_short */
static inline bool r_dot3_negative(real_t ax, real_t ay, real_t az, real_t bx, real_t by, real_t bz)
{
    return fx_dot3_negative_short(ax, ay, az, bx, by, bz);
}
/* a . b of unit vectors to 2^-13, for shading weights: fx_dot3_unit */
static inline real_t r_cos3(real_t ax, real_t ay, real_t az, real_t bx, real_t by, real_t bz)
{
    return fx_dot3_unit(ax, ay, az, bx, by, bz);
}
/* |a|^2 for |a| <= 2, rounded once: fx_norm2_short */
static inline real_t r_norm2(real_t ax, real_t ay, real_t az) { return fx_norm2_short(ax, ay, az); }
static inline real_t r_div(real_t a, real_t b) { return fx_div(a, b); }
static inline real_t r_recip(real_t b) { return fx_recip(b); }
/* BVH slab distances (scene_hit.c) in 32 bits: t = (bound - o) / d is the
 * high word of the exact product (bound - o) * inv, where inv is 1/d in
 * Q(F + k): t comes out in Q(2F - 32 + k), rounded down. k is per ray, as
 * large as keeps every |inv| below 2^30 (16 to 18 fraction bits for most
 * rays), and shift = 32 - F - k turns a Q.F distance into that format.
 * One SMULL and 32-bit compares per plane, where Q.2F needs 64-bit ones.
 * inv comes from fx_recip_q31 (2^-27) rounded once: within 2^-(F+1)
 * relative, like a rounded fx_recip (the bound RT_BOX_SLACK assumes). */
typedef int32_t real_slab_t;
static inline int r_slab_inverse(const real_t d[3], unsigned skip, real_t inv[3])
{
    uint32_t m[3], m_min = UINT32_MAX;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        m[a] = (skip >> a) & 1u ? 0 : (uint32_t)(d[a] < 0 ? -d[a] : d[a]);
        m_min = m[a] && m[a] < m_min ? m[a] : m_min;
    }
    /* with m 2^s in [2^31, 2^32), 1/d = y 2^(F + s - 62) for y =
     * fx_recip_q31(m 2^s) < 2^31, that is y 2^(2F + s + k - 62) in
     * Q(F + k): k = 61 - 2F - s_max keeps the largest below 2^30 */
    int s_max = fx_clz32(m_min);
    int k = 61 - 2 * FX_FRAC_BITS - s_max;
    k = k > 32 - FX_FRAC_BITS ? 32 - FX_FRAC_BITS : k;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        int32_t v = 0;
        if (m[a]) {
            int s = fx_clz32(m[a]), down = 62 - 2 * FX_FRAC_BITS - s - k; /* >= 1 */
            v = (int32_t)((fx_recip_q31(m[a] << s) + ((uint32_t)1 << (down - 1))) >> down);
        }
        inv[a] = d[a] < 0 ? -v : v;
    }
    return 32 - FX_FRAC_BITS - k;
}
/* No saturation: bounds lie within the scene's extent (|bound| < 2^(4+F))
 * and origins within the far extent (< 2^(9+F), rt_config.h), so the
 * difference stays below 2^30. */
static inline real_slab_t r_slab_dist(real_t bound, real_t o, real_t inv)
{
    return fx_mul64_hi(bound - o, inv);
}
static inline real_slab_t r_slab_from_t_down(real_t t, int shift) { return t >> shift; }
static inline real_slab_t r_slab_from_t_up(real_t t, int shift) { return -((-t) >> shift); }
static inline int r_wsign_dot(real_t dx, real_t dy, real_t dz, real_wide_t nx, real_wide_t ny, real_wide_t nz)
{
    return fx_wdot3_sign_short(dx, dy, dz, nx, ny, nz);
}
static inline real_t r_sqrt(real_t a) { return fx_sqrt(a); }
static inline real_wide_t r_wmul(real_t a, real_t b) { return fx_wmul(a, b); }
static inline real_wide_t r_to_wide(real_t a) { return fx_to_wide(a); }
static inline real_t r_from_wide(real_wide_t w) { return fx_from_wide(w); }
static inline real_t r_wsqrt(real_wide_t w) { return fx_wsqrt(w); }
static inline real_t r_wdiv(real_wide_t a, real_wide_t b) { return fx_wdiv(a, b); }
static inline real_wide_t r_wdiv_real(real_wide_t w, real_t a) { return fx_wdiv_fx(w, a); }
static inline real_wide_t r_wdiv_int(real_wide_t w, int32_t n) { return fx_wdiv_int(w, n); }
static inline real_wide_t r_wmul_real(real_wide_t w, real_t a) { return fx_wmul_fits(w, a); }
static inline int32_t r_floor_int(real_t a) { return a >> FX_FRAC_BITS; /* arithmetic shift */ }
static inline int32_t r_wsplit(real_wide_t w, real_t *frac)
{
    *frac = (fx_t)((w >> FX_FRAC_BITS) & (FX_ONE - 1)); /* rounded down, as the floor */
    return (int32_t)(w >> (2 * FX_FRAC_BITS));
}
static inline real_t r_add_sat(real_t a, real_t b) { return fx_add_sat(a, b); }
/* a b and a + b held within [-lim, lim] (0 < lim <= FX_MAX), for
 * quantities that may outgrow the range harmlessly: a bound, not an
 * overflow, so not counted as a saturation */
static inline real_t r_bound_wide(int64_t v, real_t lim) { return v > lim ? lim : v < -lim ? -lim : (real_t)v; }
static inline real_t r_mul_bounded(real_t a, real_t b, real_t lim)
{
    return r_bound_wide(fx_round_shift(fx_mul64(a, b), FX_FRAC_BITS), lim);
}
static inline real_t r_add_bounded(real_t a, real_t b, real_t lim) { return r_bound_wide((int64_t)a + b, lim); }
static inline real_t r_next_up(real_t a) { return a < FX_MAX ? a + 1 : a; }
static inline real_wide_t r_tan_deg_wide(real_t deg) { return fx_wtan_deg(deg); }
static inline void r_unit3(real_wide_t x, real_wide_t y, real_wide_t z, real_t out[3])
{
    fx_unit3(x, y, z, out);
}
static inline void r_unit3_narrow(real_t x, real_t y, real_t z, real_t out[3]) { fx_unit3_narrow(x, y, z, out); }
static inline void r_unit3_narrow_len(real_t x, real_t y, real_t z, real_t out[3], real_t *len)
{
    fx_unit3_narrow_len(x, y, z, out, len);
}
static inline void r_sincos_deg(real_t deg, real_t *s, real_t *c) { fx_sincos_deg(deg, s, c); }
static inline uint8_t r_to_u8(real_t c)
{
    if (c <= 0)
        return 0;
    if (c >= FX_ONE)
        return 255;
#if FX_MUL64_PARTIAL
    /* 0 < c < 2^F: c 255 + 2^(F-1) < 2^(F+8) fits 32 bits (F <= 24), one
     * MULS instead of a 64-bit product (GCC narrows it itself on the M3) */
    return (uint8_t)(((uint32_t)c * 255u + (uint32_t)FX_HALF) >> FX_FRAC_BITS);
#else
    return (uint8_t)(((int64_t)c * 255 + FX_HALF) >> FX_FRAC_BITS);
#endif
}
static inline bool r_ldexp(real_t v, int32_t k, real_t *out)
{
    int64_t w = v;
    for (; k > 0; k--) {
        w *= 2;
        if (w > FX_MAX || w < FX_MIN)
            return false;
    }
    for (; k < 0; k++)
        w /= 2;
    *out = (real_t)w;
    return true;
}
/* the scale is folded into the fraction bits: exact, one rounding */
static inline bool r_from_decimal_scaled(bool neg, uint64_t mant, int32_t exp10, int32_t scale_log2,
                                         real_t *out)
{
    return fx_from_decimal(neg, mant, exp10, FX_FRAC_BITS + scale_log2, (uint32_t)FX_MAX, out);
}
static inline bool shine_from_decimal(bool neg, uint64_t mant, int32_t exp10, shine_t *out)
{
    int32_t v;
    if (neg || !fx_from_decimal(false, mant, exp10, R_SHINE_FRAC_BITS, (uint32_t)INT32_MAX, &v))
        return false;
    *out = (shine_t)v;
    return true;
}

#endif

static inline real_t r_abs(real_t a) { return a < 0 ? -a : a; }
static inline real_t r_min(real_t a, real_t b) { return a < b ? a : b; }
static inline real_t r_max(real_t a, real_t b) { return a > b ? a : b; }

_Static_assert(sizeof(real_t) == RT_REAL_BYTES, "RT_REAL_BYTES (rt_config.h) is the size of real_t");

#endif
