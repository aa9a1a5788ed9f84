/*
 * main.c - the hosted `rt` command: render an NFF scene to PNG/PPM with the
 * fixed or the double build of the core, or compare two images.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "backend.h"
#include "image.h"
#include "receive.h"
#include "report.h"

#define EXIT_BAD_INPUT 2

static const char usage_text[] =
    "usage: rt SCENE.nff -o OUT.png|OUT.ppm [options]\n"
    "       rt compare A.png B.png [--psnr-min DB] [--max-over8 PERCENT] [--max-error N]\n"
    "       rt receive [STREAM] -o OUT.png   (the board's UART stream, stdin by default)\n"
    "\n"
    "render options:\n"
    "  -o, --output FILE   output image; the format follows the extension\n"
    "  --size WxH          image size (default: the scene's resolution)\n"
    "  --fixed             fixed-point build of the core (default)\n"
    "  --double            double-precision build: the exact reference\n"
    "  --double-ftol       double precision with the fixed build's tolerances\n"
    "                      (splits the fixed build's error: format vs tolerances)\n"
    "  --float             single-precision build (for comparison)\n"
    "  --depth N           maximum ray-tree depth, 1..%d (default %d)\n"
    "  --format F          framebuffer pixel format: rgb888 (default) or rgb565\n"
    "  --stats             print ray counts, BVH statistics and render time on stderr\n"
    "  --spd               SPD test procedure: 512x512 pixels (or --size) from corner\n"
    "                      rays, four averaged per pixel, depth 5, SPD rule 8\n"
    "  --adaptive W        skip child rays whose share of the pixel is below W\n"
    "                      (0.001..1; off by default)\n"
    "  --quiet             no progress indicator\n"
    "compare options:\n"
    "  --psnr-min DB       exit 1 if PSNR is below DB\n"
    "  --max-over8 PCT     exit 1 if more than PCT %% of pixels differ by > 8/255\n"
    "  --max-error N       exit 1 if any channel differs by more than N/255\n"
    "\n"
    "exit status: 0 success, 1 output or threshold failure, 2 bad input or usage\n";

static int usage_error(const char *fmt, const char *arg)
{
    fprintf(stderr, "rt: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(run 'rt --help' for usage)\n");
    return EXIT_BAD_INPUT;
}

static bool parse_uint(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end != '\0' || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

static bool parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end != '\0' || v != v)
        return false;
    *out = v;
    return true;
}

/* The whole file, NUL-terminated; NULL with a message on failure. */
static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (n == cap) {
            char *nb = realloc(buf, cap *= 2);
            if (!nb)
                break;
            buf = nb;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        fprintf(stderr, "%s: cannot read: %s\n", path, strerror(errno ? errno : EIO));
        fclose(f);
        free(buf);
        return NULL;
    }
    fclose(f);
    *len = n;
    return buf;
}

/* ---- the framebuffer sink: collects bands into a whole image ---------- */

#define HOST_BAND_LINES 8

typedef struct {
    fb_sink_t sink;
    image_t img;
    bool progress;
    uint8_t band_a[HOST_BAND_LINES * RT_MAX_WIDTH * 3];
    uint8_t band_b[HOST_BAND_LINES * RT_MAX_WIDTH * 3];
} host_sink_t;

static int host_begin(fb_sink_t *s, uint16_t w, uint16_t h)
{
    host_sink_t *hs = s->user;
    hs->img.width = w;
    hs->img.height = h;
    hs->img.rgb = malloc((size_t)w * h * 3);
    return hs->img.rgb ? 0 : 1;
}

static void host_flush(fb_sink_t *s, const fb_area_t *a, const uint8_t *px)
{
    host_sink_t *hs = s->user;
    size_t w = (size_t)hs->img.width;
    for (unsigned y = a->y1; y <= a->y2; y++) {
        uint8_t *dst = hs->img.rgb + (size_t)y * w * 3;
        const uint8_t *src = px + (size_t)(y - a->y1) * w * fb_bytes_per_pixel(s->format);
        if (s->format == FB_RGB888) {
            memcpy(dst, src, w * 3);
        } else {
            for (size_t x = 0; x < w; x++) {
                unsigned v = (unsigned)src[2 * x] | (unsigned)src[2 * x + 1] << 8;
                unsigned r = v >> 11, g = (v >> 5) & 63, b = v & 31;
                dst[3 * x] = (uint8_t)((r * 255 + 15) / 31);
                dst[3 * x + 1] = (uint8_t)((g * 255 + 31) / 63);
                dst[3 * x + 2] = (uint8_t)((b * 255 + 15) / 31);
            }
        }
    }
    if (hs->progress)
        fprintf(stderr, "\rrendering: %3u%%", (unsigned)(100 * (a->y2 + 1) / hs->img.height));
    fb_flush_ready(s); /* synchronous: the band is free again */
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* How many fraction bits the geometry gave up so that a far camera or
 * light fits the range (the reader puts the largest coordinate of the
 * geometry in [8, 16) otherwise). */
static int geometry_bits_lost(const rt_backend_t *be)
{
    double mn[3], mx[3], m = 0;
    if (!be->bounds(mn, mx))
        return 0;
    for (int k = 0; k < 3; k++)
        m = fmax(m, fmax(fabs(mn[k]), fabs(mx[k])));
    double scaled = ldexp(m, (int)be->scale_log2());
    int lost = scaled > 0 ? 3 - (int)floor(log2(scaled)) : 0;
    return lost > 0 ? lost : 0;
}

static int cmd_render(int argc, char **argv)
{
    const char *scene_path = NULL, *out_path = NULL;
    const rt_backend_t *be = &rt_backend_fixed;
    render_opts_t opts = { 0 };
    fb_format_t format = FB_RGB888;
    bool stats = false, quiet = false;

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        bool has_value = i + 1 < argc;
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!has_value)
                return usage_error("%s needs a file name", a);
            out_path = argv[++i];
        } else if (!strcmp(a, "--size")) {
            long w, h;
            char buf[32];
            if (!has_value)
                return usage_error("%s needs WxH", a);
            const char *v = argv[++i];
            const char *x = strchr(v, 'x');
            if (!x || (size_t)(x - v) >= sizeof buf)
                return usage_error("--size: expected WxH, got '%s'", v);
            memcpy(buf, v, (size_t)(x - v));
            buf[x - v] = '\0';
            if (!parse_uint(buf, 1, RT_MAX_WIDTH, &w) || !parse_uint(x + 1, 1, RT_MAX_HEIGHT, &h))
                return usage_error("--size: expected WxH within the configured maximum, got '%s'", v);
            opts.width = (uint16_t)w;
            opts.height = (uint16_t)h;
        } else if (!strcmp(a, "--fixed")) {
            be = &rt_backend_fixed;
        } else if (!strcmp(a, "--double")) {
            be = &rt_backend_double;
        } else if (!strcmp(a, "--double-ftol")) {
            be = &rt_backend_double_ftol;
        } else if (!strcmp(a, "--float")) {
            be = &rt_backend_float;
        } else if (!strcmp(a, "--depth")) {
            long d;
            if (!has_value)
                return usage_error("%s needs a number", a);
            if (!parse_uint(argv[++i], 1, RT_MAX_DEPTH, &d))
                return usage_error("--depth: expected 1..RT_MAX_DEPTH, got '%s'", argv[i]);
            opts.max_depth = (uint8_t)d;
        } else if (!strcmp(a, "--format")) {
            if (!has_value)
                return usage_error("%s needs rgb888 or rgb565", a);
            const char *f = argv[++i];
            if (!strcmp(f, "rgb888"))
                format = FB_RGB888;
            else if (!strcmp(f, "rgb565"))
                format = FB_RGB565;
            else
                return usage_error("--format: expected rgb888 or rgb565, got '%s'", f);
        } else if (!strcmp(a, "--spd")) {
            opts.spd = true;
        } else if (!strcmp(a, "--adaptive")) {
            double v;
            if (!has_value)
                return usage_error("%s needs a number", a);
            if (!parse_double(argv[++i], &v) || v < 0.001 || v > 1)
                return usage_error("--adaptive: expected a number from 0.001 to 1, got '%s'", argv[i]);
            opts.adaptive_milli = (uint16_t)(v * 1000 + 0.5);
        } else if (!strcmp(a, "--stats")) {
            stats = true;
        } else if (!strcmp(a, "--quiet")) {
            quiet = true;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else if (!scene_path) {
            scene_path = a;
        } else {
            return usage_error("unexpected argument '%s'", a);
        }
    }
    if (!scene_path)
        return usage_error("%s", "no scene file given");
    if (!out_path)
        return usage_error("%s", "no output file given (-o OUT.png)");

    size_t len;
    char *text = read_file(scene_path, &len);
    if (!text)
        return EXIT_BAD_INPUT;
    rt_error_t err;
    bool ok = be->load(text, len, &err);
    free(text);
    if (!ok) {
        if (err.line)
            fprintf(stderr, "%s:%u: %s\n", scene_path, (unsigned)err.line, err.msg);
        else
            fprintf(stderr, "%s: %s\n", scene_path, err.msg);
        return EXIT_BAD_INPUT;
    }

    if (be->flat_skipped())
        fprintf(stderr, "%s: note: skipped %u zero-area polygon(s)\n", scene_path,
                (unsigned)be->flat_skipped());
    int lost = geometry_bits_lost(be);
    if (be == &rt_backend_fixed && lost >= 4)
        fprintf(stderr, "%s: warning: the camera or a light lies so far beyond the geometry that the fixed "
                        "build keeps %d fewer bits for it: expect noisy edges (keep them within 500 times "
                        "the geometry's extent)\n",
                scene_path, lost);

    if (opts.spd && !opts.width) {
        opts.width = opts.height = 512;
    }
    /* two rows of corner colours, sized for the wider (double) backend */
    size_t scratch_bytes = 2 * ((size_t)(opts.width ? opts.width : RT_MAX_WIDTH) + 1) * 3 * sizeof(double);
    void *scratch = opts.spd ? malloc(scratch_bytes) : NULL;
    opts.scratch = scratch;
    opts.scratch_bytes = scratch ? scratch_bytes : 0;

    static host_sink_t hs;
    hs.sink = (fb_sink_t){ .format = format,
                           .band = { hs.band_a, hs.band_b },
                           .band_bytes = sizeof hs.band_a,
                           .begin = host_begin,
                           .flush = host_flush,
                           .user = &hs };
    hs.progress = !quiet && isatty(2);
    rt_stats_t st = { 0 };
    double t0 = now_seconds();
    int status = be->render(&opts, &hs.sink, &st, &err);
    double secs = now_seconds() - t0;
    free(scratch);
    if (hs.progress)
        fprintf(stderr, "\r                \r");
    if (status != 0) {
        fprintf(stderr, "%s: %s\n", scene_path, status < 0 ? err.msg : "framebuffer sink failed");
        image_free(&hs.img);
        return status < 0 ? EXIT_BAD_INPUT : 1;
    }
    if (stats)
        report_stats(stderr, REPORT_TEXT, be, &st, hs.img.width, hs.img.height, secs, geometry_bits_lost(be));
    char why[256];
    if (image_write(out_path, &hs.img, why, sizeof why) != 0) {
        fprintf(stderr, "rt: %s\n", why);
        image_free(&hs.img);
        return 1;
    }
    image_free(&hs.img);
    return 0;
}

static int cmd_compare(int argc, char **argv)
{
    const char *paths[2] = { NULL, NULL };
    double psnr_min = -1, max_over8 = -1, max_error = -1;
    int n = 0;
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--psnr-min") || !strcmp(a, "--max-over8") || !strcmp(a, "--max-error")) {
            double v;
            if (i + 1 >= argc || !parse_double(argv[i + 1], &v) || v < 0)
                return usage_error("%s needs a non-negative number", a);
            *(!strcmp(a, "--psnr-min") ? &psnr_min : !strcmp(a, "--max-over8") ? &max_over8 : &max_error) = v;
            i++;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else if (n < 2) {
            paths[n++] = a;
        } else {
            return usage_error("unexpected argument '%s'", a);
        }
    }
    if (n != 2)
        return usage_error("%s", "compare needs two image files");
    image_t img[2] = { { 0, 0, NULL }, { 0, 0, NULL } };
    char why[256];
    for (int k = 0; k < 2; k++) {
        if (image_read(paths[k], &img[k], why, sizeof why) != 0) {
            fprintf(stderr, "rt: %s\n", why);
            image_free(&img[0]);
            return EXIT_BAD_INPUT;
        }
    }
    image_diff_t d;
    int rc = image_compare(&img[0], &img[1], &d, why, sizeof why);
    image_free(&img[0]);
    image_free(&img[1]);
    if (rc != 0) {
        fprintf(stderr, "rt: %s\n", why);
        return EXIT_BAD_INPUT;
    }
    printf("psnr %.2f dB  max-error %d  over2 %.3f%%  over8 %.3f%%\n", d.psnr_db, d.max_err,
           100 * d.share_over2, 100 * d.share_over8);
    bool fail = (psnr_min >= 0 && d.psnr_db < psnr_min) ||
                (max_over8 >= 0 && 100 * d.share_over8 > max_over8) ||
                (max_error >= 0 && d.max_err > max_error);
    return fail ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        printf(usage_text, RT_MAX_DEPTH, RT_MAX_DEPTH);
        return 0;
    }
    if (argc >= 2 && !strcmp(argv[1], "compare"))
        return cmd_compare(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "receive"))
        return cmd_receive(argc, argv);
    return cmd_render(argc, argv);
}
