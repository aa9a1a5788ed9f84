/*
 * nff_scene.h - the reader's middle layer (layers: nff_lex.h): the state
 * both grammars share while they build a scene_store_t, positions read in
 * the scene's scale, and the checks every entity makes (capacity, a
 * material first). Uses the lexer only. Internal to the reader.
 */
#ifndef NFF_SCENE_H
#define NFF_SCENE_H

#include <stdbool.h>
#include <stdint.h>

#include "nff_lex.h"
#include "geometry/scene.h"

/* An open transform or CSG block. */
typedef struct {
    const char *name;     /* the word that opened it */
    uint8_t csg;          /* 0: transform block, else 1 + enum csg_op */
    uint32_t line;        /* where it was opened */
    xform_t xf;           /* the transform in force inside it */
    bool identity;
    uint16_t xf_index;    /* xf stored in the table, XFORM_NONE until needed */
    int32_t extent_exp2;  /* measuring pass: growth of sizes inside it */
    bool has_acc;         /* CSG: the solid built from the children so far */
    uint16_t acc;
    uint16_t children;
} block_t;

typedef struct {
    lexer_t lx;
    scene_store_t *st;
    bool have_view, have_material;
    uint16_t material;
    /* Range management: a first pass only measures the positions (their
     * largest binary exponent); the second converts every position times
     * 2^scale_log2, exactly, so the scene fills the fixed range. */
    bool measuring;
    bool far;              /* reading the camera or a light (range: far) */
    int32_t max_exp2[2];   /* [0] the geometry, [1] the camera and lights */
    uint32_t max_line[2];  /* where the largest position is */
    const char *max_what[2];
    int32_t scale_log2;
    block_t blocks[RT_MAX_BLOCK_DEPTH];
    uint32_t n_blocks;
} reader_t;

/* True if count < cap, else the "too many <what>" error naming the macro. */
#define CHECK_ROOM(r, count, cap, what) \
    ((count) < (cap) ? true : lex_over_capacity(&(r)->lx, (what), #cap, (int32_t)(cap)))

/* A position (or a length): scaled by 2^scale_log2 with the rest of the
 * scene; in the measuring pass only its size is recorded. */
bool rd_pos(reader_t *r, const char *what, real_t *out);
/* the same, with the number as written (*d) */
bool rd_pos_decimal(reader_t *r, const char *what, decimal_t *d, real_t *out);
bool rd_pos3(reader_t *r, const char *what, vec3_t *v);
/* A position read (second pass) on the fixed build's position grid, in
 * units of 2^-FX_FRAC_BITS in the scene's scale, the same in every build:
 * what a degenerate shape (a zero radius, a point twice) is judged on, so
 * that every build gives one verdict. */
int32_t rd_grid(const reader_t *r, const decimal_t *d);
bool rd_pos3_grid(reader_t *r, const char *what, vec3_t *v, int32_t g[3]);
/* Exact integer vectors on the position grid, for the degenerate-shape
 * verdicts every build shares (docs/scenes.md): a x b, exact while each
 * |a_i b_j| < 2^62; v cut to its leading bits (the largest component
 * below 2^20, keeping its direction to 2^-19); and a nonzero v as a
 * direction every build holds exactly (v cut, times 2^-20). */
void rd_cross(const int64_t a[3], const int64_t b[3], int64_t out[3]);
void rd_cut(const int64_t v[3], int64_t out[3]);
vec3_t rd_direction(const int64_t v[3]);
/* The "<what> before any 'f' material line" error unless there is one. */
bool rd_need_material(reader_t *r, const char *what);
/* The innermost open block, or NULL. */
block_t *rd_top_block(reader_t *r);

#endif
