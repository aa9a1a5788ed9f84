/* camera.h - the shading model's pinhole camera over a grid of samples. */
#ifndef CAMERA_H
#define CAMERA_H

#include <stdint.h>

#include "geometry.h"

/* Each eye ray is built through a point T on the exact ray at the distance
 * of `at`, near the scene, and starts at `start` from the eye: a rounded
 * direction then errs only across the scene, not over the whole distance
 * from a far camera (a narrow lens from far away stays sharp). */
typedef struct {
    vec3_t eye, at, u, v;     /* T's reference point; right, image up (unit) */
    real_wide_t half_span;    /* s / 2 = tan(angle / 2) / (max(X, Y) - 1),
                               * times |at - eye|: at T's distance */
    real_t start;             /* rays start this far from the eye */
    int32_t cx, cy;           /* sample (i, j) lies (2i - cx, 2j - cy) half
                               * spans from T's reference point */
#if RT_RAY_CONES
    real_t spread;            /* eye rays' cone spread: the spacing of
                               * adjacent samples at unit distance, s / sub */
#endif
} camera_t;

/* NULL, or why the view cannot make a camera (rays start at the eye) whose
 * sample (i, j) lies 2i - cx, 2j - cy half spans from the view's centre,
 * a half span being 1 / (2 sub) of the spacing of span + 1 samples across
 * the field of view. */
const char *camera_setup(camera_t *c, const view_t *view, int32_t span, int32_t sub, int32_t cx, int32_t cy);

/* A camera of nx x ny samples (the model's X x Y grid). */
static inline const char *camera_init(camera_t *c, const view_t *view, int32_t nx, int32_t ny)
{
    return camera_setup(c, view, (nx > ny ? nx : ny) - 1, 1, nx - 1, ny - 1);
}

/* The same view for a frame of w x h pixels, each split into sub x sub
 * cells: sample (i, j) is the cell corner i / sub, j / sub pixels from the
 * frame's top left pixel corner (the pixel-area grid of
 * docs/shading-model.md). Pixel i's centre is 2i - (w - 1) of the pixel
 * camera's half spans, so (2i - (w - 1)) sub of the cells', and its left
 * corner sub of them before: corner i sub lies at 2 i sub - sub w. */
static inline const char *camera_init_cells(camera_t *c, const view_t *view, int32_t w, int32_t h, int32_t sub)
{
    return camera_setup(c, view, (w > h ? w : h) - 1, sub, sub * w, sub * h);
}

/* Start eye rays where they reach the sphere around the box [min, max]
 * (the scene's bounds), if the eye is outside it. */
void camera_start_at_bounds(camera_t *c, vec3_t min, vec3_t max);

/* A row of samples walked left to right: the fixed build's next T and
 * its step, the others' row part at - b v of T. */
typedef struct {
#if RT_BACKEND_FIXED
    real_wide_t t[3], dt[3]; /* the next sample's T, and the step to the one after (wide) */
#else
    real_wide_t row[3];      /* T's row part */
#endif
    int32_t k;     /* the next sample's 2i - cx */
    int32_t dk;    /* k's step to the sample after: 2 (camera_stride: more) */
    int32_t m;     /* the row's 2j - cy */
} camera_row_t;

/* Row j of the camera's samples, from column i. */
void camera_row(const camera_t *c, int32_t i, int32_t j, camera_row_t *row);

/* Column i's part of the walk, for samples taken down a column. */
typedef struct {
#if RT_BACKEND_FIXED
    real_wide_t kt[3], dt[3]; /* T's column part k (s/2) u, and the row step */
#endif
    int32_t k; /* 2i - cx */
} camera_column_t;
void camera_column(const camera_t *c, int32_t i, camera_column_t *col);

/* The walk of row j from column col: exactly camera_row's (camera_row is
 * these two), for the price of the row part alone. */
void camera_column_row(const camera_t *c, const camera_column_t *col, int32_t j, camera_row_t *row);

/* The eye ray through the row's next sample; steps to the one after. */
ray_t camera_next(const camera_t *c, camera_row_t *row);

/* From here on the row's walk takes every n-th sample (camera_row sets
 * n = 1): each camera_next is exactly where n of them would have left it
 * (the fixed build's step is n steps, the same integer sum). */
static inline void camera_stride(camera_row_t *row, int32_t n)
{
#if RT_BACKEND_FIXED
    for (int i = 0; i < 3; i++)
        row->dt[i] *= n;
#endif
    row->dk = 2 * n;
}

/* The eye ray through sample (i, j), column i from the left, row j from the top. */
ray_t camera_ray(const camera_t *c, int32_t i, int32_t j);

/* The samples whose eye rays may meet a sphere: 2i - cx in [box[0],
 * box[1]] and 2j - cy in [box[2], box[3]], a box that holds every one that
 * does (INT32_MIN / INT32_MAX where it is unbounded: a sphere reaching
 * behind the eye, a lens too wide). */
void camera_sphere_box(const camera_t *c, vec3_t centre, real_t radius, int32_t box[4]);

#endif
