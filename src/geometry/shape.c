/*
 * shape.c - quadrics, tori and boxes in object space (layers: xform.h):
 * set-up, the spans of a ray through one shape, and surface normals.
 * Uses xform.h; csg.c calls shape_spans, nothing here calls csg.c.
 *
 * A world ray is first tested against the shape's world bounding sphere
 * (most rays that reach a shape miss it); a sphere that its transform keeps
 * a sphere is met right there, in world space. Otherwise the ray goes into
 * the shape's object space by the inverse transform (direction
 * renormalised, with k = |M^-1 d| so that world t = s / k), and is moved to
 * its point of closest approach to the object's origin: the shape's
 * bounding sphere rejects it there, and every root is found close to that
 * point, where the numbers are small.
 */
#include "shape.h"

#include "xform.h"

/* ---- shapes: set-up ------------------------------------------------------ */

static real_t corner_radius(vec3_t lo, vec3_t hi)
{
    vec3_t c = v3(r_max(r_abs(lo.x), r_abs(hi.x)), r_max(r_abs(lo.y), r_abs(hi.y)),
                  r_max(r_abs(lo.z), r_abs(hi.z)));
    return v3_length(c) + RT_BOUND_PAD;
}

const char *shape_init_quadric(shape_t *s, const real_t q[10], vec3_t lo, vec3_t hi)
{
    s->kind = SHAPE_QUADRIC;
    for (int i = 0; i < 10; i++)
        s->q[i] = q[i];
    s->lo = lo;
    s->hi = hi;
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        return "quadric clip box is empty (need x0 < x1, y0 < y1, z0 < z1)";
    /* the reader keeps the clip box within 64 of the origin, decided on
     * the position grid (nff_solids.c) */
    s->bound = corner_radius(lo, hi);
    /* an ellipsoid sum A_i (x_i - c_i)^2 <= K inside the clip box needs no
     * clipping, and its own box and bound are tighter */
    if (q[0] > 0 && q[1] > 0 && q[2] > 0 && q[3] == 0 && q[4] == 0 && q[5] == 0) {
        real_t c[3], rad[3], k = -q[9], far = 0;
        for (int i = 0; i < 3; i++) {
            c[i] = r_div(-q[6 + i] / 2, q[i]);
            k = r_add_sat(k, -r_mul(q[6 + i] / 2, c[i])); /* far centre: k saturates; the box test keeps the quadric */
        }
        bool inside = k > 0;
        for (int i = 0; i < 3 && inside; i++) {
            real_t a = r_sqrt(r_div(k, q[i]));
            rad[i] = a + a / 512 + RT_BOUND_PAD; /* rounding of c, k, a */
            /* touching the box (a unit sphere in [-1, 1]^3) is inside */
            inside = c[i] - a >= v3_axis(&lo, (unsigned)i) - RT_BOUND_PAD &&
                     c[i] + a <= v3_axis(&hi, (unsigned)i) + RT_BOUND_PAD;
            far = r_max(far, rad[i]);
        }
        if (inside) {
            s->kind = SHAPE_ELLIPSOID;
            s->lo = v3(c[0] - rad[0], c[1] - rad[1], c[2] - rad[2]);
            s->hi = v3(c[0] + rad[0], c[1] + rad[1], c[2] + rad[2]);
            s->bound = r_min(s->bound, v3_length(v3(c[0], c[1], c[2])) + far + RT_BOUND_PAD);
        }
    }
    return 0;
}

const char *shape_init_torus(shape_t *s, real_t major, real_t minor)
{
    s->kind = SHAPE_TORUS;
    s->q[0] = r_abs(major);
    s->q[1] = r_abs(minor);
    if (s->q[1] == 0)
        return "torus minor radius is zero";
    s->hi = v3(s->q[0] + s->q[1], s->q[0] + s->q[1], s->q[1]);
    s->lo = v3_neg(s->hi);
    s->bound = s->q[0] + s->q[1] + RT_BOUND_PAD;
    return 0;
}

const char *shape_init_box(shape_t *s, vec3_t lo, vec3_t hi)
{
    s->kind = SHAPE_BOX;
    s->lo = v3(r_min(lo.x, hi.x), r_min(lo.y, hi.y), r_min(lo.z, hi.z));
    s->hi = v3(r_max(lo.x, hi.x), r_max(lo.y, hi.y), r_max(lo.z, hi.z));
    if (!(s->lo.x < s->hi.x && s->lo.y < s->hi.y && s->lo.z < s->hi.z))
        return "box has no volume";
    s->bound = corner_radius(s->lo, s->hi);
    return 0;
}

/* The world-space sphere about the transform's origin that holds the
 * shape: the object bound times the largest stretch of M (Gershgorin on
 * M^T M), or the farthest corner of the mapped box [lo, hi] if nearer;
 * padded for rounding and for M and the M^-1 the tracer uses differing in
 * their last places (relative 2^-9, absolute RT_BOUND_PAD). */
void shape_set_world_bound(const scene_t *sc, shape_t *s)
{
    s->wbound = s->bound;
    if (s->xform == XFORM_NONE)
        return;
    const xform_t *x = &sc->xforms[s->xform];
    real_wide_t g = 0, mtm[3][3];
    for (int i = 0; i < 3; i++) {
        real_wide_t row = 0;
        for (int j = 0; j < 3; j++) {
            real_wide_t a = r_wmul(x->m.rows[0][i], x->m.rows[0][j]) + r_wmul(x->m.rows[1][i], x->m.rows[1][j]) +
                            r_wmul(x->m.rows[2][i], x->m.rows[2][j]);
            mtm[i][j] = a;
            row += a < 0 ? -a : a;
        }
        g = row > g ? row : g;
    }
    /* a sphere about the origin kept a sphere (M^T M = a^2 I to within
     * RT_BOUND_PAD relative): its world radius, exactly */
    bool sphere = s->kind == SHAPE_ELLIPSOID && s->q[0] == s->q[1] && s->q[1] == s->q[2] && s->q[6] == 0 &&
                  s->q[7] == 0 && s->q[8] == 0;
    for (int i = 0; i < 3 && sphere; i++)
        for (int j = 0; j < 3; j++) {
            real_wide_t e = mtm[i][j] - (i == j ? mtm[0][0] : 0);
            sphere &= (e < 0 ? -e : e) <= r_wmul(r_from_wide(mtm[0][0]), RT_BOUND_PAD);
        }
    if (sphere) {
        s->kind = SHAPE_SPHERE;
        s->wbound = r_mul(r_wsqrt(mtm[0][0]), r_sqrt(r_div(-s->q[9], s->q[0])));
        return;
    }
    real_t w = r_mul(s->bound, r_next_up(r_wsqrt(g))), corner = 0;
    for (int i = 0; i < 8; i++) {
        vec3_t c = xform_mat_vec(&x->m, v3(i & 1 ? s->hi.x : s->lo.x, i & 2 ? s->hi.y : s->lo.y,
                                           i & 4 ? s->hi.z : s->lo.z));
        real_t l = r_next_up(r_wsqrt(v3_wdot(c, c)));
        corner = r_max(corner, l);
    }
    w = r_min(w, corner);
    s->wbound = r_add_sat(r_add_sat(w, w / 512), RT_BOUND_PAD);
}

void shape_world_box(const scene_t *sc, const shape_t *s, vec3_t *min, vec3_t *max)
{
    const real_t pad = RT_BOX_SLACK;
    vec3_t lo = s->lo, hi = s->hi;
    if (s->xform == XFORM_NONE) {
        *min = v3(lo.x - pad, lo.y - pad, lo.z - pad);
        *max = v3(hi.x + pad, hi.y + pad, hi.z + pad);
        return;
    }
    const xform_t *x = &sc->xforms[s->xform];
    for (int i = 0; i < 8; i++) {
        vec3_t c = v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        vec3_t w = xform_point(x, c);
        if (i == 0) {
            *min = *max = w;
        } else {
            *min = v3(r_min(min->x, w.x), r_min(min->y, w.y), r_min(min->z, w.z));
            *max = v3(r_max(max->x, w.x), r_max(max->y, w.y), r_max(max->z, w.z));
        }
    }
    *min = v3(min->x - pad, min->y - pad, min->z - pad);
    *max = v3(max->x + pad, max->y + pad, max->z + pad);
}

/* ---- spans --------------------------------------------------------------- */

void spans_push(spans_t *out, bound_t in, bound_t out_b)
{
    if (out->n < RT_CSG_MAX_SPANS) { /* the reader bounds n; never drops */
        out->s[out->n].in = in;
        out->s[out->n].out = out_b;
        out->n++;
    }
}

/* The ray in a shape's object space, at its point of closest approach to
 * the origin: object parameter s = s0 + sigma, world t = s / k. */
typedef struct {
    vec3_t p0, u;
    real_t s0, k, half_chord;
} oray_t;

RT_NOINLINE static bool object_ray(const scene_t *sc, const shape_t *s, const ray_t *r, oray_t *o)
{
    const xform_t *x = s->xform == XFORM_NONE ? 0 : &sc->xforms[s->xform];
    vec3_t org = r->origin;
    real_t radius = s->bound;
    o->u = r->dir;
    o->k = R_ONE;
    if (x) { /* the world bounding sphere first: most rays that reach here miss */
        org = v3(org.x - x->t[0], org.y - x->t[1], org.z - x->t[2]);
        radius = s->wbound;
    }
    for (;;) { /* once in world space (with a transform), once in object space */
        o->s0 = -v3_dot(org, o->u);
        o->p0 = v3_madd(org, o->s0, o->u);
        real_wide_t h2 = r_wmul(radius, radius) - v3_wdot(o->p0, o->p0);
        if (h2 < 0)
            return false; /* misses the bounding sphere */
        if (!x || s->kind == SHAPE_SPHERE) {
            /* the torus's march uses the half chord; a sphere kept a
             * sphere is its world bounding sphere: its span is s0 -+ it */
            o->half_chord = s->kind == SHAPE_TORUS || s->kind == SHAPE_SPHERE ? r_wsqrt(h2) : 0;
            return true;
        }
        org = xform_mat_vec(&x->im, org);
        vec3_t d = xform_dir_to_object(x, r->dir);
        o->k = v3_length(d);
        o->u = v3_unit(d);
        radius = s->bound;
        x = 0;
    }
}

RT_NOINLINE static real_t to_world(const oray_t *o, real_t sigma)
{
    real_t s = o->s0 + sigma;
    return o->k == R_ONE ? s : r_div(s, o->k);
}

static bound_t bnd(real_t t, uint16_t shape, uint8_t face)
{
    bound_t b = { t, shape, face, 0 };
    return b;
}

/* The slab interval of the box [lo, hi] along the object ray, in sigma,
 * with the faces it enters and leaves by. */
static bool box_interval(const oray_t *o, const vec3_t *lo, const vec3_t *hi, real_t *a, real_t *b,
                         uint8_t *fa, uint8_t *fb)
{
    *a = -R_BIG;
    *b = R_BIG;
    *fa = *fb = FACE_CURVED;
    for (unsigned i = 0; i < 3; i++) {
        real_t p = v3_axis(&o->p0, i), u = v3_axis(&o->u, i);
        real_t l = v3_axis(lo, i), h = v3_axis(hi, i);
        if (r_abs(u) < RT_OBJ_PARALLEL) {
            if (p < l || p > h)
                return false;
            continue;
        }
        real_t inv = r_recip(u);
        real_t t0 = r_mul(l - p, inv), t1 = r_mul(h - p, inv);
        uint8_t f0 = (uint8_t)(FACE_XMIN + 2 * i), f1 = (uint8_t)(FACE_XMAX + 2 * i);
        if (t0 > t1) {
            real_t tt = t0;
            t0 = t1;
            t1 = tt;
            uint8_t ff = f0;
            f0 = f1;
            f1 = ff;
        }
        if (t0 > *a) {
            *a = t0;
            *fa = f0;
        }
        if (t1 < *b) {
            *b = t1;
            *fb = f1;
        }
    }
    return *a <= *b;
}

static void box_spans(const shape_t *s, uint16_t id, const oray_t *o, spans_t *out)
{
    real_t a, b;
    uint8_t fa, fb;
    if (box_interval(o, &s->lo, &s->hi, &a, &b, &fa, &fb))
        spans_push(out, bnd(to_world(o, a), id, fa), bnd(to_world(o, b), id, fb));
}

/* q(x) = x^T A x + 2 b^T x + j with A, b from the ten coefficients;
 * returns A x + b (affine) or A x. */
static vec3_t quadric_grad_half(const real_t q[10], vec3_t x, bool affine)
{
    real_t g[3];
    for (unsigned i = 0; i < 3; i++) { /* row i of A (A_ij = q[2 + i + j] / 2 off the diagonal) */
        real_wide_t w = 0;
        for (unsigned j = 0; j < 3; j++) {
            real_wide_t p = r_wmul(q[i == j ? i : 2 + i + j], v3_axis(&x, j));
            w += i == j ? p : p / 2;
        }
        g[i] = r_from_wide(w);
        if (affine)
            g[i] = r_add_sat(g[i], q[6 + i] / 2); /* saturating */
    }
    return v3(g[0], g[1], g[2]);
}

/* num / den clamped to +-R_BIG (roots far away are as good as infinite).
 * Out of line: five callers, none in an inner loop. */
RT_NOINLINE static real_t safe_div(real_t num, real_t den)
{
    if (r_to_wide(r_abs(num)) >= r_wmul(r_abs(den), R_RATIO(64, 1)))
        return (num < 0) != (den < 0) ? -R_BIG : R_BIG;
    return r_div(num, den);
}

RT_NOINLINE static void quadric_spans(const shape_t *s, uint16_t id, const oray_t *o, spans_t *out)
{
    real_t ca = -R_BIG, cb = R_BIG;
    uint8_t fa = FACE_CURVED, fb = FACE_CURVED;
    if (s->kind != SHAPE_ELLIPSOID && !box_interval(o, &s->lo, &s->hi, &ca, &cb, &fa, &fb))
        return;
    /* q along the ray: alpha sigma^2 + 2 beta sigma + gamma */
    vec3_t w = quadric_grad_half(s->q, o->p0, true);
    real_t alpha = v3_dot(o->u, quadric_grad_half(s->q, o->u, false));
    real_t beta = v3_dot(o->u, w);
    /* summed wide: a general quadric's coefficients may be large */
    real_t gamma = r_from_wide(v3_wdot(o->p0, w) + r_wmul(s->q[6] / 2, o->p0.x) + r_wmul(s->q[7] / 2, o->p0.y) +
                               r_wmul(s->q[8] / 2, o->p0.z) + r_to_wide(s->q[9]));
    /* the inside of q as at most two intervals of sigma */
    real_t iv[2][2] = { { -R_BIG, R_BIG }, { -R_BIG, R_BIG } };
    int n = 1;
    if (r_abs(alpha) < RT_QUADRIC_LINEAR) {
        if (beta == 0)
            n = gamma <= 0; /* everywhere or nowhere */
        else /* beta > 0: up to the root, else from it */
            iv[0][beta > 0] = safe_div(-gamma, r_add_sat(beta, beta));
    } else {
        real_wide_t disc = r_wmul(beta, beta) - r_wmul(alpha, gamma);
        if (disc < 0) {
            n = alpha < 0; /* everywhere or nowhere */
        } else {
            real_t h = r_wsqrt(disc);
            real_t qv = beta > 0 ? -r_add_sat(beta, h) : r_add_sat(h, -beta);
            real_t r1 = safe_div(qv, alpha), r2 = qv != 0 ? safe_div(gamma, qv) : r1;
            if (r2 < r1) {
                real_t tt = r1;
                r1 = r2;
                r2 = tt;
            }
            if (alpha > 0) { /* between the roots, else outside them */
                iv[0][0] = r1, iv[0][1] = r2;
            } else {
                iv[0][1] = r1, iv[1][0] = r2;
                n = 2;
            }
        }
    }
    /* clipped by the box; boundaries inside it are the curved surface */
    for (int i = 0; i < n; i++) {
        real_t a = r_max(iv[i][0], ca), b = r_min(iv[i][1], cb);
        if (a > b)
            continue;
        spans_push(out, bnd(to_world(o, a), id, iv[i][0] >= ca ? FACE_CURVED : fa),
             bnd(to_world(o, b), id, iv[i][1] <= cb ? FACE_CURVED : fb));
    }
}

static vec3_t torus_normal_obj(const shape_t *s, vec3_t x)
{
    real_t rho = r_wsqrt(r_wmul(x.x, x.x) + r_wmul(x.y, x.y));
    if (rho == 0)
        return v3(0, 0, x.z < 0 ? -R_ONE : R_ONE);
    /* from the nearest point of the centre circle to x */
    real_t f = R_ONE - r_div(s->q[0], rho);
    return v3_unit(v3(r_mul(x.x, f), r_mul(x.y, f), x.z));
}

/* Torus roots. Along the ray x(sigma) = p0 + sigma u the squared distance
 * to the centre circle is D = (rho - R)^2 + z^2 = sigma^2 + |p0|^2 + R^2 -
 * 2 R rho, where rho = |(x, y)| is convex in sigma (the length of an affine
 * function). So F = D - r^2 (negative inside) has two quadratic bounds:
 * above, with rho's tangent at s0 (rho >= rho0 + rho0' (sigma - s0)),
 *   F <= F0 + d^2 + 2 d (s0 - R rho0'),                 d = sigma - s0;
 * below on [s0, s1], with rho's chord (rho <= rho0 + m d, m its slope),
 *   F >= F0 + d^2 + 2 d (s0 - R m).
 * From a point outside, the lower bound's first root is a step that
 * cannot pass a root, and the upper bound's first root a point at or past
 * one; from inside, the other way round. Each iteration takes the safe
 * step from the near end and brings in the far end of the bracket, and
 * both converge on the nearest root (quadratically where the ray crosses
 * the surface). The march goes from root to root (a torus has at most
 * four) along the bounding chord, clipped to the slab |z| <= r. */

typedef struct {
    real_t s, rho, dr; /* sigma, rho and d rho / d sigma */
    real_wide_t f;     /* (rho - R)^2 + z^2 - r^2 */
} tpt_t;

/* The march's values at sigma; d rho / d sigma only
 * with `slope` (the points steps start from). */
static tpt_t torus_at(const shape_t *sh, const oray_t *o, real_t sigma, bool slope)
{
    vec3_t x = v3_madd(o->p0, sigma, o->u);
    tpt_t p;
    p.s = sigma;
    p.rho = r_wsqrt(r_wmul(x.x, x.x) + r_wmul(x.y, x.y));
    real_t q = p.rho - sh->q[0];
    p.f = r_wmul(q, q) + r_wmul(x.z, x.z) - r_wmul(sh->q[1], sh->q[1]);
    real_t xu = r_from_wide(r_wmul(x.x, o->u.x) + r_wmul(x.y, o->u.y));
    p.dr = slope && p.rho > 0 ? r_div(xu, p.rho) : 0; /* |xu| <= rho */
    return p;
}

/* The first d > 0 with d^2 + 2 beta d + g = 0, or -1 if there is none
 * (g = 0: the roots 0 and -2 beta). */
static real_t first_root(real_wide_t g, real_t beta)
{
    real_t b = r_abs(beta); /* the same square; cppcheck sees no negative shift in fx_mul64 */
    real_wide_t disc = r_wmul(b, b) - g;
    if (disc < 0 || (g >= 0 && beta >= 0))
        return -R_ONE;
    real_t h = r_wsqrt(disc);
    return g > 0 ? r_div(r_from_wide(g), h - beta) : h - beta; /* no cancellation */
}

/* The nearest root past *p before `end` (false if there is none). The
 * bounds' chord runs from a to b: `end`, or a nearer point when the chord
 * to `end` is too loose to step by, or a point past the root (bracket). */
static bool torus_cross(const shape_t *sh, const oray_t *o, tpt_t *p, tpt_t end, bool inside)
{
    const real_t r0 = sh->q[0];
    tpt_t a = *p, b = end;
    if (inside ? a.f > 0 : a.f < 0)
        a.f = 0; /* starting on the surface just crossed */
    for (int it = 0; it < RT_TORUS_STEPS; it++) {
        bool past = inside ? b.f >= 0 : b.f <= 0; /* a root lies in (a, b] */
        real_t span = b.s - a.s;
        real_t m = r_div(b.rho - a.rho, span); /* |rho'| <= 1: no overflow */
        real_t chord = a.s - r_mul(r0, m), tangent = a.s - r_mul(r0, a.dr);
        real_t step = first_root(a.f, inside ? tangent : chord);
        real_t reach = first_root(a.f, inside ? chord : tangent);
        real_t next = a.s + step;
        bool stop = false;
        if (span <= RT_TORUS_TOL || step < 0 || step >= span) { /* no root before b */
            if (!past && b.s >= end.s)
                return false;
            next = b.s; /* at the root if past, else on from there */
            stop = past;
            b = end;
        } else if (reach >= 0 && reach - step <= RT_TORUS_TOL) { /* a root in [step, reach] */
            stop = true;
        } else if (!past && step < span / 4) {
            /* slow: the chord is loose. Bring b in: outside, to where the
             * upper bound comes nearest to the surface (the closest pass);
             * inside, past where the step's bound puts the root; else
             * halfway. */
            real_t v = inside ? 2 * step : -tangent;
            b = torus_at(sh, o, a.s + (v > step && v < span ? v : span / 2), false);
            continue;
        } else if (reach > step && reach < span) { /* the upper bound's root: past the root */
            tpt_t q = torus_at(sh, o, a.s + reach, false);
            if (inside ? q.f >= 0 : q.f <= 0)
                b = q;
        }
        a = torus_at(sh, o, next, true);
        if (stop || (inside ? a.f >= 0 : a.f <= 0))
            break; /* at (or just past) the root */
    }
    *p = a;
    return true;
}

RT_NOINLINE static void torus_spans(const shape_t *s, uint16_t id, const oray_t *o, const real_t win[2],
                                    spans_t *out)
{
    /* the bounding chord, clipped to the window (sigma = k t - s0, wide:
     * the window's far end may be R_BIG) and to the slab |z| <= r */
    real_t lo = -o->half_chord, hi = o->half_chord;
    real_wide_t w0 = r_wmul(o->k, win[0]) - r_to_wide(o->s0), w1 = r_wmul(o->k, win[1]) - r_to_wide(o->s0);
    if (w0 > r_to_wide(lo + RT_TORUS_EPS))
        lo = r_from_wide(w0) - RT_TORUS_EPS;
    if (w1 < r_to_wide(hi - RT_TORUS_EPS))
        hi = r_from_wide(w1) + RT_TORUS_EPS;
    real_t slab = s->q[1] + RT_TORUS_EPS;
    if (r_abs(o->u.z) < RT_OBJ_PARALLEL) {
        if (r_abs(o->p0.z) > slab)
            return;
    } else {
        real_t t0 = safe_div(-slab - o->p0.z, o->u.z), t1 = safe_div(slab - o->p0.z, o->u.z);
        lo = r_max(lo, r_min(t0, t1));
        hi = r_min(hi, r_max(t0, t1));
    }
    if (lo >= hi)
        return;
    /* forward from root to root; a window end inside the torus bounds its
     * span by a boundary the caller never takes (t = -+R_BIG) */
    tpt_t a = torus_at(s, o, lo, true), far = torus_at(s, o, hi, true);
    bool inside = a.f <= 0;
    bound_t in = bnd(-R_BIG, id, FACE_CURVED);
    real_t entry = -R_BIG;
    for (int n = 0; n < 4; n++) {
        if (!torus_cross(s, o, &a, far, inside))
            break;
        bound_t b = bnd(to_world(o, a.s), id, FACE_CURVED);
        if (!inside)
            in = b, entry = a.s;
        else if (a.s > entry + 4 * RT_TORUS_EPS) /* else a tangent touch: no span */
            spans_push(out, in, b);
        inside = !inside;
    }
    if (inside)
        spans_push(out, in, bnd(R_BIG, id, FACE_CURVED));
}

/* Not inlined: its locals stay out of csg.c's recursive solid_spans frame. */
RT_NOINLINE void shape_spans(const scene_t *sc, uint16_t id, const ray_t *r, const real_t win[2], spans_t *out)
{
    const shape_t *s = &sc->shapes[id];
    oray_t o;
    out->n = 0;
    if (!object_ray(sc, s, r, &o))
        return;
    switch (s->kind) {
    case SHAPE_SPHERE:
        spans_push(out, bnd(o.s0 - o.half_chord, id, FACE_CURVED), bnd(o.s0 + o.half_chord, id, FACE_CURVED));
        break;
    case SHAPE_BOX: box_spans(s, id, &o, out); break;
    case SHAPE_TORUS: torus_spans(s, id, &o, win, out); break;
    default: quadric_spans(s, id, &o, out); break;
    }
}

vec3_t shape_normal(const scene_t *sc, uint16_t id, uint8_t face, vec3_t p)
{
    const shape_t *s = &sc->shapes[id];
    vec3_t x = p, n;
    const xform_t *xf = s->xform == XFORM_NONE ? 0 : &sc->xforms[s->xform];
    if (xf)
        x = xform_to_object(xf, p);
    if (face == FACE_CURVED) {
        n = s->kind == SHAPE_TORUS ? torus_normal_obj(s, x) : v3_unit(quadric_grad_half(s->q, x, true));
    } else { /* a box face: FACE_XMIN = 1, FACE_XMAX, ... */
        real_t c[3] = { 0, 0, 0 };
        c[(face - 1) / 2] = face & 1 ? -R_ONE : R_ONE;
        n = v3(c[0], c[1], c[2]);
    }
    return xf ? xform_normal(xf, n) : n;
}
