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

#if RT_BACKEND_FIXED && FX_FRAC_BITS == 20
/* Cores without a long multiply (ARMv6-M: a 64-bit product is ~17
 * instructions) first try a coarse test in 32-bit products, which says
 * "missed" only where the exact test would: most tests miss, and this
 * costs a third of the exact one. Proof of the bounds (Q.20 units unless
 * said; |l| < 2^10, |d| <= 1 + 2^-18, v the exact test's l . d):
 *  - a = floor(l 2^8) (Q.8, |a_i| < 2^18 + 1), b = floor(d 2^12) (Q.12,
 *    |b_i| <= 2^12 + 1): sum |a_i b_i| <= 2^20 |l||d| + 2^8 sqrt3 |l| +
 *    2^12 sqrt3 |d| + 3 < 2^31, so V = a . b needs no overflow test;
 *  - |V - v| <= sum (|d_i| 2^12 + |l_i| 2^8 + 1) + 2 (v's rounding)
 *    <= 7095 + sum (|a_i| + 1) + 5 < E = 7200 + sum |a_i|;
 *  - radii up to 2^6 only (R = r in Q.20): V +- (E + R) stays in 32 bits;
 *    the sphere lies behind tmin when V + E + R <= tmin, beyond t when
 *    V - E - R >= t;
 *  - w = floor(V / 2^12) (Q.8: within E / 2^12 + 1 of v 2^8, |w| <= 2^18
 *    + 1, so |w b_i| < 2^31), p_i = a_i - floor(w b_i / 2^12): within
 *    1 + (E / 2^12 + 1) + (|w| / 2^12 + 1) + 1 of perp_i 2^8 (the third
 *    term is v 2^8 times b_i's floor), so |p| is within G = 2 (5 + (E +
 *    |w|) / 2^12) of |perp| 2^8 (2 > sqrt3);
 *  - the line misses when |p| > lim = ceil(r 2^8) + G: a component past
 *    lim says so at once, else each |p_i| <= lim < 2^14.1 (r <= 2^6, G <
 *    530) and the squares' sum < 2^31. */
#define SPHERE_COARSE FX_MUL64_PARTIAL /* where it pays; tests/unit/test_sphere_coarse.c checks it on the host */
static RT_INLINE bool sphere_coarse_miss(const sphere_t *s, const ray_t *r, real_t tmin, real_t t)
{
    if (s->radius > ((fx_t)64 << FX_FRAC_BITS))
        return false;
    int32_t a0 = (s->centre.x - r->origin.x) >> 12, a1 = (s->centre.y - r->origin.y) >> 12,
            a2 = (s->centre.z - r->origin.z) >> 12;
    int32_t b0 = r->dir.x >> 8, b1 = r->dir.y >> 8, b2 = r->dir.z >> 8;
    int32_t v = a0 * b0 + a1 * b1 + a2 * b2;
    int32_t e = 7200 + (a0 < 0 ? -a0 : a0) + (a1 < 0 ? -a1 : a1) + (a2 < 0 ? -a2 : a2);
    if (v + e + s->radius <= tmin || v - e - s->radius >= t)
        return true;
    int32_t w = v >> 12;
    int32_t lim = (s->radius >> 12) + 1 + 2 * (5 + ((e + (w < 0 ? -w : w)) >> 12) + 1);
    int32_t p0 = a0 - ((w * b0) >> 12), p1 = a1 - ((w * b1) >> 12), p2 = a2 - ((w * b2) >> 12);
    if (p0 > lim || p0 < -lim || p1 > lim || p1 < -lim || p2 > lim || p2 < -lim)
        return true;
    return (uint32_t)(p0 * p0) + (uint32_t)(p1 * p1) + (uint32_t)(p2 * p2) > (uint32_t)(lim * lim);
}
#else
#define SPHERE_COARSE 0
#endif

static RT_INLINE bool sphere_hit_inline(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only)
{
#if SPHERE_COARSE
    if (sphere_coarse_miss(s, r, tmin, *t))
        return false;
#endif
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
