/* render.h - render a scene line by line into a framebuffer sink. */
#ifndef RENDER_H
#define RENDER_H

#include "fb.h"
#include "rt_error.h"
#include "scene.h"
#include "stats.h"

typedef struct {
    uint16_t width, height; /* 0: the scene's resolution */
    uint8_t max_depth;      /* 0: RT_MAX_DEPTH */
    /* Adaptive depth: a child ray whose share of the pixel (product of
     * Ks and T along its path) is below adaptive_milli / 1000 is not
     * traced. 0 = off (the default). */
    uint16_t adaptive_milli;
    /* SPD mode: (W+1) x (H+1) corner rays, each pixel the mean of its four
     * corners, and SPD rule 8. Needs `scratch` for two rows of corner
     * colours: at least RENDER_SPD_SCRATCH(width) bytes. */
    bool spd;
    void *scratch;
    size_t scratch_bytes;
} render_opts_t;

#define RENDER_SPD_SCRATCH(width) (2 * ((size_t)(width) + 1) * sizeof(colour_t))

/* 0 on success; a sink's non-zero status (begin or flush; end() is then
 * not called), or -1 with *err set. stats may be NULL. */
int rt_render(const scene_t *sc, const render_opts_t *opts, fb_sink_t *sink, rt_stats_t *stats,
              rt_error_t *err);

#endif
