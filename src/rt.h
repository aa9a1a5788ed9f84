/*
 * rt.h - the renderer's public interface: all a user's firmware includes.
 *
 *   const rt_scene_t *sc = ...;            (scene compiler tables, or the
 *                                           NFF reader at run time)
 *   rt_render(sc, &opts, &sink, NULL, &err);
 *
 * Configuration: rt_config.h (defaults; a user file through
 * RT_CONFIG_FILE). The framebuffer HAL: rt_fb.h.
 */
#ifndef RT_H
#define RT_H

#include "nff.h"
#include "render.h"
#include "rt_config.h"
#include "rt_error.h"
#include "rt_version.h"
#include "rt_stats.h"

#endif
