/* rt_render.h - render a scene line by line into a framebuffer sink. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include "rt_fb.h"
#include "rt_error.h"
#include "rt_config.h"
#include "rt_stats.h"

/* A scene: tables the scene compiler wrote into flash (rt_scene), or
 * what rt_nff_load read (rt.h). */
typedef struct scene rt_scene_t;

/* A rectangle of the frame, in frame pixels (as LVGL's lv_area_t, but
 * origin and size). w = h = 0: the whole frame. */
typedef struct {
    uint16_t x, y, w, h;
} rt_viewport_t;

/* A viewpoint as NFF's 'v', in the scene file's units, every value in
 * Q16.16 (times 65536), so setting one needs no floating point: from,
 * at, up, and the full field of view in degrees (0 < angle < 180). */
typedef struct {
    int32_t from[3], at[3], up[3];
    int32_t angle;
} rt_view_t;
#define RT_Q16(v) ((int32_t)((v) * 65536.0 + ((v) < 0 ? -0.5 : 0.5))) /* a constant in Q16.16 */

/* A viewpoint ready for a scene (opts.camera); its contents are the
 * core's. */
typedef struct rt_camera {
    int64_t opaque[12];
} rt_camera_t;

typedef struct {
    uint16_t width, height; /* 0: the scene's resolution */
    /* The camera: NULL for the scene's own viewpoint, or another one made
     * by rt_camera_from_view (the scene stays const, in flash too). */
    const struct rt_camera *camera;
    /* Only these pixels are rendered and flushed, each the same as in the
     * whole frame (SPD mode included); the sink's areas are in frame
     * coordinates and its buffer lines hold the viewport's columns. */
    rt_viewport_t viewport;
    uint8_t max_depth;      /* 0: RT_DEFAULT_DEPTH */
    /* Adaptive depth: a child ray whose share of the pixel (product of
     * Ks and T along its path) is below adaptive_milli / 1000 is not
     * traced. 0 = off (the default). */
    uint16_t adaptive_milli;
    /* SPD mode: (W+1) x (H+1) corner rays, each pixel the mean of its four
     * corners, and SPD rule 8. Needs `scratch` for two rows of corner
     * colours: at least RT_RENDER_SPD_SCRATCH(width) bytes (the viewport's
     * width if one is set). */
    bool spd;
    /* Anti-aliasing (RT_USE_AA), each pixel the mean over its square of
     * the model's colour, clamped (docs/shading-model.md, "Pixel area"):
     *   aa_levels 1..RT_AA_MAX_LEVELS: adaptive. Samples at the pixel's
     *     corners (shared with its neighbours); a square whose corners
     *     differ by more than aa_threshold / 255 in a channel is split in
     *     four, down to aa_levels times; each square counts its corners'
     *     mean by its area. Needs `scratch` of at least
     *     RT_RENDER_AA_SCRATCH(width, aa_levels) bytes (the viewport's
     *     width if one is set). aa_threshold 0: RT_AA_THRESHOLD.
     *   spp 2..RT_AA_MAX_SPP: uniform, spp x spp samples at the centres
     *     of equal cells (the converged reference with many); no scratch.
     * 0 for both: one sample at the pixel's centre (the default). Neither
     * goes with SPD mode, nor with each other. */
    uint8_t aa_levels, aa_threshold, spp;
    void *scratch; /* aligned for the core's real_t (8 bytes will do) */
    size_t scratch_bytes;
    /* Which of the RT_MAX_WORKERS workers (rt_config.h) renders: renders
     * running at the same time, on other cores or threads, each need
     * their own (and their own sink and stats). 0 by default. */
    uint8_t worker;
    /* Textures sampled at the hit point, as the pixel-area image takes
     * them, instead of averaged over each ray's footprint (the default
     * where the build has RT_TEXTURE_FILTER; docs/shading-model.md,
     * "Filtered textures"). */
    bool point_textures;
    /* Progressive display, for a panel that keeps its own frame memory:
     * the frame in RT_PROGRESSIVE_PASSES passes over an interlaced
     * lattice (Adam7's), each traced pixel painted over its block:
     *   pass  samples of each 8x8 tile     block     tile after the pass
     *   1     (0, 0)                       8 x 8     1 sample
     *   2     (4, 0)                       4 x 8     2
     *   3     (0, 4) (4, 4)                4 x 4     4
     *   4     x = 2, 6; y = 0, 4           2 x 4     8
     *   5     x = 0, 2, 4, 6; y = 2, 6     2 x 2     16
     *   6     odd x, even y                1 x 2     32
     *   7     odd y                        1 x 1     64
     * so after pass p pixel (x, y) shows the pixel traced at the corner
     * of its cell of the lattice so far (8x8, 4x8, 4x4, 2x4, 2x2, 1x2,
     * 1x1), and after pass 7 each pixel is the one scanline order gives:
     * every pixel traced once, the same rays. 0: scanline order (the
     * default); RT_PROGRESSIVE_ALL: every pass; 1..7: pass p alone (two
     * cores can share a pass as bands). A viewport must lie on the 8x8
     * grid (each edge a multiple of 8 or the frame's), so that no block
     * crosses it. Passes 1, 3, 5, 7 flush rows of blocks, areas that span
     * the viewport (lines `pitch` apart); passes 2, 4, 6, whose blocks
     * stack down columns, flush columns of blocks, areas always narrower
     * than the viewport, their lines packed tightly. Needs whole-byte pixels (not
     * l4) and one sample a pixel or uniform anti-aliasing (spp): SPD mode
     * and adaptive anti-aliasing share corners between neighbours. */
    uint8_t progressive;
#if RT_AA_REPLAY
    /* Adaptive anti-aliasing's split decisions (builds with RT_AA_REPLAY):
     * aa_splits_mode RT_AA_SPLITS_RECORD writes each rendered pixel's
     * decisions into aa_splits; RT_AA_SPLITS_REPLAY makes them instead of
     * the corners' colours, so another numeric build with the same
     * options traces exactly the same samples. The caller's buffer of
     * aa_splits_words words holds RT_AA_SPLIT_WORDS(aa_levels) a pixel of
     * the whole frame (RT_AA_SPLITS_WORDS(width, height, aa_levels)),
     * pixel (x, y) of the frame at (y * width + x) * RT_AA_SPLIT_WORDS,
     * so a viewport or the bands of several workers share one buffer.
     * Replay with the aa_levels it was recorded with. */
    uint8_t aa_splits_mode; /* RT_AA_SPLITS_OFF (0, the default), _RECORD, _REPLAY */
    uint32_t *aa_splits;
    size_t aa_splits_words;
#endif
} rt_render_opts_t;

#define RT_PROGRESSIVE_PASSES 7
#define RT_PROGRESSIVE_ALL 0xFF
/* Whether pass p's blocks stack down columns (2, 4, 6: each block as tall
 * as its samples are apart), which render.c walks and flushes a column at
 * a time; the others' blocks touch along rows. Several cores share such a
 * pass best as strips of columns, the others as bands of lines. */
#define RT_PROGRESSIVE_BY_COLUMNS(p) ((p) % 2u == 0u)

/* A pixel's split decisions (opts.aa_splits): two bits for each square
 * that may split, at level l < levels (the pixel is level 0, 2^l squares
 * a side), square (a, b) counted from the pixel's top left: bit 2 q, its
 * corners spread over the threshold (its centre is traced), and bit
 * 2 q + 1, it is split in four; q = (4^l - 1) / 3 + b 2^l + a. By
 * position alone: the same in whatever order the squares are visited. */
#define RT_AA_SPLITS_OFF 0
#define RT_AA_SPLITS_RECORD 1
#define RT_AA_SPLITS_REPLAY 2
#define RT_AA_SPLIT_BITS(levels) (2 * ((((size_t)1) << (2 * (levels))) - 1) / 3)
#define RT_AA_SPLIT_WORDS(levels) ((RT_AA_SPLIT_BITS(levels) + 31) / 32)
#define RT_AA_SPLITS_WORDS(width, height, levels) ((size_t)(width) * (size_t)(height) * RT_AA_SPLIT_WORDS(levels))

/* Scratch sizes in colours (three scalars each) and in bytes. SPD mode:
 * two rows of corner colours. Adaptive anti-aliasing: two rows of
 * cell-corner colours, and the rows inside one pixel (on the M3, 128
 * pixels wide: 12,492 bytes at 2 levels, 25,356 at 3). */
#define RT_RENDER_SPD_COLOURS(width) (2 * ((size_t)(width) + 1))
#define RT_RENDER_AA_COLOURS(width, levels) \
    (2 * (((size_t)(width) << (levels)) + 1) + ((size_t)1 << (2 * (levels))) - 1)
#define RT_RENDER_SPD_SCRATCH(width) (RT_RENDER_SPD_COLOURS(width) * 3 * RT_REAL_BYTES)
#define RT_RENDER_AA_SCRATCH(width, levels) (RT_RENDER_AA_COLOURS(width, levels) * 3 * RT_REAL_BYTES)


/* Another viewpoint for scene sc: 0, or -1 with *err set when a position
 * lies beyond the range the reader allows the camera (RT_FAR_EXTENT_LOG2
 * times the scene's extent) or the view is degenerate (up along the line
 * of sight, from == at, angle out of (0, 180)). Linked only when called. */
int rt_camera_from_view(rt_camera_t *cam, const rt_scene_t *sc, const rt_view_t *view, rt_error_t *err);

/* The whole frame (or opts->viewport) in one call: 0 on success; a sink's
 * non-zero status (begin or flush; end() is then not called), or -1 with
 * *err set. stats may be NULL; the render's counts are added to it. One
 * render at a time per worker (opts->worker): its camera and tracer state
 * are static. */
int rt_render(const rt_scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink, rt_stats_t *stats,
              rt_error_t *err);

/* The same in steps, for a caller with other work between them (a UI
 * loop, a watchdog): the caller owns the context, nothing is allocated.
 *
 *     rt_render_ctx_t ctx;
 *     int st = rt_render_begin(&ctx, sc, &opts, &sink, NULL, &err);
 *     while (st == 0 && !rt_render_done(&ctx))
 *         st = rt_render_step(&ctx, 4);      (up to 4 lines, then return)
 *     if (st == 0)
 *         st = rt_render_end(&ctx);          (waits for the last flush, end())
 *
 * begin checks the options and calls the sink's begin(): 0, -1 with *err
 * set, or the sink's status. step renders up to `lines` lines, flushing
 * each band as it fills: 0, or a flush's non-zero status (the frame is
 * then over: rt_render_done, and end() is not to be called). end waits for
 * the flushes in flight and returns the sink's end() status. The pixels
 * are the same however the frame is stepped; the counts are added to
 * *stats at the end of each step.
 *
 * Two cores or threads render one frame as bands: each its own viewport
 * of whole lines, its own worker, sink and stats (docs/boards.md, "Two cores").
 * Every pixel is the same as in the whole frame. */
typedef struct {
    rt_fb_sink_t *sink;
    size_t pitch, band_lines;
    uint16_t x0, w;            /* the viewport's columns */
    uint16_t y, y_end, band_y; /* next line, end, first line of the band */
    uint16_t y0;               /* the viewport's first line */
    uint16_t x;                /* progressive: the next column of blocks (passes 2, 4, 6) */
    uint8_t pass, last_pass;   /* progressive: the pass under way, the last (0: scanline order) */
    unsigned cur;              /* the band buffer being filled */
    bool spd;
    uint8_t aa_levels, spp;    /* anti-aliasing: as the options say */
    void *rows[2];             /* SPD or AA corner rows (in the scratch) */
    void *cells;               /* AA: one pixel's cell corners (in the scratch) */
    struct rt_worker *worker;  /* the core's state for this render (frame.h) */
    rt_stats_t *stats;         /* the caller's, or NULL */
} rt_render_ctx_t;

int rt_render_begin(rt_render_ctx_t *ctx, const rt_scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink,
                    rt_stats_t *stats, rt_error_t *err);
int rt_render_step(rt_render_ctx_t *ctx, uint16_t lines);
int rt_render_end(rt_render_ctx_t *ctx);
static inline bool rt_render_done(const rt_render_ctx_t *ctx) { return ctx->y >= ctx->y_end; }

#endif
