/*
 * zephyr_display.c - the renderer on Zephyr's display API.
 *
 * Mirrors Zephyr's display_write(dev, x, y, desc, buf) with its
 * struct display_buffer_descriptor { buf_size, width, height, pitch }:
 * the sink's flush() writes each finished band at its place on the
 * display and hands the buffer straight back (display_write returns when
 * the data is taken). The sink's pitch is the descriptor's pitch; here
 * the band buffer is wider than the frame to show it.
 *
 * What a user changes: the display device (DEVICE_DT_GET of the chosen
 * zephyr,display) and the pixel format (display_get_capabilities():
 * PIXEL_FORMAT_RGB_888 here; RGB_565, L_8 and MONO are close cousins).
 * On the host, a stand-in display_write copies into memory.
 *
 *   zephyr_display SCENE.nff OUT.ppm
 */
#include <string.h>

#include "common.h"

#define W 64
#define H 64
#define PITCH_PIXELS 80 /* the buffer's line, in pixels: wider than W */

/* ---- the stand-in for Zephyr's display driver ---------------------------- */

struct display_buffer_descriptor {
    uint32_t buf_size;
    uint16_t width, height, pitch; /* pitch in pixels, as Zephyr counts it */
};
struct device {
    uint8_t fb[H][W * 3];
};

static int display_write(const struct device *dev, uint16_t x, uint16_t y,
                         const struct display_buffer_descriptor *desc, const void *buf)
{
    struct device *d = (struct device *)dev;
    const uint8_t *src = buf;
    if (x + desc->width > W || y + desc->height > H || desc->pitch < desc->width)
        return -22; /* -EINVAL */
    for (uint16_t r = 0; r < desc->height; r++)
        memcpy(&d->fb[y + r][x * 3u], src + (size_t)r * desc->pitch * 3u, (size_t)desc->width * 3u);
    return 0;
}

/* ---- the sink -------------------------------------------------------------- */

static int zephyr_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    const struct device *dev = s->user;
    struct display_buffer_descriptor desc = {
        .width = (uint16_t)(a->x2 - a->x1 + 1),
        .height = (uint16_t)(a->y2 - a->y1 + 1),
        .pitch = PITCH_PIXELS,
    };
    desc.buf_size = (uint32_t)desc.pitch * 3u * desc.height;
    int rc = display_write(dev, a->x1, a->y1, &desc, px);
    if (rc == 0)
        rt_fb_flush_ready(s); /* display_write is synchronous */
    return rc;                /* a failed write aborts the frame */
}

static struct device display;
static uint8_t band[4 * PITCH_PIXELS * 3]; /* four lines */

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: zephyr_display SCENE.nff OUT.ppm\n");
        return 2;
    }
    const rt_scene_t *sc = example_load(argv[1]);
    rt_render_opts_t opts = { .width = W, .height = H };
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { band, NULL }, .band_bytes = sizeof band,
                          .pitch = PITCH_PIXELS * 3, .flush = zephyr_flush, .user = &display };
    rt_error_t err;
    int st = rt_render(sc, &opts, &sink, NULL, &err);
    if (st != 0) {
        fprintf(stderr, "zephyr_display: render failed (%d): %s\n", st, st < 0 ? err.msg : "display_write");
        return 1;
    }
    printf("zephyr_display: %ux%u through display_write, a 4-line band, pitch %u pixels\n", W, H, PITCH_PIXELS);
    return example_write_ppm(argv[2], &display.fb[0][0], W, H);
}
