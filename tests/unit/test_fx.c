/*
 * test_fx.c - every fixed-point operation against double over dense or
 * random input sweeps. Each check asserts the accuracy its header (fx.h or
 * one beside it) documents and
 * prints the measured worst case in ulps (1 ulp = 2^-FX_FRAC_BITS). The
 * exact operations (fx_div, fx_recip, fx_sqrt, fx_wsqrt) are also held to
 * the exact answer, bit for bit, from plain integer arithmetic here, and
 * fx_unit3 to the bits of its plain 64-bit formulation.
 */
#include <math.h>
#include <stdlib.h>

/* The board's wide-product path on the host: this file's inline fixed
 * layer (fx_mul, fx_wmul, ...) computes its products from 16x16->32
 * partial products (fx_wide.h, FX_MUL64_PARTIAL), while the fixed layer's
 * .c files, built without the macro, and the reference products below
 * are the plain C product. */
#define FX_MUL64_PARTIAL 1
#include "numeric/fx.h"
#include "numeric/fx_rsqrt_line.h"
#include "numeric/real.h"
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

/* ---- exact answers by plain integer arithmetic (nothing shared with the fixed layer) */

/* round(a 2^F / b), half away from zero, saturated to +-FX_MAX (b != 0) */
static fx_t ref_div(fx_t a, fx_t b)
{
    uint64_t n = (uint64_t)(a < 0 ? -(int64_t)a : a) << FX_FRAC_BITS;
    uint64_t d = (uint64_t)(b < 0 ? -(int64_t)b : b);
    uint64_t q = n / d, r = n % d;
    if (2 * r >= d)
        q++;
    if (q > (uint64_t)FX_MAX)
        q = (uint64_t)FX_MAX;
    return (a < 0) != (b < 0) ? -(fx_t)q : (fx_t)q;
}

/* round(sqrt(v)) digit by digit: r = floor(sqrt(v)), then up when v - r^2 > r */
static uint64_t ref_isqrt_round(uint64_t v)
{
    uint64_t r = 0, rem = v, bit = (uint64_t)1 << 62;
    while (bit > v)
        bit >>= 2;
    for (; bit; bit >>= 2) {
        if (rem >= r + bit) {
            rem -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
    }
    return rem > r ? r + 1 : r;
}

static fx_t ref_wsqrt(fx_wide_t w)
{
    if (w <= 0)
        return 0;
    uint64_t r = ref_isqrt_round((uint64_t)w);
    return r > (uint64_t)FX_MAX ? FX_MAX : (fx_t)r;
}

static fx_t ref_sqrt(fx_t a) { return a <= 0 ? 0 : (fx_t)ref_isqrt_round((uint64_t)a << FX_FRAC_BITS); }

/* a random value of random bit length (0..bits), either sign when sgn */
static int64_t rnd_bits(int bits, bool sgn)
{
    uint64_t r = tl_rand();
    int64_t v = (int64_t)(tl_rand() >> (64 - bits) >> (r % (uint64_t)(bits + 1)));
    return sgn && (r & 0x100) ? -v : v;
}

static const int32_t div_edges[] = {
    1, 2, 3, 5, 7, 0xFF, 0x100, 0x101, 0x7FF, 0x800, 0x801, 0xFFF, 0x1000, 0x1001, 0xFFFF, 0x10000, 0x10001,
    FX_ONE - 1, FX_ONE, FX_ONE + 1, FX_HALF, FX_HALF + 1, 3 * FX_HALF, 0x7FFF0000, 0x7FFF8000,
    0x3FFFFFFF, 0x40000000, 0x40000001, 0x55555555, 0x7FFFFFFE, 0x7FFFFFFF, INT32_MIN, 0x12345678,
};
#define N_DIV_EDGES (int)(sizeof div_edges / sizeof div_edges[0])

static void test_div_exact(void)
{
    long bad = 0, n = 0;
    for (int i = 0; i < N_DIV_EDGES; i++)
        for (int j = 0; j < N_DIV_EDGES; j++)
            for (int k = 0; k < 4; k++) {
                fx_t a = div_edges[i], b = div_edges[j];
                a = (k & 1) && a != INT32_MIN ? -a : a;
                b = (k & 2) && b != INT32_MIN ? -b : b;
                bad += fx_div(a, b) != ref_div(a, b);
                n++;
            }
    /* around the quotient's powers of two and the saturation threshold:
     * a = 2^i +- e, b = 2^j +- f */
    for (int i = 0; i < 31; i++)
        for (int j = 0; j < 31; j++)
            for (int e = -2; e <= 2; e++)
                for (int f = -2; f <= 2; f++) {
                    int64_t a = ((int64_t)1 << i) + e, b = ((int64_t)1 << j) + f;
                    if (a <= 0 || b <= 0 || a > FX_MAX || b > FX_MAX)
                        continue;
                    bad += fx_div((fx_t)a, (fx_t)b) != ref_div((fx_t)a, (fx_t)b);
                    bad += fx_div(-(fx_t)a, (fx_t)b) != ref_div(-(fx_t)a, (fx_t)b);
                    n += 2;
                }
    for (long i = 0; i < 6000000; i++) {
        fx_t a = (fx_t)rnd_bits(31, true), b = (fx_t)rnd_bits(31, true);
        if (b == 0)
            continue;
        bad += fx_div(a, b) != ref_div(a, b);
        n++;
    }
    CHECK(bad == 0, "fx_div: %ld of %ld edge, power-of-two and random pairs differ from the exact rounded quotient",
          bad, n);

    bad = n = 0;
    for (int64_t b = -(1 << 22); b <= (1 << 22); b++) {
        if (b == 0)
            continue;
        bad += fx_recip((fx_t)b) != ref_div(FX_ONE, (fx_t)b);
        n++;
    }
    for (long i = 0; i < 2000000; i++) {
        fx_t b = (fx_t)rnd_bits(31, true);
        if (b == 0)
            continue;
        bad += fx_recip(b) != ref_div(FX_ONE, b);
        n++;
    }
    bad += fx_recip(INT32_MIN) != ref_div(FX_ONE, INT32_MIN) || fx_recip(FX_MAX) != ref_div(FX_ONE, FX_MAX);
    CHECK(bad == 0, "fx_recip: %ld of %ld (every |b| <= 2^22, random) differ from the exact rounded quotient", bad,
          n + 2);
}

/* fx_wdiv and fx_wdiv_fx as they were first written, with C's 64-bit
 * division (the tracer's images are made with these bits): a / b
 * rounded half away from zero after halving both while |a| >= 2^(62-F);
 * w 2^F / a truncated, (w / a) 2^F for larger |w|. */
static fx_t ref_wdiv(fx_wide_t a, fx_wide_t b)
{
    const int64_t lim = (int64_t)1 << (62 - FX_FRAC_BITS);
    while (a >= lim || a <= -lim) {
        a /= 2;
        b /= 2;
    }
    if (b == 0)
        return a > 0 ? FX_MAX : a < 0 ? FX_MIN : 0;
    int64_t n = a * FX_ONE, h = (int64_t)((b < 0 ? 0 - (uint64_t)b : (uint64_t)b) / 2);
    int64_t q = (n >= 0 ? n + h : n - h) / b;
    return q > FX_MAX ? FX_MAX : q < FX_MIN ? FX_MIN : (fx_t)q;
}

static fx_wide_t ref_wdiv_fx(fx_wide_t w, fx_t a) /* not INT64_MIN / -1 */
{
    const int64_t lim = (int64_t)1 << (62 - FX_FRAC_BITS);
    if (a == 0)
        return w > 0 ? INT64_MAX : w < 0 ? -INT64_MAX : 0;
    if (w < lim && w > -lim)
        return w * FX_ONE / a;
    return (fx_wide_t)((uint64_t)(w / a) << FX_FRAC_BITS);
}

static void test_wdiv_exact(void)
{
    /* +-(2^k - 1, 2^k, 2^k + 1), 0, the ends and fx_wdiv's 2^(62-F) */
    int64_t e[3 * 2 * 63 + 7];
    int ne = 0;
    for (int k = 0; k < 63; k++)
        for (int64_t f = -1; f <= 1; f++) {
            e[ne++] = ((int64_t)1 << k) + f;
            e[ne++] = -(((int64_t)1 << k) + f);
        }
    const int64_t lim = (int64_t)1 << (62 - FX_FRAC_BITS);
    int64_t ends[] = { 0, INT64_MAX, INT64_MIN, INT64_MIN + 1, lim - 1, lim, -lim };
    for (int i = 0; i < 7; i++)
        e[ne++] = ends[i];
    long bad = 0, bad_fx = 0, n = 0, n_fx = 0;
    for (int i = 0; i < ne; i++) {
        for (int j = 0; j < ne; j++, n++)
            bad += fx_wdiv(e[i], e[j]) != ref_wdiv(e[i], e[j]);
        for (int j = 0; j < N_DIV_EDGES; j++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                fx_t a = div_edges[j] == INT32_MIN ? (sgn < 0 ? 0 : INT32_MIN) : sgn * div_edges[j];
                if (e[i] == INT64_MIN && a == -1)
                    continue;
                bad_fx += fx_wdiv_fx(e[i], a) != ref_wdiv_fx(e[i], a);
                n_fx++;
            }
    }
    /* random operands of random lengths, and quotients of random lengths
     * up to past 2^31 (saturation) around whole values: a ~ q b 2^-F */
    for (long i = 0; i < 3000000; i++) {
        int64_t a = rnd_bits(63, true), b = rnd_bits(63, true), w = rnd_bits(63, true);
        fx_t f = (fx_t)rnd_bits(31, true);
        bad += fx_wdiv(a, b) != ref_wdiv(a, b);
        bad_fx += fx_wdiv_fx(w, f) != ref_wdiv_fx(w, f);
        uint64_t q = (uint64_t)rnd_bits(32, false), bm = (uint64_t)(b < 0 ? -b : b) >> (tl_rand() & 31);
        if (bm != 0 && q <= UINT64_MAX / bm) {
            a = (int64_t)((q * bm >> FX_FRAC_BITS) & ((uint64_t)INT64_MAX >> 2)) + (int64_t)(tl_rand() % 5) - 2;
            bad += fx_wdiv(a, b) != ref_wdiv(a, b);
            n++;
        }
        /* w ~ q a 2^-F with |w| < 2^(62-F) */
        uint64_t am = (uint64_t)(f < 0 ? -(int64_t)f : f);
        w = (int64_t)((q * am >> FX_FRAC_BITS) & (uint64_t)(lim - 1)) * (w < 0 ? -1 : 1);
        bad_fx += fx_wdiv_fx(w, f) != ref_wdiv_fx(w, f);
        n++;
        n_fx += 2;
    }
    CHECK(bad == 0, "fx_wdiv: %ld of %ld edge, random and near-whole-quotient pairs differ from C's 64-bit division",
          bad, n);
    CHECK(bad_fx == 0, "fx_wdiv_fx: %ld of %ld edge, random and near-whole-quotient pairs differ from C's 64-bit "
          "division", bad_fx, n_fx);
}

/* fx_clz32 (the binary search where the core has no CLZ) against a loop */
static void test_clz(void)
{
    long bad = 0, n = 0;
    for (int k = 0; k < 32; k++)
        for (int i = 0; i < 1000; i++, n++) {
            uint32_t v = (uint32_t)1 << k | (uint32_t)(tl_rand() >> 32 >> (32 - k));
            bad += fx_clz32(v) != 31 - k;
        }
    CHECK(bad == 0, "fx_clz32 (%s): %ld of %ld values of every length differ", FX_CLZ_BUILTIN ? "builtin" : "search",
          bad, n);
}

static void test_sqrt_exact(void)
{
    long bad = 0, n = 0;
    for (int64_t a = -3; a < (1 << 22); a++, n++)
        bad += fx_sqrt((fx_t)a) != ref_sqrt((fx_t)a);
    for (int64_t a = (1 << 22); a <= FX_MAX; a += 499, n++)
        bad += fx_sqrt((fx_t)a) != ref_sqrt((fx_t)a);
    for (int i = 0; i < 1000000; i++, n++) {
        fx_t a = (fx_t)(tl_rand() & 0x7FFFFFFF);
        bad += fx_sqrt(a) != ref_sqrt(a);
    }
    bad += fx_sqrt(FX_MAX) != ref_sqrt(FX_MAX) || fx_sqrt(INT32_MIN) != 0;
    CHECK(bad == 0, "fx_sqrt: %ld of %ld (all raw x < 2^22, every 499th above, random) differ from the exact "
          "rounded root", bad, n + 2);

    bad = n = 0;
    for (long i = 0; i < 3000000; i++) {
        fx_wide_t w = rnd_bits(63, false);
        bad += fx_wsqrt(w) != ref_wsqrt(w);
        /* next to squares k^2 and to the halfway points k^2 + k (+ 1/4) */
        uint64_t k = (uint64_t)rnd_bits(32, false);
        for (int t = 0; t < 2; t++) {
            uint64_t c = k * k + (t ? k : 0);
            for (int e = -1; e <= 1; e++) {
                fx_wide_t v = (fx_wide_t)(c + (uint64_t)e);
                bad += fx_wsqrt(v) != ref_wsqrt(v);
            }
        }
        n += 7;
    }
    /* where the root reaches 2^31 - 1/2 (saturation), and the ends */
    static const int64_t ends[] = { ((int64_t)1 << 62) - ((int64_t)1 << 32), ((int64_t)1 << 62) - ((int64_t)1 << 31),
                                    (int64_t)1 << 62, INT64_MAX - 1000 };
    for (int i = 0; i < 4; i++)
        for (int64_t e = -1000; e <= 1000; e++, n++)
            bad += fx_wsqrt(ends[i] + e) != ref_wsqrt(ends[i] + e);
    bad += fx_wsqrt(0) != 0 || fx_wsqrt(-1) != 0 || fx_wsqrt(INT64_MIN) != 0;
    CHECK(bad == 0, "fx_wsqrt: %ld of %ld random Q.2F values, values next to squares and half-squares and the "
          "saturation edge differ from the exact rounded root", bad, n + 3);
}

/* fx_unit3 in plain 64-bit arithmetic: the bits the tracer's images are
 * made with (tests/host/image-tests.sh), so a change to them shows here. */
static uint32_t ref_rsqrt_q31(uint32_t x)
{
    static const uint32_t line[FX_RSQRT_LINES] = FX_RSQRT_LINE_INIT; /* fx.c's seed; test_rsqrt_line checks it */
    uint64_t c = line[(x >> 26) - 16];
    uint64_t y = c - (c & 0x7FF) * ((x >> 10) & 0xFFFF);
    uint64_t y2 = (y * y) >> 31; /* one step: y (3 - x y^2) / 2 */
    uint64_t xy2 = ((uint64_t)x * y2) >> 30;
    return (uint32_t)((y * (((uint64_t)3 << 31) - xy2)) >> 32);
}

static void ref_unit3(int64_t x, int64_t y, int64_t z, fx_t out[3])
{
    int64_t v[3] = { x, y, z };
    uint64_t m = 0, len2 = 0;
    for (int i = 0; i < 3; i++)
        m |= (uint64_t)(v[i] < 0 ? -v[i] : v[i]);
    if (m == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    int len_bits = 64;
    while (!(m >> (len_bits - 1)))
        len_bits--;
    for (int i = 0; i < 3; i++) { /* the largest component to 28 bits */
        v[i] = len_bits <= 28 ? v[i] * ((int64_t)1 << (28 - len_bits)) : v[i] >> (len_bits - 28);
        len2 += (uint64_t)(v[i] * v[i]);
    }
    int s = 0; /* len2 = (x / 2^30) 2^(62 - s), s even */
    while (!(len2 << s >> 62))
        s += 2;
    int64_t r = ref_rsqrt_q31((uint32_t)((len2 << s) >> 32));
    int shift = 62 - s / 2 - FX_FRAC_BITS;
    for (int i = 0; i < 3; i++)
        out[i] = (fx_t)((v[i] * r + ((int64_t)1 << (shift - 1))) >> shift);
}

/* The seed lines of fx.c's reciprocal square root, against the function
 * they stand for: under it, within 2^-11.3, at every 997th x and at both
 * ends of each line's interval. */
static void test_rsqrt_line(void)
{
    static const uint32_t line[FX_RSQRT_LINES] = FX_RSQRT_LINE_INIT;
    long above = 0;
    double worst = 0;
    for (uint64_t x = (uint64_t)1 << 30; x < (uint64_t)1 << 32;) {
        uint32_t c = line[(x >> 26) - 16];
        double y = (double)(c - (c & 0x7FFu) * ((x >> 10) & 0xFFFFu));
        double f = 2147483648.0 / sqrt((double)x / 1073741824.0);
        above += y > f;
        worst = (f - y) / f > worst ? (f - y) / f : worst;
        /* the next sample, or the last x of this interval, or the first of the next */
        uint64_t end = (x | 0x3FFFFFFu);
        x = (x == end) ? x + 1 : (x + 997 > end ? end : x + 997);
    }
    CHECK(above == 0 && worst < 0x1.ap-12, "rsqrt seed lines: %ld values above the function, worst %.2e below "
          "(bound 2^-11.3 = 4.0e-4)", above, worst);
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

    long bad = 0, n = 0;
    for (long i = 0; i < 2000000; i++) {
        int64_t w[3];
        int bits = 1 + (int)(tl_rand() % 62); /* a common scale, or any sizes */
        for (int k = 0; k < 3; k++)
            w[k] = (i & 1) ? rnd_bits(bits, true) : rnd_bits(62, true);
        if (i % 5 == 0)
            w[tl_rand() % 3] = 0;
        fx_t u[3], r[3];
        fx_unit3(w[0], w[1], w[2], u);
        ref_unit3(w[0], w[1], w[2], r);
        bad += u[0] != r[0] || u[1] != r[1] || u[2] != r[2];
        n++;
    }
    CHECK(bad == 0, "fx_unit3: %ld of %ld random vectors (scales 2^0..2^62) differ from the plain 64-bit "
          "formulation", bad, n);

    /* fx_unit3_narrow_len: the unit of fx_unit3_narrow, the length within
     * 2^-21 relative and a unit (saturated past FX_MAX) */
    bad = n = 0;
    long bad_len = 0;
    double worst_len = 0;
    for (long i = 0; i < 1000000; i++) {
        int bits = 1 + (int)(tl_rand() % 31);
        fx_t w[3];
        for (int k = 0; k < 3; k++)
            w[k] = (fx_t)rnd_bits(i & 1 ? bits : 31, true);
        fx_t u[3], r[3], len;
        fx_unit3_narrow_len(w[0], w[1], w[2], u, &len);
        fx_unit3_narrow(w[0], w[1], w[2], r);
        bad += u[0] != r[0] || u[1] != r[1] || u[2] != r[2];
        double l = sqrt((double)w[0] * w[0] + (double)w[1] * w[1] + (double)w[2] * w[2]);
        double want = l > FX_MAX ? FX_MAX : l, e = fabs(len - want);
        bad_len += e > 1 + want * pow(2, -21);
        worst_len = fmax(worst_len, e / (1 + want * pow(2, -21)));
        n++;
    }
    CHECK(bad == 0 && bad_len == 0, "fx_unit3_narrow_len: %ld of %ld units differ from fx_unit3_narrow, %ld lengths "
          "beyond 2^-21 relative and a unit (worst %.2f of that)", bad, n, bad_len, worst_len);
}

static void test_pow(void)
{
    static const double shines[] = { 1, 3.0827, 4.81884, 10, 100, 1000, 10000, 100000, 2, 4, 8, 16, 32, 64, 128 };
    for (unsigned k = 0; k < sizeof shines / sizeof shines[0]; k++) {
        shine_t s = (shine_t)llround(shines[k] * (1 << R_SHINE_FRAC_BITS));
        double sd = (double)s / (1 << R_SHINE_FRAC_BITS);
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
        double got = (double)fx_wtan_deg(deg) / ((double)FX_ONE * FX_ONE);
        double e = fabs(got - exact) / exact;
        worst = e > worst ? e : worst;
    }
    CHECK(worst < 3e-7, "fx_wtan_deg: max relative error %.2e over 0.5..89 degrees (bound 3e-7)", worst);
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
        int32_t a = rnd_word(), b = rnd_word();
        fx_t dx = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE; /* |d| <= 2, as fx_wdot3_sign_short wants */
        fx_t dy = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE;
        fx_t dz = (fx_t)(tl_rand() % (4u * FX_ONE + 1)) - 2 * FX_ONE;
        fx_wide_t nx = (int64_t)tl_rand() >> (tl_rand() & 63), ny = (int64_t)tl_rand() >> (tl_rand() & 63);
        fx_wide_t nz = (int64_t)tl_rand() >> (tl_rand() & 63);
        bad += fx_mul(a, b) != fx_sat64(fx_round_shift(plain_mul64(a, b), FX_FRAC_BITS));
        bad += fx_wmul(a, b) != plain_mul64(a, b);
        /* fx_wdot3_sign_short with the plain products (n shifted as it does) */
        uint64_t m = (uint64_t)(nx < 0 ? -nx : nx) | (uint64_t)(ny < 0 ? -ny : ny) | (uint64_t)(nz < 0 ? -nz : nz);
        int s = 0;
        while ((m >> s) >= ((uint64_t)1 << 40))
            s++;
        int64_t v = (int64_t)dx * (nx >> s) + (int64_t)dy * (ny >> s) + (int64_t)dz * (nz >> s);
        bad += fx_wdot3_sign_short(dx, dy, dz, nx, ny, nz) != (v > 0) - (v < 0);
        /* fx_wmul_fits inside its range: |w| < 2^(31+F), |w a| < 2^(63-F) */
        int wl = (int)(tl_rand() % (uint64_t)(62 - FX_FRAC_BITS < 30 + FX_FRAC_BITS ? 63 - FX_FRAC_BITS
                                                                                      : 31 + FX_FRAC_BITS));
        int fl = 62 - FX_FRAC_BITS - wl > 30 ? 30 : 62 - FX_FRAC_BITS - wl;
        fx_wide_t w = (int64_t)tl_rand() >> (63 - wl); /* |w| <= 2^wl */
        fx_t f = (fx_t)((int64_t)tl_rand() >> (63 - fl)); /* |f| <= 2^fl */
        int64_t whi = w >> FX_FRAC_BITS, wlo = (int64_t)((uint64_t)w & (uint64_t)(FX_ONE - 1));
        bad += fx_wmul_fits(w, f) != whi * f + fx_round_shift(wlo * f, FX_FRAC_BITS);
        n++;
    }
    CHECK(bad == 0, "fx_mul, fx_wmul, fx_wdot3_sign_short, fx_wmul_fits on the partial products: %ld of %ld "
          "random cases differ from the plain product", bad, 4 * n);

    bad = 0;
    for (fx_t c = -2; c <= FX_ONE + 2; c++)
        bad += r_to_u8(c) != (c <= 0 ? 0 : c >= FX_ONE ? 255 : (uint8_t)(((int64_t)c * 255 + FX_HALF) >> FX_FRAC_BITS));
    CHECK(bad == 0, "r_to_u8's 32-bit product: %ld of the %ld values -2..FX_ONE+2 differ from the 64-bit one", bad,
          (long)FX_ONE + 5);
}

/* fx_mul_weight (split into 16-bit halves here, FX_MUL64_PARTIAL) against
 * the long product of the same rounded weight, and within |c| 2^-16 + 1/2
 * unit of the exact c w; fx_mul_small within 1/2 + 4 |e| units of a e. */
static void test_weight(void)
{
    long bad_bits = 0, bad_err = 0, n = 0;
    double worst = 0;
    for (int i = 0; i < 400000; i++) {
        fx_t c = i < 8 ? (i & 1 ? FX_MAX : FX_MIN + (i >> 1)) : i & 1 ? (fx_t)rnd_bits(31, true) : rnd_fx(-4, 4);
        fx_t w = i % 7 == 0 ? FX_ONE + (i % 5) : i % 11 == 0 ? 0 : rnd_fx(0, 1);
        fx_t got = fx_mul_weight(c, w);
        int32_t w15 = (int32_t)((w + ((fx_t)1 << (FX_FRAC_BITS - 16))) >> (FX_FRAC_BITS - 15));
        if (w15 > 32768)
            w15 = 32768;
        bad_bits += got != (fx_t)(((int64_t)c * w15 + (1 << 14)) >> 15);
        double exact = (double)c * ((w > FX_ONE ? FX_ONE : w) / (double)FX_ONE);
        double err = fabs(got - exact), bound = fabs((double)c) / 65536 + 0.5;
        bad_err += err > bound;
        worst = fmax(worst, err / bound);
        n++;
    }
    CHECK(bad_bits == 0, "fx_mul_weight's 16-bit halves: %ld of %ld cases differ from the long product", bad_bits, n);
    CHECK(bad_err == 0, "fx_mul_weight within |c| 2^-16 + 1/2 unit of c w: %ld of %ld over (worst %.3f of the bound)",
          bad_err, n, worst);
    long bad = 0;
    n = 0;
    for (int i = 0; i < 400000; i++) {
        fx_t a = rnd_fx(-2, 2), e = rnd_fx(-1.0 / 1024, 1.0 / 1024);
        double err = fabs(fx_mul_small(a, e) - (double)a * e / FX_ONE);
        bad += err > 0.5 + 4 * fabs((double)e) / FX_ONE;
        n++;
    }
    CHECK(bad == 0, "fx_mul_small within 1/2 + 4 |e| units of a e: %ld of %ld over", bad, n);
    /* random pairs, and pairs made near perpendicular (b less its part along a) */
    bad = n = 0;
    long near = 0;
    for (int i = 0; i < 400000; i++) {
        fx_t a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = rnd_fx(-1.15, 1.15);
            b[k] = rnd_fx(-1.15, 1.15);
        }
        if (i & 1) {
            double ab = 0, aa = 0;
            for (int k = 0; k < 3; k++)
                ab += d(a[k]) * d(b[k]), aa += d(a[k]) * d(a[k]);
            for (int k = 0; k < 3; k++)
                b[k] -= (fx_t)llround(ab / aa * a[k] * (i % 3 ? 1 : 1 - 1e-4));
        }
        int64_t v = (int64_t)a[0] * b[0] + (int64_t)a[1] * b[1] + (int64_t)a[2] * b[2];
        bad += fx_dot3_negative_short(a[0], a[1], a[2], b[0], b[1], b[2]) != (v < 0);
        near += llabs(v) < ((int64_t)1 << (2 * FX_FRAC_BITS - 9));
        n++;
    }
    CHECK(bad == 0 && near > n / 4, "fx_dot3_negative_short (the 32-bit filter) is the exact sign's: %ld of %ld differ (%ld near "
          "perpendicular)", bad, n, near);

    /* fx_norm2_short the rounded 64-bit |a|^2 (|a| <= 2); fx_dot3_unit within 2^-13
     * of a . b for unit a, b */
    long bad_n = 0, bad_c = 0;
    double worst_c = 0;
    for (int i = 0; i < 400000; i++) {
        double v[3], w[3], lv = 0, lw = 0;
        for (int k = 0; k < 3; k++) {
            v[k] = tl_uniform(-1, 1), w[k] = tl_uniform(-1, 1);
            lv += v[k] * v[k], lw += w[k] * w[k];
        }
        double sv = (i & 1 ? 1 : tl_uniform(0, 2)) / sqrt(lv), sw = 1 / sqrt(lw);
        fx_t a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = (fx_t)llround(v[k] * sv * FX_ONE);
            b[k] = (fx_t)llround(w[k] * sw * FX_ONE);
        }
        int64_t n2_bits = (int64_t)a[0] * a[0] + (int64_t)a[1] * a[1] + (int64_t)a[2] * a[2];
        bad_n += fx_norm2_short(a[0], a[1], a[2]) != (fx_t)((n2_bits + FX_HALF) >> FX_FRAC_BITS);
        if (i & 1) {
            double c = d(a[0]) * d(b[0]) + d(a[1]) * d(b[1]) + d(a[2]) * d(b[2]);
            double e = fabs(d(fx_dot3_unit(a[0], a[1], a[2], b[0], b[1], b[2])) - c);
            bad_c += e > 1.0 / 8192;
            worst_c = fmax(worst_c, e);
        }
    }
    CHECK(bad_n == 0, "fx_norm2_short (32-bit halves) is the rounded 64-bit |a|^2 (|a| <= 2): %ld of 400000 differ", bad_n);
    CHECK(bad_c == 0, "fx_dot3_unit within 2^-13 of a . b for unit vectors: %ld of 200000 over (worst 2^%.1f)", bad_c,
          log2(worst_c));
}

int main(void)
{
    printf("test_fx (Q%d.%d)\n", 31 - FX_FRAC_BITS, FX_FRAC_BITS);
    test_mul_div();
    test_div_exact();
    test_wdiv_exact();
    test_clz();
    test_sqrt();
    test_sqrt_exact();
    test_unit3();
    test_rsqrt_line();
    test_pow();
    test_tan();
    test_decimal();
    test_mul64();
    test_weight();
    return tl_summary("test_fx");
}
