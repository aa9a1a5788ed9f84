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

/* The colour C of texture tx at point p (in the scene's scale): its mean
 * over the footprint fp, or its value at p where fp is 0 or has no width
 * (and in a build without RT_RAY_CONES). */
colour_t texture_colour(const texture_t *tx, vec3_t p, const footprint_t *fp);

/* What a ray along unit direction d sees of the sky. */
colour_t sky_colour(const sky_t *sky, vec3_t d);

#endif
