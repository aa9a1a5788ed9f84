/*
 * scenec_tables.c - a scene compiled by rt-scenec (scene_data.c, rt_scene)
 * against the reader, for tests/host/scenec-tables-tests.sh: built with the
 * same backend flags as the rt-scenec that wrote the tables.
 *
 *   scenec_tables SCENE.nff > OUT.ppm   (host) reads SCENE.nff with the
 *       core's reader and compares every field of every table of rt_scene
 *       with it, bit for bit (exit 1 on a difference, named on stderr);
 *       then renders rt_scene
 *   built with -DTABLES_BOARD=1: firmware for a board of platform/
 *       (port.h: the port's start-up, which switches a hard-float build's
 *       FPU on, and console) that renders rt_scene to the console
 * The render is WIDTH x HEIGHT (-D, default 64 x 64), depth RT_MAX_DEPTH,
 * RGB888, written as a binary PPM.
 */
#include <string.h>

#include "rt_render.h"
#include "geometry/scene.h"

#ifndef WIDTH
#define WIDTH 64
#endif
#ifndef HEIGHT
#define HEIGHT 64
#endif
#define BAND_LINES 4

extern const scene_t rt_scene; /* scene_data.c */

#if TABLES_BOARD
#include "port.h"

static int out_write(const void *p, size_t n)
{
    port_write(p, n);
    return 0;
}
#else
#include <stdio.h>
#include <stdlib.h>

#include "reader/nff.h"

static int out_write(const void *p, size_t n) { return fwrite(p, 1, n, stdout) == n ? 0 : 1; }

/* ---- the tables against the reader's, field by field ------------------- */

static scene_store_t store;
static unsigned mismatches;

static void differ(const char *table, uint32_t row, const char *field)
{
    if (mismatches++ < 20)
        fprintf(stderr, "scenec_tables: %s[%u].%s differs from the reader's\n", table, (unsigned)row, field);
}

/* a field's bytes (vec3_t and view_t hold no padding) */
#define CMP_FIELD(type, name, dims) \
    if (memcmp(&a->name, &b->name, sizeof a->name) != 0) \
        differ(table, row, #name);
#define DEFINE_CMP(type) \
    static void cmp_##type(const char *table, uint32_t row, const type *a, const type *b) \
    { \
        FIELDS_##type(CMP_FIELD) \
    }
#define DEFINE_CMP_PRIM(type, table, cap, KIND, name, use) DEFINE_CMP(type)
DEFINE_CMP(material_t)
DEFINE_CMP(texture_t)
DEFINE_CMP(light_t)
DEFINE_CMP(xform_t)
DEFINE_CMP(shape_t)
DEFINE_CMP(csg_node_t)
DEFINE_CMP(bvh_node_t)
RT_PRIM_KINDS(DEFINE_CMP_PRIM)

static void cmp_vec3_t(const char *table, uint32_t row, const vec3_t *a, const vec3_t *b)
{
    if (memcmp(a, b, sizeof *a) != 0)
        differ(table, row, "xyz");
}

static void cmp_prim_ref_t(const char *table, uint32_t row, const prim_ref_t *a, const prim_ref_t *b)
{
    if (*a != *b)
        differ(table, row, "ref");
}

static void cmp_scene(const scene_t *a, const scene_t *b)
{
    const char *table = "scene";
    uint32_t row = 0;
    FIELDS_scene_t(CMP_FIELD)
#define CMP_TABLE(type, tab, cap) \
    if (a->n_##tab != b->n_##tab) \
        differ(#tab, 0, "count"); \
    else \
        for (uint32_t i = 0; i < a->n_##tab; i++) \
            cmp_##type(#tab, i, &a->tab[i], &b->tab[i]);
#define CMP_PRIM_TABLE(type, tab, cap, KIND, name, use) CMP_TABLE(type, tab, cap)
    RT_PRIM_KINDS(CMP_PRIM_TABLE)
    RT_SCENE_TABLES(CMP_TABLE)
}

static bool tables_match(const char *path)
{
    FILE *f = fopen(path, "rb");
    static char text[1 << 24];
    size_t len = f ? fread(text, 1, sizeof text, f) : 0;
    if (!f || ferror(f) || len == sizeof text) {
        fprintf(stderr, "scenec_tables: %s: cannot read it\n", path);
        return false;
    }
    fclose(f);
    rt_error_t err;
    if (!nff_read(text, len, &store, &err)) {
        fprintf(stderr, "scenec_tables: %s:%u: %s\n", path, (unsigned)err.line, err.msg);
        return false;
    }
    cmp_scene(&rt_scene, &store.scene);
    if (mismatches)
        fprintf(stderr, "scenec_tables: %u fields differ\n", mismatches);
    return mismatches == 0;
}
#endif

/* ---- the render -------------------------------------------------------- */

static uint8_t band[BAND_LINES * WIDTH * 3];
static int out_status;

static int begin(rt_fb_sink_t *s, uint16_t width, uint16_t height)
{
    (void)s;
    char header[24] = "P6\n", *p = header + 3;
    unsigned v[2] = { width, height };
    for (int k = 0; k < 2; k++) {
        char digits[5];
        int n = 0;
        do
            digits[n++] = (char)('0' + v[k] % 10);
        while ((v[k] /= 10) != 0);
        while (n > 0)
            *p++ = digits[--n];
        *p++ = k == 0 ? ' ' : '\n';
    }
    memcpy(p, "255\n", 4);
    return out_write(header, (size_t)(p + 4 - header));
}

static int flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *pixels)
{
    out_status = out_write(pixels, (size_t)(a->x2 - a->x1 + 1) * (size_t)(a->y2 - a->y1 + 1) * 3u);
    rt_fb_flush_ready(s);
    return out_status;
}

static int render(void)
{
    rt_fb_sink_t sink = { .format = RT_FB_RGB888, .band = { band, 0 }, .band_bytes = sizeof band,
                          .begin = begin, .flush = flush };
    rt_render_opts_t opts = { .width = WIDTH, .height = HEIGHT };
    static rt_error_t err;
    return rt_render(&rt_scene, &opts, &sink, NULL, &err) == 0 ? 0 : 1;
}

#if TABLES_BOARD
int main(void)
{
    port_init();
    return render();
}
#else
int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: scenec_tables SCENE.nff > OUT.ppm\n");
        return 2;
    }
    if (!tables_match(argv[1]))
        return 1;
    return render() != 0 || fflush(stdout) != 0;
}
#endif
