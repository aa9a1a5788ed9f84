/* polygon.c - the 'p' (polygon) and 'pp' (patch) primitives. */
#include "geometry.h"

/* A point projected on the polygon's plane of largest extent. */
typedef struct {
    real_t u, v;
} pt2_t;

static inline pt2_t project_axis(unsigned drop_axis, vec3_t a)
{
    pt2_t r;
    switch (drop_axis) {
    case 0: r.u = a.y; r.v = a.z; break;
    case 1: r.u = a.z; r.v = a.x; break;
    default: r.u = a.x; r.v = a.y; break;
    }
    return r;
}

static pt2_t project(const polygon_t *p, vec3_t a) { return project_axis(p->drop_axis, a); }

/* Twice the signed area of (a, b, c): > 0 when c is left of a->b. Exact. */
static real_wide_t edge_fn(pt2_t a, pt2_t b, pt2_t c)
{
    return r_wmul(b.u - a.u, c.v - a.v) - r_wmul(b.v - a.v, c.u - a.u);
}

/* A 'p' rectangle whose sides run along the axes of its plane, which is
 * an axis plane (Ng exactly a unit axis), each side at least 1/16 long:
 * the SPD floors. For it, N . D, N . O and so the box test's products are
 * exact, and the box test (unpadded) gives the inside test's answer where
 * the hit is inside by a margin (ray_hit_polygon). The fixed build's. */
static bool axis_rect(const polygon_t *p, const vec3_t *v, uint16_t count, uint32_t normals)
{
#if RT_BACKEND_FIXED
    const real_t n[3] = { p->normal.x, p->normal.y, p->normal.z };
    if (count != 4 || normals != POLY_NO_NORMALS || !p->convex || r_abs(n[p->drop_axis]) != R_ONE ||
        n[(p->drop_axis + 1) % 3] != 0 || n[(p->drop_axis + 2) % 3] != 0)
        return false;
    unsigned prev_axis = 3;
    for (uint32_t i = 0; i < count; i++) {
        vec3_t e = v3_sub(v[(i + 1) % count], v[i]);
        const real_t c[3] = { e.x, e.y, e.z };
        unsigned along = 3, moved = 0;
        for (unsigned k = 0; k < 3; k++) {
            if (c[k] != 0)
                along = k, moved++;
        }
        /* one axis in the plane, alternating with the neighbours' */
        if (moved != 1 || along == p->drop_axis || along == prev_axis || r_abs(c[along]) < R_RATIO(1, 16))
            return false;
        prev_axis = along;
    }
    return true;
#else
    (void)p, (void)v, (void)count, (void)normals;
    return false;
#endif
}

const char *polygon_init(polygon_t *p, const vec3_t *pool, uint32_t first, uint16_t count,
                         uint32_t normals, uint16_t material, vec3_t grid_normal)
{
    const vec3_t *v = &pool[first];
    p->first = first;
    p->count = count;
    p->normals = normals;
    p->material = material;
    p->normal = v3_unit_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[1]));
    if (p->normal.x == 0 && p->normal.y == 0 && p->normal.z == 0)
        p->normal = v3_unit(grid_normal);
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
    /* convex (in the projection): consecutive edges all turn one way */
    bool left = false, right = false;
    for (uint32_t i = 0; i < count; i++) {
        pt2_t a = project(p, v[i]), b = project(p, v[(i + 1) % count]), c = project(p, v[(i + 2) % count]);
        real_wide_t e = edge_fn(a, b, c);
        left |= e > 0;
        right |= e < 0;
    }
    p->convex = !(left && right);
    p->rect = axis_rect(p, v, count, normals);
    /* Slack so the exact box test never rejects a hit that the rounded
     * inside test (or a neighbour sharing the edge) would accept. */
    const real_t slack = RT_BOX_SLACK;
    p->box_min = v3(p->box_min.x - slack, p->box_min.y - slack, p->box_min.z - slack);
    p->box_max = v3(p->box_max.x + slack, p->box_max.y + slack, p->box_max.z + slack);
    return 0;
}

/* Even-odd rule: count edges crossed by the ray from q towards +u. Inline
 * with a constant axis, so each of the three copies loads just the two
 * coordinates it needs (this loop is most of the time on the gears). */
#if RT_USE_CONCAVE
static inline bool even_odd_axis(const vec3_t *v, uint32_t count, pt2_t q, unsigned axis)
{
    bool inside = false;
    pt2_t a = project_axis(axis, v[count - 1]);
    for (uint32_t i = 0; i < count; i++) {
        pt2_t b = project_axis(axis, v[i]);
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

static bool inside_even_odd(const scene_t *sc, const polygon_t *p, pt2_t q)
{
    const vec3_t *v = &sc->vertices[p->first];
    switch (p->drop_axis) {
    case 0: return even_odd_axis(v, p->count, q, 0);
    case 1: return even_odd_axis(v, p->count, q, 1);
    default: return even_odd_axis(v, p->count, q, 2);
    }
}
#endif

/* Watertight inside tests. Which side of the edge (p, q) the ray passes:
 * the sign of D . ((p - O) x (q - O)). The two faces sharing an edge see it
 * in opposite directions; computing it in one canonical vertex order and
 * negating makes both get exactly opposite values, whatever the rounding,
 * so no ray slips between them. */
static bool vertex_before(vec3_t a, vec3_t b)
{
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

RT_NOINLINE static int edge_side(const ray_t *r, const vec3_t *p, const vec3_t *q)
{
    bool flip = vertex_before(*q, *p);
    vec3_t a = v3_sub(flip ? *q : *p, r->origin), b = v3_sub(flip ? *p : *q, r->origin);
    /* a x b exactly (wide), then its dot with D at full precision */
    int s = r_wsign_dot(r->dir.x, r->dir.y, r->dir.z, r_wmul(a.y, b.z) - r_wmul(a.z, b.y),
                        r_wmul(a.z, b.x) - r_wmul(a.x, b.z), r_wmul(a.x, b.y) - r_wmul(a.y, b.x));
    return flip ? -s : s;
}

/* A value rounded from a wide one, which GCC would otherwise keep in 64
 * bits and multiply 64x64 (five instructions for one SMULL); the empty
 * barrier of fx_mul64_hi. */
static inline real_t narrow(real_t x)
{
#if RT_BACKEND_FIXED && defined(__GNUC__)
    __asm__("" : "+r"(x));
#endif
    return x;
}

#if RT_BACKEND_FIXED
/* edge_side's answer without its canonical order and normalising shift,
 * where they cannot change it; 0 where they might. With a = p - O and
 * b = q - O, n = a x b is exact and edge_side's n is +-n. Split each
 * n_k = h_k 2^32 + l_k at its words, h_k signed and l_k in [0, 2^32):
 * D . n = H 2^32 + L for H = sum d_k h_k and L = sum d_k l_k, where
 * d_k l_k = d_k (l_k - 2^31) + d_k 2^31 makes L three SMLALs from
 * bias = 2^31 sum d_k (inside_ring's), so top = H + (L >> 32) is
 * floor(D . n / 2^32) exactly. fx_wdot3_sign_short's shift moves D . n by
 * less than sum |d_k| 2^s <= 2^46 (|d_k| <= 2, s <= 23): where
 * |D . n| >= 2^46 it gives this sign. */
static inline int edge_side_sure(const ray_t *r, vec3_t a, vec3_t b, int64_t bias)
{
    int64_t nx = r_wmul(a.y, b.z) - r_wmul(a.z, b.y), ny = r_wmul(a.z, b.x) - r_wmul(a.x, b.z),
            nz = r_wmul(a.x, b.y) - r_wmul(a.y, b.x);
    int32_t hx = narrow((int32_t)(nx >> 32)), hy = narrow((int32_t)(ny >> 32)), hz = narrow((int32_t)(nz >> 32));
    int32_t lx = (int32_t)((uint32_t)nx ^ 0x80000000u), ly = (int32_t)((uint32_t)ny ^ 0x80000000u),
            lz = (int32_t)((uint32_t)nz ^ 0x80000000u);
    int64_t h = fx_mul64(r->dir.x, hx) + fx_mul64(r->dir.y, hy) + fx_mul64(r->dir.z, hz);
    int64_t l = bias + fx_mul64(r->dir.x, lx) + fx_mul64(r->dir.y, ly) + fx_mul64(r->dir.z, lz);
    int64_t top = h + (l >> 32);
    if ((uint64_t)(top + (1 << 14)) < (1u << 15))
        return 0; /* |D . n| may be below 2^46 */
    return top < 0 ? -1 : 1;
}

static inline int64_t edge_bias(const ray_t *r)
{
    return (int64_t)((uint64_t)(int64_t)(r->dir.x + r->dir.y + r->dir.z) << 31); /* 2^31 sum d_k */
}
#else
static inline int64_t edge_bias(const ray_t *r) { return (void)r, 0; }
#endif

/* The side of the edge from vertex p to q, with a = p - O and b = q - O. */
static inline int edge_sign(const ray_t *r, const vec3_t *p, const vec3_t *q, vec3_t a, vec3_t b,
                            int64_t bias)
{
#if RT_BACKEND_FIXED
    int s = edge_side_sure(r, a, b, bias);
    if (s)
        return s;
#else
    (void)a, (void)b, (void)bias;
#endif
    return edge_side(r, p, q);
}

/* The ray passes every edge of the ring of n vertices on the same side
 * (zero is either side). Vertex k of the ring is v[0] for k = 0, else
 * v[base + k]: the polygon itself for base 0 and n = count, or the fan
 * triangle (0, base + 1, base + 2) for n = 3. Each vertex's difference
 * from the origin is taken once. */
static bool inside_ring(const ray_t *r, const vec3_t *v, uint32_t base, uint32_t n)
{
    const vec3_t *p = &v[base + n - 1];
    vec3_t a = v3_sub(*p, r->origin);
    int64_t bias = edge_bias(r);
    bool pos = false, neg = false;
    for (uint32_t k = 0; k < n; k++) {
        const vec3_t *q = &v[k ? base + k : 0];
        vec3_t b = v3_sub(*q, r->origin);
        int s = edge_sign(r, p, q, a, b, bias);
        pos |= s > 0;
        neg |= s < 0;
        if (pos && neg)
            return false;
        p = q;
        a = b;
    }
    return true;
}

/* A convex polygon: the ray passes every edge on the same side. */
static bool inside_convex(const scene_t *sc, const polygon_t *p, const ray_t *r)
{
    return inside_ring(r, &sc->vertices[p->first], 0, p->count);
}

#if RT_USE_PATCHES
/* A patch: inside one triangle of its fan (a triangle is its own fan). */
static bool inside_fan(const scene_t *sc, const polygon_t *p, const ray_t *r)
{
    const vec3_t *v = &sc->vertices[p->first];
    for (uint32_t i = 1; i + 1 < p->count; i++) {
        if (inside_ring(r, v, i - 1, 3))
            return true;
    }
    return false;
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

#endif

/* N . D, and c - N . O for the plane N . x = c, rounded as v3_dot does.
 * The fixed build leaves out the saturation that |N . D| <= 6 never
 * reaches, tests N . O's (a camera some 1000 units away) once instead of
 * twice, and keeps both 32-bit (narrow). */
static inline void plane_dist(const polygon_t *p, const ray_t *r, real_t *denom, real_t *num)
{
#if RT_BACKEND_FIXED
    *denom = narrow((real_t)fx_round_shift(v3_wdot(p->normal, r->dir), FX_FRAC_BITS));
    int64_t w = fx_round_shift(v3_wdot(p->normal, r->origin), FX_FRAC_BITS);
    *num = narrow(p->offset - (w == (int32_t)w ? (int32_t)w : fx_sat64(w)));
#else
    *denom = v3_dot(p->normal, r->dir);
    *num = p->offset - v3_dot(p->normal, r->origin);
#endif
}

/* How far inside the sides lo and hi along one axis the hit o + (num /
 * denom) d is, times |denom|, computed without dividing: the nearer
 * side's (negative outside). */
static inline real_wide_t box_gap(real_t lo, real_t hi, real_t o, real_t d, real_t num, real_t denom)
{
    real_wide_t w = r_wmul(num, d), a = w - r_wmul(lo - o, denom), b = r_wmul(hi - o, denom) - w;
    if (denom < 0)
        a = -a, b = -b;
    return a < b ? a : b;
}

bool ray_hit_polygon(const scene_t *sc, const polygon_t *p, const ray_t *r, real_t tmin,
                     real_t *t)
{
    real_t denom, num;
    plane_dist(p, r, &denom, &num);
    if (denom == 0)
        return false;
    /* tmin < num / denom < *t, tested without dividing */
    real_wide_t wn = r_to_wide(num), lo = r_wmul(tmin, denom);
    if (denom > 0 ? wn <= lo : wn >= lo)
        return false;
    real_wide_t hi = r_wmul(*t, denom);
    if (denom > 0 ? wn >= hi : wn <= hi)
        return false;
    /* Bounding-box test of the hit point in the plane's two axes, still
     * without dividing: lo <= o + (num / denom) d <= hi, times denom. */
    pt2_t o = project(p, r->origin), d = project(p, r->dir);
    d.u = narrow(d.u), d.v = narrow(d.v);
    pt2_t lo2 = project(p, p->box_min), hi2 = project(p, p->box_max);
    real_wide_t gap = box_gap(lo2.u, hi2.u, o.u, d.u, num, denom);
    if (gap < 0)
        return false;
    real_wide_t gap_v = box_gap(lo2.v, hi2.v, o.v, d.v, num, denom);
    if (gap_v < 0)
        return false;
    bool inside = false;
#if RT_BACKEND_FIXED
    gap = gap < gap_v ? gap : gap_v;
    /* An axis rectangle (axis_rect) is its box less the slack. With N . D
     * and N . O exact, the gap to its side at u = lo (less the slack's
     * |denom| s) is +-(d_u (c - o_w) - d_w (lo - o_u)) exactly: the edge
     * test's D . n over the side's length e (n = (p - O) x e for p on the
     * side). Where every such gap is 2^30 or more, every D . n is 2^46 or
     * more (e >= 2^16 ulps) and of one sign, which edge_side gives too:
     * inside, without the edges. */
    inside = p->rect && gap >= ((real_wide_t)1 << 30) + r_wmul(RT_BOX_SLACK, r_abs(denom));
#endif
    /* the inside test before the division: it needs no t (but the
     * even-odd rule's point), and rejects more often than the rounded t */
    if (!inside) {
#if RT_USE_PATCHES
        if (p->normals != POLY_NO_NORMALS)
            inside = inside_fan(sc, p, r);
        else
#endif
#if RT_USE_CONCAVE
        if (!p->convex)
            inside = inside_even_odd(sc, p, project(p, ray_at(r, r_div(num, denom))));
        else
#endif
            inside = inside_convex(sc, p, r);
        if (!inside)
            return false;
    }
    real_t th = r_div(num, denom);
    if (th <= tmin || th >= *t)
        return false;
    *t = th;
    return true;
}

vec3_t polygon_shading_normal(const scene_t *sc, const polygon_t *p, vec3_t point)
{
#if !RT_USE_PATCHES
    (void)sc, (void)point;
    return p->normal;
#else
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
#endif
}
