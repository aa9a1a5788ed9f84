/*
 * nff_scene.c - the reader's middle layer (layers: nff_lex.h): positions
 * in the scene's scale and the material check, shared by the NFF grammar
 * (nff.c) and the solids grammar (nff_solids.c). Uses the lexer only.
 */
#include "nff_scene.h"

#include "numeric/fx_setup.h"

block_t *rd_top_block(reader_t *r)
{
    return r->n_blocks ? &r->blocks[r->n_blocks - 1] : 0;
}

bool rd_pos(reader_t *r, const char *what, real_t *out)
{
    decimal_t d;
    return rd_pos_decimal(r, what, &d, out);
}

bool rd_pos_decimal(reader_t *r, const char *what, decimal_t *dp, real_t *out)
{
    decimal_t d;
    if (!lex_decimal(&r->lx, what, &d))
        return false;
    *dp = d;
    *out = 0;
    if (r->measuring) {
        if (d.mant != 0) {
            /* inside transform blocks sizes may grow by their scales */
            const block_t *b = rd_top_block(r);
            int32_t p = decimal_exp2_bound(&d) + (b ? b->extent_exp2 : 0);
            unsigned f = r->far;
            if (p > r->max_exp2[f]) {
                r->max_exp2[f] = p;
                r->max_line[f] = r->lx.tok_line;
                r->max_what[f] = what;
            }
        }
        return true;
    }
    return lex_scalar_scaled(&r->lx, what, &d, r->scale_log2, out);
}

int32_t rd_grid(const reader_t *r, const decimal_t *d)
{
    int32_t g = 0;
    (void)fx_from_decimal(d->neg, d->mant, d->exp10, FX_FRAC_BITS + r->scale_log2, INT32_MAX, &g); /* in range: read */
    return g;
}

bool rd_pos3_grid(reader_t *r, const char *what, vec3_t *v, int32_t g[3])
{
    decimal_t d[3];
    if (!rd_pos_decimal(r, what, &d[0], &v->x) || !rd_pos_decimal(r, what, &d[1], &v->y) ||
        !rd_pos_decimal(r, what, &d[2], &v->z))
        return false;
    for (int i = 0; i < 3; i++)
        g[i] = r->measuring ? 0 : rd_grid(r, &d[i]);
    return true;
}

bool rd_pos3(reader_t *r, const char *what, vec3_t *v)
{
    return rd_pos(r, what, &v->x) && rd_pos(r, what, &v->y) && rd_pos(r, what, &v->z);
}

bool rd_need_material(reader_t *r, const char *what)
{
    if (r->have_material)
        return true;
    rt_error_set(r->lx.err, r->lx.tok_line, what);
    rt_error_append(r->lx.err, " before any 'f' material line");
    return false;
}

void rd_cross(const int64_t a[3], const int64_t b[3], int64_t out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void rd_cut(const int64_t v[3], int64_t out[3])
{
    uint64_t top = 0;
    for (int i = 0; i < 3; i++) {
        uint64_t m = v[i] < 0 ? 0 - (uint64_t)v[i] : (uint64_t)v[i];
        top = m > top ? m : top;
    }
    int64_t div = 1;
    for (; top >= (uint64_t)1 << 20; top >>= 1)
        div *= 2;
    for (int i = 0; i < 3; i++)
        out[i] = v[i] / div; /* toward zero: the same in every build */
}

vec3_t rd_direction(const int64_t v[3])
{
    int64_t c[3];
    real_t x[3];
    rd_cut(v, c);
    for (int i = 0; i < 3; i++) /* |c| < 2^20: exact in every scalar */
        (void)r_from_decimal_scaled(c[i] < 0, (uint64_t)(c[i] < 0 ? -c[i] : c[i]), 0, -20, &x[i]);
    return v3(x[0], x[1], x[2]);
}
