/*
 * xform.c - affine transforms of solids (layers: xform.h): composed by
 * the reader step by step (translate, scale, rotate), applied to points
 * and normals. Uses no other solid file.
 */
#include "xform.h"

/* m v, or m^T v with `transposed` */
static vec3_t mat_vec(const mat3_t *m, vec3_t v, bool transposed)
{
    real_t out[3];
    for (int i = 0; i < 3; i++) {
        const real_t *e = transposed ? &m->rows[0][i] : m->rows[i];
        int step = transposed ? 3 : 1;
        out[i] = r_from_wide(r_wmul(e[0], v.x) + r_wmul(e[step], v.y) + r_wmul(e[2 * step], v.z));
    }
    return v3(out[0], out[1], out[2]);
}

vec3_t xform_mat_vec(const mat3_t *m, vec3_t v) { return mat_vec(m, v, false); }

/* out = a * b (out may be a or b) */
static void mat_mul(mat3_t *out, const mat3_t *a, const mat3_t *b)
{
    mat3_t r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.rows[i][j] = r_from_wide(r_wmul(a->rows[i][0], b->rows[0][j]) + r_wmul(a->rows[i][1], b->rows[1][j]) +
                                       r_wmul(a->rows[i][2], b->rows[2][j]));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out->rows[i][j] = r.rows[i][j];
}

void xform_identity(xform_t *x)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            x->m.rows[i][j] = x->im.rows[i][j] = i == j ? R_ONE : 0;
        x->t[i] = 0;
    }
}

/* world = M (p + v) + t: only t moves */
void xform_translate(xform_t *x, vec3_t v)
{
    vec3_t mv = xform_mat_vec(&x->m, v);
    x->t[0] += mv.x;
    x->t[1] += mv.y;
    x->t[2] += mv.z;
}

void xform_scale(xform_t *x, vec3_t s)
{
    const mat3_t d = { { { s.x, 0, 0 }, { 0, s.y, 0 }, { 0, 0, s.z } } };
    const mat3_t di = { { { r_recip(s.x), 0, 0 }, { 0, r_recip(s.y), 0 }, { 0, 0, r_recip(s.z) } } };
    mat_mul(&x->m, &x->m, &d);
    mat_mul(&x->im, &di, &x->im);
}

void xform_rotate(xform_t *x, vec3_t axis, real_t deg)
{
    real_t s, c;
    r_sincos_deg(deg, &s, &c);
    vec3_t a = v3_unit(axis);
    real_t oc = R_ONE - c;
    /* Rodrigues: R = c I + s [a]x + (1 - c) a a^T; the inverse is R^T */
    mat3_t r = { {
        { c + r_mul(oc, r_mul(a.x, a.x)), r_mul(oc, r_mul(a.x, a.y)) - r_mul(s, a.z), r_mul(oc, r_mul(a.x, a.z)) + r_mul(s, a.y) },
        { r_mul(oc, r_mul(a.y, a.x)) + r_mul(s, a.z), c + r_mul(oc, r_mul(a.y, a.y)), r_mul(oc, r_mul(a.y, a.z)) - r_mul(s, a.x) },
        { r_mul(oc, r_mul(a.z, a.x)) - r_mul(s, a.y), r_mul(oc, r_mul(a.z, a.y)) + r_mul(s, a.x), c + r_mul(oc, r_mul(a.z, a.z)) },
    } };
    mat3_t rt;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            rt.rows[i][j] = r.rows[j][i];
    mat_mul(&x->m, &x->m, &r);
    mat_mul(&x->im, &rt, &x->im);
}

vec3_t xform_point(const xform_t *x, vec3_t p)
{
    return v3_add(xform_mat_vec(&x->m, p), v3(x->t[0], x->t[1], x->t[2]));
}

vec3_t xform_normal(const xform_t *x, vec3_t n)
{
    return v3_unit(mat_vec(&x->im, n, true)); /* (M^-1)^T n */
}
