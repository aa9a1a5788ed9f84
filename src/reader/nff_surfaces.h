/*
 * nff_surfaces.h - the surfaces grammar beyond NFF (layers: nff_lex.h):
 * infinite planes, textures and the sky, one handler per keyword for
 * nff.c's keyword table. Internal to the reader.
 */
#ifndef NFF_SURFACES_H
#define NFF_SURFACES_H

#include <stdbool.h>

#include "nff_scene.h"

bool rd_plane(reader_t *r);   /* plane px py pz nx ny nz */
bool rd_checker(reader_t *r); /* checker size r g b r g b [axes] */
bool rd_marble(reader_t *r);  /* marble size r g b r g b amount */
bool rd_sky(reader_t *r);     /* sky hr hg hb zr zg zb ux uy uz exponent */

#endif
