/*
 * rt.h - the renderer's public interface: all a user's firmware includes.
 *
 * Everything here and in the headers it includes is prefixed rt_ / RT_,
 * and none of them includes the core's internal headers.
 *
 *   scene   rt_scene (tables the scene compiler wrote into flash: declare
 *           `extern const rt_scene_t rt_scene;`), or rt_nff_load() at
 *           run time;
 *   render  rt_render() for a frame, or rt_render_begin/step/end in
 *           slices (rt_render.h), into a sink (the HAL, rt_fb.h);
 *   errors  rt_error_t (rt_error.h); counters rt_stats_t (rt_stats.h);
 *   config  rt_config.h, with a user file through RT_CONFIG_FILE;
 *   version RT_VERSION_* (rt_version.h).
 */
#ifndef RT_H
#define RT_H

#include <stddef.h>

#include "rt_config.h"
#include "rt_error.h"
#include "rt_fb.h"
#include "rt_render.h"
#include "rt_stats.h"
#include "rt_version.h"

/* Reads `len` bytes of NFF text into the library's own tables (static, at
 * the configured capacities; linked only when called): the scene, or
 * NULL with *err set (err->line is the 1-based input line, 0 when the
 * error is not about one). Each call replaces the previous scene. */
const rt_scene_t *rt_nff_load(const char *text, size_t len, rt_error_t *err);

#endif
