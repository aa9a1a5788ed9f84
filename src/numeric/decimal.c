/* decimal.c - exact arithmetic on decimal numbers (decimal.h). */
#include "decimal.h"

/* Little-endian base-2^32 naturals, wide enough for both sides of a
 * comparison near 2^DECIMAL_P_LIMIT (mant 10^e against num 2^p). */
#define BIG_WORDS 14
typedef struct { uint32_t w[BIG_WORDS]; } big_t;
_Static_assert(BIG_WORDS * 32 >= 64 + 2 * DECIMAL_P_LIMIT + 32, "big_t holds a comparison's sides");

static void big_set(big_t *b, uint64_t v)
{
    *b = (big_t){ { (uint32_t)v, (uint32_t)(v >> 32) } };
}

static void big_mul10(big_t *b)
{
    uint64_t carry = 0;
    for (unsigned i = 0; i < BIG_WORDS; i++) {
        uint64_t t = (uint64_t)b->w[i] * 10u + carry;
        b->w[i] = (uint32_t)t;
        carry = t >> 32;
    }
}

static void big_shl(big_t *b, uint32_t n)
{
    for (; n >= 32; n -= 32) {
        for (unsigned i = BIG_WORDS - 1; i > 0; i--)
            b->w[i] = b->w[i - 1];
        b->w[0] = 0;
    }
    if (n)
        for (unsigned i = BIG_WORDS - 1; i < BIG_WORDS; i--)
            b->w[i] = b->w[i] << n | (i ? b->w[i - 1] >> (32 - n) : 0);
}

static int big_cmp(const big_t *a, const big_t *b)
{
    for (unsigned i = BIG_WORDS; i-- > 0;)
        if (a->w[i] != b->w[i])
            return a->w[i] < b->w[i] ? -1 : 1;
    return 0;
}

static int32_t bit_length(uint64_t v)
{
    int32_t n = 0;
    while (n < 64 && (v >> n) != 0)
        n++;
    return n;
}

/* floor and ceiling of e log2(10), |e| <= 200000 (the lexer's bound) */
static int32_t log2_10_floor(int32_t e) { return (int32_t)(e >= 0 ? (int64_t)e * 33219 / 10000 : -((-(int64_t)e * 33220 + 9999) / 10000)); }
static int32_t log2_10_ceil(int32_t e) { return -log2_10_floor(-e); }

int decimal_cmp(const decimal_t *d, uint32_t num, int32_t p)
{
    if (d->mant == 0)
        return -1;
    /* 2^(bm-1) 10^e <= |d| < 2^bm 10^e against 2^(bn-1+p) <= num 2^p < 2^(bn+p) */
    int32_t bm = bit_length(d->mant), bn = bit_length(num);
    if (bm + log2_10_ceil(d->exp10) <= bn - 1 + p)
        return -1;
    if (bm - 1 + log2_10_floor(d->exp10) >= bn + p)
        return 1;
    /* close: |p| is bounded by the callers, so e is too (both sides are
     * within a factor 2^5 of each other) */
    if (p > DECIMAL_P_LIMIT || p < -DECIMAL_P_LIMIT)
        return bm + log2_10_floor(d->exp10) < bn + p ? -1 : 1; /* unreachable for the callers */
    big_t x, y;
    big_set(&x, d->mant);
    big_set(&y, num);
    for (int32_t i = 0; i < d->exp10; i++)
        big_mul10(&x);
    for (int32_t i = 0; i < -d->exp10; i++)
        big_mul10(&y);
    big_shl(p < 0 ? &x : &y, (uint32_t)(p < 0 ? -p : p));
    return big_cmp(&x, &y);
}

int32_t decimal_exp2_bound(const decimal_t *d)
{
    /* an upper bound within 3 of the least, then down exactly; far
     * outside the clamp only the clamp matters, a function of the value */
    int32_t p = bit_length(d->mant) + log2_10_ceil(d->exp10);
    if (p > DECIMAL_EXP2_CLAMP + 4)
        return DECIMAL_EXP2_CLAMP;
    if (p < -DECIMAL_EXP2_CLAMP)
        return -DECIMAL_EXP2_CLAMP;
    while (decimal_cmp(d, 1, p - 1) < 0)
        p--;
    return p > DECIMAL_EXP2_CLAMP ? DECIMAL_EXP2_CLAMP : p < -DECIMAL_EXP2_CLAMP ? -DECIMAL_EXP2_CLAMP : p;
}

#if RT_BACKEND_DOUBLE || RT_BACKEND_FLOAT
real_t decimal_recip_scaled(const decimal_t *d, int32_t scale_log2)
{
    real_t v = 0;
    (void)r_from_decimal_scaled(false, d->mant, d->exp10, scale_log2, &v); /* in range: the caller's */
    return R_ONE / v;
}
#else
/* n -= m where m <= n */
static void big_sub(big_t *n, const big_t *m)
{
    uint64_t borrow = 0;
    for (unsigned i = 0; i < BIG_WORDS; i++) {
        uint64_t t = (uint64_t)n->w[i] - m->w[i] - borrow;
        n->w[i] = (uint32_t)t;
        borrow = t >> 63;
    }
}

real_t decimal_recip_scaled(const decimal_t *d, int32_t scale_log2)
{
    /* round(2^(F - k) / (mant 10^e)) = round(num / den) with both sides
     * whole: 2^(F-k) 10^-e over mant, or 2^(F-k) over mant 10^e (and a
     * power of two moved to the other side when F - k < 0) */
    big_t num, den;
    int32_t p = FX_FRAC_BITS - scale_log2;
    big_set(&num, 1);
    big_set(&den, d->mant);
    for (int32_t i = 0; i < -d->exp10; i++)
        big_mul10(&num);
    for (int32_t i = 0; i < d->exp10; i++)
        big_mul10(&den);
    big_shl(p >= 0 ? &num : &den, (uint32_t)(p >= 0 ? p : -p));
    big_shl(&num, 1); /* one bit more, for the rounding */
    /* twice the quotient is below 2^(F+12) <= 2^32: its bits from the top */
    uint32_t q = 0;
    for (int bit = FX_FRAC_BITS + 11; bit >= 0; bit--) {
        big_t m = den;
        big_shl(&m, (uint32_t)bit);
        q <<= 1;
        if (big_cmp(&num, &m) >= 0) {
            big_sub(&num, &m);
            q |= 1u;
        }
    }
    return (real_t)((q + 1u) >> 1); /* ties away from zero */
}
#endif
