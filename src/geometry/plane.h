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

/* *t holds the nearest hit so far; a hit in (tmin, *t) replaces it and
 * returns true. ray_hit_plane is the one out-of-line copy (plane.c); the
 * search of a one-leaf scene takes the body inline, as the sphere's. */
bool ray_hit_plane(const plane_t *pl, const ray_t *r, real_t tmin, real_t *t);

/* The far cube's half side: hits beyond it are not part of the scene. */
#define PLANE_FAR r_from_int((int32_t)1 << RT_FAR_EXTENT_LOG2)

/* Whether the hit at t0 lies inside the far cube, from the hit point
 * (exact in the wide type): the rare far hits (plane.c). */
bool plane_hit_inside(const ray_t *r, real_t t0);

static RT_INLINE bool plane_hit_inline(const plane_t *pl, const ray_t *r, real_t tmin, real_t *t)
{
    /* t = (offset - N.O) / (N.D), compared as products before the
     * division: a ray almost parallel to the plane meets it far beyond
     * the range, and its quotient would overflow */
    real_t den, num;
    if (pl->axis != V3_ANY_AXIS) { /* N = +-1 along the axis: no products */
        den = v3_dot_along(&pl->normal, pl->axis, &r->dir);
        num = pl->offset - v3_dot_along(&pl->normal, pl->axis, &r->origin);
    } else {
        den = v3_dot_in_range(pl->normal, r->dir); /* unit vectors */
        num = pl->offset - v3_dot_in_range(pl->normal, r->origin); /* |origin| < 2^10 */
    }
    if (den < 0) {
        den = -den;
        num = -num;
    }
    if (num <= 0 || r_to_wide(num) >= r_wmul(*t, den) || r_to_wide(num) <= r_wmul(tmin, den))
        return false;
    real_t t0 = r_div(num, den);
    if (t0 <= tmin || t0 >= *t)
        return false;
    /* Inside the far cube when t0 < far - 1 - max |o_a| (|d_a| <= 1 + 2^-19
     * and t0 < 2^11): most hits, at no product. Float and double take the
     * sum of the |o_a| (three vabs, two adds), no less than their largest. */
#if RT_BACKEND_FIXED
    real_t omax = r_max(r_max(r_abs(r->origin.x), r_abs(r->origin.y)), r_abs(r->origin.z));
#else
    real_t omax = R_FN(fabs)(r->origin.x) + R_FN(fabs)(r->origin.y) + R_FN(fabs)(r->origin.z);
#endif
    if (t0 >= PLANE_FAR - R_ONE - omax && !plane_hit_inside(r, t0))
        return false;
    *t = t0;
    return true;
}

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool plane_prim_hit(const scene_t *sc, const plane_t *pl, const ray_t *r, real_t tmin,
                                  real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)self, (void)w, (void)h; /* a ray leaving a plane skips it */
    return ray_hit_plane(pl, r, tmin, t);
}

/* The same with the test inline. */
static RT_INLINE bool plane_prim_hit_inline(const scene_t *sc, const plane_t *pl, const ray_t *r, real_t tmin,
                                            real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)sc, (void)self, (void)w, (void)h;
    return plane_hit_inline(pl, r, tmin, t);
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
