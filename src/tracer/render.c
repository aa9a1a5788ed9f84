/* render.c - the frame loop: eye rays per pixel, pixels packed per band. */
#include "rt_render.h"

#include "geometry/camera.h"
#include "geometry/scene_hit.h"
#include "trace.h"

/* RT_FB_ONLY_FORMAT (a build flag, e.g. the board's): the one format the
 * build packs; the packer's switch folds to that case. */
#ifdef RT_FB_ONLY_FORMAT
#define PIXEL_FORMAT(f) ((void)(f), (rt_fb_format_t)(RT_FB_ONLY_FORMAT))
#else
#define PIXEL_FORMAT(f) (f)
#endif

/* Rounding to one of n + 1 levels: 8-bit v rounds up from d / 32 of a
 * step. d = 16 is rounding to nearest (exactly (v n + 127) / 255: the
 * format's own rounding), other d dither (dither_at). */
#define ROUND_NEAREST 16u
static RT_INLINE unsigned round_at(unsigned v, unsigned n, unsigned d) { return (v * n * 32u + 255u * d) / (255u * 32u); }

/* Pixel x of a line in format f: the one packer of every format (rt_fb.h),
 * rounding at threshold d (ROUND_NEAREST, or dither_at's). */
static RT_INLINE void put_pixel(uint8_t *line, uint16_t x, rt_fb_format_t f, colour_t c, unsigned d)
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
        w = round_at(r, 31, d) << 11 | round_at(g, 63, d) << 5 | round_at(b, 31, d);
        if (PIXEL_FORMAT(f) == RT_FB_RGB565BE)
            w = (w >> 8 | w << 8) & 0xFFFFu;
        px[0] = (uint8_t)w;
        px[1] = (uint8_t)(w >> 8);
        break;
    default: /* RT_FB_L8, RT_FB_L4 */
        l = 77u * r + 150u * g + 29u * b; /* luma times 256 */
        if (PIXEL_FORMAT(f) == RT_FB_L8)
            l = (l + 8u * d) >> 8;
        else if (d == ROUND_NEAREST) /* L4: L8 rounded to 0..15 */
            l = round_at((l + 128u) >> 8, 15, d);
        else /* dithered from the exact luma */
            l = (l * 15u * 32u + 65280u * d) / (65280u * 32u);
        if (PIXEL_FORMAT(f) == RT_FB_L8) {
            line[x] = (uint8_t)l;
        } else {
            px = line + (x >> 1);
            /* the left pixel's write clears the right one's nibble */
            *px = x & 1u ? (uint8_t)(*px | l) : (uint8_t)(l << 4);
        }
        break;
    }
}

#if RT_USE_DITHER
/* A 4x4 Bayer matrix: pixel (x, y) rounds up from (2 m + 1) / 32 of a
 * step, m = bayer4[y % 4][x % 4]; its mean is one half, the threshold of
 * rounding to nearest. */
static const uint8_t bayer4[4][4] = { { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 } };
#endif

/* The rounding threshold of frame pixel (x, y) for ctx's sink. */
static RT_INLINE unsigned dither_at(const rt_render_ctx_t *ctx, uint32_t x, uint32_t y)
{
#if RT_USE_DITHER
    return ctx->sink->dither ? 2u * bayer4[y & 3u][x & 3u] + 1u : ROUND_NEAREST;
#else
    (void)ctx, (void)x, (void)y;
    return ROUND_NEAREST;
#endif
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
    camera_row_t row; /* the row of eye rays being made: off the stack */
    tracer_t tr;
    prim_ref_t last_blocker[RT_MAX_LIGHTS];
    material_terms_t terms[RT_MAX_DEPTH];
    ray_scratch_t scratch;
#if RT_USE_AA
    real_t aa_threshold; /* adaptive: a corner spread that splits a square */
    real_t aa_scale;     /* 1 / (corners or samples a pixel sums) */
#if RT_AA_REPLAY
    uint32_t *splits;    /* the frame's split decisions (opts.aa_splits), or NULL */
    size_t splits_line;  /* words a frame line */
    unsigned split_words; /* words a pixel */
    bool splits_replay;  /* replayed, not recorded */
#endif
#endif
};
static struct rt_worker workers[RT_MAX_WORKERS];

/* The sample of the eye ray about to be traced (camera.h's offsets), for
 * the flat search's culling (scene_eye_setup). */
static RT_INLINE void eye_sample(struct rt_worker *wk, int32_t k, int32_t m)
{
#if RT_USE_FLAT
    wk->scratch.eye_k = k;
    wk->scratch.eye_m = m;
#else
    (void)wk, (void)k, (void)m;
#endif
}

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

#if RT_USE_AA
/* Anti-aliasing: samples of the pixel-area image (docs/shading-model.md),
 * each clamped to [0, 1] before it is averaged. The camera's samples are
 * the corners of cells, 2^levels (adaptive) or 2 spp (uniform, whose
 * samples are every other corner: the cells' centres) to a pixel side. */
static real_t clamp_unit(real_t c) { return c > 0 ? (c < R_ONE ? c : R_ONE) : 0; }

/* Sample (i, j), whose spacing to its neighbours at its level is 2^shift
 * cells: its eye ray's cone spreads 2^shift times the camera's. */
static colour_t aa_sample(struct rt_worker *wk, int32_t i, int32_t j, unsigned shift)
{
    eye_sample(wk, 2 * i - wk->cam.cx, 2 * j - wk->cam.cy);
    ray_t ray = camera_ray(&wk->cam, i, j);
#if RT_RAY_CONES
    ray.cone_spread *= (int32_t)1 << shift; /* exact: a power of two */
    ray.cone_width *= (int32_t)1 << shift;
#else
    (void)shift;
#endif
    wk->scratch.stats.eye_rays++;
    colour_t c = trace_ray(&wk->tr, &ray, 1, R_ONE);
    return v3(clamp_unit(c.x), clamp_unit(c.y), clamp_unit(c.z));
}

/* Frame pixel (x, y), uniform: the mean of its spp x spp cell centres. */
static colour_t uniform_pixel(const rt_render_ctx_t *ctx, uint32_t x, uint32_t y)
{
    struct rt_worker *wk = ctx->worker;
    int32_t n = ctx->spp, sub = 2 * n;
    colour_t sum = v3(0, 0, 0);
    for (int32_t b = 0; b < n; b++)
        for (int32_t a = 0; a < n; a++)
            sum = v3_add(sum, aa_sample(wk, sub * (int32_t)x + 2 * a + 1, sub * (int32_t)y + 2 * b + 1, 1));
    return v3_scale(sum, wk->aa_scale);
}

/* Line y, uniform. */
static void uniform_line(const rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    for (uint16_t x = 0; x < ctx->w; x++)
        put_pixel(line, x, ctx->sink->format, uniform_pixel(ctx, ctx->x0 + x, y), dither_at(ctx, ctx->x0 + x, y));
}

/* A cell corner not traced yet (traced ones are clamped to [0, 1]). */
#define NOT_TRACED (-R_ONE)

/* Row j of cell corners x0 << levels .. (x0 + w) << levels: the pixel
 * corners traced, the others not yet. */
static void aa_corner_row(struct rt_worker *wk, int32_t j, uint16_t x0, uint16_t w, unsigned levels, colour_t *row)
{
    for (uint32_t i = 0; i <= (uint32_t)w << levels; i++)
        row[i].x = NOT_TRACED;
    for (uint32_t i = 0; i <= w; i++)
        row[i << levels] = aa_sample(wk, (int32_t)(x0 + i) << levels, j, levels);
}

/* The largest difference of one channel among four corners. */
static real_t spread(real_t a, real_t b, real_t c, real_t d)
{
    real_t hi = a, lo = a;
    hi = b > hi ? b : hi, lo = b < lo ? b : lo;
    hi = c > hi ? c : hi, lo = c < lo ? c : lo;
    hi = d > hi ? d : hi, lo = d < lo ? d : lo;
    return hi - lo;
}

/* One pixel's cell corners: its upper and lower edges are in the corner
 * rows, the 2^levels - 1 rows between in `mid` (2^levels + 1 each). */
typedef struct {
    colour_t *top, *bottom, *mid;
    unsigned sub;  /* cells a side */
    int32_t i, j;  /* the camera's sample index of the top left corner */
    bool dirty;    /* a corner of mid traced since mid was last cleared */
} aa_grid_t;

/* The level of corner (x, y) of a pixel of sub cells a side: its spacing
 * in the coarsest grid of squares that has it, 2^shift cells (sub: the
 * pixel's corners). By position alone, so the same wherever it is traced. */
static unsigned corner_shift(unsigned x, unsigned y, unsigned sub)
{
    unsigned shift = 0;
#if RT_RAY_CONES
    unsigned m = x | y | sub;
    while (!(m >> shift & 1u))
        shift++;
#else
    (void)x, (void)y, (void)sub; /* no cones to spread */
#endif
    return shift;
}

/* Corner (x, y) of the pixel, traced if it is not yet. */
static const colour_t *aa_corner(struct rt_worker *wk, aa_grid_t *p, unsigned x, unsigned y)
{
    colour_t *c = y == 0 ? &p->top[x] : y == p->sub ? &p->bottom[x] : &p->mid[(y - 1) * (p->sub + 1) + x];
    if (c->x < 0) {
        *c = aa_sample(wk, p->i + (int32_t)x, p->j + (int32_t)y, corner_shift(x, y, p->sub));
        p->dirty |= y != 0 && y != p->sub;
    }
    return c;
}

/* Whether a channel of a, b, c, d spreads over more than t. */
static bool spread_over(colour_t a, colour_t b, colour_t c, colour_t d, real_t t)
{
    return spread(a.x, b.x, c.x, d.x) > t || spread(a.y, b.y, c.y, d.y) > t || spread(a.z, b.z, c.z, d.z) > t;
}

#if RT_AA_REPLAY
/* A pixel's split decisions (rt_render.h, RT_AA_SPLIT_BITS): `words` NULL
 * for none, else recorded into or, if `replay`, replayed from them. */
typedef struct {
    uint32_t *words;
    bool replay;
} aa_decisions_t;

/* Decision `bit`: the recorded one when replaying, else `test`'s (noted
 * when recording). */
static bool aa_decide(aa_decisions_t *d, unsigned bit, bool test)
{
    if (!d->words)
        return test;
    uint32_t mask = (uint32_t)1 << (bit & 31u);
    if (d->replay)
        return (d->words[bit >> 5] & mask) != 0;
    if (test)
        d->words[bit >> 5] |= mask;
    return test;
}
/* Bit 2 q of the square at (x, y) cells, `size` cells a side, of level `level`. */
#define AA_SQUARE_BIT(x, y, size, level) \
    (2u * ((((1u << (2u * (level))) - 1u) / 3u) + ((y) / (size) << (level)) + (x) / (size)))
#define AA_DECIDE(bit, test) aa_decide(dec, (bit), (test))
#else
#define AA_DECIDE(bit, test) (test)
#endif

/* The pixel of grid g, its cell corners traced as they are first needed
 * (docs/shading-model.md, "Adaptive anti-aliasing"). A square whose corners spread over the threshold
 * (times 4 a level: a square's share of the pixel is 4 times smaller)
 * gets its centre traced; it is split in four unless the centre lies
 * within half that of the corners' mean (the colour is close to
 * bilinear: a gradient, not an edge), when it counts as the mean of
 * corners and centre. Squares wait on a small stack (three siblings a
 * level), so no recursion adds to trace_ray's frames. */
#if RT_AA_REPLAY
static colour_t aa_pixel(struct rt_worker *wk, aa_grid_t *g, unsigned levels, aa_decisions_t *dec)
#else
static colour_t aa_pixel(struct rt_worker *wk, aa_grid_t *g, unsigned levels)
#endif
{
    struct {
        uint8_t x, y, level;
    } todo[3 * RT_AA_MAX_LEVELS + 1];
    unsigned n_todo = 1, sub = 1u << levels;
    todo[0].x = todo[0].y = todo[0].level = 0;
    colour_t sum = v3(0, 0, 0);
    while (n_todo > 0) {
        n_todo--;
        unsigned x = todo[n_todo].x, y = todo[n_todo].y, level = todo[n_todo].level, size = sub >> level;
        unsigned half = size / 2;
        const colour_t *c[4];
        for (unsigned k = 0; k < 4; k++)
            c[k] = aa_corner(wk, g, x + (k & 1u) * size, y + (k >> 1) * size);
        colour_t corners = v3_add(v3_add(*c[0], *c[1]), v3_add(*c[2], *c[3])); /* 4 times their mean */
        real_t limit = wk->aa_threshold * ((int32_t)1 << (2 * level));
#if RT_AA_REPLAY
        unsigned bit = level < levels ? AA_SQUARE_BIT(x, y, size, level) : 0;
#endif
        if (level < levels && AA_DECIDE(bit, spread_over(*c[0], *c[1], *c[2], *c[3], limit))) {
            colour_t m4 = v3_scale(*aa_corner(wk, g, x + half, y + half), r_from_int(4));
            colour_t off = v3_sub(m4, corners); /* 4 (centre - mean) */
            real_t near = 2 * limit;            /* 4 (limit / 2) */
            if (AA_DECIDE(bit + 1, r_abs(off.x) > near || r_abs(off.y) > near || r_abs(off.z) > near)) {
                wk->scratch.stats.aa_splits++;
                for (unsigned k = 0; k < 4; k++) {
                    todo[n_todo].x = (uint8_t)(x + (k & 1u) * half);
                    todo[n_todo].y = (uint8_t)(y + (k >> 1) * half);
                    todo[n_todo].level = (uint8_t)(level + 1);
                    n_todo++;
                }
                continue;
            }
            corners = v3_scale(v3_add(corners, m4), R_RATIO(1, 2));
        }
        /* 4 times the square's mean times its share, 4^(levels - level) of 4^levels cells */
        int32_t cells = (int32_t)1 << (2 * (levels - level));
        sum = v3_add(sum, v3(corners.x * cells, corners.y * cells, corners.z * cells));
    }
    return v3_scale(sum, wk->aa_scale);
}

/* Line y, adaptive: rows[0] holds the cell corners on the line's upper
 * edge, rows[1] gets those of its lower edge (traced once, shared by the
 * pixels above and below); a pixel's left edge is its left neighbour's
 * right one, and its inner corners are cleared only when some were
 * traced. */
static void adaptive_line(rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    struct rt_worker *wk = ctx->worker;
    unsigned levels = ctx->aa_levels, sub = 1u << levels, n = sub + 1;
    colour_t *above = ctx->rows[0], *below = ctx->rows[1];
    aa_grid_t g = { .mid = ctx->cells, .sub = sub, .j = (int32_t)y << levels, .dirty = true };
    aa_corner_row(wk, (int32_t)(y + 1) << levels, ctx->x0, ctx->w, levels, below);
    for (uint16_t x = 0; x < ctx->w; x++) {
        for (unsigned r = 0; r + 1 < sub; r++)
            g.mid[r * n] = x > 0 ? g.mid[r * n + sub] : v3(NOT_TRACED, 0, 0);
        if (g.dirty) {
            for (unsigned r = 0; r + 1 < sub; r++)
                for (unsigned k = 1; k <= sub; k++)
                    g.mid[r * n + k].x = NOT_TRACED;
            g.dirty = false;
        }
        g.top = above + x * sub;
        g.bottom = below + x * sub;
        g.i = (int32_t)(ctx->x0 + x) << levels;
#if RT_AA_REPLAY
        aa_decisions_t dec = { NULL, wk->splits_replay };
        if (wk->splits) { /* the frame pixel's words; cleared to record */
            dec.words = wk->splits + y * wk->splits_line + (size_t)(ctx->x0 + x) * wk->split_words;
            for (unsigned k = 0; !dec.replay && k < wk->split_words; k++)
                dec.words[k] = 0;
        }
        colour_t c = aa_pixel(wk, &g, levels, &dec);
#else
        colour_t c = aa_pixel(wk, &g, levels);
#endif
        put_pixel(line, x, ctx->sink->format, c, dither_at(ctx, ctx->x0 + x, y));
    }
    ctx->rows[1] = ctx->rows[0];
    ctx->rows[0] = below;
}
#endif

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
#define TILE 8 /* the lattice's period: a viewport's edges lie on it */

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
        return uniform_pixel(ctx, x, y);
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

/* Whether the options record or replay split decisions (RT_AA_REPLAY). */
#if RT_AA_REPLAY
#define SPLITS_ASKED(opts) ((opts)->aa_splits_mode != RT_AA_SPLITS_OFF)
#else
#define SPLITS_ASKED(opts) false
#endif

/* The bodies of rt_render_begin, _step and _end, inlined into them and
 * into rt_render: a build that only calls rt_render (the board) links one
 * function, as small as a single loop. */
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
#if RT_USE_PROGRESSIVE
    ctx->y0 = vp.y;
#endif
    ctx->cur = 0;
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
            adaptive_line(ctx, y, line);
        else if (ctx->spp)
            uniform_line(ctx, y, line);
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
