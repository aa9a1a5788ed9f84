/*
 * nff_lex.h - the reader's bottom layer: whitespace-separated tokens of
 * NFF text, decimal numbers to the active scalar, line numbers and the
 * error messages that point at them.
 *
 * The reader's layers (each file uses only the ones below it):
 *
 *   nff.c         NFF grammar, the keyword table, the two passes
 *     |     \
 *     |   nff_solids.c  solids grammar: blocks, transforms, shapes, CSG
 *     |     /
 *   nff_scene.c   reader state: positions in scene scale, the material
 *     |
 *   nff_lex.c     tokens, numbers, lines, errors (this layer)
 */
#ifndef NFF_LEX_H
#define NFF_LEX_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "numeric/decimal.h"
#include "numeric/real.h"
#include "rt_error.h"
#include "numeric/vec3.h"

typedef struct {
    const char *p, *end;
    uint32_t line;      /* line of the current position */
    uint32_t tok_line;  /* line of the last token read */
    uint32_t prev_line; /* line of the token before it */
    const char *tok;    /* the last token, NULL at the end of input */
    size_t tok_len;
    rt_error_t *err;
} lexer_t;

void lex_start(lexer_t *lx, const char *text, size_t len, rt_error_t *err);

/* Errors: each sets lx->err and returns false. */
bool lex_fail(lexer_t *lx, uint32_t line, const char *msg);
/* "<what><msg>, found '<token>'" with the token shortened, on the token's line. */
bool lex_fail_tok(lexer_t *lx, const char *what, const char *msg);
/* The same for a token an entity needed but did not get (a number, a
 * field's name): on the line where the entity stopped short, the previous
 * token's, naming the found token's line when it is a later one (most
 * often the next entity's keyword: `s 0 1 1` then `f ...`). */
bool lex_fail_missing(lexer_t *lx, const char *what, const char *msg);
bool lex_out_of_range(lexer_t *lx, const char *what);
bool lex_over_capacity(lexer_t *lx, const char *what, const char *macro, int32_t cap);

/* Next token (tok NULL at the end of input); false on a byte that is not text. */
bool lex_next(lexer_t *lx);
/* The next token if it is on the current line; otherwise *found is false
 * and the position stays where it was. */
bool lex_next_on_line(lexer_t *lx, bool *found);
bool lex_is(const lexer_t *lx, const char *word);

/* The current token as a decimal, or the error "<what><msg>, found ...". */
bool lex_tok_decimal(lexer_t *lx, const char *what, const char *msg, decimal_t *d);
/* The next token as a decimal, a scalar, three scalars, a whole number in [lo, hi]. */
bool lex_decimal(lexer_t *lx, const char *what, decimal_t *d);
bool lex_real(lexer_t *lx, const char *what, real_t *out);
bool lex_vec3(lexer_t *lx, const char *what, vec3_t *v);
bool lex_count(lexer_t *lx, const char *what, uint32_t lo, uint32_t hi, uint32_t *out);
/* Three numbers giving a direction (any size): *zero when all three are
 * 0, else the vector times a power of ten that brings its largest
 * component to 1..10 in size (not unit). */
bool lex_direction(lexer_t *lx, const char *what, vec3_t *v, bool *zero);
/* The same, and the direction as the fixed build holds it: on the
 * position grid (2^-FX_FRAC_BITS), the same integers in every build. */
bool lex_direction_grid(lexer_t *lx, const char *what, vec3_t *v, bool *zero, int32_t grid[3]);
/* An exponent (Phong's, the sky's): 0 to RT_SHINE_MAX, or with `positive`
 * 2^RT_SHINE_MIN_LOG2 (the fixed build's least positive exponent) to
 * RT_SHINE_MAX; else the error msg. */
#define RT_SHINE_MAX 524287u
#define RT_SHINE_MIN_LOG2 (-12)
#if !RT_BACKEND_DOUBLE && !RT_BACKEND_FLOAT
_Static_assert(RT_SHINE_MIN_LOG2 == -R_SHINE_FRAC_BITS && RT_SHINE_MAX == (INT32_MAX >> R_SHINE_FRAC_BITS),
               "the exponents' limits are the fixed format's");
#endif
bool lex_shine(lexer_t *lx, const char *msg, bool positive, shine_t *out);
/* A decimal (times 2^scale_log2) to the scalar, or the out-of-range
 * error: one rule for every build, |value| rounding into the fixed
 * range (below 2^(31 - FX_FRAC_BITS) - 2^-(FX_FRAC_BITS + 1)). */
bool lex_scalar(lexer_t *lx, const char *what, const decimal_t *d, real_t *out);
bool lex_scalar_scaled(lexer_t *lx, const char *what, const decimal_t *d, int32_t scale_log2, real_t *out);

#endif
