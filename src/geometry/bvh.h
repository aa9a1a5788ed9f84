/*
 * bvh.h - the bounding volume hierarchy over all primitives of a scene.
 *
 * Built once (by the scene compiler for a board, at load time on the
 * host) into the statically sized arrays of a scene_store_t; the renderer
 * only traverses it (scene_hit.c).
 */
#ifndef BVH_H
#define BVH_H

#include "scene.h"

typedef struct {
    uint32_t nodes, leaves, max_depth, max_leaf_size;
    uint32_t primitives;
    /* expected node visits and primitive tests per ray, by the surface
     * area heuristic, in 1/1000 */
    uint32_t sah_nodes_milli, sah_tests_milli;
} bvh_stats_t;

/* Conservative box of one primitive. */
void prim_box(const scene_t *sc, prim_ref_t ref, vec3_t *min, vec3_t *max);

/* Builds the tree over store->scene with a binned surface area heuristic
 * and points the scene at it. NULL, or why it could not be built. */
const char *bvh_build(scene_store_t *store);

void bvh_tree_stats(const scene_t *sc, bvh_stats_t *out);

#endif
