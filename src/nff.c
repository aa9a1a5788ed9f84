/*
 * nff.c - NFF reader: text in a caller's buffer to a scene_store_t.
 *
 * Whitespace-separated tokens, so an entity may span lines or share one
 * (the SPD cones put base and apex on one line). Numbers are parsed from
 * their decimal digits straight to the active scalar, correctly rounded in
 * the fixed build; no libc.
 */
#include "nff.h"

#include "bvh.h"
#include "nff_reader.h"
#include "camera.h"
#include "geometry.h"

/* ---- tokens ----------------------------------------------------------- */

static bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool rd_fail(reader_t *r, uint32_t line, const char *msg)
{
    rt_error_set(r->err, line, msg);
    return false;
}

/* "<what><msg>, found '<token>'" with the token shortened. */
bool rd_fail_tok(reader_t *r, const char *what, const char *msg)
{
    rt_error_set(r->err, r->tok_line, what);
    rt_error_append(r->err, msg);
    if (r->tok == 0) {
        rt_error_append(r->err, " (end of file)");
        return false;
    }
    char q[24];
    size_t n = 0;
    for (; n < r->tok_len && n < 16; n++)
        q[n] = r->tok[n];
    if (r->tok_len > 16) {
        q[n++] = '.';
        q[n++] = '.';
        q[n++] = '.';
    }
    q[n] = '\0';
    rt_error_append(r->err, ", found '");
    rt_error_append(r->err, q);
    rt_error_append(r->err, "'");
    return false;
}

/* Skips blanks and comments; false (with the error set) on a control or
 * non-ASCII byte, which means the file is not text. */
static bool skip_blank(reader_t *r)
{
    while (r->p < r->end) {
        unsigned char c = (unsigned char)*r->p;
        if (c == '\n') {
            r->line++;
            r->p++;
        } else if (is_space((char)c)) {
            r->p++;
        } else if (c == '#') {
            while (r->p < r->end && *r->p != '\n')
                r->p++;
        } else if (c < 0x20 || c >= 0x7F) {
            rt_error_set(r->err, r->line, "not a text file (byte ");
            rt_error_append_int(r->err, c);
            rt_error_append(r->err, ")");
            return false;
        } else {
            return true;
        }
    }
    return true;
}

/* Next token, or tok == NULL at the end of input. */
bool rd_next_token(reader_t *r)
{
    if (!skip_blank(r))
        return false;
    if (r->p >= r->end) { /* errors at the end point at the last token */
        r->tok = 0;
        r->tok_len = 0;
        return true;
    }
    r->tok_line = r->line;
    r->tok = r->p;
    while (r->p < r->end && !is_space(*r->p) && *r->p != '#') {
        unsigned char c = (unsigned char)*r->p;
        if (c < 0x20 || c >= 0x7F)
            break;
        r->p++;
    }
    r->tok_len = (size_t)(r->p - r->tok);
    return true;
}

bool rd_tok_is(const reader_t *r, const char *word)
{
    size_t i = 0;
    if (r->tok == 0)
        return false;
    for (; i < r->tok_len; i++)
        if (word[i] == '\0' || word[i] != r->tok[i])
            return false;
    return word[i] == '\0';
}

/* ---- numbers ---------------------------------------------------------- */

/* Parses the current token as [+-]digits[.digits][(e|E)[+-]digits]. */
static bool parse_decimal(const reader_t *r, decimal_t *d)
{
    int digits = 0, sig = 0;
    int32_t exp10 = 0;
    d->neg = false;
    d->mant = 0;
    if (r->tok == 0) /* end of input */
        return false;
    const char *s = r->tok, *e = r->tok + r->tok_len;
    if (s < e && (*s == '+' || *s == '-'))
        d->neg = *s++ == '-';
    for (; s < e && *s >= '0' && *s <= '9'; s++, digits++) {
        if (sig < 19) {
            d->mant = d->mant * 10 + (uint64_t)(*s - '0');
            sig += d->mant != 0;
        } else if (exp10 < 100000) {
            exp10++; /* dropped integer digit (bounded: any more is huge) */
        }
    }
    if (s < e && *s == '.') {
        for (s++; s < e && *s >= '0' && *s <= '9'; s++, digits++) {
            if (sig < 19) {
                d->mant = d->mant * 10 + (uint64_t)(*s - '0');
                sig += d->mant != 0;
                exp10--;
            }
        }
    }
    if (digits == 0)
        return false;
    if (s < e && (*s == 'e' || *s == 'E')) {
        bool eneg = false;
        int32_t ev = 0;
        s++;
        if (s < e && (*s == '+' || *s == '-'))
            eneg = *s++ == '-';
        if (s >= e || *s < '0' || *s > '9')
            return false;
        for (; s < e && *s >= '0' && *s <= '9'; s++)
            if (ev < 100000)
                ev = ev * 10 + (*s - '0');
        exp10 += eneg ? -ev : ev;
    }
    d->exp10 = exp10;
    return s == e;
}

bool rd_decimal(reader_t *r, const char *what, decimal_t *d)
{
    if (!rd_next_token(r))
        return false;
    if (!parse_decimal(r, d))
        return rd_fail_tok(r, what, ": expected a number");
    return true;
}

bool rd_out_of_range(reader_t *r, const char *what)
{
    rt_error_set(r->err, r->tok_line, what);
    rt_error_append(r->err, ": number out of range for the ");
    rt_error_append(r->err, R_BACKEND_NAME);
    rt_error_append(r->err, " build");
    return false;
}

bool rd_real(reader_t *r, const char *what, real_t *out)
{
    decimal_t d;
    if (!rd_decimal(r, what, &d))
        return false;
    if (!r_from_decimal(d.neg, d.mant, d.exp10, out))
        return rd_out_of_range(r, what);
    return true;
}

bool rd_vec3(reader_t *r, const char *what, vec3_t *v)
{
    return rd_real(r, what, &v->x) && rd_real(r, what, &v->y) && rd_real(r, what, &v->z);
}

/* An upper bound p with |mant * 10^exp10| < 2^p (within 2 of the least). */
static int32_t decimal_exp2_bound(uint64_t mant, int32_t exp10)
{
    int32_t bits = 0;
    while (bits < 64 && (mant >> bits) != 0)
        bits++;
    /* log2(10) = 3.3219...: round up for 10^e, down for 10^-e */
    int64_t e = exp10; /* |exp10| <= 200000: the products fit */
    return (int32_t)(e >= 0 ? bits + (e * 3322 + 999) / 1000 : bits - (-e * 3321) / 1000);
}

/* A position (or a length): scaled by 2^scale_log2 with the rest of the
 * scene; in the measuring pass only its size is recorded. */
bool rd_pos(reader_t *r, const char *what, real_t *out)
{
    decimal_t d;
    if (!rd_decimal(r, what, &d))
        return false;
    *out = 0;
    if (r->measuring) {
        if (d.mant != 0) {
            /* inside transform blocks sizes may grow by their scales */
            int32_t p = decimal_exp2_bound(d.mant, d.exp10) +
                        (r->n_blocks ? r->blocks[r->n_blocks - 1].extent_exp2 : 0);
            unsigned f = r->far;
            if (p > r->max_exp2[f]) {
                r->max_exp2[f] = p;
                r->max_line[f] = r->tok_line;
                r->max_what[f] = what;
            }
        }
        return true;
    }
    if (!r_from_decimal_scaled(d.neg, d.mant, d.exp10, r->scale_log2, out))
        return rd_out_of_range(r, what);
    return true;
}

bool rd_pos3(reader_t *r, const char *what, vec3_t *v)
{
    return rd_pos(r, what, &v->x) && rd_pos(r, what, &v->y) && rd_pos(r, what, &v->z);
}

/* A non-negative integer in [lo, hi]. */
static bool rd_count(reader_t *r, const char *what, uint32_t lo, uint32_t hi, uint32_t *out)
{
    decimal_t d;
    if (!rd_decimal(r, what, &d))
        return false;
    uint64_t v = d.mant;
    for (int32_t i = 0; i < d.exp10 && v <= hi; i++)
        v *= 10;
    if (d.neg || d.exp10 < 0 || v < lo || v > hi) {
        rt_error_set(r->err, r->tok_line, what);
        rt_error_append(r->err, ": expected a whole number from ");
        rt_error_append_int(r->err, (int32_t)lo);
        rt_error_append(r->err, " to ");
        rt_error_append_int(r->err, (int32_t)hi);
        return false;
    }
    *out = (uint32_t)v;
    return true;
}

/* ---- capacities ------------------------------------------------------- */

bool rd_over_capacity(reader_t *r, const char *what, const char *macro, int32_t cap)
{
    rt_error_set(r->err, r->tok_line, "too many ");
    rt_error_append(r->err, what);
    rt_error_append(r->err, ": capacity ");
    rt_error_append(r->err, macro);
    rt_error_append(r->err, " = ");
    rt_error_append_int(r->err, cap);
    rt_error_append(r->err, " (raise it with -D");
    rt_error_append(r->err, macro);
    rt_error_append(r->err, "=N)");
    return false;
}

bool rd_need_material(reader_t *r, const char *what)
{
    if (r->have_material)
        return true;
    rt_error_set(r->err, r->tok_line, what);
    rt_error_append(r->err, " before any 'f' material line");
    return false;
}

/* ---- entities --------------------------------------------------------- */

static bool read_view(reader_t *r)
{
    static const char *const keys[] = { "from", "at", "up", "angle", "hither", "resolution" };
    view_t *v = &r->st->scene.view;
    uint32_t line = r->tok_line;
    for (unsigned k = 0; k < 6; k++) {
        if (!rd_next_token(r))
            return false;
        if (!rd_tok_is(r, keys[k]))
            return rd_fail_tok(r, "v: expected ", keys[k]);
        real_t hither;
        uint32_t w = 0, h = 0;
        bool ok = true;
        switch (k) {
        case 0:
            r->far = true;
            ok = rd_pos3(r, "from", &v->from);
            r->far = false;
            break;
        case 1: ok = rd_pos3(r, "at", &v->at); break;
        case 2: ok = rd_vec3(r, "up", &v->up); break;
        case 3:
            ok = rd_real(r, "angle", &v->angle);
            /* valid angles only (the fixed tangent's argument must stay in
             * range); camera_init reports the others */
            v->tan_half = ok && v->angle > 0 && v->angle < r_from_int(180) ? r_tan_deg_wide(v->angle / 2) : 0;
            break;
        case 4: ok = rd_real(r, "hither", &hither); break; /* ignored by the model */
        default:
            ok = rd_count(r, "resolution", 1, RT_MAX_WIDTH, &w) &&
                 rd_count(r, "resolution", 1, RT_MAX_HEIGHT, &h);
            r->st->scene.width = (uint16_t)w;
            r->st->scene.height = (uint16_t)h;
            break;
        }
        if (!ok)
            return false;
    }
    r->have_view = true;
    if (r->measuring)
        return true;
    camera_t cam;
    const char *why = camera_init(&cam, v, r->st->scene.width, r->st->scene.height);
    if (why)
        return rd_fail(r, line, why);
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
    const char *save_p = r->p;
    uint32_t save_line = r->line;
    if (!rd_next_token(r))
        return false;
    if (r->tok != 0 && r->tok_line == save_line) {
        decimal_t d;
        if (!parse_decimal(r, &d))
            return rd_fail_tok(r, "l", ": expected a number or the end of the line");
        if (!r_from_decimal(d.neg, d.mant, d.exp10, &l->colour.x))
            return rd_out_of_range(r, "l");
        if (!rd_real(r, "l", &l->colour.y) || !rd_real(r, "l", &l->colour.z))
            return false;
    } else {
        r->p = save_p;
        r->line = save_line;
    }
    if (!r->measuring)
        sc->n_lights++;
    return true;
}

static bool read_material(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    material_t m;
    decimal_t d;
    if (!rd_vec3(r, "f", &m.colour) || !rd_real(r, "f", &m.kd) || !rd_real(r, "f", &m.ks) ||
        !rd_decimal(r, "f", &d))
        return false;
    if (!shine_from_decimal(d.neg, d.mant, d.exp10, &m.shine))
        return rd_fail(r, r->tok_line, "f: Phong exponent must be from 0 to 524287");
    if (!rd_real(r, "f", &m.t) || !rd_real(r, "f", &m.ior))
        return false;
    if (m.t > 0 && m.ior <= 0)
        return rd_fail(r, r->tok_line, "f: index of refraction must be positive");
    r->have_material = true;
    if (r->measuring)
        return true;
    /* reuse an identical material (SPD files repeat a few many times) */
    for (uint32_t i = 0; i < sc->n_materials; i++) {
        const material_t *o = &r->st->materials[i];
        if (o->colour.x == m.colour.x && o->colour.y == m.colour.y && o->colour.z == m.colour.z &&
            o->kd == m.kd && o->ks == m.ks && o->shine == m.shine && o->t == m.t &&
            o->ior == m.ior) {
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
    uint32_t line = r->tok_line;
    vec3_t c;
    real_t rad;
    if (!rd_need_material(r, "s") ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_spheres, RT_MAX_SPHERES, "spheres")) ||
        !rd_pos3(r, "s", &c) || !rd_pos(r, "s", &rad))
        return false;
    if (r->measuring)
        return true;
    const char *why = sphere_init(&r->st->spheres[sc->n_spheres], c, rad, r->material);
    if (why)
        return rd_fail(r, line, why);
    sc->n_spheres++;
    return true;
}

static bool read_cone(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    uint32_t line = r->tok_line;
    vec3_t base, apex;
    real_t rb, ra;
    if (!rd_need_material(r, "c") ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_cones, RT_MAX_CONES, "cones")) ||
        !rd_pos3(r, "c", &base) || !rd_pos(r, "c", &rb) || !rd_pos3(r, "c", &apex) ||
        !rd_pos(r, "c", &ra))
        return false;
    if (r->measuring)
        return true;
    const char *why = cone_init(&r->st->cones[sc->n_cones], base, rb, apex, ra, r->material);
    if (why)
        return rd_fail(r, line, why);
    sc->n_cones++;
    return true;
}

static bool read_polygon(reader_t *r, bool patch)
{
    scene_t *sc = &r->st->scene;
    const char *what = patch ? "pp" : "p";
    uint32_t line = r->tok_line, n;
    if (!rd_need_material(r, what) ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_polygons, RT_MAX_POLYGONS, "polygons and patches")))
        return false;
    if (!rd_count(r, what, 3, 0xFFFFFFFFu >> 8, &n))
        return false;
    if (n > RT_MAX_POLY_VERTS)
        return rd_over_capacity(r, "vertices in one polygon", "RT_MAX_POLY_VERTS", RT_MAX_POLY_VERTS);
    if (!r->measuring && n > RT_MAX_VERTICES - sc->n_vertices)
        return rd_over_capacity(r, "vertices", "RT_MAX_VERTICES", RT_MAX_VERTICES);
    if (!r->measuring && patch && n > RT_MAX_VERTICES - sc->n_normals)
        return rd_over_capacity(r, "patch normals", "RT_MAX_VERTICES", RT_MAX_VERTICES);
    for (uint32_t i = 0; i < n; i++) {
        vec3_t scratch;
        if (!rd_pos3(r, what, r->measuring ? &scratch : &r->st->vertices[sc->n_vertices + i]))
            return false;
        if (patch) {
            vec3_t nv;
            if (!rd_vec3(r, what, &nv))
                return false;
            if (r->measuring)
                continue;
            nv = v3_unit(nv);
            if (nv.x == 0 && nv.y == 0 && nv.z == 0)
                return rd_fail(r, r->tok_line, "pp: vertex normal is zero");
            r->st->normals[sc->n_normals + i] = nv;
        }
    }
    if (r->measuring)
        return true;
    if (polygon_is_flat(r->st->vertices, sc->n_vertices, (uint16_t)n)) {
        sc->n_flat_skipped++; /* invisible: nothing to intersect */
        return true;
    }
    const char *why = polygon_init(&r->st->polygons[sc->n_polygons], r->st->vertices,
                                   sc->n_vertices, (uint16_t)n,
                                   patch ? sc->n_normals : POLY_NO_NORMALS, r->material);
    if (why)
        return rd_fail(r, line, why);
    sc->n_vertices += n;
    if (patch)
        sc->n_normals += n;
    sc->n_polygons++;
    return true;
}

static bool read_entity(reader_t *r)
{
    if (rd_tok_is(r, "v")) {
        if (r->have_view)
            return rd_fail(r, r->tok_line, "v: a second viewpoint");
        return read_view(r);
    }
    if (rd_tok_is(r, "b"))
        return rd_vec3(r, "b", &r->st->scene.background);
    if (rd_tok_is(r, "#"))
        return true;
    if (r->n_blocks) {
        static const char *const not_in_blocks[] = { "l", "c", "p", "pp", "b" };
        for (unsigned i = 0; i < sizeof not_in_blocks / sizeof not_in_blocks[0]; i++) {
            if (rd_tok_is(r, not_in_blocks[i])) {
                rt_error_set(r->err, r->tok_line, "'");
                rt_error_append(r->err, not_in_blocks[i]);
                rt_error_append(r->err, "' is not allowed inside a transform or CSG block");
                return false;
            }
        }
    }
    static const char *const need_view[] = { "l", "f", "s", "c", "p", "pp" };
    for (unsigned i = 0; i < sizeof need_view / sizeof need_view[0]; i++) {
        if (rd_tok_is(r, need_view[i]) && !r->have_view) {
            rt_error_set(r->err, r->tok_line, "'");
            rt_error_append(r->err, need_view[i]);
            rt_error_append(r->err, "' before the 'v' viewpoint");
            return false;
        }
    }
    bool handled;
    bool ok = rd_solid_entity(r, &handled);
    if (handled)
        return ok;
    if (rd_tok_is(r, "l"))
        return read_light(r);
    if (rd_tok_is(r, "f"))
        return read_material(r);
    if (rd_tok_is(r, "s"))
        return read_sphere(r);
    if (rd_tok_is(r, "c"))
        return read_cone(r);
    if (rd_tok_is(r, "p"))
        return read_polygon(r, false);
    if (rd_tok_is(r, "pp"))
        return read_polygon(r, true);
    return rd_fail_tok(r, "", "unknown entity (expected v, b, l, f, c, s, p, pp, a solid or a block)");
}

/* The power of two that brings the geometry's largest coordinate below
 * 2^RT_SCENE_EXTENT_LOG2 and the camera's and lights' below
 * 2^RT_FAR_EXTENT_LOG2 (so distances stay inside the scalar's range), as
 * large as possible (so positions keep the most fraction bits). */
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
    if (k < RT_SCALE_LOG2_MIN || k > RT_SCALE_LOG2_MAX) {
        rt_error_set(r->err, r->max_line[f], r->max_what[f]);
        rt_error_append(r->err, k < RT_SCALE_LOG2_MIN ? ": scene too large for the fixed range (coordinates up to 2^"
                                                      : ": scene too small for the fixed range (coordinates only up to 2^");
        rt_error_append_int(r->err, r->max_exp2[f]);
        rt_error_append(r->err, k < RT_SCALE_LOG2_MIN ? ", at most 2^" : ", at least 2^");
        rt_error_append_int(r->err, extent[f] - (k < RT_SCALE_LOG2_MIN ? RT_SCALE_LOG2_MIN : RT_SCALE_LOG2_MAX));
        rt_error_append(r->err, ")");
        return false;
    }
    r->scale_log2 = k;
    return true;
}

static bool read_pass(reader_t *r)
{
    for (;;) {
        if (!rd_next_token(r))
            return false;
        if (r->tok == 0)
            return rd_blocks_closed(r);
        if (!read_entity(r))
            return false;
    }
}

static void reader_start(reader_t *r, const char *text, size_t len, scene_store_t *store, rt_error_t *err)
{
    *r = (reader_t){ 0 };
    r->p = text;
    r->end = text + len;
    r->line = 1;
    r->tok_line = 1;
    r->st = store;
    r->err = err;
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
        return rd_fail(&r, r.tok_line, "no 'v' viewpoint in the file");
    if (!choose_scale(&r))
        return false;
    int32_t scale = r.scale_log2;
    reader_start(&r, text, len, store, err);
    r.scale_log2 = scale;
    scene_t *sc = &store->scene;
    *sc = (scene_t){ 0 };
    sc->materials = store->materials;
    sc->lights = store->lights;
    sc->spheres = store->spheres;
    sc->cones = store->cones;
    sc->polygons = store->polygons;
    sc->vertices = store->vertices;
    sc->normals = store->normals;
    sc->xforms = store->xforms;
    sc->shapes = store->shapes;
    sc->csg_nodes = store->csg_nodes;
    sc->objects = store->objects;
    sc->scale_log2 = scale;
    if (!read_pass(&r))
        return false;
    uint32_t n = sc->n_lights;
    sc->light_intensity = n ? r_div(r_sqrt(r_from_int((int32_t)n)), r_from_int(2 * (int32_t)n)) : 0;
    const char *why = bvh_build(store);
    if (why)
        return rd_fail(&r, r.tok_line, why);
    return true;
}
