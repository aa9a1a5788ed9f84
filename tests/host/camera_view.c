/*
 * camera_view.c - rt_camera_from_view through the public API: a scene read
 * with one viewpoint and rendered from another (opts.camera) gives the
 * same pixels as the scene whose file has that other viewpoint; a camera
 * out of range or degenerate (zero up) is refused with a message. Values are
 * exact in Q16.16, so the two routes must agree to the bit.
 */
#include <stdio.h>
#include <string.h>

#include "rt.h"

#define W 40
#define H 30

static const char scene_fmt[] = "v\nfrom %s\nat 0 0 0.5\nup 0 0 1\nangle %s\nhither 1\nresolution 40 30\n"
                                "b 0.1 0.2 0.3\nl 4 -3 6\nf 0.9 0.3 0.2 0.7 0.3 20 0 1\ns 0 0 0.5 0.5\n"
                                "f 0.2 0.8 0.3 0.8 0 0 0 1\np 4 -2 -2 0 2 -2 0 2 2 0 -2 2 0\n";

static uint8_t frame[2][H][W * 3];
static unsigned which;

static int put(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    for (unsigned y = a->y1; y <= a->y2; y++)
        memcpy(frame[which][y], px + (y - a->y1) * W * 3u, W * 3u);
    rt_fb_flush_ready(s);
    return 0;
}

static uint8_t band[8 * W * 3];

static int render(const char *from, const char *angle, const rt_camera_t *cam, unsigned into)
{
    static char text[1024];
    int n = snprintf(text, sizeof text, scene_fmt, from, angle);
    rt_error_t err;
    const rt_scene_t *sc = rt_nff_load(text, (size_t)n, &err);
    if (!sc) {
        fprintf(stderr, "camera_view: %u: %s\n", (unsigned)err.line, err.msg);
        return -1;
    }
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { band, NULL }, .band_bytes = sizeof band, .flush = put };
    rt_render_opts_t opts = { .width = W, .height = H, .camera = cam };
    which = into;
    return rt_render(sc, &opts, &sink, NULL, &err);
}

int main(void)
{
    int fail = 0;
    /* the scene's own viewpoint: from 4 -6 3, angle 40 */
    if (render("4 -6 3", "40", NULL, 0) != 0)
        return 1;
    /* a file with another viewpoint, watched from the first one */
    char text[1024];
    int n = snprintf(text, sizeof text, scene_fmt, "-5 2 1.5", "60");
    rt_error_t err;
    const rt_scene_t *sc = rt_nff_load(text, (size_t)n, &err);
    rt_view_t v = { { RT_Q16(4), RT_Q16(-6), RT_Q16(3) }, { 0, 0, RT_Q16(0.5) }, { 0, 0, RT_Q16(1) }, RT_Q16(40) };
    rt_camera_t cam;
    if (!sc || rt_camera_from_view(&cam, sc, &v, &err) != 0 || render("-5 2 1.5", "60", &cam, 1) != 0) {
        fprintf(stderr, "camera_view: %s\n", err.msg);
        return 1;
    }
    if (memcmp(frame[0], frame[1], sizeof frame[0]) == 0) {
        printf("  ok    rt_camera_from_view: the other file from the first viewpoint, same %dx%d pixels\n", W, H);
    } else {
        printf("  FAIL  rt_camera_from_view: the pixels differ from the file with that viewpoint\n");
        fail++;
    }
    if (render("-5 2 1.5", "60", NULL, 1) == 0 && memcmp(frame[0], frame[1], sizeof frame[0]) != 0) {
        printf("  ok    without opts.camera the file's own viewpoint (different pixels)\n");
    } else {
        printf("  FAIL  opts.camera NULL did not give the file's viewpoint\n");
        fail++;
    }
    /* refused: a camera far beyond the range, a zero up vector */
    rt_view_t far = v, flat = v;
    far.from[0] = RT_Q16(30000);
    flat.up[0] = flat.up[1] = flat.up[2] = 0;
    if (rt_camera_from_view(&cam, sc, &far, &err) == -1 && strstr(err.msg, "RT_FAR_EXTENT_LOG2")) {
        printf("  ok    a camera out of range: %s\n", err.msg);
    } else {
        printf("  FAIL  a camera out of range was accepted\n");
        fail++;
    }
    if (rt_camera_from_view(&cam, sc, &flat, &err) == -1 && err.msg[0]) {
        printf("  ok    a zero up vector: %s\n", err.msg);
    } else {
        printf("  FAIL  a degenerate view was accepted\n");
        fail++;
    }
    return fail != 0;
}
