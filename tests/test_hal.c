/* test_hal.c - the framebuffer HAL (src/fb.h, src/render.h) through the
 * fixed and double backends: a failing flush aborts the frame, stats may
 * be NULL. */
#include <stdlib.h>
#include <string.h>

#include "backend.h"
#include "testlib.h"

#define MAX_W 96
#define MAX_H 64

static char *read_text(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    static char buf[1 << 20];
    *len = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[*len] = '\0';
    return buf;
}

/* A sink that collects the frame as RGB888 and counts its calls; it fails
 * the flush number fail_at (1-based; 0: never). */
typedef struct {
    fb_sink_t sink;
    uint8_t img[MAX_W * MAX_H * 3];
    uint16_t w, h;
    int flushes, ends, fail_at;
    uint8_t band_a[MAX_W * 3 * 5], band_b[MAX_W * 3 * 5];
} test_sink_t;

static int t_begin(fb_sink_t *s, uint16_t w, uint16_t h)
{
    test_sink_t *t = s->user;
    t->w = w;
    t->h = h;
    return w <= MAX_W && h <= MAX_H ? 0 : 1;
}

static int t_flush(fb_sink_t *s, const fb_area_t *a, const uint8_t *px)
{
    test_sink_t *t = s->user;
    t->flushes++;
    if (t->flushes == t->fail_at)
        return 42;
    for (unsigned y = a->y1; y <= a->y2; y++)
        memcpy(t->img + (size_t)y * t->w * 3, px + (size_t)(y - a->y1) * t->w * 3, (size_t)t->w * 3);
    fb_flush_ready(s);
    return 0;
}

static int t_end(fb_sink_t *s)
{
    test_sink_t *t = s->user;
    t->ends++;
    return 0;
}

static void sink_init(test_sink_t *t, int lines_per_band, bool two)
{
    memset(t, 0, sizeof *t);
    t->sink.format = RT_FB_RGB888;
    t->sink.band[0] = t->band_a;
    t->sink.band[1] = two ? t->band_b : NULL;
    t->sink.band_bytes = (size_t)lines_per_band * MAX_W * 3;
    t->sink.begin = t_begin;
    t->sink.flush = t_flush;
    t->sink.end = t_end;
    t->sink.user = t;
}

static test_sink_t ref, got;

int main(void)
{
    size_t len;
    const char *text = read_text("scenes/spd/balls-1.nff", &len);
    if (!text) {
        printf("  FAIL  cannot read scenes/spd/balls-1.nff (run from the repository root)\n");
        return 1;
    }
    const struct {
        const char *name;
        const rt_backend_t *be;
    } bes[] = { { "fixed", &rt_backend_fixed }, { "double", &rt_backend_double } };
    for (size_t b = 0; b < 2; b++) {
        const rt_backend_t *be = bes[b].be;
        rt_error_t err;
        if (!be->load(text, len, &err)) {
            CHECK(0, "%s: load: %s", bes[b].name, err.msg);
            continue;
        }
        render_opts_t opts = { .width = 40, .height = 30, .max_depth = 3 };
        rt_stats_t st = { 0 };
        /* 30 lines of 120 bytes, 4 * MAX_W * 3 bytes a band: 9 lines a band, 4 bands */
        sink_init(&ref, 4, true);
        int rc = be->render(&opts, &ref.sink, &st, &err);
        CHECK(rc == 0 && ref.flushes == 4 && ref.ends == 1, "%s: full frame: status %d, %d flushes, %d end",
              bes[b].name, rc, ref.flushes, ref.ends);

        /* flush status: the third band fails */
        for (int two = 0; two < 2; two++) {
            sink_init(&got, 4, two);
            got.fail_at = 3;
            rc = be->render(&opts, &got.sink, &st, &err);
            CHECK(rc == 42 && got.flushes == 3 && got.ends == 0 && !got.sink.flushing,
                  "%s, %s buffer: flush 3 fails -> status %d, %d flushes, end() called %d times, not flushing",
                  bes[b].name, two ? "double" : "single", rc, got.flushes, got.ends);
        }

        /* stats may be NULL: the same image */
        sink_init(&got, 4, true);
        rc = be->render(&opts, &got.sink, NULL, &err);
        CHECK(rc == 0 && memcmp(got.img, ref.img, sizeof ref.img) == 0, "%s: stats NULL: status %d, same image",
              bes[b].name, rc);
    }
    return tl_summary("test_hal");
}
