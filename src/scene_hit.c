/* scene_hit.c - brute-force traversal: every primitive of every kind. */
#include "scene_hit.h"

bool scene_nearest(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, rt_stats_t *st)
{
    bool found = false;
    for (uint32_t i = 0; i < sc->n_spheres; i++) {
        if (ray_hit_sphere(&sc->spheres[i], r, tmin, &h->t)) {
            h->kind = PRIM_SPHERE;
            h->index = i;
            found = true;
        }
    }
    for (uint32_t i = 0; i < sc->n_cones; i++) {
        if (ray_hit_cone(&sc->cones[i], r, tmin, &h->t)) {
            h->kind = PRIM_CONE;
            h->index = i;
            found = true;
        }
    }
    for (uint32_t i = 0; i < sc->n_polygons; i++) {
        if (ray_hit_polygon(sc, &sc->polygons[i], r, tmin, &h->t)) {
            h->kind = PRIM_POLYGON;
            h->index = i;
            found = true;
        }
    }
    st->tests_sphere += sc->n_spheres;
    st->tests_cone += sc->n_cones;
    st->tests_polygon += sc->n_polygons;
    return found;
}

bool scene_occluded(const scene_t *sc, const ray_t *r, real_t tmin, real_t tmax, rt_stats_t *st)
{
    real_t t = tmax;
    for (uint32_t i = 0; i < sc->n_spheres; i++) {
        st->tests_sphere++;
        if (ray_hit_sphere(&sc->spheres[i], r, tmin, &t))
            return true;
    }
    for (uint32_t i = 0; i < sc->n_cones; i++) {
        st->tests_cone++;
        if (ray_hit_cone(&sc->cones[i], r, tmin, &t))
            return true;
    }
    for (uint32_t i = 0; i < sc->n_polygons; i++) {
        st->tests_polygon++;
        if (ray_hit_polygon(sc, &sc->polygons[i], r, tmin, &t))
            return true;
    }
    return false;
}
