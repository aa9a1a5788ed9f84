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
    vec3_t l = v3_sub(s->centre, r->origin);
    real_t v = v3_dot(l, r->dir); /* distance to the point of closest approach */
    /* Early rejection (MIT 6.837): the whole sphere lies beyond the best hit
     * or behind the origin. */
    if (v - s->radius >= *t || v + s->radius <= tmin)
        return false;
    /* disc = r^2 - |l_perp|^2 from the perpendicular itself: its rounding
     * error scales with the radius, not with the distance (v^2 - |l|^2
     * would cancel catastrophically for a small, far sphere). */
    vec3_t perp = v3_madd(l, -v, r->dir);
    real_wide_t disc = s->radius2 - v3_wdot(perp, perp);
    if (disc < 0)
        return false;
    real_t h = r_wsqrt(disc);
    real_t t0 = v - h;
    if (t0 <= tmin || far_only)
        t0 = v + h;
    if (t0 <= tmin || t0 >= *t)
        return false;
    *t = t0;
    return true;
}

vec3_t sphere_normal(const sphere_t *s, vec3_t p)
{
    return v3_unit(v3_sub(p, s->centre));
}
