/* texture.c - checker and marble textures, the sky gradient. */
#include "texture.h"

#if RT_USE_CHECKER
/* The parity of the sum of the cells' indices: the cell index is the
 * floor of the exact product p inv_size (wide), so tiles far from the
 * origin and on the negative side are as wide as the others. */
static colour_t checker(const texture_t *tx, vec3_t p)
{
    const real_t c[3] = { p.x, p.y, p.z };
    int32_t sum = 0;
    real_t frac;
    for (unsigned a = 0; a < 3; a++)
        if (tx->axes >> a & 1u)
            sum += r_wsplit(r_wmul(c[a], tx->inv_size), &frac);
    return sum & 1 ? tx->b : tx->a;
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

/* Stripes across x, one a tile, bent by two octaves of noise. */
static colour_t marble(const texture_t *tx, vec3_t p)
{
    const real_t c[3] = { p.x, p.y, p.z };
    real_wide_t q[3], q2[3];
    for (unsigned a = 0; a < 3; a++) {
        q[a] = r_wmul(c[a], tx->inv_size);
        q2[a] = q[a] + q[a];
    }
    real_t n = noise(q) + noise(q2) / 2;
    real_t frac;
    (void)r_wsplit(q[0] + r_to_wide(r_mul(tx->amount, n)), &frac);
    real_t k = r_abs(2 * frac - R_ONE); /* a triangle wave, 1 at the stripes' edges */
    return v3_madd(tx->a, k, v3_sub(tx->b, tx->a));
}
#endif

colour_t texture_colour(const texture_t *tx, vec3_t p)
{
    (void)p;
    switch (tx->kind) {
#if RT_USE_CHECKER
    case TEXTURE_CHECKER:
        return checker(tx, p);
#endif
#if RT_USE_MARBLE
    case TEXTURE_MARBLE:
        return marble(tx, p);
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
