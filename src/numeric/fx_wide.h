/*
 * fx_wide.h - the fixed layer's wide integer products, one name per
 * operation (fx.h includes it):
 *   fx_mul64(a, b)     signed 32x32 -> 64
 *   fx_umul64(a, b)    unsigned 32x32 -> 64
 *   fx_mul64_hi(a, b)  the high word of fx_mul64: the product / 2^32,
 *                      rounded down
 *   fx_mul64x(a, b)    signed 32x64, exact where the product fits 64 bits
 *   fx_umul64x(a, b)   unsigned 64x64, modulo 2^64 (C's uint64_t product)
 *   fx_mul64xx(a, b)   signed 64x64, the bits of fx_umul64x
 * All of them are exact and give the same bits on every path below.
 *
 * FX_MUL64_PARTIAL picks how the 32x32 products are computed:
 *   0  the plain C product: one SMULL/UMULL on the M3, one instruction on
 *      a host (the default everywhere but ARMv6-M);
 *   1  from four 16x16->32 partial products, inline: for cores with no
 *      long multiply. On ARMv6-M (Cortex-M0/M0+) the plain product is a
 *      call to libgcc's general 64x64 __aeabi_lmul (44 instructions, plus
 *      sign-extending both operands at the call); this is 17 instructions
 *      of inline assembly (the default when __ARM_ARCH_6M__ is defined);
 *   2  the same partial products out of line (fx_mul64_call and
 *      fx_umul64_call, fx.c): smaller code than both 0 and 1 on ARMv6-M,
 *      3 to 6 instructions more per product than 1 (bench/m0-mul.sh
 *      measures all three).
 * The partial products are inline assembly on ARMv6-M with GCC or clang
 * (fewer instructions than the C, which has no add-with-carry), and
 * elsewhere (a host forcing the path to test it: tests/unit/test_fx.c against
 * the plain product) the same arithmetic in C.
 */
#ifndef FX_WIDE_H
#define FX_WIDE_H

#include <stdint.h>

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

#if FX_MUL64_ASM
/* The partial products in Thumb-1, 17 instructions; SH is asrs (signed)
 * or lsrs (unsigned). In: h = a, b = b. Out: l = low word, h = high word. */
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

/* The partial products (fx_mul64's paths 1 and 2). a = ah 2^16 + al with
 * al = the low half (unsigned) and ah = a >> 16 (as signed as a); the
 * same for b. a b = ah bh 2^32 + (ah bl + al bh) 2^16 + al bl, where each
 * partial product fits 32 bits (al bl unsigned, the cross terms below
 * 2^31 in magnitude, ah bh below 2^30 for signed inputs) and each cross
 * term is added at bit 16 with its carry into the high word. Right shifts
 * of negative values are arithmetic (GCC, clang). */
static inline int64_t fx_mul64_parts(int32_t a, int32_t b)
{
#if FX_MUL64_ASM
    uint32_t l, t, u, h = (uint32_t)a, bb = (uint32_t)b;
    __asm__(FX_MUL64_THUMB1("asrs")
            : [l] "=&l"(l), [h] "+&l"(h), [t] "=&l"(t), [u] "=&l"(u), [b] "+&l"(bb)
            :
            : "cc");
    return (int64_t)(((uint64_t)h << 32) | l);
#else
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
#endif
}

static inline uint64_t fx_umul64_parts(uint32_t a, uint32_t b)
{
#if FX_MUL64_ASM
    uint32_t l, t, u, h = a, bb = b;
    __asm__(FX_MUL64_THUMB1("lsrs")
            : [l] "=&l"(l), [h] "+&l"(h), [t] "=&l"(t), [u] "=&l"(u), [b] "+&l"(bb)
            :
            : "cc");
    return ((uint64_t)h << 32) | l;
#else
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
#endif
}

#if FX_MUL64_PARTIAL == 2
int64_t fx_mul64_call(int32_t a, int32_t b);     /* fx_mul64_parts, out of line */
uint64_t fx_umul64_call(uint32_t a, uint32_t b); /* fx_umul64_parts, out of line */
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
    return fx_mul64_parts(a, b);
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
    return fx_umul64_parts(a, b);
#else
    return (uint64_t)a * b;
#endif
}

/* The high word of a * b, that is the product / 2^32 rounded down: one
 * SMULL, whose high register the compiler keeps. The empty barrier hides
 * where a and b came from: without it GCC 12 can lose that they are
 * 32-bit and multiply 64x64 (three instructions for one SMULL). */
static inline int32_t fx_mul64_hi(int32_t a, int32_t b)
{
#if defined(__GNUC__)
    __asm__("" : "+r"(a), "+r"(b));
#endif
    return (int32_t)((uint64_t)fx_mul64(a, b) >> 32);
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

/* a * b for signed 64-bit operands through fx_umul64x: where the signed
 * product is defined, its bits are the same. The plain path is a macro,
 * so that its code is exactly the product written out. */
#if FX_MUL64_PARTIAL
static inline int64_t fx_mul64xx(int64_t a, int64_t b) { return (int64_t)fx_umul64x((uint64_t)a, (uint64_t)b); }
#else
#define fx_mul64xx(a, b) ((int64_t)(a) * (b))
#endif

#endif
