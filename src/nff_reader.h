/* nff_reader.h - the NFF reader's state and helpers, shared by nff.c
 * (tokens, numbers, the NFF entities) and nff_solids.c (blocks and the
 * solids beyond NFF). Internal to the reader. */
#ifndef NFF_READER_H
#define NFF_READER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rt_error.h"
#include "scene.h"


/* An open transform or CSG block. */
typedef struct {
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
    const char *p, *end;
    uint32_t line;      /* line of the current position */
    uint32_t tok_line;  /* line of the last token read */
    const char *tok;
    size_t tok_len;
    scene_store_t *st;
    rt_error_t *err;
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


typedef struct {
    bool neg;
    uint64_t mant;   /* up to 19 significant digits */
    int32_t exp10;
} decimal_t;


#define CHECK_ROOM(r, count, cap, what) \
    ((count) < (cap) ? true : rd_over_capacity((r), (what), #cap, (int32_t)(cap)))


bool rd_fail(reader_t *r, uint32_t line, const char *msg);
bool rd_fail_tok(reader_t *r, const char *what, const char *msg);
bool rd_next_token(reader_t *r);
bool rd_tok_is(const reader_t *r, const char *word);
bool rd_decimal(reader_t *r, const char *what, decimal_t *d);
bool rd_out_of_range(reader_t *r, const char *what);
bool rd_real(reader_t *r, const char *what, real_t *out);
bool rd_vec3(reader_t *r, const char *what, vec3_t *v);
bool rd_pos(reader_t *r, const char *what, real_t *out);
bool rd_pos3(reader_t *r, const char *what, vec3_t *v);
bool rd_over_capacity(reader_t *r, const char *what, const char *macro, int32_t cap);
bool rd_need_material(reader_t *r, const char *what);

/* nff_solids.c: block keywords and solids. rd_solid_entity returns false
 * with *handled false when the token is none of its keywords. */
bool rd_solid_entity(reader_t *r, bool *handled);
bool rd_blocks_closed(reader_t *r);

#endif
