/*
 * lvgl_flush.c - the renderer behind an LVGL-style flush callback, with a
 * DMA transfer, its completion interrupt and two band buffers.
 *
 * Mirrors LVGL's display driver: flush_cb(disp, area, px_map) starts the
 * transfer of an area to the panel and returns; the DMA-complete
 * interrupt calls lv_display_flush_ready(disp). Here the sink's flush()
 * is the flush_cb, rt_fb_flush_ready() is lv_display_flush_ready(), and
 * the renderer fills the second band buffer while the first one is on
 * the wire. The panel is an SPI one (ST7789-like), so the pixels are
 * RGB565 big-endian. The frame is rendered a few lines per pass of the
 * application's main loop (rt_render_step), as a UI task would.
 *
 * What a user changes: spi_dma_start() and the interrupt handler (the
 * panel's window commands and the DMA channel), the band size, the
 * format. On the host the "DMA" copies into a panel framebuffer and its
 * "interrupt" fires from the sink's wait hook.
 *
 *   lvgl_flush SCENE.nff OUT.ppm [W H]
 */
#include <string.h>

#include "common.h"

#define BAND_LINES 8
#define MAX_W 256
#define MAX_H 256

/* ---- the panel and its DMA (the part a board replaces) ------------------ */

static uint8_t panel[MAX_H][MAX_W * 2]; /* what the ST7789's GRAM would hold */

static struct {
    rt_fb_sink_t *sink;   /* whom to tell when the transfer is done */
    const uint8_t *src;
    rt_fb_area_t area;
    size_t pitch;
    int busy;
} dma;

/* Start the transfer of an area (the CASET/RASET window, then the data). */
static void spi_dma_start(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px, size_t pitch)
{
    dma.sink = s;
    dma.src = px;
    dma.area = *a;
    dma.pitch = pitch;
    dma.busy = 1;
}

/* The DMA-complete interrupt: on a board, the DMA controller's IRQ handler. */
static void dma_complete_irq(void)
{
    if (!dma.busy)
        return;
    size_t w = (size_t)(dma.area.x2 - dma.area.x1 + 1) * 2;
    for (unsigned y = dma.area.y1; y <= dma.area.y2; y++)
        memcpy(&panel[y][dma.area.x1 * 2u], dma.src + (y - dma.area.y1) * dma.pitch, w);
    dma.busy = 0;
    rt_fb_flush_ready(dma.sink); /* lv_display_flush_ready(disp) */
}

/* ---- the sink: LVGL's flush_cb ------------------------------------------ */

static int flush_cb(rt_fb_sink_t *s, const rt_fb_area_t *area, const uint8_t *px_map)
{
    spi_dma_start(s, area, px_map, RT_FB_LINE_BYTES(s->format, area->x2 - area->x1 + 1));
    return 0; /* returns at once; the interrupt says when the buffer is free */
}

/* The core waits here for a busy buffer: a board would WFI; on the host
 * the "interrupt" fires now. */
static void wait_for_irq(rt_fb_sink_t *s)
{
    (void)s;
    dma_complete_irq();
}

static uint8_t band_a[BAND_LINES * MAX_W * 2], band_b[BAND_LINES * MAX_W * 2];

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 5) {
        fprintf(stderr, "usage: lvgl_flush SCENE.nff OUT.ppm [W H]\n");
        return 2;
    }
    const rt_scene_t *sc = example_load(argv[1]);
    rt_render_opts_t opts = { .width = 64, .height = 64 };
    if (argc == 5) {
        opts.width = (uint16_t)atoi(argv[3]);
        opts.height = (uint16_t)atoi(argv[4]);
    }
    if (opts.width < 1 || opts.width > MAX_W || opts.height < 1 || opts.height > MAX_H) {
        fprintf(stderr, "lvgl_flush: size 1x1 to %dx%d\n", MAX_W, MAX_H);
        return 2;
    }
    rt_fb_sink_t sink = { .format = RT_FB_RGB565BE, .band = { band_a, band_b }, .band_bytes = sizeof band_a,
                          .flush = flush_cb, .wait = wait_for_irq };
    rt_error_t err;
    rt_render_ctx_t ctx;
    int st = rt_render_begin(&ctx, sc, &opts, &sink, NULL, &err);
    unsigned passes = 0;
    while (st == 0 && !rt_render_done(&ctx)) {
        st = rt_render_step(&ctx, 2); /* two lines, then the rest of the UI loop */
        passes++;
        dma_complete_irq();            /* the interrupt may fire between passes */
    }
    if (st == 0)
        st = rt_render_end(&ctx);
    if (st != 0) {
        fprintf(stderr, "lvgl_flush: render failed (%d): %s\n", st, st < 0 ? err.msg : "sink");
        return 1;
    }
    /* The panel as 8-bit RGB, to check it against the reference. */
    static unsigned char rgb[MAX_W * MAX_H * 3];
    for (unsigned y = 0; y < opts.height; y++)
        for (unsigned x = 0; x < opts.width; x++)
            rt_fb_expand(RT_FB_RGB565BE, panel[y], x, &rgb[(y * opts.width + x) * 3]);
    printf("lvgl_flush: %ux%u in %u passes of the main loop\n", (unsigned)opts.width, (unsigned)opts.height,
           passes);
    return example_write_ppm(argv[2], rgb, opts.width, opts.height);
}
