/*
 * fx.h - signed fixed point for the tracer, Q(31-F).F with F = FX_FRAC_BITS.
 *
 * Default F = 20 (rt_config.h): range +-2047.999999, resolution 2^-20 = 9.5e-7.
 * Products keep a 64-bit intermediate; every conversion back to fx_t rounds
 * to nearest and saturates to +-FX_MAX (never wraps). FX_ON_SATURATE() is
 * called on each saturation so a debug build can count them.
 *
 * Accuracy (measured by tests/unit/test_fx.c over dense input sweeps; "ulp" is
 * one unit of the last place, 2^-F):
 *   fx_mul, fx_div        correctly rounded (<= 0.5 ulp)
 *   fx_recip              correctly rounded (<= 0.5 ulp)
 *   fx_wdiv               correctly rounded while |a| < 2^(62-F), else
 *                         both operands lose low bits first
 *   fx_wdiv_fx            truncated to 2^-2F while |w| < 2^(62-F)
 *   fx_sqrt, fx_wsqrt     correctly rounded (<= 0.5 ulp)
 *   fx_unit3              each component within 1 ulp of the true unit vector
 *   fx_unit3_narrow_len   fx_unit3_narrow's unit, the length within 2^-21
 *                         relative + 1 ulp
 *   fx_norm2              correctly rounded (the 64-bit sum's bits)
 *   fx_dot3_negative      exact
 *   fx_mul_weight(c, w)   within |c| 2^-16 + 0.5 ulp (w in [0, 1] to Q.15)
 *   fx_mul_small(a, e)    within 0.5 ulp + 4 |e| (|e| <= 2^-10)
 *   fx_cos3               within 2^-13 for unit vectors (a shading weight)
 *   fx_pow_unit(x, s)     within 2 ulp + 1e-7 * s relative of x^s for the
 *                         exact value of x (x itself carries 0.5 ulp); 0.5 ulp
 *                         + 2^-26 for s = 1, 2, 4, .., 64
 *   fx_tan_deg_wide       relative error < 3e-7 for 0.5 <= deg <= 89 (the sine
 *                         is Q.30, so small angles carry the most)
 *   fx_from_decimal       correctly rounded (the nearest fx_t, ties away)
 *                         for inputs with at most 18 fraction digits
 */
#ifndef FX_H
#define FX_H

#include <stdbool.h>
#include <stdint.h>

#include "rt_config.h"
#include "rt_prefix.h"

typedef int32_t fx_t;       /* Q(31-F).F scalar */
typedef int64_t fx_wide_t;  /* Q(63-2F).2F: an exact product of two fx_t */
typedef uint32_t fx_shine_t;/* unsigned Q20.12: Phong exponents up to ~1e6 */

#define FX_SHINE_FRAC_BITS 12
#define FX_ONE ((fx_t)1 << FX_FRAC_BITS)
#define FX_HALF ((fx_t)1 << (FX_FRAC_BITS - 1))
#define FX_MAX ((fx_t)INT32_MAX)
#define FX_MIN (-(fx_t)INT32_MAX) /* symmetric: negation never overflows */

/* n/d as fx_t, rounded; an integer constant expression (no float). */
#define FX_RATIO(n, d) \
    ((fx_t)((((int64_t)(n) * FX_ONE) + ((((int64_t)(n) < 0) == ((int64_t)(d) < 0)) ? (d) / 2 : -(d) / 2)) / (d)))

/* Overflow is never silent: every conversion that would overflow clamps
 * to +-FX_MAX and calls FX_ON_SATURATE(). A build with
 * FX_COUNT_SATURATIONS=1 counts them (the stress suite asserts the count). */
#ifndef FX_COUNT_SATURATIONS
#define FX_COUNT_SATURATIONS 0
#endif
#if FX_COUNT_SATURATIONS
extern volatile uint32_t fx_saturations;
/* One counter for every worker: a relaxed atomic add where the compiler
 * has one (the host's stress build renders on several threads), so no
 * count is lost; a plain one otherwise. */
#ifdef __ATOMIC_RELAXED
#define FX_ON_SATURATE() ((void)__atomic_fetch_add(&fx_saturations, 1u, __ATOMIC_RELAXED))
#else
#define FX_ON_SATURATE() ((void)fx_saturations++)
#endif
#endif
#ifndef FX_ON_SATURATE
#define FX_ON_SATURATE() ((void)0)
#endif

/* In range when the high word is the low word's sign and the low word is
 * not INT32_MIN (below FX_MIN): a compare and two branches on the M3. */
static inline fx_t fx_sat64(int64_t v)
{
    uint32_t lo = (uint32_t)v, hi = (uint32_t)((uint64_t)v >> 32);
    if (hi == 0u - (lo >> 31) && lo != 0x80000000u)
        return (fx_t)lo;
    FX_ON_SATURATE();
    return v > 0 ? FX_MAX : FX_MIN;
}

/* Leading zero bits of a non-zero 32-bit value: CLZ on the M3 (and
 * hosts); on cores without one (ARMv6-M, RISC-V without Zbb), where
 * __builtin_clz is a libgcc call, a binary search inline (as cheap, and
 * the caller keeps its registers across it). */
#ifndef FX_CLZ_BUILTIN
#if defined(__GNUC__) && (defined(__ARM_FEATURE_CLZ) || defined(__riscv_zbb) || !(defined(__arm__) || defined(__riscv)))
#define FX_CLZ_BUILTIN 1
#else
#define FX_CLZ_BUILTIN 0
#endif
#endif
static inline int fx_clz32(uint32_t v)
{
#if FX_CLZ_BUILTIN
    return __builtin_clz(v);
#else
    int n = 0;
    if (!(v >> 16)) { n = 16; v <<= 16; }
    if (!(v >> 24)) { n += 8; v <<= 8; }
    if (!(v >> 28)) { n += 4; v <<= 4; }
    if (!(v >> 30)) { n += 2; v <<= 2; }
    return n + (int)(~v >> 31);
#endif
}

/* Round a value with `shift` extra fraction bits to nearest (half up). */
static inline int64_t fx_round_shift(int64_t v, unsigned shift)
{
    return (v + ((int64_t)1 << (shift - 1))) >> shift;
}

/*
 * Wide products. Every 32x32->64 product of the fixed layer is fx_mul64
 * (signed) or fx_umul64 (unsigned); fx_mul64x (32x64) and fx_umul64x
 * (64x64, modulo 2^64) are built on them for 64-bit factors.
 * FX_MUL64_PARTIAL picks how they are computed:
 *   0  the plain C product: one SMULL/UMULL on the M3, one instruction on
 *      a host (the default everywhere but ARMv6-M);
 *   1  from four 16x16->32 partial products, inline: for cores with no
 *      long multiply. On ARMv6-M (Cortex-M0/M0+) the plain product is a
 *      call to libgcc's general 64x64 __aeabi_lmul (44 instructions, plus
 *      sign-extending both operands at the call); this is 17 instructions
 *      of inline assembly (the default when __ARM_ARCH_6M__ is defined);
 *   2  the same partial products out of line (fx_mul64_call and
 *      fx_umul64_call in fx.c; GCC still inlines them inside fx.c):
 *      smaller code than both 0 and 1 on ARMv6-M, 3 to 6 instructions
 *      more per product than 1 (bench/m0-mul.sh measures all three).
 * All three give the same bits for every input. The partial path is
 * inline assembly on ARMv6-M with GCC or clang (fewer instructions than
 * the C, which has no add-with-carry), and elsewhere (a host forcing the
 * path to test it) fx_mul64_partial / fx_umul64_partial, the same
 * arithmetic in C, which tests/unit/test_fx.c checks against the plain product.
 */
#ifndef FX_MUL64_PARTIAL
#if defined(__ARM_ARCH_6M__)
#define FX_MUL64_PARTIAL 1
#else
#define FX_MUL64_PARTIAL 0
#endif
#endif
#if !(FX_MUL64_PARTIAL >= 0 && FX_MUL64_PARTIAL <= 2)
#error "FX_MUL64_PARTIAL is 0, 1 or 2"
#endif
#if defined(__ARM_ARCH_6M__) && defined(__GNUC__)
#define FX_MUL64_ASM 1
#else
#define FX_MUL64_ASM 0
#endif

/* a = ah 2^16 + al with al = the low half (unsigned) and ah = a >> 16 (as
 * signed as a); the same for b. a b = ah bh 2^32 + (ah bl + al bh) 2^16 +
 * al bl, where each partial product fits 32 bits (al bl unsigned, the
 * cross terms below 2^31 in magnitude, ah bh below 2^30 for signed
 * inputs) and each cross term is added at bit 16 with its carry into the
 * high word. Right shifts of negative values are arithmetic (GCC, clang). */
static inline int64_t fx_mul64_partial(int32_t a, int32_t b)
{
    uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    int32_t ah = a >> 16, bh = b >> 16;
    int32_t m1 = ah * (int32_t)bl, m2 = (int32_t)al * bh;
    uint32_t lo = al * bl, hi = (uint32_t)(ah * bh);
    uint32_t t = (uint32_t)m1 << 16;
    lo += t;
    hi += (uint32_t)(m1 >> 16) + (lo < t);
    t = (uint32_t)m2 << 16;
    lo += t;
    hi += (uint32_t)(m2 >> 16) + (lo < t);
    return (int64_t)(((uint64_t)hi << 32) | lo);
}

static inline uint64_t fx_umul64_partial(uint32_t a, uint32_t b)
{
    uint32_t al = a & 0xFFFFu, bl = b & 0xFFFFu, ah = a >> 16, bh = b >> 16;
    uint32_t m1 = ah * bl, m2 = al * bh;
    uint32_t lo = al * bl, hi = ah * bh;
    uint32_t t = m1 << 16;
    lo += t;
    hi += (m1 >> 16) + (lo < t);
    t = m2 << 16;
    lo += t;
    hi += (m2 >> 16) + (lo < t);
    return ((uint64_t)hi << 32) | lo;
}

#if FX_MUL64_ASM
/* The same in Thumb-1, 17 instructions; SH is asrs (signed) or lsrs
 * (unsigned). In: h = a, b = b. Out: l = low word, h = high word. */
#define FX_MUL64_THUMB1(SH)                                                   \
    ".syntax unified\n\t"                                                    \
    "uxth  %[t], %[h]\n\t"         /* t = al */                              \
    SH "  %[h], %[h], #16\n\t"     /* h = ah */                              \
    "uxth  %[u], %[b]\n\t"         /* u = bl */                              \
    SH "  %[b], %[b], #16\n\t"     /* b = bh */                              \
    "movs  %[l], %[t]\n\t"                                                   \
    "muls  %[l], %[u], %[l]\n\t"   /* l = al bl */                           \
    "muls  %[u], %[h], %[u]\n\t"   /* u = ah bl */                           \
    "muls  %[h], %[b], %[h]\n\t"   /* h = ah bh */                           \
    "muls  %[b], %[t], %[b]\n\t"   /* b = al bh */                           \
    "lsls  %[t], %[u], #16\n\t"                                              \
    SH "  %[u], %[u], #16\n\t"                                               \
    "adds  %[l], %[l], %[t]\n\t"                                             \
    "adcs  %[h], %[h], %[u]\n\t"   /* += ah bl 2^16 */                       \
    "lsls  %[t], %[b], #16\n\t"                                              \
    SH "  %[b], %[b], #16\n\t"                                               \
    "adds  %[l], %[l], %[t]\n\t"                                             \
    "adcs  %[h], %[h], %[b]\n\t"   /* += al bh 2^16 */
/* Both operands constant, or one a constant power of two: the compiler
 * folds the plain product or turns it into shifts (no library call). */
#define FX_MUL64_PLAIN_CONST(a, b)                                            \
    ((__builtin_constant_p(a) && __builtin_constant_p(b)) ||                  \
     (__builtin_constant_p(a) && (a) > 0 && ((a) & ((a) - 1)) == 0) ||        \
     (__builtin_constant_p(b) && (b) > 0 && ((b) & ((b) - 1)) == 0))
#endif

/* The partial path inline: the assembly on ARMv6-M, else the C. */
static inline int64_t fx_mul64_inline(int32_t a, int32_t b)
{
#if FX_MUL64_ASM
    uint32_t l, t, u, h = (uint32_t)a, bb = (uint32_t)b;
    __asm__(FX_MUL64_THUMB1("asrs")
            : [l] "=&l"(l), [h] "+&l"(h), [t] "=&l"(t), [u] "=&l"(u), [b] "+&l"(bb)
            :
            : "cc");
    return (int64_t)(((uint64_t)h << 32) | l);
#else
    return fx_mul64_partial(a, b);
#endif
}

static inline uint64_t fx_umul64_inline(uint32_t a, uint32_t b)
{
#if FX_MUL64_ASM
    uint32_t l, t, u, h = a, bb = b;
    __asm__(FX_MUL64_THUMB1("lsrs")
            : [l] "=&l"(l), [h] "+&l"(h), [t] "=&l"(t), [u] "=&l"(u), [b] "+&l"(bb)
            :
            : "cc");
    return ((uint64_t)h << 32) | l;
#else
    return fx_umul64_partial(a, b);
#endif
}

#if FX_MUL64_PARTIAL == 2
int64_t fx_mul64_call(int32_t a, int32_t b);     /* fx_mul64_inline */
uint64_t fx_umul64_call(uint32_t a, uint32_t b); /* fx_umul64_inline */
#endif

/* a * b, signed 32x32 -> 64 */
static inline int64_t fx_mul64(int32_t a, int32_t b)
{
#if FX_MUL64_PARTIAL && FX_MUL64_ASM
    if (FX_MUL64_PLAIN_CONST(a, b))
        return (int64_t)a * b;
#endif
#if FX_MUL64_PARTIAL == 2
    return fx_mul64_call(a, b);
#elif FX_MUL64_PARTIAL == 1
    return fx_mul64_inline(a, b);
#else
    return (int64_t)a * b;
#endif
}

/* a * b, unsigned 32x32 -> 64 */
static inline uint64_t fx_umul64(uint32_t a, uint32_t b)
{
#if FX_MUL64_PARTIAL && FX_MUL64_ASM
    if (FX_MUL64_PLAIN_CONST(a, b))
        return (uint64_t)a * b;
#endif
#if FX_MUL64_PARTIAL == 2
    return fx_umul64_call(a, b);
#elif FX_MUL64_PARTIAL == 1
    return fx_umul64_inline(a, b);
#else
    return (uint64_t)a * b;
#endif
}

/* a * b for a 64-bit b: the plain product wherever that is defined (it
 * fits 64 bits). The partial path works modulo 2^64: with b = bh 2^32 +
 * bl, bl read as signed is bl - 2^32 [bl >= 2^31], so a b = a (int32)bl +
 * a (bh + [bl >= 2^31]) 2^32, of whose second term only the low word
 * reaches the result's high word. */
static inline int64_t fx_mul64x(int32_t a, int64_t b)
{
#if FX_MUL64_PARTIAL
    uint32_t bl = (uint32_t)b, bh = (uint32_t)((uint64_t)b >> 32) + (bl >> 31);
    uint64_t p = (uint64_t)fx_mul64(a, (int32_t)bl);
    uint32_t hi = (uint32_t)(p >> 32) + (uint32_t)a * bh;
    return (int64_t)(((uint64_t)hi << 32) | (uint32_t)p);
#else
    return (int64_t)a * b;
#endif
}

/* a * b modulo 2^64, the C semantics of a uint64_t product: the low words'
 * full product plus the cross products, which only reach the high word
 * (an operand the compiler knows fits 32 bits folds its cross term away). */
static inline uint64_t fx_umul64x(uint64_t a, uint64_t b)
{
#if FX_MUL64_PARTIAL
    uint32_t al = (uint32_t)a, bl = (uint32_t)b;
    uint64_t p = fx_umul64(al, bl);
    uint32_t hi = (uint32_t)(p >> 32) + al * (uint32_t)(b >> 32) + (uint32_t)(a >> 32) * bl;
    return ((uint64_t)hi << 32) | (uint32_t)p;
#else
    return a * b;
#endif
}

static inline fx_t fx_from_int(int32_t i) { return fx_sat64((int64_t)i * FX_ONE); }

static inline fx_t fx_mul(fx_t a, fx_t b)
{
    return fx_sat64(fx_round_shift(fx_mul64(a, b), FX_FRAC_BITS));
}

static inline fx_wide_t fx_wmul(fx_t a, fx_t b) { return fx_mul64(a, b); }
/* a e for |a| <= 2 and a small |e| <= 2^-10 (a correction term, such
 * as a Newton step's): one 32-bit product of a / 4 and e, whose product
 * stays under 2^(2F-11), within half a unit plus 4 |e| units of a e. e is
 * held to +-2^-10, so no input overflows. */
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
 * long multiply take the same bits from it. */
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

static inline fx_t fx_from_wide(fx_wide_t w) { return fx_sat64(fx_round_shift(w, FX_FRAC_BITS)); }

static inline fx_wide_t fx_to_wide(fx_t a) { return (int64_t)a * FX_ONE; }

fx_t fx_div(fx_t a, fx_t b);          /* b == 0 saturates by the sign of a */
fx_t fx_recip(fx_t b);                /* 1 / b */

/* Cores without a 32-bit divide instruction (ARMv6-M, where it is a
 * libgcc call of 40 to 130 instructions) seed reciprocals from a table. */
#ifndef FX_RECIP_TABLE
#if (defined(__arm__) && !defined(__ARM_FEATURE_IDIV)) || (defined(__riscv) && !defined(__riscv_div))
#define FX_RECIP_TABLE 1
#else
#define FX_RECIP_TABLE 0
#endif
#endif

/* Towards 2^63 / d for d in [2^31, 2^32) from y under it by less than
 * 2^-13.8: one Newton step y + y (1 - d y), where 2^31 - d y / 2^32 =
 * 2^31 (1 - d y / 2^63) is at most 1 over; 2 units off keep it under. */
static inline uint32_t fx_recip_step(uint32_t d, uint32_t y)
{
    uint32_t e = 0x80000000u - (uint32_t)(fx_umul64(d, y) >> 32);
    return y + ((uint32_t)(fx_umul64(y, e) >> 32) << 1) - 2;
}

/* 2^63 / d from a 32-bit divide (UDIV, 2..12 cycles on the M3) */
static inline uint32_t fx_recip_q63_div(uint32_t d) { return fx_recip_step(d, (0xFFFFFFFFu / ((d >> 16) + 1)) << 15); }

/* 2^62 / x for x in [2^31, 2^32), never above it and less than 2^-27
 * relative under: the reciprocal before rounding, for callers that scale
 * it themselves (the BVH's slabs, three a ray: inline where it is a
 * divide). */
#if FX_RECIP_TABLE
uint32_t fx_recip_q31(uint32_t x);
#else
static inline uint32_t fx_recip_q31(uint32_t x) { return fx_recip_q63_div(x) >> 1; }
#endif

/* a + b as fx_sat64 of the 64-bit sum, from the 32-bit sum and its
 * overflow flag (the M3's ADDS and BVS: 4 instructions instead of 10 when
 * in range). */
static inline fx_t fx_add_sat(fx_t a, fx_t b)
{
#if defined(__GNUC__)
    int32_t s;
    bool over = __builtin_add_overflow(a, b, &s);
    if (over || s == INT32_MIN) {
        FX_ON_SATURATE();
        return (over ? a : s) < 0 ? FX_MIN : FX_MAX; /* the true sum's sign */
    }
    return s;
#else
    return fx_sat64((int64_t)a + b);
#endif
}

/* a - b, saturated to 32 bits. */
static inline int32_t fx_sub_sat(fx_t a, fx_t b)
{
    int32_t d;
#if defined(__GNUC__)
    if (__builtin_sub_overflow(a, b, &d))
        d = a > b ? FX_MAX : FX_MIN;
    /* an empty barrier: without it GCC 12 forgets d is 32-bit after the
     * select and multiplies 64x64 (three instructions for one SMULL) */
    __asm__("" : "+r"(d));
#else
    int64_t w = (int64_t)a - b;
    d = w > FX_MAX ? FX_MAX : w < FX_MIN ? FX_MIN : (int32_t)w;
#endif
    return d;
}

/* (a - b) * c exactly, as Q.2F, the difference saturated to 32 bits:
 * one SMULL. */
static inline fx_wide_t fx_wmul_diff(fx_t a, fx_t b, fx_t c) { return fx_mul64(fx_sub_sat(a, b), c); }

/* The high word of a * b, that is the product / 2^32 rounded down: one
 * SMULL (the compiler keeps the high register). */
static inline int32_t fx_mul_hi(int32_t a, int32_t b)
{
#if defined(__GNUC__)
    __asm__("" : "+r"(a), "+r"(b)); /* as in fx_sub_sat: keeps one SMULL */
#endif
    return (int32_t)((uint64_t)fx_mul64(a, b) >> 32);
}

/* a . b, exact (Q.2F) */
static inline fx_wide_t fx_wdot3(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
    return fx_mul64(ax, bx) + fx_mul64(ay, by) + fx_mul64(az, bz);
}

/* a . b from components cut to Q(F - s) (arithmetic shifts), in 32-bit
 * products: the caller bounds the sum */
static inline int32_t fx_dot3_cut(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz, int s)
{
    return (ax >> s) * (bx >> s) + (ay >> s) * (by >> s) + (az >> s) * (bz >> s);
}

/* |a|^2 for |a| <= 2, rounded once: the bits of the 64-bit sum. Without a
 * long multiply, from 32-bit products: each component split at bit k =
 * F/2 into h = a >> k and l = a - h 2^k in [0, 2^k), so a^2 = h^2 2^F + 2
 * h l 2^k + l^2, and the rounding's floors nest: (2 M 2^k + L + 2^(F-1))
 * >> F = (2 M + ((L + 2^(F-1)) >> k)) >> k, M = sum h l, L = sum l^2. */
static inline fx_t fx_norm2(fx_t ax, fx_t ay, fx_t az)
{
#if FX_MUL64_PARTIAL && FX_FRAC_BITS % 2 == 0 && FX_FRAC_BITS >= 12
    const int k = FX_FRAC_BITS / 2;
    const uint32_t low = ((uint32_t)1 << k) - 1;
    int32_t hx = ax >> k, hy = ay >> k, hz = az >> k;
    int32_t lx = (int32_t)((uint32_t)ax & low), ly = (int32_t)((uint32_t)ay & low), lz = (int32_t)((uint32_t)az & low);
    int32_t l2 = lx * lx + ly * ly + lz * lz + ((int32_t)1 << (FX_FRAC_BITS - 1));
    return hx * hx + hy * hy + hz * hz + ((2 * (hx * lx + hy * ly + hz * lz) + (l2 >> k)) >> k);
#else
    return (fx_t)fx_round_shift(fx_wdot3(ax, ay, az, ax, ay, az), FX_FRAC_BITS);
#endif
}

/* a . b for unit vectors a and b (or up to 1.4 long), good to 2^-13 (a
 * cosine that weighs a colour): 32-bit products of the components cut to
 * Q.15, each within (|a_k| + |b_k|) 2^-15 of the exact one; every partial
 * sum of |a_k b_k| is at most |a| |b| (Cauchy-Schwarz), under 2^31. */
static inline fx_t fx_cos3(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
#if FX_FRAC_BITS > 15
    int32_t q = fx_dot3_cut(ax, ay, az, bx, by, bz, FX_FRAC_BITS - 15); /* Q.30 */
    return (q + ((int32_t)1 << (29 - FX_FRAC_BITS))) >> (30 - FX_FRAC_BITS);
#else
    return (fx_t)fx_round_shift(fx_wdot3(ax, ay, az, bx, by, bz), FX_FRAC_BITS);
#endif
}

/* Whether a . b < 0 for |a_k|, |b_k| <= 2, exactly. Without a long
 * multiply, 32-bit products of a and b cut to Q.13 first: each cut
 * product is within |a'| + |b'| + 1 <= 2^15 + 1 of the exact one (in
 * their units, 2^-26), so a sum beyond 3 (2^15 + 1) has the exact sum's
 * sign; only near-perpendicular pairs (|a . b| below 2^-9.4) take the
 * 64-bit products. */
static inline bool fx_dot3_negative(fx_t ax, fx_t ay, fx_t az, fx_t bx, fx_t by, fx_t bz)
{
#if FX_MUL64_PARTIAL && FX_FRAC_BITS > 13
    const int32_t sure = 3 * (((int32_t)1 << 15) + 1);
    int32_t q = fx_dot3_cut(ax, ay, az, bx, by, bz, FX_FRAC_BITS - 13);
    if (q > sure || q < -sure)
        return q < 0;
#endif
    return fx_wdot3(ax, ay, az, bx, by, bz) < 0;
}

/* Sign of d . n for a Q.F vector d (|d_k| <= 2) and a Q.2F vector n, at
 * full precision: n is shifted right just enough for the products to fit
 * 64 bits (the same shift for the same n, so equal inputs give equal
 * answers: what watertight edge tests need). */
static inline int fx_wsign_dot(fx_t dx, fx_t dy, fx_t dz, fx_wide_t nx, fx_wide_t ny, fx_wide_t nz)
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

/* w * a as Q.2F, rounded once: w is split at the binary point so both
 * partial products fit in 64 bits (|w| < 2^(31+F) and |w a| < 2^(63-F)). */
static inline fx_wide_t fx_wmul_fx(fx_wide_t w, fx_t a)
{
    int64_t hi = w >> FX_FRAC_BITS; /* floor */
    int64_t lo = (int64_t)((uint64_t)w & (uint64_t)(FX_ONE - 1));
    return fx_mul64x(a, hi) + fx_round_shift(fx_mul64x(a, lo), FX_FRAC_BITS);
}
fx_t fx_wdiv(fx_wide_t a, fx_wide_t b); /* a / b of two Q.2F values, as Q.F */
fx_wide_t fx_wdiv_fx(fx_wide_t w, fx_t a); /* w / a, as Q.2F; a == 0 saturates */
fx_wide_t fx_wdiv_int(fx_wide_t w, int32_t n); /* w / n truncated, n != 0 (C's w / n) */
fx_t fx_sqrt(fx_t a);                 /* a < 0 gives 0 */
fx_t fx_wsqrt(fx_wide_t w);           /* sqrt of a Q.2F value, as Q.F */
fx_t fx_pow_unit(fx_t x, fx_shine_t s);/* x^s for x in [0,1]; 0 for x <= 0 */
/* fx_pow_unit's path for x in (0, 1) and an integer s, 1 <= s <= 128 (a
 * Phong exponent mostly is): its binary powers in Q.31, each product
 * rounded (within 2^-24 in all), one rounding to Q.F; inline, so the
 * highlight calls nothing (fx_pow_unit_fast) */
static inline bool fx_pow_unit_int_path(fx_t x, fx_shine_t s)
{
    return x > 0 && x < FX_ONE && s != 0 && (s & ((1u << FX_SHINE_FRAC_BITS) - 1)) == 0 &&
           s <= (128u << FX_SHINE_FRAC_BITS);
}
static inline fx_t fx_pow_unit_int(fx_t x, fx_shine_t s)
{
    uint32_t m = s >> FX_SHINE_FRAC_BITS;
    uint32_t u = (uint32_t)x << (31 - FX_FRAC_BITS); /* x < 1: u < 2^31 */
    for (; !(m & 1); m >>= 1)
        u = (uint32_t)((fx_umul64(u, u) + (1u << 30)) >> 31);
    uint32_t p = u; /* x^(lowest bit of s) */
    for (m >>= 1; m; m >>= 1) {
        u = (uint32_t)((fx_umul64(u, u) + (1u << 30)) >> 31);
        if (m & 1)
            p = (uint32_t)((fx_umul64(p, u) + (1u << 30)) >> 31);
    }
    return (fx_t)((p + (1u << (30 - FX_FRAC_BITS))) >> (31 - FX_FRAC_BITS));
}
static inline fx_t fx_pow_unit_fast(fx_t x, fx_shine_t s)
{
    return fx_pow_unit_int_path(x, s) ? fx_pow_unit_int(x, s) : fx_pow_unit(x, s);
}

/* Unit vector along (x, y, z) given at any common scale; zero stays zero. */
void fx_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3]);
/* fx_unit3 of a vector of fx_t, the same bits in 32-bit operations */
void fx_unit3_narrow(fx_t x, fx_t y, fx_t z, fx_t out[3]);
/* the same and |v| (len, saturated), within 2^-21 relative and a unit */
void fx_unit3_narrow_len(fx_t x, fx_t y, fx_t z, fx_t out[3], fx_t *len);

/* tan(deg degrees) as Q.2F, for 0 <= deg < 90. */
fx_wide_t fx_tan_deg_wide(fx_t deg);

/* sin and cos of deg degrees (any angle), each within 1 ulp. */
void fx_sincos_deg(fx_t deg, fx_t *sin_out, fx_t *cos_out);

/* Nearest multiple of 2^-frac_bits (-24 <= frac_bits <= 31) to
 * +-mant * 10^exp10 (exact for up to 18 fraction digits; digits beyond
 * are truncated). Returns false when the magnitude exceeds `max`. */
bool fx_from_decimal(bool neg, uint64_t mant, int32_t exp10, int32_t frac_bits,
                     uint32_t max, int32_t *out);

#endif
