/* polygon.h - the NFF 'p' polygon and 'pp' patch (polygon.c). */
#ifndef POLYGON_H
#define POLYGON_H

#include "ray.h"

#define POLY_NO_NORMALS UINT32_MAX

/* Vertices [first, first + count) of the scene's vertex pool; a patch
 * also has normals at the same indices. Inside tests work in the plane
 * of the two axes other than `drop_axis`. */
#define FIELDS_polygon_t(X) \
    X(vec3_t, normal, )    /* Ng, unit, from the first three vertices */ \
    X(real_t, offset, )    /* Ng . v0 */ \
    X(vec3_t, box_min, ) \
    X(vec3_t, box_max, ) \
    X(uint32_t, first, ) \
    X(uint32_t, normals, ) /* first normal, or POLY_NO_NORMALS for 'p' */ \
    X(uint16_t, count, ) \
    X(uint16_t, material, ) \
    X(uint8_t, drop_axis, ) \
    X(uint8_t, convex, )   /* inside test by edge sides (watertight) */ \
    X(uint8_t, rect, )     /* fixed build: an axis rectangle, see axis_rect */
typedef struct { FIELDS_polygon_t(RT_DECLARE_FIELD) } polygon_t;

/* NULL, or why the polygon is degenerate. The reader decides that (its
 * vertices on one line, its first three collinear) on the position grid
 * and passes the first three's normal there, grid_normal (any size): the
 * normal where this build's rounded vertices make the cross product zero. */
const char *polygon_init(polygon_t *p, const vec3_t *pool, uint32_t first, uint16_t count,
                         uint32_t normals, uint16_t material, vec3_t grid_normal);

/* As ray_hit_sphere (sphere.h); a ray never meets the plane it leaves. */
bool ray_hit_polygon(const scene_t *sc, const polygon_t *p, const ray_t *r, real_t tmin,
                     real_t *t);

/* A patch's interpolated vertex normal at p (unit); Ng for a plain polygon. */
vec3_t polygon_shading_normal(const scene_t *sc, const polygon_t *p, vec3_t point);

/* ---- the primitive-kind interface (prim_kinds.h) ---------------------- */

static inline bool polygon_prim_hit(const scene_t *sc, const polygon_t *p, const ray_t *r, real_t tmin,
                                    real_t *t, bool self, struct ray_scratch *w, hit_t *h)
{
    (void)self, (void)w, (void)h;
    return ray_hit_polygon(sc, p, r, tmin, t);
}

static inline real_t polygon_prim_bounds(const polygon_t *p, vec3_t *lo, vec3_t *hi)
{
    *lo = p->box_min; /* already padded */
    *hi = p->box_max;
    return 0;
}

static inline void polygon_prim_surface(const scene_t *sc, const polygon_t *p, const hit_t *h, vec3_t point,
                                        prim_surface_t *out)
{
    (void)h;
    out->ng = p->normal;
    out->n = polygon_shading_normal(sc, p, point);
    out->material = p->material;
    out->leave = LEAVE_SKIP_SELF;
    out->offset = RT_PLANE_OFFSET;
    out->smooth = p->normals != POLY_NO_NORMALS;
}

#endif
