/*
 * scenec.c - the scene compiler: NFF in, C out, for firmware that carries
 * its scene in flash.
 *
 *   rt-scenec SCENE.nff -o scene_data.c --header scene_data.h [--text]
 *   rt-scenec --help | --version
 *
 * It reads the scene with the same reader and capacities as the firmware's
 * core (so over-capacity scenes fail here, with the same message), and
 * writes the tables already converted to the fixed format, with every
 * per-primitive constant precomputed. The header says what the scene
 * contains, so the firmware can be built for exactly that scene.
 * --text instead embeds the NFF text, for builds that read it at boot.
 */
#include <errno.h>
#include <getopt.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "host_io.h" /* beside this file: found without -I */
#include "nff.h"
#include "version.h"

#if !RT_BACKEND_FIXED
#error "the scene compiler emits fixed-point tables: build it for the fixed backend"
#endif

static scene_store_t store;

static void emit_vec(FILE *f, vec3_t v) { fprintf(f, "{ %" PRId32 ", %" PRId32 ", %" PRId32 " }", v.x, v.y, v.z); }

static void emit_mat(FILE *f, const real_t m[3][3])
{
    fprintf(f, "{ ");
    for (int i = 0; i < 3; i++)
        fprintf(f, "{ %" PRId32 ", %" PRId32 ", %" PRId32 " }%s", m[i][0], m[i][1], m[i][2], i < 2 ? ", " : " }");
}

/* A table of vectors (vertices, patch normals); nothing for an empty one. */
static void emit_vec_table(FILE *f, const char *name, const vec3_t *v, uint32_t n)
{
    if (!n)
        return;
    fprintf(f, "static const vec3_t %s[%" PRIu32 "] TABLE = {\n", name, n);
    for (uint32_t i = 0; i < n; i++) {
        fprintf(f, "    ");
        emit_vec(f, v[i]);
        fprintf(f, ",\n");
    }
    fprintf(f, "};\n\n");
}

static void emit_wide(FILE *f, real_wide_t w) { fprintf(f, "INT64_C(%" PRId64 ")", w); }

static void emit_tables(FILE *f, const scene_t *sc)
{
    fprintf(f, "#define TABLE __attribute__((section(\".scene.tables\")))\n\n");
    if (sc->n_materials) {
        fprintf(f, "static const material_t materials[%" PRIu32 "] TABLE = {\n", sc->n_materials);
        for (uint32_t i = 0; i < sc->n_materials; i++) {
            const material_t *m = &sc->materials[i];
            fprintf(f, "    { .colour = ");
            emit_vec(f, m->colour);
            fprintf(f, ", .kd = %" PRId32 ", .ks = %" PRId32 ", .t = %" PRId32 ", .ior = %" PRId32
                       ", .shine = %" PRIu32 "u },\n",
                    m->kd, m->ks, m->t, m->ior, m->shine);
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_lights) {
        fprintf(f, "static const light_t lights[%" PRIu32 "] TABLE = {\n", sc->n_lights);
        for (uint32_t i = 0; i < sc->n_lights; i++) {
            fprintf(f, "    { .pos = ");
            emit_vec(f, sc->lights[i].pos);
            fprintf(f, ", .colour = ");
            emit_vec(f, sc->lights[i].colour);
            fprintf(f, " },\n");
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_spheres) {
        fprintf(f, "static const sphere_t spheres[%" PRIu32 "] TABLE = {\n", sc->n_spheres);
        for (uint32_t i = 0; i < sc->n_spheres; i++) {
            const sphere_t *s = &sc->spheres[i];
            fprintf(f, "    { .centre = ");
            emit_vec(f, s->centre);
            fprintf(f, ", .radius = %" PRId32 ", .radius2 = ", s->radius);
            emit_wide(f, s->radius2);
            fprintf(f, ", .material = %u },\n", (unsigned)s->material);
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_cones) {
        fprintf(f, "static const cone_t cones[%" PRIu32 "] TABLE = {\n", sc->n_cones);
        for (uint32_t i = 0; i < sc->n_cones; i++) {
            const cone_t *c = &sc->cones[i];
            fprintf(f, "    { .base = ");
            emit_vec(f, c->base);
            fprintf(f, ", .axis = ");
            emit_vec(f, c->axis);
            fprintf(f, ", .height = %" PRId32 ", .r0 = %" PRId32 ", .slope = %" PRId32 ",\n      .bound_centre = ",
                    c->height, c->r0, c->slope);
            emit_vec(f, c->bound_centre);
            fprintf(f, ", .bound_radius = %" PRId32 ", .bound_radius2 = ", c->bound_radius);
            emit_wide(f, c->bound_radius2);
            fprintf(f, ", .material = %u },\n", (unsigned)c->material);
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_polygons) {
        fprintf(f, "static const polygon_t polygons[%" PRIu32 "] TABLE = {\n", sc->n_polygons);
        for (uint32_t i = 0; i < sc->n_polygons; i++) {
            const polygon_t *p = &sc->polygons[i];
            fprintf(f, "    { .normal = ");
            emit_vec(f, p->normal);
            fprintf(f, ", .offset = %" PRId32 ", .box_min = ", p->offset);
            emit_vec(f, p->box_min);
            fprintf(f, ", .box_max = ");
            emit_vec(f, p->box_max);
            fprintf(f, ",\n      .first = %" PRIu32 ", .normals = %" PRIu32 "u, .count = %u, .material = %u, .drop_axis = %u, .convex = %u },\n",
                    p->first, p->normals, (unsigned)p->count, (unsigned)p->material, (unsigned)p->drop_axis,
                    (unsigned)p->convex);
        }
        fprintf(f, "};\n\n");
    }
    emit_vec_table(f, "vertices", sc->vertices, sc->n_vertices);
    emit_vec_table(f, "normals", sc->normals, sc->n_normals);

    if (sc->n_xforms) {
        fprintf(f, "static const xform_t xforms[%" PRIu32 "] TABLE = {\n", sc->n_xforms);
        for (uint32_t i = 0; i < sc->n_xforms; i++) {
            const xform_t *x = &sc->xforms[i];
            fprintf(f, "    { .m = ");
            emit_mat(f, x->m);
            fprintf(f, ",\n      .t = { %" PRId32 ", %" PRId32 ", %" PRId32 " },\n      .im = ", x->t[0], x->t[1], x->t[2]);
            emit_mat(f, x->im);
            fprintf(f, " },\n");
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_shapes) {
        fprintf(f, "static const shape_t shapes[%" PRIu32 "] TABLE = {\n", sc->n_shapes);
        for (uint32_t i = 0; i < sc->n_shapes; i++) {
            const shape_t *p = &sc->shapes[i];
            fprintf(f, "    { .q = {");
            for (int k = 0; k < 10; k++)
                fprintf(f, " %" PRId32 ",", p->q[k]);
            fprintf(f, " },\n      .lo = ");
            emit_vec(f, p->lo);
            fprintf(f, ", .hi = ");
            emit_vec(f, p->hi);
            fprintf(f, ", .bound = %" PRId32 ", .xform = %u, .material = %u, .kind = %u },\n", p->bound,
                    (unsigned)p->xform, (unsigned)p->material, (unsigned)p->kind);
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_csg_nodes) {
        fprintf(f, "static const csg_node_t csg_nodes[%" PRIu32 "] TABLE = {\n", sc->n_csg_nodes);
        for (uint32_t i = 0; i < sc->n_csg_nodes; i++)
            fprintf(f, "    { .a = %u, .b = %u, .op = %u },\n", (unsigned)sc->csg_nodes[i].a,
                    (unsigned)sc->csg_nodes[i].b, (unsigned)sc->csg_nodes[i].op);
        fprintf(f, "};\n\n");
    }
    if (sc->n_objects) {
        fprintf(f, "static const object_t objects[%" PRIu32 "] TABLE = {\n", sc->n_objects);
        for (uint32_t i = 0; i < sc->n_objects; i++) {
            fprintf(f, "    { .box_min = ");
            emit_vec(f, sc->objects[i].box_min);
            fprintf(f, ", .box_max = ");
            emit_vec(f, sc->objects[i].box_max);
            fprintf(f, ", .root = %u },\n", (unsigned)sc->objects[i].root);
        }
        fprintf(f, "};\n\n");
    }
    if (sc->n_bvh_nodes) {
        fprintf(f, "static const bvh_node_t bvh_nodes[%" PRIu32 "] TABLE = {\n", sc->n_bvh_nodes);
        for (uint32_t i = 0; i < sc->n_bvh_nodes; i++) {
            const bvh_node_t *n = &sc->bvh_nodes[i];
            fprintf(f, "    { ");
            emit_vec(f, n->min);
            fprintf(f, ", ");
            emit_vec(f, n->max);
            fprintf(f, ", %" PRIu32 ", %u, %u },\n", n->index, (unsigned)n->count, (unsigned)n->axis);
        }
        fprintf(f, "};\n\n");
        uint32_t n_prims = sc->n_spheres + sc->n_cones + sc->n_polygons + sc->n_objects;
        fprintf(f, "static const prim_ref_t bvh_prims[%" PRIu32 "] TABLE = {", n_prims);
        for (uint32_t i = 0; i < n_prims; i++)
            fprintf(f, "%s0x%08" PRIx32 "u,", i % 8 ? " " : "\n    ", sc->bvh_prims[i]);
        fprintf(f, "\n};\n\n");
    }

    const view_t *v = &sc->view;
    fprintf(f, "const scene_t rt_scene TABLE = {\n    .view = { .from = ");
    emit_vec(f, v->from);
    fprintf(f, ", .at = ");
    emit_vec(f, v->at);
    fprintf(f, ", .up = ");
    emit_vec(f, v->up);
    fprintf(f, ", .angle = %" PRId32 ", .tan_half = %" PRId64 " },\n    .background = ", v->angle,
            (int64_t)v->tan_half);
    emit_vec(f, sc->background);
    fprintf(f, ",\n    .width = %u, .height = %u, .light_intensity = %" PRId32 ",\n", (unsigned)sc->width,
            (unsigned)sc->height, sc->light_intensity);
    fprintf(f, "    .materials = %s, .lights = %s, .spheres = %s, .cones = %s,\n",
            sc->n_materials ? "materials" : "0", sc->n_lights ? "lights" : "0",
            sc->n_spheres ? "spheres" : "0", sc->n_cones ? "cones" : "0");
    fprintf(f, "    .polygons = %s, .vertices = %s, .normals = %s,\n", sc->n_polygons ? "polygons" : "0",
            sc->n_vertices ? "vertices" : "0", sc->n_normals ? "normals" : "0");
    fprintf(f, "    .bvh_nodes = %s, .bvh_prims = %s, .n_bvh_nodes = %" PRIu32 ",\n",
            sc->n_bvh_nodes ? "bvh_nodes" : "0", sc->n_bvh_nodes ? "bvh_prims" : "0", sc->n_bvh_nodes);
    fprintf(f, "    .xforms = %s, .shapes = %s, .csg_nodes = %s, .objects = %s,\n", sc->n_xforms ? "xforms" : "0",
            sc->n_shapes ? "shapes" : "0", sc->n_csg_nodes ? "csg_nodes" : "0", sc->n_objects ? "objects" : "0");
    fprintf(f, "    .n_xforms = %" PRIu32 ", .n_shapes = %" PRIu32 ", .n_csg_nodes = %" PRIu32 ", .n_objects = %" PRIu32 ",\n",
            sc->n_xforms, sc->n_shapes, sc->n_csg_nodes, sc->n_objects);
    fprintf(f, "    .scale_log2 = %" PRId32 ",\n", sc->scale_log2);
    fprintf(f, "    .n_materials = %" PRIu32 ", .n_lights = %" PRIu32 ", .n_spheres = %" PRIu32
               ", .n_cones = %" PRIu32 ", .n_polygons = %" PRIu32 ",\n",
            sc->n_materials, sc->n_lights, sc->n_spheres, sc->n_cones, sc->n_polygons);
    fprintf(f, "    .n_vertices = %" PRIu32 ", .n_normals = %" PRIu32 ", .n_flat_skipped = %" PRIu32 ",\n};\n",
            sc->n_vertices, sc->n_normals, sc->n_flat_skipped);
}

static void emit_text(FILE *f, const char *text, size_t len)
{
    fprintf(f, "#include <stddef.h>\n\nconst char rt_scene_text[] = {");
    for (size_t i = 0; i < len; i++)
        fprintf(f, "%s%d,", i % 20 ? " " : "\n    ", (unsigned char)text[i]);
    fprintf(f, "\n};\nconst size_t rt_scene_text_len = %zu;\n", len);
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
    fprintf(f, "#define SCENE_N_MATERIALS %" PRIu32 "\n#define SCENE_N_LIGHTS %" PRIu32 "\n", sc->n_materials,
            sc->n_lights);
    fprintf(f, "#define SCENE_N_SPHERES %" PRIu32 "\n#define SCENE_N_CONES %" PRIu32 "\n", sc->n_spheres,
            sc->n_cones);
    fprintf(f, "#define SCENE_N_POLYGONS %" PRIu32 "\n#define SCENE_N_VERTICES %" PRIu32 "\n\n",
            sc->n_polygons, sc->n_vertices);
    bvh_stats_t bs;
    bvh_tree_stats(sc, &bs);
    fprintf(f, "/* BVH: %" PRIu32 " nodes, %" PRIu32 " leaves, depth %" PRIu32 ", largest leaf %" PRIu32
               ";\n * SAH estimate per ray: %.2f node visits, %.2f primitive tests */\n",
            bs.nodes, bs.leaves, bs.max_depth, bs.max_leaf_size, bs.sah_nodes_milli / 1000.0,
            bs.sah_tests_milli / 1000.0);
    fprintf(f, "#define SCENE_N_BVH_NODES %" PRIu32 "\n\n", bs.nodes);
    fprintf(f, "/* What the scene uses; with PRUNE=1 the firmware is built with these\n"
               " * as its RT_USE_* switches (src/rt_config.h). */\n");
    fprintf(f, "#define SCENE_USES_SPHERES %d\n", sc->n_spheres > 0);
    fprintf(f, "#define SCENE_USES_CONES %d\n", sc->n_cones > 0);
    fprintf(f, "#define SCENE_USES_POLYGONS %d\n", sc->n_polygons > 0);
    fprintf(f, "#define SCENE_USES_OBJECTS %d\n", sc->n_objects > 0);
    fprintf(f, "#define SCENE_USES_PATCHES %d\n", patches);
    fprintf(f, "#define SCENE_USES_SHADOWS %d\n", sc->n_lights > 0);
    fprintf(f, "#define SCENE_USES_SPECULAR %d\n", specular);
    fprintf(f, "#define SCENE_USES_REFLECTION %d\n", reflection);
    fprintf(f, "#define SCENE_USES_REFRACTION %d\n\n", refraction);
    fprintf(f, "#if SCENE_PRUNE\n");
    static const char *const names[] = { "SPHERES", "CONES", "POLYGONS", "OBJECTS", "PATCHES", "SHADOWS", "SPECULAR", "REFLECTION", "REFRACTION" };
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        fprintf(f, "#define RT_USE_%s SCENE_USES_%s\n", names[i], names[i]);
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
        fprintf(out, "#include <stdint.h>\n\n#include \"scene.h\"\n\n");
        fprintf(out, "#if !RT_BACKEND_FIXED || FX_FRAC_BITS != %d\n", FX_FRAC_BITS);
        fprintf(out, "#error \"these tables are for the fixed build with FX_FRAC_BITS = %d\"\n#endif\n\n",
                FX_FRAC_BITS);
        emit_tables(out, sc);
    }
    if (hdr)
        emit_header(hdr, sc, src);
    return ferror(out) || (hdr && ferror(hdr)) ? -1 : 0;
}

#ifndef SCENEC_NO_MAIN

static const char scenec_usage[] =
    "usage: rt-scenec SCENE.nff -o OUT.c [--header OUT.h] [--text]\n"
    "\n"
    "Compiles an NFF scene into C tables for firmware that carries its scene in\n"
    "flash, with the firmware's capacities and fixed-point format.\n"
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
            printf("rt-scenec %s\n", RT_VERSION);
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
