/*
 * nff_solids.h - the solids grammar (layers: nff_lex.h): one handler per
 * keyword of the scene syntax beyond NFF, for nff.c's keyword table. Each
 * is called with the keyword as the current token, after the table's
 * checks (viewpoint, block); it reads the rest of the entity. Internal to
 * the reader.
 */
#ifndef NFF_SOLIDS_H
#define NFF_SOLIDS_H

#include <stdbool.h>

#include "nff_scene.h"

/* Blocks: transform | union | intersection | difference ... end */
bool rd_transform_block(reader_t *r);
bool rd_union_block(reader_t *r);
bool rd_intersection_block(reader_t *r);
bool rd_difference_block(reader_t *r);
bool rd_end_block(reader_t *r);
/* At the end of input: the error for a block left open. */
bool rd_blocks_closed(reader_t *r);

/* Transform steps, right inside a transform block. */
bool rd_translate(reader_t *r);
bool rd_rotate(reader_t *r);
bool rd_scale(reader_t *r);

/* Shapes. */
bool rd_box(reader_t *r);
bool rd_torus(reader_t *r);
bool rd_quadric(reader_t *r);
bool rd_ellipsoid(reader_t *r);
bool rd_paraboloid(reader_t *r);
bool rd_hyperboloid(reader_t *r);
bool rd_hyperboloid2(reader_t *r);
bool rd_quadcone(reader_t *r);
bool rd_quadcylinder(reader_t *r);
/* 's' inside a block: a sphere solid (outside, 's' is NFF's sphere). */
bool rd_sphere_solid(reader_t *r);

#endif
