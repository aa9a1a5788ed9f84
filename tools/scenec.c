/*
 * tools/scenec.c - the scene compiler: NFF in, C out, for firmware that carries
 * its scene in flash.
 *
 *   rt-scenec SCENE.nff -o scene_data.c --header scene_data.h [--text]
 *   rt-scenec --help | --version
 *
 * It reads the scene with the same reader and capacities as the firmware's
 * core (so over-capacity scenes fail here, with the same message), and
 * writes the tables already converted to the core's numeric format, with
 * every per-primitive constant precomputed. The header says what the
 * scene contains, so the firmware can be built for exactly that scene.
 * --text instead embeds the NFF text, for builds that read it at boot.
 *
 * The format is the one this program is built for, as the core: fixed
 * point by default, float with -DRT_BACKEND_FLOAT=1, double with
 * -DRT_BACKEND_DOUBLE=1. Floating-point values are written as exact
 * hexadecimal constants, so the tables hold bit for bit what the reader
 * computed here; the generated file refuses to compile for another
 * format. Build it with the same -D flags (capacities, backend) as the
 * firmware's core and with -ffp-contract=off (GCC's default under
 * -std=c11), so that this host computes the reader's and the BVH
 * builder's values as any other host does.
 */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/bvh.h"
#include "host_io.h" /* beside this file: found without -I */
#include "reader/nff.h"
#include "rt_version.h"

#if defined(RT_TOLERANCES_FIXED) && RT_TOLERANCES_FIXED
#define SCENEC_TOLERANCES_FIXED 1
#else
#define SCENEC_TOLERANCES_FIXED 0
#endif

static scene_store_t store;

/* ---- values: one emitter per field type, in the core's format -------- */

typedef void emit_fn(FILE *f, const void *value);

static void emit_i32(FILE *f, const void *v) { fprintf(f, "%" PRId32, *(const int32_t *)v); }
static void emit_u32(FILE *f, const void *v) { fprintf(f, "%" PRIu32 "u", *(const uint32_t *)v); }
static void emit_u16(FILE *f, const void *v) { fprintf(f, "%u", (unsigned)*(const uint16_t *)v); }
static void emit_u8(FILE *f, const void *v) { fprintf(f, "%u", (unsigned)*(const uint8_t *)v); }
static void emit_i64(FILE *f, const void *v) { fprintf(f, "INT64_C(%" PRId64 ")", *(const int64_t *)v); }

/* A float or double exactly: %a for a finite value (with -0 as -0x0p+0),
 * the compiler's constants for an infinity or a NaN (its sign, and its
 * payload bits in the significand, kept). suffix is "f" for a float. */
static void emit_floating(FILE *f, double v, bool neg, uint64_t payload, bool quiet, const char *suffix)
{
    if (v - v == 0) /* finite */
        fprintf(f, "%a%s", v, suffix);
    else if (v == v) /* an infinity */
        fprintf(f, "%s__builtin_inf%s()", neg ? "-" : "", suffix);
    else
        fprintf(f, "%s__builtin_nan%s%s(\"0x%" PRIx64 "\")", neg ? "-" : "", quiet ? "" : "s", suffix, payload);
}
static void emit_float(FILE *f, const void *v)
{
    uint32_t u;
    memcpy(&u, v, sizeof u);
    emit_floating(f, *(const float *)v, u >> 31, u & 0x3FFFFFu, (u >> 22) & 1, "f");
}
static void emit_double(FILE *f, const void *v)
{
    uint64_t u;
    memcpy(&u, v, sizeof u);
    emit_floating(f, *(const double *)v, u >> 63, u & 0x7FFFFFFFFFFFFu, (u >> 51) & 1, "");
}

static void emit_prim_ref_t(FILE *f, const void *v) { fprintf(f, "0x%08" PRIx32 "u", *(const prim_ref_t *)v); }
static void emit_vec3_t(FILE *f, const void *v);
static void emit_view_t(FILE *f, const void *v);
static void emit_sky_t(FILE *f, const void *v);
static void emit_mat3_t(FILE *f, const void *v);

/* The emitter of a field type: real_t, real_wide_t and shine_t are
 * int32_t, int64_t and uint32_t in the fixed build, all float (double)
 * in the float (double) build; colour_t is vec3_t. */
#define EMITTER(type) \
    _Generic((type){ 0 }, int32_t: emit_i32, uint32_t: emit_u32, uint16_t: emit_u16, uint8_t: emit_u8, \
             int64_t: emit_i64, float: emit_float, double: emit_double, vec3_t: emit_vec3_t, view_t: emit_view_t, \
             sky_t: emit_sky_t, mat3_t: emit_mat3_t)

static void emit_vec3_t(FILE *f, const void *v)
{
    const vec3_t *p = v;
    emit_fn *fn = EMITTER(real_t);
    fprintf(f, "{ ");
    fn(f, &p->x);
    fprintf(f, ", ");
    fn(f, &p->y);
    fprintf(f, ", ");
    fn(f, &p->z);
    fprintf(f, " }");
}

/* n values of an array field with dimensions dims ("" for a scalar,
 * "[3][3]" for a matrix), as nested braces. */
static void emit_array(FILE *f, const char *dims, const unsigned char *p, size_t n, size_t elem, emit_fn *fn)
{
    if (!*dims) {
        fn(f, p);
        return;
    }
    char *rest;
    size_t groups = strtoul(dims + 1, &rest, 10);
    fprintf(f, "{ ");
    for (size_t i = 0; i < groups; i++) {
        emit_array(f, rest + 1, p + i * (n / groups) * elem, n / groups, elem, fn);
        fprintf(f, i + 1 < groups ? ", " : " }");
    }
}

static void emit_field(FILE *f, const char *name, const char *dims, const void *p, size_t size, size_t elem,
                       emit_fn *fn)
{
    fprintf(f, ".%s = ", name);
    emit_array(f, dims, p, size / elem, elem, fn);
    fprintf(f, ", ");
}

/* A struct, field by field from its FIELDS_<type> list (scene.h and the
 * kind headers), so the tables cannot miss a field the tracer reads. */
#define EMIT_FIELD(type, name, dims) emit_field(f, #name, #dims, &e->name, sizeof e->name, sizeof(type), EMITTER(type));
#define DEFINE_EMIT_STRUCT(type) \
    static void emit_##type(FILE *f, const void *v) \
    { \
        const type *e = v; \
        fprintf(f, "{ "); \
        FIELDS_##type(EMIT_FIELD) fprintf(f, "}"); \
    }
#define DEFINE_EMIT_PRIM(type, table, cap, KIND, name, use) DEFINE_EMIT_STRUCT(type)
/* the element types of scene.h's tables, the transforms' matrices, and the view */
DEFINE_EMIT_STRUCT(material_t)
DEFINE_EMIT_STRUCT(light_t)
DEFINE_EMIT_STRUCT(mat3_t)
DEFINE_EMIT_STRUCT(xform_t)
DEFINE_EMIT_STRUCT(shape_t)
DEFINE_EMIT_STRUCT(csg_node_t)
DEFINE_EMIT_STRUCT(bvh_node_t)
DEFINE_EMIT_STRUCT(view_t)
DEFINE_EMIT_STRUCT(sky_t)
DEFINE_EMIT_STRUCT(texture_t)
RT_PRIM_KINDS(DEFINE_EMIT_PRIM)

/* ---- tables and the scene ------------------------------------------------ */

static void emit_table(FILE *f, const char *type, const char *name, const void *rows, uint32_t n, size_t size,
                       emit_fn *fn)
{
    if (!n)
        return;
    fprintf(f, "static const %s %s[%" PRIu32 "] TABLE = {\n", type, name, n);
    for (uint32_t i = 0; i < n; i++) {
        fprintf(f, "    ");
        fn(f, (const unsigned char *)rows + i * size);
        fprintf(f, ",\n");
    }
    fprintf(f, "};\n\n");
}

static void emit_table_ref(FILE *f, const char *name, uint32_t n)
{
    fprintf(f, "    .%s = %s, .n_%s = %" PRIu32 ",\n", name, n ? name : "0", name, n);
}

static void emit_tables(FILE *f, const scene_t *sc)
{
    fprintf(f, "#define TABLE __attribute__((section(\".scene.tables\")))\n\n");
#define EMIT_TABLE(type, table, cap) emit_table(f, #type, #table, sc->table, sc->n_##table, sizeof(type), emit_##type);
#define EMIT_PRIM_TABLE(type, table, cap, KIND, name, use) EMIT_TABLE(type, table, cap)
    RT_PRIM_KINDS(EMIT_PRIM_TABLE)
    RT_SCENE_TABLES(EMIT_TABLE)

    const scene_t *e = sc;
    fprintf(f, "const scene_t rt_scene TABLE = {\n    ");
    FIELDS_scene_t(EMIT_FIELD)
    fprintf(f, "\n");
#define EMIT_TABLE_REF(type, table, cap) emit_table_ref(f, #table, sc->n_##table);
#define EMIT_PRIM_TABLE_REF(type, table, cap, KIND, name, use) EMIT_TABLE_REF(type, table, cap)
    RT_PRIM_KINDS(EMIT_PRIM_TABLE_REF)
    RT_SCENE_TABLES(EMIT_TABLE_REF)
    fprintf(f, "};\n");
}

static void emit_text(FILE *f, const char *text, size_t len)
{
    fprintf(f, "#include <stddef.h>\n\nconst char rt_scene_text[] = {");
    for (size_t i = 0; i < len; i++)
        fprintf(f, "%s%d,", i % 20 ? " " : "\n    ", (unsigned char)text[i]);
    fprintf(f, "\n};\nconst size_t rt_scene_text_len = %zu;\n", len);
}

static void emit_upper(FILE *f, const char *name)
{
    for (const char *c = name; *c; c++)
        fputc(toupper((unsigned char)*c), f);
}

/* "SCENE_N_" and the table's name in capitals. */
static void emit_count(FILE *f, const char *table, uint32_t n)
{
    fprintf(f, "#define SCENE_N_");
    emit_upper(f, table);
    fprintf(f, " %" PRIu32 "\n", n);
}

/* What the scene uses, for building firmware for exactly that scene. */
static void emit_header(FILE *f, const scene_t *sc, const char *src)
{
    bool refraction = false, reflection = false, specular = false, patches = false, concave = false;
    for (uint32_t i = 0; i < sc->n_materials; i++) {
        refraction |= sc->materials[i].t > 0;
        /* SPD rule 8 traces reflections off transmitting surfaces too */
        reflection |= sc->materials[i].ks > 0 || sc->materials[i].t > 0;
        specular |= sc->materials[i].ks > 0 && sc->n_lights > 0;
    }
    bool checker = false, marble = false;
    for (uint32_t i = 0; i < sc->n_textures; i++) {
        checker |= sc->textures[i].kind == TEXTURE_CHECKER;
        marble |= sc->textures[i].kind == TEXTURE_MARBLE;
    }
    for (uint32_t i = 0; i < sc->n_polygons; i++) {
        patches |= sc->polygons[i].normals != POLY_NO_NORMALS;
        concave |= sc->polygons[i].normals == POLY_NO_NORMALS && !sc->polygons[i].convex;
    }
    fprintf(f, "/* Generated by rt-scenec from %s: do not edit. */\n", src);
    fprintf(f, "#ifndef SCENE_DATA_H\n#define SCENE_DATA_H\n\n");
    fprintf(f, "#define SCENE_WIDTH %u\n#define SCENE_HEIGHT %u\n", (unsigned)sc->width, (unsigned)sc->height);
#define EMIT_COUNT(type, table, cap) emit_count(f, #table, sc->n_##table);
#define EMIT_PRIM_COUNT(type, table, cap, KIND, name, use) EMIT_COUNT(type, table, cap)
    RT_PRIM_KINDS(EMIT_PRIM_COUNT)
    RT_SCENE_TABLES(EMIT_COUNT)
    bvh_stats_t bs;
    bvh_tree_stats(sc, &bs);
    fprintf(f, "\n/* BVH: %" PRIu32 " nodes, %" PRIu32 " leaves, depth %" PRIu32 ", largest leaf %" PRIu32
               ";\n * SAH estimate per ray: %.2f node visits, %.2f primitive tests */\n\n",
            bs.nodes, bs.leaves, bs.max_depth, bs.max_leaf_size, bs.sah_nodes_milli / 1000.0,
            bs.sah_tests_milli / 1000.0);
    /* RT_USE_<X> (rt_config.h) is set from SCENE_USES_<X> */
    fprintf(f, "/* What the scene uses; with PRUNE=1 the firmware is built with these\n"
               " * as its RT_USE_* switches (include/rt_config.h). */\n");
    /* a kind's switch is RT_USE_<its table's name> (prim_kinds.h) */
    struct {
        const char *name;
        bool used;
    } uses[] = {
#define USE_OF_KIND(type, table, cap, KIND, name, use) { #table, sc->n_##table > 0 },
        RT_PRIM_KINDS(USE_OF_KIND)
        { "patches", patches },
        { "concave", concave },
        { "bvh", sc->n_bvh_nodes > 1 },   /* scene_hit.c: a tree, or one leaf searched flat */
        { "flat", sc->n_bvh_nodes <= 1 },
        { "checker", checker },
        { "marble", marble },
        { "sky", sc->sky.on != 0 },
        { "shadows", sc->n_lights > 0 },
        { "specular", specular },
        { "reflection", reflection },
        { "refraction", refraction },
    };
    size_t n_uses = sizeof uses / sizeof uses[0];
    for (size_t i = 0; i < n_uses; i++) {
        fprintf(f, "#define SCENE_USES_");
        emit_upper(f, uses[i].name);
        fprintf(f, " %d\n", uses[i].used);
    }
    /* defined(): a user's file may include this header without SCENE_PRUNE, under -Wundef */
    fprintf(f, "\n#if defined(SCENE_PRUNE) && SCENE_PRUNE\n");
    for (size_t i = 0; i < n_uses; i++) {
        fprintf(f, "#define RT_USE_");
        emit_upper(f, uses[i].name);
        fprintf(f, " SCENE_USES_");
        emit_upper(f, uses[i].name);
        fprintf(f, "\n");
    }
    fprintf(f, "#endif\n\n#endif\n");
}

/* The C for one scene: the tables (or, with text_mode, the NFF text) to
 * out and, when hdr is not NULL, the header saying what the scene uses.
 * src names the input in the generated comments. Returns 0, or -1 when a
 * write failed (the caller reports it). The fuzz harness calls it too. */
static int scenec_emit(FILE *out, FILE *hdr, const char *src, const scene_t *sc, const char *text, size_t len,
                       bool text_mode)
{
    fprintf(out, "/* Generated by rt-scenec from %s: do not edit. */\n", src);
    if (text_mode) {
        emit_text(out, text, len);
    } else {
        fprintf(out, "#include <stdint.h>\n\n/* the core's internal headers: -I path/to/rt/src, or installed\n"
                     " * -I PREFIX/include/rt/internal (rt_add_scene adds it) */\n"
                     "#include \"geometry/scene.h\"\n\n");
#if RT_BACKEND_FIXED
        fprintf(out, "#if !RT_BACKEND_FIXED || FX_FRAC_BITS != %d\n", FX_FRAC_BITS);
        fprintf(out, "#error \"these tables are for the fixed build with FX_FRAC_BITS = %d\"\n#endif\n\n",
                FX_FRAC_BITS);
#elif RT_BACKEND_FLOAT
        fprintf(out, "#if !RT_BACKEND_FLOAT\n#error \"these tables are for the float build\"\n#endif\n\n");
#else /* the fixed build's tolerances pad the boxes differently */
        fprintf(out, "#if !RT_BACKEND_DOUBLE || RT_TOLERANCES_FIXED != %d\n", SCENEC_TOLERANCES_FIXED);
        fprintf(out, "#error \"these tables are for the double build with RT_TOLERANCES_FIXED = %d\"\n#endif\n\n",
                SCENEC_TOLERANCES_FIXED);
#endif
        emit_tables(out, sc);
    }
    if (hdr)
        emit_header(hdr, sc, src);
    return ferror(out) || (hdr && ferror(hdr)) ? -1 : 0;
}

#ifndef SCENEC_NO_MAIN

/* cppcheck (2.10) takes this for a local shadowing itself under the
 * SCENEC_NO_MAIN configuration; it is the one declaration. */
// cppcheck-suppress shadowVariable
static const char scenec_usage[] =
    "usage: rt-scenec SCENE.nff -o OUT.c [--header OUT.h] [--text]\n"
    "\n"
    "Compiles an NFF scene into C tables for firmware that carries its scene in\n"
    "flash, with the firmware's capacities and numeric format (this build: " R_BACKEND_NAME ").\n"
    "  -o, --output FILE   the C file to write\n"
    "  --header FILE       also write a header saying what the scene uses\n"
    "  --text              embed the NFF text instead (read at boot)\n"
    "  -h, --help          this text; --version: the version\n"
    "\n"
    "exit status: 0 success, 1 output failure, 2 bad input or usage\n";

#define SCENEC_HELP "rt-scenec --help"

enum { OPT_HEADER = 256, OPT_TEXT, OPT_VERSION };

static FILE *open_out(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        fprintf(stderr, "rt-scenec: %s: cannot open for writing: %s\n", path, strerror(errno));
    return f;
}

int main(int argc, char **argv)
{
    static const struct option options[] = {
        { "output", required_argument, NULL, 'o' },
        { "header", required_argument, NULL, OPT_HEADER },
        { "text", no_argument, NULL, OPT_TEXT },
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, OPT_VERSION },
        { NULL, 0, NULL, 0 },
    };
    static const host_option_need_t needs[] = { { 'o', "a file name" }, { OPT_HEADER, "a file name" }, { 0, NULL } };
    const char *in = NULL, *out = NULL, *hdr = NULL;
    bool text_mode = false;
    opterr = 0;
    int c;
    while ((c = getopt_long(argc, argv, ":ho:", options, NULL)) != -1) {
        switch (c) {
        case 'o':
            out = optarg;
            break;
        case OPT_HEADER:
            hdr = optarg;
            break;
        case OPT_TEXT:
            text_mode = true;
            break;
        case 'h':
            fputs(scenec_usage, stdout);
            return 0;
        case OPT_VERSION:
            printf("rt-scenec %s\n", RT_VERSION_STRING);
            return 0;
        default:
            return host_option_error("rt-scenec", SCENEC_HELP, c, argv, needs);
        }
    }
    if (argc - optind > 1)
        return host_usage_error("rt-scenec", SCENEC_HELP, "unexpected argument '%s'", argv[optind + 1]);
    in = optind < argc ? argv[optind] : NULL;
    if (!in)
        return host_usage_error("rt-scenec", SCENEC_HELP, "%s", "no scene file given");
    if (!out)
        return host_usage_error("rt-scenec", SCENEC_HELP, "%s", "no output file given (-o OUT.c)");
    size_t len;
    char *text = host_read_file(in, &len);
    if (!text)
        return EXIT_BAD_INPUT;
    rt_error_t err;
    if (!nff_read(text, len, &store, &err)) {
        host_error_at(in, (unsigned)err.line, err.msg);
        free(text);
        return EXIT_BAD_INPUT;
    }
    FILE *f = open_out(out);
    FILE *h = f && hdr ? open_out(hdr) : NULL;
    int rc = f && (h || !hdr) ? scenec_emit(f, h, in, &store.scene, text, len, text_mode) : -1;
    free(text);
    if (f && fclose(f) != 0)
        rc = -1;
    if (h && fclose(h) != 0)
        rc = -1;
    if (rc != 0 && f && (h || !hdr))
        fprintf(stderr, "rt-scenec: cannot write %s%s%s: %s\n", out, hdr ? " or " : "", hdr ? hdr : "",
                strerror(errno ? errno : EIO));
    return rc != 0 ? 1 : 0;
}

#endif /* SCENEC_NO_MAIN */
