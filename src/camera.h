/* camera.h - the shading model's pinhole camera over a grid of samples. */
#ifndef CAMERA_H
#define CAMERA_H

#include <stdint.h>

#include "geometry.h"

typedef struct {
    vec3_t eye, w, u, v;    /* forward, right, image up (unit) */
    real_wide_t half_step;  /* s / 2 = tan(angle / 2) / (max(X, Y) - 1) */
    int32_t nx, ny;         /* samples per row and column */
} camera_t;

/* NULL, or why the view cannot make a camera. */
const char *camera_init(camera_t *c, const view_t *view, int32_t nx, int32_t ny);

/* The eye ray through sample (i, j), column i from the left, row j from the top. */
ray_t camera_ray(const camera_t *c, int32_t i, int32_t j);

#endif
