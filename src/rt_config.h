/*
 * rt_config.h - every compile-time knob of the core in one place.
 *
 * Each value can be overridden from the compiler command line
 * (-DRT_MAX_SPHERES=4096 ...). The defaults fit a small microcontroller
 * scene; the hosted build raises them (see the Makefile) so that the SPD
 * "default" scenes load.
 */
#ifndef RT_CONFIG_H
#define RT_CONFIG_H

/* Numeric backend: 0 = fixed point (the product), 1 = double (reference). */
#ifndef RT_BACKEND_DOUBLE
#define RT_BACKEND_DOUBLE 0
#endif

/* Fraction bits of the fixed-point scalar: Q(31-F).F. */
#ifndef FX_FRAC_BITS
#define FX_FRAC_BITS 16
#endif

/* Ray-tree depth: eye ray = 1. RT_MAX_DEPTH bounds recursion (and stack);
 * the run-time depth option may only lower it. */
#ifndef RT_MAX_DEPTH
#define RT_MAX_DEPTH 5
#endif

/* Object tables. */
#ifndef RT_MAX_SPHERES
#define RT_MAX_SPHERES 128
#endif
#ifndef RT_MAX_CONES
#define RT_MAX_CONES 256
#endif
#ifndef RT_MAX_POLYGONS          /* 'p' and 'pp' entities together */
#define RT_MAX_POLYGONS 512
#endif
#ifndef RT_MAX_VERTICES          /* vertex pool shared by all polygons */
#define RT_MAX_VERTICES 2048
#endif
#ifndef RT_MAX_POLY_VERTS        /* vertices of one polygon */
#define RT_MAX_POLY_VERTS 256
#endif
#ifndef RT_MAX_LIGHTS
#define RT_MAX_LIGHTS 8
#endif
#ifndef RT_MAX_MATERIALS
#define RT_MAX_MATERIALS 64
#endif

/* Largest image side accepted (bounds the per-line work buffers). */
#ifndef RT_MAX_WIDTH
#define RT_MAX_WIDTH 4096
#endif
#ifndef RT_MAX_HEIGHT
#define RT_MAX_HEIGHT 4096
#endif

/* Keeps a helper's locals out of the recursive trace_ray frame, which is
 * what bounds the stack (RT_MAX_DEPTH frames of it). */
#if defined(__GNUC__)
#define RT_NOINLINE __attribute__((noinline))
#else
#define RT_NOINLINE
#endif

_Static_assert(RT_MAX_DEPTH >= 1 && RT_MAX_DEPTH <= 16, "RT_MAX_DEPTH out of 1..16");
_Static_assert(FX_FRAC_BITS >= 8 && FX_FRAC_BITS <= 24, "FX_FRAC_BITS out of 8..24");
_Static_assert(RT_MAX_POLY_VERTS >= 3 && RT_MAX_POLY_VERTS <= 65535, "RT_MAX_POLY_VERTS out of 3..65535");
_Static_assert(RT_MAX_POLYGONS <= 0xFFFFFF && RT_MAX_SPHERES <= 0xFFFFFF && RT_MAX_CONES <= 0xFFFFFF,
               "primitive indices are 24-bit");
_Static_assert(RT_MAX_MATERIALS >= 1 && RT_MAX_MATERIALS <= 65535, "materials are indexed by uint16_t");
_Static_assert(RT_MAX_LIGHTS >= 1 && RT_MAX_LIGHTS <= 255, "RT_MAX_LIGHTS out of 1..255");

#endif
