/* trace.h - Whitted shading of one ray (docs/shading-model.md). */
#ifndef TRACE_H
#define TRACE_H

#include "geometry.h"
#include "rt_stats.h"

typedef struct {
    const scene_t *scene;
    int max_depth;      /* 1..RT_MAX_DEPTH; the eye ray has depth 1 */
    rt_stats_t *stats;
    bool spd_rules;     /* SPD rule 8: reflect off transmitting surfaces too */
    real_t min_weight;  /* adaptive depth: skip child rays whose share of
                         * the pixel falls below this; 0 = off */
    prim_ref_t *last_blocker; /* per light: what blocked its last shadow
                               * ray, tried first (PRIM_NONE at the start) */
} tracer_t;

/* Colour seen along `ray`; `weight` is its share of the pixel (1 for an
 * eye ray, times Ks or T at each bounce). */
colour_t trace_ray(const tracer_t *tr, const ray_t *ray, int depth, real_t weight);

#endif
