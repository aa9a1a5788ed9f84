/* frame.h - what the parts of render.c's unit share (frame_setup.h,
 * aa.h): the worker that a render writes (render.c owns one per core),
 * and the eye sample the flat search culls by. */
#ifndef FRAME_H
#define FRAME_H

#include "rt_render.h"

#include "geometry/camera.h"
#include "geometry/scene_hit.h"
#include "trace.h"

/* Everything a render writes, one per worker: static, so the stack stays
 * small, and one each, so renders on other cores or threads share none. */
struct rt_worker {
    rt_render_ctx_t ctx; /* rt_render's */
    camera_t cam;
    camera_row_t row; /* the row of eye rays being made: off the stack */
    tracer_t tr;
    prim_ref_t last_blocker[RT_MAX_LIGHTS];
    material_terms_t terms[RT_MAX_DEPTH];
    ray_scratch_t scratch;
#if RT_USE_AA
    real_t aa_threshold; /* adaptive: a corner spread that splits a square */
    real_t aa_scale;     /* 1 / (corners or samples a pixel sums) */
#if RT_AA_REPLAY
    uint32_t *splits;    /* the frame's split decisions (opts.aa_splits), or NULL */
    size_t splits_line;  /* words a frame line */
    unsigned split_words; /* words a pixel */
    bool splits_replay;  /* replayed, not recorded */
#endif
#endif
};

/* The sample of the eye ray about to be traced (camera.h's offsets), for
 * the flat search's culling (scene_eye_setup). */
static RT_INLINE void eye_sample(struct rt_worker *wk, int32_t k, int32_t m)
{
#if RT_USE_FLAT
    wk->scratch.eye_k = k;
    wk->scratch.eye_m = m;
#else
    (void)wk, (void)k, (void)m;
#endif
}

#endif
