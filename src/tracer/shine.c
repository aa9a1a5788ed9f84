/* shine.c - the fixed build's Phong power (shine.h): x^s as 2^(s log2 x),
 * the logarithm bit by bit and 2^f by its Taylor series, each step one
 * 32x32 product. */
#include "shine.h"

#if RT_BACKEND_FIXED

/* FX_FAST_MATH trades exactness for instructions: 16 instead of 24 log2
 * bits and a degree-6 exp2. */
#if FX_FAST_MATH
#define POW_LOG_BITS 16
#define EXP2_DEGREE 6
#else
#define POW_LOG_BITS 24
#define EXP2_DEGREE 9
#endif

/* log2(x) for x > 0 in Q.F, result in Q.24 (always < 0 for x < 1), bit
 * by bit: squaring the mantissa m in [1, 2) (Q.30, truncated) doubles its
 * log, and a square of 2 or more gives the next bit. m fits 31 bits, so
 * each square is one 32x32 product: m is kept doubled (a = 2m, Q.31),
 * where the high word of a^2 is the Q.30 square. */
static int32_t log2_q24(fx_t x)
{
    int s = fx_clz32((uint32_t)x);
    uint32_t a = (uint32_t)x << s; /* x = (a / 2^31) 2^(31 - s - F) */
    uint32_t bits = 0;
    for (int i = 0; i < POW_LOG_BITS; i++) {
        uint32_t sq = (uint32_t)(fx_umul64(a, a) >> 32); /* m^2, Q.30 */
        bits = bits << 1 | sq >> 31;
        a = sq >> 31 ? sq & ~1u : sq << 1; /* m^2 >= 2: halved, its low bit dropped */
    }
    return (31 - s - FX_FRAC_BITS) * ((int32_t)1 << 24) + (int32_t)(bits << (24 - POW_LOG_BITS));
}

/* 2^f for f in [0, 1) given in Q.24, result in Q.30. Taylor series of
 * e^(f ln 2) to degree 9; the coefficients are (ln 2)^k / k! in Q.30,
 * truncation error below 1e-8. Every partial sum is below 2 (Q.30 fits
 * 31 bits), so each step is one 32x32 product. */
static uint32_t exp2_frac_q30(int32_t f_q24)
{
    static const uint32_t coef[10] = {
        1073741824u, 744261118u, 257941248u, 59597083u, 10327387u,
        1431680u, 165394u, 16377u, 1419u, 109u,
    };
    uint32_t z = (uint32_t)f_q24 << 6; /* Q.30 */
    uint32_t p = coef[EXP2_DEGREE];
    for (int k = EXP2_DEGREE - 1; k >= 0; k--)
        p = coef[k] + (uint32_t)(fx_umul64(p, z) >> 30);
    return p;
}

fx_t fx_pow_unit(fx_t x, shine_t s)
{
    if (x <= 0)
        return 0;
    if (x >= FX_ONE || s == 0)
        return FX_ONE;
    /* s an integer, 1 <= s <= 128: a tenth of the general path's
     * instructions, for the exponents scenes pick by hand (shine.h) */
    if (fx_pow_unit_int_path(x, s))
        return fx_pow_unit_int(x, s);
    /* y = s * log2(x) in Q.24; below -(F+2) the result rounds to 0. */
    int64_t y = fx_mul64xx(s, log2_q24(x)) / ((int64_t)1 << R_SHINE_FRAC_BITS);
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

#else
typedef int shine_unused_t; /* ISO C forbids an empty translation unit */
#endif
