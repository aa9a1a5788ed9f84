/*
 * bands.c - `rt --threads N`: the frame (or viewport) cut into bands of
 * BANDS_LINES lines, each rendered by one call of the core as its own
 * viewport (pixels the same as in the whole frame), handed out in order
 * by an atomic counter to N threads. Thread i is the core's worker i and
 * has its own sink, SPD scratch and stats; the sinks write disjoint rows
 * of one image, so pixels need no lock.
 *
 * Band height, measured on balls-2 at 512x512 --spd, fixed backend, two
 * threads on two cores (median of 3, seconds; eye rays from --stats):
 *
 *     lines   seconds   eye rays    (one band: 263169 corner rays)
 *       1      2.85      525312
 *       4      1.79      328960
 *       8      1.60      295065
 *      16      1.52      279616
 *      32      1.47      271393
 *      64      1.45      267281
 *
 * In SPD mode each band recomputes its top row of corners, W+1 rays, so
 * a band of h lines costs 1/h more eye rays (16: +6 %); smaller bands
 * balance the threads better at the end of the frame. Past 16 lines the
 * time gains little (the extra row is cheap beside the shading of the
 * other 16), while 512 / 16 = 32 bands still leave the last one a small
 * share of a many-thread run and keep a small image (48x40: 3 bands)
 * spread over more than one thread. Non-SPD renders do not care (the
 * same within noise from 1 to 64 lines).
 */
#include "bands.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct band_thread;

typedef struct {
    const rt_backend_t *be;
    const rt_render_opts_t *opts;
    rt_viewport_t vp;      /* the viewport the bands cut */
    unsigned n_bands;
    bool split;            /* false: one band, opts->viewport as given */
    image_t *img;
    atomic_uint next_band; /* the next band to hand out */
    atomic_bool failed;    /* stop handing out bands */
    /* the progress indicator: lines done by every thread */
    bool progress;
    atomic_uint lines_done;
    pthread_mutex_t lock; /* the indicator's line, and the first failure */
    unsigned shown;       /* per cent last printed */
    unsigned fail_band;   /* the lowest band that failed (n_bands: none) */
    int fail_status;
    rt_error_t fail_err;
} band_job_t;

typedef struct band_thread {
    rt_fb_sink_t sink;
    band_job_t *job;
    unsigned index; /* the core's worker */
    rt_stats_t stats;
    void *scratch;
    size_t scratch_bytes;
    uint8_t *band;
    pthread_t tid;
    bool started;
} band_thread_t;

unsigned bands_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        n = 1;
    if (n > RT_MAX_WORKERS)
        n = RT_MAX_WORKERS;
    return (unsigned)n;
}

/* The band's lines into their rows of the image, expanded to RGB. */
static int band_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    band_thread_t *t = s->user;
    band_job_t *job = t->job;
    image_t *img = job->img;
    if (!img->rgb || a->y1 < job->vp.y || a->y2 >= job->vp.y + img->height || a->x1 != job->vp.x ||
        a->x2 - a->x1 + 1 != img->width)
        return 1; /* not a band of this image: cannot happen */
    size_t w = (size_t)img->width;
    for (unsigned y = a->y1; y <= a->y2; y++) {
        uint8_t *dst = img->rgb + (size_t)(y - job->vp.y) * w * 3;
        const uint8_t *src = px + (size_t)(y - a->y1) * RT_FB_LINE_BYTES(s->format, w);
        for (size_t x = 0; x < w; x++)
            rt_fb_expand(s->format, src, x, dst + 3 * x);
    }
    unsigned lines = (unsigned)(a->y2 - a->y1 + 1);
    unsigned done = atomic_fetch_add(&job->lines_done, lines) + lines;
    if (job->progress) {
        unsigned pct = (unsigned)(100.0 * done / img->height);
        pthread_mutex_lock(&job->lock);
        if (pct > job->shown) { /* threads finish out of order: never back */
            job->shown = pct;
            fprintf(stderr, "\rrendering: %3u%%", pct);
        }
        pthread_mutex_unlock(&job->lock);
    }
    rt_fb_flush_ready(s); /* synchronous: the buffer is free again */
    return 0;
}

static void *band_worker(void *arg)
{
    band_thread_t *t = arg;
    band_job_t *job = t->job;
    for (;;) {
        unsigned k = atomic_fetch_add(&job->next_band, 1);
        if (k >= job->n_bands || atomic_load(&job->failed))
            break;
        rt_render_opts_t o = *job->opts;
        if (job->split) {
            unsigned y = job->vp.y + k * BANDS_LINES;
            unsigned h = job->vp.y + job->vp.h - y;
            o.viewport = (rt_viewport_t){ job->vp.x, (uint16_t)y, job->vp.w, (uint16_t)(h < BANDS_LINES ? h : BANDS_LINES) };
        }
        o.worker = (uint8_t)t->index;
        o.scratch = t->scratch;
        o.scratch_bytes = t->scratch_bytes;
        rt_error_t err = { 0 };
        int status = job->be->render(&o, &t->sink, &t->stats, &err);
        if (status != 0) {
            pthread_mutex_lock(&job->lock);
            if (k < job->fail_band) { /* the first band's failure, whichever thread is first */
                job->fail_band = k;
                job->fail_status = status;
                job->fail_err = err;
            }
            pthread_mutex_unlock(&job->lock);
            atomic_store(&job->failed, true);
            break;
        }
    }
    return NULL;
}

int bands_render(const rt_backend_t *be, const rt_render_opts_t *opts, rt_fb_format_t format, unsigned threads,
                 bool progress, image_t *img, rt_stats_t *stats, rt_error_t *err)
{
    /* the frame as the core will see it */
    uint16_t fw = opts->width, fh = opts->height, sw, sh;
    be->resolution(&sw, &sh);
    if (!fw)
        fw = sw;
    if (!fh)
        fh = sh;
    rt_viewport_t vp = opts->viewport;
    if (vp.w == 0 && vp.h == 0)
        vp = (rt_viewport_t){ 0, 0, fw, fh };

    static band_job_t job; /* one render at a time */
    job = (band_job_t){ .be = be, .opts = opts, .vp = vp, .img = img, .progress = progress };
    bool valid = fw >= 1 && fh >= 1 && fw <= RT_MAX_WIDTH && fh <= RT_MAX_HEIGHT && vp.w >= 1 && vp.h >= 1 &&
                 vp.x < fw && vp.y < fh && vp.w <= fw - vp.x && vp.h <= fh - vp.y;
    /* One thread renders the viewport as one band: the render and counts
     * of one call of the core, as the board's. A frame or viewport the
     * core would refuse is not cut either, for the core's own message. */
    job.split = valid && threads > 1;
    job.n_bands = job.split ? (vp.h + BANDS_LINES - 1u) / BANDS_LINES : 1;
    job.fail_band = job.n_bands;
    atomic_init(&job.next_band, 0);
    atomic_init(&job.failed, false);
    atomic_init(&job.lines_done, 0);
    pthread_mutex_init(&job.lock, NULL);

    *img = (image_t){ 0, 0, NULL };
    if (valid) {
        img->width = vp.w;
        img->height = vp.h;
        img->rgb = malloc((size_t)vp.w * vp.h * 3);
    }
    if (threads < 1)
        threads = 1;
    if (threads > job.n_bands)
        threads = job.n_bands;
    band_thread_t *t = calloc(threads, sizeof *t);
    /* each thread: a band's lines in the format, two rows of corner
     * colours (sized for the widest real_t, double) */
    size_t band_bytes = BANDS_LINES * RT_FB_LINE_BYTES(format, vp.w ? vp.w : 1);
    size_t scratch_bytes = 2 * ((size_t)(vp.w ? vp.w : RT_MAX_WIDTH) + 1) * 3 * sizeof(double);
    bool ok = t != NULL && (img->rgb || !valid);
    for (unsigned i = 0; ok && i < threads; i++) {
        t[i].job = &job;
        t[i].index = i;
        t[i].band = malloc(band_bytes);
        t[i].scratch = opts->spd ? malloc(scratch_bytes) : NULL;
        t[i].scratch_bytes = opts->spd ? scratch_bytes : 0;
        t[i].sink = (rt_fb_sink_t){ .format = format,
                                    .band = { t[i].band, NULL },
                                    .band_bytes = band_bytes,
                                    .flush = band_flush,
                                    .user = &t[i] };
        ok = t[i].band && (t[i].scratch || !opts->spd);
    }
    int status = 1; /* out of memory: as a sink's failure */
    if (ok) {
        /* threads 1.. on their own; thread 0 is this one */
        for (unsigned i = 1; i < threads; i++)
            t[i].started = pthread_create(&t[i].tid, NULL, band_worker, &t[i]) == 0;
        band_worker(&t[0]); /* the others, if they could not start, leave it more bands */
        for (unsigned i = 1; i < threads; i++)
            if (t[i].started)
                pthread_join(t[i].tid, NULL);
        for (unsigned i = 0; i < threads; i++)
            be->stats_add(stats, &t[i].stats);
        status = 0;
        if (job.fail_band < job.n_bands) {
            status = job.fail_status;
            if (status < 0)
                *err = job.fail_err;
        }
    }
    for (unsigned i = 0; t && i < threads; i++) {
        free(t[i].band);
        free(t[i].scratch);
    }
    free(t);
    pthread_mutex_destroy(&job.lock);
    if (status != 0)
        image_free(img);
    return status;
}
