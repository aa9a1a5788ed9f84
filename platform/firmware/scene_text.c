/* scene_text.c - NFF text embedded in the image, read at boot into RAM
 * tables (rt-scenec --text writes rt_scene_text). */
#include <stddef.h>

#include "board_scene.h"
#include "nff.h"

extern const char rt_scene_text[];
extern const size_t rt_scene_text_len;

static scene_store_t store;

const scene_t *board_scene(rt_error_t *err)
{
    return nff_read(rt_scene_text, rt_scene_text_len, &store, err) ? &store.scene : 0;
}
