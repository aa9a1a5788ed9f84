/*
 * main.c - the Make project's program (examples/make): renders the scene
 * compiled into it (rt_scene: scene_data.c, from scene.nff) at the
 * scene's resolution into a binary PPM file, a band of lines at a time.
 * Hosted C (stdio), to run on the build machine; on a board the sink's
 * flush sends each band to the display instead (docs/hal.md).
 *
 *   ./app [OUT.ppm]     (scene.ppm unless given)
 */
#include <stdio.h>

#include "rt.h"
#include "scene_data.h" /* SCENE_WIDTH: the scene's resolution, for the band */

#define BAND_LINES 8

extern const rt_scene_t rt_scene; /* scene_data.c */

/* opts.width 0 renders SCENE_WIDTH pixels a line */
static uint8_t band[BAND_LINES * RT_FB_CONST_LINE_BYTES(RT_FB_RGB888, SCENE_WIDTH)];

static int begin(rt_fb_sink_t *s, uint16_t width, uint16_t height)
{
    return fprintf((FILE *)s->user, "P6\n%u %u\n255\n", (unsigned)width, (unsigned)height) > 0 ? 0 : 1;
}

static int flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *pixels)
{
    size_t n = (size_t)(a->x2 - a->x1 + 1) * (size_t)(a->y2 - a->y1 + 1) * 3u;
    int status = fwrite(pixels, 1, n, (FILE *)s->user) == n ? 0 : 1;
    rt_fb_flush_ready(s); /* written: the band is free again */
    return status;        /* a failed write ends the frame */
}

static int end(rt_fb_sink_t *s)
{
    return fflush((FILE *)s->user) == 0 ? 0 : 1;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "scene.ppm";
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        return 1;
    }
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { band, 0 }, .band_bytes = sizeof band,
                       .begin = begin, .flush = flush, .end = end, .user = f };
    rt_render_opts_t opts = { .width = 0, .height = 0 }; /* the scene's resolution; depth: RT_DEFAULT_DEPTH */
    static rt_error_t err;
    int status = rt_render(&rt_scene, &opts, &sink, NULL, &err);
    if (fclose(f) != 0 && status == 0)
        status = 1;
    if (status != 0) {
        fprintf(stderr, "%s: %s\n", path, status < 0 ? err.msg : "could not write the image");
        return 1;
    }
    return 0;
}
