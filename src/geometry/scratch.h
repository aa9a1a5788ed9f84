/*
 * scratch.h - what following rays writes, besides the tracer's caches:
 * the counters, the BVH traversal's stacks and the CSG span lists. One
 * per worker (render.c: RT_MAX_WORKERS), so renders running at once on
 * two cores or threads never write the same byte; static storage, so the
 * call stack stays small.
 */
#ifndef SCRATCH_H
#define SCRATCH_H

#include "rt_stats.h"
#include "shape.h"

/* A ray set up for slab tests (scene_hit.c). Distances along the ray are
 * real_slab_t (real.h): in the fixed build a 32-bit format chosen per
 * ray, rounded down. */
typedef struct {
    real_t o[3];
    real_t inv[3];         /* 1/d in r_slab_dist's scale; 0 on parallel axes */
    real_t dir_abs[3];
    uint8_t near[3], far[3]; /* byte offsets in bvh_node_t of the bound the
                              * ray enters slab a by, and leaves it by */
    uint8_t parallel;      /* bit a: |d_a| < RT_SLAB_PARALLEL */
    int shift;             /* for r_slab_from_t_* */
    real_slab_t lo;        /* tmin */
    real_t tmax;           /* the current far end (parallel axes' drift) */
} slab_ray_t;

/* A node waiting on the nearest-hit traversal's stack. */
typedef struct {
    uint32_t node;
    real_slab_t entry;
} bvh_stack_t;

/* Per sphere of a flat scene (scene_hit.c): the box of samples whose
 * eye rays may meet it, made once a frame, so an eye ray outside the box
 * skips the sphere with four compares. */
typedef struct {
    int32_t box[4]; /* the eye samples that may meet it (camera_sphere_box) */
} eye_sphere_t;

/* Per sphere of a flat scene and light (scene_hit.c): the cone from the
 * light that holds the sphere, made once a frame, so a shadow ray to the
 * light outside it skips the sphere with one dot product. */
typedef struct {
#if RT_BACKEND_FIXED
    /* in 32-bit products (scene_hit.c): cheap also without a long multiply */
    int32_t toward[3]; /* unit, from the centre to the light, in Q.K (scene_hit.c) */
    int32_t cos_cut;   /* in Q.2K */
#else
    vec3_t toward;  /* unit, from the centre to the light */
    real_t cos_cut; /* a shadow ray's d . toward below it misses (less a margin) */
#endif
} light_sphere_t;

typedef struct ray_scratch {
    rt_stats_t stats;                          /* added to the caller's after each step */
    uint32_t flat_tests[RT_STATS_MAX_KINDS];   /* the flat search's tests, into stats a line at
                                                * a time (scene_fold_stats): a 32-bit add */
    bvh_stack_t nearest_stack[RT_BVH_MAX_DEPTH]; /* scene_nearest */
    uint32_t any_stack[RT_BVH_MAX_DEPTH];      /* scene_occluded */
    slab_ray_t any_slab;                       /* scene_occluded's ray: off the stack under the shading */
#if RT_USE_FLAT
    bool flat;                                 /* the scene is searched flat (scene_eye_setup) */
    /* eye_ray and shadow_light are set by trace_ray only, whose caller
     * (render.c) has set the frame up (frame_setup.h: scene_eye_setup) */
    bool eye_ray;                              /* the ray searched now is an eye ray (trace.c) */
    int32_t eye_k, eye_m;                      /* its sample: 2i - cx, 2j - cy (frame.h) */
    int32_t row_m;                             /* row_mask is for this m */
    uint32_t row_mask;                         /* bit i: sphere i's box holds row m */
    uint32_t n_eye_spheres;                    /* set up: min(spheres, RT_FLAT_EYE_SPHERES) */
    eye_sphere_t eye_spheres[RT_FLAT_EYE_SPHERES];
    uint8_t shadow_light;                      /* 1 + the light the next scene_occluded's ray goes
                                                * to (trace.c), or 0 (as zeroed); read once */
    light_sphere_t light_spheres[RT_FLAT_SHADOW_LIGHTS][RT_FLAT_EYE_SPHERES];
#endif
#if RT_USE_OBJECTS
    spans_t csg_spans[RT_CSG_MAX_DEPTH + 1][2]; /* both children, per CSG level */
    spans_t object_spans;                      /* an object's whole span list */
#endif
} ray_scratch_t;

#endif
