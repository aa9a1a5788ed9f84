/* trace.c - the Whitted tracer: a ray tree of depth <= RT_MAX_DEPTH, walked without recursion. */
#include "trace.h"

#include "geometry/prims.h"
#include "geometry/scene_hit.h"
#include "shine.h"
#include "texture.h"

typedef struct {
    vec3_t point;
    vec3_t n;        /* shading normal, facing the incoming ray */
#if RT_USE_PATCHES
    vec3_t n_out;    /* geometric normal, facing the incoming ray (N_OUT) */
#endif
    bool entering;   /* D . Ng < 0 */
    bool smooth;     /* a patch: n and n_out may disagree */
    prim_ref_t ref;  /* the primitive, PRIM_NONE for a solid */
    bool far_root;   /* a ray going through meets it again only at its far root */
    uint32_t leaf;   /* its BVH leaf (ray_t) */
    real_t offset;   /* origin offset of rays leaving it (tolerance.h) */
    const material_t *m;
#if RT_RAY_CONES
    real_t cone_width; /* the incoming ray's cone here (signed) */
#endif
} surface_t;
/* The geometric normal: n itself but on a patch (one vector less in the
 * surface record where the build has no patches). */
#if RT_USE_PATCHES
#define N_OUT(s) ((s)->n_out)
#else
#define N_OUT(s) ((s)->n)
#endif

#if RT_RAY_CONES
/* A cone's widths and spreads: products and sums within CONE_LIMIT */
static inline real_t cone_mul(real_t a, real_t b) { return r_mul_bounded(a, b, CONE_LIMIT); }
static inline real_t cone_add(real_t a, real_t b) { return r_add_bounded(a, b, CONE_LIMIT); }
#endif

static inline void surface_at(const scene_t *sc, const hit_t *h, const ray_t *ray, surface_t *s)
{
    prim_surface_t ps;
    s->point = v3_madd_in_range(ray->origin, h->t, ray->dir); /* a point of the scene */
    prim_surface(sc, h, s->point, &ps);
    s->ref = ps.leave == LEAVE_OFFSET ? PRIM_NONE : PRIM_REF(h->kind, h->index);
    s->far_root = ps.leave == LEAVE_FAR_ROOT;
    s->leaf = h->leaf;
    s->smooth = ps.smooth;
    s->offset = ps.offset;
    s->entering = v3_dot_negative(ray->dir, ps.ng); /* the sign alone: no rounding */
    s->n = s->entering ? ps.ng : v3_neg(ps.ng); /* n = Ng but on a patch */
#if RT_USE_PATCHES
    s->n_out = s->n;
    if (ps.smooth)
        s->n = v3_dot_in_range(ps.n, ray->dir) < 0 ? ps.n : v3_neg(ps.n);
#endif
    s->m = &sc->materials[ps.material];
#if RT_RAY_CONES
    s->cone_width = cone_add(ray->cone_width, cone_mul(ray->cone_spread, h->t));
#endif
}

#if RT_USE_SHADOWS || RT_USE_REFLECTION || RT_USE_REFRACTION /* (else no ray leaves a surface) */
/* The start of a ray leaving surface s: to the side the incoming ray came
 * from, or `through` it. Spheres and cones say whether it goes into them
 * (from_far) or away (skipped); polygons are skipped; solids, which may be
 * met again anywhere, offset the origin by their error bound instead
 * (s->offset; 0 for the others except polygons in the float build).
 * Inline but where the code has no room for the copies (RT_HOT: with
 * solids, whose firmware fills its 20 KiB budget, out of line). */
RT_HOT static void leave(const surface_t *s, bool through, ray_t *out)
{
    out->origin = s->point;
    if (s->offset != 0)
        out->origin = v3_madd_in_range(s->point, through ? -s->offset : s->offset, N_OUT(s));
    out->from = s->ref;
    out->from_far = s->far_root && through == s->entering;
    out->leaf = s->leaf;
}
#endif

/* Colour arithmetic: a few uses per light and bounce, each inline copy of
 * three rounded products ~100 bytes of flash; inline but with solids
 * (RT_HOT, as leave). */
/* c k: a weight's product (r_mul_weight) for k in [0, 1], the most a
 * scene's reflectances and intensities are */
RT_HOT static colour_t colour_scale(colour_t c, real_t k)
{
    return r_is_weight(k) ? c3_scale_weight(c, k) : v3_scale(c, k);
}
/* a + b k, the sum saturated (a weight's product inline, the rare
 * reflectance over 1 by colour_scale) */
RT_HOT static colour_t colour_add_scaled(colour_t a, colour_t b, real_t k)
{
    return c3_add(a, r_is_weight(k) ? c3_scale_weight(b, k) : colour_scale(b, k));
}

#if RT_USE_SHADOWS
/* c + I (Kd C (N.L) + Ks spec) Lc: the share of light l, whose shadow ray
 * along ldir is clear, from the terms' I Kd C and I Ks; `mirror` is the
 * incoming ray mirrored about N. */
static inline void add_light(colour_t *c, const material_terms_t *t, const surface_t *s, const light_t *l,
                             const vec3_t *ldir, real_t ndl, const vec3_t *mirror)
{
    colour_t lit = c3_scale_weight(t->ambient, ndl); /* 0 < N.L <= 1 */
    (void)s, (void)ldir, (void)mirror; /* only the specular term looks at them */
#if RT_USE_SPECULAR
    if (t->iks > 0) {
        /* Phong's R.V, R = 2 (N.L) N - L and V = -D, is L.M for the
         * mirror direction M = D - 2 (N.D) N the surface already has */
        real_t rv = v3_dot_in_range(*ldir, *mirror);
        real_t spec = r_mul_weight(t->iks, r_pow_unit(rv, s->m->shine)); /* the power is in [0, 1] */
        lit = c3_add(lit, v3(spec, spec, spec));
    }
#endif
    /* white: lit as it is (a float product by 1 is exact and cheaper
     * than the test; the fixed build's costs more) */
    if (!RT_BACKEND_FIXED || l->colour.x != R_ONE || l->colour.y != R_ONE || l->colour.z != R_ONE)
        lit = v3_mul(lit, l->colour);
    *c = c3_add(*c, lit);
}
#endif

static inline colour_t direct_light(const tracer_t *tr, const surface_t *s, const ray_t *ray, int depth,
                                    const vec3_t *mirror)
{
    const scene_t *sc = TRACER_SCENE(tr);
    const material_t *m = s->m;
    real_t I = sc->light_intensity;
    (void)ray; /* only the lights' shares and a filtered texture look at it */
    (void)mirror; /* only the lights' highlights, in the loop a build with shadows has */
    material_terms_t *t = &tr->terms[depth - 1];
    /* Kd C and I Kd C are kept per depth until the material or, under a
     * texture, C changes: a checker's tile mostly repeats ray after ray. */
    bool same = t->material == m;
#if RT_USE_TEXTURES
    colour_t base = m->colour;
    if (m->texture != TEXTURE_NONE) {
#if RT_RAY_CONES
        const footprint_t fp = { ray->dir, s->n, s->cone_width };
        base = texture_colour(&sc->textures[m->texture], s->point, &fp);
#else
        base = texture_colour(&sc->textures[m->texture], s->point, 0);
#endif
        same = same && base.x == t->base.x && base.y == t->base.y && base.z == t->base.z;
    }
#else
    const colour_t base = m->colour;
#endif
    if (!same) {
        t->material = m;
        t->base = base;
        t->ambient = colour_scale(base, r_mul(I, m->kd));
        t->iks = r_mul_in_range(I, m->ks);
    }
    colour_t c = t->ambient;
#if RT_USE_SHADOWS
    ray_t shadow;
    leave(s, false, &shadow);
    for (uint32_t i = 0; i < sc->n_lights; i++) {
        const light_t *l = &sc->lights[i];
        real_t dist;
#if R_UNIT_LEN_FREE
        vec3_t ldir = v3_unit_len(v3_sub(l->pos, s->point), &dist);
#else
        vec3_t ldir = v3_unit(v3_sub(l->pos, s->point));
#endif
        real_t ndl = v3_cos(s->n, ldir); /* only weighs the light */
        if (ndl <= 0)
            continue;
        tr->scratch->stats.shadow_rays++;
#if RT_USE_PATCHES
        /* the patch policy of docs/shading-model.md: a light below the
         * geometric surface is blocked by the patch itself (at t = 0) */
        if (s->smooth && v3_dot_in_range(N_OUT(s), ldir) <= 0)
            continue;
#endif
        shadow.dir = ldir;
        /* the light's distance: in the fixed build |L - P| from ldir's
         * making; else, or where the ray starts off the surface (solids),
         * (L - O) . ldir, within a few ulps of |L - O| */
        if (!R_UNIT_LEN_FREE || s->offset != 0)
            dist = v3_dot(v3_sub(l->pos, shadow.origin), ldir);
#if RT_USE_FLAT
        tr->scratch->shadow_light = (uint8_t)(i + 1); /* it goes to light i (scene_eye_setup) */
#endif
        if (!scene_occluded(sc, &shadow, RT_T_MIN, dist, &tr->last_blocker[i], tr->scratch))
            add_light(&c, t, s, l, &shadow.dir, ndl, mirror);
    }
#endif
    return c;
}

/* D mirrored about N, made once for the highlights and the reflection
 * ray. D and N are unit (a sphere's N within 2^-15: sphere_normal), so M
 * is within 2^-12 of unit before v3_renorm. */
static inline vec3_t mirror_dir(vec3_t d, vec3_t n)
{
    return v3_renorm(v3_madd_in_range(d, -2 * v3_dot_in_range(d, n), n));
}

#if RT_USE_REFLECTION || RT_USE_REFRACTION /* (the child rays) */
/* Whether the child ray of a ray of this weight, whose colour counts
 * `factor` times, is worth tracing. */
static inline bool worth_tracing(const tracer_t *tr, real_t weight, real_t factor)
{
    return tr->min_weight == 0 || r_mul(weight, factor) >= tr->min_weight;
}
#endif

/* That child's weight; in the fixed build only where worth_tracing reads
 * it (a saturating product costs more than the test, a float one less). */
static inline real_t child_weight(const tracer_t *tr, real_t weight, real_t factor)
{
    return RT_BACKEND_FIXED && tr->min_weight == 0 ? weight : r_mul(weight, factor);
}

/* The nearest surface along the ray, if any. */
static inline bool find_surface(const tracer_t *tr, const ray_t *ray, surface_t *s)
{
    hit_t h; /* the rest is written with a hit: no memset of it per ray (the M0's GCC calls one) */
    h.t = RT_T_FAR;
    h.leaf = RT_NO_LEAF;
    if (!scene_nearest(TRACER_SCENE(tr), ray, RT_T_MIN, &h, tr->scratch))
        return false;
    surface_at(TRACER_SCENE(tr), &h, ray, s);
    return true;
}

#if RT_USE_REFLECTION
/* The mirror ray leaving s. On a patch, a mirror direction about the
 * shading normal that would go into the geometric surface is taken about
 * the geometric normal instead (the patch policy). */
static inline void reflected(const ray_t *ray, const surface_t *s, const vec3_t *mirror, ray_t *out)
{
    (void)ray; /* only the patch policy looks at it */
    leave(s, false, out);
    out->dir = *mirror;
#if RT_USE_PATCHES
    if (s->smooth && v3_dot_in_range(out->dir, N_OUT(s)) <= 0)
        out->dir = v3_unit(v3_madd_in_range(ray->dir, -2 * v3_dot_in_range(ray->dir, N_OUT(s)), N_OUT(s)));
#endif
}
#endif

#if RT_USE_REFRACTION
/* Snell's law about the unit normal n (n . d = -cos_i < 0); false on
 * total internal reflection. */
static bool snell(vec3_t d, vec3_t n, real_t cos_i, real_t eta, vec3_t *out)
{
    real_t sin2_t = r_mul(r_mul(eta, eta), R_ONE - r_mul(cos_i, cos_i));
    if (sin2_t > R_ONE)
        return false;
    real_t cos_t = r_sqrt(R_ONE - sin2_t);
    *out = v3_unit(v3_madd(v3_scale(d, eta), r_mul(eta, cos_i) - cos_t, n));
    return true;
}

/* The refracted ray leaving s; false on total internal reflection. On a
 * patch, a direction that would stay on the incoming side of the
 * geometric surface is refracted about the geometric normal instead. */
static inline bool refracted(const ray_t *ray, const surface_t *s, real_t cos_i, ray_t *out)
{
    real_t eta = s->entering ? r_div(R_ONE, s->m->ior) : s->m->ior; /* n1 / n2 */
    if (!snell(ray->dir, s->n, cos_i, eta, &out->dir))
        return false;
#if RT_USE_PATCHES
    if (s->smooth && v3_dot_in_range(out->dir, N_OUT(s)) >= 0 &&
        !snell(ray->dir, N_OUT(s), -v3_dot_in_range(ray->dir, N_OUT(s)), eta, &out->dir))
        return false;
#endif
    leave(s, true, out);
    return true;
}
#endif

#if RT_RAY_CONES && (RT_USE_REFLECTION || RT_USE_REFRACTION)
/* The cone's bend at s: its width there times the surface's curvature,
 * 1/r on a sphere met from outside and -1/r from inside, 0 on every
 * other surface (docs/shading-model.md, "Filtered textures"). */
static real_t cone_bend(const tracer_t *tr, const surface_t *s)
{
    (void)tr, (void)s;
#if RT_USE_SPHERES
    if (s->ref != PRIM_NONE && PRIM_KIND(s->ref) == PRIM_SPHERE && s->cone_width != 0) {
        const sphere_t *sp = &TRACER_SCENE(tr)->spheres[PRIM_INDEX(s->ref)];
        real_t bend = cone_mul(s->cone_width, sp->inv_radius != 0 ? sp->inv_radius : r_recip(sp->radius));
        return s->entering ? bend : -bend;
    }
#endif
    return 0;
}
#endif

#if RT_RAY_CONES && RT_USE_REFLECTION
/* The mirror ray's cone: the same width, the spread grown by twice the
 * bend (a convex mirror spreads it). */
static void cone_reflected(const tracer_t *tr, const ray_t *ray, const surface_t *s, ray_t *out)
{
    real_t bend = cone_bend(tr, s);
    out->cone_width = s->cone_width;
    out->cone_spread = cone_add(ray->cone_spread, cone_add(bend, bend));
}
#endif

#if RT_RAY_CONES && RT_USE_REFRACTION
/* The refracted ray's cone: the same width, the spread eta times the
 * incoming one plus (eta cos_i - cos_t) times the bend (a convex surface
 * into a denser medium focuses it). */
static void cone_refracted(const tracer_t *tr, const ray_t *ray, const surface_t *s, real_t cos_i, ray_t *out)
{
    real_t eta = s->entering ? r_div(R_ONE, s->m->ior) : s->m->ior;
    real_t bend = cone_bend(tr, s);
    out->cone_width = s->cone_width;
    out->cone_spread = cone_mul(eta, ray->cone_spread);
    if (bend != 0) {
        real_t cos_t = -v3_dot_in_range(out->dir, s->n);
        out->cone_spread = cone_add(out->cone_spread, cone_mul(r_mul(eta, cos_i) - cos_t, bend));
    }
}
#endif

/* What a ray that meets nothing sees. */
static colour_t background(const scene_t *sc, const ray_t *ray)
{
#if RT_USE_SKY
    if (sc->sky.on)
        return sky_colour(&sc->sky, ray->dir);
#endif
    (void)ray;
    return sc->background;
}

/* One ray of a path, once traced: the light its hit point sends back
 * (or what it sees beyond everything), and its children's factors. The
 * path's rays form a tree of depth <= RT_MAX_DEPTH; trace_ray walks it
 * with one of these a depth, so no C recursion bounds the stack. */
typedef struct {
    colour_t c;         /* direct light, then + Ks mirror, then + T refracted */
    real_t weight;      /* the ray's share of the pixel (where worth_tracing reads it) */
#if RT_USE_REFLECTION
    real_t ks;          /* the mirror child's factor (0: traced, adds nothing: SPD rule 8) */
#endif
#if RT_USE_REFRACTION
    real_t t;           /* the refracted child's factor, 0: none to trace */
    bool refracting;    /* the child being traced is the refracted one */
    ray_t refr;         /* that child, traced after the mirror one */
#endif
} path_level_t;

/* A level's children as the walk sees them, whatever the build traces:
 * with reflection or refraction left out (rt_config.h), its factor is a
 * constant 0 and its predicates false, so the walk's branches for it
 * fold away and the level holds no fields for it. (Macros: the walk
 * compiles as if it read the fields itself.) */
#if RT_USE_REFLECTION
#define MIRROR_FACTOR(lv) ((lv)->ks)
#else
#define MIRROR_FACTOR(lv) ((void)(lv), (real_t)0)
#endif
#if RT_USE_REFRACTION
#define REFRACTION_FACTOR(lv) ((lv)->t)
#define REFRACTING(lv) ((lv)->refracting)            /* the refracted child is the one being traced */
#define REFRACTION_LEFT(lv) ((lv)->t > 0 && !(lv)->refracting) /* it is still to trace */
#define REFRACTED_CHILD(lv) (&(lv)->refr)
#define START_REFRACTION(lv) ((lv)->refracting = true)
#define NO_CHILDREN(lv) ((lv)->t = 0, (lv)->refracting = false) /* none traced or to trace yet */
#else
#define REFRACTION_FACTOR(lv) ((void)(lv), (real_t)0)
#define REFRACTING(lv) ((void)(lv), false)
#define REFRACTION_LEFT(lv) ((void)(lv), false)
#define REFRACTED_CHILD(lv) ((void)(lv), (const ray_t *)0)
#define START_REFRACTION(lv) ((void)(lv))
#define NO_CHILDREN(lv) ((void)(lv))
#endif

/* Marks the ray about to be searched as an eye ray or not, for the flat
 * search's culling (scene_eye_setup). */
#if RT_USE_FLAT
#define MARK_EYE_RAY(tr, eye) ((tr)->scratch->eye_ray = (eye))
#else
#define MARK_EYE_RAY(tr, eye) ((void)(tr), (void)(eye))
#endif

/* The profile (bench/profile.py) tells a path's rays apart by the entries
 * of trace_segment and of these counters, so they stay out of line in the
 * generic firmware and where make profile keeps the frames (RT_KEEP_FRAMES).
 * Hot: else GCC takes trace_ray's walk for a cold loop and optimises what
 * the segment calls for size (with the scene a constant, the flat
 * search's loops over the primitives stay rolled: the card +17%). With
 * the scene a constant (LTO, not profiled) the float build inlines them
 * into the walk (the card -3%); the fixed build's 64-bit products run
 * short of core registers there (+0.5%). */
#if defined(RT_KEEP_FRAMES) /* make profile of a whole-program build */
#define PATH_STEP RT_FRAME __attribute__((hot)) static
#elif defined(__GNUC__) && defined(RT_CONST_SCENE) && !RT_BACKEND_FIXED
#define PATH_STEP __attribute__((hot)) static inline
#elif defined(__GNUC__)
#define PATH_STEP RT_NOINLINE __attribute__((hot)) static
#else
#define PATH_STEP RT_NOINLINE static
#endif

PATH_STEP void count_reflect_ray(const tracer_t *tr) { tr->scratch->stats.reflect_rays++; }
PATH_STEP void count_refract_ray(const tracer_t *tr) { tr->scratch->stats.refract_rays++; }

/* Traces `ray` at `depth` into lv: its colour without its children, and
 * the children to trace: true when its mirror ray is in *mirror (the
 * refracted one, if any, in lv->refr). */
PATH_STEP bool trace_segment(const tracer_t *tr, const ray_t *ray, int depth, path_level_t *lv, ray_t *mirror)
{
    surface_t s;
    MARK_EYE_RAY(tr, depth == 1); /* it passes the eye */
    bool found = find_surface(tr, ray, &s);
    MARK_EYE_RAY(tr, false);
    NO_CHILDREN(lv);
    (void)mirror;
    if (!found) {
        lv->c = background(TRACER_SCENE(tr), ray);
        return false;
    }
    if (depth == 1)
        tr->scratch->stats.eye_hits++;

    const material_t *m = s.m;
    /* SPD rule 8: a transmitting surface also spawns its reflection ray */
    bool mirrors = m->ks > 0 || (tr->spd_rules && m->t > 0);
    (void)mirrors;
    vec3_t mdir = { 0, 0, 0 };
    if ((RT_USE_SPECULAR || RT_USE_REFLECTION) && mirrors) /* (the highlights' and the mirror ray's) */
        mdir = mirror_dir(ray->dir, s.n);
    lv->c = direct_light(tr, &s, ray, depth, &mdir);
    if (depth >= tr->max_depth)
        return false;
    real_t weight = lv->weight;
    (void)weight;
#if RT_USE_REFRACTION
    real_t cos_i = -v3_dot_in_range(ray->dir, s.n); /* > 0 */
    if (m->t > 0 && worth_tracing(tr, weight, m->t) && refracted(ray, &s, cos_i, &lv->refr)) {
#if RT_RAY_CONES
        cone_refracted(tr, ray, &s, cos_i, &lv->refr);
#endif
        lv->t = m->t;
    }
#endif
#if RT_USE_REFLECTION
    if (mirrors && worth_tracing(tr, weight, m->ks)) {
        reflected(ray, &s, &mdir, mirror);
#if RT_RAY_CONES
        cone_reflected(tr, ray, &s, mirror);
#endif
        lv->ks = m->ks;
        return true;
    }
#endif
    return false;
}

/* The ray tree walked depth first, the mirror child before the refracted
 * one, each level's colour made as docs/shading-model.md adds it up:
 * direct + Ks mirror + T refracted, in that order. */
RT_FRAME colour_t trace_ray(const tracer_t *tr, const ray_t *eye, int depth, real_t weight)
{
    path_level_t lv[RT_MAX_DEPTH];
    ray_t rays[2]; /* the ray being traced and its mirror child, in turn */
    const ray_t *ray = eye;
    unsigned next = 0;
    int k = 0; /* lv[k]: the ray at depth depth + k */
    lv[0].weight = weight;
    for (;;) {
        bool down = trace_segment(tr, ray, depth + k, &lv[k], &rays[next]);
        if (RT_USE_REFLECTION && down) { /* the mirror child next */
            count_reflect_ray(tr);
            ray = &rays[next];
            next ^= 1u;
            lv[k + 1].weight = child_weight(tr, lv[k].weight, MIRROR_FACTOR(&lv[k]));
            k++;
            continue;
        }
        /* lv[k] is done but for its refracted child: up to the next level
         * with a child left to trace */
        for (;;) {
            if (REFRACTION_LEFT(&lv[k])) {
                START_REFRACTION(&lv[k]);
                count_refract_ray(tr);
                ray = REFRACTED_CHILD(&lv[k]);
                lv[k + 1].weight = child_weight(tr, lv[k].weight, REFRACTION_FACTOR(&lv[k]));
                k++;
                break;
            }
            if (k == 0)
                return lv[0].c;
            colour_t child = lv[k].c;
            k--;
            if (REFRACTING(&lv[k])) {
                lv[k].c = colour_add_scaled(lv[k].c, child, REFRACTION_FACTOR(&lv[k]));
                continue;
            }
            if (MIRROR_FACTOR(&lv[k]) > 0)
                lv[k].c = colour_add_scaled(lv[k].c, child, MIRROR_FACTOR(&lv[k]));
        }
    }
}
