/*
 * fx.h - signed fixed point for the tracer, Q(31-F).F with F = FX_FRAC_BITS:
 * the format, saturation, and the general operations. The rest of the
 * fixed layer is split by idea:
 *   fx_wide.h     the 32x32 -> 64 products (included here)
 *   fx_bounded.h  products that rely on a bound their callers keep
 *   fx_div.h      quotients of wide values, reciprocals for the BVH
 *   fx_root.h     square roots and unit vectors
 *   fx_pow.h      x^s for x in [0, 1] (the Phong highlight's)
 *   fx_setup.h    trigonometry and decimal conversion, for set-up only
 * fx.c holds the operations that run while rendering, fx_setup.c the
 * set-up maths.
 *
 * Default F = 20 (rt_config.h): range +-2047.999999, resolution 2^-20 = 9.5e-7.
 * Products keep a 64-bit intermediate; every conversion back to fx_t rounds
 * to nearest and saturates to +-FX_MAX (never wraps). FX_ON_SATURATE() is
 * called on each saturation so a debug build can count them.
 *
 * Accuracy (measured by tests/unit/test_fx.c over dense input sweeps; "ulp" is
 * one unit of the last place, 2^-F; each header lists its own):
 *   fx_mul, fx_div        correctly rounded (<= 0.5 ulp)
 *   fx_recip              correctly rounded (<= 0.5 ulp)
 *
 * Names: a w after fx_ marks a Q.2F (fx_wide_t) operand or result, as in
 * fx_wmul; fx_bounded.h's suffixes name what the caller guarantees.
 */
#ifndef FX_H
#define FX_H

#include <stdbool.h>
#include <stdint.h>

#include "rt_config.h"
#include "rt_prefix.h"

typedef int32_t fx_t;       /* Q(31-F).F scalar */
typedef int64_t fx_wide_t;  /* Q(63-2F).2F: an exact product of two fx_t */

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

#include "fx_wide.h"

static inline fx_t fx_from_int(int32_t i) { return fx_sat64((int64_t)i * FX_ONE); }

static inline fx_t fx_mul(fx_t a, fx_t b)
{
    return fx_sat64(fx_round_shift(fx_mul64(a, b), FX_FRAC_BITS));
}

static inline fx_wide_t fx_wmul(fx_t a, fx_t b) { return fx_mul64(a, b); }

static inline fx_t fx_from_wide(fx_wide_t w) { return fx_sat64(fx_round_shift(w, FX_FRAC_BITS)); }

static inline fx_wide_t fx_to_wide(fx_t a) { return (int64_t)a * FX_ONE; }

fx_t fx_div(fx_t a, fx_t b);          /* b == 0 saturates by the sign of a */
fx_t fx_recip(fx_t b);                /* 1 / b */

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

#endif
