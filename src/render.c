/* render.c - the frame loop: eye rays per pixel, pixels packed per band. */
#include "render.h"

#include "camera.h"
#include "trace.h"

/* RT_FB_ONLY_FORMAT (a build flag, e.g. the board's): the one format the
 * build packs; the packer's switch folds to that case. */
#ifdef RT_FB_ONLY_FORMAT
#define PIXEL_FORMAT(f) ((void)(f), (fb_format_t)(RT_FB_ONLY_FORMAT))
#else
#define PIXEL_FORMAT(f) (f)
#endif

/* Pixel x of a line in format f: the one packer of every format (fb.h). */
static void put_pixel(uint8_t *line, uint16_t x, fb_format_t f, colour_t c)
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

static void wait_flushed(fb_sink_t *sink)
{
    while (sink->flushing) {
        if (sink->wait)
            sink->wait(sink);
    }
}

/* The sink's status: 0, or its failure (then no flush is in flight). */
static int flush_band(fb_sink_t *sink, unsigned *cur, uint16_t w, uint16_t y1, uint16_t y2)
{
    fb_area_t area = { 0, y1, (uint16_t)(w - 1), y2 };
    wait_flushed(sink); /* the other buffer's flush */
    sink->flushing = true;
    int status = sink->flush(sink, &area, sink->band[*cur]);
    if (status != 0) {
        sink->flushing = false;
        return status;
    }
    if (sink->band[1])
        *cur ^= 1u;
    else
        wait_flushed(sink);
    return 0;
}

#if RT_USE_SPD
/* One row of SPD corner samples (w + 1 of them). */
static void corner_row(const tracer_t *tr, const camera_t *cam, int32_t j, uint16_t w, colour_t *row)
{
    for (int32_t i = 0; i <= w; i++) {
        ray_t ray = camera_ray(cam, i, j);
        tr->stats->eye_rays++;
        row[i] = trace_ray(tr, &ray, 1, R_ONE);
    }
}

/* Line y of an SPD frame: each pixel the mean of its four corners;
 * rows[0] holds the corners above the line, rows[1] gets those below. */
static void spd_line(const tracer_t *tr, const camera_t *cam, uint16_t y, uint16_t w, colour_t *rows[2],
                     uint8_t *line, fb_format_t f)
{
    corner_row(tr, cam, y + 1, w, rows[1]);
    for (uint16_t x = 0; x < w; x++) {
        colour_t sum = c3_add(c3_add(rows[0][x], rows[0][x + 1]), c3_add(rows[1][x], rows[1][x + 1]));
        put_pixel(line, x, f, v3_scale(sum, R_RATIO(1, 4)));
    }
    colour_t *t = rows[0];
    rows[0] = rows[1];
    rows[1] = t;
}
#endif

/* Line y of a normal frame: one eye ray per pixel. */
static void plain_line(const tracer_t *tr, const camera_t *cam, uint16_t y, uint16_t w, uint8_t *line,
                       fb_format_t f)
{
    for (uint16_t x = 0; x < w; x++) {
        ray_t ray = camera_ray(cam, x, y);
        tr->stats->eye_rays++;
        put_pixel(line, x, f, trace_ray(tr, &ray, 1, R_ONE));
    }
}

RT_COLD int rt_render(const scene_t *sc, const render_opts_t *opts, fb_sink_t *sink, rt_stats_t *stats,
              rt_error_t *err)
{
    uint16_t w = opts->width ? opts->width : sc->width;
    uint16_t h = opts->height ? opts->height : sc->height;
    int depth = opts->max_depth ? opts->max_depth : RT_MAX_DEPTH;
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
#ifdef RT_FB_ONLY_FORMAT
    if (sink->format != RT_FB_ONLY_FORMAT) {
        rt_error_set(err, 0, "this build packs one pixel format only (RT_FB_ONLY_FORMAT)");
        return -1;
    }
#endif
    size_t line_bytes = RT_FB_LINE_BYTES(PIXEL_FORMAT(sink->format), w);
    if (line_bytes == 0) {
        rt_error_set(err, 0, "unknown framebuffer pixel format");
        return -1;
    }
    size_t band_lines = sink->band_bytes / line_bytes;
    if (band_lines == 0 || sink->band[0] == 0) {
        rt_error_set(err, 0, "framebuffer band buffer is smaller than one line");
        return -1;
    }
#if !RT_USE_SPD
    if (opts->spd) {
        rt_error_set(err, 0, "SPD mode is not compiled in (RT_USE_SPD = 0)");
        return -1;
    }
#else
    colour_t *rows[2] = { 0, 0 };
    if (opts->spd) {
        if (opts->scratch == 0 || opts->scratch_bytes < RENDER_SPD_SCRATCH(w)) {
            rt_error_set(err, 0, "SPD mode needs a scratch buffer of two rows of corner colours");
            return -1;
        }
        rows[0] = opts->scratch;
        rows[1] = rows[0] + w + 1;
    }
#endif
    static camera_t cam; /* static: one render at a time; keeps the stack small */
    int32_t nx = w, ny = h;
#if RT_USE_SPD
    if (opts->spd) { /* a grid of corners, one more each way */
        nx++;
        ny++;
    }
#endif
    const char *why = camera_init(&cam, &sc->view, nx, ny);
    if (why) {
        rt_error_set(err, 0, why);
        return -1;
    }
    if (sc->n_bvh_nodes > 0)
        camera_start_at_bounds(&cam, sc->bvh_nodes[0].min, sc->bvh_nodes[0].max);
    static rt_stats_t no_stats; /* stats == NULL: counted here, unread */
    if (stats == 0)
        stats = &no_stats;
    static tracer_t tr; /* static like cam */
    tr = (tracer_t){ sc, depth, stats, opts->spd, R_RATIO(opts->adaptive_milli, 1000) };

    sink->flushing = false;
    int status = sink->begin ? sink->begin(sink, w, h) : 0;
    if (status != 0)
        return status;
#if RT_USE_SPD
    if (opts->spd)
        corner_row(&tr, &cam, 0, w, rows[0]);
#endif
    unsigned cur = 0;
    uint16_t band_y = 0;
    for (uint16_t y = 0; y < h; y++) {
        uint8_t *line = sink->band[cur] + (size_t)(y - band_y) * line_bytes;
#if RT_USE_SPD
        if (opts->spd)
            spd_line(&tr, &cam, y, w, rows, line, sink->format);
        else
#endif
            plain_line(&tr, &cam, y, w, line, sink->format);
        if ((size_t)(y - band_y + 1) == band_lines || y + 1 == h) {
            status = flush_band(sink, &cur, w, band_y, y);
            if (status != 0)
                return status;
            band_y = (uint16_t)(y + 1);
        }
    }
    wait_flushed(sink);
    return sink->end ? sink->end(sink) : 0;
}
