/*
 * fb.h - the framebuffer HAL: where finished scanlines go.
 *
 * Shaped like LVGL's flush callback and Zephyr's display_write(): the core
 * fills a band of whole lines in a buffer the sink owns, hands it over with
 * flush(), and does not touch that buffer again until the sink signals
 * completion with fb_flush_ready(). A synchronous sink calls
 * fb_flush_ready() inside flush(); a DMA-driven one calls it from its
 * transfer-complete interrupt. With two band buffers the core renders into
 * one while the other is being flushed.
 *
 * Pixel formats: FB_RGB888 is 3 bytes R, G, B; FB_RGB565 is one 16-bit
 * word per pixel (R in bits 15..11), stored little-endian.
 */
#ifndef FB_H
#define FB_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum { FB_RGB888 = 0, FB_RGB565 = 1 } fb_format_t;

/* Inclusive pixel rectangle, as LVGL's lv_area_t. Bands span whole lines. */
typedef struct {
    uint16_t x1, y1, x2, y2;
} fb_area_t;

typedef struct fb_sink fb_sink_t;

struct fb_sink {
    fb_format_t format;
    uint8_t *band[2];    /* band[1] may be NULL: single buffering */
    size_t band_bytes;   /* size of each band buffer */

    /* 0 to go on; anything else aborts the frame with that status. */
    int (*begin)(fb_sink_t *s, uint16_t width, uint16_t height);
    void (*flush)(fb_sink_t *s, const fb_area_t *area, const uint8_t *pixels);
    /* Optional: idle (e.g. WFI) until fb_flush_ready(); NULL busy-waits. */
    void (*wait)(fb_sink_t *s);
    int (*end)(fb_sink_t *s);

    void *user;
    volatile bool flushing; /* owned by the core and fb_flush_ready() */
};

static inline void fb_flush_ready(fb_sink_t *s) { s->flushing = false; }

static inline unsigned fb_bytes_per_pixel(fb_format_t f) { return f == FB_RGB565 ? 2u : 3u; }

#endif
