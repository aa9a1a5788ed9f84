/*
 * test_fx.c - every fixed-point operation against double over dense or
 * random input sweeps. Each check asserts the accuracy fx.h documents and
 * prints the measured worst case in ulps (1 ulp = 2^-FX_FRAC_BITS).
 */
#include <math.h>
#include <stdlib.h>

#include "fx.h"
#include "testlib.h"

static const double ULP = 1.0 / FX_ONE;
static const double RANGE = (double)FX_MAX / FX_ONE; /* largest fx_t value */
static double d(fx_t v) { return (double)v / FX_ONE; }
static fx_t rnd_fx(double lo, double hi) { return (fx_t)llround(tl_uniform(lo, hi) * FX_ONE); }

static void test_mul_div(void)
{
    double worst_mul = 0, worst_div = 0;
    for (int i = 0; i < 2000000; i++) {
        double scale = (i & 1) ? 0.95 * sqrt(RANGE) : 2.0; /* products stay in range */
        fx_t a = rnd_fx(-scale, scale), b = rnd_fx(-scale, scale);
        double e = fabs(d(fx_mul(a, b)) - d(a) * d(b));
        worst_mul = e > worst_mul ? e : worst_mul;
        if (b != 0 && fabs(d(a) / d(b)) < 0.99 * RANGE) {
            e = fabs(d(fx_div(a, b)) - d(a) / d(b));
            worst_div = e > worst_div ? e : worst_div;
        }
    }
    CHECK(worst_mul <= 0.5 * ULP, "fx_mul: max error %.3f ulp over 2e6 random pairs (bound 0.5)",
          worst_mul / ULP);
    CHECK(worst_div <= 0.5 * ULP, "fx_div: max error %.3f ulp over 2e6 random pairs (bound 0.5)",
          worst_div / ULP);
    double worst_recip = 0;
    for (fx_t b = 1; b < (1 << 22); b += 1 + (b >> 12)) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double exact = 1.0 / d(sgn * b);
            if (fabs(exact) > 0.99 * RANGE)
                continue;
            double e = fabs(d(fx_recip(sgn * b)) - exact);
            worst_recip = e > worst_recip ? e : worst_recip;
        }
    }
    CHECK(worst_recip <= 0.5 * ULP, "fx_recip: max error %.3f ulp over |b| up to %g (bound 0.5)",
          worst_recip / ULP, d(1 << 22));
    CHECK(fx_mul(FX_MAX, FX_ONE * 2) == FX_MAX && fx_mul(FX_MAX, -FX_ONE * 2) == FX_MIN,
          "fx_mul saturates instead of wrapping");
    CHECK(fx_div(FX_ONE, 0) == FX_MAX && fx_div(-FX_ONE, 0) == FX_MIN && fx_div(0, 0) == 0,
          "fx_div by zero saturates by the numerator's sign");
}

static void test_sqrt(void)
{
    double worst = 0;
    /* every value up to 2^22, then random ones over the whole range */
    for (int32_t x = 0; x < (1 << 22); x++) {
        double e = fabs(d(fx_sqrt(x)) - sqrt(d(x)));
        worst = e > worst ? e : worst;
    }
    for (int i = 0; i < 1000000; i++) {
        fx_t x = (fx_t)(tl_rand() & 0x7FFFFFFF);
        double e = fabs(d(fx_sqrt(x)) - sqrt(d(x)));
        worst = e > worst ? e : worst;
    }
    CHECK(worst <= 0.5 * ULP + 1e-12, "fx_sqrt: max error %.3f ulp, all raw x < 2^22 + 1e6 random (bound 0.5)",
          worst / ULP);
    double worst_w = 0;
    for (int i = 0; i < 1000000; i++) {
        int64_t w = (int64_t)(tl_rand() >> (1 + tl_rand() % 40));
        double exact = sqrt((double)w / ((double)FX_ONE * FX_ONE));
        if (exact > 0.99 * RANGE)
            continue;
        double e = fabs(d(fx_wsqrt(w)) - exact);
        worst_w = e > worst_w ? e : worst_w;
    }
    CHECK(worst_w <= 0.5 * ULP + 1e-9, "fx_wsqrt: max error %.3f ulp over 1e6 random Q.2F values (bound 0.5)",
          worst_w / ULP);
}

static void test_unit3(void)
{
    double worst = 0;
    for (int i = 0; i < 1000000; i++) {
        double scale = pow(2.0, tl_uniform(-12, 40));
        double v[3] = { tl_uniform(-1, 1) * scale, tl_uniform(-1, 1) * scale, tl_uniform(-1, 1) * scale };
        int64_t w[3] = { llround(v[0]), llround(v[1]), llround(v[2]) };
        if (!w[0] && !w[1] && !w[2])
            continue;
        double l = sqrt((double)w[0] * w[0] + (double)w[1] * w[1] + (double)w[2] * w[2]);
        fx_t u[3];
        fx_unit3(w[0], w[1], w[2], u);
        for (int k = 0; k < 3; k++) {
            double e = fabs(d(u[k]) - w[k] / l);
            worst = e > worst ? e : worst;
        }
    }
    CHECK(worst <= 1.0 * ULP, "fx_unit3: max component error %.3f ulp over 1e6 vectors, scales 2^0..2^40 (bound 1)",
          worst / ULP);
}

static void test_pow(void)
{
    static const double shines[] = { 1, 3.0827, 4.81884, 10, 100, 1000, 10000, 100000 };
    for (unsigned k = 0; k < sizeof shines / sizeof shines[0]; k++) {
        fx_shine_t s = (fx_shine_t)llround(shines[k] * (1 << FX_SHINE_FRAC_BITS));
        double sd = (double)s / (1 << FX_SHINE_FRAC_BITS);
        double worst = 0, bound = 2 * ULP;
        for (fx_t x = 0; x <= FX_ONE; x += (k < 4 ? 1 : 3)) {
            double exact = pow(d(x), sd);
            double e = fabs(d(fx_pow_unit(x, s)) - exact);
            double allowed = 2 * ULP + 1e-7 * sd * exact;
            if (e - allowed > worst - bound) {
                worst = e;
                bound = allowed;
            }
        }
        CHECK(worst <= bound, "fx_pow_unit(x, %g): worst error %.3f ulp for x over [0,1] (bound 2 ulp + 1e-7*s*x^s)",
              shines[k], worst / ULP);
    }
}

static void test_tan(void)
{
    double worst = 0;
    for (fx_t deg = FX_ONE / 2; deg <= 89 * FX_ONE; deg += 97) {
        double exact = tan(d(deg) * 3.14159265358979323846 / 180);
        double got = (double)fx_tan_deg_wide(deg) / ((double)FX_ONE * FX_ONE);
        double e = fabs(got - exact) / exact;
        worst = e > worst ? e : worst;
    }
    CHECK(worst < 3e-7, "fx_tan_deg_wide: max relative error %.2e over 0.5..89 degrees (bound 3e-7)", worst);
}

static void test_decimal(void)
{
    int wrong = 0, n = 0;
    for (int i = 0; i < 1000000; i++) {
        uint64_t mant = tl_rand() % 1000000000000ull;
        int32_t e10 = -(int32_t)(tl_rand() % 16);
        /* exact nearest by 128-bit integer arithmetic, ties away from zero */
        unsigned __int128 num = (unsigned __int128)mant << FX_FRAC_BITS, den = 1;
        for (int k = 0; k < -e10; k++)
            den *= 10;
        unsigned __int128 q = num / den, r = num % den;
        if (2 * r >= den)
            q++;
        int32_t got;
        bool ok = fx_from_decimal(false, mant, e10, FX_FRAC_BITS, (uint32_t)FX_MAX, &got);
        if (q > (unsigned __int128)FX_MAX) {
            wrong += ok;
            continue;
        }
        n++;
        wrong += !ok || (uint64_t)got != (uint64_t)q;
    }
    CHECK(wrong == 0, "fx_from_decimal: %d of %d random decimals not the nearest fx_t", wrong, n);
    int32_t v;
    uint64_t too_big = (uint64_t)1 << (31 - FX_FRAC_BITS);
    CHECK(!fx_from_decimal(false, too_big, 0, FX_FRAC_BITS, (uint32_t)FX_MAX, &v) &&
              !fx_from_decimal(true, 1, 30, FX_FRAC_BITS, (uint32_t)FX_MAX, &v),
          "fx_from_decimal rejects %llu and -1e30 (out of range)", (unsigned long long)too_big);
}

int main(void)
{
    printf("test_fx (Q%d.%d)\n", 31 - FX_FRAC_BITS, FX_FRAC_BITS);
    test_mul_div();
    test_sqrt();
    test_unit3();
    test_pow();
    test_tan();
    test_decimal();
    return tl_summary("test_fx");
}
