/*
 * geometry.h - rays and the NFF primitives: set-up of the per-primitive
 * constants, ray intersection, and surface normals.
 *
 * The ray_hit_* functions share one convention: *t holds the nearest hit
 * found so far (the ray's far limit); a hit in (tmin, *t) replaces it and
 * returns true. Rays have unit directions, so t is a distance.
 */
#ifndef GEOMETRY_H
#define GEOMETRY_H

#include <stdbool.h>

#include "scene.h"
#include "tolerance.h"

/* A secondary ray starts on the surface of primitive `from` (PRIM_NONE for
 * eye rays and rays leaving solids). Leaving that primitive's outside, or
 * any plane, it cannot meet it again and skips it; going into a sphere or
 * cone (from_far) it meets it only at the far root. This replaces a
 * surface offset (tolerance.h). */
typedef struct {
    vec3_t origin, dir;
    prim_ref_t from;
    bool from_far;
} ray_t;

static inline vec3_t ray_at(const ray_t *r, real_t t) { return v3_madd(r->origin, t, r->dir); }

/* Set-up: each returns NULL, or the reason the primitive is degenerate. */
const char *sphere_init(sphere_t *s, vec3_t centre, real_t radius, uint16_t material);
const char *cone_init(cone_t *c, vec3_t base, real_t r_base, vec3_t apex, real_t r_apex,
                      uint16_t material);
/* True when all the polygon's vertices lie on one line (it has no area and
 * can never be hit; the SPD teapot has a few such triangles). */
bool polygon_is_flat(const vec3_t *pool, uint32_t first, uint16_t count);
const char *polygon_init(polygon_t *p, const vec3_t *pool, uint32_t first, uint16_t count,
                         uint32_t normals, uint16_t material);

/* far_only: the ray starts on this surface going in; only the far root. */
bool ray_hit_sphere(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only);
bool ray_hit_cone(const cone_t *c, const ray_t *r, real_t tmin, real_t *t, bool far_only);
bool ray_hit_polygon(const scene_t *sc, const polygon_t *p, const ray_t *r, real_t tmin,
                     real_t *t);

/* Outward geometric normals (unit) at a point on the surface. */
vec3_t sphere_normal(const sphere_t *s, vec3_t p);
vec3_t cone_normal(const cone_t *c, vec3_t p);
/* A patch's interpolated vertex normal at p (unit); Ng for a plain polygon. */
vec3_t polygon_shading_normal(const scene_t *sc, const polygon_t *p, vec3_t point);

#endif
