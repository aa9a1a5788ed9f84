/* report.c - `rt --stats` as "key value" lines or one JSON object. */
#include "report.h"

#include <inttypes.h>

typedef struct {
    FILE *f;
    report_format_t format;
    int fields;
} report_t;

/* Keys are [a-z0-9_] and string values plain words, so neither needs
 * escaping in JSON. */
static void key(report_t *r, const char *k)
{
    if (r->format == REPORT_JSON)
        fprintf(r->f, "%s\n  \"%s\": ", r->fields ? "," : "{", k);
    else
        fprintf(r->f, "%-24s ", k);
    r->fields++;
}

static void end_line(report_t *r)
{
    if (r->format == REPORT_TEXT)
        fputc('\n', r->f);
}

static void put_uint(void *ctx, const char *k, uint64_t v)
{
    report_t *r = ctx;
    key(r, k);
    fprintf(r->f, "%" PRIu64, v);
    end_line(r);
}

static void put_int(report_t *r, const char *k, long long v)
{
    key(r, k);
    fprintf(r->f, "%lld", v);
    end_line(r);
}

static void put_real(report_t *r, const char *k, double v, int decimals)
{
    key(r, k);
    fprintf(r->f, "%.*f", decimals, v);
    end_line(r);
}

static void put_str(report_t *r, const char *k, const char *v)
{
    key(r, k);
    fprintf(r->f, r->format == REPORT_JSON ? "\"%s\"" : "%s", v);
    end_line(r);
}

void report_stats(FILE *f, report_format_t format, const rt_backend_t *be, const char *backend,
                  const rt_stats_t *st, int width, int height, double seconds, unsigned threads, double busy,
                  int range_bits_lost)
{
    report_t r = { f, format, 0 };
    put_str(&r, "backend", backend);
    put_int(&r, "width", width);
    put_int(&r, "height", height);
    put_real(&r, "render_seconds", seconds, 6);
    put_int(&r, "threads", threads);
    put_real(&r, "threads_busy", busy, 3);
    be->stats_each(st, put_uint, &r);

    put_int(&r, "scene_scale_log2", be->scale_log2());
    put_int(&r, "range_bits_lost", range_bits_lost);
    if (be->saturations(false) >= 0)
        put_int(&r, "saturations", be->saturations(false));
    bvh_stats_t bs;
    be->bvh_stats(&bs);
    put_uint(&r, "primitives", bs.primitives);
    put_uint(&r, "bvh_nodes", bs.nodes);
    put_uint(&r, "bvh_leaves", bs.leaves);
    put_uint(&r, "bvh_depth", bs.max_depth);
    put_uint(&r, "bvh_largest_leaf", bs.max_leaf_size);
    /* the builder's surface-area estimate, per ray */
    put_real(&r, "bvh_sah_node_visits", bs.sah_nodes_milli / 1000.0, 3);
    put_real(&r, "bvh_sah_tests", bs.sah_tests_milli / 1000.0, 3);
    if (format == REPORT_JSON)
        fprintf(f, "\n}\n");
}
