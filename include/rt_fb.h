/*
 * rt_fb.h - the framebuffer HAL: where finished scanlines go.
 *
 * Shaped like LVGL's flush callback and Zephyr's display_write(): the core
 * fills a band of whole lines in a buffer the sink owns, hands it over with
 * flush(), and does not touch that buffer again until the sink signals
 * completion with rt_fb_flush_ready(). A synchronous sink calls
 * rt_fb_flush_ready() inside flush(); a DMA-driven one calls it from its
 * transfer-complete interrupt. With two band buffers the core renders into
 * one while the other is being flushed.
 *
 * Pixel formats: one list, RT_FB_FORMATS below; the core packs them
 * (src/tracer/pixel.h), rt_fb_expand() turns any of them back into 8-bit R, G, B
 * (the host's image writer and UART stream decoder use it).
 */
#ifndef RT_FB_H
#define RT_FB_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* X(ID, name, value, bits per pixel). Values are stable: the board's UART
 * stream carries them.
 *   RGB888    3 bytes R, G, B.
 *   RGB565    16-bit word, R in bits 15..11, G 10..5, B 4..0, stored
 *             little-endian (low byte first).
 *   RGB565BE  the same word stored big-endian (high byte first), as SPI
 *             panels (ST7789, ILI9341) take it.
 *   XRGB8888  32-bit word 0x00RRGGBB stored little-endian: bytes B, G, R, 0.
 *   L8        8-bit grey, luma = (77 R + 150 G + 29 B + 128) >> 8
 *             (integer Rec.601 weights, which sum to 256).
 *   L4        4-bit grey (L8 scaled to 0..15, rounded), two pixels per
 *             byte, the left pixel in the high nibble (SSD0323 OLEDs); an
 *             odd width leaves the low nibble of each line's last byte 0.
 * 565 channels and L4 are rounded to nearest: v * max / 255 (or dithered:
 * the sink's `dither`). */
#define RT_FB_FORMATS(X)                         \
    X(RT_FB_RGB888, "rgb888", 0, 24)             \
    X(RT_FB_RGB565, "rgb565", 1, 16)             \
    X(RT_FB_RGB565BE, "rgb565be", 2, 16)         \
    X(RT_FB_XRGB8888, "xrgb8888", 3, 32)         \
    X(RT_FB_L8, "l8", 4, 8)                      \
    X(RT_FB_L4, "l4", 5, 4)

#define RT_FB_ENUM_(id, name, value, bits) id = value,
typedef enum {
    RT_FB_FORMATS(RT_FB_ENUM_)
} rt_fb_format_t;
#undef RT_FB_ENUM_

#define RT_FB_COUNT_(id, name, value, bits) +1
#define RT_FB_N_FORMATS (0 RT_FB_FORMATS(RT_FB_COUNT_))

/* Bits per pixel of format f (0: not a format). */
static inline unsigned rt_fb_bits(rt_fb_format_t f)
{
#define RT_FB_ROW_(id, name, value, bits) [value] = bits,
    static const uint8_t bits[] = { RT_FB_FORMATS(RT_FB_ROW_) };
#undef RT_FB_ROW_
    return (unsigned)f < sizeof bits ? bits[f] : 0u;
}
/* Bytes of one line of w pixels, tightly packed. */
#define RT_FB_LINE_BYTES(f, w) (((size_t)(w) * rt_fb_bits(f) + 7) / 8)

/* The same as constant expressions, for a format named by its ID (or a
 * macro expanding to one): RT_FB_CONST_LINE_BYTES(RT_FB_L4, 64) is 32. */
#define RT_FB_BITS_ENUM_(id, name, value, bits) id##_BITS_ = bits,
enum { RT_FB_FORMATS(RT_FB_BITS_ENUM_) };
#undef RT_FB_BITS_ENUM_
#define RT_FB_CONST_BITS_(id) id##_BITS_
#define RT_FB_CONST_BITS(id) RT_FB_CONST_BITS_(id)
#define RT_FB_CONST_LINE_BYTES(id, w) (((size_t)(w) * RT_FB_CONST_BITS(id) + 7) / 8)

/* Inclusive pixel rectangle, as LVGL's lv_area_t: x1..x2 and y1..y2 are
 * all in it, x2 - x1 + 1 pixels by y2 - y1 + 1 lines, in frame
 * coordinates. Bands span whole lines (of the viewport, when one is set),
 * but for progressive display's columns of blocks (rt_render.h), whose
 * lines are packed tightly. */
typedef struct {
    uint16_t x1, y1, x2, y2;
} rt_fb_area_t;

typedef struct rt_fb_sink rt_fb_sink_t;

struct rt_fb_sink {
    rt_fb_format_t format;
    uint8_t *band[2];    /* band[1] may be NULL: single buffering */
    size_t band_bytes;   /* size of each band buffer: band_bytes / pitch whole
                          * lines a band, at least one line of the width
                          * rendered (opts.width; 0: the scene's, SCENE_WIDTH
                          * in the scene compiler's scene_data.h) */
    size_t pitch;        /* bytes from one line to the next in a band;
                          * 0: tightly packed (RT_FB_LINE_BYTES) */
    /* Ordered dithering (RT_USE_DITHER) of the formats with fewer than 8
     * bits a channel (565, L4) and of L8's luma: each pixel rounds at the
     * threshold of a 4x4 Bayer matrix by its frame position instead of
     * at one half, so smooth shading shows no bands. false: round to
     * nearest (the default). */
    bool dither;

    /* begin and flush: 0 to go on; anything else aborts the frame, and
     * rt_render returns that status without calling end() (a sink that
     * must clean up does it before returning the failure). A flush that
     * fails must not have started a transfer: the core takes the buffer
     * back (clears `flushing`) and flushes nothing more. */
    int (*begin)(rt_fb_sink_t *s, uint16_t width, uint16_t height);
    int (*flush)(rt_fb_sink_t *s, const rt_fb_area_t *area, const uint8_t *pixels);
    /* Optional: idle (e.g. WFI) until rt_fb_flush_ready(); NULL busy-waits. */
    void (*wait)(rt_fb_sink_t *s);
    int (*end)(rt_fb_sink_t *s);
    /* Optional, progressive display (rt_render_opts_t.progressive): pass
     * `pass` (1..RT_PROGRESSIVE_PASSES) of the render is on the display,
     * its last flush done. NULL: nothing to do. */
    void (*pass_end)(rt_fb_sink_t *s, unsigned pass);

    void *user;
    volatile bool flushing; /* owned by the core and rt_fb_flush_ready() */
};

static inline void rt_fb_flush_ready(rt_fb_sink_t *s) { s->flushing = false; }

/* Whole bytes per pixel (L4: 0, two pixels share a byte); prefer
 * RT_FB_LINE_BYTES. */
static inline unsigned rt_fb_bytes_per_pixel(rt_fb_format_t f) { return rt_fb_bits(f) / 8u; }

/* Pixel x of a line in format f as 8-bit R, G, B: 565 channels expanded by
 * rounding (v * 255 / max), grey as R = G = B, L4 as v * 17. */
static inline void rt_fb_expand(rt_fb_format_t f, const uint8_t *line, size_t x, uint8_t rgb[3])
{
    unsigned v;
    switch (f) {
    case RT_FB_RGB888:
        line += 3 * x;
        rgb[0] = line[0];
        rgb[1] = line[1];
        rgb[2] = line[2];
        return;
    case RT_FB_XRGB8888:
        line += 4 * x;
        rgb[0] = line[2];
        rgb[1] = line[1];
        rgb[2] = line[0];
        return;
    case RT_FB_RGB565:
    case RT_FB_RGB565BE:
        line += 2 * x;
        v = f == RT_FB_RGB565 ? (unsigned)line[0] | (unsigned)line[1] << 8
                              : (unsigned)line[1] | (unsigned)line[0] << 8;
        rgb[0] = (uint8_t)(((v >> 11) * 255 + 15) / 31);
        rgb[1] = (uint8_t)((((v >> 5) & 63) * 255 + 31) / 63);
        rgb[2] = (uint8_t)(((v & 31) * 255 + 15) / 31);
        return;
    case RT_FB_L8:
        v = line[x];
        break;
    default: /* RT_FB_L4 */
        v = (x & 1 ? line[x >> 1] & 15u : (unsigned)line[x >> 1] >> 4) * 17u;
        break;
    }
    rgb[0] = rgb[1] = rgb[2] = (uint8_t)v;
}

#endif
