/*
 * fx_root.h - square roots and unit vectors of the fixed layer (fx.c).
 *
 * Accuracy (tests/unit/test_fx.c; ulp = 2^-F):
 *   fx_sqrt, fx_wsqrt     correctly rounded (<= 0.5 ulp); within 0.76 ulp
 *                         with FX_FAST_MATH
 *   fx_unit3              each component within 1 ulp of the true unit vector
 *   fx_unit3_narrow_len   fx_unit3_narrow's unit, the length within 2^-21
 *                         relative + 1 ulp
 */
#ifndef FX_ROOT_H
#define FX_ROOT_H

#include "fx.h"

fx_t fx_sqrt(fx_t a);                 /* a < 0 gives 0 */
fx_t fx_wsqrt(fx_wide_t w);           /* sqrt of a Q.2F value, as Q.F */

/* Unit vector along (x, y, z) given at any common scale; zero stays zero. */
void fx_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3]);
/* fx_unit3 of a vector of fx_t, the same bits in 32-bit operations */
void fx_unit3_narrow(fx_t x, fx_t y, fx_t z, fx_t out[3]);
/* the same and |v| (len, saturated), within 2^-21 relative and a unit */
void fx_unit3_narrow_len(fx_t x, fx_t y, fx_t z, fx_t out[3], fx_t *len);

#endif
