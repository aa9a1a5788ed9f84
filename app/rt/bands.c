/*
 * bands.c - `rt --threads N`. One thread renders the frame (or viewport)
 * in one call of the core: nothing to split, so nothing traced twice.
 * With two or more, thread i starts on the i-th of N equal runs of lines
 * and renders it top down, one line per step of one render context
 * (rt_render_begin/_step, as its own viewport), so in SPD mode each
 * corner row is traced once within a run. A thread whose run is done
 * takes the lower half of what is left of the longest other run, down
 * to one line, and renders that the same way: the threads stay busy to
 * the end, and in SPD mode a frame costs one
 * more row of corners per run start (N - 1 plus one per such split),
 * where fixed bands of 16 lines cost one per band (6% more eye rays at
 * 512 lines). Thread i is the core's worker i and has its own sink (one
 * line: every step is flushed), SPD or anti-aliasing scratch and stats; the sinks write
 * disjoint rows of one image, so pixels take no lock; the runs' bounds
 * take one mutex. The calling thread is thread 0.
 *
 * Pixels do not depend on who renders what (a viewport's pixels are
 * those of the whole frame); counts do: where runs start and split (which
 * depends on timing) decides how many corner rows SPD mode traces again
 * and where the core's caches start afresh.
 */
#include "bands.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#define ONE_CALL_LINES 16 /* lines per flush of the one-thread render */

/* A run of lines [next, end) of the viewport, rendered top down by its
 * thread; a thread out of lines lowers `end` of another run to take the
 * rest below (both under the job's lock). */
typedef struct {
    unsigned next, end;
} run_t;

typedef struct {
    const rt_backend_t *be;
    const rt_render_opts_t *opts;
    rt_viewport_t vp;      /* the viewport the threads share */
    bool split;            /* false: one call of the core, opts->viewport as given */
    unsigned upto;         /* progressive display up to this pass (0: as opts says) */
    image_t *img;
    run_t *runs;           /* one per thread */
    unsigned n_runs;
    atomic_bool failed;    /* stop taking lines */
    /* the progress indicator: lines done by every thread */
    bool progress;
    atomic_uint lines_done;
    pthread_mutex_t lock; /* the runs, the indicator's line, the first failure */
    unsigned shown;       /* per cent last printed */
    int fail_status;      /* the first failure (0: none) */
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
    if (!img->rgb || a->y1 < job->vp.y || a->y2 >= job->vp.y + img->height || a->y2 < a->y1 ||
        a->x1 < job->vp.x || a->x2 >= job->vp.x + img->width || a->x2 < a->x1)
        return 1; /* not an area of this image: cannot happen */
    /* a band spans the viewport; progressive display's blocks may be
     * narrower, packed tightly too (pitch 0) */
    size_t w = (size_t)(a->x2 - a->x1 + 1);
    for (unsigned y = a->y1; y <= a->y2; y++) {
        uint8_t *dst = img->rgb + ((size_t)(y - job->vp.y) * img->width + (a->x1 - job->vp.x)) * 3;
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

/* The next line of the thread's run, if it has one: claimed before each
 * step, so a thread taking lines below never takes this one. */
static bool claim_line(void *user)
{
    band_thread_t *t = user;
    band_job_t *job = t->job;
    run_t *r = &job->runs[t->index];
    pthread_mutex_lock(&job->lock);
    bool mine = r->next < r->end && !atomic_load(&job->failed);
    if (mine)
        r->next++;
    pthread_mutex_unlock(&job->lock);
    return mine;
}

/* A thread out of lines: its run becomes the lower half of the longest
 * other run with two lines or more left (the owner keeps the upper half,
 * which it is working down). False when there is none. */
static bool take_lines(band_thread_t *t)
{
    band_job_t *job = t->job;
    run_t *mine = &job->runs[t->index], *longest = NULL;
    unsigned most = 1;
    pthread_mutex_lock(&job->lock);
    for (unsigned i = 0; i < job->n_runs; i++) {
        run_t *r = &job->runs[i];
        if (r != mine && r->end - r->next > most) {
            most = r->end - r->next;
            longest = r;
        }
    }
    if (longest) {
        unsigned mid = longest->next + (most + 1) / 2;
        *mine = (run_t){ mid, longest->end };
        longest->end = mid;
    }
    pthread_mutex_unlock(&job->lock);
    return longest != NULL && !atomic_load(&job->failed);
}

static void *band_worker(void *arg)
{
    band_thread_t *t = arg;
    band_job_t *job = t->job;
    run_t *r = &job->runs[t->index];
    do {
        rt_render_opts_t o = *job->opts;
        o.worker = (uint8_t)t->index;
        o.scratch = t->scratch;
        o.scratch_bytes = t->scratch_bytes;
        rt_error_t err = { 0 };
        double t0 = now_seconds();
        int status;
        if (job->split) {
            pthread_mutex_lock(&job->lock);
            run_t now = *r;
            pthread_mutex_unlock(&job->lock);
            if (now.next >= now.end)
                continue; /* taken before it began */
            o.viewport = (rt_viewport_t){ job->vp.x, (uint16_t)(job->vp.y + now.next), job->vp.w,
                                          (uint16_t)(now.end - now.next) };
            status = job->be->render_steps(&o, &t->sink, &t->stats, &err, 1, claim_line, t);
        } else if (job->upto) { /* passes 1..upto, a call each, into the one image */
            status = 0;
            for (unsigned p = 1; p <= job->upto && status == 0; p++) {
                o.progressive = (uint8_t)p;
                status = job->be->render(&o, &t->sink, &t->stats, &err);
            }
        } else {
            status = job->be->render(&o, &t->sink, &t->stats, &err);
        }
        t->busy += now_seconds() - t0;
        if (status != 0) {
            pthread_mutex_lock(&job->lock);
            if (job->fail_status == 0) { /* the first failure */
                job->fail_status = status;
                job->fail_err = err;
            }
            pthread_mutex_unlock(&job->lock);
            atomic_store(&job->failed, true);
            break;
        }
    } while (job->split && take_lines(t));
    return NULL;
}

int bands_render(const rt_backend_t *be, const rt_render_opts_t *opts, rt_fb_format_t format, bool dither,
                 unsigned threads, unsigned upto_pass, bool progress, image_t *img, rt_stats_t *stats,
                 bands_time_t *time, rt_error_t *err)
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
    /* progressive display: one call of the core (a pass's blocks span
     * eight lines), and no indicator (the passes cover the frame over and
     * over) */
    bool progressive = opts->progressive || upto_pass;
    job = (band_job_t){ .be = be, .opts = opts, .vp = vp, .img = img, .progress = progress && !progressive,
                        .upto = upto_pass };
    bool valid = fw >= 1 && fh >= 1 && fw <= RT_MAX_WIDTH && fh <= RT_MAX_HEIGHT && vp.w >= 1 && vp.h >= 1 &&
                 vp.x < fw && vp.y < fh && vp.w <= fw - vp.x && vp.h <= fh - vp.y;
    /* One thread renders the viewport in one call of the core: the render
     * and counts of the board's. A frame or viewport the core would refuse
     * is not cut either, for the core's own message. */
    job.split = valid && threads > 1 && !progressive;
    atomic_init(&job.failed, false);
    atomic_init(&job.lines_done, 0);
    pthread_mutex_init(&job.lock, NULL);

    *img = (image_t){ 0, 0, NULL };
    if (valid) {
        img->width = vp.w;
        img->height = vp.h;
        img->rgb = malloc((size_t)vp.w * vp.h * 3);
    }
    if (threads < 1 || progressive)
        threads = 1;
    if (job.split && threads > vp.h)
        threads = vp.h; /* a line each at least */
    band_thread_t *t = calloc(threads, sizeof *t);
    /* thread i starts on the i-th of `threads` equal runs of lines */
    job.runs = calloc(threads, sizeof *job.runs);
    job.n_runs = threads;
    for (unsigned i = 0; job.runs && i < threads; i++)
        job.runs[i] = (run_t){ (unsigned)((uint64_t)vp.h * i / threads), (unsigned)((uint64_t)vp.h * (i + 1) / threads) };
    /* each thread: one line in the format (every step is flushed), and
     * the scratch of SPD mode or adaptive anti-aliasing (rt_render.h),
     * sized for the widest real_t, double */
    size_t band_bytes = RT_FB_LINE_BYTES(format, vp.w ? vp.w : 1) * (job.split ? 1 : ONE_CALL_LINES);
    size_t scratch_w = vp.w ? vp.w : RT_MAX_WIDTH;
    size_t colours = opts->spd ? RT_RENDER_SPD_COLOURS(scratch_w)
                     : opts->aa_levels && opts->aa_levels <= RT_AA_MAX_LEVELS /* (the core refuses more) */
                         ? RT_RENDER_AA_COLOURS(scratch_w, opts->aa_levels)
                         : 0;
    size_t scratch_bytes = colours * 3 * sizeof(double);
    bool ok = t != NULL && job.runs != NULL && (img->rgb || !valid);
    for (unsigned i = 0; ok && i < threads; i++) {
        t[i].job = &job;
        t[i].index = i;
        t[i].band = malloc(band_bytes);
        t[i].scratch = scratch_bytes ? malloc(scratch_bytes) : NULL;
        t[i].scratch_bytes = scratch_bytes;
        t[i].sink = (rt_fb_sink_t){ .format = format,
                                    .dither = dither,
                                    .band = { t[i].band, NULL },
                                    .band_bytes = band_bytes,
                                    .flush = band_flush,
                                    .user = &t[i] };
        ok = t[i].band && (t[i].scratch || !scratch_bytes);
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
        status = job.fail_status;
        if (status < 0)
            *err = job.fail_err;
    }
    for (unsigned i = 0; t && i < threads; i++) {
        free(t[i].band);
        free(t[i].scratch);
    }
    free(t);
    free(job.runs);
    pthread_mutex_destroy(&job.lock);
    if (status != 0)
        image_free(img);
    return status;
}
