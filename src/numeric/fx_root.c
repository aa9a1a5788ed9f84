/* fx_root.c - square roots and unit vectors (fx_root.h), from one
 * reciprocal square root: a line per 2^26 of the operand (fx_rsqrt_line.h)
 * and a Newton step. FX_FAST_MATH drops the exact last-unit fix of square
 * roots (within 0.76 ulp instead of 0.5). */
#include "fx_root.h"
#include "fx_rsqrt_line.h"

/* |v| as unsigned, for any v (INT64_MIN gives 2^63) */
static inline uint64_t abs_u64(int64_t v) { return v < 0 ? 0u - (uint64_t)v : (uint64_t)v; }

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
    int n = 64 - fx_clz64(m) - 28;
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
