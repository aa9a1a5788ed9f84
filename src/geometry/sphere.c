/* sphere.c - the 's' primitive. */
#include "geometry.h"

const char *sphere_init(sphere_t *s, vec3_t centre, real_t radius, uint16_t material)
{
    s->centre = centre;
    s->radius = r_abs(radius);
    s->radius2 = r_wmul(s->radius, s->radius);
    /* Below 1/16 a point's rounding (a few ulps) would be more than 2^-16
     * of the radius: such normals are normalised instead. */
    s->inv_radius = s->radius >= R_RATIO(1, 16) ? r_div(R_ONE, s->radius) : 0;
    s->material = material;
    return s->radius > 0 ? (const char *)0 : "sphere radius is zero";
}

bool ray_hit_sphere(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only)
{
    return sphere_hit_inline(s, r, tmin, t, far_only);
}

vec3_t sphere_normal(const sphere_t *s, vec3_t p)
{
    /* (p - c) / r is unit but for the point's rounding: three products
     * instead of a normalisation (a square root and a division) */
    if (s->inv_radius != 0)
        return v3_scale_in_range(v3_sub(p, s->centre), s->inv_radius);
    return v3_unit(v3_sub(p, s->centre));
}
