/*
 * scene.h - a scene as the tracer sees it: flat tables of primitives with
 * their per-primitive constants already computed.
 *
 * scene_t only points at its tables, so they can live in RAM (filled by the
 * NFF reader into a scene_store_t) or in flash (emitted as const data by the
 * scene compiler for a board).
 */
#ifndef SCENE_H
#define SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "rt_config.h"
#include "vec3.h"

typedef struct {
    colour_t colour;  /* C */
    real_t kd, ks, t, ior;
    shine_t shine;
} material_t;

typedef struct {
    vec3_t pos;
    colour_t colour;  /* Lc, (1, 1, 1) unless given */
} light_t;

typedef struct {
    vec3_t centre;
    real_t radius;
    real_wide_t radius2; /* exact r^2 */
    uint16_t material;
} sphere_t;

/* Open cone/cylinder: radius r0 at `base`, growing by `slope` per unit of
 * height along the unit `axis`, up to `height` (the apex end). */
typedef struct {
    vec3_t base, axis;
    real_t height, r0, slope;
    vec3_t bound_centre;      /* bounding sphere, for early rejection */
    real_t bound_radius;
    real_wide_t bound_radius2;
    uint16_t material;
} cone_t;

#define POLY_NO_NORMALS UINT32_MAX

/* Planar polygon ('p') or patch ('pp'): vertices [first, first + count) of
 * the scene's vertex pool; a patch also has normals at the same indices.
 * Inside tests work in the plane of the two axes other than `drop_axis`. */
typedef struct {
    vec3_t normal;        /* Ng, unit, from the first three vertices */
    real_t offset;        /* Ng . v0 */
    vec3_t box_min, box_max;
    uint32_t first;
    uint32_t normals;     /* first normal, or POLY_NO_NORMALS for 'p' */
    uint16_t count;
    uint16_t material;
    uint8_t drop_axis;
    uint8_t convex;       /* inside test by edge sides (watertight) */
} polygon_t;

/* A primitive of any kind: kind in the top 8 bits, table index below. */
typedef uint32_t prim_ref_t;
#define PRIM_REF(kind, index) ((prim_ref_t)(kind) << 24 | (prim_ref_t)(index))
#define PRIM_KIND(ref) ((ref) >> 24)
#define PRIM_INDEX(ref) ((ref) & 0xFFFFFFu)
enum prim_kind { PRIM_SPHERE, PRIM_CONE, PRIM_POLYGON, PRIM_OBJECT };
#define PRIM_NONE UINT32_MAX

/* ---- solids beyond NFF (src/solid.c) --------------------------------- */

/* An affine map kept with its inverse: world = m p + t, p = im (world - t).
 * Built from translate/rotate/scale steps, so the inverse is exact to the
 * same rounding as the map (no matrix inversion). */
typedef struct {
    real_t m[3][3], t[3];
    real_t im[3][3];
} xform_t;

#define XFORM_NONE 0xFFFFu

enum shape_kind { SHAPE_QUADRIC, SHAPE_TORUS, SHAPE_BOX };

/* A solid in its own (object) space, placed by an optional transform:
 *   quadric  a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j <= 0
 *            inside the clip box [lo, hi] (coefficients in q[0..9])
 *   torus    around the z axis: major radius q[0], minor radius q[1]
 *   box      [lo, hi]
 * `bound` is the radius of a sphere about the object-space origin that
 * holds the solid (early rejection, root bracketing). */
typedef struct {
    real_t q[10];
    vec3_t lo, hi;
    real_t bound;
    uint16_t xform;
    uint16_t material;
    uint8_t kind;
} shape_t;

enum csg_op { CSG_UNION, CSG_INTERSECTION, CSG_DIFFERENCE };

/* A binary CSG node; a child is a shape (index) or another node
 * (index | CSG_NODE_BIT). */
#define CSG_NODE_BIT 0x8000u
typedef struct {
    uint16_t a, b;
    uint8_t op;
} csg_node_t;

/* What the BVH sees: one shape, or the root of a CSG tree. */
typedef struct {
    vec3_t box_min, box_max;  /* world bounds */
    uint16_t root;            /* shape index, or node index | CSG_NODE_BIT */
} object_t;

/* BVH node, depth-first order: an interior node's left child follows it,
 * `index` is its right child; a leaf's primitives are
 * bvh_prims[index .. index + count). Boxes are conservative: they hold
 * their primitives whatever the rounding. */
typedef struct {
    vec3_t min, max;
    uint32_t index;
    uint16_t count;   /* 0 for an interior node */
    uint8_t axis;     /* interior: the split axis (near child first) */
} bvh_node_t;

/* The NFF viewpoint; the camera basis is derived per render resolution. */
typedef struct {
    vec3_t from, at, up;
    real_t angle;         /* degrees, full field of view */
    real_wide_t tan_half; /* tan(angle / 2), set by the reader */
} view_t;

typedef struct {
    view_t view;
    colour_t background;
    uint16_t width, height;   /* the file's resolution */
    real_t light_intensity;   /* I = sqrt(n) / (2 n) */

    const material_t *materials;
    const light_t *lights;
    const sphere_t *spheres;
    const cone_t *cones;
    const polygon_t *polygons;
    const vec3_t *vertices;
    const vec3_t *normals;    /* per-vertex normals of patches (unit) */
    const bvh_node_t *bvh_nodes;
    const prim_ref_t *bvh_prims;
    const xform_t *xforms;
    const shape_t *shapes;
    const csg_node_t *csg_nodes;
    const object_t *objects;

    uint32_t n_materials, n_lights, n_spheres, n_cones, n_polygons;
    uint32_t n_vertices, n_normals;
    uint32_t n_xforms, n_shapes, n_csg_nodes, n_objects;
    uint32_t n_flat_skipped;  /* zero-area polygons dropped by the reader */
    int32_t scale_log2;       /* positions were read times 2^scale_log2 */
    uint32_t n_bvh_nodes;
} scene_t;

/* RAM tables at the configured capacities, for scenes read at run time. */
typedef struct {
    scene_t scene;
    material_t materials[RT_MAX_MATERIALS];
    light_t lights[RT_MAX_LIGHTS];
    sphere_t spheres[RT_MAX_SPHERES];
    cone_t cones[RT_MAX_CONES];
    polygon_t polygons[RT_MAX_POLYGONS];
    vec3_t vertices[RT_MAX_VERTICES];
    vec3_t normals[RT_MAX_VERTICES];
    xform_t xforms[RT_MAX_XFORMS];
    shape_t shapes[RT_MAX_SHAPES];
    csg_node_t csg_nodes[RT_MAX_CSG_NODES];
    object_t objects[RT_MAX_OBJECTS];
    bvh_node_t bvh_nodes[RT_MAX_BVH_NODES];
    prim_ref_t bvh_prims[RT_MAX_PRIMITIVES];
} scene_store_t;

#endif
