/*
 * backend.h - one numeric build of the core, as the hosted tools see it.
 *
 * The core is compiled once per backend (fixed, double, float, and double
 * with the fixed build's tolerances); each copy is linked with backend.c
 * into one relocatable object that exports only its rt_backend_t, so all
 * live in one program without symbol clashes.
 * Nothing here depends on real_t: values cross as double.
 */
#ifndef BACKEND_H
#define BACKEND_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "geometry/bvh.h"
#include "rt_fb.h"
#include "rt_render.h"
#include "rt_error.h"
#include "rt_stats.h"

typedef struct {
    double t;
    int64_t t_raw;      /* t exactly as the backend holds it (fixed: units of 2^-FX_FRAC_BITS) */
    double normal[3];   /* shading normal as the tracer uses it (unit, not flipped) */
    double point[3];    /* the hit point as the backend computes it */
    int kind;           /* enum prim_kind */
    uint32_t index;
    uint32_t leaf;      /* the BVH leaf it was found in (RT_NO_LEAF by brute force) */
} probe_hit_t;

typedef struct {
    /* Read NFF text into the backend's own static scene. */
    bool (*load)(const char *text, size_t len, rt_error_t *err);
    void (*resolution)(uint16_t *width, uint16_t *height);
    uint32_t (*flat_skipped)(void); /* zero-area polygons the reader dropped */
    int32_t (*scale_log2)(void);    /* positions were read times 2^this */
    /* Fixed-point saturations so far (-1 unless built with
     * FX_COUNT_SATURATIONS=1), and a reset. */
    int64_t (*saturations)(bool reset);

    void (*bvh_stats)(bvh_stats_t *out);
    int (*render)(const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err);
    /* The same through rt_render_begin / rt_render_step(lines) / rt_render_end;
     * with `more`, each step only while more(user) says so (the frame may
     * then end early; end() is still called). */
    int (*render_steps)(const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err,
                        uint16_t lines, bool (*more)(void *user), void *user);
    /* rt_stats_each (stats.h): the counters by key. */
    void (*stats_each)(const rt_stats_t *st, rt_stats_visit_fn *visit, void *ctx);
    /* rt_stats_add: sum += part (the threads' counts into one). */
    void (*stats_add)(rt_stats_t *sum, const rt_stats_t *part);
    /* Nearest hit of one ray against the loaded scene (for tests), through
     * the BVH or, with `brute`, by testing every primitive. Origin and t
     * are in the file's units (the backend applies the reader's scale). */
    bool (*probe)(const double origin[3], const double dir[3], bool brute, probe_hit_t *hit);
    /* The same through the BVH for a ray starting in BVH leaf `leaf` (the
     * hint of secondary rays, ray.h), and whether anything lies on the
     * ray before tmax, trying *last_blocker first (scene_occluded; a prim
     * reference as PRIM_REF(kind, index), or UINT32_MAX). */
    bool (*probe_leaf)(const double origin[3], const double dir[3], uint32_t leaf, probe_hit_t *hit);
    bool (*occluded)(const double origin[3], const double dir[3], double tmax, uint32_t leaf,
                     uint32_t *last_blocker);
    /* The same for a shadow ray to light `light`, with the frame set up as
     * a render sets it (scene_eye_setup): a flat scene's search may skip
     * spheres by the light's cones. */
    bool (*occluded_light)(uint32_t light, const double origin[3], const double dir[3], double tmax,
                           uint32_t *last_blocker);
    /* The scene's bounds (root box of the BVH); false for an empty scene. */
    bool (*bounds)(double min[3], double max[3]);
    /* Eye-ray direction of grid sample (i, j) of an nx x ny camera. */
    bool (*eye_dir)(int32_t nx, int32_t ny, int32_t i, int32_t j, double dir[3]);
    /* x^s as the shading computes it (r_pow_unit), x and s first
     * converted to the backend's real_t and shine_t. */
    double (*pow_unit)(double x, double s);
    /* Texture `texture` of the loaded scene at point p (file units, first
     * converted to the backend's real_t), point-sampled; false if there is
     * no such texture. */
    bool (*texture_at)(uint32_t texture, const double p[3], double rgb[3]);
} rt_backend_t;

/* The builds of the core in the host tools, one row each: X(id, name,
 * what). Each is rt_backend_<id>, built by the Makefile's HOST_BACKENDS
 * (with the row's flags there) and picked by `rt --<name>`; the first is
 * the default. */
#define RT_HOST_BACKENDS(X) \
    X(fixed, "fixed", "fixed-point build of the core (default)") \
    X(double, "double", "double-precision build: the exact reference") \
    X(double_ftol, "double-ftol", "double precision with the fixed build's tolerances\n" \
      "                      (splits the fixed build's error: format vs tolerances)") \
    X(float, "float", "single-precision build (for comparison)")

#define RT_BACKEND_DECLARE(id, name, what) extern const rt_backend_t rt_backend_##id;
RT_HOST_BACKENDS(RT_BACKEND_DECLARE)
#undef RT_BACKEND_DECLARE

#endif
