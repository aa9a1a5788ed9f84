/* scene_hit.h - a ray against the whole scene (through its BVH): nearest
 * hit and any hit. */
#ifndef SCENE_HIT_H
#define SCENE_HIT_H

#include <stdbool.h>

#include "camera.h"
#include "geometry.h"
#include "scratch.h"

/* Nearest hit with tmin < t < h->t (set h->t to the ray's far limit).
 * Each function counts into w->stats and uses w's stacks. */
bool scene_nearest(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, ray_scratch_t *w);

/* Whether anything lies on the ray with tmin < t < tmax (shadow rays).
 * *last_blocker (PRIM_NONE or a primitive of sc) is tried first and set
 * to the primitive found blocking, or to PRIM_NONE when nothing blocks:
 * neighbouring shadow rays towards one light tend to be blocked by the
 * same one, and a lit ray's neighbours tend to be lit. */
bool scene_occluded(const scene_t *sc, const ray_t *r, real_t tmin, real_t tmax, prim_ref_t *last_blocker,
                    ray_scratch_t *w);

/* Per frame, for the camera's eye rays and the shadow rays to the first
 * lights: what lets them reject the spheres of a flat scene early (the
 * samples each may meet, the cone from the light that holds each:
 * scratch.h, eye_sphere_t and light_sphere_t); nothing otherwise. */
void scene_eye_setup(const scene_t *sc, const camera_t *cam, ray_scratch_t *w);

/* Adds the flat search's 32-bit test counts to w->stats (and clears
 * them): at each new row of eye rays (scene_hit.c) and, in a scene
 * searched flat (w->flat), before w->stats is read. */
void scene_fold_stats(ray_scratch_t *w);

/* scene_nearest without the BVH: every primitive, in table order (the
 * reference the traversal is tested against). */
bool scene_nearest_brute(const scene_t *sc, const ray_t *r, real_t tmin, hit_t *h, ray_scratch_t *w);

#endif
