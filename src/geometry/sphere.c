/* sphere.c - the 's' primitive. */
#include "geometry.h"

const char *sphere_init(sphere_t *s, vec3_t centre, real_t radius, uint16_t material)
{
    s->centre = centre;
    s->radius = r_abs(radius);
    s->radius2 = r_wmul(s->radius, s->radius);
    s->material = material;
    return s->radius > 0 ? (const char *)0 : "sphere radius is zero";
}

bool ray_hit_sphere(const sphere_t *s, const ray_t *r, real_t tmin, real_t *t, bool far_only)
{
    return sphere_hit_inline(s, r, tmin, t, far_only);
}

vec3_t sphere_normal(const sphere_t *s, vec3_t p)
{
    return v3_unit(v3_sub(p, s->centre));
}
