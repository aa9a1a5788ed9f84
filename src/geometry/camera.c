/* camera.c - eye rays as docs/shading-model.md defines them. */
#include "camera.h"

#include "rt_error.h"
#include "rt_render.h"

RT_COLD const char *camera_setup(camera_t *c, const view_t *view, int32_t span, int32_t sub, int32_t cx, int32_t cy)
{
    vec3_t fwd = v3_sub(view->at, view->from);
    if (fwd.x == 0 && fwd.y == 0 && fwd.z == 0)
        return "view: 'from' and 'at' are the same point";
    if (!(view->angle > 0 && view->angle < r_from_int(180)))
        return "view: angle must be between 0 and 180 degrees (exclusive)";
    c->eye = view->from;
    c->at = view->at;
    c->start = 0;
    vec3_t w = v3_unit(fwd); /* forward */
    c->u = v3_unit_cross(w, view->up);
    if (c->u.x == 0 && c->u.y == 0 && c->u.z == 0)
        return "view: 'up' is zero or parallel to the view direction";
    c->v = v3_unit_cross(c->u, w);
    c->cx = cx;
    c->cy = cy;
    real_wide_t tan_half = view->tan_half;
    real_wide_t half_step = span > 0 ? r_wdiv_int(tan_half, span * sub) : 0;
    /* T at the distance of `at` (within 16, like all geometry), unless the
     * view is so wide there that T's offsets would pass 256 (a wide lens,
     * or a far camera): then at unit distance */
    real_t dist = v3_length(fwd);
    if (tan_half > r_to_wide(R_RATIO(64, 1)) || r_wmul_real(tan_half, dist) > r_to_wide(R_RATIO(256, 1))) {
        c->at = v3_add(c->eye, w);
        dist = R_ONE;
    }
    c->half_span = r_wmul_real(half_step, dist);
#if RT_RAY_CONES
    c->spread = r_from_wide(half_step + half_step);
#endif
    return 0;
}

RT_COLD void camera_start_at_bounds(camera_t *c, vec3_t min, vec3_t max)
{
    vec3_t half = v3_scale(v3_sub(max, min), R_RATIO(1, 2));
    vec3_t centre = v3_add(min, half);
    real_t gap = v3_length(v3_sub(centre, c->eye)) - v3_length(half);
    c->start = gap > 0 ? gap : 0;
}

/* T = at + a u - b v: the model's w + a' u - b' v scaled by |at - eye|,
 * so eye -> T is the exact ray; offsets in units of s/2 are integers and
 * each product is rounded once. |a|, |b| <= max(256, tan_half) and |at| <
 * 513 (camera_init), so up to a lens of 179.8 degrees none needs a
 * saturation test (a wider one would only saturate its edges). The row
 * part at - b v is made once a row (camera_row), or a sample for a walk
 * down a column (camera_column_row). */
/* The row part at - b v of row j (m = 2j - cy). */
static RT_INLINE void row_part(const camera_t *c, int32_t m, real_wide_t part[3])
{
#if RT_BACKEND_FIXED
    real_t b = r_from_wide_in_range(fx_mul64x(m, c->half_span)); /* (the same product, 32 x 64 bits) */
#else
    real_t b = r_from_wide_in_range(c->half_span * m);
#endif
    part[0] = r_to_wide(c->at.x) - r_wmul(b, c->v.x);
    part[1] = r_to_wide(c->at.y) - r_wmul(b, c->v.y);
    part[2] = r_to_wide(c->at.z) - r_wmul(b, c->v.z);
}

/* Column i's part of the walk: k = 2i - cx and, in the fixed build, the
 * step dt and T's column part kt = k (s/2) u (inline in camera_row, so a
 * build without progressive display links no camera_column). */
static RT_INLINE int32_t column_part(const camera_t *c, int32_t i, real_wide_t dt[3], real_wide_t kt[3])
{
    int32_t k = 2 * i - c->cx;
#if RT_BACKEND_FIXED
    /* the fixed build walks T along the row in the wide format: the step
     * s u rounded once to 2^-2F, so T is good to 2^-2F a sample (under
     * 2^-(F+8) across the widest row), for three additions a sample
     * instead of three 64-bit products */
    const real_t u[3] = { c->u.x, c->u.y, c->u.z };
    for (int n = 0; n < 3; n++) {
        dt[n] = r_wmul_real(2 * c->half_span, u[n]);
        kt[n] = fx_mul64x(k, dt[n]) >> 1; /* k (s/2) u */
    }
#else
    (void)dt, (void)kt;
#endif
    return k;
}

/* Row j added to a row walk that holds its column part (row->t in the
 * fixed build). */
static RT_INLINE void add_row_part(const camera_t *c, int32_t j, camera_row_t *row)
{
    real_wide_t part[3];
    row->m = 2 * j - c->cy;
    row_part(c, row->m, part);
    row->dk = 2;
    for (int n = 0; n < 3; n++) {
#if RT_BACKEND_FIXED
        row->t[n] += part[n];
#else
        row->row[n] = part[n];
#endif
    }
}

RT_COLD void camera_column(const camera_t *c, int32_t i, camera_column_t *col)
{
#if RT_BACKEND_FIXED
    col->k = column_part(c, i, col->dt, col->kt);
#else
    col->k = column_part(c, i, 0, 0);
#endif
}

void camera_column_row(const camera_t *c, const camera_column_t *col, int32_t j, camera_row_t *row)
{
    row->k = col->k;
#if RT_BACKEND_FIXED
    for (int n = 0; n < 3; n++) {
        row->dt[n] = col->dt[n];
        row->t[n] = col->kt[n];
    }
#endif
    add_row_part(c, j, row);
}

RT_COLD void camera_row(const camera_t *c, int32_t i, int32_t j, camera_row_t *row)
{
#if RT_BACKEND_FIXED
    row->k = column_part(c, i, row->dt, row->t);
#else
    row->k = column_part(c, i, 0, 0);
#endif
    add_row_part(c, j, row);
}

ray_t camera_next(const camera_t *c, camera_row_t *row)
{
#if RT_BACKEND_FIXED
    vec3_t t = v3(r_from_wide_in_range(row->t[0]), r_from_wide_in_range(row->t[1]), r_from_wide_in_range(row->t[2]));
    for (int n = 0; n < 3; n++)
        row->t[n] += row->dt[n];
#else
    real_t a = r_from_wide_in_range(c->half_span * row->k);
    vec3_t t = v3(r_from_wide_in_range(row->row[0] + r_wmul(a, c->u.x)),
                  r_from_wide_in_range(row->row[1] + r_wmul(a, c->u.y)),
                  r_from_wide_in_range(row->row[2] + r_wmul(a, c->u.z)));
#endif
    row->k += row->dk;
    vec3_t to_t = v3_sub(t, c->eye);
    ray_t r;
    real_t dist;
    r.dir = v3_unit_len(to_t, &dist);
    /* back from T along the rounded direction to `start` from the eye
     * (an error in |to_t| moves the origin along the ray: nothing). The
     * step is inside the range: |to_t| near 2048 needs the eye far out,
     * and then `start` is almost as long. */
    r.origin = v3_madd_in_range(t, c->start - dist, r.dir);
    r.from = PRIM_NONE;
    r.from_far = false;
    r.leaf = RT_NO_LEAF;
#if RT_RAY_CONES
    r.cone_spread = c->spread; /* the cone's apex is at the eye */
    r.cone_width = r_mul(c->spread, c->start);
#endif
    return r;
}

ray_t camera_ray(const camera_t *c, int32_t i, int32_t j)
{
    camera_row_t row;
    camera_row(c, i, j, &row);
    return camera_next(c, &row);
}

/* Searched offsets: 2^16 half spans either way, where the half span times
 * that stays inside the wide range (half_span <= 2^7). */
#define BOX_REACH ((int32_t)1 << 16)

/* The bound on the offset k (2i - cx or 2j - cy) of rays whose slope in the
 * T plane is num / den (den > 0): the largest k whose T offset k s/2 is at
 * most dist num / den (upper) or the smallest at least it, two samples
 * wider; unbounded past 64 or past the searched reach. */
RT_COLD static int32_t camera_bound(const camera_t *c, real_t dist, real_t num, real_t den, bool upper)
{
    int32_t unbounded = upper ? INT32_MAX : INT32_MIN;
    if (r_to_wide(r_abs(num)) >= r_wmul(den, R_RATIO(64, 1)))
        return unbounded;
    real_wide_t a = r_wmul(dist, r_div(num, den));
    int32_t lo = -BOX_REACH, hi = BOX_REACH; /* binary search: k s/2 grows with k */
    while (lo < hi) {
        if (upper) { /* the largest k with k s/2 <= a */
            int32_t mid = lo + (hi - lo + 1) / 2;
            if (c->half_span * mid <= a)
                lo = mid;
            else
                hi = mid - 1;
        } else { /* the smallest k with k s/2 >= a */
            int32_t mid = lo + (hi - lo) / 2;
            if (c->half_span * mid >= a)
                hi = mid;
            else
                lo = mid + 1;
        }
    }
    if (lo <= -BOX_REACH + 4 || lo >= BOX_REACH - 4)
        return unbounded;
    return upper ? lo + 4 : lo - 4;
}

/* A point p of the sphere (from the eye: u, v, w components pu, pv, pw >
 * 0) is on the ray through T offset (a, -b) when a = dist pu / pw and b =
 * -dist pv / pw; pu and pv are within r of the centre's, pw within r of
 * its, so a and b lie between the extreme quotients below. The radius is
 * widened by 2^-8 + |l| 2^-12: an eye ray's line passes within 2^-9 of the
 * eye, and its direction is good to a few 2^-20. */
RT_COLD void camera_sphere_box(const camera_t *c, vec3_t centre, real_t radius, int32_t box[4])
{
    box[0] = box[2] = INT32_MIN;
    box[1] = box[3] = INT32_MAX;
    vec3_t f = v3_sub(c->at, c->eye), l = v3_sub(centre, c->eye);
    real_t dist = v3_length(f);
    real_t r = radius + R_RATIO(1, 256) + r_mul(v3_length(l), R_RATIO(1, 4096));
    real_t pu = v3_dot(l, c->u), pv = -v3_dot(l, c->v), pw = v3_dot(l, v3_unit(f));
    real_t near = pw - r, far = pw + r;
    if (near < R_RATIO(1, 16) || c->half_span > r_to_wide(R_RATIO(128, 1)))
        return;
    box[0] = camera_bound(c, dist, pu - r, pu - r >= 0 ? far : near, false);
    box[1] = camera_bound(c, dist, pu + r, pu + r >= 0 ? near : far, true);
    box[2] = camera_bound(c, dist, pv - r, pv - r >= 0 ? far : near, false);
    box[3] = camera_bound(c, dist, pv + r, pv + r >= 0 ? near : far, true);
}

/* Q16.16 value v times 2^k as a scalar: false if out of range. */
static bool q16_to_real(int32_t v, int32_t k, real_t *out)
{
#if RT_BACKEND_FIXED
    return r_ldexp((real_t)v, k + FX_FRAC_BITS - 16, out);
#else
    return r_ldexp((real_t)v * (real_t)(1.0 / 65536), k, out);
#endif
}

static bool vec_from_q16(const int32_t v[3], int32_t k, real_t limit, vec3_t *out)
{
    real_t c[3];
    for (int i = 0; i < 3; i++)
        if (!q16_to_real(v[i], k, &c[i]) || r_abs(c[i]) >= limit)
            return false;
    *out = v3(c[0], c[1], c[2]);
    return true;
}

/* A user's viewpoint in the scene's scaled units, as the reader would
 * have read it: positions scaled and range-checked, up as given, the
 * angle's half tangent. */
static bool view_from_q16(const rt_view_t *u, int32_t scale_log2, view_t *v)
{
    real_t far = r_from_int((int32_t)1 << RT_FAR_EXTENT_LOG2);
    if (!vec_from_q16(u->from, scale_log2, far, &v->from) || !vec_from_q16(u->at, scale_log2, far, &v->at) ||
        !vec_from_q16(u->up, 0, far, &v->up) || !q16_to_real(u->angle, 0, &v->angle))
        return false;
    v->tan_half = v->angle > 0 && v->angle < r_from_int(180) ? r_tan_deg_wide(v->angle / 2) : 0;
    return true; /* camera_init rejects a degenerate view */
}

_Static_assert(sizeof(view_t) <= sizeof(rt_camera_t) && _Alignof(view_t) <= _Alignof(rt_camera_t),
               "rt_camera_t (rt_render.h) holds a view_t");

RT_COLD int rt_camera_from_view(rt_camera_t *cam, const rt_scene_t *sc, const rt_view_t *u, rt_error_t *err)
{
    view_t *v = (view_t *)(void *)cam;
    camera_t check;
    if (!view_from_q16(u, sc->scale_log2, v)) {
        rt_error_set(err, 0, "view: a position beyond the range the camera may take (RT_FAR_EXTENT_LOG2)");
        return -1;
    }
    const char *why = camera_init(&check, v, 1, 1);
    if (why) {
        rt_error_set(err, 0, why);
        return -1;
    }
    return 0;
}
