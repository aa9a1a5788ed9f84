/* report.h - `rt --stats`: the render's figures on one stream. */
#ifndef REPORT_H
#define REPORT_H

#include <stdbool.h>
#include <stdio.h>

#include "backend.h"

typedef enum { REPORT_TEXT, REPORT_JSON } report_format_t;

/* The core's counters (stats.h, the keys the firmware reports too), then
 * the host's own figures: backend, image size, render time (wall), the
 * threads and the share of threads x render time they spent rendering
 * (threads_busy), scene scale,
 * range bits lost, saturations (fixed build with counting on), BVH shape.
 * Text: one "key value" line each; JSON: one object. */
void report_stats(FILE *f, report_format_t format, const rt_backend_t *be, const char *backend,
                  const rt_stats_t *st, int width, int height, double seconds, unsigned threads, double busy,
                  int range_bits_lost);

#endif
