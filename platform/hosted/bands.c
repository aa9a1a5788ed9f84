/*
 * bands.c - `rt --threads N`. One thread renders the frame (or viewport)
 * in one call of the core, as rt always did. Two or more cut it into bands
 * of BANDS_LINES lines, each rendered by one call of the core as its own
 * viewport (pixels the same as in the whole frame, SPD mode included),
 * handed out in order by an atomic counter. Thread i is the core's worker
 * i and has its own sink, SPD scratch and stats; the sinks write disjoint
 * rows of one image, so pixels need no lock. The calling thread is
 * thread 0, so one thread runs the same code with no thread started.
 *
 * Band height: 16 lines. Two threads on two cores (a shared 2-vCPU VM:
 * about 5% noise), 512x512, seconds, median of 5:
 *
 *     band lines                     1      4      8     16     32     64
 *     balls-2 --spd (s)          0.196  0.127  0.114  0.112  0.111  0.110
 *       its eye rays            525312 328320 295488 279072 270864 266760
 *     showpiece, normal mode (s) 0.258  0.261  0.262  0.266  0.278  0.310
 *
 * (one thread, one band: balls-2 --spd 0.180 s and 263169 eye rays,
 * showpiece 0.497 s.)
 *
 * In SPD mode each band recomputes its top row of corners, W+1 more eye
 * rays, so h-line bands trace 1/h more (16: +6 %, and 5-8 % more time
 * on one thread: balls-2, gears-1, rings-2, teapot-2, tetra-2):
 * 1 and 4 lines waste work, 8 is 2 % slower than 16, 32 and 64 are 1-2 %
 * faster (so too on gears-1, rings-2 and teapot-2). In normal mode a band costs nothing extra
 * and only the balance counts: the showpiece's rows differ in cost and
 * 64-line bands (8 per frame) leave one thread idle at the end, 12-20 %
 * slower than small ones over runs. 16 is within 2-3 % of the best in both modes
 * on two cores and leaves a 512-line frame 32 bands for more threads.
 */
#include "bands.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

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
    double busy; /* seconds in the core's render calls */
    pthread_t tid;
    bool started;
} band_thread_t;

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

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
        double t0 = now_seconds();
        int status = job->be->render(&o, &t->sink, &t->stats, &err);
        t->busy += now_seconds() - t0;
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
                 bool progress, image_t *img, rt_stats_t *stats, bands_time_t *time, rt_error_t *err)
{
    double start = now_seconds();
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
        time->wall = now_seconds() - start;
        time->threads = 1;
        time->busy = t[0].busy;
        for (unsigned i = 1; i < threads; i++)
            if (t[i].started) {
                time->threads++;
                time->busy += t[i].busy;
            }
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
