/*
 * shape.h - the shapes of solids (layers: xform.h): quadrics, tori and
 * boxes in their own object space, placed by a transform. Set-up for the
 * reader; spans and normals for the tracer.
 */
#ifndef SHAPE_H
#define SHAPE_H

#include <stdbool.h>

#include "geometry.h"

/* Face tags of a boundary: the curved surface, or a box/clip-box face. */
enum { FACE_CURVED = 0, FACE_XMIN, FACE_XMAX, FACE_YMIN, FACE_YMAX, FACE_ZMIN, FACE_ZMAX };

/* Object-space set-up: each returns NULL or why the shape is degenerate. */
const char *shape_init_quadric(shape_t *s, const real_t q[10], vec3_t lo, vec3_t hi);
const char *shape_init_torus(shape_t *s, real_t major, real_t minor);
const char *shape_init_box(shape_t *s, vec3_t lo, vec3_t hi);

/* Sets s->wbound (scene.h) once the shape's transform is in the table. */
void shape_set_world_bound(const scene_t *sc, shape_t *s);

/* World-space box holding the shape (all of it, with rounding slack). */
void shape_world_box(const scene_t *sc, const shape_t *s, vec3_t *min, vec3_t *max);

/* Outward unit normal (world space) of a shape's face at world point p. */
vec3_t shape_normal(const scene_t *sc, uint16_t shape, uint8_t face, vec3_t p);

/* ---- spans: shape.c makes them, csg.c combines them --------------------- */

/* A span boundary: where (world t), the shape and face it lies on, and
 * whether the solid's outward normal is the shape's inward one. */
typedef struct {
    real_t t;
    uint16_t shape;
    uint8_t face;
    uint8_t flip;
} bound_t;

typedef struct {
    bound_t in, out;
} span_t;

/* Spans sorted by t, disjoint. */
typedef struct {
    uint32_t n;
    span_t s[RT_CSG_MAX_SPANS];
} spans_t;

/* Appends a span (out of line: a dozen callers, none hot enough to care). */
void spans_push(spans_t *out, bound_t in, bound_t out_b);

/* The spans of the ray through shape `id`: all of them, or (tori) those
 * meeting the window of world t [win[0], win[1]], where a span cut by the
 * window ends at t = -R_BIG or R_BIG. */
void shape_spans(const scene_t *sc, uint16_t id, const ray_t *r, const real_t win[2], spans_t *out);

#endif
