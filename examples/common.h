/* common.h - what the examples share on the host: reading the scene file
 * and writing the finished frame as a binary PPM. On a board the scene
 * comes from flash (rt-scenec) and the pixels go to the display. */
#ifndef EXAMPLES_COMMON_H
#define EXAMPLES_COMMON_H

#include <stdio.h>
#include <stdlib.h>

#include "rt.h"

/* The scene file through the library's reader, or exit with its error. */
static inline const rt_scene_t *example_load(const char *path)
{
    static char text[1 << 20];
    FILE *f = fopen(path, "rb");
    size_t len = f ? fread(text, 1, sizeof text, f) : 0;
    if (!f || ferror(f) || len == sizeof text) {
        fprintf(stderr, "%s: cannot read\n", path);
        exit(2);
    }
    fclose(f);
    rt_error_t err;
    const rt_scene_t *sc = rt_nff_load(text, len, &err);
    if (!sc) {
        fprintf(stderr, "%s:%u: %s\n", path, (unsigned)err.line, err.msg);
        exit(2);
    }
    return sc;
}

/* A w x h frame of 8-bit R, G, B as a binary PPM. */
static inline int example_write_ppm(const char *path, const unsigned char *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f || fprintf(f, "P6\n%d %d\n255\n", w, h) < 0 || fwrite(rgb, 3, (size_t)w * h, f) != (size_t)w * h ||
        fclose(f) != 0) {
        fprintf(stderr, "%s: cannot write\n", path);
        return 1;
    }
    return 0;
}

#endif
