/*
 * main.c - a user's program: render the compiled-in scene at its own
 * resolution into a sink that writes a binary PPM through out_write()
 * (out_host.c: stdout; out_mps2.c: the board's UART0). Includes rt.h and
 * the scene compiler's scene_data.h, for the size of the band buffer.
 */
#include "rt.h"
#include "scene_data.h" /* SCENE_WIDTH, SCENE_HEIGHT: the scene's resolution */

#define BAND_LINES 4

extern const rt_scene_t rt_scene;         /* rt_add_scene: scene_data.c */
int out_write(const void *p, size_t n); /* 0 on success */

/* opts.width 0 renders SCENE_WIDTH pixels a line */
static uint8_t band[BAND_LINES * RT_FB_CONST_LINE_BYTES(RT_FB_RGB888, SCENE_WIDTH)];
static int out_status;

static char *put_uint(char *p, unsigned v)
{
    char digits[5];
    int n = 0;
    do
        digits[n++] = (char)('0' + v % 10);
    while ((v /= 10) != 0);
    while (n > 0)
        *p++ = digits[--n];
    return p;
}

static int begin(rt_fb_sink_t *s, uint16_t width, uint16_t height)
{
    (void)s;
    char header[24] = "P6\n", *p = header + 3;
    p = put_uint(p, width);
    *p++ = ' ';
    p = put_uint(p, height);
    for (const char *q = "\n255\n"; *q; q++)
        *p++ = *q;
    return out_write(header, (size_t)(p - header));
}

static int flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *pixels)
{
    size_t n = (size_t)(a->x2 - a->x1 + 1) * (size_t)(a->y2 - a->y1 + 1) * 3u;
    out_status = out_write(pixels, n);
    rt_fb_flush_ready(s); /* synchronous: the band is free again */
    return out_status;    /* a failed write ends the frame */
}

static int end(rt_fb_sink_t *s)
{
    (void)s;
    return out_status;
}

int main(void)
{
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { band, 0 }, .band_bytes = sizeof band,
                       .begin = begin, .flush = flush, .end = end };
    rt_render_opts_t opts = { .width = 0, .height = 0 }; /* the scene's resolution; depth: RT_DEFAULT_DEPTH */
    static rt_error_t err;
    return rt_render(&rt_scene, &opts, &sink, NULL, &err) == 0 ? 0 : 1;
}
