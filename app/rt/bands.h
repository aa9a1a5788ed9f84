/* bands.h - `rt --threads N`: one frame rendered as runs of lines on N
 * threads (POSIX threads; the core itself knows nothing of threads). */
#ifndef BANDS_H
#define BANDS_H

#include <stdbool.h>

#include "backend.h"
#include "image.h"

/* How the render went: wall seconds (the whole call), the threads that
 * ran, and the seconds they spent together in the core's render calls
 * (busy / (threads * wall) = the share of the threads' time used). */
typedef struct {
    double wall, busy;
    unsigned threads;
} bands_time_t;

/* Threads by default: the online CPUs, 1..RT_MAX_WORKERS. */
unsigned bands_default_threads(void);

/* Renders opts (its viewport, or the whole frame: opts->width x height,
 * 0 for the scene's resolution) with `threads` threads (1..RT_MAX_WORKERS;
 * one of them the caller's; one thread: one call of the core). Thread i
 * starts on the i-th of N equal runs of lines and renders as worker i,
 * into its own sink, which expands its lines in `format` (dithered if
 * `dither`, rt_fb_sink_t) straight into
 * their rows of *img (allocated here: the viewport's size), and its own
 * stats; a thread out of lines takes the lower half of the longest run
 * left (bands.c). Progressive display (opts->progressive, or upto_pass
 * N: passes 1..N, one call of the core each, the picture as it stands
 * after pass N) renders on one thread. *stats gets the sum. opts->worker, scratch and
 * scratch_bytes are the threads' own. The progress indicator, if on,
 * shows the lines done by all threads on stderr; *time gets the times.
 * Returns as be->render does: 0, the first failure's sink status, or -1
 * with *err set (then *img is freed). */
int bands_render(const rt_backend_t *be, const rt_render_opts_t *opts, rt_fb_format_t format, bool dither,
                 unsigned threads, unsigned upto_pass, bool progress, image_t *img, rt_stats_t *stats,
                 bands_time_t *time, rt_error_t *err);

#endif
