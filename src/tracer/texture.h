/*
 * texture.h - colours that vary: the textures of materials, by world
 * position, and the sky, by direction (texture.c). docs/shading-model.md,
 * "Textures and the sky", defines both.
 */
#ifndef TEXTURE_H
#define TEXTURE_H

#include "geometry/scene.h"

/* Where a ray's cone meets a surface (docs/shading-model.md, "Filtered
 * textures"): the ray's unit direction, the unit normal facing it, and
 * the cone's signed width there. */
typedef struct {
    vec3_t dir, n;
    real_t width;
} footprint_t;

/* The footprint's caps (docs/shading-model.md, "Filtered textures"): its
 * half-extents stop at 1024 cells, where a filtered texture is within
 * 2^-11 of its mean, and its elongation at 256 (a ray within 1/4 degree
 * of the surface). Both keep every step inside the fixed range. */
#define FOOTPRINT_MAX_CELLS R_RATIO(1024, 1)
#define FOOTPRINT_MIN_COS R_RATIO(1, 256)

/* texture_colour's general case (texture.c): every kind, any footprint. */
colour_t texture_colour_at(const texture_t *tx, vec3_t p, const footprint_t *fp);

#if RT_USE_CHECKER
/* A checker's colour at point p: A where the sum of the named axes' cell
 * indices (floors of exact products) is even, B where it is odd. */
static inline colour_t checker_at_point(const texture_t *tx, vec3_t p)
{
    int32_t n = 0;
    real_t f;
    if (tx->axes & 1u)
        n += r_wsplit(r_wmul(p.x, tx->inv_size), &f);
    if (tx->axes & 2u)
        n += r_wsplit(r_wmul(p.y, tx->inv_size), &f);
    if (tx->axes & 4u)
        n += r_wsplit(r_wmul(p.z, tx->inv_size), &f);
    return n & 1 ? tx->b : tx->a;
}

#if RT_RAY_CONES
/* Whether fp's footprint lies inside p's cell along every named axis, so
 * that its mean is the point sample. texture.c's half-extent along axis a,
 * h_a = rho len_a / c, has len_a <= 1 (plus 2^-15 from the normals'
 * rounding; 2^-12 and 8 units of margin cover it and every rounding), so
 * rho < dist_a c, the distance to the cell's nearer edge, says the
 * interval [x - h_a, x + h_a] stays in the cell: the same colour without
 * the root and the division a filtered lookup takes. */
static inline bool footprint_in_cell(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
    real_t rho = r_mul(r_abs(fp->width) / 2, tx->inv_size);
    real_t c = r_max(-v3_dot_in_range(fp->dir, fp->n), FOOTPRINT_MIN_COS);
    const real_t x[3] = { p.x, p.y, p.z };
    if (rho >= FOOTPRINT_MAX_CELLS)
        return false;
    rho += rho / 4096 + R_ULPS(8);
    for (unsigned a = 0; a < 3; a++) {
        if (!(tx->axes >> a & 1u))
            continue;
        real_t f;
        r_wsplit(r_wmul(x[a], tx->inv_size), &f);
        if (r_mul(r_min(f, R_ONE - f), c) <= rho)
            return false;
    }
    return true;
}
#endif
#endif

/* The colour C of texture tx at point p (in the scene's scale): its mean
 * over the footprint fp, or its value at p where fp is 0 or has no width
 * (and in a build without RT_RAY_CONES). A checker's point sample, the
 * common case, inline. */
static inline colour_t texture_colour(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
#if RT_USE_CHECKER
#if RT_RAY_CONES
    if (tx->kind == TEXTURE_CHECKER && (!fp || fp->width == 0 || footprint_in_cell(tx, p, fp)))
        return checker_at_point(tx, p);
#else
    if (tx->kind == TEXTURE_CHECKER)
        return checker_at_point(tx, p);
#endif
#endif
    return texture_colour_at(tx, p, fp);
}

/* What a ray along unit direction d sees of the sky. */
colour_t sky_colour(const sky_t *sky, vec3_t d);

#endif
