/*
 * decimal.h - numbers as the scene file writes them, mant 10^exp10, and
 * exact arithmetic on their values: comparisons with binary values and
 * the reciprocal, so that what the reader decides from a number (the
 * scene scale, a range check, a texture's period) depends on its value
 * alone, not on its spelling (1.5, 1.50 and 15e-1 are one number), and is
 * the same in every build.
 */
#ifndef DECIMAL_H
#define DECIMAL_H

#include <stdbool.h>
#include <stdint.h>

#include "real.h"

typedef struct {
    bool neg;
    uint64_t mant;   /* up to 19 significant digits */
    int32_t exp10;   /* |exp10| <= 200000 */
} decimal_t;

/* decimal_cmp: the sign of |d| - num 2^p, for |p| <= DECIMAL_P_LIMIT.
 * decimal_exp2_bound: the least p with |d| < 2^p, d nonzero, clamped to
 * [-DECIMAL_EXP2_CLAMP, DECIMAL_EXP2_CLAMP] (far beyond any scale). */
#define DECIMAL_P_LIMIT 160
#define DECIMAL_EXP2_CLAMP (DECIMAL_P_LIMIT - 8)
int decimal_cmp(const decimal_t *d, uint32_t num, int32_t p);
int32_t decimal_exp2_bound(const decimal_t *d);

/* 1 / (|d| 2^scale_log2) as the scalar, for 2^-10 <= |d| 2^scale_log2
 * < 2^11: correctly rounded in the fixed build (so a texture's period is
 * right to the last bit however far out), the float or double quotient
 * of the converted value otherwise. */
real_t decimal_recip_scaled(const decimal_t *d, int32_t scale_log2);

#endif
