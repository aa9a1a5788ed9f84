/* real_double.c - decimal conversion for the floating-point backends. */
#include "real.h"

#if RT_BACKEND_DOUBLE || RT_BACKEND_FLOAT

/* mant * 10^exp10 to within a few ulps; the reference need not be exact. */
static bool decimal_to_double(bool neg, uint64_t mant, int32_t exp10, double *out)
{
    double v = (double)mant;
    if (mant == 0) { /* 0E631 is zero, not 0 * inf */
        *out = 0;
        return true;
    }
    if (exp10 > 308)
        return false;
    if (exp10 < -400)
        exp10 = -400; /* certainly zero */
    double p = 1.0;
    int32_t k = exp10 < 0 ? -exp10 : exp10;
    for (int32_t i = 0; i < k; i++)
        p *= 10.0;
    v = exp10 < 0 ? v / p : v * p;
    if (v > 1e300)
        return false;
    *out = neg ? -v : v;
    return true;
}

bool r_from_decimal_scaled(bool neg, uint64_t mant, int32_t exp10, int32_t scale_log2, real_t *out)
{
    double v;
    if (!decimal_to_double(neg, mant, exp10, &v))
        return false;
    for (; scale_log2 > 0; scale_log2--) /* exact: powers of two */
        v *= 2.0;
    for (; scale_log2 < 0; scale_log2++)
        v *= 0.5;
    if (v > 1e30 || v < -1e30)
        return false;
    *out = (real_t)v;
    return true;
}

bool shine_from_decimal(bool neg, uint64_t mant, int32_t exp10, shine_t *out)
{
    double v;
    if (neg || !decimal_to_double(false, mant, exp10, &v) || v > 524287.0)
        return false;
    *out = (shine_t)v;
    return true;
}

#else
typedef int real_double_unused_t; /* ISO C forbids an empty translation unit */
#endif
