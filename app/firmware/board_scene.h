/* board_scene.h - where the firmware's scene comes from: const tables in
 * flash made by the scene compiler for the build's backend
 * (scene_flash.c). A port that reads NFF text at run time instead would
 * implement this with rt_nff_load(). */
#ifndef BOARD_SCENE_H
#define BOARD_SCENE_H

#include "rt_error.h"
#include "geometry/scene.h"

/* The scene, or NULL with *err set. */
const scene_t *board_scene(rt_error_t *err);

#endif
