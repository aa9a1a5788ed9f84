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
} render_opts_t;

/* 0 on success; a sink's non-zero status, or -1 with *err set. */
int rt_render(const scene_t *sc, const render_opts_t *opts, fb_sink_t *sink, rt_stats_t *stats,
              rt_error_t *err);

#endif
