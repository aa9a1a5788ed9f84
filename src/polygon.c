/* polygon.c - the 'p' (polygon) and 'pp' (patch) primitives. */
#include "geometry.h"

static bool is_zero(real_wide_t x, real_wide_t y, real_wide_t z) { return x == 0 && y == 0 && z == 0; }

bool polygon_is_flat(const vec3_t *pool, uint32_t first, uint16_t count)
{
    const vec3_t *v = &pool[first];
    uint16_t k = 1;
    while (k < count && v[k].x == v[0].x && v[k].y == v[0].y && v[k].z == v[0].z)
        k++;
    if (k == count)
        return true;
    vec3_t a = v3_sub(v[k], v[0]);
    for (uint16_t i = k + 1; i < count; i++) {
        vec3_t b = v3_sub(v[i], v[0]);
        if (!is_zero(r_wmul(a.y, b.z) - r_wmul(a.z, b.y), r_wmul(a.z, b.x) - r_wmul(a.x, b.z),
                     r_wmul(a.x, b.y) - r_wmul(a.y, b.x)))
            return false;
    }
    return true;
}

const char *polygon_init(polygon_t *p, const vec3_t *pool, uint32_t first, uint16_t count,
                         uint32_t normals, uint16_t material)
{
    const vec3_t *v = &pool[first];
    p->first = first;
    p->count = count;
    p->normals = normals;
    p->material = material;
    p->normal = v3_unit_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[1]));
    if (p->normal.x == 0 && p->normal.y == 0 && p->normal.z == 0)
        return "polygon's first three vertices are collinear";
    p->offset = v3_dot(p->normal, v[0]);
    real_t ax = r_abs(p->normal.x), ay = r_abs(p->normal.y), az = r_abs(p->normal.z);
    p->drop_axis = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    p->box_min = p->box_max = v[0];
    for (uint32_t i = 1; i < count; i++) {
        p->box_min = v3(r_min(p->box_min.x, v[i].x), r_min(p->box_min.y, v[i].y),
                        r_min(p->box_min.z, v[i].z));
        p->box_max = v3(r_max(p->box_max.x, v[i].x), r_max(p->box_max.y, v[i].y),
                        r_max(p->box_max.z, v[i].z));
    }
    return 0;
}

/* A point projected on the polygon's plane of largest extent. */
typedef struct {
    real_t u, v;
} pt2_t;

static pt2_t project(const polygon_t *p, vec3_t a)
{
    pt2_t r;
    switch (p->drop_axis) {
    case 0: r.u = a.y; r.v = a.z; break;
    case 1: r.u = a.z; r.v = a.x; break;
    default: r.u = a.x; r.v = a.y; break;
    }
    return r;
}

/* Twice the signed area of (a, b, c): > 0 when c is left of a->b. Exact. */
static real_wide_t edge_fn(pt2_t a, pt2_t b, pt2_t c)
{
    return r_wmul(b.u - a.u, c.v - a.v) - r_wmul(b.v - a.v, c.u - a.u);
}

/* Even-odd rule: count edges crossed by the ray from q towards +u. */
static bool inside_even_odd(const scene_t *sc, const polygon_t *p, pt2_t q)
{
    const vec3_t *v = &sc->vertices[p->first];
    bool inside = false;
    pt2_t a = project(p, v[p->count - 1]);
    for (uint32_t i = 0; i < p->count; i++) {
        pt2_t b = project(p, v[i]);
        if ((b.v > q.v) != (a.v > q.v)) {
            /* q is left of the edge's crossing point when edge_fn has the
             * sign of the edge's direction in v */
            real_wide_t e = edge_fn(a, b, q);
            if ((e > 0) == (b.v > a.v))
                inside = !inside;
        }
        a = b;
    }
    return inside;
}

/* Index i of the fan triangle (0, i, i+1) holding q, or 0 when none. */
static uint32_t fan_triangle(const scene_t *sc, const polygon_t *p, pt2_t q)
{
    const vec3_t *v = &sc->vertices[p->first];
    pt2_t a = project(p, v[0]);
    for (uint32_t i = 1; i + 1 < p->count; i++) {
        pt2_t b = project(p, v[i]), c = project(p, v[i + 1]);
        real_wide_t e0 = edge_fn(a, b, q), e1 = edge_fn(b, c, q), e2 = edge_fn(c, a, q);
        if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0))
            return i;
    }
    return 0;
}

bool ray_hit_polygon(const scene_t *sc, const polygon_t *p, const ray_t *r, real_t tmin,
                     real_t *t)
{
    real_t denom = v3_dot(p->normal, r->dir);
    if (denom == 0)
        return false;
    real_t num = p->offset - v3_dot(p->normal, r->origin);
    /* tmin < num / denom < *t, tested without dividing */
    real_wide_t wn = r_to_wide(num), lo = r_wmul(tmin, denom), hi = r_wmul(*t, denom);
    if (denom > 0 ? (wn <= lo || wn >= hi) : (wn >= lo || wn <= hi))
        return false;
    real_t th = r_div(num, denom);
    if (th <= tmin || th >= *t)
        return false;
    pt2_t q = project(p, ray_at(r, th));
    pt2_t lo2 = project(p, p->box_min), hi2 = project(p, p->box_max);
    if (q.u < lo2.u || q.u > hi2.u || q.v < lo2.v || q.v > hi2.v)
        return false;
    bool inside = p->normals == POLY_NO_NORMALS ? inside_even_odd(sc, p, q)
                                                : fan_triangle(sc, p, q) != 0;
    if (!inside)
        return false;
    *t = th;
    return true;
}

vec3_t polygon_shading_normal(const scene_t *sc, const polygon_t *p, vec3_t point)
{
    if (p->normals == POLY_NO_NORMALS)
        return p->normal;
    pt2_t q = project(p, point);
    uint32_t i = fan_triangle(sc, p, q);
    if (i == 0)
        return p->normal; /* rounding put the point just outside: use Ng */
    const vec3_t *v = &sc->vertices[p->first];
    const vec3_t *n = &sc->normals[p->normals];
    pt2_t a = project(p, v[0]), b = project(p, v[i]), c = project(p, v[i + 1]);
    real_wide_t area = edge_fn(a, b, c);
    real_t wb = r_wdiv(edge_fn(c, a, q), area); /* weight of b */
    real_t wc = r_wdiv(edge_fn(a, b, q), area); /* weight of c */
    real_t wa = R_ONE - wb - wc;
    vec3_t s = v3_add(v3_add(v3_scale(n[0], wa), v3_scale(n[i], wb)), v3_scale(n[i + 1], wc));
    return v3_unit(s);
}
