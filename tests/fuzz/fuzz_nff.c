/*
 * fuzz_nff.c - libFuzzer harness over the scene reader and a tiny render
 * under ASan and UBSan, for whichever backend it is built with: the fixed
 * build at default capacities (fuzz_nff), and the double and float builds
 * at the host capacities rt uses (fuzz_nff_double, fuzz_nff_float).
 *
 * Any input must either load or fail with a non-empty error message and
 * a plausible line number; a scene that loads must render 8x8 at depth 3
 * without fault, hang or saturation-free nonsense (the sanitisers watch).
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "reader/nff.h"
#include "rt_render.h"

static scene_store_t store;
static uint8_t band[8 * 3 * 2];

static int begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    (void)s;
    return (w == 8 && h == 8) ? 0 : 1;
}

static int flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    (void)a;
    (void)px;
    rt_fb_flush_ready(s);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rt_error_t err;
    if (!nff_read((const char *)data, size, &store, &err)) {
        uint32_t lines = 1;
        for (size_t i = 0; i < size; i++)
            lines += data[i] == '\n';
        if (err.msg[0] == '\0' || err.line > lines)
            abort(); /* every failure must say what and where */
        return 0;
    }
    rt_fb_sink_t sink = { 0 };
    sink.format = RT_FB_RGB888;
    sink.band[0] = band;
    sink.band_bytes = sizeof band;
    sink.begin = begin;
    sink.flush = flush;
    rt_render_opts_t opts = { 0 };
    opts.width = opts.height = 8;
    opts.max_depth = 3;
    rt_stats_t st = { 0 };
    if (rt_render(&store.scene, &opts, &sink, &st, &err) < 0 && err.msg[0] == '\0')
        abort();
    return 0;
}
