/* plane.c - the infinite plane. */
#include "geometry.h"

const char *plane_init(plane_t *pl, vec3_t point, vec3_t normal, uint16_t material)
{
    pl->normal = v3_unit(normal);
    pl->offset = v3_dot(pl->normal, point);
    pl->material = material;
    pl->axis = v3_axis_of(pl->normal); /* a floor or a wall: N.D and N.O are one component */
    return pl->normal.x == 0 && pl->normal.y == 0 && pl->normal.z == 0 ? "plane normal is zero" : 0;
}

/* The far cube's half side: hits beyond it are not part of the scene. */
#define PLANE_FAR r_from_int((int32_t)1 << RT_FAR_EXTENT_LOG2)

bool ray_hit_plane(const plane_t *pl, const ray_t *r, real_t tmin, real_t *t)
{
    /* t = (offset - N.O) / (N.D), compared as products before the
     * division: a ray almost parallel to the plane meets it far beyond
     * the range, and its quotient would overflow */
    real_t den, num;
    if (pl->axis != V3_ANY_AXIS) { /* N = +-1 along the axis: no products */
        den = v3_dot_along(&pl->normal, pl->axis, &r->dir);
        num = pl->offset - v3_dot_along(&pl->normal, pl->axis, &r->origin);
    } else {
        den = v3_dot_in_range(pl->normal, r->dir); /* unit vectors */
        num = pl->offset - v3_dot_in_range(pl->normal, r->origin); /* |origin| < 2^10 */
    }
    if (den < 0) {
        den = -den;
        num = -num;
    }
    if (num <= 0 || r_to_wide(num) >= r_wmul(*t, den) || r_to_wide(num) <= r_wmul(tmin, den))
        return false;
    real_t t0 = r_div(num, den);
    if (t0 <= tmin || t0 >= *t)
        return false;
    /* Inside the far cube when t0 < far - 1 - max |o_a| (|d_a| <= 1 + 2^-19
     * and t0 < 2^11): most hits, at no product. Else the hit point, exact
     * in the wide type (it may lie beyond the range). */
    real_t omax = r_max(r_max(r_abs(r->origin.x), r_abs(r->origin.y)), r_abs(r->origin.z));
    if (t0 < PLANE_FAR - R_ONE - omax) {
        *t = t0;
        return true;
    }
    const real_wide_t far = r_to_wide(PLANE_FAR);
    const real_t o[3] = { r->origin.x, r->origin.y, r->origin.z }, d[3] = { r->dir.x, r->dir.y, r->dir.z };
    for (unsigned a = 0; a < 3; a++) {
        real_wide_t p = r_to_wide(o[a]) + r_wmul(t0, d[a]);
        if (p >= far || p <= -far)
            return false;
    }
    *t = t0;
    return true;
}
