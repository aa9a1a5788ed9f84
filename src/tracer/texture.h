/*
 * texture.h - colours that vary: the textures of materials, by world
 * position, and the sky, by direction (texture.c). docs/shading-model.md,
 * "Textures and the sky", defines both.
 */
#ifndef TEXTURE_H
#define TEXTURE_H

#include "geometry/scene.h"

/* The colour C of texture tx at point p (in the scene's scale). */
colour_t texture_colour(const texture_t *tx, vec3_t p);

/* What a ray along unit direction d sees of the sky. */
colour_t sky_colour(const sky_t *sky, vec3_t d);

#endif
