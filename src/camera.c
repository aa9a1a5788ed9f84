/* camera.c - eye rays as docs/shading-model.md defines them. */
#include "camera.h"

const char *camera_init(camera_t *c, const view_t *view, int32_t nx, int32_t ny)
{
    vec3_t fwd = v3_sub(view->at, view->from);
    if (fwd.x == 0 && fwd.y == 0 && fwd.z == 0)
        return "view: 'from' and 'at' are the same point";
    if (!(view->angle > 0 && view->angle < r_from_int(180)))
        return "view: angle must be between 0 and 180 degrees (exclusive)";
    c->eye = view->from;
    c->w = v3_unit(fwd);
    c->u = v3_unit_cross(c->w, view->up);
    if (c->u.x == 0 && c->u.y == 0 && c->u.z == 0)
        return "view: 'up' is zero or parallel to the view direction";
    c->v = v3_unit_cross(c->u, c->w);
    c->nx = nx;
    c->ny = ny;
    int32_t span = (nx > ny ? nx : ny) - 1;
    real_wide_t tan_half = r_tan_deg_wide(view->angle / 2);
    c->half_step = span > 0 ? tan_half / span : 0;
    return 0;
}

ray_t camera_ray(const camera_t *c, int32_t i, int32_t j)
{
    /* Offsets in units of s/2 are integers; the products stay wide so the
     * direction is rounded once, by the normalisation. */
    real_t a = r_from_wide(c->half_step * (2 * i - (c->nx - 1)));
    real_t b = r_from_wide(c->half_step * (2 * j - (c->ny - 1)));
    ray_t r;
    r.origin = c->eye;
    r.from = PRIM_NONE;
    r.from_far = false;
    real_t d[3];
    r_unit3(r_to_wide(c->w.x) + r_wmul(a, c->u.x) - r_wmul(b, c->v.x),
            r_to_wide(c->w.y) + r_wmul(a, c->u.y) - r_wmul(b, c->v.y),
            r_to_wide(c->w.z) + r_wmul(a, c->u.z) - r_wmul(b, c->v.z), d);
    r.dir = v3(d[0], d[1], d[2]);
    return r;
}
