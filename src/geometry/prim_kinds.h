/*
 * prim_kinds.h - the one list of primitive kinds.
 *
 * Whatever goes over every kind is generated from RT_PRIM_KINDS: the kind
 * enum, the scene's tables and their capacities (scene.h), the count of
 * primitives, the nearest-hit, any-hit, BVH-box and shading dispatch
 * (prims.h), the per-kind test counters (rt_stats.h), and the scene
 * compiler's tables and pruning switches. docs/embedding.md, "Adding a primitive",
 * gives the route.
 *
 * X(type, table, capacity, KIND, name, compiled_in):
 *   type         element type of the kind's table; its header gives the
 *                field list FIELDS_<type> it is declared from
 *   table        the scene_t member; n_<table> is its length
 *   capacity     the table's size in a scene_store_t (rt_config.h)
 *   KIND         PRIM_<KIND> in enum prim_kind
 *   name         prefix of the kind's interface: <name>_prim_hit,
 *                <name>_prim_bounds and <name>_prim_surface (see sphere.h)
 *   compiled_in  its switch, RT_USE_<TABLE> (rt_config.h): 0 leaves the
 *                kind's code out; the scene compiler sets it per scene
 *
 * Order matters: it is the order of the BVH's primitive list, and a tie
 * between two hits at the same t goes to the earlier kind.
 */
#ifndef PRIM_KINDS_H
#define PRIM_KINDS_H

#include "rt_config.h"

#include "cone.h"
#include "object.h"
#include "plane.h"
#include "polygon.h"
#include "sphere.h"

#define RT_PRIM_KINDS(X) \
    X(sphere_t,  spheres,  RT_MAX_SPHERES,  SPHERE,  sphere,  RT_USE_SPHERES) \
    X(cone_t,    cones,    RT_MAX_CONES,    CONE,    cone,    RT_USE_CONES) \
    X(polygon_t, polygons, RT_MAX_POLYGONS, POLYGON, polygon, RT_USE_POLYGONS) \
    X(object_t,  objects,  RT_MAX_OBJECTS,  OBJECT,  object,  RT_USE_OBJECTS) \
    X(plane_t,   planes,   RT_MAX_PLANES,   PLANE,   plane,   RT_USE_PLANES)

#define RT_PRIM_ENUM(type, table, cap, KIND, name, use) PRIM_##KIND,
enum prim_kind { RT_PRIM_KINDS(RT_PRIM_ENUM) PRIM_KIND_COUNT };
#undef RT_PRIM_ENUM

/* Kinds with no bounding box (infinite planes): left out of the BVH and
 * tested before it, on every ray (scene_hit.c). */
#define RT_PRIM_UNBOUNDED(kind) ((kind) == PRIM_PLANE)

/* Every kind's capacity together: the BVH's primitive list. */
#define RT_PRIM_CAPACITY(type, table, cap, KIND, name, use) + (cap)
#define RT_MAX_PRIMITIVES (0 RT_PRIM_KINDS(RT_PRIM_CAPACITY))

#define RT_PRIM_CHECK(type, table, cap, KIND, name, use) \
    _Static_assert((cap) >= 0 && (cap) <= 0xFFFFFF, #cap " out of 0..2^24-1: indices are 24-bit");
RT_PRIM_KINDS(RT_PRIM_CHECK)
#undef RT_PRIM_CHECK
_Static_assert(PRIM_KIND_COUNT <= 255, "the kind is 8-bit (prim_ref_t, hit_t)");

#endif
