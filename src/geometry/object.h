/*
 * object.h - a solid as the BVH sees it: one shape, or the root of a CSG
 * tree (the shapes, transforms and CSG nodes are in solid.h).
 */
#ifndef OBJECT_H
#define OBJECT_H

#include "ray.h"

#define FIELDS_object_t(X) \
    X(vec3_t, box_min, ) /* world bounds */ \
    X(vec3_t, box_max, ) \
    X(uint16_t, root, )  /* shape index, or node index | CSG_NODE_BIT */
typedef struct { FIELDS_object_t(RT_DECLARE_FIELD) } object_t;

/* Nearest boundary of the object in (tmin, *t): sets *t, the shape, face
 * and flip of that boundary. w: the worker's span lists (scratch.h). */
bool ray_hit_object(const scene_t *sc, const object_t *o, const ray_t *r, real_t tmin, real_t *t,
                    struct ray_scratch *w, uint16_t *shape, uint8_t *face, bool *flip);

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool object_prim_hit(const scene_t *sc, const object_t *o, const ray_t *r, real_t tmin,
                                   real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    uint16_t shape;
    uint8_t face;
    bool flip;
    (void)self; /* rays leave solids by an offset, never marked as from one */
    if (!ray_hit_object(sc, o, r, tmin, t, w, &shape, &face, &flip))
        return false;
    if (h) {
        h->shape = shape;
        h->face = face;
        h->flip = flip;
    }
    return true;
}

static inline real_t object_prim_bounds(const object_t *o, vec3_t *lo, vec3_t *hi)
{
    *lo = o->box_min; /* already padded */
    *hi = o->box_max;
    return 0;
}

/* The surface of the shape the hit names (object.c). */
void object_prim_surface(const scene_t *sc, const object_t *o, const hit_t *h, vec3_t p,
                         prim_surface_t *out);

#endif
