/* board_scene.h - where the firmware's scene comes from: const tables made
 * by the scene compiler (scene_flash.c), or NFF text parsed at boot into
 * RAM (scene_text.c, used for the soft-float comparison build). */
#ifndef BOARD_SCENE_H
#define BOARD_SCENE_H

#include "rt_error.h"
#include "scene.h"

/* The scene, or NULL with *err set. */
const scene_t *board_scene(rt_error_t *err);

#endif
