/* trace.h - Whitted shading of one ray (docs/shading-model.md). */
#ifndef TRACE_H
#define TRACE_H

#include "geometry/geometry.h"
#include "geometry/scratch.h"

/* A material's Kd C and ambient term I Kd C, kept per ray depth: a hit
 * is mostly on the material the same depth of the previous pixel met. */
typedef struct {
    const material_t *material; /* whose terms these are; 0: none yet */
    colour_t base;              /* and the colour C they were made of (a texture's at the point) */
    colour_t ambient;           /* I Kd C: the ambient term, and the diffuse one's but for N.L */
    real_t iks;                 /* I Ks: the highlight's weight */
} material_terms_t;

typedef struct {
    const scene_t *scene;
    int max_depth;      /* 1..RT_MAX_DEPTH; the eye ray has depth 1 */
    ray_scratch_t *scratch; /* the worker's counters and traversal scratch */
    bool spd_rules;     /* SPD rule 8: reflect off transmitting surfaces too */
    real_t min_weight;  /* adaptive depth: skip child rays whose share of
                         * the pixel falls below this; 0 = off */
    prim_ref_t *last_blocker; /* per light: what blocked its last shadow
                               * ray, tried first (PRIM_NONE at the start) */
    material_terms_t *terms;  /* per depth (material 0 at the start) */
} tracer_t;

/* The scene the tracer reads: its record's, or, in firmware built for one
 * scene (SPECIALISE=1), that scene's tables as the constant RT_CONST_SCENE,
 * so that the compiler sees them where they are read and folds them. */
#ifdef RT_CONST_SCENE
extern const scene_t RT_CONST_SCENE;
#define TRACER_SCENE(tr) ((void)(tr), &RT_CONST_SCENE)
#else
#define TRACER_SCENE(tr) ((tr)->scene)
#endif

/* Colour seen along `ray`; `weight` is its share of the pixel (1 for an
 * eye ray, times Ks or T at each bounce). */
colour_t trace_ray(const tracer_t *tr, const ray_t *ray, int depth, real_t weight);

#endif
