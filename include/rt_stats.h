/*
 * rt_stats.h - the render's counters: one list, read by `rt --stats` (text
 * or JSON), the firmware's report and the benchmarks, with the same keys
 * everywhere.
 */
#ifndef RT_STATS_H
#define RT_STATS_H

#include <stdint.h>

/* X(key, what it counts). Besides these, one "<kind>_tests" counter per
 * primitive kind (prim_kinds.h): intersection tests of that kind. */
#define RT_STATS_COUNTERS(X) \
    X(eye_rays, "eye rays traced") \
    X(eye_hits, "eye rays that hit something") \
    X(reflect_rays, "reflection rays traced") \
    X(refract_rays, "refraction rays traced") \
    X(shadow_rays, "shadow rays, including lights a patch hides from itself") \
    X(bvh_nodes_visited, "BVH nodes visited") \
    X(aa_splits, "squares adaptive anti-aliasing split in four")

/* Room for the per-kind counters: at least the number of kinds
 * (prim_kinds.h checks), so this header needs none of the core's. */
#define RT_STATS_MAX_KINDS 8

#define RT_STATS_DECLARE(key, what) uint64_t key;
typedef struct {
    RT_STATS_COUNTERS(RT_STATS_DECLARE)
    uint64_t prim_tests[RT_STATS_MAX_KINDS]; /* by enum prim_kind */
} rt_stats_t;
#undef RT_STATS_DECLARE

/* Calls visit(ctx, key, value) for every counter, in list order, then
 * the per-kind tests. */
typedef void rt_stats_visit_fn(void *ctx, const char *key, uint64_t value);
void rt_stats_each(const rt_stats_t *st, rt_stats_visit_fn *visit, void *ctx);

/* sum += part, counter by counter (workers' counts into one). */
void rt_stats_add(rt_stats_t *sum, const rt_stats_t *part);

/* Intersection tests of every kind together. */
uint64_t rt_stats_tests(const rt_stats_t *st);

#endif
