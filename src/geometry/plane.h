/*
 * plane.h - the infinite plane (plane.c): a floor to the horizon.
 *
 * A plane has no box, so it is not in the BVH: scene_hit.c tests the
 * planes before traversing it (prim_kinds.h, RT_PRIM_UNBOUNDED). Its hits
 * count only inside the far cube |x|, |y|, |z| < 2^RT_FAR_EXTENT_LOG2
 * (in the reader's scale), which the model defines as the end of the
 * world (docs/shading-model.md): every hit point, and so every ray's
 * origin, stays inside the fixed range.
 */
#ifndef PLANE_H
#define PLANE_H

#include "ray.h"

#define FIELDS_plane_t(X) \
    X(vec3_t, normal, ) /* unit: the side the plane faces */ \
    X(real_t, offset, ) /* normal . p for every point p of the plane */ \
    X(uint16_t, material, ) \
    X(uint8_t, axis, ) /* the normal is +-1 along this axis, or V3_ANY_AXIS */
typedef struct { FIELDS_plane_t(RT_DECLARE_FIELD) } plane_t;

/* NULL, or why the plane is degenerate. point: any point of it. */
const char *plane_init(plane_t *pl, vec3_t point, vec3_t normal, uint16_t material);

bool ray_hit_plane(const plane_t *pl, const ray_t *r, real_t tmin, real_t *t);

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool plane_prim_hit(const scene_t *sc, const plane_t *pl, const ray_t *r, real_t tmin,
                                  real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)self, (void)w, (void)h; /* a ray leaving a plane skips it */
    return ray_hit_plane(pl, r, tmin, t);
}

/* Never called: planes are not in the BVH. */
static inline real_t plane_prim_bounds(const plane_t *pl, vec3_t *lo, vec3_t *hi)
{
    (void)pl;
    *lo = *hi = v3(0, 0, 0);
    return 0;
}

static inline void plane_prim_surface(const scene_t *sc, const plane_t *pl, const hit_t *h, vec3_t p,
                                      prim_surface_t *out)
{
    (void)sc, (void)h, (void)p;
    out->ng = out->n = pl->normal;
    out->material = pl->material;
    out->leave = LEAVE_SKIP_SELF;
    out->offset = RT_PLANE_OFFSET;
    out->smooth = false;
}

#endif
