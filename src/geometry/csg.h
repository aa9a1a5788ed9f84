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

/* ray_hit_object (csg.c), the nearest boundary of an object, is declared
 * with the object kind in object.h. */

#endif
