/*
 * scenec.c - the scene compiler: NFF in, C out, for firmware that carries
 * its scene in flash.
 *
 *   rt-scenec SCENE.nff -o scene_data.c --header scene_data.h [--text]
 *
 * It reads the scene with the same reader and capacities as the firmware's
 * core (so over-capacity scenes fail here, with the same message), and
 * writes the tables already converted to the fixed format, with every
 * per-primitive constant precomputed. The header says what the scene
 * contains, so the firmware can be built for exactly that scene.
 * --text instead embeds the NFF text, for builds that read it at boot.
 */
#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "nff.h"

#if !RT_BACKEND_FIXED
#error "the scene compiler emits fixed-point tables: build it for the fixed backend"
#endif

static scene_store_t store;

/* ---- values: one emitter per field type, in the fixed format --------- */

typedef void emit_fn(FILE *f, const void *value);

static void emit_i32(FILE *f, const void *v) { fprintf(f, "%" PRId32, *(const int32_t *)v); }
static void emit_u32(FILE *f, const void *v) { fprintf(f, "%" PRIu32 "u", *(const uint32_t *)v); }
static void emit_u16(FILE *f, const void *v) { fprintf(f, "%u", (unsigned)*(const uint16_t *)v); }
static void emit_u8(FILE *f, const void *v) { fprintf(f, "%u", (unsigned)*(const uint8_t *)v); }
static void emit_i64(FILE *f, const void *v) { fprintf(f, "INT64_C(%" PRId64 ")", *(const int64_t *)v); }
static void emit_vec3_t(FILE *f, const void *v)
{
    const vec3_t *p = v;
    fprintf(f, "{ %" PRId32 ", %" PRId32 ", %" PRId32 " }", p->x, p->y, p->z);
}
static void emit_prim_ref_t(FILE *f, const void *v) { fprintf(f, "0x%08" PRIx32 "u", *(const prim_ref_t *)v); }
static void emit_view_t(FILE *f, const void *v);

/* The emitter of a field type (real_t is int32_t, shine_t uint32_t and
 * colour_t vec3_t in the fixed build). */
#define EMITTER(type) \
    _Generic((type){ 0 }, int32_t: emit_i32, uint32_t: emit_u32, uint16_t: emit_u16, uint8_t: emit_u8, \
             int64_t: emit_i64, vec3_t: emit_vec3_t, view_t: emit_view_t)

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
/* the element types of scene.h's tables, and the view */
DEFINE_EMIT_STRUCT(material_t)
DEFINE_EMIT_STRUCT(light_t)
DEFINE_EMIT_STRUCT(xform_t)
DEFINE_EMIT_STRUCT(shape_t)
DEFINE_EMIT_STRUCT(csg_node_t)
DEFINE_EMIT_STRUCT(bvh_node_t)
DEFINE_EMIT_STRUCT(view_t)
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

/* "SCENE_N_" and the table's name in capitals. */
static void emit_count(FILE *f, const char *table, uint32_t n)
{
    fprintf(f, "#define SCENE_N_");
    for (const char *c = table; *c; c++)
        fputc(toupper((unsigned char)*c), f);
    fprintf(f, " %" PRIu32 "\n", n);
}

/* What the scene uses, for building firmware for exactly that scene. */
static void emit_header(FILE *f, const scene_t *sc, const char *src)
{
    bool refraction = false, reflection = false, specular = false, patches = false;
    for (uint32_t i = 0; i < sc->n_materials; i++) {
        refraction |= sc->materials[i].t > 0;
        /* SPD rule 8 traces reflections off transmitting surfaces too */
        reflection |= sc->materials[i].ks > 0 || sc->materials[i].t > 0;
        specular |= sc->materials[i].ks > 0 && sc->n_lights > 0;
    }
    for (uint32_t i = 0; i < sc->n_polygons; i++)
        patches |= sc->polygons[i].normals != POLY_NO_NORMALS;
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
               " * as its RT_USE_* switches (src/rt_config.h). */\n");
    const char *use_prefix = "RT_USE_";
    size_t skip = strlen(use_prefix);
    struct {
        const char *name;
        bool used;
    } uses[] = {
#define USE_OF_KIND(type, table, cap, KIND, name, use) { #use, sc->n_##table > 0 },
        RT_PRIM_KINDS(USE_OF_KIND)
        { "RT_USE_PATCHES", patches },
        { "RT_USE_SHADOWS", sc->n_lights > 0 },
        { "RT_USE_SPECULAR", specular },
        { "RT_USE_REFLECTION", reflection },
        { "RT_USE_REFRACTION", refraction },
    };
    size_t n_uses = sizeof uses / sizeof uses[0];
    for (size_t i = 0; i < n_uses; i++)
        fprintf(f, "#define SCENE_USES_%s %d\n", uses[i].name + skip, uses[i].used);
    fprintf(f, "\n#if SCENE_PRUNE\n");
    for (size_t i = 0; i < n_uses; i++)
        fprintf(f, "#define %s SCENE_USES_%s\n", uses[i].name, uses[i].name + skip);
    fprintf(f, "#endif\n\n#endif\n");
}

static FILE *open_out(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        fprintf(stderr, "rt-scenec: cannot open '%s' for writing: %s\n", path, strerror(errno));
    return f;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *hdr = NULL;
    bool text_mode = false;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--header") && i + 1 < argc)
            hdr = argv[++i];
        else if (!strcmp(argv[i], "--text"))
            text_mode = true;
        else if (argv[i][0] != '-' && !in)
            in = argv[i];
        else {
            fprintf(stderr, "rt-scenec: unexpected argument '%s'\n"
                            "usage: rt-scenec SCENE.nff -o OUT.c [--header OUT.h] [--text]\n", argv[i]);
            return 2;
        }
    }
    if (!in || !out) {
        fprintf(stderr, "usage: rt-scenec SCENE.nff -o OUT.c [--header OUT.h] [--text]\n");
        return 2;
    }
    FILE *fin = fopen(in, "rb");
    if (!fin) {
        fprintf(stderr, "%s: cannot open: %s\n", in, strerror(errno));
        return 2;
    }
    size_t cap = 1 << 16, len = 0;
    char *text = malloc(cap);
    size_t got;
    while (text && (got = fread(text + len, 1, cap - len, fin)) > 0) {
        len += got;
        if (len == cap) {
            char *grown = realloc(text, cap *= 2);
            if (!grown)
                free(text);
            text = grown;
        }
    }
    int read_failed = ferror(fin);
    fclose(fin);
    if (!text || read_failed) {
        fprintf(stderr, "%s: cannot read\n", in);
        return 2;
    }
    rt_error_t err;
    if (!nff_read(text, len, &store, &err)) {
        if (err.line)
            fprintf(stderr, "%s:%u: %s\n", in, (unsigned)err.line, err.msg);
        else
            fprintf(stderr, "%s: %s\n", in, err.msg);
        free(text);
        return 2;
    }
    FILE *f = open_out(out);
    if (!f)
        return 1;
    fprintf(f, "/* Generated by rt-scenec from %s: do not edit. */\n", in);
    if (text_mode) {
        emit_text(f, text, len);
    } else {
        fprintf(f, "#include <stdint.h>\n\n#include \"scene.h\"\n\n");
        fprintf(f, "#if !RT_BACKEND_FIXED || FX_FRAC_BITS != %d\n", FX_FRAC_BITS);
        fprintf(f, "#error \"these tables are for the fixed build with FX_FRAC_BITS = %d\"\n#endif\n\n",
                FX_FRAC_BITS);
        emit_tables(f, &store.scene);
    }
    free(text);
    if (fclose(f) != 0)
        return 1;
    if (hdr) {
        FILE *h = open_out(hdr);
        if (!h)
            return 1;
        emit_header(h, &store.scene, in);
        if (fclose(h) != 0)
            return 1;
    }
    return 0;
}
