/*
 * test_fx.c - every fixed-point operation against double over dense or
 * random input sweeps. Each check asserts the accuracy fx.h documents and
 * prints the measured worst case in ulps (1 ulp = 2^-FX_FRAC_BITS).
 */
#include <math.h>
#include <stdlib.h>

/* The board's wide-product path on the host: this file's inline fixed
 * layer (fx_mul, fx_wmul, ...) computes its products from 16x16->32
 * partial products (fx.h, FX_MUL64_PARTIAL), while fx.c, built without
 * the macro, and the reference products below are the plain C product. */
#define FX_MUL64_PARTIAL 1
#include "fx.h"
#include "real.h"
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

/* The plain products the partial path must equal, bit for bit. The
 * 64-bit one is taken modulo 2^64 (what fx_mul64x computes; equal to the
 * signed product wherever that is defined). */
static int64_t plain_mul64(int32_t a, int32_t b) { return (int64_t)a * b; }
static uint64_t plain_umul64(uint32_t a, uint32_t b) { return (uint64_t)a * b; }
static uint64_t plain_mul64x(int32_t a, int64_t b) { return (uint64_t)(int64_t)a * (uint64_t)b; }
static uint64_t plain_umul64x(uint64_t a, uint64_t b) { return a * b; }

static const int32_t mul_edges[] = {
    0, 1, -1, 2, -2, 3, -3, 0x7FFF, -0x7FFF, 0x8000, -0x8000, 0x8001, -0x8001, 0xFFFF, -0xFFFF,
    0x10000, -0x10000, 0x10001, -0x10001, 0x1FFFF, -0x1FFFF, 0x40000000, -0x40000000, 0x7FFF0000,
    -0x7FFF0000, 0x7FFF8000, 0x7FFFFFFF, -0x7FFFFFFF, INT32_MIN, (int32_t)0x80000001u, (int32_t)0x8000FFFFu,
    (int32_t)0xFFFF0000u, (int32_t)0xFFFF8000u, (int32_t)0xFFFF7FFFu, 0x0000FFFF, 0x55555555,
    (int32_t)0xAAAAAAAAu, 0x12345678, (int32_t)0xDEADBEEFu, FX_ONE, -FX_ONE, FX_HALF, FX_ONE - 1,
};
#define N_MUL_EDGES (int)(sizeof mul_edges / sizeof mul_edges[0])

/* a random 32-bit value: any bits, a random magnitude, or halves at the
 * carry corners (0x0000, 0x7FFF, 0x8000, 0xFFFF) */
static int32_t rnd_word(void)
{
    static const uint32_t half[] = { 0x0000u, 0x7FFFu, 0x8000u, 0xFFFFu };
    uint64_t r = tl_rand();
    switch (r & 3) {
    case 0:
        return (int32_t)(uint32_t)(r >> 32);
    case 1:
        return (int32_t)(uint32_t)(r >> 32) >> ((r >> 2) & 31);
    case 2:
        return (int32_t)((uint32_t)(r >> 32) << 16 | half[(r >> 2) & 3]);
    default:
        return (int32_t)(half[(r >> 2) & 3] << 16 | (uint32_t)(r >> 32) >> 16);
    }
}

static void test_mul64(void)
{
    long bad_s = 0, bad_u = 0, bad_x = 0, bad_ux = 0, n = 0;
    for (int i = 0; i < N_MUL_EDGES; i++)
        for (int j = 0; j < N_MUL_EDGES; j++) {
            int32_t a = mul_edges[i], b = mul_edges[j];
            int64_t w = (int64_t)((uint64_t)(uint32_t)b << 32 | (uint32_t)mul_edges[(i + j) % N_MUL_EDGES]);
            bad_s += fx_mul64(a, b) != plain_mul64(a, b);
            bad_u += fx_umul64((uint32_t)a, (uint32_t)b) != plain_umul64((uint32_t)a, (uint32_t)b);
            bad_x += (uint64_t)fx_mul64x(a, w) != plain_mul64x(a, w) ||
                     (uint64_t)fx_mul64x(a, (int64_t)b) != plain_mul64x(a, (int64_t)b);
            uint64_t wa = (uint64_t)(uint32_t)a << 32 | (uint32_t)b, wb = (uint64_t)w;
            bad_ux += fx_umul64x(wa, wb) != plain_umul64x(wa, wb) ||
                      fx_umul64x((uint32_t)a, wb) != plain_umul64x((uint32_t)a, wb);
            n++;
        }
    CHECK(bad_s == 0 && bad_u == 0 && bad_x == 0 && bad_ux == 0,
          "partial products on all %ld pairs of %d edge values: %ld signed, %ld unsigned, %ld 32x64, %ld 64x64 "
          "differ from the plain product",
          n, N_MUL_EDGES, bad_s, bad_u, bad_x, bad_ux);

    bad_s = bad_u = bad_x = bad_ux = n = 0;
    for (long i = 0; i < 4000000; i++) {
        int32_t a = rnd_word(), b = rnd_word();
        int64_t w = (int64_t)tl_rand() >> (tl_rand() & 63);
        bad_s += fx_mul64(a, b) != plain_mul64(a, b);
        bad_u += fx_umul64((uint32_t)a, (uint32_t)b) != plain_umul64((uint32_t)a, (uint32_t)b);
        bad_x += (uint64_t)fx_mul64x(a, w) != plain_mul64x(a, w);
        uint64_t wa = tl_rand() >> (tl_rand() & 63);
        bad_ux += fx_umul64x(wa, (uint64_t)w) != plain_umul64x(wa, (uint64_t)w);
        n++;
    }
    CHECK(bad_s == 0 && bad_u == 0 && bad_x == 0 && bad_ux == 0,
          "partial products on %ld random pairs: %ld signed, %ld unsigned, %ld 32x64, %ld 64x64 differ from the "
          "plain product",
          n, bad_s, bad_u, bad_x, bad_ux);

    /* the inline layer built on them, against the same formulas with the
     * plain product, on random operands of tracer-like sizes and any */
    long bad = 0;
    n = 0;
    for (long i = 0; i < 1000000; i++) {
        int32_t a = rnd_word(), b = rnd_word(), c = rnd_word();
        fx_t dx = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE; /* |d| <= 2, as fx_wsign_dot wants */
        fx_t dy = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE;
        fx_t dz = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE;
        fx_wide_t nx = (int64_t)tl_rand() >> (tl_rand() & 63), ny = (int64_t)tl_rand() >> (tl_rand() & 63);
        fx_wide_t nz = (int64_t)tl_rand() >> (tl_rand() & 63);
        bad += fx_mul(a, b) != fx_sat64(fx_round_shift(plain_mul64(a, b), FX_FRAC_BITS));
        bad += fx_wmul(a, b) != plain_mul64(a, b);
        int64_t diff = (int64_t)a - b;
        /* as its GNUC branch: saturated only outside int32 (INT32_MIN stays) */
        int32_t dsat = diff > INT32_MAX ? FX_MAX : diff < INT32_MIN ? FX_MIN : (int32_t)diff;
        bad += fx_wmul_diff(a, b, c) != plain_mul64(dsat, c);
        /* fx_wsign_dot with the plain products (n shifted as it does) */
        uint64_t m = (uint64_t)(nx < 0 ? -nx : nx) | (uint64_t)(ny < 0 ? -ny : ny) | (uint64_t)(nz < 0 ? -nz : nz);
        int s = 0;
        while ((m >> s) >= ((uint64_t)1 << 40))
            s++;
        int64_t v = (int64_t)dx * (nx >> s) + (int64_t)dy * (ny >> s) + (int64_t)dz * (nz >> s);
        bad += fx_wsign_dot(dx, dy, dz, nx, ny, nz) != (v > 0) - (v < 0);
        /* fx_wmul_fx inside its range: |w| < 2^(31+F), |w a| < 2^(63-F) */
        int wl = (int)(tl_rand() % (uint64_t)(62 - FX_FRAC_BITS < 30 + FX_FRAC_BITS ? 63 - FX_FRAC_BITS
                                                                                      : 31 + FX_FRAC_BITS));
        int fl = 62 - FX_FRAC_BITS - wl > 30 ? 30 : 62 - FX_FRAC_BITS - wl;
        fx_wide_t w = (int64_t)tl_rand() >> (63 - wl); /* |w| <= 2^wl */
        fx_t f = (fx_t)((int64_t)tl_rand() >> (63 - fl)); /* |f| <= 2^fl */
        int64_t whi = w >> FX_FRAC_BITS, wlo = (int64_t)((uint64_t)w & (uint64_t)(FX_ONE - 1));
        bad += fx_wmul_fx(w, f) != whi * f + fx_round_shift(wlo * f, FX_FRAC_BITS);
        n++;
    }
    CHECK(bad == 0, "fx_mul, fx_wmul, fx_wmul_diff, fx_wsign_dot, fx_wmul_fx on the partial products: %ld of %ld "
          "random cases differ from the plain product", bad, 5 * n);

    bad = 0;
    for (fx_t c = -2; c <= FX_ONE + 2; c++)
        bad += r_to_u8(c) != (c <= 0 ? 0 : c >= FX_ONE ? 255 : (uint8_t)(((int64_t)c * 255 + FX_HALF) >> FX_FRAC_BITS));
    CHECK(bad == 0, "r_to_u8's 32-bit product: %ld of the %ld values -2..FX_ONE+2 differ from the 64-bit one", bad,
          (long)FX_ONE + 5);
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
    test_mul64();
    return tl_summary("test_fx");
}
