/* render.c - the frame loop: eye rays per pixel, pixels packed per band. */
#include "rt_render.h"

#include "camera.h"
#include "trace.h"

/* RT_FB_ONLY_FORMAT (a build flag, e.g. the board's): the one format the
 * build packs; the packer's switch folds to that case. */
#ifdef RT_FB_ONLY_FORMAT
#define PIXEL_FORMAT(f) ((void)(f), (rt_fb_format_t)(RT_FB_ONLY_FORMAT))
#else
#define PIXEL_FORMAT(f) (f)
#endif

/* Pixel x of a line in format f: the one packer of every format (rt_fb.h). */
static RT_INLINE void put_pixel(uint8_t *line, uint16_t x, rt_fb_format_t f, colour_t c)
{
    unsigned r = r_to_u8(c.x), g = r_to_u8(c.y), b = r_to_u8(c.z);
    unsigned w, l;
    uint8_t *px;
    switch (PIXEL_FORMAT(f)) {
    case RT_FB_RGB888:
        px = line + 3u * x;
        px[0] = (uint8_t)r;
        px[1] = (uint8_t)g;
        px[2] = (uint8_t)b;
        break;
    case RT_FB_XRGB8888:
        px = line + 4u * x;
        px[0] = (uint8_t)b;
        px[1] = (uint8_t)g;
        px[2] = (uint8_t)r;
        px[3] = 0;
        break;
    case RT_FB_RGB565:
    case RT_FB_RGB565BE:
        px = line + 2u * x;
        w = ((r * 31u + 127u) / 255u) << 11 | ((g * 63u + 127u) / 255u) << 5 | ((b * 31u + 127u) / 255u);
        if (PIXEL_FORMAT(f) == RT_FB_RGB565BE)
            w = (w >> 8 | w << 8) & 0xFFFFu;
        px[0] = (uint8_t)w;
        px[1] = (uint8_t)(w >> 8);
        break;
    default: /* RT_FB_L8, RT_FB_L4 */
        l = (77u * r + 150u * g + 29u * b + 128u) >> 8;
        if (PIXEL_FORMAT(f) == RT_FB_L8) {
            line[x] = (uint8_t)l;
        } else {
            l = (l * 15u + 127u) / 255u;
            px = line + (x >> 1);
            /* the left pixel's write clears the right one's nibble */
            *px = x & 1u ? (uint8_t)(*px | l) : (uint8_t)(l << 4);
        }
        break;
    }
}

static void wait_flushed(rt_fb_sink_t *sink)
{
    while (sink->flushing) {
        if (sink->wait)
            sink->wait(sink);
    }
}

/* Lines y1..y2 of the band to the sink. Its status: 0, or its failure
 * (then no flush is in flight). */
static RT_INLINE int flush_band(rt_render_ctx_t *ctx, uint16_t y2)
{
    rt_fb_sink_t *sink = ctx->sink;
    rt_fb_area_t area = { ctx->x0, ctx->band_y, (uint16_t)(ctx->x0 + ctx->w - 1), y2 };
    wait_flushed(sink); /* the other buffer's flush */
    sink->flushing = true;
    int status = sink->flush(sink, &area, sink->band[ctx->cur]);
    if (status != 0) {
        sink->flushing = false;
        return status;
    }
    if (sink->band[1])
        ctx->cur ^= 1u;
    else
        wait_flushed(sink);
    ctx->band_y = (uint16_t)(y2 + 1);
    return 0;
}

/* Everything a render writes, one per worker: static, so the stack stays
 * small, and one each, so renders on other cores or threads share none. */
struct rt_worker {
    rt_render_ctx_t ctx; /* rt_render's */
    camera_t cam;
    tracer_t tr;
    prim_ref_t last_blocker[RT_MAX_LIGHTS];
    material_terms_t terms[RT_MAX_DEPTH];
    ray_scratch_t scratch;
};
static struct rt_worker workers[RT_MAX_WORKERS];

#if RT_USE_SPD
/* One row of SPD corner samples: corners x0 .. x0 + w of grid row j. */
static void corner_row(struct rt_worker *wk, int32_t j, uint16_t x0, uint16_t w, colour_t *row)
{
    for (int32_t i = 0; i <= w; i++) {
        ray_t ray = camera_ray(&wk->cam, x0 + i, j);
        wk->scratch.stats.eye_rays++;
        row[i] = trace_ray(&wk->tr, &ray, 1, R_ONE);
    }
}

/* Line y of an SPD frame: each pixel the mean of its four corners;
 * rows[0] holds the corners above the line, rows[1] gets those below. */
static void spd_line(rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    const colour_t *above = ctx->rows[0];
    colour_t *below = ctx->rows[1];
    corner_row(ctx->worker, y + 1, ctx->x0, ctx->w, below);
    for (uint16_t x = 0; x < ctx->w; x++) {
        colour_t sum = c3_add(c3_add(above[x], above[x + 1]), c3_add(below[x], below[x + 1]));
        put_pixel(line, x, ctx->sink->format, v3_scale(sum, R_RATIO(1, 4)));
    }
    ctx->rows[1] = ctx->rows[0]; /* the lower corners are the next line's upper */
    ctx->rows[0] = below;
}
#endif

/* Line y of a normal frame: one eye ray per pixel. */
static RT_INLINE void plain_line(const rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    struct rt_worker *wk = ctx->worker;
    for (uint16_t x = 0; x < ctx->w; x++) {
        ray_t ray = camera_ray(&wk->cam, ctx->x0 + x, y);
        wk->scratch.stats.eye_rays++;
        put_pixel(line, x, ctx->sink->format, trace_ray(&wk->tr, &ray, 1, R_ONE));
    }
}

/* The bodies of rt_render_begin, _step and _end, inlined into them and
 * into rt_render: a build that only calls rt_render (the board) links one
 * function, as small as a single loop. */
static RT_INLINE int render_begin(rt_render_ctx_t *ctx, const scene_t *sc, const rt_render_opts_t *opts,
                                  rt_fb_sink_t *sink, rt_stats_t *stats, rt_error_t *err)
{
    uint16_t w = opts->width ? opts->width : sc->width;
    uint16_t h = opts->height ? opts->height : sc->height;
    int depth = opts->max_depth ? opts->max_depth : RT_MAX_DEPTH;
    if (opts->worker >= RT_MAX_WORKERS) { /* before ctx is touched: rt_render's is a worker's */
        rt_error_set(err, 0, "worker exceeds RT_MAX_WORKERS - 1 = ");
        rt_error_append_int(err, RT_MAX_WORKERS - 1);
        return -1;
    }
    ctx->sink = sink;
    ctx->y = ctx->y_end = 0; /* done, should the caller step after a failure */
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
#if !RT_USE_SPD
    if (opts->spd) {
        rt_error_set(err, 0, "SPD mode is not compiled in (RT_USE_SPD = 0)");
        return -1;
    }
#else
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
    int32_t nx = w, ny = h;
#if RT_USE_SPD
    if (opts->spd) { /* a grid of corners, one more each way */
        nx++;
        ny++;
    }
#endif
    /* another viewpoint: rt_camera_from_view made it a view_t */
    const view_t *view = opts->camera ? (const view_t *)(const void *)opts->camera : &sc->view;
    const char *why = camera_init(&wk->cam, view, nx, ny);
    if (why) {
        rt_error_set(err, 0, why);
        return -1;
    }
    if (sc->n_bvh_nodes > 0)
        camera_start_at_bounds(&wk->cam, sc->bvh_nodes[0].min, sc->bvh_nodes[0].max);
    wk->tr = (tracer_t){ sc, depth, &wk->scratch, opts->spd,
                         r_div(r_from_int(opts->adaptive_milli), r_from_int(1000)), wk->last_blocker, wk->terms };
    for (uint32_t i = 0; i < RT_MAX_LIGHTS; i++)
        wk->last_blocker[i] = PRIM_NONE;
    for (uint32_t i = 0; i < RT_MAX_DEPTH; i++)
        wk->terms[i].material = 0;
    wk->scratch.stats = (rt_stats_t){ 0 };
    ctx->worker = wk;
    ctx->stats = stats;

    sink->flushing = false;
    int status = sink->begin ? sink->begin(sink, w, h) : 0;
    if (status != 0)
        return status;
    ctx->x0 = vp.x;
    ctx->w = vp.w;
    ctx->y = ctx->band_y = vp.y;
    ctx->y_end = (uint16_t)(vp.y + vp.h);
    ctx->cur = 0;
#if RT_USE_SPD
    if (opts->spd)
        corner_row(wk, vp.y, vp.x, vp.w, ctx->rows[0]);
#endif
    return 0;
}

/* The worker's counts so far into the caller's stats. */
static void add_stats(rt_render_ctx_t *ctx)
{
    rt_stats_t *part = &ctx->worker->scratch.stats;
    if (ctx->stats)
        rt_stats_add(ctx->stats, part);
    *part = (rt_stats_t){ 0 };
}

static RT_INLINE int render_step(rt_render_ctx_t *ctx, uint16_t lines)
{
    rt_fb_sink_t *sink = ctx->sink;
    int status = 0;
    for (; lines > 0 && ctx->y < ctx->y_end; lines--) {
        uint16_t y = ctx->y++;
        uint8_t *line = sink->band[ctx->cur] + (size_t)(y - ctx->band_y) * ctx->pitch;
#if RT_USE_SPD
        if (ctx->spd)
            spd_line(ctx, y, line);
        else
#endif
            plain_line(ctx, y, line);
        if ((size_t)(y - ctx->band_y + 1) == ctx->band_lines || ctx->y == ctx->y_end) {
            status = flush_band(ctx, y);
            if (status != 0) {
                ctx->y_end = ctx->y; /* done: nothing more to render */
                break;
            }
        }
    }
    add_stats(ctx);
    return status;
}

static RT_INLINE int render_end(rt_render_ctx_t *ctx)
{
    wait_flushed(ctx->sink);
    return ctx->sink->end ? ctx->sink->end(ctx->sink) : 0;
}

RT_COLD int rt_render(const scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats,
                      rt_error_t *err)
{
    /* the worker's own context: off the stack, under the whole render
     * (an invalid worker fails before render_begin touches it) */
    rt_render_ctx_t *ctx = &workers[opts->worker < RT_MAX_WORKERS ? opts->worker : 0].ctx;
    int status = render_begin(ctx, sc, opts, sink, stats, err);
    if (status != 0)
        return status;
    status = render_step(ctx, 0xFFFF);
    return status != 0 ? status : render_end(ctx);
}

RT_COLD int rt_render_begin(rt_render_ctx_t *ctx, const scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink,
                            rt_stats_t *stats, rt_error_t *err)
{
    ctx->y = ctx->y_end = 0; /* done, should the caller step after any failure */
    return render_begin(ctx, sc, opts, sink, stats, err);
}

RT_COLD int rt_render_step(rt_render_ctx_t *ctx, uint16_t lines) { return render_step(ctx, lines); }

RT_COLD int rt_render_end(rt_render_ctx_t *ctx) { return render_end(ctx); }
