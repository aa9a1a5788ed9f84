/* fx.c - the out-of-line fixed-point operations (see fx.h for accuracy). */
#include "fx.h"

#if FX_COUNT_SATURATIONS
volatile uint32_t fx_saturations;
#endif

/* FX_FAST_MATH trades exactness for instructions: one Newton step less
 * in the reciprocal square root (relative error 2^-20 instead of 2^-29),
 * no exact last-unit fix of square roots, 16 instead of 24 log2 bits and
 * a degree-6 exp2 in powers, and no exact last-unit fix of quotients. */
#if FX_FAST_MATH
#define RSQRT_STEPS 2
#define POW_LOG_BITS 16
#define EXP2_DEGREE 6
#else
#define RSQRT_STEPS 3
#define POW_LOG_BITS 24
#define EXP2_DEGREE 9
#endif

#if FX_MUL64_PARTIAL == 2
int64_t fx_mul64_call(int32_t a, int32_t b) { return fx_mul64_inline(a, b); }
uint64_t fx_umul64_call(uint32_t a, uint32_t b) { return fx_umul64_inline(a, b); }
#endif

/* Signed products of 64-bit operands through fx_umul64x: where the signed
 * product is defined, its bits are the same. (The plain path is a macro so
 * that its code stays exactly the product written out.) */
#if FX_MUL64_PARTIAL
static inline int64_t smul64(int64_t a, int64_t b) { return (int64_t)fx_umul64x((uint64_t)a, (uint64_t)b); }
#else
#define smul64(a, b) ((int64_t)(a) * (b))
#endif

/* Leading zero bits of a non-zero 64-bit value (CLZ on the M3). */
static int clz64(uint64_t v)
{
#if defined(__GNUC__)
    return __builtin_clzll(v);
#else
    int n = 0;
    while (!(v & ((uint64_t)1 << 63))) {
        v <<= 1;
        n++;
    }
    return n;
#endif
}

/* n / d (d != 0), truncated like C's: binary long division from n's top
 * bit, up to 64 steps. A few dozen bytes where libgcc's 64-bit division
 * is 700 on the M3, for set-up code (camera, sines, tangents); the wide
 * quotients of intersection tests (fx_wdiv, fx_wdiv_fx) keep C's
 * division, which a firmware links only when its scene needs them. */
static uint64_t udiv64(uint64_t n, uint64_t d)
{
    uint64_t q = 0, r = 0;
    for (int i = n ? 63 - clz64(n) : -1; i >= 0; i--) {
        r = (r << 1) | ((n >> i) & 1u); /* r < d <= 2^63: no overflow */
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1;
        }
    }
    return q;
}

static int64_t sdiv64(int64_t n, int64_t d)
{
    uint64_t q = udiv64(n < 0 ? 0 - (uint64_t)n : (uint64_t)n, d < 0 ? 0 - (uint64_t)d : (uint64_t)d);
    return (n < 0) != (d < 0) ? -(int64_t)q : (int64_t)q;
}

/* 1/sqrt(x / 2^30) in Q.31 for x in [2^30, 2^32): a 24-entry seed (within
 * 3.2%) and three Newton steps y' = y (3 - x y^2) / 2; relative error
 * below 2^-29. Multiplies only: the M3 has no 64-bit divide. */
static uint32_t rsqrt_q31(uint32_t x)
{
    static const uint32_t seed[24] = { /* 2^31 / sqrt((8 + i + 0.5) / 8) */
        2083365155u, 1970666148u, 1874477404u, 1791125178u, 1717986918u, 1653133683u,
        1595110809u, 1542797797u, 1495315679u, 1451963954u, 1412176548u, 1375490368u,
        1341522400u, 1309952745u, 1280511845u, 1252970736u, 1227133513u, 1202831433u,
        1179918260u, 1158266544u, 1137764631u, 1118314230u, 1099828424u, 1082230034u,
    };
    uint64_t y = seed[(x >> 27) - 8];
    for (int i = 0; i < RSQRT_STEPS; i++) {
        uint64_t y2 = fx_umul64x(y, y) >> 31;       /* Q.31 */
        uint64_t xy2 = fx_umul64x(x, y2) >> 30;     /* Q.31, close to 1 */
        y = fx_umul64x(y, ((uint64_t)3 << 31) - xy2) >> 32;
    }
    return (uint32_t)y;
}

/* v (> 0) as (x / 2^30) * 2^(62 - s) with x in [2^30, 2^32), s even. */
static uint32_t normalise_even(uint64_t v, int *s)
{
    *s = clz64(v) & ~1;
    return (uint32_t)((v << *s) >> 32);
}

/* round(sqrt(v)): estimate from the reciprocal square root, then fix the
 * last unit exactly with integer squares. */
static uint64_t isqrt64_round(uint64_t v)
{
    if (v == 0)
        return 0;
    int s;
    uint32_t x = normalise_even(v, &s);
    /* sqrt(v) = (x / 2^30) (y / 2^31) 2^((62 - s) / 2) */
    uint64_t r = fx_umul64(x, rsqrt_q31(x)) >> (30 + s / 2);
#if FX_FAST_MATH
    if (r > 0xFFFFFFFFu)
        r = 0xFFFFFFFFu;
    if (fx_umul64x(r, r) > v)
        r--;
#else
    while (fx_umul64x(r, r) > v)
        r--;
    while (r < 0xFFFFFFFFu && fx_umul64x(r + 1, r + 1) <= v)
        r++;
#endif
    /* (r + 1/2)^2 = r^2 + r + 1/4: round up when v - r^2 > r */
    return v - fx_umul64x(r, r) > r ? r + 1 : r;
}

/* 2^62 / x in Q.31 for x in [2^31, 2^32): a 16-bit estimate from one
 * 32-bit hardware divide (UDIV, 2..12 cycles on the M3), then one Newton
 * step y' = y (2 - x y); relative error below 2^-29. */
uint32_t fx_recip_q31(uint32_t x)
{
    uint32_t y = (0xFFFFFFFFu / (x >> 16)) << 14;          /* within 2^-15 */
    uint32_t two_minus_xy = 0u - (uint32_t)(fx_umul64(x, y) >> 31); /* 2^32 - x y */
    return (uint32_t)(fx_umul64(y, two_minus_xy) >> 31);
}

fx_t fx_div(fx_t a, fx_t b)
{
    if (b == 0) {
        FX_ON_SATURATE();
        return a > 0 ? FX_MAX : a < 0 ? FX_MIN : 0;
    }
    /* q = |a| 2^F / |b| from the reciprocal of |b| normalised to
     * [2^31, 2^32): an estimate within 2 of the truth, then fixed exactly
     * with the integer remainder (no 64-bit divide, which the M3 lacks). */
    uint64_t n = (uint64_t)(a < 0 ? -(int64_t)a : a);
    uint64_t d = (uint64_t)(b < 0 ? -(int64_t)b : b);
    int s = clz64(d) - 32;
    uint64_t y = fx_recip_q31((uint32_t)(d << s));   /* 2^62 / (d 2^s) */
    int shift = 62 - FX_FRAC_BITS - s;            /* q = n y 2^-shift */
    uint64_t ny = fx_umul64x(n, y);               /* < 2^62 */
    uint64_t q = shift >= 0 ? ny >> shift : (shift > -8 ? ny << -shift : UINT64_MAX);
    bool neg = (a < 0) != (b < 0);
    if (q > ((uint64_t)1 << 32))
        return fx_sat64(neg ? -((int64_t)1 << 32) : (int64_t)1 << 32);
    int64_t r = (int64_t)(n << FX_FRAC_BITS) - (int64_t)fx_umul64x(q, d);
#if !FX_FAST_MATH
    while (r < 0) {
        q--;
        r += (int64_t)d;
    }
    while (r >= (int64_t)d) {
        q++;
        r -= (int64_t)d;
    }
#endif
    if (2 * r >= (int64_t)d) /* round half away from zero */
        q++;
    return fx_sat64(neg ? -(int64_t)q : (int64_t)q);
}

fx_t fx_recip(fx_t b) { return fx_div(FX_ONE, b); }

fx_t fx_wdiv(fx_wide_t a, fx_wide_t b)
{
    const int64_t lim = (int64_t)1 << (62 - FX_FRAC_BITS);
    while (a >= lim || a <= -lim) {
        a /= 2;
        b /= 2;
    }
    if (b == 0) {
        FX_ON_SATURATE();
        return a > 0 ? FX_MAX : a < 0 ? FX_MIN : 0;
    }
    int64_t n = a * FX_ONE;
    int64_t h = (b < 0 ? -b : b) / 2;
    return fx_sat64((n >= 0 ? n + h : n - h) / b);
}

fx_wide_t fx_wdiv_fx(fx_wide_t w, fx_t a)
{
    const int64_t lim = (int64_t)1 << (62 - FX_FRAC_BITS);
    if (a == 0) {
        FX_ON_SATURATE();
        return w > 0 ? INT64_MAX : w < 0 ? -INT64_MAX : 0;
    }
    if (w < lim && w > -lim)
        return (w * FX_ONE) / a;
    return (w / a) * FX_ONE;
}

fx_wide_t fx_wdiv_int(fx_wide_t w, int32_t n) { return sdiv64(w, n); }

fx_t fx_sqrt(fx_t a)
{
    if (a <= 0)
        return 0;
    return (fx_t)isqrt64_round((uint64_t)a << FX_FRAC_BITS);
}

fx_t fx_wsqrt(fx_wide_t w)
{
    if (w <= 0)
        return 0;
    uint64_t r = isqrt64_round((uint64_t)w);
    return r > (uint64_t)FX_MAX ? fx_sat64(FX_MAX + (int64_t)1) : (fx_t)r;
}

void fx_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3])
{
    int64_t v[3] = { x, y, z };
    uint64_t m = 0;
    for (int i = 0; i < 3; i++) {
        uint64_t a = (uint64_t)(v[i] < 0 ? -v[i] : v[i]);
        m |= a;
    }
    if (m == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    /* Bring the largest component to 28 bits (the OR of the magnitudes
     * has the same bit length as the largest): the squared length stays
     * below 2^58 and v * y below 2^59. */
    int len_bits = 64 - clz64(m);
    uint64_t len2 = 0;
    for (int i = 0; i < 3; i++) {
        v[i] = len_bits <= 28 ? v[i] * ((int64_t)1 << (28 - len_bits)) : v[i] >> (len_bits - 28);
        len2 += (uint64_t)smul64(v[i], v[i]);
    }
    /* 1 / |v| = (y / 2^31) 2^-((62 - s) / 2) */
    int s;
    int64_t r = rsqrt_q31(normalise_even(len2, &s));
    unsigned shift = (unsigned)(62 - s / 2 - FX_FRAC_BITS);
    for (int i = 0; i < 3; i++)
        out[i] = (fx_t)fx_round_shift(smul64(v[i], r), shift);
}

/* log2(x) for x > 0 in Q.F, result in Q.24 (always < 0 for x < 1). */
static int32_t log2_q24(fx_t x)
{
    uint32_t m = (uint32_t)x;
    int s = 0;
    while (m < ((uint32_t)1 << 30)) {
        m <<= 1;
        s++;
    }
    /* x = (m / 2^30) * 2^(30 - s - F), with m/2^30 in [1, 2). */
    int32_t result = (30 - s - FX_FRAC_BITS) * ((int32_t)1 << 24);
    uint64_t mm = m;
    for (int bit = 23; bit >= 24 - POW_LOG_BITS; bit--) {
        mm = fx_umul64x(mm, mm) >> 30;
        if (mm >= ((uint64_t)2 << 30)) {
            mm >>= 1;
            result += (int32_t)1 << bit;
        }
    }
    return result;
}

/* 2^f for f in [0, 1) given in Q.24, result in Q.30. Taylor series of
 * e^(f ln 2) to degree 9; the coefficients are (ln 2)^k / k! in Q.30,
 * truncation error below 1e-8. */
static uint64_t exp2_frac_q30(int32_t f_q24)
{
    static const uint32_t coef[10] = {
        1073741824u, 744261118u, 257941248u, 59597083u, 10327387u,
        1431680u, 165394u, 16377u, 1419u, 109u,
    };
    uint64_t z = (uint64_t)f_q24 << 6; /* Q.30 */
    uint64_t p = coef[EXP2_DEGREE];
    for (int k = EXP2_DEGREE - 1; k >= 0; k--)
        p = coef[k] + (fx_umul64x(p, z) >> 30);
    return p;
}

fx_t fx_pow_unit(fx_t x, fx_shine_t s)
{
    if (x <= 0)
        return 0;
    if (x >= FX_ONE || s == 0)
        return FX_ONE;
    /* y = s * log2(x) in Q.24; below -(F+2) the result rounds to 0. */
    int64_t y = smul64(s, log2_q24(x)) / ((int64_t)1 << FX_SHINE_FRAC_BITS);
    if (y <= -(int64_t)(FX_FRAC_BITS + 2) * (1 << 24))
        return 0;
    int32_t yi = (int32_t)y;
    /* y = -n + f with n >= 1 integer, f in [0, 1). */
    int32_t n = (int32_t)(((int64_t)(1 << 24) - 1 - yi) >> 24); /* -floor(y), y <= 0 */
    int32_t f = yi + n * (1 << 24);
    uint64_t p = exp2_frac_q30(f);      /* Q.30, in [1, 2) */
    unsigned shift = (unsigned)(30 - FX_FRAC_BITS + n);
    return (fx_t)((p + ((uint64_t)1 << (shift - 1))) >> shift);
}

/* Q.30 sin and cos of x in [0, pi/2] (Q.30), by nested Taylor series
 * to x^15 / x^16; truncation error below 1e-11. */
static int64_t mul_q30(int64_t a, int64_t b) { return smul64(a, b) / ((int64_t)1 << 30); }

static int64_t sin_q30(int64_t x)
{
    static const int32_t den[] = { 210, 156, 110, 72, 42, 20, 6 };
    int64_t x2 = mul_q30(x, x), t = (int64_t)1 << 30;
    for (unsigned i = 0; i < sizeof den / sizeof den[0]; i++)
        t = ((int64_t)1 << 30) - sdiv64(mul_q30(x2, t), den[i]);
    return mul_q30(x, t);
}

static int64_t cos_q30(int64_t x)
{
    static const int32_t den[] = { 240, 182, 132, 90, 56, 30, 12, 2 };
    int64_t x2 = mul_q30(x, x), t = (int64_t)1 << 30;
    for (unsigned i = 0; i < sizeof den / sizeof den[0]; i++)
        t = ((int64_t)1 << 30) - sdiv64(mul_q30(x2, t), den[i]);
    return t;
}

fx_wide_t fx_tan_deg_wide(fx_t deg)
{
    /* deg * (pi/180 in Q.40), to radians in Q.30 */
    int64_t rad = ((int64_t)deg * 19190098069) / ((int64_t)1 << (FX_FRAC_BITS + 10));
    int64_t s = sin_q30(rad), c = cos_q30(rad);
    if (c <= 0)
        return INT64_MAX;
    int64_t t30 = sdiv64(s * ((int64_t)1 << 30), c); /* tan in Q.30 (s < 2^30, fits) */
#if 2 * FX_FRAC_BITS >= 30
    return t30 * ((int64_t)1 << (2 * FX_FRAC_BITS - 30));
#else
    return fx_round_shift(t30, 30 - 2 * FX_FRAC_BITS);
#endif
}

void fx_sincos_deg(fx_t deg, fx_t *sin_out, fx_t *cos_out)
{
    /* reduce to [0, 360) degrees, then to a quadrant [0, 90] */
    int64_t full = (int64_t)360 * FX_ONE;
    int64_t a = deg - sdiv64(deg, full) * full;
    if (a < 0)
        a += full;
    int quadrant = (int)sdiv64(a, (int64_t)90 * FX_ONE);
    int64_t r = a - quadrant * (int64_t)90 * FX_ONE;
    int64_t rad = (r * 19190098069) / ((int64_t)1 << (FX_FRAC_BITS + 10));
    int64_t s = sin_q30(rad), c = cos_q30(rad);
    for (int q = 0; q < quadrant; q++) { /* rotate by 90 degrees */
        int64_t t = s;
        s = c;
        c = -t;
    }
    *sin_out = fx_sat64(fx_round_shift(s, 30 - FX_FRAC_BITS));
    *cos_out = fx_sat64(fx_round_shift(c, 30 - FX_FRAC_BITS));
}

bool fx_from_decimal(bool neg, uint64_t mant, int32_t exp10, unsigned frac_bits, uint32_t max, int32_t *out)
{
    uint64_t result;
    if (mant == 0) {
        *out = 0;
        return true;
    }
    if (exp10 >= 0) {
        /* An integer: scale up with an overflow check at every step. */
        uint64_t limit = (uint64_t)max >> frac_bits;
        uint64_t v = mant;
        for (int32_t i = 0; i < exp10; i++) {
            if (v > limit)
                return false;
            v *= 10;
        }
        if (v > limit)
            return false;
        result = v << frac_bits;
    } else {
        /* mant / 10^k by long division into binary fraction bits. */
        uint32_t k = (uint32_t)-exp10;
        while (k > 18) { /* keeps 10^k and r << 1 inside 64 bits */
            mant /= 10;
            k--;
        }
        uint64_t d = 1;
        for (uint32_t i = 0; i < k; i++)
            d *= 10;
        uint64_t q = mant / d, r = mant % d;
        if (q > ((uint64_t)max >> frac_bits))
            return false;
        result = q << frac_bits;
        for (int bit = (int)frac_bits - 1; bit >= 0; bit--) {
            r <<= 1;
            if (r >= d) {
                r -= d;
                result |= (uint64_t)1 << bit;
            }
        }
        /* Round to nearest; an exact half goes away from zero. */
        if (2 * r >= d)
            result++;
    }
    if (result > max)
        return false;
    *out = neg ? -(int32_t)result : (int32_t)result;
    return true;
}
