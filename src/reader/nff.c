/*
 * nff.c - NFF reader: text in a caller's buffer to a scene_store_t.
 *
 * The top layer of the reader (layers: nff_lex.h): the NFF grammar, the
 * keyword table that dispatches every entity (NFF's and the solids' of
 * nff_solids.c), and the two passes (measure the scene's range, then
 * build it). Uses nff_solids.c, nff_scene.c and nff_lex.c; none of them
 * calls back.
 */
#include "nff.h"
#include "rt.h"

#include "geometry/bvh.h"
#include "geometry/camera.h"
#include "geometry/geometry.h"
#include "nff_lex.h"
#include "nff_scene.h"
#include "nff_solids.h"
#include "nff_surfaces.h"

/* ---- entities --------------------------------------------------------- */

/* The next token must be the viewpoint's field `key`. */
static bool view_key(reader_t *r, const char *key)
{
    if (!lex_next(&r->lx))
        return false;
    if (!lex_is(&r->lx, key))
        return lex_fail_missing(&r->lx, "v: expected ", key);
    return true;
}

/* 'from' and 'at' less than this many steps of the position grid apart
 * (in every coordinate) are one point: further apart, they are distinct
 * points to every build, also to the float build, whose spacing out at
 * the camera's extent is 2^(RT_FAR_EXTENT_LOG2 - 24), 32 steps in Q.20
 * (a fraction of one with fewer fraction bits). */
#define VIEW_MIN_STEPS 64
_Static_assert((int64_t)(VIEW_MIN_STEPS - 1) << 24 > (int64_t)1 << (RT_FAR_EXTENT_LOG2 + FX_FRAC_BITS),
               "two points VIEW_MIN_STEPS apart on the grid are more than a float spacing apart");

/* The view's degenerate cases, decided on the grid (the same integers in
 * every build; docs/scenes.md): NULL, or why there is no camera. *cross
 * is (at - from) x up on the grid, exact (|at - from| < 2^30 steps, |up|
 * < 2^24). */
static const char *view_degenerate(const int32_t from[3], const int32_t at[3], const int32_t up[3],
                                   int64_t fwd[3], int64_t cross[3])
{
    bool same = true;
    int64_t up64[3];
    for (int i = 0; i < 3; i++) {
        fwd[i] = (int64_t)at[i] - from[i];
        same = same && fwd[i] < VIEW_MIN_STEPS && fwd[i] > -VIEW_MIN_STEPS;
        up64[i] = up[i];
    }
    if (same)
        return "view: 'from' and 'at' are the same point (under 64 steps of the position grid apart)";
    rd_cross(fwd, up64, cross);
    if (cross[0] == 0 && cross[1] == 0 && cross[2] == 0)
        return "view: 'up' is zero or parallel to the view direction";
    return 0;
}

static bool read_view(reader_t *r)
{
    view_t *v = &r->st->scene.view;
    uint32_t line = r->lx.tok_line, w = 0, h = 0;
    real_t hither; /* ignored by the model */
    int32_t from_g[3], at_g[3], up_g[3];
    if (r->have_view)
        return lex_fail(&r->lx, line, "v: a second viewpoint");
    r->far = true;
    bool ok = view_key(r, "from") && rd_pos3_grid(r, "from", &v->from, from_g);
    r->far = false;
    bool zero; /* a zero 'up' is a parallel one */
    decimal_t a;
    if (!ok || !view_key(r, "at") || !rd_pos3_grid(r, "at", &v->at, at_g) || !view_key(r, "up") ||
        !lex_direction_grid(&r->lx, "up", &v->up, &zero, up_g) || !view_key(r, "angle") ||
        !lex_decimal(&r->lx, "angle", &a))
        return false;
    /* 0 < angle < 180 as every build resolves it: 2^-21 (half the fixed
     * build's unit) from each end, decided on the value */
    if (a.neg || decimal_cmp(&a, 1, -21) < 0 || decimal_cmp(&a, 180u * 2097152u - 1u, -21) >= 0)
        return lex_fail(&r->lx, r->lx.tok_line, "view: angle must be between 0 and 180 degrees (exclusive)");
    if (!lex_scalar(&r->lx, "angle", &a, &v->angle))
        return false;
    v->tan_half = r_tan_deg_wide(v->angle / 2);
    if (!view_key(r, "hither") || !lex_real(&r->lx, "hither", &hither) || !view_key(r, "resolution"))
        return false;
    ok = lex_count(&r->lx, "resolution", 1, RT_MAX_WIDTH, &w) && lex_count(&r->lx, "resolution", 1, RT_MAX_HEIGHT, &h);
    r->st->scene.width = (uint16_t)w;
    r->st->scene.height = (uint16_t)h;
    if (!ok)
        return false;
    r->have_view = true;
    if (r->measuring)
        return true;
    int64_t fwd[3], cross[3];
    const char *why = view_degenerate(from_g, at_g, up_g, fwd, cross);
    if (why)
        return lex_fail(&r->lx, line, why);
    camera_t cam;
    if (camera_init(&cam, v, r->st->scene.width, r->st->scene.height)) {
        /* the build's rounding made `up` parallel where the grid's is not
         * (a few steps off the view direction): `up` as the component of
         * the grid's up across the view, which no rounding makes parallel */
        int64_t c[3], f[3], p[3];
        rd_cut(cross, c);
        rd_cut(fwd, f);
        rd_cross(c, f, p);
        v->up = rd_direction(p);
        why = camera_init(&cam, v, r->st->scene.width, r->st->scene.height);
        if (why) /* not expected: the grid's verdict stands for every build */
            return lex_fail(&r->lx, line, why);
    }
    return true;
}

static bool read_light(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    if (!r->measuring && !CHECK_ROOM(r, sc->n_lights, RT_MAX_LIGHTS, "lights"))
        return false;
    light_t scratch = { 0 }, *l = r->measuring ? &scratch : &r->st->lights[sc->n_lights];
    r->far = true;
    bool ok = rd_pos3(r, "l", &l->pos);
    r->far = false;
    if (!ok)
        return false;
    l->colour = v3(R_ONE, R_ONE, R_ONE);
    /* optional colour: three more numbers on the same line */
    bool colour;
    if (!lex_next_on_line(&r->lx, &colour))
        return false;
    if (colour) {
        decimal_t d;
        if (!lex_tok_decimal(&r->lx, "l", ": expected a number or the end of the line", &d) ||
            !lex_scalar(&r->lx, "l", &d, &l->colour.x) || !lex_real(&r->lx, "l", &l->colour.y) ||
            !lex_real(&r->lx, "l", &l->colour.z))
            return false;
    }
    if (!r->measuring)
        sc->n_lights++;
    return true;
}

static bool read_material(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    material_t m;
    if (!lex_vec3(&r->lx, "f", &m.colour) || !lex_real(&r->lx, "f", &m.kd) || !lex_real(&r->lx, "f", &m.ks) ||
        !lex_shine(&r->lx, "f: Phong exponent must be from 0 to 524287", false, &m.shine))
        return false;
    decimal_t t, ior;
    if (!lex_decimal(&r->lx, "f", &t) || !lex_scalar(&r->lx, "f", &t, &m.t) || !lex_decimal(&r->lx, "f", &ior) ||
        !lex_scalar(&r->lx, "f", &ior, &m.ior))
        return false;
    m.texture = TEXTURE_NONE;
    /* decided on the values: 1 / ior must fit the fixed range too */
    if (!t.neg && t.mant != 0 && (ior.neg || decimal_cmp(&ior, 1, -10) < 0))
        return lex_fail(&r->lx, r->lx.tok_line, "f: index of refraction must be at least 2^-10 (1/1024)");
    r->have_material = true;
    if (r->measuring)
        return true;
    /* reuse an identical material (SPD files repeat a few many times) */
    for (uint32_t i = 0; i < sc->n_materials; i++) {
        const material_t *o = &r->st->materials[i];
        if (o->colour.x == m.colour.x && o->colour.y == m.colour.y && o->colour.z == m.colour.z &&
            o->kd == m.kd && o->ks == m.ks && o->shine == m.shine && o->t == m.t &&
            o->ior == m.ior && o->texture == m.texture) {
            r->material = (uint16_t)i;
            r->have_material = true;
            return true;
        }
    }
    if (!CHECK_ROOM(r, sc->n_materials, RT_MAX_MATERIALS, "materials"))
        return false;
    r->st->materials[sc->n_materials] = m;
    r->material = (uint16_t)sc->n_materials++;
    r->have_material = true;
    return true;
}

static bool read_sphere(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    uint32_t line = r->lx.tok_line;
    vec3_t c;
    real_t rad;
    decimal_t d;
    if (!rd_need_material(r, "s") ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_spheres, RT_MAX_SPHERES, "spheres")) ||
        !rd_pos3(r, "s", &c) || !rd_pos_decimal(r, "s", &d, &rad))
        return false;
    if (r->measuring)
        return true;
    if (rd_grid(r, &d) == 0)
        return lex_fail(&r->lx, line, "sphere radius is zero");
    const char *why = sphere_init(&r->st->spheres[sc->n_spheres], c, rad, r->material);
    if (why)
        return lex_fail(&r->lx, line, why);
    sc->n_spheres++;
    return true;
}

static bool read_cone(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    uint32_t line = r->lx.tok_line;
    vec3_t base, apex;
    real_t rb, ra;
    decimal_t db, da;
    int32_t gb[3], ga[3];
    if (!rd_need_material(r, "c") ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_cones, RT_MAX_CONES, "cones")) ||
        !rd_pos3_grid(r, "c", &base, gb) || !rd_pos_decimal(r, "c", &db, &rb) || !rd_pos3_grid(r, "c", &apex, ga) ||
        !rd_pos_decimal(r, "c", &da, &ra))
        return false;
    if (r->measuring)
        return true;
    if (gb[0] == ga[0] && gb[1] == ga[1] && gb[2] == ga[2])
        return lex_fail(&r->lx, line, "cone base and apex are the same point");
    int32_t rb_g = rd_grid(r, &db), ra_g = rd_grid(r, &da);
    if (rb_g == 0 && ra_g == 0)
        return lex_fail(&r->lx, line, "cone radii are both zero");
    /* too flat: the radii differ by over 256 times the height, on the
     * grid: dr^2 > 2^16 h^2, exact in 64 bits (geometry stays below 2^24
     * steps); flatter, it is an annulus to within the fixed precision, and
     * its slope would overflow the intersection sums */
    int64_t dr = (int64_t)(ra_g < 0 ? -ra_g : ra_g) - (rb_g < 0 ? -rb_g : rb_g), h2 = 0;
    for (int i = 0; i < 3; i++)
        h2 += ((int64_t)ga[i] - gb[i]) * ((int64_t)ga[i] - gb[i]);
    if (h2 < ((int64_t)1 << 46) && dr * dr > h2 * 65536)
        return lex_fail(&r->lx, line, "cone too flat for the fixed range (radius change over 256 times its height)");
    const char *why = cone_init(&r->st->cones[sc->n_cones], base, rb, apex, ra, r->material);
    if (why)
        return lex_fail(&r->lx, line, why);
    sc->n_cones++;
    return true;
}

static bool read_polygon(reader_t *r, bool patch)
{
    scene_t *sc = &r->st->scene;
    const char *what = patch ? "pp" : "p";
    uint32_t line = r->lx.tok_line, n;
    if (!rd_need_material(r, what) ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_polygons, RT_MAX_POLYGONS, "polygons and patches")))
        return false;
    if (!lex_count(&r->lx, what, 3, 0xFFFFFFFFu >> 8, &n))
        return false;
    if (n > RT_MAX_POLY_VERTS)
        return lex_over_capacity(&r->lx, "vertices in one polygon", "RT_MAX_POLY_VERTS", RT_MAX_POLY_VERTS);
    if (!r->measuring && n > RT_MAX_VERTICES - sc->n_vertices)
        return lex_over_capacity(&r->lx, "vertices", "RT_MAX_VERTICES", RT_MAX_VERTICES);
    if (!r->measuring && patch && n > RT_MAX_VERTICES - sc->n_normals)
        return lex_over_capacity(&r->lx, "patch normals", "RT_MAX_VERTICES", RT_MAX_VERTICES);
    /* on the grid: the first three vertices' edges and their cross
     * product (exact: edges below 2^25 steps); area once any vertex is
     * off the line of the first two distinct ones */
    int64_t g0[3] = { 0 }, e[3][3] = { { 0 } }, first3[3] = { 0 };
    bool have_line = false, area = false;
    for (uint32_t i = 0; i < n; i++) {
        vec3_t scratch;
        int32_t g[3];
        if (!rd_pos3_grid(r, what, r->measuring ? &scratch : &r->st->vertices[sc->n_vertices + i], g))
            return false;
        int64_t d[3], c[3];
        for (int k = 0; k < 3; k++) {
            if (i == 0)
                g0[k] = g[k];
            d[k] = g[k] - g0[k];
        }
        if (i == 1 || i == 2)
            for (int k = 0; k < 3; k++)
                e[i][k] = d[k];
        if (i == 2) {
            int64_t a[3] = { e[1][0], e[1][1], e[1][2] }, b[3] = { e[2][0] - a[0], e[2][1] - a[1], e[2][2] - a[2] };
            rd_cross(a, b, first3); /* (v1 - v0) x (v2 - v1) */
        }
        if (!have_line) {
            have_line = d[0] != 0 || d[1] != 0 || d[2] != 0;
            for (int k = 0; have_line && k < 3; k++)
                e[0][k] = d[k];
        } else if (!area) {
            rd_cross(e[0], d, c);
            area = c[0] != 0 || c[1] != 0 || c[2] != 0;
        }
        if (patch) {
            vec3_t nv;
            bool zero;
            if (!lex_direction(&r->lx, what, &nv, &zero))
                return false;
            if (zero)
                return lex_fail(&r->lx, r->lx.tok_line, "pp: vertex normal is zero");
            if (r->measuring)
                continue;
            nv = v3_unit(nv);
            r->st->normals[sc->n_normals + i] = nv;
        }
    }
    if (r->measuring)
        return true;
    if (!area) {
        sc->n_flat_skipped++; /* invisible: nothing to intersect */
        return true;
    }
    if (first3[0] == 0 && first3[1] == 0 && first3[2] == 0)
        return lex_fail(&r->lx, line, "polygon's first three vertices are collinear");
    const char *why = polygon_init(&r->st->polygons[sc->n_polygons], r->st->vertices,
                                   sc->n_vertices, (uint16_t)n,
                                   patch ? sc->n_normals : POLY_NO_NORMALS, r->material, rd_direction(first3));
    if (why)
        return lex_fail(&r->lx, line, why);
    sc->n_vertices += n;
    if (patch)
        sc->n_normals += n;
    sc->n_polygons++;
    return true;
}


static bool read_background(reader_t *r)
{
    return lex_vec3(&r->lx, "b", &r->st->scene.background);
}

static bool read_p(reader_t *r) { return read_polygon(r, false); }
static bool read_pp(reader_t *r) { return read_polygon(r, true); }

/* 's' is NFF's sphere, or inside a block a sphere solid (transformable). */
static bool read_s(reader_t *r)
{
    return r->n_blocks ? rd_sphere_solid(r) : read_sphere(r);
}

/* ---- the keyword table -------------------------------------------------- */

/* What an entity needs before it: nothing, or the viewpoint (the error
 * names the word for NFF's entities, says "a solid or block" for the
 * solids'). */
typedef enum { ANY_TIME, AFTER_VIEW, SOLID_AFTER_VIEW } view_rule_t;

typedef struct {
    const char *word;
    bool (*read)(reader_t *r); /* called with the word as the current token */
    view_rule_t view;
    bool in_blocks;            /* allowed inside transform and CSG blocks */
} keyword_t;

static const keyword_t keywords[] = {
    { "v", read_view, ANY_TIME, true },
    { "b", read_background, ANY_TIME, true },
    { "l", read_light, AFTER_VIEW, false },
    { "f", read_material, AFTER_VIEW, true },
    { "s", read_s, AFTER_VIEW, true },
    { "c", read_cone, AFTER_VIEW, false },
    { "p", read_p, AFTER_VIEW, false },
    { "pp", read_pp, AFTER_VIEW, false },
    { "transform", rd_transform_block, SOLID_AFTER_VIEW, true },
    { "union", rd_union_block, SOLID_AFTER_VIEW, true },
    { "intersection", rd_intersection_block, SOLID_AFTER_VIEW, true },
    { "difference", rd_difference_block, SOLID_AFTER_VIEW, true },
    { "end", rd_end_block, ANY_TIME, true },
    { "translate", rd_translate, SOLID_AFTER_VIEW, true },
    { "rotate", rd_rotate, SOLID_AFTER_VIEW, true },
    { "scale", rd_scale, SOLID_AFTER_VIEW, true },
    { "box", rd_box, SOLID_AFTER_VIEW, true },
    { "torus", rd_torus, SOLID_AFTER_VIEW, true },
    { "quadric", rd_quadric, SOLID_AFTER_VIEW, true },
    { "ellipsoid", rd_ellipsoid, SOLID_AFTER_VIEW, true },
    { "paraboloid", rd_paraboloid, SOLID_AFTER_VIEW, true },
    { "hyperboloid", rd_hyperboloid, SOLID_AFTER_VIEW, true },
    { "hyperboloid2", rd_hyperboloid2, SOLID_AFTER_VIEW, true },
    { "quadcone", rd_quadcone, SOLID_AFTER_VIEW, true },
    { "quadcylinder", rd_quadcylinder, SOLID_AFTER_VIEW, true },
    { "plane", rd_plane, AFTER_VIEW, false },
    { "checker", rd_checker, AFTER_VIEW, true },
    { "marble", rd_marble, AFTER_VIEW, true },
    { "sky", rd_sky, ANY_TIME, false },
};

static bool read_entity(reader_t *r)
{
    lexer_t *lx = &r->lx;
    const keyword_t *k = keywords;
    const keyword_t *end = keywords + sizeof keywords / sizeof keywords[0];
    while (k < end && !lex_is(lx, k->word))
        k++;
    if (k == end)
        return lex_fail_tok(lx, "", "unknown entity (expected v, b, l, f, c, s, p, pp, plane, sky, a texture, a solid or a block)");
    if (r->n_blocks && !k->in_blocks) {
        rt_error_set(lx->err, lx->tok_line, "'");
        rt_error_append(lx->err, k->word);
        rt_error_append(lx->err, "' is not allowed inside a transform or CSG block");
        return false;
    }
    if (k->view == AFTER_VIEW && !r->have_view) {
        rt_error_set(lx->err, lx->tok_line, "'");
        rt_error_append(lx->err, k->word);
        rt_error_append(lx->err, "' before the 'v' viewpoint");
        return false;
    }
    if (k->view == SOLID_AFTER_VIEW && !r->have_view)
        return lex_fail(lx, lx->tok_line, "a solid or block before the 'v' viewpoint");
    return k->read(r);
}

/* The scene scale k (docs/shading-model.md, "The scene scale"): the
 * largest k that brings every geometry number's value strictly below
 * 2^RT_SCENE_EXTENT_LOG2 and every camera and light number's below
 * 2^RT_FAR_EXTENT_LOG2 (so distances stay inside the scalar's range), as
 * large as possible (so positions keep the most fraction bits). max_exp2
 * holds the least p with |value| < 2^p over the numbers, exactly. */
static bool choose_scale(reader_t *r)
{
    static const int32_t extent[2] = { RT_SCENE_EXTENT_LOG2, RT_FAR_EXTENT_LOG2 };
    unsigned f = 2; /* which extent binds; 2: nothing measured */
    int32_t k = 0;
    for (unsigned i = 0; i < 2; i++) {
        if (r->max_exp2[i] == INT32_MIN)
            continue;
        int32_t ki = extent[i] - r->max_exp2[i];
        if (f == 2 || ki < k) {
            k = ki;
            f = i;
        }
    }
    if (f == 2) {
        r->scale_log2 = 0;
        return true;
    }
    if (k < RT_SCALE_LOG2_MIN) {
        rt_error_set(r->lx.err, r->max_line[f], r->max_what[f]);
        rt_error_append(r->lx.err, ": scene too large for the fixed range (a coordinate of 2^");
        rt_error_append_int(r->lx.err, r->max_exp2[f] - 1);
        rt_error_append(r->lx.err, " or more; all must stay below 2^");
        rt_error_append_int(r->lx.err, extent[f] - RT_SCALE_LOG2_MIN);
        rt_error_append(r->lx.err, ")");
        return false;
    }
    if (k > RT_SCALE_LOG2_MAX) {
        rt_error_set(r->lx.err, r->max_line[f], r->max_what[f]);
        rt_error_append(r->lx.err, ": scene too small for the fixed range (every coordinate below 2^");
        rt_error_append_int(r->lx.err, r->max_exp2[f]);
        rt_error_append(r->lx.err, "; the largest must reach 2^");
        rt_error_append_int(r->lx.err, extent[f] - RT_SCALE_LOG2_MAX - 1);
        rt_error_append(r->lx.err, ")");
        return false;
    }
    r->scale_log2 = k;
    return true;
}

static bool read_pass(reader_t *r)
{
    for (;;) {
        if (!lex_next(&r->lx))
            return false;
        if (r->lx.tok == 0)
            return rd_blocks_closed(r);
        if (!read_entity(r))
            return false;
    }
}

static void reader_start(reader_t *r, const char *text, size_t len, scene_store_t *store, rt_error_t *err)
{
    *r = (reader_t){ 0 };
    lex_start(&r->lx, text, len, err);
    r->st = store;
}

bool nff_read(const char *text, size_t len, scene_store_t *store, rt_error_t *err)
{
    reader_t r;
    reader_start(&r, text, len, store, err);
    r.measuring = true;
    r.max_exp2[0] = r.max_exp2[1] = INT32_MIN;
    err->line = 0;
    err->msg[0] = '\0';
    if (!read_pass(&r))
        return false;
    if (!r.have_view)
        return lex_fail(&r.lx, r.lx.tok_line, "no 'v' viewpoint in the file");
    if (!choose_scale(&r))
        return false;
    int32_t scale = r.scale_log2;
    reader_start(&r, text, len, store, err);
    r.scale_log2 = scale;
    scene_store_reset(store);
    scene_t *sc = &store->scene;
    sc->scale_log2 = scale;
    if (!read_pass(&r))
        return false;
    uint32_t n = sc->n_lights;
    sc->light_intensity = n ? r_div(r_sqrt(r_from_int((int32_t)n)), r_from_int(2 * (int32_t)n)) : 0;
    const char *why = bvh_build(store);
    if (why)
        return lex_fail(&r.lx, r.lx.tok_line, why);
    return true;
}

const rt_scene_t *rt_nff_load(const char *text, size_t len, rt_error_t *err)
{
    /* linked only when used: the tables at the configured capacities */
    static scene_store_t store;
    return nff_read(text, len, &store, err) ? &store.scene : (const scene_t *)0;
}
