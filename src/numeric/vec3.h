/* vec3.h - 3-vectors over real_t; dot products keep wide intermediates. */
#ifndef VEC3_H
#define VEC3_H

#include "real.h"

typedef struct {
    real_t x, y, z;
} vec3_t;

typedef vec3_t colour_t; /* r, g, b in x, y, z */

static inline vec3_t v3(real_t x, real_t y, real_t z)
{
    vec3_t v = { x, y, z };
    return v;
}
static inline vec3_t v3_add(vec3_t a, vec3_t b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
/* Colours are not range-managed like positions (a scene may say Kd = 900),
 * so their sums saturate instead of wrapping. */
static inline colour_t c3_add(colour_t a, colour_t b)
{
    return v3(r_add_sat(a.x, b.x), r_add_sat(a.y, b.y), r_add_sat(a.z, b.z));
}
static inline vec3_t v3_sub(vec3_t a, vec3_t b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3_t v3_neg(vec3_t a) { return v3(-a.x, -a.y, -a.z); }
static inline vec3_t v3_scale(vec3_t a, real_t s)
{
    return v3(r_mul(a.x, s), r_mul(a.y, s), r_mul(a.z, s));
}
/* a + s * b, each component rounded once */
static inline vec3_t v3_madd(vec3_t a, real_t s, vec3_t b)
{
    return v3(a.x + r_mul(s, b.x), a.y + r_mul(s, b.y), a.z + r_mul(s, b.z));
}
/* component-wise product (colours) */
static inline vec3_t v3_mul(vec3_t a, vec3_t b)
{
    return v3(r_mul(a.x, b.x), r_mul(a.y, b.y), r_mul(a.z, b.z));
}
static inline real_wide_t v3_wdot(vec3_t a, vec3_t b)
{
    return r_wmul(a.x, b.x) + r_wmul(a.y, b.y) + r_wmul(a.z, b.z);
}
/* a . b of unit vectors as a shading weight: the fixed build's to 2^-13 */
static inline real_t v3_cos(vec3_t a, vec3_t b) { return r_cos3(a.x, a.y, a.z, b.x, b.y, b.z); }
/* whether a . b < 0 for vectors of length <= 2 (directions, normals), exactly */
static inline bool v3_dot_negative(vec3_t a, vec3_t b) { return r_dot3_negative(a.x, a.y, a.z, b.x, b.y, b.z); }
static inline real_t v3_dot(vec3_t a, vec3_t b) { return r_from_wide(v3_wdot(a, b)); }
/* The same for directions (unit vectors, or a few units long) times
 * cosines, and a distance along a ray to a point of the scene: the caller
 * knows each product and sum stays inside the range, so they are rounded
 * as above without the saturation test (r_mul_in_range). */
static inline real_t v3_dot_in_range(vec3_t a, vec3_t b) { return r_from_wide_in_range(v3_wdot(a, b)); }
static inline vec3_t v3_scale_in_range(vec3_t a, real_t s)
{
    return v3(r_mul_in_range(a.x, s), r_mul_in_range(a.y, s), r_mul_in_range(a.z, s));
}
/* a colour times a weight w in [0, 1] (r_mul_weight) */
static inline colour_t c3_scale_weight(colour_t c, real_t w)
{
    return v3(r_mul_weight(c.x, w), r_mul_weight(c.y, w), r_mul_weight(c.z, w));
}
static inline vec3_t v3_madd_in_range(vec3_t a, real_t s, vec3_t b)
{
    return v3(a.x + r_mul_in_range(s, b.x), a.y + r_mul_in_range(s, b.y), a.z + r_mul_in_range(s, b.z));
}
static inline real_t v3_length(vec3_t a) { return r_wsqrt(v3_wdot(a, a)); }
static inline vec3_t v3_unit(vec3_t a)
{
    real_t u[3];
    r_unit3_narrow(a.x, a.y, a.z, u);
    return v3(u[0], u[1], u[2]);
}
/* a / |a|, and |a| in *len (the fixed build's from the unit's making,
 * the others' as a . unit: either within a few ulps) */
static inline vec3_t v3_unit_len(vec3_t a, real_t *len)
{
    real_t u[3];
    r_unit3_narrow_len(a.x, a.y, a.z, u, len);
    return v3(u[0], u[1], u[2]);
}
/* a made unit again where it is within 2^-10 of unit already (the mirror
 * of a unit direction about a unit normal): one Newton step of 1/|a|,
 * a (3 - |a|^2) / 2, leaves it within 2^-20 plus a unit or two of
 * rounding, for six products instead of a square root and a division. */
static inline vec3_t v3_renorm(vec3_t a)
{
#if RT_BACKEND_FIXED /* a + a (k - 1), whose small products are 32-bit ones */
    real_t e = (R_ONE - r_norm2(a.x, a.y, a.z)) / 2; /* k - 1, |a| <= 2 */
    return v3(a.x + r_mul_small(a.x, e), a.y + r_mul_small(a.y, e), a.z + r_mul_small(a.z, e));
#else
    real_t k = R_RATIO(3, 2) - v3_dot_in_range(a, a) / 2;
    return v3(a.x * k, a.y * k, a.z * k);
#endif
}
/* unit vector along a x b, from the exact (wide) cross product */
static inline vec3_t v3_unit_cross(vec3_t a, vec3_t b)
{
    real_t u[3];
    r_unit3(r_wmul(a.y, b.z) - r_wmul(a.z, b.y), r_wmul(a.z, b.x) - r_wmul(a.x, b.z),
            r_wmul(a.x, b.y) - r_wmul(a.y, b.x), u);
    return v3(u[0], u[1], u[2]);
}
static inline vec3_t v3_cross(vec3_t a, vec3_t b)
{
    return v3(r_from_wide(r_wmul(a.y, b.z) - r_wmul(a.z, b.y)),
              r_from_wide(r_wmul(a.z, b.x) - r_wmul(a.x, b.z)),
              r_from_wide(r_wmul(a.x, b.y) - r_wmul(a.y, b.x)));
}
static inline real_t v3_axis(const vec3_t *v, unsigned axis)
{
    return axis == 0 ? v->x : axis == 1 ? v->y : v->z;
}
/* The axis a unit vector lies along (+-1 there), or V3_ANY_AXIS: a plane's
 * or the sky's dot products with it are then one component. */
#define V3_ANY_AXIS 3
static inline uint8_t v3_axis_of(vec3_t u)
{
    for (unsigned a = 0; a < 3; a++)
        if (v3_axis(&u, a) == R_ONE || v3_axis(&u, a) == -R_ONE)
            return (uint8_t)a;
    return V3_ANY_AXIS;
}
/* u . v for u = +-1 along axis (not V3_ANY_AXIS): v's component, signed */
static inline real_t v3_dot_along(const vec3_t *u, uint8_t axis, const vec3_t *v)
{
    return v3_axis(u, axis) > 0 ? v3_axis(v, axis) : -v3_axis(v, axis);
}
/* u . v for unit u along axis (v3_axis_of), or any u where axis is V3_ANY_AXIS */
static inline real_t v3_dot_axis(vec3_t u, uint8_t axis, vec3_t v)
{
    return axis == V3_ANY_AXIS ? v3_dot_in_range(u, v) : v3_dot_along(&u, axis, &v);
}

#endif
