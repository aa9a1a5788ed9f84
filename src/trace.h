/* trace.h - Whitted shading of one ray (../shared/docs/shading-model.md). */
#ifndef TRACE_H
#define TRACE_H

#include "geometry.h"
#include "stats.h"

typedef struct {
    const scene_t *scene;
    int max_depth;      /* 1..RT_MAX_DEPTH; the eye ray has depth 1 */
    rt_stats_t *stats;
} tracer_t;

/* Secondary rays start this far off the surface, on the side they leave
 * by, so rounding cannot make them hit their own surface. */
#define RT_SURFACE_OFFSET R_RATIO(1, 2048)
/* Nearest accepted hit distance. */
#define RT_T_MIN R_RATIO(1, 65536)
/* Farthest hit distance (the fixed range). */
#define RT_T_FAR R_RATIO(32767, 1)

colour_t trace_ray(const tracer_t *tr, const ray_t *ray, int depth);

#endif
