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

/* A user's configuration, as LVGL's lv_conf.h: build with
 * -DRT_CONFIG_FILE='"my_rt_config.h"' and that file's #defines replace
 * the defaults below; the checks at the end reject values out of range. */
#ifdef RT_CONFIG_FILE
#include RT_CONFIG_FILE
#endif

/* Numeric backend: fixed point (the product) unless one of these is 1:
 * double (the reference) or float (single precision, for comparison). */
#ifndef RT_BACKEND_DOUBLE
#define RT_BACKEND_DOUBLE 0
#endif
#ifndef RT_BACKEND_FLOAT
#define RT_BACKEND_FLOAT 0
#endif
#if RT_BACKEND_DOUBLE && RT_BACKEND_FLOAT
#error "choose one numeric backend"
#endif
#define RT_BACKEND_FIXED (!RT_BACKEND_DOUBLE && !RT_BACKEND_FLOAT)

/* Fraction bits of the fixed-point scalar: Q(31-F).F. The default Q11.20
 * (range +-2048, resolution 9.5e-7) costs the same instructions as Q15.16
 * on the Cortex-M3 and is 4..18 dB closer to double on the SPD scenes
 * (bench/results.md); scenes must fit the range. */
#ifndef FX_FRAC_BITS
#define FX_FRAC_BITS 20
#endif
/* Range management: the reader scales every position by a power of two
 * so the largest coordinate is below 2^RT_SCENE_EXTENT_LOG2 (16: squared
 * distances across the scene then stay below 768, inside Q11.20). The
 * scale may range over [RT_SCALE_LOG2_MIN, RT_SCALE_LOG2_MAX]; beyond,
 * the scene is rejected as too large or too small. */
#ifndef RT_SCENE_EXTENT_LOG2
#define RT_SCENE_EXTENT_LOG2 4
#endif
/* The camera and the lights may lie farther out, below 2^RT_FAR_EXTENT_LOG2
 * (512 in Q11.20; their distances to the scene stay below 2048), so a far
 * camera or light does not take the geometry's fraction bits. */
#ifndef RT_FAR_EXTENT_LOG2
#define RT_FAR_EXTENT_LOG2 9
#endif
#ifndef RT_SCALE_LOG2_MIN              /* keeps >= 8 fraction bits */
#define RT_SCALE_LOG2_MIN (8 - FX_FRAC_BITS)
#endif
#ifndef RT_SCALE_LOG2_MAX
#define RT_SCALE_LOG2_MAX 30
#endif

/* Bytes of the scalar real_t (real.h checks): for sizes in the public
 * headers, which do not see the core's types. */
#define RT_REAL_BYTES (RT_BACKEND_DOUBLE ? 8 : 4)

/* A port's 32-bit unsigned division, for cores without a divide
 * instruction, where C's `/` is a libgcc call (ARMv6-M: __aeabi_uidiv,
 * 40 to 130 cycles). RT_UDIV32(n, d) gives n / d for d != 0, truncated;
 * RT_UDIV32_HEADER names the header that declares it (the Pico's board.mk
 * sets both to its SIO divider, platform/pico/sio_div.h). The fixed
 * layer's 64-bit quotients (fx.c) divide with it. */
#ifdef RT_UDIV32_HEADER
#include RT_UDIV32_HEADER
#endif
#ifndef RT_UDIV32
#define RT_UDIV32(n, d) ((n) / (d))
#endif

/* Faster, less exact square roots, reciprocals and powers (fx.c). */
#ifndef FX_FAST_MATH
#define FX_FAST_MATH 0
#endif

/* Ray-tree depth: eye ray = 1. RT_MAX_DEPTH bounds the tracer's levels (and stack);
 * the run-time depth option may only lower it. */
#ifndef RT_MAX_DEPTH
#define RT_MAX_DEPTH 5
#endif
/* The depth when the options ask for none (rt_render_opts_t.max_depth 0). */
#ifndef RT_DEFAULT_DEPTH
#define RT_DEFAULT_DEPTH (RT_MAX_DEPTH < 5 ? RT_MAX_DEPTH : 5)
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

/* Solids beyond NFF: shapes (quadrics, tori, boxes), transforms, CSG
 * nodes, and objects (a shape or a CSG tree, as the BVH sees them). A CSG
 * evaluation carries at most RT_CSG_MAX_SPANS inside-spans per node and
 * nests at most RT_CSG_MAX_DEPTH deep; the reader rejects trees that could
 * need more. */
#ifndef RT_MAX_TEXTURES          /* checker and marble definitions */
#define RT_MAX_TEXTURES 8
#endif
#ifndef RT_MAX_SHAPES
#define RT_MAX_SHAPES 64
#endif
#ifndef RT_MAX_XFORMS
#define RT_MAX_XFORMS 48
#endif
#ifndef RT_MAX_CSG_NODES
#define RT_MAX_CSG_NODES 32
#endif
#ifndef RT_MAX_PLANES            /* infinite planes: tested on every ray */
#define RT_MAX_PLANES 4
#endif
#ifndef RT_MAX_OBJECTS
#define RT_MAX_OBJECTS 64
#endif
#ifndef RT_CSG_MAX_SPANS
#define RT_CSG_MAX_SPANS 4
#endif
#ifndef RT_CSG_MAX_DEPTH
#define RT_CSG_MAX_DEPTH 4
#endif
#ifndef RT_MAX_BLOCK_DEPTH          /* nested transform and CSG blocks in a scene file */
#define RT_MAX_BLOCK_DEPTH 8
#endif
#ifndef RT_USE_OBJECTS
#define RT_USE_OBJECTS 1
#endif

/* Renders that may run at once, one per core or thread, each naming its
 * own worker (rt_render_opts_t.worker): a worker is the camera, tracer
 * caches, traversal stacks and counters one render writes, in static
 * storage (render.c, frame.h; on the M3, 904 bytes each for SPD balls-2, 1,656
 * with the default scene's solids). */
#ifndef RT_MAX_WORKERS
#define RT_MAX_WORKERS 1
#endif

/* Bounding volume hierarchy: nodes (at most 2 per primitive; the sum of
 * the kinds' capacities, RT_MAX_PRIMITIVES, is in prim_kinds.h) and the
 * depth of the tree, which bounds the traversal stack. */
#ifndef RT_MAX_BVH_NODES
#define RT_MAX_BVH_NODES (2 * RT_MAX_PRIMITIVES)
#endif
#ifndef RT_BVH_MAX_DEPTH
#define RT_BVH_MAX_DEPTH 32
#endif
#ifndef RT_BVH_LEAF_SIZE            /* the builder stops splitting at this many */
#define RT_BVH_LEAF_SIZE 2
#endif
#ifndef RT_BVH_MIN_PRIMITIVES       /* below this many, one leaf (the SAH */
#define RT_BVH_MIN_PRIMITIVES 2     /* decides from 2 up: a box test is cheaper
                                     * than any solid's, bench/bvh-bench.sh) */
#endif

/* Compile-time pruning: code for what a scene does not use is left out.
 * All on by default; a board build gets them from the scene compiler's
 * header (scene_data.h). Turning one off for a scene that needs it gives
 * a wrong image, so only generated values should turn them off. */
#ifndef RT_USE_SPHERES
#define RT_USE_SPHERES 1
#endif
#ifndef RT_USE_CONES
#define RT_USE_CONES 1
#endif
#ifndef RT_USE_POLYGONS
#define RT_USE_POLYGONS 1
#endif
#ifndef RT_USE_PLANES
#define RT_USE_PLANES 1
#endif
/* How a scene is searched: a BVH, or (a tree of one leaf, a few
 * primitives) every primitive kind by kind. The scene compiler leaves
 * the other out of a board's firmware. */
#ifndef RT_USE_BVH
#define RT_USE_BVH 1
#endif
#ifndef RT_USE_FLAT
#define RT_USE_FLAT 1
#endif
#ifndef RT_FLAT_EYE_SPHERES         /* a flat scene's spheres set up per frame */
#define RT_FLAT_EYE_SPHERES 8       /* for eye rays (16 bytes each a worker) */
#endif
#ifndef RT_FLAT_SHADOW_LIGHTS       /* the lights whose shadow rays a flat scene's */
#define RT_FLAT_SHADOW_LIGHTS 1     /* spheres cull by a cone (16 bytes a sphere a light) */
#endif
#ifndef RT_USE_PATCHES
#define RT_USE_PATCHES 1
#endif
#ifndef RT_USE_CONCAVE              /* polygons that are not convex (even-odd) */
#define RT_USE_CONCAVE 1
#endif
#ifndef RT_USE_CHECKER              /* the textures (texture.c) */
#define RT_USE_CHECKER 1
#endif
#ifndef RT_USE_MARBLE
#define RT_USE_MARBLE 1
#endif
#define RT_USE_TEXTURES (RT_USE_CHECKER || RT_USE_MARBLE)
#ifndef RT_TEXTURE_FILTER           /* textures averaged over each ray's footprint (ray cones), */
#define RT_TEXTURE_FILTER 1         /* not sampled at the hit point (rt_render_opts_t.point_textures) */
#endif
/* Rays carry a cone (width and spread) only where a texture filters. */
#define RT_RAY_CONES (RT_USE_TEXTURES && RT_TEXTURE_FILTER)
#ifndef RT_USE_SKY                  /* a sky (by direction) instead of a background colour */
#define RT_USE_SKY 1
#endif
#ifndef RT_USE_SHADOWS
#define RT_USE_SHADOWS 1
#endif
#ifndef RT_USE_SPECULAR
#define RT_USE_SPECULAR 1
#endif
#ifndef RT_USE_REFLECTION
#define RT_USE_REFLECTION 1
#endif
#ifndef RT_USE_REFRACTION
#define RT_USE_REFRACTION 1
#endif

/* The SPD test procedure (corner rays, rt_render_opts_t.spd); boards that
 * never use it leave it out. */
#ifndef RT_USE_SPD
#define RT_USE_SPD 1
#endif

/* Progressive display (rt_render_opts_t.progressive); firmware that
 * streams its frame leaves it out. */
#ifndef RT_USE_PROGRESSIVE
#define RT_USE_PROGRESSIVE 1
#endif

/* Anti-aliasing (rt_render_opts_t.aa_levels, .spp); firmware that never
 * asks for it leaves it out. Adaptive subdivision splits a pixel at most
 * RT_AA_MAX_LEVELS times (2^levels cells a side), where its corners differ
 * by more than RT_AA_THRESHOLD / 255 unless the options say otherwise;
 * uniform sampling takes up to RT_AA_MAX_SPP x RT_AA_MAX_SPP samples. */
#ifndef RT_USE_AA
#define RT_USE_AA 1
#endif
#ifndef RT_AA_MAX_LEVELS
#define RT_AA_MAX_LEVELS 4
#endif
#ifndef RT_AA_THRESHOLD
#define RT_AA_THRESHOLD 8
#endif
#ifndef RT_AA_MAX_SPP
#define RT_AA_MAX_SPP 16
#endif
/* Adaptive anti-aliasing's split decisions recorded into, or replayed
 * from, a caller's buffer (rt_render_opts_t.aa_splits): a reference
 * render then takes exactly another build's samples. Left out unless
 * set (the hosted build sets it; firmware has no use for it). */
#ifndef RT_AA_REPLAY
#define RT_AA_REPLAY 0
#endif

/* Ordered dithering of the packed formats (rt_fb_sink_t.dither); left
 * out of firmware that does not ask for it. */
#ifndef RT_USE_DITHER
#define RT_USE_DITHER 1
#endif

/* RT_FB_ONLY_FORMAT: the one pixel format (an RT_FB_* of rt_fb.h) the
 * render packs, so the other packers are left out; unset, all of them are
 * in (the board build sets it from FORMAT=). */

/* Largest image side accepted (bounds the per-line work buffers). */
#ifndef RT_MAX_WIDTH
#define RT_MAX_WIDTH 4096
#endif
#ifndef RT_MAX_HEIGHT
#define RT_MAX_HEIGHT 4096
#endif

/* For the few small helpers in the innermost loops. */
#if defined(__GNUC__)
#define RT_INLINE __attribute__((always_inline)) inline
#else
#define RT_INLINE inline
#endif

/* Set-up code that runs once per frame or per pixel, next to thousands of
 * instructions of tracing: optimised for size (GCC's cold functions). */
#if defined(__GNUC__)
#define RT_COLD __attribute__((cold))
#else
#define RT_COLD
#endif

/* A path the caller guarantees is never taken (lets the compiler drop
 * range checks on a switch). */
#if defined(__GNUC__)
#define RT_UNREACHABLE() __builtin_unreachable()
#else
#define RT_UNREACHABLE() ((void)0)
#endif

/* Keeps a helper's locals out of its caller's frame (a frame of a
 * recursion, or a hot loop's registers), or its code out of several
 * callers. */
#if defined(__GNUC__)
#define RT_NOINLINE __attribute__((noinline))
#else
#define RT_NOINLINE
#endif
/* The frames bench/profile.py sorts instructions by ray kind with
 * (trace_ray, scene_occluded; rt_render always is): kept as calls of their own when
 * a whole-program build (SPECIALISE=1) is profiled: make profile adds
 * -DRT_KEEP_FRAMES. */
#ifdef RT_KEEP_FRAMES
#define RT_FRAME __attribute__((noinline, noclone))
#else
#define RT_FRAME
#endif
/* rt_render stays a function of its own in every build, whole-program
 * ones included: one call a frame, and where bench/cycles.py and the
 * benchmarks start counting a render. */
#if defined(__GNUC__) && !defined(__clang__)
#define RT_ENTRY __attribute__((noinline, noclone))
#elif defined(__GNUC__)
#define RT_ENTRY __attribute__((noinline))
#else
#define RT_ENTRY
#endif

/* Hot functions called from several places in the traversal (the box
 * test, the primitive dispatch): a copy inline at each call saves the
 * calls (balls-2 -2.5%, rings-1 and teapot-1 -1.4% on the M3, for 1.2 KiB
 * more code), where there is room for the copies: not with solids, whose
 * code fills the 20 KiB budget of the showpiece firmware. */
#ifndef RT_INLINE_HOT
#define RT_INLINE_HOT (!RT_USE_OBJECTS)
#endif
#if RT_INLINE_HOT
#define RT_HOT RT_INLINE
#else
#define RT_HOT RT_NOINLINE
#endif

#if !(RT_USE_BVH || RT_USE_FLAT)
#error "RT_USE_BVH and RT_USE_FLAT: at least one way to search a scene"
#endif
#if !(RT_MAX_WORKERS >= 1 && RT_MAX_WORKERS <= 255)
#error "RT_MAX_WORKERS out of 1..255"
#endif
#if !(RT_MAX_DEPTH >= 1 && RT_MAX_DEPTH <= 16)
#error "RT_MAX_DEPTH out of 1..16"
#endif
#if !(RT_DEFAULT_DEPTH >= 1 && RT_DEFAULT_DEPTH <= RT_MAX_DEPTH)
#error "RT_DEFAULT_DEPTH out of 1..RT_MAX_DEPTH"
#endif
/* Above 20 the range (+-2^(11-F+20)) no longer holds the reader's scene
 * extent squared, nor the far end of an infinite plane: Q7.24 rendered
 * textures.nff at 11 dB, a silent wrong image. */
#if !(FX_FRAC_BITS >= 8 && FX_FRAC_BITS <= 20)
#error "FX_FRAC_BITS out of 8..20"
#endif
#if !(RT_FAR_EXTENT_LOG2 >= RT_SCENE_EXTENT_LOG2 && RT_FAR_EXTENT_LOG2 <= 29 - FX_FRAC_BITS)
#error "RT_FAR_EXTENT_LOG2: at least the scene's extent, and distances must fit the fixed range"
#endif
#if !(RT_MAX_POLY_VERTS >= 3 && RT_MAX_POLY_VERTS <= 65535)
#error "RT_MAX_POLY_VERTS out of 3..65535"
#endif
#if !(RT_MAX_MATERIALS >= 1 && RT_MAX_MATERIALS <= 65535)
#error "materials are indexed by uint16_t"
#endif
#if !(RT_MAX_SHAPES < 0x8000 && RT_MAX_CSG_NODES < 0x8000 && RT_MAX_XFORMS < 0xFFFF)
#error "shape, CSG node and transform indices are 15/16-bit"
#endif
#if !(RT_CSG_MAX_SPANS >= 2 && RT_CSG_MAX_SPANS <= 32)
#error "RT_CSG_MAX_SPANS out of 2..32"
#endif
#if !(RT_MAX_BLOCK_DEPTH >= 1 && RT_MAX_BLOCK_DEPTH <= 64)
#error "RT_MAX_BLOCK_DEPTH out of 1..64"
#endif
#if !(RT_BVH_MAX_DEPTH >= 8 && RT_BVH_MAX_DEPTH <= 64)
#error "RT_BVH_MAX_DEPTH out of 8..64"
#endif
#if !(RT_BVH_LEAF_SIZE >= 1 && RT_BVH_LEAF_SIZE <= 16)
#error "RT_BVH_LEAF_SIZE out of 1..16"
#endif
/* An adaptive pixel's sum of 4^(levels + 1) corner colours in [0, 1]
 * is at most 2^10 (inside the fixed range's 2048), as is a uniform pixel's sum of
 * spp^2 samples. */
#if !(RT_AA_MAX_LEVELS >= 1 && RT_AA_MAX_LEVELS <= 4)
#error "RT_AA_MAX_LEVELS out of 1..4"
#endif
#if !(RT_AA_THRESHOLD >= 1 && RT_AA_THRESHOLD <= 255)
#error "RT_AA_THRESHOLD out of 1..255"
#endif
#if !(RT_AA_MAX_SPP >= 2 && RT_AA_MAX_SPP <= 32)
#error "RT_AA_MAX_SPP out of 2..32"
#endif
#if !(RT_MAX_LIGHTS >= 1 && RT_MAX_LIGHTS <= 255)
#error "RT_MAX_LIGHTS out of 1..255"
#endif
#if !(RT_FLAT_EYE_SPHERES >= 1 && RT_FLAT_EYE_SPHERES <= 32)
#error "RT_FLAT_EYE_SPHERES out of 1..32"
#endif
#if !(RT_FLAT_SHADOW_LIGHTS >= 1 && RT_FLAT_SHADOW_LIGHTS <= RT_MAX_LIGHTS)
#error "RT_FLAT_SHADOW_LIGHTS out of 1..RT_MAX_LIGHTS"
#endif

#endif
