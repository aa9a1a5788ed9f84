/* render.c - the frame walk: eye rays a line at a time in scanline order
 * (one sample a pixel, SPD corners, or anti-aliasing's lines: aa.h) or in
 * progressive passes, each line packed (pixel.h) into the band buffer and
 * the bands flushed to the sink; the frame begun by frame_setup.h. The
 * three headers are parts of this one unit, each included where its code
 * always stood: the firmware's code stays as it was. */
#include "frame.h"
#include "pixel.h"

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

/* One worker a core or thread (frame.h): rt_render's context is its own. */
static struct rt_worker workers[RT_MAX_WORKERS];

#if RT_USE_SPD
/* One row of SPD corner samples: corners x0 .. x0 + w of grid row j. */
static void corner_row(struct rt_worker *wk, int32_t j, uint16_t x0, uint16_t w, colour_t *row)
{
    camera_row(&wk->cam, x0, j, &wk->row);
    for (int32_t i = 0; i <= w; i++) {
        eye_sample(wk, wk->row.k, wk->row.m);
        ray_t ray = camera_next(&wk->cam, &wk->row);
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
        put_pixel(line, x, ctx->sink->format, v3_scale(sum, R_RATIO(1, 4)), dither_at(ctx, ctx->x0 + x, y));
    }
    ctx->rows[1] = ctx->rows[0]; /* the lower corners are the next line's upper */
    ctx->rows[0] = below;
}
#endif

#include "aa.h"

/* Line y of a normal frame: one eye ray per pixel. */
static RT_INLINE void plain_line(const rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    struct rt_worker *wk = ctx->worker;
    camera_row(&wk->cam, ctx->x0, y, &wk->row);
    for (uint16_t x = 0; x < ctx->w; x++) {
        eye_sample(wk, wk->row.k, wk->row.m);
        ray_t ray = camera_next(&wk->cam, &wk->row);
        wk->scratch.stats.eye_rays++;
        put_pixel(line, x, ctx->sink->format, trace_ray(&wk->tr, &ray, 1, R_ONE), dither_at(ctx, ctx->x0 + x, y));
    }
}

#if RT_USE_PROGRESSIVE
/* The progressive passes (rt_render.h), in order: the first sample's
 * offset in each 8x8 tile, the spacing of the samples, the block each
 * one paints. One list: the passes' lattices nest, and together they
 * hold each pixel of a tile once (tests/host/progressive-tests.sh checks the
 * pictures against the rule, render.c's counts against a frame's). */
typedef struct {
    uint8_t ox, oy, sx, sy, bw, bh;
} pass_t;
static const pass_t passes[] = {
    { 0, 0, 8, 8, 8, 8 }, { 4, 0, 8, 8, 4, 8 }, { 0, 4, 4, 8, 4, 4 }, { 2, 0, 4, 4, 2, 4 },
    { 0, 2, 2, 4, 2, 2 }, { 1, 0, 2, 2, 1, 2 }, { 0, 1, 1, 2, 1, 1 },
};
_Static_assert(sizeof passes / sizeof passes[0] == RT_PROGRESSIVE_PASSES, "a row for each pass");
/* (RT_PROGRESSIVE_BY_COLUMNS, rt_render.h, names the passes whose blocks
 * are narrower than their samples are apart: bw < sx above) */

/* Flushes bytes `px` as `area` (the other buffer's flush done first):
 * 0, or the sink's failure (then nothing is in flight). */
static int flush_area(rt_fb_sink_t *sink, const rt_fb_area_t *area, const uint8_t *px)
{
    wait_flushed(sink);
    sink->flushing = true;
    int status = sink->flush(sink, area, px);
    if (status != 0)
        sink->flushing = false;
    else if (!sink->band[1])
        wait_flushed(sink);
    return status;
}

/* The colour of frame pixel (x, y) as scanline order gives it, for a row
 * walk at (x, y) (plain frames: the next sample of wk->row). */
static RT_INLINE colour_t sample_colour(const rt_render_ctx_t *ctx, uint32_t x, uint32_t y)
{
#if RT_USE_AA
    if (ctx->spp)
        return aa_uniform_pixel(ctx, x, y);
#endif
    (void)x, (void)y;
    struct rt_worker *wk = ctx->worker;
    eye_sample(wk, wk->row.k, wk->row.m);
    ray_t ray = camera_next(&wk->cam, &wk->row);
    wk->scratch.stats.eye_rays++;
    return trace_ray(&wk->tr, &ray, 1, R_ONE);
}

/* Frame pixel (x, y) traced (a row walk at it, for one sample a pixel)
 * and packed into px: one copy for the rows and the columns. */
static RT_NOINLINE void progressive_sample(const rt_render_ctx_t *ctx, uint32_t x, uint32_t y, uint8_t px[4])
{
    put_pixel(px, 0, ctx->sink->format, sample_colour(ctx, x, y), dither_at(ctx, x, y));
}

/* Pixel bytes px (`bytes` of them) to pixels from .. to - 1 of a line:
 * a 16-bit store a pixel where the pixel is two bytes and the line even
 * (the panels' 565), else byte by byte. */
static RT_INLINE void paint(uint8_t *line, const uint8_t *px, unsigned bytes, uint32_t from, uint32_t to)
{
    uint8_t *p = line + from * bytes, *end = line + to * bytes;
    if (bytes == 2 && ((uintptr_t)line & 1u) == 0) {
        uint16_t v;
        __builtin_memcpy(&v, px, 2);
        for (; p < end; p += 2)
            __builtin_memcpy(__builtin_assume_aligned(p, 2), &v, 2);
        return;
    }
    for (; p < end; p += bytes)
        for (unsigned b = 0; b < bytes; b++)
            p[b] = px[b];
}

/* n bytes from src to dst: a word at a time where both and n allow. */
static RT_INLINE void copy_bytes(uint8_t *dst, const uint8_t *src, size_t n)
{
    if ((((uintptr_t)dst | (uintptr_t)src | n) & 3u) == 0) {
        for (size_t i = 0; i < n; i += 4) {
            uint32_t v;
            __builtin_memcpy(&v, __builtin_assume_aligned(src + i, 4), 4);
            __builtin_memcpy(__builtin_assume_aligned(dst + i, 4), &v, 4);
        }
        return;
    }
    for (size_t i = 0; i < n; i++)
        dst[i] = src[i];
}

/* A pass whose blocks touch along a row (passes 1, 3, 5, 7): one row of
 * its samples, line ctx->y, each painted over its block (clipped to the
 * viewport), the row of blocks one area of band lines, the same line
 * repeated (flushed again for the lines below when the band holds fewer
 * than the blocks' height). 0 or the sink's failure. */
static int progressive_row(rt_render_ctx_t *ctx, const pass_t *ps)
{
    rt_fb_sink_t *sink = ctx->sink;
    struct rt_worker *wk = ctx->worker;
    uint32_t y = ctx->y, x_end = (uint32_t)ctx->x0 + ctx->w, x = (uint32_t)ctx->x0 + ps->ox;
    uint32_t lines = ps->bh < ctx->y_end - y ? ps->bh : ctx->y_end - y;
    unsigned bytes = rt_fb_bytes_per_pixel(PIXEL_FORMAT(sink->format));
    uint8_t *buf = sink->band[ctx->cur], px[4];
    if (!ctx->spp) {
        camera_row(&wk->cam, (int32_t)x, (int32_t)y, &wk->row);
        camera_stride(&wk->row, ps->sx);
    }
    for (; x < x_end; x += ps->sx) {
        progressive_sample(ctx, x, y, px);
        paint(buf, px, bytes, x - ctx->x0, (x + ps->bw < x_end ? x + ps->bw : x_end) - ctx->x0);
    }
    uint32_t n = lines < ctx->band_lines ? lines : (uint32_t)ctx->band_lines;
    for (uint32_t k = 1; k < n; k++)
        copy_bytes(buf + k * ctx->pitch, buf, (size_t)ctx->w * bytes);
    int status = 0;
    for (uint32_t k = 0; k < lines && status == 0; k += n) {
        uint32_t last = k + n < lines ? y + k + n - 1 : y + lines - 1;
        rt_fb_area_t area = { ctx->x0, (uint16_t)(y + k), (uint16_t)(x_end - 1), (uint16_t)last };
        status = flush_area(sink, &area, buf);
    }
    if (sink->band[1])
        ctx->cur ^= 1u;
    return status;
}

/* A pass whose blocks touch down a column (passes 2, 4, 6: blocks as
 * tall as the rows are apart): the column of blocks at ctx->x, traced top
 * down, each painted over its block (clipped), flushed as areas the
 * column's width and as many lines as a band buffer holds, packed
 * tightly (one area for the column on the Pico's panel: 280 a frame for
 * these passes' 25,200 blocks at 320x240). 0 or the sink's failure. */
static int progressive_column(rt_render_ctx_t *ctx, const pass_t *ps)
{
    rt_fb_sink_t *sink = ctx->sink;
    struct rt_worker *wk = ctx->worker;
    uint32_t x = ctx->x, x_end = (uint32_t)ctx->x0 + ctx->w;
    uint32_t w = x + ps->bw < x_end ? ps->bw : x_end - x;
    unsigned bytes = rt_fb_bytes_per_pixel(PIXEL_FORMAT(sink->format));
    size_t line = (size_t)w * bytes;
    uint32_t fit = (uint32_t)(sink->band_bytes / line); /* >= 1: w is at most the viewport's width */
    uint8_t px[4];
    camera_column_t col;
    if (!ctx->spp)
        camera_column(&wk->cam, (int32_t)x, &col);
    int status = 0;
    for (uint32_t y = ctx->y; y < ctx->y_end && status == 0;) {
        uint8_t *buf = sink->band[ctx->cur];
        uint32_t first = y, n = ctx->y_end - y < fit ? ctx->y_end - y : fit;
        for (uint32_t k = 0; k < n; k++, y++) {
            if (((y - ctx->y) & (ps->sy - 1u)) == 0) { /* a sample's line: the block's first */
                if (!ctx->spp)
                    camera_column_row(&wk->cam, &col, (int32_t)y, &wk->row);
                progressive_sample(ctx, x, y, px);
            }
            paint(buf + k * line, px, bytes, 0, w);
        }
        rt_fb_area_t area = { (uint16_t)x, (uint16_t)first, (uint16_t)(x + w - 1), (uint16_t)(y - 1) };
        status = flush_area(sink, &area, buf);
        if (sink->band[1])
            ctx->cur ^= 1u;
    }
    return status;
}

/* The next step of a progressive render: row y of the pass under way
 * (passes whose blocks touch along a row, from row to row) or its next
 * column (the others: y stays at the pass's first row while columns are
 * left); once the pass is done, the next pass (the sink told that the
 * last is on the display); y_end once the last pass is done. */
static void progressive_next(rt_render_ctx_t *ctx, uint32_t y)
{
    if (RT_PROGRESSIVE_BY_COLUMNS(ctx->pass) && ctx->x >= (uint32_t)ctx->x0 + ctx->w)
        y = ctx->y_end; /* the last column is done */
    while (y >= ctx->y_end) {
        if (ctx->sink->pass_end) {
            wait_flushed(ctx->sink);
            ctx->sink->pass_end(ctx->sink, ctx->pass);
        }
        if (ctx->pass == ctx->last_pass)
            break;
        const pass_t *ps = &passes[ctx->pass++];
        y = (uint32_t)ctx->y0 + ps->oy;
        ctx->x = (uint16_t)(ctx->x0 + ps->ox);
        if (RT_PROGRESSIVE_BY_COLUMNS(ctx->pass) && ctx->x >= (uint32_t)ctx->x0 + ctx->w)
            y = ctx->y_end; /* no column in the viewport */
    }
    ctx->y = (uint16_t)(y < ctx->y_end ? y : ctx->y_end);
}
#endif


#include "frame_setup.h"

/* The worker's counts so far into the caller's stats. */
static void add_stats(rt_render_ctx_t *ctx)
{
    rt_stats_t *part = &ctx->worker->scratch.stats;
#if RT_USE_FLAT
    if (ctx->worker->scratch.flat)
        scene_fold_stats(&ctx->worker->scratch); /* (and at each row of eye rays) */
#endif
    if (ctx->stats)
        rt_stats_add(ctx->stats, part);
    *part = (rt_stats_t){ 0 };
}

static RT_INLINE int render_step(rt_render_ctx_t *ctx, uint16_t lines)
{
    rt_fb_sink_t *sink = ctx->sink;
    int status = 0;
#if RT_USE_PROGRESSIVE
    for (; ctx->pass && lines > 0 && ctx->y < ctx->y_end; lines--) {
        const pass_t *ps = &passes[ctx->pass - 1];
        bool rows = !RT_PROGRESSIVE_BY_COLUMNS(ctx->pass);
        status = rows ? progressive_row(ctx, ps) : progressive_column(ctx, ps);
        if (status != 0) {
            ctx->y = ctx->y_end; /* done: nothing more to render */
            break;
        }
        if (!rows)
            ctx->x = (uint16_t)(ctx->x + ps->sx);
        progressive_next(ctx, rows ? (uint32_t)ctx->y + ps->sy : ctx->y);
    }
#endif
    for (; lines > 0 && ctx->y < ctx->y_end; lines--) {
        uint16_t y = ctx->y++;
        uint8_t *line = sink->band[ctx->cur] + (size_t)(y - ctx->band_y) * ctx->pitch;
#if RT_USE_SPD
        if (ctx->spd)
            spd_line(ctx, y, line);
        else
#endif
#if RT_USE_AA
        if (ctx->aa_levels)
            aa_adaptive_line(ctx, y, line);
        else if (ctx->spp)
            aa_uniform_line(ctx, y, line);
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

RT_ENTRY RT_COLD int rt_render(const scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink,
                               rt_stats_t *stats, rt_error_t *err)
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
