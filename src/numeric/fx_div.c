/* fx_div.c - quotients of the fixed layer (fx.h, fx_div.h). */
#include "fx_div.h"

/* The binary long division of fx_div64, from n's top bit, up to 64
 * steps; the wide quotients of intersection tests (fx_wdiv, fx_wdiv_fx)
 * have their own digit division below. */
static uint64_t udiv64(uint64_t n, uint64_t d)
{
    uint64_t q = 0, r = 0;
    for (int i = n ? 63 - fx_clz64(n) : -1; i >= 0; i--) {
        r = (r << 1) | ((n >> i) & 1u); /* r < d <= 2^63: no overflow */
        q <<= 1;
        if (r >= d) {
            r -= d;
            q |= 1;
        }
    }
    return q;
}

int64_t fx_div64(int64_t n, int64_t d)
{
    uint64_t q = udiv64(n < 0 ? 0 - (uint64_t)n : (uint64_t)n, d < 0 ? 0 - (uint64_t)d : (uint64_t)d);
    uint64_t sgn = 0u - (uint64_t)((n < 0) != (d < 0));
    return (int64_t)((q ^ sgn) - sgn); /* INT64_MIN / -1 wraps, as in C's on these targets */
}

/* 2^63 / d for d in [2^31, 2^32), never above it and less than 2^-27.4
 * relative under it (both checked for every d): fx_recip_q63_div (fx_div.h)
 * or, without a divide, fx_recip_step from a line per 64th of [1, 2)
 * under the curve, packed as in rsqrt_q31_sqrt (drop per unit of d's
 * bits 24..9). Inline into fx_recip_q31 (the BVH's, three a ray), out of
 * line for the quotients (recip_q63): the whole-program build would
 * otherwise weigh the two alike and call it from the BVH too. */
static RT_INLINE uint32_t recip_q63_inline(uint32_t d)
{
#if FX_RECIP_TABLE
    static const uint32_t line[64] = {
        0xFFFC6BF1u, 0xFC0C23D2u, 0xF83AB3B5u, 0xF4864B99u, 0xF0EDB37Eu, 0xED702B65u,
        0xEA0BA34Cu, 0xE6C01335u, 0xE38BEB1Fu, 0xE06DD309u, 0xDD655AF4u, 0xDA71AAE0u,
        0xD791FACDu, 0xD4C582BBu, 0xD20B1AA9u, 0xCF628298u, 0xCCCB1A88u, 0xCA43D278u,
        0xC7CC8269u, 0xC5642A5Au, 0xC30AB24Cu, 0xC0BF2A3Eu, 0xBE818A31u, 0xBC50E224u,
        0xBA2D3A18u, 0xB815B20Cu, 0xB60A5A01u, 0xB409D9F5u, 0xB21549EBu, 0xB02AD9E0u,
        0xAE4B21D6u, 0xAC7561CCu, 0xAAA9C1C3u, 0xA8E771BAu, 0xA72E39B1u, 0xA57DC9A8u,
        0xA3D651A0u, 0xA2372198u, 0xA09FF990u, 0x9F10A188u, 0x9D894981u, 0x9C08E979u,
        0x9A901972u, 0x991E416Bu, 0x97B3A165u, 0x964F215Eu, 0x94F17958u, 0x939A0952u,
        0x9248A94Cu, 0x90FD3146u, 0x8FB77140u, 0x8E77C13Bu, 0x8D3D8136u, 0x8C083130u,
        0x8AD8712Bu, 0x89ADC126u, 0x8887F921u, 0x8767691Du, 0x864B2918u, 0x8533D914u,
        0x8420A90Fu, 0x8312290Bu, 0x8207F107u, 0x8101D903u
    };
    uint32_t c = line[(d >> 25) & 63];
    uint32_t y = c - (c & 0x7FFu) * ((d >> 9) & 0xFFFFu);
    return fx_recip_step(d, y);
#else
    return fx_recip_q63_div(d);
#endif
}

static uint32_t recip_q63(uint32_t d) { return recip_q63_inline(d); }

#if FX_RECIP_TABLE
uint32_t fx_recip_q31(uint32_t x) { return recip_q63_inline(x) >> 1; }
#endif

/* All ones when v < 0, else 0 */
static inline uint32_t sign_mask(int32_t v) { return 0u - (uint32_t)(v < 0); }

/* |a| as unsigned, for any a (INT32_MIN included), without a branch */
static inline uint32_t abs_u32(int32_t a)
{
    uint32_t m = sign_mask(a);
    return ((uint32_t)a ^ m) - m;
}

/* |v| as unsigned, for any v (INT64_MIN gives 2^63) */
static inline uint64_t abs_u64(int64_t v) { return v < 0 ? 0u - (uint64_t)v : (uint64_t)v; }

/* fx_div where a or b is 0: b == 0 saturates by the sign of a */
RT_COLD RT_NOINLINE static fx_t div_zero(fx_t a, fx_t b)
{
    if (b != 0)
        return 0;
    FX_ON_SATURATE();
    return a > 0 ? FX_MAX : a < 0 ? FX_MIN : 0;
}

/* div_round's end for estimates q_est near 2^31 or above (under the
 * floor by 12 at most): rounded with 64-bit remainders, saturated from
 * 2^31 on. */
RT_COLD RT_NOINLINE static fx_t div_big(uint32_t n, uint32_t d, uint32_t q_est, uint32_t sgn)
{
    uint64_t q = q_est;
    uint64_t r = ((uint64_t)n << FX_FRAC_BITS) + (d >> 1) - q * d;
    while (r >= d) {
        q++;
        r -= d;
    }
    if (q > (uint64_t)FX_MAX) {
        FX_ON_SATURATE();
        q = (uint64_t)FX_MAX;
    }
    return (fx_t)(((uint32_t)q ^ sgn) - sgn);
}

/* round(n 2^F / d) for n, d > 0, half away from zero, with the sign of
 * sgn (0 or all ones) and saturated. */
static RT_INLINE fx_t div_round(uint32_t n, uint32_t d, uint32_t sgn)
{
    /* n 2^F / d = (n' / d') 2^(31 - sh), n' and d' being n and d
     * normalised to [2^31, 2^32); q, its floor from the reciprocal of d',
     * is at most 2^-27.4 under it, so 12 under at most below 2^31. */
    int tn = fx_clz32(n), td = fx_clz32(d);
    int sh = 31 - FX_FRAC_BITS + tn - td;
    if (sh < 0) { /* n' / d' > 1/2, so the quotient is above 2^31 */
        FX_ON_SATURATE();
        return (fx_t)(((uint32_t)FX_MAX ^ sgn) - sgn);
    }
    uint32_t q = 0;
    if (sh < 32)
        q = (uint32_t)(fx_umul64(n << tn, recip_q63(d << td)) >> 32) >> sh;
    if (q >= 0x7F000000u) /* within 2^24 of 2^31: rare */
        return div_big(n, d, q, sgn);
    /* Rounded half away from zero, the quotient is floor((n 2^F + d/2) / d)
     * (d odd or even). The remainder of that from q is below 2^32, so its
     * low word is exact; each step up takes one d off. */
    uint32_t r = (n << FX_FRAC_BITS) + (d >> 1) - q * d;
    while (r >= d) {
        q++;
        r -= d;
    }
    return (fx_t)((q ^ sgn) - sgn);
}

fx_t fx_div(fx_t a, fx_t b)
{
    uint32_t n = abs_u32(a), d = abs_u32(b);
    if (n == 0 || d == 0)
        return div_zero(a, b);
    return div_round(n, d, sign_mask(a ^ b));
}

/* fx_div(FX_ONE, b), with the numerator's normalisation folded away */
fx_t fx_recip(fx_t b)
{
    uint32_t d = abs_u32(b);
    if (d == 0)
        return div_zero(FX_ONE, b);
    return div_round(FX_ONE, d, sign_mask(b));
}

/* Quotients of 64-bit numerators (fx_wdiv, fx_wdiv_fx), exact and with
 * C's truncation, from 32-bit divisions: a normalised divisor's top 16
 * bits give each 15-bit digit of the quotient, the digit or one over,
 * and the remainder tells which. Where a 32-bit division is an
 * instruction (UDIV on the M3, divu on RISC-V) a quotient costs a few
 * dozen instructions, not libgcc's general 64-bit division (over 80 on
 * the M3 with its call), which the firmware then does not link. */
#define MASK30 0x3FFFFFFFu

/* One digit of (r 2^15 + x) / v for v in [2^30, 2^31), r < v, x < 2^15,
 * the remainder left in *r. With vh = v's top 16 bits (>= 2^15), r / vh
 * is the digit or one over (v's dropped bits, below 2^15, add less than
 * r / vh 2^15 / v < 1); the remainder is then in [-v, v), an int32. */
static RT_INLINE uint32_t div_digit15(uint32_t *r, uint32_t x, uint32_t v)
{
    uint32_t q = RT_UDIV32(*r, v >> 15);
    int32_t t = (int32_t)((*r << 15 | x) - q * v);
    uint32_t over = 0u - ((uint32_t)t >> 31); /* all ones when one over */
    *r = (uint32_t)t + (v & over);
    return q + over;
}

/* (r 2^30 + x) / v for v in [2^30, 2^31), r < v, x < 2^30: two digits */
static RT_INLINE uint32_t div_tail30(uint32_t r, uint32_t x, uint32_t v)
{
    uint32_t hi = div_digit15(&r, x >> 15, v);
    return hi << 15 | div_digit15(&r, x & 0x7FFFu, v);
}

/* The high word of (hi 2^32 + lo) << s, for 0 <= s < 32 */
static inline uint32_t shl_hi(uint32_t hi, uint32_t lo, int s) { return hi << s | (lo >> 1) >> (31 - s); }

/* (nt 2^30 + x) / d for 0 < d < 2^31, x < 2^30 and a quotient below
 * 2^62: nt / d by a 32-bit division, then the remainder and x by the
 * digits, normalised by s (d << s in [2^30, 2^31); (r 2^30 + x) 2^s /
 * 2^30 < (r + 1) 2^s, below the normalised divisor). */
static RT_INLINE uint64_t div_62_31(uint32_t nt, uint32_t x, uint32_t d)
{
    uint32_t qh = RT_UDIV32(nt, d), r = nt - qh * d;
    int s = fx_clz32(d) - 1;
    return (uint64_t)qh << 30 | div_tail30(r << s | x >> (30 - s), (x << s) & MASK30, d << s);
}

fx_t fx_wdiv(fx_wide_t a, fx_wide_t b)
{
    /* a / b = (a 2^F + b/2) / b rounded half away from zero, on the
     * magnitudes, with |a| first below 2^(62-F) so that a 2^F fits: both
     * magnitudes shifted right by the excess bits at once (the same bits
     * as halving a and b with C's truncation until it is). */
    const int lim_bits = 62 - FX_FRAC_BITS;
    uint64_t n = abs_u64(a), d = abs_u64(b);
    if (n >> lim_bits) {
        int k = 64 - lim_bits - fx_clz64(n);
        n >>= k;
        d >>= k;
    }
    if (d == 0) {
        FX_ON_SATURATE();
        return a > 0 ? FX_MAX : a < 0 ? FX_MIN : 0;
    }
    n = (n << FX_FRAC_BITS) + (d >> 1); /* < 2^63 */
    uint32_t q;
    if (d >> 31) {
        /* v = d >> t, d's top 31 bits: the quotient of n / 2 by v (below
         * 2^32), shifted right by t - 1, is n / (v 2^t), the quotient or
         * up to 3 over (v 2^t is under d by less than 2^t, which adds
         * less than (n / d) / v < 2^32 / 2^30 units); the remainder,
         * above -2^63, tells. */
        uint32_t dhi = (uint32_t)(d >> 32), nt = (uint32_t)(n >> 31), v = (uint32_t)d >> 1;
        int sh = 0; /* t - 1 */
        if (dhi) {
            int s = fx_clz32(dhi);
            v = shl_hi(dhi, (uint32_t)d, s) >> 1;
            sh = 32 - s;
        }
        uint32_t qh = RT_UDIV32(nt, v); /* below 4 */
        q = (uint32_t)((uint64_t)(qh << 30 | div_tail30(nt - qh * v, (uint32_t)n >> 1 & MASK30, v)) >> sh);
        for (int64_t rem = (int64_t)(n - fx_umul64x(q, d)); rem < 0; rem += (int64_t)d)
            q--;
    } else {
        q = (n >> 31) >= d ? 0x80000000u : (uint32_t)div_62_31((uint32_t)(n >> 30), (uint32_t)n & MASK30, (uint32_t)d);
    }
    if (q >> 31) { /* 2^31 or more */
        FX_ON_SATURATE();
        q = (uint32_t)FX_MAX;
    }
    uint32_t sgn = 0u - (uint32_t)((a < 0) != (b < 0));
    return (fx_t)((q ^ sgn) - sgn);
}

/* fx_wdiv_fx where a is 0 or -2^31 or |w| >= 2^(62-F): C's division */
RT_COLD RT_NOINLINE static fx_wide_t wdiv_fx_rare(fx_wide_t w, fx_t a)
{
    if (a == 0) {
        FX_ON_SATURATE();
        return w > 0 ? INT64_MAX : w < 0 ? -INT64_MAX : 0;
    }
    if (abs_u64(w) >> (62 - FX_FRAC_BITS) == 0)
        return fx_div64(w * FX_ONE, a);
    return (fx_wide_t)((uint64_t)fx_div64(w, a) << FX_FRAC_BITS); /* wraps: (w / a) 2^F modulo 2^64, as C's product */
}

/* w 2^F / a, truncated, while |w| < 2^(62-F) (else (w / a) 2^F) */
fx_wide_t fx_wdiv_fx(fx_wide_t w, fx_t a)
{
    uint64_t m = abs_u64(w);
    uint32_t d = abs_u32(a);
    if (m >> (62 - FX_FRAC_BITS) || d - 1 >= 0x7FFFFFFFu)
        return wdiv_fx_rare(w, a);
    uint64_t q = div_62_31((uint32_t)(m >> (30 - FX_FRAC_BITS)), (uint32_t)m << FX_FRAC_BITS & MASK30, d);
    uint64_t sgn = 0u - (uint64_t)((w < 0) != (a < 0));
    return (fx_wide_t)((q ^ sgn) - sgn);
}

fx_wide_t fx_wdiv_int(fx_wide_t w, int32_t n) { return fx_div64(w, n); }
