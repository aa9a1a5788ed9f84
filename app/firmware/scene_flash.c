/* scene_flash.c - the scene compiled into flash by rt-scenec. */
#include "board_scene.h"

extern const scene_t rt_scene;

const scene_t *board_scene(rt_error_t *err)
{
    (void)err;
    return &rt_scene;
}
