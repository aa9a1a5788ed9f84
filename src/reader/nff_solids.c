/*
 * nff_solids.c - the solids grammar, the scene syntax beyond NFF (docs/scenes.md,
 * "Solids beyond NFF"); layers: nff_lex.h. Its handlers are entries of nff.c's
 * keyword table; they use the lexer, the reader state (nff_scene.h) and
 * the solids' set-up (solid.h), never nff.c.
 *
 *   transform ... end        translate x y z | rotate ax ay az deg |
 *                            scale sx sy sz, applied to what follows
 *   union | intersection | difference ... end     CSG of the solids inside
 *   box x0 y0 z0 x1 y1 z1    torus R r            quadric a..j x0..z1
 *   ellipsoid rx ry rz       paraboloid rx ry h   hyperboloid rx ry rz h
 *   hyperboloid2 rx ry rz h  quadcone rx ry h     quadcylinder rx ry h
 *   s x y z r                inside a block: a sphere solid
 *
 * Plain NFF files never use these words, so they read as before.
 */
#include "nff_solids.h"

#include "geometry/solid.h"

/* ---- building solids ---------------------------------------------------- */

/* The innermost open CSG block, if any (transform blocks pass through). */
static block_t *csg_parent(reader_t *r)
{
    for (uint32_t i = r->n_blocks; i > 0; i--)
        if (r->blocks[i - 1].csg)
            return &r->blocks[i - 1];
    return 0;
}

/* The index of the current transform in the table (stored on first use),
 * or of `extra` (the current transform with more applied), stored anew. */
static bool current_xform(reader_t *r, const xform_t *extra, uint16_t *out)
{
    block_t *b = rd_top_block(r);
    scene_t *sc = &r->st->scene;
    if (!extra && (!b || b->identity)) {
        *out = XFORM_NONE;
        return true;
    }
    if (!extra && b->xf_index != XFORM_NONE) {
        *out = b->xf_index;
        return true;
    }
    if (!CHECK_ROOM(r, sc->n_xforms, RT_MAX_XFORMS, "transforms"))
        return false;
    xform_t *x = &r->st->xforms[sc->n_xforms];
    if (extra)
        *x = *extra;
    else
        *x = b->xf;
    *out = (uint16_t)sc->n_xforms++;
    if (!extra)
        b->xf_index = *out;
    return true;
}

static void solid_box(const scene_t *sc, uint16_t ref, vec3_t *lo, vec3_t *hi)
{
    if (!(ref & CSG_NODE_BIT)) {
        shape_world_box(sc, &sc->shapes[ref], lo, hi);
        return;
    }
    const csg_node_t *n = &sc->csg_nodes[ref & ~CSG_NODE_BIT];
    vec3_t al, ah, bl, bh;
    solid_box(sc, n->a, &al, &ah);
    if (n->op == CSG_DIFFERENCE) {
        *lo = al, *hi = ah;
        return;
    }
    solid_box(sc, n->b, &bl, &bh);
    if (n->op == CSG_UNION) {
        *lo = v3(r_min(al.x, bl.x), r_min(al.y, bl.y), r_min(al.z, bl.z));
        *hi = v3(r_max(ah.x, bh.x), r_max(ah.y, bh.y), r_max(ah.z, bh.z));
    } else {
        *lo = v3(r_max(al.x, bl.x), r_max(al.y, bl.y), r_max(al.z, bl.z));
        *hi = v3(r_min(ah.x, bh.x), r_min(ah.y, bh.y), r_min(ah.z, bh.z));
    }
}

/* A finished solid goes to the enclosing CSG block, or becomes an object. */
static bool place_solid(reader_t *r, uint16_t ref, uint32_t line)
{
    scene_t *sc = &r->st->scene;
    rt_error_t *err = r->lx.err;
    block_t *c = csg_parent(r);
    if (c) {
        c->children++;
        if (!c->has_acc) {
            c->acc = ref;
            c->has_acc = true;
            return true;
        }
        if (!CHECK_ROOM(r, sc->n_csg_nodes, RT_MAX_CSG_NODES, "CSG nodes"))
            return false;
        csg_node_t *n = &r->st->csg_nodes[sc->n_csg_nodes];
        n->op = (uint8_t)(c->csg - 1);
        n->a = c->acc;
        n->b = ref;
        c->acc = (uint16_t)(sc->n_csg_nodes++ | CSG_NODE_BIT);
        return true;
    }
    if (!CHECK_ROOM(r, sc->n_objects, RT_MAX_OBJECTS, "objects (solids and CSG trees)"))
        return false;
    if (solid_depth(sc, ref) > RT_CSG_MAX_DEPTH) {
        rt_error_set(err, line, "CSG nested deeper than RT_CSG_MAX_DEPTH = ");
        rt_error_append_int(err, RT_CSG_MAX_DEPTH);
        rt_error_append(err, " (raise it with -DRT_CSG_MAX_DEPTH=N)");
        return false;
    }
    uint32_t spans = solid_max_spans(sc, ref);
    if (spans > RT_CSG_MAX_SPANS) {
        rt_error_set(err, line, "CSG solid may need ");
        rt_error_append_int(err, (int32_t)spans);
        rt_error_append(err, " spans along a ray: capacity RT_CSG_MAX_SPANS = ");
        rt_error_append_int(err, RT_CSG_MAX_SPANS);
        rt_error_append(err, " (raise it with -DRT_CSG_MAX_SPANS=N)");
        return false;
    }
    object_t *o = &r->st->objects[sc->n_objects++];
    o->root = ref;
    solid_box(sc, ref, &o->box_min, &o->box_max);
    return true;
}

/* A new shape, with the current transform (and an extra object-space
 * scale for the named quadrics, which are unit shapes scaled). */
static bool add_shape(reader_t *r, shape_t *proto, const char *why, const vec3_t *extra_scale, uint32_t line)
{
    scene_t *sc = &r->st->scene;
    if (why)
        return lex_fail(&r->lx, line, why);
    if (!CHECK_ROOM(r, sc->n_shapes, RT_MAX_SHAPES, "shapes"))
        return false;
    if (extra_scale) {
        xform_t x;
        const block_t *b = rd_top_block(r);
        if (b)
            x = b->xf;
        else
            xform_identity(&x);
        xform_scale(&x, *extra_scale);
        if (!current_xform(r, &x, &proto->xform))
            return false;
    } else if (!current_xform(r, 0, &proto->xform)) {
        return false;
    }
    proto->material = r->material;
    shape_set_world_bound(sc, proto);
    r->st->shapes[sc->n_shapes] = *proto;
    return place_solid(r, (uint16_t)sc->n_shapes++, line);
}

/* Sizes (on the position grid, the same in every build) must be at least
 * 1/64: smaller object-space scales would put a distant ray origin past
 * the fixed range once mapped into the object's space. */
static bool sizes_ok(reader_t *r, const int32_t *grid, unsigned n, const char *what, uint32_t line)
{
    unsigned i = 0;
    while (i < n && grid[i] >= ((int32_t)1 << FX_FRAC_BITS) / 64)
        i++;
    if (i == n)
        return true;
    rt_error_set(r->lx.err, line, what);
    rt_error_append(r->lx.err, ": sizes must be positive and at least 1/64 of the scene scale");
    return false;
}

/* ---- blocks ------------------------------------------------------------- */

static bool open_block(reader_t *r, const char *name, uint8_t csg)
{
    if (r->n_blocks == RT_MAX_BLOCK_DEPTH)
        return lex_over_capacity(&r->lx, "nested blocks", "RT_MAX_BLOCK_DEPTH", RT_MAX_BLOCK_DEPTH);
    block_t *parent = rd_top_block(r), *b = &r->blocks[r->n_blocks++];
    *b = (block_t){ 0 };
    b->name = name;
    b->csg = csg;
    b->line = r->lx.tok_line;
    b->xf_index = XFORM_NONE;
    if (parent) {
        b->xf = parent->xf;
        b->identity = parent->identity;
        b->xf_index = parent->xf_index;
        b->extent_exp2 = parent->extent_exp2;
    } else {
        xform_identity(&b->xf);
        b->identity = true;
    }
    if (!csg)
        b->extent_exp2 += 1; /* rotations and offsets may add up */
    return true;
}

bool rd_transform_block(reader_t *r) { return open_block(r, "transform", 0); }
bool rd_union_block(reader_t *r) { return open_block(r, "union", 1 + CSG_UNION); }
bool rd_intersection_block(reader_t *r) { return open_block(r, "intersection", 1 + CSG_INTERSECTION); }
bool rd_difference_block(reader_t *r) { return open_block(r, "difference", 1 + CSG_DIFFERENCE); }

bool rd_end_block(reader_t *r)
{
    const block_t *b = rd_top_block(r);
    if (!b)
        return lex_fail(&r->lx, r->lx.tok_line, "'end' without an open block");
    block_t done = *b;
    r->n_blocks--;
    if (!done.csg || r->measuring)
        return true;
    if (done.children < 2) {
        rt_error_set(r->lx.err, done.line, done.name);
        rt_error_append(r->lx.err, " needs at least two solids");
        return false;
    }
    return place_solid(r, done.acc, done.line);
}

bool rd_blocks_closed(reader_t *r)
{
    const block_t *b = rd_top_block(r);
    if (!b)
        return true;
    rt_error_set(r->lx.err, b->line, "'");
    rt_error_append(r->lx.err, b->name);
    rt_error_append(r->lx.err, "' block never closed with 'end'");
    return false;
}

/* ---- transform steps ---------------------------------------------------- */

/* The block a step changes: the innermost, which must be a transform block. */
static block_t *step_block(reader_t *r)
{
    block_t *b = rd_top_block(r);
    if (!b || b->csg) {
        lex_fail_tok(&r->lx, "", "transform steps belong right inside a 'transform' block");
        return 0;
    }
    return b;
}

/* The block's transform changed: store it again on next use. */
static bool stepped(block_t *b)
{
    b->identity = false;
    b->xf_index = XFORM_NONE;
    return true;
}

bool rd_translate(reader_t *r)
{
    block_t *b = step_block(r);
    vec3_t v;
    if (!b || !rd_pos3(r, "translate", &v))
        return false;
    if (!r->measuring)
        xform_translate(&b->xf, v);
    return stepped(b);
}

bool rd_rotate(reader_t *r)
{
    block_t *b = step_block(r);
    vec3_t v;
    real_t deg;
    bool zero;
    if (!b || !lex_direction(&r->lx, "rotate", &v, &zero) || !lex_real(&r->lx, "rotate", &deg))
        return false;
    if (zero)
        return lex_fail(&r->lx, r->lx.tok_line, "rotate: the axis is zero");
    if (!r->measuring)
        xform_rotate(&b->xf, v, deg);
    return stepped(b);
}

bool rd_scale(reader_t *r)
{
    block_t *b = step_block(r);
    decimal_t d[3];
    real_t v[3];
    if (!b)
        return false;
    int32_t grow = 0; /* sizes inside grow by up to 2^grow */
    for (int i = 0; i < 3; i++) {
        if (!lex_decimal(&r->lx, "scale", &d[i]))
            return false;
        if (decimal_cmp(&d[i], 1, -6) < 0 || decimal_cmp(&d[i], 1, 6) > 0)
            return lex_fail(&r->lx, r->lx.tok_line, "scale: factors must be 1/64 to 64 in size (fixed range)");
        while (decimal_cmp(&d[i], 1, grow) > 0)
            grow++;
        if (!lex_scalar(&r->lx, "scale", &d[i], &v[i]))
            return false;
    }
    if (r->measuring)
        b->extent_exp2 += grow;
    else
        xform_scale(&b->xf, v3(v[0], v[1], v[2]));
    return stepped(b);
}

/* ---- shapes ------------------------------------------------------------- */

bool rd_box(reader_t *r)
{
    uint32_t line = r->lx.tok_line;
    vec3_t lo, hi;
    int32_t glo[3], ghi[3];
    if (!rd_need_material(r, "box") || !rd_pos3_grid(r, "box", &lo, glo) || !rd_pos3_grid(r, "box", &hi, ghi))
        return false;
    if (r->measuring)
        return true;
    if (!(glo[0] < ghi[0] && glo[1] < ghi[1] && glo[2] < ghi[2]))
        return lex_fail(&r->lx, line, "box has no volume");
    shape_t sh = { 0 };
    return add_shape(r, &sh, shape_init_box(&sh, lo, hi), 0, line);
}

bool rd_torus(reader_t *r)
{
    uint32_t line = r->lx.tok_line;
    real_t major, minor;
    decimal_t d;
    if (!rd_need_material(r, "torus") || !rd_pos(r, "torus", &major) || !rd_pos_decimal(r, "torus", &d, &minor))
        return false;
    if (r->measuring)
        return true;
    if (rd_grid(r, &d) == 0)
        return lex_fail(&r->lx, line, "torus minor radius is zero");
    shape_t sh = { 0 };
    return add_shape(r, &sh, shape_init_torus(&sh, major, minor), 0, line);
}

/* A quadric's clip box, in object space, reaches at most 64 from its
 * origin: its coordinates stay well inside the fixed range. */
#define QUADRIC_REACH_STEPS ((int32_t)64 << FX_FRAC_BITS)
#define QUADRIC_TOO_LONG "quadric too long for the fixed range (its clip box reaches over 64 times its radii)"

/* A general quadric's coefficients follow the scene scale 2^k like the
 * positions do: q(x / 2^k) 2^2k keeps the same surface. */
bool rd_quadric(reader_t *r)
{
    uint32_t line = r->lx.tok_line;
    decimal_t d[10];
    real_t q[10];
    vec3_t lo, hi;
    if (!rd_need_material(r, "quadric"))
        return false;
    for (int i = 0; i < 10; i++)
        if (!lex_decimal(&r->lx, "quadric", &d[i]))
            return false;
    int32_t lo_g[3], hi_g[3];
    if (!rd_pos3_grid(r, "quadric", &lo, lo_g) || !rd_pos3_grid(r, "quadric", &hi, hi_g))
        return false;
    if (r->measuring)
        return true;
    /* the clip box on the grid: not empty, and reaching at most 64 */
    for (int i = 0; i < 3; i++) {
        if (lo_g[i] >= hi_g[i])
            return lex_fail(&r->lx, line, "quadric clip box is empty (need x0 < x1, y0 < y1, z0 < z1)");
        if (lo_g[i] < -QUADRIC_REACH_STEPS || hi_g[i] > QUADRIC_REACH_STEPS)
            return lex_fail(&r->lx, line, QUADRIC_TOO_LONG);
    }
    int32_t k = r->scale_log2;
    for (int i = 0; i < 10; i++)
        if (!lex_scalar_scaled(&r->lx, "quadric", &d[i], i < 6 ? 0 : i < 9 ? k : 2 * k, &q[i]))
            return false;
    shape_t sh = { 0 };
    const char *why = shape_init_quadric(&sh, q, lo, hi);
    return add_shape(r, &sh, why, 0, line);
}

/* The named quadrics: unit shapes q <= 0 in a clip box, scaled. */
typedef enum { ELLIPSOID, PARABOLOID, HYPERBOLOID, HYPERBOLOID2, QUADCONE, QUADCYLINDER } named_quadric_t;

static bool named_quadric(reader_t *r, const char *what, named_quadric_t kind)
{
    uint32_t line = r->lx.tok_line;
    vec3_t s = { 0 };
    real_t h = 0;
    bool has_h = kind != ELLIPSOID;
    bool three_radii = kind == ELLIPSOID || kind == HYPERBOLOID || kind == HYPERBOLOID2;
    decimal_t d[4];
    real_t *size[4] = { &s.x, &s.y, &s.z, &h };
    unsigned n = 0; /* the sizes read: rx ry [rz] [h] */
    if (!rd_need_material(r, what))
        return false;
    for (unsigned i = 0; i < 4; i++)
        if ((i < 2 || (i == 2 && three_radii) || (i == 3 && has_h)) && !rd_pos_decimal(r, what, &d[n++], size[i]))
            return false;
    if (r->measuring)
        return true;
    if (!three_radii)
        s.z = h; /* the unit shape spans z in [0, 1] or [-1, 1] */
    int32_t g[4];
    for (unsigned i = 0; i < n; i++)
        g[i] = rd_grid(r, &d[i]);
    if (!sizes_ok(r, g, n, what, line))
        return false;
    if (kind == HYPERBOLOID || kind == HYPERBOLOID2) {
        /* the unit shape's clip box reaches h / rz along z and sqrt((h /
         * rz)^2 +- 1) across it; decided on the grid, exactly (sizes are
         * below 2^31 steps, so h^2 < 2^62; from rz = 2^25 on, 4095 rz^2
         * passes that, and h^2 stays below it): two sheets need h > rz,
         * and neither reaches past 64 */
        int64_t rz = g[2], hz = g[3];
        if (kind == HYPERBOLOID2 && hz <= rz)
            return lex_fail(&r->lx, line, "hyperboloid2: height must exceed rz (the sheets start at |z| = rz)");
        bool too_long = kind == HYPERBOLOID ? rz < ((int64_t)1 << 25) && hz * hz > 4095 * rz * rz : hz > 64 * rz;
        if (too_long)
            return lex_fail(&r->lx, line, QUADRIC_TOO_LONG);
    }
    real_t q[10] = { R_ONE, R_ONE, 0, 0, 0, 0, 0, 0, 0, 0 };
    vec3_t lo = v3(-R_ONE, -R_ONE, -R_ONE), hi = v3(R_ONE, R_ONE, R_ONE);
    switch (kind) {
    case ELLIPSOID:
        q[2] = R_ONE, q[9] = -R_ONE;
        break;
    case PARABOLOID:
        q[8] = -R_ONE; /* x^2 + y^2 - z */
        lo.z = 0;
        break;
    case HYPERBOLOID:
    case HYPERBOLOID2: {
        /* unit hyperboloid x^2 + y^2 - z^2 -+ 1 clipped at |z| <= h / rz */
        bool one_sheet = kind == HYPERBOLOID;
        real_t zc = r_div(h, s.z);
        q[2] = -R_ONE, q[9] = one_sheet ? -R_ONE : R_ONE;
        real_wide_t m2 = r_wmul(zc, zc) + (one_sheet ? r_to_wide(R_ONE) : -r_to_wide(R_ONE));
        real_t m = m2 > 0 ? r_wsqrt(m2) : 0;
        if (m < R_ULPS(1)) /* h a step or so over rz: rounding must not empty the box */
            m = R_ULPS(1);
        lo = v3(-m, -m, -zc);
        hi = v3(m, m, zc);
        break;
    }
    case QUADCONE:
        q[2] = -R_ONE; /* x^2 + y^2 - z^2 */
        break;
    default:
        q[9] = -R_ONE; /* cylinder x^2 + y^2 - 1 */
        break;
    }
    shape_t sh = { 0 };
    const char *why = shape_init_quadric(&sh, q, lo, hi);
    return add_shape(r, &sh, why, &s, line);
}

bool rd_ellipsoid(reader_t *r) { return named_quadric(r, "ellipsoid", ELLIPSOID); }
bool rd_paraboloid(reader_t *r) { return named_quadric(r, "paraboloid", PARABOLOID); }
bool rd_hyperboloid(reader_t *r) { return named_quadric(r, "hyperboloid", HYPERBOLOID); }
bool rd_hyperboloid2(reader_t *r) { return named_quadric(r, "hyperboloid2", HYPERBOLOID2); }
bool rd_quadcone(reader_t *r) { return named_quadric(r, "quadcone", QUADCONE); }
bool rd_quadcylinder(reader_t *r) { return named_quadric(r, "quadcylinder", QUADCYLINDER); }

/* The unit sphere, placed and scaled by the block's transform. */
bool rd_sphere_solid(reader_t *r)
{
    uint32_t line = r->lx.tok_line;
    vec3_t c;
    real_t a;
    decimal_t d;
    if (!rd_need_material(r, "s") || !rd_pos3(r, "s", &c) || !rd_pos_decimal(r, "s", &d, &a))
        return false;
    if (r->measuring)
        return true;
    a = r_abs(a);
    int32_t g = rd_grid(r, &d);
    g = g < 0 ? -g : g;
    if (g == 0)
        return lex_fail(&r->lx, line, "sphere radius is zero");
    if (!sizes_ok(r, &g, 1, "s", line))
        return false;
    const real_t q[10] = { R_ONE, R_ONE, R_ONE, 0, 0, 0, 0, 0, 0, -R_ONE };
    shape_t sh = { 0 };
    xform_t x = rd_top_block(r)->xf;
    xform_translate(&x, c);
    xform_scale(&x, v3(a, a, a));
    /* the transform first: a full table reports transforms, not shapes */
    if (!current_xform(r, &x, &sh.xform))
        return false;
    const char *why = shape_init_quadric(&sh, q, v3(-R_ONE, -R_ONE, -R_ONE), v3(R_ONE, R_ONE, R_ONE));
    if (why) /* cannot happen: the unit box is valid */
        return lex_fail(&r->lx, line, why);
    sh.material = r->material;
    scene_t *sc = &r->st->scene;
    shape_set_world_bound(sc, &sh);
    if (!CHECK_ROOM(r, sc->n_shapes, RT_MAX_SHAPES, "shapes"))
        return false;
    r->st->shapes[sc->n_shapes] = sh;
    return place_solid(r, (uint16_t)sc->n_shapes++, line);
}
