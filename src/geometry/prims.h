/*
 * prims.h - a primitive of any kind: the dispatch over the kinds of
 * prim_kinds.h, generated from its list. A kind compiled out (its RT_USE_*
 * switch is 0) leaves a case that does nothing, so its code is not linked.
 */
#ifndef PRIMS_H
#define PRIMS_H

#include "geometry.h"
#include "scratch.h"

/* Whether ray r meets primitive ref in (tmin, *t); sets *t and, for
 * objects, h's shape fields (h may be NULL for any-hit). `self`: the ray
 * starts on this primitive going in (only its far side counts). Counts
 * the test in w->stats; w is the worker's scratch (CSG span lists). */
static RT_INLINE bool prim_hit(const scene_t *sc, prim_ref_t ref, const ray_t *r, real_t tmin, real_t *t,
                               bool self, ray_scratch_t *w, hit_t *h)
{
    uint32_t i = PRIM_INDEX(ref);
    switch (PRIM_KIND(ref)) {
#define RT_PRIM_HIT_CASE(type, table, cap, KIND, name, use) \
    case PRIM_##KIND: \
        if (!(use)) \
            return false; \
        w->stats.prim_tests[PRIM_##KIND]++; \
        return name##_prim_hit(sc, &sc->table[i], r, tmin, t, self, w, h);
        RT_PRIM_KINDS(RT_PRIM_HIT_CASE)
#undef RT_PRIM_HIT_CASE
    default:
        return false;
    }
}

/* Conservative box of one primitive. */
static inline void prim_bounds(const scene_t *sc, prim_ref_t ref, real_t pad, vec3_t *min, vec3_t *max)
{
    uint32_t i = PRIM_INDEX(ref);
    vec3_t lo = { 0, 0, 0 }, hi = { 0, 0, 0 };
    switch (PRIM_KIND(ref)) {
#define RT_PRIM_BOUNDS_CASE(type, table, cap, KIND, name, use) \
    case PRIM_##KIND: \
        pad += name##_prim_bounds(&sc->table[i], &lo, &hi); \
        break;
        RT_PRIM_KINDS(RT_PRIM_BOUNDS_CASE)
#undef RT_PRIM_BOUNDS_CASE
    default:
        break;
    }
    *min = v3(lo.x - pad, lo.y - pad, lo.z - pad);
    *max = v3(hi.x + pad, hi.y + pad, hi.z + pad);
}

/* The surface at hit h, point p on it. */
static RT_INLINE void prim_surface(const scene_t *sc, const hit_t *h, vec3_t p, prim_surface_t *out)
{
    switch (h->kind) {
#define RT_PRIM_SURFACE_CASE(type, table, cap, KIND, name, use) \
    case PRIM_##KIND: \
        if (use) { \
            name##_prim_surface(sc, &sc->table[h->index], h, p, out); \
            return; \
        } \
        break;
        RT_PRIM_KINDS(RT_PRIM_SURFACE_CASE)
#undef RT_PRIM_SURFACE_CASE
    default:
        break;
    }
    RT_UNREACHABLE(); /* a hit is always on a kind this build has */
}

#endif
