/*
 * bvh_build.c - binned surface-area-heuristic BVH builder (host side).
 *
 * Top down: at each node the primitives' centroids are dropped into
 * BVH_BINS bins along each axis and the split with the lowest
 * area(left) * count(left) + area(right) * count(right) wins. Recursion
 * stops at RT_BVH_LEAF_SIZE primitives, when no split beats a leaf, or
 * at RT_BVH_MAX_DEPTH (which bounds the traversal stack).
 */
#include "bvh.h"

#include "prims.h"

#define BVH_BINS 12
/* Cost of visiting a node (one or two box tests) in units of one
 * primitive test. Measured on the Cortex-M3 (make run, 64x64): 1 gives
 * 0.7% to 9% fewer instructions per pixel than 2 on balls-2, rings-1 and
 * teapot-1, and 3 or 4 more. It is what makes small groups end as leaves. */
#define BVH_TRAVERSAL_COST 1
/* What a tree costs a ray once, over one leaf: the slab set-up (the
 * reciprocals) and the root's box test, about 2 sphere tests on the
 * Cortex-M3 (155 + 40 instructions against 88), so the 4 spheres of
 * scenes/bench/card.nff make one leaf. Counted only when every
 * primitive is a sphere: next to any other kind's test it is small. */
#define BVH_ROOT_COST 2

/* Rounding slack added around every primitive's box (tolerance.h). */
#define BOX_SLACK RT_BOX_SLACK

typedef struct {
    vec3_t min, max;
} box_t;

static box_t box_empty(void)
{
    const real_t big = R_BIG;
    box_t b = { { big, big, big }, { -big, -big, -big } };
    return b;
}

static void box_grow(box_t *b, vec3_t lo, vec3_t hi)
{
    b->min = v3(r_min(b->min.x, lo.x), r_min(b->min.y, lo.y), r_min(b->min.z, lo.z));
    b->max = v3(r_max(b->max.x, hi.x), r_max(b->max.y, hi.y), r_max(b->max.z, hi.z));
}

/* Half the surface area (exact in the wide type); 0 for an empty box. */
static real_wide_t box_half_area(const box_t *b)
{
    if (b->max.x < b->min.x)
        return 0;
    vec3_t d = v3_sub(b->max, b->min);
    return r_wmul(d.x, d.y) + r_wmul(d.y, d.z) + r_wmul(d.z, d.x);
}

/* area * count for the SAH; the fixed build drops the area's extra F
 * fraction bits first so the product stays inside 64 bits. */
static real_wide_t sah_cost(real_wide_t half_area, uint32_t count)
{
#if RT_BACKEND_FIXED
    return (half_area >> FX_FRAC_BITS) * (int64_t)count;
#else
    return half_area * (real_wide_t)count;
#endif
}

void prim_box(const scene_t *sc, prim_ref_t ref, vec3_t *min, vec3_t *max)
{
    prim_bounds(sc, ref, BOX_SLACK, min, max);
}

typedef struct {
    scene_store_t *st;
    uint32_t n_nodes;
    uint32_t root_cost; /* BVH_ROOT_COST, or 0 */
    const char *error;
} builder_t;

static real_t centroid(const scene_t *sc, prim_ref_t ref, unsigned axis)
{
    vec3_t lo, hi;
    prim_box(sc, ref, &lo, &hi);
    return v3_axis(&lo, axis) / 2 + v3_axis(&hi, axis) / 2;
}

static uint32_t build(builder_t *b, uint32_t first, uint32_t count, uint32_t depth)
{
    const scene_t *sc = &b->st->scene;
    prim_ref_t *prims = b->st->bvh_prims;
    uint32_t node = b->n_nodes++;
    bvh_node_t *n = &b->st->bvh_nodes[node];

    box_t box = box_empty(), cbox = box_empty();
    for (uint32_t i = first; i < first + count; i++) {
        vec3_t lo, hi;
        prim_box(sc, prims[i], &lo, &hi);
        box_grow(&box, lo, hi);
        vec3_t c = v3(lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2);
        box_grow(&cbox, c, c);
    }
    n->min = box.min;
    n->max = box.max;
    n->axis = 0;

    /* best binned split over the three axes */
    int best_axis = -1, best_split = 0;
    real_wide_t best_cost = 0;
    real_t best_lo = 0, best_scale = 0;
    for (unsigned axis = 0; axis < 3 && count > RT_BVH_LEAF_SIZE; axis++) {
        real_t lo = v3_axis(&cbox.min, axis), extent = v3_axis(&cbox.max, axis) - lo;
        /* centroids this close together do not split usefully (and the
         * bin scale would not fit the fixed range) */
        if (extent < R_RATIO(BVH_BINS, 1024))
            continue;
        real_t scale = r_div(r_from_int(BVH_BINS), extent);
        box_t bins[BVH_BINS];
        uint32_t counts[BVH_BINS] = { 0 };
        for (unsigned k = 0; k < BVH_BINS; k++)
            bins[k] = box_empty();
        for (uint32_t i = first; i < first + count; i++) {
            int32_t k = r_floor_int(r_mul(centroid(sc, prims[i], axis) - lo, scale));
            k = k < 0 ? 0 : k >= BVH_BINS ? BVH_BINS - 1 : k;
            vec3_t plo, phi;
            prim_box(sc, prims[i], &plo, &phi);
            box_grow(&bins[k], plo, phi);
            counts[k]++;
        }
        /* cost of splitting after bin s: sweep from the right, then the left */
        real_wide_t right_cost[BVH_BINS];
        box_t acc = box_empty();
        uint32_t acc_n = 0;
        for (int k = BVH_BINS - 1; k > 0; k--) {
            box_grow(&acc, bins[k].min, bins[k].max);
            acc_n += counts[k];
            right_cost[k - 1] = sah_cost(box_half_area(&acc), acc_n);
        }
        acc = box_empty();
        acc_n = 0;
        for (int s = 0; s < BVH_BINS - 1; s++) {
            box_grow(&acc, bins[s].min, bins[s].max);
            acc_n += counts[s];
            if (acc_n == 0 || acc_n == count)
                continue;
            real_wide_t cost = sah_cost(box_half_area(&acc), acc_n) + right_cost[s];
            if (best_axis < 0 || cost < best_cost) {
                best_axis = (int)axis;
                best_split = s;
                best_cost = cost;
                best_lo = lo;
                best_scale = scale;
            }
        }
    }
    /* a leaf when small, too deep, or when no split beats testing all
     * (SAH: traversal + area-weighted tests of the children) */
    real_wide_t area = box_half_area(&box);
    bool leaf = best_axis < 0 || depth + 1 >= RT_BVH_MAX_DEPTH ||
                (depth == 0 && count < RT_BVH_MIN_PRIMITIVES) ||
                (count <= 16 && sah_cost(area, BVH_TRAVERSAL_COST + (depth == 0 ? b->root_cost : 0)) + best_cost >=
                                    sah_cost(area, count));
    if (leaf) {
        if (count > 0xFFFF) {
            b->error = "BVH leaf over 65535 primitives (raise RT_BVH_MAX_DEPTH)";
            count = 0xFFFF;
        }
        n->index = first;
        n->count = (uint16_t)count;
        return node;
    }
    /* partition in place: bins <= best_split go left */
    uint32_t i = first, j = first + count;
    while (i < j) {
        int32_t k = r_floor_int(r_mul(centroid(sc, prims[i], (unsigned)best_axis) - best_lo, best_scale));
        if (k <= best_split) {
            i++;
        } else {
            prim_ref_t tmp = prims[i];
            prims[i] = prims[--j];
            prims[j] = tmp;
        }
    }
    uint32_t left_n = i - first;
    if (left_n == 0 || left_n == count)
        left_n = count / 2; /* rounding put everything on one side */
    n->axis = (uint8_t)best_axis;
    n->count = 0;
    build(b, first, left_n, depth + 1); /* left child is node + 1 */
    uint32_t right = build(b, first + left_n, count - left_n, depth + 1);
    b->st->bvh_nodes[node].index = right;
    return node;
}

const char *bvh_build(scene_store_t *st)
{
    scene_t *sc = &st->scene;
    uint32_t n = 0;
#define RT_LIST_KIND(type, table, cap, KIND, name, use) \
    for (uint32_t i = 0; i < sc->n_##table && !RT_PRIM_UNBOUNDED(PRIM_##KIND); i++) \
        st->bvh_prims[n++] = PRIM_REF(PRIM_##KIND, i);
    RT_PRIM_KINDS(RT_LIST_KIND)
#undef RT_LIST_KIND
    builder_t b = { st, 0, sc->n_spheres == n ? BVH_ROOT_COST : 0, 0 };
    if (n > 0) {
        build(&b, 0, n, 0);
        /* the box test subtracts origins from bounds unsaturated (real.h):
         * the root's box, around all others, within the far extent */
        const real_t far = r_from_int((int32_t)1 << RT_FAR_EXTENT_LOG2);
        const bvh_node_t *root = &st->bvh_nodes[0];
        if (r_min(root->min.x, r_min(root->min.y, root->min.z)) < -far ||
            r_max(root->max.x, r_max(root->max.y, root->max.z)) > far)
            b.error = "scene geometry reaches beyond the far extent (RT_FAR_EXTENT_LOG2)";
    }
    sc->bvh_nodes = st->bvh_nodes;
    sc->bvh_prims = st->bvh_prims;
    sc->n_bvh_nodes = b.n_nodes;
    sc->n_bvh_prims = n;
    return b.error;
}

static void walk(const scene_t *sc, uint32_t node, uint32_t depth, real_wide_t root_area,
                 bvh_stats_t *out, real_t *visits, real_t *tests)
{
    const bvh_node_t *n = &sc->bvh_nodes[node];
    box_t box = { n->min, n->max };
    real_wide_t area = box_half_area(&box);
    out->nodes++;
    out->max_depth = depth > out->max_depth ? depth : out->max_depth;
    /* a random ray through the root meets this node with odds area/root */
    *visits += r_wdiv(area, root_area);
    if (n->count) {
        out->leaves++;
        out->max_leaf_size = n->count > out->max_leaf_size ? n->count : out->max_leaf_size;
        *tests += r_wdiv(area, root_area) * (int32_t)n->count;
        return;
    }
    walk(sc, node + 1, depth + 1, root_area, out, visits, tests);
    walk(sc, n->index, depth + 1, root_area, out, visits, tests);
}

static uint32_t to_milli(real_t v)
{
    int32_t whole = r_floor_int(v);
    return (uint32_t)(whole * 1000 + r_floor_int(r_mul(v - r_from_int(whole), r_from_int(1000))));
}

void bvh_tree_stats(const scene_t *sc, bvh_stats_t *out)
{
    *out = (bvh_stats_t){ 0 };
    out->primitives = scene_prim_count(sc);
    if (sc->n_bvh_nodes == 0)
        return;
    box_t root = { sc->bvh_nodes[0].min, sc->bvh_nodes[0].max };
    real_wide_t root_area = box_half_area(&root);
    real_t visits = 0, tests = 0;
    if (root_area <= 0)
        return;
    walk(sc, 0, 1, root_area, out, &visits, &tests);
    out->sah_nodes_milli = to_milli(visits);
    out->sah_tests_milli = to_milli(tests);
}
