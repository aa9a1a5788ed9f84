/*
 * geometry.h - the scene and its primitive kinds in one include: rays and
 * hits (ray.h), each kind's set-up, intersection and normals (the headers
 * prim_kinds.h names), and the tables (scene.h).
 *
 * The ray_hit_* functions share one convention: *t holds the nearest hit
 * found so far (the ray's far limit); a hit in (tmin, *t) replaces it and
 * returns true. Rays have unit directions, so t is a distance.
 */
#ifndef GEOMETRY_H
#define GEOMETRY_H

#include "ray.h"
#include "scene.h"
#include "numeric/tolerance.h"

#endif
