/* cone.h - the NFF 'c' primitive: an open cone or cylinder (cone.c). */
#ifndef CONE_H
#define CONE_H

#include "ray.h"

/* Radius r0 at `base`, growing by `slope` per unit of height along the
 * unit `axis`, up to `height` (the apex end). */
#define FIELDS_cone_t(X) \
    X(vec3_t, base, ) \
    X(vec3_t, axis, ) \
    X(real_t, height, ) \
    X(real_t, r0, ) \
    X(real_t, slope, ) \
    X(vec3_t, bound_centre, ) /* bounding sphere, for early rejection */ \
    X(real_t, bound_radius, ) \
    X(real_wide_t, bound_radius2, ) \
    X(real_t, miss_radius2, ) /* cylinder_missed (cone.c) */ \
    X(uint16_t, material, )
typedef struct { FIELDS_cone_t(RT_DECLARE_FIELD) } cone_t;

/* NULL, or why the cone is degenerate. */
const char *cone_init(cone_t *c, vec3_t base, real_t r_base, vec3_t apex, real_t r_apex,
                      uint16_t material);

/* As ray_hit_sphere (sphere.h). */
bool ray_hit_cone(const cone_t *c, const ray_t *r, real_t tmin, real_t *t, bool far_only);

/* Outward unit normal at a point on the surface. */
vec3_t cone_normal(const cone_t *c, vec3_t p);

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool cone_prim_hit(const scene_t *sc, const cone_t *c, const ray_t *r, real_t tmin,
                                 real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)w, (void)h;
    return ray_hit_cone(c, r, tmin, t, self);
}

/* Both end discs fit in boxes of their larger radius. */
static inline real_t cone_prim_bounds(const cone_t *c, vec3_t *lo, vec3_t *hi)
{
    vec3_t apex = v3_madd(c->base, c->height, c->axis);
    *lo = v3(r_min(c->base.x, apex.x), r_min(c->base.y, apex.y), r_min(c->base.z, apex.z));
    *hi = v3(r_max(c->base.x, apex.x), r_max(c->base.y, apex.y), r_max(c->base.z, apex.z));
    return r_max(c->r0, c->r0 + r_mul(c->slope, c->height));
}

static inline void cone_prim_surface(const scene_t *sc, const cone_t *c, const hit_t *h, vec3_t p,
                                     prim_surface_t *out)
{
    (void)sc, (void)h;
    out->ng = out->n = cone_normal(c, p);
    out->material = c->material;
    out->leave = LEAVE_FAR_ROOT;
    out->offset = 0;
    out->smooth = false;
}

#endif
