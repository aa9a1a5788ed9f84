/* bands.h - `rt --threads N`: one frame rendered as bands of lines on N
 * threads (POSIX threads; the core itself knows nothing of threads). */
#ifndef BANDS_H
#define BANDS_H

#include <stdbool.h>

#include "backend.h"
#include "image.h"

/* Lines per band with two threads or more (bands.c says why this many).
 * Fixed, so the bands, and with them the counts of --stats (each band
 * starts the core's caches afresh; in SPD mode each recomputes its top
 * row of corners), are the same for any number of threads from 2; one
 * thread renders the viewport as one band. */
#ifndef BANDS_LINES
#define BANDS_LINES 16
#endif

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
 * one of them the caller's), the bands handed out in order by an atomic
 * counter (one thread: one band, the viewport; the same code); fewer
 * threads run than there are bands, if need be. Thread i renders as worker i, into its own sink, which expands
 * its lines in `format` straight into their rows of *img (allocated here:
 * the viewport's size), and its own stats; *stats gets their sum.
 * opts->worker, scratch and scratch_bytes are the threads' own. The
 * progress indicator, if on, shows the lines done by all threads on
 * stderr; *time gets the times. Returns as be->render does: 0, the first
 * failed band's sink status, or -1 with *err set (then *img is freed). */
int bands_render(const rt_backend_t *be, const rt_render_opts_t *opts, rt_fb_format_t format, unsigned threads,
                 bool progress, image_t *img, rt_stats_t *stats, bands_time_t *time, rt_error_t *err);

#endif
