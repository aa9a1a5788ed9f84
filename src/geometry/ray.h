/*
 * ray.h - what the code of every primitive kind sees: rays, hits, the
 * surface at a hit, and a reference to a primitive of any kind.
 *
 * The kinds themselves are listed once, in prim_kinds.h.
 */
#ifndef RAY_H
#define RAY_H

#include <stdbool.h>
#include <stdint.h>

#include "numeric/tolerance.h"
#include "numeric/vec3.h"

/* The scene (scene.h). Kind headers only pass it on, so an incomplete
 * type is enough for them. */
typedef struct scene scene_t;
/* A worker's scratch (scratch.h), passed through the kinds to CSG. */
struct ray_scratch;

/* A primitive of any kind: kind in the top 8 bits, table index below. */
typedef uint32_t prim_ref_t;
#define PRIM_REF(kind, index) ((prim_ref_t)(kind) << 24 | (prim_ref_t)(index))
#define PRIM_KIND(ref) ((ref) >> 24)
#define PRIM_INDEX(ref) ((ref) & 0xFFFFFFu)
#define PRIM_NONE UINT32_MAX

/* A secondary ray starts on the surface of primitive `from` (PRIM_NONE for
 * eye rays and rays leaving solids). Leaving that primitive's outside, or
 * any plane, it cannot meet it again and skips it; going into a sphere or
 * cone (from_far) it meets it only at the far root. This replaces a
 * surface offset (tolerance.h). */
/* `leaf` is the BVH leaf where the surface it starts on was found
 * (RT_NO_LEAF for eye rays): the boxes on the way down to it hold the
 * origin, so traversal walks that way without testing them (scene_hit.c).
 * A hint only: any value gives the same hits. */
#define RT_NO_LEAF UINT32_MAX
typedef struct {
    vec3_t origin, dir;
    prim_ref_t from;
    bool from_far;
    uint32_t leaf;
#if RT_RAY_CONES
    /* The ray's cone (docs/shading-model.md, "Filtered textures"): its
     * signed width at the origin and its spread, the width's growth per
     * unit of distance (negative: converging). */
    real_t cone_width, cone_spread;
#endif
} ray_t;
#if RT_RAY_CONES
/* The fixed build holds every width and spread a cone takes within
 * +-2^10 (widths in scaled units: twice the far cube, where every
 * texture is long since its mean), inside its range; float and double
 * leave them as they are (r_mul_bounded). */
#define CONE_LIMIT (R_ONE * 1024)
#endif

static inline vec3_t ray_at(const ray_t *r, real_t t) { return v3_madd(r->origin, t, r->dir); }

/* The nearest hit found so far. */
typedef struct {
    real_t t;
    uint8_t kind;     /* enum prim_kind */
    uint32_t index;   /* into the kind's table */
    uint32_t leaf;    /* the BVH leaf it was found in (scene_nearest) */
    /* objects: the shape, face and flip of the boundary hit */
    uint16_t shape;
    uint8_t face;
    bool flip;
} hit_t;

/* How a ray leaving a surface avoids meeting it again at its start. */
enum prim_leave {
    LEAVE_SKIP_SELF,  /* a plane: never met again, the ray skips it */
    LEAVE_FAR_ROOT,   /* a sphere or cone: skipped going out, only the far
                       * root going in */
    LEAVE_OFFSET,     /* anything else (solids): only the origin offset */
};

/* What shading needs of the surface at a hit. */
typedef struct {
    vec3_t ng;         /* geometric normal, outward, unit */
    vec3_t n;          /* shading normal: a patch's interpolated one, else ng */
    real_t offset;     /* origin offset of rays leaving it (tolerance.h) */
    uint16_t material;
    uint8_t leave;     /* enum prim_leave */
    bool smooth;       /* n and ng may disagree (patches) */
} prim_surface_t;

/* One field of a table's element type, for the field lists of the kind
 * headers and scene.h: X(type, name, array dimensions or nothing). The
 * scene compiler writes tables from the same lists. */
#define RT_DECLARE_FIELD(type, name, dims) type name dims;

#endif
