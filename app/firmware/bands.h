/*
 * bands.h - one frame on several cores (BOARD_CORES > 1): bands of
 * BOARD_BAND_LINES lines, rendered on every core and handed to the
 * display sink in order, so the sink sees the stream one core sends; or,
 * with progressive display (a panel that keeps its frame), each pass in
 * pieces whose areas go to the sink as they are rendered (bands.c).
 */
#ifndef BANDS_H
#define BANDS_H

#include "rt_render.h"

/* What one core did, in instructions, or in its own cycles on a board
 * without an instruction counter (BANDS_UNIT; bands.c's Counting). */
#if BOARD_INSTR_COUNTER
#define BANDS_UNIT "instructions"
#else
#define BANDS_UNIT "cycles"
#endif
typedef struct {
    uint64_t render; /* inside its band renders */
    uint64_t wait;   /* on the parallel timeline: for a free band buffer */
    uint32_t bands;
    rt_stats_t stats;
} bands_core_t;

typedef struct {
    bands_core_t core[BOARD_CORES];
    uint64_t critical_path; /* the latest core's render + wait */
    bool one_at_a_time;     /* the cores ran in turns (QEMU -icount): counts exact */
} bands_report_t;

/* Renders the frame of opts (width, height, depth, progressive 0 or
 * RT_PROGRESSIVE_ALL; no viewport) on all
 * cores into sink: core 0 calls this, it starts the others. A scratch
 * (adaptive anti-aliasing) is BOARD_CORES areas of scratch_bytes each,
 * one after the other: one per core. 0, -1 with
 * *err set, or the sink's failure. */
int bands_render(const rt_scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink, bands_report_t *rep,
                 rt_error_t *err);

#endif
