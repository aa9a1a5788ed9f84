/* cone.c - the 'c' primitive: open cone or cylinder, no end caps. */
#include "geometry.h"

const char *cone_init(cone_t *c, vec3_t base, real_t r_base, vec3_t apex, real_t r_apex,
                      uint16_t material)
{
    vec3_t along = v3_sub(apex, base);
    c->base = base;
    c->axis = v3_unit(along);
    c->height = v3_length(along);
    c->r0 = r_abs(r_base);
    c->material = material;
    if (c->height <= 0)
        return "cone base and apex are the same point";
    if (c->r0 == 0 && r_apex == 0)
        return "cone radii are both zero";
    /* the reader rejects a cone flatter than a radius change of 256
     * times its height, on the position grid (nff.c, read_cone) */
    c->slope = r_div(r_abs(r_apex) - c->r0, c->height);
    real_t half = c->height / 2, rmax = r_max(c->r0, r_abs(r_apex));
    c->bound_centre = v3_madd(base, half, c->axis);
    /* slack so rounding cannot cut the cone */
    c->bound_radius = r_wsqrt(r_wmul(half, half) + r_wmul(rmax, rmax)) + RT_BOX_SLACK;
    c->bound_radius2 = r_wmul(c->bound_radius, c->bound_radius);
    /* a cylinder's (r0 + (1 + r0) / 1024)^2, rounded up; 0: no such test */
    real_t miss = c->r0 + r_mul(c->r0 + R_ONE, R_RATIO(1, 1024));
    c->miss_radius2 = c->slope == 0 && miss < R_RATIO(32, 1) ? r_mul(miss, miss) + R_ULPS(1) : 0;
    return 0;
}

/* One Newton step on f(t) = |op + t dp|^2 - (rr + kdv t)^2, evaluated from
 * the geometry at t: removes the error the closed-form roots pick up from
 * rounded coefficients. */
static real_t refine_root(vec3_t op, vec3_t dp, real_t rr, real_t kdv, real_t t)
{
    vec3_t q = v3_madd(op, t, dp);
    real_t rad = r_add_sat(rr, r_mul(kdv, t));
    real_wide_t f = v3_wdot(q, q) - r_wmul(rad, rad);
    real_wide_t slope = 2 * (v3_wdot(q, dp) - r_wmul(rad, kdv));
    if (slope == 0)
        return t;
    real_t step = r_wdiv(f, slope);
    return r_abs(step) < R_ONE ? t - step : t; /* a huge step: keep t */
}

/* num / den when it lies in [0, limit); false otherwise, without a
 * division that could overflow (a root far beyond the range is a miss). */
static bool quotient_below(real_t num, real_t den, real_t limit, real_t *q)
{
    if (den == 0 || (num != 0 && (num < 0) != (den < 0)))
        return false;
    if (r_to_wide(r_abs(num)) >= r_wmul(r_abs(den), limit))
        return false;
    *q = r_div(num, den);
    return true;
}

static real_wide_t ulps(real_t x) { return r_wmul(r_abs(x), R_ULPS(1)); }

/* For a > 0, how far below 0 the discriminant b^2 - a cc of the rounded
 * a, b, cc must lie for the vertex route to find h2 < 0 too, so a miss
 * is known without its two divisions. With exact A, B, C, for any t
 * f(t) >= -(B^2 - A C) / A; the rounding of a, b, cc moves the
 * discriminant by at most (|b| + |a|/2 + |cc|/2) ulps, that of q and rad
 * moves f(tv) by at most sqrt(3) |q| + |rad| ulps, where |tv| <= 64,
 * |dp| <= 1, and |kdv| < |dp| as a > 0. In ulps of the wide products;
 * summed wide, as |op| reaches 1000 from a far camera. */
static real_wide_t vertex_slack(vec3_t op, real_t rr, real_t b, real_t cc)
{
    return ulps(b) + ulps(cc) + 2 * (ulps(op.x) + ulps(op.y) + ulps(op.z) + ulps(rr)) +
           ulps(R_RATIO(256, 1));
}

/* Whether a ray that passed the bounding sphere (l from its origin to the
 * centre, v along it) misses a cylinder (slope 0) by more than (1 + r0) /
 * 1024 (miss_radius2), as ray_hit_cone would find: from the distance
 * between the ray line and the axis line, |l . m| / |m| with m = dir x
 * axis, before the projections the quadratic needs. When |m|^2 >= 1/8
 * and |v| <= 60 - 3 bound_radius, ray_hit_cone takes the vertex route
 * (a >= 1/8, |tv| <= 64), whose q lies within 58 ulps of the ray's true
 * offset from the axis, so h2 >= 0 needs that distance below r0 + 58
 * ulps; here the rounding of m and of l . m (|l| <= 61) costs at most
 * 2.83 (55 + 0.87 r0) ulps more: the margin covers both. Out of line:
 * inlined, GCC turns the products after it into 64x64 multiplies. */
RT_NOINLINE static bool cylinder_missed(const cone_t *c, const ray_t *r, const vec3_t *l, real_t v)
{
    if (r_abs(v) > R_RATIO(60, 1) - 3 * c->bound_radius)
        return false;
    vec3_t m = v3_cross(r->dir, c->axis);
    real_wide_t mm = v3_wdot(m, m);
    if (mm < r_to_wide(R_RATIO(1, 8)))
        return false;
    real_t s = v3_dot(*l, m);
    /* both factors rounded up */
    return r_wmul(s, s) > r_wmul(c->miss_radius2, r_from_wide(mm) + R_ULPS(1));
}

/* With the ray in cone coordinates (height h along the axis, radial part
 * perpendicular to it), a point is on the surface when
 *   |radial|^2 = (r0 + slope * h)^2,
 * a quadratic a t^2 + 2 b t + c = 0 in the ray parameter. */
bool ray_hit_cone(const cone_t *c, const ray_t *r, real_t tmin, real_t *t, bool far_only)
{
    /* early rejection against the bounding sphere, as for spheres */
    vec3_t l = v3_sub(c->bound_centre, r->origin);
    real_t v = v3_dot(l, r->dir);
    if (v - c->bound_radius >= *t || v + c->bound_radius <= tmin)
        return false;
    vec3_t perp = v3_madd(l, -v, r->dir);
    if (v3_wdot(perp, perp) > c->bound_radius2 || (c->miss_radius2 > 0 && cylinder_missed(c, r, &l, v)))
        return false;

    vec3_t ob = v3_sub(r->origin, c->base);
    real_t ov = v3_dot(ob, c->axis);
    real_t dv = v3_dot(r->dir, c->axis);
    vec3_t op = v3_madd(ob, -ov, c->axis);
    vec3_t dp = v3_madd(r->dir, -dv, c->axis);
    real_t rr = c->r0, kdv = 0; /* radius at the origin's height, its change along the ray */
    if (c->slope != 0) { /* a cylinder skips two products that give r0 and 0 */
        rr = r_add_sat(c->r0, r_mul(c->slope, ov));
        kdv = r_mul(c->slope, dv);
    }

    real_t a = r_from_wide(v3_wdot(dp, dp) - r_wmul(kdv, kdv));
    real_t b = r_from_wide(v3_wdot(op, dp) - r_wmul(rr, kdv));
    real_t cc = r_from_wide(v3_wdot(op, op) - r_wmul(rr, rr));
    real_wide_t disc = r_wmul(b, b) - r_wmul(a, cc);
    if (a > 0 && disc < 0 && disc < -vertex_slack(op, rr, b, cc))
        return false; /* misses, as either route below would find */
    real_t roots[2];
    int n = 0;
    real_t tv = 0;
    /* the vertex route when the parabola is curved enough and its vertex
     * lies within reach (a far vertex means a far or no hit) */
    bool vertex = r_abs(a) >= R_RATIO(1, 64);
    if (vertex) {
        tv = r_div(-b, a);
        vertex = r_abs(tv) <= R_RATIO(64, 1);
    }
    if (vertex) {
        /* Roots tv -+ sqrt(-f(tv) / a) around the parabola's vertex tv,
         * with f evaluated there from the geometry: its rounding error
         * scales with the distance to the surface, not to the origin. */
        vec3_t q = v3_madd(op, tv, dp);
        real_t rad = rr + r_mul(kdv, tv);
        real_wide_t h2 = r_wdiv_real(r_wmul(rad, rad) - v3_wdot(q, q), a);
        if (h2 < 0)
            return false;
        real_t h = r_wsqrt(h2);
        roots[0] = r_add_sat(tv, -h);
        roots[1] = r_add_sat(tv, h);
        n = 2;
        if (far_only) { /* the root nearer the origin is the surface it starts on */
            if (r_abs(roots[0]) > r_abs(roots[1]))
                roots[1] = roots[0];
            roots[0] = roots[1];
            n = 1;
        }
    } else {
        /* Nearly parallel to a surface line: the cancellation-safe pair
         * q / a and c / q of a t^2 + 2 b t + c. */
        if (disc < 0)
            return false;
        real_t h = r_wsqrt(disc);
        real_t q = b > 0 ? -r_add_sat(b, h) : r_add_sat(h, -b);
        if (quotient_below(q, a, *t, &roots[n]))
            n++;
        /* a ray starting on the surface has cc = 0: c / q is its own root */
        if (!far_only && quotient_below(cc, q, *t, &roots[n]))
            n++;
    }
    if (n == 2 && roots[1] < roots[0]) {
        real_t tmp = roots[0];
        roots[0] = roots[1];
        roots[1] = tmp;
    }
    for (int i = 0; i < n; i++) {
        /* every position is within 16 of the origin (the reader's scale),
         * so no hit lies beyond 64 */
        if (roots[i] <= tmin || roots[i] >= *t || roots[i] > R_RATIO(64, 1))
            continue;
        real_t ti = refine_root(op, dp, rr, kdv, roots[i]);
        if (ti <= tmin || ti >= *t)
            continue;
        real_t hh = ov + r_mul(ti, dv);
        if (hh < 0 || hh > c->height)
            continue;
        *t = ti;
        return true;
    }
    return false;
}

vec3_t cone_normal(const cone_t *c, vec3_t p)
{
    vec3_t w = v3_sub(p, c->base);
    vec3_t radial = v3_madd(w, -v3_dot(w, c->axis), c->axis);
    /* gradient of |radial| - (r0 + slope h): outward, tilted by the slope */
    return v3_unit(v3_madd(v3_unit(radial), -c->slope, c->axis));
}
