/*
 * nff_lex.c - the reader's bottom layer (see nff_lex.h for the layers):
 * tokens, numbers, line numbers and error messages. Uses nothing of the
 * reader above it.
 *
 * Whitespace-separated tokens, so an entity may span lines or share one
 * (the SPD cones put base and apex on one line). Numbers are parsed from
 * their decimal digits straight to the active scalar, correctly rounded in
 * the fixed build; no libc.
 */
#include "nff_lex.h"

#include "numeric/fx_setup.h"

void lex_start(lexer_t *lx, const char *text, size_t len, rt_error_t *err)
{
    *lx = (lexer_t){ 0 };
    lx->p = text;
    lx->end = text + len;
    lx->line = 1;
    lx->tok_line = 1;
    lx->err = err;
}

/* ---- errors ------------------------------------------------------------- */

bool lex_fail(lexer_t *lx, uint32_t line, const char *msg)
{
    rt_error_set(lx->err, line, msg);
    return false;
}

static bool fail_at(lexer_t *lx, uint32_t line, const char *what, const char *msg)
{
    rt_error_set(lx->err, line, what);
    rt_error_append(lx->err, msg);
    if (lx->tok == 0) {
        rt_error_append(lx->err, " (end of file)");
        return false;
    }
    char q[24];
    size_t n = 0;
    for (; n < lx->tok_len && n < 16; n++)
        q[n] = lx->tok[n];
    if (lx->tok_len > 16) {
        q[n++] = '.';
        q[n++] = '.';
        q[n++] = '.';
    }
    q[n] = '\0';
    rt_error_append(lx->err, ", found '");
    rt_error_append(lx->err, q);
    rt_error_append(lx->err, "'");
    if (line != lx->tok_line) {
        rt_error_append(lx->err, " on line ");
        rt_error_append_int(lx->err, (int32_t)lx->tok_line);
    }
    return false;
}

bool lex_fail_tok(lexer_t *lx, const char *what, const char *msg)
{
    return fail_at(lx, lx->tok_line, what, msg);
}

bool lex_fail_missing(lexer_t *lx, const char *what, const char *msg)
{
    /* at the end of input tok_line is still the last token's */
    return fail_at(lx, lx->tok == 0 ? lx->tok_line : lx->prev_line, what, msg);
}

bool lex_out_of_range(lexer_t *lx, const char *what)
{
    rt_error_set(lx->err, lx->tok_line, what);
    rt_error_append(lx->err, ": number out of range (its size must round below 2^");
    rt_error_append_int(lx->err, 31 - FX_FRAC_BITS);
    rt_error_append(lx->err, ")");
    return false;
}

bool lex_over_capacity(lexer_t *lx, const char *what, const char *macro, int32_t cap)
{
    rt_error_set(lx->err, lx->tok_line, "too many ");
    rt_error_append(lx->err, what);
    rt_error_append(lx->err, ": capacity ");
    rt_error_append(lx->err, macro);
    rt_error_append(lx->err, " = ");
    rt_error_append_int(lx->err, cap);
    rt_error_append(lx->err, " (raise it with -D");
    rt_error_append(lx->err, macro);
    rt_error_append(lx->err, "=N)");
    return false;
}

/* ---- tokens ------------------------------------------------------------- */

static bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* Skips blanks and comments; false (with the error set) on a control or
 * non-ASCII byte, which means the file is not text. */
static bool skip_blank(lexer_t *lx)
{
    while (lx->p < lx->end) {
        unsigned char c = (unsigned char)*lx->p;
        if (c == '\n') {
            lx->line++;
            lx->p++;
        } else if (is_space((char)c)) {
            lx->p++;
        } else if (c == '#') {
            while (lx->p < lx->end && *lx->p != '\n')
                lx->p++;
        } else if (c < 0x20 || c >= 0x7F) {
            rt_error_set(lx->err, lx->line, "not a text file (byte ");
            rt_error_append_int(lx->err, c);
            rt_error_append(lx->err, ")");
            return false;
        } else {
            return true;
        }
    }
    return true;
}

bool lex_next(lexer_t *lx)
{
    if (!skip_blank(lx))
        return false;
    if (lx->p >= lx->end) { /* errors at the end point at the last token */
        lx->tok = 0;
        lx->tok_len = 0;
        return true;
    }
    lx->prev_line = lx->tok_line;
    lx->tok_line = lx->line;
    lx->tok = lx->p;
    while (lx->p < lx->end && !is_space(*lx->p) && *lx->p != '#') {
        unsigned char c = (unsigned char)*lx->p;
        if (c < 0x20 || c >= 0x7F)
            break;
        lx->p++;
    }
    lx->tok_len = (size_t)(lx->p - lx->tok);
    return true;
}

bool lex_next_on_line(lexer_t *lx, bool *found)
{
    lexer_t save = *lx;
    if (!lex_next(lx))
        return false;
    *found = lx->tok != 0 && lx->tok_line == save.line;
    if (!*found)
        *lx = save; /* the token stays the last one read */
    return true;
}

bool lex_is(const lexer_t *lx, const char *word)
{
    size_t i = 0;
    if (lx->tok == 0)
        return false;
    for (; i < lx->tok_len; i++)
        if (word[i] == '\0' || word[i] != lx->tok[i])
            return false;
    return word[i] == '\0';
}

/* ---- numbers ------------------------------------------------------------ */

/* Parses the current token as [+-]digits[.digits][(e|E)[+-]digits]. */
static bool parse_decimal(const lexer_t *lx, decimal_t *d)
{
    int digits = 0, sig = 0;
    int32_t exp10 = 0;
    d->neg = false;
    d->mant = 0;
    if (lx->tok == 0) /* end of input */
        return false;
    const char *s = lx->tok, *e = lx->tok + lx->tok_len;
    if (s < e && (*s == '+' || *s == '-'))
        d->neg = *s++ == '-';
    for (; s < e && *s >= '0' && *s <= '9'; s++, digits++) {
        if (sig < 19) {
            d->mant = d->mant * 10 + (uint64_t)(*s - '0');
            sig += d->mant != 0;
        } else if (exp10 < 100000) {
            exp10++; /* dropped integer digit (bounded: any more is huge) */
        }
    }
    if (s < e && *s == '.') {
        for (s++; s < e && *s >= '0' && *s <= '9'; s++, digits++) {
            if (sig < 19) {
                d->mant = d->mant * 10 + (uint64_t)(*s - '0');
                sig += d->mant != 0;
                exp10--;
            }
        }
    }
    if (digits == 0)
        return false;
    if (s < e && (*s == 'e' || *s == 'E')) {
        bool eneg = false;
        int32_t ev = 0;
        s++;
        if (s < e && (*s == '+' || *s == '-'))
            eneg = *s++ == '-';
        if (s >= e || *s < '0' || *s > '9')
            return false;
        for (; s < e && *s >= '0' && *s <= '9'; s++)
            if (ev < 100000)
                ev = ev * 10 + (*s - '0');
        exp10 += eneg ? -ev : ev;
    }
    d->exp10 = exp10;
    return s == e;
}

bool lex_tok_decimal(lexer_t *lx, const char *what, const char *msg, decimal_t *d)
{
    if (!parse_decimal(lx, d))
        return lex_fail_missing(lx, what, msg);
    return true;
}

bool lex_decimal(lexer_t *lx, const char *what, decimal_t *d)
{
    return lex_next(lx) && lex_tok_decimal(lx, what, ": expected a number", d);
}

bool lex_scalar_scaled(lexer_t *lx, const char *what, const decimal_t *d, int32_t scale_log2, real_t *out)
{
    /* |d| 2^scale < (2^32 - 1) 2^-(F+1): it rounds to at most FX_MAX,
     * decided on the value, so every build accepts the same numbers */
    if (decimal_cmp(d, UINT32_MAX, -(FX_FRAC_BITS + 1) - scale_log2) >= 0 ||
        !r_from_decimal_scaled(d->neg, d->mant, d->exp10, scale_log2, out))
        return lex_out_of_range(lx, what);
    return true;
}

bool lex_scalar(lexer_t *lx, const char *what, const decimal_t *d, real_t *out)
{
    return lex_scalar_scaled(lx, what, d, 0, out);
}

bool lex_real(lexer_t *lx, const char *what, real_t *out)
{
    decimal_t d;
    return lex_decimal(lx, what, &d) && lex_scalar(lx, what, &d, out);
}

bool lex_vec3(lexer_t *lx, const char *what, vec3_t *v)
{
    return lex_real(lx, what, &v->x) && lex_real(lx, what, &v->y) && lex_real(lx, what, &v->z);
}

/* floor(log10 |d|), d nonzero: exact, as 10^(digits - 1) <= mant < 10^digits */
static int32_t decimal_log10_floor(const decimal_t *d)
{
    int32_t digits = 0;
    for (uint64_t m = d->mant; m != 0; m /= 10)
        digits++;
    return digits - 1 + d->exp10;
}

bool lex_direction(lexer_t *lx, const char *what, vec3_t *v, bool *zero)
{
    return lex_direction_grid(lx, what, v, zero, 0);
}

bool lex_direction_grid(lexer_t *lx, const char *what, vec3_t *v, bool *zero, int32_t grid[3])
{
    decimal_t d[3];
    int32_t top = INT32_MIN;
    for (int i = 0; i < 3; i++) {
        if (!lex_decimal(lx, what, &d[i]))
            return false;
        if (d[i].mant != 0 && decimal_log10_floor(&d[i]) > top)
            top = decimal_log10_floor(&d[i]);
    }
    *zero = top == INT32_MIN;
    for (int i = 0; grid && i < 3; i++)
        grid[i] = 0;
    if (*zero) {
        *v = v3(0, 0, 0);
        return true;
    }
    /* times 10^-top, exactly: the largest component is then 1 to 10 in
     * size, so no build sees zero where another does not */
    real_t c[3];
    for (int i = 0; i < 3; i++) {
        d[i].exp10 -= top;
        if (!lex_scalar(lx, what, &d[i], &c[i]))
            return false;
        if (grid) /* below 10: in range */
            (void)fx_from_decimal(d[i].neg, d[i].mant, d[i].exp10, FX_FRAC_BITS, INT32_MAX, &grid[i]);
    }
    *v = v3(c[0], c[1], c[2]);
    return true;
}

bool lex_shine(lexer_t *lx, const char *msg, bool positive, shine_t *out)
{
    decimal_t d;
    if (!lex_decimal(lx, msg, &d))
        return false;
    bool low = positive ? d.neg || decimal_cmp(&d, 1, RT_SHINE_MIN_LOG2) < 0 : d.neg && d.mant != 0;
    if (low || decimal_cmp(&d, RT_SHINE_MAX, 0) > 0 || !shine_from_decimal(false, d.mant, d.exp10, out))
        return lex_fail(lx, lx->tok_line, msg);
    return true;
}

bool lex_count(lexer_t *lx, const char *what, uint32_t lo, uint32_t hi, uint32_t *out)
{
    decimal_t d;
    if (!lex_decimal(lx, what, &d))
        return false;
    uint64_t v = d.mant;
    while (d.exp10 < 0 && v % 10 == 0 && v != 0) { /* 32.0 and 3.2e1 are 32 too */
        v /= 10;
        d.exp10++;
    }
    for (int32_t i = 0; i < d.exp10 && v <= hi; i++)
        v *= 10;
    if ((d.neg && v != 0) || (d.exp10 < 0 && v != 0) || v < lo || v > hi) {
        rt_error_set(lx->err, lx->tok_line, what);
        rt_error_append(lx->err, ": expected a whole number from ");
        rt_error_append_int(lx->err, (int32_t)lo);
        rt_error_append(lx->err, " to ");
        rt_error_append_int(lx->err, (int32_t)hi);
        return false;
    }
    *out = (uint32_t)v;
    return true;
}
