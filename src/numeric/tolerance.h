/*
 * tolerance.h - every robustness epsilon of the core, per numeric backend.
 *
 * Lengths are in scene units after the reader's power-of-two scale, so the
 * geometry's largest coordinate lies in [8, 16) and no hit is farther than
 * 64 from a ray's origin.
 *
 * - double (the reference) renders the model of docs/shading-model.md:
 *   its epsilons come from double precision, about 1e-9 of the scene's
 *   extent or less, never from the fixed format;
 * - fixed and float use the smallest values their rounding needs, with
 *   the derivation beside each;
 * - RT_TOLERANCES_FIXED=1 gives the double backend the fixed build's
 *   values (`rt --double-ftol`), so an image's error against the
 *   reference splits into "number format" and "tolerances".
 *
 * Secondary rays need no surface offset where geometry rules a self-hit
 * out (ray_t.from in ray.h, leave() in trace.c): a plane is never met
 * again by a ray leaving it, a ray leaving a sphere's or cone's outside
 * never comes back, and a ray going in meets that surface only at its far
 * root. Only solids (quadrics, tori, boxes, CSG) keep an offset, and
 * polygons in the float build (RT_SOLID_OFFSET, RT_TORUS_OFFSET,
 * RT_PLANE_OFFSET).
 */
#ifndef TOLERANCE_H
#define TOLERANCE_H

#include "real.h"

#ifndef RT_TOLERANCES_FIXED
#define RT_TOLERANCES_FIXED 0
#endif
_Static_assert(!RT_TOLERANCES_FIXED || RT_BACKEND_DOUBLE, "RT_TOLERANCES_FIXED is for the double backend");

#if RT_BACKEND_FIXED || RT_TOLERANCES_FIXED
/* ---- fixed point (1 ulp = 2^-F; R_ULPS counts them in any backend) ---- */

/* Nearest accepted hit: one unit of the last place. */
#define RT_T_MIN R_ULPS(1)
/* Bounding-box padding: a reciprocal is good to 2^-(F+1) relative, so over
 * the longest ray (64) a slab plane moves by less than 2^(5-F), which this
 * exceeds; it also covers a polygon's rounded inside test. */
#if FX_FRAC_BITS < 18
#define RT_BOX_SLACK R_RATIO(1, (int32_t)1 << (FX_FRAC_BITS - 6))
#else
#define RT_BOX_SLACK R_RATIO(1, 4096)
#endif
/* BVH slab test: axes with |d| below this would have a reciprocal too
 * large for the 64-bit products (|1/d| < 2^(29-F)); they are treated as
 * parallel, plus the drift d * tmax and this margin. */
#define RT_SLAB_PARALLEL R_RATIO(1, (int64_t)1 << (29 - FX_FRAC_BITS))
#define RT_SLAB_MARGIN R_ULPS(4)
/* Solids, in object space (shape.c): a box axis whose direction is below
 * this is parallel (its reciprocal would leave the range); a quadric whose
 * sigma^2 coefficient is below this is solved as linear; bounding spheres
 * are padded by this; a torus root is bracketed (shape.c) until the
 * bracket or the safe step is below RT_TORUS_TOL, in at most
 * RT_TORUS_STEPS iterations, and spans shorter than 4 RT_TORUS_EPS are
 * tangent touches (no span). */
#define RT_OBJ_PARALLEL R_RATIO(1, 1 << 12)
#define RT_QUADRIC_LINEAR R_RATIO(1, 1 << 14)
#define RT_BOUND_PAD R_ULPS(16)
#define RT_TORUS_EPS R_RATIO(1, 8192)
#define RT_TORUS_TOL R_ULPS(1)
#define RT_TORUS_STEPS 256
/* Origin offset of secondary rays leaving a solid, along the geometric
 * normal (a CSG solid may be met again anywhere, so no skipping). A
 * solid's hit point error, its distance from the exact surface: the world
 * ray goes through M^-1 (each component rounded to 1/2 ulp), its direction
 * is renormalised (k = |M^-1 d|, 1 ulp relative), the roots are found
 * near the point of closest approach (|sigma| <= the bound radius, so the
 * 1 ulp relative errors stay a few ulps), world t = s / k adds 1/2 ulp and
 * the world point O + t D 0.87. test_geometry measures at most 17.2 ulps
 * (paraboloid; 20000 random rays per shape) and asserts at most half of
 * this offset. */
#define RT_SOLID_OFFSET R_ULPS(64)
/* Rays leaving a polygon skip it, and the fixed build computes a plane's
 * hit exactly in 64 bits before one rounding (<= 1 ulp from the plane), so
 * a neighbour sharing an edge is never met by rounding: no offset. */
#define RT_PLANE_OFFSET 0

#elif RT_BACKEND_FLOAT
/* ---- single precision: a float's unit in the last place at the scene's
 * largest coordinate (16) is 2^-20, the same length as a Q11.20 ulp, and
 * finer below it; the fixed derivations carry over with U for the ulp. */
#define RT_FLOAT_ULP ((real_t)0x1p-20f)
#define RT_T_MIN RT_FLOAT_ULP
#define RT_BOX_SLACK R_RATIO(1, 4096)
#define RT_SLAB_PARALLEL ((real_t)0x1p-40f)
#define RT_SLAB_MARGIN (4 * RT_FLOAT_ULP)
#define RT_OBJ_PARALLEL ((real_t)0x1p-40f)
#define RT_QUADRIC_LINEAR ((real_t)0x1p-40f)
#define RT_BOUND_PAD (16 * RT_FLOAT_ULP)
#define RT_TORUS_EPS ((real_t)0x1p-13f)
#define RT_TORUS_TOL RT_FLOAT_ULP
#define RT_TORUS_STEPS 256
#define RT_SOLID_OFFSET (64 * RT_FLOAT_ULP)
/* A float plane distance N . O - c rounds each of its three products and
 * sums (|O| <= 32): up to 3 * 32 * 2^-24 = 6 ulps off the plane, so a
 * neighbour sharing an edge could be met; rays leaving a polygon start
 * beyond that. */
#define RT_PLANE_OFFSET (8 * RT_FLOAT_ULP)

#else
/* ---- double, the reference: a double's ulp at 16 is 2^-48; every length
 * below is at least 2^8 of those (rounding) and at most ~1e-9 of the
 * extent (so the image is the model's). */
#define RT_T_MIN ((real_t)0x1p-40)
#define RT_BOX_SLACK ((real_t)0x1p-30)
#define RT_SLAB_PARALLEL ((real_t)0x1p-60)
#define RT_SLAB_MARGIN ((real_t)0x1p-40)
#define RT_OBJ_PARALLEL ((real_t)0x1p-60)
#define RT_QUADRIC_LINEAR ((real_t)0x1p-40)
#define RT_BOUND_PAD ((real_t)0x1p-30)
/* roots bracketed to 2^-44; spans under 4 2^-24 are tangent touches */
#define RT_TORUS_EPS ((real_t)0x1p-24)
#define RT_TORUS_TOL ((real_t)0x1p-44)
#define RT_TORUS_STEPS 4096
#define RT_SOLID_OFFSET ((real_t)0x1p-30)
#define RT_PLANE_OFFSET 0
#endif

/* A torus boundary is found to within RT_TORUS_TOL (shape.c); rays
 * leaving a torus keep the wider offset of the sphere-tracing march it
 * replaced (test_geometry measures the hit points' distance to the exact
 * surface against half of it). */
#define RT_TORUS_OFFSET (4 * RT_TORUS_EPS)

/* Farthest hit distance (the end of the fixed range). */
#define RT_T_FAR R_BIG

#endif
