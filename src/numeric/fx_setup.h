/*
 * fx_setup.h - fixed-point maths for set-up only (fx_setup.c): the
 * angles of views and transforms, and the reader's decimal numbers
 * (decimal.c holds the exact comparisons of decimals).
 *
 * Accuracy (tests/unit/test_fx.c):
 *   fx_wtan_deg       relative error < 3e-7 for 0.5 <= deg <= 89 (the sine
 *                     is Q.30, so small angles carry the most)
 *   fx_from_decimal   correctly rounded (the nearest fx_t, ties away)
 *                     for inputs with at most 18 fraction digits
 */
#ifndef FX_SETUP_H
#define FX_SETUP_H

#include "fx.h"

/* tan(deg degrees) as Q.2F, for 0 <= deg < 90. */
fx_wide_t fx_wtan_deg(fx_t deg);

/* sin and cos of deg degrees (any angle), each within 1 ulp. */
void fx_sincos_deg(fx_t deg, fx_t *sin_out, fx_t *cos_out);

/* Nearest multiple of 2^-frac_bits (-24 <= frac_bits <= 31) to
 * +-mant * 10^exp10 (exact for up to 18 fraction digits; digits beyond
 * are truncated). Returns false when the magnitude exceeds `max`. */
bool fx_from_decimal(bool neg, uint64_t mant, int32_t exp10, int32_t frac_bits,
                     uint32_t max, int32_t *out);

#endif
