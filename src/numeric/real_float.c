/*
 * real_float.c - the float backend's own power function, x^s for the
 * Phong highlight (r_pow_unit), in float + - * / and integer operations
 * only: no libm. A board with an IEEE single-precision FPU (Cortex-M4F,
 * FPv4-SP) then renders bit for bit what the host's float build renders
 * (x86-64 SSE), provided both evaluate in float (FLT_EVAL_METHOD 0),
 * round to nearest, do not contract a * b + c into a fused multiply-add
 * (-ffp-contract=off; GCC's default under -std=c11) and keep subnormals
 * (no flush-to-zero). A libm powf differs between C libraries.
 *
 * Method: x^s = 2^(s log2 x), with s log2 x carried as a float pair
 * (hi + lo, about 44 bits) so that a large exponent does not magnify the
 * error of the logarithm.
 *   log2 x = k + log2(1/c) + log2(1 + r), x = 2^k z, z in [0.71875,
 *            1.4375), c ~ 1/z from a 32-row table (12 significant bits,
 *            so z c and r = z c - 1 are exact pairs; c = 1 next to z = 1,
 *            so log2 x keeps its relative accuracy as x -> 1), |r| <= 1/32,
 *            log(1 + r) by its series to r^7 with r^2 as an exact pair;
 *   2^y    = 2^n 2^(j/32) 2^g, |g| <= 1/64, 2^(j/32) a float pair from a
 *            32-row table, 2^g - 1 by its series to g^4.
 * The products of pairs are Dekker's (split at 12 bits by masking the
 * representation), the sums Knuth's two-sum: exact in round to nearest.
 * The tables and constants are tools/real_float_tables.py's output (60
 * digits, split into the nearest float plus the remainder's float).
 *
 * Accuracy against double pow, for results in the normal range: relative
 * error at most 6.11e-8 (0.532 units in the last place; faithful, and the
 * nearest float in 99.9% of cases), measured over 3.9e8 (x, s): every
 * 16th float x in [2^-24, 1) and every float in [1 - 2^-4, 1 + 2^-11)
 * with 25 exponents from 1 to 524287 (the reader's limit), 1, 1.5, 2, 3,
 * 5, 7.3, 10, 20, ..., 10^5, 2 10^5, 524287, and 5e7 random pairs with x
 * in [2^-24, 1 + 2^-7), s in [1, 524287]. x^1 = x exactly. Subnormal
 * results are within 0.76 2^-149 of x^s; beyond the float range, +inf.
 * The exception: s = 4, 8, 16, 32, 64 take k squarings instead (s = 2 is
 * one, correctly rounded), within 2^k 2^-24 relative.
 * tests/unit/test_geometry.c asserts 6.2e-8 on a sparser sweep.
 */
#include "real.h"

#if RT_BACKEND_FLOAT

typedef union {
    float f;
    uint32_t u;
} float_bits_t;

static float from_bits(uint32_t u)
{
    float_bits_t b;
    b.u = u;
    return b.f;
}

static uint32_t to_bits(float f)
{
    float_bits_t b;
    b.f = f;
    return b.u;
}

/* a = *hi + *lo exactly, *hi holding the leading 12 significant bits */
static void split12(float a, float *hi, float *lo)
{
    *hi = from_bits(to_bits(a) & 0xFFFFF000u);
    *lo = a - *hi;
}

/* a b = *hi + *lo exactly (Dekker), barring overflow and underflow */
static void two_prod(float a, float b, float *hi, float *lo)
{
    float ah, al, bh, bl;
    split12(a, &ah, &al);
    split12(b, &bh, &bl);
    float p = a * b;
    *hi = p;
    *lo = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

/* a + b = s + (the result) exactly, where s = a + b rounded (Knuth) */
static float two_sum_err(float a, float b, float s)
{
    float bb = s - a;
    return (a - (s - bb)) + (b - bb);
}

/* z in [0.71875, 1.4375) in 32 rows: row i holds z whose mantissa bits
 * minus LOG_M0 (mod 2^23) have i as their top 5 bits; c ~ 1/z with 12
 * significant bits, and log2(1/c) = hi + lo. */
#define LOG_M0 0x380000u /* z = 0.71875 */
#define LOG_BITS 5
static const struct {
    float c, hi, lo;
} log_table[1 << LOG_BITS] = {
    { 0x1.606p+0f, -0x1.d807eep-2f, -0x1.c60086p-27f },
    { 0x1.58ep+0f, -0x1.b83f8p-2f, -0x1.158536p-27f },
    { 0x1.51ep+0f, -0x1.99f44p-2f, 0x1.8cadbcp-28f },
    { 0x1.4bp+0f, -0x1.7b957ap-2f, -0x1.8a3558p-27f },
    { 0x1.446p+0f, -0x1.5db71cp-2f, -0x1.0ce858p-28f },
    { 0x1.3e2p+0f, -0x1.40f906p-2f, 0x1.150b56p-27f },
    { 0x1.382p+0f, -0x1.24d7f8p-2f, -0x1.22573cp-31f },
    { 0x1.324p+0f, -0x1.08c588p-2f, -0x1.9b4f3cp-27f },
    { 0x1.2cap+0f, -0x1.dac51p-3f, 0x1.92b926p-31f },
    { 0x1.274p+0f, -0x1.a576eep-3f, -0x1.7cbf62p-29f },
    { 0x1.22p+0f, -0x1.70742ep-3f, 0x1.621fbp-28f },
    { 0x1.1dp+0f, -0x1.3d1146p-3f, -0x1.b3514cp-28f },
    { 0x1.182p+0f, -0x1.0a1722p-3f, 0x1.6d02c6p-30f },
    { 0x1.136p+0f, -0x1.af1e96p-4f, -0x1.661fa6p-30f },
    { 0x1.0ecp+0f, -0x1.4b0752p-4f, 0x1.fa895p-32f },
    { 0x1.0a6p+0f, -0x1.d58602p-5f, -0x1.69a922p-30f },
    { 0x1.062p+0f, -0x1.177042p-5f, -0x1.d3f06p-33f },
    { 0x1p+0f, 0x0p+0f, 0x0p+0f }, /* z in [63/64, 1) */
    { 0x1p+0f, 0x0p+0f, 0x0p+0f }, /* z in [1, 33/32) */
    { 0x1.e92p-1f, 0x1.0e17bcp-4f, 0x1.984a6p-30f },
    { 0x1.daep-1f, 0x1.bccf2ap-4f, -0x1.4ccc36p-30f },
    { 0x1.cd8p-1f, 0x1.32d13ep-3f, 0x1.1a4baep-29f },
    { 0x1.c0ep-1f, 0x1.84c5ap-3f, -0x1.4f1b28p-29f },
    { 0x1.b4ep-1f, 0x1.d4d5b8p-3f, -0x1.88a3f6p-30f },
    { 0x1.a98p-1f, 0x1.11646ep-2f, 0x1.de451ap-28f },
    { 0x1.9ecp-1f, 0x1.37320ap-2f, 0x1.078362p-27f },
    { 0x1.948p-1f, 0x1.5c2a0ap-2f, -0x1.2bd944p-27f },
    { 0x1.8acp-1f, 0x1.80359ep-2f, 0x1.73208p-27f },
    { 0x1.818p-1f, 0x1.a33d26p-2f, -0x1.a7029ep-33f },
    { 0x1.78ap-1f, 0x1.c5a5bcp-2f, 0x1.d89218p-29f },
    { 0x1.702p-1f, 0x1.e75efp-2f, -0x1.e2648ep-27f },
    { 0x1.682p-1f, 0x1.03ea3p-1f, -0x1.f212a8p-26f },
};

/* 2^(j/32) = hi + lo */
#define EXP_BITS 5
static const struct {
    float hi, lo;
} exp_table[1 << EXP_BITS] = {
    { 0x1p+0f, 0x0p+0f },
    { 0x1.059b0ep+0f, -0x1.9d4f52p-25f },
    { 0x1.0b5586p+0f, 0x1.9f3122p-25f },
    { 0x1.11301ep+0f, -0x1.fdb496p-25f },
    { 0x1.172b84p+0f, -0x1.c15742p-27f },
    { 0x1.1d4874p+0f, -0x1.d2e8cap-25f },
    { 0x1.2387a6p+0f, 0x1.ceac48p-25f },
    { 0x1.29e9ep+0f, -0x1.5c0424p-25f },
    { 0x1.306fep+0f, 0x1.4636e2p-25f },
    { 0x1.371a74p+0f, -0x1.18aac6p-25f },
    { 0x1.3dea64p+0f, 0x1.824684p-25f },
    { 0x1.44e086p+0f, 0x1.8624b4p-30f },
    { 0x1.4bfdaep+0f, -0x1.593abcp-25f },
    { 0x1.5342b6p+0f, -0x1.2c561p-25f },
    { 0x1.5ab07ep+0f, -0x1.5bd5ecp-27f },
    { 0x1.6247ecp+0f, -0x1.f8b55p-25f },
    { 0x1.6a09e6p+0f, 0x1.9fcef4p-26f },
    { 0x1.71f75ep+0f, 0x1.1d8beep-25f },
    { 0x1.7a1148p+0f, -0x1.829fdp-25f },
    { 0x1.82589ap+0f, -0x1.accc7cp-26f },
    { 0x1.8ace54p+0f, 0x1.15506ep-27f },
    { 0x1.93737cp+0f, -0x1.e64744p-25f },
    { 0x1.9c4918p+0f, 0x1.51f848p-27f },
    { 0x1.a5503cp+0f, -0x1.b83b54p-25f },
    { 0x1.ae89fap+0f, -0x1.a94b14p-26f },
    { 0x1.b7f77p+0f, -0x1.a09438p-25f },
    { 0x1.c199bep+0f, -0x1.3d56b2p-27f },
    { 0x1.cb720ep+0f, -0x1.8837ccp-27f },
    { 0x1.d5818ep+0f, -0x1.822dbcp-27f },
    { 0x1.dfc974p+0f, -0x1.908c94p-25f },
    { 0x1.ea4afap+0f, 0x1.52486cp-27f },
    { 0x1.f50766p+0f, -0x1.246ebp-26f },
};

#define INV_LN2_HI 0x1.715476p+0f /* 1/ln 2 = hi + lo */
#define INV_LN2_LO 0x1.4ae0cp-26f

/* log2 x = *hi + *lo for finite x > 0 */
static void log2_pair(float x, float *hi, float *lo)
{
    uint32_t u = to_bits(x);
    int32_t k = 0;
    if (u < 0x00800000u) { /* subnormal: scale into the normal range (exact) */
        u = to_bits(x * 0x1p23f);
        k = -23;
    }
    /* x = 2^k z: z's exponent is -1 or 0 so that z falls in [0.71875, 1.4375) */
    uint32_t mant = u & 0x7FFFFFu;
    int32_t biased = (int32_t)(u >> 23);
    unsigned i = (unsigned)(((mant - LOG_M0) & 0x7FFFFFu) >> (23 - LOG_BITS));
    float z;
    if (mant >= LOG_M0) {
        z = from_bits(0x3F000000u | mant);
        k += biased - 126;
    } else {
        z = from_bits(0x3F800000u | mant);
        k += biased - 127;
    }
    /* r = z c - 1 = rh + rl: zh c and zl c are exact (12 x 12 bits), and
     * zh c - 1 too (zh c is within a factor of 2 of 1) */
    float c = log_table[i].c, zh, zl;
    split12(z, &zh, &zl);
    float a = zh * c - 1, b = zl * c;
    float rh = a + b, rl = two_sum_err(a, b, rh);

    /* ln(1 + r) = r - r^2/2 + r^3 (1/3 - r/4 + r^2/5 - r^3/6 + r^4/7) + rl (1 - r)
     * to 2^-38 |r|, as sh + sl */
    float r2, r2l;
    two_prod(rh, rh, &r2, &r2l);
    float half = -0.5f * r2; /* exact; |half| <= |rh| / 64 */
    float sh = rh + half;
    float sl = half - (sh - rh); /* exact error of that sum (|rh| >= |half|) */
    float poly = 0x1.555556p-2f +
                 rh * (-0.25f + rh * (0x1.99999ap-3f + rh * (-0x1.555556p-3f + rh * 0x1.24924ap-3f)));
    sl += (rh * r2 * poly + (rl - rl * rh)) - 0.5f * r2l;

    /* log2(1 + r) = (sh + sl) / ln 2 = ph + pl */
    float ph, pl;
    two_prod(sh, INV_LN2_HI, &ph, &pl);
    pl += sh * INV_LN2_LO + sl * INV_LN2_HI;

    /* k + log2(1/c) + log2(1 + r): k and the table's hi are exact, the
     * sums' rounding errors are kept */
    float kf = (float)k;
    float t1 = kf + log_table[i].hi;
    float e1 = two_sum_err(kf, log_table[i].hi, t1);
    float t2 = t1 + ph;
    float e2 = two_sum_err(t1, ph, t2);
    float low = ((log_table[i].lo + pl) + e1) + e2;
    *hi = t2 + low;
    *lo = low - (*hi - t2);
}

float r_pow_float(float x, float s)
{
    if (!(x > 0))
        return x <= 0 ? 0 : x; /* 0 for x <= 0 (as r_pow_unit), NaN stays NaN */
    if (s == 0)
        return 1;
    if (to_bits(x) >= 0x7F800000u) /* +inf */
        return x;
    /* s an integer, 2 <= s <= 64: its binary powers, each product
     * rounded once (relative error below s 2^-24), a tenth of the general
     * path's work, for the exponents scenes pick by hand (real.h) */
    if (r_pow_float_small_int(s)) {
        float p = r_pow_float_int(x, s);
        if (p >= 0x1p-100f) /* no factor was subnormal (x <= 1: each is >= p); else the general path */
            return p;
    }

    /* y = s log2 x = yh + yl */
    float lh, ll, yh, yl;
    log2_pair(x, &lh, &ll);
    two_prod(s, lh, &yh, &yl);
    if (yh < -160) /* below half the least subnormal: 0 */
        return 0;
    if (yh > 129) /* above the largest float: +inf */
        return from_bits(0x7F800000u);
    yl += s * ll;

    /* y = n/32 + g: n the integer nearest 32 yh (by the 1.5 * 2^23 shifter,
     * |32 yh| < 2^22), yh - n/32 exact, |g| <= 1/64 + |yl| */
    float t = yh * 32;
    float nf = (t + 0x1.8p23f) - 0x1.8p23f;
    int32_t n = (int32_t)nf;
    float g = (yh - nf * (1.0f / 32)) + yl;
    unsigned j = (unsigned)((uint32_t)n & ((1u << EXP_BITS) - 1));
    int32_t e = (n - (int32_t)j) / (1 << EXP_BITS); /* exact division */

    /* 2^g - 1 = g ln2 + (g ln2)^2/2 + (g ln2)^3/6 + (g ln2)^4/24, to 2^-40 */
    float w = g * (0x1.62e43p-1f + g * (0x1.ebfbep-3f + g * (0x1.c6b08ep-5f + g * 0x1.3b2ab6p-7f)));
    float th = exp_table[j].hi;
    float p = th + (th * w + exp_table[j].lo);

    /* times 2^e, in two steps where 2^e is not a normal float */
    if (e > 127)
        return p * 0x1p127f * from_bits((uint32_t)e << 23); /* 2^127 2^(e - 127) */
    if (e < -126)
        return p * from_bits((uint32_t)(e + 64 + 127) << 23) * 0x1p-64f;
    return p * from_bits((uint32_t)(e + 127) << 23);
}

#else
typedef int real_float_unused_t; /* ISO C forbids an empty translation unit */
#endif
