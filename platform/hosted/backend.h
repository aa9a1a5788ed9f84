/*
 * backend.h - one numeric build of the core, as the hosted tools see it.
 *
 * The core is compiled twice (fixed and double); each copy is linked with
 * backend.c into one relocatable object that exports only its
 * rt_backend_t, so both live in one program without symbol clashes.
 * Nothing here depends on real_t: values cross as double.
 */
#ifndef BACKEND_H
#define BACKEND_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fb.h"
#include "render.h"
#include "rt_error.h"
#include "stats.h"

typedef struct {
    double t;
    double normal[3];   /* shading normal as the tracer uses it (unit, not flipped) */
    int kind;           /* 0 sphere, 1 cone, 2 polygon/patch */
    uint32_t index;
} probe_hit_t;

typedef struct {
    const char *name;  /* "fixed" or "double" */
    /* Read NFF text into the backend's own static scene. */
    bool (*load)(const char *text, size_t len, rt_error_t *err);
    void (*resolution)(uint16_t *width, uint16_t *height);
    uint32_t (*primitive_count)(void);
    uint32_t (*flat_skipped)(void); /* zero-area polygons the reader dropped */
    int (*render)(const render_opts_t *opts, fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err);
    /* Nearest hit of one ray against the loaded scene (for tests). */
    bool (*probe)(const double origin[3], const double dir[3], probe_hit_t *hit);
    /* Eye-ray direction of grid sample (i, j) of an nx x ny camera. */
    bool (*eye_dir)(int32_t nx, int32_t ny, int32_t i, int32_t j, double dir[3]);
} rt_backend_t;

extern const rt_backend_t rt_backend_fixed;
extern const rt_backend_t rt_backend_double;

#endif
