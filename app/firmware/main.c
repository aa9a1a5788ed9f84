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
#if BOARD_CORES > 1
#include "bands.h"
#endif

#ifndef BOARD_BAND_LINES
#define BOARD_BAND_LINES 4
#endif
#ifndef BOARD_CORES /* cores that render (board.mk; make CORES=1 renders on one) */
#define BOARD_CORES 1
#endif
#ifndef BOARD_FORMAT
#define BOARD_FORMAT RT_FB_RGB888
#endif
/* (a BOARD_FORMAT that is not an ID of RT_FB_FORMATS, rt_fb.h, fails to compile here) */
#ifndef BOARD_ADAPTIVE_MILLI /* adaptive depth threshold in 1/1000; 0 = off */
#define BOARD_ADAPTIVE_MILLI 0
#endif

/* Anti-aliasing (make AA=LEVELS[,THRESHOLD] or SPP=N): adaptive levels
 * and threshold, or uniform samples a side; 0 = one sample a pixel. */
#ifndef BOARD_AA_LEVELS
#define BOARD_AA_LEVELS 0
#endif
#ifndef BOARD_AA_THRESHOLD
#define BOARD_AA_THRESHOLD 0
#endif
#ifndef BOARD_SPP
#define BOARD_SPP 0
#endif
#ifndef BOARD_DITHER /* ordered dithering of the packed formats (make DITHER=1) */
#define BOARD_DITHER 0
#endif
#if BOARD_AA_LEVELS
/* each core's rows of cell corners, one after the other (bands.c) */
#define AA_SCRATCH_BYTES RT_RENDER_AA_SCRATCH(BOARD_WIDTH, BOARD_AA_LEVELS)
static uint64_t aa_scratch[BOARD_CORES][(AA_SCRATCH_BYTES + 7) / 8];
#endif

_Static_assert(BOARD_WIDTH >= 1 && BOARD_WIDTH <= RT_MAX_WIDTH, "BOARD_WIDTH out of range");
_Static_assert(BOARD_HEIGHT >= 1 && BOARD_HEIGHT <= RT_MAX_HEIGHT, "BOARD_HEIGHT out of range");
_Static_assert(BOARD_DEPTH >= 1 && BOARD_DEPTH <= RT_MAX_DEPTH, "BOARD_DEPTH out of 1..RT_MAX_DEPTH");

#if BOARD_CORES == 1 /* (with more, each core has band buffers of its own: bands.c) */
/* (word-aligned: progressive display copies its lines a word at a time) */
static uint8_t band[BOARD_BAND_LINES * RT_FB_CONST_LINE_BYTES(BOARD_FORMAT, BOARD_WIDTH)] __attribute__((aligned(4)));
#endif

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
                           .adaptive_milli = BOARD_ADAPTIVE_MILLI, .aa_levels = BOARD_AA_LEVELS,
                           .aa_threshold = BOARD_AA_THRESHOLD, .spp = BOARD_SPP };
#if BOARD_PROGRESSIVE /* a panel that keeps its frame (firmware.mk's PROGRESSIVE) */
    opts.progressive = RT_PROGRESSIVE_ALL;
#endif
#if BOARD_AA_LEVELS
    opts.scratch = aa_scratch;
    opts.scratch_bytes = sizeof aa_scratch[0];
#endif
    static rt_stats_t st;
    static rt_fb_sink_t sink;
    uint32_t pixels = (uint32_t)BOARD_WIDTH * BOARD_HEIGHT;
    /* (the render starts right after sink_init: a sink may time the frame
     * from there, as the Pico's does) */
#if BOARD_CORES == 1
    sink_init(&sink, BOARD_FORMAT, band, sizeof band);
#if BOARD_DITHER
    sink.dither = true;
#endif
#if BOARD_CYCLES
    uint64_t c0 = port_cycles_read();
#endif
    uint64_t t0 = port_icount_read();
    int rc = rt_render(sc, &opts, &sink, &st, &err);
    uint64_t instr = port_icount_read() - t0 - sink_io_instructions();
#if BOARD_CYCLES
    uint64_t cycles = port_cycles_read() - c0 - sink_io_cycles();
#endif
#else
    sink_init(&sink, BOARD_FORMAT, 0, 0);
#if BOARD_DITHER
    sink.dither = true;
#endif
    static bands_report_t rep;
#if BOARD_CYCLES
    uint64_t c0 = port_cycles_read(); /* core 0's marks, as with one core: start, output pairs, end */
#endif
    int rc = bands_render(sc, &opts, &sink, &rep, &err);
#if BOARD_CYCLES
    /* the frame's time on the board: core 0's, from the start to the end
     * of both cores' work, its own output left out */
    uint64_t cycles = port_cycles_read() - c0 - sink_io_cycles();
#endif
    uint64_t instr = 0; /* every core's render: the work, as one core counts it (BANDS_UNIT) */
    for (unsigned c = 0; c < BOARD_CORES; c++) {
        instr += rep.core[c].render;
        rt_stats_add(&st, &rep.core[c].stats);
    }
#endif
    if (rc != 0) {
        report_text(rc < 0 ? err.msg : "framebuffer sink failed");
        return 1;
    }
    report_value("pixels", pixels);
    /* cppcheck-suppress knownConditionTrueFalse ; a constant but on a port that probes (port.h) */
    if (port_counts_instructions()) {
        report_value("render_instructions", instr);
        report_value("instructions_per_pixel", (instr + pixels / 2) / pixels);
    }
#if BOARD_CYCLES
    /* cppcheck-suppress knownConditionTrueFalse ; as above */
    if (port_counts_cycles()) {
        report_value("render_cycles", cycles);
        report_value("cycles_per_pixel", (cycles + pixels / 2) / pixels);
    }
#endif
#if BOARD_CORES > 1
    /* in the unit bands.c counts in: instructions, or each core's cycles */
    static const char *const keys[][3] = { { "core0_render_" BANDS_UNIT, "core0_wait_" BANDS_UNIT, "core0_bands" },
                                           { "core1_render_" BANDS_UNIT, "core1_wait_" BANDS_UNIT, "core1_bands" } };
    _Static_assert(BOARD_CORES <= sizeof keys / sizeof keys[0], "a report key per core");
    report_value("cores", BOARD_CORES);
    report_value("cores_one_at_a_time", rep.one_at_a_time); /* 1: exact counts (per-core cycles: always) */
    for (unsigned c = 0; c < BOARD_CORES; c++) {
        report_value(keys[c][0], rep.core[c].render);
        report_value(keys[c][1], rep.core[c].wait);
        report_value(keys[c][2], rep.core[c].bands);
    }
    report_value("critical_path_" BANDS_UNIT, rep.critical_path);
    report_value("critical_path_" BANDS_UNIT "_per_pixel", (rep.critical_path + pixels / 2) / pixels);
#endif
    rt_stats_each(&st, report_counter, 0);
    report_value("stack_high_water", stack_high_water());
    report_value("stack_size", stack_size());
    int guard = stack_guard_intact();
#if BOARD_CORES > 1
    report_value("core1_stack_high_water", stack_high_water_core(1));
    guard &= stack_guard_intact_core(1);
#endif
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
