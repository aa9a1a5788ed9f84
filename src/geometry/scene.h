/*
 * scene.h - a scene as the tracer sees it: flat tables of primitives with
 * their per-primitive constants already computed.
 *
 * scene_t only points at its tables, so they can live in RAM (filled by the
 * NFF reader into a scene_store_t) or in flash (emitted as const data by the
 * scene compiler for a board). Every table and every element type is
 * declared from a list (RT_PRIM_KINDS, RT_SCENE_TABLES, FIELDS_<type>), and
 * the scene compiler writes the tables from the same lists.
 */
#ifndef SCENE_H
#define SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "prim_kinds.h"
#include "rt_config.h"
#include "numeric/vec3.h"

#define FIELDS_material_t(X) \
    X(colour_t, colour, ) /* C */ \
    X(real_t, kd, ) \
    X(real_t, ks, ) \
    X(real_t, t, ) \
    X(real_t, ior, ) \
    X(shine_t, shine, ) \
    X(uint16_t, texture, ) /* C varies over the surface: textures[texture], or TEXTURE_NONE */
typedef struct { FIELDS_material_t(RT_DECLARE_FIELD) } material_t;

/* A procedural colour, a function of the world position (texture.c):
 *   checker  a where the sum of floor(p_i / size) over the axes in `axes`
 *            (bit i: axis i) is even, b where it is odd
 *   marble   a to b across stripes along x, bent by gradient noise of
 *            strength `amount` (docs/shading-model.md gives the formula)
 * inv_size is 1 / size, size being a length in the scene's scale. */
enum texture_kind { TEXTURE_CHECKER, TEXTURE_MARBLE };
#define TEXTURE_NONE 0xFFFFu
#define FIELDS_texture_t(X) \
    X(colour_t, a, ) \
    X(colour_t, b, ) \
    X(real_t, inv_size, ) \
    X(real_t, amount, ) \
    X(uint8_t, kind, ) /* enum texture_kind */ \
    X(uint8_t, axes, )
typedef struct { FIELDS_texture_t(RT_DECLARE_FIELD) } texture_t;

/* The sky: what a ray that meets nothing sees, by its direction D:
 * zenith + (horizon - zenith) (1 - max(0, D . up))^exponent; with `on`
 * 0 it is the background colour. */
#define FIELDS_sky_t(X) \
    X(colour_t, horizon, ) \
    X(colour_t, zenith, ) \
    X(vec3_t, up, ) /* unit */ \
    X(uint8_t, up_axis, ) /* v3_axis_of(up) */ \
    X(shine_t, exponent, ) \
    X(uint8_t, on, )
typedef struct { FIELDS_sky_t(RT_DECLARE_FIELD) } sky_t;

#define FIELDS_light_t(X) \
    X(vec3_t, pos, ) \
    X(colour_t, colour, ) /* Lc, (1, 1, 1) unless given */
typedef struct { FIELDS_light_t(RT_DECLARE_FIELD) } light_t;

/* ---- solids beyond NFF (solid.h; the BVH sees them as objects) -------- */

/* A 3x3 matrix, rows[row][column]. A struct, not a bare real_t[3][3]:
 * C11 does not convert real_t (*)[3] to const real_t (*)[3], so a matrix
 * passed by pointer keeps its const-correctness only as a struct. */
#define FIELDS_mat3_t(X) \
    X(real_t, rows, [3][3])
typedef struct { FIELDS_mat3_t(RT_DECLARE_FIELD) } mat3_t;

/* An affine map kept with its inverse: world = m p + t, p = im (world - t).
 * Built from translate/rotate/scale steps, so the inverse is exact to the
 * same rounding as the map (no matrix inversion). */
#define FIELDS_xform_t(X) \
    X(mat3_t, m, ) \
    X(real_t, t, [3]) \
    X(mat3_t, im, )
typedef struct { FIELDS_xform_t(RT_DECLARE_FIELD) } xform_t;

#define XFORM_NONE 0xFFFFu

/* SHAPE_ELLIPSOID: a quadric with no cross terms and positive squares
 * that its clip box does not cut (lo, hi: its own box); SHAPE_SPHERE: one
 * that is a sphere about the object origin and that its transform keeps a
 * sphere (a rotation and a uniform scale), met in world space: its centre
 * is the transform's t and `wbound` its radius. */
enum shape_kind { SHAPE_QUADRIC, SHAPE_TORUS, SHAPE_BOX, SHAPE_ELLIPSOID, SHAPE_SPHERE };

/* A solid in its own (object) space, placed by an optional transform:
 *   quadric  a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j <= 0
 *            inside the clip box [lo, hi] (coefficients in q[0..9])
 *   torus    around the z axis: major radius q[0], minor radius q[1]
 *   box      [lo, hi]
 * `bound` is the radius of a sphere about the object-space origin that
 * holds the solid (early rejection, root bracketing); `wbound` that of a
 * world-space sphere about the transform's origin t that holds it (tested
 * before the ray is mapped into object space; unused without a transform). */
#define FIELDS_shape_t(X) \
    X(real_t, q, [10]) \
    X(vec3_t, lo, ) \
    X(vec3_t, hi, ) \
    X(real_t, bound, ) \
    X(real_t, wbound, ) \
    X(uint16_t, xform, ) \
    X(uint16_t, material, ) \
    X(uint8_t, kind, ) /* enum shape_kind */
typedef struct { FIELDS_shape_t(RT_DECLARE_FIELD) } shape_t;

enum csg_op { CSG_UNION, CSG_INTERSECTION, CSG_DIFFERENCE };

/* A binary CSG node; a child is a shape (index) or another node
 * (index | CSG_NODE_BIT). */
#define CSG_NODE_BIT 0x8000u
#define FIELDS_csg_node_t(X) \
    X(uint16_t, a, ) \
    X(uint16_t, b, ) \
    X(uint8_t, op, ) /* enum csg_op */
typedef struct { FIELDS_csg_node_t(RT_DECLARE_FIELD) } csg_node_t;

/* ---- BVH, view, the scene ----------------------------------------------- */

/* BVH node, depth-first order: an interior node's left child follows it,
 * `index` is its right child; a leaf's primitives are
 * bvh_prims[index .. index + count). Boxes are conservative: they hold
 * their primitives whatever the rounding. */
#define FIELDS_bvh_node_t(X) \
    X(vec3_t, min, ) \
    X(vec3_t, max, ) \
    X(uint32_t, index, ) \
    X(uint16_t, count, ) /* 0 for an interior node */ \
    X(uint8_t, axis, )   /* interior: the split axis (near child first) */
typedef struct { FIELDS_bvh_node_t(RT_DECLARE_FIELD) } bvh_node_t;

/* The NFF viewpoint; the camera basis is derived per render resolution. */
#define FIELDS_view_t(X) \
    X(vec3_t, from, ) \
    X(vec3_t, at, ) \
    X(vec3_t, up, ) \
    X(real_t, angle, )         /* degrees, full field of view */ \
    X(real_wide_t, tan_half, ) /* tan(angle / 2), set by the reader */
typedef struct { FIELDS_view_t(RT_DECLARE_FIELD) } view_t;

/* The scene's tables besides the primitive kinds':
 * X(element type, scene_t member, capacity). */
#define RT_SCENE_TABLES(X) \
    X(material_t, materials, RT_MAX_MATERIALS) \
    X(texture_t, textures, RT_MAX_TEXTURES) \
    X(light_t, lights, RT_MAX_LIGHTS) \
    X(vec3_t, vertices, RT_MAX_VERTICES)  /* the polygons' vertex pool */ \
    X(vec3_t, normals, RT_MAX_VERTICES)   /* per-vertex normals of patches (unit) */ \
    X(xform_t, xforms, RT_MAX_XFORMS) \
    X(shape_t, shapes, RT_MAX_SHAPES) \
    X(csg_node_t, csg_nodes, RT_MAX_CSG_NODES) \
    X(bvh_node_t, bvh_nodes, RT_MAX_BVH_NODES) \
    X(prim_ref_t, bvh_prims, RT_MAX_PRIMITIVES)

/* The scene's settings, besides its tables. */
#define FIELDS_scene_t(X) \
    X(view_t, view, ) \
    X(colour_t, background, ) \
    X(sky_t, sky, )                /* replaces the background when on */ \
    X(uint16_t, width, )           /* the file's resolution */ \
    X(uint16_t, height, ) \
    X(real_t, light_intensity, )   /* I = sqrt(n) / (2 n) */ \
    X(uint32_t, n_flat_skipped, )  /* zero-area polygons dropped by the reader */ \
    X(int32_t, scale_log2, )       /* positions were read times 2^scale_log2 */

/* Each table is a pointer and a length: `const T *name; uint32_t n_name;`. */
#define RT_DECLARE_TABLE(type, table, cap) const type *table; uint32_t n_##table;
#define RT_DECLARE_PRIM_TABLE(type, table, cap, KIND, name, use) RT_DECLARE_TABLE(type, table, cap)

struct scene {
    FIELDS_scene_t(RT_DECLARE_FIELD)
    RT_PRIM_KINDS(RT_DECLARE_PRIM_TABLE)
    RT_SCENE_TABLES(RT_DECLARE_TABLE)
};

/* RAM tables at the configured capacities, for scenes read at run time. */
#define RT_STORE_TABLE(type, table, cap) type table[cap];
#define RT_STORE_PRIM_TABLE(type, table, cap, KIND, name, use) RT_STORE_TABLE(type, table, cap)
typedef struct {
    scene_t scene;
    RT_PRIM_KINDS(RT_STORE_PRIM_TABLE)
    RT_SCENE_TABLES(RT_STORE_TABLE)
} scene_store_t;

/* An empty scene on the store's tables. */
static inline void scene_store_reset(scene_store_t *st)
{
    st->scene = (scene_t){ 0 };
#define RT_BIND_TABLE(type, table, cap) st->scene.table = st->table;
#define RT_BIND_PRIM_TABLE(type, table, cap, KIND, name, use) RT_BIND_TABLE(type, table, cap)
    RT_PRIM_KINDS(RT_BIND_PRIM_TABLE)
    RT_SCENE_TABLES(RT_BIND_TABLE)
#undef RT_BIND_TABLE
#undef RT_BIND_PRIM_TABLE
}

/* Primitives of every kind together. */
static inline uint32_t scene_prim_count(const scene_t *sc)
{
#define RT_PRIM_COUNT(type, table, cap, KIND, name, use) + sc->n_##table
    return 0 RT_PRIM_KINDS(RT_PRIM_COUNT);
#undef RT_PRIM_COUNT
}

#endif
