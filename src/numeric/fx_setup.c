/* fx_setup.c - trigonometry in degrees and decimal conversion
 * (fx_setup.h), for set-up code: the products are 64-bit and the
 * quotients long division (fx_div64), small code rather than fast. */
#include "fx_setup.h"
#include "fx_div.h"

/* Q.30 sin and cos of x in [0, pi/2] (Q.30), by nested Taylor series
 * to x^15 / x^16; truncation error below 1e-11. */
static int64_t mul_q30(int64_t a, int64_t b) { return fx_mul64xx(a, b) / ((int64_t)1 << 30); }

static int64_t sin_q30(int64_t x)
{
    static const int32_t den[] = { 210, 156, 110, 72, 42, 20, 6 };
    int64_t x2 = mul_q30(x, x), t = (int64_t)1 << 30;
    for (unsigned i = 0; i < sizeof den / sizeof den[0]; i++)
        t = ((int64_t)1 << 30) - fx_div64(mul_q30(x2, t), den[i]);
    return mul_q30(x, t);
}

static int64_t cos_q30(int64_t x)
{
    static const int32_t den[] = { 240, 182, 132, 90, 56, 30, 12, 2 };
    int64_t x2 = mul_q30(x, x), t = (int64_t)1 << 30;
    for (unsigned i = 0; i < sizeof den / sizeof den[0]; i++)
        t = ((int64_t)1 << 30) - fx_div64(mul_q30(x2, t), den[i]);
    return t;
}

/* deg (Q.F, |deg| < 2^31) times pi/180 in Q.40 (19190098069, 35 bits),
 * to radians in Q.30, truncated towards zero: the product takes up to
 * 66 bits, so it is formed in two parts that each fit. floor((a 2^20 + b) /
 * 2^(F+10)) = floor((a + floor(b / 2^20)) / 2^(F-10)), so the bits are
 * the single product's wherever that fitted. */
static int64_t deg_to_rad_q30(int64_t deg)
{
    const uint64_t k = 19190098069u, k_hi = k >> 20, k_lo = k & 0xFFFFFu;
    uint64_t m = deg < 0 ? 0 - (uint64_t)deg : (uint64_t)deg;
#if FX_FRAC_BITS >= 10
    uint64_t q = (m * k_hi + ((m * k_lo) >> 20)) >> (FX_FRAC_BITS - 10);
#else
    uint64_t q = (m * k_hi << (10 - FX_FRAC_BITS)) + ((m * k_lo) >> (FX_FRAC_BITS + 10));
#endif
    return deg < 0 ? -(int64_t)q : (int64_t)q;
}

fx_wide_t fx_wtan_deg(fx_t deg)
{
    int64_t rad = deg_to_rad_q30(deg);
    int64_t s = sin_q30(rad), c = cos_q30(rad);
    if (c <= 0)
        return INT64_MAX;
    int64_t t30 = fx_div64(s * ((int64_t)1 << 30), c); /* tan in Q.30 (s < 2^30, fits) */
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
    int64_t a = deg - fx_div64(deg, full) * full;
    if (a < 0)
        a += full;
    int quadrant = (int)fx_div64(a, (int64_t)90 * FX_ONE);
    int64_t r = a - quadrant * (int64_t)90 * FX_ONE;
    int64_t rad = deg_to_rad_q30(r);
    int64_t s = sin_q30(rad), c = cos_q30(rad);
    for (int q = 0; q < quadrant; q++) { /* rotate by 90 degrees */
        int64_t t = s;
        s = c;
        c = -t;
    }
    *sin_out = fx_sat64(fx_round_shift(s, 30 - FX_FRAC_BITS));
    *cos_out = fx_sat64(fx_round_shift(c, 30 - FX_FRAC_BITS));
}

bool fx_from_decimal(bool neg, uint64_t mant, int32_t exp10, int32_t frac_bits, uint32_t max, int32_t *out)
{
    uint64_t result;
    /* frac_bits < 0 (down to -24): multiples of 2^drop, found as the
     * multiples of 1 and then rounded at bit drop */
    uint32_t drop = frac_bits < 0 ? (uint32_t)-frac_bits : 0;
    uint32_t frac = frac_bits < 0 ? 0 : (uint32_t)frac_bits;
    uint64_t whole_max = ((uint64_t)max << drop | (((uint64_t)1 << drop) - 1)) >> frac;
    if (mant == 0) {
        *out = 0;
        return true;
    }
    if (exp10 >= 0) {
        /* An integer: scale up with an overflow check at every step. */
        uint64_t v = mant;
        for (int32_t i = 0; i < exp10; i++) {
            if (v > whole_max)
                return false;
            v *= 10;
        }
        if (v > whole_max)
            return false;
        result = drop ? (v + ((uint64_t)1 << (drop - 1))) >> drop : v << frac;
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
        if (q > whole_max)
            return false;
        if (drop) { /* the bits below 2^drop hold at least a half iff bit drop - 1 is set */
            result = (q >> drop) + (q >> (drop - 1) & 1u);
        } else {
            result = q << frac;
            for (int bit = (int)frac - 1; bit >= 0; bit--) {
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
    }
    if (result > max)
        return false;
    *out = neg ? -(int32_t)result : (int32_t)result;
    return true;
}
