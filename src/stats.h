/* stats.h - ray and intersection-test counters (rt --stats). */
#ifndef STATS_H
#define STATS_H

#include <stdint.h>

typedef struct {
    uint64_t eye_rays, eye_hits;
    uint64_t reflect_rays, refract_rays, shadow_rays;
    uint64_t tests_sphere, tests_cone, tests_polygon, tests_object;
    uint64_t bvh_nodes;     /* BVH nodes visited */
} rt_stats_t;

#endif
