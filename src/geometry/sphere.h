/* sphere.h - the NFF 's' primitive (sphere.c). */
#ifndef SPHERE_H
#define SPHERE_H

#include "ray.h"

#define FIELDS_sphere_t(X) \
    X(vec3_t, centre, ) \
    X(real_t, radius, ) \
    X(real_wide_t, radius2, ) /* exact r^2 */ \
    X(real_t, inv_radius, ) /* 1/r, or 0 where (p - c) / r would be too coarse (sphere_normal) */ \
    X(uint16_t, material, )
typedef struct { FIELDS_sphere_t(RT_DECLARE_FIELD) } sphere_t;

/* NULL, or why the sphere is degenerate. */
const char *sphere_init(sphere_t *s, vec3_t centre, real_t radius, uint16_t material);

/* *t holds the nearest hit so far; a hit in (tmin, *t) replaces it and
 * returns true. far_only: the ray starts on this surface going in.
 * ray_hit_sphere is the one out-of-line copy (sphere.c); the search of a
 * one-leaf scene takes the body inline, where a call cost a quarter of a
 * test that misses (scene_hit.c). */
bool ray_hit_sphere(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only);

static RT_INLINE bool sphere_hit_inline(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only)
{
    /* |l| < 2^10 (a centre inside the scene, an origin inside the far
     * extent), so v and v d are inside the range: no saturation tests */
    vec3_t l = v3_sub(s->centre, r->origin);
    real_t v = v3_dot_in_range(l, r->dir); /* distance to the point of closest approach */
    /* Early rejection (MIT 6.837): the whole sphere lies beyond the best hit
     * or behind the origin. */
    if (v - s->radius >= *t || v + s->radius <= tmin)
        return false;
    /* disc = r^2 - |l_perp|^2 from the perpendicular itself: its rounding
     * error scales with the radius, not with the distance (v^2 - |l|^2
     * would cancel catastrophically for a small, far sphere). */
    vec3_t perp = v3_madd_in_range(l, -v, r->dir);
    real_wide_t disc = s->radius2 - v3_wdot(perp, perp);
    if (disc < 0)
        return false;
    real_t h = r_wsqrt(disc);
    real_t t0 = v - h;
    if (t0 <= tmin || far_only)
        t0 = v + h;
    if (t0 <= tmin || t0 >= *t)
        return false;
    *t = t0;
    return true;
}

/* Outward unit normal at a point on the surface. */
vec3_t sphere_normal(const sphere_t *s, vec3_t p);

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool sphere_prim_hit(const scene_t *sc, const sphere_t *s, const ray_t *r, real_t tmin,
                                   real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)w, (void)h;
    return ray_hit_sphere(s, r, tmin, t, self);
}

/* The same with the test inline. */
static RT_INLINE bool sphere_prim_hit_inline(const scene_t *sc, const sphere_t *s, const ray_t *r, real_t tmin,
                                             real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)w, (void)h;
    return sphere_hit_inline(s, r, tmin, t, self);
}

/* Box [lo - pad, hi + pad] around it; returns pad. */
static inline real_t sphere_prim_bounds(const sphere_t *s, vec3_t *lo, vec3_t *hi)
{
    *lo = *hi = s->centre;
    return s->radius;
}

static inline void sphere_prim_surface(const scene_t *sc, const sphere_t *s, const hit_t *h, vec3_t p,
                                       prim_surface_t *out)
{
    (void)sc, (void)h;
    out->ng = out->n = sphere_normal(s, p);
    out->material = s->material;
    out->leave = LEAVE_FAR_ROOT;
    out->offset = 0;
    out->smooth = false;
}

#endif
