/* aa.h - anti-aliasing: a pixel as the mean of samples of its area,
 * uniform (spp x spp cell centres) or adaptive (squares of cell corners
 * split where their colours spread), a line at a time for render.c's row
 * walk. Part of render.c's unit, as pixel.h and frame_setup.h are: in an
 * object of its own, the whole-program firmware came out otherwise (the
 * float build's code +16 bytes, its instructions +1.1%). */
#ifndef AA_H
#define AA_H

#include "frame.h"
#include "pixel.h"

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
static colour_t aa_uniform_pixel(const rt_render_ctx_t *ctx, uint32_t x, uint32_t y)
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
static void aa_uniform_line(const rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
{
    for (uint16_t x = 0; x < ctx->w; x++)
        put_pixel(line, x, ctx->sink->format, aa_uniform_pixel(ctx, ctx->x0 + x, y), dither_at(ctx, ctx->x0 + x, y));
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

/* A pixel's split decisions (rt_render.h, RT_AA_SPLIT_BITS): `words` NULL
 * for none, else recorded into or, if `replay`, replayed from them. Only
 * builds with RT_AA_REPLAY keep any: elsewhere each decision is its test. */
typedef struct {
    uint32_t *words;
    bool replay;
} aa_decisions_t;

/* Decision `bit`: the recorded one when replaying, else `test`'s (noted
 * when recording). */
static RT_INLINE bool aa_decide(aa_decisions_t *d, unsigned bit, bool test)
{
    if (!RT_AA_REPLAY || !d->words)
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

/* The split decisions of frame pixel (x, y): the frame's words for it,
 * cleared to record, or none. */
static RT_INLINE aa_decisions_t pixel_decisions(const struct rt_worker *wk, uint32_t x, uint32_t y)
{
#if RT_AA_REPLAY
    aa_decisions_t dec = { NULL, wk->splits_replay };
    if (wk->splits) {
        dec.words = wk->splits + y * wk->splits_line + (size_t)x * wk->split_words;
        for (unsigned k = 0; !dec.replay && k < wk->split_words; k++)
            dec.words[k] = 0;
    }
    return dec;
#else
    (void)wk, (void)x, (void)y;
    return (aa_decisions_t){ NULL, false };
#endif
}

/* The pixel of grid g, its cell corners traced as they are first needed
 * (docs/shading-model.md, "Adaptive anti-aliasing"). A square whose corners spread over the threshold
 * (times 4 a level: a square's share of the pixel is 4 times smaller)
 * gets its centre traced; it is split in four unless the centre lies
 * within half that of the corners' mean (the colour is close to
 * bilinear: a gradient, not an edge), when it counts as the mean of
 * corners and centre. Squares wait on a small stack (three siblings a
 * level), so no recursion adds to trace_ray's frames. */
static colour_t aa_pixel(struct rt_worker *wk, aa_grid_t *g, unsigned levels, aa_decisions_t *dec)
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
        unsigned bit = level < levels ? AA_SQUARE_BIT(x, y, size, level) : 0;
        if (level < levels && aa_decide(dec, bit, spread_over(*c[0], *c[1], *c[2], *c[3], limit))) {
            colour_t m4 = v3_scale(*aa_corner(wk, g, x + half, y + half), r_from_int(4));
            colour_t off = v3_sub(m4, corners); /* 4 (centre - mean) */
            real_t near = 2 * limit;            /* 4 (limit / 2) */
            if (aa_decide(dec, bit + 1, r_abs(off.x) > near || r_abs(off.y) > near || r_abs(off.z) > near)) {
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
static void aa_adaptive_line(rt_render_ctx_t *ctx, uint16_t y, uint8_t *line)
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
        aa_decisions_t dec = pixel_decisions(wk, (uint32_t)ctx->x0 + x, y);
        colour_t c = aa_pixel(wk, &g, levels, &dec);
        put_pixel(line, x, ctx->sink->format, c, dither_at(ctx, ctx->x0 + x, y));
    }
    ctx->rows[1] = ctx->rows[0];
    ctx->rows[0] = below;
}
#endif

#endif
