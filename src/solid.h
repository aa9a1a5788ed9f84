/*
 * solid.h - solids beyond NFF: quadrics, tori and boxes in their own
 * object space, placed by affine transforms, and combined by CSG.
 *
 * A ray meets a solid in "spans" (the stretches of t inside it); CSG
 * combines span lists by union, intersection and difference, and the
 * nearest hit is the first span boundary past tmin. Every boundary
 * remembers the shape whose surface it is, which face of it (the curved
 * surface, or one of the six faces of a box or clip box) and whether the
 * solid's outward normal is the shape's inward one (subtracted parts).
 */
#ifndef SOLID_H
#define SOLID_H

#include <stdbool.h>

#include "geometry.h"

/* ---- transforms (the reader composes them; the tracer only applies) -- */

void xform_identity(xform_t *x);
void xform_translate(xform_t *x, vec3_t v);
void xform_scale(xform_t *x, vec3_t s);
/* Rotation by deg degrees about the (unit) axis. */
void xform_rotate(xform_t *x, vec3_t axis, real_t deg);
vec3_t xform_point(const xform_t *x, vec3_t p);
/* A normal from object to world space: by the inverse transpose, unit. */
vec3_t xform_normal(const xform_t *x, vec3_t n);

/* ---- shapes ------------------------------------------------------------ */

/* Face tags of a boundary: the curved surface, or a box/clip-box face. */
enum { FACE_CURVED = 0, FACE_XMIN, FACE_XMAX, FACE_YMIN, FACE_YMAX, FACE_ZMIN, FACE_ZMAX };

/* Object-space set-up: each returns NULL or why the shape is degenerate. */
const char *shape_init_quadric(shape_t *s, const real_t q[10], vec3_t lo, vec3_t hi);
const char *shape_init_torus(shape_t *s, real_t major, real_t minor);
const char *shape_init_box(shape_t *s, vec3_t lo, vec3_t hi);

/* World-space box holding the shape (all of it, with rounding slack). */
void shape_world_box(const scene_t *sc, const shape_t *s, vec3_t *min, vec3_t *max);

/* Most spans a ray can have through this shape or CSG tree (the reader
 * checks it against RT_CSG_MAX_SPANS), and the tree's depth. */
uint32_t solid_max_spans(const scene_t *sc, uint16_t root);
uint32_t solid_depth(const scene_t *sc, uint16_t root);

/* ray_hit_object, the nearest boundary of an object: object.h. */

/* Outward unit normal (world space) of a shape's face at world point p. */
vec3_t shape_normal(const scene_t *sc, uint16_t shape, uint8_t face, vec3_t p);

#endif
