/* frame_setup.h - a frame begun: the options checked (in the order their
 * errors are reported), the scratch carved into corner rows, the camera
 * and the tracer made, the sink begun, then the first pass's first step
 * (progressive) or the corners above the first line (SPD, adaptive
 * anti-aliasing). Part of render.c's unit, included after the row walks
 * it starts: render_begin is inlined into rt_render_begin and rt_render,
 * so a build that only calls rt_render (the board) links one function, as
 * small as a single loop. (Cut into functions of its own or moved out of
 * the unit, its steps change GCC's code for the firmware: the two-core
 * builds' rt_render 68 to 104 bytes apart, the anti-aliased set-up's
 * blocks in another order; its steps are marked in it instead.) */
#ifndef FRAME_SETUP_H
#define FRAME_SETUP_H

#include "frame.h"
#include "pixel.h"

#define TILE 8 /* the progressive lattice's period: a viewport's edges lie on it */

/* Whether the options record or replay split decisions (RT_AA_REPLAY). */
#if RT_AA_REPLAY
#define SPLITS_ASKED(opts) ((opts)->aa_splits_mode != RT_AA_SPLITS_OFF)
#else
#define SPLITS_ASKED(opts) false
#endif

/* The body of rt_render_begin, inlined into it and into rt_render (with
 * render.c's render_step and render_end). */
static RT_INLINE int render_begin(rt_render_ctx_t *ctx, const scene_t *sc, const rt_render_opts_t *opts,
                                  rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err)
{
    uint16_t w = opts->width ? opts->width : sc->width;
    uint16_t h = opts->height ? opts->height : sc->height;
    int depth = opts->max_depth ? opts->max_depth : RT_DEFAULT_DEPTH;
    if (opts->worker >= RT_MAX_WORKERS) { /* before ctx is touched: rt_render's is a worker's */
        rt_error_set(err, 0, "worker exceeds RT_MAX_WORKERS - 1 = ");
        rt_error_append_int(err, RT_MAX_WORKERS - 1);
        return -1;
    }
    ctx->sink = sink;
    ctx->y = ctx->y_end = 0; /* done, should the caller step after a failure */
#ifdef RT_CONST_SCENE
    if (sc != &RT_CONST_SCENE) { /* the tracer reads that scene alone (trace.h) */
        rt_error_set(err, 0, "this core was built for one scene (RT_CONST_SCENE), not this one");
        return -1;
    }
#endif
    if (w == 0 || h == 0 || w > RT_MAX_WIDTH || h > RT_MAX_HEIGHT) {
        rt_error_set(err, 0, "image size must be 1x1 to ");
        rt_error_append_int(err, RT_MAX_WIDTH);
        rt_error_append(err, "x");
        rt_error_append_int(err, RT_MAX_HEIGHT);
        return -1;
    }
    if (depth > RT_MAX_DEPTH) {
        rt_error_set(err, 0, "depth exceeds RT_MAX_DEPTH = ");
        rt_error_append_int(err, RT_MAX_DEPTH);
        return -1;
    }
    /* the viewport in the frame, and the sink's lines */
    struct rt_worker *wk = &workers[opts->worker];
    rt_viewport_t vp = opts->viewport;
    if (vp.w == 0 && vp.h == 0)
        vp = (rt_viewport_t){ 0, 0, w, h };
    if (vp.w == 0 || vp.h == 0 || vp.x >= w || vp.y >= h || vp.w > w - vp.x || vp.h > h - vp.y) {
        rt_error_set(err, 0, "viewport outside the frame");
        return -1;
    }
    size_t line_bytes = RT_FB_LINE_BYTES(PIXEL_FORMAT(sink->format), vp.w);
#ifdef RT_FB_ONLY_FORMAT
    if (sink->format != RT_FB_ONLY_FORMAT) /* the one format packed (line_bytes is not 0) */
#else
    if (line_bytes == 0) /* not a format */
#endif
    {
        rt_error_set(err, 0, "pixel format not built in");
        return -1;
    }
    size_t pitch = sink->pitch ? sink->pitch : line_bytes;
    size_t band_lines = sink->band_bytes / pitch;
    if (pitch < line_bytes || band_lines == 0 || sink->band[0] == 0) {
        rt_error_set(err, 0, "framebuffer band buffer is smaller than one line");
        return -1;
    }
    ctx->pitch = pitch;
    ctx->band_lines = band_lines;
    /* modes left out of this build (one message: a board leaves them out together) */
    if ((!RT_USE_SPD && opts->spd) || (!RT_USE_AA && (opts->aa_levels || opts->spp > 1 || SPLITS_ASKED(opts))) ||
        (!RT_USE_PROGRESSIVE && opts->progressive)) {
        rt_error_set(err, 0, "mode not compiled in (RT_USE_SPD, RT_USE_AA, RT_USE_PROGRESSIVE)");
        return -1;
    }
#if RT_USE_PROGRESSIVE
    ctx->pass = ctx->last_pass = 0;
    if (opts->progressive) {
        const char *why = 0;
        bool all = opts->progressive == RT_PROGRESSIVE_ALL;
        if (!all && opts->progressive > RT_PROGRESSIVE_PASSES)
            why = "progressive: a pass from 1 to 7, or RT_PROGRESSIVE_ALL";
        else if (opts->spd || opts->aa_levels)
            why = "progressive display needs one sample a pixel or uniform anti-aliasing (spp), not SPD mode or "
                  "adaptive anti-aliasing (aa_levels 0)";
        else if (rt_fb_bits(PIXEL_FORMAT(sink->format)) % 8u)
            why = "progressive display needs whole bytes a pixel (not l4)";
        else if (vp.x % TILE || vp.y % TILE || ((vp.x + vp.w) % TILE && vp.x + vp.w != w) ||
                 ((vp.y + vp.h) % TILE && vp.y + vp.h != h))
            why = "progressive display needs a viewport on the 8-pixel grid (each edge a multiple of 8 or the frame's)";
        if (why) {
            rt_error_set(err, 0, why);
            return -1;
        }
        ctx->pass = all ? 1 : opts->progressive;
        ctx->last_pass = all ? RT_PROGRESSIVE_PASSES : opts->progressive;
    }
#endif
    /* anti-aliasing: its options, its scratch, threshold and scale, the split decisions' words */
#if !RT_USE_AA
#if RT_USE_PROGRESSIVE
    ctx->aa_levels = ctx->spp = 0; /* (read by the progressive passes) */
#endif
#else
    ctx->aa_levels = opts->aa_levels;
    ctx->spp = opts->spp > 1 ? opts->spp : 0;
    if ((ctx->aa_levels || ctx->spp) && (opts->spd || (ctx->aa_levels && ctx->spp))) {
        rt_error_set(err, 0, "choose one of SPD mode, adaptive and uniform anti-aliasing");
        return -1;
    }
    if (ctx->aa_levels > RT_AA_MAX_LEVELS || ctx->spp > RT_AA_MAX_SPP) {
        rt_error_set(err, 0, ctx->spp ? "anti-aliasing samples exceed RT_AA_MAX_SPP = "
                                      : "anti-aliasing levels exceed RT_AA_MAX_LEVELS = ");
        rt_error_append_int(err, ctx->spp ? RT_AA_MAX_SPP : RT_AA_MAX_LEVELS);
        return -1;
    }
    if (ctx->aa_levels) {
        size_t row = ((size_t)vp.w << ctx->aa_levels) + 1;
        if (opts->scratch == 0 || opts->scratch_bytes < RT_RENDER_AA_SCRATCH(vp.w, ctx->aa_levels)) {
            rt_error_set(err, 0, "anti-aliasing needs a scratch buffer of RT_RENDER_AA_SCRATCH(width, levels) bytes");
            return -1;
        }
        ctx->rows[0] = opts->scratch;
        ctx->rows[1] = (colour_t *)ctx->rows[0] + row;
        ctx->cells = (colour_t *)ctx->rows[1] + row;
        uint32_t t = opts->aa_threshold ? opts->aa_threshold : RT_AA_THRESHOLD;
        wk->aa_threshold = r_div(r_from_int((int32_t)t), r_from_int(255));
        wk->aa_scale = R_RATIO(1, (int32_t)4 << (2 * ctx->aa_levels));
    } else if (ctx->spp) {
        wk->aa_scale = R_RATIO(1, ctx->spp * ctx->spp);
    }
#if RT_AA_REPLAY
    wk->splits = 0;
    if (opts->aa_splits_mode) {
        if (opts->aa_splits_mode > RT_AA_SPLITS_REPLAY || !ctx->aa_levels) {
            rt_error_set(err, 0, "recorded splits (aa_splits) need adaptive anti-aliasing and a mode");
            return -1;
        }
        if (opts->aa_splits == 0 || opts->aa_splits_words < RT_AA_SPLITS_WORDS(w, h, ctx->aa_levels)) {
            rt_error_set(err, 0, "recorded splits need RT_AA_SPLITS_WORDS(width, height, levels) words");
            return -1;
        }
        wk->splits = opts->aa_splits;
        wk->split_words = RT_AA_SPLIT_WORDS(ctx->aa_levels);
        wk->splits_line = (size_t)w * wk->split_words;
        wk->splits_replay = opts->aa_splits_mode == RT_AA_SPLITS_REPLAY;
    }
#endif
#endif
    /* SPD mode's two rows of corner colours */
#if RT_USE_SPD
    ctx->spd = opts->spd;
    if (opts->spd) {
        if (opts->scratch == 0 || opts->scratch_bytes < RT_RENDER_SPD_SCRATCH(vp.w)) {
            rt_error_set(err, 0, "SPD mode needs a scratch buffer of two rows of corner colours");
            return -1;
        }
        ctx->rows[0] = opts->scratch;
        ctx->rows[1] = (colour_t *)ctx->rows[0] + vp.w + 1;
    }
#endif
    /* the camera, the eye rays' cones and where their search starts */
    int32_t nx = w, ny = h;
#if RT_USE_SPD
    if (opts->spd) { /* a grid of corners, one more each way */
        nx++;
        ny++;
    }
#endif
    /* another viewpoint: rt_camera_from_view made it a view_t */
    const view_t *view = opts->camera ? (const view_t *)(const void *)opts->camera : &sc->view;
    const char *why;
#if RT_USE_AA
    if (ctx->aa_levels || ctx->spp) /* cells a pixel side: 2^levels, or 2 spp (samples at their centres) */
        why = camera_init_cells(&wk->cam, view, w, h, ctx->aa_levels ? (int32_t)1 << ctx->aa_levels : 2 * ctx->spp);
    else
#endif
        why = camera_init(&wk->cam, view, nx, ny);
    if (why) {
        rt_error_set(err, 0, why);
        return -1;
    }
#if RT_RAY_CONES
    if (opts->point_textures) /* cones of no width: every texture at the hit point */
        wk->cam.spread = 0;
#if RT_USE_AA
    /* adaptive: a corner stands for the squares around it, which a pixel
     * weighs by their mean, so its cone spreads half its spacing */
    if (ctx->aa_levels)
        wk->cam.spread /= 2;
#endif
#endif
    scene_eye_setup(sc, &wk->cam, &wk->scratch);
    /* eye rays start at the BVH's box unless an unbounded plane may be nearer */
    if (sc->n_bvh_nodes > 0 && sc->n_planes == 0)
        camera_start_at_bounds(&wk->cam, sc->bvh_nodes[0].min, sc->bvh_nodes[0].max);
    /* the tracer */
    wk->tr = (tracer_t){ sc, depth, &wk->scratch, opts->spd,
                         r_div(r_from_int(opts->adaptive_milli), r_from_int(1000)), wk->last_blocker, wk->terms };
    for (uint32_t i = 0; i < RT_MAX_LIGHTS; i++)
        wk->last_blocker[i] = PRIM_NONE;
    for (uint32_t i = 0; i < RT_MAX_DEPTH; i++)
        wk->terms[i].material = 0;
    wk->scratch.stats = (rt_stats_t){ 0 };
    ctx->worker = wk;
    ctx->stats = stats;

    /* the sink begun, the walk at the viewport's first line */
    sink->flushing = false;
    int status = sink->begin ? sink->begin(sink, w, h) : 0;
    if (status != 0)
        return status;
    ctx->x0 = vp.x;
    ctx->w = vp.w;
    ctx->y = ctx->band_y = vp.y;
    ctx->y_end = (uint16_t)(vp.y + vp.h);
#if RT_USE_PROGRESSIVE
    ctx->y0 = vp.y;
#endif
    ctx->cur = 0;
    /* the first step */
#if RT_USE_PROGRESSIVE
    if (ctx->pass) {
        ctx->x = (uint16_t)(vp.x + passes[ctx->pass - 1].ox);
        progressive_next(ctx, (uint32_t)vp.y + passes[ctx->pass - 1].oy);
        return 0;
    }
#endif
#if RT_USE_SPD
    if (opts->spd)
        corner_row(wk, vp.y, vp.x, vp.w, ctx->rows[0]);
#endif
#if RT_USE_AA
    if (ctx->aa_levels)
        aa_corner_row(wk, (int32_t)vp.y << ctx->aa_levels, vp.x, vp.w, ctx->aa_levels, ctx->rows[0]);
#endif
    return 0;
}

#endif
