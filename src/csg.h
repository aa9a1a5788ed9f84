/*
 * csg.h - CSG trees of shapes (layers: xform.h): union, intersection and
 * difference of their span lists, and the nearest boundary along a ray.
 */
#ifndef CSG_H
#define CSG_H

#include <stdbool.h>

#include "geometry.h"

/* Most spans a ray can have through this shape or CSG tree (the reader
 * checks it against RT_CSG_MAX_SPANS), and the tree's depth. */
uint32_t solid_max_spans(const scene_t *sc, uint16_t root);
uint32_t solid_depth(const scene_t *sc, uint16_t root);

/* Nearest boundary of the object in (tmin, *t): sets *t, the shape, face
 * and flip of that boundary. */
bool ray_hit_object(const scene_t *sc, const object_t *o, const ray_t *r, real_t tmin, real_t *t,
                    uint16_t *shape, uint8_t *face, bool *flip);

#endif
