/*
 * nff_surfaces.c - planes, textures and the sky (layers: nff_lex.h):
 *
 *   plane px py pz nx ny nz               through p, facing n, infinite
 *   checker size r g b r g b [axes]       axes: x y z xy xz yz or xyz (default)
 *   marble size r g b r g b amount
 *   sky hr hg hb zr zg zb ux uy uz exponent
 *
 * A texture line gives the current material (the last f) a texture: the
 * primitives after it take the textured material. Plain NFF never uses
 * these words.
 */
#include "nff_surfaces.h"

#include "geometry/geometry.h"

bool rd_plane(reader_t *r)
{
    scene_t *sc = &r->st->scene;
    uint32_t line = r->lx.tok_line;
    vec3_t p, n;
    bool zero;
    if (!rd_need_material(r, "plane") ||
        (!r->measuring && !CHECK_ROOM(r, sc->n_planes, RT_MAX_PLANES, "planes")) || !rd_pos3(r, "plane", &p) ||
        !lex_direction(&r->lx, "plane", &n, &zero))
        return false;
    if (zero)
        return lex_fail(&r->lx, line, "plane normal is zero");
    if (r->measuring)
        return true;
    const char *why = plane_init(&r->st->planes[sc->n_planes], p, n, r->material);
    if (why)
        return lex_fail(&r->lx, line, why);
    sc->n_planes++;
    return true;
}

/* A texture's size is at least 2^this in the scene's scale: 1 / size
 * then fits the fixed range. */
#define TEXTURE_SIZE_MIN_LOG2 (-10)

/* size r g b r g b: the part both textures share. */
static bool texture_common(reader_t *r, const char *what, texture_t *tx)
{
    real_t size;
    decimal_t d;
    if (!rd_need_material(r, what) || !rd_pos_decimal(r, what, &d, &size) || !lex_vec3(&r->lx, what, &tx->a) ||
        !lex_vec3(&r->lx, what, &tx->b))
        return false;
    if (r->measuring)
        return true;
    /* 1 / size within range in every build (the fixed one needs it),
     * decided on the value, then taken from the value itself: a size
     * rounded to the position grid would make every tile a little too
     * wide, an error that grows with the distance from the origin */
    if (d.neg || decimal_cmp(&d, 1, TEXTURE_SIZE_MIN_LOG2 - r->scale_log2) < 0) {
        rt_error_set(r->lx.err, r->lx.tok_line, what);
        rt_error_append(r->lx.err, ": size must be positive, at least 2^-10 in the scene's scale (rt --stats: scene_scale_log2)");
        return false;
    }
    tx->inv_size = decimal_recip_scaled(&d, r->scale_log2);
    return true;
}

/* The current material with texture tx: a new material, current from now. */
static bool add_textured(reader_t *r, const texture_t *tx)
{
    scene_t *sc = &r->st->scene;
    if (r->measuring)
        return true;
    if (!CHECK_ROOM(r, sc->n_textures, RT_MAX_TEXTURES, "textures") ||
        !CHECK_ROOM(r, sc->n_materials, RT_MAX_MATERIALS, "materials"))
        return false;
    r->st->textures[sc->n_textures] = *tx;
    material_t m = r->st->materials[r->material];
    m.texture = (uint16_t)sc->n_textures++;
    r->st->materials[sc->n_materials] = m;
    r->material = (uint16_t)sc->n_materials++;
    return true;
}

bool rd_checker(reader_t *r)
{
    texture_t tx = { .kind = TEXTURE_CHECKER, .axes = 7 };
    if (!texture_common(r, "checker", &tx))
        return false;
    bool more;
    if (!lex_next_on_line(&r->lx, &more))
        return false;
    if (more) {
        static const char *const names[] = { "x", "y", "xy", "z", "xz", "yz", "xyz" };
        unsigned i = 0;
        while (i < 7 && !lex_is(&r->lx, names[i]))
            i++;
        if (i == 7)
            return lex_fail_tok(&r->lx, "checker", ": axes must be x, y, z, xy, xz, yz or xyz");
        tx.axes = (uint8_t)(i + 1);
    }
    return add_textured(r, &tx);
}

bool rd_marble(reader_t *r)
{
    texture_t tx = { .kind = TEXTURE_MARBLE };
    if (!texture_common(r, "marble", &tx) || !lex_real(&r->lx, "marble", &tx.amount))
        return false;
    if (tx.amount < 0 || tx.amount > r_from_int(16))
        return lex_fail(&r->lx, r->lx.tok_line, "marble: amount must be from 0 to 16");
    return add_textured(r, &tx);
}

bool rd_sky(reader_t *r)
{
    sky_t *sky = &r->st->scene.sky;
    uint32_t line = r->lx.tok_line;
    if (sky->on)
        return lex_fail(&r->lx, line, "sky: a second sky");
    vec3_t up;
    bool zero;
    if (!lex_vec3(&r->lx, "sky", &sky->horizon) || !lex_vec3(&r->lx, "sky", &sky->zenith) ||
        !lex_direction(&r->lx, "sky", &up, &zero) ||
        !lex_shine(&r->lx, "sky: exponent must be from 2^-12 to 524287", true, &sky->exponent))
        return false;
    if (zero)
        return lex_fail(&r->lx, line, "sky: up direction is zero");
    sky->up = v3_unit(up);
    sky->up_axis = v3_axis_of(sky->up);
    sky->on = !r->measuring;
    return true;
}
