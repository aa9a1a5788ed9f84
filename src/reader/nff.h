/* nff.h - read an NFF scene from memory (no file system needed). */
#ifndef NFF_H
#define NFF_H

#include <stdbool.h>
#include <stddef.h>

#include "rt_error.h"
#include "geometry/scene.h"

/* Parses `len` bytes of NFF text into `store`, builds its BVH and points
 * store->scene at its tables. On failure returns false with err->line and err->msg set
 * ("file:line: msg" is for the caller to print). */
bool nff_read(const char *text, size_t len, scene_store_t *store, rt_error_t *err);

/* rt_nff_load (rt.h): the same into the library's own tables. */

#endif
