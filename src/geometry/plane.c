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

bool ray_hit_plane(const plane_t *pl, const ray_t *r, real_t tmin, real_t *t)
{
    return plane_hit_inline(pl, r, tmin, t);
}

bool plane_hit_inside(const ray_t *r, real_t t0)
{
    const real_wide_t far = r_to_wide(PLANE_FAR);
    const real_t o[3] = { r->origin.x, r->origin.y, r->origin.z }, d[3] = { r->dir.x, r->dir.y, r->dir.z };
    for (unsigned a = 0; a < 3; a++) {
        real_wide_t p = r_to_wide(o[a]) + r_wmul(t0, d[a]);
        if (p >= far || p <= -far)
            return false;
    }
    return true;
}
