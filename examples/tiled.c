/*
 * tiled.c - a frame rendered tile by tile through a 16-line buffer.
 *
 * For a part whose RAM holds neither the frame nor a wide band: each
 * tile is a viewport of the frame (x, y, w, h) rendered on its own into
 * the same small buffer and sent on (here: copied into place), as a GUI
 * redraws a dirty rectangle. The pixels equal those of one whole-frame
 * render.
 *
 * What a user changes: TILE_W/TILE_H to fit their buffer, and put_tile()
 * to send a finished tile to the display.
 *
 *   tiled SCENE.nff OUT.ppm
 */
#include <string.h>

#include "common.h"

#define W 96
#define H 80
#define TILE_W 40 /* tiles need not divide the frame: the last ones are cut */
#define TILE_H 16

static uint8_t frame[H][W * 3];
static uint8_t tile[TILE_H * TILE_W * 3]; /* all the pixel memory the render needs */

/* Where a finished tile goes: the display, over SPI or a parallel bus. */
static int put_tile(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    size_t w = (size_t)(a->x2 - a->x1 + 1) * 3;
    for (unsigned y = a->y1; y <= a->y2; y++)
        memcpy(&frame[y][a->x1 * 3u], px + (y - a->y1) * w, w);
    rt_fb_flush_ready(s);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: tiled SCENE.nff OUT.ppm\n");
        return 2;
    }
    const rt_scene_t *sc = example_load(argv[1]);
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { tile, NULL }, .band_bytes = sizeof tile,
                          .flush = put_tile };
    unsigned tiles = 0;
    for (uint16_t y = 0; y < H; y += TILE_H)
        for (uint16_t x = 0; x < W; x += TILE_W) {
            rt_render_opts_t opts = { .width = W, .height = H };
            opts.viewport.x = x;
            opts.viewport.y = y;
            opts.viewport.w = (uint16_t)(x + TILE_W <= W ? TILE_W : W - x);
            opts.viewport.h = (uint16_t)(y + TILE_H <= H ? TILE_H : H - y);
            rt_error_t err;
            int st = rt_render(sc, &opts, &sink, NULL, &err);
            if (st != 0) {
                fprintf(stderr, "tiled: tile at %u,%u failed (%d): %s\n", x, y, st, st < 0 ? err.msg : "sink");
                return 1;
            }
            tiles++;
        }
    printf("tiled: %ux%u in %u tiles through a %u-byte buffer\n", W, H, tiles, (unsigned)sizeof tile);
    return example_write_ppm(argv[2], &frame[0][0], W, H);
}
