/* backend.c - rt_backend_t over one build of the core (see backend.h). */
#include "backend.h"

#include <math.h>

#include "geometry/camera.h"
#include "reader/nff.h"
#include "geometry/prims.h"
#include "geometry/scene_hit.h"
#include "tracer/shine.h"
#include "tracer/texture.h"
#include "tracer/trace.h"

/* BACKEND_ID (from the Makefile) names this build: rt_backend_<id>. */
#ifndef BACKEND_ID
#error "build with -DBACKEND_ID=<an id of RT_HOST_BACKENDS>"
#endif
#define BACKEND_CAT(a, b) a##b
#define BACKEND_SYMBOL_OF(id) BACKEND_CAT(rt_backend_, id)
#define BACKEND_SYMBOL BACKEND_SYMBOL_OF(BACKEND_ID)

#if RT_BACKEND_FIXED
static real_t to_real(double v)
{
    double s = v * FX_ONE;
    return (real_t)(s < 0 ? s - 0.5 : s + 0.5);
}
static double to_double(real_t v) { return (double)v / FX_ONE; }
#else
static real_t to_real(double v) { return (real_t)v; }
static double to_double(real_t v) { return v; }
#endif

static scene_store_t store;

static bool load(const char *text, size_t len, rt_error_t *err)
{
    return nff_read(text, len, &store, err);
}

static void resolution(uint16_t *w, uint16_t *h)
{
    *w = store.scene.width;
    *h = store.scene.height;
}

static uint32_t flat_skipped(void) { return store.scene.n_flat_skipped; }

static int32_t scale_log2(void) { return store.scene.scale_log2; }

static int64_t saturations(bool reset)
{
#if RT_BACKEND_FIXED && FX_COUNT_SATURATIONS
    int64_t n = fx_saturations;
    if (reset)
        fx_saturations = 0;
    return n;
#else
    (void)reset;
    return -1;
#endif
}

static void bvh_stats(bvh_stats_t *out) { bvh_tree_stats(&store.scene, out); }

static int render(const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err)
{
    return rt_render(&store.scene, opts, sink, stats, err);
}

static int render_steps(const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err,
                        uint16_t lines, bool (*more)(void *user), void *user)
{
    rt_render_ctx_t ctx;
    int status = rt_render_begin(&ctx, &store.scene, opts, sink, stats, err);
    while (status == 0 && !rt_render_done(&ctx) && (!more || more(user)))
        status = rt_render_step(&ctx, lines);
    return status != 0 ? status : rt_render_end(&ctx);
}

/* World units per scene unit: the reader scaled positions by 2^scale_log2. */
static double world_per_unit(void)
{
    double f = 1;
    for (int32_t k = store.scene.scale_log2; k > 0; k--)
        f *= 0.5;
    for (int32_t k = store.scene.scale_log2; k < 0; k++)
        f *= 2;
    return f;
}

static bool bounds(double mn[3], double mx[3])
{
    const scene_t *sc = &store.scene;
    if (sc->n_bvh_nodes == 0)
        return false;
    const bvh_node_t *n = &sc->bvh_nodes[0];
    double w = world_per_unit();
    mn[0] = w * to_double(n->min.x), mn[1] = w * to_double(n->min.y), mn[2] = w * to_double(n->min.z);
    mx[0] = w * to_double(n->max.x), mx[1] = w * to_double(n->max.y), mx[2] = w * to_double(n->max.z);
    return true;
}

static ray_t probe_ray(const double o[3], const double d[3], uint32_t leaf)
{
    ray_t r;
    double w = world_per_unit();
    r.origin = v3(to_real(o[0] / w), to_real(o[1] / w), to_real(o[2] / w));
    r.dir = v3_unit(v3(to_real(d[0]), to_real(d[1]), to_real(d[2])));
    r.from = PRIM_NONE;
    r.from_far = false;
    r.leaf = leaf;
#if RT_RAY_CONES
    r.cone_width = r.cone_spread = 0; /* a probe has no footprint */
#endif
    return r;
}

static bool probe_with(const double o[3], const double d[3], bool brute, uint32_t leaf, probe_hit_t *out)
{
    const scene_t *sc = &store.scene;
    double w = world_per_unit();
    ray_t r = probe_ray(o, d, leaf);
    static ray_scratch_t st; /* one probe at a time */
    hit_t h = { .t = RT_T_FAR, .leaf = RT_NO_LEAF };
    if (!(brute ? scene_nearest_brute : scene_nearest)(sc, &r, RT_T_MIN, &h, &st))
        return false;
    vec3_t p = ray_at(&r, h.t);
    prim_surface_t surf;
    prim_surface(sc, &h, p, &surf);
    vec3_t n = surf.n;
    out->t = w * to_double(h.t);
#if RT_BACKEND_FIXED
    out->t_raw = (int64_t)h.t;
#else
    out->t_raw = 0;
#endif
    out->normal[0] = to_double(n.x);
    out->normal[1] = to_double(n.y);
    out->normal[2] = to_double(n.z);
    out->point[0] = w * to_double(p.x);
    out->point[1] = w * to_double(p.y);
    out->point[2] = w * to_double(p.z);
    out->kind = h.kind;
    out->index = h.index;
    out->leaf = h.leaf;
    return true;
}

static bool probe(const double o[3], const double d[3], bool brute, probe_hit_t *out)
{
    return probe_with(o, d, brute, RT_NO_LEAF, out);
}

static bool probe_leaf(const double o[3], const double d[3], uint32_t leaf, probe_hit_t *out)
{
    return probe_with(o, d, false, leaf, out);
}

static bool occluded(const double o[3], const double d[3], double tmax, uint32_t leaf, uint32_t *last_blocker)
{
    ray_t r = probe_ray(o, d, leaf);
    static ray_scratch_t st; /* one probe at a time */
    prim_ref_t blocker = *last_blocker;
    bool b = scene_occluded(&store.scene, &r, RT_T_MIN, to_real(tmax / world_per_unit()), &blocker, &st);
    *last_blocker = blocker;
    return b;
}

static bool occluded_light(uint32_t light, const double o[3], const double d[3], double tmax,
                           uint32_t *last_blocker)
{
    ray_t r = probe_ray(o, d, RT_NO_LEAF);
    static ray_scratch_t st; /* one probe at a time */
    camera_t cam;
    if (camera_init(&cam, &store.scene.view, 16, 16))
        return false;
    scene_eye_setup(&store.scene, &cam, &st);
#if RT_USE_FLAT
    st.shadow_light = (uint8_t)(light < UINT8_MAX ? light + 1 : 0);
#else
    (void)light;
#endif
    prim_ref_t blocker = *last_blocker;
    bool b = scene_occluded(&store.scene, &r, RT_T_MIN, to_real(tmax / world_per_unit()), &blocker, &st);
    *last_blocker = blocker;
    return b;
}

static bool eye_dir(int32_t nx, int32_t ny, int32_t i, int32_t j, double dir[3])
{
    camera_t cam;
    if (camera_init(&cam, &store.scene.view, nx, ny))
        return false;
    ray_t r = camera_ray(&cam, i, j);
    dir[0] = to_double(r.dir.x);
    dir[1] = to_double(r.dir.y);
    dir[2] = to_double(r.dir.z);
    return true;
}

static double pow_unit(double x, double s)
{
#if RT_BACKEND_FIXED
    shine_t sh = (shine_t)(s * (1 << R_SHINE_FRAC_BITS) + 0.5);
#else
    shine_t sh = (shine_t)s;
#endif
    return to_double(r_pow_unit(to_real(x), sh));
}

static bool texture_at(uint32_t texture, const double p[3], double rgb[3])
{
    if (texture >= store.scene.n_textures)
        return false;
    double w = world_per_unit();
    vec3_t q = v3(to_real(p[0] / w), to_real(p[1] / w), to_real(p[2] / w));
    colour_t c = texture_colour(&store.scene.textures[texture], q, 0);
    rgb[0] = to_double(c.x), rgb[1] = to_double(c.y), rgb[2] = to_double(c.z);
    return true;
}

const rt_backend_t BACKEND_SYMBOL = {
    load, resolution, flat_skipped, scale_log2, saturations, bvh_stats, render, render_steps, rt_stats_each, rt_stats_add, probe, probe_leaf, occluded,
    occluded_light, bounds, eye_dir, pow_unit, texture_at,
};
