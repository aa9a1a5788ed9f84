/*
 * xform.h - affine transforms of solids: world = M p + t, with M^-1 kept
 * beside M. The reader composes them; the tracer only applies them.
 *
 * The solids' layers (each file uses only the ones below it):
 *   csg.c     CSG trees: span lists combined, the nearest boundary
 *   shape.c   quadrics, tori, boxes: set-up, spans, normals
 *   xform.c   transforms (this layer)
 */
#ifndef XFORM_H
#define XFORM_H

#include "scene.h"
#include "numeric/vec3.h"

void xform_identity(xform_t *x);
void xform_translate(xform_t *x, vec3_t v);
void xform_scale(xform_t *x, vec3_t s);
/* Rotation by deg degrees about the (unit) axis. */
void xform_rotate(xform_t *x, vec3_t axis, real_t deg);
vec3_t xform_point(const xform_t *x, vec3_t p);
/* A normal from object to world space: by the inverse transpose, unit. */
vec3_t xform_normal(const xform_t *x, vec3_t n);

/* m v, each row summed wide. Out of line: inlined into the per-ray code
 * it costs the board both code and instructions (register pressure). */
vec3_t xform_mat_vec(const mat3_t *m, vec3_t v);

/* World to object, a point: M^-1 (p - t). The one place this is written. */
static inline vec3_t xform_to_object(const xform_t *x, vec3_t p)
{
    return xform_mat_vec(&x->im, v3(p.x - x->t[0], p.y - x->t[1], p.z - x->t[2]));
}

/* World to object, a direction: M^-1 d (not renormalised). */
static inline vec3_t xform_dir_to_object(const xform_t *x, vec3_t d)
{
    return xform_mat_vec(&x->im, d);
}

#endif
