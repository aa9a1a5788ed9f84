/* pixel.h - a colour packed into a line of the sink's pixel format, rounded
 * to nearest or dithered (rt_fb.h's formats). Inline: the per-pixel step
 * of every frame walk (render.c, aa.h), where a format fixed at build time
 * folds the packer to one case. */
#ifndef PIXEL_H
#define PIXEL_H

#include "rt_render.h"

#include "numeric/vec3.h"

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

#endif
