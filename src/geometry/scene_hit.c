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

#include <stddef.h>

#include "prims.h"

/* Parallel axes and margins: RT_SLAB_PARALLEL, RT_SLAB_MARGIN (tolerance.h).
 * A box is entered when the largest near distance (slab_ray_t, scratch.h)
 * is not above the smallest far one, which stays conservative: rounding
 * down moves both by less than a unit. */

#define NODE_MIN(a) (offsetof(bvh_node_t, min) + (a) * sizeof(real_t))
#define NODE_MAX(a) (offsetof(bvh_node_t, max) + (a) * sizeof(real_t))
_Static_assert(NODE_MIN(2) + sizeof(real_t) == offsetof(bvh_node_t, min) + sizeof(vec3_t) &&
                   NODE_MAX(2) + sizeof(real_t) == offsetof(bvh_node_t, max) + sizeof(vec3_t) &&
                   NODE_MAX(2) < 256,
               "a node's bounds are two runs of three real_t, at byte offsets below 256");

static void slab_init(slab_ray_t *s, const ray_t *r, real_t tmin, real_t tmax)
{
    const real_t d[3] = { r->dir.x, r->dir.y, r->dir.z };
    unsigned parallel = 0;
    s->o[0] = r->origin.x;
    s->o[1] = r->origin.y;
    s->o[2] = r->origin.z;
#pragma GCC unroll 3
    for (unsigned a = 0; a < 3; a++) {
        s->dir_abs[a] = r_abs(d[a]);
        parallel |= (unsigned)(s->dir_abs[a] < RT_SLAB_PARALLEL) << a;
        s->near[a] = (uint8_t)(d[a] < 0 ? NODE_MAX(a) : NODE_MIN(a));
        s->far[a] = (uint8_t)(d[a] < 0 ? NODE_MIN(a) : NODE_MAX(a));
    }
    s->parallel = (uint8_t)parallel;
    s->shift = r_slab_inverse(d, parallel, s->inv);
    s->lo = r_slab_from_t_down(tmin, s->shift);
    s->tmax = tmax;
}

/* The bound of node n at byte offset off (slab_ray_t.near, .far). */
static RT_INLINE real_t node_bound(const bvh_node_t *n, unsigned off)
{
    real_t v;
    __builtin_memcpy(&v, (const unsigned char *)n + off, sizeof v);
    return v;
}

/* One axis: narrows [*lo, *hi] to where the ray is inside the slab;
 * false once the interval is empty. */
static RT_INLINE bool slab_axis(const slab_ray_t *s, const bvh_node_t *n, unsigned a, real_slab_t *lo,
                                real_slab_t *hi, bool any_parallel)
{
    if (any_parallel && (s->parallel & (1u << a))) {
        /* no reciprocal: the ray drifts at most |d| tmax across the slab */
        real_t drift = r_mul(s->dir_abs[a], s->tmax) + RT_SLAB_MARGIN, o = s->o[a];
        return o >= r_add_sat(v3_axis(&n->min, a), -drift) && o <= r_add_sat(v3_axis(&n->max, a), drift);
    }
    real_slab_t t0 = r_slab_dist(node_bound(n, s->near[a]), s->o[a], s->inv[a]);
    real_slab_t t1 = r_slab_dist(node_bound(n, s->far[a]), s->o[a], s->inv[a]);
    *lo = t0 > *lo ? t0 : *lo;
    *hi = t1 < *hi ? t1 : *hi;
    return *lo <= *hi;
}

/* Where the ray enters the node's box within [s->lo, hi] (hi from
 * r_slab_from_t_up), or a negative value when it does not (entries are at
 * least tmin > 0). */
static RT_INLINE real_slab_t slab_entry_with(const bvh_node_t *n, const slab_ray_t *s, real_slab_t hi,
                                             bool any_parallel)
{
    real_slab_t lo = s->lo;
    if (!slab_axis(s, n, 0, &lo, &hi, any_parallel) || !slab_axis(s, n, 1, &lo, &hi, any_parallel) ||
        !slab_axis(s, n, 2, &lo, &hi, any_parallel))
        return -1;
    return lo;
}

/* Rays with a near-parallel axis (rare) take their own copy, so the
 * others test no axis for it. */
RT_NOINLINE RT_COLD static real_slab_t slab_entry_parallel(const bvh_node_t *n, const slab_ray_t *s,
                                                           real_slab_t hi)
{
    return slab_entry_with(n, s, hi, true);
}

/* The box test: inline at each call or one shared copy (RT_HOT). */
RT_HOT static real_slab_t slab_entry(const bvh_node_t *n, const slab_ray_t *s, real_slab_t hi)
{
    if (s->parallel)
        return slab_entry_parallel(n, s, hi);
    return slab_entry_with(n, s, hi, false);
}

/* A primitive against the ray; the primitive the ray leaves is skipped
 * unless the ray goes into it (ray.h). */
RT_HOT static bool hit_prim(const scene_t *sc, prim_ref_t ref, const ray_t *r, real_t tmin, real_t *t,
                            ray_scratch_t *w, hit_t *h)
{
    bool self = ref == r->from;
    if (self && !r->from_far)
        return false; /* leaving its outside, or a plane: cannot meet it again */
    return prim_hit(sc, ref, r, tmin, t, self, w, h);
}

/* Whether traversal can start: the tree is not empty and the ray meets
 * the root's box (a ray from a surface in it does). A one-leaf tree needs
 * no box test, nor the slab set-up. */
static RT_INLINE bool enter_root(const scene_t *sc, slab_ray_t *s, const ray_t *r, real_t tmin, real_t tmax)
{
    if (sc->n_bvh_nodes == 0)
        return false;
    if (sc->bvh_nodes[0].count) {
        s->shift = 0; /* read, never used: nothing is pushed */
        return true;
    }
    slab_init(s, r, tmin, tmax);
    return r->leaf != RT_NO_LEAF || slab_entry(&sc->bvh_nodes[0], s, r_slab_from_t_up(tmax, s->shift)) >= 0;
}

/* The children of interior node n (at index node) in the order to visit
 * them: on the way down to the ray's leaf `path`, the child towards it
 * comes first, entered untested at s->lo (the other must be tested). */
static RT_INLINE void children(const bvh_node_t *n, uint32_t node, uint32_t path, uint32_t *first,
                               uint32_t *second)
{
    bool right_first = path != RT_NO_LEAF && path >= n->index;
    *first = right_first ? n->index : node + 1;
    *second = right_first ? node + 1 : n->index;
}

/* Every primitive in table order, each kind's test called directly (no
 * reference or dispatch per primitive): the reference the traversal is
 * tested against, and the whole search when the tree is one leaf (a few
 * primitives: it holds them all in table order, and needs no box test).
 * Ties go to the earlier, as in the traversal. The kinds tested inline
 * read the ray from `r`, a local copy that never leaves the function, so
 * it lives in registers and hit writes cannot alias it; the others get
 * the caller's `ray`. An eye ray starts on no primitive: it skips none. */
#define FLAT_TEST(KIND, table, name, use, t, hit, eye) \
    prim_ref_t ref = PRIM_REF(PRIM_##KIND, i); \
    bool self = !(eye) && ref == r->from; \
    if (self && !r->from_far) { \
        skipped++; /* leaving its outside, or a plane */ \
        continue; \
    } \
    if (FLAT_HIT(name, &sc->table[i])(sc, &sc->table[i], FLAT_RAY(&sc->table[i]), tmin, t, self, w, hit))
/* a kind's test: the sphere's and the plane's inline (a call cost a
 * quarter of a test that misses), the others through their interface */
#define FLAT_HIT(name, e) \
    _Generic((e), const sphere_t *: sphere_prim_hit_inline, default: FLAT_HIT_NOT_SPHERE(name, e))
#define FLAT_HIT_NOT_SPHERE(name, e) _Generic((e), const plane_t *: plane_prim_hit_inline, default: name##_prim_hit)
#define FLAT_RAY(e) _Generic((e), const sphere_t *: r, default: _Generic((e), const plane_t *: r, default: ray))

/* Whether the scene is searched flat: one leaf (or none), where the
 * build has the flat search; always, where it has no BVH traversal. */
static RT_INLINE bool searched_flat(const scene_t *sc)
{
    return RT_USE_FLAT && (!RT_USE_BVH || sc->n_bvh_nodes <= 1);
}

static RT_INLINE bool never_eye_miss(const void *p, uint32_t i, const ray_scratch_t *w, uint32_t row, int32_t k)
{
    (void)p, (void)i, (void)w, (void)row, (void)k;
    return false;
}
static RT_INLINE bool never_shadow_miss(const void *p, const ray_t *r, uint32_t i, uint32_t l,
                                        const ray_scratch_t *w)
{
    (void)p, (void)r, (void)i, (void)l, (void)w;
    return false;
}

#if RT_USE_FLAT
/* A shadow ray from P along d (unit) to the light L that meets sphere
 * (C, r) at X leaves L towards X along -d, inside the cone from L that
 * holds the sphere: d . unit(L - C) >= cos a, sin a = r / |L - C|. The
 * cut is taken CONE_MARGIN lower, more than the error of d, of a test's
 * hit point seen from at least a unit away, and of these products; a
 * light less than a unit off a sphere gets no cut (-2: every ray is
 * tested). Those errors are ulps of the format, so the margin is 1024
 * of them: 2^-10 in Q.20, 2^-6 in Q.16, 2^-2 in Q.12 (where the cones
 * cull less).
 *
 * In the fixed build the test is three 32-bit products of Q.K components,
 * K = CONE_BITS, cheap also without a long multiply: K = 14 keeps each
 * product below 2^28 + 2^15 and their sum in range (|d_a| <= 1 + 2^-18);
 * a format with fewer fraction bits uses its own. */
#define CONE_MARGIN R_ULPS(1024)
#define CONE_BITS (FX_FRAC_BITS < 14 ? FX_FRAC_BITS : 14)
#define CONE_SHIFT (FX_FRAC_BITS - CONE_BITS)
RT_COLD static void light_setup(const scene_t *sc, ray_scratch_t *w)
{
    w->shadow_light = 0;
    for (uint32_t l = 0; l < RT_FLAT_SHADOW_LIGHTS; l++) {
        for (uint32_t i = 0; i < w->n_eye_spheres; i++) {
            light_sphere_t *ls = &w->light_spheres[l][i];
            const sphere_t *s = &sc->spheres[i];
            *ls = (light_sphere_t){ 0 };
#if RT_BACKEND_FIXED
            ls->cos_cut = INT32_MIN;
#else
            ls->cos_cut = -2 * R_ONE;
#endif
            if (l >= sc->n_lights)
                continue;
            vec3_t lc = v3_sub(sc->lights[l].pos, s->centre);
            real_t d = v3_length(lc);
            if (d - s->radius < R_ONE)
                continue;
            real_t sin_a = r_div(s->radius, d);
            vec3_t u = v3_unit(lc);
            real_t cut = r_sqrt(R_ONE - r_mul(sin_a, sin_a)) - CONE_MARGIN;
#if RT_BACKEND_FIXED
            /* d's components floored to Q.K (an error below 2^-K each),
             * the axis rounded to it (2^-(K+1)): the dot product is within
             * 1.5 sqrt3 2^-K < 2^(2-K) of d . u, so the cut goes 2^(2-K)
             * lower; cut is Q.F, cos_cut Q.2K */
            const int32_t axis[3] = { u.x, u.y, u.z };
            for (int a = 0; a < 3; a++)
                ls->toward[a] = (axis[a] + ((1 << CONE_SHIFT) >> 1)) >> CONE_SHIFT;
            ls->cos_cut = cut * ((int32_t)1 << (2 * CONE_BITS - FX_FRAC_BITS)) - ((int32_t)1 << (CONE_BITS + 2));
#else
            ls->toward = u;
            ls->cos_cut = cut;
#endif
        }
    }
}

void scene_eye_setup(const scene_t *sc, const camera_t *cam, ray_scratch_t *w)
{
    w->eye_ray = false;
    w->n_eye_spheres = 0;
    for (unsigned k = 0; k < RT_STATS_MAX_KINDS; k++)
        w->flat_tests[k] = 0;
    w->flat = searched_flat(sc);
    if (!w->flat)
        return;
    uint32_t i = 0;
    for (; i < sc->n_spheres && i < RT_FLAT_EYE_SPHERES; i++)
        camera_sphere_box(cam, sc->spheres[i].centre, sc->spheres[i].radius, w->eye_spheres[i].box);
    w->n_eye_spheres = i;
    w->row_m = INT32_MIN; /* (m is 2j - cy: never that) */
    light_setup(sc, w);
}

/* The spheres whose boxes hold the eye ray's row m (bit i), made when
 * m changes: along a row, each eye ray then tests only k. */
RT_NOINLINE static uint32_t eye_row_setup(ray_scratch_t *w)
{
    scene_fold_stats(w); /* a row's tests fit the 32-bit counts */
    uint32_t mask = 0;
    for (uint32_t i = 0; i < w->n_eye_spheres; i++) {
        const int32_t *box = w->eye_spheres[i].box;
        mask |= (uint32_t)(w->eye_m >= box[2] && w->eye_m <= box[3]) << i;
    }
    w->row_m = w->eye_m;
    w->row_mask = mask;
    return mask;
}

static RT_INLINE uint32_t eye_row(ray_scratch_t *w)
{
    return w->eye_m == w->row_m ? w->row_mask : eye_row_setup(w);
}

/* Whether an eye ray's sample lies outside sphere i's box (every sphere
 * below RT_FLAT_EYE_SPHERES has one, set up for the frame): row is
 * eye_row's mask. */
static RT_INLINE bool sphere_eye_miss(const sphere_t *s, uint32_t i, const ray_scratch_t *w, uint32_t row,
                                      int32_t k)
{
    (void)s;
    if (i >= RT_FLAT_EYE_SPHERES)
        return false;
    if (!(row >> i & 1))
        return true;
    const int32_t *box = w->eye_spheres[i].box;
    return k < box[0] || k > box[1];
}
_Static_assert(RT_FLAT_EYE_SPHERES <= 32, "a row's spheres are the bits of a word");
#define FLAT_EYE_MISS(e) _Generic((e), const sphere_t *: sphere_eye_miss, default: never_eye_miss)

/* Whether a shadow ray to light l (below RT_FLAT_SHADOW_LIGHTS) lies
 * outside sphere i's cone (light_setup). */
static RT_INLINE bool sphere_shadow_miss(const sphere_t *s, const ray_t *r, uint32_t i, uint32_t l,
                                         const ray_scratch_t *w)
{
    (void)s;
    if (i >= RT_FLAT_EYE_SPHERES)
        return false; /* (below it, each has its cone, set up for the frame) */
    const light_sphere_t *ls = &w->light_spheres[l][i];
#if RT_BACKEND_FIXED /* 32-bit products, Q.K x Q.K (light_setup) */
    return (r->dir.x >> CONE_SHIFT) * ls->toward[0] + (r->dir.y >> CONE_SHIFT) * ls->toward[1] +
               (r->dir.z >> CONE_SHIFT) * ls->toward[2] <
           ls->cos_cut;
#else
    return v3_dot_in_range(r->dir, ls->toward) < ls->cos_cut;
#endif
}
#define FLAT_SHADOW_MISS(e) _Generic((e), const sphere_t *: sphere_shadow_miss, default: never_shadow_miss)
#else
void scene_eye_setup(const scene_t *sc, const camera_t *cam, ray_scratch_t *w)
{
    (void)sc, (void)cam, (void)w; /* (flat_tests: only the tests' brute force counts there) */
}
#define FLAT_EYE_MISS(e) never_eye_miss /* the flat search is the tests' brute force only */
#define FLAT_SHADOW_MISS(e) never_shadow_miss
#endif
/* the tests of a kind's loop, counted once (32-bit counters that
 * scene_fold_stats adds to the 64-bit ones) */
#define FLAT_COUNT(KIND, table, use) \
    if ((use) && sc->n_##table) \
        w->flat_tests[PRIM_##KIND] += sc->n_##table - skipped;

void scene_fold_stats(ray_scratch_t *w)
{
    for (unsigned k = 0; k < PRIM_KIND_COUNT; k++) {
        w->stats.prim_tests[k] += w->flat_tests[k];
        w->flat_tests[k] = 0;
    }
}

/* eye: an eye ray (w->eye_ray), culled by the eye boxes; a constant in
 * each of the two copies below, so neither tests it per primitive. */
static RT_INLINE bool flat_nearest_with(const scene_t *sc, const ray_t *ray, real_t tmin, hit_t *h,
                                        ray_scratch_t *w, bool eye)
{
    const ray_t copy = *ray, *r = &copy;
    bool found = false;
    uint32_t row = 0;
    int32_t k = 0;
#if RT_USE_FLAT
    if (eye) {
        row = eye_row(w);
        k = w->eye_k;
    }
#endif
#define RT_FLAT_NEAREST(type, table, cap, KIND, name, use) \
    { \
        uint32_t skipped = 0; \
        for (uint32_t i = 0; (use) && i < sc->n_##table; i++) { \
            if (eye && FLAT_EYE_MISS(&sc->table[i])(&sc->table[i], i, w, row, k)) \
                continue; /* counted as tested */ \
            FLAT_TEST(KIND, table, name, use, &h->t, h, eye) { \
                h->kind = PRIM_##KIND; \
                h->index = i; \
                h->leaf = RT_PRIM_UNBOUNDED(PRIM_##KIND) ? RT_NO_LEAF : 0; \
                found = true; \
            } \
        } \
        FLAT_COUNT(KIND, table, use) \
    }
    RT_PRIM_KINDS(RT_FLAT_NEAREST)
#undef RT_FLAT_NEAREST
    return found;
}

RT_NOINLINE static bool flat_nearest(const scene_t *sc, const ray_t *ray, real_t tmin, hit_t *h, ray_scratch_t *w)
{
    return flat_nearest_with(sc, ray, tmin, h, w, false);
}

#if RT_USE_FLAT
RT_NOINLINE static bool flat_nearest_eye(const scene_t *sc, const ray_t *ray, real_t tmin, hit_t *h,
                                         ray_scratch_t *w)
{
    return flat_nearest_with(sc, ray, tmin, h, w, true);
}
#endif

/* light: the light the shadow ray goes to, culled by the light cones
 * (light_setup), or UINT32_MAX; cull: light is one of those set
 * up, a constant in each of the two copies below. */
static RT_INLINE bool flat_occluded_with(const scene_t *sc, const ray_t *ray, real_t tmin, real_t tmax,
                                         prim_ref_t *last_blocker, ray_scratch_t *w, uint32_t light, bool cull)
{
    const ray_t copy = *ray, *r = &copy; /* as in flat_nearest_with */
    (void)light;
#define RT_FLAT_ANY(type, table, cap, KIND, name, use) \
    { \
        uint32_t skipped = 0; \
        for (uint32_t i = 0; (use) && i < sc->n_##table; i++) { \
            real_t t = tmax; \
            if (cull && FLAT_SHADOW_MISS(&sc->table[i])(&sc->table[i], r, i, light, w)) \
                continue; /* counted as tested */ \
            FLAT_TEST(KIND, table, name, use, &t, 0, false) { \
                w->flat_tests[PRIM_##KIND] += i + 1 - skipped; \
                *last_blocker = ref; \
                return true; \
            } \
        } \
        FLAT_COUNT(KIND, table, use) \
    }
    RT_PRIM_KINDS(RT_FLAT_ANY)
#undef RT_FLAT_ANY
    *last_blocker = PRIM_NONE;
    return false;
}

RT_NOINLINE static bool flat_occluded(const scene_t *sc, const ray_t *ray, real_t tmin, real_t tmax,
                                    prim_ref_t *last_blocker, ray_scratch_t *w)
{
    return flat_occluded_with(sc, ray, tmin, tmax, last_blocker, w, UINT32_MAX, false);
}

#if RT_USE_FLAT
RT_NOINLINE static bool flat_occluded_cone(const scene_t *sc, const ray_t *ray, real_t tmin, real_t tmax,
                                           prim_ref_t *last_blocker, ray_scratch_t *w, uint32_t light)
{
    return flat_occluded_with(sc, ray, tmin, tmax, last_blocker, w, light, true);
}
#endif

/* The unbounded kinds (planes), every one of them: before the BVH, so
 * their nearest hit limits the traversal. Their kinds come last in the
 * table order, so a tie with a bounded primitive goes to that one. */
static RT_INLINE bool unbounded_nearest(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h,
                                        ray_scratch_t *w)
{
    bool found = false;
#if RT_USE_PLANES
    for (uint32_t i = 0; i < sc->n_planes; i++) {
        if (hit_prim(sc, PRIM_REF(PRIM_PLANE, i), r, tmin, &h->t, w, h)) {
            h->kind = PRIM_PLANE;
            h->index = i;
            h->leaf = RT_NO_LEAF;
            found = true;
        }
    }
#else
    (void)sc, (void)r, (void)tmin, (void)h, (void)w;
#endif
    return found;
}

static RT_INLINE bool unbounded_occluded(const scene_t *sc, const ray_t *r, real_t tmin, real_t tmax,
                                         prim_ref_t *last_blocker, ray_scratch_t *w)
{
#if RT_USE_PLANES
    for (uint32_t i = 0; i < sc->n_planes; i++) {
        real_t t = tmax;
        if (hit_prim(sc, PRIM_REF(PRIM_PLANE, i), r, tmin, &t, w, 0)) {
            *last_blocker = PRIM_REF(PRIM_PLANE, i);
            return true;
        }
    }
#else
    (void)sc, (void)r, (void)tmin, (void)tmax, (void)last_blocker, (void)w;
#endif
    return false;
}

bool scene_nearest(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, ray_scratch_t *w)
{
    const bvh_node_t *nodes = sc->bvh_nodes;
    slab_ray_t s;
    if (searched_flat(sc)) {
#if RT_USE_FLAT
        if (w->eye_ray) /* (set by trace_ray, whose caller set the frame up) */
            return flat_nearest_eye(sc, r, tmin, h, w);
#endif
        return flat_nearest(sc, r, tmin, h, w);
    }
    bool found = unbounded_nearest(sc, r, tmin, h, w);
    if (!enter_root(sc, &s, r, tmin, h->t))
        return found;
    bvh_stack_t *stack = w->nearest_stack; /* neither traversal re-enters itself */
    unsigned sp = 0;
    uint32_t node = 0, visited = 0; /* counted here, added once */
    uint32_t path = r->leaf;          /* while on the way down to it */
    for (;;) {
        const bvh_node_t *n = &nodes[node];
        visited++;
        if (n->count) {
            for (uint32_t k = n->index; k < n->index + n->count; k++) {
                /* Ties go to the lowest reference, as in table order: a
                 * lower one may also take a hit at exactly the best t. */
                prim_ref_t ref = sc->bvh_prims[k];
                bool lower = !found || ref < PRIM_REF(h->kind, h->index);
                real_t t = lower ? r_next_up(h->t) : h->t;
                if (hit_prim(sc, ref, r, tmin, &t, w, h)) { /* t < h->t, or lower at h->t */
                    h->t = s.tmax = t;
                    h->kind = (uint8_t)PRIM_KIND(ref);
                    h->index = PRIM_INDEX(ref);
                    h->leaf = node;
                    found = true;
                }
            }
        } else {
            uint32_t a, b;
            children(n, node, path, &a, &b);
            real_slab_t hi = r_slab_from_t_up(h->t, s.shift);
            real_slab_t ea = path != RT_NO_LEAF ? s.lo : slab_entry(&nodes[a], &s, hi);
            real_slab_t eb = slab_entry(&nodes[b], &s, hi);
            if (ea >= 0 && eb >= 0) {
                if (eb < ea) { /* nearer child first, the other waits */
                    uint32_t tn = a;
                    a = b;
                    b = tn;
                    eb = ea;
                }
                stack[sp].node = b;
                stack[sp].entry = eb;
                sp++;
            }
            if (ea >= 0 || eb >= 0) {
                node = ea >= 0 ? a : b;
                continue;
            }
        }
        /* next waiting node that can still beat the best hit */
        path = RT_NO_LEAF;
        real_slab_t best = r_slab_from_t_up(h->t, s.shift);
        do {
            if (sp == 0) {
                w->stats.bvh_nodes_visited += visited;
                return found;
            }
            sp--;
        } while (stack[sp].entry > best);
        node = stack[sp].node;
    }
}

RT_FRAME bool scene_occluded(const scene_t *sc, const ray_t *r, real_t tmin, real_t tmax,
                             prim_ref_t *last_blocker, ray_scratch_t *w)
{
    const bvh_node_t *nodes = sc->bvh_nodes;
    slab_ray_t *s = &w->any_slab;
    real_t t = tmax;
#if RT_USE_FLAT
    uint32_t light = w->shadow_light - 1u; /* UINT32_MAX: none */
    w->shadow_light = 0; /* for this ray only */
#endif
    if (*last_blocker != PRIM_NONE && hit_prim(sc, *last_blocker, r, tmin, &t, w, 0))
        return true;
    if (searched_flat(sc)) {
#if RT_USE_FLAT
        if (light < RT_FLAT_SHADOW_LIGHTS) /* (as w->eye_ray) */
            return flat_occluded_cone(sc, r, tmin, tmax, last_blocker, w, light);
#endif
        return flat_occluded(sc, r, tmin, tmax, last_blocker, w);
    }
    if (unbounded_occluded(sc, r, tmin, tmax, last_blocker, w))
        return true;
    if (!enter_root(sc, s, r, tmin, tmax))
        return false;
    const real_slab_t hi = r_slab_from_t_up(tmax, s->shift);
    uint32_t *stack = w->any_stack;
    unsigned sp = 0;
    uint32_t node = 0, visited = 0; /* counted here, added once */
    uint32_t path = r->leaf;          /* as in scene_nearest */
    bool blocked = false;
    for (;;) {
        const bvh_node_t *n = &nodes[node];
        visited++;
        if (n->count) {
            for (uint32_t k = n->index; k < n->index + n->count && !blocked; k++) {
                t = tmax;
                blocked = hit_prim(sc, sc->bvh_prims[k], r, tmin, &t, w, 0); /* any blocker will do */
                if (blocked)
                    *last_blocker = sc->bvh_prims[k];
            }
            if (blocked)
                break;
        } else {
            uint32_t a, b;
            children(n, node, path, &a, &b);
            bool ha = path != RT_NO_LEAF || slab_entry(&nodes[a], s, hi) >= 0;
            bool hb = slab_entry(&nodes[b], s, hi) >= 0;
            if (ha && hb)
                stack[sp++] = b;
            if (ha || hb) {
                node = ha ? a : b;
                continue;
            }
        }
        if (sp == 0)
            break;
        node = stack[--sp];
        path = RT_NO_LEAF;
    }
    w->stats.bvh_nodes_visited += visited;
    if (!blocked)
        *last_blocker = PRIM_NONE; /* lit: trying it on the next ray would likely be wasted */
    return blocked;
}

bool scene_nearest_brute(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, ray_scratch_t *w)
{
    return flat_nearest(sc, r, tmin, h, w);
}
