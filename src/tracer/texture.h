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
#endif

/* The colour C of texture tx at point p (in the scene's scale): its mean
 * over the footprint fp, or its value at p where fp is 0 or has no width
 * (and in a build without RT_RAY_CONES). A checker's point sample, the
 * common case, inline. */
static inline colour_t texture_colour(const texture_t *tx, vec3_t p, const footprint_t *fp)
{
#if RT_USE_CHECKER
    if (tx->kind == TEXTURE_CHECKER && (!fp || fp->width == 0))
        return checker_at_point(tx, p);
#endif
    return texture_colour_at(tx, p, fp);
}

/* What a ray along unit direction d sees of the sky. */
colour_t sky_colour(const sky_t *sky, vec3_t d);

#endif
