/* test_hal.c - the framebuffer HAL (include/rt_fb.h, include/rt_render.h) through the
 * fixed and double backends:
 *  - a flush failing on the third band ends the render with its status,
 *    no further flush and no end();
 *  - stats may be NULL;
 *  - a viewport renders exactly the same pixels as that region of the
 *    whole frame (every mode; corners, interior, one pixel, full
 *    width, one column, odd sizes), with a tight and a padded pitch, and
 *    leaves the rest of the sink's frame untouched;
 *  - the incremental API, stepping 1, 3 and 7 lines, gives the same frame
 *    as one call;
 *  - progressive display (whole frame and viewports on the 8-pixel grid,
 *    bands shorter than a block, one and two buffers, padded pitch, one
 *    call or a row a step) gives the scanline frame's pixels and ends
 *    passes 1..7 in order, each with its flushes done; each pass alone in
 *    two bands of lines (as two cores share one) builds the same frame;
 *    seven bad progressive option sets refused before any flush;
 *  - all of it in SPD mode and with adaptive and uniform anti-aliasing
 *    too, and anti-aliasing's bad options refused before any flush;
 *  - adaptive anti-aliasing's split decisions (opts.aa_splits, the host's
 *    RT_AA_REPLAY): recording them changes no pixel, a build replaying
 *    its own gives its own frame, a viewport records its pixels' words
 *    alone (the whole frame's) and replays to the crop of the whole
 *    frame; the double build replaying the fixed build's traces exactly
 *    its eye rays and splits; bad split options refused before any flush. */
#include <stdlib.h>
#include <string.h>

#include "backend.h"
#include "testlib.h"

#define W 41 /* odd sizes */
#define H 29
#define SENTINEL 0xA5

static char *read_text(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    static char buf[1 << 20];
    *len = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[*len] = '\0';
    return buf;
}

/* A sink that places each band's pixels (RGB888) into a whole W x H frame
 * by the area's frame coordinates, reading lines `pitch` apart; counts its
 * calls and fails flush number fail_at (1-based; 0: never). */
typedef struct {
    rt_fb_sink_t sink;
    uint8_t img[W * H * 3];
    int flushes, ends, fail_at;
    bool bad_area;
    uint16_t vp_w;      /* progressive: areas narrower than this are packed tightly */
    uint8_t passes[16]; /* progressive: pass_end's passes, in order */
    int n_passes;
    uint8_t band_a[(W * 3 + 16) * 5], band_b[(W * 3 + 16) * 5];
} test_sink_t;

static int t_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    (void)s;
    return w == W && h == H ? 0 : 1;
}

static int t_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    test_sink_t *t = s->user;
    t->flushes++;
    if (t->flushes == t->fail_at)
        return 42;
    if (a->x2 >= W || a->y2 >= H || a->x1 > a->x2 || a->y1 > a->y2) {
        t->bad_area = true;
        return 0;
    }
    bool block = t->vp_w && a->x2 - a->x1 + 1 < t->vp_w;
    size_t pitch = s->pitch && !block ? s->pitch : (size_t)(a->x2 - a->x1 + 1) * 3;
    for (unsigned y = a->y1; y <= a->y2; y++)
        memcpy(t->img + ((size_t)y * W + a->x1) * 3, px + (size_t)(y - a->y1) * pitch, (size_t)(a->x2 - a->x1 + 1) * 3);
    rt_fb_flush_ready(s);
    return 0;
}

static int t_end(rt_fb_sink_t *s)
{
    test_sink_t *t = s->user;
    t->ends++;
    return 0;
}

static void t_pass_end(rt_fb_sink_t *s, unsigned pass)
{
    test_sink_t *t = s->user;
    if (s->flushing || t->n_passes >= (int)sizeof t->passes)
        t->bad_area = true; /* a pass ends with its flushes done */
    else
        t->passes[t->n_passes++] = (uint8_t)pass;
}

/* band_lines lines of `pitch` bytes (0: of the whole width) a band */
static void sink_init(test_sink_t *t, size_t pitch, int band_lines, bool two)
{
    memset(t, 0, sizeof *t);
    memset(t->img, SENTINEL, sizeof t->img);
    t->sink.format = RT_FB_RGB888;
    t->sink.band[0] = t->band_a;
    t->sink.band[1] = two ? t->band_b : NULL;
    t->sink.pitch = pitch;
    t->sink.band_bytes = (size_t)band_lines * (pitch ? pitch : W * 3);
    t->sink.begin = t_begin;
    t->sink.flush = t_flush;
    t->sink.end = t_end;
    t->sink.user = t;
}

/* got equals ref inside the viewport and is untouched outside it */
static bool same_crop(const test_sink_t *got, const test_sink_t *ref, rt_viewport_t v)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            bool in = x >= v.x && x < v.x + v.w && y >= v.y && y < v.y + v.h;
            const uint8_t *g = got->img + ((size_t)y * W + x) * 3, *r = ref->img + ((size_t)y * W + x) * 3;
            for (int k = 0; k < 3; k++)
                if (in ? g[k] != r[k] : g[k] != SENTINEL)
                    return false;
        }
    return true;
}

#define MODES 4 /* one sample, SPD, adaptive (3 levels) and uniform (3 x 3) anti-aliasing */
static const char *const mode_name[MODES] = { "", " SPD", " AA 3", " SPP 3" };
static test_sink_t ref[MODES], got;
static double scratch[(2 * (W * 8 + 1) + 9 * 9) * 3]; /* the larger of SPD's and 3 levels' (for double) */
#define SPLIT_WORDS RT_AA_SPLITS_WORDS(W, H, 3)
static uint32_t splits[2][SPLIT_WORDS], splits_vp[SPLIT_WORDS]; /* each backend's; a viewport's */
static rt_stats_t split_stats[2];                                  /* each backend's recording */

/* How many of the n option sets `be` refuses before any flush, with a
 * message that contains `says` ("": any message); a set it takes is
 * printed, as bad WHAT options k. */
static int refused_count(const rt_backend_t *be, const rt_render_opts_t *bad, int n, const char *says, const char *bn,
                         const char *what, rt_error_t *err)
{
    rt_stats_t st = { 0 };
    int refused = 0;
    for (int k = 0; k < n; k++) {
        sink_init(&got, 0, 4, true);
        int rc = be->render(&bad[k], &got.sink, &st, err);
        refused += rc == -1 && got.flushes == 0 && err->msg[0] != '\0' && strstr(err->msg, says) != NULL;
        if (rc != -1)
            printf("        %s: bad %s options %d: status %d\n", bn, what, k, rc);
    }
    return refused;
}

int main(void)
{
    size_t len;
    const char *text = read_text("scenes/spd/balls-1.nff", &len);
    if (!text) {
        printf("  FAIL  cannot read scenes/spd/balls-1.nff (run from the repository root)\n");
        return 1;
    }
    const struct {
        const char *name;
        const rt_backend_t *be;
    } bes[] = { { "fixed", &rt_backend_fixed }, { "double", &rt_backend_double } };
    const rt_viewport_t vps[] = {
        { 0, 0, 1, 1 },         /* top-left pixel */
        { W - 1, H - 1, 1, 1 }, /* bottom-right pixel */
        { W - 5, 0, 5, 4 },     /* top-right corner */
        { 0, H - 3, 6, 3 },     /* bottom-left corner */
        { 7, 3, 13, 11 },       /* interior, odd */
        { 1, 2, 3, 5 },         /* small, odd */
        { 0, 5, W, 7 },         /* full width */
        { 20, 0, 1, H },        /* one column, full height */
        { 0, 0, W, H },         /* the whole frame, explicitly */
    };
    const size_t n_vps = sizeof vps / sizeof vps[0];
    for (size_t b = 0; b < 2; b++) {
        const rt_backend_t *be = bes[b].be;
        const char *bn = bes[b].name;
        rt_error_t err;
        if (!be->load(text, len, &err)) {
            CHECK(0, "%s: load: %s", bn, err.msg);
            continue;
        }
        rt_stats_t st = { 0 };
        rt_render_opts_t opts[MODES] = {
            { .width = W, .height = H, .max_depth = 3 },
            { .width = W, .height = H, .max_depth = 3, .spd = true, .scratch = scratch, .scratch_bytes = sizeof scratch },
            { .width = W, .height = H, .max_depth = 3, .aa_levels = 3, .scratch = scratch,
              .scratch_bytes = sizeof scratch },
            { .width = W, .height = H, .max_depth = 3, .spp = 3 },
        };
        for (int m = 0; m < MODES; m++) {
            /* 29 lines, 4 lines a band: 8 bands */
            sink_init(&ref[m], 0, 4, true);
            int rc = be->render(&opts[m], &ref[m].sink, &st, &err);
            CHECK(rc == 0 && ref[m].flushes == 8 && ref[m].ends == 1 && !ref[m].bad_area,
                  "%s%s: whole frame: status %d, %d flushes, %d end", bn, mode_name[m], rc, ref[m].flushes,
                  ref[m].ends);
        }

        /* flush status: the third band fails */
        for (int two = 0; two < 2; two++) {
            sink_init(&got, 0, 4, two);
            got.fail_at = 3;
            int rc = be->render(&opts[0], &got.sink, &st, &err);
            CHECK(rc == 42 && got.flushes == 3 && got.ends == 0 && !got.sink.flushing,
                  "%s, %s buffer: flush 3 fails -> status %d, %d flushes, end() called %d times, not flushing", bn,
                  two ? "double" : "single", rc, got.flushes, got.ends);
            sink_init(&got, 0, 4, two);
            got.fail_at = 3;
            rc = be->render_steps(&opts[0], &got.sink, &st, &err, 3, NULL, NULL);
            CHECK(rc == 42 && got.flushes == 3 && got.ends == 0,
                  "%s, %s buffer, in steps of 3 lines: flush 3 fails -> status %d, %d flushes, %d end", bn,
                  two ? "double" : "single", rc, got.flushes, got.ends);
        }

        /* stats may be NULL: the same image */
        sink_init(&got, 0, 4, true);
        int rc = be->render(&opts[0], &got.sink, NULL, &err);
        CHECK(rc == 0 && memcmp(got.img, ref[0].img, sizeof got.img) == 0, "%s: stats NULL: status %d, same image",
              bn, rc);

        /* progressive display: one sample and uniform anti-aliasing, the
         * frame and viewports on the 8-pixel grid, bands of 1, 3 and 5
         * lines (fewer than a block's 8), tight and padded, one buffer
         * and two, in one call and in steps of one row: the frame's
         * pixels, passes 1..7 ended in order, the rest untouched */
        {
            const rt_viewport_t pvs[] = { { 0, 0, W, H }, { 8, 8, 24, 16 }, { 16, 8, W - 16, H - 8 } };
            const struct {
                int lines;
                bool padded, two;
            } bands[] = { { 1, true, false }, { 3, true, true }, { 5, false, true } };
            int ok = 0, total = 0;
            for (int m = 0; m < MODES; m += 3)
                for (size_t i = 0; i < sizeof pvs / sizeof pvs[0]; i++)
                    for (size_t k = 0; k < sizeof bands / sizeof bands[0]; k++)
                        for (int stepped = 0; stepped < 2; stepped++) {
                            rt_render_opts_t o = opts[m];
                            o.viewport = pvs[i];
                            o.progressive = RT_PROGRESSIVE_ALL;
                            sink_init(&got, bands[k].padded ? (size_t)pvs[i].w * 3 + 7 : 0, bands[k].lines,
                                      bands[k].two);
                            got.vp_w = pvs[i].w;
                            got.sink.pass_end = t_pass_end;
                            rc = stepped ? be->render_steps(&o, &got.sink, &st, &err, 1, NULL, NULL)
                                         : be->render(&o, &got.sink, &st, &err);
                            static const uint8_t in_order[] = { 1, 2, 3, 4, 5, 6, 7 };
                            bool good = rc == 0 && !got.bad_area && got.ends == 1 && got.n_passes == 7 &&
                                        memcmp(got.passes, in_order, 7) == 0 && same_crop(&got, &ref[m], pvs[i]);
                            total++;
                            ok += good;
                            if (!good)
                                printf("        %s%s progressive: viewport %u,%u %ux%u, %d-line bands%s: status %d %s\n",
                                       bn, mode_name[m], pvs[i].x, pvs[i].y, pvs[i].w, pvs[i].h, bands[k].lines,
                                       stepped ? ", stepped" : "", rc, rc < 0 ? err.msg : "");
                        }
            CHECK(ok == total, "%s: progressive: %d of %d renders (one sample and SPP 3, 3 viewports, 3 band "
                  "shapes, one call and stepped) give the scanline frame's pixels and end passes 1..7", bn, ok, total);
            /* each pass alone, in two bands of lines on the grid (as two
             * cores share a pass), passes 1..7 one after the other into
             * one sink: the whole frame's pixels */
            {
                const rt_viewport_t halves[2] = { { 0, 0, W, 16 }, { 0, 16, W, H - 16 } };
                sink_init(&got, 0, 2, true);
                got.vp_w = W;
                got.sink.pass_end = t_pass_end;
                rc = 0;
                for (uint8_t p = 1; p <= RT_PROGRESSIVE_PASSES && rc == 0; p++)
                    for (int k = 0; k < 2 && rc == 0; k++) {
                        rt_render_opts_t o = opts[0];
                        o.viewport = halves[k];
                        o.progressive = p;
                        rc = be->render(&o, &got.sink, &st, &err);
                    }
                static const uint8_t twice[] = { 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7 };
                CHECK(rc == 0 && !got.bad_area && got.n_passes == 14 && memcmp(got.passes, twice, 14) == 0 &&
                          memcmp(got.img, ref[0].img, sizeof got.img) == 0,
                      "%s: progressive, each pass alone in two bands of lines: the whole frame (status %d %s)", bn, rc,
                      rc < 0 ? err.msg : "");
            }
            /* refused before any flush: no such pass, SPD mode, adaptive
             * anti-aliasing, a viewport off the grid (x, y, right, bottom) */
            {
                rt_render_opts_t bad[7] = { opts[0], opts[1], opts[2], opts[0], opts[0], opts[0], opts[0] };
                bad[0].progressive = RT_PROGRESSIVE_PASSES + 1;
                for (int k = 1; k < 7; k++)
                    bad[k].progressive = RT_PROGRESSIVE_ALL;
                bad[3].viewport = (rt_viewport_t){ 4, 0, 8, 8 };
                bad[4].viewport = (rt_viewport_t){ 0, 4, 8, 8 };
                bad[5].viewport = (rt_viewport_t){ 0, 0, 12, 8 };
                bad[6].viewport = (rt_viewport_t){ 0, 0, 8, 12 };
                int refused = refused_count(be, bad, 7, "progress", bn, "progressive", &err);
                CHECK(refused == 7, "%s: %d of 7 bad progressive options refused before any flush (last: '%s')", bn,
                      refused, err.msg);
            }
            rt_render_opts_t o = opts[0];
            o.progressive = RT_PROGRESSIVE_ALL;
            sink_init(&got, 0, 4, true);
            got.fail_at = 5;
            rc = be->render(&o, &got.sink, &st, &err);
            CHECK(rc == 42 && got.flushes == 5 && got.ends == 0 && !got.sink.flushing,
                  "%s: progressive, flush 5 fails -> status %d, %d flushes, %d end", bn, rc, got.flushes, got.ends);
        }

        /* viewports, tight and padded pitch, every mode */
        for (int m = 0; m < MODES; m++) {
            int ok = 0, total = 0;
            for (size_t i = 0; i < n_vps; i++) {
                for (int padded = 0; padded < 2; padded++) {
                    rt_render_opts_t o = opts[m];
                    o.viewport = vps[i];
                    sink_init(&got, padded ? (size_t)vps[i].w * 3 + 7 : 0, 3, padded);
                    rc = be->render(&o, &got.sink, &st, &err);
                    bool good = rc == 0 && !got.bad_area && got.ends == 1 && same_crop(&got, &ref[m], vps[i]);
                    total++;
                    ok += good;
                    if (!good)
                        printf("        %s%s: viewport %u,%u %ux%u pitch %s: status %d%s\n", bn, mode_name[m],
                               vps[i].x, vps[i].y, vps[i].w, vps[i].h, padded ? "padded" : "tight", rc,
                               rc < 0 ? err.msg : "");
                }
            }
            CHECK(ok == total, "%s%s: %d of %d viewports (x %zu rectangles, tight and padded pitch) "
                  "byte-identical to the crop of the whole frame, the rest untouched", bn, mode_name[m], ok, total,
                  n_vps);
        }
        /* anti-aliasing's refusals: no scratch, a short one, with SPD, both kinds, too many levels or samples */
        {
            rt_render_opts_t bad[6] = { opts[2], opts[2], opts[2], opts[2], opts[2], opts[3] };
            bad[0].scratch = NULL;
            bad[1].scratch_bytes = RT_RENDER_AA_SCRATCH(W, 3) / 4; /* (the fixed build's size is half double's) */
            bad[2].spd = true;
            bad[3].spp = 2;
            bad[4].aa_levels = RT_AA_MAX_LEVELS + 1;
            bad[5].spp = RT_AA_MAX_SPP + 1;
            int refused = refused_count(be, bad, 6, "", bn, "anti-aliasing", &err);
            CHECK(refused == 6, "%s: %d of 6 bad anti-aliasing options refused before any flush (last: '%s')", bn,
                  refused, err.msg);
        }

        /* split decisions: recorded, replayed */
        {
            rt_render_opts_t rec = opts[2];
            rec.aa_splits_mode = RT_AA_SPLITS_RECORD;
            rec.aa_splits = splits[b];
            rec.aa_splits_words = SPLIT_WORDS;
            sink_init(&got, 0, 4, true);
            rc = be->render(&rec, &got.sink, &split_stats[b], &err);
            CHECK(rc == 0 && memcmp(got.img, ref[2].img, sizeof got.img) == 0,
                  "%s: recording the splits changes no pixel (status %d, %u splits)", bn, rc,
                  (unsigned)split_stats[b].aa_splits);
            rt_render_opts_t play = rec;
            play.aa_splits_mode = RT_AA_SPLITS_REPLAY;
            sink_init(&got, 0, 4, true);
            rc = be->render(&play, &got.sink, &st, &err);
            CHECK(rc == 0 && memcmp(got.img, ref[2].img, sizeof got.img) == 0,
                  "%s: replaying its own splits: its own frame (status %d)", bn, rc);
            /* a viewport: its pixels' words, those of the whole frame; no other word written */
            rt_viewport_t v = vps[4];
            memset(splits_vp, SENTINEL, sizeof splits_vp);
            rec.aa_splits = splits_vp;
            rec.viewport = v;
            sink_init(&got, 0, 4, true);
            rc = be->render(&rec, &got.sink, &st, &err);
            const size_t pw = RT_AA_SPLIT_WORDS(3);
            int wrong = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    bool in = x >= v.x && x < v.x + v.w && y >= v.y && y < v.y + v.h;
                    for (size_t k = 0; k < pw; k++) {
                        size_t i = ((size_t)y * W + (size_t)x) * pw + k;
                        wrong += in ? splits_vp[i] != splits[b][i] : splits_vp[i] != 0xA5A5A5A5u;
                    }
                }
            CHECK(rc == 0 && wrong == 0, "%s: a viewport records the whole frame's words for its pixels alone "
                  "(%d wrong)", bn, wrong);
            play.viewport = v;
            sink_init(&got, 0, 2, false);
            rc = be->render_steps(&play, &got.sink, &st, &err, 3, NULL, NULL);
            CHECK(rc == 0 && same_crop(&got, &ref[2], v), "%s: a viewport replayed in steps of 3 lines: the crop "
                  "of the whole frame (status %d)", bn, rc);
            if (b == 1) { /* the double build at the fixed build's samples */
                rt_stats_t fx = { 0 };
                play = opts[2];
                play.aa_splits_mode = RT_AA_SPLITS_REPLAY;
                play.aa_splits = splits[0];
                play.aa_splits_words = SPLIT_WORDS;
                sink_init(&got, 0, 4, true);
                rc = be->render(&play, &got.sink, &fx, &err);
                CHECK(rc == 0 && fx.eye_rays == split_stats[0].eye_rays && fx.aa_splits == split_stats[0].aa_splits,
                      "double replaying the fixed build's splits: %u eye rays, %u splits (fixed: %u, %u; its own: "
                      "%u, %u)", (unsigned)fx.eye_rays, (unsigned)fx.aa_splits, (unsigned)split_stats[0].eye_rays,
                      (unsigned)split_stats[0].aa_splits, (unsigned)split_stats[1].eye_rays,
                      (unsigned)split_stats[1].aa_splits);
            }
            /* refusals: no adaptive anti-aliasing (one sample, uniform), no buffer, a short one, no such mode */
            rt_render_opts_t bad[5] = { opts[0], opts[3], opts[2], opts[2], opts[2] };
            for (int k = 0; k < 5; k++) {
                bad[k].aa_splits_mode = RT_AA_SPLITS_RECORD;
                bad[k].aa_splits = splits_vp;
                bad[k].aa_splits_words = SPLIT_WORDS;
            }
            bad[2].aa_splits = NULL;
            bad[3].aa_splits_words = SPLIT_WORDS - 1;
            bad[4].aa_splits_mode = RT_AA_SPLITS_REPLAY + 1;
            int refused = refused_count(be, bad, 5, "", bn, "split", &err);
            CHECK(refused == 5, "%s: %d of 5 bad split options refused before any flush (last: '%s')", bn, refused,
                  err.msg);
        }

        rt_render_opts_t o = opts[0];
        o.viewport = (rt_viewport_t){ W - 2, 0, 3, 1 };
        sink_init(&got, 0, 3, false);
        rc = be->render(&o, &got.sink, &st, &err);
        CHECK(rc == -1 && got.flushes == 0, "%s: a viewport over the frame's edge is refused: %d '%s'", bn, rc,
              err.msg);

        /* the incremental API */
        for (int m = 0; m < MODES; m++) {
            const uint16_t steps[] = { 1, 3, 7 };
            for (size_t k = 0; k < 3; k++) {
                sink_init(&got, 0, 4, true);
                rc = be->render_steps(&opts[m], &got.sink, &st, &err, steps[k], NULL, NULL);
                bool whole = rc == 0 && got.ends == 1 && memcmp(got.img, ref[m].img, sizeof got.img) == 0;
                rt_render_opts_t ov = opts[m];
                ov.viewport = vps[4];
                sink_init(&got, 0, 2, false);
                rc = be->render_steps(&ov, &got.sink, &st, &err, steps[k], NULL, NULL);
                bool part = rc == 0 && got.ends == 1 && same_crop(&got, &ref[m], vps[4]);
                CHECK(whole && part, "%s%s: steps of %u lines == one call (whole frame %s, viewport %s)", bn,
                      mode_name[m], steps[k], whole ? "same" : "DIFFERS", part ? "same" : "DIFFERS");
            }
        }
    }
    return tl_summary("test_hal");
}
