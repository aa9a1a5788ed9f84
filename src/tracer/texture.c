/* texture.c - checker and marble textures, the sky gradient. */
#include "texture.h"

#include "shine.h"

#if RT_USE_TEXTURES
/* a + (b - a) k: the texture's colour at weight k of b */
static colour_t blend(const texture_t *tx, real_t k) { return v3_madd(tx->a, k, v3_sub(tx->b, tx->a)); }

#if RT_RAY_CONES
/* (the footprint's caps: texture.h) */
_Static_assert(!RT_BACKEND_FIXED || FX_FRAC_BITS <= 20, "the cap, 1024 cells, and a stripe's slope (16) above it fit the range");

/* The half-extents h[a], in cells (inv_size a cell), along the world axes
 * named in `axes` of the ellipse where fp's cone meets the surface: minor
 * radius |width| / 2, major |width| / (2 cos), the major along T = D +
 * cos N, the surface's tangent in D's plane. For unit N and cos = -D.N,
 *   h_a = rho sqrt(c^2 (1 - N_a^2) + T_a^2) / c
 * with rho = |width| inv_size / 2 and c = cos, each capped. */
static void footprint_extents(const footprint_t *fp, real_t inv_size, unsigned axes, real_t h[3])
{
    real_t rho = r_min(r_mul(r_abs(fp->width) / 2, inv_size), FOOTPRINT_MAX_CELLS);
    real_t cos_i = -v3_dot_in_range(fp->dir, fp->n);
    real_t c = r_max(cos_i, FOOTPRINT_MIN_COS);
    real_wide_t c2 = r_wmul(c, c);
    real_t cap = r_mul(FOOTPRINT_MAX_CELLS, c); /* h_a >= the cap iff rho sqrt(..) >= cap c */
    const real_t d[3] = { fp->dir.x, fp->dir.y, fp->dir.z }, n[3] = { fp->n.x, fp->n.y, fp->n.z };
    for (unsigned a = 0; a < 3; a++) {
        if (!(axes >> a & 1u))
            continue;
        real_t t = d[a] + r_mul(cos_i, n[a]);
        real_t across = r_max(R_ONE - r_mul(n[a], n[a]), 0); /* 1 - N_a^2 */
        real_t len = r_wsqrt(r_wmul_real(c2, across) + r_wmul(t, t));
        real_t num = r_mul(rho, len);
        h[a] = num >= cap ? FOOTPRINT_MAX_CELLS : r_div(num, c);
    }
}

/* The footprint's half-extents in cells, 0 where fp gives no footprint. */
static void cell_extents(const footprint_t *fp, real_t inv_size, unsigned axes, real_t h[3])
{
    h[0] = h[1] = h[2] = 0;
    if (fp && fp->width != 0)
        footprint_extents(fp, inv_size, axes, h);
}
#else
static void cell_extents(const footprint_t *fp, real_t inv_size, unsigned axes, real_t h[3])
{
    (void)fp, (void)inv_size, (void)axes;
    h[0] = h[1] = h[2] = 0;
}
#endif
#endif

#if RT_USE_CHECKER
/* The mean over [x - h, x + h] (x in cells, exact: wide) of the square
 * wave, +1 on even cells and -1 on odd: its value where the interval is
 * inside one cell (so h = 0 is the point sample), else the change of its
 * integral, the triangle wave (frac on even cells, 1 - frac on odd), over
 * 2h. Cell indices are floors of exact values, so tiles far from the
 * origin and on the negative side are as wide as the others. */
static real_t square_wave_mean(real_wide_t x, real_t h)
{
    real_t f_lo, f_hi;
    int32_t lo = r_wsplit(x - r_to_wide(h), &f_lo), hi = r_wsplit(x + r_to_wide(h), &f_hi);
    if (lo == hi)
        return lo & 1 ? -R_ONE : R_ONE;
    real_t t_lo = lo & 1 ? R_ONE - f_lo : f_lo, t_hi = hi & 1 ? R_ONE - f_hi : f_hi;
    return r_div(t_hi - t_lo, h) / 2; /* 2h may pass the fixed range */
}

/* The checker's parity, +1 or -1 a cell, is the product of the named
 * axes' square waves; a box filter, separable, averages each alone. */
static colour_t checker(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
    const real_t c[3] = { p.x, p.y, p.z };
    real_t h[3];
    cell_extents(fp, tx->inv_size, tx->axes, h);
    if (h[0] == 0 && h[1] == 0 && h[2] == 0) /* a point: the mean of each axis is +-1, their product the parity */
        return checker_at_point(tx, p);
    real_t mean = R_ONE;
    for (unsigned a = 0; a < 3; a++)
        if (tx->axes >> a & 1u)
            mean = r_mul(mean, square_wave_mean(r_wmul(c[a], tx->inv_size), h[a]));
    if (mean == R_ONE || mean == -R_ONE) /* inside a cell: exactly A or B */
        return mean > 0 ? tx->a : tx->b;
    return blend(tx, (R_ONE - mean) / 2);
}
#endif

#if RT_USE_MARBLE
/* One of 16 gradients for lattice point (i, j, k): an integer hash, so no
 * permutation table. */
static uint32_t lattice_hash(int32_t i, int32_t j, int32_t k)
{
    uint32_t n = (uint32_t)i * 0x8da6b343u + (uint32_t)j * 0xd8163841u + (uint32_t)k * 0xcb1ab31fu;
    n ^= n >> 15;
    n *= 0x2c1b3c6du;
    n ^= n >> 12;
    return n >> 28;
}

/* The dot product of gradient h, an edge direction of the cube (the
 * 12 of them, four twice), with (x, y, z). */
static real_t gradient_dot(uint32_t h, real_t x, real_t y, real_t z)
{
    real_t u = h < 8 ? x : y;
    real_t v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1u) ? -u : u) + ((h & 2u) ? -v : v);
}

/* 6 t^5 - 15 t^4 + 10 t^3: the weight whose first two derivatives
 * vanish at the cell's faces */
static real_t fade(real_t t)
{
    real_t t3 = r_mul(r_mul(t, t), t);
    return r_mul(t3, r_mul(t, r_mul(t, r_from_int(6)) - r_from_int(15)) + r_from_int(10));
}

static real_t lerp(real_t a, real_t b, real_t t) { return a + r_mul(t, b - a); }

/* Gradient noise at the point q given exactly (wide): about -1 to 1,
 * 0 at every lattice point. */
static real_t noise(const real_wide_t q[3])
{
    int32_t c[3];
    real_t f[3], v[8];
    for (unsigned a = 0; a < 3; a++)
        c[a] = r_wsplit(q[a], &f[a]);
    for (unsigned k = 0; k < 8; k++) {
        unsigned dx = k & 1u, dy = k >> 1 & 1u, dz = k >> 2;
        v[k] = gradient_dot(lattice_hash(c[0] + (int32_t)dx, c[1] + (int32_t)dy, c[2] + (int32_t)dz),
                            dx ? f[0] - R_ONE : f[0], dy ? f[1] - R_ONE : f[1], dz ? f[2] - R_ONE : f[2]);
    }
    real_t u = fade(f[0]), s = fade(f[1]), w = fade(f[2]);
    real_t y0 = lerp(lerp(v[0], v[1], u), lerp(v[2], v[3], u), s);
    real_t y1 = lerp(lerp(v[4], v[5], u), lerp(v[6], v[7], u), s);
    return lerp(y0, y1, w);
}

/* An octave's weight at footprint diameter x of its period: 1 up to a
 * half, fading to 0 at a whole one (its mean over a period is about 0). */
static real_t octave_weight(real_t x)
{
    return x <= R_RATIO(1, 2) ? R_ONE : x >= R_ONE ? 0 : 2 * (R_ONE - x);
}

/* The integral of the triangle wave |2 frac(y) - 1| from floor(y): f - f^2
 * to the middle of the period (f <= 1/2), 1/4 + (f - 1/2)^2 after. */
static real_t triangle_part(real_t f)
{
    return f <= R_RATIO(1, 2) ? f - r_mul(f, f) : R_RATIO(1, 4) + r_mul(f - R_RATIO(1, 2), f - R_RATIO(1, 2));
}

/* The mean over [y - h, y + h] (y exact: wide) of |2 frac(y) - 1|: its
 * value where the interval lies on one of its straight pieces (so h = 0
 * is the point sample), else the change of its integral (a half a whole
 * period) over 2h. */
static real_t triangle_mean(real_wide_t y, real_t h)
{
    real_t f_lo, f_hi, f;
    int32_t lo = r_wsplit(y - r_to_wide(h), &f_lo), hi = r_wsplit(y + r_to_wide(h), &f_hi);
    if (lo == hi && (f_lo < R_RATIO(1, 2)) == (f_hi < R_RATIO(1, 2))) {
        (void)r_wsplit(y, &f);
        return r_abs(2 * f - R_ONE);
    }
    int32_t periods = hi - lo; /* halved exactly: up to 2049 passes Q11 */
    real_t change = r_from_int(periods >> 1) + (periods & 1 ? R_RATIO(1, 2) : 0);
    change += triangle_part(f_hi) - triangle_part(f_lo);
    return r_div(change, h) / 2;
}

/* Stripes across x, one a tile, bent by two octaves of noise. Over a
 * footprint of radius rho (its largest half-extent), an octave fades out
 * as rho grows to its period, and the stripes are box-filtered over the
 * footprint's x extent widened by the noise's slope (amount a whole
 * octave). */
static colour_t marble(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
    const real_t c[3] = { p.x, p.y, p.z };
    real_wide_t q[3], q2[3];
    for (unsigned a = 0; a < 3; a++) {
        q[a] = r_wmul(c[a], tx->inv_size);
        q2[a] = q[a] + q[a];
    }
    real_t h[3];
    cell_extents(fp, tx->inv_size, 7u, h);
    real_t rho = r_max(r_max(h[0], h[1]), h[2]);
    real_t w1 = 0, w2 = 0; /* the octaves' weights: periods 1 and 1/2 */
    if (rho < R_RATIO(1, 2)) {
        w1 = octave_weight(2 * rho);
        w2 = octave_weight(4 * rho);
    }
    real_t n = 0;
    if (w1 != 0)
        n = w1 == R_ONE ? noise(q) : r_mul(w1, noise(q));
    if (w2 != 0)
        n += (w2 == R_ONE ? noise(q2) : r_mul(w2, noise(q2))) / 2;
    real_t slope = r_mul(tx->amount, r_mul(rho, w1 + w2)); /* <= 16 with rho < 1/2 */
    real_t k = triangle_mean(q[0] + r_to_wide(r_mul(tx->amount, n)), h[0] + slope); /* 1 at the stripes' edges */
    return blend(tx, k);
}
#endif

colour_t texture_colour_at(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
    (void)p, (void)fp;
    switch (tx->kind) {
#if RT_USE_CHECKER
    case TEXTURE_CHECKER:
        return checker(tx, p, fp);
#endif
#if RT_USE_MARBLE
    case TEXTURE_MARBLE:
        return marble(tx, p, fp);
#endif
    default:
        RT_UNREACHABLE(); /* a scene holds only the kinds this build has */
    }
}

colour_t sky_colour(const sky_t *sky, vec3_t d)
{
    real_t up = v3_dot_axis(sky->up, sky->up_axis, d);
    real_t k = r_pow_unit(R_ONE - r_max(up, 0), sky->exponent); /* in [0, 1] */
    return v3_add(sky->zenith, c3_scale_weight(v3_sub(sky->horizon, sky->zenith), k));
}
