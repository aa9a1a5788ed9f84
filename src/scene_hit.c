/*
 * scene_hit.c - a ray against the whole scene.
 *
 * BVH traversal: nearest-first with a bounded stack for eye, reflection
 * and refraction rays; any-hit with an early exit for shadow rays. The
 * slab tests are conservative: every box is padded by RT_BOX_SLACK, more
 * than the error of the reciprocal over any ray (tolerance.h), so a box is
 * never missed because of rounding (it may be entered needlessly, which
 * costs time, not correctness). The brute-force versions are the
 * reference the BVH is tested against.
 */
#include "scene_hit.h"

#include "prims.h"

/* Parallel axes and margins: RT_SLAB_PARALLEL, RT_SLAB_MARGIN (tolerance.h). */

typedef struct {
    vec3_t origin;
    real_t inv[3], dir_abs[3];
    bool parallel[3];
    bool negative[3];   /* the ray enters a slab at its max side */
} slab_ray_t;

static void slab_init(slab_ray_t *s, const ray_t *r)
{
    const real_t d[3] = { r->dir.x, r->dir.y, r->dir.z };
    s->origin = r->origin;
    for (int a = 0; a < 3; a++) {
        s->dir_abs[a] = r_abs(d[a]);
        s->parallel[a] = s->dir_abs[a] < RT_SLAB_PARALLEL;
        s->negative[a] = d[a] < 0;
        s->inv[a] = s->parallel[a] ? 0 : r_recip(d[a]);
    }
}

/* One axis of the slab test, in the wide type: t = (bound - o) / d as an
 * exact product with the reciprocal, so no rounding or saturation here. */
static RT_INLINE bool slab_axis(const slab_ray_t *s, int a, real_t o, real_t bmin, real_t bmax,
                                 real_t tmax, real_wide_t *lo, real_wide_t *hi)
{
    if (s->parallel[a]) {
        real_t drift = r_mul(s->dir_abs[a], tmax) + RT_SLAB_MARGIN;
        return o >= r_add_sat(bmin, -drift) && o <= r_add_sat(bmax, drift);
    }
    real_t near = s->negative[a] ? bmax : bmin, far = s->negative[a] ? bmin : bmax;
    real_wide_t t0 = r_wmul_diff(near, o, s->inv[a]), t1 = r_wmul_diff(far, o, s->inv[a]);
    *lo = t0 > *lo ? t0 : *lo;
    *hi = t1 < *hi ? t1 : *hi;
    return true;
}

/* Whether the ray meets the node's box within [tmin, tmax]; *entry is
 * where it enters (for nearest-first ordering). */
static bool slab_test(const bvh_node_t *n, const slab_ray_t *s, real_t tmin, real_t tmax, real_t *entry)
{
    real_wide_t lo = r_to_wide(-R_BIG), hi = r_to_wide(R_BIG);
    if (!slab_axis(s, 0, s->origin.x, n->min.x, n->max.x, tmax, &lo, &hi) ||
        !slab_axis(s, 1, s->origin.y, n->min.y, n->max.y, tmax, &lo, &hi) ||
        !slab_axis(s, 2, s->origin.z, n->min.z, n->max.z, tmax, &lo, &hi))
        return false;
    if (lo > hi || hi < r_to_wide(tmin) || lo > r_to_wide(tmax))
        return false;
    *entry = lo > r_to_wide(tmin) ? r_from_wide(lo) : tmin;
    return true;
}

/* A primitive against the ray; the primitive the ray leaves is skipped
 * unless the ray goes into it (ray.h). */
static bool hit_prim(const scene_t *sc, prim_ref_t ref, const ray_t *r, real_t tmin, real_t *t,
                     rt_stats_t *st, hit_t *h)
{
    bool self = ref == r->from;
    if (self && !r->from_far)
        return false; /* leaving its outside, or a plane: cannot meet it again */
    return prim_hit(sc, ref, r, tmin, t, self, st, h);
}

typedef struct {
    uint32_t node;
    real_t entry;
} bvh_stack_t;

/* Traversal stacks in static storage, not on the call stack: neither
 * function re-enters itself, and the tracer runs one ray at a time (one
 * render at a time per program), so this keeps the stack budget. */
static bvh_stack_t nearest_stack[RT_BVH_MAX_DEPTH];
static uint32_t any_stack[RT_BVH_MAX_DEPTH];

/* Whether traversal can start: the tree is not empty and the ray meets
 * the root's box. A one-leaf tree needs no box test, nor the slab set-up. */
static RT_INLINE bool enter_root(const scene_t *sc, slab_ray_t *s, const ray_t *r, real_t tmin, real_t tmax)
{
    real_t entry;
    if (sc->n_bvh_nodes == 0)
        return false;
    if (sc->bvh_nodes[0].count)
        return true;
    slab_init(s, r);
    return slab_test(&sc->bvh_nodes[0], s, tmin, tmax, &entry);
}

bool scene_nearest(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, rt_stats_t *st)
{
    const bvh_node_t *nodes = sc->bvh_nodes;
    slab_ray_t s;
    real_t ea, eb;
    if (!enter_root(sc, &s, r, tmin, h->t))
        return false;
    bvh_stack_t *stack = nearest_stack;
    unsigned sp = 0;
    uint32_t node = 0;
    bool found = false;
    for (;;) {
        const bvh_node_t *n = &nodes[node];
        st->bvh_nodes_visited++;
        if (n->count) {
            for (uint32_t k = n->index; k < n->index + n->count; k++) {
                /* Ties go to the lowest reference, as in table order: a
                 * lower one may also take a hit at exactly the best t. */
                prim_ref_t ref = sc->bvh_prims[k];
                bool lower = !found || ref < PRIM_REF(h->kind, h->index);
                real_t t = lower ? r_next_up(h->t) : h->t;
                if (hit_prim(sc, ref, r, tmin, &t, st, h) && (t < h->t || lower)) {
                    h->t = t;
                    h->kind = (uint8_t)PRIM_KIND(ref);
                    h->index = PRIM_INDEX(ref);
                    found = true;
                }
            }
        } else {
            uint32_t a = node + 1, b = n->index;
            bool ha = slab_test(&nodes[a], &s, tmin, h->t, &ea);
            bool hb = slab_test(&nodes[b], &s, tmin, h->t, &eb);
            if (ha && hb) {
                if (eb < ea) { /* nearer child first, the other waits */
                    uint32_t tn = a;
                    a = b;
                    b = tn;
                    eb = ea;
                }
                stack[sp].node = b;
                stack[sp].entry = eb;
                sp++;
                node = a;
                continue;
            }
            if (ha || hb) {
                node = ha ? a : b;
                continue;
            }
        }
        /* next waiting node that can still beat the best hit */
        do {
            if (sp == 0)
                return found;
            sp--;
        } while (stack[sp].entry > h->t);
        node = stack[sp].node;
    }
}

bool scene_occluded(const scene_t *sc, const ray_t *r, real_t tmin, real_t tmax, rt_stats_t *st)
{
    const bvh_node_t *nodes = sc->bvh_nodes;
    static slab_ray_t s; /* static like the stacks above */
    real_t entry;
    if (!enter_root(sc, &s, r, tmin, tmax))
        return false;
    uint32_t *stack = any_stack;
    unsigned sp = 0;
    uint32_t node = 0;
    for (;;) {
        const bvh_node_t *n = &nodes[node];
        st->bvh_nodes_visited++;
        if (n->count) {
            for (uint32_t k = n->index; k < n->index + n->count; k++) {
                real_t t = tmax;
                if (hit_prim(sc, sc->bvh_prims[k], r, tmin, &t, st, 0))
                    return true; /* any blocker will do */
            }
        } else {
            uint32_t a = node + 1, b = n->index;
            bool ha = slab_test(&nodes[a], &s, tmin, tmax, &entry);
            bool hb = slab_test(&nodes[b], &s, tmin, tmax, &entry);
            if (ha && hb)
                stack[sp++] = b;
            if (ha || hb) {
                node = ha ? a : b;
                continue;
            }
        }
        if (sp == 0)
            return false;
        node = stack[--sp];
    }
}

bool scene_nearest_brute(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, rt_stats_t *st)
{
    bool found = false;
#define RT_BRUTE_KIND(type, table, cap, KIND, name, use) \
    for (uint32_t i = 0; i < sc->n_##table; i++) { \
        if (hit_prim(sc, PRIM_REF(PRIM_##KIND, i), r, tmin, &h->t, st, h)) { \
            h->kind = PRIM_##KIND; \
            h->index = i; \
            found = true; \
        } \
    }
    RT_PRIM_KINDS(RT_BRUTE_KIND)
#undef RT_BRUTE_KIND
    return found;
}
