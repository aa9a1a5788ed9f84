/*
 * fx.c - the fixed layer's operations that run while rendering: the
 * quotients (fx_div.h), the square roots and unit vectors (fx_root.h) and
 * the power (fx_pow.h), and the saturation count (fx.h). Set-up maths is
 * in fx_setup.c.
 *
 * They are one file because they share the wide products (fx_wide.h),
 * whose inlining a whole-program build decides file by file: split by
 * idea, the Cortex-M0 firmware inlines its reciprocal and power
 * differently (more instructions a ray on the micro:bit and the Pico).
 */
#include "fx_div.h"
#include "fx_pow.h"
#include "fx_root.h"
#include "fx_rsqrt_line.h"

#if FX_COUNT_SATURATIONS
volatile uint32_t fx_saturations;
#endif

/* FX_FAST_MATH trades exactness for instructions: no exact last-unit fix
 * of square roots (within 0.76 ulp), and 16 instead of 24 log2 bits and a
 * degree-6 exp2 in powers. Quotients are exact either way: their fix
 * costs next to nothing. */
#if FX_FAST_MATH
#define POW_LOG_BITS 16
#define EXP2_DEGREE 6
#else
#define POW_LOG_BITS 24
#define EXP2_DEGREE 9
#endif

#if FX_MUL64_PARTIAL == 2
int64_t fx_mul64_call(int32_t a, int32_t b) { return fx_mul64_parts(a, b); }
uint64_t fx_umul64_call(uint32_t a, uint32_t b) { return fx_umul64_parts(a, b); }
#endif

/* Leading zero bits of a non-zero value: fx_clz32 (fx.h), and for 64 bits */
static int clz64(uint64_t v)
{
    uint32_t hi = (uint32_t)(v >> 32);
    return hi ? fx_clz32(hi) : 32 + fx_clz32((uint32_t)v);
}

/* The binary long division of fx_div64, from n's top bit, up to 64
 * steps; the wide quotients of intersection tests (fx_wdiv, fx_wdiv_fx)
 * have their own digit division below. */
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

int64_t fx_div64(int64_t n, int64_t d)
{
    uint64_t q = udiv64(n < 0 ? 0 - (uint64_t)n : (uint64_t)n, d < 0 ? 0 - (uint64_t)d : (uint64_t)d);
    uint64_t sgn = 0u - (uint64_t)((n < 0) != (d < 0));
    return (int64_t)((q ^ sgn) - sgn); /* INT64_MIN / -1 wraps, as in C's on these targets */
}

/* One Newton step y' = y (3 - x y^2) / 2 towards 2^31 / sqrt(x / 2^30),
 * for x in [2^30, 2^32) and y within 3.2% of it, never above 2^31. Every
 * operand fits 32 bits (x y^2 / 2^30 is within 7% of 2^31), so each
 * product is one 32x32->64 multiply, and the bits are those of the same
 * step on 64-bit operands: y (2^32 + e) >> 32 = y + (y e >> 32). */
static inline uint32_t rsqrt_step(uint32_t x, uint32_t y)
{
    uint32_t y2 = (uint32_t)(fx_umul64(y, y) >> 31);   /* y^2 / 2^31 */
    uint32_t xy2 = (uint32_t)(fx_umul64(x, y2) >> 30); /* ~2^31 */
    int32_t e = (int32_t)(0x80000000u - xy2);          /* 2^31 - x y^2 */
    return y + (uint32_t)(int32_t)(fx_mul64((int32_t)y, e) >> 32);
}

/* 2^31 / sqrt(x / 2^30) for x in [2^30, 2^32), within 2^-11.4 and never
 * above it: a line per 2^26 of x (fx_rsqrt_line.h; x^-1/2 is convex, so
 * each is its chord moved down to touch it, its slope rounded steeper).
 * One 32-bit product. */
static inline uint32_t rsqrt_line(uint32_t x)
{
    static const uint32_t line[FX_RSQRT_LINES] = FX_RSQRT_LINE_INIT;
    uint32_t c = line[(x >> 26) - 16];
    return c - (c & 0x7FFu) * ((x >> 10) & 0xFFFFu);
}

/* 1/sqrt(x / 2^30) in Q.31 for x in [2^30, 2^32): the line above and one
 * Newton step (relative error below 2^-22, the step's own rounding
 * included; checked for every x). fx_unit3's bits are these. */
static uint32_t rsqrt_q31(uint32_t x) { return rsqrt_step(x, rsqrt_line(x)); }

/* 2^31 / sqrt(x / 2^30) for square roots, where only the accuracy
 * counts: the line (within 2^-11.4), then one Newton step on high words
 * (the step above with 2^-27 more rounding) and 8 units off: within
 * 2^-22 under 2^31 / sqrt((x + 1) / 2^30) and never above it (checked
 * for every x). */
static inline uint32_t rsqrt_q31_sqrt(uint32_t x)
{
    uint32_t y = rsqrt_line(x);
    uint32_t y2 = (uint32_t)(fx_umul64(y, y) >> 32);   /* Y^2 2^30 */
    uint32_t t = (uint32_t)(fx_umul64(x, y2) >> 32);   /* X Y^2 2^28, ~2^28 */
    int32_t e = (int32_t)(((uint32_t)1 << 28) - t);
    return y + ((uint32_t)(fx_mul64((int32_t)y, e) >> 32) << 3) - 8;
}

/* round(sqrt(v)) for 0 <= v < 2^60. With v = u 2^-2k, u in [2^62, 2^64)
 * and k >= 2: g, under sqrt(u) by less than 2^-22 relative, then one
 * Newton step g + (u - g^2) / (2 sqrt(u)) on the exact residual, never
 * above sqrt(u) and less than 1.01 under it (checked for every x). So
 * g / 2^k is less than 0.26 under sqrt(v), its floor r is the answer or
 * one under it, and the exact v - r (r + 1) tells which:
 * (r + 1/2)^2 = r (r + 1) + 1/4. */
static inline uint32_t isqrt_round(uint64_t v)
{
    uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v, x, ulo;
    int s;
    if (hi) {
        s = fx_clz32(hi) & ~1; /* >= 2 */
        x = hi << s | lo >> (32 - s);
        ulo = lo << s;
    } else {
        if (lo == 0)
            return 0;
        s = fx_clz32(lo) & ~1;
        x = lo << s;
        ulo = 0;
        s += 32;
    }
    uint32_t y = rsqrt_q31_sqrt(x);
    uint32_t g = (uint32_t)(fx_umul64(x, y) >> 32) << 2;
    uint64_t res = ((uint64_t)x << 32 | ulo) - fx_umul64(g, g); /* < 2^43 */
    g += (uint32_t)(fx_umul64((uint32_t)(res >> 16), y) >> 47);
#if FX_FAST_MATH
    return ((g >> (s / 2 - 1)) + 1) >> 1; /* rounded: within 0.76 */
#else
    uint32_t r = g >> s / 2;
    if (fx_umul64(r, r + 1) < v)
        r++;
    return r;
#endif
}

/* 2^63 / d for d in [2^31, 2^32), never above it and less than 2^-27.4
 * relative under it (both checked for every d): fx_recip_q63_div (fx_div.h)
 * or, without a divide, fx_recip_step from a line per 64th of [1, 2)
 * under the curve, packed as in rsqrt_q31_sqrt (drop per unit of d's
 * bits 24..9). */
static uint32_t recip_q63(uint32_t d)
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

#if FX_RECIP_TABLE
uint32_t fx_recip_q31(uint32_t x) { return recip_q63(x) >> 1; }
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
        int k = 64 - lim_bits - clz64(n);
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

/* fx_wsqrt for w < 0 or w >= 2^60 (a root of 2^30 or more, rare): w < 0
 * gives 0, roots that round to 2^31 or more saturate, else r (twice the
 * root of w / 4, within 2 of the root) fixed with e = w - r^2 both ways
 * ((r +- 1/2)^2 = r^2 +- r + 1/4). */
RT_COLD RT_NOINLINE static fx_t wsqrt_big(fx_wide_t w, uint32_t r)
{
    if (w < 0)
        return 0;
    /* sqrt(2^62 - 2^32) rounds to 2^31 - 1; from (2^31 - 1/2)^2 on, the
     * root rounds to 2^31 or more */
    if (w >= ((int64_t)1 << 62) - ((int64_t)1 << 32))
        return w > ((int64_t)1 << 62) - ((int64_t)1 << 31) ? fx_sat64(FX_MAX + (int64_t)1) : FX_MAX;
    int64_t e = w - (int64_t)fx_umul64(r, r);
    for (; e > (int64_t)r; r++)
        e -= 2 * (int64_t)r + 1;
    for (; e <= -(int64_t)r; r--)
        e += 2 * (int64_t)r - 1;
    return (fx_t)r;
}

fx_t fx_wsqrt(fx_wide_t w)
{
    /* one inline copy of isqrt_round serves both ranges */
    bool big = ((uint64_t)w >> 60) != 0;
    uint32_t r = isqrt_round((uint64_t)w >> (big ? 2 : 0));
    return big ? wsqrt_big(w, 2 * r) : (fx_t)r;
}

fx_wide_t fx_wdiv_int(fx_wide_t w, int32_t n) { return fx_div64(w, n); }

fx_t fx_sqrt(fx_t a) { return a <= 0 ? 0 : fx_wsqrt((fx_wide_t)a << FX_FRAC_BITS); }

/* v >> n (arithmetic) for 0 < n < 64, where the result fits 32 bits. */
static inline int32_t shr_to32(int64_t v, int n)
{
    if (n < 32)
        return (int32_t)((uint32_t)v >> n | (uint32_t)(v >> 32) << (32 - n));
    return (int32_t)(v >> 32) >> (n - 32);
}

/* v / |v| for v brought to 28 bits in its largest component (the
 * squared length then lies in [2^54, 2^58) and each v y fits 64 bits);
 * returns 4 |v| (below 2^31), within 2^-21 relative and a unit */
static uint32_t unit3_scaled(int32_t vx, int32_t vy, int32_t vz, fx_t out[3])
{
    uint64_t len2 = (uint64_t)(fx_mul64(vx, vx) + fx_mul64(vy, vy) + fx_mul64(vz, vz));
    /* len2 = (xn / 2^30) 2^(62 - s), s even: 6 or 8 (its high word is in
     * [2^22, 3 2^24)), which one compare tells on cores without CLZ */
    uint32_t hi = (uint32_t)(len2 >> 32);
#if defined(__ARM_FEATURE_CLZ)
    int s = fx_clz32(hi) & ~1;
#else
    int s = hi >> 24 ? 6 : 8;
#endif
    uint32_t xn = hi << s | (uint32_t)len2 >> (32 - s);
    /* 1 / |v| = (r / 2^31) 2^-((62 - s) / 2), so out = v r 2^-(62 - s/2 - F)
     * rounded; the shift exceeds 32, so the high word of v r suffices */
    int32_t r = (int32_t)rsqrt_q31(xn);
    int shift = 30 - s / 2 - FX_FRAC_BITS;
    int32_t half = (int32_t)1 << (shift - 1);
    out[0] = ((int32_t)(fx_mul64(vx, r) >> 32) + half) >> shift;
    out[1] = ((int32_t)(fx_mul64(vy, r) >> 32) + half) >> shift;
    out[2] = ((int32_t)(fx_mul64(vz, r) >> 32) + half) >> shift;
    /* |v| = len2 / |v| = (xn / 2^30) (r / 2^31) 2^(31 - s/2), r within
     * 2^-21 of the root's reciprocal: so is the length. 4 |v| is the
     * product's high word (at least 2^28) times 2^(4 - s/2). */
    return (uint32_t)(fx_umul64(xn, (uint32_t)r) >> 32) << (4 - s / 2);
}

void fx_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3])
{
    uint64_t m = abs_u64(x) | abs_u64(y) | abs_u64(z);
    if (m == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    /* Bring the largest component to 28 bits (the OR of the magnitudes
     * has the same bit length as the largest). */
    int n = 64 - clz64(m) - 28;
    if (n <= 0)
        unit3_scaled((int32_t)x * ((int32_t)1 << -n), (int32_t)y * ((int32_t)1 << -n), (int32_t)z * ((int32_t)1 << -n),
                     out);
    else
        unit3_scaled(shr_to32(x, n), shr_to32(y, n), shr_to32(z, n), out);
}

/* The same for a vector of fx_t: 32-bit magnitudes and shifts, the same
 * bits. (|INT32_MIN| is 2^31 as a uint32_t, as abs_u64 gives it.) */
void fx_unit3_narrow_len(fx_t x, fx_t y, fx_t z, fx_t out[3], fx_t *len)
{
    uint32_t m = (x < 0 ? 0u - (uint32_t)x : (uint32_t)x) | (y < 0 ? 0u - (uint32_t)y : (uint32_t)y) |
                 (z < 0 ? 0u - (uint32_t)z : (uint32_t)z);
    if (m == 0) {
        out[0] = out[1] = out[2] = 0;
        if (len)
            *len = 0;
        return;
    }
    int n = 32 - fx_clz32(m) - 28;
    uint32_t l4 = n <= 0 ? unit3_scaled(x * ((int32_t)1 << -n), y * ((int32_t)1 << -n), z * ((int32_t)1 << -n), out)
                         : unit3_scaled(x >> n, y >> n, z >> n, out);
    if (!len)
        return;
    /* |(x, y, z)| = (l4 / 4) 2^n: n <= 3 (a sum of three 31-bit squares) */
    int sh = 2 - n;
    uint32_t q = sh > 0 ? (l4 + ((uint32_t)1 << (sh - 1))) >> sh : l4 << -sh; /* l4 < 2^31: no wrap */
    *len = q > (uint32_t)FX_MAX ? FX_MAX : (fx_t)q;
}

void fx_unit3_narrow(fx_t x, fx_t y, fx_t z, fx_t out[3]) { fx_unit3_narrow_len(x, y, z, out, 0); }

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

fx_t fx_pow_unit(fx_t x, uint32_t s)
{
    if (x <= 0)
        return 0;
    if (x >= FX_ONE || s == 0)
        return FX_ONE;
    /* s an integer, 1 <= s <= 128: a tenth of the general path's
     * instructions, for the exponents scenes pick by hand (fx_pow.h) */
    if (fx_pow_unit_int_path(x, s))
        return fx_pow_unit_int(x, s);
    /* y = s * log2(x) in Q.24; below -(F+2) the result rounds to 0. */
    int64_t y = fx_mul64xx(s, log2_q24(x)) / ((int64_t)1 << FX_POW_FRAC_BITS);
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
