/*
 * main.c - the firmware of every board: render the built-in scene into
 * the board's display sink (sink.h), then report instructions, ray counts
 * and stack use on the console. The board's side is port.h.
 *
 * The image size, depth and pixel format are fixed at build time
 * (BOARD_WIDTH, BOARD_HEIGHT, BOARD_DEPTH, BOARD_FORMAT) so the band
 * buffer is sized exactly.
 */
#include "board_scene.h"
#include "port.h"
#include "sink.h"
#include "rt_render.h"

#ifndef BOARD_BAND_LINES
#define BOARD_BAND_LINES 4
#endif
#ifndef BOARD_FORMAT
#define BOARD_FORMAT RT_FB_RGB888
#endif
/* (a BOARD_FORMAT that is not an ID of RT_FB_FORMATS, rt_fb.h, fails to compile here) */
#ifndef BOARD_ADAPTIVE_MILLI /* adaptive depth threshold in 1/1000; 0 = off */
#define BOARD_ADAPTIVE_MILLI 0
#endif

_Static_assert(BOARD_WIDTH >= 1 && BOARD_WIDTH <= RT_MAX_WIDTH, "BOARD_WIDTH out of range");
_Static_assert(BOARD_HEIGHT >= 1 && BOARD_HEIGHT <= RT_MAX_HEIGHT, "BOARD_HEIGHT out of range");
_Static_assert(BOARD_DEPTH >= 1 && BOARD_DEPTH <= RT_MAX_DEPTH, "BOARD_DEPTH out of 1..RT_MAX_DEPTH");

static uint8_t band[BOARD_BAND_LINES * RT_FB_CONST_LINE_BYTES(BOARD_FORMAT, BOARD_WIDTH)];

/* The core's counters, keyed as on the host (stats.h). */
static void report_counter(void *ctx, const char *key, uint64_t value)
{
    (void)ctx;
    report_value(key, value);
}

int main(void)
{
    stack_paint();
    port_init();
    port_icount_start();
    static rt_error_t err; /* static: keeps the render's stack small */
    const scene_t *sc = board_scene(&err);
    if (!sc) {
        report_text(err.msg);
        return 2;
    }
    rt_render_opts_t opts = { .width = BOARD_WIDTH, .height = BOARD_HEIGHT, .max_depth = BOARD_DEPTH,
                           .adaptive_milli = BOARD_ADAPTIVE_MILLI };
    static rt_stats_t st;
    static rt_fb_sink_t sink;
    sink_init(&sink, BOARD_FORMAT, band, sizeof band);

    uint64_t t0 = port_icount_read();
    int rc = rt_render(sc, &opts, &sink, &st, &err);
    uint64_t instr = port_icount_read() - t0 - sink_io_instructions();
    if (rc != 0) {
        report_text(rc < 0 ? err.msg : "framebuffer sink failed");
        return 1;
    }
    uint32_t pixels = (uint32_t)BOARD_WIDTH * BOARD_HEIGHT;
    report_value("pixels", pixels);
    report_value("render_instructions", instr);
    report_value("instructions_per_pixel", (instr + pixels / 2) / pixels);
    rt_stats_each(&st, report_counter, 0);
    report_value("stack_high_water", stack_high_water());
    report_value("stack_size", stack_size());
    int guard = stack_guard_intact();
    report_value("stack_guard_intact", (uint64_t)guard);
    if (!guard)
        return 3;
    if (SINK_HOLDS_FRAME) {
        report_value("drawn", 1); /* the host captures the panel, then ends the run */
        for (;;)
            ;
    }
    return 0;
}
